/* test_laws.c — the closed-form laws against independent references: analytic limits,
 * hand-computed values, the published formulas written out again here in their plain
 * (non-limit) form, central finite differences for every law's stiffness, the radius
 * conventions, and the exact Laplace-Young solver where the sources disagree. */
#include "capbridge.h"
#include "check.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)

static const double gamma_water = 0.072;

static cb_law make_law(cb_model model, double theta, cb_validity_rule validity)
{
    cb_law law;
    cb_message msg;
    CHECK_STATUS(cb_law_init(&law, model, gamma_water, theta), CB_OK);
    law.validity = validity;
    CHECK_STATUS(cb_law_prepare(&law, &msg), CB_OK);
    return law;
}

static double force_of(const cb_law *law, double r1, double r2, double volume, double gap)
{
    double f = -1.0, df = 0.0;
    CHECK_STATUS(cb_force(law, r1, r2, volume, gap, &f, &df), CB_OK);
    return f;
}

static double harmonic(double r1, double r2) { return 2.0 * r1 * r2 / (r1 + r2); }

/* ---------------------------------------------------- independent formulas */

/* Gladkyy eqs. 9-12 exactly as printed (fine for gap > 0 not too small). */
static double rabinovich_printed(double rh, double volume, double theta, double gap,
                                 int with_alpha)
{
    double root = sqrt(1.0 + 2.0 * volume / (PI * rh * gap * gap));
    double d_sp = 0.5 * gap * (-1.0 + root);
    double alpha = sqrt(gap / rh * (-1.0 + root));
    double f = 2.0 * PI * rh * gamma_water * cos(theta) / (1.0 + gap / (2.0 * d_sp));
    if (with_alpha) f += 2.0 * PI * gamma_water * rh * sin(alpha) * sin(theta + alpha);
    return f;
}

/* Gladkyy eq. 7 with appendix B (coefficient c3 of theta^2 ln^3 V* in f1 as a parameter). */
static double willett_printed(double rh, double volume, double theta, double gap, double c3)
{
    double t = theta, t2 = theta * theta, l = log(volume / (rh * rh * rh));
    double f1 = (-0.44507 + 0.050832 * t - 1.1466 * t2) + (-0.1119 - 0.000411 * t - 0.1490 * t2) * l +
                (-0.012101 - 0.0036456 * t - 0.01255 * t2) * l * l +
                (-0.0005 - 0.0003505 * t + c3 * t2) * l * l * l;
    double f2 = (1.9222 - 0.57473 * t - 1.2918 * t2) + (-0.0668 - 0.1201 * t - 0.22574 * t2) * l +
                (-0.0013375 - 0.0068988 * t - 0.01137 * t2) * l * l;
    double f3 = (1.268 - 0.01396 * t - 0.23566 * t2) + (0.198 + 0.092 * t - 0.06418 * t2) * l +
                (0.02232 + 0.02238 * t - 0.009853 * t2) * l * l +
                (0.0008585 + 0.001318 * t - 0.00053 * t2) * l * l * l;
    double f4 = (-0.010703 + 0.073776 * t - 0.34742 * t2) + (0.03345 + 0.04543 * t - 0.09056 * t2) * l +
                (0.0018574 + 0.004456 * t - 0.006257 * t2) * l * l;
    double s = gap / (2.0 * sqrt(volume / rh));
    if (gap == 0.0) return 2.0 * PI * rh * gamma_water * exp(f1);
    return 2.0 * PI * rh * gamma_water *
           exp(f1 - f2 * exp(f3 * log(s) + f4 * log(s) * log(s)));
}

/* Gladkyy eq. 5 and A2-A7 as printed, except A6's gap term, which is `gap_term` x gap
 * (0.5: the symmetric toroid we use; 1.0: the appendix as printed). */
static double weigert_printed(double rh, double volume, double theta, double gap,
                              double gap_term)
{
    double ca = 1.0 + 6.0 * gap / (2.0 * rh);
    double ct = 1.0 + 1.1 * sin(theta);
    double beta = asin(pow(volume / (0.12 * pow(2.0 * rh, 3.0) * ca * ct), 0.25));
    double r1 = (rh * (1.0 - cos(beta)) + gap_term * gap) / cos(beta + theta);
    double r2 = rh * sin(beta) + r1 * (sin(beta + theta) - 1.0);
    double pk = gamma_water * (1.0 / r1 - 1.0 / r2);
    return PI / 4.0 * pow(2.0 * rh, 2.0) * pow(sin(beta), 2.0) * pk +
           gamma_water * PI * 2.0 * rh * sin(beta) * sin(beta + theta);
}

