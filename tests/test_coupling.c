/*
 * Coupling tests (docs/theory.md 8): the cards and their input errors, the compiled
 * model, the spring forms against each other and against the integral of
 * the stiffness table, the catenary solver (equations of docs/theory.md 8 in their
 * (c, u1, u2) form, every regime, warm against cold starts, the
 * implicit-function derivatives against finite differences of the solver,
 * the vertical limit, a failure that is recoverable), and the whole
 * Jacobian of a model with every coupling kind against central finite
 * differences of the right-hand side.
 *
 * Decks are written from strings into a private temporary directory
 * (removed at the end of the suite), in comma format except where the
 * fixed columns are under test.
 */
#include "harness.h"
#include "case/case.h"
#include "case/case_coupling.h"
#include "case/case_mesh.h"
#include "model/coupling.h"
#include "base/error.h"
#include "model/model.h"

#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "engine/assembly/assembly.h"

/* ---- decks in a temporary directory -------------------------------------- */
static char tdir[64];
static int ndeck;

/* Write `text` as a new deck file; returns its path (static buffer). */
static const char *deck(const char *text)
{
    static char path[128];
    if (!tdir[0]) {
        snprintf(tdir, sizeof tdir, "/tmp/rc_cpl_test_XXXXXX");
        if (!mkdtemp(tdir)) { perror("mkdtemp"); exit(1); }
    }
    snprintf(path, sizeof path, "%s/deck%03d.rad", tdir, ndeck++);
    FILE *f = fopen(path, "w");
    if (!f || fputs(text, f) < 0 || fclose(f) != 0) { perror(path); exit(1); }
    return path;
}

static void cleanup(void)
{
    char path[128];
    for (int k = 0; k < ndeck; k++) {
        snprintf(path, sizeof path, "%s/deck%03d.rad", tdir, k);
        remove(path);
    }
    if (tdir[0]) rmdir(tdir);
    tdir[0] = '\0';
    ndeck = 0;
}

/* Load (and compile when `compile`) a deck; expect RC_EINPUT at `line` of
 * the deck with every needle in the message (NULL-terminated). */
static int expect_error(const char *text, int compile, int line, ...)
{
    const char *path = deck(text);
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    rc_error_clear(&e);
    rc_status st = rc_case_load(path, &c, &e);
    if (compile && st == RC_OK) st = rc_model_compile(c, &m, &e);
    int bad = st != RC_EINPUT;
    char where[160];
    snprintf(where, sizeof where, "%s:%d:", path, line);
    if (line > 0 && !strstr(e.msg, where)) bad++;
    va_list ap;
    va_start(ap, line);
    for (const char *s; (s = va_arg(ap, const char *));)
        if (!strstr(e.msg, s)) {
            fprintf(stderr, "  missing \"%s\"\n", s);
            bad++;
        }
    va_end(ap);
    if (bad) fprintf(stderr, "  status %d, expected %d at %s; message: %s\n", st, RC_EINPUT, where, e.msg);
    rc_model_free(m);
    rc_case_free(c);
    return bad;
}
#define EXPECT_ERROR(text, compile, line, ...) \
    ENSURE(expect_error((text), (compile), (line), __VA_ARGS__, (const char *)NULL) == 0)

static rc_model *compile_deck(const char *text)
{
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    rc_error_clear(&e);
    if (rc_case_load(deck(text), &c, &e) == RC_OK) rc_model_compile(c, &m, &e);
    if (!m) fprintf(stderr, "  unexpected error: %s\n", e.msg);
    rc_case_free(c);
    return m;
}

/* ---- the model used by most tests ------------------------------------------ */
/* Two free bodies (full inertia), a fixed body, gravity; springs of every
 * form (form 4 with and without the reference force), catenaries slack,
 * taut, body-body, body-space and body-fixed body. */
static const char model_deck[] =
    "/NODE\n"
    "1, 0.31, -0.17, 0.23\n"
    "2, 1.41, 0.27, -0.12\n"
    "3, 3.0, 0.0, 1.0\n"
    "/RBODY/1\nbody one\n1,,,,1.3\n0.021,0.017,0.029\n0.0013,-0.0022,0.0007\n"
    "/RBODY/2\nbody two\n2,,,,0.7\n0.011,0.013,0.009\n0,0,0\n"
    "/RBODY/3\nfixed body\n3,,,,2.0\n0.1,0.1,0.1\n0,0,0\n"
    "/GRNOD/NODE/1\nfixed\n3\n"
    "/BCS/1\nfix\n111 111,0,1\n"
    "/GRAV/1\ngravity\n0,Z,0,0,0,,1,-9.81\n"
    "/FUNCT/5\nforce f_e(x)\n0,-40\n0.5,-9\n1.0,0\n1.6,23\n2.5,90\n"
    "/FUNCT/6\nstiffness k(x)\n0,10\n1,35\n2,20\n3,80\n"
    "/COUPLING/SPRING/11\nconstant\n1,0,1,0\n0.35,-0.12,0.27\n-0.9,0.4,1.1\n1.21,3.7\n143.0\n"
    "/COUPLING/SPRING/12\npolynomial\n1,2,2,0\n0.29,-0.2,0.2\n1.45,0.31,-0.1\n,2.9\n97.0,-31.0,410.0\n"
    "/COUPLING/SPRING/13\nforce table\n2,0,3,5\n1.38,0.22,-0.15\n2.2,-0.7,0.9\n,1.3\n"
    "/COUPLING/SPRING/14\nstiffness table\n1,2,4,6\n0.33,-0.15,0.21\n1.4,0.29,-0.09\n0.9,0.7\n"
    "/COUPLING/SPRING/15\nstiffness table, reference\n2,3,4,6\n1.39,0.25,-0.11\n3.05,0.02,1.01\n0.1,0.4\n,,\n17.0,1.9\n"
    "/COUPLING/CATENARY/21\nslack to space\n0,1\n-2.0,0.3,1.0\n0.3,-0.16,0.25\n1.7,3.4,2.0e4\n"
    "/COUPLING/CATENARY/22\ntaut body-body\n1,2\n0.32,-0.18,0.2\n1.43,0.25,-0.1\n0.9,1.2,3.0e3\n"
    "/COUPLING/CATENARY/23\nslack to fixed body\n2,3\n1.42,0.26,-0.13\n2.97,0.05,0.97\n0.5,2.3,5.0e4\n"
    "/RUN\n0.5,0.01\n";

/* ---- cards ------------------------------------------------------------------ */
static void test_coupling_cards_read(void)
{
    /* one card in fixed columns, the rest in comma format */
    static const char text[] =
        "/NODE\n1, 0, 0, 0\n2, 1, 0, 0\n"
        "/RBODY/1\nb\n1,,,,1\n1,1,1\n0,0,0\n/RBODY/2\nb\n2,,,,1\n1,1,1\n0,0,0\n"
        "/FUNCT/9\nk\n0,1\n1,2\n"
        "/COUPLING/SPRING/4\nfixed columns\n"
        "         1         2         4         9\n"
        "              0.0125                -0.5                 1.5\n"
        "                1.25                 0.5                   2\n"
        "                 1.1                 2.5\n"
        "\n"
        "                  -3                 0.9\n"
        "/COUPLING/CATENARY/5\nline\n0,2\n0,0,3\n1,0,0\n0.25,4.5,1.5e5\n"
        "/COUPLING/SPRING/6\nblank x0\n1,0,,\n0,0,0\n0,0,-2\n,\n"
        "/RUN\n1\n";
    rc_case *c = NULL;
    rc_error e;
    ENSURE(rc_case_load(deck(text), &c, &e) == RC_OK);
    if (!c) return;
    ENSURE(c->ncoupling == 3);
    if (c->ncoupling == 3) {
        const rc_case_coupling *s = &c->coupling[0], *k = &c->coupling[1], *d = &c->coupling[2];
        ENSURE(s->id == 4 && s->kind == RC_CASE_CPL_SPRING && strcmp(s->title, "fixed columns") == 0);
        ENSURE(s->rbody[0] == 1 && s->rbody[1] == 2 && s->iform == 4 && s->fct_id == 9);
        ENSURE(s->p[0][0] == 0.0125 && s->p[0][1] == -0.5 && s->p[0][2] == 1.5);
        ENSURE(s->p[1][0] == 1.25 && s->p[1][1] == 0.5 && s->p[1][2] == 2);
        ENSURE(s->x0 == 1.1 && s->x0_given && s->kd == 2.5 && s->a == 0 && s->b == 0 && s->c == 0);
        ENSURE(s->fr == -3 && s->xr == 0.9 && s->ref_given);
        ENSURE(k->id == 5 && k->kind == RC_CASE_CPL_CATENARY && k->rbody[0] == 0 && k->rbody[1] == 2);
        ENSURE(k->lambda0 == 0.25 && k->leq == 4.5 && k->d == 1.5e5 && k->p[0][2] == 3);
        ENSURE(d->iform == 1 && !d->x0_given && d->kd == 0 && d->a == 0 && !d->ref_given);
    }
    rc_case_free(c);
}

