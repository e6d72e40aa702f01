/*
 * Persistent contacts (solver/impacts.c): the rule that tells them from
 * impacts, and their columns against closed forms: a box resting on a floor
 * (mean normal force m g, duration the run), a block sliding to a stop with
 * Coulomb friction (slip distance v0^2 / (2 mu g), peak force m g), a ball
 * dropped on a floor (an impact, not a persistent contact); the table in the
 * results file with its units; the note of a run spent on an undamped
 * contact's vibration.
 */
#include "harness.h"

#include <netcdf.h>
#include <stdlib.h>

#include "ricochet/ricochet.h"
#include "base/error.h"
#include "solver/impacts.h"
#include "engine/assembly/assembly.h"
#include "testutil.h"
#include "case/case.h"

#define G 9.81 /* gravity of the decks [m/s^2] */

/* The rule: an impact closed by approaching and lasted at most
 * RC_IMPACT_SPAN contact times; everything else persistent. */
static void test_persist_rule(void)
{
    const double tc = 0.0031;
    ENSURE(rc_impacts_is_impact(0, 1.4, 0.003, tc));                     /* a bounce */
    ENSURE(rc_impacts_is_impact(0, 1.4, RC_IMPACT_SPAN * tc, tc));       /* at the limit */
    ENSURE(!rc_impacts_is_impact(0, 1.4, RC_IMPACT_SPAN * tc * 1.01, tc)); /* came to rest */
    ENSURE(!rc_impacts_is_impact(1, 1.4, 0.003, tc));                    /* closed by the start */
    ENSURE(!rc_impacts_is_impact(0, 0.0, 0.003, tc));                    /* touching, no approach */
    ENSURE(!rc_impacts_is_impact(0, NAN, 0.003, tc));
    ENSURE(rc_impacts_is_impact(0, 1.4, 100.0, NAN)); /* no time scale: any duration */
}

/* A box of mass M [kg] resting on the floor z = 0, touching at t = 0 (no
 * penetration), at rest; k = 1e6 N/m, damping ratio 0.5, Fric 0.3. */
#define BOX_M 3.71
static const char *box_deck =
    "/BEGIN\n"
    "box resting on a floor\n"
    "2022,0\n"
    "kg,m,s\n"
    "kg,m,s\n"
    "/NODE\n"
    "1,0.0137,-0.0291,0.0543\n"
    "/RBODY/1\n"
    "box 0.2 x 0.3 x 0.1086 m\n"
    "1,,,3,3.71\n"
    "0.0314713,0.0169763,0.0401917\n"
    "0,0,0\n"
    "/SURF/BOX/1\n"
    "box\n"
    "1\n"
    "0.0137,-0.0291,0.0543\n"
    "0.1,0.15,0.0543\n"
    "/SURF/PLANE/2\n"
    "floor\n"
    "0,0,0\n"
    "0,0,1\n"
    "/FUNCT/1\n"
    "linear k = 1e6 N/m\n"
    "0,0\n"
    "0.001,1000\n"
    "/INTER/TYPE6/1\n"
    "floor - box\n"
    "1,2\n"
    "0,0.3,0,0,0\n"
    "0,0,0,0,0,0,,\n"
    "1,0,1.0,1.0,0\n"
    "0,,0,\n"
    "1926.1,0,0,\n"
    "/GRAV/1\n"
    "gravity\n"
    "0,Z,0,0,0,,1.0,-9.81\n"
    "/RUN\n"
    "0.43,0.01\n"
    "/END\n";

static rc_model *load_text(const char *name, const char *text)
{
    rc_error e;
    rc_error_clear(&e);
    rc_model *m = tu_compile_text(text, tu_tmp_write(name, ""), &e);
    if (!m) fprintf(stderr, "  %s: %s\n", name, e.msg);
    return m;
}