/* -------------------------------------------------------- analytic limits */

static void test_contact_limits(void)
{
    double r1 = 1e-3, r2 = 2.5e-3, theta = 20.0 * DEG;
    double rh = harmonic(r1, r2);
    double derjaguin = 2.0 * PI * rh * gamma_water * cos(theta);
    double volumes[] = {1e-15, 1e-12, 1e-10};
    for (int i = 0; i < 3; ++i) {
        cb_law reduced = make_law(CB_MODEL_WILLETT_REDUCED, theta, CB_VALIDITY_EXTEND);
        cb_law rab = make_law(CB_MODEL_RABINOVICH, theta, CB_VALIDITY_EXTEND);
        CHECK_REL(force_of(&reduced, r1, r2, volumes[i], 0.0), derjaguin, 1e-14);
        CHECK_REL(force_of(&rab, r1, r2, volumes[i], 0.0), derjaguin, 1e-14);
        /* Rabinovich's one-sided stiffness at contact: -F0 sqrt(pi R_h / (2V)) */
        double f, df;
        CHECK_STATUS(cb_force(&rab, r1, r2, volumes[i], 0.0, &f, &df), CB_OK);
        CHECK_REL(df, -derjaguin * sqrt(PI * rh / (2.0 * volumes[i])), 1e-12);
        /* the uncorrected law adds sin(alpha0) sin(theta + alpha0), alpha0^2 = 2 d_sp(0)/R,
         * d_sp(0) = sqrt(V / (2 pi R)) */
        cb_law unc = make_law(CB_MODEL_RABINOVICH_UNCORRECTED, theta, CB_VALIDITY_EXTEND);
        double alpha0 = sqrt(2.0 * sqrt(volumes[i] / (2.0 * PI * rh)) / rh);
        CHECK_REL(force_of(&unc, r1, r2, volumes[i], 0.0),
                  derjaguin + 2.0 * PI * gamma_water * rh * sin(alpha0) * sin(theta + alpha0),
                  1e-13);
    }

    /* Soulie at contact, by hand. r1 = 1 mm, r2 = 2 mm (R2 = 2 mm, the larger),
     * V = 1e-10 m^3, theta = 20 deg = 0.34906585039886590 rad, gamma = 0.072:
     *   V* = 1e-10 / 8e-9 = 0.0125, ln V* = -4.382026634673882
     *   B = (-0.148 (-4.382027) - 0.96) 0.121847 - 0.0082 (-4.382027) + 0.48
     *     = (-0.311460) 0.121847 + 0.035933 + 0.48 = 0.4779821547021764
     *   C = 0.0018 (-4.382027) + 0.078 = 0.07011235205758701
     *   F(0) = pi 0.072 sqrt(2e-6) (C + e^B) = 3.19876e-4 (0.070112 + 1.612864)
     *        = 5.383480881674357e-4 N
     *   A = -1.1 0.0125^-0.53 = -11.220969405971216;
     *   F(2e-5 m) = pi 0.072 sqrt(2e-6) (C + exp(A 2e-5 / 2e-3 + B)) = 4.8358668721354626e-4 N
     * (computed independently with python3 -c, from the formula atop src_c/law_soulie.c). */
    {
        cb_law soulie = make_law(CB_MODEL_SOULIE, 20.0 * DEG, CB_VALIDITY_EXTEND);
        CHECK_REL(force_of(&soulie, 1e-3, 2e-3, 1e-10, 0.0), 5.383480881674357e-4, 1e-12);
        CHECK_REL(force_of(&soulie, 1e-3, 2e-3, 1e-10, 2e-5), 4.8358668721354626e-4, 1e-12);
        /* the larger radius, whichever order */
        CHECK_REL(force_of(&soulie, 2e-3, 1e-3, 1e-10, 2e-5), 4.8358668721354626e-4, 1e-12);
        /* had R2 been the smaller radius (V* = 0.1), F(0) would be
         * pi 0.072 sqrt(2e-6) (0.0018 ln 0.1 + 0.078 + exp(B(0.1))) — clearly different */
        double l = log(0.1), t2 = 20.0 * DEG * 20.0 * DEG;
        double wrong = PI * gamma_water * sqrt(2e-6) *
                       (0.0018 * l + 0.078 + exp((-0.148 * l - 0.96) * t2 - 0.0082 * l + 0.48));
        CHECK(fabs(force_of(&soulie, 1e-3, 2e-3, 1e-10, 0.0) - wrong) > 0.05 * wrong);
    }

    /* Willett full at contact, by hand: r1 = r2 = 1 mm (R_h = 1 mm), V = 1e-12 m^3
     * (V* = 1e-3, ln V* = -6.907755), theta = 20 deg: f1 = -0.16195579796256268 (eq. B1),
     * F(0) = 2 pi 1e-3 0.072 exp(f1) = 3.847475432805395e-4 N (python3 -c). */
    {
        cb_law willett = make_law(CB_MODEL_WILLETT, 20.0 * DEG, CB_VALIDITY_STRICT);
        CHECK_REL(force_of(&willett, 1e-3, 1e-3, 1e-12, 0.0), 3.847475432805395e-4, 1e-12);
    }

    /* Weigert at small volume and contact: Derjaguin's 2 pi R_h gamma cos(theta). This
     * fixes the sign of p_k: with p_k = gamma (1/R2 - 1/R1) F(0) would be ~ -2 pi R gamma. */
    {
        double thetas[] = {0.0, 30.0 * DEG, 60.0 * DEG};
        for (int i = 0; i < 3; ++i) {
            cb_law weigert = make_law(CB_MODEL_WEIGERT, thetas[i], CB_VALIDITY_STRICT);
            double f = force_of(&weigert, r1, r2, 1e-12 * rh * rh * rh, 0.0);
            CHECK_REL(f, 2.0 * PI * rh * gamma_water * cos(thetas[i]), 3e-3);
        }
    }
}

