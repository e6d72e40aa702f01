/*
 * Output: the netCDF-4 results file (docs/output-format.md).
 *
 * Design choices:
 * - Every variable is described once, in the table `var_spec` below (name,
 *   type, dimensions, unit kind, long name, comment). Defining the file and
 *   writing a record are loops over that table, so a variable cannot end up
 *   without units or with a record slice that disagrees with its dimensions.
 * - Units follow the unit system declared in the case (/BEGIN). A component
 *   left undeclared counts as SI; with kg, m, s the derived units are written
 *   with their SI names (N, J), otherwise as UDUNITS products ("g mm ms-2").
 * - The file is marked complete="no", status="running" at open and only
 *   rc_output_close(complete = 1) turns it to "yes".
 * - Records and event rows are buffered in memory and written in blocks: one
 *   nc_put_vara per variable per block of up to RC_OUT_BLOCK_RECORDS records
 *   (fewer when a record is large: the buffer holds about
 *   RC_OUT_BLOCK_BYTES). A netCDF call per record and variable cost ~30 us
 *   of HDF5 bookkeeping, 100x the integration of a small model. The buffer
 *   is written when full, at close (also after a failed run, so the file
 *   keeps everything computed), and whenever RC_OUT_SYNC_SECONDS of wall
 *   time have passed since the last write, which is then synced to disk: a
 *   killed run loses at most that much wall time of results.
 * - Time-series variables are chunked along time with chunks of about
 *   RC_OUT_CHUNK_BYTES, at most one block, so a full block writes whole
 *   chunks; no fill values are written (every record is written).
 * - Every block written is synced at once, so the file on disk is whole
 *   after each block. Before a block is written, the free space of the file
 *   system is compared with an upper bound of what the block can take (each
 *   chunk it starts, at full size, plus HDF5 metadata) and a reserve for
 *   closing the file: when it does not fit, nothing more is written and the
 *   file is closed with what it has, marked incomplete. A full disk is thus
 *   met before HDF5 sees it: HDF5 cannot be shut down safely after a failed
 *   write (its exit-time clean-up crashes), so after any failed netCDF write
 *   the handle is abandoned and rc_output_abandoned() tells the program to
 *   end without that clean-up. The path is also checked to still name the
 *   file that was created (a removed or renamed directory is reported).
 * - A write that fails all the same (the file system filled by another
 *   program between the check and the write, a file size limit, a device
 *   error) leaves HDF5's handle unusable: the file is then closed as far as
 *   HDF5 can, and read back from its bytes on disk (read_back: a second,
 *   in-memory netCDF handle on a copy of the file read into memory, so that
 *   HDF5 cannot answer from the handle it still holds; in a child process,
 *   read_back_apart, because HDF5 can crash on the damaged file) to say
 *   exactly what it keeps; a file that does not read back is removed, and
 *   the message says so. Nothing is claimed of a file that was not read
 *   back.
 * - HDF5 under netCDF keeps library-wide state and Debian builds it without
 *   thread safety: every netCDF call of the library runs holding one
 *   process-wide lock (rc_nc_lock), so that threads running their own
 *   simulations, each writing its own file, never call it at once.
 */
#include "output/output.h"

#include "base/error.h"
#include "base/sha256.h"

#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <sys/wait.h>
#include <math.h>
#include <netcdf.h>
#include <netcdf_mem.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

/* Write and sync the buffered records after this much wall time [s]. */
#define RC_OUT_SYNC_SECONDS 1.0
/* Memory for the buffered records, all variables together [bytes]. */
#define RC_OUT_BLOCK_BYTES (4u << 20)
/* Most records in one block [records]. */
#define RC_OUT_BLOCK_RECORDS 8192
/* Target size of one chunk of a time-series variable [bytes]. */
#define RC_OUT_CHUNK_BYTES (1u << 20)
/* Most records in one chunk of a time-series variable [records]. */
#define RC_OUT_CHUNK_RECORDS 1024
/* Event rows buffered before a write, and rows in one chunk [rows]. */
#define RC_OUT_BLOCK_EVENTS 256
/* HDF5 metadata a block may add (chunk indexes, object headers, heaps):
 * a fixed part plus a part per variable [bytes]. */
#define RC_OUT_META_FIXED (64u << 10)
#define RC_OUT_META_PER_VAR (4u << 10)
/* The git commit of the sources, baked in by the Makefile. */
#ifndef RC_COMMIT
#define RC_COMMIT "unknown"
#endif
/* Length of a derived unit string [chars]. */
#define RC_OUT_UNIT_LEN 128

/* Dimensions. */
enum { D_TIME, D_BODY, D_INTER, D_VEC3, D_QUAT, D_EVENT, D_COUPLING, D_SURF, D_SPARAM, D_SIDE, D_SEGNODE, D_SEGMENT,
       D_CORNER, D_JOINT, D_COUNT };
static const char *const dim_name[D_COUNT] = {"time",     "body",    "inter",             "vec3", "quat",
                                              "event",    "coupling", "surface", "surface_parameter", "side",
                                              "segment_node", "segment", "corner", "joint"};
/* Origin of the CF time axis: simulated time 0 (a convention, not a date). */
#define RC_OUT_TIME_ORIGIN "1970-01-01 00:00:00"

/* Kinds of units; the strings are derived from the case's unit system. */
enum { U_ONE, U_TIME, U_LENGTH, U_VELOCITY, U_ANGVEL, U_FORCE, U_ENERGY, U_MOMENT, U_COUNT };

/* Fixed variables (energies are added per entry of the meta). */
enum {
    V_TIME, V_AT_EVENT,
    V_BODY_ID, V_BODY_FIXED, V_BODY_POS, V_BODY_QUAT, V_BODY_VEL, V_BODY_OMEGA,
    V_INTER_ID, V_INTER_TYPE, V_INTER_PEN, V_INTER_FLOAD, V_INTER_FDAMP, V_INTER_FNORMAL,
    V_INTER_POINT, V_INTER_NORMAL, V_INTER_MODE, V_INTER_FFRIC, V_INTER_VSLIP, V_INTER_SLIP,
    V_EVENT_TIME, V_EVENT_KIND, V_EVENT_ELEMENT, V_EVENT_PEN, V_EVENT_VN, V_EVENT_FN,
    V_CPL_ID, V_CPL_TYPE, V_CPL_FORCE, V_CPL_LENGTH, V_CPL_F1, V_CPL_F2, V_CPL_LOWEST,
    V_BODY_COORD, V_INTER_COORD, V_CPL_COORD,
    V_SURF_COORD, V_SURF_KIND, V_SURF_BODY, V_SURF_POINT, V_SURF_NORMAL, V_SURF_RADIUS, V_SURF_PARAM, V_INTER_SURF,
    V_SURF_NODE0, V_SURF_SEG0, V_SEG_NODE, V_SEG_CORNER,
    V_JOINT_COORD, V_JOINT_TYPE, V_JOINT_FORCE, V_JOINT_MOMENT, V_JOINT_DRIFT_POS, V_JOINT_DRIFT_ANG, V_JOINT_WORK,
    V_JOINT_STOP_FORCE, V_JOINT_STOP_MOMENT, V_COUNT
};

typedef struct var_spec {
    const char *name;
    nc_type type;
    int ndims;
    int dim[3];          /* D_* */
    int unit;            /* U_* */
    const char *long_name;
    const char *comment; /* NULL: none */
} var_spec;

