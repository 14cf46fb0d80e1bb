/* cmd_force.c — `capbridge force`: one point of a law.
 * CSV: gap,force,stiffness,rupture_distance (force >= 0 is the attraction [N],
 * stiffness = dF/dgap [N/m]), and with keyword viscosity the bridge's viscous damping
 * coefficients viscous_normal,viscous_tangential [N s/m] (cb_viscous_damping). */
#include "args.h"
#include "commands.h"

#include <stdio.h>

static const char usage[] =
    "usage: capbridge force LAW [keyword value]... --r1 M (--r2 M | --plane) --volume M3\n"
    "                       --gap M\n"
    "\n"
    "The capillary force of LAW between spheres of radii r1, r2 (or sphere 1 and a plane,\n"
    "a wall: --plane) holding a bridge of the given volume at the given gap\n"
    "(surface-to-surface distance; < 0 is an overlap).\n"
    "Prints one CSV row with a header: gap,force,stiffness,rupture_distance\n"
    "  force      attraction [N], >= 0; 0 beyond the rupture distance\n"
    "  stiffness  dF/dgap [N/m]\n"
    "With keywords viscosity ETA min_gap S (the bridge's viscous force), two more columns:\n"
    "  viscous_normal, viscous_tangential  damping coefficients [N s/m]: the viscous force\n"
    "  is -viscous_normal * d(gap)/dt along the normal and -viscous_tangential * v_t\n"
    "Example: capbridge force richefeu theta 10 --r1 1e-3 --r2 5e-4 --volume 1e-11 --gap 2e-5\n";

enum { R1, R2, PLANE, VOLUME, GAP, N_OPTIONS };

int cmd_force(int argc, char **argv)
{
    const char *name = "force";
    cli_option options[N_OPTIONS] = {
        CLI_OPTION_R1, CLI_OPTION_R2, CLI_OPTION_PLANE, CLI_OPTION_VOLUME,
        {.name = "--gap", .kind = CLI_NUMBER, .required = 1,
         .meaning = "surface-to-surface distance [m], < 0 is an overlap"},
    };
    cb_law law;
    cli_request request = {name, usage, 1, &law, options, N_OPTIONS, NULL, NULL};
    int code;
    if (!cli_parse(&request, argc, argv, &code)) return code;

    double r1 = options[R1].number, r2 = 0.0, volume = options[VOLUME].number;
    double gap = options[GAP].number;
    if (!cli_second_surface(name, &options[R2], &options[PLANE], &r2, &code)) {
        cb_law_release(&law);
        return code;
    }
    double rupture = 0.0, force = 0.0, stiffness = 0.0;
    char inputs[256], what[320];
    cli_describe_pair(inputs, sizeof inputs, &law, r1, r2, volume);
    cb_status status = cb_rupture_distance(&law, r1, r2, volume, &rupture);
    if (status != CB_OK) {
        snprintf(what, sizeof what, "rupture distance of %s", inputs);
        code = cli_status_error(name, what, status);
    } else {
        status = cb_force(&law, r1, r2, volume, gap, &force, &stiffness);
        snprintf(what, sizeof what, "force at gap %.10g m, %s", gap, inputs);
        if (status != CB_OK) code = cli_status_error(name, what, status);
    }
    double row[6] = {gap, force, stiffness, rupture, 0.0, 0.0};
    const int viscous = law.viscosity > 0.0;
    if (code == CLI_EXIT_OK && viscous) {
        status = cb_viscous_damping(&law, r1, r2, gap, volume, &row[4], &row[5]);
        snprintf(what, sizeof what, "viscous damping at gap %.10g m, %s", gap, inputs);
        if (status != CB_OK) code = cli_status_error(name, what, status);
    }
    if (code == CLI_EXIT_OK) {
        puts(viscous ? "gap,force,stiffness,rupture_distance,viscous_normal,viscous_tangential"
                     : "gap,force,stiffness,rupture_distance");
        cli_print_row(stdout, viscous ? 6 : 4, row);
    }
    cb_law_release(&law);
    return code;
}
