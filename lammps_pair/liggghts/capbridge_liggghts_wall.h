/* capbridge_liggghts_wall.h — `cohesion capillary` in a fix wall/gran: the bridge between a
 * grain and a wall (a mesh or a primitive wall).
 *
 * Part of capbridge (lammps_pair/liggghts/). Compiled inside LIGGGHTS: C++98 and C++11.
 *
 * fix wall/gran instantiates the model for its walls with its own keywords after `cohesion
 * capillary` (law, rupture, overlap, validity, the law's own).  Every rule is the core's
 * sphere-plane pair (r2 = CB_PLANE), as LAMMPS's fix capillary/wall: the law of the grain's
 * atom type and the wall's (the contact angle of the mean cosine, cb_wall_contact_angle), a
 * bridge of bridgeVolume (grain type, wall type) formed at contact, held to its rupture
 * distance, its force on the grain (cb_bridge_step, cb_bridge_force).  Its state is the same
 * seven values as a pair's, in the wall's contact history (per grain for a primitive wall,
 * per triangle for a mesh: restart files keep it).
 *
 * Liquid: the pair_style's.  With liquid fixed the bridge has bridgeVolume and the liquid of a
 * broken bridge leaves, as between grains.  Under Protocols 1, 2 and 3 (primitive walls;
 * `liquid protocol1|2|3` given to both) the wall holds no liquid.  Under Protocols 2 and 3 the
 * bridge forms at contact from the grain's free liquid, its share counted with the grain's
 * other new bridges of the step (the pair's model finishes the formations after the walls:
 * capbridge_liggghts_pass.h); under Protocol 1, and at the start of Protocols 2 and 3 with
 * `start bridges`, the pair's distribution gives it its volume with the pairs' (the wall
 * hands its grains over as they are then: protocol1_slots; the wall's law must be the
 * pair's, eqs. 13-14 solving with one).  Its liquid goes back to the grain when it breaks,
 * it is a Protocol 3 receiver of its grain (the wall's key its partner), and the liquid
 * census and the pair's tally (bridgedLiquid, bridgeCount: its one grain end) count it.  The
 * reach is the pair's design volume.  The removal of bridges (keyword remove, fix
 * capillaryRemove) covers the wall's: the draw of the grain's ID and the wall's key, as
 * LAMMPS's fix capillary/liquid draws a wall bridge (the first wall's key -1).  Not in
 * LIGGGHTS yet: mesh walls under the protocols (fix contacthistory/mesh copies a contact's
 * history to the coplanar triangle a grain moves onto: the bridge's liquid with it; LAMMPS's
 * fix capillary/wall has region walls).
 *
 * Reach: fix wall/gran calls the model for a grain apart from the wall only while its gap is
 * below (contact_distance_factor - 1) r, so the wall registers the factor of its design
 * rupture distance (cb_reach with the plane).  A mesh's grain list is built with that factor;
 * a primitive wall's with the neighbor skin alone (LIGGGHTS 3.8.0, FixWallGran::pre_force), so
 * a bridged grain stays in it only if the skin covers the rupture distance: an error otherwise,
 * naming the skin needed.
 */
#ifndef CAPBRIDGE_LIGGGHTS_WALL_H_
#define CAPBRIDGE_LIGGGHTS_WALL_H_

#include "atom.h"
#include "capbridge.h"
#include "capbridge_liggghts_liquid.h"
#include "capbridge_liggghts_pass.h"
#include "capbridge_liggghts_reach.h"
#include "contact_interface.h"
#include "comm.h"
#include "error.h"
#include "fix_mesh_surface.h"
#include "fix_property_atom.h"
#include "fix_wall_gran.h"
#include "modify.h"
#include "neighbor.h"
#include "pointers.h"
#include "primitive_wall.h"
#include "property_registry.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace capbridge_liggghts {

class WallBridges : protected LAMMPS_NS::Pointers, public WallSource {
  public:
    explicit WallBridges(LAMMPS_NS::LAMMPS *lmp)
        : Pointers(lmp), wall_(NULL), history_offset_(-1), ntypes_(0), pass_(NULL),
          protocol_(false), key_(0), warned_beyond_(false), history_(NULL)
    {
    }

