/* The optimised serial vector operations (src/solver/nvfast.h) against the
 * serial vector's own, bit for bit, on random vectors with the special
 * coefficients the serial vector treats separately and aliased arguments. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include "harness.h"
#include "solver/nvfast.h"

#define NV 37

static double urand(unsigned *s)
{
    *s = *s * 1103515245u + 12345u;
    return ((double)((*s >> 8) & 0xffffff) / 16777216.0 - 0.5) * 8.0;
}

static void fill(N_Vector v, unsigned *s)
{
    double *d = N_VGetArrayPointer(v);
    for (int i = 0; i < NV; i++) d[i] = urand(s);
}

static int same(N_Vector a, N_Vector b)
{
    return memcmp(N_VGetArrayPointer(a), N_VGetArrayPointer(b), NV * sizeof(double)) == 0;
}

static int same_real(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* a pair of vectors with the same values: stock ops (r) and fast ops (f) */
typedef struct pair {
    N_Vector r, f;
} pair;

static pair mk(SUNContext ctx, unsigned *s)
{
    pair p = {N_VNew_Serial(NV, ctx), N_VNew_Serial(NV, ctx)};
    rc_nvector_fast(p.f);
    fill(p.r, s);
    memcpy(N_VGetArrayPointer(p.f), N_VGetArrayPointer(p.r), NV * sizeof(double));
    return p;
}

static void del(pair p)
{
    N_VDestroy(p.r);
    N_VDestroy(p.f);
}

static void test_nvfast_bitwise_equal_to_serial(void)
{
    SUNContext ctx = NULL;
    ENSURE(SUNContext_Create(NULL, &ctx) == 0);
    unsigned s = 12345u;
    const double coef[] = {1.0, -1.0, 0.0, 2.5, -2.5, 0.3, 1.0 / 3.0};
    const int nc = (int)(sizeof coef / sizeof coef[0]);
    int bad = 0;
    for (int ia = 0; ia < nc; ia++)
        for (int ib = 0; ib < nc; ib++)
            for (int alias = 0; alias < 3; alias++) {
                pair x = mk(ctx, &s), y = mk(ctx, &s), z = mk(ctx, &s);
                const double a = coef[ia], b = coef[ib];
                /* alias 0: z separate; 1: z = x; 2: z = y */
                N_VLinearSum(a, x.r, b, y.r, alias == 1 ? x.r : alias == 2 ? y.r : z.r);
                N_VLinearSum(a, x.f, b, y.f, alias == 1 ? x.f : alias == 2 ? y.f : z.f);
                bad += !same(x.r, x.f) || !same(y.r, y.f) || !same(z.r, z.f);
                del(x);
                del(y);
                del(z);
            }
    ENSURE(bad == 0);
    pair x = mk(ctx, &s), y = mk(ctx, &s), w = mk(ctx, &s), z = mk(ctx, &s), id = mk(ctx, &s);
    /* positive weights, a mask with zeros, one zero in x for the tests */
    double *wr = N_VGetArrayPointer(w.r), *wf = N_VGetArrayPointer(w.f);
    for (int i = 0; i < NV; i++) wr[i] = wf[i] = fabs(wr[i]) + 0.1;
    N_VGetArrayPointer(x.r)[3] = N_VGetArrayPointer(x.f)[3] = 0.0;
    ENSURE(same_real(N_VWrmsNorm(x.r, w.r), N_VWrmsNorm(x.f, w.f)));
    ENSURE(same_real(N_VWrmsNormMask(x.r, w.r, id.r), N_VWrmsNormMask(x.f, w.f, id.f)));
    ENSURE(same_real(N_VMaxNorm(x.r), N_VMaxNorm(x.f)));
    ENSURE(same_real(N_VWSqrSumLocal(x.r, w.r), N_VWSqrSumLocal(x.f, w.f)));
    ENSURE(same_real(N_VWSqrSumMaskLocal(x.r, w.r, id.r), N_VWSqrSumMaskLocal(x.f, w.f, id.f)));
    N_VScale(0.7, x.r, z.r);
    N_VScale(0.7, x.f, z.f);
    ENSURE(same(z.r, z.f));
    N_VScale(-1.0, y.r, y.r);
    N_VScale(-1.0, y.f, y.f);
    ENSURE(same(y.r, y.f));
    N_VProd(x.r, y.r, z.r);
    N_VProd(x.f, y.f, z.f);
    ENSURE(same(z.r, z.f));
    N_VDiv(y.r, w.r, z.r);
    N_VDiv(y.f, w.f, z.f);
    ENSURE(same(z.r, z.f));
    N_VAbs(y.r, z.r);
    N_VAbs(y.f, z.f);
    ENSURE(same(z.r, z.f));
    N_VInv(w.r, z.r);
    N_VInv(w.f, z.f);
    ENSURE(same(z.r, z.f));
    N_VAddConst(y.r, 0.25, z.r);
    N_VAddConst(y.f, 0.25, z.f);
    ENSURE(same(z.r, z.f));
    N_VCompare(1.5, y.r, z.r);
    N_VCompare(1.5, y.f, z.f);
    ENSURE(same(z.r, z.f));
    N_VConst(3.5, z.r);
    N_VConst(3.5, z.f);
    ENSURE(same(z.r, z.f));
    /* fused operations: against the serial vector's own (which falls back
     * on linear sums when it has none) */
    for (int nvec = 1; nvec <= 4; nvec++)
        for (int alias = 0; alias < 2; alias++) {
            double c[4] = {1.0, -0.37, 2.0, -1.0};
            if (alias) c[0] = 0.9;
            N_Vector xr[4] = {alias ? z.r : x.r, y.r, w.r, id.r}, xf[4] = {alias ? z.f : x.f, y.f, w.f, id.f};
            N_VLinearCombination(nvec, c, xr, z.r);
            N_VLinearCombination(nvec, c, xf, z.f);
            ENSURE(same(z.r, z.f));
            N_Vector yr[3] = {y.r, w.r, id.r}, yf[3] = {y.f, w.f, id.f};
            pair o[3] = {mk(ctx, &s), mk(ctx, &s), mk(ctx, &s)};
            N_Vector zr[3] = {alias ? y.r : o[0].r, o[1].r, o[2].r}, zf[3] = {alias ? y.f : o[0].f, o[1].f, o[2].f};
            const int m = nvec < 3 ? nvec : 3;
            N_VScaleAddMulti(m, c, x.r, yr, zr);
            N_VScaleAddMulti(m, c, x.f, yf, zf);
            for (int j = 0; j < m; j++) ENSURE(same(zr[j], zf[j]));
            ENSURE(same(y.r, y.f));
            for (int j = 0; j < 3; j++) del(o[j]);
        }
    del(x);
    del(y);
    del(w);
    del(z);
    del(id);
    SUNContext_Free(&ctx);
}

void suite_nvfast(void);
void suite_nvfast(void)
{
    RUN_TEST(test_nvfast_bitwise_equal_to_serial);
}
