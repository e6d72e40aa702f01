/*
 * The parsed case ("spec"): every card of the deck as read, with the
 * file:line of each card and of each data line, before any reference is
 * resolved. Filled by the case reader (src/case: reader.c, cards.c, cards_*.c), read by
 * the compiler (compile.c). Nothing here runs physics.
 *
 * Conventions
 *  - A field left blank takes the default documented in docs/case-format.md;
 *    the reader stores the default, so the compiler never sees "blank".
 *    Exception: integer references (function, surface, group ids) are 0 when
 *    blank, meaning "none".
 *  - Every card records `loc` (the card's header line) and, where the
 *    compiler may need to blame a particular field, the line of that field.
 *  - Strings are owned by the case and freed by rc_case_free.
 */
#ifndef RC_CASE_H
#define RC_CASE_H

#include "ricochet/ricochet.h"

/* Where something was read: file path (owned by rc_case.files) and line. */
typedef struct rc_loc {
    const char *file;
    int line;
} rc_loc;

/* "file:line: " of an rc_loc, for messages: printf(RC_LOCFMT "...", RC_LOC(l)). */
#define RC_LOCFMT "%s:%d: "
#define RC_LOC(l) (l).file, (l).line

/* l when it was recorded (file set), else `fallback`: for cases built by hand
 * without the lines of their fields. */
static inline rc_loc rc_loc_or(rc_loc l, rc_loc fallback) { return l.file ? l : fallback; }
/* Element k of an array of locations, or `fallback` when there is none. */
static inline rc_loc rc_loc_at(const rc_loc *a, int k, rc_loc fallback)
{
    return a ? rc_loc_or(a[k], fallback) : fallback;
}

/* /FUNCT/fct_ID: tabulated curve y(x), points in file order. */
typedef struct rc_case_funct {
    int id;
    char title[101];
    int npts;
    double *x, *y; /* [npts] */
    rc_loc loc;
} rc_case_funct;

/* /NODE: one node. */
typedef struct rc_case_node {
    int id;
    double x[3]; /* global coordinates [m] */
    rc_loc loc;
} rc_case_node;

/* /GRNOD/NODE/grnod_ID: a list of node ids. */
typedef struct rc_case_grnod {
    int id;
    char title[101];
    int n;
    int *nodes; /* [n] node ids */
    rc_loc loc;
    rc_loc *node_loc; /* [n] the line of each node id (NULL: not recorded) */
} rc_case_grnod;

/* /RBODY/rbody_ID (Radioss layout, formats 2017..2026). Every field is
 * kept; the model stage adds the mass of the mesh (model/massprop.c). */
typedef struct rc_case_rbody {
    int id;
    char title[101];
    int node_id;   /* main node                                         */
    int sens_id;   /* sensor (ricochet: none; warned)                   */
    int skew_id;   /* frame of Jxx..Jxz (0: global axes)                */
    int ispher;    /* 0..3 as Radioss (0 means 2)                       */
    double mass;   /* added mass at the main node [kg]                  */
    int grnod_id;  /* secondary nodes group (0: none)                   */
    int ikrem;     /* Radioss rigid-wall flag: read                     */
    int icog;      /* 0..4 (0 means 1)                                  */
    int surf_id;   /* envelope surface (ricochet: none; warned)         */
    double J[6];   /* added Jxx Jyy Jzz Jxy Jyz Jxz [kg m^2], skew axes */
    int ioptoff, iexpams, ifail; /* line 4: read                        */
    double fail[4];/* FN FT expN expT (Ifail = 1) [N] [N] [-] [-]       */
    rc_loc loc;
    rc_loc line_loc[5]; /* data lines 1..5 (file 0 when absent)         */
} rc_case_rbody;

/* /SURF/PLANE/surf_ID and /SURF/ELLIPS/surf_ID. */
typedef enum {
    RC_CASE_SURF_PLANE = 1, RC_CASE_SURF_ELLIPS = 2,
    RC_CASE_SURF_CYL = 3, RC_CASE_SURF_BOX = 4, /* ricochet cards (cards_surfaces.c) */
    RC_CASE_SURF_SEG = 5, RC_CASE_SURF_PART = 6 /* segment surfaces (model/segsurf.c) */
} rc_case_surf_kind;

