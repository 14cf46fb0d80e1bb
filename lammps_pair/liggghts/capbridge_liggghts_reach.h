/* capbridge_liggghts_reach.h — how far LIGGGHTS visits a pair, for `cohesion capillary`.
 *
 * Part of capbridge (lammps_pair/liggghts/). Compiled inside LIGGGHTS: C++98 and C++11.
 *
 * The pair loop calls a model for a pair that does not touch only while
 * r^2 < contact_distance_factor^2 (R1 + R2)^2.  A bridge must rupture within that reach, or
 * its pair would stop being visited while it exists and its liquid would leave with the
 * neighbor list.  The model raises the factor from the bridges it expects (register_factor)
 * and checks every bridge when it forms (check).
 */
#ifndef CAPBRIDGE_LIGGGHTS_REACH_H_
#define CAPBRIDGE_LIGGGHTS_REACH_H_

#include "atom.h"
#include "capbridge.h"
#include "error.h"
#include "fix_contact_history.h"
#include "modify.h"
#include "neighbor.h"
#include "pointers.h"
#include "property_registry.h"

#include <mpi.h>
#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace capbridge_liggghts {

/* x printed with the fewest significant digits (at least 4) whose value is >= x: a factor
 * the user copies from a message must be enough (%.4g of 1.0000001 is "1"). */
inline std::string format_at_least(const double x)
{
    char text[40];
    for (int digits = 4; digits <= 17; ++digits) {
        snprintf(text, sizeof text, "%.*g", digits, x);
        if (std::strtod(text, NULL) >= x) break;
    }
    return text;
}

/* What the model needs of a law for the reach: the law of a pair of types, and its names. */
struct ReachLaws {
    const std::vector<cb_law> *laws;
    const std::vector<int> *pair_law;
    int ntypes;
    const char *law, *rupture, *validity;
    const cb_law *of(const int a, const int b) const
    {
        return &(*laws)[(*pair_law)[a * (ntypes + 1) + b]];
    }
};

class Reach : protected LAMMPS_NS::Pointers {
  public:
    explicit Reach(LAMMPS_NS::LAMMPS *lmp) : Pointers(lmp) {}

    // the first step beyond the rupture distance must still be visited
    static double margin() { return 1.05; }

    /* The factor must cover the largest rupture distance relative to the radius sum: it is
     * estimated from the smallest and largest radius (particles and insertion fixes) and the
     * largest bridge volume (bridgeVolume, or twice the largest free liquid, and the bridges
     * that exist: held_volumes), with 10 % margin.  bridge_volume is NULL under Protocol 2,
     * free_liquid NULL with fixed volumes. */
    void register_factor(PropertyRegistry &registry, const ReachLaws &laws,
                         double **bridge_volume, const double *free_liquid,
                         const int history_offset)
    {
        const double rmin = registry.min_radius();
        const double rmax = registry.max_radius();
        if (!(rmin > 0.0) || !(rmax > 0.0) || rmin > 1e100) return;
        const double radii[3][2] = {{rmin, rmin}, {rmin, rmax}, {rmax, rmax}};
        double protocol2_volume = 0.0;
        if (free_liquid) {
            double most = 0.0;
            for (int i = 0; i < atom->nlocal; ++i) most = std::max(most, free_liquid[i]);
            MPI_Allreduce(&most, &protocol2_volume, 1, MPI_DOUBLE, MPI_MAX, world);
            protocol2_volume *= 2.0;
        }
        const std::vector<double> held = held_volumes(laws.ntypes, history_offset);
        double ratio = 0.0;
        for (int a = 1; a <= laws.ntypes; ++a)
            for (int b = a; b <= laws.ntypes; ++b) {
                // an existing bridge formed under its law's validity for its own radii; at
                // the bounding radii its rupture distance is taken as the law extends it
                cb_law extended = *laws.of(a, b);
                extended.validity = CB_VALIDITY_EXTEND;
                const double existing = std::max(held[a], held[b]);
                for (int k = 0; existing > 0.0 && k < 3; ++k) {
                    double rupture = 0.0;
                    const cb_status status = cb_rupture_distance(&extended, radii[k][0],
                                                                 radii[k][1], existing, &rupture);
                    if (status != CB_OK) {
                        // (not reached with a valid history: the bridge formed with it)
                        char text[512];
                        snprintf(text, sizeof text,
                                 "cohesion model capillary: an existing bridge of %g m^3 (atom "
                                 "types %d %d) has no rupture distance with radii %g and %g m, "
                                 "so the reach cannot be set to keep it: law %s: %s",
                                 existing, a, b, radii[k][0], radii[k][1], laws.law,
                                 cb_status_message(status));
                        error->all(FLERR, text);
                    }
                    ratio = std::max(ratio, rupture / (radii[k][0] + radii[k][1]));
                }
                const double volume = free_liquid ? protocol2_volume : bridge_volume[a][b];
                if (!(volume > 0.0)) continue;
                for (int k = 0; k < 3; ++k) {
                    double rupture = 0.0;
                    const cb_status status = cb_rupture_distance(laws.of(a, b), radii[k][0],
                                                                 radii[k][1], volume, &rupture);
                    if (status != CB_OK) {
                        if (free_liquid) continue; // only an estimate; each bridge is checked
                        char text[512];
                        snprintf(text, sizeof text,
                                 "cohesion model capillary: bridgeVolume %g m^3 of atom types "
                                 "%d %d with radii %g and %g m: law %s (rupture %s, validity "
                                 "%s): %s",
                                 volume, a, b, radii[k][0], radii[k][1], laws.law,
                                 laws.rupture, laws.validity, cb_status_message(status));
                        error->all(FLERR, text);
                    }
                    ratio = std::max(ratio, rupture / (radii[k][0] + radii[k][1]));
                }
            }
        if (ratio > 0.0) neighbor->register_contact_dist_factor(1.0 + 1.1 * ratio);
    }

