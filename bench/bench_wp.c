/* bench_wp: work-precision of GI-BD and the walled channel.  For each
   time step tau/dt = 2.5, 5, 10, 20, 40, 80 at fixed tau, each pair
   integrator (Euler, the papers; Shardlow, exact pairwise OU) and pair
   noise (Gaussian, uniform), the cost (wall seconds of hcbd_world_step per unit
   of simulated time, one thread) against the error from theory (MODEL 10):

   gibd temperature   |T/kT - 1| of the background velocities, 1000 ideal
                      carriers, n# = 0.24, tau = 1e-2 (tests/test_physics.c
                      test_equipartition_*); error_err its block error.
   gibd nu            |nu_initial / (nu_meanfield / (1 - S(k)/N)) - 1|, the
                      initial decay of the transverse current of 54 ideal
                      carriers, L = 6, k = 2 (2 pi / L) against the friction
                      average of the same run (test_transverse_current_
                      initial_decay); Gaussian noise only (the noise law
                      does not enter a second moment).
   walled channel_l2  relative L2 distance of the slab profile v_x(y) (26
                      slabs, centres inside the channel) of 406 ideal
                      carriers in the no-slip channel (13^3, walls 1.5,
                      tau = 2e-3, xi' = 1.5 as tests/test_walls.c; g = 400
                      for signal over thermal noise), tau/dt <= 20, from the
                      Newtonian parabola of hcbd_params_theory (mean-field
                      nu = Rc^2/(28 tau), v_max, width).  The measured
                      viscosity of ideal carriers is below mean field
                      (MODEL 10), so this error is mostly a model offset.
   walled channel_shape  relative L2 distance from the best no-slip
                      parabola A (y - lo)(hi - y) (amplitude fitted): what
                      the time step does to the shape, with the noise floor
                      of the slab errors as error_err.

   Temperature: tau/dt up to 40 (80 for Euler, which needs it for 1 %),
   1.5 time units per point; nu: 25 time units in 10 blocks.  The float
   build runs Gaussian noise only.  The double build writes <out>/wp.csv, the float build (-DHCBD_REAL=float)
   <out>/wp_float.csv; columns model,metric,integrator,precision,noise,dt,h,
   substeps,seconds_per_time_unit,error,error_err,config.  It prints per
   model the cheapest configuration reaching 1 % and checks the Shardlow
   targets (temperature error < 0.5 % at tau = 10 dt; Euler's error reached
   at >= 3x Euler's time step).

   usage: bench_wp [quick=0|1] [out=out/bench] [time=1] [seed=1]
          time scales all simulated times (quick=1: ~30 s smoke run) */
#include "bench_common.h"
#include "../tests/scenes.h"

#define PI 3.14159265358979323846
#define MAXPT 256

typedef struct {
    const char *model, *metric;
    int integ, noise;
    double dt, spt, err, err_err, ratio; /* ratio = tau/dt */
    char config[64];
} point;

static point pts[MAXPT];
static int npts;
static double step_seconds;
static double tscale = 1.0;
static int quick;
static unsigned long long seed0 = 1;
static const char *prec;
static double equil_arg = -1;
static int only = 0; /* 1 temperature, 2 nu, 3 channel; 0 all */

/* hcbd_world_step, timed: only the stepping counts as cost */
static int step(hcbd_world *w, int n)
{
    double t0 = now();
    hcbd_result r = hcbd_world_step(w, n);
    step_seconds += now() - t0;
    if (r != HCBD_OK) {
        printf("    (failed: %s)\n", w->err.msg);
        return 0;
    }
    return 1;
}

static point *add_point(const char *model, const char *metric, const hcbd_params *p, double ratio,
                        double sim_time, double err, double err_err)
{
    point *q = &pts[npts < MAXPT ? npts++ : MAXPT - 1];
    q->model = model;
    q->metric = metric;
    q->integ = p->pair_integrator;
    q->noise = p->noise;
    q->dt = p->dt;
    q->ratio = ratio;
    q->spt = step_seconds / sim_time;
    q->err = err;
    q->err_err = err_err;
    snprintf(q->config, sizeof q->config, "%s %s %s tau/dt=%g",
             p->pair_integrator == HCBD_PAIR_SHARDLOW ? "shardlow" : "euler", prec,
             p->noise == HCBD_NOISE_UNIFORM ? "uniform" : "gauss", ratio);
    printf("%-7s %-14s %-30s dt %-9.3g %10.4g s/time  error %.5f +- %.5f\n", model, metric, q->config,
           p->dt, q->spt, err, err_err);
    fflush(stdout);
    return q;
}

