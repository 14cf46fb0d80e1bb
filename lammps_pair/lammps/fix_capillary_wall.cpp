/* ----------------------------------------------------------------------
   capbridge — LAMMPS binding: fix capillary/wall (see fix_capillary_wall.h)

   fix ID group capillary/wall xplane|yplane|zplane LO HI [angle DEG] [volume V]
   fix ID group capillary/wall zcylinder RADIUS [angle DEG] [volume V]
   fix ID group capillary/wall region REGION-ID [angle DEG] [volume V]

   Every physical rule is the core's: the sphere-plane bridge (r2 = CB_PLANE: the laws'
   plane forms, the rupture distance), the wall's contact angle (cb_wall_contact_angle),
   the bridge states (cb_bridge_step), Protocol 2's take with the wall's share 0
   (cb_protocol2_take), the viscous damping (cb_viscous_damping).  This file gathers the
   grain and the plane (a cylinder's or a region's tangent plane at the grain), and scatters
   the force.
------------------------------------------------------------------------- */

#include "fix_capillary_wall.h"

#include "capillary_bridges.h"
#include "capillary_liquid_mode.h"
#include "fix_capillary_liquid.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "math_const.h"
#include "memory.h"
#include "modify.h"
#include "pair.h"
#include "region.h"
#include "update.h"
#include "utils.h"

#include <cmath>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;
using MathConst::MY_PI;

/* ---------------------------------------------------------------------- */

FixCapillaryWall::FixCapillaryWall(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), nwalls(0), wall_angle(-1.0), volume_given(-1.0), region_id(nullptr),
    region(nullptr), key_base(0), state(nullptr), bridges(nullptr), liquid(nullptr), per_atom_liquid(0), protocol1(0),
    liquid_groupbit(0),
    census_step(-1), timestep_warned(0)
{
  for (int k = parse_walls(narg, arg); k < narg; k += 2) {
    if (k + 1 >= narg)
      error->all(FLERR, "fix capillary/wall: keyword '{}' needs a value", arg[k]);
    if (strcmp(arg[k], "angle") == 0) {
      const double degrees = utils::numeric(FLERR, arg[k + 1], false, lmp);
      if (!(degrees >= 0.0 && degrees < 90.0))
        error->all(FLERR, "fix capillary/wall: angle {}: the wall's contact angle must be in "
                   "0 <= angle < 90 degrees", arg[k + 1]);
      wall_angle = degrees * MY_PI / 180.0;
    } else if (strcmp(arg[k], "volume") == 0) {
      volume_given = utils::numeric(FLERR, arg[k + 1], false, lmp);
      if (!(volume_given > 0.0) || !std::isfinite(volume_given))
        error->all(FLERR, "fix capillary/wall: volume {}: a bridge volume must be > 0 and "
                   "finite", arg[k + 1]);
    } else {
      error->all(FLERR, "fix capillary/wall: unknown keyword '{}': allowed angle, volume",
                 arg[k]);
    }
  }

  vector_flag = 1;
  size_vector = 5;
  global_freq = 1;
  extvector = 1;
  restart_peratom = 1;
  create_attribute = 1;
  maxexchange = nwalls * CB_BRIDGE_DOUBLES;
  for (double &v : values) v = 0.0;
  for (double &f : wall_force) f = 0.0;
  FixCapillaryWall::grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) FixCapillaryWall::set_arrays(i);
}

/* ----------------------------------------------------------------------
   the wall style and its positions (arguments 3, 4, 5) or its radius (3, 4); returns the
   index of the first keyword
------------------------------------------------------------------------- */

