/*
 * /INTER/TYPE7 (cards_interfaces.c, model/type7.c): the card read in
 * Radioss's layout, and the contacts the compiler makes of it: one TYPE6
 * contact per body of the secondary nodes (nodes on the main surface's body
 * left out, nodes of no body fixed), one way against a segment surface
 * (the nodes of the group only, while a TYPE6 between two segment surfaces
 * keeps both ways), the linear law k = Stfac, Gapmin, Fric with the stick
 * stiffness k, and VISs of the critical damping 2 sqrt(k m*); units (Stfac
 * a stiffness with Istf 1, a factor with Istf 0) and the Istf 0 errors.
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
 * no body. /INTER/TYPE6/6: the two face surfaces; /INTER/TYPE7/7: the upper
 * corners against the lower faces (Stfac 3.7e4 N/m, Fric 0.23, Gapmin
 * 1.1 mm); /INTER/TYPE7/8: the upper corners, node 9 and the lower box's
 * nodes 21 and 22 against the lower faces. */
static const char t7_deck_a[] =
    "#RADIOSS STARTER\n"
    "/BEGIN\n"
    "type7 test\n"
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
    "/GRNOD/NODE/4\n"
    "group\n"
    "        11        12        13        14        15        16        17        18         9        21\n"
    "        22\n"
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
    "         6        14        11        15        18\n"
    "/FUNCT/5\n"
    "curve\n"
    "                   0                   0\n"
    "                   1              100000\n";
static const char t7_deck_b[] =
    "/INTER/TYPE6/6\n"
    "contact\n"
    "        31        30\n"
    "                                                           0\n"
    "                   0         0         0         0         0\n"
    "         5         0                                                 0\n"
    "         0\n"
    "                             0         0\n"
    "/INTER/TYPE7/7\n"
    "box nodes on the floor\n"
    "         2        30         1         0         0                   0         0         0         0\n"
    "                   0                   0                   0         0\n"
    "                   0                   0                   0                   0         0         0\n"
    "               37000                0.23              0.0011                   0                   0\n"
    "         0                             0                   0                   0                   0\n"
    "         0         0                   0         0         0         0                   0         0\n"
    "/INTER/TYPE7/8\n"
    "box nodes on the floor\n"
    "         4        30         1         0         0                   0         0         0         0\n"
    "                   0                   0                   0         0\n"
    "                   0                   0                   0                   0         0         0\n"
    "               37000                   0                   0                   0                   0\n"
    "         0                             0                   0                   0                   0\n"
    "         0         0                   0         0         0         0                   0         0\n"
    "/GRAV/1\n"
    "gravity\n"
    "         0         Z         0         0         0                             1               -9.81\n"
    "/RUN\n"
    "                 0.1                0.01\n"
    "/END\n";

/* The whole deck (two literals: C11 guarantees 4095 characters each). */
static const char *deck_text(void)
{
    static char text[sizeof t7_deck_a + sizeof t7_deck_b];
    snprintf(text, sizeof text, "%s%s", t7_deck_a, t7_deck_b);
    return text;
}

static void test_type7_read(void)
{
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    const rc_status st = rc_case_load(tu_tmp_write("t7read.rad", deck_text()), &c, &e);
    ENSURE(st == RC_OK);
    if (st != RC_OK) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    ENSURE(c->ntype7 == 2 && c->ntype6 == 1);
    const rc_case_type7 *t = &c->type7[0];
    ENSURE(t->id == 7 && t->grnod_id == 2 && t->surf_id == 30 && t->istf == 1 && t->igap == 0);
    ENSURE_NEAR(t->stfac, 3.7e4, 0, 0);
    ENSURE_NEAR(t->fric, 0.23, 0, 0);
    ENSURE_NEAR(t->gapmin, 0.0011, 0, 0);
    ENSURE(t->tstart == 0 && t->tstop == 1e30 && t->inacti == 0 && t->sensor_id == 0 && t->fric_id == 0);
    ENSURE(t->viss == 0.05 && t->visf == 1.0); /* Radioss's defaults of blank or 0 */
    ENSURE(t->line_loc[0].line == 77 && t->line_loc[3].line == 80 && t->line_loc[5].line == 82);
    rc_case_free(c);
}

