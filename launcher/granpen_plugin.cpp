/* ----------------------------------------------------------------------
   granpen: the GRANPEN styles as a LAMMPS plugin (`plugin load`), for a
   LAMMPS built with the PLUGIN package from the source tree this object
   was compiled against.
------------------------------------------------------------------------- */

#include "lammpsplugin.h"
#include "style_registry.h"
#include "version.h"

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  auto reg = (lammpsplugin_regfunc) regfunc;
  granpen::visit_styles([&](granpen::StyleKind kind, const char *name, void *creator) {
    lammpsplugin_t plugin;
    plugin.version = LAMMPS_VERSION;
    plugin.name = name;
    plugin.author = "granpen developers";
    plugin.handle = handle;
    switch (kind) {
      case granpen::StyleKind::Fix:
        plugin.style = "fix";
        plugin.info = "GRANPEN fix style";
        plugin.creator.v2 = (lammpsplugin_factory2 *) creator;
        break;
      case granpen::StyleKind::Compute:
        plugin.style = "compute";
        plugin.info = "GRANPEN compute style";
        plugin.creator.v2 = (lammpsplugin_factory2 *) creator;
        break;
      case granpen::StyleKind::Command:
        plugin.style = "command";
        plugin.info = "GRANPEN command";
        plugin.creator.v1 = (lammpsplugin_factory1 *) creator;
        break;
    }
    (*reg)(&plugin, lmp);
  });
}
