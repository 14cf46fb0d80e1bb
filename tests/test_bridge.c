/* test_bridge.c — the bridge state and its transitions (cb_bridge_update), and
 * cb_bridge_step: every update below is made by both calls, which must agree bit for bit,
 * and the step's force (and cb_bridge_force's) must be cb_force of the new state: the
 * constants a bridge keeps (its rupture distance and force at contact) are checked against
 * the stateless calls that evaluate the law every time.
 *
 * Rupture distances are recomputed here from the published formulas (Richefeu eq. 6 for
 * Lian's rule, Gladkyy eq. 2 for Willett's), not taken from the library, wherever the
 * test needs a number; the library's own cb_rupture_distance is used only where the test
 * is about the exact boundary (held at d, ruptured just beyond). */
#include "capbridge.h"
#include "check.h"
#include "test_law.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#define PI_L 3.14159265358979323846264338327950288L

/* Richefeu 2007 eq. 6 (Lian 1998): (1 + theta/2) V^(1/3), theta in radians. */
static double lian_reference(double theta_degrees, double volume)
{
    long double theta = theta_degrees * PI_L / 180.0L;
    return (double)((1.0L + theta / 2.0L) * cbrtl((long double)volume));
}

/* Gladkyy 2014 eq. 2 (Willett 2000): R_h (1 + theta/2) (V*^(1/3) + V*^(2/3) / 10). */
static double willett_reference(double theta_degrees, double r1, double r2, double volume)
{
    long double theta = theta_degrees * PI_L / 180.0L;
    long double rh = 2.0L * r1 * r2 / ((long double)r1 + r2);
    long double v = volume / (rh * rh * rh);
    return (double)(rh * (1.0L + theta / 2.0L) * (cbrtl(v) + cbrtl(v * v) / 10.0L));
}

static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* One update, checking the status; returns the transition. cb_bridge_step makes the same
 * update on a copy: same state, transition and release, and the force of the new state
 * (cb_force, or 0 without a bridge). */
static cb_transition step(const cb_law *law, double r1, double r2, double gap, double available,
                          cb_bridge *bridge, double *released)
{
    cb_bridge copy = *bridge, before = *bridge;
    double inline_force = -1.0;
    const int held_inline = cb_bridge_held(law, r1, r2, gap, bridge, &inline_force);
    cb_transition t = (cb_transition)-1, t_step = (cb_transition)-2;
    double released_step = -2.0, force = -1.0;
    CHECK_STATUS(cb_bridge_update(law, r1, r2, gap, available, bridge, &t, released), CB_OK);
    CHECK_STATUS(cb_bridge_step(law, r1, r2, gap, available, &copy, &t_step, &released_step,
                                &force),
                 CB_OK);
    CHECK(memcmp(&copy, bridge, sizeof copy) == 0 && t_step == t &&
          same_bits(released_step, *released));
    double expected_force = 0.0;
    if (bridge->active == 1.0)
        CHECK_STATUS(cb_force(law, r1, r2, bridge->volume, gap, &expected_force, NULL), CB_OK);
    CHECK(same_bits(force, expected_force));
    double bridge_force = -1.0;
    CHECK_STATUS(cb_bridge_force(law, r1, r2, gap, bridge, &bridge_force), CB_OK);
    CHECK(same_bits(bridge_force, expected_force));
    /* the inline shortcut, where it applies: held, unchanged, the same force */
    if (held_inline)
        CHECK(t == CB_BRIDGE_HELD && memcmp(&before, bridge, sizeof before) == 0 &&
              same_bits(inline_force, expected_force));
    else
        CHECK(inline_force == -1.0);
    return t;
}

/* An active bridge of this volume, as a liquid protocol makes it. */
static cb_bridge active_bridge(const cb_law *law, double r1, double r2, double volume)
{
    cb_bridge b = {0};
    CHECK_STATUS(cb_bridge_set_volume(law, r1, r2, volume, &b), CB_OK);
    CHECK(b.active == 1.0 && same_bits(b.volume, volume));
    return b;
}

/* The full life cycle on a scripted gap sequence, for a law whose rupture distance for
 * (r1, r2, volume) is `expected_rupture` by the published formula. */
