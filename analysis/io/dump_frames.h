// granpen analysis: the frames of a LAMMPS dump as granpen flow and granpen momentum use
// them: the grains and the rod of a frame as plain arrays (core/flow_fields.h's
// GrainArrays), and a push's force trace with its header values as numbers.
#ifndef GRANPEN_DUMP_FRAMES_H
#define GRANPEN_DUMP_FRAMES_H

#include "dump_reader.h"
#include "flow_fields.h"
#include "rod_frame.h"
#include "trace_reader.h"

#include <string>
#include <vector>

namespace granpen {

// Where the rod is: from its atoms (rod_type), or an axis and a tip given as options.
struct RodOptions {
  int rod_type = 2;
  bool have_axis = false, have_tip = false;
  double axis_x = 0.0, axis_y = 0.0, tip = 0.0;
};
// Column choices, made once from the first frame.
struct ColumnChoice {
  bool mass = false;                 // a "mass" column
  std::string voronoi;               // per-atom Voronoi volume column, or empty
  std::string stress[3];             // stress x volume xx yy zz columns, or empty
};

// One frame without its rod atoms.
struct GrainFrame {
  std::string where;                 // FILE:LINE of the frame
  long long timestep = 0;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  double period_x = 0.0, period_y = 0.0;
  std::vector<double> x, y, z, vx, vy, vz, radius, mass, vor, sxx, syy, szz;
  std::vector<char> is_rod;          // per atom of the frame
  std::vector<double> rod_x, rod_y, rod_z, rod_radius;    // the rod atoms
  RodPosition rod;                   // from the rod atoms (found = false without any)
  double axis_x = 0.0, axis_y = 0.0, tip = 0.0;    // used: rod atoms or options
  bool have_vor = false, have_stress = false;
  std::size_t grains() const { return x.size(); }
  GrainArrays arrays() const;
};

// Fills g from f. rho: grain density for masses when there is no mass column. Throws
// InputError naming FILE:LINE (no rod atoms and no --axis/--tip, a bad type value, ...).
void extract_frame(const DumpFrame &f, const RodOptions &rod, const ColumnChoice &cols, double rho,
                   bool periodic_x, bool periodic_y, GrainFrame &g);

// A push's force trace and its optional header values as numbers (absent keys leave
// have_* false; a key that is not a number is an InputError naming the file).
struct PushTrace {
  bool present = false;
  Trace trace;
  bool have_dg = false, have_rho = false, have_mu = false, have_surface = false, have_dt = false;
  double d_g = 0.0, rho_g = 0.0, mu = 0.0, surface = 0.0, dt = 0.0;
};
PushTrace load_push_trace(const std::string &path);    // throws InputError

}    // namespace granpen

#endif