typedef struct rc_case_surf {
    int id;
    char title[101];
    rc_case_surf_kind kind;
    /* PLANE: point M and point M1; outward normal from M towards M1.     */
    double m[3], m1[3];       /* [m] */
    /* PLANE of an /RWALL/PARAL (model/rwall.c): bounded to the
     * parallelogram of corner M and sides e1, e2 (0: unbounded) */
    int bounded;
    double e1[3], e2[3];      /* [m] */
    /* ELLIPS: centre, semi-axes, degree n.                              */
    int skew_id;              /* 0 only */
    int degree;               /* n, default 2 */
    double c[3];              /* centre [m] */
    double abc[3];            /* semi-axes a, b, c [m]; CYL: radius in abc[0];
                                 BOX: half-sizes along its axes u, v, w */
    /* CYL: axis vector; BOX: axis u (v in axis2, w = u x v)             */
    double axis[3], axis2[3];
    double length;            /* CYL: length of the cylindrical part [m] */
    int ends;                 /* CYL: 0 flat, 1 rounded (hemispherical caps) */
    int cmode;                /* CYL: contact point 0 mid-length, 1 deepest */
    /* ricochet extension: rigid body carrying the surface (0: fixed in
     * space). Read from the documented extension field of each card.   */
    int rbody_id;
    rc_loc loc;
    /* SEG: segments as written, 4 node ids each (node 4 = 0: a triangle),
     * their ids and lines; PART: the part ids and their lines. */
    int nseg;
    int *seg;                 /* [4*nseg] */
    int *seg_id;              /* [nseg] */
    rc_loc *seg_loc;          /* [nseg] */
    int npart;
    int *part;                /* [npart] */
    rc_loc *part_loc;         /* [npart] */
    rc_loc rbody_loc;         /* the line holding rbody_ID (the header's when absent) */
    /* SEG made by the compiler for a rigid wall (model/rwall.c): node ids
     * that are contact points alone, without segments (nseg = 0); not
     * owned by the case */
    int npoint;
    const int *point;         /* [npoint] */
} rc_case_surf;

/* /INTER/TYPE6/inter_ID: every field of the six data lines. */
typedef struct rc_case_type6 {
    int id;
    char title[101];
    int surf1, surf2;                         /* line 1 */
    double sfric, fric, gap, tstart, tstop;   /* line 2: [N] [-] [m] [s] [s] */
    int istick;                               /* line 3, ricochet: 1 exact stick (IDA constraint) */
    int irs, irm, inacti, fct_ff, fct_fv;     /* line 3 */
    double ascalef, ascalev;                  /* line 3: [N] [m/s] */
    int fct_ld, iform;                        /* line 4 */
    double ascalex, fscaleld;                 /* line 4: [m] [N] */
    int icor;                                 /* line 4 */
    int fct_ul;                               /* line 5 */
    double fric_s;                            /* line 5, ricochet: static coefficient of exact stick [-]; 0: Fric */
    double stiff, fscaleul;                   /* line 5: [N/m] [N] */
    double visc;                              /* line 6: [N s/m] */
    double e_target;                          /* line 6, ricochet: restitution asked [-]; 0: none */
    double v_imp;                             /* line 6, ricochet: impact speed of e_target [m/s]; 0: derived */
    int fct_dv, fct_df;                       /* line 6 */
    double fscalev;                           /* line 6: [N] */
    rc_loc loc;
    rc_loc line_loc[6];                       /* each data line */
    int sensor_id;                            /* line 1, ricochet: /SENSOR that activates the interface (0: none) */
    const char *name;                         /* the card its messages name: NULL for a /INTER/TYPE6
                                                 card ("/INTER/TYPE6/<id>"); the contact of a /RWALL
                                                 with a surface, made by the compiler (model/rwall.c),
                                                 or of an /INTER/TYPE7 (model/type7.c) */
    /* set only by the compiler for an /INTER/TYPE7 (model/type7.c) */
    int oneway;                               /* 1: the nodes of surf_ID1 against surf_ID2 only */
    int edges_only;                           /* two boxes: 1 the edge pairs only, no corner against a face
                                                 (/INTER/TYPE11); 2 the corners only, no edge pair
                                                 (/INTER/TYPE19 Iedge 1); model/type7.c */
    double vis_crit;                          /* > 0: Visc = vis_crit 2 sqrt(k m*) (k the load
                                                 curve's slope, m* the bodies' reduced mass) */
    int fric_id;                              /* > 0: the /FRICTION card that applies (fric_ID) */
} rc_case_type6;

