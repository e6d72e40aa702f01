/*
 * The constraint sets a model needs, composed into one (cset.h; docs/
 * theory.md "IDA backend" and "Exact stick"). One set is used as it is: its
 * pattern, residual and Jacobian. Several share one extended pattern, the
 * union of theirs, built once here: the residual is the sum of their terms,
 * the Jacobian the sum of theirs less the model's block counted more than
 * once, and the consistent start solves the multipliers of all sets
 * together. A new set is one file with its rc_cset_ops and one line in
 * `sets` below.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "engine/constraints/cset.h"
#include "engine/constraints/stick.h"
#include "engine/assembly/assembly.h"

/* The sets, in the order of their extras in Y. */
static const rc_cset_ops *const sets[] = {&rc_jnt_set_ops, &rc_stk_set_ops};
#define NSETS ((int)(sizeof sets / sizeof sets[0]))

/* Iterations of the composed consistent start (projections, multipliers). */
#define CSET_MAXIT 2000

struct rc_cset {
    int ns;                       /* sets in the composition */
    const rc_cset_ops *ops[NSETS];
    void *w[NSETS];
    int base[NSETS + 1];          /* first extra of each set in Y; base[ns] = n */
    int ny, n;
    char what[256];
    /* several sets: the union of their patterns */
    int64_t nnz;                  /* entries of the pattern */
    int64_t *ucol, *urow;         /* [n + 1], [nnz] */
    int64_t *map[NSETS];          /* slot in the union of each entry of a set's pattern */
    double *val[NSETS];           /* values on a set's pattern */
    int64_t *mmap, *dmap;         /* slot of each entry of the model's pattern, of the diagonal of y */
    double *f0;                   /* [ny] consistent start: f */
    double *z[NSETS];             /* [ny] each set's accelerations */
};

int rc_cset_needed(const rc_model *m)
{
    for (int s = 0; s < NSETS; s++)
        if (sets[s]->needed(m)) return 1;
    return 0;
}

void rc_cset_free(rc_cset *c)
{
    if (!c) return;
    for (int s = 0; s < c->ns; s++) {
        c->ops[s]->close(c->w[s]);
        free(c->map[s]);
        free(c->val[s]);
        free(c->z[s]);
    }
    free(c->ucol);
    free(c->urow);
    free(c->mmap);
    free(c->dmap);
    free(c->f0);
    free(c);
}

static int64_t union_slot(const rc_cset *c, int64_t row, int64_t col)
{
    return rc_csc_slot(c->ucol, c->urow, row, col);
}

/* The union of the sets' patterns (each over Y[0 .. its base + nextra))
 * and the slot maps. */
