/* ly_branch.c — the fixed-volume branch connected to gap 0 (of the two branches at fixed
 * volume, the physical one; equations in laplace_young_internal.h): the bridge at contact
 * by continuation in delta1 from a small toroidal bridge, then pseudo-arclength continuation
 * in (delta1, delta2, P, S, gap) up to the fold (the rupture distance), since neither the
 * gap nor delta1 is monotone along it.
 *
 * Branch points. For equal spheres at larger contact angles (theta above about 30 deg:
 * 29 to 31 deg for V / R^3 from 0.1 to 1e-5) the symmetric bridge loses stability to an
 * asymmetric one (liquid moving to one sphere) before the fold of the symmetric branch:
 * a symmetry-breaking (pitchfork) bifurcation, 1.5 to 3 % below that fold at 40 deg. At
 * theta -> 90 deg it becomes the Plateau limit L = pi r of a cylinder with free contact
 * lines (rupture -> pi^(1/3) V^(1/3)), where the symmetric branch has no fold at all.
 * For unequal spheres (and for equal spheres in the discrete problem, which RK4 makes very
 * slightly asymmetric) the bifurcation is imperfect: the branch from gap 0 turns sharply
 * and folds just before it, and the other piece (the continued symmetric branch) lies
 * close by. The step control keeps the orientation of the Jacobian's null space, which
 * flips when a step jumps to the other piece, so the trace follows the turn and finds
 * that fold: the rupture distance is then continuous in the size ratio through 1. A
 * branch point that steps of BRANCH_POINT_STEP cannot resolve is taken as the rupture. */
#include "laplace_young_internal.h"

#include <math.h>
#include <string.h>

#define START_ITERATIONS 40    /* Newton iterations for the bridge at contact */
#define MAX_DELTA1_FACTOR 1.5  /* largest change of delta1 per continuation step */
#define STEP_INITIAL 0.1       /* arclength steps, in relative change of the variables */
#define STEP_MAX 0.4
#define BRANCH_POINT_STEP 1e-9 /* an orientation flip over a step this short: a branch point */
#define CORRECTOR_ITERATIONS 8
#define MIN_TANGENT_COSINE 0.9 /* consecutive tangents must not turn more than ~25 deg */
#define ROOT_ITERATIONS 60
#define SAME_GAP 1e-14         /* relative gap tolerance of a traced point */

enum { STEP_REJECTED = -1, STEP_FLIPPED = -2 }; /* try_step outcomes besides success */

static void copy_point(double to[LY_NVAR], const double from[LY_NVAR])
{
    memcpy(to, from, LY_NVAR * sizeof from[0]);
}

/* ------------------------------------------------------------ at contact */

/* The bridge at gap 0 with delta1 fixed: residuals x, y, phi in (delta2, P, S). */
static int solve_fixed_delta1(const ly_geometry *g, double z[LY_NVAR], ly_profile *p)
{
    ly_system sys;
    int iterations;
    memset(&sys, 0, sizeof sys);
    sys.geometry = g;
    sys.n_res = 3;
    sys.n_free = 3;
    sys.free_var[0] = LY_DELTA2;
    sys.free_var[1] = LY_PRESSURE;
    sys.free_var[2] = LY_LENGTH;
    sys.max_iterations = START_ITERATIONS;
    ly_variable_scales(z, sys.scale);
    return ly_newton(&sys, z, p, &iterations);
}

/* The bridge of the prescribed volume at fixed gap: all four residuals in
 * (delta1, delta2, P, S). Used at gap 0 only, where the branch is far from its fold. */
static int solve_fixed_volume(const ly_geometry *g, double z[LY_NVAR], ly_profile *p)
{
    ly_system sys;
    int iterations, k;
    memset(&sys, 0, sizeof sys);
    sys.geometry = g;
    sys.n_res = 4;
    sys.n_free = 4;
    for (k = 0; k < 4; ++k)
        sys.free_var[k] = LY_DELTA1 + k;
    sys.max_iterations = START_ITERATIONS;
    ly_variable_scales(z, sys.scale);
    return ly_newton(&sys, z, p, &iterations);
}

/* Predict the gap-0 bridge at delta1 * factor from the one at z (profile p with Jacobian):
 * du/d delta1 from the linearised residuals x, y, phi, applied as a power law
 * u * factor^(d ln u / d ln delta1), exact in the small-bridge scaling (delta2 ~ delta1,
 * S ~ delta1^2, P ~ delta1^-2), linear where u is near zero. */
