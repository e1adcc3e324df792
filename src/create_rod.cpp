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
   GRANPEN package: create_rod command

   create_rod type D length sphere spacing x y ztip shell|filled [density rho] [shaft_type T]

   Places the spheres of granpen::build_rod() with the axis at (x, y) and
   the tip (lowest sphere bottom) at ztip. Each rank creates the spheres in
   its sub-domain, as create_atoms single does. With shaft_type T the spheres
   above the tip layer (the shaft) get type T: their contacts with grains can
   then be given their own friction (a frictionless shaft) by pair_coeff.
------------------------------------------------------------------------- */

#include "create_rod.h"

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "granpen_compat.h"
#include "rod_geometry.h"

#include <cstring>
#include <stdexcept>

using namespace LAMMPS_NS;

static constexpr double FOUR_THIRDS_PI = 4.18879020478639098;

void CreateRod::command(int narg, char **arg)
{
  if (!domain->box_exist) error->all(FLERR, "Create_rod command before simulation box is defined");
  if (!gp::sphere_atoms(atom)) error->all(FLERR, "Create_rod requires atom style sphere");
  if (domain->triclinic) error->all(FLERR, "Create_rod does not support triclinic boxes");
  if (narg < 9)
    error->all(FLERR, "Illegal create_rod command: expected type D length sphere spacing x y "
               "ztip shell|filled");

  const int type = utils::inumeric(FLERR, arg[0], false, lmp);
  if (type < 1 || type > atom->ntypes)
    error->all(FLERR, "Create_rod atom type {} is outside 1 to {}", arg[0], atom->ntypes);
  ::granpen::RodSpec spec;
  spec.diameter = utils::numeric(FLERR, arg[1], false, lmp);
  spec.length = utils::numeric(FLERR, arg[2], false, lmp);
  spec.sphere = utils::numeric(FLERR, arg[3], false, lmp);
  spec.spacing = utils::numeric(FLERR, arg[4], false, lmp);
  const double xaxis = utils::numeric(FLERR, arg[5], false, lmp);
  const double yaxis = utils::numeric(FLERR, arg[6], false, lmp);
  const double ztip = utils::numeric(FLERR, arg[7], false, lmp);
  if (strcmp(arg[8], "shell") == 0) spec.filled = false;
  else if (strcmp(arg[8], "filled") == 0) spec.filled = true;
  else error->all(FLERR, "Create_rod fill must be shell or filled, got {}", arg[8]);

  double density = 1.0;
  int shaft_type = type;    // the shaft's own type: its contacts can get their own friction
  int iarg = 9;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "density") == 0) {
      gp::need_args(FLERR, "create_rod density", iarg, 2, narg, lmp);
      density = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (density <= 0.0) error->all(FLERR, "Create_rod density must be > 0, got {}", arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "shaft_type") == 0) {
      gp::need_args(FLERR, "create_rod shaft_type", iarg, 2, narg, lmp);
      shaft_type = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (shaft_type < 1 || shaft_type > atom->ntypes)
        error->all(FLERR, "Create_rod shaft_type {} is outside 1 to {}", arg[iarg + 1], atom->ntypes);
      iarg += 2;
    } else {
      error->all(FLERR, "Unknown create_rod keyword: {}", arg[iarg]);
    }
  }

  // a rod as wide as the box would overlap its own periodic images (or stick out of walls)
  for (int d = 0; d < 2; d++)
    if (spec.diameter >= domain->boxhi[d] - domain->boxlo[d])
      error->all(FLERR, "Create_rod: rod diameter {} is not below the box width {} in {}", spec.diameter,
                 domain->boxhi[d] - domain->boxlo[d], "xy"[d]);
  std::vector<::granpen::RodSphere> spheres;
  try {
    spheres = ::granpen::build_rod(spec);
  } catch (std::invalid_argument &e) {
    error->all(FLERR, "Create_rod: {}", e.what());
  }

  // every sphere must lie inside the box: a shrink-wrapped boundary grows only at setup
  const double r = 0.5 * spec.sphere;
  const double ztop = ztip + spec.length;
  for (int d = 0; d < 2; d++) {
    const double c = d == 0 ? xaxis : yaxis;
    const double half = 0.5 * spec.diameter;
    if (!domain->periodicity[d] && (c - half < domain->boxlo[d] || c + half > domain->boxhi[d]))
      error->all(FLERR, "Create_rod: rod at {} sticks out of the box in {}", c, "xy"[d]);
  }
  if (ztip < domain->boxlo[2] || ztop > domain->boxhi[2])
    error->all(FLERR, "Create_rod: rod spans z = {} to {}, outside the box z = {} to {}", ztip, ztop,
               domain->boxlo[2], domain->boxhi[2]);

  atom->nghost = 0;
  atom->avec->clear_bonus();
  const bigint natoms_previous = atom->natoms;
  const int nlocal_previous = atom->nlocal;

  double *sublo = domain->sublo, *subhi = domain->subhi;
  for (const auto &s : spheres) {
    double xone[3] = {xaxis + s.x, yaxis + s.y, ztip + s.z};
    imageint image = ((imageint) IMGMAX << IMG2BITS) | ((imageint) IMGMAX << IMGBITS) | IMGMAX;
    domain->remap(xone, image);
    if (xone[0] >= sublo[0] && xone[0] < subhi[0] && xone[1] >= sublo[1] && xone[1] < subhi[1] &&
        xone[2] >= sublo[2] && xone[2] < subhi[2]) {
      atom->avec->create_atom(s.layer == 0 ? type : shaft_type, xone);
      const int n = atom->nlocal - 1;
      atom->image[n] = image;
      atom->radius[n] = r;
      atom->rmass[n] = density * FOUR_THIRDS_PI * r * r * r;
    }
  }

  atom->data_fix_compute_variable(nlocal_previous, atom->nlocal);
  bigint nblocal = atom->nlocal;
  MPI_Allreduce(&nblocal, &atom->natoms, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  const bigint ncreated = atom->natoms - natoms_previous;
  if (ncreated != (bigint) spheres.size())
    error->all(FLERR, "Create_rod placed {} of {} spheres: some fell outside every sub-domain",
               ncreated, spheres.size());
  if (atom->tag_enable) atom->tag_extend();
  atom->tag_check();
  if (atom->map_style != Atom::MAP_NONE) {
    atom->map_init();
    atom->map_set();
  }
  if (comm->me == 0)
    utils::logmesg(lmp, "Created rod of {} spheres: D = {}, length = {}, tip at z = {}\n", ncreated,
                   spec.diameter, spec.length, ztip);
}
