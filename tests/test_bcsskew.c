/*
 * /BCS with a skew holding one or two of Tx Ty Tz: the velocity along each
 * held skew axis is held at zero (model/imposed.h). A ball on a rail (Y'
 * and Z' held) against the closed form of its motion and of its landing on
 * a floor, on CVODE and IDA; the right-hand side's rates along the held
 * axes and the Jacobian against finite differences with contacts acting on
 * a body held along one and along two axes; the input errors.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "engine/assembly/assembly.h"
#include "engine/assembly/data.h"
#include "harness.h"
#include "model/imposed.h"
#include "model/model.h"
#include "ricochet/ricochet.h"
#include "testutil.h"

/* A ball (radius 0.05 m, 2 kg) at z = 1 m on a rail inclined 30 degrees in
 * the xz plane: /SKEW/FIX/7 with X' = (cos 30, 0, sin 30) up the rail,
 * /BCS/1 holding Ty' and Tz' (`trarot`); thrown with (1, 2, 3) m/s; a
 * floor z = 0 under a linear TYPE6 contact (k = 1e7 N/m); `extra` cards
 * before /RUN. */
static const char *rail_deck(const char *trarot, const char *extra)
{
    static char text[4096];
    snprintf(text, sizeof text,
             "/BEGIN\nrail\n      2022         0\n                  kg                   m                   s\n"
             "                  kg                   m                   s\n"
             "/NODE\n         1                 0.0                 0.0                 1.0\n"
             "/RBODY/1\nball\n         1                                                 2\n"
             "               0.002               0.002               0.002\n"
             "                   0                   0                   0\n"
             "/SURF/ELLIPS/1\nball\n         0         2         1\n"
             "                 0.0                 0.0                 1.0\n"
             "                0.05                0.05                0.05\n"
             "/SURF/PLANE/2\nfloor\n                 0.0                 0.0                 0.0\n"
             "                 0.0                 0.0                 1.0\n"
             "/FUNCT/1\nlinear\n                   0                   0\n                   1            10000000\n"
             "/INTER/TYPE6/1\nball on floor\n         1         2\n\n"
             "                                                 0         0\n"
             "         1         0                 1.0                 1.0\n"
             "                                                         1.0\n"
             "                             0         0\n"
             "/SKEW/FIX/7\nrail frame: X' up the rail\n                 0.0                 0.0                 0.0\n"
             "                 0.0                 1.0                 0.0\n"
             "                -0.5                 0.0  0.8660254037844386\n"
             "/GRNOD/NODE/1\nball\n         1\n"
             "/BCS/1\non the rail\n   %s         7         1\n"
             "/INIVEL/TRA/1\nthrown\n                 1.0                 2.0                 3.0         1         0\n"
             "/GRAV/1\ngravity\n         0         Z         0         0         0                             1"
             "               -9.81\n"
             "%s/RUN\n                 1.6                0.05\n/END\n",
             trarot, extra);
    return text;
}

/* On the rail the ball moves along u = X' only, s(t) = v0.u t - g sin30 t^2
 * / 2 (the initial velocity's other components held to zero), and lands on
 * the floor when 1 + sin30 s(t) = 0.05. */
static void test_bcsskew_rail_closed_form(void)
{
    static tu_evlog ev;
    const double s30 = 0.5, c30 = sqrt(3.0) / 2, g = 9.81, u[3] = {c30, 0.0, s30}, v0u = c30 * 1.0 + s30 * 3.0;
    /* the later root of g sin30 t^2 / 2 - v0.u t - 0.95 / sin30 = 0 */
    const double tl = (v0u + sqrt(v0u * v0u + 2.0 * g * 0.95)) / (g * s30);
    for (int method = 1; method <= 2; method++) {
        rc_model *m = TU_COMPILE_OK(rail_deck("011 000", ""), "rail.rad");
        if (!m) continue;
        rc_error e;
        rc_error_clear(&e);
        ENSURE(rc_model_set_method(m, method, &e) == RC_OK);
        ENSURE(m->imp && m->imp->nt == 2 && m->imp->ttab[0] == -1 && m->imp->tbcs[0] == 1);
        /* the initial velocity keeps its component along the rail only */
        const double *v0 = m->body_y0 + 7;
        for (int i = 0; i < 3; i++) ENSURE_NEAR(v0[i], v0u * u[i], 1e-15, 0);
        /* free flight along the rail: the state at 1 s */
        double *y = calloc((size_t)rc_model_state_size(m), sizeof(double));
        rc_run_options o = {.t_end_override = 1.0, .y_end = y};
        ENSURE(rc_run(m, &o, NULL, &e) == RC_OK);
        const double t = 1.0, s = v0u * t - 0.5 * g * s30 * t * t, vs = v0u - g * s30 * t;
        const double x0[3] = {0.0, 0.0, 1.0};
        double ex = 0, evel = 0;
        for (int i = 0; i < 3; i++) {
            ex = fmax(ex, fabs(y[i] - (x0[i] + s * u[i])));
            evel = fmax(evel, fabs(y[7 + i] - vs * u[i]));
        }
        printf("    %s: |x - x_exact| %.2e m, |v - v_exact| %.2e m/s at 1 s\n", method == 1 ? "CVODE" : "IDA", ex, evel);
        ENSURE(ex < 1e-9);
        ENSURE(evel < 1e-9);
        /* the landing */
        memset(&ev, 0, sizeof ev);
        rc_run_options o2 = {.on_event = tu_evlog_event, .user = &ev};
        ENSURE(rc_run(m, &o2, NULL, &e) == RC_OK);
        double tc = -1;
        ENSURE(tu_evlog_first(&ev, "contact_close", &tc, NULL) >= 1);
        printf("    %s: lands at %.12f s (closed form %.12f s)\n", method == 1 ? "CVODE" : "IDA", tc, tl);
        ENSURE_NEAR(tc, tl, 1e-9, 0);
        free(y);
        rc_model_free(m);
    }
}

