/*
 * Input errors found when the model is compiled (references between cards,
 * physics that needs the curves): each names file:line, card and field, and
 * nothing runs (exit code 2 through rc_status RC_EINPUT).
 */
#include <stdarg.h>
#include <stdlib.h>
#include <unistd.h>

#include <math.h>

#include "base/error.h"
#include "model/model.h"
#include "harness.h"
#include "testutil.h"

/* A valid deck: a sphere on body 1 dropped on a fixed plane, TYPE6 Iform 1
 * (load k1 = 1e5 N/m, unload curve below), the pieces below replaced by the
 * tests (comma format: docs/case-format.md). */
static const char *const base[] = {
    "/FUNCT/1\nload\n0,0\n1,1e5\n",
    "/FUNCT/2\nunload\n0,0\n0.002,0\n1,9e4\n",
    "/NODE\n1,0,0,0.05\n",
    "/RBODY/1\nball\n1,,,,1.0\n0.001,0.001,0.001\n0,0,0\n",
    "/SURF/ELLIPS/10\nball\n0,2,1\n0,0,0.05\n0.05,0.05,0.05\n",
    "/SURF/PLANE/20\nfloor\n0,0,0\n0,0,1\n",
    "/INTER/TYPE6/3\ncontact\n10,20\n,,0\n,0,0,0\n1,1,,,0\n2,,2e5\n0\n",
    "/RUN\n0.01,0.001\n",
};
enum { N_BASE = sizeof base / sizeof base[0] };

/* Deck = base with piece k replaced by `piece` (NULL: dropped; k = -1: none)
 * and `extra` appended; written to a temporary file. */
static const char *deck(int k, const char *piece, const char *extra)
{
    static char path[128], text[8192];
    size_t n = 0;
    for (int i = 0; i < N_BASE; i++) {
        const char *p = i == k ? piece : base[i];
        if (p) n += (size_t)snprintf(text + n, sizeof text - n, "%s", p);
    }
    if (extra) n += (size_t)snprintf(text + n, sizeof text - n, "%s", extra);
    snprintf(path, sizeof path, "/tmp/rc_compile_test_%d.rad", (int)getpid());
    FILE *f = fopen(path, "w");
    if (f) {
        fputs(text, f);
        fclose(f);
    }
    return path;
}

/* Load and compile; expect RC_EINPUT with every needle in the message. */
static int compile_error(const char *path, ...)
{
    rc_model *m = NULL;
    rc_error e;
    rc_status st = tu_load_compile(path, &m, &e);
    int bad = st != RC_EINPUT || m != NULL;
    if (!strstr(e.msg, path)) bad++; /* names the file */
    va_list ap;
    va_start(ap, path);
    bad += tu_missing_needles(e.msg, ap);
    va_end(ap);
    if (bad) fprintf(stderr, "  status %d; message: %s\n", st, e.msg);
    rc_model_free(m);
    remove(path);
    return bad;
}

#define EXPECT_COMPILE_ERROR(path, ...) ENSURE(compile_error((path), __VA_ARGS__, (const char *)NULL) == 0)

/* Load and compile a deck that must be valid. */
static rc_model *compile_ok(const char *path)
{
    rc_model *m = NULL;
    rc_error e;
    tu_load_compile(path, &m, &e);
    return m;
}

/* The model's scales (docs/theory.md 7.1) and the tolerances derived from
 * them, against closed forms: a 1 kg sphere touching a floor with a linear
 * contact k = 1e5 N/m. Under gravity p_s = m g / k (the weight); launched at
 * v0 without gravity p_s = v0 sqrt(m / k) (the kinetic energy); positions are
 * weighed absolutely at rtol p_s, velocities at rtol p_s sqrt(k/m). Given
 * absolute tolerances are kept as given, all relative. */