int FixCapillaryWall::parse_walls(int narg, char **arg)
{
  const char *expected = "fix capillary/wall: expected 'xplane|yplane|zplane LO HI' (LO or HI "
                         "may be NULL), 'zcylinder RADIUS' or 'region REGION-ID'";
  if (narg < 5) error->all(FLERR, expected);
  if (strcmp(arg[3], "region") == 0) {
    // the faces of a region, each grain's bridges keyed by the face (Region::Contact's
    // iwall, below the region's cmax: one slot per face it can report)
    region = domain->get_region_by_id(arg[4]);
    if (!region)
      error->all(FLERR, "fix capillary/wall: region {} does not exist: define it with the "
                 "region command before this fix", arg[4]);
    axis[0] = REGION;
    region_id = utils::strdup(arg[4]);
    nwalls = region->cmax;
    if (nwalls < 1)
      error->all(FLERR, "fix capillary/wall: region {} has no surface to wet", arg[4]);
    return 5;
  }
  if (strcmp(arg[3], "zcylinder") == 0) {
    // the cylinder x^2 + y^2 = RADIUS^2 of fix wall/gran zcylinder, the grains inside
    axis[0] = CYLINDER;
    side[0] = 1.0;
    position[0] = utils::numeric(FLERR, arg[4], false, lmp);
    if (!(position[0] > 0.0) || !std::isfinite(position[0]))
      error->all(FLERR, "fix capillary/wall: zcylinder radius {} must be > 0 and finite",
                 arg[4]);
    nwalls = 1;
    return 5;
  }
  if (narg < 6) error->all(FLERR, expected);
  int normal = -1;
  if (strcmp(arg[3], "xplane") == 0) normal = 0;
  if (strcmp(arg[3], "yplane") == 0) normal = 1;
  if (strcmp(arg[3], "zplane") == 0) normal = 2;
  if (normal < 0)
    error->all(FLERR, "fix capillary/wall: unknown wall style '{}': allowed xplane, yplane, "
               "zplane, zcylinder, region", arg[3]);
  for (int k = 0; k < 2; k++) {
    if (strcmp(arg[4 + k], "NULL") == 0) continue;
    axis[nwalls] = normal;
    side[nwalls] = k == 0 ? 1.0 : -1.0;
    position[nwalls] = utils::numeric(FLERR, arg[4 + k], false, lmp);
    nwalls++;
  }
  if (nwalls == 0)
    error->all(FLERR, "fix capillary/wall: both LO and HI are NULL: give at least one plane");
  if (nwalls == 2 && !(position[0] < position[1]))
    error->all(FLERR, "fix capillary/wall: LO {} must be below HI {}", position[0], position[1]);
  return 6;
}

FixCapillaryWall::~FixCapillaryWall()
{
  if (copymode) return;
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(state);
  delete[] region_id;
  release_laws();
}

int FixCapillaryWall::setmask()
{
  return POST_FORCE;
}

/* ----------------------------------------------------------------------
   the pair's bridges and type pairs, the liquid fix, each type's wall law
------------------------------------------------------------------------- */

void FixCapillaryWall::init()
{
  bridges = dynamic_cast<CapillaryBridges *>(force->pair_match("gran/capillary", 1));
  if (!bridges)
    error->all(FLERR, "fix capillary/wall requires pair style gran/capillary (alone or as a "
               "sub-style of pair_style hybrid/overlay): its type pairs give the walls' law");
  if (update->whichflag == 2)
    error->all(FLERR, "fix capillary/wall does not support minimization");
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "fix capillary/wall does not support run_style respa: use run_style "
               "verlet");
  if (region_id) {
    // the region may have been deleted or defined again since the last run
    region = domain->get_region_by_id(region_id);
    if (!region)
      error->all(FLERR, "fix capillary/wall: region {} does not exist (any more)", region_id);
    if (region->cmax != nwalls)
      error->all(FLERR, "fix capillary/wall: region {} now has {} faces, {} when this fix was "
                 "defined: define the fix again", region_id, region->cmax, nwalls);
    // a moving region's velocity from this run's first step on
    if (region->dynamic_check()) region->reset_vel();
  }
  auto found = modify->get_fix_by_style("^capillary/liquid$");
  liquid = found.empty() ? nullptr : dynamic_cast<FixCapillaryLiquid *>(found.front());
  per_atom_liquid = liquid && capillary_liquid_per_atom(liquid->mode);
  liquid_groupbit = liquid ? liquid->groupbit : 0;
  protocol1 = liquid && liquid->mode == LIQUID_PROTOCOL1;
  if (protocol1 && wall_angle >= 0.0)
    error->all(FLERR, "fix capillary/wall: keyword angle with fix capillary/liquid protocol1: "
               "Protocol 1 distributes the liquid with one law, the grains' (their contact "
               "angle); leave out angle, or use protocol2 or protocol3");
  if (liquid && liquid->mode != LIQUID_FIXED && volume_given > 0.0)
    error->all(FLERR, "fix capillary/wall: keyword volume is for liquid mode fixed; under fix "
               "capillary/liquid {} the grains' free liquid forms the wall bridges",
               liquid->mode_name());
  // the walls' keys: after those of the capillary/wall fixes defined before this one
  key_base = 0;
  for (auto *other : modify->get_fix_by_style("^capillary/wall$")) {
    if (other == this) break;
    key_base += static_cast<FixCapillaryWall *>(other)->nwalls;
  }
  derive_laws();
  // before the run's first force evaluation, where fix capillary/liquid advances them
  check_states();
}

