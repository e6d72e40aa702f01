/*
 * Joint tests: the /JOINT cards and their input errors, the compiled rows,
 * the exact Jacobian of the joints' residual rows (complex step) against
 * central finite differences of the residual, the consistent multipliers
 * (the velocity constraints stay satisfied along the motion), and the
 * refusal of the CVODE path.
 */
#include "harness.h"
#include "testutil.h"
#include "base/error.h"
#include "model/coupling.h"
#include "model/coupling_contact.h"
#include "model/joint.h"
#include "model/model.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "engine/assembly/assembly.h"
#include "engine/constraints/joints.h"

/* A chain of five free bodies under gravity, one joint of each kind. */
static const char *all_kinds =
    "/BEGIN\njoints\n2022,0\nkg,m,s\nkg,m,s\n"
    "/NODE\n1,0.3,-0.8,0.1\n2,1.1,-1.3,-0.2\n3,1.5,-1.9,0.4\n4,2.1,-2.2,0.3\n5,2.6,-2.9,-0.1\n"
    "/RBODY/1\nbody 1\n1,,,,1.7\n0.02,0.03,0.04\n0,0,0\n"
    "/RBODY/2\nbody 2\n2,,,,0.6\n0.011,0.017,0.009\n0,0,0\n"
    "/RBODY/3\nbody 3\n3,,,,0.9\n0.013,0.011,0.02\n0,0,0\n"
    "/RBODY/4\nbody 4\n4,,,,1.2\n0.03,0.02,0.025\n0,0,0\n"
    "/RBODY/5\nbody 5\n5,,,,0.4\n0.004,0.005,0.006\n0,0,0\n"
    "/GRAV/1\ng\n0,Y,0,0,0,,1,-9.81\n"
    "/JOINT/REVOLUTE/1\nhinge\n1,0\n0,0,0\n0.2,0.3,1\n"
    "/JOINT/SPHERICAL/2\nball\n2,1\n0.7,-1.0,0.0\n"
    "/JOINT/DISTANCE/3\nrod\n2,3\n1.3,-1.5,0.1\n1.6,-1.8,0.35\n"
    "/JOINT/FIXED/4\nweld\n4,3\n1.8,-2.0,0.35\n"
    "/JOINT/PRISMATIC/5\nslider\n5,4\n2.3,-2.5,0.1\n1,-0.5,0.25\n"
    "/RUN\n1,0.01\n/END\n";

/* The full residual F(Y, Y') = [y' - f + joint terms; G u; g; W' - P]. */
static void residual(const rc_model *m, rc_data *d, const rc_jnt_work *w, double *Y, const double *Yp, double *r)
{
    rc_assemble_rhs(m, d, 0.0, Y, r);
    for (int k = 0; k < m->ny; k++) r[k] = Yp[k] - r[k];
    rc_jnt_residual(m, w, Y, Yp, r);
}

/* The residual for tu_dae_jac_fd_error. */
typedef struct {
    const rc_model *m;
    rc_data *d;
    const rc_jnt_work *w;
} fd_ctx;

static void fd_residual(void *ctx, const double *Y, const double *Yp, double *r)
{
    const fd_ctx *c = ctx;
    residual(c->m, c->d, c->w, (double *)Y, Yp, r);
}

static void test_joint_cards_compile(void)
{
    rc_error e;
    rc_model *m = tu_compile_text(all_kinds, "joints.rad", &e);
    ENSURE(m != NULL);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    const rc_joints *J = m->jnt;
    ENSURE(J && J->n == 5);
    if (J && J->n == 5) {
        ENSURE(J->nrow[0] == 5 && J->nrow[1] == 3 && J->nrow[2] == 1 && J->nrow[3] == 6 && J->nrow[4] == 5);
        ENSURE(J->nrows == 20);
        ENSURE(J->bb[0] == -1 && J->ba[1] == 1 && J->bb[1] == 0 && J->ba[4] == 4 && J->bb[4] == 3);
        /* anchor of the ball on body 2 (centre 1.1, -1.3, -0.2): (0.7, -1, 0) - centre */
        ENSURE_NEAR(J->sa[3], -0.4, 0, 1e-15);
        ENSURE_NEAR(J->sa[4], 0.3, 0, 1e-15);
        ENSURE_NEAR(J->len[2], sqrt(0.09 + 0.09 + 0.0625), 1e-15, 0);
        /* the revolute axis normalised */
        const double n = sqrt(0.04 + 0.09 + 1.0);
        ENSURE_NEAR(J->ua[0], 0.2 / n, 1e-15, 0);
    }
    /* automatic method: IDA */
    ENSURE(m->method == 2);
    /* the rows are independent at the start (a chain) */
    rc_jnt_work *w = rc_jnt_work_new(m);
    double *Y = calloc((size_t)(m->ny + rc_jnt_nextra(w)), sizeof *Y);
    rc_initial_state(m, Y);
    ENSURE(rc_jnt_dependent(m, w, Y) == -1);
    free(Y);
    rc_jnt_work_free(w);
    ENSURE(rc_model_set_method(m, 1, &e) == RC_EINPUT);
    ENSURE(strstr(e.msg, "joints") != NULL);
    rc_model_free(m);
}

