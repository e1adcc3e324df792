// granpen-cli subcommands: one function per subcommand, each in its own file in cli/,
// each parsing its own arguments (argv[0] is the first argument after the subcommand)
// and returning the process exit status. The table in granpen_cli.cpp lists them.
#ifndef GRANPEN_CLI_SUBCOMMANDS_H
#define GRANPEN_CLI_SUBCOMMANDS_H

namespace granpen {
namespace cli {

int check(int argc, char **argv);          // check_cmd.cpp
int fit(int argc, char **argv);            // fit_cmd.cpp
int calibration(int argc, char **argv);    // calibration_cmd.cpp
int collapse(int argc, char **argv);       // collapse_cmd.cpp
int sweep(int argc, char **argv);          // sweep_cmd.cpp
int flow(int argc, char **argv);           // flow_cmd.cpp
int momentum(int argc, char **argv);       // momentum_cmd.cpp
int plot(int argc, char **argv);           // plot_cmd.cpp, plot_flow_cmd.cpp
int gap(int argc, char **argv);            // gap_cmd.cpp
int convert(int argc, char **argv);        // convert_cmd.cpp
int import(int argc, char **argv);         // import_cmd.cpp

}    // namespace cli
}    // namespace granpen

#endif
