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
   GRANPEN package: restore_contact_history command

   restore_contact_history

   A gran/hertz/history pair keeps its contacts' tangential histories in a
   fix NEIGH_HISTORY named NEIGH_HISTORY_HH<n>, n the pair's instance number,
   and a restart stores them under that name. A new pair style (in.push's
   pair_style hybrid of two gran/hertz/history, for a rod friction of its
   own: inputs/model/contact.lmp) makes new instances with new numbers, so
   the bed's histories would be dropped at the first run: every static
   contact of the poured bed would lose its tangential spring at once.
   Called after the new pair style and before the first run, this renames
   the restart's pending history entries, in instance order, to the history
   fixes the current gran/hertz/history (sub-)styles will create, in the
   order they were defined; the first run then restores them as usual.
   Without a pending restart entry it does nothing (a fresh system). The
   fix's global restart entry stays under the old name ("unused" in the
   log): it holds nothing (FixNeighHistory::write_restart writes size 0).
------------------------------------------------------------------------- */

#include "restore_contact_history.h"

#include "comm.h"
#include "error.h"
#include "fix.h"
#include "modify.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

using namespace LAMMPS_NS;

namespace {

// Modify keeps the restart's per-fix entries protected; a pointer to member
// taken through a derived class reads them without changing LAMMPS.
struct RestartEntries : Modify {
  static int &count(Modify *m) { return m->*(&RestartEntries::nfix_restart_peratom); }
  static char **&ids(Modify *m) { return m->*(&RestartEntries::id_restart_peratom); }
  static char **&styles(Modify *m) { return m->*(&RestartEntries::style_restart_peratom); }
  static int *&used(Modify *m) { return m->*(&RestartEntries::used_restart_peratom); }
};

// n of "PREFIX<n>" (digits only after the prefix), or -1
long instance_of(const std::string &id, const std::string &prefix)
{
  if (id.compare(0, prefix.size(), prefix) != 0 || id.size() == prefix.size()) return -1;
  const std::string tail = id.substr(prefix.size());
  if (tail.find_first_not_of("0123456789") != std::string::npos) return -1;
  return std::stol(tail);
}

}    // namespace

void RestoreContactHistory::command(int narg, char ** /*arg*/)
{
  if (narg != 0) error->all(FLERR, "Illegal restore_contact_history command: it takes no arguments");
  const std::string HISTORY = "NEIGH_HISTORY_HH", DUMMY = "NEIGH_HISTORY_HH_DUMMY";

  // the restart's pending gran/hertz/history entries, by instance number
  std::vector<std::pair<long, int>> pending;
  for (int i = 0; i < RestartEntries::count(modify); ++i) {
    const long n = instance_of(RestartEntries::ids(modify)[i], HISTORY);
    if (n >= 0 && !RestartEntries::used(modify)[i] &&
        std::strcmp(RestartEntries::styles(modify)[i], "NEIGH_HISTORY") == 0)
      pending.emplace_back(n, i);
  }
  std::sort(pending.begin(), pending.end());
  // the history fixes the current styles will create, in the order they were defined
  std::vector<long> fresh;
  for (int i = 0; i < modify->nfix; ++i) {
    const long n = instance_of(modify->fix[i]->id, DUMMY);
    if (n >= 0) fresh.push_back(n);
  }
  if (pending.empty()) {
    if (comm->me == 0) utils::logmesg(lmp, "restore_contact_history: no contact history from a restart pending\n");
    return;
  }
  if (pending.size() > fresh.size())
    error->all(FLERR, "Restore_contact_history: the restart holds {} gran/hertz/history contact histories but "
                      "the pair style defines {} (a restart of another contact law?)",
               pending.size(), fresh.size());
  for (size_t k = 0; k < pending.size(); ++k) {
    char *&id = RestartEntries::ids(modify)[pending[k].second];
    const std::string to = HISTORY + std::to_string(fresh[k]);
    if (comm->me == 0) utils::logmesg(lmp, "restore_contact_history: {} -> {}\n", id, to);
    delete[] id;
    id = new char[to.size() + 1];
    std::strcpy(id, to.c_str());
  }
}
