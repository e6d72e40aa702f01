/*
 * Right-hand side, root functions and reports, in real arithmetic.
 * Pure: reads (t, y, modes), writes ydot; no allocation, no printing, no
 * mode change.
 */
#include <math.h>
#include <string.h>
#include <tgmath.h>

#include "model.h"

#define T double
#define RE(x) (x)
#define RCK(name) name##_r
#include "kernels.inc"

/* Acceleration slot (vdot, wdot) of body b in ydot, NULL when b has no states. */
static double *acc_slot(const rc_model *m, int b, double *ydot)
{
    return (b >= 0 && m->body_yadr[b] >= 0) ? ydot + m->body_yadr[b] + 7 : NULL;
}

int rc_assemble_rhs(const rc_model *m, rc_data *d, double t, const double *y, double *ydot)
{
    d->n_rhs++;
    /* bodies: free motion */
    for (int b = 0; b < m->nbody; b++)
        if (m->body_yadr[b] >= 0) body_rhs_r(m, b, t, y + m->body_yadr[b], ydot + m->body_yadr[b]);
    /* interfaces: forces into the accelerations, energy rates */
    for (int i = 0; i < m->ninter; i++) {
        double *edot = ydot + m->inter_eadr[i];
        edot[0] = edot[1] = 0.0;
        if (d->inter_mode[i] != RC_MODE_CLOSED) continue;
        const int ba = m->inter_ba[i], bb = m->inter_bb[i];
        type6_r(m, i, RC_MODE_CLOSED, rc_body_state(m, ba, y), rc_body_state(m, bb, y),
                acc_slot(m, ba, ydot), acc_slot(m, bb, ydot), edot, NULL, NULL, NULL);
        if (!isfinite(edot[0]) || !isfinite(edot[1])) {
            d->fail_inter = i;
            d->fail_t = t;
            return 1; /* recoverable: CVODE retries with a smaller step */
        }
    }
    return 0;
}

void rc_inter_report_eval(const rc_model *m, int i, int mode, double t, const double *y,
                          rc_inter_report *r)
{
    geom_r g;
    double fl, fd;
    (void)t;
    type6_r(m, i, mode, rc_body_state(m, m->inter_ba[i], y), rc_body_state(m, m->inter_bb[i], y),
            NULL, NULL, NULL, &g, &fl, &fd);
    r->p = m->inter_gap[i] - g.d;
    r->vn = -g.ddot;
    r->fload = fl;
    r->fdamp = fd;
    r->fn = fl + fd;
    for (int k = 0; k < 3; k++) {
        r->point[k] = g.point[k];
        r->normal[k] = g.n[k];
    }
}

void rc_assemble_roots(const rc_model *m, const rc_data *d, double t, const double *y, double *g)
{
    for (int i = 0; i < m->ninter; i++) {
        double *gi = g + RC_ROOTS_PER_INTER * i;
        gi[RC_ROOT_TSTART] = t - m->inter_tstart[i];
        gi[RC_ROOT_TSTOP] = t - m->inter_tstop[i];
        /* open: penetration crosses zero; closed: total force crosses zero */
        const int mode = d->inter_mode[i];
        if (mode == RC_MODE_INACTIVE) {
            gi[RC_ROOT_CONTACT] = 1.0;
            continue;
        }
        rc_inter_report r;
        rc_inter_report_eval(m, i, RC_MODE_CLOSED, t, y, &r);
        gi[RC_ROOT_CONTACT] = mode == RC_MODE_OPEN ? r.p : r.fn;
    }
}
