/* Tiny test framework: each test is a function registered in main.c; a
   CHECK failure prints where and why and fails the test.  Statistical
   tests compare with tolerances made from measured block-average errors. */
#ifndef HCBD_TEST_H
#define HCBD_TEST_H
#include "../hcbd.h"
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

/* Mean and standard error from nb block averages of x[0..n). */
static inline void block_stats(const double *x, int n, int nb, double *mean, double *err)
{
    double m = 0, s2 = 0;
    int b, k, len = n / nb;
    for (b = 0; b < nb; ++b) {
        double a = 0;
        for (k = 0; k < len; ++k) a += x[b * len + k];
        a /= len;
        m += a;
        s2 += a * a;
    }
    m /= nb;
    *mean = m;
    *err = sqrt((s2 / nb - m * m) / (nb - 1));
}

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

/* A reduced HCBD scene: m = 1, kT = 1, nbar = 3/(4 pi) (lattice spacing
   a = 1.612), h = 2, nu = 1, c_s = 5 (c_s h / nu = 10), dt = 0.02; the box
   holds nx x ny x nz lattice sites exactly. */
static inline hcbd_hc_world_def hc_scene(int nx, int ny, int nz, int npoly)
{
    hcbd_hc_world_def d = hcbd_hc_world_def_default();
    hcbd_hc_params *p = &d.params;
    const double a = 1.6119919540164696; /* (4 pi / 3)^(1/3) */
    p->L[0] = nx * a;
    p->L[1] = ny * a;
    p->L[2] = nz * a;
    p->dt = 0.02;
    p->kT = 1.0;
    p->nbar = 3.0 / (4.0 * 3.14159265358979323846);
    p->rho = p->nbar;
    p->eta = p->rho;            /* nu = 1 */
    p->P0 = 25.0 * p->rho / 7.0; /* c_s = 5 */
    p->h = 2.0;
    p->fluctuations = 1;
    p->xi = 10.0;
    p->sigma = 1.0;
    p->rc = 2.5;
    p->alpha = 50.0;
    p->tau_lambda = 0.5;
    p->p_kuhn = 100.0;
    p->n_max = 5.0;
    p->chi = 0.5;
    p->seed = 7;
    d.fluid_capacity = nx * ny * nz;
    d.polymer_capacity = npoly;
    return d;
}
#endif
#endif
