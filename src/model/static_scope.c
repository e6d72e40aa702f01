/*
 * The scope of the static analysis (/SOLVER Method 3, solver/static.c):
 * what it solves (contacts, friction by the return mapping, hysteresis,
 * Inacti 5, couplings of every kind, joints and their stops, imposed
 * translations and rotations), and a clear input error naming the card of
 * the first element it does not (docs/case-format.md, /SOLVER): friction
 * with no meaning at rest (viscous, step5, a law whose coefficient at zero
 * sliding speed is 0). Exact stick is solved (its friction force an
 * unknown). Called
 * where Method 3 is chosen: by the compiler for the deck's /SOLVER, by
 * rc_model_set_method, and by the static backend itself; and where a
 * preload (/SOLVER Preload 1) is asked for, which also needs the bodies at
 * rest (rc_preload_scope).
 */
#include <math.h>
#include <stdio.h>

#include "base/error.h"
#include "model/coupling.h"
#include "model/imposed.h"
#include "model/joint.h"
#include "model/model.h"
#include "model/power.h"
#include "model/sensor.h"
#include "model/table.h"

/* Friction the static analysis' return mapping takes (solver/static.c,
 * docs/theory.md 7.8): the incremental stick spring of TYPE6 (Fric, Sfric,
 * fct_IDff, fct_IDfv) or of a /FRICTION law (Ifric 0 to 3, any filter,
 * isotropic or orthotropic: the elliptic limit); exact stick is not this
 * (it has no stick spring: solver/static.c holds it by its own rows, and
 * rc_static_scope admits it). A law of the sliding speed is taken at rest
 * (v = 0: mu(p, 0), f_fv(0)); a filtered limit at rest equals the limit. */
int rc_static_friction_ok(const rc_fric *fr)
{
    if (fr->exact || fr->form != RC_FF_INCREMENTAL || !(fr->kt > 0)) return 0;
    if (fr->kind == RC_FK_TYPE6) return 1;
    if (fr->kind == RC_FK_CARD) return fr->ifric >= 0 && fr->ifric <= 3;
    return 0;
}

/* The largest of a + b p + c p^2 over p >= 0 (INFINITY: unbounded). */
static double quad_max(double a, double b, double c)
{
    if (c > 0) return INFINITY;
    if (c == 0) return b > 0 ? INFINITY : a;
    return b > 0 ? a - b * b / (4.0 * c) : a;
}

/* Why friction fr of interface i has no static friction at rest (NULL:
 * it has): the coefficient at zero sliding speed, mu(p, 0) of the law at
 * every pressure p >= 0 (0 where the law reads no pressure) or Fric
 * f_fv(0), is zero (floored) and no Sfric, so that the law gives no force
 * at rest whatever the load: nothing for the return mapping to hold. */
static const char *rest_zero(const rc_model *m, int i, const rc_fric *fr, char *buf, size_t nb)
{
    if (fr->kind == RC_FK_TYPE6) {
        if (fr->fct_fv < 0 || fr->sfric > 0) return NULL;
        const double fv0 = rc_table_value(&m->table[fr->fct_fv], 0.0);
        if (fr->fric * fv0 > 0) return NULL;
        snprintf(buf, nb, "a speed multiplier of friction (fct_IDfv) that is %g at zero sliding speed, with Sfric "
                 "0: no static friction at rest (the limit Fric f_fv(0) F_n is 0), and a static analysis has no "
                 "sliding speed", fv0);
        return buf;
    }
    if (fr->kind != RC_FK_CARD || fr->ifric == 0) return NULL;
    for (int k = 0; k < 1 + fr->ortho; k++) {
        const double *c = fr->set[k], fric = c[RC_FS_FRIC];
        const int pr = fr->area > 0; /* the law reads a pressure */
        double mx = 0.0;
        switch (fr->ifric) {
        case 1: mx = pr ? quad_max(fric, c[0], c[3]) : fric; break;        /* Fric + C1 p + C4 p^2 */
        case 2: mx = pr ? quad_max(fric + c[4], c[2], c[0]) : fric + c[4]; break; /* Fric + C5 + C3 p + C1 p^2 */
        default: mx = c[0]; break;                                          /* Renard: mu_s = C1 */
        }
        if (mx > 0) continue;
        static const char *const law[4] = {"", "generalised viscous (Ifric 1)", "modified Darmstad (Ifric 2)",
                                            "Renard (Ifric 3)"};
        snprintf(buf, nb, "a %s friction law whose coefficient at zero sliding speed, mu(p, v = 0), is 0 at every "
                 "pressure%s: no static friction at rest, and a static analysis has no sliding speed",
                 law[fr->ifric & 3], fr->ortho ? (k ? " in direction 2" : " in direction 1") : "");
        (void)i;
        return buf;
    }
    return NULL;
}

#define RC_STATIC_NOT "static analysis (/SOLVER Method 3) does not support %s in this version"

rc_status rc_static_scope(const rc_model *m, const char *how, rc_error *err)
{
    return rc_static_scope_alt(m, how, "Method 1 or 2", err);
}

