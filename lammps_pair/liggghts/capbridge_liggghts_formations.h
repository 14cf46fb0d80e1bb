/* capbridge_liggghts_formations.h — the bridges that form in one updating pass of `cohesion
 * capillary` under Protocols 2 and 3, between grains and at walls, and the liquid released in
 * it.
 *
 * Part of capbridge (lammps_pair/liggghts/). Compiled inside LIGGGHTS: C++98 and C++11.
 *
 * A dry pair in contact where either grain has free liquid, or a dry wall contact of a grain
 * with free liquid, may form a bridge in the pass.  Its liquid is taken at the end of the pass
 * (finish), once every rank knows how many bridges form on each grain in the step (per-atom
 * count capillaryFormations, sent to the ghosts): each of a grain's k new bridges takes 1/k of
 * its free liquid as the pass began (the core's k-way share, cb_protocol_grain_step; then
 * cb_protocol2_take and cb_bridge_step), so that the result depends neither on the order of
 * the neighbor list nor on the number of ranks; the wall holds none.  The grain's free liquid
 * is then cleared, and the liquid released in the pass becomes free liquid from the next step
 * on (Protocol 2; Protocol 3 hands it to the receivers: capbridge_liggghts_protocol3.h).
 */
#ifndef CAPBRIDGE_LIGGGHTS_FORMATIONS_H_
#define CAPBRIDGE_LIGGGHTS_FORMATIONS_H_

#include "capbridge.h"
#include "capbridge_liggghts_liquid.h"
#include "capbridge_liggghts_pass.h"
#include "contact_interface.h"

#include "atom.h"
#include "fix_property_atom.h"
#include "modify.h"
#include "pointers.h"

#include <cstring>
#include <vector>

namespace capbridge_liggghts {

/* A pair (or a grain and a wall: j -1, rb CB_PLANE) that may form a bridge in this pass. */
struct Candidate {
    double *history;     // its cb_bridge in the contact history
    int *contact_flags;  // the pair's (NULL at a wall)
    const cb_law *law;
    int i, j;
    int itype, jtype;
    double ra, rb, gap;  // the radii in the core's order (swap: i is b)
    double en[3];        // unit normal from j (or the wall) to i
    bool swap;
};

/* The model's side: what a formed bridge changes in its records, and its error. */
class FormationSink {
  public:
    virtual void formed(const Candidate &c, const double volume) = 0;
    virtual void failed(const cb_status status, const char *what, const int i, const int j,
                        const double gap, const double volume) = 0;

  protected:
    ~FormationSink() {}
};

class Formations : protected LAMMPS_NS::Pointers {
  public:
    explicit Formations(LAMMPS_NS::LAMMPS *lmp) : Pointers(lmp), count_(NULL) {}

    /* At the pair_style command and at every init: the per-atom count, sent to ghosts. */
    void connect() { count_ = internal_fix(modify, "capillaryFormations", "yes"); }

    /* The start of an updating pass. */
    void begin()
    {
        const int nall = atom->nlocal + atom->nghost;
        double *count = count_->vector_atom;
        for (int k = 0; k < nall; ++k) count[k] = 0.0;
        released.assign(atom->nlocal > 0 ? atom->nlocal : 1, 0.0);
        candidates_.clear();
    }

    /* A dry pair of the pair loop in contact (ra, rb in the core's order; swap: i is b). */
    void add_pair(const LIGGGHTS::ContactModels::SurfacesCloseData &d, double *history,
                  const cb_law *law, const double ra, const double rb, const bool swap,
                  const double gap, const double *en, const double *free_liquid)
    {
        if (!(free_liquid[d.i] + free_liquid[d.j] > 0.0)) return;
        double *count = count_->vector_atom;
        count[d.i] += 1.0;
        if (d.j < atom->nlocal) count[d.j] += 1.0;
        const Candidate c = {history, d.contact_flags, law, d.i, d.j, d.itype, d.jtype,
                             ra, rb, gap, {en[0], en[1], en[2]}, swap};
        candidates_.push_back(c);
    }

