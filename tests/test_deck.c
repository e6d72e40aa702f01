/*
 * Radioss decks read as Radioss reads them: each card written exactly as
 * Radioss writes it (fixed columns of its layout for the /BEGIN version)
 * reads to the values Radioss would read; the deck-level rules (/END in
 * included files, /BEGIN forms, leniencies, cards of explicit runs, several
 * errors in one run, the engine file, unit systems).
 *
 * Decks are written from strings into a private temporary directory,
 * removed at the end of the suite.
 */
#include "harness.h"
#include "testutil.h"
#include "case/case.h"
#include "base/error.h"
#include "model/model.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* Load a deck that must be valid (NULL and the message printed if not). */
static rc_case *load_ok(const char *path)
{
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    if (rc_case_load(path, &c, &e) != RC_OK) fprintf(stderr, "  unexpected error loading %s: %s\n", path, e.msg);
    return c;
}

/* Load a deck that must fail with RC_EINPUT; the message in *e. */
static int load_fails(const char *path, rc_error *e)
{
    rc_case *c = NULL;
    rc_error_clear(e);
    rc_status st = rc_case_load(path, &c, e);
    if (st == RC_OK) rc_case_free(c);
    return st == RC_EINPUT && c == NULL;
}

/* Number of warnings containing every needle (NULL-terminated). */
static int count_warnings(const rc_case *c, ...)
{
    int n = 0;
    for (int i = 0; i < c->nwarnings; i++) {
        va_list ap;
        int all = 1;
        va_start(ap, c);
        for (const char *s; (s = va_arg(ap, const char *));)
            if (!strstr(c->warnings[i], s)) all = 0;
        va_end(ap);
        n += all;
    }
    return n;
}
#define NWARN(c, ...) count_warnings((c), __VA_ARGS__, (const char *)NULL)

/* A /RUN card (ricochet's) closing small decks. */
#define RUN_CARD "/RUN\n                 1.0                0.01\n"

/* ---- /GRAV --------------------------------------------------------------- */

/* Radioss 5.1 and later: fct_IDT DIR skew_ID sensor_ID grnod_ID, ten blank
 * columns, Ascale_x in 61-80, Fscale_y in 81-100. */
static void test_deck_grav_columns(void)
{
    const char *p = tu_tmp_write("grav.rad",
                              "/GRAV/3\n"
                              "ramped gravity\n"
                              "#funct_IDT       DIR   skew_ID sensor_ID  grnod_ID                      Ascale_x            Fscale_Y\n"
                              "         7         Y         0         0        12                             2\n"
                              "/GRAV/4\n"
                              "full line\n"
                              "         0         Z         0         0         0                          0.25               -9.81\n"
                              RUN_CARD);
    rc_case *c = load_ok(p);
    ENSURE(c && c->ngrav == 2);
    if (c && c->ngrav == 2) {
        const rc_case_grav *g = &c->grav[0], *h = &c->grav[1];
        ENSURE(g->id == 3 && g->fct_id == 7 && g->dir == 1 && g->grnod_id == 12);
        ENSURE(g->ascale == 2.0 && g->fscale == 1.0); /* Fscale_y blank: 1 */
        ENSURE(h->dir == 2 && h->ascale == 0.25 && h->fscale == -9.81 && h->grnod_id == 0);
    }
    rc_case_free(c);
    /* a value in the unused columns 51-60 is an error naming the field */
    rc_error e;
    ENSURE(load_fails(tu_tmp_write("grav2.rad", "/GRAV/3\ng\n         7         Y         0         0        12         2\n" RUN_CARD), &e));
    ENSURE(strstr(e.msg, "grav2.rad:3:") && strstr(e.msg, "/GRAV/3") && strstr(e.msg, "field blank"));
}

/* ---- /END and #enddata in included files, a second /BEGIN --------------- */

static void test_deck_end_in_include(void)
{
    /* each included model ends with /END (or #enddata): only that file ends */
    tu_tmp_write("part_a.inc",
              "#RADIOSS STARTER\n"
              "/BEGIN\n"
              "model a\n"
              "      2022         0\n"
              "                  kg                   m                   s\n"
              "                  kg                   m                   s\n"
              "/FUNCT/1\n"
              "a\n"
              "                 0.0                 0.0\n"
              "                 1.0                 1.0\n"
              "/END\n"
              "/FUNCT/99\n"
              "after the end of a: never read\n");
    tu_tmp_write("part_b.inc",
              "/FUNCT/2\n"
              "b\n"
              "                 0.0                 0.0\n"
              "                 2.0                 1.0\n"
              "#enddata\n"
              "/FOO/1\n");
    const char *p = tu_tmp_write("assembled.rad",
                              "/BEGIN\n"
                              "assembled\n"
                              "      2022         0\n"
                              "                  kg                   m                   s\n"
                              "                  kg                   m                   s\n"
                              "#include part_a.inc\n"
                              "#include part_b.inc\n"
                              "/FUNCT/3\n"
                              "after both\n"
                              "                 0.0                 0.0\n"
                              "                 3.0                 1.0\n"
                              RUN_CARD
                              "/END\n"
                              "/FUNCT/98\n");
    rc_case *c = load_ok(p);
    ENSURE(c != NULL);
    if (c) {
        ENSURE(c->nfunct == 3);
        if (c->nfunct == 3) ENSURE(c->funct[0].id == 1 && c->funct[1].id == 2 && c->funct[2].id == 3);
        ENSURE(c->run.present && c->run.tend == 1.0);
        ENSURE(strcmp(c->title, "assembled") == 0 && c->invers == 2022);
        /* the included model's /BEGIN: ignored with a warning naming the first */
        ENSURE(NWARN(c, "part_a.inc:2:", "/BEGIN", "ignored", "assembled.rad:1") == 1);
    }
    rc_case_free(c);
}

/* ---- Leniencies ------------------------------------------------------------ */

