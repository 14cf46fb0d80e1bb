/* test_viscous.c — the viscous force of a liquid bridge (viscous.c, issue 19).
 *
 * The normal damping against an independent numerical solution of Reynolds' lubrication
 * equation for the film between two spheres (the film h(r) = s + r^2/(2R*), zero pressure at
 * the wetted radius r_m that holds the bridge's volume between the surfaces; the force
 * F = 6 pi eta v * integral of r^3/h^3 from 0 to r_m, by quadrature, and r_m from the volume
 * integral by bisection), the limits Reynolds (a large bridge) and (V/(2 pi R* s^2))^2 (a
 * small one), Pitois et al.'s equal-sphere form; the tangential damping against Goldman, Cox
 * & Brenner's formula; the minimum gap, and none in overlap; the keywords; bad input. */
#include "capbridge.h"
#include "check.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static cb_law viscous_law(double viscosity, double min_gap)
{
    cb_law law;
    cb_message msg;
    CHECK_STATUS(cb_law_init(&law, CB_MODEL_RICHEFEU, 0.0728, 0.0), CB_OK);
    char text[64];
    snprintf(text, sizeof text, "%.17g", viscosity);
    CHECK_STATUS(cb_law_configure(&law, "viscosity", text, &msg), CB_OK);
    snprintf(text, sizeof text, "%.17g", min_gap);
    CHECK_STATUS(cb_law_configure(&law, "min_gap", text, &msg), CB_OK);
    CHECK_STATUS(cb_law_prepare(&law, &msg), CB_OK);
    return law;
}

/* Simpson's rule of f over [a, b] with n (even) intervals in the variable u, r = a + (b-a)u^2
 * (points crowd towards r = a, where the film is thinnest) */
static double integrate(double (*f)(double r, const double *p), const double *p, double a,
                        double b, int n)
{
    double sum = 0.0;
    for (int k = 0; k <= n; ++k) {
        const double u = (double)k / n, r = a + (b - a) * u * u, jacobian = 2.0 * (b - a) * u;
        const double weight = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        sum += weight * f(r, p) * jacobian;
    }
    return sum / (3.0 * n);
}

/* p = {s, R*} */
static double film(double r, const double *p) { return p[0] + r * r / (2.0 * p[1]); }
static double volume_density(double r, const double *p) { return 2.0 * CB_PI * r * film(r, p); }
static double force_density(double r, const double *p)
{
    const double h = film(r, p);
    return r * r * r / (h * h * h);
}

/* Reynolds' equation, numerically: the normal damping coefficient F / v */
static double reynolds_damping(double eta, double reduced, double s, double volume)
{
    const double p[2] = {s, reduced};
    double lo = 0.0, hi = sqrt(2.0 * reduced * s) + sqrt(volume / (CB_PI * s)) + 1e-300;
    while (integrate(volume_density, p, 0.0, hi, 2000) < volume) hi *= 2.0;
    for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        if (integrate(volume_density, p, 0.0, mid, 2000) < volume) lo = mid;
        else hi = mid;
    }
    return 6.0 * CB_PI * eta * integrate(force_density, p, 0.0, 0.5 * (lo + hi), 20000);
}

static void normal_against_reynolds(void)
{
    const double eta = 1e-3, r1 = 0.5e-3, r2 = 0.8e-3, reduced = r1 * r2 / (r1 + r2);
    const cb_law law = viscous_law(eta, 1e-9);
    const double gaps[] = {1e-7, 1e-6, 1e-5, 5e-5};
    const double volumes[] = {1e-14, 1e-12, 1e-11, 1e-10};
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 4; ++k) {
            double cn = 0.0, ct = 0.0;
            CHECK_STATUS(cb_viscous_damping(&law, r1, r2, gaps[i], volumes[k], &cn, &ct), CB_OK);
            CHECK_REL(cn, reynolds_damping(eta, reduced, gaps[i], volumes[k]), 1e-6);
        }
}

