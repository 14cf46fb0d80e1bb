/* law_soulie.c — Soulie, Cherblanc, El Youssoufi & Saix 2006, as public DEM codes implement it.
 *
 *   F = pi gamma sqrt(R1 R2) [C + exp(A gap / R2 + B)]
 *   A = -1.1 V*^(-0.53)
 *   B = (-0.148 ln V* - 0.96) theta^2 - 0.0082 ln V* + 0.48
 *   C = 0.0018 ln V* + 0.078
 * with R2 the LARGER radius, V* = V / R2^3, theta in radians. dF/dgap = pi gamma
 * sqrt(R1 R2) exp(A gap / R2 + B) A / R2 (< 0, since A < 0).
 *
 * Extension: C < 0 when V* < exp(-0.078 / 0.0018) ~ 1.5e-19; the bracket then crosses
 * zero at a finite gap and the published formula would turn repulsive before rupture.
 * F = max(published F, 0): the published law wherever it is attractive, and no force
 * (dF/dgap = 0) from the gap where it reaches zero to the rupture distance. This keeps F
 * continuous, >= 0 and non-increasing, and changes nothing where C >= 0.
 *
 * (Noted, not changed: B grows as -0.148 ln V* theta^2, so for small V* and large theta
 * F(0) far exceeds 2 pi gamma R cos(theta) — e.g. 2.8 x at V* = 1e-12, theta = 30 deg, for
 * equal spheres.
 * That is the fit as published; the exact-solver comparison reports it.) */
#include "laws.h"

#include <math.h>


static cb_status soulie_force(const cb_law *law, const cb_pair *pair, double gap,
                              double *force, double *stiffness)
{
    double r_large = pair->r_large;
    double lv = log(pair->volume / (r_large * r_large * r_large));
    double theta2 = law->contact_angle * law->contact_angle;
    /* V*^(-0.53) = exp(-0.53 ln V*) */
    double a = -1.1 * exp(-0.53 * lv);
    double b = (-0.148 * lv - 0.96) * theta2 - 0.0082 * lv + 0.48;
    double c = 0.0018 * lv + 0.078;
    double prefactor = CB_PI * law->surface_tension * pair->r_geometric;
    /* (gap > 0 test: A may be -inf for V* below ~1e-580, and -inf * 0 is NaN) */
    double decay = exp((gap > 0.0 ? a * gap / r_large : 0.0) + b);
    double f = prefactor * (c + decay);
    if (f > 0.0) {
        *force = f;
        *stiffness = decay > 0.0 ? prefactor * decay * a / r_large : 0.0;
    } else {
        *force = 0.0;
        *stiffness = 0.0;
    }
    return CB_OK;
}

/* No range is stated for the fit in the sources available here (the formula above is
 * the one other public DEM codes implement; Gladkyy 2014 does not evaluate it). */
static cb_validity soulie_validity(const cb_law *law)
{
    (void)law;
    cb_validity v = {0.0, HUGE_VAL, HUGE_VAL, HUGE_VAL, CB_RADIUS_LARGE,
                     "Soulie et al. 2006 (as in public DEM codes): no range stated"};
    return v;
}

/* Soulie 2006 takes Lian's rupture rule. */
const cb_law_ops cb_soulie_ops = {
    .name = "soulie",
    .force = soulie_force,
    .validity = soulie_validity,
    .default_rupture = CB_RUPTURE_LIAN,
    .bridge_constant = cb_no_bridge_constant,
    .bridge_force = cb_bridge_force_in_full,
};
