/* ----------------------------------------------------------------------
   capbridge — LAMMPS binding: the liquid protocols of Richefeu 2007 (fix capillary/liquid)

   Member functions of FixCapillaryLiquid that move liquid into and out of the bridges of
   pair style gran/capillary, which it reaches through CapillaryBridges (the pair history,
   the type pairs' laws and cutoffs, the bridge events) and the pair's neighbor list:
     Protocols 2, 3 within a force evaluation (offer_liquid, called by the pair's compute()
       before its loop: update_bridges, exchange_liquid and their MPI exchange);
     Protocol 1 over the pairs of all ranks (protocol1, from distribute());
     the bridges' census (count_bridges) and the liquid released to Protocol 1's pool.
   A file of its own: the fix's other file is its command, schedule, output and restart;
   this one is the per-pair work, which walks the pair's list as the pair's loops do.
------------------------------------------------------------------------- */

#include "fix_capillary_liquid.h"

#include "capillary_bridges.h"
#include "fix_capillary_wall.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "pair.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

using namespace LAMMPS_NS;

namespace {
// the special-bond index of a neighbor entry, as the pair loop reads it (Pair::sbmask)
int sbmask(int j)
{
  return j >> SBBITS & 3;
}

}    // namespace

// Protocol 1's candidates on this rank: the wet pairs within reach, in list order
struct FixCapillaryLiquid::Protocol1Pairs {
  std::vector<double> geometry;              // r1, r2, gap per candidate
  std::vector<tagint> keys;                  // smaller tag, larger tag
  std::vector<std::pair<int, int>> where;    // i and its neighbor index jj
  // then the grain-wall candidates (geometry r1, CB_PLANE, gap; keys wall key, tag)
  struct WallEntry {
    FixCapillaryWall *fix;
    int atom, wall;
  };
  std::vector<WallEntry> walls;
  const cb_law *law = nullptr;
};

/* ----------------------------------------------------------------------
   phase 1's per-atom arrays (owned + ghost), grown with atom->nmax
------------------------------------------------------------------------- */

void FixCapillaryLiquid::grow_scratch()
{
  if (atom->nmax <= nmax_scratch) return;
  nmax_scratch = atom->nmax;
  destroy_scratch();
  memory->create(candidates, nmax_scratch, "capillary/liquid:candidates");
  memory->create(released, nmax_scratch, "capillary/liquid:released");
  memory->create(offer, nmax_scratch, "capillary/liquid:offer");
  memory->create(deposit, nmax_scratch, "capillary/liquid:deposit");
  memory->create(best_height, nmax_scratch, "capillary/liquid:best_height");
  memory->create(best_partner, nmax_scratch, "capillary/liquid:best_partner");
}

void FixCapillaryLiquid::destroy_scratch()
{
  memory->destroy(candidates);
  memory->destroy(released);
  memory->destroy(offer);
  memory->destroy(deposit);
  memory->destroy(best_height);
  memory->destroy(best_partner);
}

/* ----------------------------------------------------------------------
   Protocols 2, 3, phase 1 (the pair's compute(), before its loop): phase 2, the pair loop,
   forms new bridges with offer[] and hands Protocol 3's deposit[] to best_partner[]
------------------------------------------------------------------------- */

void FixCapillaryLiquid::offer_liquid()
{
  update_bridges();
  exchange_liquid();
  if (removing) report_removal();
}

/* ----------------------------------------------------------------------
   Protocols 2, 3, phase 1: advance every existing bridge (hold or rupture) and record,
   per atom (owned and ghost),
     released[a]      liquid a broken bridge hands to atom a (cb_protocol2_release:
                      the split in proportion to the radii, exact)
     candidates[a]    dry pairs of atom a in contact that may form a bridge now
     best_height[a], best_partner[a]   Protocol 3: atom a's lowest bridge below its centre
                      (contact height minus centre height, and the partner's tag; the
                      receiver rule and its tie-break are cb_protocol3_better's)
   With newton on a pair is seen by one rank only, which records both atoms (ghost
   entries go back to their owners by reverse communication).  With newton off a pair
   with a ghost partner is seen by both owners: each records its own atom only.
------------------------------------------------------------------------- */