/* /INTER/TYPE7/inter_ID (cards_interfaces.c): the nodes of grnd_IDs against
 * the main surface surf_IDm, one way (compiled as TYPE6 contacts of a
 * linear law by model/type7.c). The fields ricochet does not use are read
 * and checked, not kept. */
typedef struct rc_case_type7 {
    int id;
    char title[101];
    int grnod_id, surf_id;                    /* line 1: grnd_IDs, surf_IDm */
    int istf;                                 /* line 1: 0 (1000 read as 0): k = Stfac times the main
                                                 shells' stiffness E t / 2; 1: k = Stfac; 2-5: the main
                                                 and secondary shells' stiffnesses combined (mean, max,
                                                 min, series) */
    int igap;                                 /* line 1: 0 (1000 read as 0: the constant gap Gapmin); 1, 2:
                                                 the variable gap of the shells' thicknesses */
    double fscalegap, gapmax;                 /* line 2: Igap 2's scale [-] (0 read as 1) and bound [m] (0: none) */
    double stmin, stmax;                      /* line 3 [N/m]: the bounds of Istf 0, 2-5's stiffness (0: none) */
    double stfac, fric, gapmin, tstart, tstop; /* line 4: [N/m] (Istf 1) or [-] (Istf 0), [-] [m] [s] [s] */
    int inacti;                               /* line 5: 0, 5 or 6 (1000 read as 0; 6 compiled as 5) */
    double viss, visf;                        /* line 5: critical damping fractions [-] */
    int iform, sensor_id, fric_id;            /* line 6 */
    rc_loc loc;
    rc_loc line_loc[6];                       /* lines 1-6 (Radioss's lines without the curvature line) */
} rc_case_type7;

/* /INTER/TYPE24/inter_ID, /INTER/TYPE25/inter_ID, /INTER/TYPE11/inter_ID
 * and /INTER/TYPE19/inter_ID (cards_interfaces.c, all in c->type24, told
 * apart by `type`): penalty contact of two surfaces both ways (the nodes
 * of each against the segments of the other; TYPE11 the edges of two
 * lines, TYPE19 both), compiled as a two-way TYPE6 contact of a linear
 * law by model/type7.c. The fields ricochet does not use are read and
 * checked, not kept. */
typedef struct rc_case_type24 {
    int id;
    int type;                                 /* 24, 25, 11 or 19 (the card read into this struct) */
    char title[101];
    int surf1, surf2;                         /* line 1: surf_ID1, surf_ID2 (TYPE19 surf_IDs, surf_IDm; TYPE11: 0) */
    int line1, line2;                         /* TYPE11 line 1: line_IDs, line_IDm (/LINE ids); 0 otherwise */
    double gapmin;                            /* TYPE11, TYPE19: Gapmin [m] (the constant gap); 0 otherwise */
    int istf;                                 /* line 1: 0 (1000 read as 0): k = Stfac times the shells'
                                                 stiffness E t / 2; 1: k = Stfac; 2-5: the two surfaces'
                                                 shell stiffnesses combined (mean, max, min, series) */
    double stmin, stmax;                      /* line 3 [N/m]: the bounds of Istf 0, 2-5's stiffness (0: none) */
    double stfac, fric, tstart, tstop;        /* line 4: [N/m] (Istf 1) or [-] (Istf 0), [-] [s] [s] */
    int inacti;                               /* line 5: 0 or 5 (1000 and TYPE24/25's -1 read as 0), or
                                                 TYPE11/19's 6 (compiled as 5) */
    double viss;                              /* line 5: critical damping fraction [-] */
    int sensor_id, fric_id;                   /* line 6 */
    int iedge;                                /* TYPE25 line 1: 0 (1000 read as 0) or the edge option */
    rc_loc loc;
    rc_loc line_loc[6];                       /* lines 1-6 */
} rc_case_type24;

