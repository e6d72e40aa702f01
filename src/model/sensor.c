/*
 * Sensors acting on interfaces and bodies (sensor.h, docs/theory.md
 * "Sensors").
 *
 * A body with a sensor is held at rest until the sensor's time: ricochet
 * has no free nodes for Radioss's inactive rigid body, so the body waits
 * in its initial pose, as a fixed body would, with the supports taking the
 * loads; at the sensor's time the holds end (an imposed-velocity
 * breakpoint, the integration restarted there; for a sensor found in the
 * run, its release event: engine/events) and the body moves freely from
 * rest. The holds are /IMPVEL entries appended to a copy of the case, so
 * that imposed.c compiles them as any other.
 *
 * A sensor known when compiling is on over one interval [on, off)
 * (static_on): a /SENSOR/NOT is the one that turns off. An interface
 * takes the interval as its Tstart and Tstop; a body only a sensor on for
 * good once on.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "case/case_joint.h"
#include "case/case_power.h"
#include "model/sensor.h"

static const char *const kind_name[] = {"TIME", "DIST", "AND", "OR", "NOT", "INTER"};

const char *rc_sensor_kind_name(int kind)
{
    return kind >= 0 && kind < (int)(sizeof kind_name / sizeof kind_name[0]) ? kind_name[kind] : "?";
}

static int is_logic(rc_case_sensor_kind k) { return k == RC_SENS_AND || k == RC_SENS_OR || k == RC_SENS_NOT; }

/* Is sensor k's time on found in the run (a distance or interface sensor,
 * or a logic sensor of one)? (The inputs exist and form no cycle:
 * check_logic.) */
static int runtime(const rc_case *c, int k)
{
    const rc_case_sensor *s = &c->sensor[k];
    if (s->kind == RC_SENS_DIST || s->kind == RC_SENS_INTER) return 1;
    if (s->kind == RC_SENS_TIME) return 0;
    return runtime(c, rc_case_find_sensor(c, s->in[0])) || runtime(c, rc_case_find_sensor(c, s->in[1]));
}

/* Does sensor k depend on a /SENSOR/NOT (itself one, or a logic sensor of one)? */
static int has_not(const rc_case *c, int k)
{
    const rc_case_sensor *s = &c->sensor[k];
    if (s->kind == RC_SENS_NOT) return 1;
    if (!is_logic(s->kind)) return 0;
    return has_not(c, rc_case_find_sensor(c, s->in[0])) || has_not(c, rc_case_find_sensor(c, s->in[1]));
}

/* When a sensor known when compiling (not runtime) is on: the interval
 * [*on, *off) (INFINITY: never; *on >= *off: never on). A time sensor:
 * [Tdelay, inf); NOT of an input on over [a, b): [Tdelay, a) (empty when
 * Tdelay >= a), or [b + Tdelay, inf) when the input turns off at a finite b
 * and that first stretch is empty (both: two intervals); AND: the
 * intersection of its inputs' intervals, its start delayed by Tdelay; OR:
 * their union when it is one interval, its start delayed by Tdelay.
 * Returns 0, or -1 when the set is not one interval (an OR of two
 * disjoint intervals; a NOT of an input that turns off again). */
static int static_on(const rc_case *c, int k, double *on, double *off)
{
    const rc_case_sensor *s = &c->sensor[k];
    if (s->kind == RC_SENS_TIME) {
        *on = s->tdelay;
        *off = INFINITY;
        return 0;
    }
    double a0, a1, b0, b1;
    if (static_on(c, rc_case_find_sensor(c, s->in[0]), &a0, &a1) ||
        static_on(c, rc_case_find_sensor(c, s->in[1]), &b0, &b1))
        return -1;
    if (a0 >= a1) a0 = a1 = INFINITY; /* never on */
    if (b0 >= b1) b0 = b1 = INFINITY;
    double u0, u1;
    if (s->kind == RC_SENS_NOT) {
        /* the input off over [0, a0) and [a1, inf): each stretch turns the
         * NOT on Tdelay after it begins */
        const int first = s->tdelay < a0, second = isfinite(a1);
        if (first && second) return -1; /* on, off, on again */
        *on = first ? s->tdelay : second ? a1 + s->tdelay : INFINITY;
        *off = first ? a0 : INFINITY;
        return 0;
    } else if (s->kind == RC_SENS_AND) {
        u0 = fmax(a0, b0);
        u1 = fmin(a1, b1);
    } else { /* OR */
        if (!isfinite(a0)) {
            u0 = b0;
            u1 = b1;
        } else if (!isfinite(b0)) {
            u0 = a0;
            u1 = a1;
        } else {
            if (a0 > b1 || b0 > a1) return -1; /* two pieces */
            u0 = fmin(a0, b0);
            u1 = fmax(a1, b1);
        }
    }
    *on = u0 + s->tdelay;
    *off = u1;
    if (!(*on < *off)) *on = *off = INFINITY;
    return 0;
}

