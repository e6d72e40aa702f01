/*
 * Stepping (rc_session_open, rc_run_until, rc_session_close): a run
 * advanced in pieces. The integration is rc_run itself, unchanged, in a
 * second thread; the backend calls rc_pause.reached whenever it reaches the
 * time asked for (solver.h), and that thread waits there, with the state
 * copied out, until the caller asks for a later time or closes the session.
 * So a run in pieces takes the steps of one run, and nothing of the
 * backend's loop is duplicated. Only one of the two threads works at a
 * time.
 */
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "model/model.h"
#include "solver/solver.h"

struct rc_session {
    rc_pause pause; /* first: the backend's callback gets it */
    const rc_model *m;
    rc_run_options opt;
    pthread_t thread;
    pthread_mutex_t mu;
    pthread_cond_t cv;
    int running;  /* the integration thread works (the caller waits)   */
    int finished; /* rc_run returned                                   */
    int stop;     /* the caller closes the session before the end time */
    double t;     /* time reached, as seen by the caller [s]           */
    double *y;    /* [ny] state at t                                   */
    double *y_end; /* [ny] the final state of a run that ended well    */
    double *user_y_end; /* the caller's rc_run_options.y_end            */
    rc_status st; /* rc_run's status, once finished                    */
    rc_stats stats;
    rc_error err;
};

/* Integration thread: at the time asked for, hand the state over and wait. */
static int reached(rc_pause *p, double t, const double *y)
{
    rc_session *s = (rc_session *)p;
    pthread_mutex_lock(&s->mu);
    s->t = t;
    memcpy(s->y, y, (size_t)s->m->ny * sizeof(double));
    s->running = 0;
    pthread_cond_broadcast(&s->cv);
    while (!s->running) pthread_cond_wait(&s->cv, &s->mu);
    const int stop = s->stop;
    pthread_mutex_unlock(&s->mu);
    return stop;
}

static void *integrate(void *arg)
{
    rc_session *s = arg;
    rc_stats st;
    rc_error e;
    rc_error_clear(&e);
    memset(&st, 0, sizeof st);
    const rc_status r = rc_run_paused(s->m, &s->opt, &s->pause, &st, &e);
    pthread_mutex_lock(&s->mu);
    s->st = r;
    s->stats = st;
    s->err = e;
    if (r == RC_OK) {
        s->t = st.t_end;
        memcpy(s->y, s->y_end, (size_t)s->m->ny * sizeof(double));
    }
    s->finished = 1;
    s->running = 0;
    pthread_cond_broadcast(&s->cv);
    pthread_mutex_unlock(&s->mu);
    return NULL;
}

/* Caller: let the integration thread work until it pauses or ends. */
static void resume(rc_session *s)
{
    pthread_mutex_lock(&s->mu);
    s->running = 1;
    pthread_cond_broadcast(&s->cv);
    while (s->running) pthread_cond_wait(&s->cv, &s->mu);
    pthread_mutex_unlock(&s->mu);
}

rc_status rc_session_open(const rc_model *m, const rc_run_options *opt, rc_session **out, rc_error *err)
{
    rc_error local;
    if (!err) err = &local;
    rc_error_clear(err);
    *out = NULL;
    rc_session *s = calloc(1, sizeof *s);
    if (!s) RC_RAISE(err, RC_ENOMEM, "out of memory for the session");
    s->m = m;
    if (opt) s->opt = *opt;
    s->user_y_end = s->opt.y_end;
    s->y = calloc((size_t)m->ny + 1, sizeof(double));
    s->y_end = calloc((size_t)m->ny + 1, sizeof(double));
    if (!s->y || !s->y_end) {
        free(s->y);
        free(s->y_end);
        free(s);
        RC_RAISE(err, RC_ENOMEM, "out of memory for the session");
    }
    s->opt.y_end = s->y_end; /* the caller's y_end is filled at the close */
    s->pause.until = 0.0;    /* hand over the initial state */
    s->pause.reached = reached;
    pthread_mutex_init(&s->mu, NULL);
    pthread_cond_init(&s->cv, NULL);
    s->running = 1;
    if (pthread_create(&s->thread, NULL, integrate, s)) {
        pthread_mutex_destroy(&s->mu);
        pthread_cond_destroy(&s->cv);
        free(s->y);
        free(s->y_end);
        free(s);
        RC_RAISE(err, RC_ENOMEM, "cannot start the integration thread");
    }
    /* wait for t = 0 (or a run that could not start) */
    pthread_mutex_lock(&s->mu);
    while (s->running) pthread_cond_wait(&s->cv, &s->mu);
    pthread_mutex_unlock(&s->mu);
    if (s->finished && s->st != RC_OK) {
        const rc_status st = s->st;
        *err = s->err;
        rc_session_close(s, NULL, NULL);
        return st;
    }
    *out = s;
    return RC_OK;
}

rc_status rc_run_until(rc_session *s, double t, rc_error *err)
{
    rc_error local;
    if (!err) err = &local;
    if (!s->finished && t > s->t) {
        s->pause.until = t;
        resume(s);
    }
    if (s->finished && s->st != RC_OK) {
        *err = s->err;
        return s->st;
    }
    rc_error_clear(err);
    return RC_OK;
}

double rc_session_time(const rc_session *s) { return s->t; }

const double *rc_session_state(const rc_session *s) { return s->y; }

int rc_session_finished(const rc_session *s) { return s->finished; }

rc_status rc_session_close(rc_session *s, rc_stats *stats, rc_error *err)
{
    rc_error local;
    if (!err) err = &local;
    rc_error_clear(err);
    if (!s) return RC_OK;
    if (!s->finished) { /* stop the run where it is */
        s->stop = 1;
        resume(s);
    }
    pthread_join(s->thread, NULL);
    const rc_status st = s->st;
    if (st) *err = s->err;
    if (stats) *stats = s->stats;
    if (st == RC_OK && s->user_y_end) memcpy(s->user_y_end, s->y_end, (size_t)s->m->ny * sizeof(double));
    pthread_mutex_destroy(&s->mu);
    pthread_cond_destroy(&s->cv);
    free(s->y);
    free(s->y_end);
    free(s);
    return st;
}
