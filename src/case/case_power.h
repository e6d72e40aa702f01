/*
 * Parsed cards of the power-law contact and the roller (docs/theory.md 9):
 * /INTER/POWER (ricochet card) and /IMPVEL (Radioss layout), read by
 * cards_interfaces.c and cards_loads.c (/SURF/CYL and /SURF/BOX, in
 * cards_surfaces.c, fill rc_case_surf), compiled by model/power.c and
 * model/imposed.c. Part of rc_case (case.h:
 * npower, power, nimpvel, impvel). docs/case-format.md has the field tables.
 */
#ifndef RC_CASE_POWER_H
#define RC_CASE_POWER_H

#include "case/case.h"

/* Spline kinds (card field Ispline). */
enum { RC_SPL_LINEAR = 1, RC_SPL_CUBIC = 2, RC_SPL_AKIMA = 3, RC_SPL_STEFFEN = 4 };
#define RC_SPL_DEFAULT RC_SPL_STEFFEN

/* /INTER/POWER/inter_ID. */
typedef struct rc_case_power {
    int id;
    char title[101];
    int surf1, surf2;          /* line 1: surfaces                              */
    int fct_stiff, fct_damp;   /* line 1: splines (0: none)                     */
    int ispline;               /* line 1: spline kind RC_SPL_* (power.h)        */
    int irdf;                  /* line 1: 1 RDF on, 2 off                       */
    int sensor_id;             /* line 1: /SENSOR that activates it (0: none)   */
    double k, m1, c, m2, m3;   /* line 2: [N/m^m1] [-] [N (s/m)^m2/m^m3] [-] [-] */
    double rdf, dreg, vreg;    /* line 3: [-] [m] [m/s]                         */
    double tstart, tstop;      /* line 3: [s]                                   */
    double mus, vs, mud, vd;   /* line 4: step5 friction [-] [m/s] [-] [m/s]    */
    double fmax;               /* line 4: maximum friction force, 0: none [N]   */
    double kt;                 /* line 5: stiffness for an overriding incremental
                                  /FRICTION [N/m], 0: none                      */
    double e_target;           /* line 6: restitution asked, C derived [-]; 0: none */
    double v_imp;              /* line 6: impact speed of e_target [m/s]; 0: derived */
    rc_loc loc;
    rc_loc line_loc[6];        /* each data line (absent: the header's)         */
} rc_case_power;

/* /IMPVEL/impvel_ID: velocity component Dir of the bodies of grnod_ID =
 * Fscale_y f(t / Ascale_x) for Tstart <= t <= Tstop. */
typedef struct rc_case_impvel {
    int id;
    char title[101];
    int fct_id;      /* time function (required) */
    int dir;         /* 0..2: X Y Z (translation); 3..5: XX YY ZZ (rotation) */
    int skew_id;     /* 0: global axes; a /SKEW/FIX */
    int sensor_id;   /* 0: none; a sensor known when compiling (model/sensor.c:
                        rc_sensor_load_on): imposed from its time on, the
                        function shifted by that time */
    int frame_id, icoor; /* 0 only */
    int grnod_id;    /* nodes whose bodies are driven (required) */
    double ascale;   /* [s] */
    double fscale;   /* [m/s] or [rad/s] */
    double tstart, tstop; /* [s] */
    int hold_sens;   /* a hold of model/sensor.c ended by a sensor found in the
                        run: 1 + the sensor's index (Tstop is then INFINITY);
                        0: none */
    rc_loc loc;
    rc_loc line_loc[2];
} rc_case_impvel;

#endif
