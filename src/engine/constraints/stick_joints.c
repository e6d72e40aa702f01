/*
 * Joints and exact stick in one model (engine/constraints/stick.h, "together"; docs/
 * theory.md "Exact stick"): one constraint set on the integrator's vector
 * Y = [y, Lambda_J, nu, W, Lambda_S], the joints' extras (model/joint.h)
 * then the stick's Lambda. Its residual is the sum of both sets' terms; its
 * pattern the union of both extended patterns, its Jacobian their sum less
 * the model's block counted twice; the consistent start solves both sets'
 * multipliers together. The residual is pure.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "model/joint.h"
#include "model/model.h"
#include "engine/constraints/stick.h"
#include "engine/assembly/assembly.h"
#include "engine/constraints/joints.h"
#include "engine/constraints/stick_joints.h"

struct rc_both {
    rc_jnt_work *jw;
    rc_stk_work *sw;
    int ny, nj, n;          /* n = ny + nj + 3 ns (rc_stk_nextra) */
    int64_t nnz;            /* entries of the union */
    int64_t *ucol, *urow;   /* [n + 1], [nnz] */
    int64_t *jmap, *smap;   /* slot of each entry of the joints' / stick's pattern */
    int64_t *mmap, *dmap;   /* slot of each entry of the model's pattern, of the diagonal of y */
    double *vj, *vs;        /* values on the joints' / stick's pattern */
    double *f0, *zj, *zs;   /* [ny] consistent start: f, the joints' and the stick's accelerations */
};

static int64_t union_slot(const rc_both *c, int64_t row, int64_t col)
{
    return rc_csc_slot(c->ucol, c->urow, row, col);
}

void rc_both_free(rc_both *c)
{
    if (!c) return;
    rc_jnt_work_free(c->jw);
    rc_stk_work_free(c->sw);
    void *p[] = {c->ucol, c->urow, c->jmap, c->smap, c->mmap, c->dmap, c->vj, c->vs, c->f0, c->zj, c->zs};
    for (size_t k = 0; k < sizeof p / sizeof p[0]; k++) free(p[k]);
    free(c);
}

/* The union of the joints' pattern (over Y[0 .. ny + nj)) and the stick's
 * (over all of Y), and the slot maps. */
rc_both *rc_both_new(const rc_model *m)
{
    rc_both *c = calloc(1, sizeof *c);
    if (!c) return NULL;
    c->ny = m->ny;
    if (!(c->jw = rc_jnt_work_new(m))) goto fail;
    c->nj = rc_jnt_nextra(c->jw);
    if (!(c->sw = rc_stk_work_new_at(m, m->ny + c->nj))) goto fail;
    const int n = c->n = m->ny + c->nj + rc_stk_nextra(c->sw);
    const int64_t *jc, *jr, *sc, *sr;
    rc_jnt_pattern(c->jw, &jc, &jr);
    rc_stk_pattern(c->sw, &sc, &sr);
    const int64_t nj = rc_jnt_nnz(c->jw), ns = rc_stk_nnz(c->sw);
    int64_t *key = malloc((size_t)(nj + ns) * sizeof *key);
    c->ucol = calloc((size_t)n + 1, sizeof *c->ucol);
    c->jmap = malloc((size_t)nj * sizeof *c->jmap);
    c->smap = malloc((size_t)ns * sizeof *c->smap);
    c->mmap = malloc(((size_t)m->nnz + 1) * sizeof *c->mmap);
    c->dmap = malloc(((size_t)m->ny + 1) * sizeof *c->dmap);
    c->vj = malloc((size_t)nj * sizeof *c->vj);
    c->vs = malloc((size_t)ns * sizeof *c->vs);
    c->f0 = malloc(((size_t)m->ny + 1) * sizeof *c->f0);
    c->zj = malloc(((size_t)m->ny + 1) * sizeof *c->zj);
    c->zs = malloc(((size_t)m->ny + 1) * sizeof *c->zs);
    if (!key || !c->ucol || !c->jmap || !c->smap || !c->mmap || !c->dmap || !c->vj || !c->vs || !c->f0 || !c->zj ||
        !c->zs) {
        free(key);
        goto fail;
    }
    int64_t nk = 0;
    for (int col = 0; col < m->ny + c->nj; col++)
        for (int64_t k = jc[col]; k < jc[col + 1]; k++) key[nk++] = (int64_t)col * n + jr[k];
    for (int col = 0; col < n; col++)
        for (int64_t k = sc[col]; k < sc[col + 1]; k++) key[nk++] = (int64_t)col * n + sr[k];
    c->urow = rc_csc_from_keys(key, nk, n, c->ucol, &c->nnz);
    free(key);
    if (!c->urow) goto fail;
    for (int col = 0; col < m->ny + c->nj; col++)
        for (int64_t k = jc[col]; k < jc[col + 1]; k++) c->jmap[k] = union_slot(c, jr[k], col);
    for (int col = 0; col < n; col++)
        for (int64_t k = sc[col]; k < sc[col + 1]; k++) c->smap[k] = union_slot(c, sr[k], col);
    for (int col = 0; col < m->ny; col++) {
        for (int64_t k = m->jac_colptr[col]; k < m->jac_colptr[col + 1]; k++)
            c->mmap[k] = union_slot(c, m->jac_rowind[k], col);
        c->dmap[col] = union_slot(c, col, col);
    }
    return c;
fail:
    rc_both_free(c);
    return NULL;
}

