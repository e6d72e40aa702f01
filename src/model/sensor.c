/*
 * Time sensors (/SENSOR/TIME) acting on interfaces and bodies (sensor.h,
 * docs/theory.md "Sensors").
 *
 * A body with a sensor is held at rest until the sensor's time: ricochet
 * has no free nodes for Radioss's inactive rigid body, so the body waits
 * in its initial pose, as a fixed body would, with the supports taking the
 * loads; at the sensor's time the holds end (an imposed-velocity
 * breakpoint, the integration restarted there) and the body moves freely
 * from rest. The holds are /IMPVEL entries appended to a copy of the case,
 * so that imposed.c compiles them as any other.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "case/case_joint.h"
#include "case/case_power.h"
#include "model/sensor.h"

static const char *const kind_name[] = {"TIME", "DIST", "AND", "OR"};

/* Is sensor k's time on found in the run (a distance sensor, or a logic
 * sensor of one)? (The inputs exist and form no cycle: check_logic.) */
static int runtime(const rc_case *c, int k)
{
    const rc_case_sensor *s = &c->sensor[k];
    if (s->kind == RC_SENS_DIST) return 1;
    if (s->kind == RC_SENS_TIME) return 0;
    return runtime(c, rc_case_find_sensor(c, s->in[0])) || runtime(c, rc_case_find_sensor(c, s->in[1]));
}

/* The time on of a sensor known when compiling (not runtime): a time
 * sensor's Tdelay; a logic sensor's inputs' later (AND) or earlier (OR)
 * time on, plus its Tdelay. */
static double static_ton(const rc_case *c, int k)
{
    const rc_case_sensor *s = &c->sensor[k];
    if (s->kind == RC_SENS_TIME) return s->tdelay;
    const double a = static_ton(c, rc_case_find_sensor(c, s->in[0])), b = static_ton(c, rc_case_find_sensor(c, s->in[1]));
    return (s->kind == RC_SENS_AND ? fmax(a, b) : fmin(a, b)) + s->tdelay;
}

/* The logic sensors' inputs exist and form no cycle. */
static rc_status check_logic(const rc_case *c, rc_error *err)
{
    for (int k = 0; k < c->nsensor; k++) {
        const rc_case_sensor *s = &c->sensor[k];
        if (s->kind != RC_SENS_AND && s->kind != RC_SENS_OR) continue;
        for (int e = 0; e < 2; e++)
            if (rc_case_find_sensor(c, s->in[e]) < 0)
                RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /SENSOR/%s/%d, field sens_ID%d: expected the id of a /SENSOR, got %d (no such sensor)",
                         RC_LOC(s->line2_loc), kind_name[s->kind], s->id, e + 1, s->in[e]);
    }
    /* a cycle: the sensors whose inputs are all settled settle, pass by
     * pass; one left unsettled after as many passes as sensors depends on
     * itself (or on a sensor that does) */
    unsigned char *ok = calloc((size_t)c->nsensor + 1, 1);
    if (!ok) RC_RAISE(err, RC_ENOMEM, "out of memory");
    for (int k = 0; k < c->nsensor; k++) ok[k] = c->sensor[k].kind != RC_SENS_AND && c->sensor[k].kind != RC_SENS_OR;
    for (int pass = 0; pass < c->nsensor; pass++)
        for (int k = 0; k < c->nsensor; k++)
            if (!ok[k] && ok[rc_case_find_sensor(c, c->sensor[k].in[0])] && ok[rc_case_find_sensor(c, c->sensor[k].in[1])])
                ok[k] = 1;
    for (int k = 0; k < c->nsensor; k++)
        if (!ok[k]) {
            const rc_case_sensor *s = &c->sensor[k];
            free(ok);
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
                           double tstop, int *sens, rc_error *err)
{
    *sens = -1;
    if (sensor_id == 0) return RC_OK;
    const int k = rc_case_find_sensor(c, sensor_id);
    if (k < 0)
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field Isensor: expected the id of a /SENSOR, got %d (no such sensor)",
                 RC_LOC(loc), card, sensor_id);
    if (runtime(c, k)) {
        *sens = k; /* on at a time found in the run (a trigger plus Tdelay) */
        return RC_OK;
    }
    const double ts = static_ton(c, k);
    if (ts > *tstart) *tstart = ts;
    if (*tstart > tstop)
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s, field Isensor: /SENSOR/%s/%d turns the interface on at %.9g s, after its Tstop "
                 "%.9g s: it would never act; expected a sensor time before Tstop",
                 RC_LOC(loc), card, kind_name[c->sensor[k].kind], sensor_id, ts, tstop);
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

