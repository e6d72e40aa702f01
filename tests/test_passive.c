/*
 * Contacts at zero and friction at its switches: after the modes are decided
 * from the state (at the start and after every event), every root function
 * must wait strictly on its own side, so that the integrator can see the
 * crossing that changes the mode (docs/theory.md 5.1, 3.5). A root that
 * starts past its crossing is never reported: a contact that never closes
 * again (bodies passing through each other), friction that never sticks and
 * pushes the sliding.
 */
#include <math.h>
#include <netcdf.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "engine/events/events.h"
#include "harness.h"
#include "model/friction.h"
#include "model/model.h"
#include "model/power.h"
#include "testutil.h"
#include "engine/assembly/assembly.h"

/* A row of five touching balls at x = i 2R (not exactly representable: the
 * pairs overlap or part by rounding), the first one moving; Hertz contacts. */
static const char *cradle_deck(void)
{
    static char buf[8192];
    int n = snprintf(buf, sizeof buf, "/BEGIN\ncradle\n      2022         0\n"
                                      "                  kg                   m                   s\n"
                                      "                  kg                   m                   s\n/NODE\n");
    for (int i = 0; i < 5; i++) n += snprintf(buf + n, sizeof buf - (size_t)n, "%10d%20.17g%20d%20d\n", i + 1, 0.02 * i, 0, 0);
    for (int i = 0; i < 5; i++)
        n += snprintf(buf + n, sizeof buf - (size_t)n,
                      "/RBODY/%d\nball\n%10d%10s%10s%10s%20s%10d\n%20s%20s%20s\n%20d%20d%20d\n/SURF/ELLIPS/%d\nball\n"
                      "%10d%10d%10d\n%20.17g%20d%20d\n%20s%20s%20s\n/GRNOD/NODE/%d\nball\n%10d\n",
                      i + 1, i + 1, "", "", "", "0.0327", i + 1, "1.308e-6", "1.308e-6", "1.308e-6", 0, 0, 0, i + 1, 0,
                      2, i + 1, 0.02 * i, 0, 0, "0.01", "0.01", "0.01", i + 1, i + 1);
    n += snprintf(buf + n, sizeof buf - (size_t)n, "/INIVEL/TRA/1\nv\n%20s%20s%20s%10d%10d\n", "1.0", "0", "0", 1, 0);
    for (int i = 0; i < 4; i++)
        n += snprintf(buf + n, sizeof buf - (size_t)n,
                      "/INTER/POWER/%d\nHertz\n%10d%10d%10d%10d%10d%10d\n%20s%20s%20s\n\n\n", i + 1, i + 1, i + 2, 0, 0, 0,
                      0, "1e10", "1.5", "0");
    snprintf(buf + n, sizeof buf - (size_t)n, "/RUN\n%20s%20s\n/END\n", "0.002", "1e-5");
    return buf;
}

/* A sphere resting on an incline (touching, at rest) with TYPE6 friction and
 * damping, a wall below it; a box on a floor, touching, sliding with
 * friction. */
static const char *incline_deck =
    "/BEGIN\nball on a ramp\n      2022         0\n"
    "                  kg                   m                   s\n"
    "                  kg                   m                   s\n"
    "/FUNCT/1\nlinear\n                   0                   0\n                   1             1000000\n"
    "/NODE\n         1-0.26480677906948907                   0 0.14959067403699605\n"
    "/RBODY/1\nball\n         1                                                 1         1\n"
    "               0.001               0.001               0.001\n"
    "                   0                   0                   0\n"
    "/SURF/ELLIPS/1\nball\n         0         2         1\n"
    "-0.26480677906948907                   0 0.14959067403699605\n"
    "                0.05                0.05                0.05\n"
    "/SURF/PLANE/2\nincline\n                   0                   0                   0\n"
    " 0.34202014332566871                   0 0.93969262078590843\n"
    "/SURF/PLANE/3\nwall\n                 0.2                   0                   0\n"
    "                  -1                   0                   0\n"
    "/GRNOD/NODE/1\nball\n         1\n"
    "/GRAV/1\ng\n         0         Z         0         0         1                             1               -9.81\n"
    "/INTER/TYPE6/1\nball on ramp\n         1         2\n"
    "                                   0.3\n\n         1         0\n\n         600\n"
    "/INTER/TYPE6/2\nball on wall\n         1         3\n"
    "                                   0.3\n\n         1         0\n\n         600\n"
    "/RUN\n                   2               0.001\n/END\n";

static const char *box_deck =
    "/BEGIN\nbox on a floor\n      2022         0\n"
    "                  kg                   m                   s\n"
    "                  kg                   m                   s\n"
    "/FUNCT/1\nlinear\n                   0                   0\n                   1             1000000\n"
    "/NODE\n         1                   0                   0                0.05\n"
    "/RBODY/1\nbox\n         1                                                 1         1\n"
    "  0.0016666666666667  0.0016666666666667  0.0016666666666667\n"
    "                   0                   0                   0\n"
    "/SURF/BOX/1\nbox\n         1\n                   0                   0                0.05\n"
    "                0.05                0.05                0.05\n"
    "/SURF/PLANE/2\nfloor\n                   0                   0                   0\n"
    "                   0                   0                   1\n"
    "/GRNOD/NODE/1\nbox\n         1\n"
    "/GRAV/1\ng\n         0         Z         0         0         1                             1               -9.81\n"
    "/INIVEL/TRA/1\nv\n                   1                 0.3                   0         1         0\n"
    "/INTER/TYPE6/1\nbox on floor\n         1         2\n"
    "                                   0.3\n\n         1         0\n\n         600\n"
    "/RUN\n                 0.5               0.001\n/END\n";

static uint64_t rng = 0x9e3779b97f4a7c15ULL;
static double urand(void) /* [0, 1) */
{
    rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(rng >> 11) / 9007199254740992.0;
}

/* Every root of every active interface on its waiting side, in the modes
 * rc_modes_touch left (returns the number of roots that are not; each
 * printed). */
static int roots_waiting(const rc_model *m, const rc_data *d, double t, const double *y, double *g, const char *what)
{
    rc_assemble_roots(m, d, t, y, g);
    int bad = 0;
    for (int i = 0; i < m->ninter; i++) {
        const int md = d->inter_mode[i];
        if (md == RC_MODE_INACTIVE) continue;
        const double *gi = g + RC_ROOTS_PER_INTER * i;
        const char *why = NULL;
        if (!d->inter_track[i] && md == RC_MODE_OPEN && !(gi[RC_ROOT_ZONE] < 0)) why = "open, zone root not < 0";
        if (md != RC_MODE_OPEN && !(gi[RC_ROOT_ZONE] > 0)) why = "in the zone, zone root not > 0";
        if (md == RC_MODE_CLOSED && !d->inter_settled[i] && !(gi[RC_ROOT_FORCE] > 0)) why = "closed, force root not > 0";
        if (md == RC_MODE_RELEASED && !(gi[RC_ROOT_FORCE] < 0)) why = "released, force root not < 0";
        /* a slipping contact may slide along its force at the velocities'
         * rounding: up to RC_SLIP_BAND of its speed scale (events.c) */
        const rc_fric *fr = &m->inter_fr[i];
        const double vs = m->inter_vscale[i], vb = d->inter_slip[i] && isfinite(vs) ? RC_SLIP_BAND * vs : 0.0;
        if (md == RC_MODE_CLOSED && fr->kind != RC_FK_NONE && fr->form == RC_FF_INCREMENTAL && !fr->exact &&
            m->inter_npt[i] == 0 && !(gi[RC_ROOT_SLIP] <= vb))
            why = d->inter_slip[i] ? "slipping along its force (v_t . e > 0)" : "sticking beyond its limit";
        /* TYPE6 hysteresis: a curve's rate root (LOAD waits for the law's
         * rate to fall below zero, UNLOAD to rise above), the Stiff line's
         * bounds (both > 0) */
        if (md != RC_MODE_OPEN && m->inter_law[i] == RC_LAW_TYPE6 && m->inter_iform[i] != 0) {
            const int br = d->inter_branch[i];
            if (br == RC_BR_LOAD && !(gi[RC_ROOT_HYST_A] > 0)) why = "on the load curve, its rate root not > 0";
            if (br == RC_BR_UNLOAD && !(gi[RC_ROOT_HYST_A] < 0)) why = "on the unload curve, its rate root not < 0";
            if (br == RC_BR_ELASTIC && !(gi[RC_ROOT_HYST_A] > 0 && gi[RC_ROOT_HYST_B] > 0))
                why = "on the Stiff line, a bound's root not > 0";
        }
        if (why) {
            if (bad < 10) printf("    %s: %s %s (zone %.3g, force %.3g, slip %.3g)\n", what, m->inter_name[i], why,
                                 gi[RC_ROOT_ZONE], gi[RC_ROOT_FORCE], gi[RC_ROOT_SLIP]);
            if (bad < 10 && m->inter_iform[i] != 0)
                printf("      branch %d, hysteresis roots %.3g %.3g\n", d->inter_branch[i], gi[RC_ROOT_HYST_A],
                       gi[RC_ROOT_HYST_B]);
            bad++;
        }
    }
    return bad;
}

/* Random states near the deck's start (positions moved by a few ulps to a
 * few 1e-9 of their size, velocities of any size and sign; with sink > 0,
 * half of them with the free bodies lowered along z by sink times 1e-3 to
 * 1 [m]), random modes (and for a TYPE6 law with hysteresis random
 * branches, F_h on its curve or between them); after rc_modes_touch every
 * root waits on its side. */
static void roots_wait_on_their_side(const char *deck, const char *name, int trials, double sink)
{
    rc_model *m = TU_COMPILE_OK(deck, name);
    if (!m) return;
    rc_data *d = rc_data_new(m);
    double *y0 = calloc((size_t)m->ny, sizeof(double)), *y = calloc((size_t)m->ny, sizeof(double));
    double *f = calloc((size_t)m->ny, sizeof(double)), *g = calloc((size_t)rc_root_count(m) + 1, sizeof(double));
    rc_initial_state(m, y0);
    int bad = 0, events = 0;
    for (int k = 0; k < trials; k++) {
        memcpy(y, y0, (size_t)m->ny * sizeof(double));
        for (int b = 0; b < m->nbody; b++) {
            if (m->body_yadr[b] < 0) continue;
            double *s = y + m->body_yadr[b];
            const double scale = pow(10.0, -16.0 + 8.0 * urand()); /* relative position change */
            for (int q = 0; q < 3; q++) s[q] += (urand() - 0.5) * scale * (fabs(s[q]) + 0.01);
            const double vs = urand() < 0.3 ? 0.0 : pow(10.0, -12.0 + 12.0 * urand());
            for (int q = 7; q < 13; q++) s[q] += (urand() - 0.5) * vs;
        }
        const double down = sink > 0 && urand() < 0.5 ? sink * pow(10.0, -3.0 * urand()) : 0.0;
        for (int b = 0; b < m->nbody; b++)
            if (m->body_yadr[b] >= 0) y[m->body_yadr[b] + 2] -= down;
        for (int i = 0; i < m->ninter; i++) {
            const int r = (int)(4 * urand());
            d->inter_mode[i] = r == 0 ? RC_MODE_OPEN : r == 3 ? RC_MODE_RELEASED : RC_MODE_CLOSED;
            d->inter_branch[i] = RC_BR_LOAD;
            d->inter_track[i] = 0;
            d->inter_slip[i] = urand() < 0.5;
            d->inter_settled[i] = 0;
            d->inter_band[2 * i] = d->inter_band[2 * i + 1] = 0.0;
            /* a tangential state of any direction, up to a few times the weight */
            const rc_fric *fr = &m->inter_fr[i];
            if (fr->tidx >= 0)
                for (int q = 0; q < 3; q++) y[m->inter_eadr[i] + fr->tidx + q] = (urand() - 0.5) * 20.0;
            if (m->inter_law[i] == RC_LAW_TYPE6 && m->inter_iform[i] != 0 && d->inter_mode[i] != RC_MODE_OPEN) {
                /* P_e at P or a little below; F_h on its branch's curve, on
                 * the Stiff line between the curves */
                rc_inter_report q;
                if (m->inter_peidx[i] >= 0) {
                    y[m->inter_eadr[i] + m->inter_peidx[i]] = 0.0;
                    rc_inter_report_eval_d(m, d, i, 0.0, y, &q);
                    y[m->inter_eadr[i] + m->inter_peidx[i]] = fmax(0.0, q.p * (1.0 - 0.1 * urand()));
                }
                const int br = (int)(3 * urand());
                d->inter_branch[i] = br == 0 ? RC_BR_LOAD : br == 1 ? RC_BR_UNLOAD : RC_BR_ELASTIC;
                rc_inter_report_eval_d(m, d, i, 0.0, y, &q);
                y[m->inter_eadr[i] + m->inter_hidx[i]] =
                    br == 0 ? q.fl : br == 1 ? q.fu : q.fu + (q.fl - q.fu) * urand();
            }
        }
        rc_event ev[64];
        int restart = 0;
        for (int round = 0; round < 2; round++) { /* as the driver: twice */
            rc_assemble_rhs(m, d, 0.0, y, f);
            events += rc_modes_touch(m, d, 0.0, y, f, ev, 64, &restart);
        }
        bad += roots_waiting(m, d, 0.0, y, g, name);
    }
    printf("    %s: %d random states near the start, %d transitions decided, %d roots past their crossing\n", name,
           trials, events, bad);
    ENSURE(bad == 0);
    free(y0);
    free(y);
    free(f);
    free(g);
    rc_data_free(d);
    rc_model_free(m);
}

static void test_touching_roots_wait_on_their_side(void)
{
    roots_wait_on_their_side(cradle_deck(), "cradle.rad", 400, 0.0);
    roots_wait_on_their_side(incline_deck, "incline.rad", 400, 0.0);
    roots_wait_on_their_side(box_deck, "box.rad", 200, 0.0);
}

/* End-to-end: the cradle passes its momentum down the row (no ball passes
 * through another); the box sliding from a touching start stays on the
 * floor; the ball on the ramp gains no energy from friction. */
static double run_end(const char *deck, const char *name, double *yend)
{
    rc_error e;
    rc_model *m = tu_compile_text(deck, name, &e);
    ENSURE(m != NULL);
    if (!m) return NAN;
    rc_run_options o;
    memset(&o, 0, sizeof o);
    o.y_end = yend;
    rc_stats st;
    const rc_status s = rc_run(m, &o, &st, &e);
    ENSURE(s == RC_OK);
    if (s) printf("    %s\n", e.msg);
    const int ny = m->ny;
    rc_model_free(m);
    return ny;
}

static void test_cradle_off_grid_passes_momentum(void)
{
    double y[256];
    memset(y, 0, sizeof y);
    if (!(run_end(cradle_deck(), "cradle.rad", y) > 0)) return;
    /* ball i's state at 13 i: x at 0, v_x at 7 */
    double vmax = 0, dmin = INFINITY;
    for (int i = 0; i < 5; i++) vmax = fmax(vmax, y[13 * i + 7]);
    for (int i = 0; i + 1 < 5; i++) dmin = fmin(dmin, y[13 * (i + 1)] - y[13 * i]);
    printf("    cradle at x = i 2R: ball 5 leaves at %.4f m/s (1 m/s struck), closest centres %.5f m apart (2R = 0.02)\n",
           y[13 * 4 + 7], dmin);
    ENSURE(y[13 * 4 + 7] > 0.9 && y[13 * 4 + 7] <= 1.0 + 1e-9);
    ENSURE(dmin > 0.019);
}

static void test_box_sliding_from_touch_stays_on_the_floor(void)
{
    double y[64];
    memset(y, 0, sizeof y);
    if (!(run_end(box_deck, "box.rad", y) > 0)) return;
    printf("    box sliding from a touching start: centre at z = %.9f m after 0.5 s (half size 0.05 m), speed %.2e m/s\n",
           y[2], hypot(y[7], y[8]));
    ENSURE(y[2] > 0.05 - 1e-4 && y[2] < 0.05 + 1e-6);
    ENSURE(hypot(y[7], y[8]) < 1e-6); /* stopped by friction (mu g t = 1.47 m/s > 1.04) */
}