/* /SENSOR/TIME/sens_ID and /SENSOR/DIST/sens_ID (cards_rwall.c): a TIME
 * sensor is on from t = Tdelay; a DIST sensor triggers when the distance of
 * its two nodes rises above Dmax or falls below Dmin and is on Tdelay
 * later (for good: latched). /SENSOR/AND and /SENSOR/OR: on Tdelay after
 * both (either) of two other sensors are on. /SENSOR/NOT: on from Tdelay
 * while its input is off (off for good once the input is on); in[1] repeats
 * in[0]. /SENSOR/INTER: triggers when the contact of interface int_ID
 * closes (DIR blank, or FN with Fmax 0), or when its total normal force
 * rises above Fmax (DIR FN), and is on Tdelay later (latched). */
typedef enum {
    RC_SENS_TIME = 0,
    RC_SENS_DIST = 1,
    RC_SENS_AND = 2,
    RC_SENS_OR = 3,
    RC_SENS_NOT = 4,
    RC_SENS_INTER = 5
} rc_case_sensor_kind;

typedef struct rc_case_sensor {
    int id;
    char title[101];
    rc_case_sensor_kind kind;
    double tdelay;        /* [s], >= 0 */
    int node[2];          /* DIST: node_ID1, node_ID2 */
    double dmin, dmax;    /* DIST: [m], 0: no such bound */
    int in[2];            /* AND, OR: sens_ID1, sens_ID2; NOT: sens_ID1 twice */
    int inter_id;         /* INTER: int_ID (an /INTER card's id) */
    int dir;              /* INTER: 0 DIR blank (the contact closes), 1 FN (normal force) */
    double fmax;          /* INTER FN: [N], 0: the contact closing is the trigger */
    double tmin;          /* DIST, INTER FN with Fmax: [s], >= 0: how long the criterion
                             must hold before the sensor triggers */
    rc_loc loc;
    rc_loc line_loc;      /* the (first) data line */
    rc_loc line2_loc;     /* DIST: the nodes' line; AND, OR, NOT, INTER: line 2 */
} rc_case_sensor;

/* /RWALL/PLANE, /RWALL/CYL, /RWALL/SPHER, /RWALL/PARAL (cards_rwall.c): a
 * rigid wall acting on the nodes of grnd_ID1 minus those of grnd_ID2 (for
 * ricochet: on the surfaces of the bodies that own them, model/rwall.c). */
typedef enum { RC_RWALL_PLANE = 1, RC_RWALL_CYL = 2, RC_RWALL_SPHER = 3, RC_RWALL_PARAL = 4 } rc_case_rwall_kind;

typedef struct rc_case_rwall {
    int id;
    char title[101];
    rc_case_rwall_kind kind;
    int node_id;          /* moving wall's node (0: fixed wall): the wall translates with it */
    int slide;            /* 0 sliding (frictionless), 1 tied (refused), 2 Coulomb friction */
    int grnd1, grnd2;     /* nodes the wall acts on, nodes taken out (0: none) */
    int iform;            /* Radioss 2026: 0 kinematic, 1 penalty (ricochet: penalty either way) */
    double dsearch;       /* nodes within this distance of the wall at t = 0 are added [m]; 0: none */
    double fric;          /* Coulomb coefficient (Slide 2) [-] */
    double diameter;      /* CYL, SPHER: diameter [m] */
    double ffac;          /* friction filter factor (ifq) */
    int ifq;              /* friction filter flag (0 only) */
    double mass;          /* moving wall: its mass [kg] */
    double v0[3];         /* moving wall: its initial velocity [m/s] */
    double m[3];          /* point M: on the plane, on the axis, the centre [m]; a moving wall:
                             the node's position (set by the compiler) */
    double m1[3];         /* PLANE: M1 (normal M -> M1); CYL: M1 on the axis; PARAL: corner [m] */
    double m2[3];         /* PARAL: corner M2 [m] */
    rc_loc loc;
    rc_loc line_loc[5];   /* each data line (file NULL when absent) */
} rc_case_rwall;

/* /INIVEL/TRA and /INIVEL/ROT. */
typedef struct rc_case_inivel {
    int id;
    int rot;       /* 0: TRA (velocity [m/s]); 1: ROT (angular velocity [rad/s]) */
    double v[3];   /* global axes (rotated from the skew's at input) */
    double v_skew[3]; /* Vx Vy Vz as read (the skew's axes when skew_id) */
    int grnod_id;  /* nodes whose body gets the velocity */
    int skew_id;   /* 0: global axes; a /SKEW/FIX, /SKEW/MOV or /SKEW/MOV2
                    * (its axes at the nodes' initial positions) */
    rc_loc loc;
    rc_loc line_loc; /* the data line */
} rc_case_inivel;

