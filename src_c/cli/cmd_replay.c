/* cmd_replay.c — `capbridge replay`: recompute every bridge force of an engine's per-pair
 * dump with the law and report the largest difference.
 *
 * Input: a LAMMPS `dump local` file (ITEM: lines are headers; only the rows of each
 * "ITEM: ENTRIES" section are data, checked against "ITEM: NUMBER OF ENTRIES"), or a plain
 * table, whitespace or comma separated, with '#' comment lines and a header line (the first
 * other line, when one of its fields is not a number). */
#include "args.h"
#include "commands.h"

#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char usage[] =
    "usage: capbridge replay LAW [keyword value]... --columns LIST [--r1 M] [--r2 M]\n"
    "                        [--volume M3] [--tolerance REL] FILE\n"
    "\n"
    "Recomputes the capillary force of every row of FILE (- for standard input) with LAW\n"
    "and compares it with the force the file holds.\n"
    "FILE is a LAMMPS 'dump local' file (rows of the ITEM: ENTRIES sections), or a table\n"
    "separated by blanks or commas with a header line and '#' comments.\n"
    "  --columns LIST  NAME=INDEX,... the 1-based column of each quantity, e.g.\n"
    "                  r1=3,r2=4,volume=5,gap=6,force=7. Names: r1, r2, volume (m, m^3),\n"
    "                  gap (surface distance) or distance (centre distance; gap = distance\n"
    "                  - r1 - r2), force (the capillary attraction, >= 0). Required: force,\n"
    "                  gap or distance; r1, r2, volume unless given as constants.\n"
    "  --r1, --r2, --volume  a constant instead of a column\n"
    "  --tolerance REL fail (exit 1) if the largest relative difference exceeds REL\n"
    "A row with volume 0 holds no bridge: its law force is 0.\n"
    "Relative difference: |F_law - F_file| / max(|F_law|, |F_file|) (0 when both are 0).\n"
    "Prints CSV with a header:\n"
    "  rows,bridges,max_relative_difference,row,line,file_force,law_force,\n"
    "  max_absolute_difference\n"
    "rows: data rows read; bridges: rows with force > 0 or volume > 0; row, line: the data\n"
    "row (1-based) and the file line of the largest relative difference, and the two\n"
    "forces there. Exit 1 if a row is malformed (each is named on stderr with its line).\n";

enum { R1, R2, VOLUME, COLUMNS, TOLERANCE, N_OPTIONS };

enum { COL_R1, COL_R2, COL_VOLUME, COL_GAP, COL_DISTANCE, COL_FORCE, N_COLUMNS };
static const char *const column_names[N_COLUMNS] = {"r1",  "r2",       "volume",
                                                     "gap", "distance", "force"};
#define COLUMN_NAME_LIST "r1, r2, volume, gap, distance, force"
#define MAX_COLUMN 100000L
#define MAX_REPORTED 10

/* --columns NAME=INDEX,...: column[k] = 1-based index, 0 where not given. */
static int parse_columns(const char *spec, long column[N_COLUMNS])
{
    const char *cmd = "replay";
    const char *item = spec;
    cli_echo shown;
    for (int k = 0; k < N_COLUMNS; ++k) column[k] = 0;
    for (;;) {
        const char *end = strchr(item, ',');
        size_t length = end ? (size_t)(end - item) : strlen(item);
        if (length == 0)
            return cli_usage_error(cmd, "--columns %s: an empty entry",
                                   cli_quote(&shown, spec, strlen(spec)));
        const char *equals = memchr(item, '=', length);
        if (!equals)
            return cli_usage_error(cmd, "--columns entry %s must be NAME=INDEX (names: %s)",
                                   cli_quote(&shown, item, length), COLUMN_NAME_LIST);
        size_t name_length = (size_t)(equals - item);
        int which = -1;
        for (int k = 0; k < N_COLUMNS; ++k)
            if (strlen(column_names[k]) == name_length &&
                strncmp(column_names[k], item, name_length) == 0)
                which = k;
        if (which < 0)
            return cli_usage_error(cmd, "--columns: unknown quantity %s: allowed %s",
                                   cli_quote(&shown, item, name_length), COLUMN_NAME_LIST);
        /* the column: decimal digits only (no blank, no sign), 1 to MAX_COLUMN */
        const char *digits = equals + 1;
        size_t digit_length = length - name_length - 1;
        long index = 0;
        for (size_t k = 0; k < digit_length && index <= MAX_COLUMN; ++k)
            index = digits[k] >= '0' && digits[k] <= '9' ? 10 * index + (digits[k] - '0')
                                                         : MAX_COLUMN + 1;
        if (index < 1 || index > MAX_COLUMN)
            return cli_usage_error(cmd,
                                   "--columns %s: the column must be a whole number from 1 "
                                   "to %ld, in digits",
                                   cli_quote(&shown, item, length), MAX_COLUMN);
        if (column[which])
            return cli_usage_error(cmd, "--columns: '%s' is given twice", column_names[which]);
        column[which] = index;
        if (!end) break;
        item = end + 1;
    }
    return CLI_EXIT_OK;
}

