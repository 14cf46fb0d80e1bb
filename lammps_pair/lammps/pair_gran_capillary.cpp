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
   Protocols 2 and 3 under MPI: see update_bridges() and exchange_liquid().
------------------------------------------------------------------------- */

#include "pair_gran_capillary.h"

#include "fix_capillary_liquid.h"

#include "atom.h"
#include "citeme.h"
#include "domain.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "fix_dummy.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "math_const.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <string>

using namespace LAMMPS_NS;
using MathConst::MY_PI;

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

namespace {
enum { REVERSE_EVENTS = 1, FORWARD_OFFERS = 2 };
constexpr int COMM_REVERSE_SIZE = 4;
constexpr int COMM_FORWARD_SIZE = 3;
// The neighbor reach exceeds the largest rupture distance by this fraction, so that a
// bridge held at exactly its rupture distance is never cut by the reach test.
constexpr double REACH_MARGIN = 1e-9;

const char *const coeff_syntax =
    "syntax: pair_coeff I J kn kt damping mu law LAW [keyword value ...] or "
    "pair_coeff I J contact none law LAW [keyword value ...]; keywords: gamma, theta, "
    "rupture, overlap, validity, c, volume";

cb_bridge *bridge_of(double *history)
{
  return reinterpret_cast<cb_bridge *>(history + PairGranCapillary::HIST_BRIDGE);
}

// Does a contact at `offset` (contact height minus centre height) beat the current
// receiver?  The rule is cb_protocol3_receiver's (the lowest contact strictly below the
// centre); equal heights go to the smaller partner tag so that the choice does not
// depend on the order in which ranks and neighbor lists present the bridges.
// FixNeighHistory::pack_exchange's layout of one atom: the number of partners, then per
// partner its tag and its `size` values.  Where partner p's entry (its tag) starts:
int packed_entry(int partner, int size)
{
  return 1 + (1 + size) * partner;
}

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

  type_stride = 0;
  rad_min = rad_max = nullptr;
  dashpot = CB_DASHPOT_APPROACH;
  dt = update->dt;
  freeze_group_bit = 0;

  fix_history = nullptr;
  history_size = 0;
  fix_liquid = nullptr;
  liquid_mode = LIQUID_FIXED;
  liquid_groupbit = 0;
  bridges_possible = 1;

  nmax_scratch = 0;
  candidates = released = offer = deposit = best_height = nullptr;
  best_partner = nullptr;
  commflag = 0;

  n_formed = n_ruptured = n_reach = pool_released = 0.0;
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
  memory->destroy(candidates);
  memory->destroy(released);
  memory->destroy(offer);
  memory->destroy(deposit);
  memory->destroy(best_height);
  memory->destroy(best_partner);
}

/* ---------------------------------------------------------------------- */

void PairGranCapillary::allocate()
{
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  for (int i = 0; i <= n; i++)
    for (int j = 0; j <= n; j++) setflag[i][j] = 0;
  type_stride = n + 1;
  type_pairs.assign((size_t) type_stride * type_stride, TypePair());
  rad_min = new double[n + 1];
  rad_max = new double[n + 1];
  for (int i = 0; i <= n; i++) rad_min[i] = rad_max[i] = 0.0;
  held_volume.assign(n + 1, 0.0);
  coeff_text.assign((size_t) (n + 1) * (n + 1), std::string());
}

/* ----------------------------------------------------------------------
   pair_style gran/capillary [dashpot approach|both|repulsive]
------------------------------------------------------------------------- */

