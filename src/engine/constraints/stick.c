/*
 * Exact stick on the integrator's extended vector Y = [y, Lambda]
 * (engine/constraints/stick.h, docs/theory.md "Exact stick"): the constraint rows
 * c_k = t_k . v_rel of the sticking contacts, the multipliers' forces on
 * the bodies, the extended sparse pattern and its exact Jacobian (complex
 * step), the consistent multipliers at a (re)start, the slip roots and the
 * stick/slip decision of the events. The residual is pure: no allocation,
 * no printing, no mode change.
 */
#include <complex.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <tgmath.h>

#include "model/imposed.h"
#include "model/joint.h"
#include "model/model.h"
#include "engine/constraints/stick.h"
#include "engine/constraints/cset.h"
#include "engine/constraints/xpattern.h"
#include "engine/assembly/assembly.h"
#include "engine/kernels/cstep.h"

/* the kernels' vector helpers, complex (dot_c, cross_c, rotate_unit_c) */
#include "engine/kernels/as_complex.h"
#include "engine/kernels/vec.inc"
#include "engine/kernels/as_done.h"

#define SK_R 3                  /* rows per slot: t_1, t_2 (exact stick), n (settled) */
#define SK_MAXB (2 * RC_NB + SK_R)  /* rows (= columns) of an interface's dense block */

/* The stretch-fixed part of the constraints: the exact interfaces, the
 * helper axis of each tangent basis, the scratch of the multipliers. */
typedef struct sk_core {
    int ny, ns;
    int *inter;   /* [ns] interface index */
    double *axis; /* [3 ns] helper axis h: t_1 = (h - (h.n) n) / |.|, t_2 = n x t_1 */
    int *act;     /* [ns] 1: sticking (closed, exact, not sliding) */
    double *A, *b; /* [(2 ns)^2], [2 ns] */
    size_t *perm; /* [2 ns] */
    double *z;    /* [ny] accelerations of a unit multiplier */
    int *idx;     /* [2 ns] the rows in the equations: 2 q + k */
    char *ron;    /* [2 ns] 1: row k of slot q is a constraint; 0: the
                     supports (/BCS, /IMPVEL) already hold that direction on
                     both bodies (no acceleration answers its multiplier),
                     its multiplier is 0 (set at each restart) */
} sk_core;

struct rc_stk_work {
    sk_core k;
    int base; /* index of the first Lambda in Y: ny, or after the joints' extras */
    int n;    /* base + 2 ns */
    int nr;   /* constraint rows of the stretch (rc_stk_prepare) */
    int64_t nnz;
    int64_t *colptr, *rowind, *mslot, *diag, *bslot; /* bslot: [ns SK_MAXB^2] */
    double *atol; /* [SK_R ns] */
    double *f;    /* [ny] scratch of the roots: the rates without the constraints */
};


static int sticking(const rc_data *d, int i) { return d->inter_mode[i] == RC_MODE_CLOSED && !d->inter_slip[i]; }

static int exact_of(const rc_model *m, int i) { return m->inter_fr[i].exact && m->inter_fr[i].tidx >= 0; }

int rc_stk_settle_capable(const rc_model *m, int i)
{
    return !(m->jnt && m->jnt->n > 0) && m->inter_npt[i] == 0 && !rc_pair_multi(m->inter_pair[i]) && m->inter_fr[i].kind == RC_FK_NONE &&
           !m->inter_fr[i].exact;
}

/* The rows of interface i that are constraints in d's modes (bits 0, 1:
 * the tangential rows of a sticking exact contact; bit 2: the normal row
 * of a settled contact). */
static int act_of(const rc_model *m, const rc_data *d, int i)
{
    if (exact_of(m, i)) return sticking(d, i) ? 3 : 0;
    return d->inter_mode[i] == RC_MODE_CLOSED && d->inter_settled[i] ? 4 : 0;
}

int rc_stk_count(const rc_model *m)
{
    int n = 0;
    for (int i = 0; i < m->ninter; i++) n += exact_of(m, i);
    return n;
}

int rc_stk_slots(const rc_model *m)
{
    int n = 0;
    for (int i = 0; i < m->ninter; i++) n += exact_of(m, i) || rc_stk_settle_capable(m, i);
    return n;
}

/* Rows that take a force: not held by /BCS, not imposed by /IMPVEL (their
 * supports carry the constraint's share). */
static int row_free(const rc_model *m, int row)
{
    if (m->row_held && m->row_held[row]) return 0;
    if (m->imp && m->imp->row_imp && m->imp->row_imp[row]) return 0;
    return 1;
}

static int free_adr(const rc_model *m, int b) { return b >= 0 ? m->body_yadr[b] : -1; }

/* ---- kernel (complex, for its derivatives) --------------------------- */
/* R(q)^T s for the normalised quaternion q / |q| (as the kernels' rotate_c
 * with transpose, w = (-q_0) / |q|). */
