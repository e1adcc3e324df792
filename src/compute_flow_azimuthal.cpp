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
   One pass over owned atoms and one MPI_Allreduce per invocation.
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

#include <algorithm>
#include <cmath>
#include <cstring>

#include <voro++.hh>

using namespace LAMMPS_NS;

namespace {
constexpr int NCOL = 14;
// per-bin accumulators
enum { A_COUNT, A_MASS, A_VOL, A_MVR, A_MVZ, A_MVT, A_MV2, A_VOR, A_TRS, A_SZZ, A_MR, A_MZ, NACC };
constexpr double PI = 3.14159265358979323846;
}    // namespace

ComputeFlowAzimuthal::ComputeFlowAzimuthal(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), drive(nullptr), voronoi(nullptr), stress(nullptr), have_axis(false),
    tip_frame(false), xaxis(0.0), yaxis(0.0), rmin(0.0), rmax(0.0), dr(0.0), zlo(0.0), zhi(0.0),
    dz(0.0), have_rmax(false), have_zlo(false), have_zhi(false), nr(0), nz(0), nbins(0),
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
  local.assign((size_t) nbins * NACC, 0.0);
  global.assign((size_t) nbins * NACC, 0.0);
}

ComputeFlowAzimuthal::~ComputeFlowAzimuthal() { memory->destroy(array); }

/* ---------------------------------------------------------------------- */

