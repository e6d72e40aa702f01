/*
 * Rigid walls and time sensors.
 *
 * Rigid walls: /RWALL/PLANE, /RWALL/CYL, /RWALL/SPHER, /RWALL/PARAL in the
 * Radioss layouts (by the /BEGIN version: 8- and 16-character fields in
 * 4.x, 10 and 20 from 5.1, Iform on line 1 from 2026); a moving wall
 * (node_ID) has its Mass and initial velocity on line 3. The card is read
 * whole, then what ricochet cannot honour yet is refused with "not
 * supported yet" at the line of the field: a tied wall (Slide 1),
 * friction filtering (ifq), a moving parallelogram. The model
 * compiler (model/rwall.c) turns a wall into contacts of the bodies that
 * own its nodes.
 */
#include "case/case_internal.h"
#include "base/error.h"

#include <math.h>
#include <string.h>

static const char rc_note_tied[] = "(a tied wall: Slide 0 frictionless or 2 with friction)";
static const char rc_note_ifq[] = "(friction filtering of a wall: give ifq 0)";

/* Is a - b the zero vector? */
static int same_point(const double *a, const double *b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

/* /RWALL/<type>/rwall_ID[/unit_ID]: title; node_ID Slide grnd_ID1
 * grnd_ID2 [Iform]; d fric Diameter ffac ifq; XM YM ZM (or Mass VX0 VY0
 * VZ0 for a moving wall); XM1 YM1 ZM1 (not SPHER); XM2 YM2 ZM2 (PARAL). */
rc_status rc_card_rwall(rc_reader *rd, const rc_block *b)
{
    static const char *const usage[] = {"", "/RWALL/PLANE/rwall_ID", "/RWALL/CYL/rwall_ID", "/RWALL/SPHER/rwall_ID",
                                        "/RWALL/PARAL/rwall_ID"};
    static const char *const desc[] = {"", "node_ID Slide grnd_ID1 grnd_ID2, d fric Diameter ffac ifq, XM YM ZM, XM1 YM1 ZM1",
                                       "node_ID Slide grnd_ID1 grnd_ID2, d fric Diameter ffac ifq, XM YM ZM, XM1 YM1 ZM1",
                                       "node_ID Slide grnd_ID1 grnd_ID2, d fric Diameter ffac ifq, XM YM ZM",
                                       "node_ID Slide grnd_ID1 grnd_ID2, d fric Diameter ffac ifq, XM YM ZM, XM1 YM1 ZM1, XM2 YM2 ZM2"};
    static const int nlines[] = {0, 4, 4, 3, 5};
    rc_case *c = rd->c;
    const rc_case_rwall_kind kind = strcmp(b->kw[1], "PLANE") == 0 ? RC_RWALL_PLANE
                                    : strcmp(b->kw[1], "CYL") == 0 ? RC_RWALL_CYL
                                    : strcmp(b->kw[1], "SPHER") == 0 ? RC_RWALL_SPHER
                                                                      : RC_RWALL_PARAL;
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "rwall_ID", usage[kind]))) return st;
    RC_GROW(rd, c->rwall, rd->caprwall, c->nrwall);
    rc_case_rwall *w = &c->rwall[c->nrwall++];
    w->id = b->id;
    w->kind = kind;
    w->loc = b->hdr->loc;
    if ((st = rc_card_lines(rd, b, w->title, nlines[kind], nlines[kind], desc[kind], &nd))) return st;
    for (int k = 0; k < nd; k++) w->line_loc[k] = b->lines[k + 1].loc;

    /* line 1: the wall's node, the sliding flag, the node groups; Iform
     * from 2026. 10-character integers, 8 in Radioss 4.x */
    const int ver = rc_layout_version(rd), wi = ver >= 51 ? 10 : 8, wr = ver >= 51 ? 20 : 16;
    rc_field l1[] = {RC_F_INT("node_ID", &w->node_id, 0, RC_FF_NONNEG),
                     RC_F_SET("Slide", &w->slide, 0, 0, 0x7u, 0x5u, rc_note_tied),
                     RC_F_INT("grnd_ID1", &w->grnd1, 0, RC_FF_NONNEG), RC_F_INT("grnd_ID2", &w->grnd2, 0, RC_FF_NONNEG),
                     RC_F_SET("Iform", &w->iform, 0, 0, 0x3u, 0, NULL)};
    for (int k = 0; k < RC_NF(l1); k++) l1[k].width = wi;
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, ver >= 2026 ? 5 : 4))) return st;

    /* line 2: search distance, friction, diameter, filter (4.1: the first
     * three only) */
    rc_field l2[] = {RC_F_REALW("d", &w->dsearch, 0, RC_FF_NONNEG, wr, RC_D_L),
                     RC_F_REALW("fric", &w->fric, 0, RC_FF_NONNEG, wr, RC_D_NONE),
                     RC_F_REALW("Diameter", &w->diameter, 0, RC_FF_NONNEG, wr, RC_D_L),
                     RC_F_REALW("ffac", &w->ffac, 0, 0, wr, RC_D_NONE),
                     RC_F_SETW("ifq", &w->ifq, 0, 0, 0xFu, 0, NULL, wi)};
    if ((st = rc_parse_line(rd, b, &b->lines[2], l2, ver >= 44 ? 5 : 3))) return st;
    if (w->slide == 2 && w->ifq != 0)
        return rc_case_fail(rd, &b->lines[2].loc, b->name, "ifq", "expected 0, got %s: not supported yet %s", l2[4].got,
                            rc_note_ifq);
    if (w->slide != 2 && (w->fric != 0 || w->ifq != 0 || w->ffac != 0))
        if ((st = rc_case_warn(rd, &b->lines[2].loc,
                               "card %s: fields fric, ffac, ifq ignored: they act with Slide 2 only (Slide is %d)",
                               b->name, w->slide)))
            return st;
    if ((kind == RC_RWALL_CYL || kind == RC_RWALL_SPHER) && !(w->diameter > 0))
        return rc_case_fail(rd, &b->lines[2].loc, b->name, "Diameter",
                            "expected the wall's diameter, > 0, got %s", l2[2].got);

    /* line 3: the point M (a fixed wall); a moving wall: its mass and
     * initial velocity (M is its node) */
    rc_field l3[] = {RC_F_REALW("XM", &w->m[0], 0, 0, wr, RC_D_L), RC_F_REALW("YM", &w->m[1], 0, 0, wr, RC_D_L),
                     RC_F_REALW("ZM", &w->m[2], 0, 0, wr, RC_D_L)};
    rc_field l3m[] = {RC_F_REALW("Mass", &w->mass, 0, RC_FF_POS, wr, RC_D_M),
                      RC_F_REALW("VX0", &w->v0[0], 0, 0, wr, RC_D_V), RC_F_REALW("VY0", &w->v0[1], 0, 0, wr, RC_D_V),
                      RC_F_REALW("VZ0", &w->v0[2], 0, 0, wr, RC_D_V)};
    if (w->node_id == 0 && (st = rc_parse_line(rd, b, &b->lines[3], l3, RC_NF(l3)))) return st;
    if (w->node_id != 0 && (st = rc_parse_line(rd, b, &b->lines[3], l3m, RC_NF(l3m)))) return st;
    /* line 4: M1; line 5: M2 */
    if (nd >= 4) {
        rc_field l4[] = {RC_F_REALW("XM1", &w->m1[0], 0, 0, wr, RC_D_L), RC_F_REALW("YM1", &w->m1[1], 0, 0, wr, RC_D_L),
                         RC_F_REALW("ZM1", &w->m1[2], 0, 0, wr, RC_D_L)};
        if ((st = rc_parse_line(rd, b, &b->lines[4], l4, RC_NF(l4)))) return st;
        if (w->node_id == 0 && same_point(w->m, w->m1))
            return rc_case_fail(rd, &b->lines[4].loc, b->name, "XM1 YM1 ZM1",
                                "expected a point M1 different from M (%s), got M1 = M = (%.9g, %.9g, %.9g)",
                                kind == RC_RWALL_CYL ? "the axis goes from M to M1" : "the normal points from M to M1",
                                w->m[0], w->m[1], w->m[2]);
    }
    if (nd >= 5) {
        rc_field l5[] = {RC_F_REALW("XM2", &w->m2[0], 0, 0, wr, RC_D_L), RC_F_REALW("YM2", &w->m2[1], 0, 0, wr, RC_D_L),
                         RC_F_REALW("ZM2", &w->m2[2], 0, 0, wr, RC_D_L)};
        if ((st = rc_parse_line(rd, b, &b->lines[5], l5, RC_NF(l5)))) return st;
        double u[3], v[3];
        for (int k = 0; k < 3; k++) {
            u[k] = w->m1[k] - w->m[k];
            v[k] = w->m2[k] - w->m[k];
        }
        const double x[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        if (!(sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) > 0))
            return rc_case_fail(rd, &b->lines[5].loc, b->name, "XM2 YM2 ZM2",
                                "expected a corner M2 off the line through M and M1 (the parallelogram's sides are "
                                "M M1 and M M2), got (%.9g, %.9g, %.9g)",
                                w->m2[0], w->m2[1], w->m2[2]);
        /* a moving parallelogram: its corners would follow the node */
        if (w->node_id != 0)
            return rc_case_fail(rd, &b->lines[1].loc, b->name, "node_ID",
                                "expected 0 (a fixed wall), got %d: a moving /RWALL/PARAL is not supported yet",
                                w->node_id);
    }
    return rc_note_id(rd, RC_IDK_RWALL, w->id, &w->loc, b->hdr->text);
}