static void test_type7_model(void)
{
    rc_model *m = TU_COMPILE_OK(deck_text(), "t7model.rad");
    if (!m) return;
    /* TYPE6, TYPE7/7 (the upper body), TYPE7/8 (node 9, then the upper body;
     * the lower box's nodes 21, 22 on the main surface's body left out) */
    ENSURE(m->ninter == 4);
    if (m->ninter != 4) {
        rc_model_free(m);
        return;
    }
    ENSURE(m->inter_id[0] == 6 && m->inter_id[1] == 7 && m->inter_id[2] == 8 && m->inter_id[3] == 8);
    ENSURE(strstr(m->inter_name[1], "/INTER/TYPE7/7 (nodes of /RBODY/1)") != NULL);
    ENSURE(strstr(m->inter_name[2], "(nodes of no body)") != NULL);
    /* segments-segments: TYPE6 both ways (8 + 8 nodes), TYPE7 one way (8) */
    ENSURE(m->inter_pair[0] == RC_PAIR_SEG_SEG && !m->inter_oneway[0] && rc_seg_points(m, 0) == 16);
    ENSURE(m->inter_pair[1] == RC_PAIR_SEG_SEG && m->inter_oneway[1] && rc_seg_points(m, 1) == 8);
    ENSURE(rc_seg_points(m, 2) == 1 && m->inter_ba[2] < 0 && rc_seg_points(m, 3) == 8);
    ENSURE(m->inter_ba[1] == 0 && m->inter_bb[1] == 1);
    /* the law: F = Stfac P, the gap Gapmin, Fric with the stick stiffness k */
    ENSURE_NEAR(m->inter_fscaleld[1] / m->inter_ascalex[1], 3.7e4, 1e-15, 0);
    ENSURE_NEAR(m->inter_gap[1], 0.0011, 0, 0);
    ENSURE(m->inter_fr[1].kind == RC_FK_TYPE6 && m->inter_fr[3].kind == RC_FK_NONE);
    ENSURE_NEAR(m->inter_fr[1].fric, 0.23, 0, 0);
    ENSURE_NEAR(m->inter_fr[1].kt, 3.7e4, 1e-15, 0);
    /* VISs 0.05 of the critical damping of k and the reduced mass
     * (2 kg against 7 kg; against the fixed node 9: the body's 7 kg) */
    ENSURE_NEAR(m->inter_visc[1], 0.05 * 2.0 * sqrt(3.7e4 * 2.0 * 7.0 / 9.0), 1e-14, 0);
    ENSURE_NEAR(m->inter_visc[2], 0.05 * 2.0 * sqrt(3.7e4 * 7.0), 1e-14, 0);
    ENSURE(m->inter_visc[0] == 0);
    rc_model_free(m);
}

/* The deck with the first occurrence of `from` replaced by `to` (same
 * length), or NULL. */
static const char *deck_with(const char *from, const char *to)
{
    static char text[sizeof t7_deck_a + sizeof t7_deck_b];
    snprintf(text, sizeof text, "%s%s", t7_deck_a, t7_deck_b);
    char *at = strstr(text, from);
    if (!at || strlen(from) != strlen(to)) return NULL;
    memcpy(at, to, strlen(to));
    return text;
}

/* Units: with Istf 1 Stfac is a stiffness (converted), with Istf 0 a
 * factor (not converted); Gapmin a length. */
static void test_type7_units(void)
{
    const char *text = deck_with("                  kg                   m                   s\n",
                                 "                   g                  mm                  ms\n");
    ENSURE(text != NULL);
    if (!text) return;
    char buf[sizeof t7_deck_a + sizeof t7_deck_b];
    snprintf(buf, sizeof buf, "%s", text);
    char *l8 = strstr(buf, "         4        30         1");
    ENSURE(l8 != NULL);
    if (!l8) return;
    l8[29] = '0'; /* /INTER/TYPE7/8: Istf 0 */
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    const rc_status st = rc_case_load(tu_tmp_write("t7units.rad", buf), &c, &e);
    ENSURE(st == RC_OK);
    if (st != RC_OK) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    /* g mm ms: 1 g/ms^2 = 1e3 N/m */
    ENSURE_NEAR(c->type7[0].stfac, 3.7e7, 1e-15, 0);
    ENSURE_NEAR(c->type7[0].gapmin, 1.1e-6, 1e-15, 0);
    ENSURE(c->type7[1].istf == 0);
    ENSURE_NEAR(c->type7[1].stfac, 37000, 1e-15, 0);
    rc_case_free(c);
}

