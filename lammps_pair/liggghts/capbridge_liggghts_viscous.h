/* capbridge_liggghts_viscous.h — the viscous force of a bridge in `cohesion capillary`
 * (keyword `viscous on`).
 *
 * Part of capbridge (lammps_pair/liggghts/). Compiled inside LIGGGHTS: C++98 and C++11.
 *
 * The force is the core's: cb_viscous_damping gives the normal damping coefficient (Pitois,
 * Moucheront & Chateau 2000, the squeeze flow of a bridge of finite volume) and the
 * tangential one (Goldman, Cox & Brenner 1967 with R*), the gap clamped at the law's
 * min_gap, none in overlap (the contact law governs there). This file gathers the two
 * per-type-pair properties into the laws (liquidViscosity [Pa s], viscousMinGap [m]: fix
 * property/global ... peratomtypepair), and applies the force of a pair apart that holds
 * a bridge: -c_n d(gap)/dt along the line of centres, -c_t v_t at the contact point (with
 * its torques), v_t the sliding velocity with the spheres' rotation, as LAMMPS's pair
 * gran/capillary does, so that the two engines give the same numbers.
 */
#ifndef CAPBRIDGE_LIGGGHTS_VISCOUS_H_
#define CAPBRIDGE_LIGGGHTS_VISCOUS_H_

#include "atom.h"
#include "capbridge.h"
#include "contact_interface.h"
#include "error.h"
#include "property_registry.h"

#include <cstdio>
#include <string>

namespace MODEL_PARAMS
{
    /* liquidViscosity [Pa s] and viscousMinGap [m], per pair of atom types (viscous on).
     * Not `static`: one creator address in every translation unit. */
    inline MatrixProperty* createCapillaryLiquidViscosity(PropertyRegistry & registry,
                                                          const char * caller, bool)
    {
        return createPerTypePairProperty(registry, "liquidViscosity", caller);
    }
    inline MatrixProperty* createCapillaryViscousMinGap(PropertyRegistry & registry,
                                                        const char * caller, bool)
    {
        return createPerTypePairProperty(registry, "viscousMinGap", caller);
    }
}

namespace capbridge_liggghts {

class ViscousForce {
  public:
    ViscousForce() : viscosity(NULL), min_gap(NULL) {}

    /* viscous on: the two properties (the laws take them in PairLaws::build) */
    void connect(PropertyRegistry &registry, LAMMPS_NS::Error *error, const int ntypes)
    {
        const char *caller = "cohesion model capillary (viscous on)";
        registry.registerProperty("liquidViscosity", &MODEL_PARAMS::createCapillaryLiquidViscosity);
        registry.registerProperty("viscousMinGap", &MODEL_PARAMS::createCapillaryViscousMinGap);
        registry.connect("liquidViscosity", viscosity, caller);
        registry.connect("viscousMinGap", min_gap, caller);
        check(error, ntypes);
    }

    /* The force of a pair apart (gap > 0) holding a bridge of this volume, added to the
     * pair's forces and torques; ra, rb the radii in the core's order. A status other than
     * CB_OK is returned for the caller's error. */
    cb_status add(const cb_law *law, const LIGGGHTS::ContactModels::SurfacesCloseData &d,
                  LAMMPS_NS::Atom *atom, const double ra, const double rb, const double gap, const double volume,
                  const double *en, LIGGGHTS::ContactModels::ForceData &i_forces,
                  LIGGGHTS::ContactModels::ForceData &j_forces) const
    {
        double normal = 0.0, tangential = 0.0;
        const cb_status status = cb_viscous_damping(law, ra, rb, gap, volume, &normal,
                                                    &tangential);
        if (status != CB_OK || (normal == 0.0 && tangential == 0.0)) return status;
        const double *vi = atom->v[d.i], *vj = atom->v[d.j];
        // LIGGGHTS sets omega_i, omega_j of SurfacesCloseData only for pairs in contact
        const double *wi = atom->omega[d.i], *wj = atom->omega[d.j];
        const double vr[3] = {vi[0] - vj[0], vi[1] - vj[1], vi[2] - vj[2]};
        const double gap_rate = vr[0] * en[0] + vr[1] * en[1] + vr[2] * en[2];
        const double ri = d.radi, rj = d.radj;
        // the velocity of i's surface relative to j's at the contact point, i's at -ri en
        // and j's at +rj en (en from j to i): vr - (ri wi + rj wj) x en
        const double w[3] = {ri * wi[0] + rj * wj[0], ri * wi[1] + rj * wj[1],
                             ri * wi[2] + rj * wj[2]};
        const double vt[3] = {vr[0] - gap_rate * en[0] + (en[1] * w[2] - en[2] * w[1]),
                              vr[1] - gap_rate * en[1] + (en[2] * w[0] - en[0] * w[2]),
                              vr[2] - gap_rate * en[2] + (en[0] * w[1] - en[1] * w[0])};
        const double fn = -normal * gap_rate;  // along en: repulsive while the gap closes
        double ft[3];
        for (int k = 0; k < 3; ++k) {
            ft[k] = -tangential * vt[k];
            i_forces.delta_F[k] += fn * en[k] + ft[k];
            j_forces.delta_F[k] -= fn * en[k] + ft[k];
        }
        // the tangential force acts at the contact point: -r (en x ft) on each sphere
        const double turn[3] = {en[1] * ft[2] - en[2] * ft[1], en[2] * ft[0] - en[0] * ft[2],
                                en[0] * ft[1] - en[1] * ft[0]};
        for (int k = 0; k < 3; ++k) {
            i_forces.delta_torque[k] -= ri * turn[k];
            j_forces.delta_torque[k] -= rj * turn[k];
        }
        return CB_OK;
    }

    double **viscosity;  // [Pa s] per pair of atom types; NULL: viscous off
    double **min_gap;    // [m]

  private:
    /* (fix property/global refuses an asymmetric peratomtypepair matrix itself) */
    void check(LAMMPS_NS::Error *error, const int ntypes) const
    {
        char text[512];
        for (int a = 1; a <= ntypes; ++a)
            for (int b = 1; b <= ntypes; ++b) {
                const double eta = viscosity[a][b], gap = min_gap[a][b];
                if (!(eta >= 0.0) || eta - eta != 0.0)
                    snprintf(text, sizeof text, "cohesion model capillary: liquidViscosity "
                             "for atom types %d %d is %g Pa s; it must be >= 0 and finite (0: "
                             "no viscous force)", a, b, eta);
                else if (eta > 0.0 && (!(gap > 0.0) || gap - gap != 0.0))
                    snprintf(text, sizeof text, "cohesion model capillary: viscousMinGap for "
                             "atom types %d %d is %g m; with liquidViscosity %g Pa s it must be "
                             "> 0 and finite (the smallest lubrication gap, the roughness)",
                             a, b, gap, eta);
                else
                    continue;
                error->all(FLERR, text);
            }
    }
};

} /* namespace capbridge_liggghts */

#endif /* CAPBRIDGE_LIGGGHTS_VISCOUS_H_ */
