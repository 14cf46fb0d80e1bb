/* law_table.c — the exact Laplace-Young solution, tabulated and interpolated.
 *
 * At preparation the table is built from the exact solver for the law's contact angle,
 * over the size ratio through q = sqrt(1 - R_small/R_large) (uniform in q, for s =
 * R_small/R_large in [0, 1], s = 0 the sphere-plane bridge of a wall, r2 = CB_PLANE, solved
 * as such; near s = 1 the rupture distance and the force near the
 * fold change over a narrow range of s, where the symmetric bridge becomes unstable to
 * liquid shifting to one sphere (above about 30 degrees, and lower at the largest volumes;
 * the rupture distance falls there like (1 - s)^(2/3)): q spreads that range out, and 24
 * steps in q resolve it; in V/R_h^3 and gap/R_h the bridge tends smoothly to the plane's
 * as s -> 0, its force like s), the scaled volume v = V/R_h^3 (uniform in ln v, nodes reaching
 * a quarter decade beyond the domain [1e-6, 0.3] so that its edges get centred
 * stencils), and the gap through
 *     w = sqrt(1 - sqrt(gap / rupture))  in [0, 1]  (w = 1 at contact, 0 at the fold),
 * i.e. gap = rupture (1 - w^2)^2. Why w and not gap/rupture: the force has two
 * narrow features, a steep fall over gaps of order sqrt(V/R) near contact (Willett's
 * S+ scale, a small fraction of the rupture distance for small V) and a square-root
 * singularity at the fold, F ~ F* + c sqrt(rupture - gap). In w both are smooth and
 * spread out (gap ~ (1 - w)^2 near contact, sqrt(rupture - gap) ~ w near the fold); the
 * cells are uniform in a cubic of w that narrows them further near contact (gap_node).
 * Stored: sqrt(R_h v^(1/3) / rupture) at each (s, v), the rupture distance without its
 * V^(1/3) growth (Lian's scaling), which a cubic in ln v follows only to 1e-4; and in each
 * gap cell of each (s, v) node the cubic of F/(2 pi gamma R_h), from the cubic spline
 * through the cell ends (spline_slopes). Interpolation: cubic Lagrange in q and ln v
 * (4-point stencils, the same weights for the rupture distance and the force), the
 * cell's cubic in the gap.
 * The fold needs the rupture distance to ~1e-5: within 1e-4 of it the exact force rises as
 * a square root of the distance to its fold, so an error e of the table's rupture distance
 * is a force error of up to ~1.6 sqrt(e) there.
 * Domain and accuracy (table_validity; tests/test_table.c holds them): size ratio 1 to the
 * plane, V/R_h^3 1e-6..0.3, theta 0..80 degrees; the rupture distance within 5e-5 (2e-4
 * for nearly equal spheres above 30 degrees), the force within 0.1 % up to 1 - 1e-4 of
 * the rupture distance (0.5 % for nearly equal spheres in the last 5e-4 of it), 1 % beyond.
 * Outside the table (validity extend): s and v are clamped for the scaled force, and the
 * rupture distance is extended with the V^(1/3) scaling of Lian's rule from the edge. */
#include "laws.h"

#include <math.h>
#include <stdlib.h>


/* The grid. Node positions are given together with the reciprocal steps the lookup
 * multiplies by, since a division on every call would cost more than the interpolation:
 *   size ratio: q = sqrt(1 - s) at q_i = i / 24 (q = 1: the plane);
 *   volume:     ln v at ln v_j = ln(10^-6.25) + j ln(10)/4 (four per decade, 10^-0.25 last). */
enum { TABLE_RATIOS = 25, TABLE_VOLUMES = 25, TABLE_GAPS = 33 };
static const double table_ratio_nodes_per_q = 24.0;
static const double table_volume_min = 1e-6;    /* the domain in V / R_h^3 */
static const double table_volume_max = 0.3;
static const double table_log_volume_min = -13.815510557964274; /* ln 1e-6 */
static const double table_log_volume_max = -1.2039728043259361; /* ln 0.3 */
static const double table_log_volume_first = -14.391156831212787; /* -6.25 ln 10 */
static const double table_log_volume_step = 0.5756462732485115;   /* ln(10) / 4 */
static const double table_volume_nodes_per_log = 1.737177927613007; /* 4 / ln 10 */