/* Two balls in contact, ball 1 held along the rail (two axes) or in the
 * rail's plane (Tz' alone), each also pressed into the floor: the rates
 * along the held axes are zero, the free ones the projection of F / m; the
 * Jacobian against finite differences. */
static void test_bcsskew_rates_and_jacobian(void)
{
    static const char ball2[] =
        "/NODE\n         2                0.03                0.02                0.12\n"
        "/RBODY/2\nball 2\n         2                                                 1\n"
        "               0.001               0.001               0.001\n"
        "                   0                   0                   0\n"
        "/SURF/ELLIPS/3\nball 2\n         0         2         2\n"
        "                0.03                0.02                0.12\n"
        "                0.05                0.05                0.05\n"
        "/INTER/TYPE6/2\nballs\n         1         3\n                                     0.3\n"
        "                                                 0         0\n"
        "         1         0                 1.0                 1.0\n"
        "                                                         1.0\n"
        "                40.0         0         0\n";
    const char *trs[2] = {"011 000", "001 000"};
    for (int k = 0; k < 2; k++) {
        rc_model *m = TU_COMPILE_OK(rail_deck(trs[k], ball2), "rail2.rad");
        if (!m) continue;
        ENSURE(m->imp && m->imp->nt == 2 - k && m->imp->nsk == 2 - k);
        rc_data *d = rc_data_new(m);
        double *y = calloc((size_t)m->ny, sizeof(double)), *f = calloc((size_t)m->ny, sizeof(double));
        double *f0 = calloc((size_t)m->ny, sizeof(double));
        rc_initial_state(m, y);
        /* ball 1 at (0, 0, 0.048): 2 mm into the floor, 3 mm into ball 2;
         * moving and spinning */
        const int a = m->body_yadr[0];
        y[a + 2] = 0.048;
        y[a + 7] = 0.3;
        y[a + 8] = -0.2;
        y[a + 9] = 0.1;
        y[a + 10] = 2.0;
        y[a + 12] = -1.0;
        for (int i = 0; i < m->ninter; i++) {
            d->inter_mode[i] = RC_MODE_CLOSED;
            d->inter_branch[i] = 0;
            d->inter_track[i] = 0;
            d->inter_slip[i] = 1;
        }
        ENSURE(rc_assemble_rhs(m, d, 0.0, y, f) == 0);
        /* the rates without the hold: the same model with its projection
         * off (nt 0: the imposed rows left free) */
        const int nt = m->imp->nt;
        m->imp->nt = 0;
        ENSURE(rc_assemble_rhs(m, d, 0.0, y, f0) == 0);
        m->imp->nt = nt;
        double free_a[3], held = 0, along = 0, fa = 0;
        for (int i = 0; i < 3; i++) free_a[i] = f0[a + 7 + i];
        for (int h = 0; h < nt; h++) {
            const double *u = m->imp->tu + 3 * h;
            held = fmax(held, fabs(u[0] * f[a + 7] + u[1] * f[a + 8] + u[2] * f[a + 9]));
        }
        /* the free part: f = P f0, P = I - sum u u^T */
        for (int i = 0; i < 3; i++) {
            double p = free_a[i];
            for (int h = 0; h < nt; h++) {
                const double *u = m->imp->tu + 3 * h;
                p -= u[i] * (u[0] * free_a[0] + u[1] * free_a[1] + u[2] * free_a[2]);
            }
            along = fmax(along, fabs(f[a + 7 + i] - p));
            fa = fmax(fa, fabs(free_a[i]));
        }
        ENSURE(fa > 1.0); /* the contacts push */
        ENSURE(held <= 1e-12 * fa);
        ENSURE(along <= 1e-12 * fa);
        int bad = 0, outside = 0;
        const double err = tu_jac_fd_error(m, d, 0.0, y, 0, &bad, &outside);
        printf("    %s: |a.u| %.2e, |a - P a_free| %.2e (|a_free| %.3g m/s^2), jacobian max scaled |J - FD| %.2e\n",
               trs[k], held, along, fa, err);
        ENSURE(bad == 0);
        ENSURE(outside == 0);
        free(f0);
        free(f);
        free(y);
        rc_data_free(d);
        rc_model_free(m);
    }
}