void FixCapillaryLiquid::update_bridges()
{
  grow_scratch();
  const int nall = atom->nlocal + atom->nghost;
  for (int a = 0; a < nall; a++) {
    candidates[a] = released[a] = offer[a] = deposit[a] = 0.0;
    best_height[a] = 0.0;
    best_partner[a] = 0;
  }

  double **x = atom->x;
  double *radius = atom->radius;
  int *type = atom->type;
  int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const int protocol3 = mode == LIQUID_PROTOCOL3;

  NeighList *list = pair->list;
  const int inum = list->inum;
  int *ilist = list->ilist;
  int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  int **firsttouch = bridges->fix_history->firstflag;
  double **firstvalue = bridges->fix_history->firstvalue;
  double *special = force->special_lj;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    int *jlist = firstneigh[i];
    int *touch = firsttouch[i];
    double *allhistory = firstvalue[i];
    for (int jj = 0; jj < numneigh[i]; jj++) {
      int j = jlist[jj];
      if (special[sbmask(j)] == 0.0) continue;
      j &= NEIGHMASK;
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double delz = x[i][2] - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const double radsum = radius[i] + radius[j];
      // apart and flagged 0 (no bridge: see the pair's pair_force): neither a bridge to
      // advance nor a candidate (bridges form at contact)
      if (touch[jj] == 0 && cb_certainly_apart(rsq, radsum)) continue;
      cb_bridge *bridge =
          CapillaryBridges::bridge_of(&allhistory[CapillaryBridges::SIZE_BRIDGE * jj]);
      const double r = sqrt(rsq);
      const double gap = r - radsum;

      if (bridge->active != 0.0 && removing && removal_chosen(atom->tag[i], atom->tag[j]))
        remove_and_release(i, j, gap, bridge);
      else if (!cb_bridge_dry(bridge))
        advance_and_release(i, j, rsq, gap, bridge);
      if (bridge->active != 0.0) {
        if (protocol3) receive_at(i, j, delz, r);
      } else if (cb_bridge_may_form(bridge, gap) &&
                 CapillaryBridges::wet(bridges->type_pair(type[i], type[j]), mask, groupbit, i,
                                       j)) {
        candidates[i] += 1.0;
        if (newton_pair || j < nlocal) candidates[j] += 1.0;
      }
    }
  }
  for (FixCapillaryWall *wall : walls) update_wall_bridges(*wall);
}

/* ----------------------------------------------------------------------
   phase 1 for the bridges of the grains and the walls of one fix capillary/wall (owned
   grains only: a wall bridge is its grain's): removed, held or ruptured (all the liquid
   back to the grain, cb_protocol2_release with the plane), Protocol 3's receiver, the
   candidates; the fix's post_force (after the pair) forms them and gives the deposit
------------------------------------------------------------------------- */

void FixCapillaryLiquid::update_wall_bridges(FixCapillaryWall &wall)
{
  const std::vector<FixCapillaryWall::Contact> &contacts = wall.contacts();
  const double *radius = atom->radius;
  const tagint *tag = atom->tag;
  for (const FixCapillaryWall::Contact &c : contacts) {
    const int i = c.atom;
    cb_bridge *bridge = wall.bridge_at(i, c.wall);
    const long long key = wall.wall_key(c.wall);
    double volume = 0.0;
    int status = CB_OK;
    const char *what = "wall bridge update";
    if (bridge->active != 0.0 && removing && removal_chosen(tag[i], key)) {
      what = "wall bridge removal";
      status = cb_bridge_remove(c.gap, bridge, &volume);
      removed_count += 1.0;
      removed_liquid += volume;
    } else if (!cb_bridge_dry(bridge)) {
      cb_transition transition;
      status = cb_bridge_update(wall.law_of(i), radius[i], CB_PLANE, c.gap, 0.0, bridge,
                                &transition, &volume);
      if (transition == CB_BRIDGE_RUPTURED) bridges->n_ruptured += 1.0;
      else volume = 0.0;
    }
    double share_grain = 0.0, share_wall = 0.0;
    if (status == CB_OK && volume > 0.0) {
      what = "wall bridge release";
      status = cb_protocol2_release(volume, radius[i], CB_PLANE, &share_grain, &share_wall);
    }
    if (status != CB_OK)
      error->one(FLERR, "fix capillary/liquid {}: {} of atom {} (radius {}) and a wall of fix "
                 "{}: gap {}, volume {}: {}", mode_name(), what, tag[i], radius[i], wall.id,
                 c.gap, bridge->volume, cb_status_message((cb_status) status));
    released[i] += share_grain;
    if (bridge->active != 0.0) {
      if (mode == LIQUID_PROTOCOL3 &&
          cb_protocol3_better(c.offset, key, best_height[i], best_partner[i])) {
        best_height[i] = c.offset;
        best_partner[i] = (tagint) key;
      }
    } else if (c.wet && cb_bridge_may_form(bridge, c.gap)) {
      candidates[i] += 1.0;
    }
  }
}

