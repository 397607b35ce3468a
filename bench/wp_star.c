/* wp_star: hcbd's side of the work-precision benchmark against LAMMPS
   (bench/peers/wp.sh).  The 2014 star fluid (f = 128, n# = 0.24, Rc =
   rcut = 2.5, tau = 3.6e-3, kT = xi = xi' = 1) of N particles from a
   simple cubic lattice: eq time units of equilibration, then time units
   timed, with a frame of positions (extended XYZ, hcbd_world_write_xyz) every
   `every` time units written outside the timed calls.  Prints
   seconds_per_time_unit (the wall time of the hcbd_world_step calls alone, per
   unit of simulated time), T_conf_api (hcbd_world_config_temperature over all
   frames, which wp.sh holds against wp_estimate's reading of the same
   frames) and the state checksum; wp_estimate reads the frames with the
   estimator it applies to LAMMPS's dumps.

   usage: wp_star dt=1e-4 [N=1000] [time=5] [eq=1] [every=0.01]
                  [dyn=bd|gibd] [brownian=lm|euler] [pair=exact|euler]
                  [noise=gauss|uniform] [seed=1] [threads=1] out=FILE */
#include "bench_common.h"

int main(int argc, char **argv)
{
    hcbd_world_def d = hcbd_world_def_default();
    hcbd_world w;
    double dt = 0, T = 5, eq = 1, every = 0.01, spent = 0, L, tc[2], F2 = 0, lap = 0;
    int N = 1000, k, ke, blocks;
    const char *out = NULL;
    FILE *f;
    d.params.threads = 1;
    for (k = 1; k < argc; ++k) {
        const char *a = argv[k];
        if (!strncmp(a, "dt=", 3)) dt = atof(a + 3);
        else if (!strncmp(a, "N=", 2)) N = atoi(a + 2);
        else if (!strncmp(a, "time=", 5)) T = atof(a + 5);
        else if (!strncmp(a, "eq=", 3)) eq = atof(a + 3);
        else if (!strncmp(a, "every=", 6)) every = atof(a + 6);
        else if (!strcmp(a, "dyn=bd")) d.params.dynamics = HCBD_DYN_BD;
        else if (!strcmp(a, "dyn=gibd")) d.params.dynamics = HCBD_DYN_GIBD;
        else if (!strcmp(a, "brownian=lm")) d.params.brownian = HCBD_BROWNIAN_LM;
        else if (!strcmp(a, "brownian=euler")) d.params.brownian = HCBD_BROWNIAN_EULER;
        else if (!strcmp(a, "pair=exact")) d.params.pair_integrator = HCBD_PAIR_SHARDLOW;
        else if (!strcmp(a, "pair=euler")) d.params.pair_integrator = HCBD_PAIR_EULER;
        else if (!strcmp(a, "noise=gauss")) d.params.noise = HCBD_NOISE_GAUSS;
        else if (!strcmp(a, "noise=uniform")) d.params.noise = HCBD_NOISE_UNIFORM;
        else if (!strncmp(a, "seed=", 5)) d.params.seed = strtoull(a + 5, NULL, 10);
        else if (!strncmp(a, "threads=", 8)) d.params.threads = atoi(a + 8);
        else if (!strncmp(a, "out=", 4)) out = a + 4;
        else {
            fprintf(stderr, "wp_star: unknown argument '%s'\n", a);
            return 2;
        }
    }
    if (!(dt > 0) || !out || !(T > 0) || !(every >= dt) || N < 2) {
        fprintf(stderr, "usage: wp_star dt=DT out=FILE [N=] [time=] [eq=] [every=] [dyn=] [brownian=] [pair=] "
                        "[noise=] [seed=] [threads=]\n");
        return 2;
    }
    L = cbrt(N / 0.24);
    d.capacity = N;
    d.params.L[0] = d.params.L[1] = d.params.L[2] = L;
    d.params.dt = dt;
    if (hcbd_world_create(&w, &d) != HCBD_OK || hcbd_world_place_lattice(&w, N) != HCBD_OK ||
        hcbd_world_step(&w, (int)(eq / dt + 0.5)) != HCBD_OK) {
        fprintf(stderr, "wp_star: %s\n", w.err.msg);
        return 1;
    }
    if (!(f = fopen(out, "w"))) {
        fprintf(stderr, "wp_star: cannot write %s\n", out);
        return 1;
    }
    ke = (int)(every / dt + 0.5);
    blocks = (int)(T / (ke * dt) + 0.5);
    for (k = 0; k < blocks; ++k) {
        const double t0 = now();
        if (hcbd_world_step(&w, ke) != HCBD_OK) {
            fprintf(stderr, "wp_star: %s\n", w.err.msg);
            return 1;
        }
        spent += now() - t0;
        hcbd_world_write_xyz(&w, f, NULL, 0);
        if (hcbd_world_config_temperature(&w, tc) == HCBD_OK) { F2 += tc[0]; lap += tc[1]; }
    }
    fclose(f);
    printf("seconds_per_time_unit=%.6g steps=%lld frames=%d T_conf_api=%.9f checksum=%016llx\n",
           spent / (blocks * ke * dt), (long long)blocks * ke, blocks, F2 / lap,
           (unsigned long long)hcbd_world_checksum(&w));
    hcbd_world_destroy(&w);
    return 0;
}