static hcbd_params base(double density, int n, hcbd_pair_integrator integ, hcbd_noise noise, double tau,
                        double ratio)
{
    hcbd_params p = hcbd_params_default();
    double L = cbrt(n / density);
    p.L[0] = p.L[1] = p.L[2] = L;
    p.density = density;
    p.potential = HCBD_POT_IDEAL;
    p.pair_integrator = integ;
    p.noise = noise;
    p.tau = tau;
    p.dt = tau / ratio;
    p.threads = 1;
    p.seed = seed0;
    return p;
}

static int make(hcbd_world *w, hcbd_params p, int cap)
{
    hcbd_world_def d = hcbd_world_def_default();
    d.capacity = cap;
    d.params = p;
    if (hcbd_world_create(w, &d) != HCBD_OK) {
        printf("    (world: %s)\n", w->err.msg);
        return 0;
    }
    return 1;
}

/* --- GI-BD background temperature (test_equipartition_*) ---------------*/
static void temperature_point(hcbd_pair_integrator integ, hcbd_noise noise, double ratio, double sim)
{
    hcbd_params p = base(0.24, 1000, integ, noise, 1e-2, ratio);
    hcbd_world w;
    int every, nsamp, k, ok = 1;
    double *T, mean, err;
    p.skin = 1.2; /* Brownian steps of 0.08: a thin skin rebuilds every step */
    every = (int)(0.4 * ratio + 0.5);
    if (every < 1) every = 1;
    nsamp = (int)(sim / (every * p.dt) + 0.5) / 20 * 20;
    if (nsamp < 40) nsamp = 40;
    if (!make(&w, p, 1000)) return;
    hcbd_world_place_random(&w, 1000);
    T = (double *)malloc(nsamp * sizeof(double));
    step_seconds = 0;
    ok = step(&w, 20 * every);
    for (k = 0; ok && k < nsamp; ++k) {
        ok = step(&w, every);
        T[k] = hcbd_world_temperature(&w);
    }
    if (ok) {
        block_stats(T, nsamp, 20, &mean, &err);
        add_point("gibd", "temperature", &p, ratio, (20.0 + nsamp) * every * p.dt, fabs(mean - 1), err);
    }
    free(T);
    hcbd_world_destroy(&w);
}

/* --- GI-BD nu from the initial decay of the transverse current ---------*/
/* as test_physics.c measures it (initial_rate, gibd_mode_sample) */
static void nu_point(hcbd_pair_integrator integ, hcbd_noise noise, double ratio, double sim)
{
    enum { P = 64, NB = 10, N = 54, NK = 2 };
    hcbd_params p = base(0.25, N, integ, noise, 1e-2, ratio);
    hcbd_world w;
    hcbd_mtcorr c;
    size_t bytes = hcbd_mtcorr_bytes(12, P, 2, 1);
    void *mem = malloc(bytes);
    double xyz[3 * N], k, rates[NB], mf = 0, sk = 0, nu, nu_err, target;
    int b, s, nmf = 0, ok = 1, block_steps, sample_every;
    p.L[0] = p.L[1] = p.L[2] = 6.0;
    block_steps = (int)(sim / NB / p.dt + 0.5);
    sample_every = (int)(0.5 * ratio + 0.5); /* friction average and S(k) every tau/2 */
    if (sample_every < 1) sample_every = 1;
    if (!make(&w, p, N)) {
        free(mem);
        return;
    }
    hcbd_world_place_random(&w, N);
    k = 2 * PI * NK / p.L[0];
    step_seconds = 0;
    ok = step(&w, (int)(0.5 / p.dt)); /* 50 tau */
    for (b = 0; ok && b < NB; ++b) {
        double lag[P], corr[P];
        int got;
        hcbd_mtcorr_init(&c, 12, P, 2, 1, mem, bytes);
        for (s = 0; ok && s < block_steps; ++s) {
            double j[12];
            hcbd_world_transverse_current(&w, NK, j);
            hcbd_mtcorr_add(&c, j);
            if (s % sample_every == 0) {
                gibd_mode_sample(&w, NK, xyz, &mf, &sk);
                ++nmf;
            }
            ok = step(&w, 1);
        }
        hcbd_mtcorr_finalize(&c);
        got = hcbd_mtcorr_result(&c, 1, lag, corr, NULL, P);
        rates[b] = got > 1 ? initial_rate(corr, got, p.dt) / (k * k) - p.kT / p.xi : 0;
    }
    if (ok) {
        block_stats(rates, NB, NB, &nu, &nu_err);
        mf /= nmf;
        target = mf / (1 - sk / nmf / N);
        add_point("gibd", "nu", &p, ratio, 0.5 + (double)NB * block_steps * p.dt, fabs(nu / target - 1),
                  nu_err / target);
    }
    free(mem);
    hcbd_world_destroy(&w);
}