/* ----------------------------------------------------------------------
   phase 1, a bridge: held or ruptured at this gap (or at the reach); a ruptured bridge's
   liquid is split between the two atoms (released[])
------------------------------------------------------------------------- */

void FixCapillaryLiquid::advance_and_release(int i, int j, double rsq, double gap,
                                             cb_bridge *bridge)
{
  double *radius = atom->radius;
  const int itype = atom->type[i], jtype = atom->type[j];
  const int nlocal = atom->nlocal, newton_pair = force->newton_pair;
  const CapillaryBridges::TypePair &tp = bridges->type_pair(itype, jtype);
  const int counted = CapillaryBridges::counted_once(i, j, nlocal, newton_pair, atom->tag);
  double vol = 0.0;
  cb_transition transition;
  int status = cb_bridge_update(tp.law, radius[i], radius[j], gap, 0.0, bridge, &transition, &vol);
  bridges->check_cb(error, status, "bridge update", itype, jtype, radius[i], radius[j],
                    bridge->volume, gap);
  if (transition != CB_BRIDGE_RUPTURED) {
    vol = 0.0;
    if (transition == CB_BRIDGE_HELD && CapillaryBridges::beyond_reach(rsq, gap, tp)) {
      // held beyond the reach (a volume above the one the reach was built for, a grown
      // sphere): ruptured here, before the pair leaves the neighbor list with its liquid
      vol = bridge->volume;
      *bridge = cb_bridge{};
      if (counted) bridges->n_reach += 1.0;
    }
  }
  if (vol > 0.0) {
    if (counted) bridges->n_ruptured += 1.0;
    release(i, j, vol, gap);
  }
}

/* ----------------------------------------------------------------------
   phase 1, a bridge's liquid split between its two atoms (released[]): cb_protocol2_release,
   the split in proportion to the radii, exact
------------------------------------------------------------------------- */

void FixCapillaryLiquid::release(int i, int j, double volume, double gap)
{
  double *radius = atom->radius;
  double share_i = 0.0, share_j = 0.0;
  const int status = cb_protocol2_release(volume, radius[i], radius[j], &share_i, &share_j);
  bridges->check_cb(error, status, "liquid release", atom->type[i], atom->type[j], radius[i],
                    radius[j], volume, gap);
  released[i] += share_i;
  if (force->newton_pair || j < atom->nlocal) released[j] += share_j;
}

/* ----------------------------------------------------------------------
   keyword remove (the first force evaluation after the liquid starts): is the bridge of
   the atoms (or atom and wall: FixCapillaryWall::wall_key) with IDs id1, id2 among the
   removed fraction (cb_bridge_removal_chosen: a draw from the seed and the two IDs, the
   same on every rank and for both copies of a newton-off pair)
------------------------------------------------------------------------- */

int FixCapillaryLiquid::removal_chosen(long long id1, long long id2)
{
  int chosen = 0;
  const int status = cb_bridge_removal_chosen(remove_fraction, (unsigned long long) remove_seed,
                                              id1, id2, &chosen);
  if (status != CB_OK)
    error->one(FLERR, "fix capillary/liquid: remove {} (seed {}) for the bridge of IDs {} and "
               "{} (a wall's is negative): {}", remove_fraction, remove_seed, id1, id2,
               cb_status_message((cb_status) status));
  return chosen;
}

/* ----------------------------------------------------------------------
   keyword remove, one bridge: removed (cb_bridge_remove: dry, and no bridge again while the
   contact lasts) and its liquid released as a broken bridge's (Protocol 2: to its two
   atoms; Protocol 3: their receivers, exchange_liquid)
------------------------------------------------------------------------- */