static void test_ball_on_ramp_friction_never_pushes(void)
{
    double y[64];
    memset(y, 0, sizeof y);
    if (!(run_end(incline_deck, "incline.rad", y) > 0)) return;
    /* kinetic energy at the end (the ball settles against the wall within
     * 2 s) and the spin: rolling down 0.3 m of a 20 degree ramp (1.47 J),
     * then stopped by the wall; before, friction spun it up to 113 rad/s */
    const double ke = 0.5 * (y[7] * y[7] + y[8] * y[8] + y[9] * y[9]);
    printf("    ball on the ramp into the wall: final speed %.2e m/s, spin %.2e rad/s, kinetic energy %.2e J\n",
           sqrt(2 * ke), hypot(hypot(y[10], y[11]), y[12]), ke);
    ENSURE(ke < 1e-6);
    ENSURE(hypot(hypot(y[10], y[11]), y[12]) < 1.0);
}


/* ---- the energy ledger of contacts with several points ---------------- */
/* A box (/SURF/BOX: its corners against the floor, 8 contact points) of
 * mass 15 kg, half sizes (0.1, 0.06, 0.04) m, at height z0 with the
 * orientation given by the quaternion (q0..q3), velocity v and spin w; the
 * floor's TYPE6 linear law k = 1e6 N/m with Visc and Fric (fric 0: none;
 * filt: a /FRICTION Coulomb with its filter instead). */
static const char *box_ledger_deck(double z0, const double q[4], const double v[3], const double w[3], double visc,
                                   double fric, int filt)
{
    static char buf[8192];
    int n = snprintf(buf, sizeof buf,
                     "/BEGIN\nbox ledger\n      2022         0\n"
                     "                  kg                   m                   s\n"
                     "                  kg                   m                   s\n"
                     "/FUNCT/1\nlinear\n0,0\n1,1000000\n"
                     "/NODE\n1,0,0,%.17g\n"
                     "/RBODY/1\nbox\n1,,,,15,1\n0.026,0.058,0.063\n0,0,0\n"
                     "/SURF/BOX/1\nbox\n1\n0,0,%.17g\n0.1,0.06,0.04\n"
                     "/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n"
                     "/GRNOD/NODE/1\nbox\n1\n"
                     "/GRAV/1\ng\n0,Z,0,0,1,,1,-9.81\n"
                     "/INIVEL/TRA/1\nv\n%.17g,%.17g,%.17g,1,0\n"
                     "/INIVEL/ROT/2\nw\n%.17g,%.17g,%.17g,1,0\n",
                     z0, z0, v[0], v[1], v[2], w[0], w[1], w[2]);
    (void)q;
    if (filt)
        n += snprintf(buf + n, sizeof buf - (size_t)n,
                      "/PART/1\nbox\n0,0,0,0\n1\n/PART/2\nfloor\n0,0,0,0\n0,2\n"
                      "/FRICTION/1\nfiltered Coulomb\n0,3,20,2\n,,,,\n,%.17g,\n", fric);
    n += snprintf(buf + n, sizeof buf - (size_t)n,
                  "/INTER/TYPE6/1\nbox on floor\n1,2\n,%.17g\n\n1,0\n\n%.17g\n"
                  "/RUN\n0.6,0.001\n/END\n",
                  filt ? 0.0 : fric, visc);
    return buf;
}

/* The largest decrease of a ledger variable between records [J] (0 when it
 * never decreases), and its last value. */
static double ledger_drop(int ncid, const char *var, size_t nt, double *last)
{
    int id;
    *last = NAN;
    if (nc_inq_varid(ncid, var, &id) != NC_NOERR) return NAN;
    double *x = malloc(nt * sizeof(double));
    if (!x) return NAN;
    double drop = 0.0;
    if (nc_get_var_double(ncid, id, x) == NC_NOERR) {
        for (size_t k = 1; k < nt; k++) drop = fmax(drop, x[k - 1] - x[k]);
        *last = x[nt - 1];
    } else {
        drop = NAN;
    }
    free(x);
    return drop;
}

/* Runs the deck to a results file and checks that no dissipation channel
 * decreases by more than rel E_s and that the mechanical energy (kinetic,
 * potential, stored) never exceeds its start by more than that, E_s the
 * run's energy scale (the largest kinetic energy plus the range of the
 * potential energy): the integration's own error is below 1e-7 E_s at the
 * default tolerances, the sharing rule of before created 1e-2 E_s. */
/* Compiles the deck (written as `name`), runs it to the results file
 * <tmp>/name.nc (its path into out[512]) and checks it ran; 0 when it did.
 * m_check (may be NULL) is called on the compiled model first; the run's
 * statistics into *stats (NULL: not wanted). */
static int run_to_file(const char *deck, const char *name, char *out, void (*m_check)(const rc_model *),
                       rc_stats *stats)
{
    rc_error e;
    rc_model *m = TU_COMPILE_OK(deck, name);
    if (!m) return -1;
    if (m_check) m_check(m);
    snprintf(out, 512, "%s.nc", tu_tmp_write(name, ""));
    rc_run_options o;
    memset(&o, 0, sizeof o);
    o.output_path = out;
    const rc_status st = rc_run(m, &o, stats, &e);
    ENSURE(st == RC_OK);
    rc_model_free(m);
    if (st) printf("    %s\n", e.msg);
    return st ? -1 : 0;
}

static void ledger_monotone(const char *deck, const char *name, double rel)
{
    char out[512];
    if (run_to_file(deck, name, out, NULL, NULL)) return;
    int ncid, tid;
    size_t nt = 0;
    ENSURE(nc_open(out, NC_NOWRITE, &ncid) == NC_NOERR);
    ENSURE(nc_inq_dimid(ncid, "time", &tid) == NC_NOERR && nc_inq_dimlen(ncid, tid, &nt) == NC_NOERR);
    /* the energy scale, then the mechanical energy against its start */
    double *ek = malloc(nt * sizeof(double)), *ep = malloc(nt * sizeof(double)), *es = malloc(nt * sizeof(double));
    int ik, ip, is;
    double rise = NAN, escale = NAN;
    if (ek && ep && es && nc_inq_varid(ncid, "energy_kinetic", &ik) == NC_NOERR &&
        nc_inq_varid(ncid, "energy_potential", &ip) == NC_NOERR && nc_inq_varid(ncid, "energy_contact_stored", &is) == NC_NOERR &&
        nc_get_var_double(ncid, ik, ek) == NC_NOERR && nc_get_var_double(ncid, ip, ep) == NC_NOERR &&
        nc_get_var_double(ncid, is, es) == NC_NOERR) {
        double kmax = 0.0, pmin = ep[0], pmax = ep[0];
        rise = 0.0;
        for (size_t k = 0; k < nt; k++) {
            rise = fmax(rise, ek[k] + ep[k] + es[k] - (ek[0] + ep[0] + es[0]));
            kmax = fmax(kmax, ek[k]);
            pmin = fmin(pmin, ep[k]);
            pmax = fmax(pmax, ep[k]);
        }
        escale = kmax + (pmax - pmin);
    }
    const double tol = rel * escale;
    ENSURE(rise <= tol);
    const char *chan[] = {"energy_damping", "energy_hysteresis", "energy_friction"};
    double worst = 0.0, last[3];
    for (int c = 0; c < 3; c++) {
        const double d = ledger_drop(ncid, chan[c], nt, &last[c]);
        ENSURE(d <= tol);
        worst = fmax(worst, d);
    }
    printf("    %s: %zu records, E_s = %.3g J; largest drop of a dissipation channel %.2e J, mechanical energy above "
           "its start by %.2e J (< %.0e E_s); dissipated: damping %.4g, hysteresis %.4g, friction %.4g J\n",
           name, nt, escale, worst, rise, rel, last[0], last[1], last[2]);
    free(ek);
    free(ep);
    free(es);
    nc_close(ncid);
}

static void test_multi_point_contacts_are_passive(void)
{
    const double q0[4] = {1, 0, 0, 0}, none[3] = {0, 0, 0};
    /* dropped tilted on a corner (a spin about x and y), damped: it rocks
     * onto its face (before: energy_hysteresis down to -0.016 J) */
    const double wt[3] = {3.1, -2.3, 0.7}, vs[3] = {1.0, 0.3, 0.0}, vd[3] = {0.2, 0.0, -1.0};
    ledger_monotone(box_ledger_deck(0.1, q0, vd, wt, 2100.0, 0.0, 0), "box_corner.rad", 1e-6);
    /* launched sliding at its static penetration with friction: it tilts
     * under the friction moment (before: 2.3 mJ created) */
    ledger_monotone(box_ledger_deck(0.04 - 14.7e-5, q0, vs, none, 2100.0, 0.3, 0), "box_slide.rad", 1e-6);
    /* the same with a filtered /FRICTION */
    ledger_monotone(box_ledger_deck(0.04 - 14.7e-5, q0, vs, none, 2100.0, 0.3, 1), "box_filter.rad", 1e-6);
    /* undamped and frictionless, dropped spinning: no channel may run
     * backwards (the law at P gave the rocking energy) */
    ledger_monotone(box_ledger_deck(0.1, q0, vd, wt, 0.0, 0.0, 0), "box_elastic.rad", 1e-6);
}

/* A /FRICTION law that reads the contact pressure on a pair without a
 * sphere (a box: no area ricochet can take for its patch) needs the card's
 * Area: an input error naming it; with Area the deck compiles. Before, a
 * segment surface's pressure was F_n / 0 and a box took the area of a
 * sphere of its half size. */
static void test_friction_pressure_area_needed(void)
{
    static const char *head = "/BEGIN\npressure area\n      2022         0\n"
                              "                  kg                   m                   s\n"
                              "                  kg                   m                   s\n"
                              "/FUNCT/1\nlinear\n0,0\n1,1000000\n"
                              "/NODE\n1,0,0,0.04\n"
                              "/RBODY/1\nbox\n1,,,,15,1\n0.026,0.058,0.063\n0,0,0\n"
                              "/SURF/BOX/1\nbox\n1\n0,0,0.04\n0.1,0.06,0.04\n"
                              "/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n"
                              "/GRNOD/NODE/1\nbox\n1\n"
                              "/PART/1\nbox\n0,0,0,0\n1\n/PART/2\nfloor\n0,0,0,0\n0,2\n";
    static const char *tail = "/INTER/TYPE6/1\nbox on floor\n1,2\n\n\n1,0\n\n600\n/RUN\n0.1,0.001\n/END\n";
    char deck[4096];
    /* generalised viscous law with a pressure coefficient C1, Area blank */
    snprintf(deck, sizeof deck, "%s/FRICTION/1\npressure law\n1,0,,2\n1e-6,0.01,,,\n,0.3,\n%s", head, tail);
    TU_EXPECT_TEXT_ERROR(deck, "area.rad", "card /FRICTION/1", "field Area", "/INTER/TYPE6/1");
    /* the same with Area 0.012 m^2 (the box's face) */
    snprintf(deck, sizeof deck, "%s/FRICTION/1\npressure law\n1,0,,2,,0.012\n1e-6,0.01,,,\n,0.3,\n%s", head, tail);
    rc_error e;
    rc_model *m = tu_compile_text(deck, "area.rad", &e);
    ENSURE(m != NULL);
    if (m) ENSURE_NEAR(m->inter_fr[0].area, 0.012, 1e-15, 0);
    else printf("    %s\n", e.msg);
    rc_model_free(m);
    /* a law without the pressure (C1 = C3 = C4 = 0) needs no area */
    snprintf(deck, sizeof deck, "%s/FRICTION/1\nspeed law\n1,0,,2\n0,0.01,,,\n,0.3,\n%s", head, tail);
    m = tu_compile_text(deck, "area.rad", &e);
    ENSURE(m != NULL);
    rc_model_free(m);
}


/* Class 4: tolerances never below what the coordinates resolve. Two balls
 * resting in a column on a floor (linear TYPE6 contacts, rtol 1e-8), at the
 * origin and moved 1 km away: a penetration there is rounded at about
 * 2e-13 m, above rtol p_s, and the accounting states integrate the forces
 * over that rounding. With the floors the far copy takes about the steps
 * of the near one (18 518 against 6 without them, for the pair without
 * gravity). */
static const char *stack_deck(double X, double Z, int far_node)
{
    static char buf[6144];
    const double r = 0.0026, m = 0.0015, g = 9.81, k1 = 2.2e4, k2 = 2.3e5;
    const double p1 = 2 * m * g / k1, p2 = m * g / k2;
    const double z1 = Z + r - p1, z2 = z1 + 2 * r - p2;
    snprintf(buf, sizeof buf,
             "/BEGIN\nstack\n      2022         0\n"
             "                  kg                   m                   s\n"
             "                  kg                   m                   s\n"
             "/FUNCT/1\nfloor\n                   0                   0\n                   1%20.13g\n"
             "/FUNCT/2\nballs\n                   0                   0\n                   1%20.13g\n"
             "/NODE\n         1%20.13g%20d%20.13g\n         2%20.13g%20d%20.13g\n%s"
             "/RBODY/1\nball\n         1%30s%20.13g         1\n"
             "%20.13g%20.13g%20.13g\n                   0                   0                   0\n"
             "/RBODY/2\nball\n         2%30s%20.13g         2\n"
             "%20.13g%20.13g%20.13g\n                   0                   0                   0\n"
             "/SURF/ELLIPS/1\nball\n         0         2         1\n%20.13g%20d%20.13g\n%20.13g%20.13g%20.13g\n"
             "/SURF/ELLIPS/2\nball\n         0         2         2\n%20.13g%20d%20.13g\n%20.13g%20.13g%20.13g\n"
             "/SURF/PLANE/3\nfloor\n%20.13g%20d%20.13g\n%20.13g%20d%20.13g\n"
             "/GRNOD/NODE/1\nball\n         1\n/GRNOD/NODE/2\nball\n         2\n/GRNOD/NODE/3\nboth\n         1         2\n"
             "/GRAV/1\ng\n         0         Z         0         0         3                             1%20.13g\n"
             "/INTER/TYPE6/1\nball on floor\n         1         3\n\n\n         1         0\n\n\n"
             "/INTER/TYPE6/2\nball on ball\n         1         2\n\n\n         2         0\n\n\n"
             "/RUN\n                0.06              0.0003\n/END\n",
             k1, k2, X, 0, z1, X, 0, z2, far_node ? "        99                   0                   0                   0\n" : "", "", m, 0.4 * m * r * r, 0.4 * m * r * r, 0.4 * m * r * r, "", m,
             0.4 * m * r * r, 0.4 * m * r * r, 0.4 * m * r * r, X, 0, z1, r, r, r, X, 0, z2, r, r, r, X, 0, Z, X, 0, Z + 1, -g);
    return buf;
}

/* The run's steps; *patol the upper ball's position tolerance [m],
 * *origin the model's origin x [m], *floor the results file's
 * atol_position_floor [m] (-1: unreadable) and note the run's
 * tolerance_note. */
static long stack_steps(double X, double Z, int far_node, double *patol, double *origin, double *floor,
                        char *note, size_t nnote)
{
    rc_error e;
    rc_model *m = TU_COMPILE_OK(stack_deck(X, Z, far_node), "stack.rad");
    if (!m) return -1;
    ENSURE(rc_model_set_rtol(m, 1e-8, &e) == RC_OK);
    *patol = m->atol[m->body_yadr[1]];
    *origin = m->origin[0];
    char path[256];
    snprintf(path, sizeof path, "/tmp/rc_test_passive_%ld_stack.nc", (long)getpid());
    rc_run_options opt = {.output_path = path};
    rc_stats st;
    const rc_status s = rc_run(m, &opt, &st, &e);
    ENSURE(s == RC_OK);
    if (s) printf("    %s\n", e.msg);
    snprintf(note, nnote, "%s", st.tolerance_note);
    int nc;
    *floor = -1;
    if (nc_open(path, NC_NOWRITE, &nc) == NC_NOERR) {
        if (nc_get_att_double(nc, NC_GLOBAL, "atol_position_floor", floor) != NC_NOERR) *floor = -1;
        nc_close(nc);
    }
    unlink(path);
    rc_model_free(m);
    return st.steps;
}

