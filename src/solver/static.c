/*
 * Static analysis backend (/SOLVER Method 3; static.h, docs/theory.md
 * "Static analysis"): at each output time t_k of the run (0, dt_out, ...,
 * t_end) the equilibrium of the free bodies under the loads at t_k
 * (gravity times its time function, the couplings' forces, the contacts),
 * velocities zero, from the previous equilibrium. KINSOL (Newton with line
 * search) on the forces and moments, KLU on the stiffness: the rows of the
 * velocity and angular-velocity rates of the engine's Jacobian
 * (rc_assemble_jac), times the mass and the inertia, on the columns of the
 * positions and of the quaternions chained through the rotation vector of
 * each body about its orientation at the start of the solve.
 *
 * Joints: their constraint rows g (engine/constraints/joints.c) are rows
 * of the same system and their multipliers lambda (the reactions) unknowns
 * after the bodies' (jnt_*): the residual adds the reactions' wrenches to
 * the bodies' forces and moments, and the Newton matrix is the augmented
 * [K + d(G^T lambda)/du, G^T; G, 0], its joint blocks by complex step.
 * The joint stops' and contact couplings' modes join the active set.
 * Imposed translations and rotations are held displacements and
 * orientations (imp_targets), free after a Tstop before the end.
 *
 * Load steps: from t_{k-1} to t_k in substeps of the load time, halved when
 * a solve fails (down to RC_STATIC_MIN_CUT of the output interval, then an
 * error naming the load time), doubled after a solve in few iterations.
 * A solve that fails with a contact sliding brackets the load where
 * friction stops holding: the next loads are tried around the secant
 * estimate of the sticking contacts' friction utilisation reaching 1
 * (fric_util, slip_estimate), the halving only where that fails.
 * Contacts are unilateral: after each converged solve the modes that
 * contradict the state flip (an open contact penetrating closes; a closed
 * one separated or pulling opens; set here, as the events do in
 * engine/events) and the load step is solved again, to a fixed point.
 *
 * Friction (one contact point, the stick spring): an incremental return
 * mapping over the load substeps. The trial force F_t0 - K_t (relative
 * displacement of the contact's material points since the substep's
 * start) goes into the contact's friction state before the engine
 * evaluates; stick within Sfric + mu F_n, else slip (d->inter_slip: the
 * engine applies the limit along the state); the stiffness adds the
 * engine's columns of that state times the trial's derivatives. The law
 * is the engine's at rest (zero velocities: mu(p, v = 0), f_fv(0)); a
 * filter is left out (at rest the filtered limit is the limit: the view
 * s->mf) and its states set to the limit in each equilibrium; an
 * orthotropic contact sticks within the ellipse and slides on it. A load
 * beyond friction (a contact sliding where Newton fails, at the smallest
 * substep) is an error naming the interface and the load time; a solve
 * that stalls on a slide (a sliding body moved without any force changing,
 * slide_stalled) is ended there rather than run to KINSOL's failure.
 *
 * Hysteresis (TYPE6 Iform 1, 2; one contact point): the same over the
 * substeps, the trial F_h0 + Stiff (P - P_0) held between the unload and
 * the load curves (hyst_trial); on the Stiff line the stiffness adds the
 * engine's columns of F_h times Stiff dP/du (hyst_stiffness).
 *
 * The results file is that of a dynamic run (drive.c's rc_bk_open_output and
 * rc_bk_write_frame), one record per output time, velocities zero; the mode
 * flips (contact, stick/slip) go to its events table.
 */
#include <complex.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <kinsol/kinsol.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include "base/error.h"
#include "engine/assembly/assembly.h"
#include "engine/assembly/bounds.h"
#include "engine/constraints/joints.h"
#include "engine/events/events.h"
#include "model/model.h"
#include "model/coupling.h"
#include "model/coupling_contact.h"
#include "model/imposed.h"
#include "model/joint.h"
#include "model/power.h"
#include "model/table.h"
#include "output/output.h"
#include "solver/integrator.h"
#include "solver/solver.h"
#include "solver/static.h"

/* The smallest load substep, relative to the output interval [-]. */
#define RC_STATIC_MIN_CUT 1e-6
/* Newton: the residual's tolerance (max norm of force / force scale; raised
 * to the rounding of the forces where that is larger: rc_static_ftol),
 * iterations per solve, the largest Newton step in scaled norm (none that
 * binds: what a body may move in one step is set by its neighbours, not by
 * a scale of its own; the top of a column of 1000 spheres loaded anew
 * moves 49 radii, 5e5 penetration scales, while no contact moves more than
 * 1 mm; the line search keeps each step from raising the residual), the
 * iterations of a quick solve (the next substep doubles). */
#define RC_STATIC_FTOL 1e-11
#define RC_STATIC_MAXIT 60
#define RC_STATIC_MAXSTEP 1e30
#define RC_STATIC_QUICK 4
/* the slip load's bracket: the estimate of the load where friction stops
 * holding is tried this fraction of RC_STATIC_MIN_CUT Dt_out below (and
 * then above) it, so that the bracket closes inside the cut-back's
 * precision (docs/theory.md 7.8, "A load beyond friction") */
#define RC_STATIC_SLIP_MARGIN 0.25
/* A solve that stalls beyond friction (kin_f, docs/theory.md 7.8, "A load
 * beyond friction"): ended after this many residual evaluations in a row
 * that each moved a sliding contact's body from the previous one without
 * changing any force by more than the residual's tolerance. */
#define RC_STATIC_SLIDE_STALL 2
/* The first stiffness of a solve retried from a touching start, less this
 * fraction of each unknown's stiffness scale on its diagonal (kin_jac). */
#define RC_STATIC_TOUCH_REG 1e-6
/* Solves of the active set per load substep, and mode flips of one
 * interface in them, before the active set is said to cycle. */
#define RC_STATIC_ROUNDS_MIN 8
#define RC_STATIC_FLIPS 3

/* The entries of a joint in the stiffness: 12 body unknowns x RC_JNT_MAXROW
 * rows, twice (G and its transpose). */
#define RC_JPOS (2 * 12 * RC_JNT_MAXROW)

struct rc_static {
    const rc_model *m;
    rc_data *d;
    int nb, n;       /* free bodies, the bodies' unknowns (6 nb) */
    /* joints (docs/theory.md 7.8, "Joints"): their constraint rows' multipliers
     * (the reactions lambda, [N] or [N m]) are the unknowns n .. n + nl - 1,
     * and their rows g (the constraint values, [m] or [-]) the residuals there */
    int nl, nx;      /* joint rows (m->jnt->nrows, 0: none); all unknowns, n + nl */
    int *jq;         /* [2 njoint] the slots of each joint's bodies a, b (-1: not free) */
    int64_t *jpos;   /* [RC_JPOS njoint] each joint's entries in s->kval (-1: none): its
                        rows' columns of a's and b's unknowns [6 c + r], c < 12, then its
                        multipliers' columns in the bodies' rows [72 + 12 r + c] */
    char *jbody;     /* [nb] 1: the body of a joint */
    double *jw;      /* [12 nl] scratch: each row's unit wrench in its bodies' rows */
    double *jA, *jb; /* [nl nl], [nl] scratch: the start multipliers' normal equations */
    double *jl0;     /* [nl] scratch: the multipliers a solve starts from [N, N m] */
    int *fb;         /* [nb] body index of slot s */
    int *slot;       /* [nbody] slot of body b, -1: fixed */
    double *ys;      /* [ny] the start state of the solve */
    double *y;       /* [ny] the state at the unknowns */
    double *f;       /* [ny] rates */
    double *jv;      /* [nnz] the engine's Jacobian values */
    char *held;      /* [n] 1: held unknown */
    /* imposed translations (/IMPVEL X, Y, Z: a held unknown moved to the
     * integral of its velocity, docs/theory.md 7.8) */
    int *imp_k;      /* [n] the imposed translation (m->imp index) of an unknown, -1: none */
    double *imp_x0;  /* [n] its coordinate at t = 0 (the model's coordinates) [m] */
    double *imp_f;   /* [n] the unbalanced force along it at the last equilibrium [N] */
    /* imposed rotations (/IMPVEL XX, YY, ZZ: the body's rotations held at
     * the rotation the imposed angular velocity turns it by, docs/theory.md
     * 7.8) */
    int *imp_r;      /* [nb] the imposed rotation (m->imp rotation index) of a slot, -1: none */
    double *imp_q0;  /* [4 nb] its orientation at t = 0 */
    /* imposed components released before the end (Tstop < t_end): kept in
     * the Newton system, held by their row k_s (u - u_imp) while t <= Tstop,
     * free after it */
    char *soft;      /* [nx] 1: such an unknown */
    double *imp_u;   /* [n] the held unknowns' values in the solve under way (imp_targets; 0 but
                        for an imposed translation) */
    double *us, *fs; /* [n] unknown and residual scales (length or angle; force or moment) */
    double *kb;      /* [nb] the summed stiffness scales of each body's contacts, F_s / p_s [N/m] */
    int *sslot;      /* [ny] the slot of the free body a state belongs to, -1: none */
    double *bsize;   /* [nb] each free body's size (rc_body_size, 0 when not finite) [m] */
    /* the stiffness pattern: 6x6 blocks (row slot, column slot), sorted
     * by column slot then row slot */
    int nblk;
    int *brow, *bcol; /* [nblk] */
    int *bfirst;      /* [nb+1] first block of each column slot */
    int64_t *colptr;  /* [n+1] */
    int64_t *rowind;  /* [36 nblk] */
    int *ent_blk;     /* [nnz] block of each entry of the model's pattern, -1: none */
    signed char *ent_rc; /* [nnz] its place in the block's raw 6x7 */
    double *raw;      /* [42 nblk] */
    double *kval;     /* [36 nblk] the stiffness, in CSC order */
    /* the system KINSOL solves: the unknowns that are not held (a held
     * unknown's row is its own k_s u = 0 and its Newton step zero: it is
     * left out, with its column), in order; the stiffness's entries of
     * those rows and columns (CSC) */
    int nr;           /* unknowns solved for */
    int *full;        /* [nr] the unknown of each */
    int64_t *rcolptr; /* [nr + 1] */
    int64_t *rrowind; /* [its nnz] rows, in the reduced numbering */
    int64_t *remap;   /* [its nnz] the entry of s->kval */
    double *ufull, *rfull; /* [n] scratch: the unknowns and residuals in full */
    long nfev, njev;
    /* friction, the return mapping (docs/theory.md 7.8): per interface
     * whose stick spring the static analysis takes, from the start of the
     * load substep (rc_static_set_substep_start): the force F_t0 and the
     * contact point fixed in each body (its body frame; a fixed body's: the
     * global point) */
    char *fr_on;      /* [ninter] 1: friction by the return mapping */
    int fr_ready;     /* the substep's start is set */
    double *fr_t0;    /* [3 ninter] F_t0 [N] */
    double *fr_pa, *fr_pb; /* [3 ninter] the material points of a and b [m] */
    double *fr_xa, *fr_xb; /* [3 ninter] where they were at the substep's start [m] */
    double fr_band;   /* the force rounding of the slip test [N] */
    /* hysteresis (TYPE6 Iform 1, 2; one contact point), the return mapping
     * (docs/theory.md 7.8): per interface, from the substep's start, the
     * force F_h0 and the penetration P_0; whether the trial at the last
     * evaluation lies on the Stiff line (the stiffness then adds the
     * column of F_h times Stiff dP/du) */
    char *hy_on;      /* [ninter] 1: hysteresis by the return mapping */
    double *hy_f0, *hy_p0; /* [ninter] F_h0 [N], P_0 [m] */
    char *hy_el;      /* [ninter] 1: on the Stiff line (branch ELASTIC) */
    /* several contact points (docs/theory.md 2.7): the law's penetration
     * P_e is P itself, the deepest point's, in an equilibrium */
    char *pe_on;      /* [ninter] 1: P_e set to P */
    /* friction per contact point (node pairs, docs/theory.md 2.7): per
     * point (m->npt) its unit force at the substep's start, its contact
     * point as a material point of each body, where those were, whether it
     * carries a share at the trial */
    char *pf_on;      /* [ninter] 1: friction per point by the return mapping */
    double *pf_t0;    /* [3 npt] F_t0,j [N] */
    double *pf_pa, *pf_pb, *pf_xa, *pf_xb; /* [3 npt] as fr_pa ... for point j */
    char *pf_in;      /* [npt] 1: the point has a share at the trial */
    double *pf_out;   /* [RC_PT_OUT npt] rc_points_eval's values */
    /* the energies over a load substep (energy_step): at its start each
     * interface's penetration of the law (>= 0) and elastic force, each
     * point's share, each free body's position, the load time */
    double *en_p0, *en_f0; /* [ninter] [m], [N] */
    double *en_w0;    /* [npt] */
    double *en_x0;    /* [3 nb] [m] */
    double en_t0;
    double *ext;      /* [36 nblk] friction's part of the stiffness (rate rows, unknown columns) */
    /* a friction filter (Ifiltr; docs/theory.md 7.8): at rest the filtered
     * limit equals the limit, so the static analysis evaluates the engine
     * on a view of the model whose incremental friction has no filter
     * (m0 the model itself, mf the view, frf its friction records); the
     * filter states of an equilibrium are set to the limit (filter_commit) */
    const rc_model *m0;
    rc_model *mf;
    rc_fric *frf;
    /* exact stick (TYPE6 Istick 1, /FRICTION Iform 3; docs/theory.md 7.8,
     * "Exact stick"): each such interface's friction force lambda (on a,
     * global [N]) is three unknowns after the joints' (n + nl + 3 x), its
     * residual the Alart-Curnier rows lambda - Phi(P_n (lambda - r D)), D
     * the relative displacement of the contact's material points since the
     * substep's start; the engine (on the view s->m, where the exact
     * interfaces are incremental ones) applies the state lambda as a stick
     * force (its projection on the contact plane), or the sliding limit
     * along it */
    int nex;          /* exact interfaces */
    int *ex_i;        /* [nex] the interface of each */
    char *ex_on;      /* [ninter] 1: exact stick */
    char *ex_slip0;   /* [ninter] 1: sliding at the substep's start (or taken so: ex_force) */
    char *ex_force;   /* [ninter] 1: the substep is solved again as sliding from its start (a static
                         limit above the sliding one, passed at the smallest substep) */
    double *ex_r;     /* [nex] the augmentation r (the interface's K_t) [N/m] */
    double *ex_w;     /* [10 nex] the last trial: n (3), D (3), L the sliding limit, L_s the stick limit [N],
                         the held axes (bits, ex_held) */
    int64_t *ex_pos;  /* [36 nex] its rows' entries in the bodies' columns [18 side + 3 c + k] (-1: none) */
    double *ex_ydot;  /* [ny] scratch: a state direction */
};

/* ---- rotations ------------------------------------------------------- */
/* exp(theta) as a unit quaternion (w, x, y, z); analytic in theta (complex
 * step): the even functions of |theta| written in theta.theta. */
static void qexp(const double complex th[3], double complex e[4])
{
    const double complex s2 = th[0] * th[0] + th[1] * th[1] + th[2] * th[2];
    double complex c, sc; /* cos(s/2), sin(s/2)/s */
    if (cabs(s2) < 1e-6) {
        c = 1.0 - s2 / 8.0 + s2 * s2 / 384.0 - s2 * s2 * s2 / 46080.0;
        sc = 0.5 - s2 / 48.0 + s2 * s2 / 3840.0 - s2 * s2 * s2 / 645120.0;
    } else {
        const double complex s = csqrt(s2);
        c = ccos(0.5 * s);
        sc = csin(0.5 * s) / s;
    }
    e[0] = c;
    for (int k = 0; k < 3; k++) e[k + 1] = sc * th[k];
}

/* p (x) q, p real */
static void qmul(const double p[4], const double complex q[4], double complex r[4])
{
    r[0] = p[0] * q[0] - p[1] * q[1] - p[2] * q[2] - p[3] * q[3];
    r[1] = p[0] * q[1] + p[1] * q[0] + p[2] * q[3] - p[3] * q[2];
    r[2] = p[0] * q[2] - p[1] * q[3] + p[2] * q[0] + p[3] * q[1];
    r[3] = p[0] * q[3] + p[1] * q[2] - p[2] * q[1] + p[3] * q[0];
}

/* q = q0 (x) exp(theta) and dq/dtheta (4x3 row-major, NULL: not wanted). */
static void orient(const double q0[4], const double th[3], double q[4], double *dq)
{
    double complex t[3] = {th[0], th[1], th[2]}, e[4], r[4];
    qexp(t, e);
    qmul(q0, e, r);
    for (int k = 0; k < 4; k++) q[k] = creal(r[k]);
    if (!dq) return;
    const double h = 1e-30;
    for (int j = 0; j < 3; j++) {
        double complex tj[3] = {th[0], th[1], th[2]};
        tj[j] += h * I;
        qexp(tj, e);
        qmul(q0, e, r);
        for (int k = 0; k < 4; k++) dq[3 * k + j] = cimag(r[k]) / h;
    }
}

