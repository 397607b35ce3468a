/* wp_estimate: the one estimator of bench/peers/wp.sh, applied alike to
   hcbd's and LAMMPS's dumped configurations of the 2014 star fluid.  It
   reads frames of a LAMMPS "dump custom ... id x y z" (sorted or not) or
   of hcbd's extended XYZ (hcbd_world_write_xyz), cubic periodic box, and
   computes from the positions alone, with the star potential written here
   from 2014 eq. 28 (f arms, sigma = eps = 1, cut rcut):
     T_conf = <sum_i |F_i|^2> / <sum_i lap_i U>   (Rugh; kT = 1)
   as the ratio of block sums over 20 blocks of consecutive frames (error:
   the standard error of the 20 block ratios), and g(r) on [0, rmax) in
   bins of dr, with the error of each bin from the same blocks;
   T_conf_all is the ratio over every frame read (as hcbd_world_config_temperature
   summed over the same frames, which wp.sh compares).
   With ref=FILE (a g file of an earlier call) it also prints
     g_err   = sqrt(mean over bins in [rlo, rmax) of (g - g_ref)^2)
     g_floor = sqrt(mean of (err^2 + err_ref^2)), the part of g_err that
               statistics alone give
   Output: one line of key=value; with g=FILE the g(r) table "r g err".

   usage: wp_estimate FILE [f=128] [rcut=2.5] [rmax=3] [dr=0.05] [rlo=0.5]
                      [skip=0] [g=FILE] [ref=FILE] */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { NBLK = 20, MAXBIN = 400 };

typedef struct {
    int n, cap;
    double L;
    double *x; /* 3n */
} frame;

static int grow(frame *fr, int n)
{
    if (n <= fr->cap) return 1;
    free(fr->x);
    fr->x = (double *)malloc(3 * (size_t)n * sizeof(double));
    fr->cap = fr->x ? n : 0;
    return fr->x != NULL;
}

/* next frame of either format into fr; 0 at the end, -1 on a bad file */
static int read_frame(FILE *f, frame *fr)
{
    char line[4096];
    if (!fgets(line, sizeof line, f)) return 0;
    if (!strncmp(line, "ITEM: TIMESTEP", 14)) { /* LAMMPS dump custom */
        int n = 0, i, cid = -1, cx = -1, cy = -1, cz = -1, k;
        double lo, hi;
        if (!fgets(line, sizeof line, f) || !fgets(line, sizeof line, f) || !fgets(line, sizeof line, f) ||
            sscanf(line, "%d", &n) != 1 || n < 1)
            return -1;
        if (!fgets(line, sizeof line, f) || !fgets(line, sizeof line, f) || sscanf(line, "%lf %lf", &lo, &hi) != 2)
            return -1;
        fr->L = hi - lo;
        if (!fgets(line, sizeof line, f) || !fgets(line, sizeof line, f) || !fgets(line, sizeof line, f))
            return -1;
        { /* ITEM: ATOMS id x y z ... : the columns by name */
            char *t = strtok(line + 11, " \t\r\n");
            for (k = 0; t; ++k, t = strtok(NULL, " \t\r\n")) {
                if (!strcmp(t, "id")) cid = k;
                else if (!strcmp(t, "x")) cx = k;
                else if (!strcmp(t, "y")) cy = k;
                else if (!strcmp(t, "z")) cz = k;
            }
        }
        if (cid < 0 || cx < 0 || cy < 0 || cz < 0 || !grow(fr, n)) return -1;
        fr->n = n;
        for (i = 0; i < n; ++i) {
            double v[16];
            char *p = line, *e;
            int id;
            if (!fgets(line, sizeof line, f)) return -1;
            for (k = 0; k < 16; ++k) {
                v[k] = strtod(p, &e);
                if (e == p) break;
                p = e;
            }
            id = (int)v[cid];
            if (k <= cz || id < 1 || id > n) return -1;
            fr->x[3 * (id - 1)] = v[cx] - lo;
            fr->x[3 * (id - 1) + 1] = v[cy] - lo;
            fr->x[3 * (id - 1) + 2] = v[cz] - lo;
        }
        return 1;
    } else { /* extended XYZ: count, comment with Lattice="L 0 0 0 L 0 0 0 L", "S x y z ..." */
        int n, i;
        char *lat;
        if (sscanf(line, "%d", &n) != 1 || n < 1 || !fgets(line, sizeof line, f)) return -1;
        lat = strstr(line, "Lattice=\"");
        if (!lat || sscanf(lat + 9, "%lf", &fr->L) != 1 || !grow(fr, n)) return -1;
        fr->n = n;
        for (i = 0; i < n; ++i) {
            char s[16];
            if (!fgets(line, sizeof line, f) ||
                sscanf(line, "%15s %lf %lf %lf", s, &fr->x[3 * i], &fr->x[3 * i + 1], &fr->x[3 * i + 2]) != 4)
                return -1;
        }
        return 1;
    }
}

