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
   GRANPEN package: rod and bed measurements shared by the styles.
------------------------------------------------------------------------- */

#include "rod_bed_measure.h"

#include "atom.h"
#include "bed_surface.h"
#include "comm.h"
#include "domain.h"
#include "fix.h"
#include "granpen_compat.h"
#include "lammps.h"
#include "modify.h"
#include "rod_shape.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <mpi.h>
#include <vector>

using namespace LAMMPS_NS;

static constexpr double FOUR_THIRDS_PI = 4.18879020478639098;

gp::RodShape gp::measure_rod(LAMMPS *lmp, int groupbit)
{
  Atom *atom = lmp->atom;
  Domain *domain = lmp->domain;
  double **x = atom->x;
  double *radius = atom->radius;
  int *mask = atom->mask;
  const int nlocal = atom->nlocal;

  // the reference atom: the first of the group on the lowest rank that has one, so that
  // every rank takes the offsets from the same point (a rod across a periodic boundary)
  int first = -1;
  for (int i = 0; i < nlocal && first < 0; i++)
    if (mask[i] & groupbit) first = i;
  struct {
    double missing;
    int rank;
  } mine = {first < 0 ? 1.0 : 0.0, lmp->comm->me}, owner;
  MPI_Allreduce(&mine, &owner, 1, MPI_DOUBLE_INT, MPI_MINLOC, lmp->world);
  RodShape s;
  if (owner.missing > 0.5) return s;
  double ref[2] = {first >= 0 ? x[first][0] : 0.0, first >= 0 ? x[first][1] : 0.0};
  MPI_Bcast(ref, 2, MPI_DOUBLE, owner.rank, lmp->world);
  const ::granpen::RodImageFrame frame{ref[0], ref[1], domain->xperiodic ? domain->xprd : 0.0,
                                       domain->yperiodic ? domain->yprd : 0.0};

  ::granpen::RodAxisSums local = ::granpen::rod_axis_start(), sums;
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit) ::granpen::rod_axis_add(local, frame, x[i][0], x[i][1]);
  MPI_Allreduce(local.v, sums.v, 3, MPI_DOUBLE, MPI_SUM, lmp->world);
  double axis_x, axis_y;
  ::granpen::rod_axis(sums, frame, axis_x, axis_y);

  ::granpen::RodExtent lext = ::granpen::rod_extent_start(), ext;
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit)
      ::granpen::rod_extent_add(lext, frame, axis_x, axis_y, x[i][0], x[i][1], x[i][2], radius ? radius[i] : 0.0);
  MPI_Allreduce(lext.v, ext.v, 2, MPI_DOUBLE, MPI_MAX, lmp->world);

  const ::granpen::RodShapeXY shape = ::granpen::rod_shape(sums, ext, frame);
  s.count = static_cast<bigint>(shape.count);
  s.xc = shape.axis_x;
  s.yc = shape.axis_y;
  s.D = shape.diameter;
  s.ztip = shape.tip;
  return s;
}

void gp::local_group_force(LAMMPS *lmp, int groupbit, double out[3])
{
  double **f = lmp->atom->f;
  int *mask = lmp->atom->mask;
  out[0] = out[1] = out[2] = 0.0;
  for (int i = 0; i < lmp->atom->nlocal; i++)
    if (mask[i] & groupbit) {
      out[0] += f[i][0];
      out[1] += f[i][1];
      out[2] += f[i][2];
    }
}

double gp::lowest_point(LAMMPS *lmp, int groupbit)
{
  Atom *atom = lmp->atom;
  double lmin = std::numeric_limits<double>::max(), gmin;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) {
      double z = atom->x[i][2] - (atom->radius ? atom->radius[i] : 0.0);
      if (z < lmin) lmin = z;
    }
  MPI_Allreduce(&lmin, &gmin, 1, MPI_DOUBLE, MPI_MIN, lmp->world);
  return gmin;
}

gp::GrainStats gp::grain_stats(LAMMPS *lmp, int groupbit, int excludebit)
{
  Atom *atom = lmp->atom;
  double local[4] = {0.0, 0.0, 0.0, 0.0}, sum[4];
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit) || (atom->mask[i] & excludebit)) continue;
    double r = atom->radius ? atom->radius[i] : 0.0;
    double vol = FOUR_THIRDS_PI * r * r * r;
    double m = atom->rmass ? atom->rmass[i] : atom->mass[atom->type[i]];
    local[0] += 1.0;
    local[1] += vol;
    local[2] += 2.0 * r;
    local[3] += vol > 0.0 ? m / vol : 0.0;
  }
  MPI_Allreduce(local, sum, 4, MPI_DOUBLE, MPI_SUM, lmp->world);
  GrainStats s;
  s.count = static_cast<bigint>(sum[0]);
  s.volume = sum[1];
  if (sum[0] > 0.0) {
    s.d_mean = sum[2] / sum[0];
    s.rho_mean = sum[3] / sum[0];
  }
  return s;
}

double gp::bed_surface(LAMMPS *lmp, int groupbit, int excludebit, int ngrid, int &nempty,
                            double &top_max)
{
  Atom *atom = lmp->atom;
  Domain *domain = lmp->domain;
  ::granpen::SurfaceGrid grid{domain->boxlo[0], domain->boxhi[0], domain->boxlo[1],
                              domain->boxhi[1], ngrid};
  std::vector<double> xs, ys, tops;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit) || (atom->mask[i] & excludebit)) continue;
    xs.push_back(atom->x[i][0]);
    ys.push_back(atom->x[i][1]);
    tops.push_back(atom->x[i][2] + (atom->radius ? atom->radius[i] : 0.0));
  }
  std::vector<double> local(ngrid * ngrid, ::granpen::EMPTY_COLUMN), global(ngrid * ngrid);
  ::granpen::column_max_tops(grid, xs.data(), ys.data(), tops.data(), xs.size(), local);
  MPI_Allreduce(local.data(), global.data(), ngrid * ngrid, MPI_DOUBLE, MPI_MAX, lmp->world);
  top_max = ::granpen::EMPTY_COLUMN;
  for (double h : global)
    if (h > top_max) top_max = h;
  return ::granpen::surface_from_columns(global, nempty);
}

double gp::gravity_magnitude(LAMMPS *lmp)
{
  for (int i = 0; i < gp::nfix(lmp); i++) {
    Fix *f = gp::fix_at(lmp, i);
    if (!utils::strmatch(f->style, "^gravity")) continue;    // gravity, gravity/omp, gravity/kk
    int dim = 0;
    auto gvec = static_cast<double *>(f->extract("gvec", dim));
    if (gvec) return std::sqrt(gvec[0] * gvec[0] + gvec[1] * gvec[1] + gvec[2] * gvec[2]);
  }
  return 0.0;
}