/* ---- the problem ------------------------------------------------------ */
static int cmp_i64(const void *a, const void *b)
{
    const int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

void rc_static_free(rc_static *s)
{
    if (!s) return;
    void *p[] = {s->fb, s->slot, s->ys, s->y, s->f, s->jv, s->held, s->imp_k, s->imp_x0, s->imp_f, s->imp_u, s->us, s->fs, s->kb, s->bsize, s->sslot, s->brow, s->bcol, s->bfirst,
                 s->colptr, s->rowind, s->ent_blk, s->ent_rc, s->raw, s->kval, s->fr_on, s->fr_t0, s->fr_pa, s->fr_pb,
                 s->fr_xa, s->fr_xb, s->ext, s->hy_on, s->hy_f0, s->hy_p0, s->hy_el, s->pe_on,
                 s->pf_on, s->pf_t0, s->pf_pa, s->pf_pb, s->pf_xa, s->pf_xb, s->pf_in, s->pf_out,
                 s->full, s->rcolptr, s->rrowind, s->remap, s->ufull, s->rfull, s->en_p0, s->en_f0, s->en_w0, s->en_x0,
                 s->jq, s->jpos, s->jbody, s->jw, s->jA, s->jb, s->jl0, s->imp_r, s->imp_q0, s->soft, s->mf, s->frf,
                 s->ex_i, s->ex_on, s->ex_slip0, s->ex_force, s->ex_r, s->ex_w, s->ex_pos, s->ex_ydot};
    for (size_t k = 0; k < sizeof p / sizeof p[0]; k++) free(p[k]);
    free(s);
}

int rc_static_size(const rc_static *s) { return s->nx; }

/* The slot and the local index (0..12) of state i, -1 when it is not a
 * free body's (from the map s->sslot, made once: this is asked for every
 * entry of the Jacobian's pattern). */
static int body_slot(const rc_static *s, int b);
static void pen_gradient(rc_static *s, int i, double t, const double *u, int qs[2], double g[2][6]);

static int state_body(const rc_static *s, int i, int *k)
{
    const int q = i >= 0 && i < s->m->ny ? s->sslot[i] : -1;
    *k = q >= 0 ? i - s->m->body_yadr[s->fb[q]] : 0;
    return q;
}

rc_static *rc_static_new(const rc_model *m, rc_data *d)
{
    rc_static *s = calloc(1, sizeof *s);
    if (!s) return NULL;
    s->m = s->m0 = m;
    s->d = d;
    /* a friction filter: the engine on the view of the model without it */
    int filt = 0;
    for (int i = 0; i < m->ninter; i++)
        filt |= m->inter_fr[i].form == RC_FF_INCREMENTAL &&
                (m->inter_fr[i].tau > 0 || m->inter_fr[i].ortho || m->inter_fr[i].exact);
    /* exact stick: its interfaces (one contact point, one friction state) */
    const size_t nin1 = (size_t)m->ninter + 1;
    s->ex_i = malloc(nin1 * sizeof(int));
    s->ex_on = calloc(nin1, 1);
    s->ex_slip0 = calloc(nin1, 1);
    s->ex_force = calloc(nin1, 1);
    s->ex_r = calloc(nin1, sizeof(double));
    s->ex_w = calloc(10 * nin1, sizeof(double));
    s->ex_pos = malloc(36 * nin1 * sizeof(int64_t));
    s->ex_ydot = calloc((size_t)m->ny + 1, sizeof(double));
    if (!s->ex_i || !s->ex_on || !s->ex_slip0 || !s->ex_force || !s->ex_r || !s->ex_w || !s->ex_pos || !s->ex_ydot) {
        rc_static_free(s);
        return NULL;
    }
    for (int i = 0; i < m->ninter; i++) {
        const rc_fric *fr = &m->inter_fr[i];
        if (!fr->exact || fr->tidx < 0 || m->inter_npt[i] > 0 || fr->kind == RC_FK_NONE) continue;
        s->ex_on[i] = 1;
        s->ex_r[s->nex] = fr->kt > 0 ? fr->kt : m->inter_fscale[i] / m->inter_pscale[i];
        if (!(s->ex_r[s->nex] > 0) || !isfinite(s->ex_r[s->nex])) s->ex_r[s->nex] = 1.0;
        s->ex_i[s->nex++] = i;
    }
    for (size_t k = 0; k < 36 * nin1; k++) s->ex_pos[k] = -1;
    if (filt) {
        s->mf = malloc(sizeof *s->mf);
        s->frf = malloc((size_t)m->ninter * sizeof(rc_fric));
        if (!s->mf || !s->frf) {
            rc_static_free(s);
            return NULL;
        }
        *s->mf = *m;
        memcpy(s->frf, m->inter_fr, (size_t)m->ninter * sizeof(rc_fric));
        for (int i = 0; i < m->ninter; i++) {
            if (s->frf[i].form != RC_FF_INCREMENTAL) continue;
            s->frf[i].tau = 0.0;
            /* exact stick: an incremental friction whose state the static
             * analysis sets (ex_trial), the stick force its projection */
            s->frf[i].exact = 0;
            /* orthotropic: the engine's stick root without the absolute
             * band, (F_1/s_1)^2 + (F_2/s_2)^2 - 1 with s_k = L_k (1 +
             * RC_SLIP_BAND), from which fric_trial takes the scaled
             * norm of the force on the ellipse */
            if (s->frf[i].ortho) s->frf[i].fband = 0.0;
        }
        s->mf->inter_fr = s->frf;
        s->m = m = s->mf;
    }
    s->nb = m->nfree;
    s->n = 6 * s->nb;
    const int nj = m->jnt ? m->jnt->n : 0;
    s->nl = m->jnt ? m->jnt->nrows : 0;
    s->nx = s->n + s->nl + 3 * s->nex;
    const size_t n1 = (size_t)s->nx + 1, ny1 = (size_t)m->ny + 1, nnz1 = (size_t)m->nnz + 1;
    s->fb = malloc(((size_t)s->nb + 1) * sizeof(int));
    s->slot = malloc(((size_t)m->nbody + 1) * sizeof(int));
    s->ys = calloc(ny1, sizeof(double));
    s->y = calloc(ny1, sizeof(double));
    s->f = calloc(ny1, sizeof(double));
    s->jv = calloc(nnz1, sizeof(double));
    s->held = calloc(n1, 1);
    s->imp_k = malloc(n1 * sizeof(int));
    s->imp_x0 = calloc(n1, sizeof(double));
    s->imp_f = calloc(n1, sizeof(double));
    s->imp_u = calloc(n1, sizeof(double));
    s->us = calloc(n1, sizeof(double));
    s->fs = calloc(n1, sizeof(double));
    s->kb = calloc((size_t)s->nb + 1, sizeof(double));
    s->bsize = calloc((size_t)s->nb + 1, sizeof(double));
    s->sslot = malloc(ny1 * sizeof(int));
    if (s->sslot)
        for (size_t k = 0; k < ny1; k++) s->sslot[k] = -1;
    s->ent_blk = malloc(nnz1 * sizeof(int));
    s->ent_rc = malloc(nnz1);
    s->jq = malloc((2 * (size_t)nj + 1) * sizeof(int));
    s->jpos = malloc((RC_JPOS * (size_t)nj + 1) * sizeof(int64_t));
    s->jbody = calloc((size_t)s->nb + 1, 1);
    s->jw = calloc(12 * (size_t)s->nl + 1, sizeof(double));
    s->jA = calloc((size_t)s->nl * (size_t)s->nl + 1, sizeof(double));
    s->jb = calloc((size_t)s->nl + 1, sizeof(double));
    s->jl0 = calloc((size_t)s->nl + 1, sizeof(double));
    s->imp_r = malloc(((size_t)s->nb + 1) * sizeof(int));
    s->imp_q0 = calloc(4 * (size_t)s->nb + 1, sizeof(double));
    s->soft = calloc(n1, 1);
    int64_t *key = malloc((nnz1 + (size_t)s->nb + 2 * (size_t)nj) * sizeof(int64_t));
    char *mf = calloc((size_t)m->nbody + 1, 1);
    if (!s->fb || !s->slot || !s->ys || !s->y || !s->f || !s->jv || !s->held || !s->imp_k || !s->imp_x0 || !s->imp_f || !s->imp_u || !s->us || !s->fs || !s->kb || !s->bsize || !s->sslot || !s->ent_blk ||
        !s->ent_rc || !s->jq || !s->jpos || !s->jbody || !s->jw || !s->jA || !s->jb || !s->jl0 || !s->imp_r || !s->imp_q0 || !s->soft || !key ||
        !mf) {
        free(key);
        free(mf);
        rc_static_free(s);
        return NULL;
    }
    int q = 0;
    for (int b = 0; b < m->nbody; b++) {
        s->slot[b] = m->body_yadr[b] >= 0 ? q : -1;
        if (m->body_yadr[b] >= 0) {
            for (int k = 0; k < RC_NB; k++) s->sslot[m->body_yadr[b] + k] = q;
            s->fb[q++] = b;
        }
    }
    s->nb = q;
    s->n = 6 * q;
    s->nx = s->n + s->nl + 3 * s->nex;
    for (int j = 0; j < nj; j++) {
        for (int e = 0; e < 2; e++) {
            const int b = e ? m->jnt->bb[j] : m->jnt->ba[j];
            s->jq[2 * j + e] = b >= 0 ? s->slot[b] : -1;
            if (s->jq[2 * j + e] >= 0) s->jbody[s->jq[2 * j + e]] = 1;
        }
        for (int k = 0; k < RC_JPOS; k++) s->jpos[RC_JPOS * (size_t)j + k] = -1;
    }
    /* scales and held unknowns: per free body the smallest penetration
     * scale and the largest force scale of its contacts, their summed
     * stiffness scales (one pass over the interfaces), its size */
    rc_moment_free_bodies_centred(m, 1, mf);
    double *bps = malloc(((size_t)s->nb + 1) * sizeof(double)), *bfi = malloc(((size_t)s->nb + 1) * sizeof(double));
    double *size_all = malloc(((size_t)m->nbody + 1) * sizeof(double));
    if (!bps || !bfi || !size_all) {
        free(bps);
        free(bfi);
        free(size_all);
        free(key);
        free(mf);
        rc_static_free(s);
        return NULL;
    }
    rc_body_sizes(m, size_all);
    for (q = 0; q < s->nb; q++) bps[q] = INFINITY, bfi[q] = 0.0;
    for (int i = 0; i < m->ninter; i++) {
        const double pi = m->inter_pscale[i], fsi = m->inter_fscale[i];
        const int bs[2] = {m->inter_ba[i], m->inter_bb[i]};
        for (int k = 0; k < 2; k++) {
            const int qk = bs[k] >= 0 ? s->slot[bs[k]] : -1;
            if (qk < 0 || (k == 1 && bs[1] == bs[0])) continue;
            if (isfinite(pi) && pi > 0) bps[qk] = fmin(bps[qk], pi);
            if (isfinite(fsi) && fsi > bfi[qk]) bfi[qk] = fsi;
            if (isfinite(pi) && pi > 0 && isfinite(fsi)) s->kb[qk] += fsi / pi;
        }
    }
    for (q = 0; q < s->nb; q++) {
        const int b = s->fb[q];
        const double mass = m->body_mass[b], *J = m->body_J + 9 * b, *g = m->body_grav + 3 * b;
        double rg = sqrt(fmax(0.5 * (J[0] + J[4] + J[8]) / mass, 0.0));
        if (!(rg > 0) || !isfinite(rg)) rg = 1.0;
        double ps = bps[q], fsc = mass * sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]), fi = bfi[q];
        if (!isfinite(ps)) ps = 1e-3 * rg;
        const double size = size_all[b];
        s->bsize[q] = isfinite(size) ? size : 0.0;
        if (!(fsc > 0)) fsc = fi > 0 ? fi : 1.0;
        const int *mask = m->body_dofmask + 6 * b;
        for (int k = 0; k < 3; k++) {
            s->us[6 * q + k] = ps;
            s->fs[6 * q + k] = fsc;
            s->held[6 * q + k] = mask[k] != 0;
            s->us[6 * q + 3 + k] = ps / rg;
            s->fs[6 * q + 3 + k] = fsc * rg;
            s->held[6 * q + 3 + k] = mask[3 + k] != 0 || mf[b];
        }
    }
    free(mf);
    /* the joints' multipliers: scaled by the force (moment) scale of their
     * bodies, their rows by the bodies' radius of gyration [m] (point,
     * distance and slide rows) or 1 (angle rows) */
    for (int j = 0; j < nj; j++)
        for (int r = 0; r < m->jnt->nrow[j]; r++) {
            const int row = m->jnt->radr[j] + r, ang = m->jnt->rkind[row] == RC_JROW_ANGLE, i = s->n + row;
            double fsc = 0.0, len = 0.0;
            for (int e = 0; e < 2; e++) {
                const int qe = s->jq[2 * j + e];
                if (qe < 0) continue;
                fsc = fmax(fsc, s->fs[6 * qe + (ang ? 3 : 0)]);
                len = fmax(len, s->us[6 * qe] / s->us[6 * qe + 3]); /* the radius of gyration */
            }
            s->us[i] = fsc > 0 ? fsc : 1.0;
            s->fs[i] = ang || !(len > 0) ? 1.0 : len;
            s->held[i] = 0;
        }
    /* exact stick: lambda and its rows [N], scaled by its bodies' force scale */
    for (int x = 0; x < s->nex; x++) {
        const int i = s->ex_i[x], qs[2] = {body_slot(s, m->inter_ba[i]), body_slot(s, m->inter_bb[i])};
        double fsc = 0.0;
        for (int e = 0; e < 2; e++)
            if (qs[e] >= 0) fsc = fmax(fsc, s->fs[6 * qs[e]]);
        for (int k = 0; k < 3; k++) {
            s->us[s->n + s->nl + 3 * x + k] = s->fs[s->n + s->nl + 3 * x + k] = fsc > 0 ? fsc : 1.0;
            s->held[s->n + s->nl + 3 * x + k] = 0;
        }
    }
    /* imposed translations: held at the integral of their velocity */
    for (int i = 0; i < s->nx; i++) s->imp_k[i] = -1;
    for (q = 0; q < s->nb; q++) s->imp_r[q] = -1;
    if (m->imp && (m->imp->nt > 0 || m->imp->nr > 0)) {
        double *y0 = calloc(ny1, sizeof(double));
        if (!y0) {
            free(bps);
            free(bfi);
            free(size_all);
            free(key);
            rc_static_free(s);
            return NULL;
        }
        rc_initial_state(m, y0);
        for (int k = 0; k < m->imp->nt; k++) {
            const int b = m->imp->tbody[k], qk = b >= 0 ? s->slot[b] : -1;
            if (qk < 0 || m->imp->tdir[k] < 0) continue; /* along a skew axis: out of scope (static_scope.c) */
            const int i = 6 * qk + m->imp->tdir[k];
            s->held[i] = 1;
            s->soft[i] = m->imp->ttstop[k] < m->tend;
            s->imp_k[i] = k;
            s->imp_x0[i] = y0[m->body_yadr[b] + m->imp->tdir[k]];
        }
        for (int j = 0; j < m->imp->nr; j++) {
            const int b = m->imp->rbody[j], qj = b >= 0 ? s->slot[b] : -1;
            if (qj < 0) continue;
            s->imp_r[qj] = j;
            memcpy(s->imp_q0 + 4 * qj, y0 + m->body_yadr[b] + 3, 4 * sizeof(double));
            for (int k = 3; k < 6; k++) {
                s->held[6 * qj + k] = 1;
                s->soft[6 * qj + k] = m->imp->rtstop[j] < m->tend;
            }
        }
        free(y0);
    }
    free(bps);
    free(bfi);
    free(size_all);
    /* the blocks: the entries of the rate rows (7..12) of a body in the
     * position and quaternion columns (0..6) of a body, and the diagonal;
     * keys (column slot, row slot) in order, per column slot its row slots
     * found once each (mark) and sorted: linear in the entries */
    int *mark = malloc(((size_t)s->nb + 1) * sizeof(int)), *blkof = malloc(((size_t)s->nb + 1) * sizeof(int));
    if (!mark || !blkof) {
        free(mark);
        free(blkof);
        free(key);
        rc_static_free(s);
        return NULL;
    }
    for (q = 0; q < s->nb; q++) mark[q] = -1;
    for (int64_t p = 0; p < m->nnz; p++) s->ent_blk[p] = -1;
    int64_t nk = 0;
    for (q = 0; q < s->nb; q++) {
        const int64_t k0 = nk;
        const int j0 = m->body_yadr[s->fb[q]];
        for (int kc = 0; kc <= 6; kc++)
            for (int64_t p = m->jac_colptr[j0 + kc]; p < m->jac_colptr[j0 + kc + 1]; p++) {
                int kr;
                const int rs = state_body(s, (int)m->jac_rowind[p], &kr);
                if (rs < 0 || kr < 7 || mark[rs] == q) continue;
                mark[rs] = q;
                key[nk++] = (int64_t)q * s->nb + rs;
            }
        /* a joint couples its two bodies (its reactions' moments turn with
         * both) */
        for (int j = 0; j < nj; j++) {
            if (s->jq[2 * j] != q && s->jq[2 * j + 1] != q) continue;
            for (int e = 0; e < 2; e++) {
                const int rs = s->jq[2 * j + e];
                if (rs < 0 || mark[rs] == q) continue;
                mark[rs] = q;
                key[nk++] = (int64_t)q * s->nb + rs;
            }
        }
        if (mark[q] != q) key[nk++] = (int64_t)q * s->nb + q;
        qsort(key + k0, (size_t)(nk - k0), sizeof *key, cmp_i64);
    }
    const int64_t u = nk;
    s->nblk = (int)u;
    /* the joints' entries: each row in the columns of its free bodies'
     * unknowns, and its multiplier's column in their rows and its own */
    int64_t nzj = 0;
    for (int j = 0; j < nj; j++)
        nzj += (int64_t)m->jnt->nrow[j] * (12 * ((s->jq[2 * j] >= 0) + (s->jq[2 * j + 1] >= 0)) + 1);
    /* exact stick: its three rows in the columns of its free bodies'
     * unknowns, its three unknowns' columns in their rows and its own */
    for (int x = 0; x < s->nex; x++) {
        const int i = s->ex_i[x], qa = body_slot(s, m->inter_ba[i]), qb = body_slot(s, m->inter_bb[i]);
        const int ns = (qa >= 0) + (qb >= 0 && qb != qa);
        nzj += 3 * 6 * ns + 3 * (6 * ns + 3);
    }
    const size_t nzt = 36 * (size_t)u + (size_t)nzj;
    s->brow = malloc(((size_t)u + 1) * sizeof(int));
    s->bcol = malloc(((size_t)u + 1) * sizeof(int));
    s->bfirst = calloc((size_t)s->nb + 2, sizeof(int));
    s->colptr = calloc(n1, sizeof(int64_t));
    s->rowind = malloc((nzt + 1) * sizeof(int64_t));
    s->raw = calloc(42 * (size_t)u + 1, sizeof(double));
    s->kval = calloc(nzt + 1, sizeof(double));
    s->ext = calloc(36 * (size_t)u + 1, sizeof(double));
    const size_t ni1 = (size_t)m->ninter + 1;
    s->fr_on = calloc(ni1, 1);
    s->fr_t0 = calloc(3 * ni1, sizeof(double));
    s->fr_pa = calloc(3 * ni1, sizeof(double));
    s->fr_pb = calloc(3 * ni1, sizeof(double));
    s->fr_xa = calloc(3 * ni1, sizeof(double));
    s->fr_xb = calloc(3 * ni1, sizeof(double));
    s->hy_on = calloc(ni1, 1);
    s->hy_f0 = calloc(ni1, sizeof(double));
    s->hy_p0 = calloc(ni1, sizeof(double));
    s->hy_el = calloc(ni1, 1);
    s->pe_on = calloc(ni1, 1);
    const size_t np1 = (size_t)m->npt + 1;
    s->pf_on = calloc(ni1, 1);
    s->pf_t0 = calloc(3 * np1, sizeof(double));
    s->pf_pa = calloc(3 * np1, sizeof(double));
    s->pf_pb = calloc(3 * np1, sizeof(double));
    s->pf_xa = calloc(3 * np1, sizeof(double));
    s->pf_xb = calloc(3 * np1, sizeof(double));
    s->pf_in = calloc(np1, 1);
    s->pf_out = calloc(RC_PT_OUT * np1, sizeof(double));
    s->en_p0 = calloc(ni1, sizeof(double));
    s->en_f0 = calloc(ni1, sizeof(double));
    s->en_w0 = calloc(np1, sizeof(double));
    s->en_x0 = calloc(3 * ((size_t)s->nb + 1), sizeof(double));
    if (!s->brow || !s->bcol || !s->bfirst || !s->colptr || !s->rowind || !s->raw || !s->kval || !s->ext ||
        !s->fr_on || !s->fr_t0 || !s->fr_pa || !s->fr_pb || !s->fr_xa || !s->fr_xb || !s->hy_on || !s->hy_f0 ||
        !s->hy_p0 || !s->hy_el || !s->pe_on || !s->pf_on || !s->pf_t0 || !s->pf_pa || !s->pf_pb || !s->pf_xa ||
        !s->pf_xb || !s->pf_in || !s->pf_out || !s->en_p0 || !s->en_f0 || !s->en_w0 || !s->en_x0) {
        free(key);
        free(mark);
        free(blkof);
        rc_static_free(s);
        return NULL;
    }
    for (int k = 0; k < s->nblk; k++) {
        s->bcol[k] = (int)(key[k] / s->nb);
        s->brow[k] = (int)(key[k] % s->nb);
        s->bfirst[s->bcol[k] + 1]++;
    }
    for (q = 0; q < s->nb; q++) s->bfirst[q + 1] += s->bfirst[q];
    for (q = 0; q < s->nb; q++) {
        for (int c = 0; c < 6; c++) {
            /* the blocks' rows first (stiffness() writes them by offset) */
            const int col = 6 * q + c;
            int64_t p = s->colptr[col];
            for (int k = s->bfirst[q]; k < s->bfirst[q + 1]; k++)
                for (int r = 0; r < 6; r++) s->rowind[p++] = 6 * s->brow[k] + r;
            /* then the rows of the joints on the body, in order */
            for (int j = 0; j < nj; j++)
                for (int e = 0; e < 2; e++) {
                    if (s->jq[2 * j + e] != q) continue;
                    for (int r = 0; r < m->jnt->nrow[j]; r++) {
                        s->jpos[RC_JPOS * (size_t)j + 6 * (6 * e + c) + r] = p;
                        s->rowind[p++] = s->n + m->jnt->radr[j] + r;
                    }
                }
            /* then the rows of the exact-stick interfaces on the body */
            for (int x = 0; x < s->nex; x++) {
                const int i = s->ex_i[x], qa = body_slot(s, m->inter_ba[i]), qb = body_slot(s, m->inter_bb[i]);
                const int e = qa == q ? 0 : qb == q ? 1 : -1;
                if (e < 0) continue;
                for (int k = 0; k < 3; k++) {
                    s->ex_pos[36 * (size_t)x + 18 * e + 3 * c + k] = p;
                    s->rowind[p++] = s->n + s->nl + 3 * x + k;
                }
            }
            s->colptr[col + 1] = p;
        }
    }
    /* the multipliers' columns: the rows of the joint's bodies (in slot
     * order), then its own (a zero diagonal: KLU pivots off it) */
    for (int j = 0; j < nj; j++) {
        const int qa = s->jq[2 * j], qb = s->jq[2 * j + 1];
        const int e0 = qb >= 0 && (qa < 0 || qb < qa) ? 1 : 0; /* the side of the lower slot first */
        for (int r = 0; r < m->jnt->nrow[j]; r++) {
            const int col = s->n + m->jnt->radr[j] + r;
            int64_t p = s->colptr[col];
            for (int ee = 0; ee < 2; ee++) {
                const int e = ee ? 1 - e0 : e0, qe = s->jq[2 * j + e];
                if (qe < 0) continue;
                for (int c = 0; c < 6; c++) {
                    s->jpos[RC_JPOS * (size_t)j + 72 + 12 * r + 6 * e + c] = p;
                    s->rowind[p++] = 6 * qe + c;
                }
            }
            s->rowind[p++] = col;
            s->colptr[col + 1] = p;
        }
    }
    /* the exact-stick unknowns' columns: the rows of the interface's free
     * bodies (the lower slot first), then its own three */
    for (int x = 0; x < s->nex; x++) {
        const int i = s->ex_i[x];
        int qs[2] = {body_slot(s, m->inter_ba[i]), body_slot(s, m->inter_bb[i])};
        if (qs[1] == qs[0]) qs[1] = -1;
        if (qs[0] < 0 || (qs[1] >= 0 && qs[1] < qs[0])) {
            const int w = qs[0];
            qs[0] = qs[1];
            qs[1] = w;
        }
        for (int k = 0; k < 3; k++) {
            const int col = s->n + s->nl + 3 * x + k;
            int64_t p = s->colptr[col];
            for (int e = 0; e < 2; e++)
                for (int c = 0; qs[e] >= 0 && c < 6; c++) s->rowind[p++] = 6 * qs[e] + c;
            for (int r = 0; r < 3; r++) s->rowind[p++] = s->n + s->nl + 3 * x + r;
            s->colptr[col + 1] = p;
        }
    }
    for (q = 0; q < s->nb; q++) {
        for (int k = s->bfirst[q]; k < s->bfirst[q + 1]; k++) blkof[s->brow[k]] = k;
        const int j0 = m->body_yadr[s->fb[q]];
        for (int kc = 0; kc <= 6; kc++)
            for (int64_t p = m->jac_colptr[j0 + kc]; p < m->jac_colptr[j0 + kc + 1]; p++) {
                int kr;
                const int rs = state_body(s, (int)m->jac_rowind[p], &kr);
                if (rs < 0 || kr < 7) continue;
                s->ent_blk[p] = blkof[rs];
                s->ent_rc[p] = (signed char)((kr - 7) * 7 + kc);
            }
    }
    free(mark);
    free(blkof);
    /* the reduced system (held unknowns out) */
    int *red = malloc(n1 * sizeof(int));
    s->full = malloc(n1 * sizeof(int));
    s->rcolptr = calloc(n1, sizeof(int64_t));
    s->rrowind = malloc(((size_t)s->colptr[s->nx] + 1) * sizeof(int64_t));
    s->remap = malloc(((size_t)s->colptr[s->nx] + 1) * sizeof(int64_t));
    s->ufull = calloc(n1, sizeof(double));
    s->rfull = calloc(n1, sizeof(double));
    if (!red || !s->full || !s->rcolptr || !s->rrowind || !s->remap || !s->ufull || !s->rfull) {
        free(red);
        free(key);
        rc_static_free(s);
        return NULL;
    }
    s->nr = 0;
    for (int i = 0; i < s->nx; i++) {
        const int out = s->held[i] && !s->soft[i];
        red[i] = out ? -1 : s->nr;
        if (!out) s->full[s->nr++] = i;
    }
    int64_t nzr = 0;
    for (int c2 = 0; c2 < s->nr; c2++) {
        const int cf = s->full[c2];
        for (int64_t p = s->colptr[cf]; p < s->colptr[cf + 1]; p++) {
            if (red[s->rowind[p]] < 0) continue;
            s->rrowind[nzr] = red[s->rowind[p]];
            s->remap[nzr++] = p;
        }
        s->rcolptr[c2 + 1] = nzr;
    }
    free(red);
    free(key);
    for (int i = 0; i < m->ninter; i++) {
        s->fr_on[i] = !s->ex_on[i] && !rc_inter_frictionless(m, i) && rc_static_friction_ok(&m->inter_fr[i]) &&
                      m->inter_npt[i] == 0 && m->inter_fr[i].tidx >= 0;
        s->pf_on[i] = !rc_inter_frictionless(m, i) && rc_static_friction_ok(&m->inter_fr[i]) && m->inter_npt[i] > 0 &&
                      rc_pair_nodes(m->inter_pair[i]) && (m->inter_pst[i] == 3 || m->inter_pst[i] == 6);
        s->hy_on[i] = m->inter_law[i] == RC_LAW_TYPE6 && m->inter_iform[i] != 0 && m->inter_hidx[i] >= 0;
        s->pe_on[i] = rc_pair_multi(m->inter_pair[i]) && m->inter_peidx[i] >= 0;
    }
    /* the slip test's rounding: that of the loads (as the active set's) */
    for (int i = 0; i < s->n; i++)
        if (i % 6 < 3) s->fr_band = fmax(s->fr_band, 1e3 * DBL_EPSILON * s->fs[i]);
    return s;
}

