// granpen gap, stage 13 (report): a pure function of the record (gap_result.h), the output folder:
// diagnosis.json (exact names; other tools read them), report.md with its figures
// (io/plot_writer.h), baseline/ and corrected/ (the simulated traces before and after).
#ifndef GRANPEN_GAP_REPORT_H
#define GRANPEN_GAP_REPORT_H

#include "gap_result.h"

#include <string>

namespace granpen {

// Writes diagnosis.json, report.md and the figures into dir (which exists).
void write_gap_report(const Diagnosis &d, const std::string &dir);

// The whole output written to OUT.partial, then moved to out (an older out replaced only
// then); throws InputError when a write fails (out then untouched).
void write_gap_output(const Diagnosis &d, const std::string &out);

}    // namespace granpen

#endif
