/*
 * Joints on the integrator's extended vector Y = [y, Lambda, nu, W]
 * (model/joint.h, docs/theory.md "Joints"): residual terms, the extended
 * sparse pattern and its exact Jacobian (complex step of joints.inc), the
 * consistent multipliers, the reactions. The residual is pure: no
 * allocation, no printing, no mode change.
 */
#include <complex.h>
#include <gsl/gsl_linalg.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <tgmath.h>

#include "base/error.h"
#include "model/joint.h"
#include "model/model.h"
#include "engine/constraints/joints.h"
#include "engine/constraints/cset.h"
#include "engine/constraints/xpattern.h"
#include "engine/kernels/cstep.h"

/* the joint kernels and the vector helpers they use, in real arithmetic
 * (the residual) and complex (its Jacobian by complex step) */
#include "engine/kernels/as_real.h"
#include "engine/kernels/vec.inc"
#include "joints.inc"
#include "engine/kernels/as_done.h"
#include "engine/kernels/as_complex.h"
#include "engine/kernels/vec.inc"
#include "joints.inc"
#include "engine/kernels/as_done.h"

struct rc_jnt_work {
    int ny, nrows, n;     /* n = ny + 2 nrows + 1 */
    int64_t nnz;
    int64_t *colptr, *rowind;
    int64_t *mslot;       /* [m->nnz] slot of each entry of the model's pattern */
    int64_t *diag;        /* [n] slot of each diagonal entry */
    int64_t *badr;        /* [njoint + 1] offsets into bslot */
    int64_t *bslot;       /* dense block slots, row-major per joint */
    double *atol;         /* [2 nrows + 1] */
    double *A, *b;        /* consistent multipliers: [nrows^2], [nrows] */
    size_t *perm;         /* [nrows] */
    double *z;            /* [ny] accelerations of a unit multiplier */
};

/* Rows and columns of the dense block of joint j: the states of a free a
 * (13), of a free b (13), then (rows) cv, cp, W or (columns) lambda, mu. */
static int free_adr(const rc_model *m, int b) { return b >= 0 ? m->body_yadr[b] : -1; }

static int block_rows(const rc_model *m, int j, int *rows)
{
    const rc_joints *J = m->jnt;
    const int aa = free_adr(m, J->ba[j]), ab = free_adr(m, J->bb[j]), ny = m->ny, nr = J->nrow[j];
    int n = 0;
    for (int k = 0; aa >= 0 && k < RC_NB; k++) rows[n++] = aa + k;
    for (int k = 0; ab >= 0 && k < RC_NB; k++) rows[n++] = ab + k;
    for (int r = 0; r < nr; r++) rows[n++] = ny + J->radr[j] + r;
    for (int r = 0; r < nr; r++) rows[n++] = ny + J->nrows + J->radr[j] + r;
    rows[n++] = ny + 2 * J->nrows;
    return n;
}

static int block_cols(const rc_model *m, int j, int *cols)
{
    const int n = block_rows(m, j, cols);
    return n - 1; /* the W column is not one of the joint's (its row has W' only) */
}

/* Joint j's dense block for the extended pattern (xpattern.h). */
static void xblock(const rc_model *m, const void *ctx, int j, int *rows, int *nrow, int *cols, int *ncol)
{
    (void)ctx;
    *nrow = block_rows(m, j, rows);
    *ncol = block_cols(m, j, cols);
}

void rc_jnt_work_free(rc_jnt_work *w)
{
    if (!w) return;
    void *p[] = {w->colptr, w->rowind, w->mslot, w->diag, w->badr, w->bslot, w->atol, w->A, w->b, w->perm, w->z};
    for (size_t k = 0; k < sizeof p / sizeof p[0]; k++) free(p[k]);
    free(w);
}

#define JMAXB (2 * RC_NB + 2 * RC_JNT_MAXROW + 1)

/* Absolute tolerances of the extras: Lambda, the impulse of a reaction
 * [N s] or [N m s], by what changes the velocity (angular velocity) of its
 * lightest body by its tolerance (m atol_v, J atol_omega; out of the error
 * test, in Newton's convergence test); nu, the projection displacement [m]
 * or rotation [-], by the position (quaternion) tolerances of its bodies;
 * W by the energy tolerance. */
