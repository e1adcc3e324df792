// granpen fit, collapse and plot: the --ensemble options (see ensemble_args.h).
#include "ensemble_args.h"

namespace granpen {
namespace cli {

const char *const ENSEMBLE_HELP =
    "--ensemble: traces of the same v0, g and D are one ensemble: each run's depths shifted so\n"
    "that its force onset sits at the runs' mean onset (as granpen gap aligns), F averaged in\n"
    "depth bins over the depths every run covers (--ensemble-bin, default the runs' depth\n"
    "step), with the standard error over runs per bin (the run-to-run band). Every number is\n"
    "then computed on the ensemble mean; its +- is the standard error from a bootstrap over\n"
    "runs (--bootstrap resamples, fixed seed; docs/postprocess.md says why runs and not bins).\n"
    "The per-run results are still printed and written.\n";

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
