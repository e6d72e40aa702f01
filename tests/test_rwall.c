/*
 * Rigid walls (/RWALL): the card in the Radioss layouts of each version
 * (4.1, 4.4, 5.1 to 2025, 2026 with Iform; fixed and comma format; units),
 * and the model the compiler makes of it (model/rwall.c): one TYPE6
 * contact per surface of each body the wall acts on, its stiffness from
 * the body's weight and radius of gyration, the groups, the search distance,
 * fixed bodies left out, and the input errors of the compiler.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "case/case.h"
#include "engine/assembly/assembly.h"
#include "engine/events/events.h"
#include "harness.h"
#include "model/model.h"
#include "model/rwall.h"
#include "testutil.h"

/* A ball (node 1, /RBODY/1, mass 1.3 kg, J 0.0017) with its sphere
 * /SURF/ELLIPS/2 and /GRNOD/NODE/7 = {1}, gravity -9.81 along z; then the
 * wall card `wall` under /BEGIN version `invers` and length unit `lu`. */
static const char *ball_deck(int invers, const char *lu, const char *wall)
{
    static char text[4096];
    snprintf(text, sizeof text,
             "/BEGIN\nrwall\n%10d         0\n%20s%20s%20s\n%20s%20s%20s\n"
             "/NODE\n         1                 0.0                 0.0                0.15\n"
             "/RBODY/1\nball\n         1         0         0         0                 1.3         0\n"
             "              0.0017              0.0017              0.0017\n                 0.0                 0.0                 0.0\n"
             "/GRNOD/NODE/7\nball node\n         1\n"
             "/SURF/ELLIPS/2\nball surface\n         0         2         1\n"
             "                 0.0                 0.0                0.15\n"
             "                0.05                0.05                0.05\n"
             "%s/RUN\n1.0371,0.01\n/END\n",
             invers, "kg", lu, "s", "kg", lu, "s", wall);
    return text;
}

/* Load a deck text that must be valid (the case, or NULL after a failure). */
static rc_case *load_text(const char *name, const char *text)
{
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    if (rc_case_load(tu_tmp_write(name, text), &c, &e) != RC_OK) fprintf(stderr, "  unexpected error: %s\n", e.msg);
    return c;
}

/* The wall read equals the one written in every layout. */
static int wall_is(const rc_case *c, rc_case_rwall_kind kind, int slide, double fric, double diam, double zm, double zm1,
                   int iform)
{
    if (!c || c->nrwall != 1) return 0;
    const rc_case_rwall *w = &c->rwall[0];
    return w->id == 3 && w->kind == kind && w->node_id == 0 && w->slide == slide && w->grnd1 == 7 && w->grnd2 == 0 &&
           fabs(w->fric - fric) < 1e-15 && fabs(w->diameter - diam) < 1e-15 && w->m[0] == 0 && w->m[1] == 0 &&
           fabs(w->m[2] - zm) < 1e-15 && fabs(w->m1[2] - zm1) < 1e-15 && w->iform == iform &&
           strcmp(w->title, "floor") == 0;
}

