/* ----------------------------------------------------------------------
   capbridge — LAMMPS binding: pair style gran/capillary

   Per pair of finite-size spheres i, j (radii r_i, r_j, centre distance r,
   gap = r - r_i - r_j, unit normal n from j to i):

   normal    F_n = f_contact - f_capillary   (repulsion > 0, force on i = F_n n)
     f_contact   = cb_contact_normal_force: k_n (-gap) + 2 alpha_n sqrt(m k_n) (-gap_rate),
                   gap < 0 only (Richefeu 2007 eqs. 2, 3; the dashpot rule: approach, both,
                   repulsive; m = m_i m_j / (m_i + m_j))
     f_capillary = cb_force(law, r_i, r_j, V, gap) while the bridge exists, else 0
   tangential spring k_t on the incremental shear displacement (history, projected
     onto the tangent plane each step), Coulomb limit (cb_contact_friction_limit)
       |f_t| <= mu max(f_contact, 0)
     Richefeu 2007 eq. 12, mu (f_n - f_n^c), with the f_n of his eq. 1 (elastic + damping +
     capillary): the contact force alone.  The contact law is the core's (capbridge.h), here
     and in single().
   bridge    the cb_bridge of the pair in the pair history (its volume, and constants the
     core derives from it: the force of a bridge in contact is not evaluated again each
     step); its transitions are the core's (cb_bridge_step, which gives the force of the
     new state too): formation at contact with liquid available, rupture beyond the law's
     rupture distance.  A liquid protocol sets a bridge's volume with
     cb_bridge_set_volume, and derive_bridges() derives every bridge again at the setup of
     each run (the coefficients may have changed since the bridges formed).

   Liquid (the volume a new bridge receives, where a broken bridge's liquid goes):
     fixed      the type pair's `volume` (or fix capillary/liquid fixed V)
     protocol1  fix capillary/liquid redistributes all liquid over all pairs every N
                steps (protocol1()); released liquid waits in a global pool
     protocol2  per-atom free liquid (fix capillary/liquid): a broken bridge's liquid is
                split in proportion to the radii and kept by the two atoms; a new contact
                takes the free liquid its atoms offer
     protocol3  as protocol2, but each atom's share goes to its lowest bridge on its
                lower hemisphere (kept as free liquid if it has none)
   The liquid is fix capillary/liquid's: it runs the protocols on the bridges through
   CapillaryBridges (capillary_bridges.h), the pair's base, and Protocols 2 and 3's phase 1
   (FixCapillaryLiquid::offer_liquid, capillary_protocols.cpp) is called by compute()
   before the pair loop, which reads its offers.
------------------------------------------------------------------------- */

// This file: the pair style itself (construction, init_style, compute() and the pair loop with
// its bridge steps, single()).  Its other jobs are member functions in files of their own:
// capillary_coeff.cpp (pair_style/pair_coeff, init_one, restart), capillary_history.cpp (the
// pair history that holds the bridges), capillary_checks.cpp (neighbor reach, radius ranges,
// time step, periodic images).

#include "pair_gran_capillary.h"
#include "fix_capillary_liquid.h"

#include "atom.h"
#include "citeme.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "fix_dummy.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>

using namespace LAMMPS_NS;

static const char cite_capbridge[] =
    "pair gran/capillary and fix capillary/liquid (capbridge):\n\n"
    "@Article{Richefeu2007,\n"
    " author = {V. Richefeu and M. S. El Youssoufi and R. Peyroux and F. Radja{\\\"\\i}},\n"
    " title = {A model of capillary cohesion for numerical simulations of 3D polydisperse\n"
    "          granular media},\n"
    " journal = {International Journal for Numerical and Analytical Methods in Geomechanics},\n"
    " year = 2007,\n"
    " doi = {10.1002/nag.674}\n"
    "}\n\n"
    "@Article{Gladkyy2014,\n"
    " author = {A. Gladkyy and R. Schwarze},\n"
    " title = {Comparison of different capillary bridge models for application in the\n"
    "          discrete element method},\n"
    " journal = {Granular Matter},\n"
    " year = 2014,\n"
    " volume = 16,\n"
    " pages = {911--920},\n"
    " doi = {10.1007/s10035-014-0527-z}\n"
    "}\n\n";

/* ---------------------------------------------------------------------- */

