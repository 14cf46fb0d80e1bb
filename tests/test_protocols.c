/* test_protocols.c — Richefeu 2007 liquid protocols 2 and 3 (Protocol 1: test_protocol1.c).
 *
 * Protocol 2 against a long-double running total over long random release/take sequences;
 * Protocol 3 on hand-built configurations. */
#include "capbridge.h"
#include "check.h"
#include "test_random.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------- helpers */

static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* ------------------------------------------------------------ Protocol 2 */

static void protocol2_hand(void)
{
    /* Diameters 2 mm and 4 mm: one third and two thirds. */
    double f1 = 0.0, f2 = 0.0;
    CHECK_STATUS(cb_protocol2_release(3e-12, 1e-3, 2e-3, &f1, &f2), CB_OK);
    CHECK_REL(f1, 1e-12, 1e-15);
    CHECK_REL(f2, 2e-12, 1e-15);
    CHECK(f1 + f2 == 3e-12);
    CHECK(same_bits(f1, cb_protocol_share(3e-12, 1e-3, 2e-3)));
    CHECK(same_bits(f2, cb_protocol_share(3e-12, 2e-3, 1e-3)));

    /* Equal particles: halves, exactly. */
    f1 = f2 = 0.0;
    CHECK_STATUS(cb_protocol2_release(7e-12, 5e-4, 5e-4, &f1, &f2), CB_OK);
    CHECK(f1 == 3.5e-12 && f2 == 3.5e-12);

    /* Onto existing free liquid: each grows by its share. */
    f1 = 1e-12;
    f2 = 4e-12;
    CHECK_STATUS(cb_protocol2_release(6e-12, 3e-4, 6e-4, &f1, &f2), CB_OK);
    CHECK_REL(f1, 3e-12, 1e-15);
    CHECK_REL(f2, 8e-12, 1e-15);

    /* The new bridge takes all of both. */
    double v = -1.0;
    CHECK_STATUS(cb_protocol2_take(&f1, &f2, &v), CB_OK);
    CHECK_REL(v, 11e-12, 1e-15);
    CHECK(f1 == 0.0 && f2 == 0.0);
    CHECK_STATUS(cb_protocol2_take(&f1, &f2, &v), CB_OK);
    CHECK(v == 0.0);

    /* Releasing nothing is a no-op. */
    f1 = 2e-12;
    f2 = 0.0;
    CHECK_STATUS(cb_protocol2_release(0.0, 1e-3, 2e-3, &f1, &f2), CB_OK);
    CHECK(f1 == 2e-12 && f2 == 0.0);

    /* bridge_volume may be one of the free-liquid slots. */
    f1 = 1e-12;
    f2 = 2e-12;
    CHECK_STATUS(cb_protocol2_take(&f1, &f2, &f1), CB_OK);
    CHECK(f1 == 1e-12 + 2e-12 && f2 == 0.0);
}

/* Release onto empty particles then take: the bridge gets back exactly its volume, and
 * the shares are in proportion to the diameters. */