static void test_deck_lenient_headers_and_text(void)
{
    const char *p = tu_tmp_write("lenient.rad",
                              "/BEGIN/\n"
                              "lenient\n"
                              "      2022         0         7\n"
                              "   /FUNCT/5/\n"
                              "f\n"
                              "                 0.0                 0.0\n"
                              "                 1.0                 2.0      comment\n"
                              "  /RUN/\n"
                              "                 1.0                0.01\n");
    rc_case *c = load_ok(p);
    ENSURE(c != NULL);
    if (c) {
        ENSURE(c->invers == 2022 && strcmp(c->title, "lenient") == 0);
        ENSURE(c->nfunct == 1 && c->funct[0].id == 5 && c->funct[0].npts == 2);
        if (c->nfunct == 1 && c->funct[0].npts == 2) ENSURE(c->funct[0].y[1] == 2.0);
        ENSURE(c->run.present && c->run.tend == 1.0);
        /* the third field of the version line and the text after Y: warned */
        ENSURE(NWARN(c, "lenient.rad:3:", "/BEGIN", "after column 20 ignored", "\"7\"") == 1);
        ENSURE(NWARN(c, "lenient.rad:7:", "/FUNCT/5", "after column 40 ignored", "\"comment\"") == 1);
        ENSURE(c->nwarnings == 2);
    }
    rc_case_free(c);
}

/* /INTER/TYPE6 written by Radioss 2022 with Iform 1 and Stiff 0: Iform 0. */
static void test_deck_type6_iform_without_stiff(void)
{
    const char *p = tu_tmp_write("t6stiff.rad",
                              "/INTER/TYPE6/8\n"
                              "elasto-plastic without Stiff\n"
                              "# surf_ID1  surf_ID2\n"
                              "         1         2\n"
                              "#              Sfric                Fric                 Gap              Tstart               Tstop\n"
                              "                   0                 0.2                   0                   0                   0\n"
                              "#                IRS       IRM    Inacti  fct_IDff  fct_IDfv             Ascalef             Ascalev\n"
                              "                   0         0         0         0         0                   0                   0\n"
                              "# fct_IDId     Iform             Ascalex            Fscaleid      Icor\n"
                              "         4         1                   1                   1         0\n"
                              "# fct_IDul                         Stiff            Fscaleul\n"
                              "         5                             0                   0\n"
                              "#               Visc  fct_IDdv  fct_IDdf             Fscalev\n"
                              "                   0         0         0                   0\n"
                              RUN_CARD);
    rc_case *c = load_ok(p);
    ENSURE(c && c->ntype6 == 1);
    if (c && c->ntype6 == 1) {
        const rc_case_type6 *t = &c->type6[0];
        ENSURE(t->iform == 0 && t->fct_ld == 4 && t->fct_ul == 5 && t->stiff == 0 && t->fric == 0.2);
        ENSURE(NWARN(c, "t6stiff.rad:12:", "/INTER/TYPE6/8", "Iform = 1 with Stiff = 0", "Iform = 0") == 1);
    }
    rc_case_free(c);
}

/* /FRIC_ORIENT with V = (0, 0, 0): the X axis, with a warning. */
static void test_deck_fric_orient_zero_vector(void)
{
    const char *p = tu_tmp_write("fozero.rad",
                              "/FRIC_ORIENT/3\n"
                              "orientation\n"
                              "#grpart_ID   part_ID\n"
                              "         0         7\n"
                              "#                 VX                  VY                  VZ   skew_ID                 PHI     Iorth\n"
                              "                   0                   0                   0         0                  30         0\n"
                              RUN_CARD);
    rc_case *c = load_ok(p);
    ENSURE(c && c->nfricorient == 1);
    if (c && c->nfricorient == 1 && c->fricorient[0].n == 1) {
        const rc_case_fricorient_item *it = &c->fricorient[0].item[0];
        ENSURE(it->v[0] == 1 && it->v[1] == 0 && it->v[2] == 0 && it->phi == 30 && it->part_id == 7);
        ENSURE(NWARN(c, "fozero.rad:6:", "/FRIC_ORIENT/3", "(1, 0, 0)") == 1);
    }
    rc_case_free(c);
}

/* ---- Cards of explicit runs ---------------------------------------------- */

static void test_deck_explicit_cards_one_warning_per_kind(void)
{
    const char *p = tu_tmp_write("explicit.rad",
                              "/TITLE\n"
                              "a Radioss model\n"
                              "/TH/RBODY/1\n"
                              "bodies\n"
                              "DEF\n"
                              "         1\n"
                              "/TH/INTER/2\n"
                              "interfaces\n"
                              "DEF\n"
                              "         1\n"
                              "/TH/NODE/3\n"
                              "nodes\n"
                              "DEF\n"
                              "         1\n"
                              "/ANIM/DT\n"
                              "0 1e-3\n"
                              "/ANIM/VECT/VEL\n"
                              "/MEMORY/AUTO\n"
                              "/DT/NODA/CST\n"
                              "0.9 1e-7\n"
                              "/PRINT/-1000\n"
                              "/H3D/DT\n"
                              "0 1e-3\n"
                              "/RFILE/5000\n"
                              RUN_CARD);
    rc_case *c = load_ok(p);
    ENSURE(c != NULL);
    if (c) {
        ENSURE(NWARN(c, "explicit.rad:3:", "/TH/RBODY/1", "ignored", "explicit", "(and 2 more /TH cards)") == 1);
        ENSURE(NWARN(c, "explicit.rad:17:", "/ANIM/VECT/VEL", "ignored") == 1);
        ENSURE(NWARN(c, "explicit.rad:15:", "/ANIM/DT ignored", "ricochet's /RUN") == 1);
        ENSURE(NWARN(c, "/TITLE") == 1 && NWARN(c, "/MEMORY/AUTO") == 1 && NWARN(c, "/DT/NODA/CST") == 1 &&
               NWARN(c, "/PRINT/-1000") == 1 && NWARN(c, "/H3D/DT") == 1 && NWARN(c, "/RFILE/5000") == 1);
        ENSURE(c->nwarnings == 9);
        ENSURE(c->run.present && c->run.tend == 1.0);
    }
    rc_case_free(c);
}

/* ---- Several errors in one run -------------------------------------------- */