/* --- walled channel ----------------------------------------------------*/
#if HCBD_MODEL == HCBD_MODEL_WALLED
enum { NSLAB = 26 };

static void channel_point(hcbd_pair_integrator integ, hcbd_noise noise, double ratio, double sim)
{
    hcbd_params p = base(0.24, 406, integ, noise, 2e-3, ratio);
    hcbd_theory th;
    hcbd_world w;
    hcbd_profile pr;
    static double mem[NSLAB * 16];
    const double equil = equil_arg > 0 ? equil_arg : quick ? 0.15 : 0.4;
    double out[NSLAB * 8], lo, hi, yc, sw = 0, swx = 0, sxx = 0, d2 = 0, n2 = 0, e2 = 0, s2 = 0, A;
    int s, nsamp, every, ok;
    const double grav = 400.0;
    double *v, *xyz, nu_eff;
    int i;
    p.L[0] = p.L[1] = p.L[2] = 13.0;
    p.wall.thickness = 1.5;
    p.wall.mode = HCBD_WALL_NOSLIP;
    p.wall.beta_max = 5.0;
    p.xip = 1.5;
    p.fext[0] = grav * p.xip * p.tau;
    hcbd_params_theory(&p, &th);
    if (!make(&w, p, 406)) return;
    hcbd_world_place_lattice(&w, 406);
    /* start near the developed flow (a parabola with 0.8 of the mean-field
       viscosity: the measured one lies between ~0.68 of it, MODEL 10, and
       1) on top of the thermal velocities; the rest relaxes at
       pi^2 nu / W^2 ~ 5-10 per unit time during `equil` */
    nu_eff = 0.8 * th.nu;
    v = (double *)malloc(2 * 3 * 406 * sizeof(double));
    xyz = v + 3 * 406;
    hcbd_world_get_velocities(&w, v);
    hcbd_world_get_positions(&w, xyz, 0);
    for (i = 0; i < 406; ++i) {
        double y = xyz[3 * i + 1];
        if (y > p.wall.thickness && y < p.L[1] - p.wall.thickness)
            v[3 * i] += grav / (2 * nu_eff) * (y - p.wall.thickness) * (p.L[1] - p.wall.thickness - y);
    }
    hcbd_world_set_velocities(&w, v);
    free(v);
    every = (int)(0.002 / p.dt + 0.5); /* samples every ~2e-3 */
    if (every < 1) every = 1;
    nsamp = (int)(sim / (every * p.dt)) / 20 * 20;
    if (nsamp < 40) nsamp = 40;
    if (hcbd_profile_init(&pr, &w, NSLAB, nsamp / 20, mem, sizeof mem) != HCBD_OK) {
        printf("    (profile: %s)\n", w.err.msg);
        hcbd_world_destroy(&w);
        return;
    }
    step_seconds = 0;
    ok = step(&w, (int)(equil / p.dt + 0.5));
    for (s = 0; ok && s < nsamp; ++s) {
        ok = step(&w, every);
        hcbd_profile_sample(&pr, &w);
    }
    if (!ok) {
        hcbd_world_destroy(&w);
        return;
    }
    hcbd_profile_result(&pr, out);
    lo = p.wall.thickness;
    hi = p.L[1] - p.wall.thickness;
    yc = 0.5 * (lo + hi);
    /* slabs whose centres lie in the channel; weighted fit of A q(y) */
    for (s = 0; s < NSLAB; ++s) {
        double y = out[8 * s], q = (y - lo) * (hi - y), e = out[8 * s + 4], wt;
        if (y <= lo || y >= hi) continue;
        wt = e > 0 ? 1 / (e * e) : 1;
        sw += wt * q * out[8 * s + 3];
        sxx += wt * q * q;
    }
    A = sxx > 0 ? sw / sxx : 0;
    for (s = 0; s < NSLAB; ++s) {
        double y = out[8 * s], v = out[8 * s + 3], u = (y - yc) / (0.5 * th.width);
        double vth = th.v_max * (1 - u * u), vfit = A * (y - lo) * (hi - y);
        if (y <= lo || y >= hi) continue;
        d2 += (v - vth) * (v - vth);
        n2 += vth * vth;
        s2 += (v - vfit) * (v - vfit);
        swx += vfit * vfit;
        e2 += out[8 * s + 4] * out[8 * s + 4];
    }
    add_point("walled", "channel_l2", &p, ratio, equil + (double)nsamp * every * p.dt, sqrt(d2 / n2),
              sqrt(e2 / n2));
    add_point("walled", "channel_shape", &p, ratio, equil + (double)nsamp * every * p.dt,
              sqrt(s2 / swx), sqrt(e2 / swx));
    printf("        v_max fit %.3f, mean-field theory %.3f (ratio %.3f)\n", A * 0.25 * th.width * th.width,
           th.v_max, A * 0.25 * th.width * th.width / th.v_max);
    hcbd_world_destroy(&w);
}
#endif

