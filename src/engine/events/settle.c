/*
 * Settling of accumulating bounces and the event accumulation (Zeno) guard
 * (settle.h; docs/theory.md 5.1, 5.2), applied after each root return's
 * events: a contact that closes after a flight short against its last
 * contact phase, its flights shrinking, is held closed; more than
 * RC_ZENO_MAX crowded events of one interface settle it when they are
 * contact events of a closed contact, and end the run otherwise.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "engine/events/settle.h"
#include "engine/constraints/stick.h"
#include "engine/assembly/assembly.h"

struct rc_settle {
    double *t_open;   /* [ninter] last contact_open or contact_separate [s] (NaN: none) */
    double *t_close;  /* [ninter] last contact_close [s] (NaN: none) */
    double *t_flight; /* [ninter] the last flight, t_close - t_open [s] (NaN: none) */
    double *a_open;   /* [ninter] the pair's approach acceleration from every force but the
                         contact's at t_open [m/s^2] (NaN: not judged) */
    int *nshrink;     /* [ninter] flights shrunk in a row */
    int *apart;       /* [ninter] separated (contact_separate) since its last close */
    double *zeno_t;   /* [ninter] time of the interface's last event [s] */
    int *zeno_n;      /* [ninter] its events in a row, each within the Zeno window of the previous */
    double *lq_t;     /* [ninter] time of its last event of any pass (rc_settle_lowq) [s] */
    int *lq_n;        /* [ninter] its events in a row, each within RC_LOWQ_GAP periods of the previous */
};

rc_settle *rc_settle_new(const rc_model *m)
{
    rc_settle *s = calloc(1, sizeof *s);
    if (!s) return NULL;
    const size_t n = (size_t)m->ninter + 1;
    s->t_open = malloc(n * sizeof(double));
    s->t_close = malloc(n * sizeof(double));
    s->t_flight = malloc(n * sizeof(double));
    s->a_open = malloc(n * sizeof(double));
    s->nshrink = calloc(n, sizeof(int));
    s->apart = calloc(n, sizeof(int));
    s->zeno_t = calloc(n, sizeof(double));
    s->zeno_n = calloc(n, sizeof(int));
    s->lq_t = malloc(n * sizeof(double));
    s->lq_n = calloc(n, sizeof(int));
    if (!s->t_open || !s->t_close || !s->t_flight || !s->a_open || !s->nshrink || !s->apart || !s->zeno_t ||
        !s->zeno_n || !s->lq_t || !s->lq_n) {
        rc_settle_free(s);
        return NULL;
    }
    for (int i = 0; i < m->ninter; i++) /* no contact phase yet */
        s->t_open[i] = s->t_close[i] = s->t_flight[i] = s->a_open[i] = s->lq_t[i] = NAN;
    return s;
}

void rc_settle_free(rc_settle *s)
{
    if (!s) return;
    free(s->t_open);
    free(s->t_close);
    free(s->t_flight);
    free(s->a_open);
    free(s->nshrink);
    free(s->apart);
    free(s->zeno_t);
    free(s->zeno_n);
    free(s->lq_t);
    free(s->lq_n);
    free(s);
}

const char *rc_settle_hold(const rc_model *m, int i)
{
    return m->method == 2 && rc_stk_settle_capable(m, i) ? "held by a unilateral constraint until its force turns tensile"
                                                         : "its penalty law held closed until P returns to 0";
}

void rc_settle_lowq(rc_settle *s, const rc_model *m, rc_data *d, double t, const rc_event *ev, int nev)
{
    for (int k = 0; k < nev; k++) {
        const int i = ev[k].inter;
        if (i < 0) continue;
        double period = NAN;
        const double zeta = rc_inter_zeta_stiff(m, i, &period);
        if (!(zeta < RC_LOWQ_ZETA)) continue; /* NaN: undamped, or not a TYPE6 Visc */
        s->lq_n[i] = t - s->lq_t[i] < RC_LOWQ_GAP * period ? s->lq_n[i] + 1 : 0;
        s->lq_t[i] = t;
        if (s->lq_n[i] >= RC_LOWQ_EVENTS && d->inter_mode[i] == RC_MODE_CLOSED) d->inter_lowq[i] = 1;
    }
}

/* Hold the closed contact of interface i in persistent contact: its event
 * contact_settle. */
static void settle(rc_data *d, int i, rc_event *settled, int max_settled, int *nsettled)
{
    d->inter_settled[i] = 1;
    if (*nsettled < max_settled) settled[*nsettled] = (rc_event){i, RC_EV_CONTACT_SETTLE};
    (*nsettled)++;
}

