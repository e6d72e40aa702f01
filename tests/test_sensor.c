/*
 * Time sensors (/SENSOR/TIME): the card, and what the compiler makes of
 * the sensors of a body (held by six imposed zero velocities until the
 * sensor's time, model/sensor.c) and of interfaces (their start raised to
 * the sensor's time); a sensor at t = 0 holds nothing; the TYPE6 layouts
 * before 14.0 have no Isensor.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/error.h"
#include "case/case.h"
#include "harness.h"
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

void suite_sensor(void);
void suite_sensor(void) { RUN_TEST(test_sensor_compile); }