static void test_coupling_card_errors(void)
{
    /* a valid prefix: two bodies, gravity, a function; the card under test
     * starts at line 15 */
#define PRE "/NODE\n1,0,0,0\n2,1,0,0\n/RBODY/1\nb\n1,,,,1\n1,1,1\n0,0,0\n/RUN\n1\n/FUNCT/9\nk\n0,1\n1,2\n"
    /* header */
    EXPECT_ERROR(PRE "/COUPLING/1\nt\n", 0, 15, "card /COUPLING/1", "missing subtype",
                 "/COUPLING/SPRING", "/COUPLING/CATENARY");
    EXPECT_ERROR(PRE "/COUPLING/ROPE/1\nt\n", 0, 15, "/COUPLING/ROPE", "not supported yet");
    EXPECT_ERROR(PRE "/COUPLING/SPRING\nt\n1,0\n0,0,0\n1,0,0\n,\n", 0, 15, "field cpl_ID",
                 "expected a positive integer id");
    EXPECT_ERROR(PRE "/COUPLING/SPRING/3/2\nt\n1,0\n0,0,0\n1,0,0\n,\n", 0, 15, "field unit_ID",
                 "no /UNIT/2");
    /* lines */
    EXPECT_ERROR(PRE "/COUPLING/SPRING/3\nt\n1,0\n0,0,0\n1,0,0\n", 0, 15, "card /COUPLING/SPRING/3",
                 "expected", "X0 Kd");
    EXPECT_ERROR(PRE "/COUPLING/CATENARY/3\nt\n1,0\n0,0,0\n1,0,0\n1,1,1\n1\n", 0, 21,
                 "card /COUPLING/CATENARY/3", "unexpected");
    /* fields */
    EXPECT_ERROR(PRE "/COUPLING/SPRING/3\nt\n1,0,5\n0,0,0\n1,0,0\n,\n", 0, 17, "field Iform",
                 "expected an integer in {1, 2, 3, 4}, got \"5\"");
    EXPECT_ERROR(PRE "/COUPLING/SPRING/3\nt\n1,0,3\n0,0,0\n1,0,0\n,\n", 0, 17, "field fct_ID",
                 "expected the id of a /FUNCT", "Iform = 3");
    EXPECT_ERROR(PRE "/COUPLING/SPRING/3\nt\n0,0\n0,0,0\n1,0,0\n,\n", 0, 17, "field rbody_ID1 rbody_ID2",
                 "at least one rigid body");
    EXPECT_ERROR(PRE "/COUPLING/SPRING/3\nt\n1,1\n0,0,0\n1,0,0\n,\n", 0, 17, "field rbody_ID2",
                 "a body other than rbody_ID1 = 1");
    EXPECT_ERROR(PRE "/COUPLING/SPRING/3\nt\n-1,0\n0,0,0\n1,0,0\n,\n", 0, 17, "field rbody_ID1",
                 "non-negative integer");
    EXPECT_ERROR(PRE "/COUPLING/SPRING/3\nt\n1,0\n0.5,0,1\n0.5,0,1\n,\n", 0, 19, "field X2 Y2 Z2",
                 "different from point 1");
    EXPECT_ERROR(PRE "/COUPLING/SPRING/3\nt\n1,0\n0,0,0\nx,0,0\n,\n", 0, 19, "field X2",
                 "expected a finite real number, got \"x\"");
    EXPECT_ERROR(PRE "/COUPLING/SPRING/3\nt\n1,0\n0,0,0\n1,0,0\n-1,\n", 0, 20, "field X0",
                 "non-negative real number, got \"-1\"");
    EXPECT_ERROR(PRE "/COUPLING/SPRING/3\nt\n1,0\n0,0,0\n1,0,0\n,-2\n", 0, 20, "field Kd",
                 "non-negative real number");
    EXPECT_ERROR(PRE "/COUPLING/SPRING/3\nt\n1,0\n0,0,0\n1,0,0\n,\n-100\n", 0, 21, "field A",
                 "non-negative stiffness k [N/m] for Iform = 1");
    EXPECT_ERROR(PRE "/COUPLING/SPRING/3\nt\n1,0,2\n0,0,0\n1,0,0\n,\n1,2,3\n4,0.5\n", 0, 22, "field X_r",
                 "belongs to Iform = 4");
    EXPECT_ERROR(PRE "/COUPLING/SPRING/3\nt\n1,0,4,9\n0,0,0\n1,0,0\n,\n\n4\n", 0, 22, "field X_r",
                 "expected the reference distance X_r", "got blank");
    EXPECT_ERROR(PRE "/COUPLING/CATENARY/3\nt\n1,0\n0,0,0\n1,0,0\n0,1,1\n", 0, 20, "field Lambda0",
                 "positive real number");
    EXPECT_ERROR(PRE "/COUPLING/CATENARY/3\nt\n1,0\n0,0,0\n1,0,0\n1,-1,1\n", 0, 20, "field L_eq",
                 "positive real number");
    EXPECT_ERROR(PRE "/COUPLING/CATENARY/3\nt\n1,0\n0,0,0\n1,0,0\n1,1\n", 0, 20, "field D",
                 "positive real number, got blank");
    /* duplicate ids across both kinds */
    EXPECT_ERROR(PRE "/COUPLING/SPRING/3\nt\n1,0\n0,0,0\n1,0,0\n,\n/COUPLING/CATENARY/3\nt\n1,0\n0,0,0\n1,0,0\n1,1,1\n",
                 0, 21, "field cpl_ID", "duplicate id 3");
    /* references and gravity, found by the compiler */
    EXPECT_ERROR(PRE "/COUPLING/SPRING/3\nt\n1,7\n0,0,0\n1,0,0\n,\n", 1, 17, "card /COUPLING/SPRING/3",
                 "field rbody_ID2", "got 7 (no such body)");
    EXPECT_ERROR(PRE "/COUPLING/SPRING/3\nt\n1,0,3,8\n0,0,0\n1,0,0\n,\n", 1, 17, "field fct_ID",
                 "got 8 (no such function)");
    EXPECT_ERROR(PRE "/COUPLING/CATENARY/3\nt\n1,0\n0,0,0\n1,0,0\n1,1,1\n", 1, 15, "card /COUPLING/CATENARY/3",
                 "hangs in gravity", "grnod_ID 0");
    EXPECT_ERROR(PRE "/GRNOD/NODE/1\ng\n1\n/GRAV/1\ng\n0,Z,0,0,1,,1,-9.81\n"
                     "/COUPLING/CATENARY/3\nt\n1,0\n0,0,0\n1,0,0\n1,1,1\n",
                 1, 21, "card /COUPLING/CATENARY/3", "hangs in gravity");
#undef PRE
}

/* ---- compiled model ---------------------------------------------------------- */
static void test_coupling_compile_model(void)
{
    rc_model *m = compile_deck(model_deck);
    if (!m) return;
    const rc_couplings *p = m->cpl;
    ENSURE(p->n == 8);
    /* energy states follow everything else, two per coupling */
    for (int k = 0; k < p->n; k++) ENSURE(p->eadr[k] == 2 * RC_NB + RC_CE * k);
    ENSURE(m->ny == 2 * RC_NB + RC_CE * p->n);
    /* attachment points in the body frames; space and fixed bodies */
    ENSURE(p->b1[0] == 0 && p->b2[0] == -1);
    ENSURE_NEAR(p->s1[0], 0.35 - 0.31, 0, 1e-15);
    ENSURE_NEAR(p->s2[2], 1.1, 0, 0);
    ENSURE(p->b1[4] == 1 && p->b2[4] == 2 && m->body_yadr[2] < 0);
    ENSURE_NEAR(p->s2[3 * 4], 3.05 - 3.0, 0, 1e-15);
    /* blank x0: the initial distance; form 4 reference */
    const double d12 = sqrt(pow(1.45 - 0.29, 2) + pow(0.31 + 0.2, 2) + pow(-0.1 - 0.2, 2));
    ENSURE_NEAR(p->x0[1], d12, 1e-15, 0);
    ENSURE(p->form[3] == RC_KEFF_STIFF && p->fref[3] == 0 && p->xref[3] == 0.9);
    ENSURE(p->fref[4] == 17.0 && p->xref[4] == 1.9);
    ENSURE(p->kind[5] == RC_CPL_CATENARY && p->ea[5] == 2.0e4 * 3.4 && p->lambda0[5] == 1.7);
    ENSURE(p->grav[2] == -9.81 && p->grav[0] == 0);
    ENSURE(strcmp(p->name[7], "/COUPLING/CATENARY/23") == 0);
    rc_model_free(m);
}

/* ---- /SPRING elements (/PROP/SPRING, TYPE4) ---------------------------------- */
/* Two bodies carried by nodes 1 and 2 (node 5 in body 1's group), node 9 in
 * no body; /SPRING elements of part 7 (/PROP/TYPE4/3, fixed columns) and of
 * part 8 (/PROP/SPRING/4, comma format, no mass); the same springs written
 * as /COUPLING/SPRING Iform 1 cards in the second deck. */
#define SPR_BODIES                                                                  \
    "/NODE\n1, 0.31, -0.17, 0.23\n2, 1.41, 0.27, -0.12\n5, 0.52, 0.11, 0.37\n"     \
    "9, 2.2, -0.4, 0.9\n"                                                          \
    "/GRNOD/NODE/4\nsecondary\n5\n"                                                \
    "/RBODY/1\nbody one\n1,,,,1.3,4\n0.021,0.017,0.029\n0.0013,-0.0022,0.0007\n"    \
    "/RBODY/2\nbody two\n2,,,,0.7\n0.011,0.013,0.009\n0,0,0\n"                     \
    "/RUN\n0.5,0.01\n"