/* The time on of a sensor known when compiling (not runtime) and on for
 * good once on (static_on gives [t, inf)): a time sensor's Tdelay; a logic
 * sensor's inputs' later (AND) or earlier (OR) time on, plus its Tdelay. */
static double static_ton(const rc_case *c, int k)
{
    double on, off;
    return static_on(c, k, &on, &off) ? INFINITY : on;
}

/* The logic sensors' inputs exist and form no cycle. */
static rc_status check_logic(const rc_case *c, rc_error *err)
{
    for (int k = 0; k < c->nsensor; k++) {
        const rc_case_sensor *s = &c->sensor[k];
        if (!is_logic(s->kind)) continue;
        for (int e = 0; e < (s->kind == RC_SENS_NOT ? 1 : 2); e++)
            if (rc_case_find_sensor(c, s->in[e]) < 0)
                RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /SENSOR/%s/%d, field sens_ID%d: expected the id of a /SENSOR, got %d (no such sensor)",
                         RC_LOC(s->line2_loc), kind_name[s->kind], s->id, e + 1, s->in[e]);
    }
    /* a cycle: the sensors whose inputs are all settled settle, pass by
     * pass; one left unsettled after as many passes as sensors depends on
     * itself (or on a sensor that does) */
    unsigned char *ok = calloc((size_t)c->nsensor + 1, 1);
    if (!ok) RC_RAISE(err, RC_ENOMEM, "out of memory");
    for (int k = 0; k < c->nsensor; k++) ok[k] = !is_logic(c->sensor[k].kind);
    for (int pass = 0; pass < c->nsensor; pass++)
        for (int k = 0; k < c->nsensor; k++)
            if (!ok[k] && ok[rc_case_find_sensor(c, c->sensor[k].in[0])] && ok[rc_case_find_sensor(c, c->sensor[k].in[1])])
                ok[k] = 1;
    for (int k = 0; k < c->nsensor; k++)
        if (!ok[k]) {
            const rc_case_sensor *s = &c->sensor[k];
            free(ok);
            if (s->kind == RC_SENS_NOT)
                RC_RAISE(err, RC_EINPUT,
                         RC_LOCFMT "card /SENSOR/NOT/%d, field sens_ID1: its input (%d) leads back to a sensor that "
                         "depends on itself: the logic sensors form a cycle; expected an input that does not depend on "
                         "the sensor itself",
                         RC_LOC(s->line2_loc), s->id, s->in[0]);
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /SENSOR/%s/%d, field sens_ID1 sens_ID2: its inputs (%d, %d) lead back to a sensor "
                     "that depends on itself: the logic sensors form a cycle; expected inputs that do not depend on the "
                     "sensor itself",
                     RC_LOC(s->line2_loc), kind_name[s->kind], s->id, s->in[0], s->in[1]);
        }
    free(ok);
    return RC_OK;
}

rc_status rc_sensor_tstart(const rc_case *c, int sensor_id, rc_loc loc, const char *card, double *tstart,
                           double *tstop, int *sens, rc_error *err)
{
    *sens = -1;
    if (sensor_id == 0) return RC_OK;
    const int k = rc_case_find_sensor(c, sensor_id);
    if (k < 0)
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field Isensor: expected the id of a /SENSOR, got %d (no such sensor)",
                 RC_LOC(loc), card, sensor_id);
    const char *kn = kind_name[c->sensor[k].kind];
    if (runtime(c, k)) {
        if (has_not(c, k))
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card %s, field Isensor: /SENSOR/%s/%d depends on a /SENSOR/NOT of a sensor found in "
                     "the run (a distance or interface sensor): it turns off again at a time found in the run, which an interface "
                     "is not supported yet to follow; expected a sensor that turns on for good, or a /SENSOR/NOT of "
                     "time sensors",
                     RC_LOC(loc), card, kn, sensor_id);
        *sens = k; /* on at a time found in the run (a trigger plus Tdelay) */
        return RC_OK;
    }
    double on, off;
    if (static_on(c, k, &on, &off))
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s, field Isensor: /SENSOR/%s/%d is on over two separate time intervals (an OR of "
                 "disjoint intervals, or a NOT of a sensor that turns off again): an interface that starts twice is "
                 "not supported yet; expected a sensor on over one interval",
                 RC_LOC(loc), card, kn, sensor_id);
    if (on > *tstart) *tstart = on;
    if (off < *tstop) *tstop = off; /* a NOT: off from its input's time on, as after Tstop */
    if (!(*tstart <= *tstop) && isinf(off))
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s, field Isensor: /SENSOR/%s/%d turns the interface on at %.9g s, after its Tstop "
                 "%.9g s: it would never act; expected a sensor time before Tstop",
                 RC_LOC(loc), card, kn, sensor_id, on, *tstop);
    if (!(*tstart <= *tstop))
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s, field Isensor: /SENSOR/%s/%d is on over [%.9g, %.9g) s, which leaves the interface "
                 "no time between its start and its stop: it would never act; expected a sensor on before Tstop",
                 RC_LOC(loc), card, kn, sensor_id, on, off);
    return RC_OK;
}

