/*
 * ricochet: stiff rigid-body contact, integrated implicitly with error control.
 *
 * Public API. This header includes only the C library: no SUNDIALS, GSL or
 * netCDF type appears here. Units are SI: a case whose /BEGIN or /UNIT
 * cards name other units is converted to SI when read; a case naming no
 * units is used as written (one consistent system).
 *
 * Pipeline:  rc_case_load  ->  rc_model_compile  ->  rc_run
 *            (or rc_session_open, rc_run_until ..., rc_session_close)
 *
 * Pointer arguments: every function checks them. Each declaration says
 * which may be NULL and what NULL does; a NULL where none is allowed is
 * refused with RC_EINPUT (nothing done) by the functions that return a
 * status, and gives the stated value (0, NaN, NULL, a no-op) elsewhere.
 * `err` may be NULL everywhere: the status is returned, the message lost.
 *
 * Threads: separate cases, models and sessions may be used from separate
 * threads at once (each run writing its own results file: the library
 * serialises its netCDF calls, as HDF5 under netCDF is not thread-safe).
 * One object is used from one thread at a time; a compiled model may be
 * run by several threads at once (rc_run and sessions only read it), but
 * not changed (rc_model_set_rtol, rc_model_set_method, rc_model_set_preload,
 * rc_model_free)
 * while a run or session uses it.
 *
 * Link with `pkg-config --cflags --libs ricochet` (docs/embedding.md).
 */
#ifndef RICOCHET_H
#define RICOCHET_H

#include <signal.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

#define RICOCHET_VERSION "0.2.0"

/* Status codes. The values of RC_EINPUT, RC_ESOLVER and RC_EIO are the
 * program's exit codes. */
typedef enum {
    RC_OK = 0,
    RC_EINPUT = 2,    /* the input is wrong: the case file, an option or
                         an argument of the call (a NULL pointer, a call
                         from a callback that would deadlock); nothing was
                         run or written                                  */
    RC_ESOLVER = 3,   /* the integrator failed; partial results are kept */
    RC_EIO = 4,       /* a file could not be read or written; for the
                         results file the message says what it keeps    */
    RC_ENOMEM = 5,    /* out of memory                                   */
    RC_EINTERNAL = 6, /* a bug in ricochet                               */
    RC_EINTERRUPT = 7, /* stopped by the caller (a signal, the event
                         callback, rc_session_close); partial results
                         are kept, marked incomplete                     */
    RC_EPHYSICS = 8   /* a physics check of the run failed (energy
                         created, a dissipation decreasing, bodies passing
                         through each other, non-finite values): the run
                         stopped there, results kept; exit code 5        */
} rc_status;

/* An error report. `msg` is complete and printable on its own: for input
 * errors it reads "file:line: card /X/Y/id, field F: expected ..., got ...". */
typedef struct rc_error {
    rc_status code;
    char msg[8192]; /* several lines when a deck has several input errors */
    const char *src_file; /* ricochet source location that raised it */
    int src_line;
    const char *src_func;
} rc_error;

/* Static message of a status code (never NULL; "unknown status" for a
 * value outside the enum). */
const char *rc_status_str(rc_status code);
/* Process exit code for a status: 0, 2, 3, 4; 5 when a physics check
 * failed; 130 when interrupted (the shell's 128 + SIGINT); 1 for other
 * failures. */
int rc_status_exit_code(rc_status code);
/* The one name of cand[0..n) (NULL entries skipped) within a typo of word:
 * an edit distance (insertions, deletions, substitutions, compared as
 * written) of at most 1 for words up to 4 characters, else 2; NULL when
 * none is, or when two different names are as close (the "did you mean" of
 * the messages). */
const char *rc_closest_name(const char *word, const char *const *cand, int n);
/* Version string, e.g. "0.1.0". */
const char *rc_version(void);
/* The git commit ricochet was built from ("unknown" outside a git checkout)
 * and the versions of the libraries it uses, one "name version" per line
 * (SUNDIALS, KLU, GSL, netCDF), as printed by `ricochet --version`. A NULL
 * `f` prints nothing. */
const char *rc_build_commit(void);
void rc_print_versions(FILE *f);

