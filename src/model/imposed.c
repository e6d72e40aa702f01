/*
 * Imposed velocities (/IMPVEL): compile, state layout, Jacobian pattern
 * (imposed.h). The right-hand side and Jacobian parts are
 * engine/assembly/imposed_rhs.c and imposed_jac.c.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "case/case.h"
#include "case/case_mesh.h"
#include "case/case_power.h"
#include "base/error.h"
#include "model/imposed.h"
#include "model/sensor.h"

/* Two axes held on one body by /BCS: the same when |cos| > 1 - tol,
 * orthogonal when |cos| <= tol */
#define RC_BCS_AXIS_TOL 1e-9


void rc_imp_free(rc_imposed *p)
{
    if (!p) return;
    void *a[] = {p->tu, p->tsk, p->sslot, p->tbody, p->tdir, p->trow, p->ttab, p->tbcs, p->tfirst, p->tascale, p->tfscale, p->ttstop, p->ttstart, p->ttshift, p->tsens, p->tson, p->rsens, p->rbody, p->rtab,
                 p->rascale, p->rfscale, p->rtstop, p->rqslot, p->wslot, p->row_imp};
    for (size_t k = 0; k < sizeof a / sizeof a[0]; k++) free(a[k]);
    free(p);
}

double rc_imp_tspeed(const rc_model *m, int k)
{
    const rc_imposed *p = m->imp;
    return p->ttab[k] < 0 ? 0.0 : fabs(p->tfscale[k]) * rc_table_max_abs(&m->table[p->ttab[k]]);
}

double rc_imp_rrate(const rc_model *m, int k, int j)
{
    const rc_imposed *p = m->imp;
    const int tab = p->rtab[3 * k + j];
    return tab < 0 ? 0.0 : fabs(p->rfscale[3 * k + j]) * rc_table_max_abs(&m->table[tab]);
}

/* The translations that /BCS cards with a skew hold along its axes (one or
 * two of Tx Ty Tz, rc_bcs_skewed_translations): for each body of the card's
 * group, each held axis (a unit vector in global axes), the card's id;
 * owner: the /IMPVEL card driving each body DOF (-1: none). A node in no
 * body (fixed in space) and a fixed body are left out; an axis a body
 * already holds (the group naming it twice, two cards on one skew) is
 * taken once. A body's /IMPVEL along an oblique skew axis (dir -1, u_imp)
 * is applied the same way: its axis must be orthogonal to the held ones.
 * Refused, not supported yet: a moving skew (its axes turn with its nodes),
 * a body with a translation imposed or held along a global axis (rows that
 * another rule writes), axes that are not orthogonal (the projections
 * applied one after the other are the projection on the free axes only for
 * orthogonal ones). */