static void test_deck_several_errors(void)
{
    rc_error e;
    /* three cards in error: the first one is the report's first line, the
     * others follow, then the count; the reading goes on after each */
    const char *p = tu_tmp_write("errs.rad",
                              "/FUNCT/1\n"
                              "f\n"
                              "                 0.0                 0.0\n"
                              "                 abc                 1.0\n"
                              "/GRAV/2\n"
                              "g\n"
                              "         0         W\n"
                              "/FUNCT/3\n"
                              "fine\n"
                              "                 0.0                 0.0\n"
                              "                 1.0                 1.0\n"
                              "/RUN\n"
                              "                -1.0\n");
    ENSURE(load_fails(p, &e));
    char first[160];
    snprintf(first, sizeof first, "%s:4: card /FUNCT/1, field X", p);
    ENSURE(strncmp(e.msg, first, strlen(first)) == 0);
    ENSURE(strstr(e.msg, "\n") && strstr(e.msg, "errs.rad:7: card /GRAV/2, field DIR"));
    ENSURE(strstr(e.msg, "errs.rad:13: card /RUN, field Tend"));
    ENSURE(strstr(e.msg, "3 input errors") != NULL);
    ENSURE(strstr(e.msg, "no /RUN") == NULL); /* the /RUN in error is not "missing" */

    /* more than 20: 20 reported, then "too many errors" */
    char deck[8192] = "";
    for (int k = 1; k <= 25; k++) {
        char card[128];
        snprintf(card, sizeof card, "/GRAV/%d\ng\n         0         Q\n", k);
        strcat(deck, card);
    }
    strcat(deck, RUN_CARD);
    ENSURE(load_fails(tu_tmp_write("errs25.rad", deck), &e));
    int n = 0;
    for (const char *q = e.msg; (q = strstr(q, "field DIR")); q++) n++;
    ENSURE(n == 20);
    ENSURE(strstr(e.msg, "errs25.rad:3: card /GRAV/1, field DIR") == strstr(e.msg, "errs25.rad"));
    ENSURE(strstr(e.msg, "errs25.rad:60: card /GRAV/20, field DIR") != NULL);
    ENSURE(strstr(e.msg, "/GRAV/21,") == NULL);
    ENSURE(strstr(e.msg, "too many errors") != NULL);

    /* every duplicate id is reported, in the order of the deck */
    const char *dp;
    ENSURE(load_fails(dp = tu_tmp_write("dups.rad", "/FUNCT/1\na\n0,0\n1,1\n/GRAV/4\ng\n0,Z\n/FUNCT/1\nb\n0,0\n1,1\n"
                                             "/GRAV/4\nh\n0,Z\n" RUN_CARD), &e));
    const char *d1 = strstr(e.msg, "dups.rad:8: card /FUNCT/1, field fct_ID: duplicate id 1");
    const char *d2 = strstr(e.msg, "dups.rad:12: card /GRAV/4, field grav_ID: duplicate id 4");
    ENSURE(d1 == e.msg + strlen(dp) - strlen("dups.rad") && d2 > d1 && strstr(e.msg, "2 input errors"));
}

/* ---- /BEGIN forms ---------------------------------------------------------- */

static void test_deck_begin_forms(void)
{
    /* Radioss 9.0: run name and version only */
    rc_case *c = load_ok(tu_tmp_write("begin90.rad", "/BEGIN\nold model\n        90         1\n" RUN_CARD));
    ENSURE(c && c->invers == 90 && strcmp(c->title, "old model") == 0 && c->unit_mass[0] == 0);
    rc_case_free(c);
    /* Radioss 2021 and later: Invers alone; units */
    c = load_ok(tu_tmp_write("begin2024.rad",
                          "/BEGIN/\n"
                          "new model\n"
                          "      2024\n"
                          "                  kg                   m                   s\n"
                          "                  kg                   m                   s\n" RUN_CARD));
    ENSURE(c && c->invers == 2024 && strcmp(c->unit_length, "m") == 0 && c->nwarnings == 0);
    rc_case_free(c);
    /* an empty block: accepted with a warning */
    c = load_ok(tu_tmp_write("begin0.rad", "/BEGIN\n" RUN_CARD));
    ENSURE(c && c->invers == 0 && c->title[0] == 0 && NWARN(c, "begin0.rad:1:", "/BEGIN", "empty") == 1);
    rc_case_free(c);
    /* an unknown version: the nearest older layouts, with a warning */
    c = load_ok(tu_tmp_write("begin77.rad", "/BEGIN\nx\n        77\n" RUN_CARD));
    ENSURE(c && c->invers == 77 && NWARN(c, "begin77.rad:3:", "Invers = 77") == 1);
    rc_case_free(c);
    /* a fifth line is an error naming the card */
    rc_error e;
    ENSURE(load_fails(tu_tmp_write("begin5.rad", "/BEGIN\nx\n2022\n\n\nextra\n" RUN_CARD), &e));
    ENSURE(strstr(e.msg, "begin5.rad:6:") && strstr(e.msg, "/BEGIN") && strstr(e.msg, "unexpected data line"));
}

/* ---- The Radioss engine file ------------------------------------------------ */

/* A single file with the engine card /RUN/name/n: Tend from Tstop, Dt_out
 * from /ANIM/DT (blank-separated, as engine files often are). */
static void test_deck_engine_run_single_file(void)
{
    const char *p = tu_tmp_write("single.rad",
                              "/BEGIN\nball\n      2022\n"
                              "/FUNCT/1\nf\n                 0.0                 0.0\n                 1.0                 1.0\n"
                              "#RADIOSS ENGINE\n"
                              "/RUN/ball/1\n"
                              "               0.137\n"
                              "/ANIM/DT\n"
                              "0 0.00137\n"
                              "/TFILE/0\n"
                              "1e-4\n"
                              "/PRINT/-100\n"
                              "/DT/NODA/CST/0\n"
                              "0.9 1e-9\n");
    rc_case *c = load_ok(p);
    ENSURE(c != NULL);
    if (c) {
        ENSURE(c->run.present && c->run.tend == 0.137 && c->run.dtout == 0.00137 && c->run.loc.line == 9);
        ENSURE(NWARN(c, "single.rad:9:", "/RUN/ball/1", "Tend = Tstop = 0.137", "Tfreq of /ANIM/DT") == 1);
        ENSURE(NWARN(c, "/TFILE/0", "ignored") == 1 && NWARN(c, "/PRINT/-100", "ignored") == 1 &&
               NWARN(c, "/DT/NODA/CST/0", "ignored") == 1);
    }
    rc_case_free(c);
    /* without /ANIM/DT: Tend/100; a run name that is a number, a restart letter */
    c = load_ok(tu_tmp_write("single2.rad", "/RUN/2024/1/C\n2.5\n"));
    ENSURE(c && c->run.present && c->run.tend == 2.5 && c->run.dtout == 0.025);
    rc_case_free(c);
    /* a ricochet /RUN wins, with a warning */
    c = load_ok(tu_tmp_write("both.rad", RUN_CARD "/RUN/ball/1\n7.0\n"));
    ENSURE(c && c->run.tend == 1.0 && NWARN(c, "both.rad:3:", "/RUN/ball/1", "ignored", "ricochet /RUN") == 1);
    rc_case_free(c);
    /* Tstop must be positive */
    rc_error e;
    ENSURE(load_fails(tu_tmp_write("tstop.rad", "/RUN/ball/1\n-1\n"), &e));
    ENSURE(strstr(e.msg, "tstop.rad:2: card /RUN/ball/1, field Tstop") && !strstr(e.msg, "no /RUN"));
}

