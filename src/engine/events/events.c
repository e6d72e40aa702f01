/*
 * Run data and discrete modes. Modes change only here, between solver calls:
 * at the start of a run and at located events. Some transitions also reset a
 * history state (F_h synchronised onto the curve it leaves or joins, the
 * Inacti offset at zero); the integrator then restarts from the new state.
 * docs/theory.md section 5 lists every transition.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "model/coupling.h"
#include "model/coupling_contact.h"
#include "engine/assembly/bounds.h"
#include "engine/events/events.h"
#include "engine/constraints/stick.h"
#include "model/power.h"
#include "model/segsurf.h"
#include "engine/assembly/assembly.h"
#include "engine/constraints/cset.h"

/* Touch band: RC_TOUCH_ULPS ulps of the coordinates (model.h), at least
 * RC_TOUCH_REL of the penetration scale (docs/theory.md 5.1) [-]. */
#define RC_TOUCH_REL 1e-9
/* An open contact's wait past P = 0 (open_wait): at most RC_WAIT_PFRAC p_s,
 * at least RC_WAIT_ULPS roundings of its coordinates [-] */
#define RC_WAIT_PFRAC 0.5
#define RC_WAIT_ULPS 16.0

/* Whether the close of interface i caps the BDF order of the restart after
 * it (d->multi_closed, cvode.c; docs/theory.md 7.7): a contact of several
 * points whose law damps. Its damper acts on the shared rate and leaves the
 * stiff rocking of a body landing flat on its corners undamped, a mode that
 * orders 4 and 5 amplify from the coordinates' rounding. An undamped contact
 * (elastic, or dissipating by hysteresis only) keeps the deck's order: every
 * one of its resolved vibrations is undamped, and order 3's error on them
 * adds energy at every step (its leading term has the growing sign, where
 * orders 2 and 5 lose energy): a meshed box bouncing elastically on a
 * meshed floor gained 1e-7 of its energy scale at rtol 1e-10, at 3.4 times
 * the steps, with the cap. */
static int caps_order(const rc_model *m, int i)
{
    return rc_pair_multi(m->inter_pair[i]) && !rc_inter_undamped(m, i);
}

/* Own state k of interface i (NULL when absent). */
static double *own(const rc_model *m, int i, int idx, double *y)
{
    return idx >= 0 ? y + m->inter_eadr[i] + idx : NULL;
}

static void set_state(double *s, double v, int *changed)
{
    if (s && *s != v) {
        *s = v;
        *changed = 1;
    }
}

static void report(const rc_model *m, const rc_data *d, int i, double t, const double *y, rc_inter_report *r)
{
    rc_inter_report_eval_d(m, d, i, t, y, r);
}

/* Friction starts afresh (sticking, no force) whenever the contact closes
 * and is dropped whenever it stops pushing. */
static void reset_friction(const rc_model *m, rc_data *d, int i, double *y, int *changed)
{
    d->inter_slip[i] = 0;
    const rc_fric *fr = &m->inter_fr[i];
    for (int k = 0; k < 3; k++) {
        set_state(own(m, i, fr->tidx >= 0 ? fr->tidx + k : -1, y), 0.0, changed);
        set_state(own(m, i, fr->fidx >= 0 ? fr->fidx + k : -1, y), 0.0, changed);
    }
    /* friction per contact point: every point sticks afresh */
    for (int j = 0; j < m->inter_npt[i]; j++) {
        d->pt_slip[m->inter_pbase[i] + j] = 0;
        for (int k = 0; k < m->inter_pst[i]; k++) set_state(own(m, i, m->inter_ns[i] + m->inter_pst[i] * j + k, y), 0.0, changed);
    }
}

