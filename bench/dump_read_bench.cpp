// Driver of bench/dump_read.sh: writes a large LAMMPS dump, and reads dumps with
// granpen::DumpReader, printing what it read and how fast.
//   dump_read_bench make OUT ATOMS MEGABYTES   one frame of ATOMS grains in LAMMPS's
//                                              `dump custom` layout and default formats
//                                              (id type x y z vx vy vz radius, %g),
//                                              repeated until the file holds MEGABYTES
//   dump_read_bench read FILE...               read every frame; prints
//                                              "frames N atoms N bytes N seconds S MB/s R sum X"
#include "dump_reader.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace {

int make(const char *out, long natoms, double megabytes)
{
  const double box = 40.0;
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> nv(0.0, 5.0);
  std::string atoms;
  char line[1024];
  for (long i = 0; i < natoms; ++i) {
    int n = std::snprintf(line, sizeof line, "%ld %d %g %g %g %g %g %g %g\n", i + 1, 1, box * u(rng), box * u(rng),
                          2 * box * u(rng), nv(rng), nv(rng), nv(rng), 0.2 * (1.0 + 0.1 * (u(rng) - 0.5)));
    atoms.append(line, n);
  }
  FILE *f = std::fopen(out, "wb");
  if (!f) {
    std::perror(out);
    return 1;
  }
  const double target = megabytes * 1e6;
  double written = 0;
  for (long step = 0; written < target; step += 1000) {
    int n = std::snprintf(line, sizeof line,
                          "ITEM: TIMESTEP\n%ld\nITEM: NUMBER OF ATOMS\n%ld\nITEM: BOX BOUNDS pp pp fm\n"
                          "%-1.16e %-1.16e\n%-1.16e %-1.16e\n%-1.16e %-1.16e\n"
                          "ITEM: ATOMS id type x y z vx vy vz radius\n",
                          step, natoms, 0.0, box, 0.0, box, 0.0, 2 * box);
    if (std::fwrite(line, 1, n, f) != (size_t) n || std::fwrite(atoms.data(), 1, atoms.size(), f) != atoms.size()) {
      std::perror(out);
      return 1;
    }
    written += n + atoms.size();
  }
  if (std::fclose(f) != 0) {
    std::perror(out);
    return 1;
  }
  std::printf("wrote %s: %.0f bytes\n", out, written);
  return 0;
}

int read(const std::vector<std::string> &paths)
{
  auto t0 = std::chrono::steady_clock::now();
  granpen::DumpReader reader(paths);
  granpen::DumpFrame frame;
  unsigned long long atoms = 0;
  double sum = 0;    // first and last value of every column, a check that the same was read
  while (reader.next(frame)) {
    atoms += frame.natoms();
    for (auto &c : frame.data)
      if (!c.empty()) sum += c.front() + c.back();
  }
  double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  auto p = reader.progress();
  std::printf("frames %llu atoms %llu bytes %llu seconds %.3f MB/s %.1f sum %.17g\n",
              (unsigned long long) p.frames, atoms, (unsigned long long) p.bytes, s, p.bytes / s / 1e6, sum);
  return 0;
}

}    // namespace

int main(int argc, char **argv)
{
  try {
    std::string cmd = argc > 1 ? argv[1] : "";
    if (cmd == "make" && argc == 5) return make(argv[2], std::atol(argv[3]), std::atof(argv[4]));
    if (cmd == "read" && argc > 2) return read(std::vector<std::string>(argv + 2, argv + argc));
  } catch (granpen::InputError &e) {
    std::fprintf(stderr, "dump_read_bench: %s\n", e.what());
    return 1;
  }
  std::fprintf(stderr, "usage: dump_read_bench make OUT ATOMS MEGABYTES | read FILE...\n");
  return 2;
}
