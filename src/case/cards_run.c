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
#define RC_DEF_METHOD 0 /* automatic: IDA with joints, else CVODE */
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

/* A line of three unit names (mass, length, time; 20 characters each) into
 * `u` and their values in kg, m, s into f (1 when blank). `ln` NULL: all
 * blank. */
static rc_status rc_unit_line(rc_reader *rd, const rc_block *b, const rc_line *ln, char u[3][21],
                              const char *const nm[3], double f[3])
{
    static const rc_line blank = {"", 0, {NULL, 0}};
    rc_field l[] = {RC_F_STR(nm[0], u[0], 20), RC_F_STR(nm[1], u[1], 20), RC_F_STR(nm[2], u[2], 20)};
    l[0].cap = l[1].cap = l[2].cap = 21;
    rc_status st = rc_parse_line(rd, b, ln ? ln : &blank, l, 3);
    if (st) return st;
    for (int k = 0; k < 3; k++) {
        f[k] = 1.0;
        if (u[k][0] && !rc_unit_factor(k, u[k], &f[k]))
            return rc_case_fail(rd, &ln->loc, b->name, nm[k],
                                "expected a unit name (%s) or a positive number (the unit in %s), "
                                "got \"%s\"",
                                rc_unit_names(k), k == 0 ? "kg" : k == 1 ? "m" : "s", u[k]);
    }
    return RC_OK;
}

/* /BEGIN: run name; Invers Irun; input units; work units. Every line is
 * optional: the Radioss 5.1 and 9.0 form stops after the version line (the
 * units then come from /UNIT cards), an empty block gives no name, version
 * or units. A second /BEGIN (an included model) is ignored with a warning. */
rc_status rc_card_begin(rc_reader *rd, const rc_block *b)
{
    static const char *const in_nm[3] = {"Input_mass_unit", "Input_length_unit",
                                         "Input_time_unit"};
    static const char *const wk_nm[3] = {"Work_mass_unit", "Work_length_unit",
                                         "Work_time_unit"};
    rc_case *c = rd->c;
    char in[3][21] = {"", "", ""}, wk[3][21] = {"", "", ""};
    int nd, invers = 0, lines;
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_NONE, NULL, "/BEGIN"))) return st;
    if (rd->begin_hdr)
        return rc_case_warn(rd, &b->hdr->loc,
                            "card %s ignored: a second /BEGIN (of an included model); the "
                            "first one, at %s:%d, gives the version and the units",
                            b->name, rd->begin_hdr->loc.file, rd->begin_hdr->loc.line);
    rd->begin_hdr = b->hdr;
    lines = rc_block_trim(b);
    if (lines == 0)
        return rc_case_warn(rd, &b->hdr->loc, "card %s is empty: no run name, version or units",
                            b->name);
    if ((st = rc_card_lines(rd, b, c->title, 0, 3, "Invers Irun, input units, work units", &nd)))
        return st;

    /* the version (its layouts), input units, work units */
    rc_field l1[] = {RC_F_INT("Invers", &invers, 0, RC_FF_NONNEG), RC_F_INT("Irun", NULL, 0, 0)};
    if (nd >= 1 && (st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1)))) return st;
    c->invers = invers;
    if (invers != 0 && rc_layout_known(invers) == 0 &&
        (st = rc_case_warn(rd, &b->lines[1].loc,
                           "card %s: Invers = %d is not a Radioss version ricochet knows (41..44, "
                           "51, 90, 100..140, 2017..2026): the layouts of the nearest older one "
                           "are used",
                           b->name, invers)))
        return st;

    /* the input units: every value read is converted to SI (ricochet
     * computes in kg, m, s); the work units are checked and reported only */
    double fi[3], fw[3];
    if ((st = rc_unit_line(rd, b, nd >= 2 ? &b->lines[2] : NULL, in, in_nm, fi))) return st;
    if ((st = rc_unit_line(rd, b, nd >= 3 ? &b->lines[3] : NULL, wk, wk_nm, fw))) return st;
    memcpy(rd->begin_units, fi, sizeof fi);
    if (in[0][0] || in[1][0] || in[2][0]) {
        static const char *const si[3] = {"kg", "m", "s"};
        for (int k = 0; k < 3; k++) {
            snprintf(c->deck_unit[k], sizeof c->deck_unit[k], "%.20s", in[k][0] ? in[k] : si[k]);
            c->deck_factor[k] = fi[k];
        }
        /* the case holds SI values */
        strcpy(c->unit_mass, "kg");
        strcpy(c->unit_length, "m");
        strcpy(c->unit_time, "s");
    }
    if ((fi[0] != 1 || fi[1] != 1 || fi[2] != 1) &&
        (st = rc_case_warn(rd, &b->lines[2].loc,
                           "units: the input units of %s (mass %s, length %s, time %s) are "
                           "converted to SI (kg, m, s): factors %.15g, %.15g, %.15g",
                           b->name, in[0][0] ? in[0] : "kg", in[1][0] ? in[1] : "m",
                           in[2][0] ? in[2] : "s", fi[0], fi[1], fi[2])))
        return st;
    if (nd >= 3 && (fw[0] != 1 || fw[1] != 1 || fw[2] != 1))
        return rc_case_warn(rd, &b->lines[3].loc,
                            "units: the work units of %s (%s, %s, %s) are not used: ricochet "
                            "computes and writes its results in SI (kg, m, s)",
                            b->name, wk[0], wk[1], wk[2]);
    return RC_OK;
}

