/*
 * Time sensors (/SENSOR/TIME): the card, and what the compiler makes of
 * the sensors of a body (held by six imposed zero velocities until the
 * sensor's time, model/sensor.c) and of interfaces (their start raised to
 * the sensor's time); a sensor at t = 0 holds nothing; the TYPE6 layouts
 * before 14.0 have no Isensor.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "case/case.h"
#include "harness.h"
#include "ricochet/ricochet.h"
#include "model/imposed.h"
#include "model/model.h"
#include "testutil.h"

/* A ball (/RBODY/1, sens_ID `sens`) over a floor, a TYPE6 with Isensor
 * `isens`, sensors 1 (Tdelay t1) and 2 (Tdelay t2); /BEGIN version `ver`. */
static const char *sensor_deck(int ver, int sens, int isens, double t1, double t2)
{
    static char text[4096];
    snprintf(text, sizeof text,
             "/BEGIN\nsensors\n%10d         0\n\n\n"
             "/NODE\n1,0,0,0.15\n"
             "/RBODY/1\nball\n%10d%10d                              1.3\n0.0017,0.0017,0.0017\n0,0,0\n"
             "/SENSOR/TIME/1\nrelease\n%20.9g\n/SENSOR/TIME/2\ncontact\n%20.9g\n"
             "/SURF/ELLIPS/2\nball\n0,2,1\n0,0,0.15\n0.05,0.05,0.05\n/SURF/PLANE/3\nfloor\n0,0,0\n0,0,1\n"
             "/FUNCT/1\nlinear\n0,0\n1,1e6\n"
             "/INTER/TYPE6/1\nball on floor\n%10d%10d%10d\n0,0,0,0.05,0.7\n\n1,0,1,1,0\n\n\n"
             "/GRAV/1\ng\n         0         Z         0         0         0                           1.0               -9.81\n"
             "/RUN\n1,0.01\n/END\n",
             ver, 1, sens, t1, t2, 2, 3, isens);
    return text;
}

static void test_sensor_compile(void)
{
    /* the body held until 0.37 s, the interface on at max(Tstart 0.05, 0.21) */
    rc_model *m = TU_COMPILE_OK(sensor_deck(2022, 1, 2, 0.37, 0.21), "sens1.rad");
    if (m) {
        ENSURE(m->imp != NULL);
        if (m->imp) {
            ENSURE(m->imp->nt == 3 && m->imp->nr == 1);
            for (int k = 0; k < m->imp->nt; k++)
                ENSURE(m->imp->tbody[k] == 0 && m->imp->ttstop[k] == 0.37 && m->imp->tfscale[k] == 1.0);
            if (m->imp->nr == 1) ENSURE(m->imp->rbody[0] == 0 && m->imp->rtstop[0] == 0.37);
        }
        ENSURE(m->ninter == 1 && m->inter_tstart[0] == 0.21 && m->inter_tstop[0] == 0.7);
        /* held at rest: the initial velocities imposed at zero */
        for (int k = 7; k < 13; k++) ENSURE(m->body_y0[k] == 0.0);
        /* the contact's scales see a free body (the hold ends in the run) */
        ENSURE(isfinite(m->inter_mred[0]) && isfinite(m->inter_pscale[0]));
    }
    rc_model_free(m);
    /* a sensor before Tstart leaves Tstart; a sensor at 0 holds nothing */
    m = TU_COMPILE_OK(sensor_deck(2022, 2, 1, 0.0, 0.0), "sens2.rad");
    if (m) {
        ENSURE(m->imp == NULL);
        ENSURE(m->ninter == 1 && m->inter_tstart[0] == 0.05);
    }
    rc_model_free(m);
    /* TYPE6 of Radioss 13.0 (5 lines): no Isensor (columns 21-30 are text
     * after the layout, warned); the body's sensor still holds it */
    static const char old[] = "/BEGIN\nsensors\n       130         0\n\n\n/NODE\n1,0,0,0.15\n"
                              "/RBODY/1\nball\n         1         1                              1.3\n"
                              "0.0017,0.0017,0.0017\n0,0,0\n/SENSOR/TIME/1\nrelease\n                0.37\n"
                              "/SURF/ELLIPS/2\nball\n0,2,1\n0,0,0.15\n0.05,0.05,0.05\n/SURF/PLANE/3\nfloor\n0,0,0\n0,0,1\n"
                              "/FUNCT/1\nlinear\n0,0\n1,1e6\n/INTER/TYPE6/1\nball on floor\n         2         3         1\n"
                              ",0,0,0.05,0.7\n\n1,0,1,1\n\n/RUN\n1,0.01\n/END\n";
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    ENSURE(rc_case_load(tu_tmp_write("sens130.rad", old), &c, &e) == RC_OK);
    if (!c) fprintf(stderr, "  %s\n", e.msg);
    if (c) {
        ENSURE(c->ntype6 == 1 && c->type6[0].sensor_id == 0 && c->nsensor == 1 && c->sensor[0].tdelay == 0.37);
        int warned = 0;
        for (int k = 0; k < c->nwarnings; k++) warned |= strstr(c->warnings[k], "text after column 20") != NULL;
        ENSURE(warned);
    }
    rc_case_free(c);
}

/* Ball A (node 1, /RBODY/1) falls from z = 1 m onto the fixed ball B
 * (node 2, /RBODY/2 held by /BCS); node 3 is fixed in space at A's start;
 * /SENSOR/DIST/5 between nodes 1 and n2 (Dmin, Dmax, Tdelay) turns the
 * /INTER/POWER between them on; the input units `units` (a /BEGIN line). */
static const char *dist_deck(int n2, double dmin, double dmax, double tdelay, const char *units)
{
    static char text[4096];
    snprintf(text, sizeof text,
             "/BEGIN\ndistance sensor\n      2022         0\n%s\n                  kg                   m                   s\n"
             "/NODE\n1,0,0,1\n2,0,0,0\n3,0,0,1\n"
             "/RBODY/1\nA\n         1                                                 1         1\n0.001,0.001,0.001\n0,0,0\n"
             "/RBODY/2\nB\n         2                                                 1         2\n0.001,0.001,0.001\n0,0,0\n"
             "/GRNOD/NODE/1\nA\n1\n/GRNOD/NODE/2\nB\n2\n/BCS/1\nB fixed\n   111 111         0         2\n"
             "/SURF/ELLIPS/1\nA\n0,2,1\n0,0,1\n0.05,0.05,0.05\n/SURF/ELLIPS/2\nB\n0,2,2\n0,0,0\n0.05,0.05,0.05\n"
             "/SENSOR/DIST/5\nsensor\n%20.12g\n         1%10d%20.12g%20.12g\n"
             "/INTER/POWER/1\nA on B\n         1         2         0         0         0         0         5\n"
             "            10000000                 1.5\n\n\n"
             "/GRAV/1\ng\n         0         Z         0         0         1                             1               -9.81\n"
             "/RUN\n0.6,0.01\n/END\n",
             units, tdelay, n2, dmin, dmax);
    return text;
}

static void test_sensor_dist_read(void)
{
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    /* input in mm and ms: the bounds and the delay in m and s (the deck
     * without its interface, whose K has no fixed dimension) */
    char text[4096];
    snprintf(text, sizeof text, "%s", dist_deck(2, 500, 800, 100, "                  kg                  mm                  ms"));
    char *a = strstr(text, "/INTER/POWER"), *b = strstr(text, "/GRAV");
    if (a && b) memmove(a, b, strlen(b) + 1);
    ENSURE(rc_case_load(tu_tmp_write("dist_mm.rad", text), &c, &e) == RC_OK);
    if (!c) fprintf(stderr, "  %s\n", e.msg);
    if (c) {
        ENSURE(c->nsensor == 1);
        const rc_case_sensor *s = &c->sensor[0];
        ENSURE(s->id == 5 && s->kind == RC_SENS_DIST && s->node[0] == 1 && s->node[1] == 2);
        ENSURE_NEAR(s->dmin, 0.5, 1e-15, 0);
        ENSURE_NEAR(s->dmax, 0.8, 1e-15, 0);
        ENSURE_NEAR(s->tdelay, 0.1, 1e-15, 0);
        ENSURE(s->line2_loc.line == s->line_loc.line + 1);
    }
    rc_case_free(c);
}

