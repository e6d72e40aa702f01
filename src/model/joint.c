/*
 * Compile the /JOINT cards (case_joint.h) into rc_joints (joint.h): the
 * bodies, the anchor points and the joint frame in the body frames, the
 * constraint rows of each kind; the summary of `ricochet check`.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "case/case_joint.h"
#include "model/imposed.h"
#include "model/coupling.h"
#include "model/joint.h"
#include "model/table.h"

static const char *const kind_name[6] = {"", "SPHERICAL", "REVOLUTE", "DISTANCE", "FIXED", "PRISMATIC"};

void rc_jnt_free(rc_joints *j)
{
    if (!j) return;
    if (j->name)
        for (int k = 0; k < j->n; k++) free(j->name[k]);
    void *p[] = {j->id, j->kind, j->name, j->loc, j->ba, j->bb, j->sa, j->sb, j->ua, j->ub, j->len, j->nrow, j->radr,
                 j->rkind, j->rarg};
    for (size_t k = 0; k < sizeof p / sizeof p[0]; k++) free(p[k]);
    free(j);
}

/* A right-handed orthonormal frame with e[0] along the unit axis a. */
void rc_jnt_axis_frame(const double a[3], double e[9])
{
    memcpy(e, a, 3 * sizeof(double));
    /* the global axis least aligned with a */
    int k = fabs(a[0]) <= fabs(a[1]) && fabs(a[0]) <= fabs(a[2]) ? 0 : fabs(a[1]) <= fabs(a[2]) ? 1 : 2;
    double t[3] = {0, 0, 0}, v[3], w[3];
    t[k] = 1.0;
    v[0] = a[1] * t[2] - a[2] * t[1];
    v[1] = a[2] * t[0] - a[0] * t[2];
    v[2] = a[0] * t[1] - a[1] * t[0];
    const double nv = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int i = 0; i < 3; i++) v[i] /= nv;
    w[0] = a[1] * v[2] - a[2] * v[1];
    w[1] = a[2] * v[0] - a[0] * v[2];
    w[2] = a[0] * v[1] - a[1] * v[0];
    memcpy(e + 3, v, sizeof v);
    memcpy(e + 6, w, sizeof w);
}

/* Rows of each kind: (row kind, arg0, arg1). */
static int kind_rows(rc_jnt_kind k, int *rk, int *ra)
{
    int n = 0;
#define ROW(kind, x, y) (rk[n] = (kind), ra[2 * n] = (x), ra[2 * n + 1] = (y), n++)
    if (k == RC_JNT_SPHERICAL || k == RC_JNT_REVOLUTE || k == RC_JNT_FIXED)
        for (int i = 0; i < 3; i++) ROW(RC_JROW_POINT, i, 0);
    if (k == RC_JNT_REVOLUTE) { /* a's axis normal to b's two normals */
        ROW(RC_JROW_ANGLE, 0, 1);
        ROW(RC_JROW_ANGLE, 0, 2);
    }
    if (k == RC_JNT_FIXED || k == RC_JNT_PRISMATIC) { /* no relative rotation */
        ROW(RC_JROW_ANGLE, 0, 1);
        ROW(RC_JROW_ANGLE, 0, 2);
        ROW(RC_JROW_ANGLE, 1, 2);
    }
    if (k == RC_JNT_PRISMATIC) { /* no relative motion across the axis */
        ROW(RC_JROW_SLIDE, 1, 0);
        ROW(RC_JROW_SLIDE, 2, 0);
    }
    if (k == RC_JNT_DISTANCE) ROW(RC_JROW_DIST, 0, 0);
#undef ROW
    return n;
}

