/* The root functions given to the integrators (solver/rootmap.c): the live
 * list of each interface from its configuration (model.h rc_roots_live),
 * and runs with the compact list against runs with every root function:
 * the same events (time, kind, element, values) and the same final state,
 * bit for bit, on both backends. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "model/model.h"
#include "solver/integrator.h"
#include "solver/solver.h"
#include "testutil.h"
#include "engine/assembly/assembly.h"
#include "engine/events/events.h"

/* 1 when interface i's root k is in the live list */
static int is_live(const int *live, int n, int i, int k)
{
    for (int j = 0; j < n; j++)
        if (live[j] == RC_ROOTS_PER_INTER * i + k) return 1;
    return 0;
}

/* Run m on solver s with compaction on and off: the same events and state. */
static void same_runs(const rc_model *m, const rc_solver *s, const char *what)
{
    const int ny = m->ny;
    double *ya = calloc((size_t)ny, sizeof(double)), *yb = calloc((size_t)ny, sizeof(double));
    tu_evlog *la = calloc(1, sizeof *la), *lb = calloc(1, sizeof *lb);
    ENSURE(ya && yb && la && lb);
    if (!ya || !yb || !la || !lb) goto out;
    rc_error e;
    rc_stats sa, sb;
    rc_run_options oa = {.y_end = ya, .on_event = tu_evlog_event, .user = la};
    rc_run_options ob = {.y_end = yb, .on_event = tu_evlog_event, .user = lb};
    rc_rootmap_set_compact(1);
    ENSURE(s->run(m, &oa, NULL, NULL, &sa, &e) == RC_OK);
    rc_rootmap_set_compact(0);
    ENSURE(s->run(m, &ob, NULL, NULL, &sb, &e) == RC_OK);
    rc_rootmap_set_compact(1);
    printf("    %s, %s: %d events, %ld / %ld steps (compact / all roots)\n", what, s->name, la->n, sa.steps, sb.steps);
    ENSURE(la->n > 0 && la->n == lb->n && la->n <= TU_MAXEV);
    ENSURE(sa.steps == sb.steps);
    for (int k = 0; k < la->n && k < lb->n && k < TU_MAXEV; k++) {
        ENSURE(la->t[k] == lb->t[k]);
        ENSURE(strcmp(la->kind[k], lb->kind[k]) == 0 && strcmp(la->elem[k], lb->elem[k]) == 0);
        ENSURE(memcmp(la->v[k], lb->v[k], sizeof la->v[k]) == 0);
    }
    ENSURE(memcmp(ya, yb, (size_t)ny * sizeof(double)) == 0);
out:
    free(ya);
    free(yb);
    free(la);
    free(lb);
}

/* The block on a floor with Coulomb friction (incremental) and a pusher
 * without friction, active from 1 ms to 20 ms of a 0.4 s run. */
static void test_roots_live_mixed(void)
{
    FILE *f = fopen("validation/frc_iform_compare/case.rad", "r");
    ENSURE(f != NULL);
    if (!f) return;
    static char text[16384];
    size_t len = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[len] = 0;
    /* the pusher's interface: Tstart 0.001 s (columns 61-80) */
    const char *old = "                                                           0                                    0.02";
    const char *rep = "                                                           0               0.001                0.02";
    char *p = strstr(text, old);
    ENSURE(p != NULL && strlen(old) == strlen(rep));
    if (!p) return;
    memcpy(p, rep, strlen(rep));
    rc_error e;
    rc_model *m = tu_compile_text(text, "mixed.rad", &e);
    ENSURE(m != NULL);
    if (!m) return;
    ENSURE(m->ninter == 2);
    const int nr = rc_root_count(m);
    int *live = calloc((size_t)nr + 1, sizeof(int));
    const int n = rc_roots_live(m, m->tend, live);
    printf("    %d of %d root functions live\n", n, nr);
    /* the block on the floor: contact, friction (incremental: no reversal root) */
    ENSURE(!is_live(live, n, 0, RC_ROOT_TSTART) && !is_live(live, n, 0, RC_ROOT_TSTOP));
    ENSURE(is_live(live, n, 0, RC_ROOT_ZONE) && is_live(live, n, 0, RC_ROOT_FORCE));
    ENSURE(!is_live(live, n, 0, RC_ROOT_HYST_A) && !is_live(live, n, 0, RC_ROOT_HYST_B));
    ENSURE(!is_live(live, n, 0, RC_ROOT_TRK_A) && !is_live(live, n, 0, RC_ROOT_TRK_B));
    ENSURE(is_live(live, n, 0, RC_ROOT_SLIP) && !is_live(live, n, 0, RC_ROOT_REV));
    /* the pusher: its window, contact, nothing else */
    ENSURE(is_live(live, n, 1, RC_ROOT_TSTART) && is_live(live, n, 1, RC_ROOT_TSTOP));
    ENSURE(is_live(live, n, 1, RC_ROOT_ZONE) && is_live(live, n, 1, RC_ROOT_FORCE));
    for (int k = RC_ROOT_HYST_A; k < RC_ROOTS_PER_INTER; k++) ENSURE(!is_live(live, n, 1, k));
    /* the point roots and after: all live, in order */
    for (int k = rc_root_point_base(m); k < nr; k++) ENSURE(is_live(live, n, 0, k));
    for (int j = 1; j < n; j++) ENSURE(live[j] > live[j - 1]);
    /* a run ending before Tstop: no stop root; before Tstart: no start root */
    const int n2 = rc_roots_live(m, 0.01, live);
    ENSURE(n2 == n - 1 && !is_live(live, n2, 1, RC_ROOT_TSTOP) && is_live(live, n2, 1, RC_ROOT_TSTART));
    ENSURE(rc_roots_live(m, 0.0005, live) == n - 2);
    free(live);
    /* the events of the window, the contacts and the friction all seen */
    same_runs(m, &rc_solver_cvode, "block and pusher");
    same_runs(m, &rc_solver_ida, "block and pusher");
    rc_model_free(m);
}

