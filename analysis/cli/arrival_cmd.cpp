// granpen arrival TRACE: when the rod's disturbance reaches rings about its axis and how
// fast it travels (core/wave_arrival.h on io/arrival_table.h's rings), a line per ring and
// the front's speed; --json the same as JSON.
#include "arrival_options.h"
#include "arrival_table.h"
#include "atomic_file.h"
#include "errors.h"
#include "json_text.h"
#include "json_writer.h"
#include "subcommand.h"
#include "subcommands.h"
#include "trace_parting.h"
#include "trace_reader.h"
#include "wave_arrival.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace {

using granpen::json_number;
using granpen::json_rounded;
using granpen::Json;

// ms after contact of a ring's arrival, "-" when the front did not reach it
std::string after_ms(const granpen::StationArrival &s, double contact)
{
  return s.arrived ? json_number("%.4g", (s.t - contact) * 1e3) : std::string("-");
}

std::string front_line(const granpen::WaveArrival &w)
{
  if (!w.fitted || !std::isfinite(w.speed))
    return "no front: " + std::to_string(w.arrived) + " of " + std::to_string(w.stations.size()) +
           " rings reached, arrival times not increasing with r";
  std::string se = std::isfinite(w.speed_se) ? " +- " + json_number("%.2g", w.speed_se * 1e-2) : "";
  return "front at " + json_number("%.3g", w.speed * 1e-2) + se + " m/s over " + std::to_string(w.arrived) + " rings";
}

Json arrival_json(const granpen::WaveArrival &w, const granpen::ArrivalTable &a, double contact,
                  const granpen::cli::ArrivalOptions &o)
{
  Json j;
  j["trace"] = o.trace;
  j["factor"] = json_rounded("%.6g", o.factor);
  j["contact_s"] = json_rounded("%.9g", contact);
  j["ring_width"] = json_rounded("%.6g", a.width);
  j["layer"] = json_rounded("%.6g", a.layer);
  j["fitted"] = w.fitted && std::isfinite(w.speed);
  if (w.fitted && std::isfinite(w.speed)) {
    j["speed_m_s"] = json_rounded("%.6g", w.speed * 1e-2);
    if (std::isfinite(w.speed_se)) j["speed_se_m_s"] = json_rounded("%.6g", w.speed_se * 1e-2);
    j["t_axis_after_ms"] = json_rounded("%.6g", (w.t_axis - contact) * 1e3);
  }
  Json rings = Json::array();
  for (const auto &s : w.stations) {
    Json r;
    r["r"] = json_rounded("%.6g", s.r);
    r["background"] = std::isfinite(s.background) ? json_rounded("%.6g", s.background) : Json(nullptr);
    r["arrived"] = s.arrived;
    r["t_after_ms"] = s.arrived ? json_rounded("%.6g", (s.t - contact) * 1e3) : Json(nullptr);
    rings.push_back(r);
  }
  j["rings"] = rings;
  return j;
}

}    // namespace

int granpen::cli::run_arrival(const ArrivalOptions &o)
{
  if (!o.json.empty())
    refuse_overwriting_inputs(o.json, "--json", {o.trace, o.trace + ".arrival.info", o.trace + ".arrival.txt"});
  const Trace tr = to_cgs(read_trace(o.trace));
  require_t(tr, "granpen arrival");
  const double contact = contact_time(tr.t, tr.F);
  if (std::isnan(contact)) throw InputError(o.trace + ": no contact (F is never above 0): granpen arrival times from contact");
  const ArrivalTable a = read_arrival_table(o.trace, tr.v0, tr.D, tr.g);
  ArrivalSettings s;
  s.factor = o.factor;
  const WaveArrival w = wave_arrival(a.t, a.ke, a.radii, contact, s);
  std::string text = "# granpen arrival: rings of " + json_number("%g", a.width) + " cm in the top " + json_number("%g", a.layer) +
                     " cm, the front at " + json_number("%g", o.factor) + " x each ring's kinetic energy before contact\n";
  text += "# " + o.trace + " (contact at t = " + json_number("%.6g", contact) + " s)\n";
  text += "r_cm\tbackground_erg\tarrival_ms_after_contact\n";
  for (const auto &st : w.stations)
    text += json_number("%g", st.r) + "\t" + json_number("%.3g", st.background) + "\t" + after_ms(st, contact) + "\n";
  text += front_line(w) + "\n";
  if (!o.json.empty()) write_json(o.json, arrival_json(w, a, contact, o));
  if (std::fputs(text.c_str(), stdout) == EOF || std::fflush(stdout) != 0) throw OutputError("standard output: write failed");
  return EXIT_OK;
}

int granpen::cli::arrival(int argc, char **argv) { return run_parsed(parse_arrival, run_arrival, argc, argv); }
