/*
 * Engine tests on a case built in code (no parser): the analytic Jacobian
 * against central finite differences at a high-entropy state, the pattern's
 * completeness, quaternion norm drift and gyroscopic invariants.
 */
#include <stdlib.h>

#include "case/case.h"
#include "case/case_mesh.h"
#include "case/case_coupling.h"
#include "case/case_power.h"
#include "model/imposed.h"
#include "model/model.h"
#include "model/table.h"
#include "harness.h"
#include "testutil.h"
#include "engine/assembly/assembly.h"

/* A three-body case: body 1 (sphere, offset from its CoM, full inertia),
 * body 2 (sphere), a tilted plane fixed in space; sphere-plane and
 * sphere-sphere TYPE6 with a nonlinear load curve, Visc and both damping
 * curves; gravity; a spring-damper and a catenary (add_couplings). */
static rc_case_funct fn[7];
static double fx0[] = {-0.01, 0.0, 0.0013, 0.0041, 0.0097}, fy0[] = {-3.1e3, 0.0, 2.71e3, 1.37e4, 5.9e4};
static double fx1[] = {-10.0, 0.0, 0.37, 3.3}, fy1[] = {-41.0, 0.0, 5.3, 71.0};   /* f_dv */
static double fx2[] = {0.0, 500.0, 9e4}, fy2[] = {1.0, 0.83, 0.61};               /* f_df */
static double fx3[] = {0.0, 0.002, 0.006, 0.011}, fy3[] = {0.0, 0.0, 5e3, 3.1e4};  /* f_ul */
static double fx4[] = {0.0, 300.0, 4e4}, fy4[] = {1.0, 0.91, 0.77};                /* f_ff */
static double fx5[] = {0.0, 0.3, 2.0, 9.0}, fy5[] = {1.2, 1.0, 0.83, 0.71};         /* f_fv */
static double fx6[] = {0.0, 1.0}, fy6[] = {0.3, 1.7};                             /* gravity(t) */
static rc_case_node nodes[2] = {{1, {0.0213, -0.0117, 0.0519}, {0}}, {2, {0.0371, 0.0093, 0.131}, {0}}};
static rc_case_rbody rb[2];
static rc_case_surf sf[3];
static rc_case_type6 t6[2];
static rc_case_grav gr;
static rc_case_part parts[3];
static int part_surf_plane[] = {23};
static rc_case_friction fcard[2];
static rc_case_fricpair fpair[2];
static rc_case_fricorient forient;
static rc_case_fricorient_item fitem;
static rc_case_coupling cpl[2];

/* Couplings (coupling.h): a polynomial spring-damper between offset points
 * of the two bodies, a slack catenary from a point in space to an offset
 * point of body 1 (in the ramped gravity). */
static void add_couplings(rc_case *c)
{
    memset(cpl, 0, sizeof cpl);
    cpl[0] = (rc_case_coupling){.id = 71, .kind = RC_CASE_CPL_SPRING, .rbody = {11, 12},
                                .p = {{0.031, -0.02, 0.07}, {0.029, 0.015, 0.12}}, .iform = 2, .x0 = 0.047,
                                .x0_given = 1, .kd = 3.1, .a = 2.3e3, .b = -1.1e4, .c = 7.7e5};
    cpl[1] = (rc_case_coupling){.id = 72, .kind = RC_CASE_CPL_CATENARY, .rbody = {0, 11},
                                .p = {{-0.21, 0.13, 0.33}, {0.017, -0.03, 0.061}}, .lambda0 = 0.37, .leq = 0.41,
                                .d = 3.3e3};
    c->ncoupling = 2;
    c->coupling = cpl;
}

/* /FRICTION over the same interfaces: card 1 (generalised viscous law,
 * incremental, filtered) on sphere 1 / plane; card 2 (Renard, viscous total
 * form, orthotropic with /FRIC_ORIENT) on sphere 1 / sphere 2. */
static void add_friction_cards(rc_case *c)
{
    memset(parts, 0, sizeof parts);
    parts[0] = (rc_case_part){.id = 41, .rbody_id = 11};
    parts[1] = (rc_case_part){.id = 42, .rbody_id = 12};
    parts[2] = (rc_case_part){.id = 43, .rbody_id = 0, .nsurf = 1, .surf = part_surf_plane};
    c->npart = 3;
    c->part = parts;
    memset(fcard, 0, sizeof fcard);
    memset(fpair, 0, sizeof fpair);
    fpair[0] = (rc_case_fricpair){.part1 = 41, .part2 = 43, .idir = 0};
    /* mu ~ 0.3-0.5 at p ~ 3e6 Pa: C1 [1/Pa], C2 [s/m], C3 [s/(Pa m)], C4 [1/Pa^2], C5 [s^2/m^2] */
    fpair[0].set[0] = (rc_case_fricset){{2.1e-8, 0.031, 1.3e-9, 1.7e-15, 0.0071, 0.0}, 0.27, 0.7};
    fcard[0] = (rc_case_friction){.id = 51, .ifric = 1, .ifiltr = 3, .xfreq = 37.0, .iform = 2, .area = 3.1e-4,
                                  .npair = 1, .pair = &fpair[0]};
    fpair[1] = (rc_case_fricpair){.part1 = 42, .part2 = 41, .idir = 1};
    fpair[1].set[0] = (rc_case_fricset){{0.41, 0.23, 0.53, 0.17, 0.37, 2.9}, 0.0, 0.83};
    fpair[1].set[1] = (rc_case_fricset){{0.31, 0.19, 0.47, 0.11, 0.61, 3.7}, 0.0, 0.83};
    fcard[1] = (rc_case_friction){.id = 52, .ifric = 3, .iform = 1, .npair = 1, .pair = &fpair[1]};
    c->nfriction = 2;
    c->friction = fcard;
    fitem = (rc_case_fricorient_item){.part_id = 42, .v = {0.3, 0.9, 0.1}, .phi = 17.0};
    forient = (rc_case_fricorient){.id = 61, .n = 1, .item = &fitem};
    c->nfricorient = 1;
    c->fricorient = &forient;
}

