/* test_protocol1.c — Richefeu 2007 liquid Protocol 1 (section 2.4, eqs. 13-14), against a
 * brute-force reference written here: the thresholds alpha_p from the published rupture
 * formulas (in long double), and alpha by bisection on the non-decreasing
 * S(alpha) = alpha * sum{R_g^3 : alpha_p <= alpha}. */
#include "capbridge.h"
#include "check.h"
#include "test_law.h"
#include "test_random.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI_L 3.14159265358979323846264338327950288L

/* The rupture rule, written from the published formulas. */
typedef struct rule {
    int willett;              /* 0: Lian (Richefeu eq. 6), 1: Willett (Gladkyy eq. 2) */
    long double factor;       /* 1 + theta/2 */
} rule;

/* The smallest volume whose rupture distance reaches gap (> 0). Lian: (gap / f)^3.
 * Willett: t + t^2/10 = A with t = (V / R_h^3)^(1/3), A = gap / (R_h f), so
 * t = 5 (sqrt(1 + 0.4 A) - 1); evaluated in long double. */
static long double reference_rupture_volume(rule rl, double r1, double r2, double gap)
{
    if (!rl.willett) {
        long double root = gap / rl.factor;
        return root * root * root;
    }
    long double rh = 2.0L * r1 * r2 / ((long double)r1 + r2);
    long double a = gap / (rh * rl.factor);
    long double t = 5.0L * (sqrtl(1.0L + 0.4L * a) - 1.0L);
    return t * t * t * rh * rh * rh;
}

static long double reference_rg3(double r1, double r2)
{
    long double rg = sqrtl((long double)r1 * r2);
    return rg * rg * rg;
}

/* S(alpha) = alpha * sum of R_g^3 over the pairs with threshold <= alpha. */
static long double weight_up_to(size_t n, const long double *threshold, const long double *w,
                                long double alpha)
{
    long double s = 0.0L;
    for (size_t i = 0; i < n; ++i)
        if (threshold[i] <= alpha) s += w[i];
    return s;
}

typedef struct p1_counts {
    int unique, jump, ambiguous, no_liquid, cases, partial;
} p1_counts;

