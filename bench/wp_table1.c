/* wp_table1: which time step the 2018 polymer solution needs at Table I
   (issue 28, item 1).  Table I as printed (tau_lambda = 1 s, alpha = 500
   kT, P0 = 0.13 Pa, eta = 1 mPa s, box 10^3 sigma^3, no fluid
   fluctuations, the exact fluid pair sweep), C = 5 C* by default, sheared
   by Lees-Edwards at Weissenberg numbers gdot tau_lambda; for each time
   step dt and fluid sub-steps (the fluid steps dt/substeps):
     eta          total viscosity S_yx / gdot, and its fluid and polymer parts
     d_eta        eta minus the reference configuration's (the first one),
                  block by block over the same stretches of time: every
                  run starts from the same positions and lambdas and draws
                  its polymer noise from the same seed, so the difference
                  has far less noise than either viscosity (the polymers
                  move ~0.1 sigma by diffusion per tau_lambda)
     pairs        transient pairs per polymer
     msd_z        polymer mean-squared displacement along z (vorticity,
                  no flow) over one tau_lambda
     T_fluid      fluid temperature (peculiar kinetic energy per blob over
                  kT: with fluctuations off, the numerical heating)
   and the wall time per tau_lambda of simulated time.

   Each run: startup tau_lambda of start-up (default 1), then blocks of
   half a tau_lambda (default 2).  The default list of (dt us, substeps):
   50/5 (the reference: the fluid at 10 us, below dt_visc = 12.5 us), then
   the fluid unresolved (50/1, 100/1, 200/1), the fluid at 25 us (100/4,
   200/8, 400/16) and at 10 us and 12.5 us with a long polymer step
   (400/40, 400/32).  About 35 minutes on two threads.

   pair=euler and coupling=raw take preset=paper's own schemes (the
   explicit Euler fluid pairs, the weights w/n_i) instead of the library's
   (the exact sweep, Shepard weights).

   usage: wp_table1 [C=5] [L=10] [Wi=0.3,1,3] [cfg=50/5,50/1,...] [startup=1]
                    [blocks=2] [threads=2] [seed=1] [pair=shardlow|euler]
                    [coupling=shepard|raw] [out=bench/results]
   Writes OUT/wp_table1.csv (OUT/wp_table1_euler_raw.csv and the like for
   other schemes). */
#include "bench_common.h"

#define PI 3.14159265358979323846
#define MAXCFG 16
#define MAXWI 8
#define MAXBLK 64

typedef struct {
    double dt_us;
    int sub;
} cfg;

typedef struct {
    double eta[MAXBLK], fluid[MAXBLK], poly[MAXBLK], pairs[MAXBLK], msd[MAXBLK], T[MAXBLK];
    double wall;
    int ok;
} result;

static void mean_err(const double *x, int n, double *m, double *e)
{
    double s = 0, s2 = 0;
    int k;
    for (k = 0; k < n; ++k) s += x[k], s2 += x[k] * x[k];
    *m = s / n;
    *e = n > 1 ? sqrt(fmax(s2 / n - *m * *m, 0) / (n - 1)) : NAN;
}

static int parse_list(const char *v, double *x, int max)
{
    int n = 0;
    char *end;
    while (*v && n < max) {
        x[n++] = strtod(v, &end);
        if (end == v) return 0;
        v = *end == ',' ? end + 1 : end;
    }
    return n;
}

/* One Lees-Edwards run of config c at Weissenberg number wi; block values
   per block of half a tau_lambda. */
