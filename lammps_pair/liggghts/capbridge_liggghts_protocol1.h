/* capbridge_liggghts_protocol1.h — Richefeu 2007's Protocol 1 in `cohesion capillary`: the
 * homogeneous distribution of all liquid over the eligible pairs, over all ranks.
 *
 * Part of capbridge (lammps_pair/liggghts/). Compiled inside LIGGGHTS: C++98 and C++11.
 *
 * Protocol 1 (Richefeu 2007 §2.4, eqs. 13-14): V_b = alpha R^3, R = sqrt(R_i R_j), over every
 * pair whose gap does not exceed the rupture distance of the volume it would receive, alpha
 * fixed by sum V_b = V_liquid; "the liquid distribution should be updated regularly".  The
 * solution is the core's cb_protocol1_distribute; this file gathers the pairs and scatters
 * the volumes, at the start of a pass, before LIGGGHTS's pair loop reads the bridges:
 *   - each rank takes from the pair's neighbor list every pair LIGGGHTS visits (r^2 <
 *     contact_distance_factor^2 (R1 + R2)^2, the pair loop's own test: a candidate, but
 *     for the pair of a removed bridge still in contact, cb_bridge_removed_in_contact) and
 *     every pair that holds a bridge; with newton off a pair with a ghost comes from both
 *     owners.  Per pair: the two atom IDs, the radii (smaller first, as the model hands them
 *     to the core), the gap, whether it is a candidate, and its bridge's volume; per local
 *     atom: its ID and free liquid;
 *   - each wet primitive wall of a fix wall/gran with `cohesion capillary` (WallSource,
 *     capbridge_liggghts_pass.h) adds its grains as pairs of the grain (r, CB_PLANE: the core
 *     weighs a wall pair as the grain and its mirror image, R = r) and the wall's key
 *     (negative): the grains it will visit in this step, its own test for a candidate, their
 *     gaps now; a wall bridge is its grain's, so each comes from one rank;
 *   - rank 0 orders the pairs by their IDs and keeps each once, sums the liquid (bridges in
 *     that order, free liquid in the order of the atom IDs, compensated), solves eqs. 13-14
 *     with the core over the candidates in that order, and scatters the volumes back: the
 *     result depends on the configuration only, not on the number of ranks;
 *   - every rank sets the volumes into its pairs' histories (cb_bridge_set_volume; 0 makes a
 *     pair dry) and clears the free liquid of its atoms: all liquid is in bridges.
 * Between two distributions no bridge forms, and a broken bridge's liquid is kept by its two
 * particles as free liquid (split as under Protocol 2), which the next distribution collects:
 * the free liquid is LAMMPS's pool.  When no pair can hold the liquid, nothing changes (a
 * warning, once).
 */
#ifndef CAPBRIDGE_LIGGGHTS_PROTOCOL1_H_
#define CAPBRIDGE_LIGGGHTS_PROTOCOL1_H_

#include "capbridge.h"
#include "capbridge_liggghts_pass.h"
#include "capbridge_liggghts_reach.h"

#include "atom.h"
#include "comm.h"
#include "contact_model_constants.h"
#include "error.h"
#include "force.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_gran.h"
#include "pointers.h"
#include "update.h"

#include <mpi.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace capbridge_liggghts {

/* The walls in the pass: each wall's key (negative) and its grains. */
typedef std::vector<std::pair<long long, WallSource *> > WallSources;

/* Neumaier's compensated sum: the total liquid to a few roundings, whatever the count. */
class CompensatedSum {
  public:
    CompensatedSum() : sum_(0.0), correction_(0.0) {}
    void add(const double x)
    {
        const double t = sum_ + x;
        correction_ += std::fabs(sum_) >= std::fabs(x) ? (sum_ - t) + x : (x - t) + sum_;
        sum_ = t;
    }
    double value() const { return sum_ + correction_; }

  private:
    double sum_, correction_;
};

class Protocol1 : protected LAMMPS_NS::Pointers {
  public:
    explicit Protocol1(LAMMPS_NS::LAMMPS *lmp)
        : Pointers(lmp), every_(0), attempted_(false), warned_(false), last_step_(-1)
    {
    }

