/*
 * The start of a run: bodies that overlap at t = 0 (docs/theory.md,
 * "Physics checks of every run", the start).
 *
 * A contact that starts penetrating, in the modes the run starts in (an
 * Inacti 5 offset takes the penetration as a gap reduction; Icor 1 with
 * Iform 1 declares it a plastic deformation already there, started on the
 * unload curve: both account for it), holds the elastic energy E_0 of its law at
 * that penetration, which it releases into the bodies at once. A resting
 * start (a body placed at its static penetration under its weight, a stack)
 * holds E_0 = F p / 2 (linear law) with F at most the scene's weight and p
 * the static penetration: E_0 / (M g L) = p / (2 L), far below 1 unless the
 * body sinks by twice its size. An overlap holding more than E_s (the
 * scene's energy scale, bounds.c) is therefore not a resting start but a
 * body placed inside another: an input error naming both surfaces, the
 * interface, the depth, the force and the energy, before anything runs.
 * Overlaps within the touch band (rounding of the coordinates) are touching.
 *
 * Segment surfaces: when the overlap disappears with one surface's
 * normals reversed, its normals point away from the other surface (IRS or
 * IRm of the interface the wrong way, e.g. a box on a meshed floor that
 * then overlaps by its whole thickness); the message says so and gives the
 * value of the field that makes them face each other.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "engine/assembly/bounds.h"
#include "engine/assembly/assembly.h"
#include "engine/events/events.h"
#include "engine/analyses/analyses.h"

/* Overlaps within RC_START_TOUCH_ULPS ulps of the coordinates, or
 * RC_START_TOUCH_REL of the penetration scale, are touching [-]. */
#define RC_START_TOUCH_ULPS 1e3
#define RC_START_TOUCH_REL 1e-9

/* "/SURF/PLANE/2" for surface s (the card it was read from). */
static void surf_card(const rc_case *c, const rc_model *m, int s, char *buf, size_t n)
{
    static const char *const kind[] = {"", "PLANE", "ELLIPS", "CYL", "BOX", "SEG", "PART"};
    static const char *const wall[] = {"", "PLANE", "CYL", "SPHER", "PARAL"};
    /* a wall's surface carries the id -rwall_ID (model/rwall.c) */
    const int w = m->surf_id[s] < 0 ? rc_case_find_rwall(c, -m->surf_id[s]) : -1;
    if (w >= 0) {
        snprintf(buf, n, "/RWALL/%s/%d", wall[c->rwall[w].kind], c->rwall[w].id);
        return;
    }
    const int k = rc_case_find_surf(c, m->surf_id[s]);
    const int ck = k >= 0 ? (int)c->surf[k].kind : 0;
    snprintf(buf, n, "/SURF/%s/%d", ck >= 1 && ck <= 6 ? kind[ck] : "?", m->surf_id[s]);
}

/* The TYPE6 card of interface i (NULL: a power-law interface). */
static const rc_case_type6 *type6_card(const rc_case *c, const rc_model *m, int i)
{
    if (strncmp(m->inter_name[i], "/INTER/TYPE6/", 13)) return NULL;
    for (int k = 0; k < c->ntype6; k++)
        if (c->type6[k].id == m->inter_id[i]) return &c->type6[k];
    return NULL;
}

/* Touching band of interface i at the state y [m]. */
static double touch_band(const rc_model *m, int i, const double *y, const rc_inter_report *r)
{
    return rc_touch_band(m, i, y, r, RC_START_TOUCH_ULPS, RC_START_TOUCH_REL, 1);
}

/* The IRS/IRm advice for interface i: the side whose reversed normals
 * remove the overlap, written into buf (empty: none). */
static void facing_advice(const rc_case *c, rc_model *m, int i, const double *y, double band, char *buf, size_t n)
{
    buf[0] = '\0';
    const rc_case_type6 *t6 = type6_card(c, m, i);
    if (!t6) return;
    for (int e = 0; e < 2; e++) {
        const int s = e ? m->inter_sb[i] : m->inter_sa[i];
        if (m->surf_kind[s] != RC_SURF_SEG) continue;
        int *o = m->inter_orient + 2 * i + e;
        const int was = *o, now = was == 1 ? 0 : 1;
        *o = now;
        rc_inter_report r;
        rc_inter_report_eval(m, i, RC_MODE_OPEN, RC_BR_LOAD, 0, 0, 0.0, y, &r);
        *o = was;
        if (!(r.p_raw <= band)) continue;
        char sc[64], oc[64];
        surf_card(c, m, s, sc, sizeof sc);
        surf_card(c, m, e ? m->inter_sa[i] : m->inter_sb[i], oc, sizeof oc);
        const int is_irs = m->surf_id[s] == t6->surf1;
        snprintf(buf, n,
                 "; the segment normals of %s point away from %s (%s = %d: %s), so the surfaces do not face each "
                 "other: with %s = %d (%s) they start apart",
                 sc, oc, is_irs ? "IRS" : "IRm", was,
                 was == 0 ? "as built" : was == 1 ? "reversed" : "as the elements number them", is_irs ? "IRS" : "IRm",
                 now, now == 1 ? "reversed" : "as built");
        return;
    }
}