void PairGranCapillary::settings(int narg, char **arg)
{
  dashpot = CB_DASHPOT_APPROACH;
  int iarg = 0;
  std::set<std::string> given;  // a repeated keyword is refused, as in pair_coeff
  while (iarg < narg) {
    if (!given.insert(arg[iarg]).second)
      error->all(FLERR, "pair_style gran/capillary: keyword '{}' given twice: each keyword may "
                 "be given once", arg[iarg]);
    if (strcmp(arg[iarg], "dashpot") == 0) {
      if (iarg + 2 > narg) utils::missing_cmd_args(FLERR, "pair_style gran/capillary dashpot", error);
      if (strcmp(arg[iarg + 1], "approach") == 0)
        dashpot = CB_DASHPOT_APPROACH;
      else if (strcmp(arg[iarg + 1], "both") == 0)
        dashpot = CB_DASHPOT_BOTH;
      else if (strcmp(arg[iarg + 1], "repulsive") == 0)
        dashpot = CB_DASHPOT_REPULSIVE;
      else
        error->all(FLERR, "pair_style gran/capillary: dashpot '{}': allowed approach, both, "
                   "repulsive", arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "friction") == 0) {
      // removed: 'friction wet' (the default) counted the capillary attraction twice; the
      // Coulomb limit is Richefeu 2007 eq. 12 as his eq. 1 defines f_n, always
      error->all(FLERR, "pair_style gran/capillary: keyword 'friction' was removed: the Coulomb "
                 "limit is always mu (f_n^e + f_n^d), Richefeu 2007 eq. 12 with the f_n of his "
                 "eq. 1 (the former default 'friction wet' counted the capillary attraction "
                 "twice; 'friction dry' is what every run now does): delete the keyword");
    } else
      error->all(FLERR, "pair_style gran/capillary: unknown keyword '{}': allowed dashpot",
                 arg[iarg]);
  }
}

/* ----------------------------------------------------------------------
   pair_coeff I J kn kt damping mu law LAW [keyword value ...]
   pair_coeff I J contact none law LAW [keyword value ...]
------------------------------------------------------------------------- */

void PairGranCapillary::coeff(int narg, char **arg)
{
  if (narg < 2) error->all(FLERR, "pair_coeff: missing type indices; {}", coeff_syntax);
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  parse_coeff(ilo, ihi, jlo, jhi, narg - 2, arg + 2);
}

