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
   GRANPEN package: measurements of the rod and the bed shared by
   fix rod/drive, compute rod/drag and compute bed/surface. Each sums or
   reduces over owned atoms and combines across ranks over world.
------------------------------------------------------------------------- */

#ifndef LMP_ROD_BED_MEASURE_H
#define LMP_ROD_BED_MEASURE_H

#include "lmptype.h"

namespace LAMMPS_NS {
class LAMMPS;
namespace gp {

  struct RodShape {
    bigint count = 0;
    double xc = 0.0, yc = 0.0;    // axis: centroid of the sphere centres in x, y (nearest images)
    double D = 0.0;               // outer diameter: 2 max(r_xy + radius)
    double ztip = 0.0;            // lowest point: min(z - radius)
  };

  struct GrainStats {
    bigint count = 0;
    double volume = 0.0;      // sum of sphere volumes
    double d_mean = 0.0;      // mean diameter
    double rho_mean = 0.0;    // mean material density
  };

  // Sum of f over this rank's atoms of the group (x, y, z); the caller reduces.
  void local_group_force(LAMMPS *lmp, int groupbit, double out[3]);

  // Atoms with (mask & bit) and not (mask & exclude).
  RodShape measure_rod(LAMMPS *lmp, int groupbit);
  double lowest_point(LAMMPS *lmp, int groupbit);
  GrainStats grain_stats(LAMMPS *lmp, int groupbit, int excludebit);

  // Bed surface by the bench definition over an ngrid x ngrid grid of columns
  // spanning the box in x, y. NaN when no grain is found; nempty = empty columns.
  double bed_surface(LAMMPS *lmp, int groupbit, int excludebit, int ngrid, int &nempty,
                     double &top_max);

  // |g| of the first fix gravity, or 0 when there is none.
  double gravity_magnitude(LAMMPS *lmp);

}    // namespace gp
}    // namespace LAMMPS_NS

#endif
