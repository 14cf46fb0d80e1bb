/* ----------------------------------------------------------------------
   capbridge — LAMMPS binding: pair style gran/capillary, the reach and the checks

   Member functions of PairGranCapillary that bound a run: the radius ranges per type,
   the bridge volume and the largest rupture distance the neighbor reach is built for,
   the cutoffs (init_one, radii2cut), and the two checks made at every re-neighboring:
   the periodic box against the reach, the time step against the stiffness.  A file of
   its own: estimates over ranges of radii and volumes, evaluated rarely, never per pair.
------------------------------------------------------------------------- */

#include "pair_gran_capillary.h"
#include "fix_capillary_liquid.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "fix_neigh_history.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <vector>

using namespace LAMMPS_NS;

/* ----------------------------------------------------------------------
   smallest and largest radius per type: atoms present and future fix pour/deposit
------------------------------------------------------------------------- */

void PairGranCapillary::radius_ranges()
{
  const int n = atom->ntypes;
  std::vector<double> lo(n + 1, HUGE_VAL), hi(n + 1, 0.0);
  for (auto &ifix : modify->get_fix_by_style("^(pour|deposit)")) {
    for (int t = 1; t <= n; t++) {
      int itype = t;
      auto *r = (double *) ifix->extract("radius", itype);
      if (r && *r > 0.0) {
        hi[t] = MAX(hi[t], *r);
        lo[t] = MIN(lo[t], *r);
      }
    }
  }
  double *radius = atom->radius;
  int *type = atom->type;
  for (int i = 0; i < atom->nlocal; i++) {
    hi[type[i]] = MAX(hi[type[i]], radius[i]);
    if (radius[i] > 0.0) lo[type[i]] = MIN(lo[type[i]], radius[i]);
  }
  MPI_Allreduce(&lo[1], &rad_min[1], n, MPI_DOUBLE, MPI_MIN, world);
  MPI_Allreduce(&hi[1], &rad_max[1], n, MPI_DOUBLE, MPI_MAX, world);
  for (int t = 1; t <= n; t++)
    if (rad_max[t] <= 0.0) rad_min[t] = 0.0;
}

/* ----------------------------------------------------------------------
   the bridge volume the neighbor reach of a type pair is built for
------------------------------------------------------------------------- */

double PairGranCapillary::design_volume(int itype, int jtype) const
{
  const double volume = type_pair(itype, jtype).volume;
  if (volume == 0.0) return 0.0;
  if (liquid_mode == LIQUID_FIXED) {
    if (volume > 0.0) return volume;
    return fix_liquid ? MAX(fix_liquid->fixed_volume, 0.0) : 0.0;
  }
  return fix_liquid ? fix_liquid->reach_volume() : 0.0;
}

/* ----------------------------------------------------------------------
   the neighbor reach of bridges of up to `volume` between spheres of these types: the
   core's rule (cb_reach: the largest rupture distance over the two radius ranges, the
   design rupture distance, and the reach, CB_REACH_MARGIN beyond it)
------------------------------------------------------------------------- */

void PairGranCapillary::type_pair_reach(int itype, int jtype, double volume,
                                        double &design_rupture, double &reach) const
{
  const cb_radius_range range_i = {rad_min[itype], rad_max[itype]};
  const cb_radius_range range_j = {rad_min[jtype], rad_max[jtype]};
  const int status =
      cb_reach(law(itype, jtype), range_i, range_j, volume, &design_rupture, &reach, nullptr);
  if (status != CB_OK)
    error->all(FLERR, "pair gran/capillary: types {} {}: law {} has no rupture distance for "
               "a bridge of volume {} between radii {} to {} and {} to {}: {}", itype, jtype,
               cb_model_name(law(itype, jtype)->model), volume, range_i.min, range_i.max,
               range_j.min, range_j.max, cb_status_message((cb_status) status));
}

/* ----------------------------------------------------------------------
   the neighbor cutoff of a type pair (init_one): the radius sum of its largest spheres
   plus the reach of the bridges it may hold; design_rupture: the design rupture distance
   of that reach, beyond which a held bridge is ruptured (cb_bridge_beyond_reach)
------------------------------------------------------------------------- */

double PairGranCapillary::pair_cutoff(int i, int j, double &design_rupture)
{
  double ri = rad_max[i], rj = rad_max[j];
  if (ri <= 0.0 || rj <= 0.0) {
    // no atom of this type yet: reach as far as the largest type pair with atoms
    double rmax = 0.0;
    for (int t = 1; t <= atom->ntypes; t++) rmax = MAX(rmax, rad_max[t]);
    if (ri <= 0.0) ri = rmax;
    if (rj <= 0.0) rj = rmax;
  }
  // the design volume, or a larger bridge that exists (held_volumes)
  const double reach_volume = MAX(design_volume(i, j), MAX(held_volume[i], held_volume[j]));
  double reach = 0.0;
  design_rupture = 0.0;
  if (rad_max[i] > 0.0 && rad_max[j] > 0.0)
    type_pair_reach(i, j, reach_volume, design_rupture, reach);
  const double cut = ri + rj + reach;
  if (design_rupture > ri + rj && !reach_warned) {
    // a rupture distance beyond a diameter needs a bridge of several sphere volumes
    // (Lian's rule: V > (R_i + R_j)^3): most likely a volume in other units
    reach_warned = 1;
    if (comm->me == 0)
      error->warning(FLERR, "pair gran/capillary: types {} {}: a bridge of volume {:.6g} "
                     "ruptures at {:.6g}, beyond the radius sum {:.6g} of the largest spheres "
                     "(a bridge larger than the spheres: check the volume and its units); the "
                     "neighbor cutoff is {:.6g}; this warning is given once", i, j,
                     reach_volume, design_rupture, ri + rj, cut);
  }
  return cut;
}