rc_jnt_work *rc_both_jnt(const rc_both *c) { return c->jw; }
rc_stk_work *rc_both_stk(const rc_both *c) { return c->sw; }
int rc_both_nextra(const rc_both *c) { return c->n - c->ny; }
int64_t rc_both_nnz(const rc_both *c) { return c->nnz; }

void rc_both_pattern(const rc_both *c, const int64_t **colptr, const int64_t **rowind)
{
    *colptr = c->ucol;
    *rowind = c->urow;
}

double rc_both_atol(const rc_model *m, const rc_both *c, int k)
{
    return k < c->nj ? rc_jnt_atol(m, c->jw, k) : rc_stk_atol(c->sw, k - c->nj);
}

void rc_both_id(const rc_model *m, const rc_both *c, double *id)
{
    rc_jnt_id(m, c->jw, id);
    rc_stk_id(m, c->sw, id);
}

void rc_both_residual(const rc_model *m, const rc_data *d, const rc_both *c, const double *Y, const double *Yp,
                      double *r)
{
    rc_jnt_residual(m, c->jw, Y, Yp, r);
    rc_stk_residual(m, d, c->sw, Y, Yp, r);
}

/* Each set on its own pattern, each with the model's block (cj I - J_f on
 * y), summed into the union with that block once. Values only: jf and the
 * scratch are the work's (not pure of the work, pure of the model). */
void rc_both_jacobian(const rc_model *m, const rc_data *d, const rc_both *c, double cj, const double *Y,
                      const double *Yp, const double *jf, double *val)
{
    rc_jnt_jacobian(m, c->jw, cj, Y, Yp, jf, c->vj);
    rc_stk_jacobian(m, d, c->sw, cj, Y, Yp, jf, c->vs);
    memset(val, 0, (size_t)c->nnz * sizeof(double));
    for (int64_t k = 0; k < rc_jnt_nnz(c->jw); k++) val[c->jmap[k]] += c->vj[k];
    for (int64_t k = 0; k < rc_stk_nnz(c->sw); k++) val[c->smap[k]] += c->vs[k];
    for (int64_t k = 0; k < m->nnz; k++) val[c->mmap[k]] += jf[k];
    for (int r = 0; r < m->ny; r++) val[c->dmap[r]] -= cj;
}

