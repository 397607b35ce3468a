/* wp_sph: hcbd's side of the SPH work-precision benchmark against LAMMPS
   (bench/peers/wp_sph.sh), and the one estimator both codes' series go
   through.

   Scene (reduced units, the fluid of bench/bench_wp_hcbd.c): kT = 1, nbar
   = 3/(4 pi), blob mass m = 100 (rho0 = 100 nbar), kernel support 2h = 4
   (hcbd's M4 at h = 2, LAMMPS's Lucy at h = 4), Tait c_s and nu = eta/rho0
   as given; nx x ny x ny simple-cubic sites (spacing 1.612) melted with
   fluctuations (nu = 1, c_s = 2.5, dt = 0.04, 10 time units: the same
   positions for every nu, c_s and dt) and quenched (10 time units with
   fluctuations off), then a transverse wave v_y = amp sin(k x), k = 2 pi / Lx.  The run writes
   "t S C", S = sum_i v_y sin(k x_i) and C = sum_i v_y cos(k x_i), every
   time/(samples-1); LAMMPS writes the same sums from the same start
   (data=FILE: positions, velocities and rho_i = m n_i, hcbd's summation
   density at the start, so that LAMMPS's continuity density starts where
   hcbd's summation starts).  Prints seconds_per_time_unit: the wall time
   of the hcbd_hc_world_step calls alone per unit of simulated time.

   kT=X (> 0, the SDPD work-precision study, bench/peers/wp_sdpd.sh): the
   measured run has thermal fluctuations at kT, and starts from Maxwell
   velocities at kT (zero total momentum; drawn here, the same in the data
   file) plus the wave (amp=0: none); the series gets a fourth column, the
   kinetic temperature over kT (hcbd_hc_world_temperature; LAMMPS's
   compute temp, 3N - 3 degrees of freedom both).

   Fit mode (both codes): the decay rate G of the amplitude sqrt(S^2+C^2)
   by least squares on its logarithm, nu_fit = G / k^2, and its ratio to
   the continuum prediction nu K(k) of the code's kernel (K from the
   kernel's derivative; the shear mode of the Morris force relaxes at
   nu k^2 K(k), examples/hcbd_fluid.c); nu_fit_err from the residuals.

   usage: wp_sph dt=DT [nu=1] [c=2.5] [nx=20] [ny=10] [time=20] [samples=41]
                 [amp=0.3] [pair=exact|euler] [seed=7] [data=FILE] series=FILE
          wp_sph fit=FILE L=LX nu=NU kernel=m4|lucy
          wp_sph temp=FILE [skip=0.2]: the mean of the fourth column past
          the first `skip` of the samples, and its error from 10 block means */
#include "bench_common.h"
#include "../tests/scenes.h"

#define PI_ 3.14159265358979323846
#define H 2.0

static hcbd_hc_world_def scene(int nx, int ny, double dt, double nu, double c, int integ, unsigned long long seed)
{
    hcbd_hc_world_def d = hc_scene_of(nx, ny, ny, 0, 100.0, nu, c, dt); /* tests/scenes.h */
    hcbd_hc_params *p = &d.params;
    p->h = H;
    p->xi = 100.0;
    p->alpha = 0.0;
    p->seed = seed;
    p->threads = 1;
    p->pair_integrator = (hcbd_pair_integrator)integ;
    return d;
}

/* -W'(r) r of either kernel at support 2h = 4 */
static double kernel_a(double r, int lucy)
{
    if (!lucy) return -hcbd_m4_dr(r, H) * r;
    {
        const double hs = 2 * H, s = r / hs;
        return s >= 1 ? 0 : 12.0 * 105.0 / (16.0 * PI_ * hs * hs * hs) * s * (1 - s) * (1 - s) / hs * r;
    }
}

static double kernel_factor(double k, int lucy)
{
    const int n = 4000;
    double num = 0, den = 0;
    int i;
    for (i = 0; i < n; ++i) {
        double r = (i + 0.5) * 2 * H / n, a = kernel_a(r, lucy), q = k * r;
        num += a * (q > 1e-3 ? 1 - sin(q) / q : q * q / 6 - q * q * q * q / 120);
        den += a * q * q / 6;
    }
    return num / den;
}