static void extra_tolerances(const rc_model *m, rc_jnt_work *w)
{
    const rc_joints *J = m->jnt;
    for (int j = 0; j < J->n; j++) {
        double ap = INFINITY, aq = INFINITY, fv = INFINITY, fw = INFINITY;
        const int bs[2] = {J->ba[j], J->bb[j]};
        for (int e = 0; e < 2; e++) {
            const int b = bs[e];
            if (b < 0 || m->body_yadr[b] < 0) continue;
            const double *Jb = m->body_J + 9 * b, *at = m->atol + m->body_yadr[b];
            ap = fmin(ap, at[0]);
            aq = fmin(aq, at[3]);
            fv = fmin(fv, m->body_mass[b] * at[7]);
            fw = fmin(fw, fmin(Jb[0], fmin(Jb[4], Jb[8])) * at[10]);
        }
        for (int r = 0; r < J->nrow[j]; r++) {
            const int row = J->radr[j] + r, ang = J->rkind[row] == RC_JROW_ANGLE;
            w->atol[row] = ang ? fw : fv;
            w->atol[J->nrows + row] = ang ? aq : ap;
        }
    }
    w->atol[2 * J->nrows] = m->atol_energy > 0 ? m->atol_energy : m->rtol * fmax(m->escale, 1e-300);
}

rc_jnt_work *rc_jnt_work_new(const rc_model *m)
{
    const rc_joints *J = m->jnt;
    rc_jnt_work *w = calloc(1, sizeof *w);
    if (!w) return NULL;
    w->ny = m->ny;
    w->nrows = J->nrows;
    w->n = m->ny + 2 * J->nrows + 1;
    const int n = w->n;
    w->badr = calloc((size_t)J->n + 1, sizeof *w->badr);
    w->atol = calloc(2 * (size_t)J->nrows + 1, sizeof *w->atol);
    w->A = calloc((size_t)J->nrows * (size_t)J->nrows + 1, sizeof *w->A);
    w->b = calloc((size_t)J->nrows + 1, sizeof *w->b);
    w->perm = calloc((size_t)J->nrows + 1, sizeof *w->perm);
    w->diag = calloc((size_t)n, sizeof *w->diag);
    w->z = calloc((size_t)m->ny + 1, sizeof *w->z);
    w->mslot = calloc((size_t)m->nnz + 1, sizeof *w->mslot);
    w->colptr = calloc((size_t)n + 1, sizeof *w->colptr);
    if (!w->badr || !w->atol || !w->A || !w->b || !w->perm || !w->diag || !w->z || !w->mslot || !w->colptr) {
        rc_jnt_work_free(w);
        return NULL;
    }
    /* the joints' dense blocks, row-major one after the other */
    int64_t nb = 0;
    for (int j = 0; j < J->n; j++) {
        int rows[JMAXB], cols[JMAXB];
        w->badr[j] = nb;
        nb += (int64_t)block_rows(m, j, rows) * block_cols(m, j, cols);
    }
    w->badr[J->n] = nb;
    w->bslot = malloc(((size_t)nb + 1) * sizeof *w->bslot);
    if (!w->bslot || !(w->rowind = rc_xpat_build(m, n, J->n, JMAXB, xblock, NULL, w->badr, w->colptr, &w->nnz,
                                                 w->mslot, w->diag, w->bslot))) {
        rc_jnt_work_free(w);
        return NULL;
    }
    extra_tolerances(m, w);
    return w;
}

int rc_jnt_nextra(const rc_jnt_work *w) { return 2 * w->nrows + 1; }
int64_t rc_jnt_nnz(const rc_jnt_work *w) { return w->nnz; }

void rc_jnt_pattern(const rc_jnt_work *w, const int64_t **colptr, const int64_t **rowind)
{
    *colptr = w->colptr;
    *rowind = w->rowind;
}

double rc_jnt_atol(const rc_model *m, const rc_jnt_work *w, int k)
{
    (void)m;
    return w->atol[k];
}

