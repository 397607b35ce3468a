// Registers fix hcbd with LAMMPS (plugin load build/lammps/plugin/hcbdplugin.so).
// The plugin is compiled with hidden symbols (hcbd.h's functions as the
// 2018 model, beside gibdplugin.so's walled model of the same names): only
// this entry point is exported.
#include "lammpsplugin.h"
#include "version.h"

#include "fix_hcbd.h"

using namespace LAMMPS_NS;

static Fix *hcbd_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixHCBD(lmp, argc, argv);
}

extern "C" __attribute__((visibility("default"))) void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  lammpsplugin_t plugin;
  lammpsplugin_regfunc register_plugin = (lammpsplugin_regfunc) regfunc;
  plugin.version = LAMMPS_VERSION;
  plugin.style = "fix";
  plugin.name = "hcbd";
  plugin.info = "HCBD (Ahuja et al. 2018) from hcbd.h";
  plugin.author = "hcbd";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &hcbd_creator;
  plugin.handle = handle;
  (*register_plugin)(&plugin, lmp);
}
