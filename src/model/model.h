/*
 * The compiled model (constant during a run) and the run data (mutable).
 *
 * State layout (y), fixed at compile time:
 *   free body f, at body_yadr[b] = 13 f:
 *     [0..2]  x      centre of mass, global frame            [m]
 *     [3..6]  q      unit quaternion (w, x, y, z), body->global [-]
 *     [7..9]  v      velocity of the centre of mass, global  [m/s]
 *     [10..12] w     angular velocity, BODY frame            [rad/s]
 *   then per interface i, its own states at inter_eadr[i] (inter_ns[i] of them):
 *     [0] W_load  work of the elastic(-plastic) normal force F        [J]
 *     [1] W_damp  energy dissipated by the normal damping             [J]
 *     [inter_hidx] F_h    hysteresis force, Iform 1 and 2              [N]
 *     [inter_oidx] offset gap reduction of Inacti = 5 (>= 0)           [m]
 *     [inter_peidx] P_e, the effective penetration of the law of a pair
 *                   with several contact points (docs/theory.md 2.7)   [m]
 *     [inter_dhidx] D_h, the law's dissipation (P_e's relaxation, Iform 1, 2's load curve)
 *                   (compile.c, hyst_state)                             [J]
 *     [fr.tidx .. +2] F_t tangential (friction) force on body a, global
 *                     frame, in the contact plane (incremental form)  [N]
 *     [fr.fidx .. +2] filtered friction force (/FRICTION Ifiltr)       [N]
 *     [fr.widx]       W_fric work of the friction forces              [J]
 *   (fr = inter_fr[i], friction.h)
 * Fixed bodies have no states; their pose is body_y0 (13 values, zero
 * velocities).
 *
 * The body frame coincides with the global frame at t = 0 (q0 = identity),
 * so the inertia tensor of /RBODY (global axes at t = 0) is the body-frame
 * tensor.
 */
#ifndef RC_MODEL_H
#define RC_MODEL_H

#include <math.h>
#include <stdint.h>

#include "ricochet/ricochet.h"
#include "case/case.h"
#include "model/friction.h"
#include "model/table.h"

#define RC_PI 3.14159265358979323846
#define RC_NB 13 /* states of a free body */
#define RC_NE 2  /* energy states of an interface */
/* Stick -> slip needs |F_t| > (1 + RC_SLIP_BAND) F_lim: an undamped stick
 * spring released from the limit rings back exactly to it, and a touch must
 * not count as a crossing (docs/theory.md 3.5) [-]. */
#define RC_SLIP_BAND 1e-6
/* The power band D_b of the recovery of a shared law's penetration P_e, as
 * a fraction of the interface's F_s v_s: rho = kappa (P - P_e) D / (D +
 * F_el+ kappa (P - P_e) + D_b), D the dissipation that pays for it
 * (docs/theory.md 2.7) [-]. */
#define RC_PE_PAY_BAND 0.1
/* The smallest limit scale of the slip law's rates, as a fraction of the
 * interface's force scale F_s (times a contact point's share): docs/theory.md
 * 3.5 */
#define RC_SLIP_LFLOOR 1.0
/* TYPE6's Sfric is carried in full from a normal force of RC_SFRIC_RAMP
 * times the interface's force scale F_s up, a smooth step below it
 * (docs/theory.md 3.5) [-] */
#define RC_SFRIC_RAMP 1e-3
/* Values per contact point that the points' evaluation returns
 * (rc_points_eval): the slip root, the applied force at unit share (3), the
 * share w_j, the depth q_j [m] below the level of the shares (> 0: it takes
 * a share), the magnitude of its state F_t in its tangent plane at unit
 * share [N] (its spring's energy |F_t|^2 / (2 K_t)) */
#define RC_PT_OUT 7
#define RC_NODE_CACHE 13 /* values per point of the node geometry cache (rc_data.node_cache) */
/* Pairs with several contact points (docs/theory.md 2.7): the share band,
 * relative to the penetration scale [-], and the relaxation rate of the
 * effective penetration P_e down to P, relative to the contact's frequency
 * [-]. */
#define RC_SHARE_BAND 1e-6
#define RC_PE_RELAX 10.0
#define RC_NS_MAX 12 /* own states of an interface: energies, F_h, offset, P_e, F_t, filter, W_fric */
#define RC_JB_MAX ((2 * 6 + RC_NS_MAX) * (2 * RC_NB + RC_NS_MAX)) /* largest dense block */

/* Analytic surface kinds. */
typedef enum { RC_SURF_PLANE = 1, RC_SURF_SPHERE = 2, RC_SURF_CYL = 3, RC_SURF_BOX = 4,
               RC_SURF_SEG = 5 /* segment surface: /SURF/SEG, /SURF/PART (model/segsurf.c) */ } rc_surf_kind;