/* ----------------------------------------------------------------------
   the cutoff of two spheres of these radii (fix pour, deposit): the largest reach of the
   design volumes of the type pairs (cb_reach for the two radii alone)
------------------------------------------------------------------------- */

double PairGranCapillary::radii2cut(double r1, double r2)
{
  double largest = 0.0;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (!setflag[i][j]) continue;
      double reach = 0.0;
      if (cb_reach(law(i, j), cb_radius_range{r1, r1}, cb_radius_range{r2, r2},
                   design_volume(i, j), nullptr, &reach, nullptr) == CB_OK)
        largest = MAX(largest, reach);
    }
  return r1 + r2 + largest;
}

double PairGranCapillary::atom2cut(int i)
{
  return radii2cut(atom->radius[i], atom->radius[i]);
}

/* ----------------------------------------------------------------------
   two atoms must not meet as two periodic images (the pair history is per pair of IDs)
------------------------------------------------------------------------- */

void PairGranCapillary::check_periodic_images()
{
  // The pair history, and with it every bridge, is kept per pair of atom IDs: in a
  // periodic box too narrow for the neighbor cutoff (cb_periodic_too_narrow) the same two
  // atoms can meet as two periodic images, each with a copy of their bridge.
  double width[3];
  cb_cell_widths(domain->h_inv, width);
  const int periodic[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};
  const double cutoff = neighbor->cutneighmax;
  const int d = cb_periodic_too_narrow(width, periodic, cutoff);
  if (d >= 0)
    error->all(FLERR, "pair gran/capillary: the periodic box is {:.6g} wide along {}, less "
               "than twice the neighbor cutoff {:.6g} (the largest bridge reach plus the "
               "skin): two atoms would meet as two periodic images, each holding a copy of "
               "their bridge.  Make the box at least {:.6g} wide along {} (or lower the "
               "skin, or the bridge volume the reach is built for)",
               width[d], "xyz"[d], cutoff, 2.0 * cutoff, "xyz"[d]);
}

/* ----------------------------------------------------------------------
   time-step check, at setup and after every re-neighboring, warns once: dt above the core's
   limit (cb_timestep_limit: a tenth of pi sqrt(m_min / k), k the larger of k_n and the
   capillary stiffness bound over the radius ranges and the bridge volumes in use).
   One reduction per call (the smallest mass per type and the volume range per type pair,
   packed into one MIN); the limit, ~10^3 force calls per type pair, is evaluated again
   only when a type pair's volume range or smallest mass has changed (in fixed mode: once
   per run).
------------------------------------------------------------------------- */

void PairGranCapillary::check_timestep()
{
  if (dt_warned) return;
  const int n = atom->ntypes;
  const int np = (n + 1) * (n + 1);
  reduce_timestep_ranges();
  const double *mass = timestep_global.data();
  const double *vlo_all = mass + n + 1, *minus_vhi_all = vlo_all + np;

  // the limit per type pair, for the volumes and the mass it was last evaluated at
  if (update->setupflag || timestep_key.size() != (size_t) (KEY_SIZE * np)) {
    timestep_key.assign(KEY_SIZE * np, -1.0);
    timestep_bound.assign(BOUND_SIZE * np, 0.0);
  }
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) {
      if (!setflag[i][j] || mass[i] == HUGE_VAL || mass[j] == HUGE_VAL) continue;
      const int ij = i * (n + 1) + j;
      double key[KEY_SIZE] = {0.0, 0.0, MIN(mass[i], mass[j])};    // two volumes, the mass
      if (liquid_mode == LIQUID_FIXED)
        key[0] = design_volume(i, j);
      else if (-minus_vhi_all[ij] > 0.0) {
        key[0] = vlo_all[ij];
        key[1] = -minus_vhi_all[ij];
      }
      double *bound = &timestep_bound[BOUND_SIZE * ij];    // see timestep_limit
      if (!std::equal(key, key + KEY_SIZE, &timestep_key[KEY_SIZE * ij])) {
        timestep_limit(i, j, key, bound);
        std::copy(key, key + KEY_SIZE, &timestep_key[KEY_SIZE * ij]);
      }
      // a deck that sets dt to exactly this limit is within it: allow for its rounding
      if (update->dt > bound[0] * (1.0 + 1e-12)) {
        dt_warned = 1;
        if (comm->me == 0)
          error->warning(FLERR, "pair gran/capillary: time step {:.6g} s exceeds the limit "
                         "{:.6g} s = 10% of pi sqrt(m/k) for types {} {} (smallest mass "
                         "m = {:.6g}, k the larger of k_n = {:.6g} and the capillary "
                         "stiffness bound {:.6g}); this warning is given once",
                         update->dt, bound[0], i, j, key[2], normal_stiffness(i, j), bound[1]);
        return;
      }
      if (update->dt > bound[2] * (1.0 + 1e-12)) {
        dt_warned = 1;
        if (comm->me == 0)
          error->warning(FLERR, "pair gran/capillary: time step {:.6g} s exceeds the limit "
                         "{:.6g} s = 10% of pi m/c of the bridges' viscous force for types {} "
                         "{} (smallest mass m = {:.6g}, c = {:.6g} the largest damping "
                         "coefficient, at min_gap); this warning is given once",
                         update->dt, bound[2], i, j, key[2], bound[3]);
        return;
      }
    }
}