void rc_static_set_start(rc_static *s, const double *y0)
{
    memcpy(s->ys, y0, (size_t)s->m->ny * sizeof(double));
    for (int q = 0; q < s->nb; q++)
        for (int k = 7; k < RC_NB; k++) s->ys[s->m->body_yadr[s->fb[q]] + k] = 0.0;
}

/* The state at the unknowns u into s->y (quaternions' dq/dtheta into dq
 * [12 nb] when not NULL). */
static void state_at(rc_static *s, const double *u, double *dq)
{
    memcpy(s->y, s->ys, (size_t)s->m->ny * sizeof(double));
    for (int q = 0; q < s->nb; q++) {
        const int a = s->m->body_yadr[s->fb[q]];
        for (int k = 0; k < 3; k++) s->y[a + k] = s->ys[a + k] + u[6 * q + k];
        orient(s->ys + a + 3, u + 6 * q + 3, s->y + a + 3, dq ? dq + 12 * q : NULL);
    }
}

/* ---- friction: the return mapping (docs/theory.md 7.8) ------------- */
/* v rotated by the unit quaternion q (body -> global): v + 2 w (r x v) +
 * 2 r x (r x v), r the vector part; complex (the complex step). */
static void qrot(const double complex q[4], const double v[3], double complex o[3])
{
    const double complex w = q[0], r[3] = {q[1], q[2], q[3]};
    const double complex c[3] = {r[1] * v[2] - r[2] * v[1], r[2] * v[0] - r[0] * v[2], r[0] * v[1] - r[1] * v[0]};
    const double complex cc[3] = {r[1] * c[2] - r[2] * c[1], r[2] * c[0] - r[0] * c[2], r[0] * c[1] - r[1] * c[0]};
    for (int k = 0; k < 3; k++) o[k] = v[k] + 2.0 * w * c[k] + 2.0 * cc[k];
}

/* The slot of body b, -1: fixed (or none). */
static int body_slot(const rc_static *s, int b) { return b >= 0 && b < s->m->nbody ? s->slot[b] : -1; }

/* The material point rb (body frame) of slot q at the unknowns u: p, and
 * dp/dtheta (3x3 row-major, by complex step) when D is not NULL. */
static void mpoint(const rc_static *s, int q, const double *u, const double rb[3], double p[3], double *D)
{
    const int a = s->m->body_yadr[s->fb[q]];
    const double *th = u + 6 * q + 3;
    double complex t[3] = {th[0], th[1], th[2]}, e[4], qq[4], o[3];
    qexp(t, e);
    qmul(s->ys + a + 3, e, qq);
    qrot(qq, rb, o);
    for (int k = 0; k < 3; k++) p[k] = s->ys[a + k] + u[6 * q + k] + creal(o[k]);
    if (!D) return;
    const double h = 1e-30;
    for (int j = 0; j < 3; j++) {
        double complex tj[3] = {th[0], th[1], th[2]};
        tj[j] += h * I;
        qexp(tj, e);
        qmul(s->ys + a + 3, e, qq);
        qrot(qq, rb, o);
        for (int k = 0; k < 3; k++) D[3 * k + j] = cimag(o[k]) / h;
    }
}

/* The displacements since the substep's start of the material points of
 * the contact of interface i at u (a's, b's; their dp/dtheta into Da, Db
 * when not NULL): zero, to the bit, at the start. */
static void disp_points(const rc_static *s, int i, const double *ra, const double *rb, const double *xa0,
                        const double *xb0, const double *u, double pa[3], double pb[3], double *Da, double *Db)
{
    const int qa = body_slot(s, s->m->inter_ba[i]), qb = body_slot(s, s->m->inter_bb[i]);
    pa[0] = pa[1] = pa[2] = pb[0] = pb[1] = pb[2] = 0.0;
    if (qa >= 0) mpoint(s, qa, u, ra, pa, Da);
    if (qb >= 0) mpoint(s, qb, u, rb, pb, Db);
    for (int k = 0; k < 3; k++) {
        if (qa >= 0) pa[k] -= xa0[k];
        if (qb >= 0) pb[k] -= xb0[k];
    }
}

static void fric_points(const rc_static *s, int i, const double *u, double pa[3], double pb[3], double *Da, double *Db)
{
    disp_points(s, i, s->fr_pa + 3 * i, s->fr_pb + 3 * i, s->fr_xa + 3 * i, s->fr_xb + 3 * i, u, pa, pb, Da, Db);
}


/* The point x (global) as a material point of body b (its body frame; the
 * global point for a fixed body) into rb, and where mpoint puts it at the
 * start into x0 (to the bit as mpoint at u = 0). */
static void material_point(const rc_static *s, int b, const double *y0, const double x[3], double rb[3], double x0[3])
{
    if (body_slot(s, b) < 0) {
        memcpy(rb, x, 3 * sizeof(double));
        memcpy(x0, x, 3 * sizeof(double));
        return;
    }
    const double *xb = y0 + s->m->body_yadr[b], v[3] = {x[0] - xb[0], x[1] - xb[1], x[2] - xb[2]};
    const double complex qc[4] = {xb[3], -xb[4], -xb[5], -xb[6]}; /* global -> body */
    double complex o[3];
    qrot(qc, v, o);
    for (int k = 0; k < 3; k++) rb[k] = creal(o[k]);
    const double complex q0[4] = {xb[3], xb[4], xb[5], xb[6]};
    qrot(q0, rb, o);
    for (int k = 0; k < 3; k++) x0[k] = xb[k] + creal(o[k]);
}

/* The displacements since the substep's start of point pj's material
 * points of interface i at u (a's, b's; their dp/dtheta into Da, Db when
 * not NULL). */
static void pf_points(const rc_static *s, int i, int pj, const double *u, double pa[3], double pb[3], double *Da,
                      double *Db)
{
    disp_points(s, i, s->pf_pa + 3 * pj, s->pf_pb + 3 * pj, s->pf_xa + 3 * pj, s->pf_xb + 3 * pj, u, pa, pb, Da, Db);
}

void rc_static_set_substep_start(rc_static *s, double t, const double *y0)
{
    const rc_model *m = s->m;
    rc_data *d = s->d;
    /* the energies' start (energy_step) */
    s->en_t0 = t;
    for (int q = 0; q < s->nb; q++) memcpy(s->en_x0 + 3 * q, y0 + m->body_yadr[s->fb[q]], 3 * sizeof(double));
    for (int i = 0; i < m->ninter; i++) {
        s->en_p0[i] = s->en_f0[i] = 0.0;
        if (d->inter_mode[i] != RC_MODE_CLOSED) continue;
        rc_inter_report r;
        rc_inter_report_eval_d(m, d, i, t, y0, &r);
        s->en_p0[i] = fmax(r.pl, 0.0);
        s->en_f0[i] = r.fload;
        if (s->pf_on[i]) {
            rc_points_eval(m, d, i, NULL, t, y0, s->pf_out + RC_PT_OUT * m->inter_pbase[i]);
            for (int j = 0; j < m->inter_npt[i]; j++)
                s->en_w0[m->inter_pbase[i] + j] = s->pf_out[RC_PT_OUT * (m->inter_pbase[i] + j) + 4];
        }
    }
    for (int i = 0; i < m->ninter; i++) {
        if (s->pf_on[i]) {
            /* friction per point: each point's unit force and its contact
             * point (the node) as material points of a and b */
            const int closed = d->inter_mode[i] == RC_MODE_CLOSED, st = m->inter_eadr[i] + m->inter_ns[i];
            for (int j = 0; j < m->inter_npt[i]; j++) {
                const int pj = m->inter_pbase[i] + j;
                double x[3];
                for (int k = 0; k < 3; k++) s->pf_t0[3 * pj + k] = closed ? y0[st + m->inter_pst[i] * j + k] : 0.0;
                rc_point_position(m, i, j, y0, x); /* the node, or an edge pair's middle */
                material_point(s, m->inter_ba[i], y0, x, s->pf_pa + 3 * pj, s->pf_xa + 3 * pj);
                material_point(s, m->inter_bb[i], y0, x, s->pf_pb + 3 * pj, s->pf_xb + 3 * pj);
            }
        }
        if (s->hy_on[i]) {
            /* hysteresis: the force and the penetration at the start (an
             * open contact has no history: it closes on the load curve) */
            s->hy_f0[i] = s->hy_p0[i] = 0.0;
            if (d->inter_mode[i] == RC_MODE_CLOSED) {
                rc_inter_report r;
                rc_inter_report_eval(m, i, RC_MODE_CLOSED, d->inter_branch[i], d->inter_track[i], 0, t, y0, &r);
                s->hy_f0[i] = r.fload;
                s->hy_p0[i] = r.p;
            }
        }
        if (!s->fr_on[i] && !s->ex_on[i]) continue;
        const int closed = d->inter_mode[i] == RC_MODE_CLOSED, at = m->inter_eadr[i] + m->inter_fr[i].tidx;
        s->ex_slip0[i] = closed && (d->inter_slip[i] || s->ex_force[i]);
        for (int k = 0; k < 3; k++) s->fr_t0[3 * i + k] = closed ? y0[at + k] : 0.0;
        rc_inter_report r;
        rc_inter_report_eval(m, i, RC_MODE_CLOSED, d->inter_branch[i], d->inter_track[i], 0, t, y0, &r);
        for (int side = 0; side < 2; side++)
            material_point(s, side ? m->inter_bb[i] : m->inter_ba[i], y0, r.point, (side ? s->fr_pb : s->fr_pa) + 3 * i,
                           (side ? s->fr_xb : s->fr_xa) + 3 * i);
    }
    s->fr_ready = 1;
}

/* The hysteresis states at the unknowns u, into s->y (after state_at):
 * each closed contact's trial force F_h0 + Stiff (P - P_0), the Stiff line
 * from the substep's start, held between the unload and the load curves at
 * P (F_U <= F <= F_L): the law of docs/theory.md 3.2 over a monotone
 * change of P (F = min(F_L, F_prev + Stiff dP) loading, max(F_U, ...)
 * unloading). On the load curve the branch is LOAD, on the unload curve
 * UNLOAD (the engine's force is the curve's, its derivative exact),
 * between them ELASTIC with the state F_h = the trial; an open contact's
 * state is zero, on the load curve (no history). */
static void hyst_trial(rc_static *s, double t)
{
    const rc_model *m = s->m;
    rc_data *d = s->d;
    /* several contact points: the law at the deepest point's penetration
     * (P_e = P; 0 when open). A closed contact at P <= 0 (touching, or
     * within its touch band) takes the smallest positive P_e: its force is
     * nothing, its stiffness the law's slope from the right (at P_e = 0 the
     * law, taken at max(P_e, 0), has none, and a box touching on its face
     * would have no stiffness against tilting at the first iterate) */
    for (int i = 0; i < m->ninter; i++) {
        if (!s->pe_on[i]) continue;
        double *pe = s->y + m->inter_eadr[i] + m->inter_peidx[i];
        *pe = 0.0;
        if (d->inter_mode[i] != RC_MODE_CLOSED) continue;
        rc_inter_report r;
        rc_inter_report_eval(m, i, RC_MODE_CLOSED, d->inter_branch[i], d->inter_track[i], 0, t, s->y, &r);
        *pe = fmax(r.p, DBL_MIN);
    }
    if (!s->fr_ready) return;
    for (int i = 0; i < m->ninter; i++) {
        if (!s->hy_on[i]) continue;
        double *fh = s->y + m->inter_eadr[i] + m->inter_hidx[i];
        s->hy_el[i] = 0;
        if (d->inter_mode[i] != RC_MODE_CLOSED) {
            *fh = 0.0;
            d->inter_branch[i] = RC_BR_LOAD;
            continue;
        }
        rc_inter_report r;
        rc_inter_report_eval(m, i, RC_MODE_CLOSED, RC_BR_ELASTIC, d->inter_track[i], 0, t, s->y, &r);
        const double ftr = s->hy_f0[i] + m->inter_stiff[i] * (r.p - s->hy_p0[i]);
        if (ftr >= r.fl) {
            d->inter_branch[i] = RC_BR_LOAD;
            *fh = r.fl;
        } else if (ftr <= r.fu) {
            d->inter_branch[i] = RC_BR_UNLOAD;
            *fh = r.fu;
        } else {
            d->inter_branch[i] = RC_BR_ELASTIC;
            *fh = ftr;
            s->hy_el[i] = 1;
        }
    }
}

/* The friction states at the unknowns u, into s->y (after state_at): each
 * closed contact's trial force F_t0 - K_t (p_a - p_b), the spring loaded by
 * the relative displacement of the material points since the substep's
 * start (the engine keeps its part in the contact plane at the state), and
 * its mode into d->inter_slip: stick while the trial force is within the
 * limit Sfric + mu F_n, else slip (the engine then applies the limit along
 * it: the radial return). An open contact's state is zero. */
static void fric_trial(rc_static *s, double t, const double *u)
{
    const rc_model *m = s->m;
    rc_data *d = s->d;
    if (!s->fr_ready) return;
    for (int i = 0; i < m->ninter; i++) {
        if (!s->fr_on[i]) continue;
        double *ft = s->y + m->inter_eadr[i] + m->inter_fr[i].tidx, pa[3], pb[3];
        if (d->inter_mode[i] != RC_MODE_CLOSED) {
            ft[0] = ft[1] = ft[2] = 0.0;
            d->inter_slip[i] = 0;
            continue;
        }
        fric_points(s, i, u, pa, pb, NULL, NULL);
        for (int k = 0; k < 3; k++) ft[k] = s->fr_t0[3 * i + k] - m->inter_fr[i].kt * (pa[k] - pb[k]);
        rc_inter_report r;
        rc_inter_report_eval(m, i, RC_MODE_CLOSED, d->inter_branch[i], d->inter_track[i], 0, t, s->y, &r);
        const double nf = sqrt(r.ft[0] * r.ft[0] + r.ft[1] * r.ft[1] + r.ft[2] * r.ft[2]);
        /* orthotropic: the engine's test on the ellipse, (F_1/L_1)^2 +
         * (F_2/L_2)^2 > 1 (with its bands); in slip the engine returns the
         * trial to the ellipse along its ray in the scaled plane */
        if (m->inter_fr[i].ortho) {
            const double q = sqrt(fmax(r.slip_root + 1.0, 0.0)) * (1.0 + RC_SLIP_BAND); /* |u|, u_k = F_k / L_k */
            d->inter_slip[i] = q > 1.0 + s->fr_band / fmax(r.flim, DBL_MIN);
        } else
            d->inter_slip[i] = nf > fmax(r.flim, 0.0) + s->fr_band;
    }
}

/* Friction per point at the unknowns u, into s->y (after hyst_trial, which
 * sets P_e): each point's unit trial force F_t0,j - K_t (p_a - p_b) of its
 * material points, as the single contact's (the engine applies its share
 * w_j of the unit law at the interface's limit L = Sfric + mu F_n); a point
 * without a share (out of contact at the trial) unloaded; each point's mode
 * into d->pt_slip: stick while the trial's part in the contact plane is
 * within L (the engine's slip test, with its bands), else slip (the engine
 * applies L along it). */
static void pf_trial(rc_static *s, double t, const double *u)
{
    const rc_model *m = s->m;
    rc_data *d = s->d;
    if (!s->fr_ready) return;
    for (int i = 0; i < m->ninter; i++) {
        if (!s->pf_on[i]) continue;
        const int npt = m->inter_npt[i], pb0 = m->inter_pbase[i], ps = m->inter_pst[i];
        double *st = s->y + m->inter_eadr[i] + m->inter_ns[i];
        if (d->inter_mode[i] != RC_MODE_CLOSED) {
            for (int j = 0; j < npt; j++) {
                for (int k = 0; k < 3; k++) st[ps * j + k] = 0.0;
                d->pt_slip[pb0 + j] = 0;
                s->pf_in[pb0 + j] = 0;
            }
            continue;
        }
        for (int j = 0; j < npt; j++) {
            double pa[3], pb[3];
            pf_points(s, i, pb0 + j, u, pa, pb, NULL, NULL);
            for (int k = 0; k < 3; k++) st[ps * j + k] = s->pf_t0[3 * (pb0 + j) + k] - m->inter_fr[i].kt * (pa[k] - pb[k]);
            d->pt_slip[pb0 + j] = 0;
        }
        /* the points in stick: their slip roots (the engine's test, with its
         * bands: |F_p|^2 / (L (1 + band) + f_band)^2 - 1) and shares */
        rc_points_eval(m, d, i, NULL, t, s->y, s->pf_out + RC_PT_OUT * pb0);
        for (int j = 0; j < npt; j++) {
            const double *o = s->pf_out + RC_PT_OUT * (pb0 + j);
            s->pf_in[pb0 + j] = o[5] > 0.0;
            if (!s->pf_in[pb0 + j]) {
                for (int k = 0; k < 3; k++) st[ps * j + k] = 0.0;
                continue;
            }
            d->pt_slip[pb0 + j] = o[0] > 0.0;
        }
    }
}

/* The global axes (bits 0..2) along which the supports alone hold exact
 * contact x's material points: each side fixed, or its translation along
 * the axis and its three rotations held for the whole run (/BCS, /IMPVEL
 * without a Tstop before the end), and the axis in
 * the contact plane (|n_k| below 1e-12). Its stick row along such an axis
 * would read 0 = 0 and leave lambda_k undetermined (the support carries
 * that share, as on the IDA path): its row is lambda_k = 0 instead. */
static int ex_held(const rc_static *s, int x, const double n[3])
{
    const rc_model *m = s->m;
    const int i = s->ex_i[x], qs[2] = {body_slot(s, m->inter_ba[i]), body_slot(s, m->inter_bb[i])};
    int mask = 0;
    for (int k = 0; k < 3; k++) {
        int held = fabs(n[k]) < 1e-12;
        for (int e = 0; e < 2 && held; e++) {
            const int q = qs[e];
            if (q < 0) continue;
            for (int c = 0; c < 4; c++) {
                const int j = 6 * q + (c ? 2 + c : k);
                held = held && s->held[j] && !s->soft[j]; /* a component released later is not a support */
            }
        }
        if (held) mask |= 1 << k;
    }
    return mask;
}

/* Exact stick's row (docs/theory.md 7.8, "Exact stick") of the force
 * lambda at the normal n, the relative displacement D of the material
 * points since the substep's start, the augmentation r and the sliding
 * limit L: R = lambda - Phi(v), v = P_n (lambda - r D) the trial in the
 * contact plane, Phi(v) = v in stick, L v / |v| in slip. Complex (its
 * derivatives by complex step); the mode is the caller's. */
static void ex_row(const double complex lam[3], const double complex n[3], const double complex D[3],
                   double complex L, double r, int slip, double complex R[3])
{
    double complex sg[3], v[3], sn = 0.0;
    for (int k = 0; k < 3; k++) sg[k] = lam[k] - r * D[k];
    for (int k = 0; k < 3; k++) sn += sg[k] * n[k];
    for (int k = 0; k < 3; k++) v[k] = sg[k] - sn * n[k];
    double complex f = 1.0;
    if (slip) {
        const double complex vn = csqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        f = L / vn;
    }
    for (int k = 0; k < 3; k++) R[k] = lam[k] - f * v[k];
}

