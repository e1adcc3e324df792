// granpen analysis: the flow table study's stages (see flow_table_study.h).
#include "flow_table_study.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace granpen {

namespace {

// distinct values of v, within a tolerance of their spread (1e-9 of it, at least 1e-9: the
// tables' printed digits make equal values equal)
std::size_t distinct_count(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const double tol = v.empty() ? 0.0 : 1e-9 * std::max(1.0, v.back() - v.front());
  std::size_t n = 0;
  double last = 0.0;
  for (double x : v)
    if (n == 0 || x - last > tol) ++n, last = x;
  return n;
}

}    // namespace

const char *flow_table_stage_name(FlowTableStage s)
{
  switch (s) {
    case FlowTableStage::profile: return "profile";
    case FlowTableStage::local: return "local";
    case FlowTableStage::edge: return "edge";
  }
  return "?";
}

EdgeLine fit_edge_line(const std::vector<double> &I, const std::vector<double> &phi)
{
  EdgeLine e;
  for (std::size_t i = 0; i < I.size() && i < phi.size(); ++i)
    if (std::isfinite(I[i]) && std::isfinite(phi[i])) e.I.push_back(I[i]), e.phi.push_back(phi[i]);
  if (e.I.size() >= 3 && distinct_count(e.I) >= 2) {
    e.fit = linear_fit(e.I, e.phi);
    e.ok = true;
  }
  return e;
}

FlowTableStudy run_flow_table_study(const FlowTableColumns &c, const FlowTableProgress &progress)
{
  FlowTableStudy s;
  if (c.has_profile) {
    if (progress) progress(FlowTableStage::profile);
    s.profile = fit_exponential(c.z, c.vz, c.vz_se);
    s.profile_done = true;
    if (c.local_width > 0.0) {
      if (progress) progress(FlowTableStage::local);
      s.local = local_exponential_fits(c.z, c.vz, c.vz_se, c.local_width);
      s.local_done = true;
    }
  }
  if (c.has_edge) {
    if (progress) progress(FlowTableStage::edge);
    s.edge = fit_edge_line(c.I, c.phi);
    s.edge_done = true;
  }
  return s;
}

}    // namespace granpen
