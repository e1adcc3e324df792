/* -*- c++ -*- ----------------------------------------------------------
   GRANPEN package: create_rod command
   Builds a rod of overlapping spheres. See docs/create_rod.rst.
------------------------------------------------------------------------- */

#ifdef COMMAND_CLASS
// clang-format off
CommandStyle(create_rod,CreateRod);
// clang-format on
#else

#ifndef LMP_CREATE_ROD_H
#define LMP_CREATE_ROD_H

#include "command.h"

namespace LAMMPS_NS {

class CreateRod : public Command {
 public:
  CreateRod(class LAMMPS *lmp) : Command(lmp) {}
  void command(int, char **) override;
};

}    // namespace LAMMPS_NS

#endif
#endif
