/* hcbd_polymer: polymer solutions in HCBD (Ahuja et al. 2018, sec. IV B,
   Figs. 4-6): RaPiD polymer blobs coupled two-way to the SPH fluid of
   Table I, at C1 = 2.5 C* and C2 = 5 C* (C* = 3 / (4 pi sigma^3), one
   polymer blob per sphere of radius sigma; C* = nbar in Table I).

   Units: Table I is given in SI; the run works in reduced units (length
   sigma, energy kT, time time_unit, default 1 us so dt = 1) and prints
   both, with every value that differs from Table I marked.  As in the
   paper the fluid carries no thermal fluctuations once polymers are
   present; the polymers and their pair variables keep kT = 1.  The fluid
   blobs start on a lattice (nbar V of them), the polymers at random.

   For each concentration:
     Fig. 4  Lees-Edwards flow curve, eta = S_yx / gdot split into the fluid
             (kinetic, pressure, viscous), polymer (Flory-Huggins +
             transient pairs) and interaction (coupling) parts, with block
             errors; Carreau fit of the total with eta_inf fixed at
             0.9 mPa s as in 2018 Table II (key eta_inf; eq. 36)                         flowcurve.csv
     Fig. 5  reverse Poiseuille (+g above L/2, -g below): slab profiles of
             the fluid velocity v_x and the polymer drift velocity u_x =
             v(r_a) + F_a/xi (whose mean is the polymers' mean velocity)
             against the Newtonian profile with the zero-shear viscosity,
             (g / 2 nu0) y' (L/2 - y') per half (MODEL.md 10), and against
             the Carreau fluid of the fit (the paper's COMSOL curve).  g is
             chosen so that the stress at the edges of the halves equals the
             one measured at the fastest shear rate: the profile then spans
             the measured flow curve                         profile_C<C>.csv
     Fig. 6  the same run: densities of both species across y over their
             mean, from the per-particle kernel densities (n_i with M4, n_a
             with W-RaPiD, as the paper normalises them) and from counts;
             the shear rate is largest at y = 0 and L/2, zero at L/4, 3L/4
   and one short equilibrium run (no shear, no body force) at the highest
   concentration measures the drift of the total momentum.

   Without fluctuations the fluid blobs flow in laminar sheets and keep the
   rows of their start lattice (~1.6 sigma apart): a slab between rows
   holds a few strays, so the fluid's velocity profile is read only from
   slabs with at least half the mean count (fluid_slabs_populated; the
   centre velocity is the fastest of them in each half), and the depletion
   compares the high-shear half of the box (within Ly/8 of y = 0,
   L/2) with the low-shear half.  A lattice row lying on a plane where g
   flips would tear into two sheets sliding past each other, so the
   reverse-Poiseuille box is stretched along y by whole rows until no row
   lies on y = 0 or L/2 (8 sigma: 5 rows, one on L/2; 9.6 sigma: 6 rows).

   The quick preset cannot use the paper's tau_lambda = 1 s (10^6 steps:
   a flow curve would take days).  It shortens tau_lambda to 200 us and
   scales alpha by the same factor as tau_lambda shrinks (the polymer
   viscosity goes as alpha tau_lambda, and the polymer slip F/(xi gdot L)
   at a given Weissenberg number gdot tau_lambda is unchanged); it raises
   P0 (c_s = 2 m/s, dt = 0.8 dt_sound) so that the shear rates that reach
   gdot tau_lambda = 2 stay at Mach gdot Ly / c_s <= 0.2; and it uses an
   8^3 sigma box.  Each run lasts 3 tau_lambda, of which the last one is
   measured: the stress settles only roughly (startup_rise_lowest_rate:
   how much the stress still rose over the measured window at the lowest
   rate; rp_center_change: the same for the reverse-Poiseuille centre
   velocity), and the block errors, from blocks shorter than tau_lambda,
   are too small.  preset=paper keeps Table I (tau_lambda = 1 s, alpha =
   500 kT, P0 = 0.13 Pa) in a 10^3 box (an assumption: the paper states no
   box for its polymer runs) but not its step: 1 us would make 10^6 steps
   per tau_lambda, a week of runs.  bench/wp_table1.c measured
   the viscosity against the step at Table I: the fluid needs its viscous
   step, dt_visc = 0.125 h^2/nu = 12.5 us (at 25 us its part of eta reads
   1-2.5 % low, at 100 us 10 %), the polymers and the coupling much less
   (a 400 us polymer step reads 1.7 % high at Wi = 0.3 against a 50 us
   one, 200 us 1.4 %, 100 us 0.8 +- 0.4 %; at Wi = 3 even 400 us stays
   within 0.3 %), so the preset steps the polymers by 100 us and the fluid
   in 8 sub-steps.  It takes the paper's own schemes, the weights w/n_i
   (coupling=raw) and explicit Euler fluid pairs (pair=euler): without
   fluid fluctuations the Euler pairs are converged at 12.5 us, where the
   exact sweep reads eta 2.5 % low (C2, Wi = 1); the library's defaults
   stay the Shepard weights (momentum exact) and the sweep (unbiased with
   fluctuations).  Each Lees-Edwards run measures its start-up
   (plateau=1): at least 4 times the slowest stress relaxation time (3
   tau_lambda, over 1 + 3 Wi), a strain of 3 (the stress levels off at a
   strain of 2.4-3, whatever the rate: bench/results/paper_long, so 30
   tau_lambda at Wi = 0.1) and 6 correlation times of the stress (by
   blocking), then on until the stress growth fitted to it would shift the
   measured mean by less than 0.5 %; then it measures 4 blocks of one
   tau_lambda (preset=paper-long: until a strain of 2 as well).  The error
   of the total is the largest of that block error, the one from blocks
   twice as long and the blocking (Flyvbjerg-Petersen) error of the
   window's half-block series, which also gives n_eff, the independent
   samples the window is worth.  The runs are independent, so with
   threads=2 two of them run side by side on one thread each (jobs=).

   What to look for: shear thinning (eta falls once gdot tau_lambda ~ 1),
   carried by the transient part of the polymer stress, stronger at C2;
   the fluid part stays near eta (above it once the blobs disorder), the
   interaction part is small.  In reverse Poiseuille the polymers follow
   the fluid velocity interpolated at their positions closely (slip_max);
   lag_max, against the blob velocities of the same slab, is larger: the
   polymer profile is the kernel average over rc = 2.5 sigma of a fluid
   resolved by ~3 rows per half, and it rounds off the turn of the profile
   at the high-shear planes.  The profile is blunter than the parabola
   (profile_fill above its Newtonian value) and, at the same force, faster
   than the Newtonian eta0 profile (flattening > 1).  In the quick runs it
   is faster even than the Carreau fluid of the flow curve
   (flattening_carreau > 1): the velocity changes mostly between the rows
   of blobs on either side of the high-shear planes, which the polymers
   leave (polymer_depletion > 0, against the random start,
   polymer_depletion_initial), so the flow is not the homogeneous shear of
   the flow curve.  The fluid stays uniform.

   Writes flowcurve.csv, profile_C<C>.csv, rp_start_C<C>.csv (centre
   velocity against time) and plots.gp (flowcurve.png, velocity.png,
   density.png, rp_start.png with gnuplot); a "# summary" block per
   concentration and a final one on stdout. */
#include "example_common.h"

#include <limits.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#define PI 3.14159265358979323846
#define KB 1.380649e-23
#define MAXC 4    /* concentrations */
#define MAXG 16   /* shear rates */
#define MAXB 64   /* blocks */
#define MAXS 202  /* slabs */
#define NCOMP 4   /* total, fluid, polymer, interaction */
#define NTS 300   /* rows of the start-up series */
#define NSER 256  /* half blocks of a Lees-Edwards run: start-up <= 128, blocks 2 x MAXB */
/* preset=paper's step: the largest polymer step and fluid sub-steps whose
   viscosity at Table I stays within 1 % of a resolved reference
   (bench/wp_table1.c, docs/VALIDATION.md "Table II") */
#define PAPER_DT 1e-4 /* s */
#define PAPER_SUBSTEPS 8 /* the fluid at 12.5 us = 0.125 h^2 / nu */

static const char *comp_name[NCOMP] = {"total", "fluid", "polymer", "interaction"};
static const int comp_index[NCOMP] = {HCBD_HC_S_TOTAL, HCBD_HC_S_FLUID, HCBD_HC_S_POLYMER,
                                      HCBD_HC_S_INTERACTION};

static struct {
    double time_unit;         /* seconds per reduced time unit            */
    double conc[MAXC];        /* polymer concentrations in C*            */
    int nconc;
    double gdot_si[MAXG];     /* shear rates, 1/s                         */
    int ngdot;
    double tau_si, alpha, P0_si, g_si, L[3];  /* alpha in kT; g_si 0: automatic */
    int alpha_given;
    int le_steps, rp_steps, eq_steps, nblk, nslab;
    int substeps;             /* fluid steps per polymer step              */
    int coupling;             /* hcbd_coupling: Shepard (default) or raw    */
    int pair_euler;           /* the fluid's pair step: 0 the exact sweep, 1 Euler */
    int fluid_random;         /* the fluid's start: 0 a lattice, 1 disordered */
    /* plateau=1: a Lees-Edwards run is start-up chunks of block_tau
       tau_lambda until the stress levels off (startup_bias; at most
       startup_max), then
       nblk blocks of block_tau; plateau=0: le_steps, the first 2/3 start-up */
    int plateau, startup_max;
    double block_tau, startup_tol;
    double startup_min;       /* the least start-up, tau_lambda (0: the rule's) */
    double startup_strain;    /* the least strain of a start-up             */
    double startup_corr;      /* the least start-up in stress correlation times */
    double measure_strain;    /* the least strain of the measured window    */
    double startup_lambda;    /* the stress's slowest relaxation time assumed
                                 for the least start-up, tau_lambda          */
    int jobs;                 /* runs at a time, each on threads/jobs threads */
    double eta_inf_mpas;      /* Carreau eta_inf, mPa s (Table II: 0.9)    */
    double eta_inf;           /* the same in reduced units                */
} opt;

/* Progress over all runs, reported at most every few seconds; runs at a
   time (jobs=) share it in one critical section, and a failed run stops
   the others. */
static struct {
    config *c;
    int64_t done, total;
    struct timespec t0, last;
    int failed;
} prog;
#ifdef _OPENMP
#define PROGRESS_LOCK _Pragma("omp critical(hcbd_polymer_progress)")
#else
#define PROGRESS_LOCK
#endif

/* Slab profile rows (hcbd_slabs_result): y, count density, its error,
   then mean and error of each value. */
enum { SF_V = 3, SF_N = 5, SF = 7,              /* fluid: v_x, n_i           */
       SP_U = 3, SP_N = 5, SP_SLIP = 7, SP = 9, /* polymer: u_x, n_a, F_x/xi */
       S0_N = 3, S0 = 5 };                      /* polymer at t = 0: n_a     */

/* Depletion measures: 1 - (high-shear half) / (low-shear half). */
enum { D_PCOUNT, D_PKERNEL, D_FKERNEL, ND };
static const char *dep_name[ND] = {"polymer_depletion", "polymer_depletion_kernel",
                                   "fluid_depletion_kernel"};

typedef struct {
    double C;                  /* in C* */
    int np, np_rp;             /* polymers in the Lees-Edwards, reverse-Poiseuille box */
    double eta[NCOMP][MAXG], err[NCOMP][MAXG], rise[MAXG];
    double startup[MAXG];      /* start-up taken, tau_lambda; negative: no plateau found */
    double relax[MAXG];        /* relaxation time of the stress growth, tau_lambda */
    double bias[MAXG];         /* the growth's estimated share of the measured mean */
    double series[MAXG][NSER]; /* total viscosity of each half block, start-up and blocks */
    int nser[MAXG], nser_up[MAXG]; /* its length and how much of it is start-up */
    double err_ratio[MAXG];    /* total's error from blocks twice as long over the one used */
    double neff[MAXG];         /* independent samples the measured window is worth (blocking) */
    int fp_plateau[MAXG];      /* the blocking reached its plateau (else err is a lower bound) */
    int fitted;
    double pc[3], pe[3], chi2; /* Carreau eta0, lambda, n */
    double eta0;               /* zero-shear viscosity of the Newtonian profile */
    double g;                  /* reverse-Poiseuille body force per unit mass */
    double prof_f[SF * MAXS], prof_p[SP * MAXS], prof_p0[S0 * MAXS];
    double nf_kernel, np_kernel, np0_kernel; /* mean kernel densities */
    double dep[ND][2], dep0[ND]; /* depletion with error; at t = 0 */
    double ts[NTS][3];         /* t, centre velocity of fluid, of polymers */
    int nts, ts_from;          /* rows, first row of the measured window */
} conc_run;

static hcbd_hc_si si; /* the physical parameters, SI (Table I by default) */

