/*
 * Sphere against a cylinder of finite length (docs/theory.md 2): the signed
 * distance and normal in every region (flat ends: lateral surface, end disc,
 * rim, centre inside the solid; rounded ends: lateral surface, cap) against
 * the closed forms written here, and the Jacobian against central
 * differences in each region, TYPE6 with friction (stick, slip), the
 * power law with step5 friction (uncapped, capped) and with /FRICTION
 * cards (viscous and incremental forms with a filter), closed and released.
 * And a cylinder on the rim of its end against a plane near upright: the
 * rim's depth to the rounding of the coordinates.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/error.h"
#include "model/model.h"
#include "harness.h"
#include "testutil.h"
#include "engine/assembly/assembly.h"

static char sc_path[128];

/* Body 1: a ball (sphere of radius 0.03 off the body's reference point);
 * body 2: the carrier of the cylinder (radius 0.05, length 0.2, axis
 * (1, 0.1, 0.05), centre off the reference point). %d: Iend. */
#define SC_HEAD                                                                                                  \
    "/NODE\n1,0.001,-0.002,0.3\n2,0,0,0\n"                                                                      \
    "/RBODY/1\nball\n1,,,,0.731\n2.1e-3,1.7e-3,2.9e-3\n1.3e-4,-2.2e-4,0.7e-4\n"                                  \
    "/RBODY/2\ncarrier\n2,,,,5.0\n0.11,0.13,0.2\n0.01,0,0\n"                                                     \
    "/SURF/ELLIPS/20\nball\n0,2,1\n0.0027,-0.0011,0.3021\n0.03,0.03,0.03\n"                                      \
    "/SURF/CYL/40\ncylinder\n2,%d\n0.003,-0.002,0.001\n1,0.1,0.05\n0.05,0.2\n"                                   \
    "/FUNCT/1\nload\n-0.01,-3.1e3\n0,0\n0.0013,2.71e3\n0.0041,1.37e4\n0.0097,5.9e4\n"

static const char sc_type6[] = "/INTER/TYPE6/1\nball on cylinder\n40,20\n,0.3\n\n1\n\n730\n/RUN\n0.01,0.001\n";
static const char sc_power[] =
    "/INTER/POWER/1\nball on cylinder\n40,20\n3.7e8,1.5,2.1e5,1.1,1.2\n\n0.4,0.3,0.25,1.1,7.5\n/RUN\n0.01,0.001\n";

/* /FRICTION cards replacing step5 on the power law: the viscous form with a
 * filter, the incremental form (Kt of the power card) with a filter, the
 * viscous form on the stiffness spline (its C follows the spline's slope). */
#define SC_PARTS "/PART/1\nball\n0,0,0,0\n1,20\n/PART/2\ncarrier\n0,0,0,0\n2,40\n/GRAV/1\ng\n0,Z,0,0,0,,1,-9.81\n"
static const char sc_frc_viscous[] =
    SC_PARTS "/FRICTION/1\nf\n0,3,45,1\n,\n,0.4,0.2\n0,0,1,2\n,\n,0.37,0.2\n"
             "/INTER/POWER/1\nball on cylinder\n40,20\n3.7e8,1.5,2.1e5,1.1,1.2\n\n0.4,0.3,0.25,1.1\n/RUN\n0.01,0.001\n";
static const char sc_frc_incremental[] =
    SC_PARTS "/FRICTION/1\nf\n0,3,45,2\n,\n,0.4\n0,0,1,2\n,\n,0.37\n"
             "/INTER/POWER/1\nball on cylinder\n40,20\n3.7e8,1.5,2.1e5,1.1,1.2\n\n0.4,0.3,0.25,1.1\n2.3e6\n"
             "/RUN\n0.01,0.001\n";

static const char sc_frc_spline[] =
    SC_PARTS "/FRICTION/1\nf\n0,0,0,1\n,\n,0.4,0.2\n0,0,1,2\n,\n,0.37,0.2\n"
             "/INTER/POWER/1\nball on cylinder\n40,20,1\n,,2.1e5,1.1,1.2\n\n0.4,0.3,0.25,1.1\n/RUN\n0.01,0.001\n";

