/* bench_wp_hcbd: work-precision of the HCBD (2018) fluid.  Run time per
   unit of simulated time (wall seconds, one thread, clock_gettime around
   hcbd_hc_world_step only) against the error from theory, over the time step dt,
   the kernel support h, the pair integrator (Euler, Shardlow), multiple
   time stepping (substeps) and, through the build, the precision.

   Scene (reduced units, as fluid_scene in tests/test_hcbd.c): kT = 1,
   nbar = 3/(4 pi) (simple cubic lattice spacing a = 1.612), blob mass
   m = 100 (rho = 100 nbar), nu = eta/rho = 1, c_s = 2.5, h = 2 (h = 1.5,
   2.5 in the h sweep: 27, 64, 125 neighbours within 2h); polymers RaPiD
   sigma = 1, rc = 2.5.  Metrics:
     temperature   |T/kT - 1|, fluctuations on, 6^3 lattice sites (7^3 at
                   h = 2.5) melted for 10 time units, then sampled every
                   0.2 over 80 (10 blocks); Euler's bias is about 0.33 dt/dt_visc,
                   dt_visc = 0.125 h^2/nu.
     nu            decay of a transverse wave v_y = 0.3 sin(k x) at the
                   smallest k = 2 pi/Lx (20 x 5 x 5 sites, 20 x 7 x 7 at
                   h = 2.5) by hcbd_hc_world_transverse_current, from positions
                   melted with fluctuations, then fluctuations off (no
                   noise: a deterministic fit); the error is |nu_fit/nu - 1|
                   against nu K(k), nu = eta/rho and K(k) the kernel
                   factor hcbd_m4_shear_factor (the SPH viscous force
                   relaxes a shear mode at nu k^2 K(k); K = 0.989 at h = 2
                   here); |nu_fit - 1| is in config.
     poiseuille_l2 reverse Poiseuille, g = 0.05, fluctuations off, 5 x 10 x 5
                   sites (7 x 10 x 7 at h = 2.5) from the lattice with the
                   kernel-smoothed profile as the start; L2 of the slab
                   profile (one slab per lattice row, the mean flow taken
                   out) against the parabola (g/2nu) y'(L/2 - y'), relative
                   to the parabola's norm.  The Morris viscous force is a
                   Laplacian smoothed over the kernel, which rounds the
                   kinks at y = 0, L/2: its own L2 against the parabola
                   (kernel_profile of examples/hcbd_fluid.c) is printed as
                   the floor that smaller h lowers.
     poiseuille_l2_solution  the same fluid (5 x 8 x 5 sites) with 5 x as many
                   polymer blobs, Flory-Huggins on (p = 100, n_max = 5,
                   chi = 0.5), transient pairs off (alpha = 0, Newtonian),
                   xi = 100; the fluid step is 0.04 throughout and the
                   polymer step dt = substeps x 0.04 (multiple time
                   stepping), with single-step controls at the large dt.
                   The polymers' lag behind the fluid profile at their
                   positions (kernel smoothing taken out, as in
                   test_hc_poiseuille_no_lag) is printed.

   Output: out/bench/wp_hcbd.csv (wp_hcbd_float.csv from the float build)
   model,metric,integrator,precision,noise,dt,h,substeps,
   seconds_per_time_unit,error,error_err,config
   usage: bench_wp_hcbd [quick=0|1] [out=out/bench]
          [only=temperature|nu|poiseuille|solution] */
#include "bench_common.h"
#include "../tests/scenes.h"

#define PI_ 3.14159265358979323846
#define A_LAT HC_LATTICE_A
#define MAXROWS 64
#define NSLAB 10

typedef struct {
    const char *metric;
    int integ;
    double dt, h;
    int substeps;
    double spt, err, err_err;
    char config[128];
} row;

static row rows[MAXROWS];
static int nrows = 0;
static int quick = 0;
static double tscale = 1.0; /* quick=1 shortens every run */
static char only[32] = "";   /* only=temperature|nu|poiseuille|solution */

