/*
 * Segment surfaces (/SURF/SEG, /SURF/PART; model/segsurf.c) and their
 * contact with an analytic plane (engine/kernels/kernels.inc, seg_spread): reading
 * and its errors, the outer faces of a part, the force F(P) shared over the
 * nodes in proportion to their penetrations (against the rule computed
 * here), and the exact Jacobian against central finite differences.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <float.h>
#include <math.h>

#include "base/error.h"
#include "case/case.h"
#include "model/geom.h"
#include "model/segsurf.h"
#include "model/model.h"
#include "model/power.h"
#include "harness.h"
#include "testutil.h"
#include "engine/assembly/assembly.h"
#include "engine/events/events.h"

static char seg_path[128];

static rc_model *seg_compile(const char *text, rc_error *e)
{
    snprintf(seg_path, sizeof seg_path, "/tmp/rc_seg_test_%d.rad", (int)getpid());
    return tu_compile_text(text, seg_path, e);
}

/* Expect an input error whose message holds every needle. */
static int seg_error(const char *text, ...)
{
    rc_error e;
    rc_model *m = seg_compile(text, &e);
    int bad = m != NULL || e.code != RC_EINPUT;
    va_list ap;
    va_start(ap, text);
    bad += tu_missing_needles(e.msg, ap);
    va_end(ap);
    if (bad) fprintf(stderr, "  message: %s\n", m ? "(compiled)" : e.msg);
    rc_model_free(m);
    return bad;
}
#define EXPECT_SEG_ERROR(text, ...) ENSURE(seg_error((text), __VA_ARGS__, (const char *)NULL) == 0)

/* A box 0.2 x 0.1 x 0.06 on nodes 10..17 (bottom 10..13 at z = 0, top
 * 14..17 at z = 0.06), body 1 with main node 1 at its centre, mass 2 kg. */
#define BOX_NODES                                                                                          \
    "/NODE\n1,0,0,0.03\n10,-0.1,-0.05,0\n11,0.1,-0.05,0\n12,0.1,0.05,0\n13,-0.1,0.05,0\n14,-0.1,-0.05,0.06\n" \
    "15,0.1,-0.05,0.06\n16,0.1,0.05,0.06\n17,-0.1,0.05,0.06\n"
#define BOX_BODY "/GRNOD/NODE/7\ng\n10,11,12,13,14,15,16,17\n/RBODY/1\nbox\n1,,,,2.0,7\n0.0023,0.0071,0.0083\n0.0001,0.0002,-0.0001\n"
#define BOX_SEGS "/SURF/SEG/30\nbox faces\n1,10,13,12,11\n2,14,15,16,17\n3,10,11,15,14\n4,11,12,16,15\n5,12,13,17,16\n6,13,10,14,17\n"
#define FLOOR "/SURF/PLANE/40\nfloor\n0,0,0\n0,0,1\n"
#define LINEAR "/FUNCT/1\nlinear\n0,0\n1,1e6\n"
#define T6 "/INTER/TYPE6/1\nbox on floor\n30,40\n\n\n1\n\n\n"
/* On_viol 2: several decks place the bodies overlapping, to evaluate the
 * kernels in contact from t = 0 (accepted, docs/theory.md 13.3) */
#define RUN_TAIL "/RUN\n0.01,0.001,0,2\n"

/* ---- reading ----------------------------------------------------------- */

static void test_seg_read_surfaces(void)
{
    rc_error e;
    /* /SURF/SEG with a triangle (node 4 = node 3) and a quadrilateral */
    rc_model *m = seg_compile(BOX_NODES BOX_BODY "/SURF/SEG/30\ntri and quad\n1,10,11,12,12\n2,10,11,15,14\n"
                              FLOOR LINEAR T6 RUN_TAIL, &e);
    ENSURE(m != NULL);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    ENSURE(m->surf_kind[0] == RC_SURF_SEG && m->surf_body[0] == 0);
    ENSURE(m->surf_nadr[1] - m->surf_nadr[0] == 5); /* nodes 10, 11, 12, 14, 15 */
    ENSURE(m->surf_sadr[1] - m->surf_sadr[0] == 2);
    ENSURE(m->surf_seg[3] == m->surf_seg[2]);      /* the triangle */
    ENSURE(m->inter_pair[0] == RC_PAIR_SEG_PLANE && m->inter_sa[0] == 0);
    /* body frame: node 10 relative to the centre of mass (the box centre) */
    ENSURE_NEAR(m->surf_node[0], -0.1, 0, 1e-15);
    ENSURE_NEAR(m->surf_node[2], -0.03, 0, 1e-15);
    rc_model_free(m);

    /* /SURF/PART: a part of two bricks sharing a face: 10 outer faces, 12
     * nodes, each turned outwards; a shell part on its own body */
    m = seg_compile("/NODE\n1,0,0,0\n2,0,0,5\n10,0,0,0\n11,1,0,0\n12,1,1,0\n13,0,1,0\n14,0,0,1\n15,1,0,1\n16,1,1,1\n"
                    "17,0,1,1\n18,0,0,2\n19,1,0,2\n20,1,1,2\n21,0,1,2\n"
                    "30,0,0,5\n31,1,0,5\n32,1,1,5\n"
                    "/MAT/LAW1/3\nsteel\n7800\n\n/PROP/SOLID/2\nsolid\n\n\n/PART/1\nbricks\n2,3\n"
                    "/BRICK/1\n1,10,11,12,13,14,15,16,17\n2,14,15,16,17,18,19,20,21\n"
                    "/PROP/SHELL/4\nsh\n\n\n         0         0               0.002\n/PART/5\nskin\n4,3\n"
                    "/SH3N/5\n7,30,31,32\n"
                    "/GRNOD/PART/7\ng\n1\n/GRNOD/PART/8\nh\n5\n/RBODY/1\nb\n1,,,,,7,,2\n\n\n/RBODY/2\nc\n2,,,,,8,,2\n\n\n"
                    "/SURF/PART/30\nbricks\n1\n/SURF/PART/31\nskin\n5\n" FLOOR LINEAR T6 RUN_TAIL, &e);
    ENSURE(m != NULL);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    ENSURE(m->surf_nadr[1] - m->surf_nadr[0] == 12);
    ENSURE(m->surf_sadr[1] - m->surf_sadr[0] == 10);
    ENSURE(m->surf_nadr[2] - m->surf_nadr[1] == 3 && m->surf_sadr[2] - m->surf_sadr[1] == 1);
    ENSURE(m->surf_body[1] == 1);
    /* every face of the bricks points away from the centre of the part */
    int outward = 0;
    for (int k = m->surf_sadr[0]; k < m->surf_sadr[1]; k++) {
        const int *q = m->surf_seg + 4 * k;
        const double *x[4];
        for (int j = 0; j < 4; j++) x[j] = m->surf_node + 3 * (m->surf_nadr[0] + q[j]);
        double a[3], b[3], c[3] = {0, 0, 0};
        for (int j = 0; j < 3; j++) {
            a[j] = x[2][j] - x[0][j];
            b[j] = x[3][j] - x[1][j];
            for (int l = 0; l < 4; l++) c[j] += x[l][j] / 4; /* face centre, body frame (CoM at 0) */
        }
        double n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
        outward += n[0] * c[0] + n[1] * c[1] + n[2] * c[2] > 0;
    }
    ENSURE(outward == 10);
    rc_model_free(m);
}

static void test_seg_read_errors(void)
{
    EXPECT_SEG_ERROR(BOX_NODES BOX_BODY "/SURF/SEG/30\nx\n1,10,11,10,12\n" RUN_TAIL, ":21:", "card /SURF/SEG/30",
                     "field node_ID3", "different from node_ID1");
    EXPECT_SEG_ERROR(BOX_NODES BOX_BODY "/SURF/SEG/30\nx\n" RUN_TAIL, ":19:", "card /SURF/SEG/30", "at least one segment");
    EXPECT_SEG_ERROR(BOX_NODES BOX_BODY "/SURF/SEG/30\nx\n1,10,11,99\n" FLOOR LINEAR T6 RUN_TAIL, ":21:",
                     "card /SURF/SEG/30", "field node_ID3", "no such node");
    /* nodes on a body and nodes on none */
    EXPECT_SEG_ERROR(BOX_NODES "/NODE\n50,1,1,1\n" BOX_BODY "/SURF/SEG/30\nx\n1,10,11,12\n2,10,11,50\n" FLOOR LINEAR T6
                     RUN_TAIL, ":24:", "card /SURF/SEG/30", "field node_ID3", "node 50 belongs to no /RBODY",
                     "node 10 (line 23) belongs to /RBODY/1");
    EXPECT_SEG_ERROR(BOX_NODES BOX_BODY "/SURF/PART/30\nx\n9\n" FLOOR LINEAR T6 RUN_TAIL, ":21:", "card /SURF/PART/30",
                     "field part_ID", "no such part");
    EXPECT_SEG_ERROR(BOX_NODES BOX_BODY "/SURF/PART/30\nx\n" RUN_TAIL, "card /SURF/PART/30", "at least one part id");
    /* pairs and laws not supported yet */
    /* a cylinder against a segment surface: one point, TYPE6 and POWER */
    {
        rc_error e;
        rc_model *m = seg_compile(BOX_NODES BOX_BODY BOX_SEGS "/SURF/CYL/40\ns\n0\n0,2,0\n1,0,0\n0.5,1\n" LINEAR T6
                                  RUN_TAIL, &e);
        ENSURE(m && m->inter_pair[0] == RC_PAIR_CYL_SEG && m->inter_npt[0] == 0);
        rc_model_free(m);
    }
    /* a sphere against a segment surface with friction: the interface's
     * tangential state, no points */
    {
        rc_error e;
        rc_model *m = seg_compile(BOX_NODES BOX_BODY BOX_SEGS "/NODE\n2,0,0,-0.2\n/RBODY/2\nball\n2,,,,5.0\n0.1,0.1,0.1\n"
                                  "0,0,0\n/SURF/ELLIPS/40\ns\n0,2,2\n0,0,-0.2\n0.1,0.1,0.1\n" LINEAR
                                  "/INTER/TYPE6/1\nball on box\n40,30\n,0.3\n\n1\n\n\n" RUN_TAIL,
                                  &e);
        ENSURE(m && m->inter_pair[0] == RC_PAIR_SPHERE_SEG && m->inter_npt[0] == 0 && m->inter_fr[0].tidx >= 0);
        rc_model_free(m);
    }
    /* friction per node, the incremental form with a filter: 6 states per
     * point (F_t, then the filtered force), 3 otherwise */
    {
        rc_error e;
        rc_model *m = seg_compile(BOX_NODES BOX_BODY BOX_SEGS FLOOR LINEAR T6 "/FRICTION/1\nfiltered\n0,3,50,2\n\n,0.3\n" RUN_TAIL,
                                  &e);
        ENSURE(m && m->inter_npt[0] == 8 && m->inter_pst[0] == 6 && m->inter_fr[0].tau > 0 &&
               m->inter_fr[0].form == RC_FF_INCREMENTAL && m->inter_fr[0].tidx < 0);
        if (m) {
            char nm[256];
            rc_state_name(m, m->inter_eadr[0] + m->inter_ns[0] + 6 + 1, nm, sizeof nm);
            ENSURE(strstr(nm, "tangential (friction) force F_t of contact point 2") && strstr(nm, " y [N]"));
            rc_state_name(m, m->inter_eadr[0] + m->inter_ns[0] + 6 + 5, nm, sizeof nm);
            ENSURE(strstr(nm, "filtered friction force F_f of contact point 2") && strstr(nm, " z [N]"));
        }
        rc_model_free(m);
        m = seg_compile(BOX_NODES BOX_BODY BOX_SEGS FLOOR LINEAR T6 "/FRICTION/1\nunfiltered\n0,0,,2\n\n,0.3\n" RUN_TAIL, &e);
        ENSURE(m && m->inter_npt[0] == 8 && m->inter_pst[0] == 3);
        rc_model_free(m);
    }
    /* step5 friction: per node (test_seg_step5_jacobian); against a sphere
     * the interface's, at the deepest point (test_seg_sphere_step5_jacobian) */
    rc_error e;
    rc_model *m = seg_compile(BOX_NODES BOX_BODY BOX_SEGS "/NODE\n2,0,0,-0.2\n/RBODY/2\nball\n2,,,,5.0\n0.1,0.1,0.1\n"
                    "0,0,0\n/SURF/ELLIPS/40\ns\n0,2,2\n0,0,-0.2\n0.1,0.1,0.1\n"
                    "/INTER/POWER/1\np\n40,30\n1e6,1\n\n0.3,0.01,0.2,0.05\n" RUN_TAIL,
                    &e);
    ENSURE(m && m->inter_pair[0] == RC_PAIR_SPHERE_SEG && m->inter_fr[0].kind == RC_FK_STEP5 && m->inter_npt[0] == 0);
    if (!m) fprintf(stderr, "  %s\n", e.msg);
    rc_model_free(m);
}