static void test_sensor_dist_compile(void)
{
    rc_model *m = TU_COMPILE_OK(dist_deck(3, 0, 0.2, 0.1, ""), "dist1.rad");
    if (m) {
        ENSURE(m->nsens == 1 && m->sens_kind[0] == 1 && m->sens_id[0] == 5 && m->sens_tdelay[0] == 0.1);
        /* node 1 at its body's reference point; node 3 fixed in space */
        ENSURE(m->sens_body[0] == 0 && m->sens_body[1] == -1);
        ENSURE(m->sens_p[0] == 0 && m->sens_p[1] == 0 && m->sens_p[2] == 0);
        ENSURE(m->sens_p[3] == 0 && m->sens_p[4] == 0 && m->sens_p[5] == 1.0);
        ENSURE(m->sens_d[0] == 0 && m->sens_d[1] == 0.2);
        /* the interface waits for the sensor: Tstart untouched */
        ENSURE(m->ninter == 1 && m->inter_sens[0] == 0 && m->inter_tstart[0] == 0.0);
    }
    rc_model_free(m);
}

static void test_sensor_dist_run(void)
{
    static tu_evlog ev;
    const double g = 9.81, tc = sqrt(2 * 0.9 / g);
    /* Dmax 0.2 m from a fixed node, Tdelay 0.1 s: triggered at sqrt(2 Dmax/g),
     * the interface on 0.1 s later, the contact at sqrt(2 (1 - 0.1)/g) */
    const struct {
        int n2;
        double dmin, dmax, td, ttrig;
    } cs[] = {{3, 0, 0.2, 0.1, sqrt(2 * 0.2 / g)}, {2, 0.5, 0, 0.0, sqrt(2 * 0.5 / g)}, {3, 0, 0.2, 0.3, sqrt(2 * 0.2 / g)}};
    for (int k = 0; k < 3; k++) {
        rc_model *m = TU_COMPILE_OK(dist_deck(cs[k].n2, cs[k].dmin, cs[k].dmax, cs[k].td, ""), "dist2.rad");
        if (!m) continue;
        rc_error e;
        rc_error_clear(&e);
        memset(&ev, 0, sizeof ev);
        rc_run_options o = {.on_event = tu_evlog_event, .user = &ev};
        ENSURE(rc_run(m, &o, NULL, &e) == RC_OK);
        double t = -1, v[3] = {0}, ts = -1, tcl = -1;
        ENSURE(tu_evlog_first(&ev, "sensor_trigger", &t, v) == 1);
        ENSURE_NEAR(t, cs[k].ttrig, 1e-10, 0);
        ENSURE(isnan(v[0]) && isnan(v[1]) && isnan(v[2])); /* not an interface */
        ENSURE(tu_evlog_first(&ev, "inter_start", &ts, NULL) == 1);
        ENSURE_NEAR(ts, cs[k].ttrig + cs[k].td, 1e-10, 0);
        /* on before the meeting: contact at the free-fall time; after it
         * (A past B's centre): none */
        const int nc = tu_evlog_first(&ev, "contact_close", &tcl, NULL);
        if (cs[k].ttrig + cs[k].td < tc) {
            ENSURE(nc >= 1);
            ENSURE_NEAR(tcl, tc, 1e-10, 0);
        } else {
            ENSURE(nc == 0);
        }
        rc_model_free(m);
    }
    /* out of its bounds at the start (Dmax below the initial 1 m): triggered
     * at t = 0, the interface on from the start */
    rc_model *m = TU_COMPILE_OK(dist_deck(2, 0, 0.5, 0.0, ""), "dist3.rad");
    if (m) {
        rc_error e;
        rc_error_clear(&e);
        memset(&ev, 0, sizeof ev);
        rc_run_options o = {.on_event = tu_evlog_event, .user = &ev};
        ENSURE(rc_run(m, &o, NULL, &e) == RC_OK);
        double t = -1, tcl = -1;
        ENSURE(tu_evlog_first(&ev, "sensor_trigger", &t, NULL) == 1 && t == 0.0);
        ENSURE(tu_evlog_first(&ev, "contact_close", &tcl, NULL) >= 1);
        ENSURE_NEAR(tcl, tc, 1e-10, 0);
    }
    rc_model_free(m);
}

/* text with `cards` inserted before /END and every "what" replaced by "with" (static buffer). */
static const char *edit_deck(const char *text, const char *cards, const char *what, const char *with)
{
    static char out[8192];
    char tmp[8192];
    snprintf(tmp, sizeof tmp, "%s", text);
    char *e = strstr(tmp, "/END");
    if (!e) return text;
    *e = '\0';
    const size_t a = strlen(tmp), b = strlen(cards);
    if (a + b + 6 > sizeof out) return text;
    memcpy(out, tmp, a);
    memcpy(out + a, cards, b);
    memcpy(out + a + b, "/END\n", 6);
    if (what) {
        char *w = strstr(out, what);
        if (w && strlen(what) == strlen(with)) memcpy(w, with, strlen(with));
    }
    return out;
}

static void test_sensor_logic(void)
{
    /* over time sensors: folded when compiling (AND: the later plus its
     * delay, OR: the earlier plus its delay) */
    const char *base = sensor_deck(2022, 0, 7, 0.2, 0.3);
    static const char *const cards[] = {"/SENSOR/AND/7\nboth\n0.05\n         1         2\n",
                                        "/SENSOR/OR/7\neither\n0.05\n         1         2\n"};
    const double want[] = {0.35, 0.25};
    for (int k = 0; k < 2; k++) {
        rc_model *m = TU_COMPILE_OK(edit_deck(base, cards[k], NULL, NULL), "logic1.rad");
        if (m) {
            ENSURE(m->ninter == 1 && m->inter_sens[0] == -1);
            ENSURE_NEAR(m->inter_tstart[0], want[k], 1e-15, 0);
            ENSURE(m->nsens == 3 && m->sens_kind[2] == 2 + k && m->sens_in[4] == 0 && m->sens_in[5] == 1);
        }
        rc_model_free(m);
    }
    /* over a distance sensor that never triggers (Dmax 5 m): AND never on,
     * OR on at its time input (0.3 s), followed in the run */
    static const char *const dcards[] = {"/SENSOR/TIME/6\nt\n0.3\n/SENSOR/AND/7\nboth\n\n         5         6\n",
                                         "/SENSOR/TIME/6\nt\n0.3\n/SENSOR/OR/7\neither\n\n         5         6\n"};
    for (int k = 0; k < 2; k++) {
        const char *text = edit_deck(dist_deck(3, 0, 5.0, 0.0, ""), dcards[k], "0         0         5\n",
                                     "0         0         7\n");
        rc_model *m = TU_COMPILE_OK(text, "logic2.rad");
        if (!m) continue;
        ENSURE(m->inter_sens[0] == 2); /* the logic sensor, found in the run */
        static tu_evlog ev;
        memset(&ev, 0, sizeof ev);
        rc_error e;
        rc_error_clear(&e);
        rc_run_options o = {.on_event = tu_evlog_event, .user = &ev};
        ENSURE(rc_run(m, &o, NULL, &e) == RC_OK);
        double t = -1;
        ENSURE(tu_evlog_first(&ev, "sensor_trigger", &t, NULL) == 0);
        const int n = tu_evlog_first(&ev, "inter_start", &t, NULL);
        if (k == 0) {
            ENSURE(n == 0);
        } else {
            ENSURE(n == 1);
            ENSURE_NEAR(t, 0.3, 1e-12, 0);
        }
        rc_model_free(m);
    }
    /* an interface start on an output time (0.35 s, outputs every 0.01 s):
     * its contact still closes at the free-fall time */
    {
        const char *text = edit_deck(dist_deck(3, 0, 5.0, 0.0, ""), "/SENSOR/TIME/6\nt\n0.35\n",
                                     "0         0         5\n", "0         0         6\n");
        rc_model *m6 = TU_COMPILE_OK(text, "logic4.rad");
        if (m6) {
            static tu_evlog ev;
            memset(&ev, 0, sizeof ev);
            rc_error e;
            rc_error_clear(&e);
            rc_run_options o = {.on_event = tu_evlog_event, .user = &ev};
            ENSURE(rc_run(m6, &o, NULL, &e) == RC_OK);
            double t = -1;
            ENSURE(tu_evlog_first(&ev, "inter_start", &t, NULL) == 1);
            ENSURE_NEAR(t, 0.35, 1e-15, 0);
            ENSURE(tu_evlog_first(&ev, "contact_close", &t, NULL) >= 1);
            ENSURE_NEAR(t, sqrt(2 * 0.9 / 9.81), 1e-10, 0);
        }
        rc_model_free(m6);
    }
    /* a body held by a logic sensor of time sensors: until its folded time */
    rc_model *m = TU_COMPILE_OK(edit_deck(sensor_deck(2022, 7, 0, 0.2, 0.3), cards[0], NULL, NULL), "logic3.rad");
    if (m) {
        ENSURE(m->imp != NULL);
        if (m->imp) ENSURE_NEAR(m->imp->ttstop[0], 0.35, 1e-15, 0);
    }
    rc_model_free(m);
}

