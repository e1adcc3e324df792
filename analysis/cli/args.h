// granpen subcommands: the reading of numbers from the command line's words, shared by the
// parse functions and the value checks of the one parser (subcommand.h).
#ifndef GRANPEN_CLI_ARGS_H
#define GRANPEN_CLI_ARGS_H

#include <string>

namespace granpen {
namespace cli {

// s as a whole finite number (strtod; s empty, trailing text or overflow: false). Out of
// range below (strtod's ERANGE for a value too small for a double) is refused unless
// accept_underflow (what granpen collapse and convert have always accepted).
bool number_arg(const std::string &s, double &v, bool accept_underflow = false);
// s as a whole base-10 integer (strtoll; out of range: false)
bool integer_arg(const std::string &s, long long &v);

}    // namespace cli
}    // namespace granpen

#endif
