/* hcbd_sound: the sound speed of the HCBD fluid (2018 sec. IV A, the Tait
   equation of state of MODEL 6).  A laminar run (no thermal fluctuations)
   of the Table I fluid starts from the quenched lattice at rest with a
   longitudinal wave v_x = A sin(k x), k = 2 pi / Lx along the long axis,
   and follows its amplitude a(t) = (2/N) sum_i v_x,i sin(k x_i).  The wave
   oscillates at omega' and decays at Gamma: omega^2 = omega'^2 + Gamma^2,
   c = omega / k.  The default viscosity is ten times below Table I's
   (eta = 1e-4 Pa s): with Table I's the box mode is nearly overdamped.

   Prediction: the summation density and the pressure gradient each smooth
   a density wave by the kernel's Fourier transform W~(k), so omega = c_s
   k W~(k), c_s = sqrt(7 P0 / rho); the Morris viscous term is a
   Laplacian, Gamma = nu k^2 / 2 (its own kernel factor left out).
   Keys: rho eta nbar P0 T dt sigma h (SI as hcbd_fluid; h in sigma), amp
   (A / c_s, default 1e-3), relax_steps (the quench, default 1500), steps
   (default 12000), and the run output of every example. */
#include "example_common.h"

#define PI 3.14159265358979323846

static hcbd_hc_si si;
static double amp = 1e-3;
static int relax = 1500;

static void usage(FILE *f)
{
    fprintf(f, "usage: hcbd_sound [rho eta nbar P0 T dt sigma h amp relax_steps steps seed threads\n"
                    "                  xyz xyz_every thermo_every checkpoint restart]=value\n");
}

static int own_key(config *c, const char *key, const char *v)
{
    static const char *names[] = {"rho", "eta", "nbar", "P0", "T", "dt", "sigma", "h", "amp"};
    double *dst[] = {&si.rho, &si.eta, &si.nbar, &si.P0, &si.T, &si.dt, &si.sigma, &si.h_sigma, &amp};
    int k;
    for (k = 0; k < 9; ++k)
        if (!strcmp(key, names[k])) {
            if (!parse_double(c, key, v, dst[k])) return 0;
            if (*dst[k] > 0) return 1;
            fprintf(stderr, "%s: %s=%s must be positive\n", c->name, key, v);
            return 0;
        }
    if (!strcmp(key, "relax_steps")) {
        if (!parse_int(c, key, v, &relax)) return 0;
        if (relax >= 0) return 1;
        fprintf(stderr, "%s: relax_steps=%s must not be negative\n", c->name, v);
        return 0;
    }
    if (!strcmp(key, "steps") || !strcmp(key, "seed") || !strcmp(key, "threads") || !strcmp(key, "xyz") ||
        !strcmp(key, "xyz_every") || !strcmp(key, "thermo_every") || !strcmp(key, "checkpoint") ||
        !strcmp(key, "restart") || !strcmp(key, "out"))
        return -1;
    fprintf(stderr, "%s: unknown key '%s'\n", c->name, key);
    usage(stderr);
    return 0;
}

