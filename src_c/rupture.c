/* rupture.c — rupture (debonding) distances and their inverses.
 * theta enters every rule in radians (law->rupture_factor = 1 + theta/2). */
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

/* Willett et al. 2000's form for unequal spheres (MODELS.md), R_h and V* as in eq. 2:
 *   d / R_h = (1 + theta (rho + 1) / 4) (t + (rho/2 - 0.4) t^2),  t = V*^(1/3),
 * rho = R_small / R_large; at rho = 1 it is Gladkyy eq. 2.  Against the exact fold on the
 * README's grid (theta 0-40 deg, size ratio 1-10, V* 1e-5 to 0.1) within 7 %, where eq.
 * 2 is off by up to 37 % (it grows too fast with V* for unequal spheres).
 * For rho < 0.8 the quadratic has a maximum at t_peak = 1 / (0.8 - rho) (V* >= 1.95, far
 * beyond the stated V* < 0.1); beyond it the distance grows as t / 2 times the factor,
 * continuous there, so that it keeps rising with the volume (the extend rule). */
typedef struct willett_unequal {
    double factor, b, t_peak; /* t_peak = HUGE_VAL for b >= 0 */
} willett_unequal;

static willett_unequal willett_unequal_terms(const cb_law *law, const cb_pair *pair)
{
    double rho = pair->r_small / pair->r_large;
    willett_unequal w;
    w.factor = 1.0 + 0.25 * law->contact_angle * (rho + 1.0);
    w.b = 0.5 * rho - 0.4;
    w.t_peak = w.b < 0.0 ? -0.5 / w.b : HUGE_VAL;
    return w;
}

double cb_rupture_willett_unequal(const cb_law *law, const cb_pair *pair)
{
    willett_unequal w = willett_unequal_terms(law, pair);
    double r = pair->r_harmonic;
    double t = cbrt(pair->volume / (r * r * r));
    return r * w.factor * (t <= w.t_peak ? t + w.b * t * t : 0.5 * t);
}

/* The inverse: t + b t^2 = A, A = d / (R_h factor): t = 2A / (1 + sqrt(1 + 4 b A)), the
 * root on the rising branch (1 + 4 b A >= 0 up to the peak, A_peak = t_peak / 2); beyond
 * the peak t = 2A. */
double cb_rupture_volume_willett_unequal(const cb_law *law, const cb_pair *pair, double gap)
{
    willett_unequal w = willett_unequal_terms(law, pair);
    double r = pair->r_harmonic;
    double a = gap / (r * w.factor);
    double t = a > 0.5 * w.t_peak ? 2.0 * a : 2.0 * a / (1.0 + sqrt(1.0 + 4.0 * w.b * a));
    return t * t * t * r * r * r;
}
