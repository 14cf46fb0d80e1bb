/* laws.h — internal interface between the law dispatcher (law.c) and the laws.
 *
 * The dispatcher validates the inputs, applies the overlap rule (a law is only ever
 * evaluated at gap >= 0), the rupture rule (a law is only evaluated up to its rupture
 * distance) and the validity rule. A law's function then gets finite, positive radii
 * and volume and 0 <= gap <= rupture distance, and must return a finite F >= 0 and
 * dF/dgap (handling gap = 0 by its analytic limit, never evaluating log 0 or 0/0).
 */
#ifndef CAPBRIDGE_LAWS_H
#define CAPBRIDGE_LAWS_H

#include "capbridge.h"

/* Where a pair sits in the table law's table (law_table.c): found once per call, used
 * by both its rupture distance and its force. */
typedef struct cb_table_position {
    int ratio_first, volume_first; /* first nodes of the 4-point stencils */
    double weight[4][4];           /* ratio weight times volume weight, per stencil node */
    double scaled_rupture;         /* rupture / R_h, interpolated */
} cb_table_position;

/* Inputs of one evaluation, with the radius conventions every law may need. */
typedef struct cb_pair {
    double r1, r2;       /* as given */
    double r_small, r_large;
    double r_harmonic;   /* 2 r1 r2 / (r1 + r2) */
    double r_geometric;  /* sqrt(r1 r2) */
    double volume;
    cb_table_position table; /* set by cb_table_locate, for the table law only */
} cb_pair;

/* The pair of one call; for the table law, located in its table. */
cb_pair cb_pair_make(const cb_law *law, double r1, double r2, double volume);

/* For a pair already made from checked inputs (cb_force, cb_rupture_distance and
 * cb_bridge_step share them, so that one call computes the rupture distance at most once):
 * the rupture distance under the law's rupture and validity rules; the force at a finite
 * gap under the validity, overlap and rupture rules (as cb_force), with the pair's rupture
 * distance if the caller has it, else 0 (computed here if the gap is > 0). */
cb_status cb_pair_rupture(const cb_law *law, const cb_pair *pair, double *rupture);
cb_status cb_pair_force(const cb_law *law, const cb_pair *pair, double rupture, double gap,
                        double *force, double *stiffness);

/* A law's force at 0 <= gap <= rupture: writes F >= 0 and dF/dgap.
 * Returns CB_ERR_NO_BRIDGE where the law has no bridge (e.g. Weigert's arcsin > 1). */
typedef cb_status (*cb_force_fn)(const cb_law *law, const cb_pair *pair, double gap,
                                 double *force, double *stiffness);

/* Richefeu eq. 11: 1/lambda of a bridge (kept with the bridge by derive, bridge.c). */
double cb_richefeu_inverse_length(const cb_law *law, const cb_pair *pair);
cb_status cb_richefeu_force(const cb_law *law, const cb_pair *pair, double gap,
                            double *force, double *stiffness);
cb_status cb_willett_force(const cb_law *law, const cb_pair *pair, double gap,
                           double *force, double *stiffness);
cb_status cb_willett_reduced_force(const cb_law *law, const cb_pair *pair, double gap,
                                   double *force, double *stiffness);
cb_status cb_rabinovich_force(const cb_law *law, const cb_pair *pair, double gap,
                              double *force, double *stiffness);
cb_status cb_rabinovich_uncorrected_force(const cb_law *law, const cb_pair *pair, double gap,
                                          double *force, double *stiffness);
cb_status cb_weigert_force(const cb_law *law, const cb_pair *pair, double gap,
                           double *force, double *stiffness);
cb_status cb_soulie_force(const cb_law *law, const cb_pair *pair, double gap,
                          double *force, double *stiffness);
cb_status cb_table_force(const cb_law *law, const cb_pair *pair, double gap,
                         double *force, double *stiffness);

/* Each law's stated validity (cb_law_validity returns these). */
cb_validity cb_richefeu_validity(void);
cb_validity cb_willett_validity(void);
cb_validity cb_willett_reduced_validity(void);
cb_validity cb_rabinovich_validity(void);
cb_validity cb_weigert_validity(void);
cb_validity cb_soulie_validity(void);
cb_validity cb_table_validity(const cb_law *law);

/* Rupture rules (rupture.c), for a prepared law. */
double cb_rupture_lian(const cb_law *law, const cb_pair *pair);
double cb_rupture_willett(const cb_law *law, const cb_pair *pair);
double cb_rupture_willett_unequal(const cb_law *law, const cb_pair *pair);
double cb_rupture_volume_lian(const cb_law *law, const cb_pair *pair, double gap);
double cb_rupture_volume_willett(const cb_law *law, const cb_pair *pair, double gap);
double cb_rupture_volume_willett_unequal(const cb_law *law, const cb_pair *pair, double gap);

/* The table law (law_table.c). */
cb_status cb_table_create(double contact_angle, struct cb_table **table, cb_message *msg);
void cb_table_destroy(struct cb_table *table);
double cb_table_contact_angle(const struct cb_table *table);
void cb_table_locate(const cb_law *law, cb_pair *pair);
double cb_table_rupture(const cb_law *law, const cb_pair *pair);
double cb_table_rupture_volume(const cb_law *law, const cb_pair *pair, double gap);
/* An upper bound of |dF/dgap| of cb_table_force over 0 <= gap <= the table's rupture. */
double cb_table_stiffness_bound(const cb_law *law, const cb_pair *pair);

/* Write a formatted message if msg is not NULL; returns status for chaining. */
cb_status cb_fail(cb_message *msg, cb_status status, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

#endif
