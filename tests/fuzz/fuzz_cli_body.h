// The body of the CLI option-parser fuzz target, shared by the libFuzzer driver
// (fuzz_cli_options.cpp) and the gtest driver CI runs without clang (tests/analysis/cli/
// test_cli_options.cpp: the committed corpus and regressions, then a fixed number of
// seeded random mutations), so that an input is replayed exactly as the fuzzer ran it.
//
// The input's bytes are an argument vector, one word a line ('\n' separates words; a
// word may be empty). The first word names the subcommand; when it names none, it picks
// one (its bytes summed, modulo 11) and the remaining words are still the arguments. Each
// subcommand's parse function (analysis/cli/NAME_options.h) may accept the words, answer
// --help, or throw UsageError; anything else thrown, or an accepted parse whose options
// break the checks NAME_options.h states for them, aborts.
#ifndef GRANPEN_FUZZ_CLI_BODY_H
#define GRANPEN_FUZZ_CLI_BODY_H

#include "fuzz_check.h"
#include "calibration_options.h"
#include "check_options.h"
#include "collapse_options.h"
#include "convert_options.h"
#include "fit_options.h"
#include "flow_options.h"
#include "gap_options.h"
#include "get_options.h"
#include "import_options.h"
#include "momentum_options.h"
#include "plot_options.h"
#include "arrival_options.h"
#include "parting_options.h"
#include "rate_options.h"
#include "checkpoint_options.h"
#include "sweep_options.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