/* The library's process-wide lock around its netCDF calls (HDF5 under
 * netCDF is not thread-safe; see "Threads" above). A program that calls
 * netCDF or HDF5 itself in one thread while runs of other threads write
 * their results files (reading a results file during another thread's
 * run, as the Python module does) holds it around its own calls. It is not
 * recursive; the library never holds it while it calls the event
 * callback. */
void rc_netcdf_lock(void);
void rc_netcdf_unlock(void);

/* Progress of the long stages (reading, compiling) on `f`; NULL (the
 * default) says nothing. Printed only for stages that run over a second.
 * One setting for the process: set it before starting threads. */
void rc_set_progress(FILE *f);

/* ---- Case (parsed deck) --------------------------------------------- */
typedef struct rc_case rc_case;

/* Read a case file (Radioss block format, see docs/case-format.md).
 * `path` and `out` must not be NULL. The case file and every file it
 * includes must be regular files: a named pipe, device, socket or directory
 * is refused (RC_EINPUT naming the path, and the file:line of the #include)
 * without waiting on it. On failure returns RC_EINPUT (the deck, or a file
 * that is not a regular file) or RC_EIO (the case file cannot be opened or
 * read), fills *err, sets *out to NULL. */
rc_status rc_case_load(const char *path, rc_case **out, rc_error *err);
/* rc_case_load with fields set by name, as `ricochet run --set`: each of
 * the `nset` strings of `set` is "/KEYWORD/.../ID:FIELD=VALUE" (or
 * FIELD[k]=VALUE for the k-th occurrence of a field the card repeats),
 * e.g. "/INTER/TYPE6/1:Fric=0.3". The VALUE replaces the text of that
 * numeric field of that card as the card is read, and is then read as deck
 * input: same parser, defaults, range checks and conversion from the
 * card's units to SI (docs/case-format.md, "Setting fields from the
 * command line"). Card keywords and field names are matched ignoring case.
 * RC_EINPUT, nothing loaded, with a message starting "--set ARG: " for a
 * malformed string, a card not in the deck (or matched by two cards), a
 * field the card does not have or does not read as a number, a field set
 * twice, and a value the field refuses. `set` may be NULL when nset is 0
 * (then it is rc_case_load); nset < 0 or a NULL string is RC_EINPUT. The
 * strings are read during the call only; the case keeps the list for the
 * results file (global attribute `overrides`). */
rc_status rc_case_load_set(const char *path, const char *const *set, int nset, rc_case **out, rc_error *err);
void rc_case_free(rc_case *c); /* NULL is a no-op */
/* The files the case was read from: 0 is the case file, then every file it
 * includes, in reading order. NULL when i is out of range or c is NULL
 * (whose count is 0). */
int rc_case_file_count(const rc_case *c);
const char *rc_case_file(const rc_case *c, int i);
/* Warnings of the reading ("file:line: ..."): ignored cards, leniencies,
 * unit conversions; i in [0, rc_case_warning_count(c)). A NULL c has no
 * warnings (count 0, rc_case_warning NULL). */
int rc_case_warning_count(const rc_case *c);
const char *rc_case_warning(const rc_case *c, int i);

/* ---- Model (compiled, constant) ------------------------------------- */
typedef struct rc_model rc_model;

/* Resolve references, check physics, build the state layout and the
 * Jacobian pattern. Returns RC_EINPUT with file:line in *err on bad input;
 * among the checks, values whose products overflow (a body's weight,
 * kinetic, rotational or potential energy beyond 1e300, docs/case-format.md)
 * are refused naming the field. `c` and `out` must not be NULL (RC_EINPUT);
 * *out is NULL on failure. The case may be freed once compiled. */
rc_status rc_model_compile(const rc_case *c, rc_model **out, rc_error *err);
void rc_model_free(rc_model *m); /* NULL is a no-op */
/* Notices of the compiling ("file:line: ..."): what the deck's options
 * changed in the model that its reader should know, e.g. the secondary
 * nodes or main segments that /INTER/TYPE7 Inacti 1, 2 left out; i in
 * [0, rc_model_note_count(m)). A NULL m has none (count 0, NULL). */
int rc_model_note_count(const rc_model *m);
const char *rc_model_note(const rc_model *m, int i);
/* Human-readable summary (bodies, surfaces, interfaces, state size, solver
 * settings) as printed by `ricochet check`. A NULL m or f prints nothing. */
