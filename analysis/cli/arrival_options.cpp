// granpen arrival: its command line (arrival_options.h).
#include "arrival_options.h"

#include "subcommand.h"

namespace {

const char *ARRIVAL_HELP =
    "usage: granpen arrival TRACE [--factor F] [--json FILE]\n"
    "When the rod's disturbance reaches rings of grains about its axis, and how fast it\n"
    "travels: reads TRACE (granpen-trace v1, with t) and what inputs/observe/arrival.lmp\n"
    "wrote beside it (TRACE.arrival.info, TRACE.arrival.txt: each ring's kinetic energy).\n"
    "A ring's arrival is its first sample at or after the rod's contact (the trace's first\n"
    "F > 0) with the kinetic energy above F times its mean before contact (default 100);\n"
    "the speed is the inverse slope of the arrival times against the radii, least squares\n"
    "(analysis/core/wave_arrival.h).\n"
    "Prints a line per ring (r, background, arrival in ms after contact) and a last line:\n"
    "'front at S m/s (+- SE) ...' or 'no front ...'.\n"
    "--json FILE: the same as JSON (speed_m_s, speed_se_m_s, rings[*].t_after_ms), written\n"
    "to a temporary name and renamed; never over an input.\n"
    "Exit status 0 (a front or not), 1 for an input that cannot be read, a trace without\n"
    "contact or without t, 2 for a usage error.\n";

}    // namespace

granpen::cli::ArrivalOptions granpen::cli::parse_arrival(int argc, char **argv)
{
  Command cmd("arrival", ARRIVAL_HELP);
  ArrivalOptions o;
  cmd.app.add_option("TRACE", o.trace, "the push's trace; its rings beside it")->required()->check(file_name());
  cmd.number("--factor", o.factor, "the front: kinetic energy above F x the ring's background (default 100)");
  cmd.app.add_option("--json", o.json, "write the result as JSON to FILE")->check(file_name());
  if (!cmd.parse(argc, argv, o.help)) return o;
  if (!(o.factor > 1) || o.factor > 1e12) throw UsageError("--factor: must lie above 1 and at most 1e12 (100: two decades over the background)");
  return o;
}
