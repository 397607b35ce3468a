/* channel_flow: gravity-driven flow of a star-polymer fluid between two
   solid walls with GI-BD (Ahuja et al. 2016, sec. II C and IV C, Fig. 6).

   The box is periodic; walls normal to y fill 1.5 sigma at the bottom and
   the top with artificial particles redrawn every step, which hold the
   background velocity with Morris no-slip velocities (MODEL.md 4).  A body
   force g per unit mass along x drives the flow.  For each xi'/xi the run
   accumulates slab profiles (26 slabs over the box height by default) of
   the number density, the mean background velocity and the temperature
   (from the velocity variance), with block errors.

   What to look for: layering of the stars next to the walls; a smooth,
   near-parabolic velocity profile (for stars flatter than the Newtonian
   parabola, because the fluid thins under shear); a flat temperature, also
   next to the walls.  As in the paper, g is held fixed (F = m g grows
   with m = xi' tau), so the Newtonian estimate is the same for every xi';
   the stars' share of the viscosity falls as xi'/xi grows, and the profile
   rises towards the background's parabola.  With potential=ideal the profile is Newtonian:
   compare v_max_measured with v_max_newtonian, which uses the mean-field
   nu = Rc^2/(28 tau) (the measured viscosity of ideal carriers is lower,
   see docs/GUIDE.md).  wall=gauss (the paper's repulsion) depletes the fluid next
   to the walls and the flow slips; wall=reflect or wall=noslip remove the
   slip.

   Writes profile_xip<x>.csv for each xi'/xi and plots.gp (profiles.png with
   gnuplot); a summary per xi'/xi on stdout. */
#include "example_common.h"

#define MAXX 8

static double xips[MAXX];
static int nxip, nslab = 26;
static double wall_t = 1.5, g_force = 133.4, beta_max = 0, shift = HCBD_AUTO;
static int wall_mode = HCBD_WALL_GAUSS, bg_only = 0;

static void usage(FILE *f)
{
    fprintf(f,
            "usage: channel_flow [key=value ...]\n"
            "  preset=quick|paper  quick (default): 40000 steps per run; paper: 1000000\n"
            "  xip=a,b,...         background frictions xi' (xi = 1): default 1,2,5\n"
            "  g=133.4             body force per unit mass along x (F = m g)\n"
            "  wall=gauss|reflect|noslip  wall_thickness=1.5  slabs=26  beta_max=1.5 (5 for noslip)\n"
            "  wall_shift=x         noslip: Morris plane x in front of the interface\n"
            "                      (default: the Boltzmann depletion width)\n"
            "  body=both|background  the body force drives particles and background, or\n"
            "                      the background only\n"
            "  density dt kT xi tau Rc f sigma rcut skin Lx Ly Lz potential=star|ideal\n"
            "  density_norm=2014|2016 noise=gauss|uniform pair=shardlow|euler\n"
            "  brownian=lm|euler seed steps threads out\n"
            "  (N follows from the density and the channel volume)\n"
            "  xyz=FILE xyz_every=k thermo_every=k checkpoint=FILE  run output, one file per\n"
            "                      run (FILE.<run>.ext) when there are several\n"
            "  restart=FILE        continue one run from a checkpoint (its parameters)\n");
}

static int own_key(config *c, const char *key, const char *v)
{
    if (!strcmp(key, "preset")) return check_preset(c, v);
    if (!strcmp(key, "xip")) return (nxip = parse_list(c, key, v, xips, MAXX)) > 0;
    if (!strcmp(key, "g")) return parse_double(c, key, v, &g_force);
    if (!strcmp(key, "wall_thickness")) return parse_double(c, key, v, &wall_t);
    if (!strcmp(key, "beta_max")) return parse_double(c, key, v, &beta_max);
    if (!strcmp(key, "wall_shift")) return parse_double(c, key, v, &shift);
    if (!strcmp(key, "slabs")) {
        if (!parse_int(c, key, v, &nslab)) return 0;
        if (nslab < 4 || nslab > 10000) {
            fprintf(stderr, "channel_flow: slabs=%d must be 4..10000\n", nslab);
            return 0;
        }
        return 1;
    }
    if (!strcmp(key, "wall")) {
        if (!strcmp(v, "gauss")) wall_mode = HCBD_WALL_GAUSS;
        else if (!strcmp(v, "reflect")) wall_mode = HCBD_WALL_REFLECT;
        else if (!strcmp(v, "noslip")) wall_mode = HCBD_WALL_NOSLIP;
        else {
            fprintf(stderr, "channel_flow: wall=%s is not gauss, reflect or noslip\n", v);
            return 0;
        }
        return 1;
    }
    if (!strcmp(key, "body")) return parse_choice(c, key, v, "both", "background", &bg_only, 0, 1);
    if (!strcmp(key, "N")) {
        fprintf(stderr, "channel_flow: N follows from density and the channel volume\n");
        return 0;
    }
    if (!strcmp(key, "dynamics")) {
        fprintf(stderr, "channel_flow: dynamics is GI-BD (classical BD carries no background flow)\n");
        return 0;
    }
    return -1;
}