static void test_rwall_layouts(void)
{
    /* Radioss 5.1 to 2025: 10- and 20-character fields */
    static const char w2022[] = "/RWALL/PLANE/3\nfloor\n         0         2         7         0\n"
                                "                   0                0.37                                       0         0\n"
                                "                 0.0                 0.0              -0.013\n"
                                "                 0.0                 0.0               0.987\n";
    rc_case *c = load_text("rw2022.rad", ball_deck(2022, "m", w2022));
    ENSURE(wall_is(c, RC_RWALL_PLANE, 2, 0.37, 0.0, -0.013, 0.987, 0));
    if (c) ENSURE(c->rwall[0].line_loc[0].line == 23 && c->rwall[0].line_loc[3].line == 26);
    rc_case_free(c);
    /* 2026: Iform in columns 41-50 */
    static const char w2026[] = "/RWALL/SPHER/3\nfloor\n         0         0         7         0         1\n"
                                "                   0                   0                0.71\n"
                                "                 0.0                 0.0              -0.013\n";
    c = load_text("rw2026.rad", ball_deck(2026, "m", w2026));
    ENSURE(wall_is(c, RC_RWALL_SPHER, 0, 0.0, 0.71, -0.013, 0.0, 1));
    rc_case_free(c);
    /* 4.4: 8- and 16-character fields, ffac and ifq */
    static const char w44[] = "/RWALL/CYL/3\nfloor\n       0       2       7       0\n"
                              "               0            0.37            0.71               0       0\n"
                              "             0.0             0.0          -0.013\n"
                              "             0.0             0.0           0.987\n";
    c = load_text("rw44.rad", ball_deck(44, "m", w44));
    ENSURE(wall_is(c, RC_RWALL_CYL, 2, 0.37, 0.71, -0.013, 0.987, 0));
    rc_case_free(c);
    /* 4.1: no ffac, ifq: text there is after the layout (a warning) */
    static const char w41[] = "/RWALL/PLANE/3\nfloor\n       0       2       7       0\n"
                              "               0            0.37               0\n"
                              "             0.0             0.0          -0.013\n"
                              "             0.0             0.0           0.987\n";
    c = load_text("rw41.rad", ball_deck(41, "m", w41));
    ENSURE(wall_is(c, RC_RWALL_PLANE, 2, 0.37, 0.0, -0.013, 0.987, 0));
    rc_case_free(c);
    /* comma format, and a deck in mm: lengths converted, fric not */
    static const char wmm[] = "/RWALL/CYL/3\nfloor\n0,2,7,0\n0,0.37,710,0,0\n0,0,-13\n0,0,987\n";
    c = load_text("rwmm.rad", ball_deck(2022, "mm", wmm));
    ENSURE(wall_is(c, RC_RWALL_CYL, 2, 0.37, 0.71, -0.013, 0.987, 0));
    rc_case_free(c);
    /* the 2026 Iform field is text after the layout in a 2022 deck: a
     * warning, the wall read */
    c = load_text("rw2022i.rad", ball_deck(2022, "m", w2026));
    ENSURE(wall_is(c, RC_RWALL_SPHER, 0, 0.0, 0.71, -0.013, 0.0, 0));
    int warned = 0;
    for (int k = 0; c && k < c->nwarnings; k++) warned |= strstr(c->warnings[k], "text after column 40") != NULL;
    ENSURE(warned);
    rc_case_free(c);
}

/* Interfaces of model m named after wall `name`. */
static int wall_contacts(const rc_model *m, const char *name)
{
    int n = 0;
    for (int i = 0; i < m->ninter; i++) n += strncmp(m->inter_name[i], name, strlen(name)) == 0;
    return n;
}

