// granpen analysis: granpen collapse's inputs and files: the traces read and the ensembles
// averaged as the inputs of core/collapse_study.h (the depth term from alpha when asked
// for; the fits are the study's), the binned curves as CSV (trace, v0, g, D, t~, F/F_z) and
// every result as JSON (core/collapse.h).
#ifndef GRANPEN_COLLAPSE_TABLES_H
#define GRANPEN_COLLAPSE_TABLES_H

#include "collapse.h"
#include "collapse_study.h"
#include "ensemble_tables.h"
#include "json_writer.h"
#include "trace_reader.h"

#include <cmath>
#include <string>
#include <vector>

namespace granpen {

// F_z = k_z z: k_z fitted over kz_zmin..kz_zmax (core/collapse_study.h), or with alpha > 0
// k_z = alpha mu rho_g g D^2 (mu, rho_g > 0 given, else from the headers, else 0.3 and 3).
struct DepthTerm {
  double kz_zmin = 3.0, kz_zmax = INFINITY;
  double alpha = 0.0, mu = 0.0, rho_g = 0.0;
};

// k_z = alpha mu rho_g g D^2 of the case of `header` (dt.alpha > 0).
double alpha_depth_term(const DepthTerm &dt, const Trace &header);

// The study's inputs: each trace (cgs; named by its path) with its depth term given when
// dt.alpha > 0; each group's mean with its case, the depth term from its first run's header.
std::vector<CollapseTrace> collapse_traces(const std::vector<Trace> &traces, const DepthTerm &dt);
std::vector<CollapseEnsemble> collapse_ensemble_inputs(const std::vector<TraceGroup> &groups, const DepthTerm &dt);
// The study's parameters: the collapse's, the k_z window of dt, the bootstrap's.
CollapseStudyParams collapse_study_params(const CollapseParams &p, const DepthTerm &dt, const BootstrapParams &b = {});

std::string collapse_curves_csv(const CollapseResult &r);
Json collapse_json(const CollapseResult &r, const CollapseParams &p);

}    // namespace granpen

#endif
