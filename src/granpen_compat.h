/* -*- c++ -*- ----------------------------------------------------------
   GRANPEN package: every difference between the LAMMPS versions granpen
   builds against lives here, keyed on LAMMPS_VERSION_NUMBER (yyyymmdd),
   which CMake derives from the LAMMPS it compiles against (see
   cmake/LammpsVersion.cmake and docs/compat.md).
------------------------------------------------------------------------- */

#ifndef LMP_GRANPEN_COMPAT_H
#define LMP_GRANPEN_COMPAT_H

#include "compute.h"
#include "error.h"
#include "fix.h"
#include "lammps.h"
#include "modify.h"
#include "utils.h"

#include <string>

#ifndef LAMMPS_VERSION_NUMBER
// Dropped into a LAMMPS tree without granpen's CMake: assume a current LAMMPS.
#define LAMMPS_VERSION_NUMBER 20240829
#endif

namespace LAMMPS_NS {
namespace gp {

// LAMMPS before 2Jun2022 has no Modify::get_fix_by_id / get_compute_by_id.
inline Fix *fix_by_id(LAMMPS *lmp, const std::string &id)
{
#if LAMMPS_VERSION_NUMBER >= 20220602
  return lmp->modify->get_fix_by_id(id);
#else
  int i = lmp->modify->find_fix(id);
  return (i < 0) ? nullptr : lmp->modify->fix[i];
#endif
}

inline Compute *compute_by_id(LAMMPS *lmp, const std::string &id)
{
#if LAMMPS_VERSION_NUMBER >= 20220602
  return lmp->modify->get_compute_by_id(id);
#else
  int i = lmp->modify->find_compute(id);
  return (i < 0) ? nullptr : lmp->modify->compute[i];
#endif
}

inline int nfix(LAMMPS *lmp) { return lmp->modify->nfix; }
inline Fix *fix_at(LAMMPS *lmp, int i) { return lmp->modify->fix[i]; }

// utils::logical appeared after 29Sep2021; same accepted words.
inline bool logical(const char *file, int line, const std::string &word, LAMMPS *lmp)
{
#if LAMMPS_VERSION_NUMBER >= 20220324
  return utils::logical(file, line, word, false, lmp) != 0;
#else
  if (word == "yes" || word == "on" || word == "true" || word == "1") return true;
  if (word == "no" || word == "off" || word == "false" || word == "0") return false;
  lmp->error->all(file, line, "Expected boolean parameter instead of '{}' in input script", word);
  return false;
#endif
}

// utils::missing_cmd_args appeared after 29Sep2021.
inline void need_args(const char *file, int line, const std::string &cmd, int iarg, int nneeded,
                      int narg, LAMMPS *lmp)
{
  if (iarg + nneeded > narg)
    lmp->error->all(file, line, "Illegal {} command: missing argument(s)", cmd);
}

}    // namespace gp
}    // namespace LAMMPS_NS

#endif
