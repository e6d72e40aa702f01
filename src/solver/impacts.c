/* Impacts table of a run (impacts.h). */
#include "solver/impacts.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "engine/assembly/assembly.h"
#include "model/power.h"

/* pi [-] (M_PI is not in C11) */

int rc_impacts_init(rc_impacts *im, const rc_model *m)
{
    memset(im, 0, sizeof *im);
    im->ninter = m->ninter;
    im->cur = malloc(((size_t)m->ninter + 1) * sizeof *im->cur);
    im->e0 = calloc((size_t)m->ninter + 1, sizeof *im->e0);
    im->h = calloc((size_t)m->ninter + 1, sizeof *im->h);
    im->last = calloc((size_t)m->ninter + 1, sizeof *im->last);
    im->quiet = calloc((size_t)m->ninter + 1, sizeof *im->quiet);
    im->nevt = calloc((size_t)m->ninter + 1, sizeof *im->nevt);
    im->tev = malloc(((size_t)m->ninter + 1) * sizeof *im->tev);
    if (!im->cur || !im->e0 || !im->h || !im->last || !im->quiet || !im->nevt || !im->tev) return -1;
    for (int i = 0; i < m->ninter; i++) {
        im->cur[i] = -1;
        im->tev[i] = NAN;
    }
    return 0;
}

void rc_impacts_free(rc_impacts *im)
{
    free(im->cur);
    free(im->e0);
    free(im->h);
    free(im->last);
    free(im->quiet);
    free(im->nevt);
    free(im->tev);
    free(im->row);
    free(im->acc);
    free(im->pc);
    memset(im, 0, sizeof *im);
}

/* Energy dissipated by the contacts so far [J]. */
static double dissipated(const rc_model *m, const rc_data *d, double t, const double *y)
{
    double e[RC_NENERGY];
    rc_energy(m, d, t, y, e);
    return e[RC_E_DAMP] + e[RC_E_HYST] + e[RC_E_FRIC];
}

static void report(const rc_model *m, const rc_data *d, int i, double t, const double *y, rc_inter_report *r)
{
    rc_inter_report_eval_d(m, d, i, t, y, r);
}

static void update(rc_impact *row, const rc_inter_report *r, int closed, double t)
{
    if (r->p > row->pen_max) {
        row->pen_max = r->p;
        row->t_pen_max = t;
    }
    const double fn = closed && r->fn > 0 ? r->fn : 0.0;
    if (fn > row->fn_max) {
        row->fn_max = fn;
        row->t_fn_max = t;
    }
}

/* The tangential relative speed |v_t| of the bodies at the report's
 * contact point [m/s]: v_b + w_b x (x - c_b) - (v_a + w_a x (x - c_a)),
 * less its component along the normal (the velocity of a rigid body is
 * affine in the point, so at the shares' mean point of several contact
 * points it is their shares' mean). */
static double tangential_speed(const rc_model *m, int i, const double *y, const rc_inter_report *r)
{
    double v[3] = {0.0, 0.0, 0.0};
    const int b[2] = {m->inter_ba[i], m->inter_bb[i]};
    for (int s = 0; s < 2; s++) {
        const double *q = rc_body_state(m, b[s], y);
        /* the angular velocity in the global frame: R(q) w_body */
        const double qw = q[3], qx = q[4], qy = q[5], qz = q[6], *wb = q + 10;
        const double R[9] = {1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qw * qz),     2 * (qx * qz + qw * qy),
                             2 * (qx * qy + qw * qz),     1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qw * qx),
                             2 * (qx * qz - qw * qy),     2 * (qy * qz + qw * qx),     1 - 2 * (qx * qx + qy * qy)};
        double w[3], d[3];
        for (int k = 0; k < 3; k++) {
            w[k] = R[3 * k] * wb[0] + R[3 * k + 1] * wb[1] + R[3 * k + 2] * wb[2];
            d[k] = r->point[k] - q[k];
        }
        const double sg = s == 0 ? -1.0 : 1.0;
        v[0] += sg * (q[7] + w[1] * d[2] - w[2] * d[1]);
        v[1] += sg * (q[8] + w[2] * d[0] - w[0] * d[2]);
        v[2] += sg * (q[9] + w[0] * d[1] - w[1] * d[0]);
    }
    const double vn = v[0] * r->normal[0] + v[1] * r->normal[1] + v[2] * r->normal[2];
    double t2 = 0.0;
    for (int k = 0; k < 3; k++) {
        const double c = v[k] - vn * r->normal[k];
        t2 += c * c;
    }
    return sqrt(t2);
}

