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
   GRANPEN package: fix rod/drive

   Moves the atoms of a rod rigidly downward at speed v0 (optionally after a
   linear velocity ramp, or through a spring-damper mount), measures the
   grains' force on it each step, knows the tip depth below the bed surface,
   and writes a granpen-trace v1 force trace. Drives like fix move: each rod
   atom keeps its original position, so x = x0 - s(t) z^ exactly, and the
   time origin and x0 survive write_restart/read_restart.
------------------------------------------------------------------------- */

#include "fix_rod_drive.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "granpen_compat.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "rod_bed_measure.h"
#include "scaling_laws.h"
#include "timer.h"
#include "trace_writer.h"
#include "update.h"
#include "version.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

static constexpr int RESTART_VERSION = 1;
static constexpr int NVECTOR = 9;

/* ---------------------------------------------------------------------- */

FixRodDrive::FixRodDrive(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), grainbit(1), grain_group("all"), surface_auto(true), surface_grid(granpen::SURFACE_COLUMNS), depth_max(-1.0),
    at_depth(AT_DEPTH_STOP), ramp(0.0), mount(false), kmount(0.0), cmount(0.0), mmount(0.0),
    rate(10000.0), g_user(-1.0), d_user(-1.0), elapsed(0.0), t_base(0.0), step_base(0), rod_disp(0.0), rod_vel(0.0),
    act_pos(0.0), act_vel(0.0), rod_acc(0.0), held_act(0.0), held(false), surface(0.0),
    surface_set(false), ztip0(0.0), win_sum{0.0, 0.0, 0.0}, restored(false), diameter(0.0),
    gmag(0.0), xc(0.0), yc(0.0), nwindow(1), fgrain{0.0, 0.0, 0.0}, fsensor(0.0),
    halt_pending(false), trace_opened(false), xoriginal(nullptr), initial_row(false)
{
  if (narg < 4) error->all(FLERR, "Illegal fix rod/drive command: missing v0");

  v0 = utils::numeric(FLERR, arg[3], false, lmp);
  if (v0 <= 0.0) error->all(FLERR, "Fix rod/drive v0 must be > 0, got {}", arg[3]);

  int iarg = 4;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (key == "surface") {
      gp::need_args(FLERR, "fix rod/drive surface", iarg, 2, narg, lmp);
      if (strcmp(arg[iarg + 1], "auto") == 0) {
        surface_auto = true;
      } else {
        surface_auto = false;
        surface = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
        surface_set = true;
      }
      iarg += 2;
    } else if (key == "surface_grid") {
      gp::need_args(FLERR, "fix rod/drive surface_grid", iarg, 2, narg, lmp);
      surface_grid = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (surface_grid < 1 || surface_grid > 1000)
        error->all(FLERR, "Fix rod/drive surface_grid must be 1 to 1000 columns per side, got {}",
                   arg[iarg + 1]);
      iarg += 2;
    } else if (key == "grains") {
      gp::need_args(FLERR, "fix rod/drive grains", iarg, 2, narg, lmp);
      int igrain = group->find(arg[iarg + 1]);
      if (igrain < 0) error->all(FLERR, "Fix rod/drive grains group {} does not exist", arg[iarg + 1]);
      grain_group = arg[iarg + 1];
      grainbit = group->bitmask[igrain];
      iarg += 2;
    } else if (key == "depth") {
      gp::need_args(FLERR, "fix rod/drive depth", iarg, 2, narg, lmp);
      depth_max = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (depth_max < 0.0) error->all(FLERR, "Fix rod/drive depth must be >= 0, got {}", arg[iarg + 1]);
      iarg += 2;
    } else if (key == "at_depth") {
      gp::need_args(FLERR, "fix rod/drive at_depth", iarg, 2, narg, lmp);
      if (strcmp(arg[iarg + 1], "stop") == 0) at_depth = AT_DEPTH_STOP;
      else if (strcmp(arg[iarg + 1], "halt") == 0) at_depth = AT_DEPTH_HALT;
      else error->all(FLERR, "Fix rod/drive at_depth must be stop or halt, got {}", arg[iarg + 1]);
      iarg += 2;
    } else if (key == "ramp") {
      gp::need_args(FLERR, "fix rod/drive ramp", iarg, 2, narg, lmp);
      ramp = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (ramp < 0.0) error->all(FLERR, "Fix rod/drive ramp must be >= 0, got {}", arg[iarg + 1]);
      iarg += 2;
    } else if (key == "mount") {
      gp::need_args(FLERR, "fix rod/drive mount", iarg, 4, narg, lmp);
      kmount = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      cmount = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
      mmount = utils::numeric(FLERR, arg[iarg + 3], false, lmp);
      if (kmount <= 0.0 || cmount < 0.0 || mmount <= 0.0)
        error->all(FLERR, "Fix rod/drive mount needs k > 0, c >= 0, m > 0, got {} {} {}",
                   arg[iarg + 1], arg[iarg + 2], arg[iarg + 3]);
      mount = true;
      iarg += 4;
    } else if (key == "file") {
      gp::need_args(FLERR, "fix rod/drive file", iarg, 2, narg, lmp);
      trace_file = arg[iarg + 1];
      iarg += 2;
    } else if (key == "rate") {
      gp::need_args(FLERR, "fix rod/drive rate", iarg, 2, narg, lmp);
      rate = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (rate <= 0.0) error->all(FLERR, "Fix rod/drive rate must be > 0, got {}", arg[iarg + 1]);
      iarg += 2;
    } else if (key == "g") {
      gp::need_args(FLERR, "fix rod/drive g", iarg, 2, narg, lmp);
      g_user = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (g_user <= 0.0) error->all(FLERR, "Fix rod/drive g must be > 0, got {}", arg[iarg + 1]);
      iarg += 2;
    } else if (key == "diameter") {
      gp::need_args(FLERR, "fix rod/drive diameter", iarg, 2, narg, lmp);
      d_user = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (d_user <= 0.0) error->all(FLERR, "Fix rod/drive diameter must be > 0, got {}", arg[iarg + 1]);
      iarg += 2;
    } else if (key == "mu") {
      gp::need_args(FLERR, "fix rod/drive mu", iarg, 2, narg, lmp);
      utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      mu_str = arg[iarg + 1];
      iarg += 2;
    } else if (key == "header") {
      // extra key = value lines in the trace header (a sweep records its bed and seed)
      gp::need_args(FLERR, "fix rod/drive header", iarg, 3, narg, lmp);
      const std::string hkey = arg[iarg + 1], hval = arg[iarg + 2];
      if (!utils::strmatch(hkey, "^[A-Za-z][A-Za-z0-9_]*$"))
        error->all(FLERR, "Fix rod/drive header key {} must be a word of letters, digits and _", hkey);
      if (hval.find_first_of("\n\r") != std::string::npos)
        error->all(FLERR, "Fix rod/drive header value for {} must be one line", hkey);
      user_header.emplace_back(hkey, hval);
      iarg += 3;
    } else if (key == "run") {
      gp::need_args(FLERR, "fix rod/drive run", iarg, 2, narg, lmp);
      utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      run_str = arg[iarg + 1];
      iarg += 2;
    } else {
      error->all(FLERR, "Unknown fix rod/drive keyword: {}", arg[iarg]);
    }
  }

  if (!gp::sphere_atoms(atom)) error->all(FLERR, "Fix rod/drive requires atom style sphere");
  if (group->count(igroup) == 0) error->all(FLERR, "Fix rod/drive group {} is empty", arg[1]);
  if (grain_group != "all") {
    bigint nboth_local = 0, nboth = 0;
    for (int i = 0; i < atom->nlocal; i++)
      if ((atom->mask[i] & grainbit) && (atom->mask[i] & groupbit)) nboth_local++;
    MPI_Allreduce(&nboth_local, &nboth, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    if (nboth > 0)
      error->all(FLERR, "Fix rod/drive grains group {} contains {} rod atoms", grain_group, nboth);
  }

  time_integrate = 1;
  create_attribute = 1;    // set_arrays() for rod atoms created later
  restart_global = 1;
  restart_peratom = 1;
  vector_flag = 1;
  size_vector = NVECTOR;
  global_freq = 1;
  extvector = -1;
  extlist = new int[NVECTOR]{0, 0, 0, 0, 1, 1, 1, 1, 0};

  // the rod's shape, fixed from here on
  auto shape = gp::measure_rod(lmp, groupbit);
  xc = shape.xc;
  yc = shape.yc;
  diameter = d_user > 0.0 ? d_user : shape.D;
  ztip0 = shape.ztip;

  // per-atom original positions, as fix move keeps them
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  double **x = atom->x;
  imageint *image = atom->image;
  int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++) {
    if (mask[i] & groupbit) domain->unmap(x[i], image[i], xoriginal[i]);
    else xoriginal[i][0] = xoriginal[i][1] = xoriginal[i][2] = 0.0;
  }

  actuator(0.0, act_pos, act_vel);
  rod_vel = act_vel;
}