static void test_compile_scales_and_derived_tolerances(void)
{
    const double k = 1e5, mass = 1.0, g = 9.81, v0 = 0.37, rtol = 1e-8;
    rc_model *m = compile_ok(deck(6, "/INTER/TYPE6/3\ncontact\n10,20\n,,0\n,0,0,0\n1,0\n0\n0\n",
                                  "/GRNOD/NODE/1\nball\n1\n/GRAV/1\ngravity\n0,Z,0,0,1,,1,-9.81\n"));
    ENSURE(m != NULL);
    if (m) {
        ENSURE_NEAR(m->inter_pscale[0], mass * g / k, 1e-9, 0);
        ENSURE_NEAR(m->inter_fscale[0], mass * g, 1e-9, 0);
        ENSURE_NEAR(m->inter_kscale[0], k, 1e-12, 0);
        ENSURE_NEAR(m->rtol, rtol, 0, 0);
        ENSURE(m->tol_auto != 0 && m->ewt_rel != NULL);
        const int y = m->body_yadr[0];
        ENSURE_NEAR(m->atol[y + 2], rtol * mass * g / k, 1e-9, 0); /* position z */
        ENSURE(m->ewt_rel[y + 2] == 0);
        ENSURE_NEAR(m->atol[y + 9], rtol * mass * g / k * sqrt(k / mass), 1e-9, 0); /* velocity z */
        rc_model_free(m);
    }
    char extra[256];
    snprintf(extra, sizeof extra, "/GRNOD/NODE/1\nball\n1\n/INIVEL/TRA/1\nv0\n0,0,%.17g,1,0\n", -v0);
    m = compile_ok(deck(6, "/INTER/TYPE6/3\ncontact\n10,20\n,,0\n,0,0,0\n1,0\n0\n0\n", extra));
    ENSURE(m != NULL);
    if (m) {
        ENSURE_NEAR(m->inter_pscale[0], v0 * sqrt(mass / k), 1e-9, 0);
        ENSURE_NEAR(m->inter_vscale[0], v0, 1e-9, 0);
        rc_model_free(m);
    }
    m = compile_ok(deck(-1, NULL, "/SOLVER\n1,5,,1e-7\n3e-9,4e-9,5e-6,6e-6\n7e-6\n"));
    ENSURE(m != NULL);
    if (m) {
        /* given: as given; positions absolute (no rtol |x|, theory 7.1),
         * the others rtol |y| + atol */
        ENSURE(m->tol_auto == 0 && m->ewt_rel != NULL);
        ENSURE_NEAR(m->atol[m->body_yadr[0]], 3e-9, 0, 0);
        ENSURE_NEAR(m->atol[m->body_yadr[0] + 7], 5e-6, 0, 0);
        if (m->ewt_rel)
            for (int s = 0; s < RC_NB; s++) ENSURE(m->ewt_rel[m->body_yadr[0] + s] == (s >= 3));
        rc_model_free(m);
    }
}

/* A given position tolerance (/SOLVER Atol_pos) carries to the force
 * states as the stick stiffness times it; where the law has no stick
 * stiffness to carry it (the power law's K_t, 0 at P = 0), rtol of the
 * contact's force scale, as where it is derived. A box on a power-law
 * incline with friction per contact point was refused with a tolerance of
 * 0 for its points' friction states (the message named the energy
 * accounting, not the interface). */
static void test_compile_given_atol_pos_friction_points(void)
{
    rc_model *m = TU_LOAD_OK("tests/data/box_incline_power_friction_atol_pos.rad");
    ENSURE(m != NULL);
    if (!m) return;
    ENSURE_NEAR(m->atol_pos, 7.096896e-16, 0, 0);
    int n = 0;
    for (int i = 0; i < m->ninter; i++) {
        const int k0 = m->inter_eadr[i] + m->inter_ns[i];
        for (int k = 0; k < m->inter_pst[i] * m->inter_npt[i]; k++, n++) {
            const double a = m->atol[k0 + k];
            ENSURE(a > 0 && isfinite(a));
            if (!(m->inter_fr[i].kt * m->atol_pos > 0)) ENSURE_NEAR(a, m->rtol * m->inter_fscale[i], 1e-12, 0);
        }
    }
    ENSURE(n > 0); /* the deck has contact points with friction */
    rc_model_free(m);
}

/* A touching start whose gap is the rounding of its coordinates is a
 * touching start for the scales: no fall over that gap. A 1 kg ball (R =
 * 0.05 m) on a floor, linear contact 1e5 N/m, gravity: its centre at
 * 0.05 m (touching) and one rounding above (gap 6.9e-18 m) get the same
 * p_s = m g / k; a fall over the rounding gap set p_s at 1e-2 of it (the
 * floor of a fall speed's scale), so the same scene moved 1 km away, whose
 * touching start the deck's rounding leaves 1e-13 m apart, ran with
 * tolerances 100 times tighter. A gap of 1e-9 m is a fall (the clamp 1e-2
 * p_F). */
