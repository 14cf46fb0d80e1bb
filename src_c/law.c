/* law.c — a law as a value: the registry of the laws, names, keywords, preparation, and
 * the force dispatcher that applies the overlap, rupture and validity rules around each
 * law's formula.  Adding a law: its file with its row (cb_law_ops, laws.h) and one row of
 * CB_LAWS (capbridge.h), from which the registry below and cb_law_names are made;
 * tests/test_registry.c checks each row's name against its list entry.
 * What the CLI and the engines know of a law (its name, its own keywords, whether it is
 * tabulated) they read from its row through the functions below. */
#include "laws.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


#define CB_LAW_REGISTRY_ENTRY(value, row, name) [CB_MODEL_##value] = &cb_##row##_ops,
const cb_law_ops *const cb_law_registry[] = {CB_LAWS(CB_LAW_REGISTRY_ENTRY)};
#undef CB_LAW_REGISTRY_ENTRY
/* one row per cb_model (a row left out in the middle is NULL: test_registry finds it) */
typedef char registry_has_a_row_per_model[sizeof cb_law_registry / sizeof *cb_law_registry ==
                                                  CB_MODEL_COUNT ? 1 : -1];

/* The row of a model; NULL for a value that is no model. */
static const cb_law_ops *row_of(cb_model model)
{
    return model >= 0 && model < CB_MODEL_COUNT ? cb_law_registry[model] : NULL;
}

cb_status cb_fail(cb_message *msg, cb_status status, const char *format, ...)
{
    if (msg) {
        va_list args;
        va_start(args, format);
        vsnprintf(msg->text, sizeof msg->text, format, args);
        va_end(args);
    }
    return status;
}

const char *cb_model_name(cb_model model)
{
    return row_of(model) ? row_of(model)->name : "unknown";
}

/* ", richefeu, willett, ..." at compile time from the list, without its first ", " */
#define CB_LAW_LISTED_NAME(value, row, name) ", " name
const char *cb_law_names(void)
{
    static const char listed[] = CB_LAWS(CB_LAW_LISTED_NAME);
    return listed + 2;
}
#undef CB_LAW_LISTED_NAME

int cb_model_tabulated(cb_model model)
{
    return row_of(model) ? row_of(model)->tabulated : 0;
}

int cb_law_keyword_count(cb_model model)
{
    return row_of(model) ? row_of(model)->keyword_count : 0;
}

const cb_law_keyword *cb_law_keyword_of(cb_model model, int index)
{
    if (index < 0 || index >= cb_law_keyword_count(model)) return NULL;
    return &row_of(model)->keywords[index];
}

cb_status cb_model_from_name(const char *name, cb_model *model)
{
    if (!name || !model) return CB_ERR_NULL;
    for (int m = 0; m < CB_MODEL_COUNT; ++m) {
        if (strcmp(name, cb_law_registry[m]->name) == 0) {
            *model = (cb_model)m;
            return CB_OK;
        }
    }
    return CB_ERR_UNKNOWN_LAW;
}

static cb_status check_surface_tension(double gamma, cb_message *msg)
{
    if (!isfinite(gamma))
        return cb_fail(msg, CB_ERR_NOT_FINITE, "surface tension gamma must be finite");
    if (gamma <= 0.0)
        return cb_fail(msg, CB_ERR_NEGATIVE, "surface tension gamma = %g: must be > 0 (N/m)",
                       gamma);
    return CB_OK;
}

static cb_status check_contact_angle(double theta, cb_message *msg)
{
    if (!isfinite(theta))
        return cb_fail(msg, CB_ERR_NOT_FINITE, "contact angle theta must be finite");
    if (theta < 0.0 || theta >= 0.5 * CB_PI)
        return cb_fail(msg, CB_ERR_RANGE,
                       "contact angle theta = %g degrees: allowed 0 <= theta < 90 degrees",
                       theta * 180.0 / CB_PI);
    return CB_OK;
}

