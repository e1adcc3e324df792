// granpen check: its command line as a typed struct and its parse function, words ->
// options (pure: no file read, nothing written or printed, nothing thrown but UsageError,
// subcommand.h), and its run function (check_cmd.cpp: calls the library and writes; the
// process exit status). What the parse accepts satisfies the checks listed with the
// struct (tests/fuzz/fuzz_cli_body.h asserts them on every accepted parse).
#ifndef GRANPEN_CLI_CHECK_OPTIONS_H
#define GRANPEN_CLI_CHECK_OPTIONS_H

#include "subcommand.h"

#include <string>
#include <vector>

namespace granpen {
namespace cli {

// granpen check TRACE-OR-FOLDER...    Checks: at least one trace.
struct CheckOptions : ParsedCommand {
  std::vector<std::string> traces;
};
CheckOptions parse_check(int argc, char **argv);
int run_check(const CheckOptions &o);

}    // namespace cli
}    // namespace granpen

#endif