    void set_every(const int every) { every_ = every; }

    /* eqs. 13-14 solve for one alpha over all pairs: one law (the model builds one per
     * distinct contact angle of a pair of types, the mean of its two types') */
    void check_laws(const std::vector<cb_law> &laws, const std::string &what)
    {
        if (laws.size() == 1) return;
        std::string angles;
        for (size_t k = 0; k < laws.size(); ++k) {
            char degrees[32];
            snprintf(degrees, sizeof degrees, "%s%g", k ? ", " : "",
                     laws[k].contact_angle * 180.0 / M_PI);
            angles += degrees;
        }
        char text[900];
        snprintf(text, sizeof text,
                 "cohesion model capillary: %s needs one contact angle for all "
                 "pairs (Richefeu 2007 eqs. 13-14: one alpha over all pairs, with one law), "
                 "but the atom types' contactAngle give their pairs %d contact angles (each "
                 "the mean of its two types'): %s degrees; give every atom type the same "
                 "contactAngle, or use liquid protocol2 or protocol3 with 'start free', "
                 "which take a contact angle per pair",
                 what.c_str(), (int)laws.size(), angles.c_str());
        error->all(FLERR, text);
    }

    /* In an updating pass: at the setup of this pair style's first run (also the first run
     * after read_restart: LIGGGHTS keeps no state of a contact model in restart files), then
     * every N steps, or at every re-neighboring (N = 0); once a step. */
    bool due() const
    {
        if (update->ntimestep == last_step_) return false;
        if (update->setupflag && !attempted_) return true;
        return every_ > 0 ? update->ntimestep % every_ == 0 : neighbor->ago == 0;
    }

    /* The distribution (collective): all liquid, free and in bridges, over the candidate
     * pairs and wall contacts with `law`; the design volume bounds the largest bridge it may
     * give.  Returns the liquid it distributed. */
    double distribute(const cb_law *law, const int history_offset, double *free_liquid,
                      const Reach &design, const WallSources &walls)
    {
        attempted_ = true;
        last_step_ = update->ntimestep;
        gather(law, history_offset);
        gather_walls(walls);
        std::vector<double> volumes(where_.size(), 0.0);
        double result[3] = {0.0, 0.0, 0.0};  // status, alpha, total
        solve_over_ranks(law, free_liquid, volumes, result);
        const cb_status status = (cb_status)(int)result[0];
        if (status == CB_ERR_LIQUID) {
            if (!warned_ && comm->me == 0)
                error->warning(FLERR, "cohesion model capillary: Protocol 1 found no pair that "
                                      "can hold the liquid; it stays with the particles as "
                                      "free liquid until a distribution succeeds (this "
                                      "warning is given once)");
            warned_ = true;
            return result[2];
        }
        if (status != CB_OK) {
            char text[300];
            snprintf(text, sizeof text,
                     "cohesion model capillary: Protocol 1 (cb_protocol1_distribute) failed "
                     "for %g m^3 of liquid: %s",
                     result[2], cb_status_message(status));
            error->all(FLERR, text);
        }
        check_design(result[1], design);
        apply(volumes, free_liquid);
        return result[2];
    }

  private:
    enum { PAIR_VALUES = 7 };  // low ID, high ID, ra, rb, gap, candidate, volume