static void life_cycle(const cb_law *law, double r1, double r2, double volume,
                       double expected_rupture)
{
    cb_bridge b = {0};
    double released = -1.0;
    double d = 0.0;
    CHECK_STATUS(cb_rupture_distance(law, r1, r2, volume, &d), CB_OK);
    CHECK_REL(d, expected_rupture, 1e-14);

    /* Dry and apart, liquid on offer: no bridge across a gap. */
    CHECK(step(law, r1, r2, 0.5 * d, volume, &b, &released) == CB_BRIDGE_STAYS_DRY);
    CHECK(b.volume == 0.0 && b.active == 0.0 && released == 0.0);
    /* Contact but no liquid: no bridge. */
    CHECK(step(law, r1, r2, 0.0, 0.0, &b, &released) == CB_BRIDGE_STAYS_DRY);
    CHECK(step(law, r1, r2, -1e-6, 0.0, &b, &released) == CB_BRIDGE_STAYS_DRY);
    CHECK(b.volume == 0.0 && b.active == 0.0);
    /* Approaching: still apart by a hair. */
    CHECK(step(law, r1, r2, 1e-300, volume, &b, &released) == CB_BRIDGE_STAYS_DRY);
    /* Contact with liquid: formed, with exactly the volume on offer. */
    released = -1.0;
    CHECK(step(law, r1, r2, -1e-7, volume, &b, &released) == CB_BRIDGE_FORMED);
    CHECK(same_bits(b.volume, volume));
    CHECK(b.active == 1.0);
    CHECK(released == 0.0);
    /* Held while the gap grows, whatever is on offer now. */
    const double gaps[] = {-2e-6, 0.0, 1e-300, 0.25 * d, 0.5 * d, 0.999 * d, d};
    const double offers[] = {0.0, 5.0 * volume, 0.0, volume, 1e-3, 0.0, 2.0 * volume};
    for (size_t i = 0; i < sizeof gaps / sizeof gaps[0]; ++i) {
        released = -1.0;
        CHECK(step(law, r1, r2, gaps[i], offers[i], &b, &released) == CB_BRIDGE_HELD);
        CHECK(same_bits(b.volume, volume));
        CHECK(b.active == 1.0);
        CHECK(released == 0.0);
    }
    /* Held at exactly d (repeatedly), ruptured at the first gap beyond it. */
    CHECK(step(law, r1, r2, d, 0.0, &b, &released) == CB_BRIDGE_HELD);
    CHECK(step(law, r1, r2, d * (1.0 + 1e-12), 0.0, &b, &released) == CB_BRIDGE_RUPTURED);
    CHECK(same_bits(released, volume));
    CHECK(b.volume == 0.0 && b.active == 0.0);
    /* After rupture: dry, nothing more released, no re-formation across a gap. */
    CHECK(step(law, r1, r2, 2.0 * d, volume, &b, &released) == CB_BRIDGE_STAYS_DRY);
    CHECK(released == 0.0);
    CHECK(step(law, r1, r2, 0.5 * d, volume, &b, &released) == CB_BRIDGE_STAYS_DRY);
    CHECK(b.active == 0.0);
    /* Back at contact (gap exactly 0 counts as contact): a new bridge. */
    CHECK(step(law, r1, r2, 0.0, 0.5 * volume, &b, &released) == CB_BRIDGE_FORMED);
    CHECK(same_bits(b.volume, 0.5 * volume));

    /* The boundary to the last representable gap: d held, the next double ruptures. */
    cb_bridge c = active_bridge(law, r1, r2, volume);
    CHECK(step(law, r1, r2, d, 0.0, &c, &released) == CB_BRIDGE_HELD);
    CHECK(step(law, r1, r2, nextafter(d, HUGE_VAL), 0.0, &c, &released) ==
          CB_BRIDGE_RUPTURED);
    CHECK(same_bits(released, volume));

    /* Overlap keeps a bridge, however deep. */
    cb_bridge o = active_bridge(law, r1, r2, volume);
    const double overlaps[] = {-1e-9, -1e-5, -0.1 * r1, -r1};
    for (size_t i = 0; i < sizeof overlaps / sizeof overlaps[0]; ++i) {
        CHECK(step(law, r1, r2, overlaps[i], 0.0, &o, &released) == CB_BRIDGE_HELD);
        CHECK(same_bits(o.volume, volume) && o.active == 1.0 && released == 0.0);
    }
}

/* A reference state machine, written from the rules, against random gap sequences. */
static uint64_t rng_state = 0x9E3779B97F4A7C15ull;
static double uniform(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 0x2545F4914F6CDD1Dull) >> 11) * 0x1.0p-53;
}

static void random_sequences(const cb_law *law, double theta_degrees)
{
    int formed = 0, ruptured = 0, held = 0, dry = 0, mismatches = 0;
    for (int run = 0; run < 200; ++run) {
        double r1 = 1e-3 * (0.4 + 0.25 * uniform());
        double r2 = 1e-3 * (0.4 + 0.25 * uniform());
        cb_bridge b = {0};
        double ref_volume = 0.0; /* the reference: 0 when dry */
        double gap = 0.0;
        for (int i = 0; i < 400; ++i) {
            double offer = uniform() < 0.2 ? 0.0 : 1e-12 * (0.1 + 10.0 * uniform());
            /* Volumes of 1e-13..1e-11 m^3 break at gaps of about 50..250 um. */
            gap += 8e-5 * (uniform() - 0.5);
            if (gap > 3e-4) gap = 3e-4;
            if (gap < -1e-5) gap = -1e-5;
            /* Keep clear of the rounding margin of the two formulas. */
            if (ref_volume > 0.0) {
                double dref = lian_reference(theta_degrees, ref_volume);
                if (fabs(gap - dref) <= 1e-12 * dref) gap = dref * (1.0 + 1e-9);
            }
            cb_transition expected;
            double expected_release = 0.0;
            if (ref_volume > 0.0) {
                if (gap > 0.0 && gap > lian_reference(theta_degrees, ref_volume)) {
                    expected = CB_BRIDGE_RUPTURED;
                    expected_release = ref_volume;
                    ref_volume = 0.0;
                } else {
                    expected = CB_BRIDGE_HELD;
                }
            } else if (gap <= 0.0 && offer > 0.0) {
                expected = CB_BRIDGE_FORMED;
                ref_volume = offer;
            } else {
                expected = CB_BRIDGE_STAYS_DRY;
            }
            double released = -1.0;
            cb_transition t = step(law, r1, r2, gap, offer, &b, &released);
            if (t != expected || !same_bits(b.volume, ref_volume) ||
                b.active != (ref_volume > 0.0 ? 1.0 : 0.0) ||
                !same_bits(released, expected_release))
                ++mismatches;
            formed += t == CB_BRIDGE_FORMED;
            ruptured += t == CB_BRIDGE_RUPTURED;
            held += t == CB_BRIDGE_HELD;
            dry += t == CB_BRIDGE_STAYS_DRY;
        }
    }
    CHECK(mismatches == 0);
    printf("random sequences (theta %g): %d formed, %d held, %d ruptured, %d dry\n",
           theta_degrees, formed, held, ruptured, dry);
    /* The sequences must have exercised every transition many times. */
    CHECK(formed > 100 && ruptured > 100 && held > 1000 && dry > 1000);
}