static rc_model *sc_compile(int iend, const char *inter, rc_error *e)
{
    char text[4096];
    snprintf(text, sizeof text, SC_HEAD "%s", iend, inter);
    snprintf(sc_path, sizeof sc_path, "/tmp/rc_sphcyl_test_%d.rad", (int)getpid());
    return tu_compile_text(text, sc_path, e);
}

static void quat(double a, const double *u, double *q)
{
    const double l = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    q[0] = cos(0.5 * a);
    for (int k = 0; k < 3; k++) q[k + 1] = sin(0.5 * a) * u[k] / l;
}

/* out = R(q) s, q a unit quaternion */
static void rot(const double *q, const double *s, double *out)
{
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double R[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
                         2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                         2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)};
    for (int k = 0; k < 3; k++) out[k] = R[3 * k] * s[0] + R[3 * k + 1] * s[1] + R[3 * k + 2] * s[2];
}

/* A state with the carrier turned and moving, the ball's centre at axial
 * coordinate z and radial coordinate rho (along a fixed direction across
 * the axis) of the cylinder: the cylinder's centre and axis in cb, e. */
static double *sc_state(const rc_model *m, double z, double rho, double *cb, double *e, double *xc)
{
    double *y = calloc((size_t)m->ny, sizeof(double));
    rc_initial_state(m, y);
    double *b1 = y + m->body_yadr[0], *b2 = y + m->body_yadr[1];
    /* carrier: position, a turn, velocity, spin */
    const double p2[3] = {0.0021, 0.0007, -0.0003}, ax2[3] = {0.3, -1.0, 0.7};
    double q2[4];
    quat(0.37, ax2, q2);
    const double v2[6] = {-0.41, 0.17, 0.053, -1.9, 0.7, 2.2};
    memcpy(b2, p2, sizeof p2);
    memcpy(b2 + 3, q2, sizeof q2);
    memcpy(b2 + 7, v2, sizeof v2);
    const double cl[3] = {0.003, -0.002, 0.001};
    const double el[3] = {1 / sqrt(1.0125), 0.1 / sqrt(1.0125), 0.05 / sqrt(1.0125)};
    double cr[3];
    rot(q2, cl, cr);
    rot(q2, el, e);
    for (int k = 0; k < 3; k++) cb[k] = p2[k] + cr[k];
    /* a unit direction across the axis */
    const double t[3] = {0.2, 0.3, 1.0};
    double te = t[0] * e[0] + t[1] * e[1] + t[2] * e[2], u[3], ul = 0;
    for (int k = 0; k < 3; k++) u[k] = t[k] - te * e[k];
    for (int k = 0; k < 3; k++) ul += u[k] * u[k];
    for (int k = 0; k < 3; k++) u[k] /= sqrt(ul);
    for (int k = 0; k < 3; k++) xc[k] = cb[k] + z * e[k] + rho * u[k];
    /* ball: a turn, its centre at xc (offset (0.0017, 0.0009, 0.0021) from
     * the reference point in the body frame) */
    const double ax1[3] = {1.0, 0.4, -0.2}, off[3] = {0.0017, 0.0009, 0.0021};
    double q1[4], o[3];
    quat(0.21, ax1, q1);
    rot(q1, off, o);
    for (int k = 0; k < 3; k++) b1[k] = xc[k] - o[k];
    memcpy(b1 + 3, q1, sizeof q1);
    const double v1[6] = {0.31, -0.23, -0.17, 3.1, -2.3, 4.7};
    memcpy(b1 + 7, v1, sizeof v1);
    for (int k = 26; k < m->ny; k++) y[k] = 0.013 * (k - 25);
    return y;
}

/* Regions as (z, rho) of the ball's centre, radius 0.03, cylinder radius
 * 0.05, half-length 0.1, penetration 0.0011 (0.0311 for the centre inside). */
