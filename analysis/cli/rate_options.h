// granpen rate K N [--level L]: its command line as a typed struct and parse function
// (words -> options; pure, throwing only UsageError, as every subcommand's parse).
#ifndef GRANPEN_CLI_RATE_OPTIONS_H
#define GRANPEN_CLI_RATE_OPTIONS_H

#include <string>

namespace granpen {
namespace cli {

// Checks: events and trials whole numbers, 0 <= events <= trials, trials >= 1; level in (0, 1).
struct RateOptions {
  std::string help;
  bool help_requested() const { return !help.empty(); }
  long long events = 0, trials = 1;
  double level = 0.95;
};
RateOptions parse_rate(int argc, char **argv);
int run_rate(const RateOptions &o);    // rate_cmd.cpp

}    // namespace cli
}    // namespace granpen

#endif
