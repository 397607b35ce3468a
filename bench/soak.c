/* soak: long runs of each model, checked for drift.

   Each scene runs for psteps particle-steps (default 10^7; steps =
   psteps / particles, the HCBD scene counting fluid and polymer blobs).
   Observables are sampled evenly; after an equilibration fraction the
   samples are cut into blocks, and for each observable the table gives
   the mean with its block standard error, the least-squares drift per
   10^6 particle-steps with its error from the scatter of the block means
   about the line, and a verdict:
     stationary observables (temperature, flow velocity, density, polymer
       energy) PASS when the drift is within nsig errors of zero and the
       mean of the second half of the blocks is within nsig combined
       errors of the first half's.  T is printed beside kT for reference
       only: the papers' Euler pair step runs hot by O(dt/tau), a bias,
       not a drift;
     conserved observables (total momentum with internal forces only)
       PASS when the largest deviation from the start, over all samples,
       stays below the round-off bound given with the scene.
   A step that returns an error fails its scene (the message is printed).
   ac1 is the lag-1 autocorrelation of the block means about the line:
   well above 2/sqrt(blocks) says the blocks are shorter than the
   observable's correlation time.  Where it is positive the errors are
   the block errors times sqrt((1 + ac1)/(1 - ac1)) (AR(1) effective
   sample size, ac1 capped at 0.9); the CSV keeps the factor.  That is a
   first-order repair: with ac1 near the cap the run is simply too short
   for that observable, and psteps should grow.

   Builds: -DHCBD_MODEL=HCBD_MODEL_WALLED soaks the bulk GI-BD star liquid
   (the 2014/2016 scene) and the walled channel under a body force (the
   2016 channel of examples/channel_flow.c); HCBD_MODEL_GIBD only the bulk;
   HCBD_MODEL_HCBD the 2018 fluid with fluctuations and polymer blobs (the
   reduced scene of tests/test_hcbd.c: blob mass 100, nu = 1, c_s = 2.5,
   h = 2, dt = 0.04).

   usage: soak [psteps=1e7] [model=all|bulk|channel|hcbd] [threads=1]
               [blocks=40] [equil=scene default] [nsig=4] [out=DIR]
   Exit status 0 only if every verdict passes. */
#include "bench_common.h"
#include "../tests/scenes.h"
#include <errno.h>

#define MAXOBS 4
#define MAXSLAB 64
#define SAMPLES 4000 /* per scene: enough for 40 blocks of 100 */

enum { OBS_STATIONARY, OBS_CONSERVED };

typedef struct obs_def {
    const char *name;
    int kind;
    double ref; /* printed beside the mean (NAN: none)                 */
    double tol; /* conserved: bound on the largest |value|             */
} obs_def;

/* A scene behind callbacks, so one driver and one statistics routine
   serve every model. */
typedef struct sim {
    const char *name;
    int n;        /* particles counted in particle-steps */
    int nobs;
    obs_def obs[MAXOBS];
    double equil; /* fraction of the run discarded */
    void *ctx;
    hcbd_result (*step)(void *ctx, int nsteps);
    void (*sample)(void *ctx, double *out);
    const char *(*message)(void *ctx);
    void (*note)(void *ctx, char *buf, size_t size); /* may be NULL */
    void (*destroy)(void *ctx);
} sim;

typedef struct opts {
    double psteps, equil, nsig;
    int threads, blocks;
    const char *model, *out;
} opts;

typedef struct stats {
    double mean, err, drift, drift_err, half_diff, half_err, ac1, maxabs;
    double inflate; /* the errors above are the raw block errors times this */
    int nblk;
} stats;

/* Largest component of the momentum change since p0, over scale. */
static double momentum_change(const double p[3], const double p0[3], double scale)
{
    double d = 0;
    int a;
    for (a = 0; a < 3; ++a) d = fmax(d, fabs(p[a] - p0[a]));
    return d / scale;
}

/* Round-off bound on the total momentum's change, in units of the thermal
   momentum sqrt(N m kT): each step rounds every particle's momentum by
   ~eps sqrt(m kT) with a random sign, ~eps sqrt(N m kT) in all, so the
   change is a random walk of ~eps sqrt(steps).  Test runs of 2000-3000
   steps reached 0.5-1.4 eps sqrt(steps); 20 leaves room for the tail of
   the walk, while a systematic leak (linear in steps) still crosses it. */