/* /UNIT/unit_ID: title; MUNIT LUNIT TUNIT (20 characters each). The
 * values of every card whose header names unit_ID are converted to SI. */
rc_status rc_card_unit(rc_reader *rd, const rc_block *b)
{
    static const char *const nm[3] = {"MUNIT", "LUNIT", "TUNIT"};
    static const char *const kinds[3] = {"MASS", "LENGTH", "TIME"};
    char title[RC_CASE_TITLE_MAX + 1], u[3][21] = {"", "", ""};
    double f[3];
    int nd;
    rc_status st;
    /* Radioss 5.1 and 9.0: /UNIT/MASS/name, /UNIT/LENGTH/name,
     * /UNIT/TIME/name (no line) give the deck's units */
    for (int k = 0; b->nkw >= 2 && k < 3; k++) {
        if (strcmp(b->kw[1], kinds[k]) != 0) continue;
        const char *p = strchr(b->hdr->text + 1, '/');
        p = p ? strchr(p + 1, '/') : NULL;
        char name[21] = "";
        size_t n = 0;
        if (p) {
            p++;
            while (*p == ' ') p++;
            while (p[n] && p[n] != '/' && p[n] != ' ' && n < sizeof name - 1) n++;
            memcpy(name, p, n);
            name[n] = '\0';
        }
        double fk;
        if (!name[0] || !rc_unit_factor(k, name, &fk))
            return rc_case_fail(rd, &b->hdr->loc, b->name, kinds[k],
                                "expected /UNIT/%s/name with a unit name (%s) or a positive "
                                "number, got \"%s\"",
                                kinds[k], rc_unit_names(k), name);
        if ((st = rc_card_lines(rd, b, NULL, 0, 0, "no line", &nd))) return st;
        rd->begin_units[k] = fk;
        {
            static const char *const si[3] = {"kg", "m", "s"};
            for (int j = 0; j < 3; j++)
                if (!rd->c->deck_unit[j][0]) {
                    snprintf(rd->c->deck_unit[j], sizeof rd->c->deck_unit[j], "%s", si[j]);
                    rd->c->deck_factor[j] = 1.0;
                }
            snprintf(rd->c->deck_unit[k], sizeof rd->c->deck_unit[k], "%.20s", name);
            rd->c->deck_factor[k] = fk;
        }
        strcpy(rd->c->unit_mass, "kg");
        strcpy(rd->c->unit_length, "m");
        strcpy(rd->c->unit_time, "s");
        if (rd->c->invers > 90 &&
            (st = rc_case_warn(rd, &b->hdr->loc,
                               "card %s: a Radioss 5.1/9.0 form, read although /BEGIN gives "
                               "version %d",
                               b->name, rd->c->invers)))
            return st;
        return rc_case_warn(rd, &b->hdr->loc,
                            "units: card %s: the deck's %s unit %s is converted to SI (factor "
                            "%.15g)",
                            b->name, k == 0 ? "mass" : k == 1 ? "length" : "time", name, fk);
    }
    if ((st = rc_header(rd, b, 1, RC_ID_REQUIRED, "unit_ID", "/UNIT/unit_ID"))) return st;
    for (int i = 0; i < rd->nunits; i++)
        if (rd->units[i].id == b->id)
            return rc_case_fail(rd, &b->hdr->loc, b->name, "unit_ID",
                                "duplicate id %d, first defined at %s:%d", b->id,
                                rd->units[i].loc.file, rd->units[i].loc.line);
    if ((st = rc_card_lines(rd, b, title, 1, 1, "MUNIT LUNIT TUNIT", &nd))) return st;
    if ((st = rc_unit_line(rd, b, &b->lines[1], u, nm, f))) return st;
    RC_GROW(rd, rd->units, rd->capunits, rd->nunits);
    struct rc_unitsys *us = &rd->units[rd->nunits++];
    us->id = b->id;
    memcpy(us->f, f, sizeof f);
    us->loc = b->hdr->loc;
    return rc_case_warn(rd, &b->hdr->loc,
                        "units: card %s (mass %s, length %s, time %s): the values of the cards "
                        "whose header names unit_ID %d are converted to SI (kg, m, s): factors "
                        "%.15g, %.15g, %.15g",
                        b->name, u[0][0] ? u[0] : "kg", u[1][0] ? u[1] : "m", u[2][0] ? u[2] : "s",
                        b->id, f[0], f[1], f[2]);
}