/* Lambda has id 0: out of the error test (IDASetSuppressAlg). The residual
 * holds only lambda = Lambda', so Lambda itself is an accumulator (the
 * impulse since t = 0) whose accuracy does not matter. */
void rc_jnt_id(const rc_model *m, const rc_jnt_work *w, double *id)
{
    for (int k = 0; k < w->n; k++) id[k] = 1.0;
    for (int k = 0; k < w->nrows; k++) id[m->ny + k] = 0.0;
}

/* Real body states of joint j's bodies and its multipliers, lambda = Lambda'
 * and mu = nu', from Y' (Yp NULL: both 0). */
static void load_real(const rc_model *m, int j, const double *Y, const double *Yp, double *ya, double *yb,
                      double *lam, double *mu)
{
    const rc_joints *J = m->jnt;
    memcpy(ya, rc_body_state(m, J->ba[j], Y), RC_NB * sizeof(double));
    memcpy(yb, rc_body_state(m, J->bb[j], Y), RC_NB * sizeof(double));
    for (int r = 0; r < J->nrow[j]; r++) {
        lam[r] = Yp ? Yp[m->ny + J->radr[j] + r] : 0.0;
        mu[r] = Yp ? Yp[m->ny + J->nrows + J->radr[j] + r] : 0.0;
    }
}

void rc_jnt_residual(const rc_model *m, const rc_jnt_work *w, const double *Y, const double *Yp, double *r)
{
    const rc_joints *J = m->jnt;
    double pw_sum = 0;
    for (int j = 0; j < J->n; j++) {
        double ya[RC_NB], yb[RC_NB], lam[RC_JNT_MAXROW], mu[RC_JNT_MAXROW], ra[RC_NB], rb[RC_NB], pw;
        load_real(m, j, Y, Yp, ya, yb, lam, mu);
        const int aa = free_adr(m, J->ba[j]), ab = free_adr(m, J->bb[j]);
        jnt_eval_r(m, j, ya, yb, lam, mu, aa >= 0 ? ra : NULL, ab >= 0 ? rb : NULL, r + m->ny + J->radr[j],
                   r + m->ny + J->nrows + J->radr[j], &pw);
        for (int k = 0; aa >= 0 && k < RC_NB; k++) r[aa + k] += ra[k];
        for (int k = 0; ab >= 0 && k < RC_NB; k++) r[ab + k] += rb[k];
        pw_sum += pw;
    }
    const int iw = m->ny + 2 * w->nrows;
    r[iw] = Yp[iw] - pw_sum;
}

void rc_jnt_jacobian(const rc_model *m, const rc_jnt_work *w, double cj, const double *Y, const double *Yp,
                     const double *jf, double *val)
{
    const rc_joints *J = m->jnt;
    memset(val, 0, (size_t)w->nnz * sizeof(double));
    for (int64_t k = 0; k < m->nnz; k++) val[w->mslot[k]] -= jf[k];
    for (int k = 0; k < m->ny; k++) val[w->diag[k]] += cj;
    val[w->diag[w->n - 1]] += cj; /* W' */
    for (int j = 0; j < J->n; j++) {
        const int aa = free_adr(m, J->ba[j]), ab = free_adr(m, J->bb[j]), nr = J->nrow[j];
        const int na = aa >= 0 ? RC_NB : 0, nb = ab >= 0 ? RC_NB : 0;
        const int ncl = na + nb + 2 * nr;
        double yar[RC_NB], ybr[RC_NB], lr[RC_JNT_MAXROW], mr[RC_JNT_MAXROW];
        load_real(m, j, Y, Yp, yar, ybr, lr, mr);
        rc_cx ya[RC_NB], yb[RC_NB], lam[RC_JNT_MAXROW], mu[RC_JNT_MAXROW];
        rc_cs_load(yar, RC_NB, ya);
        rc_cs_load(ybr, RC_NB, yb);
        rc_cs_load(lr, nr, lam);
        rc_cs_load(mr, nr, mu);
        const int64_t *slot = w->bslot + w->badr[j];
        for (int c = 0; c < ncl; c++) {
            rc_cx *p = c < na ? ya + c : c < na + nb ? yb + (c - na) : c < na + nb + nr ? lam + (c - na - nb)
                                                                                                 : mu + (c - na - nb - nr);
            rc_cs_step(p);
            rc_cx ra[RC_NB], rb[RC_NB], cv[RC_JNT_MAXROW], cp[RC_JNT_MAXROW], pw;
            jnt_eval_c(m, j, ya, yb, lam, mu, na ? ra : NULL, nb ? rb : NULL, cv, cp, &pw);
            rc_cs_unstep(p);
            /* the columns of Lambda and nu: the residual holds their
             * derivatives lambda and mu, d/dLambda = cj d/dlambda */
            const double sc = (c < na + nb ? 1.0 : cj) / RC_CSTEP;
            int r = 0;
            for (int k = 0; k < na; k++, r++) val[slot[r * ncl + c]] += sc * cimag(ra[k]);
            for (int k = 0; k < nb; k++, r++) val[slot[r * ncl + c]] += sc * cimag(rb[k]);
            for (int k = 0; k < nr; k++, r++) val[slot[r * ncl + c]] += sc * cimag(cv[k]);
            for (int k = 0; k < nr; k++, r++) val[slot[r * ncl + c]] += sc * cimag(cp[k]);
            val[slot[r * ncl + c]] -= sc * cimag(pw); /* W row: W' - sum pw */
        }
    }
}

