/* ----------------------------------------------------------------------
   capbridge — LAMMPS binding: fix capillary/liquid

   fix ID group capillary/liquid fixed [V]
   fix ID group capillary/liquid protocol1|protocol2|protocol3 (water W RHO | liquid V)
                                 [every N] [start bridges|free] [remove F SEED] [vmax V]
   fix_modify ID remove F SEED    (Protocols 2, 3: remove at the next run's start)

   The fix owns the liquid; pair style gran/capillary owns the bridges (in its pair
   history), which the fix reaches through CapillaryBridges (capillary_bridges.h).  This
   file: the command, the totals, the schedule, the output and the restart state; the
   protocols' work on the pairs is in capillary_protocols.cpp.  This fix
     - fixes the total liquid at the first run (W times the mass of the group over RHO,
       or V), and derives at each run the bridge volume the neighbor reach is built for
       (vmax: the core's design volume, unless given);
     - holds the per-atom free liquid of Protocols 2 and 3 (migrates with the atoms,
       written to restart files; allocated only for these protocols);
     - runs Protocol 1 (protocol1) at the start and every N steps
       (every re-neighboring for N = 0), and, for Protocols 2 and 3, once at the start
       (start bridges) or hands the liquid to the atoms in proportion to their mass
       (start free);
     - does the per-step liquid exchange of Protocols 2 and 3 (offer_liquid, called by the
       pair's compute());
     - holds the Protocol 1 pool: liquid of broken bridges until the next distribution;
     - reports the census as a global vector.
------------------------------------------------------------------------- */

#include "fix_capillary_liquid.h"

#include "capillary_bridges.h"
#include "fix_capillary_wall.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "pair.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
constexpr int N_RESTART = 8;
}    // namespace

/* ---------------------------------------------------------------------- */

FixCapillaryLiquid::FixCapillaryLiquid(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), offer(nullptr), deposit(nullptr), best_partner(nullptr), pair(nullptr),
    bridges(nullptr), free_liquid(nullptr), nmax_scratch(0), candidates(nullptr),
    released(nullptr), best_height(nullptr)
{
  if (narg < 4)
    error->all(FLERR, "fix capillary/liquid: missing mode: allowed fixed, protocol1, protocol2, "
               "protocol3");
  mode = -1;
  for (int m = 0; m < LIQUID_MODES; m++)
    if (strcmp(arg[3], capillary_liquid_mode_name(m)) == 0) mode = m;
  if (mode < 0)
    error->all(FLERR, "fix capillary/liquid: unknown mode '{}': allowed fixed, protocol1, "
               "protocol2, protocol3", arg[3]);

  fixed_volume = -1.0;
  every = 0;
  start_free = 0;
  remove_fraction = 0.0;
  remove_seed = 0;
  remove_pending = removing = 0;
  removed_count = removed_liquid = 0.0;
  water = liquid_density = liquid_given = vmax_given = -1.0;
  parse_keywords(parse_fixed_volume(narg, arg), narg, arg);
  if (remove_pending && start_free) refuse_removal_without_bridges("keyword 'remove'");
  if (mode != LIQUID_FIXED && (water < 0.0) == (liquid_given < 0.0))
    error->all(FLERR, "fix capillary/liquid {}: give the liquid once: 'water W RHO' (mass "
               "fraction, liquid density) or 'liquid V' (volume units)", mode_name());

  vector_flag = 1;
  size_vector = 8;
  global_freq = 1;
  // counts and volumes are sums over the atoms (extensive); z and the relative change not
  extvector = -1;
  extlist = new int[8]{1, 0, 1, 1, 1, 1, 1, 0};
  restart_global = 1;

  if (capillary_liquid_per_atom(mode)) {
    // the per-atom liquid exchange within a force evaluation (exchange_liquid)
    comm_forward = COMM_FORWARD_SIZE;
    comm_reverse = COMM_REVERSE_SIZE;
    peratom_flag = 1;
    size_peratom_cols = 0;
    peratom_freq = 1;
    restart_peratom = 1;
    create_attribute = 1;
    maxexchange = 1;
    FixCapillaryLiquid::grow_arrays(atom->nmax);
    atom->add_callback(Atom::GROW);
    atom->add_callback(Atom::RESTART);
    for (int i = 0; i < atom->nlocal; i++) free_liquid[i] = 0.0;
  }

  total_liquid = -1.0;
  vmax = -1.0;
  pool = 0.0;
  alpha = 0.0;
  started = 0;
  last_distribution = -1;
  for (double &v : values) v = 0.0;
  formed = ruptured = 0.0;
  total_at_run_end = -1.0;
  total_from_restart = 0;
  census_step = -1;
  census_valid = 0;
  warned_nowhere = warned_reach = 0;
}

