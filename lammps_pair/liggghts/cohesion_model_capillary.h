/* ----------------------------------------------------------------------
   cohesion_model_capillary.h — `cohesion capillary` for LIGGGHTS-PUBLIC 3.8.0:
   liquid-bridge (capillary) cohesion between spheres, computed by the capbridge C core.

   Part of capbridge (lammps_pair/liggghts/; documentation in README.md and
   doc/cohesion_model_capillary.txt there). This header is copied into LIGGGHTS's src/
   by scripts/build_liggghts.sh and compiled with the rest of LIGGGHTS: it is valid
   C++98 and C++11. It includes one header of the core, capbridge.h, and links against
   the core's static library (libcapbridge.a).

     pair_style gran model hertz tangential history cohesion capillary law willett &
                rupture default overlap contact validity extend liquid fixed tally off

   What lives where:
     - the force, the rupture distance, the bridge transitions (form / hold / rupture)
       and Richefeu's Protocols 1, 2 and 3 (the distribution of eqs. 13-14, the split of
       a broken bridge's liquid, the k-way share and take-all at formation, the
       receiver) are the core's: cb_bridge_step, cb_bridge_force, cb_protocol2_release,
       cb_protocol_grain_step, cb_protocol2_take, cb_protocol1_distribute,
       cb_protocol3_better. This file only gathers the engine's data, stores the bridge
       state in LIGGGHTS's contact history and does the MPI communication.
     - the bridge state of a pair, a cb_bridge (its volume, and the constants the core
       derives from it, so that a bridge in contact costs no force-law evaluation), is
       seven values of the contact history (capillaryBridgeVolume, ...Active, ...Rupture,
       ...ForceContact, ...RadiusSum, ...RadiusProduct, ...InverseDecayLength): it moves
       with the atoms, survives re-neighboring and goes into restart files with the rest
       of the contact history. The constants are derived again in the setup pass of every run
       (the coefficients may have changed since the bridges formed).
     - parameters come from fix property/global (surfaceTension, contactAngle,
       bridgeVolume), per-particle free liquid from fix property/atom freeLiquid.
     - walls: in a fix wall/gran, the same model makes the bridges between grains and the
       wall (capbridge_liggghts_wall.h), of fixed volume or, at primitive walls, under
       Protocols 2 and 3 with the pair's liquid: then the end of the pair's pass (the
       formations of the step, the pair's and the walls', with the count of both) waits for
       the walls, in fix capillaryFinish (capbridge_liggghts_pass.h, fix_capillary_finish.h).
     - beside this file: capbridge_liggghts_settings.h (the keywords), _laws.h (the law of
       each pair of atom types), _reach.h (how far
       LIGGGHTS visits a pair, the contact distance factor, and the bridges held beyond it,
       both by the core's rules), _liquid.h (the liquid account of the protocols: warnings
       when liquid leaves with atoms or a new pair_style), _timestep.h (the time-step check
       against the capillary stiffness), _protocols.h (the keywords every and vmax, and
       Protocols 1 and 3: _protocol1.h, _protocol3.h; start and remove: _start.h), _viscous.h
       (keyword viscous: the bridges' viscous force), _checks.h (the input's checks), _wall.h
       (the model in a fix wall/gran).

   Parallel consistency (LIGGGHTS requires `newton off` with contact history): a pair
   whose atoms live on two ranks is computed on both, each rank updating only its own
   atoms. Both copies take the same decisions because they see the same positions and
   (Protocol 2) the same free liquid: the free liquid of ghosts is communicated at the
   start of every force pass, and the bridges that form in a pass take the free liquid
   as it was at its start. When k bridges form on one particle in the same step, each
   takes 1/k of that particle's free liquid (Richefeu 2007 does not say; an equal split
   keeps the result independent of the order of the neighbor list and of the number of
   ranks). Liquid a bridge releases in a step is free liquid from the next step on.
------------------------------------------------------------------------- */

#ifdef COHESION_MODEL
COHESION_MODEL(COHESION_CAPILLARY,capillary,9)
#else

#ifndef COHESION_MODEL_CAPILLARY_H_
#define COHESION_MODEL_CAPILLARY_H_

