/* The physics checks of every run (solver/guards.c) and of the start
 * (engine/analyses/start.c): each check fires on a deliberately bad state or deck,
 * and stays quiet on good ones; a violation stops the run with
 * RC_EPHYSICS and a results file marked "physics check failed", or is
 * recorded when the run was asked to go on. */
#include "harness.h"

#include <netcdf.h>
#include <stdlib.h>
#include <unistd.h>

#include "engine/assembly/bounds.h"
#include "model/coupling.h"
#include "model/model.h"
#include "ricochet/ricochet.h"
#include "solver/guards.h"
#include "solver/integrator.h"
#include "testutil.h"
#include "engine/assembly/assembly.h"
#include "engine/events/events.h"

#define DEMO "cases/demo_sphere_drop.rad"

/* The demo's sphere (R = 0.05 m) over the floor z = 0: its centre at z,
 * its mass, the load curve's slope k [N/m], Visc, Fric, the interface's
 * Tstart and Inacti, the run's end time and /RUN On_viol. malloc'd. */
typedef struct {
    double z, mass, k, visc, fric, tstart, tend;
    int inacti, on_viol;
} sphere_opts;

static char *sphere_deck(const sphere_opts *o)
{
    char *s = malloc(4096);
    if (!s) return NULL;
    snprintf(s, 4096,
             "/BEGIN\n"
             "guards test: a sphere over a floor\n"
             "      2022         0\n"
             "                  kg                   m                   s\n"
             "                  kg                   m                   s\n"
             "/FUNCT/1\n"
             "linear load curve\n"
             "                   0                   0\n"
             "                   1%20.12g\n"
             "/NODE\n"
             "         1                   0                   0%20.12g\n"
             "/RBODY/1\n"
             "sphere\n"
             "         1                              %20.12g\n"
             "               0.001               0.001               0.001\n"
             "                   0                   0                   0\n"
             "/SURF/ELLIPS/1\n"
             "sphere surface R = 0.05 m\n"
             "         0         2         1\n"
             "                   0                   0%20.12g\n"
             "                0.05                0.05                0.05\n"
             "/SURF/PLANE/2\n"
             "floor z = 0\n"
             "                   0                   0                   0\n"
             "                   0                   0                   1\n"
             "/GRNOD/NODE/1\n"
             "sphere node\n"
             "         1\n"
             "/GRAV/1\n"
             "gravity\n"
             "         0         Z         0         0         0                             1               -9.81\n"
             "/INTER/TYPE6/1\n"
             "sphere on floor\n"
             "         1         2\n"
             "                   0%20.12g                   0%20.12g\n"
             "                   0         0%10d         0         0\n"
             "         1         0                                                 0\n"
             "         0\n"
             "%20.12g         0         0\n"
             "/RUN\n"
             "%20.12g%20.12g         0%10d\n"
             "/END\n",
             o->k, o->z, o->mass, o->z, o->fric, o->tstart, o->inacti, o->visc, o->tend, o->tend / 100, o->on_viol);
    return s;
}

static const sphere_opts DROP = {0.15, 1.0, 1e6, 148.710194195, 0.0, 0.0, 0.3, 0, 0};

static rc_model *sphere_model(const sphere_opts *o, rc_error *e)
{
    char *text = sphere_deck(o);
    rc_model *m = text ? tu_compile_text(text, "guards_sphere.rad", e) : NULL;
    free(text);
    return m;
}

static void tmp_nc(char *buf, size_t n, const char *tag)
{
    snprintf(buf, n, "/tmp/rc_test_guards_%ld_%s.nc", (long)getpid(), tag);
}

/* A global text attribute of a results file ("" when absent). */
static void nc_text(const char *path, const char *name, char *buf, size_t n)
{
    int ncid;
    size_t len = 0;
    buf[0] = '\0';
    if (nc_open(path, NC_NOWRITE, &ncid) != NC_NOERR) return;
    if (nc_inq_attlen(ncid, NC_GLOBAL, name, &len) == NC_NOERR && len < n) {
        nc_get_att_text(ncid, NC_GLOBAL, name, buf);
        buf[len] = '\0';
    }
    nc_close(ncid);
}

/* Rows of the violation table of a results file (-1: none). */
static long nc_violations(const char *path)
{
    int ncid, dim;
    size_t n = 0;
    if (nc_open(path, NC_NOWRITE, &ncid) != NC_NOERR) return -1;
    long r = nc_inq_dimid(ncid, "violation", &dim) == NC_NOERR && nc_inq_dimlen(ncid, dim, &n) == NC_NOERR ? (long)n : -1;
    nc_close(ncid);
    return r;
}

/* ---- a run's state, checked by hand -------------------------------- */
typedef struct {
    rc_model *m;
    rc_data *d;
    rc_guards *g;
    double *y;
    frame_buf fb;
    long steps; /* the integrator steps the bench pretends to take */
} bench;

static int bench_open(bench *b, rc_model *m, int warn)
{
    memset(b, 0, sizeof *b);
    b->m = m;
    b->d = rc_data_new(m);
    b->g = rc_guards_new(m, warn, 0);
    b->y = calloc((size_t)m->ny + 1, sizeof(double));
    if (!b->d || !b->g || !b->y || !rc_bk_frame_alloc(m, &b->fb)) return 0;
    rc_initial_state(m, b->y);
    rc_modes_init(m, b->d, 0.0, b->y);
    rc_guards_started(b->g, b->d);
    return 1;
}

static void bench_close(bench *b)
{
    rc_bk_frame_free(&b->fb);
    rc_guards_free(b->g);
    rc_data_free(b->d);
    free(b->y);
    rc_model_free(b->m);
}

/* A record of the bench's state at t: 1 when a check stops the run. */
static int bench_record(bench *b, double t)
{
    rc_error e;
    /* one integrator step to this state (the checks run once per step) */
    if (rc_guards_step(b->g, b->d, t, b->y, NULL, 0, ++b->steps)) return 1;
    rc_bk_write_frame(b->m, b->d, NULL, &b->fb, t, b->y, 0, &e);
    return rc_guards_record(b->g, b->d, t, b->y, &b->fb);
}

/* The checks' rows, through the statistics (warn mode). */
static long bench_violations(bench *b, char *note, size_t n)
{
    rc_stats s;
    memset(&s, 0, sizeof s);
    rc_guards_finish(b->g, b->d, &s, NULL, 0);
    if (note) snprintf(note, n, "%s", s.physics_note);
    return s.violations;
}