static void limits(void)
{
    const double eta = 0.05, r = 1e-3, reduced = r / 2.0, s = 2e-6;
    const cb_law law = viscous_law(eta, 1e-9);
    double cn = 0.0, ct = 0.0;
    /* a bridge far larger than its film: Reynolds, 6 pi eta R*^2 / s */
    CHECK_STATUS(cb_viscous_damping(&law, r, r, s, 1e3 * CB_PI * reduced * s * s * 1e6, &cn, &ct),
                 CB_OK);
    CHECK_REL(cn, 6.0 * CB_PI * eta * reduced * reduced / s, 2e-3);
    /* a small bridge: the factor (V / (2 pi R* s^2))^2 */
    const double small = 1e-4 * CB_PI * reduced * s * s;
    CHECK_STATUS(cb_viscous_damping(&law, r, r, s, small, &cn, &ct), CB_OK);
    const double x = small / (2.0 * CB_PI * reduced * s * s);
    CHECK_REL(cn, 6.0 * CB_PI * eta * reduced * reduced / s * x * x, 2e-4);
    /* Pitois et al. 2000 for two equal spheres of radius R: 3/2 pi eta R^2 / s times
     * [1 - 1/sqrt(1 + 2V/(pi R s^2))]^2 */
    const double v = 3e-11;
    CHECK_STATUS(cb_viscous_damping(&law, r, r, s, v, &cn, &ct), CB_OK);
    const double factor = 1.0 - 1.0 / sqrt(1.0 + 2.0 * v / (CB_PI * r * s * s));
    CHECK_REL(cn, 1.5 * CB_PI * eta * r * r / s * factor * factor, 1e-13);
}

static void tangential(void)
{
    const double eta = 2e-3, r1 = 1e-3, r2 = 3e-3, reduced = r1 * r2 / (r1 + r2);
    const cb_law law = viscous_law(eta, 1e-8);
    double cn = 0.0, ct = 0.0, last = HUGE_VAL;
    for (double s = 1e-8; s < 1e-4; s *= 3.0) {
        CHECK_STATUS(cb_viscous_damping(&law, r1, r2, s, 1e-11, &cn, &ct), CB_OK);
        CHECK_REL(ct, 6.0 * CB_PI * eta * reduced * (8.0 / 15.0 * log(reduced / s) + 0.9588),
                  1e-13);
        CHECK(ct > 0.0 && ct < last); /* weaker as the film thickens */
        last = ct;
    }
    /* beyond s = R* exp(15/8 0.9588), ~6 R*, the formula would turn negative: 0 */
    CHECK_STATUS(cb_viscous_damping(&law, r1, r2, 10.0 * reduced, 1e-11, &cn, &ct), CB_OK);
    CHECK(ct == 0.0);
}

static void minimum_gap_and_off(void)
{
    const double r = 1e-3, v = 1e-11, min_gap = 1e-6;
    const cb_law law = viscous_law(1e-3, min_gap);
    double at_min[2], below[2], overlap[2];
    CHECK_STATUS(cb_viscous_damping(&law, r, r, min_gap, v, &at_min[0], &at_min[1]), CB_OK);
    CHECK_STATUS(cb_viscous_damping(&law, r, r, 1e-9, v, &below[0], &below[1]), CB_OK);
    CHECK_STATUS(cb_viscous_damping(&law, r, r, -2e-6, v, &overlap[0], &overlap[1]), CB_OK);
    for (int k = 0; k < 2; ++k) {
        CHECK(below[k] == at_min[k]);
        CHECK(isfinite(at_min[k]) && at_min[k] > 0.0);
        /* in overlap the contact law governs: no viscous force */
        CHECK(overlap[k] == 0.0);
    }
    double touching[2];
    CHECK_STATUS(cb_viscous_damping(&law, r, r, 0.0, v, &touching[0], &touching[1]), CB_OK);
    CHECK(touching[0] == 0.0 && touching[1] == 0.0);
    /* no viscosity (the default), or no liquid: no viscous force */
    cb_law dry;
    CHECK_STATUS(cb_law_init(&dry, CB_MODEL_WILLETT, 0.0728, 0.0), CB_OK);
    CHECK(dry.viscosity == 0.0);
    double cn = 1.0, ct = 1.0;
    CHECK_STATUS(cb_viscous_damping(&dry, r, r, 1e-6, v, &cn, &ct), CB_OK);
    CHECK(cn == 0.0 && ct == 0.0);
    cn = ct = 1.0;
    CHECK_STATUS(cb_viscous_damping(&law, r, r, 1e-6, 0.0, &cn, &ct), CB_OK);
    CHECK(cn == 0.0 && ct == 0.0);
}

