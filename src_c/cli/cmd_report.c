/* cmd_report.c — `capbridge report`: every law's error against the exact Laplace-Young
 * solution (reference_data/cases.csv and grid.csv) and its cost per call, measured in
 * the same run, and at a plane (a wall: reference_data/plane.csv, where a closed-form law is
 * its Derjaguin-equivalent pair, capbridge.h). Prints a Markdown table; --csv writes the
 * numbers.
 * Force errors are taken at the 20 gaps 0, d/20, ... 19d/20 of each exact curve (d the
 * exact rupture distance) where the law still has a bridge; the rupture distance error
 * is |d_law - d| / d; "no bridge" counts the gaps where the law's bridge has already
 * broken although the exact one holds. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "capbridge.h"
#include "law_cost.h"
#include "reference.h"


#ifndef CAPBRIDGE_REFERENCE_DIR
#define CAPBRIDGE_REFERENCE_DIR "reference_data"
#endif

/* Max and RMS of relative errors. */
typedef struct error_sum {
    double max, sum_squares;
    long count;
    char where[64]; /* configuration and point of the largest error */
} error_sum;

static void add_error(error_sum *e, double relative, const char *name, int point)
{
    if (relative > e->max) {
        e->max = relative;
        snprintf(e->where, sizeof e->where, "%s@%d", name, point);
    }
    e->sum_squares += relative * relative;
    e->count++;
}

static double rms(const error_sum *e) { return e->count ? sqrt(e->sum_squares / e->count) : NAN; }

/* Errors of one law over one reference set: force and rupture distance, over all
 * configurations and inside the law's stated validity. */
typedef struct set_errors {
    error_sum force_all, force_valid, rupture_all, rupture_valid;
    long points, no_bridge; /* exact bridge exists but the law has none (gap > its rupture) */
} set_errors;

static int inside_validity(const cb_law *law, const cb_case *c)
{
    cb_validity v = cb_law_validity(law);
    double r = cb_radius_of(v.radius, c->r1, c->r2);
    double scaled = c->volume / (r * r * r);
    double ratio = c->r1 > c->r2 ? c->r1 / c->r2 : c->r2 / c->r1;
    return scaled >= v.volume_min && scaled <= v.volume_max &&
           c->contact_angle * CB_PI / 180.0 <= v.contact_angle_max + 1e-12 &&
           ratio <= v.size_ratio_max * (1 + 1e-12);
}

static int set_law(cb_law *law, const cb_case *c)
{
    cb_message msg;
    char value[64];
    snprintf(value, sizeof value, "%.17g", c->surface_tension);
    if (cb_law_configure(law, "gamma", value, &msg) != CB_OK) goto fail;
    snprintf(value, sizeof value, "%.17g", c->contact_angle);
    if (cb_law_configure(law, "theta", value, &msg) != CB_OK) goto fail;
    if (cb_law_prepare(law, &msg) != CB_OK) goto fail;
    return 1;
fail:
    fprintf(stderr, "capbridge report: %s: %s\n", cb_model_name(law->model), msg.text);
    return 0;
}

static int measure_set(cb_law *law, const cb_reference_curve_data *curves, long n,
                       set_errors *e)
{
    memset(e, 0, sizeof *e);
    for (long i = 0; i < n; ++i) {
        const cb_case *c = &curves[i].config;
        if (!set_law(law, c)) return 0;
        int valid = inside_validity(law, c);
        double rupture = 0.0;
        cb_status rupture_status = cb_rupture_distance(law, c->r1, c->r2, c->volume, &rupture);
        if (rupture_status != CB_OK) {
            fprintf(stderr, "capbridge report: %s: the rupture distance of %s: %s\n",
                    cb_model_name(law->model), c->name, cb_status_message(rupture_status));
            return 0;
        }
        double rupture_error = fabs(rupture - curves[i].rupture) / curves[i].rupture;
        add_error(&e->rupture_all, rupture_error, c->name, CB_CURVE_POINTS - 1);
        if (valid) add_error(&e->rupture_valid, rupture_error, c->name, CB_CURVE_POINTS - 1);
        /* The last point is the fold itself, where dF/dgap is infinite: a force error
         * there only restates the rupture-distance error, reported on its own. */
        for (int p = 0; p < CB_CURVE_POINTS - 1; ++p) {
            double gap = curves[i].gap[p], exact = curves[i].force[p];
            e->points++;
            if (gap > rupture) {
                e->no_bridge++;
                continue;
            }
            double force = 0.0;
            cb_status status = cb_force(law, c->r1, c->r2, c->volume, gap, &force, NULL);
            if (status == CB_ERR_NO_BRIDGE) {
                e->no_bridge++;
                continue;
            }
            if (status != CB_OK) {
                fprintf(stderr, "capbridge report: %s at %s gap %g: %s\n",
                        cb_model_name(law->model), c->name, gap, cb_status_message(status));
                return 0;
            }
            double relative = fabs(force - exact) / exact;
            add_error(&e->force_all, relative, c->name, p);
            if (valid) add_error(&e->force_valid, relative, c->name, p);
        }
    }
    return 1;
}