/* Integration steps of the exact solver for the nodes: half its default, within 1e-7 of
 * it in the rupture distance and 3e-8 in the force (against 1024 steps) at half the cost,
 * which pays for the 24 steps in q. */
static const int table_solver_steps = CB_EXACT_DEFAULT_STEPS / 2;

/* The cubic of one gap cell, F / (2 pi gamma R_h) = c[0] + c[1] x + c[2] x^2 + c[3] x^3 in
 * x = (y - y_k) / h, as one four-lane vector (GCC and Clang vector extension: one SSE
 * register on x86-64, NEON on arm64, scalar code elsewhere): the lookup sums the four
 * coefficients of the 16 stencil nodes with the same weights, with nothing left to form
 * from node values and slopes. In single precision (6e-8, 1000 times below the
 * interpolation's error): half the memory (320 kB, within a core's L2 cache) and half the
 * vector operations of double; the sum is taken to double before the cubic is evaluated. */
typedef float cell_cubic __attribute__((vector_size(4 * sizeof(float))));

struct cb_table {
    double contact_angle;
    /* sqrt(R_h v^(1/3) / rupture): the rupture distance without its V^(1/3) growth (Lian's
     * scaling), as the inverse square root the gap coordinate multiplies by */
    double rupture_root[TABLE_RATIOS][TABLE_VOLUMES];
    cell_cubic force[TABLE_GAPS - 1][TABLE_RATIOS][TABLE_VOLUMES]; /* per cell, the (s, v) plane */
};

static double ratio_node(int i) /* s at node i (q ascending, s descending from 1 to 0) */
{
    double q = (double)i / table_ratio_nodes_per_q;
    return 1.0 - q * q;
}

static double log_volume_node(int j)
{
    return table_log_volume_first + table_log_volume_step * j;
}

/* The gap cells are uniform in y = w - w^2 + w^3 (increasing, y = 0 at the fold and 1 at
 * contact, dy/dw = 1 at the fold and 2 at contact, 2/3 at w = 1/3): cells half as wide in w
 * near contact, where the steep fall of the force over gaps ~ sqrt(V/R) is narrowest in w at
 * the smallest volumes (uniform cells in w left 0.1 % there at V/R_h^3 = 1e-6), the same
 * at the fold, wider in between, where the force is smoothest. A cubic: one multiply-add
 * more per call than w itself. */
static double gap_node(int k) { return (double)k / (TABLE_GAPS - 1); } /* y */

static double cell_coordinate(double w) { return w * (1.0 - w * (1.0 - w)); } /* y */

static double cell_coordinate_slope(double w) { return 1.0 - w * (2.0 - 3.0 * w); } /* dy/dw */

/* w at y, by Newton's method from w = y (y is monotone with a slope >= 2/3: at most a few
 * steps to rounding; at preparation only). */
static double gap_coordinate_at(double y)
{
    double w = y;
    for (int step = 0; step < 50; ++step) {
        double change = (cell_coordinate(w) - y) / cell_coordinate_slope(w);
        w -= change;
        if (fabs(change) <= 1e-16) break;
    }
    return w;
}

/* gap / rupture at a gap coordinate w (table_force inverts it). */
static double gap_fraction(double w)
{
    double c = 1.0 - w * w;
    return c * c;
}

