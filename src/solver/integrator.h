/*
 * What the integration backends share (internal to solver/): the output
 * records, the events' way to the results file and the caller, the time
 * breakpoints, the root directions and the progress line. Defined in
 * cvode.c, the first backend, and used by ida.c; neither of them needs to
 * know which integrator the other drives.
 *
 * The helpers keep their short names inside the backends; the macros below
 * give them an rc_bk_ prefix at link time, so that the static library does
 * not export names such as write_frame.
 */
#ifndef RC_INTEGRATOR_H
#define RC_INTEGRATOR_H

#include <signal.h>

#include "engine/events.h"
#include "model/model.h"
#include "output/output.h"
#include "solver/impacts.h"
#include "solver/solver.h"

/* Event accumulation (Zeno): more than RC_ZENO_MAX consecutive events of one
 * element, each within RC_ZENO_REL * max(t, dtout) of the previous, end the
 * run with a message instead of stalling [-]. */
#define RC_ZENO_MAX 200
#define RC_ZENO_REL 1e-7
/* Events kept per root return (more are applied but not itemised). */
#define RC_MAX_EV 64
/* Progress in a log (stderr not a terminal): a line every RC_LOG_EVERY s. */
#define RC_LOG_EVERY 10.0

#define time_breakpoints rc_bk_time_breakpoints
#define root_directions rc_bk_root_directions
#define sink_event rc_bk_sink_event
#define write_event rc_bk_write_event
#define resolve_touching rc_bk_resolve_touching
#define root_on_zero rc_bk_root_on_zero
#define wall_now rc_bk_wall_now
#define frame_free rc_bk_frame_free
#define frame_alloc rc_bk_frame_alloc
#define write_frame rc_bk_write_frame
#define open_output rc_bk_open_output
#define progress_line rc_bk_progress_line

/* Where the events go: the events table of the output file (NULL: none)
 * and the caller's callback (rc_run_options.on_event, NULL: none), which
 * may ask to stop (`stop` set, with the event in `why`). */
typedef struct ev_sink {
    rc_output *out;
    rc_event_fn fn;
    void *user;
    int stop;
    char why[300];
} ev_sink;

/* Output buffers for one record. */
typedef struct frame_buf {
    double *pos, *quat, *vel, *omega, *pen, *fload, *fdamp, *fn, *point, *normal, *ffric, *vslip;
    int *mode, *slip;
    double energy[RC_NENERGY];
    double *cpl; /* [9 ncoupling] coupling values (rc_cpl_frame) */
    double *jnt; /* [8 njoint + 1] joints: force, moment, drifts, work (IDA path) */
} frame_buf;

/* Time breakpoints (ends of imposed velocities) inside (0, tend), sorted,
 * distinct; returns the count, -1 out of memory; *bp is allocated. */
int time_breakpoints(const rc_model *m, double tend, double **bp);
/* The root directions of the current modes (only the crossing that changes
 * a mode is a root) into dir[RC_ROOTS_PER_INTER ninter]. */
void root_directions(const rc_model *m, const rc_data *d, int *dir);
/* One event to the sink; v: the interface's values, NULL when none. */
rc_status sink_event(ev_sink *k, double t, const char *kind, const char *element, const double v[3], rc_error *err);
/* Event `ev` at (t, y) with its interface's P, dP/dt and normal force. */
rc_status write_event(const rc_model *m, const rc_data *d, ev_sink *o, double t, const double *y, const rc_event *ev,
                      rc_error *err);
/* Contacts at zero penetration or zero force, decided by the state (after
 * the start and every event); f is scratch [ny]; returns the events. */
int resolve_touching(const rc_model *m, rc_data *d, double t, double *y, double *f, ev_sink *out, rc_impacts *im,
                     long *nevents, int *jumped, rc_status *st, rc_error *err);
/* 1 when a root function is exactly zero at (t, y); g is scratch. */
int root_on_zero(const rc_model *m, const rc_data *d, double t, const double *y, double *g);
double wall_now(void); /* [s], monotonic */
void frame_free(frame_buf *f);
int frame_alloc(const rc_model *m, frame_buf *f);
/* Fill and write one record at (t, y) (o NULL: only f->energy is filled). */
rc_status write_frame(const rc_model *m, const rc_data *d, rc_output *o, frame_buf *f, double t, const double *y,
                      int at_event, rc_error *err);
/* Open the results file (path NULL: none); `integrator` describes the
 * backend in the file's solver attributes. */
rc_status open_output(const rc_model *m, const char *path, const char *note, rc_output **o, rc_error *err,
                      const char *integrator);
/* The progress line on stderr. */
void progress_line(double tend, const rc_stats *s, double t, long steps, double t0, int tty);

#endif