/* One Protocol-1 case against the brute force. */
static void protocol1_case(const cb_law *law, rule rl, size_t n, const double *r1,
                           const double *r2, const double *gap, double total, p1_counts *counts)
{
    double *threshold_work = malloc(n * sizeof *threshold_work);
    double *weight_work = malloc(n * sizeof *weight_work);
    size_t *order_work = malloc(n * sizeof *order_work);
    double *volume = malloc(n * sizeof *volume);
    long double *thr = malloc(n * sizeof *thr);
    long double *w = malloc(n * sizeof *w);
    if (!threshold_work || !weight_work || !order_work || !volume || !thr || !w) {
        CHECK(!"out of memory");
        return;
    }
    cb_protocol1_work work = {threshold_work, weight_work, order_work};
    ++counts->cases;

    long double max_thr = 0.0L, w_all = 0.0L;
    for (size_t i = 0; i < n; ++i) {
        w[i] = reference_rg3(r1[i], r2[i]);
        thr[i] = gap[i] > 0.0 ? reference_rupture_volume(rl, r1[i], r2[i], gap[i]) / w[i] : 0.0L;
        if (thr[i] > max_thr) max_thr = thr[i];
        w_all += w[i];
    }
    /* Bisection: alpha* = inf { alpha : S(alpha) >= total }. */
    long double lo = 0.0L, hi = (max_thr > total / w_all ? max_thr : total / w_all) * 2.0L;
    for (int it = 0; it < 400; ++it) {
        long double mid = 0.5L * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        if (mid * weight_up_to(n, thr, w, mid) >= total) hi = mid;
        else lo = mid;
    }
    long double w_hi = weight_up_to(n, thr, w, hi), w_lo = weight_up_to(n, thr, w, lo);
    int jump = w_hi != w_lo; /* a threshold in (lo, hi]: S jumps over total there */
    /* The reference wet set and alpha. */
    long double ref_alpha = jump ? (w_lo > 0.0L ? total / w_lo : 0.0L) : total / w_hi;
    long double cut = hi; /* the wet set: thresholds <= hi (unique) or < hi (jump) */
    /* Is the case decided by margins wider than rounding? */
    int ambiguous = 0;
    for (size_t i = 0; i < n; ++i)
        if (thr[i] > 0.0L && fabsl(thr[i] - cut) <= 1e-9L * cut && !(jump && thr[i] <= hi &&
                                                                     thr[i] > lo)) {
            ambiguous = 1;
        }
    if (jump) {
        /* Near the boundary between the jump and the continuous case, or ties at the jump. */
        if (w_lo > 0.0L && fabsl(total / w_lo - hi) <= 1e-9L * hi) ambiguous = 1;
        int at_jump = 0;
        for (size_t i = 0; i < n; ++i) at_jump += thr[i] > lo && thr[i] <= hi;
        if (at_jump != 1) ambiguous = 1;
    }

    double alpha = -1.0;
    for (size_t i = 0; i < n; ++i) volume[i] = -1.0;
    cb_status status = cb_protocol1_distribute(law, n, r1, r2, gap, total, work, volume, &alpha);

    if (jump && w_lo == 0.0L && !ambiguous) {
        /* No pair can take the liquid: nothing written. */
        ++counts->no_liquid;
        CHECK_STATUS(status, CB_ERR_LIQUID);
        CHECK(alpha == -1.0);
        int untouched = 1;
        for (size_t i = 0; i < n; ++i) untouched &= volume[i] == -1.0;
        CHECK(untouched);
        goto done;
    }
    if (jump && w_lo == 0.0L && status == CB_ERR_LIQUID) { /* ambiguous: either is right */
        ++counts->ambiguous;
        goto done;
    }
    CHECK_STATUS(status, CB_OK);
    if (status != CB_OK) goto done;

    /* Properties that hold in every case. */
    long double sum = 0.0L, w_wet = 0.0L;
    int outside_rupture = 0, not_eq14 = 0, not_zero = 0;
    long double max_wet_thr = 0.0L, min_dry_thr = HUGE_VALL, min_dry_w = 0.0L;
    size_t wet = 0;
    for (size_t i = 0; i < n; ++i) {
        if (volume[i] > 0.0) {
            ++wet;
            sum += volume[i];
            w_wet += w[i];
            if (gap[i] > 0.0) {
                double d = -1.0;
                CHECK_STATUS(cb_rupture_distance(law, r1[i], r2[i], volume[i], &d), CB_OK);
                if (!(gap[i] <= d)) ++outside_rupture;
            }
            /* Richefeu eq. 14, literally: V_b / R_g^3 is one alpha for every wet pair. */
            if (fabsl(volume[i] / w[i] - alpha) > 1e-14L * alpha) ++not_eq14;
            if (thr[i] > max_wet_thr) max_wet_thr = thr[i];
        } else {
            if (volume[i] != 0.0) ++not_zero;
            if (thr[i] < min_dry_thr) {
                min_dry_thr = thr[i];
                min_dry_w = w[i];
            }
        }
    }
    CHECK(wet > 0);
    counts->partial += wet < n;
    CHECK(outside_rupture == 0);
    CHECK(not_eq14 == 0);
    CHECK(not_zero == 0);
    /* Eq. 13: the liquid is conserved. */
    CHECK(fabsl(sum - total) <= 1e-13L * total);
    CHECK(fabsl(alpha - total / w_wet) <= 1e-13L * alpha);
    /* The wet set is a prefix by threshold, and maximal: the first dry pair cannot be
     * admitted without falling below its own threshold. */
    if (wet < n) {
        CHECK(max_wet_thr <= min_dry_thr * (1.0L + 1e-12L));
        CHECK(total / (w_wet + min_dry_w) < min_dry_thr * (1.0L + 1e-12L));
    }

    if (ambiguous) {
        ++counts->ambiguous;
        goto done;
    }
    /* Against the brute force: the same wet set, the same alpha and volumes. */
    int set_differs = 0, volume_differs = 0;
    for (size_t i = 0; i < n; ++i) {
        int ref_wet = jump ? thr[i] <= lo : thr[i] <= hi;
        if (ref_wet != (volume[i] > 0.0)) ++set_differs;
        long double ref_volume = ref_wet ? ref_alpha * w[i] : 0.0L;
        if (fabsl(volume[i] - ref_volume) > 1e-12L * ref_volume) ++volume_differs;
    }
    CHECK(set_differs == 0);
    CHECK(volume_differs == 0);
    CHECK(fabsl(alpha - ref_alpha) <= 1e-12L * ref_alpha);
    if (jump) {
        ++counts->jump;
        /* The margin pair is eligible at the alpha returned, yet dry (the documented edge
         * case): alpha is at or above the jump, which is at its threshold. */
        CHECK(alpha >= hi * (1.0L - 1e-12L));
    } else {
        ++counts->unique;
        CHECK(fabsl(alpha - hi) <= 1e-12L * hi);
    }

done:
    free(threshold_work);
    free(weight_work);
    free(order_work);
    free(volume);
    free(thr);
    free(w);
}

