/* -*- c++ -*- ----------------------------------------------------------
   granpen analysis: the paper's numbers that the flow readers print, plot and
   write beside their own (../shared/papers/README.md, "Inertial Number" and
   "Temporal Flows"), in one place so that a figure, a JSON file and a
   summary line cannot quote two versions of one value.
------------------------------------------------------------------------- */

#ifndef GRANPEN_PAPER_VALUES_H
#define GRANPEN_PAPER_VALUES_H

namespace granpen::paper {

// decay length of v_z below the rod's face: lambda_vz = (0.98 +- 0.15) D, independent of v0
inline constexpr double lambda_vz_over_D = 0.98;
inline constexpr double lambda_vz_over_D_error = 0.15;

// packing fraction at the rod's edge (r = R) against the inertial number: phi = 0.57 - 0.35 I
inline constexpr double edge_phi_0 = 0.57;
inline constexpr double edge_phi_slope = -0.35;

// the near-shaft strip's surface flux turns from up to down at t~ = (z / v0) sqrt(g / D) = 1
inline constexpr double surface_crossing_t_tilde = 1.0;

}    // namespace granpen::paper

#endif
