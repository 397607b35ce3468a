/* bench_speed: nanoseconds per particle-step for the 2014 star-polymer
   scene (f = 128, n# = 0.24, Rc = rcut = 2.5, skin 0.6, dt = 1e-4,
   tau = 3.6e-3) at N = 512, 4096, 32768, 262144 (and 1048576 with
   Nmax=1048576), classical BD and GI-BD, 1 and 2 threads, GI-BD under
   Lees-Edwards shear (gdot = 5, with the stress split accumulated every
   step), and (walled build) the 2016 channel: Gaussian walls 1.5 thick
   added above and below a cube of N real particles, tau = 3e-3,
   g = 133.4.  Times are per real particle-step; the artificial particles
   (redrawn every step) are listed separately.  Each point: warm up from a
   lattice (so the neighbour list rebuilds at its liquid rate), then the
   minimum over repeats of the time per particle-step; the state checksum
   of each run shows that the thread counts give identical bits.

   noise=uniform draws the pair and Brownian noise uniform with unit
   variance (as LAMMPS fix brownian does by default); scenes= runs a comma
   list of bd, gibd, gibd-le, channel; skin= sets the Verlet skin (default
   HCBD_AUTO, 0.6); pair=euler takes the papers' explicit pair step instead
   of the exact sweep; brownian=euler the Euler-Maruyama displacement of the
   papers and of LAMMPS fix brownian instead of Leimkuhler-Matthews.

   threads=n runs 1..n threads, threads=1,4,16 the listed counts; Nmin=
   skips the smaller sizes.

   usage: bench_speed [Nmin=512] [Nmax=262144] [threads=2] [out=out/bench]
                      [noise=gauss|uniform] [scenes=bd,gibd,...] [skin=0.6]
                      [pair=shardlow|euler] [brownian=lm|euler] */
#include "bench_common.h"