/* Random pair sets, 10..5000 pairs, gaps negative and positive. */
static void protocol1_random(const cb_law *law, rule rl, const char *name)
{
    static const size_t sizes[] = {10, 10, 10, 10, 10, 10, 10, 10, 20, 20, 20, 20, 30, 30,
                                   50, 50, 100, 100, 300, 1000, 2000, 5000, 5000};
    enum { N_MAX = 5000 };
    static double r1[N_MAX], r2[N_MAX], gap[N_MAX];
    p1_counts counts = {0, 0, 0, 0, 0, 0};
    for (int repeat = 0; repeat < 6; ++repeat) {
        for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s) {
            size_t n = sizes[s];
            int polydisperse = (repeat + (int)s) % 2;
            double touching = repeat == 5 ? 0.0 : 0.1 + 0.5 * uniform();
            long double w_all = 0.0L;
            for (size_t i = 0; i < n; ++i) {
                double lo = polydisperse ? 0.2e-3 : 0.4e-3, width = polydisperse ? 0.6e-3 : 0.25e-3;
                r1[i] = lo + width * uniform();
                r2[i] = lo + width * uniform();
                double u = uniform();
                gap[i] = uniform() < touching ? -1e-5 * u : 0.3e-3 * u * u;
                if (i % 97 == 13) gap[i] = 0.0;
                w_all += reference_rg3(r1[i], r2[i]);
            }
            /* alpha from 1e-7 to 0.1 (log-uniform): from a few pairs wet to all. */
            double target = pow(10.0, -7.0 + 6.0 * uniform());
            protocol1_case(law, rl, n, r1, r2, gap, (double)(target * w_all), &counts);
        }
    }
    printf("protocol 1 (%s): %d cases: %d unique, %d jump (margin pair dry), %d no liquid "
           "placeable, %d within rounding of a margin; %d with dry pairs\n",
           name, counts.cases, counts.unique, counts.jump, counts.no_liquid, counts.ambiguous,
           counts.partial);
    CHECK(counts.partial > counts.cases / 2);
    CHECK(counts.unique > 30);
    CHECK(counts.jump > 5);
    CHECK(counts.ambiguous <= counts.cases / 20);
}