/* ======================================================================
 * /RUN and /SOLVER (ricochet cards)
 * ====================================================================== */

/* /RUN: Tend Dt_out Ev_state On_viol. */
rc_status rc_card_run(rc_reader *rd, const rc_block *b)
{
    rc_case_run *r = &rd->c->run;
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_OPTIONAL, NULL, "/RUN or /RUN/1"))) return st;
    if ((st = rc_single(rd, b, &rd->run_hdr))) return st;
    if ((st = rc_card_lines(rd, b, NULL, 1, 1, "Tend Dt_out Ev_state On_viol", &nd))) return st;
    rc_field f[] = {RC_F_REALD("Tend", &r->tend, 0, RC_FF_POS, RC_D_T),
                    RC_F_REALD("Dt_out", &r->dtout, 0, RC_FF_NONNEG, RC_D_T),
                    RC_F_SET("Ev_state", &r->ev_state, 0, 0, RC_BIT(0) | RC_BIT(1) | RC_BIT(2), 0, NULL),
                    RC_F_SET("On_viol", &r->on_violation, 0, 0, RC_BIT(0) | RC_BIT(1) | RC_BIT(2), 0, NULL)};
    if ((st = rc_parse_line(rd, b, &b->lines[0], f, RC_NF(f)))) return st;
    /* output interval: blank or 0 means Tend/100 */
    if (r->dtout == 0) r->dtout = RC_DEF_DTOUT_FRACTION * r->tend;
    /* records at 0, Dt_out, ..., Tend: at most RC_MAX_RECORDS */
    const double nrec = floor(r->tend / r->dtout) + 2.0;
    if (!(nrec <= (double)RC_MAX_RECORDS))
        return rc_case_fail(rd, &b->lines[0].loc, b->name, "Dt_out",
                            "the output interval %g s over Tend = %g s gives %.4g records, more than the limit of %d; "
                            "expected an output interval of at least %g s (or a shorter Tend)",
                            r->dtout, r->tend, nrec, RC_MAX_RECORDS, r->tend / (RC_MAX_RECORDS - 2.0));
    r->present = 1;
    r->loc = b->hdr->loc;
    return RC_OK;
}

/* ======================================================================
 * Radioss engine cards: /RUN/name/n, /ANIM/DT
 * ====================================================================== */

/* Engine lines are read as Radioss reads them: fixed 20-column fields, or
 * free format (blank-separated) when a value crosses a field boundary.
 * `buf` (RC_CASE_MAX_LINE + 1) receives the comma-joined free form. */
static const rc_line *rc_engine_line(const rc_line *ln, char *buf, rc_line *tmp)
{
    int cross = 0, k = 0, last = -1;
    for (int i = 0; i < ln->len;) {
        if (ln->text[i] == ' ') { i++; continue; }
        int j = i;
        while (j < ln->len && ln->text[j] != ' ') j++;
        /* a value across two fields, or two values in one field */
        if (i / 20 != (j - 1) / 20 || i / 20 == last) cross = 1;
        last = i / 20;
        i = j;
    }
    if (!cross || memchr(ln->text, ',', (size_t)ln->len)) return ln;
    for (int i = 0; i < ln->len;) {
        if (ln->text[i] == ' ') { i++; continue; }
        if (k) buf[k++] = ',';
        while (i < ln->len && ln->text[i] != ' ' && k < RC_CASE_MAX_LINE) buf[k++] = ln->text[i++];
    }
    buf[k] = '\0';
    *tmp = *ln;
    tmp->text = buf;
    tmp->len = k;
    return tmp;
}

