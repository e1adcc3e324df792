// granpen flow / granpen momentum: what the two dump subcommands share: the grains and
// the rod of a dump frame as plain arrays, the force trace's header values, progress
// on stderr, and outputs written all at once (nothing half-written on failure).
#ifndef GRANPEN_CLI_DUMP_CMD_COMMON_H
#define GRANPEN_CLI_DUMP_CMD_COMMON_H

#include "args.h"
#include "dump_reader.h"
#include "flow_fields.h"
#include "rod_frame.h"
#include "trace_reader.h"

#include <string>
#include <utility>
#include <vector>

namespace granpen {
namespace cli {

// Where the rod is: from its atoms (rod_type), or an axis and a tip given as options.
struct RodOptions {
  int rod_type = 2;
  bool have_axis = false, have_tip = false;
  double axis_x = 0.0, axis_y = 0.0, tip = 0.0;
};
// From the numeric options (ParsedArgs::read_numbers) --rod-type N, --axis X Y, --tip Z;
// false with a message when N is not a positive integer.
bool read_rod_options(const ParsedArgs &args, RodOptions &rod, std::string &message);

// --periodic AXES: xy, x, y or none, as periodic x and y; false for anything else.
bool periodic_axes(const std::string &axes, bool &x, bool &y);

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

// The force trace's header values (as numbers; absent keys leave have_* false).
struct TraceHeader {
  bool present = false;
  Trace trace;
  bool have_dg = false, have_rho = false, have_mu = false, have_surface = false, have_dt = false;
  double d_g = 0.0, rho_g = 0.0, mu = 0.0, surface = 0.0, dt = 0.0;
};
TraceHeader load_trace(const std::string &path);    // throws InputError

// Progress lines on stderr every 2 s while reading and once at the end
// ("TOOL: N frames, X MB, Y MB/s").
void report_progress(DumpReader &reader, const std::string &tool);

// A number for CSV and JSON: %.10g; non-finite as nan in CSV, 0 in JSON (json_number).
std::string csv_num(double v);
std::string js(double v);

// Writes every (name, text) into dir (made if missing) through io/atomic_file (every
// temporary written before the first rename); false with a message naming the path.
bool write_outputs(const std::string &dir, const std::vector<std::pair<std::string, std::string>> &files,
                   std::string &message);

// Throws OutputError when dir/NAME for one of names is one of the inputs (the dumps,
// args.positional, and --trace): checked before anything is read.
void refuse_outputs_over_inputs(const std::string &dir, const std::vector<const char *> &names, const ParsedArgs &args);

}    // namespace cli
}    // namespace granpen

#endif