/* /SENSOR/NOT: on from its Tdelay while its input is off. Over time
 * sensors its interval is folded into an interface's Tstart and Tstop; a
 * body cannot follow a sensor that turns off again; a NOT of a distance
 * sensor cannot be followed by an interface; an OR of disjoint intervals
 * is refused; a NOT of itself, a cycle of NOTs, a missing input. */
static void test_sensor_not(void)
{
    /* sensor 1 on at 0.4 s, 2 at 0.3 s; the interface (Tstart 0.05, Tstop
     * 0.7) names sensor 7 */
    const char *base = sensor_deck(2022, 0, 7, 0.4, 0.3);
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    ENSURE(rc_case_load(tu_tmp_write("not0.rad", edit_deck(base, "/SENSOR/NOT/7\nnot 1\n0.1\n         1\n", NULL, NULL)),
                        &c, &e) == RC_OK);
    if (!c) fprintf(stderr, "  %s\n", e.msg);
    if (c) {
        const rc_case_sensor *s = &c->sensor[c->nsensor - 1];
        ENSURE(s->id == 7 && s->kind == RC_SENS_NOT && s->in[0] == 1 && s->in[1] == 1);
        ENSURE_NEAR(s->tdelay, 0.1, 1e-15, 0);
    }
    rc_case_free(c);
    static const struct {
        const char *cards;
        double tstart, tstop;
    } ok[] = {
        /* NOT 1 (Tdelay 0.1): on over [0.1, 0.4) */
        {"/SENSOR/NOT/7\nnot 1\n0.1\n         1\n", 0.1, 0.4},
        /* OR of NOT 1 and 2: [0, 0.4) and [0.3, inf) overlap: on for good */
        {"/SENSOR/NOT/8\nnot 1\n\n         1\n/SENSOR/OR/7\neither\n\n         8         2\n", 0.05, 0.7},
        /* AND of NOT 1 and 2: [0.3, 0.4) */
        {"/SENSOR/NOT/8\nnot 1\n\n         1\n/SENSOR/AND/7\nboth\n\n         8         2\n", 0.3, 0.4},
        /* NOT of (NOT 1): on once NOT 1 is off, for good: [0.4, inf) */
        {"/SENSOR/NOT/8\nnot 1\n\n         1\n/SENSOR/NOT/9\nnot 8\n\n         8\n"
         "/SENSOR/OR/7\nsame\n\n         9         9\n", 0.4, 0.7},
    };
    for (size_t k = 0; k < sizeof ok / sizeof ok[0]; k++) {
        rc_model *m = TU_COMPILE_OK(edit_deck(base, ok[k].cards, NULL, NULL), "not1.rad");
        if (m) {
            ENSURE(m->ninter == 1 && m->inter_sens[0] == -1);
            ENSURE_NEAR(m->inter_tstart[0], ok[k].tstart, 1e-15, 0);
            ENSURE_NEAR(m->inter_tstop[0], ok[k].tstop, 1e-15, 0);
        }
        rc_model_free(m);
    }
    /* disjoint: NOT 2 [0, 0.3) or 1 [0.4, inf) */
    TU_EXPECT_TEXT_ERROR(edit_deck(base, "/SENSOR/NOT/8\nnot 2\n\n         2\n/SENSOR/OR/7\neither\n\n         8         1\n",
                                   NULL, NULL),
                         "not2.rad", "/INTER/TYPE6/1", "field Isensor", "two separate time intervals");
    /* empty: NOT 2 with Tdelay 0.5 after 2's time on */
    TU_EXPECT_TEXT_ERROR(edit_deck(base, "/SENSOR/NOT/7\nlate\n0.5\n         2\n", NULL, NULL), "not3.rad",
                         "field Isensor", "never act");
    /* a body released by a NOT: it would be deactivated again */
    TU_EXPECT_TEXT_ERROR(edit_deck(sensor_deck(2022, 7, 0, 0.4, 0.3), "/SENSOR/NOT/7\nnot 1\n\n         1\n", NULL, NULL),
                         "not4.rad", "/RBODY/1", "field sens_ID", "turns off again");
    /* the reader: itself, a missing input, a cycle */
    TU_EXPECT_TEXT_ERROR(edit_deck(base, "/SENSOR/NOT/7\nself\n\n         7\n", NULL, NULL), "not5.rad", "/SENSOR/NOT/7",
                         "field sens_ID1", "the sensor itself");
    TU_EXPECT_TEXT_ERROR(edit_deck(base, "/SENSOR/NOT/7\nmissing\n\n        99\n", NULL, NULL), "not6.rad",
                         "/SENSOR/NOT/7", "field sens_ID1", "no such sensor");
    TU_EXPECT_TEXT_ERROR(edit_deck(base, "/SENSOR/NOT/7\na\n\n         8\n/SENSOR/NOT/8\nb\n\n         7\n", NULL, NULL),
                         "not7.rad", "field sens_ID1", "form a cycle");
    TU_EXPECT_TEXT_ERROR(edit_deck(base, "/SENSOR/NOT/7\nno input\n\n", NULL, NULL), "not8.rad", "/SENSOR/NOT/7",
                         "expected 2 data lines");
    /* a NOT of a distance sensor: turns off at a time found in the run */
    TU_EXPECT_TEXT_ERROR(edit_deck(dist_deck(3, 0, 0.2, 0.0, ""), "/SENSOR/NOT/7\nnot 5\n\n         5\n",
                                   "0         0         5\n", "0         0         7\n"),
                         "not9.rad", "/INTER/POWER/1", "field Isensor", "/SENSOR/NOT");
}

/* A body released by a distance sensor (and by an AND of one): held by
 * imposed zero velocities ended by the sensor (imposed.h tsens) until its
 * time on, found in the run: the event impvel_stop /RBODY/id at the
 * trigger plus Tdelay, free fall after. */
static void test_sensor_release(void)
{
    static const char fmt[] =
        "/BEGIN\nrelease\n      2022         0\n\n\n"
        "/NODE\n1,0,0,1\n2,1,0,1\n3,0,0,1\n"
        "/RBODY/1\nA\n         1                                                 1         1\n0.001,0.001,0.001\n0,0,0\n"
        "/RBODY/2\nB\n         2%10d                                       2         2\n0.002,0.002,0.002\n0,0,0\n"
        "/GRNOD/NODE/1\nA\n1\n/GRNOD/NODE/2\nB\n2\n"
        "/SENSOR/DIST/5\nsensor\n%20.12g\n         1         3                  0.                 0.2\n"
        "/SENSOR/TIME/6\nt\n0.3\n/SENSOR/AND/7\nboth\n0.05\n         5         6\n"
        "/GRAV/1\ng\n         0         Z         0         0         0                             1               -9.81\n"
        "/RUN\n0.5,0.01\n/END\n";
    const double g = 9.81, ts = sqrt(2 * 0.2 / g);
    const struct {
        int sens;
        double td, trel;
    } cs[] = {{5, 0.1, ts + 0.1}, {5, 0.0, ts}, {7, 0.0, 0.35}};
    for (int k = 0; k < 3; k++) {
        char text[4096];
        snprintf(text, sizeof text, fmt, cs[k].sens, cs[k].td);
        rc_model *m = TU_COMPILE_OK(text, "release1.rad");
        if (!m) continue;
        const int si = cs[k].sens == 5 ? 0 : 2;
        ENSURE(m->nsens == 3 && m->sens_hold[si] == 1 && m->sens_hold[1] == 0);
        ENSURE(m->imp != NULL);
        if (m->imp) {
            ENSURE(m->imp->nt == 3 && m->imp->nr == 1);
            for (int j = 0; j < m->imp->nt; j++)
                ENSURE(m->imp->tbody[j] == 1 && m->imp->tsens[j] == si && isinf(m->imp->ttstop[j]));
            if (m->imp->nr == 1) ENSURE(m->imp->rsens[0] == si && isinf(m->imp->rtstop[0]));
        }
        static tu_evlog ev;
        memset(&ev, 0, sizeof ev);
        rc_error e;
        rc_error_clear(&e);
        rc_run_options o = {.on_event = tu_evlog_event, .user = &ev};
        ENSURE(rc_run(m, &o, NULL, &e) == RC_OK);
        double t = -1;
        ENSURE(tu_evlog_first(&ev, "sensor_trigger", &t, NULL) == 1);
        ENSURE_NEAR(t, ts, 1e-10, 0);
        ENSURE(tu_evlog_first(&ev, "impvel_stop", &t, NULL) == 1);
        ENSURE_NEAR(t, cs[k].trel, 1e-10, 0);
        rc_model_free(m);
    }
    /* static analysis: refused */
    char text[4096];
    snprintf(text, sizeof text, fmt, 5, 0.0);
    TU_EXPECT_TEXT_ERROR(edit_deck(text, "/SOLVER\n3\n", NULL, NULL), "release2.rad", "/RBODY/2", "field sens_ID",
                         "static analysis");
}