/* Hand-made cases whose answers are known in closed form. */
static void protocol1_hand(const cb_law *lian)
{
    double tw[4], ww[4], vol[4], alpha = -1.0;
    size_t ow[4];
    cb_protocol1_work work = {tw, ww, ow};

    /* Three touching pairs: alpha = V / sum R_g^3. R_g = 1, 2, 0.5 mm (r1 r2 = R_g^2). */
    const double a1[] = {1e-3, 4e-3, 0.25e-3}, a2[] = {1e-3, 1e-3, 1e-3};
    const double touching[] = {-1e-6, 0.0, -2e-6};
    const double total = 2e-9;
    CHECK_STATUS(cb_protocol1_distribute(lian, 3, a1, a2, touching, total, work, vol, &alpha),
                 CB_OK);
    const double sum_rg3 = 1e-9 + 8e-9 + 0.125e-9;
    CHECK_REL(alpha, total / sum_rg3, 1e-15);
    CHECK_REL(vol[0], total * 1e-9 / sum_rg3, 1e-15);
    CHECK_REL(vol[1], total * 8e-9 / sum_rg3, 1e-15);
    CHECK_REL(vol[2], total * 0.125e-9 / sum_rg3, 1e-15);

    /* Zero liquid: all dry, alpha 0. */
    CHECK_STATUS(cb_protocol1_distribute(lian, 3, a1, a2, touching, 0.0, work, vol, &alpha),
                 CB_OK);
    CHECK(alpha == 0.0 && vol[0] == 0.0 && vol[1] == 0.0 && vol[2] == 0.0);
    CHECK_STATUS(cb_protocol1_distribute(lian, 0, NULL, NULL, NULL, 0.0,
                                         (cb_protocol1_work){NULL, NULL, NULL}, NULL, &alpha),
                 CB_OK);
    CHECK(alpha == 0.0);

    /* Equal spheres R = 1 mm (R_g^3 = 1e-9), theta = 0 (Lian: rupture volume gap^3).
     * Pair 0 touches; pair 1 at gap g has threshold g^3 / 1e-9.
     * g = 0.1 mm: threshold 1e-3. With V = 4e-12: alone alpha = 4e-3, both: 2e-3 >= 1e-3:
     * both wet, alpha 2e-3 (unique). */
    const double e1[] = {1e-3, 1e-3}, e2[] = {1e-3, 1e-3}, g[] = {-1e-6, 0.1e-3};
    CHECK_STATUS(cb_protocol1_distribute(lian, 2, e1, e2, g, 4e-12, work, vol, &alpha), CB_OK);
    CHECK_REL(alpha, 2e-3, 1e-15);
    CHECK_REL(vol[0], 2e-12, 1e-15);
    CHECK_REL(vol[1], 2e-12, 1e-15);
    /* V = 1.5e-12: alone 1.5e-3 >= 1e-3 but both 0.75e-3 < 1e-3: the jump. The margin pair
     * is eligible at alpha = 1.5e-3 but would push alpha below its threshold: left dry. */
    CHECK_STATUS(cb_protocol1_distribute(lian, 2, e1, e2, g, 1.5e-12, work, vol, &alpha), CB_OK);
    CHECK_REL(alpha, 1.5e-3, 1e-15);
    CHECK_REL(vol[0], 1.5e-12, 1e-15);
    CHECK(vol[1] == 0.0);
    /* V = 0.5e-12: alpha 0.5e-3 < 1e-3: only the touching pair. */
    CHECK_STATUS(cb_protocol1_distribute(lian, 2, e1, e2, g, 0.5e-12, work, vol, &alpha), CB_OK);
    CHECK_REL(vol[0], 0.5e-12, 1e-15);
    CHECK(vol[1] == 0.0);

    /* No pair touching: the liquid goes to the lowest threshold, if it reaches it.
     * Gap 0.1 mm needs V >= 1e-12 (Lian, theta 0); gap 0.2 mm needs 8e-12. */
    const double apart[] = {0.2e-3, 0.1e-3};
    CHECK_STATUS(cb_protocol1_distribute(lian, 2, e1, e2, apart, 1.01e-12, work, vol, &alpha),
                 CB_OK);
    CHECK(vol[0] == 0.0);
    CHECK_REL(vol[1], 1.01e-12, 1e-15);
    double d = 0.0;
    CHECK_STATUS(cb_rupture_distance(lian, 1e-3, 1e-3, vol[1], &d), CB_OK);
    CHECK(apart[1] <= d);
    CHECK_STATUS(cb_protocol1_distribute(lian, 2, e1, e2, apart, 17e-12, work, vol, &alpha),
                 CB_OK);
    CHECK_REL(vol[0], 8.5e-12, 1e-15);
    CHECK_REL(vol[1], 8.5e-12, 1e-15);
    /* Too little liquid for any bridge: CB_ERR_LIQUID, nothing written. */
    vol[0] = vol[1] = -1.0;
    alpha = -1.0;
    CHECK_STATUS(cb_protocol1_distribute(lian, 2, e1, e2, apart, 0.99e-12, work, vol, &alpha),
                 CB_ERR_LIQUID);
    CHECK(vol[0] == -1.0 && vol[1] == -1.0 && alpha == -1.0);
    /* Liquid but no pairs. */
    CHECK_STATUS(cb_protocol1_distribute(lian, 0, NULL, NULL, NULL, 1e-12,
                                         (cb_protocol1_work){NULL, NULL, NULL}, NULL, &alpha),
                 CB_ERR_LIQUID);
    CHECK(alpha == -1.0);
}

