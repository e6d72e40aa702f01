/*
 * Mass properties of the rigid bodies from their mesh (massprop.h,
 * docs/theory.md "Mass properties from the mesh").
 *
 * Integration is exact for the element shapes as defined:
 *  - triangle (plate): closed form of int r r^T dA over a flat triangle;
 *  - quadrilateral (plate): the bilinear surface, 3x3 Gauss points (exact
 *    for a flat quadrilateral, whose area element is linear in xi, eta;
 *    a warped one is integrated to the quadrature's accuracy);
 *  - tetrahedron: closed form of int r r^T dV;
 *  - hexahedron: the trilinear solid, 3x3x3 Gauss points, exact for any
 *    trilinear map (det J and r r^T are of degree <= 2 in each variable,
 *    their product of degree <= 4: 3 points per direction suffice).
 * Plates carry, besides their mid-surface, the through-thickness second
 * moment sigma t^2/12 n n^T per unit area (exact for a flat plate).
 */
#include "model/massprop.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_vector.h>

#include "base/error.h"
#include "case/case_mesh.h"

/* ---- elements ---------------------------------------------------------- */

static void cross3(const double *a, const double *b, double *o)
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

/* Add a point-like contribution w at r (mass, moments). */
static void add_point(rc_mp *a, const double *r, double w)
{
    a->m += w;
    for (int k = 0; k < 3; k++) a->s[k] += w * r[k];
    a->S[0] += w * r[0] * r[0];
    a->S[1] += w * r[1] * r[1];
    a->S[2] += w * r[2] * r[2];
    a->S[3] += w * r[0] * r[1];
    a->S[4] += w * r[1] * r[2];
    a->S[5] += w * r[0] * r[2];
}

/* Add w n n^T to the second moment (the through-thickness term). */
static void add_nn(rc_mp *a, const double *n, double w)
{
    a->S[0] += w * n[0] * n[0];
    a->S[1] += w * n[1] * n[1];
    a->S[2] += w * n[2] * n[2];
    a->S[3] += w * n[0] * n[1];
    a->S[4] += w * n[1] * n[2];
    a->S[5] += w * n[0] * n[2];
}

/* Simplex closed forms: for a simplex of measure V with vertices p_k,
 * int r dV = V mean(p), int r r^T dV = V/(d+1)/(d+2) (sum p p^T + s s^T)
 * with s = sum p (d = 2: 1/12; d = 3: 1/20). */
static void add_simplex(rc_mp *a, const double (*p)[3], int nv, double w, double V)
{
    double s[3] = {0, 0, 0}, P[6] = {0, 0, 0, 0, 0, 0};
    const double f = nv == 3 ? 1.0 / 12.0 : 1.0 / 20.0;
    for (int k = 0; k < nv; k++) {
        for (int i = 0; i < 3; i++) s[i] += p[k][i];
        P[0] += p[k][0] * p[k][0];
        P[1] += p[k][1] * p[k][1];
        P[2] += p[k][2] * p[k][2];
        P[3] += p[k][0] * p[k][1];
        P[4] += p[k][1] * p[k][2];
        P[5] += p[k][0] * p[k][2];
    }
    const double mw = w * V;
    a->m += mw;
    for (int i = 0; i < 3; i++) a->s[i] += mw * s[i] / nv;
    a->S[0] += mw * f * (P[0] + s[0] * s[0]);
    a->S[1] += mw * f * (P[1] + s[1] * s[1]);
    a->S[2] += mw * f * (P[2] + s[2] * s[2]);
    a->S[3] += mw * f * (P[3] + s[0] * s[1]);
    a->S[4] += mw * f * (P[4] + s[1] * s[2]);
    a->S[5] += mw * f * (P[5] + s[0] * s[2]);
}

double rc_mp_tri(rc_mp *a, const double p[3][3], double sigma, double t)
{
    double e1[3], e2[3], n[3];
    for (int i = 0; i < 3; i++) {
        e1[i] = p[1][i] - p[0][i];
        e2[i] = p[2][i] - p[0][i];
    }
    cross3(e1, e2, n);
    const double A2 = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), A = 0.5 * A2;
    if (!(A2 > 0)) return 0.0;
    add_simplex(a, p, 3, sigma, A);
    for (int i = 0; i < 3; i++) n[i] /= A2;
    add_nn(a, n, sigma * A * t * t / 12.0);
    return A;
}

/* Gauss-Legendre, 3 points on [-1, 1]. */
static const double GX[3] = {-0.77459666924148337704, 0.0, 0.77459666924148337704};
static const double GW[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};

