/* wall.c — the rule a wall adds to a law: one contact angle for two surfaces
 * (cb_wall_contact_angle in capbridge.h says why the mean cosine, and what it misses). */
#include "capbridge.h"

#include <math.h>

static int angle_valid(double angle)
{
    return isfinite(angle) && angle >= 0.0 && angle < 0.5 * CB_PI;
}

double cb_wall_contact_angle(double grain_angle, double wall_angle)
{
    if (!angle_valid(grain_angle) || !angle_valid(wall_angle)) return NAN;
    if (grain_angle == wall_angle) return grain_angle; /* exact, with no rounding */
    return acos(0.5 * (cos(grain_angle) + cos(wall_angle)));
}
