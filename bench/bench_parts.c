/* bench_parts: what each optional part of a scene costs (ns per
   particle-step, 1 thread, minimum over repeats), one row per part switched
   on or off against the first row.  An off part must cost nothing: the
   GI-BD build (no wall code compiled) and the walled build with walls off
   give the same baseline, and each part's cost is its own row's excess.

   GI-BD/walled build: 4096 stars (2014 scene), from one melted
   configuration: the baseline (GI-BD, kT = 1, Euler), then kT = 0, lagged
   densities, the Shardlow sweep, Lees-Edwards shear, stress flux
   accumulation, walls (walled build only), classical BD.  HCBD build: 8000 fluid blobs
   at Table I plus 8000 polymer blobs, against the paper's Euler pairs with
   everything off, parts: fluid fluctuations, polymer noise, Flory-Huggins
   forces, transient pairs, the exact sweep (with fluctuations), stress.

   usage: bench_parts [out=out/bench] [scale=1] (scale multiplies the
   number of steps timed) */
#include "bench_common.h"

#if HCBD_MODEL == HCBD_MODEL_HCBD
static const char *build = "hcbd";
enum { NPART = 7 };
static const char *part_name[NPART] = {"all off (Euler pairs, no noise, no polymer forces)",
                                       "fluid fluctuations (Euler)", "polymer noise",
                                       "Flory-Huggins forces", "transient pairs",
                                       "fluctuations with the exact sweep (the default)",
                                       "stress accumulation"};

static double time_part(int part, double scale, int *n)
{
    hcbd_hc_world_def d = hcbd_hc_world_def_default();
    hcbd_hc_world w;
    const int nf = 8000, np = 8000;
    const double L = cbrt(nf / (3.0 / (4.0 * 3.14159265358979323846)));
    double best = 1e30;
    int rep, steps = (int)(20 * scale) < 2 ? 2 : (int)(20 * scale);
    d.params.L[0] = d.params.L[1] = d.params.L[2] = L;
    d.params.fluctuations = part == 1 || part == 5;
    d.params.kT = part == 2 ? 1.0 : 0.0; /* kT = 0 also silences the fluid noise */
    if (part == 1 || part == 5) d.params.kT = 1.0;
    d.params.p_kuhn = part == 3 ? d.params.p_kuhn : 0.0;
    d.params.alpha = part == 4 ? d.params.alpha : 0.0;
    d.params.pair_integrator = part == 5 ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
    d.params.threads = 1;
    d.fluid_capacity = nf;
    d.polymer_capacity = np;
    *n = nf + np;
    if (hcbd_hc_world_create(&w, &d) != HCBD_OK || hcbd_hc_world_place_fluid_lattice(&w, nf) != HCBD_OK ||
        hcbd_hc_world_place_polymers_random(&w, np) != HCBD_OK ||
        (part == 6 && hcbd_hc_world_stress_enable(&w, 1) != HCBD_OK) || hcbd_hc_world_step(&w, 2) != HCBD_OK) {
        fprintf(stderr, "bench_parts: %s\n", w.err.msg);
        return -1;
    }
    for (rep = 0; rep < 3; ++rep) {
        double t0 = now();
        if (hcbd_hc_world_step(&w, steps) != HCBD_OK) {
            fprintf(stderr, "bench_parts: %s\n", w.err.msg);
            best = -1;
            break;
        }
        if ((now() - t0) / steps < best) best = (now() - t0) / steps;
    }
    hcbd_hc_world_destroy(&w);
    return best;
}
#else
static const char *build = HCBD_MODEL == HCBD_MODEL_WALLED ? "walled" : "gibd";
enum { NPART = 8 };
static const char *part_name[NPART] = {"baseline: GI-BD stars, kT = 1, Euler", "kT = 0 (no random numbers)",
                                       "+ lagged densities", "+ Shardlow pair sweep",
                                       "+ Lees-Edwards shear", "+ stress flux", "+ walls",
                                       "classical BD (no background)"};
static double *melt; /* a liquid configuration shared by all rows */