/* The w-slopes of the cubic spline through the forces (C2, fourth order: the force is a
 * smooth function of w over the whole bridge, so a spline follows it to ~h^4; the monotone
 * Fritsch-Carlson slopes used until 2026-12 were second order near contact and at extrema,
 * 0.15 % off near contact, and could not follow the non-monotone force near contact above
 * about 70 degrees). At contact (w = 1) the slope is the exact one, 0, since gap ~
 * (1 - w)^2 there. At the fold (w = 0) the end is not-a-knot (the first two cells one
 * cubic): the force has a square root there, F ~ F* + c w, or none where the symmetric
 * bridge of nearly equal spheres ruptures by instability (above about 30 degrees),
 * F ~ F* + b w^2, and the condition follows both. Solved by the Thomas algorithm on
 *     m[k-1] + 4 m[k] + m[k+1] = 3 (y[k+1] - y[k-1]) / h,   0 < k < n-1,
 *     m[0] + 2 m[1] = (-5 y[0] + 4 y[1] + y[2]) / (2 h),     m[n-1] = 0. */
static void spline_slopes(const double *y, double h, double *m)
{
    enum { N = TABLE_GAPS };
    double diagonal[N], upper[N], rhs[N];
    diagonal[0] = 1.0;
    upper[0] = 2.0;
    rhs[0] = (-5.0 * y[0] + 4.0 * y[1] + y[2]) / (2.0 * h);
    for (int k = 1; k < N - 1; ++k) { /* eliminate m[k-1] from row k */
        double factor = 1.0 / diagonal[k - 1];
        diagonal[k] = 4.0 - upper[k - 1] * factor;
        upper[k] = 1.0;
        rhs[k] = 3.0 * (y[k + 1] - y[k - 1]) / h - rhs[k - 1] * factor;
    }
    m[N - 1] = 0.0;
    for (int k = N - 2; k >= 0; --k) m[k] = (rhs[k] - upper[k] * m[k + 1]) / diagonal[k];
}

static cb_status fill_node(struct cb_table *table, int i, int j, cb_message *msg)
{
    double s = ratio_node(i), v = exp(log_volume_node(j));
    double r_small = 1.0, r_large = i == TABLE_RATIOS - 1 ? CB_PLANE : 1.0 / s;
    double rh = cb_radius_harmonic(r_small, r_large);
    cb_exact_problem problem = {r_small, r_large, table->contact_angle, table->contact_angle,
                                1.0, v * rh * rh * rh, table_solver_steps};
    double rupture = 0.0;
    cb_exact_bridge bridges[TABLE_GAPS];
    cb_status status = cb_exact_rupture(&problem, &rupture, &bridges[TABLE_GAPS - 1]);
    if (status == CB_OK) {
        double gaps[TABLE_GAPS - 1];
        /* Ascending gaps: y from 1 (contact) down to y_1; the fold (y = 0) is known. */
        for (int k = 0; k < TABLE_GAPS - 1; ++k)
            gaps[k] = rupture * gap_fraction(gap_coordinate_at(gap_node(TABLE_GAPS - 1 - k)));
        gaps[0] = 0.0;
        status = cb_exact_curve(&problem, TABLE_GAPS - 1, gaps, bridges);
    }
    if (status != CB_OK)
        return cb_fail(msg, status,
                       "table law: exact solver failed at size ratio %g, V/R_h^3 = %g, "
                       "theta = %g degrees: %s",
                       r_large, v, table->contact_angle * 180.0 / CB_PI,
                       cb_status_message(status));
    table->rupture_root[i][j] = sqrt(rh * cbrt(v) / rupture);
    double f[TABLE_GAPS], m[TABLE_GAPS], h = gap_node(1);
    for (int k = 0; k < TABLE_GAPS - 1; ++k)
        f[TABLE_GAPS - 1 - k] = bridges[k].force / (2.0 * CB_PI * rh);
    f[0] = bridges[TABLE_GAPS - 1].force / (2.0 * CB_PI * rh);
    spline_slopes(f, h, m);
    for (int k = 0; k < TABLE_GAPS - 1; ++k) { /* the Hermite cubic of the cell, in x */
        double d = f[k + 1] - f[k], hm0 = h * m[k], hm1 = h * m[k + 1];
        cell_cubic c = {(float)f[k], (float)hm0, (float)(3.0 * d - 2.0 * hm0 - hm1),
                        (float)(-2.0 * d + hm0 + hm1)};
        table->force[k][i][j] = c;
    }
    return CB_OK;
}