/* A sample of interface i's contact in progress at t for the integrals of
 * its row: the trapezoidal rule from the last sample, over an interval in
 * which the mode was `closed` (the mode changes only at events, whose
 * samples follow the step's end at the same time). */
static void integrate(rc_impacts *im, const rc_model *m, int i, double t, const double *y, const rc_inter_report *r,
                      int closed)
{
    const int k = im->cur[i];
    if (k < 0) return;
    rc_impact_last *l = &im->last[i];
    const double fn = closed ? r->fn : 0.0, vt = closed ? tangential_speed(m, i, y, r) : 0.0;
    if (l->have && t > l->t && closed) {
        const double dt = t - l->t;
        im->acc[k].fint += 0.5 * (l->fn + fn) * dt;
        im->acc[k].slip += 0.5 * (l->vt + vt) * dt;
    }
    *l = (rc_impact_last){1, t, fn, vt};
}

/* A new row for interface i closing at t (NULL: out of memory). */
static rc_impact *open_row(rc_impacts *im, int i)
{
    if (im->n == im->cap) {
        const int cap = im->cap ? 2 * im->cap : 16;
        rc_impact *p = realloc(im->row, (size_t)cap * sizeof *p);
        if (!p) return NULL; /* the table misses this contact */
        im->row = p;
        rc_impact_acc *a = realloc(im->acc, (size_t)cap * sizeof *a);
        if (!a) return NULL;
        im->acc = a;
        im->cap = cap;
    }
    const int k = im->cur[i] = im->n++;
    im->acc[k] = (rc_impact_acc){0.0, 0.0, 0};
    im->last[i].have = 0;
    im->quiet[i] = 0;
    return &im->row[k];
}

/* Append a sample to an interface's history (the older one dropped). */
static void hist_push(rc_impact_hist *h, double t, const rc_inter_report *r, int closed)
{
    if (h->n == 2) {
        h->t[0] = h->t[1];
        h->p[0] = h->p[1];
        h->vn[0] = h->vn[1];
        h->fn[0] = h->fn[1];
        h->n = 1;
    }
    h->t[h->n] = t;
    h->p[h->n] = r->p;
    h->vn[h->n] = r->vn;
    h->fn[h->n] = closed && r->fn > 0 ? r->fn : 0.0;
    h->n++;
}

void rc_impacts_event(rc_impacts *im, const rc_model *m, const rc_data *d, int i, rc_event_kind kind, double t,
                      const double *y)
{
    if (i < 0 || i >= im->ninter || kind == RC_EV_NONE) return;
    if (!(im->tev[i] == t)) im->nevt[i]++;
    im->tev[i] = t;
    /* an event changes the law's branch: the fits do not reach across it */
    im->h[i].n = 0;
    int k = im->cur[i];
    if (kind == RC_EV_CONTACT_CLOSE) {
        rc_inter_report r;
        report(m, d, i, t, y, &r);
        if (k < 0) {
            rc_impact *w = open_row(im, i);
            if (!w) return;
            k = im->cur[i];
            *w = (rc_impact){m->inter_id[i], t, NAN, NAN, r.p, t, 0.0, t, r.vn, NAN, NAN, NAN};
            im->acc[k].start = !(r.vn > 0.0);
            im->e0[i] = dissipated(m, d, t, y);
        } else {
            im->row[k].t_open = NAN; /* the force acts again */
        }
        update(&im->row[k], &r, d->inter_mode[i] == RC_MODE_CLOSED, t);
        integrate(im, m, i, t, y, &r, d->inter_mode[i] == RC_MODE_CLOSED);
        hist_push(&im->h[i], t, &r, d->inter_mode[i] == RC_MODE_CLOSED);
        return;
    }
    if (k < 0) return;
    rc_impact *w = &im->row[k];
    {
        /* the state after the event starts the next interval of the integrals */
        rc_inter_report r;
        report(m, d, i, t, y, &r);
        integrate(im, m, i, t, y, &r, d->inter_mode[i] == RC_MODE_CLOSED);
    }
    if (kind == RC_EV_CONTACT_OPEN) {
        w->t_open = t; /* released: the force stopped (until it closes again) */
    } else if (kind == RC_EV_CONTACT_SEPARATE || kind == RC_EV_INTER_STOP) {
        rc_inter_report r;
        report(m, d, i, t, y, &r);
        if (isnan(w->t_open)) w->t_open = t;
        w->duration = w->t_open - w->t_close;
        if (kind == RC_EV_CONTACT_SEPARATE) {
            w->v_out = -r.vn;
            w->restitution = w->v_in > 0 ? w->v_out / w->v_in : NAN;
        }
        w->energy_lost = dissipated(m, d, t, y) - im->e0[i];
        im->cur[i] = -1;
        im->last[i].have = 0;
    }
}