static void test_compile_scales_touching_within_rounding(void)
{
    const double z[3] = {0.05, nextafter(0.05, 1.0), 0.05 + 1e-9};
    double ps[3];
    for (int k = 0; k < 3; k++) {
        char text[2048];
        snprintf(text, sizeof text,
                 "/BEGIN\nball touching a floor\n      2022         0\n"
                 "                  kg                   m                   s\n"
                 "                  kg                   m                   s\n"
                 "/NODE\n1,0,0,%.17g\n/RBODY/1\nball\n1,,,,1,1\n0.001,0.001,0.001\n0,0,0\n"
                 "/GRNOD/NODE/1\nball\n1\n/SURF/ELLIPS/1\nball\n0,2,1\n0,0,%.17g\n0.05,0.05,0.05\n"
                 "/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n/FUNCT/1\nlinear\n0,0\n1,100000\n"
                 "/INTER/TYPE6/1\nball on floor\n1,2\n\n\n1,0\n\n\n"
                 "/GRAV/1\ng\n0,Z,0,0,1,,1,-9.81\n/RUN\n0.01,0.001\n/END\n",
                 z[k], z[k]);
        rc_model *m = TU_COMPILE_OK(text, "touch_scales.rad");
        ps[k] = m ? m->inter_pscale[0] : NAN;
        printf("    centre %.17g m: p_s %.6e m\n", z[k], ps[k]);
        rc_model_free(m);
    }
    ENSURE_NEAR(ps[0], 9.81 / 1e5, 1e-9, 0);
    ENSURE(ps[1] == ps[0]);
    ENSURE_NEAR(ps[2], 1e-2 * 9.81 / 1e5, 1e-6, 0);
}

static void test_compile_base_deck_is_valid(void)
{
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    const char *p = deck(-1, NULL, NULL);
    ENSURE(rc_case_load(p, &c, &e) == RC_OK);
    if (c) ENSURE(rc_model_compile(c, &m, &e) == RC_OK);
    rc_model_free(m);
    rc_case_free(c);
    remove(p);
}

static void test_compile_errors_references(void)
{
    /* surfaces, functions, nodes, groups that do not exist */
    EXPECT_COMPILE_ERROR(deck(6, "/INTER/TYPE6/3\ncontact\n10,21\n,,0\n,0,0,0\n1,1,,,0\n2,,2e5\n0\n", NULL),
                         ":28:", "card /INTER/TYPE6/3", "field surf_ID2", "no such surface");
    EXPECT_COMPILE_ERROR(deck(6, "/INTER/TYPE6/3\ncontact\n10,20\n,,0\n,0,0,0\n7,1,,,0\n2,,2e5\n0\n", NULL),
                         "card /INTER/TYPE6/3", "field fct_IDld", "no such function");
    EXPECT_COMPILE_ERROR(deck(6, "/INTER/TYPE6/3\ncontact\n10,20\n,,0\n,0,0,0\n1,1,,,0\n9,,2e5\n0\n", NULL),
                         "card /INTER/TYPE6/3", "field fct_IDul", "no such function");
    EXPECT_COMPILE_ERROR(deck(3, "/RBODY/1\nball\n5,,,,1.0\n0.001,0.001,0.001\n0,0,0\n", NULL), "card /RBODY/1",
                         "field node_ID", "no such node");
    EXPECT_COMPILE_ERROR(deck(-1, NULL, "/GRAV/1\ng\n0,Z,0,0,44,,1,-9.81\n"), "card /GRAV/1", "field grnod_ID",
                         "no such group");
    EXPECT_COMPILE_ERROR(deck(4, "/SURF/ELLIPS/10\nball\n0,2,8\n0,0,0.05\n0.05,0.05,0.05\n", NULL),
                         "card /SURF/ELLIPS/10", "field rbody_ID", "no such body");
}