cb_status cb_law_init(cb_law *law, cb_model model, double surface_tension, double contact_angle)
{
    if (!law) return CB_ERR_NULL;
    if (!row_of(model)) return CB_ERR_UNKNOWN_LAW;
    cb_status status = check_surface_tension(surface_tension, NULL);
    if (status != CB_OK) return status;
    status = check_contact_angle(contact_angle, NULL);
    if (status != CB_OK) return status;
    memset(law, 0, sizeof *law);
    law->model = model;
    law->surface_tension = surface_tension;
    law->contact_angle = contact_angle;
    /* each default through the row's own reader, as a user's value (test_registry: each
     * default is read) */
    const cb_law_ops *ops = cb_law_registry[model];
    for (int k = 0; k < ops->keyword_count; ++k) {
        status = ops->set_keyword(law, k, ops->keywords[k].default_text, NULL);
        if (status != CB_OK) return status;
    }
    law->rupture = CB_RUPTURE_DEFAULT;
    law->overlap = CB_OVERLAP_CONTACT;
    law->validity = CB_VALIDITY_EXTEND;
    return CB_OK;
}

/* The keywords of every law (cb_law_configure), then each law's own (its row). */
static const char *const common_keywords[] = {"gamma",    "theta",     "rupture", "overlap",
                                              "validity", "viscosity", "min_gap"};
enum { COMMON_KEYWORDS = sizeof common_keywords / sizeof *common_keywords };

/* Any change leaves the law unprepared until cb_law_prepare derives it again. */
static cb_status apply_keyword(cb_law *law, const char *keyword, const char *value,
                               cb_message *msg);

cb_status cb_law_configure(cb_law *law, const char *keyword, const char *value, cb_message *msg)
{
    if (!law || !keyword) return cb_fail(msg, CB_ERR_NULL, "missing keyword");
    cb_status status = apply_keyword(law, keyword, value, msg);
    if (status == CB_OK) law->prepared = 0;
    return status;
}

cb_status cb_law_configure_once(cb_law *law, cb_keywords_given *given, const char *keyword,
                                const char *value, cb_message *msg)
{
    if (!law || !given || !keyword) return cb_fail(msg, CB_ERR_NULL, "missing keyword");
    unsigned bit = 0;
    for (unsigned k = 0; k < COMMON_KEYWORDS; ++k)
        if (strcmp(keyword, common_keywords[k]) == 0) bit = 1u << k;
    const cb_law_ops *ops = row_of(law->model);
    for (int k = 0; ops && k < ops->keyword_count; ++k)
        if (strcmp(keyword, ops->keywords[k].name) == 0) bit = 1u << (COMMON_KEYWORDS + k);
    if (given->mask & bit)
        return cb_fail(msg, CB_ERR_RANGE,
                       "keyword '%s' given twice: each law keyword may be given once", keyword);
    cb_status status = cb_law_configure(law, keyword, value, msg);
    if (status == CB_OK) given->mask |= bit;
    return status;
}

/* CB_RUPTURE_EXACT: the law's own rupture rule, for a law that has one. */
static int has_own_rupture(const cb_law *law)
{
    return row_of(law->model) && row_of(law->model)->own_rupture != NULL;
}

/* ", name" after a list of names */
static void append_name(char *list, size_t size, const char *name)
{
    size_t used = strlen(list);
    snprintf(list + used, size - used, ", %s", name);
}

/* A keyword that is none of every law's: the law's own (its row sets it), another law's
 * (refused by name), or unknown (the message lists them all). */
static cb_status law_keyword(cb_law *law, const char *keyword, const char *value,
                             cb_message *msg)
{
    const cb_law_ops *ops = row_of(law->model);
    for (int k = 0; ops && k < ops->keyword_count; ++k)
        if (strcmp(keyword, ops->keywords[k].name) == 0)
            return ops->set_keyword(law, k, value, msg);
    char allowed[320] = "gamma";
    for (unsigned k = 1; k < COMMON_KEYWORDS; ++k)
        append_name(allowed, sizeof allowed, common_keywords[k]);
    for (int m = 0; m < CB_MODEL_COUNT; ++m) {
        const cb_law_ops *other = cb_law_registry[m];
        for (int k = 0; k < other->keyword_count; ++k) {
            if (strcmp(keyword, other->keywords[k].name) == 0)
                return cb_fail(msg, CB_ERR_UNKNOWN_KEYWORD,
                               "keyword '%s' (%s) applies to law %s only, not to %s", keyword,
                               other->keywords[k].description, other->name,
                               cb_model_name(law->model));
            append_name(allowed, sizeof allowed, other->keywords[k].name);
        }
    }
    return cb_fail(msg, CB_ERR_UNKNOWN_KEYWORD, "unknown keyword '%s': allowed %s", keyword,
                   allowed);
}

