/*
 * KLU's symbolic analysis kept across restarts. An integrator restart
 * (CVodeReInit, IDAReInit) re-initialises the linear solver, and SUNDIALS'
 * KLU module then analyses the matrix pattern again at the next setup
 * (ordering, block triangular form) before factorising it. The Newton
 * matrix of a backend with a fixed pattern has the same pattern at every
 * restart (the CVODE backend's: written once, cvode.c), and the analysis
 * depends on the pattern alone, so its result would be the same: the
 * setup below skips it and factorises with the analysis kept (klu_factor,
 * as SUNDIALS' first setup does: the same numbers bit for bit). Every
 * other setup is SUNDIALS' own.
 */
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include "solver/klukeep.h"

static int setup_keep(SUNLinearSolver S, SUNMatrix A)
{
    SUNLinearSolverContent_KLU k = (SUNLinearSolverContent_KLU)S->content;
    if (!k->first_factorize || !k->symbolic) return SUNLinSolSetup_KLU(S, A);
    if (k->numeric) sun_klu_free_numeric(&k->numeric, &k->common);
    k->numeric = sun_klu_factor(SUNSparseMatrix_IndexPointers(A), SUNSparseMatrix_IndexValues(A),
                                SUNSparseMatrix_Data(A), k->symbolic, &k->common);
    if (!k->numeric) return k->last_flag = SUNLS_PACKAGE_FAIL_REC;
    k->first_factorize = 0;
    return k->last_flag = SUNLS_SUCCESS;
}

static int keep_on = 1;

void rc_klu_keep_set(int on) { keep_on = on; }

void rc_klu_keep_symbolic(SUNLinearSolver S)
{
    if (keep_on && S && S->ops) S->ops->setup = setup_keep;
}
