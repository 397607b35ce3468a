/* bench/stability: where runs really fail, against the limits that
   hcbd_params_stability / hcbd_hc_params_stability predict.

   For each scene the time step is scanned upward, doubling from a quarter
   of the predicted bound until a step returns an error code, and the
   bracket [last pass, first fail] is then halved twice in log dt (to a
   factor 2^(1/4) = 1.19).  Every trial starts from the lattice and runs a
   fixed number of steps; the background (GI-BD) or fluid (HCBD) kinetic
   temperature is averaged over the second half.  Two boundaries come out:

     dt_fail  the smallest dt whose run was stopped by a result code, with
              the code (HCBD_ERR_UNSTABLE: a guard fired, HCBD_ERR_PARAM:
              the parameter check refused it, HCBD_ERR_NONFINITE: the
              state blew up first);
     dt_T10   the dt where |T/kT - 1| passes 10 % (linear interpolation in
              dt between the bracketing trials; halved while the bracket
              is wider than 1.5).

   The predicted bound of each limit is the dt where its margin reaches 1
   (found by bisection on hcbd_params_stability with the scene's dt dependence,
   tau = 36 dt included); the binding limit is the one with the smallest
   bound among those guarded by a result code ("accuracy" and "speed"
   limits are compared with dt_T10 instead).

   Walled build (HCBD_MODEL_WALLED): GI-BD star polymers (2014/2016 scene,
   N = 512) over f and xi, Euler and Shardlow pair integrators with
   tau = 36 dt; ideal GI-BD carriers at fixed tau over tau/dt.
   HCBD build: the 2018 pure fluid of Table I (806 blobs, 33.75 x 10 x 10)
   with fluctuations over eta and P0 (viscous and acoustic limits), Euler
   and Shardlow, 1 and 2 fluid substeps.

   usage: bench_stability [steps=N] [quick=1] [threads=1] [out=out/bench]
   Writes out/stability.csv (walled) or out/stability_hcbd.csv (HCBD). */
#include "bench_common.h"

#define MAXT 32

typedef struct scene {
    const char *name;
    char param[64];
    int shardlow, substeps, steps, n;
    double tau_over_dt; /* > 0: tau = tau_over_dt * dt (GI-BD) */
    double dt0_factor;  /* first dt = dt0_factor * predicted bound */
    double dtmax_factor;
#if HCBD_MODEL == HCBD_MODEL_HCBD
    hcbd_hc_world_def d;
#else
    hcbd_world_def d;
#endif
} scene;

typedef struct trial {
    double dt, terr;
    hcbd_result code;
    long long step;
} trial;

typedef struct result {
    trial t[MAXT];
    int nt;
    const char *bind, *acc;
    double pred, acc_pred, dt_fail, dt_t10, secs;
    int t10_below; /* the first trial already had |T/kT - 1| > 0.1 */
    hcbd_result fail_code;
    int n_unstable, n_nonfinite, n_param, n_capacity, n_other;
    char limits[512];
} result;

static int threads = 1, steps_override = 0;

/* ----------------------------------------------------------- model halves */
#if HCBD_MODEL == HCBD_MODEL_HCBD
static hcbd_hc_params params_at(const scene *s, double dt)
{
    hcbd_hc_params p = s->d.params;
    p.dt = dt;
    p.substeps = s->substeps;
    p.pair_integrator = s->shardlow ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
    p.threads = threads;
    return p;
}

static hcbd_result limits_at(const scene *s, double dt, hcbd_limit *l, int *n)
{
    hcbd_hc_params p = params_at(s, dt);
    return hcbd_hc_params_stability(&p, l, n);
}

/* The lattice of 806 blobs has vacancies that relax slowly, heating the
   fluid for thousands of microseconds: every trial of a scene starts from
   one state equilibrated with the Shardlow sweep (no viscous limit, no
   temperature bias) for 300 steps of min(4 dt_visc, 2 dt_sound). */
#define NCACHE 8
static struct {
    double eta, P0;
    int n;
    double *xyz, *v;
} cache[NCACHE];
static int ncache;

