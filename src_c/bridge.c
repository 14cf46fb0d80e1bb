/* bridge.c — the state of one pair's liquid bridge and its transitions.
 *
 *   dry    --(gap <= 0 and available_volume > 0)-->  formed: volume = available_volume
 *   active --(gap <= rupture distance of its volume)--> held (always held in overlap)
 *   active --(gap >  rupture distance of its volume)--> ruptured: the whole volume is
 *                                                       released, the state is zeroed
 *   active --(cb_bridge_remove, removal.c)-->  removed: dry, marked while it overlaps
 *   removed --(gap >= 0)-->  dry (and may form at gap 0); removed at gap < 0 stays so
 *
 * A bridge forms only at contact (Richefeu 2007 §2.2: a bridge exists from contact up to
 * the debonding distance; it does not re-form across a gap). The rupture distance is the
 * law's own rule (cb_rupture_distance), evaluated for the bridge's volume; the bridge is
 * kept at exactly that distance and removed at the first gap beyond it (Richefeu 2007 after
 * eq. 11: "removed as soon as the debonding distance is reached" — we read "reached" as
 * "passed", so that the force of eq. 10, defined up to and including delta_max, is never
 * cut inside its own domain).
 *
 * A bridge keeps with its volume its rupture distance and its force at contact (derive
 * below), so that the engines' per-step call, cb_bridge_step, evaluates the force law only
 * for a stretched bridge, and the rupture rule (a cube root) only when the constants are
 * derived.  In a dense packing most bridges are in contact: this took a third off the pair
 * time of the benchmark scene.
 *
 * Every state is validated before anything is changed, and all outputs are written
 * together at the end: on any error the bridge, the transition, the released volume and
 * the force are left exactly as they were.
 */
#include "laws.h"

#include <float.h>
#include <math.h>

static const cb_bridge dry_bridge = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};

/* A stored state is one of exactly three shapes: dry (all zero), removed (dry but rupture
 * CB_BRIDGE_REMOVED) or active {V > 0, 1, with
 * constants that a derivation can give: rupture > 0, contact force >= 0, radii > 0 (at a
 * plane the sum and product INFINITY, both), law constant >= 0 (0: the force is evaluated
 * in full, always correct)}.
 * Anything else (e.g. a corrupted pair history) is an error, never silently repaired:
 * repairing it would create or lose liquid. */
cb_status cb_bridge_check_state(const cb_bridge *b)
{
    if (!b) return CB_ERR_NULL;
    int valid;
    if (b->active == 1.0)
        valid = b->volume > 0.0 && b->volume <= DBL_MAX && b->rupture > 0.0 &&
                b->rupture <= DBL_MAX && b->force_contact >= 0.0 &&
                b->force_contact <= DBL_MAX && b->radius_sum > 0.0 &&
                b->radius_product > 0.0 &&
                ((b->radius_sum <= DBL_MAX && b->radius_product <= DBL_MAX) ||
                 (b->radius_sum == INFINITY && b->radius_product == INFINITY)) &&
                b->law_constant >= 0.0 && b->law_constant <= DBL_MAX;
    else
        valid = b->active == 0.0 && b->volume == 0.0 &&
                (b->rupture == 0.0 || b->rupture == CB_BRIDGE_REMOVED) &&
                b->force_contact == 0.0 && b->radius_sum == 0.0 && b->radius_product == 0.0 &&
                b->law_constant == 0.0;
    return valid ? CB_OK : CB_ERR_BRIDGE_STATE;
}

static cb_status check_inputs(const cb_law *law, double r1, double r2, double gap,
                              double volume)
{
    if (!law->prepared) return CB_ERR_RANGE;
    if (!isfinite(r1) || !cb_finite_or_plane(r2) || !isfinite(gap) || !isfinite(volume))
        return CB_ERR_NOT_FINITE;
    if (r1 <= 0.0 || r2 <= 0.0 || volume < 0.0) return CB_ERR_NEGATIVE;
    return CB_OK;
}

/* An active bridge of this volume between these radii: its rupture distance and its force
 * at contact, by the same calls as cb_rupture_distance and cb_force, and its law's
 * constant (the law's row, laws.h). A volume the law
 * refuses (validity strict, or beyond the table) is reported here, and *out is untouched. */
static cb_status derive(const cb_law *law, double r1, double r2, double volume, cb_bridge *out)
{
    cb_pair pair;
    cb_pair_make(law, r1, r2, volume, &pair);
    double rupture = 0.0, force = 0.0;
    cb_status status = cb_pair_rupture(law, &pair, &rupture);
    if (status != CB_OK) return status;
    status = cb_pair_force(law, &pair, rupture, 0.0, &force, NULL);
    if (status != CB_OK) return status;
    out->volume = volume;
    out->active = 1.0;
    out->rupture = rupture;
    out->force_contact = force;
    out->radius_sum = r1 + r2;
    out->radius_product = r1 * r2;
    out->law_constant = cb_law_ops_of(law)->bridge_constant(law, &pair);
    return CB_OK;
}