/* An accepted overlap deeper than this many penetrations under the weight
 * is said (a model notice): a resting start sits at about one [-]. */
#define RC_START_DEEP_FACTOR 10.0

rc_status rc_start_check(const rc_case *c, rc_model *m, rc_error *err)
{
    if (m->ninter == 0) return RC_OK;
    rc_scene sc;
    rc_scene_scales(m, &sc);
    double *y = malloc(((size_t)m->ny + 1) * sizeof *y);
    rc_data *d = rc_data_new(m);
    if (!y || !d) {
        free(y);
        rc_data_free(d);
        RC_RAISE(err, RC_ENOMEM, "out of memory for the start check");
    }
    rc_initial_state(m, y);
    rc_modes_init(m, d, 0.0, y); /* Inacti 5 offsets, initial F_h */
    const double allow = RC_START_ENERGY_FACTOR * sc.escale;
    rc_status st = RC_OK;
    for (int i = 0; i < m->ninter && !st; i++) {
        const int mode = d->inter_mode[i];
        if (mode != RC_MODE_CLOSED && mode != RC_MODE_RELEASED) continue; /* apart, touching, or not yet active */
        if (m->inter_icor[i] == 1 && m->inter_iform[i] == 1) continue; /* Icor 1: a plastic overlap declared */
        rc_inter_report r;
        rc_inter_report_eval(m, i, RC_MODE_OPEN, RC_BR_LOAD, 0, 0, 0.0, y, &r);
        const double band = touch_band(m, i, y, &r);
        if (!(r.p_raw > band)) continue;
        const double e0 = rc_inter_stored_energy(m, d, i, 0.0, y);
        if (!(e0 > allow) && isfinite(e0)) {
            /* accepted, but deeper than a resting start: said */
            const double pw = m->inter_pweight[i];
            if (isfinite(pw) && pw > 0 && r.p_raw > RC_START_DEEP_FACTOR * pw) {
                const size_t ns = 640;
                char *s = malloc(ns);
                if (!s) st = RC_SET(err, RC_ENOMEM, "out of memory for the start check");
                else {
                    snprintf(s, ns,
                             RC_LOCFMT "card %s: the surfaces overlap at t = 0 by %.6g m past the Gap, %.3g times "
                             "the penetration under the weight (%.3g m): accepted, as the law holds %.3g J there, "
                             "at most the scene's energy scale E_s = %.3g J, which it releases into the bodies at "
                             "once; if they should touch, move them apart, or set Inacti = 5 (the initial "
                             "penetration taken as a reduction of the gap)",
                             RC_LOC(m->inter_loc[i]), m->inter_name[i], r.p_raw, r.p_raw / pw, pw, e0, sc.escale);
                    st = rc_model_add_note(m, s, err);
                }
            }
            continue;
        }
        rc_inter_report rc;
        rc_inter_report_eval_d(m, d, i, 0.0, y, &rc);
        char sa[64], sb[64], adv[512];
        surf_card(c, m, m->inter_sa[i], sa, sizeof sa);
        surf_card(c, m, m->inter_sb[i], sb, sizeof sb);
        facing_advice(c, m, i, y, band, adv, sizeof adv);
        const double mr = m->inter_mred[i];
        char speed[96] = "";
        if (isfinite(mr) && mr > 0) snprintf(speed, sizeof speed, " (a separation speed up to %.3g m/s)", sqrt(2.0 * e0 / mr));
        st = RC_SET(err, RC_EINPUT,
                    RC_LOCFMT "card %s: the surfaces %s and %s overlap at t = 0: penetration %.6g m past the Gap "
                    "(%.6g m), so the contact starts with a force of %.6g N and %.6g J of elastic energy%s, more than "
                    "the scene's energy scale E_s = %.6g J (the larger of the initial kinetic energy and M g L); a "
                    "body resting at its static penetration holds far less%s; expected the bodies apart or touching "
                    "at t = 0, or Inacti = 5 (the initial penetration taken as a reduction of the gap)",
                    RC_LOC(m->inter_loc[i]), m->inter_name[i], sa, sb, r.p_raw, m->inter_gap[i], rc.fn, e0, speed,
                    sc.escale, adv);
        /* /RUN On_viol 2: the deck asks to go on; the overlap is kept for
         * the run's physics checks (the first row of its violations) */
        if (m->on_violation == 2) {
            if (!m->start_note) {
                m->start_note = malloc(strlen(err->msg) + 1);
                if (!m->start_note) break;
                strcpy(m->start_note, err->msg);
                m->start_inter = i;
                m->start_energy = e0;
                m->start_escale = sc.escale;
            }
            rc_error_clear(err);
            st = RC_OK;
        }
    }
    free(y);
    rc_data_free(d);
    return st;
}