void rc_model_print_summary(const rc_model *m, FILE *f);
/* Replace the relative tolerance (/SOLVER Rtol) of a compiled model and
 * re-derive the absolute tolerances that scale with it (those left blank
 * on /SOLVER; docs/theory.md 7.1). rtol must be finite, in (0, 1):
 * RC_EINPUT otherwise, the model unchanged. RC_EINPUT for a NULL m. Not
 * while a run or session uses the model. */
rc_status rc_model_set_rtol(rc_model *m, double rtol, rc_error *err);
/* Replace the integration backend (/SOLVER Method) of a compiled model:
 * 1 CVODE (BDF on y' = f), 2 IDA (BDF on the residual form; the one that
 * runs joints), 3 static analysis (equilibrium at each output time, KINSOL;
 * docs/case-format.md /SOLVER). RC_EINPUT for another number, or 1 for a
 * model with joints, or 3 for a model outside the static analysis' scope
 * (the message names the card), or a NULL m; the model unchanged then. Not while a run or session uses
 * the model. */
rc_status rc_model_set_method(rc_model *m, int method, rc_error *err);
/* Replace the preload (/SOLVER Preload) of a compiled model: 1 starts a
 * dynamic run (Method 1 or 2) from the static equilibrium under the loads
 * at t = 0 (positions, orientations and the friction forces of the closed
 * contacts; every body at rest), 0 from the deck's positions; with Method 3
 * it changes nothing (docs/case-format.md /SOLVER, docs/theory.md 7.8
 * "Preload"). RC_EINPUT for another number, for 1 on a model outside the
 * static analysis' scope or with a body given an initial velocity (the
 * message names the card), or a NULL m; the model unchanged then. Not
 * while a run or session uses the model. */
rc_status rc_model_set_preload(rc_model *m, int on, rc_error *err);
/* The model's preload: 1 on, 0 off (and for a NULL m). */
int rc_model_preload(const rc_model *m);
/* Replace the method switching (/SOLVER Switch) of a compiled model: 1 lets
 * the CVODE path (Method 1) switch from BDF to an explicit error-controlled
 * Runge-Kutta method (ARKODE ERKStep) while impacts pin BDF's step near
 * the explicit stability limit, and back when the contacts rest
 * (docs/theory.md 7.9); 0 BDF throughout. Other methods ignore it.
 * RC_EINPUT for another number or a NULL m; the model unchanged then. Not
 * while a run or session uses the model. */
rc_status rc_model_set_switch(rc_model *m, int on, rc_error *err);
/* The model's method switching: 1 on, 0 off (and for a NULL m). */
int rc_model_switch(const rc_model *m);
/* The relative tolerance, end time and output interval of a model [-, s, s];
 * NaN for a NULL m. */
double rc_model_rtol(const rc_model *m);
double rc_model_t_end(const rc_model *m);
double rc_model_dt_out(const rc_model *m);

/* The bodies of a model: their count (fixed bodies included; 0 for a NULL
 * m) and the /RBODY id of the i-th, i in [0, count) (-1 out of range or for
 * a NULL m), in the order of the results file's `body` dimension. */
int rc_model_body_count(const rc_model *m);
int rc_model_body_id(const rc_model *m, int i);
/* Where the 13 states of /RBODY body_id start in the state vector (layout
 * in docs/theory.md 1: position [m], quaternion (w, x, y, z) [-], velocity
 * [m/s], angular velocity in the body frame [rad/s]); -1 for a fixed body
 * (it has no states), -2 for an id that is no /RBODY of m, or a NULL m.
 * The state vectors the library hands out (rc_session_state,
 * rc_run_options.y_end) hold positions in the deck's coordinates, also for
 * a scene that the model computes about an origin of its own
 * (docs/theory.md 7.1, "The model's origin"). */
int rc_model_body_index(const rc_model *m, int body_id);
/* The state of /RBODY body_id read from a state vector `y` of m
 * (rc_model_state_size(m) values: rc_session_state, rc_run_options.y_end)
 * into out[13]: centre of mass in the deck's coordinates [m] (3), unit
 * quaternion (w, x, y, z) body -> global [-] (4), velocity of the centre of
 * mass, global frame [m/s] (3), angular velocity, body frame [rad/s] (3):
 * the values of the results file's body_* variables. A fixed body gives its
 * pose at rest (y is not read and may be NULL). RC_EINPUT for a NULL m or
 * out, a NULL y for a free body, or an id that is no /RBODY of m (the
 * message lists the model's ids). */