static void test_rwall_model(void)
{
    /* a plane wall z = -0.013 under the ball, Slide 2 */
    static const char w[] = "/RWALL/PLANE/3\nfloor\n         0         2         7         0\n"
                            "                   0                0.37                                       0         0\n"
                            "                 0.0                 0.0              -0.013\n"
                            "                 0.0                 0.0               0.987\n"
                            "/GRAV/1\ngravity\n         0         Z         0         0         0                           1.0               -9.81\n";
    rc_model *m = TU_COMPILE_OK(ball_deck(2022, "m", w), "rwmodel.rad");
    ENSURE(m != NULL);
    if (!m) return;
    ENSURE(m->ninter == 1 && m->nsurf == 2);
    if (m->ninter == 1) {
        /* k = m g / (1e-4 L), L = sqrt(tr J / (2 m)); the curve F = k P
         * through ascalex = L, fscaleld = k L */
        const double L = sqrt(3 * 0.0017 / (2 * 1.3)), k = 1.3 * 9.81 / (RC_RWALL_PEN_FRAC * L);
        ENSURE(strcmp(m->inter_name[0], "/RWALL/PLANE/3 with /SURF/ELLIPS/2") == 0);
        ENSURE(m->inter_id[0] == -3 && m->surf_id[m->inter_sb[0]] == -3 && m->inter_pair[0] == RC_PAIR_SPHERE_PLANE);
        ENSURE_NEAR(m->inter_ascalex[0], L, 1e-15, 0);
        ENSURE_NEAR(m->inter_fscaleld[0] / m->inter_ascalex[0], k, 1e-14, 0);
        ENSURE(m->inter_etarget[0] == RC_RWALL_RESTITUTION && m->inter_fr[0].kind == RC_FK_TYPE6 &&
               m->inter_fr[0].fric == 0.37);
        ENSURE(m->surf_body[m->inter_sb[0]] == -1 && m->inter_bb[0] == -1 && m->inter_ba[0] == 0);
        ENSURE(m->inter_loc[0].line == 21);
    }
    rc_model_free(m);

    /* no gravity: the stiffness of standard gravity; Slide 0: no friction */
    static const char w0[] = "/RWALL/PLANE/3\nfloor\n         0         0         7         0\n\n"
                             "                 0.0                 0.0              -0.013\n"
                             "                 0.0                 0.0               0.987\n";
    m = TU_COMPILE_OK(ball_deck(2022, "m", w0), "rwmodel0.rad");
    if (m) {
        const double L = sqrt(3 * 0.0017 / (2 * 1.3)), k = 1.3 * RC_RWALL_G_REF / (RC_RWALL_PEN_FRAC * L);
        ENSURE(m->ninter == 1);
        if (m->ninter == 1) {
            ENSURE_NEAR(m->inter_fscaleld[0] / m->inter_ascalex[0], k, 1e-14, 0);
            ENSURE(m->inter_fr[0].kind == RC_FK_NONE);
        }
    }
    rc_model_free(m);

    /* several bodies: a box (its corners against the plane), a ball taken
     * out by grnd_ID2, a fixed ball, a ball reached only by the search
     * distance d, a ball out of reach; a sphere wall and a cylinder wall */
    static const char many[] =
        "/NODE\n         1                 0.0                 0.0                 0.1\n"
        "         2                 1.0                 0.0                 0.1\n"
        "         3                 2.0                 0.0                 0.1\n"
        "         4                 3.0                 0.0                 0.1\n"
        "         5                 4.0                 0.0                 0.1\n"
        "         6                 5.0                 0.0                 5.0\n"
        "/RBODY/1\nball\n         1                                                 1\n0.001,0.001,0.001\n0,0,0\n"
        "/RBODY/2\nbox\n         2                                                 1\n0.001,0.001,0.001\n0,0,0\n"
        "/RBODY/3\nball out\n         3                                                 1\n0.001,0.001,0.001\n0,0,0\n"
        "/RBODY/4\nfixed ball\n         4                                                 1\n0.001,0.001,0.001\n0,0,0\n"
        "/RBODY/5\nsearched ball\n         5                                                 1\n0.001,0.001,0.001\n0,0,0\n"
        "/RBODY/6\nfar ball\n         6                                                 1\n0.001,0.001,0.001\n0,0,0\n"
        "/GRNOD/NODE/1\nin\n1,2,3,4\n/GRNOD/NODE/2\nout\n3\n/GRNOD/NODE/4\nfixed\n4\n/GRNOD/NODE/6\nfar\n6\n"
        "/BCS/1\nfixed\n   111 111         0         4\n"
        "/SURF/ELLIPS/11\nb1\n0,2,1\n0,0,0.1\n0.05,0.05,0.05\n"
        "/SURF/BOX/12\nb2\n2\n1,0,0.1\n0.05,0.05,0.05\n"
        "/SURF/ELLIPS/13\nb3\n0,2,3\n2,0,0.1\n0.05,0.05,0.05\n"
        "/SURF/ELLIPS/14\nb4\n0,2,4\n3,0,0.1\n0.05,0.05,0.05\n"
        "/SURF/ELLIPS/15\nb5\n0,2,5\n4,0,0.1\n0.05,0.05,0.05\n"
        "/SURF/ELLIPS/16\nb6\n0,2,6\n5,0,5\n0.05,0.05,0.05\n"
        "/RWALL/PLANE/8\nfloor\n0,0,1,2\n0.15\n0,0,0\n0,0,1\n"
        "/RWALL/SPHER/9\nball wall\n0,2,6\n0,0.2,1\n5,0,4.4\n"
        "/RWALL/CYL/10\nbar\n0,0,6\n0,0,0.2\n5,-1,5.2\n5,1,5.2\n"
        "/RUN\n1,0.01\n/END\n";
    m = TU_COMPILE_OK(many, "rwmany.rad");
    if (m) {
        /* the plane: bodies 1, 2 (grnd_ID1), 5 (within d = 0.15); not 3
         * (grnd_ID2), 4 (fixed), 6 (far) */
        ENSURE(m->ninter == 5);
        ENSURE(wall_contacts(m, "/RWALL/PLANE/8 with ") == 3);
        ENSURE(wall_contacts(m, "/RWALL/PLANE/8 with /SURF/ELLIPS/11") == 1);
        ENSURE(wall_contacts(m, "/RWALL/PLANE/8 with /SURF/BOX/12") == 1);
        ENSURE(wall_contacts(m, "/RWALL/PLANE/8 with /SURF/ELLIPS/15") == 1);
        ENSURE(wall_contacts(m, "/RWALL/SPHER/9 with /SURF/ELLIPS/16") == 1);
        ENSURE(wall_contacts(m, "/RWALL/CYL/10 with /SURF/ELLIPS/16") == 1);
        for (int i = 0; i < m->ninter; i++) {
            if (strstr(m->inter_name[i], "/SURF/BOX/12")) ENSURE(rc_pair_multi(m->inter_pair[i]));
            if (strstr(m->inter_name[i], "/RWALL/SPHER/9")) {
                ENSURE(m->inter_pair[i] == RC_PAIR_SPHERE_SPHERE && m->inter_fr[i].fric == 0.2);
                ENSURE_NEAR(m->surf_r[m->inter_sb[i]], 0.5, 1e-15, 0);
            }
            if (strstr(m->inter_name[i], "/RWALL/CYL/10")) {
                /* infinite for the scene: 2 x 1000 (S + Phi) long */
                const int s = m->inter_sa[i] == m->inter_sb[i] ? -1 : m->inter_sb[i];
                ENSURE(m->inter_pair[i] == RC_PAIR_SPHERE_CYL && s >= 0);
                if (s >= 0) ENSURE(m->surf_ext[RC_SURF_NEXT * s] > 1000.0 * 5.0);
            }
        }
    }
    rc_model_free(m);
}

