/* fix_capillary_finish.h — fix capillary/finish (ID capillaryFinish): where the walls' models
 * of `cohesion capillary` find the pair's, and under Protocols 2 and 3 the end of the pair's
 * liquid pass, after the walls.
 *
 * Part of capbridge (lammps_pair/liggghts/). Compiled inside LIGGGHTS: C++98 and C++11.
 *
 * Made by the pair's model (pair_style gran ... cohesion capillary) at the init of every run,
 * before the walls' models connect, as the last fix: a wall's model reads the pair's liquid
 * and tally through it, and under Protocols 2 and 3, where its setup and its
 * pre_final_integrate come after every fix wall/gran's force pass, the pair's model finishes
 * there the formations of the step, the pair's and the walls', with the count of both
 * (capbridge_liggghts_pass.h).
 * Not a command for decks: it takes no arguments and does nothing without the model.
 */
#ifdef FIX_CLASS

FixStyle(capillary/finish,FixCapillaryFinish)

#else

#ifndef LMP_FIX_CAPILLARY_FINISH_H
#define LMP_FIX_CAPILLARY_FINISH_H

#include "capbridge_liggghts_pass.h"
#include "error.h"
#include "fix.h"
#include "modify.h"

#include <cstring>

namespace LAMMPS_NS {

class FixCapillaryFinish : public Fix {
  public:
    FixCapillaryFinish(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg), pass(NULL)
    {
        if (narg != 3)
            error->fix_error(FLERR, this, "takes no arguments (the pair_style's cohesion model "
                                          "capillary makes it; it is not a command for decks)");
    }

    int setmask() { return FixConst::PRE_FINAL_INTEGRATE; }
    void setup(int) { finish(); }
    void pre_final_integrate() { finish(); }

    // the pair's model, set at its init and cleared when it is deleted (NULL: nothing to do)
    capbridge_liggghts::LiquidPass *pass;

  private:
    void finish()
    {
        if (pass) pass->finish_deferred();
    }
};

}  // namespace LAMMPS_NS

namespace capbridge_liggghts {

/* The pair's model, at every init: fix capillaryFinish, last in the fix list (made again if a
 * fix came after it), pointing to the model's pass. */
inline LAMMPS_NS::FixCapillaryFinish *make_finish_fix(LAMMPS_NS::Modify *modify,
                                                      LAMMPS_NS::Error *error, LiquidPass *pass)
{
    int k = modify->find_fix("capillaryFinish");
    if (k >= 0 && std::strcmp(modify->fix[k]->style, "capillary/finish") != 0)
        error->all(FLERR, "cohesion model capillary: fix ID capillaryFinish is taken by a fix "
                          "of another style; the model needs that ID for its own fix");
    if (k >= 0 && k != modify->nfix - 1) {
        modify->delete_fix("capillaryFinish");
        k = -1;
    }
    if (k < 0) {
        const char *args[3] = {"capillaryFinish", "all", "capillary/finish"};
        modify->add_fix(3, const_cast<char **>(args));
        k = modify->nfix - 1;
    }
    LAMMPS_NS::FixCapillaryFinish *fix =
        static_cast<LAMMPS_NS::FixCapillaryFinish *>(modify->fix[k]);
    fix->pass = pass;
    return fix;
}

/* A wall's model: the pass of the pair's model (NULL: the pair_style has no cohesion
 * capillary). */
inline LiquidPass *pair_pass(LAMMPS_NS::Modify *modify)
{
    const int k = modify->find_fix("capillaryFinish");
    if (k < 0 || std::strcmp(modify->fix[k]->style, "capillary/finish") != 0) return NULL;
    return static_cast<LAMMPS_NS::FixCapillaryFinish *>(modify->fix[k])->pass;
}

}  // namespace capbridge_liggghts

#endif
#endif