/* ----------------------------------------------------------------------
   per type: the law of the type's own type pair, at the wall's contact angle (the core's
   rule for two surfaces, cb_wall_contact_angle) when keyword angle differs from the grains'
------------------------------------------------------------------------- */

void FixCapillaryWall::derive_laws()
{
  release_laws();
  const int ntypes = atom->ntypes;
  own_laws.assign(ntypes + 1, cb_law{});
  laws.assign(ntypes + 1, nullptr);
  volumes.assign(ntypes + 1, 0.0);
  for (int t = 1; t <= ntypes; t++) {
    if (!bridges->wet_type_pair(t, t)) continue;
    const CapillaryBridges::TypePair &tp = bridges->type_pair(t, t);
    volumes[t] = volume_given > 0.0 ? volume_given : tp.formation_volume;
    laws[t] = tp.law;
    if (wall_angle < 0.0 || wall_angle == tp.law->contact_angle) continue;
    cb_law &own = own_laws[t];
    own = *tp.law;
    own.data = nullptr;    // a table law builds its own table (cb_law_prepare)
    own.prepared = 0;
    own.contact_angle = cb_wall_contact_angle(tp.law->contact_angle, wall_angle);
    cb_message msg;
    if (cb_law_prepare(&own, &msg) != CB_OK)
      error->all(FLERR, "fix capillary/wall: the law of type {} at the wall's angle: {}", t,
                 msg.text);
    laws[t] = &own;
  }
}

void FixCapillaryWall::release_laws()
{
  for (cb_law &own : own_laws)
    if (own.prepared) cb_law_release(&own);
  own_laws.clear();
}

int FixCapillaryWall::atom_type(int atom_index) const
{
  return atom->type[atom_index];
}

/* ---------------------------------------------------------------------- */

void FixCapillaryWall::setup(int vflag)
{
  check_timestep();
  post_force(vflag);
}

/* ----------------------------------------------------------------------
   the time step against the wall bridges' own limits (collective; at each run's setup,
   warns once): the core's cb_timestep_limit (the capillary stiffness bound; the contact's
   stiffness is fix wall/gran's) and cb_viscous_timestep_limit, for the sphere-plane pair
   (a wall bridge's damping is about four times a pair's of equal spheres: R* = r), over
   each wet type's radius range and smallest mass in the group, at the volume a bridge
   forms with (fixed) or the liquid fix's design volume (Protocols 2, 3)
------------------------------------------------------------------------- */