static rc_status bcs_skew_holds(const rc_case *c, const rc_model *m, const int *owner, const int *dir,
                                const double *u_imp, int **hb_out, double **hu_out, int **hid_out, int *nh_out,
                                rc_error *err)
{
    int cap = 0;
    for (int k = 0; k < c->nbcs; k++) {
        const int g = rc_case_find_grnod(c, c->bcs[k].grnod_id);
        if (rc_bcs_skewed_translations(&c->bcs[k]) && g >= 0) cap += 2 * c->grnod[g].n;
    }
    int *hb = malloc(((size_t)cap + 1) * sizeof(int)), *hid = malloc(((size_t)cap + 1) * sizeof(int));
    double *hu = malloc((3 * (size_t)cap + 1) * sizeof(double));
    int nh = 0;
    rc_status st = RC_OK;
    if (!hb || !hid || !hu) st = RC_SET(err, RC_ENOMEM, "out of memory");
    for (int k = 0; k < c->nbcs && !st; k++) {
        const rc_case_bcs *bc = &c->bcs[k];
        if (!rc_bcs_skewed_translations(bc)) continue;
        const rc_loc bl = rc_loc_or(bc->line_loc, bc->loc);
        const int s = rc_case_find_skew(c, bc->skew_id), g = rc_case_find_grnod(c, bc->grnod_id);
        if (s < 0 || g < 0) continue; /* the reader and the /BCS compile name these */
        const rc_case_skew *sk = &c->mesh->skew[s];
        if (sk->mov) {
            st = RC_SET(err, RC_EINPUT,
                        RC_LOCFMT "card /BCS/%d, field skew_ID: /SKEW/%s/%d moves with its nodes: translations held "
                        "along some of its axes are not supported yet (expected a /SKEW/FIX, or Tx Ty Tz all held or "
                        "all free)",
                        RC_LOC(bl), bc->id, sk->mov == 2 ? "MOV2" : "MOV", sk->id);
            break;
        }
        for (int j = 0; j < c->grnod[g].n && !st; j++) {
            const int b = rc_case_body_of_node(c, c->grnod[g].nodes[j]);
            if (b < 0 || m->body_fixed[b]) continue;
            const int *own = owner + 6 * b;
            const int imp = own[0] >= 0 ? own[0] : own[1] >= 0 ? own[1] : own[2];
            if (imp >= 0 && dir[imp] >= 0) {
                st = RC_SET(err, RC_EINPUT,
                            RC_LOCFMT "card /BCS/%d, field skew_ID: /RBODY/%d also has a translation imposed along a "
                            "global axis (/IMPVEL/%d; a skew axis that is exactly a global one counts as one): "
                            "translations held along a skew's axes together with it are not supported yet (expected "
                            "the /IMPVEL along an oblique axis of a /SKEW/FIX, orthogonal to the held ones)",
                            RC_LOC(bl), bc->id, m->body_id[b], c->impvel[imp].id);
                break;
            }
            if (m->body_dofmask[6 * b] || m->body_dofmask[6 * b + 1] || m->body_dofmask[6 * b + 2]) {
                st = RC_SET(err, RC_EINPUT,
                            RC_LOCFMT "card /BCS/%d, field skew_ID: /RBODY/%d also has a translation held along a "
                            "global axis by another /BCS: global and skewed translation holds on one body are not "
                            "supported yet together (expected one /BCS, or the holds along one skew's axes)",
                            RC_LOC(bl), bc->id, m->body_id[b]);
                break;
            }
            for (int a = 0; a < 3 && !st; a++) {
                if (bc->fix[a] != 1) continue;
                const double *u = sk->axis[a];
                int dup = 0;
                if (imp >= 0) { /* the body's velocity imposed along a skew axis */
                    const double *ui = u_imp + 3 * imp;
                    const double d = u[0] * ui[0] + u[1] * ui[1] + u[2] * ui[2];
                    if (!(fabs(d) <= RC_BCS_AXIS_TOL)) {
                        st = RC_SET(err, RC_EINPUT,
                                    RC_LOCFMT "card /BCS/%d, field skew_ID: /RBODY/%d holds a translation along the "
                                    "%c' axis of /SKEW/FIX/%d, which is not orthogonal to the axis /IMPVEL/%d imposes "
                                    "its velocity along (cosine %.6g): expected a held axis orthogonal to the "
                                    "imposed one",
                                    RC_LOC(bl), bc->id, m->body_id[b], "XYZ"[a], sk->id, c->impvel[imp].id, d);
                        break;
                    }
                }
                for (int h = 0; h < nh && !st && !dup; h++) {
                    if (hb[h] != b) continue;
                    const double d = u[0] * hu[3 * h] + u[1] * hu[3 * h + 1] + u[2] * hu[3 * h + 2];
                    if (fabs(d) > 1.0 - RC_BCS_AXIS_TOL) dup = 1;
                    else if (fabs(d) > RC_BCS_AXIS_TOL)
                        st = RC_SET(err, RC_EINPUT,
                                    RC_LOCFMT "card /BCS/%d, field skew_ID: /RBODY/%d holds a translation along the "
                                    "%c' axis of /SKEW/FIX/%d, which is not orthogonal to one /BCS/%d holds (cosine "
                                    "%.6g): holds along axes of different skews are supported when orthogonal only",
                                    RC_LOC(bl), bc->id, m->body_id[b], "XYZ"[a], sk->id, hid[h], d);
                }
                if (st || dup) continue;
                hb[nh] = b;
                hid[nh] = bc->id;
                for (int i = 0; i < 3; i++) hu[3 * nh + i] = u[i];
                nh++;
            }
        }
    }
    if (st) {
        free(hb);
        free(hu);
        free(hid);
        hb = hid = NULL;
        hu = NULL;
        nh = 0;
    }
    *hb_out = hb;
    *hu_out = hu;
    *hid_out = hid;
    *nh_out = nh;
    return st;
}

