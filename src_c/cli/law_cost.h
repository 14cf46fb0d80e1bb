/* law_cost.h — the cost of one force call per law, measured in one run. */
#ifndef CAPBRIDGE_CLI_LAW_COST_H
#define CAPBRIDGE_CLI_LAW_COST_H

#include "capbridge.h"

/* Nanoseconds per cb_force call of each of n prepared laws, on a fixed pseudo-random
 * sample of pairs inside the grid's domain (size ratio 1..10, V/R_h^3 1e-5..1e-1,
 * 0 <= gap <= the law's rupture distance). The laws take turns within every timed pass
 * and each keeps its best pass, so that the load of a shared machine falls on all of
 * them alike.  A law with a viscosity (keyword viscosity) is timed as what a bridge pays
 * with its viscous force on: cb_force and cb_viscous_damping per call.  If
 * ns_per_rupture is not NULL, the cost of cb_rupture_distance alone on the same pairs is
 * timed in the same passes (what a law pays to place the pair before its force: for the
 * table law its stencil).  If ns_per_bridge_step is not NULL, the cost of the call an
 * engine makes per step for a stretched bridge (cb_bridge_force on a state whose constants
 * were derived when it got its volume, the same pairs and gaps) is timed too.  Returns 0
 * on success, -1 when memory runs out. */
int cb_law_costs_ns(const cb_law *laws, int n, double *ns_per_call, double *ns_per_rupture,
                    double *ns_per_bridge_step);

#endif