/* An error leaves bridge, transition and released volume untouched. */
static void expect_error(const cb_law *law, double r1, double r2, double gap, double available,
                         cb_bridge state, cb_status expected)
{
    cb_bridge b = state;
    cb_transition t = (cb_transition)77;
    double released = 12345.0, force = 678.0;
    CHECK_STATUS(cb_bridge_update(law, r1, r2, gap, available, &b, &t, &released), expected);
    CHECK(memcmp(&b, &state, sizeof b) == 0);
    CHECK(t == (cb_transition)77);
    CHECK(released == 12345.0);
    CHECK_STATUS(cb_bridge_step(law, r1, r2, gap, available, &b, &t, &released, &force),
                 expected);
    CHECK(memcmp(&b, &state, sizeof b) == 0);
    CHECK(t == (cb_transition)77 && released == 12345.0 && force == 678.0);
}

/* A stored state that is neither dry nor a valid bridge's: refused by the check an engine
 * makes once where a state enters (cb_bridge_check_state) and by every call. */
static void expect_corrupt(const cb_law *law, double r1, double r2, double gap,
                           double available, cb_bridge state)
{
    CHECK_STATUS(cb_bridge_check_state(&state), CB_ERR_BRIDGE_STATE);
    expect_error(law, r1, r2, gap, available, state, CB_ERR_BRIDGE_STATE);
}

