/*
 * /INTER/TYPE11 and /INTER/TYPE19 (cards_interfaces.c, /LINE/SURF in
 * cards_bodies.c, model/type7.c): the cards read in Radioss's layouts
 * (columns, defaults, line roles), the contact the compiler makes of them
 * between two boxes (TYPE11: the box pair's 144 edge pairs alone, its
 * corners never touching; TYPE19: the whole box pair), the edges-only
 * Jacobian against central differences, and the refusals (a line of
 * several surfaces or of a surface that is not a box, a missing line,
 * self-contact, a surface that is not a box).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "case/case.h"
#include "engine/assembly/assembly.h"
#include "harness.h"
#include "model/model.h"
#include "model/segsurf.h"
#include "testutil.h"

/* A bar along x (/SURF/BOX/30 on /RBODY/1, 2 kg, 0.6 x 0.1 x 0.1 m) 0.1 mm
 * into a fixed bar along y (/SURF/BOX/40): only their edges cross; a box
 * (/SURF/BOX/31, on the same body, 0.2 x 0.1 x 0.1 m, its bottom 0.1 mm
 * into a fixed 1 m cube's top face, /SURF/BOX/41, far from the bars) whose
 * corners alone would touch. /LINE/SURF 130, 140, 131, 141: one box each. */
#define T11_GEOM                                                                                          \
    "/BEGIN\ntype11 test\n      2022         0\n"                                                       \
    "                  kg                   m                   s\n"                                   \
    "                  kg                   m                   s\n" T11_BODIES
#define T11_BODIES                                                                                        \
    "/NODE\n1,0.013,-0.021,0.0499\n/RBODY/1\nbar\n1,,,,2.0\n0.0033,0.0083,0.0083\n0,0,0\n"                 \
    "/SURF/BOX/30\nbar along x\n1\n0.013,-0.021,0.0499\n0.3,0.05,0.05\n"                                  \
    "/SURF/BOX/40\nbar along y\n0\n0,0,-0.05\n0.05,0.3,0.05\n"                                            \
    "/SURF/BOX/31\nbox\n1\n5.1,0,0.0499\n0.1,0.05,0.05\n"                                                 \
    "/SURF/BOX/41\ncube\n0\n5,0,-0.5\n0.5,0.5,0.5\n"                                                      \
    "/LINE/SURF/130\nbar x\n        30\n/LINE/SURF/140\nbar y\n        40\n"                               \
    "/LINE/SURF/131\nbox\n        31\n/LINE/SURF/141\ncube\n        41\n"
#define T11_TAIL "/RUN\n0.01,0.001\n/END\n"

/* /INTER/TYPE11/11 between lines a and b in the 2022 layout: Istf 1,
 * Stfac 3.7e4, Fric 0.2, Gapmin 2e-5, Tstart 0.001, Tstop 0.5, Inacti 5,
 * VISs 0.3, fric_ID 0; Iform 1 and sens_ID 0 on line 2. */
static const char *type11_deck(const char *a, const char *b)
{
    static char text[4096];
    snprintf(text, sizeof text,
             T11_GEOM "/INTER/TYPE11/11\nedges\n%10s%10s         1         0         0                   0         0\n"
                      "                   0                   0                   0                   0         1         0\n"
                      "               37000                 0.2               2e-05               0.001                 0.5\n"
                      "         0                             5                 0.3                                       0\n"
                      "                                                                                                   0\n" T11_TAIL,
             a, b);
    return text;
}

/* /INTER/TYPE19/19 between surfaces a and b in the 2022 layout: Istf 1,
 * Iedge 2, Stfac 4.2e4, Fric 0.1, Inacti 5, VISs 0.25; the rest blank. */
static const char *type19_deck(const char *a, const char *b)
{
    static char text[4096];
    snprintf(text, sizeof text,
             T11_GEOM "/INTER/TYPE19/19\nnodes and edges\n%10s%10s         1         0         0         2         0         0         0\n"
                      "\n\n"
                      "               42000                 0.1\n"
                      "         0                             5                0.25\n"
                      "\n" T11_TAIL,
             a, b);
    return text;
}