/* Each dissipation channel: a decrease beyond the tolerance fires, naming
 * the channel and the interface; an increase does not. */
static void test_guards_channel_decrease_fires(void)
{
    rc_error e;
    sphere_opts o = DROP;
    o.fric = 0.3;
    o.z = 0.05; /* touching: closed at the start */
    for (int ch = 0; ch < 3; ch++) {
        rc_model *m = sphere_model(&o, &e);
        ENSURE(m != NULL);
        if (!m) return;
        bench b;
        ENSURE(bench_open(&b, m, 0));
        const int a = m->inter_eadr[0];
        const int idx[3] = {a + 1, a, a + m->inter_fr[0].widx}; /* W_damp, W_load, W_fric */
        static const char *const name[3] = {"energy_damping of /INTER/TYPE6/1", "energy_hysteresis of /INTER/TYPE6/1",
                                            "energy_friction of /INTER/TYPE6/1"};
        double *v = b.y + m->body_yadr[0] + 9;
        *v = -1.0; /* moving down at 1 m/s */
        /* the hysteresis of an elastic law with a damper is the energy
         * lost at its releases, kept by the events (rc_data.inter_hacc) */
        double *acc = ch == 1 && rc_inter_release_ledger(m, 0) ? b.d->inter_hacc : b.y + idx[ch];
        ENSURE(bench_record(&b, 0.0) == 0); /* the baseline */
        *acc += 0.01; /* 0.01 J dissipated from the kinetic energy: fine */
        *v = -sqrt(1.0 - 2 * 0.01);
        ENSURE(bench_record(&b, 0.001) == 0);
        *acc -= 0.02; /* 0.02 J back: a dissipation running backwards */
        ENSURE(bench_record(&b, 0.002) == 1);
        const char *msg = rc_guards_message(b.g);
        printf("    %s\n", msg);
        ENSURE(strstr(msg, name[ch]) != NULL && strstr(msg, "decreased by 0.02 J") != NULL);
        ENSURE(strstr(msg, "between t = 0.001 and 0.002 s") != NULL);
        bench_close(&b);
    }
}

/* A coupling's damper: its dissipation running backwards fires, naming
 * the coupling. */
static void test_guards_coupling_damping_fires(void)
{
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    ENSURE(rc_case_load("validation/cpl_spring_damped/case.rad", &c, &e) == RC_OK && rc_model_compile(c, &m, &e) == RC_OK);
    rc_case_free(c);
    if (!m) return;
    ENSURE(m->cpl->n >= 1 && m->cpl->kind[0] == RC_CPL_SPRING);
    bench b;
    ENSURE(bench_open(&b, m, 0));
    ENSURE(bench_record(&b, 0.0) == 0);
    b.y[m->cpl->eadr[0] + 1] -= 0.01; /* W_damp of the first coupling */
    ENSURE(bench_record(&b, 0.001) == 1);
    printf("    %s\n", rc_guards_message(b.g));
    char want[96];
    snprintf(want, sizeof want, "energy_coupling_damping of %s decreased by 0.01 J", m->cpl->name[0]);
    ENSURE(strstr(rc_guards_message(b.g), want) != NULL);
    bench_close(&b);
}

/* The tolerance follows the run's rtol: a decrease of 1e-4 J fires at
 * rtol 1e-8 and is within the numerical drift rtol 1e-3 allows. */
static void test_guards_channel_tolerance_follows_rtol(void)
{
    rc_error e;
    sphere_opts o = DROP;
    o.z = 0.05;
    const double rtol[2] = {1e-8, 1e-3};
    for (int k = 0; k < 2; k++) {
        rc_model *m = sphere_model(&o, &e);
        ENSURE(m != NULL);
        if (!m) return;
        ENSURE(rc_model_set_rtol(m, rtol[k], &e) == RC_OK);
        bench b;
        ENSURE(bench_open(&b, m, 1));
        bench_record(&b, 0.0);
        b.y[m->inter_eadr[0] + 1] -= 1e-4;
        bench_record(&b, 0.001);
        const long n = bench_violations(&b, NULL, 0);
        printf("    rtol %g: %ld violation(s) for a decrease of 1e-4 J\n", rtol[k], n);
        ENSURE(n == (k == 0 ? 1 : 0));
        bench_close(&b);
    }
}

/* The mechanical energy: kinetic energy appearing from nothing fires; the
 * same body falling (potential into kinetic) does not. */
static void test_guards_energy_created_fires(void)
{
    rc_error e;
    rc_model *m = sphere_model(&DROP, &e);
    ENSURE(m != NULL);
    if (!m) return;
    bench b;
    ENSURE(bench_open(&b, m, 1));
    double *s = b.y + m->body_yadr[0];
    ENSURE(bench_record(&b, 0.0) == 0);
    /* a free fall of 5 cm: the same mechanical energy */
    s[2] -= 0.05;
    s[9] = -sqrt(2 * 9.81 * 0.05);
    ENSURE(bench_record(&b, 0.1) == 0);
    char note[700];
    ENSURE(bench_violations(&b, note, sizeof note) == 0);
    /* and then 0.5 J more kinetic energy than the fall gives */
    s[9] = -sqrt(2 * 9.81 * 0.05 + 1.0);
    ENSURE(bench_record(&b, 0.2) == 0); /* warn: goes on */
    ENSURE(bench_violations(&b, note, sizeof note) == 2);
    ENSURE(strstr(note, "mechanical energy") != NULL && strstr(note, "energy created") != NULL);
    ENSURE(strstr(note, "0.5 J above") != NULL);
    /* and the balance: energy_total rose by the same 0.5 J */
    const rc_violation *v = NULL;
    ENSURE(rc_guards_rows(b.g, &v) == 2);
    for (int k = 0; k < 2; k++) printf("    %s\n", v[k].message);
    ENSURE(!strcmp(v[0].check, "mechanical_energy") && !strcmp(v[1].check, "energy_balance"));
    ENSURE_NEAR(v[1].value, 0.5, 1e-9, 0);
    bench_close(&b);
}

