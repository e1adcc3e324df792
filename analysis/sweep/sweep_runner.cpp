// granpen sweep: the runner (processes, progress, resume, manifest).
#include "sweep_runner.h"

#include "atomic_file.h"
#include "json_writer.h"
#include "slurm_script.h"
#include "errors.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <new>
#include <signal.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sstream>
#include <sys/stat.h>
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
  std::string pour_checkpoints;      // a checkpointed pour's NAME.pour (pour_checkpoint = yes)
  std::string status = "pending";    // pending, running, done, skipped, failed
  std::string action;                // what was done: started, resumed, restarted, already done
  std::string error;
  int exit_code = 0;
  pid_t pid = -1;
  Clock::time_point start;
  double wall = 0.0;
  double target_depth = 0.0;
  int lock_fd = -1;                  // the run's lock while this runner holds it
};

void unlock(Job &j)
{
  if (j.lock_fd >= 0) close(j.lock_fd);
  j.lock_fd = -1;
}


// Starts argv with stdout and stderr into out. The child is a process group of its own and
// dies with the runner (PR_SET_PDEATHSIG): a runner killed with -9 leaves no LAMMPS behind
// writing the trace and checkpoints a resumed runner writes too. The run's lock is not
// inherited (close-on-exec): an MPI program forks helpers (Open MPI's singleton orted)
// that would keep it held long after the run.
pid_t spawn(const std::vector<std::string> &argv, const std::string &out)
{
  std::vector<char *> args;
  for (auto &a : argv) args.push_back(const_cast<char *>(a.c_str()));
  args.push_back(nullptr);
  const pid_t runner = getpid();
  pid_t pid = fork();
  if (pid == 0) {
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != runner) _exit(127);    // the runner died before prctl took effect
    signal(SIGXFSZ, SIG_DFL);                // the runner ignores it; LAMMPS must not write on past the limit
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
  if (pid > 0) setpgid(pid, pid);    // on both sides: whichever runs first
  return pid;
}

// The lock of one run, DIR/locks/ID.lock: an flock the runner holds from before the run's
// files are looked at until the run ends (its process dies with the runner); the file
// names the runner's pid. Returns the descriptor (close-on-exec), or -1 with holder set to the text
// of the file (the holder's pid) when another process holds it.
int lock_run(const std::string &path, std::string &holder)
{
  const int fd = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw InputError("cannot open lock file " + path + ": " + std::strerror(errno));
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    char buf[64] = {0};
    const ssize_t n = pread(fd, buf, sizeof buf - 1, 0);
    holder = n > 0 ? std::string(buf, (std::size_t) n) : std::string("?");
    while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' ')) holder.pop_back();
    close(fd);
    return -1;
  }
  const std::string pid = std::to_string(getpid()) + "\n";
  if (ftruncate(fd, 0) != 0 || pwrite(fd, pid.data(), pid.size(), 0) != (ssize_t) pid.size()) {
    const std::string e = std::strerror(errno);
    close(fd);
    throw InputError("cannot write lock file " + path + ": " + e);
  }
  return fd;
}