void FixCapillaryWall::check_timestep()
{
  if (timestep_warned) return;
  const int ntypes = atom->ntypes;
  // per type: minus the smallest mass, minus the smallest radius, the largest radius (one MAX)
  std::vector<double> local(3 * (ntypes + 1), -HUGE_VAL), global(local.size());
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    double *row = &local[3 * atom_type(i)];
    row[0] = MAX(row[0], -atom->rmass[i]);
    row[1] = MAX(row[1], -atom->radius[i]);
    row[2] = MAX(row[2], atom->radius[i]);
  }
  MPI_Allreduce(local.data(), global.data(), (int) local.size(), MPI_DOUBLE, MPI_MAX, world);
  for (int t = 1; t <= ntypes; t++) {
    const double *row = &global[3 * t];
    if (!laws[t] || row[2] == -HUGE_VAL) continue;
    const double mass = -row[0];
    const double volume = per_atom_liquid ? liquid->reach_volume() : volumes[t];
    const cb_radius_range grain = {-row[1], row[2]}, plane = {CB_PLANE, CB_PLANE};
    double limit = HUGE_VAL, stiffness = 0.0, viscous = HUGE_VAL, damping = 0.0;
    int status = cb_timestep_limit(laws[t], grain, plane, &volume, 1, mass, 0.0, &limit,
                                   &stiffness);
    if (status == CB_OK && laws[t]->viscosity > 0.0)
      status = cb_viscous_timestep_limit(laws[t], grain, plane, &volume, 1, mass, &viscous,
                                         &damping);
    if (status != CB_OK)
      error->all(FLERR, "fix capillary/wall: type {}: no time-step limit for wall bridges of "
                 "volume {} and radii {} to {} (smallest mass {}): {}", t, volume, grain.min,
                 grain.max, mass, cb_status_message((cb_status) status));
    // a deck that sets dt to exactly a limit is within it: allow for its rounding
    const double dt = update->dt * (1.0 - 1e-12);
    if (dt > limit || dt > viscous) {
      timestep_warned = 1;
      if (comm->me == 0) {
        if (dt > limit)
          error->warning(FLERR, "fix capillary/wall: time step {:.6g} s exceeds the limit "
                         "{:.6g} s = 10% of pi sqrt(m/k) of the wall bridges of type {} "
                         "(smallest mass m = {:.6g}, k = {:.6g} the capillary stiffness "
                         "bound); this warning is given once", update->dt, limit, t, mass,
                         stiffness);
        else
          error->warning(FLERR, "fix capillary/wall: time step {:.6g} s exceeds the limit "
                         "{:.6g} s = 10% of pi m/c of the wall bridges' viscous force for "
                         "type {} (smallest mass m = {:.6g}, c = {:.6g} the largest damping "
                         "coefficient, at min_gap); this warning is given once", update->dt,
                         viscous, t, mass, damping);
      }
      return;
    }
  }
}

/* ----------------------------------------------------------------------
   each stored bridge (a restart file's, an earlier run's) checked and its constants derived
   again for this run's law (new coefficients, a new angle)
------------------------------------------------------------------------- */

void FixCapillaryWall::check_states()
{
  for (int i = 0; i < atom->nlocal; i++)
    for (int w = 0; w < nwalls; w++) {
      cb_bridge *bridge = bridge_at(i, w);
      int status = cb_bridge_check_state(bridge);
      if (status != CB_OK) fail(status, "stored bridge", i, NAN, bridge->volume);
      if (bridge->active == 0.0) continue;
      const cb_law *law = law_of(i);
      if (!law)
        error->one(FLERR, "fix capillary/wall: atom {} holds a wall bridge, but its type {} is "
                   "dry in this run (pair_coeff volume 0)", atom->tag[i], atom_type(i));
      status = cb_bridge_set_volume(law, atom->radius[i], CB_PLANE, bridge->volume, bridge);
      if (status != CB_OK) fail(status, "bridge constants", i, NAN, bridge->volume);
    }
}

/* ----------------------------------------------------------------------
   a moving or changing region at this step (once per step: Region::set_velocity keeps
   the step it was called at, as fix wall/gran/region on the same region may call it too)
------------------------------------------------------------------------- */

void FixCapillaryWall::prepare_walls()
{
  if (!region || !region->dynamic_check()) return;
  region->prematch();
  region->set_velocity();
}

/* ----------------------------------------------------------------------
   the walls of grain i this step: each with its gap, its normal n at the grain (from the
   wall towards the centre) and its velocity there.  Planes and the cylinder: every wall.
   A region: the faces within `reach` of the grain's surface (Region::surface), and, with
   with_beyond, each other face that holds a bridge or a mark, beyond (its gap taken as
   reach: farther than the bridge's rupture distance, since grain_reach covers it)
------------------------------------------------------------------------- */

