/* bench_common.h: what every bench program shares, included first: the
   POSIX clock and mkdir under -std=c99, a monotonic clock, and the output
   folder with a CSV file in it. */
#ifndef BENCH_COMMON_H
#define BENCH_COMMON_H
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include "../hcbd.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

static inline double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* Makes out/ and dir, opens dir/name for writing and keeps its path in
   path[size]; on failure says so on stderr (as prog) and returns NULL. */
static inline FILE *bench_csv(const char *prog, const char *dir, const char *name, char *path,
                              size_t size)
{
    FILE *f;
    mkdir("out", 0755);
    mkdir(dir, 0755);
    snprintf(path, size, "%s/%s", dir, name);
    f = fopen(path, "w");
    if (!f) fprintf(stderr, "%s: cannot write %s\n", prog, path);
    return f;
}
#endif