/* Ball A (/RBODY/1, 1.3 kg, radius 0.05 m, centre at z = 0.15 m) falls
 * onto a floor, /INTER/TYPE6/1 (linear, k = 1e6 N/m, no damping or
 * friction); body B (/RBODY/2, 2 kg, no surface) is held at z = 1 m until
 * /SENSOR/INTER/5 (Tdelay `td`, line 2 `line2`) turns it on; `cards`
 * before /RUN; /BEGIN version `ver`. */
static const char *inter_deck_u(int ver, const char *units, double td, const char *line2, const char *cards)
{
    static char text[4096];
    snprintf(text, sizeof text,
             "/BEGIN\ninterface sensor\n%10d         0\n%s\n\n"
             "/NODE\n1,0,0,0.15\n2,1,0,1\n"
             "/RBODY/1\nA\n         1         0                              1.3\n0.0017,0.0017,0.0017\n0,0,0\n"
             "/RBODY/2\nB\n         2         5                                       2\n0.002,0.002,0.002\n0,0,0\n"
             "/SURF/ELLIPS/2\nball\n0,2,1\n0,0,0.15\n0.05,0.05,0.05\n/SURF/PLANE/3\nfloor\n0,0,0\n0,0,1\n"
             "/FUNCT/1\nlinear\n0,0\n1,1e6\n"
             "/INTER/TYPE6/1\nball on floor\n         2         3          \n\n\n1,0,1,1\n\n\n"
             "/SENSOR/INTER/5\ncontact\n%20.12g\n%s\n%s"
             "/GRAV/1\ng\n         0         Z         0         0         0                           1.0               -9.81\n"
             "/RUN\n0.3,0.01\n/END\n",
             ver, units, td, line2, cards);
    return text;
}

static const char *inter_deck(int ver, double td, const char *line2, const char *cards)
{
    return inter_deck_u(ver, "", td, line2, cards);
}

/* The card in the layouts: int_ID alone before 11.0, DIR Fmin Fmax Tmin
 * from 11.0, Fcut from 14.0; FN and the force in the deck's units. */
static void test_sensor_inter_read(void)
{
    const struct {
        int ver;
        const char *line2;
        int dir;
        double fmax, tmin;
    } cs[] = {{2022, "         1", 0, 0.0, 0.0},
              {2022, "         1        FN                   0                2000", 1, 2000.0, 0.0},
              {2026, "         1        fn                                    1500                   0                   0", 1, 1500.0, 0.0},
              {110, "         1        FN                   0                 300                   0", 1, 300.0, 0.0},
              {100, "         1", 0, 0.0, 0.0},
              {2022, "         1        FN                   0                 300              0.0025", 1, 300.0, 0.0025}};
    for (int k = 0; k < 6; k++) {
        rc_case *c = NULL;
        rc_error e;
        rc_error_clear(&e);
        ENSURE(rc_case_load(tu_tmp_write("inter_read.rad", inter_deck(cs[k].ver, 0.25, cs[k].line2, "")), &c, &e) ==
               RC_OK);
        if (!c) fprintf(stderr, "  case %d: %s\n", k, e.msg);
        if (c) {
            ENSURE(c->nsensor == 1);
            const rc_case_sensor *s = &c->sensor[0];
            ENSURE(s->id == 5 && s->kind == RC_SENS_INTER && s->inter_id == 1 && s->dir == cs[k].dir);
            ENSURE(s->fmax == cs[k].fmax && s->tmin == cs[k].tmin && s->tdelay == 0.25);
            ENSURE(s->line2_loc.line == s->line_loc.line + 1);
        }
        rc_case_free(c);
    }
    /* input in kg, mm, ms: a force unit of 1 kN, Fmax 2 is 2000 N */
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    ENSURE(rc_case_load(tu_tmp_write("inter_kn.rad",
                                     inter_deck_u(2022, "                  kg                  mm                  ms",
                                                  0, "         1        FN                   0                   2", "")),
                        &c, &e) == RC_OK);
    if (!c) fprintf(stderr, "  %s\n", e.msg);
    if (c) ENSURE_NEAR(c->sensor[0].fmax, 2000.0, 1e-9, 0);
    rc_case_free(c);
}

/* The refusals: each names the file's line, the card and the field. */
static void test_sensor_inter_errors(void)
{
    const char *d = "inter_err.rad";
    TU_EXPECT_TEXT_ERROR(inter_deck(2022, 0, "         7", ""), d, "inter_err.rad:", "card /SENSOR/INTER/5",
                         "field int_ID", "got 7 (no such interface)");
    TU_EXPECT_TEXT_ERROR(inter_deck(2022, 0, "         0", ""), d, "card /SENSOR/INTER/5", "field int_ID");
    TU_EXPECT_TEXT_ERROR(inter_deck(2022, 0, "         1        TF                   0                  10", ""), d,
                         "card /SENSOR/INTER/5", "field DIR", "tangential", "not supported yet");
    TU_EXPECT_TEXT_ERROR(inter_deck(2022, 0, "         1        XY", ""), d, "card /SENSOR/INTER/5", "field DIR",
                         "expected blank");
    TU_EXPECT_TEXT_ERROR(inter_deck(2022, 0, "         1        FN                  20                  10", ""), d,
                         "card /SENSOR/INTER/5", "field Fmin", "Fmin < Fmax");
    TU_EXPECT_TEXT_ERROR(inter_deck(2022, 0, "         1        FN                  20                   0", ""), d,
                         "card /SENSOR/INTER/5", "field Fmin", "not supported yet");
    TU_EXPECT_TEXT_ERROR(inter_deck(2022, 0, "         1                             0                  10", ""), d,
                         "card /SENSOR/INTER/5", "field Fmax", "DIR blank", "DIR FN");
    TU_EXPECT_TEXT_ERROR(inter_deck(2022, 0, "         1        FN                   0                 -10", ""), d,
                         "card /SENSOR/INTER/5", "field Fmax");
    TU_EXPECT_TEXT_ERROR(inter_deck(2022, -1, "         1", ""), d, "card /SENSOR/INTER/5", "field Tdelay");
    /* Tmin: with a force bound only (the duration of a first contact is not followed) */
    TU_EXPECT_TEXT_ERROR(inter_deck(2022, 0, "         1                             0                   0              0.001", ""),
                         d, "card /SENSOR/INTER/5", "field Tmin", "first contact", "not supported yet");
    TU_EXPECT_TEXT_ERROR(inter_deck(2022, 0, "         1        FN                   0                  10              -0.001", ""),
                         d, "card /SENSOR/INTER/5", "field Tmin");
    TU_EXPECT_TEXT_ERROR(inter_deck(2022, 0,
                                    "         1        FN                   0                  10                   0"
                                    "                 100",
                                    ""),
                         d, "card /SENSOR/INTER/5", "field Fcut", "not supported yet");
    /* an interface only this sensor turns on: it would never trigger */
    TU_EXPECT_TEXT_ERROR(edit_deck(inter_deck(2022, 0, "         1", ""), "", "         2         3          \n",
                                   "         2         3         5\n"),
                         d, "card /SENSOR/INTER/5", "field int_ID", "turned on by this sensor itself");
    /* a NOT of it naming the held body: it turns off again */
    TU_EXPECT_TEXT_ERROR(edit_deck(inter_deck(2022, 0, "         1", "/SENSOR/NOT/6\nnot\n\n         5\n"), "",
                                   "         2         5              ", "         2         6              "),
                         d, "/RBODY/2", "field sens_ID", "turns off again");
    /* static analysis: a body released by it is refused */
    TU_EXPECT_TEXT_ERROR(inter_deck(2022, 0, "         1", "/SOLVER\n3\n"), d, "/RBODY/2",
                         "field sens_ID", "static analysis");
}

