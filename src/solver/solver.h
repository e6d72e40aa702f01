/*
 * The integration stage's backend interface. A backend integrates a
 * compiled model from t = 0 to its end time: it owns the integrator, the
 * event loop (roots, engine/events/events.c), the restarts and the output writer
 * (output/output.h), and fills rc_stats. It sees the model only through
 * model/model.h and the engine's functions (right-hand side, Jacobian
 * values on the fixed pattern, roots, energies).
 *
 * rc_run (run.c, the public entry of include/ricochet/ricochet.h) picks the
 * backend whose method is the model's /SOLVER Method and calls its run.
 * Backends: rc_solver_cvode (cvode.c, BDF + KLU, Method 1) and
 * rc_solver_ida (ida.c, the residual form on IDA, Method 2; the one that
 * runs joints). What they share is in integrator.h.
 */
#ifndef RC_SOLVER_H
#define RC_SOLVER_H

#include <stdio.h>

#include "ricochet/ricochet.h"

/* Records at events and inside contacts written per output interval, at
 * most (drive.c extra_record; docs/output-format.md) [-]. */
#define RC_EXTRA_RECORDS 200

/* /SOLVER Method numbers (docs/case-format.md). */
enum { RC_METHOD_CVODE = 1, RC_METHOD_IDA = 2, RC_METHOD_STATIC = 3 };

/* Stepping (session.c): the backend hands the state over whenever the time
 * reached is at or past `until`, before it goes on. */
typedef struct rc_pause {
    double until; /* [s] */
    /* The state at t = until (interpolated when the integrator is past it).
     * Returns non-zero to stop the run there (RC_EINTERRUPT, the file
     * marked incomplete); else `until` has been moved past t. */
    int (*reached)(struct rc_pause *p, double t, const double *y);
} rc_pause;

/* A preload (/SOLVER Preload 1; docs/theory.md 7.8 "Preload"): the static
 * equilibrium under the loads at t = 0 (static.c rc_static_preload), which
 * a dynamic run starts from. */
typedef struct rc_preload {
    double *y;       /* [ny] the equilibrium: the free bodies' positions and
                        orientations (velocities zero), the closed contacts'
                        friction states (the return mapping's forces) */
    int *closed;     /* [ninter] 1: the contact is closed in it */
    long iters;      /* KINSOL's Newton iterations */
    long solves;     /* solves of the active set */
    long flips;      /* contact mode flips of the active set */
    double wall;     /* [s] */
} rc_preload;

typedef struct rc_solver {
    const char *name; /* "cvode" */
    int method;       /* RC_METHOD_* */
    /* Same contract as rc_run: RC_OK, RC_ESOLVER (partial output kept,
     * marked incomplete), RC_EIO or RC_EINTERRUPT; `opt`, `pause`, `pre`
     * (NULL: no preload) and `stats` may be NULL, `err` may be NULL. */
    rc_status (*run)(const rc_model *m, const rc_run_options *opt, rc_pause *pause, const rc_preload *pre,
                     rc_stats *stats, rc_error *err);
} rc_solver;

/* rc_run with stepping (run.c). */
rc_status rc_run_paused(const rc_model *m, const rc_run_options *opt, rc_pause *pause, rc_stats *stats,
                        rc_error *err);
/* "SUNDIALS x.y.z\nKLU x.y.z\n" (cvode.c, the SUNDIALS user). */
void rc_cvode_versions(FILE *f);

extern const rc_solver rc_solver_cvode; /* cvode.c */
extern const rc_solver rc_solver_ida;   /* ida.c */
extern const rc_solver rc_solver_static; /* static.c: equilibrium, KINSOL (Method 3) */

/* The preload of a dynamic run (static.c): the equilibrium at the load
 * time 0 from the deck's state into pre->y and pre->closed (allocated by
 * the caller, ny and ninter long), its counts into pre. RC_EINPUT for a
 * model outside its scope (rc_preload_scope), RC_ESOLVER when no
 * equilibrium is found (the message says it is the preload's). */
rc_status rc_static_preload(const rc_model *m, rc_preload *pre, rc_error *err);

#endif