/* A starter and engine pair: NAME_0000.rad reads NAME_0001.rad next to it. */
static void test_deck_engine_pair(void)
{
    tu_tmp_write("drop_0001.rad",
              "#RADIOSS ENGINE\n"
              "/RUN/drop/1\n"
              "                 0.5\n"
              "/ANIM/DT\n"
              "                   0               0.005\n"
              "/VERS/2022\n"
              "/END\n");
    const char *p = tu_tmp_write("drop_0000.rad",
                              "#RADIOSS STARTER\n"
                              "/BEGIN\ndrop\n      2022         0\n"
                              "                  kg                   m                   s\n"
                              "                  kg                   m                   s\n"
                              "/FUNCT/1\nf\n                 0.0                 0.0\n                 1.0                 1.0\n"
                              "/END\n");
    rc_case *c = load_ok(p);
    ENSURE(c != NULL);
    if (c) {
        ENSURE(c->run.present && c->run.tend == 0.5 && c->run.dtout == 0.005);
        ENSURE(c->nfiles == 2 && strstr(c->files[1], "drop_0001.rad"));
        ENSURE(c->run.loc.file == c->files[1] && c->run.loc.line == 2);
        ENSURE(NWARN(c, "drop_0001.rad:1:", "engine file", "drop_0000.rad") == 1);
        ENSURE(NWARN(c, "/VERS/2022", "ignored") == 1);
        ENSURE(c->nfunct == 1);
    }
    rc_case_free(c);
    /* without its engine file, a starter file alone has no end time */
    rc_error e;
    ENSURE(load_fails(tu_tmp_write("lone_0000.rad", "/FUNCT/1\nf\n0,0\n1,1\n/END\n"), &e));
    ENSURE(strstr(e.msg, "no /RUN card") != NULL);
}

/* ---- Layouts by /BEGIN version -------------------------------------------- */

#define BEGIN_V(v) "/BEGIN\nversioned\n" v "\n"

/* /INTER/TYPE6 as Radioss 4.4, 9.0, 11.0 and 2017 write it. */
static void test_deck_type6_layouts(void)
{
    rc_case *c = load_ok(tu_tmp_write("t6v44.rad",
                                   BEGIN_V("        44")
                                   "/INTER/TYPE6/1\n"
                                   "4.4 layout\n"
                                   "#surf_id1surf_id2\n"
                                   "       3       4\n"
                                   "#          Scale            FRIC             GAP          Tstart          Tstop\n"
                                   "             1.5             0.3           0.001             0.1             0.9\n"
                                   "#     If     IRS     IRM\n"
                                   "       7       0       0\n" RUN_CARD));
    ENSURE(c && c->ntype6 == 1);
    if (c && c->ntype6 == 1) {
        const rc_case_type6 *t = &c->type6[0];
        ENSURE(t->surf1 == 3 && t->surf2 == 4 && t->sfric == 1.5 && t->fric == 0.3 && t->gap == 0.001 &&
               t->tstart == 0.1 && t->tstop == 0.9 && t->fct_ld == 7 && t->irs == 0);
        ENSURE(t->iform == 0 && t->ascalex == 1 && t->fscaleld == 1 && t->ascalef == 1 && t->ascalev == 1 &&
               t->fscaleul == 1 && t->fscalev == 1 && t->visc == 0 && t->stiff == 0);
        ENSURE(t->line_loc[2].line == 11 && t->line_loc[5].line == 11);
    }
    rc_case_free(c);

    c = load_ok(tu_tmp_write("t6v90.rad",
                          BEGIN_V("        90         0")
                          "/INTER/TYPE6/2\n"
                          "9.0 layout\n"
                          "# surf_iD1  surf_iD2\n"
                          "         3         4\n"
                          "#                                   Fric                 Gap              Tstart               Tstop\n"
                          "                                     0.2               0.002                   0                 0.8\n"
                          "#                IRS       IRM\n"
                          "                   0         0\n"
                          "#funct_IDf                       Ascalex             FscaleY\n"
                          "         8                       0.001                1000\n" RUN_CARD));
    ENSURE(c && c->ntype6 == 1);
    if (c && c->ntype6 == 1) {
        const rc_case_type6 *t = &c->type6[0];
        ENSURE(t->sfric == 0 && t->fric == 0.2 && t->gap == 0.002 && t->tstop == 0.8 && t->fct_ld == 8 &&
               t->iform == 0 && t->ascalex == 0.001 && t->fscaleld == 1000 && t->fscaleul == 1);
    }
    rc_case_free(c);

    c = load_ok(tu_tmp_write("t6v110.rad",
                          BEGIN_V("       110         0")
                          "/INTER/TYPE6/3\n"
                          "11.0 layout\n"
                          "         3         4\n"
                          "                                     0.2                   0                   0                   0\n"
                          "                   0         0\n"
                          "# fct_IDId     Iform             Ascalex            Fscaleid\n"
                          "         8         1                 0.5                  20\n"
                          "# fct_IDul                         Stiff            Fscaleul\n"
                          "         9                         1e7                  30\n" RUN_CARD));
    ENSURE(c && c->ntype6 == 1);
    if (c && c->ntype6 == 1) {
        const rc_case_type6 *t = &c->type6[0];
        ENSURE(t->fct_ld == 8 && t->iform == 1 && t->ascalex == 0.5 && t->fscaleld == 20 && t->fct_ul == 9 &&
               t->stiff == 1e7 && t->fscaleul == 30 && t->tstop == 1e30 && t->icor == 0 && t->visc == 0);
    }
    rc_case_free(c);

    /* a 2022 deck needs six lines; a 9.0 deck has four */
    rc_error e;
    ENSURE(load_fails(tu_tmp_write("t6v90b.rad", BEGIN_V("        90") "/INTER/TYPE6/2\nx\n3,4\n\n\n8\n9\n" RUN_CARD), &e));
    ENSURE(strstr(e.msg, "t6v90b.rad:10:") && strstr(e.msg, "unexpected data line") && strstr(e.msg, "5.1/9.0"));
    ENSURE(load_fails(tu_tmp_write("t6v2022.rad", BEGIN_V("      2022") "/INTER/TYPE6/2\nx\n3,4\n\n\n8\n" RUN_CARD), &e));
    ENSURE(strstr(e.msg, "t6v2022.rad:4:") && strstr(e.msg, "expected 6 data lines"));
}

