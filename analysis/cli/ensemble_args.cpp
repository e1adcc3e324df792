// granpen fit, collapse and plot: the --ensemble options (see ensemble_args.h).
#include "ensemble_args.h"

namespace granpen {
namespace cli {

void add_ensemble_options(Command &cmd, EnsembleOptions &o)
{
  cmd.app.add_flag("--ensemble", o.on, "average the runs of each (v0, g, D) after aligning their force onsets");
  cmd.app.add_option("--ensemble-bin", o.mean.bin, "--ensemble: depth bin width, cm (default: the runs' median depth step)")
      ->check(positive_number())->type_name("W");
  cmd.app.add_option("--ensemble-v0-tolerance", o.mean.v0_tolerance,
                     "--ensemble: runs whose v0 lie within this fraction of the slowest of their group are one case "
                     "(measured speeds about one nominal; default 0: equal v0)")
      ->check(positive_number())->type_name("R");
  cmd.app.add_option("--bootstrap", o.boot.resamples, "--ensemble: bootstrap resamples over runs (default 1000, >= 20)")
      ->check(whole_number(20, 1000000))->type_name("B");
}

void check_ensemble_options(const Command &cmd, const EnsembleOptions &o)
{
  if (o.on) return;
  for (const char *flag : {"--ensemble-bin", "--ensemble-v0-tolerance", "--bootstrap"})
    if (cmd.app.get_option(flag)->count() > 0) throw UsageError(std::string(flag) + " needs --ensemble");
}

}    // namespace cli
}    // namespace granpen
