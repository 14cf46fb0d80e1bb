/* test_engine_rules.c — the rules both engine bindings take from the core: the neighbor
 * reach, the design volume of a protocol's reach, the time-step limit, the periodic cell,
 * Protocol 3's receiver and Protocol 2's k-way share.  Against the formulas written out
 * here, a dense scan, and conservation. */
#include "capbridge.h"
#include "check.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static cb_law make_law(cb_model model, double theta_degrees, const char *rupture)
{
    cb_law law;
    cb_message msg;
    CHECK_STATUS(cb_law_init(&law, model, 0.0728, theta_degrees * CB_PI / 180.0), CB_OK);
    if (rupture) CHECK_STATUS(cb_law_configure(&law, "rupture", rupture, &msg), CB_OK);
    CHECK_STATUS(cb_law_prepare(&law, &msg), CB_OK);
    return law;
}

static void reach(void)
{
    const cb_radius_range small = {0.4e-3, 0.5e-3}, mixed = {0.5e-3, 1.0e-3};
    const double v = 2e-11, margin = 1.0 + CB_REACH_MARGIN;
    /* Lian (Richefeu eq. 6): (1 + theta/2) V^(1/3), the same for every radius */
    cb_law lian = make_law(CB_MODEL_RICHEFEU, 20.0, NULL);
    double design = 0.0, r = 0.0, ratio = 0.0;
    CHECK_STATUS(cb_reach(&lian, small, mixed, v, &design, &r, &ratio), CB_OK);
    const double lian_d = (1.0 + 10.0 * CB_PI / 180.0) * cbrt(v);
    CHECK_REL(design, lian_d, 1e-14);
    CHECK_REL(r, lian_d * margin, 1e-14);
    CHECK_REL(ratio, lian_d * margin / (0.4e-3 + 0.5e-3), 1e-14);
    /* Willett (Gladkyy eq. 2) falls with R_h: largest at the two smallest radii */
    cb_law willett = make_law(CB_MODEL_WILLETT, 0.0, NULL);
    CHECK_STATUS(cb_reach(&willett, small, mixed, v, &design, &r, &ratio), CB_OK);
    double corner = 0.0;
    CHECK_STATUS(cb_rupture_distance(&willett, 0.4e-3, 0.5e-3, v, &corner), CB_OK);
    CHECK_REL(design, corner, 1e-15);
    /* Willett's unequal-sphere rule is not monotone in the radii: the grid's reach covers a
     * dense scan of the ranges (the margin is the slack) */
    cb_law unequal = make_law(CB_MODEL_WILLETT, 30.0, "willett/unequal");
    const cb_radius_range wide = {0.1e-3, 1.0e-3};
    CHECK_STATUS(cb_reach(&unequal, wide, wide, v, &design, &r, &ratio), CB_OK);
    double dense = 0.0, dense_ratio = 0.0;
    for (int a = 0; a <= 80; ++a)
        for (int b = 0; b <= 80; ++b) {
            double r1 = wide.min + (wide.max - wide.min) * a / 80.0;
            double r2 = wide.min + (wide.max - wide.min) * b / 80.0, d = 0.0;
            CHECK_STATUS(cb_rupture_distance(&unequal, r1, r2, v, &d), CB_OK);
            if (d > dense) dense = d;
            if (d / (r1 + r2) > dense_ratio) dense_ratio = d / (r1 + r2);
        }
    CHECK(r >= dense && design <= dense * (1.0 + 1e-12));
    CHECK(ratio >= dense_ratio);
    printf("reach, willett/unequal over 0.1-1 mm: grid %.6g m, dense scan %.6g m, reach %.6g m\n",
           design, dense, r);
    /* a wall (range2 the plane): Lian's distance again (it has no radius), the ratio over
     * the smallest r1 alone; Willett's largest at the smallest grain, as for a pair */
    const cb_radius_range plane = {CB_PLANE, CB_PLANE}, half_plane = {0.5e-3, CB_PLANE};
    CHECK_STATUS(cb_reach(&lian, small, plane, v, &design, &r, &ratio), CB_OK);
    CHECK_REL(design, lian_d, 1e-14);
    CHECK_REL(ratio, lian_d * margin / 0.4e-3, 1e-14);
    CHECK_STATUS(cb_reach(&willett, small, plane, v, &design, &r, &ratio), CB_OK);
    CHECK_STATUS(cb_rupture_distance(&willett, 0.4e-3, CB_PLANE, v, &corner), CB_OK);
    CHECK_REL(design, corner, 1e-15);
    CHECK_REL(ratio, corner * margin / 0.4e-3, 1e-14);
    CHECK_STATUS(cb_reach(&lian, small, half_plane, v, NULL, &r, NULL), CB_ERR_RANGE);
    CHECK_STATUS(cb_reach(&lian, plane, small, v, NULL, &r, NULL), CB_ERR_RANGE);
    /* a strict law reaches as far as its extension: a bridge that exists is kept */
    cb_law strict = make_law(CB_MODEL_WILLETT, 0.0, NULL);
    strict.validity = CB_VALIDITY_STRICT;
    double strict_reach = 0.0;
    CHECK_STATUS(cb_reach(&strict, small, mixed, 1e-6, NULL, &strict_reach, NULL), CB_OK);
    /* no liquid: no reach; bad input refused by status */
    CHECK_STATUS(cb_reach(&lian, small, mixed, 0.0, &design, &r, &ratio), CB_OK);
    CHECK(design == 0.0 && r == 0.0 && ratio == 0.0);
    const cb_radius_range backwards = {1e-3, 0.5e-3}, empty = {0.0, 0.0};
    CHECK_STATUS(cb_reach(&lian, backwards, mixed, v, NULL, &r, NULL), CB_ERR_RANGE);
    CHECK_STATUS(cb_reach(&lian, empty, mixed, v, NULL, &r, NULL), CB_ERR_RANGE);
    CHECK_STATUS(cb_reach(&lian, small, mixed, -v, NULL, &r, NULL), CB_ERR_NEGATIVE);
    CHECK_STATUS(cb_reach(&lian, small, mixed, NAN, NULL, &r, NULL), CB_ERR_NOT_FINITE);
    CHECK_STATUS(cb_reach(NULL, small, mixed, v, NULL, &r, NULL), CB_ERR_NULL);
    CHECK(cb_bridge_beyond_reach(nextafter(lian_d, 1.0), lian_d) &&
          !cb_bridge_beyond_reach(lian_d, lian_d));
    cb_law_release(&lian);
    cb_law_release(&willett);
    cb_law_release(&unequal);
    cb_law_release(&strict);
}