static int build_union(const rc_model *m, rc_cset *c)
{
    const int n = c->n;
    int64_t total = 0;
    for (int s = 0; s < c->ns; s++) total += c->ops[s]->nnz(c->w[s]);
    int64_t *key = malloc((size_t)(total + 1) * sizeof *key);
    c->ucol = calloc((size_t)n + 1, sizeof *c->ucol);
    c->mmap = malloc(((size_t)m->nnz + 1) * sizeof *c->mmap);
    c->dmap = malloc(((size_t)m->ny + 1) * sizeof *c->dmap);
    c->f0 = malloc(((size_t)m->ny + 1) * sizeof *c->f0);
    int ok = key && c->ucol && c->mmap && c->dmap && c->f0;
    for (int s = 0; ok && s < c->ns; s++) {
        const int64_t nz = c->ops[s]->nnz(c->w[s]);
        c->map[s] = malloc((size_t)(nz + 1) * sizeof *c->map[s]);
        c->val[s] = malloc((size_t)(nz + 1) * sizeof *c->val[s]);
        c->z[s] = malloc(((size_t)m->ny + 1) * sizeof *c->z[s]);
        ok = c->map[s] && c->val[s] && c->z[s];
    }
    if (!ok) {
        free(key);
        return -1;
    }
    int64_t nk = 0;
    for (int s = 0; s < c->ns; s++) {
        const int64_t *cp, *rp;
        c->ops[s]->pattern(c->w[s], &cp, &rp);
        for (int col = 0; col < c->base[s + 1]; col++)
            for (int64_t k = cp[col]; k < cp[col + 1]; k++) key[nk++] = (int64_t)col * n + rp[k];
    }
    c->urow = rc_csc_from_keys(key, nk, n, c->ucol, &c->nnz);
    free(key);
    if (!c->urow) return -1;
    for (int s = 0; s < c->ns; s++) {
        const int64_t *cp, *rp;
        c->ops[s]->pattern(c->w[s], &cp, &rp);
        for (int col = 0; col < c->base[s + 1]; col++)
            for (int64_t k = cp[col]; k < cp[col + 1]; k++) c->map[s][k] = union_slot(c, rp[k], col);
    }
    for (int col = 0; col < m->ny; col++) {
        for (int64_t k = m->jac_colptr[col]; k < m->jac_colptr[col + 1]; k++)
            c->mmap[k] = union_slot(c, m->jac_rowind[k], col);
        c->dmap[col] = union_slot(c, col, col);
    }
    return 0;
}

rc_cset *rc_cset_new(const rc_model *m)
{
    if (!rc_cset_needed(m)) return NULL;
    rc_cset *c = calloc(1, sizeof *c);
    if (!c) return NULL;
    c->ny = c->n = m->ny;
    size_t len = 0;
    for (int s = 0; s < NSETS; s++) {
        if (!sets[s]->needed(m)) continue;
        const int q = c->ns;
        c->ops[q] = sets[s];
        c->base[q] = c->n;
        if (!(c->w[q] = sets[s]->open(m, c->n))) goto fail;
        c->ns++;
        c->n += sets[s]->nextra(c->w[q]);
        len += (size_t)snprintf(c->what + len, len < sizeof c->what ? sizeof c->what - len : 0, "%s%s",
                                q ? "; " : "", sets[s]->what);
    }
    c->base[c->ns] = c->n;
    if (c->ns > 1 && build_union(m, c)) goto fail;
    return c;
fail:
    rc_cset_free(c);
    return NULL;
}

void *rc_cset_part(const rc_cset *c, const rc_cset_ops *ops)
{
    for (int s = 0; c && s < c->ns; s++)
        if (c->ops[s] == ops) return c->w[s];
    return NULL;
}

const char *rc_cset_what(const rc_cset *c) { return c->what; }

const char *rc_cset_start_failed(const rc_cset *c)
{
    if (c->ns == 1) return c->ops[0]->start_failed;
    return "joints and exact stick at t = 0: the constraint rows are dependent (a sticking contact holds a motion "
           "a joint already holds, or two sticking contacts the same) or the forces could not be evaluated";
}

int rc_cset_nextra(const rc_cset *c) { return c->n - c->ny; }
int64_t rc_cset_nnz(const rc_cset *c) { return c->ns == 1 ? c->ops[0]->nnz(c->w[0]) : c->nnz; }

void rc_cset_pattern(const rc_cset *c, const int64_t **colptr, const int64_t **rowind)
{
    if (c->ns == 1) {
        c->ops[0]->pattern(c->w[0], colptr, rowind);
        return;
    }
    *colptr = c->ucol;
    *rowind = c->urow;
}

double rc_cset_atol(const rc_model *m, const rc_cset *c, int k)
{
    int s = 0;
    while (s + 1 < c->ns && c->ny + k >= c->base[s + 1]) s++;
    return c->ops[s]->atol(m, c->w[s], c->ny + k - c->base[s]);
}

void rc_cset_id(const rc_model *m, const rc_cset *c, double *id)
{
    for (int s = 0; s < c->ns; s++) c->ops[s]->id(m, c->w[s], id);
}