static void keywords_and_bad_input(void)
{
    cb_law law;
    cb_message msg;
    CHECK_STATUS(cb_law_init(&law, CB_MODEL_RICHEFEU, 0.0728, 0.0), CB_OK);
    CHECK_STATUS(cb_law_configure(&law, "viscosity", "-1", &msg), CB_ERR_RANGE);
    CHECK_STATUS(cb_law_configure(&law, "viscosity", "nan", &msg), CB_ERR_RANGE);
    CHECK_STATUS(cb_law_configure(&law, "min_gap", "0", &msg), CB_ERR_RANGE);
    CHECK_STATUS(cb_law_configure(&law, "min_gap", "x", &msg), CB_ERR_RANGE);
    /* a viscosity without a minimum gap is refused where the law is prepared, by name */
    CHECK_STATUS(cb_law_configure(&law, "viscosity", "1e-3", &msg), CB_OK);
    CHECK_STATUS(cb_law_prepare(&law, &msg), CB_ERR_RANGE);
    CHECK(strstr(msg.text, "needs min_gap") != NULL);
    CHECK_STATUS(cb_law_configure(&law, "min_gap", "1e-7", &msg), CB_OK);
    CHECK_STATUS(cb_law_prepare(&law, &msg), CB_OK);
    /* twice on one line: refused */
    cb_keywords_given given = {0};
    CHECK_STATUS(cb_law_configure_once(&law, &given, "viscosity", "1e-3", &msg), CB_OK);
    CHECK_STATUS(cb_law_configure_once(&law, &given, "viscosity", "2e-3", &msg), CB_ERR_RANGE);
    /* laws differing in viscosity are not the same law */
    cb_law other = law;
    CHECK(cb_law_same(&law, &other));
    other.viscosity *= 2.0;
    CHECK(!cb_law_same(&law, &other));
    double cn = 0.0, ct = 0.0;
    CHECK_STATUS(cb_viscous_damping(&law, 1e-3, 1e-3, NAN, 1e-11, &cn, &ct), CB_ERR_NOT_FINITE);
    CHECK(cn == 0.0 && ct == 0.0);
    CHECK_STATUS(cb_viscous_damping(&law, 0.0, 1e-3, 1e-6, 1e-11, &cn, &ct), CB_ERR_NEGATIVE);
    CHECK_STATUS(cb_viscous_damping(&law, 1e-3, 1e-3, 1e-6, -1e-11, &cn, &ct), CB_ERR_NEGATIVE);
    CHECK_STATUS(cb_viscous_damping(NULL, 1e-3, 1e-3, 1e-6, 1e-11, &cn, &ct), CB_ERR_NULL);
    cb_law_release(&law);
}

/* the time-step bound: a tenth of pi m / c, c the largest coefficient at min_gap over the
 * radius corners and volumes; none without viscosity */
static void timestep_bound(void)
{
    const cb_law law = viscous_law(0.5, 1e-6);
    const cb_radius_range small = {0.4e-3, 0.5e-3}, large = {0.6e-3, 0.8e-3};
    const double volumes[2] = {1e-12, 1e-10}, mass = 2e-6;
    double limit = 0.0, damping = 0.0, largest = 0.0;
    CHECK_STATUS(cb_viscous_timestep_limit(&law, small, large, volumes, 2, mass, &limit, &damping),
                 CB_OK);
    const double r1[2] = {0.4e-3, 0.5e-3}, r2[2] = {0.6e-3, 0.8e-3};
    for (int v = 0; v < 2; ++v)
        for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 2; ++b) {
                double cn = 0.0, ct = 0.0;
                CHECK_STATUS(cb_viscous_damping(&law, r1[a], r2[b], 1e-6, volumes[v], &cn, &ct),
                             CB_OK);
                largest = fmax(largest, fmax(cn, ct));
            }
    CHECK_REL(damping, largest, 1e-15);
    CHECK_REL(limit, CB_TIMESTEP_FRACTION * CB_PI * mass / largest, 1e-15);
    /* the largest of the corners is the largest radii and volume (R* and V both raise c) */
    double cn = 0.0, ct = 0.0;
    CHECK_STATUS(cb_viscous_damping(&law, 0.5e-3, 0.8e-3, 1e-6, 1e-10, &cn, &ct), CB_OK);
    CHECK_REL(damping, fmax(cn, ct), 1e-15);
    cb_law dry;
    CHECK_STATUS(cb_law_init(&dry, CB_MODEL_RICHEFEU, 0.0728, 0.0), CB_OK);
    CHECK_STATUS(cb_viscous_timestep_limit(&dry, small, large, volumes, 2, mass, &limit, NULL),
                 CB_OK);
    CHECK(limit == HUGE_VAL);
    CHECK_STATUS(cb_viscous_timestep_limit(&law, small, large, volumes, 2, 0.0, &limit, NULL),
                 CB_ERR_NEGATIVE);
}

int main(int argc, char **argv)
{
    (void)argc;
    normal_against_reynolds();
    limits();
    tangential();
    minimum_gap_and_off();
    keywords_and_bad_input();
    timestep_bound();
    return check_report(argv[0]);
}
