// granpen-cli subcommands: the run function of each, in its own file in cli/, taking the
// options its parse function (options.h) read, and returning the process exit status.
// run_parsed joins the two; the table in granpen_cli.cpp lists the subcommands.
#ifndef GRANPEN_CLI_SUBCOMMANDS_H
#define GRANPEN_CLI_SUBCOMMANDS_H

#include "get_options.h"
#include "options.h"

#include <cstdio>

namespace granpen {
namespace cli {

int run_check(const CheckOptions &o);                  // check_cmd.cpp
int run_fit(const FitOptions &o);                      // fit_cmd.cpp
int run_calibration(const CalibrationOptions &o);      // calibration_cmd.cpp
int run_collapse(const CollapseOptions &o);            // collapse_cmd.cpp
int run_sweep_command(const SweepOptions &o);          // sweep_cmd.cpp
int run_flow(const FlowOptions &o);                    // flow_cmd.cpp
int run_momentum(const MomentumOptions &o);            // momentum_cmd.cpp
int run_plot(const PlotOptions &o);                    // plot_cmd.cpp
int run_gap_command(const GapCommandOptions &o);       // gap_cmd.cpp
int run_convert(const ConvertOptions &o);              // convert_cmd.cpp
int run_import(const ImportOptions &o);                // import_cmd.cpp
int run_get(const GetOptions &o);                      // get_cmd.cpp
int run_gap_score(const GapScoreOptions &o);           // gap_score_cmd.cpp

// parse, then --help's text on stdout (exit 0) or run
template <class Options>
int run_parsed(Options (*parse)(int, char **), int (*run)(const Options &), int argc, char **argv)
{
  const Options o = parse(argc, argv);
  if (o.help_requested()) {
    std::fputs(o.help.c_str(), stdout);
    return EXIT_OK;
  }
  return run(o);
}

// The subcommands as granpen-cli's table calls them: parse and run (argv[0] is the first
// word after the subcommand).
inline int check(int argc, char **argv) { return run_parsed(parse_check, run_check, argc, argv); }
inline int fit(int argc, char **argv) { return run_parsed(parse_fit, run_fit, argc, argv); }
inline int calibration(int argc, char **argv) { return run_parsed(parse_calibration, run_calibration, argc, argv); }
inline int collapse(int argc, char **argv) { return run_parsed(parse_collapse, run_collapse, argc, argv); }
inline int sweep(int argc, char **argv) { return run_parsed(parse_sweep_command, run_sweep_command, argc, argv); }
inline int flow(int argc, char **argv) { return run_parsed(parse_flow, run_flow, argc, argv); }
inline int momentum(int argc, char **argv) { return run_parsed(parse_momentum, run_momentum, argc, argv); }
inline int plot(int argc, char **argv) { return run_parsed(parse_plot, run_plot, argc, argv); }
inline int gap(int argc, char **argv) { return run_parsed(parse_gap, run_gap_command, argc, argv); }
inline int convert(int argc, char **argv) { return run_parsed(parse_convert, run_convert, argc, argv); }
inline int import(int argc, char **argv) { return run_parsed(parse_import, run_import, argc, argv); }
inline int get(int argc, char **argv) { return run_parsed(parse_get, run_get, argc, argv); }
inline int gap_score(int argc, char **argv) { return run_parsed(parse_gap_score, run_gap_score, argc, argv); }

}    // namespace cli
}    // namespace granpen

#endif