double rc_mp_quad(rc_mp *a, const double p[4][3], double sigma, double t)
{
    static const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    double area = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            const double xi = GX[i], eta = GX[j];
            double r[3] = {0, 0, 0}, dx[3] = {0, 0, 0}, de[3] = {0, 0, 0}, n[3];
            for (int k = 0; k < 4; k++) {
                const double N = 0.25 * (1 + sx[k] * xi) * (1 + sy[k] * eta);
                const double Nx = 0.25 * sx[k] * (1 + sy[k] * eta), Ne = 0.25 * sy[k] * (1 + sx[k] * xi);
                for (int d = 0; d < 3; d++) {
                    r[d] += N * p[k][d];
                    dx[d] += Nx * p[k][d];
                    de[d] += Ne * p[k][d];
                }
            }
            cross3(dx, de, n);
            const double J = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            if (!(J > 0)) continue;
            const double w = GW[i] * GW[j] * J;
            area += w;
            add_point(a, r, sigma * w);
            for (int d = 0; d < 3; d++) n[d] /= J;
            add_nn(a, n, sigma * w * t * t / 12.0);
        }
    return area;
}

double rc_mp_tet(rc_mp *a, const double p[4][3], double rho)
{
    double e1[3], e2[3], e3[3], n[3];
    for (int i = 0; i < 3; i++) {
        e1[i] = p[1][i] - p[0][i];
        e2[i] = p[2][i] - p[0][i];
        e3[i] = p[3][i] - p[0][i];
    }
    cross3(e1, e2, n);
    const double V = fabs(n[0] * e3[0] + n[1] * e3[1] + n[2] * e3[2]) / 6.0;
    add_simplex(a, p, 4, rho, V);
    return V;
}

