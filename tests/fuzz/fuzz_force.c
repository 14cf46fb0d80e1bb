/* fuzz_force.c — libFuzzer target over the force API.
 * The first byte picks one of three checks, the rest become a law and its inputs:
 *  (a) the table law's last cell before the fold: one table law, prepared once at
 *      theta = 0.3 rad, at radii and volumes in and around its domain and gaps concentrated
 *      next to its rupture distance (where its stiffness peaks): force finite and >= 0,
 *      stiffness finite and within cb_capillary_stiffness_bound;
 *  (b) every law (the closed-form ones prepared per input, the table law from (a)) on raw
 *      doubles (NaN, infinities, negatives, extreme magnitudes) and on in-domain pairs: no
 *      crash; on CB_OK the force finite and >= 0, the rupture distance finite and > 0, the
 *      force zero beyond it, and |dF/dgap| within cb_capillary_stiffness_bound;
 *  (c) cb_bridge_held against cb_bridge_step: a bridge state of 7 doubles (raw, or a valid
 *      one with one field overwritten) and a gap.  A state the engines' entry check
 *      (cb_bridge_check_state) refuses, cb_bridge_step refuses too, touching nothing, and
 *      an overwritten field outside its range is refused; for a state the check accepts
 *      (the only ones an engine gives cb_bridge_held), where cb_bridge_held returns 1,
 *      cb_bridge_step on a copy returns CB_OK, the transition HELD and the same force bit
 *      for bit, and cb_bridge_held has left the state as it was. */
#include "capbridge.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

typedef struct input {
    const uint8_t *data;
    size_t size;
} input;

static double take_double(input *in)
{
    double value = 0.0;
    if (in->size >= sizeof value) {
        memcpy(&value, in->data, sizeof value);
        in->data += sizeof value;
        in->size -= sizeof value;
    }
    return value;
}

static uint8_t take_byte(input *in)
{
    uint8_t value = 0;
    if (in->size >= 1) {
        value = *in->data;
        in->data += 1;
        in->size -= 1;
    }
    return value;
}

/* 8 bytes as a number in [0, 1): the fuzzer steers it smoothly, NaN never comes out. */
static double take_unit(input *in)
{
    uint64_t bits = 0;
    if (in->size >= sizeof bits) {
        memcpy(&bits, in->data, sizeof bits);
        in->data += sizeof bits;
        in->size -= sizeof bits;
    }
    return (double)(bits >> 11) * 0x1.0p-53;
}

/* The table law of (a), built once (its preparation is ~10^4 exact solves). */
static const cb_law *table_law(void)
{
    static cb_law law;
    static int ready = 0;
    if (!ready) {
        cb_message msg;
        if (cb_law_init(&law, CB_MODEL_TABLE, 0.0728, 0.3) != CB_OK ||
            cb_law_prepare(&law, &msg) != CB_OK)
            abort();
        ready = 1;
    }
    return &law;
}

/* A pair in and around the table's domain: R_small 1e-6..1e-2 m, size ratio 1..12.6,
 * V/R_h^3 from 10^-5.5 to 10^-0.8. */
static void take_pair(input *in, double *r1, double *r2, double *volume)
{
    *r1 = 1e-6 * pow(10.0, 4.0 * take_unit(in));
    *r2 = *r1 * pow(10.0, 1.1 * take_unit(in));
    double rh = cb_radius_harmonic(*r1, *r2);
    *volume = pow(10.0, -5.5 + 4.7 * take_unit(in)) * rh * rh * rh;
    if (take_byte(in) & 1) { /* the radii either way round */
        double r = *r1;
        *r1 = *r2;
        *r2 = r;
    }
}

/* On CB_OK of cb_force: the force finite and >= 0, the stiffness finite, and (if asked)
 * within the stiffness bound when that is CB_OK. */
static void check_force(const cb_law *law, double r1, double r2, double volume, double gap,
                        int against_bound)
{
    double force = -1.0, stiffness = 0.0, bound = -1.0;
    cb_status status = cb_force(law, r1, r2, volume, gap, &force, &stiffness);
    if (status != CB_OK) return;
    if (!isfinite(force) || force < 0.0 || !isfinite(stiffness)) abort();
    if (against_bound && cb_capillary_stiffness_bound(law, r1, r2, volume, &bound) == CB_OK &&
        !(fabs(stiffness) <= bound))
        abort();
}