static const char spring_elem_deck[] =
    SPR_BODIES
    "/PART/7\nsprings\n         3         0\n"
    "/PART/8\nmore springs\n4,0\n"
    "/PROP/TYPE4/3\nlinear\n"
    "#               Mass                                 sens_ID    Isflag     Ileng\n"
    "               0.046                                                           0\n"
    "#                  K                   C                   A                   B                   D\n"
    "               143.7                 3.1                 1.0                   0                 1.0\n"
    "#  fct_ID1         H   fct_ID2   fct_ID3   fct_ID4                          dmin                dmax\n"
    "         0         0         0         0         0                                                  \n"
    "#                  F                   E              Ascale              Hscale\n"
    "                 1.0                   0                 1.0                 1.0\n"
    "/SPRING/7\n"
    "        31         1         2\n"
    "        32         5         9                                                   0\n"
    "/PROP/SPRING/4\nno mass\n0\n97.25,0.0371\n"
    "/SPRING/8\n33,9,2\n";
static const char spring_card_deck[] =
    SPR_BODIES
    "/COUPLING/SPRING/31\n\n1,2,1,0\n0.31,-0.17,0.23\n1.41,0.27,-0.12\n,3.1\n143.7\n"
    "/COUPLING/SPRING/32\n\n1,0,1,0\n0.52,0.11,0.37\n2.2,-0.4,0.9\n,3.1\n143.7\n"
    "/COUPLING/SPRING/33\n\n0,2,1,0\n2.2,-0.4,0.9\n1.41,0.27,-0.12\n,0.0371\n97.25\n";

static void test_coupling_spring_element_read(void)
{
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    ENSURE(rc_case_load(deck(spring_elem_deck), &c, &e) == RC_OK);
    if (!c) { fprintf(stderr, "  %s\n", e.msg); return; }
    ENSURE(c->mesh && c->mesh->nspring == 3 && c->mesh->nprop == 2);
    if (c->mesh && c->mesh->nspring == 3 && c->mesh->nprop == 2) {
        const rc_case_spring *s = c->mesh->spring;
        ENSURE(s[0].id == 31 && s[0].part_id == 7 && s[0].nodes[0] == 1 && s[0].nodes[1] == 2);
        ENSURE(s[1].id == 32 && s[1].nodes[0] == 5 && s[1].nodes[1] == 9);
        ENSURE(s[2].id == 33 && s[2].part_id == 8 && s[2].nodes[0] == 9 && s[2].nodes[1] == 2);
        const rc_case_prop *q = c->mesh->prop;
        ENSURE(q[0].id == 3 && q[0].kind == RC_PROP_SPRING && q[0].sprtype == 4);
        ENSURE(q[0].mass == 0.046 && q[0].k == 143.7 && q[0].c == 3.1);
        ENSURE(q[1].id == 4 && q[1].mass == 0 && q[1].k == 97.25 && q[1].c == 0.0371);
    }
    /* the cards read, none ignored: no warning names them */
    for (int k = 0; k < c->nwarnings; k++) ENSURE(!strstr(c->warnings[k], "PROP"));
    rc_case_free(c);
}

/* The elements compile into the couplings that the equivalent
 * /COUPLING/SPRING cards give (ends, points, x0, k, k_d), and the spring
 * mass is lumped half on each node: body 1 gains 0.046 (its main node and
 * node 5, secondary), body 2 0.023. */
static void test_coupling_spring_element_matches_card(void)
{
    rc_model *a = compile_deck(spring_elem_deck), *b = compile_deck(spring_card_deck);
    if (!a || !b) { rc_model_free(a); rc_model_free(b); ENSURE(0); return; }
    const rc_couplings *p = a->cpl, *q = b->cpl;
    ENSURE(p->n == 3 && q->n == 3 && p->ncard == 3);
    for (int k = 0; k < 3 && p->n == 3 && q->n == 3; k++) {
        ENSURE(p->kind[k] == RC_CPL_SPRING && p->form[k] == RC_KEFF_CONST);
        ENSURE(p->b1[k] == q->b1[k] && p->b2[k] == q->b2[k]);
        ENSURE(p->id[k] == q->id[k] && strcmp(p->type[k], "SPRING_ELEMENT") == 0);
        ENSURE_NEAR(p->x0[k], q->x0[k], 1e-15, 0);
        ENSURE(p->kd[k] == q->kd[k] && p->coef[3 * k] == q->coef[3 * k]);
    }
    ENSURE(strcmp(p->name[0], "/SPRING/7 element 31") == 0);
    /* the points in the body frames: the bodies' centres moved with the
     * spring mass, so compare the global points (frame origin + s) */
    for (int k = 0; k < 3 && p->n == 3; k++) {
        const int ends[2] = {p->b1[k], p->b2[k]};
        const double *sa[2] = {p->s1 + 3 * k, p->s2 + 3 * k}, *sb[2] = {q->s1 + 3 * k, q->s2 + 3 * k};
        for (int j = 0; j < 2; j++)
            for (int i = 0; i < 3; i++) {
                const double oa = ends[j] >= 0 ? a->body_y0[RC_NB * ends[j] + i] : a->ground_y0[i];
                const double ob = ends[j] >= 0 ? b->body_y0[RC_NB * ends[j] + i] : b->ground_y0[i];
                ENSURE_NEAR(oa + sa[j][i], ob + sb[j][i], 0, 1e-14);
            }
    }
    ENSURE_NEAR(a->body_mass[0], b->body_mass[0] + 0.046, 1e-14, 0);
    ENSURE_NEAR(a->body_mass[1], b->body_mass[1] + 0.023, 1e-14, 0);
    rc_model_free(a);
    rc_model_free(b);
}

static void test_coupling_spring_element_errors(void)
{
#define SPRE SPR_BODIES "/PART/7\nsprings\n3\n"
    /* SPRE is 23 lines; the card under test starts at line 24 */
    const char *p4 = "/PROP/TYPE4/3\nt\n0\n10,1\n"; /* 4 lines */
    char text[4096];
    /* reader: element fields */
    snprintf(text, sizeof text, SPRE "%s/SPRING/7\n31,1,1\n", p4);
    EXPECT_ERROR(text, 0, 29, "card /SPRING/7", "field node_ID2", "other than node_ID1 = 1");
    snprintf(text, sizeof text, SPRE "%s/SPRING/7\n31,1,2,5\n", p4);
    EXPECT_ERROR(text, 0, 29, "field node_ID3", "not supported yet", "TYPE4");
    snprintf(text, sizeof text, SPRE "%s/SPRING/7\n31,1,2,,,,,4\n", p4);
    EXPECT_ERROR(text, 1, 29, "field Skew_ID", "TYPE8");
    snprintf(text, sizeof text, SPRE "%s/SPRING/7\n31,1,2\n/SPRING/7\n31,2,5\n", p4);
    EXPECT_ERROR(text, 0, 31, "sprg_ID", "31");
    /* reader: property fields */
    EXPECT_ERROR(SPRE "/PROP/TYPE4/3\nt\n0,,1\n10\n", 0, 26, "card /PROP/TYPE4/3", "field sens_ID",
                 "not supported yet");
    EXPECT_ERROR(SPRE "/PROP/TYPE4/3\nt\n0,,,,1\n10\n", 0, 26, "field Ileng", "not supported yet");
    EXPECT_ERROR(SPRE "/PROP/TYPE4/3\nt\n-1\n10\n", 0, 26, "field Mass", "non-negative");
    EXPECT_ERROR(SPRE "/PROP/TYPE4/3\nt\n0\n-10\n", 0, 27, "field K", "non-negative");
    EXPECT_ERROR(SPRE "/PROP/TYPE4/3\nt\n0\n10,1\n5\n", 0, 28, "field fct_ID1", "not supported yet",
                 "/COUPLING/SPRING");
    EXPECT_ERROR(SPRE "/PROP/TYPE4/3\nt\n0\n10,1\n0,,,,,,0.5\n", 0, 28, "field dmin", "rupture");
    EXPECT_ERROR(SPRE "/PROP/SPRING/3\nt\n0\n", 0, 24, "card /PROP/SPRING/3", "expected", "K C A B D");
    /* compiler: the property, the nodes, the bodies */
    EXPECT_ERROR(SPRE "/PROP/TYPE13/3\nt\n0\n", 0, 24, "card /PROP/TYPE13/3", "expected 19 data lines", "Ileng");
    EXPECT_ERROR(SPRE "/PROP/TYPE8/3\nt\n0\n", 0, 24, "card /PROP/TYPE8/3", "expected 19 data lines");
    snprintf(text, sizeof text, SPRE "/SPRING/7\n31,1,2\n");
    EXPECT_ERROR(text, 1, 23, "card /PART/7", "field prop_ID", "/PROP/SPRING");
    snprintf(text, sizeof text, SPRE "%s/SPRING/6\n31,1,2\n", p4);
    EXPECT_ERROR(text, 1, 29, "card /SPRING/6", "field part_ID", "no such part");
    snprintf(text, sizeof text, SPRE "%s/SPRING/7\n31,1,77\n", p4);
    EXPECT_ERROR(text, 1, 29, "card /SPRING/7", "field node_ID2", "no such node");
    /* a spring inside one body (node 5 is body 1's) never stretches: left
     * out, its mass still the body's; a bad law is reported all the same */
    snprintf(text, sizeof text, SPRE "/PROP/TYPE4/3\nt\n0.5\n10,1\n/SPRING/7\n31,1,5\n");
    rc_model *in = compile_deck(text);
    ENSURE(in && in->cpl->n == 0 && in->cpl->ncard == 0);
    if (in) ENSURE_NEAR(in->body_mass[0], 1.3 + 0.5, 1e-15, 0);
    rc_model_free(in);
    snprintf(text, sizeof text, SPRE "/PROP/TYPE12/3\nt\n0\n/SPRING/7\n31,1,5\n");
    EXPECT_ERROR(text, 1, 23, "card /PART/7", "field prop_ID", "TYPE13");
    snprintf(text, sizeof text, SPR_BODIES "/NODE\n11,0,0,0\n12,1,0,0\n/PART/7\nsprings\n3\n%s/SPRING/7\n31,11,12\n", p4);
    EXPECT_ERROR(text, 1, 32, "card /SPRING/7", "no /RBODY");
    /* a ground node (in no body, its translations held by /BCS), as Radioss
     * decks hold a spring's far end: the /BCS and the /GRAV of a group
     * holding it skip it; without the /BCS the /GRAV names it */
    snprintf(text, sizeof text,
             SPR_BODIES "/NODE\n11,0,0,-1\n/GRNOD/NODE/8\nground and body 1\n11,1\n/BCS/1\nground\n111 000,0,8\n"
                        "/GRAV/1\ng\n0,Z,0,0,8,,1,-9.81\n/PART/7\nsprings\n3\n%s/SPRING/7\n31,11,1\n", p4);
    rc_model *m = compile_deck(text);
    ENSURE(m && m->cpl->n == 1 && m->cpl->b1[0] == -1 && m->cpl->b2[0] == 0 && m->body_fixed[0] == 0);
    if (m) ENSURE(m->body_dofmask[0] == 1 && m->body_grav[2] == -9.81);
    rc_model_free(m);
    snprintf(text, sizeof text,
             SPR_BODIES "/NODE\n11,0,0,-1\n/GRNOD/NODE/8\nground and body 1\n11,1\n"
                        "/GRAV/1\ng\n0,Z,0,0,8,,1,-9.81\n/PART/7\nsprings\n3\n%s/SPRING/7\n31,11,1\n", p4);
    EXPECT_ERROR(text, 1, 25, "card /GRNOD/NODE/8", "node 11 belongs to no /RBODY", "/GRAV/1");
#undef SPRE
}

