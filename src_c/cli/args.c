/* args.c — option parsing and law construction for the `capbridge` command line.
 *
 * A command line is   LAW [keyword value]...  [--option value | --option=value | --flag]...
 * [POSITIONAL], in that order (law commands), LAMMPS-like: the law keywords are exactly
 * those of cb_law_configure, so the CLI, pair_style capillary (LAMMPS) and
 * cohesion_model capillary (LIGGGHTS) accept the same words. Every value is validated
 * here; the subcommands receive finite numbers in their stated ranges. */
#include "args.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

static void vreport(const char *command, const char *format, va_list args)
{
    if (command) fprintf(stderr, "capbridge %s: ", command);
    else fputs("capbridge: ", stderr);
    vfprintf(stderr, format, args);
    fputc('\n', stderr);
}

int cli_usage_error(const char *command, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    vreport(command, format, args);
    va_end(args);
    return CLI_EXIT_USAGE;
}

int cli_runtime_error(const char *command, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    vreport(command, format, args);
    va_end(args);
    return CLI_EXIT_RUNTIME;
}

int cli_status_error(const char *command, const char *what, cb_status status)
{
    return cli_runtime_error(command, "%s: %s", what, cb_status_message(status));
}

/* cli_quote and cli_clip (args.h). */
static const char *echo(cli_echo *out, const char *text, size_t length, int quoted)
{
    size_t shown = length;
    if (length > CLI_ECHO_LIMIT) {
        shown = CLI_ECHO_LIMIT;
        /* back to the start of a UTF-8 character: continuation bytes are 10xxxxxx */
        while (shown > 0 && ((unsigned char)text[shown] & 0xC0) == 0x80) --shown;
    }
    size_t used = 0;
    if (quoted) out->text[used++] = '\'';
    for (size_t k = 0; k < shown; ++k) {
        unsigned char c = (unsigned char)text[k];
        if (c < 0x20 || c == 0x7F) used += (size_t)snprintf(out->text + used, 5, "\\x%02x", c);
        else out->text[used++] = (char)c;
    }
    if (shown < length) {
        memcpy(out->text + used, "...", 3);
        used += 3;
    }
    if (quoted) out->text[used++] = '\'';
    out->text[used] = '\0';
    if (shown < length)
        snprintf(out->text + used, sizeof out->text - used, " (%zu bytes)", length);
    return out->text;
}

const char *cli_quote(cli_echo *out, const char *text, size_t length)
{
    return echo(out, text, length, 1);
}

const char *cli_clip(cli_echo *out, const char *text, size_t length)
{
    return echo(out, text, length, 0);
}

int cli_second_surface(const char *command, const cli_option *r2, const cli_option *plane,
                       double *value, int *code)
{
    if (r2->given == plane->given) {
        *code = cli_usage_error(command, "give exactly one of --r2 (sphere 2's radius) and "
                                "--plane (surface 2 a plane) (%s)",
                                r2->given ? "both given" : "none given");
        return 0;
    }
    *value = plane->given ? CB_PLANE : r2->number;
    return 1;
}

const char *cli_describe_pair(char *buffer, size_t size, const cb_law *law, double r1,
                              double r2, double volume)
{
    char surface[48];
    if (cb_is_plane(r2)) snprintf(surface, sizeof surface, "a plane");
    else snprintf(surface, sizeof surface, "r2 %.10g m", r2);
    snprintf(buffer, size, "law %s (gamma %.10g N/m, theta %.10g deg), r1 %.10g m, %s, "
             "volume %.10g m^3", cb_model_name(law->model), law->surface_tension,
             law->contact_angle * 180.0 / CB_PI, r1, surface, volume);
    return buffer;
}

/* A whole number, decimal digits with an optional sign. */
static int parse_integer(const char *text, long *value)
{
    char *end = NULL;
    if (!text || !*text || isspace((unsigned char)text[0])) return 0;
    errno = 0;
    long v = strtol(text, &end, 10);
    if (end == text || *end != '\0' || errno == ERANGE) return 0;
    *value = v;
    return 1;
}

static int is_option(const char *arg) { return arg[0] == '-' && arg[1] == '-' && arg[2] != '\0'; }

/* The allowed option names, comma separated, into buffer. */
static const char *option_names(const cli_request *request, char *buffer, size_t size)
{
    size_t used = 0;
    buffer[0] = '\0';
    for (size_t k = 0; k < request->n_options && used < size; ++k) {
        int n = snprintf(buffer + used, size - used, "%s%s", k ? ", " : "",
                         request->options[k].name);
        if (n < 0) break;
        used += (size_t)n;
    }
    if (request->n_options == 0) snprintf(buffer, size, "(none)");
    return buffer;
}