/* ----------------------------------------------------------------------
   mode fixed: the optional bridge volume after the mode; returns the next argument
------------------------------------------------------------------------- */

int FixCapillaryLiquid::parse_fixed_volume(int narg, char **arg)
{
  int iarg = 4;
  static const char *const keywords[] = {"water", "liquid", "every", "start", "vmax"};
  const bool is_keyword =
      iarg < narg && std::any_of(std::begin(keywords), std::end(keywords),
                                 [&](const char *k) { return strcmp(arg[iarg], k) == 0; });
  if (mode == LIQUID_FIXED && iarg < narg && !is_keyword) {
    if (!utils::is_double(arg[iarg]))
      error->all(FLERR, "fix capillary/liquid fixed: volume '{}' is not a number (the bridge "
                 "volume, >= 0, in volume units; or leave it out to use pair_coeff's)",
                 arg[iarg]);
    fixed_volume = utils::numeric(FLERR, arg[iarg], false, lmp);
    if (!(fixed_volume >= 0.0))
      error->all(FLERR, "fix capillary/liquid fixed: volume = {}: must be >= 0 (volume units)",
                 arg[iarg]);
    iarg++;
  }
  return iarg;
}

/* ----------------------------------------------------------------------
   the keywords, from arg[iarg]: water W RHO | liquid V, every N, start bridges|free, vmax V
------------------------------------------------------------------------- */

void FixCapillaryLiquid::parse_keywords(int iarg, int narg, char **arg)
{
  const bool protocol = mode != LIQUID_FIXED;
  auto need = [&](int count, const char *keyword) {
    if (iarg + count >= narg)
      error->all(FLERR, "fix capillary/liquid: keyword '{}' needs {} value{}", keyword, count,
                 count > 1 ? "s" : "");
  };
  auto only_protocols = [&](const char *keyword) {
    if (!protocol)
      error->all(FLERR, "fix capillary/liquid fixed: keyword '{}' applies to protocol1, "
                 "protocol2, protocol3 only", keyword);
  };
  while (iarg < narg) {
    const char *key = arg[iarg];
    if (strcmp(key, "water") == 0) {
      only_protocols(key);
      need(2, key);
      water = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      liquid_density = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
      if (!(water >= 0.0))
        error->all(FLERR, "fix capillary/liquid: water content {}: must be >= 0 (mass of "
                   "liquid over mass of solid)", arg[iarg + 1]);
      if (!(liquid_density > 0.0))
        error->all(FLERR, "fix capillary/liquid: liquid density {}: must be > 0 (mass/volume "
                   "units)",
                   arg[iarg + 2]);
      iarg += 3;
    } else if (strcmp(key, "liquid") == 0) {
      only_protocols(key);
      need(1, key);
      liquid_given = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(liquid_given >= 0.0))
        error->all(FLERR, "fix capillary/liquid: liquid {}: the total liquid volume must be "
                   ">= 0 (volume units)", arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(key, "every") == 0) {
      if (mode != LIQUID_PROTOCOL1)
        error->all(FLERR, "fix capillary/liquid: keyword 'every' applies to protocol1 only");
      need(1, key);
      every = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (every < 0)
        error->all(FLERR, "fix capillary/liquid: every {}: must be >= 0 (0 = at every "
                   "re-neighboring)", every);
      iarg += 2;
    } else if (strcmp(key, "start") == 0) {
      if (mode != LIQUID_PROTOCOL2 && mode != LIQUID_PROTOCOL3)
        error->all(FLERR, "fix capillary/liquid: keyword 'start' applies to protocol2 and "
                   "protocol3 only");
      need(1, key);
      if (strcmp(arg[iarg + 1], "bridges") == 0)
        start_free = 0;
      else if (strcmp(arg[iarg + 1], "free") == 0)
        start_free = 1;
      else
        error->all(FLERR, "fix capillary/liquid: start '{}': allowed bridges, free", arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(key, "remove") == 0) {
      need(2, key);
      ask_removal("keyword 'remove'", arg[iarg + 1], arg[iarg + 2]);
      iarg += 3;
    } else if (strcmp(key, "vmax") == 0) {
      only_protocols(key);
      need(1, key);
      vmax_given = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(vmax_given > 0.0))
        error->all(FLERR, "fix capillary/liquid: vmax {}: must be > 0 (volume units)",
                   arg[iarg + 1]);
      iarg += 2;
    } else
      error->all(FLERR, "fix capillary/liquid: unknown keyword '{}': allowed water, liquid, "
                 "every, start, remove, vmax", key);
  }
}