typedef struct {
    const char *name;
    int iend;
    double z, rho, d;      /* centre coordinates; expected distance      */
    double nz, nr;         /* expected normal (a to b) along e and across */
} sc_region;

static const double P0 = 0.0011, RB = 0.03, RC = 0.05, HC = 0.1;

static void sc_regions(sc_region *g)
{
    const double a = 0.6, dd = RB - P0; /* rim: the centre at dd from the rim, angle a from the axis */
    const sc_region r[7] = {
        {"flat, lateral", 0, 0.037, RC + dd, -P0, 0, -1},
        {"flat, end disc", 0, HC + dd, 0.021, -P0, -1, 0},
        {"flat, rim", 0, HC + dd * cos(a), RC + dd * sin(a), -P0, -cos(a), -sin(a)},
        {"flat, centre inside (lateral)", 0, 0.02, RC - 0.0011, -0.0011 - RB, 0, -1},
        {"flat, centre inside (disc)", 0, -(HC - 0.0011), 0.01, -0.0011 - RB, 1, 0},
        {"rounded, lateral", 1, -0.043, RC + dd, -P0, 0, -1},
        {"rounded, cap", 1, -(HC + (RC + dd) * cos(a)), (RC + dd) * sin(a), -P0, cos(a), -sin(a)},
    };
    memcpy(g, r, sizeof r);
}

/* The distance and the normal of every region against the closed forms. */
static void test_sphcyl_geometry_regions(void)
{
    sc_region g[7];
    sc_regions(g);
    for (int k = 0; k < 7; k++) {
        rc_error e;
        rc_model *m = sc_compile(g[k].iend, sc_type6, &e);
        ENSURE(m != NULL);
        if (!m) {
            fprintf(stderr, "  %s\n", e.msg);
            return;
        }
        ENSURE(m->inter_pair[0] == RC_PAIR_SPHERE_CYL);
        ENSURE(m->surf_id[m->inter_sa[0]] == 20); /* the sphere is surface a, whatever the card's order */
        double cb[3], ea[3], xc[3];
        double *y = sc_state(m, g[k].z, g[k].rho, cb, ea, xc);
        rc_inter_report r;
        rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
        /* expected normal: nz e + nr u, u the direction across the axis */
        double rel[3], z = 0, u[3], ul = 0, nx[3];
        for (int i = 0; i < 3; i++) rel[i] = xc[i] - cb[i];
        for (int i = 0; i < 3; i++) z += rel[i] * ea[i];
        for (int i = 0; i < 3; i++) u[i] = rel[i] - z * ea[i];
        for (int i = 0; i < 3; i++) ul += u[i] * u[i];
        double nerr = 0;
        for (int i = 0; i < 3; i++) {
            nx[i] = g[k].nz * ea[i] + g[k].nr * u[i] / sqrt(ul);
            nerr = fmax(nerr, fabs(r.normal[i] - nx[i]));
        }
        printf("    %-30s P = %.6g m (expected %.6g), |n - n_exact| = %.2e, F_n = %.4g N\n", g[k].name, r.p, -g[k].d,
               nerr, r.fn);
        ENSURE_NEAR(r.p, -g[k].d, 0, 1e-15);
        ENSURE(nerr < 1e-13);
        free(y);
        rc_model_free(m);
    }
}

/* Across the borders of the regions with the centre outside the solid
 * (lateral/rim, rim/end disc, rounded lateral/cap) the distance and the
 * normal are continuous: points 1e-9 m either side. */