rc_status rc_jnt_compile(const rc_case *c, rc_model *m, rc_error *err)
{
    m->jnt = NULL;
    if (c->njoint == 0) return RC_OK;
    rc_joints *J = calloc(1, sizeof *J);
    if (!J) RC_RAISE(err, RC_ENOMEM, "out of memory");
    m->jnt = J;
    const int n = c->njoint;
    J->n = n;
#define JALLOC(p, cnt) \
    if (!((p) = calloc((size_t)(cnt) + 1, sizeof *(p)))) RC_RAISE(err, RC_ENOMEM, "out of memory");
    JALLOC(J->id, n);
    JALLOC(J->kind, n);
    JALLOC(J->name, n);
    JALLOC(J->loc, n);
    JALLOC(J->ba, n);
    JALLOC(J->bb, n);
    JALLOC(J->sa, 3 * n);
    JALLOC(J->sb, 3 * n);
    JALLOC(J->ua, 9 * n);
    JALLOC(J->ub, 9 * n);
    JALLOC(J->len, n);
    JALLOC(J->nrow, n);
    JALLOC(J->radr, n);
    JALLOC(J->rkind, RC_JNT_MAXROW * n);
    JALLOC(J->rarg, 2 * RC_JNT_MAXROW * n);
#undef JALLOC
    int nrows = 0;
    for (int j = 0; j < n; j++) {
        const rc_case_joint *cj = &c->joint[j];
        char card[64];
        snprintf(card, sizeof card, "/JOINT/%s/%d", kind_name[cj->kind], cj->id);
        if (!(J->name[j] = malloc(strlen(card) + 1))) RC_RAISE(err, RC_ENOMEM, "out of memory");
        strcpy(J->name[j], card);
        J->id[j] = cj->id;
        J->kind[j] = (rc_jnt_kind)cj->kind;
        J->loc[j] = cj->loc;
        int *bs[2] = {&J->ba[j], &J->bb[j]};
        for (int e = 0; e < 2; e++) {
            int b = -1;
            if (cj->rbody[e] != 0 && (b = rc_case_find_rbody(c, cj->rbody[e])) < 0)
                RC_RAISE(err, RC_EINPUT,
                         RC_LOCFMT "card %s, field rbody_ID%d: expected the id of a /RBODY%s, got %d (no such body)",
                         RC_LOC(cj->line_loc[0]), card, e + 1, e ? " or 0 (the ground)" : "", cj->rbody[e]);
            /* a fixed body is part of the ground: its pose is constant */
            *bs[e] = b;
        }
        const int fa = J->ba[j] >= 0 && m->body_yadr[J->ba[j]] >= 0;
        const int fb = J->bb[j] >= 0 && m->body_yadr[J->bb[j]] >= 0;
        if (!fa && !fb)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card %s, fields rbody_ID1 rbody_ID2: expected at least one free rigid body, got "
                               "%d and %d (ground or fixed bodies only: the joint constrains nothing)",
                     RC_LOC(cj->line_loc[0]), card, cj->rbody[0], cj->rbody[1]);
        /* a velocity held or imposed on a jointed body would fight the
         * reaction (its row carries no reaction term) */
        for (int e = 0; e < 2; e++) {
            const int b = *bs[e];
            if (b < 0 || m->body_yadr[b] < 0) continue;
            int held = 0;
            for (int k = 0; k < 6; k++) held |= m->body_dofmask[6 * b + k];
            for (int k = 0; m->imp && k < m->imp->nt; k++) held |= m->imp->tbody[k] == b;
            for (int k = 0; m->imp && k < m->imp->nr; k++) held |= m->imp->rbody[k] == b;
            if (held)
                RC_RAISE(err, RC_EINPUT,
                         RC_LOCFMT "card %s, field rbody_ID%d: body %d has degrees of freedom held by /BCS or "
                                   "imposed by /IMPVEL; a joint on such a body is not supported yet",
                         RC_LOC(cj->line_loc[0]), card, e + 1, cj->rbody[e]);
        }
        /* body frames = global frame at t = 0, origins at the centres of mass */
        const double *pb = cj->kind == RC_CASE_JNT_DISTANCE ? cj->p2 : cj->p;
        const double *oa = J->ba[j] >= 0 ? m->body_y0 + RC_NB * J->ba[j] : m->ground_y0;
        const double *ob = J->bb[j] >= 0 ? m->body_y0 + RC_NB * J->bb[j] : m->ground_y0;
        for (int k = 0; k < 3; k++) {
            J->sa[3 * j + k] = cj->p[k] - oa[k];
            J->sb[3 * j + k] = pb[k] - ob[k];
        }
        double ax[3] = {1, 0, 0};
        if (cj->kind == RC_CASE_JNT_REVOLUTE || cj->kind == RC_CASE_JNT_PRISMATIC) {
            const double na = sqrt(cj->axis[0] * cj->axis[0] + cj->axis[1] * cj->axis[1] + cj->axis[2] * cj->axis[2]);
            for (int k = 0; k < 3; k++) ax[k] = cj->axis[k] / na;
        }
        rc_jnt_axis_frame(ax, J->ua + 9 * j);
        memcpy(J->ub + 9 * j, J->ua + 9 * j, 9 * sizeof(double));
        if (cj->kind == RC_CASE_JNT_DISTANCE)
            J->len[j] = sqrt(pow(cj->p2[0] - cj->p[0], 2) + pow(cj->p2[1] - cj->p[1], 2) + pow(cj->p2[2] - cj->p[2], 2));
        J->radr[j] = nrows;
        J->nrow[j] = kind_rows(J->kind[j], J->rkind + nrows, J->rarg + 2 * nrows);
        nrows += J->nrow[j];
    }
    J->nrows = nrows;
    return RC_OK;
}