void rc_impacts_start(rc_impacts *im, const rc_model *m, const rc_data *d, double t, const double *y)
{
    for (int i = 0; i < im->ninter; i++) {
        if (im->cur[i] >= 0 || d->inter_mode[i] != RC_MODE_CLOSED) continue;
        rc_inter_report r;
        report(m, d, i, t, y, &r);
        rc_impact *w = open_row(im, i);
        if (!w) return;
        const int k = im->cur[i];
        /* approaching at the start (a body launched into a contact it
         * touches): an impact from t; else a persistent contact, whose
         * speed in, separation and restitution do not exist */
        const int approach = r.vn > 0.0;
        *w = (rc_impact){m->inter_id[i], t, NAN, NAN, r.p, t, 0.0, t, approach ? r.vn : NAN, NAN, NAN, NAN};
        im->acc[k].start = !approach;
        im->quiet[i] = 1;
        im->e0[i] = dissipated(m, d, t, y);
        update(w, &r, 1, t);
        hist_push(&im->h[i], t, &r, 1);
        integrate(im, m, i, t, y, &r, 1);
    }
}

int rc_impacts_recent(const rc_impacts *im, double t, double span)
{
    for (int i = 0; i < im->ninter; i++)
        if (im->cur[i] >= 0 && !im->quiet[i] && t - im->row[im->cur[i]].t_close <= span) return 1;
    return 0;
}

int rc_impacts_active(const rc_impacts *im)
{
    for (int i = 0; i < im->ninter; i++)
        if (im->cur[i] >= 0) return 1;
    return 0;
}

/* The root in (0, 1) of the derivative of the cubic Hermite fit on [0, 1]
 * of values p0, p1 and scaled slopes m0 > 0 > m1 (exactly one), or NaN. */
static double hermite_max(double p0, double p1, double m0, double m1)
{
    const double a = 6.0 * (p0 - p1) + 3.0 * (m0 + m1), b = -6.0 * (p0 - p1) - 4.0 * m0 - 2.0 * m1, c = m0;
    double s1 = NAN, s2 = NAN;
    if (fabs(a) <= 1e-14 * (fabs(b) + fabs(c))) {
        if (b != 0.0) s1 = -c / b;
    } else {
        const double disc = b * b - 4.0 * a * c;
        if (disc < 0.0) return NAN;
        const double q = -0.5 * (b + copysign(sqrt(disc), b));
        s1 = q / a;
        if (q != 0.0) s2 = c / q;
    }
    if (s1 > 0.0 && s1 < 1.0) return s1;
    if (s2 > 0.0 && s2 < 1.0) return s2;
    return NAN;
}

/* One more sample of interface i at ts from the interpolant. */
static double refine(rc_impacts *im, const rc_model *m, const rc_data *d, int i, double ts, rc_interp_fn interp,
                     void *ctx)
{
    const double *yi = NULL;
    if (!interp || interp(ctx, ts, &yi) != 0 || !yi) return NAN;
    rc_inter_report r;
    report(m, d, i, ts, yi, &r);
    const int closed = d->inter_mode[i] == RC_MODE_CLOSED;
    update(&im->row[im->cur[i]], &r, closed, ts);
    return closed && r.fn > 0 ? r.fn : 0.0;
}

