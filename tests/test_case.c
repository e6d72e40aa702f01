/*
 * Case reader tests: a full deck in fixed and comma format, Fortran reals,
 * defaults, #include, comments and /END, then one test per kind of input
 * error (status RC_EINPUT and a message naming file:line, card and field),
 * and a robustness sweep over truncated and mutated decks.
 *
 * Small decks are written from strings into a private temporary directory
 * (removed at the end of the suite); larger decks live in tests/data/.
 * The test binary runs from the repository root.
 */
#include "harness.h"
#include "testutil.h"
#include "case/case.h"
#include "base/error.h"

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* ---- Helpers ------------------------------------------------------------ */

/* A deck that loads: the card under test, then /RUN. */
#define RUN_CARD "/RUN\n1.0371,0.01\n"

/* Load the deck, expect `code`, the message to contain "PATH:LINE:" (when
 * line > 0) and each needle (NULL-terminated list). Returns the number of failures and
 * prints the message when something is missing. */
static int check_error(const char *path, rc_status code, int line, ...)
{
    rc_case *c = (rc_case *)1;
    rc_error e;
    char where[256];
    int bad = 0;
    va_list ap;
    rc_error_clear(&e);
    rc_status st = rc_case_load(path, &c, &e);
    if (st != code || c != NULL || e.code != code) bad++;
    snprintf(where, sizeof where, "%s:%d:", path, line);
    if (line > 0 && !strstr(e.msg, where)) bad++;
    va_start(ap, line);
    for (const char *s; (s = va_arg(ap, const char *));)
        if (!strstr(e.msg, s)) {
            fprintf(stderr, "  missing \"%s\"\n", s);
            bad++;
        }
    va_end(ap);
    if (bad) fprintf(stderr, "  status %d, expected %d at \"%s\"; message: %s\n", st, code, where, e.msg);
    if (st == RC_OK) rc_case_free(c);
    return bad;
}

/* Write `text` as NAME and expect an input error at LINE with the needles. */
#define EXPECT_INPUT_ERROR(name, text, line, ...) \
    ENSURE(check_error(tu_tmp_write((name), (text)), RC_EINPUT, (line), __VA_ARGS__, (const char *)NULL) == 0)

/* Load a deck that must be valid. */
static rc_case *load_ok(const char *path)
{
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    rc_status st = rc_case_load(path, &c, &e);
    if (st != RC_OK) fprintf(stderr, "  unexpected error loading %s: %s\n", path, e.msg);
    return c;
}

/* ---- The full deck ------------------------------------------------------ */

/* A /FRICTION coefficient set equals C1..C6, Fric, VISF. */
static int fricset_is(const rc_case_fricset *s, double c1, double c2, double c3, double c4,
                      double c5, double c6, double fric, double visf)
{
    return s->c[0] == c1 && s->c[1] == c2 && s->c[2] == c3 && s->c[3] == c4 && s->c[4] == c5 &&
           s->c[5] == c6 && s->fric == fric && s->visf == visf;
}

/* /PART, /GRPART, /FRICTION, /FRIC_ORIENT of the full deck. */
static void check_full_friction_values(const rc_case *c)
{
    /* /PART: a whole body; surfaces fixed in space over two lines */
    ENSURE(c->npart == 2);
    if (c->npart == 2) {
        const rc_case_part *p = &c->part[0], *q = &c->part[1];
        ENSURE(p->id == 41 && strcmp(p->title, "ball part") == 0 && p->rbody_id == 7 &&
               p->nsurf == 0 && p->surf == NULL && p->loc.line == 58 && p->line_loc.line == 61);
        static const int qs[11] = {11, 113, 117, 131, 137, 171, 173, 179, 191, 193, 197};
        ENSURE(q->id == 42 && strcmp(q->title, "fixed ground faces") == 0 && q->rbody_id == 0 &&
               q->nsurf == 11 && q->loc.line == 62 && q->line_loc.line == 65);
        if (q->nsurf == 11) ENSURE(memcmp(q->surf, qs, sizeof qs) == 0);
    }
    /* /GRPART/PART */
    ENSURE(c->ngrpart == 2);
    if (c->ngrpart == 2) {
        const rc_case_grpart *g = &c->grpart[0], *h = &c->grpart[1];
        ENSURE(g->id == 51 && strcmp(g->title, "ball parts") == 0 && g->n == 3 && g->loc.line == 67);
        if (g->n == 3) ENSURE(g->parts[0] == 41 && g->parts[1] == 42 && g->parts[2] == 43);
        ENSURE(h->id == 52 && strcmp(h->title, "ground parts") == 0 && h->n == 1);
        if (h->n == 1) ENSURE(h->parts[0] == 42);
    }
    /* /FRICTION: Renard with two groups, the second orthotropic */
    ENSURE(c->nfriction == 2);
    if (c->nfriction == 2) {
        const rc_case_friction *f = &c->friction[0], *v = &c->friction[1];
        ENSURE(f->id == 61 && strcmp(f->title, "Renard, orthotropic pair") == 0);
        ENSURE(f->ifric == 3 && f->ifiltr == 3 && f->xfreq == 37.1 && f->iform == 2 &&
               f->dt_ref == 0 && f->area == 0.00137);
        ENSURE(fricset_is(&f->def, 0.31, 0.23, 0.41, 0.17, 0.0137, 0.371, 0.5, 0.73));
        ENSURE(f->loc.line == 74 && f->line_loc[0].line == 76 && f->line_loc[1].line == 77 &&
               f->line_loc[2].line == 78);
        ENSURE(f->npair == 2);
        if (f->npair == 2) {
            const rc_case_fricpair *a = &f->pair[0], *b = &f->pair[1];
            ENSURE(a->grpart1 == 51 && a->grpart2 == 52 && a->part1 == 0 && a->part2 == 0 &&
                   a->idir == 0 && a->loc.line == 79);
            ENSURE(fricset_is(&a->set[0], 0.33, 0.27, 0.47, 0.13, 0.0071, 0.137, 0, 1));
            ENSURE(b->grpart1 == 0 && b->grpart2 == 0 && b->part1 == 41 && b->part2 == 42 &&
                   b->idir == 1 && b->loc.line == 82);
            ENSURE(fricset_is(&b->set[0], 0.37, 0.29, 0.43, 0.19, 0.0113, 0.173, 0, 1.37));
            ENSURE(fricset_is(&b->set[1], 0.21, 0.19, 0.31, 0.11, 0.0031, 0.0713, 0, 0.37));
        }
        /* defaults only; Iform 0 means 1, VISF 0 means 1 */
        ENSURE(v->id == 62 && v->ifric == 1 && v->ifiltr == 1 && v->xfreq == 0.371 &&
               v->iform == 1 && v->dt_ref == 1.37e-05 && v->area == 3.7e-04 && v->npair == 0 &&
               v->pair == NULL);
        ENSURE(fricset_is(&v->def, 1.3e-07, 0.0371, -2.1e-09, 3.7e-15, 0.0013, 0, 0.137, 1));
    }
    /* /FRIC_ORIENT */
    ENSURE(c->nfricorient == 1);
    if (c->nfricorient == 1) {
        const rc_case_fricorient *o = &c->fricorient[0];
        ENSURE(o->id == 81 && strcmp(o->title, "orthotropy directions") == 0 && o->n == 2 &&
               o->loc.line == 92);
        if (o->n == 2) {
            const rc_case_fricorient_item *a = &o->item[0], *b = &o->item[1];
            ENSURE(a->grpart_id == 51 && a->part_id == 0 && a->v[0] == 1.0 && a->v[1] == 0.5 &&
                   a->v[2] == 0 && a->skew_id == 0 && a->phi == 37.1 && a->iorth == 1 &&
                   a->loc.line == 94);
            ENSURE(b->grpart_id == 0 && b->part_id == 42 && b->v[0] == 0 && b->v[1] == -0.371 &&
                   b->v[2] == 1.37 && b->skew_id == 0 && b->phi == -13.7 && b->iorth == 0 &&
                   b->loc.line == 96);
        }
    }
}