static cb_status table_create(double contact_angle, struct cb_table **table, cb_message *msg)
{
    struct cb_table *t = malloc(sizeof *t);
    if (!t) return cb_fail(msg, CB_ERR_NO_MEMORY, "table law: out of memory");
    t->contact_angle = contact_angle;
    for (int i = 0; i < TABLE_RATIOS; ++i) {
        for (int j = 0; j < TABLE_VOLUMES; ++j) {
            cb_status status = fill_node(t, i, j, msg);
            if (status != CB_OK) {
                free(t);
                return status;
            }
        }
    }
    *table = t;
    return CB_OK;
}

/* The table a prepared table law owns (law->data). */
static const struct cb_table *table_of(const cb_law *law)
{
    return (const struct cb_table *)law->data;
}

static void table_release(cb_law *law)
{
    free(law->data);
    law->data = NULL;
}

/* The table depends on the contact angle only: kept while theta is unchanged. */
static cb_status table_prepare(cb_law *law, cb_message *msg)
{
    if (law->data && table_of(law)->contact_angle == law->contact_angle) return CB_OK;
    table_release(law);
    struct cb_table *table = NULL;
    cb_status status = table_create(law->contact_angle, &table, msg);
    if (status != CB_OK) return status;
    law->data = table;
    return CB_OK;
}

/* A 4-point cubic Lagrange stencil on a uniform grid of n nodes for coordinate x
 * (in node units, clamped into [0, n-1]): first node and weights. */
static int lagrange_stencil(double x, int n, double w[4])
{
    x = x < 0.0 ? 0.0 : x > n - 1 ? n - 1 : x;
    int first = (int)x - 1; /* x >= 0: the cast is the floor */
    first = first < 0 ? 0 : first > n - 4 ? n - 4 : first;
    double t = x - first; /* in [0, 3] */
    double t1 = t - 1.0, t2 = t - 2.0, t3 = t - 3.0;
    w[0] = -t1 * t2 * t3 * (1.0 / 6.0);
    w[1] = t * t2 * t3 * 0.5;
    w[2] = -t * t1 * t3 * 0.5;
    w[3] = t * t1 * t2 * (1.0 / 6.0);
    return first;
}

/* sqrt(R_h / rupture) where the pair sits: the tabulated sqrt(R_h v^(1/3) / rupture) times
 * v^(-1/6) (beyond the table's volumes, the edge value: Lian's V^(1/3) scaling). */
static double rupture_root(const struct cb_table *t, const cb_table_position *p,
                           double inverse_sixth_root_volume)
{
    double row_sum[4];
    for (int a = 0; a < 4; ++a) {
        const double *row = &t->rupture_root[p->ratio_first + a][p->volume_first];
        const double *wt = p->volume_weight;
        row_sum[a] = (wt[0] * row[0] + wt[1] * row[1]) + (wt[2] * row[2] + wt[3] * row[3]);
    }
    const double *wt = p->ratio_weight;
    return ((wt[0] * row_sum[0] + wt[1] * row_sum[1]) +
            (wt[2] * row_sum[2] + wt[3] * row_sum[3])) * inverse_sixth_root_volume;
}

/* The pair's size ratio in ratio nodes: q = sqrt(1 - R_small / R_large) (at a plane q = 1,
 * the last node). */
static double ratio_coordinate(const cb_pair *pair)
{
    return sqrt(1.0 - pair->r_small / pair->r_large) * table_ratio_nodes_per_q;
}

/* The 4 x 4 stencil at these coordinates (in nodes) and its weights, in double for the
 * rupture distance and in single precision for the force's cells. */
