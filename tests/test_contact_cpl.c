/*
 * Contact couplings (/COUPLING/CONTACT; model/coupling_contact.c,
 * engine/kernels/contact_coupling.inc): the faces of a segment surface, the
 * estimators, the Jacobian against finite differences (plane, box from
 * inside, cylinder, a sphere and a segment surface on another body, a fixed
 * segment surface; damping and friction; every face pushing, and mixed
 * modes), the face modes and roots, the errors.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "model/coupling.h"
#include "model/coupling_contact.h"
#include "model/model.h"
#include "harness.h"
#include "testutil.h"
#include "engine/assembly/assembly.h"
#include "engine/events/events.h"

static rc_model *load(const char *path)
{
    rc_model *m = NULL;
    rc_error e;
    if (tu_load_compile(path, &m, &e) != RC_OK) {
        fprintf(stderr, "  %s\n", e.msg);
        return NULL;
    }
    return m;
}

/* Faces: three quadrilaterals and a triangle of the 0.2 m plate. */
static void test_contact_cpl_faces(void)
{
    rc_model *m = load("tests/data/contact_cpl.rad");
    ENSURE(m);
    if (!m) return;
    const rc_cpl_contact *ct = m->cpl->ct;
    ENSURE(m->cpl->n == 6 && ct->nface == 24);
    ENSURE(ct->fadr[0] == 0 && ct->fadr[1] == 4 && ct->fadr[6] == 24);
    /* the plate is nearly flat: 3 quadrilaterals of 0.01 m^2 and a triangle of 0.005 m^2 */
    double a = 0;
    for (int f = 0; f < 4; f++) a += ct->face[RC_FACE_NV * f + 6];
    ENSURE_NEAR(a, 0.035, 1e-4, 0);
    ENSURE_NEAR(ct->atot[0], a, 1e-14, 0);
    ENSURE(ct->side[0] == 1.0 && ct->side[1] == -1.0 && ct->side[2] == 1.0 && ct->side[3] == 1.0 &&
           ct->side[4] == 1.0 && ct->side[5] == 1.0);
    ENSURE(m->cpl->b1[3] == 0 && m->cpl->b2[3] == 1 && m->cpl->b2[0] == -1);
    ENSURE_NEAR(ct->mred[3], 2.0 / 3.0, 1e-15, 0);
    rc_model_free(m);
}

/* The Jacobian of the six couplings against central differences, at a
 * state with every body moving, every face pushing, then in mixed modes. */
static void test_contact_cpl_jacobian_matches_finite_differences(void)
{
    rc_model *m = load("tests/data/contact_cpl.rad");
    ENSURE(m);
    if (!m) return;
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double));
    rc_initial_state(m, y);
    /* a rotated plate and ball */
    const double q1[4] = {0.99, 0.05, -0.08, 0.03}, q2[4] = {0.97, -0.1, 0.12, 0.2};
    for (int k = 0; k < 4; k++) {
        y[m->body_yadr[0] + 3 + k] = q1[k];
        y[m->body_yadr[1] + 3 + k] = q2[k];
    }
    rc_modes_init(m, d, 0.0, y);
    const rc_cpl_contact *ct = m->cpl->ct;
    int bad = 0, outside = 0;
    double maxerr = 0;
    for (int pass = 0; pass < 3; pass++) {
        for (int f = 0; f < ct->nface; f++)
            d->cpl->fmode[f] = pass == 0 ? RC_FACE_PUSH : pass == 1 ? (f % 3 == 0 ? RC_FACE_RELEASED : RC_FACE_PUSH)
                                                                     : (f % 2 ? RC_FACE_OUT : RC_FACE_PUSH);
        maxerr = fmax(maxerr, tu_jac_fd_error(m, d, 0.0, y, 1, &bad, &outside));
    }
    printf("    contact couplings: max scaled |J - FD| %.2e, %d bad, %d outside the pattern\n", maxerr, bad, outside);
    ENSURE(bad == 0 && outside == 0);
    /* a dropped derivative would show: the check can fail */
    ENSURE(maxerr < 1e-6);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

/* Roots: d - d0 and the unclipped force per face; their directions by mode. */
static void test_contact_cpl_roots(void)
{
    rc_model *m = load("tests/data/contact_cpl.rad");
    ENSURE(m);
    if (!m) return;
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double));
    rc_initial_state(m, y);
    rc_modes_init(m, d, 0.0, y);
    const int off = rc_root_cpl_base(m), nr = rc_root_count(m);
    ENSURE(rc_cpl_nroots(m) == 48);
    double *g = calloc((size_t)nr, sizeof(double));
    int *dir = calloc((size_t)nr, sizeof(int));
    rc_assemble_roots(m, d, 0.0, y, g);
    rc_cpl_root_dirs(m, d, dir + off);
    for (int f = 0; f < 24; f++) {
        ENSURE(g[off + 2 * f] < 0);                         /* every face within d0 = 2 m */
        ENSURE(d->cpl->fmode[f] != RC_FACE_OUT);
        ENSURE(dir[off + 2 * f] == 1);                      /* leaving is the next event */
        ENSURE((g[off + 2 * f + 1] > 0) == (d->cpl->fmode[f] == RC_FACE_PUSH));
    }
    free(g);
    free(dir);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

/* A 2 kg plate (four nodes, its bottom a /SURF/SEG of area 0.04 m^2) above
 * a floor, /COUPLING/CONTACT with Iest 1, d0 = 0.01 m: the deck up to the
 * estimator line (V_imp, d_min, zeta, A), which the tests append. */