const std::vector<FixCapillaryWall::Face> &FixCapillaryWall::faces(int i, double reach,
                                                                   int with_beyond)
{
  std::vector<Face> &out = grain_faces;
  out.clear();
  const double radius = atom->radius[i];
  double *x = atom->x[i];
  if (axis[0] != REGION) {
    for (int w = 0; w < nwalls; w++) {
      Face face = {w, 0, 0.0, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
      if (axis[w] == CYLINDER) {
        // the cylinder's tangent plane at the grain: n points to the axis (along x if on it)
        const double rho = sqrt(x[0] * x[0] + x[1] * x[1]);
        face.n[0] = rho > 0.0 ? -x[0] / rho : 1.0;
        face.n[1] = rho > 0.0 ? -x[1] / rho : 0.0;
        face.gap = position[w] - rho - radius;
      } else {
        face.n[axis[w]] = side[w];
        face.gap = side[w] * (x[axis[w]] - position[w]) - radius;
      }
      out.push_back(face);
    }
    return out;
  }
  // a grain whose centre left the region (through a wall) reaches none of its faces
  const int nc = region->match(x[0], x[1], x[2]) ? region->surface(x[0], x[1], x[2],
                                                                   radius + reach) : 0;
  const int moving = region->dynamic_check();
  for (int c = 0; c < nc; c++) {
    const Region::Contact &contact = region->contact[c];
    if (!(contact.r > 0.0))
      error->one(FLERR, "fix capillary/wall: atom {} has its centre on a face of region {}: "
                 "no normal there (a grain through the wall)", atom->tag[i], region_id);
    Face face = {contact.iwall, 0, contact.r - radius,
                 {contact.delx / contact.r, contact.dely / contact.r, contact.delz / contact.r},
                 {0.0, 0.0, 0.0}};
    if (moving) region->velocity_contact(face.v, x, c);
    out.push_back(face);
  }
  if (!with_beyond) return out;
  for (int w = 0; w < nwalls; w++) {
    if (cb_bridge_dry(bridge_at(i, w))) continue;
    bool found = false;
    for (int c = 0; c < nc; c++) found = found || out[c].wall == w;
    if (!found) out.push_back({w, 1, reach, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}});
  }
  return out;
}

/* ----------------------------------------------------------------------
   how far from grain i a region's faces are looked for: beyond its bridges' rupture
   distances (a face out of it breaks its bridge) and a margin of the grain's radius for
   the contacts that form bridges (planes and the cylinder: every wall is visited)
------------------------------------------------------------------------- */

double FixCapillaryWall::grain_reach(int i) const
{
  double reach = CB_REACH_MARGIN * atom->radius[i];
  for (int w = 0; w < nwalls; w++)
    reach = MAX(reach, (1.0 + CB_REACH_MARGIN) * bridge_at(i, w)->rupture);
  return reach;
}

const std::vector<FixCapillaryWall::Contact> &FixCapillaryWall::contacts()
{
  std::vector<Contact> &out = step_contacts;
  out.clear();
  const int *mask = atom->mask;
  prepare_walls();
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit) || !laws[atom_type(i)]) continue;
    const int wet = !liquid_groupbit || (mask[i] & liquid_groupbit);
    for (const Face &face : faces(i, grain_reach(i), 1)) {
      if (face.gap > 0.0 && cb_bridge_dry(bridge_at(i, face.wall))) continue;
      // the contact point's height above the centre, -r n_z (Protocol 3)
      out.push_back({i, face.wall, face.gap, -atom->radius[i] * face.n[2], wet});
    }
  }
  return out;
}

/* ----------------------------------------------------------------------
   Protocol 1's candidates: each owned grain of a wet type in the group and each wall
   within the rupture distance of a bridge of this volume (the largest it can receive)
------------------------------------------------------------------------- */

void FixCapillaryWall::candidates(std::vector<Contact> &out, double volume)
{
  out.clear();
  const int *mask = atom->mask;
  prepare_walls();
  for (int i = 0; i < atom->nlocal; i++) {
    const cb_law *law = laws[atom_type(i)];
    if (!(mask[i] & groupbit) || !law) continue;
    double reach = 0.0;
    const int status = cb_rupture_distance(law, atom->radius[i], CB_PLANE, volume, &reach);
    if (status != CB_OK) fail(status, "Protocol 1 reach", i, NAN, volume);
    const int wet = !liquid_groupbit || (mask[i] & liquid_groupbit);
    for (const Face &face : faces(i, reach, 0))
      if (face.gap <= reach)
        out.push_back({i, face.wall, face.gap, -atom->radius[i] * face.n[2], wet});
  }
}

/* ----------------------------------------------------------------------
   the force evaluation: each grain's wall bridges, their capillary (and viscous) force
------------------------------------------------------------------------- */