/* Non-finite values in the state and in the energies. */
static void test_guards_non_finite_fires(void)
{
    rc_error e;
    rc_model *m = sphere_model(&DROP, &e);
    ENSURE(m != NULL);
    if (!m) return;
    bench b;
    ENSURE(bench_open(&b, m, 0));
    ENSURE(bench_record(&b, 0.0) == 0);
    b.y[m->body_yadr[0] + 8] = NAN;
    ENSURE(bench_record(&b, 0.01) == 1);
    printf("    %s\n", rc_guards_message(b.g));
    ENSURE(strstr(rc_guards_message(b.g), "/RBODY/1, velocity y") != NULL);
    bench_close(&b);
    /* a body of 1.7e308 kg is refused at input (its weight overflows) */
    sphere_opts o = DROP;
    o.mass = 1.7e308;
    ENSURE(sphere_model(&o, &e) == NULL);
    /* a finite state whose kinetic energy overflows: 1e200 m/s */
    m = sphere_model(&DROP, &e);
    ENSURE(m != NULL);
    if (!m) return;
    ENSURE(bench_open(&b, m, 0));
    ENSURE(bench_record(&b, 0.0) == 0);
    b.y[m->body_yadr[0] + 8] = 1e200;
    ENSURE(bench_record(&b, 0.01) == 1);
    printf("    %s\n", rc_guards_message(b.g));
    ENSURE(strstr(rc_guards_message(b.g), "non-finite energy_kinetic") != NULL);
    bench_close(&b);
    /* a non-finite force in a record */
    m = sphere_model(&DROP, &e);
    ENSURE(m != NULL);
    if (!m) return;
    ENSURE(bench_open(&b, m, 0));
    ENSURE(bench_record(&b, 0.0) == 0);
    rc_bk_write_frame(m, b.d, NULL, &b.fb, 0.001, b.y, 0, &e);
    b.fb.fdamp[0] = INFINITY;
    ENSURE(rc_guards_record(b.g, b.d, 0.001, b.y, &b.fb) == 1);
    printf("    %s\n", rc_guards_message(b.g));
    ENSURE(strstr(rc_guards_message(b.g), "non-finite damping force of /INTER/TYPE6/1") != NULL);
    bench_close(&b);
}

/* The sphere pressed 1 um into the floor (F_n = 1 N, k = 1e6 N/m, at
 * rest), TYPE6 Fric 0.3, undamped. */
static rc_model *pressed_sphere(void)
{
    rc_error e;
    sphere_opts o = DROP;
    o.fric = 0.3;
    o.visc = 0.0;
    o.z = 0.05 - 1e-6;
    rc_model *m = sphere_model(&o, &e);
    ENSURE(m != NULL);
    return m;
}

/* Coulomb's bound at every record: that sphere sticking with its spring
 * loaded to 0.2 N passes; loaded to 10 N, beyond the limit 0.3 N (a stick
 * the slip root never saw), it fires, naming the interface. */
static void test_guards_friction_limit_fires(void)
{
    rc_model *m = pressed_sphere();
    if (!m) return;
    ENSURE(m->inter_fr[0].tidx >= 0);
    bench b;
    ENSURE(bench_open(&b, m, 0));
    ENSURE(b.d->inter_mode[0] == RC_MODE_CLOSED && b.d->inter_slip[0] == 0);
    double *ft = b.y + m->inter_eadr[0] + m->inter_fr[0].tidx;
    ft[0] = 0.2;
    ENSURE(bench_record(&b, 0.0) == 0);
    ft[0] = 10.0;
    ENSURE(bench_record(&b, 0.001) == 1);
    const char *msg = rc_guards_message(b.g);
    printf("    %s\n", msg);
    ENSURE(strstr(msg, "friction force of /INTER/TYPE6/1 is 10 N") != NULL);
    ENSURE(strstr(msg, "beyond its limit 0.3 N") != NULL);
    bench_close(&b);
}

/* The limit is known only as well as F_n: the same sphere's friction may
 * exceed mu F_n by mu times the normal force's tolerance (its stiffness
 * scale times its position tolerance here: no Stiff line), and no more:
 * half of that beyond the bound passes, twice that fires. The report
 * carries the coefficient (0.3). */
static void test_guards_friction_limit_normal_force_tolerance(void)
{
    rc_model *m = pressed_sphere();
    if (!m) return;
    bench b;
    ENSURE(bench_open(&b, m, 0));
    rc_inter_report r;
    rc_inter_report_eval_d(m, b.d, 0, 0.0, b.y, &r);
    ENSURE_NEAR(r.mu, 0.3, 1e-15, 0.0);
    const double dfn = fmax(m->inter_hband[0], m->inter_kscale[0] * m->atol[m->body_yadr[0]]);
    ENSURE(dfn > 0 && isfinite(dfn));
    const double bound = r.flim * (1.0 + RC_SLIP_BAND + 1e-6) + rc_fric_band(m, 0);
    printf("    F_n %.6g N, limit %.6g N, normal force tolerance %.3g N\n", r.fn, r.flim, dfn);
    double *ft = b.y + m->inter_eadr[0] + m->inter_fr[0].tidx;
    ft[0] = bound + 0.5 * 0.3 * dfn;
    ENSURE(bench_record(&b, 0.0) == 0);
    ft[0] = bound + 2.0 * 0.3 * dfn;
    ENSURE(bench_record(&b, 0.001) == 1);
    ENSURE(strstr(rc_guards_message(b.g), "friction force of /INTER/TYPE6/1") != NULL);
    bench_close(&b);
}