static void test_sphcyl_continuity(void)
{
    const double eps = 1e-9, dd = 0.01;
    /* iend, (z, rho) of the two sides */
    const struct {
        const char *name;
        int iend;
        double z1, r1, z2, r2;
    } b[3] = {{"lateral | rim", 0, HC - eps, RC + dd, HC + eps, RC + dd},
              {"rim | end disc", 0, HC + dd, RC + eps, HC + dd, RC - eps},
              {"rounded lateral | cap", 1, -HC + eps, RC + dd, -HC - eps, RC + dd}};
    for (int k = 0; k < 3; k++) {
        rc_error e;
        rc_model *m = sc_compile(b[k].iend, sc_type6, &e);
        ENSURE(m != NULL);
        if (!m) return;
        double cb[3], ea[3], xc[3];
        rc_inter_report r1, r2;
        double *y = sc_state(m, b[k].z1, b[k].r1, cb, ea, xc);
        rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r1);
        free(y);
        y = sc_state(m, b[k].z2, b[k].r2, cb, ea, xc);
        rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r2);
        free(y);
        double dn = 0;
        for (int i = 0; i < 3; i++) dn = fmax(dn, fabs(r1.normal[i] - r2.normal[i]));
        printf("    %-22s |P1 - P2| = %.2e m, |n1 - n2| = %.2e (points %.0e m apart)\n", b[k].name, fabs(r1.p - r2.p), dn,
               2 * eps);
        ENSURE(fabs(r1.p - r2.p) < 1e-8);
        ENSURE(dn < 1e-6);
        rc_model_free(m);
    }
}

/* A cylinder standing on the rim of an end (Icont 1, flat ends) against a
 * plane, its axis within 1e-2..3e-6 rad of the plane's normal: the depth of
 * the rim's lowest point, h cos(theta) + r sin(theta) below the centre,
 * against that closed form. The part of the direction into the plane
 * across the axis, found by subtracting the axial part from a unit vector,
 * loses DBL_EPSILON / sin(theta) of itself: 2e-13 m of depth at 3e-6 rad,
 * noise that fired the hysteresis roots of a rocking cylinder. */
static const char cp_deck[] =
    "/NODE\n1,0,0,0.02\n"
    "/RBODY/1\ncylinder\n1,,,,0.002\n8.4e-8,8.4e-8,5.7e-8\n0,0,0\n"
    "/SURF/CYL/1\ncylinder\n1,0,1\n0,0,0.02\n0,0,1\n0.0072,0.019\n"
    "/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n"
    "/FUNCT/1\nload\n0,0\n1,1\n"
    "/INTER/TYPE6/1\nrim on floor\n1,2\n\n\n1,0,1e-7,1.0\n\n0.03\n/RUN\n0.01,0.001\n";

static void test_cylinder_plane_depth_near_upright(void)
{
    char path[128];
    snprintf(path, sizeof path, "/tmp/rc_cylplane_test_%d.rad", (int)getpid());
    rc_model *m = TU_COMPILE_OK(cp_deck, path);
    if (!m) return;
    ENSURE(m->inter_pair[0] == RC_PAIR_CYL_PLANE);
    const int sa = m->inter_sa[0];
    const double r = m->surf_r[sa], h = m->surf_ext[RC_SURF_NEXT * sa], p0 = 1e-7;
    const double th[5] = {1e-2, 1e-4, 5e-5, 1e-5, 3e-6};
    double worst = 0.0;
    for (int a = 0; a < 5; a++)
        for (int f = 0; f < 7; f++) {
            double *y = calloc((size_t)m->ny, sizeof(double));
            rc_initial_state(m, y);
            double *b = y + m->body_yadr[0];
            const double u[3] = {cos(0.9 * f + 0.3), sin(0.9 * f + 0.3), 0.0};
            double q[4], el[3] = {m->surf_n[3 * sa], m->surf_n[3 * sa + 1], m->surf_n[3 * sa + 2]}, ev[3], cl[3];
            quat(th[a], u, q);
            rot(q, el, ev);
            rot(q, m->surf_p + 3 * sa, cl);
            /* the centre at the height that puts the rim's lowest point p0 deep */
            const double ez = fabs(ev[2]), sn = sqrt(ev[0] * ev[0] + ev[1] * ev[1]);
            const double zc = h * ez + r * sn - p0;
            b[0] = 0.0013 - cl[0];
            b[1] = -0.0021 - cl[1];
            b[2] = zc - cl[2];
            memcpy(b + 3, q, sizeof q);
            rc_inter_report rp;
            rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &rp);
            /* the closed form at the state's own centre height */
            const double pe = h * ez + r * sn - (b[2] + cl[2]);
            worst = fmax(worst, fabs(rp.p - pe));
            free(y);
        }
    printf("    cylinder on its rim, tilt 1e-2..3e-6 rad: max |P - P_exact| = %.2e m (P = %.0e m)\n", worst, p0);
    ENSURE(worst < 1e-16);
    rc_model_free(m);
}