static void rot_t(const rc_cx *q, const rc_cx *s, rc_cx *out)
{
    const rc_cx inv = 1.0 / csqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    const rc_cx w = -q[0] * inv, u[3] = {q[1] * inv, q[2] * inv, q[3] * inv};
    rotate_unit_c(w, u, s, out);
}

/* Tangent basis of the plane normal to n from the helper axis h. */
static void basis(const double *h, const rc_cx *n, rc_cx *t1, rc_cx *t2)
{
    const rc_cx hn = h[0] * n[0] + h[1] * n[1] + h[2] * n[2];
    for (int k = 0; k < 3; k++) t1[k] = h[k] - hn * n[k];
    const rc_cx nt = csqrt(dot_c(t1, t1));
    for (int k = 0; k < 3; k++) t1[k] /= nt;
    cross_c(n, t1, t2);
}

/* The rows of body b (state yb) under the force sF at point p: the
 * residual terms -(F/m) and -J^-1 R^T ((p - x) x F) of its velocity rows. */
static void body_terms(const rc_model *m, int b, const rc_cx *yb, const rc_cx *p, const rc_cx *F, double s, rc_cx *out)
{
    for (int k = 0; k < RC_NB; k++) out[k] = 0.0;
    if (b < 0 || m->body_yadr[b] < 0) return; /* the ground or a fixed body: no rows */
    const double *Ji = m->body_Jinv + 9 * b, im = 1.0 / m->body_mass[b];
    rc_cx r[3], f[3], tau[3], taub[3];
    for (int k = 0; k < 3; k++) {
        r[k] = p[k] - yb[k];
        f[k] = s * F[k];
    }
    cross_c(r, f, tau);
    rot_t(yb + 3, tau, taub);
    for (int k = 0; k < 3; k++) {
        out[7 + k] = -f[k] * im;
        out[10 + k] = -(Ji[3 * k] * taub[0] + Ji[3 * k + 1] * taub[1] + Ji[3 * k + 2] * taub[2]);
    }
}

/* Interface i's constraint rows c[SK_R] and (ra, rb not NULL) the residual
 * terms of its bodies under the multipliers lam[SK_R]; point and basis out
 * when asked (pt, t1, t2 not NULL). */
static void kern(const rc_model *m, int i, const double *h, const rc_cx *ya, const rc_cx *yb, const rc_cx *lam, rc_cx *ra, rc_cx *rb,
                 rc_cx *c, rc_cx *pt, rc_cx *tb1, rc_cx *tb2)
{
    rc_cx p[3], n[3], v[3], t1[3], t2[3], dd;
    rc_stk_geom_c(m, i, ya, yb, p, n, v, &dd);
    basis(h, n, t1, t2);
    c[0] = dot_c(t1, v);
    c[1] = dot_c(t2, v);
    c[2] = dd; /* the rate of the signed distance (a settled contact: P frozen) */
    for (int k = 0; k < 3 && pt; k++) pt[k] = p[k];
    for (int k = 0; k < 3 && tb1; k++) tb1[k] = t1[k];
    for (int k = 0; k < 3 && tb2; k++) tb2[k] = t2[k];
    if (!ra && !rb) return;
    rc_cx F[3];
    /* lam[2] the normal force (>= 0 in compression): -lam[2] n on a */
    for (int k = 0; k < 3; k++) F[k] = lam[0] * t1[k] + lam[1] * t2[k] - lam[2] * n[k];
    if (ra) body_terms(m, m->inter_ba[i], ya, p, F, 1.0, ra);
    if (rb) body_terms(m, m->inter_bb[i], yb, p, F, -1.0, rb);
}

/* Body states of interface i as complex values, + i h z on the free ones
 * (z NULL: none). */
static void load(const rc_model *m, int i, const double *Y, const double *z, rc_cx *ya, rc_cx *yb)
{
    const int bs[2] = {m->inter_ba[i], m->inter_bb[i]};
    rc_cx *out[2] = {ya, yb};
    for (int e = 0; e < 2; e++) {
        const double *s = rc_body_state(m, bs[e], Y);
        const int adr = free_adr(m, bs[e]);
        for (int k = 0; k < RC_NB; k++) out[e][k] = rc_cs_seed(s[k], z && adr >= 0 ? z[adr + k] : 0.0);
    }
}

/* ---- the multipliers: A = G M^-1 G^T and its right-hand sides --------- */
/* Add s times the accelerations of the unit multiplier (row k of
 * interface slot q) to z [ny]. */
static void add_unit(const rc_model *m, const sk_core *K, int q, int k, const double *Y, double s, double *z)
{
    const int i = K->inter[q];
    rc_cx ya[RC_NB], yb[RC_NB], lam[SK_R] = {k == 0 ? s : 0.0, k == 1 ? s : 0.0, k == 2 ? s : 0.0}, ra[RC_NB], rb[RC_NB], c[SK_R];
    load(m, i, Y, NULL, ya, yb);
    const int aa = free_adr(m, m->inter_ba[i]), ab = free_adr(m, m->inter_bb[i]);
    kern(m, i, K->axis + 3 * q, ya, yb, lam, ra, rb, c, NULL, NULL, NULL);
    /* the residual terms are minus the accelerations */
    for (int r = 0; r < RC_NB; r++) {
        if (aa >= 0 && row_free(m, aa + r)) z[aa + r] -= creal(ra[r]);
        if (ab >= 0 && row_free(m, ab + r)) z[ab + r] -= creal(rb[r]);
    }
}

