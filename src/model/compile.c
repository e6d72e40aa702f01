/*
 * Compile a parsed case into the constant model: resolve ids, check the
 * physics of each reference, lay out the state vector and its tolerances,
 * and build the Jacobian pattern. Every error names the file:line and card
 * of the reference that is wrong.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "case/case.h"
#include "model/coupling.h"
#include "base/error.h"
#include "model/geom.h"
#include "model/segsurf.h"
#include "case/case_power.h"
#include "model/imposed.h"
#include "model/massprop.h"
#include "model/joint.h"
#include "model/model.h"
#include "base/progress.h"
#include "model/power.h"
#include "model/rwall.h"
#include "model/type7.h"
#include "model/sensor.h"

#define ALLOC(ptr, n)                                                               \
    do {                                                                            \
        (ptr) = calloc((size_t)(n) + 1, sizeof *(ptr));                             \
        if (!(ptr)) {                                                               \
            st = RC_SET(err, RC_ENOMEM, "out of memory compiling the model");       \
            goto fail;                                                              \
        }                                                                           \
    } while (0)


/* Is node_id, a node in no body, held in its three translations by a /BCS
 * (a ground node of Radioss's kind: in ricochet a node in no body is a
 * point fixed in space, the end of a spring element)? */
static int grounded(const rc_case *c, int node_id)
{
    for (int k = 0; k < c->nbcs; k++) {
        const rc_case_bcs *bc = &c->bcs[k];
        if (!(bc->fix[0] == 1 && bc->fix[1] == 1 && bc->fix[2] == 1)) continue;
        const int g = bc->grnod_id ? rc_case_find_grnod(c, bc->grnod_id) : -1;
        for (int j = 0; g >= 0 && j < c->grnod[g].n; j++)
            if (c->grnod[g].nodes[j] == node_id) return 1;
    }
    return 0;
}

/* A partial rotation lock (/BCS) needs the free axis principal: products of
 * inertia with it at most this fraction of the largest moment [-]. */
#define RC_BCS_PRINCIPAL_TOL 1e-10

/* Bodies of the nodes of group `gid` -> flag array (all bodies when gid = 0).
 * `loc`: the line of the referring card that holds grnod_ID. A node in no
 * body is an error, unless a /BCS holds its translations (grounded): that
 * /BCS and the /INIVEL, /GRAV of its group then skip it. */
static rc_status group_bodies(const rc_case *c, int gid, rc_loc loc, const char *card, int *flag,
                              rc_error *err)
{
    for (int b = 0; b < c->nrbody; b++) flag[b] = gid == 0;
    if (gid == 0) return RC_OK;
    int g = rc_case_find_grnod(c, gid);
    if (g < 0)
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field grnod_ID: expected the id of a /GRNOD, got %d (no such group)",
                 RC_LOC(loc), card, gid);
    for (int k = 0; k < c->grnod[g].n; k++) {
        int b = rc_case_body_of_node(c, c->grnod[g].nodes[k]);
        if (b < 0 && grounded(c, c->grnod[g].nodes[k])) continue;
        if (b < 0) {
            const rc_loc nl = rc_loc_at(c->grnod[g].node_loc, k, c->grnod[g].loc);
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /GRNOD/NODE/%d, field node_ID: node %d belongs to no /RBODY (ricochet bodies are "
                     "rigid; a node in no body is a point fixed in space, accepted here when a /BCS holds its "
                     "translations); the group is used by %s at %s:%d",
                     RC_LOC(nl), gid, c->grnod[g].nodes[k], card, RC_LOC(loc));
        }
        flag[b] = 1;
    }
    return RC_OK;
}

/* 3x3 inverse (symmetric positive definite checked by the reader). */
static int inv3(const double *a, double *o)
{
    double det = a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
                 a[2] * (a[3] * a[7] - a[4] * a[6]);
    if (!(det > 0)) return -1;
    o[0] = (a[4] * a[8] - a[5] * a[7]) / det;
    o[1] = (a[2] * a[7] - a[1] * a[8]) / det;
    o[2] = (a[1] * a[5] - a[2] * a[4]) / det;
    o[3] = (a[5] * a[6] - a[3] * a[8]) / det;
    o[4] = (a[0] * a[8] - a[2] * a[6]) / det;
    o[5] = (a[2] * a[3] - a[0] * a[5]) / det;
    o[6] = (a[3] * a[7] - a[4] * a[6]) / det;
    o[7] = (a[1] * a[6] - a[0] * a[7]) / det;
    o[8] = (a[0] * a[4] - a[1] * a[3]) / det;
    return 0;
}

/* ---- bodies ------------------------------------------------------------ */

/* Products of physical values must stay finite: a body of 1e308 kg weighs
 * inf N under gravity, a velocity of 1e200 m/s gives an infinite kinetic
 * energy, and the energies of the results (and their sums) would be inf or
 * NaN. Every free body's weight m |g| [N], kinetic energy m v^2 / 2 and
 * rotational energy w.J w / 2 [J] and potential energy m |g| |x| [J] at
 * t = 0 stay below RC_MAX_DERIVED (docs/case-format.md); otherwise an input
 * error names the field with the largest share of the product (in orders of
 * magnitude). The magnitudes are compared in logarithms, so that nothing
 * here overflows. Gravity is taken at Fscale_y (a time function scales it
 * during the run). */
#define RC_MAX_DERIVED 1e300

/* A factor of a product: log10 of its magnitude (counted `pow` times), and
 * where it was read. */
typedef struct factor {
    double lg;
    int pow;
    rc_loc loc;
    char card[64];
    const char *field;
    const char *what, *unit; /* "mass", "kg" */
    double value;
} factor;

static double lg10(double x) { return x > 0 ? log10(x) : -INFINITY; }

static double norm3(const double *v) { return hypot(hypot(v[0], v[1]), v[2]); }

/* Refuse `name` = coef * prod(f[k].value^f[k].pow) [unit] above RC_MAX_DERIVED. */
static rc_status check_product(const char *name, const char *unit, double coef, const factor *f, int n, int body_id,
                               rc_error *err)
{
    double lg = log10(coef);
    for (int k = 0; k < n; k++) lg += f[k].pow * f[k].lg;
    if (lg <= log10(RC_MAX_DERIVED)) return RC_OK;
    int big = 0;
    for (int k = 1; k < n; k++)
        if (f[k].pow * f[k].lg > f[big].pow * f[big].lg) big = k;
    char parts[512] = "";
    for (int k = 0; k < n; k++)
        snprintf(parts + strlen(parts), sizeof parts - strlen(parts), "%s%s %.3g %s", k ? ", " : "", f[k].what,
                 f[k].value, f[k].unit);
    RC_RAISE(err, RC_EINPUT,
             RC_LOCFMT "card %s, field %s: the %s of /RBODY/%d at t = 0 is about 1e%.0f %s (%s), beyond %.0e: "
             "its energies would not be finite; expected values whose products stay within the double range",
             RC_LOC(f[big].loc), f[big].card, f[big].field, name, body_id, lg, unit, parts, RC_MAX_DERIVED);
}