/* One line at a time, any length, without the line end. A NUL byte cannot be told from
 * the end of the text, so a line holding one is marked (nul_at) for the caller to refuse. */
typedef struct line_reader {
    FILE *file;
    char *text;
    size_t capacity;
    long number;
    size_t nul_at; /* 1-based position of the line's first NUL byte, 0 if none */
} line_reader;

/* 1: a line; 0: end of file; -1: out of memory or a read error. */
static int read_line(line_reader *reader)
{
    size_t used = 0;
    int c;
    reader->nul_at = 0;
    while ((c = getc(reader->file)) != EOF && c != '\n') {
        if (used + 1 >= reader->capacity) {
            size_t capacity = reader->capacity ? 2 * reader->capacity : 256;
            char *bigger = realloc(reader->text, capacity);
            if (!bigger) return -1;
            reader->text = bigger;
            reader->capacity = capacity;
        }
        if (c == '\0' && !reader->nul_at) reader->nul_at = used + 1;
        reader->text[used++] = (char)c;
    }
    if (ferror(reader->file)) return -1;
    if (c == EOF && used == 0) return 0;
    if (!reader->text) { /* an empty line first */
        reader->text = malloc(256);
        if (!reader->text) return -1;
        reader->capacity = 256;
    }
    while (used > 0 && reader->text[used - 1] == '\r') --used;
    reader->text[used] = '\0';
    ++reader->number;
    return 1;
}

