// granpen sweep: the sweep file, validated, and the plan of runs it implies.
// Pure: parsing and planning know nothing of processes; sweep_runner does the running.
//
// Sweep file (text, '#' comments, one `key = value` per line, lists separated by spaces):
//   name    = calib_bench       the sweep's folder name: letters, digits, _ and -
//   preset  = bench             preset names, each inputs/presets/NAME.lmp
//   mu      = 0.1 0.2 0.3 0.5   friction coefficients of the pours (default: preset's)
//   seeds   = 1 2               bed seeds, positive integers (default 1)
//   v0      = 50 100 200        push speeds (required)
//   g       = 981               push gravities (default: preset's; the bed keeps its own)
//   D       = 2.0               rod diameters (default: preset's)
//   depth   = 4.0               push depth (default: preset's)
//   mu_push = 0.2 0.3           friction during the push, raised in the poured bed
//                               (default: the pour's)
//   observe = none              an inputs/observe/NAME.lmp to include in every push
//   set     = poly=0.1 walls=1  deck variables (-var NAME VALUE) of every pour and push: the
//                               model knobs of in.pour and inputs/model/contact.lmp
//   push_set = ramp=0.3         deck variables of the pushes only (the measurement chain)
//   pour_checkpoint = yes       pours checkpoint every settling chunk and resume from it
//                               (in.pour -var checkpoint 1; for pours of hours: dg10)
// Every value is checked: numbers are parsed whole as finite positive numbers, names
// against a safe character set; no value ever reaches a shell.
#ifndef GRANPEN_SWEEP_SPEC_H
#define GRANPEN_SWEEP_SPEC_H

#include <string>
#include <utility>
#include <vector>

namespace granpen {

struct SweepSpec {
  std::string path;
  std::string name;
  std::vector<std::string> presets;
  std::vector<std::string> mu;       // kept as written (validated numbers): they name files
  std::vector<std::string> seeds;
  std::vector<std::string> v0, g, D, mu_push;
  std::string depth;                 // empty: the preset's
  std::string observe = "none";
  std::vector<std::pair<std::string, std::string>> set, push_set;    // NAME, VALUE
  bool pour_checkpoint = false;
};

struct PlannedRun {
  enum Kind { POUR, PUSH } kind;
  std::string id;          // unique, file-name safe
  std::string preset, mu, seed;
  std::string bed;         // for a push: the id of its pour
  std::string v0, g, D, depth, mu_push;
};

// Parses and validates; throws InputError naming path:line. preset_exists and
// observe_exists say whether inputs/presets/NAME.lmp and inputs/observe/NAME.lmp exist.
SweepSpec parse_sweep(const std::string &text, const std::string &path,
                      bool (*preset_exists)(const std::string &) = nullptr,
                      bool (*observe_exists)(const std::string &) = nullptr);

// Pours first (one per preset, mu, seed), then the pushes branching from each bed.
std::vector<PlannedRun> plan_sweep(const SweepSpec &spec);

// A name made only of letters, digits, '_' and '-', not starting with '-'.
bool safe_name(const std::string &s);
// A deck variable a sweep may set: a safe name that is not one the runner sets itself.
bool settable_variable(const std::string &name);
// A finite decimal number of any sign, or a safe name (yes, no, ...).
bool settable_value(const std::string &value);

// A whole, finite, positive decimal number (no sign, no exponent tricks beyond e/E).
bool positive_number(const std::string &s);

// What to do with a push whose files are as given.
enum class PushAction { SKIP_DONE, RESUME, RESTART_FRESH, START };
PushAction push_action(bool done_marker, bool trace_exists, bool checkpoint_exists);

}    // namespace granpen

#endif
