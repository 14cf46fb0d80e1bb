/* law_richefeu.c — Richefeu, El Youssoufi, Peyroux & Radjai 2007, eqs. 4-11.
 *
 *   F = kappa R_g exp(-gap / lambda),  kappa = 2 pi gamma cos(theta)      (eqs. 4, 5, 7)
 *   lambda = (c / sqrt 2) V^(1/2) r^(-1/2) (1/R1 + 1/R2)^(1/2)           (eq. 11)
 *   r = max(R1/R2, R2/R1)                                                 (eq. 8)
 *
 * R_g = sqrt(R1 R2) is the paper's choice for the force at contact (it fits the
 * Laplace-Young data better than R_h at finite volume, §2.2); the exact V -> 0 limit is
 * 2 pi gamma cos(theta) R_h, which the report shows. Continuous at gap = 0. */
#include "laws.h"

#include <math.h>

enum { RICHEFEU_C = 0 }; /* law->parameters[RICHEFEU_C]: c of eq. 11 */

/* eq. 11's 1/lambda, the constant a bridge keeps (cb_bridge.law_constant) */
static double richefeu_inverse_length(const cb_law *law, const cb_pair *pair)
{
    /* eq. 11 with 1/R1 + 1/R2 = 2/R_h and r = R_large/R_small: lambda = c sqrt(V/(R_h r));
     * three divisions instead of six (this law is the default of the engines' pair loops).
     * lambda >= sqrt(smallest subnormal) ~ 2e-162, so 1/lambda is finite. */
    double lambda = law->parameters[RICHEFEU_C] *
                    sqrt(pair->volume / pair->r_harmonic * (pair->r_small / pair->r_large));
    return 1.0 / lambda;
}

static cb_status richefeu_force(const cb_law *law, const cb_pair *pair, double gap,
                                double *force, double *stiffness)
{
    double kappa = 2.0 * CB_PI * law->surface_tension * law->cos_theta;
    double inverse_lambda = richefeu_inverse_length(law, pair);
    double f = kappa * pair->r_geometric * exp(-gap * inverse_lambda);
    *force = f;
    *stiffness = -f * inverse_lambda;
    return CB_OK;
}

/* The paper fits theta = 0 only ("perfectly wettable", §2.2) and states no volume range. */
static cb_validity richefeu_validity(const cb_law *law)
{
    (void)law;
    cb_validity v = {0.0, HUGE_VAL, 0.0, HUGE_VAL, CB_RADIUS_GEOMETRIC,
                     "Richefeu 2007 §2.2: fitted for theta = 0"};
    return v;
}

/* A stretched bridge (eq. 10): its force at contact kappa R_g times exp(-gap/lambda) with
 * its stored 1/lambda, the product richefeu_force forms, so bit for bit its value (and
 * cb_bridge_held's, capbridge.h).  A bridge stored without it (0: derived under another
 * law) evaluates the law in full. */
static cb_status richefeu_bridge_force(const cb_law *law, const cb_pair *pair,
                                       const cb_bridge *bridge, double gap, double *force)
{
    if (!(bridge->law_constant > 0.0))
        return cb_bridge_force_in_full(law, pair, bridge, gap, force);
    *force = bridge->force_contact * exp(-gap * bridge->law_constant);
    return CB_OK;
}

static const cb_law_keyword richefeu_keywords[] = {
    {"c", "Richefeu's constant", "0.9"}, /* Richefeu 2007 after eq. 9: c ~ 0.9 */
};

static cb_status richefeu_set_keyword(cb_law *law, int index, const char *value,
                                      cb_message *msg)
{
    double number = 0.0;
    if (!cb_parse_number(value, &number) || number <= 0.0)
        return cb_fail(msg, CB_ERR_RANGE, "c '%s': must be a number > 0 (default %s)", value,
                       richefeu_keywords[index].default_text);
    law->parameters[index] = number;
    return CB_OK;
}

const cb_law_ops cb_richefeu_ops = {
    .name = "richefeu",
    .force = richefeu_force,
    .validity = richefeu_validity,
    .default_rupture = CB_RUPTURE_LIAN, /* eq. 6 */
    .keywords = richefeu_keywords,
    .keyword_count = 1,
    .set_keyword = richefeu_set_keyword,
    .bridge_constant = richefeu_inverse_length,
    .bridge_force = richefeu_bridge_force,
};