/* --------------------------------------- the closed forms against the printed ones */

static void test_printed_forms(void)
{
    double r1 = 19e-6, r2 = 35e-6; /* Rabinovich's pair R1 of Gladkyy Table 1 */
    double rh = harmonic(r1, r2);
    double volume = 2e-19, theta = 10.0 * DEG;
    cb_law rab = make_law(CB_MODEL_RABINOVICH, theta, CB_VALIDITY_EXTEND);
    cb_law unc = make_law(CB_MODEL_RABINOVICH_UNCORRECTED, theta, CB_VALIDITY_EXTEND);
    cb_law wil = make_law(CB_MODEL_WILLETT, theta, CB_VALIDITY_STRICT);
    cb_law wei = make_law(CB_MODEL_WEIGERT, theta, CB_VALIDITY_STRICT);
    double rupture = 0.0;
    CHECK_STATUS(cb_rupture_distance(&rab, r1, r2, volume, &rupture), CB_OK);
    double fractions[] = {0.01, 0.1, 0.3, 0.6, 0.9, 1.0};
    for (int i = 0; i < 6; ++i) {
        double gap = fractions[i] * rupture;
        double fc = force_of(&rab, r1, r2, volume, gap);
        double fu = force_of(&unc, r1, r2, volume, gap);
        CHECK_REL(fc, rabinovich_printed(rh, volume, theta, gap, 0), 1e-11);
        CHECK_REL(fu, rabinovich_printed(rh, volume, theta, gap, 1), 1e-11);
        /* uncorrected - corrected = the alpha-term of eq. 11 */
        double root = sqrt(1.0 + 2.0 * volume / (PI * rh * gap * gap));
        double alpha = sqrt(gap / rh * (-1.0 + root));
        CHECK_REL(fu - fc, 2.0 * PI * gamma_water * rh * sin(alpha) * sin(theta + alpha), 1e-9);
        CHECK_REL(force_of(&wil, r1, r2, volume, gap),
                  willett_printed(rh, volume, theta, gap, -0.00029076), 1e-12);
        CHECK_REL(force_of(&wei, r1, r2, volume, gap),
                  weigert_printed(rh, volume, theta, gap, 0.5), 1e-11);
    }
    /* Willett's reduced form, eq. 8, equal spheres */
    cb_law red = make_law(CB_MODEL_WILLETT_REDUCED, theta, CB_VALIDITY_STRICT);
    double r = 2.381e-3, v = 13.6e-12, gap = 1e-4; /* Willett's W11 case */
    double s = gap / (2.0 * sqrt(v / r));
    CHECK_REL(force_of(&red, r, r, v, gap),
              2.0 * PI * r * gamma_water * cos(theta) / (1.0 + 2.1 * s + 10.0 * s * s), 1e-14);
}

/* -------------------------------------------------- stiffness = dF/dgap */

static int derivative_checks = 0;

