/*
 * Export of a results file to ParaView: a .pvd collection of VTK XML
 * PolyData files, written here without the VTK library
 * (docs/output-format.md, "ParaView export"). The data arrays are in the
 * appended raw binary format (UInt64 block headers, little-endian, Float64
 * and Int32 values), or ASCII on request. The frames are chosen among the
 * records (select_frames: the default's output times, dt or every N-th).
 *
 * Per frame, record k of the results file:
 *   <stem>_bodies_<k>.vtp    the surfaces, tessellated in the frame of
 *                            their body and placed by its pose: spheres
 *                            (UV spheres), cylinders (side and flat ends;
 *                            rounded ends drawn flat), boxes, and planes as
 *                            square patches sized to the motion; point data
 *                            body_id, surface_id, velocity [m/s] (of the
 *                            body's centre of mass)
 *   <stem>_contacts_<k>.vtp  one vertex per interface at its contact point;
 *                            point data inter_id, mode, penetration [m],
 *                            force_normal [N], normal (from the first to
 *                            the second surface), force_normal_vector (the
 *                            normal force on the first surface's body) and
 *                            force_friction [N]; field data TimeValue
 *                            [s] and the events since the previous record
 *                            (event_time [s], event_kind, event_element)
 * and <stem>.pvd listing both as parts 0 and 1 of each time step.
 */
#include "output/output.h"

#include "base/error.h"

#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <netcdf.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* Tessellation: segments around a sphere or cylinder, rings of a sphere [-]. */
#define VTK_NSEG 24
#define VTK_NRING 12
#define VTK_PI 3.14159265358979323846

/* The results file open for reading, and what the export needs of it. */
typedef struct vtk_src {
    const char *path;
    int ncid;
    size_t nrec, nbody, ninter, nsurf, nevent;
    int *body_id;       /* [nbody] */
    int *surf_id, *surf_bidx; /* [nsurf] id, body index (-1: fixed in space) */
    char **surf_kind;   /* [nsurf] */
    double *surf_p, *surf_n, *surf_r, *surf_x; /* geometry, body frame */
    int *inter_id;      /* [ninter] */
    double *ev_t;       /* [nevent] */
    char **ev_kind, **ev_elem; /* [nevent] */
    size_t nsegnode, nseg; /* segment surfaces: nodes and segments (0: none) */
    int *surf_node0, *surf_seg0; /* [nsurf] first node and segment of each surface */
    double *seg_node;   /* [nsegnode*3] body frame [m] */
    int *seg_corner;    /* [nseg*4] local node indices */
    double plane_half;  /* half-size of the plane patches [m] */
    double plane_c[3];  /* a point of the motion the patches are centred on [m] */
} vtk_src;

/* RC_EIO "path: what: netCDF message". */
#define NC_DO(src, call, ...)                                                                   \
    do {                                                                                        \
        int s_ = (call);                                                                        \
        if (s_ != NC_NOERR) {                                                                   \
            char w_[256];                                                                       \
            snprintf(w_, sizeof w_, __VA_ARGS__);                                               \
            return RC_SET(err, RC_EIO, "%s: %s: %s", (src)->path, w_, nc_strerror(s_));         \
        }                                                                                       \
    } while (0)

static size_t dim_or_zero(int ncid, const char *name)
{
    int id;
    size_t n = 0;
    if (nc_inq_dimid(ncid, name, &id) != NC_NOERR || nc_inq_dimlen(ncid, id, &n) != NC_NOERR) return 0;
    return n;
}

static int has_var(int ncid, const char *name)
{
    int id;
    return nc_inq_varid(ncid, name, &id) == NC_NOERR;
}

/* Read a whole variable (doubles, ints or strings) into a new array. */
static rc_status get_all(vtk_src *s, const char *name, nc_type type, size_t n, void **out, rc_error *err)
{
    int id;
    *out = NULL;
    NC_DO(s, nc_inq_varid(s->ncid, name, &id), "variable %s", name);
    const size_t sz = type == NC_DOUBLE ? sizeof(double) : type == NC_INT ? sizeof(int) : sizeof(char *);
    *out = calloc(n + 1, sz);
    if (!*out) RC_RAISE(err, RC_ENOMEM, "export: out of memory reading %s", name);
    if (n == 0) return RC_OK;
    if (type == NC_DOUBLE) NC_DO(s, nc_get_var_double(s->ncid, id, *out), "reading %s", name);
    else if (type == NC_INT) NC_DO(s, nc_get_var_int(s->ncid, id, *out), "reading %s", name);
    else NC_DO(s, nc_get_var_string(s->ncid, id, *out), "reading %s", name);
    return RC_OK;
}

/* One record's slice [k, ...] of a time series of `per` values. */
static rc_status get_rec(vtk_src *s, const char *name, size_t k, size_t d1, size_t d2, double *out, rc_error *err)
{
    int id;
    NC_DO(s, nc_inq_varid(s->ncid, name, &id), "variable %s", name);
    size_t start[3] = {k, 0, 0}, count[3] = {1, d1, d2};
    NC_DO(s, nc_get_vara_double(s->ncid, id, start, count, out), "reading %s record %zu", name, k);
    return RC_OK;
}

static rc_status get_rec_int(vtk_src *s, const char *name, size_t k, size_t d1, int *out, rc_error *err)
{
    int id;
    NC_DO(s, nc_inq_varid(s->ncid, name, &id), "variable %s", name);
    size_t start[2] = {k, 0}, count[2] = {1, d1};
    NC_DO(s, nc_get_vara_int(s->ncid, id, start, count, out), "reading %s record %zu", name, k);
    return RC_OK;
}

static void src_free(vtk_src *s)
{
    if (s->surf_kind) nc_free_string(s->nsurf, s->surf_kind);
    if (s->ev_kind) nc_free_string(s->nevent, s->ev_kind);
    if (s->ev_elem) nc_free_string(s->nevent, s->ev_elem);
    void *p[] = {s->surf_node0, s->surf_seg0, s->seg_node, s->seg_corner, s->body_id, s->surf_id, s->surf_bidx,
                 s->surf_kind, s->surf_p, s->surf_n, s->surf_r,
                 s->surf_x, s->inter_id, s->ev_t, s->ev_kind, s->ev_elem};
    for (size_t k = 0; k < sizeof p / sizeof p[0]; k++) free(p[k]);
    if (s->ncid >= 0) nc_close(s->ncid);
}

