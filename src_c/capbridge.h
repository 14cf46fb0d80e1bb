/* capbridge.h — the one public header of the capbridge core.
 *
 * Capillary (liquid-bridge) cohesion between two spheres for discrete element
 * simulations: the force laws of Richefeu et al. 2007 and of the laws compared by
 * Gladkyy & Schwarze 2014, their rupture distances, the bridge state and its
 * transitions, the liquid redistribution protocols of Richefeu et al. 2007, and an
 * exact Laplace-Young solver that every law is measured against.
 *
 * Conventions (every function):
 *   - SI units. Lengths in m, volumes in m^3, surface tension in N/m, force in N.
 *   - Contact angles are radians inside the core; the keyword parser takes degrees.
 *   - gap is the surface-to-surface distance; gap < 0 is an overlap.
 *   - force is the magnitude of the attraction: >= 0, 0 when there is no bridge.
 *   - Functions return a cb_status; outputs are written only on CB_OK.
 *     A NaN or an infinity never leaves the core: such inputs are CB_ERR_NOT_FINITE.
 *   - No globals, no allocation in the force path. C99, reentrant.
 */
#ifndef CAPBRIDGE_H
#define CAPBRIDGE_H

#include <float.h>
#include <math.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define CB_VERSION_STRING "0.1.0"

/* ---------------------------------------------------------------- status */

#define CB_PI 3.14159265358979323846 /* the one definition: angles cross the API in radians */

typedef enum cb_status {
    CB_OK = 0,
    CB_ERR_NULL,             /* a required pointer argument is NULL */
    CB_ERR_NOT_FINITE,       /* an input is NaN or infinite */
    CB_ERR_NEGATIVE,         /* a radius, volume or surface tension is negative or zero */
    CB_ERR_RANGE,            /* an input lies outside what the function accepts */
    CB_ERR_UNKNOWN_LAW,      /* a law name that is not one of cb_law_names() */
    CB_ERR_UNKNOWN_KEYWORD,  /* a keyword or keyword value that is not recognised */
    CB_ERR_OUT_OF_VALIDITY,  /* outside the law's stated validity, with validity = strict */
    CB_ERR_NO_BRIDGE,        /* no bridge of this volume exists at this gap for this law */
    CB_ERR_NO_CONVERGENCE,   /* the exact solver did not converge */
    CB_ERR_NO_MEMORY,        /* an allocation failed (never in the force path) */
    CB_ERR_LIQUID,           /* liquid bookkeeping would lose or create liquid */
    CB_ERR_BRIDGE_STATE      /* a stored cb_bridge is neither dry nor a valid active bridge */
} cb_status;

/* A short English sentence for a status; never NULL. */
const char *cb_status_message(cb_status status);

/* The number grammar of every text input (law keywords, the CLI, the engines' keyword
 * values): the whole string is one number in decimal notation -- no blanks, no
 * hexadecimal, inf or nan -- within double range (an overflow or an underflow to 0 or a
 * subnormal is refused, not rounded). Returns 1 and sets *value, else 0. */
int cb_parse_number(const char *text, double *value);

/* A message buffer for configuration errors: names what is wrong and what is allowed. */
typedef struct cb_message {
    char text[320];
} cb_message;

/* ----------------------------------------------------------------- laws */

/* The laws, one row each: its cb_model value (CB_MODEL_ + the first column), the C name of its
 * registry row (cb_<second>_ops, in the law's own file: laws.h) and its name as the keyword
 * parser spells it.  Adding a law is its file and one row here; the enum, the registry and
 * cb_law_names are made from this list. */
#define CB_LAWS(ROW)                                                                          \
    ROW(RICHEFEU, richefeu, "richefeu")      /* Richefeu 2007 eqs. 4-11, exponential decay */ \
    ROW(WILLETT, willett, "willett")         /* Willett 2000 full fit, Gladkyy eqs. 6-7 */    \
    ROW(WILLETT_REDUCED, willett_reduced, "willett/reduced") /* closed form, Gladkyy eq. 8 */ \
    ROW(RABINOVICH, rabinovich, "rabinovich") /* with Lambert 2008, Gladkyy eqs. 9-12 */      \
    ROW(RABINOVICH_UNCORRECTED, rabinovich_uncorrected, "rabinovich/uncorrected") /* eq. 11 */ \
    ROW(WEIGERT, weigert, "weigert")         /* Weigert & Ripperger 1999, Gladkyy eq. 5 */    \
    ROW(SOULIE, soulie, "soulie")            /* Soulie 2006 */                                \
    ROW(TABLE, table, "table")               /* exact Laplace-Young solution, tabulated */

#define CB_MODEL_ENUMERATOR(value, row, name) CB_MODEL_##value,
typedef enum cb_model {
    CB_LAWS(CB_MODEL_ENUMERATOR) /* CB_MODEL_RICHEFEU = 0, CB_MODEL_WILLETT, ... */
    CB_MODEL_COUNT
} cb_model;
#undef CB_MODEL_ENUMERATOR

/* The rupture (debonding) distance rule. DEFAULT means the law's own paper's rule. */
typedef enum cb_rupture_rule {
    CB_RUPTURE_DEFAULT = 0,
    CB_RUPTURE_LIAN,     /* Richefeu eq. 6: (1 + theta/2) V^(1/3) */
    CB_RUPTURE_WILLETT,  /* Gladkyy eq. 2: (1 + theta/2)(V*^(1/3) + V*^(2/3)/10) R_h */
    CB_RUPTURE_EXACT,    /* the fold of the exact Laplace-Young branch (table law only) */
    CB_RUPTURE_WILLETT_UNEQUAL /* Willett 2000 for unequal spheres (rupture.c): eq. 2 at
                                * equal radii, within 7 % of the exact fold up to 10:1 */
} cb_rupture_rule;

