/* Observables against independent computations. */
#include "test.h"

/* AR(1) signal x_{t+1} = a x_t + sqrt(1 - a^2) g has <x_t x_{t+s}> = a^s.
   The multiple-tau correlator must equal a direct computation of the same
   block-averaged estimator at every lag it reports (the long-lag tail
   included), and agree with a^s within the statistical error. */
void test_multiple_tau_correlator(void)
{
    enum { N = 1 << 16, P = 16, M = 2, LEV = 12 };
    double *x = (double *)malloc(N * sizeof(double)), lag[400], c[400];
    int64_t cnt[400];
    hcbd_mtcorr mt;
    size_t bytes = hcbd_mtcorr_bytes(2, P, M, LEV);
    void *mem = malloc(bytes);
    hcbd_rng r;
    hcbd_world_def d = scene(64, 0.24);
    hcbd_world w;
    double a = 0.98, v = 0;
    int k, nres, checked = 0;
    if (!make_world(&w, &d)) return;
    hcbd_rng_seed(&r, 5);
    CHECK(hcbd_mtcorr_init(&mt, 2, P, M, LEV, mem, bytes) == HCBD_OK, "init");
    for (k = 0; k < N; ++k) {
        double two[2];
        v = a * v + sqrt(1 - a * a) * hcbd_world_rng_normal(&w, &r);
        x[k] = v;
        two[0] = v;
        two[1] = -v; /* a second channel with the same correlation */
        hcbd_mtcorr_add(&mt, two);
    }
    hcbd_mtcorr_finalize(&mt);
    nres = hcbd_mtcorr_result(&mt, 1, lag, c, cnt, 400);
    /* level 0: P lags; levels 1..kmax-1: P - P/M each (the top level is dropped) */
    CHECK(nres == P + (P - P / M) * (LEV - 2), "%d lags", nres);
    for (k = 0; k < nres; ++k) {
        /* direct: block averages of length b = m^level, products at lag */
        int b = 1, s = (int)lag[k], nb, t;
        double sum = 0;
        int64_t n = 0;
        while (s >= P * b) b *= M;
        nb = N / b;
        {
            double *avg = (double *)malloc((size_t)nb * sizeof(double));
            for (t = 0; t < nb; ++t) {
                int u;
                avg[t] = 0;
                for (u = 0; u < b; ++u) avg[t] += x[t * b + u];
                avg[t] /= b;
            }
            for (t = 0; t + s / b < nb; ++t) {
                sum += avg[t] * avg[t + s / b];
                ++n;
            }
            free(avg);
        }
        CHECK(n == cnt[k], "lag %g: count %lld, direct %lld", lag[k], (long long)cnt[k], (long long)n);
        CHECK(fabs(sum / n - c[k]) < 1e-9 * (1 + fabs(c[k])), "lag %g: %g vs direct %g", lag[k],
              c[k], sum / n);
        /* against the exact correlation of block averages of length b:
           (1/b^2) sum_{u,v<b} a^|s + v - u|; error of an AR(1) covariance
           estimate from n products ~ sqrt((1 + a^2)/(1 - a^2) / n) */
        if (cnt[k] > 100) {
            double ex = 0, err = sqrt((1 + a * a) / (1 - a * a) / (double)cnt[k]);
            int u, v;
            for (u = 0; u < b; ++u)
                for (v = 0; v < b; ++v) ex += pow(a, fabs((double)(s + v - u)));
            ex /= (double)b * b;
            CHECK(fabs(c[k] - ex) < 5 * err, "lag %d (blocks of %d): %g vs exact %g (err %g)", s, b,
                  c[k], ex, err);
            ++checked;
        }
    }
    CHECK(c[0] > 0.9 && c[0] < 1.1, "C(0) = %g", c[0]);
    CHECK(checked > 10, "only %d lags compared with theory", checked);
    free(mem);
    free(x);
    hcbd_world_destroy(&w);
}

/* Order-n MSD equals the direct all-origins average at the lags where
   every sample is an origin (level 0), and averages over origins spaced
   B^l at higher levels; both checked against a direct computation. */
