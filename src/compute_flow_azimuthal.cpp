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
   GRANPEN package: compute flow/azimuthal

   Bins the grains of the group in (r, z) about the rod axis (lab frame, or
   z measured from the rod tip) and gives per bin, as a global array:
     1 r  2 z  (bin centre)         3 count  4 mass
     5 phi (grain volume / bin volume, grains assigned by centre)
     6 phi_voronoi (grain volume / Voronoi cell volume; needs voronoi)
     7 v_r  8 v_z  9 v_theta (mass-weighted means)
     10 granular temperature T = (<|v|^2> - |<v>|^2) / 3 (mass-weighted)
     11 p = -sum tr(S_i) / (3 V_bin) from compute stress/atom (needs stress)
     12 shear rate gammadot = sqrt(1/2 (dvr/dr - dvz/dz)^2 + 1/2 (dvr/dz + dvz/dr)^2)
     13 inertial number I = gammadot d_g / sqrt(p / rho_g), 0 where p <= 0
     14 sigma_zz = -sum S_zz,i / V_bin (vertical normal stress, compressive +)
   One pass over owned atoms and one MPI_Allreduce per invocation. The grid,
   the sums, the moments, the shear rate, I and the voro++ cells are the
   pure kernels of flow_bins.h and voronoi_cells.h, which granpen flow calls
   on dump frames: this file gathers the atoms and reduces over the ranks.
------------------------------------------------------------------------- */

#include "compute_flow_azimuthal.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_rod_drive.h"
#include "granpen_compat.h"
#include "group.h"
#include "memory.h"
#include "rod_bed_measure.h"
#include "update.h"
#include "voronoi_cells.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

using namespace LAMMPS_NS;

namespace {
constexpr int NCOL = 14;
}    // namespace

ComputeFlowAzimuthal::ComputeFlowAzimuthal(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), drive(nullptr), voronoi(nullptr), stress(nullptr), have_axis(false),
    tip_frame(false), xaxis(0.0), yaxis(0.0), rmin(0.0), rmax(0.0), dr(0.0), zlo(0.0), zhi(0.0),
    dz(0.0), have_rmax(false), have_zlo(false), have_zhi(false), nbins(0),
    d_g(-1.0), rho_g(-1.0), voro_direct(false)
{
  int iarg = 3;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (key == "axis") {
      // axis FIXID (a fix rod/drive) or axis X Y
      gp::need_args(FLERR, "compute flow/azimuthal axis", iarg, 2, narg, lmp);
      if (iarg + 2 < narg && utils::is_double(arg[iarg + 1]) && utils::is_double(arg[iarg + 2])) {
        xaxis = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
        yaxis = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
        have_axis = true;
        iarg += 3;
      } else {
        drive_id = arg[iarg + 1];
        iarg += 2;
      }
      continue;
    }
    gp::need_args(FLERR, "compute flow/azimuthal " + key, iarg, 2, narg, lmp);
    const char *val = arg[iarg + 1];
    if (key == "rbin") {
      dr = utils::numeric(FLERR, val, false, lmp);
      if (dr <= 0.0) error->all(FLERR, "Compute flow/azimuthal rbin must be > 0, got {}", val);
    } else if (key == "zbin") {
      dz = utils::numeric(FLERR, val, false, lmp);
      if (dz <= 0.0) error->all(FLERR, "Compute flow/azimuthal zbin must be > 0, got {}", val);
    } else if (key == "rmin") {
      rmin = utils::numeric(FLERR, val, false, lmp);
      if (rmin < 0.0) error->all(FLERR, "Compute flow/azimuthal rmin must be >= 0, got {}", val);
    } else if (key == "rmax") {
      rmax = utils::numeric(FLERR, val, false, lmp);
      have_rmax = true;
    } else if (key == "zlo") {
      zlo = utils::numeric(FLERR, val, false, lmp);
      have_zlo = true;
    } else if (key == "zhi") {
      zhi = utils::numeric(FLERR, val, false, lmp);
      have_zhi = true;
    } else if (key == "frame") {
      if (strcmp(val, "lab") == 0) tip_frame = false;
      else if (strcmp(val, "tip") == 0) tip_frame = true;
      else error->all(FLERR, "Compute flow/azimuthal frame must be lab or tip, got {}", val);
    } else if (key == "voronoi") {
      voro_direct = strcmp(val, "voro++") == 0;
      if (!voro_direct) voronoi_id = val;
    } else if (key == "stress") {
      stress_id = val;
    } else if (key == "d_g") {
      d_g = utils::numeric(FLERR, val, false, lmp);
      if (d_g <= 0.0) error->all(FLERR, "Compute flow/azimuthal d_g must be > 0, got {}", val);
    } else if (key == "rho_g") {
      rho_g = utils::numeric(FLERR, val, false, lmp);
      if (rho_g <= 0.0) error->all(FLERR, "Compute flow/azimuthal rho_g must be > 0, got {}", val);
    } else {
      error->all(FLERR, "Unknown compute flow/azimuthal keyword: {}", arg[iarg]);
    }
    iarg += 2;
  }

  if (!have_axis && drive_id.empty())
    error->all(FLERR, "Compute flow/azimuthal needs axis FIXID (a fix rod/drive) or axis X Y");
  if (tip_frame && drive_id.empty())
    error->all(FLERR, "Compute flow/azimuthal frame tip needs axis FIXID (a fix rod/drive)");
  if (dr <= 0.0) error->all(FLERR, "Compute flow/azimuthal needs rbin");
  if (dz <= 0.0) error->all(FLERR, "Compute flow/azimuthal needs zbin");
  if (!gp::sphere_atoms(atom)) error->all(FLERR, "Compute flow/azimuthal requires atom style sphere");
  if (domain->triclinic) error->all(FLERR, "Compute flow/azimuthal does not support triclinic boxes");

  setup_bins();
  array_flag = 1;
  size_array_rows = nbins;
  size_array_cols = NCOL;
  extarray = 0;
  memory->create(array, nbins, NCOL, "flow/azimuthal:array");
  local.assign((size_t) nbins * granpen::FLOW_NSUM, 0.0);
  global.assign((size_t) nbins * granpen::FLOW_NSUM, 0.0);
}

