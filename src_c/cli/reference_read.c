/* reference_read.c — read a reference_data CSV file back into curves. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "reference.h"

static int parse_row(char *line, cb_reference_curve_data *row, int *point, double *gap,
                     double *force)
{
    char *fields[14];
    int n = 0;
    for (char *token = strtok(line, ",\n"); token && n < 14; token = strtok(NULL, ",\n"))
        fields[n++] = token;
    if (n != 14) return 0;
    char *end;
    double values[13];
    for (int i = 1; i < 14; ++i) {
        values[i - 1] = strtod(fields[i], &end);
        if (end == fields[i] || *end != '\0') return 0;
    }
    snprintf(row->name, sizeof row->name, "%s", fields[0]);
    row->config.r1 = values[0];
    row->config.r2 = values[1];
    row->config.surface_tension = values[2];
    row->config.contact_angle = values[3];
    row->config.volume = values[4];
    row->rupture = values[5];
    *point = (int)values[6];
    *gap = values[7];
    *force = values[8];
    return 1;
}

long cb_reference_read(const char *path, cb_reference_curve_data **curves)
{
    FILE *file = fopen(path, "r");
    if (!file) {
        fprintf(stderr, "capbridge: cannot open reference file '%s'\n", path);
        return -1;
    }
    size_t capacity = 64, count = 0;
    cb_reference_curve_data *data = malloc(capacity * sizeof *data);
    char line[1024];
    long line_number = 0;
    int header_seen = 0;
    while (data && fgets(line, sizeof line, file)) {
        ++line_number;
        if (line[0] == '#' || line[0] == '\n') continue;
        if (!header_seen) {
            header_seen = strncmp(line, CB_REFERENCE_COLUMNS, strlen(CB_REFERENCE_COLUMNS)) == 0;
            if (header_seen) continue;
            fprintf(stderr, "capbridge: %s:%ld: expected the header '%s'\n", path, line_number,
                    CB_REFERENCE_COLUMNS);
            free(data);
            fclose(file);
            return -1;
        }
        cb_reference_curve_data row;
        int point = 0;
        double gap = 0, force = 0;
        if (!parse_row(line, &row, &point, &gap, &force) || point < 0 ||
            point >= CB_CURVE_POINTS) {
            fprintf(stderr, "capbridge: %s:%ld: malformed row\n", path, line_number);
            free(data);
            fclose(file);
            return -1;
        }
        if (point == 0) {
            if (count == capacity) {
                capacity *= 2;
                cb_reference_curve_data *grown = realloc(data, capacity * sizeof *data);
                if (!grown) {
                    free(data);
                    data = NULL;
                    break;
                }
                data = grown;
            }
            data[count++] = row;
        }
        if (count == 0) {
            fprintf(stderr, "capbridge: %s:%ld: a curve must start at point 0\n", path,
                    line_number);
            free(data);
            fclose(file);
            return -1;
        }
        data[count - 1].gap[point] = gap;
        data[count - 1].force[point] = force;
    }
    fclose(file);
    if (!data) {
        fprintf(stderr, "capbridge: out of memory reading '%s'\n", path);
        return -1;
    }
    for (size_t i = 0; i < count; ++i) data[i].config.name = data[i].name;
    *curves = data;
    return (long)count;
}