/* ---- spring laws ------------------------------------------------------------- */
/* Form 4's GSL cumulative integral and its runtime evaluation against the
 * exact trapezoid integral of the table (table.c), inside and outside the
 * table's range; f_e' = k. */
static void test_coupling_stiffness_integral(void)
{
    rc_model *m = compile_deck(model_deck);
    if (!m) return;
    const rc_couplings *p = m->cpl;
    const rc_table *t = &m->table[p->table[3]];
    double maxerr = 0;
    for (double x = -0.7; x < 4.2; x += 0.0373) {
        double f, df, k, dk;
        rc_cpl_stiff_force(p, t, 3, x, &f, &df);
        maxerr = fmax(maxerr, fabs(f - rc_table_integral(t, 0.9, x)));
        rc_table_eval(t, x, &k, &dk);
        ENSURE(df == k);
        rc_cpl_stiff_force(p, t, 4, x, &f, &df);
        maxerr = fmax(maxerr, fabs(f - 17.0 - rc_table_integral(t, 1.9, x)));
    }
    printf("    stiffness integral: max |GSL - trapezoid| = %.2e N\n", maxerr);
    ENSURE(maxerr < 1e-12);
    rc_model_free(m);
}

/* All forms give f = k_eff(x)(x - x0): the polynomial against the formula,
 * the tabulated force at and away from its zero (no 0/0 at x = x0). */
static void test_coupling_spring_forms(void)
{
    static const char text[] =
        "/NODE\n1, 1.3, 0, 0\n/RBODY/1\nb\n1,,,,2\n1,1,1\n0,0,0\n"
        "/FUNCT/5\nf_e\n0,-7\n1,0\n2,13\n"
        "/COUPLING/SPRING/1\np\n0,1,2\n0,0,0\n1.3,0,0\n1.0,0\n3,5,7\n"
        "/COUPLING/SPRING/2\nf\n0,1,3,5\n0,0,0\n1.3,0,0\n1.0,0\n"
        "/RUN\n1\n";
    rc_model *m = compile_deck(text);
    if (!m) return;
    rc_data *d = rc_data_new(m);
    double y[64], f[64];
    rc_initial_state(m, y);
    for (double x = 0.4; x < 2.6; x += 0.3) {
        y[0] = x - m->origin[0]; /* both springs along x from the origin (the model's coordinates) */
        rc_cpl_report r[2];
        for (int k = 0; k < 2; k++) ENSURE(rc_cpl_report_eval(m, d, k, 0, y, &r[k]) == 0);
        const double e = x - 1.0;
        ENSURE_NEAR(r[0].force, (3 + 5 * e + 7 * e * e) * e, 1e-14, 1e-14);
        ENSURE_NEAR(r[1].force, e < 0 ? 7 * e : 13 * e, 1e-14, 1e-14);
        ENSURE_NEAR(r[0].f1[0], r[0].force, 1e-15, 0);
        ENSURE_NEAR(r[0].f2[0], -r[0].force, 1e-15, 0);
    }
    /* at x = x0: zero force (to the rounding of the model's coordinates,
     * relative to the scene's centre), finite slope */
    y[0] = 1.0 - m->origin[0];
    ENSURE(rc_assemble_rhs(m, d, 0, y, f) == 0);
    ENSURE(fabs(f[7]) < 1e-13 && isfinite(f[7]));
    rc_data_free(d);
    rc_model_free(m);
}

/* ---- catenary solver ------------------------------------------------------------ */
/* A one-line coupling table for calling the solver directly. */
typedef struct {
    rc_couplings p;
    double leq, ea;
} one_line;

static void one_line_init(one_line *o, double leq, double ea)
{
    memset(o, 0, sizeof *o);
    o->leq = leq;
    o->ea = ea;
    o->p.n = 1;
    o->p.leq = &o->leq;
    o->p.ea = &o->ea;
}

/* Residual of the equations of docs/theory.md 8 in (c, u1, u2) for a solution (relative
 * to L_eq): x(u2) - x(u1) = X, y(u2) - y(u1) = Y, c = w L/(sinh u2 - sinh u1). */
static double spec_residual(const rc_cat_sol *s, double leq, double ea)
{
    const double c = s->H, u1 = asinh(s->V1 / c), u2 = asinh(s->V2 / c);
    const double a = c / s->w, b = c * a / ea;
    const double X = a * (u2 - u1) + b * (sinh(u2) - sinh(u1));
    const double Y = a * (cosh(u2) - cosh(u1)) + 0.5 * b * (sinh(u2) * sinh(u2) - sinh(u1) * sinh(u1));
    const double C = s->w * leq / (sinh(u2) - sinh(u1));
    return fmax(fabs(X - s->X), fmax(fabs(Y - s->Y), fabs(C - c) / c * leq)) / leq;
}

/* Spans covering the regimes: slack with the vertex inside, ends above or
 * below the vertex, nearly taut, taut and stretched, steep, soft. */
static const double spans[][4] = {
    /* X, Y, L_eq, EA/(w L) */
    {3.0, 0.4, 5.0, 2e3},   {3.0, -1.7, 5.0, 2e3},  {1.0, 4.6, 5.0, 2e3},   {2.0, -4.5, 5.0, 2e3},
    {4.98, 0.1, 5.0, 2e3},  {5.2, 0.3, 5.0, 2e3},   {3.0, 4.2, 5.0, 2e3},   {0.05, 3.0, 5.0, 2e3},
    {3.0, 0.4, 5.0, 0.8},   {6.0, -2.0, 5.0, 3.0},  {3.0, 0.4, 5.0, 1e9},   {0.3, -0.2, 5.0, 50.0},
};

static void test_coupling_catenary_solutions(void)
{
    void *ws = rc_cat_ws_new();
    ENSURE(ws != NULL);
    const double w = 13.7;
    double worst = 0;
    int maxit = 0;
    for (size_t i = 0; i < sizeof spans / sizeof spans[0]; i++) {
        one_line o;
        one_line_init(&o, spans[i][2], spans[i][3] * w * spans[i][2]);
        rc_cat_sol cold, warm;
        double start[2] = {NAN, NAN};
        ENSURE(rc_cat_solve(&o.p, 0, ws, start, spans[i][0], spans[i][1], w, &cold) == 0);
        worst = fmax(worst, spec_residual(&cold, o.leq, o.ea));
        /* vertical balance: the ends carry the weight */
        ENSURE_NEAR(cold.V2 - cold.V1, w * o.leq, 1e-14, 0);
        /* from the warm start of a neighbouring span (as between two
         * right-hand sides), then back */
        ENSURE(rc_cat_solve(&o.p, 0, ws, start, spans[i][0] * 1.0001, spans[i][1] + 1e-4, w, &warm) == 0);
        ENSURE(rc_cat_solve(&o.p, 0, ws, start, spans[i][0], spans[i][1], w, &warm) == 0);
        maxit = warm.iter > maxit ? warm.iter : maxit;
        /* the result does not depend on the start: the right-hand side
         * is a pure function of the state */
        ENSURE(warm.H == cold.H && warm.V1 == cold.V1 && warm.dH[0] == cold.dH[0]);
        worst = fmax(worst, spec_residual(&warm, o.leq, o.ea));
    }
    printf("    catenary: max residual of the (c, u1, u2) equations %.2e L_eq, warm start <= %d iterations\n",
           worst, maxit);
    ENSURE(worst < 1e-12);
    ENSURE(maxit <= 3);
    rc_cat_ws_free(ws);
}

/* Random spans over the extremes: EA from 1e-2 to 1e12 w L, span from 1e-6
 * to 3 L_eq, height within +-3 L_eq. Every one is solved, from a cold start
 * and from the warm start of a neighbouring span, with bit-identical
 * results, and the residual of the equations as solved is at the rounding
 * level of their terms (evaluated here plainly, with the cancellation the
 * solver's own forms avoid). */