    /* In the model's constructor: the fix wall/gran that made it and the offset of the seven
     * history values. */
    void attach(LIGGGHTS::IContactHistorySetup *setup, const int history_offset)
    {
        wall_ = dynamic_cast<LAMMPS_NS::FixWallGran *>(setup);
        history_offset_ = history_offset;
    }

    /* At the init of every run (fix wall/gran's init, after the pair's, before the neighbor
     * lists), after connect_liquid: the design rupture distance of the wall's type with every
     * grain type, the contact distance factor that covers it, and a primitive wall's skin. */
    void connect(PropertyRegistry &registry, const ReachLaws &laws, double **bridge_volume)
    {
        ntypes_ = laws.ntypes;
        design_rupture_.assign((ntypes_ + 1) * (ntypes_ + 1), 0.0);
        // a primitive wall's type is its own; a mesh wall's is each mesh's (fix wall/gran
        // sets atom_type_wall() per mesh only while it computes)
        std::vector<int> wall_types;
        if (wall_->is_mesh_wall())
            for (int m = 0; m < wall_->n_meshes(); ++m)
                wall_types.push_back(wall_->mesh_list()[m]->atomTypeWall());
        else
            wall_types.push_back(wall_->atom_type_wall());
        for (size_t w = 0; w < wall_types.size(); ++w) {
            if (wall_types[w] >= 1 && wall_types[w] <= ntypes_) continue;
            char text[200];
            snprintf(text, sizeof text, "cohesion model capillary: the wall's atom type %d is "
                     "not one of the types 1..%d of bridgeVolume and contactAngle",
                     wall_types[w], ntypes_);
            error->all(FLERR, text);
        }
        if (protocol_) connect_distribution(laws, wall_types[0]);
        const double rmin = registry.min_radius(), rmax = registry.max_radius();
        if (!(rmin > 0.0) || !(rmax > 0.0) || rmin > 1e100) return;
        const cb_radius_range radii = {rmin, rmax}, plane = {CB_PLANE, CB_PLANE};
        double ratio = 0.0, largest = 0.0;
        int largest_type = wall_types[0];
        for (size_t w = 0; w < wall_types.size(); ++w) {
            const int wall_type = wall_types[w];
            for (int a = 1; a <= ntypes_; ++a) {
                const double volume =
                    protocol_ ? pass_->design_volume() : bridge_volume[a][wall_type];
                double rupture = 0.0, pair_ratio = 0.0;
                const cb_status status = cb_reach(laws.of(a, wall_type), radii, plane, volume,
                                                  &rupture, NULL, &pair_ratio);
                if (status != CB_OK) {
                    char text[400];
                    snprintf(text, sizeof text, "cohesion model capillary: no reach for wall "
                             "bridges of %g m^3 (atom types %d and the wall's %d) for radii %g "
                             "to %g m: law %s: %s", volume, a, wall_type, rmin, rmax, laws.law,
                             cb_status_message(status));
                    error->all(FLERR, text);
                }
                design_rupture_[a * (ntypes_ + 1) + wall_type] = rupture;
                if (rupture > largest) largest_type = wall_type;
                largest = std::max(largest, rupture);
                ratio = std::max(ratio, pair_ratio);
            }
        }
        if (!(ratio > 0.0)) return;
        double factor = 1.0 + ratio;  // rounded up, so that it covers the ratio
        if (factor - 1.0 < ratio) factor = nextafter(factor, 2.0);
        neighbor->register_contact_dist_factor(factor);
        const double needed = largest * (1.0 + CB_REACH_MARGIN);
        if (!wall_->is_mesh_wall() && !(neighbor->skin >= needed)) {
            char text[500];
            snprintf(text, sizeof text, "cohesion model capillary: fix %s is a primitive wall, "
                     "whose grain list LIGGGHTS builds with the neighbor skin alone; its "
                     "bridges (%s with the wall's type %d) rupture up to %g m from it, beyond "
                     "the skin %g m: a bridged grain would leave the list with its bridge.  "
                     "Give 'neighbor %s bin' or more%s",
                     wall_->id, protocol_ ? "the pair_style's design volume" : "bridgeVolume",
                     largest_type, largest, neighbor->skin, format_at_least(needed).c_str(),
                     protocol_ ? "" : " (or a mesh wall)");
            error->all(FLERR, text);
        }
    }