double rc_mp_hex(rc_mp *a, const double p[8][3], double rho)
{
    static const double sx[8] = {-1, 1, 1, -1, -1, 1, 1, -1}, sy[8] = {-1, -1, 1, 1, -1, -1, 1, 1},
                        sz[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
    rc_mp e = {0, {0, 0, 0}, {0, 0, 0, 0, 0, 0}};
    double vol = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            for (int l = 0; l < 3; l++) {
                const double xi = GX[i], eta = GX[j], zeta = GX[l];
                double r[3] = {0, 0, 0}, g[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, n[3];
                for (int k = 0; k < 8; k++) {
                    const double ax = 1 + sx[k] * xi, ay = 1 + sy[k] * eta, az = 1 + sz[k] * zeta;
                    const double N = 0.125 * ax * ay * az;
                    const double dN[3] = {0.125 * sx[k] * ay * az, 0.125 * ax * sy[k] * az,
                                          0.125 * ax * ay * sz[k]};
                    for (int d = 0; d < 3; d++) {
                        r[d] += N * p[k][d];
                        for (int q = 0; q < 3; q++) g[q][d] += dN[q] * p[k][d];
                    }
                }
                cross3(g[0], g[1], n);
                const double w = GW[i] * GW[j] * GW[l] * (n[0] * g[2][0] + n[1] * g[2][1] + n[2] * g[2][2]);
                vol += w;
                add_point(&e, r, w); /* signed volume weights */
            }
    /* a numbering of the other orientation gives a negative volume: the
     * same solid */
    const double sg = vol < 0 ? -rho : rho;
    a->m += sg * e.m;
    for (int k = 0; k < 3; k++) a->s[k] += sg * e.s[k];
    for (int k = 0; k < 6; k++) a->S[k] += sg * e.S[k];
    return fabs(vol);
}

/* Gauss-Legendre, 5 points on [0, 1] (the collapsed-coordinate rule of
 * the quadratic tetrahedron). */
static const double G5X[5] = {0.04691007703066800360, 0.23076534494715845448, 0.5, 0.76923465505284154552,
                              0.95308992296933199640};
static const double G5W[5] = {0.11846344252809454376, 0.23931433524968323402, 0.28444444444444444444,
                              0.23931433524968323402, 0.11846344252809454376};

double rc_mp_tet10(rc_mp *a, const double p[10][3], double rho)
{
    /* barycentric L = (1 - x - y - z, x, y, z); corners N_i = L_i (2 L_i - 1),
     * mid-edge N_ij = 4 L_i L_j (edges 01 12 20 03 13 23). The integrands
     * (det J of degree 3 times r r^T of degree 4) are polynomials of degree
     * 7; the Duffy map x = u, y = v (1 - u), z = w (1 - u)(1 - v) adds the
     * factor (1 - u)^2 (1 - v): degree 9 at most in u, exact with 5 points. */
    static const int edge[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
    static const double dL[4][3] = {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    rc_mp e = {0, {0, 0, 0}, {0, 0, 0, 0, 0, 0}};
    double vol = 0;
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 5; j++)
            for (int l = 0; l < 5; l++) {
                const double u = G5X[i], v = G5X[j], s = G5X[l];
                const double x = u, y = v * (1 - u), z = s * (1 - u) * (1 - v);
                const double duffy = (1 - u) * (1 - u) * (1 - v);
                const double L[4] = {1 - x - y - z, x, y, z};
                double N[10], dN[10][3];
                for (int k = 0; k < 4; k++) {
                    N[k] = L[k] * (2 * L[k] - 1);
                    for (int q = 0; q < 3; q++) dN[k][q] = (4 * L[k] - 1) * dL[k][q];
                }
                for (int k = 0; k < 6; k++) {
                    const int a0 = edge[k][0], a1 = edge[k][1];
                    N[4 + k] = 4 * L[a0] * L[a1];
                    for (int q = 0; q < 3; q++) dN[4 + k][q] = 4 * (dL[a0][q] * L[a1] + L[a0] * dL[a1][q]);
                }
                double r[3] = {0, 0, 0}, g[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, n[3];
                for (int k = 0; k < 10; k++)
                    for (int d = 0; d < 3; d++) {
                        r[d] += N[k] * p[k][d];
                        for (int q = 0; q < 3; q++) g[q][d] += dN[k][q] * p[k][d];
                    }
                cross3(g[0], g[1], n);
                const double w = G5W[i] * G5W[j] * G5W[l] * duffy * (n[0] * g[2][0] + n[1] * g[2][1] + n[2] * g[2][2]);
                vol += w;
                add_point(&e, r, w);
            }
    const double sg = vol < 0 ? -rho : rho;
    a->m += sg * e.m;
    for (int k = 0; k < 3; k++) a->s[k] += sg * e.s[k];
    for (int k = 0; k < 6; k++) a->S[k] += sg * e.S[k];
    return fabs(vol);
}

void rc_mp_inertia(const rc_mp *a, double c[3], double J[9])
{
    double S[6];
    for (int k = 0; k < 3; k++) c[k] = a->s[k] / a->m;
    /* second moment about c: S - m c c^T */
    S[0] = a->S[0] - a->m * c[0] * c[0];
    S[1] = a->S[1] - a->m * c[1] * c[1];
    S[2] = a->S[2] - a->m * c[2] * c[2];
    S[3] = a->S[3] - a->m * c[0] * c[1];
    S[4] = a->S[4] - a->m * c[1] * c[2];
    S[5] = a->S[5] - a->m * c[0] * c[2];
    const double tr = S[0] + S[1] + S[2];
    J[0] = tr - S[0];
    J[4] = tr - S[1];
    J[8] = tr - S[2];
    J[1] = J[3] = -S[3];
    J[5] = J[7] = -S[4];
    J[2] = J[6] = -S[5];
}

/* ---- bodies ------------------------------------------------------------ */

static const char *elem_card(rc_elem_kind k)
{
    return k == RC_ELEM_SHELL ? "/SHELL" : k == RC_ELEM_SH3N ? "/SH3N" : k == RC_ELEM_BRICK ? "/BRICK"
           : k == RC_ELEM_PENTA6 ? "/PENTA6" : k == RC_ELEM_TETRA10 ? "/TETRA10" : "/TETRA4";
}

/* Ispher 2 (Radioss's automatic correction): principal moments below 1e-3
 * of the largest are raised by 0.1 of the largest (GSL eigen solver). */
static int ispher2(double J[9])
{
    double a[9], lam[3], R[9];
    memcpy(a, J, sizeof a);
    gsl_matrix_view A = gsl_matrix_view_array(a, 3, 3);
    gsl_vector_view L = gsl_vector_view_array(lam, 3);
    gsl_matrix_view V = gsl_matrix_view_array(R, 3, 3);
    gsl_eigen_symmv_workspace *w = gsl_eigen_symmv_alloc(3);
    if (!w) return -1;
    int st = gsl_eigen_symmv(&A.matrix, &L.vector, &V.matrix, w);
    gsl_eigen_symmv_free(w);
    if (st) return -1;
    const double mx = fmax(lam[0], fmax(lam[1], lam[2]));
    int changed = 0;
    if (!(mx > 0)) return 0;
    for (int k = 0; k < 3; k++)
        if (lam[k] < 1e-3 * mx) {
            lam[k] += 0.1 * mx;
            changed = 1;
        }
    if (!changed) return 0;
    /* J = R diag(lam) R^T, columns of R the principal axes */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double s = 0;
            for (int k = 0; k < 3; k++) s += R[3 * i + k] * lam[k] * R[3 * j + k];
            J[3 * i + j] = s;
        }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < i; j++) J[3 * i + j] = J[3 * j + i] = 0.5 * (J[3 * i + j] + J[3 * j + i]);
    return 1;
}

/* Positive definite (Cholesky, pivots above 1e-12 of their diagonal):
 * 0, else the failing leading minor. */
static int pd_minor(const double *J)
{
    double l11, l21, l31, l22, l32, d;
    if (!(J[0] > 0) || !isfinite(J[0])) return 1;
    l11 = sqrt(J[0]);
    l21 = J[1] / l11;
    l31 = J[2] / l11;
    d = J[4] - l21 * l21;
    if (!(d > 1e-12 * J[4]) || !isfinite(d)) return 2;
    l22 = sqrt(d);
    l32 = (J[5] - l21 * l31) / l22;
    d = J[8] - l31 * l31 - l32 * l32;
    if (!(d > 1e-12 * J[8]) || !isfinite(d)) return 3;
    return 0;
}

typedef struct mp_work {
    double *part_rho, *part_t; /* [npart] density, property thickness (resolved once) */
    char *part_done;  /* [npart] 1: shells resolved, 2: solids resolved */
    int *node_body;   /* [nnode] body index, -1 none, -2 - b: also claimed by a second body */
    int *second;      /* [nnode] the second body claiming a node (-1) */
    rc_mp *acc;       /* [nrbody] about the main node */
    double *main_add; /* [nrbody] /ADMAS mass on the main node (acts as the card's Mass) */
    int *part_in, *part_out; /* [npart] elements in a body / in none */
} mp_work;

static rc_status mark_nodes(const rc_case *c, mp_work *w, rc_error *err)
{
    for (int n = 0; n < c->nnode; n++) w->node_body[n] = -1, w->second[n] = -1;
    for (int b = 0; b < c->nrbody; b++) {
        const rc_case_rbody *rb = &c->rbody[b];
        const int g = rb->grnod_id ? rc_case_find_grnod(c, rb->grnod_id) : -1;
        const int n0 = g >= 0 ? c->grnod[g].n : 0;
        for (int k = -1; k < n0; k++) {
            const int id = k < 0 ? rb->node_id : c->grnod[g].nodes[k];
            const int n = rc_case_find_node(c, id);
            if (n < 0) {
                if (k < 0) continue; /* the main node: the compiler's error */
                RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /GRNOD/%d, field node_ID: expected the id of a /NODE, got %d (no such node; the group is /RBODY/%d's grnd_ID)",
                         RC_LOC(c->grnod[g].loc), c->grnod[g].id, id, rb->id);
            }
            if (w->node_body[n] == -1) w->node_body[n] = b;
            else if (w->node_body[n] != b && w->second[n] < 0) w->second[n] = b;
        }
    }
    return RC_OK;
}

/* Density of part p's material, and the thickness of its /PROP/SHELL (0
 * for solids), checked against element e (named in the messages). */
static rc_status part_material(const rc_case *c, const rc_case_part *p, const rc_case_elem *e, double *rho,
                               double *t, rc_error *err)
{
    const int mi = rc_case_find_mat(c, p->mat_id);
    char card[40];
    snprintf(card, sizeof card, "/PART/%d", p->id);
    if (mi < 0)
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field mat_ID: expected the id of a /MAT, got %d (no such material; the part has elements, e.g. %s/%d element %d at %s:%d)",
                 RC_LOC(p->prop_loc), card, p->mat_id, elem_card(e->kind), e->part_id, e->id, e->loc.file, e->loc.line);
    const rc_case_mat *m = &c->mesh->mat[mi];
    if (!m->has_rho)
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field mat_ID: material /MAT/%s/%d (%s:%d): ricochet does not know where this law keeps its density; expected one of the laws listed in docs/case-format.md (LAW1, LAW2, LAW36, ...)",
                 RC_LOC(p->prop_loc), card, m->law, m->id, m->loc.file, m->loc.line);
    if (!(m->rho > 0))
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /MAT/%s/%d, field Init. dens.: expected a density > 0 [kg/m^3] for the elements of /PART/%d, got %g",
                 RC_LOC(m->rho_loc), m->law, m->id, p->id, m->rho);
    *rho = m->rho;
    *t = 0;
    const int shell = e->kind == RC_ELEM_SHELL || e->kind == RC_ELEM_SH3N;
    const int pi = p->prop_id ? rc_case_find_prop(c, p->prop_id) : -1;
    if (p->prop_id && pi < 0)
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field prop_ID: expected the id of a /PROP/%s, got %d (no such property among /PROP/SHELL and /PROP/SOLID)",
                 RC_LOC(p->prop_loc), card, shell ? "SHELL" : "SOLID", p->prop_id);
    if (pi >= 0 && c->mesh->prop[pi].kind == RC_PROP_SPRING)
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field prop_ID: expected a /PROP/%s for the %s elements of the part, got the spring property %d",
                 RC_LOC(p->prop_loc), card, shell ? "SHELL" : "SOLID", elem_card(e->kind), p->prop_id);
    if (pi >= 0 && (c->mesh->prop[pi].kind == RC_PROP_SHELL) != shell)
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field prop_ID: expected a /PROP/%s for the %s elements of the part, got /PROP/%s/%d",
                 RC_LOC(p->prop_loc), card, shell ? "SHELL" : "SOLID", elem_card(e->kind), shell ? "SOLID" : "SHELL", p->prop_id);
    if (shell && pi >= 0) *t = c->mesh->prop[pi].thick;
    return RC_OK;
}