static void test_persist_box_resting_mean_force(void)
{
    rc_model *m = load_text("persist_box.rad", box_deck);
    ENSURE(m != NULL);
    if (!m) return;
    const char *path = tu_tmp_write("persist_box.nc", "");
    double y_end[64];
    ENSURE(rc_model_state_size(m) <= 64);
    rc_run_options opt = {.output_path = path, .y_end = y_end};
    rc_stats st;
    rc_error e;
    ENSURE(rc_run(m, &opt, &st, &e) == RC_OK);
    ENSURE(st.impacts == 0 && st.contacts == 1);
    const rc_contact *c = &st.contact[0];
    const double T = 0.43, W = BOX_M * G;
    /* the closed form: the floor's impulse is the weight's plus the
     * momentum gained, m g T + m (v_z(T) - 0) */
    const int b = rc_model_body_index(m, 1);
    const double vz = b >= 0 ? y_end[b + 9] : NAN;
    const double exact = W + BOX_M * vz / T;
    printf("    box at rest: duration %.9g s (run %.9g s), mean F %.9g N, m g %.9g N (+ m v_z(T)/T: %.3g N), "
           "rel. diff %.2e; peak %.6g N, slip %.3g m\n",
           c->duration, T, c->fn_mean, W, BOX_M * vz / T, fabs(c->fn_mean / W - 1), c->fn_max, c->slip);
    ENSURE(c->inter_id == 1 && c->t_close == 0.0 && isnan(c->t_open));
    ENSURE_NEAR(c->duration, T, 1e-12, 0.0);
    ENSURE_NEAR(c->fn_mean, W, 1e-6, 0.0);
    ENSURE_NEAR(c->fn_mean, exact, 1e-6, 0.0);
    /* touching at rest, loaded by its weight: the damped sinking overshoots
     * m g by at most the undamped 2 m g */
    ENSURE(c->fn_max > W && c->fn_max < 2.0 * W);
    ENSURE(c->pen_max > W / 1e6 && c->pen_max < 2.0 * W / 1e6); /* past the static m g / k */
    ENSURE(c->slip >= 0.0 && c->slip < 1e-9);            /* no sliding */
    /* the file: the same row, dimension persistent, units */
    int ncid, v;
    double x = 0.0;
    size_t len = 0, start[1] = {0};
    char units[32] = "";
    ENSURE(nc_open(path, NC_NOWRITE, &ncid) == NC_NOERR);
    int dim;
    ENSURE(nc_inq_dimid(ncid, "persistent", &dim) == NC_NOERR && nc_inq_dimlen(ncid, dim, &len) == NC_NOERR && len == 1);
    ENSURE(nc_inq_dimid(ncid, "impact", &dim) == NC_NOERR && nc_inq_dimlen(ncid, dim, &len) == NC_NOERR && len == 0);
    ENSURE(nc_inq_varid(ncid, "persistent_mean_force", &v) == NC_NOERR &&
           nc_get_var1_double(ncid, v, start, &x) == NC_NOERR && x == c->fn_mean);
    ENSURE(nc_get_att_text(ncid, v, "units", units) == NC_NOERR && !strncmp(units, "N", 2));
    static const char *const names[8][2] = {
        {"persistent_inter", "1"},         {"persistent_close_time", "s"},    {"persistent_open_time", "s"},
        {"persistent_duration", "s"},      {"persistent_peak_force", "N"},    {"persistent_mean_force", "N"},
        {"persistent_max_penetration", "m"}, {"persistent_slip_distance", "m"}};
    for (int k = 0; k < 8; k++) {
        size_t ul = 0;
        memset(units, 0, sizeof units);
        ENSURE(nc_inq_varid(ncid, names[k][0], &v) == NC_NOERR && nc_inq_attlen(ncid, v, "units", &ul) == NC_NOERR &&
               ul < sizeof units && nc_get_att_text(ncid, v, "units", units) == NC_NOERR &&
               !strcmp(units, names[k][1]));
    }
    ENSURE(nc_inq_varid(ncid, "persistent_open_time", &v) == NC_NOERR &&
           nc_get_var1_double(ncid, v, start, &x) == NC_NOERR && isnan(x));
    ENSURE(nc_close(ncid) == NC_NOERR);
    rc_model_free(m);
}

/* The block of validation/fric_slide_stop (a sphere R = 0.05 m, rotations
 * locked, resting at its static penetration m g / k) launched at V0 with
 * Coulomb friction MU: it slides v0^2 / (2 mu g) and stops. */