static void place(cb_table_position *p, double x_ratio, double x_volume)
{
    p->ratio_first = lagrange_stencil(x_ratio, TABLE_RATIOS, p->ratio_weight);
    p->volume_first = lagrange_stencil(x_volume, TABLE_VOLUMES, p->volume_weight);
    for (int n = 0; n < 4; ++n) {
        p->cell_ratio_weight[n] = (float)p->ratio_weight[n];
        p->cell_volume_weight[n] = (float)p->volume_weight[n];
    }
}

/* Where the pair sits in the table: the 4 x 4 stencil in (q, ln v), its weights along
 * each axis (a sum over the stencil is four rows summed with the volume weights, then the
 * rows with the ratio weights: no 16 products to form first), and its rupture distance.
 * This law's cost is the latency of its chain of dependent steps
 * (a division, the logarithm, the stencil, the gap coordinate's square roots, the loads):
 * what does not depend on the stencil is computed beside it, not after it. */
static void table_locate(const cb_law *law, cb_pair *pair)
{
    cb_table_position *p = &pair->table;
    /* V / R_h^3 with 1/R_h = (R1 + R2) / (2 R1 R2) from the radii: a division that runs
     * alongside R_h's own instead of after it; 1 / (2 R1) at a plane */
    double inverse_rh = pair->plane ? 0.5 / pair->r1
                                    : (pair->r1 + pair->r2) / (2.0 * pair->r1 * pair->r2);
    double v = pair->volume * (inverse_rh * inverse_rh * inverse_rh);
    double log_volume = log(v);
    double clamped = log_volume < table_log_volume_min   ? table_log_volume_min
                     : log_volume > table_log_volume_max ? table_log_volume_max
                                                         : log_volume;
    p->volume_coordinate = (clamped - table_log_volume_first) * table_volume_nodes_per_log;
    place(p, ratio_coordinate(pair), p->volume_coordinate);
    double root = rupture_root(table_of(law), p, exp(log_volume * (-1.0 / 6.0)));
    p->scaled_rupture = 1.0 / (root * root);
}

static double table_rupture(const cb_law *law, const cb_pair *pair)
{
    (void)law;
    return pair->table.scaled_rupture * pair->r_harmonic;
}

/* The inverse of the rupture distance in the volume.  Outside the table's volumes the
 * rupture distance is its edge value times (v / v_edge)^(1/3) (scaled_rupture), inverted
 * exactly; inside, by bisection in ln v (it is monotone: a larger bridge reaches further). */
static double table_rupture_volume(const cb_law *law, const cb_pair *pair_in, double gap)
{
    cb_pair pair = *pair_in;
    double rh = pair.r_harmonic;
    double rh3 = rh * rh * rh;
    double scaled_gap = gap / rh;
    pair.volume = table_volume_min * rh3;
    table_locate(law, &pair);
    if (scaled_gap <= pair.table.scaled_rupture) {
        double shrink = scaled_gap / pair.table.scaled_rupture;
        return table_volume_min * (shrink * shrink * shrink) * rh3;
    }
    pair.volume = table_volume_max * rh3;
    table_locate(law, &pair);
    if (scaled_gap >= pair.table.scaled_rupture) {
        double grow = scaled_gap / pair.table.scaled_rupture;
        return table_volume_max * (grow * grow * grow) * rh3; /* inf beyond double range */
    }
    double lo = log(table_volume_min), hi = log(table_volume_max);
    for (int iteration = 0; iteration < 200 && hi - lo > 1e-14 * fabs(hi); ++iteration) {
        double mid = 0.5 * (lo + hi);
        pair.volume = exp(mid) * rh3;
        table_locate(law, &pair);
        if (pair.table.scaled_rupture < scaled_gap) lo = mid;
        else hi = mid;
    }
    return exp(hi) * rh3;
}

/* The cubic of the gap cell k, weighted over the pair's (q, ln v) stencil: the 16 nodes'
 * coefficients summed per ratio row first, then the rows (short dependency chains). */
