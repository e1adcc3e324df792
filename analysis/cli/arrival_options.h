// granpen arrival TRACE [--factor F] [--json FILE]: its command line as a typed struct and
// parse function (words -> options; pure, throwing only UsageError, as every subcommand's
// parse).
#ifndef GRANPEN_CLI_ARRIVAL_OPTIONS_H
#define GRANPEN_CLI_ARRIVAL_OPTIONS_H

#include <string>

namespace granpen {
namespace cli {

// Checks: trace not empty; factor above 1 and at most 1e12; json, when given, not empty.
struct ArrivalOptions {
  std::string help;
  bool help_requested() const { return !help.empty(); }
  std::string trace;
  double factor = 100;
  std::string json;
};
ArrivalOptions parse_arrival(int argc, char **argv);
int run_arrival(const ArrivalOptions &o);    // arrival_cmd.cpp

}    // namespace cli
}    // namespace granpen

#endif