rc_status rc_imp_compile(const rc_case *c, rc_model *m, rc_error *err)
{
    m->imp = NULL;
    int nbs = 0; /* /BCS cards holding translations along a skew's axes */
    for (int k = 0; k < c->nbcs; k++) nbs += rc_bcs_skewed_translations(&c->bcs[k]);
    if (c->nimpvel == 0 && nbs == 0) return RC_OK;
    const int n = c->nimpvel, nb = m->nbody;
    rc_imposed *p = calloc(1, sizeof *p);
    /* which card drives each body DOF (-1: none) */
    int *owner = malloc((6 * (size_t)nb + 1) * sizeof(int));
    if (!p || !owner) {
        free(owner);
        rc_imp_free(p);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    m->imp = p;
    for (int k = 0; k < 6 * nb; k++) owner[k] = -1;
    /* each card's direction: a global axis (dir[k] 0..5, sign[k] +-1), or a
     * skew axis (dir[k] = -1, u[k]) */
    int *dir = malloc(((size_t)n + 1) * sizeof(int));
    double *u = malloc((3 * (size_t)n + 1) * sizeof(double)), *sign = malloc(((size_t)n + 1) * sizeof(double));
    /* each card's start and the shift of its function [s]: with a sensor
     * (sensor_ID), the sensor's time on Ts, imposed over (Ts, Tstop] as
     * f((t - Ts) / Ascale) (Radioss: the function shifted by the
     * activation time, imposed only when Ts is within [Tstart, Tstop]);
     * without, Tstart and no shift */
    double *tst = malloc(((size_t)n + 1) * sizeof(double)), *tsh = malloc(((size_t)n + 1) * sizeof(double));
    int *ton_rt = malloc(((size_t)n + 1) * sizeof(int)); /* a sensor found in the run, -1 */
    rc_status st = RC_OK;
    if (!dir || !u || !sign || !tst || !tsh || !ton_rt) st = RC_SET(err, RC_ENOMEM, "out of memory");
    for (int k = 0; k < n && !st; k++) {
        const rc_case_impvel *v = &c->impvel[k];
        tst[k] = v->tstart;
        tsh[k] = 0.0;
        ton_rt[k] = -1;
        if (v->sensor_id) {
            char card[64];
            snprintf(card, sizeof card, "/IMPVEL/%d", v->id);
            double ton;
            if ((st = rc_sensor_load_on(c, v->sensor_id, v->line_loc[0], card, "an imposed velocity", &ton, &ton_rt[k],
                                        err)))
                break;
            const char *kn = rc_sensor_kind_name((int)c->sensor[rc_case_find_sensor(c, v->sensor_id)].kind);
            if (ton_rt[k] >= 0) {
                /* a start at the sensor's event: a translation, Tstart <= 0 */
                if (v->dir >= 3)
                    st = RC_SET(err, RC_EINPUT,
                                RC_LOCFMT "card %s, field sensor_ID: /SENSOR/%s/%d turns on at a time found in the "
                                "run: a later start of an imposed rotation (Dir %s, a jump of the angular velocity) "
                                "is not supported yet; expected a translation (Dir X, Y, Z), or no sensor",
                                RC_LOC(v->line_loc[0]), card, kn, v->sensor_id, v->dir == 3 ? "XX" : v->dir == 4 ? "YY" : "ZZ");
                else if (v->tstart > 0)
                    st = RC_SET(err, RC_EINPUT,
                                RC_LOCFMT "card %s, field Tstart: /SENSOR/%s/%d turns on at a time found in the run: "
                                "a window [Tstart, Tstop) that its time must fall in, with Tstart > 0 (%.9g s), is not "
                                "supported yet; expected Tstart <= 0 with a distance or interface sensor",
                                RC_LOC(v->line_loc[1]), card, kn, v->sensor_id, v->tstart);
                if (st) break;
                tst[k] = INFINITY; /* free (its initial velocity) until the event */
            } else if (ton < v->tstart || !(ton < v->tstop)) {
                st = RC_SET(err, RC_EINPUT,
                            RC_LOCFMT "card %s, field sensor_ID: /SENSOR/%s/%d turns on at %.9g s, outside [Tstart, "
                            "Tstop) = [%.9g, %.9g) s: the velocity is imposed only when its sensor turns on within "
                            "that window, so it would never act; expected a sensor time within [Tstart, Tstop)",
                            RC_LOC(v->line_loc[0]), card, kn, v->sensor_id, ton, v->tstart, v->tstop);
                break;
            } else if (ton > 0 && v->dir >= 3) {
                st = RC_SET(err, RC_EINPUT,
                            RC_LOCFMT "card %s, field sensor_ID: /SENSOR/%s/%d turns on at %.9g s > 0: a later start "
                            "of an imposed rotation (Dir %s, a jump of the angular velocity) is not supported yet; "
                            "expected a sensor on from t = 0 (Tdelay 0) for a rotation, or no sensor",
                            RC_LOC(v->line_loc[0]), card, kn, v->sensor_id, ton, v->dir == 3 ? "XX" : v->dir == 4 ? "YY" : "ZZ");
                break;
            } else {
                tst[k] = ton;
                tsh[k] = ton;
            }
        }
        dir[k] = v->dir;
        sign[k] = 1.0;
        for (int i = 0; i < 3; i++) u[3 * k + i] = v->dir == i;
        if (!v->skew_id) continue;
        char card[64];
        snprintf(card, sizeof card, "/IMPVEL/%d", v->id);
        const int s = rc_case_find_skew(c, v->skew_id);
        if (s < 0) {
            st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card %s, field skew_ID: expected the id of a /SKEW/FIX, got %d (no such skew)",
                        RC_LOC(v->line_loc[0]), card, v->skew_id);
            break;
        }
        const rc_case_skew *sk = &c->mesh->skew[s];
        if (sk->mov) {
            st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card %s, field skew_ID: /SKEW/%s/%d moves with its nodes: an imposed velocity along a moving axis is not supported yet (expected a /SKEW/FIX)",
                        RC_LOC(v->line_loc[0]), card, sk->mov == 2 ? "MOV2" : "MOV", sk->id);
            break;
        }
        for (int i = 0; i < 3; i++) u[3 * k + i] = sk->axis[v->dir][i];
        /* an axis that is a global one (exactly, either sense) is that
         * component; any other is a skew axis */
        dir[k] = -1;
        for (int i = 0; i < 3 && dir[k] < 0; i++)
            if (fabs(u[3 * k + i]) == 1.0 && u[3 * k + (i + 1) % 3] == 0.0 && u[3 * k + (i + 2) % 3] == 0.0) {
                sign[k] = u[3 * k + i];
                u[3 * k + i] = 1.0;
                dir[k] = i;
            }
    }
    for (int k = 0; k < n && !st; k++) {
        const rc_case_impvel *v = &c->impvel[k];
        char card[64];
        snprintf(card, sizeof card, "/IMPVEL/%d", v->id);
        int tab;
        if ((st = rc_case_ref_funct(c, v->fct_id, 1, v->line_loc[0], card, "fct_IDT", &tab, err))) break;
        const int g = rc_case_find_grnod(c, v->grnod_id);
        if (g < 0) {
            st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card %s, field grnod_ID: expected the id of a /GRNOD, got %d (no such group)",
                        RC_LOC(v->line_loc[0]), card, v->grnod_id);
            break;
        }
        for (int j = 0; j < c->grnod[g].n && !st; j++) {
            const int b = rc_case_body_of_node(c, c->grnod[g].nodes[j]);
            if (b < 0) {
                st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card %s: node %d of /GRNOD/%d belongs to no /RBODY (ricochet bodies are rigid)",
                            RC_LOC(v->line_loc[0]), card, c->grnod[g].nodes[j], v->grnod_id);
                break;
            }
            const int *own = owner + 6 * b;
            if (dir[k] < 0) { /* along a skew axis: the body's three translations */
                if (own[0] == k) continue;
                const int held = m->body_dofmask[6 * b] || m->body_dofmask[6 * b + 1] || m->body_dofmask[6 * b + 2];
                const int other = own[0] >= 0 ? own[0] : own[1] >= 0 ? own[1] : own[2];
                if (m->body_fixed[b])
                    st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card %s: /RBODY/%d is fixed (/BCS 111 111); its velocity cannot be imposed",
                                RC_LOC(v->line_loc[0]), card, m->body_id[b]);
                else if (held)
                    st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card %s, field skew_ID: /RBODY/%d has a translation held by /BCS; a velocity along a skew axis with held translations is not supported yet",
                                RC_LOC(v->line_loc[0]), card, m->body_id[b]);
                else if (other >= 0)
                    st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card %s, field skew_ID: /RBODY/%d already has an imposed translation (/IMPVEL/%d); a velocity along a skew axis must be its only one (not supported yet)",
                                RC_LOC(v->line_loc[0]), card, m->body_id[b], c->impvel[other].id);
                for (int i = 0; i < 3 && !st; i++) owner[6 * b + i] = k;
                continue;
            }
            const int dk = dir[k];
            if (own[dk] == k) continue; /* the body named twice by the group */
            if (dk < 3 && own[0] >= 0 && dir[own[0]] < 0)
                st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card %s, field Dir: the translation of /RBODY/%d is already imposed along a skew axis by /IMPVEL/%d (not supported yet together)",
                            RC_LOC(v->line_loc[0]), card, m->body_id[b], c->impvel[own[0]].id);
            else if (m->body_fixed[b])
                st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card %s: /RBODY/%d is fixed (/BCS 111 111); its velocity cannot be imposed",
                            RC_LOC(v->line_loc[0]), card, m->body_id[b]);
            else if (m->body_dofmask[6 * b + dk])
                st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card %s, field Dir: this component of /RBODY/%d is held by /BCS; a held DOF cannot also be imposed",
                            RC_LOC(v->line_loc[0]), card, m->body_id[b]);
            else if (own[dk] >= 0)
                st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card %s, field Dir: this component of /RBODY/%d is already imposed by /IMPVEL/%d",
                            RC_LOC(v->line_loc[0]), card, m->body_id[b], c->impvel[own[dk]].id);
            for (int r = 3; r < 6 && !st && v->dir >= 3; r++)
                if (own[r] >= 0 && c->impvel[own[r]].tstop != v->tstop)
                    st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card %s, field Tstop: the rotation of /RBODY/%d is imposed as a whole (docs/theory.md 1.1); all its rotational /IMPVEL must share one Tstop (/IMPVEL/%d has %.6g)",
                                RC_LOC(v->line_loc[1]), card, m->body_id[b], c->impvel[own[r]].id, c->impvel[own[r]].tstop);
            if (!st) owner[6 * b + dk] = k;
        }
    }
    /* the translations held along skew axes by /BCS (hb, hu, hid: body,
     * axis, card, nh of them) */
    int nh = 0, *hb = NULL, *hid = NULL;
    double *hu = NULL;
    if (!st && nbs) st = bcs_skew_holds(c, m, owner, dir, u, &hb, &hu, &hid, &nh, err);
    /* count and fill: translations one by one (a skewed card once per
     * body), rotations per body */
    for (int b = 0; b < nb && !st; b++) {
        int rot = 0;
        for (int j = 0; j < 6; j++) {
            const int k = owner[6 * b + j];
            if (k < 0 || (j > 0 && j < 3 && dir[k] < 0)) continue;
            if (j < 3) p->nt++;
            else rot = 1;
        }
        p->nr += rot;
    }
    p->nt += nh;
    if (!st) {
        p->tbody = calloc((size_t)p->nt + 1, sizeof(int));
        p->tdir = calloc((size_t)p->nt + 1, sizeof(int));
        p->trow = calloc((size_t)p->nt + 1, sizeof(int));
        p->ttab = calloc((size_t)p->nt + 1, sizeof(int));
        p->tbcs = calloc((size_t)p->nt + 1, sizeof(int));
        p->tfirst = calloc((size_t)p->nt + 1, 1);
        p->tascale = calloc((size_t)p->nt + 1, sizeof(double));
        p->tfscale = calloc((size_t)p->nt + 1, sizeof(double));
        p->ttstop = calloc((size_t)p->nt + 1, sizeof(double));
        p->ttstart = calloc((size_t)p->nt + 1, sizeof(double));
        p->ttshift = calloc((size_t)p->nt + 1, sizeof(double));
        p->tson = calloc((size_t)p->nt + 1, sizeof(int));
        p->tsens = calloc((size_t)p->nt + 1, sizeof(int));
        p->rsens = calloc((size_t)p->nr + 1, sizeof(int));
        p->tu = calloc(3 * (size_t)p->nt + 1, sizeof(double));
        p->tsk = calloc((size_t)p->nt + 1, sizeof(int));
        p->rbody = calloc((size_t)p->nr + 1, sizeof(int));
        p->rtab = calloc(3 * (size_t)p->nr + 1, sizeof(int));
        p->rascale = calloc(3 * (size_t)p->nr + 1, sizeof(double));
        p->rfscale = calloc(3 * (size_t)p->nr + 1, sizeof(double));
        p->rtstop = calloc((size_t)p->nr + 1, sizeof(double));
        p->rqslot = calloc(12 * (size_t)p->nr + 1, sizeof(int64_t));
        if (!p->tbody || !p->tdir || !p->trow || !p->ttab || !p->tbcs || !p->tfirst || !p->tascale || !p->tfscale || !p->ttstop || !p->ttstart || !p->ttshift || !p->tson || !p->tsens || !p->rsens || !p->tu || !p->tsk || !p->rbody ||
            !p->rtab || !p->rascale || !p->rfscale || !p->rtstop || !p->rqslot)
            st = RC_SET(err, RC_ENOMEM, "out of memory");
    }
    int it = 0, ir = 0;
    for (int b = 0; b < nb && !st; b++) {
        double *y0 = m->body_y0 + RC_NB * b;
        int rot = 0;
        for (int j = 0; j < 6; j++) rot |= j >= 3 && owner[6 * b + j] >= 0;
        if (rot) {
            p->rbody[ir] = b;
            p->rtstop[ir] = -1e300;
            p->rsens[ir] = -1;
        }
        for (int j = 0; j < 6; j++) {
            const int k = owner[6 * b + j];
            if (j >= 3 && rot && k < 0) {
                p->rtab[3 * ir + j - 3] = -1; /* a component without a card: zero */
                y0[7 + j] = 0.0;
                continue;
            }
            if (k < 0 || (j > 0 && j < 3 && dir[k] < 0)) continue;
            const rc_case_impvel *v = &c->impvel[k];
            const int tab = rc_case_find_funct(c, v->fct_id);
            const double fs = sign[k] * v->fscale, *uk = u + 3 * k;
            /* the initial value: the imposed function at t = 0 (body frame
             * = global frame at t = 0); along a skew axis the component
             * along it, the others kept */
            double f0, df;
            rc_table_eval(&m->table[tab], 0.0, &f0, &df);
            /* a later start (Tstart > 0) leaves the initial velocity free */
            if (v->tstop >= 0 && tst[k] <= 0) {
                if (dir[k] < 0) {
                    const double du = fs * f0 - (uk[0] * y0[7] + uk[1] * y0[8] + uk[2] * y0[9]);
                    for (int i = 0; i < 3; i++) y0[7 + i] += du * uk[i];
                } else
                    y0[7 + j] = fs * f0;
            }
            if (j < 3) {
                p->tbody[it] = b;
                p->tdir[it] = dir[k] < 0 ? -1 : j;
                for (int i = 0; i < 3; i++) p->tu[3 * it + i] = dir[k] < 0 ? uk[i] : i == j;
                p->tsk[it] = dir[k] < 0 ? p->nsk++ : -1;
                p->ttab[it] = tab;
                p->tascale[it] = v->ascale;
                p->tfscale[it] = fs;
                p->ttstop[it] = v->tstop;
                p->ttstart[it] = tst[k] > 0 && isfinite(tst[k]) ? tst[k] : -INFINITY;
                p->ttshift[it] = tsh[k];
                p->tson[it] = ton_rt[k];
                p->tsens[it] = v->hold_sens - 1;
                p->tbcs[it] = 0;
                it++;
            } else {
                p->rtab[3 * ir + j - 3] = tab;
                p->rascale[3 * ir + j - 3] = v->ascale;
                p->rfscale[3 * ir + j - 3] = v->fscale;
                p->rtstop[ir] = v->tstop;
                p->rsens[ir] = v->hold_sens - 1;
            }
        }
        ir += rot;
    }
    /* the held skew axes: a velocity of zero along each, from t = 0 on;
     * the initial velocity loses its component along it (held DOFs start
     * at rest) */
    for (int h = 0; h < nh && !st; h++, it++) {
        const int b = hb[h];
        const double *uh = hu + 3 * h;
        double *v0 = m->body_y0 + RC_NB * b + 7;
        const double uv = uh[0] * v0[0] + uh[1] * v0[1] + uh[2] * v0[2];
        for (int i = 0; i < 3; i++) v0[i] -= uv * uh[i];
        p->tbody[it] = b;
        p->tdir[it] = -1;
        for (int i = 0; i < 3; i++) p->tu[3 * it + i] = uh[i];
        p->tsk[it] = p->nsk++;
        p->ttab[it] = -1;
        p->tbcs[it] = hid[h];
        p->tascale[it] = 1.0;
        p->tfscale[it] = 0.0;
        p->ttstop[it] = INFINITY;
        p->ttstart[it] = -INFINITY;
        p->ttshift[it] = 0.0;
        p->tson[it] = -1;
        p->tsens[it] = -1;
    }
    free(hb);
    free(hu);
    free(hid);
    /* each body's first skewed entry (its free rates, before any projection,
     * are the ones every skewed entry of the body measures its lambda by:
     * the right-hand side keeps them from that entry on) */
    char *seen = st ? NULL : calloc((size_t)nb + 1, 1);
    if (!st && !seen) st = RC_SET(err, RC_ENOMEM, "out of memory");
    for (int k = 0; k < p->nt && !st; k++)
        if (p->tdir[k] < 0 && !seen[p->tbody[k]]) seen[p->tbody[k]] = p->tfirst[k] = 1;
    free(seen);
    free(owner);
    free(dir);
    free(u);
    free(sign);
    free(tst);
    free(tsh);
    free(ton_rt);
    return st; /* on error the model frees m->imp */
}