static void cubic_at(const struct cb_table *t, const cb_table_position *p, int k, double c[4])
{
    cell_cubic row_sum[4];
    for (int a = 0; a < 4; ++a) {
        const cell_cubic *row = t->force[k][p->ratio_first + a] + p->volume_first;
        const float *wt = p->cell_volume_weight;
        row_sum[a] = (wt[0] * row[0] + wt[1] * row[1]) + (wt[2] * row[2] + wt[3] * row[3]);
    }
    const float *wt = p->cell_ratio_weight;
    cell_cubic sum =
        (wt[0] * row_sum[0] + wt[1] * row_sum[1]) + (wt[2] * row_sum[2] + wt[3] * row_sum[3]);
    for (int n = 0; n < 4; ++n) c[n] = sum[n];
}

/* The cell of y (the last one for y = 1) and x = (y - y_k) / h in it. */
static int cell_of(double y, double *x)
{
    double scaled = y * (TABLE_GAPS - 1);
    int k = (int)scaled;
    if (k > TABLE_GAPS - 2) k = TABLE_GAPS - 2;
    *x = scaled - k;
    return k;
}

/* The cell's cubic and its dF/dx (dF/dy is (TABLE_GAPS - 1) times it) in powers of x, not
 * by Horner's rule: x is known before the coefficients are loaded, so that after the loads
 * the terms are independent products and a sum. */
static double cubic_value(const double c[4], double x)
{
    double x2 = x * x;
    return (c[0] + c[1] * x) + (c[2] * x2 + c[3] * (x2 * x));
}

static double cubic_slope(const double c[4], double x)
{
    return c[1] + (c[2] * (2.0 * x) + c[3] * (3.0 * x * x));
}

/* Where the stiffness is taken in the end cells (table_force). */
static const double slope_w_min = 0.5 / (TABLE_GAPS - 1);
static const double slope_w_max = 1.0 - 0.25 / (TABLE_GAPS - 1);

/* F and, if stiffness is not NULL, dF/dgap at gap >= 0 for a placed stencil and the
 * table's rupture distance of the pair.  w from sqrt(gap / rupture): one division, which
 * lets a bridge's stored rupture distance (the table's own, bit for bit) stand for the
 * interpolated one. */
static void force_at(const cb_law *law, const cb_table_position *p, double r_harmonic,
                     double rupture, double gap, double *force, double *stiffness)
{
    double root_fraction = sqrt(gap / rupture);
    double w = gap < rupture && root_fraction < 1.0 ? sqrt(1.0 - root_fraction) : 0.0;
    double x = 0.0, c[4];
    int k = cell_of(cell_coordinate(w), &x);
    cubic_at(table_of(law), p, k, c);
    double scale = 2.0 * CB_PI * law->surface_tension * r_harmonic;
    double value = cubic_value(c, x);
    if (!(value > 0.0) || gap >= rupture) {
        /* clamped at 0 (a repulsive exact force near contact at large angles), or held at
         * its value at the fold beyond it (a rupture rule reaching further than the
         * exact one): the force does not change with the gap there */
        *force = value > 0.0 ? value * scale : 0.0;
        if (stiffness) *stiffness = 0.0;
        return;
    }
    *force = value * scale;
    if (!stiffness) return;
    /* dF/dgap = dF/dy dy/dw / (dgap/dw), dgap/dw = -4 rupture w (1 - w^2). Both vanish
     * at contact (a finite limit) and dgap/dw vanishes at the fold (the exact force has an
     * infinite slope there). Within half a cell of either end the stiffness is taken at
     * that half-cell point, so that it stays finite and well conditioned: w = h/2 at the
     * fold, 1 - h/4 at contact (dy/dw is 1 and 2 there); the point lies in the same end
     * cell, so the cell found for w serves. */
    double w_slope = w < slope_w_min ? slope_w_min : w > slope_w_max ? slope_w_max : w;
    double x_slope = cell_coordinate(w_slope) * (TABLE_GAPS - 1) - k;
    *stiffness = cubic_slope(c, x_slope) * (TABLE_GAPS - 1) * cell_coordinate_slope(w_slope) *
                 scale / (-4.0 * rupture * w_slope * (1.0 - w_slope * w_slope));
}