/* Successive parabolas for the force's maximum from ts, on the step's
 * interpolant over [lo, hi]: the vertex through ts - w, ts, ts + w, w a
 * tenth of the step, then a quarter of the last, for RC_PEAK_ITERS rounds
 * (each sample raises the row's maximum when above it). */
#define RC_PEAK_ITERS 4
/* A step is probed for a force maximum inside it when longer than the
 * contact's time scale over this [-]. */
#define RC_PEAK_STEPS 50.0
static void refine_force(rc_impacts *im, const rc_model *m, const rc_data *d, int i, double ts, double lo, double hi,
                         rc_interp_fn interp, void *ctx)
{
    double fc = refine(im, m, d, i, ts, interp, ctx), w = 0.1 * (hi - lo);
    for (int k = 0; k < RC_PEAK_ITERS && isfinite(fc) && w > 0; k++, w *= 0.25) {
        const double ta = fmax(lo, ts - w), tb = fmin(hi, ts + w);
        if (!(ta < ts && ts < tb)) return;
        const double fa = refine(im, m, d, i, ta, interp, ctx), fb = refine(im, m, d, i, tb, interp, ctx);
        if (!isfinite(fa) || !isfinite(fb)) return;
        const double dab = (fc - fa) / (ts - ta), dbc = (fb - fc) / (tb - ts), dabc = (dbc - dab) / (tb - ta);
        if (!(dabc < 0.0)) return;
        const double tv = 0.5 * (ta + ts) - dab / (2.0 * dabc);
        if (!(tv > ta && tv < tb)) return;
        ts = tv;
        fc = refine(im, m, d, i, ts, interp, ctx);
    }
}

