/* The atoms of a LAMMPS dump for the reference programs (gibd_ref.c,
   hc_ref.c): write_dump custom id x y z vx vy vz, sorted by id (tags 1..n).
   Returns 6 n doubles, the positions relative to the box's low corner
   (wrap: into the box) and then the velocities, with n and the box; NULL
   after a message on stderr that names prog. */
#ifndef HCBD_REF_DUMP_H
#define HCBD_REF_DUMP_H

#include <stdio.h>
#include <stdlib.h>

static double *ref_read_dump(const char *prog, const char *path, int wrap, int *n_out, double lo[3], double hi[3])
{
    char line[512];
    double *x, *v;
    int n = 0, i, d;
    FILE *in = fopen(path, "r");
    if (!in) { fprintf(stderr, "%s: cannot read %s\n", prog, path); return NULL; }
    for (i = 0; i < 9 && fgets(line, sizeof line, in); ++i) {
        if (i == 3) n = atoi(line);
        if (i >= 5 && i <= 7 && sscanf(line, "%lf %lf", &lo[i - 5], &hi[i - 5]) != 2) n = 0;
    }
    if (n < 2) { fprintf(stderr, "%s: %s is not a dump of atoms and box\n", prog, path); fclose(in); return NULL; }
    x = (double *)malloc(6 * (size_t)n * sizeof(double));
    if (!x) { fclose(in); return NULL; }
    v = x + 3 * (size_t)n;
    for (i = 0; i < n; ++i) {
        int id;
        if (fscanf(in, "%d %lf %lf %lf %lf %lf %lf", &id, &x[3 * i], &x[3 * i + 1], &x[3 * i + 2],
                   &v[3 * i], &v[3 * i + 1], &v[3 * i + 2]) != 7 || id != i + 1) {
            fprintf(stderr, "%s: atom line %d of %s (ids must run 1..n in order)\n", prog, i + 1, path);
            free(x);
            fclose(in);
            return NULL;
        }
        for (d = 0; d < 3; ++d) {
            x[3 * i + d] -= lo[d];
            if (wrap && x[3 * i + d] < 0) x[3 * i + d] += hi[d] - lo[d];
            if (wrap && x[3 * i + d] >= hi[d] - lo[d]) x[3 * i + d] -= hi[d] - lo[d];
        }
    }
    fclose(in);
    *n_out = n;
    return x;
}

#endif