void FixCapillaryLiquid::remove_and_release(int i, int j, double gap, cb_bridge *bridge)
{
  double vol = 0.0;
  const int status = cb_bridge_remove(gap, bridge, &vol);
  bridges->check_cb(error, status, "bridge removal", atom->type[i], atom->type[j],
                    atom->radius[i], atom->radius[j], bridge->volume, gap);
  if (CapillaryBridges::counted_once(i, j, atom->nlocal, force->newton_pair, atom->tag)) {
    removed_count += 1.0;
    removed_liquid += vol;
  }
  release(i, j, vol, gap);
}

/* ----------------------------------------------------------------------
   phase 1, Protocol 3: the bridge of i and j as the receiver of each atom's share
------------------------------------------------------------------------- */

void FixCapillaryLiquid::receive_at(int i, int j, double delz, double r)
{
  double *radius = atom->radius;
  tagint *tag = atom->tag;
  // contact point on sphere a: centre + r_a (partner - centre) / r
  const double offset_i = -radius[i] * delz / r;
  if (cb_protocol3_better(offset_i, tag[j], best_height[i], best_partner[i])) {
    best_height[i] = offset_i;
    best_partner[i] = tag[j];
  }
  if (force->newton_pair || j < atom->nlocal) {
    const double offset_j = radius[j] * delz / r;
    if (cb_protocol3_better(offset_j, tag[i], best_height[j], best_partner[j])) {
      best_height[j] = offset_j;
      best_partner[j] = tag[i];
    }
  }
}

/* ----------------------------------------------------------------------
   Protocols 2, 3, the owners' bookkeeping between the two phases.
   1. newton on: ghost entries (released shares, candidate counts, receivers) are summed
      (merged) into the owners by reverse communication, so each atom's owner knows all
      of it; newton off: each owner recorded its own atoms already.
   2. the owner of atom a, the core's rule (cb_protocol_grain_step): Protocol 3 with a
      receiver: deposit[a] = released[a] (goes to that bridge); else free[a] +=
      released[a].  Then, if a has k candidates, offer[a] = free[a] / k and free[a] = 0:
      the whole free liquid is handed out, an equal part to each new contact (Richefeu's
      "the new bridge takes it" with several new contacts at once; cb_protocol2_take adds
      the two offers of a pair).
   3. forward communication gives every ghost its owner's offer, deposit and receiver, so
      that both ranks of a newton-off pair form the bridge with the same volume
      offer[i] + offer[j], and the receiving bridge (on whichever rank holds it) gets the
      deposit.
   Conservation: every released share is added to exactly one owner (1.), every offer is
   consumed by exactly one pair (counted once; both copies of a newton-off pair hold the
   same volume and the pair is counted once), and offer * candidates equals the free
   liquid up to one rounding of the division.
------------------------------------------------------------------------- */

void FixCapillaryLiquid::exchange_liquid()
{
  if (force->newton_pair) comm->reverse_comm(this);
  const int protocol3 = mode == LIQUID_PROTOCOL3;
  for (int a = 0; a < atom->nlocal; a++) {
    const int status = cb_protocol_grain_step(released[a], protocol3 && best_partner[a] != 0,
                                              candidates[a], &free_liquid[a], &deposit[a],
                                              &offer[a]);
    if (status != CB_OK)
      error->one(FLERR, "fix capillary/liquid {}: atom {}: the liquid of one step "
                 "(cb_protocol_grain_step: released {}, free {}, {} new contacts): {}",
                 mode_name(), atom->tag[a], released[a], free_liquid[a], candidates[a],
                 cb_status_message((cb_status) status));
  }
  comm->forward_comm(this);
}

/* ----------------------------------------------------------------------
   the two exchanges of exchange_liquid: reverse, the ghosts' records to their owners
   (COMM_REVERSE_SIZE values an atom); forward, the owners' offers (COMM_FORWARD_SIZE)
------------------------------------------------------------------------- */

int FixCapillaryLiquid::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int a = first; a < first + n; a++) {
    buf[m++] = candidates[a];
    buf[m++] = released[a];
    buf[m++] = best_height[a];
    buf[m++] = ubuf(best_partner[a]).d;
  }
  return m;
}