rc_status rc_static_scope_alt(const rc_model *m, const char *how, const char *alt, rc_error *err)
{
    if (!how) how = "/SOLVER Method 3";
    if (!alt) alt = "Method 1 or 2";
    /* joints: their constraint rows and reactions (solver/static.c);
     * imposed translations are held displacements (the integral of the
     * velocity), imposed rotations held orientations (the rotation the
     * angular velocity turns the body by, rc_imp_rotation), each free after
     * its Tstop; a translation along a skew axis and a later start
     * (Tstart > 0) are not in this version */
    for (int k = 0; m->imp && k < m->imp->nt; k++)
        if (m->imp->tbcs[k])
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /BCS/%d: " RC_STATIC_NOT " (%s, /RBODY/%d); expected Tx Ty Tz all held or all "
                               "free with a skew, or %s",
                     RC_LOC(m->end_loc), m->imp->tbcs[k], "translations held along some of a skew's axes", how,
                     m->body_id[m->imp->tbody[k]], alt);
    for (int k = 0; m->imp && k < m->imp->nt; k++)
        if (m->imp->tdir[k] < 0)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /IMPVEL: " RC_STATIC_NOT " (%s, /RBODY/%d); expected a velocity along a global "
                               "axis, or %s",
                     RC_LOC(m->end_loc), "an imposed velocity along a skew axis (skew_ID)", how,
                     m->body_id[m->imp->tbody[k]], alt);
    for (int k = 0; m->imp && k < m->imp->nt; k++)
        if (isfinite(m->imp->ttstart[k]))
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /IMPVEL: " RC_STATIC_NOT " (%s, /RBODY/%d); expected Tstart <= 0 (a held "
                               "displacement from the load time 0), or %s",
                     RC_LOC(m->end_loc), "an imposed velocity starting later (Tstart > 0, or its sensor_ID's time > 0)", how,
                     m->body_id[m->imp->tbody[k]], alt);
    for (int k = 0; m->imp && k < m->imp->nt; k++)
        if (m->imp->tson[k] >= 0)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /IMPVEL, field sensor_ID: " RC_STATIC_NOT " (%s, /SENSOR/%s/%d on /RBODY/%d); "
                               "expected a /SENSOR/TIME, no sensor, or %s",
                     RC_LOC(m->end_loc), "an imposed velocity started by a sensor found in the run (a distance or "
                     "interface sensor)", how, rc_sensor_kind_name(m->sens_kind[m->imp->tson[k]]),
                     m->sens_id[m->imp->tson[k]], m->body_id[m->imp->tbody[k]], alt);
    if (m->grav_sens >= 0)
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card /GRAV, field sensor_ID: " RC_STATIC_NOT " (%s, /SENSOR/%s/%d); expected a "
                           "/SENSOR/TIME, no sensor, or %s",
                 RC_LOC(m->end_loc), "a gravity switched on by a sensor found in the run (a distance or interface "
                 "sensor)", how, rc_sensor_kind_name(m->sens_kind[m->grav_sens]), m->sens_id[m->grav_sens], alt);
    /* a gravity switched on by a sensor at Ts > 0 jumps on the load path */
    if (m->grav_tstart > 0) {
        char gw[96];
        snprintf(gw, sizeof gw, "a gravity switched on by its sensor at %.9g s", m->grav_tstart);
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card /GRAV, field sensor_ID: " RC_STATIC_NOT " (%s); expected a sensor on from t = 0 "
                           "(Tdelay 0), no sensor, or %s",
                 RC_LOC(m->end_loc), gw, how, alt);
    }
    /* a distance or interface sensor's trigger is an event of a dynamic run */
    for (int i = 0; i < m->ninter; i++)
        if (m->inter_sens[i] >= 0)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card %s, field Isensor: " RC_STATIC_NOT " (%s, /SENSOR/%s/%d); expected a "
                               "/SENSOR/TIME, no sensor, or %s",
                     RC_LOC(m->inter_loc[i]), m->inter_name[i],
                     "an interface turned on by a sensor found in the run (a distance or interface sensor)", how,
                     rc_sensor_kind_name(m->sens_kind[m->inter_sens[i]]), m->sens_id[m->inter_sens[i]], alt);
    for (int k = 0; m->imp && k < m->imp->nt; k++)
        if (m->imp->tsens[k] >= 0)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /RBODY/%d, field sens_ID: " RC_STATIC_NOT " (%s, /SENSOR %d); expected a "
                               "/SENSOR/TIME, no sensor, or %s",
                     RC_LOC(m->body_loc[m->imp->tbody[k]]), m->body_id[m->imp->tbody[k]],
                     "a body released by a sensor found in the run", how, m->sens_id[m->imp->tsens[k]], alt);
    for (int i = 0; i < m->ninter; i++) {
        const rc_fric *fr = &m->inter_fr[i];
        const char *what = NULL;
        char fbuf[420];
        char rbuf[320];
        /* exact stick (TYPE6 Istick 1, /FRICTION Iform 3): the friction
         * force an unknown of the equilibrium, the stuck contact held by its
         * row (solver/static.c); its law is Coulomb's at rest (the compiler
         * refuses fct_IDfv, filters, orthotropy and several contact points
         * with it) */
        if (fr->exact) {
            if (fr->tidx < 0 || m->inter_npt[i] > 0)
                what = "exact stick on this pair (no single friction state)";
        } else if (!rc_inter_frictionless(m, i) && !rc_static_friction_ok(fr)) {
            const char *why = fr->kind == RC_FK_STEP5
                                  ? "the power law's step5 friction (its force mu(s) F_n along the sliding speed s is "
                                    "zero at rest)"
                              : fr->form != RC_FF_INCREMENTAL
                                  ? "viscous friction (/FRICTION Iform 1: F = -C v_t, zero at rest; no stick state "
                                    "to hold a load)"
                              : "this friction";
            if (fr->card_id > 0) snprintf(fbuf, sizeof fbuf, "%s (/FRICTION/%d on it)", why, fr->card_id);
            else snprintf(fbuf, sizeof fbuf, "%s (its own friction fields)", why);
            what = fbuf;
        } else if (!rc_inter_frictionless(m, i) && rest_zero(m, i, fr, rbuf, sizeof rbuf)) {
            if (fr->card_id > 0) snprintf(fbuf, sizeof fbuf, "%s (/FRICTION/%d on it)", rbuf, fr->card_id);
            else snprintf(fbuf, sizeof fbuf, "%s (its own friction fields)", rbuf);
            what = fbuf;
        } else if (rc_pair_nodes(m->inter_pair[i]) && !rc_inter_frictionless(m, i) &&
                   !(m->inter_npt[i] > 0 && (m->inter_pst[i] == 3 || m->inter_pst[i] == 6)))
            /* a guard, not a limit of the scope: the compiler's layout gives
             * every node pair with friction its points' states (inter_npt >
             * 0, 3 or 6 each: model/compile.c), so that friction per point
             * (solver/static.c) takes every law the branches above let
             * through, on boxes and segment surfaces alike; a pair without
             * them would have no state to hold a tangential load */
            what = "this friction on a pair of several contact points (no friction state per point)";
        if (what)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card %s: " RC_STATIC_NOT " (%s); expected a contact of TYPE6 (any Iform), "
                               "frictionless or with the stick-spring friction of TYPE6 (Sfric, Fric, fct_IDff, fct_IDfv) "
                               "or of a /FRICTION law in the incremental form (Iform 2), or exact stick (Istick 1, Iform 3), "
                               "or of the power law without friction, between spheres, planes, boxes or "
                               "cylinders, boxes or segment surfaces, or %s",
                     RC_LOC(m->inter_loc[i]), m->inter_name[i], what, how, alt);
    }
    /* couplings: springs, catenaries (forces of the positions), contact
     * couplings and joint stops (their modes an active set, as the
     * contacts'; solver/static.c) */
    return RC_OK;
}