int main(int argc, char **argv)
{
    config c;
    hcbd_hc_world_def d = hcbd_hc_world_def_default();
    hcbd_hc_theory th;
    hcbd_hc_world w;
    hc_config rst;
    run_out o;
    char msg[256];
    double *xyz, *vel, *a, k, Wk = 0, r, zt[64], et[64], ea[64], c_meas, om, gam;
    int N, i, s, nz = 0, ne = 0;
    memset(&c, 0, sizeof c);
    c.name = "hcbd_sound", c.def = hcbd_world_def_default(), c.N = 2, c.density = 1, c.steps = 12000;
    si = hcbd_hc_si_default();
    si.eta = 1e-4;
    if (!expand_args(&c, &argc, &argv)) return 2;
    if (!parse_args(argc, argv, &c, own_key, usage)) return c.help ? 0 : 2;
    if (hcbd_hc_si_params(&si, 1e-6, &d.params, msg, sizeof msg) != HCBD_OK)
        return fprintf(stderr, "hcbd_sound: %s\n", msg), 2;
    d.params.fluctuations = 0;
    d.params.seed = c.def.params.seed;
    d.params.threads = c.def.params.threads;
    hcbd_hc_params_theory(&d.params, &th);
    N = d.fluid_capacity = (int)floor(d.params.nbar * d.params.L[0] * d.params.L[1] * d.params.L[2] + 0.5);
    d.polymer_capacity = 0;
    k = 2 * PI / d.params.L[0];
    for (r = d.params.h / 1000; r < 2 * d.params.h; r += d.params.h / 500) /* W~(k), midpoints */
        Wk += 4 * PI * r * r * hcbd_m4(r, d.params.h) * sin(k * r) / (k * r) * d.params.h / 500;
    xyz = (double *)malloc(6 * (size_t)N * sizeof(double));
    a = (double *)malloc(((size_t)c.steps + 1) * sizeof(double));
    if (!xyz || !a) return fprintf(stderr, "hcbd_sound: out of memory\n"), 2;
    vel = xyz + 3 * (size_t)N;
    if (c.restart[0]) { /* the quenched configuration of an earlier run */
        if (!hc_restart(&c, &rst) || rst.nf != N || rst.np)
            return fprintf(stderr, "hcbd_sound: restart=%s is not a fluid of %d blobs\n", c.restart, N), 2;
        memcpy(xyz, rst.fluid, 3 * (size_t)N * sizeof(double));
        free(rst.fluid), free(rst.poly);
    } else { /* the lattice relaxes at 25 P0: its force balance holds at any P0 */
        hcbd_hc_world_def q = d;
        q.params.P0 *= 25;
        if (hcbd_hc_world_create(&w, &q) != HCBD_OK || hcbd_hc_world_place_fluid_lattice(&w, N) != HCBD_OK ||
            hcbd_hc_world_step(&w, relax) != HCBD_OK)
            return fprintf(stderr, "hcbd_sound: quench: %s\n", w.err.msg), 1;
        for (i = 0; i < N; ++i) xyz[3 * i] = w.fx[i], xyz[3 * i + 1] = w.fy[i], xyz[3 * i + 2] = w.fz[i];
        hcbd_hc_world_destroy(&w);
    }
    for (i = 0; i < N; ++i)
        vel[3 * i] = amp * th.cs * sin(k * xyz[3 * i]), vel[3 * i + 1] = vel[3 * i + 2] = 0;
    if (hcbd_hc_world_create(&w, &d) != HCBD_OK || hcbd_hc_world_set_fluid(&w, N, xyz, vel) != HCBD_OK)
        return fprintf(stderr, "hcbd_sound: %s\n", w.err.msg), 2;
    if (!run_out_open(&c, &o, &w, NULL)) return 2;
    for (s = 0; s <= c.steps; ++s) {
        double sum = 0;
        for (i = 0; i < N; ++i) sum += w.fvx[i] * sin(k * w.fx[i]);
        a[s] = 2 * sum / N;
        if (s < c.steps && run_steps(&c, &o, &w, 1) != HCBD_OK)
            return fprintf(stderr, "hcbd_sound: %s\n", w.err.msg), 1;
    }
    /* zero crossings (linear interpolation) and extrema of a(t) */
    for (s = 1; s < c.steps && nz < 64; ++s) {
        if ((a[s - 1] > 0) != (a[s] > 0)) zt[nz++] = (s - 1 + a[s - 1] / (a[s - 1] - a[s])) * d.params.dt;
        if (ne < 64 && fabs(a[s]) >= fabs(a[s - 1]) && fabs(a[s]) > fabs(a[s + 1]) && s > 1)
            et[ne] = s * d.params.dt, ea[ne++] = log(fabs(a[s]));
    }
    if (nz < 3 || ne < 2) {
        printf("# fewer than 3 zero crossings or 2 extrema in %d steps: run longer (steps=) or lower eta\n", c.steps);
        return 1;
    }
    om = PI * (nz - 1) / (zt[nz - 1] - zt[0]);
    gam = -(ea[ne - 1] - ea[0]) / (et[ne - 1] - et[0]);
    c_meas = sqrt(om * om + gam * gam) / k;
    printf("hcbd_sound: %d fluid blobs, box %.4g x %.4g x %.4g sigma, eta = %g Pa s, k = %.4g / sigma, "
           "k h = %.3g, %d steps, %d zero crossings\n",
           N, d.params.L[0], d.params.L[1], d.params.L[2], si.eta, k, k * d.params.h, c.steps, nz);
    printf("# summary (reduced units: sigma, time unit 1e-6 s)\n");
    printf("c_s=%.6g\nkernel_factor=%.5f\nc_expected=%.6g\nc_measured=%.6g\nc_ratio=%.5f\n", th.cs, Wk,
           th.cs * Wk, c_meas, c_meas / (th.cs * Wk));
    printf("damping_measured=%.4g\ndamping_expected=%.4g\n", gam, th.nu * k * k / 2);
    printf("state_checksum=%016llx\n", (unsigned long long)hcbd_hc_world_checksum(&w));
    judge("c_measured", c_meas, NAN, "sigma/time", th.cs * Wk, 0.02 * th.cs * Wk,
          "c_s W~(k), the kernel-smoothed sound speed, allowance 2 % for one fit of the crossings", NULL);
    judge("damping_measured", gam, NAN, "1/time", th.nu * k * k / 2, 0.1 * th.nu * k * k / 2,
          "nu k^2 / 2, allowance 10 % for a fit over few extrema", NULL);
    if (!run_out_close(&c, &o, &w)) return 1;
    summary_end(&c, 0);
    hcbd_hc_world_destroy(&w);
    free(xyz), free(a);
    return 0;
}