void rc_jnt_keep(const rc_model *m, const rc_jnt_work *w, const unsigned char *keep, unsigned char *ext)
{
    /* what rc_jnt_jacobian writes: the model's values, the diagonal, the
     * joints' blocks */
    memset(ext, 0, (size_t)w->nnz);
    for (int64_t k = 0; k < m->nnz; k++)
        if (keep[k]) ext[w->mslot[k]] = 1;
    for (int c = 0; c < w->n; c++) ext[w->diag[c]] = 1;
    for (int k = 0; k < w->badr[m->jnt->n]; k++)
        if (w->bslot[k] >= 0) ext[w->bslot[k]] = 1;
}

/* Derivatives of joint j's velocity rows along the direction z of the
 * state (z [ny], its body slices): dcv[r] = (d cv_r / dy) z. */
static void cv_along(const rc_model *m, int j, const double *Y, const double *z, double *dcv)
{
    const rc_joints *J = m->jnt;
    double yar[RC_NB], ybr[RC_NB], lr[RC_JNT_MAXROW], mr[RC_JNT_MAXROW];
    load_real(m, j, Y, NULL, yar, ybr, lr, mr);
    const int aa = free_adr(m, J->ba[j]), ab = free_adr(m, J->bb[j]);
    rc_cx ya[RC_NB], yb[RC_NB], lam[RC_JNT_MAXROW] = {0}, mu[RC_JNT_MAXROW] = {0};
    for (int k = 0; k < RC_NB; k++) {
        ya[k] = rc_cs_seed(yar[k], aa >= 0 ? z[aa + k] : 0.0);
        yb[k] = rc_cs_seed(ybr[k], ab >= 0 ? z[ab + k] : 0.0);
    }
    rc_cx cv[RC_JNT_MAXROW], cp[RC_JNT_MAXROW], pw;
    jnt_eval_c(m, j, ya, yb, lam, mu, NULL, NULL, cv, cp, &pw);
    for (int r = 0; r < J->nrow[j]; r++) dcv[r] = rc_cs_deriv(cv[r]);
}

static int shares_body(const rc_joints *J, int i, int j)
{
    return (J->ba[i] >= 0 && (J->ba[i] == J->ba[j] || J->ba[i] == J->bb[j])) ||
           (J->bb[i] >= 0 && (J->bb[i] == J->ba[j] || J->bb[i] == J->bb[j]));
}

/* Body terms of joint j for unit multiplier lambda_r (mu = 0) added, times
 * s, into out [ny]. */
