/* capbridge_liggghts_tally.h — `tally on` of `cohesion capillary`: the per-atom output
 * bridgedLiquid (half of each pair bridge's liquid, all of a wall bridge's: the wall holds
 * none) and bridgeCount (one count per bridge end), made again in every updating pass.
 *
 * Part of capbridge (lammps_pair/liggghts/). Compiled inside LIGGGHTS: C++98 and C++11.
 */
#ifndef CAPBRIDGE_LIGGGHTS_TALLY_H_
#define CAPBRIDGE_LIGGGHTS_TALLY_H_

#include "capbridge_liggghts_liquid.h"

#include "fix_property_atom.h"
#include "modify.h"

namespace capbridge_liggghts {

class Tally {
  public:
    Tally() : bridged_(NULL), count_(NULL) {}

    /* At the pair_style command and at every init (so that dumps and computes defined
     * before the first run can refer to them). */
    void connect(LAMMPS_NS::Modify *modify)
    {
        bridged_ = internal_fix(modify, "bridgedLiquid", "no");
        count_ = internal_fix(modify, "bridgeCount", "no");
    }

    /* The start of an updating pass: local and ghost atoms cleared. */
    void begin(const int nall)
    {
        double *bridged = bridged_->vector_atom, *count = count_->vector_atom;
        for (int k = 0; k < nall; ++k) bridged[k] = count[k] = 0.0;
    }

    /* A pair's bridge (j -1: a ghost, counted by its own rank); ends 0 adds liquid only. */
    void pair(const int i, const int j, const double volume, const double ends = 1.0)
    {
        double *bridged = bridged_->vector_atom, *count = count_->vector_atom;
        bridged[i] += 0.5 * volume;
        count[i] += ends;
        if (j >= 0) {
            bridged[j] += 0.5 * volume;
            count[j] += ends;
        }
    }

    /* A wall bridge: all its liquid is its grain's, one end. */
    void wall(const int i, const double volume, const double ends)
    {
        bridged_->vector_atom[i] += volume;
        count_->vector_atom[i] += ends;
    }

  private:
    LAMMPS_NS::FixPropertyAtom *bridged_, *count_;
};

} /* namespace capbridge_liggghts */

#endif /* CAPBRIDGE_LIGGGHTS_TALLY_H_ */