/* Integrate the elements into their bodies. */
static rc_status mesh_elements(const rc_case *c, mp_work *w, rc_error *err)
{
    const rc_case_mesh *ms = c->mesh;
    int last_part = 0, pi = -1;
    for (int e = 0; ms && e < ms->nelem; e++) {
        const rc_case_elem *el = &ms->elem[e];
        const char *card = elem_card(el->kind);
        int nd[10], body = -1, nin = 0, npres = 0;
        if (el->part_id != last_part || pi < 0) {
            pi = rc_case_find_part(c, el->part_id);
            last_part = el->part_id;
        }
        if (pi < 0)
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s/%d, field part_ID: expected the id of a /PART in the header, got %d (no such part)",
                     RC_LOC(el->loc), card, el->part_id, el->part_id);
        for (int k = 0; k < el->nn; k++) {
            nd[k] = -1;
            if (el->nodes[k] == 0) continue; /* a TETRA10 straight edge: its midpoint */
            npres++;
            nd[k] = rc_case_find_node(c, el->nodes[k]);
            if (nd[k] < 0)
                RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s/%d, field node_ID%d: expected the id of a /NODE, got %d (no such node; element %d)",
                         RC_LOC(el->loc), card, el->part_id, k + 1, el->nodes[k], el->id);
            const int b = w->node_body[nd[k]];
            if (b >= 0 && w->second[nd[k]] >= 0)
                RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s/%d, field node_ID%d: node %d of element %d is in /RBODY/%d and /RBODY/%d: an element's nodes belong to one rigid body",
                         RC_LOC(el->loc), card, el->part_id, k + 1, el->nodes[k], el->id, c->rbody[b].id, c->rbody[w->second[nd[k]]].id);
            if (b >= 0) {
                nin++;
                if (body >= 0 && b != body)
                    RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s/%d, field node_ID%d: element %d has nodes in /RBODY/%d and in /RBODY/%d (node %d): an element belongs to one rigid body whole",
                             RC_LOC(el->loc), card, el->part_id, k + 1, el->id, c->rbody[body].id, c->rbody[b].id, el->nodes[k]);
                body = b;
            }
        }
        if (nin == 0) {
            w->part_out[pi]++;
            continue;
        }
        if (nin < npres) {
            int out = 0, ko = 0;
            for (int k = 0; k < el->nn; k++)
                if (nd[k] >= 0 && w->node_body[nd[k]] < 0) { out = el->nodes[k]; ko = k; break; }
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s/%d, field node_ID%d: element %d has %d of its %d nodes in /RBODY/%d and node %d in no rigid body: an element belongs to one rigid body whole (add its nodes to the body's grnd_ID group)",
                     RC_LOC(el->loc), card, el->part_id, ko + 1, el->id, nin, npres, c->rbody[body].id, out);
        }
        w->part_in[pi]++;
        const int shell = el->kind == RC_ELEM_SHELL || el->kind == RC_ELEM_SH3N;
        if (w->part_done[pi] != 1 + !shell) {
            /* first element of the part (or of the other kind): resolve */
            rc_status st = part_material(c, &c->part[pi], el, &w->part_rho[pi], &w->part_t[pi], err);
            if (st) return st;
            w->part_done[pi] = (char)(1 + !shell);
        }
        const double rho = w->part_rho[pi];
        const double t = !shell ? 0 : el->thick > 0 ? el->thick : w->part_t[pi];
        if (shell && !(t > 0))
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s/%d, field Thick: expected a shell thickness > 0 [m] for element %d (element Thick or the Thick of /PROP/SHELL/%d), got 0",
                     RC_LOC(el->loc), card, el->part_id, el->id, c->part[pi].prop_id);
        /* vertices relative to the body's main node */
        const int mn = rc_case_find_node(c, c->rbody[body].node_id);
        const double *r0 = mn >= 0 ? c->node[mn].x : c->node[nd[0]].x;
        double p[10][3];
        for (int k = 0; k < el->nn; k++)
            for (int d = 0; d < 3; d++) p[k][d] = nd[k] >= 0 ? c->node[nd[k]].x[d] - r0[d] : 0.0;
        if (el->kind == RC_ELEM_TETRA10) { /* missing mid-edge nodes: the midpoints */
            static const int edge[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
            for (int k = 4; k < 10; k++)
                if (nd[k] < 0)
                    for (int d = 0; d < 3; d++) p[k][d] = 0.5 * (p[edge[k - 4][0]][d] + p[edge[k - 4][1]][d]);
        }
        double size;
        switch (el->kind) {
        case RC_ELEM_SHELL:
        case RC_ELEM_SH3N:
            size = el->nn == 3 ? rc_mp_tri(&w->acc[body], (const double(*)[3])p, rho * t, t)
                               : rc_mp_quad(&w->acc[body], (const double(*)[3])p, rho * t, t);
            break;
        case RC_ELEM_TETRA4: size = rc_mp_tet(&w->acc[body], (const double(*)[3])p, rho); break;
        case RC_ELEM_TETRA10: size = rc_mp_tet10(&w->acc[body], (const double(*)[3])p, rho); break;
        case RC_ELEM_PENTA6: { /* the degenerate brick 1 2 3 3 4 5 6 6 (trilinear, exact) */
            double h[8][3];
            static const int map[8] = {0, 1, 2, 2, 3, 4, 5, 5};
            for (int k = 0; k < 8; k++) memcpy(h[k], p[map[k]], sizeof h[k]);
            size = rc_mp_hex(&w->acc[body], (const double(*)[3])h, rho);
            break;
        }
        default: size = rc_mp_hex(&w->acc[body], (const double(*)[3])p, rho); break;
        }
        if (!(size > 0))
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s/%d: element %d has a zero %s (coincident or aligned nodes)",
                     RC_LOC(el->loc), card, el->part_id, el->id, el->kind <= RC_ELEM_SH3N ? "area" : "volume");
    }
    return RC_OK;
}


