/* Tiny test framework: each test is a function registered in main.c; a
   CHECK failure prints where and why and fails the test.  Statistical
   tests compare with tolerances made from measured block-average errors. */
#ifndef HCBD_TEST_H
#define HCBD_TEST_H
#include "../hcbd.h"
#include "scenes.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

extern int t_fail;
extern int t_quick; /* 1 under sanitizers: shorter statistical runs */
/* Length of the long statistical runs: 1 in make validate (--long, the
   paper-length validations), T_LEN_TEST in make test.  Tolerances come
   from the block errors of the run, so a shorter run is a valid test
   with wider errors; the exact identities do not depend on it. */
#define T_LEN_TEST 0.4
extern double t_len;

#define CHECK(cond, ...)                                                       \
    do {                                                                       \
        if (!(cond)) {                                                         \
            printf("    FAIL %s:%d: %s: ", __FILE__, __LINE__, #cond);         \
            printf(__VA_ARGS__);                                               \
            printf("\n");                                                      \
            t_fail = 1;                                                        \
        }                                                                      \
    } while (0)
#define NOTE(...) do { printf("    "); printf(__VA_ARGS__); printf("\n"); } while (0)

/* Squared minimum-image distance of particles i and j of an interleaved
   position array, written independently of the library. */
static inline double pair_r2(const double *xyz, int i, int j, const double L[3])
{
    double r2 = 0;
    int c;
    for (c = 0; c < 3; ++c) {
        double dx = xyz[3 * i + c] - xyz[3 * j + c];
        dx -= L[c] * round(dx / L[c]);
        r2 += dx * dx;
    }
    return r2;
}

/* A world from the default 2014/2016 scene with the given changes. */
static inline hcbd_world_def scene(int N, double density)
{
    hcbd_world_def d = hcbd_world_def_default();
    double L = cbrt(N / density);
    d.capacity = N;
    d.params.L[0] = d.params.L[1] = d.params.L[2] = L;
    d.params.density = density;
    return d;
}

static inline int make_world(hcbd_world *w, const hcbd_world_def *d)
{
    if (hcbd_world_create(w, d) != HCBD_OK) {
        printf("    world: %s\n", w->err.msg);
        t_fail = 1;
        return 0;
    }
    return 1;
}

static inline int run(hcbd_world *w, int steps)
{
    if (hcbd_world_step(w, steps) != HCBD_OK) {
        printf("    step: %s\n", w->err.msg);
        t_fail = 1;
        return 0;
    }
    return 1;
}

#if HCBD_MODEL == HCBD_MODEL_HCBD
static inline int hc_create(hcbd_hc_world *w, const hcbd_hc_world_def *d)
{
    if (hcbd_hc_world_create(w, d) != HCBD_OK) {
        printf("    world: %s\n", w->err.msg);
        t_fail = 1;
        return 0;
    }
    return 1;
}

static inline int hc_run(hcbd_hc_world *w, int steps)
{
    if (hcbd_hc_world_step(w, steps) != HCBD_OK) {
        printf("    step: %s\n", w->err.msg);
        t_fail = 1;
        return 0;
    }
    return 1;
}
#endif
#endif
