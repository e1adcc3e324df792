// granpen-cli: the post-processor's command-line front end (./granpen SUBCOMMAND).
// A thin layer: every subcommand parses its arguments (cli/NAME_options.h) and runs
// (cli/NAME_cmd.cpp), calling the analysis library; its entry point is declared in
// cli/subcommands.h and listed in the table below; run_subcommand is the one handler that
// turns what they throw into an exit status.
#include "subcommand.h"
#include "subcommands.h"

#include <cstdio>
#include <cstring>

namespace {

struct Subcommand {
  const char *name;
  int (*run)(int, char **);
  const char *summary;
};

const Subcommand SUBCOMMANDS[] = {
    {"convert", granpen::cli::convert, "write fix ave/time output as a force trace (granpen-trace v1)"},
    {"import", granpen::cli::import, "write a lab's instrument files (own columns, units, layout) as force traces"},
    {"check", granpen::cli::check, "validate force traces (granpen-trace v1) and summarise them"},
    {"fit", granpen::cli::fit, "fit the depth term k_z, alpha, the peak and the fluctuation wavelength"},
    {"calibration", granpen::cli::calibration, "summarise a friction-calibration sweep: phi_0(mu), k_z(mu)"},
    {"collapse", granpen::cli::collapse, "F/F_z against t~ = (z/v0) sqrt(g/D): crossover, collapse quality, peak law"},
    {"sweep", granpen::cli::sweep, "run a sweep of pours and pushes from a sweep file"},
    {"checkpoint", granpen::cli::checkpoint, "whether LAMMPS checkpoints are complete, as the sweep runner resumes by"},
    {"flow", granpen::cli::flow, "flow fields about the rod from LAMMPS dumps: lambda_vz, phi(I) at the edge, strip, annulus"},
    {"momentum", granpen::cli::momentum, "upward momentum by v_z class from LAMMPS dumps; drag F against mu g M"},
    {"plot", granpen::cli::plot, "figures as gnuplot scripts + data, run to PNG and SVG: force, ratio, peak, kz, flow, momentum"},
    {"gap", granpen::cli::gap, "sim-to-real gap: where, which unmodelled effect, how far it shrinks"},
    {"gap-score", granpen::cli::gap_score, "score a diagnosis.json against a selftest case's truth (bench/gap_selftest.sh)"},
    {"arrival", granpen::cli::arrival, "when the rod's disturbance reaches rings about its axis, and how fast (observe/arrival.lmp)"},
    {"parting", granpen::cli::parting, "when two pushes part: their drag ratio in windows of time after contact (the box's echo)"},
    {"rate", granpen::cli::rate, "a rate of K in N with its exact 95% interval (the false-alarm rate: validation/gap_bench.sh)"},
    {"get", granpen::cli::get, "values of a JSON output by key path (heldout.gap_before, traces[*].peak)"},
};

void usage(std::FILE *out)
{
  std::fputs("usage: granpen SUBCOMMAND [ARGS]\nsubcommands:\n", out);
  for (const auto &s : SUBCOMMANDS) std::fprintf(out, "  %-12s %s\n", s.name, s.summary);
  std::fputs("Run `granpen SUBCOMMAND --help` for a subcommand's options.\n", out);
}

}    // namespace

int main(int argc, char **argv)
{
  if (argc < 2 || !std::strcmp(argv[1], "help") || !std::strcmp(argv[1], "--help")) {
    usage(stdout);
    return argc < 2 ? 2 : 0;
  }
  for (const auto &s : SUBCOMMANDS)
    if (!std::strcmp(argv[1], s.name)) return granpen::cli::run_subcommand(s.name, s.run, argc - 2, argv + 2);
  std::fprintf(stderr, "granpen: unknown subcommand '%s'\n", argv[1]);
  usage(stderr);
  return 2;
}