static void protocol2_exact(void)
{
    int not_exact = 0, not_proportional = 0, not_symmetric = 0;
    for (int i = 0; i < 200000; ++i) {
        double v = ldexp(0.5 + uniform(), -40 + (int)below(30)) * (i % 3 ? 1.0 : 1.0 + 1e-9);
        double r1 = 1e-4 * (0.5 + 20.0 * uniform());
        double r2 = i % 17 == 0 ? r1 : 1e-4 * (0.5 + 20.0 * uniform());
        double f1 = 0.0, f2 = 0.0;
        CHECK_STATUS(cb_protocol2_release(v, r1, r2, &f1, &f2), CB_OK);
        if (!(f1 + f2 == v)) ++not_exact;
        long double expected1 = (long double)v * r1 / ((long double)r1 + r2);
        if (fabsl(f1 - expected1) > 1e-15L * v || fabsl(f2 - ((long double)v - expected1)) >
                                                     1e-15L * v)
            ++not_proportional;
        if (!same_bits(cb_protocol_share(v, r1, r2), f1) ||
            !same_bits(cb_protocol_share(v, r2, r1), f2) ||
            cb_protocol_share(v, r1, r2) + cb_protocol_share(v, r2, r1) != v)
            ++not_symmetric;
        double taken = -1.0;
        CHECK_STATUS(cb_protocol2_take(&f1, &f2, &taken), CB_OK);
        if (!same_bits(taken, v) || f1 != 0.0 || f2 != 0.0) ++not_exact;
    }
    CHECK(not_exact == 0);
    CHECK(not_proportional == 0);
    CHECK(not_symmetric == 0);

    /* Extreme ratios and magnitudes, including subnormal volumes. */
    const double volumes[] = {5e-324, 3e-310, 1e-300, 1e-20, 1.0, 1e300};
    const double radii[][2] = {{1.0, 1e-12}, {1e-12, 1.0}, {1.0, 1.0}, {3.0, 7.0}};
    for (size_t i = 0; i < sizeof volumes / sizeof volumes[0]; ++i)
        for (size_t j = 0; j < sizeof radii / sizeof radii[0]; ++j) {
            double f1 = 0.0, f2 = 0.0, taken = 0.0;
            CHECK_STATUS(cb_protocol2_release(volumes[i], radii[j][0], radii[j][1], &f1, &f2),
                         CB_OK);
            CHECK(f1 >= 0.0 && f2 >= 0.0 && f1 + f2 == volumes[i]);
            CHECK_STATUS(cb_protocol2_take(&f1, &f2, &taken), CB_OK);
            CHECK(taken == volumes[i]);
        }

    /* radii whose sum overflows (issue 16 item 10: both shares were 0): still in
     * proportion, still adding up to the volume */
    const double huge[][2] = {{DBL_MAX, DBL_MAX}, {DBL_MAX, 0.25 * DBL_MAX}, {0.5 * DBL_MAX, DBL_MAX}};
    const double expected_first[] = {0.5, 0.8, 1.0 / 3.0};
    for (int k = 0; k < 3; ++k) {
        double v = 3e-12, f1 = 0.0, f2 = 0.0;
        double s1 = cb_protocol_share(v, huge[k][0], huge[k][1]);
        double s2 = cb_protocol_share(v, huge[k][1], huge[k][0]);
        CHECK(s1 + s2 == v);
        CHECK_REL(s1, expected_first[k] * v, 1e-15);
        CHECK_STATUS(cb_protocol2_release(v, huge[k][0], huge[k][1], &f1, &f2), CB_OK);
        CHECK(same_bits(f1, s1) && same_bits(f2, s2));
    }
}

/* Long random sequences over many particles: bridges break (release, Protocol 2) and
 * form (take), liquid is sometimes added; the total in bridges and free liquid is checked
 * against a running total kept in long double. */
static void protocol2_conservation(void)
{
    enum { PARTICLES = 400, PAIRS = 2000, EVENTS = 2000000 };
    static double radius[PARTICLES], free_liquid[PARTICLES], bridge[PAIRS];
    static size_t end1[PAIRS], end2[PAIRS];
    long double running = 0.0L;
    for (size_t i = 0; i < PARTICLES; ++i) {
        radius[i] = 1e-3 * (0.4 + 0.25 * uniform());
        free_liquid[i] = 0.0;
    }
    for (size_t p = 0; p < PAIRS; ++p) {
        end1[p] = below(PARTICLES);
        do end2[p] = below(PARTICLES);
        while (end2[p] == end1[p]);
        bridge[p] = 1e-12 * (0.5 + uniform());
        running += bridge[p];
    }
    size_t releases = 0, takes = 0;
    double worst = 0.0;
    for (long e = 0; e < EVENTS; ++e) {
        size_t p = below(PAIRS), a = end1[p], b = end2[p];
        if (e % 1000 == 0) {
            double added = 1e-13 * uniform();
            free_liquid[below(PARTICLES)] += added;
            running += added;
        }
        if (bridge[p] > 0.0) {
            CHECK_STATUS(cb_protocol2_release(bridge[p], radius[a], radius[b], &free_liquid[a],
                                              &free_liquid[b]),
                         CB_OK);
            bridge[p] = 0.0;
            ++releases;
        } else if (free_liquid[a] + free_liquid[b] > 0.0) {
            CHECK_STATUS(cb_protocol2_take(&free_liquid[a], &free_liquid[b], &bridge[p]), CB_OK);
            ++takes;
        }
        if (e % 100000 == 0 || e == EVENTS - 1) {
            long double total = 0.0L;
            for (size_t i = 0; i < PARTICLES; ++i) total += free_liquid[i];
            for (size_t q = 0; q < PAIRS; ++q) total += bridge[q];
            double rel = (double)(fabsl(total - running) / running);
            if (rel > worst) worst = rel;
        }
    }
    printf("protocol 2: %zu releases, %zu takes, worst relative drift %.3g\n", releases, takes,
           worst);
    CHECK(releases > 100000 && takes > 100000);
    CHECK(worst <= 1e-14);
}