void PairGranCapillary::parse_coeff(int ilo, int ihi, int jlo, int jhi, int narg, char **arg)
{
  auto range = [](int lo, int hi) {
    return lo == hi ? std::to_string(lo) : fmt::format("{}*{}", lo, hi);
  };
  const std::string where = fmt::format("pair_coeff {} {}", range(ilo, ihi), range(jlo, jhi));
  auto number = [&](int k, const char *name, const char *meaning) -> double {
    if (k >= narg)
      error->all(FLERR, "{}: missing coefficient {} ({}); {}", where, name, meaning, coeff_syntax);
    if (!utils::is_double(arg[k])) {
      if (strcmp(arg[k], "law") == 0 || strcmp(arg[k], "contact") == 0)
        error->all(FLERR, "{}: missing coefficient {} ({}) before '{}'; {}", where, name,
                   meaning, arg[k], coeff_syntax);
      error->all(FLERR, "{}: coefficient {} ({}) must be a number, not '{}'; {}", where, name,
                 meaning, arg[k], coeff_syntax);
    }
    return utils::numeric(FLERR, arg[k], false, lmp);
  };

  cb_contact_law contact_one{};    // contact none: all zero
  int contact_on_one = 1;
  int iarg = 0;
  if (narg > 0 && strcmp(arg[0], "contact") == 0) {
    if (narg < 2 || strcmp(arg[1], "none") != 0)
      error->all(FLERR, "{}: 'contact' must be followed by 'none' (no contact force: the "
                 "capillary force only); {}", where, coeff_syntax);
    contact_on_one = 0;
    iarg = 2;
  } else {
    const double kn_one = number(0, "kn", "normal stiffness, force/distance");
    const double kt_one = number(1, "kt", "tangential stiffness, force/distance");
    const double damping_one = number(2, "damping", "normal damping rate alpha_n, 0..1");
    const double mu_one = number(3, "mu", "friction coefficient");
    // the core's rule for the coefficients (the dashpot rule is pair_style's, applied by
    // init_one: any one here)
    cb_message msg;
    if (cb_contact_law_init(&contact_one, kn_one, kt_one, damping_one, mu_one,
                            CB_DASHPOT_APPROACH, &msg) != CB_OK)
      error->all(FLERR, "{}: {}", where, msg.text);
    iarg = 4;
  }

  if (iarg >= narg || strcmp(arg[iarg], "law") != 0)
    error->all(FLERR, "{}: missing 'law LAW' after the contact coefficients{} (laws: {}); {}",
               where, iarg < narg ? fmt::format(", found '{}'", arg[iarg]) : "",
               cb_law_names(), coeff_syntax);
  if (iarg + 1 >= narg)
    error->all(FLERR, "{}: 'law' needs a law name: allowed {}", where, cb_law_names());
  cb_model model;
  if (cb_model_from_name(arg[iarg + 1], &model) != CB_OK)
    error->all(FLERR, "{}: unknown law '{}': allowed {}", where, arg[iarg + 1], cb_law_names());
  std::string spec = arg[iarg + 1];
  iarg += 2;

  // gamma has no default: a placeholder until the keyword is read
  cb_law one;
  cb_law_init(&one, model, 1.0, 0.0);
  int have_gamma = 0;
  double volume_one = -1.0;
  cb_keywords_given given = {0};  // a repeated keyword is refused, as in the CLI
  while (iarg < narg) {
    const char *key = arg[iarg];
    if (iarg + 1 >= narg)
      error->all(FLERR, "{}: keyword '{}' needs a value", where, key);
    const char *value = arg[iarg + 1];
    if (strcmp(key, "volume") == 0) {
      if (volume_one >= 0.0)
        error->all(FLERR, "{}: keyword 'volume' given twice: each keyword may be given once",
                   where);
      if (!utils::is_double(value))
        error->all(FLERR, "{}: volume '{}' must be a number (volume units)", where, value);
      volume_one = utils::numeric(FLERR, value, false, lmp);
      if (!(volume_one >= 0.0) || !std::isfinite(volume_one))
        error->all(FLERR, "{}: volume = {}: the bridge volume must be >= 0 (volume units; 0 = no "
                   "bridges for these types)", where, value);
    } else {
      cb_message msg;
      msg.text[0] = '\0';
      if (cb_law_configure_once(&one, &given, key, value, &msg) != CB_OK)
        error->all(FLERR, "{}: {}", where, msg.text);
      if (strcmp(key, "gamma") == 0) have_gamma = 1;
      spec += fmt::format(" {} {}", key, value);
    }
    iarg += 2;
  }
  if (!have_gamma)
    error->all(FLERR, "{}: law {} needs 'gamma' (the surface tension, force/distance)", where,
               cb_model_name(model));

  // one prepared law per distinct law (by value: 'gamma 0.0728' and 'gamma 7.28e-2 theta 0'
  // are one law)
  int index = -1;
  for (size_t k = 0; k < laws.size(); k++)
    if (cb_law_same(laws[k], &one)) index = (int) k;
  if (index < 0) {
    cb_message msg;
    msg.text[0] = '\0';
    auto *prepared = new cb_law(one);
    if (cb_law_prepare(prepared, &msg) != CB_OK) {
      cb_law_release(prepared);
      delete prepared;
      error->all(FLERR, "{}: law {}: {}", where, cb_model_name(model), msg.text);
    }
    laws.push_back(prepared);
    law_text.push_back(spec);
    index = (int) laws.size() - 1;
  }

  std::string text;
  for (int k = 0; k < narg; k++) text += (k ? " " : "") + std::string(arg[k]);

  int count = 0;
  const int n = atom->ntypes;
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      TypePair &tp = type_pairs[i * type_stride + j];
      tp.contact = contact_one;
      tp.volume = volume_one;
      tp.law = laws[index];
      tp.contact_on = contact_on_one;
      tp.law_index = index;
      type_pairs[j * type_stride + i] = tp;
      coeff_text[(size_t) i * (n + 1) + j] = text;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "{}: no type pair I <= J in these ranges", where);
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

  // the liquid
  auto liquids = modify->get_fix_by_style("^capillary/liquid$");
  if (liquids.size() > 1) error->all(FLERR, "Only one fix capillary/liquid at a time allowed");
  fix_liquid = liquids.empty() ? nullptr : dynamic_cast<FixCapillaryLiquid *>(liquids.front());
  liquid_mode = fix_liquid ? fix_liquid->mode : LIQUID_FIXED;
  liquid_groupbit = fix_liquid ? fix_liquid->groupbit : 0;

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

  // The neighbor list. With liquid: a plain half list reaching the type-pair cutoff
  // (init_one), since bridges act beyond contact and the list must hold every pair up to
  // the largest rupture distance. Without (no type pair can form a bridge and none holds
  // one): the per-pair size list of LAMMPS's dry granular styles, cut at R_i + R_j + skin,
  // so that a dry scene pays for its contacts only.
  bridges_possible = 0;
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++)
      if (setflag[i][j] &&
          (liquid_mode == LIQUID_FIXED ? design_volume(i, j) > 0.0
                                        : type_pair(i, j).volume != 0.0))
        bridges_possible = 1;
  create_history();
  held_volumes();
  for (int i = 1; i <= n; i++)
    if (held_volume[i] > 0.0) bridges_possible = 1;
  if (bridges_possible)
    neighbor->add_request(this, NeighConst::REQ_HISTORY);
  else
    neighbor->add_request(this, NeighConst::REQ_SIZE | NeighConst::REQ_HISTORY);

  // per-atom liquid exchange within a force evaluation (Protocols 2, 3)
  if (liquid_mode == LIQUID_PROTOCOL2 || liquid_mode == LIQUID_PROTOCOL3) {
    comm_forward = COMM_FORWARD_SIZE;
    comm_reverse = COMM_REVERSE_SIZE;
  } else {
    comm_forward = comm_reverse = 0;
  }

  radius_ranges();
}

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
  return fix_liquid ? fix_liquid->design_volume() : 0.0;
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

