/*
 * The integration driver shared by the backends (integrator.h): the loop
 * over output times and events that cvode.c and ida.c run through their
 * rc_backend tables, and the helpers it needs (records, the events' sink,
 * breakpoints, root directions, touching contacts, the results file,
 * progress). No SUNDIALS call is made here: every integrator operation goes
 * through the backend.
 *
 * Loop: integrate to the next output time (single steps while an impact is
 * in progress, or when the backend asks for them); at a time breakpoint,
 * restart; at a root, flip the modes (engine/events/events.c), write the
 * events, act on the engine's verdict on settling and event accumulation
 * (engine/events/settle.c), write a record, and restart the integrator when
 * the modes' change calls for it (the backend decides,
 * rc_backend.after_events).
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "base/error.h"
#include "engine/events/events.h"
#include "engine/events/settle.h"
#include "model/coupling.h"
#include "model/coupling_contact.h"
#include "model/imposed.h"
#include "model/joint.h"
#include "model/model.h"
#include "model/power.h"
#include "model/sensor.h"
#include "output/output.h"
#include "solver/guards.h"
#include "solver/impacts.h"
#include "solver/integrator.h"
#include "solver/solver.h"
#include "engine/analyses/analyses.h"
#include "engine/assembly/assembly.h"
#include "engine/constraints/joints.h"
#include "engine/reports/reports.h"

/* ---- helpers ----------------------------------------------------------- */
static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Time breakpoints: instants where the right-hand side, or its rate, jumps
 * by time alone (the start and the end of an imposed velocity, /IMPVEL
 * Tstart > 0 or its sensor's time, and Tstop; the start of a gravity by its
 * sensor, /GRAV sensor_ID; the knots of the time functions of the gravity
 * and of the imposed velocities, where the piecewise linear load turns:
 * an imposed velocity's acceleration jumps there, the gravity's rate does),
 * inside (0, tend), sorted, distinct. The integrator is stopped exactly
 * there (its stop time) and restarted: a step straddling a knot lets its
 * interpolant carry the load's turn to both sides (a ball resting on a
 * penalty contact recorded 3.6e-6 m g off its load at the knot itself).
 * The knots of a function started by a sensor found in the run are not
 * known before it: not among them. Returns the count; *bp is allocated
 * (free it). */
static int add_knots(const rc_table *tb, double shift, double scale, double lo, double hi, double tend, double *bp,
                     int n)
{
    for (int k = 0; k < tb->n; k++) {
        const double t = shift + tb->x[k] * scale;
        if (t > 0 && t < tend && t > lo && t < hi) bp[n++] = t;
    }
    return n;
}

int rc_bk_time_breakpoints(const rc_model *m, double tend, double **bp)
{
    const rc_imposed *p = m->imp;
    size_t cap = (p ? 2 * (size_t)p->nt + (size_t)p->nr : 0) + 1;
    if (m->grav_table >= 0 && m->grav_sens < 0) cap += (size_t)m->table[m->grav_table].n;
    for (int k = 0; p && k < p->nt; k++)
        if (p->ttab[k] >= 0 && p->tson[k] < 0) cap += (size_t)m->table[p->ttab[k]].n;
    for (int k = 0; p && k < 3 * p->nr; k++)
        if (p->rtab[k] >= 0) cap += (size_t)m->table[p->rtab[k]].n;
    *bp = malloc((cap + 1) * sizeof(double));
    if (!*bp) return -1;
    int n = 0;
    for (int k = 0; p && k < p->nt + p->nr; k++) {
        double ts = k < p->nt ? p->ttstop[k] : p->rtstop[k - p->nt];
        if (ts > 0 && ts < tend) (*bp)[n++] = ts;
        if (k < p->nt && p->ttstart[k] > 0 && p->ttstart[k] < tend && p->ttstart[k] <= p->ttstop[k])
            (*bp)[n++] = p->ttstart[k];
    }
    /* gravity switched on by a sensor (/GRAV sensor_ID): it jumps there */
    if (m->grav_tstart > 0 && m->grav_tstart < tend) (*bp)[n++] = m->grav_tstart;
    /* the knots of the load functions */
    if (m->grav_table >= 0 && m->grav_sens < 0)
        n = add_knots(&m->table[m->grav_table], m->grav_tstart, m->grav_ascale, m->grav_tstart, INFINITY, tend, *bp, n);
    for (int k = 0; p && k < p->nt; k++)
        if (p->ttab[k] >= 0 && p->tson[k] < 0)
            n = add_knots(&m->table[p->ttab[k]], p->ttshift[k], p->tascale[k], p->ttstart[k], p->ttstop[k], tend, *bp, n);
    for (int k = 0; p && k < 3 * p->nr; k++)
        if (p->rtab[k] >= 0) n = add_knots(&m->table[p->rtab[k]], 0.0, p->rascale[k], 0.0, p->rtstop[k / 3], tend, *bp, n);
    qsort(*bp, (size_t)n, sizeof(double), cmp_double);
    int u = 0;
    for (int k = 0; k < n; k++)
        if (u == 0 || (*bp)[k] > (*bp)[u - 1]) (*bp)[u++] = (*bp)[k];
    return u;
}

/* Only the crossing that changes a mode is a root (docs/theory.md 5). */
void rc_bk_root_directions(const rc_model *m, const rc_data *d, int *dir)
{
    for (int i = 0; i < m->ninter; i++) {
        int *r = dir + RC_ROOTS_PER_INTER * i;
        const int mode = d->inter_mode[i], br = d->inter_branch[i];
        r[RC_ROOT_TSTART] = 1;
        r[RC_ROOT_TSTOP] = 1;
        r[RC_ROOT_ZONE] = mode == RC_MODE_OPEN ? 1 : -1;         /* enter / leave */
        r[RC_ROOT_FORCE] = mode == RC_MODE_RELEASED ? 1 : -1;    /* re-close / release */
        r[RC_ROOT_HYST_A] = br == RC_BR_UNLOAD ? 1 : -1;          /* reversal, or F_h meets F_L */
        r[RC_ROOT_HYST_B] = -1;                                   /* F_h meets F_U */
        r[RC_ROOT_TRK_A] = 1;                                     /* bodies approach again */
        r[RC_ROOT_TRK_B] = -1;                                    /* offset used up */
        r[RC_ROOT_SLIP] = 1;                                      /* limit reached / sliding stops */
        r[RC_ROOT_REV] = -1;                                      /* saturated sliding reverses */
    }
    for (int j = 0; j < m->npt; j++) {
        dir[rc_root_point_base(m) + j] = 1; /* points: as RC_ROOT_SLIP */
        dir[rc_root_land_base(m) + j] = 1;  /* a point lands (its share rises from 0) */
    }
    if (rc_cpl_nroots(m) > 0) rc_cpl_root_dirs(m, d, dir + rc_root_cpl_base(m));
    for (int k = 0; k < 2 * m->nsens; k++) dir[rc_root_sens_base(m) + k] = 1; /* a sensor triggers */
}

/* The distance and interface sensors triggered since the last call: their
 * events (element /SENSOR/DIST/id, /SENSOR/INTER/id; no interface values); the bodies released by
 * a sensor found in the run: an impvel_stop event each (element
 * /RBODY/id: its hold ends); the imposed velocities started by one: an
 * impvel_start event each (element /RBODY/id); then cleared. */
static rc_status sensor_events(const rc_model *m, rc_data *d, ev_sink *k, double t, const double *y, long *count,
                               rc_error *err)
{
    for (int s = 0; s < m->nsens; s++) {
        const int nw = d->sens_new[s];
        if (!nw) continue;
        d->sens_new[s] = 0;
        char el[48];
        rc_status st = RC_OK;
        if (nw & 1) {
            snprintf(el, sizeof el, "/SENSOR/%s/%d", rc_sensor_kind_name(m->sens_kind[s]), m->sens_id[s]);
            (*count)++;
            if ((st = rc_bk_sink_event(k, t, RC_EV_SENSOR_TRIGGER, el, NULL, err))) return st;
        }
        for (int j = 0; (nw & 2) && m->imp && j < m->imp->nt; j++) {
            if (m->imp->tsens[j] != s || m->imp->tdir[j] != 0) continue; /* one per body: its X row */
            snprintf(el, sizeof el, "/RBODY/%d", m->body_id[m->imp->tbody[j]]);
            (*count)++;
            if ((st = rc_bk_sink_event(k, t, RC_EV_IMPVEL_STOP, el, NULL, err))) return st;
        }
        /* the imposed velocities it starts (/IMPVEL sensor_ID): one event
         * per started translation (element /RBODY/id) */
        for (int j = 0; (nw & 2) && m->imp && j < m->imp->nt; j++) {
            if (m->imp->tson[j] != s || t > m->imp->ttstop[j]) continue;
            snprintf(el, sizeof el, "/RBODY/%d", m->body_id[m->imp->tbody[j]]);
            (*count)++;
            if ((st = rc_bk_sink_event(k, t, RC_EV_IMPVEL_START, el, NULL, err))) return st;
        }
    }
    return RC_OK;
}