/* What the force is while the spheres overlap (gap < 0). */
typedef enum cb_overlap_rule {
    CB_OVERLAP_CONTACT = 0, /* the law's value at gap 0: continuous (default, Richefeu eq. 10) */
    CB_OVERLAP_NONE         /* no capillary force in overlap (Gladkyy eq. 4): a jump at contact */
} cb_overlap_rule;

/* What happens outside the law's stated validity range (see cb_law_validity). */
typedef enum cb_validity_rule {
    CB_VALIDITY_EXTEND = 0, /* evaluate with the law's documented extension: finite, >= 0 */
    CB_VALIDITY_STRICT      /* return CB_ERR_OUT_OF_VALIDITY */
} cb_validity_rule;

struct cb_table; /* the tabulated exact solution, opaque */

#define CB_LAW_PARAMETERS 4 /* the most keywords of its own a law may have */

/* A law is a value: model, parameters and options, plus what is derived from them
 * once (cb_law_prepare). Fill it with cb_law_init, change it with cb_law_configure,
 * then call cb_law_prepare before the first force call.
 * One exception to "value": a prepared table law owns its table through a pointer. A
 * plain copy of it is a move: go on with one of the two (only it is prepared again,
 * configured or released; the other is not used again), as a std::vector of laws does.
 * A second independent table law is made with cb_law_init and cb_law_prepare of its own.
 * cb_law_init on a prepared table law leaks its table: release it first. */
typedef struct cb_law {
    cb_model model;
    double surface_tension;   /* gamma [N/m] */
    double contact_angle;     /* theta [rad], 0 <= theta < pi/2 */
    /* the values of the law's own keywords, in the order of its row's list (laws.h):
     * richefeu: [0] = c of Richefeu eq. 9 (default 0.9) */
    double parameters[CB_LAW_PARAMETERS];
    /* the bridge's viscous force (viscous.c; keywords viscosity, min_gap): eta [Pa s],
     * 0 = none (the default), and the smallest lubrication gap s_min [m] */
    double viscosity, viscous_min_gap;
    cb_rupture_rule rupture;
    cb_overlap_rule overlap;
    cb_validity_rule validity;
    /* derived by cb_law_prepare: */
    cb_rupture_rule rupture_in_use;
    double cos_theta, sin_theta;
    double rupture_factor;    /* 1 + theta/2 */
    void *data;               /* what the law's preparation allocated (the table law's
                               * table), else NULL; owned by the law */
    int prepared;
} cb_law;

/* Which radius a law scales lengths and volumes by. The sources differ and each law keeps its
 * own: R_h in Gladkyy & Schwarze 2014 eq. 1, R_g in Richefeu 2007 eqs. 4 and 14, the larger
 * radius in Soulie 2006. */
typedef enum cb_radius_reference {
    CB_RADIUS_HARMONIC = 0, /* R_h = 2 r1 r2 / (r1 + r2) (Derjaguin) */
    CB_RADIUS_GEOMETRIC,    /* R_g = sqrt(r1 r2) */
    CB_RADIUS_LARGE         /* max(r1, r2) */
} cb_radius_reference;

/* The stated validity range of a law, in the variables its source states it in.
 * A bound its source does not state is 0 (minimum) or HUGE_VAL (maximum). */
typedef struct cb_validity {
    double volume_min, volume_max;         /* V / R_ref^3 */
    double contact_angle_max;              /* [rad] */
    double size_ratio_max;                 /* R_large / R_small */
    cb_radius_reference radius;            /* R_ref */
    const char *source;                    /* where the range is stated */
} cb_validity;

/* The radius a reference names, for these two spheres. */
double cb_radius_of(cb_radius_reference reference, double r1, double r2);
const char *cb_radius_reference_name(cb_radius_reference reference);

/* Law names as the keyword parser spells them ("richefeu", "willett", "willett/reduced",
 * "rabinovich", "rabinovich/uncorrected", "weigert", "soulie", "table"). */
const char *cb_model_name(cb_model model);
/* All names, comma separated, for error messages. */
const char *cb_law_names(void);
cb_status cb_model_from_name(const char *name, cb_model *model);

/* 1 when the law's force is interpolated in a table the law builds (the table law), 0 when
 * it is a closed form; 0 for a value that is no model.  A property of the law's registry
 * row: the CLI's "cheapest closed-form law" reads it. */
int cb_model_tabulated(cb_model model);

/* A keyword of one law only, as its registry row lists it: cb_law_configure takes it for
 * that law and refuses it, by name, for every other.  The CLI's help and the engines'
 * keywords are made from these (LIGGGHTS spells one law name + "_" + name: richefeu_c). */
typedef struct cb_law_keyword {
    const char *name;         /* as cb_law_configure spells it */
    const char *description;  /* one line, for the help and for the message refusing it */
    const char *default_text; /* the value cb_law_init gives it, as a user would write it */
} cb_law_keyword;

/* The number of a law's own keywords (0 for a value that is no model), and the index-th of
 * them in its row's order (NULL unless 0 <= index < cb_law_keyword_count(model)). */
int cb_law_keyword_count(cb_model model);
const cb_law_keyword *cb_law_keyword_of(cb_model model, int index);

