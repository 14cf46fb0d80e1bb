/* ----------------------------------------------------------------------
   capbridge — LAMMPS binding: the liquid protocols of Richefeu 2007

   Protocols 2 and 3 within a force evaluation (update_bridges, exchange_liquid and their
   MPI exchange), Protocol 1 over all ranks, and the census of the bridges.
------------------------------------------------------------------------- */

#include "pair_gran_capillary.h"
#include "fix_capillary_liquid.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

using namespace LAMMPS_NS;

namespace {
enum { REVERSE_EVENTS = 1, FORWARD_OFFERS = 2 };

// Does a contact at `offset` (contact height minus centre height) beat the current
// receiver?  The rule is cb_protocol3_receiver's (the lowest contact strictly below the
// centre); equal heights go to the smaller partner tag so that the choice does not
// depend on the order in which ranks and neighbor lists present the bridges.
bool better_receiver(double offset, tagint partner, double best_offset, tagint best_partner)
{
  double heights[2];
  size_t n = 0;
  if (best_partner) heights[n++] = best_offset;
  heights[n++] = offset;
  long index = -1;
  if (cb_protocol3_receiver(0.0, heights, n, &index) != CB_OK) return false;
  if (index < 0) return false;
  if (n == 1) return true;
  if (index == 1) return true;
  return offset == best_offset && partner < best_partner;
}
}    // namespace

/* ---------------------------------------------------------------------- */

void PairGranCapillary::grow_scratch()
{
  if (atom->nmax <= nmax_scratch) return;
  nmax_scratch = atom->nmax;
  memory->destroy(candidates);
  memory->destroy(released);
  memory->destroy(offer);
  memory->destroy(deposit);
  memory->destroy(best_height);
  memory->destroy(best_partner);
  memory->create(candidates, nmax_scratch, "pair:candidates");
  memory->create(released, nmax_scratch, "pair:released");
  memory->create(offer, nmax_scratch, "pair:offer");
  memory->create(deposit, nmax_scratch, "pair:deposit");
  memory->create(best_height, nmax_scratch, "pair:best_height");
  memory->create(best_partner, nmax_scratch, "pair:best_partner");
}

/* ----------------------------------------------------------------------
   Protocols 2, 3, phase 1: advance every existing bridge (hold or rupture) and record,
   per atom (owned and ghost),
     released[a]      liquid a broken bridge hands to atom a (cb_protocol2_release:
                      the split in proportion to the radii, exact)
     candidates[a]    dry pairs of atom a in contact that may form a bridge now
     best_height[a], best_partner[a]   Protocol 3: atom a's lowest bridge below its centre
                      (contact height minus centre height, and the partner's tag)
   With newton on a pair is seen by one rank only, which records both atoms (ghost
   entries go back to their owners by reverse communication).  With newton off a pair
   with a ghost partner is seen by both owners: each records its own atom only.
------------------------------------------------------------------------- */