/* Whether a contact phase of interface i lasting phase [s] was one bounce:
 * at most RC_SETTLE_PHASE periods of the contact at its scale (settle.h),
 * 2 pi sqrt(m_eff / k_s) with m_eff its effective mass along the normal
 * (m->inter_mrest, the one of its restitution). An interface without a
 * scale (nothing moves along its normal, or no stiffness) is not judged
 * by it. */
static int one_bounce(const rc_model *m, int i, double phase)
{
    const double mr = m->inter_mrest[i], ks = m->inter_kscale[i];
    if (!(mr > 0) || !(ks > 0) || !isfinite(mr) || !isfinite(ks)) return 1;
    return phase <= RC_SETTLE_PHASE * 2.0 * RC_PI * sqrt(mr / ks);
}

/* The normal approach acceleration of interface i's pair at (t, y) from
 * every force but this contact's (its mode open for the evaluation; f
 * scratch [ny]) [m/s^2]; its approach rate into *vn [m/s]. NaN when the
 * forces cannot be evaluated. */
static double approach_acc(const rc_model *m, rc_data *d, int i, double t, const double *y, double *f, double *vn)
{
    rc_inter_report r, dr;
    rc_inter_report_eval_d(m, d, i, t, y, &r);
    *vn = r.vn;
    const int mode = d->inter_mode[i];
    d->inter_mode[i] = RC_MODE_OPEN;
    const int bad = rc_assemble_rhs(m, d, t, y, f);
    d->inter_mode[i] = mode;
    if (bad) return NAN;
    rc_inter_report_rate(m, i, RC_MODE_OPEN, d->inter_branch[i], 0, d->inter_slip[i], y, f, &dr);
    return dr.vn;
}

/* Whether the flight of interface i [s] that ended at its close at (t, y)
 * was ended by a load: the pair's approach acceleration from every force
 * but this contact's, at the close and at the flight's start (a_open),
 * over the flight reaches RC_SETTLE_LOAD times the closing speed
 * (settle.h). A load must act at both ends: a force that arrived during
 * the flight is another body's impact, not a load the bounces accumulate
 * under (a cradle in space, ball 2 struck by ball 1 9e-8 s before it
 * closed on ball 3 at 6 cm/s: the impact's 1 100 N passed at the close
 * alone, the contact settled, held rigid on IDA and not on CVODE, and the
 * two backends' cascades parted by 1.9 mm). Forces that cannot be
 * evaluated: not judged (the rule as without the load). */
static int loaded(const rc_model *m, rc_data *d, int i, double t, const double *y, double *f, double flight,
                  double a_open)
{
    double vn;
    const double a = approach_acc(m, d, i, t, y, f, &vn);
    if (isnan(a)) return 1;
    const double need = RC_SETTLE_LOAD * fabs(vn);
    return a * flight >= need && (isnan(a_open) || a_open * flight >= need);
}

/* The contact's own events (contact_close, _open, _separate, _settle). */
static int contact_kind(rc_event_kind k)
{
    return k == RC_EV_CONTACT_CLOSE || k == RC_EV_CONTACT_OPEN || k == RC_EV_CONTACT_SEPARATE ||
           k == RC_EV_CONTACT_SETTLE;
}

