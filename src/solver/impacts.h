/*
 * Impacts of the contact interfaces (rc_impact, include/ricochet/ricochet.h):
 * opened and closed by the events, peak normal force and maximum
 * penetration tracked at every integrator step by the backend (which samples
 * its interpolant), energy lost from the energy ledger at the events.
 */
#ifndef RC_IMPACTS_H
#define RC_IMPACTS_H

#include "model/model.h"
#include "engine/assembly/data.h"
#include "engine/assembly/event_kind.h"

/* The last two samples of an interface's impact in progress (step ends and
 * events): time [s], penetration P [m], its rate dP/dt [m/s], normal force
 * [N]; [0] the older. */
typedef struct rc_impact_hist {
    int n; /* samples held, 0..2 */
    double t[2], p[2], vn[2], fn[2];
    double tpk; /* the end of the last step whose force maximum inside was refined [s] */
} rc_impact_hist;

/* The state at time t from the backend's interpolant of its last step
 * (0), or -1 when t is outside it. */
typedef int (*rc_interp_fn)(void *ctx, double t, const double **y);

/* What a contact row accumulates besides rc_impact: the integrals over
 * its closed time, taken at the samples (step ends and events) by the
 * trapezoidal rule, and how it closed. */
typedef struct rc_impact_acc {
    double fint;  /* integral of the normal force while closed [N s] */
    double slip;  /* integral of |v_t| at the contact point while closed [m] */
    int start;    /* 1: closed without approaching (from the start, or
                     touching at zero approach speed) */
} rc_impact_acc;

/* The last sample of an interface's contact in progress, for the
 * integrals: time [s], normal force as it acts [N], |v_t| [m/s]. */
typedef struct rc_impact_last {
    int have;
    double t, fn, vt;
} rc_impact_last;

typedef struct rc_impacts {
    int ninter;
    int *cur;       /* [ninter] row of the contact in progress, -1: none */
    double *e0;     /* [ninter] dissipated energy when it closed [J] */
    rc_impact_hist *h; /* [ninter] */
    rc_impact_last *last; /* [ninter] */
    rc_impact *row; /* [n] every contact until rc_impacts_finish, then
                       the impacts only */
    rc_impact_acc *acc; /* [n] (rows before rc_impacts_finish) */
    int n, cap;
    int *quiet;     /* [ninter] 1: the row in progress was closed by the
                       initial state (no records inside it) */
    rc_contact *pc; /* [npc] the persistent contacts (rc_impacts_finish) */
    int npc;
    long *nevt;     /* [ninter] the instants at which the interface had events
                       (several at one instant count once: one restart) */
    double *tev;    /* [ninter] the last of them [s] (NaN: none) */
} rc_impacts;

/* 0, or -1 when out of memory. */
int rc_impacts_init(rc_impacts *im, const rc_model *m);
void rc_impacts_free(rc_impacts *im);
/* An event `kind` of interface i at (t, y), modes of d after the event. */
void rc_impacts_event(rc_impacts *im, const rc_model *m, const rc_data *d, int i, rc_event_kind kind, double t,
                      const double *y);
/* Rows for the contacts the initial state closed without an event (P > 0
 * at t = 0): persistent contacts from the start. Call once after the
 * modes are initialised and the touching contacts resolved. */
void rc_impacts_start(rc_impacts *im, const rc_model *m, const rc_data *d, double t, const double *y);
/* Is any contact in progress (the backend then samples every step)? */
int rc_impacts_active(const rc_impacts *im);
/* The end of an integrator step at t with the state y: updates the maxima of
 * the impacts in progress from the sample at t and, where the samples
 * bracket a maximum inside the step, from one more sample at the maximum of
 * a local fit (a cubic Hermite fit of P on its rate at the step's ends; a
 * parabola through the last three force samples), taken from the
 * interpolant `interp`, which covers [lo, t]. */
void rc_impacts_step(rc_impacts *im, const rc_model *m, const rc_data *d, double lo, double t, const double *y,
                     rc_interp_fn interp, void *ctx);
/* Close the table at the end of the run at t_end (contacts in progress
 * stay open: open time and separation speed NaN) and sort the rows into
 * impacts (row, n) and persistent contacts (pc, npc) by the rule of
 * rc_impacts_is_impact. */
void rc_impacts_finish(rc_impacts *im, const rc_model *m, double t_end);
/* The contact time scale of interface i: pi p_s / v_s [s], NaN when the
 * model gives no scales. */