/* Every field of tests/data/full_fixed.rad (and full_comma.rad). */
static void check_full_values(const rc_case *c)
{
    /* /BEGIN */
    ENSURE(strcmp(c->title, "Full deck test run") == 0);
    ENSURE(strcmp(c->unit_mass, "kg") == 0 && strcmp(c->unit_length, "m") == 0 &&
           strcmp(c->unit_time, "s") == 0);
    /* /NODE */
    ENSURE(c->nnode == 3);
    if (c->nnode == 3) {
        ENSURE(c->node[0].id == 1001 && c->node[0].x[0] == 0.0371 && c->node[0].x[1] == -0.1234 &&
               c->node[0].x[2] == 0.0529);
        ENSURE(c->node[1].id == 1002 && c->node[1].x[0] == 1.5 && c->node[1].x[1] == 0.25 &&
               c->node[1].x[2] == -3.75);
        ENSURE(c->node[2].id == 1003 && c->node[2].x[0] == 0 && c->node[2].x[1] == 0.125 &&
               c->node[2].x[2] == 0);
        ENSURE(c->node[1].loc.line == 11);
    }
    /* /GRNOD */
    ENSURE(c->ngrnod == 1);
    if (c->ngrnod == 1) {
        const rc_case_grnod *g = &c->grnod[0];
        ENSURE(g->id == 71 && strcmp(g->title, "group seventy-one") == 0 && g->n == 4);
        if (g->n == 4)
            ENSURE(g->nodes[0] == 1001 && g->nodes[1] == 1002 && g->nodes[2] == 1003 &&
                   g->nodes[3] == 1005);
    }
    /* /RBODY */
    ENSURE(c->nrbody == 1);
    if (c->nrbody == 1) {
        const rc_case_rbody *r = &c->rbody[0];
        ENSURE(r->id == 7 && strcmp(r->title, "ball") == 0 && r->node_id == 1001);
        ENSURE(r->skew_id == 0 && r->ispher == 1 && r->mass == 1.0371 && r->grnod_id == 71 &&
               r->icog == 3);
        ENSURE(r->J[0] == 0.0011371 && r->J[1] == 0.0012713 && r->J[2] == 0.0013137);
        ENSURE(r->J[3] == 1.37e-05 && r->J[4] == -2.71e-05 && r->J[5] == 3.13e-05);
        ENSURE(r->loc.line == 17);
    }
    /* /SURF/PLANE and /SURF/ELLIPS */
    ENSURE(c->nsurf == 2);
    if (c->nsurf == 2) {
        const rc_case_surf *p = &c->surf[0], *s = &c->surf[1];
        ENSURE(p->id == 11 && p->kind == RC_CASE_SURF_PLANE && strcmp(p->title, "ground") == 0);
        ENSURE(p->m[0] == 0 && p->m[1] == 0 && p->m[2] == -0.0013);
        ENSURE(p->m1[0] == 0 && p->m1[1] == 0 && p->m1[2] == -1.0013 && p->rbody_id == 0);
        ENSURE(s->id == 12 && s->kind == RC_CASE_SURF_ELLIPS && strcmp(s->title, "ball surface") == 0);
        ENSURE(s->skew_id == 0 && s->degree == 2 && s->rbody_id == 7);
        ENSURE(s->c[0] == 0.0371 && s->c[1] == -0.1234 && s->c[2] == 0.0529);
        ENSURE(s->abc[0] == 0.0493 && s->abc[1] == 0.0493 && s->abc[2] == 0.0493);
    }
    /* /FUNCT */
    ENSURE(c->nfunct == 1);
    if (c->nfunct == 1) {
        const rc_case_funct *f = &c->funct[0];
        ENSURE(f->id == 31 && strcmp(f->title, "load curve") == 0 && f->npts == 3);
        if (f->npts == 3)
            ENSURE(f->x[0] == 0 && f->y[0] == 0 && f->x[1] == 0.0011 && f->y[1] == 1371.25 &&
                   f->x[2] == 0.00237 && f->y[2] == 3091.1);
    }
    /* /INTER/TYPE6 */
    ENSURE(c->ntype6 == 1);
    if (c->ntype6 == 1) {
        const rc_case_type6 *t = &c->type6[0];
        ENSURE(t->id == 3 && strcmp(t->title, "sphere on ground") == 0);
        ENSURE(t->surf1 == 12 && t->surf2 == 11);
        ENSURE(t->sfric == 0 && t->fric == 0 && t->gap == 0.0001371 && t->tstart == 0.0123 &&
               t->tstop == 0.9876);
        ENSURE(t->irs == 0 && t->irm == 0 && t->inacti == 0 && t->fct_ff == 0 && t->fct_fv == 0);
        ENSURE(t->ascalef == 1.2371 && t->ascalev == 0.5371);
        ENSURE(t->fct_ld == 31 && t->iform == 0 && t->ascalex == 0.003713 &&
               t->fscaleld == 2.3711 && t->icor == 0);
        ENSURE(t->fct_ul == 0 && t->stiff == 0 && t->fscaleul == 1.0731);
        ENSURE(t->visc == 37.0137 && t->fct_dv == 0 && t->fct_df == 0 && t->fscalev == 0.7311);
        ENSURE(t->loc.line == 38);
        for (int k = 0; k < 6; k++) ENSURE(t->line_loc[k].line == 40 + k);
    }
    /* /INIVEL */
    ENSURE(c->ninivel == 2);
    if (c->ninivel == 2) {
        const rc_case_inivel *a = &c->inivel[0], *b = &c->inivel[1];
        ENSURE(a->id == 5 && a->rot == 0 && a->v[0] == 0 && a->v[1] == 0 && a->v[2] == -1.2371 &&
               a->grnod_id == 71 && a->skew_id == 0);
        ENSURE(b->id == 6 && b->rot == 1 && b->v[0] == 3.711 && b->v[1] == -1.371 &&
               b->v[2] == 0.1137 && b->grnod_id == 71);
    }
    /* /GRAV */
    ENSURE(c->ngrav == 1);
    if (c->ngrav == 1) {
        const rc_case_grav *g = &c->grav[0];
        ENSURE(g->id == 9 && g->fct_id == 0 && g->dir == 2 && g->skew_id == 0 &&
               g->sensor_id == 0 && g->grnod_id == 71 && g->ascale == 1.0137 &&
               g->fscale == -9.8137);
    }
    /* /BCS */
    ENSURE(c->nbcs == 1);
    if (c->nbcs == 1) {
        const rc_case_bcs *b = &c->bcs[0];
        ENSURE(b->id == 4 && b->skew_id == 0 && b->grnod_id == 71);
        ENSURE(b->fix[0] == 0 && b->fix[1] == 1 && b->fix[2] == 0 && b->fix[3] == 1 &&
               b->fix[4] == 1 && b->fix[5] == 1);
    }
    check_full_friction_values(c);
    /* /RUN and /SOLVER */
    ENSURE(c->run.present == 1 && c->run.tend == 1.0371 && c->run.dtout == 0.001371);
    const rc_case_solver *s = &c->solver;
    ENSURE(s->present == 1 && s->method == 1 && s->max_order == 4 && s->max_steps == 50037);
    ENSURE(s->rtol == 1.371e-07 && s->hmax == 0.0137 && s->h0 == 1.37e-06);
    ENSURE(s->atol_pos == 3.71e-10 && s->atol_quat == 7.13e-10 && s->atol_vel == 1.37e-07 &&
           s->atol_omega == 3.17e-07 && s->atol_energy == 7.31e-07);
    ENSURE(c->nwarnings == 0);
}

static void test_case_full_deck_fixed(void)
{
    rc_case *c = load_ok("tests/data/full_fixed.rad");
    ENSURE(c != NULL);
    if (!c) return;
    check_full_values(c);
    ENSURE(strcmp(c->path, "tests/data/full_fixed.rad") == 0);
    ENSURE(c->nfiles == 1 && strcmp(c->files[0], "tests/data/full_fixed.rad") == 0);
    ENSURE(c->rbody[0].loc.file == c->files[0]);
    rc_case_free(c);
}

/* Field-by-field equality of the /PART, /GRPART, /FRICTION and
 * /FRIC_ORIENT cards, locations excepted. */
static int fricset_equal(const rc_case_fricset *x, const rc_case_fricset *y)
{
    return memcmp(x->c, y->c, sizeof x->c) == 0 && x->fric == y->fric && x->visf == y->visf;
}

static int friction_equal(const rc_case *a, const rc_case *b)
{
    int eq = a->npart == b->npart && a->ngrpart == b->ngrpart && a->nfriction == b->nfriction &&
             a->nfricorient == b->nfricorient;
    if (!eq) return 0;
    for (int i = 0; i < a->npart; i++) {
        const rc_case_part *x = &a->part[i], *y = &b->part[i];
        eq &= x->id == y->id && strcmp(x->title, y->title) == 0 && x->rbody_id == y->rbody_id &&
              x->nsurf == y->nsurf &&
              (x->nsurf == 0 || memcmp(x->surf, y->surf, sizeof(int) * (size_t)x->nsurf) == 0);
    }
    for (int i = 0; i < a->ngrpart; i++) {
        const rc_case_grpart *x = &a->grpart[i], *y = &b->grpart[i];
        eq &= x->id == y->id && strcmp(x->title, y->title) == 0 && x->n == y->n &&
              (x->n == 0 || memcmp(x->parts, y->parts, sizeof(int) * (size_t)x->n) == 0);
    }
    for (int i = 0; i < a->nfriction; i++) {
        const rc_case_friction *x = &a->friction[i], *y = &b->friction[i];
        eq &= x->id == y->id && strcmp(x->title, y->title) == 0 && x->ifric == y->ifric &&
              x->ifiltr == y->ifiltr && x->xfreq == y->xfreq && x->iform == y->iform &&
              x->dt_ref == y->dt_ref && x->area == y->area &&
              fricset_equal(&x->def, &y->def) && x->npair == y->npair;
        if (x->npair != y->npair) return 0;
        for (int k = 0; k < x->npair; k++) {
            const rc_case_fricpair *p = &x->pair[k], *q = &y->pair[k];
            eq &= p->grpart1 == q->grpart1 && p->grpart2 == q->grpart2 && p->part1 == q->part1 &&
                  p->part2 == q->part2 && p->idir == q->idir &&
                  fricset_equal(&p->set[0], &q->set[0]) && fricset_equal(&p->set[1], &q->set[1]);
        }
    }
    for (int i = 0; i < a->nfricorient; i++) {
        const rc_case_fricorient *x = &a->fricorient[i], *y = &b->fricorient[i];
        eq &= x->id == y->id && strcmp(x->title, y->title) == 0 && x->n == y->n;
        if (x->n != y->n) return 0;
        for (int k = 0; k < x->n; k++) {
            const rc_case_fricorient_item *p = &x->item[k], *q = &y->item[k];
            eq &= p->grpart_id == q->grpart_id && p->part_id == q->part_id &&
                  memcmp(p->v, q->v, sizeof p->v) == 0 && p->skew_id == q->skew_id &&
                  p->phi == q->phi && p->iorth == q->iorth;
        }
    }
    return eq;
}