/* The velocities made to satisfy the joints' and the sticking rows together
 * (alternating projections, each the change of least kinetic energy, to a
 * fixed point), then the multipliers of both sets from the
 * acceleration-level equations by block Gauss-Seidel: A = G M^-1 G^T over
 * both sets is symmetric positive definite, each block is solved exactly
 * with the other's accelerations, to convergence. */
#define BOTH_MAXIT 2000
int rc_both_consistent(const rc_model *m, rc_data *d, rc_both *c, double t, double *y, double *p)
{
    const int ny = m->ny;
    int it;
    for (it = 0; it < BOTH_MAXIT; it++) {
        memcpy(c->f0, y, (size_t)ny * sizeof(double));
        if (rc_stk_prepare(m, d, c->sw, y) || rc_jnt_project_velocities(m, c->jw, y)) return -1;
        double dv = 0;
        for (int k = 0; k < ny; k++) dv = fmax(dv, fabs(y[k] - c->f0[k]) / m->atol[k]);
        if (dv < 1e-9) break;
    }
    if (it == BOTH_MAXIT) return -1;
    if (rc_assemble_rhs(m, d, t, y, c->f0)) return -1;
    double fs = 0;
    for (int k = 0; k < ny; k++) {
        c->zj[k] = c->zs[k] = 0.0;
        fs = fmax(fs, fabs(c->f0[k]));
    }
    for (it = 0; it < BOTH_MAXIT; it++) {
        for (int k = 0; k < ny; k++) p[k] = c->f0[k] + c->zs[k];
        if (rc_jnt_consistent(m, c->jw, y, p)) return -1;
        for (int k = 0; k < ny; k++) {
            c->zj[k] = p[k] - c->f0[k] - c->zs[k];
            p[k] = c->f0[k] + c->zj[k];
        }
        if (rc_stk_consistent(m, c->sw, y, p)) return -1;
        double dz = 0, zmax = fs;
        for (int k = 0; k < ny; k++) {
            const double zs = p[k] - c->f0[k] - c->zj[k];
            dz = fmax(dz, fabs(zs - c->zs[k]));
            zmax = fmax(zmax, fmax(fabs(c->zj[k]), fabs(zs)));
            c->zs[k] = zs;
        }
        if (dz <= 1e-14 * zmax) return 0;
    }
    return -1;
}

/* The force that holds sticking exact interface i with the joints: the
 * multipliers of the sticking contacts solved with the joints' on a copy
 * of the state. 0, or -1. */
static int hold_with_joints(const rc_model *m, rc_data *d, int i, double t, const double *y, double F[3])
{
    rc_both *b = rc_both_new(m);
    const int n = b ? m->ny + rc_both_nextra(b) : 0;
    double *Y = b ? calloc((size_t)n, sizeof *Y) : NULL, *Yp = b ? calloc((size_t)n, sizeof *Yp) : NULL;
    int st = -1;
    if (Y && Yp) {
        memcpy(Y, y, (size_t)m->ny * sizeof *Y);
        const rc_stk_work *w = rc_both_stk(b);
        const int me = rc_stk_slot_of(w, i);
        if (me >= 0 && !rc_both_consistent(m, d, b, t, Y, Yp)) {
            rc_stk_slot_force(m, w, me, Y, Yp, F);
            st = 0;
        }
    }
    free(Y);
    free(Yp);
    rc_both_free(b);
    return st;
}

int rc_stk_decide(const rc_model *m, rc_data *d, int i, double t, const double *y, double e[3])
{
    rc_inter_report r;
    if (rc_stk_sliding(m, d, i, t, y, &r, e)) return 1;
    /* the force that holds it, with the other sticking contacts (and the joints) */
    double F[3];
    const int st = m->jnt && m->jnt->n > 0 ? hold_with_joints(m, d, i, t, y, F) : rc_stk_hold_force(m, d, i, t, y, F);
    if (st) return -1;
    const double nf = sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]);
    for (int k = 0; k < 3; k++) e[k] = nf > 0 ? F[k] / nf : 0.0;
    return nf > r.flim; /* the slip root's limit */
}