/* At the margin itself: the liquid is exactly (within a few ulps) the rupture volume of a
 * single pair apart. Either the pair is wet and within the rupture distance of its volume
 * as the library computes it, or the liquid cannot be placed; never a wet pair beyond. */
static void protocol1_margin(const cb_law *law, const char *name)
{
    double tw[1], ww[1], vol[1];
    size_t ow[1];
    cb_protocol1_work work = {tw, ww, ow};
    int wet = 0, refused = 0, outside = 0, refused_far = 0;
    for (int i = 0; i < 20000; ++i) {
        double r1 = 1e-3 * (0.2 + uniform()), r2 = 1e-3 * (0.2 + uniform());
        double gap = 1e-4 * (0.01 + uniform()), v_r = 0.0;
        CHECK_STATUS(cb_rupture_volume(law, r1, r2, gap, &v_r), CB_OK);
        double total = v_r;
        for (int k = 0; k < i % 5; ++k) total = nextafter(total, (i / 5) % 2 ? 0.0 : HUGE_VAL);
        double alpha = 0.0;
        cb_status status = cb_protocol1_distribute(law, 1, &r1, &r2, &gap, total, work, vol,
                                                   &alpha);
        if (status == CB_OK) {
            double d = 0.0;
            CHECK_STATUS(cb_rupture_distance(law, r1, r2, vol[0], &d), CB_OK);
            outside += !(gap <= d);
            ++wet;
        } else {
            CHECK_STATUS(status, CB_ERR_LIQUID);
            refused_far += total > v_r * (1.0 + 1e-14);
            ++refused;
        }
    }
    printf("protocol 1 margin (%s): %d wet, %d refused\n", name, wet, refused);
    CHECK(outside == 0);
    CHECK(refused_far == 0);
    CHECK(wet > 1000 && refused > 1000);
}

/* The result does not depend on the order the pairs are given in. */
static void protocol1_permutation(const cb_law *law)
{
    enum { N = 1500 };
    static double r1[N], r2[N], gap[N], p1[N], p2[N], pg[N], tw[N], ww[N], vol[N], pvol[N];
    static size_t ow[N], perm[N];
    cb_protocol1_work work = {tw, ww, ow};
    long double w_all = 0.0L;
    for (size_t i = 0; i < N; ++i) {
        r1[i] = 1e-3 * (0.4 + 0.25 * uniform());
        r2[i] = 1e-3 * (0.4 + 0.25 * uniform());
        double u = uniform();
        gap[i] = u < 0.3 ? -1e-6 * u : 0.2e-3 * u * u;
        w_all += reference_rg3(r1[i], r2[i]);
        perm[i] = i;
    }
    for (size_t i = N - 1; i > 0; --i) {
        size_t j = below(i + 1), t = perm[i];
        perm[i] = perm[j];
        perm[j] = t;
    }
    for (size_t i = 0; i < N; ++i) {
        p1[i] = r1[perm[i]];
        p2[i] = r2[perm[i]];
        pg[i] = gap[perm[i]];
    }
    double total = (double)(1e-3L * w_all), alpha = 0.0, palpha = 0.0;
    CHECK_STATUS(cb_protocol1_distribute(law, N, r1, r2, gap, total, work, vol, &alpha), CB_OK);
    CHECK_STATUS(cb_protocol1_distribute(law, N, p1, p2, pg, total, work, pvol, &palpha), CB_OK);
    CHECK_REL(palpha, alpha, 1e-15);
    int differs = 0;
    for (size_t i = 0; i < N; ++i)
        if (fabs(pvol[i] - vol[perm[i]]) > 1e-15 * vol[perm[i]] ||
            (pvol[i] > 0.0) != (vol[perm[i]] > 0.0))
            ++differs;
    CHECK(differs == 0);
}

