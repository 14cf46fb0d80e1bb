/* ----------------------------------------------------------------------
   capbridge — LAMMPS binding: pair style gran/capillary, its coefficients

   Member functions of PairGranCapillary that read and keep the coefficients: pair_style
   settings, pair_coeff (into the TypePair records, the only copy), init_one (the
   constants the pair loops derive from them) and the restart file (the settings and the
   pair_coeff arguments, parsed again on reading).  A file of its own: what the input
   script and restart files say, checked once, apart from the loops that use it.
------------------------------------------------------------------------- */

#include "pair_gran_capillary.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"

#include <cmath>
#include <cstring>
#include <set>
#include <string>

using namespace LAMMPS_NS;

namespace {
// the syntax of pair_coeff; each law's own keywords as the core's rows list them
std::string coeff_syntax()
{
  std::string syntax =
      "syntax: pair_coeff I J kn kt damping mu law LAW [keyword value ...] or "
      "pair_coeff I J contact none law LAW [keyword value ...]; keywords: gamma, theta, "
      "rupture, overlap, validity";
  for (int m = 0; m < CB_MODEL_COUNT; ++m)
    for (int k = 0; k < cb_law_keyword_count((cb_model) m); ++k)
      syntax += fmt::format(", {}", cb_law_keyword_of((cb_model) m, k)->name);
  return syntax + ", volume";
}
}    // namespace

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
  if (narg < 2) error->all(FLERR, "pair_coeff: missing type indices; {}", coeff_syntax());
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
  TypePair given;    // what this pair_coeff gives every type pair of its ranges
  const int iarg = parse_contact(where, narg, arg, given);
  cb_law one;
  std::string spec;
  parse_law(where, iarg, narg, arg, one, spec, given.volume);
  const int index = prepared_law(where, one, spec);

  std::string text;
  for (int k = 0; k < narg; k++) text += (k ? " " : "") + std::string(arg[k]);

  int count = 0;
  const int n = atom->ntypes;
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      TypePair &tp = type_pairs[i * type_stride + j];
      tp.contact = given.contact;
      tp.volume = given.volume;
      tp.law = laws[index];
      tp.contact_on = given.contact_on;
      tp.law_index = index;
      type_pairs[j * type_stride + i] = tp;
      coeff_text[(size_t) i * (n + 1) + j] = text;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "{}: no type pair I <= J in these ranges", where);
}

/* ----------------------------------------------------------------------
   pair_coeff, the contact part: 'kn kt damping mu' or 'contact none' into tp.contact and
   tp.contact_on; returns the index of the next argument
------------------------------------------------------------------------- */

int PairGranCapillary::parse_contact(const std::string &where, int narg, char **arg,
                                     TypePair &tp)
{
  auto number = [&](int k, const char *name, const char *meaning) -> double {
    if (k >= narg)
      error->all(FLERR, "{}: missing coefficient {} ({}); {}", where, name, meaning,
                 coeff_syntax());
    if (!utils::is_double(arg[k])) {
      if (strcmp(arg[k], "law") == 0 || strcmp(arg[k], "contact") == 0)
        error->all(FLERR, "{}: missing coefficient {} ({}) before '{}'; {}", where, name,
                   meaning, arg[k], coeff_syntax());
      error->all(FLERR, "{}: coefficient {} ({}) must be a number, not '{}'; {}", where, name,
                 meaning, arg[k], coeff_syntax());
    }
    return utils::numeric(FLERR, arg[k], false, lmp);
  };

  tp.contact = cb_contact_law{};    // contact none: all zero
  tp.contact_on = 1;
  if (narg > 0 && strcmp(arg[0], "contact") == 0) {
    if (narg < 2 || strcmp(arg[1], "none") != 0)
      error->all(FLERR, "{}: 'contact' must be followed by 'none' (no contact force: the "
                 "capillary force only); {}", where, coeff_syntax());
    tp.contact_on = 0;
    return 2;
  }
  const double kn_one = number(0, "kn", "normal stiffness, force/distance");
  const double kt_one = number(1, "kt", "tangential stiffness, force/distance");
  const double damping_one = number(2, "damping", "normal damping rate alpha_n, 0..1");
  const double mu_one = number(3, "mu", "friction coefficient");
  // the core's rule for the coefficients (the dashpot rule is pair_style's, applied by
  // init_one: any one here)
  cb_message msg;
  if (cb_contact_law_init(&tp.contact, kn_one, kt_one, damping_one, mu_one, CB_DASHPOT_APPROACH,
                          &msg) != CB_OK)
    error->all(FLERR, "{}: {}", where, msg.text);
  return 4;
}