rc_status rc_sensor_compile(const rc_case *c, rc_model *m, rc_error *err)
{
    m->nsens = c->nsensor;
    if (m->nsens == 0) return RC_OK;
    const size_t n = (size_t)m->nsens + 1;
    m->sens_id = calloc(n, sizeof *m->sens_id);
    m->sens_kind = calloc(n, sizeof *m->sens_kind);
    m->sens_tdelay = calloc(n, sizeof *m->sens_tdelay);
    m->sens_body = calloc(2 * n, sizeof *m->sens_body);
    m->sens_p = calloc(6 * n, sizeof *m->sens_p);
    m->sens_d = calloc(2 * n, sizeof *m->sens_d);
    m->sens_in = calloc(2 * n, sizeof *m->sens_in);
    if (!m->sens_id || !m->sens_kind || !m->sens_tdelay || !m->sens_body || !m->sens_p || !m->sens_d || !m->sens_in)
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    for (int k = 0; k < m->nsens; k++) {
        const rc_case_sensor *s = &c->sensor[k];
        m->sens_id[k] = s->id;
        m->sens_kind[k] = (int)s->kind;
        m->sens_tdelay[k] = s->tdelay;
        m->sens_body[2 * k] = m->sens_body[2 * k + 1] = -1;
        m->sens_in[2 * k] = m->sens_in[2 * k + 1] = -1;
        if (s->kind == RC_SENS_AND || s->kind == RC_SENS_OR)
            for (int e = 0; e < 2; e++) m->sens_in[2 * k + e] = rc_case_find_sensor(c, s->in[e]);
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
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /RBODY/%d, field sens_ID: expected the id of a /SENSOR/TIME, got %d (no such sensor)",
                     RC_LOC(l1), rb->id, rb->sens_id);
        if (runtime(c, k))
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /RBODY/%d, field sens_ID: /SENSOR/%s/%d: a body released by a sensor found in the "
                     "run (a distance sensor, or a logic sensor of one) is not supported yet; expected a /SENSOR/TIME "
                     "(or AND, OR of them; a distance sensor activates interfaces: Isensor)",
                     RC_LOC(l1), rb->id, kind_name[c->sensor[k].kind], rb->sens_id);
        if (!(static_ton(c, k) > 0)) continue; /* on from t = 0: free from the start */
        char what[64];
        rc_loc where;
        if (other_driver(c, b, what, sizeof what, &where))
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /RBODY/%d, field sens_ID: the body is held at rest until /SENSOR/%s/%d turns it on "
                     "at %.9g s; %s (%s:%d) also drives it: a held body with an initial or imposed velocity, a /BCS or "
                     "a joint is not supported yet",
                     RC_LOC(l1), rb->id, kind_name[c->sensor[k].kind], rb->sens_id, static_ton(c, k), what, RC_LOC(where));
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
        if (k < 0 || !(static_ton(c, k) > 0)) continue;
        const rc_loc l1 = rc_loc_or(rb->line_loc[0], rb->loc);
        /* its main node, a group of its own */
        x->nodes[ng - c->ngrnod] = rb->node_id;
        x->grnod[ng] = (rc_case_grnod){.id = -rb->id, .n = 1, .nodes = &x->nodes[ng - c->ngrnod], .loc = l1};
        ng++;
        /* the six velocities held at zero until the sensor's time */
        for (int j = 0; j < 6; j++)
            x->impvel[ni++] = (rc_case_impvel){.id = -rb->id, .fct_id = -2, .dir = j, .grnod_id = -rb->id,
                                               .ascale = 1.0, .fscale = 1.0, .tstart = 0.0,
                                               .tstop = static_ton(c, k), .loc = l1, .line_loc = {l1, l1}};
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
    snprintf(buf, sizeof buf, ", on by /SENSOR/%s/%d (time found in the run)", kind >= 0 && kind < 4 ? kind_name[kind] : "?",
             m->sens_id[k]);
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