static void usage(FILE *f)
{
    fprintf(f,
            "usage: hcbd_polymer [key=value ...]\n"
            "  preset=quick|paper|paper-long  quick (default, about a minute on one core): tau_lambda=2e-4\n"
            "                      (alpha scaled to keep alpha tau_lambda), P0=571.4 (c_s = 2 m/s),\n"
            "                      box 8^3, gdot=1000,2154,4642,10000, le_steps=rp_steps=600,\n"
            "                      eq_steps=100, blocks=5;\n"
            "                      paper: Table I as printed (tau_lambda = 1 s, alpha = 500 kT,\n"
            "                      P0 = 0.13 Pa) with the paper's schemes (coupling=raw,\n"
            "                      pair=euler), box 10^3 (assumed), gdot=0.1,...,30, dt=1e-4 with\n"
            "                      substeps=8 (bench/wp_table1.c), plateau=1, blocks=4,\n"
            "                      rp_steps=50000 (5 tau_lambda), eq_steps=1000, start-ups of at\n"
            "                      least a strain of 3 (startup_strain) and 6 correlation times\n"
            "                      (startup_corr), then 4 blocks: 60 min with threads=2\n"
            "                      (the slow rates' errors are lower bounds: their windows are\n"
            "                      shorter than the stress stays correlated);\n"
            "                      paper-long: the same with windows of at least a strain of 2\n"
            "                      (measure_strain=2: 20 tau_lambda at Wi = 0.1), about\n"
            "                      1.3 times paper's time\n"
            "  C=2.5,5             polymer concentrations in C* = 3/(4 pi sigma^3)\n"
            "  gdot=a,b,...        Lees-Edwards shear rates in 1/s\n"
            "  tau_lambda=s        relaxation time of the transient pairs, seconds\n"
            "  alpha=a             transient strength in kT (default 500 x (1 s / tau_lambda))\n"
            "  P0=Pa               Tait pressure coefficient (c_s = sqrt(7 P0 / rho))\n"
            "  eta_inf=0.9         Carreau eta_inf in mPa s, held fixed in the fit (Table II)\n"
            "  g=m/s^2             reverse-Poiseuille body force (default: rho g Ly / 4, the\n"
            "                      stress at the edges of the halves, is the one measured at\n"
            "                      the largest gdot)\n"
            "  Lx Ly Lz            box edges in sigma (at least 8)\n"
            "  le_steps=N          per Lees-Edwards run (the first 2/3 are start-up)\n"
            "  rp_steps=N          reverse-Poiseuille run (the first 2/3 are start-up)\n"
            "  eq_steps=N          equilibrium run for the momentum drift\n"
            "  blocks=N slabs=N    blocks for the errors (2..64); slabs across y (4k+2, <= 202)\n"
            "  substeps=k          fluid steps of dt/k per polymer step (1..1000)\n");
    fprintf(f,
            "  pair=shardlow|euler the fluid's pair step: the exact sweep (default; preset=paper:\n"
            "                      euler) or the paper's explicit Euler pairs (stable to about\n"
            "                      2.8 dt_visc; biased only with fluid fluctuations, off here)\n"
            "  fluid_start=lattice|random  the fluid blobs' start: hcbd_hc_world_place_fluid_lattice\n"
            "                      (default) or disordered (random, no two within half the\n"
            "                      lattice spacing), both at rest\n"
            "  coupling=shepard|raw  polymer-fluid weights: psi_ai normalised per polymer\n"
            "                      (default; momentum exact) or the paper's w(r_ai)/n_i\n"
            "                      (preset=paper's default)\n"
            "  plateau=0|1         1: each Lees-Edwards run starts up in chunks of block_tau until\n"
            "                      the stress growth fitted to them would carry less than\n"
            "                      startup_tol of the measured mean (3..startup_max blocks), then\n"
            "                      measures blocks of block_tau tau_lambda; 0: le_steps, 2/3 start-up\n"
            "  block_tau=1 startup_max=8 (paper 64) startup_tol=0.005  (with plateau=1)\n"
            "  startup_min=t       at least t tau_lambda of start-up (with plateau=1; up to startup_max)\n"
            "  startup_strain=s    at least the strain s in the start-up (with plateau=1)\n"
            "  startup_corr=k      at least k correlation times of the stress (blocking of the\n"
            "                      start-up's second half; 0: off) in the start-up\n"
            "  startup_lambda=3    the slowest stress relaxation time assumed, in tau_lambda: every\n"
            "                      start-up lasts at least 4 of it over 1 + gdot startup_lambda\n"
            "                      tau_lambda (2018 Table II: lambda = 2.1-3.1 s)\n"
            "  jobs=k              runs at a time, each on threads/k threads (default: threads;\n"
            "                      1 with thermo_every); the same bits for any jobs and threads\n"
            "  time_unit=1e-6      reduced time unit in seconds (dt of Table I = 1)\n"
            "  rho eta nbar T dt sigma h xi chi rc p n_max   Table I parameters in SI (h, rc\n"
            "                      in sigma; p Kuhn segments per blob; n_max in C*)\n"
            "  steps=N             le_steps = rp_steps = N\n"
            "  xyz=FILE xyz_every=k thermo_every=k checkpoint=FILE  run output, one file per\n"
            "                      run (FILE.<run>.ext)\n"
            "  restart=FILE        the runs whose counts match this checkpoint's start from its\n"
            "                      fluid and polymers; the others start fresh\n"
            "  seed threads out    (out default out/hcbd_polymer)\n");
}

static int int_range(const config *c, const char *key, const char *v, int *x, int lo, int hi)
{
    if (!parse_int(c, key, v, x)) return 0;
    if (*x < lo || *x > hi) {
        fprintf(stderr, "%s: %s=%s must be %d..%d\n", c->name, key, v, lo, hi);
        return 0;
    }
    return 1;
}

static int positive(const config *c, const char *key, const char *v, double *x)
{
    if (!parse_double(c, key, v, x)) return 0;
    if (*x > 0) return 1;
    fprintf(stderr, "%s: %s=%s must be positive\n", c->name, key, v);
    return 0;
}

/* The physical keys of parse_args belong to GI-BD: refuse them here, so
   that only seed, threads and out reach it. */
static int own_key(config *c, const char *key, const char *v)
{
    if (!strcmp(key, "preset")) return !strcmp(v, "paper-long") || check_preset(c, v);
    if (!strcmp(key, "time_unit")) return positive(c, key, v, &opt.time_unit);
    if (!strcmp(key, "C")) return (opt.nconc = parse_list(c, key, v, opt.conc, MAXC)) > 0;
    if (!strcmp(key, "gdot")) return (opt.ngdot = parse_list(c, key, v, opt.gdot_si, MAXG)) > 0;
    if (!strcmp(key, "tau_lambda")) return positive(c, key, v, &opt.tau_si);
    if (!strcmp(key, "alpha")) return (opt.alpha_given = positive(c, key, v, &opt.alpha));
    if (!strcmp(key, "P0")) return positive(c, key, v, &opt.P0_si);
    if (!strcmp(key, "eta_inf")) return positive(c, key, v, &opt.eta_inf_mpas);
    if (!strcmp(key, "g")) return positive(c, key, v, &opt.g_si);
    if (!strcmp(key, "Lx") || !strcmp(key, "Ly") || !strcmp(key, "Lz")) {
        double *x = &opt.L[key[1] - 'x'];
        if (!parse_double(c, key, v, x)) return 0;
        if (*x >= 8) return 1;
        fprintf(stderr, "%s: %s=%s must be at least 8 (sigma)\n", c->name, key, v);
        return 0;
    }
    if (!strcmp(key, "rho")) return positive(c, key, v, &si.rho);
    if (!strcmp(key, "eta")) return positive(c, key, v, &si.eta);
    if (!strcmp(key, "nbar")) return positive(c, key, v, &si.nbar);
    if (!strcmp(key, "T")) return positive(c, key, v, &si.T);
    if (!strcmp(key, "dt")) return positive(c, key, v, &si.dt);
    if (!strcmp(key, "sigma")) return positive(c, key, v, &si.sigma);
    if (!strcmp(key, "h")) return positive(c, key, v, &si.h_sigma);
    if (!strcmp(key, "xi")) return positive(c, key, v, &si.xi);
    if (!strcmp(key, "chi")) return positive(c, key, v, &si.chi);
    if (!strcmp(key, "rc")) return positive(c, key, v, &si.rc_sigma);
    if (!strcmp(key, "p")) return positive(c, key, v, &si.p_kuhn);
    if (!strcmp(key, "n_max")) return positive(c, key, v, &si.n_max_cstar);
    if (!strcmp(key, "steps")) {
        if (!int_range(c, key, v, &opt.le_steps, 30, 1000000000)) return 0;
        opt.rp_steps = opt.le_steps;
        return 1;
    }
    if (!strcmp(key, "le_steps")) return int_range(c, key, v, &opt.le_steps, 30, 1000000000);
    if (!strcmp(key, "rp_steps")) return int_range(c, key, v, &opt.rp_steps, 30, 1000000000);
    if (!strcmp(key, "eq_steps")) return int_range(c, key, v, &opt.eq_steps, 1, 1000000000);
    if (!strcmp(key, "blocks")) return int_range(c, key, v, &opt.nblk, 2, MAXB);
    if (!strcmp(key, "substeps")) return int_range(c, key, v, &opt.substeps, 1, 1000);
    if (!strcmp(key, "pair")) {
        if (!strcmp(v, "shardlow") || !strcmp(v, "euler")) {
            opt.pair_euler = v[0] == 'e';
            return 1;
        }
        fprintf(stderr, "%s: pair=%s must be shardlow or euler\n", c->name, v);
        return 0;
    }
    if (!strcmp(key, "fluid_start")) {
        if (!strcmp(v, "lattice") || !strcmp(v, "random")) {
            opt.fluid_random = v[0] == 'r';
            return 1;
        }
        fprintf(stderr, "%s: fluid_start=%s must be lattice or random\n", c->name, v);
        return 0;
    }
    if (!strcmp(key, "coupling")) {
        if (!strcmp(v, "shepard") || !strcmp(v, "raw")) {
            opt.coupling = v[0] == 'r' ? HCBD_COUPLE_RAW : HCBD_COUPLE_SHEPARD;
            return 1;
        }
        fprintf(stderr, "%s: coupling=%s must be shepard or raw\n", c->name, v);
        return 0;
    }
    if (!strcmp(key, "plateau")) return int_range(c, key, v, &opt.plateau, 0, 1);
    if (!strcmp(key, "startup_max")) return int_range(c, key, v, &opt.startup_max, 3, 64);
    if (!strcmp(key, "startup_min")) return positive(c, key, v, &opt.startup_min);
    if (!strcmp(key, "startup_strain")) return positive(c, key, v, &opt.startup_strain);
    if (!strcmp(key, "measure_strain")) return positive(c, key, v, &opt.measure_strain);
    if (!strcmp(key, "startup_corr")) {
        if (!parse_double(c, key, v, &opt.startup_corr)) return 0;
        if (opt.startup_corr >= 0) return 1;
        fprintf(stderr, "%s: startup_corr=%s must be 0 or more\n", c->name, v);
        return 0;
    }
    if (!strcmp(key, "startup_tol")) return positive(c, key, v, &opt.startup_tol);
    if (!strcmp(key, "startup_lambda")) return positive(c, key, v, &opt.startup_lambda);
    if (!strcmp(key, "jobs")) return int_range(c, key, v, &opt.jobs, 1, 64);
    if (!strcmp(key, "block_tau")) return positive(c, key, v, &opt.block_tau);
    if (!strcmp(key, "slabs")) {
        if (!int_range(c, key, v, &opt.nslab, 6, MAXS)) return 0;
        if (opt.nslab % 4 == 2) return 1;
        /* a slab must be centred on each half's centre, y = L/4 and 3L/4 */
        fprintf(stderr, "%s: slabs=%s must be 4k+2\n", c->name, v);
        return 0;
    }
    if (!strcmp(key, "seed") || !strcmp(key, "threads") || !strcmp(key, "out") || !strcmp(key, "xyz") ||
        !strcmp(key, "xyz_every") || !strcmp(key, "thermo_every") || !strcmp(key, "checkpoint") ||
        !strcmp(key, "restart"))
        return -1;
    fprintf(stderr, "%s: unknown key '%s'\n", c->name, key);
    usage(stderr);
    return 0;
}

static double seconds_since(const struct timespec *t0)
{
    struct timespec t1;
    clock_gettime(CLOCK_MONOTONIC, &t1);
    return (t1.tv_sec - t0->tv_sec) + 1e-9 * (t1.tv_nsec - t0->tv_nsec);
}

static void sleep_s(double s)
{
    struct timespec t;
    t.tv_sec = (time_t)s;
    t.tv_nsec = (long)((s - (double)t.tv_sec) * 1e9);
    nanosleep(&t, NULL);
}

static void report_progress(int force)
{
    int64_t unit = 1 + prog.total / INT_MAX; /* progress() counts in int */
    if (!force && seconds_since(&prog.last) < 5.0) return;
    clock_gettime(CLOCK_MONOTONIC, &prog.last);
    progress(prog.c, (int)(prog.done / unit), (int)(prog.total / unit), &prog.t0);
}

static hc_config rst;  /* restart='s configuration, if given */

/* Steps with progress and run output; on failure prints the library's
   message. */
static int advance(hcbd_hc_world *w, run_out *o, int n, const char *what)
{
    while (n > 0) {
        int k = n < 1000 ? n : 1000, stop;
        if (run_steps(prog.c, o, w, k) != HCBD_OK) {
            fprintf(stderr, "\nhcbd_polymer: %s: %s\n", what, w->err.msg);
            PROGRESS_LOCK
            prog.failed = 1;
            return 0;
        }
        n -= k;
        PROGRESS_LOCK
        {
            prog.done += k;
            report_progress(0);
            stop = prog.failed;
        }
        if (stop) return 0;
    }
    return 1;
}

/* The fluid of fluid_start=random: without fluctuations the blobs keep
   the rows of a start lattice, so this start tells what the rows do to the
   stress.  Random sequential addition with no two blobs closer than half
   the lattice spacing (excluded spheres fill pi/48 of the box, so it never
   stalls),
   at rest; the pressure differences of the disorder relax within a viscous
   time L^2 / nu (a few ms at Table I), far inside the start-up. */
static hcbd_result place_fluid_random(hcbd_hc_world *w, int nf)
{
    double *xv = (double *)calloc(6 * (size_t)nf + 1, sizeof(double));
    const double *L = w->p.L;
    double dmin = 0.5 * cbrt(L[0] * L[1] * L[2] / nf);
    hcbd_rng g;
    hcbd_result r;
    int i = 0, tries = 0;
    if (!xv) {
        fprintf(stderr, "hcbd_polymer: fluid_start=random: out of memory\n");
        return HCBD_ERR_MEMORY;
    }
    hcbd_rng_seed(&g, w->p.seed ^ 0x6a09e667f3bcc909ULL);
    while (i < nf && tries < 1000 * nf) {
        double *x = xv + 3 * i;
        int j, d, ok = 1;
        ++tries;
        for (d = 0; d < 3; ++d) x[d] = hcbd_rng_uniform(&g) * L[d];
        for (j = 0; j < i && ok; ++j) {
            double r2 = 0;
            for (d = 0; d < 3; ++d) {
                double dx = x[d] - xv[3 * j + d];
                dx -= L[d] * floor(dx / L[d] + 0.5);
                r2 += dx * dx;
            }
            ok = r2 >= dmin * dmin;
        }
        i += ok;
    }
    if (i < nf) fprintf(stderr, "hcbd_polymer: fluid_start=random placed %d of %d blobs\n", i, nf);
    r = i < nf ? HCBD_ERR_OVERLAP : hcbd_hc_world_set_fluid(w, nf, xv, xv + 3 * (size_t)nf);
    free(xv);
    return r;
}

/* A run's world: Table I at p, the fluid on a lattice and the polymers at
   random, or restart='s configuration when its counts are the run's; its
   run output opens under label. */