int main(int argc, char **argv)
{
    int sizes[5] = {512, 4096, 32768, 262144, 1048576}, Nmin = 0, Nmax = 262144, k, dyn, it;
    int thl[64] = {1, 2}, nth = 2;
    char out[512] = "out/bench", path[600], scenes[256] = "";
    hcbd_noise noise = HCBD_NOISE_GAUSS;
    double skin = HCBD_AUTO;
    hcbd_pair_integrator pair = HCBD_PAIR_SHARDLOW;
    hcbd_brownian_integrator brownian = HCBD_BROWNIAN_LM;
    FILE *csv;
    for (k = 1; k < argc; ++k) {
        if (!strncmp(argv[k], "Nmax=", 5)) Nmax = atoi(argv[k] + 5);
        else if (!strncmp(argv[k], "Nmin=", 5)) Nmin = atoi(argv[k] + 5);
        else if (!strncmp(argv[k], "threads=", 8)) {
            const char *q = argv[k] + 8;
            char *e;
            nth = 0;
            while (nth < 64) {
                long v = strtol(q, &e, 10);
                if (e == q || v < 1 || v > 4096) break;
                thl[nth++] = (int)v;
                if (*e != ',') break;
                q = e + 1;
            }
            if (nth == 0 || *e) {
                fprintf(stderr, "bench_speed: threads='%s': a count or a comma list of counts >= 1\n",
                        argv[k] + 8);
                return 2;
            }
            if (nth == 1) { /* threads=n: 1..n (the count read before the list is written) */
                const int top = thl[0] < 64 ? thl[0] : 64;
                for (nth = 0; nth < top; ++nth) thl[nth] = nth + 1;
            }
        }
        else if (!strncmp(argv[k], "out=", 4)) snprintf(out, sizeof out, "%s", argv[k] + 4);
        else if (!strcmp(argv[k], "noise=gauss")) noise = HCBD_NOISE_GAUSS;
        else if (!strcmp(argv[k], "noise=uniform")) noise = HCBD_NOISE_UNIFORM;
        else if (!strncmp(argv[k], "scenes=", 7)) snprintf(scenes, sizeof scenes, ",%s,", argv[k] + 7);
        else if (!strncmp(argv[k], "skin=", 5)) skin = atof(argv[k] + 5);
        else if (!strcmp(argv[k], "pair=euler")) pair = HCBD_PAIR_EULER;
        else if (!strcmp(argv[k], "pair=shardlow")) pair = HCBD_PAIR_SHARDLOW;
        else if (!strcmp(argv[k], "brownian=euler")) brownian = HCBD_BROWNIAN_EULER;
        else if (!strcmp(argv[k], "brownian=lm")) brownian = HCBD_BROWNIAN_LM;
        else {
            fprintf(stderr, "bench_speed: unknown argument '%s' (Nmin=, Nmax=, threads=, out=, "
                            "noise=gauss|uniform, scenes=, skin=, pair=shardlow|euler, brownian=lm|euler)\n",
                    argv[k]);
            return 2;
        }
    }
    csv = bench_csv("bench_speed", out, noise == HCBD_NOISE_UNIFORM ? "speed_uniform.csv" : "speed.csv",
                    path, sizeof path);
    if (!csv) return 1;
    fprintf(csv, "scene,N,artificial,threads,ns_per_particle_step,steps,rebuilds_per_100_steps,"
                 "pairs_per_particle,noise,checksum\n");
    printf("%-8s %8s %6s %7s %14s %10s %10s %18s\n", "scene", "N", "artif.", "threads",
           "ns/particle-step", "rebuild%", "pairs/N", "checksum");
    for (k = 0; k < 5; ++k) {
        int N = sizes[k];
        if (N > Nmax) break;
        if (N < Nmin) continue;
        for (dyn = 0; dyn < (HCBD_MODEL == HCBD_MODEL_WALLED ? 4 : 3); ++dyn)
            for (it = 0; it < nth; ++it) {
                int th = thl[it];
                static const char *names[4] = {"bd", "gibd", "gibd-le", "channel"};
                hcbd_world_def d = hcbd_world_def_default();
                hcbd_world w;
                double L = cbrt(N / 0.24), best = 1e30, t0;
                /* about a second of work per repeat, at least 20 steps */
                int steps = (int)(1e9 / (N * 800.0)), rep, reps = N <= 32768 ? 3 : 1;
                int64_t r0;
                char tag[32];
                snprintf(tag, sizeof tag, ",%s,", names[dyn]);
                if (scenes[0] && !strstr(scenes, tag)) continue;
                if (steps < 20) steps = 20;
                d.capacity = N;
                d.params.L[0] = d.params.L[1] = d.params.L[2] = L;
                d.params.dynamics = dyn ? HCBD_DYN_GIBD : HCBD_DYN_BD;
                d.params.noise = noise;
                d.params.skin = skin;
                d.params.pair_integrator = pair;
                d.params.brownian = brownian;
                if (dyn == 2) d.params.gdot = 5.0;
                if (dyn == 3) { /* 2016 sec. IV C */
                    d.params.L[1] = L + 3.0;
                    d.params.wall.thickness = 1.5;
                    d.params.tau = 3e-3;
                    d.params.fext[0] = 133.4 * d.params.xip * d.params.tau;
                }
                d.params.threads = th;
                if (hcbd_world_create(&w, &d) != HCBD_OK) {
                    fprintf(stderr, "bench_speed: %s\n", w.err.msg);
                    return 1;
                }
                hcbd_world_place_lattice(&w, N);
                if (hcbd_world_step(&w, 200) != HCBD_OK) {
                    fprintf(stderr, "bench_speed: %s\n", w.err.msg);
                    return 1;
                }
                r0 = w.nl.n_rebuilds;
                if (dyn == 2) hcbd_world_stress_enable(&w, 1);
                for (rep = 0; rep < reps; ++rep) {
                    double dtm;
                    t0 = now();
                    if (hcbd_world_step(&w, steps) != HCBD_OK) {
                        fprintf(stderr, "bench_speed: %s\n", w.err.msg);
                        return 1;
                    }
                    dtm = (now() - t0) * 1e9 / ((double)N * steps);
                    if (dtm < best) best = dtm;
                }
                printf("%-8s %8d %6d %7d %14.1f %10.1f %10.2f  %016llx\n", names[dyn], N, w.ws.n_art, th,
                       best, 100.0 * (w.nl.n_rebuilds - r0) / (reps * steps), (double)w.nl.npairs / N,
                       (unsigned long long)hcbd_world_checksum(&w));
                fprintf(csv, "%s,%d,%d,%d,%.2f,%d,%.2f,%.3f,%s,%016llx\n", names[dyn], N, w.ws.n_art, th,
                        best, steps * reps, 100.0 * (w.nl.n_rebuilds - r0) / (reps * steps),
                        (double)w.nl.npairs / N, noise == HCBD_NOISE_UNIFORM ? "uniform" : "gauss",
                        (unsigned long long)hcbd_world_checksum(&w));
                fflush(stdout);
                hcbd_world_destroy(&w);
            }
    }
    fclose(csv);
    printf("wrote %s\n", path);
    return 0;
}
