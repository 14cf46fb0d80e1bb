/* capbridge_liggghts_liquid.h — the liquid account of `cohesion capillary` under Protocols
 * 1, 2 and 3.
 *
 * Part of capbridge (lammps_pair/liggghts/). Compiled inside LIGGGHTS: C++98 and C++11.
 *
 * The protocols conserve the liquid (free liquid of the particles + the bridges) within a run.
 * What changes it comes from outside the model, and LIGGGHTS says nothing about it: atoms
 * lost from the box (thermo_modify lost ignore) or deleted, free liquid set between runs,
 * atoms renumbered, or a pair_style issued again (a new contact history: every bridge and
 * its liquid gone).  The account counts the liquid in a census at the setup of every run and
 * at every re-neighboring (when atoms can have left or come), and warns with the amount:
 *   - at setup, when the total differs from the last census (of the last run);
 *   - within a run, when particles are gone since the last census: how many, and the
 *     liquid that left with them (their free liquid and their bridges').
 *
 * Where the last total is kept: a pair_style issued again deletes the pair, its models and
 * their members, and fix contacthistory, but not the fixes a model added.  The last total
 * therefore lives in a fix property/global of its own (ID capillaryLiquidTotal, values:
 * total liquid, number of particles), which the next instance of the model finds.  A static
 * variable would survive `clear` (a stale total compared with a new system), a fix does not.
 * The fix is not written to restart files: the first run after read_restart has no last total.
 *
 * Atoms that came since the last census (insertion fixes, create_atoms) are told from the
 * others by a per-atom mark (fix property/atom capillaryCounted, 0 for a new atom), so that
 * their liquid is not taken for a loss: lost = N_last + N_new - N, and the liquid that left
 * = total_last + liquid_new - total.
 */
#ifndef CAPBRIDGE_LIGGGHTS_LIQUID_H_
#define CAPBRIDGE_LIGGGHTS_LIQUID_H_

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_property_atom.h"
#include "fix_property_global.h"
#include "modify.h"
#include "pointers.h"
#include "update.h"

#include <mpi.h>
#include <cmath>
#include <cstdio>

namespace capbridge_liggghts {

/* A per-atom scalar of the model (fix property/atom NAME, default 0), found or created;
 * `comm_ghost` "yes" sends it to ghost atoms, `restart` "yes" writes it to restart files
 * (read back into the fix of the same name the model makes after read_restart). */
inline LAMMPS_NS::FixPropertyAtom *internal_fix(LAMMPS_NS::Modify *modify, const char *name,
                                                const char *comm_ghost,
                                                const char *restart = "no")
{
    LAMMPS_NS::Fix *fix = modify->find_fix_property(name, "property/atom", "scalar", 0, 0,
                                                    "cohesion model capillary", false);
    if (!fix) {
        const char *args[9] = {name, "all", "property/atom", name, "scalar",
                               restart, comm_ghost, "no", "0."};
        modify->add_fix(9, const_cast<char **>(args));
        fix = modify->find_fix_property(name, "property/atom", "scalar", 0, 0,
                                        "cohesion model capillary");
        // its values are set (0) for every atom already; without this, the first
        // run's setup would reset them after the setup force pass (Modify::setup)
        fix->just_created = 0;
    }
    return static_cast<LAMMPS_NS::FixPropertyAtom *>(fix);
}

/* LIGGGHTS sets the default values of a fix property/atom created since the last run in
 * Modify::setup, i.e. after the setup force pass, where the model may already have written
 * it (Protocol 2's free liquid taken, Protocol 1's bridges given to a new wall's contact
 * history).  Do the same initialisation now, before that pass (the condition is
 * Modify::setup's), so that the reset there does not undo the pass. */
inline void initialise_now(LAMMPS_NS::Atom *atom, LAMMPS_NS::Fix *fix)
{
    if (fix->recent_restart || !fix->just_created || !fix->create_attribute) return;
    fix->just_created = 0;
    fix->pre_set_arrays();
    const int *mask = atom->mask;
    for (int i = 0; i < atom->nlocal; ++i)
        if (mask[i] & fix->groupbit) fix->set_arrays(i);
}

class LiquidAccount : protected LAMMPS_NS::Pointers {
  public:
    explicit LiquidAccount(LAMMPS_NS::LAMMPS *lmp)
        : Pointers(lmp), last_(NULL), counted_(NULL), had_setup_(false), bridged_(0.0),
          new_atoms_(0.0), new_liquid_(0.0), count_last_(0.0), total_last_(0.0),
          lost_atoms_(0.0), lost_liquid_(0.0), reported_atoms_(0.0)
    {
    }

    /* At the pair_style command: the fixes exist from then on (a new fix property/global
     * gets its "none yet" values; values_recomputed is what the model reads and writes). */
    void create()
    {
        if (!find_last()) {
            const char *args[7] = {"capillaryLiquidTotal", "all", "property/global",
                                   "capillaryLiquidTotal", "vector", "-1", "0"};
            modify->add_fix(7, const_cast<char **>(args));
            LAMMPS_NS::FixPropertyGlobal *fix = find_last();
            fix->vector_modify(0, -1.0);
            fix->vector_modify(1, 0.0);
        }
        counted_ = internal_fix(modify, "capillaryCounted", "no");
    }

