/* reference.h — reading and computing the exact reference curves. */
#ifndef CAPBRIDGE_CLI_REFERENCE_H
#define CAPBRIDGE_CLI_REFERENCE_H

#include "capbridge.h"
#include "cases.h"

#define CB_REFERENCE_COLUMNS                                                            \
    "case,r1,r2,surface_tension,contact_angle,volume,rupture_distance,point,gap,force," \
    "filling_angle1,filling_angle2,pressure,neck_radius"

/* The exact curve of one configuration: rupture distance and CB_CURVE_POINTS bridges at
 * gaps i/(CB_CURVE_POINTS-1) of it, the last at the fold. */
cb_status cb_reference_curve(const cb_case *c, double *rupture, cb_exact_bridge *bridges);

/* One configuration as read back from a reference file. */
typedef struct cb_reference_curve_data {
    char name[48];
    cb_case config;
    double rupture;
    double gap[CB_CURVE_POINTS];
    double force[CB_CURVE_POINTS];
} cb_reference_curve_data;

/* Read every configuration of a reference CSV file; returns the count, or -1 with a
 * message on stderr when the file is missing or malformed. *curves is malloc'ed. */
long cb_reference_read(const char *path, cb_reference_curve_data **curves);

#endif