PairGranCapillary::PairGranCapillary(LAMMPS *lmp) : Pair(lmp)
{
  single_enable = 1;
  no_virial_fdotr_compute = 1;
  centroidstressflag = CENTROID_NOTAVAIL;
  finitecutflag = 1;
  beyond_contact = 1;                 // bridges act, and keep their history, beyond contact
  nondefault_history_transfer = 1;    // bridge state is copied, shear negated

  single_extra = SV_COUNT;
  svector = new double[SV_COUNT];

  dashpot = CB_DASHPOT_APPROACH;
  dt = update->dt;
  freeze_group_bit = 0;

  fix_liquid = nullptr;
  liquid_mode = LIQUID_FIXED;
  liquid_groupbit = 0;
  bridges_possible = 1;
  viscous_possible = 0;

  dt_warned = reach_warned = 0;
  neighprev = 0;

  if (lmp->citeme) lmp->citeme->add(cite_capbridge);

  // One instance at a time: its history fix has a fixed ID (history_id), and fix
  // capillary/liquid serves one pair style.
  if (modify->get_fix_by_id(dummy_id) || modify->get_fix_by_id(history_id(SIZE_BRIDGE)) ||
      modify->get_fix_by_id(history_id(SIZE_CONTACT)))
    error->all(FLERR, "pair gran/capillary can be used once: as the pair style, or as one "
               "sub-style of pair_style hybrid/overlay (its pair history and fix "
               "capillary/liquid belong to one instance)");
  // a placeholder keeps the fix order of the input script until init_style() puts the
  // NEIGH_HISTORY fix in its place (the same scheme as LAMMPS's granular styles)
  fix_dummy = dynamic_cast<FixDummy *>(
      modify->add_fix(dummy_id + " all DUMMY"));
}

/* ---------------------------------------------------------------------- */

PairGranCapillary::~PairGranCapillary()
{
  if (copymode) return;
  delete[] svector;
  svector = nullptr;

  if (!fix_history)
    modify->delete_fix(dummy_id);
  else
    modify->delete_fix(history_id(history_size));

  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    delete[] rad_min;
    delete[] rad_max;
  }
  for (auto *l : laws) {
    cb_law_release(l);
    delete l;
  }
}

/* ---------------------------------------------------------------------- */

void PairGranCapillary::init_style()
{
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag)
    error->all(FLERR, "Pair gran/capillary requires atom attributes radius, rmass, omega "
               "(atom_style sphere)");
  if (comm->ghost_velocity == 0)
    error->all(FLERR, "Pair gran/capillary requires ghost atoms store velocity "
               "(comm_modify vel yes)");

  dt = update->dt;

  auto freezes = modify->get_fix_by_style("^freeze");
  if (freezes.size() > 1) error->all(FLERR, "Only one fix freeze command at a time allowed");
  freeze_group_bit = freezes.empty() ? 0 : freezes.front()->groupbit;

  find_liquid();

  // The neighbor list. With liquid: a plain half list reaching the type-pair cutoff
  // (init_one), since bridges act beyond contact and the list must hold every pair up to
  // the largest rupture distance. Without (no type pair can form a bridge and none holds
  // one): the per-pair size list of LAMMPS's dry granular styles, cut at R_i + R_j + skin,
  // so that a dry scene pays for its contacts only.
  const int n = atom->ntypes;
  bridges_possible = viscous_possible = 0;
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) {
      if (setflag[i][j] &&
          (liquid_mode == LIQUID_FIXED ? design_volume(i, j) > 0.0
                                        : type_pair(i, j).volume != 0.0))
        bridges_possible = 1;
      if (setflag[i][j] && type_pair(i, j).law && type_pair(i, j).law->viscosity > 0.0)
        viscous_possible = 1;
    }
  create_history();
  held_volumes();
  for (int i = 1; i <= n; i++)
    if (held_volume[i] > 0.0) bridges_possible = 1;
  if (bridges_possible)
    neighbor->add_request(this, NeighConst::REQ_HISTORY);
  else
    neighbor->add_request(this, NeighConst::REQ_SIZE | NeighConst::REQ_HISTORY);

  radius_ranges();
}

/* ----------------------------------------------------------------------
   init_style: fix capillary/liquid (if any) and what it requires of the coefficients
------------------------------------------------------------------------- */