    /* A new bridge between local atom i and atom j: its rupture distance must lie within the
     * reach.  Returns false with the complete message in `why` when it does not. */
    bool check(const cb_law *law, const double ra, const double rb, const double radsum,
               const double volume, const double rupture, const int i, const int j,
               const bool protocol2, std::string &why)
    {
        const double factor = neighbor->contactDistanceFactor;
        const double reach = (factor - 1.0) * radsum;
        if (rupture * margin() <= reach) return true;
        char text[900];
        const int n = snprintf(text, sizeof text,
                 "cohesion model capillary: the bridge between particles %d and %d (volume %g "
                 "m^3) ruptures at a gap of %g m, beyond the gap %g m up to which LIGGGHTS "
                 "visits the pair (contact distance factor %.15g); ",
                 atom->tag[i], atom->tag[j], volume, rupture, reach / margin(), factor);
        // A rupture distance near the rounding of r^2 < factor^2 (R1 + R2)^2 (a few
        // DBL_EPSILON of the radius sum) cannot be told from contact by that test.  From
        // 64 DBL_EPSILON up the factor below, 1 + 74 DBL_EPSILON or more, resolves it.
        const double resolved = 64.0 * DBL_EPSILON * radsum;
        const std::string needed = format_at_least(1.0 + 1.1 * margin() * rupture / radsum);
        if (rupture >= resolved) {
            snprintf(text + n, sizeof text - n,
                     "raise it with 'neigh_modify contact_distance_factor %s'", needed.c_str());
        } else {
            double smallest = 0.0;
            char least[160] = "";
            if (cb_rupture_volume(law, ra, rb, resolved, &smallest) == CB_OK)
                snprintf(least, sizeof least, "at least %s m^3 per bridge%s, ",
                         format_at_least(smallest * (1.0 + 1e-6)).c_str(),
                         protocol2 ? " (the freeLiquid of its two particles together)" : "");
            snprintf(text + n, sizeof text - n,
                     "that gap is %.3g of the radius sum, too small for LIGGGHTS's distance "
                     "test to tell from contact: a volume this small makes no meaningful "
                     "bridge.  Give %sor no liquid (0: the pair stays dry); or, to keep such "
                     "bridges, 'neigh_modify contact_distance_factor %s'",
                     rupture / radsum, least,
                     format_at_least(1.0 + 1.1 * margin() * resolved / radsum).c_str());
        }
        why = text;
        return false;
    }

  private:
    /* The largest bridge that exists, per atom type, over all ranks: bridges read from a
     * restart file, or kept from the last run, in fix contacthistory's per-atom partner
     * arrays.  The liquid on offer now may not cover them (Protocol 2 once the free liquid
     * is in bridges; a lower bridgeVolume), and a restart starts the contact distance
     * factor again from 1: a bridge stretched beyond the reach would leave the neighbor
     * list with its liquid, without a word. */
    std::vector<double> held_volumes(const int ntypes, const int history_offset)
    {
        std::vector<double> local(ntypes + 1, 0.0), all(ntypes + 1, 0.0);
        LAMMPS_NS::FixContactHistory *history = static_cast<LAMMPS_NS::FixContactHistory *>(
            modify->find_fix_style_strict("contacthistory", 0));
        if (history) {
            const int *type = atom->type;
            for (int i = 0; i < atom->nlocal; ++i)
                for (int k = 0; k < history->n_partner(i); ++k) {
                    cb_bridge bridge;
                    std::memcpy(&bridge, history->contacthistory(i, k) + history_offset,
                                sizeof bridge);
                    if (bridge.active != 0.0 && bridge.volume > local[type[i]])
                        local[type[i]] = bridge.volume;
                }
        }
        MPI_Allreduce(&local[0], &all[0], ntypes + 1, MPI_DOUBLE, MPI_MAX, world);
        return all;
    }
};

} /* namespace capbridge_liggghts */

#endif /* CAPBRIDGE_LIGGGHTS_REACH_H_ */