static void design_volume(void)
{
    const cb_radius_range radii = {0.5e-3, 1.0e-3};
    double v = 0.0;
    /* 2 V/N (r_max/r_min)^3 = 2 x 1e-9 / 100 x 8 */
    CHECK_STATUS(cb_protocol_design_volume(1e-9, 100.0, radii, 1e-12, &v), CB_OK);
    CHECK_REL(v, 2.0 * 1e-9 / 100.0 * 8.0, 1e-15);
    /* one grain holding much of it as free liquid: twice that */
    CHECK_STATUS(cb_protocol_design_volume(1e-9, 100.0, radii, 1e-9, &v), CB_OK);
    CHECK_REL(v, 2e-9, 1e-15);
    CHECK_STATUS(cb_protocol_design_volume(-1.0, 100.0, radii, 0.0, &v), CB_ERR_NEGATIVE);
    CHECK_STATUS(cb_protocol_design_volume(1.0, INFINITY, radii, 0.0, &v), CB_ERR_NOT_FINITE);
}

static void timestep(void)
{
    const cb_radius_range range = {1e-3, 1e-3};
    const double m = 2500.0 * 4.0 / 3.0 * CB_PI * 1e-9, v = 1e-12;
    cb_law law = make_law(CB_MODEL_RICHEFEU, 0.0, NULL);
    double limit = 0.0, capillary = -1.0;
    /* k_n decides: 0.1 pi sqrt(m / k_n) */
    CHECK_STATUS(cb_timestep_limit(&law, range, range, &v, 1, m, 100.0, &limit, &capillary),
                 CB_OK);
    CHECK_REL(limit, 0.1 * CB_PI * sqrt(m / 100.0), 1e-15);
    /* k_n small: the capillary stiffness decides; richefeu is steepest at contact, where
     * |dF/dgap| = F(0) / lambda (eq. 10), which cb_force's stiffness at gap 0 gives */
    double f0 = 0.0, slope = 0.0;
    CHECK_STATUS(cb_force(&law, 1e-3, 1e-3, v, 0.0, &f0, &slope), CB_OK);
    CHECK_STATUS(cb_timestep_limit(&law, range, range, &v, 1, m, 1.0, &limit, &capillary),
                 CB_OK);
    CHECK_REL(capillary, fabs(slope), 1e-6);
    CHECK_REL(limit, 0.1 * CB_PI * sqrt(m / fabs(slope)), 1e-6);
    /* no law, no stiffness: no limit */
    CHECK_STATUS(cb_timestep_limit(NULL, range, range, NULL, 0, m, 0.0, &limit, NULL), CB_OK);
    CHECK(limit == HUGE_VAL);
    CHECK_STATUS(cb_timestep_limit(&law, range, range, &v, 1, 0.0, 1.0, &limit, NULL),
                 CB_ERR_NEGATIVE);
    cb_law_release(&law);
}