/* A point mass mk [kg] at node n of body b: onto the body's main node when n
 * is that node, else a point of the body's inertia about the main node. */
static void node_mass(const rc_case *c, mp_work *w, int b, int n, double mk)
{
    const int mn = rc_case_find_node(c, c->rbody[b].node_id);
    if (mn == n) {
        w->main_add[b] += mk;
        return;
    }
    double r[3];
    for (int d = 0; d < 3; d++) r[d] = c->node[n].x[d] - (mn >= 0 ? c->node[mn].x[d] : 0);
    add_point(&w->acc[b], r, mk);
}

/* /ADMAS: point masses on nodes of the bodies. */
static rc_status nodal_masses(const rc_case *c, mp_work *w, rc_error *err)
{
    for (int k = 0; c->mesh && k < c->mesh->nadmas; k++) {
        const rc_case_admas *ad = &c->mesh->admas[k];
        const int g = rc_case_find_grnod(c, ad->grnod_id);
        if (g < 0)
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /ADMAS/%d/%d, field grnd_ID: expected the id of a /GRNOD, got %d (no such group)",
                     RC_LOC(ad->line_loc), ad->type, ad->id, ad->grnod_id);
        const int nn = c->grnod[g].n;
        for (int j = 0; j < nn; j++) {
            const int id = c->grnod[g].nodes[j], n = rc_case_find_node(c, id);
            const int b = n >= 0 ? w->node_body[n] : -1;
            if (b < 0 || w->second[n] >= 0)
                RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /ADMAS/%d/%d, field grnd_ID: node %d of /GRNOD/%d %s: an added mass belongs to one rigid body",
                         RC_LOC(ad->line_loc), ad->type, ad->id, id, ad->grnod_id,
                         n < 0 ? "does not exist" : b < 0 ? "is in no rigid body" : "is in two rigid bodies");
            node_mass(c, w, b, n, ad->type == 0 ? ad->mass : ad->mass / nn);
        }
    }
    return RC_OK;
}