#include "contact_models.h"
#include "cohesion_model_base.h"
#include "capbridge_liggghts_settings.h"
#include "capbridge_liggghts_tally.h"
#include "capbridge_liggghts_checks.h"
#include "capbridge_liggghts_formations.h"
#include "capbridge_liggghts_laws.h"
#include "capbridge_liggghts_liquid.h"
#include "capbridge_liggghts_pass.h"
#include "capbridge_liggghts_protocols.h"
#include "capbridge_liggghts_reach.h"
#include "capbridge_liggghts_timestep.h"
#include "capbridge_liggghts_viscous.h"
#include "capbridge_liggghts_wall.h"
#include "capbridge.h"
#include "global_properties.h"
#include "fix_property_atom.h"
#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_capillary_finish.h"
#include "fix_contact_history.h"
#include "force.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace MODEL_PARAMS
{
    /* bridgeVolume: the liquid volume of a new bridge [m^3], per pair of atom types
     * (liquid fixed). Not `static`: one creator address in every translation unit. */
    inline MatrixProperty* createCapillaryBridgeVolume(PropertyRegistry & registry,
                                                       const char * caller, bool)
    {
        return createPerTypePairProperty(registry, "bridgeVolume", caller);
    }
}


namespace LIGGGHTS {
namespace ContactModels {

