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
   GRANPEN package: fix rod/drive
   Drives a rigid rod of spheres into a granular bed at constant speed and
   records the force on it. See docs/fix_rod_drive.rst.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(rod/drive,FixRodDrive);
// clang-format on
#else

#ifndef LMP_FIX_ROD_DRIVE_H
#define LMP_FIX_ROD_DRIVE_H

#include "fix.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace granpen {
class TraceWriter;
}

namespace LAMMPS_NS {

class FixRodDrive : public Fix {
 public:
  FixRodDrive(class LAMMPS *, int, char **);
  ~FixRodDrive() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void initial_integrate(int) override;
  void final_integrate() override;
  void post_run() override;
  void reset_dt() override;
  double compute_vector(int) override;

  void write_restart(FILE *) override;
  void restart(char *) override;
  double memory_usage() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;

  // read by compute rod/drag
  double push_time() const { return elapsed; }
  double tip_depth() const { return surface - (ztip0 - rod_disp); }
  double speed() const { return v0; }
  double rod_diameter() const { return diameter; }
  double gravity() const { return gmag; }
  bool surface_known() const { return surface_set; }
  double surface_height() const { return surface; }
  double axis_x() const { return xc; }
  double axis_y() const { return yc; }
  double tip_height() const { return ztip0 - rod_disp; }    // lowest point of the rod now

 private:
  // parameters
  double v0;
  int grainbit;
  std::string grain_group;
  bool surface_auto;
  int surface_grid;    // columns per side of the box for surface auto (compute bed/surface grid)
  double depth_max;    // < 0: no limit
  enum { AT_DEPTH_STOP, AT_DEPTH_HALT } at_depth;
  double ramp;                      // actuator travel to reach v0 (0: step start)
  bool mount;                       // rod driven through a spring-damper
  double kmount, cmount, mmount;    // spring, damper, rod mass
  std::string trace_file;
  double rate;         // trace rows per unit time
  double g_user;       // g for the trace header and t~; < 0: from fix gravity
  double d_user;       // rod diameter; < 0: measured
  std::string mu_str, run_str;
  std::vector<std::pair<std::string, std::string>> user_header;

  // state kept through restart
  double elapsed;                  // time since the push began
  double t_base;                   // elapsed at step_base: time = t_base + (step - step_base) dt
  bigint step_base;
  double rod_disp, rod_vel;        // rod displacement and velocity (downward +)
  double act_pos, act_vel;         // actuator displacement and velocity
  double rod_acc;                  // rod acceleration at the last force evaluation (mount)
  double held_act;                 // actuator frozen at this displacement once held
  bool held;                       // depth reached: actuator (and rigid rod) stopped
  double surface;
  bool surface_set;
  double ztip0;                    // rod tip height when the fix was created
  double win_sum[3];               // running window sums of F, Fgrain_z, samples
  bool restored;

  // derived
  double diameter, gmag, xc, yc;
  int nwindow;
  double fgrain[3];     // grain force on the rod: x, y, z (z up = resisting)
  double fsensor;       // force a sensor in series reads
  bool halt_pending;
  bool trace_opened;    // open_trace() has run (on every rank)
  double **xoriginal;
  std::unique_ptr<::granpen::TraceWriter> writer;
  bool initial_row;    // the t = 0 row has been written (or a step was taken)

  void actuator(double t, double &pos, double &vel) const;
  void place_rod();
  void sum_grain_force();
  void update_sensor();
  void check_depth();
  void open_trace();
  void sample_trace();
};

}    // namespace LAMMPS_NS

#endif
#endif