/* A flat-ended cylinder (Icont 1: the deepest point; r 0.03 m, length
 * 0.2 m, 0.5 kg) lying on a floor under gravity (linear law 1e3 N/m), its
 * axis tilted by theta about the floor's y axis, its centre at a fixed
 * height. The two ends' rims are eps apart in depth at |theta| = eps / L
 * (eps the end band, a quarter of the penetration scale): beyond, P is the
 * deeper rim's depth (closed form) and the point that rim's lowest point;
 * within, P is their C2 smooth maximum (3 eps / 16 above both at theta = 0)
 * and the point moves from one end to the other. The point is the depth's
 * own gradient (dP/dtheta = x_s - x_c: the force at it does the work F dP,
 * passive), P has no jump, and the Jacobian matches central differences
 * inside the band. Before, the point jumped between the ends as theta
 * changed sign (a cylinder coming to rest on its side: steps of 1e-12 s). */
static const char cl_deck[] =
    "/NODE\n1,0,0,0.03\n"
    "/RBODY/1\ncylinder\n1,,,,0.5\n1.8e-4,1.8e-3,1.8e-3\n0,0,0\n"
    "/SURF/CYL/1\ncylinder\n1,0,1\n0,0,0.03\n1,0,0\n0.03,0.2\n"
    "/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n"
    "/GRAV/1\ng\n0,Z,0,0,0,,1,-9.81\n"
    "/FUNCT/1\nload\n0,0\n1,1000\n"
    "/INTER/TYPE6/1\ncylinder on floor\n1,2\n,0.3\n\n1\n\n30\n/RUN\n0.01,0.001\n";

static double *cl_state(const rc_model *m, double th, double zc)
{
    double *y = calloc((size_t)m->ny, sizeof(double));
    if (!y) return NULL;
    rc_initial_state(m, y);
    double *b = y + m->body_yadr[0];
    const double u[3] = {0.0, 1.0, 0.0};
    double q[4];
    quat(th, u, q);
    b[2] = zc;
    memcpy(b + 3, q, sizeof q);
    return y;
}

/* dP/dtheta about the centre at tilt th (central differences, step dt)
 * less the contact point's x (the centre at x = 0): zero where the point
 * is the depth's own gradient (the force there does the work F dP). */
static double cl_gradient_error(const rc_model *m, double th, double dt, double zc, double xs)
{
    double *y1 = cl_state(m, th + dt, zc), *y2 = cl_state(m, th - dt, zc);
    rc_inter_report r1, r2;
    rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y1, &r1);
    rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y2, &r2);
    free(y1);
    free(y2);
    return fabs((r1.p - r2.p) / (2 * dt) - xs);
}

/* The Jacobian at the tilts th[0..n), closed, sticking and slipping (the
 * body moving and spinning), against central differences: the largest
 * scaled error; *bad and *outside count the entries beyond it. */
static double cl_jacobian_error(const rc_model *m, const double *th, int n, double zc, int *bad, int *outside)
{
    rc_data *d = rc_data_new(m);
    double err = 0;
    for (int c = 0; c < n; c++)
        for (int sl = 0; sl < 2; sl++) {
            double *y = cl_state(m, th[c], zc);
            double *yb = y + m->body_yadr[0];
            yb[7] = 0.01;
            yb[9] = -1e-3;
            yb[10] = 0.2;
            d->inter_mode[0] = RC_MODE_CLOSED;
            d->inter_slip[0] = sl;
            err = fmax(err, tu_jac_fd_error(m, d, 0.0, y, 1, bad, outside));
            free(y);
        }
    rc_data_free(d);
    return err;
}

