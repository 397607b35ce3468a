/* Statistical physics tests (MODEL 3, 10).  Every tolerance is a multiple
   of an error measured from block averages of the same run, plus, where
   stated, the size of a known higher-order term. */
#include "test.h"

#define PI 3.14159265358979323846

/* Equipartition of the background velocities with the Euler bias: the
   temperature excess is (dt/(2 tau)) <sum_j f_ij> to first order (MODEL 10)
   and halves when dt halves. */
static void temperature_run(double dt, double tau, hcbd_pair_integrator integ, hcbd_potential pot,
                            int nsamp, double *bias, double *err, double *pred)
{
    hcbd_world_def d = scene(1000, 0.24);
    hcbd_world w;
    int every = (int)(0.4 * tau / dt + 0.5), k;
    double *T, sf = 0, out[3], mean;
    nsamp = (int)(nsamp * t_len);
    if (t_quick) nsamp /= 5;
    if (every < 1) every = 1;
    T = (double *)malloc(nsamp * sizeof(double));
    d.params.potential = pot;
    d.params.pair_integrator = integ;
    d.params.tau = tau;
    d.params.dt = dt;
    d.params.seed = 77;
    d.params.skin = 1.2; /* Brownian steps of 0.08: a thin skin rebuilds every step */
    if (!make_world(&w, &d)) return;
    if (pot == HCBD_POT_IDEAL) hcbd_world_place_random(&w, 1000);
    else hcbd_world_place_lattice(&w, 1000); /* random stars overlap */
    run(&w, 20 * every);
    for (k = 0; k < nsamp; ++k) {
        run(&w, every);
        T[k] = hcbd_world_temperature(&w);
        if (k % 100 == 0) {
            hcbd_world_friction_average(&w, 1, out);
            sf += out[0];
        }
    }
    block_stats(T, nsamp, 20, &mean, err);
    *bias = mean - 1;
    *pred = dt / (2 * d.params.tau) * sf / (nsamp / 100);
    free(T);
    hcbd_world_destroy(&w);
}

void test_equipartition_euler_bias(void)
{
    double b1, e1, p1, b2, e2, p2;
    temperature_run(1e-3, 1e-2, HCBD_PAIR_EULER, HCBD_POT_IDEAL, 2000, &b1, &e1, &p1);
    temperature_run(5e-4, 1e-2, HCBD_PAIR_EULER, HCBD_POT_IDEAL, 2000, &b2, &e2, &p2);
    NOTE("tau = 10 dt: T/kT - 1 = %.4f +- %.4f, first-order (dt/2tau)<sum f> = %.4f", b1, e1, p1);
    NOTE("tau = 20 dt: T/kT - 1 = %.4f +- %.4f, first-order %.4f", b2, e2, p2);
    if (t_quick) return;
    /* second-order term of a discrete Ornstein-Uhlenbeck variance,
       1/(1 - x) = 1 + x + x^2..., bounds the departure from first order */
    CHECK(fabs(b1 - p1) < 4 * e1 + 2 * p1 * p1, "dt: bias %g vs %g", b1, p1);
    CHECK(fabs(b2 - p2) < 4 * e2 + 2 * p2 * p2, "dt/2: bias %g vs %g", b2, p2);
    CHECK(fabs(b1 / 2 - b2) < 4 * sqrt(e1 * e1 / 4 + e2 * e2) + p1 * p1,
          "bias does not halve with dt: %g -> %g", b1, b2);
    CHECK(e1 < 0.2 * b1, "run too short to resolve the bias: %g +- %g", b1, e1);
}

/* The Shardlow sweep solves every pair exactly, so the Euler excess above
   (about 5 % at tau = 10 dt) is gone: the temperature equals kT within the
   run's error, for ideal carriers and for stars (whose force kick on v is
   still explicit), and at tau = dt. */
void test_equipartition_shardlow(void)
{
    static const struct { double dt, tau; hcbd_potential pot; int nsamp; } c[3] = {
        {1e-3, 1e-2, HCBD_POT_IDEAL, 2000}, {2e-4, 2e-3, HCBD_POT_STAR, 1000},
        {1e-2, 1e-2, HCBD_POT_IDEAL, 2000}};
    int k;
    for (k = 0; k < 3; ++k) {
        double b, e, pred;
        temperature_run(c[k].dt, c[k].tau, HCBD_PAIR_SHARDLOW, c[k].pot, c[k].nsamp, &b, &e, &pred);
        NOTE("Shardlow, tau = %g dt, %s: T/kT - 1 = %.4f +- %.4f (Euler's first-order excess %.4f)",
             c[k].tau / c[k].dt, c[k].pot == HCBD_POT_STAR ? "stars" : "ideal", b, e, pred);
        if (t_quick) continue;
        CHECK(fabs(b) < 4 * e, "Shardlow temperature off by %g +- %g", b, e);
        /* Euler's excess would stand 7 errors out */
        CHECK(e < 0.15 * pred, "run too short to see an Euler-size excess: %g +- %g", b, e);
    }
}