static cb_status apply_keyword(cb_law *law, const char *keyword, const char *value,
                               cb_message *msg)
{
    if (!value) return cb_fail(msg, CB_ERR_RANGE, "keyword '%s' needs a value", keyword);
    double number = 0.0;
    int is_number = cb_parse_number(value, &number);

    if (strcmp(keyword, "gamma") == 0) {
        if (!is_number)
            return cb_fail(msg, CB_ERR_RANGE,
                           "gamma '%s' is not a decimal number within double range: give the "
                           "surface tension in N/m (> 0)",
                           value);
        cb_status status = check_surface_tension(number, msg);
        if (status == CB_OK) law->surface_tension = number;
        return status;
    }
    if (strcmp(keyword, "theta") == 0) {
        if (!is_number)
            return cb_fail(msg, CB_ERR_RANGE,
                           "theta '%s' is not a decimal number within double range: give the "
                           "contact angle in degrees, 0 <= theta < 90",
                           value);
        cb_status status = check_contact_angle(number * CB_PI / 180.0, msg);
        if (status == CB_OK) law->contact_angle = number * CB_PI / 180.0;
        return status;
    }
    if (strcmp(keyword, "rupture") == 0) {
        if (strcmp(value, "default") == 0) law->rupture = CB_RUPTURE_DEFAULT;
        else if (strcmp(value, "lian") == 0) law->rupture = CB_RUPTURE_LIAN;
        else if (strcmp(value, "willett") == 0) law->rupture = CB_RUPTURE_WILLETT;
        else if (strcmp(value, "willett/unequal") == 0) law->rupture = CB_RUPTURE_WILLETT_UNEQUAL;
        else if (strcmp(value, "exact") == 0 && has_own_rupture(law))
            law->rupture = CB_RUPTURE_EXACT;
        else
            return cb_fail(msg, CB_ERR_UNKNOWN_KEYWORD,
                           "rupture '%s': allowed lian, willett, willett/unequal, default%s", value,
                           has_own_rupture(law) ? ", exact" : "");
        return CB_OK;
    }
    if (strcmp(keyword, "overlap") == 0) {
        if (strcmp(value, "contact") == 0) law->overlap = CB_OVERLAP_CONTACT;
        else if (strcmp(value, "none") == 0) law->overlap = CB_OVERLAP_NONE;
        else
            return cb_fail(msg, CB_ERR_UNKNOWN_KEYWORD, "overlap '%s': allowed contact, none",
                           value);
        return CB_OK;
    }
    if (strcmp(keyword, "viscosity") == 0 || strcmp(keyword, "min_gap") == 0) {
        const int viscosity = keyword[0] == 'v';
        if (!is_number || !isfinite(number) || (viscosity ? number < 0.0 : !(number > 0.0)))
            return cb_fail(msg, CB_ERR_RANGE,
                           viscosity ? "viscosity '%s': give the liquid's viscosity in Pa s, "
                                       ">= 0 (0: no viscous force)"
                                     : "min_gap '%s': give the smallest lubrication gap (the "
                                       "roughness) as a length > 0",
                           value);
        if (viscosity) law->viscosity = number;
        else law->viscous_min_gap = number;
        return CB_OK;
    }
    if (strcmp(keyword, "validity") == 0) {
        if (strcmp(value, "extend") == 0) law->validity = CB_VALIDITY_EXTEND;
        else if (strcmp(value, "strict") == 0) law->validity = CB_VALIDITY_STRICT;
        else
            return cb_fail(msg, CB_ERR_UNKNOWN_KEYWORD,
                           "validity '%s': allowed extend, strict", value);
        return CB_OK;
    }
    return law_keyword(law, keyword, value, msg);
}

/* The rupture rule in use: a default one is the rule of the law's source (its row). */
static cb_rupture_rule rupture_rule(const cb_law *law)
{
    return law->rupture == CB_RUPTURE_DEFAULT ? cb_law_registry[law->model]->default_rupture
                                              : law->rupture;
}