static void test_cylinder_lying_end_band(void)
{
    char path[128];
    snprintf(path, sizeof path, "/tmp/rc_cyllying_test_%d.rad", (int)getpid());
    rc_model *m = TU_COMPILE_OK(cl_deck, path);
    if (!m) return;
    ENSURE(m->inter_pair[0] == RC_PAIR_CYL_PLANE);
    const int sa = m->inter_sa[0];
    const double r = m->surf_r[sa], h = m->surf_ext[RC_SURF_NEXT * sa], eps = m->surf_ext[RC_SURF_NEXT * sa + 3];
    const double ps = m->inter_pscale[0], zc = r - 0.4 * ps, L = 2.0 * h;
    printf("    p_s %.3e m, end band %.3e m (tilt %.2e rad)\n", ps, eps, eps / L);
    ENSURE(eps > 0 && fabs(eps - 0.25 * ps) < 1e-12 * ps);
    double maxjump = 0, worst_out = 0, worst_grad = 0, prevp = NAN, prevx = NAN;
    int mono = 1;
    for (int k = -300; k <= 300; k++) {
        const double th = 3.0 * eps / L * k / 100.0;
        double *y = cl_state(m, th, zc);
        rc_inter_report rp;
        rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &rp);
        /* the two rims' depths below the floor (closed form) */
        const double dplus = -(zc + sin(-th) * h - r * cos(th)), dminus = -(zc - sin(-th) * h - r * cos(th));
        const double pmax = fmax(dplus, dminus);
        if (fabs(dplus - dminus) >= eps * (1 + 1e-9)) worst_out = fmax(worst_out, fabs(rp.p - pmax));
        ENSURE(rp.p >= pmax - 1e-12 * ps && rp.p <= pmax + 3.0 * eps / 16.0 + 1e-12 * ps);
        if (k == 0) ENSURE(fabs(rp.p - (pmax + 3.0 * eps / 16.0)) < 1e-12 * ps);
        if (!isnan(prevp)) maxjump = fmax(maxjump, fabs(rp.p - prevp));
        /* within the band the point runs from the -x end to the +x end */
        if (!isnan(prevx) && fabs(dplus - dminus) < eps && rp.point[0] < prevx - 1e-15) mono = 0;
        prevp = rp.p;
        prevx = rp.point[0];
        /* dP/dtheta about the centre (central differences) against x_s - x_c */
        worst_grad = fmax(worst_grad, cl_gradient_error(m, th, 1e-4 * eps / L, zc, rp.point[0]) / h);
        free(y);
    }
    printf("    tilt through the band: max |P - P_rim| outside %.1e m, max step of P %.2e m (tilt step %.1e rad), "
           "point monotone %d, max |dP/dtheta - (x_s - x_c)| / h %.1e\n",
           worst_out, maxjump, 3.0 * eps / L / 100.0, mono, worst_grad);
    ENSURE(worst_out < 1e-12 * ps);
    ENSURE(maxjump < 0.05 * eps);
    ENSURE(mono);
    ENSURE(worst_grad < 1e-5);
    /* the Jacobian inside the band, closed (stick and slip) */
    int bad = 0, outside = 0;
    const double th_in = 0.3 * eps / L;
    const double err = cl_jacobian_error(m, &th_in, 1, zc, &bad, &outside);
    printf("    jacobian inside the band: max scaled |J - FD| = %.2e (%d bad, %d off the pattern)\n", err, bad, outside);
    ENSURE(bad == 0 && outside == 0);
    rc_model_free(m);
}