int rc_imp_layout(rc_model *m, int ny)
{
    rc_imposed *p = m->imp;
    if (!p) return ny;
    for (int k = 0; k < p->nt; k++) p->trow[k] = m->body_yadr[p->tbody[k]] + 7 + (p->tdir[k] < 0 ? 0 : p->tdir[k]);
    p->wadr = ny;
    return ny + 1;
}

/* Rows of the imposed velocities: translations (a skewed card's three when
 * `skewed`), then 3 per rotating body. */
static void mark_rows(const rc_model *m, char *row, int skewed)
{
    const rc_imposed *p = m->imp;
    for (int k = 0; k < p->nt; k++)
        for (int i = 0; i < (p->tdir[k] < 0 ? 3 * skewed : 1); i++) row[p->trow[k] + i] = 1;
    for (int j = 0; j < p->nr; j++)
        for (int k = 0; k < 3; k++) row[m->body_yadr[p->rbody[j]] + 10 + k] = 1;
}

rc_status rc_imp_pattern_keys(const rc_model *m, int64_t **key, int64_t *n, rc_error *err)
{
    const rc_imposed *p = m->imp;
    const int64_t ny = m->ny;
    char *row = calloc((size_t)ny + 1, 1);
    int *sk = malloc(((size_t)ny + 1) * sizeof(int)); /* the skewed card of a row, -1 */
    if (!row || !sk) {
        free(row);
        free(sk);
        RC_RAISE(err, RC_ENOMEM, "out of memory for the Jacobian pattern");
    }
    mark_rows(m, row, 1);
    for (int64_t r = 0; r < ny; r++) sk[r] = -1;
    for (int k = 0; k < p->nt; k++)
        if (p->tdir[k] < 0)
            for (int i = 0; i < 3; i++) sk[p->trow[k] + i] = k;
    /* the W_imp row depends on everything the imposed rows depend on, on
     * their velocities, and (rotations) on q; the rotation rows on q; a
     * skewed card's three rows on the union of their columns */
    int64_t extra = 1 + 6 * p->nt + 3 * 16 * (int64_t)p->nr;
    for (int64_t k = 0; k < *n; k++)
        extra += row[(*key)[k] % ny] + 3 * (sk[(*key)[k] % ny] >= 0);
    int64_t *nk = realloc(*key, (size_t)(*n + extra) * sizeof(int64_t));
    if (!nk) {
        free(row);
        free(sk);
        RC_RAISE(err, RC_ENOMEM, "out of memory for the Jacobian pattern");
    }
    *key = nk;
    const int64_t n0 = *n, w = p->wadr;
    for (int64_t k = 0; k < n0; k++) {
        const int64_t r = nk[k] % ny, col = nk[k] / ny;
        if (row[r]) nk[(*n)++] = col * ny + w;
        if (sk[r] >= 0)
            for (int i = 0; i < 3; i++) nk[(*n)++] = col * ny + p->trow[sk[r]] + i;
    }
    nk[(*n)++] = w * ny + w;
    for (int k = 0; k < p->nt; k++)
        for (int i = 0; i < (p->tdir[k] < 0 ? 3 : 1); i++) {
            nk[(*n)++] = (int64_t)(p->trow[k] + i) * ny + w;
            nk[(*n)++] = (int64_t)(p->trow[k] + i) * ny + p->trow[k] + i;
        }
    for (int j = 0; j < p->nr; j++) {
        const int a = m->body_yadr[p->rbody[j]];
        for (int c = 0; c < 4; c++) {
            for (int r = 0; r < 3; r++) nk[(*n)++] = (int64_t)(a + 3 + c) * ny + a + 10 + r;
            nk[(*n)++] = (int64_t)(a + 3 + c) * ny + w;
        }
        for (int r = 0; r < 3; r++) nk[(*n)++] = (int64_t)(a + 10 + r) * ny + w;
    }
    free(row);
    free(sk);
    return RC_OK;
}