/* Transverse current of the background velocity.  Its initial decay rate
   is exactly (1/tau) <sum_j f_ij (1 - cos k.x_ij)> + k^2 kT/xi (MODEL 10),
   so nu_initial = Gamma/k^2 - kT/xi equals nu_meanfield, with one
   finite-system factor: total momentum is exactly zero, so <v_i v_l> =
   (kT/m)(delta_il - 1/N) and C_t(k,0) = (kT/m)(1 - S(k)/N) while the
   friction decrement is unchanged; the identity is nu_initial =
   nu_meanfield / (1 - S(k)/N), S(k) = <|rho_k|^2>/N measured in the run.
   Small box and the second wave number: the decay is fast next to the
   velocity relaxation time, and independent samples come quickly. */
typedef struct {
    double nu_init, nu_init_err, nu_mf, fs;
} tc_result;

static tc_result transverse_identity(hcbd_world_def d, int nk, int nblocks, int block_steps)
{
    enum { P = 64 };
    hcbd_world w;
    tc_result r = {0, 0, 0, 0};
    double k, rates[64], sum = 0, sum2 = 0, mf = 0, sk = 0;
    int nmf = 0, b, s, n = d.capacity;
    size_t bytes = hcbd_mtcorr_bytes(12, P, 2, 1);
    void *mem = malloc(bytes);
    double *xyz = (double *)malloc(3 * (size_t)n * sizeof(double));
    hcbd_mtcorr c;
    if (!make_world(&w, &d)) return r;
    hcbd_world_place_lattice(&w, n);
    run(&w, (int)(20000 * t_len)); /* 0.8 time units at dt = 1e-4: 8 relaxation times of the stars */
    k = 2 * PI * nk / d.params.L[0];
    for (b = 0; b < nblocks; ++b) {
        double lag[P], corr[P];
        int got;
        hcbd_mtcorr_init(&c, 12, P, 2, 1, mem, bytes);
        for (s = 0; s < block_steps; ++s) {
            double j[12];
            hcbd_world_transverse_current(&w, nk, j);
            hcbd_mtcorr_add(&c, j);
            if (s % 50 == 0) {
                gibd_mode_sample(&w, nk, xyz, &mf, &sk);
                ++nmf;
            }
            if (!run(&w, 1)) return r;
        }
        hcbd_mtcorr_finalize(&c);
        got = hcbd_mtcorr_result(&c, 1, lag, corr, NULL, P);
        /* less the Brownian displacement's share: one step moves by
           variance 2 kT dt/xi with Euler-Maruyama, half that with LM */
        rates[b] = initial_rate(corr, got, d.params.dt) / (k * k) -
                   (d.params.brownian == HCBD_BROWNIAN_LM ? 0.5 : 1.0) * d.params.kT / d.params.xi;
        sum += rates[b];
        sum2 += rates[b] * rates[b];
    }
    r.nu_init = sum / nblocks;
    r.nu_init_err = sqrt((sum2 / nblocks - r.nu_init * r.nu_init) / (nblocks - 1));
    r.nu_mf = mf / nmf;
    r.fs = 1 - sk / nmf / n;
    free(mem);
    free(xyz);
    hcbd_world_destroy(&w);
    return r;
}

void test_transverse_current_initial_decay(void)
{
    int pot;
    for (pot = 0; pot < 2; ++pot) {
        hcbd_world_def d = scene(54, 0.25);
        tc_result r;
        double target;
        d.params.L[0] = d.params.L[1] = d.params.L[2] = 6.0;
        if (pot) {
            d.params.potential = HCBD_POT_STAR;
            d.params.dt = 1e-4;
            d.params.tau = 3.6e-3;
        } else {
            d.params.potential = HCBD_POT_IDEAL;
            d.params.dt = 5e-4;
            d.params.tau = 1e-2;
        }
        r = transverse_identity(d, 2, 12, t_quick ? 2000 : 16000);
        target = r.nu_mf / r.fs;
        NOTE("%s: nu_initial = %.3f +- %.3f, nu_meanfield = %.3f, 1 - S(k)/N = %.4f, "
             "nu_initial / (nu_meanfield / (1 - S/N)) = %.4f",
             pot ? "stars" : "ideal", r.nu_init, r.nu_init_err, r.nu_mf, r.fs, r.nu_init / target);
        if (t_quick) continue;
        CHECK(fabs(r.nu_init / target - 1) < 0.03, "nu_initial %g vs %g", r.nu_init, target);
        CHECK(fabs(r.nu_init - target) < 4 * r.nu_init_err + 0.01 * target,
              "nu_initial %g +- %g vs %g", r.nu_init, r.nu_init_err, target);
        CHECK(r.nu_init_err < 0.01 * target, "error %g too large to test 3 %%", r.nu_init_err);
    }
}

