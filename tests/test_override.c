/*
 * --set overrides (src/case/override.c, rc_case_load_set): a value given by
 * card and field name replaces the deck's text and is read as deck input
 * (parser, checks, defaults, units); every error names the argument.
 * The CLI side (--set, the results file's attribute) is in tests/cli_test.sh.
 */
#include "harness.h"
#include "testutil.h"
#include "case/case.h"
#include "base/error.h"
#include "model/model.h"
#include "model/friction.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#define DEMO "cases/demo_sphere_drop.rad"

/* Load `path` with the overrides (NULL-terminated list); the case or NULL
 * (the message in *e). */
static rc_case *load_set(const char *path, rc_error *e, ...)
{
    const char *set[16];
    int n = 0;
    va_list ap;
    va_start(ap, e);
    for (const char *s; n < 16 && (s = va_arg(ap, const char *));) set[n++] = s;
    va_end(ap);
    rc_case *c = (rc_case *)1;
    rc_error_clear(e);
    rc_status st = rc_case_load_set(path, set, n, &c, e);
    if (st != RC_OK) {
        ENSURE(c == NULL && e->code == st);
        return NULL;
    }
    return c;
}

/* The load fails with RC_EINPUT, nothing loaded, and the message is `msg`
 * (the whole first line when `whole`, else a prefix). */
static int fails_with(const char *path, const char *arg, const char *arg2, const char *msg, int whole)
{
    rc_error e;
    rc_case *c = (rc_case *)1;
    const char *set[2] = {arg, arg2};
    rc_error_clear(&e);
    rc_status st = rc_case_load_set(path, set, arg2 ? 2 : 1, &c, &e);
    const size_t n = strlen(msg);
    const int ok = st == RC_EINPUT && c == NULL && e.code == RC_EINPUT && strncmp(e.msg, msg, n) == 0 &&
                   (!whole || e.msg[n] == '\0' || e.msg[n] == '\n');
    if (!ok) fprintf(stderr, "  status %d, message: %s\n  expected: %s\n", st, e.msg, msg);
    if (st == RC_OK) rc_case_free(c);
    return ok;
}

/* The overrides reach the compiled model: the sphere's mass and the
 * interface's friction coefficient; the case keeps their list. Names of
 * cards and fields in any case. */
static void test_override_changes_model(void)
{
    rc_error e;
    rc_case *c = load_set(DEMO, &e, "/RBODY/1:Mass=1.4837", "/inter/type6/1:fric=0.3719", (const char *)NULL);
    ENSURE(c != NULL);
    if (!c) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    ENSURE(c->nrbody == 1 && c->rbody[0].mass == 1.4837);
    ENSURE(c->ntype6 == 1 && c->type6[0].fric == 0.3719);
    ENSURE(c->overrides && strcmp(c->overrides, "/RBODY/1:Mass=1.4837; /inter/type6/1:fric=0.3719") == 0);
    rc_model *m = NULL;
    ENSURE(rc_model_compile(c, &m, &e) == RC_OK);
    if (m) {
        ENSURE(m->nbody >= 1 && m->body_mass[0] == 1.4837);
        ENSURE(m->ninter == 1 && m->inter_fr[0].fric == 0.3719);
        ENSURE(m->overrides && strcmp(m->overrides, c->overrides) == 0);
    }
    rc_model_free(m);
    rc_case_free(c);
    /* without overrides: the deck's values, no list */
    c = load_set(DEMO, &e, (const char *)NULL);
    ENSURE(c && c->rbody[0].mass == 1.0 && c->type6[0].fric == 0.0 && c->overrides == NULL);
    rc_case_free(c);
}

/* FIELD[k]: the k-th occurrence of a repeated field (a /FUNCT point); an
 * empty value is a blank field (its default); a card without an id. */
