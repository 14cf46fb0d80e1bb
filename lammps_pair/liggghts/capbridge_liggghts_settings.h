/* capbridge_liggghts_settings.h — word-valued keywords for a LIGGGHTS 3.8 contact model.
 *
 * Part of capbridge (lammps_pair/liggghts/). Compiled inside LIGGGHTS: C++98 and C++11.
 *
 * LIGGGHTS passes the keywords that follow the model names of `pair_style gran` and
 * `fix wall/gran` to a Settings object (settings.h). A model may register on/off, yes/no
 * and number keywords through Settings' public interface; Settings also implements
 * word-valued keywords (EnumSetting) but keeps the method that registers them private.
 * `cohesion capillary` needs words (`law willett`, `rupture lian`, `liquid protocol2`), so
 * this header adds a Setting subclass for words and inserts it into the Settings' map.
 * The model's on/off keywords are words too: LIGGGHTS's on/off reader reads the value past
 * the end of the command when the keyword is its last word (a std::string from NULL, which
 * aborts the run).  The word checks of the model's keywords are at the end of this file.
 *
 * The map is a private member of Settings. It is reached with the one access path C++
 * leaves open on purpose: names used in an explicit instantiation are not access checked
 * ([temp.explicit], C++98 14.7.2/8), so an explicit instantiation may take the address of
 * a private member and hand it to a friend function. No LIGGGHTS file is changed and no
 * layout is assumed; if a later LIGGGHTS renames the member, this fails to compile rather
 * than misbehaving. The explicit instantiation appears in every translation unit that
 * includes this header; GCC and Clang treat the repeated instantiation (whose only
 * product is an inline friend) like any inline function.
 */
#ifndef CAPBRIDGE_LIGGGHTS_SETTINGS_H_
#define CAPBRIDGE_LIGGGHTS_SETTINGS_H_

#include "capbridge.h"
#include "input.h"
#include "settings.h"

#include <cstdio>
#include <functional>
#include <map>
#include <string>

namespace capbridge_liggghts {

typedef std::map<std::string, Setting *> SettingMap;
typedef SettingMap Settings::*SettingMapMember;

/* The map of a Settings object (defined by the explicit instantiation below). */
SettingMap &settings_map(Settings &settings);

template <SettingMapMember Member>
struct SettingsMapAccess {
    friend SettingMap &settings_map(Settings &settings) { return settings.*Member; }
};
template struct SettingsMapAccess<&Settings::settings>;

/* Checks a word; on failure writes the complete error message into `why`. */
typedef bool (*WordCheck)(const std::string &keyword, const std::string &value,
                          std::string &why);

/* `keyword word`: stores the word into a std::string of the model.  A keyword is given
 * once.  Settings passes no argument count, and LIGGGHTS's argument array is not
 * NULL-terminated (past the command's last argument lie those of earlier commands): the
 * end of the command is taken from `input`, the command being read, when the arguments
 * are its own. */
class WordSetting : public Setting {
  public:
    WordSetting(const std::string &keyword, WordCheck check, const LAMMPS_NS::Input *input)
        : Setting(keyword, 1), check_(check), input_(input), current_(), given_(false),
          target_(NULL), given_target_(NULL)
    {
    }
    virtual ~WordSetting() {}

    void set_default(const std::string &value) { current_ = value; store(); }
    void register_target(std::string &target, bool *given)
    {
        target_ = &target;
        given_target_ = given;
        store();
    }

    int parseArguments(char **args)
    {
        if (name != args[0]) return 0;
        if (args[1] == NULL || last_of_command(args)) {
            error_message = "cohesion model capillary: keyword '" + name + "' needs a value" +
                            allowed_values();
            return -1;
        }
        if (given_) {
            error_message = "cohesion model capillary: keyword '" + name + "' is given twice";
            return -1;
        }
        std::string value(args[1]);
        std::string why;
        if (check_ && !check_(name, value, why)) {
            error_message = why;
            return -1;
        }
        current_ = value;
        given_ = true;
        store();
        return 2;
    }

    void print_value(FILE *out) { fprintf(out, "%s", current_.c_str()); }

  private:
    /* " (allowed: ...)" as the check names them when it refuses an empty word, or "" */
    std::string allowed_values() const
    {
        std::string why;
        if (!check_ || check_(name, "", why)) return "";
        const std::string::size_type at = why.find("; allowed: ");
        return at == std::string::npos ? "" : " (" + why.substr(at + 2) + ")";
    }