static cb_status table_force(const cb_law *law, const cb_pair *pair, double gap,
                             double *force, double *stiffness)
{
    const cb_table_position *p = &pair->table;
    force_at(law, p, pair->r_harmonic, p->scaled_rupture * pair->r_harmonic, gap, force,
             stiffness);
    return CB_OK;
}

/* A bridge keeps its volume coordinate (ln v in nodes: the logarithm, the one costly step
 * of locating it) when its rupture distance is the table's own, which it then keeps too;
 * under another rupture rule it keeps none (0) and its force is evaluated in full.  The
 * coordinate is at least 1 (the domain starts a node inside the grid), so never 0. */
static double table_bridge_constant(const cb_law *law, const cb_pair *pair)
{
    return law->rupture_in_use == CB_RUPTURE_EXACT ? pair->table.volume_coordinate : 0.0;
}

/* A stretched bridge's force from its constants: the stencil from the stored volume
 * coordinate and the radii, the gap coordinate from the stored rupture distance — a
 * one-dimensional lookup in the gap, no logarithm, exponential or rupture interpolation
 * per step; the same numbers as table_force on the located pair, bit for bit. */
static cb_status table_bridge_force(const cb_law *law, const cb_pair *pair,
                                    const cb_bridge *bridge, double gap, double *force)
{
    if (!(bridge->law_constant > 0.0)) return cb_bridge_force_in_full(law, pair, bridge, gap, force);
    cb_table_position p;
    place(&p, ratio_coordinate(pair), bridge->law_constant);
    force_at(law, &p, pair->r_harmonic, bridge->rupture, gap, force, NULL);
    return CB_OK;
}

/* |dF/dx| of a cell's cubic as a quadratic in x, and its largest value over [xa, xb]:
 * at an end or at the vertex. */
typedef struct slope_quadratic {
    double c0, c1, c2;
} slope_quadratic;

static slope_quadratic slope_of(const double c[4])
{
    slope_quadratic q = {c[1], 2.0 * c[2], 3.0 * c[3]};
    return q;
}

static double slope_at(const slope_quadratic *q, double x)
{
    return q->c0 + x * (q->c1 + x * q->c2);
}

static double slope_max(const slope_quadratic *q, double xa, double xb)
{
    double m = fmax(fabs(slope_at(q, xa)), fabs(slope_at(q, xb)));
    if (q->c2 != 0.0) {
        double vertex = -q->c1 / (2.0 * q->c2);
        if (vertex > xa && vertex < xb) m = fmax(m, fabs(slope_at(q, vertex)));
    }
    return m;
}

/* w (1 - w^2), to which dgap/dw is proportional: concave on [0, 1], so its least value
 * over an interval is at an end; dy/dw is convex, so its largest is at an end. */
static double gap_rate(double w) { return w * (1.0 - w * w); }

/* The stiffness at w in units of scale / (4 rupture): |dF/dx| CELLS dy/dw / (w (1 - w^2)),
 * without the factor CELLS (table_force's expression). */
static double stiffness_at(const slope_quadratic *q, int k, double w)
{
    double x = cell_coordinate(w) * (TABLE_GAPS - 1) - k;
    return fabs(slope_at(q, x)) * cell_coordinate_slope(w) / gap_rate(w);
}

/* An upper bound of |dF/dgap| over 0 <= gap <= rupture, derived from the interpolant
 * rather than sampled (the steepest point lies in the half cell before the fold, where
 * samples of the gap rarely fall). table_force's stiffness at any gap is
 *     |H'(x)| CELLS dy/dw scale / (4 rupture u (1 - u^2)),
 * u = w clamped into [slope_w_min, slope_w_max], H the cubic of u's cell in x (0 where the
 * force is clamped or held). On an interval of a cell in w, max|H'| (a quadratic in x,
 * which is monotone in w: ends or vertex) times the largest dy/dw over the least
 * u (1 - u^2) (both at an end) bounds it; intervals are halved until that bound is within
 * 1e-3 of the largest stiffness found at their points, or is below it. The result is
 * multiplied by 1 + 1e-9 for the rounding of table_force's own evaluation. */