// A checkpoint LAMMPS finished writing ends with the restart format's magic string
// (lmprestart.h, checked by read_restart); one cut short by a kill or a full disk does not,
// and is never resumed from.
bool complete_checkpoint(const std::string &p)
{
  static const char magic[] = "LammpS RestartT";    // written with its '\0'
  const int fd = open(p.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  struct stat st;
  char tail[sizeof magic] = {0};
  const bool ok = fstat(fd, &st) == 0 && st.st_size >= (off_t) sizeof magic &&
                  pread(fd, tail, sizeof magic, st.st_size - (off_t) sizeof magic) == (ssize_t) sizeof magic &&
                  std::memcmp(tail, magic, sizeof magic) == 0;
  close(fd);
  return ok;
}

// "exit code N" or the signal that ended a run, with what it means when it is a known fault
std::string exit_reason(int wstatus)
{
  if (WIFEXITED(wstatus)) return "exit code " + std::to_string(WEXITSTATUS(wstatus));
  const int sig = WTERMSIG(wstatus);
  if (sig == SIGXFSZ) return "killed by SIGXFSZ: a file reached the file size limit (ulimit -f)";
  return "killed by signal " + std::to_string(sig) + " (" + strsignal(sig) + ")";
}

// One sweep of a pool: its runs, its folder and what its manifest keeps.
struct Sweep {
  SweepSpec spec;
  std::string dir;
  std::string label;                       // "NAME/" before run ids when a pool has several sweeps
  std::vector<Job> jobs;
  std::vector<Json> other_runs;            // manifest records of other sweep files of this name
  std::map<std::string, Json> held_runs;   // manifest records of runs another process holds
  std::string lammps_version;
  bool reported = false;                   // its closing line printed
};

bool finished(const Job &j) { return j.status == "done" || j.status == "skipped"; }
bool terminal(const Job &j) { return finished(j) || j.status == "failed"; }

// a bed (restart and info) of another sweep, hard-linked (copied across file systems)
void link_bed(const std::string &from_dir, const std::string &to_dir, const std::string &id)
{
  namespace fs = std::filesystem;
  for (const char *ext : {".restart", ".info"}) {
    const fs::path src = from_dir + "/beds/" + id + ext, dst = to_dir + "/beds/" + id + ext;
    if (fs::exists(dst)) continue;
    std::error_code ec;
    fs::create_hard_link(src, dst, ec);
    if (ec) fs::copy_file(src, dst, ec);
    if (ec) throw InputError("cannot link " + src.string() + " to " + dst.string() + ": " + ec.message());
  }
}

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

// A finished pour's checkpoints (NAME.pour.state, NAME.pour.STEP.restart): in.pour removes
// the one its state names, but a kill between LAMMPS writing a restart and the deck
// renaming the state leaves that newer restart behind, which only a listing finds.
void remove_pour_checkpoints(const std::string &stem)    // DIR/NAME.pour
{
  namespace fs = std::filesystem;
  const fs::path pour(stem);
  const std::string prefix = pour.filename().string() + ".";
  std::error_code ec;
  std::vector<fs::path> left;
  for (const auto &e : fs::directory_iterator(pour.parent_path(), ec))
    if (e.path().filename().string().rfind(prefix, 0) == 0) left.push_back(e.path());
  for (const auto &p : left) fs::remove(p, ec);
}

// in.pour's NAME.pour.state: LAMMPS variable commands; the phase and the saved step
std::pair<std::string, std::string> read_pour_state(const std::string &path)
{
  std::ifstream in(path);
  std::string line, phase, step;
  while (std::getline(in, line)) {
    std::istringstream w(line);
    std::string cmd, name, style, value;
    if (!(w >> cmd >> name >> style >> value) || cmd != "variable") continue;
    if (name == "phase") phase = value;
    if (name == "step_saved" && value.find_first_not_of("0123456789") == std::string::npos) step = value;
  }
  return {phase, step};
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
      break;
    }
    case PushAction::START: j.action = "started"; break;
  }
}

// The runs of DIR/manifest.json: its "runs", or, when the file is not valid JSON (written
// by hand, or by a granpen older than the atomic write), every line that is one run's
// record on its own (the writer puts each run on one line); a warning names the file.
std::vector<Json> manifest_runs(const std::string &path)
{
  std::vector<Json> runs;
  const std::string text = slurp(path);
  try {
    const Json m = Json::parse(text);
    if (m.is_object() && m.contains("runs") && m["runs"].is_array())
      for (const auto &r : m["runs"])
        if (r.is_object() && r.contains("id") && r["id"].is_string()) runs.push_back(r);
    return runs;
  } catch (const Json::exception &e) {
    std::fprintf(stderr, "granpen sweep: warning: %s is not valid JSON (%s); keeping the runs of its lines that are\n",
                 path.c_str(), e.what());
  }
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    while (!line.empty() && (line.back() == ',' || line.back() == ' ')) line.pop_back();
    const Json r = Json::parse(line, nullptr, false);
    if (r.is_object() && r.contains("id") && r["id"].is_string()) runs.push_back(r);
  }
  return runs;
}

