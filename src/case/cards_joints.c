/*
 * Joint cards (ricochet cards, in the Radioss block style):
 *   /JOINT/SPHERICAL/joint_ID   the anchor points of two bodies coincide
 *   /JOINT/REVOLUTE/joint_ID    ... and the bodies turn about one axis
 *   /JOINT/DISTANCE/joint_ID    two points keep their distance
 *   /JOINT/FIXED/joint_ID       no relative motion
 *   /JOINT/PRISMATIC/joint_ID   relative translation along one axis only
 * Layout (docs/case-format.md): title; rbody_ID1 rbody_ID2; X Y Z (the
 * anchor point); REVOLUTE, PRISMATIC: Ax Ay Az (the axis); DISTANCE: X2 Y2
 * Z2 (the point on body 2). References are resolved by model/joint.c.
 */
#include <string.h>

#include "base/error.h"
#include "case/case_internal.h"
#include "case/case_joint.h"

rc_status rc_card_joint(rc_reader *rd, const rc_block *b)
{
    rc_case *c = rd->c;
    rc_status st;
    static const char *const sub[] = {"", "SPHERICAL", "REVOLUTE", "DISTANCE", "FIXED", "PRISMATIC"};
    rc_case_jnt_kind kind = RC_CASE_JNT_SPHERICAL;
    for (int k = 1; k <= 5; k++)
        if (!strcmp(b->kw[1], sub[k])) kind = (rc_case_jnt_kind)k;
    char usage[64];
    snprintf(usage, sizeof usage, "/JOINT/%s/joint_ID", sub[kind]);
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "joint_ID", usage))) return st;
    RC_GROW(rd, c->joint, rd->capjoint, c->njoint);
    rc_case_joint *k = &c->joint[c->njoint++];
    memset(k, 0, sizeof *k);
    k->id = b->id;
    k->kind = kind;
    k->loc = b->hdr->loc;
    for (int i = 0; i < 3; i++) k->line_loc[i] = k->loc;
    const int third = kind == RC_CASE_JNT_REVOLUTE || kind == RC_CASE_JNT_PRISMATIC || kind == RC_CASE_JNT_DISTANCE;
    const char *desc = kind == RC_CASE_JNT_DISTANCE ? "rbody_ID1 rbody_ID2, X1 Y1 Z1, X2 Y2 Z2"
                       : third                      ? "rbody_ID1 rbody_ID2, X Y Z, Ax Ay Az"
                                                    : "rbody_ID1 rbody_ID2, X Y Z";
    int nd;
    if ((st = rc_card_lines(rd, b, k->title, third ? 3 : 2, third ? 3 : 2, desc, &nd))) return st;
    for (int i = 0; i < nd; i++) k->line_loc[i] = b->lines[i + 1].loc;

    rc_field l1[] = {RC_F_INT("rbody_ID1", &k->rbody[0], 0, RC_FF_POS),
                     RC_F_INT("rbody_ID2", &k->rbody[1], 0, RC_FF_NONNEG)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1)))) return st;
    if (k->rbody[0] == k->rbody[1])
        return rc_case_fail(rd, &k->line_loc[0], b->name, "rbody_ID2",
                            "expected a body other than rbody_ID1 = %d, or 0 (the ground), got %d", k->rbody[0],
                            k->rbody[1]);
    const int dist = kind == RC_CASE_JNT_DISTANCE;
    rc_field l2[] = {RC_F_REALD(dist ? "X1" : "X", &k->p[0], 0, 0, RC_D_L),
                     RC_F_REALD(dist ? "Y1" : "Y", &k->p[1], 0, 0, RC_D_L),
                     RC_F_REALD(dist ? "Z1" : "Z", &k->p[2], 0, 0, RC_D_L)};
    if ((st = rc_parse_line(rd, b, &b->lines[2], l2, RC_NF(l2)))) return st;
    if (dist) {
        rc_field l3[] = {RC_F_REALD("X2", &k->p2[0], 0, 0, RC_D_L), RC_F_REALD("Y2", &k->p2[1], 0, 0, RC_D_L),
                         RC_F_REALD("Z2", &k->p2[2], 0, 0, RC_D_L)};
        if ((st = rc_parse_line(rd, b, &b->lines[3], l3, RC_NF(l3)))) return st;
        if (k->p[0] == k->p2[0] && k->p[1] == k->p2[1] && k->p[2] == k->p2[2])
            return rc_case_fail(rd, &k->line_loc[2], b->name, "X2 Y2 Z2",
                                "expected a point 2 different from point 1 (the joint keeps their distance; "
                                "a zero distance is /JOINT/SPHERICAL), got both = (%.9g, %.9g, %.9g)",
                                k->p[0], k->p[1], k->p[2]);
    } else if (third) {
        rc_field l3[] = {RC_F_REALD("Ax", &k->axis[0], 0, 0, RC_D_NONE), RC_F_REALD("Ay", &k->axis[1], 0, 0, RC_D_NONE),
                         RC_F_REALD("Az", &k->axis[2], 0, 0, RC_D_NONE)};
        if ((st = rc_parse_line(rd, b, &b->lines[3], l3, RC_NF(l3)))) return st;
        if (k->axis[0] == 0 && k->axis[1] == 0 && k->axis[2] == 0)
            return rc_case_fail(rd, &k->line_loc[2], b->name, "Ax Ay Az",
                                "expected a non-zero axis direction, got (0, 0, 0)");
    }
    return rc_note_id(rd, RC_IDK_JOINT, k->id, &k->loc, b->hdr->text);
}