static double momentum_tol(double steps)
{
    return 20 * 2.220446049250313e-16 * sqrt(steps);
}

#if HCBD_MODEL != HCBD_MODEL_HCBD
/* ------------------------------------------------------------------------
   Observables of the GI-BD scenes (id order, interleaved xyz) */

static int slab_of(double x, double lo, double hi, int nslab)
{
    int s = (int)floor((x - lo) / (hi - lo) * nslab);
    return s < 0 ? 0 : (s >= nslab ? nslab - 1 : s);
}

/* rms over slabs of count / mean count - 1: a density inhomogeneity that,
   unlike n/V, can drift (clustering, migration, particles lost to walls). */
static double slab_rms(const double *xyz, int n, int axis, double lo, double hi, int nslab)
{
    double c[MAXSLAB] = {0}, mean = (double)n / nslab, s2 = 0;
    int i, s;
    for (i = 0; i < n; ++i) c[slab_of(xyz[3 * i + axis], lo, hi, nslab)] += 1;
    for (s = 0; s < nslab; ++s) s2 += (c[s] / mean - 1) * (c[s] / mean - 1);
    return sqrt(s2 / nslab);
}

/* Kinetic temperature about each y slab's own mean velocity: in a channel
   the flow profile would otherwise count as heat (the flow speed is of the
   order of the thermal speed). */
static double slab_temperature(const double *xyz, const double *v, int n, double m, double lo,
                               double hi, int nslab)
{
    double c[MAXSLAB] = {0}, s1[3 * MAXSLAB] = {0}, s2[3 * MAXSLAB] = {0}, sum = 0, dof = 0;
    int i, s, a;
    for (i = 0; i < n; ++i) {
        s = slab_of(xyz[3 * i + 1], lo, hi, nslab);
        c[s] += 1;
        for (a = 0; a < 3; ++a) {
            s1[3 * s + a] += v[3 * i + a];
            s2[3 * s + a] += v[3 * i + a] * v[3 * i + a];
        }
    }
    for (s = 0; s < nslab; ++s) {
        if (c[s] < 2) continue;
        for (a = 0; a < 3; ++a) sum += s2[3 * s + a] - s1[3 * s + a] * s1[3 * s + a] / c[s];
        dof += 3 * (c[s] - 1);
    }
    return dof > 0 ? m * sum / dof : NAN;
}

/* ------------------------------------------------------------------------
   GI-BD scenes: the bulk star liquid and the walled channel */

typedef struct gibd_ctx {
    hcbd_world w;
    double *xyz, *v, p0[3], pscale;
    int channel, nslab;
} gibd_ctx;

static hcbd_result gibd_step(void *ctx, int nsteps) { return hcbd_world_step(&((gibd_ctx *)ctx)->w, nsteps); }
static const char *gibd_message(void *ctx) { return ((gibd_ctx *)ctx)->w.err.msg; }

static void gibd_destroy(void *ctx)
{
    gibd_ctx *g = (gibd_ctx *)ctx;
    hcbd_world_destroy(&g->w);
    free(g->xyz);
    free(g->v);
    free(g);
}

/* bulk: T, momentum change, density rms over 8 slabs along each axis;
   channel: slab T, mean flow velocity, density rms over the channel */
static void gibd_sample(void *ctx, double *out)
{
    gibd_ctx *g = (gibd_ctx *)ctx;
    const hcbd_params *p = &g->w.p;
    double P[3];
    int a;
    hcbd_world_get_positions(&g->w, g->xyz, 0);
    hcbd_world_momentum(&g->w, P);
    if (!g->channel) {
        out[0] = hcbd_world_temperature(&g->w);
        out[1] = momentum_change(P, g->p0, g->pscale);
        out[2] = 0;
        for (a = 0; a < 3; ++a) out[2] += slab_rms(g->xyz, g->w.n, a, 0, p->L[a], g->nslab) / 3;
        return;
    }
    hcbd_world_get_velocities(&g->w, g->v);
    out[0] = slab_temperature(g->xyz, g->v, g->w.n, g->w.m, p->wall.thickness,
                              p->L[1] - p->wall.thickness, g->nslab);
    out[1] = P[0] / (g->w.n * g->w.m);
    out[2] = slab_rms(g->xyz, g->w.n, 1, p->wall.thickness, p->L[1] - p->wall.thickness, g->nslab);
}