static rc_status check_derived(const rc_case *c, const rc_model *m, const int *tra, const int *rot, const int *grav,
                               rc_error *err)
{
    for (int b = 0; b < c->nrbody; b++) {
        if (m->body_fixed[b]) continue;
        const rc_case_rbody *rb = &c->rbody[b];
        const double *y0 = m->body_y0 + RC_NB * b, *J = m->body_J + 9 * b;
        const double g = norm3(m->body_grav + 3 * b), v = norm3(y0 + 7), w = norm3(y0 + 10), x = norm3(y0);
        factor fm = {lg10(m->body_mass[b]), 1, rc_loc_or(rb->line_loc[0], rb->loc), "", "Mass", "mass", "kg",
                     m->body_mass[b]};
        snprintf(fm.card, sizeof fm.card, "/RBODY/%d", rb->id);
        factor fj = fm;
        fj.lg = lg10(J[0] + J[4] + J[8]);
        fj.loc = rc_loc_or(rb->line_loc[1], rb->loc);
        fj.field = "Jxx..Jxz";
        fj.what = "inertia (trace)";
        fj.unit = "kg m^2";
        fj.value = J[0] + J[4] + J[8];
        factor fg = {lg10(g), 1, rb->loc, "", "Fscale_y", "gravity", "m/s^2", g};
        if (grav[b] >= 0) {
            fg.loc = rc_loc_or(c->grav[grav[b]].line_loc, c->grav[grav[b]].loc);
            snprintf(fg.card, sizeof fg.card, "/GRAV/%d", c->grav[grav[b]].id);
        }
        factor fv = {lg10(v), 2, rb->loc, "", "Vx, Vy, Vz", "speed", "m/s", v};
        if (tra[b] >= 0) {
            fv.loc = rc_loc_or(c->inivel[tra[b]].line_loc, c->inivel[tra[b]].loc);
            snprintf(fv.card, sizeof fv.card, "/INIVEL/TRA/%d", c->inivel[tra[b]].id);
        }
        factor fw = {lg10(w), 2, rb->loc, "", "Vx, Vy, Vz", "angular speed", "rad/s", w};
        if (rot[b] >= 0) {
            fw.loc = rc_loc_or(c->inivel[rot[b]].line_loc, c->inivel[rot[b]].loc);
            snprintf(fw.card, sizeof fw.card, "/INIVEL/ROT/%d", c->inivel[rot[b]].id);
        }
        factor fx = {lg10(x), 1, rb->loc, "", "node_ID", "distance from the origin", "m", x};
        snprintf(fx.card, sizeof fx.card, "/RBODY/%d", rb->id);
        const int nd = rc_case_find_node(c, rb->node_id);
        if (nd >= 0) {
            fx.loc = c->node[nd].loc;
            snprintf(fx.card, sizeof fx.card, "/NODE");
            fx.field = "X, Y, Z";
        }
        const factor weight[2] = {fm, fg}, kin[2] = {fm, fv}, spin[2] = {fj, fw}, pot[3] = {fm, fg, fx};
        rc_status st = check_product("weight m |g|", "N", 1.0, weight, 2, rb->id, err);
        if (!st) st = check_product("kinetic energy m v^2 / 2", "J", 0.5, kin, 2, rb->id, err);
        if (!st) st = check_product("rotational energy w.J w / 2", "J", 0.5, spin, 2, rb->id, err);
        if (!st) st = check_product("potential energy m |g| |x|", "J", 1.0, pot, 3, rb->id, err);
        if (st) return st;
    }
    return RC_OK;
}

