/* ly_profile.c — one shooting of the Laplace-Young profile (nondimensional, see
 * laplace_young_internal.h): RK4 in the normalised arc length t = s / S in [0, 1], with
 * the variational equations of the three shooting parameters (delta1, P, S), so that the
 * Jacobian is the exact derivative of the discrete RK4 map (RK methods commute with
 * linearisation). No event detection: the end point is wherever s = S. */
#include "laplace_young_internal.h"

#include <math.h>

#define STATE 4                  /* x, y, phi, v (v = pi * integral of y^2 cos phi ds) */
#define PARAMS 3                 /* sensitivities to delta1, P, S */
#define AUGMENTED (STATE * (1 + PARAMS))
enum { SX = 0, SY, SPHI, SV };
enum { PDELTA1 = 0, PPRESSURE, PLENGTH };

/* Height of the cap of a sphere of radius r cut at filling angle delta: r (1 - cos delta),
 * written without cancellation. */
static double cap_height(double r, double delta)
{
    double half = sin(0.5 * delta);
    return 2.0 * r * half * half;
}

/* Volume of that cap, pi h^2 (3 r - h) / 3, and its derivative in delta. */
static double cap_volume(double r, double delta)
{
    double h = cap_height(r, delta);
    return CB_PI * h * h * (3.0 * r - h) / 3.0;
}

static double cap_volume_derivative(double r, double delta)
{
    double h = cap_height(r, delta);
    return CB_PI * h * (2.0 * r - h) * r * sin(delta);
}

double ly_contact_force(double radius, double delta, double theta, double pressure)
{
    double y = radius * sin(delta);
    return 2.0 * CB_PI * y * sin(delta + theta) - CB_PI * y * y * pressure;
}

double ly_plane_contact_force(double y, double theta, double pressure)
{
    return 2.0 * CB_PI * y * sin(theta) - CB_PI * y * y * pressure;
}

double ly_contact_radius2(const ly_geometry *g, const double z[LY_NVAR])
{
    return g->plane ? z[LY_DELTA2] : g->r2 * sin(z[LY_DELTA2]);
}

/* d w / dt for the profile (first STATE entries) and, when n == AUGMENTED, for its
 * sensitivities: d q / dt = S A q (+ S df/dP for P, + f for S), A = df/d(y, phi).
 * Returns 0 where the profile has reached the axis (y <= 0) or is not finite. */
static int profile_rhs(const double *w, int n, double pressure, double length, double *dw)
{
    double y = w[SY];
    double c, sn;
    int k;
    if (!(y > 0.0) || !isfinite(y) || !isfinite(w[SPHI]))
        return 0;
    c = cos(w[SPHI]);
    sn = sin(w[SPHI]);
    dw[SX] = length * c;
    dw[SY] = length * sn;
    dw[SPHI] = length * (c / y - pressure);
    dw[SV] = length * CB_PI * y * y * c;
    if (n == STATE)
        return 1;
    for (k = 0; k < PARAMS; ++k) {
        const double *q = w + STATE * (1 + k);
        double *dq = dw + STATE * (1 + k);
        double dy = q[SY], dphi = q[SPHI];
        dq[SX] = -length * sn * dphi;
        dq[SY] = length * c * dphi;
        dq[SPHI] = length * (-c / (y * y) * dy - sn / y * dphi);
        dq[SV] = length * CB_PI * y * (2.0 * c * dy - y * sn * dphi);
    }
    dw[STATE * (1 + PPRESSURE) + SPHI] -= length;
    for (k = 0; k < STATE; ++k)
        dw[STATE * (1 + PLENGTH) + k] += dw[k] / length;
    return 1;
}