static int new_world(hcbd_hc_world *w, run_out *o, const hcbd_hc_params *p, int nf, int np, const char *what,
                     const char *label)
{
    hcbd_hc_world_def def = hcbd_hc_world_def_default();
    def.params = *p;
    def.fluid_capacity = nf;
    def.polymer_capacity = np;
    def.pair_capacity = HCBD_AUTO;
    if (hcbd_hc_world_create(w, &def) != HCBD_OK) {
        fprintf(stderr, "hcbd_polymer: %s: %s\n", what, w->err.msg);
        return 0;
    }
    if (rst.fluid && rst.nf == nf && rst.np == np) {
        if (!hc_place(prog.c, &rst, w, nf, np)) {
            hcbd_hc_world_destroy(w);
            return 0;
        }
    } else {
        if (rst.fluid) printf("# restart: %s has %d fluid blobs and %d polymers: started fresh\n", what, nf, np);
        if ((opt.fluid_random ? place_fluid_random(w, nf) : hcbd_hc_world_place_fluid_lattice(w, nf)) != HCBD_OK ||
            hcbd_hc_world_place_polymers_random(w, np) != HCBD_OK) {
            fprintf(stderr, "hcbd_polymer: %s: %s\n", what, w->err.msg);
            hcbd_hc_world_destroy(w);
            return 0;
        }
    }
    if (!run_out_open(prog.c, o, w, label)) {
        hcbd_hc_world_destroy(w);
        return 0;
    }
    return 1;
}

/* Ends a run: its trajectory closes and, if it went well, its checkpoint
   is written. */
static int end_world(hcbd_hc_world *w, run_out *o, int ok)
{
    if (ok) ok = run_out_close(prog.c, o, w);
    else if (o->xyz) fclose(o->xyz);
    o->xyz = NULL;
    hcbd_hc_world_destroy(w);
    return ok;
}

static int blobs_in(const hcbd_hc_params *p)
{
    return (int)floor(p->nbar * p->L[0] * p->L[1] * p->L[2] + 0.5);
}

static int polymers_in(const hcbd_hc_params *p, double C)
{
    double cstar = 3.0 / (4.0 * PI * p->sigma * p->sigma * p->sigma);
    return (int)floor(C * cstar * p->L[0] * p->L[1] * p->L[2] + 0.5);
}

/* The runs' state checksums, mixed in the order of the runs (not of
   their ends, which jobs= changes). */
static void mix_checksum(uint64_t *sum, uint64_t run)
{
    *sum = (*sum ^ run) * 0x100000001B3ULL;
}

/* Steps of one block of a plateau-tested run. */
static int block_steps(const hcbd_hc_params *p)
{
    const int n = (int)floor(opt.block_tau * p->tau_lambda / p->dt + 0.5);
    return n > 0 ? n : 1;
}

/* Steps of half a block: the start-up's chunks and the series' points. */
static int half_steps(const hcbd_hc_params *p)
{
    return (block_steps(p) + 1) / 2;
}

/* Mean of the total stress over the next n steps (the stress average
   restarted). */
static int stress_chunk(hcbd_hc_world *w, run_out *o, int n, const char *what, double s[HCBD_HC_NSTRESS])
{
    hcbd_hc_world_stress_enable(w, 1);
    if (!advance(w, o, n, what)) return 0;
    hcbd_hc_world_stress_read(w, s, NULL);
    return 1;
}

/* The start-up's stress growth, chunk means c[1..nc-1] of width bt (the
   first chunk holds the fast transients and is left out), fitted by
   a + b exp(-t / tau) (least squares in a and b for each tau on a grid of
   0.2 to 20 chunks); returns the share of the measured mean that the
   growth would still carry, b tau / W exp(-T / tau) (1 - exp(-W / tau)) / a
   over the window T = nc bt .. T + W, W = nw bt, the fitted tau and
   |b| over its standard error (below 2: no growth is seen above the
   noise, and a growth fitted to noise would extrapolate anywhere). */
static double startup_bias(const double *c, int nc, double bt, int nw, double *tau_fit, double *signif)
{
    const double T = nc * bt, W = nw * bt, n = nc - 1;
    double best = INFINITY, ba = 0, bb = 0, btau = bt, bse = 0;
    int g, k;
    for (g = 0; g < 64; ++g) {
        const double tau = bt * 0.2 * pow(100.0, g / 63.0);
        double sx = 0, sy = 0, sxx = 0, sxy = 0, det, a, b, ssr = 0;
        for (k = 1; k < nc; ++k) {
            const double x = exp(-(k + 0.5) * bt / tau);
            sx += x;
            sy += c[k];
            sxx += x * x;
            sxy += x * c[k];
        }
        det = n * sxx - sx * sx;
        if (!(det > 0)) continue;
        b = (n * sxy - sx * sy) / det;
        a = (sy - b * sx) / n;
        for (k = 1; k < nc; ++k) {
            const double r = c[k] - a - b * exp(-(k + 0.5) * bt / tau);
            ssr += r * r;
        }
        if (ssr < best) {
            best = ssr;
            ba = a;
            bb = b;
            btau = tau;
            bse = sqrt(ssr / (n > 3 ? n - 3 : 1) * n / det); /* a, b and tau fitted */
        }
    }
    *tau_fit = btau;
    *signif = bse > 0 ? fabs(bb) / bse : INFINITY;
    if (!(best < INFINITY) || ba == 0) return INFINITY;
    return fabs(bb * btau / W * exp(-T / btau) * (1 - exp(-W / btau)) / ba);
}

/* One Lees-Edwards run: viscosities of the four parts at shear rate gd
   with block errors; rise = (last block - first block) / mean of the
   total, a measure of how far from steady the stress still is.

   With plateau=1 the start-up is measured, not assumed: chunks of half a
   block run until the stress growth fitted to them (startup_bias) would
   carry less than startup_tol of the measured mean, or no growth stands
   out of the noise, after at least 3 blocks and at most startup_max; a
   run that does not level off is flagged (startup < 0).  The stress of these solutions grows on the scale
   of the Carreau lambda (2-3 tau_lambda), so the slowest rates take ~4
   lambda.  The error of the total is the larger of the block error and
   the one from blocks twice as long (err_ratio), so that a correlation
   time beyond a block does not hide. */
static int shear_run(const hcbd_hc_params *base, conc_run *cr, int r, double gd, uint64_t *checksum)
{
    hcbd_hc_params p = *base;
    hcbd_hc_world w;
    run_out ro;
    double blk[NCOMP][MAXB], s[HCBD_HC_NSTRESS];
    int per, b, k, nb;
    char what[96], label[64];
    snprintf(what, sizeof what, "C = %g C*, gdot = %g 1/s", cr->C, opt.gdot_si[r]);
    snprintf(label, sizeof label, "C%g_gdot%g", cr->C, opt.gdot_si[r]);
    p.gdot = gd;
    /* the measured window: nblk blocks, and more until it spans
       measure_strain (the slow rates' stress stays correlated over
       tau_lambda's, and their signal is the weakest) */
    nb = opt.nblk;
    if (opt.plateau && opt.measure_strain > 0) {
        const int ns = (int)ceil(opt.measure_strain / (gd * block_steps(&p) * p.dt) - 1e-9);
        if (nb < ns) nb = ns < MAXB ? ns : MAXB;
    }
    if (!new_world(&w, &ro, &p, blobs_in(&p), cr->np, what, label)) return 0;
    cr->relax[r] = cr->bias[r] = NAN;
    if (opt.plateau) {
        /* start-up chunks of half a block: the growth is resolved and the
           fastest rates, which level off at once, stop after 3 blocks */
        const int half = half_steps(&p);
        const double bt = half * p.dt / p.tau_lambda;
        /* at least 3 blocks, and 4 times the assumed slowest relaxation
           time, which shear shortens as 1 / (1 + gdot lambda) */
        const double wl = gd * opt.startup_lambda * p.tau_lambda;
        int nc = 0, level = 0, least = (int)ceil(4 * opt.startup_lambda / ((1 + wl) * bt) - 1e-9);
        if (least < 6) least = 6;
        if (least < (int)ceil(opt.startup_min / bt - 1e-9)) least = (int)ceil(opt.startup_min / bt - 1e-9);
        /* and a strain: the transient pairs' structure follows the flow's
           displacements, which diffusion alone renews far slower than
           tau_lambda, so at low rates the stress still grows until the
           strain is of order one (issue 41: the long runs stored in
           bench/results/paper_long) */
        if (opt.startup_strain > 0) {
            const int ls = (int)ceil(opt.startup_strain / (gd * half * p.dt) - 1e-9);
            if (least < ls) least = ls;
        }
        if (least > 2 * opt.startup_max) least = 2 * opt.startup_max;
        per = block_steps(&p);
        /* the series holds 2 startup_max <= 128 chunks; the fit's ratios
           do not depend on the 1/gd that makes them viscosities */
        while (nc < 2 * opt.startup_max && !level) {
            if (!stress_chunk(&w, &ro, half, what, s)) goto fail;
            cr->series[r][nc++] = s[HCBD_HC_S_TOTAL] / gd;
            if (nc >= least) {
                double sig, m, e, ne;
                cr->bias[r] = startup_bias(cr->series[r], nc, bt, nb * per / half, &cr->relax[r], &sig);
                level = cr->bias[r] <= opt.startup_tol || sig < 2;
                /* at least startup_corr correlation times of the stress,
                   read by blocking from the second half of the start-up (a
                   trend still in it reads as a longer time: a longer
                   start-up) */
                if (level && opt.startup_corr > 0 && nc / 2 >= 8 &&
                    hcbd_blocking_error(cr->series[r] + nc - nc / 2, nc / 2, &m, &e, &ne, NULL) == HCBD_OK)
                    level = nc >= opt.startup_corr * (nc / 2) / (2.0 * ne);
            }
        }
        cr->startup[r] = (level ? 1 : -1) * nc * bt;
        cr->nser_up[r] = cr->nser[r] = nc;
    } else {
        per = (opt.le_steps - 2 * opt.le_steps / 3) / nb;
        if (!advance(&w, &ro, opt.le_steps - per * nb, what)) goto fail;
        cr->startup[r] = (opt.le_steps - per * nb) * p.dt / p.tau_lambda;
    }
    for (b = 0; b < nb; ++b) {
        if (opt.plateau) { /* two halves, for the series */
            double h1[HCBD_HC_NSTRESS];
            const int half = half_steps(&p);
            if (!stress_chunk(&w, &ro, half, what, h1) || !stress_chunk(&w, &ro, per - half, what, s)) goto fail;
            if (cr->nser[r] + 2 <= NSER) {
                cr->series[r][cr->nser[r]++] = h1[HCBD_HC_S_TOTAL] / gd;
                cr->series[r][cr->nser[r]++] = s[HCBD_HC_S_TOTAL] / gd;
            }
            for (k = 0; k < HCBD_HC_NSTRESS; ++k) s[k] = (half * h1[k] + (per - half) * s[k]) / per;
        } else if (!stress_chunk(&w, &ro, per, what, s)) goto fail;
        for (k = 0; k < NCOMP; ++k) blk[k][b] = s[comp_index[k]] / gd;
    }
    for (k = 0; k < NCOMP; ++k) mean_err(blk[k], nb, &cr->eta[k][r], &cr->err[k][r]);
    cr->err_ratio[r] = NAN;
    if (nb >= 4) {
        double two[MAXB / 2], m, e2;
        for (b = 0; b + 1 < nb; b += 2) two[b / 2] = 0.5 * (blk[0][b] + blk[0][b + 1]);
        mean_err(two, nb / 2, &m, &e2);
        cr->err_ratio[r] = e2 / cr->err[0][r];
        if (e2 > cr->err[0][r]) cr->err[0][r] = e2;
    }
    /* the error from the correlation time: blocking (Flyvbjerg-Petersen)
       of the half-block series of the window, which blocks of one
       block_tau understate when the stress stays correlated longer */
    cr->neff[r] = NAN;
    cr->fp_plateau[r] = 0;
    if (opt.plateau) {
        const int nw = cr->nser[r] - cr->nser_up[r];
        double m, e, ne;
        int pl;
        if (nw >= 8 && hcbd_blocking_error(cr->series[r] + cr->nser_up[r], nw, &m, &e, &ne, &pl) == HCBD_OK) {
            cr->neff[r] = ne;
            cr->fp_plateau[r] = pl;
            if (e > cr->err[0][r]) cr->err[0][r] = e;
        }
    }
    cr->rise[r] = (blk[0][nb - 1] - blk[0][0]) / cr->eta[0][r];
    *checksum = hcbd_hc_world_checksum(&w);
    return end_world(&w, &ro, 1);
fail:
    return end_world(&w, &ro, 0);
}

/* Within Ly/8 of a plane where the reverse-Poiseuille force flips. */
static int high_shear(double y, double Ly)
{
    double d = fmod(y, 0.5 * Ly);
    return d < Ly / 8 || d > 0.5 * Ly - Ly / 8;
}

/* Height of the reverse-Poiseuille box: base->L[1], stretched by whole
   lattice rows (spacing nbar^(-1/3)) until no blob of the start lattice
   lies within a quarter row of y = 0 or L/2 (fluid_start=random: no rows,
   base->L[1]). */
static int rp_height(const hcbd_hc_params *base, double *Ly)
{
    hcbd_hc_params p = *base;
    double a = 1 / cbrt(p.nbar);
    int k, i;
    p.gdot = 0;
    if (opt.fluid_random) {
        *Ly = base->L[1];
        return 1;
    }
    for (k = 0; k < 4; ++k, p.L[1] += a) {
        hcbd_hc_world_def def = hcbd_hc_world_def_default();
        hcbd_hc_world w;
        int on_plane = 0, nf = blobs_in(&p);
        def.params = p;
        def.fluid_capacity = nf;
        def.polymer_capacity = 0;
        if (hcbd_hc_world_create(&w, &def) != HCBD_OK || hcbd_hc_world_place_fluid_lattice(&w, nf) != HCBD_OK) {
            fprintf(stderr, "hcbd_polymer: reverse-Poiseuille box: %s\n", w.err.msg);
            hcbd_hc_world_destroy(&w);
            return 0;
        }
        for (i = 0; i < nf; ++i) {
            double d = fmod(w.fy[i], 0.5 * p.L[1]);
            if (d < 0.25 * a || d > 0.5 * p.L[1] - 0.25 * a) on_plane = 1;
        }
        hcbd_hc_world_destroy(&w);
        if (!on_plane) {
            *Ly = p.L[1];
            return 1;
        }
    }
    printf("# warning: lattice rows lie on y = 0 or L/2 for every box height tried\n");
    *Ly = base->L[1];
    return 1;
}