/* For ideal particles with the 2016 density the configurational friction
   average gives nu_meanfield = Rc^2/(28 tau) within 5 % (MODEL 3, 10); the
   friction of an ideal gas is a property of uncorrelated positions.  The
   band is the model's: density fluctuations make <1/rho> differ from
   1/<rho> (a few %), and k = 2 pi/L is not yet small against 1/Rc. */
void test_nu_meanfield_ideal(void)
{
    hcbd_world_def d = scene(512, 0.24);
    hcbd_world w;
    double sum = 0, sum2 = 0, k, nu_th;
    int s, nconf = 10;
    d.params.L[0] = d.params.L[1] = d.params.L[2] = 12.9;
    d.params.potential = HCBD_POT_IDEAL;
    if (!make_world(&w, &d)) return;
    k = 2 * PI / 12.9;
    nu_th = 2.5 * 2.5 / (28 * d.params.tau);
    for (s = 0; s < nconf; ++s) {
        double out[3], nu;
        w.p.seed = 500 + s;
        hcbd_world_place_random(&w, 512);
        hcbd_world_friction_average(&w, 1, out);
        nu = out[2] / (d.params.tau * k * k);
        sum += nu;
        sum2 += nu * nu;
    }
    {
        double m = sum / nconf, e = sqrt((sum2 / nconf - m * m) / (nconf - 1));
        NOTE("nu_meanfield = %.2f +- %.2f, Rc^2/(28 tau) = %.2f (ratio %.4f)", m, e, nu_th, m / nu_th);
        CHECK(fabs(m / nu_th - 1) < 0.05, "nu_meanfield %g vs %g", m, nu_th);
    }
    hcbd_world_destroy(&w);
}

/* Order-n MSD of a running world in NB consecutive blocks of `steps`
   samples, one sample per step: vals[b][l] at lag[l] (in steps); returns
   the number of lags. */
enum { MSD_NB = 10, MSD_MAXLAG = 32 };
static int msd_blocks(hcbd_world *w, int steps, double vals[MSD_NB][MSD_MAXLAG], double *lag)
{
    enum { B = 10, LEV = 3 };
    int n = w->n, b, s, nl = 0;
    size_t bytes = hcbd_msd_bytes(n, B, LEV, 0);
    void *mem = malloc(bytes);
    double *xyz = (double *)malloc(3 * (size_t)n * sizeof(double));
    hcbd_msd m;
    for (b = 0; b < MSD_NB; ++b) {
        hcbd_msd_init(&m, n, B, LEV, 0, 0, mem, bytes);
        for (s = 0; s < steps; ++s) {
            hcbd_world_get_positions(w, xyz, 1);
            hcbd_msd_add(&m, xyz);
            if (!run(w, 1)) break;
        }
        nl = hcbd_msd_result(&m, lag, vals[b], NULL, MSD_MAXLAG);
    }
    free(xyz);
    free(mem);
    return nl;
}

static void lag_stats(double vals[MSD_NB][MSD_MAXLAG], int l, double *mean, double *err)
{
    double col[MSD_NB];
    int b;
    for (b = 0; b < MSD_NB; ++b) col[b] = vals[b][l];
    block_stats(col, MSD_NB, MSD_NB, mean, err);
}

/* MSD of ideal particles (2016 eq. 32) for t <= tau, where the zeroth-order
   result holds.  Eq. 32 neglects momentum flowing back from neighbours, a
   systematic effect that grows with t (MODEL 3), so the 3 % band is the
   model's accuracy claim, checked on top of the statistical error; the
   long-time ratio D_measured/D_theory (eq. 33) is reported. */
