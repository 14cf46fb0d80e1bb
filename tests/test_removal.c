/* test_removal.c — removing a share of the bridges (cb_bridge_removal_chosen,
 * cb_bridge_remove) and the removed pair's mark in the bridge's transitions.
 *
 * The choice is tested as the statistics of a fair draw: over many pairs the removed count
 * is binomial (within 4 standard deviations of n f), the two seeds' sets overlap as
 * independent draws do (n f^2), a larger fraction removes a superset, and the draw does not
 * depend on the order of the two ids. */
#include "capbridge.h"
#include "check.h"
#include "test_law.h"

#include <math.h>
#include <string.h>

enum { PAIRS = 20000 };

/* pair k: atoms (k + 1, k + 1 + stride(k)), many atoms in several pairs, as in a packing */
static void pair_ids(int k, long long *id1, long long *id2)
{
    *id1 = k / 6 + 1;
    *id2 = *id1 + 1 + k % 6 * 37;
}

static int chosen_of(double fraction, unsigned long long seed, long long a, long long b)
{
    int chosen = -1;
    CHECK_STATUS(cb_bridge_removal_chosen(fraction, seed, a, b, &chosen), CB_OK);
    return chosen;
}

static void choice_statistics(void)
{
    const double fractions[] = {0.1, 0.25, 0.5, 0.9};
    for (size_t f = 0; f < sizeof fractions / sizeof fractions[0]; f++) {
        const double p = fractions[f];
        int count = 0, both_seeds = 0, superset = 1, symmetric = 1;
        for (int k = 0; k < PAIRS; k++) {
            long long a, b;
            pair_ids(k, &a, &b);
            const int c = chosen_of(p, 7723, a, b);
            count += c;
            both_seeds += c && chosen_of(p, 7724, a, b);
            symmetric &= c == chosen_of(p, 7723, b, a);
            if (c && !chosen_of(fmin(1.0, p + 0.05), 7723, a, b)) superset = 0;
        }
        const double sd = sqrt(PAIRS * p * (1.0 - p));
        CHECK(fabs(count - PAIRS * p) < 4.0 * sd);
        const double q = p * p, sd_both = sqrt(PAIRS * q * (1.0 - q));
        CHECK(fabs(both_seeds - PAIRS * q) < 4.0 * sd_both);
        CHECK(superset);
        CHECK(symmetric);
    }
    /* the limits: none, all */
    int none = 0, all = 0;
    for (int k = 0; k < 1000; k++) {
        long long a, b;
        pair_ids(k, &a, &b);
        none += chosen_of(0.0, 1, a, b);
        all += chosen_of(1.0, 1, a, b);
    }
    CHECK(none == 0);
    CHECK(all == 1000);
}

static void choice_errors(void)
{
    int chosen = 7;
    CHECK_STATUS(cb_bridge_removal_chosen(-0.1, 1, 1, 2, &chosen), CB_ERR_RANGE);
    CHECK_STATUS(cb_bridge_removal_chosen(1.1, 1, 1, 2, &chosen), CB_ERR_RANGE);
    CHECK_STATUS(cb_bridge_removal_chosen(NAN, 1, 1, 2, &chosen), CB_ERR_RANGE);
    CHECK_STATUS(cb_bridge_removal_chosen(0.5, 1, 3, 3, &chosen), CB_ERR_RANGE);
    CHECK(chosen == 7);
    CHECK_STATUS(cb_bridge_removal_chosen(0.5, 1, 1, 2, NULL), CB_ERR_NULL);
}

static cb_transition update(const cb_law *law, double gap, double available, cb_bridge *b,
                            double *force)
{
    cb_transition t = (cb_transition)-1;
    double released = -1.0;
    CHECK_STATUS(cb_bridge_step(law, 0.5e-3, 0.4e-3, gap, available, b, &t, &released, force),
                 CB_OK);
    if (t != CB_BRIDGE_RUPTURED) CHECK(released == 0.0);
    return t;
}

static int all_zero(const cb_bridge *b)
{
    static const cb_bridge dry = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    return memcmp(b, &dry, sizeof dry) == 0;
}