rc_status rc_model_body_state(const rc_model *m, const double *y, int body_id, double out[13], rc_error *err);

/* ---- Running --------------------------------------------------------- */

/* One impact of a contact interface: from the contact closing (P > 0 and
 * the force acting) to the bodies separating (P back to 0). Peak force and
 * maximum penetration are tracked at every integrator step (the step's
 * interpolant sampled at 4 points), not from the output records. A contact
 * is an impact when it closed by approaching (dP/dt > 0) and lasted at most
 * RC_IMPACT_SPAN contact time scales; every other contact is a persistent
 * contact (rc_contact; docs/output-format.md, "Impacts table"). */
typedef struct rc_impact {
    int inter_id;         /* /INTER id                                         */
    double t_close;       /* the contact closes (contact_close) [s]            */
    double t_open;        /* the force stops acting for the last time (released
                             or separated) [s]; NaN: still acting at the end  */
    double duration;      /* t_open - t_close [s]                              */
    double pen_max;       /* maximum penetration P [m]                         */
    double t_pen_max;     /* when [s]                                          */
    double fn_max;        /* peak total normal force [N]                       */
    double t_fn_max;      /* when [s]                                          */
    double v_in;          /* approach speed dP/dt at closing [m/s]             */
    double v_out;         /* separation speed -dP/dt at P = 0 [m/s]; NaN: not
                             separated by the end                              */
    double restitution;   /* v_out / v_in [-]                                  */
    double energy_lost;   /* contact damping + hysteresis + friction dissipated
                             from closing to separation [J]                    */
} rc_impact;

/* Impacts itemised in rc_stats (all of them are in the results file). */
#define RC_STATS_IMPACTS 5

/* One persistent contact of an interface: a contact that is not an impact
 * (docs/output-format.md, "Persistent contacts table"): closed from the
 * start or without approaching (resting, touching), or closed for longer
 * than RC_IMPACT_SPAN contact time scales (a body come to rest, rolling,
 * sliding). It runs from the closing to the separation (P back to 0), or
 * to the end of the run. The integrals are taken at every integrator step
 * end and event (trapezoidal rule), not at the output records. */
typedef struct rc_contact {
    int inter_id;         /* /INTER id                                         */
    double t_close;       /* the contact closes (0: closed from the start) [s] */
    double t_open;        /* the force stops acting for the last time [s];
                             NaN: still closed at the end of the run          */
    double duration;      /* t_open (or the end of the run) - t_close [s]      */
    double fn_max;        /* peak total normal force [N]                       */
    double fn_mean;       /* time average of the total normal force over the
                             duration [N]                                      */
    double pen_max;       /* maximum penetration P [m]                         */
    double slip;          /* slip distance: integral of the tangential relative
                             speed |v_t| of the bodies at the contact point
                             over the duration [m] (with or without friction) */
} rc_contact;

/* Persistent contacts itemised in rc_stats (all of them are in the results
 * file). */
#define RC_STATS_CONTACTS 5

/* An impact lasts at most this many contact time scales pi p_s / v_s of
 * its interface (docs/theory.md 7.1; ricochet check prints them); a
 * contact closed longer is a persistent contact [-]. */
#define RC_IMPACT_SPAN 20