/* |v| of a 3-vector. */
static double norm3(const double *v)
{
    return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

/* A friction state turned to magnitude mag along sgn dir (sgn -1: against
 * a sliding velocity dir) without storing or releasing energy; 0 (and the
 * state as it was) where dir or mag gives no direction. */
static int turn_state(double *ft, double mag, const double *dir, double sgn, int *changed)
{
    const double nd = norm3(dir);
    if (!(nd > 0) || !(mag > 0) || !isfinite(nd)) return 0;
    for (int k = 0; k < 3; k++) set_state(ft + k, sgn * mag * dir[k] / nd, changed);
    return 1;
}

/* A friction reset (stick -> slip, slip -> stick) never stores tangential
 * energy |F_t|^2 / (2 K_t) that no work put there: the new state ft keeps
 * its direction with at most the magnitude the state had before in the
 * tangent plane, where its energy is (old: the report's ftan, a point's
 * RC_PT_OUT value; a state keeps a part along the normal where the normal
 * jumped, a box's node whose nearest face changed), or
 * the slip band fb (docs/theory.md 3.5). A slipping state (slip = 1) also
 * has at least the magnitude fb, so that it keeps a direction that turns at
 * a finite rate (K_t |v_t| / |F_t|); a state without direction is left as
 * it is. So a contact that closes sliding slides at the limit with an
 * unloaded spring, and a contact that sticks after its limit grew keeps the
 * force its spring had. */
static void cap_state(double *ft, double old, double fb, int slip, int *changed)
{
    const double nf = norm3(ft), cap = fmax(old, fb);
    if (!(nf > 0) || !isfinite(nf)) return;
    double to = fmin(nf, cap);
    if (slip) to = fmax(to, fb);
    if (to == nf) return;
    for (int k = 0; k < 3; k++) ft[k] *= to / nf;
    *changed = 1;
}

/* Friction per contact point of interface i: the points whose slip roots
 * crossed flip (roots: the interface's point roots; NULL: those sticking
 * with a positive root, after a mode change). From stick to slip a point's
 * state takes the applied force (spring and stick damper), then that
 * direction on the limit; from slip to stick, the force where it is (on the
 * limit). Three evaluations of the interface, whatever the number of points
 * flipped. Returns the number of points flipped. */
static int points_flip(const rc_model *m, rc_data *d, int i, double t, double *y, const int *roots, int *changed)
{
    const int npt = m->inter_npt[i], ps = m->inter_pst[i]; /* points, states per point */
    if (npt == 0 || d->inter_mode[i] != RC_MODE_CLOSED) return 0;
    int *sl = d->pt_slip + m->inter_pbase[i];
    double *out = d->sc->pt_work; /* RC_PT_OUT per point (rc_data_new) */
    /* scratch (rc_data_new): keep [3 npt], oldn [npt], md [npt], sel [npt] */
    double *keep = d->pt_flip, *oldn = keep + 3 * npt;
    int *md = (int *)(oldn + npt);
    char *sel = (char *)(md + npt);
    if (!roots) rc_points_eval(m, d, i, NULL, t, y, out);
    int n = 0;
    /* without roots (after a mode change): every point whose root is past
     * its crossing, sticking beyond its limit, or slipping along its force
     * faster than the slip speed band (a point at rest slides along its
     * force at the velocities' rounding) */
    const double vb = rc_slip_vband(m, i);
    for (int j = 0; j < npt; j++) {
        sel[j] = roots ? roots[j] != 0 : out[RC_PT_OUT * j] > (sl[j] ? vb : 0.0);
        n += sel[j];
    }
    /* the viscous form has no tangential state (a filter's state, if any,
     * goes on): only the modes flip */
    if (n > 0 && m->inter_fr[i].form != RC_FF_INCREMENTAL) {
        for (int j = 0; j < npt; j++)
            if (sel[j]) sl[j] = !sl[j];
        *changed = 1;
    } else if (n > 0) {
        double *ft = y + m->inter_eadr[i] + m->inter_ns[i];
        rc_points_eval(m, d, i, NULL, t, y, out);
        for (int j = 0; j < npt; j++) oldn[j] = out[RC_PT_OUT * j + 6]; /* in the tangent plane (cap_state) */
        for (int j = 0; j < npt; j++)
            if (sel[j])
                for (int k = 0; k < 3; k++) set_state(ft + ps * j + k, out[RC_PT_OUT * j + 1 + k], changed);
        for (int j = 0; j < npt; j++) md[j] = sel[j] ? 1 : sl[j];
        rc_points_eval(m, d, i, md, t, y, out);
        const double fb = m->inter_fr[i].fband;
        for (int j = 0; j < npt; j++) {
            if (!sel[j] || sl[j]) continue;
            const double *f = out + RC_PT_OUT * j + 1, nr = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
            if (nr > 0 && isfinite(nr)) /* a zero limit (no share) keeps the direction */
                for (int k = 0; k < 3; k++) set_state(ft + ps * j + k, f[k], changed);
            /* with the magnitude its spring had, as slip_on_limit: the
             * limit includes the stick damper's part, and a state put there
             * stored |L|^2 - |s|^2 over 2 K_t from no work, which the
             * spring later gave back to the bodies */
            cap_state(ft + ps * j, oldn[j], fb, 1, changed);
        }
        /* a point that sticks holds the force its spring has: a state below
         * the limit stays there (cap_state, the state it slid with, below a
         * limit that rose faster than the spring loaded: an impact), and
         * its stick is tested with that state below, not with the limit
         * (with the limit, the stick damper's force across the sliding put
         * the stick just beyond it, the point slid on and its sliding
         * turned by 90 degrees within nanoseconds: Zeno) */
        for (int j = 0; j < npt; j++)
            if (sel[j] && sl[j] && out[RC_PT_OUT * j + 4] > 0) cap_state(ft + ps * j, oldn[j], fb, 0, changed);
        int nst = 0; /* slip -> stick flips */
        for (int j = 0; j < npt; j++) {
            nst += sel[j] && sl[j];
            if (sel[j]) sl[j] = !sl[j];
        }
        *changed = 1;
        /* points stopping together: when some points stick at an event,
         * every other sliding point that can stick there (its stick force,
         * the state on the limit less the damper w c_t v_t, within the
         * limit: |v_t| below about 1e-6 L / c_t at unit share) sticks with them,
         * instead of at an event of its own a fraction of a nanosecond
         * later (a meshed block stopping: hundreds of points at once) */
        if (roots && nst > 0) {
            int ng = 0;
            rc_points_eval(m, d, i, NULL, t, y, out); /* sliding points: on the limit */
            for (int j = 0; j < npt; j++) {
                md[j] = sl[j];
                if (sel[j] || !sl[j] || !(out[RC_PT_OUT * j + 4] > 0)) continue;
                double nr = 0.0;
                for (int k = 0; k < 3; k++) nr += out[RC_PT_OUT * j + 1 + k] * out[RC_PT_OUT * j + 1 + k];
                if (!(nr > 0) || !isfinite(nr)) continue;
                for (int k = 0; k < 3; k++) {
                    keep[3 * j + k] = ft[ps * j + k];
                    ft[ps * j + k] = out[RC_PT_OUT * j + 1 + k];
                }
                md[j] = 0;
                ng++;
            }
            if (ng > 0) {
                rc_points_eval(m, d, i, md, t, y, out);
                for (int j = 0; j < npt; j++) {
                    if (md[j] == sl[j]) continue;
                    if (out[RC_PT_OUT * j] <= 0) {
                        sl[j] = 0; /* sticks with them, on the limit */
                        sel[j] = 1;
                        n++;
                    } else {
                        for (int k = 0; k < 3; k++) ft[ps * j + k] = keep[3 * j + k];
                    }
                }
            }
        }
        /* slip -> stick only where the stick holds: a point whose sliding
         * along its force stopped while it still slides across it (the
         * direction lags behind the velocity; a box rocking as it comes to
         * rest) would carry a stick damper force beyond its limit at once.
         * It slides on, its state on the limit opposite to its sliding
         * velocity (maximum dissipation), so that its root starts at
         * -|v_t| and no stick/slip pair repeats at one instant (its state
         * at least the slip band, as any sliding state's: cap_state). The
         * stick force is the state (on the limit) less the damper c_t v_t
         * (the points' states and forces here at unit share). */
        int nback = 0;
        for (int j = 0; j < npt; j++) nback += sel[j] && !sl[j];
        if (nback > 0 && m->inter_fr[i].ct > 0) {
            rc_points_eval(m, d, i, NULL, t, y, out);
            for (int j = 0; j < npt; j++) {
                if (!sel[j] || sl[j] || !(out[RC_PT_OUT * j] > 0)) continue;
                double *fj = ft + ps * j, dv[3];
                for (int k = 0; k < 3; k++) dv[k] = out[RC_PT_OUT * j + 1 + k] - fj[k]; /* -c_t v_t */
                /* at least the slip band: a state left at zero (sticking
                 * at the force where it was, on a zero limit: F_n = 0 on
                 * Iform 2's unload curve) has no direction to turn, and the
                 * point would stick with its damper's force beyond that
                 * zero limit (a box on a belt: 1.2e-3 N of friction at
                 * F_n = 0); it slides on, against its sliding */
                if (turn_state(fj, fmax(norm3(fj), m->inter_fr[i].fband), dv, 1.0, changed)) {
                    sl[j] = 1;
                    /* a turn, as the single contact's fric_turn: the
                     * state reloads towards its limit at K_t |v_t| / L_r,
                     * and the restart keeps BDF order <= 2 (cvode.c). At
                     * orders above, a step of h K_t |v_t| / L_r ~ 3 put a
                     * meshed box's corner state through zero to 2.6 times
                     * its limit along the sliding, its slip root crossed,
                     * the stick was refused and the point turned again:
                     * 200 such turns within 4e-8 s, Zeno */
                    d->fric_turned = 1;
                }
            }
        }
        /* no stored energy without work (cap_state); the points' states are
         * at unit share (the whole contact's slip band) */
        for (int j = 0; j < npt; j++)
            if (sel[j] && out[RC_PT_OUT * j + 4] > 0) cap_state(ft + ps * j, oldn[j], fb, sl[j], changed);
    }
    return n;
}

/* Contact points of interface i landing (their roots `land` crossed: the
 * depth q_j below the level of the shares rose through 0, a share begins):
 * such a point lands unloaded and sticking, F_t = 0 (its force w_j F_t is 0
 * at w_j = 0, so nothing is stored or released), and slips at once when its
 * stick force, the damper's -c_t v_t, exceeds the limit (points_flip after a
 * mode change). The state it relaxed to while away would otherwise enter
 * the growing share's rate -(dw/dt / w) F_t, which sends it to zero within
 * a vanishing time, and the law's rate would start without an event
 * (docs/theory.md 2.7). Returns the number of points landed. */
static int points_land(const rc_model *m, rc_data *d, int i, double t, double *y, const int *land, int *changed)
{
    const int npt = m->inter_npt[i], ps = m->inter_pst[i];
    if (d->inter_mode[i] != RC_MODE_CLOSED || m->inter_fr[i].form != RC_FF_INCREMENTAL) return 0;
    int n = 0;
    double *ft = y + m->inter_eadr[i] + m->inter_ns[i], *out = d->sc->pt_work;
    rc_points_eval(m, d, i, NULL, t, y, out);
    /* the landing band: the position tolerance of the interface, or more
     * where the root was located at a depth beyond it */
    const double apos = m->inter_peidx[i] >= 0 ? m->atol[m->inter_eadr[i] + m->inter_peidx[i]] : m->atol_pos;
    for (int j = 0; j < npt; j++) {
        if (!land[j]) continue;
        for (int k = 0; k < 3; k++) set_state(ft + ps * j + k, 0.0, changed);
        d->pt_slip[m->inter_pbase[i] + j] = 0;
        /* the band it landed with, if any (kept through the interface's
         * events), and at least 4 times the root's value at the crossing
         * (not 4 times the band: it would grow with every landing); and the
         * root a band above zero after the landing, q_j + band >= apos: a
         * point that lifted off by its band and landed again a band early
         * (its root q_j + band crossing 0 at q_j = -band) kept the same
         * band, its root stayed at the rounding of 0 with the point at
         * rest there, and it landed again at every event (a box on a belt:
         * 200 landings within 3e-12 s, Zeno) */
        double *lb = d->pt_lband + m->inter_pbase[i] + j;
        const double qj = out[RC_PT_OUT * j + 5];
        *lb = fmax(fmax(*lb, apos - qj), fmax(apos, 4.0 * fabs(qj + *lb)));
        n++;
    }
    if (n > 0) {
        *changed = 1;
        points_flip(m, d, i, t, y, NULL, changed);
    }
    return n;
}

/* Enter the contact zone at P = 0 from separation: virgin force, on the load
 * curve (Stiff is steeper than the load curve, so min(F_L, Stiff dP) = F_L). */
static void clear_band(rc_data *d, int i)
{
    d->inter_band[2 * i] = d->inter_band[2 * i + 1] = 0.0;
    d->inter_rband[i] = 0.0;
}

/* The law's energy E interface i holds at (t, y), where it keeps D_h
 * (inter_dhidx; 0 otherwise, and out of the zone) [J]: where an event
 * sets the law's state (P_e, F_h), D_h takes what E loses, as W_load - E
 * does */
static double dh_energy(const rc_model *m, const rc_data *d, int i, double t, const double *y)
{
    if (m->inter_dhidx[i] < 0) return 0.0;
    return rc_inter_stored_energy(m, d, i, t, y);
}

static void dh_lost(const rc_model *m, int i, double *y, double lost, int *changed)
{
    if (lost != 0.0) {
        double *dh = y + m->inter_eadr[i] + m->inter_dhidx[i];
        set_state(dh, *dh + lost, changed);
    }
}

static void enter_zone(const rc_model *m, rc_data *d, int i, double t, double *y, int *changed)
{
    dh_lost(m, i, y, dh_energy(m, d, i, t, y), changed); /* P_e starts at 0 */
    clear_band(d, i);
    d->inter_mode[i] = RC_MODE_CLOSED;
    d->inter_branch[i] = RC_BR_LOAD;
    d->inter_track[i] = 0;
    set_state(own(m, i, m->inter_hidx[i], y), 0.0, changed);
    /* several points: the law's penetration starts at zero (a contact
     * found already penetrating, whose closing was missed, is not given a
     * force no work loaded) */
    set_state(own(m, i, m->inter_peidx[i], y), 0.0, changed);
    reset_friction(m, d, i, y, changed);
}

/* Leave the zone (P falls to 0): no force, no history. */
static void leave_zone(const rc_model *m, rc_data *d, int i, double t, double *y, int *changed)
{
    dh_lost(m, i, y, dh_energy(m, d, i, t, y), changed); /* the law's energy is lost */
    clear_band(d, i);
    d->inter_mode[i] = RC_MODE_OPEN;
    d->inter_branch[i] = RC_BR_LOAD;
    set_state(own(m, i, m->inter_hidx[i], y), 0.0, changed);
    set_state(own(m, i, m->inter_peidx[i], y), 0.0, changed); /* its stored energy is lost */
    double *off = own(m, i, m->inter_oidx[i], y);
    d->inter_track[i] = off && *off > 0; /* Inacti 5: the gap recovers */
    reset_friction(m, d, i, y, changed);
}

/* Modes of an active interface from its state, at t = 0 or at Tstart:
 * Inacti, Icor and the initial penetration P0 (docs/theory.md 3.4). */
/* The sliding direction at which a stateless law saturated (reversal root). */
static void set_dref(rc_data *d, int i, const rc_inter_report *r)
{
    double n = sqrt(r->vt[0] * r->vt[0] + r->vt[1] * r->vt[1] + r->vt[2] * r->vt[2]);
    for (int k = 0; k < 3; k++) d->inter_dref[3 * i + k] = n > 0 ? r->vt[k] / n : 0.0;
}

/* A friction law without state (viscous forms, step5) has no history: its
 * mode (below the limit / saturated or capped) follows from the state alone.
 * Set it whenever the contact has just closed, so that a contact closing
 * while sliding starts saturated when its adhesion force is beyond the limit
 * (its root would otherwise start positive and never cross). */
static void stateless_friction_mode(const rc_model *m, rc_data *d, int i, double t, const double *y)
{
    const rc_fric *fr = &m->inter_fr[i];
    if (d->inter_mode[i] != RC_MODE_CLOSED || fr->kind == RC_FK_NONE || fr->form != RC_FF_VISCOUS) return;
    rc_inter_report r;
    d->inter_slip[i] = 0;
    report(m, d, i, t, y, &r);
    d->inter_slip[i] = r.slip_root > 0;
    set_dref(d, i, &r);
}

static void classify(const rc_model *m, rc_data *d, int i, double t, double *y, int *changed)
{
    rc_inter_report r;
    d->inter_mode[i] = RC_MODE_OPEN;
    d->inter_branch[i] = RC_BR_LOAD;
    d->inter_track[i] = 0;
    reset_friction(m, d, i, y, changed);
    report(m, d, i, t, y, &r);
    double *off = own(m, i, m->inter_oidx[i], y), *fh = own(m, i, m->inter_hidx[i], y);
    /* Inacti 5: the gap starts reduced by P0, so P starts at 0 */
    if (off && r.p_raw > 0 && *off == 0.0) {
        set_state(off, r.p_raw, changed);
        report(m, d, i, t, y, &r);
    }
    if (r.p < 0 || (r.p == 0 && r.vn <= 0)) {
        leave_zone(m, d, i, t, y, changed);
        return;
    }
    if (r.p == 0) {
        /* touching: closed at zero force, the viscous friction's mode
         * decided as for any close (saturated: the limit is 0 there; left
         * unsaturated, a sphere started sliding on an incline at P = 0
         * exactly was braked by the whole damper force, 0.96 N at no normal
         * force, where P = 1e-18 m let it slide) */
        enter_zone(m, d, i, t, y, changed);
        stateless_friction_mode(m, d, i, t, y);
        return;
    }
    /* initial penetration P0 > 0: on the load curve, or (Icor 1 with Iform 1)
     * on the unload curve; off the curve when moving away from it; several
     * points: the law's penetration P_e starts at P0 */
    set_state(own(m, i, m->inter_peidx[i], y), r.p, changed);
    if (fh && m->inter_icor[i] == 1 && m->inter_iform[i] == 1) {
        set_state(fh, r.fu, changed);
        d->inter_branch[i] = r.vn < 0 ? RC_BR_UNLOAD : RC_BR_ELASTIC;
    } else if (fh) {
        set_state(fh, r.fl, changed);
        d->inter_branch[i] = r.vn > 0 ? RC_BR_LOAD : RC_BR_ELASTIC;
    }
    /* power law: the rebound damping factor acts while P decreases */
    if (m->inter_law[i] == RC_LAW_POWER) d->inter_branch[i] = r.vn < 0 ? RC_BR_UNLOAD : RC_BR_LOAD;
    d->inter_mode[i] = RC_MODE_CLOSED;
    report(m, d, i, t, y, &r);
    if (!(r.fn > 0)) d->inter_mode[i] = RC_MODE_RELEASED;
    stateless_friction_mode(m, d, i, t, y);
    /* the elastic energy found in the contact at activation enters the
     * ledger as contact work (so the hysteresis dissipation starts at 0;
     * D_h starts at 0 as it is) */
    double *w = y + m->inter_eadr[i];
    set_state(w, *w + rc_inter_stored_energy(m, d, i, t, y), changed);
}

/* ---- the hysteresis of elastic laws that release at P > 0 ----------- */
/* An elastic law (Iform 0, the power law) with a damper releases at P > 0
 * when the damper pulls: the energy it stores there is lost to the bodies,
 * the only hysteresis such a law has. It is kept here, at the mode changes,
 * exactly (rc_data.inter_hacc; energy.c reads it), instead of as the normal
 * work less the stored energy, whose difference is otherwise the
 * integration error of the work accumulator, of either sign: on cradles
 * and pendulums with damped tabulated or power laws it made the
 * hysteresis dissipation run backwards by up to 1e-7 J. */

/* The energy interface i's law holds at the state y [J] (closed, at P). */
static double law_energy_now(const rc_model *m, const rc_data *d, int i, double t, const double *y)
{
    rc_inter_report r;
    rc_inter_report_eval(m, i, RC_MODE_CLOSED, d->inter_branch[i], 0, d->inter_slip[i], t, y, &r);
    return rc_inter_law_energy(m, i, r.pl);
}

static void modes_remember(const rc_model *m, rc_data *d)
{
    for (int i = 0; i < m->ninter; i++) d->mode_was[i] = d->inter_mode[i];
}

/* After modes changed at (t, y): a release keeps the energy stored then; a
 * contact that leaves the released mode has lost that energy less what it
 * holds again (closed), and one that leaves the closed mode for open or
 * inactive has lost what it held (its stored energy leaves the ledger). */
static void modes_account(const rc_model *m, rc_data *d, double t, const double *y)
{
    for (int i = 0; i < m->ninter; i++) {
        const int was = d->mode_was[i], now = d->inter_mode[i];
        if (was == now || !rc_inter_release_ledger(m, i)) continue;
        double *h = d->inter_hacc + 2 * i;
        const double e = law_energy_now(m, d, i, t, y);
        if (was == RC_MODE_RELEASED) h[0] += h[1] - (now == RC_MODE_CLOSED ? e : 0.0);
        else if (was == RC_MODE_CLOSED && now != RC_MODE_RELEASED) h[0] += e;
        if (now == RC_MODE_RELEASED) h[1] = e;
    }
}

/* The logic sensors' (AND, OR) times on from their inputs'. */
static void sens_propagate(const rc_model *m, rc_data *d)
{
    /* a logic sensor is on when both (either) of its inputs are, plus its
     * delay; the inputs' times on only ever go from INFINITY to a value
     * that stays, so nsens passes settle any chain (no cycles: compile) */
    for (int pass = 0; pass < m->nsens; pass++) {
        int changed = 0;
        for (int k = 0; k < m->nsens; k++) {
            if (m->sens_kind[k] != 2 && m->sens_kind[k] != 3) continue;
            const double a = d->sens_ton[m->sens_in[2 * k]], b = d->sens_ton[m->sens_in[2 * k + 1]];
            const double v = (m->sens_kind[k] == 2 ? fmax(a, b) : fmin(a, b)) + m->sens_tdelay[k];
            if (v != d->sens_ton[k]) {
                d->sens_ton[k] = v;
                changed = 1;
            }
        }
        if (!changed) break;
    }
}

/* The sensors found in the run that hold bodies or start loads and are on
 * at t (or whose release root crossed: roots, the sensors' block; NULL:
 * none) release them: rc_data.sens_rel, read by the imposed rows and the
 * gravity; the imposed velocities they start jump to their value
 * (rc_imp_start_sens). Returns how many. */
static int sens_release(const rc_model *m, rc_data *d, double t, const int *roots, double *y)
{
    int n = 0;
    for (int k = 0; k < m->nsens; k++) {
        if (!m->sens_hold[k] || d->sens_rel[k] || !isfinite(d->sens_ton[k])) continue;
        if (d->sens_ton[k] <= t || (roots && roots[2 * k])) {
            d->sens_rel[k] = 1;
            d->sens_new[k] |= 2;
            if (m->imp) rc_imp_start_sens(m, d, k, t, y);
            n++;
        }
    }
    return n;
}

/* Sensor k with Tmin whose criterion begins to hold at t (side: 1 above
 * Dmax or Fmax, -1 below Dmin), or stops holding (side 0), before Tmin:
 * its roots change (rc_sens_roots), the integrator restarts. */
static void sens_arm(rc_data *d, int k, double t, int side)
{
    d->sens_arm[2 * k] = side ? t : NAN;
    d->sens_arm[2 * k + 1] = side;
}

/* Interface sensors not yet triggered whose interfaces' state at (t, y)
 * meets their criterion trigger at t (on at t + Tdelay, latched): without
 * a force bound, a contact of theirs closed (the contact_close event that
 * just closed it, or a contact closed at the start or when its interface
 * started); with Fmax, the total normal force above it (the root function
 * finds its rise through Fmax within a contact; this catches a force that
 * jumped there with a contact closed at the start or at an interface's
 * start). With Tmin the force above Fmax arms it instead (it triggers Tmin
 * later, rc_sens_roots), and a force that jumped back to Fmax or below
 * disarms it; *rearm set then (NULL: at the start). Returns how many
 * triggered. */
static int sens_contact(const rc_model *m, rc_data *d, double t, const double *y, int *rearm)
{
    int n = 0;
    for (int k = 0; k < m->nsens; k++) {
        if (m->sens_kind[k] != 5 || isfinite(d->sens_ton[k])) continue;
        const double fmax = m->sens_d[2 * k + 1];
        const int holds = fmax > 0 ? rc_sens_inter_force(m, d, k, t, y) > fmax : rc_sens_inter_closed(m, d, k);
        if (m->sens_tmin[k] > 0) {
            /* (one its root armed in this event stays armed: the force
             * there is Fmax to the root's tolerance) */
            const double arm = d->sens_arm[2 * k];
            if (holds ? !isfinite(arm) : isfinite(arm) && arm != t) {
                sens_arm(d, k, t, holds);
                if (rearm) *rearm = 1;
            }
            continue;
        }
        if (holds) {
            d->sens_ton[k] = t + m->sens_tdelay[k];
            d->sens_new[k] |= 1;
            n++;
        }
    }
    return n;
}

/* The sensors' times on at the start: time sensors' Tdelay, a distance
 * sensor out of its bounds then triggered at t, the logic sensors of them. */
static void sens_init(const rc_model *m, rc_data *d, double t, double *y)
{
    d->t_bp = -INFINITY; /* no time breakpoint passed yet (RC_IMP_T_ON) */
    for (int k = 0; k < m->nsens; k++) {
        d->sens_new[k] = 0;
        d->sens_rel[k] = 0;
        d->sens_ton[k] = m->sens_kind[k] == 0 ? m->sens_tdelay[k] : INFINITY;
        sens_arm(d, k, t, 0);
        if (m->sens_kind[k] != 1) continue;
        /* out of its bounds at the start: triggered then (with Tmin: armed
         * then) */
        const double dist = rc_sens_distance(m, k, y), *b = m->sens_d + 2 * k;
        const int side = b[1] > 0 && dist > b[1] ? 1 : b[0] > 0 && dist < b[0] ? -1 : 0;
        if (side && m->sens_tmin[k] > 0) {
            sens_arm(d, k, t, side);
        } else if (side) {
            d->sens_ton[k] = t + m->sens_tdelay[k];
            d->sens_new[k] = 1;
        }
    }
    sens_propagate(m, d);
    sens_release(m, d, t, NULL, y);
}

static int sens_activate(const rc_model *m, rc_data *d, double t, double *y, rc_event *ev, int max_ev, int n,
                         int *restart);

void rc_modes_init(const rc_model *m, rc_data *d, double t, double *y)
{
    int changed = 0;
    sens_init(m, d, t, y); /* first: a sensor triggered at the start turns interfaces on */
    for (int i = 0; i < m->ninter; i++) {
        const double ton = rc_sens_inter_ton(m, d, i);
        int active = t >= ton && t <= m->inter_tstop[i];
        d->inter_mode[i] = RC_MODE_INACTIVE;
        d->inter_deck[i] = 1; /* its bodies where the deck put them */
        d->inter_lowq[i] = 0;
        if (active) classify(m, d, i, t, y, &changed);
    }
    /* an interface sensor whose contact is closed at the start triggers
     * then, and what it turns on follows */
    if (m->nsens > 0 && sens_contact(m, d, t, y, NULL)) (void)sens_activate(m, d, t, y, NULL, 0, 0, &changed);
    for (int i = 0; i < m->ninter; i++) {
        d->inter_hacc[2 * i] = 0.0;
        d->inter_hacc[2 * i + 1] =
            d->inter_mode[i] == RC_MODE_RELEASED && rc_inter_release_ledger(m, i) ? law_energy_now(m, d, i, t, y) : 0.0;
    }
    rc_cpl_modes_init(m, d, t, y); /* contact coupling faces */
}

/* Activation window and Inacti tracking; returns the event kind or RC_EV_NONE. */
static rc_event_kind step_window(const rc_model *m, rc_data *d, int i, double t, double *y, const int *r,
                               int *changed)
{
    const int mode = d->inter_mode[i];
    if (r[RC_ROOT_TSTOP] > 0 && mode != RC_MODE_INACTIVE) {
        d->inter_mode[i] = RC_MODE_INACTIVE; /* history frozen */
        return RC_EV_INTER_STOP;
    }
    if (r[RC_ROOT_TSTART] > 0 && mode == RC_MODE_INACTIVE && t <= m->inter_tstop[i] &&
        (m->inter_sens[i] < 0 || t >= rc_sens_inter_ton(m, d, i))) {
        classify(m, d, i, t, y, changed);
        /* and the integrator restarts: continued without a restart, an
         * interface whose start fell on an output time (Tstart 0.35 s,
         * outputs every 0.01 s) never saw its contact close */
        *changed = 1;
        return RC_EV_INTER_START;
    }
    /* Inacti 5 tracking: the full Gap is back, or the bodies approach again */
    if (d->inter_track[i] && r[RC_ROOT_TRK_B] < 0) {
        d->inter_track[i] = 0;
        set_state(own(m, i, m->inter_oidx[i], y), 0.0, changed);
        return RC_EV_INACTI_GAP_RECOVERED;
    }
    if (d->inter_track[i] && r[RC_ROOT_TRK_A] > 0) {
        enter_zone(m, d, i, t, y, changed);
        return RC_EV_CONTACT_CLOSE;
    }
    return RC_EV_NONE;
}

/* Hysteresis branches (in the zone); F_h is put exactly on the curve it
 * leaves or joins. */
static rc_event_kind step_branch(const rc_model *m, rc_data *d, int i, double t, double *y, const int *r,
                               int *changed)
{
    const int mode = d->inter_mode[i], br = d->inter_branch[i];
    /* power law: approach (LOAD) and rebound (UNLOAD, RDF) branches */
    if (m->inter_law[i] == RC_LAW_POWER && (mode == RC_MODE_CLOSED || mode == RC_MODE_RELEASED)) {
        if (br == RC_BR_LOAD && r[RC_ROOT_HYST_A] < 0) {
            d->inter_branch[i] = RC_BR_UNLOAD;
            return RC_EV_RDF_REBOUND;
        }
        if (br == RC_BR_UNLOAD && r[RC_ROOT_HYST_A] > 0) {
            d->inter_branch[i] = RC_BR_LOAD;
            return RC_EV_RDF_APPROACH;
        }
        return RC_EV_NONE;
    }
    if (m->inter_iform[i] == 0 || (mode != RC_MODE_CLOSED && mode != RC_MODE_RELEASED)) return RC_EV_NONE;
    double *fh = own(m, i, m->inter_hidx[i], y);
    rc_inter_report q;
    report(m, d, i, t, y, &q);
    if (br == RC_BR_LOAD && r[RC_ROOT_HYST_A] < 0) {
        d->inter_branch[i] = RC_BR_ELASTIC;
        set_state(fh, q.fl, changed);
        return RC_EV_HYST_UNLOADING;
    }
    if (br == RC_BR_UNLOAD && r[RC_ROOT_HYST_A] > 0) {
        d->inter_branch[i] = RC_BR_ELASTIC;
        set_state(fh, q.fu, changed);
        return RC_EV_HYST_RELOADING;
    }
    if (br == RC_BR_ELASTIC && r[RC_ROOT_HYST_A] < 0) {
        d->inter_branch[i] = RC_BR_LOAD;
        set_state(fh, q.fl, changed);
        return RC_EV_HYST_LOAD_CURVE;
    }
    if (br == RC_BR_ELASTIC && r[RC_ROOT_HYST_B] < 0) {
        d->inter_branch[i] = RC_BR_UNLOAD;
        set_state(fh, q.fu, changed);
        return RC_EV_HYST_UNLOAD_CURVE;
    }
    return RC_EV_NONE;
}

/* Touch band of interface i at (t, y) [m]: above the rounding of P (a
 * thousand ulps of the coordinates involved) and 1e-9 of the penetration
 * scale; until the contact first changes at an event (a window, or a
 * crossing of its mode: rc_events_apply), above the rounding of the deck's
 * coordinates too (where its bodies were put: a touching start 1 km
 * away begins 2e-14 m apart). Not beyond that: at 1 km the deck's rounding
 * is 4e-12 m, and a ball bouncing on a stiff wall there (its weight
 * pressing it 5e-12 m in) separated while still 8e-13 m in and closed again
 * only 4e-12 m in, its force jumping from zero to k times that: a limit
 * cycle fed by those jumps, 18 621 bounces where the scene at the origin
 * settled after 21. */
static double touch_band(const rc_model *m, const rc_data *d, int i, const double *y, const rc_inter_report *r)
{
    const double band = rc_touch_band(m, i, y, r, RC_TOUCH_ULPS, RC_TOUCH_REL, d->inter_deck[i]);
    return band > 0 ? band : DBL_MIN;
}

/* How far past P = 0 an open contact left within its touch band waits to
 * close [m]: the band, but not beyond RC_WAIT_PFRAC p_s where the contact
 * works at the resolution of its coordinates (a stiff wall whose
 * penetration at the force scale is a few thousand ulps of them), and not
 * below RC_WAIT_ULPS roundings of them, nor of its P. Closing at the full
 * band there started the force at k times the band, many times the force that held
 * the body: it was thrown off, separated and waited again, a limit cycle
 * (a ball pressed by a ramp against a wall of 4e13 N/m: resting 2e-15 m
 * in, band 2.4e-14 m, 0.95 N at the close against 0.08 N resting, 4 343
 * closes in 0.66 s and CV_TOO_MUCH_WORK). */
static double open_wait(const rc_model *m, int i, const double *y, const rc_inter_report *r, double band)
{
    const double ps = m->inter_pscale[i];
    if (!(isfinite(ps) && ps > 0) || band <= RC_WAIT_PFRAC * ps) return band;
    const double floor = rc_touch_band(m, i, y, r, RC_WAIT_ULPS, 0.0, 0);
    /* above the contact's present P (left open within the band while
     * moving apart: its root must start below the wait) */
    return fmin(band, fmax(fmax(RC_WAIT_PFRAC * ps, floor), r->p + floor));
}

/* The contact frequency omega_s = v_s / p_s of interface i [1/s] (0: not
 * scaled). The rounding of dP/dt for its trend is the rate that moves P by
 * its touch band within 1 / omega_s, and that of d2P/dt2 the acceleration
 * that reaches that rate within 1 / omega_s. A normal built from rounded
 * coordinates turns a tangential velocity into an approach rate of that
 * rounding (2e-14 m/s for a ball rolling on a floor mesh 1 km from the
 * origin), which must not decide a separation that gravity reverses within
 * a nanosecond and a fraction of the band; nor may the rounding of the
 * accelerations in a resting chain decide which of its touching contacts
 * start open. */
static double trend_omega(const rc_model *m, int i)
{
    const double ps = m->inter_pscale[i], vs = m->inter_vscale[i];
    return isfinite(ps) && isfinite(vs) && ps > 0 && vs > 0 ? vs / ps : 0.0;
}

/* The force band of interface i [N]: a force within it is zero to the
 * rounding of a contact at its touch band (the stiffness scale times the
 * band) or of its law's own terms (the closed report c). */
static double force_band(const rc_model *m, int i, double band, const rc_inter_report *c)
{
    const double k = isfinite(m->inter_kscale[i]) ? m->inter_kscale[i] : 0.0;
    return fmax(band * k, RC_TOUCH_ULPS * DBL_EPSILON * (fabs(c->fload) + fabs(c->fdamp)));
}

/* Contact zone (P) and force clipping (total normal force). */
static rc_event_kind step_contact(const rc_model *m, rc_data *d, int i, double t, double *y, const int *r,
                                  int *changed)
{
    const int mode = d->inter_mode[i];
    if (mode == RC_MODE_INACTIVE || d->inter_track[i]) return RC_EV_NONE;
    if (mode == RC_MODE_OPEN && r[RC_ROOT_ZONE] > 0) {
        enter_zone(m, d, i, t, y, changed);
        return RC_EV_CONTACT_CLOSE;
    }
    if (mode != RC_MODE_OPEN && r[RC_ROOT_ZONE] < 0) {
        leave_zone(m, d, i, t, y, changed);
        return RC_EV_CONTACT_SEPARATE;
    }
    if (mode == RC_MODE_CLOSED && r[RC_ROOT_FORCE] < 0) {
        /* the force down to zero at P = 0 within the touch band while the
         * bodies separate faster than its rounding: the contact leaves now
         * (released, it would separate at the same instant, in the touch
         * pass: a contact_open and contact_separate pair where another
         * frame's rounding met the zone's root first and gave a
         * contact_separate alone) */
        rc_inter_report q;
        report(m, d, i, t, y, &q);
        const double band = touch_band(m, d, i, y, &q);
        if (fabs(q.p) <= band && q.vn < -band * trend_omega(m, i)) {
            leave_zone(m, d, i, t, y, changed);
            return RC_EV_CONTACT_SEPARATE;
        }
        clear_band(d, i);
        d->inter_mode[i] = RC_MODE_RELEASED;
        reset_friction(m, d, i, y, changed);
        return RC_EV_CONTACT_OPEN;
    }
    if (mode == RC_MODE_RELEASED && r[RC_ROOT_FORCE] > 0) {
        /* the force back above zero at the rounding of P = 0 while the
         * bodies separate: a damping that vanishes faster than the
         * elastic force as P -> 0 (the power law's C P^m3 v with m3 >= n)
         * leaves the force positive in the last 1e-17 m, and its root and
         * the zone's fall together within rounding; closing there gave a
         * contact_close at -1.46 m/s and its contact_separate at the same
         * instant, in one frame and not in another. The contact leaves */
        rc_inter_report q;
        report(m, d, i, t, y, &q);
        if (q.vn < 0 && q.p <= rc_inter_apos(m, i)) {
            leave_zone(m, d, i, t, y, changed);
            return RC_EV_CONTACT_SEPARATE;
        }
        /* a force root that reached zero without passing its rounding
         * (the force band): the touch pass that follows every event
         * decides on the force's rate, as for any contact at zero force.
         * A ball leaving a meshed box at 0.27 m/s, its force exactly 0 at
         * P = 1.1e-14 m (its points past their landing bands), closed here
         * and was released by that pass at the same instant: a
         * contact_close/contact_open pair in one frame and not another */
        rc_inter_report c;
        rc_inter_report_eval(m, i, RC_MODE_CLOSED, d->inter_branch[i], 0, d->inter_slip[i], t, y, &c);
        if (fabs(c.fn) <= force_band(m, i, touch_band(m, d, i, y, &q), &c)) return RC_EV_NONE;
        clear_band(d, i);
        d->inter_mode[i] = RC_MODE_CLOSED;
        reset_friction(m, d, i, y, changed);
        return RC_EV_CONTACT_CLOSE;
    }
    return RC_EV_NONE;
}

/* Incremental friction going from stick to slip: the state takes the
 * applied force (spring and stick damper) returned radially onto the limit
 * (in the scaled plane when orthotropic), so that the sliding force keeps
 * its direction and the state its magnitude. */
static void slip_on_limit(const rc_model *m, rc_data *d, int i, double t, double *y, int *changed)
{
    const rc_fric *fr = &m->inter_fr[i];
    rc_inter_report q;
    double *ft = y + m->inter_eadr[i] + fr->tidx;
    report(m, d, i, t, y, &q); /* stick: the applied force */
    const double old = q.ftan;
    for (int k = 0; k < 3; k++) set_state(ft + k, q.fraw[k], changed);
    const int slip = d->inter_slip[i];
    d->inter_slip[i] = 1;
    report(m, d, i, t, y, &q); /* slip: that direction on the limit */
    d->inter_slip[i] = slip;
    /* a zero limit (mu floored at zero, no Sfric) keeps the direction */
    const double nr = q.fraw[0] * q.fraw[0] + q.fraw[1] * q.fraw[1] + q.fraw[2] * q.fraw[2];
    if (nr > 0 && isfinite(nr))
        for (int k = 0; k < 3; k++) set_state(ft + k, q.fraw[k], changed);
    if (!fr->exact) cap_state(ft, old, fr->fband, 1, changed); /* exact stick: no spring */
    /* a force that would push the sliding (v_t . e > 0 beyond the slip
     * speed band: the applied force carried the stick damper's part across
     * a sliding that had turned) slides against the sliding instead, at the
     * same magnitude; else it sticks again at once, and slips, every 1e-9 s
     * (a ball rolling down an incline: 250 000 stick/slip pairs) */
    d->inter_slip[i] = 1;
    report(m, d, i, t, y, &q);
    d->inter_slip[i] = slip;
    if (q.slip_root > rc_slip_vband(m, i)) turn_state(ft, norm3(ft), q.vt, -1.0, changed);
}

/* Incremental friction going from slip to stick: the state is put where
 * the force is, on the limit along its direction, its magnitude capped
 * (cap_state). */
static void stick_on_state(const rc_model *m, rc_data *d, int i, double t, double *y, int *changed)
{
    const rc_fric *fr = &m->inter_fr[i];
    rc_inter_report q;
    report(m, d, i, t, y, &q);
    d->inter_slip[i] = 0;
    if (fr->tidx < 0) return;
    double *ft = y + m->inter_eadr[i] + fr->tidx;
    const double old = q.ftan;
    for (int k = 0; k < 3; k++) set_state(ft + k, q.fraw[k], changed);
    if (fr->exact) return;
    cap_state(ft, old, fr->fband, 0, changed);
    /* and within the limit of the stick it starts: a law whose coefficient
     * rises with the sliding speed (Renard's, mu_s below mu_max) slid on a
     * limit above the static one, and a spring left there would slip
     * again at once; the part above is dissipated */
    rc_inter_report s;
    report(m, d, i, t, y, &s);
    if (norm3(ft) > s.flim && s.flim > fr->fband) cap_state(ft, s.flim, 0.0, 0, changed);
}

/* Friction. Incremental: stick -> slip when the force reaches the limit;
 * slip -> stick when the sliding velocity along the force vanishes (the state
 * is then put where the force already is, on the limit). Viscous (total):
 * the adhesion force saturates at the limit and comes back below it. */
static rc_event_kind step_friction(const rc_model *m, rc_data *d, int i, double t, double *y, const int *r,
                                 int *changed)
{
    const rc_fric *fr = &m->inter_fr[i];
    if (fr->kind == RC_FK_NONE || d->inter_mode[i] != RC_MODE_CLOSED) return RC_EV_NONE;
    rc_inter_report q;
    /* saturated stateless law: the sliding reversed; its mode then follows
     * from the state, saturated again in the new direction or not */
    if (fr->form == RC_FF_VISCOUS && d->inter_slip[i] && r[RC_ROOT_REV] < 0) {
        stateless_friction_mode(m, d, i, t, y);
        *changed = 1; /* ask for a restart: see below */
        return RC_EV_FRIC_REVERSE;
    }
    if (r[RC_ROOT_SLIP] <= 0) return RC_EV_NONE;
    if (!d->inter_slip[i]) {
        /* incremental: the state takes the applied force (spring and stick
         * damper), so that the sliding force keeps its direction */
        if (fr->form == RC_FF_INCREMENTAL && fr->ct > 0) slip_on_limit(m, d, i, t, y, changed);
        d->inter_slip[i] = 1;
        if (fr->form == RC_FF_VISCOUS) {
            report(m, d, i, t, y, &q);
            set_dref(d, i, &q);
            /* the force is continuous across the limit but its Jacobian is
             * not (-C I below, rank-deficient above, C up to ~1e6 N s/m):
             * the step that crossed the limit was taken in the old mode, and
             * continuing from it, even with a fresh Jacobian, let a stiff
             * viscous law chatter across the limit; restart from the event */
            *changed = 1;
        }
        return fr->form == RC_FF_VISCOUS ? RC_EV_FRIC_SATURATE : RC_EV_FRIC_SLIP;
    }
    double f0[3] = {0.0, 0.0, 0.0};
    if (fr->tidx >= 0)
        for (int k = 0; k < 3; k++) f0[k] = y[m->inter_eadr[i] + fr->tidx + k];
    stick_on_state(m, d, i, t, y, changed);
    if (fr->form == RC_FF_VISCOUS) *changed = 1; /* restart, as for saturation */
    if (fr->form == RC_FF_INCREMENTAL && !fr->exact && fr->tidx >= 0) {
        /* the sliding along the force stopped, but not the sliding: it
         * turned across the force (v_t . e = 0 with v_t not zero, a spring
         * whose direction turns at K_t |v_t| / L_r lagging a slow sliding
         * that turns), and the stick it would start slips at once (200
         * stick/slip events within 1e-8 s of a ball rolling onto an
         * incline). It slides on, its force turned against the sliding at
         * the same magnitude: no energy stored or released, the friction
         * power -F . v_t positive from there */
        rc_inter_report u;
        report(m, d, i, t, y, &u);
        if (u.slip_root > 0 && turn_state(y + m->inter_eadr[i] + fr->tidx, fmax(norm3(f0), fr->fband), u.vt, -1.0, changed)) {
            d->inter_slip[i] = 1;
            d->fric_turned = 1; /* the restart after it: BDF order <= 2 (cvode.c) */
            return RC_EV_FRIC_TURN;
        }
    }
    return fr->form == RC_FF_VISCOUS ? RC_EV_FRIC_UNSATURATE : RC_EV_FRIC_STICK;
}

/* A settled contact (rc_data.inter_settled) stays so while it is closed;
 * so does the order hold of a contact whose events crowded (inter_lowq). */
static void clear_settled(const rc_model *m, rc_data *d)
{
    for (int i = 0; i < m->ninter; i++)
        if (d->inter_mode[i] != RC_MODE_CLOSED) d->inter_settled[i] = d->inter_lowq[i] = 0;
}

/* After sensors triggered at t: the logic sensors of them follow, the
 * holds of those on now end, and the inactive interfaces that reach their
 * time on now start now (a later time on: their start root crosses then);
 * an interface that starts closed triggers the interface sensors watching
 * it, and so on. Returns the interfaces' start events written into ev
 * from n on. */
static int sens_activate(const rc_model *m, rc_data *d, double t, double *y, rc_event *ev, int max_ev, int n,
                         int *restart)
{
    /* each round triggers at least one more sensor: at most nsens rounds */
    for (int round = 0; round <= m->nsens; round++) {
        sens_propagate(m, d); /* the logic sensors of those */
        if (sens_release(m, d, t, NULL, y)) *restart = 1; /* the holds of those on now (no delay) */
        int started = 0;
        for (int i = 0; i < m->ninter; i++) {
            const int s = m->inter_sens[i];
            if (s < 0 || d->inter_mode[i] != RC_MODE_INACTIVE || t < rc_sens_inter_ton(m, d, i) ||
                t > m->inter_tstop[i])
                continue;
            classify(m, d, i, t, y, restart);
            if (n < max_ev) {
                ev[n].inter = i;
                ev[n].kind = RC_EV_INTER_START;
            }
            n++;
            started++;
        }
        if (!started || !sens_contact(m, d, t, y, restart)) break;
        *restart = 1;
    }
    return n;
}

/* Distance and interface sensors whose trigger roots crossed trigger
 * (latched): on at t + Tdelay, and what they turn on follows
 * (sens_activate). Returns the interfaces' start events written into ev
 * from n on. */
static int sensors_apply(const rc_model *m, rc_data *d, double t, double *y, const int *roots, rc_event *ev,
                         int max_ev, int n, int *restart)
{
    const int *r = roots + rc_root_sens_base(m);
    int any = 0;
    /* a release root crossed (a time on known before this event) */
    if (sens_release(m, d, t, r, y)) *restart = 1; /* the holds end: the imposed rows jump */
    for (int k = 0; k < m->nsens; k++) {
        if (!((m->sens_kind[k] == 1 || m->sens_kind[k] == 5) && (r[2 * k] || r[2 * k + 1]) &&
              !isfinite(d->sens_ton[k])))
            continue;
        *restart = 1; /* its roots leave the set or change: start afresh */
        /* with Tmin: a criterion that begins to hold arms the sensor (slot
         * 0: above Dmax or Fmax, 1: below Dmin), one that stops holding
         * first disarms it, Tmin reached triggers it (rc_sens_roots) */
        if (m->sens_tmin[k] > 0 && !isfinite(d->sens_arm[2 * k])) {
            sens_arm(d, k, t, r[2 * k] ? 1 : -1);
            continue;
        }
        if (m->sens_tmin[k] > 0 && !r[2 * k + 1]) {
            sens_arm(d, k, t, 0);
            continue;
        }
        /* Tmin after the criterion began to hold (t, located, is at or
         * just past it) */
        d->sens_ton[k] = (m->sens_tmin[k] > 0 ? d->sens_arm[2 * k] + m->sens_tmin[k] : t) + m->sens_tdelay[k];
        d->sens_new[k] |= 1;
        any = 1;
    }
    if (!any) return n;
    return sens_activate(m, d, t, y, ev, max_ev, n, restart);
}

int rc_events_apply(const rc_model *m, rc_data *d, double t, double *y, const int *roots, rc_event *ev,
                    int max_ev, int *restart)
{
    int n = 0;
    *restart = 0;
    modes_remember(m, d);
    if (m->nsens > 0) n = sensors_apply(m, d, t, y, roots, ev, max_ev, n, restart);
    for (int i = 0; i < m->ninter; i++) {
        const int *r = roots + RC_ROOTS_PER_INTER * i;
        int any = 0;
        for (int k = 0; k < RC_ROOTS_PER_INTER; k++) any |= r[k] != 0;
        for (int j = 0; j < m->inter_npt[i]; j++)
            any |= roots[rc_root_point_base(m) + m->inter_pbase[i] + j] != 0 ||
                   roots[rc_root_land_base(m) + m->inter_pbase[i] + j] != 0;
        if (!any) continue;
        clear_band(d, i); /* the touch bands last until the interface's next event */
        /* window first; then the branch, then the contact, so that crossings
         * falling together (the Stiff line reaching zero releases the force)
         * are all applied, in the order of the law */
        rc_event_kind kind[4] = {step_window(m, d, i, t, y, r, restart), RC_EV_NONE, RC_EV_NONE, RC_EV_NONE};
        if (kind[0] == RC_EV_NONE) {
            kind[1] = step_branch(m, d, i, t, y, r, restart);
            kind[2] = step_contact(m, d, i, t, y, r, restart);
            if (kind[2] == RC_EV_NONE) kind[3] = step_friction(m, d, i, t, y, r, restart);
        }
        if ((kind[0] != RC_EV_NONE || kind[2] != RC_EV_NONE) && d->inter_mode[i] == RC_MODE_CLOSED) stateless_friction_mode(m, d, i, t, y);
        /* a damped contact of several points closed: the restart after it
         * keeps the BDF order at most 3 (cvode.c, caps_order) */
        if ((kind[0] == RC_EV_CONTACT_CLOSE || kind[2] == RC_EV_CONTACT_CLOSE) && caps_order(m, i)) d->multi_closed = 1;
        /* the rounding of the deck's coordinates lasts until the contact
         * itself changes (a window or a crossing of its mode), not through
         * its friction's or its hysteresis' events: a box started touching
         * an incline 1 km away (a gap of -4.5e-14 m, the deck's rounding)
         * separated at its first fric_slip, 4.7e-11 s in, and closed again
         * 7.9e-8 s later, where the scene at the origin stayed closed */
        if (kind[0] != RC_EV_NONE || kind[2] != RC_EV_NONE) d->inter_deck[i] = 0;
        /* the landing bands last while the contact does: a point that
         * landed keeps its land root a band away through the interface's
         * other events (its own stick -> slip flip an instant later among
         * them), so that a depth at the rounding of 0 does not land it
         * again at every event (a box edge pair landing at q = 2e-18 m
         * with a share of 3e-11: land, slip, land, ... 200 times within
         * 3e-9 s); a contact that changes clears them (points_land sets a
         * landing point's own) */
        if (kind[0] != RC_EV_NONE || kind[2] != RC_EV_NONE)
            for (int j = 0; j < m->inter_npt[i]; j++) d->pt_lband[m->inter_pbase[i] + j] = 0.0;
        /* friction per contact point: the points whose roots crossed (all
         * reset when the contact changed) */
        if (kind[0] == RC_EV_NONE && kind[2] == RC_EV_NONE && m->inter_npt[i] > 0) {
            const int *rp = roots + rc_root_point_base(m) + m->inter_pbase[i];
            if (points_land(m, d, i, t, y, roots + rc_root_land_base(m) + m->inter_pbase[i], restart) > 0) {
                kind[3] = RC_EV_FRIC_LAND;
            } else if (points_flip(m, d, i, t, y, rp, restart) > 0) {
                /* the kind most of them took (a point refused the stick
                 * slides on: points_flip) */
                int nsl = 0, nst = 0;
                for (int j = 0; j < m->inter_npt[i]; j++)
                    if (rp[j]) {
                        if (d->pt_slip[m->inter_pbase[i] + j]) nsl++;
                        else nst++;
                    }
                kind[3] = nsl >= nst ? RC_EV_FRIC_SLIP : RC_EV_FRIC_STICK;
            }
        }
        for (int k = 0; k < 4; k++) {
            if (kind[k] == RC_EV_NONE) continue;
            if (n < max_ev) {
                ev[n].inter = i;
                ev[n].kind = kind[k];
            }
            n++;
        }
    }
    /* contact coupling faces (assemble_rhs.c): their roots follow the
     * interfaces'; an event names the coupling (inter = -1 - k) */
    if (rc_cpl_nroots(m) > 0) {
        rc_event_kind kinds[RC_CPL_MAX_EV];
        int cpls[RC_CPL_MAX_EV];
        const int nc = rc_cpl_events(m, d, t, y, roots + rc_root_cpl_base(m), kinds, cpls, RC_CPL_MAX_EV,
                                     restart);
        for (int j = 0; j < nc && j < RC_CPL_MAX_EV; j++, n++)
            if (n < max_ev) {
                ev[n].inter = -1 - cpls[j];
                ev[n].kind = kinds[j];
            }
    }
    /* the interface sensors of the contacts these events closed */
    if (m->nsens > 0 && sens_contact(m, d, t, y, restart)) {
        *restart = 1;
        n = sens_activate(m, d, t, y, ev, max_ev, n, restart);
    }
    clear_settled(m, d);
    modes_account(m, d, t, y);
    return n;
}

/* ---- contacts at zero: modes decided by the state ------------------ */

/* Accelerations below this many times band omega_s^2 (what a contact
 * overlapping by its touch band gives a body of its effective mass) are
 * the rounding of the touching contacts around (the stiffer neighbours of
 * a chain: 3.5 times that in a stack of three balls 1 km away) */
#define RC_TOUCH_AFAC 100.0

/* Sign of the first non-zero time derivative of P: dP/dt, or, when it is
 * zero to the precision of a located root or to the rounding of the
 * velocities (below vband), d2P/dt2 unless that is below its own rounding
 * RC_TOUCH_AFAC vband omega (0: both zero). */
static int p_trend(double vn, double an, double t, double dtout, double vband, double omega)
{
    const double tau = RC_TOUCH_ULPS * DBL_EPSILON * (fabs(t) + dtout); /* [s] */
    if (fabs(vn) > fmax(fabs(an) * tau, vband)) return vn > 0 ? 1 : -1;
    if (fabs(an) <= RC_TOUCH_AFAC * vband * omega) return 0;
    return (an > 0) - (an < 0);
}

int rc_modes_touch(const rc_model *m, rc_data *d, double t, double *y, const double *ydot, rc_event *ev, int max_ev,
                   int *restart)
{
    int n = 0;
    modes_remember(m, d);
    for (int i = 0; i < m->ninter; i++) {
        const int mode = d->inter_mode[i], br = d->inter_branch[i];
        if (mode == RC_MODE_INACTIVE) continue;
        rc_inter_report r, c, dr, dc;
        report(m, d, i, t, y, &r);
        const double band = touch_band(m, d, i, y, &r);
        rc_event_kind kind = RC_EV_NONE;
        /* the force the contact would carry, closed, and its rate */
        const int cbr = mode == RC_MODE_OPEN ? RC_BR_LOAD : br;
        rc_inter_report_eval(m, i, RC_MODE_CLOSED, cbr, 0, d->inter_slip[i], t, y, &c);
        const double k = isfinite(m->inter_kscale[i]) ? m->inter_kscale[i] : 0.0;
        const double fband = force_band(m, i, band, &c);
        /* the rates below are needed only by a contact at zero (P or force)
         * or by a law with branches; the others (most of them, at most
         * events) skip the two complex-step evaluations */
        const int need = fabs(r.p) <= band || fabs(c.fn) <= fband ||
                         (m->inter_law[i] == RC_LAW_TYPE6 && m->inter_iform[i] != 0) ||
                         (m->inter_law[i] == RC_LAW_POWER && rc_pw_rdf_acts(&m->inter_pw[i]));
        int trend = 0, ctrend = 0, ltrend = 0; /* P, P closed, the law's penetration */
        memset(&dr, 0, sizeof dr);
        memset(&dc, 0, sizeof dc);
        /* rates at the rounding of the velocities (trend_omega): an
         * approach rate below vband; a force rate below RC_TOUCH_AFAC k vband,
         * the stiffness times the rounding of the approach rate and a
         * damper (of order k / omega_s) times that of the acceleration (a
         * damped ball in a stack 1 km away released at t = 0 on a force
         * rate of -3.6e-4 N/s, its damper on an acceleration of 7e-5 m/s^2) */
        const double om = trend_omega(m, i), vband = band * om, frate = RC_TOUCH_AFAC * k * vband;
        if (need) {
            rc_inter_report_rate(m, i, RC_MODE_CLOSED, cbr, 0, d->inter_slip[i], y, ydot, &dc);
            /* where P is heading: dP/dt, else the normal acceleration */
            rc_inter_report_rate(m, i, mode, br, d->inter_track[i], d->inter_slip[i], y, ydot, &dr);
            trend = d->inter_track[i] ? p_trend(r.vn_raw, dr.vn_raw, t, m->dtout, vband, om)
                                      : p_trend(r.vn, dr.vn, t, m->dtout, vband, om);
            ctrend = p_trend(c.vn, dc.vn, t, m->dtout, vband, om);
            ltrend = d->inter_track[i] ? trend : p_trend(r.vl, dr.vl, t, m->dtout, vband, om);
        }
        if (mode == RC_MODE_OPEN && !d->inter_track[i] && r.p > band) {
            /* a state already past a crossing of its mode cannot wait for
             * it: open while penetrating beyond the band (a closing the
             * integrator could not see, its root having started on the far
             * side) closes now; the three cases below likewise */
            enter_zone(m, d, i, t, y, restart);
            kind = RC_EV_CONTACT_CLOSE;
        } else if (mode != RC_MODE_OPEN && r.p < -band) {
            leave_zone(m, d, i, t, y, restart); /* closed or released while apart */
            kind = RC_EV_CONTACT_SEPARATE;
        } else if (mode == RC_MODE_CLOSED && !d->inter_settled[i] && c.fn < -fband) {
            d->inter_mode[i] = RC_MODE_RELEASED; /* closed under a tensile force */
            reset_friction(m, d, i, y, restart);
            kind = RC_EV_CONTACT_OPEN;
        } else if (mode == RC_MODE_RELEASED && c.fn > fband) {
            d->inter_mode[i] = RC_MODE_CLOSED; /* released under a compressive force */
            reset_friction(m, d, i, y, restart);
            kind = RC_EV_CONTACT_CLOSE;
        } else if (mode == RC_MODE_OPEN) {
            /* P at zero (or the Inacti offset tracking it): close unless the
             * bodies separate; a touching contact carries zero force */
            if (fabs(r.p) <= band && trend >= 0 && c.fn >= -fband) {
                enter_zone(m, d, i, t, y, restart);
                kind = RC_EV_CONTACT_CLOSE;
            }
        } else if (fabs(r.p) <= band && ctrend < 0) {
            /* closed or released at P = 0 while separating */
            leave_zone(m, d, i, t, y, restart);
            kind = RC_EV_CONTACT_SEPARATE;
        } else if (mode == RC_MODE_RELEASED && fabs(c.fn) <= fband && (dc.fn > frate || (fabs(dc.fn) <= frate && ctrend >= 0))) {
            /* released at zero force that would grow again: close */
            d->inter_mode[i] = RC_MODE_CLOSED;
            reset_friction(m, d, i, y, restart);
            kind = RC_EV_CONTACT_CLOSE;
        } else if (mode == RC_MODE_CLOSED && !d->inter_settled[i] && fabs(c.fn) <= fband &&
                   (dc.fn < -frate || (fabs(dc.fn) <= frate && ctrend < 0))) {
            /* closed at zero force that is about to pull: release */
            d->inter_mode[i] = RC_MODE_RELEASED;
            reset_friction(m, d, i, y, restart);
            kind = RC_EV_CONTACT_OPEN;
        } else if (m->inter_law[i] == RC_LAW_POWER && rc_pw_rdf_acts(&m->inter_pw[i])) {
            /* rebound damping branch at a zero rate of the damping's own
             * argument (dP/dt, or v_bar with several points), where the
             * damping force is zero on both branches: decided on P_e's
             * rate, which its relaxation keeps below v_bar, the branch
             * switched while the damper carried 5 N and the force's jump
             * turned the rate back at once (a box resting on an incline:
             * rebound/approach every 1e-9 s, Zeno) */
            const int still = fabs(r.vd) <= fabs(dr.vd) * RC_TOUCH_ULPS * DBL_EPSILON * (fabs(t) + m->dtout);
            const int dtrend = d->inter_track[i] ? trend : p_trend(r.vd, dr.vd, t, m->dtout, vband, om);
            if (br == RC_BR_LOAD && still && dtrend < 0) {
                d->inter_branch[i] = RC_BR_UNLOAD;
                kind = RC_EV_RDF_REBOUND;
            } else if (br == RC_BR_UNLOAD && still && dtrend > 0) {
                d->inter_branch[i] = RC_BR_LOAD;
                kind = RC_EV_RDF_APPROACH;
            }
        }
        /* hysteresis: decided after the contact's mode above, in the same
         * pass (a contact released at zero force and closed again there
         * may sit on a curve its law is already leaving: a meshed box
         * joined the floor of its unload curve, F_U = 0, while closing
         * again with its law reloading at 1.9e-7 m/s; decided in a later
         * pass only, the touch's second round was spent and the branch's
         * rate root, started past zero, never crossed: it sank 2 m
         * through its belt at zero force) */
        rc_event_kind hkind = RC_EV_NONE;
        if (mode != RC_MODE_OPEN && d->inter_mode[i] != RC_MODE_OPEN && m->inter_law[i] == RC_LAW_TYPE6 &&
            m->inter_iform[i] != 0) {
            /* hysteresis: each branch's root on its waiting side. On the
             * Stiff line (ELASTIC) F_U <= F_h <= F_L: at or past a bound
             * (within hb) that the line is heading across, join that curve
             * (the trend of F_L - F_h, F_h - F_U: (F_L' - Stiff) dP/dt, so
             * that a load curve steeper than Stiff is joined while
             * unloading too); on a curve the law's rate must keep its sign
             * (LOAD: loading, UNLOAD: unloading), else back on the Stiff
             * line at the curve. A branch left on the wrong side would
             * follow its curve back (energy from the hysteresis ledger) */
            double *fh = own(m, i, m->inter_hidx[i], y);
            const double hb = fmax(fband, RC_TOUCH_ULPS * DBL_EPSILON * (fabs(r.fh) + fabs(r.fl) + fabs(r.fu)));
            const int has_ul = m->inter_fct_ul[i] >= 0;
            /* the curves' slopes at the law's penetration: a curve steeper
             * than Stiff is followed both ways (the line would cross it) */
            double fv, sl = 0.0, su = 0.0;
            const double ax = m->inter_ascalex[i], kst = m->inter_stiff[i];
            rc_table_eval(&m->table[m->inter_fct_ld[i]], r.pl / ax, &fv, &sl);
            sl *= m->inter_fscaleld[i] / ax;
            if (has_ul) {
                rc_table_eval(&m->table[m->inter_fct_ul[i]], r.pl / ax, &fv, &su);
                su *= m->inter_fscaleul[i] / ax;
            }
            /* on the Stiff line F_h moves at Stiff dP/dt, the curves at
             * their slopes: the trends of F_L - F_h and F_h - F_U are the
             * law's trend (second order where dP/dt is zero) times the sign
             * of the slopes' difference */
            const int up = ((sl > kst) - (sl < kst)) * ltrend, lo = ((kst > su) - (kst < su)) * ltrend;
            /* a reversal on a curve: at a located root (dP/dt zero to its
             * precision), or a law clearly moving the wrong way for its
             * branch (beyond the slip speed band: a branch left on its far
             * side), not the rounding of a rate at rest */
            const int still = fabs(r.vl) <= fabs(dr.vl) * RC_TOUCH_ULPS * DBL_EPSILON * (fabs(t) + m->dtout);
            const double vb = rc_slip_vband(m, i);
            /* a curve joined on the trend alone (the line on it within hb)
             * must find its rate root on the waiting side: the load curve
             * less steep than Stiff with the law already unloading (dP/dt
             * < 0 at a located reversal whose second derivative reads the
             * other way, a corner of the rate) would follow the curve back
             * down with no root left to stop it (energy_hysteresis fell
             * 2.6e-3 J in a box dropped on a box); the line stays, its
             * roots a band away on both sides */
            const int up_ok = !(kst > sl && r.vl < 0), lo_ok = !(kst > su && r.vl > 0);
            if (br == RC_BR_ELASTIC && (r.fh - r.fu < -hb || (r.fh - r.fu <= hb && lo < 0 && lo_ok))) {
                d->inter_branch[i] = RC_BR_UNLOAD;
                set_state(fh, r.fu, restart);
                hkind = RC_EV_HYST_UNLOAD_CURVE;
            } else if (br == RC_BR_ELASTIC && (r.fl - r.fh < -hb || (r.fl - r.fh <= hb && up < 0 && up_ok))) {
                d->inter_branch[i] = RC_BR_LOAD;
                set_state(fh, r.fl, restart);
                hkind = RC_EV_HYST_LOAD_CURVE;
            } else if (br == RC_BR_LOAD && ltrend < 0 && kst > sl && (still || r.vl < -vb)) {
                d->inter_branch[i] = RC_BR_ELASTIC;
                set_state(fh, r.fl, restart);
                hkind = RC_EV_HYST_UNLOADING;
            } else if (br == RC_BR_UNLOAD && ltrend > 0 && kst > su && (still || r.vl > vb)) {
                d->inter_branch[i] = RC_BR_ELASTIC;
                set_state(fh, r.fu, restart);
                hkind = RC_EV_HYST_RELOADING;
            }
        }
        if ((kind != RC_EV_NONE || hkind != RC_EV_NONE) && d->inter_mode[i] == RC_MODE_CLOSED) stateless_friction_mode(m, d, i, t, y);
        /* friction after whatever the contact did above (a contact that has
         * just closed sticks afresh): incremental friction sticking beyond
         * its limit (a contact that closes while sliding: the stick damper
         * alone exceeds the limit) slips from the start, its state on the
         * applied force; per contact point likewise */
        const rc_fric *fr = &m->inter_fr[i];
        rc_event_kind fkind = RC_EV_NONE;
        if (points_flip(m, d, i, t, y, NULL, restart) > 0) fkind = RC_EV_FRIC_SLIP;
        const int incr1 = d->inter_mode[i] == RC_MODE_CLOSED && fr->kind != RC_FK_NONE &&
                          fr->form == RC_FF_INCREMENTAL && m->inter_npt[i] == 0 && !fr->exact;
        /* incremental friction slipping along its force (v_t . e > 0: the
         * force would push the sliding, its root started past zero and
         * could not see the stop): it sticks now, and slips again below if
         * its stick force exceeds the limit, along that force */
        if (incr1 && d->inter_slip[i]) {
            report(m, d, i, t, y, &r);
            if (r.slip_root > rc_slip_vband(m, i)) {
                stick_on_state(m, d, i, t, y, restart);
                fkind = RC_EV_FRIC_STICK;
            }
        }
        if (incr1 && !d->inter_slip[i]) {
            report(m, d, i, t, y, &r);
            if (r.slip_root > 0) {
                slip_on_limit(m, d, i, t, y, restart);
                d->inter_slip[i] = 1;
                fkind = RC_EV_FRIC_SLIP;
            }
        }
        /* exact stick, sticking: can it stick? Not when it slides (a
         * contact closing while sliding) or when the force that holds it
         * lies beyond the static limit (a slip that ended with the force
         * outside the cone, a load beyond the limit at the start): it
         * slides on the limit along that direction (the force's on a) */
        if (d->inter_mode[i] == RC_MODE_CLOSED && fr->kind != RC_FK_NONE && fr->exact && fr->tidx >= 0 &&
            !d->inter_slip[i]) {
            double e[3];
            if (rc_stk_decide(m, d, i, t, y, e) > 0) {
                double *ft = y + m->inter_eadr[i] + fr->tidx;
                for (int q = 0; q < 3; q++) set_state(ft + q, e[q], restart);
                d->inter_slip[i] = 1;
                report(m, d, i, t, y, &r); /* slip: on the (kinetic) limit along e */
                for (int q = 0; q < 3; q++) set_state(ft + q, r.fraw[q], restart);
                *restart = 1;
                fkind = RC_EV_FRIC_SLIP;
            }
        }
        /* a contact left at P = 0 or at zero force waits a band away, on
         * the side of its next crossing: closed or released, it separates
         * at P = -band; open, it closes at P = +band; closed, it releases
         * at F_n = -fband; released, it closes again at F_n = +fband. Its
         * roots thus start strictly on their waiting side, so the
         * integrator sees the crossing whichever way rounding left them */
        clear_band(d, i);
        if (d->inter_mode[i] != RC_MODE_INACTIVE) {
            const int md = d->inter_mode[i];
            report(m, d, i, t, y, &r);
            if (fabs(r.p) <= band && !(md == RC_MODE_OPEN && d->inter_track[i]))
                d->inter_band[2 * i] = md == RC_MODE_OPEN ? -open_wait(m, i, y, &r, band) : band;
            if (md != RC_MODE_OPEN && fabs(r.fn) <= fband) d->inter_band[2 * i + 1] = md == RC_MODE_CLOSED ? fband : -fband;
            /* the power law's RDF branch at a damping rate (dP/dt, v_bar)
             * within the rounding of the velocities (vband): its root waits twice that
             * away on its waiting side (in a touching cradle on IDA the rate
             * stayed at 1e-48 m/s, its sign rounding, and the roots crossed
             * at every step: 200 rebound/approach events within 3e-10 s) */
            if (md != RC_MODE_OPEN && m->inter_law[i] == RC_LAW_POWER && rc_pw_rdf_acts(&m->inter_pw[i]) &&
                fabs(r.vd) <= vband)
                d->inter_rband[i] = d->inter_branch[i] == RC_BR_LOAD ? 2.0 * vband : -2.0 * vband;
            /* a TYPE6 hysteresis curve likewise: its rate root (the law's
             * rate, LOAD waiting for it to fall below zero, UNLOAD to rise
             * above) at a rate within the slip band, where the branch was
             * kept above (a reversal is decided beyond that band), waits
             * twice the band away on its waiting side. Left at the rate,
             * the root started past zero and never crossed (a box resting
             * on its load curve at a law rate of -2e-9 m/s, within the band
             * and kept there, would follow the curve down without end:
             * 116 of 400 random touching states, test_passive) */
            const int b2 = d->inter_branch[i];
            const double vb2 = rc_slip_vband(m, i);
            if (md != RC_MODE_OPEN && m->inter_law[i] == RC_LAW_TYPE6 && m->inter_iform[i] != 0 &&
                (b2 == RC_BR_LOAD || b2 == RC_BR_UNLOAD) && fabs(r.vl) <= vb2)
                d->inter_rband[i] = b2 == RC_BR_LOAD ? 2.0 * vb2 : -2.0 * vb2;
        }
        if (kind == RC_EV_CONTACT_CLOSE && caps_order(m, i)) d->multi_closed = 1; /* cvode.c */
        const rc_event_kind kinds[3] = {kind, hkind, fkind};
        for (int q = 0; q < 3; q++) {
            if (kinds[q] == RC_EV_NONE) continue;
            if (n < max_ev) {
                ev[n].inter = i;
                ev[n].kind = kinds[q];
            }
            n++;
        }
    }
    /* the interface sensors of the contacts closed here */
    if (m->nsens > 0 && sens_contact(m, d, t, y, restart)) {
        *restart = 1;
        n = sens_activate(m, d, t, y, ev, max_ev, n, restart);
    }
    clear_settled(m, d);
    modes_account(m, d, t, y);
    return n;
}
