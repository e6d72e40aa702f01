/*
 * Stepping (rc_session_open, rc_run_until, rc_session_close): a run
 * advanced in pieces. The integration is rc_run itself, unchanged, in a
 * second thread; the backend calls rc_pause.reached whenever it reaches the
 * time asked for (solver.h), and that thread waits there, with the state
 * copied out, until the caller asks for a later time or closes the session.
 * So a run in pieces takes the steps of one run, and nothing of the
 * backend's loop is duplicated. Only one of the two threads works at a
 * time.
 *
 * The event callback runs on the integration thread while the caller's
 * thread waits in rc_run_until (or rc_session_open, rc_session_close). A
 * callback that stepped or closed its own session would wait for itself;
 * so would one stepping a session whose thread waits, through a chain of
 * callbacks, for this one. Each integration thread knows its session
 * (worker_of), each session the session whose thread waits for it
 * (waiter), and the two calls refuse such a chain with RC_EINPUT.
 */
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "model/model.h"
#include "solver/solver.h"
#include "engine/assembly/assembly.h"

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
    struct rc_session *waiter; /* the session whose integration thread waits
                                  for this one (from its callback); NULL: an
                                  application thread */
};

/* The session whose integration thread this is (NULL: another thread). */
static _Thread_local rc_session *worker_of;

/* Whether the calling thread would wait for itself by running or closing s:
 * it is s's integration thread, or that of a session waiting (through
 * callbacks) for s. */
static int waits_for_itself(const rc_session *s)
{
    for (const rc_session *w = worker_of; w; w = w->waiter)
        if (w == s) return 1;
    return 0;
}

/* Integration thread: at the time asked for, hand the state over and wait. */
static int reached(rc_pause *p, double t, const double *y)
{
    rc_session *s = (rc_session *)p;
    pthread_mutex_lock(&s->mu);
    s->t = t;
    memcpy(s->y, y, (size_t)s->m->ny * sizeof(double));
    rc_state_to_deck(s->m, s->y);
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
    worker_of = s;
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
    s->waiter = worker_of; /* a callback's thread waits: the chain */
    pthread_mutex_lock(&s->mu);
    s->running = 1;
    pthread_cond_broadcast(&s->cv);
    while (s->running) pthread_cond_wait(&s->cv, &s->mu);
    pthread_mutex_unlock(&s->mu);
    s->waiter = NULL;
}

rc_status rc_session_open(const rc_model *m, const rc_run_options *opt, rc_session **out, rc_error *err)
{
    rc_error local;
    if (!err) err = &local;
    rc_error_clear(err);
    if (!out) RC_RAISE(err, RC_EINPUT, "rc_session_open: out is NULL; expected where to store the session");
    *out = NULL;
    if (!m) RC_RAISE(err, RC_EINPUT, "rc_session_open: the model is NULL; expected a compiled model (rc_model_compile)");
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
    s->waiter = worker_of; /* opened from a callback: its thread waits for t = 0 */
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
    s->waiter = NULL;
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
    if (!s) RC_RAISE(err, RC_EINPUT, "rc_run_until: the session is NULL; expected one from rc_session_open");
    if (isnan(t)) RC_RAISE(err, RC_EINPUT, "rc_run_until: the time is NaN; expected a time [s]");
    if (waits_for_itself(s))
        RC_RAISE(err, RC_EINPUT,
                 "rc_run_until: called from the event callback of this session (or of a session that waits for "
                 "it), on its integration thread, where it would wait for itself; nothing was done. Return "
                 "non-zero from the callback to stop the run, or step the session after the callback returns");
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

double rc_session_time(const rc_session *s) { return s ? s->t : NAN; }

const double *rc_session_state(const rc_session *s) { return s ? s->y : NULL; }

int rc_session_finished(const rc_session *s) { return s ? s->finished : 1; }

rc_status rc_session_close(rc_session *s, rc_stats *stats, rc_error *err)
{
    rc_error local;
    if (!err) err = &local;
    rc_error_clear(err);
    if (!s) return RC_OK;
    if (waits_for_itself(s))
        RC_RAISE(err, RC_EINPUT,
                 "rc_session_close: called from the event callback of this session (or of a session that waits "
                 "for it), on its integration thread, where it would wait for itself; the session is left open. "
                 "Return non-zero from the callback to stop the run, and close the session after the callback "
                 "returns");
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