/* ---------------------------------------------------------------------- */

FixRodDrive::~FixRodDrive()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(xoriginal);
  delete[] extlist;
}

/* ---------------------------------------------------------------------- */

int FixRodDrive::setmask()
{
  int mask = 0;
  mask |= INITIAL_INTEGRATE;
  mask |= FINAL_INTEGRATE;
  return mask;
}

/* ---------------------------------------------------------------------- */

void FixRodDrive::init()
{
  // no other integrator may move rod atoms
  int *mask = atom->mask;
  for (int ifix = 0; ifix < gp::nfix(lmp); ifix++) {
    Fix *other = gp::fix_at(lmp, ifix);
    if (other == this) continue;
    bool integrates = other->time_integrate != 0;
    bool weighs = utils::strmatch(other->style, "^gravity");
    if (!integrates && !weighs) continue;
    bigint nlocal = 0, nboth = 0;
    for (int i = 0; i < atom->nlocal; i++)
      if ((mask[i] & groupbit) && (mask[i] & other->groupbit)) nlocal++;
    MPI_Allreduce(&nlocal, &nboth, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    if (nboth == 0) continue;
    if (integrates)
      error->all(FLERR, "Fix rod/drive: {} rod atoms are also integrated by fix {} ({})", nboth,
                 other->id, other->style);
    if (comm->me == 0)
      error->warning(FLERR,
                     "Fix rod/drive: fix {} applies gravity to {} rod atoms, so the "
                     "measured force includes their weight",
                     other->id, nboth);
  }

  if (!trace_file.empty() && strcmp(update->unit_style, "cgs") != 0 &&
      strcmp(update->unit_style, "si") != 0)
    error->all(FLERR, "Fix rod/drive file needs units cgs or si (granpen-trace v1), not {}",
               update->unit_style);

  reset_dt();
  if (!held) actuator(elapsed, act_pos, act_vel);
  if (!mount) {
    rod_disp = held ? held_act : act_pos;
    rod_vel = held ? 0.0 : act_vel;
  }
  place_rod();
}

/* ---------------------------------------------------------------------- */

void FixRodDrive::reset_dt()
{
  t_base = elapsed;
  step_base = update->ntimestep;
  double steps = 1.0 / (rate * update->dt);
  nwindow = static_cast<int>(std::lround(steps));
  if (nwindow < 1) nwindow = 1;
  if (!trace_file.empty() && std::fabs(steps - nwindow) > 1.0e-6 * steps && comm->me == 0)
    error->warning(FLERR, "Fix rod/drive rate {} is not a whole number of steps of {}: "
                   "rows are {} steps apart", rate, update->dt, nwindow);
}

/* ---------------------------------------------------------------------- */

void FixRodDrive::setup(int /*vflag*/)
{
  if (!surface_set) {
    int nempty = 0;
    double top_max = 0.0;
    surface = gp::bed_surface(lmp, grainbit, groupbit, surface_grid, nempty, top_max);
    if (std::isnan(surface))
      error->all(FLERR, "Fix rod/drive surface auto found no grains in group {} to define the bed "
                 "surface", grain_group);
    if (nempty > 0 && comm->me == 0)
      error->warning(FLERR, "Fix rod/drive surface auto: {} of {} columns hold no grains", nempty,
                     surface_grid * surface_grid);
    surface_set = true;
  }
  gmag = g_user > 0.0 ? g_user : gp::gravity_magnitude(lmp);
  if (!trace_file.empty() && gmag <= 0.0)
    error->all(FLERR, "Fix rod/drive file needs g: define fix gravity or give the g keyword");

  sum_grain_force();
  update_sensor();
  if (mount) rod_acc = (fsensor - fgrain[2]) / mmount;
  if (!trace_file.empty() && !trace_opened) {
    open_trace();
    trace_opened = true;
  }
}

/* ---------------------------------------------------------------------- */

void FixRodDrive::actuator(double t, double &pos, double &vel) const
{
  if (ramp > 0.0) {
    const double tramp = 2.0 * ramp / v0;    // linear velocity ramp covering a travel of ramp
    if (t < tramp) {
      vel = v0 * t / tramp;
      pos = 0.5 * vel * t;
      return;
    }
    vel = v0;
    pos = ramp + v0 * (t - tramp);
    return;
  }
  vel = v0;
  pos = v0 * t;
}

/* ---------------------------------------------------------------------- */

void FixRodDrive::initial_integrate(int /*vflag*/)
{
  const double dt = update->dt;
  // counted, not summed, so the rod sits at exactly v0 t
  elapsed = t_base + (update->ntimestep - step_base) * dt;
  if (held) {
    act_pos = held_act;
    act_vel = 0.0;
  } else {
    actuator(elapsed, act_pos, act_vel);
  }

  if (mount) {
    rod_vel += 0.5 * dt * rod_acc;
    rod_disp += dt * rod_vel;
  } else {
    rod_disp = act_pos;
    rod_vel = act_vel;
    // stop exactly at the requested depth
    const double smax = depth_max - (surface - ztip0);
    if (depth_max >= 0.0 && !held && rod_disp >= smax) {
      rod_disp = act_pos = held_act = smax;
      rod_vel = act_vel = 0.0;
      held = true;
      halt_pending = (at_depth == AT_DEPTH_HALT);
    }
  }
  place_rod();
}

/* ---------------------------------------------------------------------- */

void FixRodDrive::final_integrate()
{
  sum_grain_force();
  update_sensor();
  if (mount) {
    rod_acc = (fsensor - fgrain[2]) / mmount;
    rod_vel += 0.5 * update->dt * rod_acc;
    double **v = atom->v;
    int *mask = atom->mask;
    for (int i = 0; i < atom->nlocal; i++)
      if (mask[i] & groupbit) v[i][2] = -rod_vel;
    if (depth_max >= 0.0 && !held && tip_depth() >= depth_max) {
      held = true;
      held_act = act_pos;
      halt_pending = (at_depth == AT_DEPTH_HALT);
    }
  }
  sample_trace();
  if (halt_pending) {
    halt_pending = false;
    timer->force_timeout();
    if (comm->me == 0)
      utils::logmesg(lmp, "Fix rod/drive {}: depth {} reached at t = {}, halting the run\n", id,
                     depth_max, elapsed);
  }
}

/* ---------------------------------------------------------------------- */

void FixRodDrive::post_run()
{
  // fix halt leaves later runs timed out; a halted push should not
  timer->reset_timeout();
}

/* ----------------------------------------------------------------------
   x = x0 - s z^, v = -ds/dt z^, no rotation
------------------------------------------------------------------------- */

void FixRodDrive::place_rod()
{
  double **x = atom->x;
  double **v = atom->v;
  double **omega = atom->omega;
  int *mask = atom->mask;
  double xold[3];
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    xold[0] = x[i][0];
    xold[1] = x[i][1];
    xold[2] = x[i][2];
    x[i][0] = xoriginal[i][0];
    x[i][1] = xoriginal[i][1];
    x[i][2] = xoriginal[i][2] - rod_disp;
    domain->remap_near(x[i], xold);
    v[i][0] = v[i][1] = 0.0;
    v[i][2] = -rod_vel;
    if (omega) omega[i][0] = omega[i][1] = omega[i][2] = 0.0;
  }
}

