/*
 * The integration stage's backend interface. A backend integrates a
 * compiled model from t = 0 to its end time: it owns the integrator, the
 * event loop (roots, engine/events.c), the restarts and the output writer
 * (output/output.h), and fills rc_stats. It sees the model only through
 * model/model.h and the engine's functions (right-hand side, Jacobian
 * values on the fixed pattern, roots, energies).
 *
 * rc_run (run.c, the public entry of include/ricochet/ricochet.h) picks the
 * backend whose method is the model's /SOLVER Method and calls its run.
 * Backends: rc_solver_cvode (cvode.c, BDF + KLU). A coming IDA backend
 * (Method 2, which the case reader still rejects as "not supported yet")
 * adds ida.c defining rc_solver_ida and one line to the table of run.c.
 */
#ifndef RC_SOLVER_H
#define RC_SOLVER_H

#include "ricochet/ricochet.h"

/* /SOLVER Method numbers (docs/case-format.md). */
enum { RC_METHOD_CVODE = 1, RC_METHOD_IDA = 2 };

typedef struct rc_solver {
    const char *name; /* "cvode" */
    int method;       /* RC_METHOD_* */
    /* Same contract as rc_run: RC_OK, RC_ESOLVER (partial output kept,
     * marked incomplete) or RC_EIO; `opt` and `stats` may be NULL, `err`
     * may be NULL. */
    rc_status (*run)(const rc_model *m, const rc_run_options *opt, rc_stats *stats,
                     rc_error *err);
} rc_solver;

extern const rc_solver rc_solver_cvode; /* cvode.c */

#endif
