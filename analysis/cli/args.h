// granpen subcommands: the argument helpers they share: the reading of numbers, and (for
// flow and momentum, whose many options are read as numbers by name) an option table
// parsed by the one parser (subcommand.h) into ParsedArgs.
#ifndef GRANPEN_CLI_ARGS_H
#define GRANPEN_CLI_ARGS_H

#include "subcommand.h"

#include <initializer_list>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace granpen {
namespace cli {

// "OPTION 'VALUE' is not a number"
std::string not_a_number(const std::string &option, const std::string &value);

// s as a whole finite number (strtod; s empty, trailing text or overflow: false). Out of
// range below (strtod's ERANGE for a value too small for a double) is refused unless
// accept_underflow (what granpen collapse and convert have always accepted).
bool number_arg(const std::string &s, double &v, bool accept_underflow = false);
// s as a whole base-10 integer (strtoll; out of range: false)
bool integer_arg(const std::string &s, long long &v);

// A command line: positional arguments and options "--name V..." (the values as text).
struct ParsedArgs {
  std::vector<std::string> positional;
  std::map<std::string, std::vector<double>> numbers;         // by read_numbers
  std::map<std::string, std::vector<std::string>> options;    // the last of repeated ones

  bool has(const std::string &name) const { return options.count(name) > 0; }
  // the (first) value of option name, fallback when it was not given
  std::string value(const std::string &name, const std::string &fallback) const;
  // Every given option's values as numbers (number_arg) into numbers, except the options
  // named in text; false with "OPTION 'V' is not a number" for the first that is not.
  bool read_numbers(const std::set<std::string> &text, std::string &message);
  // the first number of option name; false (v untouched) when it was not given
  bool number(const std::string &name, double &v) const;
  // false with "NAME must be > 0" for the first of names given with a number <= 0
  bool positive(std::initializer_list<const char *> names, std::string &message) const;
};

// One option of a table: its name, how many values it takes (0: a flag), their names in
// the help (e.g. "X Y"), what it is.
struct OptionSpec {
  const char *name;
  int values;
  const char *type;
  const char *what;
};
// The options of spec and the positional arguments (named positional) on cmd's parser,
// parsed into out; false when --help was asked for, its text in help (Command::parse;
// usage errors throw).
bool parse_table(Command &cmd, const std::vector<OptionSpec> &spec, const char *positional, int argc, char **argv,
                 ParsedArgs &out, std::string &help);

}    // namespace cli
}    // namespace granpen

#endif