/* Field-by-field equality of two cases, locations excepted. */
static int case_equal(const rc_case *a, const rc_case *b)
{
    int eq = strcmp(a->title, b->title) == 0 && strcmp(a->unit_mass, b->unit_mass) == 0 &&
             strcmp(a->unit_length, b->unit_length) == 0 && strcmp(a->unit_time, b->unit_time) == 0;
    eq &= a->nnode == b->nnode && a->ngrnod == b->ngrnod && a->nrbody == b->nrbody &&
          a->nsurf == b->nsurf && a->nfunct == b->nfunct && a->ntype6 == b->ntype6 &&
          a->ninivel == b->ninivel && a->ngrav == b->ngrav && a->nbcs == b->nbcs;
    if (!eq) return 0;
    for (int i = 0; i < a->nnode; i++)
        eq &= a->node[i].id == b->node[i].id && memcmp(a->node[i].x, b->node[i].x, sizeof a->node[i].x) == 0;
    for (int i = 0; i < a->ngrnod; i++)
        eq &= a->grnod[i].id == b->grnod[i].id && a->grnod[i].n == b->grnod[i].n &&
              memcmp(a->grnod[i].nodes, b->grnod[i].nodes, sizeof(int) * (size_t)a->grnod[i].n) == 0 &&
              strcmp(a->grnod[i].title, b->grnod[i].title) == 0;
    for (int i = 0; i < a->nrbody; i++) {
        const rc_case_rbody *x = &a->rbody[i], *y = &b->rbody[i];
        eq &= x->id == y->id && strcmp(x->title, y->title) == 0 && x->node_id == y->node_id &&
              x->skew_id == y->skew_id && x->ispher == y->ispher && x->mass == y->mass &&
              x->grnod_id == y->grnod_id && x->icog == y->icog &&
              memcmp(x->J, y->J, sizeof x->J) == 0;
    }
    for (int i = 0; i < a->nsurf; i++) {
        const rc_case_surf *x = &a->surf[i], *y = &b->surf[i];
        eq &= x->id == y->id && x->kind == y->kind && strcmp(x->title, y->title) == 0 &&
              memcmp(x->m, y->m, sizeof x->m) == 0 && memcmp(x->m1, y->m1, sizeof x->m1) == 0 &&
              x->skew_id == y->skew_id && x->degree == y->degree &&
              memcmp(x->c, y->c, sizeof x->c) == 0 && memcmp(x->abc, y->abc, sizeof x->abc) == 0 &&
              x->rbody_id == y->rbody_id;
    }
    for (int i = 0; i < a->nfunct; i++) {
        const rc_case_funct *x = &a->funct[i], *y = &b->funct[i];
        eq &= x->id == y->id && x->npts == y->npts && strcmp(x->title, y->title) == 0 &&
              memcmp(x->x, y->x, sizeof(double) * (size_t)x->npts) == 0 &&
              memcmp(x->y, y->y, sizeof(double) * (size_t)x->npts) == 0;
    }
    for (int i = 0; i < a->ntype6; i++) {
        const rc_case_type6 *x = &a->type6[i], *y = &b->type6[i];
        eq &= x->id == y->id && strcmp(x->title, y->title) == 0 && x->surf1 == y->surf1 &&
              x->surf2 == y->surf2 && x->sfric == y->sfric && x->fric == y->fric &&
              x->gap == y->gap && x->tstart == y->tstart && x->tstop == y->tstop &&
              x->irs == y->irs && x->irm == y->irm && x->inacti == y->inacti &&
              x->fct_ff == y->fct_ff && x->fct_fv == y->fct_fv && x->ascalef == y->ascalef &&
              x->ascalev == y->ascalev && x->fct_ld == y->fct_ld && x->iform == y->iform &&
              x->ascalex == y->ascalex && x->fscaleld == y->fscaleld && x->icor == y->icor &&
              x->fct_ul == y->fct_ul && x->stiff == y->stiff && x->fscaleul == y->fscaleul &&
              x->visc == y->visc && x->fct_dv == y->fct_dv && x->fct_df == y->fct_df &&
              x->fscalev == y->fscalev;
    }
    for (int i = 0; i < a->ninivel; i++)
        eq &= a->inivel[i].id == b->inivel[i].id && a->inivel[i].rot == b->inivel[i].rot &&
              memcmp(a->inivel[i].v, b->inivel[i].v, sizeof a->inivel[i].v) == 0 &&
              a->inivel[i].grnod_id == b->inivel[i].grnod_id &&
              a->inivel[i].skew_id == b->inivel[i].skew_id;
    for (int i = 0; i < a->ngrav; i++)
        eq &= a->grav[i].id == b->grav[i].id && a->grav[i].fct_id == b->grav[i].fct_id &&
              a->grav[i].dir == b->grav[i].dir && a->grav[i].grnod_id == b->grav[i].grnod_id &&
              a->grav[i].ascale == b->grav[i].ascale && a->grav[i].fscale == b->grav[i].fscale;
    for (int i = 0; i < a->nbcs; i++)
        eq &= a->bcs[i].id == b->bcs[i].id && memcmp(a->bcs[i].fix, b->bcs[i].fix, sizeof a->bcs[i].fix) == 0 &&
              a->bcs[i].grnod_id == b->bcs[i].grnod_id;
    eq &= friction_equal(a, b);
    eq &= a->run.present == b->run.present && a->run.tend == b->run.tend && a->run.dtout == b->run.dtout;
    const rc_case_solver *s = &a->solver, *t = &b->solver;
    eq &= s->present == t->present && s->method == t->method && s->max_order == t->max_order &&
          s->max_steps == t->max_steps && s->rtol == t->rtol && s->atol_pos == t->atol_pos &&
          s->atol_quat == t->atol_quat && s->atol_vel == t->atol_vel &&
          s->atol_omega == t->atol_omega && s->atol_energy == t->atol_energy &&
          s->hmax == t->hmax && s->h0 == t->h0;
    return eq;
}

static void test_case_full_deck_comma_equals_fixed(void)
{
    rc_case *a = load_ok("tests/data/full_fixed.rad");
    rc_case *b = load_ok("tests/data/full_comma.rad");
    ENSURE(a && b);
    if (a && b) {
        check_full_values(b);
        ENSURE(case_equal(a, b));
        ENSURE(a->checksum != b->checksum); /* different bytes */
    }
    rc_case_free(a);
    rc_case_free(b);
}

/* ---- Numbers, defaults, layout ---------------------------------------- */

static void test_case_fortran_reals(void)
{
    const char *p = tu_tmp_write("reals.rad",
                              "/FUNCT/1\n"
                              "Fortran forms\n"
                              "             -2.                 .5\n"
                              "              1.E-3             1.5D+03\n"
                              "              +4              1.5d3\n"
                              "              1.E3            -0.0371D-2\n"
                              "1.0000000000000000000000000000001E4,  +.25e+1\n" RUN_CARD);
    rc_case *c = load_ok(p);
    ENSURE(c != NULL);
    if (!c) return;
    const rc_case_funct *f = &c->funct[0];
    ENSURE(f->npts == 5);
    if (f->npts == 5) {
        ENSURE(f->x[0] == -2.0 && f->y[0] == 0.5);
        ENSURE(f->x[1] == 1e-3 && f->y[1] == 1500.0);
        ENSURE(f->x[2] == 4.0 && f->y[2] == 1500.0);
        ENSURE(f->x[3] == 1000.0 && f->y[3] == -0.0371e-2);
        ENSURE(f->x[4] == 1e4 && f->y[4] == 2.5);
    }
    rc_case_free(c);
}

static void test_case_defaults(void)
{
    const char *p = tu_tmp_write("defaults.rad",
                              "/INTER/TYPE6/8\n"
                              "\n"          /* blank title */
                              "        12        11\n"
                              "\n"          /* Sfric..Tstop all blank */
                              "\n"          /* IRS..Ascalev blank */
                              "        31\n" /* only fct_IDld */
                              "         0                             0                   0\n"
                              "\n"
                              "/SURF/ELLIPS/12\n"
                              "sphere\n"
                              "         0         0\n" /* n = 0 means 2 */
                              "\n"
                              "0.0371,0.0371,0.0371\n"
                              "/GRAV/1\n"
                              "\n"
                              "         0         Z\n"
                              "/RUN\n"
                              "               0.371\n");
    rc_case *c = load_ok(p);
    ENSURE(c != NULL);
    if (!c) return;
    const rc_case_type6 *t = &c->type6[0];
    ENSURE(t->title[0] == '\0' && t->surf1 == 12 && t->surf2 == 11 && t->fct_ld == 31);
    ENSURE(t->sfric == 0 && t->fric == 0 && t->gap == 0 && t->tstart == 0 && t->tstop == 1e30);
    ENSURE(t->ascalef == 1 && t->ascalev == 1 && t->ascalex == 1 && t->fscaleld == 1);
    ENSURE(t->fscaleul == 1 && t->fscalev == 1 && t->visc == 0 && t->iform == 0);
    const rc_case_surf *s = &c->surf[0];
    ENSURE(s->degree == 2 && s->rbody_id == 0 && s->c[0] == 0 && s->abc[2] == 0.0371);
    const rc_case_grav *g = &c->grav[0];
    ENSURE(g->fct_id == 0 && g->dir == 2 && g->ascale == 1 && g->fscale == 1 && g->grnod_id == 0);
    /* /RUN: Dt_out = Tend/100; /SOLVER absent: documented defaults */
    ENSURE(c->run.tend == 0.371);
    ENSURE_NEAR(c->run.dtout, 0.00371, 1e-15, 0);
    const rc_case_solver *v = &c->solver;
    ENSURE(v->present == 0 && v->method == 0 && v->max_order == 5 && v->max_steps == 100000);
    /* blank absolute tolerances: 0, derived from the model at compile time */
    ENSURE(v->rtol == 1e-8 && v->atol_pos == 0 && v->atol_quat == 0 && v->atol_vel == 0 &&
           v->atol_omega == 0 && v->atol_energy == 0 && v->hmax == 0 && v->h0 == 0);
    ENSURE(c->title[0] == '\0' && c->unit_mass[0] == '\0');
    rc_case_free(c);
}

/* A fully blank line inside a card is a line of defaults. */
static void test_case_blank_line_is_data(void)
{
    const char *p = tu_tmp_write("blank.rad",
                              "/RBODY/3\n"
                              "\n"
                              "1,,,,0.0371\n"
                              "0.25,0.5,0.75\n"
                              "\n" /* Jxy Jyz Jxz = 0 */
                              "\n" /* optional Ioptoff line, blank too */
                              "\n" /* beyond the layout: harmless */
                              RUN_CARD);
    rc_case *c = load_ok(p);
    ENSURE(c && c->nrbody == 1);
    if (c && c->nrbody == 1)
        ENSURE(c->rbody[0].mass == 0.0371 && c->rbody[0].J[3] == 0 && c->rbody[0].J[2] == 0.75);
    rc_case_free(c);
}

/* Comments, #RADIOSS STARTER, CRLF, trailing blanks, BOM, /END. */
static void test_case_comments_and_end(void)
{
    const char *p = tu_tmp_write("comments.rad",
                              "\xEF\xBB\xBF#RADIOSS STARTER\r\n"
                              "# comment\r\n"
                              "$ comment, with a comma and\ta tab\r\n"
                              "\r\n"
                              "/RUN   \r\n"
                              "# a comment inside a card is not a line\r\n"
                              "0.0371, 0.00371   \r\n"
                              "/end\r\n"
                              "/FOO/1\n\x01\x02 garbage after the end \xff\n");
    rc_case *c = load_ok(p);
    ENSURE(c != NULL);
    if (c) ENSURE(c->run.tend == 0.0371 && c->run.dtout == 0.00371 && c->run.loc.line == 5);
    rc_case_free(c);
}

/* Ignored Radioss cards leave a warning. */
static void test_case_ignored_cards_warn(void)
{
    const char *p = tu_tmp_write("ignored.rad",
                              "/TITLE\nsome title\n/MAT/LAW99/4\nsteel\n7800 2.1e11 0.3\n"
                              "/PROP/WEIRD//header/\n" RUN_CARD);
    rc_case *c = load_ok(p);
    ENSURE(c && c->nwarnings == 3);
    if (c && c->nwarnings == 3) {
        ENSURE(strstr(c->warnings[0], "ignored.rad:1:") && strstr(c->warnings[0], "/TITLE"));
        ENSURE(strstr(c->warnings[1], "ignored.rad:3:") && strstr(c->warnings[1], "/MAT/LAW99/4") &&
               strstr(c->warnings[1], "ignored"));
    }
    rc_case_free(c);
}

/* FNV-1a 64, written independently of the reader. */
static uint64_t fnv1a(const char *s, size_t n)
{
    uint64_t h = 0xcbf29ce484222325ull;
    while (n--) h = (h ^ (unsigned char)*s++) * 0x100000001b3ull;
    return h;
}

