/* cmd_reference.c — `capbridge reference cases|grid [--only NAME]`: the exact
 * Laplace-Young curves written to reference_data/ (CSV on standard output). */
#include <stdio.h>
#include <string.h>

#include "capbridge.h"
#include "cases.h"
#include "reference.h"

#define CB_PI 3.14159265358979323846

static void print_header(const char *set)
{
    printf("# capbridge reference data: exact Laplace-Young bridges (%s).\n", set);
    printf("# Regenerate: build/src_c/cli/capbridge reference %s > reference_data/%s.csv\n",
           set, set);
    printf("# Each configuration: %d gaps from 0 to the exact rupture distance (the fold of "
           "the fixed-volume branch), the last one at the fold.\n",
           CB_CURVE_POINTS);
    printf("# Units SI; contact_angle in degrees; pressure = p_liquid - p_gas.\n");
    printf("%s\n", CB_REFERENCE_COLUMNS);
}

/* One configuration: its rupture distance and CB_CURVE_POINTS bridges. */
cb_status cb_reference_curve(const cb_case *c, double *rupture, cb_exact_bridge *bridges)
{
    cb_exact_problem problem = {c->r1, c->r2, c->contact_angle * CB_PI / 180.0,
                                c->surface_tension, c->volume, 0};
    cb_status status = cb_exact_rupture(&problem, rupture, &bridges[CB_CURVE_POINTS - 1]);
    if (status != CB_OK) return status;
    double gaps[CB_CURVE_POINTS - 1];
    for (int i = 0; i < CB_CURVE_POINTS - 1; ++i)
        gaps[i] = *rupture * (double)i / (CB_CURVE_POINTS - 1);
    return cb_exact_curve(&problem, CB_CURVE_POINTS - 1, gaps, bridges);
}

static int print_case(const cb_case *c)
{
    double rupture = 0.0;
    cb_exact_bridge bridges[CB_CURVE_POINTS];
    cb_status status = cb_reference_curve(c, &rupture, bridges);
    if (status != CB_OK) {
        fprintf(stderr, "capbridge reference: %s: %s\n", c->name, cb_status_message(status));
        return 1;
    }
    for (int i = 0; i < CB_CURVE_POINTS; ++i) {
        const cb_exact_bridge *b = &bridges[i];
        printf("%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%.17g,%.17g,%.17g,%.17g,%.17g,"
               "%.17g\n",
               c->name, c->r1, c->r2, c->surface_tension, c->contact_angle, c->volume, rupture,
               i, b->gap, b->force, b->filling_angle1, b->filling_angle2, b->pressure,
               b->neck_radius);
    }
    fflush(stdout);
    return 0;
}

int cmd_reference(int argc, char **argv)
{
    const char *usage = "usage: capbridge reference cases|grid [--only NAME]\n";
    if (argc < 2 || strcmp(argv[1], "--help") == 0) {
        fputs(usage, argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    const char *set = argv[1];
    const char *only = NULL;
    for (int i = 2; i < argc; ++i) {
        if (strcmp(argv[i], "--only") == 0 && i + 1 < argc) {
            only = argv[++i];
        } else {
            fprintf(stderr, "capbridge reference: unknown option '%s': allowed --only NAME\n",
                    argv[i]);
            return 2;
        }
    }
    int failures = 0, found = 0;
    if (strcmp(set, "cases") == 0) {
        print_header("cases");
        for (size_t i = 0; i < cb_gladkyy_case_count; ++i) {
            if (only && strcmp(only, cb_gladkyy_cases[i].name) != 0) continue;
            ++found;
            failures += print_case(&cb_gladkyy_cases[i]);
        }
    } else if (strcmp(set, "grid") == 0) {
        print_header("grid");
        for (size_t i = 0; i < cb_grid_case_count(); ++i) {
            char name[48];
            cb_case c = cb_grid_case(i, name, sizeof name);
            if (only && strcmp(only, name) != 0) continue;
            ++found;
            failures += print_case(&c);
        }
    } else {
        fprintf(stderr, "capbridge reference: unknown set '%s': allowed cases, grid\n", set);
        return 2;
    }
    if (only && !found) {
        fprintf(stderr, "capbridge reference: no configuration named '%s' in %s\n", only, set);
        return 2;
    }
    return failures ? 1 : 0;
}