/* --- summary -----------------------------------------------------------*/
static void cheapest(const char *model, const char *metric)
{
    const point *best = NULL;
    int k;
    for (k = 0; k < npts; ++k) {
        const point *q = &pts[k];
        if (strcmp(q->model, model) || (metric && strcmp(q->metric, metric))) continue;
        if (q->err + q->err_err < 0.01 && (!best || q->spt < best->spt)) best = q;
    }
    if (best)
        printf("cheapest <1%%: model=%s, metric=%s, config=%s, cost=%.4g s/time (error %.4f +- %.4f)\n", model,
               best->metric, best->config, best->spt, best->err, best->err_err);
    else printf("cheapest <1%%: model=%s, metric=%s, none of this build's points reaches 1 %%\n", model,
                metric ? metric : "any");
}

static const point *find(const char *metric, int integ, int noise, double ratio)
{
    int k;
    for (k = 0; k < npts; ++k)
        if (!strcmp(pts[k].metric, metric) && pts[k].integ == integ && pts[k].noise == noise &&
            fabs(pts[k].ratio - ratio) < 1e-9)
            return &pts[k];
    return NULL;
}

static void shardlow_targets(const double *ratios, int nr)
{
    const point *s10 = find("temperature", HCBD_PAIR_SHARDLOW, HCBD_NOISE_GAUSS, 10);
    const point *e10 = find("temperature", HCBD_PAIR_EULER, HCBD_NOISE_GAUSS, 10);
    int k, j;
    if (s10 && e10)
        printf("target: Shardlow temperature error at tau = 10 dt %.4f +- %.4f (< 0.005: %s), Euler %.4f +- %.4f\n",
               s10->err, s10->err_err, s10->err < 0.005 ? "MET" : "MISSED", e10->err, e10->err_err);
    /* for each Euler point: the largest Shardlow dt with error no larger */
    for (k = 0; k < nr; ++k) {
        const point *e = find("temperature", HCBD_PAIR_EULER, HCBD_NOISE_GAUSS, ratios[k]), *sbest = NULL;
        if (!e) continue;
        for (j = 0; j < nr; ++j) {
            const point *s = find("temperature", HCBD_PAIR_SHARDLOW, HCBD_NOISE_GAUSS, ratios[j]);
            if (s && s->err <= e->err && (!sbest || s->dt > sbest->dt)) sbest = s;
        }
        if (sbest)
            printf("target: Euler tau/dt=%-4g error %.4f; Shardlow reaches it at tau/dt=%g: %.3gx the time "
                   "step (>= 3: %s), %.3gx the cost\n", e->ratio, e->err, sbest->ratio, sbest->dt / e->dt,
                   sbest->dt / e->dt >= 3 ? "MET" : "MISSED", sbest->spt / e->spt);
        else
            printf("target: Euler tau/dt=%-4g error %.4f; no Shardlow point as good\n", e->ratio, e->err);
    }
}