/* Richardson-extrapolated central (or, at gap 0, one-sided) difference. */
static double numeric_slope(const cb_law *law, double r1, double r2, double v, double gap,
                            double h)
{
    double f[5];
    if (gap == 0.0) {
        /* one-sided, second order, extrapolated: D(h) = (-3F0 + 4F(h) - F(2h)) / (2h) */
        double d[2];
        for (int k = 0; k < 2; ++k) {
            double step = h / (k + 1);
            for (int j = 0; j < 3; ++j) f[j] = force_of(law, r1, r2, v, j * step);
            d[k] = (-3.0 * f[0] + 4.0 * f[1] - f[2]) / (2.0 * step);
        }
        return (4.0 * d[1] - d[0]) / 3.0;
    }
    double d[2];
    for (int k = 0; k < 2; ++k) {
        double step = h / (k + 1);
        d[k] = (force_of(law, r1, r2, v, gap + step) - force_of(law, r1, r2, v, gap - step)) /
               (2.0 * step);
    }
    return (4.0 * d[1] - d[0]) / 3.0;
}

static void check_slope(const cb_law *law, double r1, double r2, double v, double gap,
                        double rupture)
{
    double f, df;
    CHECK_STATUS(cb_force(law, r1, r2, v, gap, &f, &df), CB_OK);
    /* steps: 1e-3 of the room to contact or rupture; at contact, 1e-5 of the rupture
     * distance (one-sided) */
    double h = gap == 0.0 ? 1e-5 * rupture : 1e-3 * fmin(gap, rupture - gap);
    double numeric = numeric_slope(law, r1, r2, v, gap, h);
    /* relative 1e-6, plus the difference quotient's own rounding (100 ulp of F over h) */
    double tolerance = 1e-6 * fabs(df) + 100.0 * 2.2e-16 * f / h;
    ++derivative_checks;
    ++check_count;
    if (!(fabs(numeric - df) <= tolerance)) {
        ++check_failures;
        fprintf(stderr,
                "slope of %s (theta %.1f deg, r %g %g, V %g) at gap %.6g = %.6g rupture: "
                "analytic %.12g, numeric %.12g\n",
                cb_model_name(law->model), law->contact_angle / DEG, r1, r2, v, gap,
                gap / rupture, df, numeric);
    }
}

static void test_stiffness(void)
{
    struct { double r1, r2, v, theta; } cases[] = {
        {1e-3, 1e-3, 1e-12, 0.0},          /* V/R^3 = 1e-3 */
        {1e-3, 2.5e-3, 1e-11, 25.0 * DEG}, /* unequal, within Willett's range */
        {19e-6, 35e-6, 2e-19, 10.0 * DEG}, /* Gladkyy Table 1, R1 */
        {1e-3, 1e-3, 5e-11, 45.0 * DEG},   /* V/R^3 = 0.05, large angle */
        {1e-3, 4e-3, 1e-16, 70.0 * DEG},   /* tiny volume, beyond 50 deg (extensions) */
    };
    double fractions[] = {0.0, 1e-4, 1e-3, 0.02, 0.1, 0.3, 0.5, 0.8, 0.97, 0.999};
    for (int m = CB_MODEL_RICHEFEU; m <= CB_MODEL_SOULIE; ++m) {
        for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
            cb_law law = make_law((cb_model)m, cases[c].theta, CB_VALIDITY_EXTEND);
            double rupture;
            CHECK_STATUS(cb_rupture_distance(&law, cases[c].r1, cases[c].r2, cases[c].v,
                                             &rupture),
                         CB_OK);
            for (size_t i = 0; i < sizeof fractions / sizeof fractions[0]; ++i) {
                /* Willett's full fit at contact: F - F(0) ~ exp(-c ln^2 gap), flatter than
                 * any power, so no difference quotient converges there; its one-sided
                 * slope is 0 and the slope must vanish towards contact instead. */
                if (m == CB_MODEL_WILLETT && fractions[i] == 0.0) {
                    double f0, df0, f1, df1, f2, df2;
                    CHECK_STATUS(cb_force(&law, cases[c].r1, cases[c].r2, cases[c].v, 0.0,
                                          &f0, &df0), CB_OK);
                    CHECK_STATUS(cb_force(&law, cases[c].r1, cases[c].r2, cases[c].v,
                                          1e-6 * rupture, &f1, &df1), CB_OK);
                    CHECK_STATUS(cb_force(&law, cases[c].r1, cases[c].r2, cases[c].v,
                                          1e-12 * rupture, &f2, &df2), CB_OK);
                    CHECK(df0 == 0.0);
                    CHECK(fabs(df2) < 0.01 * fabs(df1) && fabs(df2) * rupture < 1e-9 * f0);
                    CHECK_REL(f2, f0, 1e-12);
                    continue;
                }
                check_slope(&law, cases[c].r1, cases[c].r2, cases[c].v,
                            fractions[i] * rupture, rupture);
            }
        }
    }
    /* the extensions' own branches: Willett's plateau (tiny V), Rabinovich's alpha cap
     * (V/R^3 = 2), Weigert's beta cap (V/R^3 = 0.5, theta = 60 deg) */
    struct { cb_model model; double v, theta; } ext[] = {
        {CB_MODEL_WILLETT, 1e-21, 30.0 * DEG},
        {CB_MODEL_RABINOVICH_UNCORRECTED, 2e-9, 10.0 * DEG},
        {CB_MODEL_WEIGERT, 5e-10, 60.0 * DEG},
        {CB_MODEL_WEIGERT, 2e-9, 0.0},
    };
    for (size_t c = 0; c < sizeof ext / sizeof ext[0]; ++c) {
        cb_law law = make_law(ext[c].model, ext[c].theta, CB_VALIDITY_EXTEND);
        double rupture;
        CHECK_STATUS(cb_rupture_distance(&law, 1e-3, 1e-3, ext[c].v, &rupture), CB_OK);
        for (size_t i = 0; i < sizeof fractions / sizeof fractions[0]; ++i)
            if (!(ext[c].model == CB_MODEL_WILLETT && fractions[i] == 0.0))
                check_slope(&law, 1e-3, 1e-3, ext[c].v, fractions[i] * rupture, rupture);
    }
    printf("stiffness: %d finite-difference comparisons\n", derivative_checks);
}