/* timed stepping: wall seconds and simulated time of the measured worlds */
static double t_wall, t_sim;

static int step(hcbd_hc_world *w, int n)
{
    double t0 = now();
    hcbd_result r = hcbd_hc_world_step(w, n);
    t_wall += now() - t0;
    t_sim += n * w->p.dt;
    if (r != HCBD_OK) {
        printf("    (stopped: %s: %s)\n", hcbd_result_name(r), w->err.msg);
        return 0;
    }
    return 1;
}

static void timer_reset(void) { t_wall = t_sim = 0; }

static const char *prec(void) { return sizeof(hcbd_real) == 4 ? "float" : "double"; }

static void add_row(const char *metric, int integ, double dt, double h, int nsub, double err,
                    double err_err, const char *config)
{
    row *r;
    if (nrows >= MAXROWS) return;
    r = &rows[nrows++];
    r->metric = metric;
    r->integ = integ;
    r->dt = dt;
    r->h = h;
    r->substeps = nsub;
    r->spt = t_wall / t_sim;
    r->err = err;
    r->err_err = err_err;
    snprintf(r->config, sizeof r->config, "%s", config);
    printf("%-23s %-8s %6.3f %4.1f %2d %10.4f %10.5f %9.5f  %s\n", metric,
           integ == HCBD_PAIR_SHARDLOW ? "shardlow" : "euler", dt, h, nsub, r->spt, err, err_err,
           config);
    fflush(stdout);
}

/* The tests' scene (tests/scenes.h) with blob mass 100, c_s = 2.5, support
   h and the polymers' friction 100 without transient forces. */
static hcbd_hc_world_def scene(int nx, int ny, int nz, double h, double dt, int integ, int nsub, int np)
{
    hcbd_hc_world_def d = hc_scene_of(nx, ny, nz, np, 100.0, 1.0, 2.5, dt);
    hcbd_hc_params *p = &d.params;
    p->h = h;
    p->xi = 100.0;
    p->alpha = 0.0;
    p->threads = 1;
    p->pair_integrator = (hcbd_pair_integrator)integ;
    p->substeps = nsub;
    return d;
}

/* lattice sites across a box edge: at least 4h (two kernel ranges) */
static int sites_for(double h, int base)
{
    int n = (int)ceil(4.0 * h / A_LAT - 1e-9);
    return n > base ? n : base;
}

static int make(hcbd_hc_world *w, const hcbd_hc_world_def *d)
{
    if (hcbd_hc_world_create(w, d) != HCBD_OK) {
        printf("    world: %s\n", w->err.msg);
        return 0;
    }
    if (hcbd_hc_world_place_fluid_lattice(w, d->fluid_capacity) != HCBD_OK) {
        printf("    lattice: %s\n", w->err.msg);
        hcbd_hc_world_destroy(w);
        return 0;
    }
    return 1;
}

static void mean_err(const double *x, int n, double *m, double *e)
{
    double s = 0, v = 0;
    int k;
    for (k = 0; k < n; ++k) s += x[k];
    s /= n;
    for (k = 0; k < n; ++k) v += (x[k] - s) * (x[k] - s);
    *m = s;
    *e = n > 1 ? sqrt(v / (n - 1) / n) : NAN;
}

/* ---- temperature ------------------------------------------------------- */

