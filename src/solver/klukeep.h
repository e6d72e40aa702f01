/*
 * KLU's symbolic analysis kept across the integrator's restarts (klukeep.c).
 */
#ifndef RC_KLUKEEP_H
#define RC_KLUKEEP_H

#include <sundials/sundials_linearsolver.h>

/* Make the KLU linear solver S keep its symbolic analysis when the
 * integrator re-initialises it (every CVodeReInit / IDAReInit): only for a
 * matrix whose pattern never changes after the first setup. */
void rc_klu_keep_symbolic(SUNLinearSolver S);
/* Tests only: 0 leaves SUNDIALS' setup in place (a new analysis at every
 * restart; default 1). */
void rc_klu_keep_set(int on);

#endif