static void protocol2_errors(void)
{
    double f1 = 1e-12, f2 = 2e-12, v = 5e-12;
    const double bad[] = {NAN, HUGE_VAL, -HUGE_VAL};
    CHECK_STATUS(cb_protocol2_release(v, 1e-3, 1e-3, NULL, &f2), CB_ERR_NULL);
    CHECK_STATUS(cb_protocol2_release(v, 1e-3, 1e-3, &f1, NULL), CB_ERR_NULL);
    CHECK_STATUS(cb_protocol2_release(v, 1e-3, 1e-3, &f1, &f1), CB_ERR_LIQUID);
    for (int i = 0; i < 3; ++i) {
        CHECK_STATUS(cb_protocol2_release(bad[i], 1e-3, 1e-3, &f1, &f2), CB_ERR_NOT_FINITE);
        CHECK_STATUS(cb_protocol2_release(v, bad[i], 1e-3, &f1, &f2), CB_ERR_NOT_FINITE);
        if (!cb_is_plane(bad[i])) /* r2 = +inf is a wall (test_wall.c) */
            CHECK_STATUS(cb_protocol2_release(v, 1e-3, bad[i], &f1, &f2), CB_ERR_NOT_FINITE);
        double g1 = bad[i], g2 = 0.0;
        CHECK_STATUS(cb_protocol2_release(v, 1e-3, 1e-3, &g1, &g2), CB_ERR_NOT_FINITE);
        CHECK(g2 == 0.0);
        CHECK_STATUS(cb_protocol2_take(&g2, &g1, &v), CB_ERR_NOT_FINITE);
        CHECK(g2 == 0.0 && v == 5e-12);
        CHECK(cb_protocol_share(bad[i], 1e-3, 1e-3) == 0.0);
        CHECK(cb_protocol_share(v, bad[i], 1e-3) == 0.0);
    }
    CHECK_STATUS(cb_protocol2_release(-v, 1e-3, 1e-3, &f1, &f2), CB_ERR_NEGATIVE);
    CHECK_STATUS(cb_protocol2_release(v, 0.0, 1e-3, &f1, &f2), CB_ERR_NEGATIVE);
    CHECK_STATUS(cb_protocol2_release(v, 1e-3, -1e-3, &f1, &f2), CB_ERR_NEGATIVE);
    double negative = -1e-12;
    CHECK_STATUS(cb_protocol2_release(v, 1e-3, 1e-3, &f1, &negative), CB_ERR_NEGATIVE);
    CHECK_STATUS(cb_protocol2_take(&negative, &f2, &v), CB_ERR_NEGATIVE);
    CHECK_STATUS(cb_protocol2_take(NULL, &f2, &v), CB_ERR_NULL);
    CHECK_STATUS(cb_protocol2_take(&f1, NULL, &v), CB_ERR_NULL);
    CHECK_STATUS(cb_protocol2_take(&f1, &f2, NULL), CB_ERR_NULL);
    CHECK_STATUS(cb_protocol2_take(&f1, &f1, &v), CB_ERR_LIQUID);
    double huge1 = 1.5e308, huge2 = 1.5e308;
    CHECK_STATUS(cb_protocol2_take(&huge1, &huge2, &v), CB_ERR_RANGE);
    CHECK_STATUS(cb_protocol2_release(1.5e308, 1e-3, 1e-3, &huge1, &huge2), CB_ERR_RANGE);
    CHECK(huge1 == 1.5e308 && huge2 == 1.5e308);
    /* Nothing changed by any of the failures. */
    CHECK(f1 == 1e-12 && f2 == 2e-12 && v == 5e-12 && negative == -1e-12);
    CHECK(cb_protocol_share(-1.0, 1e-3, 1e-3) == 0.0);
    CHECK(cb_protocol_share(1.0, 0.0, 1e-3) == 0.0);
    CHECK(cb_protocol_share(1.0, 1e-3, -1e-3) == 0.0);
}

/* ------------------------------------------------------------ Protocol 3 */

static long receiver(double centre, const double *heights, size_t n)
{
    long index = -99;
    CHECK_STATUS(cb_protocol3_receiver(centre, heights, n, &index), CB_OK);
    return index;
}