static const var_spec var_table[V_COUNT] = {
    [V_TIME] = {"time", NC_DOUBLE, 1, {D_TIME}, U_TIME, "simulated time", NULL},
    [V_AT_EVENT] = {"at_event", NC_INT, 1, {D_TIME}, U_ONE,
                    "record written at an event", "1: at an event, 0: at an output time, 2: inside a contact "
                    "that the output interval cannot resolve (about 20 per contact)"},
    [V_BODY_ID] = {"body_id", NC_INT, 1, {D_BODY}, U_ONE, "rigid body identifier (/RBODY id)",
                   NULL},
    [V_BODY_FIXED] = {"body_fixed", NC_INT, 1, {D_BODY}, U_ONE, "body is fixed (ground)",
                      "1: fixed, 0: free"},
    [V_BODY_POS] = {"body_position", NC_DOUBLE, 3, {D_TIME, D_BODY, D_VEC3}, U_LENGTH,
                    "position of the centre of mass", "global frame"},
    [V_BODY_QUAT] = {"body_quaternion", NC_DOUBLE, 3, {D_TIME, D_BODY, D_QUAT}, U_ONE,
                     "orientation unit quaternion", "w,x,y,z, body to global"},
    [V_BODY_VEL] = {"body_velocity", NC_DOUBLE, 3, {D_TIME, D_BODY, D_VEC3}, U_VELOCITY,
                    "velocity of the centre of mass", "global frame"},
    [V_BODY_OMEGA] = {"body_angular_velocity", NC_DOUBLE, 3, {D_TIME, D_BODY, D_VEC3},
                      U_ANGVEL, "angular velocity", "body frame"},
    [V_INTER_ID] = {"inter_id", NC_INT, 1, {D_INTER}, U_ONE,
                    "contact interface identifier (/INTER id)", NULL},
    [V_INTER_TYPE] = {"inter_type", NC_STRING, 1, {D_INTER}, U_ONE, "contact interface type",
                      "e.g. TYPE6"},
    [V_INTER_PEN] = {"inter_penetration", NC_DOUBLE, 2, {D_TIME, D_INTER}, U_LENGTH,
                     "maximum penetration P past the gap", NULL},
    [V_INTER_FLOAD] = {"inter_force_load", NC_DOUBLE, 2, {D_TIME, D_INTER}, U_FORCE,
                       "normal force from the loading/unloading law", NULL},
    [V_INTER_FDAMP] = {"inter_force_damping", NC_DOUBLE, 2, {D_TIME, D_INTER}, U_FORCE,
                       "normal damping force", NULL},
    [V_INTER_FNORMAL] = {"inter_force_normal", NC_DOUBLE, 2, {D_TIME, D_INTER}, U_FORCE,
                         "total normal contact force", ">= 0"},
    [V_INTER_POINT] = {"inter_contact_point", NC_DOUBLE, 3, {D_TIME, D_INTER, D_VEC3},
                       U_LENGTH, "contact point", "global frame"},
    [V_INTER_NORMAL] = {"inter_normal", NC_DOUBLE, 3, {D_TIME, D_INTER, D_VEC3}, U_ONE,
                        "unit contact normal", "global frame"},
    [V_INTER_MODE] = {"inter_mode", NC_INT, 2, {D_TIME, D_INTER}, U_ONE, "contact mode", NULL},
    [V_INTER_FFRIC] = {"inter_force_friction", NC_DOUBLE, 3, {D_TIME, D_INTER, D_VEC3}, U_FORCE,
                       "friction force on the body of the first surface", "global frame, after the filter"},
    [V_INTER_VSLIP] = {"inter_slip_speed", NC_DOUBLE, 2, {D_TIME, D_INTER}, U_VELOCITY,
                       "sliding speed at the contact point", "0 while sticking"},
    [V_INTER_SLIP] = {"inter_slip", NC_INT, 2, {D_TIME, D_INTER}, U_ONE, "friction mode",
                      "0 stick (viscous law: below the limit), 1 slip (viscous law: saturated)"},
    [V_EVENT_TIME] = {"event_time", NC_DOUBLE, 1, {D_EVENT}, U_TIME, "time of the event",
                      NULL},
    [V_EVENT_KIND] = {"event_kind", NC_STRING, 1, {D_EVENT}, U_ONE, "kind of event",
                      "docs/output-format.md lists the kinds"},
    [V_EVENT_ELEMENT] = {"event_element", NC_STRING, 1, {D_EVENT}, U_ONE,
                         "element concerned by the event", "e.g. /INTER/TYPE6/3"},
    [V_EVENT_PEN] = {"event_penetration", NC_DOUBLE, 1, {D_EVENT}, U_LENGTH,
                     "penetration P of the event's interface at the event",
                     "NaN when the element is not an interface"},
    [V_EVENT_VN] = {"event_normal_speed", NC_DOUBLE, 1, {D_EVENT}, U_VELOCITY,
                    "normal approach speed dP/dt of the event's interface at the event",
                    "> 0 approaching; NaN when the element is not an interface"},
    [V_EVENT_FN] = {"event_force_normal", NC_DOUBLE, 1, {D_EVENT}, U_FORCE,
                    "total normal force of the event's interface just after the event",
                    "in the mode after the transition, >= 0; NaN when the element is not an interface"},
    [V_CPL_ID] = {"coupling_id", NC_INT, 1, {D_COUPLING}, U_ONE, "body coupling identifier (/COUPLING id)",
                  NULL},
    [V_CPL_TYPE] = {"coupling_type", NC_STRING, 1, {D_COUPLING}, U_ONE, "body coupling type",
                    "SPRING, CATENARY or CONTACT"},
    [V_CPL_FORCE] = {"coupling_force", NC_DOUBLE, 2, {D_TIME, D_COUPLING}, U_FORCE, "coupling force",
                     "spring: elastic + damping force along the line, > 0 pulls the ends together; "
                     "catenary: line tension at end 1; contact: sum of the faces' normal forces"},
    [V_CPL_LENGTH] = {"coupling_length", NC_DOUBLE, 2, {D_TIME, D_COUPLING}, U_LENGTH,
                      "distance between the end points of the coupling",
                      "contact: the smallest distance of a face to the opposing surface"},
    [V_CPL_F1] = {"coupling_force_end1", NC_DOUBLE, 3, {D_TIME, D_COUPLING, D_VEC3}, U_FORCE,
                  "force of the coupling on its end 1", "global frame"},
    [V_CPL_F2] = {"coupling_force_end2", NC_DOUBLE, 3, {D_TIME, D_COUPLING, D_VEC3}, U_FORCE,
                  "force of the coupling on its end 2", "global frame"},
    [V_CPL_LOWEST] = {"coupling_lowest", NC_DOUBLE, 2, {D_TIME, D_COUPLING}, U_LENGTH,
                      "height of the lowest point of a catenary line",
                      "along the upward direction -g, from the origin; ground contact of the line is not "
                      "modelled (docs/theory.md); NaN for springs"},
    /* coordinate variables: select by id (xarray: ds.sel(body=2)) */
    [V_BODY_COORD] = {"body", NC_INT, 1, {D_BODY}, U_ONE, "rigid body identifier (/RBODY id)",
                      "coordinate variable, same values as body_id"},
    [V_INTER_COORD] = {"inter", NC_INT, 1, {D_INTER}, U_ONE, "contact interface identifier (/INTER id)",
                       "coordinate variable, same values as inter_id"},
    [V_CPL_COORD] = {"coupling", NC_INT, 1, {D_COUPLING}, U_ONE, "body coupling identifier (/COUPLING id)",
                     "coordinate variable, same values as coupling_id"},
    /* surface geometry, in the frame of the carrying body */
    [V_SURF_COORD] = {"surface", NC_INT, 1, {D_SURF}, U_ONE, "surface identifier (/SURF id)",
                      "coordinate variable"},
    [V_SURF_KIND] = {"surface_kind", NC_STRING, 1, {D_SURF}, U_ONE, "kind of surface",
                     "PLANE, SPHERE, CYLINDER, BOX or SEGMENTS (a segment surface: segment_corners)"},
    [V_SURF_BODY] = {"surface_body", NC_INT, 1, {D_SURF}, U_ONE, "/RBODY id of the body carrying the surface",
                     "-1: fixed in space (global frame)"},
    [V_SURF_POINT] = {"surface_point", NC_DOUBLE, 2, {D_SURF, D_VEC3}, U_LENGTH,
                      "reference point of the surface",
                      "body frame, from the centre of mass: plane point, sphere centre, cylinder or box centre"},
    [V_SURF_NORMAL] = {"surface_normal", NC_DOUBLE, 2, {D_SURF, D_VEC3}, U_ONE,
                       "unit outward normal (plane) or axis (cylinder)", "body frame; 0 for spheres and boxes"},
    [V_SURF_RADIUS] = {"surface_radius", NC_DOUBLE, 1, {D_SURF}, U_LENGTH, "radius of a sphere or cylinder",
                       "0 for planes and boxes"},
    [V_SURF_PARAM] = {"surface_parameters", NC_DOUBLE, 2, {D_SURF, D_SPARAM}, U_ONE,
                      "extra parameters of cylinders and boxes",
                      "cylinder: [0] half-length [m], [1] ends (0 flat, 1 rounded), [2] contact point (0 "
                      "mid-length, 1 deepest); box: [0..2] half-sizes [m], [3..11] unit axes u, v, w (body "
                      "frame); 0 otherwise"},
    [V_INTER_SURF] = {"inter_surface", NC_INT, 2, {D_INTER, D_SIDE}, U_ONE,
                      "surface ids of the interface", "first and second surface (normal from the first to the second)"},
    /* segment surfaces (kind SEGMENTS): their nodes and segments */
    [V_SURF_NODE0] = {"surface_first_node", NC_INT, 1, {D_SURF}, U_ONE, "first segment_node of the surface",
                      "0-based; its nodes up to the next surface's first node; other kinds: no nodes"},
    [V_SURF_SEG0] = {"surface_first_segment", NC_INT, 1, {D_SURF}, U_ONE, "first segment of the surface",
                     "0-based; its segments up to the next surface's first segment"},
    [V_SEG_NODE] = {"segment_node_position", NC_DOUBLE, 2, {D_SEGNODE, D_VEC3}, U_LENGTH,
                    "node of a segment surface", "body frame of the carrying body, from its centre of mass"},
    [V_SEG_CORNER] = {"segment_corners", NC_INT, 2, {D_SEGMENT, D_CORNER}, U_ONE, "nodes of a segment",
                      "0-based, local to the surface (add surface_first_node); a triangle repeats its third node"},
    /* joints (IDA path) */
    [V_JOINT_COORD] = {"joint", NC_INT, 1, {D_JOINT}, U_ONE, "joint identifier (/JOINT id)", "coordinate variable"},
    [V_JOINT_TYPE] = {"joint_type", NC_STRING, 1, {D_JOINT}, U_ONE, "joint type",
                      "SPHERICAL, REVOLUTE, DISTANCE, FIXED or PRISMATIC"},
    [V_JOINT_FORCE] = {"joint_force", NC_DOUBLE, 3, {D_TIME, D_JOINT, D_VEC3}, U_FORCE,
                       "reaction force of the joint on its first body (rbody_ID1)",
                       "global frame; the second body (or the ground) takes the opposite force"},
    [V_JOINT_MOMENT] = {"joint_moment", NC_DOUBLE, 3, {D_TIME, D_JOINT, D_VEC3}, U_MOMENT,
                        "reaction moment of the joint on its first body, about its anchor point",
                        "global frame"},
    [V_JOINT_DRIFT_POS] = {"joint_drift_position", NC_DOUBLE, 2, {D_TIME, D_JOINT}, U_LENGTH,
                           "largest residual of the joint's position constraints",
                           "point, distance and slide rows: 0 on the exact solution"},
    [V_JOINT_DRIFT_ANG] = {"joint_drift_angle", NC_DOUBLE, 2, {D_TIME, D_JOINT}, U_ONE,
                           "largest residual of the joint's angle constraints",
                           "dot products of axes that stay normal (radians for small values); 0 on the exact "
                           "solution"},
    [V_JOINT_WORK] = {"joint_work", NC_DOUBLE, 1, {D_TIME}, U_ENERGY, "work done by the joint reactions",
                      "integral of the reactions' power; 0 for ideal joints (not part of energy_total)"},
    [V_JOINT_STOP_FORCE] = {"joint_stop_force", NC_DOUBLE, 2, {D_TIME, D_JOINT}, U_FORCE,
                            "force of the stops of a prismatic joint on its first body, along the axis",
                            "positive along +axis (pushing the slide back from the lower stop); 0 for other "
                            "joints, within the stops, or without stops; their work is in energy_coupling_*"},
    [V_JOINT_STOP_MOMENT] = {"joint_stop_moment", NC_DOUBLE, 2, {D_TIME, D_JOINT}, U_MOMENT,
                             "moment of the stops of a revolute joint on its first body, about the axis",
                             "positive about +axis (turning back from the lower stop); 0 for other joints, "
                             "within the stops, or without stops; their work is in energy_coupling_*"},
};

/* A column of the impacts and persistent contacts tables: one variable on
 * the table's dimension (the first column an int, the others double). */
typedef struct table_col {
    const char *name;
    int unit; /* U_* */
    const char *long_name;
    const char *comment;
} table_col;

/* Impacts table (dimension impact), defined and written at close. */
enum { I_INTER, I_CLOSE, I_OPEN, I_DURATION, I_PEN, I_TPEN, I_FN, I_TFN, I_VIN, I_VOUT, I_COR, I_ELOST, I_COUNT };
static const table_col impact_table[I_COUNT] = {
    [I_INTER] = {"impact_inter", U_ONE, "contact interface of the impact (/INTER id)", NULL},
    [I_CLOSE] = {"impact_close_time", U_TIME, "time the contact closes", "event contact_close"},
    [I_OPEN] = {"impact_open_time", U_TIME, "time the normal force stops acting for the last time",
                "contact_open (released) or contact_separate; NaN: still acting at the end of the run"},
    [I_DURATION] = {"impact_duration", U_TIME, "contact duration (open time - close time)", NULL},
    [I_PEN] = {"impact_max_penetration", U_LENGTH, "maximum penetration P during the impact",
               "tracked at every integrator step (interpolant sampled at 4 points per step)"},
    [I_TPEN] = {"impact_max_penetration_time", U_TIME, "time of the maximum penetration", NULL},
    [I_FN] = {"impact_peak_force", U_FORCE, "peak total normal force during the impact",
              "tracked at every integrator step (interpolant sampled at 4 points per step)"},
    [I_TFN] = {"impact_peak_force_time", U_TIME, "time of the peak normal force", NULL},
    [I_VIN] = {"impact_speed_in", U_VELOCITY, "approach speed dP/dt when the contact closes", NULL},
    [I_VOUT] = {"impact_speed_out", U_VELOCITY, "separation speed -dP/dt when P returns to 0",
                "NaN: not separated by the end of the run"},
    [I_COR] = {"impact_restitution", U_ONE, "coefficient of restitution speed_out / speed_in", NULL},
    [I_ELOST] = {"impact_energy_lost", U_ENERGY, "energy dissipated in the impact",
                 "contact damping + hysteresis + friction dissipation from closing to separation"},
};

/* Persistent contacts table (dimension persistent), defined and written at
 * close. */
enum { P_INTER, P_CLOSE, P_OPEN, P_DURATION, P_FN, P_FMEAN, P_PEN, P_SLIP, P_COUNT };
static const table_col persistent_table[P_COUNT] = {
    [P_INTER] = {"persistent_inter", U_ONE, "contact interface of the persistent contact (/INTER id)", NULL},
    [P_CLOSE] = {"persistent_close_time", U_TIME, "time the contact closes", "0: closed from the start"},
    [P_OPEN] = {"persistent_open_time", U_TIME, "time the normal force stops acting for the last time",
                "NaN: still closed at the end of the run"},
    [P_DURATION] = {"persistent_duration", U_TIME,
                    "contact duration (open time, or the end of the run when still closed, - close time)", NULL},
    [P_FN] = {"persistent_peak_force", U_FORCE, "peak total normal force during the contact",
              "tracked at every integrator step"},
    [P_FMEAN] = {"persistent_mean_force", U_FORCE, "time average of the total normal force over the duration",
                 "trapezoidal rule on the integrator's step ends and events"},
    [P_PEN] = {"persistent_max_penetration", U_LENGTH, "maximum penetration P during the contact", NULL},
    [P_SLIP] = {"persistent_slip_distance", U_LENGTH,
                "slip distance: integral of the tangential relative speed at the contact point over the closed time",
                "trapezoidal rule on the integrator's step ends and events; with or without friction"},
};

struct rc_output {
    int ncid;
    char *path;           /* copy, for messages */
    size_t dimlen[D_COUNT]; /* fixed lengths; 1 for the unlimited ones (one record) */
    int dimid[D_COUNT];
    int var[V_COUNT];     /* varids; -1 when not defined (no interfaces) */
    int nenergy;
    int *var_energy;      /* [nenergy] varids */
    size_t nrec;          /* records written to the file */
    size_t nevent;        /* event rows written to the file */
    char unit[U_COUNT][RC_OUT_UNIT_LEN];
    /* the buffer: records nrec.. and event rows nevent.. not yet written */
    size_t block;         /* records per block [records] */
    size_t nbuf;          /* records in the buffer */
    size_t rec_size[V_COUNT]; /* bytes of one record of each time series; 0: none */
    unsigned char *buf[V_COUNT]; /* [block * rec_size[v]] */
    double *ebuf;         /* [nenergy * block] energies, entry k at k * block */
    size_t nevbuf;        /* event rows in the buffer */
    double *ev_num;       /* [4 * RC_OUT_BLOCK_EVENTS] time, P, dP/dt, F_n, by column */
    char *ev_str[2][RC_OUT_BLOCK_EVENTS]; /* kind, element (copies) */
    double last_sync;     /* wall time of the last write to disk [s] */
    size_t chunk_rec[V_COUNT]; /* rows per chunk of each time series and event variable */
    size_t echunk;        /* records per chunk of the energies */
    size_t nvars;         /* variables in the file */
    dev_t dev;            /* the file created (device, inode) */
    ino_t ino;
    int stopped;          /* no room for the next block: nothing more written, the file is whole */
    int nimpact;          /* impacts table (rc_output_impacts), written at close */
    rc_impact *impact;
    int npersist;         /* persistent contacts table, written at close */
    rc_contact *persist;
    int broken;           /* a netCDF write failed: the handle is unusable */
    char fail[2048];      /* the first failed write's message (broken) */
    long linalg[3];       /* rc_output_linalg: analyses, Newton entries, pattern entries; -1 unknown */
    /* the physics checks (rc_output_physics), written at close */
    int phys_set, phys_stopped, phys_n;
    long phys_total;
    char *phys_summary, *phys_contacts;
    rc_violation *phys_row;
    int *phys_hist;        /* [ninter] or NULL */
    double phys_ratio[3];
};

