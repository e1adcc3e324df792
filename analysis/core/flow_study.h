// granpen analysis: what granpen flow derives from the frames of a push, as a kernel that
// takes arrays (no files, no printing): per frame the rod edge, the near-shaft strip's top
// layer and the annulus; over the frames the (r, z) fields, the profile below the rod
// face with its exponential lengths, the strip profile, phi against I at the rod edge and
// the t~ where the surface flux turns from up to down (core/flow_fields.h's accumulators).
#ifndef GRANPEN_FLOW_STUDY_H
#define GRANPEN_FLOW_STUDY_H

#include "flow_fields.h"
#include "linear_fit.h"
#include "param_choice.h"

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace granpen {

struct FlowStudyParams {
  FlowGrid grid;                      // (r, z) bins about the axis, z from the tip
  double D = 0.0;                     // rod diameter
  double d_g = 0.0, rho_g = 0.0;      // grain diameter and density (I, masses)
  double z_s = 0.0;                   // bed surface height
  double v0 = 0.0, g = 0.0;           // for t~ (NaN: undefined)
  double profile_radius = 0.0;        // cylinder below the rod face
  double strip1 = 0.5, strip2 = 1.5;  // strip distances from the shaft surface
  double ann1 = 2.0, ann2 = 3.0;      // annulus radii
  double ann_top = 0.5;               // the annulus starts this far below z_s
  double edge_wr = 0.0, edge_wz = 0.0;    // edge bins: within these of r = R, z = 0
  double box_zlo = 0.0, box_zhi = 0.0;    // the box in z: the strip's extent
};

// The study's parameters, each from the first source that gives it (param_choice.h): an
// option, the push's trace header, else the first frame or a default.
struct FlowParamSources {
  ParamChoice D, d_g, rho_g, v0, g, z_s;
  // the first frame: its grains' radii and masses (mass null without a mass column), the
  // rod diameter from its atoms (NaN: no rod atoms), the box, its timestep, and the bed
  // surface measured on demand (as compute bed/surface does)
  const double *radius = nullptr, *mass = nullptr;
  std::size_t grains = 0;
  double rod_D = std::numeric_limits<double>::quiet_NaN();
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  long long timestep = 0;
  std::function<double()> measure_z_s;
  // the bins and regions (NaN: the default named in FlowStudyParams)
  double dr = std::numeric_limits<double>::quiet_NaN(), dz = dr, rmax = dr, profile_radius = dr;
  double edge_wr = dr, edge_wz = dr;
  double zlo = -4.0, zhi = 6.0;
  double strip1 = 0.5, strip2 = 1.5, ann1 = 2.0, ann2 = 3.0, ann_top = 0.5;
};
// Which source each parameter came from ("option", "trace", "first frame", "rod atoms",
// "default", "none") and notes on what is undefined or measured.
struct FlowParamOrigins {
  std::string D, d_g, rho_g, v0, g, z_s;
  std::vector<std::string> notes;
};

// The grain density for masses when a frame has no mass column: option, trace, else 3.
double flow_grain_density(const ParamChoice &rho_g, std::string &origin);

// The parameters from their sources: rho_g as flow_grain_density, but from the first
// frame's masses over its grains' volumes when it has a mass column and neither option nor
// trace gives it; d_g the first frame's mean grain diameter; D the rod atoms'; z_s measured;
// v0 and g undefined (NaN, with a note) without option or trace; bins of d_g over half the
// smaller box width; edge bins one bin size each; the profile radius D/3. Throws
// std::invalid_argument without a D from any source and for bins make_flow_grid refuses.
FlowStudyParams flow_study_params(const FlowParamSources &s, FlowParamOrigins &from);

// One frame's numbers.
struct FlowFrameRecord {
  long long timestep = 0;
  std::string where;                  // FILE:LINE of the frame
  double tip = 0, z_tip = 0, t_tilde = 0;
  std::size_t rod_atoms = 0, grains = 0;
  EdgeAverage edge;
  bool annulus = false;               // grains in the annulus, tip below its top
  SliceBin ann;
  double ann_phi = 0;                 // Voronoi phi when known, else the centres'
  double surface_vz = 0;              // the strip's top grain layer (dz below z_s)
  std::size_t surface_grains = 0;
};

// Over all frames.
struct FlowSummary {
  FlowFields fields;
  std::vector<SliceBin> below;        // the profile below the rod face (every bin)
  bool below_voronoi = false;
  ExpFit lambda_vz, lambda_gammadot;  // v_z ~ A exp(z / lambda), gammadot likewise
  std::vector<double> edge_I, edge_phi;    // per frame with the tip in the bed
  LinearFit edge_fit;                 // phi = phi_0 + b I
  bool edge_ok = false;
  std::string edge_note;              // why not ok
  std::vector<SliceBin> strip;        // bins with grains, z above the bed surface
  std::vector<double> surface_t, surface_z, surface_vz, surface_grains;    // tip in the bed
  double surface_crossing = 0.0;      // t~ of the last up-to-down turn, NaN: none
  std::size_t annulus_frames = 0;
};

class FlowStudy {
 public:
  explicit FlowStudy(const FlowStudyParams &p);
  // One frame: the grains (voronoi set when known), the rod axis and tip, how many rod atoms.
  const FlowFrameRecord &add_frame(const GrainArrays &grains, double axis_x, double axis_y, double period_x,
                                   double period_y, double tip, std::size_t rod_atoms, long long timestep,
                                   const std::string &where);
  const std::vector<FlowFrameRecord> &frames() const { return records_; }
  FlowSummary summary() const;

 private:
  FlowStudyParams p_;
  FlowAccumulator total_;
  SliceAccumulator below_, strip_;
  std::vector<FlowFrameRecord> records_;
};

}    // namespace granpen

#endif