/* Solver statistics of a run. */
typedef struct rc_stats {
    long steps;           /* integrator steps                          */
    long rhs_evals;       /* right-hand side evaluations               */
    long jac_evals;       /* Jacobian evaluations                      */
    long lin_setups;      /* linear solver setups (KLU factorisations) */
    long nonlin_iters;    /* Newton iterations                         */
    long nonlin_fails;    /* Newton convergence failures               */
    long err_test_fails;  /* local error test failures                 */
    long root_evals;      /* root function evaluations                 */
    long events;          /* located events (mode changes)             */
    long reinits;         /* integrator restarts after events          */
    double t_end;         /* simulated time reached [s]                */
    double wall_time;     /* wall-clock time of the integration [s]    */
    double energy_residual; /* energy balance residual at the end [J]  */
    long impacts;         /* impacts of the contact interfaces (rc_impact) */
    rc_impact impact[RC_STATS_IMPACTS]; /* the first ones                 */
    char sampling_note[320]; /* non-empty: /RUN Dt_out is too coarse for the
                                contacts (printed by rc_stats_print)     */
    long settles;         /* contacts that settled into persistent contact
                             after their bounces accumulated (event
                             contact_settle)                           */
    double t_settle;      /* time of the last settling [s]; NaN: none   */
    long violations;      /* physics checks that failed (docs/theory.md,
                             "Physics checks of every run"); 0: passed  */
    char physics_note[640]; /* the checks' outcome: "passed (...)", or
                             the violation that stopped the run, or the
                             count and the first (on-violation warn)    */
    char contacts_note[640]; /* interfaces that never closed, contacts
                             closed from the start or never reopened,
                             settled contacts ("" when every interface
                             closed and reopened)                       */
    int preloaded;        /* 1: the run started from a static preload
                             (/SOLVER Preload, rc_model_set_preload)    */
    long preload_iters;   /* its Newton iterations (KINSOL)             */
    double preload_wall_time; /* its wall-clock time [s]                */
    long contacts;        /* persistent contacts (rc_contact; not impacts) */
    rc_contact contact[RC_STATS_CONTACTS]; /* the first ones              */
    long switches_explicit; /* method switches from BDF to the explicit
                             method (events method_explicit)            */
    long switches_implicit; /* and back (events method_implicit)        */
    long steps_explicit;  /* of `steps`, those of the explicit method     */
    long records_thinned; /* records at events and inside contacts left
                             out of the results file: past 200 in an
                             output interval (docs/output-format.md)    */
    char vibration_note[480]; /* non-empty: a long run whose steps went
                             mostly into following undamped contact
                             vibrations (docs/theory.md 7.10)          */
    char tolerance_note[480]; /* non-empty: the derived position tolerance
                             of some bodies was raised to what their
                             coordinates resolve, so that the run cannot
                             be as accurate as rtol asks (docs/theory.md
                             7.1; printed by rc_stats_print)           */
} rc_stats;

/* The callback of every event (rc_run_options.on_event): called once per
 * row of the events table, in order, with
 *   t        the event time [s]
 *   kind     the event kind as in the events table ("contact_open",
 *            "contact_close", "contact_separate", ..., "impvel_stop";
 *            docs/output-format.md)
 *   element  the element ("/INTER/TYPE6/1", "/IMPVEL")
 *   values   the interface's penetration [m], approach speed [m/s] and
 *            normal force [N] after the event (NaN when the element is
 *            not an interface: "impvel_stop")
 * Return 0 to go on; non-zero stops the run after this event: the records
 * up to there are written, the file is marked incomplete with the reason
 * "stopped by the event callback at t = ...", and rc_run returns
 * RC_EINTERRUPT. Called from the thread that integrates: rc_run's caller,
 * or a session's integration thread; what it may call is listed under
 * "Stepping" below. `kind` and `element` are valid during the call only. */
typedef int (*rc_event_fn)(void *user, double t, const char *kind, const char *element,
                           const double values[3]);

/* The most output records a run may write: an output interval that gives
 * more over the end time (floor(t_end / dt_out) + 2 records, the events'
 * records not counted) is refused with RC_EINPUT saying the count, whether
 * it comes from the case (/RUN) or from rc_run_options. */
#define RC_MAX_RECORDS 10000000

/* Options of one run. Zero-initialise, then set what you need. The options
 * are checked as the case's values are, before anything runs or is
 * written: a wrong one is RC_EINPUT naming it. */
typedef struct rc_run_options {
    const char *output_path; /* netCDF output file; NULL: no file. Created,
                                or replaced when it is a regular file;
                                refused (RC_EINPUT, nothing written) when it
                                names the case file or a file it includes
                                (compared by device and inode, so another
                                spelling or a link is recognised) or
                                something that is not a regular file      */
    int progress;            /* 1: progress on stderr: one line updated
                                on a terminal, else a line every 10 s   */
    double t_end_override;   /* 0: the case's end time; else the end time
                                [s], finite and > 0 (NaN, infinite or
                                negative: RC_EINPUT), with at most
                                RC_MAX_RECORDS records                   */
    double *y_end;           /* non-NULL: receives the final state vector,
                                rc_model_state_size(m) values (layout in
                                docs/theory.md)                          */
    volatile sig_atomic_t *stop; /* non-NULL: when it becomes non-zero (set
                                by a signal handler), the run ends at the next
                                right-hand-side evaluation, writes what it
                                computed (marked incomplete, with its
                                statistics) and returns RC_EINTERRUPT   */
    double dt_out_override;  /* 0: the case's output interval; else the
                                interval [s], finite and > 0 (otherwise
                                RC_EINPUT), giving at most RC_MAX_RECORDS
                                records over the end time               */
    rc_event_fn on_event;    /* non-NULL: called at every event          */
    void *user;              /* passed to on_event                       */
    int on_violation;        /* what a failed physics check does:
                                RC_ON_VIOLATION_STOP ends the run with
                                RC_EPHYSICS, RC_ON_VIOLATION_WARN records it
                                (results file, rc_stats) and goes on; 0: the
                                deck's /RUN On_viol (default: stop)       */
} rc_run_options;
enum { RC_ON_VIOLATION_STOP = 1, RC_ON_VIOLATION_WARN = 2 };