ComputeFlowAzimuthal::~ComputeFlowAzimuthal() { memory->destroy(array); }

/* ---------------------------------------------------------------------- */

void ComputeFlowAzimuthal::setup_bins()
{
  const double half = 0.5 * std::min(domain->prd[0], domain->prd[1]);
  if (!have_rmax) rmax = half;
  if (!tip_frame) {
    if (!have_zlo) zlo = domain->boxlo[2];
    if (!have_zhi) zhi = domain->boxhi[2];
  } else if (!have_zlo || !have_zhi) {
    error->all(FLERR, "Compute flow/azimuthal frame tip needs zlo and zhi (relative to the tip)");
  }
  // the ranges, and every bin count checked as a double against FLOW_MAX_BINS before the
  // cast and before any allocation (a tiny rbin would otherwise overflow the int)
  try {
    grid = granpen::make_flow_grid(rmin, rmax, dr, zlo, zhi, dz, granpen::FlowGridNames("", "rbin", "zbin"));
  } catch (std::invalid_argument &e) {
    error->all(FLERR, "Compute flow/azimuthal {}", e.what());
  }
  if (rmax > half + 1.0e-12 * half)
    error->all(FLERR, "Compute flow/azimuthal rmax {} reaches outside the box (half its width is "
               "{}): annuli would overlap their periodic images", rmax, half);
  if (!tip_frame && (zlo < domain->boxlo[2] || zhi > domain->boxhi[2]))
    error->all(FLERR, "Compute flow/azimuthal bins z = {} to {} lie outside the box z = {} to {}",
               zlo, zhi, domain->boxlo[2], domain->boxhi[2]);
  nbins = grid.bins();
}

/* ---------------------------------------------------------------------- */