/* ---- One lock for every netCDF call --------------------------------------- */

static pthread_mutex_t nc_mutex = PTHREAD_MUTEX_INITIALIZER;

void rc_nc_lock(void) { pthread_mutex_lock(&nc_mutex); }

void rc_nc_unlock(void) { pthread_mutex_unlock(&nc_mutex); }

/* The same lock for programs that call netCDF themselves in threads while
 * runs write (public: include/ricochet/ricochet.h). */
void rc_netcdf_lock(void) { rc_nc_lock(); }

void rc_netcdf_unlock(void) { rc_nc_unlock(); }

const char *rc_output_netcdf_version(void)
{
    rc_nc_lock();
    const char *v = nc_inq_libvers();
    rc_nc_unlock();
    return v;
}

/* Set when HDF5 could not close a file after a failed write: it cannot be
 * shut down safely then. Written and read under the lock. */
static int output_abandoned;

int rc_output_abandoned(void)
{
    rc_nc_lock();
    const int a = output_abandoned;
    rc_nc_unlock();
    return a;
}

/* ---- Error reporting --------------------------------------------------- */

/* Record an RC_EIO "path: what: netCDF message" raised at `line` of `func`. */
static rc_status nc_fail(rc_error *err, int line, const char *func, const char *path, int st,
                         const char *fmt, ...) __attribute__((format(printf, 6, 7)));
static rc_status nc_fail(rc_error *err, int line, const char *func, const char *path, int st,
                         const char *fmt, ...)
{
    char what[1536];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return rc_error_set(err, RC_EIO, __FILE__, line, func, "%s: %s: %s", path, what,
                        nc_strerror(st));
}

/* Run a netCDF call; on failure return RC_EIO from the calling function,
 * which must have `rc_error *err` in scope. */
#define NC_TRY(path, call, ...)                                                              \
    do {                                                                                     \
        int nc_st_ = (call);                                                                 \
        if (nc_st_ != NC_NOERR)                                                              \
            return nc_fail(err, __LINE__, __func__, (path), nc_st_, __VA_ARGS__);            \
    } while (0)

/* A C string never NULL. */
static const char *str_or_empty(const char *s) { return s ? s : ""; }

/* ---- Definition -------------------------------------------------------- */

/* Write a text attribute (varid NC_GLOBAL for a global one). */
static rc_status put_text(const rc_output *o, int varid, const char *name, const char *value,
                          rc_error *err)
{
    const char *v = str_or_empty(value);
    NC_TRY(o->path, nc_put_att_text(o->ncid, varid, name, strlen(v), v),
           "writing attribute %s", name);
    return RC_OK;
}

/* Write a double global attribute. */
static rc_status put_double(const rc_output *o, const char *name, double value, rc_error *err)
{
    NC_TRY(o->path, nc_put_att_double(o->ncid, NC_GLOBAL, name, NC_DOUBLE, 1, &value),
           "writing attribute %s", name);
    return RC_OK;
}

/* Write a 64-bit integer global attribute. */
static rc_status put_int64(const rc_output *o, const char *name, long value, rc_error *err)
{
    long long v = value;
    NC_TRY(o->path, nc_put_att_longlong(o->ncid, NC_GLOBAL, name, NC_INT64, 1, &v),
           "writing attribute %s", name);
    return RC_OK;
}

/* Derive the unit strings from the declared unit system (empty = SI). */
static void derive_units(rc_output *o, const rc_output_meta *meta)
{
    const char *m = *str_or_empty(meta->unit_mass) ? meta->unit_mass : "kg";
    const char *l = *str_or_empty(meta->unit_length) ? meta->unit_length : "m";
    const char *t = *str_or_empty(meta->unit_time) ? meta->unit_time : "s";
    int si = !strcmp(m, "kg") && !strcmp(l, "m") && !strcmp(t, "s");
    snprintf(o->unit[U_ONE], RC_OUT_UNIT_LEN, "1");
    snprintf(o->unit[U_TIME], RC_OUT_UNIT_LEN, "%s", t);
    snprintf(o->unit[U_LENGTH], RC_OUT_UNIT_LEN, "%s", l);
    snprintf(o->unit[U_VELOCITY], RC_OUT_UNIT_LEN, "%s %s-1", l, t);
    snprintf(o->unit[U_ANGVEL], RC_OUT_UNIT_LEN, "rad %s-1", t);
    if (si) {
        snprintf(o->unit[U_FORCE], RC_OUT_UNIT_LEN, "N");
        snprintf(o->unit[U_ENERGY], RC_OUT_UNIT_LEN, "J");
        snprintf(o->unit[U_MOMENT], RC_OUT_UNIT_LEN, "N m");
    } else {
        snprintf(o->unit[U_FORCE], RC_OUT_UNIT_LEN, "%s %s %s-2", m, l, t);
        snprintf(o->unit[U_ENERGY], RC_OUT_UNIT_LEN, "%s %s2 %s-2", m, l, t);
        snprintf(o->unit[U_MOMENT], RC_OUT_UNIT_LEN, "%s %s2 %s-2", m, l, t);
    }
}

/* Define one variable with its units and long name; time series and the
 * events table are chunked along their unlimited dimension. */
static rc_status def_var(rc_output *o, const char *name, nc_type type, int ndims,
                         const int *dim, const char *units, const char *long_name, int *varid,
                         size_t *chunk_rows, rc_error *err)
{
    o->nvars++;
    int dimids[3];
    size_t chunk[3];
    size_t elem = type == NC_DOUBLE ? sizeof(double) : type == NC_INT ? sizeof(int)
                                                                       : sizeof(char *);
    size_t per_rec = elem;
    for (int i = 0; i < ndims; i++) {
        dimids[i] = o->dimid[dim[i]];
        chunk[i] = o->dimlen[dim[i]];
        per_rec *= o->dimlen[dim[i]];
    }
    NC_TRY(o->path, nc_def_var(o->ncid, name, type, ndims, dimids, varid),
           "defining variable %s", name);
    /* chunk of ~RC_OUT_CHUNK_BYTES along the unlimited dimension, at most
     * one block; every record is written, so no fill values */
    if (dim[0] == D_TIME || dim[0] == D_EVENT) {
        size_t n = RC_OUT_CHUNK_BYTES / per_rec;
        size_t cap = dim[0] == D_TIME ? RC_OUT_CHUNK_RECORDS : RC_OUT_BLOCK_EVENTS;
        chunk[0] = n < 1 ? 1 : n > cap ? cap : n;
        *chunk_rows = chunk[0];
        NC_TRY(o->path, nc_def_var_chunking(o->ncid, *varid, NC_CHUNKED, chunk),
               "setting chunks of variable %s", name);
        if (type != NC_STRING)
            NC_TRY(o->path, nc_def_var_fill(o->ncid, *varid, NC_NOFILL, NULL),
                   "setting no fill for variable %s", name);
    }
    rc_status rc = put_text(o, *varid, "units", units, err);
    if (rc == RC_OK) rc = put_text(o, *varid, "long_name", long_name, err);
    return rc;
}

/* Does variable `v` use the dimension `d`? */
static int var_uses_dim(int v, int d)
{
    for (int i = 0; i < var_table[v].ndims; i++)
        if (var_table[v].dim[i] == d) return 1;
    return 0;
}

/* Is variable `v` left out of the file (a dimension of length 0)? */
static int var_skipped(const rc_output_meta *meta, int v)
{
    return (meta->ninter == 0 && (var_uses_dim(v, D_INTER) || var_uses_dim(v, D_SIDE))) ||
           (meta->ncoupling == 0 && var_uses_dim(v, D_COUPLING)) || (meta->nsurf == 0 && var_uses_dim(v, D_SURF)) ||
           (meta->nseg == 0 && (v == V_SURF_NODE0 || v == V_SURF_SEG0 || var_uses_dim(v, D_SEGNODE) ||
                                var_uses_dim(v, D_SEGMENT))) ||
           (meta->njoint == 0 && (var_uses_dim(v, D_JOINT) || v == V_JOINT_WORK));
}

/* Define the dimensions, the fixed variables with their attributes, and one
 * variable per energy entry. Interface variables only if ninter > 0. */
static rc_status define_vars(rc_output *o, const rc_output_meta *meta, rc_error *err)
{
    rc_status rc = RC_OK;
    /* dimensions */
    for (int d = 0; d < D_COUNT; d++) {
        if (((d == D_INTER || d == D_SIDE) && meta->ninter == 0) || (d == D_COUPLING && meta->ncoupling == 0) ||
            ((d == D_SURF || d == D_SPARAM) && meta->nsurf == 0) ||
            ((d == D_SEGNODE || d == D_SEGMENT || d == D_CORNER) && meta->nseg == 0) || (d == D_JOINT && meta->njoint == 0))
            continue;
        size_t len = (d == D_TIME || d == D_EVENT) ? NC_UNLIMITED : o->dimlen[d];
        NC_TRY(o->path, nc_def_dim(o->ncid, dim_name[d], len, &o->dimid[d]),
               "defining dimension %s", dim_name[d]);
    }
    /* fixed variables from the table */
    for (int v = 0; v < V_COUNT; v++) {
        const var_spec *s = &var_table[v];
        o->var[v] = -1;
        if (var_skipped(meta, v)) continue;
        rc = def_var(o, s->name, s->type, s->ndims, s->dim, o->unit[s->unit], s->long_name,
                     &o->var[v], &o->chunk_rec[v], err);
        if (rc == RC_OK && s->comment) rc = put_text(o, o->var[v], "comment", s->comment, err);
        if (rc != RC_OK) return rc;
    }
    /* CF time axis: a reference time is required; simulated time 0 is put
     * at RC_OUT_TIME_ORIGIN (proleptic Gregorian), so CF tools decode it as
     * dates from there while the stored values stay seconds since the start */
    {
        char tu[RC_OUT_UNIT_LEN + 64];
        snprintf(tu, sizeof tu, "%s since %s", !strcmp(o->unit[U_TIME], "s") ? "seconds" : o->unit[U_TIME],
                 RC_OUT_TIME_ORIGIN);
        rc = put_text(o, o->var[V_TIME], "units", tu, err);
    }
    if (rc == RC_OK) rc = put_text(o, o->var[V_TIME], "calendar", "proleptic_gregorian", err);
    if (rc == RC_OK)
        rc = put_text(o, o->var[V_TIME], "comment",
                      "simulated time from the start of the run; the reference date " RC_OUT_TIME_ORIGIN
                      " is a convention marking t = 0 (values are seconds since the start; xarray: "
                      "decode_times=False keeps them as seconds)", err);
    /* CF extras: standard name of time, flags of the contact mode */
    if (rc == RC_OK) rc = put_text(o, o->var[V_TIME], "standard_name", "time", err);
    if (rc == RC_OK) rc = put_text(o, o->var[V_TIME], "axis", "T", err);
    if (rc != RC_OK) return rc;
    if (o->var[V_INTER_MODE] >= 0) {
        static const int flags[4] = {RC_OUT_MODE_INACTIVE, RC_OUT_MODE_OPEN, RC_OUT_MODE_CLOSED,
                                     RC_OUT_MODE_RELEASED};
        NC_TRY(o->path,
               nc_put_att_int(o->ncid, o->var[V_INTER_MODE], "flag_values", NC_INT, 4, flags),
               "writing attribute flag_values of inter_mode");
        rc = put_text(o, o->var[V_INTER_MODE], "flag_meanings", "inactive open closed released", err);
        if (rc != RC_OK) return rc;
    }
    /* energy ledger: one time series per entry */
    static const int time_dim[1] = {D_TIME};
    for (int k = 0; k < meta->nenergy; k++) {
        rc = def_var(o, str_or_empty(meta->energy_name[k]), NC_DOUBLE, 1, time_dim,
                     o->unit[U_ENERGY], str_or_empty(meta->energy_long[k]), &o->var_energy[k],
                     &o->echunk, err);
        if (rc != RC_OK) return rc;
    }
    return RC_OK;
}

/* The command line of this process (/proc/self/cmdline, arguments joined
 * by spaces, quoted when they hold a space); "unknown" when unreadable. */
static void command_line(char *buf, size_t n)
{
    snprintf(buf, n, "unknown");
    FILE *f = fopen("/proc/self/cmdline", "rb");
    if (!f) return;
    char raw[4096];
    size_t len = fread(raw, 1, sizeof raw - 1, f);
    fclose(f);
    if (len == 0) return;
    raw[len] = '\0';
    size_t k = 0, w = 0;
    buf[0] = '\0';
    while (k < len && w + 1 < n) {
        const char *arg = raw + k;
        const int q = strchr(arg, ' ') != NULL || *arg == '\0';
        w += (size_t)snprintf(buf + w, n - w, "%s%s%s%s", w ? " " : "", q ? "'" : "", arg, q ? "'" : "");
        k += strlen(arg) + 1;
    }
}