#if HCBD_MODEL == HCBD_MODEL_WALLED
static void gibd_note(void *ctx, char *buf, size_t size)
{
    gibd_ctx *g = (gibd_ctx *)ctx;
    int64_t last = -1, pen;
    int id = -1;
    pen = hcbd_world_wall_penetrations(&g->w, &last, &id);
    snprintf(buf, size, "wall penetrations %lld particle-steps (last step %lld, id %d)",
             (long long)pen, (long long)last, id);
}
#endif

static gibd_ctx *gibd_alloc(const hcbd_world_def *def, int n, int channel, int nslab)
{
    gibd_ctx *g = (gibd_ctx *)calloc(1, sizeof *g);
    if (!g) return NULL;
    g->channel = channel;
    g->nslab = nslab;
    g->xyz = (double *)malloc(3 * sizeof(double) * n);
    g->v = (double *)malloc(3 * sizeof(double) * n);
    if (!g->xyz || !g->v || hcbd_world_create(&g->w, def) != HCBD_OK ||
        hcbd_world_place_lattice(&g->w, n) != HCBD_OK) {
        fprintf(stderr, "soak: set-up failed: %s\n", g->w.err.msg);
        free(g->xyz);
        free(g->v);
        free(g);
        return NULL;
    }
    hcbd_world_momentum(&g->w, g->p0);
    g->pscale = sqrt(n * g->w.m * def->params.kT);
    return g;
}

static void gibd_hooks(sim *s, gibd_ctx *g)
{
    s->ctx = g;
    s->n = g->w.n;
    s->step = gibd_step;
    s->sample = gibd_sample;
    s->message = gibd_message;
    s->destroy = gibd_destroy;
}

/* The 2014/2016 star-polymer liquid: 512 stars, f = 128, n# = 0.24. */
static int scene_bulk(sim *s, const opts *o, double steps)
{
    hcbd_world_def def = hcbd_world_def_default();
    gibd_ctx *g;
    def.capacity = 512;
    def.params.potential = HCBD_POT_STAR;
    def.params.threads = o->threads;
    if (!(g = gibd_alloc(&def, 512, 0, 8))) return 0;
    gibd_hooks(s, g);
    s->nobs = 3;
    s->obs[0] = (obs_def){"T/kT", OBS_STATIONARY, def.params.kT, 0};
    s->obs[1] = (obs_def){"|dP|/sqrt(NmkT)", OBS_CONSERVED, 0, momentum_tol(steps)};
    s->obs[2] = (obs_def){"density_rms_8slab", OBS_STATIONARY, NAN, 0};
    s->equil = 0.1;
    return 1;
}
#endif /* GI-BD scenes */

#if HCBD_MODEL == HCBD_MODEL_WALLED
/* The 2016 channel (sec. IV C): 13^3 box, Gaussian walls 1.5 thick,
   n# = 0.24 stars in the channel, tau = 3e-3, body force g = 133.4 per
   unit mass along x.  The flow needs ~W^2/nu to develop and the stars to
   layer at the walls, hence the longer equilibration. */
static int scene_channel(sim *s, const opts *o, double steps)
{
    hcbd_world_def def = hcbd_world_def_default();
    hcbd_params *p = &def.params;
    gibd_ctx *g;
    int n;
    (void)steps;
    p->L[0] = p->L[1] = p->L[2] = 13.0;
    p->tau = 3e-3;
    p->potential = HCBD_POT_STAR;
    p->wall.thickness = 1.5;
    p->wall.mode = HCBD_WALL_GAUSS;
    p->fext[0] = 133.4 * p->xip * p->tau; /* F = m g */
    p->threads = o->threads;
    n = (int)floor(0.24 * p->L[0] * (p->L[1] - 2 * p->wall.thickness) * p->L[2] + 0.5);
    def.capacity = n;
    if (!(g = gibd_alloc(&def, n, 1, 20))) return 0;
    gibd_hooks(s, g);
    s->note = gibd_note;
    s->nobs = 3;
    s->obs[0] = (obs_def){"T_slab/kT", OBS_STATIONARY, p->kT, 0};
    s->obs[1] = (obs_def){"mean_vx", OBS_STATIONARY, NAN, 0};
    s->obs[2] = (obs_def){"density_rms_y20slab", OBS_STATIONARY, NAN, 0};
    s->equil = 0.2;
    return 1;
}
#endif

