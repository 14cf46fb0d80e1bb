/* cases.c — Gladkyy & Schwarze 2014, Table 1 (after Willett 2000 and Rabinovich 2005),
 * and the reference grid. */
#include "cases.h"

#include <stdio.h>

#include "capbridge.h"

#define MM 1e-3
#define UM 1e-6
#define NL 1e-12           /* nanolitre in m^3 */
#define E8NM3 (1e8 * 1e-27) /* 10^8 nm^3 in m^3 */

const cb_case cb_gladkyy_cases[] = {
    {"W11", 2.381 * MM, 2.381 * MM, 20.6e-3, 0.0, 13.6 * NL},
    {"W12", 2.381 * MM, 2.381 * MM, 20.6e-3, 0.0, 31.3 * NL},
    {"W13", 2.381 * MM, 2.381 * MM, 20.6e-3, 0.0, 74.2 * NL},
    {"W21", 2.381 * MM, 1.588 * MM, 20.6e-3, 0.0, 9.6 * NL},
    {"W22", 2.381 * MM, 1.588 * MM, 20.6e-3, 0.0, 13.2 * NL},
    {"W23", 2.381 * MM, 1.588 * MM, 20.6e-3, 0.0, 24.7 * NL},
    {"W24", 2.381 * MM, 1.588 * MM, 20.6e-3, 0.0, 59.3 * NL},
    {"W31", 2.381 * MM, 1.191 * MM, 20.6e-3, 0.0, 25.3 * NL},
    {"W32", 2.381 * MM, 1.191 * MM, 20.6e-3, 0.0, 61.8 * NL},
    {"W33", 2.381 * MM, 1.191 * MM, 20.6e-3, 0.0, 127.8 * NL},
    {"R1", 19 * UM, 35 * UM, 27e-3, 10.0, 2 * E8NM3},
    {"R2", 19 * UM, 32.5 * UM, 24e-3, 10.0, 12 * E8NM3},
    {"R3", 19 * UM, 27.5 * UM, 28e-3, 10.0, 36 * E8NM3},
};
const size_t cb_gladkyy_case_count = sizeof cb_gladkyy_cases / sizeof cb_gladkyy_cases[0];

const double cb_grid_contact_angles[] = {0.0, 10.0, 20.0, 30.0, 40.0};
const size_t cb_grid_contact_angle_count = 5;
const double cb_grid_size_ratios[] = {1.0, 1.5, 2.0, 3.0, 5.0, 10.0};
const size_t cb_grid_size_ratio_count = 6;
/* 1e-5 .. 1e-1, two points per decade. */
const double cb_grid_volumes[] = {1e-5, 3.1622776601683795e-5, 1e-4, 3.1622776601683795e-4,
                                  1e-3, 3.1622776601683795e-3, 1e-2, 3.1622776601683795e-2,
                                  1e-1};
const size_t cb_grid_volume_count = 9;

size_t cb_grid_case_count(void)
{
    return cb_grid_contact_angle_count * cb_grid_size_ratio_count * cb_grid_volume_count;
}

cb_case cb_grid_case(size_t index, char *name, size_t name_size)
{
    size_t v = index % cb_grid_volume_count;
    size_t r = (index / cb_grid_volume_count) % cb_grid_size_ratio_count;
    size_t t = index / (cb_grid_volume_count * cb_grid_size_ratio_count);
    cb_case c;
    c.r1 = CB_GRID_RADIUS;
    c.r2 = CB_GRID_RADIUS * cb_grid_size_ratios[r];
    c.surface_tension = CB_GRID_SURFACE_TENSION;
    c.contact_angle = cb_grid_contact_angles[t];
    double rh = cb_radius_harmonic(c.r1, c.r2);
    c.volume = cb_grid_volumes[v] * rh * rh * rh;
    snprintf(name, name_size, "t%g_r%g_v%.3g", cb_grid_contact_angles[t],
             cb_grid_size_ratios[r], cb_grid_volumes[v]);
    c.name = name;
    return c;
}

size_t cb_plane_case_count(void)
{
    return cb_grid_contact_angle_count * cb_grid_volume_count;
}

cb_case cb_plane_case(size_t index, char *name, size_t name_size)
{
    size_t v = index % cb_grid_volume_count;
    size_t t = index / cb_grid_volume_count;
    cb_case c;
    c.r1 = CB_GRID_RADIUS;
    c.r2 = CB_PLANE;
    c.surface_tension = CB_GRID_SURFACE_TENSION;
    c.contact_angle = cb_grid_contact_angles[t];
    double rh = cb_radius_harmonic(c.r1, c.r2);
    c.volume = cb_grid_volumes[v] * rh * rh * rh;
    snprintf(name, name_size, "t%g_plane_v%.3g", cb_grid_contact_angles[t], cb_grid_volumes[v]);
    c.name = name;
    return c;
}