    /* At the init of a run (the fixes may have been deleted and made again since). */
    void connect()
    {
        last_ = find_last();
        if (!last_)
            error->all(FLERR, "cohesion model capillary: fix capillaryLiquidTotal, which keeps "
                              "the liquid of the last run, was deleted; do not unfix it");
        counted_ = internal_fix(modify, "capillaryCounted", "no");
    }

    /* The start of a census pass (setup, re-neighboring): marks the atoms, counts the new. */
    void begin(const double *free_liquid)
    {
        bridged_ = 0.0;
        new_atoms_ = new_liquid_ = 0.0;
        double *counted = counted_->vector_atom;
        for (int i = 0; i < atom->nlocal; ++i) {
            if (counted[i] == 0.0) {
                new_atoms_ += 1.0;
                new_liquid_ += free_liquid[i];
                counted[i] = 1.0;
            }
        }
    }

    /* a bridge's liquid in this rank's count: half for each end it owns */
    void add_bridge(const bool j_local, const double volume)
    {
        bridged_ += j_local ? volume : 0.5 * volume;
    }

    /* The end of a census pass, after the pass's transitions (collective). */
    void end(const double *free_liquid)
    {
        double local[4] = {bridged_, (double)atom->nlocal, new_atoms_, new_liquid_};
        for (int i = 0; i < atom->nlocal; ++i) local[0] += free_liquid[i];
        double all[4] = {0.0, 0.0, 0.0, 0.0};
        MPI_Allreduce(local, all, 4, MPI_DOUBLE, MPI_SUM, world);
        const double total = all[0], count = all[1];
        if (update->setupflag)
            compare_with_last_run(total, count);
        else
            count_losses(total, count, all[2], all[3]);
        had_setup_ = true;
        count_last_ = count;
        total_last_ = total;
        last_->vector_modify(0, total);
        last_->vector_modify(1, count);
    }

  private:
    LAMMPS_NS::FixPropertyGlobal *find_last()
    {
        return static_cast<LAMMPS_NS::FixPropertyGlobal *>(modify->find_fix_property(
            "capillaryLiquidTotal", "property/global", "vector", 2, 0,
            "cohesion model capillary", false));
    }

    void compare_with_last_run(const double total, const double count)
    {
        lost_atoms_ = lost_liquid_ = reported_atoms_ = 0.0;
        const double last = last_->compute_vector_modified(0);
        const double last_count = last_->compute_vector_modified(1);
        const double change = total - last;
        if (!(last > 0.0) || !(std::fabs(change) > 1e-9 * last) || comm->me != 0) return;
        // a new instance of the model finding the total of another: pair_style issued again
        const char *why = had_setup_
            ? "free liquid set, atoms created, deleted or lost with their liquid, or atom IDs "
              "renumbered (delete_atoms with compress yes), which scrambles the bridges of the "
              "renumbered atoms"
            : "pair_style was issued again: its new contact history has none of the last "
              "run's bridges, and their liquid is gone (give pair_style once, before the "
              "first run), or free liquid set, atoms created, deleted or lost";
        char text[640];
        snprintf(text, sizeof text,
                 "cohesion model capillary: the liquid changed by %.17g (%+.3g of it) since "
                 "the last run (%.6g m^3 in %.0f particles then, %.6g m^3 in %.0f now): %s",
                 change, change / last, last, last_count, total, count, why);
        error->warning(FLERR, text);
    }

    /* Particles gone since the last census: reported at the first loss of a run and again
     * whenever the number lost in the run has doubled since the last report (a hopper that
     * lets particles out of the box on purpose gets a few lines, not one per step). */
    void count_losses(const double total, const double count, const double new_atoms,
                      const double new_liquid)
    {
        const double lost = count_last_ + new_atoms - count;
        if (!had_setup_ || !(lost > 0.5)) return;
        lost_atoms_ += lost;
        lost_liquid_ += total_last_ + new_liquid - total;
        if (lost_atoms_ < 2.0 * reported_atoms_) return;
        reported_atoms_ = lost_atoms_;
        if (comm->me != 0) return;
        char text[640];
        snprintf(text, sizeof text,
                 "cohesion model capillary: %.0f particles left the run by step " BIGINT_FORMAT
                 " (lost from the box, e.g. with thermo_modify lost ignore, or deleted), and "
                 "with them %.6g m^3 of liquid, their free liquid and their bridges' (%.3g "
                 "of all liquid); reported again when the number has doubled",
                 lost_atoms_, update->ntimestep, lost_liquid_,
                 lost_liquid_ / (total + lost_liquid_));
        error->warning(FLERR, text);
    }

    LAMMPS_NS::FixPropertyGlobal *last_;   // the last census: total liquid, particles
    LAMMPS_NS::FixPropertyAtom *counted_;  // 1 for an atom counted in a census, 0 if new
    bool had_setup_;                       // this instance has counted before
    double bridged_;                       // this rank's share of the bridges' liquid
    double new_atoms_, new_liquid_;        // this rank's new atoms and their free liquid
    double count_last_, total_last_;       // the last census of this instance
    double lost_atoms_, lost_liquid_;      // gone in this run
    double reported_atoms_;                // the number lost at the last report
};

} /* namespace capbridge_liggghts */

#endif /* CAPBRIDGE_LIGGGHTS_LIQUID_H_ */