    /* step 1: this rank's pairs and free liquid */
    void gather(const cb_law *law, const int history_offset)
    {
        pairs_.clear();
        where_.clear();
        LAMMPS_NS::PairGran *pair =
            static_cast<LAMMPS_NS::PairGran *>(force->pair_match("gran", 1));
        if (!pair || !pair->list || !pair->listgranhistory)
            error->all(FLERR, "cohesion model capillary: Protocol 1 needs the neighbor list and "
                              "contact history of pair_style gran (internal)");
        LAMMPS_NS::NeighList *list = pair->list;
        int **first_flags = pair->listgranhistory->firstneigh;
        double **first_history = pair->listgranhistory->firstdouble;
        const int dnum = pair->dnum();
        double **x = atom->x;
        const double *radius = atom->radius;
        const int *tag = atom->tag;
        const double factor = neighbor->contactDistanceFactor;
        const double visited = factor * factor;  // the pair loop's contactDistanceMultiplier
        for (int ii = 0; ii < list->inum; ++ii) {
            const int i = list->ilist[ii];
            for (int jj = 0; jj < list->numneigh[i]; ++jj) {
                const int j = list->firstneigh[i][jj] & NEIGHMASK;
                const double delx = x[i][0] - x[j][0];
                const double dely = x[i][1] - x[j][1];
                const double delz = x[i][2] - x[j][2];
                const double rsq = delx * delx + dely * dely + delz * delz;
                const double radsum = radius[i] + radius[j];
                double *history = &first_history[i][dnum * jj + history_offset];
                cb_bridge stored;
                std::memcpy(&stored, history, sizeof stored);
                const double gap = std::sqrt(rsq) - radsum;
                // a removed bridge's pair gets no liquid while its contact lasts
                const bool candidate = rsq < visited * radsum * radsum &&
                                       !cb_bridge_removed_in_contact(&stored, gap);
                if (!candidate && stored.active == 0.0) continue;
                const bool swap = radius[j] < radius[i];
                const double values[PAIR_VALUES] = {
                    (double)std::min(tag[i], tag[j]), (double)std::max(tag[i], tag[j]),
                    swap ? radius[j] : radius[i], swap ? radius[i] : radius[j], gap,
                    candidate ? 1.0 : 0.0, stored.active != 0.0 ? stored.volume : 0.0};
                pairs_.insert(pairs_.end(), values, values + PAIR_VALUES);
                Where w = {history, &first_flags[i][jj], law, i, j};
                where_.push_back(w);
            }
        }
    }

    /* step 1 for the walls: their grains, as pairs (the grain's ID, the wall's key) */
    void gather_walls(const WallSources &walls)
    {
        std::vector<WallSlot> slots;
        for (size_t k = 0; k < walls.size(); ++k) {
            walls[k].second->protocol1_slots(slots);
            for (size_t s = 0; s < slots.size(); ++s) {
                const WallSlot &slot = slots[s];
                cb_bridge stored;
                std::memcpy(&stored, slot.history, sizeof stored);
                const double values[PAIR_VALUES] = {
                    (double)atom->tag[slot.i], (double)walls[k].first, slot.r, CB_PLANE,
                    slot.gap, slot.candidate ? 1.0 : 0.0,
                    stored.active != 0.0 ? stored.volume : 0.0};
                pairs_.insert(pairs_.end(), values, values + PAIR_VALUES);
                Where w = {slot.history, NULL, slot.law, slot.i, -1};
                where_.push_back(w);
            }
        }
    }