static void errors(const cb_law *law)
{
    const double v = 1e-12, r = 5e-4;
    cb_bridge dry = {0}, wet = active_bridge(law, r, r, v);
    cb_transition t;
    double released;
    CHECK_STATUS(cb_bridge_update(NULL, r, r, 0.0, v, &dry, &t, &released), CB_ERR_NULL);
    CHECK_STATUS(cb_bridge_update(law, r, r, 0.0, v, NULL, &t, &released), CB_ERR_NULL);
    CHECK_STATUS(cb_bridge_update(law, r, r, 0.0, v, &dry, NULL, &released), CB_ERR_NULL);
    CHECK_STATUS(cb_bridge_update(law, r, r, 0.0, v, &dry, &t, NULL), CB_ERR_NULL);
    double force = 0.0;
    CHECK_STATUS(cb_bridge_step(NULL, r, r, 0.0, v, &dry, &t, &released, &force), CB_ERR_NULL);
    CHECK_STATUS(cb_bridge_step(law, r, r, 0.0, v, NULL, &t, &released, &force), CB_ERR_NULL);
    CHECK_STATUS(cb_bridge_step(law, r, r, 0.0, v, &dry, NULL, &released, &force), CB_ERR_NULL);
    CHECK_STATUS(cb_bridge_step(law, r, r, 0.0, v, &dry, &t, NULL, &force), CB_ERR_NULL);
    CHECK_STATUS(cb_bridge_step(law, r, r, 0.0, v, &dry, &t, &released, NULL), CB_ERR_NULL);
    CHECK(dry.volume == 0.0 && dry.active == 0.0);

    cb_law unprepared;
    CHECK_STATUS(cb_law_init(&unprepared, CB_MODEL_RICHEFEU, 0.072, 0.0), CB_OK);
    expect_error(&unprepared, r, r, 0.0, v, dry, CB_ERR_RANGE);

    const double bad[] = {NAN, HUGE_VAL, -HUGE_VAL};
    for (int i = 0; i < 3; ++i) {
        expect_error(law, bad[i], r, 0.0, v, dry, CB_ERR_NOT_FINITE);
        if (!cb_is_plane(bad[i])) /* r2 = +inf is a plane (test_wall.c) */
            expect_error(law, r, bad[i], 1e-6, v, wet, CB_ERR_NOT_FINITE);
        expect_error(law, r, r, bad[i], v, wet, CB_ERR_NOT_FINITE);
        expect_error(law, r, r, -1e-6, bad[i], dry, CB_ERR_NOT_FINITE);
        /* any of the doubles of a stored bridge */
        for (int k = 0; k < CB_BRIDGE_DOUBLES; ++k) {
            cb_bridge corrupt = wet;
            ((double *)&corrupt)[k] = bad[i];
            expect_corrupt(law, r, r, 1e-6, v, corrupt);
        }
    }
    expect_error(law, 0.0, r, 0.0, v, dry, CB_ERR_NEGATIVE);
    expect_error(law, r, -r, 0.0, v, wet, CB_ERR_NEGATIVE);
    expect_error(law, r, r, -1e-6, -v, dry, CB_ERR_NEGATIVE);
    expect_error(law, r, r, -1e-6, -0.0 - 1e-300, dry, CB_ERR_NEGATIVE);

    /* States that are neither dry (all zero) nor active {V > 0, 1, constants > 0}. */
    cb_bridge negative = wet, empty_active = wet, liquid_inactive = dry, half = wet, two = wet,
              negative_dry = dry;
    negative.volume = -v;
    empty_active.volume = 0.0;
    liquid_inactive.volume = v;
    half.active = 0.5;
    two.active = 2.0;
    negative_dry.volume = -v;
    expect_corrupt(law, r, r, 1e-6, v, negative);
    expect_corrupt(law, r, r, 1e-6, v, empty_active);
    expect_corrupt(law, r, r, -1e-6, v, liquid_inactive);
    expect_corrupt(law, r, r, 1e-6, v, half);
    expect_corrupt(law, r, r, 1e-6, v, two);
    expect_corrupt(law, r, r, 1e-6, v, negative_dry);
    CHECK_STATUS(cb_bridge_check_state(&dry), CB_OK);
    CHECK_STATUS(cb_bridge_check_state(&wet), CB_OK);
    CHECK_STATUS(cb_bridge_check_state(NULL), CB_ERR_NULL);
    /* an active bridge without its constants, and a dry one with some */
    for (int k = 2; k < CB_BRIDGE_DOUBLES; ++k) {
        cb_bridge zero_constant = wet, negative_constant = wet, dry_constant = dry;
        ((double *)&zero_constant)[k] = 0.0;
        ((double *)&negative_constant)[k] = -1.0;
        ((double *)&dry_constant)[k] = 1.0;
        /* (the contact force may be 0: a law with none at contact; 1/lambda is 0 for
         * every law but richefeu, and for it means "evaluate in full") */
        if (k != 3 && k != 6) expect_corrupt(law, r, r, -1e-6, v, zero_constant);
        else CHECK_STATUS(cb_bridge_check_state(&zero_constant), CB_OK);
        expect_corrupt(law, r, r, -1e-6, v, negative_constant);
        expect_corrupt(law, r, r, -1e-6, v, dry_constant);
    }

    /* -0.0 is a dry volume and a contact gap. */
    cb_bridge minus_zero = {0};
    minus_zero.volume = -0.0;
    CHECK(step(law, r, r, -0.0, v, &minus_zero, &released) == CB_BRIDGE_FORMED);
    CHECK(same_bits(minus_zero.volume, v));
}

/* Validity strict: a volume the law refuses is an error at formation and on the way out;
 * nothing changes. Richefeu's law is fitted for theta = 0 only (its stated validity). */
static void strict_validity(void)
{
    const double v = 1e-12, r = 5e-4;
    cb_law strict = make_law(20.0, NULL, "strict");
    cb_law extend = make_law(20.0, NULL, NULL);
    /* a bridge formed before the law turned strict (new coefficients between two runs) */
    cb_bridge dry = {0}, wet = active_bridge(&extend, r, r, v);
    expect_error(&strict, r, r, -1e-7, v, dry, CB_ERR_OUT_OF_VALIDITY);
    /* Outside the range but nothing to evaluate: dry apart, or its stored rupture
     * distance; a stretched bridge's force is refused, so the step is refused whole. */
    double released = -1.0;
    cb_bridge b = dry;
    CHECK(step(&strict, r, r, 1e-6, v, &b, &released) == CB_BRIDGE_STAYS_DRY);
    b = wet;
    cb_transition t = (cb_transition)-1;
    CHECK_STATUS(cb_bridge_update(&strict, r, r, 1e-6, 0.0, &b, &t, &released), CB_OK);
    CHECK(t == CB_BRIDGE_HELD && memcmp(&b, &wet, sizeof b) == 0);
    double force = 5.0;
    t = (cb_transition)77;
    released = 5.0;
    CHECK_STATUS(cb_bridge_step(&strict, r, r, 1e-6, 0.0, &b, &t, &released, &force),
                 CB_ERR_OUT_OF_VALIDITY);
    CHECK(memcmp(&b, &wet, sizeof b) == 0 && t == (cb_transition)77 && released == 5.0 &&
          force == 5.0);
    /* Deriving the bridge's constants again under the strict law is refused, and leaves
     * it as it was; so is setting a volume the law refuses. */
    b = wet;
    CHECK_STATUS(cb_bridge_set_volume(&strict, r, r, v, &b), CB_ERR_OUT_OF_VALIDITY);
    CHECK(memcmp(&b, &wet, sizeof b) == 0);
    b = dry;
    CHECK_STATUS(cb_bridge_set_volume(&strict, r, r, v, &b), CB_ERR_OUT_OF_VALIDITY);
    CHECK(memcmp(&b, &dry, sizeof b) == 0);
    /* ... and so is a bridge whose grains changed size, which is derived again in overlap */
    expect_error(&strict, r, 1.1 * r, -1e-7, 0.0, wet, CB_ERR_OUT_OF_VALIDITY);
    cb_law_release(&extend);

    cb_law strict_ok = make_law(0.0, NULL, "strict");
    b = dry;
    CHECK(step(&strict_ok, r, r, 0.0, v, &b, &released) == CB_BRIDGE_FORMED);
    CHECK(step(&strict_ok, r, r, 1e-6, v, &b, &released) == CB_BRIDGE_HELD);
    cb_law_release(&strict);
    cb_law_release(&strict_ok);
}

