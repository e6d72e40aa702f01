/* Test runner: runs every suite, optional name filter in argv[1]. */
#include "harness.h"

#include <stdlib.h>

int rc_test_failed_now;
const char *rc_test_filter;
static int n_pass, n_fail;

void rc_test_record(const char *name, int failed)
{
    if (failed) {
        n_fail++;
        printf("FAIL %s\n", name);
    } else {
        n_pass++;
        printf("ok   %s\n", name);
    }
    fflush(stdout);
}

#define SUITE(name) void suite_##name(void);
#include "suites.def"
#undef SUITE

int main(int argc, char **argv)
{
    if (argc > 1) rc_test_filter = argv[1];
#define SUITE(name) suite_##name();
#include "suites.def"
#undef SUITE
    printf("%d passed, %d failed\n", n_pass, n_fail);
    return n_fail ? 1 : 0;
}
