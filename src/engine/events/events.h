/* Event handling: which modes flip when roots are found. */
#ifndef RC_EVENTS_H
#define RC_EVENTS_H

#include "model/model.h"
#include "engine/assembly/data.h"
#include "engine/assembly/event_kind.h"

/* Events of the contact couplings reported per call at most. */
#define RC_CPL_MAX_EV 32

typedef struct rc_event {
    int inter;          /* interface index; < 0: coupling -1 - inter */
    rc_event_kind kind; /* RC_EV_CONTACT_CLOSE, ... (engine/assembly/event_kind.h) */
} rc_event;

/* Flip the modes named by the root directions `roots` (CVODE rootsfound:
 * +1 rising, -1 falling, 0 none) at the event state (t, y). History states
 * reset by a transition are written into y. *restart is set when the
 * integrator must start afresh from (t, y): a history state was reset, or a
 * law whose Jacobian jumps at its switch (viscous friction) switched. Writes
 * up to max_ev events; returns how many transitions happened. */
int rc_events_apply(const rc_model *m, rc_data *d, double t, double *y, const int *roots, rc_event *ev,
                    int max_ev, int *restart);

/* Contacts at zero penetration or zero force, decided by the state (at the
 * start and after every event; docs/theory.md 5.1): a contact at P = 0 closes
 * unless its bodies separate (dP/dt < 0), a closed one separating there
 * opens; a contact at zero force takes the mode its rate dF_n/dt (along
 * ydot, the state rate in the current modes) points to. Contacts left
 * closed at zero get touch bands so that their roots start off zero.
 * Writes up to max_ev events; returns the number of transitions. */
int rc_modes_touch(const rc_model *m, rc_data *d, double t, double *y, const double *ydot, rc_event *ev, int max_ev,
                   int *restart);

/* Consistent modes at (t, y) from scratch (start of run); may set history
 * states in y (Inacti offset, initial F_h). */
void rc_modes_init(const rc_model *m, rc_data *d, double t, double *y);

#endif
