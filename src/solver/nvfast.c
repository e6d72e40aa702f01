/* Optimised serial vector operations (nvfast.h). Each computes the
 * expression of the serial vector's own operation, in the same order. */
#include "solver/nvfast.h"

#include <math.h>

#define LEN(v) ((sunindextype)NV_LENGTH_S(v))
#define DAT(v) (NV_DATA_S(v))

/* z = a x + b y; a = b and a = -b factor as the serial vector does */
static void linear_sum(realtype a, N_Vector x, realtype b, N_Vector y, N_Vector z)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DAT(x), *yd = DAT(y);
    realtype *zd = DAT(z);
    if (a == b) {
        for (sunindextype i = 0; i < n; i++) zd[i] = a * (xd[i] + yd[i]);
    } else if (a == -b) {
        for (sunindextype i = 0; i < n; i++) zd[i] = a * (xd[i] - yd[i]);
    } else {
        for (sunindextype i = 0; i < n; i++) zd[i] = a * xd[i] + b * yd[i];
    }
}

static void set_const(realtype c, N_Vector z)
{
    const sunindextype n = LEN(z);
    realtype *zd = DAT(z);
    for (sunindextype i = 0; i < n; i++) zd[i] = c;
}

static void prod(N_Vector x, N_Vector y, N_Vector z)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DAT(x), *yd = DAT(y);
    realtype *zd = DAT(z);
    for (sunindextype i = 0; i < n; i++) zd[i] = xd[i] * yd[i];
}

static void divide(N_Vector x, N_Vector y, N_Vector z)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DAT(x), *yd = DAT(y);
    realtype *zd = DAT(z);
    for (sunindextype i = 0; i < n; i++) zd[i] = xd[i] / yd[i];
}

static void scale(realtype c, N_Vector x, N_Vector z)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DAT(x);
    realtype *zd = DAT(z);
    for (sunindextype i = 0; i < n; i++) zd[i] = c * xd[i];
}

static void absolute(N_Vector x, N_Vector z)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DAT(x);
    realtype *zd = DAT(z);
    for (sunindextype i = 0; i < n; i++) zd[i] = fabs(xd[i]);
}

static void inverse(N_Vector x, N_Vector z)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DAT(x);
    realtype *zd = DAT(z);
    for (sunindextype i = 0; i < n; i++) zd[i] = 1.0 / xd[i];
}

static void add_const(N_Vector x, realtype b, N_Vector z)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DAT(x);
    realtype *zd = DAT(z);
    for (sunindextype i = 0; i < n; i++) zd[i] = xd[i] + b;
}

static realtype max_norm(N_Vector x)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DAT(x);
    realtype mx = 0.0;
    for (sunindextype i = 0; i < n; i++)
        if (fabs(xd[i]) > mx) mx = fabs(xd[i]);
    return mx;
}

static realtype wsqr_sum(N_Vector x, N_Vector w)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DAT(x), *wd = DAT(w);
    realtype s = 0.0;
    for (sunindextype i = 0; i < n; i++) {
        const realtype p = xd[i] * wd[i];
        s += p * p;
    }
    return s;
}

static realtype wrms_norm(N_Vector x, N_Vector w)
{
    return sqrt(wsqr_sum(x, w) / (realtype)LEN(x));
}

static realtype wsqr_sum_mask(N_Vector x, N_Vector w, N_Vector id)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DAT(x), *wd = DAT(w), *idd = DAT(id);
    realtype s = 0.0;
    for (sunindextype i = 0; i < n; i++) {
        if (idd[i] > 0.0) {
            const realtype p = xd[i] * wd[i];
            s += p * p;
        }
    }
    return s;
}

static realtype wrms_norm_mask(N_Vector x, N_Vector w, N_Vector id)
{
    return sqrt(wsqr_sum_mask(x, w, id) / (realtype)LEN(x));
}

static void compare(realtype c, N_Vector x, N_Vector z)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DAT(x);
    realtype *zd = DAT(z);
    for (sunindextype i = 0; i < n; i++) zd[i] = fabs(xd[i]) >= c ? 1.0 : 0.0;
}

/* z = sum_j c_j X_j, accumulated from j = 0 on (z may be X_0) */
static int linear_combination(int nvec, realtype *c, N_Vector *xv, N_Vector z)
{
    const sunindextype n = LEN(z);
    realtype *zd = DAT(z);
    if (nvec < 1) return -1;
    for (sunindextype i = 0; i < n; i++) {
        realtype s = c[0] * DAT(xv[0])[i];
        for (int j = 1; j < nvec; j++) s = s + c[j] * DAT(xv[j])[i];
        zd[i] = s;
    }
    return 0;
}

/* Z_j = a_j x + Y_j */
static int scale_add_multi(int nvec, realtype *a, N_Vector x, N_Vector *yv, N_Vector *zv)
{
    const sunindextype n = LEN(x);
    const realtype *xd = DAT(x);
    if (nvec < 1) return -1;
    for (int j = 0; j < nvec; j++) {
        const realtype *yd = DAT(yv[j]);
        realtype *zd = DAT(zv[j]);
        const realtype aj = a[j];
        for (sunindextype i = 0; i < n; i++) zd[i] = aj * xd[i] + yd[i];
    }
    return 0;
}

void rc_nvector_fast(N_Vector v)
{
    if (!v || !v->ops || N_VGetVectorID(v) != SUNDIALS_NVEC_SERIAL) return;
    N_Vector_Ops o = v->ops;
    o->nvlinearsum = linear_sum;
    o->nvconst = set_const;
    o->nvprod = prod;
    o->nvdiv = divide;
    o->nvscale = scale;
    o->nvabs = absolute;
    o->nvinv = inverse;
    o->nvaddconst = add_const;
    o->nvmaxnorm = max_norm;
    o->nvwrmsnorm = wrms_norm;
    o->nvwrmsnormmask = wrms_norm_mask;
    o->nvwsqrsumlocal = wsqr_sum;
    o->nvwsqrsummasklocal = wsqr_sum_mask;
    o->nvmaxnormlocal = max_norm;
    o->nvcompare = compare;
    o->nvlinearcombination = linear_combination;
    o->nvscaleaddmulti = scale_add_multi;
}