static void test_case_checksum(void)
{
    const char *text = "/RUN\n1.0,0.1\n";
    const char *p = tu_tmp_write("sum.rad", text);
    rc_case *c = load_ok(p);
    ENSURE(c != NULL);
    ENSURE(fnv1a("a", 1) == 0xaf63dc4c8601ec8cull); /* published test vector */
    if (c) ENSURE(c->checksum == (unsigned long)fnv1a(text, strlen(text)));
    rc_case_free(c);
}

/* ---- #include ------------------------------------------------------------ */

static void test_case_include_relative(void)
{
    rc_case *c = load_ok("tests/data/include_main.rad");
    ENSURE(c != NULL);
    if (!c) return;
    ENSURE(c->nfiles == 3);
    if (c->nfiles == 3) {
        ENSURE(strcmp(c->files[1], "tests/data/sub/include_body.rad") == 0);
        ENSURE(strcmp(c->files[2], "tests/data/sub/include_curve.inc") == 0);
    }
    ENSURE(c->nrbody == 1 && c->nfunct == 1 && c->ngrav == 1);
    if (c->nrbody == 1 && c->nfunct == 1 && c->nfiles == 3) {
        ENSURE(c->rbody[0].id == 21 && c->rbody[0].mass == 0.25);
        ENSURE(c->rbody[0].loc.file == c->files[1] && c->rbody[0].loc.line == 2);
        ENSURE(c->funct[0].loc.file == c->files[2] && c->funct[0].loc.line == 1);
        ENSURE(c->funct[0].y[1] == 137.1);
        ENSURE(c->grav[0].loc.file == c->files[0] && c->grav[0].loc.line == 6);
    }
    ENSURE(c->run.tend == 0.5);
    rc_case_free(c);
}

static void test_case_include_cycle(void)
{
    tu_tmp_write("cyc_b.inc", "/FUNCT/1\nf\n0,0\n1,1\n#include cyc_a.rad\n");
    const char *a = tu_tmp_write("cyc_a.rad", RUN_CARD "#include cyc_b.inc\n");
    ENSURE(check_error(a, RC_EINPUT, 0, "cyc_b.inc:5:", "cyc_a.rad", "cycle", (const char *)NULL) == 0);
    /* a file including itself */
    EXPECT_INPUT_ERROR("self.rad", RUN_CARD "#include self.rad\n", 3, "self.rad", "cycle");
}

static void test_case_include_missing(void)
{
    EXPECT_INPUT_ERROR("incmiss.rad", RUN_CARD "# x\n#include no_such_file.inc\n", 4,
                       "#include", "no_such_file.inc", "cannot read");
    EXPECT_INPUT_ERROR("incempty.rad", RUN_CARD "#include   \n", 3, "#include", "missing file name");
}

static void test_case_include_depth_limit(void)
{
    /* d0 -> d1 -> ... -> d40: deeper than the limit of 32 levels */
    char name[32], text[64];
    const char *d0 = NULL;
    for (int i = 40; i >= 0; i--) {
        snprintf(name, sizeof name, "d%d.inc", i);
        snprintf(text, sizeof text, "#include d%d.inc\n", i + 1);
        d0 = tu_tmp_write(name, i == 40 ? RUN_CARD : text);
    }
    const char *path = d0; /* written last */
    ENSURE(check_error(path, RC_EINPUT, 0, "d32.inc:1:", "d33.inc", "deeper than 32",
                       (const char *)NULL) == 0);
}

/* The example deck of docs/case-format.md (between the example markers)
 * loads and has the documented content. */
static void test_case_docs_example(void)
{
    FILE *f = fopen("docs/case-format.md", "rb");
    ENSURE(f != NULL);
    if (!f) return;
    static char doc[1 << 18]; /* the whole page (130 KiB and growing) */
    size_t n = fread(doc, 1, sizeof doc - 1, f);
    fclose(f);
    doc[n] = '\0';
    char *s = strstr(doc, "<!-- example deck -->");
    char *b = s ? strstr(s, "```") : NULL;
    b = b ? strchr(b, '\n') : NULL; /* the deck starts after the fence line */
    char *e = b ? strstr(b, "\n```") : NULL;
    ENSURE(b && e);
    if (!b || !e) return;
    e[1] = '\0';
    rc_case *c = load_ok(tu_tmp_write("docs_example.rad", b + 1));
    ENSURE(c != NULL);
    if (!c) return;
    ENSURE(c->nrbody == 1 && c->nsurf == 2 && c->ntype6 == 1 && c->nfunct == 1 && c->ngrav == 1);
    if (c->nrbody == 1) ENSURE(c->rbody[0].mass == 1.0);
    ENSURE(c->run.tend == 1.0 && c->run.dtout == 0.001);
    if (c->ngrav == 1) ENSURE(c->grav[0].dir == 2 && c->grav[0].fscale == -9.81);
    rc_case_free(c);
}

/* ---- Errors: numbers ---------------------------------------------------- */

static void test_case_error_bad_real(void)
{
    EXPECT_INPUT_ERROR("badreal.rad",
                       "/RBODY/7\nball\n"
                       "         1         0         0         0             1.2.3\n"
                       "1,1,1\n0,0,0\n" RUN_CARD,
                       3, "card /RBODY/7", "field Mass", "expected a finite real number",
                       "\"1.2.3\"");
}

static void test_case_error_letterless_exponent(void)
{
    EXPECT_INPUT_ERROR("fexp.rad", "/FUNCT/2\nf\n0,0\n1.5-3,1\n" RUN_CARD, 4, "card /FUNCT/2",
                       "field X", "\"1.5-3\"");
}

static void test_case_error_huge_integer(void)
{
    EXPECT_INPUT_ERROR("hugeint.rad", "/NODE\n9999999999,0,0,0\n" RUN_CARD, 2, "card /NODE",
                       "field node_ID", "2147483647", "\"9999999999\"");
    EXPECT_INPUT_ERROR("hugeid.rad", "/RBODY/99999999999\nb\n1,,,,1\n1,1,1\n0,0,0\n" RUN_CARD, 1,
                       "card /RBODY/99999999999", "id larger than 2147483647");
    EXPECT_INPUT_ERROR("intreal.rad", "/NODE\n1.0,0,0,0\n" RUN_CARD, 2, "field node_ID",
                       "expected an integer", "\"1.0\"");
}

static void test_case_error_nan_inf(void)
{
    EXPECT_INPUT_ERROR("nan.rad", "/NODE\n1,nan,0,0\n" RUN_CARD, 2, "card /NODE", "field X",
                       "finite", "\"nan\"");
    EXPECT_INPUT_ERROR("inf.rad", "/NODE\n1,0,-inf,0\n" RUN_CARD, 2, "field Y", "\"-inf\"");
    EXPECT_INPUT_ERROR("overflow.rad", "/NODE\n1,0,0,1e999\n" RUN_CARD, 2, "field Z", "finite",
                       "\"1e999\"");
}

/* ---- Errors: lines and layout ------------------------------------------ */

static void test_case_error_missing_line(void)
{
    EXPECT_INPUT_ERROR("missline.rad", "/RBODY/1\nball\n1,,,,1\n" RUN_CARD, 1, "card /RBODY/1",
                       "expected 3 data lines (node_ID..., Jxx Jyy Jzz, Jxy Jyz Jxz[, Ioptoff Iexpams "
                       "Ifail[, FN FT expN expT]]), found 1");
    EXPECT_INPUT_ERROR("notitle.rad", "/FUNCT/4\n" RUN_CARD, 1, "card /FUNCT/4", "title line");
}

static void test_case_error_extra_line(void)
{
    EXPECT_INPUT_ERROR("extraline.rad", "/RUN\n1.0\n2.0\n", 3, "card /RUN",
                       "unexpected data line");
}

static void test_case_error_text_after_layout(void)
{
    /* text after the last fixed field is ignored with a warning (test_deck.c) */
    EXPECT_INPUT_ERROR("commas.rad", "/RUN\n1.0,0.01,0,1,5\n", 2, "card /RUN",
                       "at most 4 comma-separated fields");
}

static void test_case_error_tab(void)
{
    EXPECT_INPUT_ERROR("tab.rad", "/RUN\n1.0\t0.01\n", 2, "tab character", "column 4");
}

static void test_case_error_blank_field_used(void)
{
    /* TYPE6 line 3, columns 1-10 (blank in Radioss): ricochet's Istick */
    EXPECT_INPUT_ERROR("skipfield.rad",
                       "/INTER/TYPE6/3\nt\n12,11\n\n7,0,0,0,0,0\n31\n\n\n" RUN_CARD, 5,
                       "card /INTER/TYPE6/3", "field Istick", "{0, 1}", "\"7\"");
    /* line 5, columns 11-20: ricochet's Fric_s, only with Istick = 1 */
    EXPECT_INPUT_ERROR("skipfield.rad",
                       "/INTER/TYPE6/3\nt\n12,11\n,0.3\n\n31\n0,0.5\n\n" RUN_CARD, 7,
                       "card /INTER/TYPE6/3", "field Fric_s", "Istick = 1", "\"0.5\"");
}

static void test_case_error_line_too_long(void)
{
    char text[1200];
    memset(text, ' ', sizeof text);
    memcpy(text, "/RUN\n1.0", 8);
    memcpy(text + 1100, "x\n", 3);
    EXPECT_INPUT_ERROR("long.rad", text, 2, "1096 characters", "at most 1000");
}

static void test_case_error_title_too_long(void)
{
    char text[400];
    snprintf(text, sizeof text, "/FUNCT/1\n%0101d\n0,0\n1,1\n" RUN_CARD, 0);
    EXPECT_INPUT_ERROR("longtitle.rad", text, 2, "card /FUNCT/1", "field title", "at most 100");
}

static void test_case_error_outside_card(void)
{
    EXPECT_INPUT_ERROR("outside.rad", "\n1.0 2.0\n" RUN_CARD, 2, "outside any card");
}

static void test_case_error_binary(void)
{
    static const char junk[] = "/RUN\n1.0\n\x7f" "ELF\x02\x01\x01\x00\x00\x00\x00\x00\x00\x00\x00\x00";
    ENSURE(check_error(tu_tmp_write_n("binary.rad", junk, sizeof junk - 1), RC_EINPUT, 3,
                       "not a text file", (const char *)NULL) == 0);
    static const char nul[] = "/RUN\n1.0\0,0.1\n";
    ENSURE(check_error(tu_tmp_write_n("nul.rad", nul, sizeof nul - 1), RC_EINPUT, 2,
                       "byte 0x00", (const char *)NULL) == 0);
}