/* The copy the engine keeps in its pair history: CB_BRIDGE_DOUBLES plain doubles. */
static void plain_data(const cb_law *law)
{
    CHECK(sizeof(cb_bridge) == CB_BRIDGE_DOUBLES * sizeof(double));
    double history[CB_BRIDGE_DOUBLES] = {0};
    cb_bridge b;
    memcpy(&b, history, sizeof b);
    double released;
    CHECK(step(law, 5e-4, 6e-4, -1e-8, 3e-12, &b, &released) == CB_BRIDGE_FORMED);
    memcpy(history, &b, sizeof b);
    cb_bridge again;
    memcpy(&again, history, sizeof again);
    CHECK(step(law, 5e-4, 6e-4, 1e-6, 0.0, &again, &released) == CB_BRIDGE_HELD);
    CHECK(same_bits(again.volume, 3e-12));
}

/* The constants a bridge keeps: those of the stateless calls, bit for bit; derived again
 * when the grains change size (not when they only swap places) and, through
 * cb_bridge_set_volume, when the law changes. */
static void derived_constants(void)
{
    const double r1 = 0.5e-3, r2 = 0.62e-3, v = 4e-12;
    cb_law law = make_law(10.0, "willett", NULL); /* Willett's rule depends on the radii */
    cb_bridge b = active_bridge(&law, r1, r2, v);
    double d = 0.0, f0 = 0.0;
    CHECK_STATUS(cb_rupture_distance(&law, r1, r2, v, &d), CB_OK);
    CHECK_STATUS(cb_force(&law, r1, r2, v, 0.0, &f0, NULL), CB_OK);
    CHECK(same_bits(b.rupture, d) && same_bits(b.force_contact, f0) && f0 > 0.0);
    CHECK(b.radius_sum == r1 + r2 && b.radius_product == r1 * r2);

    /* Richefeu eq. 11, lambda = c sqrt(V / (R_h r)), R_h = 2 r1 r2 / (r1 + r2), r = r2/r1,
     * c = 0.9, written out here; a stretched bridge's force from it equals cb_force bit for
     * bit (the same product), and 0 beyond the rupture distance */
    const double lambda = 0.9 * sqrt(v / (2.0 * r1 * r2 / (r1 + r2)) * (r1 / r2));
    CHECK(fabs(b.law_constant * lambda - 1.0) < 1e-14);
    for (double gap = 0.0; gap <= 1.2 * d; gap += 0.05 * d) {
        cb_bridge s = b;
        double ref = 0.0, f = -1.0;
        CHECK_STATUS(cb_force(&law, r1, r2, v, gap, &ref, NULL), CB_OK);
        CHECK_STATUS(cb_bridge_force(&law, r1, r2, gap, &s, &f), CB_OK);
        CHECK(same_bits(f, ref) && (gap <= d || f == 0.0));
    }
    /* another law reading this bridge (its constants not derived again, as the C API
     * allows): the stretched force is that law's, not the stored exponential's */
    cb_law willett_law;
    cb_message msg;
    CHECK_STATUS(cb_law_init(&willett_law, CB_MODEL_WILLETT, 0.072, 0.0), CB_OK);
    CHECK_STATUS(cb_law_prepare(&willett_law, &msg), CB_OK);
    double other = 0.0, other_ref = 0.0;
    CHECK_STATUS(cb_bridge_force(&willett_law, r1, r2, 0.3 * d, &b, &other), CB_OK);
    CHECK_STATUS(cb_force(&willett_law, r1, r2, v, 0.3 * d, &other_ref, NULL), CB_OK);
    CHECK(same_bits(other, other_ref));
    cb_law_release(&willett_law);

    /* the same pair seen from the other grain: nothing to derive */
    cb_bridge swapped = b;
    double released = -1.0;
    CHECK(step(&law, r2, r1, 0.3 * d, 0.0, &swapped, &released) == CB_BRIDGE_HELD);
    CHECK(memcmp(&swapped, &b, sizeof b) == 0);

    /* a grain shrinks or grows: the stored rupture distance no longer holds (Willett's
     * d falls with R_h) */
    const double shrunk = 0.3 * r2, grown = 3.0 * r2;
    double d_shrunk = 0.0, d_grown = 0.0;
    CHECK_STATUS(cb_rupture_distance(&law, r1, shrunk, v, &d_shrunk), CB_OK);
    CHECK_STATUS(cb_rupture_distance(&law, r1, grown, v, &d_grown), CB_OK);
    CHECK(d_shrunk > 1.001 * d && d_grown < 0.999 * d);
    cb_bridge c = b;
    CHECK(step(&law, r1, shrunk, 0.5 * (d + d_shrunk), 0.0, &c, &released) == CB_BRIDGE_HELD);
    CHECK(same_bits(c.rupture, d_shrunk) && c.radius_product == r1 * shrunk);
    c = b;
    CHECK(step(&law, r1, grown, 0.5 * (d + d_grown), 0.0, &c, &released) ==
          CB_BRIDGE_RUPTURED);
    CHECK(same_bits(released, v));
    c = b;
    CHECK(step(&law, r1, grown, -1e-7, 0.0, &c, &released) == CB_BRIDGE_HELD);
    CHECK(same_bits(c.rupture, d_grown));

    /* the law changes: set_volume with the bridge's own volume derives it again */
    cb_law weaker = law;
    CHECK_STATUS(cb_law_configure(&weaker, "gamma", "0.05", &msg), CB_OK);
    CHECK_STATUS(cb_law_prepare(&weaker, &msg), CB_OK);
    c = b;
    CHECK_STATUS(cb_bridge_set_volume(&weaker, r1, r2, c.volume, &c), CB_OK);
    double f_weaker = 0.0;
    CHECK_STATUS(cb_force(&weaker, r1, r2, v, 0.0, &f_weaker, NULL), CB_OK);
    CHECK(same_bits(c.force_contact, f_weaker));
    CHECK_REL(c.force_contact, f0 * 0.05 / 0.072, 1e-14);
    CHECK(step(&weaker, r1, r2, -1e-6, 0.0, &c, &released) == CB_BRIDGE_HELD);

    /* a protocol moves liquid: new constants; volume 0 makes it dry (all zero) */
    c = b;
    CHECK_STATUS(cb_bridge_set_volume(&law, r1, r2, 2.0 * v, &c), CB_OK);
    double d2 = 0.0;
    CHECK_STATUS(cb_rupture_distance(&law, r1, r2, 2.0 * v, &d2), CB_OK);
    CHECK(same_bits(c.rupture, d2) && same_bits(c.volume, 2.0 * v));
    CHECK_STATUS(cb_bridge_set_volume(&law, r1, r2, 0.0, &c), CB_OK);
    const cb_bridge dry = {0};
    CHECK(memcmp(&c, &dry, sizeof c) == 0);

    /* bad input to set_volume and cb_bridge_force: an error, nothing changed */
    const double bad[] = {NAN, HUGE_VAL, -1e-12};
    const cb_status why[] = {CB_ERR_NOT_FINITE, CB_ERR_NOT_FINITE, CB_ERR_NEGATIVE};
    for (int i = 0; i < 3; ++i) {
        c = b;
        CHECK_STATUS(cb_bridge_set_volume(&law, r1, r2, bad[i], &c), why[i]);
        CHECK_STATUS(cb_bridge_set_volume(&law, bad[i], r2, v, &c), why[i]);
        CHECK(memcmp(&c, &b, sizeof c) == 0);
        double force = 3.0;
        if (cb_is_plane(bad[i])) continue; /* r2 = +inf is a plane (test_wall.c) */
        CHECK_STATUS(cb_bridge_force(&law, r1, bad[i], 0.0, &b, &force), why[i]);
        CHECK(force == 3.0);
    }
    double force = 3.0;
    CHECK_STATUS(cb_bridge_force(&law, r1, r2, NAN, &b, &force), CB_ERR_NOT_FINITE);
    CHECK_STATUS(cb_bridge_force(NULL, r1, r2, 0.0, &b, &force), CB_ERR_NULL);
    CHECK_STATUS(cb_bridge_force(&law, r1, r2, 0.0, NULL, &force), CB_ERR_NULL);
    CHECK_STATUS(cb_bridge_force(&law, r1, r2, 0.0, &b, NULL), CB_ERR_NULL);
    CHECK_STATUS(cb_bridge_set_volume(NULL, r1, r2, v, &c), CB_ERR_NULL);
    CHECK_STATUS(cb_bridge_set_volume(&law, r1, r2, v, NULL), CB_ERR_NULL);
    cb_bridge corrupt = b;
    corrupt.active = 0.5;
    c = corrupt;
    CHECK_STATUS(cb_bridge_set_volume(&law, r1, r2, v, &c), CB_ERR_BRIDGE_STATE);
    CHECK(memcmp(&c, &corrupt, sizeof c) == 0);
    CHECK(force == 3.0);

    /* the inline shortcut applies to exactly the bridges held with these constants: in
     * contact, or (richefeu, not strict) stretched within the rupture distance, where its
     * force is cb_force's bit for bit */
    double quick = -1.0;
    CHECK(cb_bridge_held(&law, r1, r2, -1e-7, &b, &quick) && same_bits(quick, f0));
    CHECK(cb_bridge_held(&law, r2, r1, 0.0, &b, &quick) && same_bits(quick, f0));
    const double stretched[] = {1e-12, 0.5 * d, d};
    for (int k = 0; k < 3; ++k) {
        double ref = 0.0;
        CHECK_STATUS(cb_force(&law, r1, r2, v, stretched[k], &ref, NULL), CB_OK);
        quick = -1.0;
        CHECK(cb_bridge_held(&law, r1, r2, stretched[k], &b, &quick) && same_bits(quick, ref) &&
              ref > 0.0);
    }
    quick = -1.0;
    CHECK(!cb_bridge_held(&law, r1, r2, nextafter(d, 1.0), &b, &quick)); /* to rupture */
    CHECK(!cb_bridge_held(&law, r1, r2, NAN, &b, &quick));
    CHECK(!cb_bridge_held(&law, r1, 1.01 * r2, -1e-7, &b, &quick));
    CHECK(!cb_bridge_held(&law, r1, r2, -1e-7, &dry, &quick));
    CHECK(!cb_bridge_held(&law, r1, r2, 1e-9, &dry, &quick));
    CHECK(!cb_bridge_held(&law, r1, r2, -HUGE_VAL, &b, &quick));
    /* a corrupted state is the engine's check's to refuse, where it enters (the held path
     * reads only the fields it uses); the flag of a bridge that is not active, the held
     * path too */
    const double broken[] = {NAN, -1.0, HUGE_VAL};
    for (int k = 0; k < 3; ++k) {
        cb_bridge bad_force = b, bad_volume = b, bad_flag = b, bad_rupture = b, bad_decay = b;
        bad_force.force_contact = broken[k];
        bad_volume.volume = broken[k];
        bad_flag.active = k == 0 ? NAN : 0.5;
        bad_rupture.rupture = broken[k];
        bad_decay.law_constant = broken[k];
        CHECK_STATUS(cb_bridge_check_state(&bad_force), CB_ERR_BRIDGE_STATE);
        CHECK_STATUS(cb_bridge_check_state(&bad_volume), CB_ERR_BRIDGE_STATE);
        CHECK_STATUS(cb_bridge_check_state(&bad_flag), CB_ERR_BRIDGE_STATE);
        CHECK_STATUS(cb_bridge_check_state(&bad_rupture), CB_ERR_BRIDGE_STATE);
        CHECK_STATUS(cb_bridge_check_state(&bad_decay), CB_ERR_BRIDGE_STATE);
        CHECK(!cb_bridge_held(&law, r1, r2, -1e-7, &bad_flag, &quick));
    }
    /* stretched, the call where the stored constants do not give the force: 1/lambda 0
     * (the full evaluation), a strict law, another law reading the bridge */
    cb_bridge no_decay = b;
    no_decay.law_constant = 0.0;
    CHECK(!cb_bridge_held(&law, r1, r2, 0.5 * d, &no_decay, &quick));
    cb_law strict_copy = law;
    strict_copy.validity = CB_VALIDITY_STRICT;
    CHECK(!cb_bridge_held(&strict_copy, r1, r2, 0.5 * d, &b, &quick));
    cb_law other_model = law;
    other_model.model = CB_MODEL_WILLETT;
    CHECK(!cb_bridge_held(&other_model, r1, r2, 0.5 * d, &b, &quick));
    CHECK(quick == -1.0);

    /* Gladkyy eq. 4 (overlap none): the stored contact force applies at gap 0 only */
    cb_law no_overlap = law;
    CHECK_STATUS(cb_law_configure(&no_overlap, "overlap", "none", &msg), CB_OK);
    CHECK_STATUS(cb_law_prepare(&no_overlap, &msg), CB_OK);
    c = active_bridge(&no_overlap, r1, r2, v);
    CHECK_STATUS(cb_bridge_force(&no_overlap, r1, r2, -1e-7, &c, &force), CB_OK);
    CHECK(force == 0.0);
    CHECK(step(&no_overlap, r1, r2, 0.0, 0.0, &c, &released) == CB_BRIDGE_HELD);
    CHECK(step(&no_overlap, r1, r2, -1e-7, 0.0, &c, &released) == CB_BRIDGE_HELD);
    cb_law_release(&law);
}