/* Check one value against its option's kind and store it. */
static int take_value(const cli_request *request, cli_option *option, const char *value)
{
    const char *cmd = request->command;
    double number = 0.0;
    cli_echo shown; /* the value as a message shows it */
    size_t length = strlen(value);
    switch (option->kind) {
    case CLI_TEXT:
        if (!*value) return cli_usage_error(cmd, "option %s needs a non-empty value", option->name);
        option->text = value;
        break;
    case CLI_INTEGER: {
        long integer = 0;
        if (!parse_integer(value, &integer))
            return cli_usage_error(cmd, "option %s: %s is not a whole number", option->name,
                                   cli_quote(&shown, value, length));
        if (integer < option->minimum || integer > option->maximum)
            return cli_usage_error(cmd, "option %s: %ld is out of range: allowed %ld to %ld",
                                   option->name, integer, option->minimum, option->maximum);
        option->integer = integer;
        option->number = (double)integer;
        break;
    }
    case CLI_FLAG: break;
    default:
        if (!cb_parse_number(value, &number))
            return cli_usage_error(cmd, "option %s: %s is not a decimal number within double range",
                                   option->name, cli_quote(&shown, value, length));
        if (option->kind == CLI_POSITIVE && !(number > 0.0))
            return cli_usage_error(cmd, "option %s: %s must be > 0 (%s)", option->name,
                                   cli_clip(&shown, value, length), option->meaning);
        if (option->kind == CLI_NONNEGATIVE && !(number >= 0.0))
            return cli_usage_error(cmd, "option %s: %s must be >= 0 (%s)", option->name,
                                   cli_clip(&shown, value, length), option->meaning);
        if (option->kind == CLI_FRACTION && !(number >= 0.0 && number <= 1.0))
            return cli_usage_error(cmd, "option %s: %s must be in [0, 1] (%s)", option->name,
                                   cli_clip(&shown, value, length), option->meaning);
        if (option->kind == CLI_ANGLE && !(number >= 0.0 && number < 90.0))
            return cli_usage_error(cmd, "option %s: %s must satisfy 0 <= angle < 90 degrees (%s)",
                                   option->name, cli_clip(&shown, value, length),
                                   option->meaning);
        option->number = number;
        break;
    }
    option->given = 1;
    return CLI_EXIT_OK;
}

/* LAW [keyword value]... at the front of argv; returns the index after it. */
static int parse_law(cli_request *request, int argc, char **argv, int *next)
{
    const char *cmd = request->command;
    if (argc < 1 || is_option(argv[0]))
        return cli_usage_error(cmd, "missing law: the first argument must be one of %s",
                               cb_law_names());
    cb_model model;
    cli_echo shown;
    if (cb_model_from_name(argv[0], &model) != CB_OK)
        return cli_usage_error(cmd, "unknown law %s: allowed %s",
                               cli_quote(&shown, argv[0], strlen(argv[0])), cb_law_names());
    cb_status status = cb_law_init(request->law, model, CLI_DEFAULT_GAMMA, CLI_DEFAULT_THETA);
    if (status != CB_OK) return cli_status_error(cmd, "law initialisation", status);

    int i = 1;
    cb_keywords_given given = {0};
    while (i < argc && !is_option(argv[i]) && strcmp(argv[i], "--") != 0) {
        const char *keyword = argv[i];
        const char *value = (i + 1 < argc && !is_option(argv[i + 1])) ? argv[i + 1] : NULL;
        cb_message msg;
        msg.text[0] = '\0';
        if (!value) {
            /* Tell an unknown keyword from a known one without its value: ask the
             * parser about the keyword with a value no keyword accepts. */
            cb_law scratch = *request->law;
            status = cb_law_configure(&scratch, keyword, "", &msg);
            if (status == CB_ERR_UNKNOWN_KEYWORD && strncmp(msg.text, "unknown keyword", 15) == 0)
                return cli_usage_error(cmd, "law %s: %s", argv[0], msg.text);
            return cli_usage_error(cmd, "law %s: keyword %s needs a value", argv[0],
                                   cli_quote(&shown, keyword, strlen(keyword)));
        }
        status = cb_law_configure_once(request->law, &given, keyword, value, &msg);
        if (status != CB_OK)
            return cli_usage_error(cmd, "law %s: %s", argv[0],
                                   msg.text[0] ? msg.text : cb_status_message(status));
        i += 2;
    }
    *next = i;
    return CLI_EXIT_OK;
}