void PairGranCapillary::find_liquid()
{
  auto liquids = modify->get_fix_by_style("^capillary/liquid$");
  if (liquids.size() > 1) error->all(FLERR, "Only one fix capillary/liquid at a time allowed");
  fix_liquid = liquids.empty() ? nullptr : dynamic_cast<FixCapillaryLiquid *>(liquids.front());
  liquid_mode = fix_liquid ? fix_liquid->mode : LIQUID_FIXED;
  liquid_groupbit = fix_liquid ? fix_liquid->groupbit : 0;
  if (fix_liquid) fix_liquid->derive_design_volume();    // the reach of this run (init_one)

  const int n = atom->ntypes;
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) {
      if (!setflag[i][j]) continue;
      if (liquid_mode == LIQUID_FIXED) {
        if (type_pair(i, j).volume < 0.0 && !(fix_liquid && fix_liquid->fixed_volume >= 0.0))
          error->all(FLERR, "pair_coeff {} {}: no bridge volume: give 'volume V' (volume units) or "
                     "define fix capillary/liquid", i, j);
      } else if (type_pair(i, j).volume > 0.0) {
        error->all(FLERR, "pair_coeff {} {}: volume {} conflicts with fix capillary/liquid "
                   "{}: the liquid comes from the fix (only 'volume 0', a dry type pair, is "
                   "allowed)", i, j, type_pair(i, j).volume, fix_liquid->mode_name());
      }
    }
  if (liquid_mode != LIQUID_FIXED) {
    // Protocol 1 (also the initial distribution of Protocols 2, 3) is one call of the
    // core over all pairs: one law for every wet type pair
    int first = -1;
    for (int i = 1; i <= n; i++)
      for (int j = i; j <= n; j++)
        if (setflag[i][j] && type_pair(i, j).volume != 0.0) {
          const int index = type_pair(i, j).law_index;
          if (first < 0) first = index;
          else if (index != first)
            error->all(FLERR, "fix capillary/liquid {}: every wet type pair must use the same "
                       "law (Protocol 1 distributes over all pairs with one law): '{}' and '{}'",
                       fix_liquid->mode_name(), law_text[first], law_text[index]);
        }
  }
}

/* ---------------------------------------------------------------------- */

void PairGranCapillary::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (neighbor->ago == 0) {    // at setup and after every re-neighboring
    if (bridges_possible) check_periodic_images();
    check_timestep();
  }
  if (update->setupflag) derive_bridges();

  // Protocols 2, 3, phase 1, by fix capillary/liquid: the bridges advanced, the released
  // liquid handed to the atoms, the free liquid offered (read by protocol_bridge)
  if (bridges_possible && capillary_liquid_per_atom(liquid_mode)) fix_liquid->offer_liquid();
  // compiled twice: a dry run (no type pair can hold a bridge, init_style) runs a loop
  // without any bridge code, ~14 % fewer instructions in the pair loop (callgrind,
  // bench/README.md): a scene pays only for what it uses
  // and a wet run without a viscous law (viscous_possible, init_style) a loop without the
  // viscous force: its check cost ~5 % of the instructions of a wet scene's pair loop
#ifdef CAPBRIDGE_STRUCTURE_FLOOR
  // bench/'s structure floor (CMake option): the wet list and history, the dry forces
  form_bridges_and_forces<false, false>();
  return;
#endif
  if (!bridges_possible)
    form_bridges_and_forces<false, false>();
  else if (viscous_possible)
    form_bridges_and_forces<true, true>();
  else
    form_bridges_and_forces<true, false>();
}

/* ----------------------------------------------------------------------
   phase 2 (all modes): bridge formation and the forces
------------------------------------------------------------------------- */

template <bool BRIDGES, bool VISCOUS> void PairGranCapillary::form_bridges_and_forces()
{
  const int history_update = update->setupflag ? 0 : 1;
  const AtomArrays a = atom_arrays();
  double **x = a.x;
  double *radius = a.radius;
  int *type = atom->type;
  double *special = force->special_lj;
  const int per_atom = liquid_mode == LIQUID_PROTOCOL2 || liquid_mode == LIQUID_PROTOCOL3;
  // (a run that can hold bridges has the bridge layout: create_history)
  const int stride = BRIDGES ? static_cast<int>(SIZE_BRIDGE) : history_size;

  const int inum = list->inum;
  int *ilist = list->ilist;
  int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  int **firsttouch = fix_history->firstflag;
  double **firstvalue = fix_history->firstvalue;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const int itype = type[i];
    int *jlist = firstneigh[i];
    int *touch = firsttouch[i];
    double *allhistory = firstvalue[i];
    const int jnum = numneigh[i];
    for (int jj = 0;; jj++) {
      jj = skip_apart(a, i, jlist, touch, jj, jnum);
      if (jj >= jnum) break;
      int j = jlist[jj];
      const double factor_lj = special[sbmask(j)];
      j &= NEIGHMASK;
      if (factor_lj == 0.0) continue;
      PairGeometry g;
      g.del[0] = x[i][0] - x[j][0];
      g.del[1] = x[i][1] - x[j][1];
      g.del[2] = x[i][2] - x[j][2];
      g.rsq = g.del[0] * g.del[0] + g.del[1] * g.del[1] + g.del[2] * g.del[2];
      double *history = &allhistory[stride * jj];
      g.r = sqrt(g.rsq);
      g.radi = radius[i];
      g.radj = radius[j];
      g.gap = g.r - (g.radi + g.radj);
      const TypePair &tp = type_pair(itype, type[j]);
      // (a run in which no type pair can hold a bridge: the contact forces alone)
      const double capillary =
          BRIDGES ? bridge_capillary(i, j, g, tp, bridge_of(history), per_atom) : 0.0;
      pair_force<BRIDGES, VISCOUS>(a, tp, i, j, g, capillary, history, touch[jj],
                                   history_update);
    }
  }
}