static int is_blank_char(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

static int is_blank_line(const char *text)
{
    while (*text && is_blank_char(*text)) ++text;
    return *text == '\0';
}

/* Split text in place: comma separated (fields trimmed) if it holds a comma, else on
 * blanks. Stores the first `room` fields; returns the number of fields. */
static long split_fields(char *text, char **field, long room)
{
    long count = 0;
    if (strchr(text, ',')) {
        char *start = text;
        for (;;) {
            char *comma = strchr(start, ',');
            if (comma) *comma = '\0';
            while (is_blank_char(*start)) ++start;
            char *end = start + strlen(start);
            while (end > start && is_blank_char(end[-1])) *--end = '\0';
            if (count < room) field[count] = start;
            ++count;
            if (!comma) break;
            start = comma + 1;
        }
        return count;
    }
    char *cursor = text;
    for (;;) {
        while (*cursor && is_blank_char(*cursor)) ++cursor;
        if (!*cursor) break;
        if (count < room) field[count] = cursor;
        ++count;
        while (*cursor && !is_blank_char(*cursor)) ++cursor;
        if (*cursor) *cursor++ = '\0';
    }
    return count;
}

typedef struct replay {
    const cb_law *law;
    const char *file_name;
    long column[N_COLUMNS];
    double constant[N_COLUMNS]; /* r1, r2, volume when not columns */
    long needed;                /* the largest column index used */
    char **field;
    /* results */
    long rows, bridges, malformed;
    double max_relative, max_absolute;
    long max_row, max_line;
    double max_file_force, max_law_force;
} replay;

static void row_problem(replay *r, long line, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* A malformed row: the first MAX_REPORTED are named on stderr with their line. */
static void row_problem(replay *r, long line, const char *format, ...)
{
    if (++r->malformed > MAX_REPORTED) return;
    va_list args;
    cli_echo shown;
    va_start(args, format);
    fprintf(stderr, "capbridge replay: %s:%ld: ",
            cli_clip(&shown, r->file_name, strlen(r->file_name)), line);
    vfprintf(stderr, format, args);
    fputc('\n', stderr);
    va_end(args);
}

/* Evaluate one data row (text is modified). */
static void replay_row(replay *r, char *text, long line)
{
    double value[N_COLUMNS];
    ++r->rows;
    long count = split_fields(text, r->field, r->needed);
    for (int k = 0; k < N_COLUMNS; ++k) {
        value[k] = r->constant[k];
        if (!r->column[k]) continue;
        if (r->column[k] > count) {
            row_problem(r, line, "%ld field%s, but column %ld (%s) is needed", count,
                        count == 1 ? "" : "s", r->column[k], column_names[k]);
            return;
        }
        const char *field = r->field[r->column[k] - 1];
        if (!cb_parse_number(field, &value[k])) {
            cli_echo shown;
            row_problem(r, line, "column %ld (%s) is %s, not a decimal number within double range",
                        r->column[k], column_names[k], cli_quote(&shown, field, strlen(field)));
            return;
        }
    }
    if (!(value[COL_R1] > 0.0) || !(value[COL_R2] > 0.0)) {
        row_problem(r, line, "%s = %.17g: a radius must be > 0",
                    value[COL_R1] > 0.0 ? "r2" : "r1",
                    value[COL_R1] > 0.0 ? value[COL_R2] : value[COL_R1]);
        return;
    }
    if (value[COL_VOLUME] < 0.0) {
        row_problem(r, line, "volume = %.17g: must be >= 0", value[COL_VOLUME]);
        return;
    }
    double gap = r->column[COL_GAP] ? value[COL_GAP]
                                    : value[COL_DISTANCE] - (value[COL_R1] + value[COL_R2]);
    double file_force = value[COL_FORCE], law_force = 0.0;
    if (file_force > 0.0 || value[COL_VOLUME] > 0.0) ++r->bridges;
    if (value[COL_VOLUME] > 0.0) {
        cb_status status = cb_force(r->law, value[COL_R1], value[COL_R2], value[COL_VOLUME], gap,
                                    &law_force, NULL);
        if (status != CB_OK) {
            row_problem(r, line, "the law gives no force at gap %.17g: %s", gap,
                        cb_status_message(status));
            return;
        }
    }
    double absolute = fabs(law_force - file_force);
    double scale = fmax(fabs(law_force), fabs(file_force));
    double relative = scale > 0.0 ? absolute / scale : 0.0;
    if (absolute > r->max_absolute) r->max_absolute = absolute;
    if (relative > r->max_relative) {
        r->max_relative = relative;
        r->max_row = r->rows;
        r->max_line = line;
        r->max_file_force = file_force;
        r->max_law_force = law_force;
    }
}

/* Does every field this replay needs read as a number? (Tells a header from data.) */
static int numeric_row(replay *r, const char *text)
{
    size_t length = strlen(text) + 1;
    char *copy = malloc(length);
    if (!copy) return 0;
    memcpy(copy, text, length);
    long count = split_fields(copy, r->field, r->needed);
    int numeric = count >= r->needed;
    for (long k = 0; numeric && k < r->needed; ++k) {
        double ignored;
        numeric = cb_parse_number(r->field[k], &ignored);
    }
    free(copy);
    return numeric;
}

/* The count of ITEM: NUMBER OF ENTRIES: decimal digits only (LAMMPS writes a plain
 * integer), at most LONG_MAX. */
static int parse_count(const char *text, long *count)
{
    long value = 0;
    const char *digit = text;
    for (; *digit >= '0' && *digit <= '9'; ++digit) {
        if (value > (LONG_MAX - (*digit - '0')) / 10) return 0;
        value = 10 * value + (*digit - '0');
    }
    if (digit == text || *digit != '\0') return 0;
    *count = value;
    return 1;
}

/* Where a LAMMPS dump is: its section, and the count its NUMBER OF ENTRIES announced. */
typedef struct dump_state {
    int in_entries;                 /* inside an ITEM: ENTRIES section */
    int expect_count;               /* the next line is the NUMBER OF ENTRIES */
    long announced, announced_line; /* the count (-1: none for this section) and its line */
    long entries, entries_line;     /* rows of this ENTRIES section, and its ITEM: line */
} dump_state;

/* The end of an ENTRIES section (at the next ITEM: line or the end of the file): its rows
 * against the count announced. */
static void dump_section_end(replay *r, const dump_state *d)
{
    if (d->in_entries && d->announced >= 0 && d->entries != d->announced)
        row_problem(r, d->entries_line,
                    "ITEM: NUMBER OF ENTRIES (line %ld) announced %ld rows, this ENTRIES "
                    "section has %ld",
                    d->announced_line, d->announced, d->entries);
}

/* An ITEM: line: ends the section before it and starts the next. */
static void dump_item(replay *r, dump_state *d, const char *text, long line)
{
    const char *item = text + 5;
    while (is_blank_char(*item)) ++item;
    if (d->expect_count) {
        row_problem(r, line, "ITEM: NUMBER OF ENTRIES is not followed by a count");
        d->expect_count = 0;
    }
    dump_section_end(r, d);
    if (d->in_entries) d->announced = -1;
    d->in_entries = strncmp(item, "ENTRIES", 7) == 0;
    d->expect_count = strncmp(item, "NUMBER OF ENTRIES", 17) == 0;
    if (d->in_entries) {
        d->entries = 0;
        d->entries_line = line;
    }
}

/* A line of a dump (text is modified): an ITEM: line, the count after NUMBER OF ENTRIES, a
 * row of an ENTRIES section, or a line of another section (not data). */
static void dump_line(replay *r, dump_state *d, char *text, long line)
{
    if (strncmp(text, "ITEM:", 5) == 0) {
        dump_item(r, d, text, line);
        return;
    }
    if (d->expect_count) {
        d->expect_count = 0;
        if (!parse_count(text, &d->announced)) {
            cli_echo shown;
            row_problem(r, line,
                        "ITEM: NUMBER OF ENTRIES: %s is not a count: allowed a whole number "
                        "from 0 to %ld, in digits",
                        cli_quote(&shown, text, strlen(text)), LONG_MAX);
            return;
        }
        d->announced_line = line;
        return;
    }
    if (d->in_entries) {
        ++d->entries;
        replay_row(r, text, line);
    }
}

/* A dump line refused unread (a NUL byte): it stands for the count line or a row. */
static void dump_refused_line(dump_state *d)
{
    if (d->expect_count) d->expect_count = 0;
    else if (d->in_entries) ++d->entries;
}

/* The end of a dump: its last section's rows, and a count still awaited. */
static void dump_end(replay *r, const dump_state *d, long last_line)
{
    dump_section_end(r, d);
    if (d->expect_count)
        row_problem(r, last_line, "ITEM: NUMBER OF ENTRIES is not followed by a count");
}

/* A line of a plain table (text is modified): a '#' comment, the header (the first other
 * line, when one of its fields is not a number), or a row. */
static void table_line(replay *r, int *header_seen, char *text, long line)
{
    if (text[0] == '#') return;
    if (!*header_seen) {
        *header_seen = 1;
        if (!numeric_row(r, text)) return;
    }
    replay_row(r, text, line);
}

/* Reads the whole file, a dump or a plain table by its first non-blank line; returns 0, or
 * -1 on a read or memory failure. */
static int replay_file(replay *r, FILE *file)
{
    line_reader reader = {file, NULL, 0, 0, 0};
    dump_state dump_at = {0, 0, -1, 0, 0, 0};
    int dump = -1; /* unknown until the first non-blank line */
    int header_seen = 0, got;
    while ((got = read_line(&reader)) == 1) {
        if (reader.nul_at) {
            row_problem(r, reader.number, "a NUL byte at character %zu: a line must be text",
                        reader.nul_at);
            if (dump == 1) dump_refused_line(&dump_at);
            continue;
        }
        if (is_blank_line(reader.text)) continue;
        if (dump < 0) dump = strncmp(reader.text, "ITEM:", 5) == 0;
        if (dump) dump_line(r, &dump_at, reader.text, reader.number);
        else table_line(r, &header_seen, reader.text, reader.number);
    }
    if (got == 0 && dump == 1) dump_end(r, &dump_at, reader.number);
    free(reader.text);
    return got < 0 ? -1 : 0;
}

/* The columns and constants of the command line, checked against each other. */
static int check_columns(const cli_option *options, const char *positional, replay *r)
{
    const char *name = "replay";
    int code = parse_columns(options[COLUMNS].text, r->column);
    if (code != CLI_EXIT_OK) return code;
    const int constant_option[3] = {R1, R2, VOLUME};
    for (int k = COL_R1; k <= COL_VOLUME; ++k) {
        const cli_option *option = &options[constant_option[k]];
        if (option->given && r->column[k])
            return cli_usage_error(name, "%s is both a column (--columns %s=%ld) and %s",
                                   column_names[k], column_names[k], r->column[k], option->name);
        if (!option->given && !r->column[k])
            return cli_usage_error(name, "missing %s: give --columns %s=INDEX or %s",
                                   column_names[k], column_names[k], option->name);
        r->constant[k] = option->number;
    }
    if (!r->column[COL_FORCE])
        return cli_usage_error(name, "--columns lacks force=INDEX (the capillary force column)");
    if (!r->column[COL_GAP] == !r->column[COL_DISTANCE])
        return cli_usage_error(name, "--columns needs exactly one of gap=INDEX, distance=INDEX");
    if (!positional) return cli_usage_error(name, "missing FILE (- for standard input)");
    return CLI_EXIT_OK;
}

int cmd_replay(int argc, char **argv)
{
    const char *name = "replay";
    cli_option options[N_OPTIONS] = {
        {.name = "--r1", .kind = CLI_POSITIVE, .meaning = "radius of sphere 1 [m] for every row"},
        {.name = "--r2", .kind = CLI_POSITIVE, .meaning = "radius of sphere 2 [m] for every row"},
        {.name = "--volume", .kind = CLI_NONNEGATIVE, .meaning = "bridge volume [m^3] for every row"},
        {.name = "--columns", .kind = CLI_TEXT, .required = 1,
         .meaning = "NAME=INDEX,... e.g. r1=3,r2=4,volume=5,gap=6,force=7"},
        {.name = "--tolerance", .kind = CLI_NONNEGATIVE,
         .meaning = "largest relative difference accepted"},
    };
    cb_law law;
    cli_request request = {name, usage, 1, &law, options, N_OPTIONS, "FILE", NULL};
    int code;
    if (!cli_parse(&request, argc, argv, &code)) return code;

    replay r;
    memset(&r, 0, sizeof r);
    r.max_relative = -1.0;
    code = check_columns(options, request.positional, &r);
    if (code != CLI_EXIT_OK) {
        cb_law_release(&law);
        return code;
    }
    for (int k = 0; k < N_COLUMNS; ++k)
        if (r.column[k] > r.needed) r.needed = r.column[k];

    r.law = &law;
    r.file_name = request.positional;
    FILE *file = strcmp(request.positional, "-") == 0 ? stdin : fopen(request.positional, "r");
    cli_echo quoted, clipped; /* the file name in a message */
    const char *quoted_name = cli_quote(&quoted, r.file_name, strlen(r.file_name));
    const char *clipped_name = cli_clip(&clipped, r.file_name, strlen(r.file_name));
    if (!file) {
        cb_law_release(&law);
        return cli_runtime_error(name, "cannot open %s", quoted_name);
    }
    r.field = malloc((size_t)r.needed * sizeof *r.field);
    int failed = !r.field || replay_file(&r, file) != 0;
    if (file != stdin) fclose(file);
    free(r.field);
    cb_law_release(&law);
    if (failed) return cli_runtime_error(name, "error reading %s", quoted_name);

    if (r.max_relative < 0.0) r.max_relative = 0.0;
    printf("rows,bridges,max_relative_difference,row,line,file_force,law_force,"
           "max_absolute_difference\n%ld,%ld,",
           r.rows, r.bridges);
    cli_print_number(stdout, r.max_relative);
    printf(",%ld,%ld,", r.max_row, r.max_line);
    double tail[3] = {r.max_file_force, r.max_law_force, r.max_absolute};
    cli_print_row(stdout, 3, tail);

    if (r.malformed > 0) {
        if (r.malformed > MAX_REPORTED)
            fprintf(stderr, "capbridge replay: ... and %ld more\n", r.malformed - MAX_REPORTED);
        return cli_runtime_error(name, "%s: %ld malformed row%s", clipped_name, r.malformed,
                                 r.malformed == 1 ? "" : "s");
    }
    if (r.rows == 0) return cli_runtime_error(name, "%s: no data rows", clipped_name);
    if (options[TOLERANCE].given && r.max_relative > options[TOLERANCE].number)
        return cli_runtime_error(name,
                                 "largest relative difference %.3g (row %ld, line %ld) exceeds "
                                 "--tolerance %g",
                                 r.max_relative, r.max_row, r.max_line,
                                 options[TOLERANCE].number);
    return CLI_EXIT_OK;
}