// Runs of other sweep files with the same name (sharing its beds, e.g. a v0 and a g sweep)
// stay in the manifest, keyed by their ids; so do the records of runs another process holds.
void keep_other_runs(Sweep &sw)
{
  const std::string path = sw.dir + "/manifest.json";
  if (!exists(path)) return;
  for (auto &run : manifest_runs(path)) {
    const std::string id = run["id"].get<std::string>();
    const auto planned = std::find_if(sw.jobs.begin(), sw.jobs.end(), [&](const Job &j) { return j.run.id == id; });
    if (planned == sw.jobs.end()) sw.other_runs.push_back(std::move(run));
    else if (planned->action == "refused") sw.held_runs[id] = std::move(run);
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

// A number of a .info file as JSON: as written when it is a JSON number, else its value.
Json info_number(const std::string &text)
{
  const Json v = Json::parse(text, nullptr, false);
  return v.is_number() ? v : Json(std::strtod(text.c_str(), nullptr));
}

// one run's record of the manifest
Json manifest_run(const Sweep &sw, const Job &j)
{
  const auto &r = j.run;
  Json m;
  m["id"] = r.id;
  m["kind"] = r.kind == PlannedRun::POUR ? "pour" : "push";
  m["status"] = j.status;
  m["action"] = j.action;
  m["preset"] = r.preset;
  m["mu"] = r.mu;
  m["seed"] = r.seed;
  if (r.kind == PlannedRun::POUR) {
    auto info = exists(j.info) ? read_info(j.info) : std::map<std::string, std::string>{};
    for (const char *k : {"z_s", "phi_0", "grains", "wall_seconds"})
      if (info.count(k) && positive_number(info[k])) m[k] = info_number(info[k]);
    m["bed"] = sw.dir + "/beds/" + r.id + ".restart";
  } else {
    m["bed"] = r.bed;
    m["v0"] = r.v0;
    m["g"] = r.g;
    m["D"] = r.D;
    m["depth"] = r.depth;
    m["mu_push"] = r.mu_push;
    m["trace"] = j.trace;
  }
  m["log"] = j.log;
  m["wall_seconds_run"] = json_rounded("%.3f", j.wall);
  m["exit_code"] = j.exit_code;
  m["error"] = j.error;
  return m;
}

// DIR/manifest.json (docs/sweeps.md), every run one line; a run another process holds
// keeps the record that process wrote.
Json manifest_json(const Sweep &sw)
{
  Json m;
  m["sweep"] = sw.spec.name;
  m["spec"] = sw.spec.path;
  m["granpen"] = GRANPEN_VERSION;
  m["lammps"] = sw.lammps_version;
  m["runs"] = Json::array();
  for (const auto &r : sw.other_runs) m["runs"].push_back(r);
  for (const auto &j : sw.jobs) {
    if (j.action == "refused") {
      const auto held = sw.held_runs.find(j.run.id);
      if (held != sw.held_runs.end()) m["runs"].push_back(held->second);
      continue;
    }
    m["runs"].push_back(manifest_run(sw, j));
  }
  return m;
}

// Writes DIR/manifest.json through io/atomic_file (a temporary of this process's own:
// SLURM tasks of one sweep write it too; every step checked). Returns "" or what failed.
std::string write_manifest_file(const Sweep &sw)
{
  try {
    write_json(sw.dir + "/manifest.json", manifest_json(sw), 1);
  } catch (const OutputError &e) {
    return e.what();
  }
  return "";
}

// A manifest that cannot be written is said once per sweep, and the sweep counts as failed;
// the runs go on (their traces are what matters).
bool manifest_failed = false;
void write_manifest(const Sweep &sw)
{
  const std::string e = write_manifest_file(sw);
  if (e.empty()) return;
  if (!manifest_failed) std::fprintf(stderr, "granpen sweep %s: error: manifest: %s\n", sw.spec.name.c_str(), e.c_str());
  manifest_failed = true;
}

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

  Pool(const std::vector<SweepTask> &t, const RunnerOptions &o) : tasks(t), opt(o) {}
  ~Pool()
  {
    for (auto &sw : sweeps)
      for (auto &j : sw.jobs) unlock(j);
  }

  static double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
  bool planned_in(size_t k) const { return opt.only_index < 0 || (int) k == opt.only_index; }
  Job &job(const RunKey &r) { return sweeps[r.first].jobs[r.second]; }

  void plan_links();
  void plan_order();
  void start_ready();
  void reap(pid_t pid, int wstatus);
  void report_progress();
  void close_finished();
  int finish();
};

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
  double sum_pour = 0, sum_push = 0;
  int n_pour = 0, n_push = 0, left_pour = 0, left_push = 0;
  std::string now;
  for (const auto &[s, k] : order) {
    const Job &j = sweeps[s].jobs[k];
    const bool pour = j.run.kind == PlannedRun::POUR, linked = links.count({s, k}) > 0;
    if (finished(j)) ++done;
    if (j.status == "failed") ++failed;
    if (j.status == "done" && !linked) (pour ? (sum_pour += j.wall, ++n_pour) : (sum_push += j.wall, ++n_push));
    if ((j.status == "pending" && !linked) || j.status == "running") (pour ? ++left_pour : ++left_push);
    if (j.status == "running") {
      char b[200];
      const std::string id = sweeps[s].label + j.run.id;
      double z = pour ? NAN : last_depth(j.trace);
      const std::string ps = pour ? pour_status(j.log) : "";
      if (std::isfinite(z)) std::snprintf(b, sizeof(b), " %s z=%.2f", id.c_str(), z);
      else if (!ps.empty()) std::snprintf(b, sizeof(b), " %s (%s)", id.c_str(), ps.c_str());
      else std::snprintf(b, sizeof(b), " %s %s", id.c_str(), format_duration(seconds_since(j.start)).c_str());
      now += b;
    }
  }
  // ETA from the mean time of the finished runs of each kind
  double eta = NAN;
  if ((n_pour || !left_pour) && (n_push || !left_push))
    eta = ((n_pour ? sum_pour / n_pour : 0) * left_pour + (n_push ? sum_push / n_push : 0) * left_push) /
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
  manifest_failed = false;
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
    write_manifest(sw);
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
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
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
