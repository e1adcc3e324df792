// granpen convert: its command line (convert_options.h).
#include "convert_options.h"

#include "args.h"

#include <string>

namespace {

const char *HELP =
    "usage: granpen convert FILE --from ave/time --v0 V --dt DT --D D --g G --out TRACE.csv\n"
    "                       [--units cgs|si] [--column NAME] [--step0 N] [--z0 Z] [--sign -1]\n"
    "                       [--mu MU] [--d_g DG] [--rho_g RHO]\n"
    "Writes the raw output of `fix ave/time` (scalar mode: one row per window, the TimeStep\n"
    "and the averaged values) as a granpen-trace v1 file:\n"
    "  t = (TimeStep - step0) * dt,  z = z0 + v0 t,  F = sign * the column's value.\n"
    "LAMMPS writes no units, speed or geometry into the file, so they are options.\n"
    "The trace is checked through the trace reader, then written to a temporary name and\n"
    "renamed: a failure leaves no TRACE.csv; TRACE.csv must not be FILE.\n"
    "Exit status 0, 1 for bad input, 2 for usage.\n";

// --sign: +1 or -1 only
CLI::Validator unit_sign()
{
  return CLI::Validator(
      [](std::string &s) -> std::string {
        double v;
        return granpen::cli::number_arg(s, v) && (v == 1.0 || v == -1.0) ? std::string()
                                                                         : "must be +1 or -1, got '" + s + "'";
      },
      "+1|-1");
}

// --step0: a timestep, a whole number >= 0
CLI::Validator timestep()
{
  return CLI::Validator(
      [](std::string &s) -> std::string {
        long long n;
        return granpen::cli::integer_arg(s, n) && n >= 0 ? std::string() : "must be a timestep (an integer >= 0), got '" + s + "'";
      },
      "STEP");
}

}    // namespace

granpen::cli::ConvertOptions granpen::cli::parse_convert(int argc, char **argv)
{
  Command cmd("convert", HELP);
  ConvertOptions o;
  AveTimeSpec &spec = o.spec;
  std::string mu, d_g, rho_g;
  auto &app = cmd.app;
  app.add_option("file", o.in, "fix ave/time output (scalar mode)")->required()->check(file_name());
  app.add_option("--from", o.from, "input format")->type_name("FORMAT")->check(CLI::IsMember({"ave/time"}));
  app.add_option("--out", o.out, "the trace to write")->required()->check(file_name())->type_name("TRACE.csv");
  app.add_option("--units", spec.units, "units of v0, D, g and dt (default cgs)")->type_name("UNITS")->check(CLI::IsMember({"cgs", "si"}));
  app.add_option("--column", spec.column, "a column of the '# TimeStep' line (default: the first value column)")
      ->type_name("NAME");
  app.add_option("--v0", spec.v0, "push speed, > 0")->check(positive_number())->required()->type_name("V");
  app.add_option("--dt", spec.dt, "the timestep, > 0")->check(positive_number())->required()->type_name("DT");
  app.add_option("--D", spec.D, "rod diameter, > 0")->check(positive_number())->required()->type_name("D");
  app.add_option("--g", spec.g, "gravity, > 0")->check(positive_number())->required()->type_name("G");
  app.add_option("--step0", spec.step0, "the step at which the push began, at most the first row's (default:\n"
                                         "the first row's step minus the row spacing, the first window's start)")
      ->check(timestep())->type_name("N");
  cmd.number("--z0", spec.z0, "tip depth at step0 (default -0.5: the rod starts 0.5 above the surface)",
             /*accept_underflow=*/true)->type_name("Z");
  app.add_option("--sign", spec.sign, "-1 when the column is the force on the grains rather than on the rod")
      ->check(unit_sign())->type_name("+1|-1");
  app.add_option("--mu", mu, "optional header key mu")->check(positive_number())->type_name("MU");
  app.add_option("--d_g", d_g, "optional header key d_g")->check(positive_number())->type_name("DG");
  app.add_option("--rho_g", rho_g, "optional header key rho_g")->check(positive_number())->type_name("RHO");
  if (!cmd.parse(argc, argv, o.help)) return o;
  for (const auto &key : {std::make_pair("mu", &mu), std::make_pair("d_g", &d_g), std::make_pair("rho_g", &rho_g)})
    if (!key.second->empty()) o.extra.emplace_back(key.first, *key.second);
  return o;
}