static void test_joint_card_errors(void)
{
    struct {
        const char *card, *needle;
    } bad[] = {
        {"/JOINT/SPHERICAL/1\nx\n1,1\n0,0,0\n", "rbody_ID2"},
        {"/JOINT/REVOLUTE/1\nx\n1,0\n0,0,0\n0,0,0\n", "Ax Ay Az"},
        {"/JOINT/SPHERICAL/1\nx\n7,0\n0,0,0\n", "no such body"},
        {"/JOINT/DISTANCE/1\nx\n1,0\n1,2,3\n1,2,3\n", "X2 Y2 Z2"},
        {"/JOINT/SPHERICAL/1\nx\n0,1\n0,0,0\n", "rbody_ID1"},
        {"/GRNOD/NODE/1\ng\n1\n/BCS/1\nb\n111 000,0,1\n/JOINT/SPHERICAL/1\nx\n1,0\n0,0,0\n", "not supported yet"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        char text[1024];
        snprintf(text, sizeof text,
                 "/BEGIN\nj\n2022,0\nkg,m,s\nkg,m,s\n/NODE\n1,0,-1,0\n/RBODY/1\nb\n1,,,,1\n0.1,0.1,0.1\n0,0,0\n"
                 "%s/RUN\n1,0.1\n/END\n",
                 bad[k].card);
        TU_EXPECT_TEXT_ERROR(text, "bad.rad", bad[k].needle, "bad.rad:");
    }
    /* /SOLVER Method 1 with joints: refused at the /SOLVER card */
    rc_error e;
    rc_model *m = tu_compile_text("/BEGIN\nj\n2022,0\nkg,m,s\nkg,m,s\n/NODE\n1,0,-1,0\n/RBODY/1\nb\n1,,,,1\n0.1,0.1,0.1\n"
                                  "0,0,0\n/JOINT/SPHERICAL/1\nx\n1,0\n0,0,0\n/RUN\n1,0.1\n/SOLVER\n1\n/END\n",
                                  "cvode.rad", &e);
    ENSURE(m == NULL && e.code == RC_EINPUT && strstr(e.msg, "Method") && strstr(e.msg, "cvode.rad:"));
    rc_model_free(m);
    /* a second spherical joint at the same point: dependent rows, named at
     * the second card (line 17); velocities the joint forbids (line 14) */
    const char *head = "/BEGIN\nj\n2022,0\nkg,m,s\nkg,m,s\n/NODE\n1,0,-1,0\n/RBODY/1\nb\n1,,,,1\n0.1,0.1,0.1\n0,0,0\n";
    char text[1024];
    snprintf(text, sizeof text, "%s/JOINT/SPHERICAL/1\nx\n1,0\n0,0,0\n/JOINT/SPHERICAL/2\ny\n1,0\n0,0,0\n/RUN\n1,0.1\n/END\n",
             head);
    m = tu_compile_text(text, "twice.rad", &e);
    ENSURE(m == NULL && e.code == RC_EINPUT && strstr(e.msg, "twice.rad:17:") && strstr(e.msg, "/JOINT/SPHERICAL/2") &&
           strstr(e.msg, "repeat"));
    rc_model_free(m);
    snprintf(text, sizeof text, "%s/INIVEL/TRA/1\nv\n0,1,0,0,0\n/JOINT/SPHERICAL/1\nx\n1,0\n0,0,0\n/RUN\n1,0.1\n/END\n", head);
    m = tu_compile_text(text, "moving.rad", &e);
    if (m || !strstr(e.msg, "moving.rad:16:") || !strstr(e.msg, "initial velocities")) {
        fprintf(stderr, "  %s\n", m ? "compiled" : e.msg);
        rc_test_failed_now++;
    }
    rc_model_free(m);
}

/* A state off the constraints, with non-unit quaternions, velocities and
 * multipliers: every term of the residual is exercised. */
static void off_state(const rc_model *m, const rc_jnt_work *w, double *Y, double *Yp, int n)
{
    rc_initial_state(m, Y);
    unsigned s = 12345u;
    for (int k = 0; k < n; k++) {
        s = s * 1103515245u + 12345u;
        const double u = (double)(s >> 8) / (double)(1u << 24) - 0.5;
        if (k < m->ny) Y[k] += 0.3 * u;
        else Y[k] = 2.0 * u;
        Yp[k] = u;
    }
    (void)w;
}

static void test_joint_jacobian_matches_finite_differences(void)
{
    rc_error e;
    rc_model *m = tu_compile_text(all_kinds, "joints.rad", &e);
    ENSURE(m != NULL);
    if (!m) return;
    rc_data *d = rc_data_new(m);
    rc_jnt_work *w = rc_jnt_work_new(m);
    const int n = m->ny + rc_jnt_nextra(w);
    double *Y = calloc((size_t)n, sizeof *Y), *Yp = calloc((size_t)n, sizeof *Yp);
        double *jf = calloc((size_t)m->nnz + 1, sizeof *jf), *val = calloc((size_t)rc_jnt_nnz(w), sizeof *val);
    off_state(m, w, Y, Yp, n);
    const int64_t *cp, *ri;
    rc_jnt_pattern(w, &cp, &ri);
    double worst = 0;
    int outside = 0;
    fd_ctx fc = {m, d, w};
    const tu_dae_fd_opts o = {1.0, 1e-7, 1e-6, 0, 0, NULL};
    for (int pass = 0; pass < 2; pass++) {
        const double cj = pass ? 37.5 : 0.0;
        rc_assemble_jac(m, d, 0.0, Y, jf);
        rc_jnt_jacobian(m, w, cj, Y, Yp, jf, val);
        worst = fmax(worst, tu_dae_jac_fd_error(n, Y, Yp, cj, cp, ri, val, fd_residual, &fc, &o, &outside));
    }
    ENSURE(worst < 1e-6);
    ENSURE(outside == 0);
    free(Y);
    free(Yp);
    free(jf);
    free(val);
    rc_jnt_work_free(w);
    rc_data_free(d);
    rc_model_free(m);
}

/* A pendulum of two bodies (revolute to the ground, spherical between
 * them), released: after rc_jnt_consistent the residual is zero, the
 * velocity constraints have zero rate along Y' (a difference along Y'), and
 * the hinge force balances the momentum of the pair. */
static void test_joint_consistent_multipliers(void)
{
    const char *text = "/BEGIN\nj\n2022,0\nkg,m,s\nkg,m,s\n/NODE\n1,0.6,-0.8,0\n2,1.2,-1.6,0.3\n"
                       "/RBODY/1\nb1\n1,,,,2\n0.02,0.03,0.04\n0,0,0\n/RBODY/2\nb2\n2,,,,0.5\n0.01,0.01,0.02\n0,0,0\n"
                       "/GRAV/1\ng\n0,Y,0,0,0,,1,-9.81\n"
                       "/JOINT/REVOLUTE/1\nh\n1,0\n0,0,0\n0,0,1\n/JOINT/SPHERICAL/2\nb\n2,1\n1.0,-1.4,0.1\n"
                       "/RUN\n1,0.01\n/END\n";
    rc_error e;
    rc_model *m = tu_compile_text(text, "pend.rad", &e);
    ENSURE(m != NULL);
    if (!m) return;
    rc_data *d = rc_data_new(m);
    rc_jnt_work *w = rc_jnt_work_new(m);
    const int n = m->ny + rc_jnt_nextra(w);
    double *Y = calloc((size_t)n, sizeof *Y), *Yp = calloc((size_t)n, sizeof *Yp), *r = calloc((size_t)n, sizeof *r);
    double *Y2 = calloc((size_t)n, sizeof *Y2);
    rc_initial_state(m, Y);
    ENSURE(rc_jnt_check_initial(m, w, Y, &e) == RC_OK);
    /* velocities off the constraints, projected back: G u = 0, and the
     * change is the smallest in kinetic energy, so an allowed motion (the
     * hinge's rotation) is kept */
    {
        double *v1 = Y + m->body_yadr[0] + 7, *w1 = Y + m->body_yadr[0] + 10, *v2 = Y + m->body_yadr[1] + 7;
        v1[0] += 0.02;
        v2[2] += 0.03;
        ENSURE(rc_jnt_project_velocities(m, w, Y) == 0);
        residual(m, d, w, Y, Yp, r);
        double cv = 0;
        for (int k = 0; k < m->jnt->nrows; k++) cv = fmax(cv, fabs(r[m->ny + k]));
        ENSURE(cv < 1e-14);
        ENSURE(fabs(w1[2]) > 1e-4); /* the pushes turned the hinge */
        rc_initial_state(m, Y);
    }
    rc_assemble_rhs(m, d, 0.0, Y, Yp);
    ENSURE(rc_jnt_consistent(m, w, Y, Yp) == 0);
    residual(m, d, w, Y, Yp, r);
    double worst = 0;
    for (int k = 0; k < n; k++) worst = fmax(worst, fabs(r[k]));
    ENSURE(worst < 1e-12);
    /* the velocity rows along Y' for a short time: second order in h */
    const double h = 1e-5;
    for (int k = 0; k < n; k++) Y2[k] = Y[k] + h * Yp[k];
    residual(m, d, w, Y2, Yp, r);
    const int nr = m->jnt->nrows;
    double cvmax = 0;
    for (int k = 0; k < nr; k++) cvmax = fmax(cvmax, fabs(r[m->ny + k]));
    ENSURE(cvmax < 1e-8);
    /* momentum of the pair: the hinge force and the weights accelerate
     * the two masses, F + (m1 + m2) g = m1 a1 + m2 a2 */
    double F[3], M[3], dp, da;
    for (int k = 0; k < nr; k++) Y[m->ny + k] = Yp[m->ny + k]; /* the record vector: lambda = Lambda' */
    rc_jnt_report(m, 0, Y, F, M, &dp, &da);
    const double *a1 = Yp + m->body_yadr[0] + 7, *a2 = Yp + m->body_yadr[1] + 7;
    ENSURE_NEAR(F[0], 2.0 * a1[0] + 0.5 * a2[0], 1e-10, 1e-12);
    ENSURE_NEAR(F[1] - 2.5 * 9.81, 2.0 * a1[1] + 0.5 * a2[1], 1e-10, 1e-12);
    ENSURE_NEAR(F[2], 2.0 * a1[2] + 0.5 * a2[2], 1e-10, 1e-12);
    ENSURE(fabs(F[1]) > 1.0); /* a real reaction */
    ENSURE(dp < 1e-15 && da < 1e-15);
    free(Y);
    free(Y2);
    free(Yp);
    free(r);
    rc_jnt_work_free(w);
    rc_data_free(d);
    rc_model_free(m);
}

/* A pendulum that hits a wall: contact events restart IDA with the joint's
 * multipliers recomputed; the run completes, rebounds, and keeps the energy
 * ledger (the damping's dissipation included) and the joint. */
static void test_joint_with_contact_events(void)
{
    const char *text =
        "/BEGIN\nj\n2022,0\nkg,m,s\nkg,m,s\n/FUNCT/1\nlinear\n0,0\n1,1e6\n"
        "/NODE\n1,0.866025403784,-0.5,0\n/RBODY/1\nbob\n1,,,,1\n0.004,0.004,0.004\n0,0,0\n"
        "/SURF/ELLIPS/1\nbob\n0,2,1\n0.866025403784,-0.5,0\n0.1,0.1,0.1\n"
        "/SURF/PLANE/2\nwall\n-0.3,0,0\n1,0,0\n/GRAV/1\ng\n0,Y,0,0,0,,1,-9.81\n"
        "/JOINT/REVOLUTE/1\nhinge\n1,0\n0,0,0\n0,0,1\n"
        "/INTER/TYPE6/1\nwall\n1,2\n\n\n1\n\n20\n/RUN\n2,0.01\n/END\n";
    rc_error e;
    rc_model *m = tu_compile_text(text, "wall.rad", &e);
    ENSURE(m != NULL);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    rc_run_options o = {0};
    rc_stats st;
    ENSURE(rc_run(m, &o, &st, &e) == RC_OK);
    ENSURE(st.events >= 4 && st.reinits >= 4 && st.t_end == 2.0);
    ENSURE(fabs(st.energy_residual) < 1e-6 * 9.81); /* of m g L */
    printf("    pendulum against a wall: %ld events, %ld steps, energy residual %.2e J\n", st.events, st.steps,
           st.energy_residual);
    rc_model_free(m);
}

/* Two free bodies on a revolute joint (an oblique axis) and a third on a
 * prismatic joint to the second, with stops (the prismatic's elastic part
 * from a curve). */
static const char *stops_deck =
    "/BEGIN\nstops\n2022,0\nkg,m,s\nkg,m,s\n"
    "/NODE\n1,0.3,-0.8,0.1\n2,1.1,-1.3,-0.2\n3,1.5,-1.9,0.4\n"
    "/RBODY/1\nbody 1\n1,,,,1.7\n0.02,0.03,0.04\n0,0,0\n"
    "/RBODY/2\nbody 2\n2,,,,0.6\n0.011,0.017,0.009\n0,0,0\n"
    "/RBODY/3\nbody 3\n3,,,,0.9\n0.013,0.011,0.02\n0,0,0\n"
    "/GRAV/1\ng\n0,Y,0,0,0,,1,-9.81\n"
    "/JOINT/REVOLUTE/1\nhinge\n1,2\n0.7,-1.0,0.0\n0.2,0.3,1\n-0.4,0.6,350,2.5\n"
    "/FUNCT/7\nstiffening stop\n-0.01,-50\n0,0\n0.005,100\n0.02,1500\n0.1,4e4\n"
    "/JOINT/PRISMATIC/2\nslider\n3,2\n1.3,-1.5,0.1\n1,-0.5,0.25\n-0.05,0.02,,30,7\n"
    "/RUN\n1,0.01\n/END\n";

/* The stops' Jacobian blocks (complex step) against central differences
 * of the right-hand side, at a generic state (bodies turned and moving,
 * off the joints), in every mode of the two stops; and their generalised
 * force: the stops' power on the bodies balances the rates of their
 * energy states (the wrench is the exact gradient of the coordinate). */
static void test_joint_stop_jacobian(void)
{
    rc_error e;
    rc_model *m = tu_compile_text(stops_deck, "stops.rad", &e);
    ENSURE(m != NULL);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    const rc_couplings *c = m->cpl;
    ENSURE(c->n == 2 && c->ncard == 0 && rc_cpl_nlim(m) == 2 && c->kind[0] == RC_CPL_LIMIT);
    ENSURE(rc_cpl_nroots(m) == 2 * RC_LIM_ROOTS && rc_root_count(m) == 2 * RC_LIM_ROOTS);
    ENSURE(c->lrev[0] == 1 && c->lrev[1] == 0 && c->llo[0] == -0.4 && c->lhi[1] == 0.02);
    ENSURE(c->table[0] == -1 && c->table[1] >= 0);
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double)), *f0 = calloc((size_t)m->ny, sizeof(double)),
           *f1 = calloc((size_t)m->ny, sizeof(double));
    rc_initial_state(m, y);
    const double q[3][4] = {{0.99, 0.05, -0.08, 0.03}, {0.97, -0.1, 0.12, 0.2}, {0.9, 0.2, 0.1, -0.3}};
    const double v[3][6] = {{0.3, -0.2, 0.1, 0.5, -0.7, 0.9}, {-0.4, 0.1, 0.2, -0.3, 0.8, 0.2},
                            {0.2, 0.6, -0.1, 1.1, 0.4, -0.6}};
    for (int b = 0; b < 3; b++) {
        double *s = y + m->body_yadr[b];
        for (int k = 0; k < 4; k++) s[3 + k] = q[b][k];
        for (int k = 0; k < 6; k++) s[7 + k] = v[b][k];
    }
    int bad = 0, outside = 0;
    double maxerr = 0, maxpow = 0;
    const int modes[5] = {RC_LIM_LO_PUSH, RC_LIM_LO_REL, RC_LIM_HI_PUSH, RC_LIM_HI_REL, RC_LIM_FREE};
    for (int pass = 0; pass < 5; pass++) {
        d->cpl->lmode[0] = modes[pass];
        d->cpl->lmode[1] = modes[(pass + 2) % 5];
        maxerr = fmax(maxerr, tu_jac_fd_error(m, d, 0.0, y, 1, &bad, &outside));
        /* power balance: kinetic energy rate from the stops = -(edot) */
        rc_data *d0 = rc_data_new(m);
        d0->cpl->lmode[0] = d0->cpl->lmode[1] = RC_LIM_FREE;
        rc_assemble_rhs(m, d0, 0.0, y, f0);
        rc_assemble_rhs(m, d, 0.0, y, f1);
        double pw = 0, ed = 0, scale = 0;
        for (int b = 0; b < 3; b++) {
            const double *s = y + m->body_yadr[b], *J = m->body_J + 9 * b;
            const double *a0 = f0 + m->body_yadr[b] + 7, *a1 = f1 + m->body_yadr[b] + 7;
            for (int k = 0; k < 3; k++) {
                pw += m->body_mass[b] * s[7 + k] * (a1[k] - a0[k]);
                double jw = 0;
                for (int i = 0; i < 3; i++) jw += J[3 * k + i] * (a1[3 + i] - a0[3 + i]);
                pw += s[10 + k] * jw;
                scale += fabs(m->body_mass[b] * s[7 + k] * a1[k]);
            }
        }
        for (int k = 0; k < 2; k++) ed += f1[c->eadr[k]] + f1[c->eadr[k] + 1];
        maxpow = fmax(maxpow, fabs(pw + ed) / fmax(scale, 1.0));
        rc_data_free(d0);
    }
    printf("    joint stops: max scaled |J - FD| %.2e, %d bad, %d outside the pattern; power balance %.1e\n", maxerr,
           bad, outside, maxpow);
    ENSURE(bad == 0 && outside == 0);
    ENSURE(maxerr < 1e-6);
    ENSURE(maxpow < 1e-12);
    free(y);
    free(f0);
    free(f1);
    rc_data_free(d);
    rc_model_free(m);
}