static void test_compile_errors_physics(void)
{
    /* the unload curve must lie below the load curve */
    EXPECT_COMPILE_ERROR(deck(1, "/FUNCT/2\nunload\n0,0\n0.001,150\n1,1.5e4\n", NULL), "card /INTER/TYPE6/3", "field fct_IDul",
                         "below the load curve");
    /* Stiff steeper than both curves (no chattering at a reversal) */
    EXPECT_COMPILE_ERROR(deck(6, "/INTER/TYPE6/3\ncontact\n10,20\n,,0\n,0,0,0\n1,1,,,0\n2,,5e4\n0\n", NULL),
                         "card /INTER/TYPE6/3", "field Stiff", "steeper than the load curve", "100000");
    EXPECT_COMPILE_ERROR(deck(1, "/FUNCT/2\nunload\n0,0\n0.5,0\n0.6,4e4\n", NULL), "field Stiff",
                         "steeper than the unload curve");
    /* pairs ricochet cannot compute, surfaces on one body */
    EXPECT_COMPILE_ERROR(deck(4, "/SURF/PLANE/10\np\n0,0,1\n0,0,2\n", NULL), "card /INTER/TYPE6/3",
                         "plane against plane");
    EXPECT_COMPILE_ERROR(deck(5, "/SURF/ELLIPS/20\nb\n0,2,1\n0,0,0.2\n0.05,0.05,0.05\n", NULL),
                         "card /INTER/TYPE6/3", "same body");
    /* partial rotation locks: one rotation held (two free); one free about an
     * axis that is not principal (Jxz != 0 couples z with x) */
    EXPECT_COMPILE_ERROR(deck(-1, NULL, "/GRNOD/NODE/5\ng\n1\n/BCS/1\nb\n000 100,0,5\n"), "card /BCS/1",
                         "field Trarot", "one rotation held and two free", "not supported yet");
    EXPECT_COMPILE_ERROR(deck(3, "/RBODY/1\nball\n1,,,3,1.0\n0.001,0.002,0.003\n0,0,0.0002\n",
                              "/GRNOD/NODE/5\ng\n1\n/BCS/1\nb\n000 110,0,5\n"),
                         "card /BCS/1", "field Trarot", "global Z axis", "not a principal axis", "Jxz");
    /* absurd masses and inertias: below the smallest normal number */
    EXPECT_COMPILE_ERROR(deck(3, "/RBODY/1\nball\n1,,,,1e-320\n0.001,0.001,0.001\n0,0,0\n", NULL), "card /RBODY/1",
                         "field Mass", "normal double");
    EXPECT_COMPILE_ERROR(deck(3, "/RBODY/1\nball\n1,,,3,1.0\n0.001,1e-315,0.001\n0,0,0\n", NULL), "card /RBODY/1",
                         "field Jyy", "normal double");
    /* two bodies on one main node */
    EXPECT_COMPILE_ERROR(deck(-1, NULL, "/RBODY/7\nsecond\n1,,,,2.0\n0.002,0.002,0.002\n0,0,0\n"), "card /RBODY/7",
                         "field node_ID", "already the main node of /RBODY/1");
}

static void test_compile_errors_friction_cards(void)
{
    const char *parts = "/PART/41\nball\n0,0,0,0\n1\n/PART/42\nfloor\n0,0,0,0\n0,20\n";
    char extra[1024];
    /* a pair naming a part that does not exist */
    snprintf(extra, sizeof extra, "%s/FRICTION/1\nf\n0,0,,2\n\n0,0.3,\n0,0,41,99,,0\n\n0,0.3,\n", parts);
    EXPECT_COMPILE_ERROR(deck(-1, NULL, extra), "card /FRICTION/1", "field part_ID2", "no such part");
    /* a part naming a surface of another body */
    EXPECT_COMPILE_ERROR(deck(-1, NULL, "/PART/41\nball\n0,0,0,0\n1,20\n/FRICTION/1\nf\n0,0,,2\n\n0,0.3,\n"),
                         "card /PART/41", "field surf_ID", "not carried by");
    /* orthotropic friction without /FRIC_ORIENT */
    snprintf(extra, sizeof extra, "%s/FRICTION/1\nf\n0,0,,2\n\n0,0.3,\n0,0,41,42,,1\n\n0,0.2,\n\n0,0.5,\n", parts);
    EXPECT_COMPILE_ERROR(deck(-1, NULL, extra), "card /FRICTION/1", "needs a /FRIC_ORIENT");
    /* a surface in two parts */
    EXPECT_COMPILE_ERROR(deck(-1, NULL,
                              "/PART/41\nball\n0,0,0,0\n1\n/PART/43\nball again\n0,0,0,0\n1,10\n"
                              "/FRICTION/1\nf\n0,0,,2\n\n0,0.3,\n"),
                         "card /PART/43", "already belongs to /PART/41");
}

void suite_compile(void);
void suite_compile(void)
{
    RUN_TEST(test_compile_base_deck_is_valid);
    RUN_TEST(test_compile_scales_and_derived_tolerances);
    RUN_TEST(test_compile_scales_touching_within_rounding);
    RUN_TEST(test_compile_given_atol_pos_friction_points);
    RUN_TEST(test_compile_errors_references);
    RUN_TEST(test_compile_errors_physics);
    RUN_TEST(test_compile_errors_friction_cards);
}