/* ----------------------------------------------------------------------
   the per-atom arrays of one force evaluation
------------------------------------------------------------------------- */

PairGranCapillary::AtomArrays PairGranCapillary::atom_arrays() const
{
  AtomArrays a;
  a.x = atom->x;
  a.v = atom->v;
  a.f = atom->f;
  a.omega = atom->omega;
  a.torque = atom->torque;
  a.radius = atom->radius;
  a.rmass = atom->rmass;
  a.mask = atom->mask;
  a.nlocal = atom->nlocal;
  a.newton_pair = force->newton_pair;
  return a;
}

/* ----------------------------------------------------------------------
   the pair loop's skip to the next pair to compute, from neighbor jj of atom i (returns
   jnum when none is left).  Apart, neither touching nor bridged at the last step is the
   common case: no force, and no bridge can form (only at contact); its history is all
   zero (see pair_force), so it is neither read nor written.  A loop of its own, so that
   the compiler keeps its few values in registers: inside the pair loop they were spilled
   around the pair's work, ~48 instructions a skipped pair; this way 3 % fewer
   instructions in the whole run (callgrind, bench/README.md)
------------------------------------------------------------------------- */

int PairGranCapillary::skip_apart(const AtomArrays &a, int i, const int *jlist,
                                  const int *touch, int jj, int jnum)
{
  double **x = a.x;
  double *radius = a.radius;
  for (; jj < jnum; jj++) {
    if (touch[jj] != 0) break;
    const int k = jlist[jj] & NEIGHMASK;
    const double dx = x[i][0] - x[k][0];
    const double dy = x[i][1] - x[k][1];
    const double dz = x[i][2] - x[k][2];
    if (!cb_certainly_apart(dx * dx + dy * dy + dz * dz, radius[i] + radius[k])) break;
  }
  return jj;
}

/* ----------------------------------------------------------------------
   the capillary force of a pair of a run that can hold bridges, its bridge advanced.
   The common case, a bridge held (in contact, or a richefeu bridge stretched within its
   rupture distance), gives its force from the stored constants, inline (within the reach:
   one held beyond it is ruptured by advance_bridge).  The rest is out of line: inlined, it
   made the compiler spill the contact force code's values, ~3 % more instructions and
   time in the wet loop (bench/README.md).  Dry pairs that cannot get a bridge skip both.
------------------------------------------------------------------------- */

double PairGranCapillary::bridge_capillary(int i, int j, const PairGeometry &g,
                                           const TypePair &tp, cb_bridge *bridge, int per_atom)
{
  if (per_atom) return protocol_bridge(i, j, g.gap, tp, bridge);
  double capillary = 0.0;
  // (beyond_reach, its terms split: a bridge in contact, gap <= 0, is never beyond the design
  // rupture distance (>= 0), so the held contact path tests the cutoff alone)
  if (!(g.rsq < tp.cutsq && cb_bridge_held(tp.law, g.radi, g.radj, g.gap, bridge, &capillary) &&
        (g.gap <= 0.0 || !cb_bridge_beyond_reach(g.gap, tp.design_rupture))) &&
      (!cb_bridge_dry(bridge) || (tp.formation_volume > 0.0 && wet_pair(i, j, tp))))
    capillary = advance_bridge(i, j, g.rsq, g.gap, tp, bridge);
  return capillary;
}

/* ----------------------------------------------------------------------
   Protocols 2, 3: the bridges were advanced by the fix (offer_liquid); here a dry pair in
   contact forms one with the liquid on offer, a bridge takes its Protocol 3 deposit, and
   the capillary force is returned
------------------------------------------------------------------------- */