/* ---- the force distribution ------------------------------------------- */

/* Quaternion of a rotation by angle a about unit axis u. */
static void quat(double a, const double *u, double *q)
{
    q[0] = cos(a / 2);
    for (int k = 0; k < 3; k++) q[k + 1] = sin(a / 2) * u[k];
}

static void rotate(const double *q, const double *s, double *o)
{
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double R[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
                         2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                         2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)};
    for (int i = 0; i < 3; i++) o[i] = R[3 * i] * s[0] + R[3 * i + 1] * s[1] + R[3 * i + 2] * s[2];
}

/* The box tilted so that its bottom nodes are at four different heights,
 * three of them below the floor: the accelerations are those of the
 * forces f_j = F(P_e) p_j / S at the nodes, the law at its effective
 * penetration P_e, set here to P = max p_j (linear law F = k P). */
static void test_seg_force_distribution(void)
{
    rc_error e;
    rc_model *m = seg_compile(BOX_NODES BOX_BODY BOX_SEGS FLOOR LINEAR T6 RUN_TAIL, &e);
    ENSURE(m != NULL);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double)), *yd = calloc((size_t)m->ny, sizeof(double));
    rc_initial_state(m, y);
    double *yb = y + m->body_yadr[0];
    const double ax[3] = {0.4472135954999579, -0.8944271909999159, 0.0};
    quat(0.013, ax, yb + 3);
    yb[0] = 0.003;
    yb[1] = -0.002;
    yb[2] = 0.02884;
    for (int k = 7; k < 13; k++) yb[k] = 0.0; /* at rest: no damping */
    d->inter_mode[0] = RC_MODE_CLOSED;
    rc_assemble_rhs(m, d, 0.0, y, yd);
    /* the rule, computed here */
    const int nn = m->surf_nadr[1] - m->surf_nadr[0];
    double p[8], x[8][3], P = -1, S = 0;
    int npen = 0;
    for (int j = 0; j < nn; j++) {
        rotate(yb + 3, m->surf_node + 3 * j, x[j]);
        for (int k = 0; k < 3; k++) x[j][k] += yb[k];
        p[j] = -x[j][2];
        P = fmax(P, p[j]);
        if (p[j] > 0) {
            S += p[j];
            npen++;
        }
    }
    ENSURE(npen == 3);
    y[m->inter_eadr[0] + m->inter_peidx[0]] = P; /* P_e = P */
    rc_assemble_rhs(m, d, 0.0, y, yd);
    const double F = 1e6 * P;
    double Fz = 0, tau[3] = {0, 0, 0};
    for (int j = 0; j < nn; j++) {
        if (p[j] <= 0) continue;
        const double f = F * p[j] / S, r[3] = {x[j][0] - yb[0], x[j][1] - yb[1], x[j][2] - yb[2]};
        Fz += f;
        tau[0] += r[1] * f;
        tau[1] -= r[0] * f;
    }
    ENSURE_NEAR(Fz, F, 1e-14, 0);
    const double *acc = yd + m->body_yadr[0] + 7;
    ENSURE_NEAR(acc[0], 0.0, 0, 1e-12);
    ENSURE_NEAR(acc[2], Fz / 2.0, 1e-12, 0);
    /* wdot = J^-1 R^T tau (no gyroscopic term at rest) */
    const double qc[4] = {yb[3], -yb[4], -yb[5], -yb[6]};
    double tb[3], wd[3];
    rotate(qc, tau, tb);
    const double *Ji = m->body_Jinv;
    for (int k = 0; k < 3; k++) wd[k] = Ji[3 * k] * tb[0] + Ji[3 * k + 1] * tb[1] + Ji[3 * k + 2] * tb[2];
    for (int k = 0; k < 3; k++) ENSURE_NEAR(acc[3 + k], wd[k], 1e-10, 1e-9 * fabs(wd[0]));
    printf("    three nodes past the floor: P = %.4g m, F = %.4g N, angular acceleration %.6g %.6g %.6g rad/s^2\n", P,
           F, acc[3], acc[4], acc[5]);
    /* reported: P, the deepest node */
    rc_inter_report r;
    rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
    ENSURE_NEAR(r.p, P, 1e-12, 0);
    ENSURE_NEAR(r.fn, F, 1e-12, 0);
    free(y);
    free(yd);
    rc_data_free(d);
    rc_model_free(m);
}

/* ---- Jacobian ---------------------------------------------------------- */


/* The two bodies' states (13 each) of the checks below: the box in the
 * plate, sliding and turning on it. */
static const double seg_state[26] = {0.0013, -0.0011, 0.0312, 0.97,  0.011, -0.013, 0.007, 0.31,  -0.23,
                                     -0.17,  3.1,     -2.3,   4.7,   0.0021, 0.0007, -0.2003, 0.99, -0.005,
                                     0.009,  0.003,   -0.41,  0.17,  0.053,  -1.9,   0.7,    2.2};

/* A generic state of a two-body model: the initial state with bodies 1 and
 * 2 set to s[0..12] and s[13..25] (position, quaternion, velocity, angular
 * velocity), every later state 0.013 (k - 25). The caller frees it. */
static double *two_body_state(const rc_model *m, const double s[26])
{
    double *y = calloc((size_t)m->ny, sizeof(double));
    rc_initial_state(m, y);
    for (int b = 0; b < 2; b++) memcpy(y + m->body_yadr[b], s + 13 * b, 13 * sizeof(double));
    for (int k = 26; k < m->ny; k++) y[k] = 0.013 * (k - 25);
    return y;
}

/* The box on a tilted plate carried by a second free body (box 1: a box,
 * 2: a meshed box), nonlinear load curve with Visc and both damping curves,
 * Iform 1 with an unload curve and Inacti 5, friction per node (fric 1:
 * TYPE6 Fric, incremental; 2, 3, 4: /FRICTION viscous, filtered, incremental
 * filtered): the deck into deck[size]. */
static void seg_box_plate_deck(char *deck, size_t size, int box, int fric)
{
    snprintf(deck, size, "%s%s%s%s%s%s%s", BOX_NODES BOX_BODY BOX_SEGS,
             box == 2 ? "/NODE\n2,0,0,-0.2\n/RBODY/2\nplate\n2,,,,5.0,8\n0.11,0.13,0.2\n0.01,0,0\n"
                      : "/NODE\n2,0,0,-0.2\n/RBODY/2\nplate\n2,,,,5.0\n0.11,0.13,0.2\n0.01,0,0\n",
             box == 2 ? "/NODE\n20,-0.3,-0.2,-0.1\n21,0.3,-0.2,-0.1\n22,0.3,0.2,-0.1\n23,-0.3,0.2,-0.1\n24,-0.3,-0.2,0.0011\n"
                        "25,0.3,-0.2,0.0011\n26,0.3,0.2,0.0011\n27,-0.3,0.2,0.0011\n/GRNOD/NODE/8\ng2\n20,21,22,23,24,25,26,27\n"
                        "/SURF/SEG/40\nplate faces\n1,20,23,22,21\n2,24,25,26,27\n3,20,21,25,24\n4,21,22,26,25\n"
                        "5,22,23,27,26\n6,23,20,24,27\n"
             : box ? "/SURF/BOX/40\ntable\n2\n0.01,-0.02,-0.199\n0.4,0.3,0.2\n1,0.05,0.02\n-0.04,1,0.03\n"
                   : "/SURF/PLANE/40\nplate\n0,0,0.001\n0.05,-0.03,1\n2\n",
             "/FUNCT/1\nload\n-0.01,-3.1e3\n0,0\n0.0013,2.71e3\n0.0041,1.37e4\n0.0097,5.9e4\n"
             "/FUNCT/2\nunload\n0,0\n0.002,0\n0.006,5e3\n0.011,3.1e4\n"
             "/FUNCT/3\ndv\n-10,-41\n0,0\n0.37,5.3\n3.3,71\n/FUNCT/4\ndf\n0,1\n500,0.83\n9e4,0.61\n",
             fric ? "/INTER/TYPE6/1\nbox on plate\n30,40\n0.7,0.37,0.0011\n,,,5,,,1.9,0.61\n1,1,1.3,0.77\n"
                  : "/INTER/TYPE6/1\nbox on plate\n30,40\n,,0.0011\n,,,5,,,1.9,0.61\n1,1,1.3,0.77\n",
             "2,,7.3e6,0.83\n3.7,3,4,2.3\n",
             /* 2, 3: the viscous form (Iform 1), 3 with a filter (Ifiltr 3) */
             fric == 2   ? "/FRICTION/1\nviscous\n0,0,,1\n\n,0.37,0.8\n" RUN_TAIL
             : fric == 3 ? "/FRICTION/1\nviscous, filtered\n0,3,50,1\n\n,0.37,0.8\n" RUN_TAIL
             : fric == 4 ? "/FRICTION/1\nincremental, filtered\n0,3,50,2\n\n,0.37,0.8\n" RUN_TAIL
                         : RUN_TAIL);
}

