/*
 * Error raising. One macro records where an error was raised and returns
 * its code; nothing here prints, aborts or exits.
 */
#ifndef RC_ERROR_H
#define RC_ERROR_H

#include "ricochet/ricochet.h"

/* Fill *err (may be NULL) and return `code`. printf-style message. */
rc_status rc_error_set(rc_error *err, rc_status code, const char *src_file, int src_line,
                       const char *src_func, const char *fmt, ...)
    __attribute__((format(printf, 6, 7)));

/* Raise: record and return from the calling function. */
#define RC_RAISE(err, code, ...) \
    return rc_error_set((err), (code), __FILE__, __LINE__, __func__, __VA_ARGS__)

/* Record without returning (for `goto fail` cleanup paths). */
#define RC_SET(err, code, ...) rc_error_set((err), (code), __FILE__, __LINE__, __func__, __VA_ARGS__)

void rc_error_clear(rc_error *err);

#endif