void rc_impacts_step(rc_impacts *im, const rc_model *m, const rc_data *d, double lo, double t, const double *y,
                     rc_interp_fn interp, void *ctx)
{
    /* the root functions at the step's end evaluated the same reports */
    const int cached = rc_report_cache_state(m, d, y);
    /* the state at the step's middle, interpolated once for every contact
     * (NULL: not yet, or the backend's scratch since overwritten) */
    const double *ymid = NULL;
    double tmid = NAN;
    for (int i = 0; i < im->ninter; i++) {
        if (im->cur[i] < 0) continue;
        const int closed = d->inter_mode[i] == RC_MODE_CLOSED;
        rc_inter_report r;
        if (!cached || !rc_report_cache_get(m, d, i, &r)) report(m, d, i, t, y, &r);
        rc_impact *row = &im->row[im->cur[i]];
        update(row, &r, closed, t);
        integrate(im, m, i, t, y, &r, closed);
        rc_impact_hist *h = &im->h[i];
        const int last = h->n - 1;
        if (last >= 0 && t > h->t[last]) {
            const double t0 = h->t[last], dt = t - t0, from = fmax(lo, t0);
            /* P rises at the last sample and falls now: its maximum is
             * inside, at the maximum of the Hermite fit */
            if (h->vn[last] > 0.0 && r.vn < 0.0) {
                const double s = hermite_max(h->p[last], r.p, h->vn[last] * dt, r.vn * dt);
                const double ts = t0 + s * dt;
                if (ts > from && ts < t) refine(im, m, d, i, ts, interp, ctx);
            }
            const double f1 = closed && r.fn > 0 ? r.fn : 0.0;
            /* the force rose from the last sample, peaked inside the step
             * and fell back: the interpolant at the step's middle is above
             * both ends. Its maximum is refined now, while the interpolant
             * covers it (the three samples below see it a step later, and
             * when the step is long, e.g. the explicit method's under
             * method switching, their vertex lies in the step before, out
             * of the interpolant: the parabola's value was 2e-5 low). Looked
             * for in a step longer than 1/RC_PEAK_STEPS of the contact's
             * time scale over which the samples' force did not fall (a
             * peak inside a step over which it fell is the samples'
             * parabola's, in this step or in a probed one) */
            const double f0 = h->fn[last], tc = rc_impacts_contact_time(m, i);
            if (closed && interp && from == t0 && f1 >= f0 && f1 > 0 && !(RC_PEAK_STEPS * (t - t0) < tc)) {
                const double tm = 0.5 * (t0 + t);
                if (!ymid || tm != tmid) {
                    tmid = tm;
                    if (interp(ctx, tm, &ymid) != 0) ymid = NULL;
                }
                if (ymid) {
                    rc_inter_report rm;
                    report(m, d, i, tm, ymid, &rm);
                    update(row, &rm, closed, tm);
                    const double fm = rm.fn > 0 ? rm.fn : 0.0;
                    if (fm > f0 && fm > f1) {
                        const double dab = (fm - f0) / (tm - t0), dbc = (f1 - fm) / (t - tm),
                                     dabc = (dbc - dab) / (t - t0);
                        const double ts = dabc < 0.0 ? 0.5 * (t0 + tm) - dab / (2.0 * dabc) : tm;
                        refine_force(im, m, d, i, ts > t0 && ts < t ? ts : tm, t0, t, interp, ctx);
                        h->tpk = t;
                        ymid = NULL; /* the scratch holds other times now */
                    }
                }
            }
            /* the force rose to the last sample and falls now: its maximum
             * is near the vertex of the parabola through the last three */
            if (closed && h->n == 2 && h->fn[1] >= h->fn[0] && h->fn[1] > f1 && h->t[1] > h->t[0]) {
                const double ta = h->t[0], tb = h->t[1], fa = h->fn[0], fb = h->fn[1];
                const double dab = (fb - fa) / (tb - ta), dbc = (f1 - fb) / (t - tb), dabc = (dbc - dab) / (t - ta);
                if (dabc < 0.0) {
                    const double ts = 0.5 * (ta + tb) - dab / (2.0 * dabc);
                    if (ts > from && ts < t) {
                        refine(im, m, d, i, ts, interp, ctx);
                    } else if (ts > ta && ts < t && !(ts < h->tpk)) {
                        /* in the previous step, which the interpolant no
                         * longer covers: the parabola's value */
                        const double fv = fa + dab * (ts - ta) + dabc * (ts - ta) * (ts - tb);
                        if (isfinite(fv) && fv > row->fn_max) {
                            row->fn_max = fv;
                            row->t_fn_max = ts;
                        }
                    }
                }
            }
        }
        hist_push(h, t, &r, closed);
    }
}

double rc_impacts_contact_time(const rc_model *m, int i)
{
    const double p = m->inter_pscale[i], v = m->inter_vscale[i];
    return isfinite(p) && isfinite(v) && p > 0 && v > 0 ? RC_PI * p / v : NAN;
}

int rc_impacts_is_impact(int start, double v_in, double duration, double tc)
{
    if (start || !(v_in > 0.0)) return 0;
    return !(isfinite(tc) && duration > RC_IMPACT_SPAN * tc);
}

void rc_impacts_finish(rc_impacts *im, const rc_model *m, double t_end)
{
    for (int i = 0; i < im->ninter; i++) {
        const int k = im->cur[i];
        if (k < 0) continue;
        /* still in contact at the end: no open time unless released */
        rc_impact *w = &im->row[k];
        w->duration = w->t_open - w->t_close;
        im->cur[i] = -1;
    }
    /* impacts stay in row (in order), persistent contacts go to pc */
    free(im->pc);
    im->pc = im->n > 0 ? malloc((size_t)im->n * sizeof *im->pc) : NULL;
    im->npc = 0;
    int ni = 0;
    for (int k = 0; k < im->n; k++) {
        const rc_impact w = im->row[k];
        int i = -1;
        for (int j = 0; j < m->ninter && i < 0; j++)
            if (m->inter_id[j] == w.inter_id) i = j;
        const double tc = i >= 0 ? rc_impacts_contact_time(m, i) : NAN;
        /* to the opening, or (still closed) to the end of the run */
        const double dur = isfinite(w.t_open) ? w.t_open - w.t_close : t_end - w.t_close;
        if (rc_impacts_is_impact(im->acc[k].start, w.v_in, dur, tc) || !im->pc) {
            im->acc[ni] = im->acc[k];
            im->row[ni++] = w;
            continue;
        }
        im->pc[im->npc++] = (rc_contact){w.inter_id, w.t_close,     w.t_open, dur, w.fn_max,
                                         dur > 0 ? im->acc[k].fint / dur : (w.fn_max > 0 ? w.fn_max : 0.0),
                                         w.pen_max, im->acc[k].slip};
    }
    im->n = ni;
}