/* Provenance: command line, version, commit, and the SHA-256 of every input
 * file as lines "<sha256>  <path>" (the format of sha256sum -c). */
static rc_status define_provenance(rc_output *o, const rc_output_meta *meta, rc_error *err)
{
    char cmd[4096];
    command_line(cmd, sizeof cmd);
    rc_status rc = put_text(o, NC_GLOBAL, "command_line", cmd, err);
    if (rc == RC_OK) rc = put_text(o, NC_GLOBAL, "ricochet_version", rc_version(), err);
    if (rc == RC_OK) rc = put_text(o, NC_GLOBAL, "ricochet_commit", RC_COMMIT, err);
    if (rc != RC_OK) return rc;
    const char *one[1] = {meta->case_path};
    const int nf = meta->nfile > 0 && meta->file ? meta->nfile : 1;
    const char *const *files = meta->nfile > 0 && meta->file ? meta->file : one;
    size_t cap = 1;
    for (int i = 0; i < nf; i++) cap += strlen(str_or_empty(files[i])) + 68;
    char *list = malloc(cap);
    if (!list) RC_RAISE(err, RC_ENOMEM, "output: out of memory for the input checksums");
    size_t w = 0;
    list[0] = '\0';
    for (int i = 0; i < nf; i++) {
        char hex[65];
        if (rc_sha256_file(str_or_empty(files[i]), hex) != 0) snprintf(hex, sizeof hex, "unreadable");
        if (i == 0) rc = put_text(o, NC_GLOBAL, "case_sha256", hex, err);
        w += (size_t)snprintf(list + w, cap - w, "%s%s  %s", i ? "\n" : "", hex, str_or_empty(files[i]));
    }
    if (rc == RC_OK) rc = put_text(o, NC_GLOBAL, "input_files_sha256", list, err);
    free(list);
    /* the fields set from outside the deck (--set) */
    if (rc == RC_OK && meta->overrides && *meta->overrides)
        rc = put_text(o, NC_GLOBAL, "overrides", meta->overrides, err);
    return rc;
}

/* Global attributes describing the run; complete="no" until closed. */
static rc_status define_globals(rc_output *o, const rc_output_meta *meta, rc_error *err)
{
    char buf[512];
    rc_status rc = put_text(o, NC_GLOBAL, "title", meta->title, err);
    if (rc == RC_OK) rc = put_text(o, NC_GLOBAL, "Conventions", "CF-1.8", err);
    snprintf(buf, sizeof buf, "ricochet %s", rc_version());
    if (rc == RC_OK) rc = put_text(o, NC_GLOBAL, "source", buf, err);
    if (rc == RC_OK) rc = put_text(o, NC_GLOBAL, "case_path", meta->case_path, err);
    snprintf(buf, sizeof buf, "%016lx", meta->checksum);
    if (rc == RC_OK) rc = put_text(o, NC_GLOBAL, "case_checksum", buf, err);
    if (rc != RC_OK) return rc;

    /* unit system: the declared components, or a note that none was declared */
    const char *comp[3] = {"mass", "length", "time"};
    const char *val[3] = {meta->unit_mass, meta->unit_length, meta->unit_time};
    size_t n = 0;
    buf[0] = '\0';
    for (int i = 0; i < 3; i++)
        if (*str_or_empty(val[i]) && n < sizeof buf)
            n += (size_t)snprintf(buf + n, sizeof buf - n, "%s%s=%s", n ? " " : "", comp[i],
                                  val[i]);
    rc = put_text(o, NC_GLOBAL, "unit_system",
                  buf[0] ? buf : "undeclared (consistent units assumed)", err);

    /* solver settings */
    if (rc == RC_OK) rc = put_text(o, NC_GLOBAL, "solver", meta->solver, err);
    if (rc == RC_OK) rc = put_double(o, "rtol", meta->rtol, err);
    if (rc == RC_OK) rc = put_double(o, "atol_position", meta->atol_pos, err);
    if (rc == RC_OK) rc = put_double(o, "atol_quaternion", meta->atol_quat, err);
    if (rc == RC_OK) rc = put_double(o, "atol_velocity", meta->atol_vel, err);
    if (rc == RC_OK) rc = put_double(o, "atol_angular_velocity", meta->atol_omega, err);
    if (rc == RC_OK) rc = put_double(o, "atol_energy", meta->atol_energy, err);
    if (rc == RC_OK && meta->event_records) rc = put_text(o, NC_GLOBAL, "event_records", meta->event_records, err);
    if (rc == RC_OK) rc = put_text(o, NC_GLOBAL, "tolerances_derived", meta->tol_derived, err);
    if (rc == RC_OK) rc = put_int64(o, "max_order", meta->max_order, err);
    if (rc == RC_OK) rc = put_int64(o, "max_steps", meta->max_steps, err);
    if (rc == RC_OK) rc = put_double(o, "hmax", meta->hmax, err);
    if (rc == RC_OK) rc = put_double(o, "h0", meta->h0, err);
    if (rc == RC_OK) rc = put_double(o, "t_end", meta->t_end, err);
    if (rc == RC_OK) rc = put_double(o, "dt_out", meta->dt_out, err);
    if (rc == RC_OK && meta->sampling_note && *meta->sampling_note)
        rc = put_text(o, NC_GLOBAL, "sampling_note", meta->sampling_note, err);
    if (rc == RC_OK) rc = put_double(o, "atol_position_floor", meta->atol_pos_floor, err);
    if (rc == RC_OK && meta->tolerance_note && *meta->tolerance_note)
        rc = put_text(o, NC_GLOBAL, "tolerance_note", meta->tolerance_note, err);
    if (rc == RC_OK && meta->preload) rc = put_text(o, NC_GLOBAL, "preload", meta->preload, err);
    if (rc == RC_OK && meta->preload) rc = put_int64(o, "preload_newton_iters", meta->preload_iters, err);
    if (rc == RC_OK) rc = define_provenance(o, meta, err);
    if (rc != RC_OK) return rc;

    /* provenance and completion */
    time_t now = time(NULL);
    struct tm tm;
    char date[64] = "unknown date";
    if (now != (time_t)-1 && gmtime_r(&now, &tm)) strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", &tm);
    snprintf(buf, sizeof buf, "created %s", date);
    rc = put_text(o, NC_GLOBAL, "history", buf, err);
    if (rc == RC_OK) rc = put_text(o, NC_GLOBAL, "complete", "no", err);
    if (rc == RC_OK) rc = put_text(o, NC_GLOBAL, "status", "running", err);
    return rc;
}

/* Write all n strings of an NC_STRING variable in one call (one HDF5 write,
 * not one per element: ~40 us each). */
static rc_status put_strings(const rc_output *o, int v, size_t n, const char *const *s, rc_error *err)
{
    const char **p = malloc((n + 1) * sizeof *p);
    if (!p) RC_RAISE(err, RC_ENOMEM, "output: out of memory writing %s", var_table[v].name);
    for (size_t i = 0; i < n; i++) p[i] = str_or_empty(s[i]);
    int st = nc_put_var_string(o->ncid, o->var[v], p);
    free(p);
    if (st != NC_NOERR) return nc_fail(err, __LINE__, __func__, o->path, st, "writing %s", var_table[v].name);
    return RC_OK;
}

/* Write the variables that do not depend on time (ids, fixed flags, types). */
static rc_status write_static(rc_output *o, const rc_output_meta *meta, rc_error *err)
{
    NC_TRY(o->path, nc_put_var_int(o->ncid, o->var[V_BODY_ID], meta->body_id),
           "writing body_id");
    NC_TRY(o->path, nc_put_var_int(o->ncid, o->var[V_BODY_FIXED], meta->body_fixed),
           "writing body_fixed");
    NC_TRY(o->path, nc_put_var_int(o->ncid, o->var[V_BODY_COORD], meta->body_id), "writing body");
    if (meta->ninter > 0) NC_TRY(o->path, nc_put_var_int(o->ncid, o->var[V_INTER_COORD], meta->inter_id), "writing inter");
    if (meta->ncoupling > 0)
        NC_TRY(o->path, nc_put_var_int(o->ncid, o->var[V_CPL_COORD], meta->coupling_id), "writing coupling");
    if (meta->nsurf > 0) {
        const size_t ns = (size_t)meta->nsurf;
        int *body = malloc(ns * sizeof *body);
        if (!body) RC_RAISE(err, RC_ENOMEM, "output: out of memory writing the surfaces");
        for (size_t k = 0; k < ns; k++) {
            const int b = meta->surf_body[k];
            body[k] = b >= 0 && b < meta->nbody ? meta->body_id[b] : -1;
        }
        int st = nc_put_var_int(o->ncid, o->var[V_SURF_BODY], body);
        free(body);
        if (st != NC_NOERR) return nc_fail(err, __LINE__, __func__, o->path, st, "writing surface_body");
        NC_TRY(o->path, nc_put_var_int(o->ncid, o->var[V_SURF_COORD], meta->surf_id), "writing surface");
        NC_TRY(o->path, nc_put_var_double(o->ncid, o->var[V_SURF_POINT], meta->surf_point), "writing surface_point");
        NC_TRY(o->path, nc_put_var_double(o->ncid, o->var[V_SURF_NORMAL], meta->surf_normal),
               "writing surface_normal");
        NC_TRY(o->path, nc_put_var_double(o->ncid, o->var[V_SURF_RADIUS], meta->surf_radius),
               "writing surface_radius");
        NC_TRY(o->path, nc_put_var_double(o->ncid, o->var[V_SURF_PARAM], meta->surf_param),
               "writing surface_parameters");
        rc_status rc = put_strings(o, V_SURF_KIND, ns, meta->surf_kind, err);
        if (rc != RC_OK) return rc;
        if (meta->nseg > 0) {
            NC_TRY(o->path, nc_put_var_int(o->ncid, o->var[V_SURF_NODE0], meta->surf_first_node),
                   "writing surface_first_node");
            NC_TRY(o->path, nc_put_var_int(o->ncid, o->var[V_SURF_SEG0], meta->surf_first_seg),
                   "writing surface_first_segment");
            NC_TRY(o->path, nc_put_var_double(o->ncid, o->var[V_SEG_NODE], meta->seg_node),
                   "writing segment_node_position");
            NC_TRY(o->path, nc_put_var_int(o->ncid, o->var[V_SEG_CORNER], meta->seg_corner), "writing segment_corners");
        }
        if (meta->ninter > 0 && meta->inter_surf) {
            int *is = malloc(2 * (size_t)meta->ninter * sizeof *is);
            if (!is) RC_RAISE(err, RC_ENOMEM, "output: out of memory writing inter_surface");
            for (int k = 0; k < 2 * meta->ninter; k++) {
                const int sf = meta->inter_surf[k];
                is[k] = sf >= 0 && sf < meta->nsurf ? meta->surf_id[sf] : -1;
            }
            st = nc_put_var_int(o->ncid, o->var[V_INTER_SURF], is);
            free(is);
            if (st != NC_NOERR) return nc_fail(err, __LINE__, __func__, o->path, st, "writing inter_surface");
        }
    }
    if (meta->ninter > 0) {
        NC_TRY(o->path, nc_put_var_int(o->ncid, o->var[V_INTER_ID], meta->inter_id),
               "writing inter_id");
        rc_status rc = put_strings(o, V_INTER_TYPE, (size_t)meta->ninter, meta->inter_type, err);
        if (rc != RC_OK) return rc;
    }
    if (meta->ncoupling > 0) {
        NC_TRY(o->path, nc_put_var_int(o->ncid, o->var[V_CPL_ID], meta->coupling_id),
               "writing coupling_id");
        rc_status rc = put_strings(o, V_CPL_TYPE, (size_t)meta->ncoupling, meta->coupling_type, err);
        if (rc != RC_OK) return rc;
    }
    if (meta->njoint > 0) {
        NC_TRY(o->path, nc_put_var_int(o->ncid, o->var[V_JOINT_COORD], meta->joint_id), "writing joint");
        rc_status rc = put_strings(o, V_JOINT_TYPE, (size_t)meta->njoint, meta->joint_type, err);
        if (rc != RC_OK) return rc;
    }
    return RC_OK;
}

/* Check that the meta is usable: sizes and the arrays they announce. */
static rc_status check_meta(const rc_output_meta *meta, rc_error *err)
{
    if (!meta || meta->nbody < 1 || meta->ninter < 0 || meta->nenergy < 0 || meta->ncoupling < 0)
        RC_RAISE(err, RC_EINTERNAL,
                 "output: bad meta (needs nbody >= 1, ninter >= 0, nenergy >= 0, ncoupling >= 0)");
    if (!meta->body_id || !meta->body_fixed ||
        (meta->ninter > 0 && (!meta->inter_id || !meta->inter_type)) ||
        (meta->ncoupling > 0 && (!meta->coupling_id || !meta->coupling_type)) ||
        meta->njoint < 0 || (meta->njoint > 0 && (!meta->joint_id || !meta->joint_type)) ||
        (meta->nenergy > 0 && (!meta->energy_name || !meta->energy_long)) || meta->nsurf < 0 ||
        (meta->nsurf > 0 && (!meta->surf_id || !meta->surf_kind || !meta->surf_body || !meta->surf_point ||
                             !meta->surf_normal || !meta->surf_radius || !meta->surf_param)))
        RC_RAISE(err, RC_EINTERNAL, "output: meta array missing for a non-zero count");
    return RC_OK;
}

