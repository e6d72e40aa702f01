/*
 * What the integration backends share (internal to solver/): the driver
 * loop rc_drive and the table of integrator operations it runs on
 * (rc_backend), and its helpers: the output records, the events' way to
 * the results file and the caller, the time breakpoints, the root
 * directions and the progress line. All defined in drive.c; cvode.c and
 * ida.c each fill one rc_backend and call rc_drive, and neither of them
 * needs to know which integrator the other drives.
 *
 * The helpers carry the rc_bk_ prefix in their own names (the static
 * library exports no name such as write_frame), so that grep, ctags, gdb
 * and perf find them as written; the static backend (static.c) uses the
 * output helpers too.
 */
#ifndef RC_INTEGRATOR_H
#define RC_INTEGRATOR_H

#include <signal.h>

#include "engine/events/events.h"
#include "engine/events/settle.h"
#include "model/model.h"
#include "output/output.h"
#include "solver/impacts.h"
#include "solver/solver.h"
#include "engine/assembly/assembly.h"

/* Events kept per root return (more are applied but not itemised). */
#define RC_MAX_EV 64
/* Error test failures allowed in one step before the integrator gives up
 * (CVODE's default 7, IDA's 10) [-]: a step grown far past a contact's time
 * scale while nothing moved it (a box sliding steadily down an incline,
 * steps of 0.09 s against a contact period of 5e-5 s) may need more cuts
 * of that one step than that to resolve the contact again (9 there; with
 * 7, CV_ERR_FAILURE at h = 4.3e-7 s, the error 600 times its tolerance) */
#define RC_MAX_ERR_TEST_FAILS 20
/* Newton convergence failures allowed in one step (the default of both
 * integrators 10) [-]: each cuts the step 4x with a fresh Jacobian; a
 * friction state turning at K_t |v_t| / L_r = 1e13 /s (Stiff 3e13 N/m, a
 * ball sliding down a wall at zero normal force) converged after 14 in one
 * step (with 10: CV_CONV_FAILURE at h = 7.9e-11 s; with 13, later) */
#define RC_MAX_CONV_FAILS 20
/* Progress in a log (stderr not a terminal): a line every RC_LOG_EVERY s. */
#define RC_LOG_EVERY 10.0

/* Where the events go: the events table of the output file (NULL: none)
 * and the caller's callback (rc_run_options.on_event, NULL: none), which
 * may ask to stop (`stop` set, with the event in `why`). */
typedef struct ev_sink {
    rc_output *out;
    rc_event_fn fn;
    void *user;
    int stop;
    char why[300];
    struct rc_guards *guards; /* the physics checks (guards.h): the contacts' history; NULL: none */
} ev_sink;

/* Output buffers for one record. */
typedef struct frame_buf {
    double *pos, *quat, *vel, *omega, *pen, *fload, *fdamp, *fn, *point, *normal, *ffric, *vslip;
    double *flim; /* [ninter] friction limits of the closed contacts [N]: the physics checks', not written */
    double *fmu;  /* [ninter] the coefficients mu of F_n in those limits [-]: the physics checks', not written */
    int *mode, *slip;
    double energy[RC_NENERGY];
    double *cpl; /* [9 ncoupling] coupling values (rc_cpl_frame) */
    double *jnt; /* [8 njoint + 1] joints: force, moment, drifts, work (IDA path) */
    struct rc_guards *guards; /* the physics checks of every record (guards.h); NULL: none */
    int guards_due;           /* a step was taken or events applied since the last record checked */
} frame_buf;

/* Time breakpoints (ends of imposed velocities) inside (0, tend), sorted,
 * distinct; returns the count, -1 out of memory; *bp is allocated. */
int rc_bk_time_breakpoints(const rc_model *m, double tend, double **bp);
/* The root directions of the current modes (only the crossing that changes
 * a mode is a root) into dir[RC_ROOTS_PER_INTER ninter]. */
void rc_bk_root_directions(const rc_model *m, const rc_data *d, int *dir);
/* One event to the sink, under its kind's name (rc_event_kind_name); v: the
 * interface's values, NULL when none. */
rc_status rc_bk_sink_event(ev_sink *k, double t, rc_event_kind kind, const char *element, const double v[3], rc_error *err);
/* Event `ev` at (t, y) with its interface's P, dP/dt and normal force. */
rc_status rc_bk_write_event(const rc_model *m, const rc_data *d, ev_sink *o, double t, const double *y, const rc_event *ev,
                      rc_error *err);
/* Contacts at zero penetration or zero force, decided by the state (after
 * the start and every event); f is scratch [ny]; hist the run's history of
 * closes and openings (its order holds, rc_settle_lowq; its settles,
 * rc_settle_contacts, written and counted in s, on stderr when show);
 * returns the events. */
