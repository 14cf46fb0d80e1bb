/* radius.c — the radius conventions the laws use; each law keeps its source's radius
 * (cb_radius_reference in capbridge.h). */
#include "capbridge.h"

#include <math.h>

/* Derjaguin: 2 r1 r2 / (r1 + r2); the small-volume limit of the exact force at
 * contact is 2 pi gamma cos(theta) times this radius. */
double cb_radius_harmonic(double r1, double r2)
{
    return cb_is_plane(r2) ? 2.0 * r1 : 2.0 * r1 * r2 / (r1 + r2);
}

double cb_radius_geometric(double r1, double r2) { return sqrt(r1 * r2); }

double cb_radius_of(cb_radius_reference reference, double r1, double r2)
{
    switch (reference) {
    case CB_RADIUS_HARMONIC: return cb_radius_harmonic(r1, r2);
    case CB_RADIUS_GEOMETRIC: return cb_radius_geometric(r1, r2);
    case CB_RADIUS_LARGE: return r1 > r2 ? r1 : r2;
    }
    return cb_radius_harmonic(r1, r2);
}

const char *cb_radius_reference_name(cb_radius_reference reference)
{
    switch (reference) {
    case CB_RADIUS_HARMONIC: return "R_h";
    case CB_RADIUS_GEOMETRIC: return "R_g";
    case CB_RADIUS_LARGE: return "R_large";
    }
    return "R_h";
}