static void test_type11_read(void)
{
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    const char *text = type11_deck("130", "140");
    rc_status st = rc_case_load(tu_tmp_write("t11read.rad", text), &c, &e);
    ENSURE(st == RC_OK);
    if (st != RC_OK) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    ENSURE(c->ntype24 == 1 && c->nline == 4 && c->line[0].id == 130 && c->line[0].n == 1 && c->line[0].surf[0] == 30);
    const rc_case_type24 *t = &c->type24[0];
    ENSURE(t->type == 11 && t->id == 11 && t->line1 == 130 && t->line2 == 140 && t->surf1 == 0 && t->istf == 1);
    ENSURE(t->stfac == 3.7e4 && t->fric == 0.2 && t->gapmin == 2e-5 && t->tstart == 0.001 && t->tstop == 0.5);
    ENSURE(t->inacti == 5 && t->viss == 0.3 && t->fric_id == 0 && t->sensor_id == 0);
    /* TYPE24's line roles: Stmin (2), Stfac (3), Inacti (4), fric_ID (5) */
    const int l1 = t->line_loc[0].line;
    ENSURE(t->line_loc[2].line == l1 + 1 && t->line_loc[3].line == l1 + 2 && t->line_loc[4].line == l1 + 3 &&
           t->line_loc[5].line == l1 + 4);
    rc_case_free(c);
    c = NULL;
    st = rc_case_load(tu_tmp_write("t19read.rad", type19_deck("30", "40")), &c, &e);
    ENSURE(st == RC_OK);
    if (st != RC_OK) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    t = &c->type24[0];
    ENSURE(t->type == 19 && t->id == 19 && t->surf1 == 30 && t->surf2 == 40 && t->istf == 1 && t->iedge == 2);
    ENSURE(t->stfac == 4.2e4 && t->fric == 0.1 && t->viss == 0.25 && t->tstop == 1e30 && t->inacti == 5);
    rc_case_free(c);
}

/* The contact at the start: TYPE11 between the bars 0.1 mm deep at the
 * crossings, nothing between the box and the cube (the corners do not
 * act); TYPE19 0.1 mm deep in both. */
static double start_p(const char *text, const char *path, int *edges, int *npts, double *k, double *gap)
{
    rc_model *m = TU_COMPILE_OK(text, path);
    if (!m) return NAN;
    *edges = m->inter_edges[0];
    *npts = rc_seg_points(m, 0);
    *k = m->inter_fscaleld[0] / m->inter_ascalex[0];
    *gap = m->inter_gap[0];
    ENSURE(rc_box_is_box_pair(m, 0));
    double *y = calloc((size_t)m->ny, sizeof(double));
    rc_initial_state(m, y);
    rc_inter_report r;
    rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
    free(y);
    rc_model_free(m);
    return r.p;
}

