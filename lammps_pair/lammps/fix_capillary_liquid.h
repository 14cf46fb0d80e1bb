/* -*- c++ -*- ----------------------------------------------------------
   capbridge — LAMMPS binding: fix capillary/liquid

   The liquid of pair style gran/capillary: fixed volume per bridge, or a total liquid
   (given, or from a water content) distributed by Richefeu et al. 2007's Protocol 1
   (every N steps), 2 or 3 (per-atom free liquid).  Global output vector: bridges,
   bridge coordination number, liquid in bridges, free liquid, total liquid, formations
   and ruptures since the fix was defined, relative change of the total.
   The fix owns the liquid (total, pool, free liquid per atom) and runs the protocols on the
   pair's bridges, which it reaches through CapillaryBridges (capillary_bridges.h); the
   class is defined in fix_capillary_liquid.cpp (command, schedule, output, restart) and
   capillary_protocols.cpp (the protocols).  See doc/fix_capillary_liquid.rst.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(capillary/liquid,FixCapillaryLiquid);
// clang-format on
#else

#ifndef LMP_FIX_CAPILLARY_LIQUID_H
#define LMP_FIX_CAPILLARY_LIQUID_H

#include "fix.h"

#include "capillary_liquid_mode.h"

#include <vector>

struct cb_law;
struct cb_bridge;

namespace LAMMPS_NS {

struct CapillaryBridges;
class FixCapillaryWall;

class FixCapillaryLiquid : public Fix {
 public:
  FixCapillaryLiquid(class LAMMPS *, int, char **);
  ~FixCapillaryLiquid() override;
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  void post_run() override;
  void pre_force(int) override;
  double compute_vector(int) override;
  int modify_param(int, char **) override;

  void write_restart(FILE *) override;
  void restart(char *) override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

  // ---- used by pair gran/capillary ----
  int mode;               // CapillaryLiquidMode
  double fixed_volume;    // mode fixed: the bridge volume (< 0: from pair_coeff)
  const char *mode_name() const { return capillary_liquid_mode_name(mode); }
  // the design volume of this run's neighbor reach, vmax: derived by the pair's init_style
  // (collective), read by its init_one and the fix's Protocol 1
  void derive_design_volume();
  double reach_volume() const;
  // Protocols 2, 3, phase 1 of a force evaluation (the pair's compute(), before its loop):
  // the bridges advanced, their released liquid handed to the atoms, the free liquid offered
  void offer_liquid();
  // its result per atom (owned and ghost), read by the pair loop: the liquid on offer to
  // each new contact, and Protocol 3's deposit for the bridge with best_partner
  double *offer, *deposit;
  tagint *best_partner;

 protected:
  class Pair *pair;              // pair style gran/capillary (its neighbor list)
  CapillaryBridges *bridges;     // its bridges (the same object)
  std::vector<FixCapillaryWall *> walls;    // the fixes capillary/wall: the walls' bridges
  double *free_liquid;           // Protocols 2, 3: free liquid per atom [m^3]; else nullptr
  int every;               // Protocol 1: every N steps; 0 = at every re-neighboring
  int start_free;          // Protocols 2, 3: start as free liquid (1) or as bridges (0)
  double remove_fraction;  // keyword remove or fix_modify remove: the share of the bridges
  bigint remove_seed;      // removed, and the seed of the draw
  int remove_pending;      // a removal is asked for: it acts at the next run's start
  int removing;            // 1 in the force evaluation that removes them
  double removed_count, removed_liquid;    // this rank's removals in it (pairs counted once)
  double water, liquid_density, liquid_given, vmax_given;

  // persistent state (global restart)
  double total_liquid;    // the liquid, fixed at the first run [m^3]; < 0 until then
  double vmax;            // the design volume of this run (derive_design_volume); < 0 before
  double pool;            // Protocol 1: liquid of broken bridges until the next distribution
  double alpha;           // the last Protocol 1 factor (V_b = alpha R_g^3)
  int started;            // the initial distribution is done
  bigint last_distribution;

  // output
  double values[8];
  double formed, ruptured;     // bridges formed, ruptured since the fix was defined
  double total_at_run_end;     // the total liquid at the end of the last run (< 0: none)
  int total_from_restart;      // total_liquid was read from a restart file, not yet checked
  bigint census_step;
  int census_valid, warned_nowhere, warned_reach;

  // per-atom scratch of phase 1 (owned + ghost), beside offer, deposit, best_partner
  int nmax_scratch;
  double *candidates, *released, *best_height;
  enum { COMM_REVERSE_SIZE = 4, COMM_FORWARD_SIZE = 3 };    // values an atom, each way

  int parse_fixed_volume(int narg, char **arg);
  void parse_keywords(int iarg, int narg, char **arg);
  void ensure_totals();
  void distribute(const char *why);
  void start_liquid();
  void ask_removal(const char *how, const char *share, const char *seed);
  void refuse_removal_without_bridges(const char *how);
  void begin_removal();
  void census();

  // capillary_protocols.cpp
  void grow_scratch();
  void destroy_scratch();
  void update_bridges();
  void advance_and_release(int i, int j, double rsq, double gap, cb_bridge *bridge);
  void release(int i, int j, double volume, double gap);
  int removal_chosen(long long id1, long long id2);
  void update_wall_bridges(FixCapillaryWall &wall);
  void remove_and_release(int i, int j, double gap, cb_bridge *bridge);
  void report_removal();
  void receive_at(int i, int j, double delz, double r);
  void exchange_liquid();
  void count_bridges(double *out);
  void collect_released();
  struct Protocol1Pairs;
  int protocol1(double total, double &alpha, double &largest_volume);
  void gather_candidates(Protocol1Pairs &mine);
  void gather_wall_candidates(FixCapillaryWall &wall, Protocol1Pairs &mine);
  int distribute_over_ranks(const Protocol1Pairs &mine, double total,
                            std::vector<double> &volumes, double *result);
  int distribute_on_root(const cb_law *law, const std::vector<double> &geometry,
                         const std::vector<tagint> &keys, double total,
                         std::vector<double> &volumes, double *result);
  void check_alpha(double alpha);
  void apply_volumes(const Protocol1Pairs &mine, const std::vector<double> &volumes);
};

}    // namespace LAMMPS_NS

#endif
#endif
