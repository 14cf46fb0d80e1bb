/* bridge.c — the state of one pair's liquid bridge and its transitions.
 *
 *   dry    --(gap <= 0 and available_volume > 0)-->  formed: volume = available_volume
 *   active --(gap <= rupture distance of its volume)--> held (always held in overlap)
 *   active --(gap >  rupture distance of its volume)--> ruptured: the whole volume is
 *                                                       released, the state is zeroed
 *
 * A bridge forms only at contact (Richefeu 2007 §2.2: a bridge exists from contact up to
 * the debonding distance; it does not re-form across a gap). The rupture distance is the
 * law's own rule (cb_rupture_distance), evaluated for the bridge's volume; the bridge is
 * kept at exactly that distance and removed at the first gap beyond it (Richefeu 2007 after
 * eq. 11: "removed as soon as the debonding distance is reached" — we read "reached" as
 * "passed", so that the force of eq. 10, defined up to and including delta_max, is never
 * cut inside its own domain).
 *
 * cb_bridge_step is the engines' call in their pair loop: the update and then the force of
 * the bridge's new state (cb_force), sharing one pair and one rupture distance.
 *
 * The state is validated before anything is changed, and all outputs are written together
 * at the end: on any error the bridge, the transition, the released volume and the force
 * are left exactly as they were.
 */
#include "laws.h"

#include <math.h>

/* A stored state is one of exactly two shapes: dry {0, 0} or active {V > 0, 1}.
 * Anything else (e.g. a corrupted pair history) is an error, never silently repaired:
 * repairing it would create or lose liquid. */
static cb_status check_state(const cb_bridge *bridge)
{
    if (!isfinite(bridge->volume) || !isfinite(bridge->active)) return CB_ERR_NOT_FINITE;
    if (bridge->volume < 0.0) return CB_ERR_NEGATIVE;
    if (bridge->active == 1.0) return bridge->volume > 0.0 ? CB_OK : CB_ERR_NEGATIVE;
    if (bridge->active == 0.0) return bridge->volume == 0.0 ? CB_OK : CB_ERR_RANGE;
    return CB_ERR_RANGE;
}

/* The next state of a bridge (both public calls below). *pair is made for the bridge's
 * volume when it is stretched (gap > 0) or formed now, then with *rupture its rupture
 * distance (else *rupture is 0), and when want_pair is set. */
static cb_status advance(const cb_law *law, double r1, double r2, double gap,
                         double available_volume, const cb_bridge *bridge, int want_pair,
                         cb_bridge *next, cb_transition *change, double *released,
                         cb_pair *pair, double *rupture)
{
    if (!law->prepared) return CB_ERR_RANGE;
    if (!isfinite(r1) || !isfinite(r2) || !isfinite(gap) || !isfinite(available_volume))
        return CB_ERR_NOT_FINITE;
    if (r1 <= 0.0 || r2 <= 0.0 || available_volume < 0.0) return CB_ERR_NEGATIVE;
    cb_status status = check_state(bridge);
    if (status != CB_OK) return status;

    *next = *bridge;
    *released = 0.0;
    *rupture = 0.0;
    if (bridge->active == 1.0) {
        *change = CB_BRIDGE_HELD;
        /* In contact the rupture distance (> 0) cannot be exceeded: not evaluated. */
        if (gap > 0.0 || want_pair) *pair = cb_pair_make(law, r1, r2, bridge->volume);
        if (gap > 0.0) {
            status = cb_pair_rupture(law, pair, rupture);
            if (status != CB_OK) return status;
            if (gap > *rupture) {
                *change = CB_BRIDGE_RUPTURED;
                *released = bridge->volume;
                next->volume = 0.0;
                next->active = 0.0;
            }
        }
    } else if (gap <= 0.0 && available_volume > 0.0) {
        /* Ask the law for the rupture distance of the new bridge once: a volume the law
         * refuses (validity strict, or beyond the table) is reported now, at formation,
         * not at the first force call — and no bridge is formed. */
        *pair = cb_pair_make(law, r1, r2, available_volume);
        status = cb_pair_rupture(law, pair, rupture);
        if (status != CB_OK) return status;
        *change = CB_BRIDGE_FORMED;
        next->volume = available_volume;
        next->active = 1.0;
    } else {
        *change = CB_BRIDGE_STAYS_DRY;
    }
    return CB_OK;
}

cb_status cb_bridge_update(const cb_law *law, double r1, double r2, double gap,
                           double available_volume, cb_bridge *bridge,
                           cb_transition *transition, double *released_volume)
{
    if (!law || !bridge || !transition || !released_volume) return CB_ERR_NULL;
    cb_bridge next;
    cb_transition change;
    cb_pair pair;
    double released = 0.0, rupture = 0.0;
    cb_status status = advance(law, r1, r2, gap, available_volume, bridge, 0, &next, &change,
                               &released, &pair, &rupture);
    if (status != CB_OK) return status;
    *bridge = next;
    *transition = change;
    *released_volume = released;
    return CB_OK;
}

cb_status cb_bridge_step(const cb_law *law, double r1, double r2, double gap,
                         double available_volume, cb_bridge *bridge, cb_transition *transition,
                         double *released_volume, double *force)
{
    if (!law || !bridge || !transition || !released_volume || !force) return CB_ERR_NULL;
    cb_bridge next;
    cb_transition change;
    cb_pair pair;
    double released = 0.0, rupture = 0.0, f = 0.0;
    cb_status status = advance(law, r1, r2, gap, available_volume, bridge, 1, &next, &change,
                               &released, &pair, &rupture);
    if (status != CB_OK) return status;
    if (next.active == 1.0) {
        status = cb_pair_force(law, &pair, rupture, gap, &f, NULL);
        if (status != CB_OK) return status;
    }
    *bridge = next;
    *transition = change;
    *released_volume = released;
    *force = f;
    return CB_OK;
}