/* ---------------------------------------------------------------------- */

double PairGranCapillary::init_one(int i, int j)
{
  if (setflag[i][j] == 0)
    error->all(FLERR, "pair gran/capillary: no pair_coeff for types {} {} (coefficients are not "
               "mixed: give every type pair I <= J)", i, j);

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

  // the pair loops' constants (init() calls init_one for every pair before a run)
  TypePair &tp = type_pairs[i * type_stride + j];
  const cb_contact_law given = tp.contact;
  cb_message msg;
  if (cb_contact_law_init(&tp.contact, given.normal_stiffness, given.tangential_stiffness,
                          given.damping_rate, given.friction, dashpot, &msg) != CB_OK)
    error->all(FLERR, "pair gran/capillary: types {} {}: {}", i, j, msg.text);    // (checked by pair_coeff)
  tp.formation_volume = liquid_mode == LIQUID_FIXED ? design_volume(i, j) : 0.0;
  tp.cutsq = cut * cut;
  type_pairs[j * type_stride + i] = tp;
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
   each pair counted once over all ranks: with newton on a pair is in one rank's list;
   with newton off a pair with a ghost partner is in both owners' lists and is counted
   where the owned atom has the smaller tag
------------------------------------------------------------------------- */

int PairGranCapillary::counted(int i, int j) const
{
  if (force->newton_pair || j < atom->nlocal) return 1;
  return atom->tag[i] < atom->tag[j];
}

int PairGranCapillary::wet_pair(int i, int j, const TypePair &tp) const
{
  if (tp.volume == 0.0) return 0;
  if (fix_liquid) {
    int *mask = atom->mask;
    if (!(mask[i] & liquid_groupbit) || !(mask[j] & liquid_groupbit)) return 0;
  }
  return 1;
}

void PairGranCapillary::fail_cb(int status, const char *what, int itype, int jtype, double r1,
                                double r2, double vol, double gap)
{
  error->one(FLERR, "pair gran/capillary: {} failed for types {} {} (law '{}', r1 = {}, "
             "r2 = {}, volume = {}, gap = {}): {}", what, itype, jtype,
             law_text[type_pair(itype, jtype).law_index], r1, r2, vol, gap,
             cb_status_message((cb_status) status));
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

/* ---------------------------------------------------------------------- */

void PairGranCapillary::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (neighbor->ago == 0) {    // at setup and after every re-neighboring
    if (bridges_possible) check_periodic_images();
    check_timestep();
  }
  if (update->setupflag) derive_bridges();

  if (bridges_possible && (liquid_mode == LIQUID_PROTOCOL2 || liquid_mode == LIQUID_PROTOCOL3)) {
    update_bridges();
    exchange_liquid();
  }
  // compiled twice: a dry run (no type pair can hold a bridge, init_style) runs a loop
  // without any bridge code, ~14 % fewer instructions in the pair loop (callgrind,
  // bench/README.md): a scene pays only for what it uses
  if (bridges_possible)
    form_bridges_and_forces<true>();
  else
    form_bridges_and_forces<false>();
}

/* ----------------------------------------------------------------------
   at the setup of each run: every bridge's constants (cb_bridge) derived again under the
   current coefficients, which pair_coeff may have changed since the last run, or which a
   restart file does not hold (bridges read from it keep their volume)
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
      if (firsttouch[i][jj] == 0) continue;    // flagged 0: no bridge (see pair_force)
      cb_bridge *bridge = bridge_of(&firstvalue[i][SIZE_BRIDGE * jj]);
      if (bridge->active == 0.0) continue;
      const int j = jlist[jj] & NEIGHMASK;
      const int status = cb_bridge_set_volume(law(type[i], type[j]), radius[i], radius[j],
                                              bridge->volume, bridge);
      // (a corrupted history: CB_ERR_BRIDGE_STATE, which says so; a restart file of a
      // build whose history is laid out otherwise is refused before, by
      // read_restart_settings)
      check_cb(status, "bridge constants at setup", type[i], type[j], radius[i], radius[j],
               bridge->volume, 0.0);
    }
  }
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

/* ----------------------------------------------------------------------
   phase 2 (all modes): bridge formation and the forces
------------------------------------------------------------------------- */

template <bool BRIDGES> void PairGranCapillary::form_bridges_and_forces()
{
  const int history_update = update->setupflag ? 0 : 1;
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
      // Skip to the next pair to compute.  Apart, neither touching nor bridged at the last
      // step is the common case: no force, and no bridge can form (only at contact); its
      // history is all zero (see pair_force), so it is neither read nor written.  A loop
      // of its own, so that the compiler keeps its few values in registers: inside the
      // pair loop they were spilled around the pair's work, ~48 instructions a skipped
      // pair; this way 3 % fewer instructions in the whole run (callgrind, bench/README.md)
      for (; jj < jnum; jj++) {
        if (touch[jj] != 0) break;
        const int k = jlist[jj] & NEIGHMASK;
        const double dx = x[i][0] - x[k][0];
        const double dy = x[i][1] - x[k][1];
        const double dz = x[i][2] - x[k][2];
        if (!cb_certainly_apart(dx * dx + dy * dy + dz * dz, radius[i] + radius[k])) break;
      }
      if (jj >= jnum) break;
      int j = jlist[jj];
      const double factor_lj = special[sbmask(j)];
      j &= NEIGHMASK;
      if (factor_lj == 0.0) continue;
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double delz = x[i][2] - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const double radsum = radius[i] + radius[j];
      double *history = &allhistory[stride * jj];
      cb_bridge *bridge = bridge_of(history);
      const int jtype = type[j];
      const double r = sqrt(rsq);
      const double gap = r - radsum;
      const TypePair &tp = type_pair(itype, jtype);
      const cb_law *pair_law = tp.law;
      double capillary = 0.0;
      // (a run in which no type pair can hold a bridge: the contact forces alone)
      if (BRIDGES) {
        // The common case, a bridge held (in contact, or a richefeu bridge stretched within
        // its rupture distance), gives its force from the stored constants, inline (within
        // the reach: one held beyond it is ruptured by advance_bridge).  The rest is out of
        // line: inlined, it made the compiler spill the contact force code's values, ~3 %
        // more instructions and time in the wet loop (bench/README.md).  Dry pairs that
        // cannot get a bridge skip both.
        if (per_atom)
          capillary = protocol_bridge(i, j, gap, tp, bridge);
        else if (!(rsq < tp.cutsq &&
                   cb_bridge_held(pair_law, radius[i], radius[j], gap, bridge, &capillary)) &&
                 (bridge->active != 0.0 || (tp.formation_volume > 0.0 && wet_pair(i, j, tp))))
          capillary = advance_bridge(i, j, rsq, gap, tp, bridge);
      }
      pair_force<BRIDGES>(a, tp, i, j, delx, dely, delz, rsq, r, gap, capillary, history,
                          touch[jj], history_update);
    }
  }
}