void rc_cset_residual(const rc_model *m, const rc_data *d, const rc_cset *c, const double *Y, const double *Yp,
                      double *r)
{
    for (int s = 0; s < c->ns; s++) c->ops[s]->residual(m, d, c->w[s], Y, Yp, r);
}

/* Several sets: each on its own pattern, each with the model's block
 * (cj I - J_f on y), summed into the union with that block once. */
void rc_cset_jacobian(const rc_model *m, const rc_data *d, const rc_cset *c, double cj, const double *Y,
                      const double *Yp, const double *jf, double *val)
{
    if (c->ns == 1) {
        c->ops[0]->jacobian(m, d, c->w[0], cj, Y, Yp, jf, val);
        return;
    }
    for (int s = 0; s < c->ns; s++) c->ops[s]->jacobian(m, d, c->w[s], cj, Y, Yp, jf, c->val[s]);
    memset(val, 0, (size_t)c->nnz * sizeof(double));
    for (int s = 0; s < c->ns; s++) {
        const int64_t nz = c->ops[s]->nnz(c->w[s]);
        for (int64_t k = 0; k < nz; k++) val[c->map[s][k]] += c->val[s][k];
    }
    for (int s = 1; s < c->ns; s++) {
        for (int64_t k = 0; k < m->nnz; k++) val[c->mmap[k]] += jf[k];
        for (int r = 0; r < m->ny; r++) val[c->dmap[r]] -= cj;
    }
}

int rc_cset_keeps(const rc_cset *c) { return c->ns == 1 && c->ops[0]->keep; }

void rc_cset_keep(const rc_model *m, const rc_data *d, const rc_cset *c, const unsigned char *keep,
                  unsigned char *ext)
{
    c->ops[0]->keep(m, d, c->w[0], keep, ext);
}

/* One set: its projection (at the start, or at every restart where the set
 * asks), f, its multipliers. Several: the velocities made to satisfy all
 * sets' rows (alternating projections, each the change of least kinetic
 * energy, from the last set to the first, to a fixed point), then the
 * multipliers of all sets from the acceleration-level equations by block
 * Gauss-Seidel: A = G M^-1 G^T over all sets is symmetric positive
 * definite, each block is solved exactly with the others' accelerations,
 * until the accelerations of the sets after the first no longer change
 * (the first set's follow from theirs). */
int rc_cset_consistent(const rc_model *m, rc_data *d, rc_cset *c, double t, double *y, double *p, int start)
{
    const int ny = m->ny;
    if (c->ns == 1) {
        if ((start || c->ops[0]->project_at_restart) && c->ops[0]->project(m, d, c->w[0], y)) return -1;
        if (rc_assemble_rhs(m, d, t, y, p)) return -2;
        return c->ops[0]->multipliers(m, c->w[0], y, p) ? -1 : 0;
    }
    int it;
    for (it = 0; it < CSET_MAXIT; it++) {
        memcpy(c->f0, y, (size_t)ny * sizeof(double));
        for (int s = c->ns - 1; s >= 0; s--)
            if (c->ops[s]->project(m, d, c->w[s], y)) return -1;
        double dv = 0;
        for (int k = 0; k < ny; k++) dv = fmax(dv, fabs(y[k] - c->f0[k]) / m->atol[k]);
        if (dv < 1e-9) break;
    }
    if (it == CSET_MAXIT) return -1;
    if (rc_assemble_rhs(m, d, t, y, c->f0)) return -2;
    double fs = 0;
    for (int k = 0; k < ny; k++) {
        for (int s = 0; s < c->ns; s++) c->z[s][k] = 0.0;
        fs = fmax(fs, fabs(c->f0[k]));
    }
    for (it = 0; it < CSET_MAXIT; it++) {
        double dz = 0, zmax = fs;
        for (int s = 0; s < c->ns; s++) {
            /* the rates with the other sets' accelerations */
            for (int k = 0; k < ny; k++) {
                double v = c->f0[k];
                for (int q = 0; q < c->ns; q++)
                    if (q != s) v += c->z[q][k];
                p[k] = v;
            }
            if (c->ops[s]->multipliers(m, c->w[s], y, p)) return -1;
            for (int k = 0; k < ny; k++) {
                double z = p[k] - c->f0[k];
                for (int q = 0; q < c->ns; q++)
                    if (q != s) z -= c->z[q][k];
                if (s > 0) dz = fmax(dz, fabs(z - c->z[s][k]));
                c->z[s][k] = z;
            }
        }
        for (int s = 0; s < c->ns; s++)
            for (int k = 0; k < ny; k++) zmax = fmax(zmax, fabs(c->z[s][k]));
        if (dz <= 1e-14 * zmax) return 0;
    }
    return -1;
}