/* dc/dy z of interface slot q's rows, by complex step. */
static void c_along(const rc_model *m, const sk_core *K, int q, const double *Y, const double *z, double *dc)
{
    const int i = K->inter[q];
    rc_cx ya[RC_NB], yb[RC_NB], c[SK_R];
    load(m, i, Y, z, ya, yb);
    kern(m, i, K->axis + 3 * q, ya, yb, NULL, NULL, NULL, c, NULL, NULL, NULL);
    for (int k = 0; k < SK_R; k++) dc[k] = rc_cs_deriv(c[k]);
}

/* A[j][l] = (dc_rows[j] / dy) (accelerations of the unit multiplier of
 * rows[l]) = G M^-1 G^T over the rows (2 q + k) given. */
static void build_A(const rc_model *m, sk_core *K, const double *Y, const int *rows, int nr)
{
    for (int l = 0; l < nr; l++) {
        memset(K->z, 0, (size_t)K->ny * sizeof(double));
        add_unit(m, K, rows[l] / SK_R, rows[l] % SK_R, Y, 1.0, K->z);
        for (int j = 0; j < nr; j++) {
            double dc[SK_R];
            c_along(m, K, rows[j] / SK_R, Y, K->z, dc);
            K->A[j * nr + l] = dc[rows[j] % SK_R];
        }
    }
}

/* The rows of the sticking slots that are constraints (K->ron): a row
 * whose unit multiplier moves nothing along it (held by the supports on
 * both bodies) is left out. Their count; K->idx the rows. */
static int active_rows(const rc_model *m, sk_core *K, const double *Y)
{
    int nr = 0;
    double dmax = 0;
    for (int q = 0; q < K->ns; q++)
        for (int k = 0; k < SK_R; k++) {
            K->ron[SK_R * q + k] = 0;
            K->b[SK_R * q + k] = 0.0;
            if (!(K->act[q] >> k & 1)) continue;
            memset(K->z, 0, (size_t)K->ny * sizeof(double));
            add_unit(m, K, q, k, Y, 1.0, K->z);
            double dc[SK_R];
            c_along(m, K, q, Y, K->z, dc);
            K->b[SK_R * q + k] = dc[k];
            dmax = fmax(dmax, dc[k]);
        }
    for (int q = 0; q < K->ns; q++)
        for (int k = 0; k < SK_R; k++)
            if ((K->act[q] >> k & 1) && K->b[SK_R * q + k] > 1e-12 * dmax) {
                K->ron[SK_R * q + k] = 1;
                K->idx[nr++] = SK_R * q + k;
            }
    return nr;
}

/* Solve A x = b (K->b over the rows K->idx[0..nr)) at Y; 0, or -1 when A
 * is singular (rows that repeat others). */
static int solve(const rc_model *m, sk_core *K, const double *Y, int nr)
{
    build_A(m, K, Y, K->idx, nr);
    gsl_matrix_view A = gsl_matrix_view_array(K->A, (size_t)nr, (size_t)nr);
    gsl_vector_view b = gsl_vector_view_array(K->b, (size_t)nr);
    gsl_permutation p = {(size_t)nr, K->perm};
    int sgn;
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    int bad = gsl_linalg_LU_decomp(&A.matrix, &p, &sgn);
    if (!bad) {
        double amax = 0, dmin = INFINITY;
        for (int k = 0; k < nr; k++) dmin = fmin(dmin, fabs(K->A[k * nr + k]));
        for (int k = 0; k < nr * nr; k++) amax = fmax(amax, fabs(K->A[k]));
        bad = !(dmin > 1e-13 * amax);
    }
    if (!bad) bad = gsl_linalg_LU_svx(&A.matrix, &p, &b.vector);
    gsl_set_error_handler(old);
    return bad ? -1 : 0;
}

/* Multipliers of the constraint rows (K->b[0..nr)) at Y with f [ny] the
 * rates: A lambda = -(dc/dy) f. 0, or -1. */
static int multipliers(const rc_model *m, sk_core *K, const double *Y, const double *f, int nr)
{
    for (int j = 0; j < nr; j++) {
        double dc[SK_R];
        c_along(m, K, K->idx[j] / SK_R, Y, f, dc);
        K->b[j] = -dc[K->idx[j] % SK_R];
    }
    return solve(m, K, Y, nr);
}

