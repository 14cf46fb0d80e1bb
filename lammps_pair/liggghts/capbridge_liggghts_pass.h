/* capbridge_liggghts_pass.h — the pair's `cohesion capillary` as the walls see it: what a
 * model in a fix wall/gran asks of the pair's model (its liquid, its tally; under Protocols 2
 * and 3 its liquid pass).
 *
 * Part of capbridge (lammps_pair/liggghts/). Compiled inside LIGGGHTS: C++98 and C++11.
 *
 * Under Protocols 2 and 3 the new bridges of a grain in one step share its free liquid
 * equally (cb_protocol_grain_step's k-way share), its new wall bridges among them, as
 * LAMMPS's fix capillary/liquid counts them.  LIGGGHTS computes the walls in fix wall/gran's
 * post_force, after the pair, so the pair's model cannot finish the formations of a step at
 * the end of its own pass when walls hold bridges: it leaves them to fix capillaryFinish
 * (fix_capillary_finish.h), last in the fix list, which finishes the pass after every wall
 * (in its setup and its pre_final_integrate, before the final integration).  In between,
 * each wall's model hands the pair's model, through this interface, its formations (counted
 * with the pair's), the liquid of its broken bridges (to the grain: the wall holds none) and
 * its held bridges (the liquid census, the per-atom tally, Protocol 3's receivers).
 *
 * Protocol 1 (and `start bridges`, its distribution at the start of Protocols 2 and 3)
 * distributes the liquid at the start of the pair's pass, before fix wall/gran computes: a
 * wall therefore also gives the pair's model its grains as they are now (WallSource: a
 * primitive wall resolves every grain's gap itself, and its contact history is per grain),
 * so that one distribution covers the pairs and the walls, as LAMMPS's fix capillary/liquid
 * does with fix capillary/wall.
 */
#ifndef CAPBRIDGE_LIGGGHTS_PASS_H_
#define CAPBRIDGE_LIGGGHTS_PASS_H_

#include "capbridge.h"

#include <vector>

namespace capbridge_liggghts {

/* A bridge of grain i (owned) and a wall, in the wall's contact history. */
struct WallBridge {
    double *history;    // its cb_bridge (the wall model's history offset)
    const cb_law *law;  // the law at the wall's angle
    int i, itype, wall_type;
    long long key;      // the wall's key: negative (LiquidPass::attach_wall), never a grain's
    double r, gap;
    double en[3];       // unit normal from the wall to the grain
};

/* A grain of a wall's group as Protocol 1's distribution sees it: its gap now, its bridge. */
struct WallSlot {
    double *history;    // its cb_bridge in the wall's contact history
    const cb_law *law;  // the law at the wall's angle
    int i;              // the grain (owned)
    double r, gap;
    bool candidate;     // within the distance fix wall/gran calls the model at
};

/* A wall as Protocol 1's distribution sees it. */
class WallSource {
  public:
    /* Every owned grain of the wall's group that is a candidate or holds a bridge. */
    virtual void protocol1_slots(std::vector<WallSlot> &out) = 0;

  protected:
    ~WallSource() {}
};

class LiquidPass {
  public:
    /* At a wall model's init, after the pair's (Protocols 1, 2, 3): the wall joins the pass
     * of every step and the distributions; returns its key (negative, one per wall). */
    virtual long long attach_wall(WallSource *source) = 0;
    /* The liquid mode of the pair ("protocol1", "protocol2", "protocol3") and the volume
     * its reach is built for (the design volume of the run). */
    virtual const char *liquid() const = 0;
    virtual double design_volume() const = 0;
    /* The law of Protocol 1's distributions (liquid protocol1, or `start bridges`), whose
     * eqs. 13-14 solve for one alpha with one law: a wet wall's must be the same; NULL when
     * the liquid never distributes. */
    virtual const cb_law *distribution_law() const = 0;
    /* Protocol 1: no bridge forms at contact, the distributions give them. */
    virtual bool distributes() const = 0;
    /* An updating pass of the pair is open: its end waits for the walls. */
    virtual bool open() const = 0;
    virtual double free_liquid(const int i) const = 0;
    /* A dry wall contact of grain i that may form a bridge in this step. */
    virtual void wall_formation(const WallBridge &b) = 0;
    /* The liquid of a wall bridge of grain i that broke in this step. */
    virtual void wall_release(const int i, const double r, const double volume) = 0;
    /* A wall bridge that exists after this step's transitions (any liquid: the tally; under
     * the protocols the census and Protocol 3's receivers too). */
    virtual void wall_held(const WallBridge &b, const double volume) = 0;
    /* In the pass that removes bridges (keyword remove, fix capillaryRemove): the wall
     * bridge of grain b.i, removed if the draw picks it (its liquid then the grain's, as a
     * broken bridge's), counted for the removal's report either way. */
    virtual bool removing() const = 0;
    virtual void wall_removal(const WallBridge &b, cb_bridge *bridge) = 0;
    /* fix capillaryFinish: the end of the pass, after every wall. */
    virtual void finish_deferred() = 0;

  protected:
    ~LiquidPass() {}
};

} /* namespace capbridge_liggghts */

#endif /* CAPBRIDGE_LIGGGHTS_PASS_H_ */