/* Exact stick at the unknowns u, into s->y (after hyst_trial, which sets
 * the normal law's state): each closed exact contact's friction state the
 * force lambda (the engine applies its part in the contact plane, or in
 * slip the sliding limit L along it), its trial v = P_n (lambda - r D) and
 * its mode into d->inter_slip: stick while |v| is within the stick limit
 * L_s = Sfric + mu_s F_n (the contact sticking at the substep's start; L
 * when it slid there), else slip. The normal, D, L and L_s into s->ex_w.
 * An open contact's state is zero. */
static void ex_trial(rc_static *s, double t, const double *u)
{
    const rc_model *m = s->m;
    rc_data *d = s->d;
    if (!s->fr_ready) return;
    for (int x = 0; x < s->nex; x++) {
        const int i = s->ex_i[x];
        const double *lam = u + s->n + s->nl + 3 * x;
        double *ft = s->y + m->inter_eadr[i] + m->inter_fr[i].tidx, *w = s->ex_w + 10 * x;
        if (d->inter_mode[i] != RC_MODE_CLOSED) {
            ft[0] = ft[1] = ft[2] = 0.0;
            d->inter_slip[i] = 0;
            continue;
        }
        memcpy(ft, lam, 3 * sizeof(double));
        double pa[3], pb[3];
        fric_points(s, i, u, pa, pb, NULL, NULL);
        rc_inter_report r, r0;
        rc_inter_report_eval(m, i, RC_MODE_CLOSED, d->inter_branch[i], d->inter_track[i], 0, t, s->y, &r);
        /* the stick limit: the model's own exact law in stick */
        rc_inter_report_eval(s->m0, i, RC_MODE_CLOSED, d->inter_branch[i], d->inter_track[i], 0, t, s->y, &r0);
        for (int k = 0; k < 3; k++) {
            w[k] = r.normal[k];
            w[3 + k] = pa[k] - pb[k];
        }
        w[6] = fmax(r.flim, 0.0);
        w[7] = fmax(r0.flim, 0.0);
        w[8] = ex_held(s, x, w);
        double sg[3], sn = 0.0, vv = 0.0;
        for (int k = 0; k < 3; k++) sg[k] = lam[k] - s->ex_r[x] * w[3 + k];
        for (int k = 0; k < 3; k++) sn += sg[k] * w[k];
        for (int k = 0; k < 3; k++) vv += (sg[k] - sn * w[k]) * (sg[k] - sn * w[k]);
        const double lim = s->ex_slip0[i] ? w[6] : w[7];
        d->inter_slip[i] = sqrt(vv) > lim + s->fr_band;
    }
}

/* Exact stick's rows of the residual into r (after ex_trial): an open
 * contact's lambda = 0. */
static void ex_residual(const rc_static *s, const double *u, double *r)
{
    for (int x = 0; x < s->nex; x++) {
        const int i = s->ex_i[x], c0 = s->n + s->nl + 3 * x;
        const double *w = s->ex_w + 10 * x;
        if (!s->fr_ready || s->d->inter_mode[i] != RC_MODE_CLOSED) {
            for (int k = 0; k < 3; k++) r[c0 + k] = u[c0 + k];
            continue;
        }
        double complex lam[3], n[3], D[3], R[3];
        for (int k = 0; k < 3; k++) {
            lam[k] = u[c0 + k];
            n[k] = w[k];
            D[k] = w[3 + k];
        }
        ex_row(lam, n, D, w[6], s->ex_r[x], s->d->inter_slip[i], R);
        const int hm = (int)w[8];
        for (int k = 0; k < 3; k++) r[c0 + k] = hm & (1 << k) ? u[c0 + k] : creal(R[k]);
    }
}

/* Exact stick's part of the stiffness at u (after rc_assemble_jac, with
 * dq the quaternions' dq/dtheta of state_at): the bodies' rows in lambda's
 * columns (the engine's columns of the friction state, times the mass and
 * the inertia: the state is lambda), and its rows in every column by
 * complex step of ex_row along the derivatives of its inputs: in lambda
 * itself; in a body's unknown, the normal's and the sliding limit's (the
 * engine's, rc_inter_report_rate along the state's direction: the
 * position, or the quaternion's dq/dtheta, and a hysteresis state on its
 * Stiff line, Stiff dP/du) and D's ([I, dp/dtheta] of the material point,
 * with its side's sign). */
static int ex_stiffness(rc_static *s, double t, const double *u, const double *dq)
{
    const rc_model *m = s->m;
    rc_data *d = s->d;
    const double h = 1e-30;
    for (int x = 0; x < s->nex; x++) {
        const int i = s->ex_i[x], c0 = s->n + s->nl + 3 * x, closed = s->fr_ready && d->inter_mode[i] == RC_MODE_CLOSED;
        const int slip = d->inter_slip[i], e0 = m->inter_eadr[i];
        const double *w = s->ex_w + 10 * x;
        const int qs[2] = {body_slot(s, m->inter_ba[i]), body_slot(s, m->inter_bb[i])};
        /* lambda's columns: the bodies' rows, then its own */
        for (int k = 0; k < 3; k++) {
            const int col = c0 + k, j = e0 + m->inter_fr[i].tidx + k;
            double A[2][6] = {{0}};
            for (int64_t p = m->jac_colptr[j]; p < m->jac_colptr[j + 1]; p++) {
                int kr;
                const int rs = state_body(s, (int)m->jac_rowind[p], &kr);
                if (rs < 0 || kr < 7) continue;
                for (int e = 0; e < 2; e++)
                    if (rs == qs[e] && !(e == 1 && qs[1] == qs[0])) A[e][kr - 7] += s->jv[p];
            }
            for (int64_t p = s->colptr[col]; p < s->colptr[col + 1]; p++) {
                const int row = (int)s->rowind[p];
                if (row >= c0) {
                    /* its own rows */
                    const int rr = row - c0;
                    if (!closed) {
                        s->kval[p] = rr == k ? 1.0 : 0.0;
                        continue;
                    }
                    double complex lam[3], n[3], D[3], R[3];
                    for (int kk = 0; kk < 3; kk++) {
                        lam[kk] = u[c0 + kk] + (kk == k ? h * I : 0.0);
                        n[kk] = w[kk];
                        D[kk] = w[3 + kk];
                    }
                    ex_row(lam, n, D, w[6], s->ex_r[x], slip, R);
                    s->kval[p] = (int)w[8] & (1 << rr) ? (rr == k ? 1.0 : 0.0) : cimag(R[rr]) / h;
                    continue;
                }
                const int q = row / 6, c = row % 6, e = q == qs[0] ? 0 : 1, b = s->fb[q];
                const double *J = m->body_J + 9 * b, *a = A[e];
                s->kval[p] = s->held[row] ? 0.0
                             : c < 3      ? m->body_mass[b] * a[c]
                                          : J[3 * (c - 3)] * a[3] + J[3 * (c - 3) + 1] * a[4] + J[3 * (c - 3) + 2] * a[5];
            }
        }
        /* its rows in the bodies' columns */
        int hq[2] = {-1, -1};
        double hg[2][6];
        const int hy = closed && s->hy_on[i] && s->hy_el[i];
        if (hy) pen_gradient(s, i, t, u, hq, hg);
        double pa[3], pb[3], Dm[2][9];
        if (closed) fric_points(s, i, u, pa, pb, Dm[0], Dm[1]);
        for (int e = 0; e < 2; e++) {
            if (qs[e] < 0 || (e == 1 && qs[1] == qs[0])) continue;
            const int a = m->body_yadr[s->fb[qs[e]]];
            for (int c = 0; c < 6; c++) {
                const int64_t *pos = s->ex_pos + 36 * (size_t)x + 18 * e + 3 * c;
                if (!closed) {
                    for (int k = 0; k < 3; k++)
                        if (pos[k] >= 0) s->kval[pos[k]] = 0.0;
                    continue;
                }
                double *yd = s->ex_ydot;
                if (c < 3) yd[a + c] = 1.0;
                else
                    for (int k = 0; k < 4; k++) yd[a + 3 + k] = dq[12 * qs[e] + 3 * k + (c - 3)];
                if (hy) yd[e0 + m->inter_hidx[i]] = m->inter_stiff[i] * hg[e][c];
                rc_inter_report dr;
                rc_inter_report_rate(m, i, RC_MODE_CLOSED, d->inter_branch[i], d->inter_track[i], slip, s->y, yd, &dr);
                for (int k = 0; k < RC_NB; k++) yd[a + k] = 0.0;
                if (hy) yd[e0 + m->inter_hidx[i]] = 0.0;
                const double sg = e ? -1.0 : 1.0;
                double complex lam[3], n[3], D[3], R[3];
                for (int k = 0; k < 3; k++) {
                    const double dD = sg * (c < 3 ? (k == c ? 1.0 : 0.0) : Dm[e][3 * k + (c - 3)]);
                    lam[k] = u[c0 + k];
                    n[k] = w[k] + h * I * dr.normal[k];
                    D[k] = w[3 + k] + h * I * dD;
                }
                ex_row(lam, n, D, w[6] + h * I * (w[6] > 0 ? dr.flim : 0.0), s->ex_r[x], slip, R);
                for (int k = 0; k < 3; k++)
                    if (pos[k] >= 0) s->kval[pos[k]] = (int)w[8] & (1 << k) ? 0.0 : cimag(R[k]) / h;
            }
        }
    }
    return 0;
}

/* The state of a converged solve at u into y: the positions and the
 * orientations, and each closed contact's friction state the force the
 * return mapping gives (the trial force, or the limit along it). */
static void commit_state(rc_static *s, double t, const double *u, double *y)
{
    const rc_model *m = s->m;
    rc_data *d = s->d;
    state_at(s, u, NULL);
    hyst_trial(s, t);
    fric_trial(s, t, u);
    pf_trial(s, t, u);
    ex_trial(s, t, u);
    for (int i = 0; i < m->ninter; i++) {
        if (!s->fr_on[i] || !s->fr_ready || d->inter_mode[i] != RC_MODE_CLOSED) continue;
        rc_inter_report r;
        rc_inter_report_eval(m, i, RC_MODE_CLOSED, d->inter_branch[i], d->inter_track[i], d->inter_slip[i], t, s->y,
                             &r);
        memcpy(s->y + m->inter_eadr[i] + m->inter_fr[i].tidx, r.ft, sizeof r.ft);
    }
    /* friction per point: a sliding point's unit force returned to the
     * limit L along it (its part in the plane; the normal part, which the
     * engine drops, scaled alike) */
    for (int i = 0; i < m->ninter; i++) {
        if (!s->pf_on[i] || !s->fr_ready || d->inter_mode[i] != RC_MODE_CLOSED) continue;
        rc_inter_report r;
        rc_inter_report_eval_d(m, d, i, t, s->y, &r);
        const double L = fmax(r.flim, 0.0);
        const int pb0 = m->inter_pbase[i], ps = m->inter_pst[i];
        double *st = s->y + m->inter_eadr[i] + m->inter_ns[i];
        for (int j = 0; j < m->inter_npt[i]; j++) {
            if (!d->pt_slip[pb0 + j]) continue;
            const double *f = s->pf_out + RC_PT_OUT * (pb0 + j) + 1; /* the unit force in the plane, in stick */
            const double fp = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
            if (fp > 0)
                for (int k = 0; k < 3; k++) st[ps * j + k] *= L / fp;
        }
    }
    memcpy(y, s->y, (size_t)m->ny * sizeof(double));
    /* a friction filter: at rest the filtered limit L_f has reached the
     * limit L; the model's own rate of L_f, (L - L_f) / tau, gives L (the
     * interface's states, or each point's) */
    if (s->mf && rc_assemble_rhs(s->m0, d, t, y, s->f) == 0)
        for (int i = 0; i < m->ninter; i++) {
            const rc_fric *fr = &s->m0->inter_fr[i];
            if (!(fr->tau > 0) || fr->form != RC_FF_INCREMENTAL) continue;
            const int e = m->inter_eadr[i];
            if (fr->fidx >= 0)
                for (int k = 0; k < 3; k++) y[e + fr->fidx + k] += fr->tau * s->f[e + fr->fidx + k];
            if (m->inter_pst[i] == 6)
                for (int j = 0; j < m->inter_npt[i]; j++)
                    for (int k = 3; k < 6; k++) y[e + m->inter_ns[i] + 6 * j + k] += fr->tau * s->f[e + m->inter_ns[i] + 6 * j + k];
        }
    /* the joints' reactions, where a record vector has them (joints.h) */
    for (int k = 0; k < s->nl; k++) y[m->ny + k] = u[s->n + k];
}

/* The block of (row slot rs, column slot cs), -1: none. */
static int find_block(const rc_static *s, int rs, int cs)
{
    for (int k = s->bfirst[cs]; k < s->bfirst[cs + 1]; k++)
        if (s->brow[k] == rs) return k;
    return -1;
}

/* Adds to s->ext the engine's column of state j (its rate rows) times
 * f g, g[side] the derivatives of the state by the 6 unknowns of each
 * side's slot qs[side] (-1: fixed): 0, or 1 when a block is missing. */
static int add_state_column(rc_static *s, int j, double f, const int qs[2], double g[2][6])
{
    const rc_model *m = s->m;
    for (int64_t p = m->jac_colptr[j]; p < m->jac_colptr[j + 1]; p++) {
        int kr;
        const int rs = state_body(s, (int)m->jac_rowind[p], &kr);
        if (rs < 0 || kr < 7 || s->jv[p] == 0.0) continue;
        for (int side = 0; side < 2; side++) {
            if (qs[side] < 0) continue;
            const int blk = find_block(s, rs, qs[side]);
            if (blk < 0) return 1;
            double *E = s->ext + 36 * (size_t)blk + 6 * (kr - 7);
            const double v = s->jv[p] * f;
            for (int c = 0; c < 6; c++) E[c] += v * g[side][c];
        }
    }
    return 0;
}

/* Adds to s->ext the engine's columns of a stick spring's three states
 * (from col0) times the trial's derivatives -K_t d(p_a - p_b)/du: -K_t [I,
 * Da] for body a, +K_t [I, Db] for body b (qs their slots, -1: fixed). 0,
 * or 1 when a block is missing. */
static int add_spring_columns(rc_static *s, int col0, const int qs[2], double kt, const double *Da, const double *Db)
{
    const double sg[2] = {-kt, kt}, *D[2] = {Da, Db};
    for (int k = 0; k < 3; k++) {
        double g[2][6];
        for (int side = 0; side < 2; side++)
            for (int c = 0; c < 3; c++) {
                g[side][c] = c == k ? sg[side] : 0.0;
                g[side][3 + c] = sg[side] * D[side][3 * k + c];
            }
        if (add_state_column(s, col0 + k, 1.0, qs, g)) return 1;
    }
    return 0;
}

/* Friction's part of the stiffness at u into s->ext: the engine's
 * derivatives of the rates in the friction states (stick: the projection
 * on the contact plane; slip: the limit along the state, L/|F| (I - e e')
 * there) times the trial state's derivatives -K_t d(p_a - p_b)/du. */
static int fric_stiffness(rc_static *s, const double *u)
{
    const rc_model *m = s->m;
    memset(s->ext, 0, 36 * (size_t)s->nblk * sizeof(double));
    if (!s->fr_ready) return 0;
    for (int i = 0; i < m->ninter; i++) {
        if (!s->fr_on[i] || s->d->inter_mode[i] != RC_MODE_CLOSED) continue;
        double pa[3], pb[3], Da[9], Db[9];
        fric_points(s, i, u, pa, pb, Da, Db);
        const int qs[2] = {body_slot(s, m->inter_ba[i]), body_slot(s, m->inter_bb[i])};
        if (add_spring_columns(s, m->inter_eadr[i] + m->inter_fr[i].tidx, qs, m->inter_fr[i].kt, Da, Db)) return 1;
    }
    return 0;
}

/* The gradient of the penetration P of interface i at u, dP/du, per side
 * (a, b; g[side] the 6 unknowns of its slot qs[side], -1: fixed):
 * n . [I, dp_a/dtheta_a] for body a and -n . [I, dp_b/dtheta_b] for body b,
 * the displacements of the two material points at the contact point along
 * the normal n (from a to b): the rate of P is that of the material points
 * there (the envelope theorem of docs/theory.md 2; with several contact
 * points the deepest one's, whose P is the interface's). */
static void pen_gradient(rc_static *s, int i, double t, const double *u, int qs[2], double g[2][6])
{
    const rc_model *m = s->m;
    rc_data *d = s->d;
    rc_inter_report r;
    rc_inter_report_eval(m, i, RC_MODE_CLOSED, d->inter_branch[i], d->inter_track[i], 0, t, s->y, &r);
    qs[0] = body_slot(s, m->inter_ba[i]);
    qs[1] = body_slot(s, m->inter_bb[i]);
    for (int side = 0; side < 2; side++) {
        if (qs[side] < 0) continue;
        double rb[3], x0[3], p[3], D[9];
        material_point(s, s->fb[qs[side]], s->y, r.point, rb, x0);
        mpoint(s, qs[side], u, rb, p, D);
        const double sg = side ? -1.0 : 1.0;
        for (int c = 0; c < 3; c++) {
            g[side][c] = sg * r.normal[c];
            g[side][3 + c] = sg * (r.normal[0] * D[c] + r.normal[1] * D[3 + c] + r.normal[2] * D[6 + c]);
        }
    }
}


/* The parts of the stiffness at u that the law's own states carry, added
 * to s->ext (after fric_stiffness): a contact on its Stiff line
 * (hysteresis ELASTIC: the force is the state F_h) adds the engine's
 * columns of F_h times dF_h/du = Stiff dP/du; a contact of several points
 * the columns of P_e times dP_e/du = dP/du (P_e = P, hyst_trial). */
static int law_stiffness(rc_static *s, double t, const double *u)
{
    const rc_model *m = s->m;
    rc_data *d = s->d;
    for (int i = 0; i < m->ninter; i++) {
        if (d->inter_mode[i] != RC_MODE_CLOSED) continue;
        const int hy = s->fr_ready && s->hy_on[i] && s->hy_el[i];
        if (!hy && !s->pe_on[i]) continue;
        int qs[2];
        double g[2][6];
        pen_gradient(s, i, t, u, qs, g);
        if (hy && add_state_column(s, m->inter_eadr[i] + m->inter_hidx[i], m->inter_stiff[i], qs, g)) return 1;
        if (s->pe_on[i] && add_state_column(s, m->inter_eadr[i] + m->inter_peidx[i], 1.0, qs, g)) return 1;
    }
    return 0;
}

/* Friction per point's part of the stiffness, added to s->ext (after
 * fric_stiffness): for each point with a share, the engine's columns of
 * its unit state times the trial's derivatives -K_t d(p_a - p_b)/du, as the
 * single contact's. */
static int pf_stiffness(rc_static *s, const double *u)
{
    const rc_model *m = s->m;
    if (!s->fr_ready) return 0;
    for (int i = 0; i < m->ninter; i++) {
        if (!s->pf_on[i] || s->d->inter_mode[i] != RC_MODE_CLOSED) continue;
        const int qs[2] = {body_slot(s, m->inter_ba[i]), body_slot(s, m->inter_bb[i])};
        for (int j = 0; j < m->inter_npt[i]; j++) {
            const int pj = m->inter_pbase[i] + j;
            if (!s->pf_in[pj]) continue;
            double pa[3], pb[3], Da[9], Db[9];
            pf_points(s, i, pj, u, pa, pb, Da, Db);
            if (add_spring_columns(s, m->inter_eadr[i] + m->inter_ns[i] + m->inter_pst[i] * j, qs, m->inter_fr[i].kt,
                                   Da, Db))
                return 1;
        }
    }
    return 0;
}

/* ---- joints: their constraint rows and reactions (docs/theory.md 7.8) --- */
/* The complex step of the joints' terms [m, rad, N, N m]. */
#define RC_STATIC_JSTEP 1e-30

/* v rotated by R(q)^T (global -> body frame), q a unit quaternion; complex. */
static void qrot_t(const double complex q[4], const double complex v[3], double complex o[3])
{
    const double complex w = q[0], r[3] = {-q[1], -q[2], -q[3]};
    const double complex c[3] = {r[1] * v[2] - r[2] * v[1], r[2] * v[0] - r[0] * v[2], r[0] * v[1] - r[1] * v[0]};
    const double complex cc[3] = {r[1] * c[2] - r[2] * c[1], r[2] * c[0] - r[0] * c[2], r[0] * c[1] - r[1] * c[0]};
    for (int k = 0; k < 3; k++) o[k] = v[k] + 2.0 * w * c[k] + 2.0 * cc[k];
}

/* The pose (x, q; 7 values, complex) of side e (0: a, 1: b) of joint j at
 * the unknowns u, its local unknown c (0..5) stepped by the complex step
 * (c < 0: none); the fixed pose of a body that is not free. */
static void jnt_pose(const rc_static *s, int j, int e, const double *u, int c, double complex y7[RC_NB])
{
    const rc_model *m = s->m;
    const int b = e ? m->jnt->bb[j] : m->jnt->ba[j], q = s->jq[2 * j + e];
    for (int k = 0; k < RC_NB; k++) y7[k] = 0.0;
    if (q < 0) {
        const double *p = rc_body_state(m, b, s->ys);
        for (int k = 0; k < 7; k++) y7[k] = p[k];
        return;
    }
    const int a = m->body_yadr[b];
    double complex th[3], e4[4];
    for (int k = 0; k < 3; k++) {
        y7[k] = s->ys[a + k] + u[6 * q + k] + (c == k ? I * RC_STATIC_JSTEP : 0.0);
        th[k] = u[6 * q + 3 + k] + (c == 3 + k ? I * RC_STATIC_JSTEP : 0.0);
    }
    qexp(th, e4);
    qmul(s->ys + a + 3, e4, y7 + 3);
}