/* ----------------------------------------------------------------------
   pair_coeff, from arg[iarg]: 'law LAW [keyword value ...]' into the law `one` (not yet
   prepared), its specification `spec` and the bridge volume (-1: not given)
------------------------------------------------------------------------- */

void PairGranCapillary::parse_law(const std::string &where, int iarg, int narg, char **arg,
                                  cb_law &one, std::string &spec, double &volume_one)
{
  if (iarg >= narg || strcmp(arg[iarg], "law") != 0)
    error->all(FLERR, "{}: missing 'law LAW' after the contact coefficients{} (laws: {}); {}",
               where, iarg < narg ? fmt::format(", found '{}'", arg[iarg]) : "",
               cb_law_names(), coeff_syntax());
  if (iarg + 1 >= narg)
    error->all(FLERR, "{}: 'law' needs a law name: allowed {}", where, cb_law_names());
  cb_model model;
  if (cb_model_from_name(arg[iarg + 1], &model) != CB_OK)
    error->all(FLERR, "{}: unknown law '{}': allowed {}", where, arg[iarg + 1], cb_law_names());
  spec = arg[iarg + 1];
  iarg += 2;

  // gamma has no default: a placeholder until the keyword is read
  cb_law_init(&one, model, 1.0, 0.0);
  int have_gamma = 0;
  volume_one = -1.0;
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
}

/* ----------------------------------------------------------------------
   the index in laws of the prepared law equal to `one`, prepared now if new: one prepared
   law per distinct law (by value: 'gamma 0.0728' and 'gamma 7.28e-2 theta 0' are one law)
------------------------------------------------------------------------- */

int PairGranCapillary::prepared_law(const std::string &where, const cb_law &one,
                                    const std::string &spec)
{
  int index = -1;
  for (size_t k = 0; k < laws.size(); k++)
    if (cb_law_same(laws[k], &one)) index = (int) k;
  if (index >= 0) return index;
  cb_message msg;
  msg.text[0] = '\0';
  auto *prepared = new cb_law(one);
  if (cb_law_prepare(prepared, &msg) != CB_OK) {
    cb_law_release(prepared);
    delete prepared;
    error->all(FLERR, "{}: law {}: {}", where, cb_model_name(one.model), msg.text);
  }
  laws.push_back(prepared);
  law_text.push_back(spec);
  return (int) laws.size() - 1;
}

/* ---------------------------------------------------------------------- */

double PairGranCapillary::init_one(int i, int j)
{
  if (setflag[i][j] == 0)
    error->all(FLERR, "pair gran/capillary: no pair_coeff for types {} {} (coefficients are not "
               "mixed: give every type pair I <= J)", i, j);
  double design_rupture = 0.0;
  const double cut = pair_cutoff(i, j, design_rupture);

  // the pair loops' constants (init() calls init_one for every pair before a run)
  TypePair &tp = type_pairs[i * type_stride + j];
  const cb_contact_law given = tp.contact;
  cb_message msg;
  if (cb_contact_law_init(&tp.contact, given.normal_stiffness, given.tangential_stiffness,
                          given.damping_rate, given.friction, dashpot, &msg) != CB_OK)
    error->all(FLERR, "pair gran/capillary: types {} {}: {}", i, j, msg.text);    // (checked by pair_coeff)
  tp.formation_volume = liquid_mode == LIQUID_FIXED ? design_volume(i, j) : 0.0;
  tp.cutsq = cut * cut;
  tp.design_rupture = design_rupture;
  type_pairs[j * type_stride + i] = tp;
  return cut;
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