static void test_case_error_empty_file(void)
{
    EXPECT_INPUT_ERROR("empty.rad", "", 1, "empty file");
    EXPECT_INPUT_ERROR("onlycomments.rad", "# nothing\n$ here\n\n", 3, "no cards");
    EXPECT_INPUT_ERROR("onlyend.rad", "/END\n/RUN\n1,1\n", 1, "no cards");
}

static void test_case_error_missing_run(void)
{
    EXPECT_INPUT_ERROR("norun.rad", "/FUNCT/1\nf\n0,0\n1,1\n", 4, "no /RUN card",
                       "end time is required");
}

static void test_case_error_main_missing_is_eio(void)
{
    rc_case *c = (rc_case *)1;
    rc_error e;
    rc_error_clear(&e);
    ENSURE(rc_case_load("tests/data/no_such_deck.rad", &c, &e) == RC_EIO);
    ENSURE(c == NULL && e.code == RC_EIO && strstr(e.msg, "tests/data/no_such_deck.rad"));
    /* a directory is no case file: an input error naming it */
    ENSURE(rc_case_load("tests/data", &c, &e) == RC_EINPUT);
    ENSURE(strstr(e.msg, "tests/data") && strstr(e.msg, "not a regular file (a directory)"));
}

/* ---- Errors: cards ------------------------------------------------------ */

static void test_case_error_unknown_card(void)
{
    EXPECT_INPUT_ERROR("unknown.rad", RUN_CARD "/FOO/1\nx\n", 3, "card /FOO/1", "unknown card");
    EXPECT_INPUT_ERROR("planned.rad", RUN_CARD "/SKEW/1\nx\n", 3, "card /SKEW/1",
                       "not supported yet");
    EXPECT_INPUT_ERROR("subtype.rad", RUN_CARD "/SURF/GRSHEL/1\nx\n", 3, "card /SURF/GRSHEL/1",
                       "not supported yet", "/SURF/PLANE");
    EXPECT_INPUT_ERROR("nosub.rad", RUN_CARD "/INTER/5\nx\n", 3, "card /INTER/5", "missing subtype",
                       "/INTER/TYPE6");
    /* misspellings: "did you mean"; a Radioss card ricochet does not read
     * (TYPE12, BOX2), however close to a supported one, is "not supported yet" */
    EXPECT_INPUT_ERROR("typo.rad", RUN_CARD "/INTER/TYP6/1\nx\n", 3, "card /INTER/TYP6/1", "no such card",
                       "did you mean /INTER/TYPE6?");
    EXPECT_INPUT_ERROR("typo.rad", RUN_CARD "/RBOD/1\nx\n", 3, "card /RBOD/1", "unknown card", "did you mean /RBODY?");
    EXPECT_INPUT_ERROR("typo.rad", RUN_CARD "/JOINT/REVOLUT/1\nx\n", 3, "did you mean /JOINT/REVOLUTE?");
    EXPECT_INPUT_ERROR("type12.rad", RUN_CARD "/INTER/TYPE12/1\nx\n", 3, "card /INTER/TYPE12/1", "not supported yet");
    EXPECT_INPUT_ERROR("box2.rad", RUN_CARD "/SURF/BOX2/1\nx\n", 3, "card /SURF/BOX2/1", "not supported yet");
    EXPECT_INPUT_ERROR("badhdr.rad", RUN_CARD "/RBODY/x/1\nx\n", 3, "card /RBODY/x/1",
                       "unexpected keyword /X");
    EXPECT_INPUT_ERROR("noid.rad", RUN_CARD "/RBODY\nx\n", 3, "card /RBODY", "field rbody_ID",
                       "positive integer id");
    EXPECT_INPUT_ERROR("unitid.rad", RUN_CARD "/FUNCT/1/2\nf\n0,0\n1,1\n", 3, "card /FUNCT/1/2",
                       "field unit_ID", "no /UNIT/2 in the deck");
}

static void test_case_error_duplicate_id(void)
{
    EXPECT_INPUT_ERROR("dup.rad",
                       "/RBODY/7\na\n1,,,,1\n1,1,1\n0,0,0\n"
                       "/FUNCT/7\nf\n0,0\n1,1\n" /* another kind: fine */
                       "/RBODY/7\nb\n2,,,,1\n1,1,1\n0,0,0\n" RUN_CARD,
                       10, "card /RBODY/7", "field rbody_ID", "duplicate id 7",
                       "dup.rad:1");
    EXPECT_INPUT_ERROR("dupnode.rad", "/NODE\n5,0,0,0\n6,0,0,0\n/NODE\n6,1,1,1\n" RUN_CARD, 5,
                       "card /NODE", "field node_ID", "duplicate id 6", "dupnode.rad:3");
    EXPECT_INPUT_ERROR("dupsurf.rad",
                       "/SURF/PLANE/3\np\n0,0,0\n0,0,1\n/SURF/ELLIPS/3\ns\n\n0,0,0\n1,1,1\n" RUN_CARD,
                       5, "card /SURF/ELLIPS/3", "duplicate id 3", "dupsurf.rad:1");
    EXPECT_INPUT_ERROR("duprun.rad", RUN_CARD RUN_CARD, 3, "card /RUN", "only one",
                       "duprun.rad:1");
}

static void test_case_error_negative_mass(void)
{
    EXPECT_INPUT_ERROR("negmass.rad", "/RBODY/2\nb\n1,,,,-0.0371\n1,1,1\n0,0,0\n" RUN_CARD, 3,
                       "card /RBODY/2", "field Mass", "non-negative", "\"-0.0371\"");
    EXPECT_INPUT_ERROR("nomass.rad", "/RBODY/2\nb\n1,,,,kg\n1,1,1\n0,0,0\n" RUN_CARD, 3, "field Mass",
                       "\"kg\"");
    EXPECT_INPUT_ERROR("negjxx.rad", "/RBODY/2\nb\n1,,,,1\n-1,1,1\n0,0,0\n" RUN_CARD, 4,
                       "field Jxx", "non-negative");
}

static void test_case_error_rbody_unsupported(void)
{
    EXPECT_INPUT_ERROR("icog.rad", "/RBODY/2\nb\n1,,,,1,,,5\n1,1,1\n0,0,0\n" RUN_CARD, 3,
                       "field ICoG", "\"5\"");
    EXPECT_INPUT_ERROR("ifail.rad", "/RBODY/2\nb\n1,,,,1\n1,1,1\n0,0,0\n0,0,2\n" RUN_CARD, 6,
                       "field Ifail", "\"2\"");
    EXPECT_INPUT_ERROR("line5.rad", "/RBODY/2\nb\n1,,,,1\n1,1,1\n0,0,0\n0,0,0\n1e3\n" RUN_CARD, 7,
                       "card /RBODY/2", "follows Ifail = 1 only");
    EXPECT_INPUT_ERROR("ispher.rad", "/RBODY/2\nb\n1,,,7,1\n1,1,1\n0,0,0\n" RUN_CARD, 3,
                       "field Ispher", "expected an integer in {0, 1, 2, 3}");
}

static void test_case_error_funct(void)
{
    EXPECT_INPUT_ERROR("nonmono.rad", "/FUNCT/5\nf\n0,0\n0.0371,1\n0.0371,2\n" RUN_CARD, 5,
                       "card /FUNCT/5", "field X", "not a function", "\"0.0371\"", "line 4");
    EXPECT_INPUT_ERROR("onepoint.rad", "/FUNCT/5\nf\n0,0\n\n\n" RUN_CARD, 1, "card /FUNCT/5",
                       "field X", "not a function", "at least 2 points", "found 1");
}

/* The six TYPE6 lines with one field replaced: line k (1..6) = text. */
static const char *type6_deck(const char *name, int k, const char *text)
{
    const char *def[6] = {"12,11", "", "", "31", "", ""};
    char deck[1024];
    int n = snprintf(deck, sizeof deck, "/INTER/TYPE6/3\ncontact\n");
    for (int i = 0; i < 6; i++)
        n += snprintf(deck + n, sizeof deck - (size_t)n, "%s\n", i + 1 == k ? text : def[i]);
    snprintf(deck + n, sizeof deck - (size_t)n, RUN_CARD);
    return tu_tmp_write(name, deck);
}

#define EXPECT_T6(k, text, ...) \
    ENSURE(check_error(type6_deck("t6.rad", (k), (text)), RC_EINPUT, (k) + 2, "card /INTER/TYPE6/3", __VA_ARGS__, (const char *)NULL) == 0)

static void test_case_error_type6(void)
{
    /* unsupported but valid Radioss values */
    EXPECT_T6(2, ",-0.1", "field Fric", "non-negative");
    EXPECT_T6(2, "-0.5", "field Sfric", "non-negative");
    EXPECT_T6(3, ",3", "field IRS", "expected an integer in {0, 1, 2}");
    EXPECT_T6(3, ",,,,-4", "field fct_IDff", "non-negative");
    /* Iform 1, 2 with Stiff = 0 read as Iform 0 with a warning (test_deck.c) */
    EXPECT_T6(5, ",,-1e5", "field Stiff", "non-negative");
    /* invalid values */
    EXPECT_T6(4, "31,7", "field Iform", "expected an integer in {0, 1, 2}", "\"7\"");
    EXPECT_T6(3, ",,,3", "field Inacti", "expected an integer in {0, 5}");
    EXPECT_T6(2, ",,-0.0371", "field Gap", "non-negative", "\"-0.0371\"");
    EXPECT_T6(2, ",,,0.5,0.25", "field Tstop", "Tstart", "\"0.25\"");
    EXPECT_T6(4, "31,,-0.0371", "field Ascalex", "positive");
    EXPECT_T6(3, ",,,,,,-1", "field Ascalef", "positive");
    EXPECT_T6(6, "-37", "field Visc", "non-negative");
    EXPECT_T6(4, "", "field fct_IDld", "positive", "got blank");
    EXPECT_T6(1, "12", "field surf_ID2", "positive");
}

static void test_case_error_surfaces(void)
{
    EXPECT_INPUT_ERROR("plane.rad", "/SURF/PLANE/1\np\n0.0371,0,1\n0.0371,0,1\n" RUN_CARD, 4,
                       "card /SURF/PLANE/1", "field XM1 YM1 ZM1", "different from M");
    EXPECT_INPUT_ERROR("ellips.rad", "/SURF/ELLIPS/1\ne\n\n0,0,0\n0.05,0.05,0.06\n" RUN_CARD, 5,
                       "card /SURF/ELLIPS/1", "field c", "not supported yet (only spheres");
    EXPECT_INPUT_ERROR("ellipsn.rad", "/SURF/ELLIPS/1\ne\n0,4\n0,0,0\n1,1,1\n" RUN_CARD, 3,
                       "field n", "not supported yet (only spheres");
    EXPECT_INPUT_ERROR("ellipsa.rad", "/SURF/ELLIPS/1\ne\n\n0,0,0\n0,1,1\n" RUN_CARD, 5,
                       "field a", "positive");
    EXPECT_INPUT_ERROR("ellskew.rad", "/SURF/ELLIPS/1\ne\n2\n0,0,0\n1,1,1\n" RUN_CARD, 3,
                       "field skew_ID", "not supported yet");
}

