/* capbridge_liggghts_start.h — how the liquid of Protocols 2 and 3 starts in `cohesion
 * capillary`, and the half bonds: the keywords start, remove and remove_seed.
 *
 * Part of capbridge (lammps_pair/liggghts/). Compiled inside LIGGGHTS: C++98 and C++11.
 *
 *   liquid protocol2|protocol3 [start bridges|free] [remove F remove_seed S]
 * as LAMMPS's fix capillary/liquid has them (start bridges|free, remove F SEED):
 *   - start bridges (the default): the first updating pass distributes the liquid (the free
 *     liquid of fix property/atom freeLiquid) by Protocol 1 (capbridge_liggghts_protocol1.h),
 *     as `liquid protocol1` does at its first pass; Protocol 2 or 3 rules apply from then on.
 *     start free: the liquid stays with the particles as free liquid;
 *   - remove F (Richefeu 2007 §3.2 fig. 7, §4.2.2 fig. 12: samples "with two times less
 *     bonds ... obtained by removing half of the bonds", the water content kept): in that
 *     same pass each bridge that cb_bridge_removal_chosen(F, S, id_i, id_j) picks is removed
 *     (cb_bridge_remove: a removed pair that still overlaps keeps a mark and forms no bridge
 *     while that contact lasts), its liquid handed on as a broken bridge's; the model
 *     prints how many of how many, and their liquid.  The draw is a function of the seed
 *     and the two atom IDs: the same pairs on any number of ranks, and in LAMMPS.
 * The liquid starts once per simulation: a mark per particle (fix property/atom
 * capillaryStarted, written to restart files) says it has, so that a run after
 * read_restart, or a pair_style issued again, distributes and removes nothing again.
 */
#ifndef CAPBRIDGE_LIGGGHTS_START_H_
#define CAPBRIDGE_LIGGGHTS_START_H_

#include "capbridge.h"
#include "capbridge_liggghts_liquid.h"
#include "capbridge_liggghts_settings.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_property_atom.h"
#include "pointers.h"
#include "update.h"

#include <mpi.h>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace capbridge_liggghts {

inline bool check_start(const std::string &k, const std::string &v, std::string &why)
{
    static const char *const allowed[] = {"bridges", "free", NULL};
    return check_one_of(k, v, allowed, why);
}

/* `remove F`: the share of the bridges removed, 0 < F <= 1 */
inline bool check_remove(const std::string &k, const std::string &v, std::string &why)
{
    double x = 0.0;
    if (cb_parse_number(v.c_str(), &x) && x > 0.0 && x <= 1.0) return true;
    why = "cohesion model capillary: " + k + " '" + v +
          "': the share of the bridges removed must be > 0 and <= 1 (0.5: half of them)";
    return false;
}

/* `remove_seed S`: a whole number >= 1 */
inline bool check_seed(const std::string &k, const std::string &v, std::string &why)
{
    char *end = NULL;
    errno = 0;
    const long long n = std::strtoll(v.c_str(), &end, 10);
    if (!v.empty() && *end == '\0' && errno == 0 && n >= 1) return true;
    why = "cohesion model capillary: " + k + " '" + v +
          "' must be a whole number >= 1 (the seed of the draw of the removed bridges)";
    return false;
}

class LiquidStart : protected LAMMPS_NS::Pointers {
  public:
    explicit LiquidStart(LAMMPS_NS::LAMMPS *lmp)
        : Pointers(lmp), bridges(false), fraction_(0.0), seed_(0), mark_(NULL),
          started_(false), removing_(false), start_given_(false), remove_given_(false),
          seed_given_(false), removed_(0.0), kept_(0.0), removed_liquid_(0.0), total_(0.0)
    {
    }

    void register_settings(Settings &settings, const LAMMPS_NS::Input *input)
    {
        register_word(settings, "start", "bridges", &check_start, start_, &start_given_, input);
        register_word(settings, "remove", "0", &check_remove, remove_, &remove_given_, input);
        register_word(settings, "remove_seed", "0", &check_seed, seed_word_, &seed_given_,
                      input);
    }

    /* After the keywords are read: the values, and the mark of the start. */
    void post_settings(const std::string &liquid)
    {
        bridges = (liquid == "protocol2" || liquid == "protocol3") && start_ == "bridges";
        fraction_ = remove_given_ ? std::atof(remove_.c_str()) : 0.0;
        seed_ = seed_given_ ? std::strtoull(seed_word_.c_str(), NULL, 10) : 0;
        if (bridges) mark_ = internal_fix(modify, "capillaryStarted", "no", "yes");
    }

