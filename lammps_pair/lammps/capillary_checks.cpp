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
#include "math_const.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>
#include <vector>

using namespace LAMMPS_NS;

using MathConst::MY_PI;

namespace {
// The neighbor reach exceeds the largest rupture distance by this fraction, so that a
// bridge held at exactly its rupture distance is never cut by the reach test.
constexpr double REACH_MARGIN = 1e-9;
}    // namespace

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
   the largest rupture distance of a bridge of volume vol between spheres of these
   types: a 5 x 5 grid over both radius ranges (corners included); every law in the
   core has its largest rupture distance at a corner (Lian: none depends on the radii;
   Willett: at the smallest harmonic radius), the grid covers the table law
------------------------------------------------------------------------- */

double PairGranCapillary::max_rupture(int itype, int jtype, double vol) const
{
  if (!(vol > 0.0)) return 0.0;
  cb_law extend = *law(itype, jtype);    // shallow: never released
  extend.validity = CB_VALIDITY_EXTEND;
  double largest = 0.0;
  const int steps = 4;
  for (int a = 0; a <= steps; a++)
    for (int b = 0; b <= steps; b++) {
      double r1 = rad_min[itype] + (rad_max[itype] - rad_min[itype]) * a / steps;
      double r2 = rad_min[jtype] + (rad_max[jtype] - rad_min[jtype]) * b / steps;
      if (!(r1 > 0.0) || !(r2 > 0.0)) continue;
      double d = 0.0;
      int status = cb_rupture_distance(&extend, r1, r2, vol, &d);
      if (status != CB_OK)
        error->all(FLERR, "pair gran/capillary: types {} {}: law {} has no rupture distance for "
                   "a bridge of volume {} between radii {} and {}: {}", itype, jtype,
                   cb_model_name(extend.model), vol, r1, r2,
                   cb_status_message((cb_status) status));
      largest = MAX(largest, d);
    }
  return largest;
}

/* ----------------------------------------------------------------------
   the neighbor cutoff of a type pair (init_one): the radius sum of its largest spheres
   plus the largest rupture distance of the bridges it may hold
------------------------------------------------------------------------- */

double PairGranCapillary::pair_cutoff(int i, int j)
{
  double ri = rad_max[i], rj = rad_max[j];
  if (ri <= 0.0 || rj <= 0.0) {
    // no atom of this type yet: reach as far as the largest type pair with atoms
    double rmax = 0.0;
    for (int t = 1; t <= atom->ntypes; t++) rmax = MAX(rmax, rad_max[t]);
    if (ri <= 0.0) ri = rmax;
    if (rj <= 0.0) rj = rmax;
  }
  double reach = 0.0;
  if (rad_max[i] > 0.0 && rad_max[j] > 0.0) {
    // the design volume, or a larger bridge that exists (held_volumes)
    const double reach_volume =
        MAX(design_volume(i, j), MAX(held_volume[i], held_volume[j]));
    reach = max_rupture(i, j, reach_volume) * (1.0 + REACH_MARGIN);
  }
  double cut = ri + rj + reach;
  if (reach > ri + rj && !reach_warned) {
    // a rupture distance beyond a diameter needs a bridge of several sphere volumes
    // (Lian's rule: V > (R_i + R_j)^3): most likely a volume in other units
    reach_warned = 1;
    if (comm->me == 0)
      error->warning(FLERR, "pair gran/capillary: types {} {}: a bridge of volume {:.6g} "
                     "ruptures at {:.6g}, beyond the radius sum {:.6g} of the largest spheres "
                     "(a bridge larger than the spheres: check the volume and its units); the "
                     "neighbor cutoff is {:.6g}; this warning is given once", i, j,
                     MAX(design_volume(i, j), MAX(held_volume[i], held_volume[j])),
                     reach / (1.0 + REACH_MARGIN), ri + rj, cut);
  }
  return cut;
}

/* ---------------------------------------------------------------------- */

double PairGranCapillary::radii2cut(double r1, double r2)
{
  double reach = 0.0;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (!setflag[i][j]) continue;
      double vol = design_volume(i, j);
      if (!(vol > 0.0)) continue;
      double d = 0.0;
      cb_law extend = *law(i, j);
      extend.validity = CB_VALIDITY_EXTEND;
      if (cb_rupture_distance(&extend, r1, r2, vol, &d) == CB_OK) reach = MAX(reach, d);
    }
  return r1 + r2 + reach * (1.0 + REACH_MARGIN);
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
  // The pair history, and with it every bridge, is kept per pair of atom IDs.  In a
  // periodic box narrower than twice the neighbor cutoff, the same two atoms can meet as
  // two periodic images in one neighbor list, and each image would get a copy of their
  // bridge: liquid out of nothing.  Widths between opposite faces (triclinic: 1 / |row of
  // the inverse box matrix|).
  const double *h_inv = domain->h_inv;
  const double width[3] = {
      1.0 / sqrt(h_inv[0] * h_inv[0] + h_inv[5] * h_inv[5] + h_inv[4] * h_inv[4]),
      1.0 / sqrt(h_inv[1] * h_inv[1] + h_inv[3] * h_inv[3]), 1.0 / h_inv[2]};
  const int periodic[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};
  const double cutoff = neighbor->cutneighmax;
  for (int d = 0; d < 3; d++)
    if (periodic[d] && width[d] < 2.0 * cutoff)
      error->all(FLERR, "pair gran/capillary: the periodic box is {:.6g} wide along {}, less "
                 "than twice the neighbor cutoff {:.6g} (the largest bridge reach plus the "
                 "skin): two atoms would meet as two periodic images, each holding a copy of "
                 "their bridge.  Make the box at least {:.6g} wide along {} (or lower the "
                 "skin, or the bridge volume the reach is built for)",
                 width[d], "xyz"[d], cutoff, 2.0 * cutoff, "xyz"[d]);
}

