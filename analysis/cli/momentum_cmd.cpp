// granpen momentum DUMP... --trace TRACE: the grains' upward momentum by vertical-speed
// class in each dump frame (the paper's "Temporal Flows", compute momentum/vbin's classes),
// M_slow and M(v_z > v0/320) against t~ and depth, and the drag F of the trace against
// mu g M(v_z > v0/320) (core/momentum_classes.h).
#include "dump_cmd_common.h"
#include "momentum_options.h"
#include "atomic_file.h"
#include "momentum_study.h"
#include "momentum_tables.h"
#include "rod_frame.h"
#include "scaling_laws.h"
#include "subcommands.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>


namespace {

using namespace granpen;
using namespace granpen::cli;


const char *const OUTPUTS[] = {"momentum.json", "momentum_classes.csv", "momentum_drag.csv"};

// Everything but z_s (core/momentum_study.h's momentum_study_params), the origins in how.
MomentumStudyParams resolve_parameters(const MomentumOptions &o, const PushTrace &th, MomentumProvenance &how)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  MomentumParamSources s;
  s.v0 = th.trace.v0, s.g = th.trace.g;
  s.D = {o.D, nan}, s.D_trace = th.trace.D;
  s.mu = {o.mu, th.have_mu ? th.mu : nan};
  s.dt = {o.dt, th.have_dt ? th.dt : nan};
  s.thresholds = o.thresholds.empty() ? nullptr : o.thresholds.data();
  s.mthreshold = std::isfinite(o.mthreshold) ? o.mthreshold : 0.0;
  s.by_time = o.by_time, s.push_step = o.push_step;
  MomentumParamOrigins from;
  MomentumStudyParams p;
  try {
    p = momentum_study_params(s, from);
  } catch (const std::invalid_argument &e) {
    throw UsageError(e.what());
  }
  how.D_source = from.D, how.mu_source = from.mu, how.class_source = from.classes;
  how.rho_g = resolve({o.rho_g, th.have_rho ? th.rho_g : nan}, DEFAULT_RHO_G, "default", how.rho_g_source);
  return p;
}

// z_s: option, trace, or measured in the first frame
double bed_surface_of(const MomentumOptions &o, const PushTrace &th, const DumpFrame &frame, const GrainFrame &g,
                      MomentumProvenance &how)
{
  const double z_s = resolve({o.z_s, th.have_surface ? th.surface : std::nan("")}, 0.0, "first frame", how.z_s_source);
  if (how.z_s_source != "first frame") return z_s;
  how.notes.push_back("bed surface measured in the first frame: the trace has no surface key");
  return frame_bed_surface(frame, g);
}

void print_summary(const MomentumStudyParams &p, const std::vector<MomentumFrameRecord> &records,
                   const DragComparison &dc, const MomentumProvenance &how)
{
  std::printf("granpen momentum: %zu frames of %zu dump%s; v0 = %g, D = %g (%s), g = %g, mu = %g (%s), z_s = %.4g (%s), "
              "F matched by %s\n",
              records.size(), how.dumps.size(), how.dumps.size() == 1 ? "" : "s", p.v0, p.D, how.D_source.c_str(), p.g,
              p.mu, how.mu_source.c_str(), p.z_s, how.z_s_source.c_str(), p.by_time ? "time" : "depth");
  std::printf("  %10s %8s %8s %8s %8s %8s %10s %10s %10s %10s\n", "timestep", "z_tip", "t~", "fast", "interm", "slow",
              "M_slow", "M_move", "mu_g_M", "F");
  const std::size_t step = records.size() > 20 ? (records.size() + 19) / 20 : 1;
  for (std::size_t k = 0; k < records.size(); ++k) {
    if (k % step && k + 1 != records.size()) continue;
    const MomentumFrameRecord &r = records[k];
    std::printf("  %10lld %8.4g %8.4g %8.0f %8.0f %8.0f %10.4g %10.4g %10.4g %10.4g\n", r.timestep, r.z_tip, r.t_tilde,
                r.tally.count[0], r.tally.count[1], r.tally.count[2], r.tally.M_slow, r.tally.M_move, r.mu_g_M, r.F);
  }
  if (dc.ok)
    std::printf("  drag: F = (%.4g +- %.2g) mu g M(v_z > %g) over %zu frames; mean F / (mu g M) = %.4g +- %.2g "
                "(paper: 1:1)\n",
                dc.fit.b, dc.fit.se_b, p.classes.vmove, dc.n, dc.ratio_mean, dc.ratio_se);
  else
    std::printf("  drag: F against mu g M undefined (%s)\n", dc.note.c_str());
  for (const auto &n : how.notes) std::printf("  note: %s\n", n.c_str());
}

}    // namespace

int granpen::cli::run_momentum(const MomentumOptions &o)
{
  MomentumProvenance how;
  begin_dump_command(o, std::vector<const char *>(std::begin(OUTPUTS), std::end(OUTPUTS)), how);
  const PushTrace th = load_push_trace(o.trace);
  how.trace = th.trace.path;
  MomentumStudyParams p = resolve_parameters(o, th, how);

  DumpReader reader(o.dumps);
  DumpFrame frame;
  first_frame(reader, o.dumps, frame, "granpen momentum");
  ColumnChoice cols;
  cols.mass = how.mass_column = frame.has("mass");
  if (!cols.mass && how.rho_g_source == "default")
    how.notes.push_back("masses from rho_g = 3 (default): no mass column, no rho_g");
  GrainFrame g;
  extract_frame(frame, o.rod, cols, how.rho_g, o.px, o.py, g);
  p.z_s = bed_surface_of(o, th, frame, g, how);

  const TraceColumns trace{th.trace.t, th.trace.z, th.trace.F};
  std::vector<MomentumFrameRecord> records;
  std::size_t unmatched = 0;
  bool first = true;
  do {
    if (!first) extract_frame(frame, o.rod, cols, how.rho_g, o.px, o.py, g);
    first = false;
    const MomentumFrameInput in{g.x.data(), g.y.data(), g.vz.data(), g.mass.data(), g.grains(), g.axis_x, g.axis_y,
                                g.period_x, g.period_y, g.tip, frame.timestep, g.where};
    records.push_back(momentum_frame(p, trace, in));
    unmatched += records.back().matched ? 0 : 1;
  } while (reader.next(frame));
  if (unmatched)
    how.notes.push_back(std::to_string(unmatched) + " frame(s) outside the trace's " + (p.by_time ? "time" : "depth") +
                        " range: F undefined");

  const DragComparison dc = drag_over_frames(records);
  print_summary(p, records, dc, how);
  std::string msg;
  if (!write_outputs(o.out_dir, momentum_files(p, records, dc, how), msg)) throw OutputError(msg);
  std::printf("wrote %s/{momentum.json, momentum_classes.csv, momentum_drag.csv}\n", o.out_dir.c_str());
  return EXIT_OK;
}

int granpen::cli::momentum(int argc, char **argv) { return run_parsed(parse_momentum, run_momentum, argc, argv); }