/* Defaults: rupture = law default, overlap = contact, validity = extend, each of the law's
 * own keywords its row's default_text (richefeu: c = 0.9). */
cb_status cb_law_init(cb_law *law, cb_model model, double surface_tension, double contact_angle);

/* Keyword interface shared by the CLI and the engine bindings. Keywords:
 *   gamma <N/m>                surface tension (> 0)
 *   theta <degrees>            contact angle, 0 <= theta < 90
 *   rupture lian|willett|willett/unequal|default
 *   overlap contact|none
 *   validity extend|strict
 *   viscosity <Pa s>           the liquid's viscosity for the bridge's viscous force (>= 0;
 *                              0, the default: none)
 *   min_gap <m>                the smallest lubrication gap, the roughness (> 0; needed
 *                              with viscosity > 0)
 * and each law's own keywords (cb_law_keyword_of; richefeu: c <value>, Richefeu's
 * constant, > 0): another law refuses one by name.
 * On error, msg names the keyword, the value and what is allowed. */
cb_status cb_law_configure(cb_law *law, const char *keyword, const char *value, cb_message *msg);

/* The law keywords one command line has given, for cb_law_configure_once: zero it at the
 * start of each command ({0}). */
typedef struct cb_keywords_given {
    unsigned mask;
} cb_keywords_given;

/* cb_law_configure for one keyword of a command line's list, refusing a keyword the list
 * has given already (CB_ERR_RANGE, msg names it): a repeated keyword is an error in the
 * CLI and in both engines, never "the last one wins". */
cb_status cb_law_configure_once(cb_law *law, cb_keywords_given *given, const char *keyword,
                                const char *value, cb_message *msg);

/* 1 when two laws give the same forces and rupture distances: the same model and
 * parameters, a default rupture rule taken as the rule it stands for (prepared or not). */
int cb_law_same(const cb_law *a, const cb_law *b);

/* Derive the per-law constants; for the table law, build its table (allocates).
 * Must be called after the last change and before any force call. */
cb_status cb_law_prepare(cb_law *law, cb_message *msg);
/* Free what cb_law_prepare allocated. Safe on any initialised law. */
void cb_law_release(cb_law *law);

cb_validity cb_law_validity(const cb_law *law);

/* The capillary force between spheres of radii r1, r2 holding a bridge of volume V at
 * this gap: 0 beyond the rupture distance, the overlap rule for gap < 0.
 * stiffness (may be NULL) receives dF/d(gap) [N/m] (<= 0 where F falls with the gap;
 * 0 in overlap and beyond rupture). */
cb_status cb_force(const cb_law *law, double r1, double r2, double volume, double gap,
                   double *force, double *stiffness);

/* The viscous force of a bridge (viscous.c): its damping coefficients [N s/m] at this gap,
 * normal (Pitois et al. 2000, the squeeze flow of a bridge of volume V) and tangential
 * (Goldman, Cox & Brenner 1967), the gap taken as max(gap, min_gap); the forces on sphere 1
 * are -normal * d(gap)/dt along the normal (away from sphere 2) and -tangential * v_t, v_t
 * its tangential velocity relative to sphere 2.  Both 0 when the law's viscosity is 0 or V
 * is 0.  CB_ERR_NOT_FINITE, CB_ERR_NEGATIVE (a radius <= 0, V < 0), CB_ERR_NULL. */
cb_status cb_viscous_damping(const cb_law *law, double r1, double r2, double gap,
                             double volume, double *normal, double *tangential);
/* Whether the law's viscous keywords go together (viscosity > 0 needs min_gap > 0);
 * cb_law_prepare calls it. */
cb_status cb_viscous_check(const cb_law *law, cb_message *msg);

/* The rupture distance of a bridge of volume V under the law's rupture rule. */
cb_status cb_rupture_distance(const cb_law *law, double r1, double r2, double volume,
                              double *distance);

/* The smallest volume whose rupture distance reaches this gap (0 for gap <= 0):
 * the inverse of cb_rupture_distance, used to decide which pairs may hold liquid. */
cb_status cb_rupture_volume(const cb_law *law, double r1, double r2, double gap,
                            double *volume);

/* An upper bound of |dF/d(gap)| over 0 <= gap <= rupture distance: the capillary
 * stiffness the engine's time-step check uses. */
cb_status cb_capillary_stiffness_bound(const cb_law *law, double r1, double r2, double volume,
                                       double *stiffness);

/* ------------------------------------------------------------- radii */

double cb_radius_harmonic(double r1, double r2);  /* 2 r1 r2 / (r1 + r2), Derjaguin; 2 r1 at
                                                   * a plane */
double cb_radius_geometric(double r1, double r2); /* sqrt(r1 r2) */

/* ------------------------------------------------------ sphere-plane pairs (walls) */

/* Surface 2 of a pair may be a plane, a wall: r2 = CB_PLANE (INFINITY, the limit of a
 * sphere of infinite radius), wherever a pair's radii are given: the force laws, the
 * rupture rules, the bridge state, the liquid protocols, the viscous force and the exact
 * solver.  r1 is always a sphere's, finite; r2 = -INFINITY or NaN is CB_ERR_NOT_FINITE.
 * A closed-form law has no sphere-plane form in its source (Richefeu 2007 and Gladkyy &
 * Schwarze 2014 treat sphere pairs only): it is evaluated as the Derjaguin-equivalent pair,
 * two spheres of radius 2 r1 (the same R_h = 2 r1, hence the same small-volume force
 * 2 pi gamma R_h cos(theta)); the table law tabulates the exact sphere-plane bridge.  How
 * far each is from the exact one: `capbridge report` (its sphere-plane column).
 * The wall holds no liquid: a sphere-plane bridge is the grain's liquid, and all of it
 * returns to the grain at rupture (cb_protocol2_release gives the plane no share). */