static void test_case_error_begin_units(void)
{
    /* work units other than the input units are reported, not an error;
     * an unknown unit name is one */
    EXPECT_INPUT_ERROR("units.rad",
                       "/BEGIN\nrun\n2022,0\nkg,m,s\nkg,furlong,s\n" RUN_CARD, 5, "card /BEGIN",
                       "field Work_length_unit", "expected a unit name", "\"furlong\"");
}

static void test_case_error_grav_bcs_inivel(void)
{
    EXPECT_INPUT_ERROR("gravdir.rad", "/GRAV/1\ng\n0,W\n" RUN_CARD, 3, "card /GRAV/1", "field DIR",
                       "X, Y or Z", "\"W\"");
    EXPECT_INPUT_ERROR("gravsens.rad", "/GRAV/1\ng\n0,Z,0,-4\n" RUN_CARD, 3, "field sensor_ID", "-4");
    EXPECT_INPUT_ERROR("bcs.rad", "/BCS/1\nb\n   112 000\n" RUN_CARD, 3, "card /BCS/1",
                       "field Trarot", "\"112 000\"");
    EXPECT_INPUT_ERROR("inivel.rad", "/INIVEL/AXIS/1\nv\n0,0,0\n" RUN_CARD, 1,
                       "card /INIVEL/AXIS/1", "not supported yet");
    EXPECT_INPUT_ERROR("iniskew.rad", "/INIVEL/TRA/1\nv\n0,0,1,5,3\n" RUN_CARD, 3,
                       "field skew_ID", "no such skew");
    /* some translations held along a skew's axes are read (model/imposed.h):
     * the skew must exist */
    EXPECT_INPUT_ERROR("bcsskew.rad", "/BCS/1\nb\n   110 000         3\n" RUN_CARD, 3, "card /BCS/1",
                       "field skew_ID", "no such skew");
    EXPECT_INPUT_ERROR("bcsskew.rad", "/BCS/1\nb\n   111 001         3\n" RUN_CARD, 3, "card /BCS/1",
                       "field skew_ID", "holds some rotations about the axes of skew 3", "not supported yet");
    EXPECT_INPUT_ERROR("bcsskew.rad", "/BCS/1\nb\n   111 000         3\n" RUN_CARD, 3, "card /BCS/1",
                       "field skew_ID", "no such skew");
    EXPECT_INPUT_ERROR("gravskew.rad", "/GRAV/1\ng\n0,Z,3\n" RUN_CARD, 3, "card /GRAV/1",
                       "field skew_ID", "expected the id of a /SKEW/FIX", "no such skew");
}

static void test_case_error_run_solver(void)
{
    EXPECT_INPUT_ERROR("tend.rad", "/RUN\n-1.0\n", 2, "card /RUN", "field Tend", "positive");
    EXPECT_INPUT_ERROR("tend0.rad", "/RUN\n\n", 2, "card /RUN", "field Tend", "got blank");
    EXPECT_INPUT_ERROR("dtout.rad", "/RUN\n1,-0.1\n", 2, "field Dt_out", "non-negative");
    EXPECT_INPUT_ERROR("rtol.rad", RUN_CARD "/SOLVER\n,,,-1e-6\n", 4, "card /SOLVER", "field Rtol",
                       "positive");
    EXPECT_INPUT_ERROR("atol.rad", RUN_CARD "/SOLVER\n\n,,-1e-6\n", 5, "field Atol_vel", "non-negative");
    EXPECT_INPUT_ERROR("method.rad", RUN_CARD "/SOLVER\n4\n", 4, "field Method", "{0, 1, 2, 3}");
    EXPECT_INPUT_ERROR("order.rad", RUN_CARD "/SOLVER\n1,6\n", 4, "field Max_order",
                       "{1, 2, 3, 4, 5}");
}

/* ---- /FRICTION, /FRIC_ORIENT, /PART, /GRPART ---------------------------- */

/* Defaults, blank lines, Radioss conventions (Iform 0 = 1, VISF 0 = 1,
 * Xfreq 0 = no filter), the number of groups from the lines. */
static void test_case_friction_defaults(void)
{
    const char *p = tu_tmp_write("fricdef.rad",
                              "/FRICTION/7\n"
                              "\n" /* blank title */
                              "\n" /* Ifric Ifiltr Xfreq Iform */
                              "\n" /* C1..C5 */
                              "\n" /* C6 Fric VISF */
                              "\n" /* after the last line: ignored */
                              "\n"
                              "/FRICTION/8\n"
                              "blank lines inside a group are lines of defaults\n"
                              "         2         1                   0         0\n"
                              "\n"
                              "                   0                0.29                   0\n"
                              "        17                            23\n" /* line 6 */
                              "\n"
                              "\n"
                              "\n" /* ignored */
                              "/FRICTION/9\n"
                              "both a group and a part on side 1\n"
                              "0,3,0.0037\n"
                              "\n"
                              "\n"
                              "3,4,5,,,1\n" /* line 22 */
                              "\n\n\n\n" RUN_CARD);
    rc_case *c = load_ok(p);
    ENSURE(c && c->nfriction == 3);
    if (!c || c->nfriction != 3) { rc_case_free(c); return; }
    const rc_case_friction *a = &c->friction[0], *b = &c->friction[1], *d = &c->friction[2];
    ENSURE(a->id == 7 && a->title[0] == '\0' && a->ifric == 0 && a->ifiltr == 0 &&
           a->xfreq == 1.0 && a->iform == 1 && a->dt_ref == 0 && a->area == 0 && a->npair == 0);
    ENSURE(fricset_is(&a->def, 0, 0, 0, 0, 0, 0, 0, 1));
    /* Xfreq written 0: filter off; Iform 0 means 1 */
    ENSURE(b->ifric == 2 && b->ifiltr == 0 && b->xfreq == 0 && b->iform == 1);
    ENSURE(fricset_is(&b->def, 0, 0, 0, 0, 0, 0, 0.29, 1));
    ENSURE(b->npair == 1);
    if (b->npair == 1) {
        const rc_case_fricpair *q = &b->pair[0];
        ENSURE(q->grpart1 == 17 && q->grpart2 == 0 && q->part1 == 0 && q->part2 == 23 &&
               q->idir == 0 && q->loc.line == 13 && fricset_is(&q->set[0], 0, 0, 0, 0, 0, 0, 0, 1));
    }
    /* Ifiltr 3: a frequency; an orthotropic group of blank sets */
    ENSURE(d->ifiltr == 3 && d->xfreq == 0.0037 && d->npair == 1);
    if (d->npair == 1)
        ENSURE(d->pair[0].idir == 1 && d->pair[0].grpart1 == 3 && d->pair[0].part1 == 5 &&
               d->pair[0].loc.line == 22 && d->pair[0].set[1].visf == 1);
    /* part_ID1 beside grpart_ID1: a warning (Radioss ignores the part) */
    ENSURE(c->nwarnings == 1);
    if (c->nwarnings == 1)
        ENSURE(strstr(c->warnings[0], "fricdef.rad:22:") && strstr(c->warnings[0], "/FRICTION/9") &&
               strstr(c->warnings[0], "part_ID1 = 5 ignored") &&
               strstr(c->warnings[0], "grpart_ID1 = 3"));
    rc_case_free(c);

    /* the Renard checks apply to Ifric 3 only */
    c = load_ok(tu_tmp_write("fricnorenard.rad", "/FRICTION/1\nf\n2\n0.9,0.8,0.1,0.95,-1\n-2\n" RUN_CARD));
    ENSURE(c && c->nfriction == 1 && c->friction[0].def.c[4] == -1);
    rc_case_free(c);
}

/* /FRICTION header part: A = Ifric Ifiltr Xfreq Iform, B = C1..C5, C = C6 Fric VISF. */
#define FRIC(a, b, c) "/FRICTION/5\nf\n" a "\n" b "\n" c "\n"
/* A valid Renard set (C1..C5 and C6). */
#define RENARD_B "0.31,0.23,0.41,0.17,0.0137"
#define RENARD_C "0.371"

static void test_case_error_friction_header(void)
{
    EXPECT_INPUT_ERROR("fr.rad", FRIC("4", "", "") RUN_CARD, 3, "card /FRICTION/5", "field Ifric",
                       "expected an integer in {0, 1, 2, 3}", "\"4\"");
    EXPECT_INPUT_ERROR("fr.rad", FRIC("0,4", "", "") RUN_CARD, 3, "field Ifiltr", "{0, 1, 2, 3}");
    EXPECT_INPUT_ERROR("fr.rad", FRIC("0,0,,4", "", "") RUN_CARD, 3, "field Iform", "{0, 1, 2, 3}",
                       "\"4\"");
    EXPECT_INPUT_ERROR("fr.rad", FRIC("0,1,1.0371", "", "") RUN_CARD, 3, "card /FRICTION/5",
                       "field Xfreq", "in [0, 1] for Ifiltr = 1", "\"1.0371\"");
    EXPECT_INPUT_ERROR("fr.rad", FRIC("0,2,-0.0371", "", "") RUN_CARD, 3, "field Xfreq",
                       "in [0, 1] for Ifiltr = 2", "\"-0.0371\"");
    EXPECT_INPUT_ERROR("fr.rad", FRIC("0,3,0", "", "") RUN_CARD, 3, "field Xfreq",
                       "cut-off frequency > 0 [Hz] for Ifiltr = 3", "\"0\"");
    EXPECT_INPUT_ERROR("fr.rad", FRIC("0,3,-13.7", "", "") RUN_CARD, 3, "field Xfreq", "\"-13.7\"");
    /* Ifiltr 1, 2: the reference step of ricochet's continuous filter */
    EXPECT_INPUT_ERROR("fr.rad", FRIC("0,1,0.371", "", "") RUN_CARD, 3, "card /FRICTION/5",
                       "field Dt_ref", "Ifiltr = 1", "reference step Dt_ref > 0 [s]", "got blank");
    EXPECT_INPUT_ERROR("fr.rad", FRIC("0,2,0.0371,,-1e-5", "", "") RUN_CARD, 3, "field Dt_ref",
                       "non-negative", "\"-1e-5\"");
    EXPECT_INPUT_ERROR("fr.rad", FRIC("0,2,0.0371,,0", "", "") RUN_CARD, 3, "field Dt_ref",
                       "Ifiltr = 2", "got \"0\"");
    EXPECT_INPUT_ERROR("fr.rad", FRIC("0,0,,,,-0.0137", "", "") RUN_CARD, 3, "field Area",
                       "non-negative", "\"-0.0137\"");
    EXPECT_INPUT_ERROR("fr.rad", FRIC("", "", "0,-0.0371") RUN_CARD, 5, "field Fric",
                       "non-negative", "\"-0.0371\"");
    EXPECT_INPUT_ERROR("fr.rad", FRIC("", "", "0,0,-1.37") RUN_CARD, 5, "field VISF",
                       "non-negative");
    EXPECT_INPUT_ERROR("fr.rad", FRIC("", "", "0,0,0,7") RUN_CARD, 5, "card /FRICTION/5",
                       "at most 3 comma-separated fields");
    EXPECT_INPUT_ERROR("fr.rad", "/FRICTION/5\nf\n3\n\n" RUN_CARD, 1, "card /FRICTION/5",
                       "expected 3 data lines", "found 2");
    EXPECT_INPUT_ERROR("fr.rad", "/FRICTION/5/2\nf\n\n\n\n" RUN_CARD, 1, "field unit_ID",
                       "no /UNIT/2");
    EXPECT_INPUT_ERROR("fr.rad", "/FRICTION\nf\n\n\n\n" RUN_CARD, 1, "field fric_ID",
                       "positive integer id");
    EXPECT_INPUT_ERROR("frdup.rad", FRIC("", "", "") FRIC("1", "", "") RUN_CARD, 6,
                       "card /FRICTION/5", "field fric_ID", "duplicate id 5", "frdup.rad:1");
}