/* Joint j's terms at the unknowns u with its multipliers lam [nrow]: the
 * reactions' force (global) [N] and moment (the body's frame, about its
 * centre of mass) [N m] on a, ta[6], and on b, tb[6] (sum lambda_r times
 * the rows' unit wrenches), and its rows g [nrow] ([m] or [-]); side e's
 * local unknown c stepped (e < 0: none). */
static void jnt_terms(const rc_static *s, int j, const double *u, const double complex *lam, int e, int c,
                      double complex ta[6], double complex tb[6], double complex *g)
{
    const rc_model *m = s->m;
    double complex ya[RC_NB], yb[RC_NB], w[RC_JNT_MAXROW][12], F[12];
    jnt_pose(s, j, 0, u, e == 0 ? c : -1, ya);
    jnt_pose(s, j, 1, u, e == 1 ? c : -1, yb);
    rc_jnt_rows_cx(m, j, ya, yb, g, w);
    for (int k = 0; k < 12; k++) F[k] = 0.0;
    for (int r = 0; r < m->jnt->nrow[j]; r++)
        for (int k = 0; k < 12; k++) F[k] += lam[r] * w[r][k];
    for (int k = 0; k < 3; k++) {
        ta[k] = F[k];
        tb[k] = F[6 + k];
    }
    qrot_t(ya + 3, F + 3, ta + 3);
    qrot_t(yb + 3, F + 9, tb + 3);
}

/* The joints' terms of the residual at u: their reactions added to the
 * forces and moments of their free bodies, their rows g into the rows of
 * the multipliers. */
static void jnt_residual(const rc_static *s, const double *u, double *r)
{
    const rc_model *m = s->m;
    for (int j = 0; m->jnt && j < m->jnt->n; j++) {
        const int nr = m->jnt->nrow[j], r0 = s->n + m->jnt->radr[j];
        double complex lam[RC_JNT_MAXROW], t[2][6], g[RC_JNT_MAXROW];
        for (int k = 0; k < nr; k++) lam[k] = u[r0 + k];
        jnt_terms(s, j, u, lam, -1, -1, t[0], t[1], g);
        for (int e = 0; e < 2; e++) {
            const int q = s->jq[2 * j + e];
            for (int k = 0; q >= 0 && k < 6; k++) r[6 * q + k] += creal(t[e][k]);
        }
        for (int k = 0; k < nr; k++) r[r0 + k] = creal(g[k]);
    }
}

/* The joints' part of the stiffness at u, added to s->kval after the
 * engine's (held rows left as they are): per joint, by complex step of
 * jnt_terms, the columns of its bodies' unknowns (the reactions' change
 * as the bodies turn, into the blocks; the rows' gradients, G) and of its
 * multipliers (the unit wrenches in the bodies' rows, G^T). 0, or 1 when
 * a block is missing. */
static int jnt_stiffness(rc_static *s, const double *u)
{
    const rc_model *m = s->m;
    const double h = RC_STATIC_JSTEP;
    for (int j = 0; m->jnt && j < m->jnt->n; j++) {
        const int nr = m->jnt->nrow[j], r0 = s->n + m->jnt->radr[j];
        const int64_t *jp = s->jpos + RC_JPOS * (size_t)j;
        double complex lam[RC_JNT_MAXROW], t[2][6], g[RC_JNT_MAXROW];
        for (int k = 0; k < nr; k++) lam[k] = u[r0 + k];
        for (int e = 0; e < 2; e++) {
            const int q = s->jq[2 * j + e];
            if (q < 0) continue;
            for (int c = 0; c < 6; c++) {
                jnt_terms(s, j, u, lam, e, c, t[0], t[1], g);
                for (int r = 0; r < nr; r++) s->kval[jp[6 * (6 * e + c) + r]] = cimag(g[r]) / h;
                for (int f = 0; f < 2; f++) {
                    const int qf = s->jq[2 * j + f];
                    if (qf < 0) continue;
                    const int blk = find_block(s, qf, q);
                    if (blk < 0) return 1;
                    double *out = s->kval + s->colptr[6 * q + c] + 6 * (blk - s->bfirst[q]);
                    for (int k = 0; k < 6; k++)
                        if (!s->held[6 * qf + k]) out[k] += cimag(t[f][k]) / h;
                }
            }
        }
        for (int r = 0; r < nr; r++) {
            lam[r] += I * h;
            jnt_terms(s, j, u, lam, -1, -1, t[0], t[1], g);
            lam[r] = creal(lam[r]);
            for (int f = 0; f < 2; f++) {
                const int qf = s->jq[2 * j + f];
                for (int k = 0; qf >= 0 && k < 6; k++)
                    s->kval[jp[72 + 12 * r + 6 * f + k]] = s->held[6 * qf + k] ? 0.0 : cimag(t[f][k]) / h;
            }
            s->kval[s->colptr[r0 + r + 1] - 1] = 0.0; /* the diagonal */
        }
    }
    return 0;
}

/* The joints' multipliers a solve starts from, into lam [nl]: those that
 * balance the loads at the start best (the body unknowns u at their start
 * values), in the least squares of the scaled forces and moments,
 *   (W^T S W) lambda = -W^T S r_0,
 * W the rows' unit wrenches in the bodies' rows, S = diag(1 / fs^2) on the
 * rows that are not held (0 on those), r_0 the residual at lambda = 0.
 * Without it a pendulum's first stiffness, at lambda = 0, has nothing
 * about its pivot (the reaction's moment, lambda times the turn of its
 * arm, is the only stiffness there): singular. 0, or 1 (lam unchanged)
 * when the residual fails or the equations are singular. */
static int jnt_start_multipliers(rc_static *s, double t, double *u, double *lam)
{
    const rc_model *m = s->m;
    const int nl = s->nl;
    if (nl == 0) return 0;
    for (int k = 0; k < nl; k++) u[s->n + k] = 0.0;
    if (rc_static_residual(s, t, u, s->rfull)) return 1;
    /* each row's unit wrench (force, moment in the body's frame) */
    for (int j = 0; j < m->jnt->n; j++)
        for (int r = 0; r < m->jnt->nrow[j]; r++) {
            double complex e[RC_JNT_MAXROW] = {0}, t2[2][6], g[RC_JNT_MAXROW];
            e[r] = 1.0;
            jnt_terms(s, j, u, e, -1, -1, t2[0], t2[1], g);
            double *w = s->jw + 12 * (size_t)(m->jnt->radr[j] + r);
            for (int f = 0; f < 2; f++) {
                const int q = s->jq[2 * j + f];
                for (int k = 0; k < 6; k++)
                    w[6 * f + k] = q >= 0 && !s->held[6 * q + k] ? creal(t2[f][k]) / s->fs[6 * q + k] : 0.0;
            }
        }
    /* the normal equations: rows of joints with a body in common */
    memset(s->jA, 0, (size_t)nl * (size_t)nl * sizeof(double));
    double dmax = 0.0;
    for (int j1 = 0; j1 < m->jnt->n; j1++)
        for (int r1 = 0; r1 < m->jnt->nrow[j1]; r1++) {
            const int i1 = m->jnt->radr[j1] + r1;
            const double *w1 = s->jw + 12 * (size_t)i1;
            double b = 0.0;
            for (int f = 0; f < 2; f++) {
                const int q = s->jq[2 * j1 + f];
                for (int k = 0; q >= 0 && k < 6; k++) b -= w1[6 * f + k] * s->rfull[6 * q + k] / s->fs[6 * q + k];
            }
            s->jb[i1] = b;
            for (int j2 = 0; j2 < m->jnt->n; j2++)
                for (int f1 = 0; f1 < 2; f1++)
                    for (int f2 = 0; f2 < 2; f2++) {
                        const int q = s->jq[2 * j1 + f1];
                        if (q < 0 || s->jq[2 * j2 + f2] != q) continue;
                        for (int r2 = 0; r2 < m->jnt->nrow[j2]; r2++) {
                            const double *w2 = s->jw + 12 * (size_t)(m->jnt->radr[j2] + r2);
                            double a = 0.0;
                            for (int k = 0; k < 6; k++) a += w1[6 * f1 + k] * w2[6 * f2 + k];
                            s->jA[(size_t)i1 * nl + m->jnt->radr[j2] + r2] += a;
                        }
                    }
            dmax = fmax(dmax, s->jA[(size_t)i1 * nl + i1]);
        }
    /* a row that the loads' directions leave undetermined (a wrench
     * along a held direction only) keeps a multiplier of 0 */
    for (int i = 0; i < nl; i++) s->jA[(size_t)i * nl + i] += 1e-12 * dmax + DBL_MIN;
    gsl_matrix_view A = gsl_matrix_view_array(s->jA, (size_t)nl, (size_t)nl);
    gsl_vector_view b = gsl_vector_view_array(s->jb, (size_t)nl);
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    const int bad = gsl_linalg_cholesky_decomp1(&A.matrix) || gsl_linalg_cholesky_svx(&A.matrix, &b.vector);
    gsl_set_error_handler(old);
    if (bad) return 1;
    for (int i = 0; i < nl; i++) {
        if (!isfinite(s->jb[i])) return 1;
    }
    for (int i = 0; i < nl; i++) lam[i] = s->jb[i];
    return 0;
}

int rc_static_residual(rc_static *s, double t, const double *u, double *r)
{
    const rc_model *m = s->m;
    state_at(s, u, NULL);
    hyst_trial(s, t);
    fric_trial(s, t, u);
    pf_trial(s, t, u);
    ex_trial(s, t, u);
    s->nfev++;
    if (rc_assemble_rhs(m, s->d, t, s->y, s->f)) return 1;
    for (int q = 0; q < s->nb; q++) {
        const int b = s->fb[q], a = m->body_yadr[b];
        const double *J = m->body_J + 9 * b, *w = s->f + a + 10;
        for (int k = 0; k < 3; k++) {
            r[6 * q + k] = m->body_mass[b] * s->f[a + 7 + k];
            r[6 * q + 3 + k] = J[3 * k] * w[0] + J[3 * k + 1] * w[1] + J[3 * k + 2] * w[2];
        }
    }
    jnt_residual(s, u, r);
    ex_residual(s, u, r);
    for (int i = 0; i < s->nx; i++) {
        if (s->held[i]) r[i] = s->fs[i] / s->us[i] * (u[i] - s->imp_u[i]);
        if (!isfinite(r[i])) return 1;
    }
    return 0;
}

/* The stiffness at u into s->kval (CSC on s->colptr, s->rowind): 0 or 1. */
static int stiffness(rc_static *s, double t, const double *u)
{
    const rc_model *m = s->m;
    double *dq = malloc((12 * (size_t)s->nb + 1) * sizeof(double));
    if (!dq) return 1;
    state_at(s, u, dq);
    hyst_trial(s, t);
    fric_trial(s, t, u);
    pf_trial(s, t, u);
    ex_trial(s, t, u);
    s->njev++;
    if (rc_assemble_jac(m, s->d, t, s->y, s->jv) || fric_stiffness(s, u) || law_stiffness(s, t, u) ||
        pf_stiffness(s, u)) {
        free(dq);
        return 1;
    }
    memset(s->raw, 0, 42 * (size_t)s->nblk * sizeof(double));
    for (int64_t p = 0; p < m->nnz; p++)
        if (s->ent_blk[p] >= 0) s->raw[42 * (size_t)s->ent_blk[p] + s->ent_rc[p]] += s->jv[p];
    for (int k = 0; k < s->nblk; k++) {
        const int rs = s->brow[k], cs = s->bcol[k], b = s->fb[rs];
        const double *R = s->raw + 42 * (size_t)k, *J = m->body_J + 9 * b, *D = dq + 12 * cs, *E = s->ext + 36 * (size_t)k;
        double A[6][6]; /* rate rows, unknown columns */
        for (int r = 0; r < 6; r++) {
            for (int c = 0; c < 3; c++) A[r][c] = R[7 * r + c] + E[6 * r + c];
            for (int c = 0; c < 3; c++)
                A[r][3 + c] = R[7 * r + 3] * D[c] + R[7 * r + 4] * D[3 + c] + R[7 * r + 5] * D[6 + c] +
                              R[7 * r + 6] * D[9 + c] + E[6 * r + 3 + c];
        }
        for (int c = 0; c < 6; c++) {
            const int col = 6 * cs + c;
            double *out = s->kval + s->colptr[col] + 6 * (k - s->bfirst[cs]);
            for (int r = 0; r < 3; r++) out[r] = m->body_mass[b] * A[r][c];
            for (int r = 0; r < 3; r++) out[3 + r] = J[3 * r] * A[3][c] + J[3 * r + 1] * A[4][c] + J[3 * r + 2] * A[5][c];
            for (int r = 0; r < 6; r++) {
                const int row = 6 * rs + r;
                if (s->held[row]) out[r] = row == col ? s->fs[row] / s->us[row] : 0.0;
            }
        }
    }
    if (ex_stiffness(s, t, u, dq)) {
        free(dq);
        return 1;
    }
    free(dq);
    if (jnt_stiffness(s, u)) return 1;
    for (int64_t p = 0; p < s->colptr[s->nx]; p++)
        if (!isfinite(s->kval[p])) return 1;
    return 0;
}

int rc_static_stiffness(rc_static *s, double t, const double *u, double *K)
{
    if (stiffness(s, t, u)) return 1;
    memset(K, 0, (size_t)s->nx * (size_t)s->nx * sizeof(double));
    for (int c = 0; c < s->nx; c++)
        for (int64_t p = s->colptr[c]; p < s->colptr[c + 1]; p++) K[(size_t)c * (size_t)s->nx + (size_t)s->rowind[p]] = s->kval[p];
    return 0;
}

/* The residual's tolerance (KINSOL's max norm of the scaled forces and
 * moments): RC_STATIC_FTOL, or the rounding of the forces where that is
 * larger: a body's contacts (their stiffness scales F_s / p_s summed) over
 * RC_TOL_ULPS roundings of its coordinates (model.h, as the dynamic
 * floors), in units of its force scale. A column 20 m high of contacts of
 * 1e5 N/m cannot balance its forces better than about 6e-8 N. */
static double rc_static_ftol(const rc_static *s)
{
    const rc_model *m = s->m;
    double ftol = RC_STATIC_FTOL;
    for (int q = 0; q < s->nb; q++) {
        const int b = s->fb[q];
        const double *x = s->ys + m->body_yadr[b];
        const double X = s->bsize[q] + fmax(fabs(x[0]), fmax(fabs(x[1]), fabs(x[2])));
        ftol = fmax(ftol, s->kb[q] * RC_TOL_ULPS * DBL_EPSILON * X / s->fs[6 * q]);
    }
    return ftol;
}

/* ---- KINSOL ----------------------------------------------------------- */
typedef struct st_run {
    rc_static *s;
    double t;           /* the load time of the solve [s] */
    char kmsg[512];     /* KINSOL's last error message */
    int touch;          /* the first stiffness of the solve regularised (kin_jac) */
    int njac;           /* stiffnesses evaluated in this solve */
    const double *lam0; /* [nl] the joints' multipliers the solve starts from [N, N m] (NULL: 0) */
    /* the watch for a solve beyond friction (kin_f): on during KINSol; the
     * last evaluation's unknowns and residual [nr] and the interface that
     * slid in it (-1: none, or no last evaluation); the stalled
     * evaluations in a row; 1 once the solve was ended so; the
     * penetrations [ninter] of the closed contacts on the sliding one's
     * bodies at the last evaluation and at this one (contact_p) */
    int watch, prev_slide, stall, stalled;
    double ftol; /* the solve's residual tolerance (rc_static_ftol) */
    double *uprev, *rprev, *pprev, *pcur;
} st_run;

/* The displacement of an imposed translation k from t = 0 to t [m]: the
 * integral of its velocity Fscale f(t / Ascale). */
static double imp_disp(const rc_model *m, int k, double t)
{
    const rc_imposed *p = m->imp;
    return p->tfscale[k] * p->tascale[k] * rc_table_integral(&m->table[p->ttab[k]], 0.0, t / p->tascale[k]);
}

/* The global rotation vector Phi [rad] an imposed rotation j turns its
 * body by from t = 0 to t (up to its Tstop): the integral of its angular
 * velocity w_g = Fscale f(t / Ascale) per global component: the rotation
 * where w_g keeps its axis, and the increment the work of the imposed
 * moment is taken over (the orientation itself: rc_imp_rotation). */
static void imp_phi(const rc_model *m, int j, double t, double phi[3])
{
    const rc_imposed *p = m->imp;
    const double te = fmin(t, p->rtstop[j]);
    for (int k = 0; k < 3; k++) {
        const int tab = p->rtab[3 * j + k];
        const double as = p->rascale[3 * j + k];
        phi[k] = tab < 0 ? 0.0 : p->rfscale[3 * j + k] * as * rc_table_integral(&m->table[tab], 0.0, te / as);
    }
}

/* The held unknowns' values of a solve at the load time t from the start
 * s->ys: an imposed translation's position at t less the start's; an
 * imposed rotation's orientation exp(Phi(t)) (x) q(0) put into the start
 * s->ys, its rotation unknowns held at 0. A component released before the
 * end (soft) is held while t <= Tstop, free after it. */
static void imp_targets(rc_static *s, double t)
{
    const rc_model *m = s->m;
    for (int i = 0; i < s->n; i++) {
        const int k = s->imp_k[i];
        if (k < 0) continue;
        const int a = m->body_yadr[s->fb[i / 6]] + i % 6;
        if (s->soft[i]) s->held[i] = t <= m->imp->ttstop[k];
        s->imp_u[i] = s->held[i] ? s->imp_x0[i] + imp_disp(m, k, t) - s->ys[a] : 0.0;
    }
    for (int q = 0; q < s->nb; q++) {
        const int j = s->imp_r[q];
        if (j < 0) continue;
        const int held = t <= m->imp->rtstop[j];
        for (int k = 3; k < 6; k++) {
            if (s->soft[6 * q + k]) s->held[6 * q + k] = held;
            s->imp_u[6 * q + k] = 0.0;
        }
        if (!held) continue;
        double qt[4], er[4];
        rc_imp_rotation(m, j, t, er); /* NaN when it failed: the solve then fails */
        double complex e[4] = {er[0], er[1], er[2], er[3]}, r[4];
        /* e (x) q0: a rotation about global axes */
        const double *q0 = s->imp_q0 + 4 * q;
        const double complex qc[4] = {q0[0], q0[1], q0[2], q0[3]};
        r[0] = e[0] * qc[0] - e[1] * qc[1] - e[2] * qc[2] - e[3] * qc[3];
        r[1] = e[0] * qc[1] + e[1] * qc[0] + e[2] * qc[3] - e[3] * qc[2];
        r[2] = e[0] * qc[2] - e[1] * qc[3] + e[2] * qc[0] + e[3] * qc[1];
        r[3] = e[0] * qc[3] + e[1] * qc[2] - e[2] * qc[1] + e[3] * qc[0];
        for (int k = 0; k < 4; k++) qt[k] = creal(r[k]);
        memcpy(s->ys + m->body_yadr[s->fb[q]] + 3, qt, sizeof qt);
    }
}

/* The first Tstop of an imposed component in (t, tn) (a load substep ends
 * there: the component is held up to it, free after), or tn. */
static double imp_break(const rc_model *m, double t, double tn)
{
    const rc_imposed *p = m->imp;
    for (int k = 0; p && k < p->nt; k++)
        if (p->ttstop[k] > t && p->ttstop[k] < tn) tn = p->ttstop[k];
    for (int j = 0; p && j < p->nr; j++)
        if (p->rtstop[j] > t && p->rtstop[j] < tn) tn = p->rtstop[j];
    return tn;
}

/* The unknowns solved for (u, reduced) into s->ufull, the held ones at
 * their values (imp_targets). */
static double *expand(rc_static *s, const double *u)
{
    memcpy(s->ufull, s->imp_u, (size_t)s->nx * sizeof(double));
    for (int i = 0; i < s->nr; i++) s->ufull[s->full[i]] = u[i];
    return s->ufull;
}

/* The first interface that slides at the last residual evaluation (its
 * friction in slip, or with friction per point some point in slip), or -1. */
static int sliding_inter(const rc_static *s)
{
    const rc_model *m = s->m;
    const rc_data *d = s->d;
    for (int i = 0; i < m->ninter; i++) {
        if (d->inter_mode[i] != RC_MODE_CLOSED) continue;
        if ((s->fr_on[i] || s->ex_on[i]) && d->inter_slip[i]) return i;
        for (int j = 0; s->pf_on[i] && j < m->inter_npt[i]; j++)
            if (d->pt_slip[m->inter_pbase[i] + j]) return i;
    }
    return -1;
}

/* 1 when interface j is closed and has a free body among those of the
 * interface i. */
static int shares_body(const rc_static *s, int i, int j)
{
    const rc_model *m = s->m;
    if (s->d->inter_mode[j] != RC_MODE_CLOSED) return 0;
    const int bj[2] = {m->inter_ba[j], m->inter_bb[j]};
    for (int k = 0; k < 2; k++)
        if (body_slot(s, bj[k]) >= 0 && (bj[k] == m->inter_ba[i] || bj[k] == m->inter_bb[i])) return 1;
    return 0;
}

/* The penetrations P of the closed contacts on the bodies of the sliding
 * interface i at the last residual evaluation (s->y) into c->pcur; 1 when
 * i itself is pressed (P > 0, F_n > 0). */
