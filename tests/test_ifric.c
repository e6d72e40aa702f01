/*
 * The friction law written on a penalty interface card (/INTER/TYPE7,
 * TYPE19, TYPE24, TYPE25: line 6's Ifric Ifiltr Xfreq and Radioss's law
 * lines C1..C5, C6 after it; case/cards_friction.c rc_inter_friction): it
 * compiles to the friction of the same law on a /FRICTION card named by
 * fric_ID (model/friction.c), field by field; the input errors of its
 * values.
 */
#include <stdio.h>
#include <string.h>

#include "base/error.h"
#include "case/case.h"
#include "harness.h"
#include "model/friction.h"
#include "model/model.h"
#include "testutil.h"

/* An upper box (/RBODY/1, 2 kg, corners 11-18 in /GRNOD/NODE/2, faces
 * /SURF/SEG/31) on a lower box (/RBODY/2, 7 kg, faces /SURF/SEG/30). */
static const char ifr_base[] =
    "#RADIOSS STARTER\n"
    "/BEGIN\n"
    "ifric test\n"
    "      2022         0\n"
    "                  kg                   m                   s\n"
    "                  kg                   m                   s\n"
    "/NODE\n"
    "         1                   0                   0              0.1037\n"
    "         2               0.013                   0                -0.2\n"
    "        11                -0.1                -0.1              0.0037\n"
    "        12                 0.1                -0.1              0.0037\n"
    "        13                 0.1                 0.1              0.0037\n"
    "        14                -0.1                 0.1              0.0037\n"
    "        15                -0.1                -0.1              0.2037\n"
    "        16                 0.1                -0.1              0.2037\n"
    "        17                 0.1                 0.1              0.2037\n"
    "        18                -0.1                 0.1              0.2037\n"
    "        21              -0.187                -0.2                -0.4\n"
    "        22               0.213                -0.2                -0.4\n"
    "        23               0.213                 0.2                -0.4\n"
    "        24              -0.187                 0.2                -0.4\n"
    "        25              -0.187                -0.2                   0\n"
    "        26               0.213                -0.2                   0\n"
    "        27               0.213                 0.2                   0\n"
    "        28              -0.187                 0.2                   0\n"
    "/RBODY/1\n"
    "upper\n"
    "         1                                                 2         2\n"
    "              0.0133              0.0133              0.0133\n"
    "                   0                   0                   0\n"
    "/RBODY/2\n"
    "lower\n"
    "         2                                                 7         3\n"
    "                0.19                0.19                0.19\n"
    "                   0                   0                   0\n"
    "/GRNOD/NODE/2\n"
    "group\n"
    "        11        12        13        14        15        16        17        18\n"
    "/GRNOD/NODE/3\n"
    "group\n"
    "        21        22        23        24        25        26        27        28\n"
    "/SURF/SEG/30\n"
    "lower faces\n"
    "         1        21        24        23        22\n"
    "         2        25        26        27        28\n"
    "         3        21        22        26        25\n"
    "         4        22        23        27        26\n"
    "         5        23        24        28        27\n"
    "         6        24        21        25        28\n"
    "/SURF/SEG/31\n"
    "upper faces\n"
    "         1        11        14        13        12\n"
    "         2        15        16        17        18\n"
    "         3        11        12        16        15\n"
    "         4        12        13        17        16\n"
    "         5        13        14        18        17\n"
    "         6        14        11        15        18\n";

static const char ifr_run[] = "/RUN\n                 0.1                0.01\n/END\n";

/* The interface card of `type` with Fric, line 6 and the law lines given. */
static void inter_card(char *out, size_t n, int type, const char *fric, const char *l6, const char *law)
{
    const char *l1 = type == 7 ? "         2        30         1\n" : "        31        30         1\n";
    snprintf(out, n, "/INTER/TYPE%d/%d\ninline friction\n%s\n\n%20s%20s\n\n%s\n%s", type, type, l1, "1e5", fric, l6,
             law);
}

