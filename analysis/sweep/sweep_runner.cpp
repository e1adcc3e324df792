// granpen sweep: the runner's pool: the runs of one or more sweeps, up to `jobs` at once,
// started in order as their beds are ready, reaped, reported. The parts it runs on:
// sweep_jobs.h (runs and resume), sweep_manifest.h, sweep_process.h, sweep_lock.h,
// sweep_files.h.
#include "sweep_runner.h"

#include "atomic_file.h"
#include "errors.h"
#include "slurm_script.h"
#include "sweep_files.h"
#include "sweep_jobs.h"
#include "sweep_manifest.h"
#include "sweep_process.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <signal.h>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace granpen {

// Rounded to whole seconds before splitting: 119.7 s is "2m00s", never "1m60s".
std::string format_duration(double s)
{
  char buf[64];
  if (s < 0 || !std::isfinite(s)) return "?";
  if (s < 119.5) {
    std::snprintf(buf, sizeof(buf), "%.0fs", s);
  } else if (s < 7200) {
    const long t = std::lround(s);
    std::snprintf(buf, sizeof(buf), "%ldm%02lds", t / 60, t % 60);
  } else {
    std::snprintf(buf, sizeof(buf), "%.1fh", s / 3600);
  }
  return buf;
}

double push_seconds_left(double z_then, double z_now, double elapsed, double target_depth)
{
  if (!std::isfinite(z_then) || !std::isfinite(z_now) || !std::isfinite(elapsed) || !std::isfinite(target_depth))
    return NAN;
  if (!(target_depth > 0.0)) return NAN;    // the deck's own depth: not known here
  if (z_now >= target_depth) return 0.0;
  if (!(z_now > z_then) || !(elapsed > 0.0)) return NAN;
  return (target_depth - z_now) * elapsed / (z_now - z_then);
}

namespace {

using namespace sweep_run;

// A push's cost in steps, up to a common factor: travel / (v0 dt). Pushes are started
// longest first so that the pool ends on short ones (no core idles behind a slow push).
double push_steps(const Job &j, const SweepSpec &spec)
{
  double dt = 1.0;
  for (const auto &[k, v] : spec.set)
    if (k == "dt_push") dt = std::atof(v.c_str());
  const double depth = j.target_depth > 0 ? j.target_depth : 1.0, v0 = std::atof(j.run.v0.c_str());
  return v0 > 0 && dt > 0 ? depth / (v0 * dt) : 0.0;
}

void check_runner_inputs(const std::vector<SweepTask> &tasks, const RunnerOptions &opt)
{
  if (access(opt.lmp.c_str(), X_OK) != 0)
    throw InputError("lmp_granpen not found or not executable: " + opt.lmp + " (build it: ./granpen build)");
  if (!opt.mpirun.empty() && !on_path(opt.mpirun))
    throw InputError("mpirun not found: " + opt.mpirun + " (install openmpi-bin, or run without --mpirun)");
  for (const char *deck : {"in.pour", "in.push"})
    if (!exists(opt.inputs + "/" + deck)) throw InputError("no " + std::string(deck) + " in " + opt.inputs);
  if (opt.only_index >= 0 && tasks.size() != 1) throw InputError("--only runs one planned run of one sweep");
  for (size_t a = 0; a < tasks.size(); ++a)
    for (size_t b = a + 1; b < tasks.size(); ++b)
      if (tasks[a].spec.name == tasks[b].spec.name)
        throw InputError("two sweeps named " + tasks[a].spec.name + " in one pool would share a folder");
}

using RunKey = std::pair<size_t, size_t>;    // (sweep, job)

// The sweeps of a pool run as one: which run starts when, what ended, progress.
struct Pool {
  const std::vector<SweepTask> &tasks;
  const RunnerOptions &opt;
  std::vector<Sweep> sweeps;
  // a sweep that reuses another's beds: its pours become links to that sweep's pours
  struct Link { int sweep = -1; size_t job = 0; };
  std::map<RunKey, Link> links;
  std::vector<RunKey> order;    // pours (every push waits for one), then pushes, longest first
  Clock::time_point t0 = Clock::now(), last_report = Clock::now();
  int running = 0;
  bool manifest_failed = false;    // a manifest could not be written: said once, the sweeps fail