static rc_status compile_bodies(const rc_case *c, rc_model *m, rc_error *err)
{
    /* main node -> the body that took it (+1), to refuse a second one */
    int *owner = calloc((size_t)c->nnode + 1, sizeof(int));
    rc_body_mp *mp = calloc((size_t)c->nrbody + 1, sizeof *mp);
    if (!owner || !mp) {
        free(owner);
        free(mp);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    {
        rc_status mst = rc_massprop_bodies(c, mp, err);
        if (mst) {
            free(owner);
            free(mp);
            return mst;
        }
    }
    for (int b = 0; b < c->nrbody; b++) {
        const rc_case_rbody *rb = &c->rbody[b];
        /* the data lines holding the fields (the header for a case built by hand) */
        const rc_loc l1 = rc_loc_or(rb->line_loc[0], rb->loc), l3 = rc_loc_or(rb->line_loc[2], rb->loc);
        int nd = rc_case_find_node(c, rb->node_id);
        if (nd < 0) {
            free(owner);
            free(mp);
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /RBODY/%d, field node_ID: expected the id of a /NODE, got %d (no such node)",
                     RC_LOC(l1), rb->id, rb->node_id);
        }
        if (owner[nd]) {
            const rc_case_rbody *first = &c->rbody[owner[nd] - 1];
            free(owner);
            free(mp);
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /RBODY/%d, field node_ID: node %d is already the main node of /RBODY/%d (%s:%d); expected a node of its own",
                     RC_LOC(l1), rb->id, rb->node_id, first->id, first->loc.file, first->loc.line);
        }
        owner[nd] = b + 1;
        if (rb->grnod_id && rc_case_find_grnod(c, rb->grnod_id) < 0) {
            free(owner);
            free(mp);
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /RBODY/%d, field grnd_ID: expected the id of a /GRNOD, got %d (no such group)",
                     RC_LOC(l1), rb->id, rb->grnod_id);
        }
        m->body_id[b] = rb->id;
        m->body_loc[b] = rb->loc;
        /* mass, centre of mass and inertia: mesh and card (massprop.c) */
        m->body_mass[b] = mp[b].mass;
        double *J = m->body_J + 9 * b;
        memcpy(J, mp[b].J, 9 * sizeof *J);
        int bad = inv3(J, m->body_Jinv + 9 * b);
        for (int k = 0; k < 9; k++) bad |= !isfinite(m->body_Jinv[9 * b + k]);
        if (bad) {
            free(owner);
            free(mp);
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /RBODY/%d, fields Jxx..Jxz: expected a positive-definite inertia tensor",
                     RC_LOC(l3), rb->id);
        }
        double *y0 = m->body_y0 + RC_NB * b;
        memcpy(y0, mp[b].x, 3 * sizeof(double));
        y0[3] = 1.0; /* body frame = global frame at t = 0 */
    }
    free(owner);
    free(mp);
    /* initial velocities */
    int *flag = calloc((size_t)c->nrbody + 1, sizeof(int));
    /* the cards that gave each body its velocities and gravity (-1: none) */
    int *tra = malloc(3 * ((size_t)c->nrbody + 1) * sizeof(int)), *rot = tra ? tra + c->nrbody + 1 : NULL,
        *grav = tra ? rot + c->nrbody + 1 : NULL;
    if (!flag || !tra) {
        free(flag);
        free(tra);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    for (int b = 0; b < 3 * (c->nrbody + 1); b++) tra[b] = -1;
    rc_status st = RC_OK;
    for (int k = 0; k < c->ninivel && !st; k++) {
        const rc_case_inivel *iv = &c->inivel[k];
        char card[64];
        snprintf(card, sizeof card, "/INIVEL/%s/%d", iv->rot ? "ROT" : "TRA", iv->id);
        st = group_bodies(c, iv->grnod_id, rc_loc_or(iv->line_loc, iv->loc), card, flag, err);
        for (int b = 0; b < c->nrbody && !st; b++)
            if (flag[b]) {
                memcpy(m->body_y0 + RC_NB * b + (iv->rot ? 10 : 7), iv->v, 3 * sizeof(double));
                (iv->rot ? rot : tra)[b] = k;
            }
    }
    /* /BCS on a node of a body: all six flags fix the body; otherwise the
     * flagged global translations are held, and the rotations all, none, or
     * all but one: a body turning about one global axis e only (the body
     * frame is the global one at t = 0, so the body-frame angular velocity
     * stays along e and its other two components are held at 0), exact
     * when e is a principal axis of the body's inertia (the equation of the
     * free component is then J_ee w_e' = tau_e); two free rotations are not
     * a simple condition on the state (not supported yet) */
    int *bcs_rot = malloc(((size_t)c->nrbody + 1) * sizeof(int)); /* last /BCS holding a rotation */
    if (!bcs_rot) st = RC_SET(err, RC_ENOMEM, "out of memory");
    for (int b = 0; bcs_rot && b < c->nrbody; b++) bcs_rot[b] = -1;
    for (int k = 0; k < c->nbcs && !st; k++) {
        const rc_case_bcs *bc = &c->bcs[k];
        const rc_loc bl = rc_loc_or(bc->line_loc, bc->loc);
        char card[64];
        snprintf(card, sizeof card, "/BCS/%d", bc->id);
        int all = 1, nrot = 0;
        for (int j = 0; j < 6; j++) all &= bc->fix[j] == 1;
        for (int j = 3; j < 6; j++) nrot += bc->fix[j] == 1;
        /* one or two translations held along a skew's axes: not global
         * components but the velocity along each axis, held by the imposed
         * velocities' projection (rc_imp_compile) */
        const int tskew = rc_bcs_skewed_translations(bc);
        st = group_bodies(c, bc->grnod_id, bl, card, flag, err);
        for (int b = 0; b < c->nrbody && !st; b++) {
            if (!flag[b]) continue;
            if (all) m->body_fixed[b] = 1;
            for (int j = 0; j < 6; j++) m->body_dofmask[6 * b + j] |= bc->fix[j] == 1 && !(j < 3 && tskew);
            if (nrot) bcs_rot[b] = k;
        }
    }
    for (int b = 0; b < c->nrbody && !st; b++) {
        const int *mask = m->body_dofmask + 6 * b;
        const int nrot = mask[3] + mask[4] + mask[5];
        if (nrot == 0 || nrot == 3 || m->body_fixed[b]) continue;
        const rc_case_bcs *bc = &c->bcs[bcs_rot[b]];
        const rc_loc bl = rc_loc_or(bc->line_loc, bc->loc);
        if (nrot == 1) {
            st = RC_SET(err, RC_EINPUT,
                        RC_LOCFMT "card /BCS/%d, field Trarot: /RBODY/%d has one rotation held and two free: not supported "
                                  "yet (expected the rotations all fixed, all free, or all but one fixed: \"xxx 111\", "
                                  "\"xxx 000\", \"xxx 110\", ...)",
                        RC_LOC(bl), bc->id, m->body_id[b]);
            break;
        }
        /* one free rotation: about a principal axis of the inertia */
        const int e = mask[3] ? (mask[4] ? 2 : 1) : 0;
        const double *J = m->body_J + 9 * b;
        const double jmax = fmax(J[0], fmax(J[4], J[8]));
        for (int i = 0; i < 3 && !st; i++)
            if (i != e && !(fabs(J[3 * i + e]) <= RC_BCS_PRINCIPAL_TOL * jmax))
                st = RC_SET(err, RC_EINPUT,
                            RC_LOCFMT "card /BCS/%d, field Trarot: /RBODY/%d turns about the global %c axis only, which is "
                                      "not a principal axis of its inertia (J%c%c = %.9g kg m^2, of the largest moment %.9g): "
                                      "a partial rotation lock about a non-principal axis is not supported yet",
                            RC_LOC(bl), bc->id, m->body_id[b], "XYZ"[e], "xyz"[i < e ? i : e], "xyz"[i < e ? e : i],
                            J[3 * i + e], jmax);
    }
    free(bcs_rot);
    /* held DOFs start at rest */
    for (int b = 0; b < c->nrbody && !st; b++)
        for (int j = 0; j < 6; j++)
            if (m->body_dofmask[6 * b + j]) m->body_y0[RC_NB * b + 7 + j] = 0.0;
    /* gravity: one time function for all cards (constant when 0) */
    for (int k = 0; k < c->ngrav && !st; k++) {
        const rc_case_grav *gr = &c->grav[k];
        const rc_loc gl = rc_loc_or(gr->line_loc, gr->loc);
        char card[64];
        snprintf(card, sizeof card, "/GRAV/%d", gr->id);
        int tab;
        st = rc_case_ref_funct(c, gr->fct_id, 0, gl, card, "fct_IDT", &tab, err);
        if (st) break;
        if (k > 0 && tab != m->grav_table) {
            st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card %s, field fct_IDT: all /GRAV cards must share one time function (not supported yet)",
                        RC_LOC(gl), card);
            break;
        }
        m->grav_table = tab;
        m->grav_ascale = gr->ascale;
        /* a sensor: the gravity from its time on, one start for all cards
         * (they share one time function) */
        double ton;
        int gs;
        st = rc_sensor_load_on(c, gr->sensor_id, gl, card, "a gravity", &ton, &gs, err);
        if (st) break;
        if (k > 0 && (gs >= 0 || m->grav_sens >= 0) && gs != m->grav_sens) {
            st = RC_SET(err, RC_EINPUT,
                        RC_LOCFMT "card %s, field sensor_ID: this card's gravity starts %s, /GRAV/%d's %s: all "
                        "/GRAV cards must start at one time (they share one time function; not supported yet); "
                        "expected the same sensor on every /GRAV",
                        RC_LOC(gl), card, gs >= 0 ? "with a sensor found in the run" : "at a time known when compiling",
                        c->grav[0].id, m->grav_sens >= 0 ? "with another sensor, found in the run" : "at a time known when compiling");
            break;
        }
        if (k > 0 && gs < 0 && ton != m->grav_tstart) {
            st = RC_SET(err, RC_EINPUT,
                        RC_LOCFMT "card %s, field sensor_ID: this card's gravity starts at %.9g s, /GRAV/%d's at "
                        "%.9g s: all /GRAV cards must start at one time (they share one time function; not "
                        "supported yet); expected the same sensor time (or no sensor) on every /GRAV",
                        RC_LOC(gl), card, ton, c->grav[0].id, m->grav_tstart);
            break;
        }
        m->grav_sens = gs;
        if (gs < 0) m->grav_tstart = ton;
        st = group_bodies(c, gr->grnod_id, gl, card, flag, err);
        for (int b = 0; b < c->nrbody && !st; b++)
            if (flag[b]) {
                for (int i = 0; i < 3; i++) m->body_grav[3 * b + i] += gr->fscale * gr->u[i];
                grav[b] = k;
            }
    }
    if (!st) st = check_derived(c, m, tra, rot, grav, err);
    free(flag);
    free(tra);
    return st;
}

/* ---- surfaces ---------------------------------------------------------- */
static rc_status compile_surfaces(const rc_case *c, rc_model *m, const rc_rwall_case *rx, rc_error *err)
{
    /* the boxes that meet a plane or a box (a plane wall too): their
     * corners and faces too */
    unsigned char *corners = malloc((size_t)c->nsurf + 1);
    if (!corners) RC_RAISE(err, RC_ENOMEM, "out of memory");
    rc_geom_box_corner_flags(c, corners); /* model/geom.c */
    rc_rwall_box_flags(rx, corners);      /* model/rwall.c */
    rc_status st = RC_OK;
    for (int s = 0; s < c->nsurf && !st; s++) {
        const rc_case_surf *cs = &c->surf[s];
        m->surf_nadr[s + 1] = m->surf_nadr[s];
        m->surf_sadr[s + 1] = m->surf_sadr[s];
        if (cs->kind == RC_CASE_SURF_SEG || cs->kind == RC_CASE_SURF_PART) {
            st = rc_seg_surface(c, m, s, err); /* model/segsurf.c */
            continue;
        }
        static const char *const kinds[5] = {"", "PLANE", "ELLIPS", "CYL", "BOX"};
        const char *kind = kinds[cs->kind];
        int b = -1;
        if (cs->rbody_id) {
            b = rc_case_find_rbody(c, cs->rbody_id);
            if (b < 0) {
                st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card /SURF/%s/%d, field rbody_ID: expected the id of a /RBODY, got %d (no such body)",
                            RC_LOC(rc_loc_or(cs->rbody_loc, cs->loc)), kind, cs->id, cs->rbody_id);
                break;
            }
        }
        m->surf_id[s] = cs->id;
        m->surf_body[s] = b;
        /* local frame: body frame = global at t = 0, origin at the CoM */
        const double *org = b >= 0 ? m->body_y0 + RC_NB * b : m->ground_y0;
        if (cs->kind == RC_CASE_SURF_CYL || cs->kind == RC_CASE_SURF_BOX) {
            rc_geom_surface(cs, m, s, org); /* model/geom.c */
            if (corners[s]) st = rc_geom_box_corners(m, s, err);
        } else if (cs->kind == RC_CASE_SURF_PLANE) {
            double n[3], len = 0;
            for (int k = 0; k < 3; k++) {
                n[k] = cs->m1[k] - cs->m[k];
                len += n[k] * n[k];
            }
            len = sqrt(len);
            m->surf_kind[s] = RC_SURF_PLANE;
            /* its point: the foot of the perpendicular from the frame's
             * origin (the same plane; a point of the order of the scene, not
             * of wherever M was given) */
            double dn = 0.0;
            for (int k = 0; k < 3; k++) {
                m->surf_n[3 * s + k] = n[k] / len;
                dn += (cs->m[k] - org[k]) * m->surf_n[3 * s + k];
            }
            for (int k = 0; k < 3; k++) m->surf_p[3 * s + k] = dn * m->surf_n[3 * s + k];
            if (cs->bounded) { /* a parallelogram (/RWALL/PARAL) */
                double *e = m->surf_ext + RC_SURF_NEXT * s;
                e[0] = 1.0;
                for (int k = 0; k < 3; k++) {
                    e[1 + k] = cs->m[k] - org[k];
                    e[4 + k] = cs->e1[k];
                    e[7 + k] = cs->e2[k];
                }
            }
        } else {
            m->surf_kind[s] = RC_SURF_SPHERE;
            m->surf_r[s] = cs->abc[0];
            for (int k = 0; k < 3; k++) m->surf_p[3 * s + k] = cs->c[k] - org[k];
        }
    }
    free(corners);
    return st;
}