void ComputeFlowAzimuthal::init()
{
  drive = nullptr;
  if (!drive_id.empty()) {
    Fix *f = gp::fix_by_id(lmp, drive_id);
    if (!f) error->all(FLERR, "Compute flow/azimuthal axis fix {} does not exist", drive_id);
    if (strcmp(f->style, "rod/drive") != 0)
      error->all(FLERR, "Compute flow/azimuthal axis fix {} is {}, not rod/drive", drive_id, f->style);
    drive = static_cast<FixRodDrive *>(f);
  }
  voronoi = stress = nullptr;
  if (!voronoi_id.empty()) {
    voronoi = gp::compute_by_id(lmp, voronoi_id);
    if (!voronoi) error->all(FLERR, "Compute flow/azimuthal voronoi compute {} does not exist", voronoi_id);
    if (!voronoi->peratom_flag || voronoi->size_peratom_cols < 1)
      error->all(FLERR, "Compute flow/azimuthal voronoi compute {} gives no per-atom volumes "
                 "(use compute voronoi/atom)", voronoi_id);
  }
  if (!stress_id.empty()) {
    stress = gp::compute_by_id(lmp, stress_id);
    if (!stress) error->all(FLERR, "Compute flow/azimuthal stress compute {} does not exist", stress_id);
    if (!stress->peratom_flag || stress->size_peratom_cols != 6)
      error->all(FLERR, "Compute flow/azimuthal stress compute {} is not a per-atom stress "
                 "(use compute stress/atom)", stress_id);
  }
  if (d_g <= 0.0 || rho_g <= 0.0) {
    auto grains = gp::grain_stats(lmp, groupbit, 0);
    if (d_g <= 0.0) d_g = grains.d_mean;
    if (rho_g <= 0.0) rho_g = grains.rho_mean;
  }
}

/* ---------------------------------------------------------------------- */

void ComputeFlowAzimuthal::compute_array()
{
  invoked_array = update->ntimestep;

  // invoke the per-atom computes as compute reduce does: the invoked flag is what tells
  // Modify to schedule compute stress/atom's virial tally for the next sample
  double **vor = nullptr, **sts = nullptr;
  for (Compute *c : {voronoi, stress}) {
    if (!c) continue;
    if (!(c->invoked_flag & Compute::INVOKED_PERATOM)) {
      c->compute_peratom();
      c->invoked_flag |= Compute::INVOKED_PERATOM;
    }
  }
  if (voronoi) vor = voronoi->array_atom;
  if (stress) sts = stress->array_atom;

  const double zref = tip_frame ? drive->tip_height() : 0.0;
  std::vector<double> off;
  bin_atoms(zref, off);
  if (voro_direct) tessellate();

  // the sums per bin, reduced over the ranks; then the moments, the shear rate and I: the
  // kernels granpen flow calls on a dump (src/flow_bins.h)
  double **x = atom->x, **v = atom->v;
  double *radius = atom->radius, *rmass = atom->rmass;
  std::fill(local.begin(), local.end(), 0.0);
  for (int i = 0; i < atom->nlocal; i++) {
    if (atom_bin[i] < 0) continue;
    const double cell = vor ? vor[i][0] : voro_direct ? cellvol[i] : 0.0;
    const double s[3] = {sts ? sts[i][0] : 0.0, sts ? sts[i][1] : 0.0, sts ? sts[i][2] : 0.0};
    granpen::add_grain_to_bin(&local[(size_t) atom_bin[i] * granpen::FLOW_NSUM], off[2 * i], off[2 * i + 1],
                              x[i][2] - zref, v[i][0], v[i][1], v[i][2], radius[i], rmass[i],
                              (vor || voro_direct) ? &cell : nullptr, sts ? s : nullptr);
  }
  MPI_Allreduce(local.data(), global.data(), nbins * granpen::FLOW_NSUM, MPI_DOUBLE, MPI_SUM, world);

  const std::vector<granpen::FlowBin> bins = granpen::flow_bins_from_sums(
      grid, global.data(), 1.0, sts ? 1.0 : 0.0, vor || voro_direct, d_g, rho_g);
  for (int b = 0; b < nbins; b++) {
    const granpen::FlowBin &f = bins[b];
    double *row = array[b];
    row[0] = f.r;
    row[1] = f.z;
    row[2] = f.count;
    row[3] = f.mass;
    row[4] = f.phi_centre;
    row[5] = f.phi_voronoi;
    row[6] = f.vr;
    row[7] = f.vz;
    row[8] = f.vtheta;
    row[9] = f.T;
    row[10] = f.p;
    row[11] = f.gammadot;
    row[12] = f.I;
    row[13] = f.sigma_zz;
  }
}

/* ----------------------------------------------------------------------
   the bin of each owned grain of the group (-1: outside the bins), and its
   offset from the nearest image of the axis
------------------------------------------------------------------------- */

