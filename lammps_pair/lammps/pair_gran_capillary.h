/* -*- c++ -*- ----------------------------------------------------------
   capbridge — LAMMPS binding: pair style gran/capillary

   Linear spring-dashpot contact (Richefeu et al. 2007, eqs. 2-3), tangential spring
   with history and a Coulomb limit (eq. 12), and the capillary (liquid-bridge) force of
   the capbridge core (capbridge.h) between finite-size spheres.  The bridge state of
   every pair lives in the pair history (fix NEIGH_HISTORY).  See
   doc/pair_gran_capillary.rst.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(gran/capillary,PairGranCapillary);
// clang-format on
#else

#ifndef LMP_PAIR_GRAN_CAPILLARY_H
#define LMP_PAIR_GRAN_CAPILLARY_H

#include "pair.h"

#include "capbridge.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixCapillaryLiquid;

class PairGranCapillary : public Pair {
 public:
  // Layout of the pair history (doubles per neighbor pair):
  //   [0..2] tangential (shear) displacement, negated for the partner;
  //   [3..9] the pair's cb_bridge, copied: volume [m^3], active (1.0 / 0.0), and the
  //          constants the core derives from them (rupture distance, force at contact, the
  //          radii they are for, richefeu's 1/lambda).
  // A style whose first run cannot hold a bridge keeps the contact layout, [0..2] alone
  // (SIZE_CONTACT); the first run that can hold one widens it (widen_history).
  enum { HIST_SHEAR = 0, HIST_BRIDGE = 3, SIZE_CONTACT = 3, SIZE_BRIDGE = 3 + CB_BRIDGE_DOUBLES };
  // the bridge in one pair's history values
  static cb_bridge *bridge_of(double *history)
  {
    return reinterpret_cast<cb_bridge *>(history + HIST_BRIDGE);
  }
  // the restart settings' format: 2 (0 and 1 were the friction setting of earlier files)
  enum { SETTINGS_FORMAT = 2 };
  // How bridges get their liquid.
  enum { LIQUID_FIXED = 0, LIQUID_PROTOCOL1, LIQUID_PROTOCOL2, LIQUID_PROTOCOL3 };
  // Values of single() in svector (compute pair/local p1 ... p8).
  enum {
    SV_CAPILLARY_FORCE = 0,
    SV_GAP,
    SV_VOLUME,
    SV_BRIDGE,
    SV_R1,
    SV_R2,
    SV_CONTACT_FORCE,
    SV_TANGENTIAL_FORCE,
    SV_COUNT
  };

  PairGranCapillary(class LAMMPS *);
  ~PairGranCapillary() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void reset_dt() override;
  double single(int, int, int, int, double, double, double, double &) override;
  void transfer_history(double *, double *, int, int) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;
  double atom2cut(int) override;
  double radii2cut(double, double) override;

  // ---- interface used by fix capillary/liquid ----

  // Local (this rank's) census of the pair history; each pair counted once over all
  // ranks.  out[0] bridges, out[1] liquid in bridges, out[2] formations, out[3] ruptures,
  // out[4] ruptures forced at the neighbor reach, out[5] liquid released to the global
  // pool (Protocol 1).  Event counters and the released liquid are reset.
  void census(double *out);
  // Protocol 1 (Richefeu 2007 §2.4) over every pair within reach, across all ranks.
  // Returns 0 on success (alpha and the largest bridge volume set), 1 when no pair can
  // hold the liquid (nothing changed).
  int protocol1(double total_liquid, double &alpha, double &largest_volume);
  // The neighbor reach of a type pair is built for this bridge volume.
  double design_volume(int itype, int jtype) const;
  // Protocol 1: liquid of broken bridges this rank released since the last call.
  double drain_pool()
  {
    double v = pool_released;
    pool_released = 0.0;
    return v;
  }

 protected:
  std::vector<std::string> coeff_text;    // the pair_coeff arguments, for restart files
  std::vector<cb_law *> laws;             // prepared laws, shared by type pairs
  std::vector<std::string> law_text;      // the law specification of each law

  // One type pair: its coefficients (the only copy: pair_coeff writes them) and the constants
  // the pair loops derive from them (init_one), one record per pair instead of a pointer chase
  // per coefficient.
  struct TypePair {
    cb_contact_law contact{};      // pair_coeff's k_n, k_t, alpha_n, mu; init_one derives the
                                   // rest under pair_style's dashpot rule (the core's law)
    double formation_volume = 0.0; // a new bridge's volume in liquid mode fixed (0: none forms)
    double volume = -1.0;          // the pair_coeff volume (-1: not given, 0: never a bridge)
    double cutsq = 0.0;            // the neighbor cutoff squared (init_one)
    const cb_law *law = nullptr;   // its prepared law (nullptr: no pair_coeff)
    int contact_on = 0;            // 0: pair_coeff contact none
    int law_index = -1;            // the law's place in laws and law_text
  };
  std::vector<TypePair> type_pairs;    // [itype * (ntypes + 1) + jtype], both orders
  int type_stride;
  const TypePair &type_pair(int itype, int jtype) const
  {
    return type_pairs[itype * type_stride + jtype];
  }
  // The per-atom arrays of one force evaluation, read once per compute() (through `atom` the
  // compiler must reload them after every force store).
  struct AtomArrays {
    double **x, **v, **f, **omega, **torque;
    double *radius, *rmass;
    int *mask;
    int nlocal, newton_pair;
  };

  cb_dashpot_rule dashpot;    // approach (Richefeu 2007 eq. 3), both, repulsive
  double dt;
  int freeze_group_bit;

  // radius range per type (atoms present, fix pour/deposit)
  double *rad_min, *rad_max;

  class FixDummy *fix_dummy;
  class FixNeighHistory *fix_history;
  int history_size;    // SIZE_CONTACT or SIZE_BRIDGE: fix_history's values a pair (0: no fix yet)
  FixCapillaryLiquid *fix_liquid;
  int liquid_mode, liquid_groupbit;
  int bridges_possible;    // 0: no type pair can form a bridge in this run and none exists
                           // (init_style)
  std::vector<double> held_volume;    // per type: the largest bridge that exists (init_style)

  // per-atom scratch of one force evaluation (owned + ghost), Protocols 2 and 3
  int nmax_scratch;
  double *candidates, *released, *offer, *deposit, *best_height;
  tagint *best_partner;
  int commflag;
  enum { COMM_REVERSE_SIZE = 4, COMM_FORWARD_SIZE = 3 };    // values an atom, each way

  // events since the last census (this rank, pairs counted once)
  double n_formed, n_ruptured, n_reach, pool_released;

  int dt_warned, reach_warned;
  // check_timestep(): its reduction buffers, and the capillary stiffness bound per type pair
  // with the two volumes it was evaluated at
  std::vector<double> timestep_local, timestep_global, bound_volumes, capillary_bound;
  int neighprev;

  void allocate();
  void grow_scratch();
  const cb_law *law(int itype, int jtype) const { return type_pair(itype, jtype).law; }
  int counted(int i, int j) const;
  int wet_pair(int i, int j, const TypePair &tp) const;
  // a core call's status: nothing on CB_OK (inline: it follows every core call of the pair
  // loops), else the error naming the pair (fail_cb)
  void check_cb(int status, const char *what, int itype, int jtype, double r1, double r2,
                double vol, double gap)
  {
    if (status != CB_OK) fail_cb(status, what, itype, jtype, r1, r2, vol, gap);
  }
  [[noreturn]] void fail_cb(int status, const char *what, int itype, int jtype, double r1,
                            double r2, double vol, double gap);
  [[noreturn]] void coincident_atoms(int i, int j);
  std::string history_id(int size) const;
  const std::string dummy_id = "NEIGH_HISTORY_CAPILLARY_DUMMY";
  void create_history();
  void widen_history();
  void held_volumes();
  // the bridge work of the wet pair loop beside the inline cb_bridge_held (out of line on
  // purpose, see form_bridges_and_forces)
  __attribute__((noinline)) double protocol_bridge(int i, int j, double gap, const TypePair &tp,
                                                   cb_bridge *bridge);
  __attribute__((noinline)) double advance_bridge(int i, int j, double rsq, double gap,
                                                  const TypePair &tp, cb_bridge *bridge);
  void derive_bridges();
  void update_bridges();
  // BRIDGES false: a run without bridges (bridges_possible 0)
  template <bool BRIDGES> void form_bridges_and_forces();
  template <bool BRIDGES>
  void pair_force(const AtomArrays &a, const TypePair &tp, int i, int j, double delx,
                  double dely, double delz, double rsq, double r, double gap, double capillary,
                  double *history, int &touch, int history_update);
  void exchange_liquid();
  void check_periodic_images();
  void check_timestep();
  void radius_ranges();
  double max_rupture(int itype, int jtype, double vol) const;
  double pair_cutoff(int itype, int jtype);
  double *find_history(int i, int j, double *negate);
  void parse_coeff(int ilo, int ihi, int jlo, int jhi, int narg, char **arg);
};

}    // namespace LAMMPS_NS

#endif
#endif