/* A plane wall on bodies without surfaces: their nodes of the wall's set
 * are its contact points (a segment surface of points). */
static void test_rwall_nodes(void)
{
    static const char cube[] = "/NODE\n1,0,0,0.2\n11,-0.1,-0.1,0.1\n12,0.1,-0.1,0.1\n13,0.1,0.1,0.1\n14,-0.1,0.1,0.1\n"
                               "15,-0.1,-0.1,0.3\n16,0.1,-0.1,0.3\n17,0.1,0.1,0.3\n18,-0.1,0.1,0.3\n19,5,5,5\n"
                               "/RBODY/1\ncube\n         1                                                 2         2\n"
                               "0.0133,0.0133,0.0133\n0,0,0\n"
                               "/RBODY/2\nball\n        19                                                 1\n0.001,0.001,0.001\n0,0,0\n"
                               "/SURF/ELLIPS/21\nb\n0,2,2\n5,5,5\n0.05,0.05,0.05\n"
                               "/GRNOD/NODE/2\ncorners\n11,12,13,14,15,16,17,18\n/GRNOD/NODE/3\nbottom and ball\n11,12,13,14,19\n"
                               "/RWALL/PLANE/3\nfloor\n0,0,3,0\n\n0,0,-0.1\n0,0,1\n/RUN\n1,0.01\n/END\n";
    rc_model *m = TU_COMPILE_OK(cube, "rwcube.rad");
    if (m) {
        ENSURE(m->ninter == 2 && m->nsurf == 3);
        for (int i = 0; i < m->ninter; i++) {
            if (strcmp(m->inter_name[i], "/RWALL/PLANE/3 with the nodes of /RBODY/1") == 0) {
                /* the 4 bottom nodes of group 3 that are the cube's, not 19 */
                const int s = m->inter_sa[i];
                ENSURE(m->inter_pair[i] == RC_PAIR_SEG_PLANE && m->surf_kind[s] == RC_SURF_SEG && m->surf_id[s] == -4);
                ENSURE(m->surf_nadr[s + 1] - m->surf_nadr[s] == 4 && m->surf_sadr[s + 1] == m->surf_sadr[s]);
                ENSURE(m->inter_npt[i] == 0 && m->surf_body[s] == 0);
            } else {
                /* the ball has a surface: its sphere, not its node */
                ENSURE(strcmp(m->inter_name[i], "/RWALL/PLANE/3 with /SURF/ELLIPS/21") == 0);
            }
        }
    }
    rc_model_free(m);
}

/* A moving wall: a body of its node (id -rwall_ID), its Mass, VX0..VZ0,
 * rotations held, carrying the wall's surface; gravity only from a /GRAV
 * whose group holds its node. */
