/*
 * /INTER/TYPE7 Inacti 1 and 2 (engine/analyses/inacti.c, model/type7.c):
 * the secondary nodes that penetrate the main surface at t = 0 (Inacti 1),
 * or the main segments they penetrate (Inacti 2), are left out of the
 * contact for the whole run, with a notice naming the card, the count and
 * the ids; nothing penetrating, the model and the run are those of
 * Inacti 0; Inacti 2 on a plane that a node penetrates is refused.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/error.h"
#include "case/case.h"
#include "harness.h"
#include "model/model.h"
#include "model/segsurf.h"
#include "testutil.h"

/* A block (/RBODY/1, 2 kg at its main node 1, no mesh) over a fixed floor
 * (/SURF/SEG/30: nodes 21-24 at z = 0, two segments, x < 0 and x > 0,
 * normal +z). Its secondary nodes (/GRNOD/NODE/2): four feet 11-14 at the
 * corners (x, y = +-0.1 m) 1 mm above the floor, and nodes 15 (x = -0.05)
 * and 16 (x = 0.05) on the axis y = 0 at z = Z15, Z16 (tokens below).
 * /INTER/TYPE7/7: the nodes against the floor, Istf 1, Stfac 1e5 N/m, gap
 * 0, Inacti INA, VISs 1 (critical damping: the block settles). */
static const char deck_fmt[] =
    "#RADIOSS STARTER\n"
    "/BEGIN\n"
    "inacti test\n"
    "      2022         0\n"
    "                  kg                   m                   s\n"
    "                  kg                   m                   s\n"
    "/NODE\n"
    "         1                   0                   0                 0.1\n"
    "        11                -0.1                -0.1               0.001\n"
    "        12                 0.1                -0.1               0.001\n"
    "        13                 0.1                 0.1               0.001\n"
    "        14                -0.1                 0.1               0.001\n"
    "        15               -0.05                   0%20s\n"
    "        16                0.05                   0%20s\n"
    "        21                -0.3                -0.3                   0\n"
    "        22                   0                -0.3                   0\n"
    "        23                 0.3                -0.3                   0\n"
    "        24                 0.3                 0.3                   0\n"
    "        25                   0                 0.3                   0\n"
    "        26                -0.3                 0.3                   0\n"
    "/RBODY/1\n"
    "block\n"
    "         1                                                 2         2\n"
    "              0.0133              0.0133              0.0133\n"
    "                   0                   0                   0\n"
    "/GRNOD/NODE/2\n"
    "block nodes\n"
    "        11        12        13        14        15        16\n"
    "/SURF/SEG/30\n"
    "floor\n"
    "       101        21        22        25        26\n"
    "       102        22        23        24        25\n"
    "/PLANE_TOKEN/\n"
    "/INTER/TYPE7/7\n"
    "block on the floor\n"
    "         2%10s         1         0         0                   0         0         0         0\n"
    "                   0                   0                   0         0\n"
    "                   0                   0                   0                   0         0         0\n"
    "              100000                   0                   0                   0                   0\n"
    "         0                    %10s                   1                   0                   0\n"
    "         0         0                   0         0         0         0                   0         0\n"
    "/GRAV/1\n"
    "gravity\n"
    "         0         Z         0         0         0                             1               -9.81\n"
    "/RUN\n"
    "                 0.3                0.01\n"
    "/END\n";

/* A plane floor at z = 0, normal +z (/SURF/PLANE/40), for the main surface
 * "40" in place of the segments. */
static const char plane_card[] =
    "/SURF/PLANE/40\n"
    "plane floor\n"
    "                   0                   0                   0\n"
    "                   0                   0                   1\n";

/* The deck with nodes 15, 16 at z15, z16, Inacti ina, main surface main
 * (30 or 40: the plane). */
static const char *deck(const char *z15, const char *z16, int ina, int main)
{
    char a[24], b[24], in[16], ms[16], tmp[sizeof deck_fmt + 64];
    static char text[sizeof tmp + sizeof plane_card];
    snprintf(a, sizeof a, "%20s", z15);
    snprintf(b, sizeof b, "%20s", z16);
    snprintf(in, sizeof in, "%10d", ina);
    snprintf(ms, sizeof ms, "%10d", main);
    snprintf(tmp, sizeof tmp, deck_fmt, a, b, ms, in);
    /* the plane card in place of its token */
    char *at = strstr(tmp, "/PLANE_TOKEN/\n");
    if (!at) return NULL;
    *at = '\0';
    snprintf(text, sizeof text, "%s%s%s", tmp, plane_card, at + strlen("/PLANE_TOKEN/\n"));
    return text;
}

/* The index of the TYPE7 contact of m (the only interface), or -1. */
static int t7_inter(const rc_model *m)
{
    for (int i = 0; i < m->ninter; i++)
        if (!strncmp(m->inter_name[i], "/INTER/TYPE7/7", 14)) return i;
    return -1;
}