/* Rotate v (body frame) by the unit quaternion q = (w, x, y, z). */
static void qrot(const double q[4], const double v[3], double out[3])
{
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double R[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                         2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                         2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
    for (int i = 0; i < 3; i++) out[i] = R[3 * i] * v[0] + R[3 * i + 1] * v[1] + R[3 * i + 2] * v[2];
}

/* Two unit vectors completing the unit n to an orthonormal frame. */
static void frame_of(const double n[3], double a[3], double b[3])
{
    const double h[3] = {fabs(n[0]) < 0.9 ? 1.0 : 0.0, fabs(n[0]) < 0.9 ? 0.0 : 1.0, 0.0};
    a[0] = h[1] * n[2] - h[2] * n[1];
    a[1] = h[2] * n[0] - h[0] * n[2];
    a[2] = h[0] * n[1] - h[1] * n[0];
    const double l = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    for (int i = 0; i < 3; i++) a[i] /= l;
    b[0] = n[1] * a[2] - n[2] * a[1];
    b[1] = n[2] * a[0] - n[0] * a[2];
    b[2] = n[0] * a[1] - n[1] * a[0];
}

/* The mesh of one record: points (global), polygons (offsets into conn). */
typedef struct mesh {
    double *pt;   /* [3 np] */
    int *body, *surf; /* [np] body id (-1 fixed in space), surface id */
    double *vel;  /* [3 np] */
    int np, cap;
    int *conn, nconn, conncap;
    int *off, *csurf, npoly, polycap;
} mesh;

static int mesh_point(mesh *m, const double p[3], int body, int surf, const double v[3])
{
    if (m->np == m->cap) {
        const int c = m->cap ? 2 * m->cap : 256;
        double *pt = realloc(m->pt, 3 * (size_t)c * sizeof *pt), *vel = realloc(m->vel, 3 * (size_t)c * sizeof *vel);
        if (pt) m->pt = pt;
        if (vel) m->vel = vel;
        int *b = realloc(m->body, (size_t)c * sizeof *b), *s = realloc(m->surf, (size_t)c * sizeof *s);
        if (b) m->body = b;
        if (s) m->surf = s;
        if (!pt || !vel || !b || !s) return -1;
        m->cap = c;
    }
    memcpy(m->pt + 3 * m->np, p, 3 * sizeof(double));
    memcpy(m->vel + 3 * m->np, v, 3 * sizeof(double));
    m->body[m->np] = body;
    m->surf[m->np] = surf;
    return m->np++;
}

/* A polygon of n point indices; returns -1 when out of memory. */
static int mesh_poly(mesh *m, const int *idx, int n, int surf)
{
    if (m->nconn + n > m->conncap) {
        const int c = 2 * (m->conncap + n) + 64;
        int *p = realloc(m->conn, (size_t)c * sizeof *p);
        if (!p) return -1;
        m->conn = p;
        m->conncap = c;
    }
    if (m->npoly == m->polycap) {
        const int c = m->polycap ? 2 * m->polycap : 128;
        int *o = realloc(m->off, (size_t)c * sizeof *o), *s = realloc(m->csurf, (size_t)c * sizeof *s);
        if (o) m->off = o;
        if (s) m->csurf = s;
        if (!o || !s) return -1;
        m->polycap = c;
    }
    memcpy(m->conn + m->nconn, idx, (size_t)n * sizeof *idx);
    m->nconn += n;
    m->off[m->npoly] = m->nconn;
    m->csurf[m->npoly++] = surf;
    return 0;
}

/* Tessellate surface j placed by (pos, q); local points in the body frame. */
static int tessellate(mesh *m, const vtk_src *s, size_t j, const double pos[3], const double q[4], const double v[3])
{
    const char *kind = s->surf_kind[j];
    const double *p = s->surf_p + 3 * j, *n = s->surf_n + 3 * j, *x = s->surf_x + (size_t)RC_OUT_SURF_NPARAM * j;
    const double r = s->surf_r[j];
    const int bid = s->surf_bidx[j] >= 0 ? s->body_id[s->surf_bidx[j]] : -1, sid = s->surf_id[j];
    const int base = m->np;
    int bad = 0;
    /* local point -> global point */
#define PUT(lx, ly, lz)                                                                      \
    do {                                                                                     \
        const double l_[3] = {(lx), (ly), (lz)};                                             \
        double g_[3];                                                                        \
        qrot(q, l_, g_);                                                                     \
        for (int c_ = 0; c_ < 3; c_++) g_[c_] += pos[c_];                                    \
        if (mesh_point(m, g_, bid, sid, v) < 0) bad = 1;                                     \
    } while (0)
    if (!strcmp(kind, "SPHERE")) {
        /* poles, then VTK_NRING - 1 rings of VTK_NSEG points */
        PUT(p[0], p[1], p[2] + r);
        PUT(p[0], p[1], p[2] - r);
        for (int i = 1; i < VTK_NRING; i++) {
            const double th = VTK_PI * i / VTK_NRING;
            for (int k = 0; k < VTK_NSEG; k++) {
                const double ph = 2 * VTK_PI * k / VTK_NSEG;
                PUT(p[0] + r * sin(th) * cos(ph), p[1] + r * sin(th) * sin(ph), p[2] + r * cos(th));
            }
        }
        for (int i = 0; i < VTK_NRING; i++)
            for (int k = 0; k < VTK_NSEG; k++) {
                const int k1 = (k + 1) % VTK_NSEG;
                const int a = base + 2 + (i - 1) * VTK_NSEG, b = base + 2 + i * VTK_NSEG;
                if (i == 0) bad |= mesh_poly(m, (int[]){base, b + k, b + k1}, 3, sid);
                else if (i == VTK_NRING - 1) bad |= mesh_poly(m, (int[]){a + k, base + 1, a + k1}, 3, sid);
                else bad |= mesh_poly(m, (int[]){a + k, b + k, b + k1, a + k1}, 4, sid);
            }
    } else if (!strcmp(kind, "CYLINDER")) {
        double a[3], b[3];
        frame_of(n, a, b);
        const double hl = x[0];
        for (int e = 0; e < 2; e++) {
            const double o = e ? hl : -hl;
            for (int k = 0; k < VTK_NSEG; k++) {
                const double c = r * cos(2 * VTK_PI * k / VTK_NSEG), sn = r * sin(2 * VTK_PI * k / VTK_NSEG);
                PUT(p[0] + o * n[0] + c * a[0] + sn * b[0], p[1] + o * n[1] + c * a[1] + sn * b[1],
                    p[2] + o * n[2] + c * a[2] + sn * b[2]);
            }
        }
        int cap0[VTK_NSEG], cap1[VTK_NSEG];
        for (int k = 0; k < VTK_NSEG; k++) {
            const int k1 = (k + 1) % VTK_NSEG;
            bad |= mesh_poly(m, (int[]){base + k, base + k1, base + VTK_NSEG + k1, base + VTK_NSEG + k}, 4, sid);
            cap0[k] = base + VTK_NSEG - 1 - k;
            cap1[k] = base + VTK_NSEG + k;
        }
        bad |= mesh_poly(m, cap0, VTK_NSEG, sid);
        bad |= mesh_poly(m, cap1, VTK_NSEG, sid);
    } else if (!strcmp(kind, "BOX")) {
        const double *u = x + 3, *vv = x + 6, *w = x + 9;
        for (int c = 0; c < 8; c++) {
            const double su = (c & 1) ? x[0] : -x[0], sv = (c & 2) ? x[1] : -x[1], sw = (c & 4) ? x[2] : -x[2];
            PUT(p[0] + su * u[0] + sv * vv[0] + sw * w[0], p[1] + su * u[1] + sv * vv[1] + sw * w[1],
                p[2] + su * u[2] + sv * vv[2] + sw * w[2]);
        }
        static const int face[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
        for (int f = 0; f < 6; f++)
            bad |= mesh_poly(m, (int[]){base + face[f][0], base + face[f][1], base + face[f][2], base + face[f][3]}, 4,
                             sid);
    } else if (!strcmp(kind, "PLANE")) {
        /* a square patch centred on the projection of the motion's centre */
        double a[3], b[3], nl[3], ng[3], pg[3], cg[3];
        qrot(q, n, ng);
        qrot(q, p, pg);
        for (int c = 0; c < 3; c++) pg[c] += pos[c];
        double dd = 0;
        for (int c = 0; c < 3; c++) dd += (s->plane_c[c] - pg[c]) * ng[c];
        for (int c = 0; c < 3; c++) cg[c] = s->plane_c[c] - dd * ng[c];
        frame_of(ng, a, b);
        (void)nl;
        const double h = s->plane_half;
        static const double sg[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (int c = 0; c < 4; c++) {
            const double g[3] = {cg[0] + h * (sg[c][0] * a[0] + sg[c][1] * b[0]), cg[1] + h * (sg[c][0] * a[1] + sg[c][1] * b[1]),
                                 cg[2] + h * (sg[c][0] * a[2] + sg[c][1] * b[2])};
            if (mesh_point(m, g, bid, sid, v) < 0) bad = 1;
        }
        bad |= mesh_poly(m, (int[]){base, base + 1, base + 2, base + 3}, 4, sid);
    } else if (!strcmp(kind, "SEGMENTS") && s->nseg > 0) {
        /* its nodes, then its segments (a triangle repeats its third node) */
        const size_t n0 = (size_t)s->surf_node0[j], s0 = (size_t)s->surf_seg0[j];
        size_t n1 = s->nsegnode, s1 = s->nseg;
        if (j + 1 < s->nsurf) { /* every surface has its first node (a box with corners some) */
            n1 = (size_t)s->surf_node0[j + 1];
            s1 = (size_t)s->surf_seg0[j + 1];
        }
        for (size_t k = n0; k < n1 && k < s->nsegnode; k++) PUT(s->seg_node[3 * k], s->seg_node[3 * k + 1], s->seg_node[3 * k + 2]);
        for (size_t k = s0; k < s1 && k < s->nseg; k++) {
            const int *c = s->seg_corner + 4 * k;
            const int nc = c[3] == c[2] ? 3 : 4;
            int idx[4];
            for (int e = 0; e < nc; e++) {
                if (c[e] < 0 || (size_t)c[e] >= n1 - n0) bad = 1;
                idx[e] = base + c[e];
            }
            if (!bad) bad |= mesh_poly(m, idx, nc, sid);
        }
    }
#undef PUT
    return bad ? -1 : 0;
}

/* ---- XML writing ---------------------------------------------------------- */

/* 1 on a little-endian host (checked at run time: the binary files declare
 * byte_order="LittleEndian", so a big-endian host swaps each value). */
static int host_little_endian(void)
{
    const uint16_t one = 1;
    unsigned char b;
    memcpy(&b, &one, 1);
    return b == 1;
}

/* Tests only (output.h): write the binary blocks byte-swapped, as a
 * big-endian host does. */
static int vtk_force_swap = 0;
void rc_vtk_test_force_swap(int on)
{
    vtk_force_swap = on;
}

/* A file being written: in binary, the data arrays' XML elements carry the
 * offset of their block in the appended data; the blocks (each a UInt64
 * byte count, then the bytes) follow the XML at the end of the file. */
#define VTK_MAX_BLOCKS 32
typedef struct vtkw {
    FILE *f;
    int ascii;
    uint64_t off; /* bytes of the blocks so far */
    int nblk;
    struct {
        const void *p;   /* values, or (elsize 0) an array of n strings */
        size_t n, elsize;
        uint64_t bytes;
    } blk[VTK_MAX_BLOCKS];
    int overflow;
} vtkw;

static void vtkw_block(vtkw *w, const void *p, size_t n, size_t elsize, uint64_t bytes)
{
    if (w->nblk == VTK_MAX_BLOCKS) {
        w->overflow = 1;
        return;
    }
    w->blk[w->nblk].p = p;
    w->blk[w->nblk].n = n;
    w->blk[w->nblk].elsize = elsize;
    w->blk[w->nblk++].bytes = bytes;
    w->off += sizeof(uint64_t) + bytes;
}

/* Write n values of elsize bytes, little-endian. */
static void put_le(FILE *f, const void *p, size_t n, size_t elsize, int swap)
{
    if (!swap || elsize == 1) {
        fwrite(p, elsize, n, f);
        return;
    }
    unsigned char buf[4096];
    const unsigned char *c = p;
    const size_t per = sizeof buf / elsize;
    for (size_t k = 0; k < n; k += per) {
        const size_t m = n - k < per ? n - k : per;
        for (size_t i = 0; i < m; i++)
            for (size_t e = 0; e < elsize; e++) buf[i * elsize + e] = c[(k + i) * elsize + elsize - 1 - e];
        fwrite(buf, elsize, m, f);
    }
}

static void xml_doubles(vtkw *w, const char *name, int ncomp, const double *v, size_t n)
{
    FILE *f = w->f;
    fprintf(f, "<DataArray type=\"Float64\" Name=\"%s\" NumberOfComponents=\"%d\" NumberOfTuples=\"%zu\" ", name, ncomp,
            n);
    if (!w->ascii) {
        fprintf(f, "format=\"appended\" offset=\"%" PRIu64 "\"/>\n", w->off);
        vtkw_block(w, v, n * (size_t)ncomp, sizeof *v, (uint64_t)(n * (size_t)ncomp * sizeof *v));
        return;
    }
    fprintf(f, "format=\"ascii\">\n");
    for (size_t k = 0; k < n * (size_t)ncomp; k++) fprintf(f, "%.17g%c", v[k], (k + 1) % (size_t)ncomp ? ' ' : '\n');
    fprintf(f, "</DataArray>\n");
}

static void xml_ints(vtkw *w, const char *name, const int *v, size_t n)
{
    FILE *f = w->f;
    fprintf(f, "<DataArray type=\"Int32\" Name=\"%s\" NumberOfComponents=\"1\" NumberOfTuples=\"%zu\" ", name, n);
    if (!w->ascii) {
        fprintf(f, "format=\"appended\" offset=\"%" PRIu64 "\"/>\n", w->off);
        vtkw_block(w, v, n, sizeof *v, (uint64_t)(n * sizeof *v));
        return;
    }
    fprintf(f, "format=\"ascii\">\n");
    for (size_t k = 0; k < n; k++) fprintf(f, "%d%c", v[k], (k + 1) % 16 && k + 1 < n ? ' ' : '\n');
    fprintf(f, "</DataArray>\n");
}

/* A vtkStringArray: in binary the strings one after the other, each ended
 * by a 0 byte; in ASCII each string as its byte values, then 0. */
static void xml_strings(vtkw *w, const char *name, char *const *s, size_t n)
{
    FILE *f = w->f;
    fprintf(f, "<Array type=\"String\" Name=\"%s\" NumberOfTuples=\"%zu\" ", name, n);
    if (!w->ascii) {
        uint64_t bytes = 0;
        for (size_t k = 0; k < n; k++) bytes += (s[k] ? strlen(s[k]) : 0) + 1;
        fprintf(f, "format=\"appended\" offset=\"%" PRIu64 "\"/>\n", w->off);
        vtkw_block(w, s, n, 0, bytes);
        return;
    }
    fprintf(f, "format=\"ascii\">\n");
    for (size_t k = 0; k < n; k++) {
        for (const unsigned char *c = (const unsigned char *)s[k]; c && *c; c++) fprintf(f, "%u ", *c);
        fprintf(f, "0\n");
    }
    fprintf(f, "</Array>\n");
}

/* Open a .vtp file and write its opening element. */
static rc_status vtkw_open(vtkw *w, const char *path, int ascii, rc_error *err)
{
    memset(w, 0, sizeof *w);
    w->ascii = ascii;
    if (!(w->f = fopen(path, "wb"))) RC_RAISE(err, RC_EIO, "%s: cannot create: %s", path, strerror(errno));
    fprintf(w->f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\"%s>\n"
                  "<PolyData>\n",
            ascii ? "" : " header_type=\"UInt64\"");
    return RC_OK;
}

static rc_status close_file(FILE *f, const char *path, double *bytes, rc_error *err)
{
    const int bad = ferror(f);
    const long size = bad ? -1 : ftell(f);
    if (fclose(f) != 0 || bad) RC_RAISE(err, RC_EIO, "%s: cannot write: %s", path, strerror(errno));
    if (bytes && size > 0) *bytes += (double)size;
    return RC_OK;
}

/* Close the PolyData element, write the appended blocks, close the file. */
static rc_status vtkw_close(vtkw *w, const char *path, double *bytes, rc_error *err)
{
    FILE *f = w->f;
    fprintf(f, "</PolyData>\n");
    if (!w->ascii) {
        const int swap = vtk_force_swap || !host_little_endian();
        fprintf(f, "<AppendedData encoding=\"raw\">\n_");
        for (int k = 0; k < w->nblk; k++) {
            const uint64_t nb = w->blk[k].bytes;
            put_le(f, &nb, 1, sizeof nb, swap);
            if (w->blk[k].elsize > 0) put_le(f, w->blk[k].p, w->blk[k].n, w->blk[k].elsize, swap);
            else
                for (size_t i = 0; i < w->blk[k].n; i++) {
                    const char *str = ((char *const *)w->blk[k].p)[i];
                    fwrite(str ? str : "", 1, (str ? strlen(str) : 0) + 1, f);
                }
        }
        fprintf(f, "\n</AppendedData>\n");
    }
    fprintf(f, "</VTKFile>\n");
    if (w->overflow) {
        fclose(f);
        RC_RAISE(err, RC_EINTERNAL, "%s: more than %d data arrays in one file", path, VTK_MAX_BLOCKS);
    }
    return close_file(f, path, bytes, err);
}

/* Bodies file of record k. */
static rc_status write_bodies(const char *path, const mesh *m, double t, int ascii, double *bytes, rc_error *err)
{
    vtkw w;
    rc_status rc = vtkw_open(&w, path, ascii, err);
    if (rc != RC_OK) return rc;
    FILE *f = w.f;
    fprintf(f, "<FieldData>\n");
    xml_doubles(&w, "TimeValue", 1, &t, 1);
    fprintf(f, "</FieldData>\n<Piece NumberOfPoints=\"%d\" NumberOfVerts=\"0\" NumberOfLines=\"0\" "
               "NumberOfStrips=\"0\" NumberOfPolys=\"%d\">\n<PointData Scalars=\"body_id\" Vectors=\"velocity\">\n",
            m->np, m->npoly);
    xml_ints(&w, "body_id", m->body, (size_t)m->np);
    xml_ints(&w, "surface_id", m->surf, (size_t)m->np);
    xml_doubles(&w, "velocity", 3, m->vel, (size_t)m->np);
    fprintf(f, "</PointData>\n<CellData Scalars=\"surface_id\">\n");
    xml_ints(&w, "surface_id", m->csurf, (size_t)m->npoly);
    fprintf(f, "</CellData>\n<Points>\n");
    xml_doubles(&w, "Points", 3, m->pt, (size_t)m->np);
    fprintf(f, "</Points>\n<Polys>\n");
    xml_ints(&w, "connectivity", m->conn, (size_t)m->nconn);
    xml_ints(&w, "offsets", m->off, (size_t)m->npoly);
    fprintf(f, "</Polys>\n</Piece>\n");
    return vtkw_close(&w, path, bytes, err);
}

/* The values of the contacts of one record. */
typedef struct contacts {
    double *point, *normal, *pen, *fn, *ffric, *fvec;
    int *mode, *seq;
} contacts;

/* Contacts file of a frame with the events in (t_prev, t] (rows e0..e1). */
static rc_status write_contacts(const char *path, const vtk_src *s, const contacts *c, double t, size_t e0, size_t e1,
                                int ascii, double *bytes, rc_error *err)
{
    vtkw w;
    rc_status rc = vtkw_open(&w, path, ascii, err);
    if (rc != RC_OK) return rc;
    FILE *f = w.f;
    const size_t ni = s->ninter, ne = e1 - e0;
    fprintf(f, "<FieldData>\n");
    xml_doubles(&w, "TimeValue", 1, &t, 1);
    const int nev = (int)ne;
    xml_ints(&w, "event_count", &nev, 1);
    if (ne > 0) {
        xml_doubles(&w, "event_time", 1, s->ev_t + e0, ne);
        xml_strings(&w, "event_kind", s->ev_kind + e0, ne);
        xml_strings(&w, "event_element", s->ev_elem + e0, ne);
    }
    fprintf(f, "</FieldData>\n<Piece NumberOfPoints=\"%zu\" NumberOfVerts=\"%zu\" NumberOfLines=\"0\" "
               "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n",
            ni, ni);
    if (ni > 0) {
        fprintf(f, "<PointData Scalars=\"force_normal\" Vectors=\"force_normal_vector\">\n");
        xml_ints(&w, "inter_id", s->inter_id, ni);
        xml_ints(&w, "mode", c->mode, ni);
        xml_doubles(&w, "penetration", 1, c->pen, ni);
        xml_doubles(&w, "force_normal", 1, c->fn, ni);
        xml_doubles(&w, "normal", 3, c->normal, ni);
        xml_doubles(&w, "force_normal_vector", 3, c->fvec, ni);
        xml_doubles(&w, "force_friction", 3, c->ffric, ni);
        fprintf(f, "</PointData>\n");
    }
    fprintf(f, "<Points>\n");
    xml_doubles(&w, "Points", 3, c->point, ni);
    fprintf(f, "</Points>\n<Verts>\n");
    xml_ints(&w, "connectivity", c->seq, ni);
    xml_ints(&w, "offsets", c->seq + ni, ni);
    fprintf(f, "</Verts>\n</Piece>\n");
    /* nev is read in vtkw_close (binary): still in scope here */
    return vtkw_close(&w, path, bytes, err);
}

/* ---- Reading the results file -------------------------------------------------- */

static rc_status src_open(vtk_src *s, const char *path, rc_error *err)
{
    memset(s, 0, sizeof *s);
    s->ncid = -1;
    s->path = path;
    int st = nc_open(path, NC_NOWRITE, &s->ncid);
    if (st != NC_NOERR) {
        s->ncid = -1;
        RC_RAISE(err, RC_EIO, "%s: cannot open the results file: %s", path, nc_strerror(st));
    }
    static const char *const need[] = {"time", "body", "body_position", "body_quaternion", "body_velocity"};
    for (size_t k = 0; k < sizeof need / sizeof need[0]; k++)
        if (!has_var(s->ncid, need[k]))
            RC_RAISE(err, RC_EINPUT, "%s: not a ricochet results file of this version (no variable %s)", path, need[k]);
    s->nrec = dim_or_zero(s->ncid, "time");
    s->nbody = dim_or_zero(s->ncid, "body");
    s->ninter = dim_or_zero(s->ncid, "inter");
    s->nsurf = dim_or_zero(s->ncid, "surface");
    s->nevent = has_var(s->ncid, "event_time") ? dim_or_zero(s->ncid, "event") : 0;
    if (s->nsurf > 0 && (!has_var(s->ncid, "surface_kind") || !has_var(s->ncid, "surface_parameters")))
        RC_RAISE(err, RC_EINPUT, "%s: surface geometry incomplete", path);
    rc_status rc = get_all(s, "body", NC_INT, s->nbody, (void **)&s->body_id, err);
    if (rc == RC_OK && s->ninter > 0) rc = get_all(s, "inter", NC_INT, s->ninter, (void **)&s->inter_id, err);
    if (rc == RC_OK && s->nsurf > 0) {
        int *sbody = NULL;
        rc = get_all(s, "surface", NC_INT, s->nsurf, (void **)&s->surf_id, err);
        if (rc == RC_OK) rc = get_all(s, "surface_kind", NC_STRING, s->nsurf, (void **)&s->surf_kind, err);
        if (rc == RC_OK) rc = get_all(s, "surface_point", NC_DOUBLE, 3 * s->nsurf, (void **)&s->surf_p, err);
        if (rc == RC_OK) rc = get_all(s, "surface_normal", NC_DOUBLE, 3 * s->nsurf, (void **)&s->surf_n, err);
        if (rc == RC_OK) rc = get_all(s, "surface_radius", NC_DOUBLE, s->nsurf, (void **)&s->surf_r, err);
        if (rc == RC_OK)
            rc = get_all(s, "surface_parameters", NC_DOUBLE, RC_OUT_SURF_NPARAM * s->nsurf, (void **)&s->surf_x, err);
        if (rc == RC_OK) rc = get_all(s, "surface_body", NC_INT, s->nsurf, (void **)&sbody, err);
        if (rc == RC_OK && !(s->surf_bidx = malloc(s->nsurf * sizeof *s->surf_bidx)))
            rc = RC_SET(err, RC_ENOMEM, "export: out of memory");
        for (size_t j = 0; rc == RC_OK && j < s->nsurf; j++) {
            s->surf_bidx[j] = -1;
            for (size_t b = 0; b < s->nbody; b++)
                if (sbody[j] == s->body_id[b]) s->surf_bidx[j] = (int)b;
        }
        free(sbody);
        /* segment surfaces (kind SEGMENTS) */
        s->nsegnode = dim_or_zero(s->ncid, "segment_node");
        s->nseg = has_var(s->ncid, "segment_corners") ? dim_or_zero(s->ncid, "segment") : 0;
        if (rc == RC_OK && s->nseg > 0) {
            rc = get_all(s, "surface_first_node", NC_INT, s->nsurf, (void **)&s->surf_node0, err);
            if (rc == RC_OK) rc = get_all(s, "surface_first_segment", NC_INT, s->nsurf, (void **)&s->surf_seg0, err);
            if (rc == RC_OK)
                rc = get_all(s, "segment_node_position", NC_DOUBLE, 3 * s->nsegnode, (void **)&s->seg_node, err);
            if (rc == RC_OK) rc = get_all(s, "segment_corners", NC_INT, 4 * s->nseg, (void **)&s->seg_corner, err);
        }
    }
    if (rc == RC_OK && s->nevent > 0) {
        rc = get_all(s, "event_time", NC_DOUBLE, s->nevent, (void **)&s->ev_t, err);
        if (rc == RC_OK) rc = get_all(s, "event_kind", NC_STRING, s->nevent, (void **)&s->ev_kind, err);
        if (rc == RC_OK) rc = get_all(s, "event_element", NC_STRING, s->nevent, (void **)&s->ev_elem, err);
    }
    return rc;
}

/* Plane patches: centred on the mean of the body positions over the run,
 * half-size 1.5 x the largest distance of a body from it, at least 4 x the
 * largest radius or half-size of the other surfaces (1 m when nothing
 * gives a size). */
static rc_status plane_extent(vtk_src *s, rc_error *err)
{
    double *pos = malloc((3 * s->nbody + 1) * sizeof *pos);
    if (!pos) RC_RAISE(err, RC_ENOMEM, "export: out of memory");
    double c[3] = {0, 0, 0}, lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    const size_t step = s->nrec > 200 ? s->nrec / 200 : 1;
    for (size_t k = 0; k < s->nrec; k += step) {
        rc_status rc = get_rec(s, "body_position", k, s->nbody, 3, pos, err);
        if (rc != RC_OK) {
            free(pos);
            return rc;
        }
        for (size_t b = 0; b < 3 * s->nbody; b++) {
            lo[b % 3] = fmin(lo[b % 3], pos[b]);
            hi[b % 3] = fmax(hi[b % 3], pos[b]);
        }
    }
    free(pos);
    double size = 0;
    for (int i = 0; i < 3; i++) {
        c[i] = isfinite(lo[i]) ? 0.5 * (lo[i] + hi[i]) : 0.0;
        size = fmax(size, isfinite(lo[i]) ? hi[i] - lo[i] : 0.0);
    }
    double feat = 0;
    for (size_t j = 0; j < s->nsurf; j++) {
        feat = fmax(feat, s->surf_r[j]);
        if (!strcmp(s->surf_kind[j], "BOX") || !strcmp(s->surf_kind[j], "CYLINDER"))
            for (int i = 0; i < 3; i++) feat = fmax(feat, s->surf_x[(size_t)RC_OUT_SURF_NPARAM * j + i]);
    }
    s->plane_half = fmax(0.75 * size, 4.0 * feat);
    if (!(s->plane_half > 0)) s->plane_half = 1.0;
    memcpy(s->plane_c, c, sizeof c);
    return RC_OK;
}

/* ---- Choosing the frames ------------------------------------------------- */

/* Mark in sel[k] the records to export (at_event: the records' at_event
 * values, NULL when the file has none); returns the number marked. With
 * dt > 0, among the records `cand` allows (NULL: all): the first at or after
 * each multiple of dt (within 1e-9 dt), then the last record. */
static size_t select_dt(const double *tt, size_t nrec, const char *cand, double dt, char *sel)
{
    size_t n = 0;
    double tnext = -INFINITY;
    for (size_t k = 0; k < nrec; k++) {
        const int last = k + 1 == nrec;
        if (!last && cand && !cand[k]) continue;
        if (!last && tt[k] < tnext - 1e-9 * dt) continue;
        sel[k] = 1;
        n++;
        tnext = (floor(tt[k] / dt + 1e-9) + 1.0) * dt;
    }
    return n;
}

static size_t select_frames(const double *tt, const int *at_event, size_t nrec, const rc_vtk_options *o, char *sel,
                            double *dt_used)
{
    size_t n = 0;
    *dt_used = 0;
    memset(sel, 0, nrec);
    if (nrec == 0) return 0;
    if (o->every > 0) {
        for (size_t k = 0; k < nrec; k += (size_t)o->every) sel[k] = 1, n++;
        return n;
    }
    if (o->dt > 0) return select_dt(tt, nrec, NULL, o->dt, sel);
    /* the default: the records at the output times (the event records
     * left out), thinned to at most RC_VTK_DEFAULT_MAX_FRAMES, and the last */
    char *cand = sel; /* marked in place, then thinned on a copy if needed */
    for (size_t k = 0; k < nrec; k++)
        if (!at_event || at_event[k] == 0 || k + 1 == nrec) cand[k] = 1, n++;
    if (n <= RC_VTK_DEFAULT_MAX_FRAMES) return n;
    const double span = tt[nrec - 1] - tt[0];
    if (!(span > 0) || !isfinite(span)) return n;
    double dt = 0;
    for (double dec = pow(10.0, floor(log10(span / RC_VTK_DEFAULT_MAX_FRAMES))) / 10.0; dt == 0; dec *= 10.0)
        for (int m = 0; m < 3 && dt == 0; m++) {
            const double d = dec * (m == 0 ? 1.0 : m == 1 ? 2.0 : 5.0);
            /* grid frames floor(span / d) + 1, and the last */
            if (floor(span / d + 1e-9) + 2 <= RC_VTK_DEFAULT_MAX_FRAMES) dt = d;
        }
    char *c2 = malloc(nrec);
    if (!c2) return (size_t)-1;
    memcpy(c2, cand, nrec);
    memset(sel, 0, nrec);
    n = select_dt(tt, nrec, c2, dt, sel);
    free(c2);
    *dt_used = dt;
    return n;
}

/* ---- The export ------------------------------------------------------------------ */

rc_status rc_export_vtk(const char *results_path, const char *dir, int *nframes, rc_error *err)
{
    const rc_vtk_options o = {.every = 1};
    rc_vtk_result r;
    const rc_status rc = rc_export_vtk_opts(results_path, dir, &o, &r, err);
    if (nframes) *nframes = r.frames;
    return rc;
}

rc_status rc_export_vtk_dt(const char *results_path, const char *dir, double dt, int *nframes, rc_error *err)
{
    if (nframes) *nframes = 0;
    if (!(dt >= 0) || !isfinite(dt))
        RC_RAISE(err, RC_EINPUT, "rc_export_vtk_dt: frame interval %g s; expected a finite number >= 0 (0: every record)",
                 dt);
    const rc_vtk_options o = {.dt = dt, .every = dt > 0 ? 0 : 1};
    rc_vtk_result r;
    const rc_status rc = rc_export_vtk_opts(results_path, dir, &o, &r, err);
    if (nframes) *nframes = r.frames;
    return rc;
}

rc_status rc_export_vtk_opts(const char *results_path, const char *dir, const rc_vtk_options *opt,
                             rc_vtk_result *result, rc_error *err)
{
    rc_vtk_result res_local;
    rc_vtk_result *res = result ? result : &res_local;
    memset(res, 0, sizeof *res);
    const rc_vtk_options o = opt ? *opt : (rc_vtk_options){0};
    if (!results_path)
        RC_RAISE(err, RC_EINPUT, "rc_export_vtk_opts: the results path is NULL; expected a results file");
    if (!dir) RC_RAISE(err, RC_EINPUT, "rc_export_vtk_opts: the directory is NULL; expected where to write");
    if (!(o.dt >= 0) || !isfinite(o.dt))
        RC_RAISE(err, RC_EINPUT, "rc_export_vtk_opts: frame interval dt %g s; expected a finite number >= 0 (0: not used)",
                 o.dt);
    if (o.every < 0)
        RC_RAISE(err, RC_EINPUT, "rc_export_vtk_opts: every %d; expected a number of records >= 1 (0: not used)",
                 o.every);
    if (o.every > 0 && o.dt > 0)
        RC_RAISE(err, RC_EINPUT, "rc_export_vtk_opts: both dt (%g s) and every (%d) given; expected one of them",
                 o.dt, o.every);
    /* the results file is opened first: a failed export leaves no directory behind */
    vtk_src s;
    rc_nc_lock(); /* every netCDF call under the library's lock (output.h) */
    rc_status rc = src_open(&s, results_path, err);
    rc_nc_unlock();
    if (rc == RC_OK && mkdir(dir, 0777) != 0 && errno != EEXIST)
        rc = RC_SET(err, RC_EIO, "%s: cannot create the directory: %s", dir, strerror(errno));
    rc_nc_lock();
    if (rc == RC_OK) rc = plane_extent(&s, err);
    /* the stem of the results file names the outputs */
    const char *base = strrchr(results_path, '/');
    base = base ? base + 1 : results_path;
    char stem[256];
    snprintf(stem, sizeof stem, "%s", base);
    char *dot = strrchr(stem, '.');
    if (dot && dot != stem) *dot = '\0';

    const size_t nb = s.nbody, ni = s.ninter;
    double *pos = malloc((3 * nb + 1) * sizeof *pos), *quat = malloc((4 * nb + 1) * sizeof *quat);
    double *vel = malloc((3 * nb + 1) * sizeof *vel), *tt = malloc((s.nrec + 1) * sizeof *tt);
    const int has_at = s.ncid >= 0 && has_var(s.ncid, "at_event");
    int *at_ev = has_at ? malloc((s.nrec + 1) * sizeof *at_ev) : NULL;
    char *sel = malloc(s.nrec + 1);
    contacts c = {malloc((3 * ni + 1) * sizeof(double)), malloc((3 * ni + 1) * sizeof(double)),
                  malloc((ni + 1) * sizeof(double)),     malloc((ni + 1) * sizeof(double)),
                  malloc((3 * ni + 1) * sizeof(double)), malloc((3 * ni + 1) * sizeof(double)),
                  malloc((ni + 1) * sizeof(int)),        malloc((2 * ni + 1) * sizeof(int))};
    mesh m;
    memset(&m, 0, sizeof m);
    if (rc == RC_OK && (!pos || !quat || !vel || !tt || !sel || (has_at && !at_ev) ||
                        !c.point || !c.normal || !c.pen || !c.fn || !c.ffric || !c.fvec || !c.mode || !c.seq))
        rc = RC_SET(err, RC_ENOMEM, "export: out of memory");
    int vtime, vat;
    if (rc == RC_OK && nc_inq_varid(s.ncid, "time", &vtime) == NC_NOERR && s.nrec > 0 &&
        nc_get_var_double(s.ncid, vtime, tt) != NC_NOERR)
        rc = RC_SET(err, RC_EIO, "%s: reading time", results_path);
    if (rc == RC_OK && at_ev && s.nrec > 0 &&
        (nc_inq_varid(s.ncid, "at_event", &vat) != NC_NOERR || nc_get_var_int(s.ncid, vat, at_ev) != NC_NOERR))
        rc = RC_SET(err, RC_EIO, "%s: reading at_event", results_path);
    const int has_fric = s.ncid >= 0 && has_var(s.ncid, "inter_force_friction");
    rc_nc_unlock();
    if (rc == RC_OK && select_frames(tt, at_ev, s.nrec, &o, sel, &res->dt_used) == (size_t)-1)
        rc = RC_SET(err, RC_ENOMEM, "export: out of memory");
    const size_t plen = strlen(dir) + strlen(stem) + 64;
    char *path = malloc(plen);
    FILE *pvd = NULL;
    if (rc == RC_OK && !path) rc = RC_SET(err, RC_ENOMEM, "export: out of memory");
    if (rc == RC_OK) {
        snprintf(path, plen, "%s/%s.pvd", dir, stem);
        if (!(pvd = fopen(path, "w"))) rc = RC_SET(err, RC_EIO, "%s: cannot create: %s", path, strerror(errno));
        else
            fprintf(pvd, "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" "
                         "byte_order=\"LittleEndian\">\n<Collection>\n");
    }
    for (size_t i = 0; i < ni && c.seq; i++) {
        c.seq[i] = (int)i;          /* connectivity: one vertex per point */
        c.seq[ni + i] = (int)i + 1; /* offsets */
    }
    size_t ev = 0;
    for (size_t k = 0; rc == RC_OK && k < s.nrec; k++) {
        if (!sel[k]) continue;
        rc_nc_lock();
        rc = get_rec(&s, "body_position", k, nb, 3, pos, err);
        if (rc == RC_OK) rc = get_rec(&s, "body_quaternion", k, nb, 4, quat, err);
        if (rc == RC_OK) rc = get_rec(&s, "body_velocity", k, nb, 3, vel, err);
        rc_nc_unlock();
        if (rc != RC_OK) break;
        m.np = m.nconn = m.npoly = 0;
        static const double ident[4] = {1, 0, 0, 0}, zero[3] = {0, 0, 0};
        for (size_t j = 0; rc == RC_OK && j < s.nsurf; j++) {
            const int b = s.surf_bidx[j];
            if (tessellate(&m, &s, j, b >= 0 ? pos + 3 * b : zero, b >= 0 ? quat + 4 * b : ident,
                           b >= 0 ? vel + 3 * b : zero) != 0)
                rc = RC_SET(err, RC_ENOMEM, "export: out of memory");
        }
        snprintf(path, plen, "%s/%s_bodies_%06zu.vtp", dir, stem, k);
        if (rc == RC_OK) rc = write_bodies(path, &m, tt[k], o.ascii, &res->bytes, err);
        if (rc != RC_OK) break;
        if (ni > 0) {
            rc_nc_lock();
            rc = get_rec(&s, "inter_contact_point", k, ni, 3, c.point, err);
            if (rc == RC_OK) rc = get_rec(&s, "inter_normal", k, ni, 3, c.normal, err);
            if (rc == RC_OK) rc = get_rec(&s, "inter_penetration", k, ni, 1, c.pen, err);
            if (rc == RC_OK) rc = get_rec(&s, "inter_force_normal", k, ni, 1, c.fn, err);
            if (rc == RC_OK) rc = get_rec_int(&s, "inter_mode", k, ni, c.mode, err);
            if (rc == RC_OK && has_fric) rc = get_rec(&s, "inter_force_friction", k, ni, 3, c.ffric, err);
            else if (rc == RC_OK) memset(c.ffric, 0, 3 * ni * sizeof(double));
            rc_nc_unlock();
            if (rc != RC_OK) break;
            for (size_t i = 0; i < 3 * ni; i++) c.fvec[i] = -c.fn[i / 3] * c.normal[i]; /* on the first body */
        }
        /* the events since the previous frame (all of them up to the first) */
        const size_t e0 = ev;
        while (ev < s.nevent && s.ev_t[ev] <= tt[k]) ev++;
        snprintf(path, plen, "%s/%s_contacts_%06zu.vtp", dir, stem, k);
        rc = write_contacts(path, &s, &c, tt[k], e0, ev, o.ascii, &res->bytes, err);
        if (rc != RC_OK) break;
        fprintf(pvd, "<DataSet timestep=\"%.17g\" group=\"\" part=\"0\" file=\"%s_bodies_%06zu.vtp\"/>\n", tt[k], stem,
                k);
        fprintf(pvd, "<DataSet timestep=\"%.17g\" group=\"\" part=\"1\" file=\"%s_contacts_%06zu.vtp\"/>\n", tt[k],
                stem, k);
        res->frames++;
    }
    if (pvd) {
        fprintf(pvd, "</Collection>\n</VTKFile>\n");
        snprintf(path, plen, "%s/%s.pvd", dir, stem);
        rc_error e2;
        rc_status rc2 = close_file(pvd, path, &res->bytes, rc == RC_OK ? err : &e2);
        if (rc == RC_OK) rc = rc2;
    }
    free(path);
    free(pos);
    free(quat);
    free(vel);
    free(tt);
    free(at_ev);
    free(sel);
    void *cp[] = {c.point, c.normal, c.pen, c.fn, c.ffric, c.fvec, c.mode, c.seq, m.pt, m.body, m.surf, m.vel,
                  m.conn, m.off, m.csurf};
    for (size_t k = 0; k < sizeof cp / sizeof cp[0]; k++) free(cp[k]);
    rc_nc_lock();
    src_free(&s);
    rc_nc_unlock();
    return rc;
}
