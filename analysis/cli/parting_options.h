// granpen parting A B [--window S] [--threshold X] [--sustain N] [--json FILE]: its command
// line as a typed struct and parse function (words -> options; pure, throwing only
// UsageError, as every subcommand's parse).
#ifndef GRANPEN_CLI_PARTING_OPTIONS_H
#define GRANPEN_CLI_PARTING_OPTIONS_H

#include <string>

namespace granpen {
namespace cli {

// Checks: a and b not empty; window and threshold positive, window at most 10 s (a push is
// seconds long at most; the kernel's table is bounded by it); sustain a whole number from
// 1 to 1000; json, when given, not empty.
struct PartingOptions {
  std::string help;
  bool help_requested() const { return !help.empty(); }
  std::string a, b;
  double window = 5e-4, threshold = 0.03;
  long long sustain = 2;
  std::string json;
};
PartingOptions parse_parting(int argc, char **argv);
int run_parting(const PartingOptions &o);    // parting_cmd.cpp

}    // namespace cli
}    // namespace granpen

#endif
