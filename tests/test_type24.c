/*
 * /INTER/TYPE24 (cards_interfaces.c, model/type7.c): the card read in
 * Radioss's layout (fields, defaults, line locations), and the contact the
 * compiler makes of it: one TYPE6 contact of the two segment surfaces,
 * both ways (the nodes of each against the segments of the other), the
 * linear law k = Stfac, zero gap, Fric with the stick stiffness k, VISs of
 * the critical damping 2 sqrt(k m*); units; the model errors (Istf 0 on
 * segments without shells, two surfaces of one body).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/error.h"
#include "case/case.h"
#include "harness.h"
#include "model/model.h"
#include "model/segsurf.h"
#include "testutil.h"

/* An upper box (/RBODY/1, 2 kg, corners 11-18, faces /SURF/SEG/31) above a
 * lower box (/RBODY/2, 7 kg, corners 21-28, faces /SURF/SEG/30); node 9 of
 * no body; a fixed square /SURF/SEG/9 on nodes 41-44 of no body.
 * /INTER/TYPE24/24: the two boxes' faces (Istf 1, Stfac 3.7e4 N/m, Fric
 * 0.23, Tstart 0.01, Tstop 0.09, Inacti 5, VISs 0.2, Gap_max_s 2 mm,
 * Igap0 1000); /INTER/TYPE24/25: the upper faces against the square, every
 * field blank but Stfac 5e4 (Istf 1). */
static const char t24_deck_a[] =
    "#RADIOSS STARTER\n"
    "/BEGIN\n"
    "type24 test\n"
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
    "         9                 0.5                 0.5                 0.3\n"
    "        41                  -1                  -1                  -1\n"
    "        42                   1                  -1                  -1\n"
    "        43                   1                   1                  -1\n"
    "        44                  -1                   1                  -1\n"
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

static const char t24_deck_b[] =
    "/SURF/SEG/9\n"
    "fixed square\n"
    "         1        41        42        43        44\n"
    "/INTER/TYPE24/24\n"
    "two boxes\n"
    "        31        30         1                             0                   0\n"
    "         0                             0                   0               0.002                   0\n"
    "                   0                   0      1000         0                   0\n"
    "               37000                0.23                                    0.01                0.09\n"
    "         0                             5                 0.2                                       0\n"
    "         0         0                   0                   0                                       0\n"
    "/INTER/TYPE24/25\n"
    "upper box on the fixed square\n"
    "        31         9         1                             0                   0\n"
    "\n"
    "\n"
    "                 5e4\n"
    "\n"
    "\n"
    "/GRAV/1\n"
    "gravity\n"
    "         0         Z         0         0         0                             1               -9.81\n"
    "/RUN\n"
    "                 0.1                0.01\n"
    "/END\n";

/* The whole deck (two literals: C11 guarantees 4095 characters each), with
 * the first occurrence of `from` replaced by `to` (same length) when from
 * is not NULL; NULL when from is not found. */
static const char *deck_with(const char *from, const char *to)
{
    static char text[sizeof t24_deck_a + sizeof t24_deck_b];
    snprintf(text, sizeof text, "%s%s", t24_deck_a, t24_deck_b);
    if (!from) return text;
    char *at = strstr(text, from);
    if (!at || strlen(from) != strlen(to)) return NULL;
    memcpy(at, to, strlen(to));
    return text;
}

static int line_of(const char *text, const char *what)
{
    const char *at = strstr(text, what);
    int n = 1;
    for (const char *p = text; at && p < at; p++) n += *p == '\n';
    return at ? n : -1;
}