/* That box on the plate in every mode, against central differences. */
static void seg_jacobian_check(int box, int fric)
{
    rc_error e;
    char deck[8192];
    seg_box_plate_deck(deck, sizeof deck, box, fric);
    rc_model *m = seg_compile(deck, &e);
    ENSURE(m != NULL);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    ENSURE(m->inter_pair[0] == (box == 2 ? RC_PAIR_SEG_SEG : box ? RC_PAIR_SEG_BOX : RC_PAIR_SEG_PLANE));
    ENSURE(fric < 2 || fric == 4 || (m->inter_fr[0].form == RC_FF_VISCOUS && (fric == 3) == (m->inter_fr[0].tau > 0)));
    ENSURE(fric != 4 || (m->inter_fr[0].form == RC_FF_INCREMENTAL && m->inter_fr[0].tau > 0 && m->inter_pst[0] == 6));
    rc_data *d = rc_data_new(m);
    const double *s = seg_state;
    double *y = two_body_state(m, s);
    y[m->inter_eadr[0] + m->inter_hidx[0]] = 731.0;
    y[m->inter_eadr[0] + m->inter_oidx[0]] = 3.7e-4;
    rc_inter_report r;
    rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
    ENSURE(r.p > 0);
    /* several nodes past the plate (the spread is exercised), at distinct depths */
    int npen = -1;
    if (!box) {
        double qa[4], qb[4], na = 0, nb = 0;
        for (int k = 0; k < 4; k++) {
            na += s[3 + k] * s[3 + k];
            nb += s[16 + k] * s[16 + k];
        }
        for (int k = 0; k < 4; k++) {
            qa[k] = s[3 + k] / sqrt(na);
            qb[k] = s[16 + k] / sqrt(nb);
        }
        const double nl[3] = {0.05 / sqrt(1.0034), -0.03 / sqrt(1.0034), 1.0 / sqrt(1.0034)}, pl[3] = {0, 0, 0.201};
        double ng[3], pg[3];
        rotate(qb, nl, ng);
        rotate(qb, pl, pg);
        npen = 0;
        for (int j = 0; j < m->surf_nadr[1]; j++) {
            double x[3];
            rotate(qa, m->surf_node + 3 * j, x);
            double dist = 0;
            for (int k = 0; k < 3; k++) dist += (x[k] + s[k] - pg[k] - s[13 + k]) * ng[k];
            npen += 0.0011 - dist - 3.7e-4 > 0;
        }
    }
    ENSURE(box || (npen >= 2 && npen < 8));
    int bad = 0, outside = 0, combos = 0;
    double maxerr = 0;
    const int modes[2] = {RC_MODE_CLOSED, RC_MODE_RELEASED};
    /* friction per contact point: all sticking, all slipping, alternating */
    ENSURE(!fric || m->inter_npt[0] == (box == 2 ? 16 : 8));
    for (int md = 0; md < 2; md++)
        for (int br = 0; br < 3; br++)
            for (int trk = 0; trk < 2; trk++)
                for (int sl = 0; sl < (fric ? 3 : 1); sl++) {
                    d->inter_mode[0] = modes[md];
                    d->inter_branch[0] = br;
                    d->inter_track[0] = trk;
                    for (int j = 0; j < m->inter_npt[0]; j++) d->pt_slip[j] = sl == 2 ? j % 2 : sl;
                    maxerr = fmax(maxerr, tu_jac_fd_error(m, d, 0.0, y, 1, &bad, &outside));
                    combos++;
                }
    /* stick/slip flips of a few points, each refreshed in place
     * (rc_jac_refresh_points) into values assembled whole once: they equal
     * a whole assembly in the new modes at the same state, flip after flip */
    double rworst = 0.0, rmoved = 0.0;
    int nref = 0;
    if (fric) {
        const int npt = m->inter_npt[0];
        double *val = calloc((size_t)m->nnz + 1, sizeof(double)), *ref = calloc((size_t)m->nnz + 1, sizeof(double));
        double *alt = calloc((size_t)m->nnz + 1, sizeof(double));
        int *old = calloc((size_t)npt, sizeof(int)), *ps = d->pt_slip + m->inter_pbase[0];
        d->inter_mode[0] = RC_MODE_CLOSED;
        d->inter_branch[0] = RC_BR_LOAD;
        d->inter_track[0] = 0;
        for (int j = 0; j < npt; j++) ps[j] = j % 3 == 0;
        ENSURE(rc_assemble_jac(m, d, 0.0, y, val) == 0);
        unsigned seed = 12345u;
        for (int it = 0; it < 60; it++) {
            ENSURE(rc_assemble_jac(m, d, 0.0, y, alt) == 0); /* the old modes, whole */
            memcpy(old, ps, (size_t)npt * sizeof(int));
            for (int f = 0; f < 1 + it % 3; f++) {
                seed = seed * 1103515245u + 12345u;
                const int j = (int)((seed >> 8) % (unsigned)npt);
                ps[j] = !ps[j];
            }
            int nflip = 0;
            for (int j = 0; j < npt; j++) nflip += ps[j] != old[j];
            const int st = rc_jac_refresh_points(m, d, 0, old, y, val);
            ENSURE(st == (nflip > 0 && 2 * nflip >= npt ? -1 : 0));
            ENSURE(rc_assemble_jac(m, d, 0.0, y, ref) == 0); /* the new modes, whole */
            double scale = 0.0, diff = 0.0, mv = 0.0;
            for (int64_t k = 0; k < m->nnz; k++) scale = fmax(scale, fabs(ref[k]));
            for (int64_t k = 0; k < m->nnz; k++) {
                diff = fmax(diff, fabs(val[k] - ref[k]) / scale);
                mv = fmax(mv, fabs(alt[k] - ref[k]) / scale);
            }
            if (st) {
                memcpy(val, ref, (size_t)m->nnz * sizeof(double));
                continue;
            }
            rworst = fmax(rworst, diff);
            if (nflip > 0) rmoved = fmax(rmoved, mv);
            nref += nflip > 0;
        }
        free(old);
        free(val);
        free(ref);
        free(alt);
        printf("    refresh in place after %d flips of 1 to 3 of %d points: max |refreshed - whole| / max|J| = %.2e "
               "(largest change of a value %.2e)\n", nref, npt, rworst, rmoved);
        ENSURE(nref > 20);
        ENSURE(rworst < 1e-12);
        ENSURE(rmoved > 1e-6);
    }
    /* sliding points whose states are of the size of the slip band or
     * rounding (a point that lands with the state it relaxed to, a state an
     * iteration put through zero): the slip law's force and rates are smooth
     * functions of the state there (before, written with e = F_t/|F_t|,
     * their derivatives were of size 1/|F_t|: 1e20 where the differences
     * gave 1e9) */
    if (fric == 1 && box == 0) {
        const double fb = m->inter_fr[0].fband;
        const int npt = m->inter_npt[0], ps = m->inter_pst[0];
        /* against differences where the step (1e-7 N) does not cross F_t = 0
         * (|F_t| has a kink there, bounded); at 1e-9 bands, the largest
         * entry of the states' columns against that at 0.3 bands */
        const double sizes[4] = {0.02, 0.3, 3.0, 1e-9};
        double sworst = 0.0, jmax[4] = {0, 0, 0, 0};
        int sbad = 0, sout = 0;
        double *val = calloc((size_t)m->nnz + 1, sizeof(double));
        d->inter_mode[0] = RC_MODE_CLOSED;
        d->inter_branch[0] = RC_BR_LOAD;
        d->inter_track[0] = 0;
        const int c0 = m->inter_eadr[0] + m->inter_ns[0];
        double *st = y + c0;
        for (int k = 0; k < 4; k++) {
            for (int j = 0; j < npt; j++) {
                d->pt_slip[m->inter_pbase[0] + j] = 1;
                const double a = 0.7 * j + 0.3 * k, dir[3] = {cos(a), sin(a), 0.2 * sin(3.0 * a)};
                for (int c = 0; c < 3; c++) st[ps * j + c] = sizes[k] * fb * dir[c];
            }
            if (k < 3) sworst = fmax(sworst, tu_jac_fd_error(m, d, 0.0, y, 1, &sbad, &sout));
            ENSURE(rc_assemble_jac(m, d, 0.0, y, val) == 0);
            for (int col = c0; col < c0 + ps * npt; col++)
                for (int64_t q = m->jac_colptr[col]; q < m->jac_colptr[col + 1]; q++) jmax[k] = fmax(jmax[k], fabs(val[q]));
        }
        free(val);
        for (int j = 0; j < npt * ps; j++) st[j] = 0.0;
        printf("    sliding points with states of 0.02, 0.3 and 3 slip bands (%.3g N): max scaled |J - FD| = %.2e; largest "
               "entry of their columns at 1e-9 bands %.3g, at 0.3 bands %.3g\n", fb, sworst, jmax[3], jmax[1]);
        ENSURE(fb > 1e-5); /* the differences' step on these states, 1e-7 N, stays within 0.02 bands */
        ENSURE(sbad == 0);
        ENSURE(sout == 0);
        ENSURE(jmax[3] < 10.0 * jmax[1]);
    }
    const char *fname[5] = {"", " with friction per point", " with viscous friction per point",
                            " with filtered viscous friction per point", " with filtered incremental friction per point"};
    printf("    %s%s jacobian: P = %.3g m (%d nodes past the plate; -1: not counted), %d states, %lld nonzeros, %d mode combinations, max scaled |J - FD| "
           "= %.2e\n", box == 2 ? "segments-segments" : box ? "segments-box" : "segments-plane", fname[fric], r.p, npen, m->ny, (long long)m->nnz, combos, maxerr);
    ENSURE(bad == 0);
    ENSURE(outside == 0);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

static void test_seg_jacobian_matches_finite_differences(void) { seg_jacobian_check(0, 0); }
static void test_seg_box_jacobian_matches_finite_differences(void) { seg_jacobian_check(1, 0); }
static void test_seg_friction_jacobian_matches_finite_differences(void) { seg_jacobian_check(0, 1); }
static void test_seg_box_friction_jacobian_matches_finite_differences(void) { seg_jacobian_check(1, 1); }
static void test_seg_seg_jacobian_matches_finite_differences(void) { seg_jacobian_check(2, 0); }
static void test_seg_seg_friction_jacobian_matches_finite_differences(void) { seg_jacobian_check(2, 1); }
static void test_seg_viscous_friction_jacobian(void)
{
    seg_jacobian_check(0, 2);
    seg_jacobian_check(2, 3);
}
/* the incremental form with a filter: 6 states per point */
static void test_seg_filtered_incremental_jacobian(void)
{
    seg_jacobian_check(0, 4);
    seg_jacobian_check(1, 4);
    seg_jacobian_check(2, 4);
}

/* The power law on a segment surface (the box on a tilted plate carried by
 * a moving body): F = K P^m1 at the deepest node, its damping C v^m2 P^m3 at
 * the penetration-weighted rate, RDF; closed and released, both branches,
 * against central differences. */
static void test_seg_power_jacobian_matches_finite_differences(void)
{
    rc_error e;
    rc_model *m = seg_compile(BOX_NODES BOX_BODY BOX_SEGS
                              "/NODE\n2,0,0,-0.2\n/RBODY/2\nplate\n2,,,,5.0\n0.11,0.13,0.2\n0.01,0,0\n"
                              "/SURF/PLANE/40\nplate\n0,0,0.001\n0.05,-0.03,1\n2\n"
                              "/INTER/POWER/1\np\n30,40,0,0,0,1\n1e9,1.5,3e5,1.2,0.8\n0.4\n" RUN_TAIL,
                              &e);
    ENSURE(m != NULL);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    ENSURE(m->inter_pair[0] == RC_PAIR_SEG_PLANE && m->inter_law[0] == RC_LAW_POWER);
    rc_data *d = rc_data_new(m);
    const double *s = seg_state;
    double *y = two_body_state(m, s);
    rc_inter_report r;
    rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
    ENSURE(r.p > 0);
    int bad = 0, outside = 0, combos = 0;
    double maxerr = 0;
    const int modes[2] = {RC_MODE_CLOSED, RC_MODE_RELEASED}, brs[2] = {RC_BR_LOAD, RC_BR_UNLOAD};
    for (int md = 0; md < 2; md++)
        for (int br = 0; br < 2; br++) {
            d->inter_mode[0] = modes[md];
            d->inter_branch[0] = brs[br];
            maxerr = fmax(maxerr, tu_jac_fd_error(m, d, 0.0, y, 1, &bad, &outside));
            combos++;
        }
    printf("    segments-plane power law jacobian: P = %.3g m, F = %.4g N, %d states, %d mode combinations, max scaled "
           "|J - FD| = %.2e\n", r.p, r.fn, m->ny, combos, maxerr);
    ENSURE(bad == 0);
    ENSURE(outside == 0);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

/* step5 friction per node (the power law on the box against a moving,
 * tilted plate): each node's law at its share w_j of F_n and of the cap;
 * nodes uncapped, capped and mixed, against central differences. */
static void test_seg_step5_jacobian(void)
{
    rc_error e;
    rc_model *m = seg_compile(BOX_NODES BOX_BODY BOX_SEGS
                              "/NODE\n2,0,0,-0.2\n/RBODY/2\nplate\n2,,,,5.0\n0.11,0.13,0.2\n0.01,0,0\n"
                              "/SURF/PLANE/40\nplate\n0,0,0.001\n0.05,-0.03,1\n2\n"
                              "/INTER/POWER/1\np\n30,40,0,0,0,1\n1e9,1.5,3e5,1.2,0.8\n0.4\n0.5,0.7,0.3,2.9,40\n"
                              RUN_TAIL,
                              &e);
    ENSURE(m != NULL);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    ENSURE(m->inter_npt[0] == 8 && m->inter_fr[0].kind == RC_FK_STEP5);
    rc_data *d = rc_data_new(m);
    const double *s = seg_state;
    double *y = two_body_state(m, s);
    rc_inter_report r;
    rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
    ENSURE(r.p > 0);
    int bad = 0, outside = 0, npen = 0;
    double maxerr = 0;
    d->inter_mode[0] = RC_MODE_CLOSED;
    d->inter_branch[0] = RC_BR_LOAD;
    int *ps = d->pt_slip + m->inter_pbase[0];
    for (int pat = 0; pat < 3; pat++) {
        for (int j = 0; j < 8; j++) ps[j] = pat == 0 ? 0 : pat == 1 ? 1 : j % 2;
        maxerr = fmax(maxerr, tu_jac_fd_error(m, d, 0.0, y, 1, &bad, &outside));
    }
    /* the points' forces add up to the interface's friction; each point's
     * law force is its share of the whole-contact law (uncapped) */
    double *out = calloc(RC_PT_OUT * 8, sizeof(double));
    for (int j = 0; j < 8; j++) ps[j] = 0;
    rc_points_eval(m, d, 0, NULL, 0.0, y, out);
    double wsum = 0;
    for (int j = 0; j < 8; j++) {
        wsum += out[RC_PT_OUT * j + 4];
        npen += out[RC_PT_OUT * j + 4] > 0;
    }
    ENSURE(npen >= 2 && fabs(wsum - 1.0) < 1e-12);
    printf("    segments-plane step5 friction per node: %d nodes in contact, F_n = %.4g N, max scaled |J - FD| = %.2e "
           "(uncapped, capped, mixed)\n", npen, r.fn, maxerr);
    ENSURE(bad == 0);
    ENSURE(outside == 0);
    free(out);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

/* IRS/IRm: the box (surf_ID1, body 1) resting 1.1 mm into the top face of
 * a meshed plate (surf_ID2, body 2): IRm = 1 reverses the plate's normals
 * (the side above the plate is then inside it: the box's top nodes, 60 mm
 * up, are 58.9 mm in), IRS = 1 the box's (which its bottom nodes do not
 * use), 2 keeps /SURF/SEG as written. */
static void test_seg_orientation_irs_irm(void)
{
    const char *irs[4] = {"", ",1", ",,1", ",2,2"};
    const double expect[4] = {0.0011, 0.0011, 0.0589, 0.0011};
    for (int k = 0; k < 4; k++) {
        char deck[4096];
        snprintf(deck, sizeof deck, "%s%s%s", BOX_NODES BOX_BODY BOX_SEGS,
                 "/NODE\n2,0,0,-0.05\n20,-0.3,-0.2,-0.1\n21,0.3,-0.2,-0.1\n22,0.3,0.2,-0.1\n23,-0.3,0.2,-0.1\n"
                 "24,-0.3,-0.2,0.0011\n25,0.3,-0.2,0.0011\n26,0.3,0.2,0.0011\n27,-0.3,0.2,0.0011\n/GRNOD/NODE/8\ng2\n"
                 "20,21,22,23,24,25,26,27\n/RBODY/2\nplate\n2,,,,5.0,8\n0.11,0.13,0.2\n0.01,0,0\n"
                 "/SURF/SEG/40\nplate faces\n1,20,23,22,21\n2,24,25,26,27\n3,20,21,25,24\n4,21,22,26,25\n"
                 "5,22,23,27,26\n6,23,20,24,27\n" LINEAR "/INTER/TYPE6/1\nbox on plate\n30,40\n\n",
                 irs[k]);
        strncat(deck, "\n1\n\n\n" RUN_TAIL, sizeof deck - strlen(deck) - 1);
        rc_error e;
        rc_model *m = seg_compile(deck, &e);
        ENSURE(m != NULL);
        if (!m) {
            fprintf(stderr, "  %s\n", e.msg);
            continue;
        }
        double *y = calloc((size_t)m->ny, sizeof(double));
        rc_initial_state(m, y);
        rc_inter_report r;
        rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
        printf("    IRS/IRm line \"%s\": P = %.6g m (expected %.6g)\n", irs[k], r.p, expect[k]);
        ENSURE_NEAR(r.p, expect[k], 1e-12, 0);
        free(y);
        rc_model_free(m);
    }
}

/* A roller (cylinder on body 2, axis y, moving and turning) on the top face
 * of the meshed box (body 1, moving), TYPE6 with a nonlinear load curve,
 * Visc and Fric: the plane of the segment under the roller's centre; closed
 * in stick and slip, released, against central differences. */
static void test_seg_cyl_jacobian_matches_finite_differences(void)
{
    rc_error e;
    rc_model *m = seg_compile(BOX_NODES BOX_BODY BOX_SEGS
                              "/NODE\n2,0.01,0.003,0.0785\n/RBODY/2\nroller\n2,,,,0.7\n0.0001,0.00002,0.0001\n0,0,0\n"
                              "/SURF/CYL/40\nroller\n2\n0.01,0.003,0.0785\n0.02,1,0.01\n0.02,0.03\n"
                              "/FUNCT/1\nload\n0,0\n0.001,800\n0.004,9000\n"
                              "/INTER/TYPE6/1\nroller on box\n40,30\n0.2,0.3\n\n1\n\n310\n" RUN_TAIL,
                              &e);
    ENSURE(m != NULL);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    ENSURE(m->inter_pair[0] == RC_PAIR_CYL_SEG);
    rc_data *d = rc_data_new(m);
    const double s[26] = {0.0003, -0.0002, 0.0301, 0.999, 0.011, -0.013, 0.007, 0.21, -0.13, -0.17, 1.1, -0.3, 0.7,
                          0.0102, 0.0027, 0.0783, 0.99, -0.005, 0.009, 0.003, -0.41, 0.17, 0.053, -1.9, 13.7, 2.2};
    double *y = two_body_state(m, s);
    rc_inter_report r;
    rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
    ENSURE(r.p > 0 && r.p < 0.004);
    int bad = 0, outside = 0, combos = 0;
    double maxerr = 0;
    const int modes[2] = {RC_MODE_CLOSED, RC_MODE_RELEASED};
    for (int md = 0; md < 2; md++)
        for (int sl = 0; sl < 2; sl++) {
            d->inter_mode[0] = modes[md];
            d->inter_slip[0] = sl;
            maxerr = fmax(maxerr, tu_jac_fd_error(m, d, 0.0, y, 1, &bad, &outside));
            combos++;
        }
    printf("    cylinder-segments jacobian: P = %.3g m, normal %.3f %.3f %.3f, %d states, %lld nonzeros, %d mode "
           "combinations, max scaled |J - FD| = %.2e\n",
           r.p, r.normal[0], r.normal[1], r.normal[2], m->ny, (long long)m->nnz, combos, maxerr);
    ENSURE(bad == 0);
    ENSURE(outside == 0);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

/* The sphere (body 1, off its centre of mass) and the V-shaped valley of
 * triangles and quadrilaterals on body 2 of the sphere-segment tests, with
 * the load curve 1. */
#define VALLEY_DECK_HEAD                                                                                        \
    "/NODE\n1,0.001,-0.002,0.05\n2,0,0,-0.2\n"                                                                \
    "10,-0.2,-0.2,0.06\n11,0.2,-0.2,0.06\n12,0.2,0,0\n13,-0.2,0,0\n14,0.2,0.2,0.06\n"                            \
    "15,-0.2,0.2,0.06\n16,0,0.2,0.06\n"                                                                        \
    "/GRNOD/NODE/8\nplate\n10,11,12,13,14,15,16\n"                                                          \
    "/RBODY/1\nball\n1,,,,0.731\n2.1e-3,1.7e-3,2.9e-3\n1.3e-4,-2.2e-4,0.7e-4\n"                                \
    "/RBODY/2\nvalley\n2,,,,5.0,8\n0.11,0.13,0.2\n0.01,0,0\n"                                                  \
    "/SURF/ELLIPS/20\nball\n0,2,1\n0.0017,-0.0011,0.0521\n0.05,0.05,0.05\n"                                    \
    "/SURF/SEG/40\nvalley\n1,10,11,12,13\n2,13,12,16\n3,12,14,16\n4,13,16,15\n"                                \
    "/FUNCT/1\nload\n-0.01,-3.1e3\n0,0\n0.0013,2.71e3\n0.0041,1.37e4\n0.0097,5.9e4\n"

/* A sphere (body 1, off its centre of mass) in a V-shaped valley of
 * triangles and quadrilaterals carried by a moving body 2: two face points
 * past the surface, every mode, against central differences; and the
 * force on the sphere along the sum of the two shared normal forces. */
static void test_seg_sphere_jacobian_matches_finite_differences(void)
{
    rc_error e;
    rc_model *m = seg_compile(VALLEY_DECK_HEAD
                              "/FUNCT/2\nunload\n0,0\n0.002,0\n0.006,5e3\n0.011,3.1e4\n"
                              "/FUNCT/3\ndv\n-10,-41\n0,0\n0.37,5.3\n3.3,71\n/FUNCT/4\ndf\n0,1\n500,0.83\n9e4,0.61\n"
                              "/INTER/TYPE6/1\nball in the valley\n40,20\n,,0.0011\n,,,5,,,1.9,0.61\n1,1,1.3,0.77\n"
                              "2,,7.3e6,0.83\n3.7,3,4,2.3\n" RUN_TAIL,
                              &e);
    ENSURE(m != NULL);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    ENSURE(m->inter_pair[0] == RC_PAIR_SPHERE_SEG);
    rc_data *d = rc_data_new(m);
    const double s[26] = {0.0011, -0.0023, 0.0497, 0.99, 0.011, -0.013, 0.007, 0.31, -0.23, -0.17, 3.1, -2.3, 4.7,
                          0.0021, 0.0007, -0.2003, 0.99, -0.005, 0.009, 0.003, -0.41, 0.17, 0.053, -1.9, 0.7, 2.2};
    double *y = two_body_state(m, s);
    y[m->inter_eadr[0] + m->inter_hidx[0]] = 731.0;
    y[m->inter_eadr[0] + m->inter_oidx[0]] = 3.7e-4;
    rc_inter_report r;
    rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
    ENSURE(r.p > 0);
    int bad = 0, outside = 0, combos = 0;
    double maxerr = 0;
    const int modes[2] = {RC_MODE_CLOSED, RC_MODE_RELEASED};
    for (int md = 0; md < 2; md++)
        for (int br = 0; br < 3; br++)
            for (int trk = 0; trk < 2; trk++) {
                d->inter_mode[0] = modes[md];
                d->inter_branch[0] = br;
                d->inter_track[0] = trk;
                maxerr = fmax(maxerr, tu_jac_fd_error(m, d, 0.0, y, 1, &bad, &outside));
                combos++;
            }
    printf("    sphere-segments jacobian: P = %.3g m, %d states, %lld nonzeros, %d mode combinations, max scaled "
           "|J - FD| = %.2e\n", r.p, m->ny, (long long)m->nnz, combos, maxerr);
    ENSURE(bad == 0);
    ENSURE(outside == 0);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

/* A sphere with friction (TYPE6 Fric, the interface's tangential state)
 * against the valley of the previous test: its deepest point a face point
 * (in the valley), an edge point (beyond the valley's outer edge between
 * nodes 15 and 16) and a node point (beyond node 15), each closed in stick
 * and slip, against central differences (the normal's rate of each kind). */
static void test_seg_sphere_friction_jacobian(void)
{
    rc_error e;
    rc_model *m = seg_compile(VALLEY_DECK_HEAD
                              "/INTER/TYPE6/1\nball in the valley\n40,20\n,0.3,0.0011\n\n1\n\n730\n" RUN_TAIL,
                              &e);
    ENSURE(m != NULL);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    ENSURE(m->inter_pair[0] == RC_PAIR_SPHERE_SEG && m->inter_fr[0].tidx >= 0);
    rc_data *d = rc_data_new(m);
    /* body 1 positions: the sphere's centre is 0.0007, 0.0009, 0.0021 from it */
    const double at[3][3] = {{0.0011, -0.0023, 0.0497}, {-0.1, 0.2307, 0.0934}, {-0.2229, 0.2257, 0.0884}};
    const char *what[3] = {"face", "edge", "node"};
    int bad = 0, outside = 0, combos = 0;
    double maxerr = 0;
    for (int g = 0; g < 3; g++) {
        double s[26] = {0, 0, 0, 0.99, 0.011, -0.013, 0.007, 0.31, -0.23, -0.17, 3.1, -2.3, 4.7,
                        0.0021, 0.0007, -0.2003, 1.0, -0.001, 0.002, 0.001, -0.41, 0.17, 0.053, -1.9, 0.7, 2.2};
        for (int k = 0; k < 3; k++) s[k] = at[g][k];
        double *y = two_body_state(m, s);
        rc_inter_report r;
        rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
        ENSURE(r.p > 0);
        double err = 0;
        for (int sl = 0; sl < 2; sl++) {
            d->inter_mode[0] = RC_MODE_CLOSED;
            d->inter_slip[0] = sl;
            err = fmax(err, tu_jac_fd_error(m, d, 0.0, y, 1, &bad, &outside));
            combos++;
        }
        printf("    sphere-segments friction jacobian, %s point: P = %.3g m, normal %.3f %.3f %.3f, max scaled "
               "|J - FD| = %.2e\n", what[g], r.p, r.normal[0], r.normal[1], r.normal[2], err);
        maxerr = fmax(maxerr, err);
        free(y);
    }
    printf("    sphere-segments friction jacobian: %d states, %d combinations, max scaled |J - FD| = %.2e\n", m->ny,
           combos, maxerr);
    ENSURE(bad == 0);
    ENSURE(outside == 0);
    rc_data_free(d);
    rc_model_free(m);
}

/* A sphere with step5 friction of the power law (the interface's, at the
 * deepest kept point with the whole normal force) against the valley: a
 * face, an edge and a node point, uncapped and capped, against central
 * differences; v_s and v_d span the sliding speeds of the states (the
 * inner polynomial and the step). */
static void test_seg_sphere_step5_jacobian(void)
{
    rc_error e;
    rc_model *m = seg_compile(VALLEY_DECK_HEAD
                              "/INTER/POWER/1\nball in the valley\n40,20\n3.7e7,1.3,2.1e4,1.1,1.2\n\n"
                              "0.4,0.9,0.25,4.5,31\n" RUN_TAIL,
                              &e);
    ENSURE(m != NULL);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    ENSURE(m->inter_pair[0] == RC_PAIR_SPHERE_SEG && m->inter_fr[0].kind == RC_FK_STEP5);
    rc_data *d = rc_data_new(m);
    const double at[3][3] = {{0.0011, -0.0023, 0.0497}, {-0.1, 0.2307, 0.0934}, {-0.2229, 0.2257, 0.0884}};
    const char *what[3] = {"face", "edge", "node"};
    int bad = 0, outside = 0, combos = 0;
    double maxerr = 0;
    for (int g = 0; g < 3; g++)
        for (int slow = 0; slow < 2; slow++) {
            double s[26] = {0, 0, 0, 0.99, 0.011, -0.013, 0.007, 0.31, -0.23, -0.17, 3.1, -2.3, 4.7,
                            0.0021, 0.0007, -0.2003, 1.0, -0.001, 0.002, 0.001, -0.41, 0.17, 0.053, -1.9, 0.7, 2.2};
            for (int k = 0; k < 3; k++) s[k] = at[g][k];
            if (slow) /* a slow sliding (below v_s): the ball moving with the valley, spinning slowly */
                for (int k = 0; k < 6; k++) s[7 + k] = (k < 3 ? s[20 + k] : 0.1 * s[20 + k]);
            double *y = two_body_state(m, s);
            rc_inter_report r;
            rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
            ENSURE(r.p > 0);
            double err = 0;
            for (int sl = 0; sl < 2; sl++)
                for (int br = 0; br < 2; br++) {
                    d->inter_mode[0] = RC_MODE_CLOSED;
                    d->inter_branch[0] = br ? RC_BR_UNLOAD : RC_BR_LOAD;
                    d->inter_slip[0] = sl;
                    err = fmax(err, tu_jac_fd_error(m, d, 0.0, y, 1, &bad, &outside));
                    combos++;
                }
            printf("    sphere-segments step5 jacobian, %s point: P = %.3g m, F_n = %.4g N, slip speed %.3g m/s, max "
                   "scaled |J - FD| = %.2e\n", what[g], r.p, r.fn, r.vslip, err);
            maxerr = fmax(maxerr, err);
            free(y);
        }
    printf("    sphere-segments step5 jacobian: %d states, %d combinations, max scaled |J - FD| = %.2e\n", m->ny, combos,
           maxerr);
    ENSURE(bad == 0);
    ENSURE(outside == 0);
    rc_data_free(d);
    rc_model_free(m);
}

/* A sphere at rest in a symmetric V valley (fixed): two face points at the
 * same depth share F = k P equally (the law at P_e = P); the force on the sphere is vertical,
 * 2 (F / 2) cos(alpha) with alpha the slope angle, and without moment. */
static void test_seg_sphere_valley_forces(void)
{
    rc_error e;
    rc_model *m = seg_compile("/NODE\n1,0,0,0.0515\n"
                              "10,-0.2,-0.2,0.06\n11,0.2,-0.2,0.06\n12,0.2,0,0\n13,-0.2,0,0\n14,0.2,0.2,0.06\n"
                              "15,-0.2,0.2,0.06\n"
                              "/RBODY/1\nball\n1,,,,2.0\n0.002,0.002,0.002\n0,0,0\n"
                              "/SURF/ELLIPS/20\nball\n0,2,1\n0,0,0.0515\n0.05,0.05,0.05\n"
                              "/SURF/SEG/40\nvalley\n1,10,11,12,13\n2,13,12,14,15\n" LINEAR
                              "/INTER/TYPE6/1\nball in the valley\n20,40\n\n\n1\n\n\n" RUN_TAIL,
                              &e);
    ENSURE(m != NULL);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    ENSURE(m->surf_body[1] == -1); /* nodes in no body: fixed in space */
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double)), *yd = calloc((size_t)m->ny, sizeof(double));
    rc_initial_state(m, y);
    d->inter_mode[0] = RC_MODE_CLOSED;
    const double slope = 0.06 / 0.2, ca = 1.0 / sqrt(1 + slope * slope);
    const double P = 0.05 - 0.0515 * ca, F = 1e6 * P;
    y[m->inter_eadr[0] + m->inter_peidx[0]] = P; /* the law's P_e = P */
    rc_assemble_rhs(m, d, 0.0, y, yd);
    const double *acc = yd + m->body_yadr[0] + 7;
    ENSURE_NEAR(acc[2], F * ca / 2.0, 1e-12, 0);
    ENSURE_NEAR(acc[0], 0.0, 0, 1e-9);
    ENSURE_NEAR(acc[1], 0.0, 0, 1e-9);
    for (int k = 3; k < 6; k++) ENSURE_NEAR(acc[k], 0.0, 0, 1e-9);
    rc_inter_report r;
    rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
    ENSURE_NEAR(r.p, P, 1e-12, 0);
    printf("    sphere in a V valley: P = %.6g m, vertical acceleration %.9g m/s^2 (F cos(alpha) / m = %.9g)\n", r.p,
           acc[2], F * ca / 2.0);
    free(y);
    free(yd);
    rc_data_free(d);
    rc_model_free(m);
}

/* ---- analytic boxes against a plane or a box (their corners) ---------- */
/* Body 1: a box 0.2 x 0.1 x 0.06 (half-sizes 0.1, 0.05, 0.03) at (0, 0, 0.03),
 * its axes slightly turned; body 2 at (0, 0, -0.2) carrying the other
 * surface (40). */
#define ABOX_BODY "/NODE\n1,0,0,0.03\n/RBODY/1\nbox\n1,,,,2.0\n0.0023,0.0071,0.0083\n0.0001,0.0002,-0.0001\n" \
                  "/SURF/BOX/30\nbox\n1\n0,0,0.03\n0.1,0.05,0.03\n1,0.02,-0.01\n-0.02,1,0.015\n"
#define ABOX_BODY2 "/NODE\n2,0,0,-0.2\n/RBODY/2\nplate\n2,,,,5.0\n0.11,0.13,0.2\n0.01,0,0\n"

/* The corners and faces of a box used against a plane: 8 nodes, 6
 * quadrilaterals whose normals (x2 - x0) x (x3 - x1) point out of the box
 * along its axes, the box's kind kept (a sphere still meets the analytic
 * box), either order on the card, and the listing's name. */
static void test_box_pairs_corners(void)
{
    rc_error e;
    rc_model *m = seg_compile(ABOX_BODY ABOX_BODY2 "/SURF/PLANE/40\nplate\n0,0,0.001\n0.05,-0.03,1\n2\n"
                              "/NODE\n3,0.5,0,0.2\n/RBODY/3\nball\n3,,,,1.0\n0.001,0.001,0.001\n0,0,0\n"
                              "/SURF/ELLIPS/50\nball\n0,2,3\n0.5,0,0.2\n0.05,0.05,0.05\n" LINEAR
                              "/INTER/TYPE6/1\nbox first\n30,40\n\n\n1\n\n\n"
                              "/INTER/TYPE6/2\nplane first\n40,30\n\n\n1\n\n\n"
                              "/INTER/TYPE6/3\nsphere on the box\n50,30\n\n\n1\n\n\n" RUN_TAIL,
                              &e);
    ENSURE(m != NULL);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    const int sb = 0; /* the box: first surface of the deck */
    ENSURE(m->surf_kind[sb] == RC_SURF_BOX);
    ENSURE(m->surf_nadr[sb + 1] - m->surf_nadr[sb] == 8 && m->surf_sadr[sb + 1] - m->surf_sadr[sb] == 6);
    for (int i = 0; i < 2; i++) ENSURE(m->inter_pair[i] == RC_PAIR_SEG_PLANE && m->inter_sa[i] == sb);
    ENSURE(m->inter_pair[2] == RC_PAIR_SPHERE_BOX && m->inter_sb[2] == sb);
    ENSURE(strstr(rc_geom_inter_pair_name(m, 0), "box-plane") != NULL);
    const double *c = m->surf_p + 3 * sb, *ext = m->surf_ext + RC_SURF_NEXT * sb;
    int bad = 0, axis_hit[6] = {0, 0, 0, 0, 0, 0};
    for (int q = 0; q < 6; q++) {
        const int *v = m->surf_seg + 4 * (m->surf_sadr[sb] + q);
        const double *x[4];
        for (int j = 0; j < 4; j++) x[j] = m->surf_node + 3 * (m->surf_nadr[sb] + v[j]);
        double a[3], b[3], n[3], fc[3];
        for (int k = 0; k < 3; k++) {
            a[k] = x[2][k] - x[0][k];
            b[k] = x[3][k] - x[1][k];
            fc[k] = 0.25 * (x[0][k] + x[1][k] + x[2][k] + x[3][k]) - c[k];
        }
        n[0] = a[1] * b[2] - a[2] * b[1];
        n[1] = a[2] * b[0] - a[0] * b[2];
        n[2] = a[0] * b[1] - a[1] * b[0];
        const double nn = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        /* the face centre lies at a half-size along its own axis, the
         * normal is that axis, outward */
        for (int ax = 0; ax < 3; ax++) {
            const double *u = ext + 3 + 3 * ax;
            const double cu = (n[0] * u[0] + n[1] * u[1] + n[2] * u[2]) / nn;
            const double du = fc[0] * u[0] + fc[1] * u[1] + fc[2] * u[2];
            if (fabs(fabs(cu) - 1.0) < 1e-12) {
                bad += fabs(du - cu * ext[ax]) > 1e-12;
                axis_hit[2 * ax + (cu > 0)]++;
            }
        }
    }
    for (int k = 0; k < 6; k++) bad += axis_hit[k] != 1;
    ENSURE(bad == 0);
    printf("    box 0.2 x 0.1 x 0.06: 8 corners, 6 faces, each normal along its axis, outward; pair \"%s\"\n",
           rc_geom_inter_pair_name(m, 0));
    rc_model_free(m);
}

/* Jacobians of the box pairs against central differences: kind 0 the box
 * against a tilted plane carried by body 2; 1 against a larger tilted box
 * on body 2 (the upper box's corners act); 2 against a smaller one (the
 * lower box's corners act on the upper box's bottom face); 3 against a
 * bar laid across it (no corner of either box over the other: the pairs of
 * crossing edges act); fric 0 none, 1
 * TYPE6 friction per corner, 4 a /FRICTION card (incremental, filtered),
 * 5 /INTER/POWER with step5 friction; every mode. */
static void box_pair_jacobian_check(int kind, int fric)
{
    rc_error e;
    char deck[8192];
    const char *other = kind == 0 ? "/SURF/PLANE/40\nplate\n0,0,0.001\n0.05,-0.03,1\n2\n"
                        : kind == 1 ? "/SURF/BOX/40\ntable\n2\n0.01,-0.02,-0.199\n0.4,0.3,0.2\n1,0.05,0.02\n-0.04,1,0.03\n"
                        : kind == 2 ? "/SURF/BOX/40\npost\n2\n0.01,-0.02,-0.199\n0.06,0.035,0.2\n1,0.05,0.02\n-0.04,1,0.03\n"
                                    : "/SURF/BOX/40\nbar\n2\n0.01,-0.02,-0.199\n0.03,0.3,0.2\n1,0.05,0.02\n-0.04,1,0.03\n";
    const char *inter =
        fric == 5 ? "/INTER/POWER/1\np\n30,40,0,0,0,1\n1e9,1.5,3e5,1.2,0.8\n0.4\n0.5,0.05,0.3,0.2,40\n"
        : fric == 1 ? "/INTER/TYPE6/1\nbox pair\n30,40\n0.7,0.37,0.0011\n,,,5,,,1.9,0.61\n1,1,1.3,0.77\n2,,7.3e6,0.83\n3.7,3,4,2.3\n"
                    : "/INTER/TYPE6/1\nbox pair\n40,30\n,,0.0011\n,,,5,,,1.9,0.61\n1,1,1.3,0.77\n2,,7.3e6,0.83\n3.7,3,4,2.3\n";
    snprintf(deck, sizeof deck, "%s%s%s%s%s%s", ABOX_BODY, ABOX_BODY2, other,
             "/FUNCT/1\nload\n-0.01,-3.1e3\n0,0\n0.0013,2.71e3\n0.0041,1.37e4\n0.0097,5.9e4\n"
             "/FUNCT/2\nunload\n0,0\n0.002,0\n0.006,5e3\n0.011,3.1e4\n"
             "/FUNCT/3\ndv\n-10,-41\n0,0\n0.37,5.3\n3.3,71\n/FUNCT/4\ndf\n0,1\n500,0.83\n9e4,0.61\n",
             inter, fric == 4 ? "/FRICTION/1\nincremental, filtered\n0,3,50,2\n\n,0.37,0.8\n" RUN_TAIL : RUN_TAIL);
    rc_model *m = seg_compile(deck, &e);
    ENSURE(m != NULL);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    ENSURE(m->inter_pair[0] == (kind ? RC_PAIR_SEG_SEG : RC_PAIR_SEG_PLANE));
    ENSURE(!fric || m->inter_npt[0] == (kind ? 16 + RC_BOX_EDGE_PAIRS : 8));
    rc_data *d = rc_data_new(m);
    const double *s = seg_state;
    double *y = two_body_state(m, s);
    if (m->inter_hidx[0] >= 0) y[m->inter_eadr[0] + m->inter_hidx[0]] = 731.0;
    if (m->inter_oidx[0] >= 0) y[m->inter_eadr[0] + m->inter_oidx[0]] = 3.7e-4;
    rc_inter_report r;
    rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
    ENSURE(r.p > 0);
    /* the deepest point is a corner of the surface expected: kind 2 one of
     * the lower box (|x| about 0.05), kind 3 a crossing of two edges (on an
     * edge of the upper box, |y| about 0.05, within the bar's width, |x| <
     * 0.045: neither box has a corner there), else one of the upper box
     * (0.1) */
    if (kind == 3) ENSURE(fabs(r.point[0]) < 0.045 && fabs(fabs(r.point[1]) - 0.05) < 0.01);
    else ENSURE(kind == 2 ? fabs(r.point[0]) < 0.075 : fabs(r.point[0]) > 0.075);
    int bad = 0, outside = 0, combos = 0;
    double maxerr = 0;
    const int modes[2] = {RC_MODE_CLOSED, RC_MODE_RELEASED};
    const int nbr = fric == 5 ? 2 : 3, ntrk = fric == 5 ? 1 : 2;
    for (int md = 0; md < 2; md++)
        for (int br = 0; br < nbr; br++)
            for (int trk = 0; trk < ntrk; trk++)
                for (int sl = 0; sl < (fric ? 3 : 1); sl++) {
                    d->inter_mode[0] = modes[md];
                    d->inter_branch[0] = fric == 5 && br == 1 ? RC_BR_UNLOAD : br;
                    d->inter_track[0] = trk;
                    for (int j = 0; j < m->inter_npt[0]; j++) d->pt_slip[j] = sl == 2 ? j % 2 : sl;
                    maxerr = fmax(maxerr, tu_jac_fd_error(m, d, 0.0, y, 1, &bad, &outside));
                    combos++;
                }
    static const char *const fname[6] = {"", ", TYPE6 friction per corner", "", "", ", /FRICTION (incremental, filtered)",
                                         ", power law with step5 friction"};
    printf("    %s%s jacobian: P = %.3g m at (%.3g, %.3g, %.3g), %d states, %d mode combinations, max scaled |J - FD| = "
           "%.2e\n", kind == 0 ? "box-plane" : kind == 1 ? "box-box (upper corners)" : kind == 2 ? "box-box (lower corners)"
                                                                                 : "box-box (crossing edges)",
           fname[fric], r.p, r.point[0], r.point[1], r.point[2], m->ny, combos, maxerr);
    ENSURE(bad == 0);
    ENSURE(outside == 0);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

/* Edge pairs see the two edges' own contact, not a depth across a box: a
 * box (0.2 x 0.1 x 0.1) 0.1 mm into a fixed 1 m cube's top face, hanging
 * 80 mm over its edge x = 0.5 (its left side 20 mm inside it): its bottom
 * corners over the cube and the crossings of its bottom edges with the
 * cube's top edge are 0.1 mm deep. Its vertical edges at x = 0.48 pass the
 * cube's top edge 20 mm away along x (a pair whose normal is in both edges'
 * cones, closest points on both edges, depth 20 mm < the smallest
 * half-size 50 mm), but the face of the cube nearest that point is its top,
 * not a face along the edge: no contact point. P = 0.1 mm; and the bar
 * laid across a bar (only edges cross), 0.1 mm deep, P = 0.1 mm, at a
 * crossing. */
static void test_box_edge_pairs_depth(void)
{
    for (int k = 0; k < 2; k++) {
        rc_error e;
        const char *deck =
            k == 0 ? "/NODE\n1,0.58,0,0.0499\n/RBODY/1\nbox\n1,,,,2.0\n0.0033,0.0083,0.0083\n0,0,0\n"
                     "/SURF/BOX/30\nbox\n1\n0.58,0,0.0499\n0.1,0.05,0.05\n"
                     "/SURF/BOX/40\ncube\n0\n0,0,-0.5\n0.5,0.5,0.5\n" LINEAR
                     "/INTER/TYPE6/1\nbox on the cube\n30,40\n\n\n1\n\n\n" RUN_TAIL
                   : "/NODE\n1,0.013,-0.021,0.0499\n/RBODY/1\nbar\n1,,,,2.0\n0.0033,0.0083,0.0083\n0,0,0\n"
                     "/SURF/BOX/30\nbar along x\n1\n0.013,-0.021,0.0499\n0.3,0.05,0.05\n"
                     "/SURF/BOX/40\nbar along y\n0\n0,0,-0.05\n0.05,0.3,0.05\n" LINEAR
                     "/INTER/TYPE6/1\nbar on the bar\n30,40\n\n\n1\n\n\n" RUN_TAIL;
        rc_model *m = seg_compile(deck, &e);
        ENSURE(m != NULL);
        if (!m) {
            fprintf(stderr, "  %s\n", e.msg);
            return;
        }
        ENSURE(rc_box_is_box_pair(m, 0) && rc_seg_points(m, 0) == 16 + RC_BOX_EDGE_PAIRS);
        double *y = calloc((size_t)m->ny, sizeof(double));
        rc_initial_state(m, y);
        rc_inter_report r;
        rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
        const double px = r.point[0] + m->origin[0], py = r.point[1] + m->origin[1];
        printf("    %s: P = %.9g m at (%.4f, %.4f)\n", k ? "bar across a bar" : "box over the cube's edge", r.p, px, py);
        ENSURE_NEAR(r.p, 1e-4, 1e-12, 0);
        if (k == 1) ENSURE(fabs(fabs(px) - 0.05) < 1e-9 && fabs(fabs(py + 0.021) - 0.05) < 1e-9);
        free(y);
        rc_model_free(m);
    }
}

/* A box's corners meet the face of the other box across which the two
 * overlap least, not each its nearest plane: a smaller box (half-size 5 mm,
 * fixed) under a larger one (6.74 mm, turned 26.7 degrees against it about
 * the vertical) has its top corners 3.1e-5 m inside the rim of the larger
 * box's bottom face; pressed 6e-5 m into it, each corner is nearer a side
 * face (3.1e-5 m) than the bottom (6e-5 m). Its four top corners must meet
 * the bottom face: depth 6e-5 m along the vertical. (With the nearest
 * plane they took the side faces, and the stack sank: fuzz 239000044.) */
static void test_box_pair_corner_face(void)
{
    rc_error e;
    rc_model *m = seg_compile("/NODE\n1,0,0,0.016691568\n/RBODY/1\nupper box\n1,,,,0.011\n3.3e-7,3.3e-7,3.3e-7\n0,0,0\n"
                              "/SURF/BOX/30\nupper, larger\n1\n0,0,0.016691568\n"
                              "0.0067392527,0.0067392527,0.0067392527\n0.757045908,0.653361686,0\n-0.653361686,0.757045908,0\n"
                              "/SURF/BOX/40\nlower, smaller\n0\n0,0,0.0050061578\n"
                              "0.0050061578,0.0050061578,0.0050061578\n0.382891732,0.923793224,0\n-0.923793224,0.382891732,0\n"
                              LINEAR "/INTER/TYPE6/1\nstack\n30,40\n\n\n1\n\n\n" RUN_TAIL,
                              &e);
    ENSURE(m != NULL);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    ENSURE(rc_box_is_box_pair(m, 0));
    double *y = calloc((size_t)m->ny, sizeof(double));
    rc_initial_state(m, y);
    const int na = m->surf_nadr[m->inter_sa[0] + 1] - m->surf_nadr[m->inter_sa[0]];
    const double depth = 2 * 0.0050061578 - (0.016691568 - 0.0067392527); /* 6.00003e-5 m */
    int n = 0;
    for (int j = 4; j < 8; j++) { /* the lower box's top corners (bit 2: +w) */
        const double dj = rc_point_distance(m, 0, na + j, y, NULL);
        printf("    lower box's top corner %d: d = %.6g m\n", j, dj);
        ENSURE_NEAR(dj, -depth, 1e-9, 0);
        n++;
    }
    ENSURE(n == 4);
    rc_inter_report r;
    rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
    ENSURE_NEAR(r.p, depth, 1e-9, 0);
    ENSURE(fabs(fabs(r.normal[2]) - 1.0) < 1e-9);
    free(y);
    rc_model_free(m);
}

/* The fade of a box-box edge pair's share (the cone's margin, the closest
 * points' parameters, the local separating-axis test) and its rate: the
 * rate against central differences of the fade along the bodies' motion
 * (sliding and turning), over poses of a bar laid across a fixed bar that
 * bring pairs into their fades: shifted along its length (its end passing
 * the other bar), tilted about either horizontal axis by up to 0.02 rad
 * (the cone's margin, the separating-axis test's tie band). */
static void test_box_edge_pair_fade_rates(void)
{
    rc_error e;
    rc_model *m = seg_compile("/NODE\n1,0.013,-0.021,0.0499\n/RBODY/1\nbar\n1,,,,2.0\n0.0033,0.0083,0.0083\n0,0,0\n"
                              "/SURF/BOX/30\nbar along x\n1\n0.013,-0.021,0.0499\n0.3,0.05,0.05\n"
                              "/SURF/BOX/40\nbar along y\n0\n0,0,-0.05\n0.05,0.3,0.05\n" LINEAR
                              "/INTER/TYPE6/1\nbar on the bar\n30,40\n\n\n1\n\n\n" RUN_TAIL,
                              &e);
    ENSURE(m != NULL);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double)), *yd = calloc((size_t)m->ny, sizeof(double));
    double *yp = calloc((size_t)m->ny, sizeof(double)), *ym = calloc((size_t)m->ny, sizeof(double));
    const int b = m->body_yadr[0], np = rc_seg_points(m, 0);
    int checked = 0, zone[3] = {0, 0, 0}, bad = 0;
    double worst = 0.0, fmin = 1.0;
    for (int ix = 0; ix < 201; ix++)
        for (int it = 0; it < 41; it++)
            for (int ax = 0; ax < 2; ax++) {
                rc_initial_state(m, y);
                /* the bar shifted along x so that its end passes the other
                 * bar (ix), tilted by th about x or y (ax); sliding and
                 * turning */
                const double th = 0.0005 * it, shift = 0.22 + 0.0005 * ix;
                y[b + 0] += shift;
                y[b + 3] = cos(0.5 * th);
                y[b + 4 + ax] = sin(0.5 * th);
                y[b + 7] = 0.31;
                y[b + 8] = -0.23;
                y[b + 9] = -0.017;
                y[b + 10] = 0.7;
                y[b + 11] = -0.9;
                y[b + 12] = 1.3;
                rc_assemble_rhs(m, d, 0.0, y, yd);
                for (int j = 16; j < np; j++) {
                    double f[2], fp[2], fm[2];
                    const double dist = rc_point_fade(m, 0, j, y, f);
                    if (!(dist < 0)) continue;
                    fmin = fmin < f[0] ? fmin : f[0];
                    if (!(f[0] > 2e-6 && f[0] < 1.0 - 1e-6)) continue;
                    /* a step over which the fade changes by 1e-6 */
                    const double h = 1e-6 / fmax(fabs(f[1]), 1.0);
                    for (int k = 0; k < m->ny; k++) {
                        yp[k] = y[k] + h * yd[k];
                        ym[k] = y[k] - h * yd[k];
                    }
                    rc_point_fade(m, 0, j, yp, fp);
                    rc_point_fade(m, 0, j, ym, fm);
                    const double fd = (fp[0] - fm[0]) / (2.0 * h), err = fabs(fd - f[1]) / fmax(fabs(f[1]), 1.0);
                    worst = fmax(worst, err);
                    bad += !(err < 1e-4);
                    checked++;
                    zone[f[0] < 0.1 ? 0 : f[0] < 0.9 ? 1 : 2]++;
                }
            }
    printf("    %d pairs in their fade (%d below 0.1, %d between, %d above 0.9), the smallest fade %.3g; "
           "worst |rate - central difference| / |rate| = %.2e\n",
           checked, zone[0], zone[1], zone[2], fmin, worst);
    ENSURE(checked >= 50 && zone[0] > 0 && zone[1] > 0 && zone[2] > 0);
    ENSURE(bad == 0);
    free(y);
    free(yd);
    free(yp);
    free(ym);
    rc_data_free(d);
    rc_model_free(m);
}

static void test_box_plane_jacobian(void)
{
    box_pair_jacobian_check(0, 0);
    box_pair_jacobian_check(0, 1);
    box_pair_jacobian_check(0, 4);
    box_pair_jacobian_check(0, 5);
}

static void test_box_box_jacobian(void)
{
    for (int k = 1; k <= 3; k++) {
        box_pair_jacobian_check(k, 0);
        box_pair_jacobian_check(k, 1);
        box_pair_jacobian_check(k, 4);
        box_pair_jacobian_check(k, 5);
    }
}

/* A node going from stick to slip stores no energy: its state takes the
 * direction of the applied force (spring and stick damper) on the limit,
 * with the magnitude its spring had in the node's tangent plane (where its
 * energy w_j |s_j|^2 / (2 K_t) is) or the slip band, whichever is larger.
 * On the limit itself, which includes the stick damper's part, a node
 * stored (|L|^2 - |s|^2) / (2 K_t) that no work put there, and the spring
 * gave it back to the bodies later (two boxes stacked under tilted
 * gravity, 171000103: the friction channel fell by 2.2e-5 J at a flip, and
 * the run stopped, exit 5). The box's node in the plate sticking with a
 * state of 1.4 N across its normal and 50 N along it (a normal that
 * jumped: a box's node whose nearest face changed), the box sliding and
 * turning fast enough that the node's stick damper carries it past the
 * limit; flipped by its root. Put at the state's whole magnitude or on
 * the limit, the node stored 1.7e-4 J from 1.4e-7 J. */
static void test_seg_point_slip_stores_no_energy(void)
{
    rc_error e;
    char deck[8192];
    seg_box_plate_deck(deck, sizeof deck, 0, 1);
    rc_model *m = seg_compile(deck, &e);
    ENSURE(m != NULL && m->inter_npt[0] == 8 && m->inter_fr[0].form == RC_FF_INCREMENTAL && m->inter_fr[0].kt > 0);
    if (!m) return;
    rc_data *d = rc_data_new(m);
    double st[26];
    memcpy(st, seg_state, sizeof st);
    for (int k = 7; k < 13; k++) st[k] *= 30.0; /* the box slides and turns fast: its dampers beyond the limit */
    double *y = two_body_state(m, st);
    const int npt = m->inter_npt[0], pb = m->inter_pbase[0], ps = m->inter_pst[0], nr = rc_root_count(m);
    int *roots = calloc((size_t)nr + 1, sizeof(int));
    double *out = calloc((size_t)RC_PT_OUT * npt, sizeof(double));
    if (!d || !roots || !out) goto done;
    d->inter_mode[0] = RC_MODE_CLOSED;
    d->inter_branch[0] = RC_BR_LOAD;
    double *ft = y + m->inter_eadr[0] + m->inter_ns[0];
    for (int j = 0; j < npt; j++) {
        d->pt_slip[pb + j] = 0;
        const double s0[3] = {2.0, -1.0, 50.0}; /* the plate's normal is near +z: 1.4 N across it */
        memcpy(ft + ps * j, s0, sizeof s0);
    }
    rc_points_eval(m, d, 0, NULL, 0.0, y, out);
    int nflip = 0;
    double fb_energy = 0.0; /* the slip band's energy over the flipping nodes */
    const double kt = m->inter_fr[0].kt, fb = m->inter_fr[0].fband;
    for (int j = 0; j < npt; j++)
        if (out[RC_PT_OUT * j + 4] > 0 && out[RC_PT_OUT * j] > 0) {
            roots[rc_root_point_base(m) + pb + j] = 1;
            fb_energy += out[RC_PT_OUT * j + 4] * fb * fb / (2.0 * kt);
            nflip++;
        }
    const double e0 = rc_inter_friction_stored(m, d, 0, 0.0, y);
    rc_event ev[16];
    int restart = 0;
    rc_events_apply(m, d, 0.0, y, roots, ev, 16, &restart);
    const double e1 = rc_inter_friction_stored(m, d, 0, 0.0, y);
    int nslip = 0;
    for (int j = 0; j < npt; j++) nslip += d->pt_slip[pb + j];
    printf("    %d of %d nodes flipped to slip (%d slipping): stored energy %.4g J -> %.4g J (slip band %.3g J; the "
           "limit's magnitude stored 1.7e-4 J)\n", nflip, npt, nslip, e0, e1, fb_energy);
    ENSURE(nflip >= 1 && nslip == nflip);
    ENSURE(e1 <= e0 + fb_energy + 1e-12 * e0);
done:
    free(out);
    free(roots);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

void suite_seg(void);
void suite_seg(void)
{
    RUN_TEST(test_seg_read_surfaces);
    RUN_TEST(test_seg_read_errors);
    RUN_TEST(test_seg_force_distribution);
    RUN_TEST(test_seg_jacobian_matches_finite_differences);
    RUN_TEST(test_seg_box_jacobian_matches_finite_differences);
    RUN_TEST(test_seg_friction_jacobian_matches_finite_differences);
    RUN_TEST(test_seg_box_friction_jacobian_matches_finite_differences);
    RUN_TEST(test_seg_seg_jacobian_matches_finite_differences);
    RUN_TEST(test_seg_seg_friction_jacobian_matches_finite_differences);
    RUN_TEST(test_seg_cyl_jacobian_matches_finite_differences);
    RUN_TEST(test_seg_orientation_irs_irm);
    RUN_TEST(test_seg_power_jacobian_matches_finite_differences);
    RUN_TEST(test_seg_sphere_valley_forces);
    RUN_TEST(test_seg_sphere_jacobian_matches_finite_differences);
    RUN_TEST(test_seg_sphere_friction_jacobian);
    RUN_TEST(test_seg_viscous_friction_jacobian);
    RUN_TEST(test_seg_filtered_incremental_jacobian);
    RUN_TEST(test_seg_step5_jacobian);
    RUN_TEST(test_seg_point_slip_stores_no_energy);
    RUN_TEST(test_box_pairs_corners);
    RUN_TEST(test_box_plane_jacobian);
    RUN_TEST(test_box_box_jacobian);
    RUN_TEST(test_box_edge_pairs_depth);
    RUN_TEST(test_box_pair_corner_face);
    RUN_TEST(test_box_edge_pair_fade_rates);
    RUN_TEST(test_seg_sphere_step5_jacobian);
}