/* deck = base, the interface card, an optional /FRICTION, /RUN */
static char *ifr_deck(int type, const char *fric, const char *l6, const char *law, const char *fcard)
{
    static char text[16384], card[2048];
    inter_card(card, sizeof card, type, fric, l6, law);
    snprintf(text, sizeof text, "%s%s%s%s", ifr_base, card, fcard ? fcard : "", ifr_run);
    return text;
}

static const char l6_fric_id[] =
    "                                                                                                   9";

/* The law on the card and on /FRICTION/9: the same compiled friction. */
static void expect_same(int type, const char *fric, const char *l6, const char *law, const char *fcard, int ifric,
                        double tau)
{
    char path[64];
    snprintf(path, sizeof path, "ifr%d_inline.rad", type);
    rc_model *a = TU_COMPILE_OK(ifr_deck(type, fric, l6, law, NULL), path);
    snprintf(path, sizeof path, "ifr%d_card.rad", type);
    rc_model *b = TU_COMPILE_OK(ifr_deck(type, "0", l6_fric_id, "", fcard), path);
    if (a && b) {
        ENSURE(a->ninter == 1 && b->ninter == 1);
        rc_fric fa = a->inter_fr[0], fb = b->inter_fr[0];
        ENSURE(fa.kind == RC_FK_CARD && fb.kind == RC_FK_CARD);
        ENSURE(fa.card_id < 0 && fb.card_id == 9);
        ENSURE(fa.ifric == ifric && fb.ifric == ifric);
        /* the form: TYPE24 and TYPE25 incremental; TYPE7, TYPE19 by Iform */
        const int incr = type == 24 || type == 25 || (strlen(l6) >= 50 && l6[49] == '2');
        ENSURE(fa.form == (incr ? RC_FF_INCREMENTAL : RC_FF_VISCOUS));
        ENSURE_NEAR(fa.tau, tau, 1e-15, 0);
        fa.card_id = fb.card_id;
        ENSURE(memcmp(&fa, &fb, sizeof fa) == 0);
        for (int k = 0; k < RC_FS_N; k++) ENSURE(fa.set[0][k] == fb.set[0][k]);
        ENSURE(fa.tau == fb.tau && fa.form == fb.form && fa.area == fb.area && fa.kt == fb.kt);
    }
    rc_model_free(a);
    rc_model_free(b);
}

#define PI_ 3.14159265358979323846

/* Renard filtered at 200 Hz (Ifric 3: C1..C5 and C6 lines), and the
 * generalised viscous law (Ifric 1: the C1..C5 line alone), on each card. */
static void test_ifric_same_as_friction(void)
{
    static const char l6_renard[] = "         3         3                 200";
    static const char law_renard[] = "                 0.3                0.25                 0.4                 0.2"
                                     "                0.05\n                 0.5\n";
    /* Iform: TYPE7's and TYPE19's (blank: 1, the viscous form); TYPE24 and
     * TYPE25 have none: 2, the incremental form of their own Fric */
    static const char card_renard[] = "/FRICTION/9\nRenard\n3,3,200,1\n0.3,0.25,0.4,0.2,0.05\n0.5,0,1\n";
    static const char card_renard2[] = "/FRICTION/9\nRenard\n3,3,200,2\n0.3,0.25,0.4,0.2,0.05\n0.5,0,1\n";
    static const char l6_visc[] = "         1";
    static const char law_visc[] = "                   0                 0.1\n";
    static const char card_visc[] = "/FRICTION/9\nviscous\n1,0,,1\n0,0.1\n0,0.3,1\n";
    static const char card_visc2[] = "/FRICTION/9\nviscous\n1,0,,2\n0,0.1\n0,0.3,1\n";
    const int types[4] = {7, 19, 24, 25};
    for (int k = 0; k < 4; k++) {
        const int incr = types[k] == 24 || types[k] == 25;
        expect_same(types[k], "0", l6_renard, law_renard, incr ? card_renard2 : card_renard, 3,
                    1.0 / (2.0 * PI_ * 200.0));
        expect_same(types[k], "0.3", l6_visc, law_visc, incr ? card_visc2 : card_visc, 1, 0.0);
    }
    /* TYPE7's Iform 2 is the law's (the incremental form) */
    expect_same(7, "0.3", "         1         0                   0         2", law_visc,
                "/FRICTION/9\nviscous\n1,0,,2\n0,0.1\n0,0.3,1\n", 1, 0.0);
    /* a fric_ID on the card wins over its own law (a warning) */
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    char l6[128];
    snprintf(l6, sizeof l6, "         3%89s9", "");
    const char *text = ifr_deck(24, "0", l6, law_renard, card_renard2);
    ENSURE(rc_case_load(tu_tmp_write("ifrboth.rad", text), &c, &e) == RC_OK);
    if (c) {
        ENSURE(c->ntype24 == 1 && c->type24[0].fric_id == 9 && c->nfriction == 1 && c->nwarnings >= 1);
        if (c->nwarnings >= 1) ENSURE(strstr(c->warnings[0], "/FRICTION/9, which applies"));
        rc_case_free(c);
    }
}

