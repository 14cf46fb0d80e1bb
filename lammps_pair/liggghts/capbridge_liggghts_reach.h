/* capbridge_liggghts_reach.h — how far LIGGGHTS visits a pair, for `cohesion capillary`.
 *
 * Part of capbridge (lammps_pair/liggghts/). Compiled inside LIGGGHTS: C++98 and C++11.
 *
 * The pair loop calls a model for a pair that does not touch only while
 * r^2 < contact_distance_factor^2 (R1 + R2)^2.  A bridge must rupture within that reach, or
 * its pair would stop being visited while it exists and its liquid would leave with the
 * neighbor list.  The rules are the core's (capbridge.h, "the engines' checks"): the reach
 * of a type pair, cb_reach, over the radius range of the run and the volume the reach is
 * built for (bridgeVolume, or under a per-atom liquid protocol its design volume: vmax when
 * given, else cb_protocol_design_volume; and the bridges that exist), the factor 1 + its
 * reach_ratio; a held bridge beyond its design
 * rupture distance is ruptured, cb_bridge_beyond_reach, counted and warned once.  This file
 * gathers the radii, volumes and free liquid from LIGGGHTS and applies the results.
 */
#ifndef CAPBRIDGE_LIGGGHTS_REACH_H_
#define CAPBRIDGE_LIGGGHTS_REACH_H_

#include "atom.h"
#include "capbridge.h"
#include "comm.h"
#include "error.h"
#include "fix_contact_history.h"
#include "modify.h"
#include "neighbor.h"
#include "pointers.h"
#include "property_registry.h"
#include "update.h"

