/*
 * A tiny test harness. Each test file defines suites `void suite_<name>(void)`
 * that call RUN_TEST(fn); tests use ENSURE and ENSURE_NEAR. tests/main.c
 * lists the suites, applies the name filter (argv[1], a substring) and prints
 * the closing line "N passed, N failed".
 */
#ifndef RC_HARNESS_H
#define RC_HARNESS_H

#include <math.h>
#include <stdio.h>
#include <string.h>

extern int rc_test_failed_now; /* failures in the running test */
extern const char *rc_test_filter;
void rc_test_record(const char *name, int failed);

#define RUN_TEST(fn)                                                          \
    do {                                                                      \
        if (rc_test_filter && !strstr(#fn, rc_test_filter)) break;            \
        rc_test_failed_now = 0;                                               \
        fn();                                                                 \
        rc_test_record(#fn, rc_test_failed_now);                              \
    } while (0)

#define ENSURE(cond)                                                          \
    do {                                                                      \
        if (!(cond)) {                                                        \
            fprintf(stderr, "  %s:%d: ENSURE(%s) failed\n", __FILE__,         \
                    __LINE__, #cond);                                         \
            rc_test_failed_now++;                                             \
        }                                                                     \
    } while (0)

/* |a - b| <= atol + rtol * |b| ; NaN fails. */
#define ENSURE_NEAR(a, b, rtol, atol)                                         \
    do {                                                                      \
        double ea_ = (a), eb_ = (b);                                          \
        if (!(fabs(ea_ - eb_) <= (atol) + (rtol) * fabs(eb_))) {              \
            fprintf(stderr,                                                   \
                    "  %s:%d: ENSURE_NEAR(%s, %s) failed: %.17g vs %.17g "    \
                    "(diff %.3g)\n",                                          \
                    __FILE__, __LINE__, #a, #b, ea_, eb_, fabs(ea_ - eb_));   \
            rc_test_failed_now++;                                             \
        }                                                                     \
    } while (0)

#endif