/* ---- interfaces -------------------------------------------------------- */
/* Largest slope of a scaled curve F = fs f(P / ax) over its points [N/m]. */
static double max_slope(const rc_table *t, double fs, double ax, double *at)
{
    double smax = 0;
    for (int k = 0; k + 1 < t->n; k++) {
        double s = fabs(fs / ax * (t->y[k + 1] - t->y[k]) / (t->x[k + 1] - t->x[k]));
        if (s > smax) {
            smax = s;
            *at = ax * t->x[k];
        }
    }
    return smax;
}

/* The elasto-plastic laws need Stiff steeper than both curves, so that
 * leaving a curve along the Stiff line moves away from it (no chattering at
 * a reversal, docs/theory.md); the unload curve must lie below the load curve. */
static rc_status check_hysteresis(const rc_model *m, int i, const rc_case_type6 *t6, const char *card,
                                  rc_error *err)
{
    if (m->inter_iform[i] == 0) return RC_OK;
    const double ax = m->inter_ascalex[i];
    const rc_table *tl = &m->table[m->inter_fct_ld[i]];
    double at = 0, sl = max_slope(tl, m->inter_fscaleld[i], ax, &at);
    if (!(m->inter_stiff[i] > sl))
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s, field Stiff: expected a stiffness steeper than the load curve (its slope reaches %.6g N/m at P = %.6g m), got %.6g",
                 RC_LOC(t6->line_loc[4]), card, sl, at, m->inter_stiff[i]);
    if (m->inter_fct_ul[i] < 0) return RC_OK;
    const rc_table *tu = &m->table[m->inter_fct_ul[i]];
    double su = max_slope(tu, m->inter_fscaleul[i], ax, &at);
    if (!(m->inter_stiff[i] > su))
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s, field Stiff: expected a stiffness steeper than the unload curve (its slope reaches %.6g N/m at P = %.6g m), got %.6g",
                 RC_LOC(t6->line_loc[4]), card, su, at, m->inter_stiff[i]);
    /* unload below load at every point of either curve */
    for (int pass = 0; pass < 2; pass++) {
        const rc_table *t = pass ? tu : tl;
        for (int k = 0; k < t->n; k++) {
            double P = ax * t->x[k], fl, fu, dd;
            if (P < 0) continue;
            rc_table_eval(tl, P / ax, &fl, &dd);
            rc_table_eval(tu, P / ax, &fu, &dd);
            fl *= m->inter_fscaleld[i];
            fu *= m->inter_fscaleul[i];
            if (fu > fl + 1e-12 * fabs(fl))
                RC_RAISE(err, RC_EINPUT,
                         RC_LOCFMT "card %s, field fct_IDul: expected an unload curve below the load curve, but at P = %.6g m it gives %.6g N above %.6g N",
                         RC_LOC(t6->line_loc[4]), card, P, fu, fl);
        }
    }
    return RC_OK;
}

