/* ----------------------------------------------------------------------
   capbridge — LAMMPS binding: pair style gran/capillary, the pair history

   Member functions of PairGranCapillary that keep its bridges: every pair's tangential
   displacement and cb_bridge live in a fix NEIGH_HISTORY (layouts SIZE_CONTACT and
   SIZE_BRIDGE, pair_gran_capillary.h).  Here: the fix's creation and widening between runs,
   the largest bridges that exist (for the reach), the bridges derived again at each setup,
   the transfer to the partner and the look-up of one pair's history for single().
   A file of its own: the history is state the pair loop only reads and writes in place.
------------------------------------------------------------------------- */

#include "pair_gran_capillary.h"

#include "atom.h"
#include "error.h"
#include "fix_neigh_history.h"
#include "modify.h"
#include "neigh_list.h"

#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace {
// FixNeighHistory::pack_exchange's layout of one atom: the number of partners, then per
// partner its tag and its `size` values.  Where partner p's entry (its tag) starts:
int packed_entry(int partner, int size)
{
  return 1 + (1 + size) * partner;
}
}    // namespace

/* ----------------------------------------------------------------------
   the pair history: one NEIGH_HISTORY fix per layout ID, so that a restart file's per-atom
   history is handed (by ID) only to a fix of its own layout
------------------------------------------------------------------------- */

std::string PairGranCapillary::history_id(int size) const
{
  // Not Pair::instance_me, a count of pair styles made in this process that `clear` does
  // not reset: after `clear` and `read_restart` the history would not be handed back (the
  // bridges lost).  The 0 is the count of the first pair style, the ID restart files
  // written before carry.  One instance at a time (the constructor).
  return fmt::format("NEIGH_HISTORY_CAPILLARY{}0", size == SIZE_CONTACT ? "_CONTACT" : "");
}

/* ----------------------------------------------------------------------
   at the first init, the NEIGH_HISTORY fix takes the placeholder's place in the fix list,
   with the layout this run needs (or a restart file's); a later run that can hold bridges
   widens a contact layout.  A dry scene's pairs carry 3 values instead of 10: the liquid-off
   side of the benchmark x0.91-0.94 (bench/README.md).
------------------------------------------------------------------------- */

void PairGranCapillary::create_history()
{
  if (fix_history == nullptr) {
    if (history_size == 0) history_size = bridges_possible ? SIZE_BRIDGE : SIZE_CONTACT;
    auto cmd = fmt::format("{} all NEIGH_HISTORY {}", history_id(history_size), history_size);
    fix_history = dynamic_cast<FixNeighHistory *>(modify->replace_fix(
        dummy_id, cmd, 1));
    fix_history->pair = this;
  }
  fix_history =
      dynamic_cast<FixNeighHistory *>(modify->get_fix_by_id(history_id(history_size)));
  if (!fix_history) error->all(FLERR, "Pair gran/capillary: could not find its NEIGH_HISTORY fix");
  if (bridges_possible && history_size == SIZE_CONTACT) widen_history();
}

/* ----------------------------------------------------------------------
   contact layout -> bridge layout, between two runs: a NEIGH_HISTORY fix of the bridge
   layout replaces the contact one and takes every pair's tangential displacement, its
   bridge values zero (no pair held a bridge).  The values go through the fixes' own
   per-atom exchange packing (pack_exchange, unpack_exchange), whose per-atom partner
   arrays hold the history between runs (FixNeighHistory::post_run); this rank's atoms only,
   as an atom migration would move them.
------------------------------------------------------------------------- */

void PairGranCapillary::widen_history()
{
  const int nlocal = atom->nlocal;
  const int maxpartner = fix_history->get_maxpartner();
  std::vector<double> narrow(packed_entry(maxpartner, SIZE_CONTACT));
  std::vector<double> wide;
  std::vector<std::vector<double>> packed(nlocal);
  for (int i = 0; i < nlocal; i++) {
    const int length = fix_history->pack_exchange(i, narrow.data());
    const int npartner = static_cast<int>(narrow[0]);
    if (length != packed_entry(npartner, SIZE_CONTACT))
      error->one(FLERR, "pair gran/capillary: atom {} has a pair history of {} values, not "
                 "the {} of its {} partners", atom->tag[i], length,
                 packed_entry(npartner, SIZE_CONTACT), npartner);
    wide.assign(packed_entry(npartner, SIZE_BRIDGE), 0.0);
    wide[0] = narrow[0];
    for (int n = 0; n < npartner; n++) {
      const double *from = &narrow[packed_entry(n, SIZE_CONTACT)];
      double *to = &wide[packed_entry(n, SIZE_BRIDGE)];
      for (int k = 0; k < 1 + SIZE_CONTACT; k++) to[k] = from[k];    // partner tag, shear
    }
    packed[i] = wide;
  }

  auto cmd = fmt::format("{} all NEIGH_HISTORY {}", history_id(SIZE_BRIDGE), (int) SIZE_BRIDGE);
  fix_history = dynamic_cast<FixNeighHistory *>(
      modify->replace_fix(history_id(SIZE_CONTACT), cmd, 1));
  fix_history->pair = this;
  history_size = SIZE_BRIDGE;
  fix_history->init();    // its partner pages, which unpack_exchange fills
  for (int i = 0; i < nlocal; i++) fix_history->unpack_exchange(i, packed[i].data());
  // an atom may change ranks at the setup before the fix's first pre_exchange sizes this
  fix_history->maxexchange = packed_entry(maxpartner, SIZE_BRIDGE);
}