static void test_coupling_catenary_random_spans(void)
{
    void *ws = rc_cat_ws_new();
    const double w = 9.81;
    uint64_t s = 0x2545f4914f6cdd1dULL;
    int solved = 0, same = 0, n = 4000;
    double worst = 0;
    for (int i = 0; i < n; i++) {
        double r[5];
        for (int j = 0; j < 5; j++) {
            s = s * 6364136223846793005ULL + 1442695040888963407ULL;
            r[j] = (double)(s >> 11) / 9007199254740992.0;
        }
        one_line o;
        const double L = 1.0 + 4.0 * r[0];
        one_line_init(&o, L, pow(10.0, -2.0 + 14.0 * r[1]) * w * L);
        const double X = L * pow(10.0, -6.0 + 6.5 * r[2]), Y = L * (-3.0 + 6.0 * r[3]);
        rc_cat_sol a, b;
        double st[2] = {NAN, NAN}, st2[2] = {NAN, NAN};
        if (rc_cat_solve(&o.p, 0, ws, st, X * 1.0003, Y + 3e-4 * L, w, &b) ||
            rc_cat_solve(&o.p, 0, ws, st, X, Y, w, &b) || rc_cat_solve(&o.p, 0, ws, st2, X, Y, w, &a))
            continue;
        solved++;
        same += a.H == b.H && a.V1 == b.V1;
        if (!a.vertical) {
            /* the two equations as solved, in the tensions */
            const double T1 = hypot(a.H, a.V1), T2 = hypot(a.H, a.V2);
            const double A2 = asinh(a.V2 / a.H), A1 = asinh(a.V1 / a.H);
            const double Xs = a.H * L / o.ea + a.H / w * (A2 - A1);
            const double Ys = L * (a.V1 + a.V2) * (1.0 / (T1 + T2) + 0.5 / o.ea);
            const double mx = L + a.H * L / o.ea + a.H / w * (fabs(A2) + fabs(A1));
            const double my = L + L * fabs(a.V1 + a.V2) * (1.0 / (T1 + T2) + 0.5 / o.ea);
            worst = fmax(worst, fmax(fabs(Xs - X) / mx, fabs(Ys - Y) / my));
        }
    }
    printf("    %d random spans: %d solved, %d warm == cold bit for bit, max relative residual %.1e\n", n, solved,
           same, worst);
    ENSURE(solved == n && same == n);
    ENSURE(worst < 1e-13);
    rc_cat_ws_free(ws);
}

/* d(H, V1)/d(X, Y) from the implicit-function theorem against central
 * differences of the solver. */
static void test_coupling_catenary_ift_matches_finite_differences(void)
{
    void *ws = rc_cat_ws_new();
    const double w = 9.3;
    double worst = 0;
    for (size_t i = 0; i < sizeof spans / sizeof spans[0]; i++) {
        one_line o;
        one_line_init(&o, spans[i][2], spans[i][3] * w * spans[i][2]);
        rc_cat_sol s, a, b;
        double start[2] = {NAN, NAN};
        const double X = spans[i][0], Y = spans[i][1];
        ENSURE(rc_cat_solve(&o.p, 0, ws, start, X, Y, w, &s) == 0);
        const double scale = fmax(fabs(s.H), fabs(s.V1)) / o.leq + fabs(s.dH[0]) + fabs(s.dV1[1]);
        for (int j = 0; j < 2; j++) {
            const double hs = 1e-6 * o.leq;
            ENSURE(rc_cat_solve(&o.p, 0, ws, start, X + (j == 0) * hs, Y + (j == 1) * hs, w, &a) == 0);
            ENSURE(rc_cat_solve(&o.p, 0, ws, start, X - (j == 0) * hs, Y - (j == 1) * hs, w, &b) == 0);
            const double dH = (a.H - b.H) / (2 * hs), dV = (a.V1 - b.V1) / (2 * hs);
            worst = fmax(worst, fmax(fabs(dH - s.dH[j]), fabs(dV - s.dV1[j])) / scale);
        }
    }
    printf("    catenary IFT: max scaled |d(H,V1)/d(X,Y) - FD| = %.2e\n", worst);
    ENSURE(worst < 1e-6);
    rc_cat_ws_free(ws);
}

/* Vertical limit: the closed form at X = 0 continues the general solution
 * (tensions and transverse stiffness H/X), on the three branches. */
static void test_coupling_catenary_vertical_limit(void)
{
    const double w = 7.1, L = 2.0, Ys[3] = {2.3, -2.2, 0.9};
    one_line o;
    one_line_init(&o, L, 40.0 * w * L);
    for (int i = 0; i < 3; i++) {
        rc_cat_sol v, g;
        double start[2] = {NAN, NAN};
        ENSURE(rc_cat_solve(&o.p, 0, NULL, start, 0.0, Ys[i], w, &v) == 0);
        ENSURE(v.vertical == 1 && v.H == 0);
        ENSURE(rc_cat_solve(&o.p, 0, NULL, start, 1e-7 * L, Ys[i], w, &g) == 0);
        ENSURE(g.vertical == 0);
        ENSURE_NEAR(g.V1, v.V1, 1e-5, 1e-9 * w * L);
        ENSURE_NEAR(g.dV1[1], v.dV1[1], 1e-5, 0);
        if (i < 2) ENSURE_NEAR(g.H / g.X, v.kappa, 1e-4, 0); /* taut: H = kappa X */
        else ENSURE(v.kappa == 0 && g.H / g.X < 0.1 * w);     /* folded: H ~ X / log(1/X) */
    }
    /* taut straight line: Y = L + (T1 + w L/2) L/EA with T1 = V1 */
    rc_cat_sol v;
    double start[2] = {NAN, NAN};
    rc_cat_solve(&o.p, 0, NULL, start, 0.0, 2.3, w, &v);
    ENSURE_NEAR(2.3, L + (v.V1 + 0.5 * w * L) * L / o.ea, 1e-14, 0);
}

/* Taut limit: as the line is pulled far beyond its length the tension
 * tends to the straight elastic line's, EA (chord/L_eq - 1), along the
 * chord (the weight is a relative correction of order w L/T). */
static void test_coupling_catenary_taut_limit(void)
{
    const double w = 2.0, L = 10.0, ea = 1e7;
    one_line o;
    one_line_init(&o, L, ea);
    rc_cat_sol s;
    double start[2] = {NAN, NAN};
    const double X = 10.5 * 0.8, Y = 10.5 * 0.6; /* chord 10.5 */
    ENSURE(rc_cat_solve(&o.p, 0, NULL, start, X, Y, w, &s) == 0);
    const double T = ea * (10.5 / L - 1.0), Tmid = hypot(s.H, 0.5 * (s.V1 + s.V2));
    ENSURE_NEAR(Tmid, T, 2 * w * L / T, 0);
    ENSURE_NEAR(s.H / (0.5 * (s.V1 + s.V2)), X / Y, 1e-5, 0);
}

/* A span the solver cannot take (non-finite) is a recoverable failure. */
static void test_coupling_catenary_failure_is_recoverable(void)
{
    one_line o;
    one_line_init(&o, 1.0, 1e3);
    rc_cat_sol s;
    double start[2] = {NAN, NAN};
    ENSURE(rc_cat_solve(&o.p, 0, NULL, start, NAN, 0.5, 9.81, &s) == 1);
    ENSURE(rc_cat_solve(&o.p, 0, NULL, start, 1.0, 0.5, 0.0, &s) == 1);
    /* in the right-hand side: status 1 and the coupling named */
    rc_model *m = compile_deck(model_deck);
    if (!m) return;
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double)), *f = calloc((size_t)m->ny, sizeof(double));
    rc_initial_state(m, y);
    ENSURE(rc_assemble_rhs(m, d, 0, y, f) == 0);
    y[0] = NAN;
    ENSURE(rc_assemble_rhs(m, d, 0, y, f) == 1);
    ENSURE(d->cpl->fail >= 0);
    free(y);
    free(f);
    rc_data_free(d);
    rc_model_free(m);
}

/* ---- whole Jacobian ---------------------------------------------------------- */
/* Bodies moved, turned (non-unit quaternions) and set moving. */
static void entropy_state(const rc_model *m, double *y)
{
    static const double s[26] = {0.3371, -0.1513, 0.2611, 0.93, 0.11, -0.27, 0.19, 0.31, -0.23, -1.17, 3.1, -2.3, 4.7,
                                 1.3913, 0.3107, -0.0913, 0.97, -0.05, 0.21, 0.08, -0.41, 0.17, 0.53, -1.9, 0.7, 2.2};
    rc_initial_state(m, y);
    for (int b = 0; b < 2; b++) memcpy(y + m->body_yadr[b], s + 13 * b, 13 * sizeof(double));
}

/* The analytic (complex-step) Jacobian of a deck's couplings at a random
 * state against central differences of the right-hand side. */
