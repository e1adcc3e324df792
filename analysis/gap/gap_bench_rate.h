// granpen gap: the false-alarm rate measured at a scenario's scale on real LAMMPS, as the
// diagnosis reports it beside its own null replicates (issue 37, section 3). The figure is
// committed per scenario by validation/gap_bench.sh, in the decks' folder:
//   INPUTS/false_alarms/SCENARIO.txt      # comments; key = value lines:
//     sets = 20          data sets without an effect, each diagnosed blind
//     alarms = 0         of them with a verdict other than none
//     source = ...       where the sets are (optional text)
// The diagnosis computes the rate's exact 95% interval from the two counts
// (core/rate_interval.h: Clopper-Pearson). No file: no measured rate (nullopt).
#ifndef GRANPEN_GAP_BENCH_RATE_H
#define GRANPEN_GAP_BENCH_RATE_H

#include "rate_interval.h"

#include <optional>
#include <string>

namespace granpen {

struct MeasuredFalseAlarms {
  std::string file, source;
  int sets = 0, alarms = 0;
  RateInterval interval;    // 95%
};

// The figure of scenario under the decks' folder inputs; nullopt when it has none. Throws
// InputError naming file:line for a line that is not key = value, an unknown or repeated
// key, a count that is not a whole number, alarms above sets or sets below 1.
std::optional<MeasuredFalseAlarms> measured_false_alarms(const std::string &inputs, const std::string &scenario);

// The same from the file's text (file: for messages).
MeasuredFalseAlarms parse_false_alarm_figure(const std::string &text, const std::string &file);

}    // namespace granpen

#endif