/* Extra parameters of a surface (surf_ext, RC_SURF_NEXT per surface):
 *   cylinder: [0] half-length of the cylindrical part [m], [1] ends (0 flat,
 *             1 rounded), [2] contact point (0 mid-length, 1 deepest),
 *             [3] the end band of the deepest point [m] (set with the
 *             scales; 0: the nearer end alone);
 *             its axis (unit, body frame) is surf_n, its radius surf_r;
 *   box:      [0..2] half-sizes along its axes [m], [3..11] the three unit
 *             axes u, v, w in the body frame (row k at 3 + 3 k);
 *   plane:    [0] 1 when bounded to a parallelogram (/RWALL/PARAL), then
 *             [1..3] its corner M (body frame), [4..6] and [7..9] its sides
 *             e1 = M1 - M, e2 = M2 - M [m]; 0: unbounded. */
#define RC_SURF_NEXT 12

/* Geometry pair of an interface (surface kinds, ordered). */
typedef enum {
    RC_PAIR_SPHERE_PLANE = 1, /* surface a: sphere, surface b: plane */
    RC_PAIR_SPHERE_SPHERE = 2, /* a, b: spheres                       */
    RC_PAIR_CYL_PLANE = 3,    /* a: cylinder, b: plane                */
    RC_PAIR_CYL_BOX = 4,      /* a: cylinder, b: box (nearest face)   */
    RC_PAIR_CYL_CYL = 5,      /* a, b: cylinders with parallel axes   */
    RC_PAIR_SPHERE_BOX = 6,   /* a: sphere, b: box (nearest face)     */
    RC_PAIR_SEG_PLANE = 7,    /* a: segment surface (its nodes), b: plane;
                                 several contact points (docs/theory.md) */
    RC_PAIR_SPHERE_SEG = 8,   /* a: sphere, b: segment surface (closest
                                 points on the candidate segments) */
    RC_PAIR_SEG_BOX = 9,      /* a: segment surface (its nodes), b: box
                                 (each node against its nearest face) */
    RC_PAIR_SEG_SEG = 10,     /* a, b: segment surfaces, node to segment
                                 both ways (the nodes of a against the
                                 segments of b, then those of b against a's) */
    RC_PAIR_CYL_SEG = 11,     /* a: cylinder, b: segment surface (the plane
                                 of the segment under the cylinder's centre) */
    RC_PAIR_SPHERE_CYL = 12   /* a: sphere, b: cylinder of finite length
                                 (distance from the centre to the solid) */
} rc_pair_kind;
/* Pairs with several contact points (docs/theory.md 2.7). */
static inline int rc_pair_multi(rc_pair_kind k)
{
    return k == RC_PAIR_SEG_PLANE || k == RC_PAIR_SPHERE_SEG || k == RC_PAIR_SEG_BOX || k == RC_PAIR_SEG_SEG;
}
/* Pairs whose contact points are nodes (fixed at compile time). */
static inline int rc_pair_nodes(rc_pair_kind k)
{
    return k == RC_PAIR_SEG_PLANE || k == RC_PAIR_SEG_BOX || k == RC_PAIR_SEG_SEG;
}
/* "sphere-plane", "cylinder-box", ... (model/geom.c) */
const char *rc_geom_pair_name(rc_pair_kind kind);

/* Interface modes (discrete state, changed only at events):
 *   INACTIVE  outside [Tstart, Tstop]: no force, history frozen
 *   OPEN      separated, P <= 0: no force
 *   CLOSED    P > 0 and total normal force > 0: the force acts
 *   RELEASED  P > 0 but the total force is clipped at zero (damping pulls):
 *             no force; the hysteresis law still follows P */
typedef enum { RC_MODE_INACTIVE = 0, RC_MODE_OPEN = 1, RC_MODE_CLOSED = 2, RC_MODE_RELEASED = 3 } rc_inter_mode;

/* Hysteresis branch (Iform 1, 2) while P > 0. */
typedef enum { RC_BR_LOAD = 0, RC_BR_ELASTIC = 1, RC_BR_UNLOAD = 2 } rc_branch;

/* Root functions per interface, in this order (docs/theory.md). */
enum {
    RC_ROOT_TSTART = 0, /* t - Tstart                                  */
    RC_ROOT_TSTOP,      /* t - Tstop                                   */
    RC_ROOT_ZONE,       /* P: entering / leaving the contact zone      */
    RC_ROOT_FORCE,      /* total normal force: release / re-close      */
    RC_ROOT_HYST_A,     /* LOAD, UNLOAD: dP/dt; ELASTIC: F_L(P) - F_h  */
    RC_ROOT_HYST_B,     /* ELASTIC: F_h - F_U(P)                       */
    RC_ROOT_TRK_A,      /* Inacti 5 tracking: dP_raw/dt                */
    RC_ROOT_TRK_B,      /* Inacti 5 tracking: offset                   */
    RC_ROOT_SLIP,       /* stick: |F_t|^2 - F_lim^2; slip: v_t . e     */
    RC_ROOT_REV,        /* saturated stateless friction: v_t . d_ref   */
    RC_ROOTS_PER_INTER
};