/* The first contact releases B: the sensor triggers at the contact's
 * closing, t_c = sqrt(2 h / g), h = 0.1 m; B is free from t_c + Tdelay
 * and falls g (t_end - t_rel)^2 / 2 by t_end = 0.3 s. With FN and Fmax:
 * the linear contact's force k p(tau) = Fmax, p(tau) = A (1 - cos w tau)
 * + B sin w tau (A = g / w^2, B = v_c / w, w^2 = k / m). */
static void test_sensor_inter_run(void)
{
    const double g = 9.81, tc = sqrt(2 * 0.1 / g), k = 1e6, mass = 1.3, w = sqrt(k / mass);
    const double A = g / (w * w), B = g * tc / w, R = sqrt(A * A + B * B), phi = atan2(A, B);
    const double fmax = 1000.0, tf = tc + (asin((fmax / k - A) / R) + phi) / w;
    const struct {
        const char *line2;
        double td, ttrig;
    } cs[] = {{"         1", 0.0, tc},
              {"         1", 0.05, tc},
              {"         1        FN                   0                   0", 0.0, tc},
              {"         1        FN                   0                1000", 0.0, tf},
              {"         1        FN                   0                1000", 0.02, tf}};
    for (int c = 0; c < 5; c++) {
        rc_model *m = TU_COMPILE_OK(inter_deck(2022, cs[c].td, cs[c].line2, ""), "inter_run.rad");
        if (!m) continue;
        ENSURE(m->nsens == 1 && m->sens_kind[0] == RC_SENS_INTER && m->sens_inter[0] == 1 && m->sens_hold[0] == 1);
        static tu_evlog ev;
        memset(&ev, 0, sizeof ev);
        rc_error e;
        rc_error_clear(&e);
        double *y = calloc((size_t)m->ny + 1, sizeof *y);
        rc_run_options o = {.on_event = tu_evlog_event, .user = &ev, .y_end = y};
        ENSURE(rc_run(m, &o, NULL, &e) == RC_OK);
        double t = -1, tcl = -1, v[3] = {0};
        ENSURE(tu_evlog_first(&ev, "contact_close", &tcl, NULL) >= 1);
        ENSURE_NEAR(tcl, tc, 1e-10, 0);
        ENSURE(tu_evlog_first(&ev, "sensor_trigger", &t, v) == 1);
        if (t < 0) fprintf(stderr, "  case %d: no trigger\n", c);
        ENSURE_NEAR(t, cs[c].ttrig, 1e-9, 0);
        ENSURE(isnan(v[0])); /* not an interface */
        for (int j = 0; j < ev.n && j < TU_MAXEV; j++)
            if (!strcmp(ev.kind[j], "sensor_trigger")) ENSURE(!strcmp(ev.elem[j], "/SENSOR/INTER/5"));
        double trel = -1;
        ENSURE(tu_evlog_first(&ev, "impvel_stop", &trel, NULL) == 1);
        ENSURE_NEAR(trel, cs[c].ttrig + cs[c].td, 1e-9, 0);
        /* B's free fall from rest at the release */
        const int a = m->body_yadr[1];
        if (a >= 0) {
            const double drop = m->body_y0[RC_NB * 1 + 2] - y[a + 2], want = 0.5 * g * pow(0.3 - trel, 2);
            ENSURE_NEAR(drop, want, 1e-6, 1e-6);
            ENSURE_NEAR(y[a + 9], -g * (0.3 - trel), 1e-6, 1e-6);
        }
        free(y);
        rc_model_free(m);
    }
    /* as an input of an AND with a time sensor at 0.2 s: the later */
    rc_model *m = TU_COMPILE_OK(edit_deck(inter_deck(2022, 0, "         1",
                                                     "/SENSOR/TIME/6\nt\n0.2\n/SENSOR/AND/7\nboth\n0.01\n         5         6\n"),
                                          "", "         2         5              ", "         2         7              "),
                                "inter_and.rad");
    if (m) {
        static tu_evlog ev;
        memset(&ev, 0, sizeof ev);
        rc_error e;
        rc_error_clear(&e);
        rc_run_options o = {.on_event = tu_evlog_event, .user = &ev};
        ENSURE(rc_run(m, &o, NULL, &e) == RC_OK);
        double t = -1, trel = -1;
        ENSURE(tu_evlog_first(&ev, "sensor_trigger", &t, NULL) == 1);
        ENSURE_NEAR(t, tc, 1e-9, 0);
        ENSURE(tu_evlog_first(&ev, "impvel_stop", &trel, NULL) == 1);
        ENSURE_NEAR(trel, 0.21, 1e-12, 0);
    }
    rc_model_free(m);
}

/* The sensor on other interfaces and states: an /INTER/POWER (ball A
 * falling onto the fixed ball B, K = 1e7, m1 = 1.5) releasing body C at
 * their meeting sqrt(2 (z0 - R_A - R_B) / g); a contact already closed at
 * t = 0 (A penetrating the floor) triggering at t = 0; a NOT of it naming
 * an interface: refused (it would turn the interface off at a time found
 * in the run). */
static void test_sensor_inter_kinds(void)
{
    const double g = 9.81, tc = sqrt(2 * 0.9 / g);
    static const char power[] =
        "/BEGIN\npower contact sensor\n      2022         0\n\n\n"
        "/NODE\n1,0,0,1\n2,0,0,0\n3,1,0,1\n"
        "/RBODY/1\nA\n         1                                                 1         1\n0.001,0.001,0.001\n0,0,0\n"
        "/RBODY/2\nB\n         2                                                 1         2\n0.001,0.001,0.001\n0,0,0\n"
        "/RBODY/3\nC\n         3         6                                       2         3\n0.002,0.002,0.002\n0,0,0\n"
        "/GRNOD/NODE/1\nA\n1\n/GRNOD/NODE/2\nB\n2\n/GRNOD/NODE/3\nC\n3\n/BCS/1\nB fixed\n   111 111         0         2\n"
        "/SURF/ELLIPS/1\nA\n0,2,1\n0,0,1\n0.05,0.05,0.05\n/SURF/ELLIPS/2\nB\n0,2,2\n0,0,0\n0.05,0.05,0.05\n"
        "/SENSOR/INTER/6\nA on B\n\n         4\n"
        "/INTER/POWER/4\nA on B\n         1         2         0         0         0         0         0\n"
        "            10000000                 1.5\n\n\n"
        "/GRAV/1\ng\n         0         Z         0         0         0                             1               -9.81\n"
        "/RUN\n0.6,0.01\n/END\n";
    rc_model *m = TU_COMPILE_OK(power, "inter_power.rad");
    if (m) {
        ENSURE(m->nsens == 1 && m->sens_inter[0] == 4 && m->sens_hold[0] == 1);
        static tu_evlog ev;
        memset(&ev, 0, sizeof ev);
        rc_error e;
        rc_error_clear(&e);
        rc_run_options o = {.on_event = tu_evlog_event, .user = &ev};
        ENSURE(rc_run(m, &o, NULL, &e) == RC_OK);
        double t = -1, tcl = -1, trel = -1;
        ENSURE(tu_evlog_first(&ev, "contact_close", &tcl, NULL) >= 1);
        ENSURE(tu_evlog_first(&ev, "sensor_trigger", &t, NULL) == 1);
        ENSURE_NEAR(t, tc, 1e-9, 0);
        ENSURE(t == tcl);
        ENSURE(tu_evlog_first(&ev, "impvel_stop", &trel, NULL) == 1 && trel == t);
    }
    rc_model_free(m);
    /* closed at the start: A's centre 0.04999 m above the floor (R = 0.05 m) */
    static char pen[4096];
    snprintf(pen, sizeof pen, "%s", inter_deck(2022, 0, "         1", ""));
    for (int k = 0; k < 2; k++) {
        char *w = strstr(pen, "0,0,0.15\n"), tail[4096];
        if (!w) break;
        snprintf(tail, sizeof tail, "%s", w + strlen("0,0,0.15"));
        snprintf(w, sizeof pen - (size_t)(w - pen), "0,0,0.04999%s", tail);
    }
    m = TU_COMPILE_OK(pen, "inter_pen.rad");
    if (m) {
        static tu_evlog ev;
        memset(&ev, 0, sizeof ev);
        rc_error e;
        rc_error_clear(&e);
        double *y = calloc((size_t)m->ny + 1, sizeof *y);
        rc_run_options o = {.on_event = tu_evlog_event, .user = &ev, .y_end = y};
        ENSURE(rc_run(m, &o, NULL, &e) == RC_OK);
        double t = -1, trel = -1;
        ENSURE(tu_evlog_first(&ev, "sensor_trigger", &t, NULL) == 1 && t == 0.0);
        ENSURE(tu_evlog_first(&ev, "impvel_stop", &trel, NULL) == 1 && trel == 0.0);
        const int a = m->body_yadr[1];
        if (a >= 0 && y) ENSURE_NEAR(m->body_y0[RC_NB * 1 + 2] - y[a + 2], 0.5 * g * 0.3 * 0.3, 1e-7, 1e-7);
        free(y);
    }
    rc_model_free(m);
    /* a NOT of it naming an interface */
    TU_EXPECT_TEXT_ERROR(edit_deck(inter_deck(2022, 0, "         1",
                                              "/SENSOR/NOT/6\nnot\n\n         5\n/SURF/PLANE/7\nwall\n2,0,0\n-1,0,0\n"
                                              "/INTER/TYPE6/8\nball on wall\n         2         7         6\n\n\n1,0,1,1\n\n\n"),
                                   "", "         2         5              ", "         2         0              "),
                         "inter_not.rad", "/INTER/TYPE6/8", "field Isensor", "/SENSOR/NOT/6",
                         "distance or interface sensor");
}

