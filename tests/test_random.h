/* test_random.h — the tests' reproducible random numbers: a xorshift64* generator with a
 * fixed seed, one stream per test program. */
#ifndef CAPBRIDGE_TEST_RANDOM_H
#define CAPBRIDGE_TEST_RANDOM_H

#include <stddef.h>
#include <stdint.h>

static uint64_t rng_state = 0x2545F4914F6CDD1Dull;
static inline double uniform(void) /* [0, 1) */
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 0x2545F4914F6CDD1Dull) >> 11) * 0x1.0p-53;
}
static inline size_t below(size_t n) { return (size_t)(uniform() * (double)n); }

#endif