rc_status rc_sensor_load_on(const rc_case *c, int sensor_id, rc_loc loc, const char *card, const char *what,
                            double *ton, int *sens, rc_error *err)
{
    *ton = 0.0;
    *sens = -1;
    if (sensor_id == 0) return RC_OK;
    const int k = rc_case_find_sensor(c, sensor_id);
    if (k < 0)
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field sensor_ID: expected the id of a /SENSOR, got %d (no such sensor)",
                 RC_LOC(loc), card, sensor_id);
    const char *kn = kind_name[c->sensor[k].kind];
    if (runtime(c, k)) {
        if (has_not(c, k))
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card %s, field sensor_ID: /SENSOR/%s/%d depends on a /SENSOR/NOT of a sensor found in "
                     "the run (a distance or interface sensor): it turns off again at a time found in the run; %s "
                     "that ends when its sensor turns off is not supported yet; expected a sensor that turns on for "
                     "good",
                     RC_LOC(loc), card, kn, sensor_id, what);
        *ton = INFINITY;
        *sens = k; /* on at a time found in the run: the load starts at its event */
        return RC_OK;
    }
    double on, off;
    if (static_on(c, k, &on, &off) || (isfinite(off) && on < off))
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s, field sensor_ID: /SENSOR/%s/%d turns off again (it depends on a /SENSOR/NOT: "
                 "on while its input is off): %s that ends when its sensor turns off is not supported yet; "
                 "expected a sensor that turns on for good",
                 RC_LOC(loc), card, kn, sensor_id, what);
    if (!isfinite(on))
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s, field sensor_ID: /SENSOR/%s/%d never turns on (its inputs are never on "
                 "together): %s would never act; expected a sensor that turns on",
                 RC_LOC(loc), card, kn, sensor_id, what);
    *ton = on;
    return RC_OK;
}