/* The mass of the /PROP/SPRING (TYPE4), /PROP/SPR_GENE (TYPE8) and
 * /PROP/SPR_BEAM (TYPE13) springs (not
 * their inertia, docs/case-format.md): half on each node, as
 * Radioss lumps it; a node of a rigid body gives its share to the body
 * (a point mass, or the main node's mass), a node in no body keeps it (a
 * point fixed in space). Springs whose part or property does not resolve
 * are the coupling compiler's errors (model/coupling.c). */
static void spring_masses(const rc_case *c, mp_work *w)
{
    for (int e = 0; c->mesh && e < c->mesh->nspring; e++) {
        const rc_case_spring *se = &c->mesh->spring[e];
        const int pi = rc_case_find_part(c, se->part_id);
        const int qi = pi >= 0 && c->part[pi].prop_id ? rc_case_find_prop(c, c->part[pi].prop_id) : -1;
        if (qi < 0 || c->mesh->prop[qi].kind != RC_PROP_SPRING || c->mesh->prop[qi].sprtype == 0)
            continue;
        const double mk = 0.5 * c->mesh->prop[qi].mass;
        if (!(mk > 0)) continue;
        for (int j = 0; j < 2; j++) {
            const int n = rc_case_find_node(c, se->nodes[j]);
            const int b = n >= 0 ? w->node_body[n] : -1;
            if (b < 0) continue;
            node_mass(c, w, b, n, mk);
        }
    }
}