/* ----------------------------------------------------------------------
   Protocols 2, 3: the bridges were advanced in update_bridges(); here a dry pair in
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
  double capillary = 0.0;
  if (bridge->active == 0.0) {
    if (gap <= 0.0 && wet_pair(i, j, tp)) {
      double offer_i = offer[i], offer_j = offer[j], available = 0.0;
      int status = cb_protocol2_take(&offer_i, &offer_j, &available);
      check_cb(status, "liquid take", itype, jtype, radius[i], radius[j], available, gap);
      if (available > 0.0) {
        cb_transition transition;
        double none = 0.0;
        status = cb_bridge_step(pair_law, radius[i], radius[j], gap, available, bridge,
                                &transition, &none, &capillary);
        check_cb(status, "bridge formation", itype, jtype, radius[i], radius[j],
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
        check_cb(status, "Protocol 3 deposit", itype, jtype, radius[i], radius[j], grown,
                 gap);
      }
    }
    int status = cb_bridge_force(pair_law, radius[i], radius[j], gap, bridge, &capillary);
    check_cb(status, "capillary force", itype, jtype, radius[i], radius[j],
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
  check_cb(status, "bridge update", itype, jtype, radius[i], radius[j],
           bridge->active != 0.0 ? bridge->volume : MAX(before, available), gap);
  if (transition == CB_BRIDGE_FORMED && counted(i, j)) n_formed += 1.0;
  if (transition == CB_BRIDGE_RUPTURED && counted(i, j)) n_ruptured += 1.0;
  if (transition != CB_BRIDGE_RUPTURED) vol = 0.0;
  if (bridge->active != 0.0 && rsq >= tp.cutsq) {
    // held beyond the reach (a volume above the one the reach was built for):
    // ruptured here, before the pair leaves the neighbor list with its liquid
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

template <bool BRIDGES>
void PairGranCapillary::pair_force(const AtomArrays &a, const TypePair &tp, int i, int j,
                                   double delx, double dely, double delz, double rsq, double r,
                                   double gap, double capillary, double *history, int &touch,
                                   int history_update)
{
  double **v = a.v;
  double **f = a.f;
  double **omega = a.omega;
  double **torque = a.torque;
  double *rmass = a.rmass;
  int *mask = a.mask;
  const int nlocal = a.nlocal;
  const int newton_pair = a.newton_pair;
  const double radi = a.radius[i], radj = a.radius[j];
  cb_bridge *bridge = bridge_of(history);
  double *shear = &history[HIST_SHEAR];

  // The flag (LAMMPS's neighbor-history "touch") is 1 while the pair touches or holds a
  // bridge, and a pair flagged 0 has an all-zero history: cleared here with the flag, by
  // Protocol 1 the same way, and by FixNeighHistory for every pair it does not carry over
  // at re-neighboring.  The pair loops rely on it to skip flagged-0 pairs that are apart.
  const int in_contact = tp.contact_on && gap < 0.0;
  touch = (in_contact || (BRIDGES && bridge->active != 0.0)) ? 1 : 0;
  if (!in_contact) {
    shear[0] = shear[1] = shear[2] = 0.0;
    if (!BRIDGES || capillary == 0.0) return;
  }

  if (r == 0.0) coincident_atoms(i, j);
  const double rinv = 1.0 / r;
  double contact = 0.0;
  double fs1 = 0.0, fs2 = 0.0, fs3 = 0.0;
  if (in_contact) {
    const double vr1 = v[i][0] - v[j][0];
    const double vr2 = v[i][1] - v[j][1];
    const double vr3 = v[i][2] - v[j][2];
    const double vnnr = vr1 * delx + vr2 * dely + vr3 * delz;
    const double gap_rate = vnnr * rinv;

    double mi = rmass[i], mj = rmass[j];
    double meff = mi * mj / (mi + mj);
    if (mask[i] & freeze_group_bit) meff = mj;
    if (mask[j] & freeze_group_bit) meff = mi;
    contact = cb_contact_normal_force(&tp.contact, gap, gap_rate, sqrt(meff));    // eqs. 2, 3

    // relative tangential velocity at the contact point
    const double rsqinv = 1.0 / rsq;
    const double vt1 = vr1 - delx * vnnr * rsqinv;
    const double vt2 = vr2 - dely * vnnr * rsqinv;
    const double vt3 = vr3 - delz * vnnr * rsqinv;
    const double wr1 = (radi * omega[i][0] + radj * omega[j][0]) * rinv;
    const double wr2 = (radi * omega[i][1] + radj * omega[j][1]) * rinv;
    const double wr3 = (radi * omega[i][2] + radj * omega[j][2]) * rinv;
    const double vtr1 = vt1 - (delz * wr2 - dely * wr3);
    const double vtr2 = vt2 - (delx * wr3 - delz * wr1);
    const double vtr3 = vt3 - (dely * wr1 - delx * wr2);

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
    double fs[3];
    cb_contact_tangential_force(&tp.contact, cb_contact_friction_limit(&tp.contact, contact),
                                shear, fs, history_update);    // eq. 12
    fs1 = fs[0];
    fs2 = fs[1];
    fs3 = fs[2];
  }

  const double ccel = (contact - capillary) * rinv;
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
  if (newton_pair || j < nlocal) {
    f[j][0] -= fx;
    f[j][1] -= fy;
    f[j][2] -= fz;
    torque[j][0] -= radj * tor1;
    torque[j][1] -= radj * tor2;
    torque[j][2] -= radj * tor3;
  }
  if (evflag) ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, fx, fy, fz, delx, dely, delz);
}

/* ----------------------------------------------------------------------
   time-step check, at setup and after every re-neighboring, warns once:
   dt > 0.1 pi sqrt(m_min / k), k the larger of k_n and the capillary stiffness bound
   (cb_capillary_stiffness_bound over the radius ranges and the bridge volumes in use).
   One reduction per call (the smallest mass per type and the volume range per type pair,
   packed into one MIN); the stiffness bound, ~10^3 force calls per type pair, is evaluated
   again only when a type pair's volume range has changed (in fixed mode: once per run).
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

void PairGranCapillary::check_timestep()
{
  if (dt_warned) return;
  const int n = atom->ntypes;
  const int np = (n + 1) * (n + 1);
  // [mass per type | smallest volume per type pair | minus the largest], all reduced by MIN
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
        double capillary = 0.0;
        const double ri[2] = {rad_min[i], rad_max[i]}, rj[2] = {rad_min[j], rad_max[j]};
        for (double vol : volumes) {
          if (!(vol > 0.0)) continue;
          for (double r1 : ri)
            for (double r2 : rj) {
              double k = 0.0;
              if (r1 > 0.0 && r2 > 0.0 &&
                  cb_capillary_stiffness_bound(law(i, j), r1, r2, vol, &k) == CB_OK)
                capillary = MAX(capillary, k);
            }
        }
        capillary_bound[ij] = capillary;
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
    check_cb(status, "capillary force (single)", itype, jtype, radi, radj, vol, gap);
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

/* ---------------------------------------------------------------------- */