double PairGranCapillary::protocol_bridge(int i, int j, double gap, const TypePair &tp,
                                          cb_bridge *bridge)
{
  double *radius = atom->radius;
  tagint *tag = atom->tag;
  const int itype = atom->type[i], jtype = atom->type[j];
  const cb_law *pair_law = tp.law;
  const int protocol3 = liquid_mode == LIQUID_PROTOCOL3;
  // phase 1's result, per atom (owned and ghost): the free liquid on offer to each new
  // contact, and Protocol 3's deposit for the bridge of best_partner
  const double *offer = fix_liquid->offer, *deposit = fix_liquid->deposit;
  const tagint *best_partner = fix_liquid->best_partner;
  double capillary = 0.0;
  if (bridge->active == 0.0) {
    if (cb_bridge_may_form(bridge, gap) && wet_pair(i, j, tp)) {
      double offer_i = offer[i], offer_j = offer[j], available = 0.0;
      int status = cb_protocol2_take(&offer_i, &offer_j, &available);
      check_cb(error, status, "liquid take", itype, jtype, radius[i], radius[j], available, gap);
      if (available > 0.0) {
        cb_transition transition;
        double none = 0.0;
        status = cb_bridge_step(pair_law, radius[i], radius[j], gap, available, bridge,
                                &transition, &none, &capillary);
        check_cb(error, status, "bridge formation", itype, jtype, radius[i], radius[j],
                 available, gap);
        if (transition == CB_BRIDGE_FORMED && counted(i, j)) n_formed += 1.0;
      }
    }
  } else {
    if (protocol3) {
      double deposited = 0.0;
      if (deposit[i] > 0.0 && best_partner[i] == tag[j]) deposited += deposit[i];
      if (deposit[j] > 0.0 && best_partner[j] == tag[i]) deposited += deposit[j];
      if (deposited > 0.0) {
        const double grown = bridge->volume + deposited;
        int status = cb_bridge_set_volume(pair_law, radius[i], radius[j], grown, bridge);
        check_cb(error, status, "Protocol 3 deposit", itype, jtype, radius[i], radius[j], grown,
                 gap);
      }
    }
    int status = cb_bridge_force(pair_law, radius[i], radius[j], gap, bridge, &capillary);
    check_cb(error, status, "capillary force", itype, jtype, radius[i], radius[j],
             bridge->volume, gap);
  }
  return capillary;
}

/* ----------------------------------------------------------------------
   liquid fixed or Protocol 1: a bridge to advance (held, or ruptured), or one to form;
   returns the capillary force of its new state
------------------------------------------------------------------------- */

double PairGranCapillary::advance_bridge(int i, int j, double rsq, double gap,
                                         const TypePair &tp, cb_bridge *bridge)
{
  double *radius = atom->radius;
  const int itype = atom->type[i], jtype = atom->type[j];
  const cb_law *pair_law = tp.law;
  double capillary = 0.0;
  const double available = bridge->active != 0.0 ? 0.0 : tp.formation_volume;
  double vol = 0.0;
  cb_transition transition;
  const double before = bridge->volume;
  int status = cb_bridge_step(pair_law, radius[i], radius[j], gap, available, bridge,
                              &transition, &vol, &capillary);
  check_cb(error, status, "bridge update", itype, jtype, radius[i], radius[j],
           bridge->active != 0.0 ? bridge->volume : MAX(before, available), gap);
  if (transition == CB_BRIDGE_FORMED && counted(i, j)) n_formed += 1.0;
  if (transition == CB_BRIDGE_RUPTURED && counted(i, j)) n_ruptured += 1.0;
  if (transition != CB_BRIDGE_RUPTURED) vol = 0.0;
  if (bridge->active != 0.0 && beyond_reach(rsq, gap, tp)) {
    // held beyond the reach (a volume above the one the reach was built for, a grown
    // sphere): ruptured here, before the pair leaves the neighbor list with its liquid
    vol = bridge->volume;
    *bridge = cb_bridge{};
    capillary = 0.0;
    if (counted(i, j)) {
      n_reach += 1.0;
      n_ruptured += 1.0;
    }
  }
  if (vol > 0.0 && liquid_mode == LIQUID_PROTOCOL1 && counted(i, j)) pool_released += vol;
  return capillary;
}

/* ----------------------------------------------------------------------
   contact and tangential forces of one pair plus its capillary force (computed by the
   caller with the bridge's update); keeps the history flag
------------------------------------------------------------------------- */