int rc_bk_resolve_touching(const rc_model *m, rc_data *d, double t, double *y, double *f, ev_sink *out, rc_impacts *im,
                     rc_settle *hist, rc_stats *s, int show, int *jumped, rc_status *st, rc_error *err);
/* 1 when a root function is exactly zero at (t, y); g is scratch. */
int rc_bk_root_on_zero(const rc_model *m, const rc_data *d, double t, const double *y, double *g);
double rc_bk_wall_now(void); /* [s], monotonic */
/* The first step [s] after a restart at t, h_last the last accepted step
 * before it (0: none); 0: let the integrator estimate it. */
double rc_bk_restart_step(const rc_model *m, double t, double h_last);
void rc_bk_frame_free(frame_buf *f);
int rc_bk_frame_alloc(const rc_model *m, frame_buf *f);
/* Fill and write one record at (t, y) (o NULL: only f->energy is filled). */
rc_status rc_bk_write_frame(const rc_model *m, const rc_data *d, rc_output *o, frame_buf *f, double t, const double *y,
                      int at_event, rc_error *err);
/* Open the results file of the run options `opt` (NULL or no
 * output_path: none; its end time and output interval overrides are the
 * file's t_end and dt_out); `integrator` describes the backend in the
 * file's solver attributes; `pre` (NULL: none) the preload the run started
 * from (attributes preload, preload_newton_iters). */
rc_status rc_bk_open_output(const rc_model *m, const rc_run_options *opt, const char *note, rc_output **o,
                            rc_error *err, const char *integrator, const rc_preload *pre);
/* The progress line on stderr. */
void rc_bk_progress_line(double tend, const rc_stats *s, double t, long steps, double t0, int tty);

/* The failure message of a backend: where (the element named elem, model
 * state istate or -1, with the Sfric hint of its interface's contact; or a
 * failed force), the integrator's flag name and last message, and advice. */
void rc_bk_failure_message(const rc_model *m, const rc_data *d, const char *name, double t, double h, double tout,
                     const char *fname, const char *msg, const char *elem, int istate, const char *advice, char *buf,
                     size_t n);

/* The integrator's error handler: nothing after an interruption (stop
 * set), an error kept in keep[n] for the failure message, a warning on
 * stderr as one "ricochet: warning:" line naming the integrator, the first
 * RC_BK_WARNINGS of a run (counted in *nwarn, the run's own counter), then
 * one line saying that the others are not shown. */
void rc_bk_keep_error(volatile sig_atomic_t *stop, char *keep, size_t n, int *nwarn, int code, const char *module,
                      const char *function, const char *msg);
/* Warnings of the integrator shown per run [-]. */
#define RC_BK_WARNINGS 3

/* Scratch vectors of a backend for its interpolant (rc_backend.dky):
 * RC_BK_TMP for output times, pauses and root refinement (a vector for
 * each derivative order k), RC_BK_SAMPLE for the impact table's samples. */
enum { RC_BK_TMP = 0, RC_BK_SAMPLE = 1 };

/* The root functions the integrator is given (rootmap.c): the live ones
 * of the engine's layout (model.h rc_roots_live), in its order. The
 * backend's root callback has the engine write the whole layout into
 * rc_rootmap_full(rm, g) and then calls rc_rootmap_gather(rm, g); the
 * directions go through rc_rootmap_dirs, and the integrator's roots found,
 * read into rc_rootmap_info(rm, roots), come back to the full indices
 * with rc_rootmap_found. With every root live (or compaction off) all of
 * these pass the engine's vectors through. */
typedef struct rc_rootmap {
    int nfull, n; /* the engine's root functions, the integrator's */
    int *live;    /* [n] the integrator's roots' full indices (NULL: all, n = nfull) */
    double *g;    /* [nfull] scratch: the engine's root values */
    int *iv;      /* [nfull] scratch: the integrator's directions or roots found */
    /* the interfaces' zone root values of the last evaluation, and its
     * time, for the physics checks (guards.h) */
    int ninter;
    double *zone; /* [ninter] */
    double tzone; /* [s] */
    int zone_ok;  /* 1: zone holds an evaluation */
} rc_rootmap;
/* 0, or -1 out of memory (rc_rootmap_free it anyway). */
int rc_rootmap_init(rc_rootmap *rm, const rc_model *m, const rc_run_options *opt);
void rc_rootmap_free(rc_rootmap *rm);
static inline double *rc_rootmap_full(const rc_rootmap *rm, double *g) { return rm->live ? rm->g : g; }
void rc_rootmap_gather(const rc_rootmap *rm, double *g);
/* Keep the zone values of the engine's whole layout gfull, evaluated at
 * t (each root callback, after the engine wrote them). */