static void test_type11_model(void)
{
    int edges = -1, n = 0;
    double k = 0, gap = 0;
    double p = start_p(type11_deck("130", "140"), "t11bars.rad", &edges, &n, &k, &gap);
    printf("    TYPE11 bar across a bar: P = %.9g m (Gapmin 2e-5 m), %d points, edges only %d\n", p, n, edges);
    ENSURE(edges == 1 && n == 16 + RC_BOX_EDGE_PAIRS);
    ENSURE_NEAR(k, 3.7e4, 1e-15, 0);
    ENSURE(gap == 2e-5);
    ENSURE_NEAR(p, 1e-4 + 2e-5, 1e-9, 0);
    p = start_p(type11_deck("131", "141"), "t11flat.rad", &edges, &n, &k, &gap);
    printf("    TYPE11 box flat on a cube: P = %.9g m (no edge meets an edge)\n", p);
    ENSURE(edges == 1 && p < 0);
    p = start_p(type19_deck("31", "41"), "t19flat.rad", &edges, &n, &k, &gap);
    printf("    TYPE19 box flat on a cube: P = %.9g m (its corners)\n", p);
    ENSURE(edges == 0 && gap == 0);
    ENSURE_NEAR(k, 4.2e4, 1e-15, 0);
    ENSURE_NEAR(p, 1e-4, 1e-9, 0);
    p = start_p(type19_deck("30", "40"), "t19bars.rad", &edges, &n, &k, &gap);
    ENSURE_NEAR(p, 1e-4, 1e-9, 0);
    /* TYPE19 Iedge 1: the free edges, none on a closed box: the corners
     * alone; the flat box held, the bars (only their edges cross) not */
    static const char ie2[] = "         2         0         0         0\n", ie1[] = "         1         0         0         0\n";
    char buf[4096];
    snprintf(buf, sizeof buf, "%s", type19_deck("31", "41"));
    char *at = strstr(buf, ie2);
    ENSURE(at != NULL);
    if (at) {
        memcpy(at, ie1, sizeof ie1 - 1);
        p = start_p(buf, "t19flat1.rad", &edges, &n, &k, &gap);
        printf("    TYPE19 Iedge 1 box flat on a cube: P = %.9g m (its corners), corners only %d\n", p, edges);
        ENSURE(edges == 2);
        ENSURE_NEAR(p, 1e-4, 1e-9, 0);
    }
    snprintf(buf, sizeof buf, "%s", type19_deck("30", "40"));
    at = strstr(buf, ie2);
    if (at) {
        memcpy(at, ie1, sizeof ie1 - 1);
        p = start_p(buf, "t19bars1.rad", &edges, &n, &k, &gap);
        printf("    TYPE19 Iedge 1 bar across a bar: P = %.9g m (no corner over a face, no edge pair)\n", p);
        ENSURE(edges == 2 && p < 0);
        memcpy(at, "         3", 10);
        TU_EXPECT_TEXT_ERROR(buf, "t19iedge3.rad", "card /INTER/TYPE19/19, field Iedge", "expected 0, 1 (the free edges)");
    }
}

/* The edges-only pair's Jacobian against central differences, the bar
 * turned and moving, in every mode, with TYPE11's Fric. */
static void test_type11_jacobian(void)
{
    rc_model *m = TU_COMPILE_OK(type11_deck("130", "140"), "t11jac.rad");
    if (!m) return;
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double));
    rc_initial_state(m, y);
    /* Inacti 5's offset below the start's penetration: the edges loaded
     * (at the start the offset takes the whole penetration: a kink) */
    ENSURE(m->inter_oidx[0] >= 0);
    if (m->inter_oidx[0] >= 0) y[m->inter_eadr[0] + m->inter_oidx[0]] = 3e-5;
    /* the effective penetration P_e (a state of the pair, 0 at the start),
     * off P = 1.2e-4 - 3e-5 (its relaxation towards P has a kink there) */
    ENSURE(m->inter_peidx[0] >= 0);
    if (m->inter_peidx[0] >= 0) y[m->inter_eadr[0] + m->inter_peidx[0]] = 8e-5;
    int bad = 0, outside = 0, combos = 0;
    double maxerr = 0;
    const int modes[2] = {RC_MODE_CLOSED, RC_MODE_RELEASED};
    for (int md = 0; md < 2; md++)
        for (int trk = 0; trk < 2; trk++)
        for (int sl = 0; sl < 3; sl++) {
            d->inter_mode[0] = modes[md];
            d->inter_track[0] = trk;
            for (int j = 0; j < m->inter_npt[0]; j++) d->pt_slip[j] = sl == 2 ? j % 2 : sl;
            maxerr = fmax(maxerr, tu_jac_fd_error(m, d, 0.0, y, 1, &bad, &outside));
            combos++;
        }
    printf("    TYPE11 edges-only jacobian: %d states, %d mode combinations, max scaled |J - FD| = %.2e\n", m->ny,
           combos, maxerr);
    ENSURE(bad == 0 && outside == 0);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