#if HCBD_MODEL == HCBD_MODEL_HCBD
/* ------------------------------------------------------------------------
   The 2018 model: SPH fluid with fluctuations and RaPiD polymer blobs */

typedef struct hc_ctx {
    hcbd_hc_world w;
    double p0[3], pscale;
} hc_ctx;

static hcbd_result hc_step(void *ctx, int nsteps) { return hcbd_hc_world_step(&((hc_ctx *)ctx)->w, nsteps); }
static const char *hc_message(void *ctx) { return ((hc_ctx *)ctx)->w.err.msg; }

static void hc_destroy(void *ctx)
{
    hcbd_hc_world_destroy(&((hc_ctx *)ctx)->w);
    free(ctx);
}

/* T, momentum change, spread of the SPH densities max - min of n_i/nbar
   (what the Tait fluid must keep small to stay stable), polymer energy
   per polymer over kT (the pair variables and Flory-Huggins state). */
static void hc_sample(void *ctx, double *out)
{
    hc_ctx *h = (hc_ctx *)ctx;
    double P[3], r[3];
    hcbd_hc_world_momentum(&h->w, P);
    hcbd_hc_world_density_range(&h->w, r);
    out[0] = hcbd_hc_world_temperature(&h->w);
    out[1] = momentum_change(P, h->p0, h->pscale);
    out[2] = r[1] - r[0];
    out[3] = hcbd_hc_world_polymer_energy(&h->w) / (h->w.np * h->w.p.kT);
}

static int scene_hcbd(sim *s, const opts *o, double steps)
{
    const int nside = 6, npoly = 108;
    /* the tests' scene with blob mass 100, c_s = 2.5 and twice the step */
    hcbd_hc_world_def d = hc_scene_of(nside, nside, nside, npoly, 100.0, 1.0, 2.5, 0.04);
    hcbd_hc_params *p = &d.params;
    hc_ctx *h = (hc_ctx *)calloc(1, sizeof *h);
    if (!h) return 0;
    p->threads = o->threads;
    if (hcbd_hc_world_create(&h->w, &d) != HCBD_OK ||
        hcbd_hc_world_place_fluid_lattice(&h->w, d.fluid_capacity) != HCBD_OK ||
        hcbd_hc_world_place_polymers_random(&h->w, npoly) != HCBD_OK) {
        fprintf(stderr, "soak: set-up failed: %s\n", h->w.err.msg);
        free(h);
        return 0;
    }
    hcbd_hc_world_momentum(&h->w, h->p0);
    h->pscale = sqrt(h->w.nf * h->w.m * p->kT);
    s->ctx = h;
    s->n = h->w.nf + h->w.np;
    s->step = hc_step;
    s->sample = hc_sample;
    s->message = hc_message;
    s->destroy = hc_destroy;
    s->nobs = 4;
    s->obs[0] = (obs_def){"T/kT", OBS_STATIONARY, p->kT, 0};
    s->obs[1] = (obs_def){"|dP|/sqrt(NmkT)", OBS_CONSERVED, 0, momentum_tol(steps)};
    s->obs[2] = (obs_def){"fluid_n_spread", OBS_STATIONARY, NAN, 0};
    s->obs[3] = (obs_def){"polymer_E/kT", OBS_STATIONARY, NAN, 0};
    s->equil = 0.1;
    return 1;
}
#endif

/* ------------------------------------------------------------------------
   Statistics */

/* Unweighted least squares y = c + b t over n points: slope b and its
   standard error from the residual scatter; res gets the residuals. */
