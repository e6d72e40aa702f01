/*
 * Output: netCDF-4 results file with CF-style metadata. The only module that
 * includes netCDF. The engine hands it plain arrays (rc_frame) at output
 * times and at events; it never sees the model or the solver.
 */
#ifndef RC_OUTPUT_H
#define RC_OUTPUT_H

#include "ricochet/ricochet.h"

typedef struct rc_output rc_output;

/* HDF5 under netCDF is not thread-safe (Debian builds it so): every netCDF
 * call of the library runs holding this one process-wide lock. The writer
 * (netcdf.c) and the export (vtk.c) take it themselves; a caller never
 * holds it across a callback. */
void rc_nc_lock(void);
void rc_nc_unlock(void);
/* Tests only: 1 makes the ParaView export write its binary blocks
 * byte-swapped, as on a big-endian host (vtk.c); 0 restores. */
void rc_vtk_test_force_swap(int on);
/* netCDF's version string ("4.9.0 of ..."), read under the lock. */
const char *rc_output_netcdf_version(void);

/* What the file describes; copied at open. */
typedef struct rc_output_meta {
    const char *title;        /* run title ("" allowed)                    */
    const char *case_path;    /* case file as given                        */
    unsigned long checksum;   /* FNV-1a 64 of the case file                */
    const char *unit_mass, *unit_length, *unit_time; /* from /BEGIN or ""  */
    const char *solver;       /* e.g. "CVODE BDF, Newton, KLU sparse"      */
    double rtol;              /* relative tolerance [-]                    */
    double atol_pos, atol_quat, atol_vel, atol_omega, atol_energy; /* abs tolerances */
    int nbody;
    const int *body_id;       /* [nbody] /RBODY ids                        */
    const int *body_fixed;    /* [nbody] 1: fixed (ground) body            */
    int ninter;
    const int *inter_id;      /* [ninter] /INTER ids                       */
    const char *const *inter_type; /* [ninter] e.g. "TYPE6"                */
    int nenergy;
    const char *const *energy_name;  /* [nenergy] variable names, e.g. "energy_kinetic" */
    const char *const *energy_long;  /* [nenergy] long names                */
    int ncoupling;
    const int *coupling_id;   /* [ncoupling] /COUPLING ids                 */
    const char *const *coupling_type; /* [ncoupling] "SPRING" or "CATENARY" */
    const char *event_records; /* global attribute event_records (NULL: none) */
    /* provenance: the files read (0: the case file, then its includes),
     * hashed with SHA-256 at open; NULL/0: the case_path alone */
    int nfile;
    const char *const *file;
    const char *overrides;    /* the --set arguments, "ARG; ARG" (NULL: none;
                                 global attribute overrides) */
    /* every solver setting */
    int max_order;            /* BDF order limit [-]                       */
    long max_steps;           /* steps between two output times [-]        */
    double hmax, h0;          /* step bounds, 0: CVODE's choice [s]         */
    double t_end, dt_out;     /* /RUN [s]                                  */
    const char *tol_derived;  /* which tolerances were derived from the
                                 model's scales ("" none)                  */
    const char *sampling_note; /* non-NULL: global attribute sampling_note */
    const char *tolerance_note; /* non-NULL, non-empty: global attribute
                                   tolerance_note (the position tolerance
                                   raised to the coordinates' rounding)   */
    double atol_pos_floor;     /* that raised tolerance, global attribute
                                  atol_position_floor (0: none) [m]      */
    const char *preload;       /* non-NULL: the run started from a static preload;
                                  global attribute preload (what was solved) */
    long preload_iters;        /* with preload: its Newton iterations (global
                                  attribute preload_newton_iters) [-] */
    /* surfaces: kind ("PLANE", "SPHERE", "CYLINDER", "BOX"), carrying body
     * index (-1: fixed in space), local point, local normal or axis,
     * radius, RC_OUT_SURF_NPARAM extra parameters (model.h surf_ext) */
    int nsurf;
    const int *surf_id;
    const char *const *surf_kind;
    const int *surf_body;
    const double *surf_point;  /* [nsurf*3] body frame [m]                 */
    const double *surf_normal; /* [nsurf*3] body frame [-]                 */
    const double *surf_radius; /* [nsurf] [m]                              */
    const double *surf_param;  /* [nsurf*RC_OUT_SURF_NPARAM]               */
    const int *inter_surf;     /* [ninter*2] surface indices of each interface */
    /* segment surfaces (kind "SEGMENTS"): nodes in the body frame, segments
     * of 4 local node indices; 0 segments: none in the file */
    int nseg_node, nseg;
    const int *surf_first_node, *surf_first_seg; /* [nsurf] */
    const double *seg_node;    /* [nseg_node*3] [m]                        */
    const int *seg_corner;     /* [nseg*4]                                 */
    /* joints (0: none, no joint variables in the file) */
    int njoint;
    const int *joint_id;       /* [njoint] /JOINT ids */
    const char *const *joint_type; /* [njoint] "SPHERICAL", "REVOLUTE", ... */
} rc_output_meta;

