/* protocol1.c — Richefeu 2007 Protocol 1 (§2.4): the homogeneous distribution of liquid.
 *
 *   V_b = alpha R^3, R = R_g = sqrt(R_i R_j)          (eq. 14)
 *   sum over eligible pairs of V_b = V_liquid          (eq. 13)
 *   a pair is eligible when its gap does not exceed the rupture distance of the volume it
 *   would receive (condition iii; a touching or overlapping pair is always eligible).
 * A grain-wall pair (r2 = CB_PLANE) has R = r1, the grain and its mirror image in the
 * wall: Richefeu's protocols are for grains only, and this gives a grain on a wall the
 * bridge it would have with an equal grain.
 *
 * Eligibility depends on alpha, and alpha on the eligible set. The rupture distance grows
 * with the volume, so pair p is eligible exactly when alpha >= alpha_p, its threshold:
 *
 *   alpha_p = cb_rupture_volume(law, r1, r2, gap) / R_g^3    (0 for gap <= 0).
 *
 * With the pairs sorted by threshold (ties by index) and W_k the sum of R_g^3 over the
 * first k, alpha_k = V_liquid / W_k falls with k while the k-th threshold rises, so the
 * k for which "the first k pairs are all eligible at alpha_k" (alpha_k >= k-th threshold)
 * form a prefix 1..K. We take the largest, K, and alpha = alpha_K.
 *
 * Equivalently, with S(alpha) = alpha * sum{R_g^3 : alpha_p <= alpha} (non-decreasing):
 *   - if S crosses V_liquid continuously, alpha solves S(alpha) = V_liquid, and the wet set
 *     is exactly the set of pairs eligible at alpha: the unique solution of eqs. 13-14;
 *   - if V_liquid falls in a jump of S (at a threshold t: S(t-) <= V_liquid < S(t)), eqs.
 *     13-14 have no self-consistent solution: with the pair(s) at t alpha drops below t,
 *     without them alpha is >= t. We keep the pairs below t and leave the margin pair dry,
 *     although it is eligible at the alpha we return -- and with it every pair whose
 *     threshold lies in [t, alpha] (all eligible at alpha, none admissible in threshold
 *     order, since admitting the first of them drops alpha below its threshold).
 *     Condition (iii) holds for every wet pair and eq. 13 holds; only "all eligible pairs
 *     receive liquid" fails, for those pairs. Admission is by threshold order: a pair
 *     with a higher threshold is not admitted in place of the margin pair even if it alone
 *     could have been.
 * With no pair admissible (the liquid is less than the rupture volume of the pair with the
 * lowest threshold, and no pair touches) the liquid cannot be placed in bridges:
 * CB_ERR_LIQUID, and nothing is written.
 *
 * Rounding at the margin: the forward check "gap <= cb_rupture_distance(volume)" is made
 * for every wet pair with the very volume written out; a pair that passes by threshold
 * but fails it by rounding is dropped like a margin pair (alpha then rises, so the others
 * stay eligible). Hence every wet pair satisfies the forward check exactly. The check uses
 * the law's rupture rule with validity extend: Protocol 1 does not judge the validity
 * range of the volumes it hands out (the force call does, under validity strict).
 *
 * Conservation: each wet pair gets fl(alpha * R_g^3), alpha = V_liquid / W_K with W_K
 * summed with Neumaier's compensation, so sum V_b = V_liquid to a few units of rounding,
 * independent of the number of pairs. Cost O(n log n) (an in-place heapsort), no
 * allocation: the caller's work arrays hold the thresholds, weights and order.
 * The work arrays and `volume` must not overlap each other or the inputs.
 * CB_ERR_RANGE when R_g^3, their sum or a threshold overflows, or when the volume of a
 * touching pair underflows to 0 (liquid would be lost; only for absurd magnitudes).
 */
#include "laws.h"

#include <math.h>

/* Order of pairs: by threshold, ties by index — a total order, so the result does not
 * depend on the sorting algorithm. */
static int before(const double *threshold, size_t a, size_t b)
{
    return threshold[a] < threshold[b] || (threshold[a] == threshold[b] && a < b);
}

static void sift_down(const double *threshold, size_t *order, size_t root, size_t end)
{
    for (;;) {
        size_t child = 2 * root + 1;
        if (child >= end) return;
        if (child + 1 < end && before(threshold, order[child], order[child + 1])) ++child;
        if (!before(threshold, order[root], order[child])) return;
        size_t swap = order[root];
        order[root] = order[child];
        order[child] = swap;
        root = child;
    }
}

/* In-place heapsort of order[0..n) by (threshold, index), ascending. */
static void sort_by_threshold(const double *threshold, size_t *order, size_t n)
{
    if (n < 2) return;
    for (size_t i = n / 2; i-- > 0;) sift_down(threshold, order, i, n);
    for (size_t end = n - 1; end > 0; --end) {
        size_t swap = order[0];
        order[0] = order[end];
        order[end] = swap;
        sift_down(threshold, order, 0, end);
    }
}

/* Neumaier's compensated running sum. */
typedef struct sum {
    double s, c;
} sum;

static void sum_add(sum *acc, double x)
{
    double t = acc->s + x;
    if (fabs(acc->s) >= fabs(x)) acc->c += (acc->s - t) + x;
    else acc->c += (x - t) + acc->s;
    acc->s = t;
}

static double sum_value(const sum *acc) { return acc->s + acc->c; }

static double prefix_weight(const double *weight, const size_t *order, size_t k)
{
    sum acc = {0.0, 0.0};
    for (size_t i = 0; i < k; ++i) sum_add(&acc, weight[order[i]]);
    return sum_value(&acc);
}