#define V0 0.837
#define MU 0.271
static const char *slide_deck =
    "#RADIOSS STARTER\n"
    "/BEGIN\n"
    "block sliding to a stop\n"
    "      2022         0\n"
    "                  kg                   m                   s\n"
    "                  kg                   m                   s\n"
    "/FUNCT/1\n"
    "linear load curve k = 1e6 N/m\n"
    "                   0                   0\n"
    "                   1             1000000\n"
    "/NODE\n"
    "         1                   0                   0          0.04999019\n"
    "/RBODY/1\n"
    "block 1 kg\n"
    "         1                                                 1         1\n"
    "               0.001               0.001               0.001\n"
    "                   0                   0                   0\n"
    "/SURF/ELLIPS/1\n"
    "sphere\n"
    "         0         2         1\n"
    "                   0                   0          0.04999019\n"
    "                0.05                0.05                0.05\n"
    "/SURF/PLANE/2\n"
    "floor z = 0\n"
    "                   0                   0                   0\n"
    "                   0                   0                   1\n"
    "/GRNOD/NODE/1\n"
    "group\n"
    "         1\n"
    "/BCS/1\n"
    "no rotation\n"
    "   000 111         0         1\n"
    "/INIVEL/TRA/1\n"
    "initial velocity\n"
    "               0.837                   0                   0         1         0\n"
    "/GRAV/1\n"
    "gravity\n"
    "         0         Z         0         0         1                             1               -9.81\n"
    "/INTER/TYPE6/1\n"
    "Coulomb friction mu = 0.271\n"
    "         1         2\n"
    "                                   0.271                   0\n"
    "                   0         0         0         0         0\n"
    "         1         0                                                 0\n"
    "         0\n"
    "                1000         0         0\n"
    "/RUN\n"
    "                 0.4                0.01\n"
    "/END\n";

static void test_persist_sliding_block_slip_distance(void)
{
    rc_model *m = load_text("persist_slide.rad", slide_deck);
    ENSURE(m != NULL);
    if (!m) return;
    rc_run_options opt = {0};
    rc_stats st;
    rc_error e;
    ENSURE(rc_run(m, &opt, &st, &e) == RC_OK);
    ENSURE(st.impacts == 0 && st.contacts == 1);
    const rc_contact *c = &st.contact[0];
    const double want = V0 * V0 / (2.0 * MU * G), W = 1.0 * G;
    printf("    sliding block: slip %.9g m, v0^2/(2 mu g) %.9g m, rel. diff %.2e; peak F %.9g N, mean F %.9g N, "
           "m g %.9g N\n",
           c->slip, want, fabs(c->slip / want - 1), c->fn_max, c->fn_mean, W);
    ENSURE_NEAR(c->slip, want, 1e-4, 0.0);
    ENSURE_NEAR(c->fn_max, W, 1e-6, 0.0);
    ENSURE_NEAR(c->fn_mean, W, 1e-6, 0.0);
    ENSURE(c->t_close == 0.0 && isnan(c->t_open) && c->duration == 0.4);
    rc_model_free(m);
}

/* The demo's ball bounces: impacts, no persistent contact; run long enough
 * to come to rest, its last contact is persistent (closed by approaching,
 * longer than RC_IMPACT_SPAN contact times) and carries its weight. */
static void test_persist_ball_bounces_then_rests(void)
{
    rc_model *m = TU_LOAD_OK("cases/demo_sphere_drop.rad");
    if (!m) return;
    rc_run_options opt = {.t_end_override = 0.5};
    rc_stats st;
    rc_error e;
    ENSURE(rc_run(m, &opt, &st, &e) == RC_OK);
    ENSURE(st.impacts == 2 && st.contacts == 0);
    for (long k = 0; k < st.impacts && k < RC_STATS_IMPACTS; k++)
        ENSURE(st.impact[k].v_in > 0 && st.impact[k].duration < 0.004);
    opt.t_end_override = 4.0;
    ENSURE(rc_run(m, &opt, &st, &e) == RC_OK);
    printf("    demo to 4 s: %ld impacts, %ld persistent", st.impacts, st.contacts);
    if (st.contacts > 0)
        printf(" (closed at %.6g s, %.6g s long, mean F %.6g N, m g 9.81 N)", st.contact[0].t_close,
               st.contact[0].duration, st.contact[0].fn_mean);
    printf("\n");
    ENSURE(st.contacts == 1);
    if (st.contacts == 1) {
        const rc_contact *c = &st.contact[0];
        ENSURE(isnan(c->t_open) && c->duration > RC_IMPACT_SPAN * 0.00314);
        ENSURE_NEAR(c->t_close + c->duration, 4.0, 1e-12, 0.0);
        /* at rest for most of it: the mean is m g within the last bounces' share */
        ENSURE_NEAR(c->fn_mean, 9.81, 0.05, 0.0);
    }
    rc_model_free(m);
}