static void add_unit_terms(const rc_model *m, int j, int r, const double *Y, double s, double *out)
{
    const rc_joints *J = m->jnt;
    double ya[RC_NB], yb[RC_NB], lam[RC_JNT_MAXROW] = {0}, mu[RC_JNT_MAXROW] = {0}, ra[RC_NB], rb[RC_NB];
    double cv[RC_JNT_MAXROW], cp[RC_JNT_MAXROW], pw, l0[RC_JNT_MAXROW], m0[RC_JNT_MAXROW];
    load_real(m, j, Y, NULL, ya, yb, l0, m0);
    lam[r] = 1.0;
    const int aa = free_adr(m, J->ba[j]), ab = free_adr(m, J->bb[j]);
    jnt_eval_r(m, j, ya, yb, lam, mu, aa >= 0 ? ra : NULL, ab >= 0 ? rb : NULL, cv, cp, &pw);
    for (int k = 0; aa >= 0 && k < RC_NB; k++) out[aa + k] += s * ra[k];
    for (int k = 0; ab >= 0 && k < RC_NB; k++) out[ab + k] += s * rb[k];
}

/* A = G M^-1 G^T by rows (A_sr = (dcv_s/dy) z_r, z_r the accelerations of
 * a unit lambda_r) at the state Y; zero between joints with no body in
 * common. */
static void build_A(const rc_model *m, rc_jnt_work *w, const double *Y)
{
    const rc_joints *J = m->jnt;
    const int nr = J->nrows, ny = m->ny;
    double *zr = w->z;
    memset(w->A, 0, (size_t)nr * (size_t)nr * sizeof(double));
    for (int j = 0; j < J->n; j++)
        for (int r = 0; r < J->nrow[j]; r++) {
            memset(zr, 0, (size_t)ny * sizeof(double));
            add_unit_terms(m, j, r, Y, -1.0, zr); /* accelerations = -terms */
            const int col = J->radr[j] + r;
            for (int i = 0; i < J->n; i++) {
                if (!shares_body(J, i, j)) continue;
                double dcv[RC_JNT_MAXROW];
                cv_along(m, i, Y, zr, dcv);
                for (int s = 0; s < J->nrow[i]; s++) w->A[(size_t)(J->radr[i] + s) * nr + col] = dcv[s];
            }
        }
}

/* LU of the leading n x n block of A (row stride nr) in place; 0, or 1
 * when a pivot is zero or tiny against the largest (dependent rows). */
static int lu_leading(rc_jnt_work *w, int nr, int n)
{
    gsl_matrix_view A = gsl_matrix_view_array_with_tda(w->A, (size_t)n, (size_t)n, (size_t)nr);
    gsl_permutation p = {(size_t)n, w->perm};
    int sgn;
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    int bad = gsl_linalg_LU_decomp(&A.matrix, &p, &sgn);
    gsl_set_error_handler(old);
    double dmax = 0, dmin = INFINITY;
    for (int k = 0; k < n; k++) {
        const double a = fabs(w->A[(size_t)k * nr + k]);
        dmax = fmax(dmax, a);
        dmin = fmin(dmin, a);
    }
    return bad || !(dmin > 1e-12 * dmax);
}

int rc_jnt_dependent(const rc_model *m, rc_jnt_work *w, const double *Y)
{
    const rc_joints *J = m->jnt;
    const size_t na = (size_t)J->nrows * (size_t)J->nrows;
    double *a0 = malloc((na + 1) * sizeof *a0);
    if (!a0) return J->n - 1;
    build_A(m, w, Y);
    memcpy(a0, w->A, na * sizeof *a0);
    int bad = -1;
    /* all rows at once; when they are dependent, the rows being ordered by
     * joint, the first singular leading block ends with the joint that made
     * them so (bisection over the joints) */
    if (lu_leading(w, J->nrows, J->nrows)) {
        int lo = 0, hi = J->n - 1; /* joints 0..hi are dependent */
        while (lo < hi) {
            const int mid = (lo + hi) / 2;
            memcpy(w->A, a0, na * sizeof *a0);
            if (lu_leading(w, J->nrows, J->radr[mid] + J->nrow[mid])) hi = mid;
            else lo = mid + 1;
        }
        bad = hi;
    }
    free(a0);
    return bad;
}

/* A x = b in place (w->b) for A = G M^-1 G^T at Y (build_A), by GSL's LU
 * of the leading nr x nr block; 0, or -1 when A is singular. */
