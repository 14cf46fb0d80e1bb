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

#include <math.h>

/* Where a pair sits in the table law's table (law_table.c): found once per call, used
 * by both its rupture distance and its force. */
typedef struct cb_table_position {
    int ratio_first, volume_first; /* first nodes of the 4-point stencils */
    double ratio_weight[4], volume_weight[4];        /* the Lagrange weights along each axis */
    float cell_ratio_weight[4], cell_volume_weight[4]; /* the same in single precision, for the
                                                        * force's cells */
    double volume_coordinate;      /* ln(V / R_h^3) in volume nodes, clamped to the table:
                                    * a bridge's constant (its stencil without the log) */
    double scaled_rupture;         /* rupture / R_h, interpolated (as sqrt(R_h / rupture)) */
} cb_table_position;

/* Inputs of one evaluation, with the radius conventions every law may need.  At a plane
 * (r2 = CB_PLANE) a law whose row has no plane of its own gets the Derjaguin-equivalent
 * pair, r1 = r2 = twice the grain's radius (capbridge.h); one that has (the table law) gets
 * r2 = INFINITY, r_large = INFINITY, r_harmonic = 2 r1. */
typedef struct cb_pair {
    double r1, r2;       /* as given, or the equivalent pair's */
    int plane;           /* surface 2 is a plane */
    double r_small, r_large;
    double r_harmonic;   /* 2 r1 r2 / (r1 + r2) */
    double r_geometric;  /* sqrt(r1 r2) */
    double volume;
    cb_table_position table; /* set by the table law's locate, for it only */
} cb_pair;

/* The pair of one call; for the table law, located in its table. Written through a
 * pointer, not returned: returned by value, the struct (250 bytes with the table's
 * position) was built on the stack and copied, ~25 ns on every law's call.
 * cb_pair_geometry makes the radii and volume only, not located: what a stretched
 * bridge's bridge_force gets (a law that locates finds its place from the bridge's
 * constant, or locates the pair itself). */
void cb_pair_make(const cb_law *law, double r1, double r2, double volume, cb_pair *pair);
void cb_pair_geometry(const cb_law *law, double r1, double r2, double volume, cb_pair *pair);

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

/* One row of the law registry: everything the dispatcher (law.c) and the bridge state
 * (bridge.c) know of a law. Each law defines its row in its own file; an optional
 * operation is NULL where the law has nothing of that kind. */
typedef struct cb_law_ops {
    const char *name;                           /* as the keyword parser spells it */
    cb_force_fn force;                          /* F and dF/dgap, 0 <= gap <= rupture */
    cb_validity (*validity)(const cb_law *law); /* the law's stated range */
    cb_rupture_rule default_rupture;            /* the rule of the law's source */
    int tabulated; /* 1: the force is interpolated in a table the law builds, not a closed
                    * form (cb_model_tabulated) */
    int plane;     /* 1: the law evaluates a sphere-plane pair itself; 0: as the
                    * Derjaguin-equivalent pair (cb_pair_make) */
    /* a rupture rule of the law's own (CB_RUPTURE_EXACT) and its inverse; optional */
    double (*own_rupture)(const cb_law *law, const cb_pair *pair);
    double (*own_rupture_volume)(const cb_law *law, const cb_pair *pair, double gap);
    /* what the law derives beyond the common constants (it may allocate: release frees
     * it, on any initialised law); optional, both or neither */
    cb_status (*prepare)(cb_law *law, cb_message *msg);
    void (*release)(cb_law *law);
    /* what one pair needs of the prepared law, found once per call; optional */
    void (*locate)(const cb_law *law, cb_pair *pair);
    /* an upper bound of |dF/dgap| over the bridge; optional (NULL: the force sampled) */
    double (*stiffness_bound)(const cb_law *law, const cb_pair *pair);
    /* the law's own keywords (keyword_count of them: cb_law_keyword in capbridge.h; the
     * value of keywords[k] lives in law->parameters[k]) and how a value is checked and
     * stored in law->parameters[index] (cb_law_init sets each default through it); optional */
    const cb_law_keyword *keywords;
    int keyword_count;
    cb_status (*set_keyword)(cb_law *law, int index, const char *value, cb_message *msg);
    /* the constant a bridge keeps for its law (cb_bridge.law_constant, finite, >= 0),
     * derived at formation from the located pair, and a stretched bridge's force
     * (0 < gap <= its rupture distance) from the bridge's stored constants and the pair's
     * geometry (cb_pair_geometry, not located): equal to force at that gap, bit for bit */
    double (*bridge_constant)(const cb_law *law, const cb_pair *pair);
    cb_status (*bridge_force)(const cb_law *law, const cb_pair *pair,
                              const cb_bridge *bridge, double gap, double *force);
} cb_law_ops;

/* The registry (law.c), indexed by cb_model, and each law's row. */
extern const cb_law_ops *const cb_law_registry[];
#define CB_LAW_ROW_DECLARATION(value, row, name) extern const cb_law_ops cb_##row##_ops;
CB_LAWS(CB_LAW_ROW_DECLARATION)
#undef CB_LAW_ROW_DECLARATION

/* The row of a law whose model is valid (a prepared law's). */
static inline const cb_law_ops *cb_law_ops_of(const cb_law *law)
{
    return cb_law_registry[law->model];
}

/* For the laws that keep no constant of their own (law.c): law_constant 0, and a
 * stretched bridge's force the law's force in full (the pair located first where the law
 * locates). */
double cb_no_bridge_constant(const cb_law *law, const cb_pair *pair);
cb_status cb_bridge_force_in_full(const cb_law *law, const cb_pair *pair,
                                  const cb_bridge *bridge, double gap, double *force);

/* A stretched bridge's force (0 < gap, under the validity and rupture rules, as
 * cb_pair_force with the bridge's rupture distance) through its law's bridge_force; the
 * pair as cb_pair_geometry makes it. */
cb_status cb_pair_bridge_force(const cb_law *law, const cb_pair *pair, const cb_bridge *bridge,
                               double gap, double *force);

/* Rupture rules (rupture.c), for a prepared law. */
double cb_rupture_lian(const cb_law *law, const cb_pair *pair);
double cb_rupture_willett(const cb_law *law, const cb_pair *pair);
double cb_rupture_willett_unequal(const cb_law *law, const cb_pair *pair);
double cb_rupture_volume_lian(const cb_law *law, const cb_pair *pair, double gap);
double cb_rupture_volume_willett(const cb_law *law, const cb_pair *pair, double gap);
double cb_rupture_volume_willett_unequal(const cb_law *law, const cb_pair *pair, double gap);

/* A second radius as the core accepts it: finite, or a plane (CB_PLANE). */
static inline int cb_finite_or_plane(double r2) { return isfinite(r2) || cb_is_plane(r2); }

/* Write a formatted message if msg is not NULL; returns status for chaining. */
cb_status cb_fail(cb_message *msg, cb_status status, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

#endif
