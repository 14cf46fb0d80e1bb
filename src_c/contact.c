/* contact.c — the contact law's coefficients (the forces are inline in capbridge.h, the
 * engines' hot path): Richefeu 2007 eqs. 2-3 and 12. */
#include "laws.h"

#include <math.h>

cb_status cb_contact_law_init(cb_contact_law *law, double normal_stiffness,
                              double tangential_stiffness, double damping_rate,
                              double friction, cb_dashpot_rule dashpot, cb_message *msg)
{
    if (!law) return cb_fail(msg, CB_ERR_NULL, "missing contact law");
    const struct {
        const char *name;
        double value;
    } coefficients[] = {{"kn", normal_stiffness},
                        {"kt", tangential_stiffness},
                        {"damping", damping_rate},
                        {"mu", friction}};
    for (int k = 0; k < 4; ++k) {
        if (!isfinite(coefficients[k].value))
            return cb_fail(msg, CB_ERR_NOT_FINITE, "contact coefficient %s must be finite",
                           coefficients[k].name);
        if (coefficients[k].value < 0.0)
            return cb_fail(msg, CB_ERR_NEGATIVE, "contact coefficient %s = %g: must be >= 0",
                           coefficients[k].name, coefficients[k].value);
    }
    if (damping_rate > 1.0)
        return cb_fail(msg, CB_ERR_RANGE,
                       "damping = %g: the damping rate alpha_n must lie in [0, 1] (Richefeu "
                       "2007 eq. 3; 1 is critical damping)",
                       damping_rate);
    if (dashpot != CB_DASHPOT_APPROACH && dashpot != CB_DASHPOT_BOTH &&
        dashpot != CB_DASHPOT_REPULSIVE)
        return cb_fail(msg, CB_ERR_RANGE, "dashpot rule %d: allowed approach, both, repulsive",
                       (int)dashpot);
    law->normal_stiffness = normal_stiffness;
    law->tangential_stiffness = tangential_stiffness;
    law->damping_rate = damping_rate;
    law->friction = friction;
    law->dashpot = dashpot;
    law->damping_factor = 2.0 * damping_rate * sqrt(normal_stiffness);
    law->closing_floor = dashpot == CB_DASHPOT_APPROACH ? 0.0 : -HUGE_VAL;
    law->force_floor = dashpot == CB_DASHPOT_BOTH ? -HUGE_VAL : 0.0;
    return CB_OK;
}
