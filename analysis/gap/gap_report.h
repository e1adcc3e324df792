// granpen gap, stage 9 (report): G per regime before and after, and the output folder:
// diagnosis.json (exact names; other tools read them), report.md with its figures
// (io/plot_writer.h), baseline/ and corrected/ (the simulated traces before and after).
#ifndef GRANPEN_GAP_REPORT_H
#define GRANPEN_GAP_REPORT_H

#include "gap_result.h"

#include <string>

namespace granpen {

// d.gap_by_regime: per regime (peak: z <= 0.35 D; transient; linear) the mean over speeds
// of G restricted to the regime's bins, before and after (without the noise debiasing,
// which is in the overall G).
void gap_by_regime(const GapGrid &grid, double D, Diagnosis &d);

// Writes diagnosis.json, report.md and the figures into dir (which exists).
void write_gap_report(const Diagnosis &d, const std::string &dir);

// The whole output written to OUT.partial, then moved to out (an older out replaced only
// then); throws InputError when a write fails (out then untouched).
void write_gap_output(const Diagnosis &d, const std::string &out);

}    // namespace granpen

#endif