void test_msd_order_n(void)
{
    enum { NP = 5, T = 2000, B = 8, LEV = 4 };
    double *traj = (double *)malloc((size_t)T * 3 * NP * sizeof(double));
    double lag[64], msd[64];
    int64_t cnt[64];
    size_t bytes = hcbd_msd_bytes(NP, B, LEV, 0);
    void *mem = malloc(bytes);
    hcbd_msd m;
    hcbd_rng r;
    int t, k, nres;
    hcbd_rng_seed(&r, 9);
    CHECK(hcbd_msd_init(&m, NP, B, LEV, 0, 0, mem, bytes) == HCBD_OK, "init");
    for (k = 0; k < 3 * NP; ++k) traj[k] = 0;
    for (t = 1; t < T; ++t)
        for (k = 0; k < 3 * NP; ++k)
            traj[(size_t)t * 3 * NP + k] = traj[(size_t)(t - 1) * 3 * NP + k] + hcbd_rng_uniform(&r) - 0.5;
    for (t = 0; t < T; ++t) hcbd_msd_add(&m, traj + (size_t)t * 3 * NP);
    nres = hcbd_msd_result(&m, lag, msd, cnt, 64);
    /* levels 0-2 full; level 3 (every 512 samples) has 4 positions */
    CHECK(nres == 3 * (B - 1) + 3, "%d lags", nres);
    for (k = 0; k < nres; ++k) {
        int s = (int)lag[k], every = 1, t0;
        double sum = 0;
        int64_t n = 0;
        while (s >= B * every) every *= B;
        for (t0 = 0; t0 + s < T; t0 += every) {
            int c;
            double d2 = 0;
            if ((t0 + s) % every) continue;
            for (c = 0; c < 3 * NP; ++c) {
                double dd = traj[(size_t)(t0 + s) * 3 * NP + c] - traj[(size_t)t0 * 3 * NP + c];
                d2 += dd * dd;
            }
            sum += d2 / NP;
            ++n;
        }
        CHECK(n == cnt[k] && fabs(sum / n - msd[k]) < 1e-9 * sum / n, "lag %d: %g (%lld) vs %g (%lld)",
              s, msd[k], (long long)cnt[k], sum / n, (long long)n);
    }
    free(mem);
    free(traj);
}

/* g(r) of an ideal gas is 1: both the list path and the all-pairs path. */
void test_rdf_ideal_gas(void)
{
    hcbd_world_def d = scene(2000, 0.24);
    hcbd_world w;
    double h1[25], h2[25], g1[25], g2[25];
    hcbd_rdf a, b;
    int s, k;
    d.params.potential = HCBD_POT_IDEAL;
    if (!make_world(&w, &d)) return;
    hcbd_rdf_init(&a, 2.5, 25, 0, h1, sizeof h1);
    hcbd_rdf_init(&b, 5.0, 25, 0, h2, sizeof h2);
    for (s = 0; s < 20; ++s) {
        w.p.seed = 100 + s;
        hcbd_world_place_random(&w, 2000);
        hcbd_rdf_sample(&a, &w);
        hcbd_rdf_sample(&b, &w);
    }
    hcbd_rdf_result(&a, NULL, g1, NULL);
    hcbd_rdf_result(&b, NULL, g2, NULL);
    for (k = 2; k < 25; ++k) {
        /* Poisson error of a bin count: 1 / sqrt(expected count) */
        double shell1 = 4.0 / 3 * 3.14159265 * (pow((k + 1) * 0.1, 3) - pow(k * 0.1, 3));
        double e1 = 1 / sqrt(0.5 * 2000 * 0.24 * shell1 * 20);
        double shell2 = 4.0 / 3 * 3.14159265 * (pow((k + 1) * 0.2, 3) - pow(k * 0.2, 3));
        double e2 = 1 / sqrt(0.5 * 2000 * 0.24 * shell2 * 20);
        CHECK(fabs(g1[k] - 1) < 5 * e1, "list path bin %d: %g (err %g)", k, g1[k], e1);
        CHECK(fabs(g2[k] - 1) < 5 * e2, "all-pairs path bin %d: %g (err %g)", k, g2[k], e2);
    }
    hcbd_world_destroy(&w);
}

/* The pair-virial shear stress equals (1/V) dU/dgamma under the affine
   shear x -> x + gamma y (an independent computation from energies). */