/* /RUN/run_name/run_number[/restart_letter] (the Radioss engine file
 * name_0001.rad): one line, Tstop. Gives ricochet's end time when the deck
 * has no ricochet /RUN. */
rc_status rc_card_engine_run(rc_reader *rd, const rc_block *b)
{
    int nd;
    rc_status st;
    if (rd->engine_run_hdr)
        return rc_case_fail(rd, &b->hdr->loc, b->name, NULL,
                            "only one Radioss engine /RUN card is allowed, first at %s:%d",
                            rd->engine_run_hdr->loc.file, rd->engine_run_hdr->loc.line);
    rd->engine_run_hdr = b->hdr;
    if ((st = rc_card_lines(rd, b, NULL, 1, 1, "Tstop", &nd))) return st;
    rc_field f[] = {RC_F_REALD("Tstop", &rd->engine_tstop, 0, RC_FF_POS, RC_D_T)};
    char buf[RC_CASE_MAX_LINE + 1];
    rc_line tmp;
    return rc_parse_line(rd, b, rc_engine_line(&b->lines[0], buf, &tmp), f, RC_NF(f));
}

/* /ANIM/DT (engine): Tstart Tfreq; Tfreq gives the output interval when
 * the end time comes from the engine /RUN. */
rc_status rc_card_anim_dt(rc_reader *rd, const rc_block *b)
{
    int nd;
    double tstart = 0;
    rc_status st;
    if ((st = rc_card_lines(rd, b, NULL, 1, 1, "Tstart Tfreq", &nd))) return st;
    rc_field f[] = {RC_F_REALD("Tstart", &tstart, 0, 0, RC_D_T), RC_F_REALD("Tfreq", &rd->anim_dt, 0, RC_FF_NONNEG, RC_D_T)};
    char buf[RC_CASE_MAX_LINE + 1];
    rc_line tmp;
    if ((st = rc_parse_line(rd, b, rc_engine_line(&b->lines[0], buf, &tmp), f, RC_NF(f)))) return st;
    rd->anim_dt_hdr = b->hdr;
    return RC_OK;
}

/* The run settings from the engine cards: Tend = Tstop of /RUN/name/n,
 * Dt_out = Tfreq of /ANIM/DT (else Tend/100). A ricochet /RUN wins. */
static rc_status rc_engine_settings(rc_reader *rd)
{
    rc_case *c = rd->c;
    rc_case_run *r = &c->run;
    rc_status st;
    if (rd->anim_dt_hdr && (!rd->engine_run_hdr || rd->run_hdr) &&
        (st = rc_case_warn(rd, &rd->anim_dt_hdr->loc,
                           "card /ANIM/DT ignored: the output interval is Dt_out of %s",
                           rd->run_hdr ? "ricochet's /RUN" : "the deck (no engine /RUN)")))
        return st;
    if (!rd->engine_run_hdr) return RC_OK;
    if (rd->run_hdr)
        return rc_case_warn(rd, &rd->engine_run_hdr->loc,
                            "Radioss engine card %s ignored: the ricochet /RUN at %s:%d gives "
                            "the run settings",
                            rd->engine_run_hdr->text, rd->run_hdr->loc.file, rd->run_hdr->loc.line);
    if (!(rd->engine_tstop > 0)) return RC_OK; /* its error is reported */
    r->present = 1;
    r->tend = rd->engine_tstop;
    r->dtout = rd->anim_dt > 0 ? rd->anim_dt : RC_DEF_DTOUT_FRACTION * r->tend;
    r->ev_state = 0;
    r->loc = rd->engine_run_hdr->loc;
    const double nrec = floor(r->tend / r->dtout) + 2.0;
    if (!(nrec <= (double)RC_MAX_RECORDS))
        return rc_case_fail(rd, &(rd->anim_dt > 0 ? rd->anim_dt_hdr : rd->engine_run_hdr)->loc, NULL, NULL,
                            "the output interval %g s (%s) over Tend = Tstop = %g s gives %.4g records, more than the "
                            "limit of %d; expected an output interval of at least %g s",
                            r->dtout, rd->anim_dt > 0 ? "Tfreq of /ANIM/DT" : "Tend/100", r->tend, nrec,
                            RC_MAX_RECORDS, r->tend / (RC_MAX_RECORDS - 2.0));
    return rc_case_warn(rd, &r->loc,
                        "run settings from the Radioss engine card %s: Tend = Tstop = %.15g s, "
                        "Dt_out = %.15g s (%s)",
                        rd->engine_run_hdr->text, r->tend, r->dtout,
                        rd->anim_dt > 0 ? "Tfreq of /ANIM/DT" : "Tend/100");
}