/* Jacobian entries written by one element: dense block of `nrow` rows by
 * `ncol` columns (state indices), slot[r * ncol + c] = position in the CSC
 * value array, or -1 for an entry that is structurally zero (pruned). */
typedef struct rc_jblock {
    int nrow, ncol;
    int rows[RC_NB * 2 + RC_NS_MAX]; /* state indices */
    int cols[RC_NB * 2 + RC_NS_MAX];
    int64_t *slot;               /* [nrow*ncol] */
} rc_jblock;

/* the smallest derived position tolerance, in roundings of the contact's
 * coordinates (DBL_EPSILON times their magnitude) */
#ifndef RC_TOL_ULPS
#define RC_TOL_ULPS 64.0
#endif
/* Bands about zero at events, in roundings (ulps) of the quantities
 * involved: touch bands of the coordinates, the hysteresis roots' band of
 * the forces (engine/events/events.c, assemble_rhs.c) */
#define RC_TOUCH_ULPS 1e3
/* ... and the touch bands at least this many roundings of the deck's
 * coordinates (the positions the deck gave, before the model moved its
 * origin: an error of the initial state; engine/assembly/bounds.c) */
#ifndef RC_TOL_DECK_ULPS
#define RC_TOL_DECK_ULPS 4.0
#endif

/* The error weight of a contact point's friction states s_j (its force at
 * unit share, segfric_point) follows its share w_j of the interface's
 * force: their tolerance is divided by sqrt(max(w_j, this)), so that the
 * error controlled is that of sqrt(w_j) s_j, whose square sets the energy
 * the point's spring stores (w_j |s_j|^2 / (2 K_t)), and the state of a
 * point out of the contact (no force) does not set the steps
 * (docs/theory.md 2.7). */
#define RC_EWT_SHARE_MIN 1e-12

/* A scene whose nodes' centre lies farther from the deck's origin than this
 * many times their half extent, and than RC_ORIGIN_MIN [m], is computed in
 * coordinates relative to that centre (compile.c, docs/theory.md 7.1). */
#define RC_ORIGIN_FAR 4.0
#define RC_ORIGIN_MIN 0.1

struct rc_model {
    /* provenance */
    char *case_path;
    char *overrides;     /* the --set arguments read with the case, "ARG; ARG" (NULL: none) */
    rc_loc end_loc;      /* the deck's end (rc_case.end): place of deck-level messages */
    char title[101];
    char unit_mass[21], unit_length[21], unit_time[21];
    char deck_unit[3][21]; /* the deck's input units of /BEGIN (mass, length,
                            time), "" when undeclared */
    double deck_factor[3]; /* their values in kg, m, s; 0 when undeclared */
    unsigned long checksum;
    int nfile;           /* files read: 0 the case file, then its includes */
    char **file;         /* [nfile] their paths (as given or resolved) */
    unsigned long long *file_id; /* [4*nfile] device, inode, size and modification time [ns] of
                                    each as read (NULL: not known) */