static void test_type24_read(void)
{
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    const char *text = deck_with(NULL, NULL);
    const rc_status st = rc_case_load(tu_tmp_write("t24read.rad", text), &c, &e);
    ENSURE(st == RC_OK);
    if (st != RC_OK) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    ENSURE(c->ntype24 == 2 && c->ntype6 == 0 && c->ntype7 == 0);
    const rc_case_type24 *t = &c->type24[0];
    ENSURE(t->id == 24 && t->surf1 == 31 && t->surf2 == 30 && t->istf == 1);
    ENSURE_NEAR(t->stfac, 3.7e4, 0, 0);
    ENSURE_NEAR(t->fric, 0.23, 0, 0);
    ENSURE(t->tstart == 0.01 && t->tstop == 0.09 && t->inacti == 5 && t->viss == 0.2);
    ENSURE(t->sensor_id == 0 && t->fric_id == 0 && t->stmin == 0 && t->stmax == 0);
    const int l1 = line_of(text, "/INTER/TYPE24/24") + 2;
    ENSURE(t->line_loc[0].line == l1 && t->line_loc[3].line == l1 + 3 && t->line_loc[5].line == l1 + 5);
    /* blank lines: Radioss's defaults (VISs 0.05, Tstop 1e30, Inacti 0) */
    const rc_case_type24 *u = &c->type24[1];
    ENSURE(u->id == 25 && u->surf1 == 31 && u->surf2 == 9 && u->istf == 1 && u->stfac == 5e4);
    ENSURE(u->viss == 0.05 && u->tstop == 1e30 && u->inacti == 0 && u->fric == 0 && u->tstart == 0);
    rc_case_free(c);
}

static void test_type24_model(void)
{
    rc_model *m = TU_COMPILE_OK(deck_with(NULL, NULL), "t24model.rad");
    if (!m) return;
    ENSURE(m->ninter == 2);
    if (m->ninter != 2) {
        rc_model_free(m);
        return;
    }
    ENSURE(m->inter_id[0] == 24 && m->inter_id[1] == 25);
    ENSURE(strcmp(m->inter_name[0], "/INTER/TYPE24/24") == 0);
    /* both ways: the 8 nodes of each box against the other's segments; the
     * upper box's 8 nodes and the square's 4 */
    ENSURE(m->inter_pair[0] == RC_PAIR_SEG_SEG && !m->inter_oneway[0] && rc_seg_points(m, 0) == 16);
    ENSURE(m->inter_pair[1] == RC_PAIR_SEG_SEG && !m->inter_oneway[1] && rc_seg_points(m, 1) == 12);
    /* the law: F = Stfac P, zero gap, Fric with the stick stiffness k */
    ENSURE_NEAR(m->inter_fscaleld[0] / m->inter_ascalex[0], 3.7e4, 1e-15, 0);
    ENSURE_NEAR(m->inter_fscaleld[1] / m->inter_ascalex[1], 5e4, 1e-15, 0);
    ENSURE(m->inter_gap[0] == 0 && m->inter_gap[1] == 0);
    ENSURE(m->inter_fr[0].kind == RC_FK_TYPE6 && m->inter_fr[1].kind == RC_FK_NONE);
    ENSURE_NEAR(m->inter_fr[0].fric, 0.23, 0, 0);
    ENSURE_NEAR(m->inter_fr[0].kt, 3.7e4, 1e-15, 0);
    ENSURE(m->inter_tstart[0] == 0.01 && m->inter_tstop[0] == 0.09);
    /* VISs of the critical damping of k and the reduced mass (2 kg
     * against 7 kg; against the fixed square: the body's 2 kg) */
    ENSURE_NEAR(m->inter_visc[0], 0.2 * 2.0 * sqrt(3.7e4 * 2.0 * 7.0 / 9.0), 1e-14, 0);
    ENSURE_NEAR(m->inter_visc[1], 0.05 * 2.0 * sqrt(5e4 * 2.0), 1e-14, 0);
    rc_model_free(m);
}

/* Units: with Istf 1 Stfac is a stiffness (converted), with Istf 0 a
 * factor (not converted); Tstart a time. */