/* Number of values in the state vector of a model; 0 for a NULL m. */
int rc_model_state_size(const rc_model *m);

/* Integrate the model from t = 0 to its end time, writing the output.
 * Returns RC_OK; RC_EINPUT (a NULL m, a wrong option, an output path that
 * names an input: nothing run, nothing written); RC_ESOLVER (partial output
 * kept, marked incomplete); RC_EPHYSICS (a physics check failed: partial
 * output kept, its status "physics check failed: ..."); RC_EINTERRUPT (the stop flag or the event
 * callback); RC_EIO (the results file could not be written: after a failed
 * write the file is closed as far as HDF5 can, read back from the disk, and
 * the message says exactly what it keeps, or that it did not read back and
 * was removed). `opt`, `stats` and `err` may be NULL (NULL opt: the case's
 * settings, no file). `stats` is zeroed when nothing ran. */
rc_status rc_run(const rc_model *m, const rc_run_options *opt, rc_stats *stats,
                 rc_error *err);
/* 1 after HDF5 could not close a results file whose write had failed
 * (rc_run's message says so): the HDF5 library cannot be shut down safely
 * then, so a program should end with _exit() rather than exit() or a
 * return from main (HDF5's exit-time clean-up would crash). A full file
 * system is detected before any write fails: the file is then closed
 * whole, marked incomplete, and this stays 0. */
int rc_output_abandoned(void);

/* ---- Stepping ------------------------------------------------------- */
/* A run advanced in pieces: rc_session_open starts it (the output file is
 * created, the initial modes set) and stops at t = 0; each rc_run_until
 * advances it to a time and stops there, with the state available;
 * rc_session_close ends it. Running in pieces gives the same steps, events
 * and records as one rc_run when the pieces end on output times (elsewhere
 * only the first step after a restart may differ, within the tolerances).
 * The integration runs in a second thread (the session's integration
 * thread) that waits while the caller holds the session; the callbacks of
 * `opt` are called from that thread, while the thread that called
 * rc_run_until (or rc_session_open, rc_session_close) waits for it.
 *
 * From the event callback of a session:
 *   - rc_run_until and rc_session_close of that same session, or of a
 *     session whose integration thread waits for this one (its callback
 *     stepping this session), would wait for themselves: they return
 *     RC_EINPUT and do nothing (the session goes on). To stop the run,
 *     return non-zero from the callback; close the session after the
 *     callback has returned.
 *   - rc_session_time, rc_session_state and rc_session_finished of that
 *     session may be called: they give the time and state where the
 *     caller last stopped the session (not the event's; the callback's
 *     own arguments give the event).
 *   - Its model must not be changed or freed (rc_model_set_rtol,
 *     rc_model_set_method, rc_model_free).
 *   - Everything else may be called: other cases, models, runs and
 *     sessions (opened, stepped or closed there).
 * The same holds for the callback of rc_run, which is called from the
 * thread that called rc_run. A session is used from one thread at a time
 * (not necessarily the one that opened it). */
typedef struct rc_session rc_session;

/* Start a run of `m` with the options `opt` (copied; may be NULL: the
 * case's settings, no file). The options are checked as rc_run checks them
 * (RC_EINPUT, nothing run or written). `m` and `out` must not be NULL
 * (RC_EINPUT); *out is NULL on failure. The model must outlive the
 * session. */
