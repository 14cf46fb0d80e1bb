/* test_contact.c — the contact law of the core (Richefeu 2007 eqs. 1-3, 12; Gladkyy 2014 §2).
 *
 * Its forces against the equations written out here; and the physics that tells the
 * readings of eq. 12 apart: a pair held in contact by its bridge alone, with no other
 * load, slides under a tangential load of mu F_cap (the Coulomb limit on the contact force,
 * which at rest balances the attraction), not 2 mu F_cap (the attraction counted again). */
#include "capbridge.h"
#include "check.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static cb_contact_law make_contact(double kn, double kt, double alpha, double mu,
                                   cb_dashpot_rule dashpot)
{
    cb_contact_law c;
    cb_message msg;
    CHECK_STATUS(cb_contact_law_init(&c, kn, kt, alpha, mu, dashpot, &msg), CB_OK);
    return c;
}

/* eqs. 2-3 term by term, for each dashpot rule */
static void normal_force(void)
{
    const double kn = 1e3, alpha = 0.3, m = 2e-5, sqrt_m = sqrt(m);
    const double eta = 2.0 * alpha * sqrt(m * kn); /* eq. 3's coefficient */
    cb_contact_law approach = make_contact(kn, 100.0, alpha, 0.4, CB_DASHPOT_APPROACH);
    cb_contact_law both = make_contact(kn, 100.0, alpha, 0.4, CB_DASHPOT_BOTH);
    cb_contact_law repulsive = make_contact(kn, 100.0, alpha, 0.4, CB_DASHPOT_REPULSIVE);
    const double gap = -1e-6;
    /* approaching at 0.01 m/s: every rule damps */
    CHECK_REL(cb_contact_normal_force(&approach, gap, -0.01, sqrt_m), kn * 1e-6 + eta * 0.01,
              1e-14);
    CHECK_REL(cb_contact_normal_force(&both, gap, -0.01, sqrt_m), kn * 1e-6 + eta * 0.01, 1e-14);
    CHECK_REL(cb_contact_normal_force(&repulsive, gap, -0.01, sqrt_m), kn * 1e-6 + eta * 0.01,
              1e-14);
    /* separating at 0.01 m/s: eq. 3 does not damp; a linear dashpot pulls (the elastic 1e-3 N
     * against eta 0.01 = 4.6e-4 N: net repulsive), and at 0.1 m/s it would be attractive,
     * which the repulsive rule holds at 0 */
    CHECK_REL(cb_contact_normal_force(&approach, gap, 0.01, sqrt_m), kn * 1e-6, 1e-14);
    CHECK_REL(cb_contact_normal_force(&both, gap, 0.01, sqrt_m), kn * 1e-6 - eta * 0.01, 1e-12);
    CHECK_REL(cb_contact_normal_force(&both, gap, 0.1, sqrt_m), kn * 1e-6 - eta * 0.1, 1e-12);
    CHECK(cb_contact_normal_force(&both, gap, 0.1, sqrt_m) < 0.0);
    CHECK(cb_contact_normal_force(&repulsive, gap, 0.1, sqrt_m) == 0.0);
    CHECK(cb_contact_normal_force(&approach, gap, 0.1, sqrt_m) > 0.0);
    /* apart or touching: no contact force (eq. 2: 0 for delta_n >= 0) */
    CHECK(cb_contact_normal_force(&approach, 0.0, -1.0, sqrt_m) == 0.0);
    CHECK(cb_contact_normal_force(&both, 1e-6, -1.0, sqrt_m) == 0.0);
    CHECK(cb_contact_normal_force(&both, NAN, -1.0, sqrt_m) == 0.0);
}

