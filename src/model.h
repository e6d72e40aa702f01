/*
 * The compiled model (constant during a run) and the run data (mutable).
 *
 * State layout (y), fixed at compile time:
 *   free body f, at body_yadr[b] = 13 f:
 *     [0..2]  x      centre of mass, global frame            [m]
 *     [3..6]  q      unit quaternion (w, x, y, z), body->global [-]
 *     [7..9]  v      velocity of the centre of mass, global  [m/s]
 *     [10..12] w     angular velocity, BODY frame            [rad/s]
 *   then per interface i, at inter_eadr[i]:
 *     [0] W_load  work of the load-curve force on the penetration   [J]
 *     [1] W_damp  energy dissipated by the normal damping           [J]
 * Fixed bodies have no states; their pose is body_y0 (13 values, zero
 * velocities).
 *
 * The body frame coincides with the global frame at t = 0 (q0 = identity),
 * so the inertia tensor of /RBODY (global axes at t = 0) is the body-frame
 * tensor.
 */
#ifndef RC_MODEL_H
#define RC_MODEL_H

#include <stdint.h>

#include "ricochet/ricochet.h"
#include "table.h"

#define RC_NB 13 /* states of a free body */
#define RC_NE 2  /* energy states of an interface */
#define RC_JB_MAX ((2 * 6 + RC_NE) * 2 * RC_NB) /* largest dense element block */

/* Analytic surface kinds. */
typedef enum { RC_SURF_PLANE = 1, RC_SURF_SPHERE = 2 } rc_surf_kind;

/* Geometry pair of an interface (surface kinds, ordered). */
typedef enum {
    RC_PAIR_SPHERE_PLANE = 1, /* surface a: sphere, surface b: plane */
    RC_PAIR_SPHERE_SPHERE = 2 /* a, b: spheres                        */
} rc_pair_kind;

/* Interface modes (discrete state, changed only at events). */
typedef enum { RC_MODE_INACTIVE = 0, RC_MODE_OPEN = 1, RC_MODE_CLOSED = 2 } rc_inter_mode;

/* Root functions per interface, in this order. */
enum { RC_ROOT_TSTART = 0, RC_ROOT_TSTOP = 1, RC_ROOT_CONTACT = 2, RC_ROOTS_PER_INTER = 3 };

/* Jacobian entries written by one element: dense block of `nrow` rows by
 * `ncol` columns (state indices), slot[r * ncol + c] = position in the CSC
 * value array, or -1 for an entry that is structurally zero (pruned). */
typedef struct rc_jblock {
    int nrow, ncol;
    int rows[RC_NB * 2 + RC_NE]; /* state indices */
    int cols[RC_NB * 2 + RC_NE];
    int64_t *slot;               /* [nrow*ncol] */
} rc_jblock;

struct rc_model {
    /* provenance */
    char *case_path;
    char title[101];
    char unit_mass[21], unit_length[21], unit_time[21];
    unsigned long checksum;

    /* bodies: all /RBODY, fixed ones included */
    int nbody;
    int nfree;
    int *body_id;        /* [nbody] /RBODY id */
    int *body_fixed;     /* [nbody] 1: fixed (ground) */
    int *body_yadr;      /* [nbody] offset in y, -1 when fixed */
    double *body_mass;   /* [nbody] [kg] */
    double *body_J;      /* [nbody*9] inertia, body frame, row-major [kg m^2] */
    double *body_Jinv;   /* [nbody*9] its inverse [1/(kg m^2)] */
    double *body_y0;     /* [nbody*13] initial state (pose for fixed bodies) */
    double *body_grav;   /* [nbody*3] gravity per unit function value [m/s^2] */
    double ground_y0[RC_NB]; /* pose of "fixed in space" (identity, at rest) */
    int grav_table;      /* table index of the gravity time function, -1: constant */
    double grav_ascale;  /* [s] abscissa scale of the gravity function */

    /* analytic surfaces */
    int nsurf;
    int *surf_id;        /* [nsurf] */
    rc_surf_kind *surf_kind;
    int *surf_body;      /* [nsurf] body index carrying it, -1: fixed in space */
    double *surf_p;      /* [nsurf*3] local point (plane point / sphere centre) in body frame [m] */
    double *surf_n;      /* [nsurf*3] local unit outward normal (plane) [-] */
    double *surf_r;      /* [nsurf] sphere radius [m] */

    /* curves */
    int ntable;
    rc_table *table;     /* [ntable] */