/* ----------------------------------------------------------------------
   the time-step limits of type pair i, j for key = the two bridge volumes in use (0: none)
   and the smallest mass: bound = the limit (cb_timestep_limit), the capillary stiffness
   bound, the viscous force's limit (cb_viscous_timestep_limit; HUGE_VAL without viscosity),
   its damping coefficient
------------------------------------------------------------------------- */

void PairGranCapillary::timestep_limit(int i, int j, const double *key, double *bound) const
{
  const cb_radius_range range_i = {rad_min[i], rad_max[i]};
  const cb_radius_range range_j = {rad_min[j], rad_max[j]};
  const int status = cb_timestep_limit(law(i, j), range_i, range_j, key, 2, key[2],
                                       normal_stiffness(i, j), &bound[0], &bound[1]);
  if (status != CB_OK)
    error->all(FLERR, "pair gran/capillary: types {} {}: no time-step limit for law {} with "
               "bridges of volume {} to {} between radii {} to {} and {} to {} (smallest "
               "mass {}): {}", i, j, cb_model_name(law(i, j)->model), key[0], key[1],
               range_i.min, range_i.max, range_j.min, range_j.max, key[2],
               cb_status_message((cb_status) status));
  bound[2] = HUGE_VAL;
  bound[3] = 0.0;
  if (law(i, j) && cb_viscous_timestep_limit(law(i, j), range_i, range_j, key, 2, key[2],
                                             &bound[2], &bound[3]) != CB_OK)
    error->all(FLERR, "pair gran/capillary: types {} {}: no viscous time-step limit for "
               "bridges of volume {} to {} between radii {} to {} and {} to {} (smallest mass "
               "{})", i, j, key[0], key[1], range_i.min, range_i.max, range_j.min,
               range_j.max, key[2]);
}

// the normal contact stiffness of type pair i, j in the time-step limit (contact none: 0)
double PairGranCapillary::normal_stiffness(int i, int j) const
{
  const TypePair &tp = type_pair(i, j);
  return tp.contact_on ? tp.contact.normal_stiffness : 0.0;
}

/* ----------------------------------------------------------------------
   check_timestep's one reduction, into timestep_global: [the smallest mass per type |
   the smallest bridge volume per type pair | minus the largest] over all ranks (the
   volumes in the protocol modes only: in mode fixed they are the design volumes)
------------------------------------------------------------------------- */

void PairGranCapillary::reduce_timestep_ranges()
{
  const int n = atom->ntypes;
  const int np = (n + 1) * (n + 1);
  timestep_local.assign(n + 1 + 2 * np, HUGE_VAL);
  timestep_global.resize(timestep_local.size());
  double *mass_lo = timestep_local.data();
  double *vlo = mass_lo + n + 1, *minus_vhi = vlo + np;
  for (int i = 0; i < atom->nlocal; i++)
    mass_lo[atom->type[i]] = MIN(mass_lo[atom->type[i]], atom->rmass[i]);
  if (liquid_mode != LIQUID_FIXED && history_size == SIZE_BRIDGE && fix_history && list) {
    int *type = atom->type;
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      double *allhistory = fix_history->firstvalue[i];
      for (int jj = 0; jj < list->numneigh[i]; jj++) {
        const int j = list->firstneigh[i][jj] & NEIGHMASK;
        cb_bridge *bridge = bridge_of(&allhistory[SIZE_BRIDGE * jj]);
        if (bridge->active == 0.0) continue;
        const int a = MIN(type[i], type[j]), b = MAX(type[i], type[j]);
        vlo[a * (n + 1) + b] = MIN(vlo[a * (n + 1) + b], bridge->volume);
        minus_vhi[a * (n + 1) + b] = MIN(minus_vhi[a * (n + 1) + b], -bridge->volume);
      }
    }
  }
  MPI_Allreduce(timestep_local.data(), timestep_global.data(), (int) timestep_local.size(),
                MPI_DOUBLE, MPI_MIN, world);
}
