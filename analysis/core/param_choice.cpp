// granpen analysis: a parameter from the first source that gives it (param_choice.h).
#include "param_choice.h"

#include <cmath>

namespace granpen {

double resolve(const ParamChoice &c, double fallback, const char *fallback_origin, std::string &origin)
{
  if (std::isfinite(c.option)) return origin = "option", c.option;
  if (std::isfinite(c.trace)) return origin = "trace", c.trace;
  origin = fallback_origin;
  return fallback;
}

}    // namespace granpen
