/*
 * Joint cards (ricochet cards, in the Radioss block style):
 *   /JOINT/SPHERICAL/joint_ID   the anchor points of two bodies coincide
 *   /JOINT/REVOLUTE/joint_ID    ... and the bodies turn about one axis
 *   /JOINT/DISTANCE/joint_ID    two points keep their distance
 *   /JOINT/FIXED/joint_ID       no relative motion
 *   /JOINT/PRISMATIC/joint_ID   relative translation along one axis only
 * Layout (docs/case-format.md): title; rbody_ID1 rbody_ID2; X Y Z (the
 * anchor point); REVOLUTE, PRISMATIC: Ax Ay Az (the axis); DISTANCE: X2 Y2
 * Z2 (the point on body 2); REVOLUTE, PRISMATIC: an optional fourth line
 * Lim_min Lim_max K_lim C_lim fct_lim (the stops of the joint coordinate,
 * blank: none). References are resolved by model/joint.c, the stops compiled by
 * model/coupling.c (RC_CPL_LIMIT).
 */
#include <string.h>

#include "base/error.h"
#include "case/case_internal.h"
#include "case/case_joint.h"

/* Line 4 of REVOLUTE and PRISMATIC: Lim_min Lim_max K_lim C_lim, the stops
 * of the joint coordinate (the rotation angle about the axis [rad], the
 * slide along it [m], both zero in the initial configuration); a blank
 * Lim_min or Lim_max: no such stop. */
static rc_status read_limits(rc_reader *rd, const rc_block *b, rc_case_joint *k)
{
    rc_status st;
    const int rev = k->kind == RC_CASE_JNT_REVOLUTE;
    if (k->kind == RC_CASE_JNT_DISTANCE)
        return rc_case_fail(rd, &k->line_loc[3], b->name, "Lim_min Lim_max",
                            "expected no fourth line: a distance joint keeps its length, so it has no free scalar "
                            "coordinate a stop could act on (a length that may vary between bounds is a "
                            "/COUPLING/SPRING, or a /JOINT/PRISMATIC with stops)");
    const int dl = rev ? RC_D_NONE : RC_D_L, dk = rev ? RC_D_E : RC_D_K, dc = rev ? RC_DIM(1, 2, -1) : RC_D_C;
    rc_field l4[] = {RC_F_REALD("Lim_min", &k->lim_lo, 0, 0, dl), RC_F_REALD("Lim_max", &k->lim_hi, 0, 0, dl),
                     RC_F_REALD("K_lim", &k->lim_k, 0, 0, dk), RC_F_REALD("C_lim", &k->lim_c, 0, RC_FF_NONNEG, dc),
                     RC_F_INT("fct_lim", &k->lim_fct, 0, RC_FF_NONNEG)};
    if ((st = rc_parse_line(rd, b, &b->lines[4], l4, RC_NF(l4)))) return st;
    k->has_lo = !l4[0].blank;
    k->has_hi = !l4[1].blank;
    if (!k->has_lo && !k->has_hi) return RC_OK; /* a blank line: no stops */
    const char *u = rev ? "rad" : "m";
    if (k->has_lo && !(k->lim_lo <= 0))
        return rc_case_fail(rd, &k->line_loc[3], b->name, "Lim_min",
                            "expected a lower stop <= 0 %s (the joint coordinate is 0 in the initial configuration, "
                            "which must lie within the stops), got %.9g",
                            u, k->lim_lo);
    if (k->has_hi && !(k->lim_hi >= 0))
        return rc_case_fail(rd, &k->line_loc[3], b->name, "Lim_max",
                            "expected an upper stop >= 0 %s (the joint coordinate is 0 in the initial configuration, "
                            "which must lie within the stops), got %.9g",
                            u, k->lim_hi);
    /* a revolute's angle is measured within one turn around the middle of
     * its stops (docs/theory.md 7.5): both stops, less than a turn apart */
    const double two_pi = 6.28318530717958647692;
    if (rev && (!k->has_lo || !k->has_hi))
        return rc_case_fail(rd, &k->line_loc[3], b->name, k->has_lo ? "Lim_max" : "Lim_min",
                            "expected both stops of a revolute joint (the angle is measured within one turn around "
                            "their middle; a single stop would be met again from its other side after a turn: give "
                            "the other one, e.g. a stop the motion never reaches), got it blank");
    if (rev && !(k->lim_hi - k->lim_lo < two_pi))
        return rc_case_fail(rd, &k->line_loc[3], b->name, "Lim_max",
                            "expected stops less than a turn apart, Lim_max - Lim_min < 2 pi rad, got %.9g - (%.9g) = "
                            "%.9g rad",
                            k->lim_hi, k->lim_lo, k->lim_hi - k->lim_lo);
    if (k->lim_fct > 0 && !l4[2].blank)
        return rc_case_fail(rd, &k->line_loc[3], b->name, "K_lim",
                            "expected K_lim blank with fct_lim = %d (the curve gives the stops' elastic force), got %s",
                            k->lim_fct, l4[2].got);
    if (k->lim_fct == 0 && !(k->lim_k > 0))
        return rc_case_fail(rd, &k->line_loc[3], b->name, "K_lim",
                            "expected the stiffness of the stops > 0 %s (or a curve in fct_lim), got %s",
                            rev ? "N m/rad" : "N/m", l4[2].blank ? "blank" : l4[2].got);
    return RC_OK;
}

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
    for (int i = 0; i < 4; i++) k->line_loc[i] = k->loc;
    const int third = kind == RC_CASE_JNT_REVOLUTE || kind == RC_CASE_JNT_PRISMATIC || kind == RC_CASE_JNT_DISTANCE;
    const char *desc = kind == RC_CASE_JNT_DISTANCE ? "rbody_ID1 rbody_ID2, X1 Y1 Z1, X2 Y2 Z2"
                       : third ? "rbody_ID1 rbody_ID2, X Y Z, Ax Ay Az, optional Lim_min Lim_max K_lim C_lim fct_lim"
                               : "rbody_ID1 rbody_ID2, X Y Z";
    int nd;
    /* a fourth line: the stops (REVOLUTE, PRISMATIC; DISTANCE reads it to
     * refuse it with its reason) */
    if ((st = rc_card_lines(rd, b, k->title, third ? 3 : 2, third ? 4 : 2, desc, &nd))) return st;
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
    if (nd >= 4 && (st = read_limits(rd, b, k))) return st;
    return rc_note_id(rd, RC_IDK_JOINT, k->id, &k->loc, b->hdr->text);
}
