// granpen convert FILE --from ave/time ...: a force trace in another format written as a
// granpen-trace v1 file, so that every other subcommand reads it.
#include "args.h"
#include "subcommands.h"
#include "trace_reader.h"
#include "trace_writer.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

const char *HELP =
    "usage: granpen convert FILE --from ave/time --v0 V --dt DT --D D --g G --out TRACE.csv\n"
    "                       [--units cgs|si] [--column NAME] [--step0 N] [--z0 Z] [--sign -1]\n"
    "                       [--mu MU] [--d_g DG] [--rho_g RHO]\n"
    "Writes the raw output of `fix ave/time` (scalar mode: one row per window, the TimeStep\n"
    "and the averaged values) as a granpen-trace v1 file:\n"
    "  t = (TimeStep - step0) * dt,  z = z0 + v0 t,  F = sign * the column's value.\n"
    "LAMMPS writes no units, speed or geometry into the file, so they are options:\n"
    "  --v0, --D, --g   push speed, rod diameter, gravity (in --units, default cgs)\n"
    "  --dt             the timestep\n"
    "  --column NAME    a column of the '# TimeStep' line (default: the first value column)\n"
    "  --step0 N        the step at which the push began (default: the first row's step\n"
    "                   minus the row spacing, i.e. the first window's start)\n"
    "  --z0 Z           tip depth at step0 (default -0.5: the rod starts 0.5 above the surface)\n"
    "  --sign -1        when the column is the force on the grains rather than on the rod\n"
    "  --mu, --d_g, --rho_g  optional header keys\n"
    "The trace is written to TRACE.csv.tmp, read back through the trace reader, then\n"
    "renamed: a failure leaves no TRACE.csv. Exit status 0, 1 for bad input, 2 for usage.\n";

const granpen::cli::Usage usage{"convert", HELP};

}    // namespace

int granpen::cli::convert(int argc, char **argv)
{
  if (argc < 1) return usage.no_arguments();
  if (!std::strcmp(argv[0], "--help")) return usage.help_asked();
  AveTimeSpec spec;
  std::string in = argv[0], out, from = "ave/time";
  std::vector<std::pair<std::string, std::string>> extra;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    std::string v;
    if (!next_value(argc, argv, i, v)) return usage.bare(needs_value(a));
    auto number = [&]() {
      double x;
      if (!number_arg(v, x, /*accept_underflow=*/true)) std::exit(usage.bare(needs_number(a, v)));
      return x;
    };
    if (a == "--from") from = v;
    else if (a == "--out") out = v;
    else if (a == "--units") spec.units = v;
    else if (a == "--column") spec.column = v;
    else if (a == "--v0") spec.v0 = number();
    else if (a == "--dt") spec.dt = number();
    else if (a == "--D") spec.D = number();
    else if (a == "--g") spec.g = number();
    else if (a == "--step0") spec.step0 = number();
    else if (a == "--z0") spec.z0 = number();
    else if (a == "--sign") spec.sign = number() < 0 ? -1.0 : 1.0;
    else if (a == "--mu" || a == "--d_g" || a == "--rho_g") extra.emplace_back(a.substr(2), (number(), v));
    else return usage.with_help(unknown_option(a));
  }
  if (from != "ave/time") return usage.bare("--from " + from + ": only ave/time is known");
  if (out.empty()) return usage.bare("--out TRACE.csv is required");
  try {
    const Trace t = read_ave_time(in, spec);
    TraceHeader h;
    h.units = t.units;
    h.v0 = t.v0;
    h.D = t.D;
    h.g = t.g;
    h.extra = extra;
    h.extra.emplace_back("source", t.keys.at("source"));
    const std::string tmp = out + ".tmp";
    std::FILE *f = std::fopen(tmp.c_str(), "w");
    if (!f) throw InputError(tmp + ": cannot write");
    std::string text = format_trace_header(h);
    for (std::size_t i = 0; i < t.t.size(); ++i) text += format_trace_row({t.t[i], t.z[i], t.F[i]});
    const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    if (std::fclose(f) != 0 || !ok) {
      std::remove(tmp.c_str());
      throw InputError(tmp + ": write failed");
    }
    try {
      read_trace(tmp);
    } catch (InputError &e) {
      std::remove(tmp.c_str());
      throw;
    }
    if (std::rename(tmp.c_str(), out.c_str()) != 0) throw InputError(out + ": cannot rename " + tmp);
    std::printf("granpen convert: %s -> %s: %zu rows, t = %.6g to %.6g s, z = %.4g to %.4g\n", in.c_str(), out.c_str(),
                t.t.size(), t.t.front(), t.t.back(), t.z.front(), t.z.back());
    return 0;
  } catch (InputError &e) {
    std::fprintf(stderr, "granpen convert: %s\n", e.what());
    return 1;
  }
}
