/* test_law.h — the tests' Richefeu law: contact angle theta (degrees), and where given a
 * rupture rule and a validity, configured through the keyword API as a user would, then
 * prepared; every step checked. */
#ifndef CAPBRIDGE_TEST_LAW_H
#define CAPBRIDGE_TEST_LAW_H

#include "capbridge.h"
#include "check.h"

#include <stdio.h>

static inline cb_law make_law(double theta_degrees, const char *rupture, const char *validity)
{
    cb_law law;
    cb_message msg;
    char text[32];
    CHECK_STATUS(cb_law_init(&law, CB_MODEL_RICHEFEU, 0.072, 0.0), CB_OK);
    snprintf(text, sizeof text, "%.17g", theta_degrees);
    CHECK_STATUS(cb_law_configure(&law, "theta", text, &msg), CB_OK);
    if (rupture) CHECK_STATUS(cb_law_configure(&law, "rupture", rupture, &msg), CB_OK);
    if (validity) CHECK_STATUS(cb_law_configure(&law, "validity", validity, &msg), CB_OK);
    CHECK_STATUS(cb_law_prepare(&law, &msg), CB_OK);
    return law;
}

#endif
