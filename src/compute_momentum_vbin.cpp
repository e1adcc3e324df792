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
   GRANPEN package: compute momentum/vbin

   Global array: for the grains of the group in a selection (outside a
   cylinder of radius R about the rod axis, and/or inside a region), one
   row per vertical-velocity class, fastest first: count, mass and upward
   momentum sum(m v_z). The classes are those of the paper's "Temporal
   Flows" section relative to the push speed v0 (or user thresholds, or
   log-spaced bins). Global scalar: mu g M_move, M_move = mass of the
   selected grains with v_z > v0/320, the paper's comparison for the drag.
   One pass over owned atoms and one MPI_Allreduce per timestep.
------------------------------------------------------------------------- */

#include "compute_momentum_vbin.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "fix_rod_drive.h"
#include "granpen_compat.h"
#include "memory.h"
#include "momentum_class_limits.h"
#include "region.h"
#include "rod_bed_measure.h"
#include "scaling_laws.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

using namespace LAMMPS_NS;

static constexpr int NCOLS = 3;
static constexpr int NDEFAULT = granpen::MOMENTUM_NCLASS;

/* ---------------------------------------------------------------------- */

ComputeMomentumVbin::ComputeMomentumVbin(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), v0(0.0), drive(nullptr), region(nullptr), have_axis(false),
    have_rmin(false), axis_user{0.0, 0.0}, rmin_user(0.0), xaxis(0.0), yaxis(0.0), rmin(0.0),
    cylinder(false), logbins(false), nclass(NDEFAULT), mu(granpen::DEFAULT_MU), g_user(-1.0),
    gmag(0.0), tally_step(-1), mmove(0.0)
{
  if (narg < 4) error->all(FLERR, "Illegal compute momentum/vbin command: missing v0");
  v0 = utils::numeric(FLERR, arg[3], false, lmp);
  if (v0 <= 0.0) error->all(FLERR, "Compute momentum/vbin v0 must be > 0, got {}", arg[3]);

  bool have_thresholds = false, have_mthreshold = false;
  double frac[NDEFAULT] = {0.0, 0.0, 0.0, 0.0};
  double fmin = 0.0, fmax = 0.0, mfrac = 0.0;

  int iarg = 4;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    const std::string cmd = "compute momentum/vbin " + key;
    if (key == "drive") {
      gp::need_args(FLERR, cmd, iarg, 2, narg, lmp);
      drive_id = arg[iarg + 1];
      iarg += 2;
    } else if (key == "axis") {
      gp::need_args(FLERR, cmd, iarg, 3, narg, lmp);
      axis_user[0] = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      axis_user[1] = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
      have_axis = true;
      iarg += 3;
    } else if (key == "rmin") {
      gp::need_args(FLERR, cmd, iarg, 2, narg, lmp);
      rmin_user = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (rmin_user < 0.0)
        error->all(FLERR, "Compute momentum/vbin rmin must be >= 0, got {}", arg[iarg + 1]);
      have_rmin = true;
      iarg += 2;
    } else if (key == "region") {
      gp::need_args(FLERR, cmd, iarg, 2, narg, lmp);
      region_id = arg[iarg + 1];
      if (!gp::region_by_id(lmp, region_id))
        error->all(FLERR, "Compute momentum/vbin region {} does not exist", region_id);
      iarg += 2;
    } else if (key == "thresholds") {
      gp::need_args(FLERR, cmd, iarg, 1 + NDEFAULT, narg, lmp);
      bool ok = true;
      for (int k = 0; k < NDEFAULT; k++) {
        frac[k] = utils::numeric(FLERR, arg[iarg + 1 + k], false, lmp);
        if (!(frac[k] > 0.0) || (k > 0 && !(frac[k] < frac[k - 1]))) ok = false;
      }
      if (!ok)
        error->all(FLERR,
                   "Compute momentum/vbin thresholds must be > 0 and strictly decreasing, got {} "
                   "{} {} {}",
                   arg[iarg + 1], arg[iarg + 2], arg[iarg + 3], arg[iarg + 4]);
      have_thresholds = true;
      iarg += 1 + NDEFAULT;
    } else if (key == "logbins") {
      gp::need_args(FLERR, cmd, iarg, 4, narg, lmp);
      nclass = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (nclass < 1)
        error->all(FLERR, "Compute momentum/vbin logbins N must be >= 1, got {}", arg[iarg + 1]);
      if (nclass > granpen::MOMENTUM_MAX_LOG_CLASSES)    // before allocating a row per class
        error->all(FLERR, "Compute momentum/vbin logbins N must be <= {}, got {}",
                   granpen::MOMENTUM_MAX_LOG_CLASSES, arg[iarg + 1]);
      fmin = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
      fmax = utils::numeric(FLERR, arg[iarg + 3], false, lmp);
      if (!(fmin > 0.0 && fmin < fmax))
        error->all(FLERR, "Compute momentum/vbin logbins needs 0 < fmin < fmax, got {} {}",
                   arg[iarg + 2], arg[iarg + 3]);
      logbins = true;
      iarg += 4;
    } else if (key == "mthreshold") {
      gp::need_args(FLERR, cmd, iarg, 2, narg, lmp);
      mfrac = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(mfrac > 0.0))
        error->all(FLERR, "Compute momentum/vbin mthreshold must be > 0, got {}", arg[iarg + 1]);
      have_mthreshold = true;
      iarg += 2;
    } else if (key == "mu") {
      gp::need_args(FLERR, cmd, iarg, 2, narg, lmp);
      mu = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (mu < 0.0) error->all(FLERR, "Compute momentum/vbin mu must be >= 0, got {}", arg[iarg + 1]);
      iarg += 2;
    } else if (key == "g") {
      gp::need_args(FLERR, cmd, iarg, 2, narg, lmp);
      g_user = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(g_user > 0.0))
        error->all(FLERR, "Compute momentum/vbin g must be > 0, got {}", arg[iarg + 1]);
      iarg += 2;
    } else {
      error->all(FLERR, "Unknown compute momentum/vbin keyword: {}", arg[iarg]);
    }
  }

  if (have_thresholds && logbins)
    error->all(FLERR, "Compute momentum/vbin takes thresholds or logbins, not both");
  if (have_axis && !have_rmin && drive_id.empty())
    error->all(FLERR, "Compute momentum/vbin axis needs rmin R (or drive FIXID for the rod radius)");
  if (have_rmin && !have_axis && drive_id.empty())
    error->all(FLERR, "Compute momentum/vbin rmin needs axis X Y (or drive FIXID for the rod axis)");
  if (drive_id.empty() && !have_axis && region_id.empty())
    error->all(FLERR, "Compute momentum/vbin needs drive FIXID, axis X Y with rmin R, or region ID");
  cylinder = !drive_id.empty() || have_axis;

  // class bounds in velocity units: the kernels granpen momentum calls on a dump
  // (src/momentum_class_limits.h); the keywords are checked above, so they do not throw
  try {
    classes = granpen::momentum_classes(v0, have_thresholds ? frac : nullptr, have_mthreshold ? mfrac : 0.0);
    if (logbins) edges = granpen::momentum_log_edges(v0, nclass, fmin, fmax);
  } catch (std::invalid_argument &e) {
    error->all(FLERR, "Compute momentum/vbin: {}", e.what());
  }

  local.assign(NCOLS * nclass + 1, 0.0);
  global.assign(NCOLS * nclass + 1, 0.0);

  array_flag = 1;
  size_array_rows = nclass;
  size_array_cols = NCOLS;
  extarray = 1;
  scalar_flag = 1;
  extscalar = 1;
  memory->create(array, nclass, NCOLS, "momentum/vbin:array");
  for (int r = 0; r < nclass; r++)
    for (int c = 0; c < NCOLS; c++) array[r][c] = 0.0;
}