/* a bridge removed in contact stays dry while the contact lasts, then forms at a new one */
static void removed_in_contact(void)
{
    const cb_law law = make_law(0.0, NULL, NULL);
    const double volume = 2.0e-11, overlap = -1.0e-6;
    cb_bridge b = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    double force = -1.0, released = -1.0;
    CHECK(update(&law, overlap, volume, &b, &force) == CB_BRIDGE_FORMED);
    CHECK(force > 0.0);
    CHECK_STATUS(cb_bridge_remove(overlap, &b, &released), CB_OK);
    CHECK(released == volume);
    CHECK(b.active == 0.0 && b.volume == 0.0 && b.rupture == CB_BRIDGE_REMOVED);
    CHECK_STATUS(cb_bridge_check_state(&b), CB_OK);
    CHECK(!cb_bridge_may_form(&b, overlap));
    CHECK(!cb_bridge_held(&law, 0.5e-3, 0.4e-3, overlap, &b, &force));
    /* still overlapping, liquid on offer: no bridge, no force, the mark kept */
    CHECK(update(&law, overlap, volume, &b, &force) == CB_BRIDGE_STAYS_DRY);
    CHECK(force == 0.0 && b.rupture == CB_BRIDGE_REMOVED);
    CHECK(update(&law, 0.5 * overlap, volume, &b, &force) == CB_BRIDGE_STAYS_DRY);
    /* the contact opens: plainly dry; a new contact forms a bridge as any other */
    CHECK(update(&law, 1.0e-7, volume, &b, &force) == CB_BRIDGE_STAYS_DRY);
    CHECK(all_zero(&b) && force == 0.0);
    CHECK(cb_bridge_may_form(&b, overlap));
    CHECK(update(&law, overlap, volume, &b, &force) == CB_BRIDGE_FORMED);
    CHECK(b.volume == volume);
    /* removed again; at gap 0 exactly the contact has opened (gap >= 0) and it may form */
    CHECK_STATUS(cb_bridge_remove(overlap, &b, &released), CB_OK);
    CHECK(cb_bridge_may_form(&b, 0.0));
    CHECK(update(&law, 0.0, volume, &b, &force) == CB_BRIDGE_FORMED);
}

/* a stretched bridge removed: dry at once, unmarked (its contact is open) */
static void removed_stretched(void)
{
    const cb_law law = make_law(0.0, NULL, NULL);
    const double volume = 2.0e-11;
    cb_bridge b = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    double force = -1.0, released = -1.0;
    CHECK(update(&law, -1.0e-6, volume, &b, &force) == CB_BRIDGE_FORMED);
    CHECK(update(&law, 1.0e-5, 0.0, &b, &force) == CB_BRIDGE_HELD);
    CHECK(force > 0.0);
    CHECK_STATUS(cb_bridge_remove(1.0e-5, &b, &released), CB_OK);
    CHECK(released == volume && all_zero(&b));
    /* a dry state is left as it is */
    CHECK_STATUS(cb_bridge_remove(-1.0e-6, &b, &released), CB_OK);
    CHECK(released == 0.0 && all_zero(&b));
}

static void remove_errors(void)
{
    const cb_law law = make_law(0.0, NULL, NULL);
    cb_bridge b = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    double force = 0.0, released = -1.0;
    update(&law, -1.0e-6, 2.0e-11, &b, &force);
    const cb_bridge before = b;
    CHECK_STATUS(cb_bridge_remove(NAN, &b, &released), CB_ERR_NOT_FINITE);
    CHECK(memcmp(&b, &before, sizeof b) == 0 && released == -1.0);
    CHECK_STATUS(cb_bridge_remove(0.0, NULL, &released), CB_ERR_NULL);
    CHECK_STATUS(cb_bridge_remove(0.0, &b, NULL), CB_ERR_NULL);
    /* the mark on anything but an otherwise dry state is a corrupted state */
    cb_bridge marked_wet = before, marked_volume = {1e-12, 0.0, CB_BRIDGE_REMOVED, 0, 0, 0, 0},
              other_mark = {0.0, 0.0, -2.0, 0.0, 0.0, 0.0, 0.0};
    marked_wet.rupture = CB_BRIDGE_REMOVED;
    CHECK_STATUS(cb_bridge_check_state(&marked_wet), CB_ERR_BRIDGE_STATE);
    CHECK_STATUS(cb_bridge_check_state(&marked_volume), CB_ERR_BRIDGE_STATE);
    CHECK_STATUS(cb_bridge_check_state(&other_mark), CB_ERR_BRIDGE_STATE);
    CHECK_STATUS(cb_bridge_remove(-1e-6, &marked_wet, &released), CB_ERR_BRIDGE_STATE);
}

int main(int argc, char **argv)
{
    (void)argc;
    choice_statistics();
    choice_errors();
    removed_in_contact();
    removed_stretched();
    remove_errors();
    return check_report(argv[0]);
}