    /* bodies: all /RBODY, fixed ones included */
    int nbody;
    int nfree;
    int *body_id;        /* [nbody] /RBODY id */
    rc_loc *body_loc;    /* [nbody] header of the /RBODY card, for messages */
    int *body_fixed;     /* [nbody] 1: fixed (ground) */
    int *body_yadr;      /* [nbody] offset in y, -1 when fixed */
    double *body_mass;   /* [nbody] [kg] */
    double *body_J;      /* [nbody*9] inertia, body frame, row-major [kg m^2] */
    double *body_Jinv;   /* [nbody*9] its inverse [1/(kg m^2)] */
    double *body_y0;     /* [nbody*13] initial state (pose for fixed bodies) */
    double *body_grav;   /* [nbody*3] gravity per unit function value [m/s^2] */
    int *body_dofmask;   /* [nbody*6] 1: translation x,y,z / rotation held (/BCS) */
    int nheld;           /* held acceleration rows */
    int *held;           /* [nheld] state indices of held velocities (their rates are 0) */
    char *row_held;      /* [ny] 1 for those rows */
    double ground_y0[RC_NB]; /* pose of "fixed in space" (identity, at rest) */
    double origin[3];        /* the model's origin in the deck's coordinates [m] (0, or the
                                centre of the nodes of a scene more than RC_ORIGIN_FAR times
                                its half size and RC_ORIGIN_MIN from the deck's): the
                                model's positions are relative to it (compile.c);
                                outputs add it back */
    int grav_table;      /* table index of the gravity time function, -1: constant */
    double grav_ascale;  /* [s] abscissa scale of the gravity function */
    double grav_tstart;  /* [s] the /GRAV cards' sensor's time on Ts (sensor_ID,
                            a time known when compiling): no gravity for
                            t <= Ts, then f((t - Ts) / Ascale), a time
                            breakpoint; 0: from t = 0, unshifted */
    int grav_sens;       /* the /GRAV cards' sensor found in the run (a
                            distance or interface sensor, or a logic sensor
                            of one): no gravity until its event (rc_data.
                            sens_rel), then f((t - t_on) / Ascale), t_on its
                            time on (rc_data.sens_ton); -1: none */
    int gwork_adr;       /* state: potential energy of a time-varying gravity,
                            E' = -sum m g(t).v [J]; -1 when gravity is constant */
    int64_t *gwork_slot; /* [3*nbody] Jacobian slots (row gwork_adr, columns v) */
    struct rc_imposed *imp; /* /IMPVEL imposed velocities (imposed.h); NULL: none */
    /* sensors (model/sensor.c), one per /SENSOR card in the case's order:
     * a distance sensor (kind 1) watches the distance of two points, each
     * on a body or fixed in space, through two root functions (at
     * rc_root_sens_base: d - Dmax and Dmin - d, rising through 0) until it
     * triggers; time sensors (kind 0) have none (their time is compiled
     * into the Tstart of what they activate), nor logic sensors (kinds 2,
     * 3, 4: their time on follows their inputs', engine/assembly/sensors.c);
     * a sensor found in the run that releases a held body (sens_hold) has
     * its release root in its first slot once its time on is known; an
     * interface sensor (kind 5) watches the interfaces of one /INTER card:
     * its contact closing (an event of the interfaces, events.c), or its
     * total normal force through a root function in its first slot
     * (F_n - Fmax, rising through 0) until it triggers */
    int nsens;
    int *sens_id;        /* [nsens] sens_ID */
    int *sens_kind;      /* [nsens] rc_case_sensor_kind (0 TIME, 1 DIST, 2 AND, 3 OR, 4 NOT, 5 INTER) */
    int *sens_in;        /* [2*nsens] AND, OR: the input sensors' indices; NOT: its input (-1: none) */
    int *sens_hold;      /* [nsens] 1: the sensor's time on is found in the run and
                            releases a held body (/RBODY sens_ID; imposed.h tsens)
                            or starts a load (/IMPVEL sensor_ID, imposed.h tson;
                            /GRAV sensor_ID, grav_sens): its release root and
                            event (rc_data.sens_rel) */
    double *sens_tdelay; /* [nsens] [s] */
    double *sens_tmin;   /* [nsens] DIST, INTER with Fmax: how long the criterion must
                            hold before the sensor triggers [s] (0: at once) */
    int *sens_body;      /* [2*nsens] the points' bodies (-1: fixed in space) */
    double *sens_p;      /* [6*nsens] the points in their bodies' frames [m] */
    double *sens_d;      /* [2*nsens] DIST: Dmin, Dmax [m] (0: no such bound); INTER:
                            0, Fmax [N] (0: the contact closing triggers) */
    int *sens_inter;     /* [nsens] INTER: the id of the /INTER card whose interfaces
                            (inter_id) it watches; 0: not an interface sensor */
    int *inter_sens;     /* [ninter] the sensor found in the run (a distance or interface
                            sensor, or a logic sensor of one) that turns interface i
                            on, -1: none */

