// granpen sweep: the runner's files (sweep_files.h).
#include "sweep_files.h"
#include "sweep_runner.h"    // complete_checkpoint

#include "errors.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace granpen {
namespace sweep_run {

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

}    // namespace sweep_run
}    // namespace granpen

// A checkpoint LAMMPS finished writing ends with the restart format's magic string
// (lmprestart.h, checked by read_restart); one cut short by a kill or a full disk does not,
// and is never resumed from.
bool granpen::complete_checkpoint(const std::string &p)
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