rc_status rc_preload_scope(const rc_model *m, const char *how, rc_error *err)
{
    if (!how) how = "/SOLVER field Preload";
    char why[600];
    snprintf(why, sizeof why, "a preload, asked for by %s, solves the static equilibrium at t = 0 and needs the static "
             "analysis' scope", how);
    rc_status st = rc_static_scope_alt(m, why, "no preload (/SOLVER Preload 0)", err);
    if (st) return st;
    /* the dynamic run starts from the equilibrium's positions and friction
     * forces; a hysteresis state (TYPE6 Iform 1, 2) is not carried over */
    for (int i = 0; i < m->ninter; i++)
        if (m->inter_law[i] == RC_LAW_TYPE6 && m->inter_iform[i] != 0)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card %s: a preload, asked for by %s, does not support TYPE6 Iform %d (its hysteresis "
                               "state is not carried into the dynamic run in this version); expected Iform 0, or no "
                               "preload (/SOLVER Preload 0)",
                     RC_LOC(m->inter_loc[i]), m->inter_name[i], how, m->inter_iform[i]);
    /* Inacti 5: the dynamic run's start takes a penetration as its gap
     * offset (force-free), which would undo the equilibrium's force */
    for (int i = 0; i < m->ninter; i++)
        if (m->inter_oidx[i] >= 0)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card %s: a preload, asked for by %s, does not support Inacti 5 (the dynamic run's "
                               "start would take the equilibrium's penetration as its gap offset and lose its force); "
                               "expected Inacti 0, or no preload (/SOLVER Preload 0)",
                     RC_LOC(m->inter_loc[i]), m->inter_name[i], how);
    /* the dynamic run starts from the equilibrium at rest */
    for (int b = 0; b < m->nbody; b++) {
        if (m->body_yadr[b] < 0) continue;
        const double *v = m->body_y0 + RC_NB * b + 7, *w = v + 3;
        const double vn = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), wn = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        if (vn != 0.0 || wn != 0.0)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /RBODY/%d: initial velocity %g m/s, angular velocity %g rad/s (/INIVEL): a "
                               "preload, asked for by %s, starts the dynamic run from the static equilibrium at "
                               "rest; expected a body at rest (no /INIVEL on it), or no preload (/SOLVER Preload 0)",
                     RC_LOC(m->body_loc[b]), m->body_id[b], vn, wn, how);
    }
    return RC_OK;
}