static void friction_limit_and_spring(void)
{
    cb_contact_law c = make_contact(1e3, 100.0, 0.0, 0.5, CB_DASHPOT_BOTH);
    CHECK(cb_contact_friction_limit(&c, 2e-3) == 0.5 * 2e-3);
    CHECK(cb_contact_friction_limit(&c, -2e-3) == 0.0); /* tensile: no friction */
    /* sticking: -k_t s, the displacement untouched */
    double s[3] = {1e-6, -2e-6, 0.0}, f[3];
    CHECK(cb_contact_tangential_force(&c, 1.0, s, f, 1) == 0);
    CHECK(f[0] == -100.0 * 1e-6 && f[1] == 100.0 * 2e-6 && f[2] == 0.0);
    CHECK(s[0] == 1e-6 && s[1] == -2e-6);
    /* sliding: the force on the limit, along -s; the displacement scaled with it (or kept,
     * when update is 0: a setup pass, single()) */
    const double limit = 1e-4;
    double kept[3] = {3e-6, 4e-6, 0.0};
    CHECK(cb_contact_tangential_force(&c, limit, kept, f, 0) == 1);
    CHECK(kept[0] == 3e-6 && kept[1] == 4e-6);
    CHECK_REL(sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]), limit, 1e-15);
    CHECK_REL(f[0] / f[1], 0.75, 1e-15);
    CHECK(cb_contact_tangential_force(&c, limit, kept, f, 1) == 1);
    CHECK_REL(100.0 * sqrt(kept[0] * kept[0] + kept[1] * kept[1]), limit, 1e-15);
    double zero[3] = {1e-6, 0.0, 0.0};
    CHECK(cb_contact_tangential_force(&c, 0.0, zero, f, 1) == 1); /* mu 0: no spring */
    CHECK(f[0] == 0.0 && zero[0] == 0.0);
}

static void bad_coefficients(void)
{
    cb_contact_law c;
    cb_message msg;
    memset(&msg, 0, sizeof msg);
    CHECK_STATUS(cb_contact_law_init(&c, -1.0, 1.0, 0.1, 0.4, CB_DASHPOT_APPROACH, &msg),
                 CB_ERR_NEGATIVE);
    CHECK(strstr(msg.text, "kn") && strstr(msg.text, ">= 0"));
    CHECK_STATUS(cb_contact_law_init(&c, 1.0, NAN, 0.1, 0.4, CB_DASHPOT_APPROACH, &msg),
                 CB_ERR_NOT_FINITE);
    CHECK(strstr(msg.text, "kt") != NULL);
    CHECK_STATUS(cb_contact_law_init(&c, 1.0, 1.0, 1.5, 0.4, CB_DASHPOT_APPROACH, &msg),
                 CB_ERR_RANGE);
    CHECK(strstr(msg.text, "[0, 1]") != NULL);
    CHECK_STATUS(cb_contact_law_init(&c, 1.0, 1.0, 0.5, -0.4, CB_DASHPOT_APPROACH, &msg),
                 CB_ERR_NEGATIVE);
    CHECK_STATUS(cb_contact_law_init(&c, 1.0, 1.0, 0.5, 0.4, (cb_dashpot_rule)7, &msg),
                 CB_ERR_RANGE);
    CHECK_STATUS(cb_contact_law_init(NULL, 1.0, 1.0, 0.5, 0.4, CB_DASHPOT_APPROACH, &msg),
                 CB_ERR_NULL);
}

/* Sphere 2 (radius R, mass m) beside a fixed sphere 1 of the same radius, a richefeu bridge
 * between them, no gravity, no rotation (the load acts at the centre; a free sphere would
 * roll).  It settles in contact where the contact force balances F_cap; then a tangential
 * load rising at `rate` is applied to it.  Velocity Verlet in LAMMPS's step order (fix nve:
 * the forces of the new positions see the half-step velocities).  Returns the load at the
 * first step the spring slides, NAN if it never does. */
typedef struct sphere_state {
    double gap, gap_rate, vy;   /* normal coordinate and rate, tangential velocity */
    double shear[3];            /* the spring's tangential displacement */
    double fn, ft;              /* forces on sphere 2: along +gap, along the load */
    cb_bridge bridge;
} sphere_state;

