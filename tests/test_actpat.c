/* The Newton matrix on the active part of the Jacobian pattern
 * (solver/activepart.h, engine rc_jac_active):
 * - at every new Jacobian of real runs (several decks, both backends) every
 *   nonzero of the assembled Jacobian lies in a slot rc_jac_active keeps,
 *   and slots are dropped; a mask with the closed interfaces' blocks
 *   dropped (a wrong rule) fails the same check;
 * - runs on the part and on the whole pattern give the same events and
 *   final states (within a tolerance: the pivot order changes rounding). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "model/joint.h"
#include "model/model.h"
#include "engine/constraints/stick.h"
#include "solver/activepart.h"
#include "solver/solver.h"
#include "testutil.h"
#include "engine/assembly/assembly.h"
#include "engine/events/events.h"
#include "engine/analyses/analyses.h"

typedef struct probe_log {
    long evals, checked, outside, outside_mut, mut_evals;
    double kept, total;
    unsigned char *keep;
} probe_log;

/* Every nonzero of jsave in a kept slot; the mutated mask (the blocks of the
 * closed interfaces dropped, the diagonal kept) must miss some. */
static void probe(void *ctx, const rc_model *m, const rc_data *d, double t, const double *y, const double *jsave)
{
    probe_log *p = ctx;
    p->evals++;
    if (!jsave) return; /* CVODE's Jacobian patched after an event: not a whole evaluation */
    p->checked++;
    p->kept += (double)rc_jac_active(m, d, t, y, p->keep);
    p->total += (double)m->nnz;
    for (int64_t k = 0; k < m->nnz; k++)
        if (jsave[k] != 0.0 && !p->keep[k]) p->outside++;
    int any = 0;
    for (int i = 0; i < m->ninter; i++) {
        if (d->inter_mode[i] != RC_MODE_CLOSED) continue;
        const rc_jblock *jb = &m->jb_inter[i];
        for (int k = 0; k < jb->nrow * jb->ncol; k++)
            if (jb->slot[k] >= 0 && jb->rows[k / jb->ncol] != jb->cols[k % jb->ncol]) p->keep[jb->slot[k]] = 0;
        any = 1;
    }
    if (!any) return;
    p->mut_evals++;
    for (int64_t k = 0; k < m->nnz; k++)
        if (jsave[k] != 0.0 && !p->keep[k]) p->outside_mut++;
}

/* One run of m on s with the part on or off: events, final state, stats. */
static rc_status run_once(const rc_model *m, const rc_solver *s, int on, tu_evlog *l, double *yend, rc_stats *st)
{
    rc_error e;
    /* the two runs are compared; a physics check that fails (an engine
     * defect the validation lists) is recorded, not a reason to stop */
    rc_run_options o = {.y_end = yend, .on_event = tu_evlog_event, .user = l, .on_violation = RC_ON_VIOLATION_WARN};
    rc_actpart_set_enabled(on);
    rc_status r = s->run(m, &o, NULL, NULL, st, &e);
    rc_actpart_set_enabled(1);
    if (r) printf("    run failed: %s\n", e.msg);
    return r;
}

/* The state's scale for the comparison: per body block the largest of its
 * position, velocity, ... magnitudes over both runs, at least 1. */
static double state_diff(const rc_model *m, const double *a, const double *b)
{
    double worst = 0;
    for (int k = 0; k < m->ny; k++) {
        const double sc = fmax(1.0, fmax(fabs(a[k]), fabs(b[k])));
        worst = fmax(worst, fabs(a[k] - b[k]) / sc);
    }
    return worst;
}

typedef struct deck_case {
    const char *path;
    double tend;   /* shortened run [s] (0: the deck's) */
    double tol_t;  /* event times, relative to the run's end */
    double tol_y;  /* final state, relative (absolute below 1) */
    int ida_only;  /* joints: the IDA path only */
} deck_case;