/* Mean signed velocity of the particles within L/8 of the centre planes
   y = L/4 (flow along -x) and 3L/4 (+x): wide enough to hold a row of
   fluid blobs. */
static double centre_velocity(const hcbd_real *y, const hcbd_real *v, int n, double Ly)
{
    double s = 0;
    int i, cnt = 0;
    for (i = 0; i < n; ++i) {
        if (fabs(y[i] - 0.75 * Ly) < Ly / 8) { s += v[i]; ++cnt; }
        else if (fabs(y[i] - 0.25 * Ly) < Ly / 8) { s -= v[i]; ++cnt; }
    }
    return cnt ? s / cnt : 0.0;
}

/* Sums over the two halves of the box (high and low shear) for the
   depletion measures. */
typedef struct { double pc[2], pn[2], fc[2], fn[2]; } zone_sums;

static void zones_add(zone_sums *z, const hcbd_hc_world *w)
{
    int i;
    for (i = 0; i < w->nf; ++i) {
        int h = high_shear(w->fy[i], w->p.L[1]);
        z->fc[h] += 1;
        z->fn[h] += w->fn[i];
    }
    for (i = 0; i < w->np; ++i) {
        int h = high_shear(w->py[i], w->p.L[1]);
        z->pc[h] += 1;
        z->pn[h] += w->pn[i];
    }
}

static void zones_depletion(const zone_sums *z, double d[ND])
{
    d[D_PCOUNT] = 1 - z->pc[1] / z->pc[0];
    d[D_PKERNEL] = 1 - (z->pn[1] / z->pc[1]) / (z->pn[0] / z->pc[0]);
    d[D_FKERNEL] = 1 - (z->fn[1] / z->fc[1]) / (z->fn[0] / z->fc[0]);
}

/* The reverse-Poiseuille run: slab profiles and depletion of both species
   over the last third (the polymers' also at the start, the reference for
   their migration), the centre velocities over the whole run. */
static int rp_run(const hcbd_hc_params *base, conc_run *cr, uint64_t *checksum)
{
    hcbd_hc_params p = *base;
    hcbd_hc_world w;
    run_out ro;
    hcbd_slabs sf, sp, s0;
    zone_sums z;
    size_t bf = hcbd_slabs_bytes(opt.nslab, 2), bp = hcbd_slabs_bytes(opt.nslab, 3);
    size_t b0 = hcbd_slabs_bytes(opt.nslab, 1);
    void *mf = malloc(bf), *mp = malloc(bp), *m0 = malloc(b0);
    int unit = opt.rp_steps / NTS > 1 ? opt.rp_steps / NTS : 1, nunit = opt.rp_steps / unit;
    int start = 2 * nunit / 3, nsamp = nunit - start, block, k, i, d, nb = 0, ok = 0;
    int nf = blobs_in(&p);
    double sum_nf = 0, sum_np = 0, blk[ND][MAXB];
    char what[96], label[64];
    snprintf(what, sizeof what, "C = %g C*, reverse Poiseuille", cr->C);
    snprintf(label, sizeof label, "C%g_rp", cr->C);
    p.gdot = 0;
    p.reverse_poiseuille = 1;
    p.g[0] = cr->g;
    block = nsamp / opt.nblk > 0 ? nsamp / opt.nblk : 1;
    if (!mf || !mp || !m0) {
        fprintf(stderr, "hcbd_polymer: out of memory\n");
        goto done;
    }
    if (!new_world(&w, &ro, &p, nf, cr->np_rp, what, label)) goto done;
    hcbd_slabs_init(&sf, p.L, opt.nslab, 2, block, mf, bf);
    hcbd_slabs_init(&sp, p.L, opt.nslab, 3, block, mp, bp);
    hcbd_slabs_init(&s0, p.L, opt.nslab, 1, 1, m0, b0);
    cr->np0_kernel = 0;
    for (i = 0; i < cr->np_rp; ++i) {
        double n = w.pn[i];
        hcbd_slabs_add(&s0, w.py[i], &n);
        cr->np0_kernel += n / cr->np_rp;
    }
    hcbd_slabs_end_sample(&s0);
    hcbd_slabs_result(&s0, cr->prof_p0);
    memset(&z, 0, sizeof z);
    zones_add(&z, &w);
    zones_depletion(&z, cr->dep0);
    memset(&z, 0, sizeof z);
    /* the remainder of rp_steps / unit first, as start-up */
    if (!advance(&w, &ro, opt.rp_steps - nunit * unit, what)) goto fail;
    cr->nts = 0;
    cr->ts_from = start;
    for (k = 0; k < nunit; ++k) {
        if (!advance(&w, &ro, unit, what)) goto fail;
        if (cr->nts < NTS) {
            cr->ts[cr->nts][0] = (double)w.step * p.dt;
            cr->ts[cr->nts][1] = centre_velocity(w.fy, w.fvx, nf, p.L[1]);
            cr->ts[cr->nts][2] = centre_velocity(w.py, w.pux, cr->np_rp, p.L[1]);
            cr->nts++;
        }
        if (k < start) continue;
        for (i = 0; i < nf; ++i) {
            double v[2];
            v[0] = w.fvx[i];
            v[1] = w.fn[i];
            sum_nf += v[1];
            hcbd_slabs_add(&sf, w.fy[i], v);
        }
        for (i = 0; i < cr->np_rp; ++i) {
            double u[3];
            u[0] = w.pux[i];
            u[1] = w.pn[i];
            u[2] = w.pFx[i] / p.xi; /* u_x - v_x(r_a): the polymer's slip */
            sum_np += u[1];
            hcbd_slabs_add(&sp, w.py[i], u);
        }
        hcbd_slabs_end_sample(&sf);
        hcbd_slabs_end_sample(&sp);
        zones_add(&z, &w);
        if ((k - start + 1) % block == 0 && nb < opt.nblk) {
            double dz[ND];
            zones_depletion(&z, dz);
            for (d = 0; d < ND; ++d) blk[d][nb] = dz[d];
            ++nb;
            memset(&z, 0, sizeof z);
        }
    }
    hcbd_slabs_result(&sf, cr->prof_f);
    hcbd_slabs_result(&sp, cr->prof_p);
    cr->nf_kernel = sum_nf / ((double)nf * nsamp);
    cr->np_kernel = sum_np / ((double)cr->np_rp * nsamp);
    for (d = 0; d < ND; ++d) mean_err(blk[d], nb, &cr->dep[d][0], &cr->dep[d][1]);
    *checksum = hcbd_hc_world_checksum(&w);
    ok = 1;
fail:
    ok = end_world(&w, &ro, ok);
done:
    free(mf);
    free(mp);
    free(m0);
    return ok;
}

/* Carreau law (2018 eq. 36) and the shear rate at which it carries the
   shear stress s: the stress grows monotonically for n >= 0, and
   eta >= eta_inf bounds the root by s / eta_inf. */
static double carreau_eta(const double pc[3], double eta_inf, double gd)
{
    return eta_inf + (pc[0] - eta_inf) * pow(1 + pc[1] * pc[1] * gd * gd, 0.5 * (pc[2] - 1));
}

static double carreau_rate(const double pc[3], double eta_inf, double s)
{
    double lo = 0, hi = s / eta_inf;
    int k;
    for (k = 0; k < 200 && hi - lo > 1e-14 * hi; ++k) {
        double mid = 0.5 * (lo + hi);
        if (carreau_eta(pc, eta_inf, mid) * mid < s) lo = mid;
        else hi = mid;
    }
    return 0.5 * (lo + hi);
}

/* Speed of a half of width W driven by rho g at distance y from its edge:
   the stress falls linearly to zero at the centre, |S| = rho g (W/2 - s),
   and v(y) integrates the Carreau shear rate from the edge (midpoint rule). */
static double carreau_speed(const double pc[3], double eta_inf, double rho_g, double W, double y)
{
    double a = y < W - y ? y : W - y, sum = 0;
    int k, n = 400;
    for (k = 0; k < n; ++k) sum += carreau_rate(pc, eta_inf, rho_g * (0.5 * W - (k + 0.5) * a / n));
    return sum * a / n;
}

/* Newtonian speed of a half (MODEL.md 10): (g / 2 nu) y (W - y). */
static double newton_speed(double g, double nu, double W, double y)
{
    return g / (2 * nu) * y * (W - y);
}

/* What the reverse-Poiseuille velocity profiles say (see the summary). */
typedef struct {
    double vc, vc_err, vc_polymer, vn_c, vcar_c, fill, fill_n, lag, lag_err, slip, change;
    int populated[MAXS], npop;
} rp_metrics;

static void rp_analyse(const conc_run *cr, const hcbd_hc_params *p, rp_metrics *m)
{
    const int ns = opt.nslab, q1 = (ns - 2) / 4, q3 = ns / 2 + q1;
    const double W = 0.5 * p->L[1], nu0 = cr->eta0 / p->rho;
    const double nf_mean = blobs_in(p) / (p->L[0] * p->L[1] * p->L[2]);
    double vmax = 0, best[2] = {-HUGE_VAL, -HUGE_VAL}, best_err[2] = {0, 0}, m1 = 0, m2 = 0;
    int s, k, n1 = 0, n2 = 0;
    memset(m, 0, sizeof *m);
    for (s = 0; s < ns; ++s) {
        const double *a = cr->prof_f + SF * s;
        int h = a[0] >= W;
        m->populated[s] = a[1] >= 0.5 * nf_mean;
        if (!m->populated[s]) continue;
        m->npop++;
        vmax = fmax(vmax, fabs(a[SF_V]));
        if ((h ? 1 : -1) * a[SF_V] > best[h]) {
            best[h] = (h ? 1 : -1) * a[SF_V];
            best_err[h] = a[SF_V + 1];
        }
    }
    /* centre velocity: the fastest populated slab of each half */
    m->vc = 0.5 * (best[0] + best[1]);
    m->vc_err = 0.5 * hypot(best_err[0], best_err[1]);
    m->vc_polymer = 0.5 * (cr->prof_p[SP * q3 + SP_U] - cr->prof_p[SP * q1 + SP_U]);
    m->vn_c = newton_speed(cr->g, nu0, W, 0.5 * W);
    if (cr->fitted) m->vcar_c = carreau_speed(cr->pc, opt.eta_inf, p->rho * cr->g, W, 0.5 * W);
    for (s = 0; s < ns; ++s) {
        const double *a = cr->prof_f + SF * s, *b = cr->prof_p + SP * s;
        double y = a[0], sg = y >= W ? 1 : -1, yh = y >= W ? y - W : y;
        m->slip = fmax(m->slip, fabs(b[SP_SLIP]));
        if (!m->populated[s]) continue;
        if (fabs(b[SP_U] - a[SF_V]) > m->lag) {
            m->lag = fabs(b[SP_U] - a[SF_V]);
            m->lag_err = hypot(a[SF_V + 1], b[SP_U + 1]);
        }
        m->fill += sg * a[SF_V] / m->vc;
        m->fill_n += newton_speed(cr->g, nu0, W, yh) / m->vn_c;
    }
    if (m->npop) {
        m->fill /= m->npop;
        m->fill_n /= m->npop;
    }
    if (vmax > 0) {
        m->lag /= vmax;
        m->lag_err /= vmax;
        m->slip /= vmax;
    }
    for (k = cr->ts_from; k < cr->nts; ++k) {
        if (2 * (k - cr->ts_from) < cr->nts - cr->ts_from) { m1 += cr->ts[k][1]; ++n1; }
        else { m2 += cr->ts[k][1]; ++n2; }
    }
    m->change = n1 && n2 && m1 != 0 ? (m2 / n2 - m1 / n1) / (m1 / n1) : 0;
}

/* Total momentum before and after an equilibrium run (no shear, no body
   force), against the gross impulse the polymers hand to the fluid,
   dt sum_steps sum_a |F_a|: pair forces cancel in the sum, so the
   momentum may change only by round-off. */
static int momentum_run(const hcbd_hc_params *base, int np, double *dp, double *scale,
                        uint64_t *checksum)
{
    hcbd_hc_params p = *base;
    hcbd_hc_world w;
    run_out ro;
    double P0[3], P1[3];
    int s, a;
    p.gdot = 0;
    p.reverse_poiseuille = 0;
    p.g[0] = p.g[1] = p.g[2] = 0;
    if (!new_world(&w, &ro, &p, blobs_in(&p), np, "momentum run", "momentum")) return 0;
    hcbd_hc_world_momentum(&w, P0);
    *scale = 0;
    for (s = 0; s < opt.eq_steps; ++s) {
        for (a = 0; a < w.np; ++a)
            *scale += p.dt * sqrt((double)w.pFx[a] * w.pFx[a] + (double)w.pFy[a] * w.pFy[a] +
                                  (double)w.pFz[a] * w.pFz[a]);
        if (!advance(&w, &ro, 1, "momentum run")) return end_world(&w, &ro, 0);
    }
    hcbd_hc_world_momentum(&w, P1);
    *dp = sqrt((P1[0] - P0[0]) * (P1[0] - P0[0]) + (P1[1] - P0[1]) * (P1[1] - P0[1]) +
               (P1[2] - P0[2]) * (P1[2] - P0[2]));
    *checksum = hcbd_hc_world_checksum(&w);
    return end_world(&w, &ro, 1);
}

/* Conversion of reduced values to SI. */
typedef struct { double len, t, kT, M, v, eta, P, acc; } units;

/* length sigma, energy kT, time time_unit; mass kT t^2 / sigma^2 */
static void set_units(units *u, const hcbd_hc_si *s, double time_unit)
{
    u->len = s->sigma;
    u->t = time_unit;
    u->kT = KB * s->T;
    u->M = u->kT * u->t * u->t / (u->len * u->len);
    u->v = u->len / u->t;
    u->eta = u->M / (u->len * u->t);
    u->P = u->M / (u->len * u->t * u->t);
    u->acc = u->len / (u->t * u->t);
}

/* Units of a parameter: powers of length, time, energy (kT) and mass. */
typedef struct { int len, t, kT, M; } dims;

static double to_si(const units *u, dims d)
{
    return pow(u->len, d.len) * pow(u->t, d.t) * pow(u->kT, d.kT) * pow(u->M, d.M);
}

