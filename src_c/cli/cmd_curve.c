/* cmd_curve.c — `capbridge curve`: a law's force over a range of gaps.
 * CSV: gap,force,stiffness. */
#include "args.h"
#include "commands.h"

#include <math.h>
#include <stdio.h>

static const char usage[] =
    "usage: capbridge curve LAW [keyword value]... --r1 M (--r2 M | --plane) --volume M3\n"
    "                       [--points N] [--from M] [--to M]\n"
    "\n"
    "The force of LAW at N evenly spaced gaps from --from to --to inclusive (--plane:\n"
    "between sphere 1 and a plane, a wall).\n"
    "  --points N  number of gaps, >= 2 (default 21)\n"
    "  --from M    first gap (default 0)\n"
    "  --to M      last gap, > --from (default 1.05 x the law's rupture distance)\n"
    "Prints CSV with a header: gap,force,stiffness (force >= 0 is the attraction [N],\n"
    "stiffness = dF/dgap [N/m]; both 0 beyond the rupture distance).\n";

enum { R1, R2, PLANE, VOLUME, POINTS, FROM, TO, N_OPTIONS };

int cmd_curve(int argc, char **argv)
{
    const char *name = "curve";
    cli_option options[N_OPTIONS] = {
        CLI_OPTION_R1, CLI_OPTION_R2, CLI_OPTION_PLANE, CLI_OPTION_VOLUME,
        {.name = "--points", .kind = CLI_INTEGER, .meaning = "number of gaps",
         .minimum = 2, .maximum = 100000000L, .integer = 21},
        {.name = "--from", .kind = CLI_NUMBER, .meaning = "first gap [m]", .number = 0.0},
        {.name = "--to", .kind = CLI_NUMBER, .meaning = "last gap [m]"},
    };
    cb_law law;
    cli_request request = {name, usage, 1, &law, options, N_OPTIONS, NULL, NULL};
    int code;
    if (!cli_parse(&request, argc, argv, &code)) return code;

    double r1 = options[R1].number, r2 = 0.0, volume = options[VOLUME].number;
    double rupture = 0.0;
    if (!cli_second_surface(name, &options[R2], &options[PLANE], &r2, &code)) {
        cb_law_release(&law);
        return code;
    }
    cb_status status = cb_rupture_distance(&law, r1, r2, volume, &rupture);
    char inputs[256], what[320];
    cli_describe_pair(inputs, sizeof inputs, &law, r1, r2, volume);
    if (status != CB_OK) {
        cb_law_release(&law);
        snprintf(what, sizeof what, "rupture distance of %s", inputs);
        return cli_status_error(name, what, status);
    }
    double from = options[FROM].number;
    double to = options[TO].given ? options[TO].number : 1.05 * rupture;
    if (!(to > from)) {
        cb_law_release(&law);
        return cli_usage_error(name, "the range is empty: --from %.17g must be below --to %.17g%s",
                               from, to,
                               options[TO].given ? "" : " (1.05 x the rupture distance)");
    }

    if (!isfinite(to - from)) {
        cb_law_release(&law);
        return cli_usage_error(name, "the range from --from %.17g to --to %.17g is wider than a "
                               "double holds: give gaps whose difference is finite", from, to);
    }

    long n = options[POINTS].integer;
    puts("gap,force,stiffness");
    for (long i = 0; i < n; ++i) {
        /* the last gap is exactly --to, not the sum of rounded steps */
        double gap = i == n - 1 ? to : from + (to - from) * ((double)i / (double)(n - 1));
        double row[3] = {gap, 0.0, 0.0};
        status = cb_force(&law, r1, r2, volume, gap, &row[1], &row[2]);
        if (status != CB_OK) {
            snprintf(what, sizeof what, "force at gap %.10g m, %s", gap, inputs);
            code = cli_status_error(name, what, status);
            break;
        }
        cli_print_row(stdout, 3, row);
    }
    cb_law_release(&law);
    return code;
}
