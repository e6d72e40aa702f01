/* ParaView export (src/output/vtk.c): the frames chosen by the options, the
 * layout of the appended raw binary data (UInt64 block headers, offsets that
 * chain, little-endian values), binary values equal to the ASCII ones, and
 * the options refused. */
#include "harness.h"
#include "output/output.h"
#include "ricochet/ricochet.h"
#include "testutil.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* The demo cut to 0.2 s at Dt_out 0.01 s (21 output times and the event
 * records of the first impact); its path in *nc, its records in *nrec (and
 * the every-record export in <nc>_all). */
static int demo_results(char *nc, size_t n, int *nrec)
{
    snprintf(nc, n, "/tmp/rc_test_vtk_%ld.nc", (long)getpid());
    rc_model *m = TU_LOAD_OK("cases/demo_sphere_drop.rad");
    if (!m) return -1;
    rc_run_options o = {.output_path = nc, .t_end_override = 0.2, .dt_out_override = 0.01};
    rc_error e;
    const rc_status st = rc_run(m, &o, NULL, &e);
    rc_model_free(m);
    ENSURE(st == RC_OK);
    if (st != RC_OK) return -1;
    /* count the records: the time steps of an every-record export */
    rc_vtk_result r;
    char dir[160];
    snprintf(dir, sizeof dir, "%s_all", nc);
    ENSURE(rc_export_vtk_opts(nc, dir, &(rc_vtk_options){.every = 1}, &r, &e) == RC_OK);
    *nrec = r.frames;
    return 0;
}

/* The whole file in memory (NUL-terminated); *len its size. */
static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    const long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *b = malloc((size_t)n + 1);
    if (b && fread(b, 1, (size_t)n, f) != (size_t)n) {
        free(b);
        b = NULL;
    }
    if (b) b[n] = '\0';
    fclose(f);
    *len = (size_t)n;
    return b;
}

static uint64_t le64(const unsigned char *p)
{
    uint64_t v = 0;
    for (int k = 7; k >= 0; k--) v = v << 8 | p[k];
    return v;
}

static double le_double(const unsigned char *p)
{
    const uint64_t u = le64(p);
    double d;
    memcpy(&d, &u, sizeof d);
    return d;
}

/* Check the appended data of a binary file: every DataArray/Array has an
 * offset; the blocks, each a UInt64 byte count and the bytes, follow the
 * "_" one after the other in the order of the offsets, their counts equal
 * to tuples x components x size (strings: their bytes), and the file ends
 * after the last. Returns the number of blocks (-1 when wrong); the
 * Points' values in pts (up to maxp) and their count in *np. */
static int check_appended(const char *path, double *pts, size_t maxp, size_t *np)
{
    size_t len = 0;
    char *b = slurp(path, &len);
    ENSURE(b != NULL);
    if (!b) return -1;
    int bad = 0, nblk = 0;
    ENSURE(strstr(b, "byte_order=\"LittleEndian\" header_type=\"UInt64\"") != NULL);
    char *app = strstr(b, "<AppendedData encoding=\"raw\">\n_");
    ENSURE(app != NULL);
    if (!app) {
        free(b);
        return -1;
    }
    const unsigned char *data = (const unsigned char *)strchr(app, '_') + 1;
    *np = 0;
    uint64_t expect_off = 0;
    for (char *a = b; (a = strstr(a, " Name=\"")) && a < app; a++) {
        char *el = a;
        while (el > b && *el != '<') el--;
        const char *type = strstr(el, "type=\"") + 6, *off = strstr(el, "offset=\"");
        const char *tup = strstr(el, "NumberOfTuples=\""), *comp = strstr(el, "NumberOfComponents=\"");
        char *end = strchr(el, '>');
        if (!off || off > end || !tup) {
            bad++;
            continue;
        }
        const uint64_t o = strtoull(off + 8, NULL, 10);
        const size_t nt = strtoull(tup + 16, NULL, 10), nc = comp && comp < end ? strtoull(comp + 20, NULL, 10) : 1;
        const size_t sz = !strncmp(type, "Float64", 7) ? 8 : !strncmp(type, "Int32", 5) ? 4 : 0;
        bad += o != expect_off;
        if ((const char *)data + o + 8 > b + len) {
            bad++;
            break;
        }
        const uint64_t nbytes = le64(data + o);
        if (sz) bad += nbytes != nt * nc * sz;
        else { /* strings: nt of them, each ended by a 0 */
            size_t zeros = 0;
            for (uint64_t k = 0; k < nbytes && (const char *)data + o + 8 + k < b + len; k++) zeros += data[o + 8 + k] == 0;
            bad += zeros != nt;
        }
        if (!strncmp(a, " Name=\"Points\"", 14))
            for (size_t k = 0; k < nt * nc && k < maxp; k++) pts[(*np)++] = le_double(data + o + 8 + 8 * k);
        expect_off = o + 8 + nbytes;
        nblk++;
    }
    ENSURE(!strcmp((const char *)data + expect_off, "\n</AppendedData>\n</VTKFile>\n"));
    ENSURE(bad == 0);
    free(b);
    return bad ? -1 : nblk;
}

