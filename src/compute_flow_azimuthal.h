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
   GRANPEN package: compute flow/azimuthal
   Azimuthally averaged flow fields in (r, z) about the rod axis.
   See docs/compute_flow_azimuthal.rst.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(flow/azimuthal,ComputeFlowAzimuthal);
// clang-format on
#else

#ifndef LMP_COMPUTE_FLOW_AZIMUTHAL_H
#define LMP_COMPUTE_FLOW_AZIMUTHAL_H

#include "compute.h"
#include "flow_bins.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class ComputeFlowAzimuthal : public Compute {
 public:
  ComputeFlowAzimuthal(class LAMMPS *, int, char **);
  ~ComputeFlowAzimuthal() override;
  void init() override;
  void compute_array() override;
  double memory_usage() override;

 private:
  std::string drive_id, voronoi_id, stress_id;
  class FixRodDrive *drive;
  class Compute *voronoi, *stress;
  bool have_axis, tip_frame;
  double xaxis, yaxis;
  double rmin, rmax, dr, zlo, zhi, dz;    // as the user gave them
  bool have_rmax, have_zlo, have_zhi;
  granpen::FlowGrid grid;                  // whole bins over the range (src/flow_bins.h)
  int nbins;
  double d_g, rho_g;
  std::vector<double> local, global;
  bool voro_direct;                 // voronoi voro++: tessellate here, only the binned grains
  std::vector<double> cellvol;      // per owned atom: its cell volume (voro_direct)
  std::vector<int> atom_bin;        // per owned atom: its bin, or -1

  void setup_bins();
  void bin_atoms(double zref, std::vector<double> &offset);
  void tessellate();
};

}    // namespace LAMMPS_NS

#endif
#endif