/* Run m on backend method (1 CVODE, 2 IDA) with its statistics printed:
 * the status, the statistics in *st and the state at the end in *yend
 * (malloc'd; the caller frees it). */
static rc_status run_on(rc_model *m, int method, rc_stats *st, double **yend)
{
    rc_error e;
    rc_status s = rc_model_set_method(m, method, &e);
    *yend = calloc((size_t)rc_model_state_size(m), sizeof(double));
    if (s == RC_OK) {
        rc_run_options o = {.y_end = *yend};
        s = rc_run(m, &o, st, &e);
        printf("    %s: %s, %ld steps, %ld events, %ld settles\n", method == 1 ? "CVODE" : "IDA", s ? e.msg : "ok",
               st->steps, st->events, st->settles);
    }
    return *yend ? s : RC_ENOMEM;
}

/* An elastic contact (restitution 1: TYPE6 Iform 0 without damping) does
 * not settle. Two balls stacked on a floor (the fuzzer's 165000138, three
 * balls, shrunk), the floor's contact damped, the balls' elastic: the
 * lower ball rattles between its contacts, and flights of the balls'
 * contact shrinking twice in a row by that exchange settled it as
 * accumulating bounces; on IDA the settled contact became a rigid
 * constraint and the motion left the penalty motion (0.35 mm at 0.24 s).
 * Now neither backend settles it, and the two agree. */
static void test_elastic_contact_does_not_settle(void)
{
    const char *path = "fuzz/physics/regressions/stack_elastic_contact_settled_rigid_on_ida.rad";
    double zend[2][2];
    for (int method = 1; method <= 2; method++) {
        rc_model *m = TU_LOAD_OK(path);
        if (!m) return;
        ENSURE(m->ninter == 2 && !rc_inter_elastic(m, 0) && rc_inter_elastic(m, 1)); /* floor damped, balls not */
        rc_stats st;
        double *y = NULL;
        ENSURE(run_on(m, method, &st, &y) == RC_OK && st.settles == 0);
        for (int b = 0; y && b < 2; b++) zend[method - 1][b] = y[m->body_yadr[b] + 2];
        free(y);
        rc_model_free(m);
    }
    double dz = 0.0;
    for (int b = 0; b < 2; b++) dz = fmax(dz, fabs(zend[0][b] - zend[1][b]));
    printf("    heights at the end, CVODE against IDA: max difference %.2e m\n", dz);
    ENSURE(dz < 1e-6);
}

/* A ball bouncing down a ramp against a wall (fuzz 227000197): on IDA the
 * ramp contact settles into a unilateral constraint, whose projection at the
 * restart turned the wall's released law from unloading to reloading with
 * its root past zero; the ball then passed 3 mm into the wall at zero force
 * (a physics check stopped the run). The modes are decided again by the
 * projected state: the ball stays at the wall, and CVODE and IDA agree. */
static void test_ida_settle_projection_decides_other_modes(void)
{
    const char *path = "tests/data/ramp_wall_ida_settle_projection_reloads_wall.rad";
    double yend[2] = {0.0, 0.0};
    for (int method = 1; method <= 2; method++) {
        rc_model *m = TU_LOAD_OK(path);
        if (!m) return;
        rc_stats st;
        double *y = NULL;
        ENSURE(run_on(m, method, &st, &y) == RC_OK);
        if (method == 2) ENSURE(st.settles >= 1); /* the path under test */
        if (y) yend[method - 1] = y[m->body_yadr[0] + 1];
        free(y);
        rc_model_free(m);
    }
    /* the wall y = -0.1355314391157118 m facing +y, the ball's radius 0.0261018649831601 m */
    const double gap0 = -0.1355314391157118 + 0.026101864983160174;
    printf("    ball centre at the end: CVODE %.9f m, IDA %.9f m (touching the wall: %.9f m)\n", yend[0], yend[1], gap0);
    for (int k = 0; k < 2; k++) ENSURE(yend[k] > gap0 - 1e-5);
    ENSURE(fabs(yend[0] - yend[1]) < 1e-5);
}

