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
   GRANPEN package: compute bed/surface
   Bed surface height z_s and packing fraction phi_0 of a poured bed.
   See docs/compute_bed_surface.rst.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(bed/surface,ComputeBedSurface);
// clang-format on
#else

#ifndef LMP_COMPUTE_BED_SURFACE_H
#define LMP_COMPUTE_BED_SURFACE_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputeBedSurface : public Compute {
 public:
  ComputeBedSurface(class LAMMPS *, int, char **);
  ~ComputeBedSurface() override;
  void init() override {}
  void compute_vector() override;

 private:
  int ngrid;
  double floor_z;
};

}    // namespace LAMMPS_NS

#endif
#endif
