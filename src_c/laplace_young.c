/* laplace_young.c — the exact Laplace-Young bridge between two spheres or a sphere and a plane (public API):
 * input checks, nondimensionalisation by R_h (gamma = 1), and the bridge as reported.
 * The method is in ly_profile.c (shooting), ly_newton.c and ly_branch.c (continuation). */
#include "capbridge.h"
#include "laplace_young_internal.h"

#include <float.h>
#include <math.h>

/* A requested gap this close above the fold (relative) is taken as the fold itself: the
 * fold is known to the discretisation error only, and a round trip through SI units
 * (distance = R_h * fold) may move it by an ulp. */
#define FOLD_SLACK 1e-12

static int is_plane(const cb_exact_problem *p) { return p->r2 == INFINITY; }

/* The unit of length, R_h = 2 r1 r2 / (r1 + r2); on a plane its limit 2 r1. */
static double unit_length(const cb_exact_problem *p)
{
    return is_plane(p) ? 2.0 * p->r1 : cb_radius_harmonic(p->r1, p->r2);
}

static int angle_in_range(double theta) { return theta >= 0.0 && theta < 0.5 * CB_PI; }

static cb_status check_problem(const cb_exact_problem *p)
{
    if (!isfinite(p->r1) || !(isfinite(p->r2) || is_plane(p))
        || !isfinite(p->contact_angle1) || !isfinite(p->contact_angle2)
        || !isfinite(p->surface_tension) || !isfinite(p->volume))
        return CB_ERR_NOT_FINITE;
    if (p->r1 <= 0.0 || p->r2 <= 0.0 || p->surface_tension <= 0.0 || p->volume <= 0.0)
        return CB_ERR_NEGATIVE;
    if (!angle_in_range(p->contact_angle1) || !angle_in_range(p->contact_angle2))
        return CB_ERR_RANGE;
    if (p->steps < 0 || (p->steps > 0 && p->steps < CB_EXACT_MIN_STEPS) || p->steps > CB_EXACT_MAX_STEPS)
        return CB_ERR_RANGE;
    /* the problem is solved in units of R_h: V / R_h^3 must be a number */
    double rh = unit_length(p);
    double scaled_volume = p->volume / (rh * rh * rh);
    if (!(rh > 0.0 && scaled_volume > 0.0 && scaled_volume <= DBL_MAX))
        return CB_ERR_RANGE;
    return CB_OK;
}

static cb_status check_gap(double gap)
{
    if (!isfinite(gap))
        return CB_ERR_NOT_FINITE;
    return gap < 0.0 ? CB_ERR_RANGE : CB_OK;
}

/* The nondimensional problem; *unit receives the length unit R_h. */
static ly_geometry make_geometry(const cb_exact_problem *p, double *unit)
{
    ly_geometry g;
    double rh = unit_length(p);
    g.r1 = p->r1 / rh;
    g.r2 = p->r2 / rh; /* INFINITY for the plane */
    g.plane = is_plane(p);
    g.theta1 = p->contact_angle1;
    g.theta2 = p->contact_angle2;
    g.volume = p->volume / (rh * rh * rh);
    g.steps = p->steps > 0 ? p->steps : CB_EXACT_DEFAULT_STEPS;
    *unit = rh;
    return g;
}

static int bridge_finite(const cb_exact_bridge *b)
{
    return isfinite(b->force) && isfinite(b->force_contact1) && isfinite(b->force_contact2) &&
           isfinite(b->pressure) && isfinite(b->neck_radius) && isfinite(b->volume) &&
           isfinite(b->contact_radius1) && isfinite(b->contact_radius2);
}

/* The reported bridge of branch point z, in SI units: forces scale with gamma R_h,
 * the pressure with gamma / R_h.  A bridge that leaves double range in SI units (gamma
 * 1e283 over R_h 1e-11: a pressure of 1e294 / 1e-11) is CB_ERR_RANGE, *bridge untouched. */
static cb_status make_bridge(const ly_geometry *g, const double z[LY_NVAR], double unit,
                             double gamma, double gap, cb_exact_bridge *bridge)
{
    ly_profile p;
    cb_exact_bridge out;
    double pressure = z[LY_PRESSURE];
    if (!ly_shoot(g, z, 0, &p))
        return CB_ERR_NO_CONVERGENCE;
    out.gap = gap;
    out.force = gamma * unit * p.neck_force;
    out.force_contact1 = gamma * unit * ly_contact_force(g->r1, z[LY_DELTA1], g->theta1, pressure);
    out.force_contact2 = gamma * unit *
                         (g->plane ? ly_plane_contact_force(z[LY_DELTA2], g->theta2, pressure)
                                   : ly_contact_force(g->r2, z[LY_DELTA2], g->theta2, pressure));
    out.filling_angle1 = z[LY_DELTA1];
    out.filling_angle2 = g->plane ? 0.0 : z[LY_DELTA2];
    out.contact_radius1 = unit * g->r1 * sin(z[LY_DELTA1]);
    out.contact_radius2 = unit * ly_contact_radius2(g, z);
    out.pressure = gamma * pressure / unit;
    out.neck_radius = unit * p.neck_radius;
    out.volume = unit * unit * unit * p.volume;
    if (!bridge_finite(&out))
        return CB_ERR_RANGE;
    *bridge = out;
    return CB_OK;
}