#define CB_PLANE INFINITY
static inline int cb_is_plane(double r2) { return r2 == INFINITY; }

/* The single contact angle a law is evaluated with for a sphere-plane bridge whose two
 * surfaces wet differently (grain angle, wall angle, each 0 <= angle < pi/2): the angle of
 * the mean cosine, acos((cos a + cos b) / 2), exact for the force at contact in the
 * small-volume limit (pi gamma R_h (cos a + cos b), Derjaguin) and within 1 % of the exact
 * two-angle force at contact for V/R_h^3 <= 1e-4; the rupture distance of two angles is
 * not a function of one angle (the exact one is shorter than either angle's at small
 * volumes): the report gives this rule's error.  NAN for an angle outside [0, pi/2). */
double cb_wall_contact_angle(double grain_angle, double wall_angle);

/* For an engine's pair loop: true only where the gap sqrt(rsq) - radsum, as the engine
 * computes it, is > 0, so that a dry pair can be skipped with no square root (a bridge
 * forms at gap <= 0, touching included): rsq above radsum^2 by more than the rounding of
 * the root, the square and the difference (3 ulp; 4 DBL_EPSILON is a safe bound). */
static inline int cb_certainly_apart(double rsq, double radsum)
{
    return rsq > radsum * radsum * (1.0 + 4.0 * DBL_EPSILON);
}

/* ----------------------------------------------------------- contact law */

/* The mechanical contact of two spheres, as Richefeu 2007 defines it (eqs. 1-3, 12): the
 * normal force f_n = f_n^e + f_n^d + f_n^c is elastic (eq. 2), damping (eq. 3) and the
 * capillary attraction (eq. 10, f_n^c < 0, cb_force above); here "contact force" is
 * f_n^e + f_n^d, the part a contact carries.  One definition for the engines' pair loops
 * (LAMMPS compute() and single()) and the CLI's pulloff: inline, it is the hot path. */
typedef enum cb_dashpot_rule {
    CB_DASHPOT_APPROACH = 0, /* Richefeu eq. 3: damping only while the spheres approach */
    CB_DASHPOT_BOTH,         /* a linear dashpot both ways (it may pull while they separate) */
    CB_DASHPOT_REPULSIVE     /* both ways, the contact force never attractive (Gladkyy 2014
                              * §2: "preventing undesirable attractive forces") */
} cb_dashpot_rule;

typedef struct cb_contact_law {
    double normal_stiffness;     /* k_n [N/m], >= 0 */
    double tangential_stiffness; /* k_t [N/m], >= 0 */
    double damping_rate;         /* alpha_n of eq. 3, 0 <= alpha_n <= 1 */
    double friction;             /* mu, >= 0 */
    cb_dashpot_rule dashpot;
    /* derived by cb_contact_law_init: */
    double damping_factor;       /* 2 alpha_n sqrt(k_n): times sqrt(m_eff), eq. 3 */
    double closing_floor;        /* the closing rate the dashpot sees is >= this: 0 or -inf */
    double force_floor;          /* the contact force is >= this: 0 (repulsive) or -inf */
} cb_contact_law;

/* Check and derive; on error msg names the coefficient and what is allowed. */
cb_status cb_contact_law_init(cb_contact_law *law, double normal_stiffness,
                              double tangential_stiffness, double damping_rate,
                              double friction, cb_dashpot_rule dashpot, cb_message *msg);

/* The contact force f_n^e + f_n^d (repulsive > 0) at this gap (< 0: in contact; else 0),
 * gap rate d(gap)/dt (< 0: approaching) and sqrt of the effective mass m1 m2/(m1 + m2):
 *   k_n (-gap) + 2 alpha_n sqrt(m k_n) max(-gap_rate, floor)      eqs. 2-3
 * (written without a branch on the rate: approach and separation alternate unpredictably). */
static inline double cb_contact_normal_force(const cb_contact_law *law, double gap,
                                             double gap_rate, double sqrt_effective_mass)
{
    if (!(gap < 0.0)) return 0.0;
    const double closing = -gap_rate > law->closing_floor ? -gap_rate : law->closing_floor;
    const double force = law->normal_stiffness * (-gap) +
                         law->damping_factor * sqrt_effective_mass * closing;
    return force > law->force_floor ? force : law->force_floor;
}

/* The Coulomb limit of eq. 12, mu (f_n - f_n^c), with eq. 1's f_n: mu (f_n^e + f_n^d), the
 * contact force alone.  The capillary attraction raises it only through the larger contact
 * force it causes (a pair held by its bridge alone slides at mu F_cap); a tensile contact
 * force (dashpot both) gives none. */
static inline double cb_contact_friction_limit(const cb_contact_law *law, double contact_force)
{
    return law->friction * (contact_force > 0.0 ? contact_force : 0.0);
}

/* The tangential spring under its Coulomb limit: force = -k_t displacement, held to
 * |force| <= limit.  Beyond it the force is scaled onto the limit and, when update is 1,
 * the displacement with it (the spring slides).  Returns 1 when sliding. */
