/*
 * Contact coupling (/COUPLING/CONTACT, STAR-CCM+ style; docs/theory.md
 * "Contact coupling"): per boundary face f of a body's segment surface, at
 * distance d_f from its centroid to the opposing boundary (an analytic
 * surface, fixed or on another body), within the effective range d0:
 *   f_n = a_f (k1 (d0 - d_f) - k2 dd_f/dt)      along the boundary normal,
 *         acting while positive (the face is released when it would pull),
 *   f_t = -mu f_n tanh(k_t |v_t|) v_t/|v_t|     against the sliding,
 * summed over the faces with their moments. Part of rc_couplings (kind
 * RC_CPL_CONTACT, reached as cpl->ct); face modes in rc_cpl_data.fmode.
 *
 * Energy states (RC_CE at cpl->eadr[k]): [0] work of the elastic parts
 * a_f k1 (d0 - d_f) against the distance, [1] energy dissipated by the
 * dampers and the friction.
 */
#ifndef RC_COUPLING_CONTACT_H
#define RC_COUPLING_CONTACT_H

#include <stdio.h>

#include "model/model.h"

struct rc_case;

/* Face modes (rc_cpl_data.fmode). */
enum { RC_FACE_OUT = 0, RC_FACE_PUSH = 1, RC_FACE_RELEASED = 2 };
/* Root functions per face: d - d0, the unclipped normal force. */
#define RC_FACE_ROOTS 2
/* Values per face (face[RC_FACE_NV f ...]): centroid (3) and unit outward
 * normal (3) in the body frame [m] [-], area [m^2]. */
#define RC_FACE_NV 7

typedef struct rc_cpl_contact {
    int nface;          /* faces of all contact couplings                       */
    int *fadr;          /* [n + 1] first face of coupling k (couplings of other
                           kinds have none)                                     */
    double *face;       /* [RC_FACE_NV nface]                                   */
    int *sf1, *sf2;     /* [n] the body's segment surface, the opposing surface  */
    double *side;       /* [n] +1 outside the opposing surface (plane: its
                           normal side), -1 inside (plane: the other side)       */
    double *d0, *k1, *k2, *mu, *kt; /* [n] [m] [N/m^3] [N s/m^3] [-] [s/m]       */
    int *est;           /* [n] 1: k1, k2 from the estimator                    */
    double *vimp, *dmin, *zeta, *area; /* [n] estimator inputs                  */
    double *mred;       /* [n] mass of the estimator (body-environment: m1;
                           body-body: m1 m2/(m1 + m2)) [kg]                     */
    double *tau;        /* [n] stopping time (pi/2) sqrt(m_red/(A k1)) with A the
                           estimator's area, or the total face area [s]          */
    double *atot;       /* [n] total face area [m^2]                            */
} rc_cpl_contact;

/* model/coupling_contact.c */
rc_status rc_cpl_contact_alloc(rc_model *m, rc_error *err);
rc_status rc_cpl_contact_compile(const struct rc_case *c, rc_model *m, int k, rc_error *err);
void rc_cpl_contact_free(rc_cpl_contact *ct);
/* Total number of root functions of the couplings. */
int rc_cpl_nroots(const rc_model *m);
#endif
