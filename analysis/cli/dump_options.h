// granpen flow and momentum: the options the two dump subcommands share (dump_options.cpp).
#ifndef GRANPEN_CLI_DUMP_OPTIONS_H
#define GRANPEN_CLI_DUMP_OPTIONS_H

#include "dump_frames.h"    // RodOptions
#include "subcommand.h"

#include <limits>
#include <string>
#include <vector>

namespace granpen {
namespace cli {

// A number option not given: the parameter comes from the trace, the frames or a default
// (core/param_choice.h).
constexpr double NOT_GIVEN = std::numeric_limits<double>::quiet_NaN();

// The options of the two subcommands, each bound to its field (given twice: a usage error,
// as for every subcommand): a finite number; a number > 0; a name.
CLI::Option *add_number(Command &cmd, const std::string &flag, double &v, const std::string &type, const std::string &what);
CLI::Option *add_positive(Command &cmd, const std::string &flag, double &v, const std::string &type, const std::string &what);
CLI::Option *add_text(Command &cmd, const std::string &flag, std::string &v, const std::string &type, const std::string &what);
// An option of n numbers ("--strip A B"), each checked a finite number; their values after
// the parse from take_numbers: none when not given, UsageError "FLAG needs N values" for
// another count (given twice, too).
CLI::Option *add_numbers(Command &cmd, const std::string &flag, int n, const std::string &type, const std::string &what);
std::vector<double> take_numbers(const CLI::Option *option, int n);

// --rod-type N, --axis X Y, --tip Z on cmd (axis_what and tip_what: their help), and after
// the parse into rod: UsageError unless N is a whole number from 1 to 1e9 ("--rod-type
// must be a positive integer"); have_axis and have_tip set when given.
struct RodArgs {
  double rod_type = NOT_GIVEN, tip_z = NOT_GIVEN;
  CLI::Option *axis = nullptr, *tip = nullptr;
};
void add_rod_options(Command &cmd, RodArgs &args, const char *axis_what, const char *tip_what);
void finish_rod_options(const RodArgs &args, RodOptions &rod);

// --periodic AXES on cmd, and after the parse: xy, x, y or none, as periodic x and y;
// UsageError for anything else.
void add_periodic_option(Command &cmd, std::string &axes);
void finish_periodic(const std::string &axes, bool &x, bool &y);

}    // namespace cli
}    // namespace granpen

#endif
