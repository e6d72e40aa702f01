/* Settling of accumulating bounces and the event accumulation (Zeno) guard
 * (docs/theory.md 5.1, 5.2): after each root return's events, the
 * interfaces' history of closes and openings decides which closed contacts
 * are held in persistent contact (rc_data.inter_settled) and whether events
 * accumulate on an element that cannot settle. The history lives in an
 * rc_settle that the driver allocates for the run. */
#ifndef RC_SETTLE_H
#define RC_SETTLE_H

#include <stddef.h>

#include "model/model.h"
#include "engine/assembly/data.h"
#include "engine/events/events.h"

/* Event accumulation (Zeno): more than RC_ZENO_MAX consecutive events of one
 * element, each within RC_ZENO_REL * max(t, dtout) of the previous, end the
 * run with a message instead of stalling, unless they are contact events of
 * an interface left closed: that contact settles [-]. */
#define RC_ZENO_MAX 200
#define RC_ZENO_REL 1e-7
/* Settling (docs/theory.md 5.2): a contact of a TYPE6 (POWER) interface
 * that closes after a flight shorter than RC_SETTLE_FLIGHT times the
 * contact phase before it (the time between its previous close and its
 * separation), its flights having shrunk RC_SETTLE_SHRINK times in a row, is
 * held closed ("settled"): its release at zero force is suspended, it opens
 * when its penetration returns to zero [-]. */
#define RC_SETTLE_FLIGHT 1.0
#define RC_SETTLE_SHRINK 2
/* A flight has shrunk when it is at most RC_SETTLE_RATIO times the one
 * before: an accumulation under a load shrinks its flights by the
 * restitution at each bounce (the validation problems' settling sequences
 * by 0.46 to 0.78); flights that shrink by a few percent (a meshed box
 * hopping on a belt: 2.58, 2.53, 2.45 ms) are a steady motion whose
 * flights wander, which settled at one tolerance and not at another [-]. */
#define RC_SETTLE_RATIO 0.9
/* ... and that contact phase was one bounce: no longer than RC_SETTLE_PHASE
 * times the contact's period at its scale, 2 pi sqrt(m_eff / k_s) (a
 * compression lasts about half of it; validation's settling bounces 0.31 to
 * 0.81 of it). A longer phase held several oscillations of the contact, the
 * pair riding on a motion of the bodies (the top ball of a stack on a
 * rattling middle one: phases of 1.4 to 4.1 periods) whose flights may
 * shrink without accumulating [-]. */
#define RC_SETTLE_PHASE 1.0
/* ... and the flight f it ended was ended by a load: the pair's approach
 * acceleration a_n at the close from every force but the contact's, a_n f
 * >= RC_SETTLE_LOAD times the closing speed v (a ballistic flight under a
 * steady load has a_n f = 2 v). Without one (balls of a cradle in space,
 * each flight ended by another ball's impact) bounces cannot accumulate:
 * settled, such a contact held its pair together on IDA [-]. */
#define RC_SETTLE_LOAD 0.5
/* The order hold (rc_settle_lowq): BDF order 3 holds a mode of damping
 * ratio zeta in its A(alpha) sector, alpha = 86.03 degrees, only where
 * zeta >= sin(90 - alpha) = 0.069 [-]; RC_LOWQ_EVENTS events of the
 * contact in a row, each within RC_LOWQ_GAP periods of its stiffest line
 * of the one before [-] (an impact has a handful, then a flight). */
#define RC_LOWQ_ZETA 0.069
#define RC_LOWQ_GAP 1.5
#define RC_LOWQ_EVENTS 20

/* The interfaces' history: times of their last close and opening, the last
 * flight, how many times in a row the flights shrank, and the run of
 * crowded events. */
typedef struct rc_settle rc_settle;

/* A fresh history for the run of model m (no contact phase yet); NULL when
 * out of memory. */
rc_settle *rc_settle_new(const rc_model *m);
void rc_settle_free(rc_settle *s);

/* What the driver does after the events. */
typedef enum {
    RC_SETTLE_GO_ON = 0, /* carry on (restart if *restart was set) */
    RC_SETTLE_ZENO = 1   /* events accumulate: end the run with the message */
} rc_settle_verdict;

/* The events ev[0..nev) just applied at (t, y) (rc_events_apply, modes of
 * d after them; f scratch [ny]; dtout the run's output interval): updates the history, marks
 * the closed contacts that settle (d->inter_settled) and writes one event
 * of kind RC_EV_CONTACT_SETTLE per contact settled into settled[] (at most
 * max_settled, in the order they settled; *nsettled their number). Sets
 * *restart when a settled contact's root function changed. Returns
 * RC_SETTLE_ZENO, with the message in why[0..n), when more than
 * RC_ZENO_MAX crowded events of an element cannot be settled (the events
 * after that one are not looked at); the contacts settled before it are
 * still in settled[]. */
rc_settle_verdict rc_settle_after_events(rc_settle *s, const rc_model *m, rc_data *d, double t, const double *y,
                                         double *f, double dtout, const rc_event *ev, int nev, rc_event *settled,
                                         int max_settled, int *nsettled, int *restart, char *why, size_t n);

/* The settling rule alone over the contact events ev[0..nev) at t of any
 * pass (the root return's, rc_settle_after_events calls it; the touch
 * pass's, whose closes, releases and separations are the same contact's
 * history and settle by the same rule): updates the history, marks and
 * writes the settles as rc_settle_after_events does, *nsettled their
 * number; sets *restart when a settled contact's root function changed. */
void rc_settle_contacts(rc_settle *s, const rc_model *m, rc_data *d, double t, const double *y, double *f,
                        const rc_event *ev, int nev, rc_event *settled, int max_settled, int *nsettled, int *restart);

/* The hint of a failure whose element is interface i's contact when its
 * friction limit holds Sfric and it is not open ("; its friction limit
 * holds Sfric = ..."; empty otherwise) into buf[0..n): Sfric acts at zero
 * normal force and vanishes when the contact releases, so a contact at
 * zero force switches between the two (Zeno, or steps collapsing). */
void rc_settle_sfric_hint(const rc_model *m, const rc_data *d, int i, char *buf, size_t n);

/* The order hold of a lightly damped contact whose modes chatter
 * (docs/theory.md 7.7): over the events ev[0..nev) at t of any pass (the
 * root return's, rc_settle_after_events calls it; the touch pass's), the
 * events of an interface whose TYPE6 damping ratio on its stiffest line is
 * below RC_LOWQ_ZETA (rc_inter_zeta_stiff), RC_LOWQ_EVENTS of them in a
 * row each within RC_LOWQ_GAP periods of that line of the one before, set
 * d->inter_lowq while its contact is closed. */
void rc_settle_lowq(rc_settle *s, const rc_model *m, rc_data *d, double t, const rc_event *ev, int nev);

/* How the settled contact of interface i is held, for messages: by a
 * unilateral constraint (IDA, a settle-capable contact) or by its penalty
 * law. */
const char *rc_settle_hold(const rc_model *m, int i);

#endif