/* ----------------------------------------------------------------------
   the largest volume of the bridges that exist, per type of the atoms holding them, over
   all ranks (held_volume[type]).  The next run's reach covers them (init_one): a volume
   lowered between two runs applies to new bridges, and a bridge of the old volume keeps
   its own rupture distance.  Were the reach built for the new volume only, the neighbor
   list of the setup would drop such a bridge, and its liquid, if it is already stretched
   beyond the new cutoff plus the skin.  Read from the pair history as it stands between
   runs, the fix's per-atom partner arrays (FixNeighHistory::post_run), through its
   exchange packing; a bridge is recorded on both of its atoms.
------------------------------------------------------------------------- */

void PairGranCapillary::held_volumes()
{
  const int n = atom->ntypes;
  std::vector<double> local(n + 1, 0.0);
  held_volume.assign(n + 1, 0.0);
  if (history_size == SIZE_BRIDGE) {
    int *type = atom->type;
    std::vector<double> packed(packed_entry(fix_history->get_maxpartner(), SIZE_BRIDGE));
    for (int i = 0; i < atom->nlocal; i++) {
      fix_history->pack_exchange(i, packed.data());
      const int npartner = static_cast<int>(packed[0]);
      for (int p = 0; p < npartner; p++) {
        // after the partner's tag, its values
        const cb_bridge *bridge = bridge_of(&packed[packed_entry(p, SIZE_BRIDGE) + 1]);
        if (bridge->active != 0.0) local[type[i]] = MAX(local[type[i]], bridge->volume);
      }
    }
  }
  MPI_Allreduce(local.data(), held_volume.data(), n + 1, MPI_DOUBLE, MPI_MAX, world);
}

/* ----------------------------------------------------------------------
   at the setup of each run, where a restart file's pair history first reaches the pair
   loop: every stored bridge state checked (cb_bridge_check_state), once, so that the held
   path of the loop (cb_bridge_held) reads only the fields it uses; and every bridge's
   constants (cb_bridge) derived again under the current coefficients, which pair_coeff may
   have changed since the last run, or which a restart file does not hold (bridges read
   from it keep their volume).  Between setups the states change only by the core's calls,
   which keep a valid state valid.
------------------------------------------------------------------------- */

void PairGranCapillary::derive_bridges()
{
  if (history_size != SIZE_BRIDGE) return;    // no pair has held a bridge
  double *radius = atom->radius;
  int *type = atom->type;
  int **firsttouch = fix_history->firstflag;
  double **firstvalue = fix_history->firstvalue;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      if (firsttouch[i][jj] == 0) continue;    // flagged 0: all zero (see pair_force)
      cb_bridge *bridge = bridge_of(&firstvalue[i][SIZE_BRIDGE * jj]);
      const int j = jlist[jj] & NEIGHMASK;
      // (a restart file of a build whose history is laid out otherwise is refused before,
      // by read_restart_settings)
      if (cb_bridge_check_state(bridge) != CB_OK) corrupt_bridge(i, j, bridge);
      if (bridge->active == 0.0) continue;
      const int status = cb_bridge_set_volume(law(type[i], type[j]), radius[i], radius[j],
                                              bridge->volume, bridge);
      check_cb(error, status, "bridge constants at setup", type[i], type[j], radius[i], radius[j],
               bridge->volume, 0.0);
    }
  }
}

// a stored state that is neither dry nor a valid bridge's: stop, naming the pair
void PairGranCapillary::corrupt_bridge(int i, int j, const cb_bridge *bridge)
{
  error->one(FLERR, "pair gran/capillary: the pair history of atoms {} and {} holds no valid "
             "bridge state (volume {}, active {}, rupture {}, contact force {}, radius sum {}, "
             "radius product {}, law constant {}): {}", atom->tag[i], atom->tag[j],
             bridge->volume, bridge->active, bridge->rupture, bridge->force_contact,
             bridge->radius_sum, bridge->radius_product, bridge->law_constant,
             cb_status_message(CB_ERR_BRIDGE_STATE));
}

/* ----------------------------------------------------------------------
   history transfer to the partner: shear displacement negated, bridge copied
------------------------------------------------------------------------- */

void PairGranCapillary::transfer_history(double *source, double *target, int /*itype*/,
                                         int /*jtype*/)
{
  for (int k = 0; k < 3; k++) target[HIST_SHEAR + k] = -source[HIST_SHEAR + k];
  if (history_size == SIZE_BRIDGE)
    for (int k = 0; k < CB_BRIDGE_DOUBLES; k++) target[HIST_BRIDGE + k] = source[HIST_BRIDGE + k];
}

/* ----------------------------------------------------------------------
   the history of pair (i, j): in i's list, or in j's list (shear negated)
------------------------------------------------------------------------- */

double *PairGranCapillary::find_history(int i, int j, double *negate)
{
  *negate = 1.0;
  if (!fix_history || !list) return nullptr;
  int jnum = list->numneigh[i];
  int *jlist = list->firstneigh[i];
  for (int k = 0; k < jnum; k++) {
    neighprev++;
    if (neighprev >= jnum) neighprev = 0;
    if ((jlist[neighprev] & NEIGHMASK) == j)
      return &fix_history->firstvalue[i][history_size * neighprev];
  }
  if (j < atom->nlocal) {
    jnum = list->numneigh[j];
    jlist = list->firstneigh[j];
    for (int k = 0; k < jnum; k++)
      if ((jlist[k] & NEIGHMASK) == i) {
        *negate = -1.0;
        return &fix_history->firstvalue[j][history_size * k];
      }
  }
  return nullptr;
}