static int fit(const char *file, double L, double nu, int lucy)
{
    FILE *f = fopen(file, "r");
    char line[512];
    double t, S, C, sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0, k = 2 * PI_ / L, G, res, K;
    int n = 0;
    if (!f) {
        fprintf(stderr, "wp_sph: cannot read %s\n", file);
        return 1;
    }
    while (fgets(line, sizeof line, f)) {
        double y;
        if (line[0] == '#' || sscanf(line, "%lf %lf %lf", &t, &S, &C) != 3) continue;
        if (!(S * S + C * C > 0) || !isfinite(t)) { n = -1; break; }
        y = 0.5 * log(S * S + C * C);
        sx += t; sy += y; sxx += t * t; sxy += t * y; syy += y * y; ++n;
    }
    fclose(f);
    if (n < 3) {
        printf("nu_fit=nan nu_fit_err=nan K=nan ratio=nan samples=%d\n", n);
        return 0;
    }
    G = -(n * sxy - sx * sy) / (n * sxx - sx * sx);
    /* residual sum of squares of the line, from the sums */
    res = (syy - sy * sy / n) - (sxy - sx * sy / n) * (sxy - sx * sy / n) / (sxx - sx * sx / n);
    if (res < 0) res = 0;
    K = kernel_factor(k, lucy);
    printf("nu_fit=%.8g nu_fit_err=%.3g K=%.6f ratio=%.8f samples=%d\n", G / (k * k),
           sqrt(res / (n - 2) / (sxx - sx * sx / n)) / (k * k), K, G / (k * k) / (nu * K), n);
    return 0;
}

static int temp_mean(const char *file, double skip)
{
    FILE *f = fopen(file, "r");
    char line[512];
    double t, S, C, T, *x = NULL, m = 0, e2 = 0, b[10];
    int n = 0, cap = 0, i, k, n0, len;
    if (!f) {
        fprintf(stderr, "wp_sph: cannot read %s\n", file);
        return 1;
    }
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#' || sscanf(line, "%lf %lf %lf %lf", &t, &S, &C, &T) != 4) continue;
        if (n == cap) {
            double *y = (double *)realloc(x, sizeof(double) * (cap = cap ? 2 * cap : 256));
            if (!y) break;
            x = y;
        }
        x[n++] = T;
    }
    fclose(f);
    n0 = (int)(skip * n);
    len = (n - n0) / 10;
    if (len < 2) {
        printf("T=nan T_err=nan samples=%d\n", n);
        free(x);
        return 0;
    }
    for (k = 0; k < 10; ++k) {
        b[k] = 0;
        for (i = 0; i < len; ++i) b[k] += x[n0 + k * len + i] / len;
        m += b[k] / 10;
    }
    for (k = 0; k < 10; ++k) e2 += (b[k] - m) * (b[k] - m) / 90;
    printf("T=%.8f T_err=%.3g samples=%d\n", m, sqrt(e2), 10 * len);
    free(x);
    return 0;
}

static void sums(const hcbd_hc_world *w, double k, double *S, double *C)
{
    int i;
    *S = *C = 0;
    for (i = 0; i < w->nf; ++i) {
        *S += w->fvy[i] * sin(k * w->fx[i]);
        *C += w->fvy[i] * cos(k * w->fx[i]);
    }
}

static int write_data(const char *file, int N, const double *L, const double *xyz, const double *v, double m)
{
    FILE *f = fopen(file, "w");
    int i, j, a;
    if (!f) return 0;
    fprintf(f, "wp_sph: melted fluid, transverse wave (atom_style sph: id type rho esph cv x y z)\n\n"
               "%d atoms\n1 atom types\n\n0 %.17g xlo xhi\n0 %.17g ylo yhi\n0 %.17g zlo zhi\n\n"
               "Masses\n\n1 %.17g\n\nAtoms # sph\n\n",
            N, L[0], L[1], L[2], m);
    for (i = 0; i < N; ++i) {
        double n = 0; /* hcbd's summation density at the start (self included) */
        for (j = 0; j < N; ++j) {
            double r2 = 0;
            for (a = 0; a < 3; ++a) {
                double d = xyz[3 * i + a] - xyz[3 * j + a];
                d -= L[a] * floor(d / L[a] + 0.5);
                r2 += d * d;
            }
            if (r2 < 4 * H * H) n += hcbd_m4(sqrt(r2), H);
        }
        fprintf(f, "%d 1 %.17g 0 1 %.17g %.17g %.17g\n", i + 1, m * n, xyz[3 * i], xyz[3 * i + 1],
                xyz[3 * i + 2]);
    }
    fprintf(f, "\nVelocities\n\n");
    for (i = 0; i < N; ++i) fprintf(f, "%d %.17g %.17g %.17g\n", i + 1, v[3 * i], v[3 * i + 1], v[3 * i + 2]);
    return fclose(f) == 0;
}

