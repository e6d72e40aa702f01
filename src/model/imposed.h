/*
 * Imposed velocities (/IMPVEL, docs/theory.md 1.1): a velocity
 * component of a body follows Fscale f(t / Ascale) for Tstart < t <= Tstop
 * (a translation with Tstart > 0 is free before; at Tstart, a time
 * breakpoint, its velocity jumps to Fscale f(Tstart / Ascale): rc_imp_start).
 * With a sensor (sensor_ID, a time known when compiling, Ts): imposed for
 * Ts < t <= Tstop as Fscale f((t - Ts) / Ascale), the function shifted by
 * Ts (ttshift), the jump at Ts to Fscale f(0).
 *
 * Like the held DOFs of /BCS, an imposed component is a velocity state
 * whose rate the right-hand side overwrites, here with the derivative of the
 * imposed function (its initial value is set at compile time), and whose
 * Jacobian row is replaced accordingly; the support supplies whatever force
 * that takes (the reaction).
 *
 * Along a skew axis u (skew_ID, translations): the velocity component u.v
 * follows the function and the others are free; the translational mass
 * being isotropic, the support's force is lambda u with
 * lambda = m (f' - u.a_free): the three rates become
 * a_free + u (f' - u.a_free), their Jacobian rows (I - u u^T) the free ones
 * (a body with a skewed card has no other imposed or held translation).
 * A /BCS with a skew holding one or two of Tx Ty Tz holds the velocity along
 * each held skew axis at zero the same way (an entry whose function is
 * zero, ttab -1), beside at most one skewed /IMPVEL of the body: orthogonal
 * axes, so that their projections applied one after the other are the
 * projection on the free ones and each lambda u.a_free is measured on the
 * body's free rates (those before its first skewed entry, tfirst).
 *
 * Rotations: the angular velocity state is in the body frame. A body with a
 * rotational /IMPVEL has its whole angular velocity imposed in global axes,
 * w_g(t) = (f_XX, f_YY, f_ZZ) over its rotational cards (components without
 * a card are zero): the body-frame state follows omega = R(q)^T w_g(t) with
 * rate R(q)^T dw_g/dt (the term omega x omega of d(R^T w_g)/dt vanishes on
 * that path). So a roller spins about a fixed global axis and cannot tilt.
 *
 * Energy: one state W_imp with dW_imp/dt = -(power of the reactions), so
 * that the ledger (kinetic + ... + W_imp) still closes: for an imposed
 * translation the reaction is m (a_imposed - a_free), for an imposed
 * rotation the torque J (omegadot_imposed - omegadot_free) (body frame),
 * a_free being the acceleration the applied forces alone would give.
 */
#ifndef RC_IMPOSED_H
#define RC_IMPOSED_H

#include <stdint.h>

#include "model/model.h"

/* Is imposed translation k (rotation j) held at t? Within its window and,
 * for a sensor hold, not yet released (rel: rc_data.sens_rel, set at the
 * sensor's event). A translation's window is (Tstart, Tstop] until the
 * run restarted at the time breakpoint Tstart, [Tstart, Tstop] after
 * (tbp: rc_data.t_bp), so that the restarted integration starts from the
 * right limit, the imposed rate (a function whose slope changes soon
 * after Tstart is then followed from the first step). */
#define RC_IMP_T_ON(p, k, t, rel, tbp)                                                                              \
    (!((t) > (p)->ttstop[k] || (t) < (p)->ttstart[k] || ((t) == (p)->ttstart[k] && (tbp) < (t))) &&              \
     ((p)->tsens[k] < 0 || !(rel)[(p)->tsens[k]]) && ((p)->tson[k] < 0 || (rel)[(p)->tson[k]]))
/* The shift of imposed translation k's function [s]: its sensor's time on
 * found in the run (ton: rc_data.sens_ton), else ttshift. */
#define RC_IMP_T_SHIFT(p, k, ton) ((p)->tson[k] >= 0 ? (ton)[(p)->tson[k]] : (p)->ttshift[k])
#define RC_IMP_R_ON(p, j, t, rel) (!((t) > (p)->rtstop[j]) && ((p)->rsens[j] < 0 || !(rel)[(p)->rsens[j]]))