/* Parts with elements in no rigid body: one error listing them. */
static rc_status orphan_parts(const rc_case *c, const mp_work *w, rc_error *err)
{
    char list[1024];
    size_t k = 0;
    int n = 0, first = -1;
    for (int p = 0; p < c->npart; p++) {
        if (!w->part_out[p]) continue;
        if (first < 0) first = p;
        if (n++ < 8 && k < sizeof list)
            k += (size_t)snprintf(list + k, sizeof list - k, "%s/PART/%d (%s:%d, %d of %d elements)", n > 1 ? ", " : "",
                                  c->part[p].id, c->part[p].loc.file, c->part[p].loc.line, w->part_out[p],
                                  w->part_out[p] + w->part_in[p]);
    }
    if (first < 0) return RC_OK;
    if (n > 8 && k < sizeof list) snprintf(list + k, sizeof list - k, " and %d more", n - 8);
    RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /PART/%d: %d part%s with elements in no rigid body: %s; ricochet bodies are rigid: give the nodes of every element to a /RBODY (main node or grnd_ID group, e.g. /GRNOD/PART)",
             RC_LOC(c->part[first].loc), c->part[first].id, n, n > 1 ? "s" : "", list);
}

/* Card terms, ICoG, Ispher, checks for body b. */
static rc_status finish_body(const rc_case *c, int b, const rc_mp *a, double main_add, rc_body_mp *o, rc_error *err)
{
    const rc_case_rbody *rb = &c->rbody[b];
    const double mc = rb->mass + main_add; /* the main node's mass */
    const int mn = rc_case_find_node(c, rb->node_id);
    const double *xm = c->node[mn].x;
    const int icog = rb->icog ? rb->icog : 1, ispher = rb->ispher ? rb->ispher : 2;
    rc_loc l1 = rb->line_loc[0].file ? rb->line_loc[0] : rb->loc;
    rc_loc l2 = rb->line_loc[1].file ? rb->line_loc[1] : rb->loc;
    /* added inertia, skew axes -> global: J = R Js R^T, R[:,k] = axis k */
    double Js[9] = {rb->J[0], rb->J[3], rb->J[5], rb->J[3], rb->J[1], rb->J[4], rb->J[5], rb->J[4], rb->J[2]};
    double Jc[9];
    memcpy(Jc, Js, sizeof Jc);
    if (rb->skew_id) {
        const int s = rc_case_find_skew(c, rb->skew_id);
        if (s < 0)
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /RBODY/%d, field Skew_ID: expected the id of a /SKEW/FIX, /SKEW/MOV or /SKEW/MOV2, got %d (no such skew)",
                     RC_LOC(l1), rb->id, rb->skew_id);
        const double(*ax)[3] = (const double(*)[3])c->mesh->skew[s].axis;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                double v = 0;
                for (int k = 0; k < 3; k++)
                    for (int l = 0; l < 3; l++) v += ax[k][i] * Js[3 * k + l] * ax[l][j];
                Jc[3 * i + j] = v;
            }
    }
    /* the reference point c (relative to the main node) and the second
     * moment of the mesh about it */
    double cg[3] = {0, 0, 0}, S[6] = {0, 0, 0, 0, 0, 0}, M = mc;
    const double me = a->m;
    if (icog == 2 && !(me > 0))
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /RBODY/%d, field ICoG: ICoG = 2 puts the centre of mass at the mesh's, but the body has no element (expected ICoG 1, 3 or 4, or elements on its nodes)",
                 RC_LOC(l1), rb->id);
    if (icog != 4) {
        M += me;
        if (icog == 1 && M > 0)
            for (int k = 0; k < 3; k++) cg[k] = a->s[k] / M;
        if (icog == 2)
            for (int k = 0; k < 3; k++) cg[k] = a->s[k] / me;
        /* mesh about cg: S - s cg^T - cg s^T + m cg cg^T */
        S[0] = a->S[0] - 2 * a->s[0] * cg[0] + me * cg[0] * cg[0];
        S[1] = a->S[1] - 2 * a->s[1] * cg[1] + me * cg[1] * cg[1];
        S[2] = a->S[2] - 2 * a->s[2] * cg[2] + me * cg[2] * cg[2];
        S[3] = a->S[3] - a->s[0] * cg[1] - cg[0] * a->s[1] + me * cg[0] * cg[1];
        S[4] = a->S[4] - a->s[1] * cg[2] - cg[1] * a->s[2] + me * cg[1] * cg[2];
        S[5] = a->S[5] - a->s[0] * cg[2] - cg[0] * a->s[2] + me * cg[0] * cg[2];
        /* the card's mass sits at the main node (ICoG 1, 3) or at cg (2) */
        if (icog != 2) {
            S[0] += mc * cg[0] * cg[0];
            S[1] += mc * cg[1] * cg[1];
            S[2] += mc * cg[2] * cg[2];
            S[3] += mc * cg[0] * cg[1];
            S[4] += mc * cg[1] * cg[2];
            S[5] += mc * cg[0] * cg[2];
        }
    }
    double *J = o->J;
    const double tr = S[0] + S[1] + S[2];
    J[0] = tr - S[0] + Jc[0];
    J[4] = tr - S[1] + Jc[4];
    J[8] = tr - S[2] + Jc[8];
    J[1] = J[3] = -S[3] + 0.5 * (Jc[1] + Jc[3]);
    J[5] = J[7] = -S[4] + 0.5 * (Jc[5] + Jc[7]);
    J[2] = J[6] = -S[5] + 0.5 * (Jc[2] + Jc[6]);
    if (ispher == 1) {
        const double mean = (J[0] + J[4] + J[8]) / 3.0;
        memset(J, 0, 9 * sizeof *J);
        J[0] = J[4] = J[8] = mean;
    } else if (ispher == 2 && ispher2(J) < 0)
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /RBODY/%d, field Ispher: the principal moments of the inertia tensor could not be computed",
                 RC_LOC(l1), rb->id);
    o->mass = M;
    o->mesh_mass = icog == 4 ? 0 : me;
    for (int k = 0; k < 3; k++) o->x[k] = xm[k] + cg[k];
    /* a mass or inertia below the smallest normal number is no body: its
     * inverse overflows the accelerations at t = 0 */
    if (!(M >= DBL_MIN) || !isfinite(M))
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /RBODY/%d, field Mass: expected a finite total mass of at least %g (a normal number) [kg], got %g (Mass %g + mesh %g, ICoG %d)",
                 RC_LOC(l1), rb->id, DBL_MIN, M, mc, o->mesh_mass, icog);
    static const char *const names[3] = {"Jxx", "Jyy", "Jzz"};
    for (int k = 0; k < 3; k++)
        if (!(J[4 * k] >= DBL_MIN) || !isfinite(J[4 * k]))
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /RBODY/%d, field %s: expected a finite total moment of inertia of at least %g [kg m^2], got %g (card and mesh, about the centre of mass)",
                     RC_LOC(l2), rb->id, names[k], DBL_MIN, J[4 * k]);
    const int piv = pd_minor(J);
    if (piv)
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /RBODY/%d, fields Jxx..Jxz: expected a positive-definite total inertia tensor, got Jxx Jyy Jzz = %.9g %.9g %.9g and Jxy Jyz Jxz = %.9g %.9g %.9g (card and mesh, about the centre of mass; leading minor %d is not positive)",
                 RC_LOC(l2), rb->id, J[0], J[4], J[8], J[1], J[5], J[2], piv);
    return RC_OK;
}