/* A flat-ended cylinder (Icont 1; r 0.03 m, length 0.2 m, 0.5 kg) standing
 * on its end on a floor (linear law 1e3 N/m), its axis tilted by theta
 * about the floor's y axis, its centre at a fixed height. The rim's lowest
 * point lies a = r sin(theta) below the face's centre: beyond the band
 * (a >= eps) P is that point's depth (closed form) and the contact point
 * that point; within it P is the smooth maximum of the rim's depths,
 * P_c + eps (3/8 + 3 x^2/4 - x^4/8), x = a / eps, and the point moves from
 * the face's centre to the rim continuously. The point is the depth's own
 * gradient (dP/dtheta = x_s - x_c), and the Jacobian matches central
 * differences inside the band. Before, the point was the face's centre up
 * to a tilt of 1e-6 rad and the rim beyond, a jump of r in the moment arm
 * (a cylinder that came to rest on its end: steps of 5e-11 s, Max_steps). */
static const char cu_deck[] =
    "/NODE\n1,0,0,0.1\n"
    "/RBODY/1\ncylinder\n1,,,,0.5\n1.8e-3,1.8e-3,1.8e-4\n0,0,0\n"
    "/SURF/CYL/1\ncylinder\n1,0,1\n0,0,0.1\n0,0,1\n0.03,0.2\n"
    "/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n"
    "/GRAV/1\ng\n0,Z,0,0,0,,1,-9.81\n"
    "/FUNCT/1\nload\n0,0\n1,1000\n"
    "/INTER/TYPE6/1\ncylinder on floor\n1,2\n,0.3\n\n1\n\n30\n/RUN\n0.01,0.001\n";

static void test_cylinder_standing_face_band(void)
{
    char path[128];
    snprintf(path, sizeof path, "/tmp/rc_cylstand_test_%d.rad", (int)getpid());
    rc_model *m = TU_COMPILE_OK(cu_deck, path);
    if (!m) return;
    ENSURE(m->inter_pair[0] == RC_PAIR_CYL_PLANE);
    const int sa = m->inter_sa[0];
    const double r = m->surf_r[sa], h = m->surf_ext[RC_SURF_NEXT * sa], eps = m->surf_ext[RC_SURF_NEXT * sa + 3];
    const double ps = m->inter_pscale[0], zc = h - 0.4 * ps;
    printf("    p_s %.3e m, band %.3e m (tilt %.2e rad)\n", ps, eps, eps / r);
    ENSURE(eps > 0);
    double maxjump = 0, worst_out = 0, worst_in = 0, worst_grad = 0, prevp = NAN, prevx = NAN;
    int mono = 1;
    for (int k = -300; k <= 300; k++) {
        const double th = 3.0 * eps / r * k / 100.0;
        double *y = cl_state(m, th, zc);
        rc_inter_report rp;
        rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &rp);
        /* the face's centre and the rim's lowest point below the floor */
        const double pc = h * cos(th) - zc, a = r * fabs(sin(th)), x = a / eps;
        if (x >= 1.0 + 1e-9) worst_out = fmax(worst_out, fabs(rp.p - (pc + a)));
        else worst_in = fmax(worst_in, fabs(rp.p - (pc + eps * (0.375 + 0.75 * x * x - x * x * x * x / 8.0))));
        if (!isnan(prevp)) maxjump = fmax(maxjump, fabs(rp.p - prevp));
        /* about the face's centre (-h sin(theta) in x) the point runs from
         * the -x rim (theta < 0) to the +x rim */
        const double xr = rp.point[0] + h * sin(th);
        if (!isnan(prevx) && x < 1.0 && xr < prevx - 1e-15) mono = 0;
        prevp = rp.p;
        prevx = xr;
        worst_grad = fmax(worst_grad, cl_gradient_error(m, th, 1e-4 * eps / r, zc, rp.point[0]) / r);
        free(y);
    }
    printf("    tilt through the band: max |P - P_rim| outside %.1e m, max |P - smooth form| inside %.1e m, max step "
           "of P %.2e m (tilt step %.1e rad), point monotone %d, max |dP/dtheta - (x_s - x_c)| / r %.1e\n",
           worst_out, worst_in, maxjump, 3.0 * eps / r / 100.0, mono, worst_grad);
    ENSURE(worst_out < 1e-12 * ps && worst_in < 1e-12 * ps);
    ENSURE(maxjump < 0.1 * eps);
    ENSURE(mono);
    ENSURE(worst_grad < 1e-5);
    int bad = 0, outside = 0;
    const double tilts[3] = {0.0, 0.3 * eps / r, 0.9 * eps / r};
    const double err = cl_jacobian_error(m, tilts, 3, zc, &bad, &outside);
    printf("    jacobian inside the band: max scaled |J - FD| = %.2e (%d bad, %d off the pattern)\n", err, bad, outside);
    ENSURE(bad == 0 && outside == 0);
    rc_model_free(m);
    /* the fuzzer's scene: a cylinder dropped on a floor, at rest on its end */
    m = TU_LOAD_OK("fuzz/physics/regressions/cylinder_standing_on_end_face_point_jump_max_steps.rad");
    if (!m) return;
    static tu_evlog ev;
    rc_stats st;
    ENSURE(tu_run_evlog(m, &ev, &st) == RC_OK && st.violations == 0);
    printf("    dropped and standing on its end: %ld steps, %ld events; %s\n", st.steps, st.events, st.physics_note);
    rc_model_free(m);
}