void PairGranCapillary::update_bridges()
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
  tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const int protocol3 = liquid_mode == LIQUID_PROTOCOL3;

  const int inum = list->inum;
  int *ilist = list->ilist;
  int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  int **firsttouch = fix_history->firstflag;
  double **firstvalue = fix_history->firstvalue;
  double *special = force->special_lj;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const int itype = type[i];
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
      // apart and flagged 0 (no bridge: see pair_force): neither a bridge to advance nor a
      // candidate (bridges form at contact)
      if (touch[jj] == 0 && cb_certainly_apart(rsq, radsum)) continue;
      const int jtype = type[j];
      double *history = &allhistory[SIZE_BRIDGE * jj];
      cb_bridge *bridge = bridge_of(history);
      const double r = sqrt(rsq);
      const double gap = r - radsum;

      if (bridge->active != 0.0) {
        double vol = 0.0;
        cb_transition transition;
        int status = cb_bridge_update(type_pair(itype, jtype).law, radius[i], radius[j], gap, 0.0,
                                      bridge, &transition, &vol);
        check_cb(status, "bridge update", itype, jtype, radius[i], radius[j],
                 bridge->volume, gap);
        if (transition != CB_BRIDGE_RUPTURED) {
          vol = 0.0;
          if (rsq >= type_pair(itype, jtype).cutsq) {
            // held beyond the reach (a volume above the one the reach was built for):
            // ruptured here, before the pair leaves the neighbor list with its liquid
            vol = bridge->volume;
            *bridge = cb_bridge{};
            if (counted(i, j)) n_reach += 1.0;
          }
        }
        if (vol > 0.0) {
          if (counted(i, j)) n_ruptured += 1.0;
          double share_i = 0.0, share_j = 0.0;
          int status = cb_protocol2_release(vol, radius[i], radius[j], &share_i, &share_j);
          check_cb(status, "liquid release", itype, jtype, radius[i], radius[j], vol, gap);
          released[i] += share_i;
          if (newton_pair || j < nlocal) released[j] += share_j;
        }
      }
      if (bridge->active != 0.0) {
        if (protocol3) {
          // contact point on sphere a: centre + r_a (partner - centre) / r
          const double offset_i = -radius[i] * delz / r;
          if (better_receiver(offset_i, tag[j], best_height[i], best_partner[i])) {
            best_height[i] = offset_i;
            best_partner[i] = tag[j];
          }
          if (newton_pair || j < nlocal) {
            const double offset_j = radius[j] * delz / r;
            if (better_receiver(offset_j, tag[i], best_height[j], best_partner[j])) {
              best_height[j] = offset_j;
              best_partner[j] = tag[i];
            }
          }
        }
      } else if (gap <= 0.0 && wet_pair(i, j, type_pair(itype, jtype))) {
        candidates[i] += 1.0;
        if (newton_pair || j < nlocal) candidates[j] += 1.0;
      }
    }
  }
}

/* ----------------------------------------------------------------------
   Protocols 2, 3, the owners' bookkeeping between the two phases.
   1. newton on: ghost entries (released shares, candidate counts, receivers) are summed
      (merged) into the owners by reverse communication, so each atom's owner knows all
      of it; newton off: each owner recorded its own atoms already.
   2. the owner of atom a: Protocol 3 with a receiver: deposit[a] = released[a] (goes to
      that bridge); else free[a] += released[a].  Then, if a has candidates,
      offer[a] = free[a] / candidates[a] and free[a] = 0: the whole free liquid is handed
      out, an equal part to each new contact (Richefeu's "the new bridge takes it" with
      several new contacts at once; cb_protocol2_take adds the two offers of a pair).
   3. forward communication gives every ghost its owner's offer, deposit and receiver, so
      that both ranks of a newton-off pair form the bridge with the same volume
      offer[i] + offer[j], and the receiving bridge (on whichever rank holds it) gets the
      deposit.
   Conservation: every released share is added to exactly one owner (1.), every offer is
   consumed by exactly one pair (counted once; both copies of a newton-off pair hold the
   same volume and the pair is counted once), and offer * candidates equals the free
   liquid up to one rounding of the division.
------------------------------------------------------------------------- */

void PairGranCapillary::exchange_liquid()
{
  if (force->newton_pair) {
    commflag = REVERSE_EVENTS;
    comm->reverse_comm(this);
  }
  double *free_liquid = fix_liquid->free_liquid;
  const int protocol3 = liquid_mode == LIQUID_PROTOCOL3;
  for (int a = 0; a < atom->nlocal; a++) {
    if (released[a] > 0.0) {
      if (protocol3 && best_partner[a] != 0)
        deposit[a] = released[a];
      else
        free_liquid[a] += released[a];
    }
    if (candidates[a] > 0.0 && free_liquid[a] > 0.0) {
      offer[a] = free_liquid[a] / candidates[a];
      free_liquid[a] = 0.0;
    } else
      offer[a] = 0.0;
  }
  commflag = FORWARD_OFFERS;
  comm->forward_comm(this);
}

/* ---------------------------------------------------------------------- */

int PairGranCapillary::pack_reverse_comm(int n, int first, double *buf)
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

void PairGranCapillary::unpack_reverse_comm(int n, int *list_, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int a = list_[k];
    candidates[a] += buf[m++];
    released[a] += buf[m++];
    const double height = buf[m++];
    const auto partner = (tagint) ubuf(buf[m++]).i;
    if (partner && better_receiver(height, partner, best_height[a], best_partner[a])) {
      best_height[a] = height;
      best_partner[a] = partner;
    }
  }
}

int PairGranCapillary::pack_forward_comm(int n, int *list_, double *buf, int /*pbc_flag*/,
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

void PairGranCapillary::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int a = first; a < first + n; a++) {
    offer[a] = buf[m++];
    deposit[a] = buf[m++];
    best_partner[a] = (tagint) ubuf(buf[m++]).i;
  }
}