/* 2014 eq. 28 with sigma = eps = 1: dV/dr and the Laplacian V'' + 2V'/r */
static void star_derivs(double r, double f, double *dv, double *lap)
{
    const double A = 5.0 / 18.0 * pow(f, 1.5), B = 1.0 / (1.0 + 0.5 * sqrt(f)), s = 0.5 * sqrt(f);
    if (r <= 1.0) {
        *dv = -A / r;
        *lap = -A / (r * r); /* V'' = A/r^2, 2V'/r = -2A/r^2 */
    } else {
        const double e = A * B * exp(-s * (r - 1.0));
        *dv = -e * (1.0 / (r * r) + s / r);
        *lap = e * s * s / r;
    }
}

int main(int argc, char **argv)
{
    const char *path = NULL, *gout = NULL, *ref = NULL;
    double f = 128, rcut = 2.5, rmax = 3.0, dr = 0.05, rlo = 0.5;
    int skip = 0, k, nf = 0, nbin, b;
    frame fr = {0, 0, 0, NULL};
    double *F2 = NULL, *LP = NULL, *G = NULL; /* per frame, G: nbin per frame */
    size_t cap = 0;
    FILE *in;
    for (k = 1; k < argc; ++k) {
        const char *a = argv[k];
        if (!strncmp(a, "f=", 2)) f = atof(a + 2);
        else if (!strncmp(a, "rcut=", 5)) rcut = atof(a + 5);
        else if (!strncmp(a, "rmax=", 5)) rmax = atof(a + 5);
        else if (!strncmp(a, "dr=", 3)) dr = atof(a + 3);
        else if (!strncmp(a, "rlo=", 4)) rlo = atof(a + 4);
        else if (!strncmp(a, "skip=", 5)) skip = atoi(a + 5);
        else if (!strncmp(a, "g=", 2)) gout = a + 2;
        else if (!strncmp(a, "ref=", 4)) ref = a + 4;
        else if (!strchr(a, '=') && !path) path = a;
        else {
            fprintf(stderr, "wp_estimate: unknown argument '%s'\n", a);
            return 2;
        }
    }
    nbin = (int)(rmax / dr + 0.5);
    if (!path || nbin < 1 || nbin > MAXBIN || !(f > 0) || !(rcut > 0)) {
        fprintf(stderr, "usage: wp_estimate FILE [f=] [rcut=] [rmax=] [dr=] [rlo=] [skip=] [g=FILE] [ref=FILE]\n");
        return 2;
    }
    if (!(in = fopen(path, "r"))) {
        fprintf(stderr, "wp_estimate: cannot read %s\n", path);
        return 1;
    }
    for (;;) {
        int got = read_frame(in, &fr), i, j, c;
        double *Fv, f2 = 0, lp = 0, *g;
        if (got < 0) {
            fprintf(stderr, "wp_estimate: %s: bad frame %d\n", path, nf + skip + 1);
            return 1;
        }
        if (!got) break;
        if (skip > 0) {
            --skip;
            continue;
        }
        if ((size_t)nf >= cap) {
            cap = cap ? 2 * cap : 256;
            F2 = (double *)realloc(F2, cap * sizeof *F2);
            LP = (double *)realloc(LP, cap * sizeof *LP);
            G = (double *)realloc(G, cap * nbin * sizeof *G);
            if (!F2 || !LP || !G) return 1;
        }
        Fv = (double *)calloc(3 * (size_t)fr.n, sizeof *Fv);
        g = G + (size_t)nf * nbin;
        for (b = 0; b < nbin; ++b) g[b] = 0;
        for (i = 0; i < fr.n; ++i)
            for (j = i + 1; j < fr.n; ++j) {
                double d[3], r2 = 0, r;
                for (c = 0; c < 3; ++c) {
                    d[c] = fr.x[3 * i + c] - fr.x[3 * j + c];
                    d[c] -= fr.L * round(d[c] / fr.L);
                    r2 += d[c] * d[c];
                }
                if (r2 >= rmax * rmax && r2 >= rcut * rcut) continue;
                r = sqrt(r2);
                if (r < rmax) g[(int)(r / dr)] += 2.0;
                if (r < rcut) {
                    double dv, l;
                    star_derivs(r, f, &dv, &l);
                    for (c = 0; c < 3; ++c) {
                        Fv[3 * i + c] -= dv * d[c] / r;
                        Fv[3 * j + c] += dv * d[c] / r;
                    }
                    lp += 2.0 * l;
                }
            }
        for (i = 0; i < 3 * fr.n; ++i) f2 += Fv[i] * Fv[i];
        free(Fv);
        for (b = 0; b < nbin; ++b) { /* pairs per particle in the shell over the ideal gas's */
            const double r0 = b * dr, r1 = r0 + dr;
            g[b] /= fr.n * (fr.n - 1) / (fr.L * fr.L * fr.L) * (4.0 / 3.0) * 3.14159265358979323846 * (r1 * r1 * r1 - r0 * r0 * r0);
        }
        F2[nf] = f2;
        LP[nf] = lp;
        ++nf;
    }
    fclose(in);
    if (nf < NBLK) {
        fprintf(stderr, "wp_estimate: %s: %d frames, need %d\n", path, nf, NBLK);
        return 1;
    }
    {
        double tb[NBLK], sF = 0, sL = 0, tm, te = 0, gm[MAXBIN], ge[MAXBIN], gerr = 0, gfl = 0;
        int per = nf / NBLK, used = per * NBLK, nb = 0;
        for (b = 0; b < NBLK; ++b) {
            double a = 0, c = 0;
            for (k = b * per; k < (b + 1) * per; ++k) { a += F2[k]; c += LP[k]; }
            tb[b] = a / c;
            sF += a;
            sL += c;
        }
        tm = sF / sL;
        for (b = 0; b < NBLK; ++b) te += (tb[b] - tm) * (tb[b] - tm);
        te = sqrt(te / (NBLK - 1) / NBLK);
        for (k = 0; k < nbin; ++k) {
            double bl[NBLK], m = 0, v = 0;
            for (b = 0; b < NBLK; ++b) {
                int q;
                bl[b] = 0;
                for (q = b * per; q < (b + 1) * per; ++q) bl[b] += G[(size_t)q * nbin + k];
                bl[b] /= per;
                m += bl[b];
            }
            m /= NBLK;
            for (b = 0; b < NBLK; ++b) v += (bl[b] - m) * (bl[b] - m);
            gm[k] = m;
            ge[k] = sqrt(v / (NBLK - 1) / NBLK);
        }
        if (gout) {
            FILE *o = fopen(gout, "w");
            if (!o) {
                fprintf(stderr, "wp_estimate: cannot write %s\n", gout);
                return 1;
            }
            for (k = 0; k < nbin; ++k) fprintf(o, "%.4f %.6f %.6f\n", (k + 0.5) * dr, gm[k], ge[k]);
            fclose(o);
        }
        {
            double a = 0, c = 0;
            for (k = 0; k < nf; ++k) { a += F2[k]; c += LP[k]; }
            printf("frames=%d T_conf=%.6f T_conf_err=%.6f T_conf_all=%.9f", used, tm, te, a / c);
        }
        if (ref) {
            FILE *r = fopen(ref, "r");
            double rr, rg, re;
            if (!r) {
                fprintf(stderr, "wp_estimate: cannot read %s\n", ref);
                return 1;
            }
            for (k = 0; k < nbin && fscanf(r, "%lf %lf %lf", &rr, &rg, &re) == 3; ++k)
                if (rr >= rlo) {
                    gerr += (gm[k] - rg) * (gm[k] - rg);
                    gfl += ge[k] * ge[k] + re * re;
                    ++nb;
                }
            fclose(r);
            if (nb) printf(" g_err=%.6f g_floor=%.6f", sqrt(gerr / nb), sqrt(gfl / nb));
        }
        printf("\n");
    }
    free(F2); free(LP); free(G); free(fr.x);
    return 0;
}