static void test_rwall_moving(void)
{
    static const char mv[] = "/NODE\n1,0,0,0\n9,-0.5,0,0\n"
                             "/RBODY/1\nball\n         1                                                 1         7\n"
                             "0.001,0.001,0.001\n0,0,0\n/GRNOD/NODE/7\nball\n1\n/GRNOD/NODE/8\nwall node\n9\n"
                             "/SURF/ELLIPS/2\nb\n0,2,1\n0,0,0\n0.05,0.05,0.05\n"
                             "/RWALL/PLANE/3\nmoving\n9,0,7,0\n\n3.7,2.1,0.3,-0.2\n1,0,0\n"
                             "/GRAV/1\nall bodies\n0,Z,0,0,0,,1,-9.81\n/GRAV/2\nthe wall's node\n0,Y,0,0,8,,1,-2.5\n"
                             "/RUN\n1,0.01\n/END\n";
    rc_model *m = TU_COMPILE_OK(mv, "rwmoving.rad");
    if (m) {
        ENSURE(m->nbody == 2 && m->body_id[1] == -3 && m->body_mass[1] == 3.7 && m->nfree == 2);
        const double *y0 = m->body_y0 + RC_NB;
        ENSURE(y0[0] == -0.5 && y0[7] == 2.1 && y0[8] == 0.3 && y0[9] == -0.2);
        for (int k = 0; k < 6; k++) ENSURE(m->body_dofmask[6 + k] == (k >= 3));
        ENSURE(m->body_grav[3 + 0] == 0.0 && m->body_grav[3 + 1] == -2.5 && m->body_grav[3 + 2] == 0.0);
        ENSURE(m->body_grav[2] == -9.81);
        ENSURE(m->ninter == 1);
        if (m->ninter == 1) {
            ENSURE(strcmp(m->inter_name[0], "/RWALL/PLANE/3 with /SURF/ELLIPS/2") == 0);
            ENSURE(m->inter_ba[0] == 0 && m->inter_bb[0] == 1 && m->surf_body[m->inter_sb[0]] == 1);
        }
    }
    rc_model_free(m);
}

static void test_rwall_errors(void)
{
    /* a sphere wall on a body without surfaces */
    static const char bare[] = "/NODE\n1,0,0,0.1\n2,1,0,0.1\n"
                               "/RBODY/1\nball\n         1                                                 1\n0.001,0.001,0.001\n0,0,0\n"
                               "/RBODY/2\nbare\n         2                                                 1\n0.001,0.001,0.001\n0,0,0\n"
                               "/SURF/ELLIPS/11\nb1\n0,2,1\n0,0,0.1\n0.05,0.05,0.05\n/GRNOD/NODE/1\nboth\n1,2\n"
                               "/RWALL/SPHER/8\nball wall\n0,0,1,0\n0,0,1\n0,0,-0.5\n/RUN\n1,0.01\n/END\n";
    TU_EXPECT_TEXT_ERROR(bare, "rwbare.rad", "rwbare.rad:24: card /RWALL/SPHER/8, field grnd_ID1",
                         "/RBODY/2, which carries no surface", "not supported yet");
    /* a node of grnd_ID1 on no body */
    static const char loose[] = "/NODE\n1,0,0,0.1\n2,1,0,0.1\n"
                                "/RBODY/1\nball\n         1                                                 1\n0.001,0.001,0.001\n0,0,0\n"
                                "/SURF/ELLIPS/11\nb1\n0,2,1\n0,0,0.1\n0.05,0.05,0.05\n/GRNOD/NODE/1\nboth\n1,2\n"
                                "/RWALL/PLANE/8\nfloor\n0,0,1,0\n\n0,0,0\n0,0,1\n/RUN\n1,0.01\n/END\n";
    TU_EXPECT_TEXT_ERROR(loose, "rwloose.rad", "rwloose.rad:19: card /RWALL/PLANE/8, field grnd_ID1",
                         "node 2 (", "belongs to no /RBODY");
    /* a plane wall against a body's plane: no such pair */
    static const char pp[] = "/NODE\n1,0,0,0.1\n"
                             "/RBODY/1\nslab\n         1                                                 1\n0.001,0.001,0.001\n0,0,0\n"
                             "/SURF/PLANE/11\nb1\n0,0,0.1\n0,0,1.1\n1\n/GRNOD/NODE/1\nslab\n1\n"
                             "/RWALL/PLANE/8\nfloor\n0,0,1,0\n\n0,0,0\n0,0,1\n/RUN\n1,0.01\n/END\n";
    TU_EXPECT_TEXT_ERROR(pp, "rwpp.rad", "rwpp.rad:18: card /RWALL/PLANE/8 with /SURF/PLANE/11");
}