static void run_temperature(double dt, double h, int integ)
{
    const int n = sites_for(h, 6), nb = 10;
    hcbd_hc_world_def d = scene(n, n, n, h, dt, integ, 1, 0);
    hcbd_hc_world w;
    hcbd_hc_theory th;
    int every = (int)(0.2 / dt + 0.5), ns, k, b;
    double blk[10], T, e, meas = 80.0 * tscale;
    char cfg[128];
    if (every < 1) every = 1;
    ns = (int)(meas / (every * dt) + 0.5) / nb * nb;
    hcbd_hc_params_theory(&d.params, &th);
    timer_reset();
    if (!make(&w, &d)) return;
    if (!step(&w, (int)(10.0 * tscale / dt + 0.5))) { hcbd_hc_world_destroy(&w); return; }
    for (b = 0; b < nb; ++b) {
        double s = 0;
        for (k = 0; k < ns / nb; ++k) {
            if (!step(&w, every)) { hcbd_hc_world_destroy(&w); return; }
            s += hcbd_hc_world_temperature(&w) / d.params.kT;
        }
        blk[b] = s / (ns / nb);
    }
    hcbd_hc_world_destroy(&w);
    mean_err(blk, nb, &T, &e);
    snprintf(cfg, sizeof cfg, "%s dt=%g h=%g N=%d T=%.4f Euler-bias~%.4f",
             integ == HCBD_PAIR_SHARDLOW ? "shardlow" : "euler", dt, h, n * n * n, T,
             integ == HCBD_PAIR_EULER ? 0.33 * dt / th.dt_visc : 0.0);
    add_row("temperature", integ, dt, h, 1, fabs(T - 1), e, cfg);
}

/* ---- viscosity from a transverse wave ---------------------------------- */

/* melted positions per h (fluctuations on, lattice start) */
#define NMELT 3
static double melt_h[NMELT];
static double *melt_xyz[NMELT];

static const double *melted(double h, int nx, int ny, int nz)
{
    hcbd_hc_world_def d;
    hcbd_hc_world w;
    int k, i;
    for (k = 0; k < NMELT; ++k)
        if (melt_xyz[k] && melt_h[k] == h) return melt_xyz[k];
    for (k = 0; k < NMELT && melt_xyz[k]; ++k) {}
    if (k == NMELT) return NULL;
    d = scene(nx, ny, nz, h, 0.04, HCBD_PAIR_SHARDLOW, 1, 0);
    if (!make(&w, &d)) return NULL;
    if (hcbd_hc_world_step(&w, (int)(10.0 * tscale / 0.04)) != HCBD_OK) {
        printf("    melt: %s\n", w.err.msg);
        hcbd_hc_world_destroy(&w);
        return NULL;
    }
    melt_xyz[k] = (double *)malloc(3 * sizeof(double) * w.nf);
    for (i = 0; i < w.nf; ++i) {
        melt_xyz[k][3 * i] = w.fx[i];
        melt_xyz[k][3 * i + 1] = w.fy[i];
        melt_xyz[k][3 * i + 2] = w.fz[i];
    }
    melt_h[k] = h;
    hcbd_hc_world_destroy(&w);
    return melt_xyz[k];
}

static void run_nu(double dt, double h, int integ)
{
    const int ny = sites_for(h, 5), nx = 20, N = nx * ny * ny, nsamp = 41;
    hcbd_hc_world_def d = scene(nx, ny, ny, h, dt, integ, 1, 0);
    hcbd_hc_world w;
    const double Amp = 0.3, k = 2 * PI_ / d.params.L[0], span = 20.0 * (quick ? 0.5 : 1.0);
    const double *xyz = melted(h, nx, ny, ny);
    double *v, tt[64], la[64], j[12], sx = 0, sy = 0, sxx = 0, sxy = 0, res = 0, nu, enu, K;
    int i, n, every = (int)(span / (nsamp - 1) / dt + 0.5);
    char cfg[128];
    if (!xyz) return;
    if (every < 1) every = 1;
    d.params.fluctuations = 0;
    v = (double *)calloc(3 * (size_t)N, sizeof(double));
    for (i = 0; i < N; ++i) v[3 * i + 1] = Amp * sin(k * xyz[3 * i]);
    timer_reset();
    if (hcbd_hc_world_create(&w, &d) != HCBD_OK || hcbd_hc_world_set_fluid(&w, N, xyz, v) != HCBD_OK) {
        printf("    nu set-up: %s\n", w.err.msg);
        free(v);
        return;
    }
    free(v);
    for (n = 0; n < nsamp; ++n) {
        if (n > 0 && !step(&w, every)) { hcbd_hc_world_destroy(&w); return; }
        hcbd_hc_world_transverse_current(&w, 1, j);
        tt[n] = n * every * dt;
        la[n] = log(-2 * j[1] / (Amp * N));
    }
    hcbd_hc_world_destroy(&w);
    for (i = 0; i < n; ++i) { sx += tt[i]; sy += la[i]; sxx += tt[i] * tt[i]; sxy += tt[i] * la[i]; }
    nu = -(n * sxy - sx * sy) / (n * sxx - sx * sx) / (k * k);
    for (i = 0; i < n; ++i) {
        double f = (sy + nu * k * k * sx) / n - nu * k * k * tt[i] - la[i];
        res += f * f;
    }
    enu = sqrt(res / (n - 2) / (sxx - sx * sx / n)) / (k * k);
    K = hcbd_m4_shear_factor(k, h);
    snprintf(cfg, sizeof cfg, "%s dt=%g h=%g N=%d nu_fit=%.4f K(k)=%.4f |nu_fit-1|=%.4f",
             integ == HCBD_PAIR_SHARDLOW ? "shardlow" : "euler", dt, h, N, nu, K, fabs(nu - 1));
    add_row("nu", integ, dt, h, 1, fabs(nu / K - 1.0), enu / K, cfg);
}