/* cb_bridge_held accepts exactly what cb_bridge_step holds, for every state that passes the
 * engines' entry check (cb_bridge_check_state): wherever the inline shortcut returns 1, the
 * call returns CB_OK, CB_BRIDGE_HELD and the same force bit for bit; a state the check
 * refuses, the call refuses too.  The reproducer of issue 16 item 5 (in contact, rupture
 * distance 0), then every field of a valid bridge replaced by a hostile value, at hostile
 * gaps (NaN, infinite) too. */
static void held_agrees_with_step(void)
{
    cb_law law = make_law(0.0, NULL, NULL);
    const cb_bridge reproducer = {1e-12, 1.0, 0.0, 1e-4, 2e-3, 1e-6, 0.0};
    CHECK_STATUS(cb_bridge_check_state(&reproducer), CB_ERR_BRIDGE_STATE);
    const double r1 = 0.5e-3, r2 = 0.65e-3;
    const cb_bridge valid = active_bridge(&law, r1, r2, 7.3e-12);
    const double hostile[] = {0.0, -0.0, NAN, -HUGE_VAL, HUGE_VAL, -1.0, 1e-300, DBL_MAX};
    const double gaps[] = {-HUGE_VAL, -1e300, -1e-6, 0.0, 1e-9, 0.5 * valid.rupture,
                           valid.rupture, HUGE_VAL, NAN};
    int held = 0, mismatched = 0, refused = 0;
    for (int field = -1; field < CB_BRIDGE_DOUBLES; ++field)
        for (size_t h = 0; h < sizeof hostile / sizeof *hostile; ++h)
            for (size_t g = 0; g < sizeof gaps / sizeof *gaps; ++g) {
                cb_bridge b = valid;
                if (field >= 0) { /* plain data: the bridge as its array of doubles */
                    double raw[CB_BRIDGE_DOUBLES];
                    memcpy(raw, &b, sizeof raw);
                    raw[field] = hostile[h];
                    memcpy(&b, raw, sizeof raw);
                }
                double inline_force = -1.0, force = -2.0, released = -1.0;
                cb_transition change = CB_BRIDGE_STAYS_DRY;
                cb_bridge copy = b;
                if (cb_bridge_check_state(&b) != CB_OK) {
                    ++refused;
                    if (cb_bridge_step(&law, r1, r2, gaps[g], 0.0, &copy, &change, &released,
                                       &force) == CB_OK)
                        ++mismatched;
                    continue;
                }
                if (!cb_bridge_held(&law, r1, r2, gaps[g], &b, &inline_force)) continue;
                ++held;
                cb_status s = cb_bridge_step(&law, r1, r2, gaps[g], 0.0, &copy, &change,
                                             &released, &force);
                if (s != CB_OK || change != CB_BRIDGE_HELD || !same_bits(force, inline_force))
                    ++mismatched;
            }
    CHECK(mismatched == 0);
    CHECK(held > 0);    /* the valid bridge itself is held at the gaps within its reach */
    CHECK(refused > 0); /* and the hostile values refused by the check */
    printf("held vs step: %d held states, %d refused by the check, %d disagreeing\n", held,
           refused, mismatched);
    cb_law_release(&law);
}