static const double *equilibrated(const scene *s, const double **v)
{
    hcbd_hc_world_def d = s->d;
    hcbd_hc_world w;
    hcbd_hc_theory th;
    int k, i;
    for (k = 0; k < ncache; ++k)
        if (cache[k].eta == d.params.eta && cache[k].P0 == d.params.P0 && cache[k].n == s->n) {
            *v = cache[k].v;
            return cache[k].xyz;
        }
    if (ncache == NCACHE) return *v = NULL, NULL;
    hcbd_hc_params_theory(&d.params, &th);
    d.params.dt = 4 * th.dt_visc < 2 * th.dt_sound ? 4 * th.dt_visc : 2 * th.dt_sound;
    d.params.pair_integrator = HCBD_PAIR_SHARDLOW;
    d.params.substeps = 1;
    d.params.threads = threads;
    if (hcbd_hc_world_create(&w, &d) != HCBD_OK || hcbd_hc_world_place_fluid_lattice(&w, s->n) != HCBD_OK ||
        hcbd_hc_world_step(&w, 300) != HCBD_OK) {
        fprintf(stderr, "bench_stability: equilibration failed: %s\n", w.err.msg);
        hcbd_hc_world_destroy(&w);
        return *v = NULL, NULL;
    }
    k = ncache++;
    cache[k].eta = d.params.eta;
    cache[k].P0 = d.params.P0;
    cache[k].n = s->n;
    cache[k].xyz = (double *)malloc(6 * sizeof(double) * (size_t)s->n);
    if (!cache[k].xyz) exit(1);
    cache[k].v = cache[k].xyz + 3 * s->n;
    for (i = 0; i < s->n; ++i) {
        cache[k].xyz[3 * i] = w.fx[i];
        cache[k].xyz[3 * i + 1] = w.fy[i];
        cache[k].xyz[3 * i + 2] = w.fz[i];
        cache[k].v[3 * i] = w.fvx[i];
        cache[k].v[3 * i + 1] = w.fvy[i];
        cache[k].v[3 * i + 2] = w.fvz[i];
    }
    hcbd_hc_world_destroy(&w);
    *v = cache[k].v;
    return cache[k].xyz;
}

static void run_trial(const scene *s, double dt, trial *t)
{
    hcbd_hc_world_def d = s->d;
    hcbd_hc_world w;
    double tsum = 0;
    int k, ns = 0, chunk = 5;
    const double *v = NULL, *xyz = equilibrated(s, &v);
    d.params = params_at(s, dt);
    t->dt = dt;
    t->terr = NAN;
    t->step = 0;
    t->code = hcbd_hc_world_create(&w, &d);
    if (t->code == HCBD_OK)
        t->code = xyz ? hcbd_hc_world_set_fluid(&w, s->n, xyz, v) : hcbd_hc_world_place_fluid_lattice(&w, s->n);
    for (k = 0; t->code == HCBD_OK && k < s->steps; k += chunk) {
        t->code = hcbd_hc_world_step(&w, chunk);
        if (t->code == HCBD_OK && k >= s->steps / 2) {
            tsum += hcbd_hc_world_temperature(&w);
            ++ns;
        }
    }
    t->step = (long long)w.step;
    if (t->code == HCBD_OK && ns) t->terr = tsum / ns / d.params.kT - 1.0;
    hcbd_hc_world_destroy(&w);
}
#else
static hcbd_params params_at(const scene *s, double dt)
{
    hcbd_params p = s->d.params;
    p.dt = dt;
    if (s->tau_over_dt > 0) p.tau = s->tau_over_dt * dt;
    p.pair_integrator = s->shardlow ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
    p.threads = threads;
    return p;
}

static hcbd_result limits_at(const scene *s, double dt, hcbd_limit *l, int *n)
{
    hcbd_params p = params_at(s, dt);
    return hcbd_params_stability(&p, l, n);
}

static void run_trial(const scene *s, double dt, trial *t)
{
    hcbd_world_def d = s->d;
    hcbd_world w;
    double tsum = 0;
    int k, ns = 0, chunk = 5;
    d.params = params_at(s, dt);
    d.capacity = s->n;
    t->dt = dt;
    t->terr = NAN;
    t->step = 0;
    t->code = hcbd_world_create(&w, &d);
    if (t->code == HCBD_OK) t->code = hcbd_world_place_lattice(&w, s->n);
    for (k = 0; t->code == HCBD_OK && k < s->steps; k += chunk) {
        t->code = hcbd_world_step(&w, chunk);
        if (t->code == HCBD_OK && k >= s->steps / 2) {
            tsum += hcbd_world_temperature(&w);
            ++ns;
        }
    }
    t->step = (long long)w.step;
    if (t->code == HCBD_OK && ns) t->terr = tsum / ns / d.params.kT - 1.0;
    hcbd_world_destroy(&w);
}
#endif

