/* protocol3_reference.c — one bridge's rupture under Protocol 3, computed with the capbridge
 * core independently of LIGGGHTS, for tests/liggghts/protocol3_receiver.py.
 *
 * usage: protocol3_reference ID1 ID2 < SPHERES
 * SPHERES: the spheres at the start, one line "id radius x y z free_liquid" each, a line
 * "---", then the same spheres (same order) at the step the bridge of ID1 and ID2 breaks,
 * "id radius x y z".  Computed:
 *   - formation at the start: every pair that touches forms a bridge; a grain with k of them
 *     offers each 1/k of its free liquid (cb_protocol_grain_step) and a bridge takes the two
 *     offers (cb_protocol2_take);
 *   - the rupture of ID1-ID2 (every other bridge held): its liquid split in proportion to
 *     the diameters (cb_protocol2_release), each share to its grain's receiver, the lowest
 *     contact point on its lower hemisphere (cb_protocol3_receiver, Richefeu 2007 §4.2), of
 *     equal heights the smaller partner ID (capbridge.h, cb_protocol3_better): the bridges
 *     are handed to cb_protocol3_receiver in the order of their partner IDs, and it keeps
 *     the first of equal heights; without a receiver the share is free liquid
 *     (cb_protocol_grain_step).
 * Prints "receiver ID PARTNER" (0: none) for ID1 and ID2, then "bridge I J VOLUME" (I < J)
 * for every bridge held after the rupture and "free ID VOLUME" for every sphere, %.17g.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capbridge.h"

#define MAX_SPHERES 64

typedef struct sphere {
    long id;
    double radius, x[3], free_liquid;
} sphere;

typedef struct bridge {
    int a, b;  /* sphere indices, a < b */
    double volume;
} bridge;

static double distance(const sphere *p, const sphere *q)
{
    const double dx = p->x[0] - q->x[0], dy = p->x[1] - q->x[1], dz = p->x[2] - q->x[2];
    return sqrt(dx * dx + dy * dy + dz * dz);
}

/* Two blocks of spheres separated by "---"; the second gives positions only. */
static int read_spheres(sphere *start, sphere *now, size_t *n)
{
    char line[512];
    size_t second = 0;
    int in_second = 0;
    *n = 0;
    while (fgets(line, sizeof line, stdin)) {
        sphere s;
        if (strncmp(line, "---", 3) == 0) {
            in_second = 1;
            continue;
        }
        if (!in_second) {
            if (sscanf(line, "%ld %lf %lf %lf %lf %lf", &s.id, &s.radius, &s.x[0], &s.x[1],
                       &s.x[2], &s.free_liquid) != 6)
                continue;
            if (*n == MAX_SPHERES) return 1;
            start[(*n)++] = s;
        } else {
            if (sscanf(line, "%ld %lf %lf %lf %lf", &s.id, &s.radius, &s.x[0], &s.x[1],
                       &s.x[2]) != 5)
                continue;
            if (second == *n || s.id != start[second].id) return 1;
            s.free_liquid = 0.0;
            now[second++] = s;
        }
    }
    return second == *n && *n >= 2 ? 0 : 1;
}

static void check(const cb_status status, const char *what)
{
    if (status == CB_OK) return;
    fprintf(stderr, "protocol3_reference: %s: %s\n", what, cb_status_message(status));
    exit(1);
}

/* A pair that forms a bridge at the start: it touches and has liquid. */
static int forms(const sphere *p, const sphere *q)
{
    return distance(p, q) < p->radius + q->radius && p->free_liquid + q->free_liquid > 0.0;
}

/* Formation at the start: the bridges of the touching pairs and the free liquid left. */
static size_t form_bridges(sphere *s, const size_t n, bridge *bridges)
{
    double offer[MAX_SPHERES];
    int contacts[MAX_SPHERES] = {0};
    size_t count = 0;
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j)
            if (forms(&s[i], &s[j])) {
                ++contacts[i];
                ++contacts[j];
                bridges[count].a = (int)i;
                bridges[count++].b = (int)j;
            }
    for (size_t i = 0; i < n; ++i) {
        double deposit = 0.0;
        check(cb_protocol_grain_step(0.0, 0, contacts[i], &s[i].free_liquid, &deposit,
                                     &offer[i]),
              "the k-way share");
    }
    for (size_t k = 0; k < count; ++k) {
        double from_a = offer[bridges[k].a], from_b = offer[bridges[k].b];
        check(cb_protocol2_take(&from_a, &from_b, &bridges[k].volume), "take");
    }
    return count;
}