static void test_override_index_blank_noid(void)
{
    rc_error e;
    rc_case *c = load_set(DEMO, &e, "/FUNCT/1:Y[2]=2.25e6", "/FUNCT/1:x[1]=-0.5", "/INTER/TYPE6/1:Tstop=",
                          "/RUN:Tend=0.0371", (const char *)NULL);
    ENSURE(c != NULL);
    if (!c) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    ENSURE(c->nfunct == 1 && c->funct[0].npts == 2);
    if (c->nfunct == 1 && c->funct[0].npts == 2) {
        ENSURE(c->funct[0].y[0] == 0 && c->funct[0].y[1] == 2.25e6);
        ENSURE(c->funct[0].x[0] == -0.5 && c->funct[0].x[1] == 1);
    }
    ENSURE(c->type6[0].tstop == 1e30); /* Radioss default of a blank Tstop */
    ENSURE(c->run.tend == 0.0371);
    rc_case_free(c);
}

/* The value is in the card's units, converted to SI as the deck's: a deck
 * in g, mm, ms. */
static void test_override_units(void)
{
    const char *p = tu_tmp_write("ovr_gmmms.rad",
                                 "/BEGIN\n"
                                 "grams, millimetres, milliseconds\n"
                                 "      2022         0\n"
                                 "                   g                  mm                  ms\n"
                                 "                   g                  mm                  ms\n"
                                 "/NODE\n"
                                 "         1                 0.0                 0.0               150.0\n"
                                 "/RBODY/1\n"
                                 "ball\n"
                                 "         1         0         0         0              1000.0         0\n"
                                 "           1000000.0           1000000.0           1000000.0\n"
                                 "                 0.0                 0.0                 0.0\n"
                                 "/INTER/TYPE6/1\n"
                                 "t6\n"
                                 "         2         3\n"
                                 "                   0                 0.3                   0                   0                   0\n"
                                 "                   0         0         0         0         0                   0                   0\n"
                                 "         1         0                   1                   1         0\n"
                                 "         0                          1000                   0\n"
                                 "                 2.0         0         0                   0\n"
                                 "/RUN\n"
                                 "              1000.0                 1.0\n");
    rc_error e;
    /* 1483.7 g = 1.4837 kg; Gap 2.5 mm; Stiff 3710 g/ms^2 = 3.71e6 N/m;
     * Tend 371 ms; Fric dimensionless */
    rc_case *c = load_set(p, &e, "/RBODY/1:Mass=1483.7", "/INTER/TYPE6/1:Gap=2.5", "/INTER/TYPE6/1:Stiff=3710",
                          "/INTER/TYPE6/1:Fric=0.25", "/RUN:Tend=371", (const char *)NULL);
    ENSURE(c != NULL);
    if (!c) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    ENSURE_NEAR(c->rbody[0].mass, 1.4837, 1e-14, 0);
    ENSURE_NEAR(c->type6[0].gap, 2.5e-3, 1e-14, 0);
    ENSURE_NEAR(c->type6[0].stiff, 3.71e6, 1e-14, 0);
    ENSURE(c->type6[0].fric == 0.25);
    ENSURE_NEAR(c->run.tend, 0.371, 1e-14, 0);
    ENSURE_NEAR(c->type6[0].visc, 2.0, 1e-14, 0); /* not set: the deck's, converted */
    rc_case_free(c);
    /* the value is checked after its conversion too: 1 g/ms^2 = 1e3 N/m,
     * so 1e306 g/ms^2 overflows */
    ENSURE(fails_with(p, "/INTER/TYPE6/1:Stiff=1e306", NULL,
                      "--set /INTER/TYPE6/1:Stiff=1e306: card /INTER/TYPE6/1, field Stiff: the value overflows when "
                      "converted to SI, got \"1e306\"",
                      1));
}

/* A value the field refuses: the deck's message, naming the argument. */
static void test_override_bad_value(void)
{
    ENSURE(fails_with(DEMO, "/INTER/TYPE6/1:Fric=abc", NULL,
                      "--set /INTER/TYPE6/1:Fric=abc: card /INTER/TYPE6/1, field Fric: expected a finite real number, "
                      "got \"abc\"",
                      1));
    ENSURE(fails_with(DEMO, "/RBODY/1:Mass=-0.5", NULL,
                      "--set /RBODY/1:Mass=-0.5: card /RBODY/1, field Mass: expected a non-negative real number, got "
                      "\"-0.5\"",
                      1));
    ENSURE(fails_with(DEMO, "/INTER/TYPE6/1:IRS=9", NULL,
                      "--set /INTER/TYPE6/1:IRS=9: card /INTER/TYPE6/1, field IRS: expected an integer in {0, 1, 2}, "
                      "got \"9\"",
                      1));
    ENSURE(fails_with(DEMO, "/RBODY/1:Ispher=1.5", NULL,
                      "--set /RBODY/1:Ispher=1.5: card /RBODY/1, field Ispher: expected an integer", 0));
}