/* Istf 0 takes E t / 2 of the main shells: a main /SURF/SEG on no shell is
 * an input error naming the segment (the stiffness itself:
 * validation/type7_drop, type7.rest.istf0). */
static void test_type7_istf0_errors(void)
{
    const char *text = deck_with("         2        30         1", "         2        30         0");
    ENSURE(text != NULL);
    if (!text) return;
    TU_EXPECT_TEXT_ERROR(text, "t7istf0.rad", "card /INTER/TYPE7/7, field Istf", "segment 1 of /SURF/SEG/30",
                         "is on no /SHELL or /SH3N", "expected Istf 1");
}

/* Inacti: 6 read (the case keeps 6) and compiled as 5 (the offset state);
 * 1, 2 (penetrating points left out) compiled, here with nothing to leave
 * out; 3 (nodes moved) refused with its reason. */
static void test_type7_inacti(void)
{
    static const char from[] = "0.0011                   0                   0\n         0                             0";
    char to[sizeof from];
    memcpy(to, from, sizeof from);
    to[sizeof from - 2] = '6';
    const char *text = deck_with(from, to);
    ENSURE(text != NULL);
    if (!text) return;
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    const rc_status st = rc_case_load(tu_tmp_write("t7inacti6.rad", text), &c, &e);
    ENSURE(st == RC_OK && c->type7[0].inacti == 6 && c->type7[1].inacti == 0);
    if (st) fprintf(stderr, "  %s\n", e.msg);
    rc_case_free(c);
    rc_model *m = TU_COMPILE_OK(deck_with(from, to), "t7inacti6m.rad");
    if (m) {
        ENSURE(m->inter_inacti[1] == 5 && m->inter_oidx[1] >= 0 && m->inter_inacti[2] == 0 && m->inter_oidx[2] < 0);
        rc_model_free(m);
    }
    /* 1, 2: nothing penetrates (the corners 2.6 mm above the gap): the
     * model of Inacti 0, no notice (the points left out: test_inacti.c) */
    for (int v = 1; v <= 2; v++) {
        to[sizeof from - 2] = (char)('0' + v);
        m = TU_COMPILE_OK(deck_with(from, to), "t7inacti12.rad");
        if (m) {
            ENSURE(m->ninter == 4 && rc_seg_points(m, 1) == 8 && m->inter_inacti[1] == 0 && m->inter_oidx[1] < 0);
            ENSURE(rc_model_note_count(m) == 0);
            rc_model_free(m);
        }
    }
    to[sizeof from - 2] = '3';
    TU_EXPECT_TEXT_ERROR(deck_with(from, to), "t7inacti.rad", "card /INTER/TYPE7/7, field Inacti",
                         "moves the penetrating nodes onto the surface", "expected 0, blank, 1000");
}

/* Shells for Istf 2-5 and Igap 1, 2: the lower faces /PART/5 (E 4e7 Pa,
 * /PROP/SHELL t 0.01 m), the upper faces /PART/6 (E 1.2e8 Pa, t 0.02 m). */
static const char t7_shells[] =
    "/SHELL/5\n"
    "       101        21        24        23        22\n"
    "       102        25        26        27        28\n"
    "       103        21        22        26        25\n"
    "       104        22        23        27        26\n"
    "       105        23        24        28        27\n"
    "       106        24        21        25        28\n"
    "/SHELL/6\n"
    "       111        11        14        13        12\n"
    "       112        15        16        17        18\n"
    "       113        11        12        16        15\n"
    "       114        12        13        17        16\n"
    "       115        13        14        18        17\n"
    "       116        14        11        15        18\n"
    "/PART/5\n"
    "lower shells\n"
    "         5         5\n"
    "/PART/6\n"
    "upper shells\n"
    "         6         6\n"
    "/PROP/SHELL/5\n"
    "lower thickness\n"
    "\n"
    "\n"
    "         0         0                0.01\n"
    "/PROP/SHELL/6\n"
    "upper thickness\n"
    "\n"
    "\n"
    "         0         0                0.02\n"
    "/MAT/LAW1/5\n"
    "lower material\n"
    "                7800\n"
    "            40000000                 0.3\n"
    "/MAT/LAW1/6\n"
    "upper material\n"
    "                7800\n"
    "           120000000                 0.3\n";

/* The deck with the shells, its first occurrence of each from[j] replaced
 * by to[j] (same lengths), or NULL. */
