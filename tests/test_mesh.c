/*
 * Mass properties from the mesh (model/massprop.c) and the mesh cards
 * (case/cards_mesh.c): element integrals against closed forms, meshed
 * spheres, boxes and cylinders converging at second order, and decks read
 * and compiled end to end (ICoG, Ispher, Skew_ID, /GRNOD/PART, errors).
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <math.h>

#include "base/error.h"
#include "case/case.h"
#include "model/massprop.h"
#include "model/model.h"
#include "harness.h"
#include "testutil.h"

static const double PI = 3.14159265358979323846;

/* Inertia about the centre of mass of an accumulator. */
static void mp_J(const rc_mp *a, double c[3], double J[9]) { rc_mp_inertia(a, c, J); }

/* ---- elements against closed forms -------------------------------------- */

static void test_mesh_element_closed_forms(void)
{
    rc_mp a = {0};
    /* unit right triangle in the xy plane, sigma = 1: int x^2 = 1/12, int xy = 1/24 */
    const double tri[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    ENSURE_NEAR(rc_mp_tri(&a, tri, 1.0, 0.0), 0.5, 1e-15, 0);
    ENSURE_NEAR(a.m, 0.5, 1e-15, 0);
    ENSURE_NEAR(a.s[0], 1.0 / 6.0, 1e-15, 0);
    ENSURE_NEAR(a.S[0], 1.0 / 12.0, 1e-15, 0);
    ENSURE_NEAR(a.S[3], 1.0 / 24.0, 1e-15, 0);
    ENSURE_NEAR(a.S[2], 0.0, 0, 1e-18);
    /* thickness term: sigma A t^2/12 along the normal z */
    memset(&a, 0, sizeof a);
    rc_mp_tri(&a, tri, 2.0, 0.3);
    ENSURE_NEAR(a.S[2], 2.0 * 0.5 * 0.09 / 12.0, 1e-14, 0);
    /* unit tetrahedron, rho = 1: V = 1/6, int x^2 = 1/60, int xy = 1/120 */
    memset(&a, 0, sizeof a);
    const double tet[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    ENSURE_NEAR(rc_mp_tet(&a, tet, 1.0), 1.0 / 6.0, 1e-15, 0);
    ENSURE_NEAR(a.S[0], 1.0 / 60.0, 1e-15, 0);
    ENSURE_NEAR(a.S[3], 1.0 / 120.0, 1e-15, 0);
    ENSURE_NEAR(a.s[2], 1.0 / 24.0, 1e-15, 0);
    /* box a x b x c as a brick and as a shell box: closed forms */
    const double A = 0.3, B = 0.5, C = 0.7, rho = 7800.0;
    double p[8][3], cg[3], J[9];
    for (int k = 0; k < 8; k++) {
        const int ix = (k == 1 || k == 2 || k == 5 || k == 6), iy = (k == 2 || k == 3 || k == 6 || k == 7), iz = k >= 4;
        p[k][0] = 1.0 + ix * A;
        p[k][1] = -2.0 + iy * B;
        p[k][2] = 0.5 + iz * C;
    }
    memset(&a, 0, sizeof a);
    ENSURE_NEAR(rc_mp_hex(&a, (const double(*)[3])p, rho), A * B * C, 1e-14, 0);
    mp_J(&a, cg, J);
    const double m = rho * A * B * C;
    ENSURE_NEAR(a.m, m, 1e-14, 0);
    ENSURE_NEAR(cg[0], 1.0 + A / 2, 1e-14, 0);
    ENSURE_NEAR(J[0], m * (B * B + C * C) / 12, 1e-12, 0);
    ENSURE_NEAR(J[4], m * (A * A + C * C) / 12, 1e-12, 0);
    ENSURE_NEAR(J[8], m * (A * A + B * B) / 12, 1e-12, 0);
    ENSURE_NEAR(J[1], 0.0, 0, 1e-12 * m);
    /* the other node numbering (mirrored) is the same solid */
    double q[8][3];
    for (int k = 0; k < 8; k++) memcpy(q[k], p[(k + 4) % 8], sizeof q[k]);
    rc_mp b = {0};
    rc_mp_hex(&b, (const double(*)[3])q, rho);
    ENSURE_NEAR(b.m, a.m, 1e-14, 0);
    ENSURE_NEAR(b.S[0], a.S[0], 1e-14, 0);
}

/* A flat quadrilateral is two triangles; an affine brick is six tetrahedra;
 * results rotate as tensors. */
static void test_mesh_element_consistency(void)
{
    const double quad[4][3] = {{0.1, 0.2, 0.3}, {1.3, 0.1, 0.5}, {1.1, 1.4, 0.2}, {0.0, 0.9, 0.0}};
    /* make it planar: project node 4 on the plane of nodes 1-3 */
    double e1[3], e2[3], n[3], qd[4][3];
    memcpy(qd, quad, sizeof qd);
    for (int i = 0; i < 3; i++) { e1[i] = qd[1][i] - qd[0][i]; e2[i] = qd[2][i] - qd[0][i]; }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    double nn = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), d = 0;
    for (int i = 0; i < 3; i++) { n[i] /= nn; d += (qd[3][i] - qd[0][i]) * n[i]; }
    for (int i = 0; i < 3; i++) qd[3][i] -= d * n[i];
    rc_mp a = {0}, b = {0};
    rc_mp_quad(&a, (const double(*)[3])qd, 3.0, 0.01);
    const double t1[3][3] = {{qd[0][0], qd[0][1], qd[0][2]}, {qd[1][0], qd[1][1], qd[1][2]}, {qd[2][0], qd[2][1], qd[2][2]}};
    const double t2[3][3] = {{qd[0][0], qd[0][1], qd[0][2]}, {qd[2][0], qd[2][1], qd[2][2]}, {qd[3][0], qd[3][1], qd[3][2]}};
    rc_mp_tri(&b, t1, 3.0, 0.01);
    rc_mp_tri(&b, t2, 3.0, 0.01);
    ENSURE_NEAR(a.m, b.m, 1e-13, 0);
    for (int k = 0; k < 3; k++) ENSURE_NEAR(a.s[k], b.s[k], 1e-13, 1e-15);
    for (int k = 0; k < 6; k++) ENSURE_NEAR(a.S[k], b.S[k], 1e-12, 1e-15);
    /* affine brick (parallelepiped) = 6 tetrahedra around the diagonal 0-6 */
    const double o[3] = {0.2, -0.1, 0.4}, u[3] = {0.5, 0.1, 0.0}, v[3] = {-0.1, 0.4, 0.1}, w[3] = {0.05, 0.1, 0.6};
    double p[8][3];
    for (int k = 0; k < 8; k++) {
        const int ix = (k == 1 || k == 2 || k == 5 || k == 6), iy = (k == 2 || k == 3 || k == 6 || k == 7), iz = k >= 4;
        for (int i = 0; i < 3; i++) p[k][i] = o[i] + ix * u[i] + iy * v[i] + iz * w[i];
    }
    rc_mp h = {0}, t = {0};
    rc_mp_hex(&h, (const double(*)[3])p, 2.5);
    static const int tets[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
    for (int k = 0; k < 6; k++) {
        double tp[4][3];
        for (int j = 0; j < 4; j++) memcpy(tp[j], p[tets[k][j]], sizeof tp[j]);
        rc_mp_tet(&t, (const double(*)[3])tp, 2.5);
    }
    ENSURE_NEAR(h.m, t.m, 1e-13, 0);
    for (int k = 0; k < 6; k++) ENSURE_NEAR(h.S[k], t.S[k], 1e-12, 1e-16);
}

/* ---- meshed shapes: convergence ----------------------------------------- */

/* Shell sphere, radius R, thickness t: cube-sphere of 6 n^2 quads. */
static void sphere_shell(int n, double R, double t, double rho, double *m, double *J)
{
    rc_mp a = {0};
    for (int f = 0; f < 6; f++)
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++) {
                double p[4][3];
                static const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
                for (int k = 0; k < 4; k++) {
                    const double s = -1 + 2.0 * (i + di[k]) / n, r = -1 + 2.0 * (j + dj[k]) / n;
                    double x[3];
                    const int ax = f / 2, sg = f % 2 ? -1 : 1;
                    x[ax] = sg;
                    x[(ax + 1) % 3] = s;
                    x[(ax + 2) % 3] = r;
                    const double nr = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
                    for (int d = 0; d < 3; d++) p[k][d] = R * x[d] / nr;
                }
                rc_mp_quad(&a, (const double(*)[3])p, rho * t, t);
            }
    double c[3], Jm[9];
    rc_mp_inertia(&a, c, Jm);
    *m = a.m;
    *J = Jm[0];
}

/* Solid cylinder (axis z), radius R, length L: bricks on a polar grid of
 * nt sectors and nr rings (the inner ring degenerate: wedges). */
static void cylinder_solid(int nt, int nr, double R, double L, double rho, double *m, double *Jxx, double *Jzz)
{
    rc_mp a = {0};
    for (int i = 0; i < nr; i++)
        for (int j = 0; j < nt; j++) {
            double p[8][3];
            static const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
            for (int k = 0; k < 8; k++) {
                const double r = R * (i + di[k % 4]) / nr, th = 2 * PI * (j + dj[k % 4]) / nt;
                p[k][0] = r * cos(th);
                p[k][1] = r * sin(th);
                p[k][2] = k < 4 ? -L / 2 : L / 2;
            }
            rc_mp_hex(&a, (const double(*)[3])p, rho);
        }
    double c[3], J[9];
    rc_mp_inertia(&a, c, J);
    *m = a.m;
    *Jxx = J[0];
    *Jzz = J[8];
}

static void test_mesh_convergence_sphere_cylinder(void)
{
    const double R = 0.1, t = 1e-4, rho = 7800;
    const double Ro = R + t / 2, Ri = R - t / 2;
    const double m_ex = rho * 4.0 / 3.0 * PI * (Ro * Ro * Ro - Ri * Ri * Ri);
    const double J_ex = 0.4 * m_ex * (pow(Ro, 5) - pow(Ri, 5)) / (Ro * Ro * Ro - Ri * Ri * Ri);
    double em[4], eJ[4];
    for (int l = 0; l < 4; l++) {
        double m, J;
        sphere_shell(4 << l, R, t, rho, &m, &J);
        em[l] = fabs(m - m_ex) / m_ex;
        eJ[l] = fabs(J - J_ex) / J_ex;
        printf("    shell sphere n = %2d: mass error %.3e, J error %.3e", 4 << l, em[l], eJ[l]);
        if (l) printf(", orders %.2f %.2f", log2(em[l - 1] / em[l]), log2(eJ[l - 1] / eJ[l]));
        printf("\n");
    }
    for (int l = 1; l < 4; l++) {
        ENSURE(log2(em[l - 1] / em[l]) > 1.8 && log2(em[l - 1] / em[l]) < 2.2);
        ENSURE(log2(eJ[l - 1] / eJ[l]) > 1.8 && log2(eJ[l - 1] / eJ[l]) < 2.2);
    }
    ENSURE(em[3] < 2e-3 && eJ[3] < 3e-3);
    /* solid cylinder: the polygon of nt sectors converges at order 2 */
    const double Rc = 0.05, L = 0.2, mc = rho * PI * Rc * Rc * L;
    double ec[4], ex[4];
    for (int l = 0; l < 4; l++) {
        double m, Jxx, Jzz;
        cylinder_solid(8 << l, 2 << l, Rc, L, rho, &m, &Jxx, &Jzz);
        ec[l] = fabs(m - mc) / mc;
        ex[l] = fabs(Jzz - 0.5 * mc * Rc * Rc) / (0.5 * mc * Rc * Rc);
        const double exx = fabs(Jxx - mc * (3 * Rc * Rc + L * L) / 12) / (mc * (3 * Rc * Rc + L * L) / 12);
        printf("    brick cylinder nt = %2d: mass error %.3e, Jzz error %.3e, Jxx error %.3e", 8 << l, ec[l], ex[l], exx);
        if (l) printf(", orders %.2f %.2f", log2(ec[l - 1] / ec[l]), log2(ex[l - 1] / ex[l]));
        printf("\n");
    }
    for (int l = 1; l < 4; l++) {
        ENSURE(log2(ec[l - 1] / ec[l]) > 1.9 && log2(ec[l - 1] / ec[l]) < 2.1);
        ENSURE(log2(ex[l - 1] / ex[l]) > 1.9 && log2(ex[l - 1] / ex[l]) < 2.1);
    }
}

/* ---- decks -------------------------------------------------------------- */

static char mesh_path[128];

static const char *write_deck(const char *text)
{
    snprintf(mesh_path, sizeof mesh_path, "/tmp/rc_mesh_test_%d.rad", (int)getpid());
    FILE *f = fopen(mesh_path, "w");
    if (f) {
        fputs(text, f);
        fclose(f);
    }
    return mesh_path;
}

static rc_model *compile_text(const char *text, rc_error *e)
{
    rc_model *m = NULL;
    tu_load_compile(write_deck(text), &m, e);
    remove(mesh_path);
    return m;
}

/* Expect an input error whose message holds every needle. */
static int mesh_error(const char *text, ...)
{
    rc_error e;
    rc_model *m = compile_text(text, &e);
    int bad = m != NULL || e.code != RC_EINPUT;
    va_list ap;
    va_start(ap, text);
    bad += tu_missing_needles(e.msg, ap);
    va_end(ap);
    if (bad) fprintf(stderr, "  message: %s\n", e.msg);
    rc_model_free(m);
    return bad;
}
#define EXPECT_MESH_ERROR(text, ...) ENSURE(mesh_error((text), __VA_ARGS__, (const char *)NULL) == 0)

/* A 0.2 x 0.4 x 0.6 steel box of one brick (nodes 1-8, part 1) plus a main
 * node 9, fixed format lines where the layout matters. */
#define BOX_NODES                                                                       \
    "/NODE\n1,0,0,0\n2,0.2,0,0\n3,0.2,0.4,0\n4,0,0.4,0\n5,0,0,0.6\n6,0.2,0,0.6\n7,0.2,0.4,0.6\n" \
    "8,0,0.4,0.6\n9,1,1,1\n"
#define BOX_MESH                                                                        \
    "/MAT/LAW1/3\nsteel\n#        Init. dens.          Ref. dens.\n"                     \
    "              7800.0                   0\n"                                        \
    "#                  E                  nu\n             2.1e+11                 0.3\n" \
    "/PROP/SOLID/2\nsolid\n\n\n/PART/1\nbox\n         2         3         0\n"         \
    "/BRICK/1\n1,1,2,3,4,5,6,7,8\n"
#define RUN_TAIL "/RUN\n0.01,0.001\n"

static void test_mesh_deck_brick_box_icog(void)
{
    const double m = 7800 * 0.2 * 0.4 * 0.6, a = 0.2, b = 0.4, c = 0.6;
    char deck[4096];
    rc_error e;
    /* ICoG 0 (= 1): centre of mass from the mesh and the 2 kg card mass at node 9 */
    snprintf(deck, sizeof deck, "%s%s/GRNOD/PART/7\nbox nodes\n1\n/RBODY/1\nbox\n"
             "         9         0         0         3                 2.0         7\n"
             "                0.01                0.02                0.03\n\n" RUN_TAIL,
             BOX_NODES, BOX_MESH);
    rc_model *md = compile_text(deck, &e);
    ENSURE(md != NULL);
    if (!md) fprintf(stderr, "  %s\n", e.msg);
    if (md) {
        const double M = m + 2.0, x[3] = {(m * 0.1 + 2) / M, (m * 0.2 + 2) / M, (m * 0.3 + 2) / M};
        const double *y0 = md->body_y0, *J = md->body_J;
        ENSURE_NEAR(md->body_mass[0], M, 1e-14, 0);
        for (int k = 0; k < 3; k++) ENSURE_NEAR(y0[k], x[k], 1e-14, 0);
        /* brick about x + card J + both masses' parallel axes */
        const double g[3] = {0.1 - x[0], 0.2 - x[1], 0.3 - x[2]}, h[3] = {1 - x[0], 1 - x[1], 1 - x[2]};
        const double Jxx = m * (b * b + c * c) / 12 + 0.01 + m * (g[1] * g[1] + g[2] * g[2]) + 2 * (h[1] * h[1] + h[2] * h[2]);
        const double Jxy = -m * g[0] * g[1] - 2 * h[0] * h[1];
        ENSURE_NEAR(J[0], Jxx, 1e-12, 0);
        ENSURE_NEAR(J[1], Jxy, 1e-12, 0);
        ENSURE_NEAR(J[8], m * (a * a + b * b) / 12 + 0.03 + m * (g[0] * g[0] + g[1] * g[1]) + 2 * (h[0] * h[0] + h[1] * h[1]), 1e-12, 0);
        rc_model_free(md);
    }
    /* ICoG 3: the main node keeps its place, inertia about it */
    snprintf(deck, sizeof deck, "%s%s/GRNOD/PART/7\nbox nodes\n1\n/RBODY/1\nbox\n9,0,0,3,2.0,7,0,3\n0.01,0.02,0.03\n\n" RUN_TAIL,
             BOX_NODES, BOX_MESH);
    md = compile_text(deck, &e);
    ENSURE(md != NULL);
    if (md) {
        ENSURE_NEAR(md->body_mass[0], m + 2, 1e-14, 0);
        ENSURE_NEAR(md->body_y0[0], 1.0, 0, 0);
        ENSURE_NEAR(md->body_J[0], m * (b * b + c * c) / 12 + 0.01 + m * (0.8 * 0.8 + 0.7 * 0.7), 1e-12, 0);
        rc_model_free(md);
    }
    /* ICoG 2: the mesh's centre of mass, the card mass put there */
    snprintf(deck, sizeof deck, "%s%s/GRNOD/PART/7\nbox nodes\n1\n/RBODY/1\nbox\n9,0,0,3,2.0,7,0,2\n0.01,0.02,0.03\n\n" RUN_TAIL,
             BOX_NODES, BOX_MESH);
    md = compile_text(deck, &e);
    ENSURE(md != NULL);
    if (md) {
        ENSURE_NEAR(md->body_mass[0], m + 2, 1e-14, 0);
        ENSURE_NEAR(md->body_y0[2], 0.3, 1e-14, 0);
        ENSURE_NEAR(md->body_J[0], m * (b * b + c * c) / 12 + 0.01, 1e-12, 0);
        rc_model_free(md);
    }
    /* ICoG 4: the card alone */
    snprintf(deck, sizeof deck, "%s%s/GRNOD/PART/7\nbox nodes\n1\n/RBODY/1\nbox\n9,0,0,3,2.0,7,0,4\n0.01,0.02,0.03\n\n" RUN_TAIL,
             BOX_NODES, BOX_MESH);
    md = compile_text(deck, &e);
    ENSURE(md != NULL);
    if (md) {
        ENSURE_NEAR(md->body_mass[0], 2.0, 0, 0);
        ENSURE_NEAR(md->body_J[4], 0.02, 1e-15, 0);
        rc_model_free(md);
    }
    /* Ispher 1: spherical, the mean of the principal moments */
    snprintf(deck, sizeof deck, "%s%s/GRNOD/PART/7\nbox nodes\n1\n/RBODY/1\nbox\n9,0,0,1,0,7,0,2\n\n\n" RUN_TAIL,
             BOX_NODES, BOX_MESH);
    md = compile_text(deck, &e);
    ENSURE(md != NULL);
    if (md) {
        const double mean = m * (2 * (a * a + b * b + c * c)) / 36;
        ENSURE_NEAR(md->body_J[0], mean, 1e-12, 0);
        ENSURE_NEAR(md->body_J[8], mean, 1e-12, 0);
        ENSURE(md->body_J[1] == 0);
        rc_model_free(md);
    }
}

/* /INIVEL and /GRAV with a skew_ID: the components of /INIVEL/TRA and
 * /INIVEL/ROT in the skew's axes (a /SKEW/FIX, and a /SKEW/MOV taken at its
 * nodes' initial positions), /GRAV along an axis of a /SKEW/FIX. */
static void test_mesh_deck_skew_loads(void)
{
    rc_error e;
    const double r = sqrt(0.5);
    /* skew 4: Y' = (1, 1, 0)/sqrt2, Z' = z, X' = (1, -1, 0)/sqrt2; skew 5 the
     * same frame from nodes 11 (origin), 12 (on Y', Dir Y), 13 (on Z') */
    rc_model *md = compile_text("/NODE\n1,0,0,0\n2,0,0,5\n11,0,0,0\n12,1,1,0\n13,0,0,1\n"
                                "/SKEW/FIX/4\ns\n0,0,0\n1,1,0\n0,0,1\n/SKEW/MOV/5\nm\n11,12,13,Y\n"
                                "/RBODY/1\nb\n1,0,0,3,1.0\n1.0,1.0,1.0\n0,0,0\n"
                                "/RBODY/2\nb\n2,0,0,3,2.0\n1.0,1.0,1.0\n0,0,0\n"
                                "/GRNOD/NODE/1\none\n1\n/GRNOD/NODE/2\ntwo\n2\n"
                                "/INIVEL/TRA/1\nv\n2,3,4,1,4\n/INIVEL/ROT/2\nw\n1,-1,0.5,1,4\n"
                                "/INIVEL/TRA/3\nv\n2,3,4,2,5\n"
                                "/GRAV/1\ng\n0,X,4,0,1,,1,-9.81\n/GRAV/2\ng\n0,Y,4,0,2,,1,-2\n" RUN_TAIL,
                                &e);
    ENSURE(md != NULL);
    if (!md) fprintf(stderr, "  %s\n", e.msg);
    if (md) {
        const double *y0 = md->body_y0, *y1 = md->body_y0 + RC_NB;
        /* v = 2 X' + 3 Y' + 4 Z' = ((2 + 3) r, (3 - 2) r, 4) */
        ENSURE_NEAR(y0[7], 5 * r, 1e-15, 0);
        ENSURE_NEAR(y0[8], r, 1e-15, 0);
        ENSURE_NEAR(y0[9], 4.0, 1e-15, 0);
        /* w = X' - Y' + 0.5 Z' = (0, -2 r, 0.5) */
        ENSURE_NEAR(y0[10], 0.0, 0, 1e-15);
        ENSURE_NEAR(y0[11], -2 * r, 1e-15, 0);
        ENSURE_NEAR(y0[12], 0.5, 1e-15, 0);
        /* the moving skew at the nodes' initial positions: the same */
        ENSURE_NEAR(y1[7], 5 * r, 1e-15, 0);
        ENSURE_NEAR(y1[8], r, 1e-15, 0);
        ENSURE_NEAR(y1[9], 4.0, 1e-15, 0);
        /* gravity -9.81 along X' on body 1, -2 along Y' on body 2 */
        ENSURE_NEAR(md->body_grav[0], -9.81 * r, 1e-15, 0);
        ENSURE_NEAR(md->body_grav[1], 9.81 * r, 1e-15, 0);
        ENSURE_NEAR(md->body_grav[2], 0.0, 0, 1e-15);
        ENSURE_NEAR(md->body_grav[3], -2 * r, 1e-15, 0);
        ENSURE_NEAR(md->body_grav[4], -2 * r, 1e-15, 0);
        ENSURE_NEAR(md->body_grav[5], 0.0, 0, 1e-15);
        rc_model_free(md);
    }
    /* /BCS with a skew: all three translations (or rotations) held or free,
     * the same in any frame */
    md = compile_text("/NODE\n1,0,0,0\n/SKEW/FIX/4\ns\n0,0,0\n1,1,0\n0,0,1\n"
                      "/RBODY/1\nb\n1,0,0,3,1.0\n1.0,1.0,1.0\n0,0,0\n/GRNOD/NODE/1\none\n1\n"
                      "/BCS/1\nb\n   111 000         4         1\n" RUN_TAIL,
                      &e);
    ENSURE(md != NULL);
    if (!md) fprintf(stderr, "  %s\n", e.msg);
    for (int j = 0; md && j < 6; j++) ENSURE(md->body_dofmask[j] == (j < 3));
    rc_model_free(md);
    /* refused: no such skew; gravity along a moving skew */
    EXPECT_MESH_ERROR("/NODE\n1,0,0,0\n/RBODY/1\nb\n1,0,0,3,1.0\n1.0,1.0,1.0\n0,0,0\n/GRNOD/NODE/1\none\n1\n"
                      "/INIVEL/TRA/1\nv\n2,3,4,1,9\n" RUN_TAIL,
                      "card /INIVEL/TRA/1", "field skew_ID", "no such skew");
    EXPECT_MESH_ERROR("/NODE\n1,0,0,0\n11,0,0,0\n12,1,1,0\n13,1,-1,0\n/SKEW/MOV/5\nm\n11,12,13,Y\n"
                      "/RBODY/1\nb\n1,0,0,3,1.0\n1.0,1.0,1.0\n0,0,0\n/GRAV/1\ng\n0,Z,5,0,0,,1,-9.81\n" RUN_TAIL,
                      "card /GRAV/1", "field skew_ID", "/SKEW/MOV/5 moves with its nodes", "not supported yet");
    EXPECT_MESH_ERROR("/NODE\n1,0,0,0\n/RBODY/1\nb\n1,0,0,3,1.0\n1.0,1.0,1.0\n0,0,0\n/GRAV/1\ng\n0,Z,2,0,0,,1,-9.81\n"
                      RUN_TAIL,
                      "card /GRAV/1", "field skew_ID", "expected the id of a /SKEW/FIX", "no such skew");
}

/* Skew_ID: the card's J in the skew's axes; Ispher 2 raises a tiny
 * principal moment to 0.1 of the largest. */
static void test_mesh_deck_skew_ispher(void)
{
    rc_error e;
    /* skew: Y' = (1, 1, 0)/sqrt2, Z' = z, X' = Y' x Z' = (1, -1, 0)/sqrt2 */
    rc_model *md = compile_text("/NODE\n1,0,0,0\n/SKEW/FIX/4\ns\n0,0,0\n1,1,0\n0,0,1\n"
                                "/RBODY/1\nb\n1,0,4,3,1.0\n1.0,3.0,2.0\n0,0,0\n" RUN_TAIL, &e);
    ENSURE(md != NULL);
    if (!md) fprintf(stderr, "  %s\n", e.msg);
    if (md) {
        /* J = R diag(1, 3, 2) R^T: Jxx = Jyy = 2, Jxy = (3 - 1)/2 */
        ENSURE_NEAR(md->body_J[0], 2.0, 1e-14, 0);
        ENSURE_NEAR(md->body_J[4], 2.0, 1e-14, 0);
        ENSURE_NEAR(md->body_J[8], 2.0, 1e-14, 0);
        ENSURE_NEAR(md->body_J[1], 1.0, 1e-14, 0);
        rc_model_free(md);
    }
    /* the same frame carried by three nodes (/SKEW/MOV with Dir X, Y, Z and
     * /SKEW/MOV2), the nodes after the skew cards; N1 at (0.3, 0.2, 0.1) */
    md = compile_text("/SKEW/MOV/5\nx\n11,12,13,X\n/SKEW/MOV/6\ny\n11,14,15,  y\n/SKEW/MOV/7\nz\n11,16,17,z\n"
                      "/SKEW/MOV2/8\nz\n11,16,17\n"
                      "/NODE\n11,0.3,0.2,0.1\n12,1.0,-0.5,0.1\n13,1.6,-0.2,0.1\n14,0.6,0.5,0.1\n15,0.6,0.5,0.6\n"
                      "16,0.3,0.2,2.1\n17,1.3,-0.8,0.3\n"
                      "/NODE\n1,0,0,0\n2,0,0,1\n3,0,0,2\n4,0,0,3\n"
                      "/RBODY/1\nb\n1,0,5,3,1.0\n1.0,3.0,2.0\n0,0,0\n/RBODY/2\nb\n2,0,6,3,1.0\n1.0,3.0,2.0\n0,0,0\n"
                      "/RBODY/3\nb\n3,0,7,3,1.0\n1.0,3.0,2.0\n0,0,0\n/RBODY/4\nb\n4,0,8,3,1.0\n1.0,3.0,2.0\n0,0,0\n"
                      RUN_TAIL, &e);
    ENSURE(md != NULL);
    if (!md) fprintf(stderr, "  %s\n", e.msg);
    for (int b = 0; md && b < 4; b++) {
        ENSURE_NEAR(md->body_J[9 * b + 0], 2.0, 1e-14, 0);
        ENSURE_NEAR(md->body_J[9 * b + 4], 2.0, 1e-14, 0);
        ENSURE_NEAR(md->body_J[9 * b + 8], 2.0, 1e-14, 0);
        ENSURE_NEAR(md->body_J[9 * b + 1], 1.0, 1e-14, 0);
        ENSURE_NEAR(md->body_J[9 * b + 2], 0.0, 0, 1e-14);
    }
    rc_model_free(md);
    EXPECT_MESH_ERROR("/NODE\n1,0,0,0\n2,1,0,0\n/SKEW/MOV/5\nx\n1,2,3\n" RUN_TAIL, ":6:", "card /SKEW/MOV/5",
                      "field node_ID3", "no such node");
    EXPECT_MESH_ERROR("/NODE\n1,0,0,0\n2,1,0,0\n3,2,0,0\n/SKEW/MOV/5\nx\n1,2,3\n" RUN_TAIL, ":7:",
                      "card /SKEW/MOV/5", "field node_ID1 node_ID2 node_ID3", "not on one line");
    EXPECT_MESH_ERROR("/SKEW/MOV/5\nx\n1,2,3,W\n" RUN_TAIL, ":3:", "card /SKEW/MOV/5", "field Dir", "X, Y or Z");
    EXPECT_MESH_ERROR("/SKEW/MOV/5\nx\n1,2,1\n" RUN_TAIL, ":3:", "card /SKEW/MOV/5", "three different nodes");
    EXPECT_MESH_ERROR("/SKEW/CYL/5\nx\n1,2,1\n" RUN_TAIL, ":1:", "/SKEW/CYL/5", "not supported yet", "/SKEW/MOV");
    md = compile_text("/NODE\n1,0,0,0\n/RBODY/1\nb\n1,0,0,0,1.0\n1.0,1.0,1e-6\n0,0,0\n" RUN_TAIL, &e);
    ENSURE(md != NULL);
    if (md) {
        ENSURE_NEAR(md->body_J[8], 1e-6 + 0.1, 1e-12, 0);
        ENSURE_NEAR(md->body_J[0], 1.0, 1e-12, 0);
        rc_model_free(md);
    }
}

/* A shell box (6 faces, /SHELL quads and /SH3N triangles) and a brick box
 * as two bodies from /GRNOD/GRNOD; nodes given by /GRNOD/NODE. */
static void test_mesh_deck_shell_box_groups(void)
{
    const double t = 0.002, rho = 2700, a = 0.2, b = 0.4, c = 0.6;
    char deck[8192];
    int n = snprintf(deck, sizeof deck, "%s%s", BOX_NODES, BOX_MESH);
    /* the shell box on nodes 11..18 = nodes 1..8 shifted by 2 in x */
    n += snprintf(deck + n, sizeof deck - (size_t)n,
                  "/NODE\n11,2,0,0\n12,2.2,0,0\n13,2.2,0.4,0\n14,2,0.4,0\n15,2,0,0.6\n16,2.2,0,0.6\n17,2.2,0.4,0.6\n"
                  "18,2,0.4,0.6\n19,2,2,2\n"
                  "/MAT/PLAS_JOHNS/5\nalu\n2700\n\n/PROP/SHELL/6\nsh\n\n\n         0         0               0.002\n"
                  "/PART/2\nskin\n6,5\n/PART/3\nskin tri\n6,5\n"
                  "/SHELL/2\n1,11,12,13,14\n2,15,16,17,18\n3,11,12,16,15\n4,14,13,17,18\n"
                  "/SH3N/3\n5,11,14,18\n6,11,18,15\n7,12,13,17\n8,12,17,16\n"
                  "/GRNOD/PART/20\nskin nodes\n2,3\n/GRNOD/NODE/21\nbox nodes\n1,2,3,4,5,6,7,8\n"
                  "/GRNOD/GRNOD/22\nall box\n21\n"
                  "/RBODY/1\nbox\n9,,,,,22,,3\n\n\n/RBODY/2\nskin\n19,,,,,20,,3\n\n\n" RUN_TAIL);
    rc_error e;
    rc_model *md = compile_text(deck, &e);
    ENSURE(md != NULL);
    if (!md) fprintf(stderr, "  %s\n", e.msg);
    if (md) {
        ENSURE_NEAR(md->body_mass[0], 7800 * a * b * c, 1e-14, 0);
        /* closed box of plates about its centre, plus the through-thickness
         * term, then moved to node 19 (ICoG 3) */
        const double s = rho * t, Axy = a * b, Axz = a * c, Ayz = b * c;
        const double M = s * 2 * (Axy + Axz + Ayz);
        ENSURE_NEAR(md->body_mass[1], M, 1e-13, 0);
        /* Jxx about the centre: faces z (a x b at z = +-c/2), y (a x c at
         * y = +-b/2), x (b x c at x = +-a/2) */
        const double Jxx = 2 * s * Axy * (b * b / 12 + c * c / 4 + t * t / 12) +
                           2 * s * Axz * (c * c / 12 + b * b / 4 + t * t / 12) + 2 * s * Ayz * (b * b + c * c) / 12;
        const double d[3] = {2.1 - 2, 0.2 - 2, 0.3 - 2};
        ENSURE_NEAR(md->body_J[9 + 0], Jxx + M * (d[1] * d[1] + d[2] * d[2]), 1e-12, 0);
        ENSURE_NEAR(md->body_J[9 + 1], -M * d[0] * d[1], 1e-12, 0);
        rc_model_free(md);
    }
}

static void test_mesh_deck_errors(void)
{
    char deck[4096];
    /* a part whose elements are in no body */
    snprintf(deck, sizeof deck, "%s%s/RBODY/1\nb\n9,,,,1.0\n1,1,1\n0,0,0\n" RUN_TAIL, BOX_NODES, BOX_MESH);
    EXPECT_MESH_ERROR(deck, "card /PART/1", "1 part with elements in no rigid body", "/PART/1 (", "1 of 1 elements");
    /* an element partly in a body */
    snprintf(deck, sizeof deck, "%s%s/GRNOD/NODE/7\ng\n1,2,3,4\n/RBODY/1\nb\n9,,,,1.0,7\n1,1,1\n0,0,0\n" RUN_TAIL, BOX_NODES, BOX_MESH);
    EXPECT_MESH_ERROR(deck, ":25:", "card /BRICK/1, field node_ID5", "element 1 has 4 of its 8 nodes in /RBODY/1", "node 5 in no rigid body");
    /* an element across two bodies */
    snprintf(deck, sizeof deck, "%s%s/GRNOD/NODE/7\ng\n1,2,3,4\n/GRNOD/NODE/8\ng\n5,6,7,8\n/NODE\n10,0,0,0\n"
             "/RBODY/1\nb\n9,,,,1.0,7\n1,1,1\n0,0,0\n/RBODY/2\nc\n10,,,,1.0,8\n1,1,1\n0,0,0\n" RUN_TAIL, BOX_NODES, BOX_MESH);
    EXPECT_MESH_ERROR(deck, "card /BRICK/1, field node_ID5", "in /RBODY/1 and in /RBODY/2");
    /* a law whose density ricochet does not read */
    snprintf(deck, sizeof deck, "%s/MAT/LAW99/3\nx\n7800\n/PROP/SOLID/2\ns\n/PART/1\nbox\n2,3\n/BRICK/1\n1,1,2,3,4,5,6,7,8\n"
             "/GRNOD/PART/7\ng\n1\n/RBODY/1\nb\n9,,,,1.0,7\n1,1,1\n0,0,0\n" RUN_TAIL, BOX_NODES);
    EXPECT_MESH_ERROR(deck, "card /PART/1, field mat_ID", "/MAT/LAW99/3", "density");
    /* a shell without thickness; a shell part on a solid property */
    EXPECT_MESH_ERROR("/NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n/MAT/LAW1/1\nm\n1000\n/PROP/SHELL/2\np\n\n\n0\n"
                      "/PART/1\ns\n2,1\n/SH3N/1\n1,1,2,3\n/GRNOD/PART/3\ng\n1\n/RBODY/1\nb\n1,,,,,3\n\n\n" RUN_TAIL,
                      ":17:", "card /SH3N/1, field Thick", "thickness > 0");
    EXPECT_MESH_ERROR("/NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n/MAT/LAW1/1\nm\n1000\n/PROP/SOLID/2\np\n"
                      "/PART/1\ns\n2,1\n/SH3N/1\n1,1,2,3\n/GRNOD/PART/3\ng\n1\n/RBODY/1\nb\n1,,,,,3\n\n\n" RUN_TAIL,
                      "card /PART/1, field prop_ID", "expected a /PROP/SHELL");
    /* unknown part, node, skew, group */
    EXPECT_MESH_ERROR("/NODE\n1,0,0,0\n/BRICK/5\n1,1,1,1,1,1,1,1,1\n/RBODY/1\nb\n1,,,,1\n1,1,1\n0,0,0\n" RUN_TAIL,
                      ":4:", "card /BRICK/5, field part_ID", "no such part");
    EXPECT_MESH_ERROR("/NODE\n1,0,0,0\n/RBODY/1\nb\n1,,4,,1\n1,1,1\n0,0,0\n" RUN_TAIL, ":5:", "card /RBODY/1", "field Skew_ID",
                      "no such skew");
    EXPECT_MESH_ERROR("/NODE\n1,0,0,0\n/GRNOD/PART/3\ng\n8\n/RBODY/1\nb\n1,,,,1,3\n1,1,1\n0,0,0\n" RUN_TAIL, ":5:",
                      "card /GRNOD/PART", "field part_ID", "no such part");
    EXPECT_MESH_ERROR("/NODE\n1,0,0,0\n/GRNOD/GRNOD/3\ng\n4\n/GRNOD/GRNOD/4\nh\n3\n/RBODY/1\nb\n1,,,,1,3\n1,1,1\n0,0,0\n" RUN_TAIL,
                      "cycle");
    /* ICoG 2 without elements; the total inertia not positive definite */
    EXPECT_MESH_ERROR("/NODE\n1,0,0,0\n/RBODY/1\nb\n1,,,,1,,,2\n1,1,1\n0,0,0\n" RUN_TAIL, ":5:", "field ICoG", "no element");
    EXPECT_MESH_ERROR("/NODE\n1,0,0,0\n/RBODY/1\nb\n1,,,3,1\n0.0371,0.0371,0.0371\n0.05,0,0\n" RUN_TAIL, ":6:",
                      "card /RBODY/1", "fields Jxx..Jxz", "positive-definite", "minor 2");
    EXPECT_MESH_ERROR("/NODE\n1,0,0,0\n/RBODY/1\nb\n1,,,3,1\n1,1,2\n0,1.4142135623730951,0\n" RUN_TAIL,
                      "positive-definite");
    /* no mass at all */
    EXPECT_MESH_ERROR("/NODE\n1,0,0,0\n/RBODY/1\nb\n1\n1,1,1\n0,0,0\n" RUN_TAIL, ":5:", "field Mass", "total mass");
    /* skew axes parallel */
    EXPECT_MESH_ERROR("/SKEW/FIX/4\ns\n0,0,0\n1,1,0\n2,2,0\n" RUN_TAIL, ":5:", "card /SKEW/FIX/4", "field X2 Y2 Z2",
                      "not parallel");
}

/* /TETRA4 and a /SHELL triangle (node 4 blank) with its element Thick over
 * the property's; the law and property aliases /MAT/ELAST, /PROP/TYPE14,
 * /PROP/TYPE1. */
static void test_mesh_deck_tetra_triangle(void)
{
    rc_error e;
    rc_model *md = compile_text("/NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,0,0,1\n10,5,5,5\n"
                                "11,0,0,3\n12,1,0,3\n13,0,1,3\n20,0,0,3\n"
                                "/MAT/ELAST/1\nresin\n1200,0\n1e9,0.3\n/PROP/TYPE14/2\ns\n/PROP/TYPE1/3\nsh\n\n\n,,0.5\n"
                                "/PART/1\ntet\n2,1\n/PART/2\ntri\n3,1\n"
                                "/TETRA4/1\n1,1,2,3,4\n/SHELL/2\n1,11,12,13,,,0,0.01\n"
                                "/GRNOD/PART/5\ng\n1\n/GRNOD/PART/6\nh\n2\n"
                                "/RBODY/1\nt\n10,,,3,,5\n\n\n/RBODY/2\nt\n20,,,3,,6,,3\n\n\n" RUN_TAIL, &e);
    ENSURE(md != NULL);
    if (!md) fprintf(stderr, "  %s\n", e.msg);
    if (md) {
        ENSURE_NEAR(md->body_mass[0], 200.0, 1e-14, 0);
        for (int k = 0; k < 3; k++) ENSURE_NEAR(md->body_y0[k], 0.25, 1e-14, 0);
        ENSURE_NEAR(md->body_J[0], 15.0, 1e-13, 0);
        ENSURE_NEAR(md->body_J[1], 2.5, 1e-13, 0);
        /* the triangle: sigma = 1200 x 0.01, m = 6, about node 20 (ICoG 3):
         * Jzz = sigma (int x^2 + int y^2) = 12 (1/12 + 1/12) = 2 */
        ENSURE_NEAR(md->body_mass[1], 6.0, 1e-14, 0);
        ENSURE_NEAR(md->body_J[9 + 8], 2.0, 1e-13, 0);
        ENSURE_NEAR(md->body_y0[RC_NB + 2], 3.0, 0, 0);
        rc_model_free(md);
    }
}

/* The pentahedron (/PENTA6, the degenerate brick 1 2 3 3 4 5 6 6) against
 * its three tetrahedra (exact for plane faces), a tilted right prism; the
 * quadratic tetrahedron (/TETRA10): straight edges give the linear one, and
 * the mid-edge nodes on the quadratic map phi(X) = X + eps x^2 e_x of the
 * unit tetrahedron (reproduced exactly by the element) give the closed
 * forms m = rho int det(grad phi) = rho (1/6 + eps/12) and
 * int phi_x det = 1/24 + 3 eps/60 + 2 eps^2/120, int y det = 1/24 + 2 eps/120. */
static void test_mesh_element_penta6_tetra10(void)
{
    const double rho = 2.7;
    const double w[6][3] = {{0.1, 0.2, 0.3},      {1.3, 0.25, 0.28},  {0.2, 0.9, 0.35},
                            {0.15, 0.22, 1.4},    {1.35, 0.27, 1.38}, {0.25, 0.92, 1.45}};
    /* planar quad faces: the top is the bottom translated by (0.05, 0.02, 1.1) */
    double q[6][3];
    for (int k = 0; k < 3; k++)
        for (int d = 0; d < 3; d++) {
            q[k][d] = w[k][d];
            q[k + 3][d] = w[k][d] + (d == 0 ? 0.05 : d == 1 ? 0.02 : 1.1);
        }
    static const int map[8] = {0, 1, 2, 2, 3, 4, 5, 5};
    double h[8][3];
    for (int k = 0; k < 8; k++) memcpy(h[k], q[map[k]], sizeof h[k]);
    rc_mp a = {0, {0, 0, 0}, {0, 0, 0, 0, 0, 0}}, b = a;
    const double V = rc_mp_hex(&a, (const double(*)[3])h, rho);
    static const int tets[3][4] = {{0, 1, 2, 5}, {0, 1, 5, 4}, {0, 4, 5, 3}};
    double Vt = 0;
    for (int t = 0; t < 3; t++) {
        double p4[4][3];
        for (int k = 0; k < 4; k++) memcpy(p4[k], q[tets[t][k]], sizeof p4[k]);
        Vt += rc_mp_tet(&b, (const double(*)[3])p4, rho);
    }
    ENSURE_NEAR(V, Vt, 1e-14, 0);
    ENSURE_NEAR(a.m, b.m, 1e-14, 0);
    for (int k = 0; k < 3; k++) ENSURE_NEAR(a.s[k], b.s[k], 1e-13, 0);
    for (int k = 0; k < 6; k++) ENSURE_NEAR(a.S[k], b.S[k], 1e-13, 1e-15);
    /* TETRA10, straight edges = TETRA4 */
    const double t4[4][3] = {{0.1, 0.2, 0.3}, {1.3, 0.25, 0.28}, {0.2, 0.9, 0.35}, {0.15, 0.22, 1.4}};
    static const int edge[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
    double t10[10][3];
    for (int k = 0; k < 4; k++) memcpy(t10[k], t4[k], sizeof t10[k]);
    for (int k = 0; k < 6; k++)
        for (int d = 0; d < 3; d++) t10[4 + k][d] = 0.5 * (t4[edge[k][0]][d] + t4[edge[k][1]][d]);
    rc_mp c10 = {0, {0, 0, 0}, {0, 0, 0, 0, 0, 0}}, c4 = c10;
    ENSURE_NEAR(rc_mp_tet10(&c10, (const double(*)[3])t10, rho), rc_mp_tet(&c4, t4, rho), 1e-14, 0);
    for (int k = 0; k < 3; k++) ENSURE_NEAR(c10.s[k], c4.s[k], 1e-14, 0);
    for (int k = 0; k < 6; k++) ENSURE_NEAR(c10.S[k], c4.S[k], 1e-13, 1e-16);
    /* TETRA10 on phi(X) = X + eps x^2 e_x (either numbering orientation) */
    const double eps = 0.37, u[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int flip = 0; flip < 2; flip++) {
        double X[10][3];
        for (int k = 0; k < 4; k++) memcpy(X[k], u[flip && k >= 2 ? 5 - k : k], sizeof X[k]);
        for (int k = 0; k < 6; k++)
            for (int d = 0; d < 3; d++) X[4 + k][d] = 0.5 * (X[edge[k][0]][d] + X[edge[k][1]][d]);
        for (int k = 0; k < 10; k++) X[k][0] += eps * X[k][0] * X[k][0];
        rc_mp m = {0, {0, 0, 0}, {0, 0, 0, 0, 0, 0}};
        rc_mp_tet10(&m, (const double(*)[3])X, 1.0);
        ENSURE_NEAR(m.m, 1.0 / 6.0 + eps / 12.0, 1e-14, 0);
        ENSURE_NEAR(m.s[0], 1.0 / 24.0 + 3 * eps / 60.0 + 2 * eps * eps / 120.0, 1e-14, 0);
        ENSURE_NEAR(m.s[1], 1.0 / 24.0 + 2 * eps / 120.0, 1e-14, 0);
    }
}

/* /PENTA6 and /TETRA10 read (a TETRA10 element is two lines; a blank
 * mid-edge node is the midpoint) and integrated into their body's mass. */
static void test_mesh_deck_penta6_tetra10(void)
{
    rc_error e;
    rc_model *md = compile_text("/NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,0,0,2\n5,1,0,2\n6,0,1,2\n10,5,5,5\n"
                                "21,0,0,5\n22,1,0,5\n23,0,1,5\n24,0,0,6\n25,0.5,0,5\n26,0.5,0.5,5\n"
                                "/MAT/LAW1/1\nm\n1000\n/PART/1\nwedge\n0,1\n/PART/2\ntet10\n0,1\n"
                                "/PENTA6/1\n         7         1         2         3         4         5         6\n"
                                "/TETRA10/2\n         8\n        21        22        23        24        25        26"
                                "                                        \n"
                                "/GRNOD/PART/5\ng\n1\n/GRNOD/PART/6\nh\n2\n"
                                "/RBODY/1\nw\n10,,,3,,5\n\n\n/RBODY/2\nt\n21,,,3,,6\n\n\n" RUN_TAIL, &e);
    ENSURE(md != NULL);
    if (!md) fprintf(stderr, "  %s\n", e.msg);
    if (md) {
        /* a right prism: area 1/2, height 2: 1000 kg; centroid (1/3, 1/3, 1) */
        ENSURE_NEAR(md->body_mass[0], 1000.0, 1e-13, 0);
        ENSURE_NEAR(md->body_y0[0], 1.0 / 3.0, 1e-14, 0);
        ENSURE_NEAR(md->body_y0[2], 1.0, 1e-14, 0);
        /* a straight TETRA10 (three mid nodes blank): the tetrahedron 1000/6 kg */
        ENSURE_NEAR(md->body_mass[1], 1000.0 / 6.0, 1e-13, 0);
        ENSURE_NEAR(md->body_y0[RC_NB + 2], 5.25, 1e-14, 0);
        rc_model_free(md);
    }
    /* an element of one line: the node line is missing */
    EXPECT_MESH_ERROR("/NODE\n1,0,0,0\n/TETRA10/2\n8\n" RUN_TAIL, ":4:", "card /TETRA10/2", "field node_ID1",
                      "ten nodes");
}

/* /ADMAS: type 0 on each node, type 1 shared; on the main node it acts as
 * the card's Mass (ICoG 4 keeps it, drops the secondary nodes'). */
static void test_mesh_deck_admas(void)
{
    rc_error e;
    const char *d1 = "/NODE\n1,0,0,0\n2,2,0,0\n3,0,2,0\n/GRNOD/NODE/5\ng\n2,3\n/GRNOD/NODE/6\nm\n1\n"
                     "/ADMAS/0/1\nper node\n1.5,5\n/ADMAS/1/2\nshared\n2.0,6\n"
                     "/RBODY/1\nb\n1,,,3,1.0,5,,1\n0.1,0.1,0.1\n\n" RUN_TAIL;
    rc_model *md = compile_text(d1, &e);
    ENSURE(md != NULL);
    if (!md) fprintf(stderr, "  %s\n", e.msg);
    if (md) {
        ENSURE_NEAR(md->body_mass[0], 6.0, 1e-15, 0);
        ENSURE_NEAR(md->body_y0[0], 0.5, 1e-15, 0);
        ENSURE_NEAR(md->body_y0[1], 0.5, 1e-15, 0);
        ENSURE_NEAR(md->body_J[8], 9.1, 1e-14, 0);
        rc_model_free(md);
    }
    md = compile_text("/NODE\n1,0,0,0\n2,2,0,0\n3,0,2,0\n/GRNOD/NODE/5\ng\n2,3\n/GRNOD/NODE/6\nm\n1\n"
                      "/ADMAS/0/1\nper node\n1.5,5\n/ADMAS/1/2\nshared\n2.0,6\n"
                      "/RBODY/1\nb\n1,,,3,1.0,5,,4\n0.1,0.1,0.1\n\n" RUN_TAIL, &e);
    ENSURE(md != NULL);
    if (md) {
        ENSURE_NEAR(md->body_mass[0], 3.0, 1e-15, 0);
        ENSURE_NEAR(md->body_J[8], 0.1, 1e-15, 0);
        rc_model_free(md);
    }
    EXPECT_MESH_ERROR("/NODE\n1,0,0,0\n2,2,0,0\n/GRNOD/NODE/5\ng\n2\n/ADMAS/0/1\nx\n1.5,5\n"
                      "/RBODY/1\nb\n1,,,,1.0\n0.1,0.1,0.1\n\n" RUN_TAIL,
                      ":9:", "card /ADMAS/0/1, field grnd_ID", "node 2 of /GRNOD/5 is in no rigid body");
    EXPECT_MESH_ERROR("/NODE\n1,0,0,0\n/ADMAS/3/1\nx\n1.5,5\n" RUN_TAIL, ":3:", "field type", "not supported yet");
}

/* The Radioss 2022 layout as written by a pre-processor: fixed columns,
 * comment lines, line 4 with Ioptoff and Ifail; a 2019 line 4 (Ioptoff,
 * Iexpams); a warning for Ifail (the sensor is a reference). */
static void test_mesh_rbody_layouts(void)
{
    rc_case *c = NULL;
    rc_error e;
    const char *p = write_deck(
        "/NODE\n         1                 0.0                 0.0                 0.0\n"
        "         2                 1.0                 0.0                 0.0\n"
        "/RBODY/1\nbody 2022\n"
        "#  node_ID   sens_ID   Skew_ID    Ispher                Mass   grnd_ID     Ikrem      ICoG   surf_ID\n"
        "         1         5         0         3                 1.5         0         1         3         0\n"
        "#                Jxx                 Jyy                 Jzz\n"
        "                 0.1                 0.2                 0.3\n"
        "#                Jxy                 Jyz                 Jxz\n"
        "                0.01                0.02                0.03\n"
        "#  Ioptoff               Ifail\n"
        "         1         0         1\n"
        "#                 FN                  FT                expN                expT\n"
        "               1.0E4               2.0E4                 2.0                 2.0\n"
        "/RBODY/2\nbody 2019\n"
        "         2         0         0         0                 1.0         0         0         0         0\n"
        "                 0.1                 0.1                 0.1\n"
        "                 0.0                 0.0                 0.0\n"
        "         0         2\n" RUN_TAIL);
    rc_error_clear(&e);
    ENSURE(rc_case_load(p, &c, &e) == RC_OK);
    if (!c) fprintf(stderr, "  %s\n", e.msg);
    if (c) {
        const rc_case_rbody *r = &c->rbody[0];
        ENSURE(c->nrbody == 2 && r->sens_id == 5 && r->ispher == 3 && r->mass == 1.5 && r->ikrem == 1 && r->icog == 3);
        ENSURE(r->J[2] == 0.3 && r->J[5] == 0.03 && r->ioptoff == 1 && r->ifail == 1 && r->fail[1] == 2.0e4);
        ENSURE(c->rbody[1].iexpams == 2 && c->rbody[1].ifail == 0);
        /* the sensor is a reference (resolved by the compiler): no warning */
        ENSURE(c->nwarnings == 1);
        if (c->nwarnings == 1) ENSURE(strstr(c->warnings[0], "field Ifail") != NULL);
        rc_case_free(c);
    }
    remove(mesh_path);
}

void suite_mesh(void);
void suite_mesh(void)
{
    RUN_TEST(test_mesh_element_closed_forms);
    RUN_TEST(test_mesh_element_consistency);
    RUN_TEST(test_mesh_convergence_sphere_cylinder);
    RUN_TEST(test_mesh_deck_brick_box_icog);
    RUN_TEST(test_mesh_deck_skew_ispher);
    RUN_TEST(test_mesh_deck_skew_loads);
    RUN_TEST(test_mesh_deck_shell_box_groups);
    RUN_TEST(test_mesh_deck_tetra_triangle);
    RUN_TEST(test_mesh_element_penta6_tetra10);
    RUN_TEST(test_mesh_deck_penta6_tetra10);
    RUN_TEST(test_mesh_deck_admas);
    RUN_TEST(test_mesh_deck_errors);
    RUN_TEST(test_mesh_rbody_layouts);
}