/* The stops' input errors: file:line, card, field. */
static void test_joint_stop_errors(void)
{
    struct {
        const char *line4, *kind, *needle;
    } bad[] = {
        {"0.1,0.5,100,1\n", "REVOLUTE", "Lim_min"},
        {"-0.1,-0.05,100,1\n", "PRISMATIC", "Lim_max"},
        {"-4,3,100,1\n", "REVOLUTE", "less than a turn apart"},
        {"-0.5,,100,1\n", "REVOLUTE", "both stops"},
        {"-0.1,0.1,0,1\n", "PRISMATIC", "K_lim"},
        {"-0.1,0.1,100,-1\n", "PRISMATIC", "C_lim"},
        {"-0.1,0.1,100,1\n", "DISTANCE", "no free scalar"},
        {"-0.1,0.1,100,1,1\n", "PRISMATIC", "K_lim blank"},
        {"-0.1,0.1,,1,9\n", "PRISMATIC", "no such function"},
        {"-0.1,0.1,,1,2\n", "PRISMATIC", "through 0"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        char text[1024];
        const int dist = !strcmp(bad[k].kind, "DISTANCE");
        snprintf(text, sizeof text,
                 "/BEGIN\nj\n2022,0\nkg,m,s\nkg,m,s\n/NODE\n1,0,-1,0\n/RBODY/1\nb\n1,,,,1\n0.1,0.1,0.1\n0,0,0\n"
                 "/JOINT/%s/1\nx\n1,0\n0,0,0\n%s\n%s/FUNCT/1\nlin\n0,0\n1,1e3\n/FUNCT/2\noff\n0,5\n1,1e3\n"
                 "/RUN\n1,0.1\n/END\n",
                 bad[k].kind, dist ? "0,-1,0" : "0,0,1", bad[k].line4);
        TU_EXPECT_TEXT_ERROR(text, "bad.rad", bad[k].needle, "bad.rad:18:");
    }
}

void suite_joint(void);
void suite_joint(void)
{
    RUN_TEST(test_joint_stop_jacobian);
    RUN_TEST(test_joint_stop_errors);
    RUN_TEST(test_joint_cards_compile);
    RUN_TEST(test_joint_card_errors);
    RUN_TEST(test_joint_jacobian_matches_finite_differences);
    RUN_TEST(test_joint_consistent_multipliers);
    RUN_TEST(test_joint_with_contact_events);
    tu_tmp_cleanup();
}