void ComputeFlowAzimuthal::setup_bins()
{
  const double half = 0.5 * std::min(domain->prd[0], domain->prd[1]);
  if (!have_rmax) rmax = half;
  if (rmax <= rmin)
    error->all(FLERR, "Compute flow/azimuthal rmax {} must exceed rmin {}", rmax, rmin);
  if (rmax > half + 1.0e-12 * half)
    error->all(FLERR, "Compute flow/azimuthal rmax {} reaches outside the box (half its width is "
               "{}): annuli would overlap their periodic images", rmax, half);
  if (!tip_frame) {
    if (!have_zlo) zlo = domain->boxlo[2];
    if (!have_zhi) zhi = domain->boxhi[2];
    if (zlo < domain->boxlo[2] || zhi > domain->boxhi[2])
      error->all(FLERR, "Compute flow/azimuthal bins z = {} to {} lie outside the box z = {} to {}",
                 zlo, zhi, domain->boxlo[2], domain->boxhi[2]);
  } else if (!have_zlo || !have_zhi) {
    error->all(FLERR, "Compute flow/azimuthal frame tip needs zlo and zhi (relative to the tip)");
  }
  if (zhi <= zlo) error->all(FLERR, "Compute flow/azimuthal zhi {} must exceed zlo {}", zhi, zlo);
  nr = static_cast<int>(std::lround((rmax - rmin) / dr));
  nz = static_cast<int>(std::lround((zhi - zlo) / dz));
  if (nr < 1 || nz < 1)
    error->all(FLERR, "Compute flow/azimuthal bins larger than their range: rbin {} over {}, "
               "zbin {} over {}", dr, rmax - rmin, dz, zhi - zlo);
  dr = (rmax - rmin) / nr;    // whole bins over the range
  dz = (zhi - zlo) / nz;
  nbins = nr * nz;
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

  const double xc = drive ? drive->axis_x() : xaxis;
  const double yc = drive ? drive->axis_y() : yaxis;
  const double zref = tip_frame ? drive->tip_height() : 0.0;
  double **x = atom->x, **v = atom->v;
  double *radius = atom->radius, *rmass = atom->rmass;
  int *mask = atom->mask;
  const double *prd = domain->prd;
  const int nlocal = atom->nlocal;

  // the bin of each owned grain (-1: outside the bins), and its offset from the axis
  atom_bin.assign(nlocal, -1);
  std::vector<double> off((size_t) 2 * nlocal);
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double dx = x[i][0] - xc, dy = x[i][1] - yc;
    if (domain->xperiodic) dx -= prd[0] * std::round(dx / prd[0]);    // nearest image of the axis
    if (domain->yperiodic) dy -= prd[1] * std::round(dy / prd[1]);
    const double r = std::sqrt(dx * dx + dy * dy);
    const double z = x[i][2] - zref;
    if (r < rmin || r >= rmax || z < zlo || z >= zhi) continue;
    const int ir = std::min(nr - 1, static_cast<int>((r - rmin) / dr));
    const int iz = std::min(nz - 1, static_cast<int>((z - zlo) / dz));
    atom_bin[i] = iz * nr + ir;
    off[2 * i] = dx;
    off[2 * i + 1] = dy;
  }
  if (voro_direct) tessellate();

  std::fill(local.begin(), local.end(), 0.0);
  for (int i = 0; i < nlocal; i++) {
    if (atom_bin[i] < 0) continue;
    const double dx = off[2 * i], dy = off[2 * i + 1];
    const double r = std::sqrt(dx * dx + dy * dy);
    const double z = x[i][2] - zref;
    double *acc = &local[(size_t) atom_bin[i] * NACC];
    const double m = rmass[i];
    const double c = r > 0.0 ? dx / r : 1.0, s = r > 0.0 ? dy / r : 0.0;
    const double vr = v[i][0] * c + v[i][1] * s, vt = -v[i][0] * s + v[i][1] * c;
    acc[A_COUNT] += 1.0;
    acc[A_MASS] += m;
    acc[A_VOL] += 4.0 / 3.0 * PI * radius[i] * radius[i] * radius[i];
    acc[A_MVR] += m * vr;
    acc[A_MVZ] += m * v[i][2];
    acc[A_MVT] += m * vt;
    acc[A_MV2] += m * (v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]);
    if (vor) acc[A_VOR] += vor[i][0];
    if (voro_direct) acc[A_VOR] += cellvol[i];
    if (sts) {
      acc[A_TRS] += sts[i][0] + sts[i][1] + sts[i][2];
      acc[A_SZZ] += sts[i][2];
    }
    acc[A_MR] += m * r;
    acc[A_MZ] += m * z;
  }
  MPI_Allreduce(local.data(), global.data(), nbins * NACC, MPI_DOUBLE, MPI_SUM, world);

  // per-bin means; the mass-weighted mean position of a bin is where its means sit
  std::vector<double> rbar(nbins), zbar(nbins);
  for (int iz = 0; iz < nz; iz++)
    for (int ir = 0; ir < nr; ir++) {
      const int b = iz * nr + ir;
      const double *g = &global[(size_t) b * NACC];
      double *row = array[b];
      const double r1 = rmin + ir * dr, r2 = r1 + dr;
      const double vbin = PI * (r2 * r2 - r1 * r1) * dz;
      const double M = g[A_MASS];
      row[0] = 0.5 * (r1 + r2);
      row[1] = zlo + (iz + 0.5) * dz;
      row[2] = g[A_COUNT];
      row[3] = M;
      row[4] = g[A_VOL] / vbin;
      row[5] = ((vor || voro_direct) && g[A_VOR] > 0.0) ? g[A_VOL] / g[A_VOR] : 0.0;
      row[6] = M > 0.0 ? g[A_MVR] / M : 0.0;
      row[7] = M > 0.0 ? g[A_MVZ] / M : 0.0;
      row[8] = M > 0.0 ? g[A_MVT] / M : 0.0;
      row[9] = M > 0.0 ? (g[A_MV2] / M - row[6] * row[6] - row[7] * row[7] - row[8] * row[8]) / 3.0 : 0.0;
      if (row[9] < 0.0) row[9] = 0.0;    // round-off of a rigid motion
      row[10] = sts ? -g[A_TRS] / (3.0 * vbin) : 0.0;
      row[13] = sts ? -g[A_SZZ] / vbin : 0.0;
      rbar[b] = M > 0.0 ? g[A_MR] / M : row[0];
      zbar[b] = M > 0.0 ? g[A_MZ] / M : row[1];
    }

  // shear rate from the binned v_r, v_z: centred differences over the neighbouring bins'
  // mean positions (exact for a linear field), one-sided at edges and next to empty bins
  auto derivative = [&](int b, int bm, int bp, int col, const std::vector<double> &coord) {
    const bool hm = bm >= 0 && array[bm][2] > 0.0, hp = bp >= 0 && array[bp][2] > 0.0;
    const int lo = hm ? bm : b, hi = hp ? bp : b;
    if (lo == hi || coord[hi] == coord[lo]) return 0.0;
    return (array[hi][col] - array[lo][col]) / (coord[hi] - coord[lo]);
  };
  for (int iz = 0; iz < nz; iz++)
    for (int ir = 0; ir < nr; ir++) {
      const int b = iz * nr + ir;
      double *row = array[b];
      if (row[2] <= 0.0) {
        row[11] = row[12] = 0.0;
        continue;
      }
      const int rm = ir > 0 ? b - 1 : -1, rp = ir < nr - 1 ? b + 1 : -1;
      const int zm = iz > 0 ? b - nr : -1, zp = iz < nz - 1 ? b + nr : -1;
      const double dvr_dr = derivative(b, rm, rp, 6, rbar), dvz_dz = derivative(b, zm, zp, 7, zbar);
      const double dvr_dz = derivative(b, zm, zp, 6, zbar), dvz_dr = derivative(b, rm, rp, 7, rbar);
      const double a = dvr_dr - dvz_dz, c = dvr_dz + dvz_dr;
      row[11] = std::sqrt(0.5 * a * a + 0.5 * c * c);
      const double p = row[10];
      row[12] = p > 0.0 ? row[11] * d_g / std::sqrt(p / rho_g) : 0.0;
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

  double lo[3], hi[3];
  for (int d = 0; d < 3; d++) {
    const double e = 1.0e-6 * domain->prd[d];
    lo[d] = domain->sublo[d] - comm->cutghost[d] - e;
    hi[d] = domain->subhi[d] + comm->cutghost[d] + e;
    if (!domain->periodicity[d]) {
      lo[d] = std::max(lo[d], domain->boxlo[d]);
      hi[d] = std::min(hi[d], domain->boxhi[d]);
    }
  }
  // in a non-periodic direction, close the container one grain diameter beyond the
  // outermost grain: the open cells at a free surface end there instead of at the box edge
  double amin[3] = {1e300, 1e300, 1e300}, amax[3] = {-1e300, -1e300, -1e300}, rmaxg = 0.0;
  for (int i = 0; i < nall; i++) {
    if (!(mask[i] & groupbit)) continue;
    for (int d = 0; d < 3; d++) {
      amin[d] = std::min(amin[d], x[i][d]);
      amax[d] = std::max(amax[d], x[i][d]);
    }
    rmaxg = std::max(rmaxg, radius[i]);
  }
  // the same lid on every rank, whatever the decomposition
  double ext[4] = {-amin[0], -amin[1], -amin[2], 0.0}, gext[4];
  ext[3] = rmaxg;
  MPI_Allreduce(ext, gext, 4, MPI_DOUBLE, MPI_MAX, world);
  double gmax[3];
  MPI_Allreduce(amax, gmax, 3, MPI_DOUBLE, MPI_MAX, world);
  for (int d = 0; d < 3; d++) {
    amin[d] = -gext[d];
    amax[d] = gmax[d];
  }
  rmaxg = gext[3];
  for (int d = 0; d < 3; d++)
    if (!domain->periodicity[d] && amax[d] >= amin[d]) {
      lo[d] = std::max(lo[d], amin[d] - 3.0 * rmaxg);
      hi[d] = std::min(hi[d], amax[d] + 3.0 * rmaxg);
    }
  // spatial hash of about 3 atoms per block (compute voronoi/atom uses 8; 3 measured 20% faster)
  const double V = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
  int nb[3];
  for (int d = 0; d < 3; d++)
    nb[d] = std::max(1, static_cast<int>(std::lround((hi[d] - lo[d]) * std::cbrt(nall / (V * 3.0)))));
  voro::container_poly con(lo[0], hi[0], lo[1], hi[1], lo[2], hi[2], nb[0], nb[1], nb[2], false, false,
                           false, 8);
  for (int i = 0; i < nall; i++) {
    if (!(mask[i] & groupbit)) continue;
    if (x[i][0] < lo[0] || x[i][0] > hi[0] || x[i][1] < lo[1] || x[i][1] > hi[1] || x[i][2] < lo[2] ||
        x[i][2] > hi[2])
      continue;
    con.put(i, x[i][0], x[i][1], x[i][2], radius[i]);
  }
  voro::c_loop_all loop(con);
  voro::voronoicell cell;
  if (loop.start()) do {
      const int i = loop.pid();
      if (i < nlocal && atom_bin[i] >= 0 && con.compute_cell(cell, loop)) cellvol[i] = cell.volume();
    } while (loop.inc());
}

double ComputeFlowAzimuthal::memory_usage()
{
  return (double) nbins * (NCOL + 2 * NACC + 2) * sizeof(double);
}