static void test_tolerances_above_the_coordinates_rounding(void)
{
    double a0, a1, a2, o0, o1, o2, f0, f1, f2;
    char note0[480], note1[480], note2[480];
    const long n0 = stack_steps(0, 0, 0, &a0, &o0, &f0, note0, sizeof note0);
    const long n1 = stack_steps(800, 600, 0, &a1, &o1, &f1, note1, sizeof note1);
    const long n2 = stack_steps(800, 600, 1, &a2, &o2, &f2, note2, sizeof note2);
    printf("    resting column: %ld steps at the origin (position atol %.3g m); 1 km away: %ld steps (%.3g m, the "
           "model's origin moved to x = %g m); 1 km away with a node at the deck's origin (no move: %g m): %ld "
           "steps (%.3g m)\n", n0, a0, n1, a1, o1, o2, n2, a2);
    /* a scene far from the deck's origin is computed about its centre,
     * with the tolerances of the same scene at the origin (the floors
     * follow the model's coordinates, not the deck's): no Newton iteration
     * chasing the rounding of 1 km (18 518 steps before the move). This
     * deck writes 13 digits, so the column 1 km away starts about 1e-10 m
     * off its equilibrium (0.2 % of the upper ball's penetration, far above
     * rtol 1e-8 of it), and the run follows that oscillation at the asked
     * tolerance: some thousand steps, not tens of thousands */
    ENSURE(o0 == 0 && o1 == 800 && a1 == a0);
    ENSURE(n1 > 0 && n1 <= 12000);
    /* a scene that spans from the origin to 1 km keeps the deck's
     * coordinates: its tolerances are floored at their rounding */
    ENSURE(o2 == 0 && a2 >= 64 * 2.220446049250313e-16 * 800 * 0.999);
    ENSURE(n2 > 0 && n2 <= 3 * n0 + 10);
    ENSURE(a0 < 1e-13); /* the floor changes nothing at the origin */
    /* the run says where the floor applies (the summary, the statistics,
     * the results file) and stays silent where it does not */
    printf("    floored: atol_position_floor %.3g m; note: %s\n", f2, note2);
    ENSURE(f0 == 0 && note0[0] == '\0' && f1 == 0 && note1[0] == '\0');
    ENSURE(f2 == a2 && strstr(note2, "raised to") != NULL && strstr(note2, "cannot be as accurate as rtol asks"));
}

/* A ball thrown at 1 m/s on a floor (no gravity) whose TYPE6 Iform 1 load
 * curve is linear (k_L = 1e6 N/m) and whose Stiff is k_S: the law unloads
 * along the Stiff line and returns F^2 / (2 k_S) of the k_L P^2 / 2 it
 * stored, restitution sqrt(k_L / k_S) exactly, and energy_hysteresis the
 * rest (the run's own physics checks: it never decreases). A Stiff below
 * the load curve's slope is an input error (the law would have to follow
 * the load curve back: docs/case-format.md). */
static const char *iform1_deck(double kstiff)
{
    static char buf[4096];
    snprintf(buf, sizeof buf,
             "/BEGIN\nIform 1 drop\n      2022         0\n"
             "                  kg                   m                   s\n"
             "                  kg                   m                   s\n"
             "/FUNCT/1\nlinear\n                   0                   0\n                   1             1000000\n"
             "/NODE\n         1                   0                   0                 0.1\n"
             "/RBODY/1\nball\n         1                                                 1         1\n"
             "               0.001               0.001               0.001\n"
             "                   0                   0                   0\n"
             "/SURF/ELLIPS/1\nball\n         0         2         1\n"
             "                   0                   0                 0.1\n"
             "                0.05                0.05                0.05\n"
             "/SURF/PLANE/2\nfloor\n                   0                   0                   0\n"
             "                   0                   0                   1\n"
             "/GRNOD/NODE/1\nball\n         1\n"
             "/INIVEL/TRA/1\nv\n                   0                   0                  -1         1         0\n"
             "/INTER/TYPE6/1\nball on floor\n         1         2\n\n"
             "                                                 0         0\n"
             "         1         1                 1.0                 1.0\n"
             "          %20.10g                 1.0\n"
             "                             0         0\n"
             "/RUN\n                0.15              0.0001\n/END\n",
             kstiff);
    return buf;
}

static void test_iform1_unloads_along_the_law(void)
{
    const double ks[3] = {3e6, 1e7, 1e8};
    for (int c = 0; c < 3; c++) {
        rc_error e;
        rc_model *m = TU_COMPILE_OK(iform1_deck(ks[c]), "iform1.rad");
        if (!m) continue;
        rc_stats st;
        rc_run_options o;
        memset(&o, 0, sizeof o);
        double *y = calloc((size_t)m->ny, sizeof(double));
        o.y_end = y;
        const rc_status s = rc_run(m, &o, &st, &e);
        ENSURE(s == RC_OK);
        if (s) printf("    %s\n", e.msg);
        const double expect = sqrt(1e6 / ks[c]), got = st.impacts > 0 ? st.impact[0].restitution : NAN;
        /* the law's dissipation D_h (an own state): the impact's kinetic
         * energy 1/2 m v0^2 (v0 = 1 m/s) less what the Stiff line gives
         * back, a fraction k_L / k_S */
        const int dh = m->inter_dhidx[0];
        const double dexp = 0.5 * m->body_mass[0] * (1.0 - 1e6 / ks[c]);
        const double dgot = dh >= 0 ? y[m->inter_eadr[0] + dh] : NAN;
        printf("    Stiff %.3g N/m (load curve 1e6 N/m): restitution %.7f, sqrt(k_L / k_S) = %.7f; D_h %.9g J, "
               "1/2 m v0^2 (1 - k_L / k_S) = %.9g J; physics checks: %s\n",
               ks[c], got, expect, dgot, dexp, st.physics_note);
        ENSURE(st.impacts > 0 && fabs(got - expect) < 1e-4);
        ENSURE(fabs(dgot - dexp) < 1e-6 * dexp);
        ENSURE(st.violations == 0);
        free(y);
        rc_model_free(m);
    }
    TU_EXPECT_TEXT_ERROR(iform1_deck(3e5), "iform1.rad", "field Stiff", "steeper than the load curve");
}

/* Iform 2 reversals in a cradle (tests/data/cradle_iform2_reversal.rad, a
 * fuzzer scene): at a ball's deepest point the law leaves the load curve
 * for the Stiff line (F_h := F_L), where the root F_L - F_h starts at zero.
 * Its integration error crossed zero at the next step and put the law back
 * on the load curve while unloading: it followed the curve down and
 * energy_hysteresis fell by 1.4e-5 J at rtol 1e-10. The roots now wait the
 * accuracy of F_h and of the curve at P past the curve. */
static void test_iform2_reversals_stay_on_the_stiff_line(void)
{
    const double rts[3] = {1e-6, 1e-8, 1e-10};
    for (int c = 0; c < 3; c++) {
        rc_model *m = TU_LOAD_OK("tests/data/cradle_iform2_reversal.rad");
        if (!m) return;
        rc_error e;
        ENSURE(rc_model_set_rtol(m, rts[c], &e) == RC_OK);
        rc_stats st;
        const rc_status s = rc_run(m, NULL, &st, &e);
        printf("    rtol %g: %s, %ld steps, %ld events; physics checks: %s\n", rts[c], s ? e.msg : "ok", st.steps,
               st.events, st.physics_note);
        ENSURE(s == RC_OK && st.violations == 0);
        rc_model_free(m);
    }
}

/* A ball launched across an incline slides, then rolls
 * (tests/data/ball_rolls_onto_incline.rad, a fuzzer scene: incremental
 * Renard friction, K_t = Stiff = 2.5e7 N/m). Before: CV_ERR_FAILURE at
 * 0.2-0.7 ms at every rtol (the slip law's rate K_t |v_t| / L_r swung
 * 100 x with the normal force and a Jacobian a few steps old no longer
 * held: L_r now at least F_s, and a new Jacobian after an error-test
 * failure); then 200 stick/slip events within 1e-8 s once it rolled (the
 * sliding turned across the force: it slides on against the sliding).
 * Rolling, it accelerates at (5/7) g sin(theta) along the fall line. */
static void test_ball_rolls_onto_incline(void)
{
    const double n[3] = {-0.24894353970872113, 0.01221667945544781, 0.9684409464600179}, ends[2] = {0.16, 0.24};
    const double nn = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    double u[3], v[2][13];
    /* the fall line: gravity (0, 0, -9.81) less its normal part */
    const double gn = -9.81 * n[2] / nn;
    for (int k = 0; k < 3; k++) u[k] = (k == 2 ? -9.81 : 0.0) - gn * n[k] / nn;
    const double gt = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (int k = 0; k < 3; k++) u[k] /= gt;
    for (int c = 0; c < 2; c++) {
        rc_model *m = TU_LOAD_OK("tests/data/ball_rolls_onto_incline.rad");
        if (!m) return;
        rc_error e;
        rc_run_options o;
        memset(&o, 0, sizeof o);
        double y[64];
        o.y_end = y;
        o.t_end_override = ends[c];
        rc_stats st;
        const rc_status s = rc_run(m, &o, &st, &e);
        printf("    to %g s: %s, %ld steps, %ld events; physics checks: %s\n", ends[c], s ? e.msg : "ok", st.steps,
               st.events, st.physics_note);
        ENSURE(s == RC_OK && st.violations == 0);
        memcpy(v[c], y, sizeof v[c]);
        rc_model_free(m);
    }
    double a = 0.0;
    for (int k = 0; k < 3; k++) a += (v[1][7 + k] - v[0][7 + k]) * u[k];
    a /= ends[1] - ends[0];
    const double expect = 5.0 / 7.0 * gt;
    printf("    rolling: %.10f m/s^2 along the fall line, (5/7) g sin(theta) = %.10f\n", a, expect);
    /* its normal force rings on the Stiff line (no damping), and at the
     * low points the limit mu F_n dips to what rolling needs: 1.8e-5 */
    ENSURE(fabs(a - expect) < 1e-4 * expect);
}

/* A ball sliding at 0.11 m/s along a wall whose contact settled
 * (tests/data/ball_wall_fric_turn.rad, the fuzzer's 67000016 shrunk:
 * Iform 1, Stiff = K_t = 5.8e14 N/m; the normal force falls at 3e7 N/s
 * and the limit, 0.01 N, is 3.5 force tolerances of F_t). After each
 * fric_turn the state reloads towards the limit at K_t |v_t| / L_r =
 * 1.5e13 1/s; the integrator's steps grew out of the restart to h times
 * that rate of 5 at BDF order 3, a step carried the state through zero
 * along the sliding within its tolerance, and the slip root crossed again
 * 1e-12 s later: 200 fric_turn within 3e-10 s (Zeno, exit 3). The restart
 * after a turn now keeps the order at most 2 (A-stable) until the next
 * restart: the run ends. */
static void test_fric_turn_reload_stays_against_the_sliding(void)
{
    rc_model *m = TU_LOAD_OK("tests/data/ball_wall_fric_turn.rad");
    if (!m) return;
    rc_error e;
    rc_run_options o;
    memset(&o, 0, sizeof o);
    rc_stats st;
    const rc_status s = rc_run(m, &o, &st, &e);
    printf("    %s, %ld steps, %ld events, %ld restarts; physics checks: %s\n", s ? e.msg : "ok", st.steps, st.events,
           st.reinits, st.physics_note);
    ENSURE(s == RC_OK && st.violations == 0);
    rc_model_free(m);
}

/* A ball pressed by a ramp against a wall whose Stiff line is 8.9e16 N/m
 * (the fuzzer's 163000163): the force tolerance of its friction state
 * (the line times the coordinates' rounding) is 512 N, half the friction
 * limit. At an unloading the limit fell from 1e5 N to 1e3 N while the ball
 * slid at 0.016 m/s; the slipping state relaxed with it to 5e-4 N, below
 * its tolerance, its direction the integrator's rounding; the slip root
 * crossed, the stick it called slipped at once, and the state was turned
 * against the sliding at that size: rounding again, 200 turns within
 * 8e-8 s (Zeno, exit 3). A turned state has at least the force tolerance,
 * as every slipping state an event puts (the slip band): a handful of
 * turns, and the run ends. */
static void test_fric_turn_keeps_a_resolved_state(void)
{
    rc_model *m = TU_LOAD_OK("fuzz/physics/regressions/ramp_wall_slip_state_below_force_tolerance_turn_zeno.rad");
    if (!m) return;
    ENSURE(m->ninter == 2 && m->inter_fr[1].fband > 100.0); /* the premise: a tolerance of hundreds of N */
    static tu_evlog ev;
    rc_stats st;
    ENSURE(tu_run_evlog(m, &ev, &st) == RC_OK && st.violations == 0);
    int turns = 0;
    for (int k = 0; k < ev.n && k < TU_MAXEV; k++) turns += strcmp(ev.kind[k], "fric_turn") == 0;
    printf("    %ld steps, %ld events, %d fric_turn; F_t tolerance at the wall %.4g N; physics checks: %s\n", st.steps,
           st.events, turns, m->inter_fr[1].fband, st.physics_note);
    ENSURE(ev.n < TU_MAXEV && turns < 20);
    rc_model_free(m);
}

/* A box landing flat stays level. A 12 mm box dropped level onto a floor
 * (no friction), the scene 1 km away and rotated
 * (tests/data/box_floor_flat_landing_rotated.rad, the fuzzer's 165000126
 * shrunk): at rtol 1e-8 its first landing left it rocking at 3.6e-4 rad/s
 * where rtol 1e-10 and the scene at the origin give 1e-9. The rocking of a
 * level box on its four corners starts at the coordinates' rounding; it is
 * stiff and the normal damper, acting on the shared rate, leaves it
 * undamped, and BDF orders 4 and 5 (not A-stable near the imaginary axis)
 * amplified it by 1e6 within the landing. The restart at which a contact
 * of several points closes keeps the order at most 3 until the next
 * restart: the box leaves the landing rocking at 1e-9 rad/s. */
static void test_flat_landing_keeps_the_box_level(void)
{
    rc_model *m = TU_LOAD_OK("tests/data/box_floor_flat_landing_rotated.rad");
    if (!m) return;
    rc_error e;
    rc_session *ses = NULL;
    ENSURE(rc_session_open(m, NULL, &ses, &e) == RC_OK);
    if (!ses) {
        rc_model_free(m);
        return;
    }
    /* after the first landing (0.0305 to 0.0323 s), in flight */
    ENSURE(rc_run_until(ses, 0.035, &e) == RC_OK);
    const double *y = rc_session_state(ses);
    ENSURE(y != NULL);
    const double *w = y ? y + m->body_yadr[0] + 10 : NULL;
    const double wn = w ? sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) : NAN;
    printf("    after the first landing: |omega| = %.3g rad/s\n", wn);
    ENSURE(wn < 1e-6);
    rc_session_close(ses, NULL, &e); /* stopped before its end: RC_EINTERRUPT */
    rc_model_free(m);
}

/* A resting box rings down (tests/data/box_on_box_light_damper_rest.rad,
 * the fuzzer's 199000159 over 0.1 s): a 3.3 g box on a fixed box, TYPE6
 * Iform 1, its damper at 0.26 % of critical on the Stiff line's mode
 * (2.8e5 rad/s). BDF orders 3 to 5 amplify so lightly damped a mode at
 * the steps the error test allows once the vibration is at the level of
 * the tolerances: it rang at 4.5e-7 m/s to the end (148 463 steps, the
 * damper dissipating 5e-13 W supplied by the integrator's error). CVODE's
 * stability limit detection lowers the order and CVODE raises it again;
 * once such reductions recur the integrator restarts at order 2 at most
 * (A-stable) until the next restart, and the box rings down with its
 * damper and rests. */