void FixCapillaryWall::post_force(int /*vflag*/)
{
  double **f = atom->f, **torque = atom->torque;
  const double *radius = atom->radius;
  const int *mask = atom->mask;
  for (double &w : wall_force) w = 0.0;
  prepare_walls();
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit) || !laws[atom_type(i)]) continue;
    for (const Face &face : faces(i, grain_reach(i), 1)) {
      const double gap = face.gap, *n = face.n;
      cb_bridge *bridge = bridge_at(i, face.wall);
      if (gap > 0.0 && cb_bridge_dry(bridge)) continue;
      double normal = -bridge_force(i, face.wall, gap, bridge);    // along n, from the wall
      double ft[3] = {0.0, 0.0, 0.0};
      if (laws[atom_type(i)]->viscosity > 0.0 && bridge->active != 0.0 && gap > 0.0)
        normal += viscous_normal(i, face, bridge, ft);
      for (int k = 0; k < 3; k++) {
        f[i][k] += normal * n[k] + ft[k];
        wall_force[k] -= normal * n[k] + ft[k];
      }
      // torque of ft at the contact point -r n: -r n x ft
      const double r = radius[i];
      torque[i][0] -= r * (n[1] * ft[2] - n[2] * ft[1]);
      torque[i][1] -= r * (n[2] * ft[0] - n[0] * ft[2]);
      torque[i][2] -= r * (n[0] * ft[1] - n[1] * ft[0]);
    }
  }
}

/* ----------------------------------------------------------------------
   one wall bridge at this gap: advanced here (liquid mode fixed), or, under Protocols 2
   and 3 (advanced by fix capillary/liquid), formed from the grain's offer and given its
   Protocol 3 deposit; returns the capillary attraction (>= 0)
------------------------------------------------------------------------- */

double FixCapillaryWall::bridge_force(int i, int w, double gap, cb_bridge *bridge)
{
  const cb_law *law = law_of(i);
  const double r = atom->radius[i];
  const int wet = !liquid_groupbit || (atom->mask[i] & liquid_groupbit);
  double available = 0.0, released = 0.0, capillary = 0.0;
  cb_transition transition = CB_BRIDGE_STAYS_DRY;
  int status = CB_OK;
  if (!per_atom_liquid) {
    available = wet ? volumes[atom_type(i)] : 0.0;
    status = cb_bridge_step(law, r, CB_PLANE, gap, available, bridge, &transition, &released,
                            &capillary);
    if (status != CB_OK) fail(status, "bridge step", i, gap, available);
    // Protocol 1: a broken bridge's liquid waits in the pool for the next distribution
    if (protocol1) bridges->pool_released += released;
  } else if (bridge->active == 0.0) {
    if (!wet || !cb_bridge_may_form(bridge, gap)) return 0.0;
    double offer = liquid->offer[i], wall_share = 0.0;
    status = cb_protocol2_take(&offer, &wall_share, &available);
    if (status != CB_OK) fail(status, "liquid take", i, gap, available);
    if (!(available > 0.0)) return 0.0;
    status = cb_bridge_step(law, r, CB_PLANE, gap, available, bridge, &transition, &released,
                            &capillary);
    if (status != CB_OK) fail(status, "bridge formation", i, gap, available);
  } else {
    const double deposit = liquid->deposit[i];
    if (liquid->mode == LIQUID_PROTOCOL3 && deposit > 0.0 &&
        liquid->best_partner[i] == (tagint) wall_key(w)) {
      status = cb_bridge_set_volume(law, r, CB_PLANE, bridge->volume + deposit, bridge);
      if (status != CB_OK) fail(status, "Protocol 3 deposit", i, gap, bridge->volume + deposit);
    }
    status = cb_bridge_force(law, r, CB_PLANE, gap, bridge, &capillary);
    if (status != CB_OK) fail(status, "capillary force", i, gap, bridge->volume);
  }
  if (transition == CB_BRIDGE_FORMED) bridges->n_formed += 1.0;
  if (transition == CB_BRIDGE_RUPTURED) bridges->n_ruptured += 1.0;
  return capillary;
}

/* ----------------------------------------------------------------------
   a stretched bridge's viscous force (the core's cb_viscous_damping, sphere-plane): the
   normal part returned (along n, from the wall), the tangential one in ft, at the contact
   point's velocity relative to the wall's there, v_t - r omega x n - v_wall,t
------------------------------------------------------------------------- */