typedef struct law_report {
    cb_model model;
    set_errors cases, grid, plane;
    double ns_per_call;
} law_report;

static void print_csv(FILE *out, const law_report *r, int n, double cheapest)
{
    fprintf(out, "law,force_max_cases,force_rms_cases,force_max_cases_valid,"
                 "force_rms_cases_valid,rupture_max_cases,force_max_grid,force_rms_grid,"
                 "force_max_grid_valid,force_rms_grid_valid,grid_points_valid,"
                 "rupture_max_grid,rupture_max_grid_valid,no_bridge_fraction_grid,"
                 "worst_force_grid,force_max_plane,force_rms_plane,rupture_max_plane,"
                 "no_bridge_fraction_plane,worst_force_plane,ns_per_call,cost_ratio\n");
    for (int i = 0; i < n; ++i) {
        const set_errors *c = &r[i].cases, *g = &r[i].grid, *p = &r[i].plane;
        fprintf(out, "%s,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%ld,%.6g,%.6g,%.6g,%s,"
                     "%.6g,%.6g,%.6g,%.6g,%s,%.4g,%.4g\n",
                cb_model_name(r[i].model), c->force_all.max, rms(&c->force_all),
                c->force_valid.max, rms(&c->force_valid), c->rupture_all.max,
                g->force_all.max, rms(&g->force_all), g->force_valid.max, rms(&g->force_valid),
                g->force_valid.count, g->rupture_all.max, g->rupture_valid.max,
                (double)g->no_bridge / (double)g->points, g->force_all.where,
                p->force_all.max, rms(&p->force_all), p->rupture_all.max,
                (double)p->no_bridge / (double)p->points, p->force_all.where, r[i].ns_per_call,
                r[i].ns_per_call / cheapest);
    }
}

static void percent(char *text, size_t size, double value)
{
    if (isnan(value)) snprintf(text, size, "–");
    else snprintf(text, size, "%.3g %%", 100.0 * value);
}

static void print_markdown(const law_report *r, int n, double cheapest)
{
    printf("| law | force error, 13 cases: max / RMS | grid, all: max / RMS | "
           "grid, inside validity: max / RMS | rupture distance error: cases / grid | "
           "sphere–plane: force max / RMS, rupture max | ns per call | cost vs cheapest |\n");
    printf("|---|---|---|---|---|---|---|---|\n");
    for (int i = 0; i < n; ++i) {
        const set_errors *c = &r[i].cases, *g = &r[i].grid, *p = &r[i].plane;
        char a[11][32];
        percent(a[0], 32, c->force_all.max);
        percent(a[1], 32, rms(&c->force_all));
        percent(a[2], 32, g->force_all.max);
        percent(a[3], 32, rms(&g->force_all));
        percent(a[4], 32, g->force_valid.max);
        percent(a[5], 32, rms(&g->force_valid));
        percent(a[6], 32, c->rupture_all.max);
        percent(a[7], 32, g->rupture_all.max);
        percent(a[8], 32, p->force_all.max);
        percent(a[9], 32, rms(&p->force_all));
        percent(a[10], 32, p->rupture_all.max);
        printf("| %s | %s / %s | %s / %s | %s / %s (%ld points) | %s / %s | %s / %s, %s | "
               "%.1f | %.2f× |\n",
               cb_model_name(r[i].model), a[0], a[1], a[2], a[3], a[4], a[5],
               g->force_valid.count, a[6], a[7], a[8], a[9], a[10], r[i].ns_per_call,
               r[i].ns_per_call / cheapest);
    }
}

/* The cost of every law with its defaults (water, theta = 0), all in this run, and of
 * richefeu with the bridge's viscous force (water's 1e-3 Pa s, min_gap 1e-8 m) in the same
 * passes: *viscous_ns. */
static int measure_costs(law_report *reports, double *viscous_ns)
{
    enum { VISCOUS = CB_MODEL_COUNT };
    cb_law laws[CB_MODEL_COUNT + 1];
    double ns[CB_MODEL_COUNT + 1];
    int prepared = 0, ok = 1;
    for (int m = 0; m <= VISCOUS && ok; ++m, ++prepared) {
        cb_message msg;
        ok = cb_law_init(&laws[m], m == VISCOUS ? CB_MODEL_RICHEFEU : (cb_model)m, 0.0728,
                         0.0) == CB_OK;
        if (ok && m == VISCOUS)
            ok = cb_law_configure(&laws[m], "viscosity", "1e-3", &msg) == CB_OK &&
                 cb_law_configure(&laws[m], "min_gap", "1e-8", &msg) == CB_OK;
        ok = ok && cb_law_prepare(&laws[m], &msg) == CB_OK;
    }
    ok = ok && cb_law_costs_ns(laws, CB_MODEL_COUNT + 1, ns, NULL, NULL) == 0;
    for (int m = 0; m < prepared; ++m) cb_law_release(&laws[m]);
    for (int m = 0; m < CB_MODEL_COUNT && ok; ++m) reports[m].ns_per_call = ns[m];
    *viscous_ns = ns[VISCOUS];
    return ok;
}

