// granpen subcommands: the reading of numbers (args.h).
#include "args.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace granpen {
namespace cli {

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

}    // namespace cli
}    // namespace granpen
