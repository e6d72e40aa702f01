/*
 * The run data of the engine: what changes while a model runs, next to
 * the immutable rc_model. Modes, bands and history (rc_data) change only
 * at the start and at events (engine/events); the right-hand side, the
 * Jacobian and the root functions take rc_data const and write only what
 * it reaches through sc (rc_scratch: caches, scratch, counters), so the
 * compiler holds them to it (docs/design.md, "Pipeline and files").
 */
#ifndef RC_ENGINE_DATA_H
#define RC_ENGINE_DATA_H

#include <stdint.h>

#include "model/model.h"

/* What the right-hand side, the Jacobian and the root functions may write
 * (rc_data.sc): caches, scratch and counters. They take the run data const;
 * only what is reached through sc is theirs to write. */
typedef struct rc_scratch {
    double *pt_share;    /* [npt] each contact point's share w_j at the last evaluation of the
                            roots (the integrator's step ends; 0 while its interface is not
                            closed): its states' error weights (rc_point_ewt_scale) */
    double *inter_fnr;   /* [ninter] the normal force of each closed interface at the last
                            root evaluation, 0 when not closed [N] (the interface sensors' roots) */
    double *inter_flim;  /* [2 ninter] the friction limit [N] and the sliding speed |v_t|
                            [m/s] of each interface whose single incremental friction state
                            slips, at the last evaluation of the roots (0: not closed,
                            sticking, no such state): the slip law's Jacobian rows turn the
                            state at K_t |v_t| / L_r (cvode.c, limits_moved) */
    void *pt_work;       /* Jacobian scratch of the contact points (complex) */
    void *node_cache;    /* node geometry of a node pair, RC_NODE_CACHE complex
                            values per point (kernels.inc, seg_fill); it
                            follows seg_hint in one allocation */
    unsigned char *node_only; /* [points of the largest node pair] the points a
                            complex-step Jacobian column computes into the node
                            cache (assemble_jac.c, point_mask); it follows the
                            node cache */
    int *seg_hint;       /* [rc_seg_hint_len] the segment each surface node met
                            last, -1: none (geom_seg.inc, node_seg) */
    double *imp_free;    /* [ny] imposed velocities: the free accelerations of
                            their rows at the last rhs (imposed.h), NULL: none */
    double *imp_scratch; /* [3*ny] imposed velocities: Jacobian scratch */
    /* the interfaces' dense Jacobian blocks as the last rc_assemble_jac
     * added them (rc_jac_refresh_inter); NULL when the model had no
     * Jacobian pattern yet */
    double *jcache;      /* [sum of nrow*ncol of jb_inter] */
    int64_t *jcache_off; /* [ninter + 1] offsets into jcache */
    int jcache_ok;       /* jcache holds the blocks of the values last assembled */
    /* the reports of the last root evaluation (rc_report_cache_*): read by
     * the driver's samples at the same state; NULL: none */
    struct rc_repcache *repc;
    long n_rhs, n_jac, n_root;
    long n_jac_refresh;  /* interface blocks refreshed after events */
    int fail_inter;      /* element that produced a non-finite force, -1 */
    double fail_t;
} rc_scratch;

/* The run data: modes, bands and history, changed only at the start and
 * at events (engine/events) and by the backends' settings; the
 * evaluation's own writable part behind sc. */