void test_stress_is_strain_derivative(void)
{
    enum { N = 300 };
    hcbd_world_def d = scene(N, 0.24);
    hcbd_world w;
    double xyz[3 * N], s[9], V, h = 1e-6, up, dn;
    int i;
    d.params.dynamics = HCBD_DYN_BD;
    if (!make_world(&w, &d)) return;
    hcbd_world_place_lattice(&w, N);
    run(&w, 2000); /* a liquid configuration */
    hcbd_world_get_positions(&w, xyz, 1);
    hcbd_world_virial_stress(&w, s);
    V = w.p.L[0] * w.p.L[1] * w.p.L[2];
    {
        /* energy as a function of gamma with Lees-Edwards-consistent images:
           sum over pairs of V(|x_ij + gamma y_ij e_x|) with the minimum
           image taken before the strain */
        double e[2];
        int sgn;
        for (sgn = 0; sgn < 2; ++sgn) {
            double g = sgn ? -h : h, E = 0;
            int j;
            for (i = 0; i < N; ++i)
                for (j = i + 1; j < N; ++j) {
                    double dx[3], r;
                    int c;
                    for (c = 0; c < 3; ++c) {
                        dx[c] = xyz[3 * i + c] - xyz[3 * j + c];
                        dx[c] -= w.p.L[c] * round(dx[c] / w.p.L[c]);
                    }
                    dx[0] += g * dx[1];
                    r = sqrt(dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2]);
                    if (r < 2.5) E += hcbd_star_potential(r, 128, 1, 1);
                }
            e[sgn] = E;
        }
        up = e[0];
        dn = e[1];
    }
    /* S_xy = -(1/V) sum x_ij F_ij,y: with F = -dV/dr e, this is
       (1/V) sum V'(r) x y / r = (1/V) dU/dgamma */
    CHECK(fabs(s[1] - (up - dn) / (2 * h) / V) < 1e-6 * (1 + fabs(s[1])), "S_xy %g vs dU/dg/V %g",
          s[1], (up - dn) / (2 * h) / V);
    CHECK(fabs(s[1] - s[3]) < 1e-12 * (1 + fabs(s[1])), "stress not symmetric: %g %g", s[1], s[3]);
    hcbd_world_destroy(&w);
}

/* Carreau fit on synthetic flow curves with known Gaussian errors: over
   many noisy realisations the pulls (fit - truth) / reported error of
   eta0, lambda and n have mean 0 and standard deviation 1 within their
   sampling errors, so both the fit and its uncertainties are right; the
   noiseless curve is recovered to 1e-6. */