/* A card the deck does not have; a field the card does not have (with a
 * "did you mean" and the card's fields). */
static void test_override_unknown_card_field(void)
{
    ENSURE(fails_with(DEMO, "/RBODY/7:Mass=2", NULL, "--set /RBODY/7:Mass=2: no card /RBODY/7 in the deck", 1));
    ENSURE(fails_with(DEMO, "/INTER/TYPE7/1:Fric=0.1", NULL,
                      "--set /INTER/TYPE7/1:Fric=0.1: no card /INTER/TYPE7/1 in the deck", 1));
    ENSURE(fails_with(DEMO, "/RBODY/1:Mas=2", NULL,
                      "--set /RBODY/1:Mas=2: card /RBODY/1: no numeric field Mas: did you mean Mass? (the card's "
                      "numeric fields: node_ID, sens_ID, Skew_ID, Ispher, Mass, grnd_ID, Ikrem, ICoG, surf_ID, Jxx, "
                      "Jyy, Jzz, Jxy, Jyz, Jxz)",
                      1));
    ENSURE(fails_with(DEMO, "/RBODY/1:Density=2", NULL,
                      "--set /RBODY/1:Density=2: card /RBODY/1: no numeric field Density (the card's numeric fields: "
                      "node_ID,",
                      0));
    /* a card that appears twice (no id): the address names no one card */
    const char *p = tu_tmp_write("ovr_twonode.rad", "/NODE\n         1                   0                   0"
                                                    "                   0\n/NODE\n         2                   0"
                                                    "                   0                   1\n/RUN\n1.0,0.01\n");
    ENSURE(fails_with(p, "/NODE:X[1]=1", NULL, "--set /NODE:X[1]=1: 2 cards /NODE in the deck", 0));
}

/* Text fields, repeated fields without their occurrence, unused columns
 * and fields on lines the deck's card lacks are refused. */
static void test_override_refused_fields(void)
{
    ENSURE(fails_with(DEMO, "/GRAV/1:DIR=1", NULL,
                      "--set /GRAV/1:DIR=1: card /GRAV/1, field DIR: a text field: --set sets numeric fields only "
                      "(integers and reals)",
                      1));
    ENSURE(fails_with(DEMO, "/FUNCT/1:Y=3", NULL,
                      "--set /FUNCT/1:Y=3: card /FUNCT/1, field Y: occurs 2 times in the card: write Y[k], k = 1..2, "
                      "for the k-th in reading order",
                      1));
    ENSURE(fails_with(DEMO, "/FUNCT/1:Y[3]=3", NULL,
                      "--set /FUNCT/1:Y[3]=3: card /FUNCT/1, field Y: occurs 2 times in the card: no occurrence 3", 1));
    ENSURE(fails_with(DEMO, "/RBODY/1:blank=3", NULL, "--set /RBODY/1:blank=3: card /RBODY/1: no numeric field blank",
                      0));
    /* /IMPVEL line 2 is optional: its fields are not on the deck's lines */
    const char *p = tu_tmp_write("ovr_impvel.rad", "/FUNCT/1\nf\n0,1\n1,1\n/NODE\n1,0,0,0\n/RBODY/1\nb\n1,0,0,0,1\n1,1,1\n\n/GRNOD/NODE/1\ng\n1\n"
                                                   "/IMPVEL/1\nv\n1,X,0,0,1,0,0\n/RUN\n1.0,0.01\n");
    ENSURE(fails_with(p, "/IMPVEL/1:Tstop=0.5", NULL,
                      "--set /IMPVEL/1:Tstop=0.5: card /IMPVEL/1, field Tstop: not on a line of the deck's card", 0));
}

/* A field set twice (the same name in another case, or FIELD and FIELD[1]
 * of a field the card has once). */
