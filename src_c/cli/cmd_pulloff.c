/* cmd_pulloff.c — `capbridge pulloff`: two spheres pulled apart (Gladkyy & Schwarze 2014, §3).
 *
 * Sphere 1 (free) starts at x = 0, sphere 2 at x = r1 + r2 (gap 0), both at rest; sphere
 * 2 is then driven at the constant velocity +v along x. A bridge of the given volume forms
 * at that contact (cb_bridge_update at step 0) and ruptures when the gap exceeds the law's
 * rupture distance (cb_bridge_update: the transitions are the core's). The available
 * volume offered to cb_bridge_update is the given volume at every step, as in an engine's
 * fixed-volume mode: if the spheres touch again after a rupture, a new bridge forms.
 *
 * Forces on sphere 1 along +x (towards sphere 2):  f1 = capillary - contact
 *   capillary = cb_force(law, r1, r2, bridge volume, gap) while the bridge exists, else 0
 *   contact   = cb_contact_normal_force (the engines' contact law, dashpot approach):
 *               k_n (-gap) + damping    for gap < 0 (Richefeu 2007 eq. 2), else 0
 *   damping   = 2 alpha_n sqrt(m k_n) (-gap_rate)   for gap < 0 and gap_rate < 0 only
 *               (eq. 3: in contact and approaching), gap_rate = v - v1 (half-step v1),
 *               m = m1 m2 / (m1 + m2), m_i = 4 pi / 3 r_i^3 density (LAMMPS's rmass)
 * contact is the repulsion (>= 0 pushes the spheres apart).
 *
 * The exact step order — LAMMPS fix nve on sphere 1, fix move linear on sphere 2; the
 * LAMMPS and LIGGGHTS bindings are held to this curve:
 *   step 0 (LAMMPS setup):  gap = (x2 - x1) - (r1 + r2) = 0; cb_bridge_update (forms);
 *                           f1 from the forces above with v1 = 0; print row 0.
 *   step n = 1, 2, ...:
 *     1. v1 += (0.5 dt / m1) f1                 fix nve initial_integrate (half kick)
 *     2. x1 += dt v1                            fix nve initial_integrate (drift)
 *     3. x2  = (r1 + r2) + v (n dt)             fix move linear: x0 + v (ntimestep dt)
 *     4. gap = (x2 - x1) - (r1 + r2)            pair: r = |x2 - x1|, gap = r - radsum
 *     5. cb_bridge_update(law, r1, r2, gap, volume, &bridge, ...)
 *     6. f1 = capillary(gap, bridge) - contact(gap, v - v1)   with the half-step v1
 *     7. v1 += (0.5 dt / m1) f1                 fix nve final_integrate (half kick)
 *     8. print row n: step,time,x1,v1,x2,gap,capillary_force,contact_force,bridge
 *        with time = n dt and the forces of 6.
 * The run stops --steps-after-rupture steps after the first rupture, or fails (exit 1)
 * if the bridge has not ruptured after --max-steps steps. */
#include "args.h"
#include "commands.h"

#include <math.h>
#include <stdio.h>

/* The most steps of a run: --max-steps and the other step counts, and the default
 * --max-steps (10 x the pull steps + 1000 + the steps after rupture) when it is not given. */
#define MAX_STEPS_LIMIT 1000000000L
#define MAX_STEPS_TEXT "1e9"

