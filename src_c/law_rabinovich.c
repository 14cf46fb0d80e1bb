/* law_rabinovich.c — Rabinovich, Esayanur & Moudgil 2005, as written in Gladkyy &
 * Schwarze 2014 eqs. 9-12, with and without the correction of Lambert et al. 2008.
 *
 *   d_sp  = (a/2) (-1 + sqrt(1 + 2V / (pi R a^2)))               immersion height (eq. 10)
 *   alpha = sqrt((a/R) (-1 + sqrt(1 + 2V / (pi R a^2)))) = sqrt(2 d_sp / R)        (eq. 9)
 *   corrected (Lambert, eq. 12):  F = 2 pi R gamma cos(theta) / (1 + a / (2 d_sp))
 *   as published (eq. 11):        F = the above + 2 pi gamma R sin(alpha) sin(theta + alpha)
 * Eq. 11 writes attraction as negative; here both terms are attractive magnitudes.
 *
 * Radius: R = R_h = 2 R1 R2 / (R1 + R2) (Gladkyy eq. 1). One public DEM code uses
 * R_r = R_h / 2 instead. At contact eq. 12 gives F(0) = 2 pi R gamma cos(theta) for every volume,
 * and the exact V -> 0 limit at contact is the Derjaguin value 2 pi gamma R_h cos(theta)
 * (Willett 2000; the exact solver gives F(0) / (2 pi gamma R_h cos theta) = 0.960, 0.988,
 * 0.996 at V/R_h^3 = 1e-4, 1e-6, 1e-8 for r2 = 3 r1, theta = 20 deg, where R_g would be
 * 15% high): so R = R_h, and R_r would halve every force.
 *
 * Cancellation- and overflow-free form. With k = sqrt(pi R / (2V)) and s = k a
 * (s^2 = pi R a^2 / (2V), the inverse of the term that overflows as a -> 0):
 *   a / (2 d_sp) = s^2 + s sqrt(1 + s^2)              (-> 0 as a -> 0)
 *   d_sp         = 1 / (2 k (s + sqrt(1 + s^2)))      (-> sqrt(V / (2 pi R)) at contact)
 * so F = F0 / (1 + s (s + sqrt(1 + s^2))), F0 = 2 pi R gamma cos(theta), and
 *   dF/da = -F0 k (2 s + (1 + 2 s^2) / sqrt(1 + s^2)) / D^2  ->  -F0 k at a = 0
 * (a finite one-sided stiffness: the corrected law has a kink-free but steep start).
 *
 * Extension of the alpha-term (uncorrected law only): sin(alpha) sin(theta + alpha) rises
 * with alpha up to alpha_max = (pi - theta) / 2, where it equals cos^2(theta / 2), and then
 * falls and turns negative for alpha > pi - theta — an "embracing angle" beyond 90 deg
 * that has no geometric meaning. alpha is therefore held at alpha_max (the term's
 * largest value, reached with zero slope, so F stays C1 and non-increasing in the gap).
 * This engages only for V / R^3 > ~0.6 (alpha(0)^2 = 2 d_sp(0) / R). */
#include "laws.h"

#include <math.h>


/* The corrected law; also returns d_sp and its gap derivative for the alpha-term. */
static void rabinovich_corrected(const cb_law *law, const cb_pair *pair, double gap,
                                 double *force, double *stiffness, double *immersion,
                                 double *immersion_slope)
{
    double r = pair->r_harmonic;
    /* two roots, not the root of a ratio: pi R / (2V) overflows for a subnormal V */
    double k = sqrt(0.5 * CB_PI * r) / sqrt(pair->volume);
    double s = k * gap;
    double root = sqrt(1.0 + s * s);
    double denominator = 1.0 + s * (s + root);
    double f0 = 2.0 * CB_PI * r * law->surface_tension * law->cos_theta;
    *force = f0 / denominator;
    *stiffness = -f0 * k * (2.0 * s + (1.0 + 2.0 * s * s) / root) /
                 (denominator * denominator);
    double sum = s + root;
    *immersion = 1.0 / (2.0 * k * sum);
    /* d(d_sp)/da = -(1 + s / root) / (2 sum^2) */
    *immersion_slope = -(1.0 + s / root) / (2.0 * sum * sum);
}

static cb_status rabinovich_force(const cb_law *law, const cb_pair *pair, double gap,
                                  double *force, double *stiffness)
{
    double d_sp, d_sp_slope;
    rabinovich_corrected(law, pair, gap, force, stiffness, &d_sp, &d_sp_slope);
    return CB_OK;
}

static cb_status rabinovich_uncorrected_force(const cb_law *law, const cb_pair *pair, double gap,
                                              double *force, double *stiffness)
{
    double f, df, d_sp, d_sp_slope;
    rabinovich_corrected(law, pair, gap, &f, &df, &d_sp, &d_sp_slope);
    double r = pair->r_harmonic;
    double theta = law->contact_angle;
    double alpha = sqrt(2.0 * d_sp / r);
    double alpha_max = 0.5 * (CB_PI - theta);
    double alpha_slope = 0.0; /* dalpha/da = d(d_sp)/da / (alpha R) */
    if (alpha >= alpha_max) alpha = alpha_max;
    else if (alpha > 0.0) alpha_slope = d_sp_slope / (alpha * r);
    double scale = 2.0 * CB_PI * law->surface_tension * r;
    /* d/dalpha [sin(alpha) sin(theta + alpha)] = sin(theta + 2 alpha) */
    *force = f + scale * sin(alpha) * sin(theta + alpha);
    *stiffness = df + scale * sin(theta + 2.0 * alpha) * alpha_slope;
    return CB_OK;
}

/* No range is stated for the closed form in the sources available here (Gladkyy 2014
 * §2.4 gives none; the derivation is Derjaguin's, i.e. small filling angles). */
static cb_validity rabinovich_validity(const cb_law *law)
{
    (void)law;
    cb_validity v = {0.0, HUGE_VAL, HUGE_VAL, HUGE_VAL, CB_RADIUS_HARMONIC,
                     "Rabinovich et al. 2005 via Gladkyy & Schwarze 2014 §2.4: "
                     "no range stated"};
    return v;
}

/* Gladkyy eq. 2 applies Willett's rupture rule to every law it compares. */
const cb_law_ops cb_rabinovich_ops = {
    .name = "rabinovich",
    .force = rabinovich_force,
    .validity = rabinovich_validity,
    .default_rupture = CB_RUPTURE_WILLETT,
    .bridge_constant = cb_no_bridge_constant,
    .bridge_force = cb_bridge_force_in_full,
};

const cb_law_ops cb_rabinovich_uncorrected_ops = {
    .name = "rabinovich/uncorrected",
    .force = rabinovich_uncorrected_force,
    .validity = rabinovich_validity,
    .default_rupture = CB_RUPTURE_WILLETT,
    .bridge_constant = cb_no_bridge_constant,
    .bridge_force = cb_bridge_force_in_full,
};