/* /GRAV, /FUNCT, /INIVEL, /BCS, /IMPVEL in the Radioss 4.4 layouts. */
static void test_deck_loads_layouts_44(void)
{
    rc_case *c = load_ok(tu_tmp_write("loads44.rad",
                                   BEGIN_V("        44")
                                   "/GRAV/1\n"
                                   "g\n"
                                   "# Ifunct     Dir   Iskew Isensor           Scale Gnod_id\n"
                                   "       2       Z       0       0           -9.81       5\n"
                                   "/FUNCT/2\n"
                                   "f\n"
                                   "             0.0             1.0\n"
                                   "             2.0             3.0\n"
                                   "/INIVEL/TRA/3\n"
                                   "v\n"
                                   "             1.0             2.0             3.0       5       0\n"
                                   "/BCS/4\n"
                                   "b\n"
                                   "#tra rot Skew_id Gnod_id\n"
                                   " 111 000       0       5\n"
                                   "/IMPVEL/5\n"
                                   "i\n"
                                   "# Ifunct     DIR   Iskew Isensor Gnod_id\n"
                                   "       2       X       0       0       5\n"
                                   "#          Scale          Tstart           Tstop\n"
                                   "             2.5               0             0.7\n" RUN_CARD));
    ENSURE(c != NULL);
    if (c) {
        ENSURE(c->ngrav == 1 && c->grav[0].fct_id == 2 && c->grav[0].dir == 2 && c->grav[0].fscale == -9.81 &&
               c->grav[0].grnod_id == 5 && c->grav[0].ascale == 1);
        ENSURE(c->nfunct == 1 && c->funct[0].npts == 2);
        if (c->nfunct == 1 && c->funct[0].npts == 2) ENSURE(c->funct[0].x[1] == 2.0 && c->funct[0].y[1] == 3.0);
        ENSURE(c->ninivel == 1 && c->inivel[0].v[2] == 3.0 && c->inivel[0].grnod_id == 5);
        ENSURE(c->nbcs == 1 && c->bcs[0].fix[0] == 1 && c->bcs[0].fix[3] == 0 && c->bcs[0].grnod_id == 5);
        ENSURE(c->nimpvel == 1);
        ENSURE(c->nwarnings == 0);
    }
    rc_case_free(c);
}

/* /IMPVEL before 12.0 has no Icoor: columns 61-70 are after the layout. */
static void test_deck_impvel_110(void)
{
    rc_case *c = load_ok(tu_tmp_write("iv110.rad",
                                   BEGIN_V("       110")
                                   "/IMPVEL/5\n"
                                   "i\n"
                                   "#funct_IDT       Dir   skew_ID sensor_ID  grnod_ID  frame_ID\n"
                                   "         2        XX         0         0         5         0         1\n"
                                   "#            Scale_x             Scale_y              Tstart               Tstop\n"
                                   "                   0                 2.0                   0                 0.5\n" RUN_CARD));
    ENSURE(c && c->nimpvel == 1 && NWARN(c, "iv110.rad:7:", "after column 60 ignored") == 1);
    rc_case_free(c);
    /* from 12.0 on the same line is Icoor = 1: not supported */
    rc_error e;
    ENSURE(load_fails(tu_tmp_write("iv120.rad", BEGIN_V("       120")
                                "/IMPVEL/5\ni\n         2        XX         0         0         5         0         1\n" RUN_CARD),
                      &e));
    ENSURE(strstr(e.msg, "iv120.rad:6: card /IMPVEL/5, field Icoor") && strstr(e.msg, "not supported yet"));
}

/* /INIVEL of Radioss 2025: an optional line Tstart sens_ID (0 only). */
static void test_deck_inivel_2025(void)
{
    rc_case *c = load_ok(tu_tmp_write("iv2025.rad",
                                   BEGIN_V("      2025")
                                   "/INIVEL/ROT/3\n"
                                   "v\n"
                                   "                 1.0                 2.0                 3.0         5         0\n"
                                   "#             tstart   sens_ID\n"
                                   "                   0         0\n" RUN_CARD));
    ENSURE(c && c->ninivel == 1 && c->inivel[0].rot == 1 && c->inivel[0].v[1] == 2.0);
    rc_case_free(c);
    rc_error e;
    ENSURE(load_fails(tu_tmp_write("iv2025b.rad", BEGIN_V("      2025")
                                "/INIVEL/ROT/3\nv\n1,2,3,5\n0.5\n" RUN_CARD), &e));
    ENSURE(strstr(e.msg, "iv2025b.rad:7: card /INIVEL/ROT/3, field Tstart") && strstr(e.msg, "not supported yet"));
    /* the line does not exist before 2025 */
    ENSURE(load_fails(tu_tmp_write("iv2022.rad", BEGIN_V("      2022")
                                "/INIVEL/ROT/3\nv\n1,2,3,5\n0\n" RUN_CARD), &e));
    ENSURE(strstr(e.msg, "iv2022.rad:7:") && strstr(e.msg, "unexpected data line"));
}

/* /FRICTION of Radioss 2018 and 2019: no Idir on the group line. */
static void test_deck_friction_2019(void)
{
    const char *deck = "/FRICTION/5\nf\n0,0,,1\n\n0,0.3\n"
                       "#grpartID1 grpartID2   partID1   partID2\n"
                       "         0         0         7         8\n"
                       "\n"
                       "                   0                 0.4\n" RUN_CARD;
    char text[1024];
    snprintf(text, sizeof text, "%s%s", BEGIN_V("      2019"), deck);
    rc_case *c = load_ok(tu_tmp_write("fr2019.rad", text));
    ENSURE(c && c->nfriction == 1 && c->friction[0].npair == 1);
    if (c && c->nfriction == 1 && c->friction[0].npair == 1) {
        const rc_case_fricpair *pr = &c->friction[0].pair[0];
        ENSURE(pr->part1 == 7 && pr->part2 == 8 && pr->idir == 0 && pr->set[0].fric == 0.4);
    }
    rc_case_free(c);
    /* with 2019, a value in the Idir columns is text after the layout */
    snprintf(text, sizeof text, "%s%s", BEGIN_V("      2019"),
             "/FRICTION/5\nf\n0,0,,1\n\n0,0.3\n"
             "         0         0         7         8                   1\n\n\n" RUN_CARD);
    c = load_ok(tu_tmp_write("fr2019b.rad", text));
    ENSURE(c && c->nfriction == 1 && c->friction[0].npair == 1 && NWARN(c, "fr2019b.rad:9:", "after column 40 ignored") == 1);
    if (c && c->nfriction == 1 && c->friction[0].npair == 1) ENSURE(c->friction[0].pair[0].idir == 0);
    rc_case_free(c);
}

