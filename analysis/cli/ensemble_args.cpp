// granpen fit, collapse and plot: the --ensemble options (see ensemble_args.h).
#include "ensemble_args.h"

namespace granpen {
namespace cli {

void EnsembleOptions::add_to(Command &cmd)
{
  cmd.app.add_flag("--ensemble", on, "average the runs of each (v0, g, D) after aligning their force onsets");
  bin_ = cmd.app.add_option("--ensemble-bin", mean.bin, "--ensemble: depth bin width, cm (default: the runs' median depth step)")
      ->check(positive_number())->type_name("W");
  boot_ = cmd.app.add_option("--bootstrap", boot.resamples, "--ensemble: bootstrap resamples over runs (default 1000, >= 20)")
      ->check(CLI::Range(20, 1000000))->type_name("B");
}

void EnsembleOptions::check() const
{
  if (on) return;
  if (bin_ && bin_->count() > 0) throw UsageError("--ensemble-bin needs --ensemble");
  if (boot_ && boot_->count() > 0) throw UsageError("--bootstrap needs --ensemble");
}

}    // namespace cli
}    // namespace granpen