/* /GRAV/grav_ID. Acceleration = Fscale * f(t / Ascale) along DIR. */
typedef struct rc_case_grav {
    int id;
    int fct_id;     /* 0: constant 1 */
    int dir;        /* 0, 1, 2 for X, Y, Z (of the skew when skew_id) */
    double u[3];    /* the unit direction in global axes (axis dir of the
                     * skew, or of the global frame) */
    int skew_id;    /* 0: global axes; a /SKEW/FIX */
    int sensor_id;  /* 0: none; a sensor known when compiling: the gravity
                     * acts from its time on, the function shifted by it */
    int grnod_id;   /* 0: all bodies */
    double ascale;  /* [s], default 1 */
    double fscale;  /* [m/s^2], default 1 */
    rc_loc loc;
    rc_loc line_loc; /* the data line */
} rc_case_grav;

/* /BCS/bcs_ID: Tx Ty Tz Rx Ry Rz flags (1 = fixed) on a node group. */
typedef struct rc_case_bcs {
    int id;
    int fix[6];
    int skew_id;
    int grnod_id;
    rc_loc loc;
    rc_loc line_loc; /* the data line */
} rc_case_bcs;

/* A /BCS holding one or two of Tx Ty Tz along a skew's axes (not global
 * components: the velocity along each held axis, model/imposed.h). */
static inline int rc_bcs_skewed_translations(const rc_case_bcs *b)
{
    const int n = (b->fix[0] == 1) + (b->fix[1] == 1) + (b->fix[2] == 1);
    return b->skew_id != 0 && n > 0 && n < 3;
}

/* /PART/part_ID (docs/case-format.md): Radioss's line 1 (prop_ID, mat_ID of
 * the part's elements); with ricochet's optional line 2, also a rigid body
 * or a named subset of its surfaces (for /FRICTION). */
typedef struct rc_case_part {
    int id;
    char title[101];
    int rbody_id;   /* body of the part (0: surfaces fixed in space)      */
    int nsurf;
    int *surf;      /* [nsurf] surface ids of the part; nsurf = 0: all the
                       body's surfaces                                    */
    rc_loc loc;
    rc_loc line_loc;  /* line 2: rbody_ID and the first surface ids       */
    int ext;          /* 1: the ricochet line 2 is present                */
    int prop_id, mat_id; /* Radioss line 1 (mesh parts)                  */
    rc_loc prop_loc;  /* line 1                                           */
    rc_loc *surf_loc; /* [nsurf] the line of each surface id (NULL: not recorded) */
} rc_case_part;

/* /GRPART/PART/grpart_ID: a list of part ids; /GRPART/GRPART/grpart_ID: a
 * union of part groups, expanded by the reader into the same list of part
 * ids once every card is read (each part once, in the order first met). */
typedef struct rc_case_grpart {
    int id;
    char title[101];
    int by_group;   /* 1: /GRPART/GRPART (the list below is then its parts) */
    int n;
    int *parts;     /* [n] */
    rc_loc loc;
    rc_loc *part_loc; /* [n] the line of each part id (NULL: not recorded) */
} rc_case_grpart;

/* /LINE/SURF/line_ID: the edges of a list of surfaces (the sides of
 * /INTER/TYPE11), cards_bodies.c. */
typedef struct rc_case_line {
    int id;
    char title[101];
    int n;
    int *surf;        /* [n] surface ids */
    rc_loc loc;
    rc_loc *surf_loc; /* [n] the line of each id */
} rc_case_line;

/* One coefficient set of /FRICTION (a direction of one pair, or the
 * defaults): C1..C6, Fric, VISF. */
typedef struct rc_case_fricset {
    double c[6];    /* C1..C6, units per Ifric (docs) */
    double fric;    /* Fric [-] */
    double visf;    /* VISF [-], critical damping ratio of Iform 1 */
} rc_case_fricset;