double FixCapillaryWall::viscous_normal(int i, const Face &face, const cb_bridge *bridge,
                                        double *ft)
{
  const double *omega = atom->omega[i], *n = face.n;
  const double v[3] = {atom->v[i][0] - face.v[0], atom->v[i][1] - face.v[1],
                       atom->v[i][2] - face.v[2]};
  const double r = atom->radius[i];
  double normal = 0.0, tangential = 0.0;
  const int status = cb_viscous_damping(law_of(i), r, CB_PLANE, face.gap, bridge->volume,
                                        &normal, &tangential);
  if (status != CB_OK) fail(status, "viscous damping", i, face.gap, bridge->volume);
  const double gap_rate = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
  const double spin[3] = {omega[1] * n[2] - omega[2] * n[1], omega[2] * n[0] - omega[0] * n[2],
                          omega[0] * n[1] - omega[1] * n[0]};
  for (int k = 0; k < 3; k++) ft[k] = -tangential * (v[k] - gap_rate * n[k] - r * spin[k]);
  return -normal * gap_rate;
}

[[noreturn]] void FixCapillaryWall::fail(int status, const char *what, int i, double gap,
                                         double volume) const
{
  error->one(FLERR, "fix capillary/wall: {} of atom {} (type {}, radius {}) and a wall: gap {}, "
             "volume {}: {}", what, atom->tag[i], atom_type(i), atom->radius[i], gap, volume,
             cb_status_message((cb_status) status));
}

/* ----------------------------------------------------------------------
   output: 1 wall bridges, 2 their liquid, 3-5 the force their bridges exert on the walls
------------------------------------------------------------------------- */

void FixCapillaryWall::census(double &count, double &liquid_held) const
{
  count = liquid_held = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    for (int w = 0; w < nwalls; w++) {
      const cb_bridge *bridge = bridge_at(i, w);
      if (bridge->active == 0.0) continue;
      count += 1.0;
      liquid_held += bridge->volume;
    }
}

double FixCapillaryWall::compute_vector(int n)
{
  if (census_step != update->ntimestep) {
    double local[5];
    census(local[0], local[1]);
    for (int k = 0; k < 3; k++) local[2 + k] = wall_force[k];
    MPI_Allreduce(local, values, 5, MPI_DOUBLE, MPI_SUM, world);
    census_step = update->ntimestep;
  }
  return values[n];
}

/* ----------------------------------------------------------------------
   per-atom bridges: grown, copied, migrated, written to and read from restart files
------------------------------------------------------------------------- */

void FixCapillaryWall::grow_arrays(int nmax)
{
  memory->grow(state, nmax, nwalls * CB_BRIDGE_DOUBLES, "capillary/wall:state");
}

void FixCapillaryWall::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int k = 0; k < nwalls * CB_BRIDGE_DOUBLES; k++) state[j][k] = state[i][k];
}

void FixCapillaryWall::set_arrays(int i)
{
  for (int k = 0; k < nwalls * CB_BRIDGE_DOUBLES; k++) state[i][k] = 0.0;
}

int FixCapillaryWall::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < nwalls * CB_BRIDGE_DOUBLES; k++) buf[k] = state[i][k];
  return nwalls * CB_BRIDGE_DOUBLES;
}

int FixCapillaryWall::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < nwalls * CB_BRIDGE_DOUBLES; k++) state[nlocal][k] = buf[k];
  return nwalls * CB_BRIDGE_DOUBLES;
}

int FixCapillaryWall::pack_restart(int i, double *buf)
{
  // buf[0] is the count, by the convention of atom->extra
  const int n = nwalls * CB_BRIDGE_DOUBLES;
  buf[0] = n + 1;
  for (int k = 0; k < n; k++) buf[k + 1] = state[i][k];
  return n + 1;
}

void FixCapillaryWall::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  const int n = static_cast<int>(extra[nlocal][m]) - 1;
  if (n != nwalls * CB_BRIDGE_DOUBLES)
    error->one(FLERR, "fix capillary/wall: the restart file holds {} values per atom for this "
               "fix, the input's {} wall(s) need {}", n, nwalls, nwalls * CB_BRIDGE_DOUBLES);
  m++;
  for (int k = 0; k < n; k++) state[nlocal][k] = extra[nlocal][m + k];
}

int FixCapillaryWall::size_restart(int /*nlocal*/)
{
  return nwalls * CB_BRIDGE_DOUBLES + 1;
}

int FixCapillaryWall::maxsize_restart()
{
  return nwalls * CB_BRIDGE_DOUBLES + 1;
}

double FixCapillaryWall::memory_usage()
{
  return (double) atom->nmax * nwalls * CB_BRIDGE_DOUBLES * sizeof(double);
}