/* Size the record buffer: bytes per record of each time series, records per
 * block (about RC_OUT_BLOCK_BYTES in all, 1 to RC_OUT_BLOCK_RECORDS), and
 * allocate it. Returns 0 when out of memory. */
static int alloc_buffer(rc_output *o, const rc_output_meta *meta)
{
    size_t total = (size_t)meta->nenergy * sizeof(double);
    for (int v = 0; v < V_COUNT; v++) {
        const var_spec *s = &var_table[v];
        if (s->dim[0] != D_TIME || var_skipped(meta, v)) continue;
        size_t n = s->type == NC_INT ? sizeof(int) : sizeof(double);
        for (int i = 1; i < s->ndims; i++) n *= o->dimlen[s->dim[i]];
        o->rec_size[v] = n;
        total += n;
    }
    size_t b = RC_OUT_BLOCK_BYTES / (total ? total : 1);
    o->block = b < 1 ? 1 : b > RC_OUT_BLOCK_RECORDS ? RC_OUT_BLOCK_RECORDS : b;
    for (int v = 0; v < V_COUNT; v++)
        if (o->rec_size[v] && !(o->buf[v] = malloc(o->block * o->rec_size[v]))) return 0;
    o->ebuf = malloc(((size_t)meta->nenergy * o->block + 1) * sizeof(double));
    o->ev_num = malloc(4 * RC_OUT_BLOCK_EVENTS * sizeof(double));
    return o->ebuf && o->ev_num;
}

