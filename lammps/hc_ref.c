/* hc_ref: hcbd's own 2018 world (the fluid alone) advanced from the atoms
   of a LAMMPS dump, for make test-lammps to compare fix hcbd with, atom by
   atom.  Usage:
     hc_ref IN OUT steps dt rho nbar eta P0 h kT seed fluct pair gdot gx [every]
   IN: write_dump custom id x y z vx vy vz, sorted by id (tags 1..n); OUT:
   "id x y z vx vy vz" after `steps` steps, wrapped into the box; with
   every, stdout: the step and hcbd_hc_world_temperature every `every`
   steps (as LAMMPS's compute temp with the momentum zero).  fluct:
   yes or no (the pair noise); pair: euler (HCBD_PAIR_EULER) or exact;
   gdot: the Lees-Edwards shear rate from IN on (offset 0 there); gx: a
   body force per mass along x. */
#define HCBD_IMPLEMENTATION
#include "hcbd.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    hcbd_hc_world_def def = hcbd_hc_world_def_default();
    hcbd_hc_params *p = &def.params;
    hcbd_hc_world w;
    char line[512];
    double lo[3], hi[3], *x, *v;
    int n = 0, i, d, steps, every = 0, s;
    FILE *in, *out;
    if (argc != 16 && argc != 17) {
        fprintf(stderr, "usage: hc_ref IN OUT steps dt rho nbar eta P0 h kT seed fluct pair gdot gx [every]\n");
        return 2;
    }
    in = fopen(argv[1], "r");
    if (!in) { fprintf(stderr, "hc_ref: cannot read %s\n", argv[1]); return 1; }
    for (i = 0; i < 9 && fgets(line, sizeof line, in); ++i) {
        if (i == 3) n = atoi(line);
        if (i >= 5 && i <= 7 && sscanf(line, "%lf %lf", &lo[i - 5], &hi[i - 5]) != 2) n = 0;
    }
    if (n < 2) { fprintf(stderr, "hc_ref: %s is not a dump of atoms and box\n", argv[1]); return 1; }
    x = (double *)malloc(6 * (size_t)n * sizeof(double));
    v = x + 3 * (size_t)n;
    for (i = 0; i < n; ++i) {
        int id;
        if (fscanf(in, "%d %lf %lf %lf %lf %lf %lf", &id, &x[3 * i], &x[3 * i + 1], &x[3 * i + 2],
                   &v[3 * i], &v[3 * i + 1], &v[3 * i + 2]) != 7 || id != i + 1) {
            fprintf(stderr, "hc_ref: atom line %d of %s (ids must run 1..n in order)\n", i + 1, argv[1]);
            return 1;
        }
        for (d = 0; d < 3; ++d) {
            x[3 * i + d] -= lo[d];
            if (x[3 * i + d] < 0) x[3 * i + d] += hi[d] - lo[d];
            if (x[3 * i + d] >= hi[d] - lo[d]) x[3 * i + d] -= hi[d] - lo[d];
        }
    }
    fclose(in);
    steps = atoi(argv[3]);
    def.fluid_capacity = n;
    def.polymer_capacity = 0;
    for (d = 0; d < 3; ++d) p->L[d] = hi[d] - lo[d];
    p->dt = atof(argv[4]);
    p->rho = atof(argv[5]);
    p->nbar = atof(argv[6]);
    p->eta = atof(argv[7]);
    p->P0 = atof(argv[8]);
    p->h = atof(argv[9]);
    p->kT = atof(argv[10]);
    p->seed = strtoull(argv[11], NULL, 10);
    p->fluctuations = !strcmp(argv[12], "yes");
    p->pair_integrator = strcmp(argv[13], "euler") ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
    p->gdot = atof(argv[14]);
    p->g[0] = atof(argv[15]);
    p->substeps = 1;
    p->threads = 1;
    if (argc == 17) every = atoi(argv[16]);
    if (every < 1) every = steps;
    if (hcbd_hc_world_create(&w, &def) != HCBD_OK || hcbd_hc_world_set_fluid(&w, n, x, v) != HCBD_OK) {
        fprintf(stderr, "hc_ref: %s\n", w.err.msg);
        return 1;
    }
    for (s = 0; s < steps; s += every) {
        if (hcbd_hc_world_step(&w, every) != HCBD_OK) {
            fprintf(stderr, "hc_ref: %s\n", w.err.msg);
            return 1;
        }
        if (argc == 17) printf("%d %.10g\n", s + every, hcbd_hc_world_temperature(&w));
    }
    hcbd_hc_world_get_fluid(&w, x, v);
    out = fopen(argv[2], "w");
    if (!out) { fprintf(stderr, "hc_ref: cannot write %s\n", argv[2]); return 1; }
    for (i = 0; i < n; ++i)
        fprintf(out, "%d %.17g %.17g %.17g %.17g %.17g %.17g\n", i + 1, x[3 * i] + lo[0], x[3 * i + 1] + lo[1],
                x[3 * i + 2] + lo[2], v[3 * i], v[3 * i + 1], v[3 * i + 2]);
    fclose(out);
    hcbd_hc_world_destroy(&w);
    free(x);
    return 0;
}
