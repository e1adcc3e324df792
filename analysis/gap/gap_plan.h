// granpen gap: which simulations a diagnosis needs (pure planning over the effect library).
#ifndef GRANPEN_GAP_PLAN_H
#define GRANPEN_GAP_PLAN_H

#include "gap_sims.h"

#include <string>
#include <vector>

namespace granpen {

// Seeds of the signature simulations (baseline and every effect knot) and of the
// confirming runs, which must be beds no fit has seen; the refining runs' beds (the
// magnitude corrected from the confirming runs, which it has seen).
extern const std::vector<std::string> SIGNATURE_SEEDS, REFERENCE_SEEDS, CONFIRM_SEEDS, REFINE_SEEDS;

// The baseline and every knot of the chosen effects, at the speeds v0 (the cache).
std::vector<SimRequest> signature_requests(const std::string &scenario, const std::vector<std::string> &v0,
                                           const std::vector<const Effect *> &effects);

// The runs confirming effect e at magnitude a with fresh seeds, at speeds v0; a push-only
// effect pours the fresh beds once (sweep confirm_beds, or refine_beds) and reuses them.
std::vector<SimRequest> confirm_requests(const std::string &scenario, const Effect &e, double a,
                                         const std::vector<std::string> &v0, const std::string &tag,
                                         const std::vector<std::string> &seeds = CONFIRM_SEEDS);

}    // namespace granpen

#endif