/* Least-squares parabola v = a + b y + c y^2 through the profile points
   with weights 1/err^2; C its covariance (the inverse normal matrix). */
static int fit_parabola(const double *y, const double *v, const double *e, int n, double q[3],
                        double C[9])
{
    double A[9] = {0}, r[3] = {0}, det;
    int k, i, j;
    for (k = 0; k < n; ++k) {
        double b[3] = {1.0, y[k], y[k] * y[k]}, wt = e[k] > 0 ? 1.0 / (e[k] * e[k]) : 1.0;
        for (i = 0; i < 3; ++i) {
            r[i] += wt * b[i] * v[k];
            for (j = 0; j < 3; ++j) A[3 * i + j] += wt * b[i] * b[j];
        }
    }
    det = A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
          A[2] * (A[3] * A[7] - A[4] * A[6]);
    if (n < 3 || det == 0.0) return 0;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) { /* adjugate: cofactor of A[j][i] */
            int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
            C[3 * i + j] = (A[3 * r0 + c0] * A[3 * r1 + c1] - A[3 * r0 + c1] * A[3 * r1 + c0]) / det;
        }
    for (i = 0; i < 3; ++i) q[i] = C[3 * i] * r[0] + C[3 * i + 1] * r[1] + C[3 * i + 2] * r[2];
    return 1;
}

/* sqrt(g C g): standard error of a linear function g.q of the fit */
static double fit_err(const double C[9], const double g[3])
{
    double s = 0;
    int i, j;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) s += g[i] * C[3 * i + j] * g[j];
    return sqrt(fmax(s, 0));
}