/* Penetration beyond the bound, and an open interface penetrating. */
static void test_guards_penetration_fires(void)
{
    rc_error e;
    rc_model *m = sphere_model(&DROP, &e);
    ENSURE(m != NULL);
    if (!m) return;
    bench b;
    ENSURE(bench_open(&b, m, 1));
    double fb;
    rc_scene sc;
    rc_scene_scales(m, &sc);
    const double pb = rc_pen_bound(m, 0, &sc, NULL, &fb);
    /* linear k = 1e6: the force 1e3 max(m g, F_impact) over k, under R */
    printf("    bound %.6g m (force %.6g N; weight %.4g N, E_a %.4g J)\n", pb, fb, sc.weight, sc.eavail);
    ENSURE(pb > 0 && pb <= 0.05 && isfinite(fb) && fb >= 1e3 * sc.weight);
    ENSURE_NEAR(pb, fmin(fb / 1e6, 0.05), 1e-9, 0); /* at most the sphere's radius */
    double *s = b.y + m->body_yadr[0];
    /* open, the sphere 1 mm into the floor: the contact was never closed */
    s[2] = 0.049 - m->origin[2]; /* the model's coordinates */
    ENSURE(b.d->inter_mode[0] == RC_MODE_OPEN);
    ENSURE(rc_guards_step(b.g, b.d, 0.1, b.y, NULL, 0, ++b.steps) == 0);
    char note[700];
    ENSURE(bench_violations(&b, note, sizeof note) == 1);
    printf("    %s\n", note);
    ENSURE(strstr(note, "is open (no force) while penetrating by 0.001 m") != NULL);
    /* at a located root the event is still to come: nothing within 10 p_s
     * (beyond, the closing jumped: entered_deep, test_guards_entered_deep) */
    ENSURE(isfinite(m->inter_pscale[0]) && 5 * m->inter_pscale[0] < 1e-3);
    s[2] = 0.05 - 5 * m->inter_pscale[0] - m->origin[2]; /* the model's coordinates */
    ENSURE(rc_guards_step(b.g, b.d, 0.11, b.y, NULL, 1, ++b.steps) == 0);
    ENSURE(bench_violations(&b, NULL, 0) == 1);
    /* closed, far beyond the bound: the sphere passes through */
    b.d->inter_mode[0] = RC_MODE_CLOSED;
    s[2] = 0.05 - 1.5 * pb - m->origin[2]; /* the model's coordinates */
    rc_guards_step(b.g, b.d, 0.2, b.y, NULL, 0, ++b.steps);
    ENSURE(bench_violations(&b, note, sizeof note) == 2);
    ENSURE(b.g != NULL && strstr(note, "open") != NULL); /* the first one stays first */
    /* back within the bound: no new row; beyond again: a new one */
    s[2] = 0.049 - m->origin[2]; /* the model's coordinates */
    rc_guards_step(b.g, b.d, 0.3, b.y, NULL, 0, ++b.steps);
    ENSURE(bench_violations(&b, NULL, 0) == 2);
    s[2] = 0.05 - 2 * pb - m->origin[2]; /* the model's coordinates */
    rc_guards_step(b.g, b.d, 0.4, b.y, NULL, 0, ++b.steps);
    ENSURE(bench_violations(&b, NULL, 0) == 3);
    bench_close(&b);
}

/* A thin box on a soft floor: the law's bound (1e3 x the weight over a soft
 * stiffness) and the box's half-diagonal both lie beyond its thickness; the
 * bound is half the box's smallest half-size (a box 0.25 m thick sank 0.18
 * m into a belt under a bound of its half-diagonal, 0.26 m), strictly below
 * the deepest a box reports, its smallest half-size, where its nearest face
 * changes (a meshed box sank 2.25 m through a belt whose reported depth
 * stopped at that half-size, the bound then). A sphere's is its radius, a
 * plane has none. */
static void test_guards_penetration_bound_half_thickness(void)
{
    static const char deck[] = "/NODE\n1,0,0,0.03\n"
                               "/RBODY/1\nplate\n1,,,,2.0\n0.01,0.02,0.03\n0,0,0\n"
                               "/SURF/BOX/1\nplate\n1\n0,0,0.03\n0.18,0.14,0.03\n"
                               "/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n"
                               "/GRNOD/NODE/1\nplate\n1\n"
                               "/GRAV/1\ng\n0,Z,0,0,1,,1,-9.81\n"
                               "/FUNCT/1\nload\n0,0\n1,1\n"
                               "/INTER/TYPE6/1\nplate on floor\n1,2\n\n\n1,0,1.0,10.0\n\n0\n"
                               "/RUN\n0.01,0.001\n";
    rc_model *m = TU_COMPILE_OK(deck, "guards_plate.rad");
    if (!m) return;
    double fb;
    rc_scene sc;
    rc_scene_scales(m, &sc);
    const double pb = rc_pen_bound(m, 0, &sc, NULL, &fb), size = rc_body_size(m, m->inter_ba[0]);
    printf("    bound %.6g m; the law's %.6g m (k = 10 N/m), the box's half-diagonal %.6g m\n", pb, fb / 10.0, size);
    ENSURE(size > 0.2 && fb / 10.0 > 1.0);
    ENSURE_NEAR(pb, 0.015, 0, 1e-12);
    ENSURE(pb < 0.03); /* reachable: the box reports at most its half-size 0.03 m */
    rc_model_free(m);
}

/* Two spheres: centres closer than (R1 + R2)/2. */
static void test_guards_sphere_centres_fire(void)
{
    const char *deck =
        "/BEGIN\n"
        "two spheres\n"
        "      2022         0\n"
        "                  kg                   m                   s\n"
        "                  kg                   m                   s\n"
        "/FUNCT/1\n"
        "soft\n"
        "                   0                   0\n"
        "                   1                  10\n"
        "/NODE\n"
        "         1                   0                   0                   0\n"
        "         2                 0.2                   0                   0\n"
        "/RBODY/1\n"
        "a\n"
        "         1                                                 1\n"
        "               0.001               0.001               0.001\n"
        "                   0                   0                   0\n"
        "/RBODY/2\n"
        "b\n"
        "         2                                                 1\n"
        "               0.001               0.001               0.001\n"
        "                   0                   0                   0\n"
        "/SURF/ELLIPS/1\n"
        "a\n"
        "         0         2         1\n"
        "                   0                   0                   0\n"
        "                0.05                0.05                0.05\n"
        "/SURF/ELLIPS/2\n"
        "b\n"
        "         0         2         2\n"
        "                 0.2                   0                   0\n"
        "                0.05                0.05                0.05\n"
        "/INTER/TYPE6/7\n"
        "a on b\n"
        "         1         2\n"
        "                                                           0\n"
        "                   0         0         0         0         0\n"
        "         1         0                                                 0\n"
        "         0\n"
        "                   0         0         0\n"
        "/GRNOD/NODE/1\n"
        "a's node\n"
        "         1\n"
        "/INIVEL/TRA/1\n"
        "towards b\n"
        "                   1                   0                   0         1         0\n"
        "/RUN\n"
        "                 0.5               0.001\n"
        "/END\n";
    rc_error e;
    rc_model *m = tu_compile_text(deck, "guards_spheres.rad", &e);
    ENSURE(m != NULL);
    if (!m) {
        printf("    %s\n", e.msg);
        return;
    }
    bench b;
    ENSURE(bench_open(&b, m, 1));
    double *s = b.y + m->body_yadr[1];
    s[0] = 0.06 - m->origin[0]; /* apart by 0.06 m: 0.06 < (0.05 + 0.05)/2 is false */
    b.d->inter_mode[0] = RC_MODE_CLOSED;
    rc_guards_step(b.g, b.d, 0.01, b.y, NULL, 0, ++b.steps);
    long n0 = bench_violations(&b, NULL, 0);
    s[0] = 0.04 - m->origin[0];
    rc_guards_step(b.g, b.d, 0.02, b.y, NULL, 0, ++b.steps);
    const long n1 = bench_violations(&b, NULL, 0);
    const rc_violation *v = NULL;
    const int nr = rc_guards_rows(b.g, &v);
    int centres = 0;
    for (int k = 0; k < nr; k++) {
        printf("    %s\n", v[k].message);
        centres += !strcmp(v[k].check, "sphere_centres") && !strcmp(v[k].element, "/INTER/TYPE6/7");
    }
    ENSURE(n0 == 0 && n1 > n0 && centres == 1);
    bench_close(&b);
    /* the whole run: the spheres meet at 1 m/s on a soft law and pass
     * through each other (the bound stops it first, or the centres) */
    m = tu_compile_text(deck, "guards_spheres.rad", &e);
    ENSURE(m != NULL);
    if (!m) return;
    rc_stats st;
    rc_run_options opt = {.on_violation = RC_ON_VIOLATION_STOP};
    ENSURE(rc_run(m, &opt, &st, &e) == RC_EPHYSICS);
    printf("    run: %s\n", e.msg);
    ENSURE(strstr(e.msg, "/INTER/TYPE6/7") != NULL);
    ENSURE(st.violations == 1 && st.t_end < 0.5);
    opt.on_violation = RC_ON_VIOLATION_WARN;
    ENSURE(rc_run(m, &opt, &st, &e) == RC_OK);
    printf("    warn: %ld violations, %s\n", st.violations, st.physics_note);
    ENSURE(st.violations >= 2);
    rc_model_free(m);
}