int cb_law_same(const cb_law *a, const cb_law *b)
{
    if (!a || !b) return 0;
    const cb_law_ops *ops = row_of(a->model);
    if (a->model != b->model || !ops) return 0;
    for (int k = 0; k < ops->keyword_count; ++k)
        if (a->parameters[k] != b->parameters[k]) return 0;
    return a->surface_tension == b->surface_tension && a->contact_angle == b->contact_angle &&
           rupture_rule(a) == rupture_rule(b) && a->overlap == b->overlap &&
           a->validity == b->validity && a->viscosity == b->viscosity &&
           a->viscous_min_gap == b->viscous_min_gap;
}

cb_status cb_law_prepare(cb_law *law, cb_message *msg)
{
    if (!law) return cb_fail(msg, CB_ERR_NULL, "law is NULL");
    cb_status status = check_surface_tension(law->surface_tension, msg);
    if (status != CB_OK) return status;
    status = check_contact_angle(law->contact_angle, msg);
    if (status != CB_OK) return status;
    if (!row_of(law->model))
        return cb_fail(msg, CB_ERR_UNKNOWN_LAW, "unknown law: allowed %s", cb_law_names());
    if (law->rupture == CB_RUPTURE_EXACT && !has_own_rupture(law))
        return cb_fail(msg, CB_ERR_UNKNOWN_KEYWORD,
                       "rupture exact is available for the table law only");
    status = cb_viscous_check(law, msg);
    if (status != CB_OK) return status;

    law->rupture_in_use = rupture_rule(law);
    law->cos_theta = cos(law->contact_angle);
    law->sin_theta = sin(law->contact_angle);
    law->rupture_factor = 1.0 + 0.5 * law->contact_angle; /* (1 + theta/2), theta in rad */

    law->prepared = 0;
    const cb_law_ops *ops = cb_law_registry[law->model];
    if (ops->prepare) {
        status = ops->prepare(law, msg);
        if (status != CB_OK) return status;
    }
    law->prepared = 1;
    return CB_OK;
}

void cb_law_release(cb_law *law)
{
    if (!law) return;
    const cb_law_ops *ops = row_of(law->model);
    if (ops && ops->release) ops->release(law);
    law->prepared = 0;
}

cb_validity cb_law_validity(const cb_law *law)
{
    return cb_law_ops_of(law)->validity(law);
}

void cb_pair_geometry(const cb_law *law, double r1, double r2, double volume, cb_pair *pair)
{
    const cb_law_ops *ops = cb_law_ops_of(law);
    pair->plane = cb_is_plane(r2);
    if (pair->plane && !ops->plane) /* the Derjaguin-equivalent pair (capbridge.h) */
        r1 = r2 = 2.0 * r1;
    pair->r1 = r1;
    pair->r2 = r2;
    pair->r_small = r1 < r2 ? r1 : r2;
    pair->r_large = r1 < r2 ? r2 : r1;
    pair->r_harmonic = cb_radius_harmonic(r1, r2);
    pair->r_geometric = cb_radius_geometric(r1, r2);
    pair->volume = volume;
}

void cb_pair_make(const cb_law *law, double r1, double r2, double volume, cb_pair *pair)
{
    const cb_law_ops *ops = cb_law_ops_of(law);
    cb_pair_geometry(law, r1, r2, volume, pair);
    if (ops->locate) ops->locate(law, pair);
}

static cb_status check_pair(const cb_law *law, double r1, double r2, double volume)
{
    if (!law) return CB_ERR_NULL;
    if (!law->prepared) return CB_ERR_RANGE;
    if (!isfinite(r1) || !cb_finite_or_plane(r2) || !isfinite(volume))
        return CB_ERR_NOT_FINITE;
    if (r1 <= 0.0 || r2 <= 0.0 || volume <= 0.0) return CB_ERR_NEGATIVE;
    return CB_OK;
}

static int inside_validity(const cb_law *law, const cb_pair *pair)
{
    cb_validity v = cb_law_validity(law);
    /* the pair's own conventions: at a plane those of the pair the law evaluates */
    double r_ref = v.radius == CB_RADIUS_GEOMETRIC ? pair->r_geometric
                   : v.radius == CB_RADIUS_LARGE   ? pair->r_large
                                                   : pair->r_harmonic;
    double scaled_volume = pair->volume / (r_ref * r_ref * r_ref);
    return scaled_volume >= v.volume_min && scaled_volume <= v.volume_max &&
           law->contact_angle <= v.contact_angle_max &&
           pair->r_large / pair->r_small <= v.size_ratio_max;
}

