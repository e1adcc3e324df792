// granpen flow / granpen momentum: the options they share (dump_options.h).
#include "dump_options.h"

#include <cmath>

namespace granpen {
namespace cli {

bool read_rod_options(const ParsedArgs &args, RodOptions &ro, std::string &message)
{
  double v;
  if (args.number("--rod-type", v)) {
    if (v != std::floor(v) || v < 1 || v > 1.0e9) {    // LAMMPS types are ints
      message = "--rod-type must be a positive integer";
      return false;
    }
    ro.rod_type = (int) v;
  }
  const auto axis = args.numbers.find("--axis");
  if (axis != args.numbers.end()) ro.have_axis = true, ro.axis_x = axis->second[0], ro.axis_y = axis->second[1];
  if (args.number("--tip", ro.tip)) ro.have_tip = true;
  return true;
}

bool periodic_axes(const std::string &axes, bool &x, bool &y)
{
  if (axes != "xy" && axes != "x" && axes != "y" && axes != "none") return false;
  x = axes == "xy" || axes == "x", y = axes == "xy" || axes == "y";
  return true;
}

}    // namespace cli
}    // namespace granpen