template <bool BRIDGES, bool VISCOUS>
void PairGranCapillary::pair_force(const AtomArrays &a, const TypePair &tp, int i, int j,
                                   const PairGeometry &g, double capillary, double *history,
                                   int &touch, int history_update)
{
  cb_bridge *bridge = bridge_of(history);
  double *shear = &history[HIST_SHEAR];

  // The flag (LAMMPS's neighbor-history "touch") is 1 while the pair touches or holds a
  // bridge (or a removed bridge's mark, cb_bridge_dry), and a pair flagged 0 has an all-zero
  // history: cleared here with the flag, by
  // Protocol 1 the same way, and by FixNeighHistory for every pair it does not carry over
  // at re-neighboring.  The pair loops rely on it to skip flagged-0 pairs that are apart.
  const int in_contact = tp.contact_on && g.gap < 0.0;
  touch = (in_contact || (BRIDGES && !cb_bridge_dry(bridge))) ? 1 : 0;
  // the bridge's viscous force (law keyword viscosity): while a bridge exists and the
  // surfaces are apart (the core's cb_viscous_damping is 0 in overlap)
  const int viscous = VISCOUS && g.gap > 0.0 && bridge->active != 0.0 && tp.law->viscosity > 0.0;
  if (!in_contact) {
    shear[0] = shear[1] = shear[2] = 0.0;
    if (!BRIDGES || (capillary == 0.0 && !viscous)) return;
  }

  if (g.r == 0.0) coincident_atoms(i, j);
  const double rinv = 1.0 / g.r;
  double normal = 0.0;    // the normal force but the capillary, repulsive > 0
  double fs[3] = {0.0, 0.0, 0.0};
  if (in_contact) normal = contact_force(a, tp, i, j, g, rinv, shear, history_update, fs);
  // apart (gap > 0), so never with the contact force: its own relative velocity
  if (viscous) normal += viscous_force(a, tp, i, j, g, rinv, bridge->volume, fs);
  apply_pair_force(a, i, j, g, rinv, (normal - capillary) * rinv, fs);
}

/* ----------------------------------------------------------------------
   the velocity of i relative to j: vr (of the centres), the gap's rate (returned), and
   the tangential velocity at the contact point vtr (with the spheres' rotation); two steps,
   so that the contact force is evaluated between them (all at once cost the contact loop
   1-2 % more instructions: bench --compare)
------------------------------------------------------------------------- */

double PairGranCapillary::gap_rate_of(const AtomArrays &a, int i, int j, const PairGeometry &g,
                                      double rinv, double *vr)
{
  double **v = a.v;
  vr[0] = v[i][0] - v[j][0];
  vr[1] = v[i][1] - v[j][1];
  vr[2] = v[i][2] - v[j][2];
  return (vr[0] * g.del[0] + vr[1] * g.del[1] + vr[2] * g.del[2]) * rinv;
}

void PairGranCapillary::sliding_velocity(const AtomArrays &a, int i, int j, const PairGeometry &g,
                                         double rinv, const double *vr, double *vtr)
{
  double **omega = a.omega;
  const double radi = g.radi, radj = g.radj;
  const double delx = g.del[0], dely = g.del[1], delz = g.del[2];
  const double vnnr = vr[0] * delx + vr[1] * dely + vr[2] * delz;
  const double rsqinv = 1.0 / g.rsq;
  const double vt1 = vr[0] - delx * vnnr * rsqinv;
  const double vt2 = vr[1] - dely * vnnr * rsqinv;
  const double vt3 = vr[2] - delz * vnnr * rsqinv;
  const double wr1 = (radi * omega[i][0] + radj * omega[j][0]) * rinv;
  const double wr2 = (radi * omega[i][1] + radj * omega[j][1]) * rinv;
  const double wr3 = (radi * omega[i][2] + radj * omega[j][2]) * rinv;
  vtr[0] = vt1 - (delz * wr2 - dely * wr3);
  vtr[1] = vt2 - (delx * wr3 - delz * wr1);
  vtr[2] = vt3 - (dely * wr1 - delx * wr2);
}

/* ----------------------------------------------------------------------
   a pair in contact: its normal contact force (returned; Richefeu 2007 eqs. 2, 3) and the
   tangential spring's force fs (eq. 12), the spring's displacement advanced if
   history_update
------------------------------------------------------------------------- */