/* q (w, x, y, z) applied to v transposed: the body frame's coordinates of a global vector. */
static void rot_t(const double *q, const double *v, double *o)
{
    const double w = q[0], u[3] = {-q[1], -q[2], -q[3]};
    const double c[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double cc[3] = {u[1] * c[2] - u[2] * c[1], u[2] * c[0] - u[0] * c[2], u[0] * c[1] - u[1] * c[0]};
    for (int k = 0; k < 3; k++) o[k] = v[k] + 2.0 * (w * c[k] + cc[k]);
}

/* Interface sensor k: the /INTER card int_ID names, compiled into
 * interfaces of that id (TYPE6, POWER, TYPE7, TYPE11, TYPE19, TYPE24,
 * TYPE25: m->inter_id; a wall's contacts carry -rwall_ID), and its force
 * bound. RC_EINPUT at line 2 when no interface has that id, or when the
 * sensor itself turns on every interface it watches (it would never
 * trigger). */
static rc_status compile_inter(const rc_case *c, rc_model *m, int k, rc_error *err)
{
    const rc_case_sensor *s = &c->sensor[k];
    int found = 0, self = 0;
    for (int i = 0; i < m->ninter; i++)
        if (m->inter_id[i] == s->inter_id) {
            found++;
            self += m->inter_sens[i] == k;
        }
    if (!found) {
        char why[160] = "no such interface";
        if (rc_case_find_rwall(c, s->inter_id) >= 0)
            snprintf(why, sizeof why, "no such interface; /RWALL %d is a rigid wall: a sensor on a wall's contact "
                                      "(Radioss /SENSOR/RWALL) is not supported yet",
                     s->inter_id);
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card /SENSOR/INTER/%d, field int_ID: expected the id of an /INTER (TYPE6, POWER, TYPE7, "
                           "TYPE11, TYPE19, TYPE24, TYPE25), got %d (%s)",
                 RC_LOC(s->line2_loc), s->id, s->inter_id, why);
    }
    if (self == found)
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card /SENSOR/INTER/%d, field int_ID: /INTER %d is turned on by this sensor itself (its "
                           "sensor field names /SENSOR/INTER/%d): inactive until the sensor triggers, its contact "
                           "would never trigger it; expected an interface active without this sensor",
                 RC_LOC(s->line2_loc), s->id, s->inter_id, s->id);
    m->sens_inter[k] = s->inter_id;
    m->sens_d[2 * k + 1] = s->dir ? s->fmax : 0.0;
    return RC_OK;
}

rc_status rc_sensor_compile(const rc_case *c, rc_model *m, rc_error *err)
{
    m->nsens = c->nsensor;
    if (m->nsens == 0) return RC_OK;
    const size_t n = (size_t)m->nsens + 1;
    m->sens_id = calloc(n, sizeof *m->sens_id);
    m->sens_kind = calloc(n, sizeof *m->sens_kind);
    m->sens_tdelay = calloc(n, sizeof *m->sens_tdelay);
    m->sens_tmin = calloc(n, sizeof *m->sens_tmin);
    m->sens_body = calloc(2 * n, sizeof *m->sens_body);
    m->sens_p = calloc(6 * n, sizeof *m->sens_p);
    m->sens_d = calloc(2 * n, sizeof *m->sens_d);
    m->sens_in = calloc(2 * n, sizeof *m->sens_in);
    m->sens_hold = calloc(n, sizeof *m->sens_hold);
    m->sens_inter = calloc(n, sizeof *m->sens_inter);
    if (!m->sens_id || !m->sens_kind || !m->sens_tdelay || !m->sens_tmin || !m->sens_body || !m->sens_p || !m->sens_d || !m->sens_in ||
        !m->sens_hold || !m->sens_inter)
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    /* the sensors found in the run that release a held body, or start an
     * imposed velocity or a gravity (their release root and event) */
    for (int b = 0; b < c->nrbody; b++) {
        const int k = c->rbody[b].sens_id ? rc_case_find_sensor(c, c->rbody[b].sens_id) : -1;
        if (k >= 0 && runtime(c, k)) m->sens_hold[k] = 1;
    }
    for (int j = 0; j < c->nimpvel + c->ngrav; j++) {
        const int id = j < c->nimpvel ? c->impvel[j].sensor_id : c->grav[j - c->nimpvel].sensor_id;
        const int k = id ? rc_case_find_sensor(c, id) : -1;
        if (k >= 0 && runtime(c, k)) m->sens_hold[k] = 1;
    }
    for (int k = 0; k < m->nsens; k++) {
        const rc_case_sensor *s = &c->sensor[k];
        m->sens_id[k] = s->id;
        m->sens_kind[k] = (int)s->kind;
        m->sens_tdelay[k] = s->tdelay;
        m->sens_tmin[k] = s->tmin;
        m->sens_body[2 * k] = m->sens_body[2 * k + 1] = -1;
        m->sens_in[2 * k] = m->sens_in[2 * k + 1] = -1;
        if (s->kind == RC_SENS_AND || s->kind == RC_SENS_OR)
            for (int e = 0; e < 2; e++) m->sens_in[2 * k + e] = rc_case_find_sensor(c, s->in[e]);
        if (s->kind == RC_SENS_NOT) m->sens_in[2 * k] = rc_case_find_sensor(c, s->in[0]);
        if (s->kind == RC_SENS_INTER) {
            rc_status st = compile_inter(c, m, k, err);
            if (st) return st;
        }
        if (s->kind != RC_SENS_DIST) continue;
        m->sens_d[2 * k] = s->dmin;
        m->sens_d[2 * k + 1] = s->dmax;
        for (int e = 0; e < 2; e++) {
            const int j = rc_case_find_node(c, s->node[e]);
            if (j < 0)
                RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /SENSOR/DIST/%d, field node_ID%d: expected the id of a /NODE, got %d (no such node)",
                         RC_LOC(s->line2_loc), s->id, e + 1, s->node[e]);
            const int b = rc_case_body_of_node(c, s->node[e]);
            /* the node in the model's coordinates (the origin's), then in its body's frame */
            double x[3];
            for (int i = 0; i < 3; i++) x[i] = c->node[j].x[i] - m->origin[i];
            double *p = m->sens_p + 6 * k + 3 * e;
            if (b < 0) {
                for (int i = 0; i < 3; i++) p[i] = x[i];
            } else {
                const double *y0 = m->body_y0 + RC_NB * b;
                const double r[3] = {x[0] - y0[0], x[1] - y0[1], x[2] - y0[2]};
                rot_t(y0 + 3, r, p);
            }
            m->sens_body[2 * k + e] = b;
        }
        if (m->sens_body[2 * k] == m->sens_body[2 * k + 1])
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /SENSOR/DIST/%d, field node_ID2: nodes %d and %d both belong to %s: their distance "
                     "never changes; expected nodes of two different bodies (or one fixed in space)",
                     RC_LOC(s->line2_loc), s->id, s->node[0], s->node[1], m->sens_body[2 * k] < 0 ? "no /RBODY (fixed in space)" : "one /RBODY");
    }
    return RC_OK;
}

