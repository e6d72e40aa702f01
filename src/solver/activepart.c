/*
 * The Newton matrix on the active part of the Jacobian pattern
 * (activepart.h).
 */
#include <stdlib.h>
#include <string.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include "solver/activepart.h"
#include "engine/analyses/analyses.h"
#include "engine/constraints/joints.h"
#include "engine/constraints/stick.h"

static int g_enabled = 1;
static rc_actpart_probe g_probe;
static void *g_probe_ctx;
static long g_xoutside; /* with a probe: nonzeros of the extended matrix outside its active slots */

void rc_actpart_set_enabled(int on) { g_enabled = on != 0; }
int rc_actpart_enabled(void) { return g_enabled; }
long rc_actpart_probe_outside(void)
{
    const long n = g_xoutside;
    g_xoutside = 0;
    return n;
}

void rc_actpart_set_probe(rc_actpart_probe fn, void *ctx)
{
    g_probe = fn;
    g_probe_ctx = ctx;
}

/* KLU's initialisation (called by the integrator at every (re)start) without
 * forcing a new symbolic analysis: the pattern is the part's, analysed
 * again when it changes (SUNLinSol_KLUReInit in rc_actpart_load). The
 * refactorisation on the kept analysis checks its conditioning and
 * factorises anew with pivoting when it is poor (SUNLinSolSetup_KLU). */
static int klu_init_keep(SUNLinearSolver S)
{
    ((SUNLinearSolverContent_KLU)S->content)->last_flag = 0;
    return 0;
}

/* Analyses after a failed refactorisation, in the integrating thread (read
 * into rc_actpart.nsym by rc_actpart_count). */
static _Thread_local long g_retry;

/* KLU's setup; when the refactorisation on the kept analysis fails (a pivot
 * of the old order is zero now: a constraint or contact that stopped
 * acting left only its diagonal), the pattern is analysed and factorised
 * anew with pivoting, once. */
static int klu_setup_retry(SUNLinearSolver S, SUNMatrix A)
{
    SUNLinearSolverContent_KLU k = S->content;
    const int fresh = k->first_factorize;
    int flag = SUNLinSolSetup_KLU(S, A);
    if (flag != 0 && !fresh) {
        k->first_factorize = 1;
        g_retry++;
        flag = SUNLinSolSetup_KLU(S, A);
    }
    return flag;
}

int rc_actpart_open(rc_actpart *ap, const rc_model *m, SUNLinearSolver LS, int on, const rc_cset *cs)
{
    memset(ap, 0, sizeof *ap);
    ap->on = on && g_enabled;
    ap->cs = cs;
    ap->n = m->ny;
    ap->nnz = m->nnz;
    ap->cp = m->jac_colptr;
    ap->ri = m->jac_rowind;
    if (cs) {
        ap->n = m->ny + rc_cset_nextra(cs);
        ap->nnz = rc_cset_nnz(cs);
        rc_cset_pattern(cs, &ap->cp, &ap->ri);
    }
    const int ext = cs != NULL;
    ap->nnz_max = ap->nnz;
    if (!ap->on) return 0;
    ap->nnz_max = 0;
    ap->need = malloc((size_t)m->nnz + 1);
    ap->seen = calloc((size_t)ap->nnz + 1, 1);
    ap->xneed = ext ? malloc((size_t)ap->nnz + 1) : ap->need;
    ap->xval = ext ? malloc(((size_t)ap->nnz + 1) * sizeof(double)) : NULL;
    ap->akey = malloc(2 * ((size_t)m->ninter + 1));
    ap->akey_new = ap->akey ? ap->akey + m->ninter + 1 : NULL;
    if (!ap->need || !ap->seen || !ap->xneed || (ext && !ap->xval) || !ap->akey) return -1;
    /* the parts rebuilt in the linear-system callback allocate nothing:
     * room for the whole pattern, the largest part, now */
    if (rc_subpat_reserve(&ap->sp, ap->n, ap->nnz)) return -1;
    if (!(ap->src = malloc(((size_t)ap->nnz + 1) * sizeof *ap->src))) return -1;
    ap->src_cap = ap->nnz;
    LS->ops->initialize = klu_init_keep;
    LS->ops->setup = klu_setup_retry;
    ap->retry0 = g_retry;
    return 0;
}

void rc_actpart_close(rc_actpart *ap)
{
    rc_subpat_free(&ap->sp);
    if (ap->xneed != ap->need) free(ap->xneed);
    free(ap->need);
    free(ap->seen);
    free(ap->xval);
    free(ap->src);
    free(ap->inpart);
    free(ap->akey);
    ap->akey = ap->akey_new = NULL;
    ap->akey_ok = 0;
    ap->inpart = NULL;
    ap->need = ap->seen = ap->xneed = NULL;
    ap->xval = NULL;
    ap->src = NULL;
}