/* ----------------------------------------------------------------------
   a removal of a share of the bridges, asked by keyword remove or by fix_modify ID remove:
   it acts in the first force evaluation of the next run (after the liquid starts, if it
   starts then).  Richefeu 2007 fig. 7 and fig. 12: "two times less bonds ... obtained by
   removing half of the bonds", the water content kept; Protocol 1 would give every
   eligible pair its bridge back at its next distribution, and fixed volumes keep no water
   content
------------------------------------------------------------------------- */

void FixCapillaryLiquid::ask_removal(const char *how, const char *share, const char *seed)
{
  if (mode != LIQUID_PROTOCOL2 && mode != LIQUID_PROTOCOL3)
    error->all(FLERR, "fix capillary/liquid {}: {} applies to protocol2 and protocol3 only "
               "({})", mode_name(), how,
               mode == LIQUID_PROTOCOL1
                   ? "Protocol 1 gives every eligible pair a bridge again at its next "
                     "distribution"
                   : "fixed volumes keep no water content for the removed bridges");
  remove_fraction = utils::numeric(FLERR, share, false, lmp);
  remove_seed = utils::bnumeric(FLERR, seed, false, lmp);
  if (!(remove_fraction > 0.0 && remove_fraction <= 1.0))
    error->all(FLERR, "fix capillary/liquid: remove {}: the share of the bridges removed "
               "must be > 0 and <= 1 (0.5: half of them)", share);
  if (remove_seed < 1)
    error->all(FLERR, "fix capillary/liquid: remove seed {}: must be a whole number >= 1", seed);
  remove_pending = 1;
}

void FixCapillaryLiquid::refuse_removal_without_bridges(const char *how)
{
  error->all(FLERR, "fix capillary/liquid {}: {} needs 'start bridges' (with 'start free' no "
             "bridge exists when the liquid starts; or ask for the removal with fix_modify "
             "after a run that formed bridges)", mode_name(), how);
}

/* ----------------------------------------------------------------------
   fix_modify ID remove F SEED: remove the share F of the bridges at the next run's start
   (e.g. after a consolidation, before shearing: Richefeu 2007 fig. 7)
------------------------------------------------------------------------- */