typedef struct rc_imposed {
    /* imposed translations */
    int nt;
    int *tbody;          /* [nt] body index                                 */
    int *tdir;           /* [nt] 0, 1, 2: X, Y, Z; -1: along tu (a skew axis) */
    int *trow;           /* [nt] state index of the velocity component (skew:
                            of the x component, the body's three rows)      */
    double *tu;          /* [nt*3] the direction, a global unit vector      */
    int *tsk;            /* [nt] index among the skewed cards, -1 for a global axis */
    int nsk;             /* skewed cards                                     */
    int64_t *sslot;      /* [nsk*3*ny] Jacobian slots of (row x, y, z, column), -1 absent */
    int *ttab;           /* [nt] table index of the time function; -1: a
                            translation held at zero along a skew axis by
                            /BCS (tbcs)                                      */
    int *tbcs;           /* [nt] the id of the /BCS holding it, 0: /IMPVEL   */
    char *tfirst;        /* [nt] 1: the first skewed entry of its body (whose
                            free rates the right-hand side keeps)            */
    double *tascale, *tfscale, *ttstop; /* [nt] [s] [m/s] [s]               */
    double *ttstart;     /* [nt] Tstart [s]: imposed for ttstart < t <= ttstop;
                            -INFINITY (Tstart <= 0) from t = 0 on; with a
                            sensor (sensor_ID), the sensor's time on     */
    double *ttshift;     /* [nt] [s] the function's shift: Fscale f((t -
                            ttshift) / Ascale); a sensor's time on, else 0 */
    int *tson;           /* [nt] a start by a sensor found in the run (/IMPVEL
                            sensor_ID: a distance or interface sensor, or a
                            logic sensor of one): free until its event
                            (rc_data.sens_rel), then imposed as Fscale
                            f((t - t_on) / Ascale), t_on its time on
                            (rc_data.sens_ton); the velocity jumps at the
                            event (rc_imp_start_sens); -1: none */
    int *tsens;          /* [nt] a sensor hold (model/sensor.c) that ends when
                            sensor tsens is on, a time found in the run
                            (rc_data.sens_rel; ttstop INFINITY); -1: none    */
    /* bodies with an imposed rotation (all three components) */
    int nr;
    int *rbody;          /* [nr] body index                                 */
    int *rtab;           /* [nr*3] table of the XX, YY, ZZ function, -1: zero */
    double *rascale, *rfscale; /* [nr*3] [s] [rad/s]                        */
    double *rtstop;      /* [nr] [s]                                        */
    int *rsens;          /* [nr] as tsens                                   */
    int64_t *rqslot;     /* [nr*12] Jacobian slots (omega row k, q column j) */
    /* the work state and its Jacobian row */
    int wadr;            /* state index of W_imp                            */
    int64_t *wslot;      /* [ny] slot of (wadr, column), -1 when absent      */
    char *row_imp;       /* [ny] 1 for an imposed velocity row               */
} rc_imposed;

struct rc_case;
/* /IMPVEL cards into m->imp (NULL when there are none); after the bodies,
 * before the state layout. Sets the initial velocities. */
rc_status rc_imp_compile(const struct rc_case *c, rc_model *m, rc_error *err);
/* State rows and W_imp after the other states; returns the new count. */
int rc_imp_layout(rc_model *m, int ny);
/* Jacobian pattern (jacpattern.c): append the keys (col * ny + row) of the
 * imposed rows' dependence on q and of the W_imp row; *key is grown. */
rc_status rc_imp_pattern_keys(const rc_model *m, int64_t **key, int64_t *n, rc_error *err);
/* After the CSC pattern is built: the slots used by rc_imp_jac. */
rc_status rc_imp_slots(rc_model *m, rc_error *err);
/* The largest speed imposed translation k reaches [m/s]: |Fscale| times
 * the largest |f| of its curve; 0 for a /BCS hold (ttab -1). */
double rc_imp_tspeed(const rc_model *m, int k);
/* The largest angular speed imposed rotation k reaches about axis j (0..2)
 * [rad/s]: |Fscale| times the largest |f| of its curve; 0 without a curve. */
double rc_imp_rrate(const rc_model *m, int k, int j);
void rc_imp_free(rc_imposed *imp);
void rc_imp_print(const rc_model *m, FILE *f);
/* The rotation imposed rotation j turns its body by from t = 0 to t (held
 * up to its Tstop), a unit quaternion e (w, x, y, z) about global axes
 * (the body's orientation is then e (x) q(0)): the solution of
 * de/dt = 1/2 (0, w_g(t)) (x) e, w_g the global angular velocity Fscale
 * f(t / Ascale) per component; exp(Phi) with Phi its integral when one
 * component is imposed (the axis keeps its direction), else integrated by
 * GSL's Runge-Kutta Prince-Dormand 8(9) between the points of the time
 * functions (docs/theory.md 7.8). Returns 0, or -1 when the integration
 * failed (e is then NaN). */
int rc_imp_rotation(const rc_model *m, int j, double t, double e[4]);

#endif