    /* analytic surfaces */
    int nsurf;
    int *surf_id;        /* [nsurf] */
    rc_surf_kind *surf_kind;
    int *surf_body;      /* [nsurf] body index carrying it, -1: fixed in space */
    double *surf_p;      /* [nsurf*3] local point (plane point / sphere centre) in body frame [m] */
    double *surf_n;      /* [nsurf*3] local unit outward normal (plane) [-] */
    double *surf_r;      /* [nsurf] sphere radius [m] */
    double *surf_ext;    /* [nsurf*RC_SURF_NEXT] cylinder and box parameters (above) */
    /* segment surfaces (RC_SURF_SEG; model/segsurf.c): node j of surface s
     * at surf_node + 3 (surf_nadr[s] + j), j < surf_nadr[s+1] - surf_nadr[s],
     * body frame [m]; segment k at surf_seg + 4 (surf_sadr[s] + k), four
     * local node indices (the fourth = the third: a triangle). Analytic
     * surfaces have none. */
    int *surf_nadr;      /* [nsurf+1] */
    double *surf_node;   /* [3*nodes] */
    int *surf_sadr;      /* [nsurf+1] */
    int *surf_seg;       /* [4*segments] */
    signed char *surf_seg_turned; /* [segments] 1: a solid's face turned by /SURF/PART to
                            point out of its solid (its element numbering points in) */
    int *surf_nid;       /* [nodes] the deck's id of each segment surface node (0: a box's
                            corner, rc_geom_box_corners), for messages and Inacti 1 */
    struct rc_segmesh *surf_mesh; /* [nsurf] adjacency and broad-phase grid (segsurf.h) */

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
    double *inter_etarget; /* restitution asked (TYPE6, POWER e_target) [-]; 0: none; Visc or C derived from it */
    double *inter_vimp;    /* impact speed of e_target (V_imp) [m/s]; 0: derived from the initial state */
    double *inter_fscalev; /* [N] */
    double *inter_ascalex; /* [m] */
    double *inter_fscaleld; /* [N] */
    double *inter_ascalef; /* [N] */
    double *inter_ascalev; /* [m/s] */
    int *inter_fct_ld, *inter_fct_dv, *inter_fct_df; /* table index or -1 */
    int *inter_fct_ul;   /* unload curve, table index or -1 */
    int *inter_iform;    /* 0 elastic, 1 elasto-plastic (unload curve), 2 decoupled hardening */
    int *inter_icor;     /* Icor: 1 = start on the unload curve (Iform 1) */
    int *inter_inacti;   /* 0 or 5 */
    double *inter_stiff; /* Stiff [N/m] */
    double *inter_fscaleul; /* [N] */
    int *inter_eadr;     /* [ninter] offset of the interface's own states */
    int *inter_ns;       /* [ninter] number of own states (2..RC_NS_MAX) */
    int *inter_hidx;     /* [ninter] index of F_h among them, -1 */
    int *inter_oidx;     /* [ninter] index of the Inacti offset, -1 */
    int *inter_dhidx;    /* [ninter] index of D_h (compile.c, hyst_state), -1 */
    int *inter_peidx;    /* [ninter] index of P_e, the effective penetration of a pair
                            with several contact points (rc_pair_multi), -1 */
    rc_fric *inter_fr;   /* [ninter] friction (friction.h); kind RC_FK_NONE: none */
    int *inter_orient;   /* [2*ninter] segment normals of surfaces a, b: TYPE6 IRS/IRm of
                            that surface: 0 as built (solid faces out), 1 reversed,
                            2 never reversed (solid faces as their element numbers them) */
    unsigned char *inter_oneway; /* [ninter] 1: a segments-segments pair whose contact points are the
                            nodes of a against b's segments only (an /INTER/TYPE7, model/type7.c);
                            0: node to segment both ways */
    unsigned char *inter_edges; /* [ninter] a box pair's points that act: 0 all; 1 the edge pairs
                            alone, its corners never touching (an /INTER/TYPE11); 2 the corners
                            alone, its edge pairs never touching (an /INTER/TYPE19 of Iedge 1,
                            the free edges of closed surfaces: none); model/type7.c */
    /* friction per contact point (a segment surface's nodes against a plane
     * or a box, docs/theory.md 2.7): point j of interface i has its own
     * states (inter_pst[i] of them, global frame [N]: F_t,j, or the filtered
     * force of the viscous form; F_t,j then its filtered force with the
     * incremental form and a filter) at state
     * inter_eadr[i] + inter_ns[i] + inter_pst[i] j, right after the interface's own
     * states, its stick/slip mode rc_data.pt_slip[inter_pbase[i] + j] and
     * its slip root (rc_root_count). inter_npt[i] = 0: none. */
    int npt;             /* points of all interfaces */
    int *state_pt;       /* [ny] the contact point (0..npt-1) a state belongs to, -1: none */
    int *inter_npt;      /* [ninter] points of interface i */
    int *inter_pst;      /* [ninter] states per point: 3 (F_t, or the filtered force of the viscous
                            form), 6 (incremental form with a filter: F_t, then the filtered force F_f) */
    int *inter_pbase;    /* [ninter] index of its first point */
    int64_t **inter_ptslot; /* [ninter] Jacobian slots of its points (jacpattern.c), NULL: none */
    char **inter_name;   /* [ninter] "/INTER/TYPE6/<id>" */
    rc_loc *inter_loc;   /* [ninter] header of the interface card, for messages */
    int *inter_law;      /* [ninter] normal law RC_LAW_TYPE6 / RC_LAW_POWER (power.h) */
    struct rc_power *inter_pw; /* [ninter] power-law parameters (power.h), law POWER */
    int probing;         /* 1 while the Jacobian pattern is probed (jacpattern.c): the
                            friction limit then takes the normal force with its sign,
                            so that the probe states, whose contacts may pull, see the
                            structure of a pressing contact (kernels.inc, type6) */
    unsigned char *inter_fast; /* [ninter] 1: evaluated in real arithmetic by the fast path
                            (engine/kernels/kernel_fast.inc: a centred sphere against a sphere or a
                            plane, no friction, no hysteresis state, no Inacti offset), set by
                            rc_model_compile (rc_fast_select); NULL or 0: the general kernel */