#define ESTIMATOR_DECK_HEAD \
    "/BEGIN\nestimators\n      2022         0\n                  kg                   m                   s\n" \
    "                  kg                   m                   s\n" \
    "/NODE\n         1                   0                   0                0.02\n" \
    "        10                -0.1                -0.1                0.02\n" \
    "        11                 0.1                -0.1                0.02\n" \
    "        12                 0.1                 0.1                0.02\n" \
    "        13                -0.1                 0.1                0.02\n" \
    "/GRNOD/NODE/1\nplate\n        10        11        12        13\n" \
    "/RBODY/1\nplate\n         1                                                 2         1\n" \
    "                0.01                0.01                0.02\n                   0                   0                   0\n" \
    "/SURF/SEG/5\nbottom\n         1        10        11        12        13\n" \
    "/SURF/PLANE/2\nfloor\n                   0                   0                   0\n" \
    "                   0                   0                   1\n" \
    "/COUPLING/CONTACT/1\nestimated\n         5         2         0         1\n                0.01\n"

/* The estimators: k1 = m v^2 / (A (d0 - d_min)^2), k2 = 2 zeta sqrt(m k1 / A),
 * tau = (pi/2) sqrt(m / (A k1)). */
static void test_contact_cpl_estimators(void)
{
    static const char *deck =
        ESTIMATOR_DECK_HEAD
        "                   3               0.002                 0.1                0.04\n"
        "/RUN\n                0.05               0.001\n/END\n";
    rc_error e;
    rc_model *m = tu_compile_text(deck, "estimators.rad", &e);
    ENSURE(m);
    if (!m) return;
    const rc_cpl_contact *ct = m->cpl->ct;
    const double k1 = 2.0 * 9.0 / (0.04 * 0.008 * 0.008);
    ENSURE_NEAR(ct->k1[0], k1, 1e-14, 0);
    ENSURE_NEAR(ct->k2[0], 2 * 0.1 * sqrt(2.0 * k1 / 0.04), 1e-14, 0);
    ENSURE_NEAR(ct->tau[0], 0.5 * 3.14159265358979323846 * sqrt(2.0 / (0.04 * k1)), 1e-14, 0);
    ENSURE_NEAR(ct->atot[0], 0.04, 1e-14, 0);
    rc_model_free(m);
}

/* `ricochet check`: the estimated values, tau, the warning when Dt_out
 * cannot resolve tau (Dt_out 0.01 s against tau = 0.0126 s), the cost. */
static void test_contact_cpl_check_prints_estimators(void)
{
    static const char *deck =
        ESTIMATOR_DECK_HEAD
        "                   1               0.002                 0.1                0.04\n"
        "/RUN\n                0.05                0.01\n/END\n";
    rc_error e;
    rc_model *m = tu_compile_text(deck, "estimators_check.rad", &e);
    ENSURE(m);
    if (!m) return;
    FILE *f = tmpfile();
    ENSURE(f);
    if (!f) {
        rc_model_free(m);
        return;
    }
    rc_model_print_summary(m, f);
    static char out[16384];
    rewind(f);
    size_t n = fread(out, 1, sizeof out - 1, f);
    out[n] = 0;
    fclose(f);
    ENSURE(strstr(out, "/COUPLING/CONTACT/1") && strstr(out, "1 face (0.04 m^2)"));
    ENSURE(strstr(out, "k1 = m_red V^2/(A (d0 - d_min)^2) = 781250 N/m^3"));
    ENSURE(strstr(out, "stopping time tau = (pi/2) sqrt(m_red/(A k1)) = 0.012566 s"));
    ENSURE(strstr(out, "WARNING: the output interval Dt_out = 0.01 s cannot resolve tau"));
    ENSURE(strstr(out, "cost: about 150 steps per impact"));
    rc_model_free(m);
}

/* Errors naming the field: an analytic surface for surf_ID1, an opposing
 * segment surface (not supported yet). */
static void test_contact_cpl_errors(void)
{
    rc_model *m = NULL;
    rc_error e;
    ENSURE(tu_load_compile("tests/data/contact_cpl.rad", &m, &e) == RC_OK);
    rc_model_free(m);
    static char buf[16384];
    FILE *fp = fopen("tests/data/contact_cpl.rad", "r");
    ENSURE(fp);
    if (!fp) return;
    size_t n = fread(buf, 1, sizeof buf - 1, fp);
    fclose(fp);
    buf[n] = 0;
    /* coupling 1 against the plate itself: same body */
    char *p = strstr(buf, "/COUPLING/CONTACT/1\nplate - floor\n         5         6");
    ENSURE(p);
    if (!p) return;
    char *q = p + strlen("/COUPLING/CONTACT/1\nplate - floor\n");
    memcpy(q, "         9         6", 20); /* surf_ID1 = the sphere: not a segment surface */
    m = tu_compile_text(buf, "contact_err.rad", &e);
    ENSURE(!m && strstr(e.msg, "card /COUPLING/CONTACT/1, field surf_ID1") && strstr(e.msg, "segment surface"));
    memcpy(q, "         5         5", 20);
    m = tu_compile_text(buf, "contact_err.rad", &e);
    ENSURE(!m && strstr(e.msg, "field surf_ID2"));
    memcpy(q, "        11         6", 20); /* a fixed segment surface: no body to push */
    m = tu_compile_text(buf, "contact_err.rad", &e);
    ENSURE(!m && strstr(e.msg, "field surf_ID1") && strstr(e.msg, "fixed in space"));
    rc_model_free(m);
}

void suite_contactcpl(void);
void suite_contactcpl(void)
{
    RUN_TEST(test_contact_cpl_faces);
    RUN_TEST(test_contact_cpl_jacobian_matches_finite_differences);
    RUN_TEST(test_contact_cpl_roots);
    RUN_TEST(test_contact_cpl_estimators);
    RUN_TEST(test_contact_cpl_check_prints_estimators);
    RUN_TEST(test_contact_cpl_errors);
}