/* ---- reverse Poiseuille ------------------------------------------------ */

/* v_x = (g / 2 nu) rp_shape(y): y' from the edge of each half; the lower
   half (force -g) flows back */
static double rp_shape(double y, double L)
{
    double hh = 0.5 * L;
    return y >= hh ? (y - hh) * (L - y) : -y * (hh - y);
}

/* kernel_profile of examples/hcbd_fluid.c: each odd harmonic of the square
   wave force settles at force / (nu k^2 K(k)) */
static double kernel_profile(double g, double nu, double h, double L, double y)
{
    static double kf[1000], kh = -1, kL = -1;
    double v = 0;
    int n;
    if (kh != h || kL != L) {
        for (n = 1; n < 2000; n += 2) kf[n / 2] = hcbd_m4_shear_factor(2 * PI_ * n / L, h);
        kh = h;
        kL = L;
    }
    for (n = 1; n < 2000; n += 2) {
        double k = 2 * PI_ * n / L;
        v += -4 * g / (n * PI_) / (nu * k * k * kf[n / 2]) * sin(k * y);
    }
    return v;
}

/* integral of 4 pi r^2 r^2 w(r) for the RaPiD kernel (<r^2>_w), Simpson on
   [0, sigma] and [sigma, rc] */
static double rapid_r2(double sg, double rc)
{
    const int n = 2000;
    double s = 0, lo, hi;
    int piece, k;
    for (piece = 0; piece < 2; ++piece) {
        double hs;
        lo = piece ? sg : 0;
        hi = piece ? rc : sg;
        hs = (hi - lo) / n;
        for (k = 0; k <= n; ++k) {
            double r = lo + k * hs, c = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
            s += c * hs / 3 * 4 * PI_ * r * r * r * r * hcbd_rapid_w(r, sg, rc);
        }
    }
    return s;
}

/* Reverse Poiseuille: the fluid's slab profile against the parabola; with
   np polymers also their lag.  One slab per lattice row (nyf rows); 12
   time units of transient, then 5 blocks over 8, sampled every 0.2. */
