// granpen sweep: a sweep's runs, what their files say, and their locks (sweep_jobs.h).
#include "sweep_jobs.h"

#include "errors.h"
#include "sweep_files.h"
#include "sweep_lock.h"
#include "sweep_manifest.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unistd.h>

namespace granpen {
namespace sweep_run {

void unlock(Job &j) { release_lock(j.lock_fd); }

// the command line of one planned run
Job make_job(const PlannedRun &r, const Sweep &sw, const RunnerOptions &opt)
{
  const std::string &dir = sw.dir;
  const SweepSpec &spec = sw.spec;
  Job j;
  j.run = r;
  j.log = dir + "/logs/" + r.id + ".log";
  j.out = dir + "/logs/" + r.id + ".out";
  std::vector<std::string> a;
  if (!opt.mpirun.empty()) {
    // srun counts tasks with -n, mpirun/mpiexec with -np
    const std::string base = opt.mpirun.substr(opt.mpirun.rfind('/') + 1);
    a = {opt.mpirun, base == "srun" ? "-n" : "-np", std::to_string(opt.ranks)};
  }
  a.push_back(opt.lmp);
  auto var = [&](const std::string &k, const std::string &v) {
    if (!v.empty()) a.insert(a.end(), {"-var", k, v});
  };
  if (r.kind == PlannedRun::POUR) {
    j.info = dir + "/beds/" + r.id + ".info";
    a.insert(a.end(), {"-in", opt.inputs + "/in.pour"});
    var("inputs", opt.inputs);
    var("preset", r.preset);
    var("mu", r.mu);
    var("seed", r.seed);
    var("out", dir + "/beds/" + r.id);
    if (spec.pour_checkpoint) {
      var("checkpoint", "1");
      j.pour_checkpoints = dir + "/beds/" + r.id + ".pour";
    }
    for (const auto &[k, v] : spec.set) var(k, v);
  } else {
    j.trace = dir + "/traces/" + r.id + ".csv";
    j.done = j.trace + ".done";
    a.insert(a.end(), {"-in", opt.inputs + "/in.push"});
    var("inputs", opt.inputs);
    var("preset", r.preset);
    var("mu", r.mu);
    var("bed", dir + "/beds/" + r.bed + ".restart");
    var("v0", r.v0);
    var("g_push", r.g);
    var("D", r.D);
    var("depth", r.depth);
    var("mu_push", r.mu_push);
    var("run", r.seed);
    var("trace", j.trace);
    var("checkpoint", std::to_string(opt.checkpoint));
    var("observe", opt.inputs + "/observe/" + spec.observe + ".lmp");
    for (const auto &[k, v] : spec.set) var(k, v);
    for (const auto &[k, v] : spec.push_set) var(k, v);
    var("drive_extra", "header bed " + r.bed + " header seed " + r.seed + " header preset " + r.preset);
    j.target_depth = r.depth.empty() ? 0.0 : std::atof(r.depth.c_str());
  }
  a.insert(a.end(), {"-log", j.log, "-screen", "none"});
  j.argv = a;
  return j;
}

// What a run's files say: a finished run is skipped, an interrupted push resumed from its
// newest complete checkpoint. `own`: this runner holds the run's lock and may move files.
void inspect_job(Job &j, bool own)
{
  if (j.run.kind == PlannedRun::POUR) {
    if (exists(j.info)) {
      j.status = "skipped", j.action = "already done";
      return;
    }
    // a checkpointed pour (pour_checkpoint = yes): resume from the chunk its state names,
    // when the restart it names is complete; else pour again from the start
    const std::string state = j.pour_checkpoints + ".state";
    if (own && !j.pour_checkpoints.empty() && exists(state)) {
      const auto kv = read_pour_state(state);
      const std::string restart = j.pour_checkpoints + "." + kv.second + ".restart";
      if (!kv.second.empty() && complete_checkpoint(restart)) {
        j.argv.insert(j.argv.end() - 4, {"-var", "resume", "yes"});
        j.action = "resumed at step " + kv.second + " (" + kv.first + ")";
      } else {
        std::remove(state.c_str());
        j.action = "started (its last checkpoint was incomplete)";
      }
    }
    return;
  }
  const std::string ca = j.trace + ".a.restart", cb = j.trace + ".b.restart";
  const bool ok_a = complete_checkpoint(ca), ok_b = complete_checkpoint(cb);
  switch (push_action(exists(j.done), exists(j.trace), ok_a || ok_b)) {
    case PushAction::SKIP_DONE: j.status = "skipped"; j.action = "already done"; break;
    case PushAction::RESUME: {
      const std::string from = ok_a && (!ok_b || mtime(ca) >= mtime(cb)) ? ca : cb;
      j.argv.insert(j.argv.end() - 4, {"-var", "resume", "yes", "-var", "from", from});
      j.action = "resumed from " + from.substr(from.rfind('/') + 1);
      if (exists(ca) != ok_a || exists(cb) != ok_b) j.action += " (the other checkpoint is incomplete)";
      break;
    }
    case PushAction::RESTART_FRESH: {
      if (!own) break;
      // an interrupted push with no complete checkpoint: keep its partial trace, start over
      int n = 1;
      while (exists(j.trace + ".partial" + std::to_string(n))) ++n;
      const std::string keep = j.trace + ".partial" + std::to_string(n);
      if (std::rename(j.trace.c_str(), keep.c_str()) != 0)
        throw InputError("cannot move " + j.trace + " to " + keep + ": " + std::strerror(errno));
      j.action = "restarted (partial trace kept as " + keep.substr(keep.rfind('/') + 1) + ")";
      std::remove(ca.c_str()), std::remove(cb.c_str());    // incomplete: never resumed from
      break;
    }
    case PushAction::START: {
      j.action = "started";
      // checkpoints without a trace are an earlier attempt's whose trace was removed: until
      // this run writes its own, a cut would resume from them onto the new trace, so they go
      if (own && (exists(ca) || exists(cb))) {
        std::remove(ca.c_str()), std::remove(cb.c_str());
        j.action = "started (the checkpoints of an earlier attempt without its trace removed)";
      }
      break;
    }
  }
}

Sweep setup_sweep(const SweepTask &task, const RunnerOptions &opt)
{
  Sweep sw;
  sw.spec = task.spec;
  const std::string dir = sw.dir = opt.out_root + "/" + sw.spec.name;
  for (const char *sub : {"/beds", "/traces", "/logs", "/locks"}) mkdirs(dir + sub);
  for (const auto &r : plan_sweep(sw.spec)) sw.jobs.push_back(make_job(r, sw, opt));

  // the runs this runner will run are locked before their files are looked at; one another
  // process holds is refused, its files untouched
  for (size_t k = 0; k < sw.jobs.size(); ++k) {
    Job &j = sw.jobs[k];
    const bool planned = opt.only_index < 0 || (int) k == opt.only_index;
    if (!planned) {
      inspect_job(j, false);    // read only: a pour another task may have made
      continue;
    }
    std::string holder;
    j.lock_fd = lock_run(dir + "/locks/" + j.run.id + ".lock", holder);
    if (j.lock_fd < 0) {
      j.status = "failed";
      j.action = "refused";
      j.error = "locked by another process (granpen sweep pid " + holder + ")";
      continue;
    }
    inspect_job(j, true);
    if (j.status == "skipped") unlock(j);
  }

  for (auto &j : sw.jobs) {
    if (j.status != "skipped") continue;
    auto kv = read_info(j.run.kind == PlannedRun::POUR ? j.info : j.done);
    if (kv.count("wall_seconds")) j.wall = std::atof(kv["wall_seconds"].c_str());
  }

  // the LAMMPS version from any log already there (all runs may be skipped)
  for (const auto &j : sw.jobs)
    if (sw.lammps_version.empty() && exists(j.log)) sw.lammps_version = first_line_matching(slurp(j.log), "LAMMPS (");
  keep_other_runs(sw);
  return sw;
}

}    // namespace sweep_run
}    // namespace granpen
