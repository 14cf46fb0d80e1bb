/* laplace_young_internal.h — shared declarations of the exact Laplace-Young solver.
 *
 * Everything here is nondimensional: lengths in units of the harmonic radius R_h of the
 * pair, surface tension 1. So the pressure is P = dp R_h / gamma (dp = p_liquid - p_gas,
 * negative = suction), a force is F / (gamma R_h) and a volume V / R_h^3.
 *
 * Geometry (axis x along the line of centres): sphere 1 (radius r1) has its centre at
 * x = -r1, sphere 2 (r2) at x = gap + r2, or, for a plane (the limit r2 -> infinity), the
 * plane is x = gap. The meridian profile y(s) >= 0 is parametrised by its arc length s
 * from the contact line on sphere 1, with tangent angle phi from +x:
 *     x' = cos phi,  y' = sin phi,  phi' = cos(phi) / y - P.
 * First integral: F = 2 pi y cos(phi) - pi y^2 P, the attractive axial force.
 * The liquid meets sphere 1 at the contact angle theta1 and surface 2 at theta2.
 *
 * A branch point is z = (delta1, delta2, P, S, gap): the two filling angles, the pressure,
 * the profile length and the gap; for a plane, delta2 holds the radius of the contact line
 * on the plane instead (a length: a filling angle of the plane would be 0). The shooting
 * residuals of z are the mismatch of the integrated end point with the contact line on
 * surface 2 (x, y, phi) and of the volume. */
#ifndef LAPLACE_YOUNG_INTERNAL_H
#define LAPLACE_YOUNG_INTERNAL_H

#include "capbridge.h" /* CB_PI */

enum { LY_DELTA1 = 0, LY_DELTA2, LY_PRESSURE, LY_LENGTH, LY_GAP, LY_NVAR };
enum { LY_RES_X = 0, LY_RES_Y, LY_RES_PHI, LY_RES_VOLUME, LY_NRES };

/* The nondimensional problem. */
typedef struct ly_geometry {
    double r1, r2;   /* radii / R_h; r2 = INFINITY for a plane */
    int plane;       /* surface 2 is the plane x = gap (then z[LY_DELTA2] is its contact
                      * line's radius) */
    double theta1;   /* contact angle on sphere 1 [rad] */
    double theta2;   /* ... on surface 2 */
    double volume;   /* V / R_h^3 */
    int steps;       /* RK4 steps along the profile */
} ly_geometry;

/* What one integrated profile says about its branch point. */
typedef struct ly_profile {
    double residual[LY_NRES];
    double jacobian[LY_NRES][LY_NVAR]; /* d residual / d z (only if asked for) */
    double volume;        /* pi * integral of y^2 cos(phi) ds minus the two caps */
    double neck_force;    /* first integral at the smallest y of the profile */
    double neck_radius;   /* smallest y (at the neck when interior) */
} ly_profile;

/* ly_profile.c ------------------------------------------------------------ */

/* Integrate the profile of z with RK4 (and, if with_jacobian, its sensitivities).
 * Returns 0 when the profile is not a valid shooting (it reaches the axis, or a value is
 * not finite), 1 otherwise. */
int ly_shoot(const ly_geometry *g, const double z[LY_NVAR], int with_jacobian,
             ly_profile *profile);

/* The contact-line force on sphere i (Weigert/Pietsch-Rumpf form):
 * 2 pi r sin(delta) sin(delta + theta) - pi r^2 sin^2(delta) P. */
double ly_contact_force(double radius, double delta, double theta, double pressure);

/* The same on the plane, its contact line of radius y: 2 pi y sin(theta) - pi y^2 P (the
 * limit r -> infinity at r sin(delta) = y). */
double ly_plane_contact_force(double y, double theta, double pressure);

/* The radius of the contact line on surface 2 of branch point z. */
double ly_contact_radius2(const ly_geometry *g, const double z[LY_NVAR]);

/* A circle-arc (toroidal) guess of the bridge at gap 0 with filling angle delta1. */
void ly_toroidal_guess(const ly_geometry *g, double delta1, double z[LY_NVAR]);

/* ly_newton.c ------------------------------------------------------------- */

/* A square system for Newton's method: the first n_res shooting residuals (3: no volume
 * equation, 4: fixed volume), optionally the pseudo-arclength equation
 *     sum_i tangent_i (z_i - anchor_i) / scale_i = 0,
 * solved for the n_free variables free_var[] (the others stay fixed). */
typedef struct ly_system {
    const ly_geometry *geometry;
    int n_res;
    int arclength;
    int n_free;
    int free_var[LY_NVAR];
    double scale[LY_NVAR];   /* variable scales: Newton columns and arclength metric */
    double tangent[LY_NVAR]; /* unit tangent in scaled variables (arclength only) */
    double anchor[LY_NVAR];  /* the predictor point (arclength only) */
    int max_iterations;
} ly_system;

/* Damped Newton from z; on success (1) z is the solution, profile its integrated profile
 * (with Jacobian) and *iterations the number of Newton steps taken. */
int ly_newton(const ly_system *sys, double z[LY_NVAR], ly_profile *profile, int *iterations);

/* Scales of the branch variables around z (relative, with floors at the profile size). */
void ly_variable_scales(const double z[LY_NVAR], double scale[LY_NVAR]);

/* The unit tangent (in the variables scaled by scale[]) of the fixed-volume branch at a
 * point whose profile (with Jacobian) is given, oriented along reference (unit, scaled).
 * Returns 0 if the bordered system [J; reference] is singular, else the sign of its
 * determinant: the orientation of the Jacobian's null space relative to the direction of
 * travel. It is the same on either side of a fold and flips across a branch point. */
int ly_branch_tangent(const ly_profile *profile, const double scale[LY_NVAR],
                      const double reference[LY_NVAR], double tangent[LY_NVAR]);

/* Solve the n x n system a x = b (n <= LY_NVAR) by complete pivoting (a and b are
 * overwritten). Returns 0 if singular, else the sign of det(a) (+1 or -1). */
int ly_solve_dense(int n, double a[LY_NVAR][LY_NVAR], double b[LY_NVAR], double x[LY_NVAR]);

/* ly_branch.c ------------------------------------------------------------- */

#define LY_MAX_POINTS 200 /* a trace uses ~15-45 */

/* The fixed-volume branch from gap 0, as pseudo-arclength steps: the step leaving point k
 * has metric scale[k], unit tangent tangent[k] and length step[k], and ends at point k+1.
 * The gap increases along the stored points; when has_fold, the last point is the fold. */
typedef struct ly_branch {
    int count;
    int has_fold;
    double z[LY_MAX_POINTS][LY_NVAR];
    double scale[LY_MAX_POINTS][LY_NVAR];
    double tangent[LY_MAX_POINTS][LY_NVAR];
    double step[LY_MAX_POINTS];
} ly_branch;

/* The fixed-volume bridge at gap 0, reached by continuation in delta1 from a small
 * toroidal bridge. Returns 0 on failure. */
int ly_start_at_contact(const ly_geometry *g, double z[LY_NVAR]);

/* Trace the branch from gap 0 until a point's gap reaches gap_stop, or to the fold.
 * Returns 0 on failure. */
int ly_trace(const ly_geometry *g, double gap_stop, ly_branch *branch);

/* The branch point at this gap (0 <= gap <= the last traced gap). Returns 0 on failure. */
int ly_point_at_gap(const ly_geometry *g, const ly_branch *branch, double gap,
                    double z[LY_NVAR]);

#endif