static const char usage[] =
    "usage: capbridge pulloff LAW [keyword value]... --r1 M --r2 M --volume M3\n"
    "           [--density KG/M3] [--kn N/M] [--damping ALPHA] [--velocity M/S] [--dt S]\n"
    "           [--steps-after-rupture N] [--max-steps N] [--every N]\n"
    "\n"
    "Two spheres on the x axis touch at t = 0 (gap 0) holding a bridge of the given volume;\n"
    "sphere 1 is free, sphere 2 moves at constant velocity +v along x until the bridge\n"
    "breaks. Velocity Verlet exactly as LAMMPS's fix nve (the step order is documented\n"
    "at the top of src_c/cli/cmd_pulloff.c). Contact: linear spring k_n overlap\n"
    "(Richefeu 2007 eq. 2) and damping 2 alpha sqrt(m k_n) |d gap/dt| in contact while\n"
    "approaching (eq. 3), m the reduced mass.\n"
    "  --density KG/M3         particle density (default 2500)\n"
    "  --kn N/M                normal stiffness (default 1e3)\n"
    "  --damping ALPHA         damping rate alpha_n in [0, 1] (default 0)\n"
    "  --velocity M/S          velocity of sphere 2, > 0 (default 1e-4)\n"
    "  --dt S                  time step (default min(0.02 pi sqrt(m/k_n),\n"
    "                          rupture_distance / (2000 v)))\n"
    "  --steps-after-rupture N steps run after the rupture (default 10)\n"
    "  --max-steps N           fail if the bridge has not broken by then (default\n"
    "                          10 x rupture_distance / (v dt) + 1000 + the steps after,\n"
    "                          which must not exceed " MAX_STEPS_TEXT ")\n"
    "  --every N               print every N-th step (default 1); step 0, bridge\n"
    "                          formation and rupture steps and the last step always\n"
    "Prints '#' comment lines (the command, masses, rupture distance, dt), then CSV:\n"
    "  step,time,x1,v1,x2,gap,capillary_force,contact_force,bridge\n"
    "capillary_force >= 0 is the attraction, contact_force >= 0 the repulsion (spring and\n"
    "damping); the net force on sphere 1 along +x is capillary_force - contact_force.\n"
    "bridge is 1 while the bridge exists, 0 after it ruptured.\n";

enum {
    R1, R2, VOLUME, DENSITY, KN, DAMPING, VELOCITY, DT, AFTER, MAX_STEPS, EVERY, N_OPTIONS
};

typedef struct pulloff {
    const cb_law *law;
    double r1, r2, volume, radsum;
    cb_contact_law contact; /* Richefeu eqs. 2-3, the core's (as the engines') */
    double m1, m2, mass;    /* the spheres' masses and the effective mass m1 m2 / (m1 + m2) */
    double sqrt_mass;       /* sqrt of the effective mass */
    double velocity;        /* of sphere 2 */
    double rupture;         /* the rupture distance of the bridge */
    double dt;
    long max_steps, after, every;
} pulloff;

/* The state after a force evaluation. */
typedef struct forces {
    double gap, capillary, contact, f1;
    cb_transition transition;
} forces;

/* Steps 4-6 of the step order (see the top of the file). */
static cb_status compute_forces(const pulloff *p, double x1, double v1, double x2,
                                cb_bridge *bridge, forces *out)
{
    double released = 0.0;
    out->gap = (x2 - x1) - p->radsum;
    cb_status status = cb_bridge_update(p->law, p->r1, p->r2, out->gap, p->volume, bridge,
                                        &out->transition, &released);
    if (status != CB_OK) return status;
    out->capillary = 0.0;
    if (bridge->active != 0.0) {
        status = cb_force(p->law, p->r1, p->r2, bridge->volume, out->gap, &out->capillary,
                          NULL);
        if (status != CB_OK) return status;
    }
    out->contact = cb_contact_normal_force(&p->contact, out->gap, p->velocity - v1, p->sqrt_mass);
    out->f1 = out->capillary - out->contact;
    return CB_OK;
}

static void print_row(long step, double time, double x1, double v1, double x2,
                      const cb_bridge *bridge, const forces *f)
{
    double row[8] = {time, x1, v1, x2, f->gap, f->capillary, f->contact,
                     bridge->active != 0.0 ? 1.0 : 0.0};
    printf("%ld,", step);
    for (int k = 0; k < 7; ++k) {
        cli_print_number(stdout, row[k]);
        putchar(',');
    }
    printf("%d\n", (int)row[7]);
}

/* The run's constants from the options: masses, contact law, rupture distance, time step
 * (with a warning when it is too large for the stiffer of k_n and the capillary stiffness)
 * and the step counts.  Returns 0, or the exit code of an error it has reported. */