/* --------------------------------------------------------- radius conventions */

static void test_radius_conventions(void)
{
    double ra = 1e-3, rb = 3.7e-3, v = 2e-12, theta = 15.0 * DEG;
    for (int m = CB_MODEL_RICHEFEU; m <= CB_MODEL_SOULIE; ++m) {
        cb_law law = make_law((cb_model)m, theta, CB_VALIDITY_EXTEND);
        double rupture;
        CHECK_STATUS(cb_rupture_distance(&law, ra, rb, v, &rupture), CB_OK);
        double fractions[] = {0.0, 0.2, 0.7};
        for (int i = 0; i < 3; ++i) {
            double gap = fractions[i] * rupture;
            double f1 = force_of(&law, ra, rb, v, gap), f2 = force_of(&law, rb, ra, v, gap);
            CHECK(f1 == f2); /* swapping the spheres changes nothing, bit for bit */
        }
    }
    /* Rabinovich, Willett reduced, Weigert: R_h — not R_g (0.0019235), not R_r = R_h / 2 */
    double rh = harmonic(ra, rb);
    cb_law rab = make_law(CB_MODEL_RABINOVICH, theta, CB_VALIDITY_EXTEND);
    CHECK_REL(force_of(&rab, ra, rb, v, 0.0), 2.0 * PI * rh * gamma_water * cos(theta), 1e-14);
    cb_law red = make_law(CB_MODEL_WILLETT_REDUCED, theta, CB_VALIDITY_EXTEND);
    CHECK_REL(force_of(&red, ra, rb, v, 0.0), 2.0 * PI * rh * gamma_water * cos(theta), 1e-14);
    cb_law wil = make_law(CB_MODEL_WILLETT, theta, CB_VALIDITY_EXTEND);
    CHECK_REL(force_of(&wil, ra, rb, v, 1e-5), willett_printed(rh, v, theta, 1e-5, -0.00029076),
              1e-12);
}

/* ----------------------------------------------------------- Weigert: no bridge */