void rc_rootmap_keep(rc_rootmap *rm, double t, const double *gfull);
/* The zone values kept when they were evaluated at exactly t, else NULL. */
const double *rc_rootmap_at(const rc_rootmap *rm, double t);
/* The directions dir[nfull] as the integrator's [n] (valid until the next call). */
const int *rc_rootmap_dirs(const rc_rootmap *rm, const int *dir);
static inline int *rc_rootmap_info(const rc_rootmap *rm, int *roots) { return rm->live ? rm->iv : roots; }
/* The integrator's roots found (in rc_rootmap_info) into roots[nfull]. */
void rc_rootmap_found(const rc_rootmap *rm, int *roots);
/* Tests only: 0 gives the integrator every root function (default 1). */
void rc_rootmap_set_compact(int on);
/* Tests only: 0 gives CVODE every state, the constant ones included
 * (cvode.c; default 1: rc_constant_states left out). */
void rc_cvode_set_reduce(int on);

/* An integrator behind rc_drive. Flags are the integrator's own return
 * values (negative: a failure, named by flag_name); `self` is the
 * backend's state, passed back to every operation. */
typedef struct rc_backend {
    const char *name;   /* "CVODE", "IDA": in messages */
    const char *prefix; /* "CVode", "IDA": prefix of the calls' names in messages */
    int root_return, tstop_return, too_much_work; /* the solve flags */
    /* Allocate the integrator's vectors and matrix for the model (d: the
     * run's data, kept for the callbacks); *y is the state vector the driver
     * fills with the initial state, *yp its derivative (NULL: none, the ODE
     * form), *n their length (>= m->ny: IDA's joints add states), and
     * *integrator the description for the results file. */
    rc_status (*open)(void *self, const rc_model *m, rc_data *d, const rc_run_options *opt, double **y,
                      double **yp, int *n, const char **integrator, rc_error *err);
    /* Create and set up the integrator at t = 0 from the initial state and
     * modes (may adjust y: joints project the velocities); the root
     * directions and the stop time are set by the driver afterwards. */
    rc_status (*start)(void *self, rc_error *err);
    /* Integrate towards tout (one internal step when *one_step is set, or
     * when the backend wants one: *one_step then says so); *t the time
     * reached, y (and yp) the state there. */
    int (*solve)(void *self, double tout, double *t, int *one_step);
    /* The k-th derivative of the last step's interpolant at t, into the
     * scratch vector `slot` (RC_BK_TMP, RC_BK_SAMPLE): *out. */
    int (*dky)(void *self, double t, int k, int slot, const double **out);
    int (*last_step)(void *self, double *tn, double *hu); /* end and size of the last step */
    int (*root_info)(void *self, int *roots);              /* the roots found [rc_root_count] */
    int (*set_root_dirs)(void *self, int *dir);
    int (*set_stop_time)(void *self, double tstop);
    /* Restart at (t, y) (an event or, at_breakpoint, a time breakpoint):
     * a consistent y' where the backend has one. */
    int (*restart)(void *self, double t, int at_breakpoint);
    void (*add_stats)(void *self, rc_stats *s); /* counters since the last restart (and the end) into s */
    long (*steps)(void *self);                   /* steps since the last restart, for the progress line */
    void (*failure)(void *self, int flag, double t, double tout, char *buf, size_t n); /* the failure message */
    char *(*flag_name)(long flag);               /* malloc'ed */
    const char *(*last_msg)(void *self);         /* the integrator's last error message */
    /* The vector a record is written from (NULL: y itself). */
    const double *(*record_vector)(void *self, double t, const double *y, const double *yp);
    /* Around the events of a root return: before_events (NULL: none) just
     * before the modes flip; after_events when some changed, with
     * cpl_ev set when a contact coupling's did and `restart` when the
     * driver restarts anyway: returns whether to restart; continued (NULL:
     * none) when modes changed and no restart follows. */
    void (*before_events)(void *self);
    int (*after_events)(void *self, double t, const double *y, int cpl_ev, int restart);
    void (*continued)(void *self);
    /* The interfaces' zone root values the integrator evaluated at exactly
     * t (rc_rootmap_at), NULL when its last evaluation was elsewhere (NULL
     * operation: never). */
    const double *(*roots_at)(void *self, double t);
    /* A change of integration method since the last call (method
     * switching: RC_EV_METHOD_EXPLICIT or RC_EV_METHOD_IMPLICIT, at *t),
     * reported once; RC_EV_NONE when none (NULL operation: never). The
     * driver writes it as an event and counts it. */
    rc_event_kind (*switched)(void *self, double *t);
    void (*close)(void *self); /* free everything open and start made */
} rc_backend;

/* Run the model on the backend bk (solver.h rc_solver.run). */
rc_status rc_drive(const rc_model *m, const rc_run_options *opt, rc_pause *pause, const rc_preload *pre,
                   rc_stats *stats, rc_error *err, const rc_backend *bk, void *self);

#endif