  Pool(const std::vector<SweepTask> &t, const RunnerOptions &o) : tasks(t), opt(o) {}
  ~Pool()
  {
    for (auto &sw : sweeps)
      for (auto &j : sw.jobs) unlock(j);
  }

  static double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
  bool planned_in(size_t k) const { return opt.only_index < 0 || (int) k == opt.only_index; }
  Job &job(const RunKey &r) { return sweeps[r.first].jobs[r.second]; }

  void write_manifest(const Sweep &sw);
  void plan_links();
  void plan_order();
  void start_ready();
  void reap(pid_t pid, int wstatus);
  void report_progress();
  void close_finished();
  int finish();
};

// A manifest that cannot be written is said once per pool, and the sweep counts as failed;
// the runs go on (their traces are what matters).
void Pool::write_manifest(const Sweep &sw)
{
  const std::string e = write_manifest_file(sw);
  if (e.empty()) return;
  if (!manifest_failed) std::fprintf(stderr, "granpen sweep %s: error: manifest: %s\n", sw.spec.name.c_str(), e.c_str());
  manifest_failed = true;
}

void Pool::plan_links()
{
  for (size_t s = 0; s < sweeps.size(); ++s) {
    const std::string &from = tasks[s].beds_from;
    if (from.empty()) continue;
    const std::string from_dir = opt.out_root + "/" + from;
    int src = -1;
    for (size_t t = 0; t < tasks.size(); ++t)
      if (tasks[t].spec.name == from) src = (int) t;
    for (size_t k = 0; k < sweeps[s].jobs.size(); ++k) {
      Job &j = sweeps[s].jobs[k];
      if (j.run.kind != PlannedRun::POUR || j.status == "skipped" || j.status == "failed") continue;
      if (exists(from_dir + "/beds/" + j.run.id + ".info")) {
        link_bed(from_dir, sweeps[s].dir, j.run.id);
        j.status = "skipped", j.action = "bed of " + from;
        unlock(j);
        continue;
      }
      Link l;
      if (src >= 0)
        for (size_t m = 0; m < sweeps[src].jobs.size(); ++m)
          if (sweeps[src].jobs[m].run.kind == PlannedRun::POUR && sweeps[src].jobs[m].run.id == j.run.id)
            l = {src, m};
      if (l.sweep < 0) throw InputError("no bed " + j.run.id + " in " + from_dir + " to reuse");
      j.action = "bed of " + from;
      links[{s, k}] = l;
    }
  }
}

void Pool::plan_order()
{
  for (size_t s = 0; s < sweeps.size(); ++s)
    for (size_t k = 0; k < sweeps[s].jobs.size(); ++k)
      if (planned_in(k)) order.emplace_back(s, k);
  if (opt.only_index >= 0 && order.empty())
    throw InputError("--only " + std::to_string(opt.only_index) + ": the sweep has " +
                     std::to_string(sweeps[0].jobs.size()) + " runs");
  std::stable_sort(order.begin(), order.end(), [&](const auto &a, const auto &b) {
    const Job &x = sweeps[a.first].jobs[a.second], &y = sweeps[b.first].jobs[b.second];
    const bool px = x.run.kind == PlannedRun::POUR, py = y.run.kind == PlannedRun::POUR;
    if (px != py) return px;
    return !px && push_steps(x, sweeps[a.first].spec) > push_steps(y, sweeps[b.first].spec);
  });
}

void Pool::start_ready()
{
  for (const auto &[s, k] : order) {
    Sweep &sw = sweeps[s];
    Job &j = sw.jobs[k];
    if (j.status != "pending") continue;
    const auto ln = links.find({s, k});
    if (ln != links.end()) {
      const Job &src = sweeps[ln->second.sweep].jobs[ln->second.job];
      if (src.status == "failed") j.status = "failed", j.error = "the bed it reuses failed";
      if (!finished(src)) continue;
      link_bed(sweeps[ln->second.sweep].dir, sw.dir, j.run.id);
      j.status = "done";
      unlock(j);
      write_manifest(sw);
      continue;
    }
    if (running >= opt.jobs) continue;
    if (j.run.kind == PlannedRun::PUSH) {
      const Job *b = nullptr;
      for (const auto &c : sw.jobs)
        if (c.run.kind == PlannedRun::POUR && c.run.id == j.run.bed) b = &c;
      if (b && b->status == "failed") {
        j.status = "failed";
        j.error = "its bed " + b->run.id + " failed";
        unlock(j);
        continue;
      }
      if (b && !finished(*b)) continue;    // the pour has not exited yet
    }
    j.pid = spawn(j.argv, j.out);
    if (j.pid < 0) throw InputError("cannot start " + j.argv[0] + ": " + std::strerror(errno));
    j.start = Clock::now();
    j.status = "running";
    ++running;
    std::printf("  start %s%s (%s)\n", sw.label.c_str(), j.run.id.c_str(), j.action.empty() ? "started" : j.action.c_str());
    std::fflush(stdout);
  }
}

void Pool::reap(pid_t pid, int wstatus)
{
  for (auto &sw : sweeps)
    for (auto &j : sw.jobs) {
      if (j.pid != pid || j.status != "running") continue;
      --running;
      j.wall = seconds_since(j.start);
      j.exit_code = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 128 + WTERMSIG(wstatus);
      const std::string log = slurp(j.log);
      if (sw.lammps_version.empty()) {
        auto l = first_line_matching(log, "LAMMPS (");
        if (!l.empty()) sw.lammps_version = l;
      }
      bool ok = j.exit_code == 0;
      if (ok && j.run.kind == PlannedRun::PUSH) ok = log.find("granpen push: done") != std::string::npos;
      if (ok && j.run.kind == PlannedRun::POUR) ok = exists(j.info);
      if (ok && !j.pour_checkpoints.empty()) remove_pour_checkpoints(j.pour_checkpoints);
      std::string e;
      if (ok && j.run.kind == PlannedRun::PUSH) {
        std::ostringstream done;
        done << "wall_seconds = " << j.wall << "\n";
        try {
          write_file_atomic(j.done, done.str());
        } catch (const OutputError &err) {
          ok = false;
          e = err.what();
        }
      }
      if (ok) {
        j.status = "done";
      } else {
        j.status = "failed";
        if (e.empty() && !WIFEXITED(wstatus)) e = exit_reason(wstatus);
        if (e.empty()) e = first_line_matching(log, "ERROR");
        if (e.empty()) e = first_line_matching(slurp(j.out), "ERROR");
        if (e.empty()) e = exit_reason(wstatus) + " (see " + j.out + ")";
        j.error = e;
      }
      unlock(j);
      std::printf("  %s %s%s in %s%s%s\n", j.status == "done" ? "done " : "FAILED", sw.label.c_str(),
                  j.run.id.c_str(), format_duration(j.wall).c_str(), j.error.empty() ? "" : ": ", j.error.c_str());
      std::fflush(stdout);
      write_manifest(sw);
    }
}

void Pool::report_progress()
{
  last_report = Clock::now();
  int done = 0, failed = 0, total = (int) order.size();
  double sum_pour = 0, sum_push = 0, own_left = 0;
  int n_pour = 0, n_push = 0, left_pour = 0, left_push = 0;
  std::string now;
  for (const auto &[s, k] : order) {
    Job &j = sweeps[s].jobs[k];
    const bool pour = j.run.kind == PlannedRun::POUR, linked = links.count({s, k}) > 0;
    if (finished(j)) ++done;
    if (j.status == "failed") ++failed;
    if (j.status == "done" && !linked) (pour ? (sum_pour += j.wall, ++n_pour) : (sum_push += j.wall, ++n_push));
    double own = NAN;    // a running push's own seconds left, from its rate since first seen
    if (j.status == "running") {
      char b[200];
      const std::string id = sweeps[s].label + j.run.id;
      double z = pour ? NAN : last_depth(j.trace);
      const std::string ps = pour ? pour_status(j.log) : "";
      if (std::isfinite(z)) {
        // a resumed push may first show rows past its checkpoint, which it then writes again
        if (!std::isfinite(j.z_seen) || z < j.z_seen) j.z_seen = z, j.z_seen_at = Clock::now();
        own = push_seconds_left(j.z_seen, z, seconds_since(j.z_seen_at), j.target_depth);
        if (std::isfinite(own))
          std::snprintf(b, sizeof(b), " %s z=%.2f of %.2f (%s left)", id.c_str(), z, j.target_depth,
                        format_duration(own).c_str());
        else std::snprintf(b, sizeof(b), " %s z=%.2f", id.c_str(), z);
      }
      else if (!ps.empty()) std::snprintf(b, sizeof(b), " %s (%s)", id.c_str(), ps.c_str());
      else std::snprintf(b, sizeof(b), " %s %s", id.c_str(), format_duration(seconds_since(j.start)).c_str());
      now += b;
    }
    if (std::isfinite(own)) own_left += own;
    else if ((j.status == "pending" && !linked) || j.status == "running") (pour ? ++left_pour : ++left_push);
  }
  // ETA: a running push's own rate where it has one, the mean time of the finished runs of
  // each kind for the rest
  double eta = NAN;
  if ((n_pour || !left_pour) && (n_push || !left_push))
    eta = ((n_pour ? sum_pour / n_pour : 0) * left_pour + (n_push ? sum_push / n_push : 0) * left_push + own_left) /
        std::max(1, opt.jobs);
  std::printf("  [%s] %d/%d done, %d failed; running:%s; ETA %s\n", format_duration(seconds_since(t0)).c_str(), done,
              total, failed, now.c_str(), format_duration(eta).c_str());
  std::fflush(stdout);
}

// a sweep whose planned runs have all ended gets its closing line
void Pool::close_finished()
{
  for (size_t s = 0; s < sweeps.size(); ++s) {
    Sweep &sw = sweeps[s];
    if (sw.reported) continue;
    int failed = 0, done = 0;
    bool open = false;
    for (size_t k = 0; k < sw.jobs.size(); ++k) {
      if (!planned_in(k)) continue;
      const Job &j = sw.jobs[k];
      if (!terminal(j)) open = true;
      failed += j.status == "failed", done += finished(j);
    }
    if (open) continue;
    sw.reported = true;
    write_manifest(sw);
    std::printf("granpen sweep %s: %d done, %d failed in %s; manifest %s/manifest.json\n", sw.spec.name.c_str(),
                done, failed, format_duration(seconds_since(t0)).c_str(), sw.dir.c_str());
    for (size_t k = 0; k < sw.jobs.size(); ++k)
      if (planned_in(k) && sw.jobs[k].action == "refused")
        std::printf("granpen sweep %s: refused %s: %s\n", sw.spec.name.c_str(), sw.jobs[k].run.id.c_str(),
                    sw.jobs[k].error.c_str());
    std::fflush(stdout);
  }
}

// the number of sweeps with a failed run (or an unwritable manifest)
int Pool::finish()
{
  // a run that could not start (its bed never came) is failed, not left pending
  for (const auto &[s, k] : order)
    if (Job &j = sweeps[s].jobs[k]; j.status == "pending") j.status = "failed", j.error = "not started: its bed was not made";
  close_finished();
  int failed_sweeps = 0;
  for (size_t s = 0; s < sweeps.size(); ++s) {
    bool any = manifest_failed;
    for (size_t k = 0; k < sweeps[s].jobs.size(); ++k)
      if (planned_in(k) && sweeps[s].jobs[k].status == "failed") any = true;
    failed_sweeps += any;
  }
  return failed_sweeps;
}
}    // namespace