rc_status rc_imp_slots(rc_model *m, rc_error *err)
{
    rc_imposed *p = m->imp;
    p->wslot = malloc(((size_t)m->ny + 1) * sizeof(int64_t));
    p->row_imp = calloc((size_t)m->ny + 1, 1);
    if (!p->wslot || !p->row_imp) RC_RAISE(err, RC_ENOMEM, "out of memory for the Jacobian pattern");
    for (int c = 0; c < m->ny; c++) p->wslot[c] = rc_jac_slot(m, p->wadr, c);
    /* a skewed card's rows keep their free part (they are not marked) */
    mark_rows(m, p->row_imp, 0);
    if (p->nsk) {
        p->sslot = malloc((3 * (size_t)p->nsk * (size_t)m->ny + 1) * sizeof(int64_t));
        if (!p->sslot) RC_RAISE(err, RC_ENOMEM, "out of memory for the Jacobian pattern");
        for (int k = 0; k < p->nt; k++)
            if (p->tsk[k] >= 0)
                for (int i = 0; i < 3; i++)
                    for (int c = 0; c < m->ny; c++)
                        p->sslot[(3 * (size_t)p->tsk[k] + (size_t)i) * (size_t)m->ny + (size_t)c] =
                            rc_jac_slot(m, p->trow[k] + i, c);
    }
    for (int j = 0; j < p->nr; j++) {
        const int a = m->body_yadr[p->rbody[j]];
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 4; c++) p->rqslot[12 * j + 4 * r + c] = rc_jac_slot(m, a + 10 + r, a + 3 + c);
    }
    return RC_OK;
}