int main(int argc, char **argv)
{
    double dt = 0, nu = 1, c = 2.5, T = 20, amp = 0.3, L = 0, spent = 0, kT = 0, skip = 0.2, k, S, Cs, vrms, *xyz, *v;
    int nx = 20, ny = 10, samples = 41, integ = HCBD_PAIR_SHARDLOW, lucy = -1, i, s, every, N, quench;
    unsigned long long seed = 7;
    const char *data = NULL, *series = NULL, *fitf = NULL, *tempf = NULL;
    hcbd_hc_world_def d;
    hcbd_hc_world w;
    FILE *f;
    for (i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (!strncmp(a, "dt=", 3)) dt = atof(a + 3);
        else if (!strncmp(a, "nu=", 3)) nu = atof(a + 3);
        else if (!strncmp(a, "c=", 2)) c = atof(a + 2);
        else if (!strncmp(a, "nx=", 3)) nx = atoi(a + 3);
        else if (!strncmp(a, "ny=", 3)) ny = atoi(a + 3);
        else if (!strncmp(a, "time=", 5)) T = atof(a + 5);
        else if (!strncmp(a, "samples=", 8)) samples = atoi(a + 8);
        else if (!strncmp(a, "amp=", 4)) amp = atof(a + 4);
        else if (!strcmp(a, "pair=exact")) integ = HCBD_PAIR_SHARDLOW;
        else if (!strcmp(a, "pair=euler")) integ = HCBD_PAIR_EULER;
        else if (!strncmp(a, "seed=", 5)) seed = strtoull(a + 5, NULL, 10);
        else if (!strncmp(a, "data=", 5)) data = a + 5;
        else if (!strncmp(a, "series=", 7)) series = a + 7;
        else if (!strncmp(a, "fit=", 4)) fitf = a + 4;
        else if (!strncmp(a, "temp=", 5)) tempf = a + 5;
        else if (!strncmp(a, "skip=", 5)) skip = atof(a + 5);
        else if (!strncmp(a, "kT=", 3)) kT = atof(a + 3);
        else if (!strncmp(a, "L=", 2)) L = atof(a + 2);
        else if (!strcmp(a, "kernel=m4")) lucy = 0;
        else if (!strcmp(a, "kernel=lucy")) lucy = 1;
        else {
            fprintf(stderr, "wp_sph: unknown argument '%s'\n", a);
            return 2;
        }
    }
    if (tempf) return temp_mean(tempf, skip >= 0 && skip < 1 ? skip : 0.2);
    if (fitf) {
        if (!(L > 0) || !(nu > 0) || lucy < 0) {
            fprintf(stderr, "usage: wp_sph fit=FILE L=LX nu=NU kernel=m4|lucy\n");
            return 2;
        }
        return fit(fitf, L, nu, lucy);
    }
    if (!(dt > 0) || !series || !(T > dt) || !(nu > 0) || !(c > 0) || nx < 4 || ny < 4 || samples < 3 || !(kT >= 0)) {
        fprintf(stderr, "usage: wp_sph dt=DT series=FILE [nu=] [c=] [nx=] [ny=] [time=] [samples=] [amp=] "
                        "[pair=exact|euler] [seed=] [data=FILE]\n");
        return 2;
    }
    /* the melt: the same positions whatever nu, c and dt */
    d = scene(nx, ny, 0.04, 1.0, 2.5, HCBD_PAIR_SHARDLOW, seed);
    if (hcbd_hc_world_create(&w, &d) != HCBD_OK || hcbd_hc_world_place_fluid_lattice(&w, d.fluid_capacity) != HCBD_OK ||
        hcbd_hc_world_step(&w, 250) != HCBD_OK) {
        fprintf(stderr, "wp_sph: melt: %s\n", w.err.msg);
        return 1;
    }
    N = w.nf;
    xyz = (double *)malloc(3 * sizeof(double) * N);
    v = (double *)calloc(3 * (size_t)N, sizeof(double));
    if (!xyz || !v) return 1;
    for (quench = 0; quench < 2; ++quench) {
        for (i = 0; i < N; ++i) {
            xyz[3 * i] = w.fx[i];
            xyz[3 * i + 1] = w.fy[i];
            xyz[3 * i + 2] = w.fz[i];
            v[3 * i] = w.fvx[i];
            v[3 * i + 1] = w.fvy[i];
            v[3 * i + 2] = w.fvz[i];
        }
        hcbd_hc_world_destroy(&w);
        if (quench) break;
        /* the melt's density fluctuations would turn into velocities of
           the thermal size (a 1-2 % noise on the wave's amplitude, and a
           chaotic one: it differs from step to step); 10 time units
           without fluctuations let the viscosity drain them */
        d.params.fluctuations = 0;
        if (hcbd_hc_world_create(&w, &d) != HCBD_OK || hcbd_hc_world_set_fluid(&w, N, xyz, v) != HCBD_OK ||
            hcbd_hc_world_step(&w, 250) != HCBD_OK) {
            fprintf(stderr, "wp_sph: quench: %s\n", w.err.msg);
            return 1;
        }
    }
    k = 2 * PI_ / d.params.L[0];
    for (i = 0, vrms = 0; i < 3 * N; ++i) vrms += v[i] * v[i];
    vrms = sqrt(vrms / (3 * N));
    d = scene(nx, ny, dt, nu, c, integ, seed);
    d.params.fluctuations = kT > 0;
    if (kT > 0) d.params.kT = kT;
    {
        /* Maxwell velocities at kT (Box-Muller), zero total momentum */
        const double sv = sqrt(kT * d.params.nbar / d.params.rho);
        double mean[3] = {0, 0, 0};
        hcbd_rng g;
        hcbd_rng_seed(&g, seed + 1000);
        for (i = 0; i < 3 * N; ++i) {
            const double u1 = 1.0 - hcbd_rng_uniform(&g), u2 = hcbd_rng_uniform(&g);
            v[i] = kT > 0 ? sv * sqrt(-2.0 * log(u1)) * cos(2 * PI_ * u2) : 0.0;
            mean[i % 3] += v[i] / N;
        }
        for (i = 0; i < N; ++i) {
            v[3 * i] -= mean[0];
            v[3 * i + 1] += amp * sin(k * xyz[3 * i]) - mean[1];
            v[3 * i + 2] -= mean[2];
        }
    }
    if (data && !write_data(data, N, d.params.L, xyz, v, d.params.rho / d.params.nbar)) {
        fprintf(stderr, "wp_sph: cannot write %s\n", data);
        return 1;
    }
    if (hcbd_hc_world_create(&w, &d) != HCBD_OK || hcbd_hc_world_set_fluid(&w, N, xyz, v) != HCBD_OK) {
        fprintf(stderr, "wp_sph: %s\n", w.err.msg);
        return 1;
    }
    free(xyz);
    free(v);
    if (!(f = fopen(series, "w"))) {
        fprintf(stderr, "wp_sph: cannot write %s\n", series);
        return 1;
    }
    every = (int)(T / (samples - 1) / dt + 0.5);
    if (every < 1) every = 1;
    fprintf(f, "# t S C%s (S, C = sum v_y sin, cos (k x)); hcbd, dt = %g, N = %d\n", kT > 0 ? " T/kT" : "", dt, N);
    for (s = 0; s < samples; ++s) {
        if (s > 0) {
            const double t0 = now();
            hcbd_result r = hcbd_hc_world_step(&w, every);
            spent += now() - t0;
            if (r != HCBD_OK) {
                fprintf(f, "# stopped: %s\n", w.err.msg);
                fclose(f);
                printf("seconds_per_time_unit=nan stopped=%s\n", hcbd_result_name(r));
                return 0;
            }
        }
        sums(&w, k, &S, &Cs);
        if (kT > 0) fprintf(f, "%.10g %.12g %.12g %.10g\n", s * every * dt, S, Cs, hcbd_hc_world_temperature(&w) / kT);
        else fprintf(f, "%.10g %.12g %.12g\n", s * every * dt, S, Cs);
    }
    fclose(f);
    printf("seconds_per_time_unit=%.6g N=%d L=%.17g steps=%d quench_vrms=%.3g checksum=%016llx\n",
           spent / ((samples - 1) * every * dt), N, d.params.L[0], (samples - 1) * every, vrms,
           (unsigned long long)hcbd_hc_world_checksum(&w));
    hcbd_hc_world_destroy(&w);
    return 0;
}
