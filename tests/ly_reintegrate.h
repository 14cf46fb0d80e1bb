/* ly_reintegrate.h — an independent re-integration of an exact bridge's profile, for the
 * tests of cb_exact_* (test_laplace_young.c, test_laplace_young_plane.c). Written afresh,
 * sharing nothing with ly_profile.c: from the reported filling angle on sphere 1 and the
 * reported pressure, step the meridian in arc length,
 *     x' = cos phi,  y' = sin phi,  phi' = cos(phi) / y - P,  V' = pi y^2 cos phi,
 * (fine fixed RK4 steps) to the closest approach to the reported contact line on surface 2
 * (sphere 2, or the plane x = gap), refined by Newton on (p - p2) . t = 0 with a partial
 * step; the profile must land there at the contact angle and enclose the volume. */
#ifndef CAPBRIDGE_LY_REINTEGRATE_H
#define CAPBRIDGE_LY_REINTEGRATE_H

#include "capbridge.h"

#include <math.h>

#define LYR_PI 3.14159265358979323846

typedef struct profile_point {
    double x, y, phi, volume;
} profile_point;

static inline profile_point profile_slope(profile_point a, double pressure)
{
    profile_point d;
    d.x = cos(a.phi);
    d.y = sin(a.phi);
    d.phi = cos(a.phi) / a.y - pressure;
    d.volume = LYR_PI * a.y * a.y * cos(a.phi);
    return d;
}

static inline profile_point profile_axpy(profile_point a, profile_point d, double h)
{
    profile_point r;
    r.x = a.x + h * d.x;
    r.y = a.y + h * d.y;
    r.phi = a.phi + h * d.phi;
    r.volume = a.volume + h * d.volume;
    return r;
}

static inline profile_point profile_step(profile_point a, double pressure, double h)
{
    profile_point k1 = profile_slope(a, pressure);
    profile_point k2 = profile_slope(profile_axpy(a, k1, 0.5 * h), pressure);
    profile_point k3 = profile_slope(profile_axpy(a, k2, 0.5 * h), pressure);
    profile_point k4 = profile_slope(profile_axpy(a, k3, h), pressure);
    profile_point r;
    r.x = a.x + h / 6.0 * (k1.x + 2.0 * k2.x + 2.0 * k3.x + k4.x);
    r.y = a.y + h / 6.0 * (k1.y + 2.0 * k2.y + 2.0 * k3.y + k4.y);
    r.phi = a.phi + h / 6.0 * (k1.phi + 2.0 * k2.phi + 2.0 * k3.phi + k4.phi);
    r.volume = a.volume + h / 6.0 * (k1.volume + 2.0 * k2.volume + 2.0 * k3.volume + k4.volume);
    return r;
}

static inline double sphere_cap_volume(double r, double delta)
{
    double h = r * (1.0 - cos(delta));
    return LYR_PI * h * h * (3.0 * r - h) / 3.0;
}

typedef struct reintegration {
    double position_error;  /* |end - contact point 2| / chord */
    double angle_error;     /* |phi(end) - phi demanded on surface 2| */
    double volume_error;    /* relative */
    double inside_surface2; /* deepest point inside surface 2 before the end / chord (<= 0: none) */
    double max_y;           /* largest radius of the profile */
} reintegration;

/* Depth of point a inside surface 2 (> 0 inside): sphere 2 centred at x = gap + r2, or the
 * half-space x > gap behind the plane. */
static inline double depth_in_surface2(const cb_exact_problem *p, double gap, profile_point a)
{
    if (p->r2 == INFINITY)
        return a.x - gap;
    return p->r2 - hypot(a.x - (gap + p->r2), a.y);
}

static inline reintegration reintegrate(const cb_exact_problem *p, double gap,
                                        const cb_exact_bridge *b)
{
    reintegration out = {0.0, 0.0, 0.0, 0.0, 0.0};
    int plane = p->r2 == INFINITY;
    double pressure = b->pressure / p->surface_tension, d1 = b->filling_angle1;
    double d2 = b->filling_angle2, r1 = p->r1, r2 = p->r2;
    double th1 = p->contact_angle1, th2 = p->contact_angle2;
    /* on sphere 2: (gap + r2 (1 - cos d2), r2 sin d2) at pi/2 - d2 - theta2;
     * on the plane: (gap, its contact line's radius) at pi/2 - theta2 */
    double x2 = plane ? gap : gap + r2 * (1.0 - cos(d2));
    double y2 = plane ? b->contact_radius2 : r2 * sin(d2);
    double phi2 = plane ? 0.5 * LYR_PI - th2 : 0.5 * LYR_PI - d2 - th2;
    double cap2 = plane ? 0.0 : sphere_cap_volume(r2, d2);
    profile_point start = {-r1 * (1.0 - cos(d1)), r1 * sin(d1), d1 + th1 - 0.5 * LYR_PI, 0.0};
    profile_point a = start, nearest = start, end;
    double chord = hypot(x2 - start.x, y2 - start.y);
    double h = fmin(chord, fmin(start.y, y2)) / 4000.0, best = 1e300, s = 0.0;
    long i, i_best = 0;
    for (i = 0; i < 2000000; ++i) {
        double distance;
        a = profile_step(a, pressure, h);
        distance = hypot(a.x - x2, a.y - y2);
        if (distance < best) {
            best = distance;
            nearest = a;
            i_best = i;
        } else if (best < 1e-2 * chord && i > i_best + 100) {
            break;
        }
    }
    for (i = 0; i < 20; ++i) { /* Newton on the partial step s from the nearest node */
        profile_point q = profile_step(nearest, pressure, s);
        s -= (q.x - x2) * cos(q.phi) + (q.y - y2) * sin(q.phi);
    }
    end = profile_step(nearest, pressure, s);
    out.position_error = hypot(end.x - x2, end.y - y2) / chord;
    out.angle_error = fabs(end.phi - phi2);
    out.volume_error = (end.volume - sphere_cap_volume(r1, d1) - cap2) / p->volume - 1.0;
    /* Before the end (excluding the last 20 steps, where the profile meets the surface),
     * does the profile ever enter surface 2? */
    out.max_y = start.y;
    for (a = start, i = 0; i < i_best - 20; ++i) {
        out.inside_surface2 = fmax(out.inside_surface2, depth_in_surface2(p, gap, a) / chord);
        out.max_y = fmax(out.max_y, a.y);
        a = profile_step(a, pressure, h);
    }
    return out;
}

#endif
