/* Test runner: runs every registered test (or those whose name contains
   one of the arguments); the last line is "N passed, N failed". */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, mkdir under -std=c99 */
#include "test.h"
#include <time.h>

int t_fail;
int t_quick;

#define T(name) void name(void);
#include "list.h"
#undef T

static const struct { const char *name; void (*fn)(void); } tests[] = {
#define T(name) {#name, name},
#include "list.h"
#undef T
};

int main(int argc, char **argv)
{
    int k, passed = 0, failed = 0;
    int nfilter = 0;
    for (k = 1; k < argc; ++k) {
        if (!strcmp(argv[k], "--quick")) t_quick = 1;
        else ++nfilter;
    }
    if (getenv("HCBD_TEST_QUICK")) t_quick = 1;
    for (k = 0; k < (int)(sizeof tests / sizeof tests[0]); ++k) {
        struct timespec a, b;
        if (nfilter) {
            int a, hit = 0;
            for (a = 1; a < argc; ++a) hit |= strcmp(argv[a], "--quick") && strstr(tests[k].name, argv[a]);
            if (!hit) continue;
        }
        printf("%s\n", tests[k].name);
        fflush(stdout);
        t_fail = 0;
        clock_gettime(CLOCK_MONOTONIC, &a);
        tests[k].fn();
        clock_gettime(CLOCK_MONOTONIC, &b);
        printf("  %s (%.1f s)\n", t_fail ? "FAILED" : "ok",
               (b.tv_sec - a.tv_sec) + 1e-9 * (b.tv_nsec - a.tv_nsec));
        if (t_fail) ++failed; else ++passed;
        fflush(stdout);
    }
    printf("%d passed, %d failed\n", passed, failed);
    return failed ? 1 : 0;
}