static double rupture_of(const cb_law *law, const cb_pair *pair)
{
    switch (law->rupture_in_use) {
    case CB_RUPTURE_LIAN: return cb_rupture_lian(law, pair);
    case CB_RUPTURE_WILLETT: return cb_rupture_willett(law, pair);
    case CB_RUPTURE_WILLETT_UNEQUAL: return cb_rupture_willett_unequal(law, pair);
    case CB_RUPTURE_EXACT: return cb_law_ops_of(law)->own_rupture(law, pair);
    case CB_RUPTURE_DEFAULT: break; /* never in use: cb_law_prepare resolves it */
    }
    return NAN; /* refused by the caller as out of range */
}

cb_status cb_pair_rupture(const cb_law *law, const cb_pair *pair, double *rupture)
{
    if (law->validity == CB_VALIDITY_STRICT && !inside_validity(law, pair))
        return CB_ERR_OUT_OF_VALIDITY;
    double d = rupture_of(law, pair);
    if (!(isfinite(d) && d > 0.0)) return CB_ERR_RANGE; /* scales beyond double range */
    *rupture = d;
    return CB_OK;
}

cb_status cb_rupture_distance(const cb_law *law, double r1, double r2, double volume,
                              double *distance)
{
    cb_status status = check_pair(law, r1, r2, volume);
    if (status != CB_OK) return status;
    if (!distance) return CB_ERR_NULL;
    cb_pair pair;
    cb_pair_make(law, r1, r2, volume, &pair);
    return cb_pair_rupture(law, &pair, distance);
}

cb_status cb_rupture_volume(const cb_law *law, double r1, double r2, double gap, double *volume)
{
    if (!law || !volume) return CB_ERR_NULL;
    if (!law->prepared) return CB_ERR_RANGE;
    if (!isfinite(r1) || !cb_finite_or_plane(r2) || !isfinite(gap)) return CB_ERR_NOT_FINITE;
    if (r1 <= 0.0 || r2 <= 0.0) return CB_ERR_NEGATIVE;
    if (gap <= 0.0) {
        *volume = 0.0;
        return CB_OK;
    }
    cb_pair pair;
    cb_pair_make(law, r1, r2, 0.0, &pair);
    double v = NAN; /* refused below if no rule gives it */
    switch (law->rupture_in_use) {
    case CB_RUPTURE_LIAN: v = cb_rupture_volume_lian(law, &pair, gap); break;
    case CB_RUPTURE_WILLETT: v = cb_rupture_volume_willett(law, &pair, gap); break;
    case CB_RUPTURE_WILLETT_UNEQUAL: v = cb_rupture_volume_willett_unequal(law, &pair, gap); break;
    case CB_RUPTURE_EXACT: v = cb_law_ops_of(law)->own_rupture_volume(law, &pair, gap); break;
    case CB_RUPTURE_DEFAULT: break; /* never in use: cb_law_prepare resolves it */
    }
    if (!isfinite(v)) return CB_ERR_RANGE;
    *volume = v;
    return CB_OK;
}

cb_status cb_pair_force(const cb_law *law, const cb_pair *pair, double rupture, double gap,
                        double *force, double *stiffness)
{
    cb_status status = CB_OK;
    if (law->validity == CB_VALIDITY_STRICT && !inside_validity(law, pair))
        return CB_ERR_OUT_OF_VALIDITY;
    /* The rupture distance (> 0) matters only for a stretched bridge: a bridge in contact
     * or overlap never needs its root (the common case of a dense packing). */
    if (gap > 0.0 && !(rupture > 0.0)) {
        status = cb_pair_rupture(law, pair, &rupture);
        if (status != CB_OK) return status;
    }
    double f = 0.0, df = 0.0;
    if (gap < 0.0) {
        /* Overlap: Richefeu eq. 10 keeps the contact value (continuous); Gladkyy eq. 4
         * applies no capillary force in mechanical contact. */
        if (law->overlap == CB_OVERLAP_CONTACT) {
            status = cb_law_ops_of(law)->force(law, pair, 0.0, &f, &df);
            df = 0.0;
        }
    } else if (gap == 0.0 || gap <= rupture) {
        status = cb_law_ops_of(law)->force(law, pair, gap, &f, &df);
    }
    if (status != CB_OK) return status;
    /* a stiffness out of double range fails only a call that asks for it */
    if (!isfinite(f) || f < 0.0 || (stiffness && !isfinite(df))) return CB_ERR_RANGE;
    *force = f;
    if (stiffness) *stiffness = df;
    return CB_OK;
}

