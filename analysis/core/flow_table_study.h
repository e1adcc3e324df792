// granpen analysis: what granpen plot flow derives from the tables granpen flow wrote, as
// named stages on their columns (no files, no printing), each with a typed result:
//   1. profile  |v_z| below the rod face: v_z = A exp(z / lambda), weighted by its standard
//               errors (core/flow_fields.h fit_exponential, as granpen flow fits it)
//   2. local    the same fit over each window of local_width of the profile
//               (local_exponential_fits): where below the face it decays slower or faster
//   3. edge     phi against I at the rod's bottom edge: the finite pairs, and a least-squares
//               line through them (core/linear_fit.h) when there are 3 or more at 2 or more
//               distinct I
// The front end reads the tables (io/figures.h), runs the study and draws its results.
#ifndef GRANPEN_FLOW_TABLE_STUDY_H
#define GRANPEN_FLOW_TABLE_STUDY_H

#include "flow_fields.h"
#include "linear_fit.h"

#include <functional>
#include <vector>

namespace granpen {

// The columns of the tables read (has_*: the table was there and read).
struct FlowTableColumns {
  bool has_profile = false;
  std::vector<double> z, vz, vz_se;    // the profile below the face (cm, cm/s); an se not known: 0
  double local_width = 0.0;            // cm: stage 2's windows (0: stage 2 not run)
  bool has_edge = false;
  std::vector<double> I, phi;          // at the edge
};

// Stage 3's result.
struct EdgeLine {
  std::vector<double> I, phi;    // the pairs where both are finite, in order
  bool ok = false;               // the line fitted
  LinearFit fit;                 // phi = a + b I
};

enum class FlowTableStage { profile, local, edge };
const char *flow_table_stage_name(FlowTableStage s);
using FlowTableProgress = std::function<void(FlowTableStage)>;    // called as each stage starts

struct FlowTableStudy {
  bool profile_done = false;    // stage 1 ran (has_profile)
  ExpFit profile;
  bool local_done = false;      // stage 2 ran (has_profile, local_width > 0)
  std::vector<LocalExpFit> local;
  bool edge_done = false;       // stage 3 ran (has_edge)
  EdgeLine edge;
};

// Stage 3 alone.
EdgeLine fit_edge_line(const std::vector<double> &I, const std::vector<double> &phi);

// The stages whose table was read.
FlowTableStudy run_flow_table_study(const FlowTableColumns &c, const FlowTableProgress &progress = {});

}    // namespace granpen

#endif