void FixCapillaryLiquid::unpack_reverse_comm(int n, int *list_, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int a = list_[k];
    candidates[a] += buf[m++];
    released[a] += buf[m++];
    const double height = buf[m++];
    const auto partner = (tagint) ubuf(buf[m++]).i;
    if (partner && cb_protocol3_better(height, partner, best_height[a], best_partner[a])) {
      best_height[a] = height;
      best_partner[a] = partner;
    }
  }
}

int FixCapillaryLiquid::pack_forward_comm(int n, int *list_, double *buf, int /*pbc_flag*/,
                                          int * /*pbc*/)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int a = list_[k];
    buf[m++] = offer[a];
    buf[m++] = deposit[a];
    buf[m++] = ubuf(best_partner[a]).d;
  }
  return m;
}

void FixCapillaryLiquid::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int a = first; a < first + n; a++) {
    offer[a] = buf[m++];
    deposit[a] = buf[m++];
    best_partner[a] = (tagint) ubuf(buf[m++]).i;
  }
}

/* ----------------------------------------------------------------------
   this rank's census of the pair history, each pair counted once over all ranks:
   out[0] bridges, out[1] liquid in bridges, out[2] formations, out[3] ruptures, out[4]
   ruptures forced at the neighbor reach, out[5] liquid released to the pool (Protocol 1);
   the events and the released liquid are reset
------------------------------------------------------------------------- */

void FixCapillaryLiquid::count_bridges(double *out)
{
  double count = 0.0, liquid = 0.0;
  NeighList *list = pair->list;
  FixNeighHistory *history = bridges->fix_history;
  if (bridges->history_size == CapillaryBridges::SIZE_BRIDGE && history && list &&
      history->firstvalue) {
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      double *allhistory = history->firstvalue[i];
      for (int jj = 0; jj < list->numneigh[i]; jj++) {
        const int j = list->firstneigh[i][jj] & NEIGHMASK;
        cb_bridge *bridge =
            CapillaryBridges::bridge_of(&allhistory[CapillaryBridges::SIZE_BRIDGE * jj]);
        if (bridge->active == 0.0 ||
            !CapillaryBridges::counted_once(i, j, atom->nlocal, force->newton_pair, atom->tag))
          continue;
        count += 1.0;
        liquid += bridge->volume;
      }
    }
  }
  for (const FixCapillaryWall *wall : walls) {
    double wall_count = 0.0, wall_liquid = 0.0;
    wall->census(wall_count, wall_liquid);
    count += wall_count;
    liquid += wall_liquid;
  }
  out[0] = count;
  out[1] = liquid;
  out[2] = bridges->n_formed;
  out[3] = bridges->n_ruptured;
  out[4] = bridges->n_reach;
  out[5] = bridges->pool_released;
  bridges->n_formed = bridges->n_ruptured = bridges->n_reach = bridges->pool_released = 0.0;
}

/* ----------------------------------------------------------------------
   the liquid of broken bridges released on all ranks since the last call, into the pool
   (collective)
------------------------------------------------------------------------- */

void FixCapillaryLiquid::collect_released()
{
  double local = 0.0, all = 0.0;
  if (bridges) {
    local = bridges->pool_released;
    bridges->pool_released = 0.0;
  }
  MPI_Allreduce(&local, &all, 1, MPI_DOUBLE, MPI_SUM, world);
  pool += all;
}

/* ----------------------------------------------------------------------
   Protocol 1 (Richefeu 2007 §2.4, eqs. 13-14) over every pair within reach.
   MPI: the candidate pairs (r1, r2, gap, the two tags) of all ranks are gathered on
   rank 0 (MPI_Gatherv), sorted by their tags and made unique (with newton off a pair
   with a ghost partner is sent by both owners), handed to cb_protocol1_distribute in
   that order — so the result does not depend on the number of ranks — and the volumes
   are scattered back (MPI_Scatterv); each rank writes them into its pair histories.
   Returns 0 on success (alpha and the largest bridge volume set), 1 when no pair can
   hold the liquid (nothing changed).
------------------------------------------------------------------------- */

int FixCapillaryLiquid::protocol1(double total, double &a, double &largest_volume)
{
  Protocol1Pairs mine;
  gather_candidates(mine);
  std::vector<double> volumes(mine.where.size() + mine.walls.size());
  double result[2] = {0.0, 0.0};    // alpha, the largest volume
  if (distribute_over_ranks(mine, total, volumes, result)) return 1;
  a = result[0];
  largest_volume = result[1];
  check_alpha(a);
  apply_volumes(mine, volumes);
  bridges->pool_released = 0.0;
  return 0;
}