/* ---------------------------------------------------------------------- */

void FixRodDrive::sum_grain_force()
{
  double local[3];
  gp::local_group_force(lmp, groupbit, local);
  MPI_Allreduce(local, fgrain, 3, MPI_DOUBLE, MPI_SUM, world);
}

void FixRodDrive::update_sensor()
{
  // the sensor in series reads the spring-damper force, or the grain force on a rigid drive
  if (mount) fsensor = kmount * (act_pos - rod_disp) + cmount * (act_vel - rod_vel);
  else fsensor = fgrain[2];
}

/* ---------------------------------------------------------------------- */

void FixRodDrive::open_trace()
{
  // called once, on every rank (the statistics below are collective)
  auto grains = gp::grain_stats(lmp, grainbit, groupbit);    // collective: before the rank test
  if (comm->me != 0) return;
  ::granpen::TraceHeader h;
  h.units = update->unit_style;
  h.v0 = v0;
  h.D = diameter;
  h.g = gmag;
  auto num = [](double v) { return fmt::format("{:.10g}", v); };
  if (grains.count > 0) {
    h.extra.emplace_back("d_g", num(grains.d_mean));
    h.extra.emplace_back("rho_g", num(grains.rho_mean));
  }
  if (!mu_str.empty()) h.extra.emplace_back("mu", mu_str);
  if (!run_str.empty()) h.extra.emplace_back("run", run_str);
  for (const auto &kv : user_header) h.extra.push_back(kv);
  h.extra.emplace_back("source", fmt::format("granpen fix rod/drive, LAMMPS {}", LAMMPS_VERSION));
  h.extra.emplace_back("surface", num(surface));
  h.extra.emplace_back("dt", num(update->dt));
  h.extra.emplace_back("window_steps", std::to_string(nwindow));
  if (ramp > 0.0) h.extra.emplace_back("ramp", num(ramp));
  if (mount) {
    h.extra.emplace_back("mount", fmt::format("{:.10g} {:.10g} {:.10g}", kmount, cmount, mmount));
    h.columns = {"t", "z", "F", "F_grain", "v_rod"};
  }
  writer.reset(new ::granpen::TraceWriter());    // C++11: LAMMPS 29Sep2021 builds with it
  // a restarted push continues its trace: rows the interrupted run wrote after the
  // restart point are superseded by the ones this run writes, and are dropped (said)
  bool ok;
  if (restored && elapsed > 0.0) {
    long dropped = 0;
    ok = writer->open_resume(trace_file, h, elapsed, dropped);
    if (ok && dropped > 0)
      utils::logmesg(lmp, "Fix rod/drive {}: trace {}: replacing {} rows written after t = {} "
                     "by the resumed run\n", id, trace_file, dropped, elapsed);
  } else {
    ok = writer->open(trace_file, h, false);
  }
  if (!ok)
    error->one(FLERR, "Fix rod/drive cannot open trace file {}: {}", trace_file,
               utils::getsyserror());
  if (!initial_row) {
    std::vector<double> row = {0.0, tip_depth(), fsensor};
    if (mount) row.insert(row.end(), {fgrain[2], rod_vel});
    writer->row(row);
  }
}