    /* step 2: every rank's pairs to rank 0, solved there, the volumes back; result: the
     * core's status, alpha and the total liquid (on every rank) */
    void solve_over_ranks(const cb_law *law, const double *free_liquid,
                          std::vector<double> &volumes, double *result)
    {
        const int nprocs = comm->nprocs, me = comm->me;
        std::vector<double> mine_free(2 * atom->nlocal);
        for (int i = 0; i < atom->nlocal; ++i) {
            mine_free[2 * i] = atom->tag[i];
            mine_free[2 * i + 1] = free_liquid[i];
        }
        const int counts_mine[2] = {(int)where_.size(), atom->nlocal};
        std::vector<int> counts(2 * nprocs, 0);
        MPI_Gather(const_cast<int *>(counts_mine), 2, MPI_INT, &counts[0], 2, MPI_INT, 0, world);
        std::vector<int> n_pairs(nprocs), pair_at(nprocs), n_values(nprocs), value_at(nprocs),
            n_free(nprocs), free_at(nprocs);
        int total_pairs = 0, total_free = 0;
        for (int p = 0; me == 0 && p < nprocs; ++p) {
            n_pairs[p] = counts[2 * p];
            pair_at[p] = total_pairs;
            n_values[p] = PAIR_VALUES * n_pairs[p];
            value_at[p] = PAIR_VALUES * pair_at[p];
            n_free[p] = 2 * counts[2 * p + 1];
            free_at[p] = 2 * total_free;
            total_pairs += counts[2 * p];
            total_free += counts[2 * p + 1];
        }
        std::vector<double> all_pairs(me == 0 ? PAIR_VALUES * total_pairs + 1 : 1);
        std::vector<double> all_free(me == 0 ? 2 * total_free + 1 : 1);
        std::vector<double> all_volumes(me == 0 ? total_pairs + 1 : 1, 0.0);
        MPI_Gatherv(pairs_.empty() ? NULL : &pairs_[0], (int)pairs_.size(), MPI_DOUBLE,
                    &all_pairs[0], &n_values[0], &value_at[0], MPI_DOUBLE, 0, world);
        MPI_Gatherv(mine_free.empty() ? NULL : &mine_free[0], (int)mine_free.size(), MPI_DOUBLE,
                    &all_free[0], &n_free[0], &free_at[0], MPI_DOUBLE, 0, world);
        if (me == 0) solve_on_root(law, all_pairs, total_pairs, all_free, total_free,
                                   all_volumes, result);
        MPI_Bcast(result, 3, MPI_DOUBLE, 0, world);
        if ((int)result[0] != CB_OK) return;
        MPI_Scatterv(&all_volumes[0], &n_pairs[0], &pair_at[0], MPI_DOUBLE,
                     volumes.empty() ? NULL : &volumes[0], (int)volumes.size(), MPI_DOUBLE, 0,
                     world);
    }

    struct ByIds {
        const std::vector<double> *values;
        int stride;
        bool operator()(const int a, const int b) const
        {
            const double *u = &(*values)[stride * a], *v = &(*values)[stride * b];
            if (u[0] != v[0]) return u[0] < v[0];
            if (stride > 2 && u[1] != v[1]) return u[1] < v[1];
            return a < b;
        }
    };

    void solve_on_root(const cb_law *law, const std::vector<double> &pairs, const int n,
                       const std::vector<double> &free, const int n_free,
                       std::vector<double> &volumes, double *result)
    {
        std::vector<int> order(n);
        for (int k = 0; k < n; ++k) order[k] = k;
        const ByIds by_pair = {&pairs, PAIR_VALUES};
        std::sort(order.begin(), order.end(), by_pair);
        // each pair once (the first of its entries), the candidates in ID order
        std::vector<int> unique_of(n, -1);
        std::vector<double> r1, r2, gap;
        std::vector<int> candidate_of;  // per unique pair: its index among the candidates
        CompensatedSum total;
        int unique = -1;
        for (int k = 0; k < n; ++k) {
            const double *p = &pairs[PAIR_VALUES * order[k]];
            const bool same = k > 0 && p[0] == pairs[PAIR_VALUES * order[k - 1]] &&
                              p[1] == pairs[PAIR_VALUES * order[k - 1] + 1];
            if (!same) {
                ++unique;
                total.add(p[6]);
                candidate_of.push_back(p[5] != 0.0 ? (int)r1.size() : -1);
                if (p[5] != 0.0) {
                    r1.push_back(p[2]);
                    r2.push_back(p[3]);
                    gap.push_back(p[4]);
                }
            }
            unique_of[order[k]] = unique;
        }
        std::vector<int> atoms(n_free);
        for (int k = 0; k < n_free; ++k) atoms[k] = k;
        const ByIds by_atom = {&free, 2};
        std::sort(atoms.begin(), atoms.end(), by_atom);
        for (int k = 0; k < n_free; ++k) total.add(free[2 * atoms[k] + 1]);
        result[2] = total.value();
        result[0] = CB_OK;
        if (!(result[2] > 0.0)) return;  // no liquid: every volume 0
        const size_t nc = r1.size();
        std::vector<double> threshold(nc + 1), weight(nc + 1), volume(nc + 1);
        std::vector<size_t> sorted(nc + 1);
        const cb_protocol1_work work = {&threshold[0], &weight[0], &sorted[0]};
        const cb_status status =
            cb_protocol1_distribute(law, nc, nc ? &r1[0] : NULL, nc ? &r2[0] : NULL,
                                    nc ? &gap[0] : NULL, result[2], work, &volume[0], &result[1]);
        result[0] = status;
        if (status != CB_OK) return;
        for (int e = 0; e < n; ++e) {
            const int c = candidate_of[unique_of[e]];
            volumes[e] = c >= 0 ? volume[c] : 0.0;
        }
    }

