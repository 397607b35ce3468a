/* gibd_ref: hcbd's own GI-BD world advanced from the atoms of a LAMMPS
   dump, for make test-lammps to compare fix gibd with, atom by atom.  Usage:
     gibd_ref IN OUT steps dt tau xi xip kT Rc density norm seed noise f sigma eps rcut
              pair brownian gdot [wall mode vlo vhi fx]
   IN: write_dump custom id x y z vx vy vz, sorted by id (tags 1..n); OUT:
   "id x y z vx vy vz" after `steps` steps, wrapped into the box; stdout:
   the pair energy and hcbd_world_friction_average (nk = 1) of IN, then that of
   the configuration the last step starts from (fix gibd's vector, fric),
   then the shear stress of the background exchanges and of the carriers
   crossing y, averaged over the steps (hcbd_world_stress_read's [1] and [2]).  f = 0:
   ideal carriers; otherwise the star potential (2014 eq. 28, from the
   formula, not the force table).  noise: gauss or uniform; pair: exact
   (HCBD_PAIR_SHARDLOW, the world's sweep) or euler; brownian: lm or euler;
   gdot: the Lees-Edwards shear rate from IN on (offset 0 there); wall: the
   walls' thickness (walled build; mode gauss, noslip or reflect, the walls'
   x velocities vlo and vhi), fx: a body force along x on every carrier. */
#define HCBD_IMPLEMENTATION
#include "hcbd.h"
#include "ref_dump.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    hcbd_world_def def = hcbd_world_def_default();
    hcbd_params *p = &def.params;
    hcbd_world w;
    double lo[3], hi[3], fr[3], *x, *v;
    int n = 0, i, d, steps;
    FILE *out;
    if (argc != 21 && argc != 26) {
        fprintf(stderr, "usage: gibd_ref IN OUT steps dt tau xi xip kT Rc density norm seed noise f sigma eps "
                        "rcut pair brownian gdot [wall mode vlo vhi fx]\n");
        return 2;
    }
    x = ref_read_dump("gibd_ref", argv[1], 0, &n, lo, hi);
    if (!x) return 1;
    v = x + 3 * (size_t)n;
    steps = atoi(argv[3]);
    p->dt = atof(argv[4]);
    def.capacity = n;
    for (d = 0; d < 3; ++d) p->L[d] = hi[d] - lo[d];
    p->tau = atof(argv[5]);
    p->xi = atof(argv[6]);
    p->xip = atof(argv[7]);
    p->kT = atof(argv[8]);
    p->Rc = atof(argv[9]);
    p->density = atof(argv[10]);
    p->density_norm = atoi(argv[11]);
    p->seed = strtoull(argv[12], NULL, 10);
    p->noise = strcmp(argv[13], "uniform") ? HCBD_NOISE_GAUSS : HCBD_NOISE_UNIFORM;
    p->f = atof(argv[14]);
    p->potential = p->f > 0 ? HCBD_POT_STAR : HCBD_POT_IDEAL;
    p->sigma = atof(argv[15]);
    p->star_eps = atof(argv[16]);
    p->rcut = atof(argv[17]);
    p->force_table = 0;
    p->pair_integrator = strcmp(argv[18], "euler") ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
    p->brownian = strcmp(argv[19], "euler") ? HCBD_BROWNIAN_LM : HCBD_BROWNIAN_EULER;
    p->gdot = atof(argv[20]);
    if (argc == 26) {
        p->wall.thickness = atof(argv[21]);
        if (!strcmp(argv[22], "gauss")) p->wall.mode = HCBD_WALL_GAUSS;
        else if (!strcmp(argv[22], "noslip")) p->wall.mode = HCBD_WALL_NOSLIP;
        else if (!strcmp(argv[22], "reflect")) p->wall.mode = HCBD_WALL_REFLECT;
        else {
            fprintf(stderr, "gibd_ref: wall mode '%s' is not gauss, noslip or reflect\n", argv[22]);
            return 2;
        }
        p->wall.vx[0] = atof(argv[23]);
        p->wall.vx[1] = atof(argv[24]);
        p->fext[0] = atof(argv[25]);
    }
    if (hcbd_world_create(&w, &def) != HCBD_OK || hcbd_world_set_positions(&w, n, x) != HCBD_OK ||
        hcbd_world_set_velocities(&w, v) != HCBD_OK) {
        fprintf(stderr, "gibd_ref: %s\n", w.err.msg);
        return 1;
    }
    if (hcbd_world_friction_average(&w, 1, fr) != HCBD_OK) {
        fprintf(stderr, "gibd_ref: %s\n", w.err.msg);
        return 1;
    }
    printf("%.17g %.17g %.17g %.17g\n", hcbd_world_potential_energy(&w), fr[0], fr[1], fr[2]);
    hcbd_world_stress_enable(&w, 1);
    if (steps < 1 || hcbd_world_step(&w, steps - 1) != HCBD_OK || hcbd_world_friction_average(&w, 1, fr) != HCBD_OK ||
        hcbd_world_step(&w, 1) != HCBD_OK) {
        fprintf(stderr, "gibd_ref: %s\n", w.err.msg);
        return 1;
    }
    printf("%.17g %.17g %.17g\n", fr[0], fr[1], fr[2]);
    {
        double st[4];
        hcbd_world_stress_read(&w, st, NULL);
        printf("%.17g %.17g\n", st[1], st[2]);
    }
    hcbd_world_get_positions(&w, x, 0);
    hcbd_world_get_velocities(&w, v);
    out = fopen(argv[2], "w");
    if (!out) { fprintf(stderr, "gibd_ref: cannot write %s\n", argv[2]); return 1; }
    for (i = 0; i < n; ++i)
        fprintf(out, "%d %.17g %.17g %.17g %.17g %.17g %.17g\n", i + 1, x[3 * i] + lo[0], x[3 * i + 1] + lo[1],
                x[3 * i + 2] + lo[2], v[3 * i], v[3 * i + 1], v[3 * i + 2]);
    fclose(out);
    hcbd_world_destroy(&w);
    free(x);
    return 0;
}
