/* ----------------------------------------------------------------------
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

   z_s: mean over an N x N grid of columns spanning the box in x, y of the
   highest grain top (z + radius) in each column (the bench scenario's
   definition, N = 4); phi_0 = grain volume / (box area * (z_s - floor)).
------------------------------------------------------------------------- */

#include "compute_bed_surface.h"

#include "domain.h"
#include "error.h"
#include "granpen_compat.h"
#include "rod_bed_measure.h"
#include "scaling_laws.h"
#include "update.h"

#include <cmath>
#include <limits>

using namespace LAMMPS_NS;

static constexpr int NVECTOR = 5;

ComputeBedSurface::ComputeBedSurface(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), ngrid(granpen::SURFACE_COLUMNS), floor_z(0.0)
{
  int iarg = 3;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    gp::need_args(FLERR, "compute bed/surface " + key, iarg, 2, narg, lmp);
    if (key == "grid") {
      ngrid = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (ngrid < 1) error->all(FLERR, "Compute bed/surface grid must be >= 1, got {}", arg[iarg + 1]);
    } else if (key == "floor") {
      floor_z = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    } else {
      error->all(FLERR, "Unknown compute bed/surface keyword: {}", arg[iarg]);
    }
    iarg += 2;
  }
  if (!domain->box_exist) error->all(FLERR, "Compute bed/surface needs a simulation box");

  vector_flag = 1;
  size_vector = NVECTOR;
  extvector = -1;
  extlist = new int[NVECTOR]{0, 0, 1, 0, 0};
  vector = new double[NVECTOR];
}

ComputeBedSurface::~ComputeBedSurface()
{
  delete[] vector;
  delete[] extlist;
}

void ComputeBedSurface::compute_vector()
{
  invoked_vector = update->ntimestep;
  int nempty = 0;
  double top_max = 0.0;
  const double zs = gp::bed_surface(lmp, groupbit, 0, ngrid, nempty, top_max);
  const auto grains = gp::grain_stats(lmp, groupbit, 0);
  const double area = (domain->boxhi[0] - domain->boxlo[0]) * (domain->boxhi[1] - domain->boxlo[1]);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  vector[0] = zs;
  vector[1] = (grains.count > 0 && zs > floor_z) ? grains.volume / (area * (zs - floor_z)) : nan;
  vector[2] = (double) grains.count;
  vector[3] = grains.count > 0 ? top_max : nan;
  vector[4] = (double) nempty;
}