/* ------------------------------------------------------------ predictions */
static int guarded(const char *guard)
{
    return strncmp(guard, "accuracy", 8) != 0 && strncmp(guard, "speed", 5) != 0;
}

/* Margin of the limit called name at dt; 0 where the parameters are
   refused (beyond a checked limit), -1 where the limit is absent. */
static double margin_at(const scene *s, const char *name, double dt)
{
    hcbd_limit l[HCBD_MAX_LIMITS];
    int n = 0, k;
    if (limits_at(s, dt, l, &n) != HCBD_OK) return 0;
    for (k = 0; k < n; ++k)
        if (!strcmp(l[k].name, name)) return l[k].margin;
    return -1;
}

/* The dt where the margin of limit name falls to 1; HUGE_VAL if it does
   not depend on dt. */
static double bound_of(const scene *s, const char *name, double ref)
{
    double lo = ref, hi = ref, m1 = margin_at(s, name, ref), m2 = margin_at(s, name, 4 * ref);
    int k;
    if (m1 > 0 && fabs(m1 - m2) <= 1e-9 * m1) return HUGE_VAL;
    for (k = 0; k < 200 && margin_at(s, name, lo) < 1; ++k) lo *= 0.5;
    for (k = 0; k < 200 && margin_at(s, name, hi) >= 1; ++k) hi *= 2;
    for (k = 0; k < 60; ++k) {
        double mid = sqrt(lo * hi);
        if (margin_at(s, name, mid) >= 1) lo = mid;
        else hi = mid;
    }
    return sqrt(lo * hi);
}

static void predict(const scene *s, result *r)
{
    hcbd_limit l[HCBD_MAX_LIMITS];
    int n = 0, k;
    size_t len = 0;
    const double ref = s->d.params.dt;
    r->pred = r->acc_pred = HUGE_VAL;
    r->bind = r->acc = "none";
    r->limits[0] = 0;
    if (limits_at(s, ref, l, &n) != HCBD_OK) return;
    for (k = 0; k < n; ++k) {
        double b = bound_of(s, l[k].name, ref);
        int c;
        if (guarded(l[k].guard)) {
            if (b < r->pred) { r->pred = b; r->bind = l[k].name; }
        } else if (!strncmp(l[k].guard, "accuracy", 8) && b < r->acc_pred) {
            r->acc_pred = b;
            r->acc = l[k].name;
        }
        c = snprintf(r->limits + len, sizeof r->limits - len, "%s%s [%s] = %.3g", k ? " | " : "",
                     l[k].name, l[k].guard, b);
        if (c > 0 && len + (size_t)c < sizeof r->limits) len += (size_t)c;
    }
}

/* ------------------------------------------------------------------- scan */
static int fails(const trial *t) { return t->code != HCBD_OK; }
static int t_bad(const trial *t) { return fails(t) || !(fabs(t->terr) <= 0.1); }

static int by_dt(const void *a, const void *b)
{
    const double x = ((const trial *)a)->dt, y = ((const trial *)b)->dt;
    return (x > y) - (x < y);
}

static void add_trial(const scene *s, result *r, double dt)
{
    trial *t = r->t + r->nt++;
    run_trial(s, dt, t);
    qsort(r->t, (size_t)r->nt, sizeof *r->t, by_dt);
}

/* First trial (sorted by dt) with pred true; -1 if none. */
static int first(const result *r, int (*pred)(const trial *))
{
    int k;
    for (k = 0; k < r->nt; ++k)
        if (pred(r->t + k)) return k;
    return -1;
}

