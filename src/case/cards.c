/*
 * Card dispatch: the table of supported cards (keyword, subtype, family
 * function), the Radioss cards ignored or planned, and the call of a
 * card's function. The card functions live in one file per family:
 *   cards_bodies.c      /NODE /GRNOD/NODE /RBODY /PART /GRPART/PART /GRPART/GRPART /LINE/SURF
 *   cards_mesh.c        /SHELL /SH3N /BRICK /TETRA4 /PENTA6 /TETRA10 /SPRING /PROP/SHELL /PROP/SOLID /PROP/SPRING /MAT
 *                       /SKEW/FIX /SKEW/MOV /SKEW/MOV2 /GRNOD/PART /GRNOD/GRNOD (called first)
 *   cards_surfaces.c    /SURF/PLANE /SURF/ELLIPS /SURF/CYL /SURF/BOX /SURF/SEG /SURF/PART
 *   cards_interfaces.c  /INTER/TYPE6 /INTER/TYPE7 /INTER/TYPE24 /INTER/TYPE25 /INTER/TYPE11 /INTER/TYPE19
 *                       /INTER/POWER
 *   cards_friction.c    /FRICTION /FRIC_ORIENT
 *   cards_couplings.c   /COUPLING/SPRING /COUPLING/CATENARY /COUPLING/CONTACT
 *   cards_joints.c      /JOINT/SPHERICAL /JOINT/REVOLUTE /JOINT/DISTANCE /JOINT/FIXED /JOINT/PRISMATIC
 *   cards_rwall.c       /RWALL/PLANE /RWALL/CYL /RWALL/SPHER /RWALL/PARAL /SENSOR/TIME
 *                       /SENSOR/DIST /SENSOR/AND /SENSOR/OR /SENSOR/NOT
 *                       /SENSOR/INTER
 *   cards_loads.c       /FUNCT /INIVEL /GRAV /BCS /IMPVEL
 *   cards_run.c         /BEGIN /RUN /SOLVER, deck-level defaults and checks
 */
#include "case/case_internal.h"
#include "base/error.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ======================================================================
 * Dispatch
 * ====================================================================== */

typedef enum {
    RC_CARD_BEGIN, RC_CARD_NODE, RC_CARD_GRNOD, RC_CARD_RBODY, RC_CARD_PLANE, RC_CARD_ELLIPS,
    RC_CARD_TYPE6, RC_CARD_FUNCT, RC_CARD_INIVEL, RC_CARD_GRAV, RC_CARD_BCS, RC_CARD_RUN,
    RC_CARD_SOLVER, RC_CARD_CPL_SPRING, RC_CARD_CPL_CATENARY, RC_CARD_PART, RC_CARD_GRPART,
    RC_CARD_FRICTION, RC_CARD_FRIC_ORIENT, RC_CARD_POWER, RC_CARD_CYL, RC_CARD_BOX, RC_CARD_IMPVEL,
    RC_CARD_UNIT, RC_CARD_SEG, RC_CARD_SURFPART, RC_CARD_CPL_CONTACT, RC_CARD_JOINT, RC_CARD_RWALL, RC_CARD_SENSOR, RC_CARD_TYPE7,
    RC_CARD_TYPE24, RC_CARD_TYPE25, RC_CARD_TYPE11, RC_CARD_TYPE19, RC_CARD_LINE
} rc_card_kind;