ComputeMomentumVbin::~ComputeMomentumVbin()
{
  memory->destroy(array);
}

/* ---------------------------------------------------------------------- */

void ComputeMomentumVbin::init()
{
  drive = nullptr;
  if (!drive_id.empty()) {
    Fix *f = gp::fix_by_id(lmp, drive_id);
    if (!f) error->all(FLERR, "Compute momentum/vbin drive fix {} does not exist", drive_id);
    if (strcmp(f->style, "rod/drive") != 0)
      error->all(FLERR, "Compute momentum/vbin drive fix {} is {}, not rod/drive", drive_id,
                 f->style);
    drive = static_cast<FixRodDrive *>(f);
  }
  region = nullptr;
  if (!region_id.empty()) {
    region = gp::region_by_id(lmp, region_id);
    if (!region) error->all(FLERR, "Compute momentum/vbin region {} does not exist", region_id);
  }
  if (cylinder) {
    xaxis = have_axis ? axis_user[0] : drive->axis_x();
    yaxis = have_axis ? axis_user[1] : drive->axis_y();
    rmin = have_rmin ? rmin_user : 0.5 * drive->rod_diameter();
  }

  // g: the keyword, else the drive's (known from its setup on), else the first fix gravity
  gmag = g_user > 0.0 ? g_user : gp::gravity_magnitude(lmp);
  if (gmag <= 0.0 && !drive)
    error->all(FLERR, "Compute momentum/vbin needs g: define fix gravity or give the g keyword");

  // a new run may follow changes made at the same timestep (set, velocity, ...)
  tally_step = -1;
}

