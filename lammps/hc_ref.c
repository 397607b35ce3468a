/* hc_ref: hcbd's own 2018 world advanced from the atoms of a LAMMPS dump,
   for make test-lammps to compare fix hcbd with, atom by atom.  Usage:
     hc_ref IN OUT steps key=value ...
   IN: write_dump custom id x y z vx vy vz, sorted by id (tags 1..n, the nf
   fluid blobs first, then the polymers); OUT: "id x y z vx vy vz" after
   `steps` polymer steps (of substeps fluid steps each), wrapped into the
   box, a polymer's velocity its drift velocity u_a of the last step; stdout: hcbd_hc_world_stress_read's
   ten columns, averaged over the steps.  Keys: nf (default all), dt (the fluid
   step: LAMMPS's), rho nbar eta P0 h kT seed xi sigma rc alpha tau_lambda
   p n_max chi substeps (hcbd_hc_params), fluct yes|no, pair euler|exact,
   coupling shepard|raw, gdot (Lees-Edwards from IN on, offset 0 there), gx
   (a body force per mass along x; with rp=1 the reverse-Poiseuille force:
   +gx in the upper half of y, -gx in the lower, less the mean), every k: stdout gets the step and
   hcbd_hc_world_temperature every k steps (as LAMMPS's compute temp of the
   fluid with its momentum zero) before the stress; threads (1); timing=1:
   stderr gets the steps' wall-clock seconds. */
#define _POSIX_C_SOURCE 199309L
#define HCBD_IMPLEMENTATION
#include "hcbd.h"
#include "ref_dump.h"

