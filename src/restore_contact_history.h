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
   GRANPEN package: restore_contact_history command
   Carries the grain-grain contact histories of a restart over to a new
   pair style. See the comment in restore_contact_history.cpp.
------------------------------------------------------------------------- */

#ifdef COMMAND_CLASS
// clang-format off
CommandStyle(restore_contact_history,RestoreContactHistory);
// clang-format on
#else

#ifndef LMP_RESTORE_CONTACT_HISTORY_H
#define LMP_RESTORE_CONTACT_HISTORY_H

#include "command.h"

namespace LAMMPS_NS {

class RestoreContactHistory : public Command {
 public:
  RestoreContactHistory(class LAMMPS *lmp) : Command(lmp) {}
  void command(int, char **) override;
};

}    // namespace LAMMPS_NS

#endif
#endif