static void protocol3(void)
{
    const double mixed[] = {0.5, -0.2, -0.7, 0.1};
    CHECK(receiver(0.0, mixed, 4) == 2);
    CHECK(receiver(-0.3, mixed, 4) == 2);
    CHECK(receiver(-0.7, mixed, 4) == -1); /* nothing strictly below */
    CHECK(receiver(1.0, mixed, 4) == 2);
    const double above[] = {0.5, 0.2, 0.1};
    CHECK(receiver(0.0, above, 3) == -1);
    const double equator[] = {0.0, 0.0};
    CHECK(receiver(0.0, equator, 2) == -1); /* on the equator is not the lower hemisphere */
    const double just_below[] = {0.0, -1e-300, 0.3};
    CHECK(receiver(0.0, just_below, 3) == 1);
    const double ties[] = {-0.5, 0.3, -0.5};
    CHECK(receiver(0.0, ties, 3) == 0);
    const double ties_late[] = {0.2, -0.1, -0.5, 0.0, -0.5, -0.5};
    CHECK(receiver(0.0, ties_late, 6) == 2);
    const double single[] = {-2.0};
    CHECK(receiver(0.0, single, 1) == 0);
    CHECK(receiver(-3.0, single, 1) == -1);
    CHECK(receiver(0.0, NULL, 0) == -1);
    CHECK(receiver(0.0, mixed, 0) == -1);

    /* A sphere of radius 1 mm at height 10 mm with six neighbours touching it; contact
     * points at the centre plus r times the unit normal. The lowest is the one straight
     * below; the one at 45 degrees below comes next. */
    const double r = 1e-3, zc = 10e-3;
    const double normal_z[] = {1.0, -0.70710678118654752, 0.0, -1.0, 0.3, -0.2};
    double heights[6];
    for (int i = 0; i < 6; ++i) heights[i] = zc + r * normal_z[i];
    CHECK(receiver(zc, heights, 6) == 3);
    heights[3] = zc + 2.0 * r; /* that neighbour is gone upwards */
    CHECK(receiver(zc, heights, 6) == 1);

    /* Protocol 3 on one broken bridge: the two shares go to one bridge of each particle
     * (or stay free), and the liquid is conserved exactly. */
    double bridges[3] = {1e-12, 2e-12, 3e-12};
    double free_a = 0.0, free_b = 0.0;
    const double broken = 4.5e-12, ra = 0.5e-3, rb = 0.6e-3;
    double share_a = cb_protocol_share(broken, ra, rb);
    double share_b = cb_protocol_share(broken, rb, ra);
    CHECK(share_a + share_b == broken);
    CHECK_REL(share_a, broken * 0.5 / 1.1, 1e-15);
    const double a_heights[] = {0.3e-3, -0.2e-3}; /* bridges 0 and 1, centre 0 */
    long ia = receiver(0.0, a_heights, 2);
    CHECK(ia == 1);
    const double b_heights[] = {0.4e-3}; /* bridge 2, above the centre */
    long ib = receiver(0.0, b_heights, 1);
    CHECK(ib == -1);
    bridges[ia] += share_a;
    free_b += share_b;
    CHECK_REL(bridges[1], 2e-12 + broken * 0.5 / 1.1, 1e-15);
    CHECK_REL(free_b, broken * 0.6 / 1.1, 1e-15);
    CHECK_REL(bridges[0] + bridges[1] + bridges[2] + free_a + free_b, 6e-12 + broken, 1e-15);

    /* Errors leave *index alone. */
    long index = 42;
    const double bad_heights[] = {-1.0, NAN};
    CHECK_STATUS(cb_protocol3_receiver(0.0, mixed, 4, NULL), CB_ERR_NULL);
    CHECK_STATUS(cb_protocol3_receiver(0.0, NULL, 2, &index), CB_ERR_NULL);
    CHECK_STATUS(cb_protocol3_receiver(NAN, mixed, 4, &index), CB_ERR_NOT_FINITE);
    CHECK_STATUS(cb_protocol3_receiver(HUGE_VAL, mixed, 4, &index), CB_ERR_NOT_FINITE);
    CHECK_STATUS(cb_protocol3_receiver(0.0, bad_heights, 2, &index), CB_ERR_NOT_FINITE);
    const double inf_heights[] = {-HUGE_VAL};
    CHECK_STATUS(cb_protocol3_receiver(0.0, inf_heights, 1, &index), CB_ERR_NOT_FINITE);
    CHECK(index == 42);
}

int main(int argc, char **argv)
{
    (void)argc;
    protocol2_hand();
    protocol2_exact();
    protocol2_conservation();
    protocol2_errors();
    protocol3();
    return check_report(argv[0]);
}