void test_msd_ideal_gibd(void)
{
    hcbd_world_def d = scene(500, 0.24);
    hcbd_world w;
    double vals[MSD_NB][MSD_MAXLAG], lag[MSD_MAXLAG], m0, m1, e;
    int nl, l;
    d.params.potential = HCBD_POT_IDEAL;
    d.params.tau = 0.1;
    d.params.dt = 1e-3;
    d.params.skin = 1.2;
    if (!make_world(&w, &d)) return;
    hcbd_world_place_random(&w, 500);
    run(&w, 1000);
    nl = msd_blocks(&w, t_quick ? 300 : (int)(2000 * t_len), vals, lag);
    /* slope over the last lags of the run, t = 5-9 tau */
    lag_stats(vals, nl - 5, &m0, &e);
    lag_stats(vals, nl - 1, &m1, &e);
    NOTE("D_measured / D_theory (eq. 33, t = %.2f-%.2f) = %.3f", lag[nl - 5] * d.params.dt,
         lag[nl - 1] * d.params.dt, (m1 - m0) / (6 * (lag[nl - 1] - lag[nl - 5]) * d.params.dt) / 2.0);
    for (l = 0; l < nl; ++l) {
        double t = lag[l] * d.params.dt, tau = d.params.tau, mean, th;
        if (t > tau) continue;
        lag_stats(vals, l, &mean, &e);
        /* kT = xi = xi' = 1; LM's steps share a deviate with the next:
           3 kT dt/xi less at every lag */
        th = 6 * (t - tau * (1 - exp(-t / tau))) + 6 * t - 3 * d.params.dt;
        if (l % 3 == 0 || t == tau) NOTE("t = %.3f: MSD %.5f +- %.5f, eq. 32 %.5f (ratio %.4f)", t, mean, e, th, mean / th);
        if (!t_quick)
            CHECK(fabs(mean / th - 1) < 0.03 && fabs(mean - th) < 4 * e + 0.03 * th,
                  "t = %g: %g +- %g vs %g", t, mean, e, th);
    }
    hcbd_world_destroy(&w);
}

/* The 2014 clash (MODEL 12): the paper says GI-BD hardly changes the star
   MSD at tau = 3.6e-3, but its equations add about kT/xi' of diffusion
   through the background velocity (2016 eq. 33), so the MSD lies above
   classical BD's and falls back towards it as xi' grows (2016 Figs. 2-3):
   MSD(BD) < MSD(xi' = 10 xi) < MSD(xi' = xi), each step resolved at 3
   sigma, at t = 0.02 (200 steps, 5.6 tau). */
static void star_msd(int dyn_bd, double xip, double *m, double *e)
{
    hcbd_world_def d = scene(256, 0.24);
    hcbd_world w;
    double vals[MSD_NB][MSD_MAXLAG], lag[MSD_MAXLAG];
    int nl, l;
    *m = *e = 0;
    d.params.dynamics = dyn_bd ? HCBD_DYN_BD : HCBD_DYN_GIBD;
    d.params.xip = xip;
    d.params.seed = 21;
    if (!make_world(&w, &d)) return;
    hcbd_world_place_lattice(&w, 256);
    run(&w, 3000);
    nl = msd_blocks(&w, t_quick ? 300 : 600, vals, lag);
    for (l = 0; l < nl; ++l)
        if (lag[l] == 200) lag_stats(vals, l, m, e);
    hcbd_world_destroy(&w);
}

void test_msd_tau_trend(void)
{
    double mb, eb, m1, e1, m10, e10;
    star_msd(1, 1.0, &mb, &eb);
    star_msd(0, 1.0, &m1, &e1);
    star_msd(0, 10.0, &m10, &e10);
    NOTE("star MSD at t = 0.02: BD %.4f +- %.4f, GI-BD tau = 3.6e-3 xi' = 10 xi %.4f +- %.4f (x%.2f), "
         "xi' = xi %.4f +- %.4f (x%.2f)", mb, eb, m10, e10, m10 / mb, m1, e1, m1 / mb);
    CHECK(mb > 0 && m1 > 0 && m10 > 0, "no MSD at lag 200");
    if (t_quick) return;
    CHECK(m10 - mb > 3 * sqrt(e10 * e10 + eb * eb), "xi' = 10 xi not above BD");
    CHECK(m1 - m10 > 3 * sqrt(e1 * e1 + e10 * e10), "xi' = xi not above xi' = 10 xi");
}

/* Classical BD of free particles: with Euler-Maruyama MSD = 6 D0 t
   exactly; with Leimkuhler-Matthews a step moves by sqrt(kT dt / (2 xi))
   (R_n + R_(n+1)), so successive steps share a deviate and MSD =
   6 D0 (t - dt/2): half a step's worth less at every lag, the same D.
   (The noise prefactor sqrt(kT dt / xi) instead of sqrt(2 kT dt / xi), or
   LM's 1/2 off by 10 %, fails.) */
