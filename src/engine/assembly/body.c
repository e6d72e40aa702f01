/* Rigid bodies: state views, gravity (of the bodies and of the coupling
 * lines), initial state, the states that stay constant in any run (held
 * ones; the rotations at rest of bodies on which no moment can act).
 * Energies are in energy.c. */
#include <stdlib.h>
#include <string.h>

#include "model/coupling.h"
#include "model/imposed.h"
#include "model/joint.h"
#include "model/model.h"
#include "model/power.h"
#include "engine/assembly/assembly.h"

double rc_gravity_factor(const rc_model *m, double t)
{
    /* f(t / Ascale), 1 when no function is given; with a sensor's time on
     * Ts > 0 (grav_tstart): 0 for t <= Ts, then f((t - Ts) / Ascale) */
    if (m->grav_tstart > 0 && !(t > m->grav_tstart)) return 0.0;
    if (m->grav_sens >= 0) return 0.0; /* a sensor found in the run: on only in a run (rc_gravity_factor_run) */
    double f = 1.0, df;
    if (m->grav_table >= 0) rc_table_eval(&m->table[m->grav_table], (t - m->grav_tstart) / m->grav_ascale, &f, &df);
    return f;
}

double rc_gravity_factor_run(const rc_model *m, const rc_data *d, double t)
{
    /* at the sensor's time itself, once the run restarted there (the time
     * breakpoint, rc_data.t_bp): the right limit, f(0) */
    if (m->grav_sens >= 0) {
        /* a sensor found in the run: off until its event, then shifted by
         * its time on */
        const int s = m->grav_sens;
        if (!d->sens_rel[s]) return 0.0;
        double f = 1.0, df;
        if (m->grav_table >= 0)
            rc_table_eval(&m->table[m->grav_table], (t - d->sens_ton[s]) / m->grav_ascale, &f, &df);
        return f;
    }
    if (m->grav_tstart > 0 && t == m->grav_tstart && d->t_bp >= t) {
        double f = 1.0, df;
        if (m->grav_table >= 0) rc_table_eval(&m->table[m->grav_table], 0.0, &f, &df);
        return f;
    }
    return rc_gravity_factor(m, t);
}

void rc_gravity(const rc_model *m, int b, double t, double g[3])
{
    /* g(t) = vector * f(t / Ascale) */
    const double f = rc_gravity_factor(m, t);
    for (int k = 0; k < 3; k++) g[k] = m->body_grav[3 * b + k] * f;
}

void rc_cpl_gravity(const rc_model *m, double t, double g[3])
{
    const double f = rc_gravity_factor(m, t);
    for (int k = 0; k < 3; k++) g[k] = m->cpl->grav[k] * f;
}

void rc_initial_state(const rc_model *m, double *y)
{
    memset(y, 0, (size_t)m->ny * sizeof(double));
    for (int b = 0; b < m->nbody; b++)
        if (m->body_yadr[b] >= 0) memcpy(y + m->body_yadr[b], m->body_y0 + RC_NB * b, RC_NB * sizeof(double));
    rc_gravity_work_init(m, y);
}

void rc_gravity_work_init(const rc_model *m, double *y)
{
    /* time-varying gravity: its potential starts at -sum m g(0).x0 */
    if (m->gwork_adr >= 0) {
        y[m->gwork_adr] = 0.0;
        for (int b = 0; b < m->nbody; b++) {
            if (m->body_yadr[b] < 0) continue;
            double g[3];
            const double *x = y + m->body_yadr[b], *o = m->origin; /* in the deck's coordinates */
            rc_gravity(m, b, 0.0, g);
            y[m->gwork_adr] -= m->body_mass[b] * (g[0] * (x[0] + o[0]) + g[1] * (x[1] + o[1]) + g[2] * (x[2] + o[2]));
        }
    }
}

void rc_state_to_deck(const rc_model *m, double *y)
{
    for (int b = 0; b < m->nbody; b++)
        if (m->body_yadr[b] >= 0)
            for (int k = 0; k < 3; k++) y[m->body_yadr[b] + k] += m->origin[k];
}

/* May side `side` (0: a, 1: b) of interface i act on its body with a
 * moment about the body's centre of mass? No only when that side is a
 * sphere centred exactly on the centre of mass (the kernel takes its
 * normal force at the sphere's centre: geometry's act_a / act_b, and
 * apply_force then adds no moment) in a pair that acts through that
 * centre, and the interface has nothing tangential (no friction of any
 * kind, no exact stick, no contact points with their own states). */
static int side_moment_free(const rc_model *m, int i, int side)
{
    if (!rc_inter_frictionless(m, i) || m->inter_npt[i] != 0) return 0;
    const int s = side ? m->inter_sb[i] : m->inter_sa[i];
    if (m->surf_kind[s] != RC_SURF_SPHERE || !rc_surf_centred(m, s)) return 0;
    switch (m->inter_pair[i]) {
    case RC_PAIR_SPHERE_SPHERE: /* both centres */
        return 1;
    case RC_PAIR_SPHERE_PLANE:
    case RC_PAIR_SPHERE_BOX:
    case RC_PAIR_SPHERE_CYL: /* the sphere is a: its centre */
        return side == 0;
    default: /* several points, or not a sphere's side: in doubt a moment */
        return 0;
    }
}

void rc_moment_free_bodies(const rc_model *m, char *mf) { rc_moment_free_bodies_centred(m, 0, mf); }

