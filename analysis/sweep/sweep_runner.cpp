// granpen sweep: the runner (processes, progress, resume, manifest).
#include "sweep_runner.h"

#include "json_text.h"
#include "trace_reader.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <map>
#include <signal.h>
#include <sstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace granpen {

namespace {

using Clock = std::chrono::steady_clock;

bool exists(const std::string &p)
{
  struct stat st;
  return stat(p.c_str(), &st) == 0;
}

double mtime(const std::string &p)
{
  struct stat st;
  if (stat(p.c_str(), &st) != 0) return -1.0;
  return st.st_mtim.tv_sec + 1e-9 * st.st_mtim.tv_nsec;
}

void mkdirs(const std::string &p)
{
  std::string cur;
  std::istringstream in(p);
  std::string part;
  if (!p.empty() && p[0] == '/') cur = "/";
  while (std::getline(in, part, '/')) {
    if (part.empty()) continue;
    cur += part + "/";
    if (mkdir(cur.c_str(), 0755) != 0 && errno != EEXIST)
      throw InputError("cannot create folder " + cur + ": " + std::strerror(errno));
  }
}

std::string slurp(const std::string &p)
{
  std::ifstream f(p);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

std::string first_line_matching(const std::string &text, const std::string &prefix)
{
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (line.compare(0, prefix.size(), prefix) == 0) return line;
  return "";
}

std::map<std::string, std::string> read_info(const std::string &p)
{
  std::map<std::string, std::string> kv;
  std::istringstream in(slurp(p));
  std::string line;
  while (std::getline(in, line)) {
    auto eq = line.find(" = ");
    if (line.empty() || line[0] == '#' || eq == std::string::npos) continue;
    kv[line.substr(0, eq)] = line.substr(eq + 3);
  }
  return kv;
}

// depth of the last row of a trace being written (z is the second column of our traces)
double last_depth(const std::string &trace)
{
  std::ifstream f(trace, std::ios::ate);
  if (!f) return NAN;
  const std::streamoff size = f.tellg();
  const std::streamoff back = std::min<std::streamoff>(size, 512);
  f.seekg(size - back);
  std::string tail(back, '\0');
  f.read(&tail[0], back);
  auto end = tail.find_last_not_of("\n");
  if (end == std::string::npos) return NAN;
  auto start = tail.rfind('\n', end);
  std::string line = tail.substr(start == std::string::npos ? 0 : start + 1, end - start);
  auto c1 = line.find(',');
  if (c1 == std::string::npos || line[0] == '#' || line[0] == 't') return NAN;
  return std::atof(line.c_str() + c1 + 1);
}

// an executable path, or a name found on PATH
bool on_path(const std::string &prog)
{
  if (prog.find('/') != std::string::npos) return access(prog.c_str(), X_OK) == 0;
  const char *path = std::getenv("PATH");
  std::istringstream in(path ? path : "");
  std::string dir;
  while (std::getline(in, dir, ':'))
    if (!dir.empty() && access((dir + "/" + prog).c_str(), X_OK) == 0) return true;
  return false;
}

// the last progress line a pour printed ("granpen pour: chunk 5/60: ..."), shortened
std::string pour_status(const std::string &log)
{
  std::ifstream f(log);
  std::string line, last;
  while (std::getline(f, line))
    if (line.compare(0, 14, "granpen pour: ") == 0) last = line.substr(14);
  auto colon = last.find(':');
  return last.substr(0, colon);
}

struct Job {
  PlannedRun run;
  std::vector<std::string> argv;
  std::string log, out, trace, info, done;
  std::string status = "pending";    // pending, running, done, skipped, failed
  std::string action;                // what was done: started, resumed, restarted, already done
  std::string error;
  int exit_code = 0;
  pid_t pid = -1;
  Clock::time_point start;
  double wall = 0.0;
  double target_depth = 0.0;
};

std::string fmt_seconds(double s)
{
  char buf[64];
  if (s < 0 || !std::isfinite(s)) return "?";
  if (s < 120) std::snprintf(buf, sizeof(buf), "%.0fs", s);
  else if (s < 7200) std::snprintf(buf, sizeof(buf), "%.0fm%02.0fs", std::floor(s / 60), std::fmod(s, 60));
  else std::snprintf(buf, sizeof(buf), "%.1fh", s / 3600);
  return buf;
}

pid_t spawn(const std::vector<std::string> &argv, const std::string &out)
{
  std::vector<char *> args;
  for (auto &a : argv) args.push_back(const_cast<char *>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = fork();
  if (pid == 0) {
    int fd = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, 1);
      dup2(fd, 2);
      close(fd);
    }
    int devnull = open("/dev/null", O_RDONLY);
    if (devnull >= 0) dup2(devnull, 0);
    execvp(args[0], args.data());
    std::fprintf(stderr, "cannot run %s: %s\n", args[0], std::strerror(errno));
    _exit(127);
  }
  return pid;
}

}    // namespace