void test_bd_free_diffusion(void)
{
    int k;
    for (k = 0; k < 2; ++k) {
        hcbd_world_def d = scene(1000, 0.24);
        hcbd_world w;
        double vals[MSD_NB][MSD_MAXLAG], lag[MSD_MAXLAG];
        int nl, l;
        d.params.dynamics = HCBD_DYN_BD;
        d.params.potential = HCBD_POT_IDEAL;
        d.params.brownian = k ? HCBD_BROWNIAN_LM : HCBD_BROWNIAN_EULER;
        d.params.xi = 2.0;
        d.params.kT = 1.5;
        d.params.dt = 1e-3;
        if (!make_world(&w, &d)) return;
        hcbd_world_place_random(&w, 1000);
        nl = msd_blocks(&w, 1000, vals, lag);
        for (l = 0; l < nl; ++l) {
            double t = lag[l] * d.params.dt, mean, e, th = 6 * 1.5 / 2.0 * (k ? t - 0.5 * d.params.dt : t);
            lag_stats(vals, l, &mean, &e);
            if (lag[l] == 1) NOTE("%s: one-step MSD %.6g +- %.2g, expected %.6g", k ? "LM" : "Euler", mean, e, th);
            CHECK(fabs(mean - th) < 4 * e && e < 0.05 * th, "%s, t = %g: %g +- %g vs %g", k ? "LM" : "Euler", t,
                  mean, e, th);
        }
        hcbd_world_destroy(&w);
    }
}

/* The configurational temperature <sum |F|^2> / <sum lap U> of the 2014
   star scene (N = 256) against the step, classical BD and GI-BD (issue 29).
   Euler-Maruyama's bias is first order in dt (+1.2 % per 1e-4 in BD, +1.0
   % in GI-BD); Leimkuhler-Matthews' shows no dt dependence in BD between
   1e-4 and 4e-4 (the --long run: +0.27, +0.24, +0.21 % +- 0.15 % at 1, 2,
   4 x 1e-4, and Euler extrapolates to the same +0.3 % at dt -> 0: the
   estimator's own offset, the force jump at the cut-off rcut = 2.5 that
   the Laplacian omits).  GI-BD with the exact sweep has BD's flat line
   since issue 40 (the BAOAB-like step of MODEL 13.2; before it a
   first-order rest of -0.2, -0.5, -1.0 % stayed, which this test now
   rejects: 0.1 of Euler's rise).  Blocks of equal simulated time. */
static void tconf_bd(hcbd_dynamics dyn, hcbd_brownian_integrator bi, double dt, double time, double *t, double *e)
{
    enum { N = 256, NB = 10 };
    hcbd_world_def d = scene(N, 0.24);
    hcbd_world w;
    double tb[NB];
    const int every = 10, per = (int)(time / dt / NB / every + 0.5);
    int b, s;
    *t = *e = 0;
    d.params.dynamics = dyn;
    d.params.brownian = bi;
    d.params.dt = dt;
    d.params.seed = 5;
    if (!make_world(&w, &d)) return;
    hcbd_world_place_lattice(&w, N);
    run(&w, (int)((t_quick ? 0.05 : 0.5) / dt));
    for (b = 0; b < NB; ++b) {
        double F2 = 0, lap = 0, out[2];
        for (s = 0; s < per; ++s) {
            if (!run(&w, every)) return;
            hcbd_world_config_temperature(&w, out);
            F2 += out[0];
            lap += out[1];
        }
        tb[b] = F2 / lap / d.params.kT;
    }
    block_stats(tb, NB, NB, t, e);
    hcbd_world_destroy(&w);
}

