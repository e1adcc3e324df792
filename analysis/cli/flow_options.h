// granpen flow: its command line as a typed struct and its parse function, words ->
// options (pure: no file read, nothing written or printed, nothing thrown but UsageError,
// subcommand.h), and its run function (flow_cmd.cpp: calls the library and writes; the
// process exit status). What the parse accepts satisfies the checks listed with the
// struct (tests/fuzz/fuzz_cli_body.h asserts them on every accepted parse).
#ifndef GRANPEN_CLI_FLOW_OPTIONS_H
#define GRANPEN_CLI_FLOW_OPTIONS_H

#include "dump_options.h"    // RodOptions, NOT_GIVEN, the shared options

#include <limits>
#include <string>
#include <vector>

namespace granpen {
namespace cli {

// granpen flow DUMP... Checks: at least one dump; trace empty (not given) or a name;
// out_dir not empty; the numbers finite, or NaN for not given (then the trace header's,
// the first frame's or a default: core/flow_study.h's flow_study_params); D, d_g, rho_g,
// v0, g, dr, dz, rmax, profile_radius, edge_wr, edge_wz NaN or > 0, edge_wr and edge_wz
// both given or neither; rod as finish_rod_options; 0 <= strip1 < strip2; 0 <= ann1 < ann2;
// ann_top finite; zlo < 0 and zlo < zhi; step_lo <= step_hi; voronoi, stress not empty;
// periodic xy, x, y or none, as px, py.
struct FlowOptions : ParsedCommand {
  std::vector<std::string> dumps;
  std::string trace, out_dir = ".";
  RodOptions rod;
  double D = NOT_GIVEN, d_g = NOT_GIVEN, rho_g = NOT_GIVEN, v0 = NOT_GIVEN, g = NOT_GIVEN, z_s = NOT_GIVEN;
  double dr = NOT_GIVEN, dz = NOT_GIVEN, rmax = NOT_GIVEN, profile_radius = NOT_GIVEN;
  double edge_wr = NOT_GIVEN, edge_wz = NOT_GIVEN;
  std::string voronoi = "auto", stress = "auto", periodic = "xy";
  bool px = true, py = true, rod_cells = false;
  double strip1 = 0.5, strip2 = 1.5, ann1 = 2.0, ann2 = 3.0, ann_top = 0.5, zlo = -4.0, zhi = 6.0;
  std::string steps;    // --steps as given ("" all frames)
  long long step_lo = std::numeric_limits<long long>::min(), step_hi = std::numeric_limits<long long>::max();
  bool selected(long long step) const { return step >= step_lo && step <= step_hi; }
};
FlowOptions parse_flow(int argc, char **argv);
int run_flow(const FlowOptions &o);

}    // namespace cli
}    // namespace granpen

#endif