/* Values Radioss does not have, the refused filter, missing law lines. */
static void test_ifric_errors(void)
{
    static const char law5[] = "                 0.3                0.25                 0.4                 0.2"
                               "                0.05\n";
    TU_EXPECT_TEXT_ERROR(ifr_deck(24, "0", "         4", "", NULL), "ifrbad.rad", "card /INTER/TYPE24/24",
                         "field Ifric", "expected 0 (Coulomb: Fric), 1 (generalised viscous), 2", "got \"4\"");
    TU_EXPECT_TEXT_ERROR(ifr_deck(7, "0", "        -1", "", NULL), "ifrbad.rad", "card /INTER/TYPE7/7", "field Ifric",
                         "got \"-1\"");
    TU_EXPECT_TEXT_ERROR(ifr_deck(25, "0", "         0         5", "", NULL), "ifrbad.rad", "card /INTER/TYPE25/25",
                         "field Ifiltr", "got \"5\"");
    TU_EXPECT_TEXT_ERROR(ifr_deck(19, "0", "         0         1                 0.5", "", NULL), "ifrbad.rad",
                         "card /INTER/TYPE19/19", "field Ifiltr", "not supported yet", "Dt_ref");
    TU_EXPECT_TEXT_ERROR(ifr_deck(24, "0", "         0         1                 1.5", "", NULL), "ifrbad.rad",
                         "field Xfreq", "in [0, 1]");
    TU_EXPECT_TEXT_ERROR(ifr_deck(24, "0", "         0         3                   0", "", NULL), "ifrbad.rad",
                         "field Xfreq", "cut-off frequency > 0");
    /* Renard without its C6 line; C5 >= C6 */
    TU_EXPECT_TEXT_ERROR(ifr_deck(24, "0", "         3", law5, NULL), "ifrbad.rad", "card /INTER/TYPE24/24",
                         "field C6", "expected 8 data lines");
    TU_EXPECT_TEXT_ERROR(ifr_deck(7, "0", "         3", law5, NULL), "ifrbad.rad", "field C6");
    char law[256];
    snprintf(law, sizeof law, "%s%20s\n", law5, "0.04");
    TU_EXPECT_TEXT_ERROR(ifr_deck(25, "0", "         3", law, NULL), "ifrbad.rad", "card /INTER/TYPE25/25", "field C5",
                         "0 < C5 < C6");
    /* Ifric 1 reads one law line: a second is an extra line */
    snprintf(law, sizeof law, "%s%20s\n", law5, "0.5");
    TU_EXPECT_TEXT_ERROR(ifr_deck(24, "0", "         1", law, NULL), "ifrbad.rad", "expected 7 data lines");
    /* a pressure law on segments: the interface card has no Area */
    TU_EXPECT_TEXT_ERROR(ifr_deck(24, "0", "         1", "                0.01\n", NULL), "ifrbad.rad",
                         "card /INTER/TYPE24/24", "field Ifric", "reads the contact pressure", "fric_ID");
}

void suite_ifric(void);
void suite_ifric(void)
{
    RUN_TEST(test_ifric_same_as_friction);
    RUN_TEST(test_ifric_errors);
}
