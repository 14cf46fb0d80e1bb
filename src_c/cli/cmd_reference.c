/* cmd_reference.c — `capbridge reference cases|grid|plane [--only NAME]`: the exact
 * Laplace-Young curves written to reference_data/ (CSV on standard output).  A plane's r2
 * is written as the word "plane" (reference_read.c reads it back as CB_PLANE). */
#include <stdio.h>
#include <string.h>

#include "args.h"
#include "capbridge.h"
#include "cases.h"
#include "reference.h"


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
    const double theta = c->contact_angle * CB_PI / 180.0;
    cb_exact_problem problem = {c->r1, c->r2, theta, theta, c->surface_tension, c->volume, 0};
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
        char r2[32];
        if (cb_is_plane(c->r2)) snprintf(r2, sizeof r2, "plane");
        else snprintf(r2, sizeof r2, "%.17g", c->r2);
        printf("%s,%.17g,%s,%.17g,%.17g,%.17g,%.17g,%d,%.17g,%.17g,%.17g,%.17g,%.17g,"
               "%.17g\n",
               c->name, c->r1, r2, c->surface_tension, c->contact_angle, c->volume, rupture,
               i, b->gap, b->force, b->filling_angle1, b->filling_angle2, b->pressure,
               b->neck_radius);
    }
    fflush(stdout);
    return 0;
}

/* The configurations of a set (cases, grid or plane). */
static size_t set_count(const char *set)
{
    if (strcmp(set, "grid") == 0) return cb_grid_case_count();
    if (strcmp(set, "plane") == 0) return cb_plane_case_count();
    return cb_gladkyy_case_count;
}

static cb_case set_case(const char *set, size_t i, char *name, size_t name_size)
{
    if (strcmp(set, "grid") == 0) return cb_grid_case(i, name, name_size);
    if (strcmp(set, "plane") == 0) return cb_plane_case(i, name, name_size);
    return cb_gladkyy_cases[i];
}

int cmd_reference(int argc, char **argv)
{
    const char *name = "reference";
    static const char usage[] =
        "usage: capbridge reference cases|grid|plane [--only NAME]\n"
        "\n"
        "The exact Laplace-Young curves of reference_data/ as CSV on standard output:\n"
        "  cases        Gladkyy's 13 pull-off cases (reference_data/cases.csv)\n"
        "  grid         the grid of configurations (reference_data/grid.csv)\n"
        "  plane        a sphere and a plane (a wall) at the grid's angles and volumes\n"
        "               (reference_data/plane.csv)\n"
        "  --only NAME  one configuration of the set, by its name (e.g. W11)\n";
    enum { ONLY, N_OPTIONS };
    cli_option options[N_OPTIONS] = {
        {.name = "--only", .kind = CLI_TEXT, .meaning = "the name of one configuration"},
    };
    cli_request request = {name, usage, 0, NULL, options, N_OPTIONS, "cases|grid|plane", NULL};
    int code;
    if (!cli_parse(&request, argc, argv, &code)) return code;
    const char *set = request.positional;
    cli_echo shown;
    if (!set) return cli_usage_error(name, "missing the set: allowed cases, grid, plane");
    if (strcmp(set, "cases") != 0 && strcmp(set, "grid") != 0 && strcmp(set, "plane") != 0)
        return cli_usage_error(name, "unknown set %s: allowed cases, grid, plane",
                               cli_quote(&shown, set, strlen(set)));
    const char *only = options[ONLY].given ? options[ONLY].text : NULL;
    size_t count = set_count(set);
    int found = 0;
    for (size_t i = 0; only && !found && i < count; ++i) {
        char config[48];
        cb_case c = set_case(set, i, config, sizeof config);
        found = strcmp(only, c.name) == 0;
    }
    if (only && !found)
        return cli_usage_error(name, "no configuration named %s in %s",
                               cli_quote(&shown, only, strlen(only)), set);

    int failures = 0;
    print_header(set);
    for (size_t i = 0; i < count; ++i) {
        char config[48];
        cb_case c = set_case(set, i, config, sizeof config);
        if (only && strcmp(only, c.name) != 0) continue;
        failures += print_case(&c);
    }
    return failures ? 1 : 0;
}
