/*
 * Impacts of the contact interfaces (rc_impact, include/ricochet/ricochet.h):
 * opened and closed by the events, peak normal force and maximum
 * penetration tracked at every integrator step by the backend (which samples
 * its interpolant), energy lost from the energy ledger at the events.
 */
#ifndef RC_IMPACTS_H
#define RC_IMPACTS_H

#include "model/model.h"

typedef struct rc_impacts {
    int ninter;
    int *cur;       /* [ninter] row of the impact in progress, -1: none */
    double *e0;     /* [ninter] dissipated energy when it closed [J] */
    rc_impact *row; /* [n] */
    int n, cap;
} rc_impacts;

/* 0, or -1 when out of memory. */
int rc_impacts_init(rc_impacts *im, const rc_model *m);
void rc_impacts_free(rc_impacts *im);
/* An event `kind` of interface i at (t, y), modes of d after the event. */
void rc_impacts_event(rc_impacts *im, const rc_model *m, const rc_data *d, int i, const char *kind, double t,
                      const double *y);
/* Is any impact in progress (the backend then samples every step)? */
int rc_impacts_active(const rc_impacts *im);
/* A sample of the state at t: updates the maxima of the impacts in progress. */
void rc_impacts_sample(rc_impacts *im, const rc_model *m, const rc_data *d, double t, const double *y);
/* Close the table at the end of the run (impacts in progress stay open:
 * open time and separation speed NaN). */
void rc_impacts_finish(rc_impacts *im);
/* The note when the output interval cannot resolve the contacts (fewer than
 * RC_IMPACT_MIN_RECORDS records over a contact of the linearised duration
 * pi p_s / v_s); buf[0] = 0 otherwise. */
void rc_impacts_sampling_note(const rc_model *m, char *buf, size_t n);
/* Records per contact inside contacts that Dt_out cannot resolve. */
#define RC_CONTACT_RECORDS 20
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

#endif