int FixCapillaryLiquid::modify_param(int narg, char **arg)
{
  if (strcmp(arg[0], "remove") != 0) return 0;
  if (narg < 3)
    error->all(FLERR, "fix_modify {} remove: needs 2 values, F SEED (the share of the bridges "
               "removed, > 0 and <= 1, and the seed of the draw, a whole number >= 1)", id);
  ask_removal("fix_modify remove", arg[1], arg[2]);
  if (!started && start_free) refuse_removal_without_bridges("fix_modify remove");
  return 3;
}

/* at each run's setup, once the liquid has started: a removal asked for acts in this run's
   first force evaluation, phase 1 (update_bridges) */
void FixCapillaryLiquid::begin_removal()
{
  removing = remove_pending;
  remove_pending = 0;
}

/* ---------------------------------------------------------------------- */

FixCapillaryLiquid::~FixCapillaryLiquid()
{
  if (copymode) return;
  delete[] extlist;
  if (free_liquid) {
    atom->delete_callback(id, Atom::GROW);
    atom->delete_callback(id, Atom::RESTART);
  }
  memory->destroy(free_liquid);
  destroy_scratch();
}

/* ---------------------------------------------------------------------- */

int FixCapillaryLiquid::setmask()
{
  int mask = 0;
  mask |= PRE_FORCE;
  return mask;
}

/* ---------------------------------------------------------------------- */

void FixCapillaryLiquid::init()
{
  // the pair style, and its bridges: PairGranCapillary is a CapillaryBridges
  pair = force->pair_match("gran/capillary", 1);
  bridges = dynamic_cast<CapillaryBridges *>(pair);
  if (!bridges)
    error->all(FLERR, "fix capillary/liquid requires pair style gran/capillary (alone or as a "
               "sub-style of pair_style hybrid/overlay)");
  walls.clear();
  for (auto *wall : modify->get_fix_by_style("^capillary/wall$"))
    walls.push_back(static_cast<FixCapillaryWall *>(wall));
  ensure_totals();
  census_valid = 0;
}

/* ----------------------------------------------------------------------
   the total liquid, fixed at its first use (collective)
------------------------------------------------------------------------- */

void FixCapillaryLiquid::ensure_totals()
{
  if (mode == LIQUID_FIXED) return;
  if (total_liquid < 0.0 || total_from_restart) {
    const double asked =
        water >= 0.0 ? water * group->mass(igroup) / liquid_density : liquid_given;
    if (total_liquid < 0.0)
      total_liquid = asked;
    else if (fabs(asked - total_liquid) > 1e-9 * MAX(asked, total_liquid) && comm->me == 0)
      error->warning(FLERR, "fix capillary/liquid {}: the restart file's total liquid {:.6g} "
                     "is kept (the liquid is conserved from the first run on); this fix's "
                     "{} asks for {:.6g}, which is not applied", mode_name(), total_liquid,
                     water >= 0.0 ? "water content" : "liquid", asked);
    total_from_restart = 0;
  }
}

/* ----------------------------------------------------------------------
   the design volume of this run's neighbor reach (collective; called by the pair's
   init_style, so once per run that builds its reach): vmax as given, else the core's
   (cb_protocol_design_volume) for the liquid, the group's atoms and radius range, and the
   largest free liquid of one atom now
------------------------------------------------------------------------- */

void FixCapillaryLiquid::derive_design_volume()
{
  ensure_totals();
  if (mode == LIQUID_FIXED) return;
  if (vmax_given > 0.0) {
    vmax = vmax_given;
    return;
  }
  double lo = HUGE_VAL, hi = 0.0, most_free = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) {
      lo = MIN(lo, atom->radius[i]);
      hi = MAX(hi, atom->radius[i]);
      if (free_liquid) most_free = MAX(most_free, free_liquid[i]);
    }
  double local[2] = {-lo, hi}, all[2], most_free_all = 0.0;
  MPI_Allreduce(local, all, 2, MPI_DOUBLE, MPI_MAX, world);
  MPI_Allreduce(&most_free, &most_free_all, 1, MPI_DOUBLE, MPI_MAX, world);
  const cb_radius_range radii = {-all[0], all[1]};
  const auto grains = (double) group->count(igroup);
  const int status =
      cb_protocol_design_volume(total_liquid, grains, radii, most_free_all, &vmax);
  if (status != CB_OK)
    error->all(FLERR, "fix capillary/liquid {}: no design volume for the neighbor reach "
               "(liquid {:.6g} in {:.0f} atoms of radii {:.6g} to {:.6g}, largest free liquid "
               "{:.6g}): {}; the default needs atoms with a radius > 0 in the group at the "
               "start of the run: give vmax V", mode_name(), total_liquid, grains, radii.min,
               radii.max, most_free_all, cb_status_message((cb_status) status));
}