/* The parameters used (in the run's units u) against Table I (in its own
   units ut: sigma and T may differ), compared in SI. */
static void print_parameters(const units *u, const hcbd_hc_params *p, const units *ut,
                             const hcbd_hc_params *tab)
{
    static const dims T = {0, 1, 0, 0}, RHO = {-3, 0, 0, 1}, N3 = {-3, 0, 0, 0}, ETA = {-1, -1, 0, 1},
                      PR = {-1, -2, 0, 1}, L = {1, 0, 0, 0}, XI = {0, -1, 0, 1}, E = {0, 0, 1, 0},
                      ONE = {0, 0, 0, 0};
    struct row { const char *name, *unit; double used, table; dims d; } rows[] = {
        {"dt", "s", p->dt, tab->dt, T},
        {"rho", "kg/m^3", p->rho, tab->rho, RHO},
        {"nbar", "m^-3", p->nbar, tab->nbar, N3},
        {"eta", "Pa s", p->eta, tab->eta, ETA},
        {"P0", "Pa", p->P0, tab->P0, PR},
        {"h", "m", p->h, tab->h, L},
        {"xi", "kg/s", p->xi, tab->xi, XI},
        {"sigma", "m", p->sigma, tab->sigma, L},
        {"rc", "m", p->rc, tab->rc, L},
        {"alpha", "J", p->alpha, tab->alpha, E},
        {"tau_lambda", "s", p->tau_lambda, tab->tau_lambda, T},
        {"p", "-", p->p_kuhn, tab->p_kuhn, ONE},
        {"n_max", "m^-3", p->n_max, tab->n_max, N3},
        {"chi", "-", p->chi, tab->chi, ONE},
    };
    int k;
    printf("# %-11s %14s %-8s %14s %14s\n", "parameter", "SI (used)", "unit", "reduced used", "Table I (SI)");
    for (k = 0; k < (int)(sizeof rows / sizeof rows[0]); ++k) {
        double used = rows[k].used * to_si(u, rows[k].d), table = rows[k].table * to_si(ut, rows[k].d);
        int same = fabs(used - table) <= 1e-12 * fabs(table);
        printf("# %-11s %14.6g %-8s %14.6g %14.6g", rows[k].name, used, rows[k].unit, rows[k].used, table);
        if (same) printf("\n");
        else printf("   <- differs from Table I (x %.4g)\n", used / table);
    }
}

static void write_flowcurve(const config *c, const conc_run *runs, const units *u)
{
    FILE *f = open_out(c, "flowcurve.csv");
    int ci, r, k;
    if (!f) return;
    fprintf(f, "C,gdot_per_s,gdot,Wi");
    for (k = 0; k < NCOMP; ++k) fprintf(f, ",eta_%s,eta_%s_err", comp_name[k], comp_name[k]);
    for (k = 0; k < NCOMP; ++k) fprintf(f, ",eta_%s_mPas,eta_%s_err_mPas", comp_name[k], comp_name[k]);
    fprintf(f, ",startup_rise,startup_tau_lambda,err_ratio_2blocks,n_eff,blocking_plateau\n");
    for (ci = 0; ci < opt.nconc; ++ci)
        for (r = 0; r < opt.ngdot; ++r) {
            fprintf(f, "%g,%.6g,%.6g,%.4g", runs[ci].C, opt.gdot_si[r], opt.gdot_si[r] * u->t,
                    opt.gdot_si[r] * opt.tau_si);
            for (k = 0; k < NCOMP; ++k) fprintf(f, ",%.6g,%.3g", runs[ci].eta[k][r], runs[ci].err[k][r]);
            for (k = 0; k < NCOMP; ++k)
                fprintf(f, ",%.6g,%.3g", runs[ci].eta[k][r] * u->eta * 1e3, runs[ci].err[k][r] * u->eta * 1e3);
            fprintf(f, ",%.4g,%.4g,%.4g,%.3g,%d\n", runs[ci].rise[r], runs[ci].startup[r], runs[ci].err_ratio[r],
                    runs[ci].neff[r], runs[ci].fp_plateau[r]);
        }
    fclose(f);
}

/* profile_C<C>.csv (Figs. 5, 6) and rp_start_C<C>.csv */
static void write_profiles(const config *c, const conc_run *cr, const hcbd_hc_params *p, const rp_metrics *m,
                           const units *u)
{
    const double W = 0.5 * p->L[1], nu0 = cr->eta0 / p->rho, V = p->L[0] * p->L[1] * p->L[2];
    const double nfm = blobs_in(p) / V, npm = cr->np_rp / V;
    char name[64];
    FILE *f;
    int s, k;
    snprintf(name, sizeof name, "profile_C%g.csv", cr->C);
    if ((f = open_out(c, name))) {
        fprintf(f, "y,fluid_kernel_density_over_mean,fluid_kernel_density_err,"
                   "polymer_kernel_density_over_mean,polymer_kernel_density_err,"
                   "polymer_kernel_density_initial,fluid_count_density_over_mean,fluid_count_err,"
                   "polymer_count_density_over_mean,polymer_count_err,polymer_count_density_initial,"
                   "v_fluid,v_fluid_err,u_polymer,u_polymer_err,slip,slip_err,v_newtonian_eta0,"
                   "v_carreau,fluid_populated\n");
        for (s = 0; s < opt.nslab; ++s) {
            const double *a = cr->prof_f + SF * s, *b = cr->prof_p + SP * s, *b0 = cr->prof_p0 + S0 * s;
            double y = a[0], sg = y >= W ? 1 : -1, yh = y >= W ? y - W : y;
            fprintf(f, "%.6g,%.6g,%.3g,%.6g,%.3g,%.6g,", y, a[SF_N] / cr->nf_kernel, a[SF_N + 1] / cr->nf_kernel,
                    b[SP_N] / cr->np_kernel, b[SP_N + 1] / cr->np_kernel, b0[S0_N] / cr->np0_kernel);
            fprintf(f, "%.6g,%.3g,%.6g,%.3g,%.6g,", a[1] / nfm, a[2] / nfm, b[1] / npm, b[2] / npm, b0[1] / npm);
            fprintf(f, "%.6g,%.3g,%.6g,%.3g,%.6g,%.3g,%.6g,", a[SF_V], a[SF_V + 1], b[SP_U], b[SP_U + 1],
                    b[SP_SLIP], b[SP_SLIP + 1], sg * newton_speed(cr->g, nu0, W, yh));
            if (cr->fitted) fprintf(f, "%.6g", sg * carreau_speed(cr->pc, opt.eta_inf, p->rho * cr->g, W, yh));
            fprintf(f, ",%d\n", m->populated[s]);
        }
        fclose(f);
    }
    snprintf(name, sizeof name, "rp_start_C%g.csv", cr->C);
    if ((f = open_out(c, name))) {
        fprintf(f, "t,t_s,v_center_fluid,u_center_polymer,measured\n");
        for (k = 0; k < cr->nts; ++k)
            fprintf(f, "%.6g,%.6g,%.6g,%.6g,%d\n", cr->ts[k][0], cr->ts[k][0] * u->t, cr->ts[k][1], cr->ts[k][2],
                    k >= cr->ts_from);
        fclose(f);
    }
}

/* 2018 Table II at C = 2.5 or 5 C* (else 0): eta0 / eta (with eta = 1
   mPa s), lambda / tau_lambda, n; eta_inf = 0.9 mPa s. */
static int table2(double C, double t[3])
{
    if (C != 2.5 && C != 5) return 0;
    t[0] = C == 2.5 ? 2.526 : 6.6688;
    t[1] = C == 2.5 ? 3.0504 : 2.1408;
    t[2] = C == 2.5 ? 0.3441 : 0.0008;
    return 1;
}

static void print_summary(const conc_run *cr, const hcbd_hc_params *p, const rp_metrics *m, const units *u,
                          double mach, double Ly_rp)
{
    const int hi = opt.ngdot - 1;
    const double thin = cr->eta[0][hi] / cr->eta[0][0];
    /* the Carreau form does not fit the points within their errors (chi^2/dof
       of 40-300 at Table I), so the fit's errors are compared scaled */
    const double dof_chi2 = cr->fitted ? cr->chi2 / (opt.ngdot - 3) : 0, /* a fit has 4 rates or more */
                 sc = cr->fitted ? hcbd_carreau_err_scale(cr->chi2, opt.ngdot) : 1;
    double t2[3];
    int k;
    printf("# summary C=%g (C/C* = %g, %d polymers; reduced units: sigma, kT, time unit %g s; "
           "viscosities also in mPa s)\n", cr->C, cr->C, cr->np, u->t);
    printf("eta_fluid=%.6g\neta_fluid_mPas=%.6g\n", p->eta, p->eta * u->eta * 1e3);
    printf("eta_inf=%.6g\neta_inf_mPas=%.6g\n", opt.eta_inf, opt.eta_inf * u->eta * 1e3);
    if (cr->fitted) {
        printf("eta0=%.6g\neta0_err=%.3g\neta0_mPas=%.6g\neta0_over_eta=%.4g\n", cr->pc[0], cr->pe[0],
               cr->pc[0] * u->eta * 1e3, cr->pc[0] / p->eta);
        printf("lambda=%.6g\nlambda_err=%.3g\nlambda_s=%.6g\nlambda_over_tau_lambda=%.4g\n", cr->pc[1], cr->pe[1],
               cr->pc[1] * u->t, cr->pc[1] / p->tau_lambda);
        printf("n=%.4g\nn_err=%.3g\n", cr->pc[2], cr->pe[2]);
        printf("carreau_chi2_per_dof=%.3g\ncarreau_err_scale=%.3g\n", dof_chi2, sc);
    } else {
        printf("# no Carreau fit (fewer than 4 rates, or eta0 <= eta_inf, lambda <= 0 or n < 0):\n"
               "# eta0 is the viscosity at the lowest rate\n");
        printf("eta0=%.6g\neta0_err=%.3g\neta0_mPas=%.6g\neta0_over_eta=%.4g\n", cr->eta0, cr->err[0][0],
               cr->eta0 * u->eta * 1e3, cr->eta0 / p->eta);
    }
    if (table2(cr->C, t2)) {
        printf("eta0_over_eta_paper=%g\nlambda_over_tau_lambda_paper=%g\nn_paper=%g\n", t2[0], t2[1], t2[2]);
        if (cr->fitted) {
            const double ts = p->tau_lambda * u->t, em = u->eta * 1e3;
            printf("# Table II side by side (Carreau fit, eta_inf = %g mPa s held, errors scaled by "
                   "sqrt(chi^2/dof); C = %g C*):\n"
                   "#   %-14s %22s %12s\n"
                   "#   %-14s %12.4g +- %-8.2g %12.4g\n#   %-14s %12.4g +- %-8.2g %12.4g\n"
                   "#   %-14s %12.4g +- %-8.2g %12.4g\n", opt.eta_inf_mpas, cr->C, "", "this run", "2018 paper",
                   "eta0 [mPa s]", cr->pc[0] * em, sc * cr->pe[0] * em, t2[0] * p->eta * em, "lambda [s]",
                   cr->pc[1] * u->t, sc * cr->pe[1] * u->t, t2[1] * ts, "n", cr->pc[2], sc * cr->pe[2], t2[2]);
        }
    }
    for (k = 0; k < NCOMP; ++k)
        printf("eta_%s_lowest_rate=%.6g\neta_%s_lowest_rate_err=%.3g\n", comp_name[k], cr->eta[k][0], comp_name[k],
               cr->err[k][0]);
    printf("shear_thinning=%.4g\nshear_thinning_err=%.3g\n", thin,
           thin * hypot(cr->err[0][hi] / cr->eta[0][hi], cr->err[0][0] / cr->eta[0][0]));
    printf("startup_rise_lowest_rate=%.3g\nmach_max=%.4g\n", cr->rise[0], mach);
    if (opt.plateau) {
        int bad = 0;
        for (k = 0; k < opt.ngdot; ++k) bad += cr->startup[k] < 0;
        printf("# startup_tau_lambda: the start-up each rate took before its stress levelled off (negative: it "
               "did not within startup_max); startup_relax: the time constant of the stress growth fitted to the "
               "start-up, tau_lambda; startup_bias: the share of the measured mean the fitted growth still "
               "carries; err_ratio: the error from blocks twice as long over the block error; n_eff: the "
               "independent samples the measured window is worth (blocking of its half-block series), "
               "blocking_plateau 0 where the window is too short for its correlation time (the error is then a "
               "lower bound)\n");
        for (k = 0; k < opt.ngdot; ++k)
            printf("startup_tau_lambda_gdot%g=%.3g\nstartup_relax_gdot%g=%.3g\nstartup_bias_gdot%g=%.2g\n"
                   "err_ratio_gdot%g=%.3g\nn_eff_gdot%g=%.3g\nblocking_plateau_gdot%g=%d\n", opt.gdot_si[k],
                   cr->startup[k], opt.gdot_si[k], cr->relax[k], opt.gdot_si[k], cr->bias[k], opt.gdot_si[k],
                   cr->err_ratio[k], opt.gdot_si[k], cr->neff[k], opt.gdot_si[k], cr->fp_plateau[k]);
        printf("rates_without_plateau=%d\n", bad);
    }
    printf("rp_Ly=%.4g\nrp_polymers=%d\ng=%.6g\ng_si=%.6g\n", Ly_rp, cr->np_rp, cr->g, cr->g * u->acc);
    printf("v_center=%.6g\nv_center_err=%.3g\nv_center_polymer=%.6g\nv_center_newtonian=%.6g\n", m->vc, m->vc_err,
           m->vc_polymer, m->vn_c);
    printf("flattening=%.4g\nflattening_err=%.3g\n", m->vc / m->vn_c, m->vc_err / m->vn_c);
    if (cr->fitted) printf("v_center_carreau=%.6g\nflattening_carreau=%.4g\n", m->vcar_c, m->vc / m->vcar_c);
    printf("profile_fill=%.4g\nprofile_fill_newtonian=%.4g\nfluid_slabs_populated=%d\n", m->fill, m->fill_n,
           m->npop);
    printf("lag_max=%.4g\nlag_max_err=%.3g\nslip_max=%.3g\n", m->lag, m->lag_err, m->slip);
    for (k = 0; k < ND; ++k)
        printf("%s=%.4g\n%s_err=%.3g\n%s_initial=%.4g\n", dep_name[k], cr->dep[k][0], dep_name[k], cr->dep[k][1],
               dep_name[k], cr->dep0[k]);
    printf("rp_center_change=%.3g\n", m->change);
    if (table2(cr->C, t2)) {
        const int table1 = fabs(p->tau_lambda * u->t - hcbd_hc_si_default().tau_lambda) < 1e-9;
        const char *quick = table1 ? NULL : "this run's tau_lambda (and alpha, P0) are not Table I's (NOTEs above): Table II is for Table I";
        const char *scaled = "2018 Table II; the fit's error scaled by sqrt(chi^2/dof)";
        judge("eta0_over_eta", (cr->fitted ? cr->pc[0] : cr->eta0) / p->eta,
              (cr->fitted ? sc * cr->pe[0] : cr->err[0][0]) / p->eta, "1", t2[0], 0,
              cr->fitted ? scaled : "2018 Table II", quick);
        if (cr->fitted) {
            judge("lambda_over_tau_lambda", cr->pc[1] / p->tau_lambda, sc * cr->pe[1] / p->tau_lambda, "1",
                  t2[1], 0, scaled, quick);
            judge("n", cr->pc[2], sc * cr->pe[2], "1", t2[2], 0, scaled, quick);
        }
        /* rate by rate against Table II's curve: the comparison that does not
           hang on a fit of six points */
        for (k = 0; k < opt.ngdot; ++k) {
            const double pt[3] = {t2[0] * p->eta, t2[1] * p->tau_lambda, t2[2]},
                         curve = carreau_eta(pt, opt.eta_inf, opt.gdot_si[k] * u->t);
            char key[40];
            snprintf(key, sizeof key, "eta_over_table2_gdot%g", opt.gdot_si[k]);
            judge(key, cr->eta[0][k] / curve, cr->err[0][k] / curve, "1", 1, 0.03,
                  "2018 Table II's Carreau curve at this rate, within 3 %", quick);
        }
    }
    judge("shear_thinning", thin, thin * hypot(cr->err[0][hi] / cr->eta[0][hi], cr->err[0][0] / cr->eta[0][0]), "1",
          NAN, 0, "eta at the fastest over the slowest rate: below 1 when the solution thins", NULL);
    if (cr->fitted)
        judge("flattening_carreau", m->vc / m->vcar_c, m->vc_err / m->vcar_c, "1", 1, 0,
              "the centre velocity of the Carreau fluid of the fit",
              cr->dep[D_PCOUNT][0] - cr->dep0[D_PCOUNT] > 3 * cr->dep[D_PCOUNT][1]
                  ? "the polymers migrate across the channel during the run (polymer_depletion against its "
                    "initial value), so the local viscosity is not the homogeneous fit's"
                  : NULL);
    verdicts_flush();
}

