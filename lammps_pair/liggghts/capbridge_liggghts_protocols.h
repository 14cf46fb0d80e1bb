/* capbridge_liggghts_protocols.h — Richefeu 2007's Protocols 1 and 3 in `cohesion capillary`:
 * their keywords and their parts, held by the model as one member.
 *
 * Part of capbridge (lammps_pair/liggghts/). Compiled inside LIGGGHTS: C++98 and C++11.
 *
 *   liquid protocol1 [every N] [vmax V]   Protocol 1 (capbridge_liggghts_protocol1.h)
 *   liquid protocol3 [vmax V]             Protocol 3 (capbridge_liggghts_protocol3.h)
 *   liquid protocol2 [vmax V]             Protocol 2 (the model's pair loop)
 *   liquid protocol2|3 [start bridges|free] [remove F remove_seed S]
 *                                         how the liquid starts (capbridge_liggghts_start.h),
 *                                         and fix capillaryRemove, the removal between runs
 * as LAMMPS's fix capillary/liquid names them: every N, steps between two distributions (0,
 * the default: at every re-neighboring); vmax V, the bridge volume the reach is built for
 * under any of the three (capbridge_liggghts_reach.h; without it the core's
 * cb_protocol_design_volume); start bridges, Protocol 1's distribution once at the start
 * of Protocols 2 and 3, and the bridges removed then.  The liquid itself is the
 * free liquid of fix property/atom freeLiquid at the start, as under Protocol 2 (LAMMPS's
 * `water` and `liquid` are the fix's; a LIGGGHTS deck sets freeLiquid per particle).
 */
#ifndef CAPBRIDGE_LIGGGHTS_PROTOCOLS_H_
#define CAPBRIDGE_LIGGGHTS_PROTOCOLS_H_

#include "capbridge_liggghts_protocol1.h"
#include "capbridge_liggghts_protocol3.h"
#include "capbridge_liggghts_reach.h"
#include "capbridge_liggghts_settings.h"
#include "capbridge_liggghts_start.h"

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <string>
#include <vector>

namespace capbridge_liggghts {

/* `every N`: a whole number >= 0 */
inline bool check_every(const std::string &k, const std::string &v, std::string &why)
{
    char *end = NULL;
    errno = 0;
    const long n = std::strtol(v.c_str(), &end, 10);
    if (!v.empty() && *end == '\0' && errno == 0 && n >= 0 && n <= INT_MAX) return true;
    why = "cohesion model capillary: " + k + " '" + v +
          "' must be a whole number >= 0 (steps between Protocol 1 distributions; 0: at every "
          "re-neighboring)";
    return false;
}

/* `vmax V`: a volume > 0 */
inline bool check_volume(const std::string &k, const std::string &v, std::string &why)
{
    double x = 0.0;
    if (cb_parse_number(v.c_str(), &x) && x > 0.0) return true;
    why = "cohesion model capillary: " + k + " '" + v + "' must be a volume > 0 [m^3]";
    return false;
}

/* every: Protocol 1 only; vmax: the per-atom liquid of Protocols 1, 2 and 3 (with liquid
 * fixed, bridgeVolume is the volume the reach is built for) */
inline bool protocol_keywords_apply(const std::string &liquid, const bool every_given,
                                    const bool vmax_given, std::string &why)
{
    if (every_given && liquid != "protocol1")
        why = "cohesion model capillary: keyword 'every' applies to 'liquid protocol1' only";
    else if (vmax_given && liquid == "fixed")
        why = "cohesion model capillary: keyword 'vmax' applies to 'liquid protocol1', "
              "'protocol2' and 'protocol3' only (with 'liquid fixed' the reach is built for "
              "bridgeVolume)";
    else
        return true;
    return false;
}

class Protocols {
  public:
    explicit Protocols(LAMMPS_NS::LAMMPS *lmp)
        : protocol1(false), protocol3(false), first(lmp), receivers(lmp), start(lmp),
          every_given_(false), vmax_given_(false)
    {
    }

    void register_settings(Settings &settings, const LAMMPS_NS::Input *input)
    {
        register_word(settings, "every", "0", &check_every, every_, &every_given_, input);
        register_word(settings, "vmax", "0", &check_volume, vmax_, &vmax_given_, input);
        start.register_settings(settings, input);
    }

    /* After the keywords are read, with the word of `liquid`: an error (collective, as
     * every rank reads the same command) for a keyword the protocol does not take. */
    void post_settings(const std::string &liquid, LAMMPS_NS::Error *error)
    {
        protocol1 = liquid == "protocol1";
        protocol3 = liquid == "protocol3";
        first.set_every(std::atoi(every_.c_str()));
        std::string why;
        if (!protocol_keywords_apply(liquid, every_given_, vmax_given_, why))
            error->all(FLERR, why.c_str());
        start.post_settings(liquid);
    }

    /* At init (collective), after the laws are built: the keywords of the start; Protocol
     * 1 (also at the start of Protocols 2, 3) needs one law. */
    void connect(const std::vector<cb_law> &laws, const std::string &liquid)
    {
        start.check(liquid);
        if (protocol1 || start.bridges)
            first.check_laws(laws, protocol1 ? "liquid protocol1"
                                             : "liquid " + liquid + " with 'start bridges'");
    }

    /* any keyword of the protocols given (every, vmax, start, remove, remove_seed) */
    bool given_any() const { return every_given_ || vmax_given_ || start.given_any(); }

    /* The design volume given with vmax; 0 when not given (the reach then takes the core's
     * cb_protocol_design_volume). */
    double vmax() const { return vmax_given_ ? std::atof(vmax_.c_str()) : 0.0; }

    /* The start of an updating pass, before the pair loop (collective under Protocol 1);
     * walls: the wet walls whose grains the distributions cover. */
    void begin_pass(const std::vector<cb_law> &laws, const int history_offset,
                    double *free_liquid, const Reach &reach, const WallSources &walls)
    {
        if (protocol1 ? first.due() : start.due(free_liquid))
            start.set_total(
                first.distribute(&laws[0], history_offset, free_liquid, reach, walls));
        if (!protocol1) start.ask(free_liquid);  // fix capillaryRemove, at a run's setup
        if (protocol3) receivers.begin();
    }

    bool protocol1, protocol3;
    Protocol1 first;      // Protocol 1's distributions
    Protocol3 receivers;  // Protocol 3's receivers
    LiquidStart start;    // Protocols 2, 3: start bridges, and the bridges removed then

  private:
    std::string every_, vmax_;
    bool every_given_, vmax_given_;
};

} /* namespace capbridge_liggghts */

#endif /* CAPBRIDGE_LIGGGHTS_PROTOCOLS_H_ */
