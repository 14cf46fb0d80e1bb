/* law_cost.c — time cb_force per law on the same sample of pairs. */
#define _POSIX_C_SOURCE 199309L /* clock_gettime */
#include "law_cost.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <time.h>

enum { SAMPLE = 4096, PASSES = 7 };

static double seconds_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
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

double cb_law_cost_ns(const cb_law *law)
{
    double *r1 = malloc(4 * SAMPLE * sizeof *r1);
    if (!r1) return HUGE_VAL;
    double *r2 = r1 + SAMPLE, *volume = r2 + SAMPLE, *gap = volume + SAMPLE;
    uint64_t state = 0x9E3779B97F4A7C15ULL;
    for (int i = 0; i < SAMPLE; ++i) {
        r1[i] = 1e-3;
        r2[i] = 1e-3 * exp(log(10.0) * next_uniform(&state));
        double rh = cb_radius_harmonic(r1[i], r2[i]);
        volume[i] = exp(log(1e-5) + log(1e4) * next_uniform(&state)) * rh * rh * rh;
        double rupture = 0.0;
        if (cb_rupture_distance(law, r1[i], r2[i], volume[i], &rupture) != CB_OK) rupture = 0.0;
        gap[i] = rupture * next_uniform(&state);
    }
    double best = HUGE_VAL;
    volatile double sink = 0.0;
    for (int pass = 0; pass < PASSES; ++pass) {
        const int repeats = 16;
        double sum = 0.0;
        double start = seconds_now();
        for (int r = 0; r < repeats; ++r) {
            for (int i = 0; i < SAMPLE; ++i) {
                double force = 0.0, stiffness = 0.0;
                cb_force(law, r1[i], r2[i], volume[i], gap[i], &force, &stiffness);
                sum += force + stiffness;
            }
        }
        double elapsed = seconds_now() - start;
        sink += sum;
        double per_call = elapsed / ((double)repeats * SAMPLE) * 1e9;
        if (per_call < best) best = per_call;
    }
    (void)sink;
    free(r1);
    return best;
}