int cmd_report(int argc, char **argv)
{
    const char *reference_dir = CAPBRIDGE_REFERENCE_DIR, *csv_path = NULL;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--help") == 0) {
            printf("usage: capbridge report [--reference DIR] [--csv FILE]\n"
                   "Force and rupture-distance errors of every law against the exact\n"
                   "Laplace-Young curves in DIR/cases.csv, DIR/grid.csv and DIR/plane.csv\n"
                   "(a sphere and a plane), and each law's cost per call measured in this run.\n");
            return 0;
        } else if (strcmp(argv[i], "--reference") == 0 && i + 1 < argc) {
            reference_dir = argv[++i];
        } else if (strcmp(argv[i], "--csv") == 0 && i + 1 < argc) {
            csv_path = argv[++i];
        } else {
            cli_echo shown;
            return cli_usage_error("report", "unknown option or missing value %s: allowed "
                                   "--reference DIR, --csv FILE",
                                   cli_quote(&shown, argv[i], strlen(argv[i])));
        }
    }
    char path[4096];
    if (strlen(reference_dir) + sizeof "/plane.csv" > sizeof path) {
        cli_echo shown;
        return cli_usage_error("report", "--reference %s is too long: allowed up to %zu bytes",
                               cli_quote(&shown, reference_dir, strlen(reference_dir)),
                               sizeof path - sizeof "/cases.csv");
    }
    cb_reference_curve_data *cases = NULL, *grid = NULL, *plane = NULL;
    snprintf(path, sizeof path, "%s/cases.csv", reference_dir);
    long case_count = cb_reference_read(path, &cases);
    snprintf(path, sizeof path, "%s/grid.csv", reference_dir);
    long grid_count = case_count < 0 ? -1 : cb_reference_read(path, &grid);
    snprintf(path, sizeof path, "%s/plane.csv", reference_dir);
    long plane_count = grid_count < 0 ? -1 : cb_reference_read(path, &plane);
    if (case_count < 0 || grid_count < 0 || plane_count < 0) {
        free(cases);
        free(grid);
        return 1;
    }

    law_report reports[CB_MODEL_COUNT];
    int ok = 1;
    double cheapest = HUGE_VAL;
    for (int m = 0; m < CB_MODEL_COUNT && ok; ++m) {
        law_report *r = &reports[m];
        r->model = (cb_model)m;
        cb_law law;
        ok = cb_law_init(&law, r->model, 0.0728, 0.0) == CB_OK &&
             measure_set(&law, cases, case_count, &r->cases) &&
             measure_set(&law, grid, grid_count, &r->grid) &&
             measure_set(&law, plane, plane_count, &r->plane);
        cb_law_release(&law);
    }
    free(cases);
    free(grid);
    free(plane);
    double viscous_ns = 0.0;
    if (!ok || !measure_costs(reports, &viscous_ns)) return 1;
    for (int m = 0; m < CB_MODEL_COUNT; ++m)
        if (!cb_model_tabulated((cb_model)m) && reports[m].ns_per_call < cheapest)
            cheapest = reports[m].ns_per_call;

    printf("Errors against the exact Laplace-Young solution (relative, in %%), %ld cases, "
           "%ld grid configurations and %ld sphere-plane ones x %d gaps below the fold; cost "
           "per cb_force call measured in this run, relative to the cheapest closed-form "
           "law.\n\n",
           case_count, grid_count, plane_count, CB_CURVE_POINTS - 1);
    print_markdown(reports, CB_MODEL_COUNT, cheapest);
    double alone = reports[CB_MODEL_RICHEFEU].ns_per_call;
    printf("\nThe bridge's viscous force (keyword viscosity, cb_viscous_damping beside each "
           "cb_force call): richefeu with it %.1f ns per call against %.1f ns without, "
           "%.2f× (the viscous term %.1f ns).\n",
           viscous_ns, alone, viscous_ns / alone, viscous_ns - alone);
    if (csv_path) {
        FILE *out = fopen(csv_path, "w");
        if (!out) {
            cli_echo shown;
            return cli_runtime_error("report", "cannot write %s",
                                     cli_quote(&shown, csv_path, strlen(csv_path)));
        }
        print_csv(out, reports, CB_MODEL_COUNT, cheapest);
        fclose(out);
    }
    return 0;
}
