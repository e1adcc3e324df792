// granpen flow / granpen momentum: the options they share (dump_options.h).
#include "dump_options.h"

#include "args.h"

#include <cmath>

namespace granpen {
namespace cli {

CLI::Option *add_numbers(Command &cmd, const std::string &flag, int n, const std::string &type, const std::string &what)
{
  return cmd.app.add_option(flag, what)->expected(n)->take_last()->check(finite_number())->type_name(type);
}

std::vector<double> take_numbers(const CLI::Option *option, int n)
{
  std::vector<double> values;
  if (option->count() == 0) return values;
  const auto given = option->results();
  if ((int) given.size() != n)
    throw UsageError(option->get_name() + " needs " + std::to_string(n) + (n == 1 ? " value" : " values"));
  for (const auto &s : given) {
    double v = 0.0;
    number_arg(s, v);    // checked by finite_number
    values.push_back(v);
  }
  return values;
}

CLI::Option *add_number(Command &cmd, const std::string &flag, double &v, const std::string &type, const std::string &what)
{
  return cmd.number(flag, v, what)->type_name(type);
}

CLI::Option *add_positive(Command &cmd, const std::string &flag, double &v, const std::string &type, const std::string &what)
{
  return cmd.app.add_option(flag, v, what)->check(positive_number())->type_name(type);
}

CLI::Option *add_text(Command &cmd, const std::string &flag, std::string &v, const std::string &type, const std::string &what)
{
  return cmd.app.add_option(flag, v, what)->check(file_name())->type_name(type);
}

void add_rod_options(Command &cmd, RodArgs &args, const char *axis_what, const char *tip_what)
{
  add_number(cmd, "--rod-type", args.rod_type, "N", "atom type of the rod (default 2); every other atom is a grain");
  args.axis = add_numbers(cmd, "--axis", 2, "X Y", axis_what);
  args.tip = add_number(cmd, "--tip", args.tip_z, "Z", tip_what);
}

void finish_rod_options(const RodArgs &args, RodOptions &rod)
{
  if (std::isfinite(args.rod_type)) {
    const double v = args.rod_type;
    if (v != std::floor(v) || v < 1 || v > 1.0e9) throw UsageError("--rod-type must be a positive integer");    // LAMMPS types are ints
    rod.rod_type = (int) v;
  }
  const std::vector<double> axis = take_numbers(args.axis, 2);
  if (!axis.empty()) rod.have_axis = true, rod.axis_x = axis[0], rod.axis_y = axis[1];
  if (args.tip->count()) rod.have_tip = true, rod.tip = args.tip_z;
}

void add_periodic_option(Command &cmd, std::string &axes)
{
  cmd.app.add_option("--periodic", axes, "periodic box directions among x, y: xy (default), x, y or none")->type_name("AXES");
}

void finish_periodic(const std::string &axes, bool &x, bool &y)
{
  if (axes != "xy" && axes != "x" && axes != "y" && axes != "none") throw UsageError("--periodic must be xy, x, y or none");
  x = axes == "xy" || axes == "x", y = axes == "xy" || axes == "y";
}

}    // namespace cli
}    // namespace granpen
