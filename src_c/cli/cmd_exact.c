/* cmd_exact.c — `capbridge exact`: the exact Laplace-Young bridge (cb_exact_solve,
 * cb_exact_curve, cb_exact_rupture), the reference every law is measured against. */
#include "args.h"
#include "commands.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>


static const char usage[] =
    "usage: capbridge exact --r1 M (--r2 M | --plane) --volume M3 [--theta DEG]\n"
    "                       [--theta2 DEG] [--gamma N/m] [--steps N]\n"
    "                       (--gap M | --curve N | --rupture)\n"
    "\n"
    "The exact Laplace-Young bridge between two spheres, or between sphere 1 and a plane\n"
    "(no gravity), on the branch connected to contact.\n"
    "  --plane       surface 2 is a plane (the limit r2 -> infinity; a wall)\n"
    "  --theta DEG   contact angle on sphere 1, 0 <= theta < 90 (default 0)\n"
    "  --theta2 DEG  contact angle on surface 2, 0 <= theta2 < 90 (default: --theta)\n"
    "  --gamma N/m   surface tension, > 0 (default 0.0728)\n"
    "  --steps N     integration steps along the profile: 0 (default: the solver's own,\n"
    "                256) or 16 to 1000000\n"
    "  --gap M       the bridge at one gap, 0 <= gap <= rupture distance\n"
    "  --curve N     N >= 2 gaps evenly spaced from 0 to the rupture distance inclusive\n"
    "  --rupture     the bridge at the rupture distance (its gap is the distance)\n"
    "Prints CSV with a header:\n"
    "  gap,force,force_contact1,force_contact2,filling_angle1,filling_angle2,\n"
    "  pressure,neck_radius,volume,contact_radius1,contact_radius2\n"
    "force [N] is the attraction at the neck, force_contact1/2 the same at the contact\n"
    "lines (a check), filling angles in rad (filling_angle2 0 on a plane), pressure =\n"
    "p_liquid - p_gas [Pa], volume the volume recovered from the profile [m^3], the\n"
    "contact radii those of the contact lines on sphere 1 and surface 2 [m].\n";

enum { R1, R2, PLANE, VOLUME, THETA, THETA2, GAMMA, STEPS, GAP, CURVE, RUPTURE, N_OPTIONS };

static void print_bridge(const cb_exact_bridge *b)
{
    double row[11] = {b->gap,            b->force,          b->force_contact1,
                      b->force_contact2, b->filling_angle1, b->filling_angle2,
                      b->pressure,       b->neck_radius,    b->volume,
                      b->contact_radius1, b->contact_radius2};
    cli_print_row(stdout, 11, row);
}

static const char header[] = "gap,force,force_contact1,force_contact2,filling_angle1,"
                             "filling_angle2,pressure,neck_radius,volume,contact_radius1,"
                             "contact_radius2";

int cmd_exact(int argc, char **argv)
{
    const char *name = "exact";
    cli_option options[N_OPTIONS] = {
        CLI_OPTION_R1,
        CLI_OPTION_R2, CLI_OPTION_PLANE,
        CLI_OPTION_VOLUME,
        {.name = "--theta", .kind = CLI_ANGLE, .meaning = "contact angle on sphere 1 [degrees]",
         .number = CLI_DEFAULT_THETA},
        {.name = "--theta2", .kind = CLI_ANGLE,
         .meaning = "contact angle on surface 2 [degrees]"},
        {.name = "--gamma", .kind = CLI_POSITIVE, .meaning = "surface tension [N/m]",
         .number = CLI_DEFAULT_GAMMA},
        {.name = "--steps", .kind = CLI_INTEGER, .meaning = "integration steps",
         .minimum = 0, .maximum = CB_EXACT_MAX_STEPS},
        {.name = "--gap", .kind = CLI_NONNEGATIVE, .meaning = "gap [m]"},
        {.name = "--curve", .kind = CLI_INTEGER, .meaning = "number of gaps",
         .minimum = 2, .maximum = 1000000L},
        {.name = "--rupture", .kind = CLI_FLAG, .meaning = "the bridge at rupture"},
    };
    cli_request request = {name, usage, 0, NULL, options, N_OPTIONS, NULL, NULL};
    int code;
    if (!cli_parse(&request, argc, argv, &code)) return code;
    double r2 = 0.0;
    if (!cli_second_surface(name, &options[R2], &options[PLANE], &r2, &code)) return code;
    int modes = options[GAP].given + options[CURVE].given + options[RUPTURE].given;
    if (modes != 1)
        return cli_usage_error(name, "give exactly one of --gap, --curve, --rupture (%s)",
                               modes ? "several given" : "none given");

    long steps = options[STEPS].integer;
    if (steps > 0 && steps < CB_EXACT_MIN_STEPS)
        return cli_usage_error(name, "option --steps: %ld is too few: allowed 0 (the solver's "
                               "default, %d) or %d to %d", steps, CB_EXACT_DEFAULT_STEPS,
                               CB_EXACT_MIN_STEPS, CB_EXACT_MAX_STEPS);

    cb_exact_problem problem;
    problem.r1 = options[R1].number;
    problem.r2 = r2;
    problem.volume = options[VOLUME].number;
    problem.contact_angle1 = options[THETA].number * CB_PI / 180.0;
    problem.contact_angle2 =
        (options[THETA2].given ? options[THETA2].number : options[THETA].number) * CB_PI / 180.0;
    problem.surface_tension = options[GAMMA].number;
    problem.steps = (int)steps;

    cb_exact_bridge bridge;
    cb_status status;
    if (options[GAP].given) {
        status = cb_exact_solve(&problem, options[GAP].number, &bridge);
        if (status != CB_OK) return cli_status_error(name, "cb_exact_solve", status);
        puts(header);
        print_bridge(&bridge);
        return CLI_EXIT_OK;
    }

    double rupture = 0.0;
    status = cb_exact_rupture(&problem, &rupture, &bridge);
    if (status != CB_OK) return cli_status_error(name, "cb_exact_rupture", status);
    if (options[RUPTURE].given) {
        puts(header);
        print_bridge(&bridge);
        return CLI_EXIT_OK;
    }

    size_t n = (size_t)options[CURVE].integer;
    double *gaps = malloc(n * sizeof *gaps);
    cb_exact_bridge *bridges = malloc(n * sizeof *bridges);
    if (!gaps || !bridges) {
        free(gaps);
        free(bridges);
        return cli_status_error(name, "--curve", CB_ERR_NO_MEMORY);
    }
    for (size_t i = 0; i < n; ++i)
        gaps[i] = i == n - 1 ? rupture : rupture * ((double)i / (double)(n - 1));
    status = cb_exact_curve(&problem, n, gaps, bridges);
    if (status != CB_OK) code = cli_status_error(name, "cb_exact_curve", status);
    else {
        puts(header);
        for (size_t i = 0; i < n; ++i) print_bridge(&bridges[i]);
    }
    free(gaps);
    free(bridges);
    return code;
}