/* The receiver of grain g among the held bridges (their index in `bridges`, -1: none),
 * at the positions `now`: its bridges in the order of their partner IDs. */
static long receiver_of(const int g, const sphere *now, const bridge *bridges,
                        const size_t count)
{
    double offset[MAX_SPHERES * MAX_SPHERES];
    size_t which[MAX_SPHERES * MAX_SPHERES];
    size_t m = 0;
    for (size_t k = 0; k < count; ++k) {
        if (bridges[k].a != g && bridges[k].b != g) continue;
        size_t at = m++;
        const int partner = bridges[k].a == g ? bridges[k].b : bridges[k].a;
        while (at > 0) {  // insertion by partner ID
            const bridge *prev = &bridges[which[at - 1]];
            const int prev_partner = prev->a == g ? prev->b : prev->a;
            if (now[prev_partner].id < now[partner].id) break;
            which[at] = which[at - 1];
            offset[at] = offset[at - 1];
            --at;
        }
        which[at] = k;
        // the contact point, radius_g along the line of centres, above g's centre
        offset[at] = now[g].radius * (now[partner].x[2] - now[g].x[2]) /
                     distance(&now[g], &now[partner]);
    }
    long index = -1;
    check(cb_protocol3_receiver(0.0, offset, m, &index), "receiver");
    return index < 0 ? -1 : (long)which[index];
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: protocol3_reference ID1 ID2 < SPHERES\n");
        return 2;
    }
    static sphere start[MAX_SPHERES], now[MAX_SPHERES];
    static bridge bridges[MAX_SPHERES * MAX_SPHERES];
    size_t n = 0;
    if (read_spheres(start, now, &n) != 0) {
        fprintf(stderr, "protocol3_reference: 2 to %d spheres, twice, in the same order\n",
                MAX_SPHERES);
        return 2;
    }
    const long id1 = atol(argv[1]), id2 = atol(argv[2]);
    size_t count = form_bridges(start, n, bridges);
    size_t broken = count;
    for (size_t k = 0; k < count; ++k) {
        const long a = start[bridges[k].a].id, b = start[bridges[k].b].id;
        if ((a == id1 && b == id2) || (a == id2 && b == id1)) broken = k;
    }
    if (broken == count) {
        fprintf(stderr, "protocol3_reference: %ld and %ld hold no bridge at the start\n", id1,
                id2);
        return 2;
    }
    const bridge cut = bridges[broken];
    bridges[broken] = bridges[--count];
    double share[2] = {0.0, 0.0};
    const int ends[2] = {cut.a, cut.b};
    check(cb_protocol2_release(cut.volume, start[cut.a].radius, start[cut.b].radius, &share[0],
                               &share[1]),
          "release");
    for (int e = 0; e < 2; ++e) {
        const long receiver = receiver_of(ends[e], now, bridges, count);
        double deposit = 0.0, offer = 0.0;
        check(cb_protocol_grain_step(share[e], receiver >= 0, 0.0,
                                     &start[ends[e]].free_liquid, &deposit, &offer),
              "the share");
        long partner = 0;
        if (receiver >= 0) {
            bridge *r = &bridges[receiver];
            r->volume += deposit;
            partner = now[r->a == ends[e] ? r->b : r->a].id;
        }
        printf("receiver %ld %ld\n", start[ends[e]].id, partner);
    }
    for (size_t k = 0; k < count; ++k) {
        const long a = start[bridges[k].a].id, b = start[bridges[k].b].id;
        printf("bridge %ld %ld %.17g\n", a < b ? a : b, a < b ? b : a, bridges[k].volume);
    }
    for (size_t i = 0; i < n; ++i) printf("free %ld %.17g\n", start[i].id, start[i].free_liquid);
    return 0;
}
