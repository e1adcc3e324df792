// A stand-in for lmp_granpen for the sweep runner's fault tests: the runner's command line
// and files (in.pour: OUT.restart + OUT.info; in.push: a granpen-trace v1, checkpoints
// TRACE.a/b.restart every `checkpoint` rows, resume from one, a log ending "granpen push:
// done"), slowly enough to be killed in the middle of anything, and deterministically:
// every value follows from the seed and the row, so a resumed run must give a trace equal
// byte for byte to an uninterrupted one. Like LAMMPS, a checkpoint ends with the restart
// format's magic string, and resuming from one without it is an ERROR.
//   FAULT_LMP_MS: milliseconds per push row and per pour chunk (default 4)
#include "lmp_command_line.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <unistd.h>

namespace {

const char kMagic[] = "LammpS RestartT";    // written with its '\0', as LAMMPS does

void nap()
{
  const char *ms = std::getenv("FAULT_LMP_MS");
  std::this_thread::sleep_for(std::chrono::milliseconds(ms ? std::atoi(ms) : 4));
}

// a row's force: a hash of seed and row, as text with a fixed format
double force(int seed, long i)
{
  unsigned long long h = 1469598103934665603ull ^ (unsigned long long) seed;
  h = (h ^ (unsigned long long) i) * 1099511628211ull;
  h ^= h >> 29;
  return 1000.0 * (double) i + (double) (h % 100000) / 100.0;
}

// writes a file in pieces, with naps between them, so that a kill can cut it short
bool write_slowly(const std::string &path, const std::string &text)
{
  std::FILE *f = std::fopen(path.c_str(), "wb");
  if (!f) return false;
  const std::size_t piece = 1024;
  for (std::size_t at = 0; at < text.size(); at += piece) {
    if (std::fwrite(text.data() + at, 1, std::min(piece, text.size() - at), f) == 0) break;
    std::fflush(f);
    if (at % (8 * piece) == 0) nap();
  }
  return std::fclose(f) == 0;
}

std::string checkpoint_text(long row)
{
  std::string s = "fault_lmp checkpoint\nrow " + std::to_string(row) + "\n";
  // growing with the row, so that a file size limit lets early checkpoints through and
  // cuts a later one short (the fault test's full disk)
  s += std::string(1000 + 200 * (std::size_t) row, '.');
  s += "\n";
  s.append(kMagic, sizeof kMagic);
  return s;
}

}    // namespace

int main(int argc, char **argv)
{
  auto cmd = read_lmp_command_line(argc, argv);
  auto &var = cmd.var;
  const std::string &in = cmd.in, &log = cmd.log;
  std::ofstream L(log.empty() ? "/dev/null" : log);
  L << "LAMMPS (fault_lmp: the sweep runner's fault tests)" << std::endl;
  const int seed = std::atoi(var.count("seed") ? var["seed"].c_str() : var["run"].c_str());
  if (in.size() >= 7 && in.compare(in.size() - 7, 7, "in.pour") == 0) {
    // the bed: 40 chunks of deterministic text, written as it is "poured"
    const std::string out = var["out"];
    std::string bed;
    for (int c = 0; c < 40; ++c) {
      nap();
      L << "granpen pour: chunk " << c + 1 << "/40: settling" << std::endl;
      for (int k = 0; k < 20; ++k) bed += std::to_string(force(seed, 40 * c + k)) + "\n";
    }
    bed.append(kMagic, sizeof kMagic);
    if (!write_slowly(out + ".restart", bed)) return 1;
    std::ofstream(out + ".info") << "z_s = 5.7\nphi_0 = 0.58\ngrains = 1900\nwall_seconds = 1\n";
    L << "granpen pour: bed " << out << ".restart" << std::endl;
    return 0;
  }

  const std::string trace = var["trace"];
  const double v0 = std::atof(var["v0"].c_str()), depth = std::atof(var["depth"].c_str()), dt = 1e-4;
  const long rows = (long) ((depth + 0.5) / (v0 * dt)) + 1;
  const long every = var.count("checkpoint") ? std::atol(var["checkpoint"].c_str()) : 0;
  long first = 0;
  std::FILE *T = nullptr;
  if (var["resume"] == "yes") {
    // the checkpoint: complete (magic at its end) or an ERROR, as read_restart does
    std::ifstream cf(var["from"], std::ios::binary);
    std::stringstream ss;
    ss << cf.rdbuf();
    const std::string c = ss.str();
    if (c.size() < sizeof kMagic || std::memcmp(c.data() + c.size() - sizeof kMagic, kMagic, sizeof kMagic) != 0) {
      L << "ERROR: Incomplete or corrupted LAMMPS restart file (fault_lmp)" << std::endl;
      return 1;
    }
    const long k = std::atol(c.c_str() + c.find("row ") + 4);
    // keep the header and rows 0..k, drop later rows (as fix rod/drive does)
    std::ifstream tf(trace);
    std::string line, kept;
    long row = -1;
    while (std::getline(tf, line)) {
      if (line.empty() || line[0] == '#' || line[0] == 't') {
        kept += line + "\n";
        continue;
      }
      if (++row > k) break;
      kept += line + "\n";
    }
    std::ofstream(trace, std::ios::trunc) << kept;
    L << "fault_lmp: resumed at row " << k + 1 << std::endl;
    first = k + 1;
    T = std::fopen(trace.c_str(), "a");
  } else {
    T = std::fopen(trace.c_str(), "w");
    if (T) std::fprintf(T, "# granpen-trace v1\n# units = cgs\n# v0 = %g\n# D = 2\n# g = 981\n# run = %d\nt,z,F\n", v0, seed);
  }
  if (!T) {
    L << "ERROR: cannot open trace " << trace << std::endl;
    return 1;
  }
  for (long i = first; i < rows; ++i) {
    nap();
    std::fprintf(T, "%.6f,%.6f,%.2f\n", i * dt, -0.5 + v0 * i * dt, force(seed, i));
    if (std::fflush(T) != 0) {
      L << "ERROR: cannot write trace " << trace << std::endl;
      return 1;
    }
    if (every > 0 && (i + 1) % every == 0) {
      const std::string cp = trace + ((i + 1) / every % 2 ? ".a.restart" : ".b.restart");
      if (!write_slowly(cp, checkpoint_text(i))) {
        L << "ERROR: cannot write restart file " << cp << std::endl;
        return 1;
      }
    }
  }
  std::fclose(T);
  L << "granpen push: done, depth " << depth << " cm" << std::endl;
  return 0;
}