void test_carreau_fit(void)
{
    enum { NP = 20, TRIALS = 200 };
    const double truth[3] = {2.526, 3.05, 0.344}, eta_inf = 0.9;
    double g[NP], eta[NP], err[NP], p[3], pe[3], chi2, pull[3][TRIALS];
    hcbd_world_def d = scene(64, 0.24);
    hcbd_world w;
    hcbd_rng r;
    int k, t, c;
    if (!make_world(&w, &d)) return;
    hcbd_rng_seed(&r, 17);
    for (k = 0; k < NP; ++k) {
        g[k] = pow(10.0, -2 + 4.0 * k / (NP - 1));
        eta[k] = eta_inf + (truth[0] - eta_inf) * pow(1 + pow(truth[1] * g[k], 2), (truth[2] - 1) / 2);
        err[k] = 0.01 * eta[k];
    }
    CHECK(hcbd_carreau_fit(g, eta, err, NP, eta_inf, 0, p, pe, &chi2) == HCBD_OK, "fit failed");
    for (c = 0; c < 3; ++c)
        CHECK(fabs(p[c] / truth[c] - 1) < 1e-6, "noiseless: parameter %d = %g, truth %g", c, p[c], truth[c]);
    for (t = 0; t < TRIALS; ++t) {
        double noisy[NP];
        for (k = 0; k < NP; ++k) noisy[k] = eta[k] + err[k] * hcbd_world_rng_normal(&w, &r);
        if (hcbd_carreau_fit(g, noisy, err, NP, eta_inf, 0, p, pe, &chi2) != HCBD_OK) {
            CHECK(0, "trial %d: fit failed", t);
            break;
        }
        for (c = 0; c < 3; ++c) pull[c][t] = (p[c] - truth[c]) / pe[c];
    }
    for (c = 0; c < 3; ++c) {
        double m = 0, s2 = 0;
        for (t = 0; t < TRIALS; ++t) m += pull[c][t] / TRIALS;
        for (t = 0; t < TRIALS; ++t) s2 += (pull[c][t] - m) * (pull[c][t] - m) / (TRIALS - 1);
        NOTE("parameter %d: pull mean %.3f, sd %.3f", c, m, sqrt(s2));
        /* sampling errors of the mean and sd of TRIALS unit normals */
        CHECK(fabs(m) < 4 / sqrt((double)TRIALS) && fabs(sqrt(s2) - 1) < 4 / sqrt(2.0 * TRIALS),
              "parameter %d: pulls have mean %g, sd %g", c, m, sqrt(s2));
    }
    {
        /* a flow curve thinning faster than n = 0 allows: the fit stops at
           n = 0, where chi^2 rises along n and along eta0, lambda either way */
        const double steep[3] = {2.0, 1.5, -0.3};
        double y[NP], q[3], c0;
        int s, d;
        for (k = 0; k < NP; ++k)
            y[k] = eta_inf + (steep[0] - eta_inf) * pow(1 + pow(steep[1] * g[k], 2), (steep[2] - 1) / 2);
        CHECK(hcbd_carreau_fit(g, y, err, NP, eta_inf, 0, p, pe, &chi2) == HCBD_OK, "bounded fit failed");
        CHECK(p[2] == 0.0, "n = %g, not held at 0", p[2]);
        c0 = 0;
        for (k = 0; k < NP; ++k) {
            const double r = (y[k] - (eta_inf + (p[0] - eta_inf) * pow(1 + pow(p[1] * g[k], 2), -0.5))) / err[k];
            c0 += r * r;
        }
        CHECK(fabs(c0 / chi2 - 1) < 1e-9, "chi2 %g, recomputed %g", chi2, c0);
        for (d = 0; d < 3; ++d)
            for (s = -1; s <= 1; s += 2) {
                double c1 = 0;
                if (d == 2 && s < 0) continue;
                for (c = 0; c < 3; ++c) q[c] = p[c];
                q[d] += s * (d == 2 ? 1e-3 : 1e-4 * p[d]);
                for (k = 0; k < NP; ++k) {
                    const double r = (y[k] - (eta_inf + (q[0] - eta_inf) *
                                              pow(1 + pow(q[1] * g[k], 2), (q[2] - 1) / 2))) / err[k];
                    c1 += r * r;
                }
                CHECK(c1 >= chi2 * (1 - 1e-12), "chi2 falls from %g to %g moving parameter %d by %+d", chi2, c1,
                      d, s);
            }
    }
    {
        /* The error scale on the preset's six rates, the points scattered
           K times their stated errors (as a run's scatter about the
           Carreau form exceeds its errors): chi^2 / dof, and so the squared
           scale, is K^2 on average with dof = 6 - 3, its spread
           sqrt(2 / dof) K^2 per fit. */
        enum { N6 = 6, FITS = 400 };
        const double K = 3, g6[N6] = {0.1, 0.3, 1, 3, 10, 30};
        double y6[N6], e6[N6], s2 = 0;
        int f, bad = 0;
        for (f = 0; f < FITS; ++f) {
            for (k = 0; k < N6; ++k) {
                const double c6 =
                    eta_inf + (truth[0] - eta_inf) * pow(1 + pow(truth[1] * g6[k], 2), (truth[2] - 1) / 2);
                e6[k] = 0.01 * c6;
                y6[k] = c6 + K * e6[k] * hcbd_world_rng_normal(&w, &r);
            }
            if (hcbd_carreau_fit(g6, y6, e6, N6, eta_inf, 0, p, pe, &chi2) != HCBD_OK) {
                ++bad;
                continue;
            }
            s2 += pow(hcbd_carreau_err_scale(chi2, N6), 2);
        }
        s2 /= FITS - bad;
        NOTE("six rates scattered %g errors: mean squared scale %.3f (%d fits failed)", K, s2, bad);
        CHECK(bad == 0 && fabs(s2 - K * K) < 4 * sqrt(2.0 / (N6 - 3)) * K * K / sqrt((double)FITS),
              "mean squared error scale %g, expected %g", s2, K * K);
        CHECK(hcbd_carreau_err_scale(27, 6) == 3 && hcbd_carreau_err_scale(2, 6) == 1 &&
                  hcbd_carreau_err_scale(0, 4) == 1, "scale of exact cases");
        CHECK(isnan(hcbd_carreau_err_scale(1, 3)) && isnan(hcbd_carreau_err_scale(-1, 6)) &&
                  isnan(hcbd_carreau_err_scale(INFINITY, 6)) && isnan(hcbd_carreau_err_scale(NAN, 6)),
              "bad chi^2 or too few points accepted");
    }
    CHECK(hcbd_carreau_fit(g, eta, err, 3, eta_inf, 0, p, pe, NULL) == HCBD_ERR_PARAM, "3 points accepted");
    err[2] = 0;
    CHECK(hcbd_carreau_fit(g, eta, err, NP, eta_inf, 0, p, pe, NULL) == HCBD_ERR_PARAM, "zero error accepted");
    hcbd_world_destroy(&w);
}

