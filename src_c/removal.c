/* removal.c — removing a share of the bridges at random (Richefeu 2007 §3.2, fig. 7, and
 * §4.2.2, fig. 12: the samples "with two times less bonds", the same water content).
 *
 * The choice is a pure function of (seed, pair), not a random stream: an engine meets the
 * pairs in its own order, split over ranks, and with newton off sees a pair twice; a draw
 * from the pair itself gives every rank, engine and order the same removed set.  The hash
 * is splitmix64's finaliser (Steele, Lea & Flood, OOPSLA 2014), applied in turn to the seed
 * and the two ids (the smaller first); its 53 high bits make a double uniform in [0, 1).
 */
#include "capbridge.h"

#include <math.h>
#include <stdint.h>

static uint64_t mix(uint64_t z)
{
    z += UINT64_C(0x9e3779b97f4a7c15);
    z = (z ^ (z >> 30)) * UINT64_C(0xbf58476d1ce4e5b9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94d049bb133111eb);
    return z ^ (z >> 31);
}

cb_status cb_bridge_removal_chosen(double fraction, unsigned long long seed, long long id1,
                                   long long id2, int *chosen)
{
    if (!chosen) return CB_ERR_NULL;
    if (!(fraction >= 0.0 && fraction <= 1.0) || id1 == id2) return CB_ERR_RANGE;
    const long long low = id1 < id2 ? id1 : id2, high = id1 < id2 ? id2 : id1;
    const uint64_t h = mix(mix(mix((uint64_t)seed) ^ (uint64_t)low) ^ (uint64_t)high);
    const double draw = (double)(h >> 11) * 0x1.0p-53;
    *chosen = draw < fraction;
    return CB_OK;
}

cb_status cb_bridge_remove(double gap, cb_bridge *bridge, double *released_volume)
{
    if (!bridge || !released_volume) return CB_ERR_NULL;
    if (isnan(gap)) return CB_ERR_NOT_FINITE;
    cb_status status = cb_bridge_check_state(bridge);
    if (status != CB_OK) return status;
    double released = 0.0;
    if (bridge->active == 1.0) {
        static const cb_bridge dry = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
        released = bridge->volume;
        *bridge = dry;
        if (gap < 0.0) bridge->rupture = CB_BRIDGE_REMOVED;
    }
    *released_volume = released;
    return CB_OK;
}
