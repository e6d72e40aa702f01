/*
 * SHA-256 (FIPS 180-4) of a byte buffer or a file, as 64 lowercase hex
 * digits. A compact implementation: none of the libraries ricochet links
 * (SUNDIALS, SuiteSparse, GSL, netCDF) exports one.
 */
#ifndef RC_SHA256_H
#define RC_SHA256_H

#include <stddef.h>

/* hex: 65 chars (64 digits and the terminating NUL). */
void rc_sha256_hex(const void *data, size_t n, char hex[65]);
/* The file's SHA-256; returns 0, or -1 (errno set) when it cannot be read. */
int rc_sha256_file(const char *path, char hex[65]);

#endif