/* Hysteresis (Iform 1) and Inacti 5: their roots live and their events
 * the same. */
static void test_roots_live_hysteresis_inacti(void)
{
    const char *decks[] = {"validation/t6_unload_curve/case.rad", "validation/t6_inacti_icor/case.rad"};
    for (int q = 0; q < 2; q++) {
        rc_model *m = NULL;
        rc_error e;
        ENSURE(tu_load_compile(decks[q], &m, &e) == RC_OK);
        if (!m) continue;
        const int nr = rc_root_count(m);
        int *live = calloc((size_t)nr + 1, sizeof(int));
        const int n = rc_roots_live(m, m->tend, live);
        for (int i = 0; i < m->ninter; i++) {
            ENSURE(is_live(live, n, i, RC_ROOT_HYST_A) == (m->inter_iform[i] != 0));
            ENSURE(is_live(live, n, i, RC_ROOT_HYST_B) == (m->inter_iform[i] != 0));
            ENSURE(is_live(live, n, i, RC_ROOT_TRK_A) == (m->inter_inacti[i] == 5));
            ENSURE(is_live(live, n, i, RC_ROOT_TRK_B) == (m->inter_inacti[i] == 5));
        }
        ENSURE(q == 0 ? m->inter_iform[0] != 0 : m->inter_inacti[0] == 5);
        free(live);
        same_runs(m, &rc_solver_cvode, decks[q]);
        same_runs(m, &rc_solver_ida, decks[q]);
        rc_model_free(m);
    }
}

/* The first step after a restart (drive.c restart_step, docs/theory.md
 * 7.7): min(h_last, rtol / omega_s), not below 100 ulps of t; the
 * integrator's estimate (0) when neither is known; and a run of the stiff
 * bounce (the deck whose first impact drew CVODE's "t + h = t") on both
 * backends. */
static void test_restart_first_step(void)
{
    rc_model *m = NULL;
    rc_error e;
    ENSURE(tu_load_compile("validation/bounce_settle/case.rad", &m, &e) == RC_OK);
    if (!m) return;
    ENSURE(m->h0 == 0.0 && m->ninter == 1);
    const double p = m->inter_pscale[0], v = m->inter_vscale[0], hc = m->rtol * p / v;
    printf("    p_s = %.3g m, v_s = %.3g m/s, rtol / omega_s = %.3g s\n", p, v, hc);
    ENSURE(isfinite(hc) && hc > 0);
    ENSURE(rc_bk_restart_step(m, 0.5, 1e-3) == hc);              /* a flight step: the contact bound */
    ENSURE(rc_bk_restart_step(m, 0.5, 0.5 * hc) == 0.5 * hc);    /* a smaller last step is kept */
    ENSURE(rc_bk_restart_step(m, 0.5, 0.0) == hc);               /* no step yet */
    ENSURE(rc_bk_restart_step(m, 1e6, 1e-3) == 100.0 * DBL_EPSILON * 1e6); /* late: the floor moves t */
    const double keep = m->inter_pscale[0];
    m->inter_pscale[0] = NAN; /* no scales: the last step, or the integrator's estimate */
    ENSURE(rc_bk_restart_step(m, 0.5, 1e-3) == 1e-3);
    ENSURE(rc_bk_restart_step(m, 0.5, 0.0) == 0.0);
    m->inter_pscale[0] = keep;
    const rc_solver *sv[2] = {&rc_solver_cvode, &rc_solver_ida};
    for (int k = 0; k < 2; k++) {
        rc_stats s;
        rc_run_options o = {.t_end_override = 1.2};
        ENSURE(sv[k]->run(m, &o, NULL, NULL, &s, &e) == RC_OK);
        printf("    %s: %ld steps, %ld events, %ld restarts\n", sv[k]->name, s.steps, s.events, s.reinits);
        ENSURE(s.events >= 4 && s.reinits >= 2);
    }
    rc_model_free(m);
}

/* The reports the root functions keep for the impact samples
 * (rc_report_cache_*): the same as a fresh evaluation, bit for bit, and
 * refused at another state, in other modes (an interface's or one of its
 * contact points'), or when not kept. */
