/* gibd_bulk: Galilean-invariant, momentum-conserving Brownian dynamics of
   star polymers in the bulk.

   Reproduces the quantities of Padding & Briels 2014 (J. Chem. Phys. 141,
   244108), Figs. 2-6, and Ahuja et al. 2016 (J. Chem. Phys. 145, 194903),
   Figs. 1-4, one parameter set per run:
     Fig. 2 / 2016 Fig. 1  g(r) of the star centres             rdf.csv
     Fig. 3 / 2016 Fig. 3,4 mean-squared displacement            msd.csv
     Fig. 4 / 2016 Fig. 2  stress relaxation G(t) (2014 eq. 30)  gt.csv
     Fig. 5                transverse current C_t(k,t)/C_t(k,0)  ct.csv
                           at k = 2 pi n / L, n = 1, 2, 3, with
                           exp(-nu k^2 t) (2014 eq. 33)
     Fig. 6                background-velocity autocorrelation vacf.csv
                           with its t^-3/2 tail (2014 eq. 34)
   Sweep a parameter with a shell loop, e.g. the four tau of 2014 Fig. 3:
     for t in 3.6e-4 3.6e-3 3.6e-2 3.6e-1; do
         build/gibd_bulk preset=paper tau=$t out=out/tau$t; done
   and dynamics=bd gives the classical-BD reference curve; gdot=... shears
   the box (Lees-Edwards) and reports the viscosity of each stress
   contribution.

   What to look for: statics (g(r)) do not depend on tau or xi'; dynamics do.
   The background temperature equals kT up to the Euler bias
   (dt/2tau)<sum f>.  The transverse current starts decaying at exactly the
   configurational friction average (nu_initial = nu_meanfield / (1 -
   S(k)/N), the factor because total momentum is exactly zero in a finite
   box), then more slowly (nu_hydro).  For ideal particles the MSD follows 2016 eq. 32 for
   t <= tau and diffuses faster than eq. 33 at long times (momentum flows
   back from neighbours).

   Arguments are key=value (see usage()).  The summary at the end is one
   key=value per line. */
#include "example_common.h"

#define PI 3.14159265358979323846

static double coord_r = NAN; /* coord_r: a fixed radius for the coordination */

static void usage(FILE *f)
{
    fprintf(f,
            "usage: gibd_bulk [key=value ...]\n"
            "  preset=quick|paper  quick (default): 40000 steps; paper: 10^6 steps\n"
            "  N density dt kT xi xip tau Rc f sigma rcut skin gdot  physical parameters\n"
            "                      (gdot: Lees-Edwards shear rate, reports the viscosity)\n"
            "  Lx Ly Lz            box edges (default: cube of N/density)\n"
            "  potential=star|ideal  dynamics=gibd|bd  density_norm=2014|2016\n"
            "  lagged=0|1 noise=gauss|uniform pair=shardlow|euler\n"
            "  brownian=lm|euler seed steps threads out\n"
            "  coord_r=r           the coordination within r (default: g(r)'s first minimum)\n"
            "  xyz=FILE xyz_every=k  extended XYZ frames (OVITO) every k steps\n"
            "  thermo_every=k      a thermo line every k steps\n"
            "  checkpoint=FILE     save the world at the end; restart=FILE  start from\n"
            "                      a checkpoint (its parameters, no equilibration)\n");
}

static int own_key(config *c, const char *key, const char *v)
{
    double d;
    if (!strcmp(key, "preset")) return check_preset(c, v);
    if (!strcmp(key, "coord_r")) {
        if (!parse_double(c, key, v, &d)) return 0;
        coord_r = d;
        return 1;
    }
    if (!strcmp(key, "gdot")) {
        if (!parse_double(c, key, v, &d)) return 0;
        c->def.params.gdot = d;
        return 1;
    }
    return -1;
}

/* Least-squares initial rate of a discrete decay: y(s) = 1 - C(s)/C(0) =
   a s + b s (s - 1) over the lags with C/C(0) > 0.75; the basis makes a the
   one-step decrement of a geometric decay (1 - a)^s to second order (lags
   up to 64 steps: C_t is not a single exponential, and longer fits bend
   the slope). */
static double initial_rate(const double *lag, const double *c, int n, double dt)
{
    double a11 = 0, a12 = 0, a22 = 0, b1 = 0, b2 = 0;
    int k;
    for (k = 1; k < n && lag[k] < 64 && c[k] / c[0] > 0.75; ++k) {
        double s = lag[k], u = s * (s - 1), y = 1 - c[k] / c[0];
        a11 += s * s; a12 += s * u; a22 += u * u;
        b1 += s * y; b2 += u * y;
    }
    if (k < 3) return NAN;
    return (b1 * a22 - b2 * a12) / (a11 * a22 - a12 * a12) / dt;
}

/* Rate of the later, exponential decay: slope of ln C over the lags with
   lo < C/C0 < hi. */
static double late_rate_in(const double *lag, const double *c, int n, double dt, double lo,
                           double hi)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int k, m = 0;
    for (k = 1; k < n; ++k) {
        double r = c[k] / c[0], t = lag[k] * dt;
        if (r > hi || r < lo) continue;
        sx += t; sy += log(r); sxx += t * t; sxy += t * log(r);
        ++m;
    }
    if (m < 3) return NAN;
    return -(m * sxy - sx * sy) / (m * sxx - sx * sx);
}

