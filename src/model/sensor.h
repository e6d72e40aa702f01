/*
 * Time sensors (/SENSOR/TIME), distance sensors (/SENSOR/DIST), interface
 * sensors (/SENSOR/INTER), logic sensors (AND, OR, NOT) and what they activate (model/sensor.c,
 * docs/theory.md "Sensors"): an interface naming a sensor (TYPE6 and
 * /INTER/POWER Isensor) is inactive before the sensor's time; a body
 * naming one (/RBODY sens_ID) is held at rest in its initial pose until
 * then, by imposed zero velocities of its six degrees of freedom that end
 * at the sensor's time (the /IMPVEL machinery: a breakpoint and a restart
 * there; for a time found in the run, the sensor's release event), and is
 * free afterwards.
 */
#ifndef RC_MODEL_SENSOR_H
#define RC_MODEL_SENSOR_H

#include "case/case.h"
#include "model/model.h"

typedef struct rc_sensor_case {
    rc_case c;                    /* the case with the holds appended       */
    struct rc_case_impvel *impvel; /* [nimpvel + 6 held bodies] owned        */
    rc_case_grnod *grnod;         /* [ngrnod + held bodies] owned           */
    rc_case_funct *funct;         /* [nfunct + 1] owned                     */
    int *nodes;                   /* [held bodies] the groups' node ids     */
    double fx[2], fy[2];          /* the zero function of the holds         */
} rc_sensor_case;

/* The copy of c with, for each /RBODY whose sensor's time is > 0 or found
 * in the run, a node group of its main node (id -rbody_ID) and six /IMPVEL
 * (id -rbody_ID) holding its velocities at zero until that time (the zero
 * function, id -2; a time found in the run: Tstop INFINITY and hold_sens);
 * x->c is c itself when no body has a sensor. RC_EINPUT at the /RBODY
 * line for a sensor that does not exist, one that turns off again (a
 * /SENSOR/NOT), or a held body that also has an /INIVEL, /IMPVEL, /BCS or
 * /JOINT (not supported yet). */
rc_status rc_sensor_begin(const rc_case *c, rc_sensor_case *x, rc_error *err);
void rc_sensor_end(rc_sensor_case *x);
/* The start of an interface of `card` (read at `loc`) whose Isensor is
 * sensor_id: for a sensor known when compiling, on over [a, b), *tstart
 * raised to a and *tstop lowered to b (a /SENSOR/NOT turns off at its
 * input's time on); *sens the index of a sensor found in the run (the
 * interface turns on when it does), -1 otherwise; RC_EINPUT when the sensor
 * does not exist, leaves the interface no time between start and stop, is
 * on over two separate intervals, or turns off at a time found in the run
 * (a NOT of a distance sensor). */
rc_status rc_sensor_tstart(const rc_case *c, int sensor_id, rc_loc loc, const char *card, double *tstart,
                           double *tstop, int *sens, rc_error *err);
/* The time a load of `card` (an /IMPVEL, a /GRAV, read at `loc`) starts
 * whose sensor_ID is sensor_id (`what` names the load in messages): 0 for
 * no sensor; a sensor known when compiling that turns on for good: its
 * time on [s] (a time sensor's Tdelay, a logic sensor's from its inputs');
 * a sensor found in the run (a distance or interface sensor, or a logic
 * sensor of one): *ton INFINITY and *sens its index (the load starts at
 * its event; otherwise *sens is -1). RC_EINPUT at loc, field sensor_ID,
 * when the sensor does not exist, turns off again (a /SENSOR/NOT of a
 * sensor that turns on), or never turns on. */
rc_status rc_sensor_load_on(const rc_case *c, int sensor_id, rc_loc loc, const char *card, const char *what,
                            double *ton, int *sens, rc_error *err);
/* The model's sensors (m->sens_*), one per /SENSOR card: a distance
 * sensor's nodes in their bodies' frames (the bodies' initial poses, in
 * the origin's coordinates: after the origin shift); an interface
 * sensor's /INTER id and force bound (after the interfaces are compiled).
 * RC_EINPUT at the nodes' line for a node that does not exist, or two
 * nodes of one body (or both fixed in space); at an interface sensor's
 * line 2 for an int_ID no interface has, or an interface only this sensor
 * turns on. */
rc_status rc_sensor_compile(const rc_case *c, rc_model *m, rc_error *err);
/* "TIME", "DIST", "AND", "OR", "NOT", "INTER" for a model's sens_kind; "?" otherwise. */
const char *rc_sensor_kind_name(int kind);
/* For the model summary: ", on by /SENSOR/<kind>/<id> (time found in the
 * run)" for an interface under a run-time sensor, "" otherwise (a static
 * buffer). */
const char *rc_sensor_note(const rc_model *m, int i);

#endif