static void test_case_error_friction_renard(void)
{
    /* each inequality, on the default set (line 4: C1..C5) */
    EXPECT_INPUT_ERROR("rn.rad", FRIC("3", "0.31,0.23,0.41,0.17", RENARD_C) RUN_CARD, 4,
                       "card /FRICTION/5", "field C5",
                       "expected 0 < C5 < C6 = 0.371 (Renard: 0 < V_cr1 < V_cr2), got blank");
    EXPECT_INPUT_ERROR("rn.rad", FRIC("3", "0.31,0.23,0.41,0.17,-0.0137", RENARD_C) RUN_CARD, 4,
                       "field C5", "0 < C5", "\"-0.0137\"");
    EXPECT_INPUT_ERROR("rn.rad", FRIC("3", "0.31,0.23,0.41,0.17,0.7", "0.5") RUN_CARD, 4,
                       "field C5", "expected 0 < C5 < C6 = 0.5 (Renard: 0 < V_cr1 < V_cr2), got \"0.7\"");
    EXPECT_INPUT_ERROR("rn.rad", FRIC("3", "0.31,0.23,0.41,0.17,0.371", RENARD_C) RUN_CARD, 4,
                       "field C5", "C5 < C6 = 0.371", "\"0.371\""); /* equal */
    EXPECT_INPUT_ERROR("rn.rad", FRIC("3", "0.45,0.23,0.41,0.17,0.0137", RENARD_C) RUN_CARD, 4,
                       "field C1", "expected C1 <= C3 = 0.41 (Renard: mu_s <= mu_max), got \"0.45\"");
    EXPECT_INPUT_ERROR("rn.rad", FRIC("3", "0.31,0.43,0.41,0.17,0.0137", RENARD_C) RUN_CARD, 4,
                       "field C2", "expected C2 <= C3 = 0.41 (Renard: mu_d <= mu_max), got \"0.43\"");
    EXPECT_INPUT_ERROR("rn.rad", FRIC("3", "0.31,0.37,0.41,0.33,0.0137", RENARD_C) RUN_CARD, 4,
                       "field C4", "expected C4 <= C1 = 0.31 (Renard: mu_min <= mu_s), got \"0.33\"");
    EXPECT_INPUT_ERROR("rn.rad", FRIC("3", "0.31,0.23,0.41,0.27,0.0137", RENARD_C) RUN_CARD, 4,
                       "field C4", "expected C4 <= C2 = 0.23 (Renard: mu_min <= mu_d), got \"0.27\"");
    /* in a group: direction 1 (line 7) and direction 2 (line 9) */
    EXPECT_INPUT_ERROR("rn.rad",
                       FRIC("3", RENARD_B, RENARD_C) "3,4,,,,1\n0.5,0.23,0.41,0.17,0.0137\n"
                       RENARD_C "\n" RENARD_B "\n" RENARD_C "\n" RUN_CARD,
                       7, "card /FRICTION/5", "field C1", "C1 <= C3 = 0.41", "\"0.5\"");
    EXPECT_INPUT_ERROR("rn.rad",
                       FRIC("3", RENARD_B, RENARD_C) "3,4,,,,1\n" RENARD_B "\n" RENARD_C "\n"
                       "0.31,0.23,0.41,0.17,0.0137\n0.01\n" RUN_CARD,
                       9, "card /FRICTION/5", "field C5", "C5 < C6 = 0.01", "\"0.0137\"");
    /* and a valid Renard deck with both directions loads */
    rc_case *c = load_ok(tu_tmp_write("rn.rad", FRIC("3", RENARD_B, RENARD_C) "3,4,,,,1\n" RENARD_B
                                   "\n" RENARD_C "\n" RENARD_B "\n" RENARD_C "\n" RUN_CARD));
    ENSURE(c && c->friction[0].npair == 1 && c->friction[0].pair[0].set[1].c[5] == 0.371);
    rc_case_free(c);
}

static void test_case_error_friction_groups(void)
{
    /* truncated groups: the message names the missing line (group at line 6) */
    EXPECT_INPUT_ERROR("fg.rad", FRIC("", "", "") "3,4\n" RUN_CARD, 6, "card /FRICTION/5",
                       "field C1 C2 C3 C4 C5", "part-pair group 1 (Idir = 0",
                       "expected 3 lines, found 1", "missing line 2 of the group (C1 C2 C3 C4 C5)");
    EXPECT_INPUT_ERROR("fg.rad", FRIC("", "", "") "3,4\n0.1\n" RUN_CARD, 6, "field C6 Fric VISF",
                       "missing line 3 of the group (C6 Fric VISF)");
    /* blank lines count as lines of the group */
    EXPECT_INPUT_ERROR("fg.rad", FRIC("", "", "") "3,4,,,,1\n\n\n" RUN_CARD, 6,
                       "field C1 C2 C3 C4 C5", "(Idir = 1", "expected 5 lines, found 3",
                       "missing line 4 of the group (direction 2: C1 C2 C3 C4 C5)");
    EXPECT_INPUT_ERROR("fg.rad", FRIC("", "", "") "3,4\n\n\n,,7,8,,1\n\n\n\n" RUN_CARD, 9,
                       "part-pair group 2 (Idir = 1", "found 4",
                       "missing line 5 of the group (direction 2: C6 Fric VISF)");
    /* each side needs a group or a part */
    EXPECT_INPUT_ERROR("fg.rad", FRIC("", "", "") "3\n\n\n" RUN_CARD, 6, "card /FRICTION/5",
                       "field grpart_ID2 part_ID2", "side 2 of part-pair group 1",
                       "got both blank or 0");
    EXPECT_INPUT_ERROR("fg.rad", FRIC("", "", "") "3,4\n\n\n0,4,0,9\n\n\n" RUN_CARD, 9,
                       "field grpart_ID1 part_ID1", "side 1 of part-pair group 2");
    EXPECT_INPUT_ERROR("fg.rad", FRIC("", "", "") "\n3,4\n\n\n" RUN_CARD, 6,
                       "field grpart_ID1 part_ID1", "side 1");
    /* Idir, the unused columns, ids */
    EXPECT_INPUT_ERROR("fg.rad", FRIC("", "", "") "3,4,,,,2\n\n\n" RUN_CARD, 6, "field Idir",
                       "expected an integer in {0, 1}", "\"2\"");
    EXPECT_INPUT_ERROR("fg.rad", FRIC("", "", "") "3,4,,,7\n\n\n" RUN_CARD, 6, "field blank",
                       "\"7\"");
    EXPECT_INPUT_ERROR("fg.rad", FRIC("", "", "") "3,4,-5\n\n\n" RUN_CARD, 6, "field part_ID1",
                       "non-negative");
    EXPECT_INPUT_ERROR("fg.rad", FRIC("", "", "") "3,4\n\n,-0.5\n" RUN_CARD, 8, "field Fric",
                       "non-negative");
}

static void test_case_error_fric_orient(void)
{
    /* V = (0, 0, 0) reads as (1, 0, 0) with a warning (test_deck.c) */
    EXPECT_INPUT_ERROR("fo.rad", "/FRIC_ORIENT/3\no\n3\n1,0,0,7\n" RUN_CARD, 4,
                       "card /FRIC_ORIENT/3", "field skew_ID", "expected the id of a /SKEW/FIX", "got 7",
                       "no such skew");
    /* a moving skew: refused */
    EXPECT_INPUT_ERROR("fo.rad",
                       "/NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n/SKEW/MOV/7\nm\n1,2,3,X\n"
                       "/FRIC_ORIENT/3\no\n3\n1,0,0,7\n" RUN_CARD, 11,
                       "card /FRIC_ORIENT/3", "field skew_ID", "/SKEW/MOV/7 moves with its nodes",
                       "not supported yet");
    /* a /SKEW/FIX: V is its X' axis, VX VY VZ unused (here 0: no warning) */
    {
        const char *p = tu_tmp_write("fos.rad", "/SKEW/FIX/7\ns\n0,0,0\n0,0,1\n3,-4,0\n"
                                                "/FRIC_ORIENT/3\no\n3\n0,0,0,7,30\n,4\n1,2,0\n" RUN_CARD);
        rc_case *c = load_ok(p);
        ENSURE(c != NULL);
        if (c) {
            /* Y' = z, X' = Y' x (3, -4, 0)/5 = (0.8, 0.6, 0) */
            const rc_case_fricorient_item *it = c->fricorient[0].item;
            ENSURE(c->nwarnings == 0);
            ENSURE_NEAR(it[0].v[0], 0.8, 1e-15, 0);
            ENSURE_NEAR(it[0].v[1], 0.6, 1e-15, 0);
            ENSURE_NEAR(it[0].v[2], 0.0, 0, 1e-15);
            ENSURE(it[0].skew_id == 7 && it[0].phi == 30);
            ENSURE(it[1].skew_id == 0 && it[1].v[0] == 1 && it[1].v[1] == 2);
            rc_case_free(c);
        }
    }
    EXPECT_INPUT_ERROR("fo.rad", "/FRIC_ORIENT/3\no\n3\n1,0,0,,,2\n" RUN_CARD, 4, "field Iorth",
                       "expected an integer in {0, 1}");
    EXPECT_INPUT_ERROR("fo.rad", "/FRIC_ORIENT/3\no\n3\n1,0,0\n0,0\n0,1,0\n" RUN_CARD, 5,
                       "field grpart_ID part_ID", "orientation 2", "got both blank or 0");
    EXPECT_INPUT_ERROR("fo.rad", "/FRIC_ORIENT/3\no\n3\n1,0,0\n,4\n" RUN_CARD, 5,
                       "field VX VY VZ", "orientation 2", "truncated", "missing its line 2");
    EXPECT_INPUT_ERROR("fo.rad", "/FRIC_ORIENT/3\no\n\n\n" RUN_CARD, 1, "card /FRIC_ORIENT/3",
                       "at least one orientation");
    EXPECT_INPUT_ERROR("fo.rad", "/FRIC_ORIENT/3\no\n3\n1,0,nan\n" RUN_CARD, 4, "field VZ",
                       "\"nan\"");
    EXPECT_INPUT_ERROR("fodup.rad",
                       "/FRIC_ORIENT/3\no\n3\n1,0,0\n/FRIC_ORIENT/3\np\n,4\n0,0,1\n" RUN_CARD, 5,
                       "card /FRIC_ORIENT/3", "field fric_orient_ID", "duplicate id 3");
}