/* Over 0.5 > C/C0 > 0.1, or, where the decay is too fast for three of the
   sparse multiple-tau lags there, over 0.8 > C/C0 > 0.03. */
static double late_rate(const double *lag, const double *c, int n, double dt)
{
    double r = late_rate_in(lag, c, n, dt, 0.1, 0.5);
    return r == r ? r : late_rate_in(lag, c, n, dt, 0.03, 0.8);
}

/* Long-time diffusion and its block error: slope / 6 of the MSD over the
   lags t > 5 tau (where the velocity memory e^(-t/tau) of eq. 32 is below
   1 %); NaN when the blocks are too short.  dts is the time between MSD
   samples. */
static double long_time_D(const hcbd_msd *msd, double dts, double tau, double *err)
{
    double D = NAN;
    *err = NAN;
    if (hcbd_msd_diffusion(msd, 5 * tau / dts, 1e300, &D, err) != HCBD_OK) return NAN;
    *err /= dts;
    return D / dts;
}

/* The first minimum of g(r) after its main peak (bins of width dr), where
   the first coordination shell ends; NaN without a peak above 1.05. */
static double first_minimum(const double *r, const double *g, int n)
{
    int k, peak = 0;
    for (k = 1; k < n; ++k)
        if (g[k] > g[peak]) peak = k;
    if (g[peak] < 1.05) return NAN;
    for (k = peak + 1; k + 1 < n; ++k)
        if (g[k] <= g[k - 1] && g[k] <= g[k + 1]) return r[k];
    return NAN;
}

/* MSD at time t by log-log interpolation between the bracketing lags. */
static double msd_at(const double *lag, const double *m, int n, double dt, double t)
{
    int k;
    for (k = 1; k < n; ++k)
        if (lag[k] * dt >= t) {
            double t0 = lag[k - 1] * dt, t1 = lag[k] * dt;
            double u = (log(t) - log(t0)) / (log(t1) - log(t0));
            return exp(log(m[k - 1]) + u * (log(m[k]) - log(m[k - 1])));
        }
    return NAN;
}

