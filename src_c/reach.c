/* reach.c — how far an engine's neighbor list must reach for the bridges in use, the
 * design volume of a protocol's reach, and the periodic cell that reach needs.  One rule
 * each, for both engine bindings. */
#include "laws.h"

#include <math.h>

static int range_valid(cb_radius_range r)
{
    return isfinite(r.min) && isfinite(r.max) && r.min > 0.0 && r.min <= r.max;
}

cb_status cb_reach(const cb_law *law, cb_radius_range range1, cb_radius_range range2,
                   double volume, double *design_rupture, double *reach, double *reach_ratio)
{
    if (!law) return CB_ERR_NULL;
    if (!law->prepared) return CB_ERR_RANGE;
    if (!isfinite(volume)) return CB_ERR_NOT_FINITE;
    if (volume < 0.0) return CB_ERR_NEGATIVE;
    /* surface 2 a plane (a wall): the one "radius" CB_PLANE, and the engine's distance a
     * multiple of r1 alone (LIGGGHTS visits a grain-wall pair within (factor - 1) r1) */
    const int plane = cb_is_plane(range2.min) && cb_is_plane(range2.max);
    if (!range_valid(range1) || !(plane || range_valid(range2))) return CB_ERR_RANGE;
    double largest = 0.0, ratio = 0.0;
    if (volume > 0.0) {
        cb_law extended = *law; /* shallow: the table stays the caller's */
        extended.validity = CB_VALIDITY_EXTEND;
        enum { STEPS = 4 };
        for (int a = 0; a <= STEPS; ++a)
            for (int b = 0; b <= (plane ? 0 : STEPS); ++b) {
                /* the ends exactly (min + (max - min) * 1 may round off max) */
                double r1 = a == STEPS ? range1.max
                                       : range1.min + (range1.max - range1.min) * a / STEPS;
                double r2 = plane ? CB_PLANE
                            : b == STEPS ? range2.max
                                         : range2.min + (range2.max - range2.min) * b / STEPS;
                double d = 0.0;
                cb_status status = cb_rupture_distance(&extended, r1, r2, volume, &d);
                if (status != CB_OK) return status;
                if (d > largest) largest = d;
                const double distance_unit = plane ? r1 : r1 + r2;
                if (d / distance_unit > ratio) ratio = d / distance_unit;
            }
    }
    const double margin = 1.0 + CB_REACH_MARGIN;
    if (!isfinite(largest * margin)) return CB_ERR_RANGE;
    if (design_rupture) *design_rupture = largest;
    if (reach) *reach = largest * margin;
    if (reach_ratio) *reach_ratio = ratio * margin;
    return CB_OK;
}

cb_status cb_protocol_design_volume(double total_liquid, double grains, cb_radius_range radii,
                                    double largest_free_liquid, double *volume)
{
    if (!volume) return CB_ERR_NULL;
    if (!isfinite(total_liquid) || !isfinite(grains) || !isfinite(largest_free_liquid))
        return CB_ERR_NOT_FINITE;
    if (total_liquid < 0.0 || grains < 0.0 || largest_free_liquid < 0.0) return CB_ERR_NEGATIVE;
    if (!range_valid(radii)) return CB_ERR_RANGE;
    double ratio = radii.max / radii.min;
    double protocol1 = grains > 0.0 ? 2.0 * total_liquid / grains * ratio * ratio * ratio : 0.0;
    double protocol2 = 2.0 * largest_free_liquid;
    double v = protocol1 > protocol2 ? protocol1 : protocol2;
    if (!isfinite(v)) return CB_ERR_RANGE;
    *volume = v;
    return CB_OK;
}

void cb_cell_widths(const double inverse[6], double width[3])
{
    /* rows of the upper-triangular h^-1 (xx xy xz / 0 yy yz / 0 0 zz) */
    width[0] = 1.0 / sqrt(inverse[0] * inverse[0] + inverse[5] * inverse[5] +
                          inverse[4] * inverse[4]);
    width[1] = 1.0 / sqrt(inverse[1] * inverse[1] + inverse[3] * inverse[3]);
    width[2] = 1.0 / fabs(inverse[2]);
}

int cb_periodic_too_narrow(const double width[3], const int periodic[3], double cutoff)
{
    for (int d = 0; d < 3; ++d)
        if (periodic[d] && !(width[d] >= 2.0 * cutoff)) return d;
    return -1;
}