/* A jump of the state at a breakpoint likewise: a belt whose imposed
 * velocity starts at 0.05 s at 3 m/s under a ball sliding at 0.85 m/s
 * reverses the sliding at once; the friction's slip is decided again by the
 * new state (a fric_slip at the jump), and rolling begins at the closed-form
 * time t_s = 0.294165 s (the slip left as it was: 1.07e-3 s late, the
 * friction pushing while the stick spring turned it). */
static void test_breakpoint_jump_decides_friction_again(void)
{
    rc_model *m = TU_LOAD_OK("tests/data/belt_impvel_start_reverses_sliding.rad");
    if (!m) return;
    tu_evlog ev;
    rc_stats st;
    ENSURE(tu_run_evlog(m, &ev, &st) == RC_OK);
    int slip_at_jump = 0;
    double t_stick = NAN;
    for (int k = 0; k < ev.n && k < TU_MAXEV; k++) {
        slip_at_jump |= !strcmp(ev.kind[k], "fric_slip") && fabs(ev.t[k] - 0.05) < 1e-12;
        if (!strcmp(ev.kind[k], "fric_stick") && isnan(t_stick)) t_stick = ev.t[k];
    }
    const double mug = 0.3 * 9.81, ts = 0.05 + (3.0 - (1.0 - 3.5 * mug * 0.05)) / (3.5 * mug);
    printf("    rolling from %.7f s, closed form %.7f s (error %.2e s); slip decided at the jump: %d\n", t_stick, ts,
           t_stick - ts, slip_at_jump);
    ENSURE(slip_at_jump);
    ENSURE(fabs(t_stick - ts) < 2e-5);
    rc_model_free(m);
}

/* A contact released and closed at zero force whose friction limit holds
 * Sfric (fuzz 229000250: a box sliding on a floor, Sfric = 1.8 times its
 * weight, released and closed every 3e-10 s until the Zeno guard or
 * CV_TOO_MUCH_WORK stopped it: Sfric in full at zero normal force came and
 * went with the mode, a Filippov sliding surface the modes cannot hold).
 * Sfric now ramps in over the first 1e-3 F_s of normal force: the friction
 * is continuous through the release, and the run ends normally with a
 * handful of events, as with Sfric = 0. */
static void test_sfric_ramps_in_at_zero_force(void)
{
    const char *path = "fuzz/physics/regressions/box_floor_sfric_zero_force_sliding_mode_zeno.rad";
    for (int zero = 0; zero <= 1; zero++) {
        rc_error e;
        rc_case *c = NULL;
        const char *set[1] = {"/INTER/TYPE6/1:Sfric=0"};
        ENSURE(rc_case_load_set(path, set, zero, &c, &e) == RC_OK);
        rc_model *m = NULL;
        ENSURE(c && rc_model_compile(c, &m, &e) == RC_OK);
        rc_case_free(c);
        if (!m) return;
        rc_stats st;
        const rc_status s = rc_run(m, NULL, &st, &e);
        printf("    Sfric %s: %s\n", zero ? "0" : "as given", s ? e.msg : "ok");
        printf("      %ld steps, %ld events, %ld violations\n", st.steps, st.events, st.violations);
        ENSURE(s == RC_OK && st.violations == 0);
        ENSURE(st.events < 100);
        rc_model_free(m);
    }
}

/* ---- the vibration note ------------------------------------------------ */
/* A 1 g ball resting on a floor through TYPE6 Iform 2 (load curve 1e6 N/m,
 * Stiff 1e8 N/m), without damping: once it has loaded the curve it
 * vibrates on the Stiff line between zero and twice its weight for ever,
 * with the period 2 pi sqrt(m / Stiff) = 1.99e-5 s, and the integrator
 * follows every period (some 70 steps each): 2 500 periods in 0.05 s. The
 * run says so (rc_stats.vibration_note, the results' vibration_note). With
 * Visc 50 N s/m (damping ratio 0.8 on the curve) the vibration dies out in
 * a few periods and the run takes a few hundred steps: no note. */
