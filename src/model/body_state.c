/*
 * The bodies of a compiled model for the library's users: their ids, where
 * each body's 13 states sit in the state vector, and a body's state read
 * from a state vector in the deck's coordinates (public API,
 * include/ricochet/ricochet.h).
 *
 * The state vectors the library hands out (rc_session_state,
 * rc_run_options.y_end) hold positions in the deck's coordinates (the
 * solver adds the model's origin back, rc_state_to_deck): a free body's
 * values are read as they are. A fixed body's pose (body_y0) is relative
 * to the model's origin (model.h, docs/theory.md 7.1 "The model's
 * origin"): the origin is added back, as the results file does
 * (solver/drive.c).
 */
#include "model/model.h"
#include "base/error.h"

#include <stdio.h>
#include <string.h>

int rc_model_body_count(const rc_model *m) { return m ? m->nbody : 0; }

int rc_model_body_id(const rc_model *m, int i)
{
    return m && i >= 0 && i < m->nbody ? m->body_id[i] : -1;
}

/* The model's index of /RBODY body_id, -1 when there is none. */
static int body_of(const rc_model *m, int body_id)
{
    for (int b = 0; b < m->nbody; b++)
        if (m->body_id[b] == body_id) return b;
    return -1;
}

int rc_model_body_index(const rc_model *m, int body_id)
{
    if (!m) return -2;
    const int b = body_of(m, body_id);
    if (b < 0) return -2;
    return m->body_yadr[b] >= 0 ? m->body_yadr[b] : -1;
}

rc_status rc_model_body_state(const rc_model *m, const double *y, int body_id, double out[13], rc_error *err)
{
    if (!m) RC_RAISE(err, RC_EINPUT, "rc_model_body_state: the model is NULL; expected a compiled model");
    if (!out) RC_RAISE(err, RC_EINPUT, "rc_model_body_state: out is NULL; expected room for 13 values");
    const int b = body_of(m, body_id);
    if (b < 0) {
        /* name the ids there are (at most a few), for the message */
        char ids[256] = "";
        size_t w = 0;
        for (int k = 0; k < m->nbody && w + 16 < sizeof ids; k++)
            w += (size_t)snprintf(ids + w, sizeof ids - w, "%s%d", k ? ", " : "", m->body_id[k]);
        if (m->nbody > 0 && w + 16 >= sizeof ids) snprintf(ids + w, sizeof ids - w, ", ...");
        RC_RAISE(err, RC_EINPUT, "rc_model_body_state: no /RBODY/%d in the model (its bodies: %s)", body_id,
                 m->nbody ? ids : "none");
    }
    if (m->body_yadr[b] >= 0 && !y)
        RC_RAISE(err, RC_EINPUT, "rc_model_body_state: y is NULL; expected the state vector (%d values) for the free body /RBODY/%d",
                 m->ny, body_id);
    if (m->body_yadr[b] >= 0) {
        memcpy(out, y + m->body_yadr[b], RC_NB * sizeof(double)); /* already in the deck's coordinates */
        return RC_OK;
    }
    memcpy(out, m->body_y0 + RC_NB * b, RC_NB * sizeof(double));
    for (int k = 0; k < 3; k++) out[k] += m->origin[k]; /* the deck's coordinates */
    return RC_OK;
}