/* The helper axis of slot q at Y: the global axis least aligned with n. */
static void set_axis(const rc_model *m, sk_core *K, int q, const double *Y)
{
    const int i = K->inter[q];
    rc_cx ya[RC_NB], yb[RC_NB], p[3], n[3], v[3], dd;
    load(m, i, Y, NULL, ya, yb);
    rc_stk_geom_c(m, i, ya, yb, p, n, v, &dd);
    int j = 0;
    for (int k = 1; k < 3; k++)
        if (fabs(creal(n[k])) < fabs(creal(n[j]))) j = k;
    double *h = K->axis + 3 * q;
    h[0] = h[1] = h[2] = 0.0;
    h[j] = 1.0;
}

static void core_free(sk_core *K)
{
    free(K->inter);
    free(K->axis);
    free(K->act);
    free(K->A);
    free(K->b);
    free(K->perm);
    free(K->z);
    free(K->idx);
    free(K->ron);
}

static int core_init(const rc_model *m, sk_core *K)
{
    memset(K, 0, sizeof *K);
    K->ny = m->ny;
    K->ns = rc_stk_slots(m);
    const size_t ns = (size_t)K->ns + 1;
    K->inter = calloc(ns, sizeof *K->inter);
    K->axis = calloc(3 * ns, sizeof *K->axis);
    K->act = calloc(ns, sizeof *K->act);
    K->A = calloc(SK_R * SK_R * ns * ns, sizeof *K->A);
    K->b = calloc(SK_R * ns, sizeof *K->b);
    K->perm = calloc(SK_R * ns, sizeof *K->perm);
    K->z = calloc((size_t)m->ny + 1, sizeof *K->z);
    K->idx = calloc(SK_R * ns, sizeof *K->idx);
    K->ron = calloc(SK_R * ns, sizeof *K->ron);
    if (!K->inter || !K->axis || !K->act || !K->A || !K->b || !K->perm || !K->z || !K->idx || !K->ron) {
        core_free(K);
        return -1;
    }
    int q = 0;
    for (int i = 0; i < m->ninter; i++)
        if (exact_of(m, i) || rc_stk_settle_capable(m, i)) {
            K->inter[q] = i;
            K->axis[3 * q] = 1.0;
            q++;
        }
    return 0;
}

/* ---- work, pattern ----------------------------------------------------- */

/* The rows (= columns) of slot q's dense block: its free bodies' states,
 * then its two rows (Lambda columns). */
static int block_idx(const rc_model *m, const rc_stk_work *w, int q, int *idx)
{
    const int i = w->k.inter[q], aa = free_adr(m, m->inter_ba[i]), ab = free_adr(m, m->inter_bb[i]);
    int n = 0;
    for (int k = 0; aa >= 0 && k < RC_NB; k++) idx[n++] = aa + k;
    for (int k = 0; ab >= 0 && k < RC_NB; k++) idx[n++] = ab + k;
    for (int k = 0; k < SK_R; k++) idx[n++] = w->base + SK_R * q + k;
    return n;
}

/* Slot q's dense block for the extended pattern (xpattern.h). */
static void xblock(const rc_model *m, const void *ctx, int q, int *rows, int *nrow, int *cols, int *ncol)
{
    *nrow = *ncol = block_idx(m, ctx, q, rows);
    for (int k = 0; k < *nrow; k++) cols[k] = rows[k];
}

void rc_stk_work_free(rc_stk_work *w)
{
    if (!w) return;
    core_free(&w->k);
    void *p[] = {w->colptr, w->rowind, w->mslot, w->diag, w->bslot, w->atol, w->f};
    for (size_t k = 0; k < sizeof p / sizeof p[0]; k++) free(p[k]);
    free(w);
}

rc_stk_work *rc_stk_work_new(const rc_model *m) { return rc_stk_work_new_at(m, m->ny); }

rc_stk_work *rc_stk_work_new_at(const rc_model *m, int base)
{
    rc_stk_work *w = calloc(1, sizeof *w);
    if (!w) return NULL;
    if (core_init(m, &w->k)) {
        free(w);
        return NULL;
    }
    w->base = base;
    const int ns = w->k.ns, n = w->n = base + SK_R * ns;
    w->atol = calloc(SK_R * (size_t)ns + 1, sizeof *w->atol);
    w->f = calloc((size_t)m->ny + 1, sizeof *w->f);
    w->diag = calloc((size_t)n, sizeof *w->diag);
    w->mslot = calloc((size_t)m->nnz + 1, sizeof *w->mslot);
    w->colptr = calloc((size_t)n + 1, sizeof *w->colptr);
    w->bslot = malloc(((size_t)ns * SK_MAXB * SK_MAXB + 1) * sizeof *w->bslot);
    int64_t *badr = malloc(((size_t)ns + 1) * sizeof *badr);
    if (!w->atol || !w->f || !w->diag || !w->mslot || !w->colptr || !w->bslot || !badr) {
        free(badr);
        rc_stk_work_free(w);
        return NULL;
    }
    /* slot q's block (its bodies' states and its rows, square) at q SK_MAXB^2 */
    for (int q = 0; q <= ns; q++) badr[q] = (int64_t)q * SK_MAXB * SK_MAXB;
    w->rowind = rc_xpat_build(m, n, ns, SK_MAXB, xblock, w, badr, w->colptr, &w->nnz, w->mslot, w->diag, w->bslot);
    free(badr);
    if (!w->rowind) {
        rc_stk_work_free(w);
        return NULL;
    }
    for (int q = 0; q < ns; q++) {
        /* Lambda [N s]: the impulse that changes the velocity of the
         * lightest free body by its tolerance (in Newton's test only) */
        const int i = w->k.inter[q], bs[2] = {m->inter_ba[i], m->inter_bb[i]};
        double a = INFINITY;
        for (int e = 0; e < 2; e++) {
            const int adr = free_adr(m, bs[e]);
            if (adr >= 0) a = fmin(a, m->body_mass[bs[e]] * m->atol[adr + 7]);
        }
        for (int k = 0; k < SK_R; k++) w->atol[SK_R * q + k] = isfinite(a) && a > 0 ? a : 1.0;
    }
    return w;
}

