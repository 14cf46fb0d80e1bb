/* reference_read.c — read a reference_data CSV file back into curves.
 *
 * The file is what `capbridge reference` writes: '#' comment lines, the header
 * CB_REFERENCE_COLUMNS, then per configuration CB_CURVE_POINTS rows, points 0, 1, ... in
 * order, each repeating the configuration. Every field is checked (cmd_report divides by
 * the exact rupture distance and forces): a row that is not such a row is refused with its
 * line, what is wrong and what is allowed. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "reference.h"

#define FIELDS 14
#define LINE_LIMIT 1023 /* characters of a line; the rows of `capbridge reference` hold < 400 */

static const char *const field_names[FIELDS] = {
    "case",  "r1",  "r2",    "surface_tension", "contact_angle",  "volume",   "rupture_distance",
    "point", "gap", "force", "filling_angle1",  "filling_angle2", "pressure", "neck_radius"};
enum { F_R1 = 1, F_R2, F_TENSION, F_ANGLE, F_VOLUME, F_RUPTURE, F_POINT, F_GAP, F_FORCE };

typedef struct reader {
    FILE *file;
    const char *path;
    long line;
    char text[LINE_LIMIT + 1];
} reader;

/* "capbridge report: PATH:LINE: ..." on stderr; returns -1. */
static int problem(const reader *in, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static int problem(const reader *in, const char *format, ...)
{
    cli_echo shown;
    va_list args;
    va_start(args, format);
    fprintf(stderr, "capbridge report: %s:%ld: ", cli_clip(&shown, in->path, strlen(in->path)),
            in->line);
    vfprintf(stderr, format, args);
    fputc('\n', stderr);
    va_end(args);
    return -1;
}

/* The next line, without its end: 1; 0 at the end of the file; -1 (said) if it is too
 * long, holds a NUL byte or cannot be read. */
static int next_line(reader *in)
{
    size_t used = 0;
    int c;
    while ((c = getc(in->file)) != EOF && c != '\n') {
        if (used == LINE_LIMIT) {
            ++in->line;
            return problem(in, "line longer than %d characters: a reference row is shorter",
                           LINE_LIMIT);
        }
        if (c == '\0') {
            ++in->line;
            return problem(in, "a NUL byte at character %zu: a line must be text", used + 1);
        }
        in->text[used++] = (char)c;
    }
    if (ferror(in->file)) {
        ++in->line;
        return problem(in, "read error");
    }
    if (c == EOF && used == 0) return 0;
    while (used > 0 && in->text[used - 1] == '\r') --used;
    in->text[used] = '\0';
    ++in->line;
    return 1;
}

/* One row: the configuration into row, its point, gap and force; 0, or -1 (said) if it is
 * malformed. */
static int parse_row(reader *in, cb_reference_curve_data *row, int *point, double *gap,
                     double *force)
{
    char *field[FIELDS];
    int n = 0;
    for (char *start = in->text;; ++n) {
        char *comma = strchr(start, ',');
        if (n < FIELDS) field[n] = start;
        if (!comma) break;
        *comma = '\0';
        start = comma + 1;
    }
    ++n;
    if (n != FIELDS)
        return problem(in, "%d field%s: allowed %d, those of the header", n, n == 1 ? "" : "s",
                       FIELDS);
    cli_echo shown;
    const size_t name_limit = sizeof row->name - 1;
    size_t name_length = strlen(field[0]);
    if (name_length == 0 || name_length > name_limit)
        return problem(in, "case name of %zu characters: allowed 1 to %zu", name_length,
                       name_limit);
    memcpy(row->name, field[0], name_length + 1);

    /* the point index: digits only, 0 to CB_CURVE_POINTS - 1 */
    const char *digits = field[F_POINT];
    int index = digits[0] ? 0 : CB_CURVE_POINTS;
    for (const char *d = digits; *d && index < CB_CURVE_POINTS; ++d)
        index = *d >= '0' && *d <= '9' ? 10 * index + (*d - '0') : CB_CURVE_POINTS;
    if (index >= CB_CURVE_POINTS)
        return problem(in, "point %s is not a point index: allowed a whole number from 0 to %d",
                       cli_quote(&shown, digits, strlen(digits)), CB_CURVE_POINTS - 1);
    *point = index;

    double value[FIELDS];
    for (int k = 1; k < FIELDS; ++k) {
        if (k == F_POINT) continue;
        if (k == F_R2 && strcmp(field[k], "plane") == 0) { /* a wall (cmd_reference.c) */
            value[k] = CB_PLANE;
            continue;
        }
        if (!cb_parse_number(field[k], &value[k]))
            return problem(in, "%s %s is not a decimal number within double range",
                           field_names[k], cli_quote(&shown, field[k], strlen(field[k])));
    }
    /* the ranges cmd_report relies on: a configuration the exact solver takes, a positive
     * rupture distance and force (it divides by them), a gap from 0 to the rupture */
    for (int k = F_R1; k <= F_RUPTURE; ++k)
        if (k != F_ANGLE && !(value[k] > 0.0))
            return problem(in, "%s = %.17g: allowed > 0", field_names[k], value[k]);
    if (!(value[F_ANGLE] >= 0.0 && value[F_ANGLE] < 90.0))
        return problem(in, "contact_angle = %.17g: allowed 0 <= contact_angle < 90 (degrees)",
                       value[F_ANGLE]);
    if (!(value[F_GAP] >= 0.0 && value[F_GAP] <= value[F_RUPTURE]))
        return problem(in, "gap = %.17g: allowed 0 to the rupture_distance %.17g", value[F_GAP],
                       value[F_RUPTURE]);
    if (!(value[F_FORCE] > 0.0))
        return problem(in, "force = %.17g: allowed > 0 (the exact bridge's attraction)",
                       value[F_FORCE]);
    row->config.r1 = value[F_R1];
    row->config.r2 = value[F_R2];
    row->config.surface_tension = value[F_TENSION];
    row->config.contact_angle = value[F_ANGLE];
    row->config.volume = value[F_VOLUME];
    row->rupture = value[F_RUPTURE];
    *gap = value[F_GAP];
    *force = value[F_FORCE];
    return 0;
}

/* The field in which a row's configuration differs from its curve's, or -1. */
static int differing_field(const cb_reference_curve_data *curve, const cb_reference_curve_data *row)
{
    if (strcmp(curve->name, row->name) != 0) return 0;
    const double a[6] = {curve->config.r1, curve->config.r2, curve->config.surface_tension,
                         curve->config.contact_angle, curve->config.volume, curve->rupture};
    const double b[6] = {row->config.r1, row->config.r2, row->config.surface_tension,
                         row->config.contact_angle, row->config.volume, row->rupture};
    for (int k = 0; k < 6; ++k)
        if (a[k] != b[k]) return F_R1 + k;
    return -1;
}

/* Read the rows after the header into *data (count curves, capacity allocated); 0 or -1. */
static int read_curves(reader *in, cb_reference_curve_data **data, size_t *count,
                       size_t *capacity)
{
    int next_point = CB_CURVE_POINTS; /* the point the current curve needs next */
    long first_line = 0;              /* the line of its point 0 */
    int got;
    while ((got = next_line(in)) == 1) {
        if (in->text[0] == '#' || in->text[0] == '\0') continue;
        cb_reference_curve_data row;
        int point = 0;
        double gap = 0.0, force = 0.0;
        if (parse_row(in, &row, &point, &gap, &force) != 0) return -1;
        cb_reference_curve_data *curve = *count ? &(*data)[*count - 1] : NULL;
        if (point == 0 && curve && next_point < CB_CURVE_POINTS)
            return problem(in, "point 0 of %s starts a curve while %s (line %ld) ends at point "
                           "%d: every curve needs points 0 to %d in order",
                           row.name, curve->name, first_line, next_point - 1,
                           CB_CURVE_POINTS - 1);
        if (point != 0 && point != next_point)
            return problem(in, "point %d of %s: expected point %d: every curve needs points 0 "
                           "to %d in order",
                           point, row.name, next_point < CB_CURVE_POINTS ? next_point : 0,
                           CB_CURVE_POINTS - 1);
        if (point == 0) {
            if (*count == *capacity) {
                size_t grown_capacity = *capacity ? 2 * *capacity : 64;
                cb_reference_curve_data *grown = realloc(*data, grown_capacity * sizeof **data);
                if (!grown) return problem(in, "out of memory");
                *data = grown;
                *capacity = grown_capacity;
            }
            curve = &(*data)[(*count)++];
            *curve = row;
            first_line = in->line;
        } else {
            int k = differing_field(curve, &row);
            if (k >= 0)
                return problem(in, "%s differs from line %ld, point 0 of %s: every row of a "
                               "curve repeats its configuration",
                               field_names[k], first_line, curve->name);
        }
        curve->gap[point] = gap;
        curve->force[point] = force;
        next_point = point + 1;
    }
    if (got < 0) return -1;
    if (*count == 0)
        return problem(in, "no curves: a reference file holds at least one (%d rows, points 0 "
                       "to %d, per curve after the header)",
                       CB_CURVE_POINTS, CB_CURVE_POINTS - 1);
    if (next_point < CB_CURVE_POINTS)
        return problem(in, "curve %s (line %ld) ends at point %d: every curve needs points 0 "
                       "to %d in order",
                       (*data)[*count - 1].name, first_line, next_point - 1,
                       CB_CURVE_POINTS - 1);
    return 0;
}

long cb_reference_read(const char *path, cb_reference_curve_data **curves)
{
    reader in = {NULL, path, 0, {0}};
    cli_echo shown;
    in.file = fopen(path, "r");
    if (!in.file) {
        fprintf(stderr, "capbridge report: cannot open reference file %s\n",
                cli_quote(&shown, path, strlen(path)));
        return -1;
    }
    cb_reference_curve_data *data = NULL;
    size_t count = 0, capacity = 0;
    int got;
    while ((got = next_line(&in)) == 1 && (in.text[0] == '#' || in.text[0] == '\0')) continue;
    int status = got < 0 ? -1 : 0;
    if (status == 0 && (got == 0 || strcmp(in.text, CB_REFERENCE_COLUMNS) != 0)) {
        if (got == 0) in.line++;
        status = problem(&in, "expected the header %s", CB_REFERENCE_COLUMNS);
    }
    if (status == 0) status = read_curves(&in, &data, &count, &capacity);
    fclose(in.file);
    if (status != 0) {
        free(data);
        return -1;
    }
    for (size_t i = 0; i < count; ++i) data[i].config.name = data[i].name;
    *curves = data;
    return (long)count;
}