static int predict_in_delta1(const ly_profile *p, const double z[LY_NVAR], double factor,
                             double out[LY_NVAR])
{
    static const int var[3] = {LY_DELTA2, LY_PRESSURE, LY_LENGTH};
    double a[LY_NVAR][LY_NVAR], b[LY_NVAR], du[LY_NVAR], scale[LY_NVAR];
    int i, j;
    ly_variable_scales(z, scale);
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j)
            a[i][j] = p->jacobian[i][var[j]] * scale[var[j]];
        b[i] = -p->jacobian[i][LY_DELTA1];
    }
    if (!ly_solve_dense(3, a, b, du))
        return 0;
    copy_point(out, z);
    out[LY_DELTA1] = z[LY_DELTA1] * factor;
    for (j = 0; j < 3; ++j) {
        int v = var[j];
        double slope = du[j] * scale[v];
        double log_slope = z[v] != 0.0 ? slope * z[LY_DELTA1] / z[v] : INFINITY;
        out[v] = fabs(log_slope) < 8.0 ? z[v] * pow(factor, log_slope)
                                       : z[v] + slope * (out[LY_DELTA1] - z[LY_DELTA1]);
    }
    return 1;
}

/* A first filling angle below that of the bridge: the contact radius of liquid filling the
 * whole wedge between the spheres, V = pi y^4 / (2 R_h), capped well inside both spheres. */
static double initial_filling_angle(const ly_geometry *g)
{
    double y = pow(2.0 * g->volume / CB_PI, 0.25);
    return asin(fmin(y, 0.5 * fmin(g->r1, g->r2)) / g->r1);
}

/* A small gap-0 bridge from the toroidal guess, shrinking delta1 until Newton agrees. */
static int first_bridge(const ly_geometry *g, double z[LY_NVAR], ly_profile *p)
{
    double delta1 = initial_filling_angle(g);
    int tries;
    for (tries = 0; tries < 20; ++tries, delta1 *= 0.5) {
        ly_toroidal_guess(g, delta1, z);
        if (solve_fixed_delta1(g, z, p))
            return 1;
    }
    return 0;
}

int ly_start_at_contact(const ly_geometry *g, double z[LY_NVAR])
{
    ly_profile p, q;
    double max_factor = MAX_DELTA1_FACTOR, trial[LY_NVAR];
    int it;
    if (!first_bridge(g, z, &p))
        return 0;
    /* Continue in delta1 (the volume grows with it, about as delta1^4) until the volume is
     * near V, then switch to the fixed-volume problem. */
    for (it = 0; it < 200; ++it) {
        double ratio = p.volume > 0.0 ? pow(g->volume / p.volume, 0.25) : max_factor;
        double factor = fmax(1.0 / max_factor, fmin(ratio, max_factor));
        if (fabs(log(ratio)) < log(MAX_DELTA1_FACTOR) && predict_in_delta1(&p, z, ratio, trial)
            && solve_fixed_volume(g, trial, &q)) {
            copy_point(z, trial);
            return 1;
        }
        factor = fmin(factor, 0.5 * (1.0 + CB_PI / z[LY_DELTA1])); /* delta1 stays < pi */
        if (predict_in_delta1(&p, z, factor, trial) && solve_fixed_delta1(g, trial, &q)) {
            copy_point(z, trial);
            p = q;
            max_factor = fmin(MAX_DELTA1_FACTOR, max_factor * max_factor);
        } else {
            max_factor = sqrt(max_factor);
            if (max_factor < 1.0 + 1e-6)
                return 0;
        }
    }
    return 0;
}

/* ------------------------------------------------------ pseudo-arclength */

/* The corrector: the branch point on the hyperplane tangent . (z - base)/scale = sigma,
 * from the predictor base + sigma scale tangent. */
static int correct(const ly_geometry *g, const double base[LY_NVAR],
                   const double scale[LY_NVAR], const double tangent[LY_NVAR], double sigma,
                   double z[LY_NVAR], ly_profile *p, int *iterations)
{
    ly_system sys;
    int k;
    memset(&sys, 0, sizeof sys);
    sys.geometry = g;
    sys.n_res = 4;
    sys.arclength = 1;
    sys.n_free = LY_NVAR;
    for (k = 0; k < LY_NVAR; ++k) {
        sys.free_var[k] = k;
        sys.scale[k] = scale[k];
        sys.tangent[k] = tangent[k];
        sys.anchor[k] = base[k] + sigma * scale[k] * tangent[k];
        z[k] = sys.anchor[k];
    }
    sys.max_iterations = CORRECTOR_ITERATIONS;
    return ly_newton(&sys, z, p, iterations);
}

