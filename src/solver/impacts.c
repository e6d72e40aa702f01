/* Impacts table of a run (impacts.h). */
#include "solver/impacts.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* pi [-] (M_PI is not in C11) */
#define RC_PI 3.14159265358979323846

int rc_impacts_init(rc_impacts *im, const rc_model *m)
{
    memset(im, 0, sizeof *im);
    im->ninter = m->ninter;
    im->cur = malloc(((size_t)m->ninter + 1) * sizeof *im->cur);
    im->e0 = calloc((size_t)m->ninter + 1, sizeof *im->e0);
    if (!im->cur || !im->e0) return -1;
    for (int i = 0; i < m->ninter; i++) im->cur[i] = -1;
    return 0;
}

void rc_impacts_free(rc_impacts *im)
{
    free(im->cur);
    free(im->e0);
    free(im->row);
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

void rc_impacts_event(rc_impacts *im, const rc_model *m, const rc_data *d, int i, const char *kind, double t,
                      const double *y)
{
    if (i < 0 || i >= im->ninter || !kind) return;
    int k = im->cur[i];
    if (!strcmp(kind, "contact_close")) {
        rc_inter_report r;
        report(m, d, i, t, y, &r);
        if (k < 0) {
            if (im->n == im->cap) {
                const int cap = im->cap ? 2 * im->cap : 16;
                rc_impact *p = realloc(im->row, (size_t)cap * sizeof *p);
                if (!p) return; /* the table misses this impact */
                im->row = p;
                im->cap = cap;
            }
            k = im->cur[i] = im->n++;
            rc_impact *w = &im->row[k];
            *w = (rc_impact){m->inter_id[i], t, NAN, NAN, r.p, t, 0.0, t, r.vn, NAN, NAN, NAN};
            im->e0[i] = dissipated(m, d, t, y);
        } else {
            im->row[k].t_open = NAN; /* the force acts again */
        }
        update(&im->row[k], &r, d->inter_mode[i] == RC_MODE_CLOSED, t);
        return;
    }
    if (k < 0) return;
    rc_impact *w = &im->row[k];
    if (!strcmp(kind, "contact_open")) {
        w->t_open = t; /* released: the force stopped (until it closes again) */
    } else if (!strcmp(kind, "contact_separate") || !strcmp(kind, "inter_stop")) {
        rc_inter_report r;
        report(m, d, i, t, y, &r);
        if (isnan(w->t_open)) w->t_open = t;
        w->duration = w->t_open - w->t_close;
        if (!strcmp(kind, "contact_separate")) {
            w->v_out = -r.vn;
            w->restitution = w->v_in > 0 ? w->v_out / w->v_in : NAN;
        }
        w->energy_lost = dissipated(m, d, t, y) - im->e0[i];
        im->cur[i] = -1;
    }
}

int rc_impacts_active(const rc_impacts *im)
{
    for (int i = 0; i < im->ninter; i++)
        if (im->cur[i] >= 0) return 1;
    return 0;
}

void rc_impacts_sample(rc_impacts *im, const rc_model *m, const rc_data *d, double t, const double *y)
{
    for (int i = 0; i < im->ninter; i++) {
        if (im->cur[i] < 0) continue;
        rc_inter_report r;
        report(m, d, i, t, y, &r);
        update(&im->row[im->cur[i]], &r, d->inter_mode[i] == RC_MODE_CLOSED, t);
    }
}

void rc_impacts_finish(rc_impacts *im)
{
    for (int i = 0; i < im->ninter; i++) {
        const int k = im->cur[i];
        if (k < 0) continue;
        /* still in contact at the end: no open time unless released */
        rc_impact *w = &im->row[k];
        w->duration = w->t_open - w->t_close;
        im->cur[i] = -1;
    }
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
             "the impact table",
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