/* The constants are those of these radii (both symmetric in r1, r2, exactly). */
static int derived_for(const cb_bridge *b, double r1, double r2)
{
    return b->radius_sum == r1 + r2 && b->radius_product == r1 * r2;
}

/* The next state of a valid bridge. */
static cb_status advance(const cb_law *law, double r1, double r2, double gap,
                         double available_volume, const cb_bridge *bridge, cb_bridge *next,
                         cb_transition *change, double *released)
{
    *next = *bridge;
    *released = 0.0;
    if (bridge->active == 1.0) {
        *change = CB_BRIDGE_HELD;
        if (!derived_for(bridge, r1, r2)) {
            cb_status status = derive(law, r1, r2, bridge->volume, next);
            if (status != CB_OK) return status;
        }
        /* In contact the rupture distance (> 0) cannot be exceeded. */
        if (gap > next->rupture) {
            *change = CB_BRIDGE_RUPTURED;
            *released = bridge->volume;
            *next = dry_bridge;
        }
    } else if (cb_bridge_may_form(bridge, gap) && available_volume > 0.0) {
        /* A volume the law refuses is reported now, at formation, not at the first force
         * call — and no bridge is formed. */
        cb_status status = derive(law, r1, r2, available_volume, next);
        if (status != CB_OK) return status;
        *change = CB_BRIDGE_FORMED;
    } else {
        *change = CB_BRIDGE_STAYS_DRY;
        if (gap >= 0.0) *next = dry_bridge;  /* a removed pair's mark goes: the contact opened */
    }
    return CB_OK;
}

/* The force of a valid bridge whose constants are for r1, r2. */
static cb_status force_of(const cb_law *law, double r1, double r2, double gap,
                          const cb_bridge *bridge, double *force)
{
    if (bridge->active != 1.0) {
        *force = 0.0;
        return CB_OK;
    }
    /* From the stored constants where they give it inline (in contact: always, for a valid
     * bridge with these constants; stretched, richefeu: one exponential instead of a
     * square root, four divisions and the exponential, x0.96-0.98 of the benchmark
     * scene's wet loop, bench/README.md); else through the law's row. */
    if (cb_bridge_held(law, r1, r2, gap, bridge, force)) return CB_OK;
    cb_pair pair;
    cb_pair_geometry(law, r1, r2, bridge->volume, &pair);
    return cb_pair_bridge_force(law, &pair, bridge, gap, force);
}

cb_status cb_bridge_update(const cb_law *law, double r1, double r2, double gap,
                           double available_volume, cb_bridge *bridge,
                           cb_transition *transition, double *released_volume)
{
    if (!law || !bridge || !transition || !released_volume) return CB_ERR_NULL;
    cb_status status = check_inputs(law, r1, r2, gap, available_volume);
    if (status == CB_OK) status = cb_bridge_check_state(bridge);
    if (status != CB_OK) return status;
    cb_bridge next;
    cb_transition change;
    double released = 0.0;
    status = advance(law, r1, r2, gap, available_volume, bridge, &next, &change, &released);
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
    cb_status status = check_inputs(law, r1, r2, gap, available_volume);
    if (status == CB_OK) status = cb_bridge_check_state(bridge);
    if (status != CB_OK) return status;
    cb_bridge next;
    cb_transition change;
    double released = 0.0, f = 0.0;
    status = advance(law, r1, r2, gap, available_volume, bridge, &next, &change, &released);
    if (status == CB_OK) status = force_of(law, r1, r2, gap, &next, &f);
    if (status != CB_OK) return status;
    *bridge = next;
    *transition = change;
    *released_volume = released;
    *force = f;
    return CB_OK;
}

cb_status cb_bridge_force(const cb_law *law, double r1, double r2, double gap,
                          const cb_bridge *bridge, double *force)
{
    if (!law || !bridge || !force) return CB_ERR_NULL;
    cb_status status = check_inputs(law, r1, r2, gap, 0.0);
    if (status == CB_OK) status = cb_bridge_check_state(bridge);
    if (status != CB_OK) return status;
    cb_bridge current = *bridge;
    if (current.active == 1.0 && !derived_for(&current, r1, r2))
        status = derive(law, r1, r2, current.volume, &current);
    if (status != CB_OK) return status;
    return force_of(law, r1, r2, gap, &current, force);
}

cb_status cb_bridge_set_volume(const cb_law *law, double r1, double r2, double volume,
                               cb_bridge *bridge)
{
    if (!law || !bridge) return CB_ERR_NULL;
    cb_status status = check_inputs(law, r1, r2, 0.0, volume);
    if (status == CB_OK) status = cb_bridge_check_state(bridge);
    if (status != CB_OK) return status;
    cb_bridge next = dry_bridge;
    if (volume > 0.0) status = derive(law, r1, r2, volume, &next);
    if (status != CB_OK) return status;
    *bridge = next;
    return CB_OK;
}