void rc_settle_contacts(rc_settle *s, const rc_model *m, rc_data *d, double t, const double *y, double *f,
                        const rc_event *ev, int nev, rc_event *settled, int max_settled, int *nsettled, int *restart)
{
    *nsettled = 0;
    /* settling: a contact that closes after a flight short against its
     * last contact phase is held closed (RC_SETTLE_FLIGHT) */
    for (int k = 0; k < nev; k++) {
        const int i = ev[k].inter;
        if (i < 0) continue;
        if (ev[k].kind == RC_EV_CONTACT_OPEN || ev[k].kind == RC_EV_CONTACT_SEPARATE) {
            double vn;
            s->t_open[i] = t;
            /* the load at the flight's start, for the rule below (an
             * elastic contact never settles: no evaluation) */
            s->a_open[i] = rc_inter_elastic(m, i) ? NAN : approach_acc(m, d, i, t, y, f, &vn);
        }
        if (ev[k].kind == RC_EV_CONTACT_SEPARATE) s->apart[i] = 1;
        if (ev[k].kind != RC_EV_CONTACT_CLOSE) continue;
        /* a released contact loading again before it separated: the same
         * contact phase, no landing after a flight (a cradle in space,
         * released contacts of balls pressed by their neighbours reloading
         * 0.3 to 1 ms later at separating speeds of microns per second, or
         * at once on IDA: settled as shrinking flights) */
        if (!s->apart[i] && !isnan(s->t_close[i])) continue;
        s->apart[i] = 0;
        const double flight = t - s->t_open[i], phase = s->t_open[i] - s->t_close[i];
        s->nshrink[i] = flight < RC_SETTLE_RATIO * s->t_flight[i] ? s->nshrink[i] + 1 : 0; /* the flights shrink */
        s->t_flight[i] = flight;
        s->t_close[i] = t;
        /* not an elastic contact (restitution 1): its bounces cannot
         * accumulate, and flights that shrink trade energy with other
         * motions (the middle ball of an undamped stack of three: its
         * contacts settled on CVODE, where that changes nothing, and on IDA
         * became rigid, 1 mm from the penalty motion 0.16 s later) */
        if (d->inter_mode[i] == RC_MODE_CLOSED && !d->inter_settled[i] && s->nshrink[i] >= RC_SETTLE_SHRINK &&
            flight < RC_SETTLE_FLIGHT * phase && !rc_inter_elastic(m, i) && one_bounce(m, i, phase) &&
            loaded(m, d, i, t, y, f, flight, s->a_open[i]))
            settle(d, i, settled, max_settled, nsettled);
        *restart |= d->inter_settled[i]; /* its root function changed: restart */
    }
}

void rc_settle_sfric_hint(const rc_model *m, const rc_data *d, int i, char *buf, size_t n)
{
    const double sf = m->inter_fr[i].kind != RC_FK_NONE ? m->inter_fr[i].sfric : 0.0;
    if (n > 0) buf[0] = '\0';
    if (sf > 0 && d->inter_mode[i] != RC_MODE_OPEN)
        snprintf(buf, n,
                 "; its friction limit holds Sfric = %.3g N, which acts at zero normal force and vanishes "
                 "when the contact releases: a smaller Sfric, or none, lets it release", sf);
}

rc_settle_verdict rc_settle_after_events(rc_settle *s, const rc_model *m, rc_data *d, double t, const double *y,
                                         double *f, double dtout, const rc_event *ev, int nev, rc_event *settled,
                                         int max_settled, int *nsettled, int *restart, char *why, size_t n)
{
    rc_settle_lowq(s, m, d, t, ev, nev);
    rc_settle_contacts(s, m, d, t, y, f, ev, nev, settled, max_settled, nsettled, restart);
    /* event accumulation: report it rather than stall; the contact events
     * of an interface that is closed settle it instead */
    for (int k = 0; k < nev; k++) {
        const int i = ev[k].inter;
        if (i < 0) continue; /* a contact coupling: its faces change modes with the state moving */
        s->zeno_n[i] = t - s->zeno_t[i] <= RC_ZENO_REL * fmax(fabs(t), dtout) ? s->zeno_n[i] + 1 : 0;
        s->zeno_t[i] = t;
        if (s->zeno_n[i] > RC_ZENO_MAX && contact_kind(ev[k].kind) && d->inter_mode[i] == RC_MODE_CLOSED) {
            if (!d->inter_settled[i]) settle(d, i, settled, max_settled, nsettled);
            s->zeno_n[i] = 0;
            *restart = 1;
            continue;
        }
        if (s->zeno_n[i] > RC_ZENO_MAX) {
            /* a contact released and closed at zero force whose friction
             * limit holds Sfric: the friction (up to Sfric, whatever F_n)
             * comes and goes with the mode, and turns the force the contact
             * would carry the other way each time (a box sliding on a floor
             * with Sfric = 1.8 times its weight, released and closed every
             * 3e-10 s; with Sfric = 0 it runs to the end) */
            char hint[240] = "";
            if (contact_kind(ev[k].kind)) rc_settle_sfric_hint(m, d, i, hint, sizeof hint);
            snprintf(why, n,
                     "event accumulation (Zeno) at t = %.9g s in %s: more than %d events within %.2g s of "
                     "each other (last: %s); the modes of this element switch without the state moving: "
                     "tighter tolerances or a smoother law may help%s",
                     t, m->inter_name[i], RC_ZENO_MAX, RC_ZENO_REL * fmax(fabs(t), dtout),
                     rc_event_kind_name(ev[k].kind), hint);
            return RC_SETTLE_ZENO;
        }
    }
    return RC_SETTLE_GO_ON;
}