typedef struct rc_data {
    int *inter_mode;     /* [ninter] rc_inter_mode */
    int *inter_branch;   /* [ninter] rc_branch (Iform 1, 2) */
    int *inter_track;    /* [ninter] 1: Inacti 5 offset follows the separation */
    int *inter_slip;     /* [ninter] friction: 0 stick, 1 slip */
    int *pt_slip;        /* [npt] friction per contact point: 0 stick, 1 slip */
    double *pt_lband;    /* [npt] each contact point's landing band [m]: its landing root is
                            q_j + band, set at its landing so that the root it crossed
                            does not cross again at the same instant; kept through
                            the interface's other events, 0 again when its contact
                            changes (events.c) */
    void *pt_flip;       /* scratch of the contact points' stick/slip flips at events
                            (events.c points_flip): 3 doubles, an int, a flag per point */
    double *inter_dref;  /* [ninter*3] sliding direction when a stateless friction
                            law saturated (reversal root) [-] */
    double *inter_hacc;  /* [ninter*2] an elastic law that can release at P > 0
                            (rc_inter_release_ledger): the hysteresis it has
                            dissipated [J], and the energy it stored when it
                            last released (while released) [J]; set at the
                            start and at its mode changes (events.c) */
    int *mode_was;       /* [ninter] scratch of the events: the modes before */
    double *sens_ton;    /* [nsens] a distance sensor's time on (its trigger time plus
                            Tdelay, latched), INFINITY until it triggers (events.c) */
    double *sens_arm;    /* [2*nsens] a sensor with Tmin whose criterion holds: the time
                            it began to hold [s] (NAN: it does not) and the side it
                            left its bounds by (1: above Dmax or Fmax, -1: below
                            Dmin) (events.c) */
    int *sens_new;       /* [nsens] bit 1: triggered at the last event, bit 2: released
                            its held bodies then, not yet written (the driver
                            writes the events and clears it) */
    double t_bp;         /* the time breakpoint the run last restarted at [s]
                            (-INFINITY: none yet): at t == t_bp an imposed
                            velocity starting there is on (the right limit;
                            RC_IMP_T_ON), and so is a gravity switched on
                            there by its sensor (rc_gravity_factor_run) */
    int *sens_rel;       /* [nsens] 1: a sensor found in the run that holds bodies
                            (rc_model.sens_hold) has released them (set at the
                            event of its time on; the imposed rows read it) */
    double *inter_fcstr; /* [ninter] the normal force a settled contact's
                            constraint carries (IDA path, engine/constraints/stick.c;
                            set at records, 0 otherwise) [N] */
    int *inter_settled;  /* [ninter] 1: a closed contact held in persistent contact
                            after its bounces accumulated (the release at zero
                            force suspended; it opens when P returns to 0;
                            docs/theory.md 5.2); set by the driver, cleared when
                            the mode leaves CLOSED */
    int *inter_lowq;     /* [ninter] 1: a lightly damped contact whose modes
                            chatter, events in a row within a few periods of
                            its stiffest line (settle.c, rc_settle_lowq): while
                            it stays closed the CVODE backend restarts at BDF
                            order at most 2 (docs/theory.md 7.7); cleared when
                            the mode leaves CLOSED */
    int *inter_deck;     /* [ninter] 1 until the interface's first event after the
                            start: its touch band covers the rounding of the
                            deck's coordinates (its bodies still where the deck
                            put them; events.c) */
    double *inter_band;  /* [ninter*2] signed touch bands of a contact left at
                            zero penetration or zero force (events.c): zone root
                            P + band[0] [m] (closed or released: +band, it
                            separates at P = -band; open: -band, it closes at
                            P = +band), force root F_n + band[1] [N] (closed:
                            +fband; released: -fband); 0 otherwise */
    double *inter_rband; /* [ninter] the rate root band of the power law's RDF branch and of
                            a TYPE6 hysteresis curve [m/s]: root (that rate) +
                            band, signed (LOAD: +band, the rebound waits for the rate to
                            fall below -band; UNLOAD: -band), set where the branch was
                            decided at a rate within its rounding (events.c); 0 again
                            at the interface's next event */
    int fric_turned;     /* 1: an event since the last restart turned a slipping
                            friction state against its sliding (fric_turn, or
                            a contact point's refused stick: events.c); the CVODE backend restarts at BDF order
                            at most 2 then (docs/theory.md 3.5) and clears it */
    int multi_closed;    /* 1: an event since the last restart closed a damped contact
                            of several points (a box's, a meshed surface's);
                            the CVODE backend restarts at BDF order at most 3
                            then (docs/theory.md 7.7) and clears it */
    struct rc_cpl_data *cpl; /* couplings: catenary warm starts, workspace (coupling.h) */
    const char *jac_skip; /* [ny] set by a backend that leaves these states out
                            of its Newton matrix (cvode.c): the Jacobian's
                            columns of these states are not evaluated (their
                            values are left 0); NULL: every column */
    long n_klu_sym;      /* KLU symbolic analyses of the Newton matrix so far (0: not counted) */
    long newton_nnz;     /* entries of the largest Newton matrix so far (0: not counted) */
    rc_scratch *sc;      /* what an evaluation writes */
} rc_data;

/* The reports of the last root evaluation (rc_scratch.repc): the state they
 * were evaluated at, and per interface its report and the modes it was
 * evaluated in (rc_assemble_roots writes it; engine/assembly/assemble_rhs.c). */
typedef struct rc_repcache {
    double *y;                   /* [ny] the state of the evaluation */
    int on;                      /* kept (set by the driver while it samples) */
    int ok;                      /* y holds a state */
    struct rc_inter_report *rep; /* [ninter] */
    int *key;                    /* [4 ninter] mode, branch, track, slip; mode -1: not evaluated */
    int *pslip;                  /* [npt] the contact points' modes of the evaluation */
} rc_repcache;

/* What the output and the event logic see of one interface. */
typedef struct rc_inter_report {
    double p;            /* penetration past the (effective) Gap [m] */
    double vn;           /* approach rate dp/dt [m/s] */
    double p_raw;        /* penetration past the nominal Gap [m] */
    double vn_raw;       /* its rate [m/s] */
    double pl, vl;       /* the law's penetration and rate: p and vn, or with
                            several contact points P_e and v_bar [m], [m/s] */
    double vd;           /* the rate the damping acts on: vn, or v_bar with
                            several contact points (vl before P_e's relaxation
                            and recovery) [m/s] */
    double fload;        /* elastic(-plastic) force F of the law [N] */
    double fdamp;        /* damping force [N] */
    double fn;           /* total normal force F + F_damp, unclipped [N] */
    double fl, fu;       /* load and unload curves at P [N] */
    double fh;           /* hysteresis state F_h (0 when absent) [N] */
    double offset;       /* Inacti 5 gap reduction [m] */
    double ft[3];        /* friction force on body a, applied [N] */
    double fraw[3];      /* friction force of the law, before the filter [N] */
    double flim;         /* friction limit Sfric + mu F_n [N] */
    double mu;           /* the coefficient mu of F_n in that limit at the state
                            (several contact points: the largest) [-] */
    double fstored;      /* energy in the stick springs, |F_t|^2 / (2 K_t) per
                            contact point (K_t its share) [J] */
    double ftan;         /* |F_t| of the friction state in the tangent plane,
                            the part fstored counts (one state; 0 with friction
                            per contact point: rc_points_eval has theirs) [N] */
    double vslip;        /* sliding speed |v_t| [m/s] */
    double slip_root;    /* stick: |F_t|^2 - F_lim^2; slip: v_t . e */
    double vt[3];        /* tangential relative velocity at the contact point [m/s] */
    double point[3];     /* contact point [m] */
    double normal[3];    /* unit normal, from a to b [-] */
} rc_inter_report;

rc_data *rc_data_new(const rc_model *m);
void rc_data_free(rc_data *d);

/* Name of the coupling whose forces failed in the last right-hand side or
 * Jacobian, NULL when none. */
const char *rc_cpl_failed(const rc_model *m, const rc_data *d);

#endif