void test_bd_lm_statics(void)
{
    /* under the sanitizers (quick) only the code paths count: no checks */
    const double time = (t_quick ? 0.2 : 20.0) * t_len;
    double t[2][2][2], e[2][2][2];
    int dyn, bi, k;
    for (dyn = 0; dyn < 2; ++dyn)
        for (bi = 0; bi < 2; ++bi)
            for (k = 0; k < 2; ++k) {
                const double dt = k ? 4e-4 : 1e-4;
                tconf_bd(dyn ? HCBD_DYN_GIBD : HCBD_DYN_BD, bi ? HCBD_BROWNIAN_LM : HCBD_BROWNIAN_EULER, dt, time,
                         &t[dyn][bi][k], &e[dyn][bi][k]);
                NOTE("%s %s dt = %g: T_conf - 1 = %.5f +- %.5f", dyn ? "GI-BD" : "BD", bi ? "LM" : "Euler", dt,
                     t[dyn][bi][k] - 1, e[dyn][bi][k]);
            }
    if (t_quick) return;
    for (dyn = 0; dyn < 2; ++dyn) {
        const double de = t[dyn][0][1] - t[dyn][0][0], dl = t[dyn][1][1] - t[dyn][1][0];
        const double ee = hypot(e[dyn][0][1], e[dyn][0][0]), el = hypot(e[dyn][1][1], e[dyn][1][0]);
        const char *name = dyn ? "GI-BD" : "BD";
        /* Euler: first order, 3 x 1.0-1.2 % between 1e-4 and 4e-4 */
        CHECK(de > 0.02 && de > 5 * ee, "%s Euler: T_conf rises by %.4f +- %.4f from dt = 1e-4 to 4e-4, not the "
              "first-order 3 %%", name, de, ee);
        /* LM: within 1 % of kT at 1e-4 (the estimator's offset is 0.3 %) */
        CHECK(fabs(t[dyn][1][0] - 1) < 0.01 + 3 * e[dyn][1][0], "%s LM: T_conf - 1 = %.4f +- %.4f at dt = 1e-4",
              name, t[dyn][1][0] - 1, e[dyn][1][0]);
        /* no first-order term, in BD and GI-BD alike (a tenth of
           Euler's would show at 3 errors; the old GI-BD step's rest,
           0.8 % from 1e-4 to 4e-4, fails) */
        CHECK(fabs(dl) < 3 * el + 0.1 * de, "%s LM: T_conf moves by %.4f +- %.4f from dt = "
              "1e-4 to 4e-4 (Euler %.4f)", name, dl, el, de);
    }
}


/* GI-BD with the exact sweep in a harmonic well, at a large step: one
   dimer bound by U = k r^2/2 (a table potential, F = -k r, interpolated
   exactly), k = 100, dt = 1e-3 (k dt/xi = 0.1; tau = 3.6 dt).  The step of
   MODEL 13.2 (kick, half a drift, the sweep, half a drift, the
   Leimkuhler-Matthews Brownian step) samples a quadratic potential
   exactly at any dt, so T_conf = k <r^2>/3 (from the positions, here) and
   the background temperature m <v^2>/3 are kT within their errors; the
   order of the releases before issue 40 (sweep, kick, drift with the new
   v) reads T_conf 5.7 % low and T_kin 4.7 % high here, and an error of 10 %
   in the kick (dt/m), in the drift's mean or in the Brownian amplitude
   moves one of them by more than 1 %.  Errors from 20 blocks. */
void test_gibd_harmonic_exact(void)
{
    enum { NT = 1001, NB = 20 };
    static double tF[NT], tV[NT];
    const double k = 100.0, rc = 2.5;
    const int per = (int)(t_quick ? 2000 : 30000 * t_len), every = 10;
    double tc[NB], tk[NB], mc, ec, mk, ek;
    hcbd_world_def d = scene(2, 0.24);
    hcbd_world w;
    double xyz[6] = {4.0, 4.0, 4.0, 4.1, 4.05, 3.95};
    int i, b, s;
    for (i = 0; i < NT; ++i) {
        const double r = i * rc / (NT - 1);
        tF[i] = -k * r;
        tV[i] = 0.5 * k * r * r;
    }
    d.params.L[0] = d.params.L[1] = d.params.L[2] = 9.0;
    d.params.potential = HCBD_POT_TABLE;
    d.params.table_F = tF;
    d.params.table_V = tV;
    d.params.table_n = NT;
    d.params.table_r0 = 0.0;
    d.params.rcut = rc;
    d.params.dt = 1e-3;
    d.params.tau = 3.6e-3;
    d.params.seed = 17;
    if (!make_world(&w, &d)) return;
    hcbd_world_set_positions(&w, 2, xyz);
    run(&w, 2000);
    for (b = 0; b < NB; ++b) {
        double r2 = 0, t = 0;
        for (s = 0; s < per; ++s) {
            double x[6], dd[3];
            int c;
            if (!run(&w, every)) return;
            hcbd_world_get_positions(&w, x, 0);
            for (c = 0; c < 3; ++c) {
                dd[c] = x[c] - x[3 + c];
                dd[c] -= 9.0 * round(dd[c] / 9.0);
            }
            r2 += dd[0] * dd[0] + dd[1] * dd[1] + dd[2] * dd[2];
            t += hcbd_world_temperature(&w);
        }
        tc[b] = k * r2 / per / 3.0 / d.params.kT;
        tk[b] = t / per;
    }
    block_stats(tc, NB, NB, &mc, &ec);
    block_stats(tk, NB, NB, &mk, &ek);
    NOTE("dimer, k dt/xi = 0.1: T_conf - 1 = %.4f +- %.4f, T_kin - 1 = %.4f +- %.4f", mc - 1, ec, mk - 1, ek);
    hcbd_world_destroy(&w);
    if (t_quick) return;
    CHECK(fabs(mc - 1) < 4 * ec && ec < 0.004, "T_conf - 1 = %.4f +- %.4f", mc - 1, ec);
    CHECK(fabs(mk - 1) < 4 * ek && ek < 0.004, "T_kin - 1 = %.4f +- %.4f", mk - 1, ek);
}