void rc_jnt_print(const rc_model *m, FILE *f)
{
    const rc_joints *J = m->jnt;
    if (!J) return;
    for (int j = 0; j < J->n; j++) {
        fprintf(f, "  %s: body %d - %s%d, %d constraint rows, anchor on a (%.6g, %.6g, %.6g) m body frame", J->name[j],
                m->body_id[J->ba[j]], J->bb[j] >= 0 ? "body " : "ground ", J->bb[j] >= 0 ? m->body_id[J->bb[j]] : 0,
                J->nrow[j], J->sa[3 * j], J->sa[3 * j + 1], J->sa[3 * j + 2]);
        if (J->kind[j] == RC_JNT_REVOLUTE || J->kind[j] == RC_JNT_PRISMATIC)
            fprintf(f, ", axis (%.6g, %.6g, %.6g)", J->ua[9 * j], J->ua[9 * j + 1], J->ua[9 * j + 2]);
        if (J->kind[j] == RC_JNT_DISTANCE) fprintf(f, ", length %.9g m", J->len[j]);
        for (int k = m->cpl ? m->cpl->ncard : 0; m->cpl && k < m->cpl->n; k++) {
            if (m->cpl->ljoint[k] != j) continue;
            const char *u = m->cpl->lrev[k] ? "rad" : "m";
            fprintf(f, ", stops %.9g %s .. %.9g %s (", m->cpl->llo[k], u, m->cpl->lhi[k], u);
            if (m->cpl->table[k] >= 0) fprintf(f, "F_e from /FUNCT %d", m->table[m->cpl->table[k]].id);
            else fprintf(f, "K %.6g %s", m->cpl->coef[3 * k], m->cpl->lrev[k] ? "N m/rad" : "N/m");
            fprintf(f, ", C %.6g %s)", m->cpl->kd[k], m->cpl->lrev[k] ? "N m s/rad" : "N s/m");
        }
        fprintf(f, "\n");
    }
}

const char *rc_jnt_type_name(const rc_model *m, int j) { return kind_name[m->jnt->kind[j]]; }

void rc_jnt_extra_name(const rc_model *m, int k, char *buf, size_t n)
{
    const rc_joints *J = m->jnt;
    if (k >= 2 * J->nrows) {
        snprintf(buf, n, "the work of the joint reactions [J]");
        return;
    }
    const int row = k % J->nrows;
    int j = 0;
    while (j + 1 < J->n && J->radr[j + 1] <= row) j++;
    const int ang = J->rkind[row] == RC_JROW_ANGLE;
    snprintf(buf, n, "%s, %s of constraint row %d [%s]", J->name[j],
             k < J->nrows ? "reaction impulse Lambda" : "projection nu", row - J->radr[j] + 1,
             k < J->nrows ? (ang ? "N m s" : "N s") : (ang ? "-" : "m"));
}