static int pulloff_setup(const char *name, const cli_option *options, const cb_law *law,
                         pulloff *p)
{
    p->law = law;
    p->r1 = options[R1].number;
    p->r2 = options[R2].number;
    p->volume = options[VOLUME].number;
    p->radsum = p->r1 + p->r2;
    p->velocity = options[VELOCITY].number;
    const double density = options[DENSITY].number;
    p->m1 = 4.0 * CB_PI / 3.0 * p->r1 * p->r1 * p->r1 * density;
    p->m2 = 4.0 * CB_PI / 3.0 * p->r2 * p->r2 * p->r2 * density;
    p->mass = p->m1 * p->m2 / (p->m1 + p->m2);
    p->sqrt_mass = sqrt(p->mass);
    const double kn = options[KN].number;
    cb_message msg;
    if (cb_contact_law_init(&p->contact, kn, 0.0, options[DAMPING].number, 0.0,
                            CB_DASHPOT_APPROACH, &msg) != CB_OK)
        return cli_runtime_error(name, "%s", msg.text);

    double capillary_stiffness = 0.0;
    cb_status status = cb_rupture_distance(law, p->r1, p->r2, p->volume, &p->rupture);
    if (status == CB_OK)
        status = cb_capillary_stiffness_bound(law, p->r1, p->r2, p->volume,
                                              &capillary_stiffness);
    if (status != CB_OK) return cli_status_error(name, "rupture distance", status);
    const double m = p->mass;
    double dt_elastic = 0.02 * CB_PI * sqrt(m / kn);
    double dt_pull = p->rupture / (p->velocity * 2000.0);
    double dt = options[DT].given ? options[DT].number : fmin(dt_elastic, dt_pull);
    double stiffest = fmax(kn, capillary_stiffness);
    if (dt > 0.1 * CB_PI * sqrt(m / stiffest))
        fprintf(stderr,
                "capbridge pulloff: warning: dt = %g s exceeds 10 %% of pi sqrt(m / k) = %g s "
                "(k = %g N/m, the larger of k_n and the capillary stiffness)\n",
                dt, CB_PI * sqrt(m / stiffest), stiffest);
    double pull_steps = ceil(p->rupture / (p->velocity * dt));
    double max_default = 10.0 * pull_steps + 1000.0 + (double)options[AFTER].integer;
    if (!options[MAX_STEPS].given && !(max_default <= (double)MAX_STEPS_LIMIT))
        return cli_usage_error(name, "dt = %g s: the pull reaches the rupture distance (%g m) "
                               "after %.10g steps; the default --max-steps, 10 x %.10g + 1000 + "
                               "%ld = %.10g, exceeds " MAX_STEPS_TEXT " (the most allowed): give "
                               "a larger --dt or --velocity, or --max-steps",
                               dt, p->rupture, pull_steps, pull_steps, options[AFTER].integer,
                               max_default);
    p->dt = dt;
    p->max_steps = options[MAX_STEPS].given ? options[MAX_STEPS].integer : (long)max_default;
    p->after = options[AFTER].integer;
    p->every = options[EVERY].integer;
    return 0;
}

static void print_header(int argc, char **argv, const pulloff *p, int dt_given)
{
    const cb_law *law = p->law;
    printf("# capbridge pulloff");
    for (int i = 1; i < argc; ++i) printf(" %s", argv[i]);
    printf("\n# law = %s, gamma = %.17g N/m, theta = %.17g deg\n", cb_model_name(law->model),
           law->surface_tension, law->contact_angle * 180.0 / CB_PI);
    printf("# m1 = %.17g kg, m2 = %.17g kg, reduced_mass = %.17g kg\n", p->m1, p->m2,
           p->mass);
    printf("# kn = %.17g N/m, damping_coefficient = %.17g kg/s, velocity = %.17g m/s\n",
           p->contact.normal_stiffness, p->contact.damping_factor * p->sqrt_mass, p->velocity);
    printf("# rupture_distance = %.17g m\n", p->rupture);
    printf("# dt = %.17g s (%s)\n", p->dt,
           dt_given ? "given" : "default: min(0.02 pi sqrt(m/k_n), rupture_distance/(2000 v))");
    puts("step,time,x1,v1,x2,gap,capillary_force,contact_force,bridge");
}

/* Step 0 and the steps of the step order (the top of the file) until --steps-after-rupture
 * steps after the first rupture; the rows as it goes.  Returns the exit code. */