/* widths of a triclinic cell against V / |a x b| for each face pair */
static void cell_widths(void)
{
    const double lx = 2.0, ly = 3.0, lz = 5.0, xy = 0.7, xz = -0.4, yz = 1.1;
    /* h = [[lx, xy, xz], [0, ly, yz], [0, 0, lz]]; its inverse, upper triangular */
    const double inv[6] = {1.0 / lx, 1.0 / ly, 1.0 / lz, -yz / (ly * lz),
                           (xy * yz - ly * xz) / (lx * ly * lz), -xy / (lx * ly)};
    double width[3];
    cb_cell_widths(inv, width);
    const double a[3] = {lx, 0.0, 0.0}, b[3] = {xy, ly, 0.0}, c[3] = {xz, yz, lz};
    const double *edges[3][2] = {{b, c}, {c, a}, {a, b}};
    const double volume = lx * ly * lz;
    for (int k = 0; k < 3; ++k) {
        const double *p = edges[k][0], *q = edges[k][1];
        double cross[3] = {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2],
                           p[0] * q[1] - p[1] * q[0]};
        CHECK_REL(width[k], volume / sqrt(cross[0] * cross[0] + cross[1] * cross[1] +
                                          cross[2] * cross[2]), 1e-14);
    }
    const int periodic[3] = {1, 0, 1};
    CHECK(cb_periodic_too_narrow(width, periodic, 0.5 * width[0]) == -1);
    CHECK(cb_periodic_too_narrow(width, periodic, 0.5 * width[0] * (1.0 + 1e-12)) == 0);
    const int only_z[3] = {0, 0, 1};
    CHECK(cb_periodic_too_narrow(width, only_z, 0.5 * width[2] * 1.01) == 2);
    CHECK(cb_periodic_too_narrow(width, only_z, 0.5 * width[0] * 1.01) ==
          (width[0] * 1.01 > width[2] ? 2 : -1));
}