static void run_poiseuille(const char *metric, double dt, double h, int integ, int nsub, int nyf,
                           int np)
{
    const int nxz = sites_for(h, 5), N = nxz * nyf * nxz, nb = 5;
    const double g = 0.05, nu = 1.0;
    hcbd_hc_world_def d = scene(nxz, nyf, nxz, h, dt, integ, nsub, np);
    hcbd_hc_world w;
    const double L = d.params.L[1], W = 0.5 * L, A = g / (2 * nu);
    double *xyz, *v, mean = 0, l2b[5], l2, el2, tot_v[16] = {0}, tot_f[16] = {0}, tot_y[16] = {0};
    double S1 = 0, S2 = 0, floor_num = 0, floor_den = 0, lag = NAN, Afit = NAN;
    double tot_n[16] = {0};
    long Np = 0;
    int i, s, b, k, every = (int)(0.2 / dt + 0.5), per, ntr;
    double kv_num = 0, kv_den = 0;
    char cfg[128];
    if (every < 1) every = 1;
    per = (int)(8.0 * tscale / (every * dt) / nb + 0.5);
    if (per < 1) per = 1;
    ntr = (int)(12.0 * tscale / dt + 0.5);
    d.params.fluctuations = 0;
    d.params.reverse_poiseuille = 1;
    d.params.g[0] = g;
    if (!make(&w, &d)) return;
    xyz = (double *)malloc(3 * sizeof(double) * N);
    v = (double *)calloc(3 * (size_t)N, sizeof(double));
    for (i = 0; i < N; ++i) {
        xyz[3 * i] = w.fx[i];
        xyz[3 * i + 1] = w.fy[i];
        xyz[3 * i + 2] = w.fz[i];
        v[3 * i] = kernel_profile(g, nu, h, L, w.fy[i]);
        mean += v[3 * i] / N;
    }
    for (i = 0; i < N; ++i) v[3 * i] -= mean;
    /* start on the kernel-smoothed profile: the transient left is small */
    if (hcbd_hc_world_set_fluid(&w, N, xyz, v) != HCBD_OK ||
        (np && hcbd_hc_world_place_polymers_random(&w, np) != HCBD_OK)) {
        printf("    Poiseuille set-up: %s\n", w.err.msg);
        free(xyz);
        free(v);
        hcbd_hc_world_destroy(&w);
        return;
    }
    free(xyz);
    free(v);
    timer_reset();
    if (!step(&w, ntr)) { hcbd_hc_world_destroy(&w); return; }
    for (b = 0; b < nb; ++b) {
        double bv[16] = {0}, bf[16] = {0}, bn[16] = {0}, num = 0, den = 0;
        for (k = 0; k < per; ++k) {
            double com = 0;
            if (!step(&w, every)) { hcbd_hc_world_destroy(&w); return; }
            for (i = 0; i < w.nf; ++i) com += w.fvx[i];
            com /= w.nf;
            for (i = 0; i < w.nf; ++i) {
                double y = w.fy[i];
                int sl = (int)(y / L * nyf);
                if (sl < 0) sl = 0;
                if (sl >= nyf) sl = nyf - 1;
                bv[sl] += w.fvx[i] - com;
                bf[sl] += rp_shape(y, L);
                bn[sl] += 1;
                tot_y[sl] += y;
            }
            for (i = 0; i < w.np; ++i) {
                double y = w.py[i], up = y >= W ? 1 : -1, yy = y >= W ? y - W : y;
                S1 += up * (w.pux[i] - com);
                S2 += yy * (W - yy);
                ++Np;
            }
        }
        for (s = 0; s < nyf; ++s) {
            double e;
            if (bn[s] == 0) continue;
            e = bv[s] / bn[s] - A * bf[s] / bn[s];
            num += e * e;
            den += A * A * bf[s] * bf[s] / (bn[s] * bn[s]);
            tot_v[s] += bv[s];
            tot_f[s] += bf[s];
            tot_n[s] += bn[s];
        }
        l2b[b] = sqrt(num / den);
    }
    hcbd_hc_world_destroy(&w);
    mean_err(l2b, nb, &l2, &el2);
    { /* all samples together; the kernel-smoothing floor at the slab means */
        double num = 0, den = 0, fv = 0, ff = 0;
        for (s = 0; s < nyf; ++s) {
            double vs, fs, ys, kp;
            if (tot_n[s] == 0) continue;
            vs = tot_v[s] / tot_n[s];
            fs = tot_f[s] / tot_n[s];
            ys = tot_y[s] / tot_n[s];
            num += (vs - A * fs) * (vs - A * fs);
            den += A * A * fs * fs;
            fv += fs * vs;
            ff += fs * fs;
            kp = kernel_profile(g, nu, h, L, ys);
            floor_num += (kp - A * rp_shape(ys, L)) * (kp - A * rp_shape(ys, L));
            floor_den += A * A * rp_shape(ys, L) * rp_shape(ys, L);
            kv_num += (vs - kp) * (vs - kp);
            kv_den += kp * kp;
        }
        l2 = sqrt(num / den);
        Afit = fv / ff;
    }
    if (Np > 0) {
        const double dy2 = rapid_r2(d.params.sigma, d.params.rc) / 3;
        lag = -(S1 - Afit * S2 + Afit * dy2 * Np) / Np / (Afit * W * W / 4);
    }
    if (np)
        snprintf(cfg, sizeof cfg, "fluid dt=%g x%d, polymer dt=%g, Nf=%d Np=%d nu_fit=%.4f lag=%.4f",
                 dt / nsub, nsub, dt, N, np, A / Afit, lag);
    else
        snprintf(cfg, sizeof cfg, "%s dt=%g h=%g N=%d nu_fit=%.4f kernel-floor=%.4f L2-vs-kernel=%.4f",
                 integ == HCBD_PAIR_SHARDLOW ? "shardlow" : "euler", dt, h, N, A / Afit,
                 sqrt(floor_num / floor_den), sqrt(kv_num / kv_den));
    add_row(metric, integ, dt, h, nsub, l2, el2, cfg);
}

