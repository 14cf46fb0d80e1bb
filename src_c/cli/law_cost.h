/* law_cost.h — the cost of one force call per law, measured in one run. */
#ifndef CAPBRIDGE_CLI_LAW_COST_H
#define CAPBRIDGE_CLI_LAW_COST_H

#include "capbridge.h"

/* Nanoseconds per cb_force call on a fixed pseudo-random sample of pairs inside the
 * grid's domain (size ratio 1..10, V/R_h^3 1e-5..1e-1, 0 <= gap <= the law's rupture
 * distance): the best of several timed passes. The law must be prepared. */
double cb_law_cost_ns(const cb_law *law);

#endif