static void build_case(rc_case *c)
{
    memset(c, 0, sizeof *c);
    c->path = "engine-test";
    fn[0] = (rc_case_funct){7, "load", 5, fx0, fy0, {0}};
    fn[1] = (rc_case_funct){8, "dv", 4, fx1, fy1, {0}};
    fn[2] = (rc_case_funct){9, "df", 3, fx2, fy2, {0}};
    fn[3] = (rc_case_funct){10, "ul", 4, fx3, fy3, {0}};
    fn[4] = (rc_case_funct){11, "ff", 3, fx4, fy4, {0}};
    fn[5] = (rc_case_funct){12, "fv", 4, fx5, fy5, {0}};
    fn[6] = (rc_case_funct){13, "g(t)", 2, fx6, fy6, {0}};
    c->nfunct = 7;
    c->funct = fn;
    c->nnode = 2;
    c->node = nodes;
    memset(rb, 0, sizeof rb);
    rb[0].id = 11; rb[0].node_id = 1; rb[0].mass = 0.731;
    rb[0].J[0] = 2.1e-3; rb[0].J[1] = 1.7e-3; rb[0].J[2] = 2.9e-3; rb[0].J[3] = 1.3e-4; rb[0].J[4] = -2.2e-4; rb[0].J[5] = 0.7e-4;
    rb[1].id = 12; rb[1].node_id = 2; rb[1].mass = 0.413;
    rb[1].J[0] = 1.1e-3; rb[1].J[1] = 1.3e-3; rb[1].J[2] = 0.9e-3;
    c->nrbody = 2;
    c->rbody = rb;
    memset(sf, 0, sizeof sf);
    sf[0] = (rc_case_surf){.id = 21, .kind = RC_CASE_SURF_ELLIPS, .degree = 2, .c = {0.0237, -0.0101, 0.0503}, .abc = {0.05, 0.05, 0.05}, .rbody_id = 11};
    sf[1] = (rc_case_surf){.id = 22, .kind = RC_CASE_SURF_ELLIPS, .degree = 2, .c = {0.0371, 0.0093, 0.131}, .abc = {0.031, 0.031, 0.031}, .rbody_id = 12};
    sf[2] = (rc_case_surf){.id = 23, .kind = RC_CASE_SURF_PLANE, .m = {0.0, 0.0, 0.0021}, .m1 = {0.031, -0.017, 1.0}};
    c->nsurf = 3;
    c->surf = sf;
    memset(t6, 0, sizeof t6);
    for (int k = 0; k < 2; k++) {
        t6[k].id = 31 + k; t6[k].tstop = 1e30; t6[k].fct_ld = 7; t6[k].ascalex = 1.3; t6[k].fscaleld = 0.77;
        t6[k].visc = 3.7; t6[k].fct_dv = 8; t6[k].fct_df = 9; t6[k].fscalev = 2.3; t6[k].ascalef = 1.9; t6[k].ascalev = 0.61;
        t6[k].gap = 0.0011 * k;
    }
    t6[0].surf1 = 23; t6[0].surf2 = 21; /* plane first: the compiler orders the pair */
    t6[1].surf1 = 21; t6[1].surf2 = 22;
    /* elasto-plastic with unload curve and Inacti 5; decoupled hardening */
    t6[0].iform = 1; t6[0].fct_ul = 10; t6[0].fscaleul = 0.83; t6[0].stiff = 7.3e6; t6[0].inacti = 5;
    t6[1].iform = 2; t6[1].stiff = 6.1e6;
    /* friction: Coulomb with both multipliers; static force plus Coulomb */
    t6[0].fric = 0.37; t6[0].fct_ff = 11; t6[0].fct_fv = 12;
    t6[1].sfric = 2.1; t6[1].fric = 0.23;
    c->ntype6 = 2;
    c->type6 = t6;
    gr = (rc_case_grav){.id = 1, .fct_id = 13, .dir = 2, .u = {0, 0, 1}, .ascale = 1.0, .fscale = -9.81}; /* ramped */
    c->ngrav = 1;
    c->grav = &gr;
    add_couplings(c);
    c->run = (rc_case_run){1, 0.01, 0.001, {0}, 0, 0};
    c->solver = (rc_case_solver){0, 1, 5, 100000, 1e-8, 1e-11, 1e-11, 1e-8, 1e-8, 1e-9, 0, 0, 0, {0}, {0}, 0};
}

/* A penetrating, spinning, non-unit-quaternion state. */
static void entropy_state(const rc_model *m, double *y)
{
    rc_initial_state(m, y);
    double s[26] = {0.0213, -0.0117, 0.0483, 0.93, 0.11, -0.27, 0.19, 0.31, -0.23, -1.17, 3.1, -2.3, 4.7,
                    0.0391, 0.0107, 0.1187, 0.97, -0.05, 0.21, 0.08, -0.41, 0.17, 0.53, -1.9, 0.7, 2.2};
    for (int b = 0; b < 2; b++) memcpy(y + m->body_yadr[b], s + 13 * b, 13 * sizeof(double));
    for (int k = 0; k < m->ny - 26; k++) y[26 + k] = 0.013 * (k + 1);
    /* F_h of both interfaces near their curves, a small Inacti offset */
    y[m->inter_eadr[0] + m->inter_hidx[0]] = 731.0;
    y[m->inter_eadr[0] + m->inter_oidx[0]] = 3.7e-4;
    y[m->inter_eadr[1] + m->inter_hidx[1]] = 1370.0;
    /* tangential forces, not exactly in the contact plane */
    const double ft[2][3] = {{13.7, -8.1, 2.3}, {-4.4, 11.9, 0.7}};
    for (int i = 0; i < 2; i++)
        for (int k = 0; k < 3; k++) {
            const rc_fric *fr = &m->inter_fr[i];
            if (fr->tidx >= 0) y[m->inter_eadr[i] + fr->tidx + k] = ft[i][k];
            if (fr->fidx >= 0) y[m->inter_eadr[i] + fr->fidx + k] = 0.7 * ft[1 - i][k];
        }
}


/* The two-interface model of build_case (with the /FRICTION cards), its
 * run data and the generic state of entropy_state; NULL on failure. */
static rc_model *entropy_model(int with_cards, rc_data **d, double **y)
{
    rc_case c;
    build_case(&c);
    if (with_cards) add_friction_cards(&c);
    rc_model *m = NULL;
    rc_error e;
    ENSURE(rc_model_compile(&c, &m, &e) == RC_OK);
    if (!m) return NULL;
    *d = rc_data_new(m);
    *y = calloc((size_t)m->ny, sizeof(double));
    entropy_state(m, *y);
    return m;
}