/* ----------------------------------------------------------------------
   Protocol 1, step 1: this rank's wet pairs within reach, and the law of the wet type
   pairs (one law: checked by the pair's init_style)
------------------------------------------------------------------------- */

void FixCapillaryLiquid::gather_candidates(Protocol1Pairs &mine)
{
  double **x = atom->x;
  double *radius = atom->radius;
  int *type = atom->type;
  tagint *tag = atom->tag;
  NeighList *list = pair->list;
  double **firstvalue = bridges->fix_history->firstvalue;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = list->firstneigh[i][jj] & NEIGHMASK;
      const CapillaryBridges::TypePair &tp = bridges->type_pair(type[i], type[j]);
      if (!CapillaryBridges::wet(tp, atom->mask, groupbit, i, j)) continue;
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double delz = x[i][2] - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      if (rsq >= tp.cutsq) continue;
      const double gap = sqrt(rsq) - (radius[i] + radius[j]);
      // a removed bridge's pair gets no liquid while its contact lasts (keyword remove)
      const cb_bridge *bridge =
          CapillaryBridges::bridge_of(&firstvalue[i][CapillaryBridges::SIZE_BRIDGE * jj]);
      if (cb_bridge_removed_in_contact(bridge, gap)) continue;
      mine.law = tp.law;
      mine.geometry.push_back(radius[i]);
      mine.geometry.push_back(radius[j]);
      mine.geometry.push_back(gap);
      mine.keys.push_back(MIN(tag[i], tag[j]));
      mine.keys.push_back(MAX(tag[i], tag[j]));
      mine.where.emplace_back(i, jj);
    }
  }
  for (FixCapillaryWall *wall : walls) gather_wall_candidates(*wall, mine);
  if (!mine.law) {
    for (int i = 1; i <= atom->ntypes && !mine.law; i++)
      for (int j = i; j <= atom->ntypes && !mine.law; j++)
        if (bridges->wet_type_pair(i, j)) mine.law = bridges->type_pair(i, j).law;
  }
  if (!mine.law)
    error->all(FLERR, "fix capillary/liquid {}: every type pair is dry (pair_coeff volume 0): no "
               "pair can hold the liquid", mode_name());
}

/* ----------------------------------------------------------------------
   Protocol 1, step 1 for the walls of one fix capillary/wall: each wet grain (owned) within
   the rupture distance of the design volume from a wall (a bridge of at most that volume
   can hold no farther: check_alpha keeps alpha r^3 within it), its removed bridges left out
------------------------------------------------------------------------- */

void FixCapillaryLiquid::gather_wall_candidates(FixCapillaryWall &wall, Protocol1Pairs &mine)
{
  std::vector<FixCapillaryWall::Contact> near;
  const double design = reach_volume();
  wall.candidates(near, design);
  for (const FixCapillaryWall::Contact &c : near) {
    if (!c.wet || cb_bridge_removed_in_contact(wall.bridge_at(c.atom, c.wall), c.gap)) continue;
    mine.law = mine.law ? mine.law : wall.law_of(c.atom);
    mine.geometry.push_back(atom->radius[c.atom]);
    mine.geometry.push_back(CB_PLANE);
    mine.geometry.push_back(c.gap);
    mine.keys.push_back((tagint) wall.wall_key(c.wall));
    mine.keys.push_back(atom->tag[c.atom]);
    mine.walls.push_back({&wall, c.atom, c.wall});
  }
}

/* ----------------------------------------------------------------------
   Protocol 1, step 2: every rank's candidates to rank 0, distributed there, the volumes
   back (volumes[k] for this rank's candidate k; result: alpha, the largest volume).
   Returns 1 when no pair can hold the liquid.
------------------------------------------------------------------------- */

