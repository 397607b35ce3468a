/* Random numbers: Gaussian moments from the ziggurat (per-particle
   xoshiro and counter-based pair streams), independence of neighbouring
   pair keys, the uniform variant.  Tolerances are 5 standard errors of
   the estimated moments. */
#include "test.h"

static void moments(const double *x, int n, const char *what)
{
    double m1 = 0, m2 = 0, m3 = 0, m4 = 0;
    int k;
    for (k = 0; k < n; ++k) {
        double v = x[k];
        m1 += v; m2 += v * v; m3 += v * v * v; m4 += v * v * v * v;
    }
    m1 /= n; m2 /= n; m3 /= n; m4 /= n;
    /* standard errors of the sample moments of N(0,1): sqrt(1, 2, 15, 96)/sqrt n */
    CHECK(fabs(m1) < 5 * sqrt(1.0 / n), "%s: mean %g", what, m1);
    CHECK(fabs(m2 - 1) < 5 * sqrt(2.0 / n), "%s: variance %g", what, m2);
    CHECK(fabs(m3) < 5 * sqrt(15.0 / n), "%s: third moment %g", what, m3);
    CHECK(fabs(m4 - 3) < 5 * sqrt(96.0 / n), "%s: fourth moment %g", what, m4);
}

void test_rng_gaussians(void)
{
    enum { N = 2000000 };
    double *x = (double *)malloc(N * sizeof(double));
    hcbd_world_def d = scene(64, 0.24);
    hcbd_world w;
    hcbd_rng r;
    int k, tail = 0;
    if (!make_world(&w, &d)) return;
    hcbd_rng_seed(&r, 42);
    for (k = 0; k < N; ++k) {
        x[k] = hcbd_world_rng_normal(&w, &r);
        if (fabs(x[k]) > 3.6541528853610088) ++tail;
    }
    moments(x, N, "xoshiro ziggurat");
    /* P(|x| > R) = erfc(R / sqrt 2) = 2.58e-4: the tail branch works */
    {
        double pe = erfc(3.6541528853610088 / sqrt(2.0)), e = sqrt(pe * N);
        CHECK(fabs(tail - pe * N) < 5 * e, "tail count %d, expected %g", tail, pe * N);
    }
    for (k = 0; k < N / 3; ++k) hcbd_world_pair_normals(&w, k / 1000, k % 1000, 1000 + k % 7, x + 3 * k);
    moments(x, 3 * (N / 3), "pair stream");
    /* neighbouring keys must be independent: correlation of first normals
       of (step, a, b) and (step, a, b+1), and of steps s and s+1 */
    {
        double c1 = 0, c2 = 0;
        int n = 300000;
        for (k = 0; k < n; ++k) {
            double a[3], b[3], c[3];
            hcbd_world_pair_normals(&w, 7, k, k + 1, a);
            hcbd_world_pair_normals(&w, 7, k, k + 2, b);
            hcbd_world_pair_normals(&w, 8, k, k + 1, c);
            c1 += a[0] * b[0];
            c2 += a[0] * c[0];
        }
        CHECK(fabs(c1 / n) < 5 / sqrt((double)n), "pair-neighbour correlation %g", c1 / n);
        CHECK(fabs(c2 / n) < 5 / sqrt((double)n), "step-neighbour correlation %g", c2 / n);
    }
    /* symmetric in the ids, and the three components are distinct */
    {
        double a[3], b[3];
        hcbd_world_pair_normals(&w, 3, 10, 20, a);
        hcbd_world_pair_normals(&w, 3, 20, 10, b);
        CHECK(a[0] == b[0] && a[1] == b[1] && a[2] == b[2], "key (a,b) != (b,a)");
        CHECK(a[0] != a[1] && a[1] != a[2], "components equal");
    }
    hcbd_world_destroy(&w);
    free(x);
}

void test_rng_uniform_noise(void)
{
    enum { N = 600000 };
    double *x = (double *)malloc(3 * N * sizeof(double)), m2 = 0, mx = 0;
    hcbd_world_def d = scene(64, 0.24);
    hcbd_world w;
    int k;
    d.params.noise = HCBD_NOISE_UNIFORM;
    if (!make_world(&w, &d)) return;
    for (k = 0; k < N; ++k) hcbd_world_pair_normals(&w, k, 1, 2, x + 3 * k);
    for (k = 0; k < 3 * N; ++k) {
        m2 += x[k] * x[k];
        if (fabs(x[k]) > mx) mx = fabs(x[k]);
    }
    m2 /= 3 * N;
    /* variance of U(-a, a) squared is a^4/5 - a^4/9 = 0.8 for a = sqrt 3 */
    CHECK(fabs(m2 - 1) < 5 * sqrt(0.8 / (3 * N)), "variance %g", m2);
    CHECK(mx < 1.7320508075688772, "max %g", mx);
    hcbd_world_destroy(&w);
    free(x);
}

void test_xoshiro_reference(void)
{
    /* xoshiro256** from state {1,2,3,4}: the first outputs of the reference
       C implementation (Blackman & Vigna) */
    hcbd_rng r;
    uint64_t sm = 0;
    r.s[0] = 1; r.s[1] = 2; r.s[2] = 3; r.s[3] = 4;
    CHECK(hcbd_rng_next(&r) == 11520ULL, "first output");
    CHECK(hcbd_rng_next(&r) == 0ULL, "second output");
    CHECK(hcbd_rng_next(&r) == 1509978240ULL, "third output");
    CHECK(hcbd_rng_next(&r) == 1215971899390074240ULL, "fourth output");
    /* splitmix64 from 0: reference value 0xE220A8397B1DCDAF */
    CHECK(hcbd_splitmix64(&sm) == 0xE220A8397B1DCDAFULL, "splitmix64");
}

/* The stand-alone noise stream (what lammps/ draws) gives the world's pair
   and particle noise bit for bit, both kinds, ids in either order. */
void test_noise_stream(void)
{
    int kind, k;
    for (kind = 0; kind < 2; ++kind) {
        hcbd_world_def d = scene(64, 0.24);
        hcbd_world w;
        hcbd_noise_stream ns;
        int same = 1;
        d.params.noise = kind ? HCBD_NOISE_UNIFORM : HCBD_NOISE_GAUSS;
        d.params.seed = 12345;
        if (!make_world(&w, &d)) return;
        hcbd_noise_stream_init(&ns, 12345, d.params.noise);
        for (k = 0; k < 300; ++k) {
            double a[3], b[3], c[3], e[3];
            int64_t s = k * 977LL;
            hcbd_world_pair_normals(&w, s, k, 3 * k + 1, a);
            hcbd_noise_pair(&ns, s, 3 * k + 1, k, b);
            hcbd_world_particle_normals(&w, s, k, c);
            hcbd_noise_particle(&ns, s, k, e);
            same &= !memcmp(a, b, sizeof a) && !memcmp(c, e, sizeof c);
        }
        CHECK(same, "%s noise: the stream differs from the world's", kind ? "uniform" : "Gaussian");
        hcbd_world_destroy(&w);
    }
}