static void line_fit(const double *t, const double *y, int n, double *b, double *b_err, double *res)
{
    double tm = 0, ym = 0, stt = 0, sty = 0, r2 = 0;
    int k;
    for (k = 0; k < n; ++k) { tm += t[k] / n; ym += y[k] / n; }
    for (k = 0; k < n; ++k) {
        stt += (t[k] - tm) * (t[k] - tm);
        sty += (t[k] - tm) * (y[k] - ym);
    }
    *b = stt > 0 ? sty / stt : 0;
    for (k = 0; k < n; ++k) {
        res[k] = y[k] - ym - *b * (t[k] - tm);
        r2 += res[k] * res[k];
    }
    *b_err = (n > 2 && stt > 0) ? sqrt(r2 / (n - 2) / stt) : NAN;
}

/* mean and standard error of the mean of y[0..n) */
static void mean_err(const double *y, int n, double *mean, double *err)
{
    double m = 0, v = 0;
    int k;
    for (k = 0; k < n; ++k) m += y[k] / n;
    for (k = 0; k < n; ++k) v += (y[k] - m) * (y[k] - m);
    *mean = m;
    *err = n > 1 ? sqrt(v / (n - 1) / n) : NAN;
}

/* Samples y[k * stride] at particle-steps t[k], k < n: the first
   equil * n are dropped, the rest cut into nblk blocks (a remainder at the
   end is dropped so the blocks are equal). */
static void soak_stats(const double *t, const double *y, int n, int stride, int nblk, double equil,
                        stats *st)
{
    double bt[1000], by[1000], res[1000], m1, e1, m2, e2, num = 0, den = 0;
    int k, b, k0 = (int)(equil * n), len;
    memset(st, 0, sizeof *st);
    for (k = 0; k < n; ++k) st->maxabs = fmax(st->maxabs, fabs(y[(size_t)k * stride]));
    if (nblk > n - k0) nblk = n - k0;
    if (nblk > 1000) nblk = 1000;
    st->nblk = nblk;
    if (nblk < 4) { /* too short a run for any error */
        st->mean = st->err = st->drift = st->drift_err = st->half_diff = st->half_err = NAN;
        return;
    }
    len = (n - k0) / nblk;
    for (b = 0; b < nblk; ++b) {
        bt[b] = by[b] = 0;
        for (k = k0 + b * len; k < k0 + (b + 1) * len; ++k) {
            bt[b] += t[k] / len;
            by[b] += y[(size_t)k * stride] / len;
        }
    }
    mean_err(by, nblk, &st->mean, &st->err);
    line_fit(bt, by, nblk, &st->drift, &st->drift_err, res);
    st->drift *= 1e6;
    st->drift_err *= 1e6;
    mean_err(by, nblk / 2, &m1, &e1);
    mean_err(by + nblk / 2, nblk - nblk / 2, &m2, &e2);
    st->half_diff = m2 - m1;
    st->half_err = sqrt(e1 * e1 + e2 * e2);
    for (b = 0; b < nblk; ++b) {
        den += res[b] * res[b];
        if (b > 0) num += res[b] * res[b - 1];
    }
    st->ac1 = den > 0 ? num / den : 0;
    /* Block means correlated from one block to the next (blocks shorter
       than the observable's correlation time: slow flow and structure)
       make the raw errors too small and the verdict flaky; the AR(1)
       effective-sample factor restores them.  It comes from the residuals
       about the line, so a linear drift does not widen its own error. */
    st->inflate = st->ac1 > 0 ? sqrt((1 + fmin(st->ac1, 0.9)) / (1 - fmin(st->ac1, 0.9))) : 1;
    st->err *= st->inflate;
    st->drift_err *= st->inflate;
    st->half_err *= st->inflate;
}

/* A run too short for 4 blocks fails: a soak that measured nothing must
   not pass. */
static int verdict(const obs_def *od, const stats *st, double nsig)
{
    if (st->nblk < 4) return 0;
    if (od->kind == OBS_CONSERVED) return st->maxabs <= od->tol;
    return isfinite(st->drift_err) && fabs(st->drift) <= nsig * st->drift_err &&
           fabs(st->half_diff) <= nsig * st->half_err;
}

/* ------------------------------------------------------------------------
   Driver and report */

static FILE *csv;