/* Monotonic wall clock [s]. */
static double wall_clock(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Free the handle (not the file). NULL is a no-op. */
static void output_free(rc_output *o)
{
    if (!o) return;
    free(o->path);
    free(o->var_energy);
    for (int v = 0; v < V_COUNT; v++) free(o->buf[v]);
    free(o->ebuf);
    free(o->ev_num);
    free(o->impact);
    free(o->persist);
    free(o->phys_summary);
    free(o->phys_contacts);
    free(o->phys_row);
    free(o->phys_hist);
    for (size_t i = 0; i < o->nevbuf; i++) {
        free(o->ev_str[0][i]);
        free(o->ev_str[1][i]);
    }
    free(o);
}

/* netCDF reports any failed create as "Permission denied"; say what is
 * wrong with the directory when that is the cause. */
static void directory_problem(const char *path, char *buf, size_t n)
{
    const char *slash = strrchr(path, '/');
    buf[0] = '\0';
    if (!slash) return;
    int len = slash == path ? 1 : (int)(slash - path);
    char dir[1024];
    snprintf(dir, sizeof dir, "%.*s", len, path);
    if (access(dir, W_OK) != 0) snprintf(buf, n, " (directory %s: %s)", dir, strerror(errno));
}

/* ---- Room on the file system --------------------------------------------- */

/* Chunks of `c` rows that a write of rows [n0, n1) is the first to touch. */
static size_t new_chunks(size_t n0, size_t n1, size_t c)
{
    if (n1 <= n0 || c == 0) return 0;
    const size_t first_new = (n0 + c - 1) / c, last = (n1 - 1) / c;
    return last >= first_new ? last - first_new + 1 : 0;
}

/* HDF5 metadata a write or the closing of the file may add [bytes]. */
static size_t meta_bytes(const rc_output *o)
{
    return RC_OUT_META_FIXED + RC_OUT_META_PER_VAR * o->nvars;
}

/* Upper bound of the bytes the buffered block takes in the file: every chunk
 * it starts at its full size, the event strings in HDF5's heap, metadata. */
static size_t block_bytes(const rc_output *o)
{
    size_t b = meta_bytes(o);
    for (int v = 0; v < V_COUNT; v++) {
        if (o->var[v] < 0 || !o->chunk_rec[v]) continue;
        if (var_table[v].dim[0] == D_TIME && o->rec_size[v])
            b += new_chunks(o->nrec, o->nrec + o->nbuf, o->chunk_rec[v]) * o->chunk_rec[v] * o->rec_size[v];
        else if (var_table[v].dim[0] == D_EVENT)
            b += new_chunks(o->nevent, o->nevent + o->nevbuf, o->chunk_rec[v]) * o->chunk_rec[v] * 16;
    }
    b += (size_t)o->nenergy * new_chunks(o->nrec, o->nrec + o->nbuf, o->echunk) * o->echunk * sizeof(double);
    for (size_t i = 0; i < o->nevbuf; i++)
        for (int c = 0; c < 2; c++) b += strlen(o->ev_str[c][i]) + 1 + 32;
    return b;
}

/* Free bytes on the file system holding `path`, or -1 with errno set. */
static double free_bytes(const char *path)
{
    struct statvfs fs;
    if (statvfs(path, &fs) != 0) return -1.0;
    return (double)fs.f_bavail * (double)fs.f_frsize;
}

/* Before a block is written: the path still names the file created, and the
 * block plus the reserve for closing fit on the file system. Otherwise
 * RC_EIO naming the file and the records kept; the file stays whole. */
static rc_status check_room(rc_output *o, rc_error *err)
{
    struct stat st;
    if (stat(o->path, &st) != 0 || st.st_dev != o->dev || st.st_ino != o->ino)
        RC_RAISE(err, RC_EIO,
                 "%s: the output file is gone (%s; was its directory removed or renamed?) before record %zu "
                 "could be written",
                 o->path, errno ? strerror(errno) : "replaced by another file", o->nrec);
    const double need = (double)block_bytes(o) + (double)meta_bytes(o), avail = free_bytes(o->path);
    if (avail < 0)
        RC_RAISE(err, RC_EIO, "%s: cannot query the free space of its file system before record %zu: %s",
                 o->path, o->nrec, strerror(errno));
    if (avail < need) {
        char kept[64];
        if (o->nrec) snprintf(kept, sizeof kept, "records 0 to %zu", o->nrec - 1);
        else snprintf(kept, sizeof kept, "no records");
        RC_RAISE(err, RC_EIO,
                 "%s: file system full: %.0f bytes free, writing the next %zu records (from record %zu) and %zu "
                 "event rows needs up to %.0f bytes; the file keeps %s (complete = \"no\"); free some space "
                 "or write elsewhere with -o",
                 o->path, avail, o->nbuf, o->nrec, o->nevbuf, need, kept);
    }
    return RC_OK;
}

/* ---- Public functions -------------------------------------------------- */

static rc_status output_open(rc_output **out, const char *path, const rc_output_meta *meta, rc_error *err)
{
    *out = NULL;
    rc_status rc = check_meta(meta, err);
    if (rc != RC_OK) return rc;
    if (!path) RC_RAISE(err, RC_EINTERNAL, "output: no path");

    /* the handle: copies of what outlives the call */
    rc_output *o = calloc(1, sizeof *o);
    if (!o) RC_RAISE(err, RC_ENOMEM, "output: out of memory");
    o->linalg[0] = o->linalg[1] = o->linalg[2] = -1;
    o->path = malloc(strlen(path) + 1);
    o->var_energy = calloc((size_t)meta->nenergy + 1, sizeof *o->var_energy);
    if (!o->path || !o->var_energy) {
        output_free(o);
        RC_RAISE(err, RC_ENOMEM, "output: out of memory");
    }
    strcpy(o->path, path);
    o->nenergy = meta->nenergy;
    const size_t len[D_COUNT] = {1, (size_t)meta->nbody, (size_t)meta->ninter, 3, 4, 1, (size_t)meta->ncoupling,
                                 (size_t)meta->nsurf, RC_OUT_SURF_NPARAM, 2, (size_t)meta->nseg_node,
                                 (size_t)meta->nseg, 4, (size_t)meta->njoint};
    memcpy(o->dimlen, len, sizeof len);
    derive_units(o, meta);
    if (!alloc_buffer(o, meta)) {
        output_free(o);
        RC_RAISE(err, RC_ENOMEM, "output: out of memory for the record buffer");
    }
    o->last_sync = wall_clock();

    /* room for the header, the fixed data and closing: the header of ~V_COUNT
     * variables with their attributes, the names, two metadata reserves */
    {
        char dir[1024];
        const char *slash = strrchr(path, '/');
        if (slash) snprintf(dir, sizeof dir, "%.*s", slash == path ? 1 : (int)(slash - path), path);
        else snprintf(dir, sizeof dir, ".");
        const double need = 2.0 * (double)(RC_OUT_META_FIXED + RC_OUT_META_PER_VAR * (V_COUNT + (size_t)meta->nenergy)) +
                            256.0 * (double)(meta->nbody + meta->ninter + meta->ncoupling);
        const double avail = free_bytes(dir);
        if (avail >= 0 && avail < need) {
            output_free(o);
            RC_RAISE(err, RC_EIO, "%s: file system full: %.0f bytes free, the output needs at least %.0f to start",
                     path, avail, need);
        }
    }
    /* create, define, write the fixed data */
    int st = nc_create(path, NC_NETCDF4 | NC_CLOBBER, &o->ncid);
    if (st != NC_NOERR) {
        char why[1200];
        directory_problem(path, why, sizeof why);
        output_free(o);
        return nc_fail(err, __LINE__, __func__, path, st, "cannot create the output file%s", why);
    }
    rc = define_vars(o, meta, err);
    if (rc == RC_OK) rc = define_globals(o, meta, err);
    if (rc == RC_OK && (st = nc_enddef(o->ncid)) != NC_NOERR)
        rc = nc_fail(err, __LINE__, __func__, path, st, "ending definitions");
    if (rc == RC_OK) rc = write_static(o, meta, err);
    if (rc == RC_OK && (st = nc_sync(o->ncid)) != NC_NOERR)
        rc = nc_fail(err, __LINE__, __func__, path, st, "writing the header");
    struct stat fst;
    if (rc == RC_OK && stat(path, &fst) != 0)
        rc = RC_SET(err, RC_EIO, "%s: the output file is gone right after its creation: %s", path, strerror(errno));
    if (rc != RC_OK) {
        /* a half-made file is not a result: remove it; a handle HDF5
         * cannot close after a failed write is abandoned */
        if (nc_close(o->ncid) != NC_NOERR) output_abandoned = 1;
        remove(o->path);
        output_free(o);
        return rc;
    }
    o->dev = fst.st_dev;
    o->ino = fst.st_ino;
    *out = o;
    return RC_OK;
}

rc_status rc_output_open(rc_output **out, const char *path, const rc_output_meta *meta, rc_error *err)
{
    rc_nc_lock();
    const rc_status rc = output_open(out, path, meta, err);
    rc_nc_unlock();
    return rc;
}

/* Write the buffered records (one nc_put_vara per variable) and event rows,
 * then sync to disk, after checking there is room (check_room). No room:
 * the block is dropped and nothing more is written (o->stopped), the file
 * stays whole. A failed write makes the handle unusable (o->broken). */
static rc_status write_block(rc_output *o, rc_error *err)
{
    if (o->broken || o->stopped) return RC_OK;
    if (o->nbuf == 0 && o->nevbuf == 0) return RC_OK;
    rc_status rc = check_room(o, err);
    if (rc != RC_OK) {
        o->stopped = 1;
        return rc;
    }
    o->broken = 1; /* until this write succeeds */
    if (o->nbuf > 0) {
        size_t start[3] = {o->nrec, 0, 0}, count[3] = {o->nbuf, 1, 1};
        for (int v = 0; v < V_COUNT; v++) {
            const var_spec *s = &var_table[v];
            if (!o->rec_size[v]) continue;
            for (int i = 1; i < s->ndims; i++) count[i] = o->dimlen[s->dim[i]];
            NC_TRY(o->path, nc_put_vara(o->ncid, o->var[v], start, count, o->buf[v]),
                   "writing %s, records %zu to %zu", s->name, o->nrec, o->nrec + o->nbuf - 1);
        }
        for (int k = 0; k < o->nenergy; k++)
            NC_TRY(o->path, nc_put_vara_double(o->ncid, o->var_energy[k], start, count, o->ebuf + (size_t)k * o->block),
                   "writing energy %d, records %zu to %zu", k, o->nrec, o->nrec + o->nbuf - 1);
        o->nrec += o->nbuf;
        o->nbuf = 0;
    }
    if (o->nevbuf > 0) {
        size_t start[1] = {o->nevent}, count[1] = {o->nevbuf};
        static const int num_var[4] = {V_EVENT_TIME, V_EVENT_PEN, V_EVENT_VN, V_EVENT_FN};
        for (int c = 0; c < 4; c++)
            NC_TRY(o->path, nc_put_vara_double(o->ncid, o->var[num_var[c]], start, count, o->ev_num + c * RC_OUT_BLOCK_EVENTS),
                   "writing %s, rows %zu to %zu", var_table[num_var[c]].name, o->nevent, o->nevent + o->nevbuf - 1);
        static const int str_var[2] = {V_EVENT_KIND, V_EVENT_ELEMENT};
        for (int c = 0; c < 2; c++)
            NC_TRY(o->path, nc_put_vara_string(o->ncid, o->var[str_var[c]], start, count, (const char **)o->ev_str[c]),
                   "writing %s, rows %zu to %zu", var_table[str_var[c]].name, o->nevent, o->nevent + o->nevbuf - 1);
        for (size_t i = 0; i < o->nevbuf; i++) {
            free(o->ev_str[0][i]);
            free(o->ev_str[1][i]);
            o->ev_str[0][i] = o->ev_str[1][i] = NULL;
        }
        o->nevent += o->nevbuf;
        o->nevbuf = 0;
    }
    NC_TRY(o->path, nc_sync(o->ncid), "flushing after record %zu", o->nrec);
    o->last_sync = wall_clock();
    o->broken = 0;
    return RC_OK;
}

/* write_block, keeping the message of a failed write for the close. Holds
 * the netCDF lock. */
static rc_status flush(rc_output *o, rc_error *err)
{
    rc_error local;
    if (!err) err = &local;
    const rc_status rc = write_block(o, err);
    if (rc != RC_OK && o->broken && !o->fail[0]) snprintf(o->fail, sizeof o->fail, "%.2000s", err->msg);
    return rc;
}

/* flush, taking the lock (from the record and event calls). */
static rc_status flush_locked(rc_output *o, rc_error *err)
{
    rc_nc_lock();
    const rc_status rc = flush(o, err);
    rc_nc_unlock();
    return rc;
}

rc_status rc_output_frame(rc_output *o, const rc_frame *f, rc_error *err)
{
    /* the record's data, in the order of the variable table */
    const void *data[V_COUNT] = {
        [V_TIME] = &f->t,
        [V_AT_EVENT] = &f->at_event,
        [V_BODY_POS] = f->body_pos,
        [V_BODY_QUAT] = f->body_quat,
        [V_BODY_VEL] = f->body_vel,
        [V_BODY_OMEGA] = f->body_omega,
        [V_INTER_PEN] = f->inter_pen,
        [V_INTER_FLOAD] = f->inter_fload,
        [V_INTER_FDAMP] = f->inter_fdamp,
        [V_INTER_FNORMAL] = f->inter_fnormal,
        [V_INTER_POINT] = f->inter_point,
        [V_INTER_NORMAL] = f->inter_normal,
        [V_INTER_MODE] = f->inter_mode,
        [V_INTER_FFRIC] = f->inter_ffric,
        [V_INTER_VSLIP] = f->inter_vslip,
        [V_INTER_SLIP] = f->inter_slip,
        [V_CPL_FORCE] = f->cpl_force,
        [V_CPL_LENGTH] = f->cpl_length,
        [V_CPL_F1] = f->cpl_f1,
        [V_CPL_F2] = f->cpl_f2,
        [V_CPL_LOWEST] = f->cpl_lowest,
        [V_JOINT_FORCE] = f->joint_force,
        [V_JOINT_MOMENT] = f->joint_moment,
        [V_JOINT_DRIFT_POS] = f->joint_drift_pos,
        [V_JOINT_DRIFT_ANG] = f->joint_drift_ang,
        [V_JOINT_WORK] = f->joint_work,
        [V_JOINT_STOP_FORCE] = f->joint_stop_force,
        [V_JOINT_STOP_MOMENT] = f->joint_stop_moment,
    };
    if (o->broken || o->stopped) RC_RAISE(err, RC_EIO, "%s: an earlier write failed or found no room", o->path);
    /* check everything before copying anything: a record is whole or absent */
    for (int v = 0; v < V_COUNT; v++)
        if (o->rec_size[v] && !data[v])
            RC_RAISE(err, RC_EINTERNAL, "output: frame field for %s is NULL", var_table[v].name);
    if (o->nenergy > 0 && !f->energy) RC_RAISE(err, RC_EINTERNAL, "output: frame field for energy is NULL");
    /* the buffer is flushed when full, so there is room for one record */
    for (int v = 0; v < V_COUNT; v++)
        if (o->rec_size[v]) memcpy(o->buf[v] + o->nbuf * o->rec_size[v], data[v], o->rec_size[v]);
    for (int k = 0; k < o->nenergy; k++) o->ebuf[(size_t)k * o->block + o->nbuf] = f->energy[k];
    o->nbuf++;
    if (o->nbuf == o->block || wall_clock() - o->last_sync >= RC_OUT_SYNC_SECONDS) return flush_locked(o, err);
    return RC_OK;
}

/* A copy of s ("" for NULL), or NULL when out of memory. */
static char *copy_string(const char *s)
{
    const char *p = str_or_empty(s);
    char *c = malloc(strlen(p) + 1);
    if (c) strcpy(c, p);
    return c;
}

rc_status rc_output_event_values(rc_output *o, double t, const char *kind, const char *element,
                                 const double values[3], rc_error *err)
{
    if (o->broken || o->stopped) RC_RAISE(err, RC_EIO, "%s: an earlier write failed or found no room", o->path);
    const size_t i = o->nevbuf;
    char *k = copy_string(kind), *e = copy_string(element);
    if (!k || !e) {
        free(k);
        free(e);
        RC_RAISE(err, RC_ENOMEM, "output: out of memory for event row %zu", o->nevent + i);
    }
    o->ev_str[0][i] = k;
    o->ev_str[1][i] = e;
    o->ev_num[i] = t;
    for (int c = 0; c < 3; c++) o->ev_num[(c + 1) * RC_OUT_BLOCK_EVENTS + i] = values ? values[c] : NAN;
    o->nevbuf++;
    if (o->nevbuf == RC_OUT_BLOCK_EVENTS) return flush_locked(o, err);
    return RC_OK;
}

rc_status rc_output_event(rc_output *o, double t, const char *kind, const char *element,
                          rc_error *err)
{
    return rc_output_event_values(o, t, kind, element, NULL, err);
}

/* Statistics and completion attributes (in define mode). */
static rc_status write_final(rc_output *o, const rc_stats *st, int complete, const char *reason,
                             rc_error *err)
{
    rc_status rc = RC_OK;
    if (st) {
        rc = put_int64(o, "stats_steps", st->steps, err);
        if (rc == RC_OK) rc = put_int64(o, "stats_rhs_evals", st->rhs_evals, err);
        if (rc == RC_OK) rc = put_int64(o, "stats_jac_evals", st->jac_evals, err);
        if (rc == RC_OK) rc = put_int64(o, "stats_lin_setups", st->lin_setups, err);
        if (rc == RC_OK) rc = put_int64(o, "stats_nonlin_iters", st->nonlin_iters, err);
        if (rc == RC_OK) rc = put_int64(o, "stats_nonlin_fails", st->nonlin_fails, err);
        if (rc == RC_OK) rc = put_int64(o, "stats_err_test_fails", st->err_test_fails, err);
        if (rc == RC_OK) rc = put_int64(o, "stats_root_evals", st->root_evals, err);
        if (rc == RC_OK) rc = put_int64(o, "stats_events", st->events, err);
        if (rc == RC_OK) rc = put_int64(o, "stats_reinits", st->reinits, err);
        if (rc == RC_OK) rc = put_int64(o, "stats_switches_explicit", st->switches_explicit, err);
        if (rc == RC_OK) rc = put_int64(o, "stats_switches_implicit", st->switches_implicit, err);
        if (rc == RC_OK) rc = put_int64(o, "stats_steps_explicit", st->steps_explicit, err);
        if (rc == RC_OK) rc = put_int64(o, "stats_settles", st->settles, err);
        if (rc == RC_OK) rc = put_int64(o, "stats_records_thinned", st->records_thinned, err);
        if (rc == RC_OK) rc = put_double(o, "stats_t_settle", st->t_settle, err);
        if (rc == RC_OK) rc = put_double(o, "stats_t_end", st->t_end, err);
        if (rc == RC_OK) rc = put_double(o, "stats_wall_time", st->wall_time, err);
        if (rc == RC_OK) rc = put_double(o, "energy_balance_residual", st->energy_residual, err);
        if (rc == RC_OK && st->vibration_note[0]) rc = put_text(o, NC_GLOBAL, "vibration_note", st->vibration_note, err);
        static const char *const lname[3] = {"stats_klu_analyses", "stats_newton_nnz", "stats_pattern_nnz"};
        for (int k = 0; k < 3; k++)
            if (rc == RC_OK && o->linalg[k] >= 0) rc = put_int64(o, lname[k], o->linalg[k], err);
    }
    char status[sizeof(((rc_error *)0)->msg) + 16]; /* "incomplete: " + an rc_error message */
    if (complete)
        snprintf(status, sizeof status, "complete");
    else if (o->phys_stopped) /* "physics check failed: ..." */
        snprintf(status, sizeof status, "%s", reason && *reason ? reason : "physics check failed");
    else
        snprintf(status, sizeof status, "incomplete: %s",
                 reason && *reason ? reason : "no reason given");
    if (rc == RC_OK) rc = put_text(o, NC_GLOBAL, "complete", complete ? "yes" : "no", err);
    if (rc == RC_OK) rc = put_text(o, NC_GLOBAL, "status", status, err);
    return rc;
}

rc_status rc_output_impacts(rc_output *o, int n, const rc_impact *rows, int np, const rc_contact *pers,
                            rc_error *err)
{
    rc_impact *c = NULL;
    rc_contact *p = NULL;
    if (n > 0) {
        c = malloc((size_t)n * sizeof *c);
        if (!c) RC_RAISE(err, RC_ENOMEM, "output: out of memory for %d impacts", n);
        memcpy(c, rows, (size_t)n * sizeof *c);
    }
    if (np > 0) {
        p = malloc((size_t)np * sizeof *p);
        if (!p) {
            free(c);
            RC_RAISE(err, RC_ENOMEM, "output: out of memory for %d persistent contacts", np);
        }
        memcpy(p, pers, (size_t)np * sizeof *p);
    }
    free(o->impact);
    o->impact = c;
    o->nimpact = n > 0 ? n : 0;
    free(o->persist);
    o->persist = p;
    o->npersist = np > 0 ? np : 0;
    return RC_OK;
}

/* A table of rows: dimension dname (unlimited, so that an empty table is
 * allowed), one variable per column of cols[ncol], their ids in varid (the
 * impacts, the persistent contacts). Only in files with interfaces. Define
 * mode. */
static rc_status define_table(rc_output *o, const char *dname, const table_col *cols, int ncol, int *varid,
                              rc_error *err)
{
    int dim;
    NC_TRY(o->path, nc_def_dim(o->ncid, dname, NC_UNLIMITED, &dim), "defining dimension %s", dname);
    for (int c = 0; c < ncol; c++) {
        NC_TRY(o->path, nc_def_var(o->ncid, cols[c].name, c == 0 ? NC_INT : NC_DOUBLE, 1, &dim, &varid[c]),
               "defining %s", cols[c].name);
        rc_status rc = put_text(o, varid[c], "units", o->unit[cols[c].unit], err);
        if (rc == RC_OK) rc = put_text(o, varid[c], "long_name", cols[c].long_name, err);
        if (rc == RC_OK && cols[c].comment) rc = put_text(o, varid[c], "comment", cols[c].comment, err);
        if (rc != RC_OK) return rc;
    }
    return RC_OK;
}

/* The cells of the two tables: row k's value in column c >= 1 (column 0,
 * the interface ids, is written apart). */
static double impact_cell(const rc_output *o, size_t k, int c)
{
    const rc_impact *r = &o->impact[k];
    const double v[I_COUNT] = {0, r->t_close, r->t_open, r->duration, r->pen_max, r->t_pen_max, r->fn_max,
                               r->t_fn_max, r->v_in, r->v_out, r->restitution, r->energy_lost};
    return v[c];
}

static double persistent_cell(const rc_output *o, size_t k, int c)
{
    const rc_contact *r = &o->persist[k];
    const double v[P_COUNT] = {0, r->t_close, r->t_open, r->duration, r->fn_max, r->fn_mean, r->pen_max, r->slip};
    return v[c];
}

/* Write the n rows of a table defined by define_table (data mode): the
 * interface ids ids[n] in column 0, cell(o, k, c) in the columns 1..ncol-1;
 * what names the table in the messages. */
static rc_status write_table(rc_output *o, const int *varid, int ncol, size_t n, const int *ids,
                             double (*cell)(const rc_output *, size_t, int), const char *what, rc_error *err)
{
    const size_t start[1] = {0}, count[1] = {n};
    if (n == 0) return RC_OK;
    double *col = malloc(n * sizeof *col);
    if (!col) RC_RAISE(err, RC_ENOMEM, "output: out of memory writing the %s", what);
    int st = nc_put_vara_int(o->ncid, varid[0], start, count, ids);
    for (int c = 1; c < ncol && st == NC_NOERR; c++) {
        for (size_t k = 0; k < n; k++) col[k] = cell(o, k, c);
        st = nc_put_vara_double(o->ncid, varid[c], start, count, col);
    }
    free(col);
    if (st != NC_NOERR) return nc_fail(err, __LINE__, __func__, o->path, st, "writing the %s table", what);
    return RC_OK;
}

/* The impacts and the persistent contacts (data mode). */
static rc_status write_tables(rc_output *o, const int *impact_var, const int *persist_var, rc_error *err)
{
    const size_t n = (size_t)(o->nimpact > o->npersist ? o->nimpact : o->npersist);
    int *ids = malloc((n + 1) * sizeof *ids);
    if (!ids) RC_RAISE(err, RC_ENOMEM, "output: out of memory writing the impacts");
    for (int k = 0; k < o->nimpact; k++) ids[k] = o->impact[k].inter_id;
    rc_status st = write_table(o, impact_var, I_COUNT, (size_t)o->nimpact, ids, impact_cell, "impacts", err);
    for (int k = 0; k < o->npersist; k++) ids[k] = o->persist[k].inter_id;
    if (st == RC_OK)
        st = write_table(o, persist_var, P_COUNT, (size_t)o->npersist, ids, persistent_cell, "persistent contacts",
                         err);
    free(ids);
    return st;
}

rc_status rc_output_physics(rc_output *o, const rc_out_physics *p, rc_error *err)
{
    if (!o) return RC_OK;
    free(o->phys_summary);
    free(o->phys_contacts);
    free(o->phys_row);
    free(o->phys_hist);
    o->phys_set = 1;
    o->phys_stopped = p->stopped;
    o->phys_total = p->total;
    o->phys_n = p->n > 0 ? p->n : 0;
    memcpy(o->phys_ratio, p->ratio, sizeof o->phys_ratio);
    o->phys_summary = copy_string(p->summary);
    o->phys_contacts = copy_string(p->contacts);
    o->phys_row = malloc(((size_t)o->phys_n + 1) * sizeof *o->phys_row);
    const size_t ni = o->dimlen[D_INTER];
    o->phys_hist = p->inter_history && o->var[V_INTER_ID] >= 0 ? malloc(ni * sizeof(int)) : NULL;
    if (!o->phys_summary || !o->phys_contacts || !o->phys_row || (p->inter_history && o->var[V_INTER_ID] >= 0 && !o->phys_hist)) {
        o->phys_set = 0;
        RC_RAISE(err, RC_ENOMEM, "output: out of memory for the physics checks");
    }
    if (o->phys_n) memcpy(o->phys_row, p->row, (size_t)o->phys_n * sizeof *o->phys_row);
    if (o->phys_hist) memcpy(o->phys_hist, p->inter_history, ni * sizeof(int));
    return RC_OK;
}

/* The physics checks (docs/output-format.md): global attributes, the
 * violation table (dimension violation, unlimited: an empty table is
 * allowed) and the contacts' history per interface. Define mode; varid[8]
 * receives the ids (-1: not defined). */
enum { PV_TIME, PV_FROM, PV_CHECK, PV_ELEMENT, PV_VALUE, PV_LIMIT, PV_MESSAGE, PV_HIST, PV_COUNT };
static rc_status define_physics(rc_output *o, int *varid, rc_error *err)
{
    static const struct {
        const char *name;
        nc_type type;
        const char *long_name, *comment;
    } col[PV_HIST] = {
        {"violation_time", NC_DOUBLE, "time the physics check failed", NULL},
        {"violation_time_from", NC_DOUBLE, "start of the interval the violation concerns",
         "the earlier record for a decrease or an excess of energy; the same time for a state"},
        {"violation_check", NC_STRING, "physics check that failed",
         "energy_damping, energy_hysteresis, energy_friction, energy_coupling_damping, mechanical_energy, "
         "energy_balance, penetration, sphere_centres, box_overlap, support_beyond_edge, law_deficit, open_penetrating, "
         "entered_deep, friction_limit, non_finite, start_overlap (docs/theory.md)"},
        {"violation_element", NC_STRING, "element concerned", "e.g. /INTER/TYPE6/3, /RBODY/2; empty: the whole model"},
        {"violation_value", NC_DOUBLE, "value found",
         "a decrease or an excess [J], a penetration or a distance [m]; non_finite: the value"},
        {"violation_limit", NC_DOUBLE, "tolerance or bound it was compared with", "in the unit of violation_value"},
        {"violation_message", NC_STRING, "the violation in words", NULL}};
    for (int c = 0; c < PV_COUNT; c++) varid[c] = -1;
    rc_status rc = put_text(o, NC_GLOBAL, "physics_checks", o->phys_summary, err);
    if (rc == RC_OK) rc = put_int64(o, "physics_violations", o->phys_total, err);
    if (rc == RC_OK) rc = put_double(o, "physics_max_energy_excess_ratio", o->phys_ratio[0], err);
    if (rc == RC_OK) rc = put_double(o, "physics_max_channel_decrease_ratio", o->phys_ratio[1], err);
    if (rc == RC_OK) rc = put_double(o, "physics_max_penetration_ratio", o->phys_ratio[2], err);
    if (rc == RC_OK) rc = put_text(o, NC_GLOBAL, "contact_summary", o->phys_contacts, err);
    if (rc != RC_OK) return rc;
    int dim;
    NC_TRY(o->path, nc_def_dim(o->ncid, "violation", NC_UNLIMITED, &dim), "defining dimension violation");
    for (int c = 0; c < PV_HIST; c++) {
        NC_TRY(o->path, nc_def_var(o->ncid, col[c].name, col[c].type, 1, &dim, &varid[c]), "defining %s", col[c].name);
        rc = put_text(o, varid[c], "long_name", col[c].long_name, err);
        if (rc == RC_OK && (c == PV_TIME || c == PV_FROM)) rc = put_text(o, varid[c], "units", o->unit[U_TIME], err);
        if (rc == RC_OK && col[c].comment) rc = put_text(o, varid[c], "comment", col[c].comment, err);
        if (rc != RC_OK) return rc;
    }
    if (!o->phys_hist) return RC_OK;
    static const int flags[5] = {0, 1, 2, 3, 4};
    NC_TRY(o->path, nc_def_var(o->ncid, "inter_contact_history", NC_INT, 1, &o->dimid[D_INTER], &varid[PV_HIST]),
           "defining inter_contact_history");
    rc = put_text(o, varid[PV_HIST], "long_name", "what the contact did over the run", err);
    if (rc == RC_OK)
        NC_TRY(o->path, nc_put_att_int(o->ncid, varid[PV_HIST], "flag_values", NC_INT, 5, flags),
               "writing attribute flag_values");
    if (rc == RC_OK)
        rc = put_text(o, varid[PV_HIST], "flag_meanings",
                      "never_closed closed_and_reopened closed_from_the_start_never_reopened "
                      "closed_during_the_run_never_reopened settled",
                      err);
    return rc;
}

/* Write the violation rows and the contacts' history (data mode). */
static rc_status write_physics(rc_output *o, const int *varid, rc_error *err)
{
    const size_t n = (size_t)o->phys_n, start[1] = {0}, count[1] = {n};
    if (o->phys_hist)
        NC_TRY(o->path, nc_put_var_int(o->ncid, varid[PV_HIST], o->phys_hist), "writing inter_contact_history");
    if (n == 0) return RC_OK;
    double *num = malloc(n * sizeof *num);
    const char **str = malloc(n * sizeof *str);
    if (!num || !str) {
        free(num);
        free(str);
        RC_RAISE(err, RC_ENOMEM, "output: out of memory writing the violations");
    }
    int st = NC_NOERR;
    for (int c = 0; c < PV_HIST && st == NC_NOERR; c++) {
        for (size_t k = 0; k < n; k++) {
            const rc_violation *v = &o->phys_row[k];
            num[k] = c == PV_TIME ? v->t : c == PV_FROM ? v->t_from : c == PV_VALUE ? v->value : v->limit;
            str[k] = c == PV_CHECK ? v->check : c == PV_ELEMENT ? v->element : v->message;
        }
        if (c == PV_CHECK || c == PV_ELEMENT || c == PV_MESSAGE)
            st = nc_put_vara_string(o->ncid, varid[c], start, count, str);
        else
            st = nc_put_vara_double(o->ncid, varid[c], start, count, num);
    }
    free(num);
    free(str);
    if (st != NC_NOERR) return nc_fail(err, __LINE__, __func__, o->path, st, "writing the violation table");
    return RC_OK;
}

void rc_output_linalg(rc_output *o, long klu_analyses, long newton_nnz, long pattern_nnz)
{
    if (!o) return;
    o->linalg[0] = klu_analyses;
    o->linalg[1] = newton_nnz;
    o->linalg[2] = pattern_nnz;
}

/* ---- After a failed write ------------------------------------------------ */

/* What a results file holds, read back from its bytes on disk. */
typedef struct readback {
    size_t nrec;      /* records (length of the time axis)                */
    size_t nvalid;    /* of them, the first ones with finite, increasing times */
    double t_last;    /* time of record nvalid - 1 [s]                    */
    size_t nevent;    /* event rows                                       */
    char complete[16], status[256]; /* the attributes as written      */
} readback;

/* Every attribute of variable v (NC_GLOBAL: the file's) read: NC_NOERR or
 * the first failure, its name in `what`. */
static int read_attributes(int nc, int v, char *what, size_t nwhat)
{
    int natt = 0, st = v == NC_GLOBAL ? nc_inq_natts(nc, &natt) : nc_inq_varnatts(nc, v, &natt);
    for (int a = 0; st == NC_NOERR && a < natt; a++) {
        char name[NC_MAX_NAME + 1];
        nc_type type;
        size_t len = 0, size = 0;
        if ((st = nc_inq_attname(nc, v, a, name)) != NC_NOERR) break;
        snprintf(what, nwhat, "attribute %.100s", name);
        if ((st = nc_inq_att(nc, v, name, &type, &len)) != NC_NOERR ||
            (st = nc_inq_type(nc, type, NULL, &size)) != NC_NOERR)
            break;
        void *buf = calloc(len + 1, size + 1);
        if (!buf) return NC_ENOMEM;
        if (type == NC_STRING) {
            if ((st = nc_get_att_string(nc, v, name, buf)) == NC_NOERR) nc_free_string(len, buf);
        } else
            st = nc_get_att(nc, v, name, buf);
        free(buf);
    }
    return st;
}

/* The whole header of an open file read (every variable and its attributes,
 * the file's attributes), and the last row of every variable along an
 * unlimited dimension (the time series, the events, the impacts): what a
 * reader of the file (ncdump, xarray) meets first. NC_NOERR or the first
 * failure, named in `what`. */
static int read_header_and_ends(int nc, char *what, size_t nwhat)
{
    int nvar = 0, nunlim = 0, unlim[8];
    int st = read_attributes(nc, NC_GLOBAL, what, nwhat);
    if (st == NC_NOERR) st = nc_inq_nvars(nc, &nvar);
    if (st == NC_NOERR) st = nc_inq_unlimdims(nc, &nunlim, NULL);
    if (st == NC_NOERR && nunlim > 8) return NC_EMAXDIMS;
    if (st == NC_NOERR) st = nc_inq_unlimdims(nc, &nunlim, unlim);
    for (int v = 0; st == NC_NOERR && v < nvar; v++) {
        char name[NC_MAX_NAME + 1];
        nc_type type;
        int ndims = 0, dim[NC_MAX_VAR_DIMS];
        size_t size = 0, n = 1, start[NC_MAX_VAR_DIMS] = {0}, count[NC_MAX_VAR_DIMS];
        if ((st = nc_inq_var(nc, v, name, &type, &ndims, dim, NULL)) != NC_NOERR) break;
        snprintf(what, nwhat, "variable %.100s", name);
        if ((st = nc_inq_type(nc, type, NULL, &size)) != NC_NOERR) break;
        char vwhat[128];
        if ((st = read_attributes(nc, v, vwhat, sizeof vwhat)) != NC_NOERR) {
            snprintf(what, nwhat, "variable %.60s, %.110s", name, vwhat);
            break;
        }
        int along = 0;
        for (int k = 0; k < nunlim; k++) along |= ndims > 0 && dim[0] == unlim[k];
        if (!along) continue;
        for (int d = 0; d < ndims && st == NC_NOERR; d++) st = nc_inq_dimlen(nc, dim[d], &count[d]);
        if (st != NC_NOERR || count[0] == 0) continue;
        start[0] = count[0] - 1; /* the last row */
        count[0] = 1;
        for (int d = 1; d < ndims; d++) n *= count[d];
        void *buf = calloc(n + 1, size + 1);
        if (!buf) return NC_ENOMEM;
        if (type == NC_STRING) {
            if ((st = nc_get_vara_string(nc, v, start, count, buf)) == NC_NOERR) nc_free_string(n, buf);
        } else
            st = nc_get_vara(nc, v, start, count, buf);
        free(buf);
    }
    return st;
}

/* Read back the file at `path` (created as o->dev, o->ino) from its bytes
 * on disk: a copy in memory opened as an in-memory netCDF file, not
 * through HDF5's handle (which may still be open in this process and would
 * answer from its own cache). It reads back when its whole header, the
 * times of all records and the last row of every series read. Returns 1
 * when it reads back (rb filled), 0 when it does not (the file is
 * unusable), -1 when it could not be checked; `why` says why not. Holds the
 * netCDF lock. */
static int read_back(const rc_output *o, readback *rb, char *why, size_t nwhy)
{
    memset(rb, 0, sizeof *rb);
    int fd = open(o->path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    struct stat sb;
    if (fd < 0) {
        snprintf(why, nwhy, "cannot open it: %s", strerror(errno));
        return -1;
    }
    if (fstat(fd, &sb) != 0 || !S_ISREG(sb.st_mode) || sb.st_dev != o->dev || sb.st_ino != o->ino) {
        snprintf(why, nwhy, "the path no longer names the file written");
        close(fd);
        return -1;
    }
    if (sb.st_size == 0) {
        snprintf(why, nwhy, "the file is empty");
        close(fd);
        return 0;
    }
    /* read into memory, not mapped: a mapped page of a file on a full
     * tmpfs that falls on a hole the failed writes left faults (tmpfs
     * allocates the page then) and kills the process with SIGBUS, where
     * read() returns the hole's zeros or an error */
    unsigned char *p = malloc((size_t)sb.st_size);
    if (!p) {
        snprintf(why, nwhy, "no memory to read its %lld bytes", (long long)sb.st_size);
        close(fd);
        return -1;
    }
    for (size_t got = 0; got < (size_t)sb.st_size;) {
        const ssize_t n = pread(fd, p + got, (size_t)sb.st_size - got, (off_t)got);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            snprintf(why, nwhy, "cannot read it: %s", n < 0 ? strerror(errno) : "it became shorter");
            free(p);
            close(fd);
            return -1;
        }
        got += (size_t)n;
    }
    close(fd);
    NC_memio mem = {(size_t)sb.st_size, p, NC_MEMIO_LOCKED};
    int nc, st = nc_open_memio(o->path, NC_NOWRITE, &mem, &nc);
    if (st != NC_NOERR) {
        snprintf(why, nwhy, "netCDF cannot open it: %s", nc_strerror(st));
        free(p);
        return 0;
    }
    int dim, var;
    size_t len = 0;
    if ((st = nc_inq_dimid(nc, "time", &dim)) == NC_NOERR && (st = nc_inq_dimlen(nc, dim, &rb->nrec)) == NC_NOERR)
        st = nc_inq_varid(nc, "time", &var);
    /* the times, in pieces: the records whose time is finite and increasing */
    double piece[4096], prev = -INFINITY;
    int valid = 1;
    for (size_t k = 0; st == NC_NOERR && valid && k < rb->nrec; k += 4096) {
        const size_t start[1] = {k}, count[1] = {rb->nrec - k < 4096 ? rb->nrec - k : 4096};
        if ((st = nc_get_vara_double(nc, var, start, count, piece)) != NC_NOERR) break;
        for (size_t i = 0; i < count[0] && valid; i++) {
            valid = isfinite(piece[i]) && piece[i] >= prev && (k + i > 0 || piece[i] == 0.0);
            if (valid) {
                prev = rb->t_last = piece[i];
                rb->nvalid++;
            }
        }
    }
    char what[192] = "the time axis";
    if (st == NC_NOERR && nc_inq_dimid(nc, "event", &dim) == NC_NOERR) st = nc_inq_dimlen(nc, dim, &rb->nevent);
    if (st == NC_NOERR) st = read_header_and_ends(nc, what, sizeof what);
    /* the completion attributes, which every file has */
    if (st == NC_NOERR) snprintf(what, sizeof what, "attribute complete");
    if (st == NC_NOERR && (st = nc_inq_attlen(nc, NC_GLOBAL, "complete", &len)) == NC_NOERR)
        st = len < sizeof rb->complete ? nc_get_att_text(nc, NC_GLOBAL, "complete", rb->complete) : NC_EINVAL;
    if (st == NC_NOERR) snprintf(what, sizeof what, "attribute status");
    if (st == NC_NOERR && (st = nc_inq_attlen(nc, NC_GLOBAL, "status", &len)) == NC_NOERR) {
        char *t = calloc(len + 1, 1);
        st = t ? nc_get_att_text(nc, NC_GLOBAL, "status", t) : NC_ENOMEM;
        if (st == NC_NOERR) snprintf(rb->status, sizeof rb->status, "%s", t);
        free(t);
    }
    nc_close(nc);
    free(p);
    if (st != NC_NOERR) {
        snprintf(why, nwhy, "netCDF cannot read %s: %s", what, nc_strerror(st));
        return 0;
    }
    return 1;
}

/* Longest a read-back may take before its child process is killed [s]. */
#define RC_READBACK_SECONDS 60.0

/* What read_back says, sent from the child process to the parent. */
typedef struct readback_msg {
    int r;
    readback rb;
    char why[512];
} readback_msg;

/* read_back in a child process: HDF5 parsing the bytes that a filled disk
 * left damaged can read through a garbage pointer (seen: SIGBUS in
 * H5MM_xfree under nc_open_memio), which must not take the program down
 * with it. The calling thread holds the netCDF lock, so no other thread is
 * inside netCDF or HDF5 at the fork; the child only reads, sends its answer
 * through a pipe and leaves with _exit (HDF5's exit-time clean-up would
 * crash on the abandoned handle). A child that dies, or takes longer than
 * RC_READBACK_SECONDS, is a file that does not read back (0). Without a
 * child (fork or pipe failing) the read-back runs here. */
static int read_back_apart(const rc_output *o, readback *rb, char *why, size_t nwhy)
{
    int fds[2];
    if (pipe(fds) != 0) return read_back(o, rb, why, nwhy);
    fflush(NULL);
    const pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        return read_back(o, rb, why, nwhy);
    }
    if (pid == 0) {
        close(fds[0]);
        /* what HDF5 (or a sanitizer) prints of a crash there is not the
         * run's: the parent reports the outcome */
        const int dn = open("/dev/null", O_WRONLY | O_CLOEXEC);
        if (dn >= 0) dup2(dn, 2);
        readback_msg msg;
        memset(&msg, 0, sizeof msg);
        msg.r = read_back(o, &msg.rb, msg.why, sizeof msg.why);
        const char *b = (const char *)&msg;
        for (size_t put = 0; put < sizeof msg;) {
            const ssize_t n = write(fds[1], b + put, sizeof msg - put);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) _exit(3);
            put += (size_t)n;
        }
        _exit(0);
    }
    close(fds[1]);
    readback_msg msg;
    memset(&msg, 0, sizeof msg);
    size_t got = 0;
    int status = 0, reaped = 1;
    const struct timespec nap = {0, 10 * 1000 * 1000}; /* 0.01 s */
    for (double waited = 0.0;; waited += 0.01) {
        const pid_t w = waitpid(pid, &status, WNOHANG);
        if (w == pid) break;
        if (w < 0 && errno != EINTR) {
            /* reaped elsewhere (SIGCHLD ignored by the program): its
             * answer, if whole in the pipe, is all there is */
            reaped = 0;
            break;
        }
        if (waited > RC_READBACK_SECONDS) {
            kill(pid, SIGKILL);
            while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
            }
            close(fds[0]);
            snprintf(why, nwhy, "reading it back took longer than %.0f s", RC_READBACK_SECONDS);
            return 0;
        }
        nanosleep(&nap, NULL);
    }
    /* the child has ended: its answer is whole in the pipe, or missing */
    for (char *b = (char *)&msg; got < sizeof msg;) {
        const ssize_t n = read(fds[0], b + got, sizeof msg - got);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        got += (size_t)n;
    }
    close(fds[0]);
    if (!reaped) status = got == sizeof msg ? 0 : SIGKILL; /* whole: as exited 0; else as killed */
    if (WIFSIGNALED(status)) {
        snprintf(why, nwhy, "netCDF crashed reading it (signal %d, in a child process)", WTERMSIG(status));
        return 0;
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || got != sizeof msg) {
        snprintf(why, nwhy, "the child process reading it ended without an answer");
        return 0;
    }
    *rb = msg.rb;
    snprintf(why, nwhy, "%s", msg.why);
    return msg.r;
}