static void jacobian_vs_fd(const char *text, const char *what)
{
    rc_model *m = compile_deck(text);
    ENSURE(m != NULL);
    if (!m) return;
    rc_data *d = rc_data_new(m);
    const int n = m->ny;
    double *y = calloc((size_t)n, sizeof(double)), *f1 = calloc((size_t)n, sizeof(double));
    double *f2 = calloc((size_t)n, sizeof(double)), *val = calloc((size_t)m->nnz, sizeof(double));
    entropy_state(m, y);
    const double t = 0.0137;
    ENSURE(rc_assemble_jac(m, d, t, y, val) == 0);
    int bad = 0, outside = 0;
    double maxerr = 0;
    for (int col = 0; col < n; col++) {
        const double h = 1e-6 * fmax(fabs(y[col]), 1.0), keep = y[col];
        y[col] = keep + h;
        ENSURE(rc_assemble_rhs(m, d, t, y, f1) == 0);
        y[col] = keep - h;
        ENSURE(rc_assemble_rhs(m, d, t, y, f2) == 0);
        y[col] = keep;
        double scale = 1.0;
        for (int r = 0; r < n; r++) scale = fmax(scale, fabs((f1[r] - f2[r]) / (2 * h)));
        for (int r = 0; r < n; r++) {
            double fd = (f1[r] - f2[r]) / (2 * h), an = 0;
            int64_t k;
            for (k = m->jac_colptr[col]; k < m->jac_colptr[col + 1]; k++)
                if (m->jac_rowind[k] == r) break;
            if (k < m->jac_colptr[col + 1]) an = val[k];
            else if (fabs(fd) > 1e-9 * scale) {
                outside++;
                fprintf(stderr, "    outside the pattern: row %d, col %d, FD %.3e\n", r, col, fd);
            }
            const double er = fabs(an - fd) / scale;
            maxerr = fmax(maxerr, er);
            if (er > 1e-6) bad++;
        }
    }
    printf("    %s jacobian: %d states, %lld nonzeros, max scaled |J - FD| = %.2e\n", what, n, (long long)m->nnz,
           maxerr);
    ENSURE(bad == 0);
    ENSURE(outside == 0);
    free(y);
    free(f1);
    free(f2);
    free(val);
    rc_data_free(d);
    rc_model_free(m);
}

static void test_coupling_jacobian_matches_finite_differences(void) { jacobian_vs_fd(model_deck, "coupling"); }

/* /PROP/TYPE8 general springs: a body-to-body element of non-zero length in
 * a turned /SKEW/FIX (the property's), a body-to-ground one in the global
 * frame (the element's Skew_ID 0 and the property's overridden by 6, the
 * identity), all six stiffnesses and dampings non-zero. */
#define GENE_DECK                                                                                  \
    SPR_BODIES "/SKEW/FIX/5\nturned\n0,0,0\n0.48,-0.6,0.64\n0,0,1\n/SKEW/FIX/6\nglobal\n0,0,0\n0,1,0\n0,0,1\n" \
               "/PART/7\ngeneral springs\n3\n/PROP/TYPE8/3\nt\n0.02,0.001,5\n"                   \
               "130,1.1\n0\n1\n170,0.9\n0\n1\n210,1.7\n0\n1\n"                               \
               "3.1,0.013\n0\n1\n4.3,0.021\n0\n1\n2.7,0.017\n0\n1\n"                         \
               "/SPRING/7\n31,1,2\n32,9,1,,,,,6\n"

static void test_coupling_gene_read(void)
{
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    ENSURE(rc_case_load(deck(GENE_DECK), &c, &e) == RC_OK);
    if (!c) { fprintf(stderr, "  %s\n", e.msg); return; }
    const rc_case_prop *q = c->mesh->prop;
    ENSURE(c->mesh->nprop == 1 && q->sprtype == 8 && q->mass == 0.02 && q->inertia == 0.001 && q->skew_id == 5);
    ENSURE(q->k6[0] == 130 && q->c6[0] == 1.1 && q->k6[2] == 210 && q->k6[5] == 2.7 && q->c6[5] == 0.017);
    ENSURE(c->mesh->nspring == 2 && c->mesh->spring[0].skew_id == 0 && c->mesh->spring[1].skew_id == 6);
    rc_case_free(c);
    rc_model *m = compile_deck(GENE_DECK);
    ENSURE(m && m->cpl->n == 2);
    if (m && m->cpl->n == 2) {
        const rc_couplings *p = m->cpl;
        ENSURE(p->form[0] == RC_KEFF_GENE && p->form[1] == RC_KEFF_GENE);
        /* the turned frame: Y' along (0.48, -0.6, 0.64); the global one */
        ENSURE_NEAR(p->lfrm[3], 0.48, 0, 1e-15);
        ENSURE_NEAR(p->lfrm[5], 0.64, 0, 1e-15);
        ENSURE(p->lfrm[9] == 1 && p->lfrm[13] == 1 && p->lfrm[17] == 1);
        ENSURE(p->gk[0] == 130 && p->gk[11] == 0.017 && p->gk[12 + 5] == 2.7);
        ENSURE(p->b1[1] == -1 && p->b2[1] == 0);
        ENSURE_NEAR(p->gd0[0], 1.41 - 0.31, 0, 1e-15);
    }
    rc_model_free(m);
}

static void test_coupling_gene_jacobian_matches_finite_differences(void)
{
    jacobian_vs_fd(GENE_DECK, "general spring");
}

/* The general springs' energy: a short run's ledger closes (the elastic
 * energy states are the work of the forces and moments). */
static void test_coupling_gene_energy_ledger_closes(void)
{
    char text[sizeof GENE_DECK + 256];
    snprintf(text, sizeof text, "%s/INIVEL/ROT/1\nspin\n0.3,-0.2,0.5,0,0\n/INIVEL/TRA/2\nv\n0.1,0.05,-0.2,0,0\n"
             "/SOLVER\n1,5,100000,1e-10,0,0\n1e-12,1e-9,1e-10,1e-10\n1e-12\n", GENE_DECK);
    rc_model *m = compile_deck(text);
    ENSURE(m != NULL);
    if (!m) return;
    rc_run_options opt = {0};
    rc_stats st;
    rc_error e;
    ENSURE(rc_run(m, &opt, &st, &e) == RC_OK);
    printf("    general springs: energy residual after 0.5 s %.2e J\n", st.energy_residual);
    ENSURE(fabs(st.energy_residual) < 1e-8);
    rc_model_free(m);
}

/* /PROP/TYPE13 beam springs and /PROP/TYPE8 springs in moving skews:
 * body 1 (nodes 1, 3, 5) and body 2 (nodes 2, 6, 7), node 9 and node 10
 * (at node 2) in no body. Part 7 (TYPE13, its Y from the turned skew 5,
 * all 26 lines): 31 body 1 -> body 2, 32 ground -> body 1, 33 body 2 ->
 * ground, 34 zero length (the skew's frame), carried by body 2. Part 8
 * (TYPE8, 19 lines, /SKEW/MOV 6 on body 2): 41 carried by end 2, 42 with
 * the element's /SKEW/MOV2 7 on body 1 (end 1), 43 to ground by end 1. */
#define BEAM_DECK                                                                                               \
    "/NODE\n1, 0.31, -0.17, 0.23\n2, 1.41, 0.27, -0.12\n3, 0.1, 0.4, -0.3\n5, 0.52, 0.11, 0.37\n"              \
    "6, 1.2, 0.5, 0.1\n7, 1.5, -0.2, 0.4\n9, 2.2, -0.4, 0.9\n10, 1.41, 0.27, -0.12\n"                           \
    "/GRNOD/NODE/4\nsecondary\n3\n5\n/GRNOD/NODE/8\nsecondary two\n6\n7\n"                                       \
    "/RBODY/1\nbody one\n1,,,,1.3,4\n0.021,0.017,0.029\n0.0013,-0.0022,0.0007\n"                                 \
    "/RBODY/2\nbody two\n2,,,,0.7,8\n0.011,0.013,0.009\n0,0,0\n/RUN\n0.5,0.01\n"                                 \
    "/SKEW/FIX/5\nturned\n0,0,0\n0.48,-0.6,0.64\n0,0,1\n/SKEW/MOV/6\non body two\n2,6,7,Y\n"                    \
    "/SKEW/MOV2/7\non body one\n1,3,5\n"                                                                     \
    "/PART/7\nbeam springs\n3\n/PROP/TYPE13/3\nt\n0.02,0.001,5\n"                                              \
    "130,1.1\n0\n1\n170,0.9\n0\n1\n210,1.7\n0\n1\n"                                                          \
    "3.1,0.013\n0\n1\n4.3,0.021\n0\n1\n2.7,0.017\n0\n1\n0,0,0,0\n1,1,1,1\n1,1,1,1\n1,1,1,1\n1,1,1,1\n"        \
    "1,1,1,1\n1,1,1,1\n/SPRING/7\n31,1,2\n32,9,1\n33,2,9\n34,2,10\n"                                         \
    "/PART/8\ngeneral springs\n4\n/PROP/TYPE8/4\nt\n0,0,6\n"                                                 \
    "90,0.7\n0\n1\n150,0.5\n0\n1\n60,1.2\n0\n1\n"                                                            \
    "2.1,0.011\n0\n1\n1.3,0.023\n0\n1\n3.7,0.007\n0\n1\n"                                                    \
    "/SPRING/8\n41,1,2\n42,1,2,,,,,7\n43,5,9,,,,,7\n"