/* cb_certainly_apart may skip a pair only where the gap an engine computes, sqrt(rsq) -
 * radsum, is > 0: checked on squares within a few ulp of contact, where rounding decides,
 * and it must skip pairs clearly apart. */
static void certainly_apart(void)
{
    int skipped = 0, wrong = 0;
    for (int n = 0; n < 200000; ++n) {
        double radsum = 1e-4 * (1.0 + 100.0 * uniform());
        double rsq = radsum * radsum * (1.0 + (uniform() - 0.5) * 32.0 * DBL_EPSILON);
        if (cb_certainly_apart(rsq, radsum)) {
            ++skipped;
            if (!(sqrt(rsq) - radsum > 0.0)) ++wrong;
        }
    }
    CHECK(wrong == 0);
    CHECK(skipped > 10000); /* it does skip near contact, not only far away */
    CHECK(cb_certainly_apart(1.1 * 1.1, 1.0) && !cb_certainly_apart(1.0, 1.0) &&
          !cb_certainly_apart(0.81, 1.0));
    printf("certainly apart: %d of 200000 near-contact pairs skipped, %d wrongly\n", skipped,
           wrong);
}

int main(int argc, char **argv)
{
    (void)argc;
    const double r1 = 0.5e-3, r2 = 0.65e-3, volume = 7.3e-12;

    /* Lian's rule (Richefeu's default), theta = 0 and theta = 30 degrees. */
    cb_law lian = make_law(0.0, NULL, NULL);
    CHECK(lian.rupture_in_use == CB_RUPTURE_LIAN);
    life_cycle(&lian, r1, r2, volume, lian_reference(0.0, volume));
    cb_law lian30 = make_law(30.0, NULL, NULL);
    life_cycle(&lian30, r1, r2, volume, lian_reference(30.0, volume));
    life_cycle(&lian30, 1e-3, 0.25e-3, 1e-13, lian_reference(30.0, 1e-13));

    /* Willett's rule on the same law. */
    cb_law willett = make_law(0.0, "willett", NULL);
    CHECK(willett.rupture_in_use == CB_RUPTURE_WILLETT);
    life_cycle(&willett, r1, r2, volume, willett_reference(0.0, r1, r2, volume));
    cb_law willett25 = make_law(25.0, "willett", NULL);
    life_cycle(&willett25, 1e-3, 0.3e-3, 2e-11, willett_reference(25.0, 1e-3, 0.3e-3, 2e-11));

    random_sequences(&lian, 0.0);
    random_sequences(&lian30, 30.0);
    errors(&lian);
    strict_validity();
    derived_constants();
    plain_data(&lian);
    certainly_apart();
    held_agrees_with_step();

    cb_law_release(&lian);
    cb_law_release(&lian30);
    cb_law_release(&willett);
    cb_law_release(&willett25);
    return check_report(argv[0]);
}