  template<>
  class CohesionModel<COHESION_CAPILLARY> : public CohesionModelBase,
                                             public capbridge_liggghts::LiquidPass,
                                             public capbridge_liggghts::FormationSink {

  public:
    CohesionModel(LAMMPS * lmp, IContactHistorySetup * hsetup, class ContactModelBase * cmb) :
      CohesionModelBase(lmp, hsetup, cmb),
      wall_(cmb->is_wall()),
      history_offset_(-1),
      law_given_(false),
      law_keywords_(capbridge_liggghts::law_keyword_words()),
      tally_(false),
      per_atom_liquid_(false),
      model_(CB_MODEL_WILLETT),
      surface_tension_(0.0),
      contact_angle_(NULL),
      bridge_volume_(NULL),
      ntypes_(0),
      fix_free_(NULL),
      formations_(lmp),
      updating_(false),
      open_(false),
      nwalls_(0),
      finish_fix_(NULL),
      census_(false),
      counting_(false),
      timing_(false),
      account_(lmp),
      reach_(lmp),
      timestep_(lmp),
      protocols_(lmp),
      wall_bridges_(lmp)
    {
      // a cb_bridge, in its field order (none changes sign with the pair's order); a wall's
      // contact history has the same seven values
      static_assert(CB_BRIDGE_DOUBLES == 7, "one history value per field of cb_bridge");
      history_offset_ = hsetup->add_history_value("capillaryBridgeVolume", "0");
      hsetup->add_history_value("capillaryBridgeActive", "0");
      hsetup->add_history_value("capillaryBridgeRupture", "0");
      hsetup->add_history_value("capillaryBridgeForceContact", "0");
      hsetup->add_history_value("capillaryBridgeRadiusSum", "0");
      hsetup->add_history_value("capillaryBridgeRadiusProduct", "0");
      hsetup->add_history_value("capillaryBridgeInverseDecayLength", "0");
      if (wall_) wall_bridges_.attach(hsetup, history_offset_);
    }

    /* a pair_style issued again deletes this model, not fix capillaryFinish */
    ~CohesionModel()
    {
      const int k = finish_fix_ ? modify->find_fix("capillaryFinish") : -1;
      if (k >= 0 && modify->fix[k] == finish_fix_ && finish_fix_->pass == this)
        finish_fix_->pass = NULL;
    }

    void registerSettings(Settings & settings)
    {
      using namespace capbridge_liggghts;
      register_word(settings, "law", "", &check_law, law_name_, &law_given_, input);
      register_word(settings, "rupture", "default", &check_rupture, rupture_, NULL, input);
      register_word(settings, "overlap", "contact", &check_overlap, overlap_, NULL, input);
      register_word(settings, "validity", "extend", &check_validity, validity_, NULL, input);
      // each law's own keywords, from the core's rows: law name + "_" + keyword (richefeu_c)
      for (size_t k = 0; k < law_keywords_.size(); ++k) {
        capbridge_liggghts::LawKeywordWord &word = law_keywords_[k];
        const char *initial = cb_law_keyword_of(word.model, word.index)->default_text;
        register_word(settings, word.spelling, initial, &check_law_keyword, word.value,
                      &word.given, input);
      }
      register_word(settings, "liquid", "fixed", &check_liquid, liquid_, NULL, input);
      // on/off as words: LIGGGHTS's own on/off reader reads past the end of the command
      // when the keyword is its last word (std::string from NULL: SIGABRT)
      register_word(settings, "tally", "off", &check_on_off, tally_word_, NULL, input);
      register_word(settings, "viscous", "off", &check_on_off, viscous_word_, NULL, input);
      protocols_.register_settings(settings, input);
      register_removed(settings, "capillary_friction",
                       "cohesion model capillary: keyword 'capillary_friction' was removed: the "
                       "Coulomb limit of the tangential model is always mu |f_n^e + f_n^d|, the "
                       "normal model's contact force alone (Richefeu 2007 eq. 12 with the f_n "
                       "of his eq. 1); the former default 'capillary_friction on' added the "
                       "capillary attraction to it, counting it twice, and 'capillary_friction "
                       "off' is what every run now does: delete the keyword");
    }

    inline void postSettings(IContactHistorySetup *, ContactModelBase *)
    {
      per_atom_liquid_ = (liquid_ != "fixed");
      tally_ = (tally_word_ == "on");
      if (law_given_) {
        if (cb_model_from_name(law_name_.c_str(), &model_) != CB_OK)
          fail_all("cohesion model capillary: law '" + law_name_ + "' is unknown; allowed: " +
                   cb_law_names());
      }
      if (wall_) {
        // what the wall bridges do not have yet: said, not ignored
        // (no fix made here: this runs inside fix wall/gran's constructor, in Modify::add_fix)
        if (protocols_.given_any())
          fail_all("cohesion model capillary in a fix wall/gran: the keywords every, vmax, "
                   "start, remove and remove_seed are the pair_style's (the wall's bridges "
                   "take the pair's liquid and its reach)");
        if (tally_ || viscous_word_ == "on")
          fail_all("cohesion model capillary in a fix wall/gran takes neither 'tally on' nor "
                   "'viscous on' (the pair_style's tally counts the bridges between grains)");
        return;
      }
      protocols_.post_settings(liquid_, error);  // (an error for a keyword it does not take)
      connect_internal_fixes();
      if (per_atom_liquid_) account_.create();
      if (protocols_.protocol3) protocols_.receivers.create();
    }

    void connectToProperties(PropertyRegistry & registry)
    {
      const char *caller = "cohesion model capillary";
      if (!law_given_)
        fail_all(std::string("cohesion model capillary needs 'law NAME' after "
                             "'cohesion capillary' in ") +
                 (wall_ ? "fix wall/gran" : "pair_style gran") + "; NAME is one of " +
                 cb_law_names());
      if (force->cg_active())
        error->cg(FLERR, "cohesion model capillary");
      if (force->newton_pair && !wall_)
        error->all(FLERR, "cohesion model capillary requires 'newton off'");

      registry.registerProperty("surfaceTension", &MODEL_PARAMS::createSurfaceTension);
      registry.registerProperty("contactAngle", &MODEL_PARAMS::createContactAngle);
      registry.connect("surfaceTension", surface_tension_, caller);
      registry.connect("contactAngle", contact_angle_, caller);
      // a wall's liquid is the pair_style's: checked before the properties it would need
      if (wall_) wall_bridges_.connect_liquid(capbridge_liggghts::pair_pass(modify), liquid_);
      if (!per_atom_liquid_) {
        registry.registerProperty("bridgeVolume", &MODEL_PARAMS::createCapillaryBridgeVolume);
        registry.connect("bridgeVolume", bridge_volume_, caller);
      }
      ntypes_ = registry.max_type();

      capbridge_liggghts::check_properties(error, surface_tension_, contact_angle_,
                                           per_atom_liquid_ ? NULL : bridge_volume_, ntypes_);
      const capbridge_liggghts::LawWords words = {model_, law_name_, rupture_, overlap_,
                                                  validity_, law_keywords_};
      if (viscous_word_ == "on") viscous_.connect(registry, error, ntypes_);
      laws_.build(error, words, surface_tension_, contact_angle_, viscous_.viscosity,
                  viscous_.min_gap, ntypes_, wall_);
      const capbridge_liggghts::ReachLaws laws = {&laws_.laws, &laws_.pair_law, ntypes_,
                                                  law_name_.c_str(),
                                                  rupture_.c_str(), validity_.c_str()};
      if (wall_) {
        wall_bridges_.connect(registry, laws, bridge_volume_);
        return;
      }
      connect_per_atom();
      reach_.register_factor(registry, laws, per_atom_liquid_ ? NULL : bridge_volume_,
                             per_atom_liquid_ ? fix_free_->vector_atom : NULL,
                             protocols_.vmax(), history_offset_);
      protocols_.connect(laws_.laws, liquid_);
      // (before the walls' models connect, in fix wall/gran's init: they find this model
      // through the fix, for its liquid, its tally, and under Protocols 2, 3 its pass)
      nwalls_ = 0;
      walls_.clear();
      open_ = false;
      finish_fix_ = capbridge_liggghts::make_finish_fix(modify, error, this);
    }

    /* ------------------------------------------ the pass as the walls see it (LiquidPass) */

    long long attach_wall(capbridge_liggghts::WallSource *source)
    {
      walls_.push_back(std::make_pair(-(++nwalls_), source));
      return walls_.back().first;
    }
    const char *liquid() const { return liquid_.c_str(); }
    const cb_law *distribution_law() const
    {
      return protocols_.protocol1 || protocols_.start.bridges ? &laws_.laws[0] : NULL;
    }
    bool distributes() const { return protocols_.protocol1; }
    double design_volume() const { return reach_.design_volume(); }
    bool open() const { return open_; }
    double free_liquid(const int i) const { return fix_free_->vector_atom[i]; }

    void wall_formation(const capbridge_liggghts::WallBridge &b) { formations_.add_wall(b); }

    void wall_release(const int i, const double r, const double volume)
    {
      double grain = 0.0, wall = 0.0;  // the wall holds no liquid: all of it to the grain
      check_at(cb_protocol2_release(volume, r, CB_PLANE, &grain, &wall),
               "Protocol 2 release at a wall", i, -1, 0.0, volume);
      formations_.released[i] += grain;
    }

    bool removing() const { return protocols_.start.removing(); }

    void wall_removal(const capbridge_liggghts::WallBridge &b, cb_bridge *bridge)
    {
      const double held = bridge->volume;
      double volume = 0.0;
      if (protocols_.start.chosen(atom->tag[b.i], b.key)) {
        check_at(cb_bridge_remove(b.gap, bridge, &volume), "bridge removal at a wall", b.i, -1,
                 b.gap, held);
        wall_release(b.i, b.r, volume);
      }
      protocols_.start.count(true, volume, held);  // a wall bridge is on its grain's rank only
    }

    void wall_held(const capbridge_liggghts::WallBridge &b, const double volume)
    {
      if (counting_) account_.add_bridge(true, volume);  // all of it: its one grain's
      if (tally_) per_atom_tally_.wall(b.i, volume, 1.0);
      if (protocols_.protocol3) protocols_.receivers.offer_wall(b);
    }

    void finish_deferred()
    {
      if (open_) end_pass();
    }

    void beginPass(SurfacesIntersectData & sidata, ForceData &, ForceData &)
    {
      if (wall_) return;
      // state changes only in real force passes (also in setup: the bridge that
      // exists at the start is formed there); not for compute pair/gran/local
      updating_ = sidata.computeflag != 0;
      if (!updating_) return;
      // the census passes: setup and re-neighboring (when atoms may have left or come)
      const bool census = update->setupflag || neighbor->ago == 0;
      if (neighbor->ago == 0)  // the box as the list was built
        capbridge_liggghts::check_periodic_images(domain, neighbor, error);
      census_ = census;
      counting_ = per_atom_liquid_ && census;
      timing_ = census && timestep_.wanted();
      if (timing_) timestep_.begin(ntypes_);
      const int nall = atom->nlocal + atom->nghost;
      if (per_atom_liquid_) {
        if (open_)
          error->all(FLERR, "cohesion model capillary: the last step's liquid pass was not "
                            "finished: fix capillaryFinish, which finishes it after the walls, "
                            "was deleted; do not unfix it");
        open_ = true;
        if (counting_) account_.begin(fix_free_->vector_atom);
        protocols_.begin_pass(laws_.laws, history_offset_, fix_free_->vector_atom, reach_,
                              walls_);
        fix_free_->do_forward_comm();
        formations_.begin();
      }
      if (tally_) per_atom_tally_.begin(nall);
    }

    void endPass(SurfacesIntersectData &, ForceData &, ForceData &)
    {
      if (wall_ || !updating_) return;
      // with walls in the pass, fix capillaryFinish ends it after them (finish_deferred)
      if (!(open_ && nwalls_ > 0)) end_pass();
    }

    /* The end of an updating pass: the formations of the step (the pair's and the walls'),
     * the removal's report, the census, the time-step check. */
    void end_pass()
    {
      updating_ = false;
      open_ = false;
      if (per_atom_liquid_) finish_formations();
      if (protocols_.start.removing()) protocols_.start.report(liquid_);
      if (counting_) account_.end(fix_free_->vector_atom);
      if (census_) reach_.report_beyond();
      if (timing_)
        timestep_.finish(laws_.laws, laws_.pair_law,
                         per_atom_liquid_ ? NULL : bridge_volume_, viscous_.viscosity != NULL);
    }

    /* a bridge that exists after this pass's transitions, in a census pass */
    void census_bridge(const int itype, const int jtype, const bool j_local, const double volume)
    {
      if (counting_) account_.add_bridge(j_local, volume);
      if (timing_ && per_atom_liquid_) timestep_.add_bridge(itype, jtype, volume);
    }

    inline void endSurfacesIntersect(SurfacesIntersectData &, ForceData &, ForceData &) {}

    void surfacesIntersect(SurfacesIntersectData & sidata, ForceData & i_forces, ForceData & j_forces)
    {
      const double gap = sidata.r - sidata.radsum;  // a wall's radsum is the grain's radius
      const double capillary =
          wall_ ? wall_force(sidata, gap, sidata.en) : pair_force(sidata, gap, sidata.en);
      // sidata.Fn is left as the normal model set it, f_n^e + f_n^d: the tangential model
      // (called after this one) limits its force by mu |sidata.Fn|, Richefeu 2007 eq. 12
      // mu (f_n - f_n^c) with eq. 1's f_n = f_n^e + f_n^d + f_n^c: the contact force alone
      if (capillary > 0.0) apply(capillary, sidata.en, i_forces, j_forces);
    }

    void surfacesClose(SurfacesCloseData & scdata, ForceData & i_forces, ForceData & j_forces)
    {
      // dry (no bridge, no removed bridge's mark: cb_bridge_dry) and certainly apart: no
      // force, and no bridge can form (only at contact), so no square root and no call into
      // the core; not at a run's setup, where pair_force checks every stored state once (a
      // restart file's: active 0 with other values is corrupt)
      cb_bridge stored;
      if (scdata.contact_history)
        std::memcpy(&stored, &scdata.contact_history[history_offset_], sizeof stored);
      if (scdata.contact_history && cb_bridge_dry(&stored) && !update->setupflag &&
          cb_certainly_apart(scdata.rsq, scdata.radsum)) {
        if (scdata.contact_flags) *scdata.contact_flags &= ~CONTACT_COHESION_MODEL;
        return;
      }
      const double r = std::sqrt(scdata.rsq);
      const double rinv = 1.0 / r;
      const double en[3] = {scdata.delta[0] * rinv, scdata.delta[1] * rinv,
                            scdata.delta[2] * rinv};
      const double gap = r - scdata.radsum;
      const double capillary = wall_ ? wall_force(scdata, gap, en) : pair_force(scdata, gap, en);
      if (capillary > 0.0) {
        apply(capillary, en, i_forces, j_forces);
        scdata.has_force_update = true;
      }
      if (viscous_.viscosity && gap > 0.0 && viscous_force(scdata, gap, en, i_forces, j_forces))
        scdata.has_force_update = true;
    }

  private:
    /* The bridge of a grain and the wall of a fix wall/gran (j is the wall): fixed volume,
     * or the pair's Protocol 2 or 3 (en: from the wall to the grain). */
    double wall_force(SurfacesCloseData & d, const double gap, const double *en)
    {
      return wall_bridges_.force(laws_.of(d.itype, d.jtype), d, gap,
                                 per_atom_liquid_ ? 0.0 : bridge_volume_[d.itype][d.jtype], en);
    }

    /* The bridge of one pair: its transition (in updating passes) and its force. */
    double pair_force(SurfacesCloseData & d, const double gap, const double *en)
    {
      if (!d.contact_history)
        fail_one("cohesion model capillary: no contact history for a pair (internal)");
      double * const hist = &d.contact_history[history_offset_];
      cb_bridge bridge;
      std::memcpy(&bridge, hist, sizeof bridge);

      const int i = d.i, j = d.j;
      const int nlocal = atom->nlocal;
      const bool j_local = j < nlocal;
      // The core gets the radii in a fixed order (smaller first), so that the two ranks
      // holding a pair, which see it as (i, j) and (j, i), compute the same numbers.
      const bool swap = d.radj < d.radi;
      const double ra = swap ? d.radj : d.radi;
      const double rb = swap ? d.radi : d.radj;
      const cb_law *law = laws_.of(d.itype, d.jtype);
      if (updating_ && update->setupflag) {
        // every state checked once where it enters (a restart file's, at the first pass of a
        // run), so that cb_bridge_held below may read only what it uses; a restart file of a
        // build whose history was laid out otherwise (2 values a pair before the bridge kept
        // its constants) is CB_ERR_BRIDGE_STATE, which says so
        check(cb_bridge_check_state(&bridge), "bridge state at setup", d, gap, bridge.volume);
        if (bridge.active != 0.0) {
          check(cb_bridge_set_volume(law, ra, rb, bridge.volume, &bridge),
                "bridge constants at setup", d, gap, bridge.volume);
          std::memcpy(hist, &bridge, sizeof bridge);
        }
      }
      if (updating_ && protocols_.start.removing() && bridge.active != 0.0)
        remove_if_chosen(bridge, hist, ra, rb, swap, d, gap);
      // the force of the bridge's state after this pass: from cb_bridge_step where the
      // bridge is advanced, else from cb_bridge_force below
      double capillary = 0.0;
      bool have_force = false;

      if (updating_ && cb_bridge_held(law, ra, rb, gap, &bridge, &capillary)) {
        // the common case, a bridge held in contact: its stored force, inline
        have_force = true;
      } else if (updating_ && (!cb_bridge_dry(&bridge) || gap <= 0.0)) {
        // (a dry unmarked pair that does not touch stays dry: nothing to do)
        if (!per_atom_liquid_) {
          const double available = bridge_volume_[d.itype][d.jtype];
          cb_transition change = CB_BRIDGE_STAYS_DRY;
          double released = 0.0;
          const bool forming = bridge.active == 0.0 && available > 0.0;
          const double before = forming ? available : bridge.volume;
          check(cb_bridge_step(law, ra, rb, gap, available, &bridge, &change, &released,
                               &capillary),
                forming ? "bridge update (a new bridge of bridgeVolume)" : "bridge update", d,
                gap, before);
          have_force = true;
          // fixed volume: the liquid of a broken bridge leaves the system
        } else {
          if (!cb_bridge_dry(&bridge)) {  // a bridge, or a removed one's mark (gone at gap >= 0)
            cb_transition change = CB_BRIDGE_HELD;
            double released = 0.0;
            check(cb_bridge_step(law, ra, rb, gap, 0.0, &bridge, &change, &released,
                                 &capillary), "bridge update", d, gap, bridge.volume);
            have_force = true;
            if (change == CB_BRIDGE_RUPTURED) release(released, ra, rb, swap, d, gap);
          }
          if (cb_bridge_may_form(&bridge, gap) && !protocols_.protocol1)  // (P1: distributes)
            formations_.add_pair(d, hist, law, ra, rb, swap, gap, en, fix_free_->vector_atom);
        }
        std::memcpy(hist, &bridge, sizeof bridge);
      }
      if (updating_ && bridge.active != 0.0 && reach_.beyond(d.itype, d.jtype, gap))
        rupture_beyond_reach(bridge, hist, ra, rb, swap, d, gap);
      if (updating_ && tally_ && bridge.active != 0.0)
        per_atom_tally_.pair(i, j_local ? j : -1, bridge.volume);
      if (updating_ && protocols_.protocol3 && bridge.active != 0.0)
        protocols_.receivers.offer(d, hist, law, ra, rb, gap, en[2]);

      // keeps the pair's history through re-neighboring while a bridge or a mark exists
      if (d.contact_flags && cb_bridge_dry(&bridge)) *d.contact_flags &= ~CONTACT_COHESION_MODEL;
      else if (d.contact_flags) *d.contact_flags |= CONTACT_COHESION_MODEL;
      if (bridge.active == 0.0) return 0.0;
      if (updating_) census_bridge(d.itype, d.jtype, j_local, bridge.volume);
      if (!have_force)
        check(cb_bridge_force(law, ra, rb, gap, &bridge, &capillary), "force", d, gap,
              bridge.volume);
      return capillary;
    }

    /* viscous on: the viscous force of the pair's bridge (after this pass's transitions), if
     * it holds one and its law has a viscosity; whether there was one */
    bool viscous_force(SurfacesCloseData & d, const double gap, const double *en,
                       ForceData & i_forces, ForceData & j_forces)
    {
      cb_bridge bridge;
      std::memcpy(&bridge, &d.contact_history[history_offset_], sizeof bridge);
      const cb_law *law = laws_.of(d.itype, d.jtype);
      if (bridge.active == 0.0 || !(law->viscosity > 0.0)) return false;
      const bool swap = d.radj < d.radi;  // the core's order, as in pair_force
      check(viscous_.add(law, d, atom, swap ? d.radj : d.radi, swap ? d.radi : d.radj, gap,
                         bridge.volume, en, i_forces, j_forces),
            "viscous force", d, gap, bridge.volume);
      return true;
    }

    /* keyword remove or fix capillaryRemove, in the pass that removes: counted on one rank, and
     * removed if the draw picks its pair (cb_bridge_remove: dry, marked while it overlaps),
     * its liquid handed on as a broken bridge's (ra, rb in the core's order; swap: i is b) */
    void remove_if_chosen(cb_bridge &bridge, double *hist, const double ra, const double rb,
                          const bool swap, const SurfacesCloseData & d, const double gap)
    {
      const int *tag = atom->tag;
      double volume = 0.0;
      const double held = bridge.volume;
      if (protocols_.start.chosen(tag[d.i], tag[d.j])) {
        check(cb_bridge_remove(gap, &bridge, &volume), "bridge removal", d, gap, bridge.volume);
        std::memcpy(hist, &bridge, sizeof bridge);
        release(volume, ra, rb, swap, d, gap);
      }
      protocols_.start.count(d.j < atom->nlocal || tag[d.i] < tag[d.j], volume, held);
    }

    /* A bridge held beyond the reach (a volume above the one the reach was built for) is
     * ruptured now, before its pair leaves the neighbor list with its liquid (the core's
     * rule, cb_bridge_beyond_reach); its liquid goes where a broken bridge's goes. */
    void rupture_beyond_reach(cb_bridge &bridge, double *hist, const double ra,
                              const double rb, const bool swap, const SurfacesCloseData & d,
                              const double gap)
    {
      const double volume = bridge.volume;
      std::memset(&bridge, 0, sizeof bridge);
      std::memcpy(hist, &bridge, sizeof bridge);
      reach_.count_beyond(d.j < atom->nlocal);
      if (per_atom_liquid_) release(volume, ra, rb, swap, d, gap);
    }

    /* Protocol 2: a broken bridge's liquid to its two particles' free liquid, from the next
     * step on (ra, rb in the core's order; swap: i is b). */
    void release(const double volume, const double ra, const double rb, const bool swap,
                 const SurfacesCloseData & d, const double gap)
    {
      double share_a = 0.0, share_b = 0.0;
      check(cb_protocol2_release(volume, ra, rb, &share_a, &share_b), "Protocol 2 release", d,
            gap, volume);
      formations_.released[d.i] += swap ? share_b : share_a;
      if (d.j < atom->nlocal) formations_.released[d.j] += swap ? share_a : share_b;
    }

    /* Protocols 2, 3: the bridges that formed in this pass, between grains and at walls,
     * take their liquid; Protocol 3's receivers the released liquid. */
    void finish_formations()
    {
      formations_.finish(fix_free_->vector_atom, protocols_.protocol3, *this);
      if (protocols_.protocol3) deposit_released();
    }

    /* FormationSink: a bridge formed at the end of the pass, in the tally and the census */
    void formed(const capbridge_liggghts::Candidate &c, const double volume)
    {
      if (c.j < 0) {  // at a wall: all its liquid is its grain's
        if (counting_) account_.add_bridge(true, volume);
        if (tally_) per_atom_tally_.wall(c.i, volume, 1.0);
        return;
      }
      const bool j_local = c.j < atom->nlocal;
      if (tally_) per_atom_tally_.pair(c.i, j_local ? c.j : -1, volume);
      census_bridge(c.itype, c.jtype, j_local, volume);
    }

    void failed(const cb_status status, const char *what, const int i, const int j,
                const double gap, const double volume)
    {
      check_at(status, what, i, j, gap, volume);
    }

    /* Protocol 3: the liquid released in this pass to its receivers (or the free liquid);
     * a bridge grown beyond the reach is ruptured at its next step beyond it (Reach). */
    void deposit_released()
    {
      capbridge_liggghts::Protocol3 &receivers = protocols_.receivers;
      receivers.settle(fix_free_->vector_atom, formations_.released);
      for (size_t k = 0; k < receivers.size(); ++k) {
        double volume = 0.0;  // the bridge grows in its history; this pass counted it before
        const double added = receivers.deposit(k, &volume);
        if (!(added > 0.0)) continue;
        const capbridge_liggghts::HeldBridge &b = receivers.bridge(k);
        const bool wall = b.j < 0;  // a wall bridge: all its liquid is its grain's
        const bool j_local = wall || b.j < atom->nlocal;
        if (counting_) account_.add_bridge(j_local, added);
        if (timing_ && !wall) timestep_.add_bridge(b.itype, b.jtype, volume);
        if (tally_ && wall) per_atom_tally_.wall(b.i, added, 0.0);  // liquid, no new bridge
        else if (tally_) per_atom_tally_.pair(b.i, j_local ? b.j : -1, added, 0.0);
      }
    }

    void apply(const double capillary, const double *en, ForceData & i_forces,
               ForceData & j_forces)
    {
      // en points from j to i: the attraction pulls i along -en, j along +en
      const double fx = -capillary * en[0];
      const double fy = -capillary * en[1];
      const double fz = -capillary * en[2];
      i_forces.delta_F[0] += fx;
      i_forces.delta_F[1] += fy;
      i_forces.delta_F[2] += fz;
      j_forces.delta_F[0] -= fx;
      j_forces.delta_F[1] -= fy;
      j_forces.delta_F[2] -= fz;
    }

    /* ---------------------------------------------------------------- errors */

    void fail_all(const std::string &message)
    {
      error->all(FLERR, message.c_str());
    }

    /* Error::one writes to the screen only, unflushed, before MPI_Abort: when the screen is
     * a pipe or a file, or -screen none, the message is lost. Into the log file too. */
    void fail_one(const std::string &message)
    {
      if (logfile) {
        fprintf(logfile, "ERROR on proc %d: %s\n", comm->me, message.c_str());
        fflush(logfile);
      }
      if (screen) fflush(screen);
      error->one(FLERR, message.c_str());
    }

    void check(const cb_status status, const char *what, const SurfacesCloseData & d,
               const double gap, const double volume)
    {
      if (status != CB_OK) check_at(status, what, d.i, d.j, gap, volume);
    }

    void check_at(const cb_status status, const char *what, const int i, const int j,
                  const double gap, const double volume)
    {
      if (status == CB_OK) return;
      char text[512];
      if (j < 0)  // a wall (its bridges' candidates: j -1)
        snprintf(text, sizeof text,
                 "cohesion model capillary: %s failed for particle %d and a wall (law %s, "
                 "radius %g m, gap %g m, volume %g m^3): %s",
                 what, atom->tag[i], cb_model_name(model_), atom->radius[i], gap, volume,
                 cb_status_message(status));
      else
        snprintf(text, sizeof text,
                 "cohesion model capillary: %s failed for particles %d and %d (law %s, radii "
                 "%g and %g m, gap %g m, volume %g m^3): %s",
                 what, atom->tag[i], atom->tag[j], cb_model_name(model_), atom->radius[i],
                 atom->radius[j], gap, volume, cb_status_message(status));
      fail_one(text);
    }

    /* ---------------------------------------------------------------- set-up */

    /* the per-atom arrays of the model exist from the pair_style command on, so that dumps
     * and computes defined before the first run can refer to them */
    void connect_internal_fixes()
    {
      if (per_atom_liquid_) formations_.connect();
      if (tally_) per_atom_tally_.connect(modify);
    }

    void connect_per_atom()
    {
      if (per_atom_liquid_) {
        fix_free_ = static_cast<FixPropertyAtom *>(modify->find_fix_property(
            "freeLiquid", "property/atom", "scalar", 0, 0,
            "cohesion model capillary (liquid protocol1, protocol2, protocol3)"));
        capbridge_liggghts::initialise_now(atom, fix_free_);
        if (fix_free_->comm_forward < 1)
          error->all(FLERR, "cohesion model capillary: fix property/atom freeLiquid must be "
                            "communicated to ghost atoms: 'fix ID all property/atom freeLiquid "
                            "scalar yes yes no VOLUME'");
        const double *free_liquid = fix_free_->vector_atom;
        int bad = 0;
        for (int i = 0; i < atom->nlocal; ++i)
          if (!(free_liquid[i] >= 0.0) || !capbridge_liggghts::is_finite(free_liquid[i])) bad = 1;
        int bad_all = 0;
        MPI_Allreduce(&bad, &bad_all, 1, MPI_INT, MPI_MAX, world);
        if (bad_all)
          error->all(FLERR, "cohesion model capillary: freeLiquid must be >= 0 and finite "
                            "for every particle");
        account_.connect();
      }
      connect_internal_fixes();
    }

    // settings
    bool wall_;
    int history_offset_;
    std::string law_name_, rupture_, overlap_, validity_, liquid_;
    bool law_given_;
    // every law's own keywords (register_word binds to them: never resized)
    std::vector<capbridge_liggghts::LawKeywordWord> law_keywords_;
    std::string tally_word_;  // on/off
    std::string viscous_word_;  // on/off: the bridges' viscous force (ViscousForce)
    bool tally_;
    capbridge_liggghts::Tally per_atom_tally_;  // tally on: bridgedLiquid, bridgeCount
    bool per_atom_liquid_;  // Protocols 1, 2, 3: the liquid in freeLiquid and the bridges
    cb_model model_;
    // properties
    double surface_tension_;
    double *contact_angle_;   // [rad], per atom type (LIGGGHTS converts from degrees)
    double **bridge_volume_;  // [m^3], per pair of atom types (liquid fixed)
    int ntypes_;
    // laws: one per distinct contact angle
    capbridge_liggghts::PairLaws laws_;
    // per-atom data
    FixPropertyAtom *fix_free_;
    capbridge_liggghts::Formations formations_;  // Protocols 2, 3: this pass's new bridges
    bool updating_;
    bool open_;        // Protocols 2, 3: an updating pass whose formations are not finished
    long long nwalls_; // walls whose models joined the pass in this run (attach_wall)
    capbridge_liggghts::WallSources walls_;  // their keys and grains, for Protocol 1
    FixCapillaryFinish *finish_fix_;  // ends the pass after the walls when nwalls_ > 0
    bool census_;      // this pass is a census pass (setup, re-neighboring)
    bool counting_;    // this pass is a census of the liquid (Protocol 2: setup, re-neighboring)
    bool timing_;      // this pass checks the time step (setup, re-neighboring; until it warned)
    capbridge_liggghts::LiquidAccount account_;
    capbridge_liggghts::Reach reach_;
    capbridge_liggghts::TimestepCheck timestep_;
    capbridge_liggghts::Protocols protocols_;
    capbridge_liggghts::ViscousForce viscous_;
    capbridge_liggghts::WallBridges wall_bridges_;  // in a fix wall/gran
  };
}
}

#endif // COHESION_MODEL_CAPILLARY_H_
#endif
