/*
 * Cards of the run, the solver and the output: /BEGIN (run name, units),
 * /RUN (end time, output interval), /SOLVER (ricochet: method, tolerances);
 * the deck-level defaults and checks.
 * Layouts are field tables (case_internal.h), documented in
 * docs/case-format.md; references between cards are resolved by the
 * compiler (src/model). Values ricochet cannot honour yet are rejected with
 * "not supported yet", never ignored.
 */
#include "case/case_internal.h"
#include "base/error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Defaults of /SOLVER (docs/case-format.md). */
#define RC_DEF_METHOD 1
#define RC_DEF_MAX_ORDER 5
#define RC_DEF_MAX_STEPS 100000
#define RC_DEF_RTOL 1e-8
/* absolute tolerances: 0 (blank) = derived from the model's scales */
#define RC_DEF_ATOL_POS 0.0
#define RC_DEF_ATOL_QUAT 0.0
#define RC_DEF_ATOL_VEL 0.0
#define RC_DEF_ATOL_OMEGA 0.0
#define RC_DEF_ATOL_ENERGY 0.0
/* Default output interval as a fraction of Tend. */
#define RC_DEF_DTOUT_FRACTION 0.01

/* A card allowed once per deck. */
static rc_status rc_single(rc_reader *rd, const rc_block *b, const rc_line **slot)
{
    if (*slot)
        return rc_case_fail(rd, &b->hdr->loc, b->name, NULL,
                            "only one such card is allowed, first at %s:%d", (*slot)->loc.file,
                            (*slot)->loc.line);
    *slot = b->hdr;
    return RC_OK;
}

/* ======================================================================
 * /BEGIN
 * ====================================================================== */

/* /BEGIN: run name; Invers Irun; input units; work units (= input). */
rc_status rc_card_begin(rc_reader *rd, const rc_block *b)
{
    static const char *const in_nm[3] = {"Input_mass_unit", "Input_length_unit",
                                         "Input_time_unit"};
    static const char *const wk_nm[3] = {"Work_mass_unit", "Work_length_unit",
                                         "Work_time_unit"};
    rc_case *c = rd->c;
    char in[3][21] = {"", "", ""}, wk[3][21] = {"", "", ""};
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_NONE, NULL, "/BEGIN"))) return st;
    if ((st = rc_single(rd, b, &rd->begin_hdr))) return st;
    if ((st = rc_card_lines(rd, b, c->title, 3, 3, "Invers Irun, input units, work units", &nd)))
        return st;

    /* three lines: version flags (ignored), input units, work units */
    rc_field l1[] = {RC_F_INT("Invers", NULL, 0, 0), RC_F_INT("Irun", NULL, 0, 0)};
    rc_field l2[] = {RC_F_STR(in_nm[0], in[0], 20), RC_F_STR(in_nm[1], in[1], 20),
                     RC_F_STR(in_nm[2], in[2], 20)};
    rc_field l3[] = {RC_F_STR(wk_nm[0], wk[0], 20), RC_F_STR(wk_nm[1], wk[1], 20),
                     RC_F_STR(wk_nm[2], wk[2], 20)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1)))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[2], l2, RC_NF(l2)))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[3], l3, RC_NF(l3)))) return st;

    /* work units must be blank or the input units: no conversion yet */
    for (int k = 0; k < 3; k++)
        if (wk[k][0] && strcmp(wk[k], in[k]) != 0)
            return rc_case_fail(rd, &b->lines[3].loc, b->name, wk_nm[k],
                                "expected blank or \"%s\" (the input unit), got \"%s\": unit "
                                "conversion not supported yet",
                                in[k], wk[k]);
    memcpy(c->unit_mass, in[0], sizeof in[0]);
    memcpy(c->unit_length, in[1], sizeof in[1]);
    memcpy(c->unit_time, in[2], sizeof in[2]);
    return RC_OK;
}

/* ======================================================================
 * /RUN and /SOLVER (ricochet cards)
 * ====================================================================== */

/* /RUN: Tend Dt_out Ev_state. */
rc_status rc_card_run(rc_reader *rd, const rc_block *b)
{
    rc_case_run *r = &rd->c->run;
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_OPTIONAL, NULL, "/RUN or /RUN/1"))) return st;
    if ((st = rc_single(rd, b, &rd->run_hdr))) return st;
    if ((st = rc_card_lines(rd, b, NULL, 1, 1, "Tend Dt_out Ev_state", &nd))) return st;
    rc_field f[] = {RC_F_REAL("Tend", &r->tend, 0, RC_FF_POS),
                    RC_F_REAL("Dt_out", &r->dtout, 0, RC_FF_NONNEG),
                    RC_F_SET("Ev_state", &r->ev_state, 0, 0, RC_BIT(0) | RC_BIT(1) | RC_BIT(2), 0, NULL)};
    if ((st = rc_parse_line(rd, b, &b->lines[0], f, RC_NF(f)))) return st;
    /* output interval: blank or 0 means Tend/100 */
    if (r->dtout == 0) r->dtout = RC_DEF_DTOUT_FRACTION * r->tend;
    r->present = 1;
    r->loc = b->hdr->loc;
    return RC_OK;
}

