/* args.h — the command line of `capbridge`: option tables, number validation, the law
 * specification shared by the law subcommands, and the error conventions.
 *
 * Exit codes: 0 success; 1 a run-time failure (the core's message, e.g. no convergence,
 * or a malformed data file); 2 a wrong command line (one line on stderr naming what is
 * wrong and what is allowed). */
#ifndef CAPBRIDGE_CLI_ARGS_H
#define CAPBRIDGE_CLI_ARGS_H

#include "capbridge.h"

#include <stddef.h>
#include <stdio.h>

enum { CLI_EXIT_OK = 0, CLI_EXIT_RUNTIME = 1, CLI_EXIT_USAGE = 2 };

/* Defaults of the law specification: water at 20 C, perfectly wetting. */
#define CLI_DEFAULT_GAMMA 0.0728
#define CLI_DEFAULT_THETA 0.0

typedef enum cli_kind {
    CLI_NUMBER,      /* any finite number */
    CLI_POSITIVE,    /* a finite number > 0 */
    CLI_NONNEGATIVE, /* a finite number >= 0 */
    CLI_FRACTION,    /* a finite number in [0, 1] */
    CLI_ANGLE,       /* degrees, 0 <= value < 90 */
    CLI_INTEGER,     /* a whole number in [minimum, maximum] */
    CLI_FLAG,        /* takes no value */
    CLI_TEXT         /* any non-empty text */
} cli_kind;

/* One option of a subcommand. Set the default in `number`/`integer` before parsing;
 * cli_parse sets `given` and the value. */
typedef struct cli_option {
    const char *name;    /* with its dashes: "--r1" */
    cli_kind kind;
    int required;
    const char *meaning; /* "radius of sphere 1 [m]", quoted when the option is missing */
    long minimum, maximum; /* CLI_INTEGER only */
    /* results */
    int given;
    double number;
    long integer;
    const char *text;
} cli_option;

/* The geometry options every law subcommand shares (SI). */
#define CLI_OPTION_R1 {.name = "--r1", .kind = CLI_POSITIVE, .required = 1, .meaning = "radius of sphere 1 [m]"}
/* Surface 2: --r2 (a sphere) or --plane (a wall, r2 = CB_PLANE), exactly one of the two
 * (cli_second_surface). */
#define CLI_OPTION_R2 {.name = "--r2", .kind = CLI_POSITIVE, .meaning = "radius of sphere 2 [m]"}
#define CLI_OPTION_PLANE {.name = "--plane", .kind = CLI_FLAG, .meaning = "surface 2 is a plane"}
#define CLI_OPTION_VOLUME {.name = "--volume", .kind = CLI_POSITIVE, .required = 1, .meaning = "liquid bridge volume [m^3]"}

/* What a subcommand's command line looks like. */
typedef struct cli_request {
    const char *command;       /* subcommand name, for messages */
    const char *usage;         /* printed for --help or -h */
    int wants_law;             /* the line starts with LAW [keyword value]... */
    cb_law *law;               /* out: initialised, configured and prepared */
    cli_option *options;
    size_t n_options;
    const char *positional_name; /* e.g. "FILE"; NULL if the command takes none */
    const char *positional;      /* out: the positional argument, NULL if absent */
} cli_request;

/* Parse argv (argv[0] is the subcommand name). Returns 1 to go on; 0 to stop with the
 * exit code in *exit_code: CLI_EXIT_OK after printing the usage (--help or -h anywhere
 * before a "--"), CLI_EXIT_USAGE after printing one line on stderr. A required option
 * that is missing is an error; a missing positional is left to the caller. With
 * wants_law, the law is also prepared (CLI_EXIT_RUNTIME with the core's message if that
 * fails). */
int cli_parse(cli_request *request, int argc, char **argv, int *exit_code);

/* Messages: "capbridge COMMAND: ..." on stderr, one line; return the exit code. */
int cli_usage_error(const char *command, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
int cli_runtime_error(const char *command, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* User text (an argument, a field of a file) as a message shows it, on one short line:
 * its first CLI_ECHO_LIMIT bytes (not cutting a UTF-8 character) and, when it is longer,
 * "..." and its length; control bytes (a newline would end the message) as \xHH.
 * cli_quote: 'TEXT' or 'TEXT...' (N bytes); cli_clip: TEXT or TEXT... (N bytes) (file
 * names before ":LINE:"). They return echo->text; length is the text's length. */
#define CLI_ECHO_LIMIT 60
typedef struct cli_echo {
    char text[4 * CLI_ECHO_LIMIT + 48];
} cli_echo;
const char *cli_quote(cli_echo *echo, const char *text, size_t length);
const char *cli_clip(cli_echo *echo, const char *text, size_t length);

/* A failed core call: "capbridge COMMAND: WHAT: <cb_status_message>"; exit code 1. */
int cli_status_error(const char *command, const char *what, cb_status status);

/* "law L (gamma G N/m, theta T deg), r1 A m, r2 B m, volume V m^3" into buffer: the inputs
 * of a failed call, so that its message shows which of them is out of range. */
/* r2 from the --r2 and --plane options (CB_PLANE for --plane): 1, or 0 with the usage
 * error's exit code in *code when neither or both are given. */
int cli_second_surface(const char *command, const cli_option *r2, const cli_option *plane,
                       double *value, int *code);

const char *cli_describe_pair(char *buffer, size_t size, const cb_law *law, double r1,
                              double r2, double volume);

/* The law specification help shared by every law subcommand. */
void cli_print_law_help(FILE *out);

/* Print a number so that it reads back to the same double. */
void cli_print_number(FILE *out, double value);
/* Print n numbers as one CSV row. */
void cli_print_row(FILE *out, size_t n, const double *values);

#endif