/* ----------------------------------------------------------------------
   time-step check, at setup and after every re-neighboring, warns once:
   dt > 0.1 pi sqrt(m_min / k), k the larger of k_n and the capillary stiffness bound
   (cb_capillary_stiffness_bound over the radius ranges and the bridge volumes in use).
   One reduction per call (the smallest mass per type and the volume range per type pair,
   packed into one MIN); the stiffness bound, ~10^3 force calls per type pair, is evaluated
   again only when a type pair's volume range has changed (in fixed mode: once per run).
------------------------------------------------------------------------- */

void PairGranCapillary::check_timestep()
{
  if (dt_warned) return;
  const int n = atom->ntypes;
  const int np = (n + 1) * (n + 1);
  reduce_timestep_ranges();
  const double *mass = timestep_global.data();
  const double *vlo_all = mass + n + 1, *minus_vhi_all = vlo_all + np;

  // the bound per type pair, for the volumes it was last evaluated at
  if (update->setupflag || bound_volumes.size() != (size_t) (2 * np)) {
    bound_volumes.assign(2 * np, -1.0);
    capillary_bound.assign(np, 0.0);
  }
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) {
      if (!setflag[i][j] || mass[i] == HUGE_VAL || mass[j] == HUGE_VAL) continue;
      const int ij = i * (n + 1) + j;
      double volumes[2] = {0.0, 0.0};
      if (liquid_mode == LIQUID_FIXED)
        volumes[0] = design_volume(i, j);
      else if (-minus_vhi_all[ij] > 0.0) {
        volumes[0] = vlo_all[ij];
        volumes[1] = -minus_vhi_all[ij];
      }
      if (volumes[0] != bound_volumes[2 * ij] || volumes[1] != bound_volumes[2 * ij + 1]) {
        capillary_bound[ij] = capillary_stiffness(i, j, volumes);
        bound_volumes[2 * ij] = volumes[0];
        bound_volumes[2 * ij + 1] = volumes[1];
      }
      const double m = MIN(mass[i], mass[j]);
      const double capillary = capillary_bound[ij];
      const TypePair &tp = type_pair(i, j);
      const double contact = tp.contact_on ? tp.contact.normal_stiffness : 0.0;
      const double k = MAX(contact, capillary);
      if (!(k > 0.0)) continue;
      const double limit = 0.1 * MY_PI * sqrt(m / k);
      // a deck that sets dt to exactly this limit is within it: allow for its rounding
      if (update->dt > limit * (1.0 + 1e-12)) {
        dt_warned = 1;
        if (comm->me == 0)
          error->warning(FLERR, "pair gran/capillary: time step {:.6g} s exceeds the limit "
                         "{:.6g} s = 10% of pi sqrt(m/k) for types {} {} (smallest mass "
                         "m = {:.6g}, k = {:.6g}: the larger of k_n = {:.6g} and "
                         "the capillary stiffness bound {:.6g}); this warning is given once",
                         update->dt, limit, i, j, m, k, contact, capillary);
        return;
      }
    }
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

/* ----------------------------------------------------------------------
   the capillary stiffness bound of type pair i, j: the largest over the corners of both
   radius ranges and the (up to two) bridge volumes given (0: none)
------------------------------------------------------------------------- */

double PairGranCapillary::capillary_stiffness(int i, int j, const double *volumes) const
{
  double capillary = 0.0;
  const double ri[2] = {rad_min[i], rad_max[i]}, rj[2] = {rad_min[j], rad_max[j]};
  for (int v = 0; v < 2; v++) {
    const double vol = volumes[v];
    if (!(vol > 0.0)) continue;
    for (double r1 : ri)
      for (double r2 : rj) {
        double k = 0.0;
        if (r1 > 0.0 && r2 > 0.0 &&
            cb_capillary_stiffness_bound(law(i, j), r1, r2, vol, &k) == CB_OK)
          capillary = MAX(capillary, k);
      }
  }
  return capillary;
}
