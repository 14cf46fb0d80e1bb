/* ly_newton.c — damped Newton on the shooting residuals (with or without the volume
 * equation, with or without a pseudo-arclength equation), and the branch tangent. */
#include "laplace_young_internal.h"

#include <math.h>

#define RESIDUAL_TOLERANCE 1e-12 /* scaled residual (inf-norm) of a converged point */
#define RESIDUAL_FLOOR 1e-9      /* accepted if no step can reduce it further (round-off) */
#define MIN_DAMPING (1.0 / 256.0)

int ly_solve_dense(int n, double a[LY_NVAR][LY_NVAR], double b[LY_NVAR], double x[LY_NVAR])
{
    int col[LY_NVAR], i, j, k, sign = 1;
    for (j = 0; j < n; ++j)
        col[j] = j;
    for (k = 0; k < n; ++k) {
        int pr = k, pc = k;
        double best = -1.0;
        for (i = k; i < n; ++i)
            for (j = k; j < n; ++j)
                if (fabs(a[i][j]) > best) {
                    best = fabs(a[i][j]);
                    pr = i;
                    pc = j;
                }
        if (!(best > 0.0) || !isfinite(best))
            return 0;
        if (pr != k)
            sign = -sign;
        if (pc != k)
            sign = -sign;
        if (a[pr][pc] < 0.0)
            sign = -sign;
        for (j = 0; j < n; ++j) { /* row swap k <-> pr */
            double t = a[k][j];
            a[k][j] = a[pr][j];
            a[pr][j] = t;
        }
        {
            double t = b[k];
            b[k] = b[pr];
            b[pr] = t;
        }
        for (i = 0; i < n; ++i) { /* column swap k <-> pc */
            double t = a[i][k];
            a[i][k] = a[i][pc];
            a[i][pc] = t;
        }
        {
            int t = col[k];
            col[k] = col[pc];
            col[pc] = t;
        }
        for (i = k + 1; i < n; ++i) {
            double m = a[i][k] / a[k][k];
            for (j = k; j < n; ++j)
                a[i][j] -= m * a[k][j];
            b[i] -= m * b[k];
        }
    }
    for (k = n - 1; k >= 0; --k) {
        double s = b[k];
        for (j = k + 1; j < n; ++j)
            s -= a[k][j] * b[j];
        b[k] = s / a[k][k];
    }
    for (k = 0; k < n; ++k)
        x[col[k]] = b[k];
    for (k = 0; k < n; ++k)
        if (!isfinite(x[k]))
            return 0;
    return sign;
}

void ly_variable_scales(const double z[LY_NVAR], double scale[LY_NVAR])
{
    double length = z[LY_LENGTH];
    scale[LY_DELTA1] = z[LY_DELTA1];
    scale[LY_DELTA2] = z[LY_DELTA2];
    scale[LY_PRESSURE] = fmax(fabs(z[LY_PRESSURE]), 1.0 / length);
    scale[LY_LENGTH] = length;
    scale[LY_GAP] = fmax(fabs(z[LY_GAP]), length);
}

/* Residual row scales: end-point mismatch relative to the profile length, phi in
 * radians, volume relative to the target. Fixed for one Newton solve. */
static void residual_scales(const ly_system *sys, const double z[LY_NVAR],
                            double row[LY_NRES])
{
    row[LY_RES_X] = row[LY_RES_Y] = 1.0 / z[LY_LENGTH];
    row[LY_RES_PHI] = 1.0;
    row[LY_RES_VOLUME] = 1.0 / sys->geometry->volume;
}

static int equation_count(const ly_system *sys) { return sys->n_res + sys->arclength; }

/* The scaled residual vector of the system at z. */
static void system_residual(const ly_system *sys, const double row[LY_NRES],
                            const double z[LY_NVAR], const ly_profile *p, double r[LY_NVAR])
{
    int i;
    for (i = 0; i < sys->n_res; ++i)
        r[i] = row[i] * p->residual[i];
    if (sys->arclength) {
        double s = 0.0;
        for (i = 0; i < LY_NVAR; ++i)
            s += sys->tangent[i] * (z[i] - sys->anchor[i]) / sys->scale[i];
        r[sys->n_res] = s;
    }
}

static double norm2(int n, const double *r)
{
    double s = 0.0;
    int i;
    for (i = 0; i < n; ++i)
        s += r[i] * r[i];
    return sqrt(s);
}

static double norm_inf(int n, const double *r)
{
    double m = 0.0;
    int i;
    for (i = 0; i < n; ++i)
        m = fmax(m, fabs(r[i]));
    return m;
}

