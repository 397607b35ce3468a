// Registers fix gibd and pair_style star with LAMMPS (plugin load
// build/lammps/plugin/gibdplugin.so).
#include "lammpsplugin.h"
#include "version.h"

#include "fix_gibd.h"
#include "pair_star.h"

using namespace LAMMPS_NS;

static Fix *gibd_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixGIBD(lmp, argc, argv);
}

static Pair *star_creator(LAMMPS *lmp)
{
  return new PairStar(lmp);
}

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  lammpsplugin_t plugin;
  lammpsplugin_regfunc register_plugin = (lammpsplugin_regfunc) regfunc;
  plugin.version = LAMMPS_VERSION;
  plugin.style = "fix";
  plugin.name = "gibd";
  plugin.info = "GI-BD (Padding & Briels 2014, Ahuja et al. 2016) from hcbd.h";
  plugin.author = "hcbd";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &gibd_creator;
  plugin.handle = handle;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "pair";
  plugin.name = "star";
  plugin.info = "Likos star-polymer potential (Padding & Briels 2014 eq. 28) from hcbd.h";
  plugin.creator.v1 = (lammpsplugin_factory1 *) &star_creator;
  (*register_plugin)(&plugin, lmp);
}