int FixCapillaryLiquid::distribute_over_ranks(const Protocol1Pairs &mine, double total,
                                              std::vector<double> &volumes, double *result)
{
  const int nprocs = comm->nprocs, me = comm->me;
  int nmine = (int) (mine.where.size() + mine.walls.size());
  std::vector<int> counts(nprocs), displs(nprocs), counts3(nprocs), displs3(nprocs),
      counts2(nprocs), displs2(nprocs);
  MPI_Gather(&nmine, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, world);
  bigint ntotal = 0;
  if (me == 0) {
    for (int p = 0; p < nprocs; p++) {
      displs[p] = (int) ntotal;
      ntotal += counts[p];
      counts3[p] = 3 * counts[p];
      displs3[p] = 3 * displs[p];
      counts2[p] = 2 * counts[p];
      displs2[p] = 2 * displs[p];
    }
    if (3 * ntotal > MAXSMALLINT)
      error->one(FLERR, "fix capillary/liquid: too many pairs for Protocol 1 on one rank");
  }
  std::vector<double> all_geometry(me == 0 ? 3 * ntotal : 0);
  std::vector<tagint> all_keys(me == 0 ? 2 * ntotal : 0);
  std::vector<double> all_volumes(me == 0 ? ntotal : 0);
  MPI_Gatherv(mine.geometry.data(), 3 * nmine, MPI_DOUBLE, all_geometry.data(), counts3.data(),
              displs3.data(), MPI_DOUBLE, 0, world);
  MPI_Gatherv(mine.keys.data(), 2 * nmine, MPI_LMP_TAGINT, all_keys.data(), counts2.data(),
              displs2.data(), MPI_LMP_TAGINT, 0, world);

  int status = CB_OK;
  if (me == 0)
    status = distribute_on_root(mine.law, all_geometry, all_keys, total, all_volumes, result);
  MPI_Bcast(&status, 1, MPI_INT, 0, world);
  MPI_Bcast(result, 2, MPI_DOUBLE, 0, world);
  if (status == CB_ERR_LIQUID) return 1;
  if (status != CB_OK)
    error->all(FLERR, "fix capillary/liquid: Protocol 1 (cb_protocol1_distribute) failed: {}",
               cb_status_message((cb_status) status));
  MPI_Scatterv(all_volumes.data(), counts.data(), displs.data(), MPI_DOUBLE, volumes.data(),
               nmine, MPI_DOUBLE, 0, world);
  return 0;
}

/* ----------------------------------------------------------------------
   Protocol 1 on rank 0: the pairs of all ranks sorted by their tags, each pair once (so
   that the result does not depend on the number of ranks), distributed by the core;
   volumes[e] for every entry e as gathered.  Returns the core's status.
------------------------------------------------------------------------- */

int FixCapillaryLiquid::distribute_on_root(const cb_law *law, const std::vector<double> &geometry,
                                           const std::vector<tagint> &keys, double total,
                                           std::vector<double> &volumes, double *result)
{
  const bigint ntotal = (bigint) volumes.size();
  std::vector<bigint> order(ntotal);
  for (bigint k = 0; k < ntotal; k++) order[k] = k;
  std::sort(order.begin(), order.end(), [&](bigint a, bigint b) {
    if (keys[2 * a] != keys[2 * b]) return keys[2 * a] < keys[2 * b];
    if (keys[2 * a + 1] != keys[2 * b + 1]) return keys[2 * a + 1] < keys[2 * b + 1];
    return a < b;
  });
  std::vector<double> r1, r2, gap;
  std::vector<bigint> unique_of(ntotal);
  for (bigint k = 0; k < ntotal; k++) {
    const bigint e = order[k];
    const bool same = k > 0 && keys[2 * e] == keys[2 * order[k - 1]] &&
        keys[2 * e + 1] == keys[2 * order[k - 1] + 1];
    if (!same) {
      r1.push_back(geometry[3 * e]);
      r2.push_back(geometry[3 * e + 1]);
      gap.push_back(geometry[3 * e + 2]);
    }
    unique_of[e] = (bigint) r1.size() - 1;
  }
  const size_t nu = r1.size();
  std::vector<double> threshold(nu), weight(nu), vol(nu);
  std::vector<size_t> sorted(nu);
  cb_protocol1_work work = {threshold.data(), weight.data(), sorted.data()};
  const int status = cb_protocol1_distribute(law, nu, r1.data(), r2.data(), gap.data(), total,
                                             work, vol.data(), &result[0]);
  if (status == CB_OK) {
    for (bigint e = 0; e < ntotal; e++) volumes[e] = vol[unique_of[e]];
    for (size_t k = 0; k < nu; k++) result[1] = MAX(result[1], vol[k]);
  }
  return status;
}