/* A change of the backend's integration method (rc_backend.switched):
 * its event (element /SOLVER; no interface values) and its count. */
static rc_status method_event(const rc_backend *bk, void *self, ev_sink *k, rc_stats *s, rc_error *err)
{
    double ts = 0.0;
    const rc_event_kind ek = bk->switched ? bk->switched(self, &ts) : RC_EV_NONE;
    if (ek == RC_EV_NONE) return RC_OK;
    if (ek == RC_EV_METHOD_EXPLICIT) s->switches_explicit++;
    else s->switches_implicit++;
    return rc_bk_sink_event(k, ts, ek, "/SOLVER", NULL, err);
}

static rc_status settled(const rc_model *m, const rc_data *d, ev_sink *sink, double t, const double *y,
                         const rc_event *ev, rc_stats *s, int show, rc_error *err);

/* After a restart at t: when the restart moved the state from ypre (IDA's
 * projection onto the constraints the events switched on: a settled
 * contact's approach velocity removed at once; the velocity an imposed
 * velocity jumps to) or `moved` says the right-hand side jumped there (a
 * breakpoint: gravity or an imposed velocity starting or ending), the
 * contacts' modes are decided again by the state, as after an event
 * (rc_bk_resolve_touching), with a further restart when they change: the
 * jump may have carried a contact past the root its mode waits on (a ball
 * settling on a ramp on IDA: the projection turned the wall's released law
 * from unloading to reloading, its root started past zero, and the ball
 * passed 3 mm through the wall at zero force). Adds the events to *nev. */
static rc_status modes_after_restart(const rc_backend *bk, void *self, const rc_model *m, rc_data *d, double t,
                                     double *y, double *ypre, double *flook, ev_sink *sink, rc_impacts *im,
                                     rc_settle *hist, int *rootdir, int nr, rc_stats *s, int show, int moved,
                                     int *nev, rc_error *err)
{
    rc_status st = RC_OK;
    for (int pass = 0; pass < 2 && (moved || memcmp(ypre, y, (size_t)m->ny * sizeof(double))); pass++) {
        moved = 0;
        int jmp = 0;
        const int ne = rc_bk_resolve_touching(m, d, t, y, flook, sink, im, hist, s, show, &jmp, &st, err);
        if (st) return st;
        if (ne == 0 && !jmp) break;
        *nev += ne;
        if (nr > 0) {
            rc_bk_root_directions(m, d, rootdir);
            const int f = bk->set_root_dirs(self, rootdir);
            if (f < 0) return RC_SET(err, RC_ESOLVER, "%s call SetRootDirection failed at t = %.9g s", bk->name, t);
        }
        memcpy(ypre, y, (size_t)m->ny * sizeof(double));
        bk->add_stats(self, s);
        const int f = bk->restart(self, t, 0);
        if (f < 0) return RC_SET(err, RC_ESOLVER, "%s call ReInit failed at t = %.9g s", bk->name, t);
        s->reinits++;
    }
    return st;
}

/* One event to the sink; RC_OK or the output's error. */
rc_status rc_bk_sink_event(ev_sink *k, double t, rc_event_kind ek, const char *element, const double v[3],
                            rc_error *err)
{
    rc_status st = RC_OK;
    const char *kind = rc_event_kind_name(ek);
    if (k->out) st = v ? rc_output_event_values(k->out, t, kind, element, v, err) : rc_output_event(k->out, t, kind, element, err);
    if (!st && k->fn && !k->stop) {
        const double none[3] = {NAN, NAN, NAN}; /* not an interface, as in the file */
        if (k->fn(k->user, t, kind, element, v ? v : none)) {
            k->stop = 1;
            snprintf(k->why, sizeof k->why, "stopped by the event callback at t = %.9g s (%s %s)", t, kind, element);
        }
    }
    return st;
}

/* Append event `ev` at (t, y) to the events table with its interface's
 * penetration P [m], approach speed dP/dt [m/s] and normal force [N], in the
 * mode after the event. */
rc_status rc_bk_write_event(const rc_model *m, const rc_data *d, ev_sink *o, double t, const double *y,
                             const rc_event *ev, rc_error *err)
{
    const int i = ev->inter;
    if (i < 0) return rc_bk_sink_event(o, t, ev->kind, m->cpl->name[-1 - i], NULL, err); /* a coupling */
    rc_inter_report r;
    rc_inter_report_eval_d(m, d, i, t, y, &r);
    const double v[3] = {r.p, r.vn, d->inter_mode[i] == RC_MODE_CLOSED && r.fn > 0 ? r.fn : 0.0};
    rc_guards_event(o->guards, d, i, ev->kind, t); /* the contact's history */
    return rc_bk_sink_event(o, t, ev->kind, m->inter_name[i], v, err);
}

/* Contacts at zero penetration or zero force, decided by the state after
 * the start and after every event (events.c, rc_modes_touch): the rate of
 * the state in the current modes is computed first, for the force rates.
 * Writes the events; returns their number (*jumped is set when history
 * states were reset). */
int rc_bk_resolve_touching(const rc_model *m, rc_data *d, double t, double *y, double *f, ev_sink *out,
                            rc_impacts *im, rc_settle *hist, rc_stats *s, int show, int *jumped, rc_status *st,
                            rc_error *err)
{
    int total = 0;
    *st = RC_OK;
    if (m->ninter == 0) return 0;
    /* a touching contact closed at zero force changes no rate, so one more
     * round settles what the first one enabled */
    for (int round = 0; round < 2; round++) {
        if (rc_assemble_rhs(m, d, t, y, f)) break;
        rc_event ev[RC_MAX_EV];
        int jmp = 0, nev = rc_modes_touch(m, d, t, y, f, ev, RC_MAX_EV, &jmp);
        *jumped |= jmp;
        total += nev;
        s->events += nev;
        for (int k = 0; k < nev && k < RC_MAX_EV; k++) rc_impacts_event(im, m, d, ev[k].inter, ev[k].kind, t, y);
        rc_settle_lowq(hist, m, d, t, ev, nev < RC_MAX_EV ? nev : RC_MAX_EV);
        /* the interface sensors of the contacts closed here (events.c) */
        if (m->nsens > 0 && (*st = sensor_events(m, d, out, t, y, &s->events, err))) return total;
        for (int k = 0; k < nev && k < RC_MAX_EV; k++)
            if ((*st = rc_bk_write_event(m, d, out, t, y, &ev[k], err))) return total;
        /* the same contacts' history and settling rule as a root's events:
         * a close the touch pass decides is a close (the same fall of a
         * cradle's ball, closed by a root in one unit system and by this
         * pass after another root in the other, settled in one only) */
        rc_event sev[RC_MAX_EV];
        int nsev = 0;
        rc_settle_contacts(hist, m, d, t, y, f, ev, nev < RC_MAX_EV ? nev : RC_MAX_EV, sev, RC_MAX_EV, &nsev,
                           jumped);
        for (int k = 0; k < nsev && k < RC_MAX_EV; k++)
            if ((*st = settled(m, d, out, t, y, &sev[k], s, show, err))) return total;
        if (nev == 0) break;
    }
    return total;
}

/* A root function exactly zero at the event state (flat to rounding, e.g. a
 * penetration of two slowly separating bodies) makes the integrator stop with "close
 * roots" on the next call; after a restart it instead deactivates it until
 * it moves away from zero. */
int rc_bk_root_on_zero(const rc_model *m, const rc_data *d, double t, const double *y, double *g)
{
    rc_assemble_roots(m, d, t, y, g);
    for (int k = 0; k < rc_root_count(m); k++)
        if (g[k] == 0.0) return 1;
    return 0;
}

/* The first step after a restart (docs/theory.md 7.7): the last accepted
 * step h_last, bounded by rtol / omega_s over the contacts with scales
 * (omega_s = v_s / p_s their frequency: the first step moves a contact's
 * state by rtol of its scales), and not below 100 ulps of t (CVODE's own
 * lower bound on its estimate). 0 (the integrator's own estimate) when
 * neither is known. */
double rc_bk_restart_step(const rc_model *m, double t, double h_last)
{
    double h = h_last > 0 && isfinite(h_last) ? h_last : INFINITY;
    const double frac = m->rtol; /* h omega_s = rtol */
    for (int i = 0; i < m->ninter; i++) {
        const double p = m->inter_pscale[i], v = m->inter_vscale[i];
        if (isfinite(p) && isfinite(v) && p > 0 && v > 0) h = fmin(h, frac * p / v);
    }
    if (!isfinite(h)) return 0.0;
    return fmax(h, 100.0 * DBL_EPSILON * fabs(t));
}