static rc_status compile_type6(const rc_case *c, rc_model *m, int i, rc_error *err)
{
    const rc_case_type6 *t6 = &c->type6[i];
    char card[128];
    if (t6->name) snprintf(card, sizeof card, "%s", t6->name); /* a wall's contact (model/rwall.c) */
    else snprintf(card, sizeof card, "/INTER/TYPE6/%d", t6->id);
    int s1 = rc_case_find_surf(c, t6->surf1), s2 = rc_case_find_surf(c, t6->surf2);
    if (s1 < 0 || s2 < 0)
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field %s: expected the id of a /SURF, got %d (no such surface)",
                 RC_LOC(t6->line_loc[0]), card, s1 < 0 ? "surf_ID1" : "surf_ID2", s1 < 0 ? t6->surf1 : t6->surf2);
    /* order the pair (a: sphere or cylinder) and name its kind (model/geom.c) */
    char where[600];
    snprintf(where, sizeof where, RC_LOCFMT "card %s", RC_LOC(t6->line_loc[0]), card);
    const int s1_in = s1;
    rc_status pst = rc_geom_pair(m, s1, s2, &s1, &s2, &m->inter_pair[i], where, err);
    if (pst) return pst;
    /* IRS belongs to surf_ID1, IRm to surf_ID2, whichever is surface a */
    m->inter_orient[2 * i] = s1 == s1_in ? t6->irs : t6->irm;
    m->inter_orient[2 * i + 1] = s1 == s1_in ? t6->irm : t6->irs;
    /* no effect on an analytic surface: a box's faces point out of it */
    for (int e = 0; e < 2; e++)
        if (m->surf_kind[e ? s2 : s1] != RC_SURF_SEG) m->inter_orient[2 * i + e] = 0;
    m->inter_sa[i] = s1;
    m->inter_sb[i] = s2;
    m->inter_ba[i] = m->surf_body[s1];
    m->inter_bb[i] = m->surf_body[s2];
    if (m->inter_ba[i] == m->inter_bb[i])
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, fields surf_ID1/surf_ID2: both surfaces are on the same body; they must belong to two different rigid bodies",
                 RC_LOC(t6->line_loc[0]), card);
    m->inter_id[i] = t6->id;
    m->inter_loc[i] = t6->loc;
    m->inter_gap[i] = t6->gap;
    m->inter_tstart[i] = t6->tstart;
    m->inter_tstop[i] = t6->tstop;
    /* a sensor turns the interface on at its time (model/sensor.c) */
    rc_status sst = rc_sensor_tstart(c, t6->sensor_id, rc_loc_or(t6->line_loc[0], t6->loc), card, &m->inter_tstart[i],
                                     &m->inter_tstop[i], &m->inter_sens[i], err);
    if (sst) return sst;
    m->inter_visc[i] = t6->visc;
    m->inter_oneway[i] = t6->oneway && m->inter_pair[i] == RC_PAIR_SEG_SEG && s1 == s1_in;
    m->inter_edges[i] = rc_box_is_box_pair(m, i) ? (unsigned char)t6->edges_only : 0;
    if (t6->vis_crit > 0) {
        /* TYPE7's VISs: a fraction of the critical damping 2 sqrt(k m*) of
         * the linear law's slope k and the two bodies' reduced mass (a
         * fixed body is infinitely heavy) */
        const int bb[2] = {m->inter_ba[i], m->inter_bb[i]};
        double inv = 0.0;
        for (int k = 0; k < 2; k++)
            if (bb[k] >= 0 && !m->body_fixed[bb[k]]) inv += 1.0 / m->body_mass[bb[k]];
        const double kl = t6->fscaleld / t6->ascalex;
        m->inter_visc[i] = inv > 0 ? t6->vis_crit * 2.0 * sqrt(kl / inv) : 0.0;
    }
    m->inter_etarget[i] = t6->e_target;
    m->inter_vimp[i] = t6->v_imp;
    if (t6->e_target > 0) {
        /* the damping that gives it is derived with the scales
         * (engine/analyses/scales.c); it needs a law whose restitution is known */
        const rc_loc l6 = rc_loc_or(t6->line_loc[5], t6->loc);
        if (!(t6->e_target <= 1))
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field e_target: expected a restitution in (0, 1], got %g",
                     RC_LOC(l6), card, t6->e_target);
        if (t6->visc != 0 || t6->fct_dv != 0 || t6->iform != 0)
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field e_target: a restitution asked replaces the damping: "
                     "expected Visc = 0, fct_IDdv = 0 and Iform = 0 with it, got Visc %g, fct_IDdv %d, Iform %d",
                     RC_LOC(l6), card, t6->visc, t6->fct_dv, t6->iform);
    }
    m->inter_fscalev[i] = t6->fscalev;
    m->inter_ascalex[i] = t6->ascalex;
    m->inter_fscaleld[i] = t6->fscaleld;
    m->inter_ascalef[i] = t6->ascalef;
    m->inter_ascalev[i] = t6->ascalev;
    rc_status st;
    if ((st = rc_case_ref_funct(c, t6->fct_ld, 0, t6->line_loc[3], card, "fct_IDld", &m->inter_fct_ld[i], err))) return st;
    if ((st = rc_case_ref_funct(c, t6->fct_dv, 0, t6->line_loc[5], card, "fct_IDdv", &m->inter_fct_dv[i], err))) return st;
    if ((st = rc_case_ref_funct(c, t6->fct_df, 0, t6->line_loc[5], card, "fct_IDdf", &m->inter_fct_df[i], err))) return st;
    if ((st = rc_case_ref_funct(c, t6->fct_ul, 0, t6->line_loc[4], card, "fct_IDul", &m->inter_fct_ul[i], err))) return st;
    m->inter_iform[i] = t6->iform;
    m->inter_icor[i] = t6->icor;
    m->inter_inacti[i] = t6->inacti;
    m->inter_stiff[i] = t6->stiff;
    m->inter_fscaleul[i] = t6->fscaleul;
    /* Iform 2 has no unload curve (floor at zero); Iform 1 without one behaves as 2 */
    if (t6->iform == 2) m->inter_fct_ul[i] = -1;
    /* friction of the TYPE6 card itself: limit Sfric + Fric f_ff f_fv F_n,
     * incremental, stick stiffness Stiff or, when not given, the steepest
     * slope of the load curve (a /FRICTION card may override it) */
    rc_fric *fr = &m->inter_fr[i];
    fr->fct_ff = fr->fct_fv = -1;
    fr->tidx = fr->fidx = fr->widx = fr->obody = -1;
    if ((st = rc_case_ref_funct(c, t6->fct_ff, 0, t6->line_loc[2], card, "fct_IDff", &fr->fct_ff, err))) return st;
    if ((st = rc_case_ref_funct(c, t6->fct_fv, 0, t6->line_loc[2], card, "fct_IDfv", &fr->fct_fv, err))) return st;
    fr->sfric = t6->sfric;
    fr->fric = t6->fric;
    fr->kind = t6->sfric > 0 || t6->fric > 0 ? RC_FK_TYPE6 : RC_FK_NONE;
    fr->form = RC_FF_INCREMENTAL;
    double at = 0;
    fr->kt = t6->stiff > 0 ? t6->stiff
                           : max_slope(&m->table[m->inter_fct_ld[i]], m->inter_fscaleld[i], m->inter_ascalex[i], &at);
    if (fr->kind != RC_FK_NONE && !(fr->kt > 0))
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field Stiff: friction needs a tangential stiffness [N/m]; the default (the load curve's steepest slope) is 0",
                 RC_LOC(t6->line_loc[4]), card);
    if (m->inter_fct_ld[i] < 0)
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field fct_IDld: expected the id of the load curve (required), got 0",
                 RC_LOC(t6->line_loc[3]), card);
    /* exact stick (ricochet's Istick, Fric_s): the stick limit Sfric + Fric_s F_n */
    fr->exact = t6->istick == 1;
    fr->mus = t6->fric_s > 0 ? t6->fric_s : t6->fric;
    if (fr->exact && fr->kind == RC_FK_NONE)
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field Istick: exact stick (1) asks for friction, but Sfric and Fric "
                                           "are 0: expected Sfric > 0 or Fric > 0, or Istick blank",
                 RC_LOC(t6->line_loc[2]), card);
    if (fr->exact && fr->fct_fv >= 0)
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field Istick: exact stick with a speed-dependent coefficient "
                                           "(fct_IDfv) is not supported yet: expected Istick blank or fct_IDfv 0",
                 RC_LOC(t6->line_loc[2]), card);
    if ((st = check_hysteresis(m, i, t6, card, err))) return st;
    m->inter_name[i] = malloc(strlen(card) + 1);
    if (!m->inter_name[i]) RC_RAISE(err, RC_ENOMEM, "out of memory");
    strcpy(m->inter_name[i], card);
    return RC_OK;
}

/* Exact stick (docs/theory.md, "Exact stick") holds one contact point:
 * interfaces with several points are refused. */
static rc_status check_exact_stick(const rc_case *c, rc_model *m, rc_error *err)
{
    for (int i = 0; i < m->ninter; i++) {
        const rc_fric *fr = &m->inter_fr[i];
        if (!fr->exact || !rc_pair_multi(m->inter_pair[i])) continue;
        rc_loc loc = m->inter_loc[i];
        char what[80];
        snprintf(what, sizeof what, "%s, field Istick", m->inter_name[i]);
        for (int k = 0; k < c->nfriction; k++)
            if (fr->kind == RC_FK_CARD && c->friction[k].id == fr->card_id) {
                loc = c->friction[k].line_loc[0];
                snprintf(what, sizeof what, "/FRICTION/%d, field Iform", fr->card_id);
            }
        for (int k = 0; fr->kind != RC_FK_CARD && k < c->ntype6; k++)
            if (c->type6[k].id == m->inter_id[i]) loc = c->type6[k].line_loc[2];
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s: exact stick on %s, a %s pair with several contact points, is not supported yet: "
                           "expected a single-point pair (sphere, cylinder against a plane, box, sphere) or the "
                           "incremental friction",
                 RC_LOC(loc), what, m->inter_name[i], rc_geom_inter_pair_name(m, i));
    }
    return RC_OK;
}

/* ---- state layout and tolerances -------------------------------------- */
/* Does interface i integrate its law's dissipation D_h (own state
 * inter_dhidx) for its hysteresis channel? With several contact points
 * (P_e) and a law whose stored energy is the law's energy at P_e (Iform 0,
 * the power law): D_h' = F_el kappa (P_e - P)+ closed; with the Iform 1, 2
 * hysteresis (one or several points, no Inacti 5 offset) that plus, on the
 * load curve, Delta (Stiff - F_L') dP/dt, Delta the length of the
 * unloading path's first Stiff line: energy_hysteresis is then the
 * integral of a rate >= 0 rather than the difference of W_load and the
 * stored energy, which their separate integration errors made fall
 * (docs/theory.md 2.7, 4). */
static int hyst_state(const rc_model *m, int i)
{
    if (m->inter_law[i] != RC_LAW_POWER && m->inter_iform[i] != 0) return m->inter_oidx[i] < 0;
    return m->inter_peidx[i] >= 0;
}