double FixCapillaryLiquid::reach_volume() const
{
  return MAX(vmax, 0.0);
}

/* ---------------------------------------------------------------------- */

void FixCapillaryLiquid::setup_pre_force(int /*vflag*/)
{
  if (mode == LIQUID_FIXED) return;
  if (!started) {
    start_liquid();
    started = 1;
    begin_removal();
    return;
  }
  if (total_at_run_end >= 0.0 && free_liquid) {
    // Protocols 2, 3 keep their liquid in the bridges and the atoms: whatever changed it
    // between two runs took liquid with it
    census();
    const double change = values[4] - total_at_run_end;
    if (fabs(change) > 1e-9 * total_liquid && comm->me == 0)
      error->warning(FLERR, "fix capillary/liquid {}: the liquid changed by {:.6g} ({:+.3g} of "
                     "the total) between two runs: atoms deleted with their free liquid and "
                     "bridges, or atom IDs renumbered (delete_atoms with compress yes, "
                     "reset_atoms id), which drops the bridges of the renumbered atoms (the "
                     "pair history is kept per pair of atom IDs)", mode_name(), change,
                     change / total_liquid);
  }
  begin_removal();
  pre_force(0);
}

void FixCapillaryLiquid::post_run()
{
  if (mode == LIQUID_FIXED) return;
  census();
  total_at_run_end = values[4];
}

void FixCapillaryLiquid::pre_force(int /*vflag*/)
{
  if (mode != LIQUID_PROTOCOL1) return;
  const bigint step = update->ntimestep;
  if (step == last_distribution) return;
  const bool due = every > 0 ? (step % every == 0) : (neighbor->ago == 0);
  if (due) distribute("every");
}

/* ----------------------------------------------------------------------
   the liquid at the start of the first run
------------------------------------------------------------------------- */

void FixCapillaryLiquid::start_liquid()
{
  // Bridges may exist before the liquid starts: from runs with fixed volumes, or from a
  // restart file whose fix had another ID (its state not handed to this fix).  They are
  // part of the total: Protocol 1 distributes the total anew over the pairs, and free
  // liquid is what the bridges do not hold.
  census();
  const double held = values[2];
  if (held > 0.0 && comm->me == 0)
    error->warning(FLERR, "fix capillary/liquid {}: {:.0f} bridges holding {:.6g} exist at the "
                   "start of the liquid (an earlier run, or a restart file with another fix "
                   "ID); they are part of the total liquid {:.6g}: {}", mode_name(), values[0],
                   held, total_liquid,
                   mode == LIQUID_PROTOCOL1 || !start_free
                       ? "the total is distributed anew over the pairs"
                       : "the free liquid is the rest");
  if (mode == LIQUID_PROTOCOL1 || !start_free) {
    distribute("start");
    if (mode == LIQUID_PROTOCOL1 || last_distribution == update->ntimestep)
      return;
  }
  // Protocols 2, 3: the liquid as free liquid, in proportion to the atoms' masses (what a
  // failed distribution left in the bridges stays there)
  census();
  const double rest = total_liquid - values[2];
  if (rest < -1e-12 * total_liquid)
    error->all(FLERR, "fix capillary/liquid {}: the bridges that exist at the start hold "
               "{:.6g}, more than the total liquid {:.6g}: give at least that much liquid",
               mode_name(), values[2], total_liquid);
  const double mass = group->mass(igroup);
  if (mass > 0.0)
    for (int i = 0; i < atom->nlocal; i++)
      if (atom->mask[i] & groupbit) free_liquid[i] = MAX(rest, 0.0) * (atom->rmass[i] / mass);
  pool = 0.0;
}

