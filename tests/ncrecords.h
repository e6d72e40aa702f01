/* The records of a ricochet results file and its completion flag, as
 * another process reads them (shared by the contract tests and the
 * ThreadSanitizer program). */
#ifndef RC_TESTS_NCRECORDS_H
#define RC_TESTS_NCRECORDS_H

#include <netcdf.h>
#include <stddef.h>

/* The length of the time dimension (-1: the file does not open) and the
 * global attribute "complete" into complete[n] ("" when absent). */
static inline long tu_nc_records(const char *path, char *complete, size_t n)
{
    int nc, dim;
    size_t len = 0, alen = 0;
    complete[0] = '\0';
    if (nc_open(path, NC_NOWRITE, &nc) != NC_NOERR) return -1;
    if (nc_inq_dimid(nc, "time", &dim) != NC_NOERR || nc_inq_dimlen(nc, dim, &len) != NC_NOERR) len = 0;
    if (nc_inq_attlen(nc, NC_GLOBAL, "complete", &alen) == NC_NOERR && alen < n) {
        nc_get_att_text(nc, NC_GLOBAL, "complete", complete);
        complete[alen] = '\0';
    }
    nc_close(nc);
    return (long)len;
}

#endif