static void jacobian_check(int with_cards)
{
    rc_data *d = NULL;
    double *y = NULL;
    rc_model *m = entropy_model(with_cards, &d, &y);
    if (!m) return;
    for (int i = 0; i < m->ninter; i++) {
        rc_inter_report r;
        rc_inter_report_eval(m, i, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
        ENSURE(r.p > 0); /* both contacts penetrate in this state */
    }
    /* every mode in which the interfaces write: closed and released, each
     * hysteresis branch, Inacti tracking on and off, stick and slip */
    int bad = 0, outside = 0, combos = 0;
    double maxerr = 0;
    const int modes[2] = {RC_MODE_CLOSED, RC_MODE_RELEASED};
    for (int md = 0; md < 2; md++)
        for (int br = 0; br < 3; br++)
            for (int trk = 0; trk < 2; trk++)
                for (int sl = 0; sl < 2; sl++) {
                    for (int i = 0; i < m->ninter; i++) {
                        d->inter_mode[i] = modes[md];
                        d->inter_branch[i] = br;
                        d->inter_track[i] = trk && m->inter_oidx[i] >= 0;
                        d->inter_slip[i] = sl;
                    }
                    /* the /FRICTION cards' rows are large (a viscous C of
                     * 1e6 N s/m, angular accelerations of 1e4 rad/s^2): their
                     * differences at h = 1e-6 are at the rounding there */
                    maxerr = fmax(maxerr, tu_jac_fd_error(m, d, 0.0137, y, with_cards, &bad, &outside));
                    combos++;
                }
    printf("    jacobian%s: %d states, %lld nonzeros, %d mode combinations, max scaled |J - FD| = %.2e\n", with_cards ? " (/FRICTION)" : "", m->ny,
           (long long)m->nnz, combos, maxerr);
    ENSURE(bad == 0);
    ENSURE(outside == 0);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

static void test_engine_jacobian_matches_finite_differences(void) { jacobian_check(0); }

/* After a mode change of one interface, its block refreshed in place
 * (rc_jac_refresh_inter) gives the values of a whole assembly in the new
 * modes at the same state; the other interface's block is untouched. */
static void test_engine_jacobian_refresh_after_mode_change(void)
{
    rc_data *d = NULL;
    double *y = NULL;
    rc_model *m = entropy_model(1, &d, &y);
    if (!m) return;
    double *val = calloc((size_t)m->nnz + 1, sizeof(double)), *ref = calloc((size_t)m->nnz + 1, sizeof(double));
    ENSURE(d->sc->jcache != NULL);
    ENSURE(rc_jac_refresh_inter(m, d, 0, y, val) == -1); /* nothing assembled yet */
    const int modes[3] = {RC_MODE_CLOSED, RC_MODE_RELEASED, RC_MODE_INACTIVE};
    int changes = 0;
    double worst = 0.0, moved = 0.0;
    for (int from = 0; from < 3; from++)
        for (int to = 0; to < 3; to++)
            for (int sl = 0; sl < 2; sl++) {
                if (from == to && sl == 0) continue;
                for (int i = 0; i < m->ninter; i++) {
                    d->inter_mode[i] = RC_MODE_CLOSED;
                    d->inter_slip[i] = 0;
                    d->inter_branch[i] = RC_BR_LOAD;
                }
                d->inter_mode[1] = modes[from];
                ENSURE(rc_assemble_jac(m, d, 0.0137, y, val) == 0);
                d->inter_mode[1] = modes[to];
                d->inter_slip[1] = sl;
                ENSURE(rc_jac_refresh_inter(m, d, 1, y, val) == 0);
                ENSURE(rc_assemble_jac(m, d, 0.0137, y, ref) == 0);
                double scale = 0.0;
                for (int64_t k = 0; k < m->nnz; k++) scale = fmax(scale, fabs(ref[k]));
                for (int64_t k = 0; k < m->nnz; k++) worst = fmax(worst, fabs(val[k] - ref[k]) / scale);
                /* the refresh did change something (the check can fail) */
                d->inter_mode[1] = modes[from];
                d->inter_slip[1] = 0;
                double *alt = calloc((size_t)m->nnz + 1, sizeof(double));
                ENSURE(rc_assemble_jac(m, d, 0.0137, y, alt) == 0);
                for (int64_t k = 0; k < m->nnz; k++) moved = fmax(moved, fabs(alt[k] - ref[k]) / scale);
                free(alt);
                changes++;
            }
    printf("    refresh after %d mode changes of interface 2: max |refreshed - whole| / max|J| = %.2e "
           "(largest change of a value %.2e)\n", changes, worst, moved);
    ENSURE(worst < 1e-12);
    ENSURE(moved > 1e-3);
    free(val);
    free(ref);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

static void test_engine_jacobian_friction_cards_matches_finite_differences(void)
{
    jacobian_check(1);
}

/* Renard's law (/FRICTION Ifric 3, card 2 on interface 1): mu and dmu/dv
 * continuous at V_cr1 = C5 and V_cr2 = C6, on the kernel's own function. */
static void test_engine_renard_continuity(void)
{
    rc_case c;
    build_case(&c);
    add_friction_cards(&c);
    rc_model *m = NULL;
    rc_error e;
    ENSURE(rc_model_compile(&c, &m, &e) == RC_OK);
    if (!m) return;
    ENSURE(m->inter_fr[1].kind == RC_FK_CARD && m->inter_fr[1].ifric == 3);
    for (int dir = 0; dir < 2; dir++) {
        const double *cs = m->inter_fr[1].set[dir];
        const double bp[2] = {cs[4], cs[5]}; /* V_cr1, V_cr2 */
        for (int k = 0; k < 2; k++) {
            const double v = bp[k], h = 1e-7 * v;
            double lo = rc_friction_mu(m, 1, dir, 3.1e5, v - h, 731.0);
            double hi = rc_friction_mu(m, 1, dir, 3.1e5, v + h, 731.0);
            double at = rc_friction_mu(m, 1, dir, 3.1e5, v, 731.0);
            /* one-sided slopes from each side (second-order differences) */
            double sl = (3 * at - 4 * lo + rc_friction_mu(m, 1, dir, 3.1e5, v - 2 * h, 731.0)) / (2 * h);
            double sr = (-3 * at + 4 * hi - rc_friction_mu(m, 1, dir, 3.1e5, v + 2 * h, 731.0)) / (2 * h);
            printf("    Renard set %d at v = %.3g m/s: mu %.9f | %.9f | %.9f, slopes %.3e | %.3e\n", dir + 1, v, lo, at,
                   hi, sl, sr);
            ENSURE_NEAR(lo, at, 0, 1e-9);
            ENSURE_NEAR(hi, at, 0, 1e-9);
            ENSURE_NEAR(sl, sr, 0, 1e-6);
        }
        /* the values of docs/theory.md 6: mu_s at rest, mu_max at V_cr1, mu_min at V_cr2, -> mu_d */
        ENSURE_NEAR(rc_friction_mu(m, 1, dir, 0, 0.0, 731.0), cs[0], 1e-15, 0);
        ENSURE_NEAR(rc_friction_mu(m, 1, dir, 0, cs[4], 731.0), cs[2], 1e-15, 0);
        ENSURE_NEAR(rc_friction_mu(m, 1, dir, 0, cs[5], 731.0), cs[3], 1e-15, 0);
        ENSURE_NEAR(rc_friction_mu(m, 1, dir, 0, 1e6, 731.0), cs[1], 1e-9, 0);
    }
    rc_model_free(m);
}

/* Torque-free asymmetric top: quaternion norm held by projection, kinetic
 * energy and the angular momentum magnitude conserved. */
static void test_engine_quaternion_drift_and_gyroscopic_invariants(void)
{
    rc_case c;
    build_case(&c);
    c.ntype6 = 0;
    c.ngrav = 0;
    c.ncoupling = 0;
    c.nrbody = 1;
    c.nsurf = 0;
    c.run.tend = 200.0;
    c.run.dtout = 7.3;
    rc_model *m = NULL;
    rc_error e;
    ENSURE(rc_model_compile(&c, &m, &e) == RC_OK);
    if (!m) return;
    double *w = m->body_y0 + 10; /* spin mostly about the intermediate axis */
    w[0] = 0.37; w[1] = 9.1; w[2] = -0.23;
    double y0[13], y1[13];
    rc_initial_state(m, y0);
    rc_run_options opt = {.y_end = y1};
    rc_stats st;
    ENSURE(rc_run(m, &opt, &st, &e) == RC_OK);
    double nq = sqrt(y1[3] * y1[3] + y1[4] * y1[4] + y1[5] * y1[5] + y1[6] * y1[6]);
    printf("    200 s spin: | |q| - 1 | = %.2e, steps %ld\n", fabs(nq - 1), st.steps);
    /* steps are projected; the value returned at an output time is CVODE's
     * interpolant, within the error tolerance (rtol 1e-8), and the norm
     * error does not accumulate over the steps */
    ENSURE_NEAR(nq, 1.0, 0, 1e-8);
    /* invariants: T = 1/2 w.J w, |L| = |J w| */
    const double *J = m->body_J;
    double T0 = 0, T1 = 0, L0 = 0, L1 = 0;
    for (int i = 0; i < 3; i++) {
        double a = 0, b = 0;
        for (int j = 0; j < 3; j++) {
            a += J[3 * i + j] * y0[10 + j];
            b += J[3 * i + j] * y1[10 + j];
        }
        T0 += 0.5 * y0[10 + i] * a;
        T1 += 0.5 * y1[10 + i] * b;
        L0 += a * a;
        L1 += b * b;
    }
    printf("    invariants: dT/T = %.2e, d|L|/|L| = %.2e\n", fabs(T1 - T0) / T0, fabs(sqrt(L1) - sqrt(L0)) / sqrt(L0));
    ENSURE_NEAR(T1, T0, 1e-5, 0);
    ENSURE_NEAR(sqrt(L1), sqrt(L0), 1e-5, 0);
    rc_model_free(m);
}

/* A cube spinning in free flight above a floor it never reaches: its
 * quaternion tolerance comes from the contact's scales (about 1e-12), far
 * below the norm error that the projection removes at every step. With the
 * projected error estimate CVODE's order selection read the unprojected
 * radial part and BDF stayed at order 1 (6 329 steps, the quaternion off the
 * exact rotation by 2.5e-5); its isotropic inertia keeps omega constant, so
 * q(t) = (cos(|w| t / 2), sin(|w| t / 2) w / |w|) exactly. */
static void test_engine_spin_projection_keeps_bdf_order(void)
{
    static const char *deck =
        "/BEGIN\nspinning cube\n      2022         0\n"
        "                  kg                   m                   s\n"
        "                  kg                   m                   s\n"
        "/NODE\n         1                   0                   0                 1.0\n"
        "/FUNCT/1\nlinear\n                   0                   0\n                   1             1000000\n"
        "/SURF/PLANE/10\nfloor\n                   0                   0                   0\n"
        "                   0                   0                   1\n"
        "/GRNOD/NODE/1\ncube\n         1\n"
        "/RBODY/1\ncube\n         1                                                15         1\n"
        "     0.0016666666667     0.0016666666667     0.0016666666667\n"
        "                   0                   0                   0\n"
        "/SURF/BOX/11\ncube\n         1\n                   0                   0                 1.0\n"
        "                0.05                0.05                0.05\n"
        "/INIVEL/ROT/1\nspin\n                  20                 -35                  50         1         0\n"
        "/INTER/TYPE6/1\ncube on the floor\n        11        10\n"
        "                                                           0\n"
        "                   0         0         0         0         0\n"
        "         1         0                                                 0\n"
        "         0\n                   0         0         0\n"
        "/RUN\n                 0.5                0.05\n/END\n";
    rc_error e;
    rc_model *m = TU_COMPILE_OK(deck, "spin.rad");
    if (!m) return;
    const int n = rc_model_state_size(m);
    double *y1 = calloc((size_t)n, sizeof(double));
    ENSURE(y1 != NULL);
    if (!y1) {
        rc_model_free(m);
        return;
    }
    rc_run_options opt = {.y_end = y1};
    rc_stats st;
    ENSURE(rc_run(m, &opt, &st, &e) == RC_OK);
    const double w[3] = {20.0, -35.0, 50.0}, wn = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    const double th = wn * 0.5, qa[4] = {cos(th / 2), sin(th / 2) * w[0] / wn, sin(th / 2) * w[1] / wn,
                                         sin(th / 2) * w[2] / wn};
    double s = 0.0, dq = 0.0;
    for (int k = 0; k < 4; k++) s += y1[3 + k] * qa[k];
    for (int k = 0; k < 4; k++) dq = fmax(dq, fabs(y1[3 + k] - (s < 0 ? -qa[k] : qa[k])));
    printf("    5 turns in 0.5 s: %ld steps, quaternion off the exact rotation by %.2e\n", st.steps, dq);
    ENSURE(dq < 2e-6);
    ENSURE(st.steps < 1500);
    free(y1);
    rc_model_free(m);
}

/* ---- power law, cylinders, boxes, imposed velocities (issue 5) ------- */
/* Four bodies: 1 a roller (cylinder, offset from its CoM, tilted axis, full
 * inertia) on a fixed plane and under body 2, a box; 3 carries a sphere on
 * the box and a cylinder beside the roller (parallel axes); 4 a capsule
 * (rounded ends, deepest-point contact) on the plane. /INTER/POWER roller-
 * plane (m1, m3 < 1 regularised, m2 > 1, RDF, step5 friction capped),
 * roller-box (stiffness and damping splines), sphere-box (m2 < 1); TYPE6
 * cylinder-cylinder (incremental friction) and capsule-plane; /IMPVEL: the
 * box's X velocity and the capsule's rotation (XX, ZZ). */
static rc_case_funct pfn[5];
static double pfx0[] = {-0.001, 0.0, 0.0004, 0.001, 0.003}, pfy0[] = {-90.0, 0.0, 41.0, 230.0, 1900.0}; /* stiff */
static double pfx1[] = {-5.0, -1.0, 0.0, 1.0, 5.0}, pfy1[] = {-31.0, -4.1, 0.0, 3.7, 27.0};           /* damp */
static double pfx2[] = {0.0, 0.01, 1.0}, pfy2[] = {0.2, 0.29, 1.3};                                    /* v(t) */
static double pfx3[] = {0.0, 0.5, 1.0}, pfy3[] = {1.1, 2.3, 1.7};                                      /* w(t) */
static rc_case_node pnodes[4] = {{1, {0.0013, 0.0011, 0.0497}, {0}},
                                 {2, {0.0021, -0.0017, 0.1311}, {0}},
                                 {3, {0.0371, 0.0413, 0.1307}, {0}},
                                 {4, {0.5013, 0.0021, 0.0541}, {0}}};
static rc_case_rbody prb[4];
static rc_case_surf psf[7];
static rc_case_type6 pt6[2];
static rc_case_power ppw[3];
static rc_case_impvel pimp[3];
static rc_case_grnod pgrn[2];
static int pgrn_nodes[2][1] = {{2}, {4}};

static void build_power_case(rc_case *c)
{
    memset(c, 0, sizeof *c);
    c->path = "engine-power-test";
    pfn[0] = (rc_case_funct){71, "stiff", 5, pfx0, pfy0, {0}};
    pfn[1] = (rc_case_funct){72, "damp", 5, pfx1, pfy1, {0}};
    pfn[2] = (rc_case_funct){73, "v(t)", 3, pfx2, pfy2, {0}};
    pfn[3] = (rc_case_funct){74, "w(t)", 3, pfx3, pfy3, {0}};
    pfn[4] = (rc_case_funct){7, "load", 5, fx0, fy0, {0}};
    c->nfunct = 5;
    c->funct = pfn;
    c->nnode = 4;
    c->node = pnodes;
    memset(prb, 0, sizeof prb);
    const double J[4][6] = {{2.1e-3, 1.7e-3, 2.9e-3, 1.3e-4, -2.2e-4, 0.7e-4}, {3.1e-2, 2.3e-2, 4.7e-2, 0, 0, 0},
                            {1.1e-3, 1.3e-3, 0.9e-3, 0, 0, 0}, {0.7e-3, 0.9e-3, 0.5e-3, 0.1e-3, 0, 0}};
    const double mass[4] = {0.731, 2.37, 0.413, 0.291};
    for (int b = 0; b < 4; b++) {
        prb[b].id = 11 + b;
        prb[b].node_id = 1 + b;
        prb[b].mass = mass[b];
        memcpy(prb[b].J, J[b], sizeof J[b]);
    }
    c->nrbody = 4;
    c->rbody = prb;
    memset(psf, 0, sizeof psf);
    /* roller: lowest generator 0.8 mm into the plane, top 0.6 mm into the box */
    psf[0] = (rc_case_surf){.id = 21, .kind = RC_CASE_SURF_CYL, .c = {0.0023, 0.0005, 0.0492}, .abc = {0.05, 0.05, 0.05},
                            .axis = {1.0, 0.05, 0.02}, .length = 0.2, .rbody_id = 11};
    psf[1] = (rc_case_surf){.id = 22, .kind = RC_CASE_SURF_PLANE, .m = {0.0, 0.0, 0.0}, .m1 = {0.011, -0.007, 1.0}};
    psf[2] = (rc_case_surf){.id = 23, .kind = RC_CASE_SURF_BOX, .c = {0.0, 0.0, 0.1286}, .abc = {0.15, 0.1, 0.03},
                            .axis = {1.0, 0.03, 0.0}, .axis2 = {0.0, 1.0, 0.01}, .rbody_id = 12};
    psf[3] = (rc_case_surf){.id = 24, .kind = RC_CASE_SURF_ELLIPS, .degree = 2, .c = {0.05, 0.02, 0.1782},
                            .abc = {0.02, 0.02, 0.02}, .rbody_id = 13};
    psf[4] = (rc_case_surf){.id = 25, .kind = RC_CASE_SURF_CYL, .c = {0.0023, 0.0805, 0.0492}, .abc = {0.031, 0.031, 0.031},
                            .axis = {1.0, 0.05, 0.02}, .length = 0.1, .rbody_id = 13};
    psf[5] = (rc_case_surf){.id = 26, .kind = RC_CASE_SURF_CYL, .c = {0.5023, 0.0011, 0.0521}, .abc = {0.02, 0.02, 0.02},
                            .axis = {0.3, 0.1, 1.0}, .length = 0.08, .ends = 1, .cmode = 1, .rbody_id = 14};
    c->nsurf = 6;
    c->surf = psf;
    /* the roller's neighbour overlaps it by 0.5 mm */
    const double *a = psf[0].axis, ay = a[1] / sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    psf[4].c[1] = psf[0].c[1] + (0.05 + 0.031 - 0.001) / sqrt(1.0 - ay * ay);
    memset(ppw, 0, sizeof ppw);
    ppw[0] = (rc_case_power){.id = 41, .surf1 = 22, .surf2 = 21, .ispline = 4, .irdf = 1, .k = 3.7e4, .m1 = 0.7,
                             .c = 2.9e3, .m2 = 1.3, .m3 = 0.6, .rdf = 0.001, .dreg = 5e-4, .vreg = 1e-6,
                             .tstop = 1e30, .mus = 0.31, .vs = 0.21, .mud = 0.23, .vd = 1.9, .fmax = 0.0};
    ppw[1] = (rc_case_power){.id = 42, .surf1 = 21, .surf2 = 23, .fct_stiff = 71, .fct_damp = 72, .ispline = 3,
                             .irdf = 1, .k = 0.0, .m1 = 2.0, .c = 0.0, .m2 = 1.0, .m3 = 1.5, .rdf = 0.013,
                             .dreg = 1e-6, .vreg = 1e-6, .tstop = 1e30, .mus = 0.41, .vs = 7.3, .mud = 0.2,
                             .vd = 9.1, .fmax = 30.0};
    ppw[2] = (rc_case_power){.id = 43, .surf1 = 24, .surf2 = 23, .ispline = 4, .irdf = 2, .k = 2.3e7, .m1 = 1.5,
                             .c = 3.1e4, .m2 = 0.8, .m3 = 0.7, .rdf = 0.001, .dreg = 1e-3, .vreg = 0.6,
                             .tstop = 1e30};
    for (int k = 0; k < 3; k++) ppw[k].line_loc[0] = (rc_loc){"engine-power-test", 1};
    c->npower = 3;
    c->power = ppw;
    memset(pt6, 0, sizeof pt6);
    for (int k = 0; k < 2; k++) {
        pt6[k].id = 31 + k; pt6[k].tstop = 1e30; pt6[k].fct_ld = 7; pt6[k].ascalex = 1.3; pt6[k].fscaleld = 0.77;
        pt6[k].visc = 3.7; pt6[k].ascalef = 1.0; pt6[k].ascalev = 1.0; pt6[k].fscalev = 1.0; pt6[k].fscaleul = 1.0;
    }
    pt6[0].surf1 = 21; pt6[0].surf2 = 25; pt6[0].fric = 0.37; pt6[0].stiff = 3.1e4; /* incremental friction */
    pt6[1].surf1 = 22; pt6[1].surf2 = 26;
    c->ntype6 = 2;
    c->type6 = pt6;
    pgrn[0] = (rc_case_grnod){.id = 91, .n = 1, .nodes = pgrn_nodes[0]};
    pgrn[1] = (rc_case_grnod){.id = 92, .n = 1, .nodes = pgrn_nodes[1]};
    c->ngrnod = 2;
    c->grnod = pgrn;
    memset(pimp, 0, sizeof pimp);
    pimp[0] = (rc_case_impvel){.id = 1, .fct_id = 73, .dir = 0, .grnod_id = 91, .ascale = 0.7, .fscale = 1.3, .tstop = 1e30};
    pimp[1] = (rc_case_impvel){.id = 2, .fct_id = 74, .dir = 3, .grnod_id = 92, .ascale = 1.1, .fscale = 2.9, .tstop = 1e30};
    pimp[2] = (rc_case_impvel){.id = 3, .fct_id = 73, .dir = 5, .grnod_id = 92, .ascale = 0.3, .fscale = -3.7, .tstop = 1e30};
    c->nimpvel = 3;
    c->impvel = pimp;
    gr = (rc_case_grav){.id = 1, .fct_id = 0, .dir = 2, .u = {0, 0, 1}, .ascale = 1.0, .fscale = -9.81};
    c->ngrav = 1;
    c->grav = &gr;
    c->run = (rc_case_run){1, 0.01, 0.001, {0}, 0, 0};
    c->solver = (rc_case_solver){0, 1, 5, 100000, 1e-8, 1e-11, 1e-11, 1e-8, 1e-8, 1e-9, 0, 0, 0, {0}, {0}, 0};
}

/* Near the initial pose: every body turned a little (non-unit quaternion),
 * moving and spinning, own states of high entropy. */
static void power_entropy_state(const rc_model *m, double *y)
{
    rc_initial_state(m, y);
    static const double dq[4][4] = {{1.0003, 0.0021, -0.0013, 0.0017}, {0.9991, -0.0011, 0.0007, 0.0023},
                                    {1.0011, 0.0019, 0.0009, -0.0031}, {0.9997, 0.0013, -0.0021, 0.0011}};
    static const double dv[4][6] = {{0.31, -0.23, -0.17, 3.1, -2.3, 4.7}, {0.53, 0.19, 0.07, 0.7, 0.3, -0.9},
                                    {-0.41, 0.17, 0.53, -1.9, 0.7, 2.2}, {0.13, -0.29, -0.37, 1.3, -0.7, 2.9}};
    for (int b = 0; b < 4; b++) {
        double *s = y + m->body_yadr[b];
        for (int k = 0; k < 3; k++) s[k] += 1e-5 * (k + 1) * (b % 2 ? 1 : -1);
        for (int k = 0; k < 4; k++) s[3 + k] = dq[b][k];
        for (int k = 0; k < 6; k++) s[7 + k] = dv[b][k];
    }
    for (int i = 0; i < m->ninter; i++)
        for (int k = 0; k < m->inter_ns[i]; k++) y[m->inter_eadr[i] + k] = 0.013 * (k + 1) + 0.7 * i;
    const rc_fric *fr = &m->inter_fr[3]; /* TYPE6 cylinder-cylinder: F_t off the plane */
    const double ft[3] = {13.7, -8.1, 2.3};
    for (int k = 0; k < 3 && fr->tidx >= 0; k++) y[m->inter_eadr[3] + fr->tidx + k] = ft[k];
    y[m->imp->wadr] = 0.37;
}

static void test_engine_jacobian_power_cylinders_impvel_matches_finite_differences(void)
{
    rc_case c;
    build_power_case(&c);
    rc_model *m = NULL;
    rc_error e;
    rc_status st = rc_model_compile(&c, &m, &e);
    if (st) printf("    %s\n", e.msg);
    ENSURE(st == RC_OK);
    if (!m) return;
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double));
    power_entropy_state(m, y);
    for (int i = 0; i < m->ninter; i++) {
        rc_inter_report r;
        rc_inter_report_eval(m, i, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
        printf("    %s: P = %.4g m, v_n = %.4g m/s, slip speed %.4g m/s, F_n %.4g N\n", m->inter_name[i], r.p, r.vn,
               r.vslip, r.fn);
        ENSURE(r.p > 0); /* every contact penetrates in this state */
    }
    int bad = 0, outside = 0, combos = 0;
    double maxerr = 0;
    const int modes[2] = {RC_MODE_CLOSED, RC_MODE_RELEASED};
    for (int md = 0; md < 2; md++)
        for (int br = 0; br < 3; br++)
            for (int sl = 0; sl < 2; sl++) {
                for (int i = 0; i < m->ninter; i++) {
                    d->inter_mode[i] = modes[md];
                    d->inter_branch[i] = br;
                    d->inter_track[i] = 0;
                    d->inter_slip[i] = sl;
                }
                if (getenv("RC_DEBUG_JAC")) printf("    mode %d branch %d slip %d\n", modes[md], br, sl);
                maxerr = fmax(maxerr, tu_jac_fd_error(m, d, 0.0137, y, 0, &bad, &outside));
                combos++;
            }
    printf("    jacobian (power, cylinders, box, /IMPVEL): %d states, %lld nonzeros, %d mode combinations, max scaled "
           "|J - FD| = %.2e\n",
           m->ny, (long long)m->nnz, combos, maxerr);
    ENSURE(bad == 0);
    ENSURE(outside == 0);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

/* The same model with the box's imposed velocity along a skew axis u
 * (/IMPVEL skew_ID on a /SKEW/FIX): the box's three translation rows are
 * (I - u u^T) the free ones and the W_imp row gains the skewed terms; the
 * whole Jacobian against central differences. */
static void test_engine_jacobian_impvel_skew_matches_finite_differences(void)
{
    rc_case c;
    build_power_case(&c);
    static rc_case_mesh ms;
    static rc_case_skew sk;
    memset(&ms, 0, sizeof ms);
    memset(&sk, 0, sizeof sk);
    sk.id = 5;
    const double ax[3][3] = {{0.6, 0.8, 0.0}, {0.48, -0.36, 0.8}, {0.64, -0.48, -0.6}};
    memcpy(sk.axis, ax, sizeof ax);
    ms.nskew = 1;
    ms.skew = &sk;
    c.mesh = &ms;
    pimp[0].skew_id = 5;
    pimp[0].dir = 1; /* along Y' = (0.48, -0.36, 0.8) */
    rc_model *m = NULL;
    rc_error e;
    rc_status st = rc_model_compile(&c, &m, &e);
    if (st) printf("    %s\n", e.msg);
    ENSURE(st == RC_OK);
    if (!m) return;
    ENSURE(m->imp->nt == 1 && m->imp->tdir[0] == -1 && m->imp->nsk == 1);
    /* the initial velocity along u is the function's, the others zero */
    const double *v0 = m->body_y0 + RC_NB * 1 + 7;
    ENSURE_NEAR(v0[0] * 0.48 - v0[1] * 0.36 + v0[2] * 0.8, 1.3 * 0.2, 1e-15, 1e-15);
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double));
    power_entropy_state(m, y);
    int bad = 0, outside = 0;
    double maxerr = 0;
    for (int sl = 0; sl < 2; sl++) {
        for (int i = 0; i < m->ninter; i++) {
            d->inter_mode[i] = RC_MODE_CLOSED;
            d->inter_branch[i] = 0;
            d->inter_track[i] = 0;
            d->inter_slip[i] = sl;
        }
        maxerr = fmax(maxerr, tu_jac_fd_error(m, d, 0.0137, y, 0, &bad, &outside));
    }
    /* the rates: along u the imposed one, 1.3 f'(t / 0.7) / 0.7, t / 0.7 on the
     * table's second segment (slope 1.01 / 0.99) */
    double *f = calloc((size_t)m->ny, sizeof(double));
    rc_assemble_rhs(m, d, 0.0137, y, f);
    const double *a = f + m->body_yadr[1] + 7;
    ENSURE_NEAR(a[0] * 0.48 - a[1] * 0.36 + a[2] * 0.8, 1.3 * (1.01 / 0.99) / 0.7, 1e-12, 0);
    printf("    jacobian (/IMPVEL along a skew axis): %d states, %lld nonzeros, max scaled |J - FD| = %.2e\n", m->ny,
           (long long)m->nnz, maxerr);
    ENSURE(bad == 0);
    ENSURE(outside == 0);
    free(f);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
    pimp[0].skew_id = 0;
    pimp[0].dir = 0;
}

/* The smoothed slope of a tabulated curve (the viscous friction's
 * stiffness): the segments' slopes at their mid-points, linear between
 * them, continuous where x crosses a point of the curve (where the slope of
 * the piecewise-linear curve jumps), constant beyond the end mid-points;
 * its derivative against central differences. */
static void test_engine_table_slope_smooth(void)
{
    const double x[5] = {0.0, 0.3, 1.0, 3.0, 10.0}, y[5] = {0.0, 0.2, 1.0, 5.4, 46.0};
    rc_table t;
    rc_error e;
    ENSURE(rc_table_init(&t, 1, 5, x, y, &e) == RC_OK);
    double d;
    const double s0 = 0.2 / 0.3, s1 = 0.8 / 0.7, s2 = 4.4 / 2.0, s3 = 40.6 / 7.0;
    ENSURE_NEAR(rc_table_slope_smooth(&t, -1.0, &d), s0, 1e-15, 0.0);
    ENSURE(d == 0.0);
    ENSURE_NEAR(rc_table_slope_smooth(&t, 0.15, &d), s0, 1e-15, 0.0);
    ENSURE_NEAR(rc_table_slope_smooth(&t, 0.65, &d), s1, 1e-14, 0.0);
    ENSURE_NEAR(rc_table_slope_smooth(&t, 2.0, &d), s2, 1e-14, 0.0);
    ENSURE_NEAR(rc_table_slope_smooth(&t, 6.5, &d), s3, 1e-14, 0.0);
    ENSURE_NEAR(rc_table_slope_smooth(&t, 50.0, &d), s3, 1e-14, 0.0);
    ENSURE(d == 0.0);
    /* at a point of the curve: the mean of the two mid-point lines, no jump */
    for (int k = 1; k < 4; k++) {
        const double h = 1e-9 * x[k];
        const double a = rc_table_slope_smooth(&t, x[k] - h, &d), b = rc_table_slope_smooth(&t, x[k] + h, &d);
        ENSURE(fabs(b - a) < 1e-6 * fabs(a));
    }
    /* the derivative inside each interval between mid-points */
    const double xs[4] = {0.4, 0.9, 1.7, 4.2};
    for (int k = 0; k < 4; k++) {
        const double h = 1e-6;
        double dp, dm;
        rc_table_slope_smooth(&t, xs[k], &d);
        const double fd =
            (rc_table_slope_smooth(&t, xs[k] + h, &dp) - rc_table_slope_smooth(&t, xs[k] - h, &dm)) / (2 * h);
        ENSURE_NEAR(d, fd, 1e-6, 0.0);
    }
    /* a two-point curve: its one slope */
    rc_table t2;
    ENSURE(rc_table_init(&t2, 2, 2, x, y, &e) == RC_OK);
    ENSURE_NEAR(rc_table_slope_smooth(&t2, 0.7, &d), s0, 1e-15, 0.0);
    rc_table_free(&t2);
    rc_table_free(&t);
}

/* The slope of a tabulated curve for a scale (rc_table_slope_at): at a
 * point of the curve within 1e-9 of it, the steeper of the two segments
 * meeting there, on either side of the point; elsewhere the segment's own.
 * A scale found by inverting the load curve at a body's weight lands on a
 * point of the curve within rounding when the curve has one there; the
 * slope then depended on the side the rounding took (a fuzzer scene moved
 * 1 km away and rotated: k_s 1.1e4 N/m against 2.3e4, other tolerances, a
 * motion 5 mm away after 0.9 s). Then a deck whose box weighs exactly the
 * force of a point of its load curve: the interface's stiffness scale is
 * the steeper side's, with gravity as given and 1e-15 weaker. */
static void test_engine_table_slope_at_a_point(void)
{
    const double x[5] = {0.0, 0.3, 1.0, 3.0, 10.0}, y[5] = {0.0, 0.2, 1.0, 5.4, 46.0};
    rc_table t;
    rc_error e;
    ENSURE(rc_table_init(&t, 1, 5, x, y, &e) == RC_OK);
    const double s[4] = {0.2 / 0.3, 0.8 / 0.7, 4.4 / 2.0, 40.6 / 7.0};
    for (int k = 1; k < 4; k++) {
        const double steep = fmax(s[k - 1], s[k]);
        for (int side = -1; side <= 1; side++) {
            const double xk = x[k] * (1.0 + side * 1e-12);
            ENSURE_NEAR(rc_table_slope_at(&t, xk), steep, 1e-14, 0.0);
        }
        ENSURE_NEAR(rc_table_slope_at(&t, x[k] * (1.0 - 1e-6)), s[k - 1], 1e-14, 0.0);
        ENSURE_NEAR(rc_table_slope_at(&t, x[k] * (1.0 + 1e-6)), s[k], 1e-14, 0.0);
    }
    ENSURE_NEAR(rc_table_slope_at(&t, 0.0), s[0], 1e-15, 0.0);   /* the first point: its one segment */
    ENSURE_NEAR(rc_table_slope_at(&t, 20.0), s[3], 1e-14, 0.0);  /* beyond the last: extended */
    rc_table_free(&t);
    /* the deck: a 1 kg box, load curve with a point at 9.81 N (1e-4 m) */
    char deck[2048];
    double kk[2];
    for (int v = 0; v < 2; v++) {
        snprintf(deck, sizeof deck,
                 "/BEGIN\nbox whose weight is a point of its curve\n      2022         0\n"
                 "                  kg                   m                   s\n"
                 "                  kg                   m                   s\n"
                 "/NODE\n1,0,0,0.05\n/RBODY/1\nbox\n1,,,,1,1\n0.001,0.001,0.001\n0,0,0\n"
                 "/GRNOD/NODE/1\nbox\n1\n/SURF/BOX/1\nbox\n1\n0,0,0.05\n0.05,0.05,0.05\n"
                 "/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n"
                 "/FUNCT/1\nload\n0,0\n0.0001,9.81\n0.0002,40\n"
                 "/INTER/TYPE6/1\nbox on floor\n1,2\n\n\n1,0\n\n\n"
                 "/GRAV/1\ng\n0,Z,0,0,1,,1,%.17g\n/RUN\n0.01,0.001\n/END\n",
                 v == 0 ? -9.81 : -9.81 * (1.0 - 1e-15));
        rc_model *m = TU_COMPILE_OK(deck, "slope_at_point.rad");
        kk[v] = m ? m->inter_kscale[0] : NAN;
        printf("    gravity %s: p_s %.17g m, k_s %.17g N/m\n", v ? "1e-15 weaker" : "as given",
               m ? m->inter_pscale[0] : NAN, kk[v]);
        rc_model_free(m);
    }
    ENSURE_NEAR(kk[0], (40.0 - 9.81) / 0.0001, 1e-9, 0.0);
    ENSURE(kk[1] == kk[0]);
}

void suite_engine(void);
void suite_engine(void)
{
    RUN_TEST(test_engine_jacobian_matches_finite_differences);
    RUN_TEST(test_engine_jacobian_friction_cards_matches_finite_differences);
    RUN_TEST(test_engine_jacobian_refresh_after_mode_change);
    RUN_TEST(test_engine_renard_continuity);
    RUN_TEST(test_engine_table_slope_smooth);
    RUN_TEST(test_engine_table_slope_at_a_point);
    RUN_TEST(test_engine_quaternion_drift_and_gyroscopic_invariants);
    RUN_TEST(test_engine_spin_projection_keeps_bdf_order);
    RUN_TEST(test_engine_jacobian_power_cylinders_impvel_matches_finite_differences);
    RUN_TEST(test_engine_jacobian_impvel_skew_matches_finite_differences);
}