rc_status rc_massprop_bodies(const rc_case *c, rc_body_mp *out, rc_error *err)
{
    mp_work w;
    rc_status st = RC_OK;
    w.node_body = malloc(((size_t)c->nnode + 1) * sizeof(int));
    w.second = malloc(((size_t)c->nnode + 1) * sizeof(int));
    w.acc = calloc((size_t)c->nrbody + 1, sizeof *w.acc);
    w.main_add = calloc((size_t)c->nrbody + 1, sizeof(double));
    w.part_in = calloc((size_t)c->npart + 1, sizeof(int));
    w.part_out = calloc((size_t)c->npart + 1, sizeof(int));
    w.part_rho = calloc((size_t)c->npart + 1, sizeof(double));
    w.part_t = calloc((size_t)c->npart + 1, sizeof(double));
    w.part_done = calloc((size_t)c->npart + 1, 1);
    if (!w.node_body || !w.second || !w.acc || !w.main_add || !w.part_in || !w.part_out || !w.part_rho || !w.part_t || !w.part_done) {
        st = RC_SET(err, RC_ENOMEM, "out of memory computing the mass properties");
        goto done;
    }
    if ((st = mark_nodes(c, &w, err))) goto done;
    if ((st = mesh_elements(c, &w, err))) goto done;
    if ((st = orphan_parts(c, &w, err))) goto done;
    if ((st = nodal_masses(c, &w, err))) goto done;
    spring_masses(c, &w);
    for (int b = 0; b < c->nrbody && !st; b++) {
        memset(&out[b], 0, sizeof out[b]);
        if (rc_case_find_node(c, c->rbody[b].node_id) < 0) continue; /* the compiler's error */
        st = finish_body(c, b, &w.acc[b], w.main_add[b], &out[b], err);
        out[b].nelem = 0;
    }
    /* element counts per body */
    for (int e = 0; !st && c->mesh && e < c->mesh->nelem; e++) {
        const int n = rc_case_find_node(c, c->mesh->elem[e].nodes[0]);
        if (n >= 0 && w.node_body[n] >= 0) out[w.node_body[n]].nelem++;
    }
done:
    free(w.node_body);
    free(w.second);
    free(w.acc);
    free(w.main_add);
    free(w.part_in);
    free(w.part_out);
    free(w.part_rho);
    free(w.part_t);
    free(w.part_done);
    return st;
}
