/*
 * Run data and discrete modes. Modes change only here, between solver calls:
 * at the start of a run and at located events.
 */
#include <stdlib.h>

#include "events.h"

rc_data *rc_data_new(const rc_model *m)
{
    rc_data *d = calloc(1, sizeof *d);
    if (!d) return NULL;
    d->inter_mode = calloc((size_t)m->ninter + 1, sizeof(int));
    if (!d->inter_mode) {
        free(d);
        return NULL;
    }
    d->fail_inter = -1;
    return d;
}

void rc_data_free(rc_data *d)
{
    if (!d) return;
    free(d->inter_mode);
    free(d);
}

/* Mode of an active interface from its state: closed when penetrating with
 * a positive force, or exactly touching while approaching. */
static int contact_mode(const rc_model *m, int i, double t, const double *y)
{
    rc_inter_report r;
    rc_inter_report_eval(m, i, RC_MODE_CLOSED, t, y, &r);
    if ((r.p > 0 && r.fn > 0) || (r.p == 0 && r.vn > 0)) return RC_MODE_CLOSED;
    return RC_MODE_OPEN;
}

void rc_modes_init(const rc_model *m, rc_data *d, double t, const double *y)
{
    for (int i = 0; i < m->ninter; i++) {
        int active = t >= m->inter_tstart[i] && t <= m->inter_tstop[i];
        d->inter_mode[i] = active ? contact_mode(m, i, t, y) : RC_MODE_INACTIVE;
    }
}

int rc_events_apply(const rc_model *m, rc_data *d, double t, const double *y, const int *roots,
                    rc_event *ev, int max_ev)
{
    int n = 0;
    for (int i = 0; i < m->ninter; i++) {
        const int *r = roots + RC_ROOTS_PER_INTER * i;
        int old = d->inter_mode[i], mode = old;
        const char *kind = NULL;
        if (r[RC_ROOT_TSTOP] > 0 && old != RC_MODE_INACTIVE) {
            mode = RC_MODE_INACTIVE;
            kind = "inter_stop";
        } else if (r[RC_ROOT_TSTART] > 0 && old == RC_MODE_INACTIVE && t <= m->inter_tstop[i]) {
            mode = contact_mode(m, i, t, y);
            kind = "inter_start";
        } else if (r[RC_ROOT_CONTACT] > 0 && old == RC_MODE_OPEN) {
            mode = RC_MODE_CLOSED;
            kind = "contact_close";
        } else if (r[RC_ROOT_CONTACT] < 0 && old == RC_MODE_CLOSED) {
            mode = RC_MODE_OPEN;
            kind = "contact_open";
        }
        if (!kind) continue;
        d->inter_mode[i] = mode;
        if (n < max_ev) {
            ev[n].inter = i;
            ev[n].kind = kind;
        }
        n++;
    }
    return n;
}