/* A part-pair line group of /FRICTION. */
typedef struct rc_case_fricpair {
    int grpart1, grpart2;   /* part group ids (0: none) */
    int part1, part2;       /* part ids (0: none) */
    int idir;               /* 0 isotropic, 1 orthotropic (set[1] used) */
    rc_case_fricset set[2]; /* direction 1, direction 2 */
    rc_loc loc;             /* first line of the group */
} rc_case_fricpair;

/* /FRICTION/fric_ID. */
typedef struct rc_case_friction {
    int id;
    char title[101];
    int ifric;      /* 0 Coulomb, 1 generalised viscous, 2 Darmstad, 3 Renard */
    int ifiltr;     /* 0..3 */
    double xfreq;   /* filter coefficient/frequency (docs) */
    int iform;      /* 1 viscous (0 means 1), 2 incremental stiffness, 3 exact stick (ricochet) */
    double dt_ref;  /* ricochet extension: reference step of Ifiltr 1, 2 [s] (0: none) */
    double area;    /* ricochet extension: contact area for the pressure [m^2] (0: default) */
    rc_case_fricset def;    /* default coefficients */
    int npair;
    rc_case_fricpair *pair; /* [npair] */
    rc_loc loc;
    rc_loc line_loc[3];     /* the three lines of the header part */
    char owner[64];         /* "" a /FRICTION card; else the interface card whose line 6 and
                             * law lines gave it ("/INTER/TYPE7/12"; id < 0, named by its fric_id) */
} rc_case_friction;

/* /FRIC_ORIENT/id: direction 1 of orthotropic friction per part / group. */
typedef struct rc_case_fricorient_item {
    int grpart_id, part_id;
    double v[3];    /* vector V, projected on the contact plane (the
                     * skew's X' axis when skew_id) */
    int skew_id;    /* 0: V as read; a /SKEW/FIX: V = its X' axis */
    double phi;     /* angle PHI from V about the normal [deg] */
    int iorth;      /* Radioss Iorth (0 or 1), read */
    rc_loc loc;
    rc_loc line_loc; /* its second line (VX VY VZ skew_ID PHI Iorth) */
} rc_case_fricorient_item;

typedef struct rc_case_fricorient {
    int id;
    char title[101];
    int n;
    rc_case_fricorient_item *item; /* [n] */
    rc_loc loc;
} rc_case_fricorient;

/* /RUN (ricochet): end time and output interval. */
typedef struct rc_case_run {
    int present;
    double tend;  /* [s] */
    double dtout; /* [s], default tend/100 */
    rc_loc loc;
    int ev_state; /* full-state records at events: 0 auto, 1 always, 2 never */
    int on_violation; /* a failed physics check: 0 default (1), 1 stop the run, 2 warn and go on */
} rc_case_run;

/* /SOLVER (ricochet): integrator settings. Defaults in docs. */
typedef struct rc_case_solver {
    int present;
    int method;        /* 0: automatic (default), 1: CVODE BDF, 2: IDA, 3: static analysis (KINSOL) */
    int max_order;     /* 1..5, default 5 */
    long max_steps;    /* per output interval, default 100000 */
    double rtol;       /* default 1e-6 */
    double atol_pos;   /* [m], default 1e-9 */
    double atol_quat;  /* [-], default 1e-9 */
    double atol_vel;   /* [m/s], default 1e-6 */
    double atol_omega; /* [rad/s], default 1e-6 */
    double atol_energy;/* [J], default 1e-6 */
    double hmax;       /* [s], 0: no limit */
    double h0;         /* [s], 0: CVODE's estimate */
    int preload;       /* 0: off (default), 1: start a dynamic run from the static equilibrium at t = 0 */
    rc_loc loc;
    rc_loc method_loc; /* the line of Method and Preload (the deck's end without /SOLVER) */
    int method_switch; /* 0: off (default), 1: automatic switching BDF <-> explicit (Method 1) */
} rc_case_solver;