/* The figures in SI (micrometres, mm/s, microseconds, mPa s); the values
   they need beyond the CSV files (fit parameters, the Carreau fluid's
   profile on a fine grid) are printed into plots.gp. */
static void write_plots(const config *c, const conc_run *runs, const hcbd_hc_params *p, double Ly,
                        const units *u)
{
    const double ei = opt.eta_inf * u->eta * 1e3, W = 0.5 * Ly, um = u->len * 1e6, mm = u->v * 1e3;
    const double us = u->t * 1e6, tau_s = p->tau_lambda * u->t, eta_f = p->eta * u->eta * 1e3;
    const hcbd_hc_si t1 = hcbd_hc_si_default();
    const int ny = 121;
    char scene[400], tl[64] = "";
    double ylo = HUGE_VAL, yhi = 0, t2[3];
    FILE *f = open_out(c, "plots.gp");
    int ci, k, j;
    if (!f) return;
    if (fabs(tau_s - t1.tau_lambda) > 1e-9 * t1.tau_lambda) snprintf(tl, sizeof tl, " (Table I: %g s)", t1.tau_lambda);
    snprintf(scene, sizeof scene, "RaPiD polymer blobs in the SPH fluid: " GP_TAU "_" GP_LAMBDA " = %g s%s, "
             GP_ALPHA " = %g kT, P_0 = %.4g Pa, solvent " GP_ETA " = %g mPa s, " GP_SIGMA " = %g " GP_MU "m, "
             "no fluid fluctuations", tau_s, tl, p->alpha, p->P0 * u->P, eta_f, um);
    /* log axes: explicit ranges (graph offsets would span decades), with
       the upper decades left to the key */
    for (ci = 0; ci < opt.nconc; ++ci)
        for (j = 0; j < opt.ngdot; ++j)
            for (k = 0; k < NCOMP; ++k) {
                double e = runs[ci].eta[k][j] * u->eta * 1e3;
                if (e > 0) { ylo = fmin(ylo, e); yhi = fmax(yhi, e); }
            }
    gp_preamble(f, opt.nconc > 1 ? 820 * opt.nconc : 1250, 1100);
    fprintf(f, "scene = \"%s\"\ntau = %.17g\n", scene, tau_s);
    if (!(yhi > 0)) ylo = yhi = eta_f;
    /* ---- flow curve: the four parts, the Carreau fit with eta_inf fixed,
       and the Carreau law of 2018 Table II with lambda scaled by this
       run's tau_lambda (the quick preset shortens tau_lambda) */
    fprintf(f, "set output 'flowcurve.png'\n"
               "set multiplot layout 2,%d title \"Lees-Edwards flow curves, stress split (block errors)\\n"
               "{/*0.85 \".scene.\"}\"\n"
               "set logscale xy\nset format y '%%g'\nset xlabel 'shear rate " GP_GDOT " (1/s)'\n"
               "set ylabel 'viscosity " GP_ETA " (mPa s)'\nset key top right\n"
               "set yrange [%.6g:%.6g]\n"
               "set logscale x2\nset x2label 'Wi = " GP_GDOT GP_TAU "_" GP_LAMBDA "'\nset xtics nomirror\n"
               "set xrange [%.6g:%.6g]\nset x2range [%.6g:%.6g]\n", opt.nconc, ylo / 2, yhi * 1e5,
            opt.gdot_si[0] / 1.5, opt.gdot_si[opt.ngdot - 1] * 1.5, opt.gdot_si[0] / 1.5 * tau_s,
            opt.gdot_si[opt.ngdot - 1] * 1.5 * tau_s);
    fprintf(f, "set xtics (");
    for (j = 0; j < opt.ngdot; ++j) fprintf(f, "%s%g", j ? ", " : "", opt.gdot_si[j]);
    fprintf(f, ")\nset x2tics (");
    for (j = 0; j < opt.ngdot; ++j) fprintf(f, "%s%.3g", j ? ", " : "", opt.gdot_si[j] * tau_s);
    fprintf(f, ")\n");
    for (ci = 0; ci < opt.nconc; ++ci) {
        const conc_run *cr = &runs[ci];
        static const int pt[NCOMP] = {7, 5, 9, 11};
        if (cr->fitted)
            fprintf(f, "set title \"C = %g C*\\n{/*0.8 Carreau fit: " GP_ETA "_0 = %.3g " GP_PM " %.2g mPa s, "
                       GP_LAMBDA " = %.3g " GP_PM " %.2g s, n = %.3g " GP_PM " %.2g}\" font ',12'\n",
                    cr->C, cr->pc[0] * u->eta * 1e3, cr->pe[0] * u->eta * 1e3, cr->pc[1] * u->t, cr->pe[1] * u->t,
                    cr->pc[2], cr->pe[2]);
        else
            fprintf(f, "set title \"C = %g C*\\n{/*0.8 no Carreau fit (fewer than 4 rates, or no thinning)}\" "
                       "font ',12'\n", cr->C);
        fprintf(f, "plot ");
        for (k = 0; k < NCOMP; ++k)
            fprintf(f, "%s'flowcurve.csv' u ($1==%g&&$%d>0?$2:1/0):%d:%d w yerrorbars pt %d ps 1.3 lc %d t '%s'",
                    k ? ", " : "", cr->C, 13 + 2 * k, 13 + 2 * k, 14 + 2 * k, pt[k], k + 1, comp_name[k]);
        if (cr->fitted)
            fprintf(f, ", \\\n     " GP_CARREAU " w l lw 2 lc 1 "
                       "t 'Carreau fit of the total'", ei, cr->pc[0] * u->eta * 1e3, ei, cr->pc[1] * u->t, cr->pc[2]);
        if (table2(cr->C, t2)) {
            /* Table II with eta = 1 mPa s, scaled by this run's solvent */
            double e0 = t2[0] * eta_f, l = t2[1] * tau_s, n = t2[2], einf = 0.9 * eta_f;
            fprintf(f, ", \\\n     " GP_CARREAU " w l dt 4 lw 2 "
                       "lc 'gray30' t '2018 Table II Carreau, " GP_LAMBDA " scaled to this " GP_TAU "_" GP_LAMBDA "'",
                    einf, e0, einf, l, n);
        }
        fprintf(f, ", \\\n     %.17g w l dt 2 lc 1 t '" GP_ETA "_" GP_INF " = %g mPa s (held fixed)', "
                   "%.17g w l dt 3 lc 2 t 'solvent " GP_ETA " = %g mPa s'\n", ei, ei, eta_f, eta_f);
    }
    /* the second row: the total over Table II's Carreau curve, rate by
       rate, with its error (a log axis over seven decades hides 5 %) */
    fprintf(f, "unset logscale y\nset format y '%%.2f'\nset ylabel 'run / Table II Carreau'\n"
               "set yrange [0.85:1.15]\nset key top right\n");
    for (ci = 0; ci < opt.nconc; ++ci) {
        const conc_run *cr = &runs[ci];
        if (!table2(cr->C, t2)) {
            fprintf(f, "set title 'C = %g C*: no Table II row'\nplot 1 w l lc 'gray30' notitle\n", cr->C);
            continue;
        }
        {
            const double e0 = t2[0] * eta_f, l = t2[1] * tau_s, n = t2[2], einf = 0.9 * eta_f;
            fprintf(f, "t2c%d(x) = " GP_CARREAU "\n", ci, einf,
                    e0, einf, l, n);
            fprintf(f, "set title \"C = %g C*: total viscosity over 2018 Table II's Carreau curve\" font ',12'\n"
                       "plot 'flowcurve.csv' u ($1==%g&&$13>0?$2:1/0):($13/t2c%d($2)):($14/t2c%d($2)) w yerrorbars "
                       "pt 7 ps 1.3 lc 1 t 'this run (error from the correlation time)', 1 w l lc 'gray30' notitle, "
                       "1.03 w l dt 2 lc 'gray50' t '" GP_PM " 3 %%', 0.97 w l dt 2 lc 'gray50' notitle\n",
                    cr->C, cr->C, ci, ci);
        }
    }
    fprintf(f, "unset multiplot\nunset logscale\nunset x2tics\nunset x2label\nset xtics mirror autofreq\n"
               "set offsets 0, 0, 0, 0\nset xrange [*:*]\nset yrange [*:*]\n");
    /* ---- reverse-Poiseuille velocity: fluid and polymers against the
       Newtonian eta0 profile and the Carreau fluid of the fit */
    for (ci = 0; ci < opt.nconc; ++ci) {
        const conc_run *cr = &runs[ci];
        if (cr->fitted) {
            fprintf(f, "$carreau%d << EOD\n", ci);
            for (j = 0; j < ny; ++j) {
                double y = Ly * j / (ny - 1), yh = y >= W ? y - W : y;
                fprintf(f, "%.6g,%.6g\n", y * um,
                        (y >= W ? 1 : -1) * carreau_speed(cr->pc, opt.eta_inf, p->rho * cr->g, W, yh) * mm);
            }
            fprintf(f, "EOD\n");
        }
        if (table2(cr->C, t2)) {
            /* the Carreau fluid of Table II (lambda in units of tau_lambda)
               under the same square-wave force: the paper's CFD curve of
               Fig. 5, as a one-dimensional steady solve */
            const double pt[3] = {t2[0] * p->eta, t2[1] * p->tau_lambda, t2[2]};
            fprintf(f, "$table2carreau%d << EOD\n", ci);
            for (j = 0; j < ny; ++j) {
                double y = Ly * j / (ny - 1), yh = y >= W ? y - W : y;
                fprintf(f, "%.6g,%.6g\n", y * um,
                        (y >= W ? 1 : -1) * carreau_speed(pt, opt.eta_inf, p->rho * cr->g, W, yh) * mm);
            }
            fprintf(f, "EOD\n");
        }
    }
    fprintf(f, "set output 'velocity.png'\n"
               "set multiplot layout 1,%d title \"Reverse Poiseuille flow (+g above L_y/2, -g below), last third "
               "of the run, block errors\\n{/*0.85 \".scene.\"}\"\n"
               "set xlabel 'y (" GP_MU "m)'\nset ylabel 'v_x (mm/s)'\nset key top left\nset xrange [0:%.6g]\n"
               "set offsets 0, 0, graph 0.1, graph 0.1\n", opt.nconc, Ly * um);
    for (ci = 0; ci < opt.nconc; ++ci) {
        const conc_run *cr = &runs[ci];
        double A = cr->g / (2 * cr->eta0 / p->rho);
        fprintf(f, "set title 'C = %g C*, g = %.4g m/s^2, box %g " GP_TIMES " %g " GP_TIMES " %g " GP_SIGMA "' "
                   "font ',12'\n"
                   "plot 'profile_C%g.csv' u ($20>0?$1*%.17g:1/0):($12*%.17g):($13*%.17g) w yerrorbars pt 7 ps 1.2 "
                   "lc 1 t 'fluid v_x (slabs holding blob rows)', \\\n"
                   "     '' u ($1*%.17g):($14*%.17g):($15*%.17g) w yerrorbars pt 6 ps 1.8 lc 2 "
                   "t 'polymer drift u_x', \\\n"
                   "     (x < %.17g ? -1 : 1) * %.17g * (x < %.17g ? x : x - %.17g) * (%.17g - (x < %.17g ? x : x - "
                   "%.17g)) w l dt 2 lw 2 lc 'black' t \"Newtonian, %s = %.3g mPa s: (g/2" GP_NU "_0) y"
                   GP_PRIME "(L_y/2 - y" GP_PRIME ")\"",
                cr->C, cr->g * u->acc, p->L[0], Ly, p->L[2], cr->C, um, mm, mm, um, mm, mm, W * um, A * mm / (um * um),
                W * um, W * um, W * um, W * um, W * um,
                cr->fitted ? GP_ETA "_0" : GP_ETA "_0 (lowest rate, no fit)", cr->eta0 * u->eta * 1e3);
        fprintf(f, ", \\\n     '' u ($1*%.17g):(($14-$16)*%.17g):(sqrt($15**2+$17**2)*%.17g) w yerrorbars pt 4 "
                   "ps 1.0 lc 1 t 'fluid v(r_a) at the polymers (their slabs, as u_x)'", um, mm, mm);
        if (cr->fitted) fprintf(f, ", \\\n     $carreau%d u 1:2 w l lw 2 lc 3 t 'Carreau fluid of the fit'", ci);
        if (table2(cr->C, t2))
            fprintf(f, ", \\\n     $table2carreau%d u 1:2 w l dt 4 lw 2 lc 'gray30' t 'Carreau fluid of Table II'", ci);
        fprintf(f, ", 0 w l lc 'gray40' notitle\n");
    }
    /* ---- densities: the high-shear zones (within Ly/8 of the planes
       where g flips) shaded */
    fprintf(f, "unset multiplot\nset output 'density.png'\n"
               "set multiplot layout 1,%d title \"Densities across y over their mean, reverse Poiseuille "
               "(last third of the run)\\n{/*0.85 \".scene.\"}\"\n"
               "set ylabel 'density / mean'\nset key top center maxrows 3 font ',10'\n"
               "set offsets 0, 0, graph 0.45, graph 0.05\n"
               "set object 1 rect from first 0, graph 0 to first %.6g, graph 1 fc rgb '#fbe5cf' fs solid noborder "
               "behind\n"
               "set object 2 rect from first %.6g, graph 0 to first %.6g, graph 1 fc rgb '#fbe5cf' fs solid noborder "
               "behind\n"
               "set object 3 rect from first %.6g, graph 0 to first %.6g, graph 1 fc rgb '#fbe5cf' fs solid noborder "
               "behind\n",
            opt.nconc, Ly / 8 * um, 3 * Ly / 8 * um, 5 * Ly / 8 * um, 7 * Ly / 8 * um, Ly * um);
    for (ci = 0; ci < opt.nconc; ++ci)
        fprintf(f, "set title 'C = %g C*' font ',12'\n"
                   "plot 'profile_C%g.csv' u ($20>0?$1*%.17g:1/0):2:3 w yerrorbars pt 7 lc 1 t 'fluid n_i (kernel)', "
                   "\\\n     '' u ($1*%.17g):4:5 w yerrorlines pt 6 lc 2 t 'polymer n_a (kernel)', "
                   "'' u ($1*%.17g):6 w l dt 3 lw 2 lc 2 t 'polymer n_a, t = 0', \\\n"
                   "     '' u ($1*%.17g):9:10 w yerrorlines pt 1 lc 4 t 'polymer counts', "
                   "'' u ($1*%.17g):11 w l dt 3 lw 2 lc 4 t 'polymer counts, t = 0', \\\n"
                   "     NaN w filledcurves fc rgb '#fbe5cf' t 'high shear (< L_y/8 from a plane)', "
                   "1 w l dt 2 lc 'black' notitle\n",
                runs[ci].C, runs[ci].C, um, um, um, um, um);
    fprintf(f, "unset multiplot\nunset object 1\nunset object 2\nunset object 3\nset offsets 0, 0, 0, 0\n");
    /* ---- start-up of the reverse-Poiseuille flow; the profiles are
       averaged over the shaded window */
    fprintf(f, "set output 'rp_start.png'\nset xrange [*:*]\n"
               "set multiplot layout 1,%d title \"Start-up of the reverse Poiseuille flow: centre velocity (mean "
               "within L_y/8 of y = L_y/4, 3L_y/4)\\n{/*0.85 \".scene.\"}\"\n"
               "set xlabel 't (" GP_MU "s)'\nset ylabel 'centre velocity (mm/s)'\n"
               "set key bottom right maxrows auto font ',11'\n"
               "set offsets 0, 0, graph 0.1, 0\nset yrange [0:*]\n", opt.nconc);
    for (ci = 0; ci < opt.nconc; ++ci) {
        const conc_run *cr = &runs[ci];
        double t0 = cr->ts_from < cr->nts ? cr->ts[cr->ts_from][0] * us : 0;
        fprintf(f, "set title 'C = %g C*' font ',12'\n"
                   "set object 1 rect from first %.6g, graph 0 to graph 1, graph 1 fc rgb '#e4ecf7' fs solid noborder "
                   "behind\n"
                   "plot NaN w filledcurves fc rgb '#e4ecf7' t 'measured window (profiles)', "
                   "'rp_start_C%g.csv' u ($1*%.17g):($3*%.17g) w l lw 2 lc 1 t 'fluid', "
                   "'' u ($1*%.17g):($4*%.17g) w l lw 2 lc 2 t 'polymer', \\\n"
                   "     %.17g w l dt 2 lw 2 lc 'black' t 'Newtonian, " GP_ETA "_0 (steady)'",
                cr->C, t0, cr->C, us, mm, us, mm,
                newton_speed(cr->g, cr->eta0 / p->rho, W, 0.5 * W) * mm);
        if (cr->fitted)
            fprintf(f, ", %.17g w l lw 2 lc 3 t 'Carreau fluid of the fit (steady)'",
                    carreau_speed(cr->pc, opt.eta_inf, p->rho * cr->g, W, 0.5 * W) * mm);
        fprintf(f, "\n");
    }
    fprintf(f, "unset multiplot\nunset object 1\n");
    if (opt.plateau) { /* ---- the Lees-Edwards start-ups */
        fprintf(f, "set output 'startup.png'\nset xrange [0:*]\nset yrange [*:*]\n"
                   "set multiplot layout 1,%d title \"Lees-Edwards start-up: the total viscosity of each half "
                   "block over the measured mean (start-up: points; measured: line)\\n{/*0.85 \".scene.\"}\"\n"
                   "set xlabel 't / " GP_TAU "_" GP_LAMBDA "'\nset ylabel '" GP_ETA " / " GP_ETA
                   " (measured)'\nset key bottom right font ',11'\n", opt.nconc);
        for (ci = 0; ci < opt.nconc; ++ci) {
            int r;
            fprintf(f, "set title 'C = %g C*' font ',12'\nplot 1 w l dt 2 lc 'black' notitle", runs[ci].C);
            for (r = 0; r < opt.ngdot; ++r)
                fprintf(f, ", 'startup_C%g.csv' u ($1 == %g && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc %d "
                           "t 'Wi = %g', '' u ($1 == %g && $5 == 1 ? $2 : NaN):4 w l lw 2 lc %d notitle",
                        runs[ci].C, opt.gdot_si[r] * opt.tau_si, r + 1, opt.gdot_si[r] * opt.tau_si,
                        opt.gdot_si[r] * opt.tau_si, r + 1);
            fprintf(f, "\n");
        }
        fprintf(f, "unset multiplot\n");
    }
    fclose(f);
    make_figures(c);
}