#include <mpi.h>
#include <algorithm>
#include <cfloat>
#include <cmath>
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
    explicit Reach(LAMMPS_NS::LAMMPS *lmp)
        : Pointers(lmp), ntypes_(0), per_atom_(false), vmax_given_(false), design_volume_(0.0),
          largest_radius_(0.0), beyond_(0.0), warned_(false)
    {
    }

    /* At the init of every run: the design rupture distance of every pair of types and the
     * contact distance factor that covers it.  The radius range is the run's (particles and
     * insertion fixes: PropertyRegistry); the volume, per pair of types, the largest of the
     * design volume (bridgeVolume, or under Protocols 1, 2, 3 vmax > 0 when given, else the
     * core's design volume of the liquid) and the bridges that exist (held_volumes).  The
     * design rupture distance never decreases for one pair_style, as LIGGGHTS's contact
     * distance factor never does: the
     * bridges of the last run that formed after its last re-neighboring are in no record
     * the model can read now (fix contacthistory's partner arrays are that old), and stay
     * covered.  bridge_volume is NULL under the protocols, free_liquid NULL with fixed
     * volumes. */
    void register_factor(PropertyRegistry &registry, const ReachLaws &laws,
                         double **bridge_volume, const double *free_liquid, const double vmax,
                         const int history_offset)
    {
        ntypes_ = laws.ntypes;
        per_atom_ = free_liquid != NULL;
        vmax_given_ = vmax > 0.0;
        if (design_rupture_.size() != (size_t)((ntypes_ + 1) * (ntypes_ + 1)))
            design_rupture_.assign((ntypes_ + 1) * (ntypes_ + 1), 0.0);
        const double rmin = registry.min_radius();
        const double rmax = registry.max_radius();
        if (!(rmin > 0.0) || !(rmax > 0.0) || rmin > 1e100) return;
        largest_radius_ = rmax;
        const cb_radius_range radii = {rmin, rmax};
        const std::vector<double> held = held_volumes(history_offset, per_atom_ && !vmax_given_);
        if (per_atom_)
            design_volume_ =
                vmax_given_ ? vmax : protocol_design_volume(radii, free_liquid, held);
        double ratio = 0.0;
        int widest[2] = {1, 1};
        for (int a = 1; a <= ntypes_; ++a)
            for (int b = a; b <= ntypes_; ++b) {
                const double design = free_liquid ? design_volume_ : bridge_volume[a][b];
                const double volume = std::max(design, std::max(held[a], held[b]));
                double rupture = 0.0, pair_ratio = 0.0;
                const cb_status status =
                    cb_reach(laws.of(a, b), radii, radii, volume, &rupture, NULL, &pair_ratio);
                if (status != CB_OK) {
                    char text[512];
                    snprintf(text, sizeof text,
                             "cohesion model capillary: no reach for bridges of %g m^3 (atom "
                             "types %d %d, %s) between radii %g and %g m: law %s (rupture %s): "
                             "%s",
                             volume, a, b, volume > design ? "a bridge that exists"
                             : design_name(), rmin, rmax, laws.law, laws.rupture,
                             cb_status_message(status));
                    error->all(FLERR, text);
                }
                double &ab = design_rupture_[a * (ntypes_ + 1) + b];
                ab = std::max(ab, rupture);
                design_rupture_[b * (ntypes_ + 1) + a] = ab;
                if (pair_ratio > ratio) {
                    ratio = pair_ratio;
                    widest[0] = a;
                    widest[1] = b;
                }
            }
        if (!(ratio > 0.0)) return;
        // 1 + ratio rounded up, so that the factor covers the ratio
        double factor = 1.0 + ratio;
        if (factor - 1.0 < ratio) factor = nextafter(factor, 2.0);
        neighbor->register_contact_dist_factor(factor);
        check_resolved(laws.of(widest[0], widest[1]), rmin, ratio);
    }

    /* Under the liquid protocols: the design volume of this run and the largest radius it
     * was built for (Protocol 1 checks its largest bridge against them). */
    double design_volume() const { return design_volume_; }
    double largest_radius() const { return largest_radius_; }

    /* A bridge of atom types a, b held at this gap is beyond the reach (the core's rule):
     * the model ruptures it now and counts it. */
    bool beyond(const int a, const int b, const double gap) const
    {
        return cb_bridge_beyond_reach(gap, design_rupture_[a * (ntypes_ + 1) + b]);
    }
    void count_beyond(const bool j_local) { beyond_ += j_local ? 1.0 : 0.5; }

    /* In census passes (collective), until it has warned: the bridges ruptured beyond the
     * reach on all ranks so far, one warning with their number. */
    void report_beyond()
    {
        if (warned_) return;
        double all = 0.0;
        MPI_Allreduce(&beyond_, &all, 1, MPI_DOUBLE, MPI_SUM, world);
        if (!(all > 0.0)) return;
        warned_ = true;
        if (comm->me != 0) return;
        char text[640];
        snprintf(text, sizeof text,
                 "cohesion model capillary: %.0f bridge(s) held beyond the reach by step "
                 BIGINT_FORMAT " (a gap beyond the rupture distance %g m of the volume the "
                 "reach of this run is built for, %s) were ruptured there, before their own "
                 "rupture distance, their liquid released as at any rupture (liquid "
                 "protocol1, protocol2: to the two particles; protocol3: to their receivers; "
                 "liquid fixed: it leaves); the next run's reach also covers the bridges "
                 "then%s; this warning is given once",
                 all, update->ntimestep, largest_design_rupture(), design_name(),
                 per_atom_ && !vmax_given_ ? " and the free liquid" : "");
        error->warning(FLERR, text);
    }

  private:
    const char *design_name() const
    {
        return !per_atom_ ? "bridgeVolume"
                          : vmax_given_ ? "vmax" : "the design volume of the liquid";
    }

    /* The protocols' design volume (cb_protocol_design_volume): the liquid of the run (free
     * liquid and bridges, held[0]), the number of particles, their radius range and the
     * largest free liquid of one particle, over all ranks. */
    double protocol_design_volume(const cb_radius_range &radii, const double *free_liquid,
                                  const std::vector<double> &held)
    {
        double local[2] = {held[0], 0.0}, all[2] = {0.0, 0.0};
        double most = 0.0, most_all = 0.0;
        for (int i = 0; i < atom->nlocal; ++i) {
            local[0] += free_liquid[i];
            most = std::max(most, free_liquid[i]);
        }
        local[1] = atom->nlocal;
        MPI_Allreduce(local, all, 2, MPI_DOUBLE, MPI_SUM, world);
        MPI_Allreduce(&most, &most_all, 1, MPI_DOUBLE, MPI_MAX, world);
        double volume = 0.0;
        const cb_status status = cb_protocol_design_volume(all[0], all[1], radii, most_all,
                                                           &volume);
        if (status != CB_OK) {
            char text[400];
            snprintf(text, sizeof text,
                     "cohesion model capillary: no design volume for the reach (liquid %g m^3 "
                     "in %.0f particles of radii %g to %g m, largest free liquid %g m^3): %s",
                     all[0], all[1], radii.min, radii.max, most_all, cb_status_message(status));
            error->all(FLERR, text);
        }
        return volume;
    }

    double largest_design_rupture() const
    {
        double largest = 0.0;
        for (size_t k = 0; k < design_rupture_.size(); ++k)
            largest = std::max(largest, design_rupture_[k]);
        return largest;
    }

    /* LIGGGHTS tells a pair apart from contact by r^2 < factor^2 (R1 + R2)^2 in double
     * precision: a reach below a few DBL_EPSILON of the radius sum is not resolved.  From
     * 64 DBL_EPSILON up it is (the factor 1 + 64 DBL_EPSILON or more); below, the bridges
     * would leave with the neighbor list as soon as the particles part: an error with the
     * smallest volume that works (for the smallest radii, where the ratio is largest) and a
     * factor that keeps such bridges. */
    void check_resolved(const cb_law *law, const double rmin, const double ratio)
    {
        const double resolved = 64.0 * DBL_EPSILON;
        if (neighbor->contactDistanceFactor - 1.0 >= resolved) return;
        double smallest = 0.0;
        char least[160] = "";
        if (cb_rupture_volume(law, rmin, rmin, resolved * 2.0 * rmin, &smallest) == CB_OK)
            snprintf(least, sizeof least, "at least %s m^3 per bridge%s, ",
                     format_at_least(smallest * (1.0 + 1e-6)).c_str(),
                     per_atom_ ? " (the freeLiquid of its two particles together)" : "");
        char text[900];
        snprintf(text, sizeof text,
                 "cohesion model capillary: the bridges this run is built for (%s) rupture "
                 "within %.3g of the radius sum, too small for LIGGGHTS's distance test to "
                 "tell from contact: a volume this small makes no meaningful bridge.  Give "
                 "%sor no liquid (0: the pair stays dry); or, to keep such bridges, "
                 "'neigh_modify contact_distance_factor %s'",
                 design_name(), ratio,
                 least, format_at_least(1.0 + resolved).c_str());
        error->all(FLERR, text);
    }

    /* The largest bridge that exists, per atom type, over all ranks (index 0: under
     * Protocol 2, the liquid in the bridges, half for each end this rank owns): bridges read
     * from a restart file, or kept from the last run, in fix contacthistory's per-atom
     * partner arrays (as of the last re-neighboring).  The liquid on offer now may not cover
     * them (Protocol 2 once the free liquid is in bridges; a lower bridgeVolume), and a
     * restart starts the contact distance factor again from 1: a bridge stretched beyond the
     * reach would leave the neighbor list with its liquid, without a word. */
    std::vector<double> held_volumes(const int history_offset, const bool sum_liquid)
    {
        std::vector<double> local(ntypes_ + 1, 0.0), all(ntypes_ + 1, 0.0);
        double liquid = 0.0;
        LAMMPS_NS::FixContactHistory *history = static_cast<LAMMPS_NS::FixContactHistory *>(
            modify->find_fix_style_strict("contacthistory", 0));
        if (history) {
            const int *type = atom->type;
            for (int i = 0; i < atom->nlocal; ++i)
                for (int k = 0; k < history->n_partner(i); ++k) {
                    cb_bridge bridge;
                    std::memcpy(&bridge, history->contacthistory(i, k) + history_offset,
                                sizeof bridge);
                    if (bridge.active == 0.0) continue;
                    liquid += 0.5 * bridge.volume;
                    if (bridge.volume > local[type[i]]) local[type[i]] = bridge.volume;
                }
        }
        MPI_Allreduce(&local[0], &all[0], ntypes_ + 1, MPI_DOUBLE, MPI_MAX, world);
        all[0] = 0.0;
        if (sum_liquid) MPI_Allreduce(&liquid, &all[0], 1, MPI_DOUBLE, MPI_SUM, world);
        return all;
    }

    int ntypes_;
    bool per_atom_;                       // liquid protocol1, 2, 3 (not fixed)
    bool vmax_given_;                     // the design volume given with vmax
    std::vector<double> design_rupture_;  // per pair of types, [a * (ntypes + 1) + b]
    double design_volume_;                // the protocols' design volume [m^3]
    double largest_radius_;               // the largest radius of the run [m]
    double beyond_;                       // this rank's bridges ruptured beyond the reach
    bool warned_;
};

} /* namespace capbridge_liggghts */

#endif /* CAPBRIDGE_LIGGGHTS_REACH_H_ */
