/* cmd_rupture.c — `capbridge rupture`: the rupture distance of a law's bridge. */
#include "args.h"
#include "commands.h"

#include <stdio.h>

static const char usage[] =
    "usage: capbridge rupture LAW [keyword value]... --r1 M (--r2 M | --plane) --volume M3\n"
    "\n"
    "The rupture (debonding) distance [m] of a bridge of the given volume between\n"
    "spheres of radii r1, r2 (or sphere 1 and a plane, a wall: --plane), under the law's\n"
    "rupture rule (keyword rupture).\n"
    "Prints CSV with a header: rupture_distance\n";

enum { R1, R2, PLANE, VOLUME, N_OPTIONS };

int cmd_rupture(int argc, char **argv)
{
    const char *name = "rupture";
    cli_option options[N_OPTIONS] = {CLI_OPTION_R1, CLI_OPTION_R2, CLI_OPTION_PLANE,
                                     CLI_OPTION_VOLUME};
    cb_law law;
    cli_request request = {name, usage, 1, &law, options, N_OPTIONS, NULL, NULL};
    int code;
    if (!cli_parse(&request, argc, argv, &code)) return code;

    double rupture = 0.0, r2 = 0.0;
    if (!cli_second_surface(name, &options[R2], &options[PLANE], &r2, &code)) {
        cb_law_release(&law);
        return code;
    }
    cb_status status = cb_rupture_distance(&law, options[R1].number, r2,
                                           options[VOLUME].number, &rupture);
    if (status != CB_OK) {
        char inputs[256], what[320];
        cli_describe_pair(inputs, sizeof inputs, &law, options[R1].number, r2,
                          options[VOLUME].number);
        snprintf(what, sizeof what, "rupture distance of %s", inputs);
        code = cli_status_error(name, what, status);
    }
    else {
        puts("rupture_distance");
        cli_print_row(stdout, 1, &rupture);
    }
    cb_law_release(&law);
    return code;
}
