/* -*- c++ -*- ----------------------------------------------------------
   capbridge — LAMMPS binding: the bridges of pair style gran/capillary, as the liquid
   reaches them

   Pair style gran/capillary keeps every bridge in its pair history; fix capillary/liquid
   runs the protocols that move liquid into and out of them.  This struct is all of the
   pair that the fix uses: where the bridges are (the fix NEIGH_HISTORY and its layout; the
   pairs are the pair style's neighbor list), the constants of each type pair, the radius
   range per type, and the bridge events since the last census.  The pair is one
   (PairGranCapillary derives from it, so that its loops use these members as their own);
   the fix finds it as dynamic_cast<CapillaryBridges *>(force->pair_match(...)) and never
   includes the pair's header.
------------------------------------------------------------------------- */

#ifndef LMP_CAPILLARY_BRIDGES_H
#define LMP_CAPILLARY_BRIDGES_H

#include "lmptype.h"

#include "capbridge.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class Error;
class FixNeighHistory;

struct CapillaryBridges {
  // Layout of the pair history (doubles per neighbor pair):
  //   [0..2] tangential (shear) displacement, negated for the partner;
  //   [3..9] the pair's cb_bridge, copied: volume [m^3], active (1.0 / 0.0), and the
  //          constants the core derives from them (rupture distance, force at contact, the
  //          radii they are for, richefeu's 1/lambda); a dry pair's rupture place holds
  //          CB_BRIDGE_REMOVED after fix capillary/liquid remove, while its contact lasts.
  // A style whose first run cannot hold a bridge keeps the contact layout, [0..2] alone
  // (SIZE_CONTACT); the first run that can hold one widens it (widen_history).
  enum { HIST_SHEAR = 0, HIST_BRIDGE = 3, SIZE_CONTACT = 3, SIZE_BRIDGE = 3 + CB_BRIDGE_DOUBLES };
  // the bridge in one pair's history values
  static cb_bridge *bridge_of(double *history)
  {
    return reinterpret_cast<cb_bridge *>(history + HIST_BRIDGE);
  }

  // One type pair: its coefficients (the only copy: pair_coeff writes them) and the constants
  // the pair loops derive from them (init_one), one record per pair instead of a pointer chase
  // per coefficient.
  struct TypePair {
    cb_contact_law contact{};      // pair_coeff's k_n, k_t, alpha_n, mu; init_one derives the
                                   // rest under pair_style's dashpot rule (the core's law)
    double formation_volume = 0.0; // a new bridge's volume in liquid mode fixed (0: none forms)
    double volume = -1.0;          // the pair_coeff volume (-1: not given, 0: never a bridge)
    double cutsq = 0.0;            // the neighbor cutoff squared (init_one)
    double design_rupture = 0.0;   // the largest rupture distance the reach is built for
                                   // (cb_reach): a held bridge beyond it is ruptured
    const cb_law *law = nullptr;   // its prepared law (nullptr: no pair_coeff)
    int contact_on = 0;            // 0: pair_coeff contact none
    int law_index = -1;            // the law's place in law_text (and the pair's laws)
  };
  std::vector<TypePair> type_pairs;    // [itype * (ntypes + 1) + jtype], both orders
  int type_stride = 0;
  const TypePair &type_pair(int itype, int jtype) const
  {
    return type_pairs[itype * type_stride + jtype];
  }
  // a type pair that may hold bridges: given by pair_coeff, with a volume other than 0
  bool wet_type_pair(int itype, int jtype) const
  {
    const TypePair &tp = type_pair(itype, jtype);
    return tp.law && tp.volume != 0.0;
  }
  std::vector<std::string> law_text;    // the law specification of each law

  FixNeighHistory *fix_history = nullptr;
  int history_size = 0;    // SIZE_CONTACT or SIZE_BRIDGE: fix_history's values a pair
                           // (0: no fix yet)

  // radius range per type (atoms present, fix pour/deposit), [ntypes + 1]
  double *rad_min = nullptr, *rad_max = nullptr;

  // events since the last census (this rank, pairs counted once), and the liquid the broken
  // bridges released into Protocol 1's pool since the fix last collected it
  double n_formed = 0.0, n_ruptured = 0.0, n_reach = 0.0, pool_released = 0.0;

  // Each pair counted once over all ranks: with newton on a pair is in one rank's list;
  // with newton off a pair with a ghost partner is in both owners' lists and is counted
  // where the owned atom has the smaller tag.
  static int counted_once(int i, int j, int nlocal, int newton_pair, const tagint *tag)
  {
    if (newton_pair || j < nlocal) return 1;
    return tag[i] < tag[j];
  }
  // May pair i, j hold a bridge: its type pair is wet and, with fix capillary/liquid
  // (groupbit != 0; no group has bit 0), both atoms are in the fix's group.
  static int wet(const TypePair &tp, const int *mask, int groupbit, int i, int j)
  {
    if (tp.volume == 0.0) return 0;
    if (groupbit && (!(mask[i] & groupbit) || !(mask[j] & groupbit))) return 0;
    return 1;
  }

  // A held bridge beyond the reach is ruptured now: the core's rule (a gap beyond the design
  // rupture distance, cb_bridge_beyond_reach), and where LAMMPS's list ends (the cutoff is a
  // distance, not a multiple of the radii: a sphere grown beyond its type's radius range
  // reaches it first), so that the pair never leaves the list holding liquid.
  static bool beyond_reach(double rsq, double gap, const TypePair &tp)
  {
    return cb_bridge_beyond_reach(gap, tp.design_rupture) || rsq >= tp.cutsq;
  }

  // a core call's status: nothing on CB_OK (inline: it follows every core call of the bridge
  // loops), else the error naming the pair and its law (fail_cb)
  void check_cb(Error *error, int status, const char *what, int itype, int jtype, double r1,
                double r2, double vol, double gap) const
  {
    if (status != CB_OK) fail_cb(error, status, what, itype, jtype, r1, r2, vol, gap);
  }
  [[noreturn]] void fail_cb(Error *error, int status, const char *what, int itype, int jtype,
                            double r1, double r2, double vol, double gap) const;
};

}    // namespace LAMMPS_NS

#endif