static int run(const hcbd_hc_params *base, int np, cfg c, double wi, int startup, int nblk, result *r)
{
    hcbd_hc_world_def def = hcbd_hc_world_def_default();
    hcbd_hc_world w;
    const double tl = base->tau_lambda; /* in time units of 1 us */
    double *z0 = NULL;
    int b, a, per, nf;
    memset(r, 0, sizeof *r);
    def.params = *base;
    def.params.dt = c.dt_us;
    def.params.substeps = c.sub;
    def.params.gdot = wi / tl;
    nf = (int)floor(def.params.nbar * def.params.L[0] * def.params.L[1] * def.params.L[2] + 0.5);
    def.fluid_capacity = nf;
    def.polymer_capacity = np;
    def.pair_capacity = HCBD_AUTO;
    per = (int)floor(0.5 * tl / c.dt_us + 0.5);
    if (hcbd_hc_world_create(&w, &def) != HCBD_OK) {
        fprintf(stderr, "wp_table1: %s\n", w.err.msg);
        return 0;
    }
    /* the same start for every configuration: lattice, random polymers of
       the same seed, lambdas at equilibrium */
    if (hcbd_hc_world_place_fluid_lattice(&w, nf) != HCBD_OK ||
        hcbd_hc_world_place_polymers_random(&w, np) != HCBD_OK ||
        !(z0 = (double *)malloc(sizeof(double) * (size_t)np)))
        goto fail;
    r->wall = now();
    if (hcbd_hc_world_step(&w, startup * 2 * per) != HCBD_OK) goto fail;
    for (b = 0; b < nblk; ++b) {
        double s[HCBD_HC_NSTRESS], m = 0;
        int k, t;
        for (a = 0; a < np; ++a) z0[a] = w.pz[a];
        hcbd_hc_world_stress_enable(&w, 1);
        r->pairs[b] = r->T[b] = 0;
        for (k = 0; k < 10; ++k) { /* ten samples of the pair count and T */
            t = per / 10 + (k < per % 10);
            if (hcbd_hc_world_step(&w, t) != HCBD_OK) goto fail;
            r->pairs[b] += (double)w.npairs / np / 10;
            r->T[b] += hcbd_hc_world_temperature(&w) / w.p.kT / 10;
        }
        hcbd_hc_world_stress_read(&w, s, NULL);
        r->eta[b] = s[HCBD_HC_S_TOTAL] / w.p.gdot / w.p.eta;
        r->fluid[b] = s[HCBD_HC_S_FLUID] / w.p.gdot / w.p.eta;
        r->poly[b] = s[HCBD_HC_S_POLYMER] / w.p.gdot / w.p.eta;
        for (a = 0; a < np; ++a) { /* z is periodic; a polymer moves << L/2 in half a tau_lambda */
            double d = w.pz[a] - z0[a];
            d -= w.p.L[2] * floor(d / w.p.L[2] + 0.5);
            m += d * d;
        }
        r->msd[b] = 2 * m / np; /* half a tau_lambda: times 2 for one tau_lambda if diffusive */
    }
    r->wall = (now() - r->wall) / (startup + 0.5 * nblk); /* seconds per tau_lambda */
    r->ok = 1;
    free(z0);
    hcbd_hc_world_destroy(&w);
    return 1;
fail:
    fprintf(stderr, "wp_table1: dt = %g us, substeps %d, Wi = %g: %s\n", c.dt_us, c.sub, wi, w.err.msg);
    free(z0);
    hcbd_hc_world_destroy(&w);
    return 0;
}

/* Means over the blocks of run (i, j): eta, its error, the paired
   difference from configuration 0 and its error, fluid, polymer, pairs,
   msd_z, T_fluid. */
static void stats(result res[][MAXCFG], int i, int j, int nblk, double o[9])
{
    const result *r = &res[i][j];
    double x;
    int k;
    mean_err(r->eta, nblk, &o[0], &o[1]);
    o[2] = j == 0 ? 0 : NAN;
    o[3] = j == 0 ? 0 : NAN;
    if (res[i][0].ok && j > 0) {
        double d[MAXBLK];
        for (k = 0; k < nblk; ++k) d[k] = r->eta[k] - res[i][0].eta[k];
        mean_err(d, nblk, &o[2], &o[3]);
    }
    mean_err(r->fluid, nblk, &o[4], &x);
    mean_err(r->poly, nblk, &o[5], &x);
    mean_err(r->pairs, nblk, &o[6], &x);
    mean_err(r->msd, nblk, &o[7], &x);
    mean_err(r->T, nblk, &o[8], &x);
}

