/* capbridge_liggghts_laws.h — the capillary laws of `cohesion capillary`, one per distinct
 * contact angle of a pair of atom types.
 *
 * Part of capbridge (lammps_pair/liggghts/). Compiled inside LIGGGHTS: C++98 and C++11.
 *
 * The law of a pair of types is the core's cb_law of the model's keywords (law, rupture,
 * overlap, validity, richefeu_c), the surface tension and the mean of the two types' contact
 * angles.  The laws are built again only when one of these changed (the table law builds its
 * table in cb_law_prepare), so that a run after a run costs nothing here.
 */
#ifndef CAPBRIDGE_LIGGGHTS_LAWS_H_
#define CAPBRIDGE_LIGGGHTS_LAWS_H_

#include "capbridge.h"
#include "error.h"

#include <cstdio>
#include <string>
#include <vector>

namespace capbridge_liggghts {

/* The model's keywords that make a law (as the user gave them). */
struct LawWords {
    cb_model model;
    std::string name, rupture, overlap, validity, richefeu_c;
    bool c_given;
};

class PairLaws {
  public:
    PairLaws() : ntypes_(0) {}
    ~PairLaws() { release(); }

    /* The laws of atom types 1..ntypes; contact_angle [rad] per type.  An error (all ranks:
     * the same input) for a law the core refuses. */
    void build(LAMMPS_NS::Error *error, const LawWords &words, const double surface_tension,
               const double *contact_angle, const int ntypes)
    {
        ntypes_ = ntypes;
        std::vector<double> thetas;
        std::vector<int> index((ntypes + 1) * (ntypes + 1), 0);
        for (int a = 1; a <= ntypes; ++a)
            for (int b = 1; b <= ntypes; ++b) {
                const double theta = 0.5 * (contact_angle[a] + contact_angle[b]);
                size_t k = 0;
                while (k < thetas.size() && thetas[k] != theta) ++k;
                if (k == thetas.size()) thetas.push_back(theta);
                index[a * (ntypes + 1) + b] = (int)k;
            }
        char number[64];
        std::string key = words.name + "|" + words.rupture + "|" + words.overlap + "|" +
                          words.validity + "|" + (words.c_given ? words.richefeu_c : "-");
        snprintf(number, sizeof number, "|%.17g", surface_tension);
        key += number;
        for (size_t k = 0; k < thetas.size(); ++k) {
            snprintf(number, sizeof number, "|%.17g", thetas[k]);
            key += number;
        }
        pair_law = index;
        if (key == key_ && laws.size() == thetas.size()) return;

        release();
        for (size_t k = 0; k < thetas.size(); ++k) {
            cb_law law;
            cb_message msg;
            msg.text[0] = '\0';
            const cb_status status = cb_law_init(&law, words.model, surface_tension, thetas[k]);
            if (status != CB_OK)
                fail(error, std::string("cohesion model capillary: ") + cb_status_message(status));
            configure(error, words, law, "rupture", words.rupture);
            configure(error, words, law, "overlap", words.overlap);
            configure(error, words, law, "validity", words.validity);
            if (words.c_given) configure(error, words, law, "c", words.richefeu_c);
            if (cb_law_prepare(&law, &msg) != CB_OK) {
                cb_law_release(&law);
                fail(error, "cohesion model capillary: law " + words.name + ": " + msg.text);
            }
            laws.push_back(law);
        }
        key_ = key;
    }

    void release()
    {
        for (size_t k = 0; k < laws.size(); ++k) cb_law_release(&laws[k]);
        laws.clear();
        key_.clear();
    }

    /* the law of a pair of atom types */
    const cb_law *of(const int itype, const int jtype) const
    {
        return &laws[pair_law[itype * (ntypes_ + 1) + jtype]];
    }

    std::vector<cb_law> laws;   // one per distinct contact angle of a pair of types
    std::vector<int> pair_law;  // per pair of types, [a * (ntypes + 1) + b]: its law in laws

  private:
    static void configure(LAMMPS_NS::Error *error, const LawWords &words, cb_law &law,
                          const char *keyword, const std::string &value)
    {
        cb_message msg;
        msg.text[0] = '\0';
        if (cb_law_configure(&law, keyword, value.c_str(), &msg) != CB_OK) {
            cb_law_release(&law);
            fail(error, "cohesion model capillary: law " + words.name + ": " + msg.text);
        }
    }

    static void fail(LAMMPS_NS::Error *error, const std::string &message)
    {
        error->all(FLERR, message.c_str());
    }

    std::string key_;  // what the laws were built from
    int ntypes_;
};

} /* namespace capbridge_liggghts */

#endif /* CAPBRIDGE_LIGGGHTS_LAWS_H_ */