static void test_weigert_no_bridge(void)
{
    /* V/R^3 = 2 > 0.96 C_a C_theta at contact: A2's arcsin argument exceeds 1 */
    double r = 1e-3, v = 2e-9, f = -1.0, df = 0.0;
    cb_law strict = make_law(CB_MODEL_WEIGERT, 0.0, CB_VALIDITY_STRICT);
    CHECK_STATUS(cb_force(&strict, r, r, v, 0.0, &f, &df), CB_ERR_NO_BRIDGE);
    CHECK(f == -1.0); /* nothing written on error */
    cb_law extend = make_law(CB_MODEL_WEIGERT, 0.0, CB_VALIDITY_EXTEND);
    double rupture;
    CHECK_STATUS(cb_rupture_distance(&extend, r, r, v, &rupture), CB_OK);
    double previous = HUGE_VAL;
    for (int i = 0; i <= 200; ++i) {
        double gap = rupture * i / 200.0;
        CHECK_STATUS(cb_force(&extend, r, r, v, gap, &f, &df), CB_OK);
        CHECK(isfinite(f) && isfinite(df) && f >= 0.0 && f <= previous);
        previous = f;
    }
    /* the capped bridge at contact still carries a Derjaguin-size force */
    CHECK_STATUS(cb_force(&extend, r, r, v, 0.0, &f, &df), CB_OK);
    CHECK(f > 0.3 * 2.0 * PI * r * gamma_water && f < 2.0 * PI * r * gamma_water);
    /* V/R^3 = 0.316, theta = 0: at the rupture distance eq. 5 has turned repulsive (the
     * toroid's neck is about to close): strict says no bridge, extend gives F = 0 there,
     * after a monotone fall. */
    {
        double v2 = 3.16e-10, d;
        CHECK_STATUS(cb_rupture_distance(&strict, r, r, v2, &d), CB_OK);
        CHECK_STATUS(cb_force(&strict, r, r, v2, d, &f, &df), CB_ERR_NO_BRIDGE);
        CHECK_STATUS(cb_force(&strict, r, r, v2, 0.98 * d, &f, &df), CB_OK);
        CHECK(f > 0.0);
        CHECK_STATUS(cb_force(&extend, r, r, v2, d, &f, &df), CB_OK);
        CHECK(f == 0.0 && df == 0.0);
    }
}

/* ------------------------------------------------ the documented extensions */

static void test_extensions(void)
{
    double r = 1e-3, f, df;
    /* Soulie with C < 0 (V* = 1e-21 < 1.5e-19): the published bracket C + exp(...) is
     * negative once exp(A gap / R2 + B) < -C; the law gives 0 there, with dF = 0. */
    {
        cb_law soulie = make_law(CB_MODEL_SOULIE, 0.0, CB_VALIDITY_EXTEND);
        double v = 1e-21 * r * r * r, lv = log(1e-21), d;
        double c = 0.0018 * lv + 0.078;
        CHECK(c < 0.0);
        CHECK_STATUS(cb_rupture_distance(&soulie, r, r, v, &d), CB_OK);
        double a = -1.1 * pow(1e-21, -0.53), b = -0.0082 * lv + 0.48;
        double published = PI * gamma_water * r * (c + exp(a * 0.5 * d / r + b));
        CHECK(published < 0.0);
        CHECK_STATUS(cb_force(&soulie, r, r, v, 0.5 * d, &f, &df), CB_OK);
        CHECK(f == 0.0 && df == 0.0);
        CHECK_STATUS(cb_force(&soulie, r, r, v, 0.0, &f, &df), CB_OK);
        CHECK_REL(f, PI * gamma_water * r * (c + exp(b)), 1e-12);
    }
    /* Willett full: below V* = 1e-5 the coefficients are those of V* = 1e-5, so the
     * contact force no longer depends on V; above 50 deg, the 50-deg fit times
     * cos(theta) / cos(50 deg). */
    {
        cb_law w30 = make_law(CB_MODEL_WILLETT, 30.0 * DEG, CB_VALIDITY_EXTEND);
        double floor_force = force_of(&w30, r, r, 1e-5 * r * r * r, 0.0);
        CHECK_REL(force_of(&w30, r, r, 1e-12 * r * r * r, 0.0), floor_force, 1e-14);
        CHECK_REL(floor_force, willett_printed(r, 1e-5 * r * r * r, 30.0 * DEG, 0.0, -0.00029076),
                  1e-12);
        cb_law w50 = make_law(CB_MODEL_WILLETT, 50.0 * DEG, CB_VALIDITY_EXTEND);
        cb_law w70 = make_law(CB_MODEL_WILLETT, 70.0 * DEG, CB_VALIDITY_EXTEND);
        CHECK_REL(force_of(&w70, r, r, 1e-12, 0.0),
                  force_of(&w50, r, r, 1e-12, 0.0) * cos(70.0 * DEG) / cos(50.0 * DEG), 1e-14);
        /* tiny volume: the plateau beyond S* keeps F constant up to rupture */
        double v = 1e-12 * r * r * r, d;
        CHECK_STATUS(cb_rupture_distance(&w30, r, r, v, &d), CB_OK);
        double f1 = force_of(&w30, r, r, v, 0.6 * d), f2 = force_of(&w30, r, r, v, d);
        CHECK(f1 == f2 && f1 > 0.0);
        CHECK(f1 < 0.02 * floor_force);
    }
    /* Rabinovich uncorrected: alpha held at (pi - theta)/2 where the term is cos^2(theta/2) */
    {
        double theta = 40.0 * DEG;
        cb_law unc = make_law(CB_MODEL_RABINOVICH_UNCORRECTED, theta, CB_VALIDITY_EXTEND);
        double v = 5.0 * r * r * r; /* alpha(0)^2 = 2 sqrt(V / (2 pi R)) / R = 1.78 */
        CHECK_REL(force_of(&unc, r, r, v, 0.0),
                  2.0 * PI * r * gamma_water * (cos(theta) + pow(cos(0.5 * theta), 2.0)), 1e-14);
    }
}