int main(int argc, char **argv)
{
    static const char *metrics[4] = {"temperature", "nu", "poiseuille_l2", "poiseuille_l2_solution"};
    char out[512] = "out/bench", path[600];
    FILE *csv;
    double t_start = now();
    int k, m;
    for (k = 1; k < argc; ++k) {
        if (!strncmp(argv[k], "quick=", 6)) quick = atoi(argv[k] + 6);
        else if (!strncmp(argv[k], "out=", 4)) snprintf(out, sizeof out, "%s", argv[k] + 4);
        else if (!strncmp(argv[k], "only=", 5)) snprintf(only, sizeof only, "%s", argv[k] + 5);
        else {
            fprintf(stderr, "bench_wp_hcbd: unknown argument '%s' (quick=, out=, only=)\n", argv[k]);
            return 2;
        }
    }
    tscale = quick ? 0.25 : 1.0;
    printf("# bench_wp_hcbd: HCBD fluid, %s, %s; m = 100, nu = 1, c_s = 2.5, nbar = 3/(4 pi)\n",
           prec(), quick ? "quick" : "full");
    printf("%-23s %-8s %6s %4s %2s %10s %10s %9s  %s\n", "metric", "integr", "dt", "h", "k",
           "s/time", "error", "+-", "config");
    if (!*only || !strcmp(only, "temperature")) { /* temperature: dt sweep at h = 2, both integrators; h sweep */
        const double dte[4] = {0.01, 0.02, 0.04, 0.08}, dts[4] = {0.02, 0.04, 0.08, 0.16};
        for (k = quick ? 1 : 0; k < 4; ++k) run_temperature(dte[k], 2.0, HCBD_PAIR_EULER);
        for (k = 0; k < 4; ++k) run_temperature(dts[k], 2.0, HCBD_PAIR_SHARDLOW);
        run_temperature(0.04, 1.5, HCBD_PAIR_EULER);
        run_temperature(0.04, 2.5, HCBD_PAIR_EULER);
        run_temperature(0.08, 1.5, HCBD_PAIR_SHARDLOW);
        run_temperature(0.08, 2.5, HCBD_PAIR_SHARDLOW);
    }
    if (!*only || !strcmp(only, "nu")) { /* nu at the smallest k: dt and h */
        const double dtn[3] = {0.04, 0.08, 0.16}, hs[3] = {1.5, 2.0, 2.5};
        for (k = 0; k < 3; ++k) run_nu(dtn[k], 2.0, HCBD_PAIR_EULER);
        for (k = 0; k < 3; ++k) run_nu(dtn[k], 2.0, HCBD_PAIR_SHARDLOW);
        for (k = 0; k < 3; ++k)
            if (hs[k] != 2.0) run_nu(0.04, hs[k], HCBD_PAIR_EULER);
    }
    if (!*only || !strcmp(only, "poiseuille")) { /* reverse Poiseuille, fluid alone */
        const double dtp[3] = {0.04, 0.08, 0.16}, hs[2] = {1.5, 2.5};
        for (k = 0; k < 3; ++k) run_poiseuille("poiseuille_l2", dtp[k], 2.0, HCBD_PAIR_EULER, 1, 10, 0);
        for (k = 0; k < 3; ++k) run_poiseuille("poiseuille_l2", dtp[k], 2.0, HCBD_PAIR_SHARDLOW, 1, 10, 0);
        for (k = 0; k < 2; ++k) run_poiseuille("poiseuille_l2", 0.04, hs[k], HCBD_PAIR_EULER, 1, 10, 0);
    }
    if (!*only || !strcmp(only, "solution")) { /* polymer solution: multiple time stepping at fluid step 0.04 */
        const int nf = 5 * 8 * 5;
        run_poiseuille("poiseuille_l2_solution", 0.04, 2.0, HCBD_PAIR_EULER, 1, 8, 5 * nf);
        run_poiseuille("poiseuille_l2_solution", 0.08, 2.0, HCBD_PAIR_EULER, 2, 8, 5 * nf);
        run_poiseuille("poiseuille_l2_solution", 0.16, 2.0, HCBD_PAIR_EULER, 4, 8, 5 * nf);
        run_poiseuille("poiseuille_l2_solution", 0.08, 2.0, HCBD_PAIR_EULER, 1, 8, 5 * nf);
        run_poiseuille("poiseuille_l2_solution", 0.16, 2.0, HCBD_PAIR_EULER, 1, 8, 5 * nf);
    }
    for (k = 0; k < NMELT; ++k) free(melt_xyz[k]);

    csv = bench_csv("bench_wp_hcbd", out, sizeof(hcbd_real) == 4 ? "wp_hcbd_float.csv" : "wp_hcbd.csv",
                    path, sizeof path);
    if (!csv) return 1;
    fprintf(csv, "model,metric,integrator,precision,noise,dt,h,substeps,seconds_per_time_unit,"
                 "error,error_err,config\n");
    for (k = 0; k < nrows; ++k) {
        row *r = &rows[k];
        char *c;
        for (c = r->config; *c; ++c)
            if (*c == ',') *c = ';'; /* one CSV field */
        fprintf(csv, "hcbd,%s,%s,%s,gauss,%.6g,%.6g,%d,%.6g,%.6g,%.6g,%s\n", r->metric,
                r->integ == HCBD_PAIR_SHARDLOW ? "shardlow" : "euler", prec(), r->dt, r->h,
                r->substeps, r->spt, r->err, r->err_err, r->config);
    }
    fclose(csv);
    for (m = 0; m < 4; ++m) {
        int best = -1;
        for (k = 0; k < nrows; ++k)
            if (!strcmp(rows[k].metric, metrics[m]) && rows[k].err < 0.01 &&
                (best < 0 || rows[k].spt < rows[best].spt))
                best = k;
        if (best < 0)
            printf("cheapest <1%%: model=hcbd, metric=%s, config=none below 1 %%, cost=-\n", metrics[m]);
        else
            printf("cheapest <1%%: model=hcbd, metric=%s, config=%s, cost=%.4g s per time unit "
                   "(error %.4f +- %.4f)\n",
                   metrics[m], rows[best].config, rows[best].spt, rows[best].err, rows[best].err_err);
    }
    printf("wrote %s (%d rows, %.0f s)\n", path, nrows, now() - t_start);
    return 0;
}