/* The Points of an ASCII file, in pts (up to maxp); their count. */
static size_t ascii_points(const char *path, double *pts, size_t maxp)
{
    size_t len = 0, n = 0;
    char *b = slurp(path, &len);
    ENSURE(b != NULL);
    if (!b) return 0;
    char *p = strstr(b, "Name=\"Points\"");
    ENSURE(p != NULL && strstr(p, "format=\"ascii\">") != NULL);
    if (p && (p = strchr(p, '>'))) {
        p++;
        char *end;
        for (double v; n < maxp && (v = strtod(p, &end), end != p); p = end) pts[n++] = v;
    }
    free(b);
    return n;
}

static void test_vtk_frames_binary_layout_ascii_equal(void)
{
    char nc[128], dir[192], f[256];
    int nrec = 0;
    if (demo_results(nc, sizeof nc, &nrec) != 0) return;
    ENSURE(nrec > 21); /* the output times and the event records */
    rc_error e;
    rc_vtk_result r;
    /* the default: the 21 output times (the last record among them) */
    snprintf(dir, sizeof dir, "%s_def", nc);
    ENSURE(rc_export_vtk_opts(nc, dir, NULL, &r, &e) == RC_OK);
    ENSURE(r.frames == 21 && r.dt_used == 0 && r.bytes > 0);
    /* every 4th record: ceil(nrec / 4) */
    snprintf(dir, sizeof dir, "%s_ev4", nc);
    ENSURE(rc_export_vtk_opts(nc, dir, &(rc_vtk_options){.every = 4}, &r, &e) == RC_OK);
    ENSURE(r.frames == (nrec + 3) / 4);
    /* --dt 0.05: 0, 0.05, ..., 0.2 */
    int n = 0;
    snprintf(dir, sizeof dir, "%s_dt", nc);
    ENSURE(rc_export_vtk_dt(nc, dir, 0.05, &n, &e) == RC_OK && n == 5);
    /* the old entry point: every record */
    snprintf(dir, sizeof dir, "%s_old", nc);
    ENSURE(rc_export_vtk(nc, dir, &n, &e) == RC_OK && n == nrec);

    /* binary layout, and the values equal to the ASCII export's */
    const char *stem = strrchr(nc, '/') + 1;
    char stemb[64];
    snprintf(stemb, sizeof stemb, "%.*s", (int)(strlen(stem) - 3), stem);
    snprintf(dir, sizeof dir, "%s_asc", nc);
    ENSURE(rc_export_vtk_opts(nc, dir, &(rc_vtk_options){.every = 1, .ascii = 1}, &r, &e) == RC_OK);
    static double pb[4096], pa[4096];
    for (int k = 0; k < nrec; k += nrec / 5) {
        size_t nb = 0;
        snprintf(f, sizeof f, "%s_all/%s_bodies_%06d.vtp", nc, stemb, k);
        ENSURE(check_appended(f, pb, 4096, &nb) == 8);
        snprintf(f, sizeof f, "%s_asc/%s_bodies_%06d.vtp", nc, stemb, k);
        const size_t na = ascii_points(f, pa, 4096);
        ENSURE(na == nb && na == 3 * 270 && !memcmp(pa, pb, na * sizeof *pa));
        snprintf(f, sizeof f, "%s_all/%s_contacts_%06d.vtp", nc, stemb, k);
        ENSURE(check_appended(f, pb, 4096, &nb) >= 11 && nb == 3);
    }
    /* the first record's contacts file holds the events up to it (none), a
     * later one the string arrays of its events */
    int with_events = 0;
    for (int k = 0; k < nrec; k++) {
        size_t len, nb;
        snprintf(f, sizeof f, "%s_all/%s_contacts_%06d.vtp", nc, stemb, k);
        char *b = slurp(f, &len);
        if (b && strstr(b, "Name=\"event_kind\"")) {
            with_events++;
            ENSURE(check_appended(f, pb, 4096, &nb) == 15);
        }
        free(b);
    }
    ENSURE(with_events > 0);

    /* a big-endian host's files: every block byte-swapped to little-endian */
    rc_vtk_test_force_swap(1);
    snprintf(dir, sizeof dir, "%s_swap", nc);
    ENSURE(rc_export_vtk_opts(nc, dir, &(rc_vtk_options){.every = 1}, &r, &e) == RC_OK);
    rc_vtk_test_force_swap(0);
    {
        size_t l1, l2;
        snprintf(f, sizeof f, "%s_all/%s_bodies_%06d.vtp", nc, stemb, nrec - 1);
        char *b1 = slurp(f, &l1);
        snprintf(f, sizeof f, "%s_swap/%s_bodies_%06d.vtp", nc, stemb, nrec - 1);
        char *b2 = slurp(f, &l2);
        ENSURE(b1 && b2 && l1 == l2);
        if (b1 && b2 && l1 == l2) {
            const unsigned char *d1 = (unsigned char *)strstr(b1, "\n_") + 2, *d2 = (unsigned char *)strstr(b2, "\n_") + 2;
            int swapped = 1;
            for (int k = 0; k < 8; k++) swapped &= d1[k] == d2[7 - k] && d1[8 + k] == d2[15 - k]; /* header, TimeValue */
            ENSURE(swapped && le64(d1) == 8);
        }
        free(b1);
        free(b2);
    }

    /* options refused, nothing written */
    snprintf(dir, sizeof dir, "%s_bad", nc);
    ENSURE(rc_export_vtk_opts(nc, dir, &(rc_vtk_options){.every = 2, .dt = 0.1}, &r, &e) == RC_EINPUT &&
           strstr(e.msg, "expected one of them") && r.frames == 0);
    ENSURE(rc_export_vtk_opts(nc, dir, &(rc_vtk_options){.every = -1}, NULL, &e) == RC_EINPUT);
    ENSURE(rc_export_vtk_opts(nc, dir, &(rc_vtk_options){.dt = -1}, NULL, &e) == RC_EINPUT);
    ENSURE(rc_export_vtk_opts(nc, dir, &(rc_vtk_options){.dt = NAN}, NULL, NULL) == RC_EINPUT);
    ENSURE(rc_export_vtk_opts(NULL, dir, NULL, NULL, &e) == RC_EINPUT && strstr(e.msg, "results path is NULL"));
    ENSURE(rc_export_vtk_opts(nc, NULL, NULL, NULL, &e) == RC_EINPUT && strstr(e.msg, "directory is NULL"));
    ENSURE(access(dir, F_OK) != 0);

    char cmd[1400];
    snprintf(cmd, sizeof cmd, "rm -rf '%s' '%s'_all '%s'_def '%s'_ev4 '%s'_dt '%s'_old '%s'_asc '%s'_swap", nc, nc, nc, nc,
             nc, nc, nc, nc);
    ENSURE(system(cmd) == 0);
}

void suite_vtk(void);
void suite_vtk(void)
{
    RUN_TEST(test_vtk_frames_binary_layout_ascii_equal);
}