    /* args[0] is the last argument of the command being read */
    bool last_of_command(char **args) const
    {
        if (!input_ || !input_->arg || input_->narg <= 0) return false;
        std::less<char **> before;
        char **first = input_->arg, **end = input_->arg + input_->narg;
        if (before(args, first) || !before(args, end)) return false; /* not its arguments */
        return !before(args + 1, end);
    }
    void store()
    {
        if (target_) *target_ = current_;
        if (given_target_) *given_target_ = given_;
    }
    WordCheck check_;
    const LAMMPS_NS::Input *input_;
    std::string current_;
    bool given_;
    std::string *target_;
    bool *given_target_;
};

/* A keyword the model no longer takes: given (with or without a value), it is an error with
 * `why`, the complete message (what it did, what happens now). */
class RemovedSetting : public Setting {
  public:
    RemovedSetting(const std::string &keyword, const std::string &why)
        : Setting(keyword, 1), why_(why)
    {
    }
    virtual ~RemovedSetting() {}
    int parseArguments(char **args)
    {
        if (name != args[0]) return 0;
        error_message = why_;
        return -1;
    }
    void print_value(FILE *out) { fprintf(out, "(removed)"); }

  private:
    std::string why_;
};

inline void register_removed(Settings &settings, const std::string &keyword,
                             const std::string &why)
{
    SettingMap &map = settings_map(settings);
    if (map.find(keyword) == map.end())
        map[keyword] = new RemovedSetting(keyword, why); /* owned (deleted) by Settings */
}

/* Register `keyword` (default value `initial`) in `settings`, bound to `target`;
 * *given (may be NULL) tells whether the keyword appeared; `input` is LIGGGHTS's command
 * reader (the end of the command). */
inline void register_word(Settings &settings, const std::string &keyword,
                          const std::string &initial, WordCheck check, std::string &target,
                          bool *given, const LAMMPS_NS::Input *input)
{
    SettingMap &map = settings_map(settings);
    WordSetting *setting = NULL;
    SettingMap::iterator it = map.find(keyword);
    if (it == map.end()) {
        setting = new WordSetting(keyword, check, input); /* owned (deleted) by Settings */
        setting->set_default(initial);
        map[keyword] = setting;
    } else {
        setting = dynamic_cast<WordSetting *>(it->second);
        if (!setting) return; /* another model owns this keyword: leave it alone */
    }
    if (given) *given = false;
    setting->register_target(target, given);
}

/* The word checks of `cohesion capillary`'s keywords (the message is the complete error). */
inline bool check_law(const std::string &, const std::string &value, std::string &why)
{
    cb_model model;
    if (cb_model_from_name(value.c_str(), &model) == CB_OK) return true;
    why = "cohesion model capillary: law '" + value + "' is unknown; allowed: " +
          std::string(cb_law_names());
    return false;
}

inline bool check_one_of(const std::string &keyword, const std::string &value,
                         const char *const *allowed, std::string &why)
{
    std::string list;
    for (int k = 0; allowed[k]; ++k) {
        if (value == allowed[k]) return true;
        if (k) list += ", ";
        list += allowed[k];
    }
    why = "cohesion model capillary: " + keyword + " '" + value + "' is unknown; allowed: " +
          list;
    return false;
}

inline bool check_rupture(const std::string &k, const std::string &v, std::string &why)
{
    static const char *const allowed[] = {"default", "lian", "willett", "willett/unequal", "exact", NULL};
    return check_one_of(k, v, allowed, why);
}
inline bool check_overlap(const std::string &k, const std::string &v, std::string &why)
{
    static const char *const allowed[] = {"contact", "none", NULL};
    return check_one_of(k, v, allowed, why);
}
inline bool check_validity(const std::string &k, const std::string &v, std::string &why)
{
    static const char *const allowed[] = {"extend", "strict", NULL};
    return check_one_of(k, v, allowed, why);
}
inline bool check_liquid(const std::string &k, const std::string &v, std::string &why)
{
    static const char *const allowed[] = {"fixed", "protocol1", "protocol2", "protocol3", NULL};
    return check_one_of(k, v, allowed, why);
}
inline bool check_on_off(const std::string &k, const std::string &v, std::string &why)
{
    static const char *const allowed[] = {"on", "off", NULL};
    return check_one_of(k, v, allowed, why);
}

} /* namespace capbridge_liggghts */

#endif /* CAPBRIDGE_LIGGGHTS_SETTINGS_H_ */