/* Line 2 of /SENSOR/INTER: int_ID (all layouts), DIR Fmin Fmax Tmin (11.0
 * on), Fcut (14.0 on). DIR blank: the contact closing triggers (no force
 * bound); FN: the normal force rising above Fmax (Fmax 0: the contact
 * closing), held for Tmin; TF, Fmin, Fcut and a Tmin on the first contact:
 * not supported yet. Whether int_ID
 * names an interface: the compiler (model/sensor.c). */
static rc_status sensor_inter_line(rc_reader *rd, const rc_block *b, rc_case_sensor *s)
{
    char dir[16] = "";
    double fmin = 0.0, fcut = 0.0;
    rc_field g[] = {RC_F_INT("int_ID", &s->inter_id, 0, RC_FF_POS),
                    RC_F_STR("DIR", dir, 10),
                    RC_F_REALD("Fmin", &fmin, 0, RC_FF_NONNEG, RC_D_F),
                    RC_F_REALD("Fmax", &s->fmax, 0, RC_FF_NONNEG, RC_D_F),
                    RC_F_REALD("Tmin", &s->tmin, 0, RC_FF_NONNEG, RC_D_T),
                    RC_F_REALD("Fcut", &fcut, 0, RC_FF_NONNEG | RC_FF_ONLY0, RC_D_W)};
    g[5].note = "(a filter of the contact force)";
    const int v = rc_layout_version(rd), nf = v >= 140 ? 6 : v >= 110 ? 5 : 1;
    s->line2_loc = b->lines[2].loc;
    rc_status st = rc_parse_line(rd, b, &b->lines[2], g, nf);
    if (st) return st;
    /* DIR: blank, FN or TF, either case */
    for (char *p = dir; *p; p++)
        if (*p >= 'a' && *p <= 'z') *p = (char)(*p - 'a' + 'A');
    if (dir[0] && strcmp(dir, "FN") != 0 && strcmp(dir, "TF") != 0)
        return rc_case_fail(rd, &b->lines[2].loc, b->name, "DIR",
                            "expected blank (the first contact), FN (the normal force) or TF (the tangential force), "
                            "got %s",
                            g[1].got);
    if (strcmp(dir, "TF") == 0)
        return rc_case_fail(rd, &b->lines[2].loc, b->name, "DIR",
                            "expected blank or FN, got TF: a sensor on the tangential (friction) force is not "
                            "supported yet");
    s->dir = dir[0] ? 1 : 0;
    if (fmin > 0 && s->fmax > 0 && fmin >= s->fmax)
        return rc_case_fail(rd, &b->lines[2].loc, b->name, "Fmin",
                            "expected Fmin < Fmax, got Fmin %s and Fmax %s [force]", g[2].got, g[3].got);
    if (!s->dir && (fmin > 0 || s->fmax > 0))
        return rc_case_fail(rd, &b->lines[2].loc, b->name, fmin > 0 ? "Fmin" : "Fmax",
                            "expected 0 with DIR blank (the sensor triggers at the first contact, without a force "
                            "bound), got %s; expected DIR FN for a bound on the normal force",
                            fmin > 0 ? g[2].got : g[3].got);
    if (fmin > 0)
        return rc_case_fail(rd, &b->lines[2].loc, b->name, "Fmin",
                            "expected 0, got %s: a sensor triggered by the normal force falling below Fmin is not "
                            "supported yet; expected Fmax (the force rising above it) or the first contact",
                            g[2].got);
    if (s->tmin > 0 && !(s->fmax > 0))
        return rc_case_fail(rd, &b->lines[2].loc, b->name, "Tmin",
                            "expected 0 without a force bound, got %s: the duration of a first contact is not "
                            "supported yet; expected DIR FN and Fmax > 0 (the force held above Fmax for Tmin)",
                            g[4].got);
    return RC_OK;
}