void rc_impacts_sampling_note(const rc_model *m, char *buf, size_t n)
{
    buf[0] = '\0';
    double tc = INFINITY;
    int worst = -1;
    for (int i = 0; i < m->ninter; i++) {
        const double p = m->inter_pscale[i], v = m->inter_vscale[i];
        if (!(isfinite(p) && isfinite(v) && p > 0 && v > 0)) continue;
        const double c = RC_PI * p / v; /* half period of the linearised contact */
        if (c < tc) {
            tc = c;
            worst = i;
        }
    }
    if (worst < 0 || !(m->dtout > 0) || tc / m->dtout >= RC_IMPACT_MIN_RECORDS) return;
    snprintf(buf, n,
             "output interval %.3g s samples a contact of ~%.2g s (%s) with ~%.0f records; peak values are in "
             "the impact and persistent contact tables",
             m->dtout, tc, m->inter_name[worst], floor(tc / m->dtout));
}

double rc_contact_record_interval(const rc_model *m, double dtout)
{
    double tc = INFINITY;
    for (int i = 0; i < m->ninter; i++) {
        const double p = m->inter_pscale[i], v = m->inter_vscale[i];
        if (isfinite(p) && isfinite(v) && p > 0 && v > 0) tc = fmin(tc, RC_PI * p / v);
    }
    const double dt = tc / RC_CONTACT_RECORDS;
    return isfinite(dt) && dt < dtout ? dt : 0.0;
}

/* The period [s] of the undamped normal vibration of interface i's closed
 * contact: 2 pi sqrt(m / k), m the reduced mass of its free bodies, k its
 * stiffness scale or, for TYPE6 Iform 1 and 2, its Stiff line, the
 * steeper; NaN when it is damped or has no scale. */
static double vib_period(const rc_model *m, int i)
{
    if (!rc_inter_undamped(m, i)) return NAN;
    const double k = rc_inter_k_stiff(m, i);
    const int ba = m->inter_ba[i], bb = m->inter_bb[i];
    const double ma = ba >= 0 && m->body_yadr[ba] >= 0 ? m->body_mass[ba] : INFINITY;
    const double mb = bb >= 0 && m->body_yadr[bb] >= 0 ? m->body_mass[bb] : INFINITY;
    const double mr = isfinite(ma) && isfinite(mb) ? ma * mb / (ma + mb) : fmin(ma, mb);
    if (!(k > 0) || !isfinite(k) || !(mr > 0) || !isfinite(mr)) return NAN;
    return 2.0 * RC_PI * sqrt(mr / k);
}

void rc_impacts_max_steps_hint(const rc_impacts *im, const rc_model *m, double t, double dt_out, double t_left,
                               char *buf, size_t n)
{
    buf[0] = '\0';
    int best = -1;
    double tb = INFINITY;
    for (int i = 0; i < m->ninter; i++) {
        const double T = vib_period(m, i);
        if (!(T < tb)) continue;
        /* closed now, or at some time of the last output interval (a
         * contact that grazes open once a period) */
        int closed = im->cur[i] >= 0;
        for (int k = im->n - 1; k >= 0 && !closed; k--)
            closed = im->row[k].inter_id == m->inter_id[i] && !(im->row[k].t_open < t - dt_out);
        if (closed) {
            tb = T;
            best = i;
        }
    }
    if (best < 0) return;
    /* its event instants in an output interval at the run's rate so far
     * (its friction's stick and slip as the force rings), each a restart */
    const double ne = t > 0 ? (double)im->nevt[best] * dt_out / t : 0.0;
    const double np = dt_out / tb, need = RC_VIB_STEPS_PER_PERIOD * np + RC_VIB_STEPS_PER_EVENT * ne;
    if (need < 0.5 * (double)m->max_steps) return;
    char evs[200] = "", per[40] = "";
    if (RC_VIB_STEPS_PER_EVENT * ne >= 0.5 * RC_VIB_STEPS_PER_PERIOD * np) {
        snprintf(evs, sizeof evs, " and %.3g event instants of its own (its friction's stick and slip, each a restart)",
                 ne);
        snprintf(per, sizeof per, " and %d an event", RC_VIB_STEPS_PER_EVENT);
    }
    snprintf(buf, n,
             "; the contact %s vibrates undamped (period %.3g s: %.3g periods in an output interval of %.3g s%s, "
             "about %.3g steps at %d a period%s, against Max_steps %ld) and without damping the vibrations never die "
             "out: give it a normal damping (TYPE6 Visc or a restitution, the power law's C) so that they settle, or "
             "raise /SOLVER Max_steps and follow the %.3g periods to the end time (docs/theory.md 7.10)",
             m->inter_name[best], tb, np, dt_out, evs, need, RC_VIB_STEPS_PER_PERIOD, per, (long)m->max_steps,
             t_left / tb);
}

