/*
 * Forward sensitivities (sens.c) on the CVODE backend (cvode.c): what the
 * sensitivity backend needs of cvode.c's run context. CVODES is a superset
 * of CVODE (the same calls on the same integrator memory); the library
 * links CVODES only, so cvode.c's integrator accepts CVodeSensInit.
 */
#ifndef RC_SOLVER_SENS_H
#define RC_SOLVER_SENS_H

#include <stddef.h>

#include "solver/integrator.h"

/* cvode.c's operations, and the size of its run context (the `self` they
 * take, zeroed before open). */
const rc_backend *rc_cvode_backend(void);
size_t rc_cvode_self_size(void);
/* Of a started run context: the integrator memory (NULL before start), the
 * count nr of the states CVODE carries, their indices kidx[nr] in the
 * whole state, the driver's whole state (its constant states keep their
 * values) and the SUNContext. */
void *rc_cvode_parts(void *self, int *nr, const int **kidx, double **yfull, void **sunctx);

#endif