static void test_coupling_beam_read(void)
{
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    ENSURE(rc_case_load(deck(BEAM_DECK), &c, &e) == RC_OK);
    if (!c) { fprintf(stderr, "  %s\n", e.msg); return; }
    const rc_case_prop *q = c->mesh->prop;
    ENSURE(c->mesh->nprop == 2 && q->sprtype == 13 && q->mass == 0.02 && q->inertia == 0.001 && q->skew_id == 5);
    ENSURE(q->k6[0] == 130 && q->c6[0] == 1.1 && q->k6[2] == 210 && q->k6[5] == 2.7 && q->c6[5] == 0.017);
    rc_case_free(c);
    rc_model *m = compile_deck(BEAM_DECK);
    ENSURE(m && m->cpl->n == 7);
    if (m && m->cpl->n == 7) {
        const rc_couplings *p = m->cpl;
        for (int k = 0; k < 7; k++) ENSURE(p->form[k] == RC_KEFF_GENE);
        /* carriers: TYPE13 end 1; the moving skews' bodies */
        const int fb[7] = {1, 1, 1, 1, 2, 1, 1};
        for (int k = 0; k < 7; k++) ENSURE(p->gfb[k] == fb[k]);
        /* 31: X' along node 1 -> node 2, Y' in the plane of X' and the
         * skew's Y, normal to X'; 34 (zero length): the skew's axes */
        const double L[3] = {1.41 - 0.31, 0.27 + 0.17, -0.12 - 0.23};
        const double nl = sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
        const double *E = p->lfrm;
        for (int i = 0; i < 3; i++) ENSURE_NEAR(E[i], L[i] / nl, 0, 1e-15);
        ENSURE_NEAR(E[0] * E[3] + E[1] * E[4] + E[2] * E[5], 0, 0, 1e-15);
        ENSURE(0.48 * E[3] - 0.6 * E[4] + 0.64 * E[5] > 0.5);
        ENSURE_NEAR(E[6], E[1] * E[5] - E[2] * E[4], 0, 1e-15);
        ENSURE_NEAR(p->lfrm[27 + 3], 0.48, 0, 1e-15);
        ENSURE_NEAR(p->lfrm[27 + 5], 0.64, 0, 1e-15);
        /* 41: /SKEW/MOV 6, Y' along node 2 -> node 6 */
        const double a[3] = {1.2 - 1.41, 0.5 - 0.27, 0.1 + 0.12};
        const double na = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        for (int i = 0; i < 3; i++) ENSURE_NEAR(p->lfrm[36 + 3 + i], a[i] / na, 0, 1e-15);
        ENSURE(p->gk[12 * 4] == 90 && p->gk[12 * 4 + 11] == 0.007);
    }
    rc_model_free(m);
}

/* A TYPE13 spring along the global Y without a skew: the global Y lies
 * on X', so Y' is the global Z made normal to X' and Z' = X' x Y' the
 * global X. */
static void test_coupling_beam_frame_fallback(void)
{
    rc_model *m = compile_deck("/NODE\n1, 0.3, 0.2, 0.1\n9, 0.3, 0.7, 0.1\n/RBODY/1\nbody\n1,,,,1.3\n"
                               "0.021,0.017,0.029\n0,0,0\n/RUN\n0.5,0.01\n/PART/7\nbeam\n3\n/PROP/TYPE13/3\nt\n0\n"
                               "130\n0\n1\n170\n0\n1\n210\n0\n1\n3.1\n0\n1\n4.3\n0\n1\n2.7\n0\n1\n"
                               "/SPRING/7\n31,9,1\n");
    ENSURE(m && m->cpl->n == 1);
    if (m && m->cpl->n == 1) {
        const double *E = m->cpl->lfrm, want[9] = {0, -1, 0, 0, 0, 1, -1, 0, 0};
        for (int i = 0; i < 9; i++) ENSURE_NEAR(E[i], want[i], 0, 1e-15);
        ENSURE(m->cpl->gfb[0] == 1 && m->cpl->b1[0] == -1 && m->cpl->b2[0] == 0);
    }
    rc_model_free(m);
}

static void test_coupling_beam_errors(void)
{
    char text[sizeof BEAM_DECK + 512];
    /* a moving skew on a third body: a body 3 on node 11, skew 9 */
    snprintf(text, sizeof text,
             "%s/NODE\n11,3,3,3\n12,3.5,3,3\n13,3,3.5,3\n/GRNOD/NODE/12\nthree\n12\n13\n"
             "/RBODY/3\nbody three\n11,,,,1,12\n0.1,0.1,0.1\n0,0,0\n/SKEW/MOV/9\nthree\n11,12,13\n/SPRING/8\n44,1,2,,,,,9\n",
             BEAM_DECK);
    EXPECT_ERROR(text, 1, 0, "card /SPRING/8", "field Skew_ID", "third body", "/RBODY 3");
    /* a moving skew whose nodes are on two bodies */
    snprintf(text, sizeof text, "%s/SKEW/MOV/9\ntwo\n1,2,3\n/SPRING/8\n44,1,2,,,,,9\n", BEAM_DECK);
    EXPECT_ERROR(text, 1, 0, "card /SPRING/8", "field Skew_ID", "different bodies");
    snprintf(text, sizeof text, "%s/SPRING/8\n44,1,2,,,,,19\n", BEAM_DECK);
    EXPECT_ERROR(text, 1, 0, "card /SPRING/8", "field Skew_ID", "no such skew");
}

static void test_coupling_beam_jacobian_matches_finite_differences(void)
{
    jacobian_vs_fd(BEAM_DECK, "beam and moving-frame spring");
}

/* The beam springs' and moving frames' energy: a short run's ledger closes
 * (the elastic energy states are the work of the forces and moments, which
 * derive from the potential through the turning frames), and the angular
 * momentum about the origin of the two bodies, joined only by springs 31,
 * 41 and 42, is kept. */
static void test_coupling_beam_energy_ledger_closes(void)
{
    char text[sizeof BEAM_DECK + 256];
    snprintf(text, sizeof text, "%s/INIVEL/ROT/1\nspin\n0.3,-0.2,0.5,0,0\n/INIVEL/TRA/2\nv\n0.1,0.05,-0.2,0,0\n"
             "/SOLVER\n1,5,100000,1e-10,0,0\n1e-12,1e-9,1e-10,1e-10\n1e-12\n", BEAM_DECK);
    rc_model *m = compile_deck(text);
    ENSURE(m != NULL);
    if (!m) return;
    rc_run_options opt = {0};
    rc_stats st;
    rc_error e;
    ENSURE(rc_run(m, &opt, &st, &e) == RC_OK);
    printf("    beam and moving-frame springs: energy residual after 0.5 s %.2e J\n", st.energy_residual);
    ENSURE(fabs(st.energy_residual) < 1e-8);
    rc_model_free(m);
}

/* Elastic curves (fct_ID1i): BEAM_DECK's TYPE8 property 4 with a
 * stiffening curve in X (A 2 N, Ascale 0.05 m), a softening one about Y
 * (A 0.3 N m, Ascale 0.2 rad), and TYPE13's curve in Z (A 1 N, Ascale 1). */
#define CURVE_DECK                                                                                            \
    "/NODE\n1, 0.31, -0.17, 0.23\n2, 1.41, 0.27, -0.12\n3, 0.1, 0.4, -0.3\n5, 0.52, 0.11, 0.37\n"            \
    "6, 1.2, 0.5, 0.1\n7, 1.5, -0.2, 0.4\n9, 2.2, -0.4, 0.9\n"                                                \
    "/GRNOD/NODE/4\nsecondary\n3\n5\n/GRNOD/NODE/8\nsecondary two\n6\n7\n"                                     \
    "/RBODY/1\nbody one\n1,,,,1.3,4\n0.021,0.017,0.029\n0.0013,-0.0022,0.0007\n"                               \
    "/RBODY/2\nbody two\n2,,,,0.7,8\n0.011,0.013,0.009\n0,0,0\n/RUN\n0.5,0.01\n"                               \
    "/SKEW/MOV/6\non body two\n2,6,7,Y\n"                                                                  \
    "/FUNCT/11\nstiffening\n-3,-60\n-1,-4\n0,0\n1,4\n3,60\n"                                                 \
    "/FUNCT/12\nsoftening\n-2,-1.5\n-1,-1\n0,0\n1,1\n2,1.5\n"                                                \
    "/FUNCT/13\nlinear\n-1,-150\n1,150\n"                                                                    \
    "/PART/7\nbeam springs\n3\n/PROP/TYPE13/3\nt\n0.02,0.001\n"                                              \
    "130,1.1\n0\n1\n170,0.9\n0\n1\n210,1.7\n13\n1\n"                                                         \
    "3.1,0.013\n0\n1\n4.3,0.021\n0\n1\n2.7,0.017\n0\n1\n"                                                    \
    "/SPRING/7\n31,1,2\n32,9,1\n"                                                                          \
    "/PART/8\ngeneral springs\n4\n/PROP/TYPE8/4\nt\n0,0,6\n"                                                 \
    "90,0.7,2\n11\n1,0,0.05\n150,0.5\n0\n1\n60,1.2\n0\n1\n"                                                  \
    "2.1,0.011\n0\n1\n1.3,0.023,0.3\n12\n1,0,0.2\n3.7,0.007\n0\n1\n"                                         \
    "/SPRING/8\n41,1,2\n43,9,2\n"