int rc_stk_nextra(const rc_stk_work *w) { return SK_R * w->k.ns; }
int64_t rc_stk_nnz(const rc_stk_work *w) { return w->nnz; }

void rc_stk_pattern(const rc_stk_work *w, const int64_t **colptr, const int64_t **rowind)
{
    *colptr = w->colptr;
    *rowind = w->rowind;
}

double rc_stk_atol(const rc_stk_work *w, int k) { return w->atol[k]; }

/* Lambda: id 0, out of the error test (only lambda = Lambda' enters). */
void rc_stk_id(const rc_model *m, const rc_stk_work *w, double *id)
{
    for (int k = 0; k < w->n; k++) id[k] = k < m->ny ? 1.0 : k < w->base ? id[k] : 0.0;
}

/* ---- residual, Jacobian ------------------------------------------------ */
void rc_stk_residual(const rc_model *m, const rc_data *d, const rc_stk_work *w, const double *Y, const double *Yp,
                     double *r)
{
    for (int q = 0; q < w->k.ns; q++) {
        const int i = w->k.inter[q], row = w->base + SK_R * q;
        if (!act_of(m, d, i)) {
            for (int k = 0; k < SK_R; k++) r[row + k] = Yp[row + k];
            continue;
        }
        rc_cx ya[RC_NB], yb[RC_NB], ra[RC_NB], rb[RC_NB], c[SK_R], lam[SK_R] = {Yp[row], Yp[row + 1], Yp[row + 2]};
        load(m, i, Y, NULL, ya, yb);
        const int aa = free_adr(m, m->inter_ba[i]), ab = free_adr(m, m->inter_bb[i]);
        kern(m, i, w->k.axis + 3 * q, ya, yb, lam, ra, rb, c, NULL, NULL, NULL);
        for (int k = 0; k < RC_NB; k++) {
            if (aa >= 0 && row_free(m, aa + k)) r[aa + k] += creal(ra[k]);
            if (ab >= 0 && row_free(m, ab + k)) r[ab + k] += creal(rb[k]);
        }
        /* a row the supports hold: its multiplier is 0 */
        for (int k = 0; k < SK_R; k++) r[row + k] = w->k.ron[SK_R * q + k] ? creal(c[k]) : Yp[row + k];
    }
}

void rc_stk_jacobian(const rc_model *m, const rc_data *d, const rc_stk_work *w, double cj, const double *Y,
                     const double *Yp, const double *jf, double *val)
{
    const int ny = m->ny;
    memset(val, 0, (size_t)w->nnz * sizeof(double));
    for (int64_t k = 0; k < m->nnz; k++) val[w->mslot[k]] -= jf[k];
    for (int k = 0; k < ny; k++) val[w->diag[k]] += cj;
    for (int q = 0; q < w->k.ns; q++) {
        const int i = w->k.inter[q], row = w->base + SK_R * q;
        if (!act_of(m, d, i)) {
            for (int k = 0; k < SK_R; k++) val[w->diag[row + k]] += cj;
            continue;
        }
        const int aa = free_adr(m, m->inter_ba[i]), ab = free_adr(m, m->inter_bb[i]);
        const int na = aa >= 0 ? RC_NB : 0, nb = ab >= 0 ? RC_NB : 0, nc = na + nb + SK_R;
        int idx[SK_MAXB];
        block_idx(m, w, q, idx);
        rc_cx ya[RC_NB], yb[RC_NB], lam[SK_R] = {Yp[row], Yp[row + 1], Yp[row + 2]};
        load(m, i, Y, NULL, ya, yb);
        const int64_t *slot = w->bslot + (int64_t)q * SK_MAXB * SK_MAXB;
        for (int c = 0; c < nc; c++) {
            rc_cx *p = c < na ? ya + c : c < na + nb ? yb + (c - na) : lam + (c - na - nb);
            rc_cs_step(p);
            rc_cx ra[RC_NB], rb[RC_NB], cv[SK_R];
            kern(m, i, w->k.axis + 3 * q, ya, yb, lam, na ? ra : NULL, nb ? rb : NULL, cv, NULL, NULL, NULL);
            rc_cs_unstep(p);
            /* d/dLambda = cj d/dlambda: the residual holds lambda = Lambda' */
            const double sc = (c < na + nb ? 1.0 : cj) / RC_CSTEP;
            int r = 0;
            for (int k = 0; k < na; k++, r++)
                if (row_free(m, idx[r])) val[slot[r * nc + c]] += sc * cimag(ra[k]);
            for (int k = 0; k < nb; k++, r++)
                if (row_free(m, idx[r])) val[slot[r * nc + c]] += sc * cimag(rb[k]);
            for (int k = 0; k < SK_R; k++, r++)
                if (w->k.ron[SK_R * q + k]) val[slot[r * nc + c]] += sc * cimag(cv[k]);
        }
        for (int k = 0; k < SK_R; k++)
            if (!w->k.ron[SK_R * q + k]) val[w->diag[row + k]] += cj;
    }
}

