/* capbridge_liggghts_laws.h — the capillary laws of `cohesion capillary`, one per distinct
 * contact angle (and, viscous on, viscosity and minimum gap) of a pair of atom types.
 *
 * Part of capbridge (lammps_pair/liggghts/). Compiled inside LIGGGHTS: C++98 and C++11.
 *
 * The law of a pair of types is the core's cb_law of the model's keywords (law, rupture,
 * overlap, validity, and the law's own keywords such as richefeu_c), the surface tension,
 * the mean of the two types' contact angles (at a wall, of a grain's type and the wall's:
 * the core's cb_wall_contact_angle, the angle of the mean cosine, as LAMMPS's fix
 * capillary/wall) and (viscous on) the pair's liquidViscosity and
 * viscousMinGap.  The laws are built again only when one of these changed (the table law
 * builds its table in cb_law_prepare), so that a run after a run costs nothing here.
 */
#ifndef CAPBRIDGE_LIGGGHTS_LAWS_H_
#define CAPBRIDGE_LIGGGHTS_LAWS_H_

#include "capbridge.h"
#include "error.h"

#include <cstdio>
#include <string>
#include <vector>

namespace capbridge_liggghts {

/* A law's own keyword as `cohesion capillary` spells it: the law's name, '_', the core's
 * keyword (Richefeu's c is `richefeu_c`, the name users have), one per keyword of the core's
 * registry rows (cb_law_keyword_of): a new law's keywords need no edit here. */
struct LawKeywordWord {
    cb_model model;
    int index;             // in the law's list (cb_law_keyword_of)
    std::string spelling;  // law name + "_" + keyword
    std::string value;     // as the user gave it
    bool given;
};

inline std::string law_keyword_spelling(const cb_model model, const int index)
{
    return std::string(cb_model_name(model)) + "_" + cb_law_keyword_of(model, index)->name;
}

/* Every law's own keywords, in the order of the registry */
inline std::vector<LawKeywordWord> law_keyword_words()
{
    std::vector<LawKeywordWord> words;
    for (int m = 0; m < CB_MODEL_COUNT; ++m)
        for (int k = 0; k < cb_law_keyword_count((cb_model)m); ++k) {
            LawKeywordWord word = {(cb_model)m, k, law_keyword_spelling((cb_model)m, k), "",
                                   false};
            words.push_back(word);
        }
    return words;
}

/* The word check of a law's own keyword (as settings.h's checks): the core reads the value
 * as it would for its law (cb_law_configure), so that a bad value stops at the keyword. */
inline bool check_law_keyword(const std::string &spelling, const std::string &value,
                              std::string &why)
{
    const std::vector<LawKeywordWord> words = law_keyword_words();
    for (size_t w = 0; w < words.size(); ++w) {
        if (words[w].spelling != spelling) continue;
        cb_law scratch;
        cb_message msg;
        msg.text[0] = '\0';
        cb_law_init(&scratch, words[w].model, 1.0, 0.0);
        const char *keyword = cb_law_keyword_of(words[w].model, words[w].index)->name;
        if (cb_law_configure(&scratch, keyword, value.c_str(), &msg) == CB_OK) return true;
        why = "cohesion model capillary: keyword '" + spelling + "': " + msg.text;
        return false;
    }
    why = "cohesion model capillary: '" + spelling + "' is no law's keyword";
    return false;
}

/* The model's keywords that make a law (as the user gave them). */
struct LawWords {
    cb_model model;
    std::string name, rupture, overlap, validity;
    std::vector<LawKeywordWord> keywords;  // every law's own (law_keyword_words)
};

class PairLaws {
  public:
    PairLaws() : ntypes_(0) {}
    ~PairLaws() { release(); }