double cb_no_bridge_constant(const cb_law *law, const cb_pair *pair)
{
    (void)law;
    (void)pair;
    return 0.0;
}

cb_status cb_bridge_force_in_full(const cb_law *law, const cb_pair *pair,
                                  const cb_bridge *bridge, double gap, double *force)
{
    (void)bridge;
    const cb_law_ops *ops = cb_law_ops_of(law);
    double stiffness = 0.0;
    if (!ops->locate) return ops->force(law, pair, gap, force, &stiffness);
    cb_pair located = *pair;
    ops->locate(law, &located);
    return ops->force(law, &located, gap, force, &stiffness);
}

cb_status cb_pair_bridge_force(const cb_law *law, const cb_pair *pair, const cb_bridge *bridge,
                               double gap, double *force)
{
    if (!(gap > 0.0 && gap <= bridge->rupture)) {
        const cb_law_ops *ops = cb_law_ops_of(law);
        if (!ops->locate) return cb_pair_force(law, pair, bridge->rupture, gap, force, NULL);
        cb_pair located = *pair;
        ops->locate(law, &located);
        return cb_pair_force(law, &located, bridge->rupture, gap, force, NULL);
    }
    if (law->validity == CB_VALIDITY_STRICT && !inside_validity(law, pair))
        return CB_ERR_OUT_OF_VALIDITY;
    double f = 0.0;
    cb_status status = cb_law_ops_of(law)->bridge_force(law, pair, bridge, gap, &f);
    if (status != CB_OK) return status;
    if (!isfinite(f) || f < 0.0) return CB_ERR_RANGE;
    *force = f;
    return CB_OK;
}

cb_status cb_force(const cb_law *law, double r1, double r2, double volume, double gap,
                   double *force, double *stiffness)
{
    cb_status status = check_pair(law, r1, r2, volume);
    if (status != CB_OK) return status;
    if (!force) return CB_ERR_NULL;
    if (!isfinite(gap)) return CB_ERR_NOT_FINITE;
    cb_pair pair;
    cb_pair_make(law, r1, r2, volume, &pair);
    return cb_pair_force(law, &pair, 0.0, gap, force, stiffness);
}

/* |dF/dgap| at gap = rupture t^2 (0 where the law has no bridge). */
static cb_status stiffness_at(const cb_law *law, double r1, double r2, double volume,
                             double rupture, double t, double *magnitude)
{
    double f = 0.0, df = 0.0;
    cb_status status = cb_force(law, r1, r2, volume, rupture * t * t, &f, &df);
    if (status == CB_ERR_NO_BRIDGE) {
        *magnitude = 0.0;
        return CB_OK;
    }
    *magnitude = fabs(df);
    return status;
}

/* |dF/dgap| at the edge of the gaps where a law has a bridge, between t_in (a bridge) and
 * t_out (none), found by bisection: the strict Weigert law has none where its arcsin
 * argument passes 1, and its force falls steepest into that edge. */
static cb_status edge_stiffness(const cb_law *law, double r1, double r2, double volume,
                                double rupture, double t_in, double t_out, double *magnitude)
{
    for (int k = 0; k < 64; ++k) {
        double mid = 0.5 * (t_in + t_out), f = 0.0, df = 0.0;
        cb_status status = cb_force(law, r1, r2, volume, rupture * mid * mid, &f, &df);
        if (status == CB_ERR_NO_BRIDGE) t_out = mid;
        else if (status == CB_OK) t_in = mid;
        else return status;
    }
    return stiffness_at(law, r1, r2, volume, rupture, t_in, magnitude);
}

/* The bound's sample points in t = sqrt(gap / rupture), ascending: 0, then 8^-k down the
 * whole double range (a law's steepest point can sit at a gap many decades below the
 * rupture distance far outside its validity: Willett's at V/R^3 = 1e300, the fuzzer found),
 * then i / BOUND_UNIFORM, clustered towards contact in the gap. */