/* /RWALL/PARAL: read, compiled into a plane bounded to the parallelogram
 * (surf_ext: corner, sides; normal e1 x e2), against the ball's sphere;
 * the Jacobian of the contact beyond a side and beyond a corner (the
 * nearest point of the sides, model/rwall.c, kernels.inc geom_sph_paral)
 * against finite differences. */
static void test_rwall_paral(void)
{
    /* the ball at (0, 0, 0.15); the parallelogram z = 0.1, corner
     * (-0.2, -0.1), sides 0.3 along x and (0.1, 0.3) (a skewed one) */
    static const char w[] = "/RWALL/PARAL/3\nplate\n         0         0         7         0\n\n"
                            "                -0.2                -0.1                 0.1\n"
                            "                 0.1                -0.1                 0.1\n"
                            "                -0.1                 0.2                 0.1\n"
                            "/GRAV/1\ngravity\n         0         Z         0         0         0                           1.0               -9.81\n";
    rc_case *c = load_text("rwparal.rad", ball_deck(2022, "m", w));
    ENSURE(c && c->nrwall == 1 && c->rwall[0].kind == RC_RWALL_PARAL);
    if (c) ENSURE(c->rwall[0].m2[0] == -0.1 && c->rwall[0].m2[1] == 0.2 && c->rwall[0].m2[2] == 0.1);
    rc_case_free(c);
    rc_model *m = TU_COMPILE_OK(ball_deck(2022, "m", w), "rwparal.rad");
    if (!m) return;
    ENSURE(m->ninter == 1 && m->inter_pair[0] == RC_PAIR_SPHERE_PLANE);
    if (m->ninter == 1) {
        ENSURE(strcmp(m->inter_name[0], "/RWALL/PARAL/3 with /SURF/ELLIPS/2") == 0);
        const int s = m->inter_sb[0];
        const double *e = m->surf_ext + RC_SURF_NEXT * s, *n = m->surf_n + 3 * s;
        ENSURE(e[0] == 1.0);
        ENSURE(fabs(e[4] - 0.3) < 1e-15 && e[5] == 0 && e[6] == 0);
        ENSURE(fabs(e[7] - 0.1) < 1e-15 && fabs(e[8] - 0.3) < 1e-15 && e[9] == 0);
        ENSURE(n[0] == 0 && n[1] == 0 && n[2] == 1.0); /* e1 x e2 */
    }
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double));
    rc_initial_state(m, y);
    /* beyond the side from (0.1, -0.1) to (0.2, 0.2) (its nearest point
     * inside the side), beyond the corner (0.2, 0.2), and over the
     * parallelogram; each within R of it, moving and spinning */
    static const double pos[3][3] = {{0.16, 0.0, 0.12}, {0.22, 0.22, 0.13}, {0.0, 0.0, 0.14}};
    int bad = 0, outside = 0;
    double maxerr = 0;
    for (int k = 0; k < 3; k++) {
        double *yb = y + m->body_yadr[0];
        for (int j = 0; j < 3; j++) yb[j] = pos[k][j] - m->origin[j];
        yb[7] = 0.3, yb[8] = 0.2, yb[9] = -0.1, yb[10] = 1.0, yb[11] = -2.0, yb[12] = 0.5;
        rc_modes_init(m, d, 0.0, y);
        ENSURE(d->inter_mode[0] != RC_MODE_OPEN && d->inter_mode[0] != RC_MODE_INACTIVE); /* in contact */
        int b1 = 0, o1 = 0;
        const double e1 = tu_jac_fd_error(m, d, 0.0, y, 1, &b1, &o1);
        printf("    position %d: mode %d, |J - FD| %.2e, %d bad, %d outside\n", k, d->inter_mode[0], e1, b1, o1);
        maxerr = fmax(maxerr, e1);
        bad += b1;
        outside += o1;
    }
    printf("    parallelogram wall: max scaled |J - FD| %.2e, %d bad, %d outside the pattern\n", maxerr, bad, outside);
    ENSURE(bad == 0 && outside == 0 && maxerr < 1e-6);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

void suite_rwall(void);
void suite_rwall(void)
{
    RUN_TEST(test_rwall_layouts);
    RUN_TEST(test_rwall_model);
    RUN_TEST(test_rwall_nodes);
    RUN_TEST(test_rwall_moving);
    RUN_TEST(test_rwall_errors);
    RUN_TEST(test_rwall_paral);
}
