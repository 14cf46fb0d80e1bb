/* check.h — the small assertion harness of the C tests.
 * Each test program counts failed checks and returns non-zero if any failed,
 * printing every failure with its file, line and the numbers involved. */
#ifndef CAPBRIDGE_CHECK_H
#define CAPBRIDGE_CHECK_H

#include <math.h>
#include <stdio.h>

static int check_failures = 0;
static int check_count = 0;

#define CHECK(cond)                                                              \
    do {                                                                         \
        ++check_count;                                                           \
        if (!(cond)) {                                                           \
            ++check_failures;                                                    \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
        }                                                                        \
    } while (0)

/* |actual - expected| <= rel * |expected| (or <= rel when expected is 0). */
#define CHECK_REL(actual, expected, rel)                                         \
    do {                                                                         \
        double check_a_ = (actual), check_e_ = (expected), check_r_ = (rel);     \
        double check_scale_ = fabs(check_e_) > 0.0 ? fabs(check_e_) : 1.0;      \
        ++check_count;                                                           \
        if (!(fabs(check_a_ - check_e_) <= check_r_ * check_scale_)) {           \
            ++check_failures;                                                    \
            fprintf(stderr, "%s:%d: %s = %.17g, expected %s = %.17g (rel. diff %.3g > %.3g)\n", \
                    __FILE__, __LINE__, #actual, check_a_, #expected, check_e_,  \
                    fabs(check_a_ - check_e_) / check_scale_, check_r_);          \
        }                                                                        \
    } while (0)

#define CHECK_STATUS(call, expected)                                             \
    do {                                                                         \
        int check_s_ = (int)(call);                                              \
        ++check_count;                                                           \
        if (check_s_ != (int)(expected)) {                                       \
            ++check_failures;                                                    \
            fprintf(stderr, "%s:%d: %s returned %d, expected %s (%d)\n", __FILE__, \
                    __LINE__, #call, check_s_, #expected, (int)(expected));      \
        }                                                                        \
    } while (0)

/* Print the tally; use as `return check_report(argv[0]);` at the end of main. */
static int check_report(const char *name)
{
    printf("%s: %d checks, %d failed\n", name, check_count, check_failures);
    return check_failures == 0 ? 0 : 1;
}

#endif
