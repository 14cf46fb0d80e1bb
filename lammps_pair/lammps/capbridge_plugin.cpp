/* ----------------------------------------------------------------------
   capbridge — LAMMPS plugin entry: registers pair style gran/capillary,
   fix capillary/liquid and fix capillary/wall.  Load with:   plugin load /path/to/capbridgeplugin.so
------------------------------------------------------------------------- */

#include "lammpsplugin.h"

#include "version.h"

#include "fix_capillary_liquid.h"
#include "fix_capillary_wall.h"
#include "pair_gran_capillary.h"

using namespace LAMMPS_NS;

static Pair *gran_capillary_creator(LAMMPS *lmp)
{
  return new PairGranCapillary(lmp);
}

static Fix *capillary_liquid_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixCapillaryLiquid(lmp, argc, argv);
}

static Fix *capillary_wall_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixCapillaryWall(lmp, argc, argv);
}

// the plugin's one exported symbol (the rest of the .so is built with hidden visibility)
extern "C" __attribute__((visibility("default"))) void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  lammpsplugin_t plugin;
  auto register_plugin = (lammpsplugin_regfunc) regfunc;

  plugin.version = LAMMPS_VERSION;
  plugin.style = "pair";
  plugin.name = "gran/capillary";
  plugin.info = "capbridge capillary (liquid-bridge) cohesion pair style, core " CB_VERSION_STRING;
  plugin.author = "capbridge";
  plugin.creator.v1 = (lammpsplugin_factory1 *) &gran_capillary_creator;
  plugin.handle = handle;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "fix";
  plugin.name = "capillary/liquid";
  plugin.info = "capbridge liquid bookkeeping fix (fixed volume, Richefeu protocols 1-3)";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &capillary_liquid_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "capillary/wall";
  plugin.info = "capbridge liquid bridges between grains and flat walls";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &capillary_wall_creator;
  (*register_plugin)(&plugin, lmp);
}