/* Supported cards; a family (kw with a sub) lists each subtype. */
static const struct {
    const char *kw, *sub;
    rc_card_kind kind;
} rc_card_table[] = {
    {"BEGIN", NULL, RC_CARD_BEGIN},    {"NODE", NULL, RC_CARD_NODE},
    {"GRNOD", "NODE", RC_CARD_GRNOD},  {"RBODY", NULL, RC_CARD_RBODY},
    {"SURF", "PLANE", RC_CARD_PLANE},  {"SURF", "ELLIPS", RC_CARD_ELLIPS},
    {"INTER", "TYPE6", RC_CARD_TYPE6}, {"INTER", "TYPE7", RC_CARD_TYPE7}, {"INTER", "TYPE24", RC_CARD_TYPE24},
    {"INTER", "TYPE25", RC_CARD_TYPE25}, {"INTER", "TYPE11", RC_CARD_TYPE11},
    {"INTER", "TYPE19", RC_CARD_TYPE19}, {"LINE", "SURF", RC_CARD_LINE}, {"FUNCT", NULL, RC_CARD_FUNCT},
    {"INIVEL", "TRA", RC_CARD_INIVEL}, {"INIVEL", "ROT", RC_CARD_INIVEL},
    {"GRAV", NULL, RC_CARD_GRAV},      {"BCS", NULL, RC_CARD_BCS},
    {"RUN", NULL, RC_CARD_RUN},        {"SOLVER", NULL, RC_CARD_SOLVER},
    {"COUPLING", "SPRING", RC_CARD_CPL_SPRING}, {"COUPLING", "CATENARY", RC_CARD_CPL_CATENARY},
    {"PART", NULL, RC_CARD_PART},      {"GRPART", "PART", RC_CARD_GRPART},
    {"GRPART", "GRPART", RC_CARD_GRPART},
    {"FRICTION", NULL, RC_CARD_FRICTION}, {"FRIC_ORIENT", NULL, RC_CARD_FRIC_ORIENT},
    {"INTER", "POWER", RC_CARD_POWER}, {"SURF", "CYL", RC_CARD_CYL},
    {"SURF", "BOX", RC_CARD_BOX},      {"IMPVEL", NULL, RC_CARD_IMPVEL},
    {"UNIT", NULL, RC_CARD_UNIT},
    {"SURF", "SEG", RC_CARD_SEG},      {"SURF", "PART", RC_CARD_SURFPART},
    {"COUPLING", "CONTACT", RC_CARD_CPL_CONTACT},
    {"JOINT", "SPHERICAL", RC_CARD_JOINT}, {"JOINT", "REVOLUTE", RC_CARD_JOINT},
    {"JOINT", "DISTANCE", RC_CARD_JOINT},  {"JOINT", "FIXED", RC_CARD_JOINT},
    {"JOINT", "PRISMATIC", RC_CARD_JOINT},
    {"RWALL", "PLANE", RC_CARD_RWALL},     {"RWALL", "CYL", RC_CARD_RWALL},
    {"RWALL", "SPHER", RC_CARD_RWALL},     {"RWALL", "PARAL", RC_CARD_RWALL},
    {"SENSOR", "TIME", RC_CARD_SENSOR},    {"SENSOR", "DIST", RC_CARD_SENSOR},
    {"SENSOR", "AND", RC_CARD_SENSOR},     {"SENSOR", "OR", RC_CARD_SENSOR},
    {"SENSOR", "NOT", RC_CARD_SENSOR},     {"SENSOR", "INTER", RC_CARD_SENSOR},
};

/* Radioss cards without meaning for rigid bodies: skipped with a warning. */
static const char *const rc_ignored[] = {"PROP", "MAT"};
/* Radioss starter and engine options that only matter to explicit runs
 * (time step, outputs, restart, memory, parallelism): skipped with one
 * warning per kind. */
static const char *const rc_explicit[] = {
    "TITLE", "ANALY", "DEF_SOLID", "DEF_SHELL", "IOFLAG", "SPMD", "RANDOM", "TH", "ANIM",
    "MEMORY", "DT", "DTIX", "PRINT", "VERS", "STOP", "OUTP", "H3D", "RFILE", "TFILE", "ATFILE",
    "MON", "PARITH", "CHKPT", "STATE", "DYNAIN", "KEREL", "DYREL", "ADYREL", "SHFRA",
    "CAA", "MADYMO", "INSPIRE", "NEGVOL", "MSTOP", "NSTOP"};
/* Radioss cards ricochet plans to support: an error until then. */
static const char *const rc_planned[] = {"SKEW"};

static int rc_in_list(const char *kw, const char *const *list, int n)
{
    for (int i = 0; i < n; i++)
        if (strcmp(kw, list[i]) == 0) return 1;
    return 0;
}

/* Skip a card with one warning per kind (its first keyword): the first card
 * of a kind gets the warning, which then counts the others. */