double PairGranCapillary::contact_force(const AtomArrays &a, const TypePair &tp, int i, int j,
                                        const PairGeometry &g, double rinv, double *shear,
                                        int history_update, double *fs)
{
  const double rsq = g.rsq, gap = g.gap;
  const double delx = g.del[0], dely = g.del[1], delz = g.del[2];
  double vr[3], vtr[3];
  const double gap_rate = gap_rate_of(a, i, j, g, rinv, vr);

  double mi = a.rmass[i], mj = a.rmass[j];
  double meff = mi * mj / (mi + mj);
  if (a.mask[i] & freeze_group_bit) meff = mj;
  if (a.mask[j] & freeze_group_bit) meff = mi;
  const double contact = cb_contact_normal_force(&tp.contact, gap, gap_rate, sqrt(meff));

  // relative tangential velocity at the contact point
  sliding_velocity(a, i, j, g, rinv, vr, vtr);
  const double vtr1 = vtr[0], vtr2 = vtr[1], vtr3 = vtr[2];
  const double rsqinv = 1.0 / rsq;

  if (history_update) {
    shear[0] += vtr1 * dt;
    shear[1] += vtr2 * dt;
    shear[2] += vtr3 * dt;
    // keep the displacement in the current tangent plane
    const double normal_part = (shear[0] * delx + shear[1] * dely + shear[2] * delz) * rsqinv;
    shear[0] -= normal_part * delx;
    shear[1] -= normal_part * dely;
    shear[2] -= normal_part * delz;
  }
  cb_contact_tangential_force(&tp.contact, cb_contact_friction_limit(&tp.contact, contact),
                              shear, fs, history_update);
  return contact;
}

/* ----------------------------------------------------------------------
   a bridge's viscous force (the core's cb_viscous_damping, its law's viscosity): the
   normal part returned (repulsive > 0 while the gap closes), the tangential part, against
   the sliding at the contact point, added to fs
------------------------------------------------------------------------- */

double PairGranCapillary::viscous_force(const AtomArrays &a, const TypePair &tp, int i, int j,
                                        const PairGeometry &g, double rinv, double volume,
                                        double *fs)
{
  double vr[3], vtr[3];
  const double gap_rate = gap_rate_of(a, i, j, g, rinv, vr);
  sliding_velocity(a, i, j, g, rinv, vr, vtr);
  double normal = 0.0, tangential = 0.0;
  const int status = cb_viscous_damping(tp.law, g.radi, g.radj, g.gap, volume, &normal,
                                        &tangential);
  if (status != CB_OK)
    error->one(FLERR, "pair gran/capillary: atoms {} and {}: no viscous force for radii {} "
               "and {}, gap {}, bridge volume {}: {}", atom->tag[i], atom->tag[j], g.radi,
               g.radj, g.gap, volume, cb_status_message((cb_status) status));
  for (int k = 0; k < 3; k++) fs[k] -= tangential * vtr[k];
  return -normal * gap_rate;
}

/* ----------------------------------------------------------------------
   a pair's force on i and j: ccel along del (the normal force over r; rinv = 1 / r), fs at
   the contact point (with its torques), and the tally
------------------------------------------------------------------------- */

void PairGranCapillary::apply_pair_force(const AtomArrays &a, int i, int j,
                                         const PairGeometry &g, double rinv, double ccel,
                                         const double *fs)
{
  double **f = a.f;
  double **torque = a.torque;
  const double delx = g.del[0], dely = g.del[1], delz = g.del[2];
  const double fs1 = fs[0], fs2 = fs[1], fs3 = fs[2];
  const double radi = g.radi, radj = g.radj;
  const double fx = delx * ccel + fs1;
  const double fy = dely * ccel + fs2;
  const double fz = delz * ccel + fs3;
  f[i][0] += fx;
  f[i][1] += fy;
  f[i][2] += fz;
  const double tor1 = rinv * (dely * fs3 - delz * fs2);
  const double tor2 = rinv * (delz * fs1 - delx * fs3);
  const double tor3 = rinv * (delx * fs2 - dely * fs1);
  torque[i][0] -= radi * tor1;
  torque[i][1] -= radi * tor2;
  torque[i][2] -= radi * tor3;
  if (a.newton_pair || j < a.nlocal) {
    f[j][0] -= fx;
    f[j][1] -= fy;
    f[j][2] -= fz;
    torque[j][0] -= radj * tor1;
    torque[j][1] -= radj * tor2;
    torque[j][2] -= radj * tor3;
  }
  if (evflag) ev_tally_xyz(i, j, a.nlocal, a.newton_pair, 0.0, 0.0, fx, fy, fz, delx, dely, delz);
}