/* The older layouts: 10.0 (three lines, no Stmin line) and 4.4 (the same
 * in 8- and 16-character fields) give the 2022 card's values; TYPE19 is
 * read from 10.0 on, refused before. */
static void test_type11_layouts(void)
{
    static const char *const v[2] = {
        "/BEGIN\nv100\n       100         0\n" T11_BODIES "/INTER/TYPE11/11\nedges\n"
        "       130       140         1                   0         0                   0\n"
        "               37000                 0.2               2e-05               0.001                 0.5\n"
        "         0                             5                 0.3\n" T11_TAIL,
        "/BEGIN\nv44\n        44\n" T11_BODIES "/INTER/TYPE11/11\nedges\n"
        "     130     140       1               0       0\n"
        "           37000             0.2           2e-05           0.001             0.5\n"
        "       0                       5             0.3\n" T11_TAIL};
    for (int k = 0; k < 2; k++) {
        rc_case *c = NULL;
        rc_error e;
        rc_error_clear(&e);
        const rc_status st = rc_case_load(tu_tmp_write(k ? "t11v44.rad" : "t11v100.rad", v[k]), &c, &e);
        ENSURE(st == RC_OK);
        if (st != RC_OK) {
            fprintf(stderr, "  %s\n", e.msg);
            continue;
        }
        const rc_case_type24 *t = &c->type24[0];
        ENSURE(t->type == 11 && t->line1 == 130 && t->line2 == 140 && t->istf == 1 && t->stmin == 0 && t->stmax == 0);
        ENSURE(t->stfac == 3.7e4 && t->fric == 0.2 && t->gapmin == 2e-5 && t->tstart == 0.001 && t->tstop == 0.5);
        ENSURE(t->inacti == 5 && t->viss == 0.3 && t->fric_id == 0);
        ENSURE(t->line_loc[3].line == t->line_loc[0].line + 1 && t->line_loc[4].line == t->line_loc[0].line + 2);
        rc_case_free(c);
    }
    char buf[4096];
    snprintf(buf, sizeof buf, "%s", type19_deck("30", "40"));
    char *at = strstr(buf, "      2022");
    ENSURE(at != NULL);
    if (!at) return;
    memcpy(at, "       100", 10);
    rc_model *m = TU_COMPILE_OK(buf, "t19v100.rad");
    if (m) {
        ENSURE(m->ninter == 1 && rc_box_is_box_pair(m, 0) && !m->inter_edges[0]);
        rc_model_free(m);
    }
    memcpy(at, "        90", 10);
    TU_EXPECT_TEXT_ERROR(buf, "t19v90.rad", "/INTER/TYPE19 layout of Radioss versions before 10.0", "not supported yet");
}