static void test_coupling_curve_read(void)
{
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    ENSURE(rc_case_load(deck(CURVE_DECK), &c, &e) == RC_OK);
    if (!c) { fprintf(stderr, "  %s\n", e.msg); return; }
    const rc_case_prop *q = &c->mesh->prop[1];
    ENSURE(q->sprtype == 8 && q->fct6[0] == 11 && q->fct6[4] == 12 && q->fct6[1] == 0);
    ENSURE(q->a6[0] == 2 && q->ascale6[0] == 0.05 && q->a6[4] == 0.3 && q->ascale6[4] == 0.2);
    ENSURE(q->a6[1] == 1 && q->ascale6[1] == 1); /* the defaults */
    rc_case_free(c);
    rc_model *m = compile_deck(CURVE_DECK);
    ENSURE(m && m->cpl->n == 4);
    if (m && m->cpl->n == 4) {
        const rc_couplings *p = m->cpl;
        ENSURE(p->gtab[0] == -1 && p->gtab[2] >= 0 && p->gtab[12] >= 0 && p->gtab[12 + 4] >= 0);
        ENSURE(p->gtab[12 + 1] == -1 && p->gsc[24] == 2 && p->gsc[24 + 6] == 0.05 && p->gsc[24 + 10] == 0.2);
    }
    rc_model_free(m);
    char text[sizeof CURVE_DECK + 64];
    snprintf(text, sizeof text, "%s", CURVE_DECK);
    char *at = strstr(text, "2.1,0.011\n0\n");
    if (at) at[10] = '7'; /* fct_ID14 = 7: no such function */
    EXPECT_ERROR(text, 1, 0, "card /PROP/TYPE8/4", "field fct_ID14", "no such function");
}

static void test_coupling_curve_jacobian_matches_finite_differences(void)
{
    jacobian_vs_fd(CURVE_DECK, "spring curves");
}

/* The curves' energy: W_el is the work of the curves' forces and moments,
 * the ledger closes. */
static void test_coupling_curve_energy_ledger_closes(void)
{
    char text[sizeof CURVE_DECK + 256];
    snprintf(text, sizeof text, "%s/INIVEL/ROT/1\nspin\n0.3,-0.2,0.5,0,0\n/INIVEL/TRA/2\nv\n0.1,0.05,-0.2,0,0\n"
             "/SOLVER\n1,5,100000,1e-10,0,0\n1e-12,1e-9,1e-10,1e-10\n1e-12\n", CURVE_DECK);
    rc_model *m = compile_deck(text);
    ENSURE(m != NULL);
    if (!m) return;
    rc_run_options opt = {0};
    rc_stats st;
    rc_error e;
    ENSURE(rc_run(m, &opt, &st, &e) == RC_OK);
    printf("    spring curves: energy residual after 0.5 s %.2e J\n", st.energy_residual);
    ENSURE(fabs(st.energy_residual) < 1e-8);
    rc_model_free(m);
}

/* Rupture: CURVE_DECK's properties with bounds (TYPE13 dmax2 0.01 m, its
 * springs 31 and 32; TYPE8 dmax1 0.02 m, springs 41 and 43: four rupture
 * roots), body 2 thrown hard enough to break some: the run locates the
 * ruptures, the ledger still closes (the energy stored at a rupture stays
 * in W_el), and the Jacobian of the whole springs matches. */
static void test_coupling_rupture(void)
{
    char text[sizeof CURVE_DECK + 512];
    snprintf(text, sizeof text, "%s", CURVE_DECK);
    char *at = strstr(text, "170,0.9\n0\n1\n"); /* TYPE13 direction Y: dmax2 0.01 */
    char *at8 = strstr(text, "90,0.7,2\n11\n1,0,0.05\n"); /* TYPE8 direction X: dmax1 0.02 */
    ENSURE(at && at8);
    if (!at || !at8) return;
    char out[sizeof text + 256];
    const size_t n1 = (size_t)(at - text), n2 = (size_t)(at8 - text);
    snprintf(out, sizeof out, "%.*s170,0.9\n0,,,,,,,0.01\n1\n%.*s90,0.7,2\n11,,,,,,,0.02\n1,0,0.05\n%s"
             "/INIVEL/TRA/2\nv\n0.9,-0.6,0.4,0,0\n/SOLVER\n1,5,100000,1e-10,0,0\n1e-12,1e-9,1e-10,1e-10\n1e-12\n",
             (int)n1, text, (int)(n2 - n1 - strlen("170,0.9\n0\n1\n")), at + strlen("170,0.9\n0\n1\n"),
             at8 + strlen("90,0.7,2\n11\n1,0,0.05\n"));
    rc_model *m = compile_deck(out);
    ENSURE(m && m->cpl->nrup == 4);
    if (!m) return;
    for (int k = 0; k < 4; k++) ENSURE(m->cpl->grup[k] == k);
    ENSURE(m->cpl->gdhi[6 * 0 + 1] == 0.01 && isinf(m->cpl->gdlo[6 * 0 + 1]) && m->cpl->gdhi[6 * 2] == 0.02);
    rc_run_options opt = {0};
    rc_stats st;
    rc_error e;
    ENSURE(rc_run(m, &opt, &st, &e) == RC_OK);
    printf("    rupture: %ld events, energy residual after 0.5 s %.2e J\n", st.events, st.energy_residual);
    ENSURE(st.events >= 2);
    ENSURE(fabs(st.energy_residual) < 1e-8);
    rc_model_free(m);
    jacobian_vs_fd(out, "springs with rupture bounds (whole)");
}

/* Energy ledger of a short run of the model (about 15 J exchanged between
 * motion, springs, dampers and lines): the couplings' stored and dissipated
 * energies close the balance, to a residual that shrinks with rtol. */
static void test_coupling_energy_ledger_closes(void)
{
    char text[sizeof model_deck + 256];
    double res[2];
    for (int i = 0; i < 2; i++) {
        const double rtol = i ? 1e-10 : 1e-8;
        snprintf(text, sizeof text, "%s/SOLVER\n1,5,100000,%g,0,0\n%g,1e-9,%g,%g\n%g\n", model_deck, rtol,
                 1e-3 * rtol, rtol, rtol, 1e-2 * rtol);
        rc_model *m = compile_deck(text);
        if (!m) return;
        rc_run_options opt = {0};
        rc_stats st;
        rc_error e;
        ENSURE(rc_run(m, &opt, &st, &e) == RC_OK);
        res[i] = fabs(st.energy_residual);
        rc_model_free(m);
    }
    printf("    energy residual after 0.5 s: %.2e J (rtol 1e-8), %.2e J (rtol 1e-10)\n", res[0], res[1]);
    ENSURE(res[0] < 1e-5);
    ENSURE(res[1] < 0.1 * res[0]);
}

/* Truncated and byte-mutated coupling decks load and compile, or fail with
 * an input error; never crash (the compiler solves every catenary while
 * probing the Jacobian pattern, whatever the values). */
static int load_compile_any(const char *text, size_t n)
{
    char path[160];
    snprintf(path, sizeof path, "%s", deck(""));
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(text, 1, n, f) != n || fclose(f) != 0) return 0;
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    rc_status st = rc_case_load(path, &c, &e);
    if (st == RC_OK) st = rc_model_compile(c, &m, &e);
    rc_model_free(m);
    rc_case_free(c);
    return st == RC_OK || st == RC_EINPUT;
}

static void test_coupling_robust_truncated_and_mutated(void)
{
    static char buf[sizeof model_deck];
    const size_t n = sizeof model_deck - 1;
    const size_t start = (size_t)(strstr(model_deck, "/COUPLING") - model_deck);
    int bad = 0;
    for (size_t k = start; k < n; k += 11) bad += !load_compile_any(model_deck, k);
    uint32_t seed = 0x0cafu;
    static const char alphabet[] = " ,./-+0123456789eEdD\t\n#\xff" "9e99";
    for (int it = 0; it < 600; it++) {
        memcpy(buf, model_deck, n);
        for (int j = 0; j < 1 + it % 3; j++) {
            seed = seed * 1664525u + 1013904223u;
            const size_t pos = start + (seed >> 8) % (n - start);
            seed = seed * 1664525u + 1013904223u;
            buf[pos] = alphabet[(seed >> 8) % (sizeof alphabet - 1)];
        }
        bad += !load_compile_any(buf, n);
    }
    ENSURE(bad == 0);
}

void suite_coupling(void);
void suite_coupling(void)
{
    RUN_TEST(test_coupling_cards_read);
    RUN_TEST(test_coupling_card_errors);
    RUN_TEST(test_coupling_compile_model);
    RUN_TEST(test_coupling_spring_element_read);
    RUN_TEST(test_coupling_spring_element_matches_card);
    RUN_TEST(test_coupling_spring_element_errors);
    RUN_TEST(test_coupling_gene_read);
    RUN_TEST(test_coupling_gene_jacobian_matches_finite_differences);
    RUN_TEST(test_coupling_gene_energy_ledger_closes);
    RUN_TEST(test_coupling_beam_read);
    RUN_TEST(test_coupling_beam_frame_fallback);
    RUN_TEST(test_coupling_beam_errors);
    RUN_TEST(test_coupling_beam_jacobian_matches_finite_differences);
    RUN_TEST(test_coupling_beam_energy_ledger_closes);
    RUN_TEST(test_coupling_curve_read);
    RUN_TEST(test_coupling_curve_jacobian_matches_finite_differences);
    RUN_TEST(test_coupling_curve_energy_ledger_closes);
    RUN_TEST(test_coupling_rupture);
    RUN_TEST(test_coupling_stiffness_integral);
    RUN_TEST(test_coupling_spring_forms);
    RUN_TEST(test_coupling_catenary_solutions);
    RUN_TEST(test_coupling_catenary_random_spans);
    RUN_TEST(test_coupling_catenary_ift_matches_finite_differences);
    RUN_TEST(test_coupling_catenary_vertical_limit);
    RUN_TEST(test_coupling_catenary_taut_limit);
    RUN_TEST(test_coupling_catenary_failure_is_recoverable);
    RUN_TEST(test_coupling_jacobian_matches_finite_differences);
    RUN_TEST(test_coupling_energy_ledger_closes);
    RUN_TEST(test_coupling_robust_truncated_and_mutated);
    cleanup();
}