static const deck_case decks[] = {
    {"validation/seg_box_slide_stop/case.rad", 0, 1e-6, 1e-6, 0},  /* meshed box landing and sliding to rest */
    {"validation/stack10_rest/case.rad", 1.0, 1e-6, 1e-6, 0},      /* a column of ten spheres */
    {"validation/cradle5/case.rad", 0, 1e-6, 1e-6, 0},             /* five interfaces, contacts passing on */
    {"validation/frc_iform_compare/case.rad", 0, 1e-6, 1e-6, 0},   /* friction, two interfaces */
    {"validation/t6_inacti_icor/case.rad", 0, 1e-6, 1e-6, 0},      /* Inacti 5 tracking */
    {"validation/seg_seg_collide/case.rad", 0, 1e-6, 1e-6, 0},     /* two meshed boxes */
    {"validation/cc_stop/case.rad", 0, 1e-6, 1e-6, 0},             /* a contact coupling */
    {"validation/seg_box_incline/case.rad", 0, 1e-6, 1e-6, 0},     /* friction per point, sticking */
    {"validation/seg_box_filter_slide/case.rad", 0, 1e-6, 1e-6, 0}, /* per point with a filter */
    {"validation/seg_box_viscous/case.rad", 0, 1e-6, 1e-6, 0},     /* viscous friction per point */
    {"validation/seg_sphere_floor/case.rad", 0, 1e-6, 1e-6, 0},    /* a sphere on a meshed floor */
    {"validation/bounce_settle/case.rad", 0, 1e-6, 1e-6, 0},       /* settling (IDA: a settled contact's constraint) */
    {"validation/stick_incline/case.rad", 0, 1e-6, 1e-6, 0},       /* exact stick (IDA: velocity constraints) */
    {"validation/bounce_release/case.rad", 0, 1e-6, 1e-6, 0},      /* a settled contact's constraint released (IDA:
                                                                   the kept pivots fail, analysed anew) */
    {"validation/joint_slider_crank/case.rad", 0, 1e-6, 1e-6, 1}, /* joints (IDA: their extended pattern) */
    {"validation/joint_stop_flap/case.rad", 0, 1e-6, 1e-6, 1},  /* a joint's stops */
    {"validation/stick_joint_train/case.rad", 0, 1e-6, 1e-6, 1}, /* joints and exact stick: the whole pattern */
};

static void check_deck(const deck_case *dc, const rc_solver *s)
{
    rc_model *m = NULL;
    rc_error e;
    ENSURE(tu_load_compile(dc->path, &m, &e) == RC_OK);
    if (!m) return;
    if (dc->tend > 0) m->tend = dc->tend;
    probe_log p;
    memset(&p, 0, sizeof p);
    p.keep = malloc((size_t)m->nnz + 1);
    double *ya = calloc((size_t)m->ny, sizeof(double)), *yb = calloc((size_t)m->ny, sizeof(double));
    tu_evlog *la = calloc(1, sizeof *la), *lb = calloc(1, sizeof *lb);
    ENSURE(p.keep && ya && yb && la && lb);
    if (!p.keep || !ya || !yb || !la || !lb) goto out;
    rc_stats sa, sb;
    rc_actpart_set_probe(probe, &p);
    rc_actpart_probe_outside();
    ENSURE(run_once(m, s, 1, la, ya, &sa) == RC_OK);
    const long xout = rc_actpart_probe_outside();
    rc_actpart_set_probe(NULL, NULL);
    ENSURE(run_once(m, s, 0, lb, yb, &sb) == RC_OK);
    double dt = 0;
    int same = la->n == lb->n;
    for (int k = 0; same && k < la->n && k < TU_MAXEV; k++) {
        same = strcmp(la->kind[k], lb->kind[k]) == 0 && strcmp(la->elem[k], lb->elem[k]) == 0;
        dt = fmax(dt, fabs(la->t[k] - lb->t[k]) / m->tend);
    }
    const double dy = state_diff(m, ya, yb);
    printf("    %s, %s: %ld Jacobians checked, %.1f%% of the slots kept on average, %ld outside (mutated: %ld in %ld); "
           "%d / %d events, times %.2g, state %.2g; steps %ld / %ld; extended matrix: %ld outside\n",
           dc->path, s->name, p.checked, 100.0 * p.kept / fmax(p.total, 1), p.outside, p.outside_mut, p.mut_evals,
           la->n, lb->n, dt, dy, sa.steps, sb.steps, xout);
    /* IDA with a constraint set (joints, exact stick, contacts that can
     * settle) runs on its whole extended pattern */
    const int whole = s == &rc_solver_ida && m->jnt && m->jnt->n > 0 && rc_stk_slots(m) > 0;
    ENSURE(whole ? p.checked == 0 : p.checked > 0);
    ENSURE(p.outside == 0);
    ENSURE(xout == 0);
    ENSURE(p.mut_evals == 0 || p.outside_mut > 0);
    ENSURE(same);
    ENSURE(dt <= dc->tol_t);
    ENSURE(dy <= dc->tol_y);
out:
    rc_actpart_set_probe(NULL, NULL);
    free(p.keep);
    free(ya);
    free(yb);
    free(la);
    free(lb);
    rc_model_free(m);
}