    /* The bridge of grain d.i and the wall in one call: its transition (in real force passes,
     * d.computeflag; under Protocols 2, 3 in the pair's open pass) and its force on the grain;
     * en the unit normal from the wall to the grain.  volume: bridgeVolume of the two types
     * with liquid fixed (a bridge forms at contact here); 0 under the protocols, where a
     * formation is the pair's model's, at the end of the pass (wall_formation). */
    double force(const cb_law *law, LIGGGHTS::ContactModels::SurfacesCloseData &d,
                 const double gap, const double volume, const double *en)
    {
        if (!d.contact_history) fail("no contact history for a wall contact (internal)");
        double *const hist = &d.contact_history[history_offset_];
        cb_bridge bridge;
        std::memcpy(&bridge, hist, sizeof bridge);
        const bool updating = d.computeflag != 0 && (!protocol_ || pass_->open());
        const double r = d.radi;
        if (updating && update->setupflag) setup_state(law, d, gap, bridge, hist);
        const WallBridge b = {hist, law, d.i, d.itype, d.jtype, key_, r, gap,
                              {en[0], en[1], en[2]}};
        if (updating && protocol_ && bridge.active != 0.0 && pass_->removing()) {
            pass_->wall_removal(b, &bridge);  // (a removed one is marked while it overlaps)
            std::memcpy(hist, &bridge, sizeof bridge);
        }
        double capillary = 0.0;
        bool have_force = false;
        if (updating && cb_bridge_held(law, r, CB_PLANE, gap, &bridge, &capillary)) {
            have_force = true;  // held in contact: its stored force
        } else if (updating && (!cb_bridge_dry(&bridge) || (!protocol_ && gap <= 0.0))) {
            cb_transition change = CB_BRIDGE_STAYS_DRY;
            double released = 0.0;  // liquid fixed: a broken bridge's liquid leaves
            check(cb_bridge_step(law, r, CB_PLANE, gap, volume, &bridge, &change, &released,
                                 &capillary), "bridge update", d, gap,
                  volume > 0.0 ? volume : bridge.volume);
            have_force = true;
            std::memcpy(hist, &bridge, sizeof bridge);
            if (protocol_ && change == CB_BRIDGE_RUPTURED) pass_->wall_release(d.i, r, released);
        }
        // (Protocol 1: no formation at contact, its distributions give the bridges)
        if (protocol_ && updating && bridge.active == 0.0 && !pass_->distributes() &&
            cb_bridge_may_form(&bridge, gap) && pass_->free_liquid(d.i) > 0.0)
            pass_->wall_formation(b);
        if (updating && bridge.active != 0.0 &&
            cb_bridge_beyond_reach(gap, design_rupture_[d.itype * (ntypes_ + 1) + d.jtype])) {
            rupture_beyond_reach(d, gap, bridge.volume);
            if (protocol_) pass_->wall_release(d.i, r, bridge.volume);
            std::memset(&bridge, 0, sizeof bridge);
            std::memcpy(hist, &bridge, sizeof bridge);
        }
        if (bridge.active == 0.0) return 0.0;
        // the pair's tally (any liquid), census and Protocol 3's receivers (protocols)
        if (updating && pass_) pass_->wall_held(b, bridge.volume);
        if (!have_force)
            check(cb_bridge_force(law, r, CB_PLANE, gap, &bridge, &capillary), "force", d, gap,
                  bridge.volume);
        return capillary;
    }