/* Good runs pass: the demo on both backends, a resting start. */
static void test_guards_good_runs_pass(void)
{
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    ENSURE(rc_case_load(DEMO, &c, &e) == RC_OK && rc_model_compile(c, &m, &e) == RC_OK);
    rc_case_free(c);
    if (!m) return;
    for (int method = 1; method <= 2; method++) {
        char path[256], attr[800];
        tmp_nc(path, sizeof path, "demo");
        ENSURE(rc_model_set_method(m, method, &e) == RC_OK);
        rc_stats st;
        rc_run_options opt = {.output_path = path};
        ENSURE(rc_run(m, &opt, &st, &e) == RC_OK);
        printf("    method %d: %s; contacts: \"%s\"\n", method, st.physics_note, st.contacts_note);
        ENSURE(st.violations == 0 && !strncmp(st.physics_note, "passed", 6));
        nc_text(path, "physics_checks", attr, sizeof attr);
        ENSURE(!strncmp(attr, "passed", 6));
        ENSURE(nc_violations(path) == 0);
        unlink(path);
    }
    rc_model_free(m);
    /* a sphere resting at its static penetration m g / k */
    sphere_opts o = DROP;
    o.z = 0.05 - 9.81 / 1e6;
    m = sphere_model(&o, &e);
    ENSURE(m != NULL);
    if (!m) {
        printf("    %s\n", e.msg);
        return;
    }
    rc_stats st;
    ENSURE(rc_run(m, NULL, &st, &e) == RC_OK);
    printf("    resting start: %s; contacts: %s\n", st.physics_note, st.contacts_note);
    ENSURE(st.violations == 0 && strstr(st.contacts_note, "closed from the start and never reopened (/INTER/TYPE6/1)"));
    rc_model_free(m);
    /* a sphere that never reaches the floor */
    o = DROP;
    o.tend = 0.05;
    m = sphere_model(&o, &e);
    ENSURE(m != NULL && rc_run(m, NULL, &st, &e) == RC_OK);
    ENSURE(strstr(st.contacts_note, "1 never closed (/INTER/TYPE6/1)") != NULL);
    rc_model_free(m);
}

/* A heavy sphere on a soft floor sinks through it: the run stops with
 * RC_EPHYSICS, the file kept and marked; with warn it goes on and the
 * violation is in the file's table. */
static void test_guards_soft_floor_stops_run(void)
{
    rc_error e;
    sphere_opts o = DROP;
    o.mass = 1000;
    o.k = 1e3;
    o.visc = 2000;
    rc_model *m = sphere_model(&o, &e);
    ENSURE(m != NULL);
    if (!m) {
        printf("    %s\n", e.msg);
        return;
    }
    char path[256], status[1200], complete[16];
    tmp_nc(path, sizeof path, "soft");
    rc_stats st;
    rc_run_options opt = {.output_path = path};
    ENSURE(rc_run(m, &opt, &st, &e) == RC_EPHYSICS);
    ENSURE(rc_status_exit_code(RC_EPHYSICS) == 5);
    printf("    %s\n", e.msg);
    ENSURE(strstr(e.msg, "penetration of /INTER/TYPE6/1") != NULL && strstr(e.msg, "pass through") != NULL);
    nc_text(path, "status", status, sizeof status);
    nc_text(path, "complete", complete, sizeof complete);
    ENSURE(!strncmp(status, "physics check failed: penetration of /INTER/TYPE6/1", 51));
    ENSURE(!strcmp(complete, "no"));
    ENSURE(nc_violations(path) == 1);
    ENSURE(st.t_end > 0 && st.t_end < o.tend);
    unlink(path);
    /* warn: the run goes on to its end, the violation recorded */
    opt.on_violation = RC_ON_VIOLATION_WARN;
    ENSURE(rc_run(m, &opt, &st, &e) == RC_OK);
    nc_text(path, "status", status, sizeof status);
    ENSURE(!strcmp(status, "complete") && st.violations >= 1 && nc_violations(path) == st.violations);
    nc_text(path, "physics_checks", status, sizeof status);
    printf("    warn: %s\n", status);
    ENSURE(strstr(status, "the run went on") != NULL);
    unlink(path);
    rc_model_free(m);
    /* the deck's /RUN On_viol 2 asks the same */
    o.on_viol = 2;
    m = sphere_model(&o, &e);
    ENSURE(m != NULL && rc_run(m, NULL, &st, &e) == RC_OK && st.violations >= 1);
    /* and the option overrides the deck */
    opt.output_path = NULL;
    opt.on_violation = RC_ON_VIOLATION_STOP;
    ENSURE(m != NULL && rc_run(m, &opt, &st, &e) == RC_EPHYSICS);
    rc_model_free(m);
}

/* An interface activated (Tstart) while its bodies overlap releases the
 * energy of the overlap: energy created, caught by the mechanical check. */