/* ----------------------------------------------------------------------
   keyword remove, after the force evaluation that removed the bridges (collective): how
   many, of how many, and their liquid, which the protocol handed on as a broken bridge's
------------------------------------------------------------------------- */

void FixCapillaryLiquid::report_removal()
{
  removing = 0;
  double local[2] = {removed_count, removed_liquid}, global[2];
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, world);
  removed_count = removed_liquid = 0.0;
  census();
  if (comm->me == 0)
    utils::logmesg(lmp, "fix capillary/liquid {}: removed {:.0f} of {:.0f} bridges (remove {} "
                   "seed {}: {:.4f} of them), holding {:.17g} of the liquid {:.17g}, handed on as "
                   "the liquid of broken bridges\n", mode_name(), global[0],
                   global[0] + values[0], remove_fraction, remove_seed,
                   global[0] > 0.0 ? global[0] / (global[0] + values[0]) : 0.0, global[1],
                   total_liquid);
}

/* ----------------------------------------------------------------------
   Protocol 1 over all pairs; if no pair can hold the liquid, nothing changes
------------------------------------------------------------------------- */

void FixCapillaryLiquid::distribute(const char *why)
{
  double a = 0.0, largest = 0.0;
  // liquid of broken bridges not yet collected is part of what is redistributed
  collect_released();
  if (total_liquid <= 0.0) {
    last_distribution = update->ntimestep;
    return;
  }
  const int nowhere = protocol1(total_liquid, a, largest);
  if (nowhere) {
    if (!warned_nowhere && comm->me == 0)
      error->warning(FLERR, "fix capillary/liquid {} ({}, step {}): no pair can hold the liquid "
                     "({:.6g} volume units): {}; this warning is given once", mode_name(), why,
                     update->ntimestep, total_liquid,
                     mode == LIQUID_PROTOCOL1
                         ? "it stays in the pool until a distribution succeeds"
                         : "the atoms keep it as free liquid, in proportion to their mass");
    warned_nowhere = 1;
    if (mode == LIQUID_PROTOCOL1 && !started) pool = total_liquid;
    return;
  }
  alpha = a;
  pool = 0.0;
  last_distribution = update->ntimestep;
}

/* ----------------------------------------------------------------------
   output: 1 bridges, 2 bridge coordination number z = 2 bridges / atoms in the group,
   3 liquid in bridges, 4 free liquid (per-atom free liquid and the Protocol 1 pool),
   5 total liquid (3 + 4), 6 formations and 7 ruptures since the fix was defined,
   8 relative change of the total since the start ((5 - total) / total; 0 in mode fixed)
------------------------------------------------------------------------- */

void FixCapillaryLiquid::census()
{
  double local[7] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0}, global[7];
  if (bridges) count_bridges(local);
  if (free_liquid)
    for (int i = 0; i < atom->nlocal; i++) local[6] += free_liquid[i];
  MPI_Allreduce(local, global, 7, MPI_DOUBLE, MPI_SUM, world);
  pool += global[5];
  const bigint count = group->count(igroup);
  const double free_total = global[6] + pool;
  const double total = global[1] + free_total;
  values[0] = global[0];
  values[1] = count > 0 ? 2.0 * global[0] / (double) count : 0.0;
  values[2] = global[1];
  values[3] = free_total;
  values[4] = total;
  formed += global[2];
  ruptured += global[3];
  values[5] = formed;
  values[6] = ruptured;
  values[7] = (mode != LIQUID_FIXED && total_liquid > 0.0)
      ? (total - total_liquid) / total_liquid
      : 0.0;
  if (global[4] > 0.0 && !warned_reach) {
    warned_reach = 1;
    if (comm->me == 0)
      error->warning(FLERR, "fix capillary/liquid: {} bridge(s) ruptured at the neighbor reach "
                     "(built for bridge volumes up to {:.6g} volume units) before their rupture "
                     "distance; "
                     "their liquid is kept; raise vmax; this warning is given once",
                     global[4], vmax);
  }
}

