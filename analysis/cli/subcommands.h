// granpen-cli subcommands: the entry point of each, as granpen-cli's table (granpen_cli.cpp)
// calls it: argv[0] is the first word after the subcommand; returns the exit status. Each
// is run_parsed (subcommand.h) of its parse and run functions, declared with its options
// in NAME_options.h and defined in NAME_cmd.cpp. This header names no options type, so
// that a change to one subcommand's options recompiles that subcommand alone.
#ifndef GRANPEN_CLI_SUBCOMMANDS_H
#define GRANPEN_CLI_SUBCOMMANDS_H

namespace granpen {
namespace cli {

int convert(int argc, char **argv);        // convert_cmd.cpp
int import(int argc, char **argv);         // import_cmd.cpp
int check(int argc, char **argv);          // check_cmd.cpp
int fit(int argc, char **argv);            // fit_cmd.cpp
int calibration(int argc, char **argv);    // calibration_cmd.cpp
int collapse(int argc, char **argv);       // collapse_cmd.cpp
int sweep(int argc, char **argv);          // sweep_cmd.cpp
int checkpoint(int argc, char **argv);     // checkpoint_cmd.cpp
int flow(int argc, char **argv);           // flow_cmd.cpp
int momentum(int argc, char **argv);       // momentum_cmd.cpp
int plot(int argc, char **argv);           // plot_cmd.cpp
int gap(int argc, char **argv);            // gap_cmd.cpp
int get(int argc, char **argv);            // get_cmd.cpp
int gap_score(int argc, char **argv);      // gap_score_cmd.cpp
int parting(int argc, char **argv);        // parting_cmd.cpp
int arrival(int argc, char **argv);        // arrival_cmd.cpp
int rate(int argc, char **argv);           // rate_cmd.cpp

}    // namespace cli
}    // namespace granpen

#endif