#define VIB_DECK(visc) VIB_DECK_S(visc, "")
#define VIB_DECK_S(visc, solver)                                                                                   \
    "/BEGIN\nball on an undamped Stiff line\n      2022         0\n"                                            \
    "                  kg                   m                   s\n"                                            \
    "                  kg                   m                   s\n"                                            \
    "/NODE\n1,0,0,0.01\n/RBODY/1\nball\n1,,,,0.001\n4e-8,4e-8,4e-8\n0,0,0\n"                                    \
    "/SURF/ELLIPS/1\nball\n0,2,1\n0,0,0.01\n0.01,0.01,0.01\n/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n"                \
    "/GRNOD/NODE/1\nball\n1\n/GRAV/1\ng\n0,Z,0,0,1,,1,-9.81\n/FUNCT/1\nlinear\n0,0\n1,1000000\n"               \
    "/INTER/TYPE6/1\nball on floor\n1,2\n0,0\n\n1,2\n0,,100000000\n" visc "\n" solver "/RUN\n0.05,0.001\n/END\n"

static void test_vibration_note_undamped_stiff_line(void)
{
    for (int damped = 0; damped < 2; damped++) {
        rc_model *m = load_text(damped ? "vib_damped.rad" : "vib_undamped.rad", damped ? VIB_DECK("50") : VIB_DECK(""));
        ENSURE(m != NULL);
        if (!m) return;
        rc_run_options opt = {.output_path = tu_tmp_write(damped ? "vib_damped.nc" : "vib_undamped.nc", "")};
        rc_stats st;
        rc_error e;
        ENSURE(rc_run(m, &opt, &st, &e) == RC_OK);
        printf("    %s: %ld steps; note \"%s\"\n", damped ? "Visc 50" : "undamped", st.steps, st.vibration_note);
        if (damped) {
            ENSURE(st.steps < 10000);
            ENSURE(st.vibration_note[0] == '\0');
        } else {
            ENSURE(st.steps >= RC_VIB_NOTE_STEPS);
            ENSURE(strstr(st.vibration_note, "/INTER/TYPE6/1") != NULL);
            const char *p = strstr(st.vibration_note, ", period ");
            double T = p ? atof(p + 9) : NAN;
            ENSURE_NEAR(T, 2.0 * 3.14159265358979 * sqrt(1e-3 / 1e8), 1e-2, 0.0);
        }
        rc_model_free(m);
    }
}

/* Two such balls, each on its own undamped Stiff line (the same period
 * T): one step serves both while they ring together, so the note counts
 * the periods of the fastest vibration closed at each time, not their sum
 * (a chain of seven balls on a floor, its twelve contacts ringing
 * together, took 82 steps a period of its fastest and had no note). Two
 * persistent contacts of 1 s, with steps 0.6 x 30 / T: closed together
 * they account for 30 / T steps, and the run followed them (a note naming
 * both); one after the other for 60 / T, 0.3 of which is not following
 * them (no note). */
static void test_vibration_note_counts_contacts_ringing_together_once(void)
{
    static const char deck[] =
        "/BEGIN\ntwo balls on undamped Stiff lines\n      2022         0\n"
        "                  kg                   m                   s\n"
        "                  kg                   m                   s\n"
        "/NODE\n1,0,0,0.01\n2,0.1,0,0.01\n/RBODY/1\nball\n1,,,,0.001\n4e-8,4e-8,4e-8\n0,0,0\n"
        "/RBODY/2\nball\n2,,,,0.001\n4e-8,4e-8,4e-8\n0,0,0\n"
        "/SURF/ELLIPS/1\nball\n0,2,1\n0,0,0.01\n0.01,0.01,0.01\n/SURF/ELLIPS/2\nball\n0,2,2\n0.1,0,0.01\n"
        "0.01,0.01,0.01\n/SURF/PLANE/3\nfloor\n0,0,0\n0,0,1\n"
        "/GRAV/1\ng\n0,Z,0,0,0,,1,-9.81\n/FUNCT/1\nlinear\n0,0\n1,1000000\n"
        "/INTER/TYPE6/1\nball 1 on floor\n1,3\n0,0\n\n1,2\n0,,100000000\n\n"
        "/INTER/TYPE6/2\nball 2 on floor\n2,3\n0,0\n\n1,2\n0,,100000000\n\n/RUN\n2,0.001\n/END\n";
    rc_model *m = load_text("vib_two.rad", deck);
    ENSURE(m != NULL);
    if (!m) return;
    const double T = 2.0 * 3.14159265358979 * sqrt(1e-3 / 1e8);
    const long steps = (long)(0.6 * RC_VIB_STEPS_PER_PERIOD / T);
    for (int apart = 0; apart < 2; apart++) {
        rc_impacts im;
        ENSURE(rc_impacts_init(&im, m) == 0);
        im.pc = calloc(2, sizeof *im.pc);
        im.npc = 2;
        for (int c = 0; c < 2; c++) {
            im.pc[c].inter_id = c + 1;
            im.pc[c].t_close = apart ? c * 1.0 : 0.0;
            im.pc[c].duration = 1.0;
            im.pc[c].t_open = im.pc[c].t_close + 1.0;
        }
        char note[1024];
        rc_impacts_vibration_note(&im, m, steps, note, sizeof note);
        printf("    %s, %ld steps (T %.3g s): note \"%.90s...\"\n", apart ? "one after the other" : "together", steps,
               T, note);
        if (apart) {
            ENSURE(note[0] == '\0');
        } else {
            ENSURE(strstr(note, "/INTER/TYPE6/1") != NULL && strstr(note, "/INTER/TYPE6/2") != NULL);
            ENSURE(strstr(note, "about 18 a period") != NULL); /* 0.6 x 30 */
        }
        rc_impacts_free(&im);
    }
    rc_model_free(m);
}

