/* test_table.c — the table law against the exact Laplace-Young solver, at points that
 * are not table nodes, over the whole domain: size ratio 1..10, V/R_h^3 1e-5..1e-1,
 * gap 0..rupture, for contact angles on and off the reference grid.
 * Bound: 0.5 % relative on the force, and on the rupture distance.  Also: the rupture
 * volume (the inverse of the rupture distance) inside and beyond the table's volumes, and
 * a stiffness of 0 where the force is clamped at 0 or held beyond the fold. */
#include <math.h>
#include <stdint.h>

#include "capbridge.h"
#include "check.h"

static double next_uniform(uint64_t *state)
{
    *state ^= *state >> 12;
    *state ^= *state << 25;
    *state ^= *state >> 27;
    return (double)((*state * 2685821657736338717ULL) >> 11) * 0x1.0p-53;
}

static double worst_force = 0.0, worst_rupture = 0.0;

static void compare(const cb_law *law, double r1, double r2, double scaled_volume,
                    double gap_fraction)
{
    double rh = cb_radius_harmonic(r1, r2);
    double volume = scaled_volume * rh * rh * rh;
    cb_exact_problem problem = {r1, r2, law->contact_angle, law->surface_tension, volume, 0};
    double exact_rupture = 0.0, rupture = 0.0;
    cb_exact_bridge at_fold, exact;
    CHECK_STATUS(cb_exact_rupture(&problem, &exact_rupture, &at_fold), CB_OK);
    CHECK_STATUS(cb_rupture_distance(law, r1, r2, volume, &rupture), CB_OK);
    CHECK_REL(rupture, exact_rupture, 5e-3);
    double e = fabs(rupture - exact_rupture) / exact_rupture;
    if (e > worst_rupture) worst_rupture = e;

    /* The gap as a fraction of the exact rupture distance, kept where both have a bridge. */
    double gap = gap_fraction * fmin(rupture, exact_rupture);
    double force = 0.0, stiffness = 0.0;
    CHECK_STATUS(cb_exact_solve(&problem, gap, &exact), CB_OK);
    CHECK_STATUS(cb_force(law, r1, r2, volume, gap, &force, &stiffness), CB_OK);
    CHECK_REL(force, exact.force, 5e-3);
    CHECK(stiffness <= 0.0 && isfinite(stiffness));
    e = fabs(force - exact.force) / exact.force;
    if (e > worst_force) worst_force = e;
}

/* cb_rupture_volume inverts cb_rupture_distance: inside the table (bisection) and beyond
 * its volumes on either side (the V^(1/3) extension, inverted exactly), down to a gap of
 * 1e-15 m and up to 1e10 m between millimetre spheres. */
static void test_rupture_inverse(const cb_law *law)
{
    const double ratios[] = {1.0, 3.0, 10.0};
    const double scaled_volumes[] = {1e-40, 1e-12, 1e-5, 3e-3, 1e-1, 10.0, 1e30};
    for (size_t q = 0; q < sizeof ratios / sizeof ratios[0]; ++q) {
        double r1 = 1e-3, r2 = 1e-3 * ratios[q];
        double rh = 2.0 * r1 * r2 / (r1 + r2);
        for (size_t k = 0; k < sizeof scaled_volumes / sizeof scaled_volumes[0]; ++k) {
            double v = scaled_volumes[k] * rh * rh * rh, d = 0.0, back = 0.0;
            CHECK_STATUS(cb_rupture_distance(law, r1, r2, v, &d), CB_OK);
            CHECK_STATUS(cb_rupture_volume(law, r1, r2, d, &back), CB_OK);
            CHECK_REL(back, v, 1e-12);
        }
        const double gaps[] = {1e-15, 1e10};
        for (size_t k = 0; k < 2; ++k) {
            double v = 0.0, d = 0.0;
            CHECK_STATUS(cb_rupture_volume(law, r1, r2, gaps[k], &v), CB_OK);
            CHECK_STATUS(cb_rupture_distance(law, r1, r2, v, &d), CB_OK);
            CHECK_REL(d, gaps[k], 1e-12);
        }
    }
}

/* Where the force does not change with the gap its slope is 0: clamped at 0 near contact
 * at a large angle (the exact force there is repulsive), and held at its fold value
 * between the exact fold and a rupture rule that reaches further (Lian's, here). */
static void test_flat_force(void)
{
    cb_law law;
    cb_message msg;
    double force = -1.0, stiffness = -1.0;
    CHECK_STATUS(cb_law_init(&law, CB_MODEL_TABLE, 0.0728, 85.0 * CB_PI / 180.0), CB_OK);
    CHECK_STATUS(cb_law_prepare(&law, &msg), CB_OK);
    CHECK_STATUS(cb_force(&law, 1e-3, 2e-3, 1e-11, 0.0, &force, &stiffness), CB_OK);
    CHECK(force == 0.0 && stiffness == 0.0);
    cb_law_release(&law);

    double r1 = 1e-3, r2 = 1e-2, v = 1e-10, fold = 0.0, reach = 0.0;
    CHECK_STATUS(cb_law_init(&law, CB_MODEL_TABLE, 0.0728, 0.0), CB_OK);
    CHECK_STATUS(cb_law_prepare(&law, &msg), CB_OK);
    CHECK_STATUS(cb_rupture_distance(&law, r1, r2, v, &fold), CB_OK);
    CHECK_STATUS(cb_law_configure(&law, "rupture", "lian", &msg), CB_OK);
    CHECK_STATUS(cb_law_prepare(&law, &msg), CB_OK);
    CHECK_STATUS(cb_rupture_distance(&law, r1, r2, v, &reach), CB_OK);
    CHECK(reach > 1.05 * fold);
    double at_fold = 0.0;
    CHECK_STATUS(cb_force(&law, r1, r2, v, fold, &at_fold, NULL), CB_OK);
    CHECK(at_fold > 0.0);
    for (int i = 1; i <= 4; ++i) {
        double gap = fold + (reach - fold) * i / 5.0;
        CHECK_STATUS(cb_force(&law, r1, r2, v, gap, &force, &stiffness), CB_OK);
        CHECK(force == at_fold && stiffness == 0.0);
    }
    cb_law_release(&law);
}

int main(int argc, char **argv)
{
    (void)argc;
    const double angles[] = {0.0, 17.0, 40.0};
    uint64_t state = 12345;
    for (size_t a = 0; a < sizeof angles / sizeof angles[0]; ++a) {
        cb_law law;
        cb_message msg;
        CHECK_STATUS(cb_law_init(&law, CB_MODEL_TABLE, 0.0728, angles[a] * CB_PI / 180.0),
                     CB_OK);
        CHECK_STATUS(cb_law_prepare(&law, &msg), CB_OK);
        for (int i = 0; i < 40; ++i) {
            double ratio = exp(log(10.0) * next_uniform(&state));
            double scaled_volume = exp(log(1e-5) + log(1e4) * next_uniform(&state));
            double fraction = next_uniform(&state);
            if (i % 10 == 0) fraction = 0.0;       /* contact */
            if (i % 10 == 1) fraction = 0.999;     /* next to the fold */
            compare(&law, 1e-3, 1e-3 * ratio, scaled_volume, fraction);
        }
        test_rupture_inverse(&law);
        cb_law_release(&law);
    }
    test_flat_force();
    printf("table law: worst force error %.3g %%, worst rupture error %.3g %%\n",
           100 * worst_force, 100 * worst_rupture);
    return check_report(argv[0]);
}
