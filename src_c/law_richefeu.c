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


double cb_richefeu_inverse_length(const cb_law *law, const cb_pair *pair)
{
    /* eq. 11 with 1/R1 + 1/R2 = 2/R_h and r = R_large/R_small: lambda = c sqrt(V/(R_h r));
     * three divisions instead of six (this law is the default of the engines' pair loops).
     * lambda >= sqrt(smallest subnormal) ~ 2e-162, so 1/lambda is finite. */
    double lambda = law->richefeu_c *
                    sqrt(pair->volume / pair->r_harmonic * (pair->r_small / pair->r_large));
    return 1.0 / lambda;
}

cb_status cb_richefeu_force(const cb_law *law, const cb_pair *pair, double gap, double *force,
                            double *stiffness)
{
    double kappa = 2.0 * CB_PI * law->surface_tension * law->cos_theta;
    double inverse_lambda = cb_richefeu_inverse_length(law, pair);
    double f = kappa * pair->r_geometric * exp(-gap * inverse_lambda);
    *force = f;
    *stiffness = -f * inverse_lambda;
    return CB_OK;
}

/* The paper fits theta = 0 only ("perfectly wettable", §2.2) and states no volume range. */
cb_validity cb_richefeu_validity(void)
{
    cb_validity v = {0.0, HUGE_VAL, 0.0, HUGE_VAL, CB_RADIUS_GEOMETRIC,
                     "Richefeu 2007 §2.2: fitted for theta = 0"};
    return v;
}