static void protocol1_errors(const cb_law *law)
{
    double r[2] = {1e-3, 1e-3}, g[2] = {0.0, 1e-5}, tw[2], ww[2], vol[2] = {-1.0, -1.0};
    size_t ow[2];
    double alpha = -1.0;
    cb_protocol1_work work = {tw, ww, ow}, no_order = {tw, ww, NULL};
    CHECK_STATUS(cb_protocol1_distribute(NULL, 2, r, r, g, 1e-12, work, vol, &alpha),
                 CB_ERR_NULL);
    CHECK_STATUS(cb_protocol1_distribute(law, 2, r, r, g, 1e-12, work, vol, NULL), CB_ERR_NULL);
    CHECK_STATUS(cb_protocol1_distribute(law, 2, NULL, r, g, 1e-12, work, vol, &alpha),
                 CB_ERR_NULL);
    CHECK_STATUS(cb_protocol1_distribute(law, 2, r, r, NULL, 1e-12, work, vol, &alpha),
                 CB_ERR_NULL);
    CHECK_STATUS(cb_protocol1_distribute(law, 2, r, r, g, 1e-12, work, NULL, &alpha),
                 CB_ERR_NULL);
    CHECK_STATUS(cb_protocol1_distribute(law, 2, r, r, g, 1e-12, no_order, vol, &alpha),
                 CB_ERR_NULL);
    cb_law unprepared;
    CHECK_STATUS(cb_law_init(&unprepared, CB_MODEL_RICHEFEU, 0.072, 0.0), CB_OK);
    CHECK_STATUS(cb_protocol1_distribute(&unprepared, 2, r, r, g, 1e-12, work, vol, &alpha),
                 CB_ERR_RANGE);
    CHECK_STATUS(cb_protocol1_distribute(law, 2, r, r, g, NAN, work, vol, &alpha),
                 CB_ERR_NOT_FINITE);
    CHECK_STATUS(cb_protocol1_distribute(law, 2, r, r, g, HUGE_VAL, work, vol, &alpha),
                 CB_ERR_NOT_FINITE);
    CHECK_STATUS(cb_protocol1_distribute(law, 2, r, r, g, -1e-12, work, vol, &alpha),
                 CB_ERR_NEGATIVE);
    double bad_r[2] = {1e-3, NAN}, zero_r[2] = {1e-3, 0.0}, bad_g[2] = {-HUGE_VAL, 0.0};
    CHECK_STATUS(cb_protocol1_distribute(law, 2, bad_r, r, g, 1e-12, work, vol, &alpha),
                 CB_ERR_NOT_FINITE);
    CHECK_STATUS(cb_protocol1_distribute(law, 2, r, zero_r, g, 1e-12, work, vol, &alpha),
                 CB_ERR_NEGATIVE);
    CHECK_STATUS(cb_protocol1_distribute(law, 2, r, r, bad_g, 1e-12, work, vol, &alpha),
                 CB_ERR_NOT_FINITE);
    /* Invalid input is reported even with no liquid to place. */
    CHECK_STATUS(cb_protocol1_distribute(law, 2, r, zero_r, g, 0.0, work, vol, &alpha),
                 CB_ERR_NEGATIVE);
    /* R_g^3 overflowing. */
    double giant[2] = {1e200, 1e200};
    CHECK_STATUS(cb_protocol1_distribute(law, 2, giant, giant, g, 1e-12, work, vol, &alpha),
                 CB_ERR_RANGE);
    /* Volumes underflowing to 0 would lose the liquid. */
    double mm[3] = {1e-3, 1e-3, 1e-3}, touch[3] = {-1e-7, 0.0, -1e-8};
    double tw3[3], ww3[3], vol3[3] = {-1.0, -1.0, -1.0};
    size_t ow3[3];
    cb_protocol1_work work3 = {tw3, ww3, ow3};
    CHECK_STATUS(cb_protocol1_distribute(law, 3, mm, mm, touch, 5e-324, work3, vol3, &alpha),
                 CB_ERR_RANGE);
    CHECK(vol3[0] == -1.0 && vol3[1] == -1.0 && vol3[2] == -1.0 && alpha == -1.0);
}

