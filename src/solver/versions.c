/*
 * Library versions for `ricochet --version` (rc_print_versions; the
 * build's commit is base/commit.c's rc_build_commit). SUNDIALS and KLU are
 * named by cvode.c, their only user; GSL by its version macro and the
 * library's gsl_version; netCDF by the output stage (its netCDF lock).
 */
#include <gsl/gsl_version.h>
#include <stdio.h>
#include <string.h>

#include "output/output.h"
#include "solver/solver.h"

void rc_print_versions(FILE *f)
{
    if (!f) return;
    rc_cvode_versions(f);
    fprintf(f, "GSL %s (headers %s)\n", gsl_version, GSL_VERSION);
    const char *nv = rc_output_netcdf_version(); /* "4.9.0 of <build date> $" */
    fprintf(f, "netCDF %.*s\n", (int)strcspn(nv, " "), nv);
}