static inline int cb_contact_tangential_force(const cb_contact_law *law, double limit,
                                              double displacement[3], double force[3],
                                              int update)
{
    const double k_t = law->tangential_stiffness;
    force[0] = -k_t * displacement[0];
    force[1] = -k_t * displacement[1];
    force[2] = -k_t * displacement[2];
    const double magnitude = sqrt(force[0] * force[0] + force[1] * force[1] + force[2] * force[2]);
    if (!(magnitude > limit)) return 0;
    const double scale = magnitude > 0.0 ? limit / magnitude : 0.0;
    if (update) {
        displacement[0] *= scale;
        displacement[1] *= scale;
        displacement[2] *= scale;
    }
    force[0] *= scale;
    force[1] *= scale;
    force[2] *= scale;
    return 1;
}

/* ------------------------------------------- the engines' checks, one rule each */

/* The radii one atom type has in a run (the smallest and the largest, > 0). */
typedef struct cb_radius_range {
    double min, max;
} cb_radius_range;

/* The engines' neighbor reach exceeds the largest rupture distance in use by this
 * fraction: the first step beyond a bridge's rupture distance must still visit the pair
 * (LIGGGHTS visits a pair only within its contact distance factor; the margin is the slack
 * a pair may move in one step). */
#define CB_REACH_MARGIN 0.05

/* The neighbor reach of bridges of up to `volume` between radii of these two ranges:
 * design_rupture, the largest rupture distance over a 5 x 5 grid of the two ranges (ends
 * included: every law's rupture rule but the table is monotone in each radius, and the
 * grid covers the table's), the law extended beyond its validity (a bridge that exists
 * must be kept whatever its radii); reach = design_rupture (1 + CB_REACH_MARGIN); and
 * reach_ratio, the largest reach / (r1 + r2) over the grid, for an engine whose neighbor
 * distance is a multiple of the radius sum (LIGGGHTS: contact_distance_factor =
 * 1 + reach_ratio).  range2 may be the plane {CB_PLANE, CB_PLANE} (a wall's bridges):
 * the grid then runs over range1 alone and reach_ratio is over r1 (LIGGGHTS visits a
 * grain-wall pair while its gap is below (contact_distance_factor - 1) r1).  All three 0
 * for volume 0.  Outputs may be NULL. */
cb_status cb_reach(const cb_law *law, cb_radius_range range1, cb_radius_range range2,
                   double volume, double *design_rupture, double *reach, double *reach_ratio);

/* The one behaviour of a bridge beyond the reach: a held bridge whose gap exceeds the
 * design rupture distance of the reach (a volume above the design volume, a grain that
 * grew) is ruptured now, its liquid released as at any rupture, before its pair can leave
 * the engine's neighbor list with it; the engine counts it and warns once. */
static inline int cb_bridge_beyond_reach(double gap, double design_rupture)
{
    return gap > design_rupture;
}

/* The bridge volume a liquid protocol's reach is built for when the user gives none:
 * the larger of twice the mean liquid per grain times (r_max / r_min)^3 (the Protocol 1
 * volume, eq. 14 V_b = alpha R_g^3, of a bridge between the largest grains with at least
 * one bridge per grain) and twice the largest free liquid of one grain (a Protocol 2
 * bridge takes the free liquid of both its grains). */
cb_status cb_protocol_design_volume(double total_liquid, double grains, cb_radius_range radii,
                                    double largest_free_liquid, double *volume);

/* The time step the engines warn above: Richefeu 2007 §2 sets it "10% below the elastic
 * response time pi sqrt(m/K_n)", which we read, as DEM practice does, as a tenth of it:
 * CB_TIMESTEP_FRACTION pi sqrt(m / k), m the smallest mass, k the larger of k_n and the
 * capillary stiffness bound (cb_capillary_stiffness_bound) at the corners of the two radius
 * ranges for each volume given (the smallest and the largest in use; law NULL or no
 * volumes: k_n alone).  *limit is HUGE_VAL when k is 0; *capillary_stiffness may be NULL. */
#define CB_TIMESTEP_FRACTION 0.1
cb_status cb_timestep_limit(const cb_law *law, cb_radius_range range1, cb_radius_range range2,
                            const double *volumes, size_t n_volumes, double smallest_mass,
                            double normal_stiffness, double *limit,
                            double *capillary_stiffness);

/* The time step the engines warn above for the bridge's viscous force (law keyword
 * viscosity): CB_TIMESTEP_FRACTION pi m / c, c the largest damping coefficient
 * (cb_viscous_damping at the law's min_gap) at the corners of the two radius ranges for each
 * volume given, the same margin against explicit integration's bound (dt < m/c for a damper
 * between two masses >= m) as cb_timestep_limit's against its own.  *limit is HUGE_VAL
 * without viscosity or volumes; *damping (may be NULL) receives c. */
cb_status cb_viscous_timestep_limit(const cb_law *law, cb_radius_range range1,
                                    cb_radius_range range2, const double *volumes,
                                    size_t n_volumes, double smallest_mass, double *limit,
                                    double *damping);

/* The widths of a periodic cell between opposite faces, from the upper-triangular inverse
 * h^-1 of its edge matrix in LAMMPS's (and LIGGGHTS's) order xx, yy, zz, yz, xz, xy:
 * 1 / |row k of h^-1| (orthogonal boxes: the edge lengths). */
void cb_cell_widths(const double inverse[6], double width[3]);
/* With bridges, every periodic width must be at least twice the neighbor cutoff: else two
 * atoms meet as two periodic images, each holding a copy of their bridge (liquid from
 * nothing).  Returns the first direction (0, 1, 2) that is too narrow, or -1. */
int cb_periodic_too_narrow(const double width[3], const int periodic[3], double cutoff);