void rc_cset_roots(const rc_model *m, rc_data *d, const rc_cset *c, double t, const double *Y, const double *Yp,
                   double *g)
{
    for (int s = 0; s < c->ns; s++)
        if (c->ops[s]->roots) c->ops[s]->roots(m, d, c->w[s], t, Y, Yp, g);
}

void rc_cset_record(const rc_model *m, rc_data *d, const rc_cset *c, double t, const double *Y, const double *Yp,
                    double *Yrec)
{
    memcpy(Yrec, Y, (size_t)c->n * sizeof(double));
    for (int s = c->ns - 1; s >= 0; s--)
        if (c->ops[s]->record) c->ops[s]->record(m, d, c->w[s], t, Y, Yp, Yrec);
}

void rc_cset_before_events(const rc_model *m, const rc_data *d, const rc_cset *c, double *Y, const double *Yp)
{
    for (int s = 0; s < c->ns; s++)
        if (c->ops[s]->before_events) c->ops[s]->before_events(m, d, c->w[s], Y, Yp);
}

/* The force that holds sticking exact interface i with the other sets: the
 * multipliers of the sticking contacts solved with theirs on a copy of the
 * state. 0, or -1. */
static int hold_with_sets(const rc_model *m, rc_data *d, int i, double t, const double *y, double F[3])
{
    rc_cset *c = rc_cset_new(m);
    const int n = c ? c->n : 0;
    double *Y = c ? calloc((size_t)n, sizeof *Y) : NULL, *Yp = c ? calloc((size_t)n, sizeof *Yp) : NULL;
    int st = -1;
    if (Y && Yp) {
        memcpy(Y, y, (size_t)m->ny * sizeof *Y);
        const rc_stk_work *w = rc_cset_part(c, &rc_stk_set_ops);
        const int me = w ? rc_stk_slot_of(w, i) : -1;
        if (me >= 0 && !rc_cset_consistent(m, d, c, t, Y, Yp, 1)) {
            rc_stk_slot_force(m, w, me, Y, Yp, F);
            st = 0;
        }
    }
    free(Y);
    free(Yp);
    rc_cset_free(c);
    return st;
}

int rc_stk_decide(const rc_model *m, rc_data *d, int i, double t, const double *y, double e[3])
{
    rc_inter_report r;
    if (rc_stk_sliding(m, d, i, t, y, &r, e)) return 1;
    /* the force that holds it, with the other sticking contacts (and the
     * other sets' multipliers where the model has more than exact stick) */
    int others = 0;
    for (int s = 0; s < NSETS; s++) others |= sets[s] != &rc_stk_set_ops && sets[s]->needed(m);
    double F[3];
    const int st = others ? hold_with_sets(m, d, i, t, y, F) : rc_stk_hold_force(m, d, i, t, y, F);
    if (st) return -1;
    const double nf = sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]);
    for (int k = 0; k < 3; k++) e[k] = nf > 0 ? F[k] / nf : 0.0;
    return nf > r.flim; /* the slip root's limit */
}