/* ----------------------------------------------------------------------
   the rules of CapillaryBridges (shared with the fix's protocols) on this pair's atoms;
   here, beside the loops that call them, so that they inline there
------------------------------------------------------------------------- */

int PairGranCapillary::counted(int i, int j) const
{
  return counted_once(i, j, atom->nlocal, force->newton_pair, atom->tag);
}

int PairGranCapillary::wet_pair(int i, int j, const TypePair &tp) const
{
  // the atoms' masks read only with a fix (liquid_groupbit 0: none): this runs for every
  // pair in contact without a bridge
  if (tp.volume == 0.0) return 0;
  return !liquid_groupbit || wet(tp, atom->mask, liquid_groupbit, i, j);
}

// two atoms at distance 0 have no contact normal: stop before their NaN force is applied
// (LAMMPS printed a NaN pressure at step 0, then the error of the next step's gap)
void PairGranCapillary::coincident_atoms(int i, int j)
{
  error->one(FLERR, "pair gran/capillary: atoms {} and {} are at the same position ({}, {}, {}): "
             "a pair at distance 0 has no contact normal; move or delete one of them (e.g. "
             "delete_atoms overlap)", atom->tag[i], atom->tag[j], atom->x[i][0], atom->x[i][1],
             atom->x[i][2]);
}

/* ---------------------------------------------------------------------- */

double PairGranCapillary::single(int i, int j, int itype, int jtype, double rsq,
                                 double /*factor_coul*/, double /*factor_lj*/, double &fforce)
{
  double *radius = atom->radius;
  const double radi = radius[i], radj = radius[j];
  const double r = sqrt(rsq);
  const double gap = r - (radi + radj);
  double negate = 1.0;
  double *history = find_history(i, j, &negate);

  double vol = 0.0, active = 0.0, capillary = 0.0;
  if (history && history_size == SIZE_BRIDGE) {
    cb_bridge *bridge = bridge_of(history);
    active = bridge->active;
    vol = bridge->volume;
    int status = cb_bridge_force(law(itype, jtype), radi, radj, gap, bridge, &capillary);
    check_cb(error, status, "capillary force (single)", itype, jtype, radi, radj, vol, gap);
  }

  double contact = 0.0, tangential = 0.0;
  if (type_pair(itype, jtype).contact_on && gap < 0.0) {
    double **x = atom->x, **v = atom->v;
    const double delx = x[i][0] - x[j][0];
    const double dely = x[i][1] - x[j][1];
    const double delz = x[i][2] - x[j][2];
    const double vnnr =
        (v[i][0] - v[j][0]) * delx + (v[i][1] - v[j][1]) * dely + (v[i][2] - v[j][2]) * delz;
    const double gap_rate = vnnr * (1.0 / r);    // rounded as in pair_force
    double mi = atom->rmass[i], mj = atom->rmass[j];
    double meff = mi * mj / (mi + mj);
    if (atom->mask[i] & freeze_group_bit) meff = mj;
    if (atom->mask[j] & freeze_group_bit) meff = mi;
    const cb_contact_law &law_contact = type_pair(itype, jtype).contact;
    contact = cb_contact_normal_force(&law_contact, gap, gap_rate, sqrt(meff));
    if (history) {
      // the spring's force as the pair loop gives it this step (no update of the history)
      double shear[3] = {history[HIST_SHEAR], history[HIST_SHEAR + 1], history[HIST_SHEAR + 2]};
      double fs[3];
      cb_contact_tangential_force(&law_contact, cb_contact_friction_limit(&law_contact, contact),
                                  shear, fs, 0);
      tangential = sqrt(fs[0] * fs[0] + fs[1] * fs[1] + fs[2] * fs[2]);
    }
  }
  (void) negate;

  fforce = (contact - capillary) / r;
  svector[SV_CAPILLARY_FORCE] = capillary;
  svector[SV_GAP] = gap;
  svector[SV_VOLUME] = active != 0.0 ? vol : 0.0;
  svector[SV_BRIDGE] = active != 0.0 ? 1.0 : 0.0;
  svector[SV_R1] = radi;
  svector[SV_R2] = radj;
  svector[SV_CONTACT_FORCE] = contact;
  svector[SV_TANGENTIAL_FORCE] = tangential;
  return 0.0;
}

/* ---------------------------------------------------------------------- */

void PairGranCapillary::reset_dt()
{
  dt = update->dt;
}