static void test_case_error_part_grpart(void)
{
    /* the Radioss line is required; ricochet's line 2 is optional */
    EXPECT_INPUT_ERROR("pt.rad", "/PART/4\np\n" RUN_CARD, 1, "card /PART/4", "field prop_ID",
                       "found 0");
    EXPECT_INPUT_ERROR("pt.rad", "/PART/4\np\n\n0\n" RUN_CARD, 4, "card /PART/4", "field rbody_ID",
                       "at least one surface id", "got \"0\"");
    EXPECT_INPUT_ERROR("pt.rad", "/PART/4\np\n\n\n\n" RUN_CARD, 1, "field prop_ID", "found 0");
    EXPECT_INPUT_ERROR("pt.rad", "/PART/4\np\n\n7,12,-3\n" RUN_CARD, 4, "field surf_ID",
                       "non-negative", "\"-3\"");
    EXPECT_INPUT_ERROR("pt.rad", "/PART/4\np\n\n7\n1,2,3,4,5,6,7,8,9,10,11\n" RUN_CARD, 5,
                       "card /PART/4", "at most 10 comma-separated fields");
    EXPECT_INPUT_ERROR("pt.rad", "/PART/4\np\nsteel\n7\n" RUN_CARD, 3, "field prop_ID",
                       "expected an integer", "\"steel\"");
    EXPECT_INPUT_ERROR("pt.rad", "/PART/4\np\n,,,1.2.3\n7\n" RUN_CARD, 3, "field Thick");
    EXPECT_INPUT_ERROR("ptdup.rad", "/PART/4\np\n\n7\n/PART/4\nq\n\n8\n" RUN_CARD, 5,
                       "card /PART/4", "field part_ID", "duplicate id 4", "ptdup.rad:1");
    /* /GRPART: PART and GRPART; the other subtypes are refused */
    EXPECT_INPUT_ERROR("gp.rad", "/GRPART/BOX/3\ng\n1\n" RUN_CARD, 1, "card /GRPART/BOX/3",
                       "not supported yet", "/GRPART/PART", "/GRPART/GRPART");
    EXPECT_INPUT_ERROR("gp.rad", "/GRPART/GRPART/3\ng\n1\n" RUN_CARD, 3, "card /GRPART/GRPART/3",
                       "field grpart_ID", "no such group");
    EXPECT_INPUT_ERROR("gp.rad", "/GRPART/GRPART/3\ng\n3\n" RUN_CARD, 3, "card /GRPART/GRPART/3",
                       "names itself");
    EXPECT_INPUT_ERROR("gp.rad",
                       "/GRPART/GRPART/3\ng\n4\n/GRPART/GRPART/4\nh\n5\n/GRPART/GRPART/5\ni\n\n3\n" RUN_CARD,
                       10, "card /GRPART/GRPART/5", "form a cycle");
    EXPECT_INPUT_ERROR("gp.rad", "/GRPART/3\ng\n1\n" RUN_CARD, 1, "missing subtype",
                       "/GRPART/PART");
    EXPECT_INPUT_ERROR("gp.rad", "/GRPART/PART/3\ng\n1,-2\n" RUN_CARD, 3, "card /GRPART/PART/3",
                       "field part_ID", "non-negative");
    EXPECT_INPUT_ERROR("gpdup.rad", "/GRPART/PART/3\ng\n1\n/GRPART/PART/3\nh\n2\n" RUN_CARD, 4,
                       "field grpart_ID", "duplicate id 3");
    /* /GRPART/GRPART: the union of its groups (nested ones too), each part once,
     * in the order first met; the plain groups are unchanged */
    rc_case *c = load_ok(tu_tmp_write("gpgp.rad", "/GRPART/GRPART/9\nall\n8,2\n/GRPART/PART/2\na\n11,12\n"
                                         "/GRPART/GRPART/8\nnested\n\n7\n/GRPART/PART/7\nb\n12,13,14\n" RUN_CARD));
    ENSURE(c && c->ngrpart == 4);
    if (c && c->ngrpart == 4) {
        const rc_case_grpart *g = &c->grpart[0], *h = &c->grpart[2];
        ENSURE(g->by_group && g->n == 4 && g->parts[0] == 12 && g->parts[1] == 13 && g->parts[2] == 14 &&
               g->parts[3] == 11);
        ENSURE(h->by_group && h->n == 3 && h->parts[0] == 12 && h->parts[2] == 14);
        ENSURE(g->part_loc && g->part_loc[0].line == 3 && g->part_loc[3].line == 3);
        ENSURE(!c->grpart[1].by_group && c->grpart[1].n == 2);
    }
    rc_case_free(c);
    /* a part id and a part group id may coincide: separate id spaces */
    c = load_ok(tu_tmp_write("ptgp.rad", "/PART/3\np\n\n7\n/GRPART/PART/3\ng\n3\n" RUN_CARD));
    ENSURE(c && c->npart == 1 && c->ngrpart == 1 && c->nwarnings == 0);
    rc_case_free(c);
}

/* ---- Robustness --------------------------------------------------------- */

/* Load and check the contract: OK, or an input error with a message that
 * starts with the path; never a crash (valgrind/ASan watch the rest). */
static int load_any(const char *path)
{
    rc_case *c = NULL;
    rc_error e;
    rc_error_clear(&e);
    rc_status st = rc_case_load(path, &c, &e);
    if (st == RC_OK) {
        int ok = c != NULL;
        rc_case_free(c);
        return ok;
    }
    return st == RC_EINPUT && c == NULL && strncmp(e.msg, path, strlen(path)) == 0;
}

static void test_case_robust_truncated_and_mutated(void)
{
    FILE *f = fopen("tests/data/full_fixed.rad", "rb");
    static char deck[8192], buf[8192];
    size_t n = f ? fread(deck, 1, sizeof deck, f) : 0;
    if (f) fclose(f);
    ENSURE(n > 1000);
    int bad = 0;
    /* every truncation */
    for (size_t k = 0; k < n; k += 7)
        bad += !load_any(tu_tmp_write_n("trunc.rad", deck, k));
    /* random byte mutations (deterministic LCG) */
    uint32_t seed = 0x0371u;
    static const char alphabet[] = " ,./-+0123456789eEdD\t\r\n#$\0\xff" "ZX";
    for (int it = 0; it < 1500; it++) {
        memcpy(buf, deck, n);
        for (int m = 0; m < 1 + it % 4; m++) {
            seed = seed * 1664525u + 1013904223u;
            size_t pos = (seed >> 8) % n;
            seed = seed * 1664525u + 1013904223u;
            buf[pos] = alphabet[(seed >> 8) % (sizeof alphabet - 1)];
        }
        bad += !load_any(tu_tmp_write_n("mut.rad", buf, n));
    }
    ENSURE(bad == 0);
}

void suite_case(void);
void suite_case(void)
{
    RUN_TEST(test_case_full_deck_fixed);
    RUN_TEST(test_case_full_deck_comma_equals_fixed);
    RUN_TEST(test_case_fortran_reals);
    RUN_TEST(test_case_defaults);
    RUN_TEST(test_case_blank_line_is_data);
    RUN_TEST(test_case_comments_and_end);
    RUN_TEST(test_case_ignored_cards_warn);
    RUN_TEST(test_case_checksum);
    RUN_TEST(test_case_include_relative);
    RUN_TEST(test_case_include_cycle);
    RUN_TEST(test_case_include_missing);
    RUN_TEST(test_case_include_depth_limit);
    RUN_TEST(test_case_docs_example);
    RUN_TEST(test_case_error_bad_real);
    RUN_TEST(test_case_error_letterless_exponent);
    RUN_TEST(test_case_error_huge_integer);
    RUN_TEST(test_case_error_nan_inf);
    RUN_TEST(test_case_error_missing_line);
    RUN_TEST(test_case_error_extra_line);
    RUN_TEST(test_case_error_text_after_layout);
    RUN_TEST(test_case_error_tab);
    RUN_TEST(test_case_error_blank_field_used);
    RUN_TEST(test_case_error_line_too_long);
    RUN_TEST(test_case_error_title_too_long);
    RUN_TEST(test_case_error_outside_card);
    RUN_TEST(test_case_error_binary);
    RUN_TEST(test_case_error_empty_file);
    RUN_TEST(test_case_error_missing_run);
    RUN_TEST(test_case_error_main_missing_is_eio);
    RUN_TEST(test_case_error_unknown_card);
    RUN_TEST(test_case_error_duplicate_id);
    RUN_TEST(test_case_error_negative_mass);
    RUN_TEST(test_case_error_rbody_unsupported);
    RUN_TEST(test_case_error_funct);
    RUN_TEST(test_case_error_type6);
    RUN_TEST(test_case_error_surfaces);
    RUN_TEST(test_case_error_begin_units);
    RUN_TEST(test_case_error_grav_bcs_inivel);
    RUN_TEST(test_case_error_run_solver);
    RUN_TEST(test_case_friction_defaults);
    RUN_TEST(test_case_error_friction_header);
    RUN_TEST(test_case_error_friction_renard);
    RUN_TEST(test_case_error_friction_groups);
    RUN_TEST(test_case_error_fric_orient);
    RUN_TEST(test_case_error_part_grpart);
    RUN_TEST(test_case_robust_truncated_and_mutated);
    tu_tmp_cleanup();
}