/* A random walk of np walkers, T samples, uniform steps in (-1/2, 1/2):
   MSD(s) = s / 4, D = 1/24 per sample. */
static double *walk(int np, int T, uint64_t seed)
{
    double *traj = (double *)malloc((size_t)T * 3 * np * sizeof(double));
    hcbd_rng r;
    int t, k;
    if (!traj) return NULL;
    hcbd_rng_seed(&r, seed);
    for (k = 0; k < 3 * np; ++k) traj[k] = 0;
    for (t = 1; t < T; ++t)
        for (k = 0; k < 3 * np; ++k)
            traj[(size_t)t * 3 * np + k] = traj[(size_t)(t - 1) * 3 * np + k] + hcbd_rng_uniform(&r) - 0.5;
    return traj;
}

/* Dense origins and blocks: at every lag the block means, their error and
   the all-sample mean equal a direct computation with origins every
   B^max(0, l - dense) samples, restarted in each block. */
void test_msd_dense_blocks(void)
{
    enum { NP = 4, T = 3000, B = 4, LEV = 4, DENSE = 1, BLK = 1000, NBK = T / BLK };
    double *traj = walk(NP, T, 11), lag[64], msd[64], err[64], all[64];
    size_t bytes = hcbd_msd_bytes(NP, B, LEV, DENSE);
    void *mem = malloc(bytes);
    hcbd_msd m;
    int t, k, nres, nall;
    if (!traj || !mem) { CHECK(0, "out of memory"); free(traj); free(mem); return; }
    CHECK(hcbd_msd_init(&m, NP, B, LEV, DENSE, BLK, mem, bytes) == HCBD_OK, "init");
    for (t = 0; t < T; ++t) hcbd_msd_add(&m, traj + (size_t)t * 3 * NP);
    nres = hcbd_msd_stats(&m, lag, msd, err, 64);
    nall = hcbd_msd_result(&m, NULL, all, NULL, 64);
    CHECK(nres == LEV * (B - 1) && nall == nres, "%d block lags, %d lags", nres, nall);
    for (k = 0; k < nres; ++k) {
        int s = (int)lag[k], level = 0, stride = 1, b, t0;
        double bm[NBK], sum = 0, mean, e;
        int64_t n = 0;
        while (s >= B * (int)pow(B, level)) ++level;
        for (t0 = level - DENSE; t0 > 0; --t0) stride *= B;
        for (b = 0; b < NBK; ++b) {
            double bs = 0;
            int bn = 0;
            for (t0 = 0; t0 + s < BLK; t0 += stride) {
                int c;
                double d2 = 0;
                for (c = 0; c < 3 * NP; ++c) {
                    double dd = traj[(size_t)(b * BLK + t0 + s) * 3 * NP + c] - traj[(size_t)(b * BLK + t0) * 3 * NP + c];
                    d2 += dd * dd;
                }
                bs += d2 / NP;
                ++bn;
            }
            bm[b] = bs / bn;
            sum += bs;
            n += bn;
        }
        block_stats(bm, NBK, NBK, &mean, &e);
        CHECK(fabs(msd[k] - mean) < 1e-9 * mean && fabs(err[k] - e) < 1e-6 * e &&
              fabs(all[k] - sum / n) < 1e-9 * mean,
              "lag %d: blocks %g +- %g vs %g +- %g, all %g vs %g", s, msd[k], err[k], mean, e,
              all[k], sum / n);
    }
    free(mem);
    free(traj);
}