/* (a) gaps at the table's fold: 1 - gap/rupture = u^8 / 20 (mostly far below the last half
 * cell, 1 - gap/rupture < 2.4e-4), or exactly the rupture distance, or one ulp either side. */
static void fuzz_table_fold(input *in)
{
    const cb_law *law = table_law();
    double r1, r2, volume, rupture = 0.0;
    take_pair(in, &r1, &r2, &volume);
    uint8_t where = take_byte(in);
    double u = take_unit(in), u2 = u * u, u4 = u2 * u2;
    if (cb_rupture_distance(law, r1, r2, volume, &rupture) != CB_OK) abort();
    double gap = rupture * (1.0 - 0.05 * u4 * u4);
    if (where % 4 == 1) gap = rupture;
    if (where % 4 == 2) gap = nextafter(rupture, 0.0);
    if (where % 4 == 3) gap = nextafter(rupture, INFINITY);
    check_force(law, r1, r2, volume, gap, 1);
}

/* A law of every model, its options from a byte; the table law keeps its one table. */
static int make_law(uint8_t model_byte, uint8_t options, input *in, cb_law *law)
{
    cb_model model = (cb_model)(model_byte % CB_MODEL_COUNT);
    cb_message msg;
    if (model == CB_MODEL_TABLE) {
        *law = *table_law(); /* shares the table: configured and prepared again, never freed */
    } else {
        double theta = take_double(in), gamma = take_double(in);
        if (options & 8) { /* in range, so that the checks below run */
            theta = 1.5 * take_unit(in);
            gamma = 1e-3 + take_unit(in);
        }
        if (cb_law_init(law, model, gamma, theta) != CB_OK) return 0;
    }
    cb_law_configure(law, "overlap", (options & 1) ? "none" : "contact", &msg);
    cb_law_configure(law, "validity", (options & 2) ? "strict" : "extend", &msg);
    cb_law_configure(law, "rupture", (options & 4) ? "lian" : "default", &msg);
    if (cb_law_prepare(law, &msg) != CB_OK) abort();
    return 1;
}

static void release_law(cb_law *law)
{
    if (law->model != CB_MODEL_TABLE) cb_law_release(law);
}

/* A pair over a wide physical range for (b): radii 1e-9..1 m, size ratio 1..1000,
 * V/R_h^3 1e-12..1e3. */
static void take_wide_pair(input *in, double *r1, double *r2, double *volume)
{
    *r1 = 1e-9 * pow(10.0, 9.0 * take_unit(in));
    *r2 = *r1 * pow(10.0, 3.0 * take_unit(in));
    double rh = cb_radius_harmonic(*r1, *r2);
    *volume = pow(10.0, -12.0 + 15.0 * take_unit(in)) * rh * rh * rh;
}

/* (b) raw inputs (the force's checks) and wide-range pairs (also the bound) for every
 * law. Far outside any law's range (V/R^3 ~ 1e300, radii 1e-115 m, gamma 1e-231 N/m: raw
 * doubles) the closed-form laws' steepest point can sit between the bound's samples. */
static void fuzz_every_law(uint8_t model_byte, input *in)
{
    uint8_t options = take_byte(in);
    cb_law law;
    if (!make_law(model_byte, options, in, &law)) return;
    double r1 = take_double(in), r2 = take_double(in), volume = take_double(in);
    double gap = take_double(in);
    int wide = options & 16;
    if (wide) {
        take_wide_pair(in, &r1, &r2, &volume);
        double rupture = 0.0, u = take_unit(in);
        if (cb_rupture_distance(&law, r1, r2, volume, &rupture) == CB_OK)
            gap = rupture * ((options & 32) ? u * u * u : 1.0 - u * u * u);
    }
    check_force(&law, r1, r2, volume, gap,
                law.model == CB_MODEL_TABLE || (wide && (options & 8)));
    double rupture = 0.0, force = 0.0;
    if (cb_rupture_distance(&law, r1, r2, volume, &rupture) == CB_OK) {
        if (!isfinite(rupture) || rupture <= 0.0) abort();
        if (rupture < 1e300 && cb_force(&law, r1, r2, volume, rupture * 1.5 + 1e-300, &force,
                                         NULL) == CB_OK && force != 0.0)
            abort();
    }
    double bound = 0.0;
    if (cb_capillary_stiffness_bound(&law, r1, r2, volume, &bound) == CB_OK &&
        (!isfinite(bound) || bound < 0.0))
        abort();
    release_law(&law);
}