int main(int argc, char **argv)
{
    enum { NB = 10, PC = 32, LEVC = 16, PV = 16, LEVV = 16, NRDF = 100, BMSD = 10 };
    config c;
    hcbd_world w;
    hcbd_params *p;
    hcbd_mtcorr ct[NB][3], gt, vacf;
    hcbd_msd msd;
    hcbd_rdf rdf;
    run_out ro;
    double rdf_mem[6 * NRDF], *xyz, *vel, V, k1, nu_theory, rdf_max;
    double Tblk[NB], nu_init_b[NB], nu_hydro_b[NB], mf_b[NB], eff_b[NB], ident_b[NB];
    double mf = 0, eff = 0, sumf = 0, sk = 0, rdf_min, coord = NAN, coord_err = NAN;
    int nmf = 0, b, s, k, gibd, blk_steps, msd_levels = 1;
    size_t bytes_ct = hcbd_mtcorr_bytes(12, PC, 2, LEVC), bytes_gt, bytes_v, bytes_msd;
    void *mem_ct, *mem_gt, *mem_v, *mem_msd;
    struct timespec t0;
    FILE *f;

    memset(&c, 0, sizeof c);
    c.name = "gibd_bulk";
    c.def = hcbd_world_def_default();
    c.N = 512;
    c.density = 0.24;
    c.steps = 40000;
    snprintf(c.out, sizeof c.out, "out/gibd_bulk");
    if (!expand_args(&c, &argc, &argv)) return 2;
    for (k = 1; k < argc; ++k) /* the preset first: explicit keys override it */
        if (!strcmp(argv[k], "preset=paper")) c.steps = 1000000;
    if (!parse_args(argc, argv, &c, own_key, usage)) return c.help ? 0 : 2;
    p = &c.def.params;
    gibd = p->dynamics == HCBD_DYN_GIBD;
    if (!world_start(&c, &w)) return 2;
    print_limits(p);
    mkdirs(c.out);
    write_run_conf(&c);
    V = p->L[0] * p->L[1] * p->L[2];
    k1 = 2 * PI / p->L[0];
    nu_theory = p->Rc * p->Rc / (28 * p->tau);
    printf("gibd_bulk: %s, %s, N = %d, box %.3g x %.3g x %.3g, n# = %g, dt = %g, tau = %g, "
           "xi = %g, xi' = %g, kT = %g, steps = %d, threads = %d\n",
           gibd ? "GI-BD" : "classical BD", p->potential == HCBD_POT_STAR ? "star polymers" : "ideal particles",
           c.N, p->L[0], p->L[1], p->L[2], c.density, p->dt, p->tau, p->xi, p->xip, p->kT, c.steps,
           p->threads);
    fflush(stdout);
    if (gibd && p->tau < 10 * p->dt)
        printf("warning: tau = %g < 10 dt breaks 2014 eq. 27; expect an Euler bias of "
               "about %.0f %% in the temperature\n", p->tau, 50 * p->dt / p->tau);

    xyz = (double *)malloc(3 * (size_t)c.N * sizeof(double));
    vel = (double *)malloc(3 * (size_t)c.N * sizeof(double));
    bytes_gt = hcbd_mtcorr_bytes(3, PC, 2, LEVC);
    bytes_v = hcbd_mtcorr_bytes(3 * c.N, PV, 2, LEVV);
    /* MSD samples every 5 steps, one block of them per NB-th of the run;
       levels up to the block length, one level denser than the book's
       order-n scheme */
    blk_steps = c.steps / NB;
    while (msd_levels < 6 && pow(BMSD, msd_levels) < blk_steps / 5) ++msd_levels;
    bytes_msd = hcbd_msd_bytes(c.N, BMSD, msd_levels, 1);
    mem_ct = malloc(NB * 3 * bytes_ct);
    mem_gt = malloc(bytes_gt);
    mem_v = malloc(bytes_v);
    mem_msd = malloc(bytes_msd);
    if (!xyz || !vel || !mem_ct || !mem_gt || !mem_v || !mem_msd) {
        fprintf(stderr, "gibd_bulk: out of memory\n");
        return 2;
    }
    hcbd_mtcorr_init(&gt, 3, PC, 2, LEVC, mem_gt, bytes_gt);
    hcbd_mtcorr_init(&vacf, 3 * c.N, PV, 2, LEVV, mem_v, bytes_v);
    hcbd_msd_init(&msd, c.N, BMSD, msd_levels, 1, (blk_steps + 4) / 5, mem_msd, bytes_msd);
    rdf_max = fmin(0.5 * fmin(p->L[0], fmin(p->L[1], p->L[2])), 5.0);
    hcbd_rdf_init(&rdf, rdf_max, NRDF, (blk_steps + 199) / 200, rdf_mem, sizeof rdf_mem);

    /* equilibrate from a lattice: a tenth of the run, at least 5000 steps */
    if (!c.restart[0]) {
        const int eq = c.steps / 10 > 5000 ? c.steps / 10 : 5000;
        printf("gibd_bulk: %d steps of equilibration from a lattice first, not measured (the trajectory's "
               "and thermo's Step= count them: the measured steps are %d..%d)\n", eq, eq, eq + c.steps);
        fflush(stdout);
        hcbd_world_place_lattice(&w, c.N);
        if (hcbd_world_step(&w, eq) != HCBD_OK) {
            fprintf(stderr, "gibd_bulk: %s\n", w.err.msg);
            return 1;
        }
    }
    if (!run_out_open(&c, &ro, &w, NULL)) return 2;
    if (p->gdot != 0.0 && !w.core.stress_on) hcbd_world_stress_enable(&w, 1); /* a restart keeps its sums */
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (b = 0; b < NB; ++b) {
        double Tb = 0, mfb = 0, effb = 0, sfb = 0, fk[3] = {0, 0, 0}, skb[3] = {0, 0, 0};
        int nTb = 0, nmb = 0;
        for (k = 0; k < 3; ++k)
            hcbd_mtcorr_init(&ct[b][k], 12, PC, 2, LEVC, (char *)mem_ct + (b * 3 + k) * bytes_ct, bytes_ct);
        for (s = 0; s < blk_steps; ++s) {
            const int g = b * blk_steps + s; /* samples evenly spaced across blocks */
            if (gibd) {
                double j[12];
                for (k = 0; k < 3; ++k) {
                    hcbd_world_transverse_current(&w, k + 1, j);
                    hcbd_mtcorr_add(&ct[b][k], j);
                }
                hcbd_world_get_velocities(&w, vel);
                hcbd_mtcorr_add(&vacf, vel);
                if (g % 10 == 0) { Tb += hcbd_world_temperature(&w); ++nTb; }
                if (g % 50 == 0) {
                    double out[3];
                    int i, a;
                    /* S(k) = |rho_k|^2 / N: with total momentum exactly
                       zero, C_t(k,0) = (kT/m)(1 - S(k)/N) */
                    hcbd_world_get_positions(&w, xyz, 0);
                    for (k = 2; k >= 0; --k) {
                        hcbd_world_friction_average(&w, k + 1, out);
                        fk[k] += out[2];
                        for (a = 0; a < 3; ++a) {
                            double re = 0, im = 0, ka = 2 * PI * (k + 1) / p->L[a];
                            for (i = 0; i < c.N; ++i) {
                                re += cos(ka * xyz[3 * i + a]);
                                im += sin(ka * xyz[3 * i + a]);
                            }
                            skb[k] += (re * re + im * im) / c.N / 3;
                        }
                    }
                    /* out: k = 2 pi / L, the last one asked for */
                    mfb += out[2] / (p->tau * k1 * k1);
                    effb += out[1] / (6 * p->tau);
                    sfb += out[0];
                    ++nmb;
                }
            }
            if (p->potential != HCBD_POT_IDEAL && g % 5 == 0) {
                double st[9], o[3];
                hcbd_world_virial_stress(&w, st);
                o[0] = st[1]; o[1] = st[2]; o[2] = st[5];
                hcbd_mtcorr_add(&gt, o);
            }
            if (g % 5 == 0) {
                hcbd_world_get_positions(&w, xyz, 1);
                hcbd_msd_add(&msd, xyz);
            }
            if (g % 200 == 0) hcbd_rdf_sample(&rdf, &w);
            if (run_steps(&c, &ro, &w, 1) != HCBD_OK) {
                fprintf(stderr, "gibd_bulk: %s\n", w.err.msg);
                return 1;
            }
        }
        if (gibd) {
            double lag[512], cc[512];
            int n;
            for (k = 0; k < 3; ++k) hcbd_mtcorr_finalize(&ct[b][k]);
            n = hcbd_mtcorr_result(&ct[b][0], 1, lag, cc, NULL, 512);
            nu_init_b[b] = initial_rate(lag, cc, n, p->dt) / (k1 * k1) - p->kT / p->xi;
            nu_hydro_b[b] = late_rate(lag, cc, n, p->dt) / (k1 * k1) - p->kT / p->xi;
            sk += skb[0];
            /* the initial-decay identity at k, 2k, 3k: measured rate over
               (1/tau) <sum_j f_ij (1 - cos k.x_ij)> / (1 - S(k)/N) + k^2 kT/xi,
               weighted by k^2 (the relative error of a rate falls as
               1/k: the larger k resolve it better than k alone) */
            ident_b[b] = 0;
            for (k = 0; k < 3; ++k) {
                double kk = (k + 1) * k1, rate, pred;
                n = hcbd_mtcorr_result(&ct[b][k], 1, lag, cc, NULL, 512);
                rate = initial_rate(lag, cc, n, p->dt);
                pred = fk[k] / nmb / p->tau / (1 - skb[k] / nmb / c.N) + kk * kk * p->kT / p->xi;
                ident_b[b] += (k + 1) * (k + 1) / 14.0 * rate / pred;
            }
            Tblk[b] = Tb / nTb / p->kT;
            mf_b[b] = mfb / nmb;
            eff_b[b] = effb / nmb;
            mf += mfb; eff += effb; sumf += sfb; nmf += nmb;
        }
        progress(&c, (b + 1) * blk_steps, NB * blk_steps, &t0);
    }

    /* ---- CSV output ---- */
    {
        double r[NRDF], g[NRDF], ge[NRDF];
        hcbd_rdf_result(&rdf, r, g, ge);
        if ((f = open_out(&c, "rdf.csv"))) {
            fprintf(f, "r,g,g_err\n");
            for (k = 0; k < NRDF; ++k) fprintf(f, "%.6g,%.6g,%.3g\n", r[k], g[k], ge[k]);
            fclose(f);
        }
        /* an ideal gas has no shell (its g(r) is 1 within the noise) */
        rdf_min = isfinite(coord_r) ? coord_r
                  : p->potential == HCBD_POT_IDEAL ? NAN : first_minimum(r, g, NRDF);
        if (isfinite(rdf_min)) hcbd_rdf_coordination(&rdf, rdf_min, &coord, &coord_err);
    }
    {
        double lag[128], m[128], me[128], th;
        int n = hcbd_msd_stats(&msd, lag, m, me, 128);
        if ((f = open_out(&c, "msd.csv"))) {
            /* msd: mean of the NB blocks, msd_err its standard error */
            fprintf(f, "t,msd,eq32,msd_err\n");
            for (k = 0; k < n; ++k) {
                double t = lag[k] * 5 * p->dt;
                th = gibd ? 6 * p->kT / p->xip * (t - p->tau * (1 - exp(-t / p->tau))) + 6 * p->kT / p->xi * t
                          : 6 * p->kT / p->xi * t;
                fprintf(f, "%.6g,%.6g,%.6g,%.3g\n", t, m[k], th, me[k]);
            }
            fclose(f);
        }
    }
    if (p->potential != HCBD_POT_IDEAL && (f = open_out(&c, "gt.csv"))) {
        double lag[512], cc[512];
        int n;
        hcbd_mtcorr_finalize(&gt);
        n = hcbd_mtcorr_result(&gt, 10, lag, cc, NULL, 512);
        fprintf(f, "t,G\n");
        for (k = 0; k < n; ++k) fprintf(f, "%.6g,%.6g\n", lag[k] * 5 * p->dt, V / p->kT * cc[k]);
        fclose(f);
    }
    if (gibd) {
        double lag[3][512], cc[3][512], acc[3][512] = {{0}}, rs[3][512] = {{0}}, rs2[3][512] = {{0}};
        int n[3], kk;
        for (kk = 0; kk < 3; ++kk) {
            for (b = 0; b < NB; ++b) {
                n[kk] = hcbd_mtcorr_result(&ct[b][kk], 1, lag[kk], cc[kk], NULL, 512);
                for (k = 0; k < n[kk]; ++k) {
                    acc[kk][k] += cc[kk][k] / NB;
                    /* each block's own C_t/C_t(0): their spread is the
                       block error of the figure */
                    rs[kk][k] += cc[kk][k] / cc[kk][0];
                    rs2[kk][k] += cc[kk][k] / cc[kk][0] * (cc[kk][k] / cc[kk][0]);
                }
            }
        }
        if ((f = open_out(&c, "ct.csv"))) {
            /* eq13: the paper's exp(-nu k^2 t), nu = Rc^2/(28 tau), for ideal
               particles; eff: nu_eff = <sum f r^2>/(6 tau) of this run plus the
               Brownian kT/xi, the small-k rate for interacting particles;
               ct_k*_err: standard error of the NB block values */
            double nu_e = nmf ? eff / nmf + p->kT / p->xi : NAN;
            fprintf(f, "t,ct_k1,ct_k2,ct_k3,eq13_k1,eq13_k2,eq13_k3,eff_k1,eff_k2,eff_k3,"
                       "ct_k1_err,ct_k2_err,ct_k3_err\n");
            for (k = 0; k < n[0] && k < n[1] && k < n[2]; ++k) {
                double t = lag[0][k] * p->dt;
                fprintf(f, "%.6g", t);
                for (kk = 0; kk < 3; ++kk) fprintf(f, ",%.6g", acc[kk][k] / acc[kk][0]);
                for (kk = 0; kk < 3; ++kk) fprintf(f, ",%.6g", exp(-nu_theory * pow((kk + 1) * k1, 2) * t));
                for (kk = 0; kk < 3; ++kk) fprintf(f, ",%.6g", exp(-nu_e * pow((kk + 1) * k1, 2) * t));
                for (kk = 0; kk < 3; ++kk) {
                    double m = rs[kk][k] / NB;
                    fprintf(f, ",%.3g", sqrt(fmax(rs2[kk][k] / NB - m * m, 0) / (NB - 1)));
                }
                fprintf(f, "\n");
            }
            fclose(f);
        }
        if ((f = open_out(&c, "vacf.csv"))) {
            double lagv[512], cv[512];
            int nv;
            hcbd_mtcorr_finalize(&vacf);
            nv = hcbd_mtcorr_result(&vacf, 10, lagv, cv, NULL, 512);
            fprintf(f, "t,vacf,tail_eq34\n");
            /* eq. 34 with the measured long-time diffusion of the run */
            double De, D = long_time_D(&msd, 5 * p->dt, p->tau, &De);
            for (k = 0; k < nv; ++k) {
                double t = lagv[k] * p->dt, nu_e = eff / nmf;
                /* 3 cv: the correlator averages over the 3N components */
                fprintf(f, "%.6g,%.6g,%.6g\n", t, 3 * cv[k],
                        t > 0 ? 2 * p->kT / (c.density * w.m * pow(4 * PI * (nu_e + D) * t, 1.5)) : NAN);
            }
            fclose(f);
        }
    }
    if ((f = open_out(&c, "plots.gp"))) {
        /* reduced units of the 2014/2016 scene (docs/MODEL.md 9): length
           sigma, energy kT, time xi sigma^2 / kT */
        const int ideal = p->potential == HCBD_POT_IDEAL;
        const char *tu = "t / (" GP_XI GP_SIGMA "^2/kT)";
        char scene[320], pot[64];
        double Dl_err, Dl = long_time_D(&msd, 5 * p->dt, p->tau, &Dl_err);
        double nu_eff = nmf ? eff / nmf : NAN;
        if (ideal) snprintf(pot, sizeof pot, "ideal particles");
        else if (p->potential == HCBD_POT_STAR) snprintf(pot, sizeof pot, "star polymers (f = %g)", p->f);
        else snprintf(pot, sizeof pot, "tabulated potential");
        if (gibd)
            snprintf(scene, sizeof scene, "GI-BD, %s, N = %d, n_# = %g, " GP_TAU " = %g, " GP_XIP "/" GP_XI
                     " = %g, R_c = %g", pot, c.N, c.density, p->tau, p->xip / p->xi, p->Rc);
        else
            snprintf(scene, sizeof scene, "classical BD, %s, N = %d, n_# = %g", pot, c.N, c.density);
        gp_preamble(f, 900, 650);
        fprintf(f, "scene = \"%s\"\ntau = %.17g\n", scene, p->tau);
        fprintf(f, "set output 'rdf.png'\n"
                   "set title \"Radial distribution function of the particle centres\\n{/*0.85 \".scene.\"}\"\n"
                   "set xlabel 'r / " GP_SIGMA "'\nset ylabel 'g(r)'\nset key top right\n"
                   "set offsets 0, 0, graph 0.3, 0\n");
        if (isfinite(rdf_min))
            fprintf(f, "set arrow 1 from %.6g, graph 0 to %.6g, graph 1 nohead dt 3 lc 'gray40'\n", rdf_min, rdf_min);
        fprintf(f, "plot [0:%.6g] 'rdf.csv' u 1:2:3 w yerrorlines pt 7 ps 0.5 lc 1 t 'measured (block errors)', "
                   "1 w l dt 2 lc 'black' t '%s'",
                rdf_max, ideal ? "ideal gas, g = 1 (exact)" : "g = 1 (no correlation)");
        if (isfinite(rdf_min))
            fprintf(f, ", NaN w l dt 3 lc 'gray40' t 'first minimum r = %.4g " GP_SIGMA ": %.3f " GP_PM
                       " %.2g neighbours'", rdf_min, coord, coord_err);
        fprintf(f, "\nunset arrow 1\nset offsets 0, 0, 0, 0\n");
        /* MSD: 2016 eq. 32 is the ideal-particle result (and 6 kT t / xi
           exact for ideal classical BD); with interactions only the
           short-time limit (free Brownian steps) and the fitted long-time
           line are drawn */
        fprintf(f, "set output 'msd.png'\nset logscale xy\nset format xy '10^{%%L}'\n"
                   "set title \"Mean-squared displacement\\n{/*0.85 \".scene.\"}\"\n"
                   "set xlabel '%s'\nset ylabel 'MSD / " GP_SIGMA "^2'\nset key top left\nset autoscale xfix\n", tu);
        if (gibd)
            fprintf(f, "set arrow 2 from tau, graph 0 to tau, graph 1 nohead dt 3 lc 'gray40'\n"
                       "set label 2 ' t = " GP_TAU "' at tau, graph 0.06 tc 'gray40'\n");
        fprintf(f, "plot 'msd.csv' u 1:2:4 w yerrorlines pt 7 ps 0.8 lc 1 t 'measured (block errors)'");
        if (ideal && gibd)
            fprintf(f, ", '' u 1:3 w l dt 2 lw 2 lc 'black' t '2016 eq. 32: 6kT/" GP_XIP " [t - " GP_TAU
                       "(1 - e^{-t/" GP_TAU "})] + 6kT t/" GP_XI "'");
        else if (ideal)
            fprintf(f, ", '' u 1:3 w l dt 2 lw 2 lc 'black' t 'free diffusion 6kT t/" GP_XI " (exact)'");
        else
            fprintf(f, ", 6 * %.17g * x w l dt 2 lc 'black' t 'short-time limit 6kT t/" GP_XI
                       " (asymptote)'", p->kT / p->xi);
        if (isfinite(Dl)) {
            /* the intercept of the same least-squares line (hcbd_msd_diffusion
               returns the slope only): the mean MSD less 6 D times the mean t
               over the fitted lags */
            double lg[128], ms[128], st = 0, sm = 0;
            int nl = hcbd_msd_stats(&msd, lg, ms, NULL, 128), nf = 0;
            for (k = 0; k < nl; ++k)
                if (lg[k] >= p->tau / p->dt) { st += lg[k] * 5 * p->dt; sm += ms[k]; ++nf; }
            fprintf(f, ", (x >= %.17g ? 6 * %.17g * x + %.17g : 1/0) w l dt 4 lw 2 lc 2 "
                       "t 'long-time fit 6Dt + c, D = %.4g " GP_PM " %.2g (t " GP_GEQ " %g)'",
                    5 * p->tau, Dl, (sm - 6 * Dl * st) / nf, Dl, Dl_err, 5 * p->tau);
        }
        fprintf(f, "\nunset arrow 2\nunset label 2\n");
        if (!ideal)
            fprintf(f, "set output 'gt.png'\n"
                       "set title \"Stress relaxation modulus G(t) = (V/kT)" GP_LANGLE "S_{xy}(t) S_{xy}(0)"
                       GP_RANGLE " (2014 eq. 30)\\n{/*0.85 \".scene.\"}\"\n"
                       "set ylabel 'G(t) / (kT/" GP_SIGMA "^3)'\nset key top right\n"
                       "plot 'gt.csv' u 1:($2>0?$2:1/0) w lp pt 7 ps 0.6 lc 1 t 'measured, G > 0', "
                       "'' u 1:($2<0?-$2:1/0) w p pt 6 ps 0.6 lc 1 t '|G| where G < 0 (noise floor)'\n");
        if (gibd) {
            /* the mean-field decay of 2014 eq. 33 holds for ideal carriers;
               interacting ones decay at the friction network's nu_eff */
            char th[160], def[200];
            int pan;
            if (ideal) {
                snprintf(th, sizeof th, "exp(-" GP_NU "k^2t), " GP_NU " = %.4g", nu_theory);
                snprintf(def, sizeof def, GP_NU " = R_c^2/(28" GP_TAU "): mean field, 2014 eq. 33");
            } else {
                snprintf(th, sizeof th, "exp(-(" GP_NU "_{eff} + kT/" GP_XI ")k^2t), " GP_NU "_{eff} = %.4g", nu_eff);
                snprintf(def, sizeof def, GP_NU "_{eff} = " GP_LANGLE GP_SUM "_j f_{ij} r_{ij}^2" GP_RANGLE "/(6" GP_TAU
                         ") of this run: the friction network only");
            }
            /* (a) semilog, where an exponential is a straight line; (b)
               linear, where a negative undershoot shows */
            gp_terminal(f, 1500, 620);
            fprintf(f, "set output 'ct.png'\nunset logscale\nset format x '%%g'\nset format y '%%g'\n"
                       "set multiplot layout 1,2 title \"Transverse current at k = n 2" GP_PI "/L\\n"
                       "{/*0.85 \".scene.\"}\"\n"
                       "set xlabel '%s'\nset ylabel 'C_t(k,t) / C_t(k,0)'\n", tu);
            for (pan = 0; pan < 2; ++pan) {
                if (pan)
                    fprintf(f, "set title \"(b) linear scale; %s\" font ',11'\nunset logscale y\n"
                               "set yrange [-0.3:1.05]\nset key top right\n", def);
                else
                    fprintf(f, "set title '(a) log scale; error bars: block errors' font ',11'\nset logscale y\n"
                               "set yrange [0.01:1.05]\nunset key\n");
                fprintf(f, "plot for [i=1:3] 'ct.csv' u 1:(column(1+i)):(column(10+i)) w yerrorlines pt 7 ps 0.5 "
                           "lc i t sprintf('measured, n = %%d', i), \\\n"
                           "     for [i=1:3] '' u 1:(column(%d+i)) w l dt 2 lw 2 lc i notitle, "
                           "NaN w l dt 2 lw 2 lc 'black' t '%s'%s\n",
                        ideal ? 4 : 7, th, pan ? ", 0 w l lc 'gray40' notitle" : "");
            }
            fprintf(f, "unset multiplot\nunset yrange\nset title font ',13'\n");
            gp_terminal(f, 900, 650);
            fprintf(f, "set output 'vacf.png'\nset logscale xy\nset autoscale y\nset format xy '10^{%%L}'\n"
                       "set title \"Background-velocity autocorrelation\\n{/*0.85 \".scene.\"}\\n"
                       "{/*0.85 tail (2014 eq. 34): 2kT/(n_# m [4" GP_PI "(" GP_NU "_{eff} + D)t]^{3/2}), "
                       GP_NU "_{eff} = %.4g, D = %.4g (this run)}\" font ',13'\n"
                       "set ylabel '" GP_LANGLE "v(t)" GP_CDOT "v(0)" GP_RANGLE " / (kT/" GP_XI GP_SIGMA ")^2'\n"
                       "set key bottom left\n"
                       "plot 'vacf.csv' u 1:($2>0?$2:1/0) w lp pt 7 ps 0.6 lc 1 t 'measured, > 0', "
                       "'' u 1:($2<0?-$2:1/0) w p pt 6 ps 0.8 lc 1 t '|measured| where < 0', \\\n"
                       "     (x < tau ? %.17g : 1/0) w l dt 3 lw 2 lc 'black' t '3kT/m (equipartition)', \\\n"
                       "     '' u 1:($1 >= tau ? $3 : 1/0) w l dt 2 lw 2 lc 2 "
                       "t 'long-time tail, t " GP_GEQ " " GP_TAU "'\n",
                    nu_eff, Dl, 3 * p->kT / w.m);
        }
        fclose(f);
        make_figures(&c);
    }

    /* ---- summary ---- */
    printf("# summary (measured next to theory)\n");
    if (gibd) {
        double m, e, lag[128], mm[128], tau = p->tau, D_err;
        int n = hcbd_msd_stats(&msd, lag, mm, NULL, 128);
        double th_tau = 6 * p->kT / p->xip * tau * exp(-1.0) + 6 * p->kT / p->xi * tau;
        double D_th = p->kT / p->xi + p->kT / p->xip, D_meas = NAN;
        const double bias = p->dt / (2 * tau) * sumf / nmf; /* the Euler pairs' first-order excess */
        mean_err(Tblk, NB, &m, &e);
        printf("T_ratio=%.5f\nT_ratio_err=%.5f\n", m, e);
        if (p->pair_integrator == HCBD_PAIR_EULER)
            judge("T_ratio", m, e, "kT", 1.0 + bias, 0.1 * bias,
                  "1 + the Euler bias (dt/2tau)<sum f>, allowance 10 % of it for its higher orders", NULL);
        else
            judge("T_ratio", m, e, "kT", 1, 0, "equipartition", NULL);
        /* the temperature excess the papers' Euler pairs would give; the
           exact sweep (the default) has none */
        printf("pair=%s\nbrownian=%s\n", p->pair_integrator == HCBD_PAIR_EULER ? "euler" : "shardlow",
               p->brownian == HCBD_BROWNIAN_EULER ? "euler" : "lm");
        printf("euler_bias_first_order=%.5f\n", bias);
        printf("T_ratio_expected=%.5f\n", 1.0 + (p->pair_integrator == HCBD_PAIR_EULER
                                                  ? bias : 0.0));
        printf("sum_f=%.5f\n", sumf / nmf);
        printf("k=%.6g\n", k1);
        printf("nu_theory=%.6g\n", nu_theory);
        mean_err(mf_b, NB, &m, &e);
        printf("nu_meanfield=%.6g\nnu_meanfield_err=%.3g\n", m, e);
        judge("nu_meanfield", m, e, "sigma^2/time", nu_theory, 0, "2016 eq. 35, Rc^2/(28 tau)",
              p->potential == HCBD_POT_IDEAL ? "eq. 35 is the k -> 0 limit; the friction average is taken at k = 2 pi/L"
                                             : "eq. 35 takes g(r) = 1; the stars' first shell within Rc raises the friction sum");
        mean_err(eff_b, NB, &m, &e);
        printf("nu_eff=%.6g\n", m);
        if (mean_err(nu_init_b, NB, &m, &e) < NB)
            printf("# nu_initial: in some blocks C_t(k,t) fell below 0.75 C_t(k,0) within two lags "
                   "(decay faster than a few steps): those blocks are left out\n");
        printf("nu_initial=%.6g\nnu_initial_err=%.3g\n", m, e);
        judge("nu_initial", m, e, "sigma^2/time", mf / nmf / (1 - sk / nmf / c.N), 0,
              "nu_meanfield / (1 - S(k)/N), exact", NULL);
        /* the exact finite-system identity (see tests/test_physics.c) */
        printf("finite_size_factor=%.5f\n", 1 - sk / nmf / c.N);
        printf("nu_initial_over_meanfield=%.4f\n", m / (mf / nmf / (1 - sk / nmf / c.N)));
        mean_err(ident_b, NB, &m, &e);
        printf("# initial_decay_identity: initial decay rate of C_t at k, 2k, 3k over the friction\n"
               "# average that must equal it (1 exactly, tests/test_physics.c)\n");
        printf("initial_decay_identity=%.4f\ninitial_decay_identity_err=%.3g\n", m, e);
        judge("initial_decay_identity", m, e, "1", 1, 0, "exact finite-system identity", NULL);
        if (mean_err(nu_hydro_b, NB, &m, &e) < NB)
            printf("# nu_hydro: in some blocks C_t(k,t) had fewer than three lags between 0.03 and "
                   "0.8 of C_t(k,0) (too fast a decay for the lag grid, or blocks shorter than the "
                   "decay): those blocks are left out\n");
        printf("nu_hydro=%.6g\nnu_hydro_err=%.3g\n", m, e);
        judge("nu_hydro", m, e, "sigma^2/time", NAN, 0,
              "no closed form for the late decay rate of C_t", NULL);
        {
            double t = tau, mt;
            for (k = 0; k < n; ++k) lag[k] *= 5; /* samples were every 5 steps */
            mt = msd_at(lag, mm, n, p->dt, t);
            printf("msd_ratio_at_tau=%.4f\n", mt / th_tau);
            if (p->potential == HCBD_POT_IDEAL)
                judge("msd_ratio_at_tau", mt / th_tau, NAN, "1", 1, 0.03,
                      "2016 eq. 32, allowance 3 % for the MSD's log interpolation", NULL);
            else
                judge("msd_ratio_at_tau", mt / th_tau, NAN, "1", NAN, 0,
                      "eq. 32 is for ideal particles; the stars' cage slows them", NULL);
            if (p->potential != HCBD_POT_IDEAL)
                printf("# msd_ratio_at_tau: 2016 eq. 32 is the ideal-particle result\n");
            if (tau < 5 * p->dt) printf("# msd_ratio_at_tau: tau is shorter than the MSD sampling interval\n");
        }
        D_meas = long_time_D(&msd, 5 * p->dt, tau, &D_err);
        if (!isfinite(D_meas))
            printf("# D_measured: the MSD blocks (%g time units) hold fewer than two lags beyond "
                   "5 tau = %g: run steps >= %.0f (blocks of 10 tau) for the long-time diffusion\n",
                   blk_steps * p->dt, 5 * tau, ceil(NB * 10 * tau / p->dt));
        if (!isfinite(D_meas))
            judge("D_measured", D_meas, D_err, "sigma^2/time", NAN, 0,
                  "not measured: the blocks are shorter than 10 tau (see the note above)", NULL);
        else
            judge("D_measured", D_meas, D_err, "sigma^2/time", D_th, 0, "2016 eq. 33, kT/xi + kT/xi'",
                  p->potential == HCBD_POT_IDEAL ? "ideal carriers diffuse faster than eq. 33 at long times "
                                                   "(momentum flows back from the neighbours)"
                                                 : "eq. 33 is for ideal carriers: the stars' interactions slow them");
        printf("D_theory=%.6g\nD_measured=%.6g\nD_measured_err=%.3g\nD_ratio=%.4f\n", D_th, D_meas,
               D_err, D_meas / D_th);
    } else {
        printf("T_ratio=nan\n# classical BD carries no background velocity\n");
    }
    if (p->gdot != 0.0) {
        /* shear stress / gdot for each contribution (MODEL 5) */
        double fl[4];
        hcbd_world_stress_read(&w, fl, NULL);
        printf("eta_particle_measured=%.6g\neta_background_measured=%.6g\n", fl[0] / p->gdot, fl[1] / p->gdot);
        printf("eta_carrier_measured=%.6g\neta_total_measured=%.6g\n", fl[2] / p->gdot, fl[3] / p->gdot);
        printf("eta_background_theory=%.6g\n", p->Rc * p->Rc * c.density * p->xip / 28);
        judge("eta_background_measured", fl[1] / p->gdot, NAN, "kT time/sigma^3", p->Rc * p->Rc * c.density * p->xip / 28,
              0.1 * p->Rc * p->Rc * c.density * p->xip / 28, "2016 eq. 35 times n# xi', allowance 10 %",
              "Lees-Edwards, channel and transverse-current runs read 0.63-0.69 of eq. 35 (docs/MODEL.md 12)");
        judge("eta_total_measured", fl[3] / p->gdot, NAN, "kT time/sigma^3", NAN, 0,
              "the sum of the particle, background and carrier parts", NULL);
    }
    if (isfinite(coord)) {
        printf("# coordination: neighbours within the first minimum of g(r), with its block error\n");
        printf("rdf_first_minimum=%.4g\ncoordination=%.4f\ncoordination_err=%.3g\n", rdf_min, coord, coord_err);
        judge("coordination", coord, coord_err, "neighbours", NAN, 0,
              "the structure of the star liquid (2014 Fig. 2)", NULL);
    }
    printf("neighbour_rebuilds=%lld\n", (long long)w.nl.n_rebuilds);
    printf("state_checksum=%016llx\n", (unsigned long long)hcbd_world_checksum(&w));
    if (!run_out_close(&c, &ro, &w)) return 1;
    summary_end(&c, 1);
    hcbd_world_destroy(&w);
    free(xyz); free(vel); free(mem_ct); free(mem_gt); free(mem_v); free(mem_msd);
    return 0;
}