/* startup_C<C>.csv: each Lees-Edwards run's total viscosity in half
   blocks, through its start-up (phase 0) and measured blocks (phase 1). */
static void write_startups(const config *c, const conc_run *cr, const hcbd_hc_params *p, const units *u)
{
    char name[64];
    FILE *f;
    int r, k;
    if (!opt.plateau) return;
    snprintf(name, sizeof name, "startup_C%g.csv", cr->C);
    if (!(f = open_out(c, name))) return;
    fprintf(f, "Wi,t_over_tau_lambda,eta_mPas,eta_over_measured,phase\n");
    for (r = 0; r < opt.ngdot; ++r) {
        const double bt = half_steps(p) * p->dt / p->tau_lambda;
        double t = 0;
        for (k = 0; k < cr->nser[r]; ++k) {
            const double w = k < cr->nser_up[r] ? bt : ((k - cr->nser_up[r]) % 2 ? opt.block_tau - bt : bt);
            fprintf(f, "%g,%.5g,%.6g,%.6g,%d\n", opt.gdot_si[r] * opt.tau_si, t + 0.5 * w,
                    cr->series[r][k] * u->eta * 1e3, cr->series[r][k] / cr->eta[0][r], k >= cr->nser_up[r]);
            t += w;
        }
    }
    fclose(f);
}

/* What one queued run needs of main's state; each job writes only its own slots. */
typedef struct {
    const hcbd_hc_params *p, *prp;
    conc_run *runs;
    const units *u;
    double gmax, *dp, *dscale;
    int nmom, *shear_done;
    uint64_t (*sum_shear)[MAXG], *sum_rp, *sum_mom;
} job_ctx;

/* Queue entry q: q >= 0 a shear run (concentration q / MAXG, rate q % MAXG), -1 - ci the
   reverse-Poiseuille run of concentration ci once its shear runs are done, -1 - MAXC the
   momentum run. */
static void run_job(const job_ctx *j, int q)
{
    int ok;
    if (q >= 0) {
        ok = shear_run(j->p, &j->runs[q / MAXG], q % MAXG, opt.gdot_si[q % MAXG] * j->u->t, &j->sum_shear[q / MAXG][q % MAXG]);
    } else if (q > -1 - MAXC) {
        conc_run *cr = &j->runs[-1 - q];
        hcbd_hc_params q_rp = *j->prp;
        int ready = 0, stop = 0;
        while (!ready && !stop) {
            PROGRESS_LOCK
            {
                ready = j->shear_done[-1 - q];
                stop = prog.failed;
            }
            if (!ready && !stop) sleep_s(0.05);
        }
        ok = 0;
        if (ready) {
            /* the stress at the edges of the halves, rho g Ly / 4, is
               the one measured at the fastest rate: the profile spans
               the flow curve */
            cr->g = opt.g_si > 0 ? opt.g_si / j->u->acc
                                 : 4 * cr->eta[0][opt.ngdot - 1] * j->gmax / (j->p->rho * j->prp->L[1]);
            q_rp.reverse_poiseuille = 1;
            q_rp.g[0] = cr->g;
            PROGRESS_LOCK
            print_limits(&q_rp);
            ok = rp_run(j->prp, cr, &j->sum_rp[-1 - q]);
        }
    } else {
        ok = momentum_run(j->p, j->runs[j->nmom].np, j->dp, j->dscale, j->sum_mom);
    }
    PROGRESS_LOCK
    {
        if (!ok) prog.failed = 1;
        if (q >= 0 && q % MAXG == opt.ngdot - 1) j->shear_done[q / MAXG] = 1;
    }
}