    /* At the init of every run, first: the liquid of the wall's bridges is the pair_style's
     * (pass: the pair's model, NULL when the pair_style has no cohesion capillary), fixed or
     * its Protocol 1, 2 or 3, whose pass (and distributions) this wall then joins. */
    void connect_liquid(LiquidPass *pass, const std::string &liquid)
    {
        if (!wall_) error->all(FLERR, "cohesion model capillary: a wall model outside fix "
                                      "wall/gran (internal)");
        pass_ = pass;
        protocol_ = false;
        const std::string pair = pass ? pass->liquid() : "fixed";
        if (liquid != pair) {
            const std::string text =
                std::string("cohesion model capillary in fix ") + wall_->id + ": 'liquid " +
                liquid + "' must be the pair_style's liquid, 'liquid " + pair +
                "' (the grains and the walls share one liquid: " +
                (liquid == "fixed" ? "fixed-volume wall bridges beside the protocols would "
                                     "make and destroy the liquid they conserve)"
                                   : "the protocols need pair_style gran with cohesion "
                                     "capillary under the same liquid)");
            error->all(FLERR, text.c_str());
        }
        if (liquid == "fixed") return;
        if (wall_->is_mesh_wall()) {
            const std::string text =
                std::string("cohesion model capillary in fix ") + wall_->id + ": 'liquid " +
                liquid + "' takes primitive walls only in LIGGGHTS: a mesh keeps its bridges per "
                "triangle, and fix contacthistory/mesh copies a contact's history to the "
                "coplanar triangle a grain moves onto, the bridge's liquid with it (LAMMPS's "
                "fix capillary/wall has region walls)";
            error->all(FLERR, text.c_str());
        }
        protocol_ = true;
        key_ = pass_->attach_wall(this);
    }

    /* Protocol 1's distribution (WallSource): the grains fix wall/gran will visit in this
     * step (the primitive wall's grain list, built in its pre_force before the pair's pass;
     * at a run's setup, where fix wall/gran builds it only after the pair's pass, built here
     * as its setup will), those of the wall's group within the distance it calls the model
     * at (its own test, FixWallGran::post_force_primitive: gap <= 0 or gap < (contact
     * distance factor - 1) r) or holding a bridge, with their gaps now. */
    void protocol1_slots(std::vector<WallSlot> &out)
    {
        out.clear();
        LAMMPS_NS::PrimitiveWall *plane = wall_->primitiveWall();
        double **x = atom->x;
        const double *radius = atom->radius;
        if (update->setupflag) plane->buildNeighList(neighbor->skin, x, atom->radius, atom->nlocal);
        double **history = history_->array_atom;
        const int *mask = atom->mask, *type = atom->type;
        const double multiplier = neighbor->contactDistanceFactor - 1.0;
        int *grains = NULL;
        const int n = plane->getNeighbors(grains);
        for (int k = 0; k < n; ++k) {
            const int i = grains[k];
            if (!(mask[i] & wall_->groupbit)) continue;
            double delta[3];
            const double gap = plane->resolveContact(x[i], radius[i], delta);
            if (gap > neighbor->cutneighmax) continue;
            double *hist = &history[i][history_offset_];
            cb_bridge stored;
            std::memcpy(&stored, hist, sizeof stored);
            // (the wall bridge of a removed bridge gets no liquid while its contact lasts)
            const bool candidate = (gap <= 0.0 || gap < multiplier * radius[i]) &&
                                   !cb_bridge_removed_in_contact(&stored, gap);
            if (!candidate && stored.active == 0.0) continue;
            const WallSlot slot = {hist, slot_laws_[type[i]], i, radius[i], gap, candidate};
            out.push_back(slot);
        }
    }

  private:
    /* At connect under the protocols: each grain type's law with this wall and the wall's
     * contact history (per grain: fix wall/gran's property/atom history_ID); where the
     * liquid distributes (Protocol 1, start bridges), every such law must be the
     * distribution's, but for the viscosity, which takes no part in eqs. 13-14. */
    void connect_distribution(const ReachLaws &laws, const int wall_type)
    {
        slot_laws_.assign(ntypes_ + 1, NULL);
        for (int a = 1; a <= ntypes_; ++a) slot_laws_[a] = laws.of(a, wall_type);
        const std::string name = std::string("history_") + wall_->id;
        const int k = modify->find_fix(name.c_str());
        history_ = k >= 0 ? dynamic_cast<LAMMPS_NS::FixPropertyAtom *>(modify->fix[k]) : NULL;
        if (!history_)
            fail("the contact history of a primitive wall (fix property/atom history_ID) "
                 "was not found (internal)");
        // a wall made since the last run: its history's reset in Modify::setup would wipe the
        // bridges the pair's setup distribution gives it, their liquid lost
        initialise_now(atom, history_);
        const cb_law *pair = pass_->distribution_law();
        if (!pair) return;
        for (int a = 1; a <= ntypes_; ++a) {
            cb_law wall_law = *slot_laws_[a];
            wall_law.viscosity = pair->viscosity;
            wall_law.viscous_min_gap = pair->viscous_min_gap;
            if (cb_law_same(&wall_law, pair)) continue;
            char text[900];
            snprintf(text, sizeof text,
                     "cohesion model capillary in fix %s: the pair_style's 'liquid %s' "
                     "distributes the liquid by Protocol 1 (Richefeu 2007 eqs. 13-14: one "
                     "alpha over all pairs, with one law) over the grains and this wall, but "
                     "the wall's bridges with atom type %d have another law (contact angle "
                     "%g degrees, the mean cosine of the type's and the wall type %d's "
                     "contactAngle, against the pairs' %g; or other law words after 'cohesion "
                     "capillary'): give the wall's atom type the grains' contactAngle and the "
                     "pair_style's law words, or use 'start free' under Protocol 2 or 3",
                     wall_->id, pass_->liquid(), a, slot_laws_[a]->contact_angle * 180.0 / M_PI,
                     wall_type, pair->contact_angle * 180.0 / M_PI);
            error->all(FLERR, text);
        }
    }