/* The branch point at arclength sigma along step k, and its unit tangent in the metric of
 * step k (whose gap component is > 0 before the fold). */
static int point_on_step(const ly_geometry *g, const ly_branch *b, int k, double sigma,
                         double z[LY_NVAR], double tangent[LY_NVAR])
{
    ly_profile p;
    int iterations;
    return correct(g, b->z[k], b->scale[k], b->tangent[k], sigma, z, &p, &iterations)
           && ly_branch_tangent(&p, b->scale[k], b->tangent[k], tangent);
}

/* The fold inside step k (tangent gap component > 0 at sigma = 0, <= 0 at sigma = hi):
 * the root of that component by the Illinois method. Writes the fold as point k+1. */
static int refine_fold(const ly_geometry *g, ly_branch *b, int k, double hi, double t_hi)
{
    double lo = 0.0, t_lo = b->tangent[k][LY_GAP], z[LY_NVAR], tangent[LY_NVAR];
    double sigma = hi;
    int it, side = 0;
    copy_point(z, b->z[k + 1]);
    for (it = 0; it < ROOT_ITERATIONS && hi - lo > 1e-12 * b->step[k]; ++it) {
        double t;
        sigma = (lo * t_hi - hi * t_lo) / (t_hi - t_lo);
        if (!point_on_step(g, b, k, sigma, z, tangent))
            return 0;
        t = tangent[LY_GAP];
        if (fabs(t) <= 1e-13)
            break;
        if (t > 0.0) {
            lo = sigma;
            t_lo = t;
            if (side > 0)
                t_hi *= 0.5;
            side = 1;
        } else {
            hi = sigma;
            t_hi = t;
            if (side < 0)
                t_lo *= 0.5;
            side = -1;
        }
    }
    b->step[k] = sigma;
    copy_point(b->z[k + 1], z);
    return 1;
}

/* The scaled unit tangent of a raw direction in the metric scale. */
static void scaled_unit(const double raw[LY_NVAR], const double scale[LY_NVAR],
                        double unit[LY_NVAR])
{
    double norm = 0.0;
    int k;
    for (k = 0; k < LY_NVAR; ++k) {
        unit[k] = raw[k] / scale[k];
        norm += unit[k] * unit[k];
    }
    norm = sqrt(norm);
    for (k = 0; k < LY_NVAR; ++k)
        unit[k] /= norm;
}

static void scaled_to_raw(const double unit[LY_NVAR], const double scale[LY_NVAR],
                          double raw[LY_NVAR])
{
    int k;
    for (k = 0; k < LY_NVAR; ++k)
        raw[k] = unit[k] * scale[k];
}

static double dot(const double a[LY_NVAR], const double b[LY_NVAR])
{
    double s = 0.0;
    int k;
    for (k = 0; k < LY_NVAR; ++k)
        s += a[k] * b[k];
    return s;
}

/* The tangent at gap 0, pointing to increasing gap, as a raw direction; returns its
 * orientation (see ly_branch_tangent), 0 on failure. */
static int initial_direction(const ly_geometry *g, const double z[LY_NVAR],
                             double direction[LY_NVAR])
{
    ly_profile p;
    double scale[LY_NVAR], reference[LY_NVAR] = {0.0, 0.0, 0.0, 0.0, 1.0}, unit[LY_NVAR];
    int orientation;
    if (!ly_shoot(g, z, 1, &p))
        return 0;
    ly_variable_scales(z, scale);
    if (!(orientation = ly_branch_tangent(&p, scale, reference, unit)))
        return 0;
    scaled_to_raw(unit, scale, direction);
    return orientation;
}

/* One predictor-corrector step of length ds from point k, written as point k+1 with its
 * unit tangent (metric of step k). A step is good when the corrector converges, the
 * tangent turns little and the orientation is kept: a flip means the step crossed a
 * branch point or jumped onto another piece of the branches near one (see the top of this
 * file). Returns the corrector iterations, STEP_REJECTED or STEP_FLIPPED. */
