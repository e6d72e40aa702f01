/*
 * Parsed /JOINT cards (ricochet cards, docs/case-format.md): read by
 * cards_joints.c, compiled by model/joint.c. Part of rc_case (case.h:
 * njoint, joint).
 */
#ifndef RC_CASE_JOINT_H
#define RC_CASE_JOINT_H

#include "case/case.h"

/* The same numbers as rc_jnt_kind (model/joint.h). */
typedef enum {
    RC_CASE_JNT_SPHERICAL = 1,
    RC_CASE_JNT_REVOLUTE = 2,
    RC_CASE_JNT_DISTANCE = 3,
    RC_CASE_JNT_FIXED = 4,
    RC_CASE_JNT_PRISMATIC = 5
} rc_case_jnt_kind;

typedef struct rc_case_joint {
    int id;
    char title[101];
    rc_case_jnt_kind kind;
    int rbody[2];      /* rbody_ID1 (a body), rbody_ID2 (a body, or 0: the ground) */
    double p[3];       /* anchor point (DISTANCE: on body 1), global at t = 0 [m] */
    double p2[3];      /* DISTANCE: the point on body 2, global at t = 0 [m] */
    double axis[3];    /* REVOLUTE, PRISMATIC: axis, global at t = 0 [-] (not normalised) */
    /* REVOLUTE, PRISMATIC: the stops of the joint coordinate (optional line
     * 4): lower and upper stop [rad] or [m] (has_lo, has_hi: given), the
     * stiffness [N m/rad] or [N/m] and damping [N m s/rad] or [N s/m] of the
     * stop's contact law */
    int has_lo, has_hi;
    double lim_lo, lim_hi, lim_k, lim_c;
    int lim_fct;       /* /FUNCT id of the stops' elastic part F_e(p) [N] or [N m] (K_lim blank); 0: K_lim p */
    rc_loc loc;
    rc_loc line_loc[4]; /* the data lines */
} rc_case_joint;

#endif