static rc_status layout(const rc_case *c, rc_model *m, rc_error *err)
{
    int ny = 0;
    for (int b = 0; b < m->nbody; b++) {
        m->body_yadr[b] = m->body_fixed[b] ? -1 : ny;
        if (!m->body_fixed[b]) {
            ny += RC_NB;
            m->nfree++;
        }
    }
    for (int i = 0; i < m->ninter; i++) {
        m->inter_eadr[i] = ny;
        int ns = RC_NE;
        m->inter_hidx[i] = m->inter_iform[i] != 0 ? ns++ : -1;
        m->inter_oidx[i] = m->inter_inacti[i] == 5 ? ns++ : -1;
        m->inter_peidx[i] = rc_pair_multi(m->inter_pair[i]) ? ns++ : -1;
        m->inter_dhidx[i] = hyst_state(m, i) ? ns++ : -1;
        rc_fric *fr = &m->inter_fr[i];
        /* friction per contact point (a segment surface's nodes): F_t of
         * each point after the own states, none for the interface */
        const int per_point = fr->kind != RC_FK_NONE && rc_pair_nodes(m->inter_pair[i]);
        m->inter_pbase[i] = m->npt;
        m->inter_npt[i] = per_point ? rc_seg_points(m, i) : 0;
        m->npt += m->inter_npt[i];
        m->inter_pst[i] = per_point && fr->form == RC_FF_INCREMENTAL && fr->tau > 0 ? 6 : 3;
        if (fr->kind != RC_FK_NONE) {
            if (fr->form == RC_FF_INCREMENTAL && !per_point) {
                fr->tidx = ns;
                ns += 3;
            }
            if (fr->tau > 0) {
                fr->fidx = ns;
                ns += 3;
            }
            fr->widx = ns++;
        }
        m->inter_ns[i] = ns;
        ny += ns + m->inter_pst[i] * m->inter_npt[i];
    }
    ny = rc_cpl_layout(m, ny);
    /* a gravity that varies in time has no potential: integrate its work */
    m->gwork_adr = m->grav_table >= 0 || m->grav_tstart > 0 || m->grav_sens >= 0 ? ny++ : -1;
    /* work of the imposed velocities (imposed.c) */
    ny = rc_imp_layout(m, ny);
    m->ny = ny;
    /* rows of held DOFs (accelerations set to zero), for rhs and Jacobian */
    m->nheld = 0;
    m->held = malloc((size_t)(6 * m->nbody + 1) * sizeof(int));
    if (!m->held) RC_RAISE(err, RC_ENOMEM, "out of memory");
    for (int b = 0; b < m->nbody; b++)
        for (int j = 0; j < 6 && m->body_yadr[b] >= 0; j++)
            if (m->body_dofmask[6 * b + j]) m->held[m->nheld++] = m->body_yadr[b] + 7 + j;
    m->row_held = calloc((size_t)ny + 1, 1);
    if (!m->row_held) RC_RAISE(err, RC_ENOMEM, "out of memory");
    /* each state's contact point (its error weight follows the point's
     * share, rc_point_ewt_scale), -1 for the others */
    m->state_pt = malloc(((size_t)ny + 1) * sizeof(int));
    if (!m->state_pt) RC_RAISE(err, RC_ENOMEM, "out of memory");
    for (int k = 0; k < ny; k++) m->state_pt[k] = -1;
    for (int i = 0; i < m->ninter; i++)
        for (int j = 0; j < m->inter_npt[i]; j++)
            for (int k = 0; k < m->inter_pst[i]; k++)
                m->state_pt[m->inter_eadr[i] + m->inter_ns[i] + m->inter_pst[i] * j + k] = m->inter_pbase[i] + j;
    for (int k = 0; k < m->nheld; k++) m->row_held[m->held[k]] = 1;
    if (ny == 0) RC_RAISE(err, RC_EINPUT, RC_LOCFMT "the case has nothing to integrate (no free body)", RC_LOC(m->end_loc));
    return RC_OK;
}

/* The file of a location as the model's own copy (m->file, m->case_path):
 * the messages of the model's setters and runs name their cards after the
 * case is freed (it may be, once compiled). */
static const char *own_file(const rc_case *c, const rc_model *m, const char *f)
{
    if (!f) return f;
    if (c->path && !strcmp(f, c->path) && m->case_path) return m->case_path;
    for (int k = 0; k < m->nfile; k++)
        if (m->file[k] && !strcmp(f, rc_case_file(c, k))) return m->file[k];
    return f;
}

/* The locations the model keeps for its messages, on its own file names. */
static void own_locations(const rc_case *c, rc_model *m)
{
    m->end_loc.file = own_file(c, m, m->end_loc.file);
    m->preload_loc.file = own_file(c, m, m->preload_loc.file);
    for (int b = 0; b < m->nbody; b++) m->body_loc[b].file = own_file(c, m, m->body_loc[b].file);
    for (int i = 0; i < m->ninter; i++) m->inter_loc[i].file = own_file(c, m, m->inter_loc[i].file);
    for (int k = 0; m->cpl && m->cpl->law_loc && k < m->cpl->n; k++)
        m->cpl->law_loc[k].file = own_file(c, m, m->cpl->law_loc[k].file);
    for (int k = 0; m->jnt && m->jnt->loc && k < m->jnt->n; k++) m->jnt->loc[k].file = own_file(c, m, m->jnt->loc[k].file);
}

rc_status rc_model_build(const rc_case *c, rc_model **out, rc_error *err)
{
    return rc_model_build_drop(c, NULL, out, err);
}

