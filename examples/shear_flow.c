/* shear_flow: flow curves of a star-polymer fluid under Lees-Edwards shear
   with GI-BD (Ahuja et al. 2016, sec. IV B, Fig. 5).

   For each shear rate the box is sheared (MODEL.md 5), the run starts on the
   linear velocity profile, and after a start-up the shear stress is
   accumulated in blocks, split into its three parts:
     particle    pair forces of the star potential (2016 eq. 26)
     background  friction and noise exchanges of the background velocities
     carrier     momentum carried across the sheared boundary by particles
   viscosity = stress / gdot, with the standard error of the blocks.  The
   total is fitted with the Carreau law (2016 eq. 34) with eta_inf fixed at
   the background viscosity of eq. 35, Rc^2 n# xi' / 28.

   What to look for: shear thinning (eta falls with gdot) carried by the
   particle part; the background part lies 20-30 % above eq. 35 for stars
   (their structure raises the friction network's viscosity factor,
   MODEL 3: 1.23 with the 2016 density), where ideal carriers read about
   two thirds of it (MODEL 12); raising xip raises the plateau eta_inf.  The
   default runs the three xi'/xi of Fig. 5 (xip=1,2,5).

   Writes flowcurve.csv and plots.gp (flowcurve.png with gnuplot); the
   summary per xi' gives the viscosities at the lowest rate, the Carreau
   parameters with errors and the particle Reynolds number gdot sigma^2 /
   nu of the fastest rate; a
   checksum of all runs ends it. */
#include "example_common.h"

#define NB 5
#define MAXR 32
#define MAXX 8

static double rates[MAXR], xips[MAXX];
static int nrates, nxip;

static void usage(FILE *f)
{
    fprintf(f,
            "usage: shear_flow [key=value ...]\n"
            "  preset=quick|paper  quick (default): gdot=2,5,10,20, 20000 steps each;\n"
            "                      paper: 10 rates from 0.3 to 100, 300000 steps each\n"
            "  gdot=a,b,c,...      shear rates (comma-separated)\n"
            "  xip=a,b,...         background frictions xi' (xi = 1): default 1,2,5\n"
            "  N density dt kT xi tau Rc f sigma rcut skin Lx Ly Lz potential=star|ideal\n"
            "  density_norm=2014|2016 lagged=0|1 noise=gauss|uniform pair=shardlow|euler\n"
            "  brownian=lm|euler seed steps threads out\n"
            "  (steps: per shear rate)\n"
            "  xyz=FILE xyz_every=k thermo_every=k checkpoint=FILE  run output, one file per\n"
            "                      run (FILE.<run>.ext) when there are several\n"
            "  restart=FILE        continue one run from a checkpoint (its parameters)\n");
}

static int own_key(config *c, const char *key, const char *v)
{
    if (!strcmp(key, "preset")) return check_preset(c, v);
    if (!strcmp(key, "gdot")) return (nrates = parse_list(c, key, v, rates, MAXR)) > 0;
    if (!strcmp(key, "xip")) return (nxip = parse_list(c, key, v, xips, MAXX)) > 0;
    if (!strcmp(key, "dynamics")) {
        fprintf(stderr, "shear_flow: dynamics is GI-BD (classical BD carries no background flow)\n");
        return 0;
    }
    return -1;
}