/* ---- Units ------------------------------------------------------------------ */

#define NEAR(a, b) (fabs((a) - (b)) <= 1e-12 * fabs(b))

/* /BEGIN input units g, mm, ms: every value read is converted to SI. */
static void test_deck_units_begin(void)
{
    const char *p = tu_tmp_write("gmmms.rad",
                              "/BEGIN\n"
                              "grams, millimetres, milliseconds\n"
                              "      2022         0\n"
                              "                   g                  mm                  ms\n"
                              "                  Mg                  mm                  ms\n"
                              "/NODE\n"
                              "         1                 0.0                 0.0               150.0\n"
                              "/RBODY/1\n"
                              "ball\n"
                              "         1         0         0         0              1000.0         0\n"
                              "           1000000.0           1000000.0           1000000.0\n"
                              "                 0.0                 0.0                 0.0\n"
                              "/SURF/ELLIPS/2\n"
                              "ball surface\n"
                              "         0         2         1\n"
                              "                 0.0                 0.0               150.0\n"
                              "                  50                  50                  50\n"
                              "/INTER/TYPE6/1\n"
                              "t6\n"
                              "         2         3\n"
                              "                   0                 0.3                   0                   0                   0\n"
                              "                   0         0         0         0         0                   0                   0\n"
                              "         1         0                   1                   1         0\n"
                              "         0                          1000                   0\n"
                              "                 2.0         0         0                   0\n"
                              "/GRAV/1\n"
                              "g\n"
                              "         0         Z         0         0         0                                      -0.00981\n"
                              "/INIVEL/TRA/2\n"
                              "v\n"
                              "                 1.0                 0.0                -2.0         0         0\n"
                              "/INIVEL/ROT/3\n"
                              "w\n"
                              "                0.01                 0.0                 0.0         0         0\n"
                              "/RUN\n"
                              "              1000.0                 1.0\n");
    rc_case *c = load_ok(p);
    ENSURE(c != NULL);
    if (!c) return;
    ENSURE(strcmp(c->unit_mass, "kg") == 0 && strcmp(c->unit_length, "m") == 0 && strcmp(c->unit_time, "s") == 0);
    ENSURE(c->nnode == 1 && NEAR(c->node[0].x[2], 0.15));
    if (c->nrbody == 1) {
        ENSURE(NEAR(c->rbody[0].mass, 1.0));
        ENSURE(NEAR(c->rbody[0].J[0], 1e-3) && NEAR(c->rbody[0].J[2], 1e-3) && c->rbody[0].J[3] == 0);
    }
    if (c->nsurf == 1) ENSURE(NEAR(c->surf[0].c[2], 0.15) && NEAR(c->surf[0].abc[0], 0.05));
    if (c->ntype6 == 1) {
        const rc_case_type6 *t = &c->type6[0];
        /* Stiff 1000 g/ms^2 = 1e6 N/m; Visc 2 g/ms = 2 N s/m; Fric stays;
         * Ascalex 1 mm, FscaleId 1 g mm/ms^2 = 1 N; Tstop 1e30 ms */
        ENSURE(NEAR(t->stiff, 1e6) && NEAR(t->visc, 2.0) && t->fric == 0.3 && NEAR(t->ascalex, 1e-3) &&
               NEAR(t->fscaleld, 1.0) && NEAR(t->tstop, 1e27) && NEAR(t->ascalev, 1.0));
    }
    if (c->ngrav == 1) ENSURE(NEAR(c->grav[0].fscale, -9.81) && NEAR(c->grav[0].ascale, 1e-3));
    if (c->ninivel == 2) {
        ENSURE(NEAR(c->inivel[0].v[0], 1.0) && NEAR(c->inivel[0].v[2], -2.0)); /* mm/ms = m/s */
        ENSURE(NEAR(c->inivel[1].v[0], 10.0));                                  /* 0.01 /ms */
    }
    ENSURE(NEAR(c->run.tend, 1.0) && NEAR(c->run.dtout, 1e-3));
    /* the conversion is reported, and the unused work units */
    ENSURE(NWARN(c, "gmmms.rad:4:", "input units", "mass g, length mm, time ms", "SI") == 1);
    ENSURE(NWARN(c, "gmmms.rad:5:", "work units", "not used") == 1);
    rc_case_free(c);
}

/* /UNIT/unit_ID and cards naming it in their header. */
static void test_deck_units_unit_cards(void)
{
    const char *p = tu_tmp_write("unitcards.rad",
                              "/BEGIN\nold form\n        90         0\n"
                              "/UNIT/2\n"
                              "millimetres and tonnes\n"
                              "#              MUNIT               LUNIT               TUNIT\n"
                              "                   t                  mm                   s\n"
                              "/UNIT/3\n"
                              "as numbers\n"
                              "                   1               0.001               0.001\n"
                              "/NODE/2\n"
                              "         1                 0.0                 0.0               150.0\n"
                              "/RBODY/1/2\n"
                              "ball\n"
                              "         1         0         0         0               0.001         0\n"
                              "                   1                   1                   1\n"
                              "                 0.0                 0.0                 0.0\n"
                              "/GRAV/1/3\n"
                              "g\n"
                              "         0         Z         0         0         0                                      -0.00981\n"
                              "/RUN\n"
                              "                 1.0\n");
    rc_case *c = load_ok(p);
    ENSURE(c != NULL);
    if (!c) return;
    ENSURE(c->invers == 90 && c->unit_mass[0] == 0); /* no /BEGIN units: recorded as undeclared */
    if (c->nnode == 1) ENSURE(NEAR(c->node[0].x[2], 0.15));
    if (c->nrbody == 1) ENSURE(NEAR(c->rbody[0].mass, 1.0) && NEAR(c->rbody[0].J[0], 1e-3));
    if (c->ngrav == 1) ENSURE(NEAR(c->grav[0].fscale, -9.81));
    ENSURE(c->run.tend == 1.0); /* /RUN in the /BEGIN system (none: as written) */
    ENSURE(NWARN(c, "unitcards.rad:4:", "/UNIT/2", "mass t, length mm, time s", "unit_ID 2") == 1);
    rc_case_free(c);

    rc_error e;
    /* an unknown unit, a missing /UNIT, a duplicate /UNIT */
    ENSURE(load_fails(tu_tmp_write("badunit.rad", "/UNIT/2\nu\n                  kg            parsec\n" RUN_CARD), &e));
    ENSURE(strstr(e.msg, "badunit.rad:3: card /UNIT/2, field LUNIT") && strstr(e.msg, "\"parsec\""));
    ENSURE(load_fails(tu_tmp_write("nounit.rad", "/NODE/4\n1,0,0,0\n" RUN_CARD), &e));
    ENSURE(strstr(e.msg, "nounit.rad:1: card /NODE/4, field unit_ID") && strstr(e.msg, "no /UNIT/4"));
    ENSURE(load_fails(tu_tmp_write("dupunit.rad", "/UNIT/2\nu\nkg,m,s\n/UNIT/2\nu\ng,mm,ms\n" RUN_CARD), &e));
    ENSURE(strstr(e.msg, "dupunit.rad:4: card /UNIT/2, field unit_ID") && strstr(e.msg, "duplicate id 2"));
}