/* ------------------------------------------ the radian trap and the exact judge */

static double exact_force(double r1, double r2, double theta, double v, double gap)
{
    cb_exact_problem p;
    memset(&p, 0, sizeof p);
    p.r1 = r1;
    p.r2 = r2;
    p.contact_angle1 = p.contact_angle2 = theta;
    p.surface_tension = gamma_water;
    p.volume = v;
    cb_exact_bridge b;
    cb_status s = cb_exact_solve(&p, gap, &b);
    CHECK_STATUS(s, CB_OK);
    return s == CB_OK ? b.force : NAN;
}

static double exact_rupture(double r1, double r2, double theta, double v)
{
    cb_exact_problem p;
    memset(&p, 0, sizeof p);
    p.r1 = r1;
    p.r2 = r2;
    p.contact_angle1 = p.contact_angle2 = theta;
    p.surface_tension = gamma_water;
    p.volume = v;
    double d = NAN;
    cb_exact_bridge b;
    CHECK_STATUS(cb_exact_rupture(&p, &d, &b), CB_OK);
    return d;
}

static void test_against_exact(void)
{
    double r = 1e-3;
    /* theta in radians: Willett at 30 deg, V* = 1e-3, gives F(0) / (2 pi R gamma) = 0.773,
     * near cos 30 deg = 0.866 (the exact value is 0.797). Fed "30" (degrees read as
     * radians) exp(f1) would be 2.7e-243: silently no force. */
    {
        cb_law wil = make_law(CB_MODEL_WILLETT, 30.0 * DEG, CB_VALIDITY_STRICT);
        double ratio = force_of(&wil, r, r, 1e-12, 0.0) / (2.0 * PI * r * gamma_water);
        CHECK(fabs(ratio - cos(30.0 * DEG)) < 0.15 * cos(30.0 * DEG));
        CHECK(fabs(willett_printed(r, 1e-12, 30.0, 0.0, -0.00029076) /
                       (2.0 * PI * r * gamma_water) -
                   cos(30.0 * DEG)) > 0.5); /* what degrees would have given */
    }
    /* The f1 coefficient: -0.00029076 (ours) tracks the exact contact force within 5% for
     * theta up to 50 deg; -0.0029076 is off by more than 10% at 30-50 deg. */
    {
        double thetas[] = {0.0, 30.0 * DEG, 45.0 * DEG, 50.0 * DEG};
        double volumes[] = {1e-13, 1e-12, 1e-11}; /* V* = 1e-4 .. 1e-2 */
        for (int i = 0; i < 4; ++i) {
            cb_law wil = make_law(CB_MODEL_WILLETT, thetas[i], CB_VALIDITY_STRICT);
            for (int j = 0; j < 3; ++j) {
                double exact = exact_force(r, r, thetas[i], volumes[j], 0.0);
                double ours = force_of(&wil, r, r, volumes[j], 0.0);
                double other = willett_printed(r, volumes[j], thetas[i], 0.0, -0.0029076);
                CHECK(fabs(ours / exact - 1.0) < 0.05);
                if (thetas[i] >= 30.0 * DEG && volumes[j] <= 1e-12)
                    CHECK(fabs(other / exact - 1.0) > 0.10);
            }
        }
        /* ... and along the gap, to 3/4 of the exact rupture distance */
        for (int i = 0; i < 3; ++i) {
            cb_law wil = make_law(CB_MODEL_WILLETT, thetas[i], CB_VALIDITY_STRICT);
            double v = 1e-11, d = exact_rupture(r, r, thetas[i], v);
            for (int k = 1; k <= 6; ++k) {
                double gap = d * k / 8.0;
                CHECK(fabs(force_of(&wil, r, r, v, gap) / exact_force(r, r, thetas[i], v, gap) -
                           1.0) < 0.05);
            }
        }
    }
    /* Radius of the Derjaguin limit: for r2 = 3 r1 the exact contact force at small volume
     * tends to 2 pi gamma R_h cos(theta) (R_h = 1.5 r1; R_g = 1.73 r1, R_r = 0.75 r1). */
    {
        double r1 = 1e-3, r2 = 3e-3, rh = harmonic(r1, r2), theta = 20.0 * DEG;
        double exact = exact_force(r1, r2, theta, 1e-6 * rh * rh * rh, 0.0);
        CHECK_REL(exact, 2.0 * PI * gamma_water * rh * cos(theta), 0.03);
        cb_law rab = make_law(CB_MODEL_RABINOVICH, theta, CB_VALIDITY_EXTEND);
        CHECK_REL(force_of(&rab, r1, r2, 1e-6 * rh * rh * rh, 0.0), exact, 0.03);
    }
    /* Weigert, A6 with a/2: at contact within 6% of exact; F stays attractive to rupture
     * where the printed "+ a" turns repulsive (theta = 0, V* = 1e-3 and 1e-2); and the law
     * keeps its known over-prediction at moderate gaps (Gladkyy §3), > 1.3 x exact at half
     * the rupture distance — the law as published, not corrected towards exact. */
    {
        double volumes[] = {1e-12, 1e-11};
        for (int j = 0; j < 2; ++j) {
            cb_law wei = make_law(CB_MODEL_WEIGERT, 0.0, CB_VALIDITY_STRICT);
            double v = volumes[j];
            CHECK_REL(force_of(&wei, r, r, v, 0.0), exact_force(r, r, 0.0, v, 0.0), 0.06);
            double d = exact_rupture(r, r, 0.0, v);
            CHECK(force_of(&wei, r, r, v, 0.9 * d) > 0.0);
            CHECK(weigert_printed(r, v, 0.0, 0.9 * d, 1.0) < 0.0);
            CHECK(force_of(&wei, r, r, v, 0.5 * d) > 1.3 * exact_force(r, r, 0.0, v, 0.5 * d));
        }
    }
}