static int run_pulloff(const char *name, const pulloff *p)
{
    /* step 0: LAMMPS's setup computes the forces at the initial positions */
    const double dt = p->dt;
    const double x2_start = p->radsum;
    const double dtfm = 0.5 * dt / p->m1; /* fix nve: dtf = 0.5 dt, dtfm = dtf / mass */
    double x1 = 0.0, v1 = 0.0, x2 = x2_start;
    cb_bridge bridge = {0};
    forces f;
    cb_status status = compute_forces(p, x1, v1, x2, &bridge, &f);
    if (status != CB_OK) return cli_status_error(name, "step 0", status);
    if (bridge.active == 0.0)
        return cli_runtime_error(name, "no bridge formed at contact (cb_bridge_update)");
    print_row(0, 0.0, x1, v1, x2, &bridge, &f);

    long rupture_step = -1;
    for (long n = 1;; ++n) {
        v1 += dtfm * f.f1;                        /* 1. half kick */
        x1 += dt * v1;                            /* 2. drift */
        x2 = x2_start + p->velocity * ((double)n * dt); /* 3. driven sphere */
        status = compute_forces(p, x1, v1, x2, &bridge, &f); /* 4.-6. */
        if (status != CB_OK) {
            char what[48];
            snprintf(what, sizeof what, "step %ld", n);
            return cli_status_error(name, what, status);
        }
        v1 += dtfm * f.f1;                        /* 7. half kick */
        if (f.transition == CB_BRIDGE_RUPTURED && rupture_step < 0) rupture_step = n;
        int last = rupture_step >= 0 && n - rupture_step >= p->after;
        int event = f.transition == CB_BRIDGE_RUPTURED || f.transition == CB_BRIDGE_FORMED;
        int stuck = rupture_step < 0 && n >= p->max_steps;
        if (last || event || stuck || n % p->every == 0)
            print_row(n, (double)n * dt, x1, v1, x2, &bridge, &f); /* 8. */
        if (last) return 0;
        if (stuck)
            return cli_runtime_error(
                name,
                "the bridge did not rupture within --max-steps %ld steps (%.6g s, gap %.6g m, "
                "rupture distance %.6g m): sphere 1 follows sphere 2; raise --velocity or "
                "--max-steps",
                p->max_steps, (double)n * dt, f.gap, p->rupture);
    }
}

int cmd_pulloff(int argc, char **argv)
{
    const char *name = "pulloff";
    cli_option options[N_OPTIONS] = {
        CLI_OPTION_R1,
        {.name = "--r2", .kind = CLI_POSITIVE, .required = 1, .meaning = "radius of sphere 2 [m]"},
        CLI_OPTION_VOLUME,
        {.name = "--density", .kind = CLI_POSITIVE, .meaning = "density [kg/m^3]",
         .number = 2500.0},
        {.name = "--kn", .kind = CLI_POSITIVE, .meaning = "normal stiffness [N/m]",
         .number = 1e3},
        {.name = "--damping", .kind = CLI_FRACTION, .meaning = "damping rate alpha_n",
         .number = 0.0},
        {.name = "--velocity", .kind = CLI_POSITIVE, .meaning = "velocity of sphere 2 [m/s]",
         .number = 1e-4},
        {.name = "--dt", .kind = CLI_POSITIVE, .meaning = "time step [s]"},
        {.name = "--steps-after-rupture", .kind = CLI_INTEGER,
         .meaning = "steps run after the rupture", .minimum = 0, .maximum = MAX_STEPS_LIMIT,
         .integer = 10},
        {.name = "--max-steps", .kind = CLI_INTEGER, .meaning = "largest number of steps",
         .minimum = 1, .maximum = MAX_STEPS_LIMIT},
        {.name = "--every", .kind = CLI_INTEGER, .meaning = "print every N-th step",
         .minimum = 1, .maximum = MAX_STEPS_LIMIT, .integer = 1},
    };
    cb_law law;
    cli_request request = {name, usage, 1, &law, options, N_OPTIONS, NULL, NULL};
    int code;
    if (!cli_parse(&request, argc, argv, &code)) return code;
    pulloff p;
    code = pulloff_setup(name, options, &law, &p);
    if (code == 0) {
        print_header(argc, argv, &p, options[DT].given);
        code = run_pulloff(name, &p);
    }
    cb_law_release(&law);
    return code;
}
