// granpen parting: its command line (parting_options.h).
#include "parting_options.h"

#include "subcommand.h"

namespace {

const char *PARTING_HELP =
    "usage: granpen parting A B [--window S] [--threshold X] [--sustain N] [--json FILE]\n"
    "When two pushes part: traces A and B (granpen-trace v1, with t) read in windows of time\n"
    "after each one's own contact (its first sample with F > 0), the ratio A / B of their mean\n"
    "drag per window, and the parting, the first window from which N windows in a row leave 1\n"
    "by X or more on the same side (analysis/core/trace_parting.h). Meant for two pushes over\n"
    "the same grains (one tile under the rod in boxes of different width): an echo from the\n"
    "narrower box's boundary parts them at a time, a flow front at a depth.\n"
    "Prints a line per window (t from, t to in ms after contact, A / B) and a last line:\n"
    "'parted at T ms after contact (z = Z cm in B) ...' or 'not parted ...'.\n"
    "--json FILE: the same as JSON (parted, t_part_ms, z_part, ratio_at_part, largest_before,\n"
    "windows), written to a temporary name and renamed; never over A or B.\n"
    "Exit status 0 (parted or not), 1 for a trace that cannot be read or has no contact,\n"
    "2 for a usage error.\n";

constexpr double MAX_WINDOW_S = 10;
constexpr long long MAX_SUSTAIN = 1000;

}    // namespace

granpen::cli::PartingOptions granpen::cli::parse_parting(int argc, char **argv)
{
  Command cmd("parting", PARTING_HELP);
  PartingOptions o;
  cmd.app.add_option("A", o.a, "the first trace (the ratio's numerator)")->required()->check(file_name());
  cmd.app.add_option("B", o.b, "the second trace (its denominator; z_part is its depth)")->required()->check(file_name());
  cmd.number("--window", o.window, "window width, s (default 5e-4: 0.5 ms)");
  cmd.number("--threshold", o.threshold, "|A / B - 1| that counts as apart (default 0.03)");
  cmd.app.add_option("--sustain", o.sustain, "windows in a row apart, on one side (default 2)")->check(whole_number(1, MAX_SUSTAIN));
  cmd.app.add_option("--json", o.json, "write the result as JSON to FILE")->check(file_name());
  if (!cmd.parse(argc, argv, o.help)) return o;
  if (!(o.window > 0) || o.window > MAX_WINDOW_S) throw UsageError("--window: must be a time above 0 and at most 10 s, in s (5e-4 for 0.5 ms)");
  if (!(o.threshold > 0)) throw UsageError("--threshold: must be above 0 (0.03 for 3%)");
  return o;
}
