// granpen rate K N: a rate with its exact interval (core/rate_interval.h), one line.
#include "rate_interval.h"
#include "rate_options.h"
#include "subcommand.h"
#include "subcommands.h"
#include "text_util.h"

#include <cstdio>

int granpen::cli::run_rate(const RateOptions &o)
{
  const RateInterval r = clopper_pearson(int(o.events), int(o.trials), o.level);
  std::fputs(format_text("%lld\t%lld\t%.4f\t%.4f\t%.4f\t%g\n", o.events, o.trials, r.rate, r.low, r.high, o.level).c_str(), stdout);
  return EXIT_OK;
}
int granpen::cli::rate(int argc, char **argv) { return run_parsed(parse_rate, run_rate, argc, argv); }