static rc_status rc_skip(rc_reader *rd, const rc_block *b, const char *why)
{
    rc_case *c = rd->c;
    for (int i = 0; i < rd->nskipped; i++) {
        if (strcmp(rd->skipped[i].kw, b->kw[0]) != 0) continue;
        /* rewrite the kind's warning with the new count */
        char *w = c->warnings[rd->skipped[i].warning], *e = strstr(w, " (and ");
        int n = ++rd->skipped[i].count;
        size_t keep = e ? (size_t)(e - w) : strlen(w);
        char *nw = malloc(keep + 64);
        if (!nw) return rc_case_nomem(rd);
        memcpy(nw, w, keep);
        snprintf(nw + keep, 64, " (and %d more /%s card%s)", n - 1, b->kw[0], n > 2 ? "s" : "");
        free(w);
        c->warnings[rd->skipped[i].warning] = nw;
        return RC_OK;
    }
    int slot = rd->nskipped < (int)(sizeof rd->skipped / sizeof rd->skipped[0]);
    if (slot) {
        snprintf(rd->skipped[rd->nskipped].kw, sizeof rd->skipped[0].kw, "%s", b->kw[0]);
        rd->skipped[rd->nskipped].warning = c->nwarnings;
        rd->skipped[rd->nskipped].count = 1;
        rd->nskipped++;
    }
    return rc_case_warn(rd, &b->hdr->loc, "card %s ignored: %s", b->name, why);
}

/* Call the card function of a kind. */
static rc_status rc_card_call(rc_reader *rd, const rc_block *b, rc_card_kind kind)
{
    switch (kind) {
    case RC_CARD_BEGIN: return rc_card_begin(rd, b);
    case RC_CARD_NODE: return rc_card_node(rd, b);
    case RC_CARD_GRNOD: return rc_card_grnod(rd, b);
    case RC_CARD_RBODY: return rc_card_rbody(rd, b);
    case RC_CARD_PLANE: return rc_card_plane(rd, b);
    case RC_CARD_ELLIPS: return rc_card_ellips(rd, b);
    case RC_CARD_TYPE6: return rc_card_type6(rd, b);
    case RC_CARD_TYPE7: return rc_card_type7(rd, b);
    case RC_CARD_TYPE24: return rc_card_type24(rd, b);
    case RC_CARD_TYPE25: return rc_card_type25(rd, b);
    case RC_CARD_TYPE11: return rc_card_type11(rd, b);
    case RC_CARD_TYPE19: return rc_card_type19(rd, b);
    case RC_CARD_LINE: return rc_card_line(rd, b);
    case RC_CARD_FUNCT: return rc_card_funct(rd, b);
    case RC_CARD_INIVEL: return rc_card_inivel(rd, b);
    case RC_CARD_GRAV: return rc_card_grav(rd, b);
    case RC_CARD_BCS: return rc_card_bcs(rd, b);
    case RC_CARD_RUN: return rc_card_run(rd, b);
    case RC_CARD_SOLVER: return rc_card_solver(rd, b);
    case RC_CARD_CPL_SPRING: return rc_card_coupling_spring(rd, b);
    case RC_CARD_CPL_CATENARY: return rc_card_coupling_catenary(rd, b);
    case RC_CARD_CPL_CONTACT: return rc_card_coupling_contact(rd, b);
    case RC_CARD_PART: return rc_card_part(rd, b);
    case RC_CARD_GRPART: return rc_card_grpart(rd, b);
    case RC_CARD_FRICTION: return rc_card_friction(rd, b);
    case RC_CARD_FRIC_ORIENT: return rc_card_fricorient(rd, b);
    case RC_CARD_POWER: return rc_card_power(rd, b);
    case RC_CARD_CYL: return rc_card_cyl(rd, b);
    case RC_CARD_BOX: return rc_card_box(rd, b);
    case RC_CARD_IMPVEL: return rc_card_impvel(rd, b);
    case RC_CARD_UNIT: return rc_card_unit(rd, b);
    case RC_CARD_SEG: return rc_card_seg(rd, b);
    case RC_CARD_SURFPART: return rc_card_surfpart(rd, b);
    case RC_CARD_JOINT: return rc_card_joint(rd, b);
    case RC_CARD_RWALL: return rc_card_rwall(rd, b);
    case RC_CARD_SENSOR: return rc_card_sensor_time(rd, b);
    }
    return RC_SET(rd->err, RC_EINTERNAL, "unknown card kind %d", (int)kind);
}