static int solve_A(const rc_model *m, rc_jnt_work *w, const double *Y, int nr)
{
    build_A(m, w, Y);
    if (lu_leading(w, nr, nr)) return -1;
    gsl_matrix_view A = gsl_matrix_view_array(w->A, (size_t)nr, (size_t)nr);
    gsl_vector_view b = gsl_vector_view_array(w->b, (size_t)nr);
    gsl_permutation p = {(size_t)nr, w->perm};
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    const int bad = gsl_linalg_LU_svx(&A.matrix, &p, &b.vector);
    gsl_set_error_handler(old);
    return bad ? -1 : 0;
}

int rc_jnt_project_velocities(const rc_model *m, rc_jnt_work *w, double *Y)
{
    const rc_joints *J = m->jnt;
    const int nr = J->nrows, ny = m->ny;
    /* b = -G u; A x = b; u += M^-1 G^T x (the accelerations of the unit
     * multipliers, z_r, are M^-1 G^T e_r): the smallest change of the
     * kinetic energy that satisfies G u = 0 (G depends on q only) */
    for (int j = 0; j < J->n; j++) {
        double ya[RC_NB], yb[RC_NB], lam[RC_JNT_MAXROW], mu[RC_JNT_MAXROW], pw;
        double cv[RC_JNT_MAXROW], cp[RC_JNT_MAXROW];
        load_real(m, j, Y, NULL, ya, yb, lam, mu);
        jnt_eval_r(m, j, ya, yb, lam, mu, NULL, NULL, cv, cp, &pw);
        for (int r = 0; r < J->nrow[j]; r++) w->b[J->radr[j] + r] = -cv[r];
    }
    if (solve_A(m, w, Y, nr)) return -1;
    memset(w->z, 0, (size_t)ny * sizeof(double));
    for (int j = 0; j < J->n; j++)
        for (int r = 0; r < J->nrow[j]; r++) add_unit_terms(m, j, r, Y, -w->b[J->radr[j] + r], w->z);
    for (int k = 0; k < ny; k++) Y[k] += w->z[k];
    return 0;
}

int rc_jnt_consistent(const rc_model *m, rc_jnt_work *w, double *Y, double *Yp)
{
    const rc_joints *J = m->jnt;
    const int nr = J->nrows, ny = m->ny;
    /* the residual of the bodies is y' - f - (accelerations of lambda) with
     * mu = 0; the velocity rows stay zero along the motion:
     * A lambda = -(dcv/dy) f, A = G M^-1 G^T (build_A) */
    for (int j = 0; j < J->n; j++) {
        double dcv[RC_JNT_MAXROW];
        cv_along(m, j, Y, Yp, dcv);
        for (int r = 0; r < J->nrow[j]; r++) w->b[J->radr[j] + r] = -dcv[r];
    }
    if (solve_A(m, w, Y, nr)) return -1;
    for (int k = 0; k < nr; k++) {
        Yp[ny + k] = w->b[k];  /* lambda; Lambda keeps the impulse so far */
        Yp[ny + nr + k] = 0.0; /* mu = 0; nu keeps the projection so far */
    }
    /* y' = f + accelerations of lambda */
    double pw_sum = 0;
    for (int j = 0; j < J->n; j++) {
        double ya[RC_NB], yb[RC_NB], lam[RC_JNT_MAXROW], mu[RC_JNT_MAXROW], ra[RC_NB], rb[RC_NB], pw;
        double cv[RC_JNT_MAXROW], cp[RC_JNT_MAXROW];
        load_real(m, j, Y, Yp, ya, yb, lam, mu);
        const int aa = free_adr(m, J->ba[j]), ab = free_adr(m, J->bb[j]);
        jnt_eval_r(m, j, ya, yb, lam, mu, aa >= 0 ? ra : NULL, ab >= 0 ? rb : NULL, cv, cp, &pw);
        for (int k = 0; aa >= 0 && k < RC_NB; k++) Yp[aa + k] -= ra[k];
        for (int k = 0; ab >= 0 && k < RC_NB; k++) Yp[ab + k] -= rb[k];
        pw_sum += pw;
    }
    Yp[ny + 2 * nr] = pw_sum;
    return 0;
}