static void print_header(void)
{
    printf("%-8s %10s %-20s %12s %10s %8s %12s %10s %11s %6s %s\n", "model", "psteps", "observable",
           "mean", "err", "ref", "drift/1e6", "drift_err", "half_diff", "ac1", "verdict");
    if (csv)
        fprintf(csv, "model,psteps,observable,mean,err,ref,drift_per_1e6,drift_err,half_diff,half_err,"
                     "ac1,err_inflation,max_abs,tol,verdict\n");
}

static void print_row(const sim *s, double ps, const obs_def *od, const stats *st, int ok)
{
    char half[32];
    snprintf(half, sizeof half, "%.2g/%.2g", st->half_diff, st->half_err);
    if (od->kind == OBS_CONSERVED)
        printf("%-8s %10.4g %-20s %12.4e %10.2e %8s %12.3e %10.2e %11s %6.2f %s (max %.2e, tol %.2e)\n",
               s->name, ps, od->name, st->mean, st->err, "0", st->drift, st->drift_err, "-", st->ac1,
               ok ? "PASS" : "FAIL", st->maxabs, od->tol);
    else
        printf("%-8s %10.4g %-20s %12.6g %10.2e %8.4g %12.3e %10.2e %11s %6.2f %s\n", s->name, ps,
               od->name, st->mean, st->err, od->ref, st->drift, st->drift_err, half, st->ac1,
               ok ? "PASS" : "FAIL");
    if (csv)
        fprintf(csv, "%s,%.0f,%s,%.10g,%.4g,%.6g,%.6g,%.4g,%.6g,%.4g,%.4f,%.4f,%.4g,%.4g,%s\n", s->name,
                ps, od->name, st->mean, st->err, od->ref, st->drift, st->drift_err, st->half_diff,
                st->half_err, st->ac1, st->inflate, st->maxabs, od->tol, ok ? "PASS" : "FAIL");
}

/* Runs a built scene for o->psteps particle-steps and reports it; returns
   the number of failed verdicts. */
static int soak(sim *s, const opts *o, double steps)
{
    int every = (int)ceil(steps / SAMPLES), nsamp = (int)ceil(steps / every), k, j, fails = 0;
    double *t = (double *)malloc(sizeof(double) * nsamp);
    double *y = (double *)malloc(sizeof(double) * nsamp * MAXOBS), t0, wall, ps;
    hcbd_result r = HCBD_OK;
    char note[256] = "";
    if (!t || !y) { fprintf(stderr, "soak: out of memory\n"); free(t); free(y); return 1; }
    t0 = now();
    for (k = 0; k < nsamp && r == HCBD_OK; ++k) {
        if ((r = s->step(s->ctx, every)) != HCBD_OK) break;
        t[k] = (double)(k + 1) * every * s->n;
        s->sample(s->ctx, y + (size_t)k * s->nobs);
    }
    wall = now() - t0;
    ps = (double)k * every * s->n;
    if (s->note) s->note(s->ctx, note, sizeof note);
    printf("# %s: %d particles, %d steps (%d samples), %.1f s, %.0f ns per particle-step, hcbd_world_step %s%s%s\n",
           s->name, s->n, k * every, k, wall, 1e9 * wall / fmax(ps, 1), hcbd_result_name(r),
           note[0] ? "; " : "", note);
    if (r != HCBD_OK) {
        printf("%-8s %10.4g %-20s step error %s: %s  FAIL\n", s->name, ps, "hcbd_world_step", hcbd_result_name(r),
               s->message(s->ctx));
        if (csv) fprintf(csv, "%s,%.0f,hcbd_world_step,,,,,,,,,,,,FAIL\n", s->name, ps);
        ++fails;
    }
    for (j = 0; j < s->nobs; ++j) {
        stats st;
        int ok;
        soak_stats(t, y + j, k, s->nobs, o->blocks, o->equil >= 0 ? o->equil : s->equil, &st);
        ok = verdict(&s->obs[j], &st, o->nsig) && r == HCBD_OK;
        print_row(s, ps, &s->obs[j], &st, ok);
        fails += !ok;
    }
    fflush(stdout);
    free(t);
    free(y);
    return fails;
}

typedef int (*scene_fn)(sim *s, const opts *o, double steps);

#if HCBD_MODEL == HCBD_MODEL_HCBD
#define BUILD_NAME "hcbd"
#elif HCBD_MODEL == HCBD_MODEL_WALLED
#define BUILD_NAME "walled"
#else
#define BUILD_NAME "gibd"
#endif