/* The Newton step dz (raw variables) of the system at z. */
static int newton_step(const ly_system *sys, const double row[LY_NRES], const ly_profile *p,
                       const double r[LY_NVAR], double dz[LY_NVAR])
{
    double a[LY_NVAR][LY_NVAR], b[LY_NVAR], x[LY_NVAR];
    int i, j, n = equation_count(sys);
    for (j = 0; j < sys->n_free; ++j) {
        int v = sys->free_var[j];
        for (i = 0; i < sys->n_res; ++i)
            a[i][j] = row[i] * p->jacobian[i][v] * sys->scale[v];
        if (sys->arclength)
            a[sys->n_res][j] = sys->tangent[v];
    }
    for (i = 0; i < n; ++i)
        b[i] = -r[i];
    if (!ly_solve_dense(n, a, b, x))
        return 0;
    for (i = 0; i < LY_NVAR; ++i)
        dz[i] = 0.0;
    for (j = 0; j < sys->n_free; ++j)
        dz[sys->free_var[j]] = x[j] * sys->scale[sys->free_var[j]];
    return 1;
}

/* The largest damping in (0, 1] that keeps the filling angles inside (0, pi), changing
 * by at most 0.5 rad, and the profile length positive; on a plane, the radius of its
 * contact line (z[LY_DELTA2]) positive, changing by at most 0.5 R_h. */
static double step_limit(const ly_geometry *g, const double z[LY_NVAR],
                         const double dz[LY_NVAR])
{
    double lambda = 1.0;
    int k;
    for (k = LY_DELTA1; k <= LY_DELTA2; ++k) {
        int angle = !(k == LY_DELTA2 && g->plane);
        if (dz[k] < 0.0)
            lambda = fmin(lambda, (2.0 / 3.0) * z[k] / -dz[k]);
        else if (dz[k] > 0.0 && angle)
            lambda = fmin(lambda, (2.0 / 3.0) * (CB_PI - z[k]) / dz[k]);
        if (fabs(dz[k]) > 0.5)
            lambda = fmin(lambda, 0.5 / fabs(dz[k]));
    }
    if (dz[LY_LENGTH] < 0.0)
        lambda = fmin(lambda, (2.0 / 3.0) * z[LY_LENGTH] / -dz[LY_LENGTH]);
    return lambda;
}

int ly_newton(const ly_system *sys, double z[LY_NVAR], ly_profile *profile, int *iterations)
{
    double row[LY_NRES], r[LY_NVAR];
    int n = equation_count(sys), it, k;
    residual_scales(sys, z, row);
    if (!ly_shoot(sys->geometry, z, 1, profile))
        return 0;
    system_residual(sys, row, z, profile, r);
    for (it = 0; it < sys->max_iterations; ++it) {
        double dz[LY_NVAR], lambda, merit = norm2(n, r);
        int accepted = 0;
        if (norm_inf(n, r) <= RESIDUAL_TOLERANCE)
            break;
        if (!newton_step(sys, row, profile, r, dz))
            return 0;
        /* Backtracking: halve until the profile is valid and the residual decreases. */
        for (lambda = step_limit(sys->geometry, z, dz); lambda >= MIN_DAMPING && !accepted; lambda *= 0.5) {
            double trial[LY_NVAR], rt[LY_NVAR];
            ly_profile pt;
            for (k = 0; k < LY_NVAR; ++k)
                trial[k] = z[k] + lambda * dz[k];
            if (!ly_shoot(sys->geometry, trial, 1, &pt))
                continue;
            system_residual(sys, row, trial, &pt, rt);
            if (norm2(n, rt) < (1.0 - 1e-4 * lambda) * merit) {
                for (k = 0; k < LY_NVAR; ++k)
                    z[k] = trial[k];
                for (k = 0; k < n; ++k)
                    r[k] = rt[k];
                *profile = pt;
                accepted = 1;
            }
        }
        if (!accepted) { /* no descent left: converged only at the round-off floor */
            *iterations = it;
            return norm_inf(n, r) <= RESIDUAL_FLOOR;
        }
    }
    *iterations = it;
    return norm_inf(n, r) <= RESIDUAL_TOLERANCE;
}

int ly_branch_tangent(const ly_profile *profile, const double scale[LY_NVAR],
                      const double reference[LY_NVAR], double tangent[LY_NVAR])
{
    /* Bordered system [J diag(scale); reference^T] t = e_last: t spans the null space of
     * the scaled 4 x 5 Jacobian of the fixed-volume residuals, with reference . t = 1. */
    double a[LY_NVAR][LY_NVAR], b[LY_NVAR], norm;
    int i, j, orientation;
    for (i = 0; i < LY_NRES; ++i) {
        double m = 0.0;
        for (j = 0; j < LY_NVAR; ++j) {
            a[i][j] = profile->jacobian[i][j] * scale[j];
            m = fmax(m, fabs(a[i][j]));
        }
        if (!(m > 0.0))
            return 0;
        for (j = 0; j < LY_NVAR; ++j)
            a[i][j] /= m; /* row equilibration */
        b[i] = 0.0;
    }
    for (j = 0; j < LY_NVAR; ++j)
        a[LY_NRES][j] = reference[j];
    b[LY_NRES] = 1.0;
    if (!(orientation = ly_solve_dense(LY_NVAR, a, b, tangent)))
        return 0;
    norm = norm2(LY_NVAR, tangent);
    for (j = 0; j < LY_NVAR; ++j)
        tangent[j] /= norm;
    return orientation;
}