static void test_report_cache(void)
{
    rc_error e;
    rc_model *m = NULL;
    ENSURE(tu_load_compile("validation/cradle5/case.rad", &m, &e) == RC_OK && m != NULL);
    if (!m) return;
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double));
    double *g = calloc((size_t)rc_root_count(m) + 1, sizeof(double));
    ENSURE(d && y && g && m->ninter >= 2);
    if (!d || !y || !g) goto out;
    rc_initial_state(m, y);
    rc_modes_init(m, d, 0.0, y);
    for (int i = 0; i < m->ninter; i++) d->inter_mode[i] = RC_MODE_CLOSED; /* every kernel evaluated */
    /* the fast path's interfaces (all of cradle5's) keep none: the state is
     * not kept either */
    int nfast = 0;
    for (int i = 0; i < m->ninter; i++) nfast += m->inter_fast[i];
    ENSURE(nfast == m->ninter);
    d->sc->repc->on = 1;
    rc_assemble_roots(m, d, 0.0, y, g);
    ENSURE(!rc_report_cache_state(m, d, y));
    /* the general kernel's reports are kept */
    for (int i = 0; i < m->ninter; i++) m->inter_fast[i] = 0;
    /* not kept unless the driver asks */
    d->sc->repc->on = 0;
    rc_assemble_roots(m, d, 0.0, y, g);
    ENSURE(!rc_report_cache_state(m, d, y));
    d->sc->repc->on = 1;
    rc_assemble_roots(m, d, 0.0, y, g);
    ENSURE(rc_report_cache_state(m, d, y));
    int hits = 0;
    for (int i = 0; i < m->ninter; i++) {
        rc_inter_report a, b;
        memset(&a, 0, sizeof a);
        memset(&b, 0, sizeof b);
        if (!rc_report_cache_get(m, d, i, &a)) continue;
        rc_inter_report_eval_d(m, d, i, 0.0, y, &b);
        ENSURE(memcmp(&a, &b, sizeof a) == 0);
        hits++;
    }
    ENSURE(hits == m->ninter);
    /* another mode of interface 0: its report is refused, the others kept */
    rc_inter_report r;
    d->inter_mode[0] = RC_MODE_OPEN;
    ENSURE(!rc_report_cache_get(m, d, 0, &r) && rc_report_cache_get(m, d, 1, &r));
    d->inter_mode[0] = RC_MODE_CLOSED;
    d->inter_branch[0] = d->inter_branch[0] + 1;
    ENSURE(!rc_report_cache_get(m, d, 0, &r));
    d->inter_branch[0] = d->inter_branch[0] - 1;
    ENSURE(rc_report_cache_get(m, d, 0, &r));
    /* another state, by one ulp of one coordinate: refused */
    y[m->body_yadr[0]] = nextafter(y[m->body_yadr[0]], INFINITY);
    ENSURE(!rc_report_cache_state(m, d, y));
out:
    free(y);
    free(g);
    rc_data_free(d);
    rc_model_free(m);
    y = g = NULL;
    d = NULL;
    /* an interface with contact points (a box on an incline, with friction
     * per corner): its report kept too, the same as a fresh evaluation;
     * refused when one point's mode differs from the evaluation's */
    m = NULL;
    ENSURE(tu_load_compile("validation/box_plane_incline/case.rad", &m, &e) == RC_OK && m != NULL);
    if (!m) return;
    d = rc_data_new(m);
    y = calloc((size_t)m->ny, sizeof(double));
    g = calloc((size_t)rc_root_count(m) + 1, sizeof(double));
    ENSURE(d && y && g && m->inter_npt[0] > 0);
    if (d && y && g && m->inter_npt[0] > 0) {
        rc_initial_state(m, y);
        rc_modes_init(m, d, 0.0, y);
        d->inter_mode[0] = RC_MODE_CLOSED;
        d->sc->repc->on = 1;
        rc_assemble_roots(m, d, 0.0, y, g);
        ENSURE(rc_report_cache_state(m, d, y));
        rc_inter_report a, b;
        memset(&a, 0, sizeof a);
        memset(&b, 0, sizeof b);
        ENSURE(rc_report_cache_get(m, d, 0, &a));
        rc_inter_report_eval_d(m, d, 0, 0.0, y, &b);
        ENSURE(memcmp(&a, &b, sizeof a) == 0);
        const int pb = m->inter_pbase[0];
        d->pt_slip[pb + 1] = !d->pt_slip[pb + 1];
        ENSURE(!rc_report_cache_get(m, d, 0, &a));
        d->pt_slip[pb + 1] = !d->pt_slip[pb + 1];
        ENSURE(rc_report_cache_get(m, d, 0, &a));
    }
    free(y);
    free(g);
    rc_data_free(d);
    rc_model_free(m);
}

void suite_roots(void);
void suite_roots(void)
{
    RUN_TEST(test_roots_live_mixed);
    RUN_TEST(test_roots_live_hysteresis_inacti);
    RUN_TEST(test_restart_first_step);
    RUN_TEST(test_report_cache);
}