/* -------------------------------------------------------- bridge state */

/* The state of the liquid bridge of one pair, kept by the engine in its pair history and
 * changed only by the calls below.  volume and active are the state; the other five are
 * derived from the volume, the two radii and the law whenever a bridge forms or its volume
 * is set (cb_bridge_set_volume), so that a bridge in contact costs no force-law evaluation
 * and a stretched one no rupture distance per step.  They are derived again by the calls
 * below when the radii differ from the ones stored (a grain that grows or shrinks); after
 * the law changes (new coefficients between two runs, a restart) the engine derives them
 * again with cb_bridge_set_volume(..., bridge->volume, ...).
 * Plain data: the engine may copy it as an array of CB_BRIDGE_DOUBLES doubles.  A dry
 * bridge is all zero. */
typedef struct cb_bridge {
    double volume;         /* liquid in the bridge [m^3]; 0 when there is no bridge */
    double active;         /* 1.0 while the bridge exists, 0.0 otherwise (a double for history) */
    double rupture;        /* rupture distance of this volume between these radii [m]; in a
                            * dry state 0, or CB_BRIDGE_REMOVED while the pair of a removed
                            * bridge (cb_bridge_remove) still overlaps */
    double force_contact;  /* the force at gap 0 [N] */
    double radius_sum;     /* r1 + r2 and r1 r2 of the radii the two above are for
                            * (INFINITY both at a plane, r2 = CB_PLANE) */
    double radius_product;
    double law_constant;   /* the constant the law keeps for a stretched bridge (finite,
                            * >= 0): richefeu's 1/lambda (eq. 11) [1/m], so that its force
                            * is force_contact exp(-gap/lambda); 0 for a law that keeps
                            * none and evaluates its force in full */
} cb_bridge;
#define CB_BRIDGE_DOUBLES 7
/* The mark of a dry pair whose bridge was removed and whose contact has not opened since:
 * it forms no bridge until its gap is >= 0 again (cb_bridge_remove). */
#define CB_BRIDGE_REMOVED (-1.0)

typedef enum cb_transition {
    CB_BRIDGE_STAYS_DRY = 0, /* no bridge before, none now */
    CB_BRIDGE_FORMED,        /* formed this step: contact and liquid available */
    CB_BRIDGE_HELD,          /* existed and still exists */
    CB_BRIDGE_RUPTURED       /* broke this step: its liquid is released */
} cb_transition;

/* Advance the bridge of a pair to this gap.
 * available_volume: the liquid a new bridge would receive if it formed now (the fixed
 *   volume, or what the protocol offers); a bridge forms only at contact (gap <= 0) and
 *   only when available_volume > 0.
 * On CB_BRIDGE_RUPTURED, *released_volume is the liquid the bridge held (else 0). */
cb_status cb_bridge_update(const cb_law *law, double r1, double r2, double gap,
                           double available_volume, cb_bridge *bridge,
                           cb_transition *transition, double *released_volume);

/* cb_bridge_update, then the capillary force of the bridge's new state at this gap (as
 * cb_bridge_force): the call of an engine's pair loop. */
cb_status cb_bridge_step(const cb_law *law, double r1, double r2, double gap,
                         double available_volume, cb_bridge *bridge, cb_transition *transition,
                         double *released_volume, double *force);

/* The capillary force of the bridge at this gap, without advancing it: equal to
 * cb_force(law, r1, r2, bridge->volume, gap) while it exists, else 0. */
cb_status cb_bridge_force(const cb_law *law, double r1, double r2, double gap,
                          const cb_bridge *bridge, double *force);

/* CB_OK when a stored state is one of the three shapes the calls above and below produce:
 * dry (all zero), dry and removed (all zero but rupture = CB_BRIDGE_REMOVED) or an active
 * bridge's (volume > 0, active 1, rupture > 0, contact force
 * >= 0, radii > 0, law constant >= 0, every one finite but a plane's radius sum and product,
 * INFINITY both); else CB_ERR_BRIDGE_STATE (a
 * corrupted pair history or restart file).  Every call above checks the state it is given
 * with it; an engine checks each stored state once where it enters (a restart file's pair
 * history at the first force pass of a run) before it uses cb_bridge_held. */
cb_status cb_bridge_check_state(const cb_bridge *bridge);

/* For an engine's pair loop, inline: a bridge that is held at this gap with no change of
 * state and whose force comes from its stored constants — what cb_bridge_step would do,
 * bit for bit, without the call (its validation and copies):
 *   - in contact (gap <= 0), any law: the stored force (cb_pair_force's overlap rule);
 *     the common case of a dense packing, where the call cost ~10 % of the benchmark
 *     scene's loop time;
 *   - stretched (0 < gap <= rupture distance), richefeu with its stored 1/lambda and a
 *     validity that is not strict: force_contact exp(-gap/lambda) (eq. 10).
 * Returns 1 and sets *force then; returns 0, touching nothing, where cb_bridge_step must
 * be called: no bridge, a bridge to rupture, a gap that is NaN or infinite, other radii,
 * another law's stretched bridge.  The state must be one cb_bridge_check_state accepts and
 * the law prepared: the caller checked the state once where it entered (every call here
 * keeps a valid state valid), so that the held path reads only the fields it uses.  Uses
 * exp(): the engine links libm. */