    /* At init (collective): the refusals of LAMMPS's fix.  Not in post_settings: LIGGGHTS
     * calls it also after a keyword it could not read, whose own error would follow. */
    void check(const std::string &liquid)
    {
        const bool protocol23 = liquid == "protocol2" || liquid == "protocol3";
        std::string why;
        if (start_given_ && !protocol23)
            why = "keyword 'start' applies to 'liquid protocol2' and 'protocol3' only "
                  "(Protocol 1 distributes the liquid at its first pass anyway)";
        else if (remove_given_ && !protocol23)
            why = std::string("keyword 'remove' applies to 'liquid protocol2' and 'protocol3' "
                              "only (") +
                  (liquid == "protocol1" ? "Protocol 1 gives every eligible pair a bridge "
                                           "again at its next distribution)"
                                         : "fixed volumes keep no water content for the "
                                           "removed bridges)");
        else if (remove_given_ && !bridges)
            why = "keyword 'remove' needs 'start bridges' (with 'start free' no bridge exists "
                  "when the liquid starts)";
        else if (remove_given_ != seed_given_)
            why = remove_given_ ? "keyword 'remove' needs 'remove_seed S' (a whole number >= "
                                  "1, the seed of the draw of the removed bridges)"
                                : "keyword 'remove_seed' applies with 'remove F' only";
        if (!why.empty()) error->all(FLERR, ("cohesion model capillary: " + why).c_str());
    }

    /* At the start of an updating pass (collective at setup): does the liquid start now
     * (start bridges: the setup of the first run whose particles have free liquid, so
     * that free liquid set after a `run 0`, as LIGGGHTS needs, is distributed)? */
    bool due(const double *free_liquid)
    {
        if (!bridges || started_ || !update->setupflag) return false;
        const double *mark = mark_->vector_atom;
        double mine[2] = {0.0, 0.0}, all[2] = {0.0, 0.0};  // marked particles, free liquid
        for (int i = 0; i < atom->nlocal; ++i) {
            if (mark[i] != 0.0) mine[0] += 1.0;
            mine[1] += free_liquid[i];
        }
        MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_SUM, world);
        if (all[0] == 0.0 && !(all[1] > 0.0)) return false;  // no liquid yet
        started_ = true;
        if (all[0] > 0.0) {
            if (fraction_ > 0.0 && comm->me == 0)
                error->warning(FLERR, "cohesion model capillary: keyword 'remove' acts when "
                                      "the liquid starts, and it has started (a restart file "
                                      "or an earlier pair_style): no bridge is removed");
            return false;
        }
        double *marks = mark_->vector_atom;
        for (int i = 0; i < atom->nlocal; ++i) marks[i] = 1.0;
        removing_ = fraction_ > 0.0;
        removed_ = kept_ = removed_liquid_ = 0.0;
        return true;
    }

    /* The total liquid the start distributed (for the report). */
    void set_total(const double total) { total_ = total; }

    /* In the pass that removes: is the bridge of atoms with these IDs removed? */
    bool removing() const { return removing_; }
    bool chosen(const int id_i, const int id_j) const
    {
        int chosen = 0;
        const cb_status status = cb_bridge_removal_chosen(fraction_, seed_, id_i, id_j, &chosen);
        if (status != CB_OK) {
            char text[300];
            snprintf(text, sizeof text,
                     "cohesion model capillary: remove %g (remove_seed %llu) for particles %d "
                     "and %d: %s",
                     fraction_, seed_, id_i, id_j, cb_status_message(status));
            error->one(FLERR, text);
        }
        return chosen != 0;
    }

    /* a bridge that existed after the start, counted on one rank (`once`); `volume` > 0:
     * removed with that liquid */
    void count(const bool once, const double volume)
    {
        if (!once) return;
        if (volume > 0.0) {
            removed_ += 1.0;
            removed_liquid_ += volume;
        } else {
            kept_ += 1.0;
        }
    }

    /* The end of the pass that removed (collective): the log line, as LAMMPS's fix's. */
    void report(const std::string &liquid)
    {
        removing_ = false;
        double local[3] = {removed_, kept_, removed_liquid_}, all[3] = {0.0, 0.0, 0.0};
        MPI_Allreduce(local, all, 3, MPI_DOUBLE, MPI_SUM, world);
        if (comm->me != 0) return;
        const double bridges_before = all[0] + all[1];
        char text[600];
        snprintf(text, sizeof text,
                 "cohesion model capillary %s: removed %.0f of %.0f bridges (remove %g "
                 "remove_seed %llu: %.4f of them), holding %.17g of the liquid %.17g, handed "
                 "on as the liquid of broken bridges\n",
                 liquid.c_str(), all[0], bridges_before, fraction_, seed_,
                 bridges_before > 0.0 ? all[0] / bridges_before : 0.0, all[2], total_);
        if (screen) fputs(text, screen);
        if (logfile) fputs(text, logfile);
    }

    bool bridges;  // start bridges under Protocol 2 or 3

  private:
    std::string start_, remove_, seed_word_;
    double fraction_;
    unsigned long long seed_;
    LAMMPS_NS::FixPropertyAtom *mark_;  // per particle: 1 once the liquid has started
    bool started_;                      // this instance has asked (due) already
    bool removing_;                     // this pass removes
    bool start_given_, remove_given_, seed_given_;
    double removed_, kept_, removed_liquid_;  // this rank's count in the removing pass
    double total_;
};

} /* namespace capbridge_liggghts */

#endif /* CAPBRIDGE_LIGGGHTS_START_H_ */
