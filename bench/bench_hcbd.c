/* bench_hcbd: nanoseconds per particle-step of the 2018 HCBD model, 1 and
   2 threads; the state checksum shows that thread counts give the same
   bits.  Each point: the minimum over repeats of about a second of steps,
   after a warm-up.  Scenes (scenes= picks a comma-separated subset):
     sph, sdpd   the peers of LAMMPS sph/taitwater/morris and
                 sdpd/taitwater/isothermal (bench/peers): nbar = 3/(4 pi),
                 h = 2 (support 4), rho = 1, c_s = 20, eta = 1, dt = 1e-3,
                 kT = 1, cubes of N = 8000 and 64000 blobs, disordered and
                 relaxed at kT = 1 before timing (LAMMPS starts from random
                 positions); sdpd with the pairwise thermal noise
     fluid, fluid-fluct  Table I fluid (reduced units sigma, kT, 1 us) from
                 the lattice, cubes of 806 (the paper's box), 8000, 64000,
                 512000 blobs
     table1, table1-off  8000 fluid + 8000 polymer blobs at Table I (cube),
                 with the defaults (fluctuations, Flory-Huggins, transient
                 pairs) and with every optional part off
     solution-C2 C2 = 5 C* in the paper's box; the time split by species
                 with the fluid alone run beside it
   The CSV has the fluid's neighbours per blob (pairs of its half list
   within 2h + skin) next to each row.

   usage: bench_hcbd [Nmax=512000] [threads=2] [scenes=all] [out=out/bench] */
#include "bench_common.h"

static const double PI = 3.14159265358979323846;

typedef struct {
    double t, pairs; /* seconds per step, fluid half-list pairs per blob */
    uint64_t sum;
} result;

/* The LAMMPS peers' fluid, disordered and at kT = 1: the lattice with
   every coordinate displaced by up to half a spacing (uniform random
   positions leave voids that the density guard refuses at this size), then
   four rounds of Maxwellian velocities at kT (momentum removed) and 100
   steps, so the heat the relaxing density releases is taken out again. */
static int disordered(hcbd_hc_world *w, int nf)
{
    hcbd_rng g;
    double *xyz = (double *)malloc(sizeof(double) * 6 * (size_t)nf), *v = xyz + 3 * (size_t)nf;
    const double s = sqrt(w->p.kT / w->m), a = cbrt(w->p.L[0] * w->p.L[1] * w->p.L[2] / nf);
    int i, d, c, ok;
    if (!xyz) return 0;
    hcbd_rng_seed(&g, 12345);
    ok = hcbd_hc_world_place_fluid_lattice(w, nf) == HCBD_OK;
    for (c = 0; c < 4 && ok; ++c) {
        double mom[3] = {0, 0, 0};
        for (i = 0; i < nf; ++i) {
            const double r[3] = {w->fx[i], w->fy[i], w->fz[i]};
            for (d = 0; d < 3; ++d) {
                double x = r[d], u = hcbd_rng_uniform(&g);
                if (c == 0) {
                    x += a * (hcbd_rng_uniform(&g) - 0.5);
                    x -= w->p.L[d] * floor(x / w->p.L[d]);
                    if (x >= w->p.L[d]) x = 0;
                }
                xyz[3 * i + d] = x;
                v[3 * i + d] = s * sqrt(-2.0 * log(1.0 - u)) * cos(2.0 * PI * hcbd_rng_uniform(&g));
                mom[d] += v[3 * i + d] / nf;
            }
        }
        for (i = 0; i < 3 * nf; ++i) v[i] -= mom[i % 3];
        ok = hcbd_hc_world_set_fluid(w, nf, xyz, v) == HCBD_OK && hcbd_hc_world_step(w, 100) == HCBD_OK;
    }
    free(xyz);
    return ok;
}

/* kind: 0 Table I fluid lattice, 1 LAMMPS peer (disordered), 2 Table I
   fluid + polymers, 3 the same with every optional part off */