void rc_stk_keep(const rc_model *m, const rc_data *d, const rc_stk_work *w, const unsigned char *keep,
                 unsigned char *ext)
{
    /* what rc_stk_jacobian writes: the model's values, the diagonal, the
     * blocks of the acting constraints */
    memset(ext, 0, (size_t)w->nnz);
    for (int64_t k = 0; k < m->nnz; k++)
        if (keep[k]) ext[w->mslot[k]] = 1;
    for (int c = 0; c < w->n; c++) ext[w->diag[c]] = 1;
    for (int q = 0; q < w->k.ns; q++) {
        if (!act_of(m, d, w->k.inter[q])) continue;
        int idx[SK_MAXB];
        const int nb = block_idx(m, w, q, idx);
        const int64_t *slot = w->bslot + (int64_t)q * SK_MAXB * SK_MAXB;
        for (int k = 0; k < nb * nb; k++) ext[slot[k]] = 1;
    }
}

/* ---- (re)start, roots, records ---------------------------------------- */
int rc_stk_prepare(const rc_model *m, rc_data *d, rc_stk_work *w, double *Y)
{
    sk_core *K = &w->k;
    const int ny = m->ny;
    for (int q = 0; q < K->ns; q++) {
        set_axis(m, K, q, Y);
        K->act[q] = act_of(m, d, K->inter[q]);
    }
    const int nr = w->nr = active_rows(m, K, Y);
    if (nr == 0) return 0;
    /* the velocities made exact: u += M^-1 G^T x, A x = -c (G depends on
     * the positions only; the change of least kinetic energy) */
    for (int j = 0; j < nr; j++) {
        const int q = K->idx[j] / SK_R, i = K->inter[q];
        rc_cx ya[RC_NB], yb[RC_NB], c[SK_R];
        load(m, i, Y, NULL, ya, yb);
        kern(m, i, K->axis + 3 * q, ya, yb, NULL, NULL, NULL, c, NULL, NULL, NULL);
        K->b[j] = -creal(c[K->idx[j] % SK_R]);
    }
    if (solve(m, K, Y, nr)) return -1;
    memset(K->z, 0, (size_t)ny * sizeof(double));
    for (int j = 0; j < nr; j++) add_unit(m, K, K->idx[j] / SK_R, K->idx[j] % SK_R, Y, K->b[j], K->z);
    for (int k = 0; k < ny; k++) Y[k] += K->z[k];
    return 0;
}

int rc_stk_consistent(const rc_model *m, rc_stk_work *w, const double *Y, double *Yp)
{
    sk_core *K = &w->k;
    const int ny = m->ny, nr = w->nr;
    for (int q = 0; q < K->ns; q++)
        for (int k = 0; k < SK_R; k++) Yp[w->base + SK_R * q + k] = 0.0;
    if (nr == 0) return 0;
    if (multipliers(m, K, Y, Yp, nr)) return -1;
    memset(K->z, 0, (size_t)ny * sizeof(double));
    for (int j = 0; j < nr; j++) {
        Yp[w->base + K->idx[j]] = K->b[j];
        add_unit(m, K, K->idx[j] / SK_R, K->idx[j] % SK_R, Y, K->b[j], K->z);
    }
    for (int k = 0; k < ny; k++) Yp[k] += K->z[k];
    return 0;
}

int rc_stk_restart(const rc_model *m, rc_data *d, rc_stk_work *w, double t, double *Y, double *Yp)
{
    if (rc_stk_prepare(m, d, w, Y)) return -1;
    if (rc_assemble_rhs(m, d, t, Y, Yp)) return -1;
    return rc_stk_consistent(m, w, Y, Yp);
}