/* ---------------------------------------------------------------------- */

void FixRodDrive::sample_trace()
{
  initial_row = true;
  win_sum[0] += fsensor;
  win_sum[1] += fgrain[2];
  win_sum[2] += 1.0;
  if (win_sum[2] < nwindow) return;
  if (writer && writer->is_open()) {
    std::vector<double> row = {elapsed, tip_depth(), win_sum[0] / win_sum[2]};
    if (mount) row.insert(row.end(), {win_sum[1] / win_sum[2], rod_vel});
    writer->row(row);
  }
  win_sum[0] = win_sum[1] = win_sum[2] = 0.0;
}

/* ---------------------------------------------------------------------- */

double FixRodDrive::compute_vector(int n)
{
  switch (n) {
    case 0: return elapsed;
    case 1: return tip_depth();
    case 2: return rod_vel;
    case 3: return act_pos;
    case 4: return fgrain[2];
    case 5: return fgrain[0];
    case 6: return fgrain[1];
    case 7: return fsensor;
    case 8: return surface;
    default: return 0.0;
  }
}

/* ----------------------------------------------------------------------
   global state: push time, rod and actuator kinematics, surface, window
------------------------------------------------------------------------- */

void FixRodDrive::write_restart(FILE *fp)
{
  double list[] = {(double) RESTART_VERSION, mount ? 1.0 : 0.0, elapsed, rod_disp, rod_vel,
                   act_pos, act_vel, rod_acc, held_act, held ? 1.0 : 0.0, surface,
                   surface_set ? 1.0 : 0.0, ztip0, win_sum[0], win_sum[1], win_sum[2],
                   initial_row ? 1.0 : 0.0};
  const int n = sizeof(list) / sizeof(double);
  if (comm->me == 0) {
    int size = n * sizeof(double);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list, sizeof(double), n, fp);
  }
}

