/* protocols.c — Richefeu 2007 Protocols 2 and 3: where the liquid of a broken bridge goes.
 *
 * Protocol 2 (§3.2): the volume of a broken bridge "is split between the corresponding
 * particles (proportionally to their diameters)" and kept by them as free liquid, used
 * only when a new bridge forms with one of them; the new bridge takes it all.
 * Protocol 3 (§4.2): the volume is shared by the two particles in proportion to their
 * sizes, and each share goes to "the lowest contact located on the lower hemisphere" of
 * its particle (the engine finds the contacts; cb_protocol3_receiver picks one).
 *
 * The split is exact: the two shares add up to the volume with no rounding at all
 * (see split()), so liquid is neither created nor lost by splitting.
 * A plane (r2 = CB_PLANE, a wall) holds no liquid: the grain's share is the whole volume.
 */
#include "laws.h"

#include <limits.h>
#include <math.h>

/* Split `volume` in proportion to r1 : r2 (diameters are proportional to radii).
 * The larger particle's share is computed by multiplication; it is >= volume / 2, so the
 * other share, volume - larger, is exact (Sterbenz; with subnormals the difference of two
 * numbers on the same grid is exact too). Hence share1 + share2 == volume exactly, and
 * the split of (volume, r1, r2) is the mirror image of the split of (volume, r2, r1).
 * Inputs must be finite with volume >= 0 and r1, r2 > 0. */
static void split(double volume, double r1, double r2, double *share1, double *share2)
{
    if (cb_is_plane(r2)) { /* the wall holds no liquid */
        *share1 = volume;
        *share2 = 0.0;
        return;
    }
    /* large / (large + small) as 1 / (1 + small / large): r1 + r2 may overflow, the ratio
     * (in (0, 1]) cannot */
    if (r1 >= r2) {
        *share1 = volume / (1.0 + r2 / r1);
        *share2 = volume - *share1;
    } else {
        *share2 = volume / (1.0 + r1 / r2);
        *share1 = volume - *share2;
    }
}

/* Returns 0 for inputs outside its domain (non-finite, volume < 0, a radius <= 0): it
 * cannot return a status, and a NaN must not leave the core. Callers that need the
 * distinction validate first (cb_protocol2_release does). */
double cb_protocol_share(double volume, double r1, double r2)
{
    if (!isfinite(volume) || !isfinite(r1) || !cb_finite_or_plane(r2)) return 0.0;
    if (volume < 0.0 || r1 <= 0.0 || r2 <= 0.0) return 0.0;
    double share1, share2;
    split(volume, r1, r2, &share1, &share2);
    return share1;
}

static cb_status check_free(double free_volume)
{
    if (!isfinite(free_volume)) return CB_ERR_NOT_FINITE;
    if (free_volume < 0.0) return CB_ERR_NEGATIVE;
    return CB_OK;
}

cb_status cb_protocol2_release(double volume, double r1, double r2, double *free1,
                               double *free2)
{
    if (!free1 || !free2) return CB_ERR_NULL;
    /* One particle cannot be both ends: the second write would drop the first share. */
    if (free1 == free2) return CB_ERR_LIQUID;
    if (!isfinite(volume) || !isfinite(r1) || !cb_finite_or_plane(r2))
        return CB_ERR_NOT_FINITE;
    if (volume < 0.0 || r1 <= 0.0 || r2 <= 0.0) return CB_ERR_NEGATIVE;
    cb_status status = check_free(*free1);
    if (status == CB_OK) status = check_free(*free2);
    if (status != CB_OK) return status;

    double share1, share2;
    split(volume, r1, r2, &share1, &share2);
    double next1 = *free1 + share1;
    double next2 = *free2 + share2;
    if (!isfinite(next1) || !isfinite(next2)) return CB_ERR_RANGE;
    *free1 = next1;
    *free2 = next2;
    return CB_OK;
}

cb_status cb_protocol2_take(double *free1, double *free2, double *bridge_volume)
{
    if (!free1 || !free2 || !bridge_volume) return CB_ERR_NULL;
    /* The same particle's liquid counted twice would create liquid. */
    if (free1 == free2) return CB_ERR_LIQUID;
    cb_status status = check_free(*free1);
    if (status == CB_OK) status = check_free(*free2);
    if (status != CB_OK) return status;
    double taken = *free1 + *free2;
    if (!isfinite(taken)) return CB_ERR_RANGE;
    *free1 = 0.0;
    *free2 = 0.0;
    *bridge_volume = taken; /* last: bridge_volume may alias free1 or free2 */
    return CB_OK;
}

/* The lowest contact point strictly below the centre; a contact exactly at the centre's
 * height (on the equator) is not on the lower hemisphere. Ties go to the lowest index, so
 * the choice does not depend on anything but the input order. */
cb_status cb_protocol3_receiver(double centre_height, const double *contact_height, size_t n,
                                long *index)
{
    if (!index || (n > 0 && !contact_height)) return CB_ERR_NULL;
    if (n > (size_t)LONG_MAX) return CB_ERR_RANGE;
    if (!isfinite(centre_height)) return CB_ERR_NOT_FINITE;
    for (size_t i = 0; i < n; ++i)
        if (!isfinite(contact_height[i])) return CB_ERR_NOT_FINITE;

    long best = -1;
    for (size_t i = 0; i < n; ++i) {
        double h = contact_height[i];
        if (h < centre_height && (best < 0 || h < contact_height[best])) best = (long)i;
    }
    *index = best;
    return CB_OK;
}

int cb_protocol3_better(double offset, long long partner, double best_offset,
                        long long best_partner)
{
    double heights[2];
    size_t n = 0;
    if (best_partner != 0) heights[n++] = best_offset;
    heights[n++] = offset;
    long index = -1;
    if (cb_protocol3_receiver(0.0, heights, n, &index) != CB_OK || index < 0) return 0;
    if (n == 1 || index == 1) return 1;
    /* the receiver rule keeps the first of equal heights: the tie goes by id */
    return offset == best_offset && partner < best_partner;
}

cb_status cb_protocol_grain_step(double released, int to_receiver, double new_contacts,
                                 double *free_liquid, double *deposit, double *offer)
{
    if (!free_liquid || !deposit || !offer) return CB_ERR_NULL;
    if (!isfinite(released) || !isfinite(new_contacts) || !isfinite(*free_liquid))
        return CB_ERR_NOT_FINITE;
    if (released < 0.0 || new_contacts < 0.0 || *free_liquid < 0.0) return CB_ERR_NEGATIVE;
    double free_now = *free_liquid, deposited = 0.0, offered = 0.0;
    if (released > 0.0) {
        if (to_receiver)
            deposited = released;
        else
            free_now += released;
    }
    if (new_contacts > 0.0 && free_now > 0.0) {
        offered = free_now / new_contacts;
        free_now = 0.0;
    }
    if (!isfinite(free_now)) return CB_ERR_RANGE;
    *free_liquid = free_now;
    *deposit = deposited;
    *offer = offered;
    return CB_OK;
}