/* A write failed (o->fail): close the file as far as HDF5 can, read it back
 * from the disk and say what it keeps; a file that does not read back is
 * removed. `closed`: nc_close was already called (and failed). RC_EIO.
 * Holds the netCDF lock. */
static rc_status salvage(rc_output *o, int closed, rc_error *err)
{
    char close_why[256] = "";
    if (!closed) {
        const int s = nc_close(o->ncid);
        if (s != NC_NOERR) snprintf(close_why, sizeof close_why, "%s", nc_strerror(s));
    } else
        snprintf(close_why, sizeof close_why, "it failed at the close");
    /* HDF5 keeps a file it could not close, and its exit-time clean-up
     * would crash on it (rc_output_abandoned) */
    if (close_why[0]) output_abandoned = 1;
    const char *failed = o->fail[0] ? o->fail : "a write of the results file failed";
    readback rb;
    char why[512] = "";
    const int r = read_back_apart(o, &rb, why, sizeof why);
    if (r > 0) {
        char kept[160];
        if (rb.nvalid > 0)
            snprintf(kept, sizeof kept, "records 0 to %zu (t = 0 to %.9g s)", rb.nvalid - 1, rb.t_last);
        else
            snprintf(kept, sizeof kept, "no records");
        char beyond[96] = "";
        if (rb.nrec > rb.nvalid)
            snprintf(beyond, sizeof beyond, "; records %zu to %zu are not valid (never written)", rb.nvalid,
                     rb.nrec - 1);
        RC_RAISE(err, RC_EIO,
                 "%s; the file was then %s and read back from the disk: it keeps %s and %zu event rows%s, "
                 "marked complete = \"%s\" with the status \"%.120s\"%s",
                 failed, close_why[0] ? "left as HDF5 had written it (it could not close it)" : "closed", kept,
                 rb.nevent, beyond, rb.complete, rb.status,
                 strcmp(rb.status, "running") ? "" : " (the closing attributes could not be written)");
    }
    if (r == 0) {
        const int removed = remove(o->path) == 0;
        RC_RAISE(err, RC_EIO, "%s; the file %s and does not read back from the disk (%s): %s; no results were kept",
                 failed, close_why[0] ? "could not be closed whole" : "was closed", why,
                 removed ? "it was removed" : "it could not be removed either");
    }
    RC_RAISE(err, RC_EIO, "%s; the file could not be read back to check it (%s): it may be unreadable", failed, why);
}