static double table_stiffness_bound(const cb_law *law, const cb_pair *pair)
{
    enum { CELLS = TABLE_GAPS - 1, STACK = 64, DEPTH = 40 };
    const double tolerance = 1e-3;
    slope_quadratic slopes[CELLS];
    double edge[CELLS + 1]; /* the cells' ends in w */
    for (int k = 0; k <= CELLS; ++k) edge[k] = gap_coordinate_at(gap_node(k));
    double lower = 0.0; /* the largest stiffness found at a point */
    for (int k = 0; k < CELLS; ++k) {
        double c[4];
        cubic_at(table_of(law), &pair->table, k, c);
        slopes[k] = slope_of(c);
        for (int i = 0; i <= 4; ++i) {
            double u = edge[k] + 0.25 * i * (edge[k + 1] - edge[k]);
            u = fmin(fmax(u, slope_w_min), slope_w_max);
            lower = fmax(lower, stiffness_at(&slopes[k], k, u));
        }
    }
    double upper = lower;
    for (int k = 0; k < CELLS; ++k) {
        struct { double a, b; int depth; } stack[STACK];
        int n = 0;
        stack[n].a = fmax(edge[k], slope_w_min);
        stack[n].b = fmin(edge[k + 1], slope_w_max);
        stack[n++].depth = 0;
        while (n > 0) {
            --n;
            double a = stack[n].a, b = stack[n].b;
            int depth = stack[n].depth;
            if (!(a < b)) continue; /* an end cell's part beyond the clamp */
            double xa = cell_coordinate(a) * CELLS - k, xb = cell_coordinate(b) * CELLS - k;
            double mid = 0.5 * (a + b);
            double bound = slope_max(&slopes[k], xa, xb) *
                           fmax(cell_coordinate_slope(a), cell_coordinate_slope(b)) /
                           fmin(gap_rate(a), gap_rate(b));
            lower = fmax(lower, stiffness_at(&slopes[k], k, mid));
            if (bound <= lower * (1.0 + tolerance) || depth == DEPTH || n + 2 > STACK) {
                upper = fmax(upper, bound);
                continue;
            }
            stack[n].a = a;
            stack[n].b = mid;
            stack[n++].depth = depth + 1;
            stack[n].a = mid;
            stack[n].b = b;
            stack[n++].depth = depth + 1;
        }
    }
    double rupture = pair->table.scaled_rupture * pair->r_harmonic;
    double scale = 2.0 * CB_PI * law->surface_tension * pair->r_harmonic;
    return upper * CELLS * scale / (4.0 * rupture) * (1.0 + 1e-9);
}

/* The table's range, where tests/test_table.c holds it to the exact solver (the file's
 * head states the figures). Between the two rupture distances one bridge has ruptured and
 * the other not. Above 80 degrees the force near contact is a small difference of the
 * pressure and tension terms, repulsive at the larger volumes (clamped at 0 here). */
static cb_validity table_validity(const cb_law *law)
{
    (void)law;
    cb_validity v = {table_volume_min, table_volume_max, 80.0 * CB_PI / 180.0,
                     HUGE_VAL, CB_RADIUS_HARMONIC,
                     "the table's range, checked against the exact solver (law_table.c)"};
    return v;
}

const cb_law_ops cb_table_ops = {
    .name = "table",
    .force = table_force,
    .validity = table_validity,
    .default_rupture = CB_RUPTURE_EXACT, /* the fold of the exact branch, tabulated */
    .tabulated = 1,
    .plane = 1, /* the plane is the table's s = 0 */
    .own_rupture = table_rupture,
    .own_rupture_volume = table_rupture_volume,
    .prepare = table_prepare,
    .release = table_release,
    .locate = table_locate,
    .stiffness_bound = table_stiffness_bound,
    .bridge_constant = table_bridge_constant,
    .bridge_force = table_bridge_force,
};