    /* The laws of atom types 1..ntypes; contact_angle [rad] per type; viscosity [Pa s] and
     * min_gap [m] per pair of types, or NULL (viscous off); wall: the laws of a fix
     * wall/gran (grain type, wall type).  An error (all ranks: the same input) for a law the
     * core refuses. */
    void build(LAMMPS_NS::Error *error, const LawWords &words, const double surface_tension,
               const double *contact_angle, double **viscosity, double **min_gap,
               const int ntypes, const bool wall)
    {
        refuse_other_laws_keywords(error, words);
        ntypes_ = ntypes;
        std::vector<Distinct> distinct;
        std::vector<int> index((ntypes + 1) * (ntypes + 1), 0);
        for (int a = 1; a <= ntypes; ++a)
            for (int b = 1; b <= ntypes; ++b) {
                const double theta =
                    wall ? cb_wall_contact_angle(contact_angle[a], contact_angle[b])
                         : 0.5 * (contact_angle[a] + contact_angle[b]);
                Distinct d = {theta, 0.0, 0.0};
                if (viscosity && viscosity[a][b] > 0.0) {
                    d.viscosity = viscosity[a][b];
                    d.min_gap = min_gap[a][b];
                }
                size_t k = 0;
                while (k < distinct.size() && !distinct[k].same(d)) ++k;
                if (k == distinct.size()) distinct.push_back(d);
                index[a * (ntypes + 1) + b] = (int)k;
            }
        char number[96];
        std::string key = words.name + "|" + words.rupture + "|" + words.overlap + "|" +
                          words.validity;
        for (size_t w = 0; w < words.keywords.size(); ++w)
            key += "|" + (words.keywords[w].given ? words.keywords[w].value : "-");
        snprintf(number, sizeof number, "|%.17g", surface_tension);
        key += number;
        for (size_t k = 0; k < distinct.size(); ++k) {
            snprintf(number, sizeof number, "|%.17g,%.17g,%.17g", distinct[k].theta,
                     distinct[k].viscosity, distinct[k].min_gap);
            key += number;
        }
        pair_law = index;
        if (key == key_ && laws.size() == distinct.size()) return;

        release();
        for (size_t k = 0; k < distinct.size(); ++k) {
            cb_law law;
            cb_message msg;
            msg.text[0] = '\0';
            const cb_status status = cb_law_init(&law, words.model, surface_tension,
                                                 distinct[k].theta);
            if (status != CB_OK)
                fail(error, std::string("cohesion model capillary: ") + cb_status_message(status));
            configure(error, words, law, "rupture", words.rupture);
            configure(error, words, law, "overlap", words.overlap);
            configure(error, words, law, "validity", words.validity);
            for (size_t w = 0; w < words.keywords.size(); ++w)
                if (words.keywords[w].given)  // the law's own (refuse_other_laws_keywords)
                    configure(error, words, law,
                              cb_law_keyword_of(words.model, words.keywords[w].index)->name,
                              words.keywords[w].value);
            if (distinct[k].viscosity > 0.0) {  // the core's keywords, its parsing
                snprintf(number, sizeof number, "%.17g", distinct[k].viscosity);
                configure(error, words, law, "viscosity", number);
                snprintf(number, sizeof number, "%.17g", distinct[k].min_gap);
                configure(error, words, law, "min_gap", number);
            }
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

    std::vector<cb_law> laws;   // one per Distinct of a pair of types
    std::vector<int> pair_law;  // per pair of types, [a * (ntypes + 1) + b]: its law in laws

  private:
    /* what makes the law of a pair of types differ from another's */
    struct Distinct {
        double theta, viscosity, min_gap;  // [rad], [Pa s], [m] (viscosity 0: none)
        bool same(const Distinct &o) const
        {
            return theta == o.theta && viscosity == o.viscosity && min_gap == o.min_gap;
        }
    };

    /* A law's own keyword given for another law, refused by the name the user gave (the
     * core would read a keyword another law spells alike as that law's own). */
    static void refuse_other_laws_keywords(LAMMPS_NS::Error *error, const LawWords &words)
    {
        for (size_t w = 0; w < words.keywords.size(); ++w) {
            const LawKeywordWord &word = words.keywords[w];
            if (!word.given || word.model == words.model) continue;
            const cb_law_keyword *keyword = cb_law_keyword_of(word.model, word.index);
            fail(error, "cohesion model capillary: keyword '" + word.spelling + "' (" +
                            keyword->description + ", the keyword '" + keyword->name +
                            "' of law " + cb_model_name(word.model) + ") applies to law " +
                            cb_model_name(word.model) + " only, not to " + words.name);
        }
    }

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