static void test_resting_box_rings_down(void)
{
    rc_model *m = TU_LOAD_OK("tests/data/box_on_box_light_damper_rest.rad");
    if (!m) return;
    double *y = calloc((size_t)m->ny, sizeof *y);
    rc_run_options o = {.y_end = y};
    rc_stats st;
    rc_error e;
    ENSURE(y && rc_run(m, &o, &st, &e) == RC_OK);
    const double vz = y ? y[m->body_yadr[0] + 9] : NAN;
    printf("    at the end (0.1 s): v_z = %.3g m/s; %ld steps\n", vz, st.steps);
    ENSURE(fabs(vz) < 1e-12 && st.steps < 60000);
    free(y);
    rc_model_free(m);
}

/* The friction of a ball resting against a lightly damped wall (TYPE6
 * Iform 1, zeta 0.0067 on its Stiff line) stuck and slipped once a period
 * as BDF orders 3 to 5 rang the wall's mode: 284 079 events, then
 * CV_TOO_MUCH_WORK at 1.02 s of 1.32 s. The contact whose events crowd is
 * held at order 2 while it is closed (docs/theory.md 7.7): the run ends
 * with some 100 events. */
static void test_light_damper_chatter_held_at_order_2(void)
{
    rc_model *m = TU_LOAD_OK("tests/data/ramp_wall_light_damper_stick_slip_chatter.rad");
    if (!m) return;
    rc_run_options o = {0};
    rc_stats st;
    rc_error e;
    const rc_status rs = rc_run(m, &o, &st, &e);
    printf("    to the end (1.32 s): %s; %ld events, %ld steps\n", rs == RC_OK ? "ok" : e.msg, st.events, st.steps);
    ENSURE(rs == RC_OK && st.events < 1000 && st.steps < 200000);
    rc_model_free(m);
}

/* A 1 kg ball (radius 0.05 m) touching a floor plane z = 0: its node,
 * body, sphere, the plane and the ball's node group, as deck text. */
#define BALL_ON_FLOOR \
    "/NODE\n         1                   0                   0                0.05\n" \
    "/RBODY/1\nball\n         1                                                 1         1\n" \
    "               0.001               0.001               0.001\n" \
    "                   0                   0                   0\n" \
    "/SURF/ELLIPS/1\nball\n         0         2         1\n" \
    "                   0                   0                0.05\n" \
    "                0.05                0.05                0.05\n" \
    "/SURF/PLANE/2\nfloor\n                   0                   0                   0\n" \
    "                   0                   0                   1\n" \
    "/GRNOD/NODE/1\nball\n         1\n"

/* The ball of BALL_ON_FLOOR on TYPE6 Iform 1: a load curve of two
 * segments (1 N at 1 um, 20 N at 10 um), an unload curve at zero up to
 * 3 um, then 1.43e6 N/m, Stiff 1e8 N/m. */
#define IFORM1_BALL_DECK                                                                                          \
    "/BEGIN\nIform 1 ball on a floor\n      2022         0\n"                                                     \
    "                  kg                   m                   s\n"                                              \
    "                  kg                   m                   s\n"                                              \
    "/FUNCT/1\nload\n                   0                   0\n                1e-6                   1\n"         \
    "                1e-5                  20\n"                                                                   \
    "/FUNCT/2\nunload\n                   0                   0\n                3e-6                   0\n"       \
    "                1e-5                  10\n" BALL_ON_FLOOR                                                     \
    "/INTER/TYPE6/1\nball on floor\n         1         2\n\n"                                                   \
    "                                                 0         0\n"                                              \
    "         1         1                 1.0                 1.0\n"                                              \
    "         2                 1e8                 1.0\n"                                                        \
    "                             0         0\n"                                                                  \
    "/RUN\n                0.01              0.0001\n/END\n"

/* The stored energy of Iform 1 where the unload curve leaves zero at a
 * breakpoint (F_U = 0 up to 3 um, then 1.43e6 N/m): the path down the
 * Stiff line meets the unload curve and follows it to its zero. Computing
 * where F_U crosses zero could land a rounding above the breakpoint, and
 * the path then stopped at 0 J (the hysteresis jumped by the whole stored
 * energy at a friction event of a box, 7.6e-6 J). Against the path
 * integrated by hand at 2001 states of the elastic branch. */
static void test_iform1_stored_energy_on_the_unload_path(void)
{
    rc_model *m = TU_COMPILE_OK(IFORM1_BALL_DECK, "iform1e.rad");
    if (!m) return;
    ENSURE(m->inter_hidx[0] >= 0);
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double));
    rc_initial_state(m, y);
    d->inter_mode[0] = RC_MODE_CLOSED;
    d->inter_branch[0] = RC_BR_ELASTIC;
    const double k = 1e8, su = 10.0 / 7e-6;
    double worst = 0.0, wp = 0.0;
    int zero = 0;
    for (int n = 0; n <= 2000; n++) {
        const double P = 4e-6 + 5e-6 * n / 2000.0;
        const double fl = 1.0 + 19.0 * (P - 1e-6) / 9e-6, fu = su * (P - 3e-6);
        const double F = fu + 0.1 * (fl - fu);
        y[m->body_yadr[0] + 2] = 0.05 - P; /* the centre: the ball penetrates by P */
        y[m->inter_eadr[0] + m->inter_hidx[0]] = F;
        /* by hand: down the Stiff line to F_U at s, then along F_U to 3 um */
        const double s = (F - k * P + su * 3e-6) / (su - k);
        const double expect = 0.5 * (F + su * (s - 3e-6)) * (P - s) + 0.5 * su * (s - 3e-6) * (s - 3e-6);
        const double got = rc_inter_stored_energy(m, d, 0, 0.0, y);
        zero += got == 0.0;
        if (fabs(got - expect) / expect > worst) {
            worst = fabs(got - expect) / expect;
            wp = P;
        }
    }
    printf("    2001 states from P = 4 to 9 um on the elastic branch: %d at 0 J, largest relative error %.3g "
           "(P = %.4g m)\n", zero, worst, wp);
    ENSURE(zero == 0);
    ENSURE(worst < 1e-9);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

/* The law's dissipation rate of Iform 1 on the load curve (the deck of
 * the test above, a ball approaching the floor at 0.01 m/s): D_h' is the
 * work rate less the rate of the stored energy, Delta (Stiff - F_L') dP/dt
 * with Delta the length of the unloading path's first Stiff line, against
 * the stored energy's rate by central differences along the load curve
 * (the path integrated by rc_inter_path_energy), at 31 depths over both
 * segments of the load curve; >= 0; and 0 on the Stiff line, where the
 * law stores its work. Before, energy_hysteresis was the work less the
 * stored energy, two values integrated apart, and fell by their error (a
 * ball on a ramp into a wall: 2.5e-6 J at rtol 1e-10). */
static void test_iform1_dissipation_rate_on_the_load_curve(void)
{
    rc_model *m = TU_COMPILE_OK(IFORM1_BALL_DECK, "iform1r.rad");
    if (!m) return;
    ENSURE(m->inter_hidx[0] >= 0 && m->inter_dhidx[0] >= 0);
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double)), *yd = calloc((size_t)m->ny, sizeof(double));
    if (!d || !y || !yd || m->inter_dhidx[0] < 0) goto out;
    rc_initial_state(m, y);
    d->inter_mode[0] = RC_MODE_CLOSED;
    const double v = 0.01;
    double worst = 0.0, dmin = INFINITY, elastic = 0.0;
    for (int n = 0; n <= 30; n++) {
        const double P = 0.5e-6 + 8.5e-6 * n / 30.0;
        double fl = P < 1e-6 ? 1e6 * P : 1.0 + 19.0 * (P - 1e-6) / 9e-6;
        y[m->body_yadr[0] + 2] = 0.05 - P; /* the ball penetrates by P */
        y[m->body_yadr[0] + 9] = -v;       /* approaching */
        y[m->inter_eadr[0] + m->inter_hidx[0]] = fl;
        d->inter_branch[0] = RC_BR_LOAD;
        ENSURE(rc_assemble_rhs(m, d, 0.0, y, yd) == 0);
        const double dh = yd[m->inter_eadr[0] + m->inter_dhidx[0]], w = yd[m->inter_eadr[0]];
        /* dE/dt along the load curve by central differences */
        const double h = 1e-3 * fmin(P, fabs(P - 1e-6) > 0 ? fabs(P - 1e-6) : P) / v;
        double e2[2];
        for (int k = 0; k < 2; k++) {
            const double q = P + (k ? v : -v) * h;
            e2[k] = rc_inter_path_energy(m, 0, q, q < 1e-6 ? 1e6 * q : 1.0 + 19.0 * (q - 1e-6) / 9e-6);
        }
        const double expect = w - (e2[1] - e2[0]) / (2 * h);
        worst = fmax(worst, fabs(dh - expect) / (fl * v));
        dmin = fmin(dmin, dh / (fl * v));
        /* on the Stiff line, halfway between the curves: no dissipation */
        const double fu = P > 3e-6 ? 10.0 * (P - 3e-6) / 7e-6 : 0.0;
        y[m->inter_eadr[0] + m->inter_hidx[0]] = 0.5 * (fl + fu);
        d->inter_branch[0] = RC_BR_ELASTIC;
        ENSURE(rc_assemble_rhs(m, d, 0.0, y, yd) == 0);
        elastic = fmax(elastic, fabs(yd[m->inter_eadr[0] + m->inter_dhidx[0]]));
    }
    printf("    31 depths on the load curve: D_h' against the work less dE/dt: largest difference %.3g of F v; "
           "smallest D_h' %.4g of F v; on the Stiff line |D_h'| <= %.3g W\n", worst, dmin, elastic);
    ENSURE(worst < 1e-6);
    ENSURE(dmin >= 0.0);
    ENSURE(elastic == 0.0);
out:
    free(yd);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

/* A box sliding from a touching start at every tolerance: its friction
 * limit rises from zero as the box settles, and the slip law's rates stay
 * bounded (L_r at least w F_s, docs/theory.md 3.5): before, the run
 * failed at 4.6e-5 s (error test failures on the corners' springs) or
 * created 0.05 J of spring energy, depending on rtol. */
static void test_box_sliding_start_at_every_rtol(void)
{
    const double rt[4] = {1e-5, 1e-6, 1e-7, 1e-8};
    for (int k = 0; k < 4; k++) {
        rc_error e;
        rc_model *m = tu_compile_text(box_deck, "box.rad", &e);
        ENSURE(m != NULL);
        if (!m) continue;
        ENSURE(rc_model_set_rtol(m, rt[k], &e) == RC_OK);
        double y[64];
        rc_run_options o;
        memset(&o, 0, sizeof o);
        o.y_end = y;
        rc_stats st;
        const rc_status s = rc_run(m, &o, &st, &e);
        printf("    rtol %g: %s, %ld steps, z = %.9f m, speed %.3g m/s; %s\n", rt[k], s ? e.msg : "ok", st.steps,
               y[2], hypot(y[7], y[8]), st.physics_note);
        ENSURE(s == RC_OK);
        ENSURE(s || (y[2] > 0.0499 && y[2] < 0.0501 && hypot(y[7], y[8]) < 1e-6));
        rc_model_free(m);
    }
}


/* The at_event flags of the records of results file `path` (the caller
 * frees *ae); their number, 0 when the file cannot be read. */
static size_t read_at_event(const char *path, int **ae)
{
    int ncid, dim, var;
    size_t nt = 0;
    *ae = NULL;
    if (nc_open(path, NC_NOWRITE, &ncid) != NC_NOERR) return 0;
    if (nc_inq_dimid(ncid, "time", &dim) == NC_NOERR && nc_inq_dimlen(ncid, dim, &nt) == NC_NOERR &&
        (*ae = calloc(nt + 1, sizeof(int))) != NULL && nc_inq_varid(ncid, "at_event", &var) == NC_NOERR)
        nc_get_var_int(ncid, var, *ae);
    nc_close(ncid);
    return *ae ? nt : 0;
}

/* Records inside contacts (at_event = 2, docs/output-format.md) cover the
 * first contact times of an impact, not a contact that lasts: a ball
 * resting on a floor for 2 s (Dt_out 0.5 s, its contact time ~6 ms) gets
 * about 4 x 20 of them, where it got one per step before (a resting
 * contact filled 200 MB in a few seconds). */
static void test_contact_records_bounded(void)
{
    static const char *deck =
        "/BEGIN\nresting ball\n      2022         0\n"
        "                  kg                   m                   s\n"
        "                  kg                   m                   s\n"
        "/FUNCT/1\nlinear\n                   0                   0\n                   1             1000000\n"
        BALL_ON_FLOOR
        "/GRAV/1\ng\n         0         Z         0         0         1                             1               -9.81\n"
        "/INTER/TYPE6/1\nball on floor\n         1         2\n\n\n         1         0\n\n         600\n"
        "/RUN\n                   2                 0.5\n/END\n";
    char out[512];
    rc_stats st;
    ENSURE(run_to_file(deck, "rest.rad", out, NULL, &st) == 0);
    int *ae = NULL;
    const size_t nt = read_at_event(out, &ae);
    long n2 = 0;
    for (size_t k = 0; k < nt; k++) n2 += ae[k] == 2;
    free(ae);
    printf("    resting ball, 2 s: %zu records, %ld inside the contact (at_event = 2), %ld steps\n", nt, n2, st.steps);
    ENSURE(nt > 0 && n2 > 0 && n2 <= 4 * 20 + 10);
}


/* Records at events and inside contacts are at most RC_EXTRA_RECORDS per
 * output interval (docs/output-format.md): a ball dropped 0.1 m on a floor
 * (k 1e6 N/m, Visc 60 N s/m) bounces 11 times within one output interval
 * of 2 s, some 20 such records each; the file keeps 200 of them and every
 * event in its events table, and the run says how many it left out (a
 * chattering cradle filled 213 MB in 0.3 s). */
static void test_extra_records_bounded(void)
{
    static const char *deck =
        "/BEGIN\nbouncing ball\n      2022         0\n"
        "                  kg                   m                   s\n"
        "                  kg                   m                   s\n"
        "/FUNCT/1\nlinear\n                   0                   0\n                   1             1000000\n"
        "/NODE\n         1                   0                   0                0.15\n"
        "/RBODY/1\nball\n         1                                                 1         1\n"
        "               0.001               0.001               0.001\n"
        "                   0                   0                   0\n"
        "/SURF/ELLIPS/1\nball\n         0         2         1\n"
        "                   0                   0                0.15\n"
        "                0.05                0.05                0.05\n"
        "/SURF/PLANE/2\nfloor\n                   0                   0                   0\n"
        "                   0                   0                   1\n"
        "/GRNOD/NODE/1\nball\n         1\n"
        "/GRAV/1\ng\n         0         Z         0         0         1                             1               -9.81\n"
        "/INTER/TYPE6/1\nball on floor\n         1         2\n\n\n         1         0\n\n          60\n"
        "/RUN\n                   2                   2\n/END\n";
    char out[512];
    rc_stats st;
    ENSURE(run_to_file(deck, "bounce.rad", out, NULL, &st) == 0);
    int *ae = NULL;
    const size_t nt = read_at_event(out, &ae);
    long nx = 0, thinned = -1;
    for (size_t k = 0; k < nt; k++) nx += ae[k] != 0;
    free(ae);
    int ncid, dim;
    size_t nev = 0;
    if (nc_open(out, NC_NOWRITE, &ncid) == NC_NOERR) {
        if (nc_inq_dimid(ncid, "event", &dim) == NC_NOERR) nc_inq_dimlen(ncid, dim, &nev);
        long long v = -1;
        if (nc_get_att_longlong(ncid, NC_GLOBAL, "stats_records_thinned", &v) == NC_NOERR) thinned = (long)v;
        nc_close(ncid);
    }
    printf("    %ld events; %zu records, %ld at events or inside contacts; %ld left out (the file says %ld); "
           "%zu rows in the events table\n", st.events, nt, nx, st.records_thinned, thinned, nev);
    ENSURE(st.events > 20 && st.records_thinned > 0 && thinned == st.records_thinned);
    ENSURE(nx == 200 && nt == 202 && (long)nev == st.events);
}