/* ---------------------------------------------------------------------- */

void ComputeMomentumVbin::compute_array()
{
  invoked_array = update->ntimestep;
  tally();
}

double ComputeMomentumVbin::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  tally();
  double g = gmag;
  if (g_user <= 0.0 && drive && drive->gravity() > 0.0) g = drive->gravity();
  if (g <= 0.0)
    error->all(FLERR, "Compute momentum/vbin needs g: define fix gravity or give the g keyword");
  scalar = mu * g * mmove;
  return scalar;
}

/* ----------------------------------------------------------------------
   row of a grain moving at vz (0 = fastest), or -1 when it is in no class
------------------------------------------------------------------------- */

int ComputeMomentumVbin::classify(double vz) const
{
  return logbins ? granpen::momentum_log_class(edges, vz) : granpen::momentum_class(classes, vz);
}

/* ----------------------------------------------------------------------
   one pass over owned atoms, one reduction; once per timestep (and run)
------------------------------------------------------------------------- */

void ComputeMomentumVbin::tally()
{
  if (tally_step == update->ntimestep) return;

  double **x = atom->x;
  double **v = atom->v;
  int *mask = atom->mask;
  int *type = atom->type;
  double *rmass = atom->rmass;
  double *mass = atom->mass;
  const int nlocal = atom->nlocal;
  const double r2min = rmin * rmin;

  std::fill(local.begin(), local.end(), 0.0);
  if (region) region->prematch();
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    if (cylinder) {
      double dx = x[i][0] - xaxis, dy = x[i][1] - yaxis, dz = 0.0;
      gp::minimum_image(domain, FLERR, dx, dy, dz);
      if (dx * dx + dy * dy <= r2min) continue;
    }
    if (region && !region->match(x[i][0], x[i][1], x[i][2])) continue;
    const double vz = v[i][2];
    const double m = rmass ? rmass[i] : mass[type[i]];
    if (vz > classes.vmove) local[NCOLS * nclass] += m;
    const int row = classify(vz);
    if (row < 0) continue;
    double *p = &local[NCOLS * row];
    p[0] += 1.0;
    p[1] += m;
    p[2] += m * vz;
  }
  MPI_Allreduce(local.data(), global.data(), (int) global.size(), MPI_DOUBLE, MPI_SUM, world);

  for (int r = 0; r < nclass; r++)
    for (int c = 0; c < NCOLS; c++) array[r][c] = global[NCOLS * r + c];
  mmove = global[NCOLS * nclass];
  tally_step = update->ntimestep;
}