static void test_guards_activation_overlap_creates_energy(void)
{
    rc_error e;
    sphere_opts o = DROP;
    o.z = 0.045; /* 5 mm inside the floor, accepted: the interface starts later */
    o.tstart = 0.01;
    rc_model *m = sphere_model(&o, &e);
    ENSURE(m != NULL);
    if (!m) {
        printf("    %s\n", e.msg);
        return;
    }
    rc_stats st;
    ENSURE(rc_run(m, NULL, &st, &e) == RC_EPHYSICS);
    printf("    %s\n", e.msg);
    ENSURE(strstr(e.msg, "mechanical energy") != NULL && strstr(e.msg, "energy created") != NULL);
    rc_model_free(m);
}

/* The start: an overlap is an input error naming both surfaces, the
 * interface and the depth; a resting start and Inacti 5 are accepted. */
static void test_guards_start_overlap(void)
{
    rc_error e;
    sphere_opts o = DROP;
    o.z = 0.01; /* 4 cm inside the floor */
    char *text = sphere_deck(&o);
    TU_EXPECT_TEXT_ERROR(text, "guards_inside.rad", "guards_inside.rad:32: card /INTER/TYPE6/1",
                         "surfaces /SURF/ELLIPS/1 and /SURF/PLANE/2 overlap at t = 0", "penetration 0.04 m",
                         "800 J of elastic energy", "Inacti = 5");
    free(text);
    o.inacti = 5;
    rc_model *m = sphere_model(&o, &e);
    ENSURE(m != NULL);
    rc_model_free(m);
    /* the deck accepts it (/RUN On_viol 2): the run's first violation */
    o.inacti = 0;
    o.on_viol = 2;
    o.tend = 0.01;
    m = sphere_model(&o, &e);
    ENSURE(m != NULL && m->start_note != NULL);
    if (m) {
        rc_stats st;
        ENSURE(rc_run(m, NULL, &st, &e) == RC_OK);
        printf("    accepted: %.160s...\n", st.physics_note);
        ENSURE(st.violations >= 1 && strstr(st.physics_note, "the first: ") && strstr(st.physics_note, "overlap at t = 0"));
        rc_run_options opt = {.on_violation = RC_ON_VIOLATION_STOP};
        ENSURE(rc_run(m, &opt, &st, &e) == RC_EPHYSICS && st.t_end == 0.0);
    }
    rc_model_free(m);
    /* at its static penetration, and 10 times deeper: still a resting start,
     * silent at its static penetration; 50 times deeper (0.125 J, below
     * E_s) accepted with a notice that says how deep */
    const double depth[3] = {9.81e-6, 9.81e-5, 5e-4};
    for (int k = 0; k < 3; k++) {
        o = DROP;
        o.z = 0.05 - depth[k];
        m = sphere_model(&o, &e);
        ENSURE(m != NULL);
        if (!m) continue;
        const char *note = rc_model_note_count(m) > 0 ? rc_model_note(m, 0) : "";
        printf("    %g m deep: %d notice(s) %.200s\n", depth[k], rc_model_note_count(m), note);
        if (k == 0) ENSURE(rc_model_note_count(m) == 0);
        if (k == 2)
            ENSURE(rc_model_note_count(m) == 1 && strstr(note, "card /INTER/TYPE6/1") &&
                   strstr(note, "overlap at t = 0 by 0.0005 m") && strstr(note, "times the penetration under the weight") &&
                   strstr(note, "Inacti = 5"));
        rc_model_free(m);
    }
    /* a meshed box on a meshed box whose normals are reversed (IRm 1):
     * the message says the surfaces do not face each other */
    FILE *f = fopen("validation/seg_seg_collide/case.rad", "r");
    ENSURE(f != NULL);
    if (!f) return;
    static char deck[65536];
    size_t n = fread(deck, 1, sizeof deck - 1, f);
    fclose(f);
    deck[n] = '\0';
    char *p = strstr(deck, "/INTER/TYPE6/1\n");
    for (int k = 0; p && k < 4; k++) p = strchr(p, '\n') + 1; /* line 3 of the card */
    ENSURE(p != NULL && !strncmp(p, "                   0         0", 30));
    if (!p) return;
    p[29] = '1'; /* IRm = 1 */
    TU_EXPECT_TEXT_ERROR(deck, "guards_irm.rad", "card /INTER/TYPE6/1", "/SURF/PART/31 and /SURF/PART/32 overlap",
                         "the segment normals of /SURF/PART/32 point away from /SURF/PART/31 (IRm = 1: reversed)",
                         "with IRm = 0 (as built) they start apart");
}

/* A box (half-size 0.08 m) turned about the vertical by `turn` degrees,
 * over a larger fixed box (0.1 m) with a gap of 1e-4 m, TYPE6 between
 * them (a linear load curve, 1e5 N/m). At 30 degrees every corner of each
 * box lies outside the other's face: only their edges cross, and the
 * edge-to-edge contact points carry the upper box (docs/theory.md 2.7). */
static const char *box_turned_deck(double turn)
{
    static char deck[2048];
    const double a = turn * 3.14159265358979323846 / 180.0;
    snprintf(deck, sizeof deck,
             "/NODE\n1,0,0,0.2801\n"
             "/RBODY/1\nupper box\n1,,,,2.0\n0.0133,0.0133,0.0133\n0,0,0\n"
             "/GRNOD/NODE/1\nupper\n1\n"
             "/SURF/BOX/1\nupper\n1\n0,0,0.2801\n0.08,0.08,0.08\n%.17g,%.17g,0\n%.17g,%.17g,0\n"
             "/SURF/BOX/2\nlower, fixed\n0\n0,0,0.1\n0.1,0.1,0.1\n"
             "/GRAV/1\ng\n0,Z,0,0,1,,1,-9.81\n"
             "/FUNCT/1\nload\n0,0\n1,1e5\n"
             "/INTER/TYPE6/1\nupper on lower\n1,2\n\n\n1,0,1.0,1.0\n\n50\n"
             "/RUN\n0.3,0.01\n",
             cos(a), sin(a), -sin(a), cos(a));
    return deck;
}

/* Run it to 0.3 s: the status, the message, the end time and the upper
 * box's height and tilt (the angle of its w axis from the vertical) there. */
