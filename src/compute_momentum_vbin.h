/* -*- c++ -*- ----------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   Steve Plimpton, sjplimp@sandia.gov

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   Contributing author: granpen developers
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   GRANPEN package: compute momentum/vbin
   Count, mass and upward momentum of the grains by vertical-velocity
   class (relative to the push speed v0), and mu g M(v_z > v0/320).
   See docs/compute_momentum_vbin.rst.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(momentum/vbin,ComputeMomentumVbin);
// clang-format on
#else

#ifndef LMP_COMPUTE_MOMENTUM_VBIN_H
#define LMP_COMPUTE_MOMENTUM_VBIN_H

#include "compute.h"
#include "momentum_class_limits.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class ComputeMomentumVbin : public Compute {
 public:
  ComputeMomentumVbin(class LAMMPS *, int, char **);
  ~ComputeMomentumVbin() override;
  void init() override;
  double compute_scalar() override;
  void compute_array() override;

 private:
  double v0;

  // selection: outside a cylinder about the rod axis and/or inside a region
  std::string drive_id, region_id;
  class FixRodDrive *drive;
  class Region *region;
  bool have_axis, have_rmin;
  double axis_user[2], rmin_user;
  double xaxis, yaxis, rmin;    // in use (from axis/rmin or the drive), set at init
  bool cylinder;                // select on r > rmin

  // classes
  bool logbins;
  int nclass;
  granpen::MomentumClasses classes;    // the four class bounds (velocity); M_move counts v_z > vmove
  std::vector<double> edges;    // logbins: nclass + 1 ascending bounds (velocity)

  // scalar
  double mu, g_user, gmag;

  // the last tally: rows of (count, mass, momentum), then M_move
  bigint tally_step;
  double mmove;
  std::vector<double> local, global;

  void tally();
  int classify(double vz) const;
};

}    // namespace LAMMPS_NS

#endif
#endif