/* The Jacobian in every region against central differences: TYPE6 with
 * friction (stick, slip), power law with step5 friction (uncapped, capped)
 * or a /FRICTION card (viscous and incremental, filtered), closed and
 * released. */
static void test_sphcyl_jacobian_regions(void)
{
    sc_region g[7];
    sc_regions(g);
    int bad = 0, outside = 0, combos = 0;
    double maxerr = 0;
    const char *decks[5] = {sc_type6, sc_power, sc_frc_viscous, sc_frc_incremental, sc_frc_spline};
    const char *names[5] = {"type6+fric", "power+step5", "power+/FRICTION viscous, filter",
                            "power+/FRICTION incremental, filter", "power spline+/FRICTION viscous"};
    for (int law = 0; law < 5; law++)
        for (int k = 0; k < 7; k++) {
            rc_error e;
            rc_model *m = sc_compile(g[k].iend, decks[law], &e);
            ENSURE(m != NULL);
            if (!m) {
                fprintf(stderr, "  %s\n", e.msg);
                return;
            }
            rc_data *d = rc_data_new(m);
            double cb[3], ea[3], xc[3];
            double *y = sc_state(m, g[k].z, g[k].rho, cb, ea, xc);
            double err = 0;
            const int modes[2] = {RC_MODE_CLOSED, RC_MODE_RELEASED};
            for (int md = 0; md < 2; md++)
                for (int sl = 0; sl < 2; sl++) {
                    d->inter_mode[0] = modes[md];
                    d->inter_branch[0] = law ? RC_BR_UNLOAD : RC_BR_LOAD;
                    d->inter_slip[0] = sl;
                    err = fmax(err, tu_jac_fd_error(m, d, 0.0, y, 1, &bad, &outside));
                    combos++;
                }
            rc_inter_report r;
            rc_inter_report_eval(m, 0, RC_MODE_CLOSED, d->inter_branch[0], 0, 0, 0.0, y, &r);
            printf("    %s, %-30s P = %.4g m, F_n = %.4g N, slip speed %.3g m/s, max scaled |J - FD| = %.2e\n",
                   names[law], g[k].name, r.p, r.fn, r.vslip, err);
            maxerr = fmax(maxerr, err);
            free(y);
            rc_data_free(d);
            rc_model_free(m);
        }
    printf("    sphere-cylinder jacobian: %d combinations, max scaled |J - FD| = %.2e\n", combos, maxerr);
    ENSURE(bad == 0);
    ENSURE(outside == 0);
}

void suite_sphcyl(void);
void suite_sphcyl(void)
{
    RUN_TEST(test_sphcyl_geometry_regions);
    RUN_TEST(test_sphcyl_continuity);
    RUN_TEST(test_sphcyl_jacobian_regions);
    RUN_TEST(test_cylinder_plane_depth_near_upright);
    RUN_TEST(test_cylinder_standing_face_band);
    RUN_TEST(test_cylinder_lying_end_band);
}