/* The diffusion coefficient of random walks, D = 1/24 per sample, and its
   block error: over R independent walks the z-scores (D - 1/24) / err
   have the variance of a t-distribution with NBK - 1 degrees of freedom,
   9/7; the pooled mean is within four of its errors. */
void test_msd_diffusion_walk(void)
{
    enum { NP = 50, T = 20000, B = 10, LEV = 3, BLK = 2000, R = 16 };
    size_t bytes = hcbd_msd_bytes(NP, B, LEV, 1);
    void *mem = malloc(bytes);
    double z2 = 0, Dsum = 0, e2sum = 0;
    int r;
    if (!mem) { CHECK(0, "out of memory"); return; }
    for (r = 0; r < R; ++r) {
        double *traj = walk(NP, T, 100 + (uint64_t)r), D, e;
        hcbd_msd m;
        int t;
        if (!traj) { CHECK(0, "out of memory"); break; }
        hcbd_msd_init(&m, NP, B, LEV, 1, BLK, mem, bytes);
        for (t = 0; t < T; ++t) hcbd_msd_add(&m, traj + (size_t)t * 3 * NP);
        CHECK(hcbd_msd_diffusion(&m, 10, 90, &D, &e) == HCBD_OK && e > 0, "diffusion");
        z2 += (D - 1.0 / 24) * (D - 1.0 / 24) / (e * e);
        Dsum += D;
        e2sum += e * e;
        free(traj);
    }
    NOTE("D = %.6f +- %.6f (1/24 = %.6f), mean z^2 = %.2f (9/7 expected)", Dsum / R,
         sqrt(e2sum) / R, 1.0 / 24, z2 / R);
    /* mean z^2 of R t(9) variables: 9/7 with spread about 0.5 */
    CHECK(z2 / R > 0.4 && z2 / R < 3.0, "mean z^2 = %g: the block error is not the scatter", z2 / R);
    CHECK(fabs(Dsum / R - 1.0 / 24) < 4 * sqrt(e2sum) / R, "D = %g vs 1/24", Dsum / R);
    free(mem);
}

/* Coordination on a simple cubic lattice (spacing 1) is exact: 6 within
   1.2, 18 within 1.5, and 6 + 12 f inside the shell that holds sqrt 2,
   f its volume fraction below rc. */
void test_rdf_coordination_lattice(void)
{
    enum { K = 8, N = K * K * K };
    hcbd_world_def d = scene(N, 1.0);
    hcbd_world w;
    double xyz[3 * N], mem[40], nc[3], f;
    hcbd_rdf g;
    int i;
    d.params.potential = HCBD_POT_IDEAL;
    if (!make_world(&w, &d)) return;
    for (i = 0; i < N; ++i) {
        xyz[3 * i] = i % K + 0.5;
        xyz[3 * i + 1] = i / K % K + 0.5;
        xyz[3 * i + 2] = i / (K * K) + 0.5;
    }
    CHECK(hcbd_world_set_positions(&w, N, xyz) == HCBD_OK, "lattice");
    CHECK(hcbd_rdf_init(&g, 4.0, 40, 0, mem, sizeof mem) == HCBD_OK, "init");
    CHECK(hcbd_rdf_sample(&g, &w) == HCBD_OK, "sample");
    hcbd_rdf_coordination(&g, 1.2, &nc[0], NULL);
    hcbd_rdf_coordination(&g, 1.5, &nc[1], NULL);
    hcbd_rdf_coordination(&g, 1.45, &nc[2], NULL);
    f = (pow(1.45, 3) - pow(1.4, 3)) / (pow(1.5, 3) - pow(1.4, 3));
    CHECK(fabs(nc[0] - 6) < 1e-12 && fabs(nc[1] - 18) < 1e-12 && fabs(nc[2] - 6 - 12 * f) < 1e-12,
          "coordination %g %g %g vs 6 18 %g", nc[0], nc[1], nc[2], 6 + 12 * f);
    hcbd_world_destroy(&w);
}