/* Periods of the fastest undamped vibration closed at each time, over the
 * run: the integral of max_i 1/T_i over the persistent contacts' closed
 * intervals (one step serves every contact ringing at once: a chain of
 * seven balls on a floor, its twelve contacts closed together, took the
 * steps of its fastest one, not of the sum). The contacts in order of
 * frequency, each contributing where no faster one is closed. Scratch:
 * pf (npc) each contact's frequency, cov (2 npc) the union covered so
 * far, as sorted disjoint intervals. */
static double fastest_periods(const rc_impacts *im, const rc_model *m, double *pf, double *cov)
{
    for (int c = 0; c < im->npc; c++) {
        const rc_contact *pc = &im->pc[c];
        pf[c] = 0.0; /* damped, unscaled or of no duration: none */
        for (int i = 0; i < m->ninter && isfinite(pc->duration) && pc->duration > 0; i++)
            if (m->inter_id[i] == pc->inter_id) {
                const double T = vib_period(m, i);
                if (T > 0 && isfinite(T)) pf[c] = 1.0 / T;
                break;
            }
    }
    int ncov = 0;
    double total = 0.0, above = INFINITY; /* the frequencies done are above this */
    for (;;) {
        double f = 0.0; /* the next frequency down */
        for (int c = 0; c < im->npc; c++)
            if (pf[c] > f && pf[c] < above) f = pf[c];
        if (!(f > 0)) break;
        for (int c = 0; c < im->npc; c++) {
            if (pf[c] != f) continue;
            const double a0 = im->pc[c].t_close, b0 = a0 + im->pc[c].duration;
            /* the part of [a0, b0] outside cov, then [a0, b0] merged into it */
            double open = b0 - a0, a = a0, b = b0;
            int lo = 0;
            while (lo < ncov && cov[2 * lo + 1] < a0) lo++;
            int hi = lo;
            while (hi < ncov && cov[2 * hi] <= b0) {
                open -= fmin(b0, cov[2 * hi + 1]) - fmax(a0, cov[2 * hi]);
                a = fmin(a, cov[2 * hi]);
                b = fmax(b, cov[2 * hi + 1]);
                hi++;
            }
            total += f * open;
            memmove(cov + 2 * (lo + 1), cov + 2 * hi, 2 * (size_t)(ncov - hi) * sizeof(double));
            ncov += 1 - (hi - lo);
            cov[2 * lo] = a;
            cov[2 * lo + 1] = b;
        }
        above = f;
    }
    return total;
}