/* One classical RK4 step of size h on the first n entries of w. */
static int rk4_step(double *w, int n, double h, double pressure, double length)
{
    double k1[AUGMENTED], k2[AUGMENTED], k3[AUGMENTED], k4[AUGMENTED], t[AUGMENTED];
    int i;
    if (!profile_rhs(w, n, pressure, length, k1))
        return 0;
    for (i = 0; i < n; ++i)
        t[i] = w[i] + 0.5 * h * k1[i];
    if (!profile_rhs(t, n, pressure, length, k2))
        return 0;
    for (i = 0; i < n; ++i)
        t[i] = w[i] + 0.5 * h * k2[i];
    if (!profile_rhs(t, n, pressure, length, k3))
        return 0;
    for (i = 0; i < n; ++i)
        t[i] = w[i] + h * k3[i];
    if (!profile_rhs(t, n, pressure, length, k4))
        return 0;
    for (i = 0; i < n; ++i)
        w[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    return isfinite(w[SX]) && isfinite(w[SY]) && isfinite(w[SPHI]) && isfinite(w[SV]);
}

/* The start of the profile: the contact line on sphere 1, point
 * (-r1 (1 - cos delta1), r1 sin delta1), leaving at phi1 = delta1 + theta1 - pi/2. */
static void initial_state(const ly_geometry *g, double delta1, double *w, int n)
{
    int i;
    for (i = 0; i < n; ++i)
        w[i] = 0.0;
    w[SX] = -cap_height(g->r1, delta1);
    w[SY] = g->r1 * sin(delta1);
    w[SPHI] = delta1 + g->theta1 - 0.5 * CB_PI;
    if (n == AUGMENTED) {
        double *q = w + STATE * (1 + PDELTA1);
        q[SX] = -g->r1 * sin(delta1);
        q[SY] = g->r1 * cos(delta1);
        q[SPHI] = 1.0;
    }
}

/* The neck radius from the first integral: at phi = 0, pi P y^2 - 2 pi y + F = 0, whose
 * smaller root (the one with y < 1/P, i.e. y'' > 0) is y = F / (pi (1 + sqrt(1 - P F/pi))).
 * Falls back on the node value when that root is not consistent with the nodes. */
static double neck_radius(double force, double pressure, double y_node)
{
    double d = 1.0 - pressure * force / CB_PI;
    double y;
    if (!(d >= 0.0) || !(force > 0.0))
        return y_node;
    y = force / (CB_PI * (1.0 + sqrt(d)));
    return (y <= y_node * (1.0 + 1e-6) && y >= 0.5 * y_node) ? y : y_node;
}

/* The end of the profile on surface 2 for the unknown d2 (z[LY_DELTA2]): the contact line's
 * x - gap, y, the angle phi the profile must arrive at, the cap of surface 2 inside the
 * profile's volume, and their derivatives in d2. On sphere 2 (centre x = gap + r2) the
 * point (gap + r2 (1 - cos d2), r2 sin d2) at phi = pi/2 - d2 - theta2; on the plane
 * x = gap the point (gap, d2) at phi = pi/2 - theta2, no cap. */
typedef struct end_target {
    double x, y, phi, cap;
    double dx, dy, dphi, dcap;
} end_target;

static end_target surface2_target(const ly_geometry *g, double d2)
{
    end_target t;
    if (g->plane) {
        t.x = 0.0;
        t.y = d2;
        t.phi = 0.5 * CB_PI - g->theta2;
        t.cap = 0.0;
        t.dx = 0.0;
        t.dy = 1.0;
        t.dphi = 0.0;
        t.dcap = 0.0;
        return t;
    }
    t.x = cap_height(g->r2, d2);
    t.y = g->r2 * sin(d2);
    t.phi = 0.5 * CB_PI - d2 - g->theta2;
    t.cap = cap_volume(g->r2, d2);
    t.dx = g->r2 * sin(d2);
    t.dy = g->r2 * cos(d2);
    t.dphi = -1.0;
    t.dcap = cap_volume_derivative(g->r2, d2);
    return t;
}

/* Residuals of z and, if asked for, their Jacobian in z (see the header). */
static void fill_residuals(const ly_geometry *g, const double z[LY_NVAR], const double *w,
                           int with_jacobian, ly_profile *p)
{
    end_target end = surface2_target(g, z[LY_DELTA2]);
    int i;
    p->volume = w[SV] - cap_volume(g->r1, z[LY_DELTA1]) - end.cap;
    p->residual[LY_RES_X] = w[SX] - (z[LY_GAP] + end.x);
    p->residual[LY_RES_Y] = w[SY] - end.y;
    p->residual[LY_RES_PHI] = w[SPHI] - end.phi;
    p->residual[LY_RES_VOLUME] = p->volume - g->volume;
    if (!with_jacobian)
        return;
    for (i = 0; i < LY_NRES; ++i) {
        p->jacobian[i][LY_DELTA1] = w[STATE * (1 + PDELTA1) + i];
        p->jacobian[i][LY_PRESSURE] = w[STATE * (1 + PPRESSURE) + i];
        p->jacobian[i][LY_LENGTH] = w[STATE * (1 + PLENGTH) + i];
        p->jacobian[i][LY_DELTA2] = 0.0;
        p->jacobian[i][LY_GAP] = 0.0;
    }
    p->jacobian[LY_RES_VOLUME][LY_DELTA1] -= cap_volume_derivative(g->r1, z[LY_DELTA1]);
    p->jacobian[LY_RES_X][LY_DELTA2] = -end.dx;
    p->jacobian[LY_RES_Y][LY_DELTA2] = -end.dy;
    p->jacobian[LY_RES_PHI][LY_DELTA2] = -end.dphi;
    p->jacobian[LY_RES_VOLUME][LY_DELTA2] = -end.dcap;
    p->jacobian[LY_RES_X][LY_GAP] = -1.0;
}

int ly_shoot(const ly_geometry *g, const double z[LY_NVAR], int with_jacobian,
             ly_profile *profile)
{
    double w[AUGMENTED];
    int n = with_jacobian ? AUGMENTED : STATE;
    int steps = g->steps, k, k_min = 0;
    double h = 1.0 / steps, pressure = z[LY_PRESSURE], length = z[LY_LENGTH];
    double y_min, phi_min;
    if (!(length > 0.0) || !isfinite(pressure))
        return 0;
    initial_state(g, z[LY_DELTA1], w, n);
    y_min = w[SY];
    phi_min = w[SPHI];
    for (k = 1; k <= steps; ++k) {
        if (!rk4_step(w, n, h, pressure, length))
            return 0;
        if (w[SY] < y_min) {
            y_min = w[SY];
            phi_min = w[SPHI];
            k_min = k;
        }
    }
    if (!(y_min > 0.0))
        return 0;
    fill_residuals(g, z, w, with_jacobian, profile);
    /* The first integral at the smallest node, F = 2 pi y cos(phi) - pi y^2 P. */
    profile->neck_force = 2.0 * CB_PI * y_min * cos(phi_min) - CB_PI * y_min * y_min * pressure;
    profile->neck_radius = (k_min > 0 && k_min < steps)
                               ? neck_radius(profile->neck_force, pressure, y_min)
                               : y_min;
    return 1;
}

/* sin(x) / x, exact at 0. */
static double sinc(double x) { return fabs(x) < 1e-8 ? 1.0 - x * x / 6.0 : sin(x) / x; }

void ly_toroidal_guess(const ly_geometry *g, double delta1, double z[LY_NVAR])
{
    /* Contact points and tangent angles at gap 0, with the contact line on surface 2 of
     * the radius y1 of sphere 1's (r1 sin delta1 = r2 sin delta2; on a plane, y2 = y1). */
    double y1 = g->r1 * sin(delta1);
    double delta2 = g->plane ? y1 : asin(fmin(y1 / g->r2, 0.99));
    end_target end = surface2_target(g, delta2);
    double y2 = end.y;
    double x1 = -cap_height(g->r1, delta1), x2 = end.x;
    double phi1 = delta1 + g->theta1 - 0.5 * CB_PI, phi2 = end.phi;
    double turning = phi2 - phi1;
    double chord = hypot(x2 - x1, y2 - y1);
    /* A circle arc of turning angle dphi over the chord L: S = L / sinc(dphi/2); its
     * middle lies S sin(dphi/4) sinc(dphi/4) / 2 below the chord middle. */
    double length = chord / sinc(0.5 * turning);
    double q = 0.25 * turning;
    double y_mid = fmax(0.5 * (y1 + y2) - 0.5 * length * sin(q) * sinc(q), 0.1 * fmin(y1, y2));
    z[LY_DELTA1] = delta1;
    z[LY_DELTA2] = delta2;
    z[LY_LENGTH] = length;
    /* phi' = cos(phi)/y - P with phi' = dphi/S and cos(phi) = 1 at the middle. */
    z[LY_PRESSURE] = 1.0 / y_mid - turning / length;
    z[LY_GAP] = 0.0;
}