/* Is sub a subtype that Radioss has for the family kw (a card of its own,
 * not supported yet), as opposed to a misspelling? The interface types
 * TYPEn, and the other subtypes of the families ricochet reads in part. */
static int rc_radioss_subtype(const char *kw, const char *sub)
{
    static const char *const surf[] = {"SEG", "PART", "BOX", "BOX2", "ELLIPS", "PLANE", "GRSHEL", "GRSH3N",
                                       "GRBRIC", "GRTRIA", "MAT", "PROP", "SUBSET", "SURF", "DSURF", "SUBMOD"};
    static const char *const grnod[] = {"NODE", "BOX", "BOX2", "PART", "GRNOD", "SURF", "SUBSET", "MAT",
                                        "PROP", "GEN_INCR", "NODENS", "LINE", "SUBMOD", "GENE"};
    static const char *const grpart[] = {"PART", "GRPART", "BOX", "BOX2", "MAT", "PROP", "SUBSET", "SUBMOD"};
    static const char *const inivel[] = {"TRA", "ROT", "T&R", "AXIS", "GRID", "FVM", "NODE"};
    static const char *const inter[] = {"SUB", "KINE", "LAGMUL", "HERTZ"};
    static const char *const rwall[] = {"PLANE", "CYL", "SPHER", "PARAL", "LAGMUL", "THERM"};
    static const char *const line[] = {"SURF", "EDGE", "SEG", "PART", "MAT", "PROP", "SUBSET", "BOX", "BOX2",
                                       "LINE", "GRTRUS", "GRSPRI", "GRBEAM", "SUBMOD"};
    static const char *const sensor[] = {"TIME", "ACCE", "DIST", "SENS", "AND", "OR", "NOT", "INTER", "RWALL", "RBODY",
                                         "SECT", "WORK", "ENERGY", "DIST_SURF", "HIC", "VEL", "GAUGE", "TEMP", "NIC_NIJ",
                                         "PYTHON", "USER1", "USER2", "USER3", "MATLAB", "DISP", "CONTACT"};
    if (strcmp(kw, "INTER") == 0) {
        if (strncmp(sub, "TYPE", 4) == 0 && sub[4] >= '0' && sub[4] <= '9') {
            const char *p = sub + 4;
            while (*p >= '0' && *p <= '9') p++;
            if (!*p) return 1;
        }
        return rc_in_list(sub, inter, RC_NF(inter));
    }
    if (strcmp(kw, "SURF") == 0) return rc_in_list(sub, surf, RC_NF(surf));
    if (strcmp(kw, "GRNOD") == 0) return rc_in_list(sub, grnod, RC_NF(grnod));
    if (strcmp(kw, "GRPART") == 0) return rc_in_list(sub, grpart, RC_NF(grpart));
    if (strcmp(kw, "INIVEL") == 0) return rc_in_list(sub, inivel, RC_NF(inivel));
    if (strcmp(kw, "RWALL") == 0) return rc_in_list(sub, rwall, RC_NF(rwall));
    if (strcmp(kw, "SENSOR") == 0) return rc_in_list(sub, sensor, RC_NF(sensor));
    if (strcmp(kw, "LINE") == 0) return rc_in_list(sub, line, RC_NF(line));
    return 0; /* /JOINT, /COUPLING: ricochet's own */
}

/* A family whose subtype is missing or not supported; a subtype that is
 * no card at all but one letter or two from a supported one is taken for
 * a misspelling ("did you mean"). */