static int contact_p(st_run *c, int i)
{
    const rc_static *s = c->s;
    int pressed = 0;
    for (int j = 0; j < s->m->ninter; j++) {
        if (!shares_body(s, i, j)) continue;
        rc_inter_report r;
        rc_inter_report_eval_d(s->m, s->d, j, c->t, s->y, &r);
        c->pcur[j] = r.p;
        if (j == i) pressed = r.p > 0 && r.fn > 0;
    }
    return pressed;
}

/* A solve beyond friction (docs/theory.md 7.8, "A load beyond friction"):
 * 1 when the residual r at the unknowns u (reduced numbering) has stalled
 * on a slide: the interface i slides here, pressed (P > 0, F_n > 0), and
 * slid at the last evaluation (uprev, rprev, pprev), a body of i has moved
 * since (its translations or rotations) along every closed contact on its
 * bodies (none of their penetrations changed by more than 1e-9 of it), no
 * residual has changed by more than the tolerance ftol (max norm of r /
 * force scale), and the residual is not within 16 ftol (what a stalled
 * search counts as converged, kin_solve). A move of the sliding body along
 * its contacts that changes no force is a direction without stiffness that
 * only the contact's friction, at its limit, acts along, and the residual
 * left there is the load's excess over that limit. */
static int slide_stalled(st_run *c, int i, const double *u, const double *r, double ftol)
{
    const rc_static *s = c->s;
    if (i < 0 || !contact_p(c, i) || c->prev_slide != i) return 0;
    for (int j = 0; j < s->m->ninter; j++)
        if (shares_body(s, i, j) && !(fabs(c->pcur[j] - c->pprev[j]) <= 1e-9 * fabs(c->pcur[j]))) return 0;
    const int qa = body_slot(s, s->m->inter_ba[i]), qb = body_slot(s, s->m->inter_bb[i]);
    int moved = 0;
    double dr = 0.0, rn = 0.0;
    for (int k = 0; k < s->nr; k++) {
        const int f = s->full[k];
        const double fs = s->fs[f];
        dr = fmax(dr, fabs(r[k] - c->rprev[k]) / fs);
        rn = fmax(rn, fabs(r[k]) / fs);
        if (f < s->n && (f / 6 == qa || f / 6 == qb) && u[k] != c->uprev[k]) moved = 1;
    }
    return moved && dr <= ftol && rn > 16.0 * ftol;
}

static int kin_f(N_Vector u, N_Vector r, void *user)
{
    st_run *c = user;
    rc_static *s = c->s;
    if (rc_static_residual(s, c->t, expand(s, N_VGetArrayPointer(u)), s->rfull)) return 1;
    double *rr = N_VGetArrayPointer(r);
    for (int i = 0; i < s->nr; i++) rr[i] = s->rfull[s->full[i]];
    if (c->watch && c->uprev && c->rprev && c->pprev && c->pcur) {
        const double *uu = N_VGetArrayPointer(u);
        const int i = sliding_inter(s);
        c->stall = slide_stalled(c, i, uu, rr, c->ftol) ? c->stall + 1 : 0;
        c->prev_slide = i;
        if (i < 0) return 0; /* nothing to compare the next evaluation with */
        double *pw = c->pprev;
        c->pprev = c->pcur;
        c->pcur = pw;
        memcpy(c->uprev, uu, (size_t)s->nr * sizeof(double));
        memcpy(c->rprev, rr, (size_t)s->nr * sizeof(double));
        if (c->stall >= RC_STATIC_SLIDE_STALL) {
            /* no Newton step can leave it: end the solve (KINSOL returns
             * KIN_SYSFUNC_FAIL; the driver finds the contact sliding) */
            c->stalled = 1;
            return -1;
        }
    }
    return 0;
}

static int kin_jac(N_Vector u, N_Vector fu, SUNMatrix A, void *user, N_Vector t1, N_Vector t2)
{
    st_run *c = user;
    rc_static *s = c->s;
    if (stiffness(s, c->t, expand(s, N_VGetArrayPointer(u)))) return 1;
    sunindextype *cp = SUNSparseMatrix_IndexPointers(A), *ri = SUNSparseMatrix_IndexValues(A);
    double *v = SUNSparseMatrix_Data(A);
    for (int k = 0; k <= s->nr; k++) cp[k] = (sunindextype)s->rcolptr[k];
    const int64_t nz = s->rcolptr[s->nr];
    for (int64_t p = 0; p < nz; p++) {
        ri[p] = (sunindextype)s->rrowind[p];
        v[p] = s->kval[s->remap[p]];
    }
    /* A solve retried from a touching start (touch): contacts exactly at
     * P = 0 carry no load yet, so a body resting on a face has no stiffness
     * against tilting until it presses in (the force's moment over the
     * contact points grows with the force); the first stiffness of the
     * retry has on its diagonal each unloaded unknown's stiffness scale
     * (F_s / p_s: it stays about where it is) and -RC_STATIC_TOUCH_REG of
     * a loaded one's added, so that Newton's first step presses the loaded
     * directions in, and the later iterations have the contacts' own
     * stiffness. */
    const int first = c->njac++ == 0;
    /* A loaded unknown without stiffness (a contact just touching whose law
     * starts with zero slope, Hertz at P = 0): the secant stiffness that
     * moves it by its scale (the contact's penetration scale), so that
     * Newton enters the contact; an unloaded one stays singular (KLU
     * names it). */
    const double *r = N_VGetArrayPointer(fu);
    for (int i = 0; i < s->nr; i++) {
        const int f = s->full[i];
        if (f >= s->n) continue; /* a joint's multiplier */
        const double ks = s->fs[f] / s->us[f];
        double cmax = 0.0;
        int64_t pd = -1;
        for (int64_t p = s->rcolptr[i]; p < s->rcolptr[i + 1]; p++) {
            cmax = fmax(cmax, fabs(v[p]));
            if (s->rrowind[p] == i) pd = p;
        }
        if (pd < 0 || cmax > RC_STATIC_FTOL * ks || !(fabs(r[i]) > RC_STATIC_FTOL * s->fs[f])) continue;
        v[pd] = -fabs(r[i]) / s->us[f];
    }
    if (c->touch && first)
        for (int i = 0; i < s->nr; i++) {
            const int f = s->full[i], loaded = fabs(r[i]) > RC_STATIC_FTOL * s->fs[f];
            if (f >= s->n) continue;
            for (int64_t p = s->rcolptr[i]; p < s->rcolptr[i + 1]; p++)
                if (s->rrowind[p] == i) v[p] -= (loaded ? RC_STATIC_TOUCH_REG : 1.0) * s->fs[f] / s->us[f];
        }
    return 0;
}

static void kin_err(int code, const char *module, const char *function, char *msg, void *user)
{
    st_run *c = user;
    if (code < 0) snprintf(c->kmsg, sizeof c->kmsg, "%s", msg);
}

/* The static run's solver: KINSOL, its matrix and KLU. */
typedef struct st_kin {
    SUNContext ctx;
    void *kin;
    N_Vector u, us, fs;
    SUNMatrix A;
    SUNLinearSolver LS;
} st_kin;

static void kin_close(st_kin *k)
{
    if (k->kin) KINFree(&k->kin);
    if (k->LS) SUNLinSolFree(k->LS);
    if (k->A) SUNMatDestroy(k->A);
    if (k->u) N_VDestroy(k->u);
    if (k->us) N_VDestroy(k->us);
    if (k->fs) N_VDestroy(k->fs);
    if (k->ctx) SUNContext_Free(&k->ctx);
}

static rc_status kin_open(st_kin *k, st_run *c, rc_error *err)
{
    rc_static *s = c->s;
    const sunindextype n = s->nr > 0 ? s->nr : 1;
    if (SUNContext_Create(NULL, &k->ctx)) RC_RAISE(err, RC_ESOLVER, "SUNContext_Create failed");
    k->u = N_VNew_Serial(n, k->ctx);
    k->us = N_VNew_Serial(n, k->ctx);
    k->fs = N_VNew_Serial(n, k->ctx);
    k->A = SUNSparseMatrix(n, n, s->rcolptr[s->nr] > 0 ? (sunindextype)s->rcolptr[s->nr] : 1, CSC_MAT, k->ctx);
    if (!k->u || !k->us || !k->fs || !k->A) RC_RAISE(err, RC_ENOMEM, "out of memory for KINSOL");
    for (int i = 0; i < s->nr; i++) {
        NV_Ith_S(k->us, i) = 1.0 / s->us[s->full[i]];
        NV_Ith_S(k->fs, i) = 1.0 / s->fs[s->full[i]];
    }
    N_VConst(0.0, k->u);
    if (!(k->LS = SUNLinSol_KLU(k->u, k->A, k->ctx))) RC_RAISE(err, RC_ESOLVER, "SUNLinSol_KLU failed");
    /* AMD on the stiffness (block-symmetric in pattern: body i in body j's
     * rows where j is in i's) rather than COLAMD */
    if (SUNLinSol_KLUSetOrdering(k->LS, 0)) RC_RAISE(err, RC_ESOLVER, "SUNLinSol_KLUSetOrdering failed");
    if (!(k->kin = KINCreate(k->ctx))) RC_RAISE(err, RC_ENOMEM, "KINCreate failed");
    if (KINInit(k->kin, kin_f, k->u) || KINSetUserData(k->kin, c) || KINSetErrHandlerFn(k->kin, kin_err, c) ||
        KINSetLinearSolver(k->kin, k->LS, k->A) || KINSetJacFn(k->kin, kin_jac) || KINSetMaxSetupCalls(k->kin, 1) ||
        KINSetNumMaxIters(k->kin, RC_STATIC_MAXIT) || KINSetFuncNormTol(k->kin, RC_STATIC_FTOL) ||
        KINSetScaledStepTol(k->kin, 1e-15) || KINSetMaxNewtonStep(k->kin, RC_STATIC_MAXSTEP))
        RC_RAISE(err, RC_ESOLVER, "KINSOL set-up failed");
    return RC_OK;
}

/* A solve's outcome: converged, failed (cut the step), or an error. */
typedef struct st_out {
    int ok;
    long iters;
    int flag;
    int singular_col; /* KLU's singular column, -1: none */
    double fnorm;
} st_out;

/* The unknown (full numbering) of the column KLU found singular in its
 * last factorisation, or -1. */
static int klu_singular(st_kin *k, const rc_static *s)
{
    sun_klu_common *kc = SUNLinSol_KLUGetCommon(k->LS);
    if (kc && kc->status == KLU_SINGULAR && kc->singular_col >= 0 && kc->singular_col < s->nr)
        return s->full[kc->singular_col];
    return -1;
}

/* One KINSOL solve at the load time t from the state s->ys. */
static st_out kin_solve(st_kin *k, st_run *c, double t)
{
    st_out o = {0, 0, 0, -1, NAN};
    c->t = t;
    c->kmsg[0] = '\0';
    c->njac = 0;
    imp_targets(c->s, t);
    N_VConst(0.0, k->u);
    for (int i = 0; i < c->s->nr; i++) /* a soft-held component at its value */
        if (c->s->held[c->s->full[i]]) NV_Ith_S(k->u, i) = c->s->imp_u[c->s->full[i]];
    /* exact stick: lambda from the start's friction state (the last
     * equilibrium's force; 0 for an open contact) */
    for (int i = 0; i < c->s->nr; i++) {
        const rc_static *s = c->s;
        const int f = s->full[i], x = (f - s->n - s->nl) / 3;
        if (f < s->n + s->nl) continue;
        const int ii = s->ex_i[x];
        NV_Ith_S(k->u, i) = s->d->inter_mode[ii] == RC_MODE_CLOSED
                                ? s->ys[s->m->inter_eadr[ii] + s->m->inter_fr[ii].tidx + (f - s->n - s->nl) % 3]
                                : 0.0;
    }
    /* the joints' multipliers: those that balance the loads at the start
     * best, else the last equilibrium's */
    if (c->s->nl > 0) {
        rc_static *s = c->s;
        double *uf = expand(s, N_VGetArrayPointer(k->u)), *l0 = s->jl0;
        for (int i = 0; i < s->nl; i++) l0[i] = c->lam0 ? c->lam0[i] : 0.0;
        jnt_start_multipliers(s, t, uf, l0);
        for (int i = 0; i < s->nr; i++)
            if (s->full[i] >= s->n && s->full[i] < s->n + s->nl) NV_Ith_S(k->u, i) = l0[s->full[i] - s->n];
    }
    if (c->s->nr == 0) {
        o.ok = 1;
        return o;
    }
    const double ftol = rc_static_ftol(c->s);
    KINSetFuncNormTol(k->kin, ftol);
    c->watch = 1;
    c->ftol = ftol;
    c->prev_slide = -1;
    c->stall = c->stalled = 0;
    o.flag = KINSol(k->kin, k->u, KIN_LINESEARCH, k->us, k->fs);
    c->watch = 0;
    KINGetNumNonlinSolvIters(k->kin, &o.iters);
    KINGetFuncNorm(k->kin, &o.fnorm);
    /* converged; or a search that stalled (its step below KINSOL's step
     * tolerance, or a line search that found no decrease) within a few
     * roundings of the forces (rc_static_ftol: the contacts' stiffness
     * times the coordinates' roundings), which it cannot improve: KINSOL
     * also tests the start 100 times tighter than its iterates, so the last
     * equilibrium under an unchanged load stops its line search; or a step
     * below the step tolerance at 1e-8 of the force scales, where a stiff
     * stick spring's rounding (K_t times the positions' ulps) sets the
     * floor */
    const int stalled = o.flag == KIN_STEP_LT_STPTOL || o.flag == KIN_LINESEARCH_NONCONV;
    o.ok = o.flag == KIN_SUCCESS || o.flag == KIN_INITIAL_GUESS_OK || (stalled && o.fnorm <= 16.0 * ftol) ||
           (o.flag == KIN_STEP_LT_STPTOL && o.fnorm <= 1e-8);
    if (!o.ok && !c->stalled) o.singular_col = klu_singular(k, c->s);
    return o;
}

/* After a solve retried from a touching start (kin_jac's regularised first
 * stiffness) converged: the stiffness at the equilibrium must hold every
 * unknown (a direction that no contact, spring or /BCS holds stays
 * singular, or unstable, there, and the regularised step may have
 * converged at once because nothing loads it). The first unknown without
 * support (full numbering), or -1. */
static int kin_support(st_kin *k, st_run *c)
{
    rc_static *s = c->s;
    if (s->nr == 0) return -1;
    N_Vector fu = N_VClone(k->u);
    if (!fu) return -1;
    int col = -1;
    c->touch = 0;
    c->njac = 1;
    if (kin_f(k->u, fu, c) == 0 && kin_jac(k->u, fu, k->A, c, NULL, NULL) == 0) {
        /* a stable equilibrium's stiffness (dR/du, the forces' change) is
         * negative definite, so each diagonal entry is negative: an unknown
         * whose own stiffness is not (a frictionless column of spheres,
         * whose straight line the compression makes unstable sideways) has
         * no support */
        const sunindextype *cp = SUNSparseMatrix_IndexPointers(k->A), *ri = SUNSparseMatrix_IndexValues(k->A);
        const double *v = SUNSparseMatrix_Data(k->A);
        for (int i = 0; i < s->nr && col < 0; i++) {
            const int f = s->full[i];
            /* a jointed body's stiffness is that of its motions the joints
             * allow, not its own diagonal (a pendulum's translations have
             * none): the factorisation below judges it */
            if (f >= s->n || s->jbody[f / 6] || s->held[f]) continue;
            double dg = 0.0;
            for (sunindextype p = cp[i]; p < cp[i + 1]; p++)
                if (ri[p] == i) dg = v[p];
            if (!(dg < -RC_STATIC_FTOL * s->fs[f] / s->us[f])) col = f;
        }
        if (col < 0 && SUNLinSolSetup(k->LS, k->A) != 0) col = klu_singular(k, s);
    }
    N_VDestroy(fu);
    return col;
}

/* The energy states over a converged load substep, from its start
 * (rc_static_set_substep_start) to y at the unknowns u (commit_state's),
 * by the trapezoidal rule on the path between: each interface's work of its
 * elastic law, W_load += (F_0 + F_1)/2 (P_1 - P_0) (exact where the law is
 * linear over the substep: the load curve's segments, the Stiff line); the
 * friction's work, W_fric -= (F_t0 + F_t1)/2 . (Delta_a - Delta_b) at the
 * contact point (per point, each at its share); and, with a time-varying
 * gravity, its potential, E += -m (g(t_0) + g(t_1))/2 . (x_1 - x_0). A
 * static path then keeps the ledger's sum (energy_total) at its start, and
 * energy_hysteresis and energy_friction (work less what is stored) are the
 * dissipations of the path (docs/theory.md 7.8). */
static void energy_step(rc_static *s, double t, const double *u, double *y)
{
    const rc_model *m = s->m;
    rc_data *d = s->d;
    for (int i = 0; i < m->ninter; i++) {
        rc_inter_report r;
        rc_inter_report_eval_d(m, d, i, t, y, &r);
        const int closed = d->inter_mode[i] == RC_MODE_CLOSED;
        const double p1 = closed ? fmax(r.pl, 0.0) : 0.0, f1 = closed ? r.fload : 0.0;
        const double dw = 0.5 * (s->en_f0[i] + f1) * (p1 - s->en_p0[i]);
        y[m->inter_eadr[i]] += dw;
        /* D_h: the work less the change of the law's energy (at P_e = P;
         * Iform 1, 2: at its elastic force too) */
        if (m->inter_dhidx[i] >= 0)
            y[m->inter_eadr[i] + m->inter_dhidx[i]] +=
                dw - (rc_inter_path_energy(m, i, p1, f1) - rc_inter_path_energy(m, i, s->en_p0[i], s->en_f0[i]));
        const rc_fric *fr = &m->inter_fr[i];
        if ((s->fr_on[i] || s->ex_on[i]) && closed) {
            double pa[3], pb[3];
            fric_points(s, i, u, pa, pb, NULL, NULL);
            for (int k = 0; k < 3; k++) y[m->inter_eadr[i] + fr->widx] -= 0.5 * (s->fr_t0[3 * i + k] + r.ft[k]) * (pa[k] - pb[k]);
        }
        if (s->pf_on[i] && closed) {
            const int pb0 = m->inter_pbase[i], ps = m->inter_pst[i];
            const double *st = y + m->inter_eadr[i] + m->inter_ns[i];
            for (int j = 0; j < m->inter_npt[i]; j++) {
                double pa[3], pb[3];
                pf_points(s, i, pb0 + j, u, pa, pb, NULL, NULL);
                /* the slide in the contact plane (the points' states keep a
                 * part along the normal, which the engine drops; the
                 * interface's normal for every point: a face contact) */
                double dl[3], dn = 0.0;
                for (int k = 0; k < 3; k++) dl[k] = pa[k] - pb[k];
                for (int k = 0; k < 3; k++) dn += dl[k] * r.normal[k];
                for (int k = 0; k < 3; k++) dl[k] -= dn * r.normal[k];
                const double w1 = s->pf_in[pb0 + j] ? s->pf_out[RC_PT_OUT * (pb0 + j) + 4] : 0.0, w0 = s->en_w0[pb0 + j];
                for (int k = 0; k < 3; k++)
                    y[m->inter_eadr[i] + fr->widx] -= 0.5 * (w0 * s->pf_t0[3 * (pb0 + j) + k] + w1 * st[ps * j + k]) * dl[k];
            }
        }
    }
    /* imposed translations: W_imp = -(work of the reactions) = the work of
     * the unbalanced force F along the component, sum 0.5 (F_0 + F_1) dx */
    if (m->imp && (m->imp->nt > 0 || m->imp->nr > 0) && rc_assemble_rhs(m, d, t, y, s->f) == 0) {
        for (int i = 0; i < s->n; i++) {
            if (s->imp_k[i] < 0 || !s->held[i]) continue;
            const int q = i / 6, b = s->fb[q], a = m->body_yadr[b], c = i % 6;
            const double f1 = m->body_mass[b] * d->sc->imp_free[a + 7 + c]; /* before the imposed rate (rc_imp_rhs) */
            y[m->imp->wadr] += 0.5 * (s->imp_f[i] + f1) * (y[a + c] - s->en_x0[3 * q + c]);
            s->imp_f[i] = f1;
        }
        /* imposed rotations: the unbalanced moment M (global: R J
         * omegadot_free) over the rotation's increment, sum 0.5 (M_0 +
         * M_1) . dPhi */
        for (int q = 0; q < s->nb; q++) {
            const int j = s->imp_r[q];
            if (j < 0 || !s->held[6 * q + 3]) continue;
            const int b = s->fb[q], a = m->body_yadr[b];
            const double *J = m->body_J + 9 * b, *wf = d->sc->imp_free + a + 10, *qq = y + a + 3;
            double mb[3], p0[3], p1[3];
            for (int k = 0; k < 3; k++) mb[k] = J[3 * k] * wf[0] + J[3 * k + 1] * wf[1] + J[3 * k + 2] * wf[2];
            const double complex qc[4] = {qq[0], qq[1], qq[2], qq[3]};
            double complex mg[3];
            qrot(qc, mb, mg);
            imp_phi(m, j, s->en_t0, p0);
            imp_phi(m, j, t, p1);
            for (int k = 0; k < 3; k++) {
                y[m->imp->wadr] += 0.5 * (s->imp_f[6 * q + 3 + k] + creal(mg[k])) * (p1[k] - p0[k]);
                s->imp_f[6 * q + 3 + k] = creal(mg[k]);
            }
        }
    }
    if (m->gwork_adr >= 0)
        for (int q = 0; q < s->nb; q++) {
            const int b = s->fb[q];
            double g0[3], g1[3];
            rc_gravity(m, b, s->en_t0, g0);
            rc_gravity(m, b, t, g1);
            const double *x1 = y + m->body_yadr[b], *x0 = s->en_x0 + 3 * q;
            for (int k = 0; k < 3; k++) y[m->gwork_adr] -= m->body_mass[b] * 0.5 * (g0[k] + g1[k]) * (x1[k] - x0[k]);
        }
}

