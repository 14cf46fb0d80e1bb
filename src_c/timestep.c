/* timestep.c — the time step the engines warn above (Richefeu 2007 §2). */
#include "laws.h"

#include <math.h>

cb_status cb_timestep_limit(const cb_law *law, cb_radius_range range1, cb_radius_range range2,
                            const double *volumes, size_t n_volumes, double smallest_mass,
                            double normal_stiffness, double *limit,
                            double *capillary_stiffness)
{
    if (!limit || (n_volumes > 0 && !volumes)) return CB_ERR_NULL;
    if (!isfinite(smallest_mass) || !isfinite(normal_stiffness)) return CB_ERR_NOT_FINITE;
    if (!(smallest_mass > 0.0) || normal_stiffness < 0.0) return CB_ERR_NEGATIVE;
    double capillary = 0.0;
    if (law) {
        /* as the reach (cb_reach): a bridge that exists is kept whatever its radii */
        cb_law extended = *law;
        extended.validity = CB_VALIDITY_EXTEND;
        const double r1[2] = {range1.min, range1.max}, r2[2] = {range2.min, range2.max};
        for (size_t v = 0; v < n_volumes; ++v) {
            if (!(volumes[v] > 0.0)) continue;
            for (int a = 0; a < 2; ++a)
                for (int b = 0; b < 2; ++b) {
                    double k = 0.0;
                    cb_status status =
                        cb_capillary_stiffness_bound(&extended, r1[a], r2[b], volumes[v], &k);
                    if (status != CB_OK) return status;
                    if (k > capillary) capillary = k;
                }
        }
    }
    const double k = normal_stiffness > capillary ? normal_stiffness : capillary;
    *limit = k > 0.0 ? CB_TIMESTEP_FRACTION * CB_PI * sqrt(smallest_mass / k) : HUGE_VAL;
    if (capillary_stiffness) *capillary_stiffness = capillary;
    return CB_OK;
}

/* The bridge's viscous force (viscous.c) is a damper c between the two spheres: explicit
 * integration is stable for dt < 2 m_r / c, m_r >= m/2 the reduced mass, i.e. for dt < m/c; the
 * limit keeps the elastic rule's margin against its own bound (a tenth of pi sqrt(m/k) is
 * pi/20 of the stability bound 2 sqrt(m/k)): CB_TIMESTEP_FRACTION pi m / c, c the larger
 * damping coefficient at the minimum gap (where it is largest) for the largest radii and
 * volume. */
cb_status cb_viscous_timestep_limit(const cb_law *law, cb_radius_range range1,
                                    cb_radius_range range2, const double *volumes,
                                    size_t n_volumes, double smallest_mass, double *limit,
                                    double *damping)
{
    if (!law || !limit || (n_volumes > 0 && !volumes)) return CB_ERR_NULL;
    if (!isfinite(smallest_mass)) return CB_ERR_NOT_FINITE;
    if (!(smallest_mass > 0.0)) return CB_ERR_NEGATIVE;
    double largest = 0.0;
    const double r1[2] = {range1.min, range1.max}, r2[2] = {range2.min, range2.max};
    for (size_t v = 0; law->viscosity > 0.0 && v < n_volumes; ++v) {
        if (!(volumes[v] > 0.0)) continue;
        for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 2; ++b) {
                double normal = 0.0, tangential = 0.0;
                cb_status status = cb_viscous_damping(law, r1[a], r2[b], law->viscous_min_gap,
                                                      volumes[v], &normal, &tangential);
                if (status != CB_OK) return status;
                if (normal > largest) largest = normal;
                if (tangential > largest) largest = tangential;
            }
    }
    *limit = largest > 0.0 ? CB_TIMESTEP_FRACTION * CB_PI * smallest_mass / largest : HUGE_VAL;
    if (damping) *damping = largest;
    return CB_OK;
}