static inline int cb_bridge_held(const cb_law *law, double r1, double r2, double gap,
                                 const cb_bridge *bridge, double *force)
{
    /* the constants are for these radii; the gap is finite (NaN fails both tests below) */
    if (!(bridge->active == 1.0 && bridge->radius_sum == r1 + r2 &&
          bridge->radius_product == r1 * r2 && gap >= -DBL_MAX))
        return 0;
    if (gap <= 0.0) {
        /* Richefeu eq. 10 keeps the contact value in overlap; Gladkyy eq. 4 applies none */
        *force = gap < 0.0 && law->overlap == CB_OVERLAP_NONE ? 0.0 : bridge->force_contact;
        return 1;
    }
    /* Richefeu's stretched bridge inline, the one law here: it is the engines' default and
     * the call costs more than its one exp.  The product its row's bridge_force forms
     * (law_richefeu.c); a strict law checks its validity at every evaluation, so it takes
     * the call, as does every other law's stretched bridge (its own bridge_force). */
    if (gap <= bridge->rupture && bridge->law_constant > 0.0 &&
        law->model == CB_MODEL_RICHEFEU && law->validity != CB_VALIDITY_STRICT) {
        *force = bridge->force_contact * exp(-gap * bridge->law_constant);
        return 1;
    }
    return 0;
}

/* Dry and unmarked: a pair with nothing for cb_bridge_update to advance (an engine may skip
 * it while it is apart). */
static inline int cb_bridge_dry(const cb_bridge *bridge)
{
    return bridge->active == 0.0 && bridge->rupture == 0.0;
}

/* The pair of a removed bridge that still overlaps (cb_bridge_remove): it forms none, and
 * Protocol 1 gives it no liquid. */
static inline int cb_bridge_removed_in_contact(const cb_bridge *bridge, double gap)
{
    return bridge->active == 0.0 && bridge->rupture == CB_BRIDGE_REMOVED && gap < 0.0;
}

/* A dry pair at this gap that may form a bridge if liquid is offered: the candidates an
 * engine counts for Protocols 2 and 3.  At gap >= 0 a removed pair's mark is gone
 * (cb_bridge_update makes it plainly dry). */
static inline int cb_bridge_may_form(const cb_bridge *bridge, double gap)
{
    return bridge->active == 0.0 && gap <= 0.0 && !cb_bridge_removed_in_contact(bridge, gap);
}

/* Removing bridges (Richefeu 2007 §3.2, fig. 7, and §4.2.2, fig. 12: samples "with two
 * times less bonds ... obtained by removing half of the bonds", the water content kept).
 * cb_bridge_removal_chosen: whether the bridge between atoms id1 and id2 is among the
 * `fraction` (0..1) removed with this seed: a hash of (seed, the two ids in either order)
 * gives a number uniform in [0, 1) (splitmix64's finaliser, Steele, Lea & Flood 2014),
 * removed when it is below fraction.  The same pair gets the same draw on every rank, in
 * every engine and in any order, so the removed set does not depend on the decomposition,
 * and a larger fraction removes a superset.  CB_ERR_RANGE for a fraction outside [0, 1]
 * (or NaN) or id1 == id2; *chosen is then untouched.
 * cb_bridge_remove: the bridge is removed at this gap; its whole volume is released (the
 * engine hands it on as the liquid of a broken bridge under its protocol) and the pair
 * becomes dry, marked CB_BRIDGE_REMOVED while it overlaps (gap < 0), so that it does not
 * form a bridge again at the same contact: in a dense packing most bridges are in contact,
 * and every one would form again at once from the liquid it just released.  The mark goes
 * at the first update with gap >= 0: the contact has opened, and a new contact may form a
 * bridge as any other.  A dry state is left as it is (released 0). */
cb_status cb_bridge_removal_chosen(double fraction, unsigned long long seed, long long id1,
                                   long long id2, int *chosen);
cb_status cb_bridge_remove(double gap, cb_bridge *bridge, double *released_volume);

/* Set the bridge's volume (a liquid protocol moves liquid into or out of it) and derive
 * its constants for these radii and this law: volume 0 makes it dry.  Called with the
 * bridge's own volume, it derives them again after the law changed.  A volume the law
 * refuses (validity strict) is an error, and the bridge is left as it was. */
cb_status cb_bridge_set_volume(const cb_law *law, double r1, double r2, double volume,
                               cb_bridge *bridge);

/* ------------------------------------------------------ liquid protocols */

/* Protocol 2 (Richefeu 2007 §3.2): the liquid of a broken bridge is split between the
 * two particles in proportion to their diameters and kept as free liquid. Exact:
 * *free1 + *free2 grows by exactly `volume` up to one rounding. */
cb_status cb_protocol2_release(double volume, double r1, double r2, double *free1,
                               double *free2);
/* Protocol 2, formation: the new bridge takes all free liquid of both particles. */
cb_status cb_protocol2_take(double *free1, double *free2, double *bridge_volume);

/* Protocol 3 (Richefeu 2007 §4.2): each particle's share (in proportion to its diameter)
 * goes to its lowest contact on its lower hemisphere. Given the heights of the contact
 * points of one particle's bridges and the particle's centre height, return the index
 * of the receiving bridge in *index, or -1 when the particle has no bridge below its
 * centre (the share is then kept as the particle's free liquid). */
cb_status cb_protocol3_receiver(double centre_height, const double *contact_height, size_t n,
                                long *index);
/* Protocol 3, one bridge at a time (an engine meets a grain's bridges in no set order): 1
 * when a bridge whose contact point lies `offset` above the grain's centre (< 0: on the
 * lower hemisphere), to the grain of id `partner`, is a better receiver than the best so far
 * (best_partner 0: none yet).  Lower is better (cb_protocol3_receiver's rule); an equal
 * height goes to the smaller partner id, so that every rank and every order choose alike. */
