/* roofline: each pass of the 2018 step against a bare SIMD pass over the
   same list, at Table II's composition (preset=paper: Table I, 10^3
   sigma^3, C2 = 5 c*, 239 fluid blobs and 1194 polymers, the polymers
   stepped by 100 us and the fluid by 12.5 us, Lees-Edwards at Wi = 1).
   The bare pass is the least a pair pass does, in the traversal's lean
   loop: per list entry the partner's position, the minimum image, r^2
   (kept within the cut), one kernel value in 64-bit fixed point, summed
   into the owner and scattered to the partner.  The redistribution reads
   the interpolation's weights and no geometry, so it may beat it.  Each pass's rate is list entries
   (pairs of its half list within range + skin) per second; the ratio to
   the bare pass over the same list says how near it runs to that limit.
   The polymer force pass also draws the pair variables' next values, so
   its row holds their update.
   This program includes the implementation (HCBD_IMPLEMENTATION) to call
   the passes one at a time; 1 thread, the minimum over repeats.

   usage: roofline [C=5] [reps=20] [steps=0] [out=out/bench]   writes OUT/roofline.csv
   steps=N first times N whole steps of the same world and counts its
   list builds (how the passes add up to a step). */
#define HCBD_IMPLEMENTATION
#include "bench_common.h"

#define PI 3.14159265358979323846

/* the bare pass: the traversal's lean loop (its gather, the same minimum
   image) with the least evaluator, one kernel value (1 - r^2/cut^2)^2 per
   pair in fixed point, summed into the owner and scattered to the
   partner */
typedef struct {
    int64_t *acc;
    double ic2;
} bare_pass;

typedef struct {
    int64_t w;
} bare_own;

HCBD__INLINE void bare_begin(const bare_pass *b, int i, bare_own *a)
{
    (void)b; (void)i;
    a->w = 0;
}

HCBD__INLINE void bare_pairs(bare_pass *b, int i, const hcbd__near *c, int m, bare_own *a)
{
    int64_t v[HCBD__CHUNK], *HCBD__RESTRICT acc = b->acc;
    int t;
    (void)i;
    HCBD__OMP(omp simd)
    for (t = 0; t < m; ++t) {
        const double s = 1.0 - c->r2[t] * b->ic2;
        v[t] = hcbd__fix(1e12 * s * s);
    }
    for (t = 0; t < m; ++t) {
        a->w += v[t];
        acc[c->j[t]] += v[t];
    }
}

HCBD__INLINE int bare_end(bare_pass *b, int i, bare_own *a)
{
    b->acc[i] += a->w;
    return INT_MAX;
}

HCBD__PASS(bare)

/* over list L of owners at x, y, z, taken in the order owners[0 .. n),
   and partners at X, Y, Z within cut.  The order is the pass's own: the
   polymer-fluid list is never sorted (its perm is all zeros), and its
   passes take the polymer list's cell order. */
static int64_t bare(const hcbd_hc_world *w, const hcbd__nlist *L, const int32_t *owners, int n,
                    const hcbd_real *x, const hcbd_real *y, const hcbd_real *z, const hcbd_real *X,
                    const hcbd_real *Y, const hcbd_real *Z, double cut, int64_t *acc)
{
    const hcbd__trav T = hcbd__trav_make(L, x, y, z, X, Y, Z, hcbd__hc_box(w), cut);
    bare_pass b;
    int64_t tot = 0;
    int i;
    b.acc = acc;
    b.ic2 = 1.0 / (cut * cut);
    memset(acc, 0, sizeof(int64_t) * (size_t)(w->nf + w->np + 1));
    bare_traverse(&T, owners, 0, n, &b);
    for (i = 0; i < n; ++i) tot += acc[i];
    return tot;
}

typedef struct {
    const char *name;
    double t, entries;
} row;

static volatile int64_t sink;

