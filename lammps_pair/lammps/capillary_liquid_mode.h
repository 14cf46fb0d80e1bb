/* -*- c++ -*- ----------------------------------------------------------
   capbridge — LAMMPS binding: how bridges get their liquid

   The liquid modes of fix capillary/liquid, which pair style gran/capillary reads too (the
   reach, the formation volume and the per-step exchange depend on them).  A header of its
   own so that the pair and the fix share it without including each other.  The values are
   written to restart files (fix capillary/liquid's global state): do not renumber.
------------------------------------------------------------------------- */

#ifndef LMP_CAPILLARY_LIQUID_MODE_H
#define LMP_CAPILLARY_LIQUID_MODE_H

namespace LAMMPS_NS {

enum CapillaryLiquidMode {
  LIQUID_FIXED = 0,    // a fixed volume per new bridge (pair_coeff volume or fix ... fixed V)
  LIQUID_PROTOCOL1,    // Richefeu 2007 Protocol 1: all liquid redistributed every N steps
  LIQUID_PROTOCOL2,    // Protocol 2: per-atom free liquid, shared at rupture
  LIQUID_PROTOCOL3,    // Protocol 3: as 2, each share to the atom's lowest bridge
  LIQUID_MODES
};

// the fix's keyword for each mode
inline const char *capillary_liquid_mode_name(int mode)
{
  static const char *const names[LIQUID_MODES] = {"fixed", "protocol1", "protocol2", "protocol3"};
  return mode >= 0 && mode < LIQUID_MODES ? names[mode] : "unknown";
}

// Protocols 2 and 3 keep free liquid per atom and exchange it within a force evaluation
inline bool capillary_liquid_per_atom(int mode)
{
  return mode == LIQUID_PROTOCOL2 || mode == LIQUID_PROTOCOL3;
}

}    // namespace LAMMPS_NS

#endif
