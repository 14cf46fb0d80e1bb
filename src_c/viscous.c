/* viscous.c — the viscous force of a liquid bridge between two spheres (issue 19): the
 * damping coefficients of its normal and tangential parts, for a bridge of volume V at a gap
 * s, with the law's viscosity eta and minimum gap s_min (keywords viscosity, min_gap).
 *
 * Normal (squeeze flow): Pitois, Moucheront & Chateau, J. Colloid Interface Sci. 231 (2000)
 * 26-31, the lubrication force of a bridge of finite volume,
 *     F_n = 6 pi eta R*^2 (1/s) (ds/dt) [1 - 1/sqrt(1 + V / (pi R* s^2))]^2,
 * written there for equal spheres of radius R (R* = R/2: 3/2 pi eta R^2, 2V/(pi R s^2)).
 * It follows from Reynolds' equation for the gap h(r) = s + r^2/(2 R*) between two spheres,
 * the pressure zero at the wetted radius r_m, whose gap h_m holds the bridge's volume between
 * the two surfaces, V = pi R* (h_m^2 - s^2): F_n = 6 pi eta R*^2 (ds/dt) / s (1 - s/h_m)^2.
 * V -> infinity is Reynolds' 6 pi eta R*^2 v / s; for a small bridge the factor is
 * (V / (2 pi R* s^2))^2.  Valid for s << R* (lubrication) and slow flow (Re << 1).
 *
 * Tangential (shear flow): Goldman, Cox & Brenner, Chem. Eng. Sci. 22 (1967) 637-651, a
 * sphere translating parallel to a plane at a small gap s,
 *     F_t = 6 pi eta R (8/15 ln(R/s) + 0.9588) v_t,
 * used for two spheres with R* in place of R by DEM models of wet particles (e.g. Shi &
 * McCarthy 2008, Powder Technol., on liquid transfer between particles).  Valid for s << R;
 * it has no bridge-volume dependence, and the logarithm falls below zero only at s > 6 R*,
 * far beyond any rupture distance (clamped at 0 there).
 *
 * Both diverge as s -> 0: the gap is taken as max(s, s_min) (the asperities' height: a
 * sphere does not squeeze its film thinner than its roughness).  In overlap (s <= 0) there is
 * none: the film is squeezed out and the contact law, with its dashpot, governs; a DEM
 * overlap is far deeper than any roughness (~20 um against 1 um for 1 mm spheres at
 * k_n = 1e4 N/m and 1 m/s), and a lubrication force held at s_min over it would dissipate in
 * proportion to 1/k_n, a numerical parameter (it did: the critical Stokes number of a wet
 * collision rose from ~7 to ~40).  The forces oppose the relative motion: F = -c v. */
#include "laws.h"

#include <math.h>

static cb_status check_viscous_input(double r1, double r2, double gap, double volume)
{
    if (!isfinite(r1) || !cb_finite_or_plane(r2) || !isfinite(gap) || !isfinite(volume))
        return CB_ERR_NOT_FINITE;
    if (!(r1 > 0.0) || !(r2 > 0.0) || volume < 0.0) return CB_ERR_NEGATIVE;
    return CB_OK;
}

cb_status cb_viscous_damping(const cb_law *law, double r1, double r2, double gap,
                             double volume, double *normal, double *tangential)
{
    if (!law || !normal || !tangential) return CB_ERR_NULL;
    *normal = *tangential = 0.0;
    cb_status status = check_viscous_input(r1, r2, gap, volume);
    if (status != CB_OK) return status;
    if (!(law->viscosity > 0.0) || !(volume > 0.0) || !(gap > 0.0)) return CB_OK;
    const double reduced = 0.5 * cb_radius_harmonic(r1, r2); /* R*; r1 at a plane */
    const double s = gap > law->viscous_min_gap ? gap : law->viscous_min_gap;
    const double eta = law->viscosity;
    /* 1 - s/h_m, with (h_m/s)^2 = 1 + V/(pi R* s^2) */
    const double filled = 1.0 - 1.0 / sqrt(1.0 + volume / (CB_PI * reduced * s * s));
    *normal = 6.0 * CB_PI * eta * reduced * reduced / s * filled * filled;
    const double shear = (8.0 / 15.0) * log(reduced / s) + 0.9588;
    *tangential = shear > 0.0 ? 6.0 * CB_PI * eta * reduced * shear : 0.0;
    return CB_OK;
}

cb_status cb_viscous_check(const cb_law *law, cb_message *msg)
{
    if (!law) return cb_fail(msg, CB_ERR_NULL, "law is NULL");
    if (!(law->viscosity > 0.0)) return CB_OK;
    if (!(law->viscous_min_gap > 0.0))
        return cb_fail(msg, CB_ERR_RANGE,
                       "viscosity %g needs min_gap: the smallest lubrication gap (the "
                       "particles' roughness, a length > 0), where the viscous force of "
                       "Pitois et al. 2000 would otherwise diverge at contact",
                       law->viscosity);
    return CB_OK;
}