static const char *shell_deck(int nrep, const char *const *from, const char *const *to)
{
    static char text[sizeof t7_deck_a + sizeof t7_shells + sizeof t7_deck_b];
    snprintf(text, sizeof text, "%s%s%s", t7_deck_a, t7_shells, t7_deck_b);
    for (int j = 0; j < nrep; j++) {
        char *at = strstr(text, from[j]);
        if (!at || strlen(from[j]) != strlen(to[j])) return NULL;
        memcpy(at, to[j], strlen(to[j]));
    }
    return text;
}

/* TYPE7/7 line 1 (Istf, Igap) and line 4 (Stfac 0.5, a factor) of the
 * shell deck. */
static const char t7_l1[] = "         2        30         1         0         0";
static const char t7_l4[] = "               37000                0.23";

/* Istf 2-5: km = Stfac E t / 2 of the lower (main) shells = 1e5 N/m, ks
 * the same of the upper box's shells on its corners = 6e5 N/m: their mean,
 * larger, smaller, in series; Stmax bounds the result; a secondary node on
 * no shell (node 9 of TYPE7/8) is an error naming it. */
static void test_type7_istf_combined(void)
{
    static const double want[6] = {0, 0, 3.5e5, 6e5, 1e5, 1e5 * 6e5 / 7e5};
    for (int istf = 2; istf <= 5; istf++) {
        char l1[sizeof t7_l1];
        memcpy(l1, t7_l1, sizeof l1);
        l1[29] = (char)('0' + istf);
        const char *from[2] = {t7_l1, t7_l4}, *to[2] = {l1, "                 0.5                0.23"};
        rc_model *m = TU_COMPILE_OK(shell_deck(2, from, to), "t7istf.rad");
        if (!m) continue;
        ENSURE(m->ninter == 4);
        if (m->ninter == 4) {
            ENSURE_NEAR(m->inter_fscaleld[1] / m->inter_ascalex[1], want[istf], 1e-14, 0);
            ENSURE_NEAR(m->inter_fr[1].kt, want[istf], 1e-14, 0);
            /* TYPE7/8 keeps Istf 1, Stfac 37000 */
            ENSURE_NEAR(m->inter_fscaleld[3] / m->inter_ascalex[3], 3.7e4, 1e-14, 0);
            printf("    Istf %d: k = %.9g N/m (closed form %.9g)\n", istf, m->inter_fscaleld[1] / m->inter_ascalex[1],
                   want[istf]);
        }
        rc_model_free(m);
    }
    /* Stmax 2e5 bounds Istf 3's 6e5 */
    {
        const char *from[3] = {"                   0                   0                   0                   0         0         0\n               37000",
                               t7_l1, t7_l4};
        const char *to[3] = {"                   0              200000                   0                   0         0         0\n               37000",
                             "         2        30         3         0         0", "                 0.5                0.23"};
        rc_model *m = TU_COMPILE_OK(shell_deck(3, from, to), "t7stmax.rad");
        if (m) {
            ENSURE(m->ninter == 4 && fabs(m->inter_fscaleld[1] / m->inter_ascalex[1] - 2e5) < 1e-9);
            rc_model_free(m);
        }
    }
    /* TYPE7/8's node 9 is on no shell */
    const char *from[1] = {"         4        30         1"}, *to[1] = {"         4        30         2"};
    TU_EXPECT_TEXT_ERROR(shell_deck(1, from, to), "t7istf2err.rad", "card /INTER/TYPE7/8, field Istf",
                         "node 9 of /GRNOD 4 is on no /SHELL or /SH3N", "expected secondary nodes on shells");
}

/* Igap 1: the gap gm + gs, half the main shells' thickness (0.005 m) and
 * half the secondary node's shells' (0.01 m; 0 for node 9, on none): 0.015
 * m for the upper body, 0.005 m for node 9 (TYPE7/8); Igap 2 scales it by
 * Fscalegap and bounds it by Gapmax; Gapmin stays the floor; Igap 3 and a
 * gap that varies from node to node are refused. */