static rc_status box_turned_run(double turn, char *msg, size_t n, double *t_end, double *z, double *tilt)
{
    rc_error e;
    rc_model *m = tu_compile_text(box_turned_deck(turn), "guards_boxes.rad", &e);
    if (!m) {
        snprintf(msg, n, "%s", e.msg);
        return e.code;
    }
    rc_session *s = NULL;
    rc_status r = rc_session_open(m, NULL, &s, &e);
    if (r == RC_OK) r = rc_run_until(s, INFINITY, &e);
    *t_end = rc_session_time(s);
    const double *y = rc_session_state(s);
    if (y) {
        const double *b = y + m->body_yadr[0], *q = b + 3;
        *z = b[2]; /* the session's state is in the deck's coordinates */
        /* R(q) e_z . e_z = 1 - 2 (qx^2 + qy^2) for a unit quaternion */
        *tilt = acos(fmin(1.0, fmax(-1.0, 1.0 - 2.0 * (q[1] * q[1] + q[2] * q[2]))));
    }
    rc_stats st;
    const rc_status rc = rc_session_close(s, &st, &e);
    if (r == RC_OK) r = rc;
    snprintf(msg, n, "%s", r == RC_OK ? "" : e.msg);
    rc_model_free(m);
    return r;
}

static void test_guards_box_edges_cross(void)
{
    char msg[8192];
    for (int k = 0; k < 2; k++) {
        const double turn = k ? 30.0 : 0.0;
        double t_end = 0.0, z = 0.0, tilt = 1.0;
        ENSURE(box_turned_run(turn, msg, sizeof msg, &t_end, &z, &tilt) == RC_OK);
        /* at rest on the lower box's top (z = 0.2 m) at its half-size: the
         * weight 19.62 N on 1e5 N/m sinks it 0.2 mm, a hundredth of that
         * left from the drop's oscillation at most */
        printf("    turned %g deg: ran to %.4g s %s; centre at z = %.6f m, tilt %.2e rad\n", turn, t_end, msg, z, tilt);
        ENSURE_NEAR(t_end, 0.3, 0, 1e-12);
        ENSURE(fabs(z - (0.28 - 2.0 * 9.81 / 1e5)) < 0.02 * 2.0 * 9.81 / 1e5 + 1e-4);
        ENSURE(tilt < 1e-3);
    }
}

/* The bench on the turned deck, the upper box's centre put by hand at
 * height z [m] (into the lower box, whose top is at 0.2 m) and the contact
 * closed; 0 when the deck did not compile or the bench did not open. */
static int bench_boxes_closed(bench *b, double z)
{
    rc_error e;
    memset(b, 0, sizeof *b);
    rc_model *m = tu_compile_text(box_turned_deck(30.0), "guards_boxes.rad", &e);
    if (!m) return 0;
    if (!bench_open(b, m, 1)) {
        bench_close(b);
        return 0;
    }
    b->y[m->body_yadr[0] + 2] = z - m->origin[2]; /* the model's coordinates */
    b->d->inter_mode[0] = RC_MODE_CLOSED;
    return 1;
}

/* The overlap check itself: the upper box of the turned deck put by hand
 * 0.1 m into the lower one (deeper than its half-size 0.08 m, the bound of
 * the penetration: the contact points see nothing that deep), the contact
 * closed; the run stops and names the separating-axis overlap. */
static void test_guards_box_overlap_fires(void)
{
    bench b;
    const int ok = bench_boxes_closed(&b, 0.18);
    ENSURE(ok);
    if (!ok) return;
    rc_guards_step(b.g, b.d, 0.1, b.y, NULL, 0, ++b.steps);
    char note[1200];
    ENSURE(bench_violations(&b, note, sizeof note) >= 1);
    printf("    %s\n", note);
    ENSURE(strstr(note, "the boxes of /INTER/TYPE6/1 overlap by 0.1 m") != NULL);
    ENSURE(strstr(note, "pass through each other") != NULL);
    bench_close(&b);
}

/* The law behind its contact points (law_deficit): the upper box of the
 * turned deck put 0.02 m into the lower one (within the penetration bound,
 * a quarter of its thickness, 0.04 m), the contact closed, its law's
 * penetration P_e left at the static 2e-4 m (a stack of three boxes rocking
 * under its friction reached that, fuzz 217000139): the run stops and names
 * the deficit; with P_e at 0.019 m nothing fires, nor when it falls back to
 * 2e-4 m afterwards (the bound is of its largest since the contact closed:
 * within an impact on a corner P_e falls as the other corners recede). */
static void test_guards_law_deficit_fires(void)
{
    for (int k = 0; k < 2; k++) {
        bench b;
        const int ok = bench_boxes_closed(&b, 0.26);
        ENSURE(ok);
        if (!ok) return;
        const rc_model *m = b.m;
        ENSURE(m->inter_peidx[0] >= 0 && m->inter_pscale[0] < 1.5e-3);
        b.y[m->inter_eadr[0] + m->inter_peidx[0]] = k ? 0.019 : 2e-4;
        rc_guards_step(b.g, b.d, 0.1, b.y, NULL, 0, ++b.steps);
        if (k) { /* then down to 2e-4 m, as within an impact on a corner: P_e^max stays */
            b.y[m->inter_eadr[0] + m->inter_peidx[0]] = 2e-4;
            rc_guards_step(b.g, b.d, 0.1001, b.y, NULL, 0, ++b.steps);
        }
        char note[1200];
        const long nv = bench_violations(&b, note, sizeof note);
        printf("    P_e %g m: %ld violations %s\n", k ? 0.019 : 2e-4, nv, note);
        if (k == 0) {
            ENSURE(nv == 1);
            ENSURE(strstr(note, "the contact points of /INTER/TYPE6/1 penetrate by 0.02") != NULL);
            ENSURE(strstr(note, "0.0198 m deeper than its law's penetration P_e = 0.0002 m") != NULL);
            ENSURE(strstr(note, "sink into each other") != NULL);
        } else {
            ENSURE(nv == 0);
        }
        bench_close(&b);
    }
}

/* A contact point that comes in under a face across the face's free edge,
 * already deep (entered_deep): a meshed box (0.1 m cube, 1 kg, no gravity)
 * whose bottom face is 0.02 m below the plane of a finite meshed floor and
 * beyond its edge x = 0.5 moves back over it at 1 m/s. Its leading bottom
 * corners pass under the floor's edge at t = 0.1 s, 0.02 m deep (20 p_s):
 * the closing root fires on a jump, not a crossing, and the run stops
 * there naming the depth and the point; node to surface does not see the
 * floor's edge cutting into the box before (fuzz 247000130: a tilted box
 * bounced off the side of its floor). The same box moving away from the
 * floor runs to its end without a violation. */