/* Statics of the 2014 star scene at the library's defaults (tau = 3.6e-3,
   dt = 1e-4): the exact pairwise update (Shardlow) gives classical BD's
   g(r) and configurational temperature within errors, at the same dt
   (all three with the default Leimkuhler-Matthews displacement, see
   test_bd_lm_statics; with Euler-Maruyama BD itself is 1.5 % hot); the papers'
   Euler pair step is hotter by the static bias of its explicit coupling
   of R and v, 1.3 % +- 0.14 % in a long reference run (MODEL 12), and the
   run here must agree with that number.  The configurational temperature
   <sum |F_i|^2> / <sum lap_i U> is computed in the test from positions
   with the analytic derivatives of 2014 eq. 28, and compared once with
   hcbd_world_config_temperature. */
typedef struct {
    double g[50], gerr[50], tc, tcerr;
} gr_result;

static void star_derivs(double r, double *dv, double *lap)
{
    const double f = 128, A = 5.0 / 18 * pow(f, 1.5), B = 1 / (1 + sqrt(f) / 2), s = sqrt(f) / 2;
    if (r <= 1) {
        *dv = -A / r;
        *lap = -A / (r * r);
    } else {
        double e = A * B * exp(-s * (r - 1));
        *dv = -e * (1 / (r * r) + s / r);
        *lap = e * s * s / r;
    }
}

/* sum |F_i|^2 and sum lap_i U of N particles from positions */
static void tconf_terms(const double *xyz, int N, const double L[3], double *F2, double *lap)
{
    double *F = (double *)calloc(3 * (size_t)N, sizeof(double));
    int i, j, c;
    *F2 = *lap = 0;
    for (i = 0; i < N; ++i)
        for (j = i + 1; j < N; ++j) {
            double dx[3], r2 = pair_r2(xyz, i, j, L), r, dv, lp;
            if (r2 >= 2.5 * 2.5) continue;
            for (c = 0; c < 3; ++c) {
                dx[c] = xyz[3 * i + c] - xyz[3 * j + c];
                dx[c] -= L[c] * round(dx[c] / L[c]);
            }
            r = sqrt(r2);
            star_derivs(r, &dv, &lp);
            for (c = 0; c < 3; ++c) {
                F[3 * i + c] -= dv * dx[c] / r;
                F[3 * j + c] += dv * dx[c] / r;
            }
            *lap += 2 * lp;
        }
    for (i = 0; i < 3 * N; ++i) *F2 += F[i] * F[i];
    free(F);
}

enum { GR_BD, GR_SHARDLOW, GR_EULER, GR_BD2 };
static gr_result gr_run(int kind, int steps, double *api_vs_test)
{
    enum { N = 256, NB = 10 };
    hcbd_world_def d = scene(N, 0.24);
    hcbd_world w;
    gr_result res;
    double hist[50], xyz[3 * N], gb[NB][50], tb[NB];
    int b, s, k;
    hcbd_rdf rdf;
    memset(&res, 0, sizeof res);
    d.params.dynamics = kind == GR_BD || kind == GR_BD2 ? HCBD_DYN_BD : HCBD_DYN_GIBD;
    d.params.pair_integrator = kind == GR_SHARDLOW ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
    d.params.seed = kind == GR_BD2 ? 7 : 3;
    if (!make_world(&w, &d)) return res;
    hcbd_world_place_lattice(&w, N);
    run(&w, 5000);
    for (b = 0; b < NB; ++b) {
        double F2 = 0, lap = 0;
        hcbd_rdf_init(&rdf, 5.0, 50, 0, hist, sizeof hist); /* half the box: all-pairs path */
        for (s = 0; s < steps / NB / 100; ++s) {
            double f2, lp;
            if (!run(&w, 100)) return res;
            hcbd_rdf_sample(&rdf, &w);
            hcbd_world_get_positions(&w, xyz, 0);
            tconf_terms(xyz, N, w.p.L, &f2, &lp);
            F2 += f2;
            lap += lp;
            if (api_vs_test && b == 0 && s == 0) {
                double out[2];
                hcbd_world_config_temperature(&w, out);
                *api_vs_test = fmax(fabs(out[0] / f2 - 1), fabs(out[1] / lp - 1));
            }
        }
        hcbd_rdf_result(&rdf, NULL, gb[b], NULL);
        tb[b] = F2 / lap;
    }
    for (k = 0; k < 50; ++k) {
        double col[NB];
        for (b = 0; b < NB; ++b) col[b] = gb[b][k];
        block_stats(col, NB, NB, &res.g[k], &res.gerr[k]);
    }
    block_stats(tb, NB, NB, &res.tc, &res.tcerr);
    hcbd_world_destroy(&w);
    return res;
}