rc_status rc_session_open(const rc_model *m, const rc_run_options *opt, rc_session **out, rc_error *err);
/* Advance to min(t, end time) [s] (t = +infinity: to the end time). RC_OK,
 * or the status of a run that ended (RC_ESOLVER, RC_EIO, RC_EINTERRUPT)
 * with *err filled; once ended, every later call returns that status
 * again. A t at or before the time reached does nothing. RC_EINPUT, and
 * nothing done, for a NULL s, a NaN t, or a call from the event callback
 * that would wait for itself (above). */
rc_status rc_run_until(rc_session *s, double t, rc_error *err);
/* The time reached [s] and the state there (rc_model_state_size values,
 * valid until the next rc_run_until or rc_session_close). NaN and NULL for
 * a NULL s. */
double rc_session_time(const rc_session *s);
const double *rc_session_state(const rc_session *s);
/* 1 when the run has reached its end time or ended on an error; 1 for a
 * NULL s (nothing left to run). */
int rc_session_finished(const rc_session *s);
/* End the session: a run not at its end time is stopped there (the file
 * closed, marked incomplete with the reason "stopped by the caller at t =
 * ...", status RC_EINTERRUPT); else the status of the run. Fills `stats`
 * (may be NULL) and frees the session. NULL is a no-op (RC_OK). From the
 * event callback that would wait for itself (above): RC_EINPUT, the
 * session left open. */
rc_status rc_session_close(rc_session *s, rc_stats *stats, rc_error *err);

/* Print statistics in the format of `ricochet run`: counters, the first
 * impacts and the sampling note. A NULL s or f prints nothing. */
void rc_stats_print(const rc_stats *s, FILE *f);

/* ---- Export ------------------------------------------------------------ */

/* Write a ParaView time series of a results file: DIR/<stem>.pvd listing,
 * per frame, one VTK XML PolyData file of the bodies (surfaces
 * tessellated) and one of the contacts (points with force vectors, the
 * events since the previous frame as field data); docs/output-format.md.
 * The data arrays are in VTK's appended raw binary format (little-endian,
 * UInt64 block headers; Float64 values, Int32 ids) unless opt->ascii.
 *
 * Frames (opt may be NULL: all defaults):
 *   - dt > 0 [s]: one frame per dt at most: the first record at or after
 *     each multiple of dt, and the last record;
 *   - every > 0: records 0, every, 2 every, ... (ceil(records / every)
 *     frames; every = 1: every record, the event records included);
 *   - neither (the default): the records at the output times (/RUN Dt_out;
 *     not the extra records at events), thinned when there are more than
 *     RC_VTK_DEFAULT_MAX_FRAMES of them to one per dt, dt the smallest 1, 2
 *     or 5 x 10^k s giving at most that many frames; and the last record.
 *     (The 1 s demo at Dt_out 0.1 ms: 501 frames, one per 2 ms.)
 * dt and every together, a negative or non-finite dt or a negative every:
 * RC_EINPUT, nothing written.
 *
 * DIR is created when missing; files of an earlier export there are
 * replaced, not removed. `result` (may be NULL) receives the frames and
 * bytes written, also when the export fails part way (what was written).
 * The results file is opened first: one that cannot be read leaves no
 * directory behind. RC_EIO when a file cannot be read or written, RC_EINPUT
 * when the results file lacks the variables needed, for a NULL
 * results_path or dir, or for options as above. */
typedef struct rc_vtk_options {
    double dt;  /* > 0: one frame per dt [s] at most; 0: not used        */
    int every;  /* > 0: every N-th record; 0: not used                  */
    int ascii;  /* 1: ASCII data arrays (larger and slower to write and
                   read; for reading the files by eye); 0: appended raw
                   binary                                              */
} rc_vtk_options;
#define RC_VTK_DEFAULT_MAX_FRAMES 1000
typedef struct rc_vtk_result {
    int frames;       /* time steps in the .pvd (two files each)       */
    double bytes;     /* bytes written, the .pvd included              */
    double dt_used;   /* the default's frame interval [s]; 0 when the
                         output times were taken as they are, or when
                         dt or every was given                          */
} rc_vtk_result;
rc_status rc_export_vtk_opts(const char *results_path, const char *dir, const rc_vtk_options *opt,
                             rc_vtk_result *result, rc_error *err);