int run_sweep(const SweepSpec &spec, const RunnerOptions &opt)
{
  if (access(opt.lmp.c_str(), X_OK) != 0)
    throw InputError("lmp_granpen not found or not executable: " + opt.lmp + " (build it: ./granpen build)");
  if (!opt.mpirun.empty() && !on_path(opt.mpirun))
    throw InputError("mpirun not found: " + opt.mpirun + " (install openmpi-bin, or run without --mpirun)");
  for (const char *deck : {"in.pour", "in.push"})
    if (!exists(opt.inputs + "/" + deck)) throw InputError("no " + std::string(deck) + " in " + opt.inputs);

  const std::string dir = opt.out_root + "/" + spec.name;
  mkdirs(dir + "/beds");
  mkdirs(dir + "/traces");
  mkdirs(dir + "/logs");
  const auto plan = plan_sweep(spec);

  std::vector<Job> jobs;
  for (const auto &r : plan) {
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
    jobs.push_back(j);
  }

  // what is already there: finished runs are skipped, interrupted pushes resumed
  for (auto &j : jobs) {
    if (j.run.kind == PlannedRun::POUR) {
      if (exists(j.info)) j.status = "skipped", j.action = "already done";
      continue;
    }
    const std::string ca = j.trace + ".a.restart", cb = j.trace + ".b.restart";
    const bool cp = exists(ca) || exists(cb);
    switch (push_action(exists(j.done), exists(j.trace), cp)) {
      case PushAction::SKIP_DONE: j.status = "skipped"; j.action = "already done"; break;
      case PushAction::RESUME: {
        const std::string from = mtime(ca) >= mtime(cb) ? ca : cb;
        j.argv.insert(j.argv.end() - 4, {"-var", "resume", "yes", "-var", "from", from});
        j.action = "resumed from " + from.substr(from.rfind('/') + 1);
        break;
      }
      case PushAction::RESTART_FRESH: {
        // an interrupted push with no checkpoint: keep its partial trace, start over
        int n = 1;
        while (exists(j.trace + ".partial" + std::to_string(n))) ++n;
        const std::string keep = j.trace + ".partial" + std::to_string(n);
        std::rename(j.trace.c_str(), keep.c_str());
        j.action = "restarted (partial trace kept as " + keep.substr(keep.rfind('/') + 1) + ")";
        break;
      }
      case PushAction::START: j.action = "started"; break;
    }
  }

  for (auto &j : jobs) {
    if (j.status != "skipped") continue;
    auto kv = read_info(j.run.kind == PlannedRun::POUR ? j.info : j.done);
    if (kv.count("wall_seconds")) j.wall = std::atof(kv["wall_seconds"].c_str());
  }

  std::vector<size_t> order;
  for (size_t i = 0; i < jobs.size(); ++i)
    if (opt.only_index < 0 || (int) i == opt.only_index) order.push_back(i);
  if (opt.only_index >= (int) jobs.size())
    throw InputError("--only " + std::to_string(opt.only_index) + ": the sweep has " +
                     std::to_string(jobs.size()) + " runs");

  // the LAMMPS version from any log already there (all runs may be skipped)
  std::string lammps_version;
  for (const auto &j : jobs)
    if (lammps_version.empty() && exists(j.log)) lammps_version = first_line_matching(slurp(j.log), "LAMMPS (");
  // Runs of other sweep files with the same name (sharing its beds, e.g. a v0 and a g sweep)
  // stay in the manifest: each run is one line, keyed by its id.
  std::vector<std::string> other_runs;
  if (exists(dir + "/manifest.json")) {
    std::istringstream in(slurp(dir + "/manifest.json"));
    const std::string key = "    {\"id\": ";
    for (std::string line; std::getline(in, line);) {
      if (line.compare(0, key.size(), key) != 0) continue;
      const bool planned = std::any_of(jobs.begin(), jobs.end(), [&](const Job &j) {
        return line.compare(key.size(), json_string(j.run.id).size() + 1, json_string(j.run.id) + ",") == 0;
      });
      if (planned) continue;
      if (!line.empty() && line.back() == ',') line.pop_back();
      other_runs.push_back(line);
    }
  }
  auto write_manifest = [&]() {
    const std::string tmp = dir + "/manifest.json.tmp";
    std::FILE *f = std::fopen(tmp.c_str(), "w");
    if (!f) return;
    std::fprintf(f, "{\n  \"sweep\": %s,\n  \"spec\": %s,\n  \"granpen\": %s,\n  \"lammps\": %s,\n  \"runs\": [\n",
                 json_string(spec.name).c_str(), json_string(spec.path).c_str(),
                 json_string(GRANPEN_VERSION).c_str(), json_string(lammps_version).c_str());
    for (const auto &line : other_runs) std::fprintf(f, "%s,\n", line.c_str());
    for (size_t i = 0; i < jobs.size(); ++i) {
      const auto &j = jobs[i];
      const auto &r = j.run;
      std::fprintf(f, "    {\"id\": %s, \"kind\": \"%s\", \"status\": %s, \"action\": %s, \"preset\": %s, "
                      "\"mu\": %s, \"seed\": %s",
                   json_string(r.id).c_str(), r.kind == PlannedRun::POUR ? "pour" : "push",
                   json_string(j.status).c_str(), json_string(j.action).c_str(), json_string(r.preset).c_str(),
                   json_string(r.mu).c_str(), json_string(r.seed).c_str());
      if (r.kind == PlannedRun::POUR) {
        auto info = exists(j.info) ? read_info(j.info) : std::map<std::string, std::string>{};
        for (const char *k : {"z_s", "phi_0", "grains", "wall_seconds"})
          if (info.count(k) && positive_number(info[k])) std::fprintf(f, ", \"%s\": %s", k, info[k].c_str());
        std::fprintf(f, ", \"bed\": %s", json_string(dir + "/beds/" + r.id + ".restart").c_str());
      } else {
        std::fprintf(f, ", \"bed\": %s, \"v0\": %s, \"g\": %s, \"D\": %s, \"depth\": %s, \"mu_push\": %s, "
                        "\"trace\": %s",
                     json_string(r.bed).c_str(), json_string(r.v0).c_str(), json_string(r.g).c_str(),
                     json_string(r.D).c_str(), json_string(r.depth).c_str(), json_string(r.mu_push).c_str(),
                     json_string(j.trace).c_str());
      }
      std::fprintf(f, ", \"log\": %s, \"wall_seconds_run\": %.3f, \"exit_code\": %d, \"error\": %s}%s\n",
                   json_string(j.log).c_str(), j.wall, j.exit_code, json_string(j.error).c_str(),
                   i + 1 < jobs.size() ? "," : "");
    }
    std::fprintf(f, "  ]\n}\n");
    std::fclose(f);
    std::rename(tmp.c_str(), (dir + "/manifest.json").c_str());
  };

  const auto t0 = Clock::now();
  auto seconds_since = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };
  auto bed_job = [&](const Job &j) -> const Job * {
    for (const auto &b : jobs)
      if (b.run.kind == PlannedRun::POUR && b.run.id == j.run.bed) return &b;
    return nullptr;
  };

  int skipped = 0;
  for (size_t i : order)
    if (jobs[i].status == "skipped") ++skipped;
  std::printf("granpen sweep %s: %zu runs (%d already done) in %s, up to %d at once\n", spec.name.c_str(),
              order.size(), skipped, dir.c_str(), opt.jobs);
  std::fflush(stdout);
  write_manifest();

  auto last_report = Clock::now();
  int running = 0;
  while (true) {
    // start what can start
    for (size_t i : order) {
      Job &j = jobs[i];
      if (j.status != "pending" || running >= opt.jobs) continue;
      if (j.run.kind == PlannedRun::PUSH) {
        const Job *b = bed_job(j);
        if (b && (b->status == "failed")) {
          j.status = "failed";
          j.error = "its bed " + b->run.id + " failed";
          continue;
        }
        if (b && b->status != "done" && b->status != "skipped") continue;    // the pour has exited
      }
      j.pid = spawn(j.argv, j.out);
      j.start = Clock::now();
      j.status = "running";
      ++running;
      std::printf("  start %s (%s)\n", j.run.id.c_str(), j.action.empty() ? "started" : j.action.c_str());
      std::fflush(stdout);
    }
    if (running == 0) break;

    int wstatus = 0;
    pid_t pid = waitpid(-1, &wstatus, WNOHANG);
    if (pid > 0) {
      for (auto &j : jobs) {
        if (j.pid != pid || j.status != "running") continue;
        --running;
        j.wall = seconds_since(j.start);
        j.exit_code = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 128 + WTERMSIG(wstatus);
        const std::string log = slurp(j.log);
        if (lammps_version.empty()) {
          auto l = first_line_matching(log, "LAMMPS (");
          if (!l.empty()) lammps_version = l;
        }
        bool ok = j.exit_code == 0;
        if (ok && j.run.kind == PlannedRun::PUSH) ok = log.find("granpen push: done") != std::string::npos;
        if (ok && j.run.kind == PlannedRun::POUR) ok = exists(j.info);
        if (ok) {
          j.status = "done";
          if (j.run.kind == PlannedRun::PUSH) {
            std::ofstream(j.done) << "wall_seconds = " << j.wall << "\n";
          }
        } else {
          j.status = "failed";
          std::string e = first_line_matching(log, "ERROR");
          if (e.empty()) e = first_line_matching(slurp(j.out), "ERROR");
          if (e.empty()) e = "exit code " + std::to_string(j.exit_code) + " (see " + j.out + ")";
          j.error = e;
        }
        std::printf("  %s %s in %s%s%s\n", j.status == "done" ? "done " : "FAILED", j.run.id.c_str(),
                    fmt_seconds(j.wall).c_str(), j.error.empty() ? "" : ": ", j.error.c_str());
        std::fflush(stdout);
        write_manifest();
      }
      continue;
    }

    if (seconds_since(last_report) >= opt.progress_seconds) {
      last_report = Clock::now();
      int done = 0, failed = 0, total = (int) order.size();
      double sum_pour = 0, sum_push = 0;
      int n_pour = 0, n_push = 0, left_pour = 0, left_push = 0;
      std::string now;
      for (size_t i : order) {
        const Job &j = jobs[i];
        const bool pour = j.run.kind == PlannedRun::POUR;
        if (j.status == "done" || j.status == "skipped") ++done;
        if (j.status == "failed") ++failed;
        if (j.status == "done") (pour ? (sum_pour += j.wall, ++n_pour) : (sum_push += j.wall, ++n_push));
        if (j.status == "pending" || j.status == "running") (pour ? ++left_pour : ++left_push);
        if (j.status == "running") {
          char b[160];
          double z = pour ? NAN : last_depth(j.trace);
          const std::string ps = pour ? pour_status(j.log) : "";
          if (std::isfinite(z)) std::snprintf(b, sizeof(b), " %s z=%.2f", j.run.id.c_str(), z);
          else if (!ps.empty()) std::snprintf(b, sizeof(b), " %s (%s)", j.run.id.c_str(), ps.c_str());
          else std::snprintf(b, sizeof(b), " %s %s", j.run.id.c_str(), fmt_seconds(seconds_since(j.start)).c_str());
          now += b;
        }
      }
      // ETA from the mean time of the finished runs of each kind
      double eta = NAN;
      if ((n_pour || !left_pour) && (n_push || !left_push))
        eta = ((n_pour ? sum_pour / n_pour : 0) * left_pour + (n_push ? sum_push / n_push : 0) * left_push) /
            std::max(1, opt.jobs);
      std::printf("  [%s] %d/%d done, %d failed; running:%s; ETA %s\n", fmt_seconds(seconds_since(t0)).c_str(),
                  done, total, failed, now.c_str(), fmt_seconds(eta).c_str());
      std::fflush(stdout);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }

  int failed = 0, done = 0;
  for (size_t i : order) {
    if (jobs[i].status == "failed") ++failed;
    if (jobs[i].status == "done" || jobs[i].status == "skipped") ++done;
  }
  write_manifest();
  std::printf("granpen sweep %s: %d done, %d failed in %s; manifest %s/manifest.json\n", spec.name.c_str(), done,
              failed, fmt_seconds(seconds_since(t0)).c_str(), dir.c_str());
  return failed ? 1 : 0;
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
  std::ofstream f(file);
  if (!f) throw InputError("cannot write " + file);
  auto q = [](const std::string &s) { return "'" + s + "'"; };
  const std::string run_one = q(cli) + " sweep " + q(spec.path) + " --lmp " + q(opt.lmp) + " --inputs " +
                              q(opt.inputs) + " --out " + q(opt.out_root) + " --mpirun srun --ranks " +
                              std::to_string(opt.ranks) + " --only";
  f << "#!/bin/bash\n"
    << "# granpen sweep " << spec.name << ": submit with `bash " << file << "` on the cluster.\n"
    << "# " << npour << " pours as one job array, then " << nrun - npour
    << " pushes as a second array that starts when every pour has succeeded.\n"
    << "# Each task runs one planned run with " << opt.ranks << " MPI ranks; rerunning this script\n"
    << "# skips finished runs and resumes interrupted pushes from their checkpoints.\n"
    << "set -euo pipefail\n"
    << "SBATCH_OPTS=${SBATCH_OPTS:-}   # e.g. --partition=... --time=...\n"
    << "pours=$(sbatch --parsable $SBATCH_OPTS --job-name=" << spec.name << "-pour --ntasks=" << opt.ranks
    << " --array=0-" << npour - 1 << " --wrap=\"" << run_one << " \\$SLURM_ARRAY_TASK_ID\")\n"
    << "sbatch $SBATCH_OPTS --job-name=" << spec.name << "-push --ntasks=" << opt.ranks
    << " --dependency=afterok:$pours --array=" << npour << "-" << nrun - 1 << " --wrap=\"" << run_one
    << " \\$SLURM_ARRAY_TASK_ID\"\n";
}

}    // namespace granpen