/* Loads switched on by a sensor (/IMPVEL and /GRAV sensor_ID): a body
 * (/RBODY/1, 1.3 kg, node 1 at (0, 0, 1) m) and the sensors
 * /SENSOR/TIME/1 (Tdelay t1), /SENSOR/TIME/2 (Tdelay 0.15 s),
 * /SENSOR/AND/3 of both (Tdelay 0.05 s), /SENSOR/NOT/4 of 1 and
 * /SENSOR/DIST/5 (nodes 1 and 2, Dmax 0.1 m); `cards` before /RUN
 * (0.5 s). */
static const char *load_solver =
    "/SOLVER\n         1         5    100000               1e-10                   0                   0\n"
    "               1e-14               1e-11               1e-12               1e-06\n               1e-12\n";

static const char *load_deck_s(double t1, const char *cards, const char *solver)
{
    static char text[4096];
    snprintf(text, sizeof text,
             "/BEGIN\nloads by sensors\n      2022         0\n\n\n"
             "/NODE\n1,0,0,1\n2,0,0,1\n"
             "/RBODY/1\nbody\n         1         0                              1.3\n0.0017,0.0017,0.0017\n0,0,0\n"
             "/GRNOD/NODE/1\nbody\n1\n"
             "/FUNCT/1\nramp\n0,0\n10,10\n/FUNCT/2\none\n0,1\n10,1\n/FUNCT/3\nramp then flat\n0,0\n0.1,0.1\n10,0.1\n"
             "/SENSOR/TIME/1\nt1\n%20.12g\n/SENSOR/TIME/2\nt2\n0.15\n/SENSOR/AND/3\nboth\n0.05\n         1         2\n"
             "/SENSOR/NOT/4\nnot 1\n\n         1\n"
             "/SENSOR/DIST/5\ndistance\n\n         1         2                  0.                 0.1\n"
             "%s/RUN\n0.5,0.01\n%s/END\n",
             t1, cards, solver);
    return text;
}

static const char *load_deck(double t1, const char *cards) { return load_deck_s(t1, cards, load_solver); }

/* The state of a model run to t_end [s] (the deck's coordinates), its
 * events in ev. Returns 0 when the run succeeded. */
static int run_to(rc_model *m, double t_end, double *y, tu_evlog *ev)
{
    rc_error e;
    rc_error_clear(&e);
    if (ev) memset(ev, 0, sizeof *ev);
    rc_run_options o = {.t_end_override = t_end, .y_end = y, .on_event = ev ? tu_evlog_event : NULL, .user = ev};
    const rc_status st = rc_run(m, &o, NULL, &e);
    if (st) fprintf(stderr, "  run: %s\n", e.msg);
    return st != RC_OK;
}

/* /IMPVEL sensor_ID: a time sensor (Tdelay T = 0.2 s) starts a velocity
 * X = 2 f(t - T), f(s) = s up to s = 0.1 s then 0.1 (/FUNCT/3): at rest
 * until T, then x(t) = (t - T)^2 m up to T + 0.1 s, 0.01 + 0.2 (t - T -
 * 0.1) m after (the function shifted by the sensor's time, as Radioss
 * does); the start is a time breakpoint (impvel_start at T). */
static void test_sensor_impvel_time(void)
{
    const double T = 0.2;
    const char *cards = "/IMPVEL/1\nX by sensor 1\n         3         X         0         1         1         0         0\n"
                        "                   1                   2\n";
    rc_model *m = TU_COMPILE_OK(load_deck(T, cards), "load_impvel.rad");
    if (!m) return;
    ENSURE(m->imp && m->imp->nt == 1 && m->imp->nr == 0);
    if (m->imp && m->imp->nt == 1) {
        ENSURE(m->imp->ttstart[0] == T && m->imp->ttshift[0] == T && m->imp->tsens[0] < 0);
        ENSURE(m->body_y0[7] == 0.0); /* free (at rest) before its start */
    }
    static tu_evlog ev;
    double *y = calloc((size_t)m->ny, sizeof *y);
    const double ts[] = {0.1, 0.2, 0.35, 0.5};
    for (int k = 0; k < 4 && y; k++) {
        ENSURE(run_to(m, ts[k], y, &ev) == 0);
        const double dt = ts[k] > T ? ts[k] - T : 0.0;
        ENSURE_NEAR(y[m->body_yadr[0]], dt <= 0.1 ? dt * dt : 0.01 + 0.2 * (dt - 0.1), 1e-8, 0);
        ENSURE_NEAR(y[m->body_yadr[0] + 7], dt <= 0.1 ? 2 * dt : 0.2, 1e-9, 0);
        ENSURE_NEAR(y[m->body_yadr[0] + 2], 1.0, 1e-12, 0); /* no gravity */
        double t = -1;
        if (ts[k] > T) {
            ENSURE(tu_evlog_first(&ev, "impvel_start", &t, NULL) == 1);
            ENSURE_NEAR(t, T, 1e-14, 0);
        } else {
            ENSURE(tu_evlog_first(&ev, "impvel_start", &t, NULL) == 0);
        }
    }
    free(y);
    rc_model_free(m);
    /* an AND of time sensors folded: on at max(0.1, 0.15) + 0.05 s */
    static const char and3[] = "/IMPVEL/1\nX by sensor 3\n         2         X         0         3         1         0         0\n"
                               "                   1                 0.5\n";
    m = TU_COMPILE_OK(load_deck(0.1, and3), "load_impvel_and.rad");
    if (m && m->imp && m->imp->nt == 1) {
        ENSURE_NEAR(m->imp->ttstart[0], 0.2, 1e-15, 0);
        y = calloc((size_t)m->ny, sizeof *y);
        if (y && run_to(m, 0.5, y, NULL) == 0) ENSURE_NEAR(y[m->body_yadr[0]], 0.5 * 0.3, 1e-9, 0);
        free(y);
    }
    rc_model_free(m);
    /* a sensor on at t = 0 (Tdelay 0): imposed from the start, unshifted */
    m = TU_COMPILE_OK(load_deck(0.0, cards), "load_impvel0.rad");
    if (m && m->imp && m->imp->nt == 1) ENSURE(isinf(m->imp->ttstart[0]) && m->imp->ttshift[0] == 0.0);
    rc_model_free(m);
}

