/* Event handling: which modes flip when roots are found. */
#ifndef RC_EVENTS_H
#define RC_EVENTS_H

#include "model.h"

typedef struct rc_event {
    int inter;        /* interface index */
    const char *kind; /* "contact_close", "contact_open", "inter_start", "inter_stop" */
} rc_event;

/* Flip the modes named by the root directions `roots` (CVODE rootsfound:
 * +1 rising, -1 falling, 0 none) at the event state (t, y); history states
 * reset by a transition are written into y and *state_changed set. Writes up
 * to max_ev events; returns how many transitions happened. */
int rc_events_apply(const rc_model *m, rc_data *d, double t, double *y, const int *roots, rc_event *ev,
                    int max_ev, int *state_changed);

#endif