void rc_imp_print(const rc_model *m, FILE *f)
{
    const rc_imposed *p = m->imp;
    if (!p) return;
    static const char *const ax = "XYZ";
    fprintf(f, "imposed     %d translation component(s), %d body rotation(s)\n", p->nt, p->nr);
    for (int k = 0; k < p->nt && k < 20; k++) {
        char what[80];
        if (p->tdir[k] < 0)
            snprintf(what, sizeof what, "along (%.6g, %.6g, %.6g)", p->tu[3 * k], p->tu[3 * k + 1], p->tu[3 * k + 2]);
        else
            snprintf(what, sizeof what, "%c", ax[p->tdir[k]]);
        char until[80];
        if (p->tsens[k] >= 0 && m->sens_id)
            snprintf(until, sizeof until, "sensor %d turns on (a time found in the run)", m->sens_id[p->tsens[k]]);
        else
            snprintf(until, sizeof until, "%.5g s", p->ttstop[k]);
        char arg[48];
        if (p->tson[k] >= 0 && m->sens_id) snprintf(arg, sizeof arg, "(t - t_on)");
        else if (p->ttshift[k] > 0) snprintf(arg, sizeof arg, "(t - %.5g)", p->ttshift[k]);
        else snprintf(arg, sizeof arg, "t");
        char from[96];
        if (p->tson[k] >= 0 && m->sens_id)
            snprintf(from, sizeof from, "t_on, when sensor %d turns on (a time found in the run),", m->sens_id[p->tson[k]]);
        else snprintf(from, sizeof from, "%.5g", isfinite(p->ttstart[k]) ? p->ttstart[k] : 0.0);
        if (p->ttab[k] < 0) {
            fprintf(f, "  /RBODY/%-6d velocity %s held at 0 (/BCS/%d)\n", m->body_id[p->tbody[k]], what, p->tbcs[k]);
            continue;
        }
        fprintf(f, "  /RBODY/%-6d velocity %s = %.5g f(%s / %.5g) (/FUNCT/%d) from %s until %s\n",
                m->body_id[p->tbody[k]], what, p->tfscale[k], arg, p->tascale[k], m->table[p->ttab[k]].id, from,
                until);
    }
    for (int j = 0; j < p->nr && j < 20; j++) {
        fprintf(f, "  /RBODY/%-6d angular velocity (global axes) =", m->body_id[p->rbody[j]]);
        for (int k = 0; k < 3; k++) {
            const int t = p->rtab[3 * j + k];
            if (t < 0) fprintf(f, " %c 0", ax[k]);
            else fprintf(f, " %c %.5g f(t / %.5g)", ax[k], p->rfscale[3 * j + k], p->rascale[3 * j + k]);
        }
        if (p->rsens[j] >= 0 && m->sens_id)
            fprintf(f, " until sensor %d turns on (a time found in the run)\n", m->sens_id[p->rsens[j]]);
        else
            fprintf(f, " until %.5g s\n", p->rtstop[j]);
    }
    if (p->nt > 20 || p->nr > 20)
        fprintf(f, "  ... and %d more (the first 20 of each kind are listed)\n",
                (p->nt > 20 ? p->nt - 20 : 0) + (p->nr > 20 ? p->nr - 20 : 0));
}