#include <time.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    hcbd_hc_world_def def = hcbd_hc_world_def_default();
    hcbd_hc_params *p = &def.params;
    hcbd_hc_world w;
    double lo[3], hi[3], *x, *v, *u, dt_f = 0;
    int n = 0, nf = -1, i, d, steps, every = 0, s, a, timing = 0;
    struct timespec t0, t1;
    FILE *out;
    if (argc < 4) {
        fprintf(stderr, "usage: hc_ref IN OUT steps key=value ...\n");
        return 2;
    }
    p->fluctuations = 0;
    p->substeps = 1;
    p->threads = 1;
    p->pair_integrator = HCBD_PAIR_EULER;
    for (a = 4; a < argc; ++a) {
        const char *eq = strchr(argv[a], '='), *val = eq ? eq + 1 : "";
        const size_t len = eq ? (size_t)(eq - argv[a]) : 0;
        struct { const char *key; double *dst; } keys[] = {
            {"rho", &p->rho}, {"nbar", &p->nbar}, {"eta", &p->eta}, {"P0", &p->P0}, {"h", &p->h},
            {"kT", &p->kT}, {"xi", &p->xi}, {"sigma", &p->sigma}, {"rc", &p->rc}, {"alpha", &p->alpha},
            {"tau_lambda", &p->tau_lambda}, {"p", &p->p_kuhn}, {"n_max", &p->n_max}, {"chi", &p->chi},
            {"gdot", &p->gdot}, {"gx", &p->g[0]}, {"dt", &dt_f}};
        int k, hit = 0;
        for (k = 0; k < (int)(sizeof keys / sizeof keys[0]); ++k)
            if (len == strlen(keys[k].key) && !strncmp(argv[a], keys[k].key, len)) {
                *keys[k].dst = atof(val);
                hit = 1;
            }
        if (hit) continue;
        if (!strncmp(argv[a], "nf=", 3)) nf = atoi(val);
        else if (!strncmp(argv[a], "seed=", 5)) p->seed = strtoull(val, NULL, 10);
        else if (!strncmp(argv[a], "substeps=", 9)) p->substeps = atoi(val);
        else if (!strncmp(argv[a], "every=", 6)) every = atoi(val);
        else if (!strncmp(argv[a], "rp=", 3)) p->reverse_poiseuille = atoi(val);
        else if (!strncmp(argv[a], "threads=", 8)) p->threads = atoi(val);
        else if (!strncmp(argv[a], "timing=", 7)) timing = atoi(val);
        else if (!strncmp(argv[a], "fluct=", 6)) p->fluctuations = !strcmp(val, "yes");
        else if (!strncmp(argv[a], "pair=", 5)) p->pair_integrator = strcmp(val, "euler") ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
        else if (!strncmp(argv[a], "coupling=", 9)) p->coupling = strcmp(val, "raw") ? HCBD_COUPLE_SHEPARD : HCBD_COUPLE_RAW;
        else {
            fprintf(stderr, "hc_ref: unknown argument %s\n", argv[a]);
            return 2;
        }
    }
    p->dt = dt_f * p->substeps;
    x = ref_read_dump("hc_ref", argv[1], 1, &n, lo, hi);
    if (!x) return 1;
    v = x + 3 * (size_t)n;
    if (nf < 0 || nf > n) nf = n;
    steps = atoi(argv[3]);
    def.fluid_capacity = nf;
    def.polymer_capacity = n - nf;
    for (d = 0; d < 3; ++d) p->L[d] = hi[d] - lo[d];
    if (every < 1) every = steps;
    if (hcbd_hc_world_create(&w, &def) != HCBD_OK || hcbd_hc_world_set_fluid(&w, nf, x, v) != HCBD_OK ||
        (n > nf && hcbd_hc_world_set_polymers(&w, n - nf, x + 3 * (size_t)nf) != HCBD_OK)) {
        fprintf(stderr, "hc_ref: %s\n", w.err.msg);
        return 1;
    }
    if (!timing) hcbd_hc_world_stress_enable(&w, 1);
    clock_gettime(CLOCK_MONOTONIC, &t0);
    u = (double *)calloc(3 * (size_t)(n - nf) + 1, sizeof(double));
    for (s = 0; s < steps; s += every) {
        /* the last step's drift velocities are prepared before it */
        const int last = s + every >= steps, k = last ? every - 1 : every;
        if (hcbd_hc_world_step(&w, k) != HCBD_OK) {
            fprintf(stderr, "hc_ref: %s\n", w.err.msg);
            return 1;
        }
        for (i = 0; last && i < n - nf; ++i) {
            u[3 * i] = w.pux[i]; u[3 * i + 1] = w.puy[i]; u[3 * i + 2] = w.puz[i];
        }
        if (last && hcbd_hc_world_step(&w, 1) != HCBD_OK) {
            fprintf(stderr, "hc_ref: %s\n", w.err.msg);
            return 1;
        }
        if (every < steps) printf("%d %.10g\n", s + every, hcbd_hc_world_temperature(&w));
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    if (timing) fprintf(stderr, "seconds %.6f\n", (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec));
    {
        double st[HCBD_HC_NSTRESS];
        hcbd_hc_world_stress_read(&w, st, NULL);
        for (d = 0; d < HCBD_HC_NSTRESS; ++d) printf("%.17g%c", st[d], d + 1 < HCBD_HC_NSTRESS ? ' ' : '\n');
    }
    hcbd_hc_world_get_fluid(&w, x, v);
    if (n > nf) hcbd_hc_world_get_polymers(&w, x + 3 * (size_t)nf);
    out = fopen(argv[2], "w");
    if (!out) { fprintf(stderr, "hc_ref: cannot write %s\n", argv[2]); return 1; }
    for (i = 0; i < n; ++i)
        fprintf(out, "%d %.17g %.17g %.17g %.17g %.17g %.17g\n", i + 1, x[3 * i] + lo[0], x[3 * i + 1] + lo[1],
                x[3 * i + 2] + lo[2], i < nf ? v[3 * i] : u[3 * (i - nf)], i < nf ? v[3 * i + 1] : u[3 * (i - nf) + 1],
                i < nf ? v[3 * i + 2] : u[3 * (i - nf) + 2]);
    fclose(out);
    hcbd_hc_world_destroy(&w);
    free(x);
    free(u);
    return 0;
}