/* The secondary node ids of contact i, ascending (its point surface). */
static int contact_nodes(const rc_model *m, int i, int *ids, int cap)
{
    const int sa = m->inter_sa[i], n = m->surf_nadr[sa + 1] - m->surf_nadr[sa];
    for (int j = 0; j < n && j < cap; j++) ids[j] = m->surf_nid[m->surf_nadr[sa] + j];
    return n;
}

/* The block's height (its main node, deck coordinates) after the run. */
static double final_z(rc_model *m)
{
    double y[64], b[13];
    if (rc_model_state_size(m) > 64) return NAN;
    rc_run_options o = {.y_end = y};
    rc_error e;
    rc_error_clear(&e);
    if (rc_run(m, &o, NULL, &e) != RC_OK) {
        fprintf(stderr, "  %s\n", e.msg);
        return NAN;
    }
    if (rc_model_body_state(m, y, 1, b, &e) != RC_OK) return NAN;
    return b[2];
}

/* Inacti 1: nodes 15, 16 1 mm below the floor are left out (exactly
 * those), the notice names them; the block falls 1 mm onto its four feet,
 * which carry its weight: the main node at 0.1 - 0.001 - m g / k (ricochet's
 * one force over the nodes, docs/theory.md 3.7). Inacti 0 keeps them: the
 * block is pushed up onto them, 0.1 + 0.001 - m g / k. */
static void test_inacti_nodes(void)
{
    rc_model *m = TU_COMPILE_OK(deck("-0.001", "-0.001", 1, 30), "inacti1.rad");
    if (!m) return;
    const int i = t7_inter(m);
    ENSURE(i >= 0 && m->ninter == 1);
    if (i < 0) {
        rc_model_free(m);
        return;
    }
    int ids[16];
    const int n = contact_nodes(m, i, ids, 16);
    ENSURE(n == 4 && ids[0] == 11 && ids[1] == 12 && ids[2] == 13 && ids[3] == 14);
    ENSURE(rc_model_note_count(m) == 1);
    const char *note = rc_model_note(m, 0);
    ENSURE(note && strstr(note, "inacti1.rad:") && strstr(note, "card /INTER/TYPE7/7, field Inacti") &&
           strstr(note, "leaves 2 of the 6 secondary nodes") && strstr(note, "nodes 15, 16") &&
           !strstr(note, "no contact at all"));
    if (note) printf("  notice: %s\n", note);
    const double mg_k = 2.0 * 9.81 / 1e5;
    const double z1 = final_z(m);
    ENSURE_NEAR(z1, 0.1 - 0.001 - mg_k, 0, 1e-7);
    rc_model_free(m);
    m = TU_COMPILE_OK(deck("-0.001", "-0.001", 0, 30), "inacti0.rad");
    if (!m) return;
    ENSURE(rc_model_note_count(m) == 0);
    const double z0 = final_z(m);
    ENSURE_NEAR(z0, 0.1 + 0.001 - mg_k, 0, 1e-7);
    printf("  settled: Inacti 1 z = %.9f m (closed form %.9f), Inacti 0 z = %.9f m (%.9f)\n", z1,
           0.1 - 0.001 - mg_k, z0, 0.1 + 0.001 - mg_k);
    rc_model_free(m);
}

/* Nothing penetrating (nodes 15, 16 2 mm above): nothing left out, no
 * notice, and the run bit for bit that of Inacti 0; a node exactly on the
 * floor (gap 0) touches, it does not penetrate. */
static void test_inacti_none(void)
{
    rc_model *m1 = TU_COMPILE_OK(deck("0.002", "0", 1, 30), "inacti1n.rad");
    rc_model *m0 = TU_COMPILE_OK(deck("0.002", "0", 0, 30), "inacti0n.rad");
    if (m1 && m0) {
        int a[16], b[16];
        const int i1 = t7_inter(m1), i0 = t7_inter(m0);
        ENSURE(i1 >= 0 && i0 >= 0 && m1->ninter == m0->ninter && m1->ny == m0->ny);
        if (i1 >= 0 && i0 >= 0) {
            const int n1 = contact_nodes(m1, i1, a, 16), n0 = contact_nodes(m0, i0, b, 16);
            ENSURE(n1 == 6 && n0 == 6 && !memcmp(a, b, sizeof(int) * 6));
        }
        ENSURE(rc_model_note_count(m1) == 0);
        const double z1 = final_z(m1), z0 = final_z(m0);
        ENSURE(z1 == z0 && isfinite(z1));
    }
    rc_model_free(m1);
    rc_model_free(m0);
}

/* Every node penetrating: all left out, the notice says the card has no
 * contact left (the block falls freely: no interface). */