/* The whole deck. Arrays grow as cards are read. */
struct rc_case {
    char *path;          /* main file as given */
    char title[101];     /* run name from /BEGIN (or empty) */
    char unit_mass[21], unit_length[21], unit_time[21]; /* from /BEGIN, "" if absent */
    char deck_unit[3][21]; /* /BEGIN's input units as named (mass, length, time); "" if absent */
    double deck_factor[3]; /* their values in kg, m, s; 0 if absent */
    unsigned long checksum; /* FNV-1a 64 of the main file's bytes */
    int invers;          /* Radioss input version from /BEGIN (e.g. 2022, 140, 90); 0: none */
    char *overrides;     /* the --set arguments applied, "ARG; ARG" as given
                            (rc_case_load_set); NULL: none */

    int nfiles; char **files; /* every file read (main + includes); rc_loc.file points here */
    unsigned long long *file_id; /* [4*nfiles] device, inode, size and modification time [ns] of each file as it was read
                                    (NULL in a case built by hand) */

    int nfunct;  rc_case_funct *funct;
    int nnode;   rc_case_node *node;
    int ngrnod;  rc_case_grnod *grnod;
    int nrbody;  rc_case_rbody *rbody;
    int nsurf;   rc_case_surf *surf;
    int ntype6;  rc_case_type6 *type6;
    int npower;  struct rc_case_power *power;   /* case_power.h */
    int ntype7;  rc_case_type7 *type7;
    int ntype24; rc_case_type24 *type24;
    int nrwall;  rc_case_rwall *rwall;
    int nsensor; rc_case_sensor *sensor;
    int nimpvel; struct rc_case_impvel *impvel; /* case_power.h */
    int ninivel; rc_case_inivel *inivel;
    int ngrav;   rc_case_grav *grav;
    int nbcs;    rc_case_bcs *bcs;
    int ncoupling; struct rc_case_coupling *coupling; /* case_coupling.h */
    int njoint;  struct rc_case_joint *joint;       /* case_joint.h */
    int npart;   rc_case_part *part;
    int ngrpart; rc_case_grpart *grpart;
    int nline;   rc_case_line *line;
    int nfriction; rc_case_friction *friction;
    int nfricorient; rc_case_fricorient *fricorient;
    struct rc_case_mesh *mesh; /* elements, /PROP, /MAT, /SKEW (case_mesh.h); NULL: none */
    rc_case_run run;
    rc_case_solver solver;

    rc_loc end; /* where the deck ends, the place of deck-level messages (no
                   /RUN, no /RBODY, nothing to integrate): the main file and its
                   /END line, or its last line (the #include line when /END is
                   in an included file) */
    int nwarnings; char **warnings; /* "file:line: ..." ignored-card warnings */
    struct rc_case_index *index; /* sorted ids for the look-ups (case/lookup.c); NULL: scan */
};

typedef struct rc_case_index rc_case_index;
/* Build (or rebuild) c->index, the sorted ids behind the look-ups below;
 * rc_case_load calls it. Without it, or after a count changed, the look-ups
 * scan the arrays (same answers, O(N) each). */
rc_status rc_case_index_build(rc_case *c, rc_error *err);
void rc_case_index_free(rc_case_index *x);
/* Index of the card with this id in its array (the first one), or -1
 * (case/lookup.c); O(log N) with the index. */
int rc_case_find_funct(const rc_case *c, int id);
int rc_case_find_node(const rc_case *c, int id);
int rc_case_find_grnod(const rc_case *c, int id);
int rc_case_find_rbody(const rc_case *c, int id);
int rc_case_find_surf(const rc_case *c, int id);
/* The card name of a surface kind (RC_CASE_SURF_*): "PLANE" .. "PART", "?" otherwise. */
const char *rc_case_surf_kind_name(int kind);
int rc_case_find_rwall(const rc_case *c, int id);  /* a linear scan */
int rc_case_find_sensor(const rc_case *c, int id); /* a linear scan */
int rc_case_find_part(const rc_case *c, int id);
int rc_case_find_grpart(const rc_case *c, int id);
/* Body carrying a node (its main node or in its secondary group), or -1. */
int rc_case_body_of_node(const rc_case *c, int node_id);
/* Reference from field `field` of `card` (read at `loc`) to a /FUNCT: *index
 * = its index (= the model's table index), or -1 when id = 0 and the
 * reference is optional; RC_EINPUT naming file:line, card and field when the
 * function does not exist (or is missing and required). */
rc_status rc_case_ref_funct(const rc_case *c, int id, int required, rc_loc loc, const char *card,
                            const char *field, int *index, rc_error *err);

#endif
