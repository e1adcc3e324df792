// granpen fit, collapse and plot: the options of --ensemble (runs of one case averaged,
// core/ensemble_average.h; uncertainties by a bootstrap over runs, core/ensemble_fit.h),
// added to a parse function's Command and checked after its parse (NAME_options.h).
#ifndef GRANPEN_CLI_ENSEMBLE_ARGS_H
#define GRANPEN_CLI_ENSEMBLE_ARGS_H

#include "ensemble_average.h"
#include "ensemble_fit.h"
#include "subcommand.h"

namespace granpen {
namespace cli {

// Checks (after check_ensemble_options): mean.bin 0 (not given: the runs' median depth
// step) or > 0 and finite; boot.resamples 20 to 1000000; without on, both at their
// defaults (0, 1000).
struct EnsembleOptions {
  bool on = false;          // --ensemble
  EnsembleParams mean;      // --ensemble-bin, --ensemble-v0-tolerance
  BootstrapParams boot;     // --bootstrap
};

// Adds --ensemble, --ensemble-bin, --ensemble-v0-tolerance and --bootstrap to cmd, bound to o.
void add_ensemble_options(Command &cmd, EnsembleOptions &o);
// After cmd.parse: UsageError when --ensemble-bin or --bootstrap came without --ensemble.
void check_ensemble_options(const Command &cmd, const EnsembleOptions &o);

}    // namespace cli
}    // namespace granpen

#endif