static int rebuild(rc_actpart *ap, const unsigned char *keep)
{
    const int st = rc_subpat_build(&ap->sp, ap->n, ap->cp, ap->ri, ap->idx, keep);
    if (st) return st;
    /* the gather runs over the part's entries, not the whole pattern's */
    if (!ap->src || ap->sp.nnz > ap->src_cap) { /* reserved at open when on: never */
        int64_t *q = realloc(ap->src, ((size_t)ap->sp.nnz + 1) * sizeof *q);
        if (!q) return -1;
        ap->src = q;
        ap->src_cap = ap->sp.nnz;
    }
    int64_t *src = ap->src;
    for (int64_t k = 0; k < ap->nnz; k++)
        if (ap->sp.map[k] >= 0) src[ap->sp.map[k]] = k;
    ap->built = ap->changed = 1;
    ap->nbuild++;
    if (ap->sp.nnz > ap->nnz_max) ap->nnz_max = ap->sp.nnz;
    return 0;
}

int rc_actpart_set_states(rc_actpart *ap, const int *idx)
{
    ap->idx = idx;
    if (!idx) return 0;
    /* the kept states' part, whole: the slots a part can hold */
    ap->nnz_max = 0;
    const int st = rebuild(ap, NULL);
    if (st) return st;
    if (!(ap->inpart = malloc((size_t)ap->nnz + 1))) return -1;
    for (int64_t k = 0; k < ap->nnz; k++) ap->inpart[k] = ap->sp.map[k] >= 0;
    /* on: the first new Jacobian builds the active part */
    if (ap->on) ap->built = 0;
    return 0;
}

int rc_actpart_follow(rc_actpart *ap, const rc_model *m, const rc_data *d, double t, const double *y,
                      const double *jsave)
{
    if (g_probe) g_probe(g_probe_ctx, m, d, t, y, jsave);
    if (!ap->on) return 0;
    /* the interfaces on and off as at the last follow (nothing else
     * decides): the same active slots, already in the part and in seen */
    const int keyed = !g_probe && !ap->cs && ap->akey && rc_jac_active_key(m, d, ap->akey_new);
    if (keyed && ap->built && ap->akey_ok && memcmp(ap->akey, ap->akey_new, (size_t)m->ninter) == 0) return 0;
    ap->akey_ok = 0;
    rc_jac_active(m, d, t, y, ap->need);
    if (ap->cs) rc_cset_keep(m, d, ap->cs, ap->need, ap->xneed);
    const int64_t nz = ap->nnz, *map = ap->sp.map;
    if (ap->inpart) /* slots of states the integrator does not carry */
        for (int64_t k = 0; k < nz; k++) ap->xneed[k] &= ap->inpart[k];
    const unsigned char *need = ap->xneed;
    if (g_probe && ap->xval)
        for (int64_t k = 0; k < nz; k++) g_xoutside += ap->xval[k] != 0.0 && !need[k];
    int st = 0;
    if (!ap->built) {
        memcpy(ap->seen, need, (size_t)nz);
        st = rebuild(ap, need);
    } else {
        int out = 0;
        for (int64_t k = 0; k < nz; k++) {
            out |= need[k] && map[k] < 0;
            ap->seen[k] |= need[k];
        }
        if (out) {
            /* the part: every slot active since the last rebuild; then count anew */
            st = rebuild(ap, ap->seen);
            memcpy(ap->seen, need, (size_t)nz);
        }
    }
    if (keyed && !st) {
        memcpy(ap->akey, ap->akey_new, (size_t)m->ninter);
        ap->akey_ok = 1;
    }
    return st;
}

long rc_actpart_analyses(const rc_actpart *ap) { return ap->nsym + (ap->on ? g_retry - ap->retry0 : 0); }

int rc_actpart_load(rc_actpart *ap, const rc_model *m, SUNMatrix A, SUNLinearSolver LS, double a,
                    const double *val, double c, int pattern)
{
    sunindextype *cp = SUNSparseMatrix_IndexPointers(A), *ri = SUNSparseMatrix_IndexValues(A);
    double *v = SUNSparseMatrix_Data(A);
    const int n = ap->n;
    if (!ap->built) { /* off: the model's pattern (IDA's extended ones do not come here when off) */
        if (pattern) {
            for (int k = 0; k <= n; k++) cp[k] = (sunindextype)m->jac_colptr[k];
            for (int64_t k = 0; k < m->nnz; k++) ri[k] = (sunindextype)m->jac_rowind[k];
        }
        for (int64_t k = 0; k < m->nnz; k++) v[k] = a * val[k];
        for (int r = 0; r < n; r++) v[m->jac_diag[r]] += c;
    } else {
        const rc_subpat *sp = &ap->sp;
        if (pattern || ap->changed) {
            /* A was made with the whole pattern's capacity: the part fits */
            for (int k = 0; k <= sp->n; k++) cp[k] = (sunindextype)sp->colptr[k];
            for (int64_t k = 0; k < sp->nnz; k++) ri[k] = (sunindextype)sp->rowind[k];
        }
        if (ap->changed) {
            if (SUNLinSol_KLUReInit(LS, A, SUNSparseMatrix_NNZ(A), SUNKLU_REINIT_PARTIAL) != 0) return -1;
            ap->changed = 0;
        }
        const int64_t *src = ap->src; /* rc_subpat_gather over the part's entries */
        for (int64_t p = 0; p < sp->nnz; p++) v[p] = a * val[src[p]];
        for (int r = 0; r < sp->n; r++) v[sp->diag[r]] += c;
    }
    /* the setup that follows analyses the pattern when KLU has none */
    if (((SUNLinearSolverContent_KLU)LS->content)->first_factorize) ap->nsym++;
    return 0;
}