/* Radioss 5.1 and 9.0: /BEGIN of two lines, the units in /UNIT/kind/name. */
static void test_deck_units_90_form(void)
{
    const char *p = tu_tmp_write("units90.rad",
                              "/BEGIN\n"
                              "a 9.0 deck\n"
                              "        90         0\n"
                              "/UNIT/LENGTH/mm\n"
                              "/UNIT/MASS/Mg\n"
                              "/UNIT/TIME/ms\n"
                              "/NODE\n"
                              "         1                 0.0                 0.0               150.0\n"
                              "/RBODY/1\n"
                              "ball\n"
                              "         1         0         0         0               0.001         0\n"
                              "                   1                   1                   1\n"
                              "                 0.0                 0.0                 0.0\n"
                              "/RUN\n"
                              "              1000.0\n");
    rc_case *c = load_ok(p);
    ENSURE(c != NULL);
    if (!c) return;
    ENSURE(c->invers == 90 && strcmp(c->unit_length, "m") == 0);
    if (c->nnode == 1) ENSURE(NEAR(c->node[0].x[2], 0.15));
    /* 1e-3 Mg = 1 kg; 1 Mg mm^2 = 1e-3 kg m^2 */
    if (c->nrbody == 1) ENSURE(NEAR(c->rbody[0].mass, 1.0) && NEAR(c->rbody[0].J[0], 1e-3));
    ENSURE(NEAR(c->run.tend, 1.0));
    ENSURE(NWARN(c, "units90.rad:5:", "/UNIT/MASS/Mg", "mass unit Mg", "1000") == 1);
    rc_case_free(c);
    rc_error e;
    ENSURE(load_fails(tu_tmp_write("units90b.rad", "/BEGIN\nx\n90\n/UNIT/LENGTH/league\n" RUN_CARD), &e));
    ENSURE(strstr(e.msg, "units90b.rad:4: card /UNIT/LENGTH/league, field LENGTH") && strstr(e.msg, "\"league\""));
}

/* The demo deck written in g, mm, ms runs as the SI deck does: the same
 * final state (SI) after the bounce. */
static void test_deck_units_run_matches_si(void)
{
    const char *p = tu_tmp_write("demo_gmmms.rad",
                              "#RADIOSS STARTER\n"
                              "/BEGIN\n"
                              "demo in g, mm, ms\n"
                              "      2022         0\n"
                              "                   g                  mm                  ms\n"
                              "                   g                  mm                  ms\n"
                              "/FUNCT/1\n"
                              "linear load curve, 1e6 N per 1000 mm\n"
                              "                   0                   0\n"
                              "                1000             1000000\n"
                              "/NODE\n"
                              "         1                   0                   0                 150\n"
                              "/RBODY/1\n"
                              "sphere, 1000 g\n"
                              "         1                                              1000\n"
                              "             1000000             1000000             1000000\n"
                              "                   0                   0                   0\n"
                              "/SURF/ELLIPS/1\n"
                              "sphere surface R = 50 mm\n"
                              "         0         2         1\n"
                              "                   0                   0                 150\n"
                              "                  50                  50                  50\n"
                              "/SURF/PLANE/2\n"
                              "floor\n"
                              "                   0                   0                   0\n"
                              "                   0                   0                1000\n"
                              "/GRNOD/NODE/1\n"
                              "sphere node\n"
                              "         1\n"
                              "/GRAV/1\n"
                              "gravity\n"
                              "         0         Z         0         0         0                                      -0.00981\n"
                              "/INTER/TYPE6/1\n"
                              "sphere on floor\n"
                              "         1         2\n"
                              "                                                           0\n"
                              "                   0         0         0         0         0\n"
                              "         1         0                                                 0\n"
                              "         0\n"
                              "       148.710194195         0         0\n"
                              "/RUN\n"
                              "                1000                 0.1\n"
                              "/SOLVER\n"
                              "         1         5    100000               1e-06                   0                   0\n"
                              "               1e-06               1e-09               1e-06               1e-09\n"
                              "               0.001\n"
                              "/END\n");
    rc_case *a = load_ok("cases/demo_sphere_drop.rad"), *b = load_ok(p);
    rc_model *ma = NULL, *mb = NULL;
    rc_error e;
    ENSURE(a && b);
    if (a && b) {
        ENSURE(rc_model_compile(a, &ma, &e) == RC_OK);
        ENSURE(rc_model_compile(b, &mb, &e) == RC_OK);
    }
    if (ma && mb) {
        int n = rc_model_state_size(ma);
        ENSURE(n == rc_model_state_size(mb) && n > 0 && n <= 64);
        double ya[64], yb[64];
        rc_run_options oa = {.t_end_override = 0.3, .y_end = ya}, ob = {.t_end_override = 0.3, .y_end = yb};
        ENSURE(rc_run(ma, &oa, NULL, &e) == RC_OK);
        ENSURE(rc_run(mb, &ob, NULL, &e) == RC_OK);
        double worst = 0;
        for (int k = 0; k < n && k < 64; k++) {
            double d = fabs(ya[k] - yb[k]) / (1e-6 + fabs(ya[k]));
            if (d > worst) worst = d;
        }
        printf("    demo in g, mm, ms vs SI after 0.3 s: max relative state difference %.2e\n", worst);
        ENSURE(worst < 1e-4);
        ENSURE(NEAR(ya[2], yb[2]) || fabs(ya[2] - yb[2]) < 1e-6); /* the height */
    }
    rc_model_free(ma);
    rc_model_free(mb);
    rc_case_free(a);
    rc_case_free(b);
}