/* Rupture rules against the exact fold over theta 0-40 deg, size ratio 1-10 and V* 1e-5 to
 * 0.1 (the README's grid, a corner of each): Willett's unequal-sphere form within 8 %
 * everywhere; Gladkyy eq. 2 (the equal-sphere form) off by more than 30 % at the large
 * ratio and volume, and equal to the unequal form at ratio 1. */
static void test_rupture_rules_against_exact(void)
{
    const double thetas[] = {0.0, 20.0 * DEG, 40.0 * DEG};
    const double ratios[] = {1.0, 3.0, 10.0};
    const double scaled_volumes[] = {1e-5, 1e-3, 1e-1};
    double worst_unequal = 0.0, worst_equal = 0.0;
    for (int a = 0; a < 3; ++a) {
        cb_law equal, unequal;
        cb_message msg;
        CHECK_STATUS(cb_law_init(&equal, CB_MODEL_WILLETT, gamma_water, thetas[a]), CB_OK);
        CHECK_STATUS(cb_law_init(&unequal, CB_MODEL_WILLETT, gamma_water, thetas[a]), CB_OK);
        CHECK_STATUS(cb_law_configure(&unequal, "rupture", "willett/unequal", &msg), CB_OK);
        CHECK_STATUS(cb_law_prepare(&equal, &msg), CB_OK);
        CHECK_STATUS(cb_law_prepare(&unequal, &msg), CB_OK);
        for (int q = 0; q < 3; ++q) {
            double r1 = 1e-3, r2 = 1e-3 * ratios[q], rh = harmonic(r1, r2);
            for (int k = 0; k < 3; ++k) {
                double v = scaled_volumes[k] * rh * rh * rh, d_equal = 0.0, d_unequal = 0.0;
                double exact = exact_rupture(r1, r2, thetas[a], v);
                CHECK_STATUS(cb_rupture_distance(&equal, r1, r2, v, &d_equal), CB_OK);
                CHECK_STATUS(cb_rupture_distance(&unequal, r1, r2, v, &d_unequal), CB_OK);
                worst_unequal = fmax(worst_unequal, fabs(d_unequal / exact - 1.0));
                worst_equal = fmax(worst_equal, fabs(d_equal / exact - 1.0));
                if (q == 0) CHECK_REL(d_unequal, d_equal, 1e-15);
            }
        }
    }
    CHECK(worst_unequal < 0.08);
    CHECK(worst_equal > 0.30);
    printf("rupture rules against the exact fold: willett/unequal within %.1f %%, willett "
           "(eq. 2) %.1f %%\n", 100 * worst_unequal, 100 * worst_equal);
}

int main(int argc, char **argv)
{
    (void)argc;
    test_contact_limits();
    test_printed_forms();
    test_stiffness();
    test_radius_conventions();
    test_weigert_no_bridge();
    test_extensions();
    test_against_exact();
    test_rupture_rules_against_exact();
    return check_report(argv[0]);
}