/* ----------------------------------------------------------------------
   census for fix capillary/liquid (this rank; see the header)
------------------------------------------------------------------------- */

void PairGranCapillary::census(double *out)
{
  double bridges = 0.0, liquid = 0.0;
  if (history_size == SIZE_BRIDGE && fix_history && list && fix_history->firstvalue) {
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      double *allhistory = fix_history->firstvalue[i];
      for (int jj = 0; jj < list->numneigh[i]; jj++) {
        const int j = list->firstneigh[i][jj] & NEIGHMASK;
        cb_bridge *bridge = bridge_of(&allhistory[SIZE_BRIDGE * jj]);
        if (bridge->active == 0.0 || !counted(i, j)) continue;
        bridges += 1.0;
        liquid += bridge->volume;
      }
    }
  }
  out[0] = bridges;
  out[1] = liquid;
  out[2] = n_formed;
  out[3] = n_ruptured;
  out[4] = n_reach;
  out[5] = pool_released;
  n_formed = n_ruptured = n_reach = pool_released = 0.0;
}

/* ----------------------------------------------------------------------
   Protocol 1 (Richefeu 2007 §2.4, eqs. 13-14) over every pair within reach.
   MPI: the candidate pairs (r1, r2, gap, the two tags) of all ranks are gathered on
   rank 0 (MPI_Gatherv), sorted by their tags and made unique (with newton off a pair
   with a ghost partner is sent by both owners), handed to cb_protocol1_distribute in
   that order — so the result does not depend on the number of ranks — and the volumes
   are scattered back (MPI_Scatterv); each rank writes them into its pair histories.
------------------------------------------------------------------------- */