void PairGranCapillary::reset_dt()
{
  dt = update->dt;
}

/* ----------------------------------------------------------------------
   restart: the settings and, per type pair, the pair_coeff arguments (re-parsed)
------------------------------------------------------------------------- */

void PairGranCapillary::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  const int n = atom->ntypes;
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (setflag[i][j]) {
        const std::string &text = coeff_text[(size_t) i * (n + 1) + j];
        int length = (int) text.size();
        fwrite(&length, sizeof(int), 1, fp);
        fwrite(text.data(), sizeof(char), length, fp);
      }
    }
}

void PairGranCapillary::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  const int n = atom->ntypes;
  const int me = comm->me;
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) {
      int flag = 0;
      if (me == 0) utils::sfread(FLERR, &flag, sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&flag, 1, MPI_INT, 0, world);
      if (!flag) continue;
      int length = 0;
      if (me == 0) utils::sfread(FLERR, &length, sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&length, 1, MPI_INT, 0, world);
      std::string text(length, ' ');
      if (me == 0 && length > 0) utils::sfread(FLERR, &text[0], sizeof(char), length, fp, nullptr, error);
      if (length > 0) MPI_Bcast(&text[0], length, MPI_CHAR, 0, world);
      auto words = utils::split_words(text);
      std::vector<char *> args;
      for (auto &w : words) args.push_back(&w[0]);
      parse_coeff(i, i, j, j, (int) args.size(), args.data());
    }
}