static void scan(const scene *s, result *r)
{
    double dt, t0 = now();
    int k, f, b;
    memset(r, 0, sizeof *r);
    predict(s, r);
    dt = s->dt0_factor * (r->pred < HUGE_VAL ? r->pred : s->d.params.dt);
    for (;;) {
        add_trial(s, r, dt);
        if (first(r, fails) >= 0 || dt >= s->dtmax_factor * r->pred || r->nt >= MAXT / 2) break;
        dt *= 2;
    }
    /* halve the fail bracket twice */
    for (k = 0; k < 2 && (f = first(r, fails)) > 0 && r->nt < MAXT; ++k)
        add_trial(s, r, sqrt(r->t[f - 1].dt * r->t[f].dt));
    /* the first trial already too hot: go down (twice at most) */
    for (k = 0; k < 2 && first(r, t_bad) == 0 && !fails(r->t) && r->nt < MAXT; ++k)
        add_trial(s, r, 0.5 * r->t[0].dt);
    /* halve the temperature bracket while wider than 1.5 */
    while ((b = first(r, t_bad)) > 0 && r->t[b].dt > 1.5 * r->t[b - 1].dt && r->nt < MAXT)
        add_trial(s, r, sqrt(r->t[b - 1].dt * r->t[b].dt));
    f = first(r, fails);
    r->dt_fail = f >= 0 ? r->t[f].dt : NAN;
    r->fail_code = f >= 0 ? r->t[f].code : HCBD_OK;
    b = first(r, t_bad);
    r->dt_t10 = NAN;
    if (b == 0) {
        r->dt_t10 = r->t[0].dt;
        r->t10_below = 1;
    } else if (b > 0) {
        const trial *lo = r->t + b - 1, *hi = r->t + b;
        if (!fails(hi) && isfinite(hi->terr) && fabs(hi->terr) > fabs(lo->terr))
            r->dt_t10 = lo->dt + (0.1 - fabs(lo->terr)) / (fabs(hi->terr) - fabs(lo->terr)) *
                                     (hi->dt - lo->dt);
        else r->dt_t10 = sqrt(lo->dt * hi->dt);
    }
    for (k = 0; k < r->nt; ++k) {
        switch (r->t[k].code) {
        case HCBD_OK: break;
        case HCBD_ERR_UNSTABLE: r->n_unstable++; break;
        case HCBD_ERR_NONFINITE: r->n_nonfinite++; break;
        case HCBD_ERR_PARAM: r->n_param++; break;
        case HCBD_ERR_CAPACITY: r->n_capacity++; break;
        default: r->n_other++; break;
        }
    }
    r->secs = now() - t0;
}

/* ------------------------------------------------------------------ report */
static const char *code_name(hcbd_result c)
{
    return c == HCBD_OK ? "none" : hcbd_result_name(c);
}

/* A guard (a result code from a check, not the blow-up) stopped the run. */
static int guard_first(const result *r)
{
    return r->fail_code == HCBD_ERR_UNSTABLE || r->fail_code == HCBD_ERR_PARAM;
}

static int in3(double x) { return isfinite(x) && x >= 1.0 / 3.0 && x <= 3.0; }

typedef struct summary {
    int points, with_fail, ratio_in, ratio_n, caught, nonfinite_runs, capacity_runs, failed_runs, t10_in,
        t10_n;
} summary;

static void report(FILE *csv, const char *model, const scene *s, const result *r, summary *sum)
{
    const double ratio = r->dt_fail / r->pred, rt = r->dt_t10 / r->acc_pred;
    const char *integ = s->shardlow ? "shardlow" : "euler";
    int k;
    printf("\n%s %s [%s] %s substeps=%d  (%d trials, %.1f s)\n", s->name, s->param, integ,
           model, s->substeps, r->nt, r->secs);
    printf("  limits: %s\n", r->limits);
    for (k = 0; k < r->nt; ++k) {
        const trial *t = r->t + k;
        printf("    dt %-10.4g dt/pred %-7.3g steps %-6lld %-20s T/kT-1 %+.4f\n", t->dt,
               t->dt / r->pred, t->step, code_name(t->code), t->terr);
    }
    printf("  binding: %s\n  predicted %.4g  dt_fail %.4g (%s)  ratio %.3g%s  dt_T10 %s%.4g",
           r->bind, r->pred, r->dt_fail, code_name(r->fail_code), ratio,
           isnan(ratio) ? "" : (in3(ratio) ? " [in 1/3..3]" : " [OUTSIDE 1/3..3]"),
           r->t10_below ? "<" : "", r->dt_t10);
    if (r->acc_pred < HUGE_VAL)
        printf("  accuracy bound %.4g (T10/accuracy %.3g)", r->acc_pred, rt);
    printf("\n");
    fprintf(csv, "%s,%s,%s,%s,%d,\"%s\",%.6g,%s%.6g,%.6g,%s,%.4g,%d,\"%s\",%.6g,%.4g,%d,%d,%d,%d,%d,%.2f,\"%s\"\n",
            model, s->name, s->param, integ, s->substeps, r->bind, r->pred, r->t10_below ? "<" : "",
            r->dt_t10, r->dt_fail, code_name(r->fail_code), ratio, isnan(r->dt_fail) ? 0 : guard_first(r),
            r->acc, r->acc_pred, rt, r->nt, r->n_unstable, r->n_nonfinite, r->n_param, r->n_capacity,
            r->secs,
            r->limits);
    fflush(csv);
    fflush(stdout);
    sum->points++;
    if (!isnan(r->dt_fail)) {
        sum->with_fail++;
        sum->caught += guard_first(r);
    }
    if (isfinite(ratio)) {
        sum->ratio_n++;
        sum->ratio_in += in3(ratio);
    }
    if (isfinite(rt) && !r->t10_below) {
        sum->t10_n++;
        sum->t10_in += in3(rt);
    }
    sum->failed_runs += r->n_unstable + r->n_nonfinite + r->n_param + r->n_capacity + r->n_other;
    sum->nonfinite_runs += r->n_nonfinite;
    sum->capacity_runs += r->n_capacity;
}