int main(int argc, char **argv)
{
    static result res[MAXWI][MAXCFG];
    cfg cf[MAXCFG] = {{50, 5}, {50, 1}, {100, 1}, {200, 1}, {100, 4}, {200, 8}, {400, 16}, {400, 40}, {400, 32}};
    double wis[MAXWI] = {0.3, 1, 3}, C = 5, L = 10;
    int ncf = 9, nwi = 3, startup = 1, nblk = 2, threads = 2, k, i, j, np;
    unsigned long long seed = 1;
    const char *out = "bench/results";
    char msg[256], path[512], tag[32] = "";
    hcbd_pair_integrator pair = HCBD_PAIR_SHARDLOW;
    hcbd_coupling coupling = HCBD_COUPLE_SHEPARD;
    hcbd_hc_si si = hcbd_hc_si_default();
    hcbd_hc_params p;
    FILE *f;
    for (k = 1; k < argc; ++k) {
        const char *v = strchr(argv[k], '=');
        if (!v) { fprintf(stderr, "wp_table1: '%s' is not key=value\n", argv[k]); return 2; }
        ++v;
        if (!strncmp(argv[k], "C=", 2)) C = atof(v);
        else if (!strncmp(argv[k], "L=", 2)) L = atof(v);
        else if (!strncmp(argv[k], "Wi=", 3)) nwi = parse_list(v, wis, MAXWI);
        else if (!strncmp(argv[k], "cfg=", 4)) {
            const char *s = v;
            ncf = 0;
            while (*s && ncf < MAXCFG) {
                char *e;
                cf[ncf].dt_us = strtod(s, &e);
                if (*e != '/') { fprintf(stderr, "wp_table1: cfg items are dt_us/substeps\n"); return 2; }
                cf[ncf].sub = (int)strtol(e + 1, &e, 10);
                ++ncf;
                s = *e == ',' ? e + 1 : e;
            }
        }
        else if (!strncmp(argv[k], "startup=", 8)) startup = atoi(v);
        else if (!strncmp(argv[k], "blocks=", 7)) nblk = atoi(v);
        else if (!strncmp(argv[k], "threads=", 8)) threads = atoi(v);
        else if (!strncmp(argv[k], "seed=", 5)) seed = strtoull(v, NULL, 10);
        else if (!strncmp(argv[k], "out=", 4)) out = v;
        else if (!strncmp(argv[k], "pair=", 5) && (!strcmp(v, "euler") || !strcmp(v, "shardlow")))
            pair = !strcmp(v, "euler") ? HCBD_PAIR_EULER : HCBD_PAIR_SHARDLOW;
        else if (!strncmp(argv[k], "coupling=", 9) && (!strcmp(v, "raw") || !strcmp(v, "shepard")))
            coupling = !strcmp(v, "raw") ? HCBD_COUPLE_RAW : HCBD_COUPLE_SHEPARD;
        else { fprintf(stderr, "wp_table1: unknown key or value '%s'\n", argv[k]); return 2; }
    }
    if (nwi < 1 || ncf < 1 || startup < 0 || nblk < 2 || nblk > MAXBLK || !(C > 0) || !(L >= 8)) {
        fprintf(stderr, "wp_table1: bad Wi, cfg, startup, blocks (2..%d), C or L (>= 8)\n", MAXBLK);
        return 2;
    }
    if (hcbd_hc_si_params(&si, 1e-6, &p, msg, sizeof msg) != HCBD_OK) {
        fprintf(stderr, "wp_table1: %s\n", msg);
        return 2;
    }
    p.L[0] = p.L[1] = p.L[2] = L;
    p.fluctuations = 0;
    p.pair_integrator = pair;
    p.coupling = coupling;
    if (pair != HCBD_PAIR_SHARDLOW || coupling != HCBD_COUPLE_SHEPARD)
        snprintf(tag, sizeof tag, "_%s_%s", pair == HCBD_PAIR_EULER ? "euler" : "shardlow",
                 coupling == HCBD_COUPLE_RAW ? "raw" : "shepard");
    p.threads = threads;
    p.seed = seed;
    np = (int)floor(C * 3.0 / (4.0 * PI) * L * L * L + 0.5);
    printf("wp_table1: Table I, box %g^3, C = %g C* (%d polymers), tau_lambda = %g us, startup %d tau_lambda, "
           "%d blocks of tau_lambda/2, threads %d, %s fluid pairs, %s weights\n", L, C, np, p.tau_lambda, startup,
           nblk, threads, pair == HCBD_PAIR_EULER ? "Euler" : "exact sweep",
           coupling == HCBD_COUPLE_RAW ? "raw (w/n_i)" : "Shepard");
    printf("%-6s %-5s %-4s %9s %9s %9s %9s %9s %8s %9s %8s %8s %8s\n", "dt_us", "sub", "Wi", "eta/eta_s", "err",
           "d_eta", "d_err", "fluid", "polymer", "pairs", "msd_z", "T_fluid", "s/tau_l");
    fflush(stdout);
    for (i = 0; i < nwi; ++i)
        for (j = 0; j < ncf; ++j) {
            result *r = &res[i][j];
            double o[9];
            if (!run(&p, np, cf[j], wis[i], startup, nblk, r)) continue;
            stats(res, i, j, nblk, o);
            printf("%-6g %-5d %-4g %9.5f %9.2g %9.2g %9.2g %9.5f %8.5f %9.4f %8.3g %8.3g %8.1f\n", cf[j].dt_us,
                   cf[j].sub, wis[i], o[0], o[1], o[2], o[3], o[4], o[5], o[6], o[7], o[8], r->wall);
            fflush(stdout);
        }
    snprintf(path, sizeof path, "%s/wp_table1%s.csv", out, tag);
    if (!(f = fopen(path, "w"))) {
        fprintf(stderr, "wp_table1: cannot write %s\n", path);
        return 1;
    }
    fprintf(f, "# wp_table1 C=%g L=%g startup=%d blocks=%d threads=%d seed=%llu pair=%s coupling=%s; eta in units of "
               "the solvent eta; d_eta: eta minus the first configuration's, paired block by block\n", C, L, startup,
            nblk, threads, seed, pair == HCBD_PAIR_EULER ? "euler" : "shardlow",
            coupling == HCBD_COUPLE_RAW ? "raw" : "shepard");
    fprintf(f, "dt_us,substeps,Wi,eta,eta_err,d_eta,d_eta_err,eta_fluid,eta_polymer,pairs_per_polymer,msd_z,T_fluid,"
               "seconds_per_tau_lambda\n");
    for (i = 0; i < nwi; ++i)
        for (j = 0; j < ncf; ++j) {
            double o[9];
            if (!res[i][j].ok) continue;
            stats(res, i, j, nblk, o);
            fprintf(f, "%g,%d,%g,%.6g,%.3g,%.4g,%.3g,%.6g,%.6g,%.6g,%.4g,%.4g,%.4g\n", cf[j].dt_us, cf[j].sub, wis[i],
                    o[0], o[1], o[2], o[3], o[4], o[5], o[6], o[7], o[8], res[i][j].wall);
        }
    fclose(f);
    printf("wrote %s\n", path);
    return 0;
}
