/*
 * The Newton matrix on the active part of the model's Jacobian pattern
 * (docs/theory.md 7, "The Newton matrix follows the contacts"), shared by
 * the CVODE and IDA backends: the engine says which slots can be nonzero
 * in the present modes (model.h rc_jac_active); the part (subpat.h) holds
 * them, and KLU analyses its pattern again only when the part changes.
 *
 * Policy: at every new Jacobian the active slots are compared with the
 * part. A slot that became inactive stays in the part (a zero entry costs
 * little); an active slot outside the part rebuilds it, as every slot
 * active at some new Jacobian since the previous rebuild (the margin:
 * contacts that opened since then are likely to close again, a bouncing
 * contact does not rebuild at each bounce). KLU's own re-analysis at every
 * integrator restart (SUNLinSolInitialize) is replaced by one that keeps
 * the analysis while the pattern is the same; a refactorisation that fails
 * on the kept pivot order is followed by a new analysis (SUNLinSolSetup).
 */
#ifndef RC_ACTIVEPART_H
#define RC_ACTIVEPART_H

#include <stdint.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include "model/model.h"
#include "engine/constraints/cset.h"
#include "solver/subpat.h"

typedef struct rc_actpart {
    int on;              /* 0: the whole pattern (SUNDIALS's re-analysis at every restart) */
    int built;           /* the part exists */
    int changed;         /* rebuilt since A's pattern was last written */
    /* the matrix's whole pattern: the model's, or IDA's extended one with
     * constraint sets (cs) */
    int n;
    int64_t nnz;
    const int64_t *cp, *ri;
    const rc_cset *cs;   /* IDA's constraint sets: their extended pattern is the matrix's */
    const int *idx;      /* [n] the states' indices in the integrator's vector, -1: left out
                            (rc_actpart_set_states); NULL: every state */
    unsigned char *inpart; /* [nnz] with idx: the slot's row and column are kept */
    rc_subpat sp;        /* the part */
    unsigned char *need; /* [m->nnz] the model's active slots at the last new Jacobian */
    unsigned char *xneed; /* [nnz] the matrix's (need itself without cs) */
    unsigned char *seen; /* [nnz] active at some new Jacobian since the last rebuild */
    double *xval;        /* [nnz] with cs: the extended matrix's values before the gather */
    int64_t *src;        /* [sp.nnz] the whole pattern's slot of each of the part's entries */
    int64_t src_cap;     /* entries allocated in src */
    long nsym;           /* KLU symbolic analyses at the setups after a load (rc_actpart_analyses: all) */
    long retry0;         /* the thread's count of analyses after failed refactorisations at open */
    long nbuild;         /* builds of the part */
    int64_t nnz_max;     /* largest part (the whole pattern when off) */
    /* rc_jac_active_key of the last follow (akey_ok) and scratch: the same
     * key gives the same active slots, so the follow has nothing to do */
    unsigned char *akey, *akey_new; /* [ninter + 1] each */
    int akey_ok;
} rc_actpart;

/* Set up for model m and KLU solver LS (with on: LS's initialisation keeps
 * the analysis of an unchanged pattern); cs: IDA's constraint sets, whose
 * extended pattern is the matrix's (NULL: the model's pattern; with on,
 * they give their active slots: rc_cset_keeps). 0, or -1 out of memory. */
int rc_actpart_open(rc_actpart *ap, const rc_model *m, SUNLinearSolver LS, int on, const rc_cset *cs);
void rc_actpart_close(rc_actpart *ap);
/* The integrator carries only the states idx[i] >= 0 (increasing; the
 * model's pattern only, no extended one): the part is on their rows and
 * columns; with the active part off, that is the part, built here. NULL:
 * every state. 0, -1 out of memory, -2 a kept state without its diagonal. */
int rc_actpart_set_states(rc_actpart *ap, const int *idx);
/* A new Jacobian jsave [nnz] at (t, y) in the modes of d: the part follows
 * the active slots (rebuilt when one is outside it). 0, or -1 out of memory. */
int rc_actpart_follow(rc_actpart *ap, const rc_model *m, const rc_data *d, double t, const double *y,
                      const double *jsave);
/* The Newton matrix into A: a val + c I on the part (on the whole pattern
 * when off), val the values of the matrix's whole pattern (jsave, or with
 * cs ap->xval); A's pattern written when the part changed or `pattern` is
 * set (IDA zeroes A before its Jacobian callback), KLU told to analyse a
 * changed pattern. 0, or -1 (KLU re-initialisation failed). */
int rc_actpart_load(rc_actpart *ap, const rc_model *m, SUNMatrix A, SUNLinearSolver LS, double a,
                    const double *jsave, double c, int pattern);

/* KLU symbolic analyses so far (after failed refactorisations included). */
long rc_actpart_analyses(const rc_actpart *ap);

/* Tests only: run the part (1, default) or the whole pattern (0); a probe
 * called at every new Jacobian with the state, the modes and its values
 * (NULL: none). */
void rc_actpart_set_enabled(int on);
int rc_actpart_enabled(void);
typedef void (*rc_actpart_probe)(void *ctx, const rc_model *m, const rc_data *d, double t, const double *y,
                                 const double *jsave);
void rc_actpart_set_probe(rc_actpart_probe fn, void *ctx);
/* With a probe set, IDA's extended matrix (exact stick, settled contacts)
 * is checked too: its nonzeros outside the active slots since the last
 * call. */
long rc_actpart_probe_outside(void);

#endif