/* Block errors of g(r) and of the coordination number equal the scatter of
   separate estimators, one per block; the ideal gas's coordination within
   rc = 2.4 (a shell edge) is 4/3 pi rc^3 (n - 1) / V within four of those errors. */
void test_rdf_blocks(void)
{
    enum { N = 2000, NB = 25, BLK = 4, NBK = 5 };
    hcbd_world_def d = scene(N, 0.24);
    hcbd_world w;
    double mem[6 * NB], sep[NBK][NB], g[NB], err[NB], gb[NBK][NB], cb[NBK], nc, ec, V, th;
    hcbd_rdf all, one[NBK];
    int s, k, b;
    d.params.potential = HCBD_POT_IDEAL;
    if (!make_world(&w, &d)) return;
    CHECK(hcbd_rdf_init(&all, 5.0, NB, BLK, mem, sizeof mem) == HCBD_OK, "init");
    for (b = 0; b < NBK; ++b) hcbd_rdf_init(&one[b], 5.0, NB, 0, sep[b], sizeof sep[b]);
    for (s = 0; s < BLK * NBK; ++s) {
        w.p.seed = 300 + s;
        hcbd_world_place_random(&w, N);
        hcbd_rdf_sample(&all, &w);
        hcbd_rdf_sample(&one[s / BLK], &w);
    }
    CHECK(hcbd_rdf_result(&all, NULL, g, err) == NBK, "closed blocks");
    for (b = 0; b < NBK; ++b) {
        hcbd_rdf_result(&one[b], NULL, gb[b], NULL);
        hcbd_rdf_coordination(&one[b], 2.4, &cb[b], NULL);
    }
    for (k = 1; k < NB; ++k) {
        double col[NBK], m, e;
        for (b = 0; b < NBK; ++b) col[b] = gb[b][k];
        block_stats(col, NBK, NBK, &m, &e);
        CHECK(fabs(g[k] - m) < 1e-12 && fabs(err[k] - e) < 1e-9, "bin %d: %g +- %g vs %g +- %g", k, g[k],
              err[k], m, e);
    }
    {
        double m, e;
        block_stats(cb, NBK, NBK, &m, &e);
        hcbd_rdf_coordination(&all, 2.4, &nc, &ec);
        CHECK(fabs(nc - m) < 1e-12 && fabs(ec - e) < 1e-9, "coordination %g +- %g vs %g +- %g", nc, ec, m, e);
    }
    V = w.p.L[0] * w.p.L[1] * w.p.L[2];
    th = 4.0 / 3 * 3.14159265358979 * pow(2.4, 3) * (N - 1) / V;
    NOTE("ideal gas coordination within 2.4: %.4f +- %.4f, theory %.4f", nc, ec, th);
    CHECK(fabs(nc - th) < 4 * ec, "coordination %g +- %g vs %g", nc, ec, th);
    hcbd_world_destroy(&w);
}


/* hcbd_blocking_error against series whose error of the mean is known:
   independent normals (err = 1/sqrt(n)) and AR(1), x' = phi x +
   sqrt(1 - phi^2) z, whose mean over n samples has the variance
   ((1 + phi)/(1 - phi) - 2 phi (1 - phi^n)/(n (1 - phi)^2)) / n. */