/* /SOLVER: Method Max_order Max_steps Rtol Hmax H0 Preload; the four
 * absolute tolerances; Atol_energy Switch. */
rc_status rc_card_solver(rc_reader *rd, const rc_block *b)
{
    rc_case_solver *s = &rd->c->solver;
    int nd, steps = 0;
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_OPTIONAL, NULL, "/SOLVER or /SOLVER/1"))) return st;
    if ((st = rc_single(rd, b, &rd->solver_hdr))) return st;
    if ((st = rc_card_lines(rd, b, NULL, 1, 3,
                            "Method Max_order Max_steps Rtol Hmax H0 Preload[, Atol_pos Atol_quat "
                            "Atol_vel Atol_omega[, Atol_energy Switch]]",
                            &nd)))
        return st;

    const unsigned zp = RC_FF_ZDEF | RC_FF_POS;
    rc_field l1[] = {
        RC_F_SET("Method", &s->method, RC_DEF_METHOD, 0, RC_BIT(0) | RC_BIT(1) | RC_BIT(2) | RC_BIT(3), 0, NULL),
        RC_F_SET("Max_order", &s->max_order, RC_DEF_MAX_ORDER, RC_FF_ZDEF, 0x3Eu, 0, NULL),
        RC_F_INT("Max_steps", &steps, RC_DEF_MAX_STEPS, zp),
        RC_F_REALD("Rtol", &s->rtol, RC_DEF_RTOL, zp, RC_D_NONE),
        RC_F_REALD("Hmax", &s->hmax, 0, RC_FF_NONNEG, RC_D_T),
        RC_F_REALD("H0", &s->h0, 0, RC_FF_NONNEG, RC_D_T),
        RC_F_SET("Preload", &s->preload, 0, 0, RC_BIT(0) | RC_BIT(1), 0, NULL)};
    rc_field l2[] = {RC_F_REALD("Atol_pos", &s->atol_pos, RC_DEF_ATOL_POS, RC_FF_ZDEF | RC_FF_NONNEG, RC_D_L),
                     RC_F_REALD("Atol_quat", &s->atol_quat, RC_DEF_ATOL_QUAT, RC_FF_ZDEF | RC_FF_NONNEG, RC_D_NONE),
                     RC_F_REALD("Atol_vel", &s->atol_vel, RC_DEF_ATOL_VEL, RC_FF_ZDEF | RC_FF_NONNEG, RC_D_V),
                     RC_F_REALD("Atol_omega", &s->atol_omega, RC_DEF_ATOL_OMEGA, RC_FF_ZDEF | RC_FF_NONNEG, RC_D_W)};
    rc_field l3[] = {RC_F_REALD("Atol_energy", &s->atol_energy, RC_DEF_ATOL_ENERGY, RC_FF_ZDEF | RC_FF_NONNEG, RC_D_E),
                     RC_F_SET("Switch", &s->method_switch, 0, 0, RC_BIT(0) | RC_BIT(1), 0, NULL)};
    if ((st = rc_parse_line(rd, b, &b->lines[0], l1, RC_NF(l1)))) return st;
    if (nd >= 2 && (st = rc_parse_line(rd, b, &b->lines[1], l2, RC_NF(l2)))) return st;
    if (nd >= 3 && (st = rc_parse_line(rd, b, &b->lines[2], l3, RC_NF(l3)))) return st;
    s->max_steps = steps;
    s->present = 1;
    s->loc = b->hdr->loc;
    s->method_loc = b->lines[0].loc;
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
    s->preload = 0;
    s->method_switch = 0;
}

rc_status rc_cards_finish(rc_reader *rd)
{
    rc_case *c = rd->c;
    rc_status st;
    if ((st = rc_engine_settings(rd))) return st;
    /* deck-level messages name the end of the deck (the /END line) */
    c->end = (rc_loc){c->files[0], rd->main_last_line > 0 ? rd->main_last_line : 1};
    /* the end time is required */
    if (!c->run.present && !rd->run_hdr && !rd->engine_run_hdr)
        return rc_case_fail(rd, &c->end, NULL, NULL,
                            "no /RUN card: the end time is required (ricochet's /RUN, or the "
                            "Radioss engine card /RUN/name/n)");
    /* without /SOLVER, the defaults apply there too */
    if (!c->solver.present) c->solver.loc = c->solver.method_loc = c->end;
    return RC_OK;
}