/* ------------------------------------------------------------------ scenes */
static int build_scenes(scene *sc, int quick)
{
    int n = 0;
#if HCBD_MODEL == HCBD_MODEL_HCBD
    /* eta and P0 multipliers: viscous limit binds in the first three,
       acoustic in the next two */
    static const double mul[][2] = {{1, 1}, {4, 1}, {0.25, 1}, {1, 100}, {0.25, 10}};
    const int nm = quick ? 2 : 5;
    int k, sh;
    for (sh = 0; sh < 2; ++sh)
        for (k = 0; k < nm; ++k) {
            scene *s = sc + n++;
            memset(s, 0, sizeof *s);
            s->d = hcbd_hc_world_def_default();
            s->d.fluid_capacity = s->n = 806;
            s->d.params.fluctuations = 1;
            s->d.params.eta *= mul[k][0];
            s->d.params.P0 *= mul[k][1];
            s->name = "fluid";
            snprintf(s->param, sizeof s->param, "eta x%g P0 x%g", mul[k][0], mul[k][1]);
            s->shardlow = sh;
            s->substeps = 1;
            s->steps = 200;
            /* Shardlow has no temperature bias to resolve at small dt */
            s->dt0_factor = sh ? 0.5 : 0.25;
            s->dtmax_factor = 32;
            if (sh && k == 1) --n; /* eta x4: as eta x1, no failure */
        }
    if (!quick) { /* multiple time stepping: the limits apply to dt/substeps */
        static const double mst[][2] = {{1, 1}, {1, 100}};
        for (k = 0; k < 2; ++k) {
            scene *s = sc + n++;
            memset(s, 0, sizeof *s);
            s->d = hcbd_hc_world_def_default();
            s->d.fluid_capacity = s->n = 806;
            s->d.params.fluctuations = 1;
            s->d.params.eta *= mst[k][0];
            s->d.params.P0 *= mst[k][1];
            s->name = "fluid";
            snprintf(s->param, sizeof s->param, "eta x%g P0 x%g", mst[k][0], mst[k][1]);
            s->substeps = 2;
            s->steps = 200;
            s->dt0_factor = 0.25;
            s->dtmax_factor = 32;
        }
    }
#else
    static const double fs[] = {32, 64, 128, 256}, xis[] = {0.25, 4};
    int k, sh;
    for (sh = 0; sh < 2; ++sh)
        for (k = 0; k < (quick ? 2 : 4); ++k) {
            scene *s = sc + n++;
            memset(s, 0, sizeof *s);
            s->d = hcbd_world_def_default();
            s->n = 512;
            s->d.params.f = fs[k];
            s->name = "star";
            snprintf(s->param, sizeof s->param, "f=%g xi=1", fs[k]);
            s->shardlow = sh;
            s->substeps = 1;
            s->tau_over_dt = 36;
            s->steps = 1000;
            s->dt0_factor = 0.25;
            s->dtmax_factor = 64;
        }
    for (k = 0; k < (quick ? 0 : 2); ++k) {
        scene *s = sc + n++;
        memset(s, 0, sizeof *s);
        s->d = hcbd_world_def_default();
        s->n = 512;
        s->d.params.xi = xis[k];
        s->name = "star";
        snprintf(s->param, sizeof s->param, "f=128 xi=%g", xis[k]);
        s->substeps = 1;
        s->tau_over_dt = 36;
        s->steps = 1000;
        s->dt0_factor = 0.25;
        s->dtmax_factor = 64;
    }
    for (sh = 0; sh < 2; ++sh) { /* ideal carriers at fixed tau: scan tau/dt */
        scene *s = sc + n++;
        memset(s, 0, sizeof *s);
        s->d = hcbd_world_def_default();
        s->n = 512;
        s->d.params.potential = HCBD_POT_IDEAL;
        s->name = "ideal";
        snprintf(s->param, sizeof s->param, "tau=%g", s->d.params.tau);
        s->shardlow = sh;
        s->substeps = 1;
        s->steps = 1000;
        s->dt0_factor = 1.0 / 32; /* of tau (the Euler overshoot bound) */
        s->dtmax_factor = 8;
    }
#endif
    return n;
}