    /* every state checked once where it enters (a restart file's), its constants derived */
    void setup_state(const cb_law *law, const LIGGGHTS::ContactModels::SurfacesCloseData &d,
                     const double gap, cb_bridge &bridge, double *hist)
    {
        check(cb_bridge_check_state(&bridge), "bridge state at setup", d, gap, bridge.volume);
        if (bridge.active == 0.0) return;
        check(cb_bridge_set_volume(law, d.radi, CB_PLANE, bridge.volume, &bridge),
              "bridge constants at setup", d, gap, bridge.volume);
        std::memcpy(hist, &bridge, sizeof bridge);
    }

    /* A bridge held beyond the reach (a volume above bridgeVolume, from a restart file) is
     * ruptured now, before its grain leaves the wall's list (cb_bridge_beyond_reach); warned
     * once on the rank that saw it. */
    void rupture_beyond_reach(const LIGGGHTS::ContactModels::SurfacesCloseData &d,
                              const double gap, const double volume)
    {
        if (warned_beyond_) return;
        warned_beyond_ = true;
        char text[400];
        snprintf(text, sizeof text, "cohesion model capillary: the bridge of particle %d and "
                 "fix %s (%g m^3, above the bridgeVolume the reach is built for) was ruptured "
                 "at gap %g m, beyond the reach, before its own rupture distance; this warning "
                 "is given once per processor", atom->tag[d.i], wall_->id, volume, gap);
        error->warning(FLERR, text);
    }

    void check(const cb_status status, const char *what,
               const LIGGGHTS::ContactModels::SurfacesCloseData &d, const double gap,
               const double volume)
    {
        if (status == CB_OK) return;
        char text[400];
        snprintf(text, sizeof text, "%s failed for particle %d (radius %g m) and fix %s (gap "
                 "%g m, volume %g m^3): %s", what, atom->tag[d.i], d.radi, wall_->id, gap,
                 volume, cb_status_message(status));
        fail(text);
    }

    /* error->one writes to the screen only: into the log file too (as the pair's fail_one) */
    void fail(const char *message)
    {
        const std::string text = std::string("cohesion model capillary: ") + message;
        if (logfile) {
            fprintf(logfile, "ERROR on proc %d: %s\n", comm->me, text.c_str());
            fflush(logfile);
        }
        if (screen) fflush(screen);
        error->one(FLERR, text.c_str());
    }

    LAMMPS_NS::FixWallGran *wall_;
    int history_offset_;
    int ntypes_;
    std::vector<double> design_rupture_;  // per pair of types, [grain * (ntypes + 1) + wall]
    LiquidPass *pass_;                    // the pair's model (NULL: no cohesion capillary)
    bool protocol_;                       // Protocols 2, 3: the wall joins the pair's pass
    long long key_;                       // this wall's key in the pass (negative)
    bool warned_beyond_;
    LAMMPS_NS::FixPropertyAtom *history_;   // a primitive wall's contact history, per grain
    std::vector<const cb_law *> slot_laws_; // per grain type: its law with this wall
};

} /* namespace capbridge_liggghts */

#endif /* CAPBRIDGE_LIGGGHTS_WALL_H_ */