    /* the model's own scales (scales.c, docs/theory.md 7.1), per interface;
     * NAN when the model gives none (no gravity, no speed reaching it) */
    double *inter_pscale; /* penetration scale p_s [m] */
    double *inter_fscale; /* force scale F_L(p_s) [N] */
    double *inter_kscale; /* normal stiffness at p_s [N/m] */
    double *inter_vscale; /* contact speed scale p_s omega_s [m/s] */
    double *inter_mred;   /* reduced mass of the pair [kg] */
    double *inter_pweight; /* penetration under the weight of the lighter
                              free body, p_F (NAN: none) [m] */
    double *inter_pimpact; /* penetration of an impact at the speed scale,
                              p_E (NAN: none) [m] */
    double *inter_sband;  /* share band b of a pair with several contact points:
                             below P = b the points within b of the deepest share
                             the force (docs/theory.md 2.7) [m] */
    double *inter_perelax; /* relaxation rate kappa of P_e down to P [1/s]
                             (docs/theory.md 2.7; 0: none) */
    double *inter_hband;  /* band of the Stiff line's roots (Iform 1, 2): F_h and
                             F_L(P), F_U(P) are integrated to about this [N]
                             (rc_model_tolerances) */
    double *inter_mrest;  /* the mass the contact drives at t = 0: inter_mred, or
                             with the rotations at the single contact point of
                             free bodies (rc_point_mass); a derived restitution
                             uses it [kg] */

    /* state vector */
    int ny;
    double *atol;        /* [ny] absolute tolerances (units of each state) */
    char *ewt_rel;       /* [ny] 1: the weight has the relative part rtol |y_i|;
                            0: absolute only (positions and rotations under the
                            derived tolerances); NULL: all relative */
    int tol_auto;        /* bit mask of the tolerances derived from the model
                            (RC_TOL_AUTO_*), 0 when all are given */
    double escale;       /* energy scale of the model [J] */
    double vscale;       /* speed scale of the model [m/s] (0: none) */

    /* run and solver settings */
    double tend, dtout;  /* [s] */
    int ev_state;        /* /RUN Ev_state: 0 auto, 1 always, 2 never (rc_event_records) */
    int on_violation;    /* /RUN On_viol: a failed physics check 0, 1 stops the run, 2 warns (solver/guards.h) */
    char *start_note;    /* an overlap at t = 0 accepted by On_viol 2 (engine/analyses/start.c): its message; NULL: none */
    int nnote;           /* notices of the compiler (the /INTER/TYPE7 Inacti 1, 2 points left out:
                            engine/analyses/prepare.c), "FILE:LINE: ..." each */
    char **note;         /* [nnote] owned */
    int start_inter;     /* its interface */
    double start_energy, start_escale; /* its elastic energy and the scene's E_s [J] */
    double rtol;
    double atol_pos, atol_quat, atol_vel, atol_omega, atol_energy;
    int tol_floored;       /* bodies whose derived position tolerance was raised to RC_TOL_ULPS
                            * roundings of their contacts' coordinates */
    double tol_floor_pos;  /* the largest such floor [m] */
    int method;          /* /SOLVER Method: integration backend (src/solver/solver.h) */
    int preload;         /* /SOLVER Preload: 1: a dynamic run starts from the static equilibrium at t = 0 */
    rc_loc preload_loc;  /* the line of /SOLVER Preload (the deck's end without /SOLVER), for messages */
    int method_switch;   /* /SOLVER Switch: 1: the CVODE path switches to an explicit method and back (docs/theory.md 7.9) */
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

    /* body couplings: spring-dampers, catenaries (coupling.h) */
    struct rc_couplings *cpl;
    /* joints (joint.h), run by the IDA backend; NULL: none */
    struct rc_joints *jnt;
};

/* Which tolerances are derived from the model's scales (blank /SOLVER fields). */
enum { RC_TOL_AUTO_POS = 1, RC_TOL_AUTO_QUAT = 2, RC_TOL_AUTO_VEL = 4, RC_TOL_AUTO_OMEGA = 8, RC_TOL_AUTO_ENERGY = 16 };

/* ---- records, state names ------------------------------------------ */
/* Full-state records at events (docs/case-format.md, /RUN Ev_state): with
 * Ev_state 0, while the model has at most RC_EVREC_MAX_BODIES bodies. */
#define RC_EVREC_MAX_BODIES 100
static inline int rc_event_records(const rc_model *m)
{
    return m->ev_state == 1 || (m->ev_state == 0 && m->nbody <= RC_EVREC_MAX_BODIES);
}

/* Name of state i for messages: "/RBODY/3, velocity z [m/s]" (statename.c). */
void rc_state_name(const rc_model *m, int i, char *buf, size_t n);
/* The interface whose own or contact-point states hold state i, or -1. */
int rc_state_inter(const rc_model *m, int i);

/* ---- layout views (the engine's functions over a model are declared in
 *      the engine's headers: engine/assembly/assembly.h, ...) ---------- */