/* ---- the power law's rebound branch on the damping's own rate --------- */
/* A box resting flat on a floor with /INTER/POWER (K 1e9 N/m^1.5, m1 1.5,
 * C 1e4, m2 1, m3 1.5, RDF 0.001): its law's penetration P_e a little above
 * P (a relaxation in progress, rate -kappa (P_e - P)), the box at rest
 * (v_bar = 0). The RDF root is v_bar, the rate the damping acts on, where
 * the damping force is zero on both branches; on P_e's rate (negative
 * here) the branch switched while the damper carried a force, and the jump
 * turned the rate back at once (a box on an incline: rebound/approach every
 * 1e-9 s, Zeno). */
static void test_power_rdf_root_on_damping_rate(void)
{
    static const char *deck =
        "/BEGIN\nbox on a floor, power law\n      2022         0\n"
        "                  kg                   m                   s\n"
        "                  kg                   m                   s\n"
        "/NODE\n1,0,0,0.04\n"
        "/RBODY/1\nbox\n1,,,,15,1\n0.026,0.058,0.063\n0,0,0\n"
        "/SURF/BOX/1\nbox\n1\n0,0,0.04\n0.1,0.06,0.04\n"
        "/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n"
        "/GRNOD/NODE/1\nbox\n1\n"
        "/GRAV/1\ng\n0,Z,0,0,1,,1,-9.81\n"
        "/INTER/POWER/1\nbox on floor\n1,2\n1e9,1.5,1e4,1,1.5\n0.001\n"
        "/RUN\n0.01,0.001\n/END\n";
    rc_model *m = TU_COMPILE_OK(deck, "power_rdf.rad");
    if (!m) return;
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double));
    const int ng = rc_root_land_base(m) + m->npt;
    double *g = calloc((size_t)ng + 1, sizeof(double));
    ENSURE(d && y && g && m->ninter == 1 && m->inter_peidx[0] >= 0 && m->inter_pw[0].rdf == 0.001);
    if (!d || !y || !g) goto out;
    rc_initial_state(m, y);
    double *yb = y + m->body_yadr[0];
    const double p = 1e-6;
    yb[2] = 0.04 - p; /* every corner 1e-6 m into the floor, at rest */
    y[m->inter_eadr[0] + m->inter_peidx[0]] = 1.5 * p; /* P_e above P: relaxing */
    d->inter_mode[0] = RC_MODE_CLOSED;
    for (int br = 0; br < 2; br++) {
        d->inter_branch[0] = br == 0 ? RC_BR_LOAD : RC_BR_UNLOAD;
        rc_inter_report r;
        rc_inter_report_eval_d(m, d, 0, 0.0, y, &r);
        rc_assemble_roots(m, d, 0.0, y, g);
        const double root = g[RC_ROOT_HYST_A];
        printf("    %s: P %.6e m, P_e %.6e m, v_bar %.3e m/s, P_e rate %.6e m/s, RDF root %.3e m/s, damping %.3e N\n",
               br == 0 ? "approach" : "rebound", r.p, r.pl, r.vd, r.vl, root, r.fdamp);
        ENSURE(fabs(r.p - p) < 1e-12 && fabs(r.pl - 1.5 * p) < 1e-12);
        ENSURE(fabs(r.vd) < 1e-12);         /* at rest: v_bar = 0 */
        ENSURE(r.vl < -1e-3 * p);           /* P_e relaxes down */
        ENSURE(fabs(root - r.vd) < 1e-12);  /* the root is the damping's rate */
        ENSURE(fabs(r.fdamp) < 1e-9);       /* no damping force at the root */
    }
out:
    free(g);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

/* ---- no recovery of P_e on the unload floor ---------------------------- */
/* A box (1 kg) on a floor, TYPE6 Iform 2 (load curve 1e6 N/m, Stiff 1e8
 * N/m, Visc 100 N s/m, Fric 0.5), flat, 1e-6 m into the floor with its
 * law's penetration P_e = 0.5e-6 m (a deficit), sliding at 0.1 m/s and
 * lifting at 2e-3 m/s, so that its damper dissipates (pays a recovery). On
 * the unload floor (F_el = 0) the law's rate is v_bar: P_e does not
 * recover there, and the reloading root (the law's rate) stays negative
 * while the box lifts. Recovering "for free" at F_el = 0 read a reloading
 * rate on the floor that the Stiff line, paying for it, turned back at once
 * (a box lifting off its floor: reloading and unloading every 3e-12 s,
 * Zeno). On the Stiff line carrying 1 N the recovery still acts, and on
 * the Stiff line at zero force it is that of a force just above zero (the
 * rate is continuous there: withholding it made the error test fail). */
/* The box of these tests: 1 kg on a floor, TYPE6 Iform 2 (load curve 1e6
 * N/m, Stiff 1e8 N/m, Fric 0.5), its damping line `visc` (Visc [N s/m], or
 * blank). */
#define BOX_IFORM2_DECK(visc)                                                                                      \
    "/BEGIN\nbox on a floor, Iform 2\n      2022         0\n"                                                       \
    "                  kg                   m                   s\n"                                              \
    "                  kg                   m                   s\n"                                              \
    "/NODE\n1,0,0,0.04\n"                                                                                         \
    "/RBODY/1\nbox\n1,,,,1,1\n0.002,0.002,0.002\n0,0,0\n"                                                        \
    "/SURF/BOX/1\nbox\n1\n0,0,0.04\n0.05,0.05,0.04\n"                                                           \
    "/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n"                                                                       \
    "/GRNOD/NODE/1\nbox\n1\n"                                                                                    \
    "/GRAV/1\ng\n0,Z,0,0,1,,1,-9.81\n"                                                                           \
    "/FUNCT/1\nlinear\n0,0\n1,1000000\n"                                                                        \
    "/INTER/TYPE6/1\nbox on floor\n1,2\n0,0.5\n\n1,2\n0,,100000000\n" visc "\n"                                  \
    "/RUN\n0.01,0.001\n/END\n"

/* The roots of the hysteresis after the touch pass: the box of these tests
 * at random depths (up to 1e-6 m, its load curve's force there 1 N) and
 * rates, in random modes and branches. A contact released at zero force on
 * the floor of its unload curve and closed again there while its law
 * reloads must reload in the same pass: deciding the branch only when the
 * mode had not changed left it on the floor with its rate root started
 * past zero (a meshed box sank 2 m through its belt at zero force); and a
 * curve kept at a rate within the slip band waits that band away. */
static void test_hysteresis_roots_wait_on_their_side(void)
{
    roots_wait_on_their_side(BOX_IFORM2_DECK("100"), "box_iform2_visc.rad", 400, 1e-6);
    roots_wait_on_their_side(BOX_IFORM2_DECK(""), "box_iform2.rad", 400, 1e-6);
}

static void test_pe_no_recovery_at_zero_force(void)
{
    rc_model *m = TU_COMPILE_OK(BOX_IFORM2_DECK("100"), "pe_zero_force.rad");
    if (!m) return;
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double));
    const int ng = rc_root_land_base(m) + m->npt;
    double *g = calloc((size_t)ng + 1, sizeof(double));
    ENSURE(d && y && g && m->ninter == 1 && m->inter_peidx[0] >= 0 && m->inter_hidx[0] >= 0 &&
           m->inter_iform[0] == 2);
    if (!d || !y || !g) goto out;
    rc_initial_state(m, y);
    double *yb = y + m->body_yadr[0];
    const double p = 1e-6;
    yb[2] = 0.04 - p; /* every corner 1e-6 m into the floor */
    yb[7] = 0.1;      /* sliding */
    yb[9] = 2e-3;     /* lifting */
    y[m->inter_eadr[0] + m->inter_peidx[0]] = 0.5 * p; /* P_e below P: a deficit */
    d->inter_mode[0] = RC_MODE_CLOSED;
    const double fhs[4] = {0.0, 1.0, 0.0, 1e-9};
    const char *what[4] = {"unload floor", "Stiff line at 1 N", "Stiff line at 0 N", "Stiff line at 1e-9 N"};
    double vl[4];
    for (int k = 0; k < 4; k++) {
        d->inter_branch[0] = k == 0 ? RC_BR_UNLOAD : RC_BR_ELASTIC;
        y[m->inter_eadr[0] + m->inter_hidx[0]] = fhs[k]; /* F_h on the Stiff line [N] */
        rc_inter_report r;
        rc_inter_report_eval_d(m, d, 0, 0.0, y, &r);
        rc_assemble_roots(m, d, 0.0, y, g);
        printf("    %s: F_el %.3e N, damping %.3e N, v_bar %.6e m/s, law's rate %.6e m/s, HYST_A root %.3e\n",
               what[k], r.fload, r.fdamp, r.vd, r.vl, g[RC_ROOT_HYST_A]);
        ENSURE(fabs(r.vd + 2e-3) < 1e-9); /* v_bar: the lifting */
        vl[k] = r.vl;
        if (k == 0) {
            ENSURE(r.fload == 0.0);
            ENSURE(r.vl == r.vd);                /* no recovery at zero force */
            ENSURE(g[RC_ROOT_HYST_A] < 0.0);     /* no reloading while lifting */
        } else {
            ENSURE(r.vl > r.vd + 1e-6);          /* recovery, paid by the damper */
        }
    }
    ENSURE(fabs(vl[2] - vl[3]) <= 1e-6 * fabs(vl[3])); /* continuous at F_el = 0 on the Stiff line */
out:
    free(g);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

/* ---- the recovery of P_e is continuous in what pays for it ------------- */
/* The box of the test above (Visc 100 N s/m), on the Stiff line at zero
 * force (F_h = 0), with the same deficit of P_e, approaching at v: its
 * damper dissipates D = Visc v^2, which pays for the recovery,
 * rho = kappa (P - P_e) D / (D + F_el+ kappa (P - P_e) + D_b). At rest
 * nothing pays (rho = 0: undamped and frictionless, a free recovery held
 * the Stiff line at zero force by its own rates, a stack of boxes 15 times
 * slower); at 1e-9 m/s it is still about 0 (continuous across D = 0: a
 * recovery switched on by any D > 0 jumped from 0 to kappa (P - P_e) where
 * a box's friction power turned, and Newton failed, CV_CONV_FAILURE with h
 * = 8e-11 s); it grows with D towards kappa (P - P_e), never beyond it. On
 * the Stiff line carrying 1 N at rest: none. Friction pays on the load
 * curve only: the box without a damper sliding at 0.3 m/s recovers on its
 * load curve and not on its Stiff line (paid there, the sliding's heat
 * lifted F_h at Stiff times the recovery and launched the box: a box
 * sliding down an incline cycled its hysteresis 6 000 times in 0.9 s,
 * 31 971 events, and a meshed box on a belt 2 464 times in 0.68 s). */
static void test_pe_recovery_continuous_in_its_payment(void)
{
    rc_model *m = TU_COMPILE_OK(BOX_IFORM2_DECK("100"), "pe_zero_force_pay.rad");
    rc_model *mf = TU_COMPILE_OK(BOX_IFORM2_DECK(""), "pe_zero_force_fric.rad");
    if (!m || !mf) goto out0;
    rc_data *d = rc_data_new(m), *df = rc_data_new(mf);
    double *y = calloc((size_t)m->ny, sizeof(double)), *yf = calloc((size_t)mf->ny, sizeof(double));
    ENSURE(d && y && df && yf && m->ninter == 1 && m->inter_peidx[0] >= 0 && m->inter_hidx[0] >= 0 &&
           m->inter_perelax[0] > 0);
    if (!d || !y || !df || !yf) goto out;
    rc_initial_state(m, y);
    double *yb = y + m->body_yadr[0];
    const double p = 1e-6, kd = m->inter_perelax[0] * 0.5 * p;
    yb[2] = 0.04 - p;
    y[m->inter_eadr[0] + m->inter_peidx[0]] = 0.5 * p;
    d->inter_mode[0] = RC_MODE_CLOSED;
    d->inter_branch[0] = RC_BR_ELASTIC;
    const double vz[4] = {0.0, -1e-9, -1e-3, -0.3}; /* approaching (z falling) */
    double rho[4], rho1 = NAN;
    for (int k = 0; k < 4; k++) {
        yb[9] = vz[k];
        y[m->inter_eadr[0] + m->inter_hidx[0]] = 0.0; /* the Stiff line at zero force */
        rc_inter_report r;
        rc_inter_report_eval_d(m, d, 0, 0.0, y, &r);
        rho[k] = r.vl - r.vd; /* the law's rate less the bodies' (v_bar) */
        printf("    Stiff line at 0 N, approaching at %g m/s: F_el %.3e N, recovery %.9e m/s (kappa (P - P_e) %.9e)\n",
               -vz[k], r.fload, rho[k], kd);
        ENSURE(!(r.fload > 0));
        ENSURE(rho[k] >= 0.0 && rho[k] <= kd * (1.0 + 1e-12));
        if (k == 0) {
            y[m->inter_eadr[0] + m->inter_hidx[0]] = 1.0; /* carrying 1 N, at rest: nothing pays */
            rc_inter_report_eval_d(m, d, 0, 0.0, y, &r);
            rho1 = r.vl - r.vd;
        }
    }
    printf("    Stiff line at 1 N, at rest: recovery %.3e m/s\n", rho1);
    ENSURE(rho[0] == 0.0);                          /* nothing pays at rest */
    ENSURE(rho[1] > 0.0 && rho[1] < 1e-6 * kd);     /* continuous across D = 0 */
    ENSURE(rho[2] > rho[1] && rho[3] > rho[2]);     /* grows with what pays */
    ENSURE(rho[3] > 0.5 * kd);                      /* towards kappa (P - P_e) */
    ENSURE(fabs(rho1) < 1e-15);
    /* no damper, sliding at 0.3 m/s: friction pays on the load curve only */
    rc_initial_state(mf, yf);
    double *ybf = yf + mf->body_yadr[0];
    ybf[2] = 0.04 - p;
    ybf[7] = 0.3;
    yf[mf->inter_eadr[0] + mf->inter_peidx[0]] = 0.5 * p;
    df->inter_mode[0] = RC_MODE_CLOSED;
    double rf[2];
    for (int k = 0; k < 2; k++) {
        df->inter_branch[0] = k ? RC_BR_ELASTIC : RC_BR_LOAD;
        rc_inter_report r;
        rc_inter_report_eval_d(mf, df, 0, 0.0, yf, &r);
        yf[mf->inter_eadr[0] + mf->inter_hidx[0]] = k ? 0.5 * r.fl : r.fl; /* on the line below the curve */
        rc_inter_report_eval_d(mf, df, 0, 0.0, yf, &r);
        rf[k] = r.vl - r.vd;
        printf("    no damper, sliding at 0.3 m/s, %s: F_el %.3e N, recovery %.9e m/s\n",
               k ? "Stiff line" : "load curve", r.fload, rf[k]);
    }
    ENSURE(rf[0] > 0.5 * kd && rf[0] <= kd * (1.0 + 1e-12)); /* the load curve: paid by the sliding */
    ENSURE(rf[1] == 0.0);                                  /* the Stiff line: not */
out:
    free(y);
    free(yf);
    rc_data_free(d);
    rc_data_free(df);
out0:
    rc_model_free(m);
    rc_model_free(mf);
}

/* ---- a falling limit: the slip goes on until the spring outruns it ---- */
/* A ball (1 kg, R = 0.05 m) pressed into a floor by p = 1e-5 m (linear law
 * 1e6 N/m: F_n = 10 N), Fric 0.3 (limit 3 N), stick stiffness Stiff 1e7
 * N/m, slipping with its friction state 1.2 times the limit along +x and a
 * sliding velocity along it, v_x = 1e-4 m/s (v_t . e > 0). Lifting at
 * v_z = 0.01 m/s, its limit falls at mu k v_z = 3e3 N/s, faster than the
 * spring unloads (K_t v_x = 1e3 N/s): the slip root v_t . e - (-dL/dt) / K_t
 * stays negative (it slides on), where v_t . e = 0 alone called for a stick
 * that the falling limit broke 1e-10 s later (a box lifting off a belt:
 * Zeno). Pressing down instead (v_z < 0, a rising limit) the root is v_t . e.
 * Either way the spring sliding along its force unloads as a spring,
 * dF_t/dt = -K_t v_t, and the law dissipates (docs/theory.md 3.5). */
