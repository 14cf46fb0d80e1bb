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
 *
 * Removing later (Richefeu 2007 fig. 7: the half-bonds sample has the all-bonds sample's
 * configuration at the start of shearing, i.e. after the consolidation), asked for between
 * two runs the way LIGGGHTS changes a model parameter:
 *   fix ID all property/global capillaryRemove vector F S
 * At the setup pass of each run, once the liquid has started (start bridges: the start
 * distribution done, in that pass or before; start free: at any run), the same removal as
 * keyword remove (F, S) acts in that pass, once per simulation: a second mark per particle
 * (capillaryRemoved, written to restart files) is set at the end of the pass that removed,
 * by either way; a run whose particles carry it removes nothing and says so in one line.
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
#include "fix_property_global.h"
#include "modify.h"
#include "pointers.h"
#include "update.h"

#include <mpi.h>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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
        : Pointers(lmp), bridges(false), protocol23_(false), fraction_(0.0), seed_(0),
          mark_(NULL), removed_mark_(NULL), started_(false), removing_(false),
          start_given_(false), remove_given_(false), seed_given_(false), requested_(false),
          asked_(false), said_done_(false), request_fraction_(0.0), request_seed_(0),
          removed_(0.0), kept_(0.0), removed_liquid_(0.0), kept_liquid_(0.0),
          free_at_start_(0.0), total_(0.0)
    {
    }

    void register_settings(Settings &settings, const LAMMPS_NS::Input *input)
    {
        register_word(settings, "start", "bridges", &check_start, start_, &start_given_, input);
        register_word(settings, "remove", "0", &check_remove, remove_, &remove_given_, input);
        register_word(settings, "remove_seed", "0", &check_seed, seed_word_, &seed_given_,
                      input);
    }

    /* start, remove or remove_seed given */
    bool given_any() const { return start_given_ || remove_given_ || seed_given_; }

    /* After the keywords are read: the values, and the mark of the start. */
    void post_settings(const std::string &liquid)
    {
        protocol23_ = liquid == "protocol2" || liquid == "protocol3";
        bridges = protocol23_ && start_ == "bridges";
        fraction_ = remove_given_ ? std::atof(remove_.c_str()) : 0.0;
        seed_ = seed_given_ ? std::strtoull(seed_word_.c_str(), NULL, 10) : 0;
        if (bridges) mark_ = internal_fix(modify, "capillaryStarted", "no", "yes");
        // the removal is done once per simulation, by keyword or request: marked per particle
        if (protocol23_) removed_mark_ = internal_fix(modify, "capillaryRemoved", "no", "yes");
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
        find_request(liquid);
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
        if (fraction_ > 0.0) begin_removal(false, 0.0);
        return true;
    }

    /* At the start of an updating pass, after due() (collective at setup): the removal asked
     * for by fix capillaryRemove acts in this pass, if the liquid has started (start
     * bridges) and no removal has been done in this simulation (the particles' mark). */
    void ask(const double *free_liquid)
    {
        if (!requested_ || !update->setupflag || removing_ || (bridges && !started_)) return;
        const double *mark = removed_mark_->vector_atom;
        double mine[2] = {0.0, 0.0}, all[2] = {0.0, 0.0};  // marked particles, free liquid
        for (int i = 0; i < atom->nlocal; ++i) {
            if (mark[i] != 0.0) mine[0] += 1.0;
            mine[1] += free_liquid[i];
        }
        MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_SUM, world);
        if (all[0] > 0.0) {
            if (!said_done_ && comm->me == 0)
                say("cohesion model capillary: fix capillaryRemove asks for a removal, and this "
                    "simulation has removed bridges once already (its particles carry the mark "
                    "capillaryRemoved, kept in restart files): no bridge is removed; the "
                    "removal acts once per simulation\n");
            said_done_ = true;
            return;
        }
        fraction_ = request_fraction_;
        seed_ = request_seed_;
        begin_removal(true, all[1]);
    }

    /* The total liquid the start distributed (for the report). */
    void set_total(const double total) { total_ = total; }

    /* In the pass that removes: is the bridge of atoms with these IDs removed? */
    bool removing() const { return removing_; }
    bool chosen(const long long id_i, const long long id_j) const
    {
        int chosen = 0;
        const cb_status status = cb_bridge_removal_chosen(fraction_, seed_, id_i, id_j, &chosen);
        if (status != CB_OK) {
            char text[300];
            snprintf(text, sizeof text,
                     "cohesion model capillary: %s %g (%s %llu) for particles (or a wall: "
                     "negative) %lld and %lld: %s",
                     asked_ ? "fix capillaryRemove" : "remove", fraction_,
                     asked_ ? "seed" : "remove_seed", seed_, id_i, id_j,
                     cb_status_message(status));
            error->one(FLERR, text);
        }
        return chosen != 0;
    }

    /* a bridge that existed at the start of the removing pass, of liquid `held`, counted on
     * one rank (`once`); `volume` > 0: removed with that liquid */
    void count(const bool once, const double volume, const double held)
    {
        if (!once) return;
        if (volume > 0.0) {
            removed_ += 1.0;
            removed_liquid_ += volume;
        } else {
            kept_ += 1.0;
            kept_liquid_ += held;
        }
    }

    /* The end of the pass that removed (collective): the log line, as LAMMPS's fix's. */
    void report(const std::string &liquid)
    {
        removing_ = false;
        double local[4] = {removed_, kept_, removed_liquid_, kept_liquid_};
        double all[4] = {0.0, 0.0, 0.0, 0.0};
        MPI_Allreduce(local, all, 4, MPI_DOUBLE, MPI_SUM, world);
        const double bridges_before = all[0] + all[1];
        if (asked_ && bridges_before == 0.0) {
            // no bridge yet (start free before any contact, or a run 0 before the liquid):
            // the request waits for a run whose setup finds bridges, as LAMMPS refuses a
            // fix_modify remove whose next run would have none
            if (comm->me == 0)
                say("cohesion model capillary: fix capillaryRemove: no bridge exists at this "
                    "run's setup: nothing removed; the removal waits for a run that has "
                    "bridges\n");
            return;
        }
        double *marks = removed_mark_->vector_atom;  // done: once per simulation
        for (int i = 0; i < atom->nlocal; ++i) marks[i] = 1.0;
        if (comm->me != 0) return;
        // the request's total: the free liquid and the bridges' at the start of the pass
        const double total = asked_ ? free_at_start_ + all[2] + all[3] : total_;
        char text[700];
        snprintf(text, sizeof text,
                 "cohesion model capillary %s: removed %.0f of %.0f bridges (%s %g %s %llu: "
                 "%.4f of them), holding %.17g of the liquid %.17g, handed on as the liquid "
                 "of broken bridges%s\n",
                 liquid.c_str(), all[0], bridges_before,
                 asked_ ? "fix capillaryRemove" : "remove", fraction_,
                 asked_ ? "seed" : "remove_seed", seed_,
                 bridges_before > 0.0 ? all[0] / bridges_before : 0.0, all[2], total,
                 asked_ ? " (asked for by fix capillaryRemove, at this run's setup)" : "");
        say(text);
    }

    bool bridges;  // start bridges under Protocol 2 or 3

  private:
    /* the removing pass begins: by the request (`asked`, the free liquid `free` at its
     * start) or by keyword remove */
    void begin_removal(const bool asked, const double free)
    {
        removing_ = true;
        asked_ = asked;
        free_at_start_ = free;
        removed_ = kept_ = removed_liquid_ = kept_liquid_ = 0.0;
    }

    /* At init: the request fix capillaryRemove (F S), if defined, and its refusals. */
    void find_request(const std::string &liquid)
    {
        requested_ = false;
        LAMMPS_NS::Fix *fix = NULL;
        static const char *const styles[] = {"vector", "scalar", "matrix", NULL};
        for (int k = 0; styles[k] && !fix; ++k)
            fix = modify->find_fix_property("capillaryRemove", "property/global", styles[k], 0,
                                            0, "cohesion model capillary", false);
        if (!fix || std::strcmp(fix->style, "property/global") != 0) return;
        const char *what = "cohesion model capillary: fix property/global capillaryRemove "
                           "(the removal request, 'vector F S')";
        char text[700];
        std::string why;
        if (!protocol23_)
            why = std::string("applies to 'liquid protocol2' and 'protocol3' only (") +
                  (liquid == "protocol1" ? "Protocol 1 gives every eligible pair a bridge "
                                           "again at its next distribution)"
                                         : "fixed volumes keep no water content for the "
                                           "removed bridges)");
        else if (remove_given_)
            why = "and keyword 'remove' are both given: give the removal once (keyword "
                  "'remove': when the liquid starts; the request: at the next run's setup)";
        else if (!fix->vector_flag || fix->size_vector != 2)
            why = "must be a vector of 2 values, F S (the share of the bridges removed, and "
                  "the seed of the draw)";
        if (!why.empty()) {
            snprintf(text, sizeof text, "%s %s", what, why.c_str());
            error->all(FLERR, text);
        }
        LAMMPS_NS::FixPropertyGlobal *values = static_cast<LAMMPS_NS::FixPropertyGlobal *>(fix);
        const double f = values->compute_vector(0), s = values->compute_vector(1);
        if (!(f > 0.0 && f <= 1.0)) {
            snprintf(text, sizeof text, "%s: F = %g; the share of the bridges removed must be "
                     "> 0 and <= 1 (0.5: half of them)", what, f);
            error->all(FLERR, text);
        }
        if (!(s >= 1.0 && s <= 9007199254740992.0 && s == std::floor(s))) {
            snprintf(text, sizeof text, "%s: S = %.17g; the seed of the draw must be a whole "
                     "number >= 1", what, s);
            error->all(FLERR, text);
        }
        requested_ = true;
        request_fraction_ = f;
        request_seed_ = (unsigned long long)s;
    }

    void say(const char *text)
    {
        if (screen) fputs(text, screen);
        if (logfile) fputs(text, logfile);
    }

    std::string start_, remove_, seed_word_;
    bool protocol23_;                   // liquid protocol2 or protocol3
    double fraction_;                   // the removal of this pass: F, S
    unsigned long long seed_;
    LAMMPS_NS::FixPropertyAtom *mark_;  // per particle: 1 once the liquid has started
    LAMMPS_NS::FixPropertyAtom *removed_mark_;  // per particle: 1 once bridges were removed
    bool started_;                      // the liquid has started (start bridges)
    bool removing_;                     // this pass removes
    bool start_given_, remove_given_, seed_given_;
    bool requested_;                    // fix capillaryRemove is defined (this run's init)
    bool asked_;                        // this removal is the request's
    bool said_done_;                    // the line "removed once already" was printed
    double request_fraction_;
    unsigned long long request_seed_;
    double removed_, kept_, removed_liquid_, kept_liquid_;  // this rank's count in the pass
    double free_at_start_;              // the request's pass: free liquid at its start
    double total_;                      // keyword remove: the liquid the start distributed
};

} /* namespace capbridge_liggghts */

#endif /* CAPBRIDGE_LIGGGHTS_START_H_ */
