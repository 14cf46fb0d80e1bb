/* main.c — `capbridge`, the standalone C reference of the capbridge core: the table of
 * subcommands and the dispatch. Everything a subcommand does is in its cmd_NAME.c. */
#include "args.h"
#include "commands.h"

#include <stdio.h>
#include <string.h>

typedef struct subcommand {
    const char *name;
    const char *summary; /* one line of `capbridge --help` */
    int (*run)(int argc, char **argv); /* argv[0] is the name; returns the exit code */
} subcommand;

/* The subcommands, in the order `capbridge --help` lists them: one line each. */
static const subcommand subcommands[] = {
    {"force", "one point of a law: gap,force,stiffness,rupture_distance", cmd_force},
    {"curve", "a law's force over a range of gaps: gap,force,stiffness", cmd_curve},
    {"rupture", "the rupture distance of a law's bridge", cmd_rupture},
    {"exact", "the exact Laplace-Young bridge at a gap, over a curve, or at rupture", cmd_exact},
    {"pulloff", "two spheres pulled apart until the bridge breaks, per step", cmd_pulloff},
    {"replay", "recompute the bridge forces of an engine's dump, largest difference", cmd_replay},
    {"reference", "the exact curves of reference_data/ (cases or grid), as CSV", cmd_reference},
    {"report", "every law's error against the exact curves, and its cost", cmd_report},
    {"bench", "the cost per force call of every law, relative to the cheapest", cmd_bench},
};
#define SUBCOMMAND_COUNT (sizeof subcommands / sizeof subcommands[0])

static void print_overview(FILE *out)
{
    fprintf(out,
            "capbridge %s: capillary (liquid-bridge) forces between two spheres, SI units\n"
            "usage: capbridge SUBCOMMAND [arguments]   (capbridge SUBCOMMAND --help for more)\n"
            "\nSubcommands:\n",
            CB_VERSION_STRING);
    for (size_t k = 0; k < SUBCOMMAND_COUNT; ++k)
        fprintf(out, "  %-10s %s\n", subcommands[k].name, subcommands[k].summary);
    fprintf(out, "\nExit status: 0 success, 1 run-time failure (with the core's message),\n"
                 "2 wrong command line (one line on stderr naming what is wrong).\n");
}

static const subcommand *find(const char *name)
{
    for (size_t k = 0; k < SUBCOMMAND_COUNT; ++k)
        if (strcmp(subcommands[k].name, name) == 0) return &subcommands[k];
    return NULL;
}

/* An unknown subcommand, or none (name NULL). */
static int unknown(const char *name)
{
    char allowed[512] = "";
    size_t used = 0;
    for (size_t k = 0; k < SUBCOMMAND_COUNT && used < sizeof allowed; ++k) {
        int n = snprintf(allowed + used, sizeof allowed - used, "%s%s", k ? ", " : "",
                         subcommands[k].name);
        if (n < 0) break;
        used += (size_t)n;
    }
    if (!name)
        return cli_usage_error(NULL, "missing subcommand: allowed %s (capbridge --help)", allowed);
    cli_echo shown;
    return cli_usage_error(NULL, "unknown subcommand %s: allowed %s",
                           cli_quote(&shown, name, strlen(name)), allowed);
}

/* Flush stdout; a failed write (a full disk, a closed pipe) is a failure. */
static int finish(int code)
{
    if (fflush(stdout) != 0 || ferror(stdout)) {
        cli_runtime_error(NULL, "error writing the output");
        return code ? code : CLI_EXIT_RUNTIME;
    }
    return code;
}

int main(int argc, char **argv)
{
    if (argc < 2) return unknown(NULL);
    const char *name = argv[1];
    if (strcmp(name, "--help") == 0 || strcmp(name, "-h") == 0 || strcmp(name, "help") == 0) {
        if (argc == 2) {
            print_overview(stdout);
            return finish(CLI_EXIT_OK);
        }
        /* capbridge help SUBCOMMAND = capbridge SUBCOMMAND --help */
        const subcommand *command = find(argv[2]);
        if (!command) return unknown(argv[2]);
        char help[] = "--help";
        char *help_argv[3] = {argv[2], help, NULL};
        return finish(command->run(2, help_argv));
    }
    if (strcmp(name, "--version") == 0) {
        printf("capbridge %s\n", CB_VERSION_STRING);
        return finish(CLI_EXIT_OK);
    }
    const subcommand *command = find(name);
    if (!command) return unknown(name);
    return finish(command->run(argc - 1, argv + 1));
}
