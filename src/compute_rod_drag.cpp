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
   GRANPEN package: compute rod/drag

   Global vector: the grains' force on a rod (z, x, y), the number of
   rod-grain contacts, the tip depth, t~ = (z / v0) sqrt(g / D) and
   F / F_z with F_z = alpha mu rho_g g D^2 z. Reads depth, v0, D and g from
   a fix rod/drive, or measures them for any moving group.
------------------------------------------------------------------------- */

#include "compute_rod_drag.h"

#include "atom.h"
#include "error.h"
#include "fix_rod_drive.h"
#include "force.h"
#include "granpen_compat.h"
#include "group.h"
#include "neigh_list.h"
#include "pair.h"
#include "rod_bed_measure.h"
#include "scaling_laws.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

static constexpr int NVECTOR = 7;

/* ---------------------------------------------------------------------- */

ComputeRodDrag::ComputeRodDrag(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), drive(nullptr), grainbit(1), surface(0.0), v0(0.0), diameter(-1.0),
    g_user(-1.0), have_surface(false), have_v0(false), alpha(35.0), mu(granpen::DEFAULT_MU), rho_g(-1.0),
    gmag(0.0)
{
  int iarg = 3;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    gp::need_args(FLERR, "compute rod/drag " + key, iarg, 2, narg, lmp);
    const char *val = arg[iarg + 1];
    if (key == "drive") {
      drive_id = val;
    } else if (key == "surface") {
      surface = utils::numeric(FLERR, val, false, lmp);
      have_surface = true;
    } else if (key == "v0") {
      v0 = utils::numeric(FLERR, val, false, lmp);
      if (v0 <= 0.0) error->all(FLERR, "Compute rod/drag v0 must be > 0, got {}", val);
      have_v0 = true;
    } else if (key == "D") {
      diameter = utils::numeric(FLERR, val, false, lmp);
      if (diameter <= 0.0) error->all(FLERR, "Compute rod/drag D must be > 0, got {}", val);
    } else if (key == "g") {
      g_user = utils::numeric(FLERR, val, false, lmp);
      if (g_user <= 0.0) error->all(FLERR, "Compute rod/drag g must be > 0, got {}", val);
    } else if (key == "alpha") {
      alpha = utils::numeric(FLERR, val, false, lmp);
    } else if (key == "mu") {
      mu = utils::numeric(FLERR, val, false, lmp);
    } else if (key == "rho") {
      rho_g = utils::numeric(FLERR, val, false, lmp);
      if (rho_g <= 0.0) error->all(FLERR, "Compute rod/drag rho must be > 0, got {}", val);
    } else if (key == "grains") {
      int igrain = group->find(val);
      if (igrain < 0) error->all(FLERR, "Compute rod/drag grains group {} does not exist", val);
      grainbit = group->bitmask[igrain];
    } else {
      error->all(FLERR, "Unknown compute rod/drag keyword: {}", arg[iarg]);
    }
    iarg += 2;
  }

  if (drive_id.empty() && !have_surface)
    error->all(FLERR, "Compute rod/drag needs either drive FIXID or surface VALUE");
  if (drive_id.empty() && !have_v0)
    error->all(FLERR, "Compute rod/drag without drive needs v0 VALUE");
  if (group->count(igroup) == 0) error->all(FLERR, "Compute rod/drag group {} is empty", arg[1]);

  vector_flag = 1;
  size_vector = NVECTOR;
  extvector = -1;
  extlist = new int[NVECTOR]{1, 1, 1, 1, 0, 0, 0};
  vector = new double[NVECTOR];
}

ComputeRodDrag::~ComputeRodDrag()
{
  delete[] vector;
  delete[] extlist;
}

/* ---------------------------------------------------------------------- */

void ComputeRodDrag::init()
{
  drive = nullptr;
  if (!drive_id.empty()) {
    Fix *f = gp::fix_by_id(lmp, drive_id);
    if (!f) error->all(FLERR, "Compute rod/drag drive fix {} does not exist", drive_id);
    if (strcmp(f->style, "rod/drive") != 0)
      error->all(FLERR, "Compute rod/drag drive fix {} is {}, not rod/drive", drive_id, f->style);
    drive = static_cast<FixRodDrive *>(f);
  }
  if (diameter <= 0.0 && !drive) diameter = gp::measure_rod(lmp, groupbit).D;
  if (rho_g <= 0.0) rho_g = gp::grain_stats(lmp, grainbit, groupbit).rho_mean;
  gmag = g_user > 0.0 ? g_user : gp::gravity_magnitude(lmp);
}

/* ---------------------------------------------------------------------- */

void ComputeRodDrag::compute_vector()
{
  invoked_vector = update->ntimestep;

  // one reduction: force x, y, z and the contact count
  double local[4], sum[4];
  gp::local_group_force(lmp, groupbit, local);
  local[3] = count_contacts();
  MPI_Allreduce(local, sum, 4, MPI_DOUBLE, MPI_SUM, world);

  double depth, speed, dia, g = gmag;
  if (drive) {
    depth = drive->tip_depth();
    speed = have_v0 ? v0 : drive->speed();
    dia = diameter > 0.0 ? diameter : drive->rod_diameter();
    if (g_user <= 0.0 && drive->gravity() > 0.0) g = drive->gravity();
  } else {
    depth = surface - gp::lowest_point(lmp, groupbit);
    speed = v0;
    dia = diameter;
  }

  vector[0] = sum[2];
  vector[1] = sum[0];
  vector[2] = sum[1];
  vector[3] = sum[3];
  vector[4] = depth;
  const double t = granpen::t_tilde(depth, speed, g, dia);
  vector[5] = std::isfinite(t) ? t : 0.0;
  const double fz = granpen::k_z_from_alpha(alpha, mu, rho_g, g, dia) * depth;
  vector[6] = (depth > 0.0 && fz > 0.0) ? sum[2] / fz : 0.0;
}

/* ----------------------------------------------------------------------
   rod-grain pairs in overlap, from the pair style's own neighbor list
   (no request of our own): each pair counted once across ranks. With
   newton off an owned-ghost pair is listed on both owners, so count it
   where the rod atom is owned. -1 when the pair style has no list.
------------------------------------------------------------------------- */

double ComputeRodDrag::count_contacts()
{
  Pair *pair = force->pair;
  if (!pair || !pair->list || !atom->radius) return -1.0;
  NeighList *list = pair->list;
  double **x = atom->x;
  double *radius = atom->radius;
  int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const bool newton = force->newton_pair != 0;
  double n = 0.0;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const bool irod = mask[i] & groupbit, jrod = mask[j] & groupbit;
      if (irod == jrod) continue;
      const int grain = irod ? j : i;
      if (!(mask[grain] & grainbit)) continue;
      if (!newton && !(irod ? i < nlocal : j < nlocal)) continue;
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
      const double rsum = radius[i] + radius[j];
      if (dx * dx + dy * dy + dz * dz < rsum * rsum) n += 1.0;
    }
  }
  return n;
}