/* /SOLVER: Method Max_order Max_steps Rtol Hmax H0; the four absolute
 * tolerances; Atol_energy. */
rc_status rc_card_solver(rc_reader *rd, const rc_block *b)
{
    rc_case_solver *s = &rd->c->solver;
    int nd, steps = 0;
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_OPTIONAL, NULL, "/SOLVER or /SOLVER/1"))) return st;
    if ((st = rc_single(rd, b, &rd->solver_hdr))) return st;
    if ((st = rc_card_lines(rd, b, NULL, 1, 3,
                            "Method Max_order Max_steps Rtol Hmax H0[, Atol_pos Atol_quat "
                            "Atol_vel Atol_omega[, Atol_energy]]",
                            &nd)))
        return st;

    const unsigned zp = RC_FF_ZDEF | RC_FF_POS;
    rc_field l1[] = {
        RC_F_SET("Method", &s->method, RC_DEF_METHOD, RC_FF_ZDEF, RC_BIT(1) | RC_BIT(2), RC_BIT(1),
                 "(2 = IDA is planned)"),
        RC_F_SET("Max_order", &s->max_order, RC_DEF_MAX_ORDER, RC_FF_ZDEF, 0x3Eu, 0, NULL),
        RC_F_INT("Max_steps", &steps, RC_DEF_MAX_STEPS, zp),
        RC_F_REAL("Rtol", &s->rtol, RC_DEF_RTOL, zp),
        RC_F_REAL("Hmax", &s->hmax, 0, RC_FF_NONNEG),
        RC_F_REAL("H0", &s->h0, 0, RC_FF_NONNEG)};
    rc_field l2[] = {RC_F_REAL("Atol_pos", &s->atol_pos, RC_DEF_ATOL_POS, RC_FF_ZDEF | RC_FF_NONNEG),
                     RC_F_REAL("Atol_quat", &s->atol_quat, RC_DEF_ATOL_QUAT, RC_FF_ZDEF | RC_FF_NONNEG),
                     RC_F_REAL("Atol_vel", &s->atol_vel, RC_DEF_ATOL_VEL, RC_FF_ZDEF | RC_FF_NONNEG),
                     RC_F_REAL("Atol_omega", &s->atol_omega, RC_DEF_ATOL_OMEGA, RC_FF_ZDEF | RC_FF_NONNEG)};
    rc_field l3[] = {RC_F_REAL("Atol_energy", &s->atol_energy, RC_DEF_ATOL_ENERGY, RC_FF_ZDEF | RC_FF_NONNEG)};
    if ((st = rc_parse_line(rd, b, &b->lines[0], l1, RC_NF(l1)))) return st;
    if (nd >= 2 && (st = rc_parse_line(rd, b, &b->lines[1], l2, RC_NF(l2)))) return st;
    if (nd >= 3 && (st = rc_parse_line(rd, b, &b->lines[2], l3, RC_NF(l3)))) return st;
    s->max_steps = steps;
    s->present = 1;
    s->loc = b->hdr->loc;
    return RC_OK;
}

/* ======================================================================
 * Deck level
 * ====================================================================== */

void rc_cards_defaults(rc_case *c)
{
    rc_case_solver *s = &c->solver;
    s->present = 0;
    s->method = RC_DEF_METHOD;
    s->max_order = RC_DEF_MAX_ORDER;
    s->max_steps = RC_DEF_MAX_STEPS;
    s->rtol = RC_DEF_RTOL;
    s->atol_pos = RC_DEF_ATOL_POS;
    s->atol_quat = RC_DEF_ATOL_QUAT;
    s->atol_vel = RC_DEF_ATOL_VEL;
    s->atol_omega = RC_DEF_ATOL_OMEGA;
    s->atol_energy = RC_DEF_ATOL_ENERGY;
    s->hmax = 0;
    s->h0 = 0;
}

rc_status rc_cards_finish(rc_reader *rd)
{
    rc_case *c = rd->c;
    /* deck-level messages name the end of the deck (the /END line) */
    c->end = (rc_loc){c->files[0], rd->main_last_line > 0 ? rd->main_last_line : 1};
    /* the end time is required */
    if (!c->run.present) return rc_case_fail(rd, &c->end, NULL, NULL, "no /RUN card: the end time is required");
    /* without /SOLVER, the defaults apply there too */
    if (!c->solver.present) c->solver.loc = c->end;
    return RC_OK;
}
