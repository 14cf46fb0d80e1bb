/* fuzz_force.c — libFuzzer target over the force API.
 * The input bytes become a law (model, theta, gamma, options) and a pair (radii, volume,
 * gap), including NaN, infinities, negatives and extreme magnitudes. Whatever comes in,
 * the core must not crash, and on CB_OK the force must be finite and >= 0, the rupture
 * distance finite and > 0, and the force zero beyond it. */
#include "capbridge.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static double take_double(const uint8_t **data, size_t *size)
{
    double value = 0.0;
    if (*size >= sizeof value) {
        memcpy(&value, *data, sizeof value);
        *data += sizeof value;
        *size -= sizeof value;
    }
    return value;
}

static uint8_t take_byte(const uint8_t **data, size_t *size)
{
    uint8_t value = 0;
    if (*size >= 1) {
        value = **data;
        *data += 1;
        *size -= 1;
    }
    return value;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    uint8_t selector = take_byte(&data, &size);
    uint8_t options = take_byte(&data, &size);
    double theta = take_double(&data, &size);
    double gamma = take_double(&data, &size);
    double r1 = take_double(&data, &size);
    double r2 = take_double(&data, &size);
    double volume = take_double(&data, &size);
    double gap = take_double(&data, &size);

    /* The table law builds its table from the exact solver at preparation; it is
     * exercised by its own tests, the fuzzer covers the closed-form laws' force path. */
    cb_model model = (cb_model)(selector % CB_MODEL_TABLE);
    cb_law law;
    if (cb_law_init(&law, model, gamma, theta) != CB_OK) return 0;
    cb_message msg;
    cb_law_configure(&law, "overlap", (options & 1) ? "none" : "contact", &msg);
    cb_law_configure(&law, "validity", (options & 2) ? "strict" : "extend", &msg);
    cb_law_configure(&law, "rupture", (options & 4) ? "lian" : "willett", &msg);
    if (cb_law_prepare(&law, &msg) != CB_OK) abort();

    double force = -1.0, stiffness = 0.0, rupture = 0.0;
    cb_status status = cb_force(&law, r1, r2, volume, gap, &force, &stiffness);
    if (status == CB_OK && (!isfinite(force) || force < 0.0 || !isfinite(stiffness))) abort();
    status = cb_rupture_distance(&law, r1, r2, volume, &rupture);
    if (status == CB_OK) {
        if (!isfinite(rupture) || rupture <= 0.0) abort();
        if (rupture < 1e300 && cb_force(&law, r1, r2, volume, rupture * 1.5 + 1e-300, &force,
                                         NULL) == CB_OK && force != 0.0)
            abort();
    }
    double bound = 0.0;
    if (cb_capillary_stiffness_bound(&law, r1, r2, volume, &bound) == CB_OK &&
        (!isfinite(bound) || bound < 0.0))
        abort();
    cb_law_release(&law);
    return 0;
}
