/* Status codes, their messages, and the error recorder. */
#include "base/error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

const char *rc_status_str(rc_status code)
{
    switch (code) {
    case RC_OK: return "success";
    case RC_EINPUT: return "input error";
    case RC_ESOLVER: return "solver failure";
    case RC_EIO: return "I/O error";
    case RC_ENOMEM: return "out of memory";
    case RC_EINTERNAL: return "internal error";
    case RC_EINTERRUPT: return "interrupted";
    case RC_EPHYSICS: return "physics check failed";
    }
    return "unknown status";
}

int rc_status_exit_code(rc_status code)
{
    switch (code) {
    case RC_OK: return 0;
    case RC_EINPUT: return 2;
    case RC_ESOLVER: return 3;
    case RC_EIO: return 4;
    case RC_EPHYSICS: return 5;
    case RC_EINTERRUPT: return 130;
    default: return 1;
    }
}

const char *rc_version(void) { return RICOCHET_VERSION; }

void rc_error_clear(rc_error *err)
{
    if (!err) return;
    memset(err, 0, sizeof *err);
}

rc_status rc_error_set(rc_error *err, rc_status code, const char *src_file, int src_line,
                       const char *src_func, const char *fmt, ...)
{
    if (!err) return code;
    err->code = code;
    err->src_file = src_file;
    err->src_line = src_line;
    err->src_func = src_func;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->msg, sizeof err->msg, fmt, ap);
    va_end(ap);
    return code;
}
