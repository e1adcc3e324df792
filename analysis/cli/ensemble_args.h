// granpen fit, collapse and plot: the options of --ensemble (runs of one case averaged,
// core/ensemble_average.h; uncertainties by a bootstrap over runs, core/ensemble_fit.h).
#ifndef GRANPEN_CLI_ENSEMBLE_ARGS_H
#define GRANPEN_CLI_ENSEMBLE_ARGS_H

#include "ensemble_average.h"
#include "ensemble_fit.h"
#include "subcommand.h"

namespace granpen {
namespace cli {

struct EnsembleOptions {
  bool on = false;          // --ensemble
  EnsembleParams mean;      // --ensemble-bin
  BootstrapParams boot;     // --bootstrap
  // Adds --ensemble, --ensemble-bin and --bootstrap to cmd.
  void add_to(Command &cmd);
  // UsageError when --ensemble-bin or --bootstrap came without --ensemble (after parsing).
  void check() const;

 private:
  CLI::Option *bin_ = nullptr, *boot_ = nullptr;
};

}    // namespace cli
}    // namespace granpen

#endif
