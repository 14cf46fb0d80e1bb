/* capbridge_liggghts_checks.h — the checks of `cohesion capillary`'s input: its
 * properties at set-up and the periodic box at every re-neighboring.
 *
 * Part of capbridge (lammps_pair/liggghts/). Compiled inside LIGGGHTS: C++98 and C++11.
 * Every check stops all ranks (the same input on each) with an error that names the
 * property, the atom types and what is allowed.
 */
#ifndef CAPBRIDGE_LIGGGHTS_CHECKS_H_
#define CAPBRIDGE_LIGGGHTS_CHECKS_H_

#include "capbridge.h"
#include "domain.h"
#include "error.h"
#include "neighbor.h"

#include <cmath>
#include <cstdio>

namespace capbridge_liggghts {

/* false for NaN and infinities (std::isfinite is C++11) */
inline bool is_finite(const double x) { return x == x && x - x == 0.0; }

/* surfaceTension > 0; 0 <= contactAngle < 90 degrees per type (radians here); bridgeVolume
 * (NULL unless liquid fixed) >= 0 and finite per pair of types (fix property/global
 * refuses an asymmetric peratomtypepair matrix itself) */
inline void check_properties(LAMMPS_NS::Error *error, const double surface_tension,
                             const double *contact_angle, double **bridge_volume,
                             const int ntypes)
{
    char text[512];
    if (!(surface_tension > 0.0) || !is_finite(surface_tension)) {
        snprintf(text, sizeof text,
                 "cohesion model capillary: surfaceTension = %g N/m; it must be > 0 "
                 "(fix property/global surfaceTension scalar VALUE)",
                 surface_tension);
        error->all(FLERR, text);
    }
    for (int t = 1; t <= ntypes; ++t) {
        const double degrees = contact_angle[t] * 180.0 / M_PI;
        if (!(contact_angle[t] >= 0.0 && contact_angle[t] < 0.5 * M_PI)) {
            snprintf(text, sizeof text,
                     "cohesion model capillary: contactAngle of atom type %d is %g degrees; "
                     "it must satisfy 0 <= contactAngle < 90",
                     t, degrees);
            error->all(FLERR, text);
        }
    }
    if (!bridge_volume) return;
    for (int a = 1; a <= ntypes; ++a)
        for (int b = 1; b <= ntypes; ++b) {
            const double v = bridge_volume[a][b];
            if (!(v >= 0.0) || !is_finite(v)) {
                snprintf(text, sizeof text,
                         "cohesion model capillary: bridgeVolume for atom types %d %d is %g "
                         "m^3; it must be >= 0 (0: the pair stays dry)",
                         a, b, v);
                error->all(FLERR, text);
            }
        }
}

/* The contact history, and with it every bridge, is kept per pair of atom IDs: in a
 * periodic box narrower than twice the neighbor cutoff two atoms can meet as two
 * periodic images, each with a copy of their bridge, creating or destroying liquid.
 * The widths and the rule are the core's (cb_cell_widths, cb_periodic_too_narrow). */
inline void check_periodic_images(LAMMPS_NS::Domain *domain, LAMMPS_NS::Neighbor *neighbor,
                                  LAMMPS_NS::Error *error)
{
    double width[3];
    cb_cell_widths(domain->h_inv, width);
    const int periodic[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};
    const double cutoff = neighbor->cutneighmax;
    const int d = cb_periodic_too_narrow(width, periodic, cutoff);
    if (d < 0) return;
    char text[480];
    snprintf(text, sizeof text,
             "cohesion model capillary: the periodic box is %g wide along %c, less than "
             "twice the neighbor cutoff %g: two atoms would meet as two periodic images, "
             "each holding a copy of their bridge.  Make the box at least %g wide along "
             "%c (or lower the neighbor skin)",
             width[d], "xyz"[d], cutoff, 2.0 * cutoff, "xyz"[d]);
    error->all(FLERR, text);
}

} /* namespace capbridge_liggghts */

#endif /* CAPBRIDGE_LIGGGHTS_CHECKS_H_ */
