/* ----------------------------------------------------------------------
   granpen: style registry. Each header is included twice, as LAMMPS's own
   style_*.h files are: once for the class, once with the *_CLASS macros
   set so it yields only its FixStyle/ComputeStyle/CommandStyle line.
------------------------------------------------------------------------- */

#include "style_registry.h"

#include "input.h"
#include "lammps.h"
#include "modify.h"

#include "granpen_style_headers.h"    // generated: the classes

using namespace LAMMPS_NS;

namespace {
template <typename T> Fix *fix_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new T(lmp, narg, arg);
}
template <typename T> Compute *compute_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new T(lmp, narg, arg);
}
template <typename T> Command *command_creator(LAMMPS *lmp) { return new T(lmp); }
}    // namespace

void granpen::visit_styles(const StyleVisitor &visit)
{
#define FIX_CLASS
#define COMPUTE_CLASS
#define COMMAND_CLASS
#define FixStyle(key, Class) visit(StyleKind::Fix, #key, (void *) &fix_creator<Class>)
#define ComputeStyle(key, Class) visit(StyleKind::Compute, #key, (void *) &compute_creator<Class>)
#define CommandStyle(key, Class) visit(StyleKind::Command, #key, (void *) &command_creator<Class>)
#include "granpen_style_headers.h"    // generated: the style lines
#undef FixStyle
#undef ComputeStyle
#undef CommandStyle
#undef FIX_CLASS
#undef COMPUTE_CLASS
#undef COMMAND_CLASS
}

void granpen::register_styles(LAMMPS *lmp)
{
  visit_styles([lmp](StyleKind kind, const char *name, void *creator) {
    switch (kind) {
      case StyleKind::Fix:
        (*lmp->modify->fix_map)[name] = (Modify::FixCreator) creator;
        break;
      case StyleKind::Compute:
        (*lmp->modify->compute_map)[name] = (Modify::ComputeCreator) creator;
        break;
      case StyleKind::Command:
        (*lmp->input->command_map)[name] = (Input::CommandCreator) creator;
        break;
    }
  });
}