/* (c): a value outside the range of field k of an active bridge's state (volume, active,
 * rupture, contact force, radius sum, radius product, law constant; capbridge.h). */
static int out_of_range(int k, double value)
{
    if (k == 1) return value != 1.0;
    if (!(value <= DBL_MAX)) return 1; /* NaN, +inf */
    return (k == 3 || k == 6) ? !(value >= 0.0) : !(value > 0.0);
}

/* (c) cb_bridge_held agrees with cb_bridge_step wherever it answers, on every state the
 * entry check accepts; the check refuses what cb_bridge_step refuses. */
static void fuzz_bridge_held(uint8_t model_byte, input *in)
{
    uint8_t options = take_byte(in), corrupt = take_byte(in);
    cb_law law;
    if (!make_law(model_byte, options, in, &law)) return;
    double r1 = take_double(in), r2 = take_double(in), raw[CB_BRIDGE_DOUBLES];
    for (int i = 0; i < CB_BRIDGE_DOUBLES; ++i) raw[i] = take_double(in);
    double gap = take_double(in);
    cb_bridge bridge;
    memcpy(&bridge, raw, sizeof bridge);
    if (options & 16) { /* a valid bridge, one field then overwritten (or none) */
        double volume;
        take_pair(in, &r1, &r2, &volume);
        if (cb_bridge_set_volume(&law, r1, r2, volume, &bridge) != CB_OK) {
            release_law(&law);
            return;
        }
        double fields[CB_BRIDGE_DOUBLES];
        memcpy(fields, &bridge, sizeof fields);
        const int field = corrupt % 8, was_active = bridge.active == 1.0;
        if (field < CB_BRIDGE_DOUBLES) fields[field] = raw[0];
        memcpy(&bridge, fields, sizeof bridge);
        if (was_active && field < CB_BRIDGE_DOUBLES && out_of_range(field, raw[0]) &&
            cb_bridge_check_state(&bridge) != CB_ERR_BRIDGE_STATE)
            abort();
        if (options & 32) gap = bridge.rupture * (2.0 * take_unit(in) - 0.5);
    }
    cb_bridge before = bridge, copy = bridge;
    double held = 0.0, stepped = 0.0, released = 0.0;
    cb_transition transition = CB_BRIDGE_STAYS_DRY;
    if (cb_bridge_check_state(&bridge) != CB_OK) {
        if (cb_bridge_step(&law, r1, r2, gap, 0.0, &copy, &transition, &released, &stepped) ==
                CB_OK ||
            memcmp(&before, &copy, sizeof copy) != 0)
            abort();
    } else if (cb_bridge_held(&law, r1, r2, gap, &bridge, &held)) {
        if (memcmp(&before, &bridge, sizeof bridge) != 0) abort();
        if (cb_bridge_step(&law, r1, r2, gap, 0.0, &copy, &transition, &released, &stepped) !=
                CB_OK ||
            transition != CB_BRIDGE_HELD || memcmp(&held, &stepped, sizeof held) != 0)
            abort();
    }
    release_law(&law);
}

/* The table before the first input (~11 s under the sanitizers: outside the per-input
 * timeout, within the run's 60 s). */
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    table_law();
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    input in = {data, size};
    uint8_t selector = take_byte(&in);
    switch (selector % 3) {
    case 0: fuzz_table_fold(&in); break;
    case 1: fuzz_every_law((uint8_t)(selector / 3), &in); break;
    default: fuzz_bridge_held((uint8_t)(selector / 3), &in); break;
    }
    return 0;
}