void FixRodDrive::restart(char *buf)
{
  auto list = (double *) buf;
  if ((int) list[0] != RESTART_VERSION)
    error->all(FLERR, "Fix rod/drive restart data has version {}, expected {}", (int) list[0],
               RESTART_VERSION);
  const bool written_with_mount = list[1] != 0.0;
  if (written_with_mount != mount)
    error->all(FLERR, "Fix rod/drive {}: the restart was written {} the mount keyword; give the "
               "fix the same keywords", id, written_with_mount ? "with" : "without");
  elapsed = list[2];
  rod_disp = list[3];
  rod_vel = list[4];
  act_pos = list[5];
  act_vel = list[6];
  rod_acc = list[7];
  held_act = list[8];
  held = list[9] != 0.0;
  surface = list[10];
  surface_set = list[11] != 0.0;
  ztip0 = list[12];
  win_sum[0] = list[13];
  win_sum[1] = list[14];
  win_sum[2] = list[15];
  initial_row = list[16] != 0.0;
  restored = true;
}

/* ----------------------------------------------------------------------
   per-atom original positions
------------------------------------------------------------------------- */

double FixRodDrive::memory_usage() { return (double) atom->nmax * 3 * sizeof(double); }

void FixRodDrive::grow_arrays(int nmax) { memory->grow(xoriginal, nmax, 3, "rod/drive:xoriginal"); }