int main(int argc, char **argv)
{
    static const double ratios_full[6] = {2.5, 5, 10, 20, 40, 80}, ratios_quick[3] = {2.5, 10, 20};
    const double *ratios;
    char out[512] = "out/bench", path[600];
    int nr, k, ii, nn, r, nnoise;
    double t_start = now();
    FILE *csv;
    prec = sizeof(hcbd_real) == sizeof(float) ? "float" : "double";
    for (k = 1; k < argc; ++k) {
        if (!strncmp(argv[k], "quick=", 6)) quick = atoi(argv[k] + 6);
        else if (!strncmp(argv[k], "out=", 4)) snprintf(out, sizeof out, "%s", argv[k] + 4);
        else if (!strncmp(argv[k], "time=", 5)) tscale = atof(argv[k] + 5);
        else if (!strncmp(argv[k], "equil=", 6)) equil_arg = atof(argv[k] + 6);
        else if (!strncmp(argv[k], "only=", 5)) only = atoi(argv[k] + 5);
        else if (!strncmp(argv[k], "seed=", 5)) seed0 = strtoull(argv[k] + 5, NULL, 10);
        else {
            fprintf(stderr, "bench_wp: unknown argument '%s' (quick=, out=, time=, seed=, equil=, only=)\n", argv[k]);
            return 2;
        }
    }
    if (quick) tscale *= 0.15;
    ratios = quick ? ratios_quick : ratios_full;
    nr = quick ? 3 : 6;
    printf("bench_wp: %s build, %s, one thread, cost = hcbd_world_step seconds per unit simulated time%s\n", prec,
           HCBD_MODEL == HCBD_MODEL_WALLED ? "GI-BD and walled channel" : "GI-BD only", quick ? " (quick)" : "");
    fflush(stdout);
    /* the float build compares precision on Gaussian noise only */
    nnoise = sizeof(hcbd_real) == sizeof(float) ? 1 : 2;
    for (ii = 0; ii < 2 && (!only || only == 1); ++ii)
        for (nn = 0; nn < nnoise; ++nn)
            for (r = 0; r < nr; ++r)
                if (ratios[r] <= 40 || ii == HCBD_PAIR_EULER) /* Euler needs 80 to reach 1 % */
                    temperature_point((hcbd_pair_integrator)ii, (hcbd_noise)nn, ratios[r], 1.5 * tscale);
    for (ii = 0; ii < 2 && (!only || only == 2); ++ii)
        for (r = 0; r < nr; ++r)
            nu_point((hcbd_pair_integrator)ii, HCBD_NOISE_GAUSS, ratios[r], 25.0 * tscale);
#if HCBD_MODEL == HCBD_MODEL_WALLED
    for (ii = 0; ii < 2 && (!only || only == 3); ++ii)
        for (nn = 0; nn < nnoise; ++nn)
            for (r = 0; r < nr && ratios[r] <= 20; ++r)
                channel_point((hcbd_pair_integrator)ii, (hcbd_noise)nn, ratios[r], 1.0 * tscale);
#endif
    csv = bench_csv("bench_wp", out, sizeof(hcbd_real) == sizeof(float) ? "wp_float.csv" : "wp.csv", path,
                    sizeof path);
    if (!csv) return 1;
    fprintf(csv, "model,metric,integrator,precision,noise,dt,h,substeps,seconds_per_time_unit,error,error_err,config\n");
    for (k = 0; k < npts; ++k) {
        const point *q = &pts[k];
        fprintf(csv, "%s,%s,%s,%s,%s,%.6g,,1,%.6g,%.6g,%.6g,%s\n", q->model, q->metric,
                q->integ == HCBD_PAIR_SHARDLOW ? "shardlow" : "euler", prec,
                q->noise == HCBD_NOISE_UNIFORM ? "uniform" : "gauss", q->dt, q->spt, q->err, q->err_err,
                q->config);
    }
    fclose(csv);
    shardlow_targets(ratios, nr);
    cheapest("gibd", "temperature");
    cheapest("gibd", "nu");
#if HCBD_MODEL == HCBD_MODEL_WALLED
    cheapest("walled", "channel_l2");
    cheapest("walled", "channel_shape");
#endif
    printf("wrote %s (%d points, %.1f s)\n", path, npts, now() - t_start);
    return 0;
}