int main(int argc, char **argv)
{
    config c;
    hcbd_params *p;
    hcbd_theory th;
    uint64_t checksum = 0;
    int k, r, paper = 0, start, nblk = 20;
    double fig_q[MAXX][3], fig_vmax[MAXX][3]; /* for the figure: the fit, v_max +- err, Newtonian v_max */
    struct timespec t0;
    FILE *f;

    memset(&c, 0, sizeof c);
    c.name = "channel_flow";
    c.def = hcbd_world_def_default();
    c.def.params.tau = 3e-3; /* 2016 sec. IV C */
    c.N = 2;
    c.density = 0.24;
    c.L[0] = c.L[1] = c.L[2] = 13.0;
    c.box_given = 7;
    if (!expand_args(&c, &argc, &argv)) return 2;
    for (k = 1; k < argc; ++k)
        if (!strcmp(argv[k], "preset=paper")) paper = 1;
    c.steps = paper ? 1000000 : 40000;
    xips[0] = 1; xips[1] = 2; xips[2] = 5;
    nxip = 3;
    snprintf(c.out, sizeof c.out, "out/channel_flow");
    if (!parse_args(argc, argv, &c, own_key, usage)) return c.help ? 0 : 2;
    p = &c.def.params;
    p->wall.thickness = wall_t;
    p->wall.mode = (hcbd_wall_mode)wall_mode;
    /* the no-slip mode needs a firmer grip on the particles next to the
       Morris plane than the paper's cap (docs/GUIDE.md) */
    p->wall.beta_max = beta_max > 0 ? beta_max : (wall_mode == HCBD_WALL_NOSLIP ? 5.0 : 1.5);
    p->wall.shift = shift;
    p->fext_background_only = bg_only;
    c.N = (int)floor(c.density * p->L[0] * (p->L[1] - 2 * wall_t) * p->L[2] + 0.5);
    c.def.capacity = c.N < 2 ? 2 : c.N;
    if (c.restart[0]) nxip = 1; /* one run, with the checkpoint's xi' and flow */
    mkdirs(c.out);
    write_run_conf(&c);
    printf("channel_flow: GI-BD %s, N = %d real particles, box %.3g x %.3g x %.3g, walls %.3g thick "
           "(%s), n# = %g, dt = %g, tau = %g, g = %g (body force on %s), %d steps per run\n",
           p->potential == HCBD_POT_STAR ? "star polymers" : "ideal particles", c.N, p->L[0],
           p->L[1], p->L[2], wall_t,
           wall_mode == HCBD_WALL_GAUSS ? "Gaussian repulsion" :
           wall_mode == HCBD_WALL_REFLECT ? "reflecting" : "no-slip at the interface",
           c.density, p->dt, p->tau, g_force, bg_only ? "the background only" : "particles and background",
           c.steps);
    fflush(stdout);
    start = c.steps / 5; /* the flow develops in ~W^2/nu; stars layer at the walls */
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (r = 0; r < nxip; ++r) {
        hcbd_world w;
        run_out ro;
        char label[32];
        hcbd_profile prof;
        double *mem, *out, ys[10000], vs[10000], es[10000], q[3] = {0, 0, 0}, C[9] = {0};
        double gv[3], gs[3], vmax_err, slip_err;
        double lo, hi, nbulk = 0, nbulk_e2 = 0, tc_e2 = 0, tc_err, tc = 0, vmax, slip = 0, slope, dep = 0, dep_err, tdev = 0, meanc = 0;
        int nint = 0, ncen = 0, s, nc = 0, nsamp = (c.steps - start) / 10;
        /* the carriers' mean x velocity in 10 blocks of the samples */
        double vb[10] = {0}, vmean = 0, vmean_err = 0;
        int nvb[10] = {0};
        int64_t pen;
        size_t bytes = hcbd_profile_bytes(nslab);
        p->xip = xips[r];
        p->fext[0] = g_force * p->xip * p->tau; /* F = m g, m = xi' tau */
        print_limits(p);
        if (!world_start(&c, &w)) return 2;
        if (c.restart[0]) xips[r] = p->xip; /* the checkpoint's parameters, its flow developed */
        hcbd_params_theory(p, &th);
        mem = (double *)malloc(bytes);
        out = (double *)malloc((size_t)nslab * 8 * sizeof(double));
        if (!mem || !out || (!c.restart[0] && hcbd_world_place_lattice(&w, c.N) != HCBD_OK) ||
            hcbd_profile_init(&prof, &w, nslab, (c.steps - start) / (10 * nblk), mem, bytes) != HCBD_OK) {
            fprintf(stderr, "channel_flow: set-up failed: %s\n", w.err.msg);
            return 2;
        }
        snprintf(label, sizeof label, "xip%g", xips[r]);
        if (!run_out_open(&c, &ro, &w, nxip > 1 ? label : NULL)) return 2;
        if (run_steps(&c, &ro, &w, c.restart[0] ? 0 : start) != HCBD_OK) {
            fprintf(stderr, "channel_flow: xip = %g: %s\n", xips[r], w.err.msg);
            return 1;
        }
        for (k = 0; k < (c.steps - start) / 10; ++k) {
            if (run_steps(&c, &ro, &w, 10) != HCBD_OK) {
                fprintf(stderr, "channel_flow: xip = %g: %s\n", xips[r], w.err.msg);
                return 1;
            }
            hcbd_profile_sample(&prof, &w);
            {
                double sv = 0;
                int q, b = (int)((int64_t)k * 10 / nsamp);
                for (q = 0; q < w.n; ++q) sv += w.vx[q];
                vb[b] += sv / w.n;
                nvb[b]++;
            }
            if (k % 1000 == 999)
                progress(&c, r * c.steps + start + 10 * (k + 1), nxip * c.steps, &t0);
        }
        hcbd_profile_result(&prof, out);
        lo = p->wall.thickness;
        hi = p->L[1] - p->wall.thickness;
        /* central fifth of the channel: bulk density and temperature */
        for (s = 0; s < nslab; ++s) {
            double y = out[8 * s];
            if (fabs(y - 0.5 * p->L[1]) <= 0.1 * (hi - lo)) {
                nbulk += out[8 * s + 1]; tc += out[8 * s + 5]; ++ncen;
                nbulk_e2 += out[8 * s + 2] * out[8 * s + 2];
                tc_e2 += out[8 * s + 6] * out[8 * s + 6];
            }
            if (out[8 * s + 7] > 0) { meanc += out[8 * s + 7]; ++nc; }
            /* interior profile: slabs at least 1 sigma from the interfaces */
            if (y > lo + 1.0 && y < hi - 1.0) {
                ys[nint] = y; vs[nint] = out[8 * s + 3]; es[nint] = out[8 * s + 4]; ++nint;
            }
        }
        nbulk /= ncen; tc /= ncen; meanc /= nc;
        for (s = 0; s < 10; ++s) vmean += (vb[s] /= nvb[s] > 0 ? nvb[s] : 1) / 10;
        for (s = 0; s < 10; ++s) vmean_err += (vb[s] - vmean) * (vb[s] - vmean) / 90;
        vmean_err = sqrt(vmean_err);
        for (s = 0; s < nslab; ++s) {
            double a = out[8 * s] - 0.5 * p->L[1] / nslab, b = a + p->L[1] / nslab;
            double ov = fmin(b, hi) - fmax(a, lo);
            /* excluded width: integral over the channel of 1 - n/n_bulk,
               exact for slabs that straddle an interface */
            if (ov > 0) dep += ov - out[8 * s + 7] / (nbulk * p->L[0] * p->L[2]);
            if (out[8 * s + 7] >= 0.2 * meanc && tc > 0)
                tdev = fmax(tdev, fabs(out[8 * s + 5] / tc - 1));
        }
        dep *= 0.5;
        /* the particles in the channel are fixed, so dep = (W - N/(n_bulk A))/2
           and its error is n_bulk's (slab errors taken as independent) */
        dep_err = 0.5 * (hi - lo - 2 * dep) * sqrt(nbulk_e2) / ncen / nbulk;
        tc_err = sqrt(tc_e2) / ncen;
        fit_parabola(ys, vs, es, nint, q, C);
        vmax = q[2] != 0 ? q[0] - q[1] * q[1] / (4 * q[2]) : 0;
        slope = 0.5 * (fabs(q[1] + 2 * q[2] * lo) + fabs(q[1] + 2 * q[2] * hi));
        slip = 0.5 * ((q[0] + q[1] * lo + q[2] * lo * lo) + (q[0] + q[1] * hi + q[2] * hi * hi));
        gv[0] = 1; gv[1] = q[2] != 0 ? -q[1] / (2 * q[2]) : 0; gv[2] = q[2] != 0 ? q[1] * q[1] / (4 * q[2] * q[2]) : 0;
        gs[0] = 1; gs[1] = 0.5 * (lo + hi); gs[2] = 0.5 * (lo * lo + hi * hi);
        vmax_err = fit_err(C, gv);
        slip_err = fit_err(C, gs);
        memcpy(fig_q[r], q, sizeof q);
        fig_vmax[r][0] = vmax; fig_vmax[r][1] = vmax_err; fig_vmax[r][2] = th.v_max;
        pen = hcbd_world_wall_penetrations(&w, NULL, NULL);
        checksum = (checksum ^ hcbd_world_checksum(&w)) * 0x100000001B3ULL;
        {
            char name[64];
            snprintf(name, sizeof name, "profile_xip%g.csv", xips[r]);
            if ((f = open_out(&c, name))) {
                fprintf(f, "y,density,density_err,vx,vx_err,T_over_kT,T_err,particles\n");
                for (s = 0; s < nslab; ++s)
                    fprintf(f, "%.6g,%.6g,%.3g,%.6g,%.3g,%.6g,%.3g,%.6g\n", out[8 * s], out[8 * s + 1],
                            out[8 * s + 2], out[8 * s + 3], out[8 * s + 4], out[8 * s + 5] / p->kT,
                            out[8 * s + 6] / p->kT, out[8 * s + 7]);
                fclose(f);
            }
        }
        printf("# summary xip=%g (xi'/xi = %g)\n", xips[r], xips[r] / p->xi);
        printf("v_max_measured=%.6g\nv_max_err=%.3g\nv_max_newtonian=%.6g\n", vmax, vmax_err, th.v_max);
        printf("v_mean_measured=%.6g\nv_mean_err=%.3g\n", vmean, vmean_err);
        printf("slip_velocity_ratio=%.4g\nslip_velocity_ratio_err=%.3g\nslip_length=%.4g\n",
               vmax != 0 ? slip / vmax : 0, vmax != 0 ? slip_err / fabs(vmax) : 0,
               slope > 0 ? slip / slope : 0);
        printf("depletion_width=%.4g\ndepletion_width_err=%.3g\ndepletion_width_boltzmann=%.4g\n", dep, dep_err,
               th.depletion_width);
        printf("T_bulk_ratio=%.4g\nT_profile_max_dev=%.4g\n", tc / p->kT, tdev);
        printf("wall_penetrations=%lld\n", (long long)pen);
        judge("v_max_measured", vmax, vmax_err, "kT/(xi sigma)", th.v_max, 0, "Newtonian parabola, mean-field nu",
              p->potential == HCBD_POT_IDEAL
                  ? "ideal carriers' viscosity is ~0.66 of the mean field (docs/MODEL.md 12), and Gaussian walls slip"
                  : "the stars add their own viscosity to the background's, and thin under shear");
        if (wall_mode == HCBD_WALL_GAUSS)
            judge("slip_velocity_ratio", vmax != 0 ? slip / vmax : 0, vmax != 0 ? slip_err / fabs(vmax) : NAN, "1", NAN, 0,
                  "soft Gaussian walls slip (2016 sec. IV C)", NULL);
        else
            judge("slip_velocity_ratio", vmax != 0 ? slip / vmax : 0, vmax != 0 ? slip_err / fabs(vmax) : NAN, "1", 0, 0,
                  "no slip at the interface", NULL);
        if (wall_mode == HCBD_WALL_GAUSS && p->potential == HCBD_POT_IDEAL)
            judge("depletion_width", dep, dep_err, "sigma", th.depletion_width, 0,
                  "Boltzmann, integral of 1 - exp(-phi/kT)", NULL);
        else
            judge("depletion_width", dep, dep_err, "sigma", NAN, 0,
                  wall_mode != HCBD_WALL_GAUSS ? "the Boltzmann width is for Gaussian walls"
                                               : "stars layer at the walls (negative: denser than the bulk)", NULL);
        judge("T_bulk_ratio", tc / p->kT, tc_err / p->kT, "kT", 1, 0, "equipartition in the channel's centre", NULL);
        judge("wall_penetrations", (double)pen, NAN, "count", 0, 0, "none through the walls", NULL);
        verdicts_flush();
        printf("eta_inf=%.6g\nnu_meanfield=%.6g\nre_max=%.4g\n", th.eta_inf, th.nu, th.re_max);
        if (th.re_max >= 1)
            printf("# warning: Re_max = %.3g >= 1 (2016 eq. 37-39): inertia is not negligible "
                   "here, lower g or raise nu\n", th.re_max);
        free(mem);
        free(out);
        if (!run_out_close(&c, &ro, &w)) return 1;
        hcbd_world_destroy(&w);
    }
    printf("state_checksum=%016llx\n", (unsigned long long)checksum);
    if ((f = open_out(&c, "plots.gp"))) {
        /* reduced units of the star scene (docs/MODEL.md 9): sigma, kT,
           time xi sigma^2 / kT, so velocity in kT / (xi sigma).  The walls
           are shaded; the channel is lo < y < hi.  g is the same for every
           xi' and so is the Newtonian profile (nu does not depend on xi') */
        const double lo = p->wall.thickness, hi = p->L[1] - p->wall.thickness;
        static const char *lab[3] = {"number density  n " GP_SIGMA "^3", "v_x / (kT/" GP_XI GP_SIGMA ")", "T / kT"};
        static const char *sub[3] = {"(a) density", "(b) mean background velocity; lines: parabola fits to the "
                                     "slabs > 1 " GP_SIGMA " from the walls", "(c) temperature (velocity variance)"};
        static const double org[3] = {0, 0.29, 0.71}, wid[3] = {0.29, 0.42, 0.29};
        gp_preamble(f, 1700, 600);
        fprintf(f, "set output 'profiles.png'\n"
                   "set multiplot title \"Gravity-driven channel flow between walls (%s)\\n{/*0.85 GI-BD, "
                   "%s, N = %d, n_# = %g, " GP_TAU " = %g, R_c = %g, g = %g (body force on %s), %d slabs, %d steps "
                   "per run}\"\n"
                   "set xlabel 'y / " GP_SIGMA "'\nset xrange [0:%.6g]\n"
                   "set object 1 rect from graph 0, graph 0 to first %.6g, graph 1 fc rgb '#d8d8d8' fs solid noborder "
                   "behind\n"
                   "set object 2 rect from first %.6g, graph 0 to graph 1, graph 1 fc rgb '#d8d8d8' fs solid noborder "
                   "behind\n"
                   "set label 1 'wall' at first %.6g, graph 0.5 center rotate by 90 tc 'gray30'\n"
                   "set label 2 'wall' at first %.6g, graph 0.5 center rotate by 90 tc 'gray30'\n",
                wall_mode == HCBD_WALL_GAUSS ? "Gaussian repulsion" :
                wall_mode == HCBD_WALL_REFLECT ? "reflecting" : "no-slip at the interface",
                p->potential == HCBD_POT_STAR ? "star polymers" : "ideal particles", c.N, c.density, p->tau, p->Rc,
                g_force, bg_only ? "the background only" : "particles and background", nslab, c.steps, p->L[1], lo,
                hi, 0.5 * lo, 0.5 * (hi + p->L[1]));
        for (k = 0; k < 3; ++k) {
            fprintf(f, "set origin %g, 0\nset size %g, 0.89\nset title '%s' font ',12'\nset ylabel '%s'\n", org[k],
                    wid[k], sub[k], lab[k]);
            fprintf(f, "set key top center\nset offsets 0, 0, graph %g, graph 0.05\nset yrange [%s:*]\n",
                    k == 1 ? 0.55 : 0.45, k == 1 ? "0" : "*");
            fprintf(f, "plot ");
            for (r = 0; r < nxip; ++r)
                fprintf(f, "%s'profile_xip%g.csv' u 1:($8>0?$%d:1/0):%d w %s pt 7 ps 0.7 lc %d "
                           "t \"" GP_XIP "/" GP_XI " = %g: measured\"", r ? ", \\\n     " : "", xips[r], 2 + 2 * k,
                        3 + 2 * k, k == 1 ? "yerrorbars" : "yerrorlines", r + 1, xips[r] / p->xi);
            if (k == 0)
                fprintf(f, ", %.17g w l dt 2 lc 'black' t 'n_# = %g (nominal bulk density)'", c.density, c.density);
            else if (k == 2)
                fprintf(f, ", 1 w l dt 2 lc 'black' t 'T = kT'");
            else {
                /* the fitted parabola over the channel, and the Newtonian
                   profile of the background viscosity alone with no slip
                   at the interfaces */
                for (r = 0; r < nxip; ++r)
                    fprintf(f, ", \\\n     (x > %.17g && x < %.17g ? %.17g + %.17g * x + %.17g * x**2 : 1/0) w l "
                               "lc %d t 'fit: v_{max} = %.4g " GP_PM " %.2g'", lo, hi, fig_q[r][0], fig_q[r][1],
                            fig_q[r][2], r + 1, fig_vmax[r][0], fig_vmax[r][1]);
                fprintf(f, ", \\\n     (x > %.17g && x < %.17g ? %.17g * (x - %.17g) * (%.17g - x) : 1/0) "
                           "w l dt 2 lw 2 "
                           "lc 'black' t \"Newtonian, no slip, %s" GP_NU " = R_c^2/(28" GP_TAU "): v_{max} = %.4g\"",
                        lo, hi, 4 * fig_vmax[nxip - 1][2] / ((hi - lo) * (hi - lo)), lo, hi,
                        p->potential == HCBD_POT_STAR ? "background " : "", fig_vmax[nxip - 1][2]);
            }
            fprintf(f, "\n");
        }
        fprintf(f, "unset multiplot\n");
        fclose(f);
        make_figures(&c);
    }
    summary_end(&c, 1);
    return 0;
}