int main(int argc, char **argv)
{
    config c;
    hcbd_params *p;
    static double eta[MAXX][4][MAXR], err[MAXX][4][MAXR];
    double carreau[MAXX][3], carreau_err[MAXX][3]; /* the fit and its errors, for the figure */
    int fitted[MAXX];
    uint64_t checksum = 0;
    int k, r, b, x, paper = 0, start;
    struct timespec t0;
    FILE *f;

    memset(&c, 0, sizeof c);
    c.name = "shear_flow";
    c.def = hcbd_world_def_default();
    c.def.params.tau = 3e-3; /* 2016 sec. IV */
    c.N = 512;
    c.density = 0.24;
    if (!expand_args(&c, &argc, &argv)) return 2;
    for (k = 1; k < argc; ++k)
        if (!strcmp(argv[k], "preset=paper")) paper = 1;
    c.steps = paper ? 300000 : 15000;
    nrates = 0;
    if (paper)
        for (r = 0; r < 10; ++r) rates[nrates++] = 0.3 * pow(100 / 0.3, r / 9.0);
    else {
        rates[0] = 2; rates[1] = 5; rates[2] = 10; rates[3] = 20;
        nrates = 4;
    }
    xips[0] = 1; xips[1] = 2; xips[2] = 5;
    nxip = 3;
    snprintf(c.out, sizeof c.out, "out/shear_flow");
    if (!parse_args(argc, argv, &c, own_key, usage)) return c.help ? 0 : 2;
    p = &c.def.params;
    if (c.restart[0]) nxip = nrates = 1; /* one run, at the checkpoint's rate and xi' */
    mkdirs(c.out);
    write_run_conf(&c);
    printf("shear_flow: GI-BD %s, N = %d, box %.3g x %.3g x %.3g, n# = %g, dt = %g, tau = %g, "
           "%d values of xi', %d rates, %d steps each\n",
           p->potential == HCBD_POT_STAR ? "star polymers" : "ideal particles", c.N, p->L[0], p->L[1],
           p->L[2], c.density, p->dt, p->tau, nxip, nrates, c.steps);
    fflush(stdout);
    start = c.steps / 5; /* start-up at each rate: the profile and the structure settle */
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (x = 0; x < nxip; ++x)
        for (r = 0; r < nrates; ++r) {
            hcbd_world w;
            run_out ro;
            char label[64];
            double blk[4][NB];
            p->xip = xips[x];
            p->gdot = rates[r];
            if (x == 0 && r == nrates - 1) print_limits(p); /* the fastest shear */
            if (!world_start(&c, &w)) return 2;
            if (c.restart[0]) { /* the checkpoint's rate and xi', already sheared */
                xips[x] = p->xip;
                rates[r] = p->gdot;
            } else {
                hcbd_world_place_lattice(&w, c.N);
            }
            snprintf(label, sizeof label, "xip%g_gdot%g", xips[x], rates[r]);
            if (!run_out_open(&c, &ro, &w, nxip * nrates > 1 ? label : NULL)) return 2;
            if (run_steps(&c, &ro, &w, c.restart[0] ? 0 : start) != HCBD_OK) {
                fprintf(stderr, "shear_flow: xip = %g, gdot = %g: %s\n", xips[x], rates[r], w.err.msg);
                return 1;
            }
            for (b = 0; b < NB; ++b) {
                double fl[4];
                hcbd_world_stress_enable(&w, 1);
                if (run_steps(&c, &ro, &w, (c.steps - start) / NB) != HCBD_OK) {
                    fprintf(stderr, "shear_flow: xip = %g, gdot = %g: %s\n", xips[x], rates[r], w.err.msg);
                    return 1;
                }
                hcbd_world_stress_read(&w, fl, NULL);
                for (k = 0; k < 4; ++k) blk[k][b] = fl[k] / rates[r];
            }
            for (k = 0; k < 4; ++k) mean_err(blk[k], NB, &eta[x][k][r], &err[x][k][r]);
            checksum = (checksum ^ hcbd_world_checksum(&w)) * 0x100000001B3ULL;
            if (!run_out_close(&c, &ro, &w)) return 1;
            hcbd_world_destroy(&w);
            progress(&c, (x * nrates + r + 1) * c.steps, nxip * nrates * c.steps, &t0);
        }

    if ((f = open_out(&c, "flowcurve.csv"))) {
        fprintf(f, "xip,gdot,eta_total,err_total,eta_particle,err_particle,eta_background,err_background,"
                   "eta_carrier,err_carrier\n");
        for (x = 0; x < nxip; ++x)
            for (r = 0; r < nrates; ++r)
                fprintf(f, "%g,%.6g,%.6g,%.3g,%.6g,%.3g,%.6g,%.3g,%.6g,%.3g\n", xips[x], rates[r],
                        eta[x][3][r], err[x][3][r], eta[x][0][r], err[x][0][r], eta[x][1][r],
                        err[x][1][r], eta[x][2][r], err[x][2][r]);
        fclose(f);
    }
    for (x = 0; x < nxip; ++x) {
        hcbd_theory th;
        double pc[3], pe[3], chi2, e[MAXR], re;
        p->xip = xips[x];
        p->gdot = 0;
        hcbd_params_theory(p, &th);
        printf("# summary xip=%g (xi'/xi = %g; lowest shear rate; Carreau fit of the total)\n", xips[x],
               xips[x] / p->xi);
        printf("gdot_lowest=%g\n", rates[0]);
        printf("eta_total_measured=%.6g\neta_total_err=%.3g\n", eta[x][3][0], err[x][3][0]);
        printf("eta_particle_measured=%.6g\neta_particle_err=%.3g\n", eta[x][0][0], err[x][0][0]);
        printf("eta_background_measured=%.6g\neta_background_err=%.3g\n", eta[x][1][0], err[x][1][0]);
        printf("eta_carrier_measured=%.6g\neta_carrier_err=%.3g\n", eta[x][2][0], err[x][2][0]);
        printf("eta_background_theory=%.6g\n", th.eta_inf);
        judge("eta_total_measured", eta[x][3][0], err[x][3][0], "xi/sigma", NAN, 0,
              "particle + background + carrier stress over gdot", NULL);
        judge("eta_background_measured", eta[x][1][0], err[x][1][0], "xi/sigma", th.eta_inf, 0,
              "2016 eq. 35 times n# xi'",
              p->potential == HCBD_POT_IDEAL ? "ideal carriers read 0.63-0.69 of eq. 35 (docs/MODEL.md 12)"
                                             : "eq. 35 takes g(r) = 1; the stars' first shell within Rc raises the friction sum");
        fitted[x] = 0;
        for (r = 0; r < nrates; ++r) e[r] = err[x][3][r] > 0 ? err[x][3][r] : 1e-12;
        if (nrates >= 4 && hcbd_carreau_fit(rates, eta[x][3], e, nrates, th.eta_inf, 0, pc, pe, &chi2) == HCBD_OK) {
            printf("eta_inf=%.6g\neta0=%.6g\neta0_err=%.3g\nlambda=%.6g\nlambda_err=%.3g\nn=%.4g\nn_err=%.3g\n",
                   th.eta_inf, pc[0], pe[0], pc[1], pe[1], pc[2], pe[2]);
            printf("carreau_chi2_per_dof=%.3g\n", chi2 / (nrates - 3));
            judge("n", pc[2], pe[2], "1", NAN, 0, "the Carreau exponent; below 1: shear thinning (2016 Fig. 7)", NULL);
            memcpy(carreau[x], pc, sizeof pc);
            memcpy(carreau_err[x], pe, sizeof pe);
            fitted[x] = 1;
        } else {
            printf("# Carreau fit: needs 4 or more rates with errors, or did not converge\n");
        }
        /* 2016 eq. 37-39 bound the channel's sigma v_max / nu; a sheared box
           has no frame-independent v_max, so the particle Reynolds number
           uses the velocity difference across a particle, gdot sigma */
        re = rates[nrates - 1] * p->sigma * p->sigma / th.nu;
        printf("re_max=%.4g\n", re);
        if (re >= 1)
            printf("# warning: Re = %.3g >= 1 at gdot = %g (2016 eq. 37-39): inertia is not "
                   "negligible\n", re, rates[nrates - 1]);
        verdicts_flush();
    }
    printf("state_checksum=%016llx\n", (unsigned long long)checksum);
    if ((f = open_out(&c, "plots.gp"))) {
        /* reduced units of the star scene (docs/MODEL.md 9): sigma, kT and
           time xi sigma^2 / kT, so eta in xi / sigma.  Colour = xi'/xi,
           symbol or dash = what is drawn; the ranges leave room for the
           keys and the fit table */
        double lo = HUGE_VAL, hi = 0, lob = 0, hib = 0;
        for (x = 0; x < nxip; ++x) {
            lo = fmin(lo, p->Rc * p->Rc * c.density * xips[x] / 28);
            for (r = 0; r < nrates; ++r) {
                hi = fmax(hi, eta[x][3][r] + err[x][3][r]);
                for (k = 0; k < 3; ++k) {
                    lob = fmin(lob, eta[x][k][r] - err[x][k][r]);
                    hib = fmax(hib, eta[x][k][r] + err[x][k][r]);
                }
            }
        }
        gp_preamble(f, 1600, 650);
        fprintf(f, "set output 'flowcurve.png'\n"
                   "set multiplot layout 1,2 title \"Flow curve under Lees-Edwards shear\\n{/*0.85 GI-BD, %s, N = %d, "
                   "n_# = %g, " GP_TAU " = %g, R_c = %g, %d steps per rate}\"\n"
                   "set xlabel 'shear rate  " GP_GDOT " / (kT/" GP_XI GP_SIGMA "^2)'\n"
                   "set ylabel 'viscosity  " GP_ETA " / (" GP_XI "/" GP_SIGMA ")'\nset logscale x\n"
                   "set xrange [%.6g:%.6g]\nset xtics (",
                p->potential == HCBD_POT_STAR ? "star polymers" : "ideal particles", c.N, c.density, p->tau, p->Rc,
                c.steps, rates[0] / 1.4, rates[nrates - 1] * 1.4);
        for (r = 0; r < nrates; ++r) fprintf(f, "%s%g", r ? ", " : "", rates[r]);
        /* (a) the total with its Carreau fit, eta_inf fixed at eq. 35 */
        fprintf(f, ")\nset logscale y\nset yrange [%.6g:%.6g]\nset key top right\n"
                   "set title '(a) total viscosity, Carreau fit (2016 eq. 34)' font ',12'\nset format y '%%g'\n",
                lo / 4, hi * 3);
        { /* the range spans about a decade: tics at 1, 2, 5 times powers of ten */
            int d;
            for (d = (int)floor(log10(lo / 4)); d <= (int)ceil(log10(hi * 3)); ++d)
                fprintf(f, "set ytics add (%g, %g)\n", 2 * pow(10, d), 5 * pow(10, d));
        }
        for (x = 0; x < nxip; ++x)
            if (fitted[x])
                fprintf(f, "set label %d \"" GP_XIP "/" GP_XI " = %g:  " GP_ETA "_0 = %.3g " GP_PM " %.2g,  " GP_LAMBDA
                           " = %.3g " GP_PM " %.2g,  n = %.3g " GP_PM " %.2g\" at graph 0.03, graph %g tc lt %d "
                           "font ',11'\n", x + 1, xips[x] / p->xi, carreau[x][0], carreau_err[x][0], carreau[x][1],
                        carreau_err[x][1], carreau[x][2], carreau_err[x][2], 0.05 + 0.06 * (nxip - 1 - x), x + 1);
            else
                fprintf(f, "set label %d \"" GP_XIP "/" GP_XI " = %g:  no Carreau fit (needs 4 rates with errors)\" "
                           "at graph 0.03, graph %g tc lt %d font ',11'\n", x + 1, xips[x] / p->xi,
                        0.05 + 0.06 * (nxip - 1 - x), x + 1);
        fprintf(f, "set label %d 'Carreau fits, " GP_ETA "_" GP_INF " held at eq. 35:' at graph 0.03, graph %g "
                   "font ',11'\n"
                   "plot NaN w p pt 7 lc 'black' t 'measured (block errors)', NaN w l lw 2 lc 'black' t 'Carreau fit', "
                   "NaN w l dt 2 lc 'black' t '" GP_ETA "_" GP_INF " = R_c^2 n_# " GP_XIP "/28 (2016 eq. 35)'",
                nxip + 1, 0.05 + 0.06 * nxip);
        for (x = 0; x < nxip; ++x) {
            double ei = p->Rc * p->Rc * c.density * xips[x] / 28;
            fprintf(f, ", \\\n     'flowcurve.csv' u ($1==%g?$2:1/0):3:4 w yerrorbars pt 7 ps 1.3 lc %d "
                       "t \"" GP_XIP "/" GP_XI " = %g\"", xips[x], x + 1, xips[x] / p->xi);
            if (fitted[x])
                fprintf(f, ", " GP_CARREAU " w l lw 2 lc %d "
                           "notitle", ei, carreau[x][0], ei, carreau[x][1], carreau[x][2], x + 1);
            fprintf(f, ", %.17g w l dt 2 lc %d notitle", ei, x + 1);
        }
        /* (b) the three parts: symbol = part */
        fprintf(f, "\nunset label\nunset logscale y\nset ytics autofreq\nset yrange [%.6g:%.6g]\n"
                   "set title '(b) contributions (block errors)' font ',12'\n"
                   "plot NaN w p pt 7 lc 'black' t 'particle (star pair forces)', "
                   "NaN w p pt 4 lc 'black' t 'background (friction + noise)', "
                   "NaN w p pt 8 lc 'black' t 'carrier (crossing particles)', "
                   "NaN w l dt 2 lc 'black' t 'eq. 35'", lob - 0.05 * (hib - lob), hib + 0.6 * (hib - lob));
        for (x = 0; x < nxip; ++x)
            fprintf(f, ", \\\n     'flowcurve.csv' u ($1==%g?$2:1/0):5:6 w yerrorbars pt 7 lc %d t \"" GP_XIP "/" GP_XI
                       " = %g\", '' u ($1==%g?$2:1/0):7:8 w yerrorbars pt 4 lc %d notitle, "
                       "'' u ($1==%g?$2:1/0):9:10 w yerrorbars pt 8 lc %d notitle, %.17g w l dt 2 lc %d notitle",
                    xips[x], x + 1, xips[x] / p->xi, xips[x], x + 1, xips[x], x + 1,
                    p->Rc * p->Rc * c.density * xips[x] / 28, x + 1);
        fprintf(f, ", 0 w l lc 'gray40' notitle\nunset multiplot\n");
        fclose(f);
        make_figures(&c);
    }
    summary_end(&c, 1);
    return 0;
}