int main(int argc, char **argv)
{
    static scene sc[24];
    static result res;
    summary sum;
    int quick = 0, k, n;
    char out[512] = "out/bench", path[600];
    const char *model = HCBD_MODEL == HCBD_MODEL_HCBD ? "hcbd" : "walled";
    FILE *csv;
    double t0 = now();
    for (k = 1; k < argc; ++k) {
        if (!strncmp(argv[k], "steps=", 6)) steps_override = atoi(argv[k] + 6);
        else if (!strncmp(argv[k], "quick=", 6)) quick = atoi(argv[k] + 6);
        else if (!strncmp(argv[k], "threads=", 8)) threads = atoi(argv[k] + 8);
        else if (!strncmp(argv[k], "out=", 4)) snprintf(out, sizeof out, "%s", argv[k] + 4);
        else {
            fprintf(stderr, "bench_stability: unknown argument '%s' (steps=, quick=, threads=, out=)\n",
                    argv[k]);
            return 2;
        }
    }
    if (threads < 1) threads = 1;
    csv = bench_csv("bench_stability", out, HCBD_MODEL == HCBD_MODEL_HCBD ? "stability_hcbd.csv" : "stability.csv",
                    path, sizeof path);
    if (!csv) return 1;
    fprintf(csv, "model,scene,param,integrator,substeps,binding_limit,predicted_dt,"
                 "dt_temperature_10pct,dt_fail,fail_code,ratio_fail_over_predicted,guard_first,"
                 "accuracy_limit,accuracy_dt,ratio_t10_over_accuracy,trials,unstable_runs,"
                 "nonfinite_runs,param_runs,capacity_runs,seconds,limits\n");
    memset(&sum, 0, sizeof sum);
    n = build_scenes(sc, quick);
    for (k = 0; k < n; ++k) {
        if (steps_override > 0) sc[k].steps = steps_override;
        scan(sc + k, &res);
        report(csv, model, sc + k, &res, &sum);
    }
    fclose(csv);
    printf("\n%-44s %-9s %-5s %-10s %-10s %-10s %-18s %-7s %s\n", "scene", "integ", "sub",
           "predicted", "dt_fail", "dt_T10", "code", "ratio", "guard_first");
    {
        /* re-read nothing: the table is printed from the CSV as it is cheap */
        FILE *f = fopen(path, "r");
        char line[2048];
        if (f && fgets(line, sizeof line, f))
            while (fgets(line, sizeof line, f)) {
                char scn[64], param[64], integ[16], code[32], t10[32];
                int sub, gf;
                double pred, fail, ratio;
                char *q = strchr(line, '"'), *q2 = q ? strchr(q + 1, '"') : NULL;
                if (!q2) continue;
                if (sscanf(line, "%*[^,],%63[^,],%63[^,],%15[^,],%d", scn, param, integ, &sub) != 4)
                    continue;
                if (sscanf(q2 + 2, "%lf,%31[^,],%lf,%31[^,],%lf,%d", &pred, t10, &fail, code, &ratio,
                           &gf) != 6)
                    continue;
                snprintf(line, sizeof line, "%s %s", scn, param);
                printf("%-44s %-9s %-5d %-10.4g %-10.4g %-10s %-18s %-7.3g %d\n", line, integ, sub,
                       pred, fail, t10, code, ratio, gf);
            }
        if (f) fclose(f);
    }
    printf("\nsummary %s: %d points, dt_fail/predicted inside [1/3, 3] for %d of %d; failures "
           "caught by a guard (UNSTABLE/PARAM, not NONFINITE) %d of %d points; of %d failed runs "
           "%d NONFINITE, %d CAPACITY; dt_T10/accuracy bound inside [1/3, 3] for %d of %d; %.1f s\n",
           model, sum.points, sum.ratio_in, sum.ratio_n, sum.caught, sum.with_fail,
           sum.failed_runs, sum.nonfinite_runs, sum.capacity_runs, sum.t10_in, sum.t10_n,
           now() - t0);
    printf("wrote %s\n", path);
    return 0;
}