int main(int argc, char **argv)
{
    static conc_run runs[MAXC];
    config c;
    const hcbd_hc_si si1 = hcbd_hc_si_default();
    hcbd_hc_params tab, par, prp, *p = &par;
    hcbd_hc_theory th;
    units u, ut;
    char msg[256];
    uint64_t checksum = 0, sum_shear[MAXC][MAXG], sum_rp[MAXC], sum_mom = 0;
    double gmax = 0, mach, dp = 0, dscale = 0;
    int paper = 0, k, r, ci, nmom, njob, jobs, queue[MAXC * (MAXG + 1) + 1], shear_done[MAXC] = {0};

    memset(&c, 0, sizeof c);
    c.name = "hcbd_polymer";
    c.def = hcbd_world_def_default(); /* carries seed and threads from parse_args */
    c.N = 2;
    c.density = 1;
    c.steps = 1000;
    if (!expand_args(&c, &argc, &argv)) return 2;
    for (k = 1; k < argc; ++k) /* the preset first: explicit keys override it */
        if (!strcmp(argv[k], "preset=paper") || !strcmp(argv[k], "preset=paper-long"))
            paper = 1 + !strcmp(argv[k], "preset=paper-long");
    si = si1;
    opt.time_unit = 1e-6;
    opt.conc[0] = 2.5;
    opt.conc[1] = 5;
    opt.nconc = 2;
    if (paper) {
        static const double gp[6] = {0.1, 0.3, 1, 3, 10, 30};
        memcpy(opt.gdot_si, gp, sizeof gp);
        opt.ngdot = 6;
        opt.tau_si = si.tau_lambda;
        opt.P0_si = si.P0;
        opt.L[0] = opt.L[1] = opt.L[2] = 10;
        si.dt = PAPER_DT;
        opt.le_steps = 3000000; /* used only with plateau=0 */
        opt.rp_steps = (int)floor(5 * si.tau_lambda / PAPER_DT + 0.5);
        opt.eq_steps = 1000;
        opt.nblk = 4;
        /* the paper's own schemes: without fluid fluctuations the Euler pairs
           are converged at the preset's fluid step, the sweep 2.5 % short
           (C2, Wi = 1: bench/results/table2_departures), and the raw weights
           are what Table II was run with (docs/VALIDATION.md "Table II") */
        opt.coupling = HCBD_COUPLE_RAW;
        opt.pair_euler = 1;
    } else {
        static const double gq[4] = {1000, 2154, 4642, 10000};
        memcpy(opt.gdot_si, gq, sizeof gq);
        opt.ngdot = 4;
        opt.tau_si = 2e-4;
        opt.P0_si = 0; /* c_s = 2 m/s, set once rho is known */
        opt.L[0] = opt.L[1] = opt.L[2] = 8;
        opt.le_steps = opt.rp_steps = 600;
        opt.eq_steps = 100;
        opt.nblk = 5;
    }
    opt.nslab = 18;
    opt.eta_inf_mpas = 0.9;
    opt.substeps = paper ? PAPER_SUBSTEPS : 1;
    opt.plateau = paper;
    opt.block_tau = 1;
    opt.startup_max = paper ? 64 : 8;
    /* issue 41: at Wi = 0.1 the stress still grows until a strain of about
       2.4 (bench/results/paper_long), and it stays correlated over 1.5-2.5
       tau_lambda */
    opt.startup_strain = paper ? 3 : 0;
    opt.startup_corr = paper ? 6 : 0;
    opt.measure_strain = paper == 2 ? 2 : 0;
    opt.startup_tol = 0.005;
    opt.startup_lambda = 3;
    snprintf(c.out, sizeof c.out, "out/hcbd_polymer");
    if (!parse_args(argc, argv, &c, own_key, usage)) return c.help ? 0 : 2;
    for (k = 1; k < opt.ngdot; ++k) /* ascending: the summary compares the ends */
        for (r = k; r > 0 && opt.gdot_si[r] < opt.gdot_si[r - 1]; --r) {
            double t = opt.gdot_si[r];
            opt.gdot_si[r] = opt.gdot_si[r - 1];
            opt.gdot_si[r - 1] = t;
        }
    if (!(opt.P0_si > 0)) opt.P0_si = si.rho * 2.0 * 2.0 / 7;
    if (!opt.alpha_given) opt.alpha = si.alpha_kT * si.tau_lambda / opt.tau_si;
    if ((opt.le_steps - 2 * opt.le_steps / 3) / opt.nblk < 1) {
        fprintf(stderr, "hcbd_polymer: le_steps=%d is too short for %d blocks\n", opt.le_steps, opt.nblk);
        return 2;
    }

    /* ---- units and parameters ---- */
    if (hcbd_hc_si_params(&si, opt.time_unit, &par, msg, sizeof msg) != HCBD_OK ||
        hcbd_hc_si_params(&si1, opt.time_unit, &tab, msg, sizeof msg) != HCBD_OK) {
        fprintf(stderr, "hcbd_polymer: %s\n", msg);
        return 2;
    }
    set_units(&u, &si, opt.time_unit);
    set_units(&ut, &si1, opt.time_unit);
    opt.eta_inf = opt.eta_inf_mpas * 1e-3 / u.eta;
    memcpy(p->L, opt.L, sizeof opt.L);
    p->fluctuations = 0; /* the paper's choice with polymers present (sec. IV A 3) */
    p->P0 = opt.P0_si / u.P;
    p->tau_lambda = opt.tau_si / u.t;
    p->alpha = opt.alpha;
    p->substeps = opt.substeps;
    p->coupling = (hcbd_coupling)opt.coupling;
    p->pair_integrator = opt.pair_euler ? HCBD_PAIR_EULER : HCBD_PAIR_SHARDLOW;
    p->seed = c.def.params.seed;
    /* independent runs side by side scale better than one run's threads
       (1.4x on two cores at Table I); thermo lines would interleave */
    jobs = opt.jobs > 0 ? opt.jobs : c.def.params.threads;
    if (c.thermo_every > 0) jobs = 1;
    if (jobs > opt.nconc * opt.ngdot) jobs = opt.nconc * opt.ngdot;
    p->threads = c.def.params.threads / jobs > 1 ? c.def.params.threads / jobs : 1;
    if (hcbd_hc_params_check(p, msg, sizeof msg) != HCBD_OK) {
        fprintf(stderr, "hcbd_polymer: %s\n", msg);
        return 2;
    }
    hcbd_hc_params_theory(p, &th);
    prp = par;
    if (!rp_height(p, &prp.L[1])) return 2;
    for (ci = 0; ci < opt.nconc; ++ci) {
        runs[ci].C = opt.conc[ci];
        runs[ci].np = polymers_in(p, opt.conc[ci]);
        runs[ci].np_rp = polymers_in(&prp, opt.conc[ci]);
    }
    for (r = 0; r < opt.ngdot; ++r) gmax = fmax(gmax, opt.gdot_si[r] * u.t);
    mach = gmax * p->L[1] / th.cs;
    mkdirs(c.out);
    write_run_conf(&c);

    printf("hcbd_polymer: HCBD polymer solutions (2018 sec. IV B), preset %s, box %.4g x %.4g x %.4g sigma "
           "(reverse Poiseuille %.4g x %.4g x %.4g), fluid blobs %d (%d), polymers", paper == 2 ? "paper-long" : paper ? "paper" : "quick",
           p->L[0], p->L[1], p->L[2], prp.L[0], prp.L[1], prp.L[2], blobs_in(p), blobs_in(&prp));
    for (ci = 0; ci < opt.nconc; ++ci) printf(" %d (%d) at C = %g C*", runs[ci].np, runs[ci].np_rp, runs[ci].C);
    printf(", threads = %d (%d run%s at a time, %d thread%s each), seed = %llu\n", c.def.params.threads, jobs,
           jobs > 1 ? "s" : "", p->threads, p->threads > 1 ? "s" : "", (unsigned long long)p->seed);
    printf("# reduced units: sigma = %g m, kT = %.6g J (T = %g K), time unit = %g s, mass unit "
           "kT t^2/sigma^2 = %.6g kg\n", u.len, u.kT, si.T, u.t, u.M);
    print_parameters(&u, p, &ut, &tab);
    printf("# derived: blob mass m = %.6g (%.4g kg), nu = eta/rho = %.6g, c_s = %.6g (%.4g m/s; Table I "
           "%.4g m/s), dt limits: viscous %.4g, sound %.4g (dt = %g)\n", th.m, th.m * u.M, th.nu, th.cs,
           th.cs * u.v, sqrt(7 * si.P0 / si.rho), th.dt_visc, th.dt_sound, p->dt);
    printf("# kT = %g for the polymer noise and pair variables; fluid fluctuations off (as in the paper with "
           "polymers); fluid start: %s\n", p->kT,
           opt.fluid_random ? "disordered (fluid_start=random)" : "a lattice (fluid_start=lattice)");
    printf("# schemes: polymer-fluid weights %s, fluid pairs %s\n",
           opt.coupling == HCBD_COUPLE_RAW ? "w/n_i as the paper's (coupling=raw; momentum not exact)"
                                           : "Shepard-normalised (coupling=shepard; momentum exact)",
           opt.pair_euler ? "explicit Euler as the paper's (pair=euler)" : "the exact sweep (pair=shardlow)");
    if (fabs(p->tau_lambda - tab.tau_lambda) > 1e-12 * tab.tau_lambda)
        printf("# NOTE tau_lambda = %g s = %g steps here; the paper's is %g s = %g steps\n", opt.tau_si,
               p->tau_lambda / p->dt, si.tau_lambda, tab.tau_lambda / p->dt);
    if (fabs(p->alpha - tab.alpha) > 1e-12 * tab.alpha)
        printf("# NOTE alpha = %g kT (paper %g kT)%s\n", p->alpha, si.alpha_kT,
               opt.alpha_given ? "" : ": scaled with 1/tau_lambda to keep the polymer viscosity ~ alpha tau_lambda");
    if (fabs(p->dt - tab.dt) > 1e-12 * tab.dt)
        printf("# NOTE dt = %g s (Table I %g s), the fluid in %d sub-steps of %g s%s\n", si.dt, si1.dt, p->substeps,
               si.dt / p->substeps, paper && fabs(si.dt - PAPER_DT) < 1e-15
                   ? ": eta within 1 % of a resolved step (+0.8 +- 0.4 % at Wi = 0.3, less above; "
                     "bench/wp_table1.c), where 10^6 steps per tau_lambda would take a week"
                   : "");
    if (fabs(p->P0 - tab.P0) > 1e-12 * tab.P0)
        printf("# NOTE P0 = %g Pa (Table I %g Pa): c_s = %.4g m/s keeps the fastest shear at Mach %.3g\n",
               opt.P0_si, si.P0, th.cs * u.v, mach);
    printf("# shear rates [1/s] (Wi = gdot tau_lambda):");
    for (r = 0; r < opt.ngdot; ++r) printf(" %g (%.3g)", opt.gdot_si[r], opt.gdot_si[r] * opt.tau_si);
    printf("; Mach gdot_max Ly / c_s = %.3g\n", mach);
    if (opt.plateau)
        printf("# runs per concentration: Lees-Edwards x %d rates, each a start-up of at least 4 x %g tau_lambda / "
               "(1 + %g Wi), a strain of %g and %g correlation times of the stress, then until its fitted stress "
               "growth would shift the mean by less than %g (3..%d blocks), then %d blocks of %g tau_lambda (%d "
               "steps) and more until a strain of %g; reverse Poiseuille %d steps; equilibrium %d steps; %d slabs\n",
               opt.ngdot, opt.startup_lambda, opt.startup_lambda, opt.startup_strain, opt.startup_corr,
               opt.startup_tol, opt.startup_max, opt.nblk, opt.block_tau, block_steps(p), opt.measure_strain,
               opt.rp_steps, opt.eq_steps, opt.nslab);
    else
        printf("# runs per concentration: Lees-Edwards %d steps (%.3g tau_lambda) x %d rates, reverse Poiseuille "
               "%d steps; equilibrium %d steps; %d blocks, %d slabs\n", opt.le_steps,
               opt.le_steps * p->dt / p->tau_lambda, opt.ngdot, opt.rp_steps, opt.eq_steps, opt.nblk, opt.nslab);
    if (p->dt / p->substeps > 1.0001 * th.dt_sound || p->dt / p->substeps > 1.0001 * th.dt_visc)
        printf("# warning: the fluid step %g is not below the explicit limits (sound %.4g, viscous %.4g)\n",
               p->dt / p->substeps, th.dt_sound, th.dt_visc);
    if (mach > 0.3) printf("# warning: Mach %.3g: the fastest shear is not well below the sound speed\n", mach);
    fflush(stdout);

    /* ---- the runs ---- */
    prog.c = &c;
    if (c.restart[0] && !hc_restart(&c, &rst)) return 2;
    /* with plateau=1 the start-up is a guess: its least strain, or 5 blocks */
    prog.total = (int64_t)opt.nconc * opt.rp_steps + opt.eq_steps;
    for (r = 0; r < opt.ngdot; ++r) {
        const double wi = opt.gdot_si[r] * opt.tau_si;
        double up = 5, me = opt.nblk;
        if (opt.plateau && opt.startup_strain / wi > up) up = opt.startup_strain / wi;
        if (opt.plateau && opt.measure_strain / wi > me) me = opt.measure_strain / wi;
        prog.total += (int64_t)opt.nconc * (opt.plateau ? (int64_t)((up + me) * block_steps(p)) : opt.le_steps);
    }
    for (r = 0; r < opt.ngdot; ++r) { /* before the runs, which may overlap */
        hcbd_hc_params q = *p;
        q.gdot = opt.gdot_si[r] * u.t;
        print_limits(&q);
    }
    fflush(stdout);
    clock_gettime(CLOCK_MONOTONIC, &prog.t0);
    prog.last = prog.t0;
    nmom = opt.nconc - 1;
    for (ci = 0; ci < opt.nconc; ++ci)
        if (runs[ci].C > runs[nmom].C) nmom = ci;
    /* One queue of runs, the longest first so that the last to end is
       short: the fastest rate of each concentration (its reverse-Poiseuille
       run takes g from it), then the slower rates, the higher
       concentration first, the reverse-Poiseuille runs before the two
       fastest rates' neighbours, the momentum run last.  A run whose input
       is not ready waits for it. */
    njob = 0;
    for (ci = opt.nconc - 1; ci >= 0; --ci) queue[njob++] = ci * MAXG + opt.ngdot - 1;
    for (r = 0; r < opt.ngdot - 1; ++r) {
        if (r == opt.ngdot - 2 && r > 0)
            for (ci = opt.nconc - 1; ci >= 0; --ci) queue[njob++] = -1 - ci;
        for (ci = opt.nconc - 1; ci >= 0; --ci) queue[njob++] = ci * MAXG + r;
    }
    if (opt.ngdot < 3)
        for (ci = opt.nconc - 1; ci >= 0; --ci) queue[njob++] = -1 - ci;
    queue[njob++] = -1 - MAXC; /* momentum */
    {
        const job_ctx jc = {p, &prp, runs, &u, gmax, &dp, &dscale, nmom, shear_done, sum_shear, sum_rp, &sum_mom};
#ifdef _OPENMP
        /* one run at a time takes no enclosing region: libgomp starts fresh threads for
           every team nested in one, which made a single rate 5x slower with threads=2 */
        if (jobs > 1) {
            if (p->threads > 1) omp_set_max_active_levels(2);
#pragma omp parallel for schedule(dynamic, 1) num_threads(jobs)
            for (k = 0; k < njob; ++k) run_job(&jc, queue[k]);
        } else
#endif
            for (k = 0; k < njob; ++k) run_job(&jc, queue[k]);
    }
    if (prog.failed) return 1;
    for (ci = 0; ci < opt.nconc; ++ci) {
        conc_run *cr = &runs[ci];
        double e[MAXG], g_red[MAXG];
        for (r = 0; r < opt.ngdot; ++r) {
            g_red[r] = opt.gdot_si[r] * u.t;
            e[r] = cr->err[0][r] > 0 ? cr->err[0][r] : 1e-12 * fabs(cr->eta[0][r]);
        }
        cr->fitted = opt.ngdot >= 4 &&
                     hcbd_carreau_fit(g_red, cr->eta[0], e, opt.ngdot, opt.eta_inf, 0, cr->pc, cr->pe, &cr->chi2) ==
                         HCBD_OK &&
                     cr->pc[0] > opt.eta_inf && cr->pc[1] > 0 && cr->pc[2] >= 0;
        /* the fit's eta0 where it is usable, else the slowest rate's viscosity */
        cr->eta0 = cr->fitted ? cr->pc[0] : cr->eta[0][0];
    }
    for (ci = 0; ci < opt.nconc; ++ci) {
        for (r = 0; r < opt.ngdot; ++r) mix_checksum(&checksum, sum_shear[ci][r]);
        mix_checksum(&checksum, sum_rp[ci]);
    }
    mix_checksum(&checksum, sum_mom);
    report_progress(1);

    /* ---- output ---- */
    write_flowcurve(&c, runs, &u);
    for (ci = 0; ci < opt.nconc; ++ci) {
        rp_metrics m;
        rp_analyse(&runs[ci], &prp, &m);
        write_profiles(&c, &runs[ci], &prp, &m, &u);
        write_startups(&c, &runs[ci], p, &u);
        print_summary(&runs[ci], p, &m, &u, mach, prp.L[1]);
    }
    printf("# summary (all runs; momentum: equilibrium run at C = %g C*)\n", runs[nmom].C);
    printf("momentum_drift=%.3g\nmomentum_change=%.3g\nmomentum_scale=%.4g\n", dscale > 0 ? dp / dscale : 0, dp,
           dscale);
    printf("run_time_s=%.1f\n", seconds_since(&prog.t0));
    printf("state_checksum=%016llx\n", (unsigned long long)checksum);
    judge("momentum_drift", dscale > 0 ? dp / dscale : 0, NAN, "1", 0, 1e-12, "exact momentum conservation (round-off)",
          opt.coupling == HCBD_COUPLE_RAW ? "coupling=raw: the paper's weights w/n_i do not sum to one over a "
                                            "polymer's blobs, so the redistribution does not conserve momentum "
                                            "(MODEL 7)" : NULL);
    fflush(stdout);
    write_plots(&c, runs, &prp, prp.L[1], &u);
    summary_end(&c, 1);
    free(rst.fluid);
    free(rst.poly);
    return 0;
}