rc_status rc_jnt_check_initial(const rc_model *m, rc_jnt_work *w, const double *Y, rc_error *err)
{
    const rc_joints *J = m->jnt;
    (void)w;
    for (int j = 0; j < J->n; j++) {
        double ya[RC_NB], yb[RC_NB], lam[RC_JNT_MAXROW], mu[RC_JNT_MAXROW], g[RC_JNT_MAXROW], wr[RC_JNT_MAXROW][12];
        load_real(m, j, Y, NULL, ya, yb, lam, mu);
        jnt_rows_r(m, j, ya, yb, g, wr);
        double wa[3], wb[3];
        jrot_r(ya + 3, ya + 10, wa, 0);
        jrot_r(yb + 3, yb + 10, wb, 0);
        for (int r = 0; r < J->nrow[j]; r++) {
            const double *F = wr[r];
            const double t[4] = {dot_r(F, ya + 7), dot_r(F + 3, wa), dot_r(F + 6, yb + 7), dot_r(F + 9, wb)};
            const double cv = t[0] + t[1] + t[2] + t[3];
            const double scale = fabs(t[0]) + fabs(t[1]) + fabs(t[2]) + fabs(t[3]);
            const int row = J->radr[j] + r, ang = J->rkind[row] == RC_JROW_ANGLE;
            if (fabs(cv) > 1e-6 * scale + 1e-12)
                RC_RAISE(err, RC_EINPUT,
                         RC_LOCFMT "card %s: the initial velocities of its bodies violate the joint (constraint row "
                                   "%d, %s): %s = %.6g %s, expected 0; give the bodies velocities (/RBODY, /INIVEL) "
                                   "that the joint allows",
                         RC_LOC(J->loc[j]), J->name[j], r + 1, ang ? "relative rotation rate" : "relative velocity",
                         ang ? "rate of the axes' dot product" : "relative velocity along the row", cv,
                         ang ? "1/s" : "m/s");
            if (fabs(g[r]) > 1e-9 * (1.0 + sqrt(dot_r(ya, ya)) + sqrt(dot_r(yb, yb))))
                RC_RAISE(err, RC_EINPUT,
                         RC_LOCFMT "card %s: the initial positions of its bodies violate the joint (constraint row "
                                   "%d): residual %.6g %s, expected 0",
                         RC_LOC(J->loc[j]), J->name[j], r + 1, g[r], ang ? "" : "m");
        }
    }
    return RC_OK;
}

void rc_jnt_report(const rc_model *m, int j, const double *Y, double force[3], double moment[3], double *drift_pos,
                   double *drift_ang)
{
    const rc_joints *J = m->jnt;
    double ya[RC_NB], yb[RC_NB], lam[RC_JNT_MAXROW], mu[RC_JNT_MAXROW], g[RC_JNT_MAXROW], wr[RC_JNT_MAXROW][12];
    load_real(m, j, Y, NULL, ya, yb, lam, mu);
    for (int r = 0; r < J->nrow[j]; r++) lam[r] = Y[m->ny + J->radr[j] + r]; /* a record vector: lambda there */
    jnt_rows_r(m, j, ya, yb, g, wr);
    double F[3] = {0, 0, 0}, tau[3] = {0, 0, 0};
    *drift_pos = 0;
    *drift_ang = 0;
    for (int r = 0; r < J->nrow[j]; r++) {
        for (int k = 0; k < 3; k++) {
            F[k] += lam[r] * wr[r][k];
            tau[k] += lam[r] * wr[r][3 + k];
        }
        if (J->rkind[J->radr[j] + r] == RC_JROW_ANGLE) *drift_ang = fmax(*drift_ang, fabs(g[r]));
        else *drift_pos = fmax(*drift_pos, fabs(g[r]));
    }
    /* moment about the anchor point of a: tau - r_a x F */
    double ra[3], rxf[3];
    jrot_r(ya + 3, J->sa + 3 * j, ra, 0);
    cross_r(ra, F, rxf);
    for (int k = 0; k < 3; k++) {
        force[k] = F[k];
        moment[k] = tau[k] - rxf[k];
    }
}