double rc_bk_wall_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void rc_bk_frame_free(frame_buf *f)
{
    void *p[] = {f->pos, f->quat, f->vel, f->omega, f->pen, f->fload, f->fdamp, f->fn, f->point, f->normal, f->mode,
                 f->cpl, f->ffric, f->vslip, f->flim, f->fmu, f->slip, f->jnt};
    for (size_t k = 0; k < sizeof p / sizeof p[0]; k++) free(p[k]);
}

int rc_bk_frame_alloc(const rc_model *m, frame_buf *f)
{
    memset(f, 0, sizeof *f);
    size_t nb = (size_t)m->nbody + 1, ni = (size_t)m->ninter + 1;
    f->pos = malloc(3 * nb * sizeof(double));
    f->quat = malloc(4 * nb * sizeof(double));
    f->vel = malloc(3 * nb * sizeof(double));
    f->omega = malloc(3 * nb * sizeof(double));
    f->pen = malloc(ni * sizeof(double));
    f->fload = malloc(ni * sizeof(double));
    f->fdamp = malloc(ni * sizeof(double));
    f->fn = malloc(ni * sizeof(double));
    f->point = malloc(3 * ni * sizeof(double));
    f->normal = malloc(3 * ni * sizeof(double));
    f->mode = malloc(ni * sizeof(int));
    f->ffric = malloc(3 * ni * sizeof(double));
    f->vslip = malloc(ni * sizeof(double));
    f->flim = malloc(ni * sizeof(double));
    f->fmu = malloc(ni * sizeof(double));
    f->slip = malloc(ni * sizeof(int));
    f->cpl = malloc((9 * (size_t)m->cpl->n + 1) * sizeof(double));
    f->jnt = malloc((10 * (size_t)(m->jnt ? m->jnt->n : 0) + 10) * sizeof(double));
    return f->jnt && f->pos && f->quat && f->vel && f->omega && f->pen && f->fload && f->fdamp && f->fn && f->point &&
           f->normal && f->mode && f->cpl && f->ffric && f->vslip && f->flim && f->fmu && f->slip;
}

/* Fill and write one record at (t, y). */
rc_status rc_bk_write_frame(const rc_model *m, const rc_data *d, rc_output *o, frame_buf *f, double t,
                             const double *y, int at_event, rc_error *err)
{
    for (int b = 0; b < m->nbody; b++) {
        const double *s = rc_body_state(m, b, y);
        for (int k = 0; k < 3; k++) f->pos[3 * b + k] = s[k] + m->origin[k]; /* the deck's coordinates */
        memcpy(f->quat + 4 * b, s + 3, 4 * sizeof(double));
        memcpy(f->vel + 3 * b, s + 7, 3 * sizeof(double));
        memcpy(f->omega + 3 * b, s + 10, 3 * sizeof(double));
    }
    for (int i = 0; i < m->ninter; i++) {
        rc_inter_report r;
        int mode = d->inter_mode[i];
        rc_inter_report_eval_d(m, d, i, t, y, &r);
        const int acts = mode == RC_MODE_CLOSED;
        f->pen[i] = r.p;
        f->fload[i] = acts ? r.fload : 0.0;
        f->fdamp[i] = acts ? r.fdamp : 0.0;
        /* settled: as it acts, with its constraint's force on the IDA path */
        f->fn[i] = acts && (r.fn > 0 || d->inter_settled[i]) ? r.fn + (d->inter_settled[i] ? d->inter_fcstr[i] : 0.0) : 0.0;
        for (int k = 0; k < 3; k++) f->point[3 * i + k] = r.point[k] + m->origin[k];
        memcpy(f->normal + 3 * i, r.normal, 3 * sizeof(double));
        for (int k = 0; k < 3; k++) f->ffric[3 * i + k] = acts ? r.ft[k] : 0.0;
        f->vslip[i] = acts ? r.vslip : 0.0;
        f->flim[i] = acts ? r.flim : 0.0;
        f->fmu[i] = acts ? r.mu : 0.0;
        int sl = d->inter_slip[i]; /* friction per point: any point slipping */
        for (int j = 0; j < m->inter_npt[i]; j++) sl |= d->pt_slip[m->inter_pbase[i] + j];
        f->slip[i] = acts && sl;
        f->mode[i] = mode == RC_MODE_CLOSED     ? RC_OUT_MODE_CLOSED
                     : mode == RC_MODE_OPEN     ? RC_OUT_MODE_OPEN
                     : mode == RC_MODE_RELEASED ? RC_OUT_MODE_RELEASED
                                                : RC_OUT_MODE_INACTIVE;
    }
    rc_energy(m, d, t, y, f->energy);
    if (!o) return RC_OK;
    const int nc = m->cpl->ncard; /* the joint stops are reported with their joints */
    rc_cpl_frame(m, d, t, y, f->cpl);
    rc_frame fr = {.t = t, .at_event = at_event, .body_pos = f->pos, .body_quat = f->quat, .body_vel = f->vel,
                   .body_omega = f->omega, .inter_pen = f->pen, .inter_fload = f->fload, .inter_fdamp = f->fdamp,
                   .inter_fnormal = f->fn, .inter_point = f->point, .inter_normal = f->normal,
                   .inter_mode = f->mode, .inter_ffric = f->ffric, .inter_vslip = f->vslip, .inter_slip = f->slip,
                   .energy = f->energy, .cpl_force = f->cpl, .cpl_length = f->cpl + nc, .cpl_f1 = f->cpl + 2 * nc,
                   .cpl_f2 = f->cpl + 5 * nc, .cpl_lowest = f->cpl + 8 * nc};
    if (m->jnt) { /* joints: y is the IDA backend's whole vector (model/joint.h) */
        const int nj = m->jnt->n;
        rc_jnt_frame(m, y, f->jnt, f->jnt + 3 * nj, f->jnt + 6 * nj, f->jnt + 7 * nj, f->jnt + 8 * nj);
        fr.joint_force = f->jnt;
        fr.joint_moment = f->jnt + 3 * nj;
        fr.joint_drift_pos = f->jnt + 6 * nj;
        fr.joint_drift_ang = f->jnt + 7 * nj;
        fr.joint_work = f->jnt + 8 * nj;
        /* the stops: the generalised force on the joint coordinate, a
         * force along a prismatic joint's axis, a moment about a revolute's */
        for (int j = 0; j < nj; j++) {
            double q;
            const double Q = rc_cpl_joint_stop(m, d, j, y, &q);
            const int rev = m->jnt->kind[j] == RC_JNT_REVOLUTE;
            f->jnt[9 + 8 * nj + j] = rev ? 0.0 : Q;
            f->jnt[9 + 9 * nj + j] = rev ? Q : 0.0;
        }
        fr.joint_stop_force = f->jnt + 9 + 8 * nj;
        fr.joint_stop_moment = f->jnt + 9 + 9 * nj;
    }
    return rc_output_frame(o, &fr, err);
}

static const char *const energy_name[RC_NENERGY] = {
    "energy_kinetic",        "energy_potential",  "energy_contact_work", "energy_damping", "energy_friction_work",
    "energy_contact_stored", "energy_hysteresis", "energy_friction",     "energy_coupling_elastic",
    "energy_coupling_damping", "energy_catenary", "energy_imposed", "energy_total"};
static const char *const energy_long[RC_NENERGY] = {
    "kinetic energy of the free bodies",
    "gravitational potential energy",
    "work done on the contacts by the elastic(-plastic) normal forces",
    "energy dissipated by the contact damping",
    "work done on the contacts by the friction forces",
    "elastic energy stored in the contacts, normal and tangential (recoverable by unloading)",
    "energy dissipated by contact hysteresis (normal work - normal stored)",
    "energy dissipated by friction (friction work - tangential stored)",
    "elastic energy stored in the spring-damper couplings, the contact couplings and the joint stops",
    "energy dissipated by the dampers of the couplings and the joint stops",
    "elastic and gravitational energy of the catenary lines (work done by their ends)",
    "minus the work done on the bodies by the imposed velocities (/IMPVEL reactions)",
    ("kinetic + potential + contact work + damping + friction work + couplings + imposed (constant in exact "
     "arithmetic)")};

_Static_assert(RC_SURF_NEXT == RC_OUT_SURF_NPARAM, "surface parameters: model and file disagree");
static const char *const surf_kind_name[] = {"", "PLANE", "SPHERE", "CYLINDER", "BOX", "SEGMENTS"};