static int try_step(const ly_geometry *g, ly_branch *b, int k, double ds, int orientation,
                    double tangent[LY_NVAR])
{
    ly_profile p;
    int iterations, turned;
    if (!correct(g, b->z[k], b->scale[k], b->tangent[k], ds, b->z[k + 1], &p, &iterations)
        || !(turned = ly_branch_tangent(&p, b->scale[k], b->tangent[k], tangent))
        || dot(tangent, b->tangent[k]) < MIN_TANGENT_COSINE)
        return STEP_REJECTED;
    return turned == orientation ? iterations : STEP_FLIPPED;
}

int ly_trace(const ly_geometry *g, double gap_stop, ly_branch *b)
{
    double direction[LY_NVAR], ds = STEP_INITIAL;
    int k, orientation;
    b->count = 1;
    b->has_fold = 0;
    if (!ly_start_at_contact(g, b->z[0])
        || !(orientation = initial_direction(g, b->z[0], direction)))
        return 0;
    for (k = 0; b->z[k][LY_GAP] < gap_stop; ++k) {
        double tangent[LY_NVAR];
        int iterations;
        if (k + 1 >= LY_MAX_POINTS)
            return 0;
        ly_variable_scales(b->z[k], b->scale[k]);
        scaled_unit(direction, b->scale[k], b->tangent[k]);
        while ((iterations = try_step(g, b, k, ds, orientation, tangent)) < 0) {
            if ((ds *= 0.5) < BRANCH_POINT_STEP) {
                /* Still flipping over so short a step: a branch point within ds of point
                 * k, where the bridge loses stability; the rupture is taken there. */
                b->has_fold = iterations == STEP_FLIPPED;
                return b->has_fold;
            }
        }
        b->step[k] = ds;
        b->count = k + 2;
        if (tangent[LY_GAP] <= 0.0) { /* the gap has passed its maximum: the fold */
            b->has_fold = 1;
            return refine_fold(g, b, k, ds, tangent[LY_GAP]);
        }
        scaled_to_raw(tangent, b->scale[k], direction);
        if (iterations <= 3)
            ds = fmin(1.5 * ds, STEP_MAX);
    }
    return 1;
}

/* ---------------------------------------------------------- point at gap */

/* A traced point at this gap, to round-off (the gap may have been through SI units):
 * its index, or -1. */
static int traced_point_at(const ly_branch *b, int k, double gap)
{
    int i;
    for (i = k; i <= k + 1 && i < b->count; ++i) {
        double scale[LY_NVAR];
        ly_variable_scales(b->z[i], scale);
        if (fabs(b->z[i][LY_GAP] - gap) <= SAME_GAP * scale[LY_GAP])
            return i;
    }
    return -1;
}

int ly_point_at_gap(const ly_geometry *g, const ly_branch *b, double gap, double z[LY_NVAR])
{
    double lo, hi, sigma, tangent[LY_NVAR], gap_scale;
    int k, it, traced;
    for (k = b->count - 1; k > 0 && b->z[k][LY_GAP] > gap; --k)
        ;
    if ((traced = traced_point_at(b, k, gap)) >= 0) {
        copy_point(z, b->z[traced]);
        return 1;
    }
    if (k == b->count - 1)
        return 0; /* beyond the traced branch */
    /* Safeguarded Newton in sigma on gap(sigma) = gap inside step k, where the gap rises
     * monotonically; d gap / d sigma = scale_gap t_gap / (t . tangent_k). */
    lo = 0.0;
    hi = b->step[k];
    gap_scale = b->scale[k][LY_GAP];
    sigma = hi * (gap - b->z[k][LY_GAP]) / (b->z[k + 1][LY_GAP] - b->z[k][LY_GAP]);
    for (it = 0; it < ROOT_ITERATIONS; ++it) {
        double h, slope, next;
        if (!point_on_step(g, b, k, sigma, z, tangent))
            return 0;
        h = z[LY_GAP] - gap;
        if (fabs(h) <= 1e-13 * gap_scale)
            return 1;
        if (h < 0.0)
            lo = sigma;
        else
            hi = sigma;
        slope = gap_scale * tangent[LY_GAP] / dot(tangent, b->tangent[k]);
        next = sigma - h / slope;
        sigma = (slope > 0.0 && next > lo && next < hi) ? next : 0.5 * (lo + hi);
        if (hi - lo <= 1e-14 * b->step[k])
            return fabs(h) <= 1e-10 * gap_scale;
    }
    return 0;
}
