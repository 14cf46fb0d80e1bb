/* cmd_bench.c — `capbridge bench`: the cost per cb_force call of every law, measured in
 * one run on the same sample of pairs, its ratio to the cheapest closed-form law, and the
 * cost of cb_rupture_distance alone (the part of the call that places the pair: for the
 * table law, its stencil), and the cost of a stretched bridge's step (cb_bridge_force on a
 * stored state: what an engine pays per step). The table law's target is a ratio of at
 * most 1.5 (issue 20). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "args.h"
#include "capbridge.h"
#include "law_cost.h"

int cmd_bench(int argc, char **argv)
{
    if (argc > 1) {
        if (strcmp(argv[1], "--help") == 0) {
            printf("usage: capbridge bench\nnanoseconds per force call of every law (water, "
                   "theta = 0), the ratio to the cheapest closed-form law, nanoseconds per "
                   "rupture-distance call, and nanoseconds per stretched-bridge step (the "
                   "engines' per-step call) with its ratio, one run\n");
            return 0;
        }
        cli_echo shown;
        return cli_usage_error("bench", "unknown argument %s: bench takes none",
                               cli_quote(&shown, argv[1], strlen(argv[1])));
    }
    cb_law laws[CB_MODEL_COUNT];
    double ns[CB_MODEL_COUNT], rupture_ns[CB_MODEL_COUNT], step_ns[CB_MODEL_COUNT];
    double cheapest = HUGE_VAL, cheapest_step = HUGE_VAL;
    int prepared = 0, failed = 0;
    for (int m = 0; m < CB_MODEL_COUNT && !failed; ++m, ++prepared) {
        cb_message msg;
        if (cb_law_init(&laws[m], (cb_model)m, 0.0728, 0.0) != CB_OK ||
            cb_law_prepare(&laws[m], &msg) != CB_OK) {
            fprintf(stderr, "capbridge bench: %s: %s\n", cb_model_name((cb_model)m), msg.text);
            failed = 1;
        }
    }
    if (!failed && cb_law_costs_ns(laws, CB_MODEL_COUNT, ns, rupture_ns, step_ns) != 0) {
        fprintf(stderr, "capbridge bench: out of memory\n");
        failed = 1;
    }
    for (int m = 0; m < prepared; ++m) cb_law_release(&laws[m]);
    if (failed) return 1;
    for (int m = 0; m < CB_MODEL_COUNT; ++m) {
        if (cb_model_tabulated((cb_model)m)) continue;
        if (ns[m] < cheapest) cheapest = ns[m];
        if (step_ns[m] < cheapest_step) cheapest_step = step_ns[m];
    }
    printf("law,ns_per_call,ratio_to_cheapest_closed_form,ns_per_rupture_call,"
           "ns_per_bridge_step,bridge_step_ratio_to_cheapest_closed_form\n");
    for (int m = 0; m < CB_MODEL_COUNT; ++m)
        printf("%s,%.2f,%.3f,%.2f,%.2f,%.3f\n", cb_model_name((cb_model)m), ns[m],
               ns[m] / cheapest, rupture_ns[m], step_ns[m], step_ns[m] / cheapest_step);
    return 0;
}