/* The events an undamped vibration drives: one ball on its undamped Stiff
 * line closed for 1 s (1/T periods) and 200 000 event instants of its
 * interface (its friction's stick and slip each period: 247000049, a
 * spinning ball on a tilted floor), each a restart of the integrator. A run
 * of 30/T + 50 x 200 000 steps is explained by both (a note naming the
 * periods and the events, ~30 steps a period and ~50 an event); the same
 * steps without those events are over 4 x what the periods alone account
 * for: no note. Several instants at one time count once. */
static void test_vibration_note_counts_driven_events(void)
{
    rc_model *m = load_text("vib_ev.rad", VIB_DECK(""));
    ENSURE(m != NULL);
    if (!m) return;
    const double T = 2.0 * 3.14159265358979 * sqrt(1e-3 / 1e8);
    const long nev = 200000;
    const long steps = (long)(RC_VIB_STEPS_PER_PERIOD / T + RC_VIB_STEPS_PER_EVENT * (double)nev);
    for (int events = 0; events < 2; events++) {
        rc_impacts im;
        ENSURE(rc_impacts_init(&im, m) == 0);
        im.pc = calloc(1, sizeof *im.pc);
        im.npc = 1;
        im.pc[0] = (rc_contact){0};
        im.pc[0].inter_id = 1;
        im.pc[0].t_close = 0.0;
        im.pc[0].duration = 1.0;
        im.pc[0].t_open = 1.0;
        if (events) {
            rc_data *d = rc_data_new(m);
            double *y = calloc((size_t)m->ny, sizeof(double));
            ENSURE(d != NULL && y != NULL);
            if (!d || !y) return;
            rc_initial_state(m, y);
            /* two events at one instant, then one per instant */
            rc_impacts_event(&im, m, d, 0, RC_EV_FRIC_STICK, 1e-6, y);
            rc_impacts_event(&im, m, d, 0, RC_EV_FRIC_SLIP, 1e-6, y);
            ENSURE(im.nevt[0] == 1);
            im.nevt[0] = nev;
            free(y);
            rc_data_free(d);
        }
        char note[1024];
        rc_impacts_vibration_note(&im, m, steps, note, sizeof note);
        printf("    %s, %ld steps (T %.3g s): note \"%.160s...\"\n", events ? "200 000 events" : "no events", steps, T,
               note);
        if (events) {
            ENSURE(strstr(note, "0 impacts") != NULL && strstr(note, "and 200000 event instants") != NULL);
            ENSURE(strstr(note, "(~30 steps each)") != NULL && strstr(note, "~50 each, a restart") != NULL);
            ENSURE(strstr(note, "/INTER/TYPE6/1") != NULL && strstr(note, "lets them settle") != NULL);
        } else {
            ENSURE(note[0] == '\0');
        }
        rc_impacts_free(&im);
    }
    rc_model_free(m);
}

