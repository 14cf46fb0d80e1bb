/* capbridge_liggghts_timestep.h — the time-step check of `cohesion capillary`.
 *
 * Part of capbridge (lammps_pair/liggghts/). Compiled inside LIGGGHTS: C++98 and C++11.
 *
 * The rule is the core's (cb_timestep_limit, the one the LAMMPS binding applies): at setup
 * and after every re-neighboring, until it has warned once, a time step above
 * CB_TIMESTEP_FRACTION pi sqrt(m / k) warns, m the smallest mass of the two atom types, k
 * the capillary stiffness bound (cb_capillary_stiffness_bound) at the smallest and largest
 * radius of each type, for the bridge volumes in use: bridgeVolume of the type pair
 * (liquid fixed), or the smallest and largest bridge that exists (Protocol 2).  LAMMPS
 * gives the core its contact stiffness k_n too; LIGGGHTS checks the contact (Rayleigh and
 * Hertz times) itself with fix check/timestep/gran, so the model gives 0.  With `viscous
 * on`, a time step above CB_TIMESTEP_FRACTION pi m / c warns too, c the largest damping
 * coefficient of the bridges' viscous force (cb_viscous_timestep_limit, at the law's
 * minimum gap), as in LAMMPS.  The bounds (~200 force evaluations per volume and pair of
 * radii) are evaluated again only when a type pair's volumes or radii have changed.
 */
#ifndef CAPBRIDGE_LIGGGHTS_TIMESTEP_H_
#define CAPBRIDGE_LIGGGHTS_TIMESTEP_H_

#include "atom.h"
#include "capbridge.h"
#include "comm.h"
#include "error.h"
#include "pointers.h"
#include "update.h"

#include <mpi.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace capbridge_liggghts {

class TimestepCheck : protected LAMMPS_NS::Pointers {
  public:
    explicit TimestepCheck(LAMMPS_NS::LAMMPS *lmp) : Pointers(lmp), warned_(false), ntypes_(0)
    {
    }

    /* false once it has warned: the model then gathers nothing for it */
    bool wanted() const { return !warned_; }

    /* The start of a checked pass: no bridge volumes gathered yet. */
    void begin(const int ntypes)
    {
        ntypes_ = ntypes;
        const size_t np = (size_t)(ntypes + 1) * (ntypes + 1);
        vlo_.assign(np, HUGE_VAL);
        minus_vhi_.assign(np, HUGE_VAL);
    }

    /* Protocol 2: a bridge that exists after this pass's transitions. */
    void add_bridge(int a, int b, const double volume)
    {
        if (a > b) std::swap(a, b);
        const int ab = a * (ntypes_ + 1) + b;
        vlo_[ab] = std::min(vlo_[ab], volume);
        minus_vhi_[ab] = std::min(minus_vhi_[ab], -volume);
    }

