/* cases.h — the reference configurations: the 13 pull-off cases of Gladkyy & Schwarze
 * 2014, Table 1, and the grid over contact angle, size ratio and volume. */
#ifndef CAPBRIDGE_CLI_CASES_H
#define CAPBRIDGE_CLI_CASES_H

#include <stddef.h>

typedef struct cb_case {
    const char *name;
    double r1, r2;          /* [m] */
    double surface_tension; /* [N/m] */
    double contact_angle;   /* [deg] */
    double volume;          /* [m^3] */
} cb_case;

extern const cb_case cb_gladkyy_cases[];
extern const size_t cb_gladkyy_case_count;

/* Points per exact curve: gaps i/(n-1) * rupture distance, i = 0 .. n-1. */
#define CB_CURVE_POINTS 21

/* The grid: contact angle [deg] x size ratio r2/r1 x V / R_h^3 (log spaced). */
extern const double cb_grid_contact_angles[];
extern const size_t cb_grid_contact_angle_count;
extern const double cb_grid_size_ratios[];
extern const size_t cb_grid_size_ratio_count;
extern const double cb_grid_volumes[];
extern const size_t cb_grid_volume_count;
/* Radius of the smaller sphere and surface tension used for the grid. */
#define CB_GRID_RADIUS 1.0e-3
#define CB_GRID_SURFACE_TENSION 0.0728

/* The i-th grid configuration, i in [0, contact angles x ratios x volumes); its name
 * (e.g. "t10_r1.5_v0.001") is written to name. */
cb_case cb_grid_case(size_t index, char *name, size_t name_size);
size_t cb_grid_case_count(void);

/* The sphere-plane set (a wall, r2 = CB_PLANE): the grid's contact angles x its volumes,
 * V / R_h^3 with R_h = 2 r1, sphere radius CB_GRID_RADIUS; names like "t10_plane_v0.001". */
cb_case cb_plane_case(size_t index, char *name, size_t name_size);
size_t cb_plane_case_count(void);

#endif