/* ---- the orientation an imposed rotation reaches (statics) ---------- */
typedef struct {
    const rc_model *m;
    int j;
} rot_ctx;

/* global angular velocity of imposed rotation j at t [rad/s] */
static void rot_omega(const rc_model *m, int j, double t, double w[3])
{
    const rc_imposed *p = m->imp;
    for (int k = 0; k < 3; k++) {
        const int tab = p->rtab[3 * j + k];
        w[k] = tab < 0 ? 0.0 : p->rfscale[3 * j + k] * rc_table_value(&m->table[tab], t / p->rascale[3 * j + k]);
    }
}

/* de/dt = 1/2 (0, w) (x) e */
static int rot_rhs(double t, const double e[], double de[], void *user)
{
    const rot_ctx *c = user;
    double w[3];
    rot_omega(c->m, c->j, t, w);
    de[0] = -0.5 * (w[0] * e[1] + w[1] * e[2] + w[2] * e[3]);
    de[1] = 0.5 * (w[0] * e[0] + w[1] * e[3] - w[2] * e[2]);
    de[2] = 0.5 * (w[1] * e[0] + w[2] * e[1] - w[0] * e[3]);
    de[3] = 0.5 * (w[2] * e[0] + w[0] * e[2] - w[1] * e[1]);
    return GSL_SUCCESS;
}