static void test_type11_errors(void)
{
    /* the reader: self-contact, a blank line_IDm, Igap 1, VISF */
    TU_EXPECT_TEXT_ERROR(type11_deck("130", "130"), "t11self.rad", "card /INTER/TYPE11/11, field line_IDm",
                         "expected a line other than line_IDs", "not supported yet");
    TU_EXPECT_TEXT_ERROR(type11_deck("130", ""), "t11blank.rad", "field line_IDm", "self-contact of line_IDs");
    TU_EXPECT_TEXT_ERROR(type19_deck("30", "30"), "t19self.rad", "card /INTER/TYPE19/19, field surf_IDm",
                         "expected a surface other than surf_IDs");
    /* the compiler: a missing line, a line of no box, a line of two
     * surfaces, a TYPE19 of a plane */
    TU_EXPECT_TEXT_ERROR(type11_deck("130", "199"), "t11noline.rad", "card /INTER/TYPE11/11, field line_IDm",
                         "expected the id of a /LINE/SURF, got 199");
    static const char plane[] = "/SURF/PLANE/50\nfloor\n0,0,-1\n0,0,1\n";
    char text[4096];
    const char *d11 = type11_deck("130", "150");
    const char *cut = strstr(d11, "/INTER/TYPE11");
    snprintf(text, sizeof text, "%.*s%s/LINE/SURF/150\nfloor\n        50\n/LINE/SURF/151\ntwo\n        30        40\n%s",
             (int)(cut - d11), d11, plane, cut);
    TU_EXPECT_TEXT_ERROR(text, "t11plane.rad", "card /INTER/TYPE11/11, field line_IDm", "/SURF/PLANE/50 is not supported yet",
                         "expected a /SURF/BOX or a closed box mesh");
    char *l2 = strstr(text, "       150         1");
    ENSURE(l2 != NULL);
    if (l2) {
        memcpy(l2, "       151", 10);
        TU_EXPECT_TEXT_ERROR(text, "t11two.rad", "field line_IDm", "/LINE/SURF/151 lists 2 surfaces", "not supported yet");
    }
    const char *d19 = type19_deck("30", "50");
    cut = strstr(d19, "/INTER/TYPE19");
    snprintf(text, sizeof text, "%.*s%s%s", (int)(cut - d19), d19, plane, cut);
    TU_EXPECT_TEXT_ERROR(text, "t19plane.rad", "card /INTER/TYPE19/19, field surf_IDm", "/SURF/PLANE/50 is not supported yet");
}

/* A side that is a /SURF/PART of one /BRICK (a bar's solid, /RBODY/1) is
 * taken as its box: the bars of type11_deck, the upper one meshed. */
static void test_type11_brick_part(void)
{
    static const char deck[] =
        "/BEGIN\nbrick part\n      2022         0\n"
        "                  kg                   m                   s\n"
        "                  kg                   m                   s\n"
        "/NODE\n1,0.013,-0.021,0.0499\n"
        "11,-0.287,-0.071,-0.0001\n12,0.313,-0.071,-0.0001\n13,0.313,0.029,-0.0001\n14,-0.287,0.029,-0.0001\n"
        "15,-0.287,-0.071,0.0999\n16,0.313,-0.071,0.0999\n17,0.313,0.029,0.0999\n18,-0.287,0.029,0.0999\n"
        "/MAT/LAW1/1\nsteel\n7800\n2.1e11,0.3\n/PROP/SOLID/1\nsolid\n/PART/1\nbar\n1,1\n"
        "/BRICK/1\n1,11,12,13,14,15,16,17,18\n/GRNOD/PART/1\nbar nodes\n1\n"
        "/RBODY/1\nbar\n1,,,,0,1\n0,0,0\n0,0,0\n"
        "/SURF/PART/30\nbar faces\n1\n/SURF/BOX/40\nbar along y\n0\n0,0,-0.05\n0.05,0.3,0.05\n"
        "/LINE/SURF/130\nbar x\n        30\n/LINE/SURF/140\nbar y\n        40\n"
        "/INTER/TYPE11/11\nedges\n130,140,1\n\n37000\n,,5\n\n" T11_TAIL;
    int edges = -1, n = 0;
    double k = 0, gap = 0;
    const double p = start_p(deck, "t11brick.rad", &edges, &n, &k, &gap);
    printf("    TYPE11 of a /SURF/PART of one /BRICK: P = %.9g m, %d points, edges only %d\n", p, n, edges);
    ENSURE(edges == 1 && n == 16 + RC_BOX_EDGE_PAIRS);
    ENSURE_NEAR(p, 1e-4, 1e-9, 0);
}

void suite_type11(void);
void suite_type11(void)
{
    RUN_TEST(test_type11_read);
    RUN_TEST(test_type11_model);
    RUN_TEST(test_type11_jacobian);
    RUN_TEST(test_type11_layouts);
    RUN_TEST(test_type11_brick_part);
    RUN_TEST(test_type11_errors);
}
