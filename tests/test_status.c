/* test_status.c — every status has its own sentence, and success is "ok". */
#include "capbridge.h"
#include "check.h"

#include <string.h>

int main(int argc, char **argv)
{
    (void)argc;
    const cb_status all[] = {CB_OK, CB_ERR_NULL, CB_ERR_NOT_FINITE, CB_ERR_NEGATIVE,
                             CB_ERR_RANGE, CB_ERR_UNKNOWN_LAW, CB_ERR_UNKNOWN_KEYWORD,
                             CB_ERR_OUT_OF_VALIDITY, CB_ERR_NO_BRIDGE, CB_ERR_NO_CONVERGENCE,
                             CB_ERR_NO_MEMORY, CB_ERR_LIQUID, CB_ERR_BRIDGE_STATE};
    const size_t n = sizeof all / sizeof all[0];
    CHECK(strcmp(cb_status_message(CB_OK), "ok") == 0);
    for (size_t i = 0; i < n; ++i) {
        const char *m = cb_status_message(all[i]);
        CHECK(m != NULL && strlen(m) > 1);
        for (size_t j = 0; j < i; ++j) CHECK(strcmp(m, cb_status_message(all[j])) != 0);
    }
    CHECK(strcmp(cb_status_message((cb_status)999), "unknown status") == 0);
    return check_report(argv[0]);
}