void test_statics_default_tau(void)
{
    const int steps = (int)((t_quick ? 10000 : 100000) * t_len);
    int k, nbins = 0;
    double chi2 = 0, chi2_0 = 0, api = 1, ds, es, de, ee;
    gr_result bd = gr_run(GR_BD, steps, NULL);
    gr_result sh = gr_run(GR_SHARDLOW, steps, &api);
    gr_result eu = gr_run(GR_EULER, steps, NULL);
    gr_result b2 = t_quick ? bd : gr_run(GR_BD2, steps, NULL);
    for (k = 0; k < 50; ++k) {
        double e2s = bd.gerr[k] * bd.gerr[k] + sh.gerr[k] * sh.gerr[k];
        double e20 = bd.gerr[k] * bd.gerr[k] + b2.gerr[k] * b2.gerr[k];
        if (bd.g[k] < 0.05 || e2s <= 0 || e20 <= 0) continue; /* empty core bins */
        chi2 += (bd.g[k] - sh.g[k]) * (bd.g[k] - sh.g[k]) / e2s;
        chi2_0 += (bd.g[k] - b2.g[k]) * (bd.g[k] - b2.g[k]) / e20;
        ++nbins;
    }
    ds = sh.tc - bd.tc;
    es = sqrt(sh.tcerr * sh.tcerr + bd.tcerr * bd.tcerr);
    de = eu.tc - bd.tc;
    ee = sqrt(eu.tcerr * eu.tcerr + bd.tcerr * bd.tcerr);
    NOTE("T_conf: BD %.4f +- %.4f, GI-BD Shardlow %.4f +- %.4f, GI-BD Euler %.4f +- %.4f (%d steps)",
         bd.tc, bd.tcerr, sh.tc, sh.tcerr, eu.tc, eu.tcerr, steps);
    NOTE("Shardlow - BD = %.4f +- %.4f; Euler - BD = %.4f +- %.4f (reference 0.013 +- 0.0014)", ds, es, de, ee);
    NOTE("g(r) Shardlow vs BD: chi2 = %.1f over %d bins; two BD runs: %.1f; hcbd_world_config_temperature "
         "vs the test's sums: %.1e", chi2, nbins, chi2_0, api);
    CHECK(api < 1e-9, "hcbd_world_config_temperature differs from 2014 eq. 28 evaluated here: %g", api);
    if (t_quick) return;
    /* Blocks of 4000 steps are not quite independent (two BD runs with
       different seeds give chi2 ~ 1.6 n, not n), so the chi2 is measured
       against that of two BD runs, which shares the flaw: their ratio is
       F-distributed with (n, n) degrees of freedom, 2.7 its 0.1 % point
       at n = 37. */
    CHECK(chi2 < 2.7 * chi2_0, "g(r) differs: chi2 %g over %d bins, two BD runs %g", chi2, nbins, chi2_0);
    CHECK(fabs(ds) < 4 * es, "Shardlow T_conf differs from BD's: %g +- %g", ds, es);
    CHECK(fabs(de - 0.013) < 4 * sqrt(ee * ee + 0.0014 * 0.0014), "Euler excess %g +- %g, reference 0.013",
          de, ee);
    /* at make-test length the Euler excess is a 2-sigma effect; make
       validate (100000 steps) resolves it */
    CHECK(es < 0.006 / sqrt(t_len) && ee < 0.006 / sqrt(t_len), "errors %g %g too large", es, ee);
    if (t_len >= 1) CHECK(de > 3 * ee && de - ds > 3 * sqrt(ee * ee + es * es), "Euler excess not resolved");
}