/* Trace the branch to gap_stop (nondimensional) and check that it reaches it. */
static cb_status trace_to(const ly_geometry *g, double gap_stop, ly_branch *branch)
{
    const double *last;
    if (!ly_trace(g, gap_stop, branch))
        return CB_ERR_NO_CONVERGENCE;
    last = branch->z[branch->count - 1];
    if (branch->has_fold && gap_stop > last[LY_GAP] * (1.0 + FOLD_SLACK))
        return CB_ERR_NO_BRIDGE;
    return CB_OK;
}

/* The bridge at one SI gap on a traced branch. */
static cb_status bridge_at_gap(const ly_geometry *g, const ly_branch *branch, double unit,
                               double gamma, double gap, cb_exact_bridge *bridge)
{
    double z[LY_NVAR];
    const double *last = branch->z[branch->count - 1];
    double scaled = gap / unit;
    if (branch->has_fold && fabs(scaled - last[LY_GAP]) <= FOLD_SLACK * last[LY_GAP])
        return make_bridge(g, last, unit, gamma, gap, bridge); /* the fold itself */
    if (!ly_point_at_gap(g, branch, scaled, z))
        return CB_ERR_NO_CONVERGENCE;
    return make_bridge(g, z, unit, gamma, gap, bridge);
}

cb_status cb_exact_solve(const cb_exact_problem *problem, double gap, cb_exact_bridge *bridge)
{
    ly_branch branch;
    ly_geometry g;
    double unit;
    cb_status s;
    if (!problem || !bridge)
        return CB_ERR_NULL;
    if ((s = check_problem(problem)) != CB_OK || (s = check_gap(gap)) != CB_OK)
        return s;
    g = make_geometry(problem, &unit);
    if ((s = trace_to(&g, gap / unit, &branch)) != CB_OK)
        return s;
    return bridge_at_gap(&g, &branch, unit, problem->surface_tension, gap, bridge);
}

/* at_rupture may be NULL when only the distance is wanted. */
cb_status cb_exact_rupture(const cb_exact_problem *problem, double *distance,
                           cb_exact_bridge *at_rupture)
{
    ly_branch branch;
    ly_geometry g;
    double unit, fold;
    cb_exact_bridge bridge;
    cb_status s;
    if (!problem || !distance)
        return CB_ERR_NULL;
    if ((s = check_problem(problem)) != CB_OK)
        return s;
    g = make_geometry(problem, &unit);
    if (!ly_trace(&g, INFINITY, &branch) || !branch.has_fold)
        return CB_ERR_NO_CONVERGENCE;
    fold = branch.z[branch.count - 1][LY_GAP];
    s = make_bridge(&g, branch.z[branch.count - 1], unit, problem->surface_tension,
                    unit * fold, &bridge);
    if (s != CB_OK)
        return s;
    *distance = unit * fold;
    if (at_rupture)
        *at_rupture = bridge;
    return CB_OK;
}

/* The gaps must be finite, >= 0 and ascending; nothing is written unless all are solved
 * (but on CB_ERR_NO_CONVERGENCE the bridges before the failing gap may have been). */
cb_status cb_exact_curve(const cb_exact_problem *problem, size_t n, const double *gaps,
                         cb_exact_bridge *bridges)
{
    ly_branch branch;
    ly_geometry g;
    double unit;
    size_t i;
    cb_status s;
    if (!problem || (n > 0 && (!gaps || !bridges)))
        return CB_ERR_NULL;
    if ((s = check_problem(problem)) != CB_OK)
        return s;
    for (i = 0; i < n; ++i) {
        if ((s = check_gap(gaps[i])) != CB_OK)
            return s;
        if (i > 0 && gaps[i] < gaps[i - 1])
            return CB_ERR_RANGE;
    }
    if (n == 0)
        return CB_OK;
    g = make_geometry(problem, &unit);
    if ((s = trace_to(&g, gaps[n - 1] / unit, &branch)) != CB_OK)
        return s;
    for (i = 0; i < n; ++i)
        if ((s = bridge_at_gap(&g, &branch, unit, problem->surface_tension, gaps[i],
                               &bridges[i])) != CB_OK)
            return s;
    return CB_OK;
}