static uint64_t rng = 0x2545F4914F6CDD1Dull;
static double uniform(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

/* the receiver chosen bridge by bridge is the lowest below the centre, the smaller partner
 * id among equal heights, whatever the order the bridges come in */
static void protocol3_receiver(void)
{
    int wrong = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        double offset[8];
        long long partner[8];
        int n = 1 + trial % 8;
        for (int k = 0; k < n; ++k) {
            offset[k] = (double)((int)(uniform() * 7.0) - 4) * 1e-4; /* ties, and above 0 */
            partner[k] = 1 + (long long)(uniform() * 1000.0);
        }
        /* the answer by brute force */
        int expected = -1;
        for (int k = 0; k < n; ++k)
            if (offset[k] < 0.0 &&
                (expected < 0 || offset[k] < offset[expected] ||
                 (offset[k] == offset[expected] && partner[k] < partner[expected])))
                expected = k;
        for (int order = 0; order < 3; ++order) {
            int visit_order[8];
            for (int k = 0; k < n; ++k) visit_order[k] = order == 1 ? n - 1 - k : k;
            for (int k = n - 1; order == 2 && k > 0; --k) { /* a random order */
                int swap = (int)(uniform() * (k + 1)), keep = visit_order[k];
                visit_order[k] = visit_order[swap];
                visit_order[swap] = keep;
            }
            double best = 0.0;
            long long best_partner = 0;
            for (int visit = 0; visit < n; ++visit) {
                const int k = visit_order[visit];
                if (cb_protocol3_better(offset[k], partner[k], best, best_partner)) {
                    best = offset[k];
                    best_partner = partner[k];
                }
            }
            long long want = expected < 0 ? 0 : partner[expected];
            /* equal heights and equal ids are the same choice */
            if (best_partner != want && !(expected >= 0 && best == offset[expected] &&
                                          best_partner == partner[expected]))
                ++wrong;
        }
    }
    CHECK(wrong == 0);
}

static void grain_step(void)
{
    double free_liquid = 3e-12, deposit = -1.0, offer = -1.0;
    /* released liquid to the free liquid, then three new contacts share it all */
    CHECK_STATUS(cb_protocol_grain_step(1e-12, 0, 3.0, &free_liquid, &deposit, &offer), CB_OK);
    CHECK(free_liquid == 0.0 && deposit == 0.0);
    CHECK_REL(3.0 * offer, 4e-12, 1e-15);
    /* Protocol 3 with a receiver: the released liquid goes there, the free liquid stays */
    free_liquid = 3e-12;
    CHECK_STATUS(cb_protocol_grain_step(1e-12, 1, 0.0, &free_liquid, &deposit, &offer), CB_OK);
    CHECK(free_liquid == 3e-12 && deposit == 1e-12 && offer == 0.0);
    /* conservation over random steps */
    double worst = 0.0;
    for (int n = 0; n < 100000; ++n) {
        double f = uniform() * 1e-11, released = uniform() < 0.5 ? uniform() * 1e-11 : 0.0;
        double k = (double)(int)(uniform() * 6.0), before = f + released;
        int receiver = uniform() < 0.3;
        CHECK_STATUS(cb_protocol_grain_step(released, receiver, k, &f, &deposit, &offer), CB_OK);
        double after = f + deposit + k * offer;
        if (before > 0.0 && fabs(after - before) / before > worst)
            worst = fabs(after - before) / before;
    }
    CHECK(worst <= 4.0 * DBL_EPSILON);
    printf("grain step: worst relative liquid change %.3g over 1e5 random steps\n", worst);
    CHECK_STATUS(cb_protocol_grain_step(-1.0, 0, 1.0, &free_liquid, &deposit, &offer),
                 CB_ERR_NEGATIVE);
    CHECK_STATUS(cb_protocol_grain_step(NAN, 0, 1.0, &free_liquid, &deposit, &offer),
                 CB_ERR_NOT_FINITE);
    CHECK_STATUS(cb_protocol_grain_step(0.0, 0, 1.0, NULL, &deposit, &offer), CB_ERR_NULL);
}

int main(int argc, char **argv)
{
    (void)argc;
    reach();
    design_volume();
    timestep();
    cell_widths();
    protocol3_receiver();
    grain_step();
    return check_report(argv[0]);
}