/* The Max_steps hint counts the events the vibration drives too: the ball
 * on its undamped Stiff line (T = 1.99e-5 s) closed, an output interval of
 * 0.01 s (502 periods: 15 000 steps, under half the default Max_steps of
 * 100 000, no hint) and 1 000 event instants of its interface in the 0.01 s
 * run so far (its friction's stick and slip: 50 000 steps more, fuzz
 * 253000218, a ball against an undamped wall stopped at Max_steps): the
 * hint names the contact, the events and the remedy. */
static void test_max_steps_hint_counts_driven_events(void)
{
    rc_model *m = load_text("vib_hint.rad", VIB_DECK(""));
    ENSURE(m != NULL);
    if (!m) return;
    ENSURE(m->max_steps == 100000);
    for (int events = 0; events < 2; events++) {
        rc_impacts im;
        ENSURE(rc_impacts_init(&im, m) == 0);
        im.cur[0] = 0; /* closed now */
        im.nevt[0] = events ? 1000 : 0;
        char hint[1024];
        rc_impacts_max_steps_hint(&im, m, 0.01, 0.01, 0.04, hint, sizeof hint);
        printf("    %s: \"%.200s...\"\n", events ? "1 000 events" : "no events", hint);
        if (events) {
            ENSURE(strstr(hint, "the contact /INTER/TYPE6/1 vibrates undamped") != NULL);
            ENSURE(strstr(hint, "and 1e+03 event instants of its own") != NULL);
            ENSURE(strstr(hint, "at 30 a period and 50 an event") != NULL);
        } else {
            ENSURE(hint[0] == '\0');
        }
        rc_impacts_free(&im);
    }
    rc_model_free(m);
}

/* The same ball with /SOLVER Max_steps 3000 between output times 0.05 s
 * apart: following its 2 500 periods takes some 75 000 steps, and the run
 * stops at Max_steps; the failure says that the contact vibrates undamped,
 * with its period, and what to do. Damped, a Max_steps of 60 also stops
 * it, but no vibration is to blame: no such hint. */
static void test_max_steps_failure_names_undamped_vibration(void)
{
    for (int damped = 0; damped < 2; damped++) {
        rc_model *m = load_text(damped ? "vibmax_damped.rad" : "vibmax_undamped.rad",
                                damped ? VIB_DECK_S("50", "/SOLVER\n1,0,60\n") : VIB_DECK_S("", "/SOLVER\n1,0,3000\n"));
        ENSURE(m != NULL);
        if (!m) return;
        rc_run_options opt = {.dt_out_override = 0.05};
        rc_stats st;
        rc_error e;
        ENSURE(rc_run(m, &opt, &st, &e) == RC_ESOLVER);
        printf("    %s: %s\n", damped ? "Visc 50, Max_steps 60" : "undamped, Max_steps 3000", e.msg);
        ENSURE(strstr(e.msg, "CV_TOO_MUCH_WORK") != NULL);
        const char *p = strstr(e.msg, "vibrates undamped (period ");
        if (damped) {
            ENSURE(p == NULL);
        } else {
            ENSURE(p != NULL && strstr(e.msg, "the contact /INTER/TYPE6/1") != NULL);
            const double T = p ? atof(p + 26) : NAN;
            ENSURE_NEAR(T, 2.0 * 3.14159265358979 * sqrt(1e-3 / 1e8), 1e-2, 0.0);
            ENSURE(strstr(e.msg, "normal damping") != NULL && strstr(e.msg, "raise /SOLVER Max_steps") != NULL);
        }
        rc_model_free(m);
    }
}

void suite_persist(void);
void suite_persist(void)
{
    RUN_TEST(test_persist_rule);
    RUN_TEST(test_persist_box_resting_mean_force);
    RUN_TEST(test_persist_sliding_block_slip_distance);
    RUN_TEST(test_persist_ball_bounces_then_rests);
    RUN_TEST(test_elastic_contact_does_not_settle);
    RUN_TEST(test_ida_settle_projection_decides_other_modes);
    RUN_TEST(test_breakpoint_jump_decides_friction_again);
    RUN_TEST(test_sfric_ramps_in_at_zero_force);
    RUN_TEST(test_vibration_note_undamped_stiff_line);
    RUN_TEST(test_vibration_note_counts_contacts_ringing_together_once);
    RUN_TEST(test_vibration_note_counts_driven_events);
    RUN_TEST(test_max_steps_hint_counts_driven_events);
    RUN_TEST(test_max_steps_failure_names_undamped_vibration);
}
