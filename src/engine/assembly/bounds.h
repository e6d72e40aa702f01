/*
 * The scene's own scales for the physics checks of every run, the bounds
 * derived from them, and the check of the start (docs/theory.md, "Physics
 * checks of every run"). Computed once from the compiled model at t = 0;
 * the run-time checks (solver/guards.c) read them.
 */
#ifndef RC_BOUNDS_H
#define RC_BOUNDS_H

#include "model/model.h"
#include "engine/assembly/data.h"

/* A penetration is beyond its contact's scales when the law's force there
 * reaches RC_PEN_FORCE_FACTOR times the larger of the scene's weight and
 * the impact force at the scene's energy [-]. */
#define RC_PEN_FORCE_FACTOR 1e3
/* Two spheres' centres closer than RC_SPHERE_CENTRE_FRAC (R1 + R2) [-]. */
#define RC_SPHERE_CENTRE_FRAC 0.5
/* A contact of several points is behind its geometry when its points
 * penetrate by more than its law's penetration P_e plus RC_DEFICIT_FACTOR
 * max(P_e^max, p_s), P_e^max the largest since the contact closed
 * (docs/theory.md 2.7, 13.2) [-]. */
#define RC_DEFICIT_FACTOR 10.0
/* A start overlap is refused when the elastic energy it holds exceeds
 * RC_START_ENERGY_FACTOR times the scene's energy scale E_s [-]. */
#define RC_START_ENERGY_FACTOR 1.0

/* Scales of the scene at t = 0 [SI]. */
typedef struct rc_scene {
    double mass;    /* total mass of the free bodies [kg] */
    double gmax;    /* largest gravity acceleration over the run [m/s^2] */
    double lmax;    /* largest body size (centre to the farthest point of its surfaces) [m] */
    double height;  /* extent of the scene along gravity (bodies, surfaces, nodes) + 2 lmax [m] */
    double ekin0;   /* kinetic energy at t = 0 [J] */
    double vimp;    /* largest imposed speed [m/s] */
    double escale;  /* E_s = max(ekin0, mass gmax lmax) [J] */
    double eavail;  /* energy the scene can put into one contact: ekin0 + mass gmax height
                       + mass vimp^2 / 2 [J] */
    double weight;  /* mass gmax [N] */
} rc_scene;

/* The scene's scales of model m (at its initial state). */
void rc_scene_scales(const rc_model *m, rc_scene *s);
/* Size of body b: the largest distance from its centre to the far side of
 * one of its surfaces [m] (0 without surfaces). */
double rc_body_size(const rc_model *m, int b);
/* The sizes of all bodies into size[nbody] (one pass over the surfaces;
 * rc_body_size of each) [m]. */
void rc_body_sizes(const rc_model *m, double *size);
/* A band about P = 0 of interface i at the state y with its report r [m]:
 * ulps roundings of the coordinates involved (the pair's centres and the
 * contact point), with deck at least RC_TOL_DECK_ULPS roundings of the
 * same in the deck's coordinates, and rel times the penetration scale. */
double rc_touch_band(const rc_model *m, int i, const double *y, const rc_inter_report *r, double ulps, double rel,
                     int deck);
/* The load law of interface i (no hysteresis, no damping) at penetration
 * p >= 0: its force [N] and its energy integral_0^p F [J]. */
double rc_law_force(const rc_model *m, int i, double p);
double rc_law_energy(const rc_model *m, int i, double p);
/* Smallest p > 0 where the law's force (energy = 0) or energy (energy = 1)
 * reaches target > 0 [m]; NAN when it never does. */
double rc_law_reach(const rc_model *m, int i, int energy, double target);
/* The penetration bound of interface i [m]: where its law's force reaches
 * RC_PEN_FORCE_FACTOR max(weight, F_imp) (F_imp the force where its
 * energy reaches s->eavail), and at most the size of the smaller body of
 * the pair (beyond it a body has passed through); INFINITY when neither
 * exists. size: the bodies' sizes (rc_body_size; NULL: computed here).
 * *fbound receives the force limit [N] (NAN: none). */
double rc_pen_bound(const rc_model *m, int i, const rc_scene *s, const double *size, double *fbound);


#endif
