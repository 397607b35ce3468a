/* Test runner: runs every registered test (or those whose name contains
   one of the arguments); --quick (sanitizer builds) shortens the
   statistical runs and skips their asserts, --long runs them at full
   length (make validate); the last line is "N passed, N failed" and the
   total time comes before it. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, mkdir under -std=c99 */
#include "test.h"
#include <time.h>

int t_fail;
int t_quick;
double t_len = T_LEN_TEST;

#define T(name) void name(void);
#include "list.h"
#undef T

static const struct { const char *name; void (*fn)(void); } tests[] = {
#define T(name) {#name, name},
#include "list.h"
#undef T
};

/* HCBD_TEST_SKIP: comma-separated name parts of tests to leave out */
static int skipped(const char *name)
{
    const char *s = getenv("HCBD_TEST_SKIP");
    char part[64];
    while (s && *s) {
        size_t n = strcspn(s, ",");
        if (n > 0 && n < sizeof part) {
            memcpy(part, s, n);
            part[n] = 0;
            if (strstr(name, part)) return 1;
        }
        s += n + (s[n] == ',');
    }
    return 0;
}

int main(int argc, char **argv)
{
    int k, passed = 0, failed = 0;
    struct timespec start, end;
    int nfilter = 0;
    for (k = 1; k < argc; ++k) {
        if (!strcmp(argv[k], "--quick")) t_quick = 1;
        else if (!strcmp(argv[k], "--long")) t_len = 1.0;
        else ++nfilter;
    }
    if (getenv("HCBD_TEST_QUICK")) t_quick = 1;
    clock_gettime(CLOCK_MONOTONIC, &start);
    for (k = 0; k < (int)(sizeof tests / sizeof tests[0]); ++k) {
        struct timespec a, b;
        /* mutation runs leave out the golden hashes, which catch any
           change of bits: they ask the physics tests */
        if (skipped(tests[k].name)) continue;
        if (nfilter) {
            int a, hit = 0;
            for (a = 1; a < argc; ++a)
                hit |= strcmp(argv[a], "--quick") && strcmp(argv[a], "--long") && strstr(tests[k].name, argv[a]);
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
        if (t_fail && getenv("HCBD_TEST_STOP")) break; /* mutation runs: the first catch is enough */
    }
    clock_gettime(CLOCK_MONOTONIC, &end);
    printf("total %.1f s%s\n", (end.tv_sec - start.tv_sec) + 1e-9 * (end.tv_nsec - start.tv_nsec),
           t_len < 1 ? " (statistical runs at make-test length; --long for make validate)" : "");
    printf("%d passed, %d failed\n", passed, failed);
    return failed ? 1 : 0;
}