    /* step 3: the largest bridge alpha gives (between the largest radii) must lie within the
     * volume the reach was built for, or eligible pairs beyond the reach were left out */
    void check_design(const double alpha, const Reach &design)
    {
        const double r = design.largest_radius();
        const double largest = alpha * r * r * r;
        if (!(largest > design.design_volume() * (1.0 + 1e-12))) return;
        char text[600];
        snprintf(text, sizeof text,
                 "cohesion model capillary: Protocol 1 gives alpha = %.6g: a bridge between the "
                 "largest particles (radius %g m) would hold %.6g m^3, more than the volume "
                 "%.6g m^3 the contact distance factor was built for, so pairs that should "
                 "receive liquid lie beyond the pairs LIGGGHTS visits; give a larger 'vmax' "
                 "(at least %.6g)",
                 alpha, r, largest, design.design_volume(), largest);
        error->all(FLERR, text);
    }

    /* step 4: the volumes into this rank's histories, the free liquid cleared */
    void apply(const std::vector<double> &volumes, double *free_liquid)
    {
        for (size_t k = 0; k < where_.size(); ++k) {
            const Where &w = where_[k];
            const double *p = &pairs_[PAIR_VALUES * k];
            cb_bridge bridge;
            std::memcpy(&bridge, w.history, sizeof bridge);
            const cb_status status =
                cb_bridge_set_volume(w.law, p[2], p[3], volumes[k], &bridge);
            if (status != CB_OK) {
                char text[400];
                if (w.j >= 0)
                    snprintf(text, sizeof text,
                             "cohesion model capillary: Protocol 1 could not give %g m^3 to the "
                             "pair of particles %d and %d (radii %g and %g m, gap %g m): %s",
                             volumes[k], atom->tag[w.i], atom->tag[w.j], p[2], p[3], p[4],
                             cb_status_message(status));
                else
                    snprintf(text, sizeof text,
                             "cohesion model capillary: Protocol 1 could not give %g m^3 to the "
                             "bridge of particle %d (radius %g m) and a wall (gap %g m): %s",
                             volumes[k], atom->tag[w.i], p[2], p[4], cb_status_message(status));
                error->one(FLERR, text);
            }
            std::memcpy(w.history, &bridge, sizeof bridge);
            // a bridge keeps its pair's history through re-neighboring (a wall's is per grain)
            if (w.flags && bridge.active != 0.0)
                *w.flags |= LIGGGHTS::ContactModels::CONTACT_COHESION_MODEL;
            else if (w.flags)
                *w.flags &= ~LIGGGHTS::ContactModels::CONTACT_COHESION_MODEL;
        }
        for (int i = 0; i < atom->nlocal; ++i) free_liquid[i] = 0.0;
    }

    struct Where {
        double *history;    // the pair's cb_bridge
        int *flags;         // the pair's contact flags (NULL: a wall's)
        const cb_law *law;  // the pair's law (a wall's: at the wall's angle, the same)
        int i, j;           // j -1: a wall
    };

    int every_;                  // steps between distributions; 0: at every re-neighboring
    bool attempted_;             // a distribution was tried by this instance
    bool warned_;                // no pair could hold the liquid (warned once)
    LAMMPS_NS::bigint last_step_;
    std::vector<double> pairs_;  // PAIR_VALUES per pair of this rank
    std::vector<Where> where_;
};

} /* namespace capbridge_liggghts */

#endif /* CAPBRIDGE_LIGGGHTS_PROTOCOL1_H_ */