/* Root functions, in this order: RC_ROOTS_PER_INTER per interface; one slip
 * root per contact point with friction (inter_npt, at rc_root_point_base),
 * then one landing root per such point (its depth q_j below the level of the
 * shares, rising through 0 as it takes a share; at rc_root_land_base); the
 * contact couplings' faces (at rc_root_cpl_base; coupling_contact.h), then
 * RC_LIM_ROOTS per joint with stops (coupling.h), then one per spring with
 * rupture deformations (coupling.h, RC_SPR_BROKEN); last two per sensor
 * (rc_root_sens_base). */
static inline int rc_root_point_base(const rc_model *m) { return RC_ROOTS_PER_INTER * m->ninter; }
static inline int rc_root_land_base(const rc_model *m) { return RC_ROOTS_PER_INTER * m->ninter + m->npt; }
static inline int rc_root_cpl_base(const rc_model *m) { return RC_ROOTS_PER_INTER * m->ninter + 2 * m->npt; }
int rc_root_count(const rc_model *m); /* all of them (coupling_contact.c) */
int rc_root_sens_base(const rc_model *m); /* the sensors' roots, last (coupling_contact.c) */
/* Pose and velocity view of body b: pointer to its 13 values in y, the
 * fixed pose of a fixed body, or the ground pose for b = -1 (inline: the
 * interfaces' loops call it twice per interface and evaluation). */
static inline const double *rc_body_state(const rc_model *m, int b, const double *y)
{
    if (b < 0) return m->ground_y0;
    return m->body_yadr[b] >= 0 ? y + m->body_yadr[b] : m->body_y0 + RC_NB * b;
}
/* Surface s's reference point (a sphere's centre) is its body's reference
 * point: the offset is exactly 0. */
static inline int rc_surf_centred(const rc_model *m, int s)
{
    const double *c = m->surf_p + 3 * s;
    return c[0] == 0.0 && c[1] == 0.0 && c[2] == 0.0;
}
/* Interface i has nothing tangential: no friction law, no exact stick, no
 * friction work state. */
static inline int rc_inter_frictionless(const rc_model *m, int i)
{
    const rc_fric *fr = &m->inter_fr[i];
    return fr->kind == RC_FK_NONE && !fr->exact && fr->widx < 0;
}

/* The force band of interface i's friction tests [N]: the force tolerance
 * of F_t (rc_fric.fband, scales.c), at least RC_SLIP_BAND of the contact's
 * force scale (the viscous form has no F_t whose tolerance would carry it). */
static inline double rc_fric_band(const rc_model *m, int i)
{
    const double fsc = m->inter_fscale[i], b = m->inter_fr[i].fband, s = isfinite(fsc) ? RC_SLIP_BAND * fsc : 0.0;
    return b > s ? b : s;
}

/* The position tolerance of interface i [m]: its law's P_e, its Inacti 5
 * offset, or its bodies' positions (the larger). */
static inline double rc_inter_apos(const rc_model *m, int i)
{
    const int e = m->inter_eadr[i];
    if (m->inter_peidx[i] >= 0) return m->atol[e + m->inter_peidx[i]];
    if (m->inter_oidx[i] >= 0) return m->atol[e + m->inter_oidx[i]];
    double a = 0.0;
    for (int k = 0; k < 2; k++) {
        const int b = k ? m->inter_bb[i] : m->inter_ba[i];
        if (b >= 0 && m->body_yadr[b] >= 0 && m->atol[m->body_yadr[b]] > a) a = m->atol[m->body_yadr[b]];
    }
    return a > 0 ? a : m->atol_pos;
}

/* The slip speed band of interface i's friction tests [m/s]: the sliding
 * speed below which a slipping contact's v_t . e > 0 (its sliding along its
 * force) is rounding rather than a push, RC_SLIP_BAND of the contact's
 * speed scale, or the velocity tolerance without one. */
static inline double rc_slip_vband(const rc_model *m, int i)
{
    const double vs = m->inter_vscale[i];
    return isfinite(vs) && vs > 0 ? RC_SLIP_BAND * vs : m->atol_vel;
}

/* Interface i's normal law has no damping of any kind (TYPE6: Visc 0 and
 * no damping curve acting; the power law: C 0 and no damping curve, whose
 * RDF then scales nothing) (model/power.c). */
int rc_inter_undamped(const rc_model *m, int i);
/* ... and loses nothing at an impact either (restitution 1): undamped, no
 * hysteresis (TYPE6 Iform 0, or the power law), a single contact point
 * (the shares of several points relax P_e, which dissipates). */
int rc_inter_elastic(const rc_model *m, int i);
/* The stiffness of interface i's stiffest line [N/m]: the steeper of its
 * stiffness scale and, for TYPE6 Iform 1 and 2, its Stiff line (the
 * vibration of a contact resting on it). */