    /* The end of the pass (collective). laws[pair_law[a * (ntypes + 1) + b]] is the law of
     * types a, b; bridge_volume the volume of a new bridge (liquid fixed) or NULL; viscous:
     * the laws may have a viscosity (viscous on). */
    void finish(const std::vector<cb_law> &laws, const std::vector<int> &pair_law,
                double **bridge_volume, const bool viscous)
    {
        const int n = ntypes_;
        const int np = (n + 1) * (n + 1);
        // [mass | radius | minus radius per type | volume | minus volume per pair]: all MIN
        std::vector<double> local(3 * (n + 1) + 2 * np, HUGE_VAL), all(local.size());
        double *mass = &local[0], *rlo = mass + n + 1, *minus_rhi = rlo + n + 1;
        std::copy(vlo_.begin(), vlo_.end(), minus_rhi + n + 1);
        std::copy(minus_vhi_.begin(), minus_vhi_.end(), minus_rhi + n + 1 + np);
        for (int i = 0; i < atom->nlocal; ++i) {
            const int t = atom->type[i];
            mass[t] = std::min(mass[t], atom->rmass[i]);
            rlo[t] = std::min(rlo[t], atom->radius[i]);
            minus_rhi[t] = std::min(minus_rhi[t], -atom->radius[i]);
        }
        MPI_Allreduce(&local[0], &all[0], (int)local.size(), MPI_DOUBLE, MPI_MIN, world);
        mass = &all[0];
        rlo = mass + n + 1;
        minus_rhi = rlo + n + 1;
        const double *vlo = minus_rhi + n + 1, *minus_vhi = vlo + np;

        // the bound per type pair for the volumes and radii it was last evaluated at; the
        // law may have changed between runs
        if (update->setupflag || keys_.size() != (size_t)(KEY * np)) {
            keys_.assign(KEY * np, -1.0);
            bound_.assign(np, 0.0);
        }
        for (int a = 1; a <= n; ++a)
            for (int b = a; b <= n; ++b) {
                if (mass[a] == HUGE_VAL || mass[b] == HUGE_VAL) continue;
                const int ab = a * (n + 1) + b;
                double key[KEY] = {0.0, 0.0, rlo[a], -minus_rhi[a], rlo[b], -minus_rhi[b]};
                if (bridge_volume)
                    key[0] = bridge_volume[a][b];
                else if (-minus_vhi[ab] > 0.0) {
                    key[0] = vlo[ab];
                    key[1] = -minus_vhi[ab];
                }
                const double m = std::min(mass[a], mass[b]);
                const cb_law *law = &laws[pair_law[ab]];
                if (!std::equal(key, key + KEY, &keys_[KEY * ab])) {
                    // (a bound the core cannot give, e.g. radii outside a table: no check)
                    double limit = 0.0, k = 0.0;
                    const cb_radius_range ra = {key[2], key[3]}, rb = {key[4], key[5]};
                    if (cb_timestep_limit(law, ra, rb, key, 2, m, 0.0, &limit, &k) != CB_OK)
                        k = 0.0;
                    bound_[ab] = k;
                    std::copy(key, key + KEY, &keys_[KEY * ab]);
                }
                const double k = bound_[ab];
                double limit = HUGE_VAL;
                const cb_radius_range none = {0.0, 0.0};
                // a deck that sets dt to exactly this limit is within it: allow for rounding
                if (k > 0.0 &&
                    cb_timestep_limit(NULL, none, none, NULL, 0, m, k, &limit, NULL) == CB_OK &&
                    update->dt > limit * (1.0 + 1e-12)) {
                    warned_ = true;
                    if (comm->me == 0) {
                        char text[512];
                        snprintf(text, sizeof text,
                                 "cohesion model capillary: time step %.6g s exceeds the limit "
                                 "%.6g s = %g%% of pi sqrt(m/k) for types %d %d (smallest mass "
                                 "m = %.6g, k = %.6g: the capillary stiffness bound; the "
                                 "contact stiffness is checked by fix check/timestep/gran); "
                                 "this warning is given once",
                                 update->dt, limit, 100.0 * CB_TIMESTEP_FRACTION, a, b, m,
                                 k);
                        error->warning(FLERR, text);
                    }
                    return;
                }
                // (8 damping evaluations: not worth a cache)
                if (viscous && warn_viscous(a, b, law, key, m)) return;
            }
    }

  private:
    /* the viscous limit of types a, b (cb_viscous_timestep_limit for the volumes and radius
     * ranges of key): warned once */
    bool warn_viscous(const int a, const int b, const cb_law *law, const double *key,
                      const double m)
    {
        double limit = HUGE_VAL, c = 0.0;
        const cb_radius_range ra = {key[2], key[3]}, rb = {key[4], key[5]};
        if (cb_viscous_timestep_limit(law, ra, rb, key, 2, m, &limit, &c) != CB_OK ||
            !(update->dt > limit * (1.0 + 1e-12)))
            return false;
        warned_ = true;
        if (comm->me == 0) {
            char text[512];
            snprintf(text, sizeof text,
                     "cohesion model capillary: time step %.6g s exceeds the limit %.6g s = "
                     "%g%% of pi m/c of the bridges' viscous force for types %d %d (smallest "
                     "mass m = %.6g, c = %.6g the largest damping coefficient, at "
                     "viscousMinGap); this warning is given once",
                     update->dt, limit, 100.0 * CB_TIMESTEP_FRACTION, a, b, m, c);
            error->warning(FLERR, text);
        }
        return true;
    }

    enum { KEY = 6 };  // two volumes (first the volumes cb_timestep_limit gets), then the
                       // radius range of each type

    bool warned_;
    int ntypes_;
    std::vector<double> vlo_, minus_vhi_;  // Protocol 2: this rank's bridges per type pair
    std::vector<double> keys_, bound_;     // the bound per type pair, and what it is for
};

} /* namespace capbridge_liggghts */

#endif /* CAPBRIDGE_LIGGGHTS_TIMESTEP_H_ */