static void test_inacti_all(void)
{
    static const char *const low = "-0.002";
    char text[sizeof deck_fmt + 64 + sizeof plane_card];
    const char *d = deck(low, low, 1, 30);
    if (!d) return;
    snprintf(text, sizeof text, "%s", d);
    /* the feet 1 mm below too */
    for (char *p = strstr(text, "               0.001\n"); p; p = strstr(p, "               0.001\n")) memcpy(p, "              -0.001", 20);
    rc_model *m = TU_COMPILE_OK(text, "inacti1all.rad");
    if (!m) return;
    ENSURE(m->ninter == 0 && rc_model_note_count(m) == 1);
    const char *note = rc_model_note(m, 0);
    ENSURE(note && strstr(note, "leaves 6 of the 6 secondary nodes") && strstr(note, "nodes 11, 12, 13, 14, 15, 16") &&
           strstr(note, "no secondary node is left: the card has no contact at all"));
    rc_model_free(m);
}

/* Inacti 2: node 15 (x < 0) 1 mm below the floor penetrates segment 101:
 * that segment is left out of the contact's main surface (a copy with
 * segment 102 alone); the notice names it. Inacti 2 on a plane that a node
 * penetrates is refused (no segments); without penetration it leaves
 * nothing out. Inacti 3 stays refused. */
static void test_inacti_segments(void)
{
    rc_model *m = TU_COMPILE_OK(deck("-0.001", "0.002", 2, 30), "inacti2.rad");
    if (m) {
        const int i = t7_inter(m);
        ENSURE(i >= 0);
        if (i >= 0) {
            const int sb = m->inter_sb[i];
            ENSURE(m->surf_sadr[sb + 1] - m->surf_sadr[sb] == 1);
            ENSURE(m->surf_id[sb] != 30);
            /* the kept segment is 102 (nodes 22 23 24 25) */
            const int *v = m->surf_seg + 4 * m->surf_sadr[sb];
            const int *nid = m->surf_nid + m->surf_nadr[sb];
            ENSURE(nid[v[0]] == 22 && nid[v[1]] == 23 && nid[v[2]] == 24 && nid[v[3]] == 25);
            int ids[16];
            ENSURE(contact_nodes(m, i, ids, 16) == 6); /* the nodes stay */
        }
        ENSURE(rc_model_note_count(m) == 1);
        const char *note = rc_model_note(m, 0);
        ENSURE(note && strstr(note, "Inacti 2 leaves 1 of the 2 main segments") && strstr(note, "segments 101") &&
               strstr(note, "/SURF/SEG/30"));
        rc_model_free(m);
    }
    /* both penetrated: no segment left, no contact */
    m = TU_COMPILE_OK(deck("-0.001", "-0.001", 2, 30), "inacti2all.rad");
    if (m) {
        ENSURE(m->ninter == 0 && rc_model_note_count(m) == 1);
        ENSURE(rc_model_note(m, 0) && strstr(rc_model_note(m, 0), "segments 101, 102") &&
               strstr(rc_model_note(m, 0), "no main segment is left"));
        rc_model_free(m);
    }
    /* a plane */
    TU_EXPECT_TEXT_ERROR(deck("-0.001", "0.002", 2, 40), "inacti2p.rad", "card /INTER/TYPE7/7, field Inacti",
                         "node 15 penetrates the main surface /SURF/PLANE/40", "one analytic surface",
                         "expected a main /SURF/SEG");
    m = TU_COMPILE_OK(deck("0.002", "0.002", 2, 40), "inacti2pn.rad");
    if (m) {
        ENSURE(m->ninter == 1 && rc_model_note_count(m) == 0);
        rc_model_free(m);
    }
    /* Inacti 1 on the plane: nodes 15, 16 out */
    m = TU_COMPILE_OK(deck("-0.001", "-0.001", 1, 40), "inacti1p.rad");
    if (m) {
        int ids[16];
        const int i = t7_inter(m);
        ENSURE(i >= 0 && contact_nodes(m, i, ids, 16) == 4 && ids[3] == 14);
        ENSURE(rc_model_note_count(m) == 1 && strstr(rc_model_note(m, 0), "/SURF/PLANE/40"));
        rc_model_free(m);
    }
    TU_EXPECT_TEXT_ERROR(deck("0.002", "0.002", 3, 30), "inacti3.rad", "card /INTER/TYPE7/7, field Inacti",
                         "moves the penetrating nodes onto the surface", "1, 2 (the penetrating nodes or segments");
}

void suite_inacti(void);
void suite_inacti(void)
{
    RUN_TEST(test_inacti_nodes);
    RUN_TEST(test_inacti_none);
    RUN_TEST(test_inacti_all);
    RUN_TEST(test_inacti_segments);
}
