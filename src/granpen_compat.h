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
   GRANPEN package: every difference between the LAMMPS versions granpen
   builds against lives here, keyed on LAMMPS_VERSION_NUMBER (yyyymmdd),
   which CMake derives from the LAMMPS it compiles against (see
   cmake/LammpsVersion.cmake and docs/compat.md).
------------------------------------------------------------------------- */

#ifndef LMP_GRANPEN_COMPAT_H
#define LMP_GRANPEN_COMPAT_H

#include "atom.h"
#include "compute.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "lammps.h"
#include "modify.h"
#include "utils.h"

#include <string>
#include <type_traits>
#include <utility>

#ifndef LAMMPS_VERSION_NUMBER
// Dropped into a LAMMPS tree without granpen's CMake: assume a current LAMMPS.
#define LAMMPS_VERSION_NUMBER 20240829
#endif

namespace LAMMPS_NS {
class Region;
namespace gp {

// Each cutoff below is the first LAMMPS *release* carrying the change, found in
// LAMMPS's git history (docs/compat.md lists the commits). A development tree
// carries the date of the release before it (version.h then also says
// LAMMPS_UPDATE "Development"), so it takes the older branch: every #else branch
// here only uses API that current LAMMPS still has.

// Modify::get_fix_by_id / get_compute_by_id: LAMMPS PR #3001 (commit 5b40e4cb,
// merged 2 Nov 2021), first released in 14Dec2021. Debian's 29Sep2021 lacks them.
inline Fix *fix_by_id(LAMMPS *lmp, const std::string &id)
{
#if LAMMPS_VERSION_NUMBER >= 20211214
  return lmp->modify->get_fix_by_id(id);
#else
  int i = lmp->modify->find_fix(id);
  return (i < 0) ? nullptr : lmp->modify->fix[i];
#endif
}

inline Compute *compute_by_id(LAMMPS *lmp, const std::string &id)
{
#if LAMMPS_VERSION_NUMBER >= 20211214
  return lmp->modify->get_compute_by_id(id);
#else
  int i = lmp->modify->find_compute(id);
  return (i < 0) ? nullptr : lmp->modify->compute[i];
#endif
}

// Modify::nfix and Modify::fix[] are public in every supported version.
// Domain::get_region_by_id came with LAMMPS PR #3001 (merged 2 Nov 2021), first released
// in 14Dec2021; 29Sep2021 has find_region() and the public regions[] list.
inline Region *region_by_id(LAMMPS *lmp, const std::string &id)
{
#if LAMMPS_VERSION_NUMBER >= 20211214
  return lmp->domain->get_region_by_id(id);
#else
  int i = lmp->domain->find_region(id);
  return (i < 0) ? nullptr : lmp->domain->regions[i];
#endif
}

inline int nfix(LAMMPS *lmp) { return lmp->modify->nfix; }
inline Fix *fix_at(LAMMPS *lmp, int i) { return lmp->modify->fix[i]; }

// utils::logical(file, line, const char *, do_abort, lmp): LAMMPS PR #2951
// (commit cef10099, merged 30 Sep 2021, the day after 29Sep2021), first released
// in 27Oct2021; the std::string overload only came with 7Jan2022, so pass c_str().
// It has always accepted exactly these words.
inline bool logical(const char *file, int line, const std::string &word, LAMMPS *lmp)
{
#if LAMMPS_VERSION_NUMBER >= 20211027
  return utils::logical(file, line, word.c_str(), false, lmp) != 0;
#else
  if (word.empty())
    lmp->error->all(file, line,
                    "Expected boolean parameter instead of NULL or empty string in input script "
                    "or data file");
  if (word == "yes" || word == "on" || word == "true" || word == "1") return true;
  if (word == "no" || word == "off" || word == "false" || word == "0") return false;
  lmp->error->all(file, line,
                  "Expected boolean parameter instead of '{}' in input script or data file", word);
  return false;
#endif
}

// utils::missing_cmd_args: commit dc4752ef (LAMMPS PR #3227, merged 23 Apr 2022),
// first released in 4May2022. Same message on both sides.
inline void need_args(const char *file, int line, const std::string &cmd, int iarg, int nneeded,
                      int narg, LAMMPS *lmp)
{
  if (iarg + nneeded <= narg) return;
#if LAMMPS_VERSION_NUMBER >= 20220504
  utils::missing_cmd_args(file, line, cmd, lmp->error);
#else
  lmp->error->all(file, line, "Illegal {} command: missing argument(s)", cmd);
#endif
}

// "atom style sphere": Atom::sphere_flag was removed in 7Feb2024 (commit 0d8f549e,
// LAMMPS PR #4054, merged 26 Jan 2024; LAMMPS itself now tests radius_flag and
// omega_flag). Atom styles sphere, line and tri, the ones that set sphere_flag
// where it exists, set radius_flag, rmass_flag and omega_flag in every supported
// version, and those are the per-atom arrays the GRANPEN styles use. So this test
// is the same on every version and needs no cutoff (which also covers development
// trees dated 21 Nov 2023 that already lack sphere_flag).
inline bool sphere_atoms(const Atom *atom)
{
  return atom->radius_flag && atom->rmass_flag && atom->omega_flag;
}

// Return type of Fix::dof(int): int up to 21Nov2023, bigint from 7Feb2024
// (commit 8b89c330, LAMMPS PR #4037, merged 15 Jan 2024). For a future
// `dof_t dof(int) override;` -- no GRANPEN fix overrides dof() today.
#if LAMMPS_VERSION_NUMBER >= 20240207
typedef bigint dof_t;
#else
typedef int dof_t;
#endif


// Domain::minimum_image(FLERR, dx, dy, dz): LAMMPS PR #4610 added the caller's file and
// line in front (absent in 29Aug2024, present in stable 22Jul2025, which has no overload
// without them). Decided by what the header offers, not by a date: the
// 5-argument overload exists or it does not, whatever a development tree's date says.
template <typename D, typename = void> struct has_located_minimum_image : std::false_type {};
template <typename D>
struct has_located_minimum_image<
    D,
    decltype(void(std::declval<const D &>().minimum_image(
        std::declval<const char *>(), 0, std::declval<double &>(), std::declval<double &>(),
        std::declval<double &>())))> : std::true_type {};

// (tag dispatch rather than if constexpr: the package sources stay C++11 for 29Sep2021)
template <typename D>
inline void minimum_image_impl(D *domain, const char *file, int line, double &dx, double &dy,
                               double &dz, std::true_type)
{
  domain->minimum_image(file, line, dx, dy, dz);
}
template <typename D>
inline void minimum_image_impl(D *domain, const char *, int, double &dx, double &dy, double &dz,
                               std::false_type)
{
  domain->minimum_image(dx, dy, dz);
}
template <typename D>
inline void minimum_image(D *domain, const char *file, int line, double &dx, double &dy,
                          double &dz)
{
  minimum_image_impl(domain, file, line, dx, dy, dz, has_located_minimum_image<D>());
}

// LAMMPSAbortException::universe: a public member up to 2023, protected behind
// get_universe() since (LAMMPS's own main() calls get_universe()). Chosen by overload:
// the first template applies where get_universe() exists.
template <typename E>
inline auto abort_universe_impl(const E &e, int) -> decltype(e.get_universe())
{
  return e.get_universe();
}
template <typename E> inline MPI_Comm abort_universe_impl(const E &e, long)
{
  return e.universe;
}
template <typename E> inline MPI_Comm abort_universe(const E &e)
{
  return abort_universe_impl(e, 0);
}

}    // namespace gp
}    // namespace LAMMPS_NS

#endif