void rc_jnt_rows(const rc_model *m, int j, const double *ya, const double *yb, double *g, double (*w)[12])
{
    jnt_rows_r(m, j, ya, yb, g, w);
}

void rc_jnt_rows_cx(const rc_model *m, int j, const double complex *ya, const double complex *yb, double complex *g,
                    double complex (*w)[12])
{
    jnt_rows_c(m, j, ya, yb, g, w);
}

double rc_jnt_work_done(const rc_model *m, const double *Y) { return Y[m->ny + 2 * m->jnt->nrows]; }

void rc_jnt_frame(const rc_model *m, const double *Y, double *force, double *moment, double *drift_pos,
                  double *drift_ang, double *work)
{
    for (int j = 0; j < m->jnt->n; j++)
        rc_jnt_report(m, j, Y, force + 3 * j, moment + 3 * j, drift_pos + j, drift_ang + j);
    *work = rc_jnt_work_done(m, Y);
}

/* ---- the joints as a constraint set (cset.h) -------------------------- */
static int jset_needed(const rc_model *m) { return m->jnt && m->jnt->n > 0; }
/* their extras start at ny: the first set of a composition */
static void *jset_open(const rc_model *m, int base) { return base == m->ny ? rc_jnt_work_new(m) : NULL; }
static void jset_close(void *w) { rc_jnt_work_free(w); }
static int jset_nextra(const void *w) { return rc_jnt_nextra(w); }
static int64_t jset_nnz(const void *w) { return rc_jnt_nnz(w); }
static void jset_pattern(const void *w, const int64_t **colptr, const int64_t **rowind)
{
    rc_jnt_pattern(w, colptr, rowind);
}
static double jset_atol(const rc_model *m, const void *w, int k) { return rc_jnt_atol(m, w, k); }
static void jset_id(const rc_model *m, const void *w, double *id) { rc_jnt_id(m, w, id); }
static void jset_residual(const rc_model *m, const rc_data *d, const void *w, const double *Y, const double *Yp,
                          double *r)
{
    (void)d;
    rc_jnt_residual(m, w, Y, Yp, r);
}
static void jset_jacobian(const rc_model *m, const rc_data *d, const void *w, double cj, const double *Y,
                          const double *Yp, const double *jf, double *val)
{
    (void)d;
    rc_jnt_jacobian(m, w, cj, Y, Yp, jf, val);
}
static void jset_keep(const rc_model *m, const rc_data *d, const void *w, const unsigned char *keep,
                      unsigned char *ext)
{
    (void)d;
    rc_jnt_keep(m, w, keep, ext);
}
static int jset_project(const rc_model *m, rc_data *d, void *w, double *Y)
{
    (void)d;
    return rc_jnt_project_velocities(m, w, Y);
}
static int jset_multipliers(const rc_model *m, void *w, double *Y, double *Yp)
{
    return rc_jnt_consistent(m, w, Y, Yp);
}
/* the reactions lambda = Lambda' in the slots of Lambda */
static void jset_record(const rc_model *m, rc_data *d, void *w, double t, const double *Y, const double *Yp,
                        double *Yrec)
{
    (void)d;
    (void)w;
    (void)t;
    (void)Y;
    memcpy(Yrec + m->ny, Yp + m->ny, (size_t)m->jnt->nrows * sizeof(double));
}

const rc_cset_ops rc_jnt_set_ops = {
    .what = "joints: stabilised index-2 constraints (GGL)",
    .start_failed = "the joints' constraint rows are dependent at t = 0 (the model's compile checks them: an "
                    "internal error)",
    .needed = jset_needed, .open = jset_open, .close = jset_close, .nextra = jset_nextra, .nnz = jset_nnz,
    .pattern = jset_pattern, .atol = jset_atol, .id = jset_id, .residual = jset_residual, .jacobian = jset_jacobian,
    .keep = jset_keep, .project = jset_project, .project_at_restart = 0, .multipliers = jset_multipliers,
    .roots = NULL, .record = jset_record, .before_events = NULL};