double FixCapillaryLiquid::compute_vector(int n)
{
  if (!census_valid || census_step != update->ntimestep) {
    census();
    census_step = update->ntimestep;
    census_valid = 1;
  }
  return values[n];
}

/* ----------------------------------------------------------------------
   global restart: the liquid, the design volume, the pool, the schedule
------------------------------------------------------------------------- */

void FixCapillaryLiquid::write_restart(FILE *fp)
{
  // collect released liquid still held by the pair on each rank (collective)
  if (bridges) collect_released();
  double list[N_RESTART] = {(double) mode, total_liquid,      vmax, pool, alpha,
                            (double) started, (double) last_distribution, (double) every};
  if (comm->me == 0) {
    int size = N_RESTART * sizeof(double);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list, sizeof(double), N_RESTART, fp);
  }
}

void FixCapillaryLiquid::restart(char *buf)
{
  auto *list = (double *) buf;
  if ((int) list[0] != mode)
    error->all(FLERR, "fix capillary/liquid: the restart file holds mode {}, the input script "
               "gives {}", capillary_liquid_mode_name((int) list[0]), mode_name());
  total_liquid = list[1];
  total_from_restart = 1;
  // list[2], the design volume of the run that wrote the file, is not read: each run
  // derives its own (derive_design_volume), from the liquid and the atoms read here
  pool = list[3];
  alpha = list[4];
  started = (int) list[5];
  last_distribution = (bigint) list[6];
  if (started && remove_pending) {
    remove_pending = 0;
    if (comm->me == 0)
      error->warning(FLERR, "fix capillary/liquid {}: keyword 'remove' acts when the liquid "
                     "starts, and the restart file's liquid has started: no bridge is "
                     "removed (fix_modify {} remove F SEED removes at the next run)",
                     mode_name(), id);
  }
}

/* ----------------------------------------------------------------------
   per-atom free liquid (Protocols 2, 3)
------------------------------------------------------------------------- */

void FixCapillaryLiquid::grow_arrays(int nmax)
{
  memory->grow(free_liquid, nmax, "capillary/liquid:free_liquid");
  vector_atom = free_liquid;
}

void FixCapillaryLiquid::copy_arrays(int i, int j, int /*delflag*/)
{
  free_liquid[j] = free_liquid[i];
}

void FixCapillaryLiquid::set_arrays(int i)
{
  free_liquid[i] = 0.0;
}

int FixCapillaryLiquid::pack_exchange(int i, double *buf)
{
  buf[0] = free_liquid[i];
  return 1;
}

int FixCapillaryLiquid::unpack_exchange(int nlocal, double *buf)
{
  free_liquid[nlocal] = buf[0];
  return 1;
}

int FixCapillaryLiquid::pack_restart(int i, double *buf)
{
  // buf[0] is the count, by the convention of atom->extra
  buf[0] = 2;
  buf[1] = free_liquid[i];
  return 2;
}

void FixCapillaryLiquid::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  free_liquid[nlocal] = extra[nlocal][m];
}

int FixCapillaryLiquid::size_restart(int /*nlocal*/)
{
  return 2;
}

int FixCapillaryLiquid::maxsize_restart()
{
  return 2;
}

double FixCapillaryLiquid::memory_usage()
{
  return (free_liquid ? (double) atom->nmax * sizeof(double) : 0.0) +
      (double) nmax_scratch * (5 * sizeof(double) + sizeof(tagint));
}