static void test_actpat_decks(void)
{
    for (size_t k = 0; k < sizeof decks / sizeof decks[0]; k++) {
        if (!decks[k].ida_only) check_deck(&decks[k], &rc_solver_cvode);
        check_deck(&decks[k], &rc_solver_ida);
    }
}

void suite_actpat(void);

/* The key of the active slots (rc_jac_active_key): the same key gives the
 * same slots (a closed and a released contact are both on), another key
 * other slots; models whose slots follow more than the interfaces' on/off
 * states (contact points) have none. */
static void test_actpat_key(void)
{
    rc_error e;
    rc_model *m = NULL;
    ENSURE(tu_load_compile("validation/cradle5/case.rad", &m, &e) == RC_OK && m != NULL);
    if (!m) return;
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double));
    unsigned char *k1 = calloc((size_t)m->ninter + 1, 1), *k2 = calloc((size_t)m->ninter + 1, 1);
    unsigned char *a1 = calloc((size_t)m->nnz + 1, 1), *a2 = calloc((size_t)m->nnz + 1, 1);
    ENSURE(d && y && k1 && k2 && a1 && a2 && m->ninter >= 2);
    if (!d || !y || !k1 || !k2 || !a1 || !a2) goto out;
    rc_initial_state(m, y);
    rc_modes_init(m, d, 0.0, y);
    for (int i = 0; i < m->ninter; i++) d->inter_mode[i] = RC_MODE_CLOSED;
    ENSURE(rc_jac_active_key(m, d, k1) == 1);
    rc_jac_active(m, d, 0.0, y, a1);
    d->inter_mode[0] = RC_MODE_RELEASED;
    ENSURE(rc_jac_active_key(m, d, k2) == 1 && memcmp(k1, k2, (size_t)m->ninter) == 0);
    rc_jac_active(m, d, 0.0, y, a2);
    ENSURE(memcmp(a1, a2, (size_t)m->nnz) == 0);
    d->inter_mode[0] = RC_MODE_OPEN;
    ENSURE(rc_jac_active_key(m, d, k2) == 1 && memcmp(k1, k2, (size_t)m->ninter) != 0);
    rc_jac_active(m, d, 0.0, y, a2);
    ENSURE(memcmp(a1, a2, (size_t)m->nnz) != 0);
out:
    free(y);
    free(k1);
    free(k2);
    free(a1);
    free(a2);
    rc_data_free(d);
    rc_model_free(m);
    /* contact points: no key */
    m = NULL;
    ENSURE(tu_load_compile("validation/seg_box_slide_stop/case.rad", &m, &e) == RC_OK && m != NULL);
    if (!m) return;
    ENSURE(m->npt > 0);
    d = rc_data_new(m);
    unsigned char *k = calloc((size_t)m->ninter + 1, 1);
    ENSURE(d && k);
    if (d && k) ENSURE(rc_jac_active_key(m, d, k) == 0);
    free(k);
    rc_data_free(d);
    rc_model_free(m);
}

void suite_actpat(void)
{
    RUN_TEST(test_actpat_decks);
    RUN_TEST(test_actpat_key);
}