/* /SENSOR/TIME/sens_ID[/unit_ID]: title; Tdelay (the sensor is on from
 * t = Tdelay). /SENSOR/DIST/sens_ID[/unit_ID]: title; Tdelay; node_ID1
 * node_ID2 Dmin Dmax [Tmin Dflag from 2022: Dflag 0 only] (the sensor is
 * on Tdelay after the nodes' distance has stayed out of [Dmin, Dmax] for
 * Tmin). /SENSOR/AND and
 * /SENSOR/OR: title; Tdelay; sens_ID1 sens_ID2. /SENSOR/NOT: title;
 * Tdelay; sens_ID1 (on from Tdelay while sens_ID1 is off).
 * /SENSOR/INTER: title; Tdelay; int_ID [DIR Fmin Fmax Tmin from 11.0; Fcut
 * from 14.0] (on Tdelay after the contact of interface int_ID closes, DIR
 * blank, or after its normal force has stayed above Fmax for Tmin, DIR FN;
 * Fmin, Fcut 0 only and DIR TF refused: not supported yet). The /RBODY and
 * interfaces naming a sensor, and the interface a /SENSOR/INTER names: the
 * compiler (model/sensor.c). */
rc_status rc_card_sensor_time(rc_reader *rd, const rc_block *b)
{
    rc_case *c = rd->c;
    const int dist = strcmp(b->kw[1], "DIST") == 0, is_and = strcmp(b->kw[1], "AND") == 0,
              is_or = strcmp(b->kw[1], "OR") == 0, is_not = strcmp(b->kw[1], "NOT") == 0,
              inter = strcmp(b->kw[1], "INTER") == 0;
    const int two = dist || is_and || is_or || is_not || inter; /* a second line */
    int nd;
    rc_status st;
    char usage[40];
    snprintf(usage, sizeof usage, "/SENSOR/%s/sens_ID", b->kw[1]);
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "sens_ID", usage))) return st;
    RC_GROW(rd, c->sensor, rd->capsensor, c->nsensor);
    rc_case_sensor *s = &c->sensor[c->nsensor++];
    s->id = b->id;
    s->kind = dist     ? RC_SENS_DIST
              : is_and ? RC_SENS_AND
              : is_or  ? RC_SENS_OR
              : is_not ? RC_SENS_NOT
              : inter  ? RC_SENS_INTER
                       : RC_SENS_TIME;
    s->loc = s->line_loc = s->line2_loc = b->hdr->loc;
    if ((st = rc_card_lines(rd, b, s->title, two ? 2 : 1, two ? 2 : 1,
                            dist     ? "Tdelay, node_ID1 node_ID2 Dmin Dmax"
                            : inter  ? "Tdelay, int_ID DIR Fmin Fmax Tmin Fcut"
                            : is_not ? "Tdelay, sens_ID1"
                            : two    ? "Tdelay, sens_ID1 sens_ID2"
                                     : "Tdelay",
                            &nd)))
        return st;
    s->line_loc = b->lines[1].loc;
    rc_field f[] = {RC_F_REALD("Tdelay", &s->tdelay, 0, RC_FF_NONNEG, RC_D_T)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], f, RC_NF(f)))) return st;
    if (is_and || is_or) {
        s->line2_loc = b->lines[2].loc;
        rc_field g[] = {RC_F_INT("sens_ID1", &s->in[0], 0, RC_FF_POS), RC_F_INT("sens_ID2", &s->in[1], 0, RC_FF_POS)};
        if ((st = rc_parse_line(rd, b, &b->lines[2], g, RC_NF(g)))) return st;
    }
    if (is_not) {
        s->line2_loc = b->lines[2].loc;
        rc_field g[] = {RC_F_INT("sens_ID1", &s->in[0], 0, RC_FF_POS)};
        if ((st = rc_parse_line(rd, b, &b->lines[2], g, RC_NF(g)))) return st;
        if (s->in[0] == s->id)
            return rc_case_fail(rd, &b->lines[2].loc, b->name, "sens_ID1",
                                "expected another sensor, got %d (the sensor itself: on while it is off)", s->in[0]);
        s->in[1] = s->in[0]; /* one input: the checks of the two-input sensors see it twice */
    }
    if (dist) {
        s->line2_loc = b->lines[2].loc;
        int dflag = 0;
        rc_field g[] = {RC_F_INT("node_ID1", &s->node[0], 0, RC_FF_POS),
                        RC_F_INT("node_ID2", &s->node[1], 0, RC_FF_POS),
                        RC_F_REALD("Dmin", &s->dmin, 0, RC_FF_NONNEG, RC_D_L),
                        RC_F_REALD("Dmax", &s->dmax, 0, RC_FF_NONNEG, RC_D_L),
                        RC_F_REALD("Tmin", &s->tmin, 0, RC_FF_NONNEG, RC_D_T),
                        RC_F_INTN("Dflag", &dflag, RC_FF_ONLY0, "(a sensor that deactivates again)")};
        if ((st = rc_parse_line(rd, b, &b->lines[2], g, rc_layout_version(rd) >= 2022 ? 6 : 4))) return st;
        if (s->node[0] == s->node[1])
            return rc_case_fail(rd, &b->lines[2].loc, b->name, "node_ID2",
                                "expected a node other than node_ID1, got %d (the distance of a node to itself is 0)",
                                s->node[1]);
        if (s->dmin == 0 && s->dmax == 0)
            return rc_case_fail(rd, &b->lines[2].loc, b->name, "Dmax",
                                "expected Dmin > 0 or Dmax > 0 [length], got both 0 (the sensor would never trigger)");
        if (s->dmax > 0 && s->dmin >= s->dmax)
            return rc_case_fail(rd, &b->lines[2].loc, b->name, "Dmin",
                                "expected Dmin < Dmax, got Dmin %s and Dmax %s [length]", g[2].got, g[3].got);
    }
    if (inter && (st = sensor_inter_line(rd, b, s))) return st;
    return rc_note_id(rd, RC_IDK_SENSOR, s->id, &s->loc, b->hdr->text);
}