/* Does group gid hold a node of body b? */
static int group_has_body(const rc_case *c, int gid, int b)
{
    const int g = gid ? rc_case_find_grnod(c, gid) : -1;
    for (int k = 0; g >= 0 && k < c->grnod[g].n; k++)
        if (rc_case_body_of_node(c, c->grnod[g].nodes[k]) == b) return 1;
    return 0;
}

/* The card that also drives body b (an /INIVEL, /IMPVEL, /BCS, /JOINT),
 * written into what/where; 0: none. */
static int other_driver(const rc_case *c, int b, char *what, size_t n, rc_loc *where)
{
    for (int k = 0; k < c->ninivel; k++)
        if (group_has_body(c, c->inivel[k].grnod_id, b)) {
            snprintf(what, n, "/INIVEL/%s/%d", c->inivel[k].rot ? "ROT" : "TRA", c->inivel[k].id);
            *where = c->inivel[k].loc;
            return 1;
        }
    for (int k = 0; k < c->nimpvel; k++)
        if (group_has_body(c, c->impvel[k].grnod_id, b)) {
            snprintf(what, n, "/IMPVEL/%d", c->impvel[k].id);
            *where = c->impvel[k].loc;
            return 1;
        }
    for (int k = 0; k < c->nbcs; k++)
        if (group_has_body(c, c->bcs[k].grnod_id, b)) {
            snprintf(what, n, "/BCS/%d", c->bcs[k].id);
            *where = c->bcs[k].loc;
            return 1;
        }
    for (int k = 0; k < c->njoint; k++)
        for (int e = 0; e < 2; e++)
            if (c->joint[k].rbody[e] == c->rbody[b].id) {
                snprintf(what, n, "/JOINT/%d", c->joint[k].id);
                *where = c->joint[k].loc;
                return 1;
            }
    return 0;
}