void FixRodDrive::copy_arrays(int i, int j, int /*delflag*/)
{
  xoriginal[j][0] = xoriginal[i][0];
  xoriginal[j][1] = xoriginal[i][1];
  xoriginal[j][2] = xoriginal[i][2];
}

void FixRodDrive::set_arrays(int i)
{
  // an atom created later: its original is where it would have been at s = 0
  if (!(atom->mask[i] & groupbit)) {
    xoriginal[i][0] = xoriginal[i][1] = xoriginal[i][2] = 0.0;
    return;
  }
  domain->unmap(atom->x[i], atom->image[i], xoriginal[i]);
  xoriginal[i][2] += rod_disp;
}

int FixRodDrive::pack_exchange(int i, double *buf)
{
  buf[0] = xoriginal[i][0];
  buf[1] = xoriginal[i][1];
  buf[2] = xoriginal[i][2];
  return 3;
}

int FixRodDrive::unpack_exchange(int nlocal, double *buf)
{
  xoriginal[nlocal][0] = buf[0];
  xoriginal[nlocal][1] = buf[1];
  xoriginal[nlocal][2] = buf[2];
  return 3;
}

int FixRodDrive::pack_restart(int i, double *buf)
{
  // buf[0] holds the count, as every fix packs it
  buf[0] = 4;
  buf[1] = xoriginal[i][0];
  buf[2] = xoriginal[i][1];
  buf[3] = xoriginal[i][2];
  return 4;
}

void FixRodDrive::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  xoriginal[nlocal][0] = extra[nlocal][m++];
  xoriginal[nlocal][1] = extra[nlocal][m++];
  xoriginal[nlocal][2] = extra[nlocal][m++];
}

int FixRodDrive::size_restart(int /*nlocal*/) { return 4; }

int FixRodDrive::maxsize_restart() { return 4; }
