// granpen flow: its command line as a typed struct and its parse function, words ->
// options (pure: no file read, nothing written or printed, nothing thrown but UsageError,
// subcommand.h), and its run function (flow_cmd.cpp: calls the library and writes; the
// process exit status). What the parse accepts satisfies the checks listed with the
// struct (tests/fuzz/fuzz_cli_body.h asserts them on every accepted parse).
#ifndef GRANPEN_CLI_FLOW_OPTIONS_H
#define GRANPEN_CLI_FLOW_OPTIONS_H

#include "dump_options.h"    // RodOptions, periodic_axes

#include <limits>
#include <string>
#include <vector>

namespace granpen {
namespace cli {

// granpen flow DUMP... Checks: at least one dump; out_dir not empty; the numbers given
// (args.numbers) finite, and --D, --dg, --rho, --v0, --g, --dr, --dz, --rmax,
// --profile-radius > 0; rod.rod_type >= 1; 0 <= strip1 < strip2; 0 <= ann1 < ann2;
// --edge WR WZ both > 0;
// zlo < 0 and zlo < zhi; step_lo <= step_hi; periodic xy, x, y or none, as px, py.
struct FlowOptions : ParsedCommand {
  ParsedArgs args;
  RodOptions rod;
  std::string out_dir, voronoi, stress, periodic;
  bool px = true, py = true, rod_cells = false;
  double strip1 = 0.5, strip2 = 1.5, ann1 = 2.0, ann2 = 3.0, ann_top = 0.5, zlo = -4.0, zhi = 6.0;
  long long step_lo = std::numeric_limits<long long>::min(), step_hi = std::numeric_limits<long long>::max();
  bool selected(long long step) const { return step >= step_lo && step <= step_hi; }
};
FlowOptions parse_flow(int argc, char **argv);
int run_flow(const FlowOptions &o);

}    // namespace cli
}    // namespace granpen

#endif