/* Extra parameters of a surface in the file (variable surface_parameters). */
#define RC_OUT_SURF_NPARAM 12

/* Interface modes as stored in the file (variable inter_mode). */
enum { RC_OUT_MODE_INACTIVE = 0, RC_OUT_MODE_OPEN = 1, RC_OUT_MODE_CLOSED = 2, RC_OUT_MODE_RELEASED = 3 };

/* One record. All pointers are non-NULL arrays of the sizes in the meta. */
typedef struct rc_frame {
    double t;                    /* [s]                                     */
    int at_event;                /* 1: written at an event                  */
    const double *body_pos;      /* [nbody*3] centre of mass, global [m]    */
    const double *body_quat;     /* [nbody*4] unit quaternion (w,x,y,z) body->global [-] */
    const double *body_vel;      /* [nbody*3] velocity of the CoM, global [m/s] */
    const double *body_omega;    /* [nbody*3] angular velocity, body frame [rad/s] */
    const double *inter_pen;     /* [ninter] max penetration P past the Gap [m] */
    const double *inter_fload;   /* [ninter] force from load/unload law [N] */
    const double *inter_fdamp;   /* [ninter] damping force [N]              */
    const double *inter_fnormal; /* [ninter] total normal force (>= 0) [N]  */
    const double *inter_point;   /* [ninter*3] contact point, global [m]    */
    const double *inter_normal;  /* [ninter*3] unit normal, global [-]      */
    const int *inter_mode;       /* [ninter] RC_OUT_MODE_*                  */
    const double *inter_ffric;   /* [ninter*3] friction force on the first body, global [N] */
    const double *inter_vslip;   /* [ninter] sliding speed [m/s]            */
    const int *inter_slip;       /* [ninter] 0 stick, 1 slip                */
    const double *energy;        /* [nenergy] [J]                           */
    const double *cpl_force;     /* [ncoupling] spring: f_e + f_damp (> 0 pulls
                                    the ends together); catenary: tension at end 1 [N] */
    const double *cpl_length;    /* [ncoupling] distance between the end points [m] */
    const double *cpl_f1;        /* [ncoupling*3] force on end 1, global [N] */
    const double *cpl_f2;        /* [ncoupling*3] force on end 2, global [N] */
    const double *cpl_lowest;    /* [ncoupling] catenary: height of its lowest
                                    point along -g (NaN for springs) [m] */
    /* joints (read only when the meta has njoint > 0) */
    const double *joint_force;   /* [njoint*3] reaction on the first body, global [N] */
    const double *joint_moment;  /* [njoint*3] its moment about the anchor, global [N m] */
    const double *joint_drift_pos; /* [njoint] position constraint residual [m] */
    const double *joint_drift_ang; /* [njoint] angle constraint residual [-] */
    const double *joint_work;    /* [1] work of the reactions [J] */
    const double *joint_stop_force;  /* [njoint] stop force along a prismatic joint's axis, on the first
                                        body, + along the axis [N]; 0 for other joints or no stop */
    const double *joint_stop_moment; /* [njoint] stop moment about a revolute joint's axis on the first
                                        body, + about the axis [N m]; 0 for other joints or no stop */
} rc_frame;

