/* bench_hcbd: nanoseconds per particle-step of the 2018 HCBD model at
   Table I (reduced units sigma, kT, 1 us): the pure fluid at nbar =
   3/(4 pi) in cubes of N = 806, 8000, 64000, 512000 blobs, with and without
   thermal fluctuations, and the polymer solution at C2 = 5 C* (fluid
   without fluctuations, as in the paper) in the 33.75 x 10 x 10 box, where
   the time is split by species with the fluid alone run beside it.  1 and
   2 threads; the state checksum shows that thread counts give the same
   bits.  Each point: the minimum over repeats of about a second of steps,
   after a warm-up from the lattice.

   usage: bench_hcbd [Nmax=512000] [threads=2] [out=out/bench] */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, mkdir under -std=c99 */
#include "../hcbd.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <sys/stat.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* Seconds per step of a scene, and its checksum; -1 on error. */
static double time_scene(int nf, int np, const double L[3], int fluct, int th, uint64_t *sum)
{
    hcbd_hc_def d = hcbd_hc_def_default();
    hcbd_hc_world w;
    double best = 1e30;
    int steps = (int)(1e9 / ((nf + 2.0 * np) * 5000.0)), rep, reps = nf <= 8000 ? 3 : 1;
    if (steps < 3) steps = 3;
    memcpy(d.params.L, L, sizeof d.params.L);
    d.params.fluctuations = fluct;
    d.params.threads = th;
    d.fluid_capacity = nf;
    d.polymer_capacity = np;
    if (hcbd_hc_world_create(&w, &d) != HCBD_OK || hcbd_hc_place_fluid_lattice(&w, nf) != HCBD_OK ||
        (np && hcbd_hc_place_polymers_random(&w, np) != HCBD_OK) || hcbd_hc_step(&w, 2) != HCBD_OK) {
        fprintf(stderr, "bench_hcbd: %s\n", w.err.msg);
        hcbd_hc_world_destroy(&w);
        return -1;
    }
    for (rep = 0; rep < reps; ++rep) {
        double t0 = now();
        if (hcbd_hc_step(&w, steps) != HCBD_OK) {
            fprintf(stderr, "bench_hcbd: %s\n", w.err.msg);
            best = -1;
            break;
        }
        if ((now() - t0) / steps < best) best = (now() - t0) / steps;
    }
    *sum = hcbd_hc_state_checksum(&w);
    hcbd_hc_world_destroy(&w);
    return best;
}

int main(int argc, char **argv)
{
    const int sizes[4] = {806, 8000, 64000, 512000};
    const double nbar = 3.0 / (4.0 * 3.14159265358979323846);
    int Nmax = 512000, maxth = 2, k, th, fl;
    char out[512] = "out/bench", path[600];
    FILE *csv;
    for (k = 1; k < argc; ++k) {
        if (!strncmp(argv[k], "Nmax=", 5)) Nmax = atoi(argv[k] + 5);
        else if (!strncmp(argv[k], "threads=", 8)) maxth = atoi(argv[k] + 8);
        else if (!strncmp(argv[k], "out=", 4)) snprintf(out, sizeof out, "%s", argv[k] + 4);
        else {
            fprintf(stderr, "bench_hcbd: unknown argument '%s' (Nmax=, threads=, out=)\n", argv[k]);
            return 2;
        }
    }
    if (maxth < 1) maxth = 1;
    mkdir("out", 0755);
    mkdir(out, 0755);
    snprintf(path, sizeof path, "%s/speed_hcbd.csv", out);
    csv = fopen(path, "w");
    if (!csv) {
        fprintf(stderr, "bench_hcbd: cannot write %s\n", path);
        return 1;
    }
    fprintf(csv, "scene,N_fluid,N_polymer,threads,ns_per_particle_step,ns_per_fluid_step,"
                 "ns_per_polymer_step,checksum\n");
    printf("%-14s %8s %8s %7s %16s %12s %12s %18s\n", "scene", "fluid", "polymer", "threads",
           "ns/particle-step", "ns/fluid", "ns/polymer", "checksum");
    for (k = 0; k < 4; ++k) {
        const int nf = sizes[k];
        double L[3];
        if (nf > Nmax) break;
        /* the first size is the paper's box, the others cubes */
        if (k == 0) { L[0] = 33.75; L[1] = L[2] = 10.0; }
        else L[0] = L[1] = L[2] = cbrt(nf / nbar);
        for (fl = 1; fl >= 0; --fl)
            for (th = 1; th <= maxth; ++th) {
                uint64_t sum = 0;
                double t = time_scene(nf, 0, L, fl, th, &sum);
                const char *name = fl ? "fluid-fluct" : "fluid";
                if (t < 0) return 1;
                printf("%-14s %8d %8d %7d %16.0f %12.0f %12s %18llx\n", name, nf, 0, th, 1e9 * t / nf,
                       1e9 * t / nf, "-", (unsigned long long)sum);
                fprintf(csv, "%s,%d,0,%d,%.1f,%.1f,,%llx\n", name, nf, th, 1e9 * t / nf, 1e9 * t / nf,
                        (unsigned long long)sum);
                fflush(stdout);
            }
    }
    { /* C2 = 5 C* in the paper's box: polymer time = total - fluid alone */
        const double L[3] = {33.75, 10.0, 10.0};
        const int nf = 806, np = 5 * 806;
        for (th = 1; th <= maxth; ++th) {
            uint64_t sum = 0, s0 = 0;
            double t = time_scene(nf, np, L, 0, th, &sum), tf = time_scene(nf, 0, L, 0, th, &s0);
            if (t < 0 || tf < 0) return 1;
            printf("%-14s %8d %8d %7d %16.0f %12.0f %12.0f %18llx\n", "solution-C2", nf, np, th,
                   1e9 * t / (nf + np), 1e9 * tf / nf, 1e9 * (t - tf) / np, (unsigned long long)sum);
            fprintf(csv, "solution-C2,%d,%d,%d,%.1f,%.1f,%.1f,%llx\n", nf, np, th, 1e9 * t / (nf + np),
                    1e9 * tf / nf, 1e9 * (t - tf) / np, (unsigned long long)sum);
            fflush(stdout);
        }
    }
    fclose(csv);
    printf("wrote %s\n", path);
    return 0;
}
