/* carreau_refit: how much the Carreau parameters of a flow curve depend on
   the choices the 2018 paper leaves open (issue 28, item 3).  Reads the
   flowcurve.csv of hcbd_polymer (total viscosity in mPa s with its error,
   per concentration and rate) and, per concentration, refits with
   eta_inf = 0.9 mPa s (Table II), with eta_inf = 1 mPa s (the solvent), with
   the lowest or the highest rate left out; and scores Table II's own curve
   against the points (chi^2 per point, with the points' errors).  With the
   run's folder as a second argument, each rate's error is first raised to
   the blocking error (hcbd_blocking_error as this build has it) of the
   half-block series of its measured window (startup_C<C>.csv), so that
   the outputs of an older build are scored as the present one would, and
   each rate's viscosity over Table II's curve is printed.  Two fits weigh
   the points without their errors (equal relative, equal absolute), as
   the paper, which does not say, may have.

   With --pool and several run folders (seeds of one preset), each rate's
   viscosity is the mean over the folders and its error the larger of the
   scatter's (standard deviation / sqrt(runs)) and the stated errors'
   (root sum of squares / runs): at the slow rates a window is worth a few
   independent samples, its blocking error is a lower bound, and the seeds'
   scatter is the honest one (issue 41).  One fit of the pooled points,
   rather than the mean of per-seed fits, keeps a fit that hangs on its two
   slowest points from amplifying their scatter.

   usage: carreau_refit FLOWCURVE.csv [RUN_DIR]
          carreau_refit --pool RUN_DIR RUN_DIR... */
#include "../hcbd.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAXP 32

static double carreau(const double p[3], double eta_inf, double g)
{
    return eta_inf + (p[0] - eta_inf) * pow(1 + (p[1] * g) * (p[1] * g), 0.5 * (p[2] - 1));
}

static void fit(const char *what, const double *g, const double *e, const double *s, int n, double eta_inf)
{
    double p[3], pe[3], chi2;
    if (n < 4 || hcbd_carreau_fit(g, e, s, n, eta_inf, 0, p, pe, &chi2) != HCBD_OK) {
        printf("  %-34s no fit (%d rates)\n", what, n);
        return;
    }
    {
        /* in brackets the errors scaled by sqrt(chi^2/dof) where it is above 1 */
        const double sc = hcbd_carreau_err_scale(chi2, n);
        printf("  %-34s eta0 %7.3f +- %-6.2g (%-6.2g) lambda %8.4g +- %-6.2g (%-6.2g) n %6.3f +- %-6.2g (%-6.2g) "
               "chi2/dof %.2f\n", what, p[0], pe[0], pe[0] * sc, p[1], pe[1], pe[1] * sc, p[2], pe[2], pe[2] * sc,
               chi2 / (n - 3));
    }
}

/* the blocking error of rate gdot's window in DIR/startup_C<C>.csv (0 if
   the file or the series is missing) */
static double window_error(const char *dir, double conc, double wi)
{
    char name[1024], line[512];
    double x[1024];
    int n = 0;
    FILE *f;
    snprintf(name, sizeof name, "%s/startup_C%g.csv", dir, conc);
    if (!(f = fopen(name, "r"))) return 0;
    while (n < 1024 && fgets(line, sizeof line, f)) {
        double w, t, e, r;
        int ph;
        if (sscanf(line, "%lf,%lf,%lf,%lf,%d", &w, &t, &e, &r, &ph) == 5 && ph == 1 && fabs(w - wi) <= 1e-9 * wi)
            x[n++] = e;
    }
    fclose(f);
    {
        double m, err;
        return n >= 8 && hcbd_blocking_error(x, n, &m, &err, NULL, NULL) == HCBD_OK ? err : 0;
    }
}

/* reads FLOWCURVE (raising each error to its window's blocking error when
   dir is given) into C, g, wi, e, s from index n up to cap; returns the new
   count */
static int read_curve(const char *path, const char *dir, double *C, double *g, double *wi, double *e, double *s,
                      int n, int cap)
{
    char line[4096];
    FILE *f = fopen(path, "r");
    if (!f || !fgets(line, sizeof line, f)) { /* header */
        fprintf(stderr, "carreau_refit: cannot read %s\n", path);
        if (f) fclose(f);
        return -1;
    }
    while (n < cap && fgets(line, sizeof line, f)) {
        double v[32];
        int m = 0;
        char *tok = strtok(line, ",");
        while (tok && m < 32) { v[m++] = atof(tok); tok = strtok(NULL, ","); }
        if (m < 14) continue;
        /* C, gdot_per_s, gdot, Wi, 4 x (eta, err) reduced, then mPa s */
        C[n] = v[0]; g[n] = v[1]; wi[n] = v[3]; e[n] = v[12]; s[n] = v[13] > 0 ? v[13] : 1e-9;
        if (dir) s[n] = fmax(s[n], window_error(dir, C[n], wi[n]));
        ++n;
    }
    fclose(f);
    return n;
}