/* The force of slot q's multipliers (global, on a) at Y [N]. */
static void force_of(const rc_model *m, const sk_core *K, int q, const double *Y, const double *lam, double *F)
{
    const int i = K->inter[q];
    rc_cx ya[RC_NB], yb[RC_NB], c[SK_R], t1[3], t2[3];
    load(m, i, Y, NULL, ya, yb);
    kern(m, i, K->axis + 3 * q, ya, yb, NULL, NULL, NULL, c, NULL, t1, t2);
    for (int k = 0; k < 3; k++) F[k] = lam[0] * creal(t1[k]) + lam[1] * creal(t2[k]);
}

/* The normal force of the settled contacts: their multipliers from the
 * acceleration-level equations at (t, Y), in K->b (the integrator's
 * interpolated Lambda' of an algebraic row is not reliable between its
 * steps: the roots and the records take these). 1: solved. */
static int settled_solve(const rc_model *m, rc_data *d, rc_stk_work *w, double t, const double *Y)
{
    sk_core *K = &w->k;
    int settled = 0;
    for (int q = 0; q < K->ns; q++) settled |= (act_of(m, d, K->inter[q]) & 4) && K->ron[SK_R * q + 2];
    return settled && w->nr > 0 && !rc_assemble_rhs(m, d, t, Y, w->f) && !multipliers(m, K, Y, w->f, w->nr);
}

/* Slot q's normal multiplier [N]: solved (settled_solve), else Yp's. */
static double settled_force(const rc_stk_work *w, int solved, int q, const double *Yp)
{
    for (int j = 0; solved && j < w->nr; j++)
        if (w->k.idx[j] == SK_R * q + 2) return w->k.b[j];
    return Yp[w->base + SK_R * q + 2];
}

void rc_stk_roots(const rc_model *m, rc_data *d, rc_stk_work *w, double t, const double *Y, const double *Yp,
                  double *g)
{
    sk_core *K = &w->k;
    const int solved = settled_solve(m, d, w, t, Y);
    for (int q = 0; q < w->k.ns; q++) {
        const int i = w->k.inter[q];
        const int act = act_of(m, d, i);
        if (!act) continue;
        rc_inter_report r;
        rc_inter_report_eval_d(m, d, i, t, Y, &r);
        const double *lam = Yp + w->base + SK_R * q;
        if (act & 4) {
            /* settled: released when the normal force (the multiplier and
             * the penalty force of the frozen penetration) turns tensile */
            if (!K->ron[SK_R * q + 2]) continue;
            g[RC_ROOTS_PER_INTER * i + RC_ROOT_FORCE] = settled_force(w, solved, q, Yp) + r.fn;
            continue;
        }
        /* no band: the multiplier is exact (algebraic), no spring rings
         * about the limit nor does a damper carry a ramped load */
        const double s = r.flim;
        g[RC_ROOTS_PER_INTER * i + RC_ROOT_SLIP] = s > 0 ? (lam[0] * lam[0] + lam[1] * lam[1]) / (s * s) - 1.0 : 1.0;
    }
}

void rc_stk_sync(const rc_model *m, const rc_data *d, const rc_stk_work *w, const double *Y, const double *Yp,
                 double *Yout)
{
    for (int q = 0; q < w->k.ns; q++) {
        const int i = w->k.inter[q];
        if (act_of(m, d, i) != 3) continue;
        double F[3];
        force_of(m, &w->k, q, Y, Yp + w->base + SK_R * q, F);
        double *ft = Yout + m->inter_eadr[i] + m->inter_fr[i].tidx;
        for (int k = 0; k < 3; k++) ft[k] = F[k];
    }
}

int rc_stk_slot_of(const rc_stk_work *w, int i)
{
    int me = -1;
    for (int q = 0; q < w->k.ns; q++)
        if (w->k.inter[q] == i) me = q;
    return me;
}

void rc_stk_slot_force(const rc_model *m, const rc_stk_work *w, int q, const double *Y, const double *Yp, double F[3])
{
    force_of(m, &w->k, q, Y, Yp + w->base + SK_R * q, F);
}

int rc_stk_sliding(const rc_model *m, const rc_data *d, int i, double t, const double *y, rc_inter_report *r,
                   double e[3])
{
    rc_inter_report_eval_d(m, d, i, t, y, r);
    /* a sliding velocity beyond the tolerances: it slides on */
    double vtol = INFINITY;
    const int bs[2] = {m->inter_ba[i], m->inter_bb[i]};
    for (int k = 0; k < 2; k++)
        if (free_adr(m, bs[k]) >= 0) vtol = fmin(vtol, 100.0 * m->atol[free_adr(m, bs[k]) + 7]);
    const double vt = sqrt(r->vt[0] * r->vt[0] + r->vt[1] * r->vt[1] + r->vt[2] * r->vt[2]);
    if (vt > vtol) {
        for (int k = 0; k < 3; k++) e[k] = -r->vt[k] / vt;
        return 1;
    }
    return 0;
}

