/* rupture.c — rupture (debonding) distances and their inverses.
 * theta enters both rules in radians (law->rupture_factor = 1 + theta/2). */
#include "laws.h"

#include <math.h>

/* Lian et al. 1998, Richefeu 2007 eq. 6: d = (1 + theta/2) V^(1/3). */
double cb_rupture_lian(const cb_law *law, const cb_pair *pair)
{
    return law->rupture_factor * cbrt(pair->volume);
}

double cb_rupture_volume_lian(const cb_law *law, const cb_pair *pair, double gap)
{
    (void)pair;
    double root = gap / law->rupture_factor;
    return root * root * root;
}

/* Willett et al. 2000, Gladkyy eq. 2 with R = R_h (Gladkyy eq. 1):
 * d / R_h = (1 + theta/2) (V*^(1/3) + V*^(2/3) / 10), V* = V / R_h^3. */
double cb_rupture_willett(const cb_law *law, const cb_pair *pair)
{
    double r = pair->r_harmonic;
    double t = cbrt(pair->volume / (r * r * r));
    return r * law->rupture_factor * (t + 0.1 * t * t);
}

/* The inverse: t + t^2/10 = A with t = V*^(1/3), A = d / (R_h (1 + theta/2));
 * t = 2A / (1 + sqrt(1 + 0.4 A)), the cancellation-free root. */
double cb_rupture_volume_willett(const cb_law *law, const cb_pair *pair, double gap)
{
    double r = pair->r_harmonic;
    double a = gap / (r * law->rupture_factor);
    double t = 2.0 * a / (1.0 + sqrt(1.0 + 0.4 * a));
    return t * t * t * r * r * r;
}
