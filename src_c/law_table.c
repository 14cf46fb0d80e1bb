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
 * a quarter decade beyond the domain [1e-5, 1e-1] so that its edges get centred
 * stencils), and the gap through
 *     w = sqrt(1 - sqrt(gap / rupture))  in [0, 1]  (w = 1 at contact, 0 at the fold),
 * i.e. gap = rupture (1 - w^2)^2. Why w and not gap/rupture: the force has two
 * narrow features, a steep fall over gaps of order sqrt(V/R) near contact (Willett's
 * S+ scale, a small fraction of the rupture distance for small V) and a square-root
 * singularity at the fold, F ~ F* + c sqrt(rupture - gap). In w both are smooth and
 * spread out (gap ~ (1 - w)^2 near contact, sqrt(rupture - gap) ~ w near the fold).
 * Stored: rupture/(R_h v^(1/3)) at each (s, v), the rupture distance without its V^(1/3)
 * growth (Lian's scaling), which a cubic in ln v follows only to 1e-4; and F/(2 pi gamma
 * R_h) with its w-slopes at each (s, v, w). Interpolation: cubic Lagrange in q and ln v
 * (4-point stencils), monotone cubic Hermite in w (Fritsch-Carlson slopes), so that along
 * the gap the force never rises where the exact one does not.
 * The fold needs the rupture distance to ~1e-5: within 1e-4 of it the exact force rises as
 * a square root of the distance to its fold, so an error e of the table's rupture distance
 * is a force error of up to ~1.6 sqrt(e) there (1.2 % at the 1.1e-4 of 12 steps in q and
 * an unscaled rupture distance).
 * Outside the table (validity extend): s and v are clamped for the scaled force, and the
 * rupture distance is extended with the V^(1/3) scaling of Lian's rule from the edge. */
#include "laws.h"

#include <math.h>
#include <stdlib.h>


/* The grid. Node positions are given together with the reciprocal steps the lookup
 * multiplies by, since a division on every call would cost more than the interpolation:
 *   size ratio: q = sqrt(1 - s) at q_i = i / 24 (q = 1: the plane);
 *   volume:     ln v at ln v_j = ln(10^-5.25) + j ln(10)/4 (four per decade, 10^-0.75 last). */
enum { TABLE_RATIOS = 25, TABLE_VOLUMES = 19, TABLE_GAPS = 33 };
static const double table_ratio_nodes_per_q = 24.0;
static const double table_volume_min = 1e-5;    /* the domain in V / R_h^3 */
static const double table_volume_max = 1e-1;
static const double table_log_volume_min = -11.512925464970229; /* ln 1e-5 */
static const double table_log_volume_max = -2.3025850929940455; /* ln 1e-1 */
static const double table_log_volume_first = -12.088571738218741; /* -5.25 ln 10 */
static const double table_log_volume_step = 0.5756462732485115;   /* ln(10) / 4 */
static const double table_volume_nodes_per_log = 1.737177927613007; /* 4 / ln 10 */

/* Integration steps of the exact solver for the nodes: half its default, within 1e-7 of
 * it in the rupture distance and 3e-8 in the force (against 1024 steps) at half the cost,
 * which pays for the 24 steps in q. */
static const int table_solver_steps = CB_EXACT_DEFAULT_STEPS / 2;

/* A force value and its w-slope as one two-lane vector (GCC and Clang vector extension;
 * SSE2 on x86-64, NEON on arm64, scalar code elsewhere): the lookup sums both with the
 * same weights, one vector multiply-add per node instead of two scalar ones. */
typedef double force_slope __attribute__((vector_size(2 * sizeof(double))));