static rc_status rc_bad_subtype(rc_reader *rd, const rc_block *b)
{
    char list[256] = "";
    const char *subs[32];
    int ns = 0;
    size_t k = 0;
    for (size_t i = 0; i < sizeof rc_card_table / sizeof rc_card_table[0]; i++)
        if (rc_card_table[i].sub && strcmp(rc_card_table[i].kw, b->kw[0]) == 0 && k < sizeof list) {
            k += (size_t)snprintf(list + k, sizeof list - k, "%s/%s/%s", k ? ", " : "",
                                  rc_card_table[i].kw, rc_card_table[i].sub);
            if (ns < 32) subs[ns++] = rc_card_table[i].sub;
        }
    if (b->nkw < 2)
        return rc_case_fail(rd, &b->hdr->loc, b->name, NULL, "missing subtype (expected %s)",
                            list);
    const char *near = rc_radioss_subtype(b->kw[0], b->kw[1]) ? NULL : rc_closest_name(b->kw[1], subs, ns);
    if (near)
        return rc_case_fail(rd, &b->hdr->loc, b->name, NULL, "/%s/%s: no such card: did you mean /%s/%s? (supported: %s)",
                            b->kw[0], b->kw[1], b->kw[0], near, list);
    return rc_case_fail(rd, &b->hdr->loc, b->name, NULL,
                        "/%s/%s: not supported yet (supported: %s)", b->kw[0], b->kw[1], list);
}

rc_status rc_card_dispatch(rc_reader *rd, const rc_block *b)
{
    const char *kw = b->kw[0];
    int family = 0, mesh = 0;
    rc_status st;
    /* the Radioss engine /RUN/name/n[/letter] (a run name after RUN, or two
     * numbers) and /ANIM/DT give the run settings */
    if (strcmp(kw, "RUN") == 0 && (b->nkw >= 2 || b->unit_id || (b->bad && b->nkw == 1)))
        return rc_card_engine_run(rd, b);
    if (strcmp(kw, "ANIM") == 0 && b->nkw == 2 && strcmp(b->kw[1], "DT") == 0 && !b->has_id)
        return rc_card_anim_dt(rd, b);
    /* the mesh cards (cards_mesh.c) first: /PROP and /MAT are partly read */
    if ((st = rc_cards_mesh(rd, b, &mesh)) || mesh) return st;
    /* ignored Radioss cards: a warning, whatever their header */
    if (rc_in_list(kw, rc_ignored, RC_NF(rc_ignored)))
        return rc_skip(rd, b, "no meaning for rigid bodies");
    if (rc_in_list(kw, rc_explicit, RC_NF(rc_explicit)))
        return rc_skip(rd, b, "only meaningful to an explicit run (ricochet integrates implicitly)");
    if (b->bad)
        return rc_case_fail(rd, &b->hdr->loc, b->name, NULL, "malformed card header: %s", b->bad);
    /* supported cards */
    for (size_t i = 0; i < sizeof rc_card_table / sizeof rc_card_table[0]; i++) {
        if (strcmp(rc_card_table[i].kw, kw) != 0) continue;
        if (!rc_card_table[i].sub) return rc_card_call(rd, b, rc_card_table[i].kind);
        family = 1;
        if (b->nkw >= 2 && strcmp(rc_card_table[i].sub, b->kw[1]) == 0)
            return rc_card_call(rd, b, rc_card_table[i].kind);
    }
    if (family) return rc_bad_subtype(rd, b);
    /* planned, then unknown */
    if (rc_in_list(kw, rc_planned, RC_NF(rc_planned)))
        return rc_case_fail(rd, &b->hdr->loc, b->name, NULL, "not supported yet");
    /* a misspelling of a card read, ignored or planned */
    const char *all[sizeof rc_card_table / sizeof rc_card_table[0] + RC_NF(rc_ignored) + RC_NF(rc_explicit) +
                    RC_NF(rc_planned)];
    int na = 0;
    for (size_t i = 0; i < sizeof rc_card_table / sizeof rc_card_table[0]; i++) all[na++] = rc_card_table[i].kw;
    for (int i = 0; i < RC_NF(rc_ignored); i++) all[na++] = rc_ignored[i];
    for (int i = 0; i < RC_NF(rc_explicit); i++) all[na++] = rc_explicit[i];
    for (int i = 0; i < RC_NF(rc_planned); i++) all[na++] = rc_planned[i];
    const char *near = rc_closest_name(kw, all, na);
    if (near)
        return rc_case_fail(rd, &b->hdr->loc, b->name, NULL,
                            "unknown card: did you mean /%s? (docs/case-format.md lists the cards read and those "
                            "ignored)", near);
    return rc_case_fail(rd, &b->hdr->loc, b->name, NULL,
                        "unknown card (docs/case-format.md lists the cards read and those "
                        "ignored)");
}
