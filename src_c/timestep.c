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
