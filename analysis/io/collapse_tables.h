// granpen analysis: granpen collapse's inputs and files: each trace read with its depth
// term k_z (fitted, or from alpha), the binned curves as CSV (trace, v0, g, D, t~, F/F_z)
// and every result as JSON (core/collapse.h).
#ifndef GRANPEN_COLLAPSE_TABLES_H
#define GRANPEN_COLLAPSE_TABLES_H

#include "collapse.h"
#include "json_writer.h"
#include "trace_fit.h"
#include "trace_reader.h"

#include <cmath>
#include <string>
#include <vector>

namespace granpen {

// F_z = k_z z: k_z fitted over kz_zmin..kz_zmax (core/trace_fit.h), or with alpha > 0
// k_z = alpha mu rho_g g D^2 (mu, rho_g > 0 given, else from the headers, else 0.3 and 3).
struct DepthTerm {
  double kz_zmin = 3.0, kz_zmax = INFINITY;
  double alpha = 0.0, mu = 0.0, rho_g = 0.0;
};
// The traces (cgs) with their k_z (a window the data do not fill shortened, as
// core/trace_fit's shorten_window; notes say so). A trace without a positive depth term is
// a line in left_out naming the file.
std::vector<CollapseInput> collapse_inputs(const std::vector<Trace> &traces, const DepthTerm &dt,
                                           std::vector<std::string> &left_out, std::vector<std::string> &notes);

// The depth term of a trace or an ensemble of the case of `header`: k_z = alpha mu rho_g g
// D^2 when dt.alpha > 0 (fixed), else the window of the fit (shorten_window on).
double alpha_depth_term(const DepthTerm &dt, const Trace &header);
TraceFitParams depth_term_window(const DepthTerm &dt, const Trace &header);

std::string collapse_curves_csv(const CollapseResult &r);
Json collapse_json(const CollapseResult &r, const CollapseParams &p);

}    // namespace granpen

#endif
