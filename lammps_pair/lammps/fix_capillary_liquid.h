/* -*- c++ -*- ----------------------------------------------------------
   capbridge — LAMMPS binding: fix capillary/liquid

   The liquid of pair style gran/capillary: fixed volume per bridge, or a total liquid
   (given, or from a water content) distributed by Richefeu et al. 2007's Protocol 1
   (every N steps), 2 or 3 (per-atom free liquid).  Global output vector: bridges,
   bridge coordination number, liquid in bridges, free liquid, total liquid, formations
   and ruptures since the fix was defined, relative change of the total.
   See doc/fix_capillary_liquid.rst.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(capillary/liquid,FixCapillaryLiquid);
// clang-format on
#else

#ifndef LMP_FIX_CAPILLARY_LIQUID_H
#define LMP_FIX_CAPILLARY_LIQUID_H

#include "fix.h"

namespace LAMMPS_NS {

class PairGranCapillary;

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
  double memory_usage() override;

  // ---- used by pair gran/capillary ----
  int mode;               // PairGranCapillary::LIQUID_*
  double fixed_volume;    // mode fixed: the bridge volume (< 0: from pair_coeff)
  double *free_liquid;    // Protocols 2, 3: free liquid per atom [m^3]; else nullptr
  const char *mode_name() const;
  double design_volume();    // the largest bridge volume the neighbor reach is built for

 protected:
  PairGranCapillary *pair;
  int every;               // Protocol 1: every N steps; 0 = at every re-neighboring
  int start_free;          // Protocols 2, 3: start as free liquid (1) or as bridges (0)
  double water, liquid_density, liquid_given, vmax_given;

  // persistent state (global restart)
  double total_liquid;    // the liquid, fixed at the first run [m^3]; < 0 until then
  double vmax;            // design volume in use; < 0 until computed
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

  void ensure_totals();
  void distribute(const char *why);
  void start_liquid();
  void census();
};

}    // namespace LAMMPS_NS

#endif
#endif