enum { BOUND_GEOMETRIC = 170, BOUND_UNIFORM = 128 };
enum { BOUND_SAMPLES = 1 + BOUND_GEOMETRIC + BOUND_UNIFORM };

static double bound_sample(int i)
{
    if (i == 0) return 0.0;
    if (i <= BOUND_GEOMETRIC) return ldexp(1.0, -3 * (BOUND_GEOMETRIC + 3 - i));
    return (double)(i - BOUND_GEOMETRIC) / BOUND_UNIFORM;
}

cb_status cb_capillary_stiffness_bound(const cb_law *law, double r1, double r2, double volume,
                                       double *stiffness)
{
    /* The closed-form laws' dF/dgap is smooth where they have a bridge; its largest
     * magnitude is sampled (bound_sample). Some laws (Willett's two, Weigert) are steepest at an
     * interior gap, which the samples can miss by ~1%: the best sample's bracket is then
     * refined by golden section, an edge of the gaps with a bridge (Weigert's) by
     * bisection, and the result raised by 1e-9 for the rounding of the maximum between the
     * points evaluated. */
    enum { REFINE = 60 };
    if (!stiffness) return CB_ERR_NULL;
    double rupture = 0.0;
    cb_status status = cb_rupture_distance(law, r1, r2, volume, &rupture);
    if (status != CB_OK) return status;
    const cb_law_ops *ops = cb_law_ops_of(law);
    if (ops->stiffness_bound) {
        /* the law's own (the table law's, from its interpolant cell by cell: its steepest
         * point, in the half cell before the fold, falls between any samples of the gap) */
        cb_pair pair;
        cb_pair_make(law, r1, r2, volume, &pair);
        double bound = ops->stiffness_bound(law, &pair);
        if (!isfinite(bound)) return CB_ERR_RANGE;
        *stiffness = bound;
        return CB_OK;
    }
    double largest = 0.0;
    int best = 0;
    int had_bridge = 0;
    for (int i = 0; i < BOUND_SAMPLES; ++i) {
        double magnitude = 0.0, f = 0.0;
        status = cb_force(law, r1, r2, volume, rupture * bound_sample(i) * bound_sample(i), &f,
                          &magnitude);
        int has_bridge = status != CB_ERR_NO_BRIDGE;
        if (!has_bridge) magnitude = 0.0;
        else if (status != CB_OK) return status;
        magnitude = fabs(magnitude);
        if (magnitude > largest) {
            largest = magnitude;
            best = i;
        }
        if (i > 0 && has_bridge != had_bridge) {
            double edge = 0.0;
            status = edge_stiffness(law, r1, r2, volume, rupture,
                                    bound_sample(has_bridge ? i : i - 1),
                                    bound_sample(has_bridge ? i - 1 : i), &edge);
            if (status != CB_OK) return status;
            largest = fmax(largest, edge);
        }
        had_bridge = has_bridge;
    }
    const double golden = 0.61803398874989485;
    double lo = bound_sample(best > 0 ? best - 1 : 0);
    double hi = bound_sample(best < BOUND_SAMPLES - 1 ? best + 1 : BOUND_SAMPLES - 1);
    double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo), fa = 0.0, fb = 0.0;
    if ((status = stiffness_at(law, r1, r2, volume, rupture, a, &fa)) != CB_OK) return status;
    if ((status = stiffness_at(law, r1, r2, volume, rupture, b, &fb)) != CB_OK) return status;
    for (int k = 0; k < REFINE; ++k) {
        if (fa > largest) largest = fa;
        if (fb > largest) largest = fb;
        if (fa >= fb) {
            hi = b;
            b = a;
            fb = fa;
            a = hi - golden * (hi - lo);
            status = stiffness_at(law, r1, r2, volume, rupture, a, &fa);
        } else {
            lo = a;
            a = b;
            fa = fb;
            b = lo + golden * (hi - lo);
            status = stiffness_at(law, r1, r2, volume, rupture, b, &fb);
        }
        if (status != CB_OK) return status;
    }
    if (fa > largest) largest = fa;
    if (fb > largest) largest = fb;
    *stiffness = largest * (1.0 + 1e-9);
    return CB_OK;
}