rc_status rc_model_build_drop(const rc_case *c, const rc_t7_drop *drop, rc_model **out, rc_error *err)
{
    rc_status st = RC_OK;
    *out = NULL;
    /* the rigid walls: the case with their surfaces, load curve and (once
     * the bodies and surfaces are known) contacts appended (model/rwall.c) */
    /* first the bodies held until their sensor's time (model/sensor.c) */
    rc_sensor_case sx;
    rc_rwall_case rx;
    rc_type7_case tx; /* then the TYPE7 cards' point surfaces (model/type7.c) */
    if ((st = rc_sensor_begin(c, &sx, err))) return st;
    if ((st = rc_type7_begin(&sx.c, drop, &tx, err))) {
        rc_sensor_end(&sx);
        return st;
    }
    if ((st = rc_rwall_begin(&tx.c, &rx, err))) {
        rc_type7_end(&tx);
        rc_sensor_end(&sx);
        return st;
    }
    c = &rx.c;
    rc_model *m = calloc(1, sizeof *m);
    if (!m) {
        rc_rwall_end(&rx);
        rc_type7_end(&tx);
        rc_sensor_end(&sx);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    /* provenance and settings */
    m->case_path = malloc(strlen(c->path) + 1);
    if (!m->case_path) {
        st = RC_SET(err, RC_ENOMEM, "out of memory");
        goto fail;
    }
    strcpy(m->case_path, c->path);
    if (c->overrides && !(m->overrides = strdup(c->overrides))) {
        st = RC_SET(err, RC_ENOMEM, "out of memory");
        goto fail;
    }
    m->end_loc = rc_loc_or(c->end, (rc_loc){c->path, 1});
    /* the files read, for the results file's checksums */
    m->nfile = rc_case_file_count(c);
    m->file = calloc((size_t)m->nfile + 1, sizeof *m->file);
    int files_ok = m->file != NULL;
    for (int k = 0; m->file && k < m->nfile; k++)
        if ((m->file[k] = malloc(strlen(rc_case_file(c, k)) + 1))) strcpy(m->file[k], rc_case_file(c, k));
        else files_ok = 0;
    /* and their device and inode as read: the results never overwrite them */
    if (files_ok && c->file_id) {
        m->file_id = malloc(4 * ((size_t)m->nfile + 1) * sizeof *m->file_id);
        if (m->file_id) memcpy(m->file_id, c->file_id, 4 * (size_t)m->nfile * sizeof *m->file_id);
        else files_ok = 0;
    }
    if (!files_ok) {
        st = RC_SET(err, RC_ENOMEM, "out of memory");
        goto fail;
    }
    snprintf(m->title, sizeof m->title, "%s", c->title);
    snprintf(m->unit_mass, sizeof m->unit_mass, "%s", c->unit_mass);
    snprintf(m->unit_length, sizeof m->unit_length, "%s", c->unit_length);
    for (int k = 0; k < 3; k++) {
        snprintf(m->deck_unit[k], sizeof m->deck_unit[k], "%s", c->deck_unit[k]);
        m->deck_factor[k] = c->deck_factor[k];
    }
    snprintf(m->unit_time, sizeof m->unit_time, "%s", c->unit_time);
    m->checksum = c->checksum;
    m->tend = c->run.tend;
    m->dtout = c->run.dtout;
    m->ev_state = c->run.ev_state;
    m->on_violation = c->run.on_violation;
    m->rtol = c->solver.rtol;
    m->atol_pos = c->solver.atol_pos;
    m->atol_quat = c->solver.atol_quat;
    m->atol_vel = c->solver.atol_vel;
    m->atol_omega = c->solver.atol_omega;
    m->atol_energy = c->solver.atol_energy;
    /* blank (zero) absolute tolerances are derived from the model (scales.c) */
    m->tol_auto = (m->atol_pos == 0 ? RC_TOL_AUTO_POS : 0) | (m->atol_quat == 0 ? RC_TOL_AUTO_QUAT : 0) |
                  (m->atol_vel == 0 ? RC_TOL_AUTO_VEL : 0) | (m->atol_omega == 0 ? RC_TOL_AUTO_OMEGA : 0) |
                  (m->atol_energy == 0 ? RC_TOL_AUTO_ENERGY : 0);
    /* exact stick (TYPE6 Istick 1, /FRICTION Iform 3): a constraint of the IDA path */
    int nexact = 0;
    rc_loc exact_loc = c->end;
    char exact_what[80] = "";
    for (int k = c->nfriction - 1; k >= 0; k--)
        if (c->friction[k].iform == 3) {
            nexact++;
            exact_loc = c->friction[k].line_loc[0];
            snprintf(exact_what, sizeof exact_what, "/FRICTION/%d, field Iform (3)", c->friction[k].id);
        }
    for (int k = c->ntype6 - 1; k >= 0; k--)
        if (c->type6[k].istick == 1) {
            nexact++;
            exact_loc = c->type6[k].line_loc[2];
            snprintf(exact_what, sizeof exact_what, "/INTER/TYPE6/%d, field Istick (1)", c->type6[k].id);
        }
    if (nexact > 0 && c->solver.method == 1) {
        st = RC_SET(err, RC_EINPUT,
                    RC_LOCFMT "card /SOLVER, field Method: exact stick (%s, line %d) is a constraint that only the IDA "
                              "path (Method 2) runs; expected 0 (automatic), blank or 2, got 1",
                    RC_LOC(c->solver.method_loc), exact_what, exact_loc.line);
        goto fail;
    }
    /* Method 0: IDA for a model with joints or exact stick, else CVODE */
    m->method = c->solver.method ? c->solver.method : c->njoint > 0 || nexact > 0 ? 2 : 1;
    if (c->njoint > 0 && m->method == 1) {
        st = RC_SET(err, RC_EINPUT,
                 RC_LOCFMT "card /SOLVER, field Method: the model has joints (%d), which only the IDA path (Method "
                           "2) runs; expected 0 (automatic), blank or 2, got 1",
                 RC_LOC(c->solver.method_loc), c->njoint);
        goto fail;
    }
    m->preload = c->solver.preload;
    m->method_switch = c->solver.method_switch;
    m->preload_loc = c->solver.method_loc;
    m->max_order = c->solver.max_order;
    m->max_steps = c->solver.max_steps;
    m->hmax = c->solver.hmax;
    m->h0 = c->solver.h0;
    m->ground_y0[3] = 1.0;
    /* the model's origin: the centre of the nodes' bounding box. The model
     * works in coordinates relative to it (x - origin), so that its
     * numbers are those of the scene's size, not of its distance from the
     * deck's origin (a scene 1 km away resolves as one at the origin;
     * docs/theory.md 7.1). While compiling, the deck's global points are
     * made local to the ground frame placed at the origin; at the end the
     * bodies' poses move to it (shift_origin) */
    if (c->nnode > 0) {
        double lo[3], hi[3];
        for (int k = 0; k < 3; k++) lo[k] = hi[k] = c->node[0].x[k];
        for (int j = 1; j < c->nnode; j++)
            for (int k = 0; k < 3; k++) {
                lo[k] = fmin(lo[k], c->node[j].x[k]);
                hi[k] = fmax(hi[k], c->node[j].x[k]);
            }
        /* only a scene far from the deck's origin for its size: one near it
         * keeps the deck's coordinates (its rounding is that of its size) */
        double cmax = 0.0, half = 0.0;
        for (int k = 0; k < 3; k++) {
            cmax = fmax(cmax, fabs(0.5 * (lo[k] + hi[k])));
            half = fmax(half, 0.5 * (hi[k] - lo[k]));
        }
        if (cmax > RC_ORIGIN_FAR * half && cmax > RC_ORIGIN_MIN)
            for (int k = 0; k < 3; k++) m->origin[k] = m->ground_y0[k] = 0.5 * (lo[k] + hi[k]);
    }
    m->grav_table = -1;
    m->grav_ascale = 1.0;
    m->grav_sens = -1;

    /* curves */
    m->ntable = c->nfunct;
    ALLOC(m->table, m->ntable);
    for (int k = 0; k < c->nfunct; k++) {
        const rc_case_funct *f = &c->funct[k];
        if ((st = rc_table_init(&m->table[k], f->id, f->npts, f->x, f->y, err))) goto fail;
    }
    /* bodies */
    m->nbody = c->nrbody;
    if (m->nbody == 0) {
        st = RC_SET(err, RC_EINPUT, RC_LOCFMT "no /RBODY card: ricochet needs at least one rigid body", RC_LOC(m->end_loc));
        goto fail;
    }
    ALLOC(m->body_id, m->nbody);
    ALLOC(m->body_fixed, m->nbody);
    ALLOC(m->body_yadr, m->nbody);
    ALLOC(m->body_mass, m->nbody);
    ALLOC(m->body_J, 9 * m->nbody);
    ALLOC(m->body_Jinv, 9 * m->nbody);
    ALLOC(m->body_y0, RC_NB * m->nbody);
    ALLOC(m->body_grav, 3 * m->nbody);
    ALLOC(m->body_dofmask, 6 * m->nbody);
    ALLOC(m->body_loc, m->nbody);
    if ((st = compile_bodies(c, m, err))) goto fail;
    if ((st = rc_rwall_bodies(&rx, m, err))) goto fail;
    /* surfaces */
    m->nsurf = c->nsurf;
    ALLOC(m->surf_id, m->nsurf);
    ALLOC(m->surf_kind, m->nsurf);
    ALLOC(m->surf_body, m->nsurf);
    ALLOC(m->surf_p, 3 * m->nsurf);
    ALLOC(m->surf_n, 3 * m->nsurf);
    ALLOC(m->surf_r, m->nsurf);
    ALLOC(m->surf_ext, RC_SURF_NEXT * m->nsurf);
    ALLOC(m->surf_nadr, m->nsurf + 1);
    ALLOC(m->surf_sadr, m->nsurf + 1);
    if ((st = compile_surfaces(c, m, &rx, err))) goto fail;
    if ((st = rc_rwall_points(&rx, m, err))) goto fail; /* a plane wall's nodes of bodies without surfaces */
    if ((st = rc_seg_meshes(m, err))) goto fail; /* model/segsurf.c */
    if ((st = rc_rwall_contacts(&rx, m, err))) goto fail; /* the walls' contacts, TYPE6 laws */
    if ((st = rc_type7_contacts(&tx, &rx.c, m, err))) goto fail; /* the TYPE7 contacts, TYPE6 laws */
    /* interfaces */
    m->ninter = c->ntype6 + c->npower; /* TYPE6, then /INTER/POWER */
    ALLOC(m->inter_id, m->ninter);
    ALLOC(m->inter_pair, m->ninter);
    ALLOC(m->inter_sa, m->ninter);
    ALLOC(m->inter_sb, m->ninter);
    ALLOC(m->inter_ba, m->ninter);
    ALLOC(m->inter_bb, m->ninter);
    ALLOC(m->inter_gap, m->ninter);
    ALLOC(m->inter_tstart, m->ninter);
    ALLOC(m->inter_tstop, m->ninter);
    ALLOC(m->inter_sens, m->ninter);
    ALLOC(m->inter_visc, m->ninter);
    ALLOC(m->inter_etarget, m->ninter);
    ALLOC(m->inter_vimp, m->ninter);
    ALLOC(m->inter_fscalev, m->ninter);
    ALLOC(m->inter_ascalex, m->ninter);
    ALLOC(m->inter_fscaleld, m->ninter);
    ALLOC(m->inter_ascalef, m->ninter);
    ALLOC(m->inter_ascalev, m->ninter);
    ALLOC(m->inter_fct_ld, m->ninter);
    ALLOC(m->inter_fct_dv, m->ninter);
    ALLOC(m->inter_fct_df, m->ninter);
    ALLOC(m->inter_eadr, m->ninter);
    ALLOC(m->inter_fct_ul, m->ninter);
    ALLOC(m->inter_iform, m->ninter);
    ALLOC(m->inter_icor, m->ninter);
    ALLOC(m->inter_inacti, m->ninter);
    ALLOC(m->inter_stiff, m->ninter);
    ALLOC(m->inter_fscaleul, m->ninter);
    ALLOC(m->inter_ns, m->ninter);
    ALLOC(m->inter_hidx, m->ninter);
    ALLOC(m->inter_oidx, m->ninter);
    ALLOC(m->inter_peidx, m->ninter);
    ALLOC(m->inter_dhidx, m->ninter);
    ALLOC(m->inter_fr, m->ninter);
    ALLOC(m->inter_npt, m->ninter);
    ALLOC(m->inter_pst, m->ninter);
    ALLOC(m->inter_orient, 2 * m->ninter);
    ALLOC(m->inter_oneway, m->ninter);
    ALLOC(m->inter_edges, m->ninter);
    ALLOC(m->inter_pbase, m->ninter);
    ALLOC(m->inter_ptslot, m->ninter);
    ALLOC(m->inter_name, m->ninter);
    ALLOC(m->inter_loc, m->ninter);
    ALLOC(m->inter_law, m->ninter);
    ALLOC(m->inter_pw, m->ninter);
    for (int i = 0; i < c->ntype6; i++) {
        rc_progress(i, c->ntype6);
        if ((st = compile_type6(c, m, i, err))) goto fail;
    }
    for (int k = 0; k < c->npower; k++) /* model/power.c */
        if ((st = rc_power_compile(c, m, k, c->ntype6 + k, err))) goto fail;
    if ((st = rc_friction_compile(c, m, err))) goto fail;
    if ((st = check_exact_stick(c, m, err))) goto fail;
    /* couplings (model/coupling.c) */
    if ((st = rc_cpl_compile(c, m, err))) goto fail;
    /* imposed velocities (imposed.c) */
    if ((st = rc_imp_compile(c, m, err))) goto fail;
    /* states (the tolerances and the Jacobian pattern follow in
     * engine/analyses/prepare.c) */
    if ((st = layout(c, m, err))) goto fail;
    /* joints (model/joint.c), on the state layout */
    if ((st = rc_jnt_compile(c, m, err))) goto fail;
    /* into the origin's coordinates: the bodies' poses; the ground frame,
     * whose local points were taken from the origin, becomes the global */
    for (int b = 0; b < m->nbody; b++)
        for (int k = 0; k < 3; k++) m->body_y0[RC_NB * b + k] -= m->origin[k];
    for (int k = 0; k < 3; k++) m->ground_y0[k] = 0.0;
    /* sensors (model/sensor.c), on the bodies' poses */
    if ((st = rc_sensor_compile(c, m, err))) goto fail;
    own_locations(c, m);
    rc_rwall_end(&rx);
    rc_type7_end(&tx);
    rc_sensor_end(&sx);
    *out = m;
    return RC_OK;
fail:
    rc_rwall_end(&rx);
    rc_type7_end(&tx);
    rc_sensor_end(&sx);
    rc_model_free(m);
    return st;
}

void rc_model_free(rc_model *m)
{
    if (!m) return;
    if (m->table)
        for (int k = 0; k < m->ntable; k++) rc_table_free(&m->table[k]);
    if (m->inter_name)
        for (int i = 0; i < m->ninter; i++) free(m->inter_name[i]);
    rc_jac_free(m);
    rc_cpl_free(m->cpl);
    rc_jnt_free(m->jnt);
    rc_power_free(m);
    rc_imp_free(m->imp);
    if (m->file)
        for (int k = 0; k < m->nfile; k++) free(m->file[k]);
    free(m->file);
    free(m->file_id);
    rc_seg_free(m);
    for (int k = 0; m->note && k < m->nnote; k++) free(m->note[k]);
    free(m->note);
    free(m->surf_nid);
    void *arrays[] = {m->case_path, m->overrides, m->table, m->body_id, m->body_fixed, m->body_yadr, m->body_mass,
                      m->body_J, m->body_Jinv, m->body_y0, m->body_grav, m->body_dofmask, m->surf_id, m->surf_kind,
                      m->surf_body, m->surf_p, m->surf_n, m->surf_r, m->inter_id, m->inter_pair,
                      m->inter_sa, m->inter_sb, m->inter_ba, m->inter_bb, m->inter_gap,
                      m->inter_tstart, m->inter_tstop, m->inter_sens, m->sens_id, m->sens_kind, m->sens_in, m->sens_hold, m->sens_tdelay, m->sens_tmin,
                      m->sens_body, m->sens_p, m->sens_d, m->sens_inter, m->inter_visc, m->inter_etarget, m->inter_vimp, m->inter_fscalev,
                      m->inter_ascalex, m->inter_fscaleld, m->inter_ascalef, m->inter_ascalev,
                      m->inter_fct_ld, m->inter_fct_dv, m->inter_fct_df, m->inter_eadr,
                      m->inter_fct_ul, m->inter_iform, m->inter_icor, m->inter_inacti, m->inter_stiff,
                      m->inter_fscaleul, m->inter_ns, m->inter_hidx, m->inter_oidx, m->inter_peidx, m->inter_dhidx, m->inter_fr,
                      m->inter_name, m->atol, m->held, m->row_held, m->gwork_slot, m->surf_ext,
                      m->inter_law, m->inter_pw, m->inter_pscale, m->inter_fscale, m->inter_kscale,
                      m->inter_vscale, m->inter_mred, m->inter_mrest, m->inter_pweight, m->inter_pimpact, m->inter_sband, m->inter_perelax, m->inter_hband, m->ewt_rel, m->body_loc, m->inter_loc,
                      m->surf_nadr, m->surf_node, m->surf_sadr, m->surf_seg, m->inter_npt, m->inter_pst, m->inter_pbase,
                      m->inter_ptslot, m->surf_seg_turned, m->inter_orient, m->inter_oneway, m->inter_edges, m->inter_fast, m->start_note, m->state_pt};
    for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; k++) free(arrays[k]);
    free(m);
}

int rc_model_state_size(const rc_model *m) { return m ? m->ny : 0; }

int rc_model_note_count(const rc_model *m) { return m ? m->nnote : 0; }

rc_status rc_model_add_note(rc_model *m, char *s, rc_error *err)
{
    char **nn = s ? realloc(m->note, ((size_t)m->nnote + 1) * sizeof *nn) : NULL;
    if (!nn) {
        free(s);
        RC_RAISE(err, RC_ENOMEM, "out of memory for the compiler's notices");
    }
    m->note = nn;
    m->note[m->nnote++] = s;
    return RC_OK;
}

const char *rc_model_note(const rc_model *m, int i) { return m && i >= 0 && i < m->nnote ? m->note[i] : NULL; }
