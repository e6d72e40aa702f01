/*
 * Parsed /COUPLING cards (ricochet cards, docs/case-format.md): read by
 * cards_couplings.c, compiled by model/coupling.c. Part of rc_case
 * (case.h: ncoupling, coupling).
 */
#ifndef RC_CASE_COUPLING_H
#define RC_CASE_COUPLING_H

#include "case/case.h"

typedef enum { RC_CASE_CPL_SPRING = 1, RC_CASE_CPL_CATENARY = 2, RC_CASE_CPL_CONTACT = 3 } rc_case_cpl_kind;

/* /COUPLING/SPRING/cpl_ID and /COUPLING/CATENARY/cpl_ID. */
typedef struct rc_case_coupling {
    int id;
    char title[101];
    rc_case_cpl_kind kind;
    int rbody[2];      /* rbody_ID1, rbody_ID2; 0: point fixed in space      */
    double p[2][3];    /* attachment points, global at t = 0 [m]            */
    /* spring */
    int iform;         /* 1 constant, 2 polynomial, 3 f_e table, 4 k table   */
    int fct_id;        /* Iform 3, 4: the /FUNCT                             */
    double x0;         /* relaxation length [m]                             */
    int x0_given;      /* 0: blank, x0 = initial distance                    */
    double kd;         /* damping [N s/m]                                    */
    double a, b, c;    /* Iform 1: k = a; Iform 2: a [N/m], b [N/m^2], c [N/m^3] */
    double fr, xr;     /* Iform 4: reference force [N] at distance [m]       */
    int ref_given;     /* 1: x_r given                                       */
    /* catenary */
    double lambda0;    /* mass per unstretched length [kg/m]                 */
    double leq;        /* unstretched length [m]                             */
    double d;          /* stiffness of the whole line [N/m]; EA = D L_eq    */
    /* contact (/COUPLING/CONTACT, STAR-CCM+ contact coupling) */
    int surf[2];       /* surf_ID1 (segment surface of the body), surf_ID2 (opposing) */
    int iside;         /* 0 auto, 1 outside, 2 inside the opposing surface    */
    int iest;          /* 0: k1, k2 given; 1: estimated (line 3)             */
    double d0;         /* effective range [m]                               */
    double k1, k2;     /* elastic [N/m^3] and damping [N s/m^3] coefficients */
    double mu, kt;     /* friction coefficient [-], tanh coefficient [s/m]   */
    double vimp, dmin, zeta, area; /* estimator: impact speed [m/s], minimum
                          distance [m], damping factor [-], contact area [m^2] */
    rc_loc loc;
    rc_loc line_loc[6]; /* each data line (unread lines: the header's)     */
} rc_case_coupling;

#endif