static const char *slip_limit_deck =
    "/BEGIN\nball on a floor, slipping\n      2022         0\n"
    "                  kg                   m                   s\n"
    "                  kg                   m                   s\n"
    "/FUNCT/1\nlinear\n0,0\n1,1000000\n" BALL_ON_FLOOR
    "/INTER/TYPE6/1\nball on floor\n1,2\n0,0.3\n\n1,0\n0,,10000000\n\n"
    "/RUN\n0.01,0.001\n/END\n";

static void test_slip_waits_for_a_falling_limit(void)
{
    rc_model *m = TU_COMPILE_OK(slip_limit_deck, "slip_limit.rad");
    if (!m) return;
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double)), *yd = calloc((size_t)m->ny, sizeof(double));
    ENSURE(d && y && yd && m->ninter == 1 && m->inter_fr[0].tidx >= 0);
    if (!d || !y || !yd) goto out;
    rc_initial_state(m, y);
    const double kt = m->inter_fr[0].kt, vx = 1e-4;
    double *yb = y + m->body_yadr[0], *ft = y + m->inter_eadr[0] + m->inter_fr[0].tidx;
    yb[2] = 0.05 - 1e-5; /* 1e-5 m into the floor */
    yb[7] = vx;
    d->inter_mode[0] = RC_MODE_CLOSED;
    d->inter_slip[0] = 1;
    for (int c = 0; c < 2; c++) {
        const double vz = c == 0 ? 0.01 : -0.01; /* lifting, pressing */
        yb[9] = vz;
        rc_inter_report r;
        rc_inter_report_eval_d(m, d, 0, 0.0, y, &r);
        ft[0] = 1.2 * r.flim; /* the state above the limit, along the sliding */
        ft[1] = ft[2] = 0.0;
        rc_inter_report_eval_d(m, d, 0, 0.0, y, &r);
        /* mu = F_lim / F_n, k = F / P (a line through 0), dP/dt = -v_z */
        const double mu = r.flim / r.fn, k = r.fload / r.pl;
        const double thr = c == 0 ? mu * k * vz / kt : 0.0;
        ENSURE(rc_assemble_rhs(m, d, 0.0, y, yd) == 0);
        printf("    %s at %g m/s: F_n %.4g N, limit %.4g N, K_t %.3g N/m, slip root %.6e m/s (v_t.e %.1e less %.6e), "
               "dF_t/dt %.6e N/s (-K_t v_t %.6e)\n",
               c == 0 ? "lifting" : "pressing", fabs(vz), r.fn, r.flim, kt, r.slip_root, vx, thr, yd[m->inter_eadr[0] + m->inter_fr[0].tidx],
               -kt * vx);
        ENSURE(fabs(r.fn - 10.0) < 1e-9 && fabs(r.flim - 3.0) < 1e-9 && fabs(kt - 1e7) < 1e-3);
        ENSURE(fabs(r.slip_root - (vx - thr)) <= 1e-12 * fabs(vx));
        ENSURE(c == 0 ? r.slip_root < -1e-4 : r.slip_root > 0);
        /* below the threshold the spring unloads as a spring; pressing,
         * the root calls the stick at once */
        if (c == 0) ENSURE(fabs(yd[m->inter_eadr[0] + m->inter_fr[0].tidx] + kt * vx) <= 1e-9 * kt * vx);
    }
    /* lifting, the state put on the limit by a stick -> slip event, a few
     * roundings below it: still "at the limit" (within the force band), the
     * root is v_t . e less the threshold; taken as below the limit, the root
     * was +v_t . e and the slip that starts turned against the sliding by
     * rounding (a ball struck by a meshed box left at 3.60 or 3.64 m/s) */
    {
        yb[7] = vx;
        yb[9] = 0.01;
        rc_inter_report r;
        rc_inter_report_eval_d(m, d, 0, 0.0, y, &r);
        ft[0] = nextafter(nextafter(nextafter(r.flim, 0.0), 0.0), 0.0);
        ft[1] = ft[2] = 0.0;
        rc_inter_report_eval_d(m, d, 0, 0.0, y, &r);
        const double thr = 3e-4;
        printf("    lifting, the state 3 roundings below the limit: slip root %.6e m/s (want %.6e)\n", r.slip_root,
               vx - thr);
        ENSURE(fabs(r.slip_root - (vx - thr)) <= 1e-8 * vx && r.slip_root < 0);
    }
    /* lifting, the state below the falling limit: the threshold fades out
     * of the root over the slip band under the limit (wb = 1e-6 L + the
     * force band), so a state that drops below the limit while it unloads
     * as a spring sticks; the rate is the spring's on both sides of the
     * limit (it jumped from -K_t v to ~0 there, and Newton's iteration
     * failed on a ball leaving a ramp: CV_TOO_MUCH_WORK at 7e-14 s) */
    {
        yb[7] = vx;
        yb[9] = 0.01;
        rc_inter_report r;
        rc_inter_report_eval_d(m, d, 0, 0.0, y, &r);
        const double L = r.flim, wb = 1e-6 * L + m->inter_fr[0].fband, thr = 3e-4;
        const double off[4] = {-1e-9 * L, 1e-9 * L, 0.5 * wb, 2.0 * wb};
        const double want[4] = {vx - thr, vx - thr * (1.0 - 1e-9 * L / wb), vx - 0.5 * thr, vx};
        double rate[4];
        for (int c = 0; c < 4; c++) {
            ft[0] = L - off[c];
            ft[1] = ft[2] = 0.0;
            rc_inter_report_eval_d(m, d, 0, 0.0, y, &r);
            ENSURE(rc_assemble_rhs(m, d, 0.0, y, yd) == 0);
            rate[c] = yd[m->inter_eadr[0] + m->inter_fr[0].tidx];
            printf("    lifting, the state %.3g N below the limit %.3g N (band %.3g N): slip root %.6e m/s (want %.6e), "
                   "dF_t/dt %.6e N/s\n", off[c], L, wb, r.slip_root, want[c], rate[c]);
            ENSURE(fabs(r.slip_root - want[c]) <= 1e-6 * vx);
            ENSURE(fabs(rate[c] + kt * vx) <= 1e-6 * kt * vx);
        }
        ENSURE(fabs(rate[0] - rate[1]) <= 1e-6 * kt * vx);
        ft[0] = L; /* on the limit again, for the case below */
    }
    /* lifting, sliding along the force past the threshold (5e-4 > 3e-4 m/s):
     * the root calls the stick, and until then the state goes on at about
     * the limit's rate, K_t thr (1 + ln(v / thr)) = 4.53e3 N/s, not K_t v
     * (5e3 N/s, and 1e18 N/m stiffnesses made that rate swing the state
     * through zero within a step) */
    {
        const double v2 = 5e-4, thr = 3e-4;
        yb[7] = v2;
        yb[9] = 0.01;
        rc_inter_report r;
        rc_inter_report_eval_d(m, d, 0, 0.0, y, &r);
        ENSURE(rc_assemble_rhs(m, d, 0.0, y, yd) == 0);
        const double rate = yd[m->inter_eadr[0] + m->inter_fr[0].tidx], want = -kt * thr * (1.0 + log(v2 / thr));
        printf("    lifting, sliding at %g m/s: slip root %.6e m/s, dF_t/dt %.6e N/s (want %.6e)\n", v2, r.slip_root, rate, want);
        ENSURE(fabs(r.slip_root - (v2 - thr)) <= 1e-9 * v2 && r.slip_root > 0);
        ENSURE(fabs(rate - want) <= 1e-9 * fabs(want));
    }
out:
    free(y);
    free(yd);
    rc_data_free(d);
    rc_model_free(m);
}



/* Run a fuzzer regression deck to its end: exit 0 and fewer events than the
 * Zeno guard's 200 (what, the line's label). */
static void regression_runs_without_zeno(const char *path, const char *what)
{
    rc_model *m = TU_LOAD_OK(path);
    if (!m) return;
    rc_error e;
    rc_run_options o;
    memset(&o, 0, sizeof o);
    rc_stats st;
    const rc_status s = rc_run(m, &o, &st, &e);
    printf("    %s: %s, %ld events, %ld steps; %s\n", what, s ? e.msg : "ok", st.events, st.steps, st.physics_note);
    ENSURE(s == RC_OK);
    ENSURE(st.events < 200);
    rc_model_free(m);
}

/* A corner that sticks holds the force its spring has. A tilted box
 * striking a floor (TYPE6 friction per corner, K_t 2.2e10 N/m; a fuzzer
 * scene): a corner slides with its spring at ~600 N while the impact raises
 * the limit to 16 400 N; when its sliding along the force stops, the stick
 * is tested with that state (its stick force within the limit: it sticks),
 * not with the state put on the limit, where the stick damper's force
 * across the sliding (~50 N) left it 5e-6 beyond: the corner slid on, its
 * sliding turned by 90 degrees and stopped again 7 ns later, 200 times
 * (Zeno at t = 1.19 s). */
static void test_corner_stick_tested_with_its_spring(void)
{
    regression_runs_without_zeno("fuzz/physics/regressions/box_landing_corner_stick_tested_on_limit_zeno.rad",
                                 "tilted box landing with friction per corner");
}

/* The reversal root of a saturated viscous friction law (v_t . d_ref) is
 * not watched on a zero limit: there the saturated force is zero whatever
 * the direction, and two balls touching at zero force, sliding at the
 * velocities' rounding, reversed 200 times within 2e-10 s (a cradle on a
 * floor, Zeno at rtol 1e-10). When the limit rises from zero the root
 * takes v_t . d_ref and crosses if the sliding turned: the mode is then
 * set anew. */
static const char *viscous_zero_limit_deck =
    "/BEGIN\nball touching a floor, viscous friction\n      2022         0\n"
    "                  kg                   m                   s\n"
    "                  kg                   m                   s\n"
    "/FUNCT/1\nlinear\n0,0\n1,1000000\n" BALL_ON_FLOOR
    "/INTER/TYPE6/1\nball on floor\n1,2\n\n\n1,0\n\n\n"
    "/FRICTION/1\nviscous\n0,0,,1\n\n,0.37,0.8\n"
    "/RUN\n0.01,0.001\n/END\n";

static void test_viscous_reversal_root_waits_for_a_limit(void)
{
    rc_model *m = TU_COMPILE_OK(viscous_zero_limit_deck, "viscous_zero_limit.rad");
    if (!m) return;
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double)), *g = calloc((size_t)rc_root_count(m), sizeof(double));
    ENSURE(d && y && g && m->ninter == 1 && m->inter_fr[0].form == RC_FF_VISCOUS);
    if (!d || !y || !g) goto out;
    rc_initial_state(m, y);
    double *yb = y + m->body_yadr[0];
    d->inter_mode[0] = RC_MODE_CLOSED;
    d->inter_slip[0] = 1; /* saturated, sliding along +x when it saturated */
    d->inter_dref[0] = 1.0;
    d->inter_dref[1] = d->inter_dref[2] = 0.0;
    yb[7] = -1e-17; /* the sliding reversed, at the velocities' rounding */
    yb[2] = 0.05;   /* touching: no normal force, no limit */
    rc_assemble_roots(m, d, 0.0, y, g);
    const double at_zero = g[RC_ROOT_REV];
    yb[2] = 0.05 - 1e-6; /* pressed 1e-6 m: F_n 1 N, a limit */
    rc_assemble_roots(m, d, 0.0, y, g);
    const double pressed = g[RC_ROOT_REV];
    printf("    reversal root on a zero limit %.3g, with a limit %.3g m/s\n", at_zero, pressed);
    ENSURE(at_zero > 0);
    ENSURE(pressed < 0 && fabs(pressed + 1e-17) < 1e-30);
out:
    free(y);
    free(g);
    rc_data_free(d);
    rc_model_free(m);
}

/* The viscous form saturates on the limit with its bands, as the
 * incremental form slips: C |v_t| must exceed (1 + RC_SLIP_BAND) L plus the
 * force band (at least RC_SLIP_BAND of the force scale). Without the force
 * band, a limit rising from zero (a filtered limit at a closing, 5e-19 N)
 * against a sliding at the velocities' rounding decided the saturation on
 * rounding: a stack of boxes on the power law flipped eight points in and
 * out of saturation every 1e-13 s (Zeno at t = 0.0012 s). The ball on the
 * floor: (a) a limit of rounding size and a sliding of 1e-12 m/s, whose
 * viscous force is beyond that limit but within the band, stays below the
 * limit; (b) pressed 1 micron (a limit of 0.37 N), a viscous force of
 * twice the limit saturates, (c) one of half the limit does not; (d) once
 * saturated, it comes back below (1 - RC_SLIP_BAND) L only. */
static const char *viscous_band_deck =
    "/BEGIN\nball resting on a floor, viscous friction\n      2022         0\n"
    "                  kg                   m                   s\n"
    "                  kg                   m                   s\n"
    "/FUNCT/1\nlinear\n0,0\n1,1000000\n" BALL_ON_FLOOR
    "/INTER/TYPE6/1\nball on floor\n1,2\n\n\n1,0\n\n\n"
    "/FRICTION/1\nviscous\n0,0,,1\n\n,0.37,0.8\n"
    "/GRAV/1\ng\n0,Z,0,0,1,,1,-9.81\n"
    "/RUN\n0.01,0.001\n/END\n";

static void test_viscous_saturation_needs_the_force_band(void)
{
    rc_model *m = TU_COMPILE_OK(viscous_band_deck, "viscous_band.rad");
    if (!m) return;
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double));
    ENSURE(d && y && m->ninter == 1 && m->inter_fr[0].form == RC_FF_VISCOUS);
    if (!d || !y) goto out;
    rc_initial_state(m, y);
    double *yb = y + m->body_yadr[0];
    d->inter_mode[0] = RC_MODE_CLOSED;
    d->inter_slip[0] = 0;
    const double fbv = RC_SLIP_BAND * m->inter_fscale[0];
    rc_inter_report r;
    /* (a) */
    yb[2] = 0.05 - 2e-16;
    yb[7] = 1e-12;
    rc_inter_report_eval_d(m, d, 0, 0.0, y, &r);
    double fv = sqrt(r.ft[0] * r.ft[0] + r.ft[1] * r.ft[1] + r.ft[2] * r.ft[2]);
    printf("    rounding limit %.3g N, viscous force %.3g N, band %.3g N: root %.3g\n", r.flim, fv, fbv, r.slip_root);
    ENSURE(r.flim > 0 && fv > 2.0 * r.flim && fv < 0.1 * fbv);
    ENSURE(r.slip_root < 0);
    /* (b), (c): the sliding speed that gives a viscous force of s L */
    yb[2] = 0.05 - 1e-6;
    yb[7] = 1e-6;
    rc_inter_report_eval_d(m, d, 0, 0.0, y, &r);
    const double c = fabs(r.ft[0]) / 1e-6, L = r.flim;
    ENSURE(c > 0 && L > 0.3 && L < 0.4);
    yb[7] = 2.0 * L / c;
    rc_inter_report_eval_d(m, d, 0, 0.0, y, &r);
    const double twice = r.slip_root;
    yb[7] = 0.5 * L / c;
    rc_inter_report_eval_d(m, d, 0, 0.0, y, &r);
    const double half = r.slip_root;
    /* (d) saturated, at (1 - RC_SLIP_BAND / 2) L and (1 - 2 RC_SLIP_BAND) L */
    d->inter_slip[0] = 1;
    yb[7] = (1.0 - 0.5 * RC_SLIP_BAND) * L / c;
    rc_inter_report_eval_d(m, d, 0, 0.0, y, &r);
    const double stays = r.slip_root;
    yb[7] = (1.0 - 2.0 * RC_SLIP_BAND) * L / c;
    rc_inter_report_eval_d(m, d, 0, 0.0, y, &r);
    const double back = r.slip_root;
    printf("    limit %.4g N, C %.4g N s/m: roots at 2 L %.3g, L/2 %.3g; saturated at (1-b/2) L %.3g, (1-2b) L %.3g\n", L,
           c, twice, half, stays, back);
    ENSURE(twice > 0 && half < 0);
    ENSURE(stays < 0 && back > 0);