rc_status rc_sensor_begin(const rc_case *c, rc_sensor_case *x, rc_error *err)
{
    memset(x, 0, sizeof *x);
    x->c = *c;
    rc_status cst = check_logic(c, err);
    if (cst) return cst;
    /* the bodies held until their sensor's time */
    int nh = 0;
    for (int b = 0; b < c->nrbody; b++) {
        const rc_case_rbody *rb = &c->rbody[b];
        if (rb->sens_id == 0) continue;
        const rc_loc l1 = rc_loc_or(rb->line_loc[0], rb->loc);
        const int k = rc_case_find_sensor(c, rb->sens_id);
        if (k < 0)
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /RBODY/%d, field sens_ID: expected the id of a /SENSOR, got %d (no such sensor)",
                     RC_LOC(l1), rb->id, rb->sens_id);
        const char *kn = kind_name[c->sensor[k].kind];
        const int rt = runtime(c, k);
        double on = 0.0, off = INFINITY;
        /* a body turned on for good: a NOT (off once its input is on)
         * would deactivate the rigid body again, which ricochet cannot */
        if ((rt && has_not(c, k)) || (!rt && (static_on(c, k, &on, &off) || isfinite(off))))
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /RBODY/%d, field sens_ID: /SENSOR/%s/%d turns off again (it depends on a "
                     "/SENSOR/NOT: on while its input is off): a rigid body deactivated after its release is not "
                     "supported (a held body is released once, for good); expected a sensor that turns on for good",
                     RC_LOC(l1), rb->id, kn, rb->sens_id);
        if (!rt && !(on > 0)) continue; /* on from t = 0: free from the start */
        char what[64];
        rc_loc where;
        if (other_driver(c, b, what, sizeof what, &where)) {
            char when[64];
            if (rt) snprintf(when, sizeof when, "at a time found in the run");
            else snprintf(when, sizeof when, "at %.9g s", on);
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /RBODY/%d, field sens_ID: the body is held at rest until /SENSOR/%s/%d turns it on "
                     "%s; %s (%s:%d) also drives it: a held body with an initial or imposed velocity, a /BCS or "
                     "a joint is not supported yet",
                     RC_LOC(l1), rb->id, kn, rb->sens_id, when, what, RC_LOC(where));
        }
        nh++;
    }
    if (nh == 0) return RC_OK;
    x->c.index = NULL; /* the copy gets its own below (the case's stays the case's) */
    x->impvel = calloc((size_t)(c->nimpvel + 6 * nh) + 1, sizeof *x->impvel);
    x->grnod = calloc((size_t)(c->ngrnod + nh) + 1, sizeof *x->grnod);
    x->funct = calloc((size_t)c->nfunct + 1, sizeof *x->funct);
    x->nodes = calloc((size_t)nh + 1, sizeof *x->nodes);
    if (!x->impvel || !x->grnod || !x->funct || !x->nodes) {
        rc_sensor_end(x);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    if (c->nimpvel) memcpy(x->impvel, c->impvel, (size_t)c->nimpvel * sizeof *x->impvel);
    if (c->ngrnod) memcpy(x->grnod, c->grnod, (size_t)c->ngrnod * sizeof *x->grnod);
    if (c->nfunct) memcpy(x->funct, c->funct, (size_t)c->nfunct * sizeof *x->funct);
    /* the zero function: a hold imposes v = 0 */
    x->fx[1] = 1.0;
    x->funct[c->nfunct] = (rc_case_funct){.id = -2, .npts = 2, .x = x->fx, .y = x->fy, .loc = c->end};
    int ni = c->nimpvel, ng = c->ngrnod;
    for (int b = 0; b < c->nrbody; b++) {
        const rc_case_rbody *rb = &c->rbody[b];
        const int k = rb->sens_id ? rc_case_find_sensor(c, rb->sens_id) : -1;
        const int rt = k >= 0 && runtime(c, k);
        if (k < 0 || (!rt && !(static_ton(c, k) > 0))) continue;
        const rc_loc l1 = rc_loc_or(rb->line_loc[0], rb->loc);
        /* its main node, a group of its own */
        x->nodes[ng - c->ngrnod] = rb->node_id;
        x->grnod[ng] = (rc_case_grnod){.id = -rb->id, .n = 1, .nodes = &x->nodes[ng - c->ngrnod], .loc = l1};
        ng++;
        /* the six velocities held at zero until the sensor's time */
        for (int j = 0; j < 6; j++)
            x->impvel[ni++] = (rc_case_impvel){.id = -rb->id, .fct_id = -2, .dir = j, .grnod_id = -rb->id,
                                               .ascale = 1.0, .fscale = 1.0, .tstart = 0.0,
                                               .tstop = rt ? INFINITY : static_ton(c, k), .hold_sens = rt ? k + 1 : 0,
                                               .loc = l1, .line_loc = {l1, l1}};
    }
    x->c.impvel = x->impvel;
    x->c.nimpvel = ni;
    x->c.grnod = x->grnod;
    x->c.ngrnod = ng;
    x->c.funct = x->funct;
    x->c.nfunct = c->nfunct + 1;
    /* the copy's own index: its look-ups stay O(log N) (case/lookup.c) */
    x->c.index = NULL;
    rc_status st = rc_case_index_build(&x->c, err);
    if (st) rc_sensor_end(x);
    return st;
}

const char *rc_sensor_note(const rc_model *m, int i)
{
    static char buf[96];
    const int k = m->inter_sens ? m->inter_sens[i] : -1;
    if (k < 0) return "";
    const int kind = m->sens_kind[k];
    snprintf(buf, sizeof buf, ", on by /SENSOR/%s/%d (time found in the run)", rc_sensor_kind_name(kind), m->sens_id[k]);
    return buf;
}

void rc_sensor_end(rc_sensor_case *x)
{
    if (x->impvel) rc_case_index_free(x->c.index); /* the copy's own (rc_sensor_begin) */
    free(x->impvel);
    free(x->grnod);
    free(x->funct);
    free(x->nodes);
    memset(x, 0, sizeof *x);
}