static int parse(cli_request *request, int argc, char **argv)
{
    const char *cmd = request->command;
    char names[512];
    cli_echo shown;
    int i = 0;
    request->positional = NULL;
    if (request->wants_law) {
        int code = parse_law(request, argc, argv, &i);
        if (code != CLI_EXIT_OK) return code;
    }

    int options_ended = 0;
    for (; i < argc; ++i) {
        const char *arg = argv[i];
        if (!options_ended && strcmp(arg, "--") == 0) {
            options_ended = 1;
            continue;
        }
        if (options_ended || !is_option(arg)) {
            if (request->positional_name && !request->positional) {
                request->positional = arg;
                continue;
            }
            if (request->wants_law)
                return cli_usage_error(cmd,
                                       "unexpected argument %s: law keywords go right after "
                                       "the law name, options start with --",
                                       cli_quote(&shown, arg, strlen(arg)));
            return cli_usage_error(cmd, "unexpected argument %s",
                                   cli_quote(&shown, arg, strlen(arg)));
        }

        /* --name value, or --name=value */
        const char *equals = strchr(arg, '=');
        size_t length = equals ? (size_t)(equals - arg) : strlen(arg);
        cli_option *option = NULL;
        for (size_t k = 0; k < request->n_options; ++k) {
            const char *name = request->options[k].name;
            if (strlen(name) == length && strncmp(name, arg, length) == 0) {
                option = &request->options[k];
                break;
            }
        }
        if (!option)
            return cli_usage_error(cmd, "unknown option %s: allowed %s",
                                   cli_quote(&shown, arg, length),
                                   option_names(request, names, sizeof names));
        if (option->given) return cli_usage_error(cmd, "option %s is given twice", option->name);
        if (option->kind == CLI_FLAG) {
            if (equals) return cli_usage_error(cmd, "option %s takes no value", option->name);
            option->given = 1;
            continue;
        }
        const char *value = NULL;
        if (equals) value = equals + 1;
        else if (i + 1 < argc && !is_option(argv[i + 1])) value = argv[++i];
        else
            return cli_usage_error(cmd, "option %s needs a value (%s)", option->name,
                                   option->meaning);
        int code = take_value(request, option, value);
        if (code != CLI_EXIT_OK) return code;
    }

    for (size_t k = 0; k < request->n_options; ++k) {
        const cli_option *option = &request->options[k];
        if (option->required && !option->given)
            return cli_usage_error(cmd, "missing option %s (%s)", option->name, option->meaning);
    }
    return CLI_EXIT_OK;
}

static int prepare_law(const char *command, cb_law *law);

int cli_parse(cli_request *request, int argc, char **argv, int *exit_code)
{
    for (int i = 1; i < argc && strcmp(argv[i], "--") != 0; ++i) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(request->usage, stdout);
            if (request->wants_law) cli_print_law_help(stdout);
            *exit_code = CLI_EXIT_OK;
            return 0;
        }
    }
    *exit_code = argc > 0 ? parse(request, argc - 1, argv + 1) : CLI_EXIT_USAGE;
    if (*exit_code == CLI_EXIT_OK && request->wants_law)
        *exit_code = prepare_law(request->command, request->law);
    return *exit_code == CLI_EXIT_OK;
}

/* Prepare the law (build what it derives). On failure prints the core's message and
 * returns CLI_EXIT_RUNTIME. */
static int prepare_law(const char *command, cb_law *law)
{
    cb_message msg;
    msg.text[0] = '\0';
    cb_status status = cb_law_prepare(law, &msg);
    if (status == CB_OK) return CLI_EXIT_OK;
    return cli_runtime_error(command, "law %s: %s", cb_model_name(law->model),
                             msg.text[0] ? msg.text : cb_status_message(status));
}

void cli_print_law_help(FILE *out)
{
    fprintf(out,
            "\nLAW is one of:\n  %s\n"
            "Law keywords (the same as in the LAMMPS and LIGGGHTS bindings):\n"
            "  gamma N/m        surface tension, > 0 (default %g, water)\n"
            "  theta DEG        contact angle, 0 <= theta < 90 degrees (default 0)\n"
            "  rupture RULE     lian | willett | willett/unequal | default (table also: exact)\n"
            "  overlap RULE     contact | none: the force in overlap (default contact)\n"
            "  validity RULE    extend | strict: outside the law's validity (default extend)\n",
            cb_law_names(), CLI_DEFAULT_GAMMA);
    /* each law's own keywords, as its registry row lists them */
    for (int m = 0; m < CB_MODEL_COUNT; ++m) {
        for (int k = 0; k < cb_law_keyword_count((cb_model)m); ++k) {
            const cb_law_keyword *keyword = cb_law_keyword_of((cb_model)m, k);
            char usage[64];
            snprintf(usage, sizeof usage, "%s VALUE", keyword->name);
            fprintf(out, "  %-16s %s, %s only (default %s)\n", usage, keyword->description,
                    cb_model_name((cb_model)m), keyword->default_text);
        }
    }
}

void cli_print_number(FILE *out, double value) { fprintf(out, "%.17g", value); }

void cli_print_row(FILE *out, size_t n, const double *values)
{
    for (size_t k = 0; k < n; ++k) {
        if (k) fputc(',', out);
        cli_print_number(out, values[k]);
    }
    fputc('\n', out);
}
