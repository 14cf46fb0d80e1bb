/* test_registry.c — the law registry (law.c, each law's row in its file) is consistent:
 * every row complete, the names unique and the ones the parser knows, each law's
 * validity its own, each law's keywords its own (and what the public enumeration and the
 * tabulated flag return), and each law's held or stretched bridge
 * (its bridge_force from the constants kept at formation) the force of cb_force bit for
 * bit.  Argument "closed-form": the table law (whose table takes minutes to build under
 * the sanitizers) is left out of the force part. */
#include "capbridge.h"
#include "check.h"
#include "laws.h"

#include <string.h>

static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

static void rows_complete(void)
{
    for (int m = 0; m < CB_MODEL_COUNT; ++m) {
        const cb_law_ops *ops = cb_law_registry[m];
        CHECK(ops != NULL);
        if (!ops) continue;
        CHECK(ops->name && ops->name[0] && ops->force && ops->validity);
        CHECK(ops->bridge_constant && ops->bridge_force);
        CHECK(ops->default_rupture != CB_RUPTURE_DEFAULT);
        CHECK(ops->default_rupture != CB_RUPTURE_EXACT || ops->own_rupture);
        CHECK(!ops->own_rupture == !ops->own_rupture_volume);
        CHECK(!ops->prepare == !ops->release);
        CHECK(ops->keyword_count >= 0 && ops->keyword_count <= CB_LAW_PARAMETERS);
        CHECK(!ops->keywords == (ops->keyword_count == 0));
        CHECK(!ops->set_keyword == (ops->keyword_count == 0));
        for (int k = 0; k < ops->keyword_count; ++k)
            CHECK(ops->keywords[k].name[0] && ops->keywords[k].description[0] &&
                  ops->keywords[k].default_text[0]);
        CHECK(ops->tabulated == 0 || ops->tabulated == 1);
    }
}

/* The public enumeration of a law's own keywords (what the CLI's help and the engines'
 * keywords are made from) returns its row's list, in order, and nothing beyond it;
 * Richefeu's is c, 0.9 by default (Richefeu 2007 after eq. 9). */
static void keywords_enumerated(void)
{
    for (int m = 0; m < CB_MODEL_COUNT; ++m) {
        const cb_law_ops *ops = cb_law_registry[m];
        CHECK(cb_law_keyword_count((cb_model)m) == ops->keyword_count);
        for (int k = 0; k < ops->keyword_count; ++k)
            CHECK(cb_law_keyword_of((cb_model)m, k) == &ops->keywords[k]);
        CHECK(cb_law_keyword_of((cb_model)m, -1) == NULL);
        CHECK(cb_law_keyword_of((cb_model)m, ops->keyword_count) == NULL);
    }
    CHECK(cb_law_keyword_count(CB_MODEL_COUNT) == 0);
    CHECK(cb_law_keyword_of(CB_MODEL_COUNT, 0) == NULL);
    CHECK(cb_law_keyword_count(CB_MODEL_RICHEFEU) == 1);
    const cb_law_keyword *c = cb_law_keyword_of(CB_MODEL_RICHEFEU, 0);
    CHECK(c && strcmp(c->name, "c") == 0 && strcmp(c->default_text, "0.9") == 0);
    cb_law richefeu;
    CHECK_STATUS(cb_law_init(&richefeu, CB_MODEL_RICHEFEU, 0.072, 0.0), CB_OK);
    CHECK(richefeu.parameters[0] == 0.9);
}

/* Only the table law is tabulated: the CLI's cheapest closed-form law leaves it out. */
static void tabulated_only_table(void)
{
    for (int m = 0; m < CB_MODEL_COUNT; ++m)
        CHECK(cb_model_tabulated((cb_model)m) == (m == CB_MODEL_TABLE));
    CHECK(cb_model_tabulated(CB_MODEL_COUNT) == 0);
}

/* Names unique, through cb_model_from_name and cb_model_name both ways, and
 * cb_law_names the list of them all in the order of cb_model. */
static void names(void)
{
    char list[400] = "";
    for (int m = 0; m < CB_MODEL_COUNT; ++m) {
        const char *name = cb_law_registry[m]->name;
        cb_model found = CB_MODEL_COUNT;
        CHECK_STATUS(cb_model_from_name(name, &found), CB_OK);
        CHECK(found == (cb_model)m);
        CHECK(strcmp(cb_model_name((cb_model)m), name) == 0);
        for (int other = 0; other < m; ++other)
            CHECK(strcmp(name, cb_law_registry[other]->name) != 0);
        if (m > 0) strcat(list, ", ");
        strcat(list, name);
    }
    CHECK(strcmp(cb_law_names(), list) == 0);
    cb_model none = CB_MODEL_COUNT;
    CHECK_STATUS(cb_model_from_name("table/", &none), CB_ERR_UNKNOWN_LAW);
    CHECK(strcmp(cb_model_name(CB_MODEL_COUNT), "unknown") == 0);
}

