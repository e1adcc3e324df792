/* -*- c++ -*- ----------------------------------------------------------
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