struct cb_table {
    double contact_angle;
    double rupture[TABLE_RATIOS][TABLE_VOLUMES]; /* rupture / (R_h v^(1/3)) */
    /* F / (2 pi gamma R_h) and its w-slope, for each gap node the (s, v) plane */
    force_slope force[TABLE_GAPS][TABLE_RATIOS][TABLE_VOLUMES];
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

static double gap_node(int k) { return (double)k / (TABLE_GAPS - 1); } /* w */

/* gap / rupture at a gap coordinate w, and back. */
static double gap_fraction(double w)
{
    double c = 1.0 - w * w;
    return c * c;
}

static double gap_coordinate(double fraction) { return sqrt(1.0 - sqrt(fraction)); }

/* Fritsch-Carlson slopes of a sequence increasing or decreasing in w: a cubic Hermite
 * with these slopes is monotone wherever the data are. At contact (w = 1) the slope is
 * the exact one, 0, since gap ~ (1 - w)^2 there. At the fold (w = 0) it is the slope of
 * the parabola through the first three nodes, kept to the sign of the first difference:
 * where the symmetric bridge of nearly equal spheres ruptures by instability (above about
 * 30 degrees) the exact force has no square root there, F ~ F* + b w^2, and the first
 * difference as the slope put the force of the last cell up to 0.6 % off. */
static void monotone_slopes(const double *y, double h, double *m)
{
    double d[TABLE_GAPS - 1];
    for (int k = 0; k < TABLE_GAPS - 1; ++k) d[k] = (y[k + 1] - y[k]) / h;
    m[0] = 0.5 * (3.0 * d[0] - d[1]);
    if (m[0] * d[0] <= 0.0) m[0] = 0.0;
    m[TABLE_GAPS - 1] = 0.0;
    for (int k = 1; k < TABLE_GAPS - 1; ++k) {
        if (d[k - 1] * d[k] <= 0.0) m[k] = 0.0;
        else m[k] = 2.0 / (1.0 / d[k - 1] + 1.0 / d[k]); /* harmonic mean: monotone */
    }
    for (int k = 0; k < TABLE_GAPS - 1; ++k) {
        if (d[k] == 0.0) {
            m[k] = m[k + 1] = 0.0;
            continue;
        }
        double a = m[k] / d[k], b = m[k + 1] / d[k];
        double r = a * a + b * b;
        if (r > 9.0) {
            double t = 3.0 / sqrt(r);
            m[k] = t * a * d[k];
            m[k + 1] = t * b * d[k];
        }
    }
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
        /* Ascending gaps: w from 1 (contact) down to w_1; the fold (w = 0) is known. */
        for (int k = 0; k < TABLE_GAPS - 1; ++k)
            gaps[k] = rupture * gap_fraction(gap_node(TABLE_GAPS - 1 - k));
        gaps[0] = 0.0;
        status = cb_exact_curve(&problem, TABLE_GAPS - 1, gaps, bridges);
    }
    if (status != CB_OK)
        return cb_fail(msg, status,
                       "table law: exact solver failed at size ratio %g, V/R_h^3 = %g, "
                       "theta = %g degrees: %s",
                       r_large, v, table->contact_angle * 180.0 / CB_PI,
                       cb_status_message(status));
    table->rupture[i][j] = rupture / (rh * cbrt(v));
    double f[TABLE_GAPS], m[TABLE_GAPS];
    for (int k = 0; k < TABLE_GAPS - 1; ++k)
        f[TABLE_GAPS - 1 - k] = bridges[k].force / (2.0 * CB_PI * rh);
    f[0] = bridges[TABLE_GAPS - 1].force / (2.0 * CB_PI * rh);
    monotone_slopes(f, gap_node(1), m);
    for (int k = 0; k < TABLE_GAPS; ++k) {
        table->force[k][i][j][0] = f[k];
        table->force[k][i][j][1] = m[k];
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

/* rupture / R_h where the pair sits: the tabulated rupture / (R_h v^(1/3)) times v^(1/3)
 * (beyond the table's volumes, the edge value times v^(1/3): Lian's V^(1/3) scaling). */
static double scaled_rupture(const struct cb_table *t, const cb_table_position *p,
                             double cube_root_volume)
{
    double row_sum[4];
    for (int a = 0; a < 4; ++a) {
        const double *row = &t->rupture[p->ratio_first + a][p->volume_first];
        const double *wt = p->weight[a];
        row_sum[a] = (wt[0] * row[0] + wt[1] * row[1]) + (wt[2] * row[2] + wt[3] * row[3]);
    }
    return ((row_sum[0] + row_sum[1]) + (row_sum[2] + row_sum[3])) * cube_root_volume;
}

/* Where the pair sits in the table: the 4 x 4 stencil in (q, ln v), its weights as
 * products (so that each lookup of the force is one weighted sum over 16 nodes), and
 * its rupture distance. */
static void table_locate(const cb_law *law, cb_pair *pair)
{
    cb_table_position *p = &pair->table;
    /* V / R_h^3 with 1/R_h = (R1 + R2) / (2 R1 R2) from the radii: a division that runs
     * alongside R_h's own instead of after it (this law's cost is its chain of dependent
     * divisions, square roots and the logarithm); 1 / (2 R1) at a plane */
    double inverse_rh = pair->plane ? 0.5 / pair->r1
                                    : (pair->r1 + pair->r2) / (2.0 * pair->r1 * pair->r2);
    double v = pair->volume * (inverse_rh * inverse_rh * inverse_rh);
    double log_volume = log(v);
    double clamped = log_volume < table_log_volume_min   ? table_log_volume_min
                     : log_volume > table_log_volume_max ? table_log_volume_max
                                                         : log_volume;
    double x_ratio = sqrt(1.0 - pair->r_small / pair->r_large) * table_ratio_nodes_per_q;
    double x_volume = (clamped - table_log_volume_first) * table_volume_nodes_per_log;
    double ratio_weight[4], volume_weight[4];
    p->ratio_first = lagrange_stencil(x_ratio, TABLE_RATIOS, ratio_weight);
    p->volume_first = lagrange_stencil(x_volume, TABLE_VOLUMES, volume_weight);
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) p->weight[a][b] = ratio_weight[a] * volume_weight[b];
    p->scaled_rupture = scaled_rupture(table_of(law), p, exp(log_volume * (1.0 / 3.0)));
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

/* The Hermite cell of w, with the (q, ln v)-weighted values and w-slopes at its ends. */
typedef struct hermite_cell {
    double w0, h, f0, f1, m0, m1;
} hermite_cell;

static hermite_cell cell_at(const struct cb_table *t, const cb_table_position *p, double w)
{
    hermite_cell c = {0.0, gap_node(1), 0.0, 0.0, 0.0, 0.0};
    int k = (int)(w * (TABLE_GAPS - 1));
    if (k > TABLE_GAPS - 2) k = TABLE_GAPS - 2;
    c.w0 = k * c.h;
    /* [f, m] at gap nodes k and k+1, each the weighted sum over the 16 stencil nodes,
     * summed per ratio row first: short dependency chains */
    force_slope low[4], high[4];
    for (int a = 0; a < 4; ++a) {
        const force_slope *lo = t->force[k][p->ratio_first + a] + p->volume_first;
        const force_slope *hi = t->force[k + 1][p->ratio_first + a] + p->volume_first;
        const double *wt = p->weight[a];
        low[a] = (wt[0] * lo[0] + wt[1] * lo[1]) + (wt[2] * lo[2] + wt[3] * lo[3]);
        high[a] = (wt[0] * hi[0] + wt[1] * hi[1]) + (wt[2] * hi[2] + wt[3] * hi[3]);
    }
    force_slope at_low = (low[0] + low[1]) + (low[2] + low[3]);
    force_slope at_high = (high[0] + high[1]) + (high[2] + high[3]);
    c.f0 = at_low[0];
    c.m0 = at_low[1];
    c.f1 = at_high[0];
    c.m1 = at_high[1];
    return c;
}

static double hermite_value(const hermite_cell *c, double w)
{
    double x = (w - c->w0) * (TABLE_GAPS - 1), x2 = x * x, x3 = x2 * x;
    return (2 * x3 - 3 * x2 + 1) * c->f0 + (x3 - 2 * x2 + x) * c->h * c->m0 +
           (-2 * x3 + 3 * x2) * c->f1 + (x3 - x2) * c->h * c->m1;
}

static double hermite_slope(const hermite_cell *c, double w)
{
    double x = (w - c->w0) * (TABLE_GAPS - 1), x2 = x * x;
    return ((6 * x2 - 6 * x) * c->f0 + (3 * x2 - 4 * x + 1) * c->h * c->m0 +
            (-6 * x2 + 6 * x) * c->f1 + (3 * x2 - 2 * x) * c->h * c->m1) * (TABLE_GAPS - 1);
}

static cb_status table_force(const cb_law *law, const cb_pair *pair, double gap,
                             double *force, double *stiffness)
{
    const struct cb_table *t = table_of(law);
    double rupture = pair->table.scaled_rupture * pair->r_harmonic;
    double fraction = gap < rupture ? gap / rupture : 1.0;
    double w = gap_coordinate(fraction);
    hermite_cell c = cell_at(t, &pair->table, w);
    double scale = 2.0 * CB_PI * law->surface_tension * pair->r_harmonic;
    double value = hermite_value(&c, w);
    if (!(value > 0.0) || gap >= rupture) {
        /* clamped at 0 (a repulsive exact force near contact at large angles), or held at
         * its value at the fold beyond it (a rupture rule reaching further than the
         * exact one): the force does not change with the gap there */
        *force = value > 0.0 ? value * scale : 0.0;
        *stiffness = 0.0;
        return CB_OK;
    }
    *force = value * scale;
    /* dF/dgap = dF/dw / (dgap/dw), dgap/dw = -4 rupture w (1 - w^2). Both vanish at
     * contact (a finite limit) and dgap/dw vanishes at the fold (the exact force has an
     * infinite slope there). Within half a cell of either end the stiffness is taken at
     * that half-cell point, so that it stays finite and well conditioned; the point lies
     * in the same end cell, so the cell found for w serves. */
    double half = 0.5 * c.h;
    double w_slope = w < half ? half : w > 1.0 - half ? 1.0 - half : w;
    *stiffness = hermite_slope(&c, w_slope) * scale /
                 (-4.0 * rupture * w_slope * (1.0 - w_slope * w_slope));
    return CB_OK;
}

/* |dF/dw| / (scale / h) on a Hermite cell, as a quadratic in x = (w - w0) / h: the
 * derivative of hermite_value's cubic, collected by powers of x. */
typedef struct slope_quadratic {
    double c0, c1, c2;
} slope_quadratic;

static slope_quadratic slope_of(const hermite_cell *c)
{
    double d = c->f1 - c->f0, hm0 = c->h * c->m0, hm1 = c->h * c->m1;
    slope_quadratic q = {hm0, 6.0 * d - 4.0 * hm0 - 2.0 * hm1, -6.0 * d + 3.0 * (hm0 + hm1)};
    return q;
}

static double slope_at(const slope_quadratic *q, double x)
{
    return q->c0 + x * (q->c1 + x * q->c2);
}

/* The largest |slope| over [xa, xb]: at an end or at the vertex. */
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
 * over an interval is at an end. */
static double gap_rate(double w) { return w * (1.0 - w * w); }

/* An upper bound of |dF/dgap| over 0 <= gap <= rupture, derived from the interpolant
 * rather than sampled (the steepest point lies in the half cell before the fold, where
 * samples of the gap rarely fall). table_force's stiffness at any gap is
 *     |H'(u)| scale / (4 rupture u (1 - u^2)),  u = w clamped into [h/2, 1 - h/2],
 * H the Hermite cubic of u's cell (0 where the force is clamped or held). On an interval
 * of a cell, max|H'| (a quadratic: ends or vertex) over the least u (1 - u^2) (an end)
 * bounds it; intervals are halved until that bound is within 1e-3 of the largest
 * stiffness found at their points, or is below it. The result is multiplied by
 * 1 + 1e-9 for the rounding of table_force's own evaluation. */
static double table_stiffness_bound(const cb_law *law, const cb_pair *pair)
{
    enum { CELLS = TABLE_GAPS - 1, STACK = 64, DEPTH = 40 };
    const double h = 1.0 / CELLS, half = 0.5 * h, tolerance = 1e-3;
    slope_quadratic slopes[CELLS];
    double lower = 0.0; /* the largest |H'| / rate found at a point */
    for (int k = 0; k < CELLS; ++k) {
        hermite_cell c = cell_at(table_of(law), &pair->table, k * h);
        slopes[k] = slope_of(&c);
        for (int i = 0; i <= 4; ++i) {
            double u = fmin(fmax((k + 0.25 * i) * h, half), 1.0 - half);
            lower = fmax(lower, fabs(slope_at(&slopes[k], (u - k * h) * CELLS)) / gap_rate(u));
        }
    }
    double upper = lower;
    for (int k = 0; k < CELLS; ++k) {
        struct { double a, b; int depth; } stack[STACK];
        int n = 0;
        stack[n].a = fmax(k * h, half);
        stack[n].b = fmin((k + 1) * h, 1.0 - half);
        stack[n++].depth = 0;
        while (n > 0) {
            --n;
            double a = stack[n].a, b = stack[n].b;
            int depth = stack[n].depth;
            double xa = (a - k * h) * CELLS, xb = (b - k * h) * CELLS, mid = 0.5 * (a + b);
            double bound = slope_max(&slopes[k], xa, xb) / fmin(gap_rate(a), gap_rate(b));
            lower = fmax(lower, fabs(slope_at(&slopes[k], 0.5 * (xa + xb))) / gap_rate(mid));
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

/* The table's range, where tests/test_table.c holds it to the exact solver: the rupture
 * distance within 2e-4 (relative; 1e-4 at most found), the force within 0.5 % at every gap
 * up to (1 - 1e-4) of the smaller of the two rupture distances, and within 1 % from there
 * to it (the exact force's square root at its fold magnifies the rupture distance's error).
 * Between the two rupture distances one bridge has ruptured and the other not.
 * Above about 70 degrees the exact force near contact is small and no longer falls
 * monotonically with the gap, which the monotone interpolant does not follow. */
static cb_validity table_validity(const cb_law *law)
{
    (void)law;
    cb_validity v = {table_volume_min, table_volume_max, 70.0 * CB_PI / 180.0,
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
    .bridge_constant = cb_no_bridge_constant,
    .bridge_force = cb_bridge_force_in_full,
};