static int cmp_dbl(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int rc_imp_rotation(const rc_model *m, int j, double t, double e[4])
{
    const rc_imposed *p = m->imp;
    const double te = fmin(t, p->rtstop[j]);
    e[0] = 1.0;
    e[1] = e[2] = e[3] = 0.0;
    if (!(te > 0)) return 0;
    int nc = 0, nk = 0;
    for (int k = 0; k < 3; k++)
        if (p->rtab[3 * j + k] >= 0) {
            nc++;
            nk += m->table[p->rtab[3 * j + k]].n;
        }
    if (nc <= 1) {
        /* one axis: the rotation by the integral of its speed */
        double phi[3];
        for (int k = 0; k < 3; k++) {
            const int tab = p->rtab[3 * j + k];
            const double as = p->rascale[3 * j + k];
            phi[k] = tab < 0 ? 0.0 : p->rfscale[3 * j + k] * as * rc_table_integral(&m->table[tab], 0.0, te / as);
        }
        const double a = sqrt(phi[0] * phi[0] + phi[1] * phi[1] + phi[2] * phi[2]);
        const double sc = a > 1e-8 ? sin(0.5 * a) / a : 0.5 - a * a / 48.0;
        e[0] = cos(0.5 * a);
        for (int k = 0; k < 3; k++) e[k + 1] = sc * phi[k];
        return 0;
    }
    /* several axes: the points of the time functions in (0, te) split the
     * integration where the speeds have kinks */
    double *bk = malloc(((size_t)nk + 1) * sizeof(double));
    if (!bk) return -1;
    int nb = 0;
    for (int k = 0; k < 3; k++) {
        const int tab = p->rtab[3 * j + k];
        if (tab < 0) continue;
        for (int q = 0; q < m->table[tab].n; q++) {
            const double tk = m->table[tab].x[q] * p->rascale[3 * j + k];
            if (tk > 0 && tk < te) bk[nb++] = tk;
        }
    }
    bk[nb++] = te;
    qsort(bk, (size_t)nb, sizeof(double), cmp_dbl);
    rot_ctx c = {m, j};
    gsl_odeiv2_system sys = {rot_rhs, NULL, 4, &c};
    double s = 0.0;
    int st = GSL_SUCCESS;
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    for (int q = 0; q < nb && st == GSL_SUCCESS; q++) {
        if (!(bk[q] > s)) continue;
        gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 0.125 * (bk[q] - s),
                                                             1e-15, 1e-14);
        if (!d) {
            st = GSL_ENOMEM;
            break;
        }
        st = gsl_odeiv2_driver_apply(d, &s, bk[q], e);
        gsl_odeiv2_driver_free(d);
    }
    gsl_set_error_handler(old);
    free(bk);
    const double n = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + e[3] * e[3]);
    if (st != GSL_SUCCESS || !(n > 0) || !isfinite(n)) {
        for (int k = 0; k < 4; k++) e[k] = NAN;
        return -1;
    }
    for (int k = 0; k < 4; k++) e[k] /= n;
    return 0;
}