static int pair_forces(const cb_contact_law *contact, const cb_law *law, double radius,
                       double sqrt_m, double volume, sphere_state *s, int *failures)
{
    cb_transition change;
    double released = 0.0, capillary = 0.0, ft[3] = {0.0, 0.0, 0.0};
    if (cb_bridge_step(law, radius, radius, s->gap, volume, &s->bridge, &change, &released,
                       &capillary) != CB_OK)
        ++*failures;
    const double contact_force = cb_contact_normal_force(contact, s->gap, s->gap_rate, sqrt_m);
    int sliding = 0;
    if (s->gap < 0.0)
        sliding = cb_contact_tangential_force(
            contact, cb_contact_friction_limit(contact, contact_force), s->shear, ft, 1);
    else
        s->shear[1] = 0.0;
    s->fn = contact_force - capillary;
    s->ft = ft[1];
    return sliding;
}

static double sliding_load(const cb_contact_law *contact, const cb_law *law, double radius,
                           double mass, double volume, double rate)
{
    const double dt = 0.02 * CB_PI * sqrt(mass / contact->normal_stiffness);
    const double sqrt_m = sqrt(mass); /* beside a fixed sphere the effective mass is m */
    const long settle = 20000;        /* ~400 periods of the normal spring */
    sphere_state s;
    memset(&s, 0, sizeof s);
    int failures = 0;
    pair_forces(contact, law, radius, sqrt_m, volume, &s, &failures);
    double result = NAN;
    for (long n = 1; n < 4000000 && isnan(result); ++n) {
        const double load_before = n - 1 > settle ? rate * (n - 1 - settle) * dt : 0.0;
        const double load = n > settle ? rate * (n - settle) * dt : 0.0;
        s.gap_rate += 0.5 * dt * s.fn / mass;
        s.vy += 0.5 * dt * (s.ft + load_before) / mass;
        s.gap += dt * s.gap_rate;
        s.shear[1] += dt * s.vy; /* the tangential displacement at the contact */
        if (pair_forces(contact, law, radius, sqrt_m, volume, &s, &failures) && n > settle)
            result = load;
        s.gap_rate += 0.5 * dt * s.fn / mass;
        s.vy += 0.5 * dt * (s.ft + load) / mass;
    }
    CHECK(failures == 0);
    return result;
}

static void held_by_its_bridge_alone(void)
{
    const double radius = 1e-3, mass = 2500.0 * 4.0 / 3.0 * CB_PI * 1e-9, volume = 1e-11;
    const double gamma = 0.0728, mu = 0.4;
    cb_law law;
    cb_message msg;
    CHECK_STATUS(cb_law_init(&law, CB_MODEL_RICHEFEU, gamma, 0.0), CB_OK);
    CHECK_STATUS(cb_law_prepare(&law, &msg), CB_OK);
    double f_cap = 0.0;
    CHECK_STATUS(cb_force(&law, radius, radius, volume, 0.0, &f_cap, NULL), CB_OK);
    CHECK_REL(f_cap, 2.0 * CB_PI * gamma * radius, 1e-14); /* eq. 4, R_g = R */
    const cb_dashpot_rule rules[] = {CB_DASHPOT_APPROACH, CB_DASHPOT_BOTH, CB_DASHPOT_REPULSIVE};
    for (int k = 0; k < 3; ++k) {
        cb_contact_law contact = make_contact(1e3, 400.0, 0.5, mu, rules[k]);
        /* mu F_cap = 1.8e-4 N reached in ~0.2 s of load */
        const double load = sliding_load(&contact, &law, radius, mass, volume, 1e-3);
        CHECK_REL(load, mu * f_cap, 0.02);
        printf("held by its bridge alone, dashpot %d: slides at %.5g N = %.4f mu F_cap\n",
               (int)rules[k], load, load / (mu * f_cap));
    }
    cb_law_release(&law);
}

int main(int argc, char **argv)
{
    (void)argc;
    normal_force();
    friction_limit_and_spring();
    bad_coefficients();
    held_by_its_bridge_alone();
    return check_report(argv[0]);
}