static rc_status output_close(rc_output *o, const rc_stats *st, int complete, const char *reason, rc_error *err)
{
    /* the buffered records, then the final attributes and the close; after
     * a failed write, salvage says what the file keeps */
    rc_status rc = flush(o, err);
    int closed = 0;
    if (!o->broken) {
        /* after a refused write (no room), the attributes say so (first error reported) */
        rc_error later;
        rc_error *e = rc == RC_OK ? err : &later;
        const int ok = rc == RC_OK;
        rc_status rc2 = RC_OK;
        o->broken = 1; /* until the file is closed */
        int s = nc_redef(o->ncid);
        if (s != NC_NOERR) rc2 = nc_fail(e, __LINE__, __func__, o->path, s, "entering define mode");
        if (rc2 == RC_OK) rc2 = write_final(o, st, complete && ok && !o->stopped, ok ? reason : err->msg, e);
        int impact_var[I_COUNT];
        const int impacts = o->var[V_INTER_ID] >= 0;
        int persist_var[P_COUNT];
        if (rc2 == RC_OK && impacts) rc2 = define_table(o, "impact", impact_table, I_COUNT, impact_var, e);
        if (rc2 == RC_OK && impacts) rc2 = define_table(o, "persistent", persistent_table, P_COUNT, persist_var, e);
        int phys_var[PV_COUNT];
        if (rc2 == RC_OK && o->phys_set) rc2 = define_physics(o, phys_var, e);
        if (rc2 == RC_OK && (s = nc_enddef(o->ncid)) != NC_NOERR)
            rc2 = nc_fail(e, __LINE__, __func__, o->path, s, "ending definitions");
        if (rc2 == RC_OK && impacts) rc2 = write_tables(o, impact_var, persist_var, e);
        if (rc2 == RC_OK && o->phys_set) rc2 = write_physics(o, phys_var, e);
        if (rc2 == RC_OK) {
            closed = 1;
            if ((s = nc_close(o->ncid)) == NC_NOERR) {
                o->broken = 0;
                return rc;
            }
            rc2 = nc_fail(e, __LINE__, __func__, o->path, s, "closing the file");
        }
        if (!o->fail[0]) snprintf(o->fail, sizeof o->fail, "%.2000s", e->msg);
    }
    return salvage(o, closed, err);
}

rc_status rc_output_close(rc_output *o, const rc_stats *st, int complete, const char *reason, rc_error *err)
{
    if (!o) return RC_OK;
    rc_error local;
    if (!err) err = &local;
    rc_nc_lock();
    const rc_status rc = output_close(o, st, complete, reason, err);
    rc_nc_unlock();
    output_free(o);
    return rc;
}