rc_status rc_bk_open_output(const rc_model *m, const rc_run_options *opt, const char *note, rc_output **o,
                            rc_error *err, const char *integrator, const rc_preload *pre)
{
    const char *path = opt ? opt->output_path : NULL;
    *o = NULL;
    if (!path) return RC_OK;
    const char **types = malloc(((size_t)m->ninter + 1) * sizeof(char *));
    if (!types) RC_RAISE(err, RC_ENOMEM, "out of memory");
    /* a wall's contacts (model/rwall.c), a TYPE7's, TYPE24's, TYPE25's, TYPE11's and
     * TYPE19's (model/type7.c) are named after their card */
    for (int i = 0; i < m->ninter; i++)
        types[i] = m->inter_law[i] == RC_LAW_POWER                      ? "POWER"
                   : strncmp(m->inter_name[i], "/RWALL/", 7) == 0        ? "RWALL"
                   : strncmp(m->inter_name[i], "/INTER/TYPE7/", 13) == 0 ? "TYPE7"
                   : strncmp(m->inter_name[i], "/INTER/TYPE24/", 14) == 0 ? "TYPE24"
                   : strncmp(m->inter_name[i], "/INTER/TYPE25/", 14) == 0 ? "TYPE25"
                   : strncmp(m->inter_name[i], "/INTER/TYPE11/", 14) == 0 ? "TYPE11"
                   : strncmp(m->inter_name[i], "/INTER/TYPE19/", 14) == 0 ? "TYPE19"
                                                                         : "TYPE6";
    rc_output_meta meta = {m->title, m->case_path, m->checksum, m->unit_mass, m->unit_length, m->unit_time,
                           integrator, m->rtol, m->atol_pos,
                           m->atol_quat, m->atol_vel, m->atol_omega, m->atol_energy, m->nbody, m->body_id,
                           m->body_fixed, m->ninter, m->inter_id, types, RC_NENERGY, energy_name, energy_long,
                           m->cpl->ncard, m->cpl->id, m->cpl->type, NULL, .nfile = 0};
    /* provenance, every solver setting, the surfaces */
    meta.nfile = m->nfile;
    meta.file = (const char *const *)m->file;
    meta.overrides = m->overrides;
    meta.max_order = m->max_order;
    meta.max_steps = m->max_steps;
    meta.hmax = m->hmax;
    meta.h0 = m->h0;
    /* the run's: the deck's /RUN, or the overrides of the options */
    meta.t_end = opt && opt->t_end_override > 0 ? opt->t_end_override : m->tend;
    meta.dt_out = opt && opt->dt_out_override > 0 ? opt->dt_out_override : m->dtout;
    char derived[128] = "";
    static const char *const tol_name[5] = {"atol_position", "atol_quaternion", "atol_velocity",
                                            "atol_angular_velocity", "atol_energy"};
    for (int k = 0; k < 5; k++)
        if (m->tol_auto & (1 << k))
            snprintf(derived + strlen(derived), sizeof derived - strlen(derived), "%s%s", derived[0] ? " " : "",
                     tol_name[k]);
    meta.tol_derived = derived[0] ? derived : "none (all given in /SOLVER)";
    meta.sampling_note = note;
    char tnote[sizeof ((rc_stats *)0)->tolerance_note];
    rc_model_tol_floor_note(m, tnote, sizeof tnote);
    meta.tolerance_note = tnote;
    meta.atol_pos_floor = m->tol_floored > 0 ? m->tol_floor_pos : 0.0;
    char pl[400];
    if (pre) {
        snprintf(pl, sizeof pl,
                 "static equilibrium under the loads at t = 0 (KINSOL Newton with line search, KLU): %ld Newton "
                 "iterations in %ld solves of the contacts' active set, %ld contact mode flips; the dynamic run "
                 "started from it at rest, its closed contacts closed with their static friction forces",
                 pre->iters, pre->solves, pre->flips);
        meta.preload = pl;
        meta.preload_iters = pre->iters;
    }
    const char **kinds = malloc(((size_t)m->nsurf + 1) * sizeof *kinds);
    int *isurf = malloc((2 * (size_t)m->ninter + 1) * sizeof *isurf);
    /* the surfaces fixed in space in the deck's coordinates (the model's
     * are relative to its origin); the others in their body frames */
    const size_t nnode = m->surf_nadr ? (size_t)m->surf_nadr[m->nsurf] : 0;
    double *spt = malloc((3 * (size_t)m->nsurf + 1) * sizeof *spt), *snd = malloc((3 * nnode + 1) * sizeof *snd);
    if (!kinds || !isurf || !spt || !snd) {
        free(kinds);
        free(isurf);
        free(types);
        free(spt);
        free(snd);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    for (int s = 0; s < m->nsurf; s++) {
        const int fixed = m->surf_body[s] < 0;
        for (int k = 0; k < 3; k++) spt[3 * s + k] = m->surf_p[3 * s + k] + (fixed ? m->origin[k] : 0.0);
        if (m->surf_nadr)
            for (int j = m->surf_nadr[s]; j < m->surf_nadr[s + 1]; j++)
                for (int k = 0; k < 3; k++) snd[3 * j + k] = m->surf_node[3 * j + k] + (fixed ? m->origin[k] : 0.0);
    }
    for (int k = 0; k < m->nsurf; k++)
        kinds[k] = m->surf_kind[k] >= RC_SURF_PLANE && m->surf_kind[k] <= RC_SURF_SEG ? surf_kind_name[m->surf_kind[k]]
                                                                                    : "UNKNOWN";
    for (int i = 0; i < m->ninter; i++) {
        isurf[2 * i] = m->inter_sa[i];
        isurf[2 * i + 1] = m->inter_sb[i];
    }
    meta.nsurf = m->nsurf;
    meta.surf_id = m->surf_id;
    meta.surf_kind = kinds;
    meta.surf_body = m->surf_body;
    meta.surf_point = spt;
    meta.surf_normal = m->surf_n;
    meta.surf_radius = m->surf_r;
    meta.surf_param = m->surf_ext;
    meta.inter_surf = isurf;
    /* segment surfaces: their nodes and segments */
    if (m->surf_nadr && m->surf_sadr && m->surf_sadr[m->nsurf] > 0) {
        meta.nseg_node = m->surf_nadr[m->nsurf];
        meta.nseg = m->surf_sadr[m->nsurf];
        meta.surf_first_node = m->surf_nadr;
        meta.surf_first_seg = m->surf_sadr;
        meta.seg_node = snd;
        meta.seg_corner = m->surf_seg;
    }
    const int njt = m->jnt ? m->jnt->n : 0;
    const char **jtype = malloc(((size_t)njt + 1) * sizeof *jtype);
    if (!jtype) {
        free(types);
        free(kinds);
        free(isurf);
        free(spt);
        free(snd);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    for (int j = 0; j < njt; j++) jtype[j] = rc_jnt_type_name(m, j);
    meta.njoint = njt;
    meta.joint_id = m->jnt ? m->jnt->id : NULL;
    meta.joint_type = jtype;
    char evrec[160];
    const int full = rc_event_records(m);
    if (m->ev_state == 0)
        snprintf(evrec, sizeof evrec, "%s (/RUN Ev_state 0: %d bodies, %s %d)",
                 full ? "full-state record at every event" : "events table only", m->nbody,
                 full ? "at most" : "more than", RC_EVREC_MAX_BODIES);
    else
        snprintf(evrec, sizeof evrec, "%s (/RUN Ev_state %d)",
                 full ? "full-state record at every event" : "events table only", m->ev_state);
    meta.event_records = evrec;
    rc_status st = rc_output_open(o, path, &meta, err);
    free(jtype);
    free(types);
    free(kinds);
    free(isurf);
    free(spt);
    free(snd);
    return st;
}

/* Progress of the integration on stderr: one line rewritten on a terminal,
 * whole lines in a log. The time remaining is estimated from the rate of
 * simulated time over the wall time so far. */
/* A progress line on a terminal not yet ended by a newline: a message of
 * the run (a settled contact) starts on a line of its own, and the run's
 * end ends it (per thread: each run its own). */
static _Thread_local int progress_open;

static void progress_break(void)
{
    if (progress_open) fputc('\n', stderr);
    progress_open = 0;
}

void rc_bk_progress_line(double tend, const rc_stats *s, double t, long steps, double t0, int tty)
{
    const double wall = rc_bk_wall_now() - t0;
    char left[64] = "";
    if (t > 0 && t < tend) {
        const double rem = (tend - t) * wall / t;
        if (rem < 10) snprintf(left, sizeof left, ", about %.1f s left", rem);
        else if (rem < 120) snprintf(left, sizeof left, ", about %.0f s left", rem);
        else if (rem < 7200) snprintf(left, sizeof left, ", about %.0f min left", rem / 60);
        else snprintf(left, sizeof left, ", about %.1f h left", rem / 3600);
    }
    fprintf(stderr, "%sricochet: t = %.6g of %.6g s (%.1f%%), steps %ld, events %ld, wall %.1f s%s%s", tty ? "\r" : "",
            t, tend, 100.0 * t / tend, steps, s->events, wall, left, tty ? "   " : "\n");
    fflush(stderr);
    progress_open = tty;
}


/* the settles a run lists on stderr, one line each */
#define RC_SETTLE_LINES 10

/* A contact the engine settled into persistent contact at t (its event
 * contact_settle, engine/events/settle.c; docs/theory.md 5.2): the event
 * written, the statistics, a line on stderr with the progress. */
static rc_status settled(const rc_model *m, const rc_data *d, ev_sink *sink, double t, const double *y,
                         const rc_event *ev, rc_stats *s, int show, rc_error *err)
{
    s->settles++;
    s->t_settle = t;
    s->events++;
    /* with the progress (not with `ricochet run -q`, nor for an embedding
     * without it); the first RC_SETTLE_LINES of a run: a box chattering on
     * its corners settles hundreds of times, every one of them in the
     * results file's events and counted in the summary */
    if (show && s->settles <= RC_SETTLE_LINES + 1) progress_break(); /* not on the progress line's tail */
    if (show && s->settles <= RC_SETTLE_LINES)
        fprintf(stderr, "ricochet: %s settled into persistent contact at t = %.9g s (bounces accumulated; %s)\n",
                m->inter_name[ev->inter], t, rc_settle_hold(m, ev->inter));
    else if (show && s->settles == RC_SETTLE_LINES + 1)
        fprintf(stderr, "ricochet: %s settled into persistent contact at t = %.9g s; the further settles of this run "
                        "are not listed here (all are events contact_settle in the results file, counted in the "
                        "summary)\n",
                m->inter_name[ev->inter], t);
    return rc_bk_write_event(m, d, sink, t, y, ev, err);
}

/* ---- the driver ------------------------------------------------------- */
/* One record at (t, y, y'): the backend's record vector (with joints, the
 * reactions in the slots of their impulses), or y itself. */
static rc_status record(const rc_backend *bk, void *self, const rc_model *m, const rc_data *d, rc_output *o,
                        frame_buf *fb, double t, const double *y, const double *yp, int at_event, rc_error *err)
{
    const double *v = bk->record_vector ? bk->record_vector(self, t, y, yp) : y;
    rc_status st = rc_bk_write_frame(m, d, o, fb, t, v, at_event, err);
    /* the physics checks of the record's energies and forces (guards.h),
     * once per step: the records in between interpolate the same step */
    if (!st && fb->guards_due) {
        fb->guards_due = 0;
        if (rc_guards_record(fb->guards, d, t, v, fb)) st = RC_SET(err, RC_EPHYSICS, "%s", rc_guards_message(fb->guards));
    }
    return st;
}

/* A record between two output times (at an event, inside a contact):
 * written while the output interval has had fewer than RC_EXTRA_RECORDS of
 * them (*extra), else left out of the file and counted (*thinned), its
 * physics checks run all the same. A chattering contact (a cradle of
 * undamped balls on a floor: 86 625 such records, 213 MB, in 0.3 s of a
 * 1.67 s run) cannot fill the file; the events table keeps every event. */
static rc_status extra_record(const rc_backend *bk, void *self, const rc_model *m, const rc_data *d, rc_output *o,
                              frame_buf *fb, double t, const double *y, const double *yp, int at_event, long *extra,
                              long *thinned, rc_error *err)
{
    const int keep = *extra < RC_EXTRA_RECORDS;
    if (keep) (*extra)++;
    else (*thinned)++;
    return record(bk, self, m, d, keep ? o : NULL, fb, t, y, yp, at_event, err);
}

/* The interpolant of the integrator's last step for the impact table
 * (rc_interp_fn). */
typedef struct interp_ctx {
    const rc_backend *bk;
    void *self;
} interp_ctx;

static int interp_last_step(void *ctx, double t, const double **y)
{
    interp_ctx *c = ctx;
    return c->bk->dky(c->self, t, 0, RC_BK_SAMPLE, y) < 0 ? -1 : 0;
}

/* The impacts in progress at the end of a step over (t_prev, t] with the
 * state y (rc_impacts_step); the part of the interval before the last step
 * (right after a root return) is not covered by the interpolant. */
static void sample_step(const rc_backend *bk, void *self, rc_impacts *im, const rc_model *m, const rc_data *d,
                        double t_prev, double t, const double *y)
{
    double tn = t, hu = 0.0;
    if (!rc_impacts_active(im) || bk->last_step(self, &tn, &hu) < 0) return;
    const double lo = fmax(t_prev, tn - hu);
    if (!(t > lo)) return;
    interp_ctx c = {bk, self};
    rc_impacts_step(im, m, d, lo, t, y, interp_last_step, &c);
}

/* The roots reported at t are all exactly zero there and were positive (or
 * negative) at the start of the step: a function that reached zero and stayed
 * flat (the integrator reports such a root at the step's end, not where it
 * got there). Bisect on the interpolant over [t_n - h_u, t] for the first
 * time all of them are zero; on success the state there is in *yref (the
 * backend's scratch), the time in *refined_time, and the number of
 * bisections is returned (0: nothing to do). */
static int refine_flat_roots(const rc_backend *bk, void *self, const rc_model *m, rc_data *d, double t,
                             const int *roots, double *g, const double **yref, double *refined_time)
{
    const int nr = rc_root_count(m);
    double tn, hu;
    const double *y;
    if (nr == 0 || bk->last_step(self, &tn, &hu) < 0) return 0;
    if (bk->dky(self, t, 0, RC_BK_TMP, &y) < 0) return 0;
    rc_assemble_roots(m, d, t, y, g);
    for (int k = 0; k < nr; k++)
        if (roots[k] != 0 && g[k] != 0.0) return 0; /* a true crossing: located by the integrator */
    double lo = fmax(tn - hu, 0.0), hi = t;
    if (bk->dky(self, lo, 0, RC_BK_TMP, &y) < 0) return 0;
    rc_assemble_roots(m, d, lo, y, g);
    for (int k = 0; k < nr; k++)
        if (roots[k] != 0 && g[k] == 0.0) return 0; /* already zero at the start */
    int it = 0;
    for (; it < 200 && hi - lo > 4.0 * DBL_EPSILON * fmax(fabs(hi), 1.0); it++) {
        const double mid = 0.5 * (lo + hi);
        if (bk->dky(self, mid, 0, RC_BK_TMP, &y) < 0) return 0;
        rc_assemble_roots(m, d, mid, y, g);
        int all = 1;
        for (int k = 0; k < nr; k++)
            if (roots[k] != 0 && g[k] != 0.0) all = 0;
        if (all) hi = mid;
        else lo = mid;
    }
    if (hi >= t || bk->dky(self, hi, 0, RC_BK_TMP, yref) < 0) return 0;
    *refined_time = hi;
    return it > 0 ? it : 1;
}

/* Output times strictly before t (not within rounding of it) that a single
 * step passed before stopping at an event or a breakpoint at t: their
 * records, from the interpolant of that step, in the modes before the
 * event. Advances *tout and *nout. */
static rc_status outputs_before(const rc_backend *bk, void *self, const rc_model *m, const rc_data *d, rc_output *o,
                                frame_buf *fb, double t, double tend, double dtout, int with_yp, double *tout,
                                long *nout, rc_error *err)
{
    while (*tout < t && t - *tout > 1e-12 * fmax(fabs(t), dtout)) {
        const double *y = NULL, *yp = NULL;
        if (bk->dky(self, *tout, 0, RC_BK_TMP, &y) < 0 || (with_yp && bk->dky(self, *tout, 1, RC_BK_TMP, &yp) < 0))
            RC_RAISE(err, RC_ESOLVER, "%s interpolation at the output time %.9g s failed", bk->name, *tout);
        rc_status st = record(bk, self, m, d, o, fb, *tout, y, yp, 0, err);
        if (st) return st;
        (*nout)++;
        const double next = fmin(*nout * dtout, tend);
        if (next <= *tout) break;
        *tout = next;
        if (tend - *tout < 1e-12 * tend) *tout = tend;
    }
    return RC_OK;
}

void rc_bk_failure_message(const rc_model *m, const rc_data *d, const char *name, double t, double h, double tout,
                     const char *fname, const char *msg, const char *elem, int istate, const char *advice, char *buf,
                     size_t n)
{
    const char *cf = rc_cpl_failed(m, d);
    char where[512];
    if (d->sc->fail_inter >= 0)
        snprintf(where, sizeof where, "non-finite force in %s", m->inter_name[d->sc->fail_inter]);
    else if (cf)
        snprintf(where, sizeof where, "no force from %s", cf);
    else if (elem[0]) {
        /* an interface's state: Sfric at zero force may be the cause */
        const int it = istate >= 0 ? rc_state_inter(m, istate) : -1;
        char hint[240] = "";
        if (it >= 0) rc_settle_sfric_hint(m, d, it, hint, sizeof hint);
        snprintf(where, sizeof where, "largest local error in %s%s", elem, hint);
    }
    else
        snprintf(where, sizeof where, "element not identified");
    snprintf(buf, n, "%s failed at t = %.9g s (step h = %.3g s, next output at %.9g s): %s%s%s%s; %s. Likely "
             "cause: %s",
             name, t, h, tout, fname ? fname : "?", msg[0] ? " (\"" : "", msg, msg[0] ? "\")" : "", where, advice);
}

void rc_bk_keep_error(volatile sig_atomic_t *stop, char *keep, size_t n, int *nwarn, int code, const char *module,
                      const char *function, const char *msg)
{
    if (stop && *stop) return;
    if (code < 0 && keep) {
        snprintf(keep, n, "%s", msg);
        return;
    }
    const int k = nwarn ? (*nwarn)++ : 0;
    if (k < RC_BK_WARNINGS)
        fprintf(stderr, "ricochet: %s: %s (%s): %s\n", code < 0 ? "error" : "warning", module ? module : "?",
                function ? function : "?", msg ? msg : "");
    else if (k == RC_BK_WARNINGS)
        fprintf(stderr, "ricochet: warning: %s: further warnings of the integrator in this run are not shown\n",
                module ? module : "?");
}

/* A failed call of the integrator: its flag's name and last message. */
#define BKCHECK(call, what)                                                                                   \
    do {                                                                                                      \
        int flag_ = (call);                                                                                   \
        if (flag_ < 0) {                                                                                      \
            char *name_ = bk->flag_name(flag_); /* malloc'ed by SUNDIALS */                                   \
            st = RC_SET(err, RC_ESOLVER, "%s call %s%s failed at t = %.9g s: %s (%s)", bk->name, bk->prefix, \
                        what, t, name_ ? name_ : "?", bk->last_msg(self));                                    \
            free(name_);                                                                                      \
            goto done;                                                                                        \
        }                                                                                                     \
    } while (0)

/* What an interrupted run's message says of its results: true once the
 * file is closed (else rc_output_close's message says what it keeps). */
#define RC_KEPT ": the results up to there are kept"

/* Stop the run as interrupted, with the reason kept for the file. */
#define INTERRUPT(...)                                        \
    do {                                                      \
        snprintf(reason, sizeof reason, __VA_ARGS__);         \
        fail_reason = reason;                                 \
        st = RC_SET(err, RC_EINTERRUPT, "%s", reason);        \
    } while (0)

/* A preload (solver.h rc_preload; docs/theory.md 7.8 "Preload"): the free
 * bodies' positions and orientations of the static equilibrium, at rest
 * (rc_preload_scope refused bodies given a velocity); the gravity work
 * state restarted from them. */
static void preload_state(const rc_model *m, const rc_preload *pre, double *y)
{
    for (int b = 0; b < m->nbody; b++) {
        const int a = m->body_yadr[b];
        if (a < 0) continue;
        memcpy(y + a, pre->y + a, 7 * sizeof(double));
        for (int k = 7; k < RC_NB; k++) y[a + k] = 0.0;
    }
    rc_gravity_work_init(m, y);
}

/* After the initial modes (rc_modes_init: a contact penetrating by its
 * static P = F / k is closed, its friction state zero): each contact
 * closed in both the equilibrium and the dynamic modes starts sticking
 * with the static friction force, the return mapping's (a body held by
 * friction stays held from the first step). */
static void preload_friction(const rc_model *m, rc_data *d, const rc_preload *pre, double *y)
{
    for (int i = 0; i < m->ninter; i++) {
        const rc_fric *fr = &m->inter_fr[i];
        if (!pre->closed[i] || d->inter_mode[i] != RC_MODE_CLOSED || rc_inter_frictionless(m, i) ||
            !rc_static_friction_ok(fr))
            continue;
        if (fr->tidx >= 0) {
            const int at = m->inter_eadr[i] + fr->tidx;
            memcpy(y + at, pre->y + at, 3 * sizeof(double));
        }
        /* a friction filter: the filtered limit at rest, the limit */
        if (fr->fidx >= 0 && fr->tau > 0) {
            const int at = m->inter_eadr[i] + fr->fidx;
            memcpy(y + at, pre->y + at, 3 * sizeof(double));
        }
        /* friction per contact point: each point's unit force, sticking
         * (and its filtered limit, with a filter) */
        for (int j = 0; j < m->inter_npt[i]; j++) {
            const int at = m->inter_eadr[i] + m->inter_ns[i] + m->inter_pst[i] * j;
            memcpy(y + at, pre->y + at, (size_t)(m->inter_pst[i] == 6 ? 6 : 3) * sizeof(double));
            d->pt_slip[m->inter_pbase[i] + j] = 0;
        }
        d->inter_slip[i] = 0;
    }
}

rc_status rc_drive(const rc_model *m, const rc_run_options *opt, rc_pause *pause, const rc_preload *pre,
                   rc_stats *stats, rc_error *err, const rc_backend *bk, void *self)
{
    rc_status st = RC_OK;
    double t = 0.0; /* time reached [s] */
    rc_error local_err;
    if (!err) err = &local_err;
    rc_error_clear(err);
    rc_stats s;
    memset(&s, 0, sizeof s);
    rc_impacts im;
    memset(&im, 0, sizeof im);
    char note[sizeof s.sampling_note];
    rc_impacts_sampling_note(m, note, sizeof note);
    int *rootdir = NULL, *roots = NULL;
    double *gbuf = NULL, *flook = NULL, *bp = NULL, *ypre = NULL;
    rc_settle *hist = NULL; /* the interfaces' closes and openings (settling, Zeno guard) */
    int nbp = 0, ibp = 0;
    rc_output *out = NULL;
    frame_buf fb;
    memset(&fb, 0, sizeof fb);
    const char *fail_reason = NULL;
    char reason[2048] = "";
    rc_data *d = rc_data_new(m);
    const double tend = opt && opt->t_end_override > 0 ? opt->t_end_override : m->tend;
    const double dtout = opt && opt->dt_out_override > 0 ? opt->dt_out_override : m->dtout;
    const int show = opt && opt->progress, tty = show && isatty(2);
    ev_sink sink = {NULL, opt ? opt->on_event : NULL, opt ? opt->user : NULL, 0, "", NULL};
    const int evrec = rc_event_records(m); /* full-state records at events */
    double wall0 = rc_bk_wall_now(), last_progress = wall0;
    const int nr = rc_root_count(m);
    double *y = NULL, *yp = NULL; /* the backend's state (and derivative, NULL: none) */
    int n = m->ny;                /* their length */
    const char *integrator = "";
    int opened = 0;
    /* the physics checks (guards.h): stop at a violation unless asked to go on */
    const int on_viol = opt && opt->on_violation ? opt->on_violation : m->on_violation;
    rc_guards *gd = rc_guards_new(m, on_viol == RC_ON_VIOLATION_WARN, show);

    if (!d || !gd || !rc_bk_frame_alloc(m, &fb)) {
        st = RC_SET(err, RC_ENOMEM, "out of memory");
        goto done;
    }
    fb.guards = sink.guards = gd;
    fb.guards_due = 1; /* the first record: the baseline */
    opened = 1;
    if ((st = bk->open(self, m, d, opt, &y, &yp, &n, &integrator, err))) goto done;
    rootdir = calloc((size_t)nr + 1, sizeof(int));
    roots = calloc((size_t)nr + 1, sizeof(int));
    gbuf = calloc((size_t)nr + 1, sizeof(double));
    hist = rc_settle_new(m);
    flook = calloc((size_t)n, sizeof(double));
    ypre = calloc((size_t)m->ny + 1, sizeof(double));
    if (rc_impacts_init(&im, m) || !rootdir || !roots || !gbuf || !hist || !flook || !ypre) {
        st = RC_SET(err, RC_ENOMEM, "out of memory for the solver");
        goto done;
    }
    s.t_settle = NAN;
    /* initial state and modes (a preload: from the static equilibrium) */
    rc_initial_state(m, y);
    if (pre) preload_state(m, pre, y);
    rc_modes_init(m, d, t, y);
    if (pre) preload_friction(m, d, pre, y);
    if ((st = rc_bk_open_output(m, opt, note, &out, err, integrator, pre))) goto done;
    sink.out = out;
    if (m->nsens > 0 && (st = sensor_events(m, d, &sink, t, y, &s.events, err))) goto done;
    {
        int jmp = 0;
        rc_bk_resolve_touching(m, d, t, y, flook, &sink, &im, hist, &s, show, &jmp, &st, err);
        if (st) goto done;
        /* contacts the initial state closed without an event: persistent
         * contacts from the start, followed at every step like the impacts */
        rc_impacts_start(&im, m, d, t, y);
        if (rc_guards_started(gd, d)) {
            st = RC_SET(err, RC_EPHYSICS, "%s", rc_guards_message(gd));
            goto done;
        }
    }
    if ((st = bk->start(self, err))) goto done;
    if (nr > 0) {
        rc_bk_root_directions(m, d, rootdir);
        BKCHECK(bk->set_root_dirs(self, rootdir), "SetRootDirection");
    }
    /* time breakpoints: stop exactly there */
    if ((nbp = rc_bk_time_breakpoints(m, tend, &bp)) < 0) {
        st = RC_SET(err, RC_ENOMEM, "out of memory");
        goto done;
    }
    /* and never step past the end time (a single step may overshoot tout) */
    BKCHECK(bk->set_stop_time(self, nbp > 0 ? bp[0] : tend), "SetStopTime");

    double e0[RC_NENERGY];
    rc_energy(m, d, t, y, e0);
    if ((st = record(bk, self, m, d, out, &fb, t, y, yp, 0, err))) goto done;

    /* ---- main loop: output times and events ---- */
    long nout = 1;
    double tout = fmin(dtout, tend);
    double t_prev = t; /* where the last call ended [s] */
    /* records inside contacts, at their own time scale, when the output
     * interval cannot resolve them (with full-state event records only) */
    const double dt_contact =
        evrec && m->nbody <= RC_CONTACT_REC_MAX_BODIES ? rc_contact_record_interval(m, dtout) : 0.0;
    double t_contact_rec = -INFINITY; /* time of the last such record [s] */
    long extra = 0;                   /* records at events and inside contacts since the last output time */
    long single = 0;                  /* single steps since the last output time */
    long rhs_seen = -1;               /* d->sc->n_rhs at the last return (the physics checks) */
    while (t < tend) {
        /* the event callback asked to stop: end here as an interrupted run */
        if (sink.stop) {
            INTERRUPT("%s" RC_KEPT, sink.why);
            break;
        }
        /* stepping (rc_run_until): hand over the state at each time asked
         * for; the caller may stop the run there */
        int paused_stop = 0;
        while (pause && t >= pause->until && !paused_stop) {
            const double tu = pause->until;
            const double *yu = y;
            if (t > tu) BKCHECK(bk->dky(self, tu, 0, RC_BK_TMP, &yu), "GetDky");
            paused_stop = pause->reached(pause, tu, yu);
        }
        if (paused_stop) {
            INTERRUPT("stopped by the caller at t = %.9g s" RC_KEPT, t);
            break;
        }
        /* single steps while an impact is in progress: its peak force and
         * maximum penetration are tracked at every step (sample_step);
         * /SOLVER Max_steps then bounds the single steps between two output
         * times, as the integrator bounds the steps of one call. The
         * backend may ask for single steps of its own (rc_backend.solve). */
        int one_step = rc_impacts_active(&im);
        /* the root functions keep their reports for the samples (sample_step) */
        if (d->sc->repc) d->sc->repc->on = one_step;
        /* a time asked for by the caller before the next output time: return
         * there (interpolated; the steps are the same) */
        const double tcall = pause && pause->until < tout ? pause->until : tout;
        int flag = bk->solve(self, tcall, &t, &one_step);
        /* interrupted (a signal): inside the integrator the right-hand side
         * made it fail; between two calls the next call returns at its first one */
        if (opt && opt->stop && *opt->stop) {
            INTERRUPT("interrupted at t = %.9g s (signal)" RC_KEPT, t);
            break;
        }
        if (one_step && flag >= 0 && ++single > m->max_steps) flag = bk->too_much_work;
        if (flag >= 0) sample_step(bk, self, &im, m, d, t_prev, t, y);
        if (flag >= 0 && (st = method_event(bk, self, &sink, &s, err))) break;
        t_prev = t;
        if (flag < 0) {
            bk->failure(self, flag, t, tout, reason, sizeof reason);
            /* Max_steps spent following an undamped vibration: say so */
            if (flag == bk->too_much_work) {
                const size_t l = strlen(reason);
                rc_impacts_max_steps_hint(&im, m, t, dtout, tend - t, reason + l, sizeof reason - l);
            }
            fail_reason = reason;
            st = RC_SET(err, RC_ESOLVER, "%s", reason);
            break;
        }
        /* stepping: the times asked for that this call passed over (a
         * single step beyond them, or a root found after them) are handed
         * over now, interpolated in the step just taken, before an event
         * restarts the integrator or the end time ends the loop */
        while (pause && t > pause->until && !paused_stop) {
            const double tu = pause->until;
            const double *yu = y;
            BKCHECK(bk->dky(self, tu, 0, RC_BK_TMP, &yu), "GetDky");
            paused_stop = pause->reached(pause, tu, yu);
        }
        if (paused_stop) {
            INTERRUPT("stopped by the caller at t = %.9g s" RC_KEPT, t);
            break;
        }
        /* the physics checks of the accepted state, on the zone roots the
         * integrator evaluated there (guards.h) */
        const int at_root = flag == bk->root_return;
        /* no right-hand side evaluated since the last return: no step taken */
        const int moved = at_root || d->sc->n_rhs != rhs_seen;
        rhs_seen = d->sc->n_rhs;
        const int due = moved && rc_guards_due(gd, s.steps + bk->steps(self), at_root);
        fb.guards_due |= due;
        if (due && rc_guards_step(gd, d, t, y, bk->roots_at ? bk->roots_at(self, t) : NULL, at_root,
                                  s.steps + bk->steps(self))) {
            st = RC_SET(err, RC_EPHYSICS, "%s", rc_guards_message(gd));
            break;
        }
        const int at_bp = flag == bk->tstop_return && ibp < nbp && t >= bp[ibp];
        if (at_bp || flag == bk->root_return)
            if ((st = outputs_before(bk, self, m, d, out, &fb, t, tend, dtout, yp != NULL, &tout, &nout, err)))
                goto done;
        if (at_bp) {
            /* a time breakpoint: imposed velocities start (their velocity
             * jumps to the imposed value) or end; restart there */
            const double t_bp0 = ibp > 0 ? bp[ibp - 1] : 0.0;
            int ev_here = t == m->grav_tstart; /* not a mere knot of a load function */
            memcpy(ypre, y, (size_t)m->ny * sizeof(double));
            if (rc_imp_start(m, t_bp0, t, y) > 0) {
                ev_here = 1;
                s.events++;
                if ((st = rc_bk_sink_event(&sink, t, RC_EV_IMPVEL_START, "/IMPVEL", NULL, err))) goto done;
            }
            int stops = 0;
            for (int k = 0; m->imp && k < m->imp->nt + m->imp->nr; k++) {
                const double ts = k < m->imp->nt ? m->imp->ttstop[k] : m->imp->rtstop[k - m->imp->nt];
                stops += ts > t_bp0 && ts <= t;
            }
            if (stops) {
                ev_here = 1;
                s.events++;
                if ((st = rc_bk_sink_event(&sink, t, RC_EV_IMPVEL_STOP, "/IMPVEL", NULL, err))) goto done;
            }
            bk->add_stats(self, &s);
            d->t_bp = t; /* the right limit from here on (RC_IMP_T_ON) */
            BKCHECK(bk->restart(self, t, 1), "ReInit");
            s.reinits++;
            int nbpev = 0;
            if ((st = modes_after_restart(bk, self, m, d, t, y, ypre, flook, &sink, &im, hist, rootdir, nr, &s, show, ev_here,
                                          &nbpev, err)))
                goto done;
            ev_here |= nbpev > 0;
            if ((st = method_event(bk, self, &sink, &s, err))) goto done;
            while (ibp < nbp && bp[ibp] <= t) ibp++;
            /* the next breakpoint, or the end time */
            BKCHECK(bk->set_stop_time(self, ibp < nbp ? bp[ibp] : tend), "SetStopTime");
            /* a full-state record at the event (rc_event_records), or the
             * output record when the event falls on an output time; a knot
             * alone is no event */
            const int on_out = tout - t <= 1e-12 * fmax(fabs(t), dtout);
            if (on_out) st = record(bk, self, m, d, out, &fb, t, y, yp, evrec && ev_here, err);
            else if (evrec && ev_here)
                st = extra_record(bk, self, m, d, out, &fb, t, y, yp, 1, &extra, &s.records_thinned, err);
            if (st) goto done;
            if (on_out) {
                extra = 0;
                nout++;
                tout = fmin(nout * dtout, tend);
            }
            continue;
        }
        if (flag == bk->root_return) {
            t_contact_rec = t; /* the event's own record stands for a contact record */
            BKCHECK(bk->root_info(self, roots), "GetRootInfo");
            /* roots that land exactly on zero at the step's end (a law flat at
             * zero: an unload curve reaching zero before P does) were not
             * located: bisect on the interpolant for where they reached it */
            double t_ref = t;
            const double *yref = NULL;
            const int refined = refine_flat_roots(bk, self, m, d, t, roots, gbuf, &yref, &t_ref);
            if (refined > 0) {
                t = t_ref;
                memcpy(y, yref, (size_t)n * sizeof(double));
            }
            if (bk->before_events) bk->before_events(self);
            /* the ledger just before the events: a jump at them is measured
             * against it (guards.h) */
            fb.guards_due = 1; /* the record after the events is checked against this state */
            if (rc_guards_before_events(gd, d, t, y)) {
                st = RC_SET(err, RC_EPHYSICS, "%s", rc_guards_message(gd));
                goto done;
            }
            rc_event ev[RC_MAX_EV];
            int jumped = 0;
            int nev = rc_events_apply(m, d, t, y, roots, ev, RC_MAX_EV, &jumped);
            int cpl_ev = 0; /* a contact coupling's faces changed modes */
            for (int k = 0; k < nev && k < RC_MAX_EV; k++) cpl_ev |= ev[k].inter < 0;
            s.events += nev;
            for (int k = 0; k < nev && k < RC_MAX_EV; k++) rc_impacts_event(&im, m, d, ev[k].inter, ev[k].kind, t, y);
            if (m->nsens > 0 && (st = sensor_events(m, d, &sink, t, y, &s.events, err))) goto done;
            for (int k = 0; k < nev && k < RC_MAX_EV; k++)
                if ((st = rc_bk_write_event(m, d, &sink, t, y, &ev[k], err))) goto done;
            /* settling of accumulating bounces and the event accumulation
             * (Zeno) guard: the engine's verdict on these events
             * (engine/events/settle.c); the contacts it settled are written
             * and counted here, a Zeno verdict ends the run */
            rc_event sev[RC_MAX_EV];
            int nsev = 0;
            const rc_settle_verdict verdict =
                rc_settle_after_events(hist, m, d, t, y, flook, dtout, ev, nev < RC_MAX_EV ? nev : RC_MAX_EV, sev, RC_MAX_EV,
                                       &nsev, &jumped, reason, sizeof reason);
            for (int k = 0; k < nsev && k < RC_MAX_EV; k++)
                if ((st = settled(m, d, &sink, t, y, &sev[k], &s, show, err))) goto done;
            if (verdict == RC_SETTLE_ZENO) {
                fail_reason = reason;
                st = RC_SET(err, RC_ESOLVER, "%s", reason);
                goto done;
            }
            /* contacts left at zero penetration or zero force: by the state */
            nev += rc_bk_resolve_touching(m, d, t, y, flook, &sink, &im, hist, &s, show, &jumped, &st, err);
            if (st) goto done;
            if (nev > 0 && nr > 0) {
                rc_bk_root_directions(m, d, rootdir);
                BKCHECK(bk->set_root_dirs(self, rootdir), "SetRootDirection");
            }
            /* restart at a refined root, a jump of history states, a change
             * the backend restarts for, or a root function left at zero */
            int restart = refined > 0 || jumped;
            if (nev > 0) restart = bk->after_events(self, t, y, cpl_ev, restart);
            if (!restart) restart = rc_bk_root_on_zero(m, d, t, y, gbuf);
            if (restart) {
                bk->add_stats(self, &s);
                memcpy(ypre, y, (size_t)m->ny * sizeof(double));
                BKCHECK(bk->restart(self, t, 0), "ReInit");
                s.reinits++;
                if ((st = modes_after_restart(bk, self, m, d, t, y, ypre, flook, &sink, &im, hist, rootdir, nr, &s, show, 0,
                                              &nev, err)))
                    goto done;
                if ((st = method_event(bk, self, &sink, &s, err))) goto done;
            } else if (nev > 0 && bk->continued) {
                bk->continued(self);
            }
            /* an event on an output time stands for that output: a
             * full-state record at the event (rc_event_records), or else the
             * output record */
            const int on_out = tout - t <= 1e-12 * fmax(fabs(t), dtout);
            if (nev > 0 && on_out) st = record(bk, self, m, d, out, &fb, t, y, yp, evrec, err);
            else if (nev > 0 && evrec)
                st = extra_record(bk, self, m, d, out, &fb, t, y, yp, evrec, &extra, &s.records_thinned, err);
            if (st) goto done;
            if (on_out) {
                extra = 0;
                nout++;
                tout = fmin(nout * dtout, tend);
            }
        } else if (one_step && t < tout) {
            /* the single step ended before the output time: carry on, with
             * a record inside a contact when its time scale calls for one */
            if (dt_contact > 0 && t - t_contact_rec >= dt_contact &&
                rc_impacts_recent(&im, t, RC_CONTACT_REC_SPAN * RC_CONTACT_RECORDS * dt_contact)) {
                if ((st = extra_record(bk, self, m, d, out, &fb, t, y, yp, RC_REC_CONTACT, &extra, &s.records_thinned,
                                       err)))
                    goto done;
                t_contact_rec = t;
            }
        } else {
            /* output times reached (a single step may pass several) */
            while (tout <= t) {
                const double *yo = y, *ypo = yp;
                if (tout < t) {
                    BKCHECK(bk->dky(self, tout, 0, RC_BK_TMP, &yo), "GetDky");
                    if (yp) BKCHECK(bk->dky(self, tout, 1, RC_BK_TMP, &ypo), "GetDky");
                }
                if ((st = record(bk, self, m, d, out, &fb, tout, yo, ypo, 0, err))) goto done;
                single = 0;
                extra = 0;
                nout++;
                const double next = fmin(nout * dtout, tend);
                if (next <= tout) break;
                tout = next;
                if (tend - tout < 1e-12 * tend) tout = tend;
            }
        }
        if (show && rc_bk_wall_now() - last_progress > (tty ? 0.5 : RC_LOG_EVERY)) {
            rc_bk_progress_line(tend, &s, t, s.steps + bk->steps(self), wall0, tty);
            last_progress = rc_bk_wall_now();
        }
    }
    double e1[RC_NENERGY];
    rc_energy(m, d, t, y, e1);
    s.energy_residual = e1[RC_E_TOTAL] - e0[RC_E_TOTAL];
    s.t_end = t;
    if (opt && opt->y_end) {
        memcpy(opt->y_end, y, (size_t)m->ny * sizeof(double));
        rc_state_to_deck(m, opt->y_end);
    }

done:
    if (opened) bk->add_stats(self, &s);
    /* the impacts and the persistent contacts: in the file and, the first
     * ones, in the statistics */
    rc_impacts_finish(&im, m, t);
    s.impacts = im.n;
    for (int k = 0; k < im.n && k < RC_STATS_IMPACTS; k++) s.impact[k] = im.row[k];
    s.contacts = im.npc;
    for (int k = 0; k < im.npc && k < RC_STATS_CONTACTS; k++) s.contact[k] = im.pc[k];
    snprintf(s.sampling_note, sizeof s.sampling_note, "%s", note);
    rc_impacts_vibration_note(&im, m, s.steps, s.vibration_note, sizeof s.vibration_note);
    rc_model_tol_floor_note(m, s.tolerance_note, sizeof s.tolerance_note);
    if (out && st == RC_OK) st = rc_output_impacts(out, im.n, im.row, im.npc, im.pc, err);
    else if (out) {
        rc_error e3;
        rc_output_impacts(out, im.n, im.row, im.npc, im.pc, &e3);
    }
    if (st != RC_OK) s.t_end = t; /* how far a failed run got */
    s.wall_time = rc_bk_wall_now() - wall0;
    progress_break(); /* a progress line on a terminal ends here */
    /* the physics checks' outcome: statistics and results file */
    if (st == RC_EPHYSICS) {
        snprintf(reason, sizeof reason, "physics check failed: %s", rc_guards_message(gd));
        fail_reason = reason;
    }
    if (opened) rc_guards_finish(gd, d, &s, out, st == RC_EPHYSICS);
    if (out) {
        rc_error e2;
        rc_output_linalg(out, d && d->n_klu_sym > 0 ? d->n_klu_sym : -1, d && d->newton_nnz > 0 ? d->newton_nnz : -1,
                         (long)m->nnz);
        rc_status st2 = rc_output_close(out, &s, st == RC_OK, fail_reason ? fail_reason : err->msg, &e2);
        if (st2 && st != RC_OK && st != RC_EIO) {
            /* the file failed after the run stopped: its fate first, then why
             * the run stopped, less the claim that the results are kept */
            char *kept = strstr(err->msg, RC_KEPT);
            if (kept) *kept = '\0';
            snprintf(reason, sizeof reason, "%.2000s", err->msg);
            RC_SET(err, st2, "%s\n(the run had stopped before: %s)", e2.msg, reason);
            st = st2;
        } else if (st2) {
            st = st2;
            *err = e2;
        }
    }
    if (stats) *stats = s;
    if (opened) bk->close(self);
    rc_impacts_free(&im);
    free(rootdir);
    free(roots);
    free(gbuf);
    rc_settle_free(hist);
    free(flook);
    free(ypre);
    free(bp);
    rc_bk_frame_free(&fb);
    rc_guards_free(gd);
    rc_data_free(d);
    return st;
}