namespace granpen_fuzz {

using namespace granpen::cli;

inline bool positive_finite(double v) { return std::isfinite(v) && v > 0.0; }
// 0 (not given: the header's or a default) or a positive finite value
inline bool zero_or_positive(double v) { return v == 0.0 || positive_finite(v); }
// a header value given as text: a whole positive finite number
inline bool positive_text(const std::string &s)
{
  char *end = nullptr;
  errno = 0;
  const double v = std::strtod(s.c_str(), &end);
  return !s.empty() && *end == '\0' && positive_finite(v);
}
inline bool periodic_matches(const std::string &p, bool x, bool y)
{
  return (p == "xy" && x && y) || (p == "x" && x && !y) || (p == "y" && !x && y) || (p == "none" && !x && !y);
}
// a number option of flow and momentum: NaN (not given) or finite
inline bool not_given_or_finite(double v) { return std::isnan(v) || std::isfinite(v); }
// NaN (not given) or > 0 and finite
inline bool not_given_or_positive(double v) { return std::isnan(v) || positive_finite(v); }
inline void check_rod(const granpen::RodOptions &r) { GRANPEN_FUZZ_CHECK(r.rod_type >= 1); }
// --ensemble-bin 0 (the runs' median step) or > 0; --bootstrap 20 to 1000000; both at
// their defaults without --ensemble (ensemble_args.h)
inline void check_ensemble(bool on, const granpen::EnsembleParams &mean, const granpen::BootstrapParams &boot)
{
  GRANPEN_FUZZ_CHECK(mean.bin == 0.0 || positive_finite(mean.bin));
  GRANPEN_FUZZ_CHECK(boot.resamples >= 20 && boot.resamples <= 1000000);
  if (!on) GRANPEN_FUZZ_CHECK(mean.bin == 0.0 && boot.resamples == granpen::BootstrapParams().resamples);
}

inline void check(const ConvertOptions &o)
{
  GRANPEN_FUZZ_CHECK(!o.in.empty() && !o.out.empty() && o.from == "ave/time");
  const granpen::AveTimeSpec &s = o.spec;
  for (double v : {s.v0, s.dt, s.D, s.g}) GRANPEN_FUZZ_CHECK(positive_finite(v));
  GRANPEN_FUZZ_CHECK(s.sign == 1.0 || s.sign == -1.0);
  GRANPEN_FUZZ_CHECK(std::isnan(s.step0) || (s.step0 >= 0.0 && s.step0 == std::floor(s.step0)));
  GRANPEN_FUZZ_CHECK(std::isfinite(s.z0));
  GRANPEN_FUZZ_CHECK(s.units == "cgs" || s.units == "si");
  std::set<std::string> keys;
  for (const auto &kv : o.extra) {
    GRANPEN_FUZZ_CHECK(keys.insert(kv.first).second);
    GRANPEN_FUZZ_CHECK(kv.first == "mu" || kv.first == "d_g" || kv.first == "rho_g");
    GRANPEN_FUZZ_CHECK(positive_text(kv.second));
  }
}
inline void check(const CheckOptions &o) { GRANPEN_FUZZ_CHECK(!o.traces.empty()); }
inline void check(const FitOptions &o)
{
  const granpen::FitWindow &w = o.window;
  GRANPEN_FUZZ_CHECK(!o.traces.empty());
  if (w.tmin != -1.0) {
    GRANPEN_FUZZ_CHECK(positive_finite(w.tmin) && w.zmin == 3.0);
  } else {
    GRANPEN_FUZZ_CHECK(std::isfinite(w.zmin) && w.zmin < w.zmax);
  }
  GRANPEN_FUZZ_CHECK(!std::isnan(w.zmax));
  GRANPEN_FUZZ_CHECK(zero_or_positive(w.mu) && zero_or_positive(w.rho_g));
  check_ensemble(o.ensemble.on, o.ensemble.mean, o.ensemble.boot);
  GRANPEN_FUZZ_CHECK(o.ensemble_csv.empty() || o.ensemble.on);
}
inline void check(const CalibrationOptions &o)
{
  GRANPEN_FUZZ_CHECK(!o.sweep.empty() && !o.out.empty());
  GRANPEN_FUZZ_CHECK(std::isfinite(o.zmin) && std::isfinite(o.zmax) && o.zmin < o.zmax);
}
inline void check(const CollapseOptions &o)
{
  GRANPEN_FUZZ_CHECK(!o.traces.empty());
  GRANPEN_FUZZ_CHECK(std::isfinite(o.depth.kz_zmin) && o.depth.kz_zmin < o.depth.kz_zmax);
  for (double v : {o.depth.alpha, o.depth.mu, o.depth.rho_g}) GRANPEN_FUZZ_CHECK(zero_or_positive(v));
  GRANPEN_FUZZ_CHECK(positive_finite(o.params.band) && positive_finite(o.params.tbin));
  GRANPEN_FUZZ_CHECK(std::isfinite(o.params.zmin));
  check_ensemble(o.ensemble.on, o.ensemble.mean, o.ensemble.boot);
}
inline void check(const SweepOptions &o)
{
  const granpen::RunnerOptions &r = o.runner;
  GRANPEN_FUZZ_CHECK(!o.spec.empty() && !r.out_root.empty());
  GRANPEN_FUZZ_CHECK(r.jobs >= 1 && r.checkpoint >= 1 && r.ranks >= 1);
  GRANPEN_FUZZ_CHECK(r.only_index == -1 || r.only_index >= 0);
  GRANPEN_FUZZ_CHECK(r.progress_seconds >= 1 && r.progress_seconds <= 86400);
}
inline void check(const FlowOptions &o)
{
  GRANPEN_FUZZ_CHECK(!o.dumps.empty() && !o.out_dir.empty());
  for (double v : {o.D, o.d_g, o.rho_g, o.v0, o.g, o.dr, o.dz, o.rmax, o.profile_radius, o.edge_wr, o.edge_wz})
    GRANPEN_FUZZ_CHECK(not_given_or_positive(v));
  GRANPEN_FUZZ_CHECK(not_given_or_finite(o.z_s));
  GRANPEN_FUZZ_CHECK(std::isnan(o.edge_wr) == std::isnan(o.edge_wz));
  check_rod(o.rod);
  GRANPEN_FUZZ_CHECK(0.0 <= o.strip1 && o.strip1 < o.strip2 && 0.0 <= o.ann1 && o.ann1 < o.ann2);
  GRANPEN_FUZZ_CHECK(std::isfinite(o.strip2) && std::isfinite(o.ann2));
  GRANPEN_FUZZ_CHECK(o.zlo < 0.0 && o.zlo < o.zhi && std::isfinite(o.zhi) && std::isfinite(o.ann_top));
  GRANPEN_FUZZ_CHECK(o.step_lo <= o.step_hi);
  GRANPEN_FUZZ_CHECK(periodic_matches(o.periodic, o.px, o.py));
  GRANPEN_FUZZ_CHECK(!o.voronoi.empty() && !o.stress.empty());
}
inline void check(const MomentumOptions &o)
{
  GRANPEN_FUZZ_CHECK(!o.dumps.empty() && !o.out_dir.empty() && !o.trace.empty());
  for (double v : {o.D, o.rho_g, o.dt, o.mthreshold}) GRANPEN_FUZZ_CHECK(not_given_or_positive(v));
  GRANPEN_FUZZ_CHECK(std::isnan(o.mu) || (std::isfinite(o.mu) && o.mu >= 0.0));
  GRANPEN_FUZZ_CHECK(not_given_or_finite(o.z_s));
  check_rod(o.rod);
  if (!o.thresholds.empty()) {
    GRANPEN_FUZZ_CHECK(o.thresholds.size() == 4 && o.thresholds[3] > 0.0);
    for (int k = 0; k < 3; ++k) GRANPEN_FUZZ_CHECK(o.thresholds[k] > o.thresholds[k + 1]);
  }
  if (!o.by_time) GRANPEN_FUZZ_CHECK(o.push_step == 0);
  GRANPEN_FUZZ_CHECK(periodic_matches(o.periodic, o.px, o.py));
}
inline void check(const PlotOptions &o)
{
  static const std::set<std::string> kinds = {"force", "ratio", "peak", "kz", "flow", "momentum"};
  GRANPEN_FUZZ_CHECK(kinds.count(o.kind) == 1 && !o.inputs.empty());
  if (o.kind == "flow" || o.kind == "momentum") GRANPEN_FUZZ_CHECK(o.inputs.size() == 1);
  const granpen::figures::Options &f = o.figures;
  GRANPEN_FUZZ_CHECK(!f.out.empty() && std::isfinite(f.kz_zmin) && f.kz_zmin < f.kz_zmax);
  for (double v : {f.alpha, f.mu, f.rho, f.D}) GRANPEN_FUZZ_CHECK(std::isfinite(v) && v >= 0.0);
  GRANPEN_FUZZ_CHECK(positive_finite(f.collapse.band) && positive_finite(f.collapse.tbin));
  GRANPEN_FUZZ_CHECK(std::isfinite(f.collapse.zmin));
  check_ensemble(f.ensemble, f.ens, f.boot);
  if (f.ensemble) GRANPEN_FUZZ_CHECK(o.kind != "flow" && o.kind != "momentum" && !f.each);
}
inline void check(const GapCommandOptions &o)
{
  const granpen::GapOptions &g = o.gap;
  GRANPEN_FUZZ_CHECK(g.runner.jobs >= 1 && g.runner.jobs <= 1024 && g.runner.ranks >= 1);
  if (o.list_effects) return;
  GRANPEN_FUZZ_CHECK(!g.scenario.empty());
  GRANPEN_FUZZ_CHECK((!g.real.empty() && !g.out.empty()) || ((g.prepare_only || !g.slurm.empty()) && !g.v0.empty()));
}
inline void check(const ImportOptions &o)
{
  GRANPEN_FUZZ_CHECK(!o.inputs.empty() && !o.mapping.empty() && !o.out_dir.empty());
  GRANPEN_FUZZ_CHECK(positive_finite(o.D) && positive_finite(o.g));
  GRANPEN_FUZZ_CHECK(zero_or_positive(o.v0) && zero_or_positive(o.window));
  GRANPEN_FUZZ_CHECK(o.first_run >= 1);
  for (const std::string *s : {&o.d_g, &o.rho_g, &o.mu}) GRANPEN_FUZZ_CHECK(s->empty() || positive_text(*s));
}

// A usage error names what is wrong, in granpen's words: never empty (or else it carries
// the usage), never the C++ library's own text (unless the user's own words hold it: an
// unknown option is quoted).
// get_options.h's checks: a file and at least one key; --missing only with has_missing
inline void check(const GetOptions &o)
{
  GRANPEN_FUZZ_CHECK(!o.file.empty() && !o.keys.empty());
  if (!o.has_missing) GRANPEN_FUZZ_CHECK(o.missing.empty());
}
// a finite magnitude for a library truth; as_effect only with truth outside; wall_seconds
// -1 (not given) or >= 0
inline void check(const GapScoreOptions &o)
{
  GRANPEN_FUZZ_CHECK(!o.diagnosis.empty() && !o.case_name.empty() && !o.truth.empty() && !o.magnitude_text.empty());
  if (o.truth != "none" && o.truth != "outside") {
    char *end = nullptr;
    const double m = std::strtod(o.magnitude_text.c_str(), &end);
    GRANPEN_FUZZ_CHECK(*end == '\0' && std::isfinite(m));
  }
  if (!o.as_effect.empty()) GRANPEN_FUZZ_CHECK(o.truth == "outside");
  if (o.below_limit) GRANPEN_FUZZ_CHECK(o.truth != "none" && o.truth != "outside");
  GRANPEN_FUZZ_CHECK(o.wall_seconds >= -1);
}

inline void check(const RateOptions &o)
{
  GRANPEN_FUZZ_CHECK(o.events >= 0 && o.events <= o.trials && o.trials >= 1 && o.level > 0 && o.level < 1);
}
inline void check(const PartingOptions &o)
{
  GRANPEN_FUZZ_CHECK(!o.a.empty() && !o.b.empty() && o.window > 0 && o.window <= 10 && o.threshold > 0);
  GRANPEN_FUZZ_CHECK(o.sustain >= 1 && o.sustain <= 1000);
}
inline void check(const ArrivalOptions &o) { GRANPEN_FUZZ_CHECK(!o.trace.empty() && o.factor > 1 && o.factor <= 1e12); }
inline void check(const CheckpointOptions &o) { GRANPEN_FUZZ_CHECK(!o.files.empty()); }
inline void check_usage_error(const UsageError &e, const std::vector<std::string> &words)
{
  const std::string what = e.what();
  GRANPEN_FUZZ_CHECK(!what.empty() || e.usage.compare(0, 15, "usage: granpen ") == 0);
  for (const char *raw : {"std::", "basic_string", "what()", "terminate called", "stod", "stoi"}) {
    bool quoted = false;
    for (const auto &w : words) quoted = quoted || w.find(raw) != std::string::npos;
    GRANPEN_FUZZ_CHECK(quoted || what.find(raw) == std::string::npos);
  }
}

template <class Options>
void parse_one(Options (*parse)(int, char **), const char *name, std::vector<std::string> &words)
{
  std::vector<char *> argv;
  for (auto &w : words) argv.push_back(&w[0]);
  argv.push_back(nullptr);
  try {
    const Options o = parse((int) words.size(), argv.data());
    if (o.help_requested()) {
      GRANPEN_FUZZ_CHECK(o.help.compare(0, 15 + std::string(name).size(), std::string("usage: granpen ") + name) == 0);
      return;
    }
    check(o);
  } catch (const UsageError &e) {
    check_usage_error(e, words);
  }
  // anything else thrown escapes: libFuzzer reports it, the gtest driver fails on it
}

const char *const SUBCOMMAND_NAMES[] = {"convert", "import", "check", "fit", "calibration", "collapse",
                                        "sweep", "flow", "momentum", "plot", "gap", "get", "gap-score", "rate", "parting", "arrival", "checkpoint"};
const int SUBCOMMAND_COUNT = sizeof(SUBCOMMAND_NAMES) / sizeof(SUBCOMMAND_NAMES[0]);

// The words of an input: split at '\n', at most 64 (more add nothing to the parsers).
inline std::vector<std::string> cli_words(const std::string &bytes)
{
  std::vector<std::string> words;
  std::size_t start = 0;
  while (words.size() < 65) {
    const std::size_t nl = bytes.find('\n', start);
    words.push_back(bytes.substr(start, nl == std::string::npos ? std::string::npos : nl - start));
    if (nl == std::string::npos) break;
    start = nl + 1;
  }
  return words;
}

inline void cli_body(const std::string &bytes)
{
  std::vector<std::string> words = cli_words(bytes);
  const std::string first = words.front();
  words.erase(words.begin());
  int which = -1;
  for (int k = 0; k < SUBCOMMAND_COUNT; ++k)
    if (first == SUBCOMMAND_NAMES[k]) which = k;
  if (which < 0) {
    unsigned sum = 0;
    for (unsigned char c : first) sum += c;
    which = (int) (sum % SUBCOMMAND_COUNT);
  }
  const char *name = SUBCOMMAND_NAMES[which];
  switch (which) {
    case 0: parse_one(parse_convert, name, words); break;
    case 1: parse_one(parse_import, name, words); break;
    case 2: parse_one(parse_check, name, words); break;
    case 3: parse_one(parse_fit, name, words); break;
    case 4: parse_one(parse_calibration, name, words); break;
    case 5: parse_one(parse_collapse, name, words); break;
    case 6: parse_one(parse_sweep_command, name, words); break;
    case 7: parse_one(parse_flow, name, words); break;
    case 8: parse_one(parse_momentum, name, words); break;
    case 9: parse_one(parse_plot, name, words); break;
    case 10: parse_one(parse_gap, name, words); break;
    case 11: parse_one(parse_get, name, words); break;
    case 12: parse_one(parse_gap_score, name, words); break;
    case 13: parse_one(parse_rate, name, words); break;
    case 14: parse_one(parse_parting, name, words); break;
    case 15: parse_one(parse_arrival, name, words); break;
    default: parse_one(parse_checkpoint, name, words); break;
  }
}

}    // namespace granpen_fuzz

#endif