static int same_validity(cb_validity a, cb_validity b)
{
    return same_bits(a.volume_min, b.volume_min) && same_bits(a.volume_max, b.volume_max) &&
           same_bits(a.contact_angle_max, b.contact_angle_max) &&
           same_bits(a.size_ratio_max, b.size_ratio_max) && a.radius == b.radius &&
           strcmp(a.source, b.source) == 0;
}

/* cb_law_validity is the row's validity, and a law shares another's range only where the
 * two rows name the same function (the two Rabinovich laws): no law falls back on another
 * law's range, as the table law's once was the default of a switch. */
static void validity_own(void)
{
    for (int m = 0; m < CB_MODEL_COUNT; ++m) {
        cb_law law;
        CHECK_STATUS(cb_law_init(&law, (cb_model)m, 0.072, 0.0), CB_OK);
        cb_validity v = cb_law_validity(&law);
        CHECK(same_validity(v, cb_law_registry[m]->validity(&law)));
        for (int other = 0; other < m; ++other) {
            cb_law o;
            CHECK_STATUS(cb_law_init(&o, (cb_model)other, 0.072, 0.0), CB_OK);
            int same_function = cb_law_registry[m]->validity == cb_law_registry[other]->validity;
            CHECK(same_function == (strcmp(v.source, cb_law_validity(&o).source) == 0));
        }
    }
}

/* A law's own keyword: its default after cb_law_init, accepted and stored by
 * cb_law_configure (once), told apart by cb_law_same, refused for every other law by
 * name, and listed among the allowed keywords of an unknown one. */
static void keywords_own(void)
{
    cb_message msg;
    cb_law unknown;
    CHECK_STATUS(cb_law_init(&unknown, CB_MODEL_WILLETT, 0.072, 0.0), CB_OK);
    CHECK_STATUS(cb_law_configure(&unknown, "no-such-keyword", "1", &msg),
                 CB_ERR_UNKNOWN_KEYWORD);
    for (int m = 0; m < CB_MODEL_COUNT; ++m) {
        const cb_law_ops *ops = cb_law_registry[m];
        for (int k = 0; k < ops->keyword_count; ++k) {
            const cb_law_keyword *kw = &ops->keywords[k];
            cb_law law, changed;
            CHECK_STATUS(cb_law_init(&law, (cb_model)m, 0.072, 0.0), CB_OK);
            double default_value = -1.0;
            CHECK(cb_parse_number(kw->default_text, &default_value));
            CHECK(same_bits(law.parameters[k], default_value));
            changed = law;
            cb_keywords_given given = {0};
            CHECK_STATUS(cb_law_configure_once(&changed, &given, kw->name, "0.625", &msg), CB_OK);
            CHECK(changed.parameters[k] == 0.625 && !cb_law_same(&law, &changed));
            CHECK_STATUS(cb_law_configure_once(&changed, &given, kw->name, "0.5", &msg),
                         CB_ERR_RANGE);
            CHECK(strstr(msg.text, "given twice") != NULL);
            char expected_name[80];
            snprintf(expected_name, sizeof expected_name, ", %s", kw->name);
            CHECK_STATUS(cb_law_configure(&unknown, "no-such-keyword", "1", &msg),
                         CB_ERR_UNKNOWN_KEYWORD);
            CHECK(strstr(msg.text, expected_name) != NULL);
            for (int other = 0; other < CB_MODEL_COUNT; ++other) {
                if (other == m) continue;
                cb_law o;
                CHECK_STATUS(cb_law_init(&o, (cb_model)other, 0.072, 0.0), CB_OK);
                CHECK_STATUS(cb_law_configure(&o, kw->name, "0.625", &msg),
                             CB_ERR_UNKNOWN_KEYWORD);
                CHECK(strstr(msg.text, ops->name) &&
                      strstr(msg.text, cb_law_registry[other]->name));
            }
        }
    }
}

/* One bridge formed at contact, then held at gaps up to its rupture distance: its force
 * from the row's bridge_force, cb_bridge_force and cb_bridge_step, each equal to cb_force
 * bit for bit, and its kept constant the row's. */
