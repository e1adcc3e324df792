// granpen rate: its command line (rate_options.h).
#include "rate_options.h"

#include "subcommand.h"

namespace {

const char *RATE_HELP =
    "usage: granpen rate K N [--level L]\n"
    "A rate of K events in N trials (the false-alarm rate of granpen gap on data without an\n"
    "effect: validation/gap_bench.sh) with its exact two-sided confidence interval\n"
    "(Clopper-Pearson, analysis/core/rate_interval.h): 0 of 20 gives 0 to 0.168 at 95%.\n"
    "Prints one line: K, N, the rate, the interval's low and high ends, the level, tab-separated.\n"
    "Exit status 0; 2 for a usage error (K above N, N below 1, L outside 0 to 1).\n";

// the largest count the interval is summed over (the kernel is exact to rounding far beyond)
constexpr long long MAX_TRIALS = 1000000;

}    // namespace

granpen::cli::RateOptions granpen::cli::parse_rate(int argc, char **argv)
{
  Command cmd("rate", RATE_HELP);
  RateOptions o;
  cmd.app.add_option("K", o.events, "events (false alarms)")->required()->check(whole_number(0, MAX_TRIALS));
  cmd.app.add_option("N", o.trials, "trials (data sets)")->required()->check(whole_number(1, MAX_TRIALS));
  cmd.number("--level", o.level, "the interval's confidence level (default 0.95)");
  if (!cmd.parse(argc, argv, o.help)) return o;
  if (o.events > o.trials) throw UsageError("K = " + std::to_string(o.events) + " events in N = " + std::to_string(o.trials) + " trials: K must not exceed N");
  if (!(o.level > 0 && o.level < 1)) throw UsageError("--level: must lie between 0 and 1 (0.95 for 95%)");
  return o;
}