static void test_override_duplicate(void)
{
    ENSURE(fails_with(DEMO, "/RBODY/1:Mass=2", "/rbody/1:MASS=3",
                      "--set /rbody/1:MASS=3: card /RBODY/1, field MASS: set twice (also by --set /RBODY/1:Mass=2)", 1));
    ENSURE(fails_with(DEMO, "/RBODY/1:Mass=2", "/RBODY/1:Mass[1]=3",
                      "--set /RBODY/1:Mass[1]=3: card /RBODY/1, field Mass: set twice (also by --set /RBODY/1:Mass=2)",
                      1));
}

/* Malformed arguments, and the NULL contract of rc_case_load_set. */
static void test_override_syntax_and_contract(void)
{
    ENSURE(fails_with(DEMO, "Mass=2", NULL, "--set Mass=2: expected /KEYWORD[/SUBTYPE]/ID:FIELD=VALUE", 0));
    ENSURE(fails_with(DEMO, "/RBODY/1:Mass", NULL, "--set /RBODY/1:Mass: expected /KEYWORD", 0));
    ENSURE(fails_with(DEMO, "RBODY/1:Mass=2", NULL, "--set RBODY/1:Mass=2: the card must start with '/'", 0));
    ENSURE(fails_with(DEMO, "/RBODY/1:=2", NULL, "--set /RBODY/1:=2: no field name", 0));
    ENSURE(fails_with(DEMO, "/RBODY/1:Mass[0]=2", NULL, "--set /RBODY/1:Mass[0]=2: expected FIELD[k] with k a positive",
                      0));
    ENSURE(fails_with(DEMO, "/RBODY/1/2:Mass=2", NULL, "--set /RBODY/1/2:Mass=2: the card /RBODY/1/2 has two numbers",
                      0));
    ENSURE(fails_with(DEMO, "/RBODY//1:Mass=2", NULL, "--set /RBODY//1:Mass=2: malformed card /RBODY//1: empty keyword",
                      0));
    /* the pointers */
    rc_error e;
    rc_case *c = (rc_case *)1;
    const char *one[1] = {NULL};
    ENSURE(rc_case_load_set(DEMO, NULL, 1, &c, &e) == RC_EINPUT && c == NULL && strstr(e.msg, "set is NULL"));
    c = (rc_case *)1;
    ENSURE(rc_case_load_set(DEMO, one, 1, &c, &e) == RC_EINPUT && c == NULL && strstr(e.msg, "set[0] is NULL"));
    c = (rc_case *)1;
    ENSURE(rc_case_load_set(DEMO, one, -1, &c, &e) == RC_EINPUT && c == NULL && strstr(e.msg, "nset is negative"));
    ENSURE(rc_case_load_set(DEMO, NULL, 0, &c, &e) == RC_OK && c != NULL && c->overrides == NULL);
    rc_case_free(c);
}

/* A deck error and an override error are reported together; the error of
 * a card does not also blame the override on that card. */
static void test_override_with_deck_errors(void)
{
    const char *p = tu_tmp_write("ovr_bad.rad", "/NODE\n1,0,0,0\n/RBODY/1\nb\n"
                                                "1,0,0,0,abc\n1,1,1\n\n/RUN\n1.0,0.01\n");
    rc_error e;
    rc_case *c = load_set(p, &e, "/RBODY/1:Jxx=2", "/RUN:Tend=x", (const char *)NULL);
    ENSURE(c == NULL && e.code == RC_EINPUT);
    ENSURE(strstr(e.msg, "ovr_bad.rad:5: card /RBODY/1, field Mass: expected a finite real number, got \"abc\""));
    ENSURE(strstr(e.msg, "--set /RUN:Tend=x: card /RUN, field Tend: expected a finite real number, got \"x\""));
    ENSURE(strstr(e.msg, "2 input errors"));
    ENSURE(!strstr(e.msg, "Jxx"));
}

void suite_override(void);
void suite_override(void)
{
    RUN_TEST(test_override_changes_model);
    RUN_TEST(test_override_index_blank_noid);
    RUN_TEST(test_override_units);
    RUN_TEST(test_override_bad_value);
    RUN_TEST(test_override_unknown_card_field);
    RUN_TEST(test_override_refused_fields);
    RUN_TEST(test_override_duplicate);
    RUN_TEST(test_override_syntax_and_contract);
    RUN_TEST(test_override_with_deck_errors);
    tu_tmp_cleanup();
}