void ComputeFlowAzimuthal::bin_atoms(double zref, std::vector<double> &off)
{
  const double xc = drive ? drive->axis_x() : xaxis;
  const double yc = drive ? drive->axis_y() : yaxis;
  double **x = atom->x;
  int *mask = atom->mask;
  const double px = domain->xperiodic ? domain->prd[0] : 0.0, py = domain->yperiodic ? domain->prd[1] : 0.0;
  const int nlocal = atom->nlocal;
  atom_bin.assign(nlocal, -1);
  off.assign((size_t) 2 * nlocal, 0.0);
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double dx = granpen::nearest_image(x[i][0] - xc, px), dy = granpen::nearest_image(x[i][1] - yc, py);
    atom_bin[i] = granpen::flow_bin_of(grid, std::sqrt(dx * dx + dy * dy), x[i][2] - zref);
    off[2 * i] = dx;
    off[2 * i + 1] = dy;
  }
}

/* ----------------------------------------------------------------------
   voronoi voro++: the radical Voronoi tessellation (Voro++'s container_poly, atom radii)
   of the group's owned and ghost atoms, in the container compute voronoi/atom uses (the
   sub-domain widened by the ghost cutoff, cut by the box in non-periodic directions),
   closed in non-periodic directions 1.5 grain diameters beyond the outermost grain, with
   cells computed only for the owned atoms that fall in a bin and without neighbour
   bookkeeping: the same volumes inside the bed at under half the cost.
------------------------------------------------------------------------- */

void ComputeFlowAzimuthal::tessellate()
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  double **x = atom->x;
  double *radius = atom->radius;
  int *mask = atom->mask;
  cellvol.assign(nlocal, 0.0);

  granpen::VoronoiContainer con;
  bool lid[3];
  for (int d = 0; d < 3; d++) {
    const double e = 1.0e-6 * domain->prd[d];
    con.lo[d] = domain->sublo[d] - comm->cutghost[d] - e;
    con.hi[d] = domain->subhi[d] + comm->cutghost[d] + e;
    if (!domain->periodicity[d]) {
      con.lo[d] = std::max(con.lo[d], domain->boxlo[d]);
      con.hi[d] = std::min(con.hi[d], domain->boxhi[d]);
    }
    con.periodic[d] = false;    // the ghosts are the periodic images
    lid[d] = !domain->periodicity[d];
  }
  // the same lid on every rank, whatever the decomposition: the group's extent over all ranks
  double amin[3] = {1e300, 1e300, 1e300}, amax[3] = {-1e300, -1e300, -1e300}, rmaxg = 0.0;
  for (int i = 0; i < nall; i++) {
    if (!(mask[i] & groupbit)) continue;
    for (int d = 0; d < 3; d++) {
      amin[d] = std::min(amin[d], x[i][d]);
      amax[d] = std::max(amax[d], x[i][d]);
    }
    rmaxg = std::max(rmaxg, radius[i]);
  }
  double ext[4] = {-amin[0], -amin[1], -amin[2], rmaxg}, gext[4], gmax[3];
  MPI_Allreduce(ext, gext, 4, MPI_DOUBLE, MPI_MAX, world);
  MPI_Allreduce(amax, gmax, 3, MPI_DOUBLE, MPI_MAX, world);
  for (int d = 0; d < 3; d++) amin[d] = -gext[d];
  granpen::close_container(con, lid, amin, gmax, gext[3]);

  // the group's owned and ghost atoms take part; cells only for the owned ones in a bin
  std::vector<char> put(nall), wanted(nall);
  for (int i = 0; i < nall; i++) {
    put[i] = (mask[i] & groupbit) ? 1 : 0;
    wanted[i] = (i < nlocal && atom_bin[i] >= 0) ? 1 : 0;
  }
  granpen::voronoi_cell_volumes(con, nall, &x[0][0], &x[0][1], &x[0][2], 3, radius, put.data(), wanted.data(),
                                cellvol.data());
}

double ComputeFlowAzimuthal::memory_usage()
{
  return (double) nbins * (NCOL + 2 * granpen::FLOW_NSUM + sizeof(granpen::FlowBin) / sizeof(double)) * sizeof(double);
}