int main(int argc, char **argv)
{
    static const double table2[2][4] = {{2.5, 2.526, 3.0504, 0.3441}, {5, 6.6688, 2.1408, 0.0008}};
    double C[MAXP], g[MAXP], wi[MAXP], e[MAXP], s[MAXP];
    int n = 0, k, c;
    const int pool = argc >= 2 && !strcmp(argv[1], "--pool");
    if (pool && argc < 3) {
        fprintf(stderr, "usage: carreau_refit --pool RUN_DIR RUN_DIR... (hcbd_polymer's output folders)\n");
        return 2;
    }
    if (pool) {
        /* every folder's curve, then the mean of each (C, rate) over them */
        static double PC[MAXP * 8], Pg[MAXP * 8], Pw[MAXP * 8], Pe[MAXP * 8], Ps[MAXP * 8];
        char path[1024];
        int np = 0, r, d;
        if (argc - 2 > 8) {
            fprintf(stderr, "carreau_refit: at most 8 folders to pool (%d given)\n", argc - 2);
            return 2;
        }
        for (d = 2; d < argc; ++d) {
            const int before = np;
            snprintf(path, sizeof path, "%s/flowcurve.csv", argv[d]);
            if ((np = read_curve(path, argv[d], PC, Pg, Pw, Pe, Ps, np, MAXP * 8)) < 0) return 2;
            printf("%s: %d rates\n", argv[d], np - before);
        }
        for (k = 0; k < np; ++k) {
            double sum = 0, sum2 = 0, var = 0;
            int runs = 0, seen = 0;
            for (r = 0; r < k && !seen; ++r) seen = PC[r] == PC[k] && Pg[r] == Pg[k];
            if (seen) continue;
            if (n == MAXP) {
                fprintf(stderr, "carreau_refit: more than %d rates to pool: C = %g, %g 1/s left out\n", MAXP,
                        PC[k], Pg[k]);
                continue;
            }
            for (r = k; r < np; ++r)
                if (PC[r] == PC[k] && Pg[r] == Pg[k]) { sum += Pe[r]; sum2 += Ps[r] * Ps[r]; ++runs; }
            C[n] = PC[k]; g[n] = Pg[k]; wi[n] = Pw[k]; e[n] = sum / runs;
            for (r = k; r < np; ++r)
                if (PC[r] == PC[k] && Pg[r] == Pg[k]) var += (Pe[r] - e[n]) * (Pe[r] - e[n]);
            var = runs > 1 ? var / (runs - 1) : 0;
            s[n] = fmax(sqrt(var / runs), sqrt(sum2) / runs);
            printf("C = %g, Wi = %g: %d runs, mean %.4f mPa s, scatter's error %.4f, stated %.4f\n", C[n], wi[n],
                   runs, e[n], sqrt(var / runs), sqrt(sum2) / runs);
            ++n;
        }
        /* by rate, as a single curve is: the fits that leave out the lowest
           or the highest rate take the ends of the list */
        for (k = 1; k < n; ++k)
            for (r = k; r > 0 && g[r] < g[r - 1]; --r) {
                double t;
                t = C[r]; C[r] = C[r - 1]; C[r - 1] = t;
                t = g[r]; g[r] = g[r - 1]; g[r - 1] = t;
                t = wi[r]; wi[r] = wi[r - 1]; wi[r - 1] = t;
                t = e[r]; e[r] = e[r - 1]; e[r - 1] = t;
                t = s[r]; s[r] = s[r - 1]; s[r - 1] = t;
            }
    } else {
        if (argc < 2 || argc > 3) {
            fprintf(stderr, "usage: carreau_refit FLOWCURVE.csv [RUN_DIR] | --pool RUN_DIR RUN_DIR... "
                            "(hcbd_polymer's)\n");
            return 2;
        }
        if ((n = read_curve(argv[1], argc == 3 ? argv[2] : NULL, C, g, wi, e, s, 0, MAXP)) < 0) return 2;
    }
    for (c = 0; c < 2; ++c) {
        double gg[MAXP], ee[MAXP], ss[MAXP], chi = 0;
        int m = 0;
        for (k = 0; k < n; ++k)
            if (C[k] == table2[c][0]) { gg[m] = g[k]; ee[m] = e[k]; ss[m] = s[k]; ++m; }
        if (!m) continue;
        printf("C = %g C* (%d rates %g..%g 1/s); eta in mPa s, lambda in s\n", table2[c][0], m, gg[0], gg[m - 1]);
        for (k = 0; k < m; ++k) {
            const double d = (ee[k] - carreau(table2[c] + 1, 0.9, gg[k])) / ss[k];
            chi += d * d;
        }
        printf("  %-34s eta0 %7.3f                     lambda %8.4g                     n %6.3f                     "
               "chi2/point %.2f\n", "Table II (against these points)", table2[c][1], table2[c][2], table2[c][3],
               chi / m);
        printf("  over Table II's curve:");
        for (k = 0; k < m; ++k) {
            const double t2 = carreau(table2[c] + 1, 0.9, gg[k]);
            printf(" %.3f +- %.3f", ee[k] / t2, ss[k] / t2);
        }
        printf("\n");
        fit("fit, eta_inf = 0.9 (Table II)", gg, ee, ss, m, 0.9);
        fit("fit, eta_inf = 1.0 (the solvent)", gg, ee, ss, m, 1.0);
        fit("fit, lowest rate left out", gg + 1, ee + 1, ss + 1, m - 1, 0.9);
        fit("fit, highest rate left out", gg, ee, ss, m - 1, 0.9);
        {
            /* weights the paper may have used instead of the errors: each
               point's relative, or absolute, misfit counting the same.  The
               stated 0.1 % is far below the misfit, so the bracketed
               errors are those of the unweighted fit, from its scatter */
            double rel[MAXP], same[MAXP], mean = 0;
            for (k = 0; k < m; ++k) mean += ee[k] / m;
            for (k = 0; k < m; ++k) { rel[k] = 1e-3 * ee[k]; same[k] = 1e-3 * mean; }
            fit("fit, equal relative weights", gg, ee, rel, m, 0.9);
            fit("fit, equal weights", gg, ee, same, m, 0.9);
        }
    }
    return 0;
}