void test_blocking_error(void)
{
    enum { N = 16384, TRIALS = 300 };
    static double x[N];
    const double phis[2] = {0.0, 0.9};
    hcbd_world_def d = scene(64, 0.24);
    hcbd_world w;
    hcbd_rng r;
    double m, e, neff;
    int c, t, k, pl;
    if (!make_world(&w, &d)) return;
    hcbd_rng_seed(&r, 23);
    for (c = 0; c < 2; ++c) {
        const double phi = phis[c], a = sqrt(1 - phi * phi);
        const double truth = sqrt(((1 + phi) / (1 - phi) - 2 * phi * (1 - pow(phi, N)) / (N * (1 - phi) * (1 - phi))) / N);
        double se = 0, sp = 0, sp2 = 0, sn = 0;
        int npl = 0;
        for (t = 0; t < TRIALS; ++t) {
            double v = hcbd_world_rng_normal(&w, &r);
            for (k = 0; k < N; ++k) {
                x[k] = v;
                v = phi * v + a * hcbd_world_rng_normal(&w, &r);
            }
            if (hcbd_blocking_error(x, N, &m, &e, &neff, &pl) != HCBD_OK) {
                CHECK(0, "phi %g: blocking failed", phi);
                break;
            }
            se += e / truth;
            sp += m / e;
            sp2 += (m / e) * (m / e);
            sn += neff;
            npl += pl;
        }
        se /= TRIALS;
        sp /= TRIALS;
        sp2 = sqrt(sp2 / TRIALS - sp * sp);
        NOTE("phi %.1f: err / truth %.3f, pulls mean %.3f sd %.3f, neff %.0f (truth %.0f), plateau %d of %d", phi, se,
             sp, sp2, sn / TRIALS, 1 / (truth * truth), npl, TRIALS);
        /* the estimate's own scatter is 4-7 % per trial, so its mean over
           TRIALS is known to 0.4 %; blocks short of the correlation time
           read a few per cent low by design (tau / length) */
        CHECK(se > 0.93 && se < 1.03, "phi %g: mean error estimate %g of the truth", phi, se);
        CHECK(fabs(sp) < 4 / sqrt((double)TRIALS) && sp2 > 1 - 4 / sqrt(2.0 * TRIALS) &&
              sp2 < 1.04 + 4 / sqrt(2.0 * TRIALS), "phi %g: pulls have mean %g, sd %g", phi, sp, sp2);
        CHECK(fabs(sn / TRIALS * truth * truth - 1) < 0.15, "phi %g: neff %g, truth %g", phi, sn / TRIALS,
              1 / (truth * truth));
        CHECK(npl == TRIALS, "phi %g: %d of %d series found no plateau", phi, TRIALS - npl, TRIALS);
    }
    /* a series far shorter than its correlation time has no plateau */
    {
        double v = 0;
        for (k = 0; k < 256; ++k) {
            x[k] = v;
            v = 0.9995 * v + 0.0316 * hcbd_world_rng_normal(&w, &r);
        }
        CHECK(hcbd_blocking_error(x, 256, &m, &e, NULL, &pl) == HCBD_OK && pl == 0,
              "a 256-sample series with tau ~ 2000 samples reported a plateau");
    }
    /* an alternating series (an oscillation aliased by the sampling, as
       a sheared stress can be) agrees in its pairs' means far better than
       in its samples; 8 samples cannot vouch for that, so the error stays
       at least the samples' own and n_eff at most their number */
    for (t = 0; t < 100; ++t) {
        double s2 = 0;
        for (k = 0; k < 8; ++k) x[k] = (k % 2 ? 1.0 : -1.0) + 0.01 * hcbd_world_rng_normal(&w, &r);
        hcbd_blocking_error(x, 8, &m, &e, &neff, &pl);
        for (k = 0; k < 8; ++k) s2 += (x[k] - m) * (x[k] - m);
        if (!(e >= sqrt(s2 / 7 / 8) * (1 - 1e-12) && neff <= 8 * (1 + 1e-9))) {
            CHECK(0, "alternating series: err %g below the samples' %g (n_eff %g of 8)", e, sqrt(s2 / 56), neff);
            break;
        }
    }
    CHECK(hcbd_blocking_error(x, 7, &m, &e, NULL, NULL) == HCBD_ERR_PARAM, "7 samples accepted");
    CHECK(hcbd_blocking_error(NULL, 16, &m, &e, NULL, NULL) == HCBD_ERR_NULL, "NULL series accepted");
    CHECK(hcbd_blocking_error(x, 16, NULL, &e, NULL, NULL) == HCBD_ERR_NULL, "NULL mean accepted");
    x[3] = NAN;
    CHECK(hcbd_blocking_error(x, 16, &m, &e, NULL, NULL) == HCBD_ERR_NONFINITE, "NaN accepted");
    hcbd_world_destroy(&w);
}