static void test_type7_igap(void)
{
    {
        const char *from[2] = {t7_l1, "         4        30         1         0         0"};
        const char *to[2] = {"         2        30         1         0         1", "         4        30         1         0         1"};
        rc_model *m = TU_COMPILE_OK(shell_deck(2, from, to), "t7igap1.rad");
        if (m) {
            ENSURE(m->ninter == 4);
            if (m->ninter == 4) {
                ENSURE_NEAR(m->inter_gap[1], 0.015, 1e-15, 0);
                ENSURE_NEAR(m->inter_gap[2], 0.005, 1e-15, 0); /* node 9: gm alone */
                ENSURE_NEAR(m->inter_gap[3], 0.015, 1e-15, 0);
                ENSURE_NEAR(m->inter_gap[0], 0.0, 0, 0); /* the TYPE6 keeps its own */
            }
            rc_model_free(m);
        }
    }
    {
        /* Igap 2, Fscalegap 0.5, Gapmax 0.006: min(0.5 * 0.015, 0.006) */
        const char *from[2] = {t7_l1, "\n                   0                   0                   0         0\n"};
        const char *to[2] = {"         2        30         1         0         2", "\n                 0.5               0.006                   0         0\n"};
        rc_model *m = TU_COMPILE_OK(shell_deck(2, from, to), "t7igap2.rad");
        if (m) {
            ENSURE(m->ninter == 4 && fabs(m->inter_gap[1] - 0.006) < 1e-15);
            rc_model_free(m);
        }
        /* Gapmax 0: none, 0.5 * 0.015; Gapmin 0.0011 below it */
        to[1] = "\n                 0.5                   0                   0         0\n";
        m = TU_COMPILE_OK(shell_deck(2, from, to), "t7igap2b.rad");
        if (m) {
            ENSURE(m->ninter == 4 && fabs(m->inter_gap[1] - 0.0075) < 1e-15);
            rc_model_free(m);
        }
        /* Fscalegap 0.05: 7.5e-4 < Gapmin 0.0011 */
        to[1] = "\n                0.05                   0                   0         0\n";
        m = TU_COMPILE_OK(shell_deck(2, from, to), "t7igap2c.rad");
        if (m) {
            ENSURE(m->ninter == 4 && fabs(m->inter_gap[1] - 0.0011) < 1e-15);
            rc_model_free(m);
        }
    }
    {
        const char *from[1] = {t7_l1}, *to[1] = {"         2        30         1         0         3"};
        TU_EXPECT_TEXT_ERROR(shell_deck(1, from, to), "t7igap3.rad", "card /INTER/TYPE7/7, field Igap",
                             "not supported yet (Igap 3 also bounds", "expected 0, blank or 1000");
        to[0] = "         2        30         1         0         4";
        TU_EXPECT_TEXT_ERROR(shell_deck(1, from, to), "t7igap4.rad", "card /INTER/TYPE7/7, field Igap",
                             "expected 0, blank or 1000");
    }
    /* the main gap varies: the lower top face's shell in /PART/6 (0.02 m)
     * instead of /PART/5 (0.01 m) */
    {
        static char text[sizeof t7_deck_a + sizeof t7_shells + sizeof t7_deck_b + 64];
        const char *from[1] = {t7_l1}, *to[1] = {"         2        30         1         0         1"};
        const char *base = shell_deck(1, from, to);
        ENSURE(base != NULL);
        if (!base) return;
        /* move element 102 (the lower top face) to /SHELL/6 */
        const char *cut = strstr(base, "       102        25        26        27        28\n");
        const char *sh6 = strstr(base, "/SHELL/6\n");
        ENSURE(cut && sh6);
        if (!cut || !sh6) return;
        const size_t lcut = strlen("       102        25        26        27        28\n");
        const size_t a = (size_t)(cut - base), b = (size_t)(sh6 - base) + strlen("/SHELL/6\n");
        snprintf(text, sizeof text, "%.*s%.*s%.*s%s", (int)a, base, (int)(b - a - lcut), cut + lcut, (int)lcut, cut,
                 base + b);
        TU_EXPECT_TEXT_ERROR(text, "t7igapvar.rad", "card /INTER/TYPE7/7, field Igap", "/SURF/SEG/30 has segment",
                             "not supported yet", "expected main shells of one thickness");
    }
}

void suite_type7(void);
void suite_type7(void)
{
    RUN_TEST(test_type7_read);
    RUN_TEST(test_type7_model);
    RUN_TEST(test_type7_units);
    RUN_TEST(test_type7_istf0_errors);
    RUN_TEST(test_type7_inacti);
    RUN_TEST(test_type7_istf_combined);
    RUN_TEST(test_type7_igap);
}