double rc_inter_k_stiff(const rc_model *m, int i);
/* Interface i's TYPE6 damping Visc against its stiffest line: the damping
 * ratio zeta = Visc / (2 sqrt(k m)) [-] of its closed contact, k =
 * rc_inter_k_stiff, m the mass it drives (inter_mrest), and that line's
 * period 2 pi sqrt(m / k) into *period [s]; NaN (period too) where
 * undamped, damped by a curve or the power law, or without a scale. */
double rc_inter_zeta_stiff(const rc_model *m, int i, double *period);

/* ---- compile (model/compile.c) ------------------------------------ */
/* The model of a case up to its state layout, without the scales,
 * tolerances and Jacobian pattern: those evaluate the kernels and follow in
 * rc_model_compile (engine/analyses/prepare.c). On failure *out stays NULL. */
rc_status rc_model_build(const rc_case *c, rc_model **out, rc_error *err);
/* What Inacti 1, 2 of the /INTER/TYPE7 cards leave out of their contacts
 * (found by the engine on a first build: engine/analyses/prepare.c): for
 * card i of c->type7, n[i] ascending ints at ids[i]: the secondary node
 * ids (Inacti 1) or the indices of the main segments in the list of its
 * main /SURF/SEG (Inacti 2). */
typedef struct rc_t7_drop {
    int **ids; /* [ntype7] */
    int *n;    /* [ntype7] */
} rc_t7_drop;
/* rc_model_build with those points or segments left out (drop NULL: none;
 * model/type7.c). */
rc_status rc_model_build_drop(const rc_case *c, const rc_t7_drop *drop, rc_model **out, rc_error *err);

/* ---- static analysis (model/static_scope.c) ---------------------- */
/* The first element of m that the static analysis (/SOLVER Method 3,
 * solver/static.c) does not support in this version: RC_EINPUT naming its
 * card (friction with no meaning at rest: viscous, step5, a law with no
 * coefficient at zero sliding speed; /IMPVEL along a skew axis or
 * starting later; a body released or an interface turned on by a sensor
 * found in the run); exact stick and the stick spring of
 * rc_static_friction_ok are in the scope; `how` says how Method 3 was
 * chosen. */
rc_status rc_static_scope(const rc_model *m, const char *how, rc_error *err);
/* The same, the message ending with `alt` as the way out instead of
 * "Method 1 or 2". */
rc_status rc_static_scope_alt(const rc_model *m, const char *how, const char *alt, rc_error *err);
/* What a preload (/SOLVER Preload 1, docs/theory.md 7.8 "Preload")
 * needs: the static analysis' scope, and free bodies at rest (zero initial
 * velocity and angular velocity): RC_EINPUT naming the card (the element
 * out of scope, or the /RBODY of a moving body); `how` says how the
 * preload was asked for. */
rc_status rc_preload_scope(const rc_model *m, const char *how, rc_error *err);
/* 1: friction fr is the incremental stick spring that the static
 * analysis' return mapping takes (TYPE6 Sfric, Fric, fct_IDff, fct_IDfv;
 * a /FRICTION law of Ifric 0 to 3 in the incremental form, any filter,
 * isotropic or orthotropic); 0 for exact stick, which the static analysis
 * takes by its own rows (rc_static_scope admits it). */
int rc_static_friction_ok(const rc_fric *fr);

/* ---- friction (model/friction.c) ------------------------------- */
struct rc_case;
/* Apply the /FRICTION cards to the interfaces between the parts they name
 * (after the TYPE6 interfaces are compiled, before the state layout). */
rc_status rc_friction_compile(const struct rc_case *c, rc_model *m, rc_error *err);
void rc_friction_print(const rc_model *m, int i, FILE *f);

/* ---- Jacobian pattern: built by probing (engine/analyses/jacpattern.c),
 *      read and released as model data (model/pattern.c) ---------------- */
/* CSC position of (row, col), -1 when the entry is not in the pattern. */
int64_t rc_jac_slot(const rc_model *m, int row, int col);
/* The position of (row, col) in a CSC pattern with sorted row indices, -1
 * when absent; the order of int64_t for qsort (pattern.c). */
int64_t rc_csc_slot(const int64_t *colptr, const int64_t *rowind, int64_t row, int64_t col);
int rc_cmp_i64(const void *a, const void *b);
/* The CSC pattern of n columns from entries keyed col * n + row (sorted and
 * made unique in place): colptr[n + 1] (zeroed by the caller) filled, the
 * row indices returned (malloc'd; NULL: out of memory), their count in *nnz. */
int64_t *rc_csc_from_keys(int64_t *key, int64_t nk, int64_t n, int64_t *colptr, int64_t *nnz);
void rc_jac_free(rc_model *m);

/* Append the notice s (malloc'ed; owned by m afterwards, freed on failure)
 * to the model's notices (rc_model_note). */
rc_status rc_model_add_note(rc_model *m, char *s, rc_error *err);

#endif
