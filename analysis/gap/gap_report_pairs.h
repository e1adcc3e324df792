// granpen gap, stage 13 (report), the pair stage's part: diagnosis.json's "pairs" and
// report.md's "Two effects at once" and its plain verdict, from the stage's record
// (gap_pairs.h, PairStage) alone. Writes nothing, computes nothing.
#ifndef GRANPEN_GAP_REPORT_PAIRS_H
#define GRANPEN_GAP_REPORT_PAIRS_H

#include "gap_pairs.h"
#include "json_writer.h"    // Json

#include <optional>
#include <string>

namespace granpen {

// "pairs": null when the stage was not entered; else why, the line and the chain's seeded
// knot, every pair tried (magnitudes, likelihood ratio, threshold, evidence, its best single
// member's, the margin, explained, held out, passes, why not), the pair named and its
// confirmation on fresh runs.
Json pair_stage_json(const std::optional<PairStage> &stage);

// The verdict in plain words for a pair verdict (the first screen).
std::string pair_plain_verdict(const PairStage &stage, bool provisional);

// report.md's section ("" when the stage was not entered).
std::string pair_stage_markdown(const std::optional<PairStage> &stage);

}    // namespace granpen

#endif