static double time_part(int part, double scale, int *n)
{
    hcbd_world_def d = hcbd_world_def_default();
    hcbd_world w;
    const int N = 4096;
    double best = 1e30, L = cbrt(N / 0.24);
    int rep, steps = (int)(300 * scale) < 5 ? 5 : (int)(300 * scale);
    if (part == 6 && HCBD_MODEL != HCBD_MODEL_WALLED) return 0;
    d.capacity = N;
    d.params.L[0] = d.params.L[1] = d.params.L[2] = L;
    d.params.kT = part == 1 ? 0.0 : 1.0;
    d.params.lagged_density = part == 2;
    /* the papers' Euler pairs, the baseline's name says (not the default) */
    d.params.pair_integrator = part == 3 ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
    if (part == 4) d.params.gdot = 5.0;
    if (part == 6) { /* walls added outside the liquid's box */
        d.params.L[1] = L + 3.0;
        d.params.wall.thickness = 1.5;
    }
    if (part == 7) d.params.dynamics = HCBD_DYN_BD;
    d.params.threads = 1;
    *n = N;
    if (hcbd_world_create(&w, &d) != HCBD_OK) {
        fprintf(stderr, "bench_parts: %s\n", w.err.msg);
        return -1;
    }
    if (!melt) {
        melt = (double *)malloc(3 * sizeof(double) * N);
        if (!melt || hcbd_world_place_lattice(&w, N) != HCBD_OK || hcbd_world_step(&w, 300) != HCBD_OK ||
            hcbd_world_get_positions(&w, melt, 0) != HCBD_OK) {
            fprintf(stderr, "bench_parts: melting failed: %s\n", w.err.msg);
            return -1;
        }
    }
    if (part == 6) {
        int i;
        for (i = 0; i < N; ++i) melt[3 * i + 1] += 1.5;
    }
    if (hcbd_world_set_positions(&w, N, melt) != HCBD_OK || hcbd_world_step(&w, 20) != HCBD_OK) {
        fprintf(stderr, "bench_parts: %s\n", w.err.msg);
        return -1;
    }
    if (part == 6) {
        int i;
        for (i = 0; i < N; ++i) melt[3 * i + 1] -= 1.5;
    }
    if (part == 5) hcbd_world_stress_enable(&w, 1);
    for (rep = 0; rep < 3; ++rep) {
        double t0 = now();
        if (hcbd_world_step(&w, steps) != HCBD_OK) {
            fprintf(stderr, "bench_parts: %s\n", w.err.msg);
            best = -1;
            break;
        }
        if ((now() - t0) / steps < best) best = (now() - t0) / steps;
    }
    hcbd_world_destroy(&w);
    return best;
}
#endif

int main(int argc, char **argv)
{
    char out[512] = "out/bench", path[600];
    double scale = 1.0, base = 0;
    FILE *csv;
    int k;
    for (k = 1; k < argc; ++k) {
        if (!strncmp(argv[k], "out=", 4)) snprintf(out, sizeof out, "%s", argv[k] + 4);
        else if (!strncmp(argv[k], "scale=", 6)) scale = atof(argv[k] + 6);
        else {
            fprintf(stderr, "bench_parts: unknown argument '%s' (out=, scale=)\n", argv[k]);
            return 2;
        }
    }
    {
        char name[64];
        snprintf(name, sizeof name, "parts_%s.csv", build);
        if (!(csv = bench_csv("bench_parts", out, name, path, sizeof path))) return 1;
    }
    fprintf(csv, "build,part,ns_per_particle_step,over_first_row\n");
    printf("| build | scene | ns/particle-step | x first row |\n|---|---|---:|---:|\n");
    for (k = 0; k < NPART; ++k) {
        int n = 1;
        double t = time_part(k, scale, &n);
        if (t < 0) return 1;
        if (t == 0) continue; /* not in this build */
        t *= 1e9 / n;
        if (k == 0) base = t;
        printf("| %s | %s | %.0f | %.2f |\n", build, part_name[k], t, t / base);
        fprintf(csv, "%s,%s,%.1f,%.3f\n", build, part_name[k], t, t / base);
        fflush(stdout);
    }
    fclose(csv);
    return 0;
}