/* ----------------------------------------------------------------------
   Protocol 1, step 3: the bridges between the largest spheres of a wet type pair must
   stay within the volume the neighbor reach was built for, or pairs beyond the reach
   would be eligible
------------------------------------------------------------------------- */

void FixCapillaryLiquid::check_alpha(double a)
{
  const double *rad_max = bridges->rad_max;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (!bridges->wet_type_pair(i, j) || rad_max[i] <= 0.0 || rad_max[j] <= 0.0) continue;
      const double rg = sqrt(rad_max[i] * rad_max[j]);
      const double largest = a * rg * rg * rg;
      const double design = reach_volume();
      if (largest > design * (1.0 + 1e-12))
        error->all(FLERR, "fix capillary/liquid: Protocol 1 gives alpha = {:.6g}: a bridge between "
                   "the largest spheres of types {} {} would hold {:.6g}, more than vmax = "
                   "{:.6g} that the neighbor reach was built for; raise vmax",
                   a, i, j, largest, design);
    }
}

/* ----------------------------------------------------------------------
   Protocol 1, step 4: the volumes into this rank's pair histories; the history flag and
   the shear of a pair neither bridged nor touching cleared, as the pair loop keeps them
------------------------------------------------------------------------- */

void FixCapillaryLiquid::apply_volumes(const Protocol1Pairs &mine,
                                       const std::vector<double> &volumes)
{
  double *radius = atom->radius;
  int *type = atom->type;
  NeighList *list = pair->list;
  int **firsttouch = bridges->fix_history->firstflag;
  double **firstvalue = bridges->fix_history->firstvalue;
  for (size_t k = 0; k < mine.where.size(); k++) {
    const int i = mine.where[k].first, jj = mine.where[k].second;
    const int j = list->firstneigh[i][jj] & NEIGHMASK;
    // wet pairs: the bridge layout
    double *history = &firstvalue[i][CapillaryBridges::SIZE_BRIDGE * jj];
    cb_bridge *bridge = CapillaryBridges::bridge_of(history);
    const CapillaryBridges::TypePair &tp = bridges->type_pair(type[i], type[j]);
    const int was = bridge->active != 0.0;
    const double gap = mine.geometry[3 * k + 2];
    int status = cb_bridge_set_volume(tp.law, radius[i], radius[j], volumes[k], bridge);
    bridges->check_cb(error, status, "Protocol 1 redistribution", type[i], type[j], radius[i],
                      radius[j], volumes[k], gap);
    const int now = bridge->active != 0.0;
    const int in_contact = tp.contact_on && gap < 0.0;
    firsttouch[i][jj] = (now || in_contact) ? 1 : 0;
    if (!in_contact) {
      const int shear = CapillaryBridges::HIST_SHEAR;
      history[shear] = history[shear + 1] = history[shear + 2] = 0.0;
    }
    if (CapillaryBridges::counted_once(i, j, atom->nlocal, force->newton_pair, atom->tag)) {
      if (now && !was) bridges->n_formed += 1.0;
      if (was && !now) bridges->n_ruptured += 1.0;
    }
  }
  for (size_t k = 0; k < mine.walls.size(); k++) {
    const Protocol1Pairs::WallEntry &entry = mine.walls[k];
    const size_t e = mine.where.size() + k;
    cb_bridge *bridge = entry.fix->bridge_at(entry.atom, entry.wall);
    const int was = bridge->active != 0.0;
    const int status = cb_bridge_set_volume(entry.fix->law_of(entry.atom), radius[entry.atom],
                                            CB_PLANE, volumes[e], bridge);
    if (status != CB_OK)
      error->one(FLERR, "fix capillary/liquid protocol1: the redistribution's wall bridge of "
                 "atom {} (radius {}), fix {}: gap {}, volume {}: {}", atom->tag[entry.atom],
                 radius[entry.atom], entry.fix->id, mine.geometry[3 * e + 2], volumes[e],
                 cb_status_message((cb_status) status));
    const int now = bridge->active != 0.0;
    if (now && !was) bridges->n_formed += 1.0;
    if (was && !now) bridges->n_ruptured += 1.0;
  }
}