/* Conservation with thousands of pairs, many times over. */
static void protocol1_conservation(const cb_law *law)
{
    enum { N = 4000 };
    static double r1[N], r2[N], gap[N], tw[N], ww[N], vol[N];
    static size_t ow[N];
    cb_protocol1_work work = {tw, ww, ow};
    double worst = 0.0;
    for (int run = 0; run < 40; ++run) {
        long double w_all = 0.0L;
        for (size_t i = 0; i < N; ++i) {
            r1[i] = 1e-3 * (0.05 + uniform());
            r2[i] = 1e-3 * (0.05 + uniform());
            double u = uniform();
            gap[i] = u < 0.5 ? -1e-6 * u : 0.5e-3 * u * u * u;
            w_all += reference_rg3(r1[i], r2[i]);
        }
        double total = (double)(w_all * pow(10.0, -6.0 + 5.0 * uniform())), alpha = 0.0;
        CHECK_STATUS(cb_protocol1_distribute(law, N, r1, r2, gap, total, work, vol, &alpha),
                     CB_OK);
        long double sum = 0.0L;
        for (size_t i = 0; i < N; ++i) sum += vol[i];
        double rel = (double)(fabsl(sum - total) / total);
        if (rel > worst) worst = rel;
    }
    printf("protocol 1: worst relative conservation error over 40 x %d pairs: %.3g\n", N, worst);
    CHECK(worst <= 1e-13);
}

int main(int argc, char **argv)
{
    (void)argc;
    cb_law lian = make_law(0.0, NULL, NULL);
    cb_law lian30 = make_law(30.0, NULL, NULL);
    cb_law willett = make_law(0.0, "willett", NULL);
    cb_law willett40 = make_law(40.0, "willett", NULL);
    const long double deg = PI_L / 180.0L;
    rule lian_rule = {0, 1.0L}, lian30_rule = {0, 1.0L + 15.0L * deg};
    rule willett_rule = {1, 1.0L}, willett40_rule = {1, 1.0L + 20.0L * deg};

    protocol1_hand(&lian);
    protocol1_random(&lian, lian_rule, "lian, theta 0");
    protocol1_random(&lian30, lian30_rule, "lian, theta 30");
    protocol1_random(&willett, willett_rule, "willett, theta 0");
    protocol1_random(&willett40, willett40_rule, "willett, theta 40");
    protocol1_margin(&lian, "lian, theta 0");
    protocol1_margin(&lian30, "lian, theta 30");
    protocol1_margin(&willett40, "willett, theta 40");
    protocol1_permutation(&lian);
    protocol1_permutation(&willett);
    protocol1_errors(&lian);
    protocol1_conservation(&lian);
    protocol1_conservation(&willett40);

    cb_law_release(&lian);
    cb_law_release(&lian30);
    cb_law_release(&willett);
    cb_law_release(&willett40);
    return check_report(argv[0]);
}