/* 1: some contact point of interface i slides (friction per point). */
static int point_slip(const rc_model *m, const rc_data *d, int i)
{
    for (int j = 0; j < m->inter_npt[i]; j++)
        if (d->pt_slip[m->inter_pbase[i] + j]) return 1;
    return 0;
}

/* A limit point at the state y: a closed contact on its load branch whose
 * law's force does not grow past its penetration P (the load curve's slope
 * there not positive: past a peak of a softening curve). The interface
 * (-1: none), its P and force. A static analysis follows the loads up a
 * rising curve only: past such a point the equilibrium under a growing
 * load is elsewhere (a snap-through), which only dynamics can reach. */
static int limit_point(const rc_model *m, const rc_data *d, double t, const double *y, double *pl, double *fl)
{
    for (int i = 0; i < m->ninter; i++) {
        if (d->inter_mode[i] != RC_MODE_CLOSED || d->inter_branch[i] != RC_BR_LOAD) continue;
        rc_inter_report r;
        rc_inter_report_eval_d(m, d, i, t, y, &r);
        const double P = r.pl > 0 ? r.pl : r.p;
        if (!(P > 0) || !isfinite(P)) continue;
        const double h = 1e-6 * P;
        const double f0 = rc_law_force(m, i, P), f1 = rc_law_force(m, i, P + h);
        if (!(f1 > f0)) {
            *pl = P;
            *fl = f0;
            return i;
        }
    }
    return -1;
}

/* The most unknowns of jointed bodies whose equilibrium's stability is
 * checked (a dense eigenvalue problem of that size). */
#define RC_STATIC_STAB_MAX 300

/* The stability of an equilibrium y with joints at the load time t
 * (docs/theory.md 7.8, "Joints"): the stiffness K = dR/du of the jointed
 * bodies' unknowns that are not held (the others fixed), on the motions
 * the joints allow (the null space Z of their rows' gradients G), must be
 * negative definite: the largest eigenvalue of Z^T K_s Z (K_s the
 * symmetric part; unknowns scaled by their scales, a congruence that keeps
 * the signs). 1 when it is positive beyond 1e-8 of the largest in
 * magnitude (*ratio that fraction), else 0; 0 also when not checked (no
 * joints, more than RC_STATIC_STAB_MAX such unknowns, a contact sliding:
 * its tangent is not symmetric, or out of memory). */
static int jnt_unstable(rc_static *s, double t, const double *y, double *ratio)
{
    const rc_model *m = s->m;
    *ratio = 0.0;
    if (s->nl == 0) return 0;
    for (int i = 0; i < m->ninter; i++)
        if (s->d->inter_mode[i] == RC_MODE_CLOSED &&
            ((s->fr_on[i] && s->d->inter_slip[i]) || (s->pf_on[i] && point_slip(m, s->d, i)) || s->ex_on[i]))
            return 0;
    int nb = 0;
    for (int i = 0; i < s->n; i++) nb += !s->held[i] && s->jbody[i / 6];
    const int nl = s->nl, mz = nb - nl;
    if (nb > RC_STATIC_STAB_MAX || mz <= 0) return 0;
    int *loc = malloc(((size_t)s->nx + 1) * sizeof(int));
    double *u = calloc((size_t)s->nx + 1, sizeof(double));
    gsl_matrix *K = gsl_matrix_calloc((size_t)nb, (size_t)nb), *Gt = gsl_matrix_calloc((size_t)nb, (size_t)nl);
    gsl_matrix *Q = gsl_matrix_alloc((size_t)nb, (size_t)nb), *R = gsl_matrix_alloc((size_t)nb, (size_t)nl);
    gsl_matrix *KZ = gsl_matrix_alloc((size_t)nb, (size_t)mz), *H = gsl_matrix_alloc((size_t)mz, (size_t)mz);
    gsl_vector *tau = gsl_vector_alloc((size_t)nl), *ev = gsl_vector_alloc((size_t)mz);
    gsl_eigen_symm_workspace *ws = gsl_eigen_symm_alloc((size_t)mz);
    int unstable = 0;
    if (!loc || !u || !K || !Gt || !Q || !R || !KZ || !H || !tau || !ev || !ws) goto out;
    /* the stiffness at the equilibrium (the start of a solve there) */
    rc_static_set_start(s, y);
    for (int k = 0; k < nl; k++) u[s->n + k] = y[m->ny + k];
    if (stiffness(s, t, u)) goto out;
    int q = 0;
    for (int i = 0; i < s->nx; i++) loc[i] = i < s->n && !s->held[i] && s->jbody[i / 6] ? q++ : -1;
    for (int c = 0; c < s->n; c++) {
        if (loc[c] < 0) continue;
        for (int64_t p = s->colptr[c]; p < s->colptr[c + 1]; p++) {
            const int r = (int)s->rowind[p];
            const double v = s->kval[p] * s->us[c];
            if (r < s->n && loc[r] >= 0) gsl_matrix_set(K, (size_t)loc[r], (size_t)loc[c], v * s->us[r]);
            else if (r >= s->n) gsl_matrix_set(Gt, (size_t)loc[c], (size_t)(r - s->n), v);
        }
    }
    /* K_s, the null space of G (the last columns of Q in G^T = Q R) */
    for (int i = 0; i < nb; i++)
        for (int j = 0; j < i; j++) {
            const double a = 0.5 * (gsl_matrix_get(K, (size_t)i, (size_t)j) + gsl_matrix_get(K, (size_t)j, (size_t)i));
            gsl_matrix_set(K, (size_t)i, (size_t)j, a);
            gsl_matrix_set(K, (size_t)j, (size_t)i, a);
        }
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    int bad = gsl_linalg_QR_decomp(Gt, tau) || gsl_linalg_QR_unpack(Gt, tau, Q, R);
    if (!bad) {
        gsl_matrix_const_view Z = gsl_matrix_const_submatrix(Q, 0, (size_t)nl, (size_t)nb, (size_t)mz);
        bad = gsl_blas_dgemm(CblasNoTrans, CblasNoTrans, 1.0, K, &Z.matrix, 0.0, KZ) ||
              gsl_blas_dgemm(CblasTrans, CblasNoTrans, 1.0, &Z.matrix, KZ, 0.0, H) || gsl_eigen_symm(H, ev, ws);
    }
    gsl_set_error_handler(old);
    if (bad) goto out;
    double emax = -INFINITY, amax = 0.0;
    for (int i = 0; i < mz; i++) {
        emax = fmax(emax, gsl_vector_get(ev, (size_t)i));
        amax = fmax(amax, fabs(gsl_vector_get(ev, (size_t)i)));
    }
    if (amax > 0 && emax > 1e-8 * amax) {
        unstable = 1;
        *ratio = emax / amax;
    }
out:
    free(loc);
    free(u);
    gsl_matrix_free(K);
    gsl_matrix_free(Gt);
    gsl_matrix_free(Q);
    gsl_matrix_free(R);
    gsl_matrix_free(KZ);
    gsl_matrix_free(H);
    gsl_vector_free(tau);
    gsl_vector_free(ev);
    if (ws) gsl_eigen_symm_free(ws);
    return unstable;
}

/* ---- the run ------------------------------------------------------------ */
static const char *const dof_name[6] = {"translation x", "translation y", "translation z",
                                        "rotation about the body's x axis", "rotation about the body's y axis",
                                        "rotation about the body's z axis"};

/* Inacti 5, the gap offset o of each interface that has one, in y at the
 * load time t (docs/theory.md 3.1, 7.8): on an open contact (no force: a
 * closed one that pulls is opened by the active set first),
 * o := max(0, min(o, P_raw)) (the gap recovers while the bodies separate,
 * and keeps what it recovered when they approach again, as the tracking of
 * a dynamic run); an interface starting at t (Tstart) with o = 0 takes its
 * penetration P_raw > 0 as its offset (force-free at its start). Returns
 * the number of offsets changed. */
static int update_offsets(const rc_model *m, rc_data *d, double t, double *y)
{
    int changed = 0;
    for (int i = 0; i < m->ninter; i++) {
        if (m->inter_oidx[i] < 0) continue;
        const int active = t >= m->inter_tstart[i] && t <= m->inter_tstop[i];
        if (!active) continue;
        double *o = y + m->inter_eadr[i] + m->inter_oidx[i];
        rc_inter_report r;
        rc_inter_report_eval(m, i, RC_MODE_CLOSED, d->inter_branch[i], d->inter_track[i], d->inter_slip[i], t, y, &r);
        double on = *o;
        if (d->inter_mode[i] == RC_MODE_INACTIVE) on = *o == 0.0 ? fmax(r.p_raw, 0.0) : *o;
        else if (d->inter_mode[i] == RC_MODE_OPEN) on = fmax(0.0, fmin(*o, r.p_raw));
        if (on != *o) {
            *o = on;
            changed++;
        }
    }
    return changed;
}

/* The couplings' modes at the load time t from the state y (at rest, the
 * modes a dynamic run starts from: rc_cpl_modes_init): a joint stop pushes
 * while its coordinate is past the stop, a contact coupling's face while
 * it is within its effective range. Writes the changes as events
 * (stop_enter, stop_leave; cpl_contact_enter, cpl_contact_leave, one per
 * coupling and kind); old [n + nface] scratch. Returns the number of
 * changes, or -1 on an output error. */
static int update_cpl_modes(const rc_model *m, rc_data *d, double t, const double *y, int *old, ev_sink *sink,
                            long *nev, rc_error *err)
{
    const rc_couplings *c = m->cpl;
    if (!c || c->n == 0) return 0;
    const int nf = c->ct ? c->ct->nface : 0;
    memcpy(old, d->cpl->lmode, (size_t)c->n * sizeof(int));
    if (nf) memcpy(old + c->n, d->cpl->fmode, (size_t)nf * sizeof(int));
    rc_cpl_modes_init(m, d, t, y);
    /* a stop touched (its coordinate on the stop to the rounding of the
     * angles or positions, RC_TOUCH_ULPS) pushes, as a touching contact is
     * closed: at rest nothing else decides, and a free stop under a load
     * towards it leaves the joint's coordinate without stiffness */
    for (int k = c->ncard; k < c->n; k++) {
        if (c->kind[k] != RC_CPL_LIMIT || d->cpl->lmode[k] != RC_LIM_FREE) continue;
        rc_cpl_report r;
        if (rc_cpl_report_eval(m, d, k, t, y, &r)) continue;
        const double q = r.length, band = RC_TOUCH_ULPS * DBL_EPSILON * (1.0 + fabs(q));
        if (isfinite(c->llo[k]) && fabs(q - c->llo[k]) <= band) d->cpl->lmode[k] = RC_LIM_LO_PUSH;
        else if (isfinite(c->lhi[k]) && fabs(q - c->lhi[k]) <= band) d->cpl->lmode[k] = RC_LIM_HI_PUSH;
    }
    int changed = 0;
    for (int k = 0; k < c->n; k++) {
        rc_event_kind kind = RC_EV_NONE;
        const char *name = c->name[k];
        if (c->kind[k] == RC_CPL_LIMIT && d->cpl->lmode[k] != old[k]) {
            kind = d->cpl->lmode[k] == RC_LIM_FREE ? RC_EV_STOP_LEAVE : RC_EV_STOP_ENTER;
            if (c->ljoint[k] >= 0 && m->jnt) name = m->jnt->name[c->ljoint[k]];
        } else if (c->kind[k] == RC_CPL_CONTACT) {
            int in = 0, out = 0;
            for (int f = c->ct->fadr[k]; f < c->ct->fadr[k + 1]; f++) {
                const int was = old[c->n + f] != RC_FACE_OUT, now = d->cpl->fmode[f] != RC_FACE_OUT;
                in += now && !was;
                out += was && !now;
            }
            if (in || out) kind = in ? RC_EV_CPL_CONTACT_ENTER : RC_EV_CPL_CONTACT_LEAVE;
        }
        if (kind == RC_EV_NONE) continue;
        changed++;
        (*nev)++;
        rc_cpl_report r;
        const int bad = rc_cpl_report_eval(m, d, k, t, y, &r);
        const double v[3] = {bad ? 0.0 : r.length, 0.0, bad ? 0.0 : r.force};
        if (rc_bk_sink_event(sink, t, kind, name, v, err)) return -1;
    }
    return changed;
}

/* The modes of the interfaces at the load time t from the state y: the
 * activation windows, then the unilateral rule (an open contact
 * penetrating closes; a closed one separated or pulling opens). Writes
 * the events, counts the flips per interface in flips[] (NULL: none);
 * returns the number of mode changes, or -1 on an output error. */
static int update_modes(const rc_model *m, rc_data *d, double t, const double *y, const double *ptol, double ftol,
                        ev_sink *sink, int *flips, long *nev, rc_error *err)
{
    int changed = 0;
    for (int i = 0; i < m->ninter; i++) {
        const int active = t >= m->inter_tstart[i] && t <= m->inter_tstop[i];
        const int mode = d->inter_mode[i];
        rc_event_kind kind = RC_EV_NONE;
        int next = mode;
        rc_inter_report r;
        if (!active) {
            if (mode != RC_MODE_INACTIVE) {
                next = RC_MODE_INACTIVE;
                kind = RC_EV_INTER_STOP;
            }
        } else {
            rc_inter_report_eval(m, i, RC_MODE_CLOSED, d->inter_branch[i], d->inter_track[i], d->inter_slip[i], t, y,
                                 &r);
            if (mode == RC_MODE_INACTIVE) {
                next = r.p >= -ptol[i] ? RC_MODE_CLOSED : RC_MODE_OPEN;
                kind = RC_EV_INTER_START;
            } else if (mode != RC_MODE_CLOSED && r.p > ptol[i]) {
                next = RC_MODE_CLOSED;
                kind = RC_EV_CONTACT_CLOSE;
            } else if (mode == RC_MODE_CLOSED &&
                       (r.p < -ptol[i] || r.fn < -fmax(ftol, fabs(rc_law_force(m, i, ptol[i]))))) {
                /* pulling: beyond the force tolerance, and beyond what the
                 * law gives within the touch tolerance (a sphere touching
                 * two walls given to 12 digits sits 6e-16 m off each, a
                 * pull of k 6e-16 that is rounding, not a release) */
                next = RC_MODE_OPEN;
                kind = RC_EV_CONTACT_OPEN;
            }
        }
        if (next == mode) continue;
        d->inter_mode[i] = next; /* the static analysis' own active set (docs/theory.md) */
        changed++;
        (*nev)++;
        if (flips) flips[i]++;
        rc_inter_report_eval_d(m, d, i, t, y, &r);
        const double v[3] = {r.p, 0.0, next == RC_MODE_CLOSED && r.fn > 0 ? r.fn : 0.0};
        if (rc_bk_sink_event(sink, t, kind, m->inter_name[i], v, err)) return -1;
    }
    return changed;
}

/* The friction utilisation |F_t| / F_lim of each contact sticking at the
 * equilibrium (t, y) (with friction per point: no point sliding); NAN for
 * the others. */
static void fric_util(const rc_static *s, const rc_data *d, double t, const double *y, double *u)
{
    const rc_model *m = s->m;
    for (int i = 0; i < m->ninter; i++) {
        u[i] = NAN;
        if ((!s->fr_on[i] && !s->pf_on[i] && !s->ex_on[i]) || d->inter_mode[i] != RC_MODE_CLOSED) continue;
        if (s->pf_on[i] ? point_slip(m, d, i) : d->inter_slip[i]) continue;
        rc_inter_report r;
        /* exact stick: the model's own law in stick (the force lambda
         * against the stick limit L_s) */
        rc_inter_report_eval_d(s->ex_on[i] ? s->m0 : m, d, i, t, y, &r);
        const double ft = sqrt(r.ft[0] * r.ft[0] + r.ft[1] * r.ft[1] + r.ft[2] * r.ft[2]);
        if (r.flim > 0.0 && isfinite(ft)) u[i] = ft / r.flim;
    }
}

/* The load time where the first sticking contact reaches its friction
 * limit, u = 1, extrapolated linearly (a secant on the load time) from the
 * utilisations uA, uB at the last two equilibria tA < tB; NAN where no
 * contact's utilisation rises. */
static double slip_estimate(int n, double tA, const double *uA, double tB, const double *uB)
{
    if (!(tB > tA)) return NAN;
    double est = INFINITY;
    for (int i = 0; i < n; i++)
        if (isfinite(uA[i]) && isfinite(uB[i]) && uB[i] > uA[i] && uB[i] < 1.0)
            est = fmin(est, tB + (1.0 - uB[i]) * (tB - tA) / (uB[i] - uA[i]));
    return isfinite(est) ? est : NAN;
}

/* The static analysis of the run (pre == NULL), or the preload of a
 * dynamic run (pre != NULL): the one equilibrium at the load time 0, no
 * results file, no event callback; its state into pre->y, its contacts'
 * modes into pre->closed. */
