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
   GRANPEN package: compute rod/drag
   The grains' drag on a rod and its normalisation by the depth term.
   See docs/compute_rod_drag.rst.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(rod/drag,ComputeRodDrag);
// clang-format on
#else

#ifndef LMP_COMPUTE_ROD_DRAG_H
#define LMP_COMPUTE_ROD_DRAG_H

#include "compute.h"

#include <string>

namespace LAMMPS_NS {

class ComputeRodDrag : public Compute {
 public:
  ComputeRodDrag(class LAMMPS *, int, char **);
  ~ComputeRodDrag() override;
  void init() override;
  void compute_vector() override;

 private:
  std::string drive_id;
  class FixRodDrive *drive;
  int grainbit;
  double surface, v0, diameter, g_user;
  bool have_surface, have_v0;
  double alpha, mu, rho_g;
  double gmag;

  double count_contacts();
};

}    // namespace LAMMPS_NS

#endif
#endif
