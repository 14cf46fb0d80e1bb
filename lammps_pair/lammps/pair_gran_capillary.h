/* -*- c++ -*- ----------------------------------------------------------
   capbridge — LAMMPS binding: pair style gran/capillary

   Linear spring-dashpot contact (Richefeu et al. 2007, eqs. 2-3), tangential spring
   with history and a Coulomb limit (eq. 12), and the capillary (liquid-bridge) force of
   the capbridge core (capbridge.h) between finite-size spheres.  The bridge state of
   every pair lives in the pair history (fix NEIGH_HISTORY); what fix capillary/liquid
   reaches of it is the base CapillaryBridges (capillary_bridges.h).  The class is defined
   over several files, one job each (see pair_gran_capillary.cpp).  See
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
#include "capillary_bridges.h"
#include "capillary_liquid_mode.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixCapillaryLiquid;

class PairGranCapillary : public Pair, public CapillaryBridges {
 public:
  // the restart settings' format: 2 (0 and 1 were the friction setting of earlier files)
  enum { SETTINGS_FORMAT = 2 };
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
  double atom2cut(int) override;
  double radii2cut(double, double) override;

 protected:
  std::vector<std::string> coeff_text;    // the pair_coeff arguments, for restart files
  std::vector<cb_law *> laws;             // prepared laws, shared by type pairs
  const cb_law *law(int itype, int jtype) const { return type_pair(itype, jtype).law; }
  // The per-atom arrays of one force evaluation, read once per compute() (through `atom` the
  // compiler must reload them after every force store).
  struct AtomArrays {
    double **x, **v, **f, **omega, **torque;
    double *radius, *rmass;
    int *mask;
    int nlocal, newton_pair;
  };
  // One pair's geometry, computed once by the pair loop and passed on by value: read from
  // the atom arrays in each step, the radii were loaded again after every force store
  struct PairGeometry {
    double del[3];        // x_i - x_j
    double rsq, r, gap;   // |del|^2, |del|, r - radi - radj
    double radi, radj;
  };

  cb_dashpot_rule dashpot;    // approach (Richefeu 2007 eq. 3), both, repulsive
  double dt;
  int freeze_group_bit;

  class FixDummy *fix_dummy;
  FixCapillaryLiquid *fix_liquid;
  int liquid_mode, liquid_groupbit;
  int bridges_possible;    // 0: no type pair can form a bridge in this run and none exists
                           // (init_style)
  int viscous_possible;    // 1: a type pair's law has a viscosity (init_style)
  std::vector<double> held_volume;    // per type: the largest bridge that exists (init_style)

  int dt_warned, reach_warned;
  // check_timestep(): its reduction buffers, and per type pair the limit and the capillary
  // stiffness bound (timestep_bound) with the two volumes and the mass they are for
  // (timestep_key, KEY_SIZE each)
  enum { KEY_SIZE = 3, BOUND_SIZE = 4 };
  std::vector<double> timestep_local, timestep_global, timestep_key, timestep_bound;
  int neighprev;

  void allocate();
  void find_liquid();
  // the bridge volume the neighbor reach of a type pair is built for
  double design_volume(int itype, int jtype) const;
  int counted(int i, int j) const;
  int wet_pair(int i, int j, const TypePair &tp) const;
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
  [[noreturn]] void corrupt_bridge(int i, int j, const cb_bridge *bridge);
  // BRIDGES false: a run without bridges (bridges_possible 0)
  // VISCOUS false: no type pair has a viscous law (viscous_possible 0)
  // (each its own function: inlined into compute() together, the three loops exceeded
  // GCC's growth limits and lost the inlining of the held-bridge path, +2.5 % instructions)
  template <bool BRIDGES, bool VISCOUS> __attribute__((noinline)) void form_bridges_and_forces();
  // the pair loop's steps, inline in it (as one function they were: its registers, its
  // instruction count)
  AtomArrays atom_arrays() const;
  __attribute__((always_inline)) inline static int skip_apart(const AtomArrays &a, int i,
                                                               const int *jlist,
                                                               const int *touch, int jj,
                                                               int jnum);
  __attribute__((always_inline)) inline double bridge_capillary(int i, int j,
                                                                const PairGeometry &g,
                                                                const TypePair &tp,
                                                                cb_bridge *bridge,
                                                                int per_atom);
  template <bool BRIDGES, bool VISCOUS>
  void pair_force(const AtomArrays &a, const TypePair &tp, int i, int j, const PairGeometry &g,
                  double capillary, double *history, int &touch, int history_update);
  __attribute__((always_inline)) inline static double
  gap_rate_of(const AtomArrays &a, int i, int j, const PairGeometry &g, double rinv, double *vr);
  __attribute__((always_inline)) inline static void
  sliding_velocity(const AtomArrays &a, int i, int j, const PairGeometry &g, double rinv,
                   const double *vr, double *vtr);
  __attribute__((always_inline)) inline double
  contact_force(const AtomArrays &a, const TypePair &tp, int i, int j, const PairGeometry &g,
                double rinv, double *shear, int history_update, double *fs);
  double viscous_force(const AtomArrays &a, const TypePair &tp, int i, int j,
                       const PairGeometry &g, double rinv, double volume, double *fs);
  __attribute__((always_inline)) inline void apply_pair_force(const AtomArrays &a, int i, int j,
                                                              const PairGeometry &g, double rinv,
                                                              double ccel, const double *fs);
  void check_periodic_images();
  void check_timestep();
  void reduce_timestep_ranges();
  void timestep_limit(int i, int j, const double *key, double *bound) const;
  double normal_stiffness(int i, int j) const;
  void radius_ranges();
  void type_pair_reach(int itype, int jtype, double volume, double &design_rupture,
                       double &reach) const;
  double pair_cutoff(int itype, int jtype, double &design_rupture);
  double *find_history(int i, int j, double *negate);
  void parse_coeff(int ilo, int ihi, int jlo, int jhi, int narg, char **arg);
  int parse_contact(const std::string &where, int narg, char **arg, TypePair &tp);
  void parse_law(const std::string &where, int iarg, int narg, char **arg, cb_law &one,
                 std::string &spec, double &volume_one);
  int prepared_law(const std::string &where, const cb_law &one, const std::string &spec);
};

}    // namespace LAMMPS_NS

#endif
#endif
