/* capbridge_liggghts_protocol3.h — Richefeu 2007's Protocol 3 in `cohesion capillary`: the
 * receivers of a broken bridge's liquid, and the MPI exchange they need.
 *
 * Part of capbridge (lammps_pair/liggghts/). Compiled inside LIGGGHTS: C++98 and C++11.
 *
 * Protocol 3 (Richefeu 2007 §4.2) transfers "the liquid from broken bond between two
 * particles to the lowest contact located on the lower hemisphere of each of the two
 * particles", the bond's volume "shared by the two particles proportionally to their
 * sizes".  The rules are the core's: the split is cb_protocol2_release (the model's rupture
 * branch, as under Protocol 2), the receiver cb_protocol3_better (the bridge whose contact
 * point lies lowest below the particle's centre along z; equal heights go to the smaller
 * partner ID, so that no rank count or list order changes the choice), and the share goes
 * to the receiver or, without one, to the particle's free liquid by cb_protocol_grain_step.
 * This file gathers and scatters:
 *   - in the pass, every bridge that exists after its transition is offered as a receiver
 *     to its local ends (offer).  With newton off the owner of an atom computes every pair
 *     of it (a pair with a ghost is computed by both owners), so each owner picks its own
 *     atoms' receivers from complete information;
 *   - at the end of the pass (settle), each owner hands its atoms' released liquid to the
 *     receiver (a deposit) or to the free liquid, and forward communication gives every
 *     ghost its owner's receiver and deposit (fix property/atom capillaryReceiver, the
 *     partner's atom ID or 0, and capillaryDeposit);
 *   - every copy of a receiving bridge, on whichever rank holds it, then grows by the
 *     deposits meant for it (deposit_for): the two copies of a pair held by two ranks grow
 *     alike, and every deposit lands in one bridge, so the liquid is conserved.
 * The deposit is made at the end of the pass, so its force acts from the next step on.
 */
#ifndef CAPBRIDGE_LIGGGHTS_PROTOCOL3_H_
#define CAPBRIDGE_LIGGGHTS_PROTOCOL3_H_

#include "capbridge.h"
#include "capbridge_liggghts_liquid.h"
#include "capbridge_liggghts_pass.h"
#include "contact_interface.h"

#include "atom.h"
#include "error.h"
#include "fix_property_atom.h"
#include "modify.h"
#include "pointers.h"

#include <cstdio>
#include <cstring>
#include <vector>

namespace capbridge_liggghts {

/* A bridge that exists after this pass's transitions, as the model's pair loop (or a wall's
 * model) saw it. */
struct HeldBridge {
    double *history;     // its cb_bridge in the contact history
    const cb_law *law;
    int i, j;            // i local; j local or ghost, or -1: a wall
    int itype, jtype;
    double ra, rb;       // the radii in the core's order (smaller first; a wall's rb CB_PLANE)
    double radsum, gap;
    long long key_j;     // j's key in the receiver choice: its atom ID, or the wall's key
};

class Protocol3 : protected LAMMPS_NS::Pointers {
  public:
    explicit Protocol3(LAMMPS_NS::LAMMPS *lmp) : Pointers(lmp), receiver_(NULL), deposit_(NULL) {}

    /* At the pair_style command: the per-atom receiver and deposit, sent to ghosts. */
    void create()
    {
        receiver_ = internal_fix(modify, "capillaryReceiver", "yes");
        deposit_ = internal_fix(modify, "capillaryDeposit", "yes");
    }

    /* The start of an updating pass: no receiver, no deposit yet. */
    void begin()
    {
        const int nall = atom->nlocal + atom->nghost;
        double *receiver = receiver_->vector_atom, *deposit = deposit_->vector_atom;
        for (int k = 0; k < nall; ++k) receiver[k] = deposit[k] = 0.0;
        lowest_.assign(atom->nlocal > 0 ? atom->nlocal : 1, 0.0);
        held_.clear();
    }

    /* A bridge that exists after its transition, the pair `d` with its history `history`,
     * radii ra <= rb for the core, gap: a receiver for its local ends.  en points from j
     * to i, so the contact point on i lies radi en_z below i's centre along z. */
    void offer(const LIGGGHTS::ContactModels::SurfacesCloseData &d, double *history,
               const cb_law *law, const double ra, const double rb, const double gap,
               const double en_z)
    {
        const bool j_local = d.j < atom->nlocal;
        consider(d.i, -d.radi * en_z, atom->tag[d.j]);
        if (j_local) consider(d.j, d.radj * en_z, atom->tag[d.i]);
        const HeldBridge held = {history, law, d.i, d.j, d.itype, d.jtype, ra, rb, d.radsum,
                                 gap, atom->tag[d.j]};
        held_.push_back(held);
    }