static int time_scene(int kind, int nf, int np, const double L[3], int fluct, int th, result *res)
{
    hcbd_hc_world_def d = hcbd_hc_world_def_default();
    hcbd_hc_params *p = &d.params;
    hcbd_hc_world w;
    double best = 1e30;
    int steps = (int)(1e9 / ((nf + 2.0 * np) * 1500.0)), rep, reps = nf <= 8000 ? 3 : 2, ok;
    if (steps < 3) steps = 3;
    memcpy(p->L, L, sizeof p->L);
    p->fluctuations = fluct;
    p->threads = th;
    if (kind == 1) {
        p->nbar = 3.0 / (4.0 * PI);
        p->h = 2.0;
        p->rho = 1.0;
        p->P0 = p->rho * 20.0 * 20.0 / 7.0; /* c_s = 20 */
        p->eta = 1.0;
        p->dt = 1e-3;
        p->kT = 1.0;
    }
    if (kind == 3) {
        p->kT = 0;
        p->p_kuhn = 0;
        p->alpha = 0;
    }
    d.fluid_capacity = nf;
    d.polymer_capacity = np;
    ok = hcbd_hc_world_create(&w, &d) == HCBD_OK;
    if (ok && kind == 1) ok = disordered(&w, nf);
    else if (ok) ok = hcbd_hc_world_place_fluid_lattice(&w, nf) == HCBD_OK &&
                      (!np || hcbd_hc_world_place_polymers_random(&w, np) == HCBD_OK) &&
                      hcbd_hc_world_step(&w, 2) == HCBD_OK;
    if (!ok) {
        fprintf(stderr, "bench_hcbd: %s\n", w.err.msg);
        hcbd_hc_world_destroy(&w);
        return 0;
    }
    for (rep = 0; rep < reps; ++rep) {
        double t0 = now();
        if (hcbd_hc_world_step(&w, steps) != HCBD_OK) {
            fprintf(stderr, "bench_hcbd: %s\n", w.err.msg);
            hcbd_hc_world_destroy(&w);
            return 0;
        }
        if ((now() - t0) / steps < best) best = (now() - t0) / steps;
    }
    res->t = best;
    res->pairs = (double)w.lf.npairs / nf;
    res->sum = hcbd_hc_world_checksum(&w);
    hcbd_hc_world_destroy(&w);
    return 1;
}

static int want(const char *scenes, const char *name)
{
    const char *s = scenes;
    size_t n = strlen(name);
    if (!strcmp(scenes, "all")) return 1;
    while ((s = strstr(s, name)) != NULL) {
        if ((s == scenes || s[-1] == ',') && (s[n] == ',' || s[n] == 0)) return 1;
        s += n;
    }
    return 0;
}

static FILE *csv;

static void row(const char *name, int nf, int np, int th, const result *r, double tf)
{
    const double ns = 1e9 * r->t / (nf + np);
    char pol[32] = "-";
    if (tf > 0) snprintf(pol, sizeof pol, "%.0f", 1e9 * (r->t - tf) / np);
    printf("%-12s %8d %8d %7d %16.0f %12.0f %12s %8.1f %18llx\n", name, nf, np, th, ns,
           1e9 * (tf > 0 ? tf : r->t) / nf, pol, r->pairs, (unsigned long long)r->sum);
    fprintf(csv, "%s,%d,%d,%d,%.1f,%.1f,%s,%.2f,%llx\n", name, nf, np, th, ns,
            1e9 * (tf > 0 ? tf : r->t) / nf, tf > 0 ? pol : "", r->pairs,
            (unsigned long long)r->sum);
    fflush(stdout);
    fflush(csv);
}

