/* Status codes and the error recorder. */
#include "harness.h"
#include "base/error.h"

static rc_status raise_input(rc_error *e) { RC_RAISE(e, RC_EINPUT, "field %s: expected %d", "Iform", 0); }

static void test_error_raise_records_message(void)
{
    rc_error e;
    rc_error_clear(&e);
    ENSURE(raise_input(&e) == RC_EINPUT);
    ENSURE(e.code == RC_EINPUT);
    ENSURE(strcmp(e.msg, "field Iform: expected 0") == 0);
    ENSURE(e.src_line > 0);
    ENSURE(raise_input(NULL) == RC_EINPUT); /* NULL error is allowed */
}

static void test_error_exit_codes(void)
{
    ENSURE(rc_status_exit_code(RC_OK) == 0);
    ENSURE(rc_status_exit_code(RC_EINPUT) == 2);
    ENSURE(rc_status_exit_code(RC_ESOLVER) == 3);
    ENSURE(rc_status_exit_code(RC_EIO) == 4);
    ENSURE(rc_status_exit_code(RC_ENOMEM) == 1);
    ENSURE(strlen(rc_status_str(RC_ESOLVER)) > 0);
}

void suite_error(void);
void suite_error(void)
{
    RUN_TEST(test_error_raise_records_message);
    RUN_TEST(test_error_exit_codes);
}