    /* A wall bridge that exists after its transition: a receiver for its grain, the wall's
     * key (negative) its partner (the contact point lies r en_z below the grain's centre). */
    void offer_wall(const WallBridge &b)
    {
        consider(b.i, -b.r * b.en[2], b.key);
        const HeldBridge held = {b.history, b.law, b.i, -1, b.itype, b.wall_type, b.r,
                                 CB_PLANE, b.r, b.gap, b.key};
        held_.push_back(held);
    }

    /* The end of the pass (collective): each local atom's released liquid to its receiver
     * or its free liquid (no new contact takes any here: the model's formations took the
     * free liquid the pass started with), then the owners' receivers and deposits to the
     * ghosts. */
    void settle(double *free_liquid, const std::vector<double> &released)
    {
        const double *receiver = receiver_->vector_atom;
        double *deposit = deposit_->vector_atom;
        for (int i = 0; i < atom->nlocal; ++i) {
            double offer_none = 0.0;
            const cb_status status = cb_protocol_grain_step(
                released[i], receiver[i] != 0.0, 0.0, &free_liquid[i], &deposit[i], &offer_none);
            if (status != CB_OK) {
                char text[300];
                snprintf(text, sizeof text,
                         "cohesion model capillary: Protocol 3 failed for particle %d (released "
                         "%g m^3, free liquid %g m^3): %s",
                         atom->tag[i], released[i], free_liquid[i], cb_status_message(status));
                error->one(FLERR, text);
            }
        }
        receiver_->do_forward_comm();
        deposit_->do_forward_comm();
    }

    size_t size() const { return held_.size(); }
    const HeldBridge &bridge(const size_t k) const { return held_[k]; }

    /* After settle: bridge k grows by the deposit of each end whose receiver it is (in its
     * history; *volume its new volume).  Returns the liquid it received (0: none). */
    double deposit(const size_t k, double *volume)
    {
        const HeldBridge &b = held_[k];
        const double *receiver = receiver_->vector_atom, *deposit = deposit_->vector_atom;
        const int *tag = atom->tag;
        double added = 0.0;
        if (deposit[b.i] > 0.0 && receiver[b.i] == (double)b.key_j) added += deposit[b.i];
        if (b.j >= 0 && deposit[b.j] > 0.0 && receiver[b.j] == tag[b.i]) added += deposit[b.j];
        if (!(added > 0.0)) return 0.0;
        cb_bridge bridge;
        std::memcpy(&bridge, b.history, sizeof bridge);
        *volume = bridge.volume + added;
        const cb_status status = cb_bridge_set_volume(b.law, b.ra, b.rb, *volume, &bridge);
        if (status != CB_OK) {
            char text[400];
            snprintf(text, sizeof text,
                     "cohesion model capillary: Protocol 3 could not grow the bridge of "
                     "particle %d and %s %lld (radii %g and %g m, gap %g m) to %g m^3: %s",
                     tag[b.i], b.j < 0 ? "the wall of key" : "particle", b.key_j, b.ra, b.rb,
                     b.gap, *volume, cb_status_message(status));
            error->one(FLERR, text);
        }
        std::memcpy(b.history, &bridge, sizeof bridge);
        return added;
    }

  private:
    void consider(const int a, const double offset, const int partner)
    {
        double *receiver = receiver_->vector_atom;
        if (cb_protocol3_better(offset, partner, lowest_[a], (long long)receiver[a])) {
            lowest_[a] = offset;
            receiver[a] = partner;
        }
    }

    LAMMPS_NS::FixPropertyAtom *receiver_;  // per atom: the partner ID of its receiver, 0: none
    LAMMPS_NS::FixPropertyAtom *deposit_;   // per atom: the liquid for its receiver [m^3]
    std::vector<double> lowest_;            // per local atom: its receiver's contact offset
    std::vector<HeldBridge> held_;          // this pass's bridges after their transitions
};

} /* namespace capbridge_liggghts */

#endif /* CAPBRIDGE_LIGGGHTS_PROTOCOL3_H_ */