int run_sweep(const SweepSpec &spec, const RunnerOptions &opt) { return run_sweeps({{spec, ""}}, opt) ? 1 : 0; }

int run_sweeps(const std::vector<SweepTask> &tasks, const RunnerOptions &opt)
{
  check_runner_inputs(tasks, opt);
  // a file that outgrows `ulimit -f` is a write error here (EFBIG), not the runner's death;
  // its children get the default back (spawn)
  signal(SIGXFSZ, SIG_IGN);
  Pool pool(tasks, opt);
  for (const auto &t : tasks) {
    pool.sweeps.push_back(setup_sweep(t, opt));
    if (tasks.size() > 1) pool.sweeps.back().label = t.spec.name + "/";
  }
  pool.plan_links();
  pool.plan_order();
  for (auto &sw : pool.sweeps) {
    int skipped = 0, planned = 0;
    for (const auto &[s, k] : pool.order)
      if (&pool.sweeps[s] == &sw) ++planned, skipped += sw.jobs[k].status == "skipped";
    std::printf("granpen sweep %s: %d runs (%d already done) in %s, up to %d at once%s\n", sw.spec.name.c_str(),
                planned, skipped, sw.dir.c_str(), opt.jobs,
                pool.sweeps.size() > 1 ? (" (a pool of " + std::to_string(pool.sweeps.size()) + " sweeps)").c_str() : "");
    pool.write_manifest(sw);
  }
  std::fflush(stdout);

  while (true) {
    pool.start_ready();
    pool.close_finished();
    if (pool.running == 0) break;
    int wstatus = 0;
    const pid_t pid = waitpid(-1, &wstatus, WNOHANG);
    if (pid > 0) {
      pool.reap(pid, wstatus);
      continue;
    }
    if (Pool::seconds_since(pool.last_report) >= opt.progress_seconds) pool.report_progress();
    // a free slot waits half a poll on average: at 200 ms that was 0.1 s a run, 23% of the
    // synthetic diagnosis's wall time (160 runs of about 0.5 s, bench/gap_cost.sh --synthetic
    // --jobs 1); at 10 ms it is 5 ms a run, and the wakeups cost nothing measurable
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return pool.finish();
}

void write_slurm_script(const SweepSpec &spec, const RunnerOptions &opt, const std::string &cli,
                        const std::string &file)
{
  // only paths we were given go into the script, each single-quoted; refuse quotes in them
  for (const auto &p : {cli, spec.path, opt.lmp, opt.inputs, opt.out_root})
    if (p.find('\'') != std::string::npos) throw InputError("a path with a single quote cannot go into a SLURM script: " + p);
  const auto plan = plan_sweep(spec);
  int npour = 0;
  for (const auto &r : plan)
    if (r.kind == PlannedRun::POUR) ++npour;
  const int nrun = (int) plan.size();
  auto q = [](const std::string &s) { return "'" + s + "'"; };
  const std::string run_one = q(cli) + " sweep " + q(spec.path) + " --lmp " + q(opt.lmp) + " --inputs " +
                              q(opt.inputs) + " --out " + q(opt.out_root) + " --mpirun srun --ranks " +
                              std::to_string(opt.ranks) + " --only";
  const std::vector<std::string> what = {
      "granpen sweep " + spec.name + ": submit with `bash " + file + "` on the cluster.",
      std::to_string(npour) + " pours as one job array, then " + std::to_string(nrun - npour) +
          " pushes as a second array that starts when every pour has succeeded.",
      "Each task runs one planned run with " + std::to_string(opt.ranks) + " MPI ranks; rerunning this script",
      "skips finished runs and resumes interrupted pushes from their checkpoints."};
  write_slurm_arrays(what, {{spec.name + "-pour", "pours", 0, npour - 1, run_one},
                            {spec.name + "-push", "pushes", npour, nrun - 1, run_one}},
                     opt.ranks, file);
}

}    // namespace granpen