/* Create the file (overwrites). RC_EIO with the path and netCDF message. */
rc_status rc_output_open(rc_output **out, const char *path, const rc_output_meta *meta,
                         rc_error *err);
/* Append one record to the time series. Records and event rows are
 * buffered and written in blocks; rc_output_close writes what is left. */
rc_status rc_output_frame(rc_output *o, const rc_frame *f, rc_error *err);
/* Append one row to the events table: time [s], kind (e.g. "contact_close",
 * "contact_open", "inter_start", "inter_stop": the engine's names of its
 * event kinds), element (e.g. "/INTER/TYPE6/3"). */
rc_status rc_output_event(rc_output *o, double t, const char *kind, const char *element,
                          rc_error *err);
/* The same with the event's own values: values[0] penetration P of the
 * interface [m], values[1] its approach speed dP/dt [m/s], values[2] its
 * total normal force just after the event [N]; NULL: not an interface (NaN). */
rc_status rc_output_event_values(rc_output *o, double t, const char *kind, const char *element,
                                 const double values[3], rc_error *err);
/* The impacts table (rc_impact rows) and the persistent contacts table
 * (rc_contact rows), written at close; replace earlier tables. The rows
 * are copied. */
rc_status rc_output_impacts(rc_output *o, int n, const rc_impact *rows, int np, const rc_contact *pers,
                            rc_error *err);
/* The linear algebra of the run, written with the statistics at close:
 * KLU symbolic analyses, entries of the largest Newton matrix, entries of
 * the model's whole Jacobian pattern (-1: not known, not written). */
void rc_output_linalg(rc_output *o, long klu_analyses, long newton_nnz, long pattern_nnz);
/* A physics check that failed (docs/output-format.md, the violation table). */
typedef struct rc_violation {
    double t;           /* when it was found [s] */
    double t_from;      /* start of the interval it concerns (the earlier record) [s]; t for a state */
    char check[40];     /* energy_damping, energy_hysteresis, energy_friction, energy_coupling_damping,
                           mechanical_energy, energy_balance, penetration, sphere_centres, box_overlap,
                           support_beyond_edge, law_deficit, open_penetrating, entered_deep,
                           friction_limit, non_finite, start_overlap */
    char element[64];   /* "/INTER/TYPE6/3", "/RBODY/2", "/COUPLING/SPRING/4"; "" the whole model */
    double value;       /* what was found: a decrease or an excess [J], a penetration or a distance [m] */
    double limit;       /* what it was compared with, in the same unit */
    char message[600];
} rc_violation;

/* The physics checks of the run (docs/theory.md), written at close. */
typedef struct rc_out_physics {
    const char *summary;        /* global attribute physics_checks */
    const char *contacts;       /* global attribute contact_summary ("" none) */
    int stopped;                /* 1: a violation stopped the run (the status is the close's reason) */
    long total;                 /* violations found */
    int n;                      /* rows given (the first ones) */
    const rc_violation *row;    /* [n] */
    const int *inter_history;   /* [ninter] contact history (docs/output-format.md); NULL: none */
    double ratio[3];            /* largest mechanical energy excess, channel decrease and penetration,
                                   each over its tolerance or bound [-] */
} rc_out_physics;
/* Keep the physics checks' results for rc_output_close (copied). */
rc_status rc_output_physics(rc_output *o, const rc_out_physics *p, rc_error *err);

/* Write statistics and completion attributes, close, free. `complete` 0
 * marks the file incomplete with `reason`. o == NULL is a no-op. After a
 * failed write (here or earlier) the file is closed as far as HDF5 can, read
 * back from the disk, and RC_EIO says what it keeps (records, time reached,
 * event rows, its attributes as read) or that it did not read back and was
 * removed. */
rc_status rc_output_close(rc_output *o, const rc_stats *st, int complete, const char *reason,
                          rc_error *err);

#endif