static void test_type24_units(void)
{
    char buf[sizeof t24_deck_a + sizeof t24_deck_b];
    const char *text = deck_with("                  kg                   m                   s\n",
                                 "                   g                  mm                  ms\n");
    ENSURE(text != NULL);
    if (!text) return;
    snprintf(buf, sizeof buf, "%s", text);
    char *l25 = strstr(buf, "        31         9         1");
    ENSURE(l25 != NULL);
    if (!l25) return;
    l25[29] = '0'; /* /INTER/TYPE24/25: Istf 0 */
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    const rc_status st = rc_case_load(tu_tmp_write("t24units.rad", buf), &c, &e);
    ENSURE(st == RC_OK);
    if (st != RC_OK) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    /* g mm ms: 1 g/ms^2 = 1e3 N/m */
    ENSURE_NEAR(c->type24[0].stfac, 3.7e7, 1e-15, 0);
    ENSURE_NEAR(c->type24[0].tstart, 1e-5, 1e-15, 0);
    ENSURE(c->type24[1].istf == 0);
    ENSURE_NEAR(c->type24[1].stfac, 5e4, 1e-15, 0);
    rc_case_free(c);
}

/* The model's errors: Istf 0 on segments without shells names the
 * segment; two surfaces of one body. */
static void test_type24_model_errors(void)
{
    const char *text = deck_with("        31        30         1", "        31        30         0");
    ENSURE(text != NULL);
    if (text)
        TU_EXPECT_TEXT_ERROR(text, "t24istf0.rad", "card /INTER/TYPE24/24, field Istf", "segment 1 of /SURF/SEG/31",
                             "is on no /SHELL or /SH3N", "expected Istf 1");
    text = deck_with("        31         9         1", "        31         9       100");
    ENSURE(text != NULL);
    if (text)
        TU_EXPECT_TEXT_ERROR(text, "t24istf100.rad", "card /INTER/TYPE24/25, field Istf", "expected 0, 1000",
                             "2, 3, 4 or 5", "got \"100\"");
    /* TYPE24's Istf 6 (the smaller, adjusted for Radioss's implicit
     * solver) is read as 4 */
    text = deck_with("        31         9         1", "        31         9         6");
    ENSURE(text != NULL);
    if (text) {
        rc_case *c = NULL;
        rc_error e;
        rc_error_clear(&e);
        const rc_status st = rc_case_load(tu_tmp_write("t24istf6.rad", text), &c, &e);
        ENSURE(st == RC_OK && c->type24[1].istf == 4);
        if (st) fprintf(stderr, "  %s\n", e.msg);
        rc_case_free(c);
    }
}

/* /INTER/TYPE25/26 between the two boxes' faces (Istf 1, Stfac 4.2e4 N/m,
 * Fric 0.11, Igap 1000, Iedge 0, Inacti 5, VISs 0.3), in place of the
 * TYPE24 cards. */
static const char t25_deck_c[] =
    "/INTER/TYPE25/26\n"
    "two boxes\n"
    "        31        30         1         0      1000         0                   0         0\n"
    "         0                             0                   0                   0                   0\n"
    "                   0                   0         0         0                   0\n"
    "               42000                0.11                                       0                   0\n"
    "         0                   0         5                 0.3\n"
    "         0         0                   0                   0                                       0\n"
    "/GRAV/1\n"
    "gravity\n"
    "         0         Z         0         0         0                             1               -9.81\n"
    "/RUN\n"
    "                 0.1                0.01\n"
    "/END\n";

/* The TYPE25 deck, with the first occurrence of `from` replaced by `to`
 * (same length) when from is not NULL; NULL when from is not found. */
static const char *deck25_with(const char *from, const char *to)
{
    static char text[sizeof t24_deck_a + sizeof t25_deck_c];
    snprintf(text, sizeof text, "%s%s", t24_deck_a, t25_deck_c);
    if (!from) return text;
    char *at = strstr(text, from);
    if (!at || strlen(from) != strlen(to)) return NULL;
    memcpy(at, to, strlen(to));
    return text;
}

/* TYPE25: its own layout (Iedge 81-90, IVIS2 21-30, Inacti 31-40, VISs
 * 41-60 of line 5), the same two-way contact as TYPE24; Iedge on two
 * closed box meshes: their boxes' pair; on other segment surfaces refused
 * by the compiler. */