static const struct {
    const char *name;
    scene_fn make;
    int n; /* particles, to turn psteps into steps before the build */
} scenes[] = {
#if HCBD_MODEL == HCBD_MODEL_HCBD
    {"hcbd", scene_hcbd, 216 + 108},
#else
    {"bulk", scene_bulk, 512},
#if HCBD_MODEL == HCBD_MODEL_WALLED
    {"channel", scene_channel, 406},
#endif
#endif
};

static int parse_args(int argc, char **argv, opts *o)
{
    int k;
    for (k = 1; k < argc; ++k) {
        const char *eq = strchr(argv[k], '=');
        char *end = NULL;
        double x = 0;
        size_t kl = eq ? (size_t)(eq - argv[k]) : 0;
        if (!eq) break;
#define KEY(s) (kl == strlen(s) && !strncmp(argv[k], s, kl))
        if (KEY("model")) { o->model = eq + 1; continue; }
        if (KEY("out")) { o->out = eq + 1; continue; }
        errno = 0;
        x = strtod(eq + 1, &end);
        if (errno || end == eq + 1 || *end || !isfinite(x)) break;
        if (KEY("psteps") && x >= 1) o->psteps = x;
        else if (KEY("threads") && x >= 1 && x <= 1024) o->threads = (int)x;
        else if (KEY("blocks") && x >= 4 && x <= 1000) o->blocks = (int)x;
        else if (KEY("equil") && x >= 0 && x < 0.9) o->equil = x;
        else if (KEY("nsig") && x > 0) o->nsig = x;
        else break;
#undef KEY
    }
    if (k == argc) return 1;
    fprintf(stderr, "soak: bad argument '%s'\n"
                    "usage: soak [psteps=1e7] [model=all|<scene>] [threads=1] [blocks=40 (4..1000)]\n"
                    "            [equil=<fraction>] [nsig=4] [out=DIR]\n", argv[k]);
    return 0;
}

static void open_csv(const opts *o)
{
    char path[1024];
    if (!o->out) return;
    if (mkdir(o->out, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "soak: cannot create %s: %s\n", o->out, strerror(errno));
        return;
    }
    snprintf(path, sizeof path, "%s/soak_%s.csv", o->out, BUILD_NAME);
    if (!(csv = fopen(path, "w"))) fprintf(stderr, "soak: cannot write %s\n", path);
}

int main(int argc, char **argv)
{
    opts o = {1e7, -1, 4, 1, 40, "all", NULL};
    int i, fails = 0, known;
    double t0 = now();
    if (!parse_args(argc, argv, &o)) return 2;
    known = !strcmp(o.model, "all");
    for (i = 0; i < (int)(sizeof scenes / sizeof scenes[0]); ++i) known |= !strcmp(o.model, scenes[i].name);
    if (!known) {
        fprintf(stderr, "soak: model=%s is not a scene of this build\n", o.model);
        return 2;
    }
    open_csv(&o);
    printf("soak (" BUILD_NAME " build): %.3g particle-steps per scene, %d blocks, equilibration %s, drift and half-difference "
           "within %g errors, %d thread(s)\n"
           "      (errors: block errors times sqrt((1 + ac1)/(1 - ac1)) where ac1 > 0; half_diff = second "
           "half - first half / its error)\n",
           o.psteps, o.blocks, o.equil >= 0 ? "as given" : "scene default", o.nsig, o.threads);
    print_header();
    for (i = 0; i < (int)(sizeof scenes / sizeof scenes[0]); ++i) {
        sim s;
        double steps = ceil(o.psteps / scenes[i].n);
        if (strcmp(o.model, "all") && strcmp(o.model, scenes[i].name)) continue;
        memset(&s, 0, sizeof s);
        s.name = scenes[i].name;
        if (!scenes[i].make(&s, &o, steps)) { ++fails; continue; }
        fails += soak(&s, &o, steps);
        s.destroy(s.ctx);
    }
    printf("soak: %d failed verdict(s), %.1f s in all\n", fails, now() - t0);
    if (csv) fclose(csv);
    return fails ? 1 : 0;
}
