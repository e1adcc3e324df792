// granpen subcommands: shared argument helpers (args.h).
#include "args.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace granpen {
namespace cli {

std::string not_a_number(const std::string &option, const std::string &value)
{
  return option + " '" + value + "' is not a number";
}

bool number_arg(const std::string &s, double &v, bool accept_underflow)
{
  char *end = nullptr;
  errno = 0;
  v = std::strtod(s.c_str(), &end);
  return !s.empty() && end && *end == '\0' && (accept_underflow || errno != ERANGE) && std::isfinite(v);
}

bool integer_arg(const std::string &s, long long &v)
{
  char *end = nullptr;
  errno = 0;
  v = std::strtoll(s.c_str(), &end, 10);
  return !s.empty() && end && *end == '\0' && errno != ERANGE;
}

std::string ParsedArgs::value(const std::string &name, const std::string &fallback) const
{
  const auto it = options.find(name);
  return it == options.end() ? fallback : it->second[0];
}

bool ParsedArgs::read_numbers(const std::set<std::string> &text, std::string &message)
{
  for (const auto &o : options) {
    if (text.count(o.first)) continue;
    for (const auto &s : o.second) {
      double x;
      if (!number_arg(s, x)) {
        message = not_a_number(o.first, s);
        return false;
      }
      numbers[o.first].push_back(x);
    }
  }
  return true;
}

bool ParsedArgs::number(const std::string &name, double &v) const
{
  const auto it = numbers.find(name);
  if (it == numbers.end()) return false;
  v = it->second[0];
  return true;
}

bool ParsedArgs::positive(std::initializer_list<const char *> names, std::string &message) const
{
  for (const char *n : names) {
    double v;
    if (number(n, v) && !(v > 0.0)) {
      message = std::string(n) + " must be > 0";
      return false;
    }
  }
  return true;
}

bool parse_table(Command &cmd, const std::vector<OptionSpec> &spec, const char *positional, int argc, char **argv,
                 ParsedArgs &out, std::string &help)
{
  std::vector<CLI::Option *> added;
  for (const auto &o : spec)
    added.push_back(o.values == 0 ? cmd.app.add_flag(o.name, o.what)
                                  : cmd.app.add_option(o.name, o.what)->expected(o.values)->take_last()->type_name(o.type));
  cmd.app.add_option(positional, out.positional, positional);
  if (!cmd.parse(argc, argv, help)) return false;
  for (std::size_t k = 0; k < spec.size(); ++k) {
    if (added[k]->count() == 0) continue;
    const auto values = spec[k].values == 0 ? std::vector<std::string>() : added[k]->results();
    if ((int) values.size() != spec[k].values)
      throw UsageError(std::string(spec[k].name) + " needs " + std::to_string(spec[k].values) +
                       (spec[k].values == 1 ? " value" : " values"));
    out.options[spec[k].name] = values;
  }
  return true;
}

}    // namespace cli
}    // namespace granpen
