// granpen plot: its command line as a typed struct and its parse function, words ->
// options (pure: no file read, nothing written or printed, nothing thrown but UsageError,
// subcommand.h), and its run function (plot_cmd.cpp: calls the library and writes; the
// process exit status). What the parse accepts satisfies the checks listed with the
// struct (tests/fuzz/fuzz_cli_body.h asserts them on every accepted parse).
#ifndef GRANPEN_CLI_PLOT_OPTIONS_H
#define GRANPEN_CLI_PLOT_OPTIONS_H

#include "figures.h"    // figures::Options
#include "subcommand.h"

#include <string>
#include <vector>

namespace granpen {
namespace cli {

// granpen plot KIND INPUTS... --out DIR. Checks: kind force, ratio, peak, kz, flow or
// momentum; at least one input (flow, momentum: exactly one); figures.out not empty;
// figures.kz_zmin < kz_zmax; figures.alpha, mu, rho, D >= 0; figures.collapse.band, tbin
// > 0 and finite, collapse.zmin finite; figures.ensemble only with kind force, ratio, peak
// or kz and without figures.each; figures.ens.bin and figures.boot.resamples as
// EnsembleOptions' mean.bin and boot.resamples (ensemble_args.h).
struct PlotOptions : ParsedCommand {
  std::string kind;
  std::vector<std::string> inputs;
  figures::Options figures;
};
PlotOptions parse_plot(int argc, char **argv);
int run_plot(const PlotOptions &o);

}    // namespace cli
}    // namespace granpen

#endif
