/* law_cost.c — time cb_force (and cb_rupture_distance) per law on the same sample of pairs,
 * laws interleaved. */
#define _POSIX_C_SOURCE 199309L /* clock_gettime, CLOCK_PROCESS_CPUTIME_ID */
#include "law_cost.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <time.h>

enum { SAMPLE = 4096, PASSES = 9, REPEATS = 8 };

/* CPU time of this (single-threaded) process: on a busy machine the time the process
 * waits for a core is not counted, only what the calls cost while running. */
static double seconds_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* A fixed sequence (xorshift64*) so every law sees the same pairs. */
static double next_uniform(uint64_t *state)
{
    *state ^= *state >> 12;
    *state ^= *state << 25;
    *state ^= *state >> 27;
    return (double)((*state * 2685821657736338717ULL) >> 11) * 0x1.0p-53;
}

/* The pairs, and for each a uniform fraction of the law's rupture distance. */
typedef struct sample {
    double r1[SAMPLE], r2[SAMPLE], volume[SAMPLE], fraction[SAMPLE];
} sample;

static void make_sample(sample *s)
{
    uint64_t state = 0x9E3779B97F4A7C15ULL;
    for (int i = 0; i < SAMPLE; ++i) {
        s->r1[i] = 1e-3;
        s->r2[i] = 1e-3 * exp(log(10.0) * next_uniform(&state));
        double rh = cb_radius_harmonic(s->r1[i], s->r2[i]);
        s->volume[i] = exp(log(1e-5) + log(1e4) * next_uniform(&state)) * rh * rh * rh;
        s->fraction[i] = next_uniform(&state);
    }
}

/* Seconds for REPEATS sweeps of the sample with one law. */
static double time_law(const cb_law *law, const sample *s, const double *gap)
{
    volatile double sink = 0.0;
    double sum = 0.0;
    double start = seconds_now();
    for (int r = 0; r < REPEATS; ++r) {
        for (int i = 0; i < SAMPLE; ++i) {
            double force = 0.0, stiffness = 0.0;
            cb_force(law, s->r1[i], s->r2[i], s->volume[i], gap[i], &force, &stiffness);
            sum += force + stiffness;
            if (law->viscosity > 0.0) {
                double normal = 0.0, tangential = 0.0;
                cb_viscous_damping(law, s->r1[i], s->r2[i], gap[i], s->volume[i], &normal,
                                   &tangential);
                sum += normal + tangential;
            }
        }
    }
    double elapsed = seconds_now() - start;
    sink += sum;
    (void)sink;
    return elapsed;
}

/* Seconds for REPEATS sweeps of the sample's stretched bridges with one law: the call an
 * engine makes per step for a bridge beyond contact (cb_bridge_force on the stored state,
 * whose constants were derived once when the bridge got its volume). */
static double time_bridge_step(const cb_law *law, const sample *s, const double *gap,
                               const cb_bridge *bridges)
{
    volatile double sink = 0.0;
    double sum = 0.0;
    double start = seconds_now();
    for (int r = 0; r < REPEATS; ++r) {
        for (int i = 0; i < SAMPLE; ++i) {
            double force = 0.0;
            cb_bridge_force(law, s->r1[i], s->r2[i], gap[i], &bridges[i], &force);
            sum += force;
        }
    }
    double elapsed = seconds_now() - start;
    sink += sum;
    (void)sink;
    return elapsed;
}

/* Seconds for REPEATS sweeps of the sample's rupture distances with one law. */
static double time_rupture(const cb_law *law, const sample *s)
{
    volatile double sink = 0.0;
    double sum = 0.0;
    double start = seconds_now();
    for (int r = 0; r < REPEATS; ++r) {
        for (int i = 0; i < SAMPLE; ++i) {
            double distance = 0.0;
            cb_rupture_distance(law, s->r1[i], s->r2[i], s->volume[i], &distance);
            sum += distance;
        }
    }
    double elapsed = seconds_now() - start;
    sink += sum;
    (void)sink;
    return elapsed;
}

int cb_law_costs_ns(const cb_law *laws, int n, double *ns_per_call, double *ns_per_rupture,
                    double *ns_per_bridge_step)
{
    sample *s = malloc(sizeof *s);
    double *gaps = malloc((size_t)n * SAMPLE * sizeof *gaps);
    cb_bridge *bridges = calloc((size_t)n * SAMPLE, sizeof *bridges);
    if (!s || !gaps || !bridges) {
        free(s);
        free(gaps);
        free(bridges);
        return -1;
    }
    make_sample(s);
    for (int l = 0; l < n; ++l) {
        ns_per_call[l] = HUGE_VAL;
        if (ns_per_rupture) ns_per_rupture[l] = HUGE_VAL;
        for (int i = 0; i < SAMPLE; ++i) {
            double rupture = 0.0;
            if (cb_rupture_distance(&laws[l], s->r1[i], s->r2[i], s->volume[i], &rupture) !=
                CB_OK)
                rupture = 0.0;
            gaps[(size_t)l * SAMPLE + i] = rupture * s->fraction[i];
            /* a volume the law refuses leaves the bridge dry (a zero force) */
            if (ns_per_bridge_step)
                cb_bridge_set_volume(&laws[l], s->r1[i], s->r2[i], s->volume[i],
                                     &bridges[(size_t)l * SAMPLE + i]);
        }
        if (ns_per_bridge_step) ns_per_bridge_step[l] = HUGE_VAL;
    }
    for (int pass = 0; pass < PASSES; ++pass) {
        for (int l = 0; l < n; ++l) {
            double ns = time_law(&laws[l], s, gaps + (size_t)l * SAMPLE) /
                        ((double)REPEATS * SAMPLE) * 1e9;
            if (ns < ns_per_call[l]) ns_per_call[l] = ns;
            if (ns_per_rupture) {
                ns = time_rupture(&laws[l], s) / ((double)REPEATS * SAMPLE) * 1e9;
                if (ns < ns_per_rupture[l]) ns_per_rupture[l] = ns;
            }
            if (ns_per_bridge_step) {
                ns = time_bridge_step(&laws[l], s, gaps + (size_t)l * SAMPLE,
                                      bridges + (size_t)l * SAMPLE) /
                     ((double)REPEATS * SAMPLE) * 1e9;
                if (ns < ns_per_bridge_step[l]) ns_per_bridge_step[l] = ns;
            }
        }
    }
    free(s);
    free(gaps);
    free(bridges);
    return 0;
}