int PairGranCapillary::protocol1(double total_liquid, double &alpha, double &largest_volume)
{
  double **x = atom->x;
  double *radius = atom->radius;
  int *type = atom->type;
  tagint *tag = atom->tag;

  std::vector<double> geometry;    // r1, r2, gap per candidate
  std::vector<tagint> keys;        // smaller tag, larger tag
  std::vector<std::pair<int, int>> where;
  const cb_law *the_law = nullptr;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = list->firstneigh[i][jj] & NEIGHMASK;
      const int itype = type[i], jtype = type[j];
      if (!wet_pair(i, j, type_pair(itype, jtype))) continue;
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double delz = x[i][2] - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      if (rsq >= cutsq[itype][jtype]) continue;
      the_law = law(itype, jtype);
      geometry.push_back(radius[i]);
      geometry.push_back(radius[j]);
      geometry.push_back(sqrt(rsq) - (radius[i] + radius[j]));
      keys.push_back(MIN(tag[i], tag[j]));
      keys.push_back(MAX(tag[i], tag[j]));
      where.emplace_back(i, jj);
    }
  }
  // the law of the wet type pairs (one law: checked in init_style)
  if (!the_law) {
    for (int i = 1; i <= atom->ntypes && !the_law; i++)
      for (int j = i; j <= atom->ntypes && !the_law; j++)
        if (setflag[i][j] && type_pair(i, j).volume != 0.0) the_law = law(i, j);
  }
  if (!the_law)
    error->all(FLERR, "fix capillary/liquid {}: every type pair is dry (pair_coeff volume 0): no "
               "pair can hold the liquid", fix_liquid->mode_name());

  const int nprocs = comm->nprocs, me = comm->me;
  int nmine = (int) where.size();
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
  MPI_Gatherv(geometry.data(), 3 * nmine, MPI_DOUBLE, all_geometry.data(), counts3.data(),
              displs3.data(), MPI_DOUBLE, 0, world);
  MPI_Gatherv(keys.data(), 2 * nmine, MPI_LMP_TAGINT, all_keys.data(), counts2.data(),
              displs2.data(), MPI_LMP_TAGINT, 0, world);

  int status = CB_OK;
  double result[2] = {0.0, 0.0};
  if (me == 0) {
    std::vector<bigint> order(ntotal);
    for (bigint k = 0; k < ntotal; k++) order[k] = k;
    std::sort(order.begin(), order.end(), [&](bigint a, bigint b) {
      if (all_keys[2 * a] != all_keys[2 * b]) return all_keys[2 * a] < all_keys[2 * b];
      if (all_keys[2 * a + 1] != all_keys[2 * b + 1])
        return all_keys[2 * a + 1] < all_keys[2 * b + 1];
      return a < b;
    });
    std::vector<double> r1, r2, gap;
    std::vector<bigint> unique_of(ntotal);
    for (bigint k = 0; k < ntotal; k++) {
      const bigint e = order[k];
      const bool same = k > 0 && all_keys[2 * e] == all_keys[2 * order[k - 1]] &&
          all_keys[2 * e + 1] == all_keys[2 * order[k - 1] + 1];
      if (!same) {
        r1.push_back(all_geometry[3 * e]);
        r2.push_back(all_geometry[3 * e + 1]);
        gap.push_back(all_geometry[3 * e + 2]);
      }
      unique_of[e] = (bigint) r1.size() - 1;
    }
    const size_t nu = r1.size();
    std::vector<double> threshold(nu), weight(nu), vol(nu);
    std::vector<size_t> sorted(nu);
    cb_protocol1_work work = {threshold.data(), weight.data(), sorted.data()};
    status = cb_protocol1_distribute(the_law, nu, r1.data(), r2.data(), gap.data(), total_liquid,
                                     work, vol.data(), &result[0]);
    if (status == CB_OK) {
      for (bigint e = 0; e < ntotal; e++) all_volumes[e] = vol[unique_of[e]];
      for (size_t k = 0; k < nu; k++) result[1] = MAX(result[1], vol[k]);
    }
  }
  MPI_Bcast(&status, 1, MPI_INT, 0, world);
  MPI_Bcast(result, 2, MPI_DOUBLE, 0, world);
  if (status == CB_ERR_LIQUID) return 1;
  if (status != CB_OK)
    error->all(FLERR, "fix capillary/liquid: Protocol 1 (cb_protocol1_distribute) failed: {}",
               cb_status_message((cb_status) status));

  std::vector<double> mine(nmine);
  MPI_Scatterv(all_volumes.data(), counts.data(), displs.data(), MPI_DOUBLE, mine.data(), nmine,
               MPI_DOUBLE, 0, world);

  alpha = result[0];
  largest_volume = result[1];

  // the bridges between the largest spheres of a wet type pair must stay within the
  // volume the neighbor reach was built for, or pairs beyond the reach would be eligible
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (!setflag[i][j] || type_pair(i, j).volume == 0.0 || rad_max[i] <= 0.0 ||
          rad_max[j] <= 0.0)
        continue;
      const double rg = sqrt(rad_max[i] * rad_max[j]);
      const double largest = alpha * rg * rg * rg;
      const double design = design_volume(i, j);
      if (largest > design * (1.0 + 1e-12))
        error->all(FLERR, "fix capillary/liquid: Protocol 1 gives alpha = {:.6g}: a bridge between "
                   "the largest spheres of types {} {} would hold {:.6g}, more than vmax = "
                   "{:.6g} that the neighbor reach was built for; raise vmax",
                   alpha, i, j, largest, design);
    }

  int **firsttouch = fix_history->firstflag;
  double **firstvalue = fix_history->firstvalue;
  for (int k = 0; k < nmine; k++) {
    const int i = where[k].first, jj = where[k].second;
    const int j = list->firstneigh[i][jj] & NEIGHMASK;
    double *history = &firstvalue[i][SIZE_BRIDGE * jj];    // wet pairs: the bridge layout
    cb_bridge *bridge = bridge_of(history);
    const int was = bridge->active != 0.0;
    const double gap = geometry[3 * k + 2];
    int status = cb_bridge_set_volume(law(type[i], type[j]), radius[i], radius[j], mine[k],
                                      bridge);
    check_cb(status, "Protocol 1 redistribution", type[i], type[j], radius[i], radius[j],
             mine[k], gap);
    const int now = bridge->active != 0.0;
    const int in_contact = type_pair(type[i], type[j]).contact_on && gap < 0.0;
    firsttouch[i][jj] = (now || in_contact) ? 1 : 0;
    if (!in_contact) history[HIST_SHEAR] = history[HIST_SHEAR + 1] = history[HIST_SHEAR + 2] = 0.0;
    if (counted(i, j)) {
      if (now && !was) n_formed += 1.0;
      if (was && !now) n_ruptured += 1.0;
    }
  }
  pool_released = 0.0;
  return 0;
}