    /* TYPE6 interfaces */
    int ninter;
    int *inter_id;       /* [ninter] */
    rc_pair_kind *inter_pair;
    int *inter_sa, *inter_sb; /* surface indices in pair order (a = sphere) */
    int *inter_ba, *inter_bb; /* body indices of a and b (-1: fixed in space) */
    double *inter_gap;   /* Gap [m] */
    double *inter_tstart, *inter_tstop; /* [s] */
    double *inter_visc;  /* [N s/m] */
    double *inter_fscalev; /* [N] */
    double *inter_ascalex; /* [m] */
    double *inter_fscaleld; /* [N] */
    double *inter_ascalef; /* [N] */
    double *inter_ascalev; /* [m/s] */
    int *inter_fct_ld, *inter_fct_dv, *inter_fct_df; /* table index or -1 */
    int *inter_eadr;     /* [ninter] offset of the 2 energy states */
    char **inter_name;   /* [ninter] "/INTER/TYPE6/<id>" */

    /* state vector */
    int ny;
    double *atol;        /* [ny] absolute tolerances (units of each state) */

    /* run and solver settings */
    double tend, dtout;  /* [s] */
    double rtol;
    double atol_pos, atol_quat, atol_vel, atol_omega, atol_energy;
    int max_order;
    long max_steps;
    double hmax, h0;     /* [s] */

    /* Jacobian: CSC pattern over y, full diagonal, and element blocks */
    int64_t nnz;
    int64_t *jac_colptr; /* [ny+1] */
    int64_t *jac_rowind; /* [nnz] */
    rc_jblock *jb_body;  /* [nbody] (only free bodies used) */
    rc_jblock *jb_inter; /* [ninter] */
    int64_t *jac_diag;   /* [ny] slot of each diagonal entry */
};

/* Mutable run data. */
typedef struct rc_data {
    int *inter_mode;     /* [ninter] rc_inter_mode */
    long n_rhs, n_jac, n_root;
    int fail_inter;      /* element that produced a non-finite force, -1 */
    double fail_t;
} rc_data;

/* What the output and the event logic see of one interface. */
typedef struct rc_inter_report {
    double p;            /* penetration past the Gap [m] */
    double vn;           /* approach rate dp/dt [m/s] */
    double fload;        /* load-curve force [N] */
    double fdamp;        /* damping force [N] */
    double fn;           /* total normal force of the law (may be < 0 off-mode) [N] */
    double point[3];     /* contact point [m] */
    double normal[3];    /* unit normal, from a to b [-] */
} rc_inter_report;

/* ---- data ---------------------------------------------------------- */
rc_data *rc_data_new(const rc_model *m);
void rc_data_free(rc_data *d);

/* ---- engine (assemble.c) ------------------------------------------- */
/* Initial state vector [ny]. */
void rc_initial_state(const rc_model *m, double *y);
/* ydot = f(t, y; modes). Returns 0, or 1 (recoverable) on a non-finite force. */
int rc_assemble_rhs(const rc_model *m, rc_data *d, double t, const double *y, double *ydot);
/* Jacobian values into `val` [nnz] on the fixed pattern. */
int rc_assemble_jac(const rc_model *m, rc_data *d, double t, const double *y, double *val);
/* Root functions [ninter*RC_ROOTS_PER_INTER]. */
void rc_assemble_roots(const rc_model *m, const rc_data *d, double t, const double *y, double *g);
/* Evaluate one interface at (t, y), in `mode`, for reports and events. */
void rc_inter_report_eval(const rc_model *m, int i, int mode, double t, const double *y,
                          rc_inter_report *r);
/* Gravity acceleration vector of body b at time t [m/s^2]. */
void rc_gravity(const rc_model *m, int b, double t, double g[3]);
/* Pose and velocity view of body b: pointer to its 13 values in y, the
 * fixed pose of a fixed body, or the ground pose for b = -1. */
const double *rc_body_state(const rc_model *m, int b, const double *y);

/* Energies [J]: kinetic, gravitational potential, contact elastic work,
 * damping dissipation, total. */
enum { RC_E_KIN, RC_E_POT, RC_E_ELASTIC, RC_E_DAMP, RC_E_TOTAL, RC_NENERGY };
void rc_energy(const rc_model *m, double t, const double *y, double e[RC_NENERGY]);

/* Dense block of an element (body e, or interface e in closed mode) at
 * (t, y), row-major over its rc_jblock rows and columns (assemble_jac.c). */
void rc_jac_dense_block(const rc_model *m, int is_inter, int e, double t, const double *y, double *out);

/* ---- Jacobian pattern (jacpattern.c) ------------------------------- */
rc_status rc_jac_build(rc_model *m, rc_error *err);
void rc_jac_free(rc_model *m);

/* ---- modes and events (events.c) ----------------------------------- */
/* Consistent modes at (t, y) from scratch (start of run). */
void rc_modes_init(const rc_model *m, rc_data *d, double t, const double *y);

#endif
