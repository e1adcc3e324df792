/* -*- c++ -*- ----------------------------------------------------------
   granpen: LAMMPS's `-h` text with the GRANPEN styles in it. LAMMPS prints
   its style lists from the style headers it was compiled with, before any
   style can be registered at run time, so lmp_granpen captures that text
   and adds the package: GRANPEN among the installed packages, and each
   style at the end of its "* Fix styles", "* Compute styles" or
   "* Command styles" list, laid out as LAMMPS's print_style() lays them.
------------------------------------------------------------------------- */

#ifndef GRANPEN_HELP_STYLES_H
#define GRANPEN_HELP_STYLES_H

#include <string>
#include <vector>

namespace granpen {

struct HelpStyles {
  std::vector<std::string> fixes, computes, commands;
};

// help: LAMMPS's -h output; returns it with `package` and the styles added.
// A list that is missing from help is left alone (the text is returned unchanged there).
std::string add_styles_to_help(const std::string &help, const std::string &package,
                               const HelpStyles &styles);

}    // namespace granpen

#endif