double rc_impacts_contact_time(const rc_model *m, int i);
/* Is a contact an impact? It closed by approaching (approach speed > 0 at
 * the close, not closed by the initial state) and lasted (to its opening,
 * or to the end of the run when still closed) at most RC_IMPACT_SPAN
 * contact time scales tc (any duration when tc is NaN). */
int rc_impacts_is_impact(int start, double v_in, double duration, double tc);
/* The note when the output interval cannot resolve the contacts (fewer than
 * RC_IMPACT_MIN_RECORDS records over a contact of the linearised duration
 * pi p_s / v_s); buf[0] = 0 otherwise. */
void rc_impacts_sampling_note(const rc_model *m, char *buf, size_t n);
/* Records per contact inside contacts that Dt_out cannot resolve. */
#define RC_CONTACT_RECORDS 20
/* ... written over the first this many contact times of an impact: a
 * contact that lasts (a body coming to rest, a persistent contact) gets no
 * more records than an impact, whatever the length of the run */
#define RC_CONTACT_REC_SPAN 4
/* Is an impact in progress that closed at most `span` seconds before t? */
int rc_impacts_recent(const rc_impacts *im, double t, double span);
/* ... written for models of at most this many bodies (impact studies; a
 * many-body model has contacts in progress all the time) */
#define RC_CONTACT_REC_MAX_BODIES 10
/* at_event value of such a record */
#define RC_REC_CONTACT 2
/* The interval of the records inside contacts [s]: the shortest contact
 * time scale pi p_s / v_s over RC_CONTACT_RECORDS, or 0 when Dt_out
 * (dtout) already gives that many records per contact. */
double rc_contact_record_interval(const rc_model *m, double dtout);

/* Records per contact below which the note is given [-]. */
#define RC_IMPACT_MIN_RECORDS 10

/* The note of a long run (at least RC_VIB_NOTE_STEPS steps) whose steps
 * went mostly into following undamped contact vibrations: the persistent
 * contacts (pc, after rc_impacts_finish) of the interfaces without normal
 * damping, each vibrating with the period 2 pi sqrt(m / k) of its closed
 * contact (m the reduced mass of its free bodies, k its stiffness scale or
 * its Stiff line, the steeper), when the run took 0.5 to 4 times
 * RC_VIB_STEPS_PER_PERIOD steps for each period of the fastest of them
 * closed at each time plus RC_VIB_STEPS_PER_EVENT for each instant at
 * which those interfaces had events (nevt) and RC_VIB_STEPS_PER_IMPACT for
 * each of their impacts (row); buf[0] = 0
 * otherwise (docs/theory.md 7.10). */
void rc_impacts_vibration_note(const rc_impacts *im, const rc_model *m, long steps, char *buf, size_t n);
/* The hint appended to a failure for Max_steps at t [s] ("; the contact
 * ... vibrates undamped ..."): written when an interface closed at t or in
 * the output interval before it (im's contacts) vibrates undamped (the
 * period of rc_impacts_vibration_note) and following its periods in an
 * output interval dt_out [s] at RC_VIB_STEPS_PER_PERIOD, with its event
 * instants there (nevt at the run's rate so far) at RC_VIB_STEPS_PER_EVENT,
 * takes at least half of /SOLVER Max_steps; t_left [s] the time to the
 * end. buf[0] = 0 otherwise (docs/theory.md 7.10). */
void rc_impacts_max_steps_hint(const rc_impacts *im, const rc_model *m, double t, double dt_out, double t_left,
                               char *buf, size_t n);
/* Steps of a run from which the vibration note is considered [-]. */
#define RC_VIB_NOTE_STEPS 100000
/* Steps an error-controlled integrator spends on a period of an undamped
 * vibration it follows (BDF at rtol 1e-6 .. 1e-10: 30 to 70) [-]. */
#define RC_VIB_STEPS_PER_PERIOD 30
/* Steps the integrator spends after each event instant of a contact that
 * vibrates undamped (the restart's climb back to its step and order: 45 to
 * 66 measured on a ball, a small box and a box on an incline whose undamped
 * vibrations drive their friction's stick and slip every period) [-]. */
#define RC_VIB_STEPS_PER_EVENT 50
/* Steps an impact takes at the default tolerances (its compression and
 * restitution followed: the measured cost `ricochet check` estimates with)
 * [-], for the impacts of those contacts (their bounces never die out
 * either) */
#define RC_VIB_STEPS_PER_IMPACT 150

#endif