int main(int argc, char **argv)
{
    hcbd_hc_si si = hcbd_hc_si_default();
    hcbd_hc_world_def d = hcbd_hc_world_def_default();
    hcbd_hc_params *p = &d.params;
    hcbd_hc_world w;
    double C = 5, best[16], t0;
    int reps = 20, steps = 0, k, r, np, nf, need, nrow = 0;
    const char *out = "out/bench";
    char msg[256], path[600];
    int64_t *acc;
    row rows[16];
    FILE *csv;
    for (k = 1; k < argc; ++k) {
        if (!strncmp(argv[k], "C=", 2)) C = atof(argv[k] + 2);
        else if (!strncmp(argv[k], "reps=", 5)) reps = atoi(argv[k] + 5);
        else if (!strncmp(argv[k], "steps=", 6)) steps = atoi(argv[k] + 6);
        else if (!strncmp(argv[k], "out=", 4)) out = argv[k] + 4;
        else {
            fprintf(stderr, "roofline: unknown argument '%s' (C=, reps=, steps=, out=)\n", argv[k]);
            return 2;
        }
    }
    if (!(C > 0) || reps < 1 || steps < 0) {
        fprintf(stderr, "roofline: C > 0, reps >= 1 and steps >= 0\n");
        return 2;
    }
    si.dt = 1e-4;
    if (hcbd_hc_si_params(&si, 1e-6, p, msg, sizeof msg) != HCBD_OK) {
        fprintf(stderr, "roofline: %s\n", msg);
        return 1;
    }
    p->L[0] = p->L[1] = p->L[2] = 10.0;
    p->substeps = 8;
    p->fluctuations = 0;
    p->coupling = HCBD_COUPLE_RAW;
    p->pair_integrator = HCBD_PAIR_EULER;
    p->gdot = 1.0 / p->tau_lambda;
    p->threads = 1;
    nf = (int)floor(p->nbar * 1000.0 + 0.5);
    np = (int)floor(C * 3.0 / (4.0 * PI) * 1000.0 + 0.5);
    d.fluid_capacity = nf;
    d.polymer_capacity = np;
    if (hcbd_hc_world_create(&w, &d) != HCBD_OK || hcbd_hc_world_place_fluid_lattice(&w, nf) != HCBD_OK ||
        hcbd_hc_world_place_polymers_random(&w, np) != HCBD_OK || hcbd_hc_world_step(&w, 200) != HCBD_OK) {
        fprintf(stderr, "roofline: %s\n", w.err.msg);
        return 1;
    }
    if (steps > 0) {
        const int64_t b0 = w.lp.n_rebuilds;
        t0 = now();
        if (hcbd_hc_world_step(&w, steps) != HCBD_OK) {
            fprintf(stderr, "roofline: %s\n", w.err.msg);
            return 1;
        }
        t0 = now() - t0;
        printf("roofline: %d whole steps: %.3f ms per step, lists built %lld times (every %.0f steps)\n", steps,
               t0 / steps * 1e3, (long long)(w.lp.n_rebuilds - b0),
               (double)steps / (double)(w.lp.n_rebuilds - b0 > 0 ? w.lp.n_rebuilds - b0 : 1));
    }
    acc = (int64_t *)malloc(sizeof(int64_t) * (size_t)(nf + np + 1));
    for (k = 0; k < 16; ++k) best[k] = 1e30;
#define TIME(K, NAME, ENTRIES, CODE)                                                                 \
    do {                                                                                             \
        t0 = now();                                                                                  \
        CODE;                                                                                        \
        t0 = now() - t0;                                                                             \
        if (t0 < best[K]) best[K] = t0;                                                              \
        rows[K].name = NAME;                                                                         \
        rows[K].entries = (double)(ENTRIES);                                                         \
        if (K >= nrow) nrow = K + 1;                                                                 \
    } while (0)
    for (r = 0; r < reps; ++r) {
        const double dtf = p->dt / p->substeps;
        TIME(0, "polymer densities", w.lp.npairs, hcbd__hc_poly_density(&w));
        TIME(1, "polymer densities + forces", w.lp.npairs, hcbd__hc_poly_density(&w);
             hcbd__hc_poly_forces(&w, &need));
        TIME(2, "interpolation v(r_a)", w.lx.npairs, hcbd__hc_interp(&w));
        TIME(3, "redistribution of F_a", w.lx.npairs, hcbd__hc_redistribute(&w));
        TIME(4, "fluid densities", w.lf.npairs, hcbd__hc_fluid_density(&w));
        w.p.pair_integrator = HCBD_PAIR_EULER;
        TIME(5, "fluid Euler pairs", w.lf.npairs, hcbd__hc_fluid_kick(&w, dtf, 1));
        w.p.pair_integrator = HCBD_PAIR_SHARDLOW;
        TIME(6, "fluid exact sweep with pressure", w.lf.npairs, hcbd__hc_fluid_kick(&w, dtf, 1));
        w.p.pair_integrator = HCBD_PAIR_EULER;
        TIME(7, "lists (all three)", w.lf.npairs + w.lp.npairs + w.lx.npairs, hcbd__hc_lists_stale(&w);
             hcbd__hc_lists(&w, w.step));
        TIME(8, "bare: fluid list (2h)", w.lf.npairs,
             sink = bare(&w, &w.lf, w.lf.perm, nf, w.sx, w.sy, w.sz, w.sx, w.sy, w.sz, 2.0 * p->h, acc));
        TIME(9, "bare: polymer list (rc)", w.lp.npairs,
             sink = bare(&w, &w.lp, w.lp.perm, np, w.px, w.py, w.pz, w.px, w.py, w.pz, p->rc, acc));
        TIME(10, "bare: polymer-fluid list (rc)", w.lx.npairs,
             sink = bare(&w, &w.lx, w.lp.perm, np, w.px, w.py, w.pz, w.sx, w.sy, w.sz, p->rc, acc));
    }
#undef TIME
    /* the forces alone: the two together less the densities */
    best[1] -= best[0];
    rows[1].name = "polymer forces + lambda after densities";
    csv = bench_csv("roofline", out, "roofline.csv", path, sizeof path);
    if (!csv) return 1;
    fprintf(csv, "# roofline C=%g reps=%d: %d fluid blobs, %d polymers, 1 thread\n", C, reps, nf, np);
    fprintf(csv, "pass,list_entries,seconds,entries_per_second,bare_entries_per_second,ratio_to_bare\n");
    printf("roofline: Table II's composition, C = %g c* (%d fluid blobs, %d polymers), 1 thread, min of %d\n", C, nf,
           np, reps);
    printf("%-40s %10s %10s %12s %12s %7s\n", "pass", "entries", "us", "entries/s", "bare/s", "ratio");
    for (k = 0; k < nrow; ++k) {
        const int b = k == 4 || k == 5 || k == 6 ? 8 : k <= 1 ? 9 : k == 2 || k == 3 ? 10 : -1;
        const double rate = rows[k].entries / best[k], brate = b >= 0 ? rows[b].entries / best[b] : NAN;
        printf("%-40s %10.0f %10.1f %12.3g %12.3g %7.3f\n", rows[k].name, rows[k].entries, best[k] * 1e6, rate,
               brate, rate / brate);
        fprintf(csv, "%s,%.0f,%.4g,%.4g,%.4g,%.4f\n", rows[k].name, rows[k].entries, best[k], rate, brate,
                rate / brate);
    }
    fclose(csv);
    printf("wrote %s\n", path);
    free(acc);
    hcbd_hc_world_destroy(&w);
    return 0;
}