static void test_bcsskew_errors(void)
{
    /* a moving skew */
    static const char mov[] = "/NODE\n 11,0,0,0\n 12,1,0,0\n 13,0,1,0\n"
                              "/SKEW/MOV/8\nmoving\n 11,12,13\n"
                              "/BCS/2\nm\n   001 000         8         1\n";
    ENSURE(tu_text_error(rail_deck("000 000", mov), "mov.rad", "card /BCS/2", "field skew_ID", "/SKEW/MOV/8",
                         "not supported yet", (const char *)NULL) == 0);
    /* with a global hold on the same body */
    ENSURE(tu_text_error(rail_deck("011 000", "/BCS/3\ng\n   100 000         0         1\n"), "glob.rad", "card /BCS/1",
                         "/RBODY/1", "along a global axis", "not supported yet", (const char *)NULL) == 0);
    /* with an imposed translation */
    ENSURE(tu_text_error(rail_deck("011 000", "/IMPVEL/4\nv\n         1         X         0         0         1\n"),
                         "imp.rad", "card /BCS/1", "/IMPVEL/4", "not supported yet", (const char *)NULL) == 0);
    /* an imposed velocity along a skew axis not orthogonal to the held ones */
    ENSURE(tu_text_error(rail_deck("011 000", "/SKEW/FIX/9\ntilted\n0,0,0\n0,0.6,0.8\n0,-0.8,0.6\n"
                                              "/IMPVEL/4\nv\n         1         Y         9         0         1\n"),
                         "impskew.rad", "card /BCS/1", "/IMPVEL/4", "not orthogonal", (const char *)NULL) == 0);
    /* axes of two skews that are not orthogonal */
    static const char two[] = "/SKEW/FIX/9\ntilted\n0,0,0\n0,0.6,0.8\n0,-0.8,0.6\n"
                              "/BCS/5\nb\n   001 000         9         1\n";
    ENSURE(tu_text_error(rail_deck("001 000", two), "two.rad", "card /BCS/5", "not orthogonal", "/BCS/1",
                         (const char *)NULL) == 0);
    /* the same axis held twice (two cards on one skew) is taken once */
    rc_model *m = TU_COMPILE_OK(rail_deck("011 000", "/BCS/6\nagain\n   001 000         7         1\n"), "twice.rad");
    if (m) ENSURE(m->imp && m->imp->nt == 2);
    rc_model_free(m);
    /* the static analysis refuses it, naming the card */
    m = TU_COMPILE_OK(rail_deck("011 000", ""), "stat.rad");
    if (m) {
        rc_error e;
        rc_error_clear(&e);
        ENSURE(rc_model_set_method(m, 3, &e) != RC_OK || rc_run(m, &(rc_run_options){0}, NULL, &e) != RC_OK);
        ENSURE(strstr(e.msg, "/BCS/1") && strstr(e.msg, "skew"));
        if (!strstr(e.msg, "/BCS/1")) printf("    %s\n", e.msg);
    }
    rc_model_free(m);
}

/* The ball on the rail driven along it (/IMPVEL Dir X on skew 7: X', the
 * rail; Y', Z' held by /BCS): x(t) = x0 + V t u, the velocity V u from
 * t = 0 (the /INIVEL's other components removed), whatever gravity does;
 * W_imp takes the work of the drive against gravity, m g sin30 V t. */