/* /GRAV sensor_ID: gravity from the sensor's time T on: z(t) = z0 for
 * t <= T, z0 - g (t - T)^2 / 2 after (a constant gravity, AND sensor 3 on
 * at 0.2 s); with the ramp f(s) = s as time function, g(t) = -9.81
 * (t - T) m/s^2 (shifted): z0 - 9.81 (t - T)^3 / 6. */
static void test_sensor_grav_time(void)
{
    const double T = 0.2, g = 9.81;
    static const char c0[] =
        "/GRAV/1\ng\n         0         Z         0         3         0                             1               -9.81\n";
    static const char c1[] =
        "/GRAV/1\ng\n         1         Z         0         3         0                             1               -9.81\n";
    for (int f = 0; f < 2; f++) {
        rc_model *m = TU_COMPILE_OK(load_deck(0.1, f ? c1 : c0), "load_grav.rad");
        if (!m) continue;
        ENSURE_NEAR(m->grav_tstart, T, 1e-15, 0);
        ENSURE(m->gwork_adr >= 0); /* a gravity that varies in time: its work integrated */
        double *y = calloc((size_t)m->ny, sizeof *y);
        const double ts[] = {0.15, 0.2, 0.3, 0.5};
        for (int k = 0; k < 4 && y; k++) {
            ENSURE(run_to(m, ts[k], y, NULL) == 0);
            const double dt = ts[k] > T ? ts[k] - T : 0.0;
            const double z = f ? 1.0 - g * dt * dt * dt / 6.0 : 1.0 - 0.5 * g * dt * dt;
            const double vz = f ? -0.5 * g * dt * dt : -g * dt;
            ENSURE_NEAR(y[m->body_yadr[0] + 2], z, 1e-9, 0);
            ENSURE_NEAR(y[m->body_yadr[0] + 9], vz, 1e-9, 0);
            /* the work of gravity: -m g.(x - x0) for a constant one */
            if (!f) ENSURE_NEAR(y[m->gwork_adr], -1.3 * g * (1.0 - z), 1e-8, 0);
        }
        free(y);
        rc_model_free(m);
    }
}

/* The refusals: a sensor that does not exist, one found in the run, one
 * that turns off again or never turns on, a start outside [Tstart, Tstop),
 * a rotation started later, two /GRAV starting at different times, a
 * static analysis with a later start. */
static void test_sensor_load_errors(void)
{
    static const char iv[] = "/IMPVEL/1\nX\n         2         X         0%10d         1         0         0\n"
                             "                   1                 0.5%20s%20s\n";
    char cards[1024];
    snprintf(cards, sizeof cards, iv, 9, "", "");
    TU_EXPECT_TEXT_ERROR(load_deck(0.2, cards), "load_e1.rad", "load_e1.rad:", "/IMPVEL/1", "field sensor_ID",
                         "no such sensor");
    /* a distance sensor: accepted (a start at its event: test_sensor_load_runtime) */
    snprintf(cards, sizeof cards, iv, 5, "", "");
    rc_model *md = TU_COMPILE_OK(load_deck(0.2, cards), "load_e2.rad");
    if (md) ENSURE(md->imp && md->imp->nt == 1 && md->imp->tson[0] == 4 && md->sens_hold[4] == 1);
    rc_model_free(md);
    snprintf(cards, sizeof cards, iv, 4, "", "");
    TU_EXPECT_TEXT_ERROR(load_deck(0.2, cards), "load_e3.rad", "/IMPVEL/1", "field sensor_ID", "/SENSOR/NOT/4",
                         "turns off again");
    snprintf(cards, sizeof cards, iv, 1, "0.3", "");
    TU_EXPECT_TEXT_ERROR(load_deck(0.2, cards), "load_e4.rad", "/IMPVEL/1", "field sensor_ID", "outside [Tstart, Tstop)",
                         "never act");
    snprintf(cards, sizeof cards, iv, 1, "", "0.1");
    TU_EXPECT_TEXT_ERROR(load_deck(0.2, cards), "load_e5.rad", "/IMPVEL/1", "outside [Tstart, Tstop)");
    TU_EXPECT_TEXT_ERROR(load_deck(0.2, "/IMPVEL/1\nZZ\n         2        ZZ         0         1         1         0         0\n"
                                        "                   1                 0.5\n"),
                         "load_e6.rad", "/IMPVEL/1", "field sensor_ID", "imposed rotation", "not supported yet");
    TU_EXPECT_TEXT_ERROR(load_deck(0.2, "/GRAV/1\ng\n         0         Z         0         9         0                             1               -9.81\n"),
                         "load_e7.rad", "load_e7.rad:", "/GRAV/1", "field sensor_ID", "no such sensor");
    md = TU_COMPILE_OK(load_deck(0.2, "/GRAV/1\ng\n         0         Z         0         5         0                             1               -9.81\n"),
                       "load_e8.rad");
    if (md) ENSURE(md->grav_sens == 4 && md->grav_tstart == 0.0);
    rc_model_free(md);
    TU_EXPECT_TEXT_ERROR(load_deck(0.2, "/GRAV/1\ng\n         0         Z         0         4         0                             1               -9.81\n"),
                         "load_e9.rad", "/GRAV/1", "field sensor_ID", "/SENSOR/NOT/4", "turns off again");
    TU_EXPECT_TEXT_ERROR(load_deck(0.2, "/GRAV/1\ng\n         0         Z         0         1         0                             1               -9.81\n"
                                        "/GRAV/2\ng2\n         0         X         0         0         0                             1                   1\n"),
                         "load_e10.rad", "/GRAV/2", "field sensor_ID", "start at one time");
    /* a NOT never on (its input on from t = 0) */
    TU_EXPECT_TEXT_ERROR(load_deck(0.0, "/GRAV/1\ng\n         0         Z         0         4         0                             1               -9.81\n"),
                         "load_e11.rad", "/GRAV/1", "/SENSOR/NOT/4", "never turns on");
    /* a static analysis: refused for a later start; fine from t = 0 */
    TU_EXPECT_TEXT_ERROR(load_deck_s(0.2, "/GRAV/1\ng\n         0         Z         0         1         0                             1               -9.81\n",
                                     "/SOLVER\n3\n"),
                         "load_e12.rad", "/GRAV", "field sensor_ID", "static analysis", "0.2 s");
    snprintf(cards, sizeof cards, iv, 1, "", "");
    TU_EXPECT_TEXT_ERROR(load_deck_s(0.2, cards, "/SOLVER\n3\n"), "load_e13.rad", "/IMPVEL", "static analysis", "sensor_ID's time");
    /* a preload and the sensitivities: refused for a gravity switched on
     * later; from t = 0 (Tdelay 0) the preload is accepted */
    static const char g1[] =
        "/GRAV/1\ng\n         0         Z         0         1         0                             1               -9.81\n";
    for (int late = 0; late < 2; late++) {
        rc_model *m = TU_COMPILE_OK(load_deck(late ? 0.2 : 0.0, g1), "load_pre.rad");
        if (!m) continue;
        rc_error e;
        rc_error_clear(&e);
        const rc_status st = rc_model_set_preload(m, 1, &e);
        ENSURE(late ? st == RC_EINPUT : st == RC_OK);
        if (late) ENSURE(strstr(e.msg, "a gravity switched on by its sensor at 0.2 s") != NULL);
        if (late) {
            const int ny = rc_model_state_size(m);
            double *y = calloc((size_t)ny, sizeof(double)), *sv = calloc((size_t)ny, sizeof(double));
            const rc_model *mm[1] = {m};
            const double val[1] = {1.3}, dp[1] = {1e-4}, at[1] = {0.3};
            rc_error_clear(&e);
            ENSURE(rc_sens_run(m, 1, mm, mm, val, dp, 1, at, y, sv, NULL, NULL, NULL, &e) == RC_EINPUT);
            ENSURE(strstr(e.msg, "switched on by its sensor at 0.2 s is not covered") != NULL);
            free(y);
            free(sv);
        }
        rc_model_free(m);
    }
}

/* Loads started at a time found in the run: ball A (/RBODY/1, 1.3 kg,
 * radius 0.05 m, its lowest point h = 0.1 m over a floor) is thrown down
 * at 1 m/s with no gravity; /SENSOR/INTER/5 (Tdelay `td`) watches its
 * floor contact (TYPE6, k = 1e6 N/m), which closes at t_c = h / v0 =
 * 0.1 s; body B (/RBODY/2, 2 kg, no surface, at (1, 0, 1) m) has
 * `cards` (an /IMPVEL, a /GRAV naming sensor 5); `extra` before /RUN. */