int cb_protocol3_better(double offset, long long partner, double best_offset,
                        long long best_partner);

/* Protocols 2 and 3, one grain between the two phases of a step: the liquid its broken
 * bridges released this step goes to its Protocol 3 receiver (to_receiver 1: *deposit) or
 * to its free liquid; then, if `new_contacts` (k) dry pairs of it may form a bridge now, its
 * free liquid is offered to them in k equal parts (*offer each; *free_liquid 0): the whole
 * of it, Richefeu's "the new bridge takes it" with several new bridges at once.  The two
 * offers of a pair form its bridge (cb_protocol2_take).  Conserves liquid: deposit +
 * free + k offer = released + free before, up to the rounding of one division. */
cb_status cb_protocol_grain_step(double released, int to_receiver, double new_contacts,
                                 double *free_liquid, double *deposit, double *offer);

/* The share of a released volume that goes to particle 1 (diameter proportion);
 * 0 for invalid input (a non-finite or non-positive radius or volume). */
double cb_protocol_share(double volume, double r1, double r2);

/* Protocol 1 (Richefeu 2007 §2.4, eq. 14): V_b = alpha R_g^3 over every eligible pair,
 * alpha fixed by sum V_b = total liquid (eq. 13); a pair is eligible when its gap does
 * not exceed the rupture distance of the volume it would receive.
 * Input arrays of n pairs (r1, r2, gap); output volume[i] (0 for pairs left dry) and
 * alpha. Liquid is conserved: sum volume = total_liquid up to rounding.
 * Pairs are admitted in the order of the alpha at which they become eligible; when the
 * total falls in a jump of sum(alpha) (eqs. 13-14 have no exact solution), the pair at
 * the jump and every pair whose threshold lies between it and the alpha returned stay
 * dry, although eligible at that alpha (protocol1.c says why). CB_ERR_LIQUID when
 * liquid > 0 but no pair can hold it.
 * work: scratch of at least 2 n doubles and n size_t (caller-provided, no allocation). */
typedef struct cb_protocol1_work {
    double *threshold;  /* n */
    double *weight;     /* n */
    size_t *order;      /* n */
} cb_protocol1_work;
cb_status cb_protocol1_distribute(const cb_law *law, size_t n, const double *r1,
                                  const double *r2, const double *gap, double total_liquid,
                                  cb_protocol1_work work, double *volume, double *alpha);

/* --------------------------------------------- exact Laplace-Young solver */

/* An axisymmetric, gravity-free bridge between two spheres, or between a sphere and a
 * plane (r2 = INFINITY: the limit of a sphere 2 of infinite radius; a wall).
 * pressure is p_liquid - p_gas (negative: suction). The axial force is the first integral
 * F = 2 pi gamma y cos(phi) - pi y^2 pressure, evaluated at three places as a check. */
typedef struct cb_exact_bridge {
    double gap;
    double force;            /* attractive > 0 [N] (the value at the neck) */
    double force_contact1;   /* the same force at the contact line on sphere 1 */
    double force_contact2;   /* ... and on surface 2 (sphere 2 or the plane) */
    double filling_angle1;   /* delta_1 [rad] */
    double filling_angle2;   /* delta_2 [rad]; 0 on a plane */
    double contact_radius1;  /* radius of the contact line on sphere 1 [m], r1 sin delta_1 */
    double contact_radius2;  /* ... on surface 2 */
    double pressure;         /* p_liquid - p_gas [Pa] */
    double neck_radius;      /* smallest radius of the profile [m] */
    double volume;           /* volume recovered from the profile [m^3] */
} cb_exact_bridge;

typedef struct cb_exact_problem {
    double r1, r2;           /* radii [m]; r2 = INFINITY: surface 2 is a plane */
    double contact_angle1;   /* on sphere 1 [rad], 0 <= theta < pi/2 */
    double contact_angle2;   /* on surface 2 [rad], 0 <= theta < pi/2 */
    double surface_tension;  /* [N/m] */
    double volume;           /* [m^3] */
    int steps;               /* integration steps along the profile: 0 (the default,
                              * CB_EXACT_DEFAULT_STEPS) or CB_EXACT_MIN_STEPS to
                              * CB_EXACT_MAX_STEPS; else CB_ERR_RANGE */
} cb_exact_problem;
#define CB_EXACT_DEFAULT_STEPS 256
#define CB_EXACT_MIN_STEPS 16
#define CB_EXACT_MAX_STEPS 1000000

/* The bridge at one gap (0 <= gap <= rupture distance), on the branch connected to
 * gap = 0. CB_ERR_NO_BRIDGE beyond rupture.  CB_ERR_RANGE (for this and the two below)
 * where V / R_h^3 or the bridge in SI units (force, pressure, volume) leaves double range. */
cb_status cb_exact_solve(const cb_exact_problem *problem, double gap, cb_exact_bridge *bridge);

/* The rupture distance: the fold (largest gap) of that branch at fixed volume. */
cb_status cb_exact_rupture(const cb_exact_problem *problem, double *distance,
                           cb_exact_bridge *at_rupture);

/* n bridges at the given gaps (ascending, each within [0, rupture]), tracing the branch once. */
cb_status cb_exact_curve(const cb_exact_problem *problem, size_t n, const double *gaps,
                         cb_exact_bridge *bridges);

#ifdef __cplusplus
}
#endif

#endif /* CAPBRIDGE_H */