void PairGranCapillary::write_restart_settings(FILE *fp)
{
  // first the number of values a pair's history holds (its layout): FixNeighHistory stores
  // them without it, and reads them with the count of the fix it restores into, so a file
  // of another layout would be misread (bridges shifted into other pairs' values)
  fwrite(&history_size, sizeof(int), 1, fp);
  // then the settings' format (files before the contact law moved into the core have the
  // friction setting, 0 or 1, here and the dashpot as a double) and the dashpot rule
  const int settings_format = SETTINGS_FORMAT;
  const int rule = (int) dashpot;
  fwrite(&settings_format, sizeof(int), 1, fp);
  fwrite(&rule, sizeof(int), 1, fp);
}

void PairGranCapillary::read_restart_settings(FILE *fp)
{
  if (comm->me == 0) {
    utils::sfread(FLERR, &history_size, sizeof(int), 1, fp, nullptr, error);
    // (files of builds before this check start with the friction setting, 0 or 1)
    if (history_size != SIZE_CONTACT && history_size != SIZE_BRIDGE)
      error->one(FLERR, "pair gran/capillary: this restart file was written by a build whose "
                 "pair history is laid out otherwise (read {} where this build writes {} "
                 "values a pair, or {} with no liquid): its bridges cannot be read; write it "
                 "again with the build that made it, or start from a data file", history_size,
                 (int) SIZE_BRIDGE, (int) SIZE_CONTACT);
    int format = 0, rule = 0;
    utils::sfread(FLERR, &format, sizeof(int), 1, fp, nullptr, error);
    if (format == 0 || format == 1) {
      // an earlier file: format is its friction setting (1: 'friction wet'), then the
      // dashpot's closing-rate floor (0: approach, -inf: both)
      double floor = 0.0;
      utils::sfread(FLERR, &floor, sizeof(double), 1, fp, nullptr, error);
      rule = floor == 0.0 ? CB_DASHPOT_APPROACH : CB_DASHPOT_BOTH;
      if (format == 1)
        error->warning(FLERR, "pair gran/capillary: this restart file was written with "
                       "'friction wet', which counted the capillary attraction twice in the "
                       "Coulomb limit; it runs on with Richefeu 2007 eq. 12, mu (f_n^e + "
                       "f_n^d): sliding contacts carry less tangential force than before");
    } else if (format == SETTINGS_FORMAT) {
      utils::sfread(FLERR, &rule, sizeof(int), 1, fp, nullptr, error);
    } else {
      error->one(FLERR, "pair gran/capillary: this restart file holds settings of format {}, "
                 "which this build does not know (it writes {})", format, (int) SETTINGS_FORMAT);
    }
    if (rule != CB_DASHPOT_APPROACH && rule != CB_DASHPOT_BOTH && rule != CB_DASHPOT_REPULSIVE)
      error->one(FLERR, "pair gran/capillary: this restart file holds dashpot rule {}: allowed "
                 "0 (approach), 1 (both), 2 (repulsive)", rule);
    dashpot = (cb_dashpot_rule) rule;
  }
  MPI_Bcast(&history_size, 1, MPI_INT, 0, world);
  int rule = (int) dashpot;
  MPI_Bcast(&rule, 1, MPI_INT, 0, world);
  dashpot = (cb_dashpot_rule) rule;
}

/* ---------------------------------------------------------------------- */

double PairGranCapillary::memory_usage()
{
  return (double) nmax_scratch * (5 * sizeof(double) + sizeof(tagint));
}