int rc_stk_hold_force(const rc_model *m, rc_data *d, int i, double t, const double *y, double F[3])
{
    sk_core K;
    if (core_init(m, &K)) return -1;
    double *f = malloc(((size_t)m->ny + 1) * sizeof *f);
    int me = -1, st = -1;
    for (int q = 0; q < K.ns; q++) {
        K.act[q] = act_of(m, d, K.inter[q]);
        if (K.inter[q] == i) me = q;
        set_axis(m, &K, q, y);
    }
    const int nr = me >= 0 ? active_rows(m, &K, y) : 0;
    if (f && me >= 0 && !rc_assemble_rhs(m, d, t, y, f) && (nr == 0 || !multipliers(m, &K, y, f, nr))) {
        double lam[SK_R] = {0.0, 0.0, 0.0};
        for (int j = 0; j < nr; j++)
            if (K.idx[j] / SK_R == me) lam[K.idx[j] % SK_R] = K.b[j];
        force_of(m, &K, me, y, lam, F);
        st = 0;
    }
    free(f);
    core_free(&K);
    return st;
}

void rc_stk_fcstr(const rc_model *m, rc_data *d, rc_stk_work *w, double t, const double *Y, const double *Yp)
{
    for (int i = 0; i < m->ninter; i++) d->inter_fcstr[i] = 0.0;
    const int solved = settled_solve(m, d, w, t, Y);
    for (int q = 0; q < w->k.ns; q++)
        if (act_of(m, d, w->k.inter[q]) & 4 && w->k.ron[SK_R * q + 2])
            d->inter_fcstr[w->k.inter[q]] = settled_force(w, solved, q, Yp);
}

/* ---- exact stick as a constraint set (cset.h) ------------------------- */
static int sset_needed(const rc_model *m) { return rc_stk_slots(m) > 0; }
static void *sset_open(const rc_model *m, int base) { return rc_stk_work_new_at(m, base); }
static void sset_close(void *w) { rc_stk_work_free(w); }
static int sset_nextra(const void *w) { return rc_stk_nextra(w); }
static int64_t sset_nnz(const void *w) { return rc_stk_nnz(w); }
static void sset_pattern(const void *w, const int64_t **colptr, const int64_t **rowind)
{
    rc_stk_pattern(w, colptr, rowind);
}
static double sset_atol(const rc_model *m, const void *w, int k)
{
    (void)m;
    return rc_stk_atol(w, k);
}
static void sset_id(const rc_model *m, const void *w, double *id) { rc_stk_id(m, w, id); }
static void sset_residual(const rc_model *m, const rc_data *d, const void *w, const double *Y, const double *Yp,
                          double *r)
{
    rc_stk_residual(m, d, w, Y, Yp, r);
}
static void sset_jacobian(const rc_model *m, const rc_data *d, const void *w, double cj, const double *Y,
                          const double *Yp, const double *jf, double *val)
{
    rc_stk_jacobian(m, d, w, cj, Y, Yp, jf, val);
}
static void sset_keep(const rc_model *m, const rc_data *d, const void *w, const unsigned char *keep,
                      unsigned char *ext)
{
    rc_stk_keep(m, d, w, keep, ext);
}
/* the tangent bases of the stretch and the sticking velocities made exact */
static int sset_project(const rc_model *m, rc_data *d, void *w, double *Y) { return rc_stk_prepare(m, d, w, Y); }
static int sset_multipliers(const rc_model *m, void *w, double *Y, double *Yp)
{
    return rc_stk_consistent(m, w, Y, Yp);
}
static void sset_roots(const rc_model *m, rc_data *d, void *w, double t, const double *Y, const double *Yp,
                       double *g)
{
    rc_stk_roots(m, d, w, t, Y, Yp, g);
}
/* the sticking contacts' F_t as their multipliers' force; the settled
 * contacts' normal force into d */
static void sset_record(const rc_model *m, rc_data *d, void *w, double t, const double *Y, const double *Yp,
                        double *Yrec)
{
    rc_stk_sync(m, d, w, Y, Yp, Yrec);
    rc_stk_fcstr(m, d, w, t, Y, Yp);
}
/* the sticking contacts' F_t as their multipliers' force before the events
 * (the slip direction, the event records) */
static void sset_before_events(const rc_model *m, const rc_data *d, void *w, double *Y, const double *Yp)
{
    rc_stk_sync(m, d, w, Y, Yp, Y);
}

const rc_cset_ops rc_stk_set_ops = {
    .what = "exact stick: velocity constraints",
    .start_failed = "exact stick at t = 0: the sticking contacts' rows are dependent (two sticking contacts hold "
                    "the same motion) or the forces could not be evaluated",
    .needed = sset_needed, .open = sset_open, .close = sset_close, .nextra = sset_nextra, .nnz = sset_nnz,
    .pattern = sset_pattern, .atol = sset_atol, .id = sset_id, .residual = sset_residual, .jacobian = sset_jacobian,
    .keep = sset_keep, .project = sset_project, .project_at_restart = 1, .multipliers = sset_multipliers,
    .roots = sset_roots, .record = sset_record, .before_events = sset_before_events};