/* Every record, in binary (rc_export_vtk_opts with every = 1). *nframes
 * (may be NULL) receives the number of frames written. NULL results_path
 * or dir: RC_EINPUT. */
rc_status rc_export_vtk(const char *results_path, const char *dir, int *nframes, rc_error *err);
/* One frame per dt [s] at most, in binary (rc_export_vtk_opts with this
 * dt; dt = 0: every record, as rc_export_vtk). A frame's contacts file
 * holds the events since the previous frame. RC_EINPUT for a dt below 0
 * or not finite, or a NULL results_path or dir. */
rc_status rc_export_vtk_dt(const char *results_path, const char *dir, double dt, int *nframes, rc_error *err);

/* ---- Forward sensitivities (docs/calibration.md "Sensitivities") ------
 * The derivatives ds/dp of the state vector with respect to np numeric
 * fields of the deck, by CVODES forward sensitivity analysis between the
 * events and the jump of the sensitivities at each event (docs/theory.md
 * "Sensitivities"). A field enters through three compiled models of the
 * same deck: `m` at the field's value p, m_lo[j] and m_hi[j] at p -+ h
 * (rc_case_load_set), which must have the same structure (states,
 * interfaces, roots); p[j] the field's value (the scale of its
 * sensitivities' absolute tolerances, atol / |p|; NULL: 1); dp[j] = (p + h) - (p - h) in the field's own card
 * units, so that the derivatives are per card unit of the field. The
 * right-hand side's df/dp is the central difference of the two models at
 * the same state and modes, the initial ds/dp that of their initial
 * states. Only /SOLVER Method 1 (CVODE) without a preload is covered
 * (RC_EINPUT otherwise).
 * times[nt]: increasing, >= 0, the last > 0; the run ends at the last. y[nt * ny] and
 * s[(nt * np + j) * ny ...] (time i, parameter j: s + (i * np + j) * ny)
 * receive the state and its derivatives there (ny = rc_model_state_size).
 * `info` (may be NULL) counts what was done; `stats` (may be NULL) as
 * rc_run's. */
typedef struct rc_sens_info {
    long jumps;        /* events at which the sensitivities jumped          */
    long resets;       /* of them, events that also set states (a history
                          state reset: the map's derivative by central
                          differences of the event applied along s)        */
    long simultaneous; /* of them, events with several roots at one time
                          (the first root's event time derivative is used) */
    long restarts;     /* sensitivity restarts (CVodeSensReInit)            */
    int errcon;        /* 1: the sensitivities were in the integrator's
                          error test; 0: that run failed and this one was
                          run with the state's error test alone            */
} rc_sens_info;
/* The events of a sensitivity run and the derivatives of their times
 * (the caller's arrays; rc_sens_run fills the first `max`): the event time
 * tau, its derivative dtau/dp_j, and the state just before the event with
 * its total derivative d y(tau(p)-)/dp_j = s- + f- dtau/dp_j (what a
 * quantity read at the event, such as a rebound speed, moves by). */
typedef struct rc_sens_events {
    int max;            /* capacity of the arrays                           */
    int n;              /* events with a root written (at most max); events
                           beyond max are counted in `more`                 */
    long more;
    double *t;          /* [max] tau [s]                                    */
    int *inter_id;      /* [max] /INTER id of the root, 0: not an interface's */
    const char **kind;  /* [max] the first event's kind (as in the results
                           file's events table: "contact_close", ...)     */
    double *dtdp;       /* [max np] dtau/dp_j [s per card unit]             */
    double *vn;         /* [max] the interface's approach rate dP/dt just
                           before [m/s] (an impact's v_in at its closing,
                           -v_out at its separation; 0: not an interface)  */
    double *dvndp;      /* [max np] its total derivative [m/s per card unit] */
    double *y;          /* [max ny] the state just before; NULL: not kept   */
    double *dydp;       /* [max np ny] (event k, parameter j: + (k np + j) ny)
                           its total derivative; NULL: not kept             */
} rc_sens_events;
/* `ev` may be NULL. */
rc_status rc_sens_run(const rc_model *m, int np, const rc_model *const *m_lo, const rc_model *const *m_hi,
                      const double *p, const double *dp, int nt, const double *times, double *y, double *s, rc_sens_info *info,
                      rc_sens_events *ev, rc_stats *stats, rc_error *err);

#ifdef __cplusplus
}
#endif
#endif /* RICOCHET_H */