out:
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

/* A ball started exactly touching a floor (P = 0) while sliding at 1 m/s
 * and approaching at 1 mm/s, viscous friction (Iform 1, Fric 0.37): at no
 * normal force the limit is 0, and the viscous form starts saturated, as
 * at any close. Left unsaturated (the start at P = 0 skipped the mode's
 * decision that P > 0 and every close make), the whole damper force
 * C v_t braked the ball with no normal force (a sphere on an incline,
 * 175000063: 0.96 N at F_n = 0, its sliding stopped within 1.6 ms where
 * P = 1e-18 m let it slide). Until the ball rolls (at 0.079 s) it slides
 * on Coulomb's law: the friction impulse is Fric times the normal one,
 * which the vertical momentum gives, m (v_z(t) - v_z(0) + g t), whatever
 * the law's ringing (the ball rebounds by 1e-11 m each period). */
static void test_viscous_friction_starts_saturated_when_touching(void)
{
    char deck[2048];
    snprintf(deck, sizeof deck, "%s", viscous_band_deck);
    char *run = strstr(deck, "/RUN\n");
    if (run)
        snprintf(run, sizeof deck - (size_t)(run - deck), "/INIVEL/TRA/1\nv\n1,0,-0.001,1,0\n/RUN\n0.02,0.001\n/END\n");
    rc_model *m = TU_COMPILE_OK(deck, "viscous_touch_slide.rad");
    if (!m) return;
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double));
    ENSURE(d && y && run);
    if (!d || !y) goto out;
    rc_initial_state(m, y);
    rc_modes_init(m, d, 0.0, y);
    ENSURE(d->inter_mode[0] == RC_MODE_CLOSED && d->inter_slip[0] == 1);
    rc_error e;
    rc_session *ses = NULL;
    ENSURE(rc_session_open(m, NULL, &ses, &e) == RC_OK);
    if (!ses) goto out;
    ENSURE(rc_run_until(ses, 0.02, &e) == RC_OK);
    const double *ys = rc_session_state(ses);
    const double vx = ys ? ys[m->body_yadr[0] + 7] : NAN, vz = ys ? ys[m->body_yadr[0] + 9] : NAN;
    const double want = 1.0 - 0.37 * (vz + 1e-3 + 9.81 * 0.02);
    printf("    started saturated: %d; v_x at 0.02 s %.9f m/s, Coulomb sliding %.9f m/s\n", d->inter_slip[0], vx, want);
    ENSURE(fabs(vx - want) < 1e-7);
    rc_session_close(ses, NULL, &e);
out:
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

/* Model m's data (*d) and initial state (malloc'd; NULL, and *d NULL or
 * to free, when out of memory). */
static double *initial_state_of(const rc_model *m, rc_data **d)
{
    *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double));
    ENSURE(*d && y);
    if (!*d || !y) {
        free(y);
        return NULL;
    }
    rc_initial_state(m, y);
    return y;
}

/* Body 1 of m (started on the top of a table whose edge is the line x =
 * 0.5 m, z = 0, sliding off it at v0 = 0.3 m/s without friction) leaves the
 * edge where its centre, on the circle of radius R about the edge, leaves
 * a particle: cos(theta*) = (v0^2 / (g R) + 2) / 3. Run to the end, then
 * again to the first separation for the state there; frees m. */
/* Run m to t_end (0: the deck's end time) and body 1's 13 states there. */
static rc_status run_body_state(rc_model *m, double t_end, double b[13])
{
    double y[64];
    rc_error e;
    rc_run_options o;
    rc_stats st;
    memset(&o, 0, sizeof o);
    o.y_end = y;
    o.t_end_override = t_end;
    rc_status s = rc_run(m, &o, &st, &e);
    if (s == RC_OK) s = rc_model_body_state(m, y, 1, b, &e);
    return s;
}

static void leaves_edge_at_closed_form(rc_model *m, const char *what)
{
    tu_evlog ev;
    rc_status s = tu_run_evlog(m, &ev, NULL);
    ENSURE(s == RC_OK);
    double tsep = NAN;
    for (int k = 0; k < ev.n && k < TU_MAXEV; k++)
        if (!strcmp(ev.kind[k], "contact_separate") || !strcmp(ev.kind[k], "contact_open")) {
            tsep = ev.t[k];
            break;
        }
    ENSURE(isfinite(tsep));
    if (isfinite(tsep)) {
        double b[13];
        ENSURE(run_body_state(m, tsep, b) == RC_OK);
        const double dx = b[0] - 0.5, dz = b[2], rr = hypot(dx, dz), v0 = 0.3, g = 9.81;
        const double want = (v0 * v0 / (g * rr) + 2.0) / 3.0;
        printf("    the %s leaves the edge at t = %.6f s, cos(theta) = %.6f (closed form %.6f), |c - edge| %.9f m\n",
               what, tsep, dz / rr, want, rr);
        ENSURE(fabs(dz / rr - want) < 2e-3);
    }
    rc_model_free(m);
}

/* A ball over the edge of a box: the edge is rounded by the geometry (the
 * distance to the solid box), so a ball sliding off a table pivots about
 * the edge and leaves it where a particle on a circle of radius R does,
 * cos(theta*) = (v0^2 / (g R) + 2) / 3 from the top at speed v0 (no
 * friction: the spin plays no part). Before, the top face's infinite plane
 * held it up beyond the edge until its centre reached the bisector, and the
 * contact then jumped to the side face. The distance and the normal at an
 * edge and a corner against the closed forms; the Jacobian there against
 * central differences. */
static const char *ball_box_edge_deck =
    "/BEGIN\nball sliding off the edge of a table\n      2022         0\n"
    "                  kg                   m                   s\n"
    "                  kg                   m                   s\n"
    "/NODE\n1,0.45,0,0.05\n"
    "/RBODY/1\nball\n1,,,,1.0\n0.001,0.001,0.001\n0,0,0\n"
    "/GRNOD/NODE/1\nball\n1\n"
    "/SURF/ELLIPS/1\nball\n0,2,1\n0.45,0,0.05\n0.05,0.05,0.05\n"
    "/SURF/BOX/2\ntable\n0\n0,0,-0.5\n0.5,0.5,0.5\n1,0,0\n0,1,0\n"
    "/FUNCT/1\nlinear\n0,0\n1,10000000\n"
    "/INTER/TYPE6/1\nball on table\n1,2\n\n\n1,0\n\n2000\n"
    "/GRAV/1\ng\n0,Z,0,0,1,,1,-9.81\n"
    "/INIVEL/TRA/1\nv0\n0.3,0,0,1,0\n"
    "/RUN\n0.6,0.01\n/END\n";

static void test_ball_pivots_over_a_box_edge(void)
{
    rc_model *m = TU_COMPILE_OK(ball_box_edge_deck, "ball_box_edge.rad");
    if (!m) return;
    ENSURE(m->inter_pair[0] == RC_PAIR_SPHERE_BOX);
    /* geometry at an edge (x and z beyond the half-sizes) and a corner */
    {
        rc_data *d = NULL;
        double *y = initial_state_of(m, &d);
        if (y) {
            double *yb = y + m->body_yadr[0], y0[3];
            const double x0[3] = {0.45, 0.0, 0.05}; /* the state is about the model's origin */
            for (int k = 0; k < 3; k++) y0[k] = yb[k];
            const double cs[2][3] = {{0.53, 0.1, 0.04}, {0.53, 0.52, 0.035}};
            for (int c = 0; c < 2; c++) {
                for (int k = 0; k < 3; k++) yb[k] = y0[k] + cs[c][k] - x0[k];
                yb[7] = 0.2;
                yb[9] = -0.1;
                rc_inter_report r;
                rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
                const double w[3] = {0.03, c ? 0.02 : 0.0, cs[c][2]}, nw = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
                printf("    %s: P %.15g m (closed form %.15g), normal (%.6f %.6f %.6f)\n", c ? "corner" : "edge", r.p,
                       0.05 - nw, r.normal[0], r.normal[1], r.normal[2]);
                ENSURE_NEAR(r.p, 0.05 - nw, 0, 1e-15);
                for (int k = 0; k < 3; k++) ENSURE_NEAR(r.normal[k], -w[k] / nw, 0, 1e-15);
                ENSURE_NEAR(r.vn, -(0.2 * w[0] - 0.1 * w[2]) / nw, 0, 1e-15);
                d->inter_mode[0] = RC_MODE_CLOSED;
                int bad = 0;
                int outside = 0;
                const double err = tu_jac_fd_error(m, d, 0.0, y, 1, &bad, &outside);
                printf("    %s: Jacobian against central differences %.3g (bad %d)\n", c ? "corner" : "edge", err, bad);
                ENSURE(bad == 0);
            }
        }
        free(y);
        rc_data_free(d);
    }
    leaves_edge_at_closed_form(m, "ball");
}

/* A roller (a cylinder lying along a table's edge) rolling over the edge
 * pivots about it: the edge is rounded for a cylinder whose axis runs
 * along it, as for a ball. No friction: its centre moves on the circle of
 * radius R about the edge and leaves it at cos(theta*) = (v0^2 / (g R) +
 * 2) / 3 (the spin plays no part). Before, the top face's infinite plane
 * held it up beyond the edge and the run stopped on its own check. The
 * distance and the normal beyond the edge against the closed forms, the
 * normal's rate against central differences of the normal
 * (roller_edge_normal_rate), the Jacobian there against central
 * differences; a roller lying across the edge
 * (axis perpendicular to it) is still held by the face's plane, which
 * the run's check reports. */
#define ROLLER_BOX_EDGE_DECK(fric)                                                                                     \
    "/BEGIN\nroller rolling off the edge of a table\n      2022         0\n"                                           \
    "                  kg                   m                   s\n"                                                  \
    "                  kg                   m                   s\n"                                                  \
    "/NODE\n1,0.45,0,0.05\n"                                                                                         \
    "/RBODY/1\nroller\n1,,,,1.0\n0.001,0.001,0.001\n0,0,0\n"                                                        \
    "/GRNOD/NODE/1\nroller\n1\n"                                                                                    \
    "/SURF/CYL/1\nroller\n1,0,0\n0.45,0,0.05\n0,1,0\n0.05,0.2\n"                                                   \
    "/SURF/BOX/2\ntable\n0\n0,0,-0.5\n0.5,0.5,0.5\n1,0,0\n0,1,0\n"                                                \
    "/FUNCT/1\nlinear\n0,0\n1,10000000\n"                                                                          \
    "/INTER/TYPE6/1\nroller on table\n1,2\n" fric "\n\n1,0\n\n2000\n"                                                \
    "/GRAV/1\ng\n0,Z,0,0,1,,1,-9.81\n"                                                                             \
    "/INIVEL/TRA/1\nv0\n0.3,0,0,1,0\n"                                                                             \
    "/RUN\n0.6,0.01\n/END\n"
static const char *roller_box_edge_deck = ROLLER_BOX_EDGE_DECK("");
/* the same with TYPE6 friction (its tangential force a state that turns with the normal) */
static const char *roller_box_edge_fric_deck = ROLLER_BOX_EDGE_DECK(",0.3");

/* The normal's rate beyond the edge, read through the friction state's
 * rate: a tangential force F held in the state turns with the normal, so
 * the normal part of its rate is -F.dn/dt; against central differences of
 * the normal along the motion (the roller translating, the box fixed). */
static void roller_edge_normal_rate(void)
{
    rc_model *m = TU_COMPILE_OK(roller_box_edge_fric_deck, "roller_box_edge_fric.rad");
    if (!m) return;
    const int ti = m->inter_fr[0].tidx;
    ENSURE(m->inter_fr[0].kind != RC_FK_NONE && ti >= 0);
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double)), *yd = calloc((size_t)m->ny, sizeof(double));
    ENSURE(d && y && yd);
    if (d && y && yd && ti >= 0) {
        rc_initial_state(m, y);
        double *yb = y + m->body_yadr[0];
        const double x0[3] = {0.45, 0.0, 0.05}, c[3] = {0.53, 0.1, 0.039}, v[3] = {0.2, 0.0, -0.1};
        for (int k = 0; k < 3; k++) {
            yb[k] += c[k] - x0[k];
            yb[7 + k] = v[k];
        }
        rc_inter_report r, rp, rm;
        rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
        /* F: 2 N along the tangent of the plane of the motion */
        const double F[3] = {2.0 * r.normal[2], 0.0, -2.0 * r.normal[0]};
        double *fs = y + m->inter_eadr[0] + ti;
        for (int k = 0; k < 3; k++) fs[k] = F[k];
        d->inter_mode[0] = RC_MODE_CLOSED;
        d->inter_slip[0] = 0;
        ENSURE(rc_assemble_rhs(m, d, 0.0, y, yd) == 0);
        const double *fd = yd + m->inter_eadr[0] + ti;
        const double got = -(fd[0] * r.normal[0] + fd[1] * r.normal[1] + fd[2] * r.normal[2]);
        const double h = 1e-6;
        for (int k = 0; k < 3; k++) yb[k] += h * v[k];
        rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &rp);
        for (int k = 0; k < 3; k++) yb[k] -= 2.0 * h * v[k];
        rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &rm);
        double want = 0.0;
        for (int k = 0; k < 3; k++) want += F[k] * (rp.normal[k] - rm.normal[k]) / (2.0 * h);
        printf("    beyond the edge: F.dn/dt %.12g (central differences of the normal %.12g)\n", got, want);
        ENSURE(fabs(want) > 1.0);
        ENSURE_NEAR(got, want, 1e-7, 0);
    }
    free(y);
    free(yd);
    rc_data_free(d);
    rc_model_free(m);
}

/* A cylinder lying level on a plane (mid-length contact, Icont 0, the
 * default): before, its contact point was the lowest point of the middle
 * section alone, which a tilt moves towards the raised end, so the level
 * was an unstable equilibrium (growth rate sqrt(m g r / I), 11 /s here: a
 * cylinder on a floor tipped itself on end, 135000082). Now the load passes
 * to the lower end over the end band, as a line contact's does: a pitch
 * of 0.05 rad/s rings about the level. The depth: the middle's exactly
 * when level, the lower rim's less 3 eps / 16 beyond the band; the
 * Jacobian inside the band against central differences. */
#define LYING_CYL_DECK(w0, k, L)                                                                                            \
    "/BEGIN\ncylinder lying on a floor\n      2022         0\n"                                                       \
    "                  kg                   m                   s\n"                                                  \
    "                  kg                   m                   s\n"                                                  \
    "/NODE\n1,0,0,0.049\n"                                                                                           \
    "/RBODY/1\ncylinder\n1,,,,1.0\n0.004,0.00125,0.004\n0,0,0\n"                                                    \
    "/GRNOD/NODE/1\ncylinder\n1\n"                                                                                  \
    "/SURF/CYL/1\ncylinder\n1,0,0\n0,0,0.049\n0,1,0\n0.05," L "\n"                                                 \
    "/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n"                                                                         \
    "/FUNCT/1\nlinear\n0,0\n1," k "\n"                                                                           \
    "/INTER/TYPE6/1\ncylinder on floor\n1,2\n\n\n1,0\n\n20\n"                                                      \
    "/GRAV/1\ng\n0,Z,0,0,1,,1,-9.81\n"                                                                             \
    "/INIVEL/ROT/1\npitch\n" w0 ",0,0,1,0\n"                                                                       \
    "/RUN\n1.0,0.01\n/END\n"