static rc_status static_solve(const rc_model *m, const rc_run_options *opt, rc_pause *pause, rc_stats *stats,
                              rc_error *err, rc_preload *pre)
{
    rc_error local_err;
    if (!err) err = &local_err;
    rc_error_clear(err);
    rc_stats st0;
    memset(&st0, 0, sizeof st0);
    st0.t_settle = NAN;
    rc_stats *S = &st0;
    rc_status st = pre ? rc_preload_scope(m, "the model's /SOLVER Preload (or rc_model_set_preload)", err)
                       : rc_static_scope(m, "the static analysis, /SOLVER Method 3", err);
    if (st) {
        if (stats) *stats = st0;
        return st;
    }
    if (pre) opt = NULL; /* one solve at t = 0; nothing written, no callback */
    const double wall0 = rc_bk_wall_now();
    const double tend = pre ? 0.0 : opt && opt->t_end_override > 0 ? opt->t_end_override : m->tend;
    const double dtout = pre ? 1.0 : opt && opt->dt_out_override > 0 ? opt->dt_out_override : m->dtout;
    rc_data *d = rc_data_new(m);
    rc_static *s = d ? rc_static_new(m, d) : NULL;
    st_run c = {.s = s, .prev_slide = -1};
    st_kin k;
    memset(&k, 0, sizeof k);
    rc_output *out = NULL;
    frame_buf fb;
    memset(&fb, 0, sizeof fb);
    ev_sink sink = {NULL, opt ? opt->on_event : NULL, opt ? opt->user : NULL, 0, "", NULL};
    /* the state, and with joints the record vector's extras after it
     * (joints.h: their reactions lambda, the projection's nu = 0, the
     * reactions' work W = 0) */
    const int nyx = m->ny + (m->jnt && m->jnt->n > 0 ? 2 * m->jnt->nrows + 1 : 0);
    double *y = calloc((size_t)nyx + 1, sizeof(double)), *ysave = calloc((size_t)nyx + 1, sizeof(double));
    double *ptol = calloc((size_t)m->ninter + 1, sizeof(double));
    int *msave = calloc((size_t)m->ninter + 1, sizeof(int)), *flips = calloc((size_t)m->ninter + 1, sizeof(int));
    int *slsave = calloc((size_t)m->ninter + 1, sizeof(int));
    int *pfsave = calloc((size_t)m->ninter + 1, sizeof(int));
    /* the friction utilisations at the last two equilibria (fric_util) */
    double *uA = malloc(((size_t)m->ninter + 1) * sizeof(double));
    double *uB = malloc(((size_t)m->ninter + 1) * sizeof(double));
    /* the couplings' modes (joint stops, contact coupling faces): scratch
     * of update_cpl_modes, and their save at a substep's start */
    const size_t ncm = m->cpl ? (size_t)m->cpl->n + (size_t)(m->cpl->ct ? m->cpl->ct->nface : 0) : 0;
    int *cplold = calloc(ncm + 1, sizeof(int)), *cplsave = calloc(ncm + 1, sizeof(int));
    char reason[1536] = "";
    const char *fail_reason = NULL;
    double t = 0.0;
    int fb_ok = 0;
    if (!d || !s || !y || !ysave || !ptol || !msave || !flips || !slsave || !pfsave || !uA || !uB || !cplold || !cplsave || !(fb_ok = rc_bk_frame_alloc(m, &fb))) {
        st = RC_SET(err, RC_ENOMEM, "out of memory for the static analysis");
        goto done;
    }
    c.lam0 = y + m->ny;
    c.uprev = malloc(((size_t)s->nr + 1) * sizeof(double));
    c.rprev = malloc(((size_t)s->nr + 1) * sizeof(double));
    c.pprev = malloc(((size_t)m->ninter + 1) * sizeof(double));
    c.pcur = malloc(((size_t)m->ninter + 1) * sizeof(double));
    if (!c.uprev || !c.rprev || !c.pprev || !c.pcur) {
        st = RC_SET(err, RC_ENOMEM, "out of memory for the static analysis");
        goto done;
    }
    if ((st = kin_open(&k, &c, err))) goto done;
    /* tolerances of the active set: a penetration within rounding of the
     * coordinates (RC_TOUCH_ULPS), a force within rounding of the loads */
    double ftol = 0.0;
    for (int i = 0; i < s->n; i++)
        if (i % 6 < 3) ftol = fmax(ftol, s->fs[i]);
    ftol *= 1e3 * DBL_EPSILON;
    rc_initial_state(m, y);
    rc_modes_init(m, d, 0.0, y);
    /* Inacti 5: the offsets are the static analysis' own (update_offsets),
     * not tracked by the engine */
    memset(d->inter_track, 0, (size_t)m->ninter * sizeof(int));
    for (int i = 0; i < m->ninter; i++) {
        rc_inter_report r;
        rc_inter_report_eval(m, i, RC_MODE_CLOSED, d->inter_branch[i], d->inter_track[i], d->inter_slip[i], 0.0, y, &r);
        const double L = fabs(r.point[0]) + fabs(r.point[1]) + fabs(r.point[2]) + fabs(r.p);
        ptol[i] = RC_TOUCH_ULPS * DBL_EPSILON * fmax(L, 1e-300);
        /* at the start: a contact touching or penetrating is closed */
        if (d->inter_mode[i] != RC_MODE_INACTIVE) d->inter_mode[i] = r.p >= -ptol[i] ? RC_MODE_CLOSED : RC_MODE_OPEN;
    }
    if ((st = rc_bk_open_output(m, opt, "", &out, err,
                          "static (KINSOL, Newton with line search; KLU sparse direct on the stiffness)", NULL)))
        goto done;
    sink.out = out;

    /* the output times: t_0 = 0, then each from the last */
    double dtau = dtout;          /* the load substep [s] */
    const double dmin = RC_STATIC_MIN_CUT * dtout;
    /* the slip load's bracket: the first load time that failed with a
     * contact sliding (above t while open), the next load time to try
     * (the slip estimate; NAN: none), the times of uA, uB */
    const double dslip = RC_STATIC_SLIP_MARGIN * dmin;
    double t_hi = INFINITY, t_try = NAN, tA = NAN, tB = NAN;
    for (long kout = 0;; kout++) {
        double tk = fmin((double)kout * dtout, tend);
        if (tend - tk < 1e-12 * tend) tk = tend;
        if (kout > 0 && tk <= t) break;
        if (pre && kout > 0) break;
        /* from t to tk in substeps of the load time */
        int first = kout == 0;
        while (first || t < tk) {
            const int from_est = !first && !isnan(t_try) && t_try > t && t_try <= tk;
            const double tn = first      ? 0.0
                              : from_est ? t_try
                                         : imp_break(m, t, tk - t <= dtau * (1 + 1e-12) ? tk : t + dtau);
            if (from_est) dtau = tn - t;
            t_try = NAN;
            memcpy(ysave, y, (size_t)nyx * sizeof(double));
            memcpy(msave, d->inter_mode, (size_t)m->ninter * sizeof(int));
            memcpy(slsave, d->inter_slip, (size_t)m->ninter * sizeof(int));
            for (int i = 0; i < m->ninter; i++) pfsave[i] = point_slip(m, d, i);
            if (ncm) {
                memcpy(cplsave, d->cpl->lmode, (size_t)m->cpl->n * sizeof(int));
                if (ncm > (size_t)m->cpl->n)
                    memcpy(cplsave + m->cpl->n, d->cpl->fmode, (ncm - (size_t)m->cpl->n) * sizeof(int));
            }
            memset(flips, 0, (size_t)m->ninter * sizeof(int));
            /* friction: the substep's start (its forces, the contact points) */
            rc_static_set_substep_start(s, t, y);
            long iters = 0;
            int ok = 0, rounds = 0, slide = -1;
            double slide_lim = NAN;
            const int max_rounds = RC_STATIC_ROUNDS_MIN + 2 * m->ninter;
            for (;;) {
                update_offsets(m, d, tn, y);
                int ch = update_modes(m, d, tn, y, ptol, ftol, &sink, NULL, &S->events, err);
                if (ch >= 0) {
                    const int cc = update_cpl_modes(m, d, tn, y, cplold, &sink, &S->events, err);
                    ch = cc < 0 ? cc : ch + cc;
                }
                if (ch < 0) {
                    st = RC_EIO;
                    goto done;
                }
                rc_static_set_start(s, y);
                st_out o = kin_solve(&k, &c, tn);
                iters += o.iters;
                S->nonlin_iters += o.iters;
                if (!o.ok && o.singular_col >= 0 && o.singular_col < s->n) {
                    /* singular: once more from a touching start (kin_jac) */
                    c.touch = 1;
                    o = kin_solve(&k, &c, tn);
                    c.touch = 0;
                    iters += o.iters;
                    S->nonlin_iters += o.iters;
                    const int sc = o.ok ? kin_support(&k, &c) : -1;
                    if (sc >= 0) {
                        o.ok = 0;
                        o.singular_col = sc;
                    }
                }
                if (!o.ok) {
                    /* a contact sliding at the last iterate: the load may
                     * exceed what its friction holds (no equilibrium; cut
                     * the substep to find the onset) */
                    slide = -1;
                    for (int i = 0; i < m->ninter && slide < 0; i++) {
                        if ((s->fr_on[i] || s->ex_on[i]) && d->inter_mode[i] == RC_MODE_CLOSED && d->inter_slip[i])
                            slide = i;
                        for (int j = 0; s->pf_on[i] && d->inter_mode[i] == RC_MODE_CLOSED && j < m->inter_npt[i]; j++)
                            if (d->pt_slip[m->inter_pbase[i] + j]) slide = i;
                    }
                    if (slide >= 0) {
                        rc_inter_report r;
                        /* the law at rest (exact stick: its stick limit, the
                         * model's own law in stick) */
                        rc_inter_report_eval(s->ex_on[slide] ? s->m0 : s->m, slide, RC_MODE_CLOSED,
                                             d->inter_branch[slide], d->inter_track[slide], !s->ex_on[slide], tn, s->y,
                                             &r);
                        slide_lim = r.flim;
                        snprintf(reason, sizeof reason, "a contact slides");
                        break;
                    }
                    if (o.singular_col >= s->n + s->nl && o.singular_col < s->nx) {
                        /* exact stick whose rows hold a motion that a
                         * support already holds (or another contact's) */
                        const int ii = s->ex_i[(o.singular_col - s->n - s->nl) / 3];
                        snprintf(reason, sizeof reason,
                                 "static analysis: no equilibrium at the load time t = %.9g s: the stiffness with the "
                                 "exact-stick rows is singular at " RC_LOCFMT "card %s: its sticking contact holds a "
                                 "tangential motion that nothing else leaves free (a /BCS or /IMPVEL on its bodies, or "
                                 "another exact contact, already holds it); use the stick spring (Istick 0, /FRICTION "
                                 "Iform 2) there, or free that motion",
                                 tn, RC_LOC(m->inter_loc[ii]), m->inter_name[ii]);
                        fail_reason = reason;
                        st = RC_SET(err, RC_ESOLVER, "%s", reason);
                        goto done;
                    }
                    if (o.singular_col >= s->n && o.singular_col < s->nx) {
                        /* a joint's row that the others repeat (or a
                         * direction that only the joints could hold) */
                        const int row = o.singular_col - s->n;
                        int j = 0;
                        while (j + 1 < m->jnt->n && m->jnt->radr[j + 1] <= row) j++;
                        snprintf(reason, sizeof reason,
                                 "static analysis: no equilibrium at the load time t = %.9g s: the stiffness with the "
                                 "joints' constraint rows is singular at " RC_LOCFMT "card %s (its constraint row %d): "
                                 "its rows repeat those of other joints, or a body it holds has no support in a "
                                 "direction the joints leave free (add a contact or a spring, or hold it with /BCS)",
                                 tn, RC_LOC(m->jnt->loc[j]), m->jnt->name[j], row - m->jnt->radr[j] + 1);
                        fail_reason = reason;
                        st = RC_SET(err, RC_ESOLVER, "%s", reason);
                        goto done;
                    }
                    if (o.singular_col >= 0 && o.singular_col < s->n) {
                        const int b = s->fb[o.singular_col / 6];
                        snprintf(reason, sizeof reason,
                                 "static analysis: no equilibrium at the load time t = %.9g s: the stiffness is "
                                 "singular: " RC_LOCFMT "/RBODY/%d has no support in %s (nothing holds it in that "
                                 "direction: add a contact or a spring, or hold it with /BCS)",
                                 tn, RC_LOC(m->body_loc[b]), m->body_id[b], dof_name[o.singular_col % 6]);
                        fail_reason = reason;
                        st = RC_SET(err, RC_ESOLVER, "%s", reason);
                        goto done;
                    }
                    char *fname = KINGetReturnFlagName(o.flag);
                    snprintf(reason, sizeof reason, "%s%s%s%s", fname ? fname : "?", c.kmsg[0] ? " (\"" : "", c.kmsg,
                             c.kmsg[0] ? "\")" : "");
                    free(fname);
                    break;
                }
                /* the state at the solution, the friction forces of the
                 * return mapping */
                commit_state(s, tn, expand(s, N_VGetArrayPointer(k.u)), y);
                S->reinits += rounds > 0;
                /* Inacti 5: the offsets taken up as the contacts opened
                 * (the state changes, not the modes: no new solve unless
                 * a mode changes) */
                update_offsets(m, d, tn, y);
                ch = update_modes(m, d, tn, y, ptol, ftol, &sink, flips, &S->events, err);
                if (ch >= 0) {
                    const int cc = update_cpl_modes(m, d, tn, y, cplold, &sink, &S->events, err);
                    ch = cc < 0 ? cc : ch + cc;
                }
                if (ch < 0) {
                    st = RC_EIO;
                    goto done;
                }
                if (ch == 0) {
                    ok = 1;
                    break;
                }
                rounds++;
                for (int i = 0; i < m->ninter; i++)
                    if (flips[i] > RC_STATIC_FLIPS || rounds > max_rounds) {
                        const int ii = flips[i] > RC_STATIC_FLIPS ? i : 0;
                        snprintf(reason, sizeof reason,
                                 "static analysis: the contacts' active set cycles at the load time t = %.9g s: "
                                 "%s " RC_LOCFMT "opened and closed %d times (a contact at the limit of its "
                                 "support); try another output interval or check the deck's supports",
                                 tn, m->ninter ? m->inter_name[ii] : "?", RC_LOC(m->inter_loc[ii]), flips[ii]);
                        fail_reason = reason;
                        st = RC_SET(err, RC_ESOLVER, "%s", reason);
                        goto done;
                    }
                if (rounds > max_rounds + (int)ncm) { /* the couplings' modes (joint stops, faces) cycle */
                    snprintf(reason, sizeof reason,
                             "static analysis: the active set of the joint stops and contact couplings cycles at "
                             "the load time t = %.9g s (%d solves of the load step); try another output interval",
                             tn, rounds);
                    fail_reason = reason;
                    st = RC_SET(err, RC_ESOLVER, "%s", reason);
                    goto done;
                }
            }
            if (ok) {
                memset(s->ex_force, 0, (size_t)m->ninter);
                /* the energies over the substep (the last commit's unknowns) */
                energy_step(s, tn, s->ufull, y);
                /* friction: the contacts that changed between stick and slip
                 * (with friction per point: between no point sliding and
                 * some sliding) */
                for (int i = 0; i < m->ninter; i++) {
                    if ((!s->fr_on[i] && !s->pf_on[i] && !s->ex_on[i]) || d->inter_mode[i] != RC_MODE_CLOSED) continue;
                    const int now = s->pf_on[i] ? point_slip(m, d, i) : d->inter_slip[i];
                    const int was = msave[i] == RC_MODE_CLOSED && (s->pf_on[i] ? pfsave[i] : slsave[i]);
                    if (was == now) continue;
                    rc_inter_report r;
                    rc_inter_report_eval_d(m, d, i, tn, y, &r);
                    const double v[3] = {r.p, 0.0, r.fn > 0 ? r.fn : 0.0};
                    S->events++;
                    if ((st = rc_bk_sink_event(&sink, tn, now ? RC_EV_FRIC_SLIP : RC_EV_FRIC_STICK, m->inter_name[i], v,
                                               err)))
                        goto done;
                }
                t = tn;
                S->steps++;
                /* the friction utilisations of the last two equilibria */
                double *uw = uA;
                uA = uB;
                uB = uw;
                tA = tB;
                tB = t;
                fric_util(s, d, t, y, uB);
                if (t >= t_hi) t_hi = INFINITY; /* past the failed load: no bracket */
                if (t_hi < INFINITY) {
                    /* inside the slip load's bracket: at the cut-back's
                     * precision, the failed load once more (its failure
                     * ends the run); else just below, or above, the
                     * estimate; else half the bracket */
                    const double est = slip_estimate(m->ninter, tA, uA, tB, uB);
                    if (t_hi - t < 2.0 * dmin)
                        t_try = t_hi;
                    else if (est > t && est < t_hi)
                        t_try = est - t > 1.5 * dslip ? est - dslip : fmin(est + dslip, t_hi);
                    else
                        dtau = 0.5 * (t_hi - t);
                } else if (!first && iters <= RC_STATIC_QUICK)
                    dtau = fmin(2.0 * dtau, dtout);
                first = 0;
                continue;
            }
            /* failed: back to t, half the substep */
            S->nonlin_fails++;
            memcpy(y, ysave, (size_t)nyx * sizeof(double));
            memcpy(d->inter_mode, msave, (size_t)m->ninter * sizeof(int));
            memcpy(d->inter_slip, slsave, (size_t)m->ninter * sizeof(int));
            if (ncm) {
                memcpy(d->cpl->lmode, cplsave, (size_t)m->cpl->n * sizeof(int));
                if (ncm > (size_t)m->cpl->n)
                    memcpy(d->cpl->fmode, cplsave + m->cpl->n, (ncm - (size_t)m->cpl->n) * sizeof(int));
            }
            if ((first || dtau * 0.5 < dmin) && slide >= 0 && s->ex_on[slide] && !s->ex_force[slide]) {
                /* exact stick whose static limit L_s lies above its sliding
                 * limit L: past L_s (at the smallest substep) the force
                 * drops to L, and the equilibrium in slip (something else
                 * holding the body) lies a finite slide away, across the
                 * drop, which Newton's line search does not cross; solved
                 * again as sliding from the substep's start (the test
                 * against L, the force L: continuous) */
                int x = 0;
                while (x + 1 < s->nex && s->ex_i[x] != slide) x++;
                if (s->ex_w[10 * x + 7] > s->ex_w[10 * x + 6] * (1.0 + 1e-12)) {
                    s->ex_force[slide] = 1;
                    continue;
                }
            }
            if ((first || dtau * 0.5 < dmin) && slide >= 0) {
                snprintf(reason, sizeof reason,
                         "static analysis: no static equilibrium at the load time t = %.9g s: the load exceeds what "
                         "friction can hold: " RC_LOCFMT "card %s slides (its friction force would pass the limit "
                         "Sfric + mu F_n = %.6g N; the last equilibrium at t = %.9g s, load substeps down to %.3g s); "
                         "a static analysis has no equilibrium for a sliding body: follow the motion with Method 1 or "
                         "2, or hold the body",
                         tn, RC_LOC(m->inter_loc[slide]), m->inter_name[slide], slide_lim, t, dtau);
                fail_reason = reason;
                st = RC_SET(err, RC_ESOLVER, "%s", reason);
                goto done;
            }
            double plim = 0.0, flim = 0.0;
            const int lim = (first || dtau * 0.5 < dmin) ? limit_point(m, d, t, y, &plim, &flim) : -1;
            if (lim >= 0) {
                snprintf(reason, sizeof reason,
                         "static analysis: no static equilibrium at the load time t = %.9g s: a limit point "
                         "(snap-through) at the load time t = %.9g s (gravity's time function at %.9g): the load "
                         "curve of " RC_LOCFMT "card %s stops rising at P = %.6g m, F = %.6g N, so a greater load has "
                         "no equilibrium near the last one (load substeps down to %.3g s); the structure snaps "
                         "through to another state, which a static analysis does not follow: use Method 1 or 2",
                         tn, t, rc_gravity_factor(m, t), RC_LOC(m->inter_loc[lim]), m->inter_name[lim], plim, flim,
                         dtau);
                fail_reason = reason;
                st = RC_SET(err, RC_ESOLVER, "%s", reason);
                goto done;
            }
            if (first || dtau * 0.5 < dmin) {
                char what[1024]; /* KINSOL's reason, cut to leave room for the message around it */
                snprintf(what, sizeof what, "%.1000s", reason);
                snprintf(reason, sizeof reason,
                         "static analysis: no equilibrium found at the load time t = %.9g s (from the equilibrium "
                         "at t = %.9g s, load substeps down to %.3g s): KINSOL %s; the loads may exceed what the "
                         "contacts can hold, or a body may have lost its support",
                         tn, t, dtau, what);
                fail_reason = reason;
                st = RC_SET(err, RC_ESOLVER, "%s", reason);
                goto done;
            }
            if (slide >= 0) {
                /* a contact slides: the slip load lies below tn; unless
                 * this load was already the estimate, try just below the
                 * estimate (the cut-back where there is none) */
                t_hi = fmin(t_hi, tn);
                const double est = from_est ? NAN : slip_estimate(m->ninter, tA, uA, tB, uB);
                if (est > t && est < t_hi) {
                    t_try = est - t > 1.5 * dslip ? est - dslip : fmin(est + dslip, t_hi);
                    continue;
                }
            }
            dtau *= 0.5;
        }
        /* with joints: Newton finds the equilibrium nearest its start,
         * which must be a stable one */
        double ratio = 0.0;
        if (jnt_unstable(s, t, y, &ratio)) {
            snprintf(reason, sizeof reason,
                     "static analysis: the equilibrium found at the load time t = %.9g s is unstable: the stiffness "
                     "on the motions the joints allow has a positive eigenvalue (%.3g of the largest): a jointed "
                     "body balanced against its load (an inverted pendulum, a lever over its pivot); Newton finds "
                     "the equilibrium nearest the start: start the model nearer the stable one, or follow the motion "
                     "with Method 2",
                     t, ratio);
            fail_reason = reason;
            st = RC_SET(err, RC_ESOLVER, "%s", reason);
            goto done;
        }
        if ((st = rc_bk_write_frame(m, d, out, &fb, tk, y, 0, err))) goto done;
        if (opt && opt->stop && *opt->stop) {
            snprintf(reason, sizeof reason, "interrupted at t = %.9g s (signal): the results up to there are kept", t);
            fail_reason = reason;
            st = RC_SET(err, RC_EINTERRUPT, "%s", reason);
            goto done;
        }
        if (sink.stop) {
            snprintf(reason, sizeof reason, "%s: the results up to there are kept", sink.why);
            fail_reason = reason;
            st = RC_SET(err, RC_EINTERRUPT, "%s", reason);
            goto done;
        }
        /* stepping: the equilibrium of the first output time at or after
         * the time asked for */
        int pstop = 0;
        while (pause && tk >= pause->until && !pstop) pstop = pause->reached(pause, pause->until, y);
        if (pstop) {
            snprintf(reason, sizeof reason, "stopped by the caller at t = %.9g s: the results up to there are kept", t);
            fail_reason = reason;
            st = RC_SET(err, RC_EINTERRUPT, "%s", reason);
            goto done;
        }
        if (tk >= tend) break;
    }
    if (opt && opt->y_end) {
        memcpy(opt->y_end, y, (size_t)m->ny * sizeof(double));
        rc_state_to_deck(m, opt->y_end);
    }
    if (pre) {
        memcpy(pre->y, y, (size_t)m->ny * sizeof(double));
        for (int i = 0; i < m->ninter; i++) pre->closed[i] = d->inter_mode[i] == RC_MODE_CLOSED;
    }

done:
    S->t_end = t;
    if (s) {
        S->rhs_evals = s->nfev;
        S->jac_evals = s->njev;
        S->lin_setups = s->njev;
    }
    snprintf(S->physics_note, sizeof S->physics_note,
             "not run (static analysis: equilibria, no motion; the contact forces balance the loads to the "
             "residual tolerance)");
    S->wall_time = rc_bk_wall_now() - wall0;
    if (out) {
        rc_error e2;
        rc_output_linalg(out, -1, s ? (long)s->colptr[s->nx] : -1, (long)m->nnz);
        rc_status st2 = rc_output_close(out, S, st == RC_OK, fail_reason ? fail_reason : err->msg, &e2);
        if (st2 && st == RC_OK) {
            st = st2;
            *err = e2;
        }
    }
    if (stats) *stats = *S;
    kin_close(&k);
    rc_bk_frame_free(&fb);
    rc_static_free(s);
    rc_data_free(d);
    free(y);
    free(ysave);
    free(ptol);
    free(msave);
    free(flips);
    free(slsave);
    free(pfsave);
    free(uA);
    free(uB);
    free(c.uprev);
    free(c.rprev);
    free(c.pprev);
    free(c.pcur);
    free(cplold);
    free(cplsave);
    return st;
}

static rc_status static_run(const rc_model *m, const rc_run_options *opt, rc_pause *pause, const rc_preload *pre,
                            rc_stats *stats, rc_error *err)
{
    (void)pre; /* the static analysis starts from the same equilibrium: a preload adds nothing */
    return static_solve(m, opt, pause, stats, err, NULL);
}

rc_status rc_static_preload(const rc_model *m, rc_preload *pre, rc_error *err)
{
    rc_error local_err;
    if (!err) err = &local_err;
    rc_stats S;
    const rc_status st = static_solve(m, NULL, NULL, &S, err, pre);
    pre->iters = S.nonlin_iters;
    pre->solves = S.steps + S.reinits;
    pre->flips = S.events;
    pre->wall = S.wall_time;
    if (st && st != RC_EINPUT) { /* say that it is the preload that failed */
        char msg[7801];
        snprintf(msg, sizeof msg, "%.7800s", err->msg);
        snprintf(err->msg, sizeof err->msg, "preload (the static equilibrium at t = 0 the dynamic run would start "
                                            "from; nothing run or written): %s", msg);
    }
    return st;
}

const rc_solver rc_solver_static = {"static", RC_METHOD_STATIC, static_run};