/* The attachment point of end e (0, 1) of coupling k is the centre of
 * mass of its body, exactly, on a spring or a catenary. */
static int cpl_end_centred(const rc_couplings *cp, int k, int e)
{
    const double *s = (e ? cp->s2 : cp->s1) + 3 * k;
    /* a general spring (form 5) has moments of its own */
    return (cp->kind[k] == RC_CPL_SPRING || cp->kind[k] == RC_CPL_CATENARY) && cp->form[k] != RC_KEFF_GENE &&
           s[0] == 0.0 && s[1] == 0.0 &&
           s[2] == 0.0;
}

void rc_moment_free_bodies_centred(const rc_model *m, int centred, char *mf)
{
    for (int b = 0; b < m->nbody; b++) mf[b] = m->body_yadr[b] >= 0;
    /* imposed velocities: their reactions (a rotation's is a torque) */
    const rc_imposed *p = m->imp;
    for (int k = 0; p && k < p->nt && !centred; k++) mf[p->tbody[k]] = 0;
    for (int k = 0; p && k < p->nr; k++) mf[p->rbody[k]] = 0;
    /* couplings (springs, catenaries, contact couplings, joint stops) and
     * joints: forces at attachment points, moments */
    const rc_couplings *cp = m->cpl;
    for (int k = 0; cp && k < cp->n; k++) {
        if (cp->b1[k] >= 0 && !(centred && cpl_end_centred(cp, k, 0))) mf[cp->b1[k]] = 0;
        if (cp->b2[k] >= 0 && !(centred && cpl_end_centred(cp, k, 1))) mf[cp->b2[k]] = 0;
    }
    const rc_joints *jn = m->jnt;
    for (int k = 0; jn && k < jn->n; k++) {
        if (jn->ba[k] >= 0) mf[jn->ba[k]] = 0;
        if (jn->bb[k] >= 0) mf[jn->bb[k]] = 0;
    }
    /* interfaces: each side on a body must act through its centre */
    for (int i = 0; i < m->ninter; i++) {
        const int ba = m->inter_ba[i], bb = m->inter_bb[i];
        if (ba >= 0 && !side_moment_free(m, i, 0)) mf[ba] = 0;
        if (bb >= 0 && !side_moment_free(m, i, 1)) mf[bb] = 0;
    }
}

int rc_constant_states(const rc_model *m, const double *y0, const char *written, char *cst)
{
    memset(cst, 0, (size_t)m->ny);
    int n = 0;
    /* bodies on which no moment can act (out of memory: none, which only
     * keeps more states) */
    char *mf = malloc((size_t)m->nbody + 1);
    if (mf) rc_moment_free_bodies(m, mf);
#define RC_W(k) (written && written[k])
    /* an imposed velocity's row has its own rate (a held component cannot
     * be imposed: the compiler refuses it; checked again here) */
    const rc_imposed *p = m->imp;
    for (int b = 0; b < m->nbody; b++) {
        const int a = m->body_yadr[b];
        if (a < 0) continue;
        int held[6];
        for (int j = 0; j < 6; j++) held[j] = m->body_dofmask[6 * b + j];
        for (int k = 0; p && k < p->nt; k++)
            if (p->trow[k] >= a + 7 && p->trow[k] < a + 10) held[p->trow[k] - a - 7] = 0;
        for (int k = 0; p && k < p->nr; k++)
            if (p->rbody[k] == b) held[3] = held[4] = held[5] = 0;
        /* translations: v_j held; x_j also when v_j starts at exactly 0 */
        for (int j = 0; j < 3; j++) {
            if (!held[j] || !m->row_held[a + 7 + j] || RC_W(a + 7 + j)) continue;
            cst[a + 7 + j] = 1;
            n++;
            if (y0[a + 7 + j] == 0.0 && !RC_W(a + j)) {
                cst[a + j] = 1;
                n++;
            }
        }
        /* rotations: all held, omega held; q also when omega starts at
         * exactly 0 (q' = q (0, omega) / 2 = 0); all but one held (a body
         * turning about one axis): its held rows stay integrated (rate 0) */
        int rot = 1, still = 1;
        for (int j = 3; j < 6; j++) {
            rot &= held[j] && m->row_held[a + 7 + j] && !RC_W(a + 7 + j);
            still &= y0[a + 7 + j] == 0.0;
        }
        if (!rot) {
            /* rotations free, but no moment about the centre of mass can
             * ever act and omega starts at exactly 0: omega' = J^-1 (0 -
             * omega x J omega) = 0 and q' = 0 at all times, both constant */
            if (!mf || !mf[b] || !still) continue;
            for (int k = 3; k < 7; k++) still &= !RC_W(a + k);
            for (int j = 3; j < 6; j++) still &= !RC_W(a + 7 + j);
            if (!still) continue;
            for (int k = 3; k < 7; k++) cst[a + k] = 1;
            for (int j = 3; j < 6; j++) cst[a + 7 + j] = 1;
            n += 7;
            continue;
        }
        for (int j = 3; j < 6; j++) cst[a + 7 + j] = 1;
        n += 3;
        for (int k = 3; k < 7; k++) still &= !RC_W(a + k);
        if (!still) continue;
        for (int k = 3; k < 7; k++) cst[a + k] = 1;
        n += 4;
    }
#undef RC_W
    free(mf);
    return n;
}