void rc_impacts_vibration_note(const rc_impacts *im, const rc_model *m, long steps, char *buf, size_t n)
{
    buf[0] = '\0';
    if (steps < RC_VIB_NOTE_STEPS || im->npc == 0) return;
    double *scratch = malloc(3 * (size_t)im->npc * sizeof(double));
    if (!scratch) return;
    /* steps the vibrations account for: their periods, and the restarts
     * at the events of the contacts that vibrate (their friction's stick
     * and slip, their bounces: driven by the vibrations, which never die
     * out) */
    const double periods = fastest_periods(im, m, scratch, scratch + im->npc);
    free(scratch);
    long nev = 0, nimp = 0;
    for (int i = 0; i < m->ninter; i++) {
        if (!isfinite(vib_period(m, i))) continue;
        nev += im->nevt[i];
        for (int k = 0; k < im->n; k++) nimp += im->row[k].inter_id == m->inter_id[i]; /* its bounces */
    }
    const double total = RC_VIB_STEPS_PER_PERIOD * periods + RC_VIB_STEPS_PER_EVENT * (double)nev +
                         RC_VIB_STEPS_PER_IMPACT * (double)nimp;
    /* the three interfaces with the most periods, most first */
    struct {
        int i;
        double periods, closed, period;
    } best[3] = {{-1, 0, 0, 0}, {-1, 0, 0, 0}, {-1, 0, 0, 0}};
    for (int i = 0; i < m->ninter; i++) {
        const double T = vib_period(m, i);
        if (!isfinite(T)) continue;
        double d = 0.0;
        for (int c = 0; c < im->npc; c++)
            if (im->pc[c].inter_id == m->inter_id[i] && isfinite(im->pc[c].duration)) d += im->pc[c].duration;
        if (!(d > 0)) continue;
        const double np = d / T;
        int r = 0;
        while (r < 3 && best[r].i >= 0 && best[r].periods >= np) r++;
        if (r == 3) continue;
        memmove(best + r + 1, best + r, (size_t)(2 - r) * sizeof best[0]);
        best[r].i = i;
        best[r].periods = np;
        best[r].closed = d;
        best[r].period = T;
    }
    /* the vibrations account for the steps at 0.5 to 4 RC_VIB_STEPS_PER_PERIOD
     * a period (BDF at rtol 1e-8 took 66 on a ball resting on its Stiff line);
     * fewer than 15 a period: the run does not follow them (they do not
     * ring: friction or a lighter load holds them), and its steps went
     * elsewhere */
    if (best[0].i < 0 || 4.0 * total < (double)steps || (double)steps < 0.5 * total) return;
    size_t l;
    if (RC_VIB_STEPS_PER_EVENT * (double)nev + RC_VIB_STEPS_PER_IMPACT * (double)nimp <
        0.5 * RC_VIB_STEPS_PER_PERIOD * periods)
        l = (size_t)snprintf(buf, n,
                             "%ld steps, about %.0f a period of undamped contact vibrations, which they mostly "
                             "followed: ",
                             steps, (double)steps * RC_VIB_STEPS_PER_PERIOD / total);
    else /* the events' restarts cost as much as the periods, or more */
        l = (size_t)snprintf(buf, n,
                             "%ld steps: %.3g periods of undamped contact vibrations (~%.0f steps each), %ld "
                             "impacts (~%.0f each) and %ld event instants (stick, slip, bounces; ~%.0f each, a "
                             "restart) of those contacts: ",
                             steps, periods, (double)steps * RC_VIB_STEPS_PER_PERIOD / total, nimp,
                             (double)steps * RC_VIB_STEPS_PER_IMPACT / total, nev,
                             (double)steps * RC_VIB_STEPS_PER_EVENT / total);
    /* the interfaces, as many as leave room for the advice (the whole, or
     * its short form) */
    static const char advice[] = "; the integrator follows each period to the tolerances and without damping they "
                                 "never die out: a normal damping (TYPE6 Visc or a restitution, the power law's C) "
                                 "lets them settle";
    static const char brief[] = "; a normal damping lets them settle";
    for (int r = 0; r < 3 && best[r].i >= 0 && l < n; r++) {
        char one[200];
        const int w = snprintf(one, sizeof one, "%s%s closed %.3g s, period %.3g s (%.3g periods)", r ? "; " : "",
                               m->inter_name[best[r].i], best[r].closed, best[r].period, best[r].periods);
        if (r > 0 && l + (size_t)w + sizeof brief > n) break;
        l += (size_t)snprintf(buf + l, n - l, "%s", one);
    }
    if (l < n) snprintf(buf + l, n - l, "%s", l + sizeof advice <= n ? advice : brief);
}
