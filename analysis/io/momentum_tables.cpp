// granpen analysis: granpen momentum's files (see momentum_tables.h).
#include "momentum_tables.h"

#include "json_text.h"

#include <cmath>
#include <sstream>

namespace granpen {

namespace {

// %.10g; non-finite as nan in a table, 0 in JSON, or null where a value may be undefined
std::string csv_num(double v) { return std::isfinite(v) ? json_number("%.10g", v) : std::string("nan"); }
Json js(double v) { return json_rounded("%.10g", v); }
Json js_or_null(double v) { return std::isfinite(v) ? js(v) : Json(); }

Json parameters_json(const MomentumStudyParams &p, const MomentumProvenance &how)
{
  Json j = {{"v0", js(p.v0)}, {"g", js(p.g)}, {"D", js(p.D)}, {"D_source", how.D_source}, {"R", js(0.5 * p.D)},
            {"mu", js(p.mu)}, {"mu_source", how.mu_source}, {"rho_g", js(how.rho_g)}, {"rho_g_source", how.rho_g_source},
            {"masses", how.mass_column ? "column mass" : "rho_g 4/3 pi r^3"}, {"z_s", js(p.z_s)},
            {"z_s_source", how.z_s_source}, {"match", p.by_time ? "time" : "depth"}};
  if (p.by_time) j["push_step"] = p.push_step, j["dt"] = js(p.dt);
  j["rod_type"] = how.rod_type;
  j["periodic"] = how.periodic;
  Json names = Json::array(), bounds = Json::array();
  for (int k = 0; k < MOMENTUM_NCLASS; ++k) names.push_back(MOMENTUM_CLASS_NAMES[k]), bounds.push_back(js(p.classes.bound[k]));
  j["classes"] = {{"source", how.class_source}, {"names", names}, {"bounds", bounds}, {"v_move", js(p.classes.vmove)}};
  return j;
}

Json frame_json(const MomentumFrameRecord &r)
{
  Json classes = Json::array();
  for (int c = 0; c < MOMENTUM_NCLASS; ++c)
    classes.push_back({{"count", js(r.tally.count[c])}, {"mass", js(r.tally.mass[c])}, {"p_up", js(r.tally.p_up[c])}});
  return {{"timestep", r.timestep}, {"where", r.where}, {"t", js_or_null(r.t)}, {"t_tilde", js_or_null(r.t_tilde)},
          {"z_tip", js(r.z_tip)}, {"selected", r.tally.selected}, {"classes", classes}, {"M_slow", js(r.tally.M_slow)},
          {"M_move", js(r.tally.M_move)}, {"mu_g_M", js(r.mu_g_M)}, {"F", js_or_null(r.F)}};
}

}    // namespace

Json momentum_json(const MomentumStudyParams &p, const std::vector<MomentumFrameRecord> &frames,
                   const DragComparison &dc, const MomentumProvenance &how)
{
  Json j;
  j["tool"] = "granpen momentum";
  j["units"] = "those of the dump and the trace (granpen decks: cgs: cm, g, s, dyne)";
  j["inputs"] = {{"dumps", how.dumps}, {"trace", how.trace}, {"frames", frames.size()}};
  j["parameters"] = parameters_json(p, how);
  j["drag"] = {{"ok", dc.ok}, {"n", dc.n}, {"k", js(dc.fit.b)}, {"k_se", js(dc.fit.se_b)}, {"rms", js(dc.fit.rms)},
               {"ratio_mean", js(dc.ratio_mean)}, {"ratio_se", js(dc.ratio_se)}, {"note", dc.note},
               {"paper", "F about equal to mu g M (1:1)"}};
  j["frames"] = Json::array();
  for (const auto &r : frames) j["frames"].push_back(frame_json(r));
  j["notes"] = how.notes;
  return j;
}

std::vector<std::pair<std::string, std::string>> momentum_files(const MomentumStudyParams &p,
                                                                const std::vector<MomentumFrameRecord> &frames,
                                                                const DragComparison &drag,
                                                                const MomentumProvenance &how)
{
  std::ostringstream cls, drg;
  cls << "t_tilde,z_tip,class,count,p_up\n";
  drg << "t_tilde,z_tip,F,mu_g_M\n";
  for (const auto &r : frames) {
    for (int k = 0; k < MOMENTUM_NCLASS; ++k)
      cls << csv_num(r.t_tilde) << ',' << csv_num(r.z_tip) << ',' << MOMENTUM_CLASS_NAMES[k] << ','
          << csv_num(r.tally.count[k]) << ',' << csv_num(r.tally.p_up[k]) << '\n';
    drg << csv_num(r.t_tilde) << ',' << csv_num(r.z_tip) << ',' << csv_num(r.F) << ',' << csv_num(r.mu_g_M) << '\n';
  }
  return {{"momentum.json", json_layout(momentum_json(p, frames, drag, how), 1)},
          {"momentum_classes.csv", cls.str()},
          {"momentum_drag.csv", drg.str()}};
}

}    // namespace granpen