static void test_cylinder_level_is_stable(void)
{
    rc_model *m = TU_COMPILE_OK(LYING_CYL_DECK("0.05", "10000", "0.2"), "lying_cylinder.rad");
    if (!m) return;
    ENSURE(m->inter_pair[0] == RC_PAIR_CYL_PLANE);
    const double *ext = m->surf_ext + RC_SURF_NEXT * m->inter_sa[0];
    const double h = ext[0], eps = ext[3], r = 0.05;
    printf("    half-length %.3g m, end band %.3g m (penetration scale %.3g m)\n", h, eps, m->inter_pscale[0]);
    ENSURE(ext[2] == 0.0 && eps > 0 && h > 0);
    rc_data *d = NULL;
    double *y = initial_state_of(m, &d);
    if (y) {
        double *yb = y + m->body_yadr[0];
        rc_inter_report rep;
        /* level: the middle's depth exactly */
        yb[2] = 0.049 - m->origin[2];
        rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &rep);
        printf("    level: P %.15g m (the middle's 0.001)\n", rep.p);
        ENSURE_NEAR(rep.p, 1e-3, 0, 1e-15);
        /* tilted by 0.01 rad about x, beyond the band: the lower rim's depth less 3 eps / 16 */
        const double a = 0.01;
        yb[3] = cos(0.5 * a);
        yb[4] = sin(0.5 * a);
        rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &rep);
        const double rim = -(0.049 - r * cos(a) - h * sin(a)) - 0.1875 * eps;
        printf("    tilted 0.01 rad: P %.15g m (the lower rim's less 3 eps/16: %.15g)\n", rep.p, rim);
        ENSURE_NEAR(rep.p, rim, 0, 1e-15);
    }
    free(y);
    rc_data_free(d);
    /* inside the band: the Jacobian, on a softer law and a shorter
     * cylinder (its band a tilt of 1.2e-3 rad, 600 of the differences'
     * steps of 2e-6 rad, whose truncation error stays below 1e-6) */
    rc_model *ms = TU_COMPILE_OK(LYING_CYL_DECK("0.05", "1000", "0.02"), "lying_cylinder_soft.rad");
    d = NULL;
    y = ms ? initial_state_of(ms, &d) : NULL;
    if (y) {
        double *yb = y + ms->body_yadr[0];
        yb[2] = 0.049 - ms->origin[2];
        yb[3] = cos(0.5 * 1e-3);
        yb[4] = sin(0.5 * 1e-3);
        d->inter_mode[0] = RC_MODE_CLOSED;
        int bad = 0, outside = 0;
        const double err = tu_jac_fd_error(ms, d, 0.0, y, 1, &bad, &outside);
        printf("    inside the band (tilt 1e-3 rad, band %.3g m): Jacobian against central differences %.3g (bad %d)\n",
               ms->surf_ext[RC_SURF_NEXT * ms->inter_sa[0] + 3], err, bad);
        ENSURE(bad == 0);
    }
    free(y);
    rc_data_free(d);
    rc_model_free(ms);
    /* the run: a pitch of 0.05 rad/s rings about the level */
    double b[13];
    const rc_status s = run_body_state(m, 0.0, b);
    ENSURE(s == RC_OK);
    if (s == RC_OK) {
        /* the axis' height gradient: 2 (q_y q_z + q_w q_x) is e_z of R (0, 1, 0) */
        const double ez = 2.0 * (b[5] * b[6] + b[3] * b[4]);
        printf("    after 1 s: tilt %.3g rad, centre at z = %.9f m, pitch rate %.3g rad/s\n", asin(ez), b[2], b[10]);
        ENSURE(fabs(ez) < 1e-3);
        ENSURE(fabs(b[2] - 0.049) < 1e-3);
    }
    rc_model_free(m);
}

static void test_roller_pivots_over_a_box_edge(void)
{
    rc_model *m = TU_COMPILE_OK(roller_box_edge_deck, "roller_box_edge.rad");
    if (!m) return;
    ENSURE(m->inter_pair[0] == RC_PAIR_CYL_BOX);
    rc_data *d = NULL;
    double *y = initial_state_of(m, &d);
    if (y) {
        /* the centre beyond the edge x = 0.5, z = 0 (positions about the
         * model's origin): w = (0.03, 0, 0.039) */
        double *yb = y + m->body_yadr[0];
        const double c[3] = {0.53, 0.1, 0.039}, border[3] = {0.5, 0.0, 0.049};
        {
            for (int k = 0; k < 3; k++) yb[k] = c[k] - m->origin[k];
            yb[7] = 0.2;
            yb[9] = -0.1;
            rc_inter_report r;
            rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
            const double w[3] = {0.03, 0.0, 0.039}, nw = sqrt(w[0] * w[0] + w[2] * w[2]);
            printf("    beyond the edge: P %.15g m (closed form %.15g), normal (%.6f %.6f %.6f), vn %.15g\n", r.p,
                   0.05 - nw, r.normal[0], r.normal[1], r.normal[2], r.vn);
            ENSURE_NEAR(r.p, 0.05 - nw, 0, 1e-15);
            for (int k = 0; k < 3; k++) ENSURE_NEAR(r.normal[k], -w[k] / nw, 0, 1e-15);
            ENSURE_NEAR(r.vn, -(0.2 * w[0] - 0.1 * w[2]) / nw, 0, 1e-15);
            /* at the border (the centre over the edge, x = 0.5): the face's
             * plane and the edge's give the same P */
            for (int k = 0; k < 3; k++) yb[k] = border[k] - m->origin[k];
            rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
            ENSURE_NEAR(r.p, 1e-3, 0, 1e-15);
            yb[0] = nextafter(yb[0], INFINITY);
            rc_inter_report r2;
            rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r2);
            ENSURE_NEAR(r2.p, 1e-3, 0, 1e-15);
            ENSURE_NEAR(r2.normal[2], -1.0, 0, 1e-12);
            for (int k = 0; k < 3; k++) yb[k] = c[k] - m->origin[k];
            /* the Jacobian with the axis tilted by 1e-4 rad out of the
             * edge's plane (about e x N): beyond the end band (a tilt of
             * 1.25e-6 rad here), whose curvature the differences' steps
             * (2e-6 rad of the quaternion) straddle; the band's own
             * Jacobian: test_cylinder_level_is_stable */
            const double a = 1e-4, u[3] = {w[2] / nw, 0.0, -w[0] / nw}; /* e x N, e = (0, 1, 0) */
            yb[3] = cos(0.5 * a);
            yb[4] = sin(0.5 * a) * u[0];
            yb[5] = 0.0;
            yb[6] = sin(0.5 * a) * u[2];
            d->inter_mode[0] = RC_MODE_CLOSED;
            int bad = 0, outside = 0;
            const double err = tu_jac_fd_error(m, d, 0.0, y, 1, &bad, &outside);
            printf("    beyond the edge: Jacobian against central differences %.3g (bad %d)\n", err, bad);
            ENSURE(bad == 0);
            yb[3] = 1.0;
            yb[4] = yb[5] = yb[6] = 0.0;
        }
    }
    free(y);
    rc_data_free(d);
    roller_edge_normal_rate();
    leaves_edge_at_closed_form(m, "roller");
}

/* A law's state stiffness beyond what the coordinates resolve is refused:
 * a ball striking a wall whose Stiff line and stick spring (2.21e18 N/m)
 * move the force by 3e3 N over the position tolerance the coordinates
 * allow (64 roundings) against a force scale of 151 N (a fuzzer scene: its
 * friction state was rounding noise); the message gives the largest
 * resolvable Stiff, F_s over the 64 roundings. */
static void test_state_stiffness_beyond_resolution_refused(void)
{
    const char *path = "fuzz/physics/regressions/ramp_wall_stale_jacobian_rising_limit.rad";
    rc_model *m = NULL;
    rc_error e;
    const rc_status st = tu_load_compile(path, &m, &e);
    printf("    %s\n", st ? e.msg : "(compiled)");
    ENSURE(st == RC_EINPUT);
    ENSURE(strstr(e.msg, "too stiff for double precision") != NULL);
    ENSURE(strstr(e.msg, "card /INTER/TYPE6/2") != NULL && strstr(e.msg, "expected Stiff below") != NULL);
    rc_model_free(m);
    /* the largest resolvable value it gives is F_s over the 64 roundings */
    const char *pf = strstr(e.msg, "(64 roundings, "), *pfs = strstr(e.msg, "force scale F_s = "),
               *pk = strstr(e.msg, "expected Stiff below ");
    ENSURE(pf && pfs && pk);
    if (pf && pfs && pk) {
        const double dist = atof(pf + strlen("(64 roundings, ")), fs = atof(pfs + strlen("force scale F_s = ")),
                     kmax = atof(pk + strlen("expected Stiff below "));
        printf("    64 roundings %.3g m, F_s %.3g N, largest Stiff %.3g N/m (F_s / 64 roundings %.3g)\n", dist, fs, kmax,
               fs / dist);
        ENSURE(fabs(kmax - fs / dist) <= 0.01 * kmax);
        ENSURE(kmax < 2.213071818637e18);
    }
}

/* A contact point's landing band lasts while the contact does. A box
 * sliding on a fixed box (a fuzzer scene): an edge pair landed at a depth at
 * the rounding of 0 (2e-18 m, share 3e-11) and slipped at once; that very
 * slip event cleared its landing band, the rounding landed it again, and
 * land/slip repeated 200 times within 3e-10 s (Zeno at 3.2 ms). */
static void test_landing_band_kept_through_flips(void)
{
    regression_runs_without_zeno("fuzz/physics/regressions/box_box_edge_pair_relands_at_rounding_zeno.rad",
                                 "box sliding on a box, edge pairs with friction");
}

/* ---- an elastic law with a damper: hysteresis kept at its releases ---- */
/* A 1 kg ball dropped at 1 m/s onto a floor, linear law k = 1e6 N/m
 * (Iform 0) with Visc 400 N s/m (zeta 0.2), or Visc 0 and the same damping
 * as TYPE6's damping curve (fct_IDdv, Fscalev 1): on each rebound the
 * damper pulls and the contact releases at P_r > 0, losing k P_r^2 / 2.
 * The hysteresis dissipation is exactly the sum of these over the releases
 * the events record (before: the normal work less the stored energy, whose
 * integration error ran backwards by up to 1e-7 J on damped cradles; with
 * the damping curve, 0: the law was taken for an elastic one), and never
 * decreases. */
#define RELEASE_DECK(FUNCT2, LINE6) \
    "/BEGIN\nball dropped on a damped elastic floor\n      2022         0\n" \
    "                  kg                   m                   s\n" \
    "                  kg                   m                   s\n" \
    "/FUNCT/1\nlinear\n0,0\n1,1000000\n" FUNCT2 BALL_ON_FLOOR "/GRAV/1\ng\n0,Z,0,0,1,,1,-9.81\n" \
    "/INIVEL/TRA/1\nv\n0,0,-1,1,0\n" \
    "/INTER/TYPE6/1\nball on floor\n1,2\n\n\n1,0\n\n" LINE6 "\n" \
    "/RUN\n0.3,0.001\n/END\n"
static const char *release_decks[2] = {RELEASE_DECK("", "400"),
                                       RELEASE_DECK("/FUNCT/2\ndamping\n-10,-4000\n10,4000\n", "0,2,0,1")};

static void release_ledger_kept(const rc_model *m) { ENSURE(rc_inter_release_ledger(m, 0)); }

static void release_ledger_check(const char *deck, const char *what)
{
    char out[512];
    if (run_to_file(deck, "release.rad", out, release_ledger_kept, NULL)) return;
    int ncid, id, dim;
    size_t nt = 0, nev = 0;
    ENSURE(nc_open(out, NC_NOWRITE, &ncid) == NC_NOERR);
    ENSURE(nc_inq_dimid(ncid, "time", &dim) == NC_NOERR && nc_inq_dimlen(ncid, dim, &nt) == NC_NOERR);
    ENSURE(nc_inq_dimid(ncid, "event", &dim) == NC_NOERR && nc_inq_dimlen(ncid, dim, &nev) == NC_NOERR);
    double *pen = calloc(nev + 1, sizeof(double));
    char **kind = calloc(nev + 1, sizeof(char *));
    double expect = 0.0, last = NAN;
    int nrel = 0;
    if (pen && kind && nev > 0 && nc_inq_varid(ncid, "event_penetration", &id) == NC_NOERR &&
        nc_get_var_double(ncid, id, pen) == NC_NOERR && nc_inq_varid(ncid, "event_kind", &id) == NC_NOERR &&
        nc_get_var_string(ncid, id, kind) == NC_NOERR) {
        for (size_t k = 0; k < nev; k++)
            if (strcmp(kind[k], "contact_open") == 0 && pen[k] > 0) { /* released at P > 0 */
                expect += 0.5 * 1e6 * pen[k] * pen[k];
                nrel++;
            }
        nc_free_string(nev, kind);
    }
    const double drop = ledger_drop(ncid, "energy_hysteresis", nt, &last);
    printf("    %s: %d releases at P > 0: sum k P_r^2 / 2 = %.9e J, energy_hysteresis at the end %.9e J (rel. %.1e), "
           "largest drop %.1e J\n",
           what, nrel, expect, last, fabs(last - expect) / expect, drop);
    ENSURE(nrel >= 2);
    ENSURE(fabs(last - expect) <= 1e-9 * expect);
    ENSURE(drop == 0.0);
    free(pen);
    free(kind);
    nc_close(ncid);
}

static void test_elastic_damped_release_ledger(void)
{
    for (int k = 0; k < 2; k++) release_ledger_check(release_decks[k], k ? "damping curve" : "Visc");
}

void suite_passive(void);
void suite_passive(void)
{
    RUN_TEST(test_touching_roots_wait_on_their_side);
    RUN_TEST(test_cradle_off_grid_passes_momentum);
    RUN_TEST(test_box_sliding_from_touch_stays_on_the_floor);
    RUN_TEST(test_ball_on_ramp_friction_never_pushes);
    RUN_TEST(test_multi_point_contacts_are_passive);
    RUN_TEST(test_friction_pressure_area_needed);
    RUN_TEST(test_tolerances_above_the_coordinates_rounding);
    RUN_TEST(test_iform1_unloads_along_the_law);
    RUN_TEST(test_iform1_stored_energy_on_the_unload_path);
    RUN_TEST(test_iform1_dissipation_rate_on_the_load_curve);
    RUN_TEST(test_iform2_reversals_stay_on_the_stiff_line);
    RUN_TEST(test_ball_rolls_onto_incline);
    RUN_TEST(test_fric_turn_reload_stays_against_the_sliding);
    RUN_TEST(test_fric_turn_keeps_a_resolved_state);
    RUN_TEST(test_flat_landing_keeps_the_box_level);
    RUN_TEST(test_resting_box_rings_down);
    RUN_TEST(test_light_damper_chatter_held_at_order_2);
    RUN_TEST(test_slip_waits_for_a_falling_limit);
    RUN_TEST(test_corner_stick_tested_with_its_spring);
    RUN_TEST(test_viscous_reversal_root_waits_for_a_limit);
    RUN_TEST(test_viscous_saturation_needs_the_force_band);
    RUN_TEST(test_viscous_friction_starts_saturated_when_touching);
    RUN_TEST(test_ball_pivots_over_a_box_edge);
    RUN_TEST(test_roller_pivots_over_a_box_edge);
    RUN_TEST(test_cylinder_level_is_stable);
    RUN_TEST(test_state_stiffness_beyond_resolution_refused);
    RUN_TEST(test_landing_band_kept_through_flips);
    RUN_TEST(test_power_rdf_root_on_damping_rate);
    RUN_TEST(test_hysteresis_roots_wait_on_their_side);
    RUN_TEST(test_pe_no_recovery_at_zero_force);
    RUN_TEST(test_pe_recovery_continuous_in_its_payment);
    RUN_TEST(test_elastic_damped_release_ledger);
    RUN_TEST(test_box_sliding_start_at_every_rtol);
    RUN_TEST(test_contact_records_bounded);
    RUN_TEST(test_extra_records_bounded);
}