static cb_status check_inputs(const cb_law *law, size_t n, const double *r1, const double *r2,
                              const double *gap, double total_liquid, cb_protocol1_work work,
                              const double *volume, const double *alpha)
{
    if (!law || !alpha) return CB_ERR_NULL;
    if (n > 0 && (!r1 || !r2 || !gap || !volume || !work.threshold || !work.weight ||
                  !work.order))
        return CB_ERR_NULL;
    if (!law->prepared) return CB_ERR_RANGE;
    if (!isfinite(total_liquid)) return CB_ERR_NOT_FINITE;
    if (total_liquid < 0.0) return CB_ERR_NEGATIVE;
    for (size_t i = 0; i < n; ++i)
        if (!isfinite(r1[i]) || !cb_finite_or_plane(r2[i]) || !isfinite(gap[i]))
            return CB_ERR_NOT_FINITE;
    for (size_t i = 0; i < n; ++i)
        if (r1[i] <= 0.0 || r2[i] <= 0.0) return CB_ERR_NEGATIVE;
    return CB_OK;
}

/* Each pair's weight R_g^3 (eq. 14) and threshold alpha_p, and the pairs in threshold order. */
static cb_status sort_pairs(const cb_law *law, size_t n, const double *r1, const double *r2,
                            const double *gap, cb_protocol1_work work)
{
    for (size_t i = 0; i < n; ++i) {
        /* a wall pair (r2 a plane) weighs as the grain and its mirror image: R_g = r1 */
        double rg = cb_is_plane(r2[i]) ? r1[i] : cb_radius_geometric(r1[i], r2[i]);
        double w = rg * rg * rg;
        if (!(w > 0.0) || !isfinite(w)) return CB_ERR_RANGE; /* R_g^3 under- or overflows */
        double t = 0.0;
        if (gap[i] > 0.0) {
            double v = 0.0;
            cb_status status = cb_rupture_volume(law, r1[i], r2[i], gap[i], &v);
            if (status != CB_OK) return status;
            t = v / w;
            if (!isfinite(t)) return CB_ERR_RANGE;
        }
        work.weight[i] = w;
        work.threshold[i] = t;
        work.order[i] = i;
    }
    sort_by_threshold(work.threshold, work.order, n);
    return CB_OK;
}

/* The largest admissible prefix K (see the comment at the top): *wet = K, *share = alpha_K. */
static cb_status largest_prefix(size_t n, double total_liquid, cb_protocol1_work work,
                                size_t *wet, double *share)
{
    sum acc = {0.0, 0.0};
    *wet = 0;
    *share = 0.0;
    for (size_t k = 0; k < n; ++k) {
        sum_add(&acc, work.weight[work.order[k]]);
        double w_k = sum_value(&acc);
        if (!isfinite(w_k)) return CB_ERR_RANGE;
        double a_k = total_liquid / w_k;
        if (a_k < work.threshold[work.order[k]]) break;
        *wet = k + 1;
        *share = a_k;
    }
    return CB_OK;
}

/* The forward check, on the volumes as they will be written; drop rounding failures (the
 * prefix shrinks to the first failure and alpha rises).  CB_ERR_LIQUID when none is left. */
static cb_status forward_check(const cb_law *law, const double *r1, const double *r2,
                               const double *gap, double total_liquid, cb_protocol1_work work,
                               size_t *wet, double *share)
{
    const double *weight = work.weight;
    const size_t *order = work.order;
    cb_law extend = *law; /* a shallow copy: never released */
    extend.validity = CB_VALIDITY_EXTEND;
    for (;;) {
        if (*wet == 0) return CB_ERR_LIQUID; /* the liquid cannot be placed in any bridge */
        size_t first_failure = *wet;
        for (size_t k = 0; k < *wet; ++k) {
            size_t p = order[k];
            double v = *share * weight[p], d = 0.0;
            /* A touching pair whose volume underflows to 0 would lose its liquid. */
            if (gap[p] <= 0.0) {
                if (!(v > 0.0)) return CB_ERR_RANGE;
                continue;
            }
            cb_status status = v > 0.0 ? cb_rupture_distance(&extend, r1[p], r2[p], v, &d)
                                       : CB_OK;
            if (status != CB_OK) return status;
            if (!(gap[p] <= d)) {
                first_failure = k;
                break;
            }
        }
        if (first_failure == *wet) return CB_OK;
        *wet = first_failure;
        if (*wet > 0) *share = total_liquid / prefix_weight(weight, order, *wet);
    }
}

cb_status cb_protocol1_distribute(const cb_law *law, size_t n, const double *r1,
                                  const double *r2, const double *gap, double total_liquid,
                                  cb_protocol1_work work, double *volume, double *alpha)
{
    cb_status status = check_inputs(law, n, r1, r2, gap, total_liquid, work, volume, alpha);
    if (status != CB_OK) return status;
    if (total_liquid == 0.0) {
        for (size_t i = 0; i < n; ++i) volume[i] = 0.0;
        *alpha = 0.0;
        return CB_OK;
    }
    if (n == 0) return CB_ERR_LIQUID; /* liquid but no pair to hold it */

    size_t wet = 0;
    double share = 0.0;
    status = sort_pairs(law, n, r1, r2, gap, work);
    if (status == CB_OK) status = largest_prefix(n, total_liquid, work, &wet, &share);
    if (status == CB_OK)
        status = forward_check(law, r1, r2, gap, total_liquid, work, &wet, &share);
    if (status != CB_OK) return status;

    for (size_t i = 0; i < n; ++i) volume[i] = 0.0;
    for (size_t k = 0; k < wet; ++k) volume[work.order[k]] = share * work.weight[work.order[k]];
    *alpha = share;
    return CB_OK;
}
