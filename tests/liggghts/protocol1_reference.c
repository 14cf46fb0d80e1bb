/* protocol1_reference.c — Protocol 1's distribution of the capbridge core, computed
 * independently of LIGGGHTS, for tests/liggghts/protocol1_reference.py.
 *
 * usage: protocol1_reference LAW SURFACE_TENSION CONTACT_ANGLE_DEG TOTAL_LIQUID < ATOMS
 * ATOMS: one line per sphere, "id radius x y z" (the rest of a line is ignored).  Every pair
 * of spheres is offered to cb_protocol1_distribute (Richefeu 2007 eqs. 13-14), which decides
 * eligibility itself (gap <= the rupture distance of the volume it would receive), the
 * radii smaller first and the gap as LIGGGHTS forms it (sqrt of the squared distance minus
 * the radius sum).  Prints "alpha A", then "ID1 ID2 VOLUME" (ID1 < ID2) for every pair that
 * receives liquid, %.17g.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "capbridge.h"

#define MAX_ATOMS 1000

typedef struct sphere {
    long id;
    double radius, x[3];
} sphere;

static int read_spheres(sphere *s, size_t *n)
{
    char line[512];
    *n = 0;
    while (fgets(line, sizeof line, stdin)) {
        sphere a;
        if (sscanf(line, "%ld %lf %lf %lf %lf", &a.id, &a.radius, &a.x[0], &a.x[1], &a.x[2]) != 5)
            continue;
        if (*n == MAX_ATOMS) return 1;
        s[(*n)++] = a;
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc != 5) {
        fprintf(stderr, "usage: protocol1_reference LAW SURFACE_TENSION CONTACT_ANGLE_DEG "
                        "TOTAL_LIQUID < ATOMS\n");
        return 2;
    }
    static sphere s[MAX_ATOMS];
    size_t n = 0;
    if (read_spheres(s, &n) != 0 || n < 2) {
        fprintf(stderr, "protocol1_reference: 2 to %d spheres needed\n", MAX_ATOMS);
        return 2;
    }
    cb_model model;
    cb_law law;
    cb_message msg;
    msg.text[0] = '\0';
    if (cb_model_from_name(argv[1], &model) != CB_OK ||
        cb_law_init(&law, model, atof(argv[2]), atof(argv[3]) * CB_PI / 180.0) != CB_OK ||
        cb_law_prepare(&law, &msg) != CB_OK) {
        fprintf(stderr, "protocol1_reference: law %s: %s\n", argv[1], msg.text);
        return 2;
    }
    const size_t pairs = n * (n - 1) / 2;
    double *values = malloc(6 * pairs * sizeof *values);
    size_t *order = malloc(pairs * sizeof *order);
    long *ids = malloc(2 * pairs * sizeof *ids);
    if (!values || !order || !ids) return 2;
    double *r1 = values, *r2 = values + pairs, *gap = values + 2 * pairs;
    double *volume = values + 3 * pairs;
    cb_protocol1_work work = {values + 4 * pairs, values + 5 * pairs, order};
    size_t k = 0;
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j, ++k) {
            const double dx = s[i].x[0] - s[j].x[0], dy = s[i].x[1] - s[j].x[1],
                         dz = s[i].x[2] - s[j].x[2];
            const int swap = s[j].radius < s[i].radius;
            r1[k] = swap ? s[j].radius : s[i].radius;
            r2[k] = swap ? s[i].radius : s[j].radius;
            gap[k] = sqrt(dx * dx + dy * dy + dz * dz) - (s[i].radius + s[j].radius);
            ids[2 * k] = s[i].id < s[j].id ? s[i].id : s[j].id;
            ids[2 * k + 1] = s[i].id < s[j].id ? s[j].id : s[i].id;
        }
    double alpha = 0.0;
    const cb_status status =
        cb_protocol1_distribute(&law, pairs, r1, r2, gap, atof(argv[4]), work, volume, &alpha);
    if (status != CB_OK) {
        fprintf(stderr, "protocol1_reference: %s\n", cb_status_message(status));
        return 1;
    }
    printf("alpha %.17g\n", alpha);
    for (k = 0; k < pairs; ++k)
        if (volume[k] > 0.0) printf("%ld %ld %.17g\n", ids[2 * k], ids[2 * k + 1], volume[k]);
    free(values);
    free(order);
    free(ids);
    cb_law_release(&law);
    return 0;
}