    /* A dry wall contact of a wet grain (a wall's model, during fix wall/gran's pass). */
    void add_wall(const WallBridge &b)
    {
        count_->vector_atom[b.i] += 1.0;
        const Candidate c = {b.history, NULL, b.law, b.i, -1, b.itype, b.wall_type,
                             b.r, CB_PLANE, b.gap, {b.en[0], b.en[1], b.en[2]}, false};
        candidates_.push_back(c);
    }

    /* The end of the pass: each candidate takes its shares and forms (its history, its
     * contact flag, the attraction on its local grains; sink.formed); the grains' free liquid
     * cleared where bridges formed, and the released liquid added to it (keep_released:
     * Protocol 3, whose receivers take it instead). */
    void finish(double *free_liquid, const bool keep_released, FormationSink &sink)
    {
        count_->do_forward_comm();
        const double *count = count_->vector_atom;
        const int nlocal = atom->nlocal;
        double **f = atom->f;
        for (size_t k = 0; k < candidates_.size(); ++k) {
            const Candidate &c = candidates_[k];
            const bool wall = c.j < 0;
            double from_i = share(free_liquid[c.i], count[c.i], c, sink);
            double from_j = wall ? 0.0 : share(free_liquid[c.j], count[c.j], c, sink);
            double volume = 0.0;
            double *from_a = c.swap ? &from_j : &from_i;
            double *from_b = c.swap ? &from_i : &from_j;
            cb_status status = cb_protocol2_take(from_a, from_b, &volume);
            if (status != CB_OK) sink.failed(status, "Protocol 2 take", c.i, c.j, c.gap, volume);
            cb_bridge bridge;
            std::memset(&bridge, 0, sizeof bridge);
            cb_transition change = CB_BRIDGE_STAYS_DRY;
            double gone = 0.0, capillary = 0.0;
            status = cb_bridge_step(c.law, c.ra, c.rb, c.gap, volume, &bridge, &change, &gone,
                                    &capillary);
            if (status != CB_OK) sink.failed(status, "bridge update", c.i, c.j, c.gap, volume);
            if (change != CB_BRIDGE_FORMED) continue;
            std::memcpy(c.history, &bridge, sizeof bridge);
            if (c.contact_flags)
                *c.contact_flags |= LIGGGHTS::ContactModels::CONTACT_COHESION_MODEL;
            sink.formed(c, bridge.volume);
            const bool j_local = !wall && c.j < nlocal;
            for (int k3 = 0; k3 < 3; ++k3) {  // attraction: i towards j or the wall
                f[c.i][k3] -= capillary * c.en[k3];
                if (j_local) f[c.j][k3] += capillary * c.en[k3];
            }
        }
        for (int i = 0; i < nlocal; ++i) {
            if (count[i] > 0.0) free_liquid[i] = 0.0;
            if (!keep_released) free_liquid[i] += released[i];
        }
        candidates_.clear();
    }

    std::vector<double> released;  // per local atom: the liquid broken bridges gave it

  private:
    /* the part of a grain's free liquid each of its `formations` new bridges is offered */
    static double share(const double free_liquid, const double formations, const Candidate &c,
                        FormationSink &sink)
    {
        double free_after = free_liquid, deposit = 0.0, offer = 0.0;
        const cb_status status =
            cb_protocol_grain_step(0.0, 0, formations, &free_after, &deposit, &offer);
        if (status != CB_OK) sink.failed(status, "Protocol 2 share", c.i, c.j, c.gap, free_liquid);
        return offer;
    }

    LAMMPS_NS::FixPropertyAtom *count_;  // per atom: its new bridges in this pass
    std::vector<Candidate> candidates_;
};

} /* namespace capbridge_liggghts */

#endif /* CAPBRIDGE_LIGGGHTS_FORMATIONS_H_ */