int main(int argc, char **argv)
{
    const int sizes[4] = {806, 8000, 64000, 512000};
    const double nbar = 3.0 / (4.0 * PI);
    int Nmax = 512000, maxth = 2, k, th, fl;
    char out[512] = "out/bench", path[600], scenes[256] = "all";
    for (k = 1; k < argc; ++k) {
        if (!strncmp(argv[k], "Nmax=", 5)) Nmax = atoi(argv[k] + 5);
        else if (!strncmp(argv[k], "threads=", 8)) maxth = atoi(argv[k] + 8);
        else if (!strncmp(argv[k], "out=", 4)) snprintf(out, sizeof out, "%s", argv[k] + 4);
        else if (!strncmp(argv[k], "scenes=", 7)) snprintf(scenes, sizeof scenes, "%s", argv[k] + 7);
        else {
            fprintf(stderr, "bench_hcbd: unknown argument '%s' (Nmax=, threads=, scenes=, out=)\n",
                    argv[k]);
            return 2;
        }
    }
    if (maxth < 1) maxth = 1;
    if (!(csv = bench_csv("bench_hcbd", out, "speed_hcbd.csv", path, sizeof path))) return 1;
    fprintf(csv, "scene,N_fluid,N_polymer,threads,ns_per_particle_step,ns_per_fluid_step,"
                 "ns_per_polymer_step,pairs_per_particle,checksum\n");
    printf("%-12s %8s %8s %7s %16s %12s %12s %8s %18s\n", "scene", "fluid", "polymer", "threads",
           "ns/particle-step", "ns/fluid", "ns/polymer", "nb/blob", "checksum");
    for (fl = 0; fl < 2; ++fl) { /* the LAMMPS peers */
        const char *name = fl ? "sdpd" : "sph";
        if (!want(scenes, name)) continue;
        for (k = 1; k < 3 && sizes[k] <= Nmax; ++k) {
            double L[3];
            L[0] = L[1] = L[2] = cbrt(sizes[k] / nbar);
            for (th = 1; th <= maxth; ++th) {
                result r;
                if (!time_scene(1, sizes[k], 0, L, fl, th, &r)) return 1;
                row(name, sizes[k], 0, th, &r, 0);
            }
        }
    }
    for (fl = 1; fl >= 0; --fl) {
        const char *name = fl ? "fluid-fluct" : "fluid";
        if (!want(scenes, name)) continue;
        for (k = 0; k < 4 && sizes[k] <= Nmax; ++k) {
            double L[3];
            /* the first size is the paper's box, the others cubes */
            if (k == 0) { L[0] = 33.75; L[1] = L[2] = 10.0; }
            else L[0] = L[1] = L[2] = cbrt(sizes[k] / nbar);
            for (th = 1; th <= maxth; ++th) {
                result r;
                if (!time_scene(0, sizes[k], 0, L, fl, th, &r)) return 1;
                row(name, sizes[k], 0, th, &r, 0);
            }
        }
    }
    for (fl = 0; fl < 2; ++fl) {
        const char *name = fl ? "table1-off" : "table1";
        double L[3];
        if (!want(scenes, name) || 8000 > Nmax) continue;
        L[0] = L[1] = L[2] = cbrt(8000 / nbar);
        for (th = 1; th <= maxth; ++th) {
            result r;
            if (!time_scene(fl ? 3 : 2, 8000, 8000, L, !fl, th, &r)) return 1;
            row(name, 8000, 8000, th, &r, 0);
        }
    }
    if (want(scenes, "solution-C2")) { /* polymer time = total - fluid alone */
        const double L[3] = {33.75, 10.0, 10.0};
        const int nf = 806, np = 5 * 806;
        for (th = 1; th <= maxth; ++th) {
            result r, rf;
            if (!time_scene(2, nf, np, L, 0, th, &r) || !time_scene(0, nf, 0, L, 0, th, &rf)) return 1;
            row("solution-C2", nf, np, th, &r, rf.t);
        }
    }
    fclose(csv);
    printf("wrote %s\n", path);
    return 0;
}