static void test_guards_entered_deep(void)
{
    for (int k = 0; k < 2; k++) {
        char deck[2048];
        snprintf(deck, sizeof deck,
                 "/NODE\n1,0.65,0,0.03\n11,0.6,-0.05,-0.02\n12,0.7,-0.05,-0.02\n13,0.7,0.05,-0.02\n"
                 "14,0.6,0.05,-0.02\n15,0.6,-0.05,0.08\n16,0.7,-0.05,0.08\n17,0.7,0.05,0.08\n18,0.6,0.05,0.08\n"
                 "21,-1,-1,0\n22,0.5,-1,0\n23,0.5,1,0\n24,-1,1,0\n"
                 "/RBODY/1\nbox\n1,0,0,3,1.0,2\n0.00167,0.00167,0.00167\n0,0,0\n"
                 "/GRNOD/NODE/2\nbox corners\n11,12,13,14,15,16,17,18\n/GRNOD/NODE/3\nmain node\n1\n"
                 "/SURF/SEG/30\nbox faces\n1,11,14,13,12\n2,15,16,17,18\n3,11,12,16,15\n4,12,13,17,16\n"
                 "5,13,14,18,17\n6,14,11,15,18\n/SURF/SEG/40\nfloor\n1,21,22,23,24\n"
                 "/FUNCT/1\nlinear\n0,0\n1,1e6\n/INTER/TYPE6/1\nbox on floor\n30,40\n\n\n1\n\n\n"
                 "/INIVEL/TRA/1\nmoving\n%s,0,0,3,0\n/RUN\n0.2,0.01\n",
                 k ? "1" : "-1");
        rc_error e;
        rc_model *m = tu_compile_text(deck, "guards_entered_deep.rad", &e);
        ENSURE(m != NULL);
        if (!m) {
            printf("    %s\n", e.msg);
            return;
        }
        rc_stats st;
        const rc_status s = rc_run(m, NULL, &st, &e);
        printf("    moving %s the floor: status %d, t_end %.9g s%s%s\n", k ? "away from" : "back over", (int)s, st.t_end,
               s != RC_OK ? ": " : "", s != RC_OK ? e.msg : "");
        if (k == 0) {
            ENSURE(s == RC_EPHYSICS);
            ENSURE(fabs(st.t_end - 0.1) < 1e-6);
            ENSURE(strstr(e.msg, "/INTER/TYPE6/1 closes at t = 0.1") != NULL ||
                   strstr(e.msg, "/INTER/TYPE6/1 closes at t = 0.0999999") != NULL);
            ENSURE(strstr(e.msg, "already 0.02 m deep") != NULL);
            ENSURE(strstr(e.msg, "deepest at (0.5, ") != NULL && strstr(e.msg, "-0.02) m") != NULL);
            ENSURE(strstr(e.msg, "pass into each other") != NULL);
        } else {
            ENSURE(s == RC_OK && st.violations == 0);
        }
        rc_model_free(m);
    }
}

/* A cylinder held where the box is not: lying across a table's edge (its
 * axis perpendicular to the edge, which is not modelled) it acts through
 * the face's plane, which goes on beyond the rectangle. A roller (R =
 * 0.05 m, axis y, 0.2 m long) 1e-5 m into the top of a fixed box
 * (half-size 0.5 m): its centre over the face (y = 0.45 m) nothing fires;
 * at y = 0.52 m, its contact point 0.02 m outside the box (more than 1 %
 * of R), the run stops naming the distance. */
static void test_guards_cylinder_beyond_box_edge(void)
{
    static const char *deck = "/NODE\n1,0,0.45,0.04999\n"
                              "/RBODY/1\nroller\n1,,,,2.0\n0.0025,0.0025,0.0025\n0,0,0\n"
                              "/GRNOD/NODE/1\nroller\n1\n"
                              "/SURF/CYL/1\nroller\n1,0,0\n0,0.45,0.04999\n0,1,0\n0.05,0.2\n"
                              "/SURF/BOX/2\ntable, fixed\n0\n0,0,-0.5\n0.5,0.5,0.5\n"
                              "/GRAV/1\ng\n0,Z,0,0,1,,1,-9.81\n"
                              "/FUNCT/1\nload\n0,0\n1,1e6\n"
                              "/INTER/TYPE6/1\nroller on table\n1,2\n\n\n1,0,1.0,1.0\n\n50\n"
                              "/RUN\n0.3,0.01\n";
    rc_error e;
    rc_model *m = tu_compile_text(deck, "guards_cylinder.rad", &e);
    if (!m) printf("    %s\n", e.msg);
    ENSURE(m != NULL);
    if (!m) return;
    ENSURE(m->inter_pair[0] == RC_PAIR_CYL_BOX);
    bench b;
    ENSURE(bench_open(&b, m, 1));
    double *s = b.y + m->body_yadr[0];
    b.d->inter_mode[0] = RC_MODE_CLOSED;
    rc_guards_step(b.g, b.d, 0.1, b.y, NULL, 0, ++b.steps);
    ENSURE(bench_violations(&b, NULL, 0) == 0);
    s[1] = 0.52 - m->origin[1]; /* the model's coordinates */
    rc_guards_step(b.g, b.d, 0.2, b.y, NULL, 0, ++b.steps);
    char note[1200];
    ENSURE(bench_violations(&b, note, sizeof note) == 1);
    printf("    %s\n", note);
    ENSURE(strstr(note, "lies 0.02 m outside the box") != NULL);
    bench_close(&b); /* frees the model too */
}

void suite_guards(void);
void suite_guards(void)
{
    RUN_TEST(test_guards_channel_decrease_fires);
    RUN_TEST(test_guards_cylinder_beyond_box_edge);
    RUN_TEST(test_guards_coupling_damping_fires);
    RUN_TEST(test_guards_channel_tolerance_follows_rtol);
    RUN_TEST(test_guards_energy_created_fires);
    RUN_TEST(test_guards_non_finite_fires);
    RUN_TEST(test_guards_friction_limit_fires);
    RUN_TEST(test_guards_friction_limit_normal_force_tolerance);
    RUN_TEST(test_guards_penetration_fires);
    RUN_TEST(test_guards_penetration_bound_half_thickness);
    RUN_TEST(test_guards_sphere_centres_fire);
    RUN_TEST(test_guards_good_runs_pass);
    RUN_TEST(test_guards_soft_floor_stops_run);
    RUN_TEST(test_guards_activation_overlap_creates_energy);
    RUN_TEST(test_guards_start_overlap);
    RUN_TEST(test_guards_box_edges_cross);
    RUN_TEST(test_guards_box_overlap_fires);
    RUN_TEST(test_guards_law_deficit_fires);
    RUN_TEST(test_guards_entered_deep);
}