/* Values without a fixed dimension cannot be converted: errors naming them. */
static void test_deck_units_refused(void)
{
    rc_error e;
#define MM_DECK(body) "/BEGIN\nmm\n2022\nkg,mm,s\n" body RUN_CARD
    /* /INTER/POWER K: N/m^m1 depends on m1 */
    ENSURE(load_fails(tu_tmp_write("upow.rad", MM_DECK("/INTER/POWER/1\np\n1,2\n1e6,1.5\n")), &e));
    ENSURE(strstr(e.msg, "upow.rad:8: card /INTER/POWER/1, field K") && strstr(e.msg, "no fixed dimension"));
    /* a spring's force table */
    ENSURE(load_fails(tu_tmp_write("uspr.rad", MM_DECK("/COUPLING/SPRING/1\ns\n0,1,3,9\n0,0,0\n1,0,0\n,\n")), &e));
    ENSURE(strstr(e.msg, "uspr.rad:7: card /COUPLING/SPRING/1, field fct_ID") && strstr(e.msg, "not SI"));
    /* /FRICTION Ifric 1 coefficients */
    ENSURE(load_fails(tu_tmp_write("ufr.rad", MM_DECK("/FRICTION/1\nf\n1\n1e-6\n0,0.3\n")), &e));
    ENSURE(strstr(e.msg, "ufr.rad:8: card /FRICTION/1, field C1") && strstr(e.msg, "no fixed dimension"));
    /* ...but Renard's velocities and a zero K convert */
    rc_case *c = load_ok(tu_tmp_write("ufr3.rad", MM_DECK("/FRICTION/1\nf\n3\n0.3,0.2,0.4,0.1,10\n200,0.3\n")));
    ENSURE(c && c->nfriction == 1 && NEAR(c->friction[0].def.c[4], 0.01) && NEAR(c->friction[0].def.c[5], 0.2) &&
           c->friction[0].def.c[0] == 0.3);
    rc_case_free(c);
#undef MM_DECK
}

/* tests/data/radioss_rigid_cards.rad: a deck of Radioss cards only (a
 * /PENTA6 wedge and a /TETRA10 body joined by a /SPRING of /PROP/TYPE4, a
 * point body framed by /SKEW/MOV on a spring to a free node and pushed by
 * an /IMPVEL from Tstart to Tstop, /GRPART/GRPART, the engine's /RUN and
 * /ANIM/DT) read, compiled and run end to end: the masses from the mesh
 * and the springs, the imposed window's events and velocity. */
static void test_deck_radioss_rigid_cards(void)
{
    rc_case *c = load_ok("tests/data/radioss_rigid_cards.rad");
    rc_model *m = NULL;
    rc_error e;
    rc_error_clear(&e);
    ENSURE(c != NULL);
    if (!c) return;
    ENSURE(c->ngrpart == 3 && c->grpart[2].n == 2 && c->grpart[2].parts[0] == 1 && c->grpart[2].parts[1] == 2);
    ENSURE(rc_model_compile(c, &m, &e) == RC_OK);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        rc_case_free(c);
        return;
    }
    const double *M = m->body_mass;
    ENSURE(rc_model_body_count(m) == 3);
    /* 7800 kg/m^3: the wedge 0.02 x 0.1 m^3, the tetrahedron 0.0045 m^3;
     * the springs' 0.2 kg shared by their nodes (node 106 in no body) */
    ENSURE_NEAR(M[0], 7800 * 0.002 + 0.1, 1e-13, 0);
    ENSURE_NEAR(M[1], 7800 * 0.0045 + 0.1, 1e-13, 0);
    ENSURE_NEAR(M[2], 2.5 + 0.1, 1e-14, 0);
    int n = rc_model_state_size(m);
    double *y = malloc((size_t)n * sizeof *y);
    static tu_evlog ev;
    memset(&ev, 0, sizeof ev);
    rc_run_options o = {.t_end_override = 0.04, .y_end = y, .on_event = tu_evlog_event, .user = &ev};
    ENSURE(y && rc_run(m, &o, NULL, &e) == RC_OK);
    double s[13];
    if (y && rc_model_body_state(m, y, 3, s, &e) == RC_OK) ENSURE_NEAR(s[7], 0.4, 1e-9, 0);
    int starts = 0;
    for (int k = 0; k < ev.n && k < TU_MAXEV; k++)
        if (!strcmp(ev.kind[k], "impvel_start")) starts += fabs(ev.t[k] - 0.02) < 1e-14;
    ENSURE(starts == 1);
    /* the whole run (to 0.1 s): the window closes at Tstop */
    memset(&ev, 0, sizeof ev);
    rc_run_options o2 = {.on_event = tu_evlog_event, .user = &ev};
    ENSURE(rc_run(m, &o2, NULL, &e) == RC_OK);
    int stops = 0;
    for (int k = 0; k < ev.n && k < TU_MAXEV; k++)
        if (!strcmp(ev.kind[k], "impvel_stop")) stops += fabs(ev.t[k] - 0.05) < 1e-14;
    ENSURE(stops == 1);
    free(y);
    rc_model_free(m);
    rc_case_free(c);
}

void suite_deck(void);
void suite_deck(void)
{
    RUN_TEST(test_deck_grav_columns);
    RUN_TEST(test_deck_end_in_include);
    RUN_TEST(test_deck_lenient_headers_and_text);
    RUN_TEST(test_deck_type6_iform_without_stiff);
    RUN_TEST(test_deck_fric_orient_zero_vector);
    RUN_TEST(test_deck_explicit_cards_one_warning_per_kind);
    RUN_TEST(test_deck_several_errors);
    RUN_TEST(test_deck_begin_forms);
    RUN_TEST(test_deck_engine_run_single_file);
    RUN_TEST(test_deck_engine_pair);
    RUN_TEST(test_deck_type6_layouts);
    RUN_TEST(test_deck_loads_layouts_44);
    RUN_TEST(test_deck_impvel_110);
    RUN_TEST(test_deck_inivel_2025);
    RUN_TEST(test_deck_friction_2019);
    RUN_TEST(test_deck_units_begin);
    RUN_TEST(test_deck_units_unit_cards);
    RUN_TEST(test_deck_units_90_form);
    RUN_TEST(test_deck_units_run_matches_si);
    RUN_TEST(test_deck_units_refused);
    RUN_TEST(test_deck_radioss_rigid_cards);
    tu_tmp_cleanup();
}
