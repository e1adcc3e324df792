// granpen subcommands: each one's command line as a typed struct and its parse function,
// words -> options. A parse function is pure: it reads no file, writes nothing, prints
// nothing, and throws nothing but UsageError (subcommand.h); what it accepts satisfies the
// checks listed with each struct (the fuzz target tests/fuzz/fuzz_cli_options.cpp asserts
// them on every accepted parse). Checks that need the file system (an output that is an
// input, a folder that exists) are the run functions' (subcommands.h).
// argv[0] is the first word after the subcommand.
#ifndef GRANPEN_CLI_OPTIONS_H
#define GRANPEN_CLI_OPTIONS_H

#include "args.h"
#include "collapse_tables.h"    // DepthTerm
#include "dump_frames.h"        // RodOptions
#include "ensemble_args.h"      // EnsembleOptions
#include "figures.h"            // figures::Options
#include "fit_tables.h"         // FitWindow
#include "gap_diagnosis.h"      // GapOptions
#include "sweep_runner.h"       // RunnerOptions
#include "trace_reader.h"       // AveTimeSpec

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace granpen {
namespace cli {

// What every parse returns besides its options: --help's text when --help was asked for
// (every other field is then its default).
struct ParsedCommand {
  std::string help;
  bool help_requested() const { return !help.empty(); }
};

// granpen convert FILE --from ave/time --out TRACE ...
// Checks: in, out not empty; spec.v0, dt, D, g > 0 and finite; spec.sign +1 or -1;
// spec.step0 NaN (not given) or a whole number >= 0; spec.z0 finite; spec.units cgs or
// si; extra: mu, d_g, rho_g, each at most once, with a number > 0.
struct ConvertOptions : ParsedCommand {
  std::string in, out, from = "ave/time";
  AveTimeSpec spec;
  std::vector<std::pair<std::string, std::string>> extra;
};
ConvertOptions parse_convert(int argc, char **argv);

// granpen check TRACE-OR-FOLDER...    Checks: at least one trace.
struct CheckOptions : ParsedCommand {
  std::vector<std::string> traces;
};
CheckOptions parse_check(int argc, char **argv);

// granpen fit TRACE... Checks: at least one trace; window.tmin -1 (not given) or > 0 and
// finite, and then zmin at its default 3 (--zmin and --tmin exclude each other);
// without tmin, zmin < zmax (zmax may be +inf); window.mu, rho_g 0 (from the header) or
// > 0; json, csv empty (not written) or a name; ensemble as EnsembleOptions
// (ensemble_args.h); ensemble_csv empty, or a name and then ensemble.on.
struct FitOptions : ParsedCommand {
  std::vector<std::string> traces;
  FitWindow window = {3.0, std::numeric_limits<double>::infinity(), -1.0, 0.0, 0.0};
  std::string json, csv;
  EnsembleOptions ensemble;
  std::string ensemble_csv;
};
FitOptions parse_fit(int argc, char **argv);

// granpen calibration SWEEP_DIR. Checks: sweep not empty; zmin < zmax, both finite; out
// not empty (SWEEP_DIR when not given).
struct CalibrationOptions : ParsedCommand {
  std::string sweep, out;
  double zmin = 1.0, zmax = 3.0;
};
CalibrationOptions parse_calibration(int argc, char **argv);

// granpen collapse TRACE-OR-FOLDER... Checks: at least one trace; depth.kz_zmin <
// kz_zmax (kz_zmax may be +inf, kz_zmin finite); depth.alpha, mu, rho_g 0 (not given) or
// > 0; params.band, tbin > 0 and finite, params.zmin finite; csv, json empty or a name;
// ensemble as EnsembleOptions (ensemble_args.h).
struct CollapseOptions : ParsedCommand {
  std::vector<std::string> traces;
  DepthTerm depth;
  CollapseParams params;
  std::string csv, json;
  EnsembleOptions ensemble;
};
CollapseOptions parse_collapse(int argc, char **argv);

// granpen sweep SPEC. Checks: spec not empty; runner.jobs, checkpoint, ranks >= 1;
// runner.only_index -1 (all runs) or >= 0; runner.out_root not empty; slurm empty or a
// name. Defaults from the environment: GRANPEN_LMP, GRANPEN_INPUTS, GRANPEN_RUNS.
struct SweepOptions : ParsedCommand {
  std::string spec;
  RunnerOptions runner;
  std::string slurm;
  bool plan_only = false;
};
SweepOptions parse_sweep_command(int argc, char **argv);

// For flow and momentum: from the numeric options (ParsedArgs::read_numbers) --rod-type
// N, --axis X Y, --tip Z; false with a message when N is not a positive integer.
bool read_rod_options(const ParsedArgs &args, RodOptions &rod, std::string &message);
// --periodic AXES: xy, x, y or none, as periodic x and y; false for anything else.
bool periodic_axes(const std::string &axes, bool &x, bool &y);

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

// granpen momentum DUMP... --trace TRACE. Checks: at least one dump; --trace given;
// out_dir not empty; the numbers given finite, --D, --rho, --dt, --mthreshold > 0, --mu
// >= 0; --thresholds F1 > F2 > F3 > F4 > 0; --push-step a whole number; rod.rod_type
// >= 1; periodic xy, x, y or none, as px, py.
struct MomentumOptions : ParsedCommand {
  ParsedArgs args;
  RodOptions rod;
  std::string out_dir, periodic;
  bool px = true, py = true;
};
MomentumOptions parse_momentum(int argc, char **argv);

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

// granpen gap. Checks, unless list_effects: gap.scenario not empty, and either gap.real
// and gap.out, or (prepare_only or slurm) and v0; gap.runner.jobs 1 to 1024,
// runner.ranks >= 1.
struct GapCommandOptions : ParsedCommand {
  GapOptions gap;
  bool list_effects = false;
};
GapCommandOptions parse_gap(int argc, char **argv);

// granpen import FILE-OR-FOLDER... --mapping MAP --out DIR --D D --g G. Checks: at least
// one input; mapping, out_dir not empty; D, g > 0 and finite; v0 0 (not given) or > 0;
// window 0 (the mapping's) or > 0; first_run >= 1; d_g, rho_g, mu empty or a number > 0.
struct ImportOptions : ParsedCommand {
  std::vector<std::string> inputs;
  std::string mapping, out_dir;
  bool si = false;
  double D = 0.0, g = 0.0, v0 = 0.0, window = 0.0;
  std::string v0_table;                                // file -> nominal v0 ("" none)
  double speed_tolerance = 0.0, end_tolerance = 0.0;   // 0: the mapping's
  std::string d_g, rho_g, mu;
  int first_run = 1;
  bool dry_run = false;
};
ImportOptions parse_import(int argc, char **argv);

}    // namespace cli
}    // namespace granpen

#endif