static void bridge_of_law(const cb_law *law, double r1, double r2, double volume)
{
    cb_bridge bridge;
    memset(&bridge, 0, sizeof bridge);
    cb_transition change;
    double released = 0.0, force = 0.0, rupture = 0.0;
    CHECK_STATUS(cb_bridge_step(law, r1, r2, 0.0, volume, &bridge, &change, &released, &force),
                 CB_OK);
    CHECK(change == CB_BRIDGE_FORMED);
    CHECK_STATUS(cb_rupture_distance(law, r1, r2, volume, &rupture), CB_OK);
    cb_pair pair;
    cb_pair_make(law, r1, r2, volume, &pair);
    const cb_law_ops *ops = cb_law_ops_of(law);
    CHECK(same_bits(bridge.law_constant, ops->bridge_constant(law, &pair)));
    CHECK(bridge.law_constant >= 0.0);
    if (law->model == CB_MODEL_RICHEFEU) CHECK(bridge.law_constant > 0.0); /* its 1/lambda */
    for (int i = -2; i <= 40; ++i) {
        double gap = rupture * i / 40.0, exact = 0.0, from_op = -1.0, held = -1.0, stepped = -1.0;
        if (i == 40) gap = rupture;
        cb_status status = cb_force(law, r1, r2, volume, gap, &exact, NULL);
        if (status == CB_ERR_NO_BRIDGE) continue; /* the strict Weigert law near its edge */
        CHECK_STATUS(status, CB_OK);
        if (gap > 0.0) {
            CHECK_STATUS(ops->bridge_force(law, &pair, &bridge, gap, &from_op), CB_OK);
            CHECK(same_bits(from_op, exact));
        }
        CHECK_STATUS(cb_bridge_force(law, r1, r2, gap, &bridge, &held), CB_OK);
        CHECK(same_bits(held, exact));
        cb_bridge copy = bridge;
        CHECK_STATUS(cb_bridge_step(law, r1, r2, gap, 0.0, &copy, &change, &released, &stepped),
                     CB_OK);
        CHECK(change == CB_BRIDGE_HELD && same_bits(stepped, exact));
        if (!same_bits(stepped, exact))
            fprintf(stderr, "  %s theta %g: gap %g, step %.17g, cb_force %.17g\n",
                    cb_model_name(law->model), law->contact_angle, gap, stepped, exact);
    }
}

static void bridges_equal_force(int with_table)
{
    const double geometry[][3] = {{1e-3, 1e-3, 1e-11}, {1e-3, 3e-3, 5e-11}, {2e-4, 1e-3, 1e-13}};
    /* the defaults (theta 0), then one keyword changed, then each of the law's own */
    const char *settings[][2] = {{"theta", "0"}, {"theta", "20"}, {"validity", "strict"},
                                 {"overlap", "none"}};
    enum { SETTINGS = sizeof settings / sizeof *settings };
    for (int m = 0; m < CB_MODEL_COUNT; ++m) {
        if (!with_table && m == CB_MODEL_TABLE) continue;
        const cb_law_ops *ops = cb_law_registry[m];
        for (int s = 0; s < SETTINGS + ops->keyword_count; ++s) {
            cb_law law;
            cb_message msg;
            CHECK_STATUS(cb_law_init(&law, (cb_model)m, 0.072, 0.0), CB_OK);
            const char *keyword = s < SETTINGS ? settings[s][0] : ops->keywords[s - SETTINGS].name;
            const char *value = s < SETTINGS ? settings[s][1] : "0.7";
            CHECK_STATUS(cb_law_configure(&law, keyword, value, &msg), CB_OK);
            CHECK_STATUS(cb_law_prepare(&law, &msg), CB_OK);
            for (int g = 0; g < 3; ++g) {
                double rupture = 0.0;
                cb_status inside = cb_rupture_distance(&law, geometry[g][0], geometry[g][1],
                                                       geometry[g][2], &rupture);
                if (inside == CB_ERR_OUT_OF_VALIDITY) continue; /* strict, outside */
                bridge_of_law(&law, geometry[g][0], geometry[g][1], geometry[g][2]);
            }
            cb_law_release(&law);
        }
    }
}

int main(int argc, char **argv)
{
    int with_table = !(argc > 1 && strcmp(argv[1], "closed-form") == 0);
    rows_complete();
    names();
    validity_own();
    keywords_own();
    keywords_enumerated();
    tabulated_only_table();
    bridges_equal_force(with_table);
    return check_report(argv[0]);
}