static const char *rt_deck(double td, const char *cards, const char *extra)
{
    static char text[4096];
    snprintf(text, sizeof text,
             "/BEGIN\nrun-time load start\n      2022         0\n\n\n"
             "/NODE\n1,0,0,0.15\n2,1,0,1\n"
             "/RBODY/1\nA\n         1         0                              1.3\n0.0017,0.0017,0.0017\n0,0,0\n"
             "/RBODY/2\nB\n         2         0                                2\n0.002,0.002,0.002\n0,0,0\n"
             "/GRNOD/NODE/1\nA\n1\n/GRNOD/NODE/2\nB\n2\n"
             "/SURF/ELLIPS/2\nball\n0,2,1\n0,0,0.15\n0.05,0.05,0.05\n/SURF/PLANE/3\nfloor\n0,0,0\n0,0,1\n"
             "/FUNCT/1\nlinear\n0,0\n1,1e6\n/FUNCT/3\nramp then flat\n0,0\n0.1,0.1\n10,0.1\n"
             "/FUNCT/4\none\n0,1\n10,1\n"
             "/INTER/TYPE6/1\nball on floor\n         2         3          \n\n\n1,0,1,1\n\n\n"
             "/SENSOR/INTER/5\ncontact\n%20.12g\n         1\n"
             "/INIVEL/TRA/1\nthrown down\n0,0,-1,1,0\n"
             "%s%s/RUN\n0.4,0.01\n"
             "/SOLVER\n         1         5    100000               1e-10                   0                   0\n"
             "               1e-14               1e-11               1e-12               1e-06\n               1e-12\n/END\n",
             td, cards, extra);
    return text;
}

/* /IMPVEL and /GRAV sensor_ID naming an interface sensor: the imposed
 * velocity X of B = 2 f(t - t_on) (f: 0.1 s ramp to 0.1, /FUNCT/3), Y of
 * B = 0.3 m/s (/FUNCT/4: the velocity jumps from 0 at t_on) and a gravity
 * (B alone, 9.81 m/s^2 down) from t_on = t_c + Tdelay; B's x, y and z
 * against the closed forms, the start events at t_on. */
static void test_sensor_load_runtime(void)
{
    static tu_evlog ev;
    const double tc = 0.1, g = 9.81;
    static const char cards[] =
        "/IMPVEL/1\nX of B\n         3         X         0         5         2         0         0\n"
        "                   1                   2\n"
        "/IMPVEL/2\nY of B\n         4         Y         0         5         2         0         0\n"
        "                   1                 0.3\n"
        "/GRAV/1\ng on B\n         0         Z         0         5         2                             1               -9.81\n";
    for (int k = 0; k < 2; k++) {
        const double td = k ? 0.05 : 0.0, ton = tc + td;
        rc_model *m = TU_COMPILE_OK(rt_deck(td, cards, ""), "load_rt.rad");
        if (!m) continue;
        ENSURE(m->nsens == 1 && m->sens_hold[0] == 1 && m->grav_sens == 0 && m->gwork_adr >= 0);
        ENSURE(m->imp && m->imp->nt == 2);
        if (m->imp && m->imp->nt == 2)
            for (int j = 0; j < 2; j++) ENSURE(m->imp->tson[j] == 0 && isinf(m->imp->ttstart[j]));
        double *y = calloc((size_t)m->ny, sizeof *y);
        const double ts[] = {0.05, 0.12, 0.18, 0.4};
        for (int j = 0; j < 4 && y; j++) {
            ENSURE(run_to(m, ts[j], y, &ev) == 0);
            const int a = m->body_yadr[1];
            const double dt = ts[j] > ton ? ts[j] - ton : 0.0;
            ENSURE_NEAR(y[a], 1.0 + (dt <= 0.1 ? dt * dt : 0.01 + 0.2 * (dt - 0.1)), 1e-8, 0);
            ENSURE_NEAR(y[a + 7], dt <= 0.1 ? 2 * dt : 0.2, 1e-8, 0);
            ENSURE_NEAR(y[a + 2], 1.0 - 0.5 * g * dt * dt, 1e-8, 0);
            ENSURE_NEAR(y[a + 1], 0.3 * dt, 1e-8, 0);
            ENSURE_NEAR(y[a + 8], ts[j] > ton ? 0.3 : 0.0, 1e-10, 0);
            double t = -1;
            if (ts[j] > ton) {
                ENSURE(tu_evlog_first(&ev, "sensor_trigger", &t, NULL) == 1);
                ENSURE_NEAR(t, tc, 1e-10, 0);
                ENSURE(tu_evlog_first(&ev, "impvel_start", &t, NULL) == 2);
                ENSURE_NEAR(t, ton, 1e-10, 0);
            } else {
                ENSURE(tu_evlog_first(&ev, "impvel_start", &t, NULL) == 0);
            }
            /* A, with no gravity, still falls at 1 m/s before its contact */
            if (ts[j] < tc) ENSURE_NEAR(y[m->body_yadr[0] + 2], 0.15 - ts[j], 1e-10, 0);
        }
        free(y);
        rc_model_free(m);
    }
    /* refused: a static analysis, a preload, the sensitivities; a NOT of
     * the interface sensor; a rotation; Tstart > 0 with it */
    TU_EXPECT_TEXT_ERROR(rt_deck(0, cards, "/SENSOR/NOT/6\nnot\n\n         5\n"
                                           "/GRAV/2\ng2\n         0         Z         0         6         1                             1               -9.81\n"),
                         "load_rt1.rad", "/GRAV/2", "field sensor_ID", "/SENSOR/NOT/6", "turns off again");
    TU_EXPECT_TEXT_ERROR(rt_deck(0, "/IMPVEL/1\nZZ of B\n         3        ZZ         0         5         2         0         0\n", ""),
                         "load_rt2.rad", "/IMPVEL/1", "field sensor_ID", "imposed rotation", "not supported yet");
    TU_EXPECT_TEXT_ERROR(rt_deck(0, "/IMPVEL/1\nX of B\n         3         X         0         5         2         0         0\n"
                                    "                   1                   2                 0.2\n", ""),
                         "load_rt3.rad", "/IMPVEL/1", "field Tstart", "not supported yet");
    TU_EXPECT_TEXT_ERROR(rt_deck(0, cards, "/GRAV/2\ng2\n         0         Z         0         0         1                             1               -9.81\n"),
                         "load_rt4.rad", "/GRAV/2", "field sensor_ID", "start at one time");
    rc_model *m = TU_COMPILE_OK(rt_deck(0, cards, ""), "load_rt5.rad");
    if (m) {
        rc_error e;
        rc_error_clear(&e);
        ENSURE(rc_model_set_preload(m, 1, &e) == RC_EINPUT);
        ENSURE(strstr(e.msg, "started by a sensor found in the run") != NULL);
        const int ny = rc_model_state_size(m);
        double *y = calloc((size_t)ny, sizeof(double)), *sv = calloc((size_t)ny, sizeof(double));
        const rc_model *mm[1] = {m};
        const double val[1] = {1.3}, dp[1] = {1e-4}, at[1] = {0.3};
        rc_error_clear(&e);
        ENSURE(rc_sens_run(m, 1, mm, mm, val, dp, 1, at, y, sv, NULL, NULL, NULL, &e) == RC_EINPUT);
        ENSURE(strstr(e.msg, "at a time found in the run is not covered") != NULL);
        free(y);
        free(sv);
    }
    rc_model_free(m);
}

void suite_sensor(void);
void suite_sensor(void)
{
    RUN_TEST(test_sensor_compile);
    RUN_TEST(test_sensor_dist_read);
    RUN_TEST(test_sensor_dist_compile);
    RUN_TEST(test_sensor_dist_run);
    RUN_TEST(test_sensor_logic);
    RUN_TEST(test_sensor_not);
    RUN_TEST(test_sensor_release);
    RUN_TEST(test_sensor_inter_read);
    RUN_TEST(test_sensor_inter_errors);
    RUN_TEST(test_sensor_inter_run);
    RUN_TEST(test_sensor_inter_kinds);
    RUN_TEST(test_sensor_impvel_time);
    RUN_TEST(test_sensor_grav_time);
    RUN_TEST(test_sensor_load_errors);
    RUN_TEST(test_sensor_load_runtime);
}