static void test_bcsskew_driven_along_the_rail(void)
{
    const double V = 0.7, u[3] = {sqrt(3.0) / 2, 0.0, 0.5};
    rc_model *m = TU_COMPILE_OK(rail_deck("011 000", "/FUNCT/2\none\n0,1\n10,1\n"
                                                     "/IMPVEL/4\nv\n         2         X         7         0         1\n"
                                                     "                 1.0                 0.7\n"),
                                "drive.rad");
    if (!m) return;
    ENSURE(m->imp && m->imp->nt == 3 && m->imp->nsk == 3);
    int nfirst = 0;
    for (int k = 0; k < m->imp->nt; k++) nfirst += m->imp->tfirst[k];
    ENSURE(nfirst == 1);
    double *y = calloc((size_t)rc_model_state_size(m), sizeof(double));
    rc_error e;
    rc_error_clear(&e);
    rc_run_options o = {.t_end_override = 1.0, .y_end = y};
    ENSURE(rc_run(m, &o, NULL, &e) == RC_OK);
    double ex = 0, ev = 0;
    const double x0[3] = {0.0, 0.0, 1.0};
    for (int i = 0; i < 3; i++) {
        ex = fmax(ex, fabs(y[i] - (x0[i] + V * 1.0 * u[i])));
        ev = fmax(ev, fabs(y[7 + i] - V * u[i]));
    }
    const double wimp = y[m->imp->wadr], wexp = -2.0 * 9.81 * 0.5 * V * 1.0;
    printf("    driven along the rail: |x - x_exact| %.2e m, |v - V u| %.2e m/s at 1 s, W_imp %.9g J (%.9g J)\n", ex,
           ev, wimp, wexp);
    ENSURE(ex < 1e-9);
    ENSURE(ev < 1e-12);
    ENSURE_NEAR(wimp, wexp, 1e-8, 0);
    free(y);
    rc_model_free(m);
    /* the drive stopping at Tstop = 0.5 s beside the holds: the Jacobian
     * (the W_imp row, whose lambdas the holds measure on the body's free
     * rates) against finite differences while it drives and after */
    m = TU_COMPILE_OK(rail_deck("011 000", "/FUNCT/2\none\n0,1\n10,1\n"
                                           "/IMPVEL/4\nv\n         2         X         7         0         1\n"
                                           "                 1.0                 0.7                 0.0"
                                           "                 0.5\n"),
                      "drive2.rad");
    if (!m) return;
    rc_data *d = rc_data_new(m);
    y = calloc((size_t)m->ny, sizeof(double));
    rc_initial_state(m, y);
    y[7] += 0.01; /* off the constraint a little: lambda u.v != 0 */
    y[9] -= 0.02;
    for (int k = 0; k < 2; k++) {
        int bad = 0, outside = 0;
        const double t = k ? 0.3 : 0.7, err = tu_jac_fd_error(m, d, t, y, 0, &bad, &outside);
        printf("    driven until 0.5 s, at %.1f s: jacobian max scaled |J - FD| %.2e\n", t, err);
        ENSURE(bad == 0);
        ENSURE(outside == 0);
    }
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

/* A hold along a skew's axes counts for the contact's mass as one along
 * the global axes does: the ball on the rail moves along u = X' alone, so
 * along the floor's normal z it weighs m / (u.z)^2 = 2 / 0.25 = 8 kg (its
 * reduced mass, which sets the contact's speed scale, stick damper and
 * tolerances; and its mass at the point). Counted as free, 2 kg: a belt
 * held along a skew's axes gave its contact another speed scale than the
 * same scene in the belt's own axes, and the answers parted by 1e-4 of
 * the motion within 3 ms. */
static void test_bcsskew_contact_mass(void)
{
    rc_model *m = TU_COMPILE_OK(rail_deck("011 000", ""), "mass.rad");
    if (!m) return;
    printf("    ball on the rail against the floor: m_red %.15g kg, m at the point %.15g kg (8)\n", m->inter_mred[0],
           m->inter_mrest[0]);
    ENSURE_NEAR(m->inter_mred[0], 8.0, 1e-12, 0);
    ENSURE_NEAR(m->inter_mrest[0], 8.0, 1e-12, 0);
    rc_model_free(m);
    /* held along all three of the skew's axes: it does not move along the
     * normal at all */
    m = TU_COMPILE_OK(rail_deck("111 000", ""), "mass3.rad");
    if (!m) return;
    ENSURE(!isfinite(m->inter_mred[0]));
    rc_model_free(m);
}

void suite_bcsskew(void);
void suite_bcsskew(void)
{
    RUN_TEST(test_bcsskew_driven_along_the_rail);
    RUN_TEST(test_bcsskew_rail_closed_form);
    RUN_TEST(test_bcsskew_rates_and_jacobian);
    RUN_TEST(test_bcsskew_errors);
    RUN_TEST(test_bcsskew_contact_mass);
}
