/*
 * Build and library versions for `ricochet --version` (rc_build_commit,
 * rc_print_versions). The git commit is baked in by the Makefile
 * (-DRC_COMMIT, "unknown" outside a git checkout). SUNDIALS and KLU are
 * named by cvode.c, their only user; GSL by its version macro and the
 * library's gsl_version; netCDF by nc_inq_libvers(), the one netCDF call
 * outside src/output (it reads a string, it writes no file).
 */
#include <gsl/gsl_version.h>
#include <netcdf.h>
#include <stdio.h>
#include <string.h>

#include "solver/solver.h"

#ifndef RC_COMMIT
#define RC_COMMIT "unknown"
#endif

const char *rc_build_commit(void) { return RC_COMMIT; }

void rc_print_versions(FILE *f)
{
    rc_cvode_versions(f);
    fprintf(f, "GSL %s (headers %s)\n", gsl_version, GSL_VERSION);
    const char *nv = nc_inq_libvers(); /* "4.9.0 of <build date> $" */
    fprintf(f, "netCDF %.*s\n", (int)strcspn(nv, " "), nv);
}
