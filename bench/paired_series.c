/* paired_series: the effect of one change on a Lees-Edwards viscosity of
   hcbd_polymer, from two runs that differ only by that change (same seed,
   same start-up and window: startup_min = startup_max and blocks fixed).
   Reads the half-block series of both runs (startup_C<C>.csv; the rows of
   one Wi in the measured window, phase 1) and prints each run's mean with
   its blocking error (hcbd_blocking_error) and the mean of the paired
   difference b - a over a's mean with the blocking error of the
   differences: the two runs share their polymer and pair noise, so while
   they stay correlated the difference is far less noisy than either run.

   usage: paired_series A.csv B.csv Wi */
#include "../hcbd.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAXS 1024

static int load(const char *file, double wi, double *x)
{
    char line[512];
    int n = 0;
    FILE *f = fopen(file, "r");
    if (!f) {
        fprintf(stderr, "paired_series: cannot read %s\n", file);
        return -1;
    }
    while (fgets(line, sizeof line, f) && n < MAXS) {
        double w, t, e, r;
        int ph;
        if (sscanf(line, "%lf,%lf,%lf,%lf,%d", &w, &t, &e, &r, &ph) == 5 && ph == 1 &&
            fabs(w - wi) <= 1e-9 * wi)
            x[n++] = e;
    }
    fclose(f);
    return n;
}

int main(int argc, char **argv)
{
    static double a[MAXS], b[MAXS], d[MAXS];
    double wi, ma, ea, mb, eb, md, ed, ne;
    int na, nb, k, pa, pb, pd;
    if (argc != 4 || !((wi = atof(argv[3])) > 0)) {
        fprintf(stderr, "usage: paired_series A.csv B.csv Wi\n");
        return 2;
    }
    na = load(argv[1], wi, a);
    nb = load(argv[2], wi, b);
    if (na < 0 || nb < 0) return 1;
    if (na != nb || na < 8) {
        fprintf(stderr, "paired_series: windows of %d and %d half blocks at Wi = %g (equal and >= 8 needed)\n", na,
                nb, wi);
        return 1;
    }
    if (hcbd_blocking_error(a, na, &ma, &ea, NULL, &pa) != HCBD_OK ||
        hcbd_blocking_error(b, nb, &mb, &eb, NULL, &pb) != HCBD_OK)
        return 1;
    for (k = 0; k < na; ++k) d[k] = (b[k] - a[k]) / ma;
    if (hcbd_blocking_error(d, na, &md, &ed, &ne, &pd) != HCBD_OK) return 1;
    printf("Wi=%g half_blocks=%d a=%.5g a_err=%.3g b=%.5g b_err=%.3g rel_diff=%+.5f rel_diff_err=%.5f "
           "plateaus=%d%d%d\n", wi, na, ma, ea, mb, eb, md, ed, pa, pb, pd);
    return 0;
}