static void test_type25(void)
{
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    const rc_status st = rc_case_load(tu_tmp_write("t25read.rad", deck25_with(NULL, NULL)), &c, &e);
    ENSURE(st == RC_OK);
    if (st != RC_OK) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    ENSURE(c->ntype24 == 1 && c->type24[0].type == 25 && c->type24[0].id == 26);
    const rc_case_type24 *t = &c->type24[0];
    ENSURE(t->surf1 == 31 && t->surf2 == 30 && t->istf == 1 && t->iedge == 0 && t->inacti == 5 && t->viss == 0.3);
    ENSURE(t->stfac == 42000 && t->fric == 0.11 && t->tstop == 1e30);
    rc_case_free(c);
    rc_model *m = TU_COMPILE_OK(deck25_with(NULL, NULL), "t25model.rad");
    if (m) {
        ENSURE(m->ninter == 1 && m->inter_id[0] == 26 && strcmp(m->inter_name[0], "/INTER/TYPE25/26") == 0);
        ENSURE(m->inter_pair[0] == RC_PAIR_SEG_SEG && !m->inter_oneway[0] && rc_seg_points(m, 0) == 16);
        ENSURE_NEAR(m->inter_fscaleld[0] / m->inter_ascalex[0], 4.2e4, 1e-15, 0);
        ENSURE_NEAR(m->inter_fr[0].fric, 0.11, 0, 0);
        ENSURE_NEAR(m->inter_visc[0], 0.3 * 2.0 * sqrt(4.2e4 * 2.0 * 7.0 / 9.0), 1e-14, 0);
        rc_model_free(m);
    }
    /* Iedge 2: the two face surfaces are closed box meshes (6
     * quadrilaterals on 8 corners each): taken as their boxes, the box
     * pair (8 + 8 corners, 144 edge pairs) */
    static const char iedge_from[] = "         0         0\n         0", iedge_to[] = "         0         2\n         0";
    m = TU_COMPILE_OK(deck25_with(iedge_from, iedge_to), "t25boxes.rad");
    if (m) {
        ENSURE(m->ninter == 1 && rc_box_is_box_pair(m, 0) && rc_seg_points(m, 0) == 16 + 144);
        ENSURE(m->surf_kind[m->inter_sa[0]] == RC_SURF_BOX && m->inter_ba[0] == 0 && m->inter_bb[0] == 1);
        ENSURE_NEAR(m->inter_fscaleld[0] / m->inter_ascalex[0], 4.2e4, 1e-15, 0);
        rc_model_free(m);
    }
    /* a face surface that is not a closed box mesh (a segment on 3 nodes) */
    char buf[sizeof t24_deck_a + sizeof t25_deck_c];
    snprintf(buf, sizeof buf, "%s", deck25_with(iedge_from, iedge_to));
    char *seg = strstr(buf, "        14        11        15        18");
    ENSURE(seg != NULL);
    if (seg) {
        memcpy(seg, "        14        11        15        15", 40);
        TU_EXPECT_TEXT_ERROR(buf, "t25iedge.rad", "card /INTER/TYPE25/26, field Iedge",
                             "edge-to-edge contact of segment surfaces", "closed box meshes", "/SURF/SEG/31");
    }
}

/* TYPE24's Inacti -1 (every initial penetration acts): ricochet's 0, no
 * offset; values TYPE24 lacks (Radioss has -1, 0, 5, 1000) are errors. */
static void test_type24_inacti(void)
{
    static const char from[] = "         5                 0.2", to[] = "        -1                 0.2";
    rc_model *m = TU_COMPILE_OK(deck_with(from, to), "t24inacti.rad");
    if (m) {
        ENSURE(m->inter_inacti[0] == 0 && m->inter_oidx[0] < 0);
        rc_model_free(m);
    }
    TU_EXPECT_TEXT_ERROR(deck_with(from, "         6                 0.2"), "t24inacti6.rad",
                         "card /INTER/TYPE24/24, field Inacti", "expected -1 (every initial penetration acts)",
                         "Radioss's values of TYPE24");
}

void suite_type24(void);
void suite_type24(void)
{
    RUN_TEST(test_type24_read);
    RUN_TEST(test_type24_model);
    RUN_TEST(test_type24_units);
    RUN_TEST(test_type24_model_errors);
    RUN_TEST(test_type25);
    RUN_TEST(test_type24_inacti);
}
