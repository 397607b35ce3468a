/* The stress split of the 2018 model (HCBD_HC_S_*: the numbers behind
   Table II) against the virial written out here from the state of the
   step (MODEL.md 6, 8, 13.3), column by column, S_yx = -(1/V) sum y_ij
   F_ij,x:
     kinetic      m (v_x - gdot (y - L_y/2)) v_y, the velocities of t (Euler)
                  or after the sweep (exact)
     pressure     -(P_i/n_i^2 + P_j/n_j^2) w'(r) e_ij
     viscous      -f_ij (v_i - v_j'), v_j' the velocity of j's image;
                  the exact sweep's whole pair impulse P_ij / dt
     noise        sqrt(2 kT f_ij / dt) z_ij (Euler; the exact sweep's noise
                  is in its impulse), z from the exported noise streams
     conservative -(p kT / n_max) (mu_a + mu_b) W'(r) e_ab
     transient    alpha (lambda - leq) leq'(r) e_ab
     interaction  (y_i - y_a) psi_ai F_a,x, psi_ai = W(r_ai)/n_i over S_a
                  (Shepard) or not (raw)
   for both pair schemes and both couplings, under Lees-Edwards images.
   Each column is compared with its own sum of |terms| as the scale, so a
   3 % error in a coefficient or a lever arm fails by 10^5 of the
   tolerance; each column must be at least 1 % of that scale (no column
   hides in a cancellation).  The exact sweep's impulses are known pair by
   pair only when pairs share no blob: its scene holds isolated pairs.

     stress_columns      the four schemes (Euler/exact x Shepard/raw)
     stress_momentum     the fluid columns against the momentum each pair
                         handed over (m dv of the lower id across y_ij)
     stress_substeps     the stress of a step of two fluid sub-steps is the
                         second's (a world of one sub-step, twice as many)
     raw_coupling        the paper's weights w/n_i: v(r_a) and the force
                         given to the fluid, and the momentum they create,
                         dt sum_a (S_a - 1) F_a, to round-off
     stress_planes       the method of planes (Todd, Evans and Daivis 1995)
                         against the split's total in a sheared run at
                         Table I: momentum carried across planes of
                         constant y by crossing blobs and by pair impulses */
#include "hc_ref.h"
#if HCBD_MODEL == HCBD_MODEL_HCBD

/* r_a - r_b to the image of b nearest a, under Lees-Edwards with offset s
   (MODEL 5): returns that image's layer k (+1: above), whose velocity
   along x is v_b,x + k gdot L_y.  Every box here is wider than twice the
   longest range, so one image counts. */
static int s_sep(const hcbd_hc_params *p, double s, const double a[3], const double b[3], double d[3])
{
    const double *L = p->L;
    int k = 0;
    d[1] = a[1] - b[1];
    if (d[1] > 0.5 * L[1]) k = 1;
    else if (d[1] < -0.5 * L[1]) k = -1;
    d[1] -= k * L[1];
    d[0] = a[0] - b[0] - (p->gdot != 0 ? k * s : 0.0);
    d[0] -= L[0] * round(d[0] / L[0]);
    d[2] = a[2] - b[2];
    d[2] -= L[2] * round(d[2] / L[2]);
    return k;
}

/* the world's particles as doubles, interleaved */
static void s_get(const hcbd_hc_world *w, double *fx, double *fv, double *px)
{
    int i;
    for (i = 0; i < w->nf; ++i) {
        fx[3 * i] = w->fx[i]; fx[3 * i + 1] = w->fy[i]; fx[3 * i + 2] = w->fz[i];
        fv[3 * i] = w->fvx[i]; fv[3 * i + 1] = w->fvy[i]; fv[3 * i + 2] = w->fvz[i];
    }
    for (i = 0; i < w->np; ++i) {
        px[3 * i] = w->px[i]; px[3 * i + 1] = w->py[i]; px[3 * i + 2] = w->pz[i];
    }
}

static double s_norm(const double d[3]) { return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]); }

enum { S_NF = 160, S_NP = 60 };

/* The split the next step must report, from the state now: out[k] as
   HCBD_HC_S_*, scale[k] = (1/V) sum |term| of column k.  The fluid's
   pair noise is the world's of step w->step (one sub-step).  With the
   exact sweep every blob must have at most one partner within 2h (returns
   0 otherwise). */
static int s_expect(const hcbd_hc_world *w, double out[HCBD_HC_NSTRESS], double scale[HCBD_HC_NSTRESS])
{
    const hcbd_hc_params *p = &w->p;
    const int nf = w->nf, np = w->np, exact = p->pair_integrator == HCBD_PAIR_SHARDLOW;
    const int noise = p->fluctuations && p->kT > 0, raw = p->coupling == HCBD_COUPLE_RAW;
    const double m = A_MASS(p), dt = p->dt, h = p->h, s = w->core.le_offset, vj = p->gdot * p->L[1];
    const double V = p->L[0] * p->L[1] * p->L[2], sg = p->sigma, rc = p->rc;
    const double cfh = p->p_kuhn * p->kT / p->n_max;
    static double x[3 * S_NF], v[3 * S_NF], n[S_NF], P[S_NF], y[3 * S_NF], pn[S_NP], mu[S_NP], F[3 * S_NP];
    static int partners[S_NF];
    double col[HCBD_HC_NSTRESS] = {0}, ab[HCBD_HC_NSTRESS] = {0};
    hcbd_hc_noise_stream ns;
    int i, j, a, b, c;
    if (nf > S_NF || np > S_NP || p->substeps != 1) return 0;
    hcbd_hc_noise_stream_init(&ns, p->seed);
    s_get(w, x, v, y);
    for (i = 0; i < nf; ++i) {
        double d[3];
        n[i] = 0;
        partners[i] = 0;
        for (j = 0; j < nf; ++j) {
            s_sep(p, s, x + 3 * i, x + 3 * j, d);
            n[i] += a_m4(s_norm(d), h);
        }
        P[i] = a_tait(p, n[i]);
    }
    /* fluid pairs: force on i (the lower id) from j */
    for (i = 0; i < nf; ++i)
        for (j = i + 1; j < nf; ++j) {
            double d[3], z[3] = {0, 0, 0}, wd, f, r, T[3];
            const int k = s_sep(p, s, x + 3 * i, x + 3 * j, d);
            r = s_norm(d);
            if (r >= 2 * h) continue;
            partners[i]++;
            partners[j]++;
            wd = a_m4d(r, h);
            f = -2.0 * p->eta * wd / (n[i] * n[j] * r);
            if (noise) hcbd_hc_noise_fluid_pair(&ns, w->step, i, j, z);
            T[0] = -(P[i] / (n[i] * n[i]) + P[j] / (n[j] * n[j])) * wd * d[0] / r;
            if (!exact) {
                T[1] = -f * (v[3 * i] - (v[3 * j] + k * vj));
                T[2] = sqrt(2.0 * p->kT * f / dt) * z[0];
            } else {
                /* u = v_i - v_j' relaxes as an Ornstein-Uhlenbeck process
                   of rate 2 f/m and variance 2 kT/m; i takes (m/2)(u' - u) */
                const double e = exp(-2.0 * f * dt / m);
                double dP[3];
                for (c = 0; c < 3; ++c) {
                    const double u = v[3 * i + c] - v[3 * j + c] - (c == 0 ? k * vj : 0.0);
                    const double u1 = u * e + (noise ? sqrt(2.0 * p->kT / m * (1.0 - e * e)) * z[c] : 0.0);
                    dP[c] = 0.5 * m * (u1 - u);
                }
                for (c = 0; c < 3; ++c) { /* the kinetic part reads the velocities after the sweep */
                    v[3 * i + c] += dP[c] / m;
                    v[3 * j + c] -= dP[c] / m;
                }
                T[1] = dP[0] / dt;
                T[2] = 0;
            }
            for (c = 0; c < 3; ++c) {
                col[HCBD_HC_S_PRESSURE + c] += d[1] * T[c];
                ab[HCBD_HC_S_PRESSURE + c] += fabs(d[1] * T[c]);
            }
        }
    for (i = 0; i < nf; ++i) {
        const double t = m * (v[3 * i] - p->gdot * (x[3 * i + 1] - 0.5 * p->L[1])) * v[3 * i + 1];
        col[HCBD_HC_S_KINETIC] += t;
        ab[HCBD_HC_S_KINETIC] += fabs(t);
        if (exact && partners[i] > 1) return 0;
    }
    /* polymer pairs: force on a from b */
    for (a = 0; a < np; ++a) {
        double d[3];
        pn[a] = 0;
        for (b = 0; b < np; ++b) {
            s_sep(p, s, y + 3 * a, y + 3 * b, d);
            pn[a] += a_rapid(s_norm(d), sg, rc);
        }
        mu[a] = p->p_kuhn > 0 ? a_mu(pn[a] / p->n_max, p->chi) : 0.0;
        F[3 * a] = F[3 * a + 1] = F[3 * a + 2] = 0;
    }
    for (a = 0; a < np; ++a)
        for (b = a + 1; b < np; ++b) {
            double d[3], r, fr, ft = 0, lam;
            s_sep(p, s, y + 3 * a, y + 3 * b, d);
            r = s_norm(d);
            if (r >= rc || r < 1e-12 * sg) continue;
            fr = -cfh * (mu[a] + mu[b]) * a_rapidd(r, sg, rc);
            if (p->alpha > 0) {
                if (hcbd_hc_world_get_lambda(w, a, b, &lam) != HCBD_OK) return 0;
                ft = p->alpha * (lam - (1 - r / rc) * (1 - r / rc)) * (-2.0 * (1 - r / rc) / rc);
            }
            col[HCBD_HC_S_CONSERVATIVE] += d[1] * fr * d[0] / r;
            col[HCBD_HC_S_TRANSIENT] += d[1] * ft * d[0] / r;
            ab[HCBD_HC_S_CONSERVATIVE] += fabs(d[1] * fr * d[0] / r);
            ab[HCBD_HC_S_TRANSIENT] += fabs(d[1] * ft * d[0] / r);
            for (c = 0; c < 3; ++c) {
                F[3 * a + c] += (fr + ft) * d[c] / r;
                F[3 * b + c] -= (fr + ft) * d[c] / r;
            }
        }
    /* the coupling: F_a handed to the fluid blobs around a, weight psi_ai */
    for (a = 0; a < np; ++a) {
        double S = 0, d[3];
        for (i = 0; i < nf; ++i) {
            s_sep(p, s, y + 3 * a, x + 3 * i, d);
            S += a_rapid(s_norm(d), sg, rc) / n[i];
        }
        for (i = 0; i < nf; ++i) {
            double psi, t;
            s_sep(p, s, y + 3 * a, x + 3 * i, d);
            psi = a_rapid(s_norm(d), sg, rc) / n[i] / (raw ? 1.0 : S);
            t = -d[1] * psi * F[3 * a];
            col[HCBD_HC_S_INTERACTION] += t;
            ab[HCBD_HC_S_INTERACTION] += fabs(t);
        }
    }
    col[HCBD_HC_S_FLUID] = col[0] + col[1] + col[2] + col[3];
    col[HCBD_HC_S_POLYMER] = col[5] + col[6];
    col[HCBD_HC_S_TOTAL] = col[HCBD_HC_S_FLUID] + col[HCBD_HC_S_POLYMER] + col[HCBD_HC_S_INTERACTION];
    ab[HCBD_HC_S_FLUID] = ab[0] + ab[1] + ab[2] + ab[3];
    ab[HCBD_HC_S_POLYMER] = ab[5] + ab[6];
    ab[HCBD_HC_S_TOTAL] = ab[HCBD_HC_S_FLUID] + ab[HCBD_HC_S_POLYMER] + ab[HCBD_HC_S_INTERACTION];
    for (c = 0; c < HCBD_HC_NSTRESS; ++c) {
        out[c] = -col[c] / V;
        scale[c] = ab[c] / V;
    }
    return 1;
}

/* Isolated fluid pairs: a 24^3 box of 27 cells 8 wide, in each a pair of
   blobs 0.8-3 apart about the cell's centre (so every blob lies more than
   2h = 4 from every other pair), velocities in (-0.5, 0.5); with polymers,
   two near each centre (their pair variables set off equilibrium).  The
   cells centred on y = 0 straddle the sheared boundary.  nbar = 0.05 (a
   lone pair has n about 1.2 nbar), m = 1. */
static int s_pair_scene(hcbd_hc_world *w, hcbd_hc_world_def *d, int poly, uint64_t seed)
{
    hcbd_hc_params *p = &d->params;
    double x[3 * 54], v[3 * 54], px[3 * 54];
    hcbd_rng g;
    int q, c, ok;
    p->L[0] = p->L[1] = p->L[2] = 24.0;
    p->nbar = 0.05;
    p->rho = p->nbar;
    p->eta = 2.0 * p->rho;
    p->P0 = 25.0 * p->rho / 7.0;
    p->n_max = 3.0;
    d->fluid_capacity = 54;
    d->polymer_capacity = poly ? 54 : 0;
    hcbd_rng_seed(&g, seed);
    for (q = 0; q < 27; ++q) {
        const double ctr[3] = {8.0 * (q % 3), 8.0 * (q / 3 % 3), 8.0 * (q / 9) + 4.0};
        double e[3], r = 0.8 + 2.2 * hcbd_rng_uniform(&g), nr;
        for (c = 0; c < 3; ++c) e[c] = hcbd_rng_uniform(&g) - 0.5;
        nr = s_norm(e);
        for (c = 0; c < 3; ++c) {
            double a = ctr[c] + 0.5 * r * e[c] / nr, b = ctr[c] - 0.5 * r * e[c] / nr;
            x[6 * q + c] = a - p->L[c] * floor(a / p->L[c]);
            x[6 * q + 3 + c] = b - p->L[c] * floor(b / p->L[c]);
            v[6 * q + c] = hcbd_rng_uniform(&g) - 0.5;
            v[6 * q + 3 + c] = hcbd_rng_uniform(&g) - 0.5;
            a = ctr[c] + 0.3 + 0.5 * (hcbd_rng_uniform(&g) - 0.5);
            b = ctr[c] - 0.3 + 0.5 * (hcbd_rng_uniform(&g) - 0.5);
            px[6 * q + c] = a - p->L[c] * floor(a / p->L[c]);
            px[6 * q + 3 + c] = b - p->L[c] * floor(b / p->L[c]);
        }
    }
    if (!hc_create(w, d)) return 0;
    ok = a_ok(w, hcbd_hc_world_set_fluid(w, 54, x, v), "fluid");
    if (ok && poly) {
        ok = a_ok(w, hcbd_hc_world_set_polymers(w, 54, px), "polymers");
        for (q = 0; q < 27 && ok; ++q) {
            double lam;
            if (hcbd_hc_world_get_lambda(w, 2 * q, 2 * q + 1, &lam) == HCBD_OK)
                ok = a_ok(w, hcbd_hc_world_set_lambda(w, 2 * q, 2 * q + 1, lam + 0.4 - 0.2 * (q % 5)), "lambda");
        }
    }
    return ok;
}

static const char *s_col[HCBD_HC_NSTRESS] = {"kinetic", "pressure", "viscous", "noise", "fluid",
                                            "conservative", "transient", "polymer", "interaction", "total"};

/* One step with the stress on against s_expect: the largest deviation of
   a column in units of its scale (*e), and 0 when a column that must be
   there is under 1 % of its scale or the reference could not be taken. */
static int s_one_step(hcbd_hc_world *w, const char *name, double tol, double *e)
{
    double want[HCBD_HC_NSTRESS], scale[HCBD_HC_NSTRESS], got[HCBD_HC_NSTRESS];
    const int exact = w->p.pair_integrator == HCBD_PAIR_SHARDLOW;
    const int noise = w->p.fluctuations && w->p.kT > 0;
    int64_t ns = 0;
    int k, ok = 1;
    *e = 0;
    if (!a_ok(w, hcbd_hc_world_stress_enable(w, 1), "stress_enable")) return 0;
    if (!s_expect(w, want, scale)) {
        CHECK(0, "%s: the reference needs one sub-step, at most %d blobs, %d polymers, known pair "
              "variables, and for the sweep pairs that share no blob", name, S_NF, S_NP);
        return 0;
    }
    if (!hc_run(w, 1)) return 0;
    hcbd_hc_world_stress_read(w, got, &ns);
    CHECK(ns == 1, "%s: %lld steps averaged", name, (long long)ns);
    for (k = 0; k < HCBD_HC_NSTRESS; ++k) {
        const int absent = k == HCBD_HC_S_NOISE && (exact || !noise);
        const double dev = fabs(got[k] - want[k]) / (scale[k] > 0 ? scale[k] : 1.0);
        if (dev > *e) *e = dev;
        CHECK(dev < tol, "%s: %s column %.12g, expected %.12g (scale %.3g)", name, s_col[k], got[k], want[k],
              scale[k]);
        if (absent) CHECK(got[k] == 0, "%s: %s column %g must be 0", name, s_col[k], got[k]);
        else if (!(fabs(want[k]) > 0.01 * scale[k])) {
            CHECK(0, "%s: %s column %g is under 1 %% of its scale %g: the scene does not test it", name,
                  s_col[k], want[k], scale[k]);
            ok = 0;
        }
    }
    /* the parts and their sums, as the code adds them */
    CHECK(fabs(got[HCBD_HC_S_FLUID] - (got[0] + got[1] + got[2] + got[3])) <= 1e-12 * scale[HCBD_HC_S_FLUID] &&
              fabs(got[HCBD_HC_S_POLYMER] - (got[5] + got[6])) <= 1e-12 * scale[HCBD_HC_S_POLYMER] &&
              fabs(got[HCBD_HC_S_TOTAL] - (got[4] + got[7] + got[8])) <= 1e-12 * scale[HCBD_HC_S_TOTAL],
          "%s: the sums of the columns", name);
    return ok;
}

void test_hc_stress_columns(void)
{
    const double tol = ABS_FLOAT ? 1e-4 : 1e-9;
    int var;
    for (var = 0; var < 4; ++var) {
        const int exact = var >= 2, raw = var % 2;
        hcbd_hc_world_def d = hc_scene(5, 5, 5, 6);
        hcbd_hc_params *p = &d.params;
        hcbd_hc_world w;
        char name[96];
        double lam0[36], e = 0;
        int npair, ok;
        p->pair_integrator = exact ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
        p->coupling = raw ? HCBD_COUPLE_RAW : HCBD_COUPLE_SHEPARD;
        p->gdot = 0.3;
        p->n_max = 3.0;
        /* the library's defaults carry fluctuations; preset=paper's
           Euler pairs and raw weights do not */
        p->fluctuations = !raw;
        snprintf(name, sizeof name, "%s pairs, %s weights, fluctuations %s", exact ? "exact" : "Euler",
                 raw ? "raw" : "Shepard", raw ? "off" : "on");
        if (exact) {
            ok = s_pair_scene(&w, &d, 1, 41 + var);
        } else {
            ok = a_step_scene(&w, &d, 17 + var, lam0, &npair);
            /* ten steps: a Lees-Edwards offset, pairs made and kept */
            ok = ok && hc_run(&w, 10);
        }
        if (ok) {
            s_one_step(&w, name, tol, &e);
            NOTE("%s (offset %.3f): every column within %.1e of its scale", name, w.core.le_offset, e);
        }
        hcbd_hc_world_destroy(&w);
    }
}

/* Fluid only, isolated pairs, noise on: the pressure, viscous and noise
   columns together are -(1/V) sum_pairs y_ij (m dv_i,x) / dt, dv_i the
   velocity change of the lower id in the step, which only its pair moved
   (no blob crosses the sheared boundary in it). */
void test_hc_stress_momentum(void)
{
    const double tol = ABS_FLOAT ? 1e-4 : 1e-9;
    int var;
    for (var = 0; var < 2; ++var) {
        hcbd_hc_world_def d = hc_scene(5, 5, 5, 0);
        hcbd_hc_world w;
        static double x0[3 * 54], v0[3 * 54], x1[3 * 54], v1[3 * 54], py[3];
        double got[HCBD_HC_NSTRESS], sum = 0, ab = 0, pair;
        const double *L = d.params.L;
        int i, j, cross = 0, npairs = 0;
        d.params.pair_integrator = var ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
        d.params.gdot = 0.3;
        if (!s_pair_scene(&w, &d, 0, 7 + var)) {
            hcbd_hc_world_destroy(&w);
            return;
        }
        s_get(&w, x0, v0, py);
        hcbd_hc_world_stress_enable(&w, 1);
        if (!hc_run(&w, 1)) break;
        hcbd_hc_world_stress_read(&w, got, NULL);
        s_get(&w, x1, v1, py);
        for (i = 0; i < w.nf; ++i) {
            cross += fabs(x1[3 * i + 1] - x0[3 * i + 1]) > 0.5 * L[1];
            for (j = i + 1; j < w.nf; ++j) {
                double dd[3];
                s_sep(&w.p, 0.0, x0 + 3 * i, x0 + 3 * j, dd);
                if (s_norm(dd) >= 2 * w.p.h) continue;
                pair = dd[1] * A_MASS(&w.p) * (v1[3 * i] - v0[3 * i]) / w.p.dt;
                sum += pair;
                ab += fabs(pair);
                ++npairs;
            }
        }
        sum *= -1.0 / (L[0] * L[1] * L[2]);
        ab /= L[0] * L[1] * L[2];
        pair = got[HCBD_HC_S_PRESSURE] + got[HCBD_HC_S_VISCOUS] + got[HCBD_HC_S_NOISE];
        NOTE("%s: pressure + viscous + noise %.10g, momentum handed over %.10g (%d pairs)",
             var ? "exact" : "Euler", pair, sum, npairs);
        CHECK(cross == 0 && npairs == 27, "%d blobs crossed the boundary, %d pairs", cross, npairs);
        CHECK(fabs(pair - sum) < tol * ab && fabs(sum) > 0.01 * ab,
              "%s: the fluid's pair stress %.12g is not the momentum handed over, %.12g (scale %g)",
              var ? "exact" : "Euler", pair, sum, ab);
        hcbd_hc_world_destroy(&w);
    }
}

/* A step of two fluid sub-steps reports the stress of its second: the
   same as the second step of a world of one sub-step of dt/2 (fluid
   only, so that the two worlds move alike: the same pair noise, sub-step
   by sub-step), both pair schemes, under shear. */
void test_hc_stress_substeps(void)
{
    int var;
    for (var = 0; var < 2; ++var) {
        hcbd_hc_world w[2];
        double got[2][HCBD_HC_NSTRESS], e = 0, sc = 0;
        int k, ok = 1;
        for (k = 0; k < 2 && ok; ++k) {
            hcbd_hc_world_def d = hc_scene(5, 5, 5, 0);
            d.params.pair_integrator = var ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
            d.params.gdot = 0.3;
            d.params.substeps = k ? 2 : 1;
            d.params.dt = k ? 0.04 : 0.02;
            ok = hc_create(&w[k], &d) && a_ok(&w[k], hcbd_hc_world_place_fluid_lattice(&w[k], 125), "lattice");
            if (ok && !k) ok = hc_run(&w[k], 1);
            ok = ok && a_ok(&w[k], hcbd_hc_world_stress_enable(&w[k], 1), "stress") && hc_run(&w[k], 1);
            if (ok) hcbd_hc_world_stress_read(&w[k], got[k], NULL);
        }
        if (!ok) return;
        for (k = 0; k < HCBD_HC_NSTRESS; ++k) {
            e = fmax(e, fabs(got[1][k] - got[0][k]));
            sc = fmax(sc, fabs(got[0][k]));
        }
        NOTE("%s: two sub-steps of 0.02 against two steps: stress columns within %.1e of %.3g", var ? "exact" : "Euler",
             e, sc);
        CHECK(e <= 1e-12 * sc && sc > 0, "%s: the stress of two sub-steps is not that of the second (%g of %g)",
              var ? "exact" : "Euler", e, sc);
        for (k = 0; k < 2; ++k) hcbd_hc_world_destroy(&w[k]);
    }
}

/* The paper's weights psi_ai = w(r_ai)/n_i (coupling = raw), against
   the sums done here: the interpolated velocity sum_i psi_ai v_i + F_a/xi
   and the force sum_a psi_ai F_a on each blob.  They do not sum to one,
   so the fluid gains momentum in a step: what the fluid receives is
   dt sum_i sum_a psi_ai F_a = dt sum_a S_a F_a, S_a = sum_i psi_ai, and
   the polymers' pair forces sum to zero, so (no body force, no shear)
       sum_i m dv_i = dt sum_a (S_a - 1) F_a
   to round-off, the pair sums of the fluid cancelling exactly (fixed
   point).  With Shepard weights (S_a = 1 by construction) it is zero. */
void test_hc_raw_coupling(void)
{
    const double tol = ABS_FLOAT ? 1e-4 : 1e-9;
    int var;
    for (var = 0; var < 2; ++var) {
        hcbd_hc_world_def d = hc_scene(5, 5, 5, 6);
        hcbd_hc_params *p = &d.params;
        hcbd_hc_world w;
        const int nf = d.fluid_capacity, np = 6, raw = var == 0;
        double *n = (double *)malloc(sizeof(double) * nf), *fa = (double *)malloc(sizeof(double) * 3 * nf);
        double *v0 = (double *)malloc(sizeof(double) * 3 * nf), *x0 = (double *)malloc(sizeof(double) * 3 * nf);
        double *v1 = (double *)malloc(sizeof(double) * 3 * nf), *buf = (double *)malloc(sizeof(double) * 3 * nf);
        double pn[6], F[18], u[18], S[6], lam0[36], e_u, e_fa, usc, fsc, dp[3] = {0, 0, 0}, pred[3] = {0, 0, 0};
        double Fabs = 0, py[18], smin = 1e300, smax = -1e300;
        int i, a, c, npair, ok;
        p->coupling = raw ? HCBD_COUPLE_RAW : HCBD_COUPLE_SHEPARD;
        p->pair_integrator = HCBD_PAIR_EULER;
        p->fluctuations = 0;
        p->n_max = 3.0;
        ok = a_step_scene(&w, &d, 5, lam0, &npair);
        if (ok) {
            a_fluid_density(&w, n);
            a_polymer(&w, n, pn, F, u, fa, S);
            for (a = 0; a < np; ++a) {
                buf[3 * a] = w.pux[a]; buf[3 * a + 1] = w.puy[a]; buf[3 * a + 2] = w.puz[a];
            }
            e_u = a_maxdiff(buf, u, 3 * np, &usc) / usc;
            for (i = 0; i < nf; ++i) {
                buf[3 * i] = w.fax[i]; buf[3 * i + 1] = w.fay[i]; buf[3 * i + 2] = w.faz[i];
            }
            e_fa = a_maxdiff(buf, fa, 3 * nf, &fsc) / fsc;
            s_get(&w, x0, v0, py);
            ok = hc_run(&w, 1);
        }
        if (ok) {
            s_get(&w, x0, v1, py);
            for (i = 0; i < nf; ++i)
                for (c = 0; c < 3; ++c) dp[c] += A_MASS(p) * (v1[3 * i + c] - v0[3 * i + c]);
            for (a = 0; a < np; ++a) {
                smin = fmin(smin, S[a]);
                smax = fmax(smax, S[a]);
                for (c = 0; c < 3; ++c) {
                    pred[c] += p->dt * (raw ? S[a] - 1.0 : 0.0) * F[3 * a + c];
                    Fabs += p->dt * fabs(F[3 * a + c]);
                }
            }
            NOTE("%s weights (S_a in %.4f .. %.4f): v(r_a) + F_a/xi within %.1e, sum_a psi_ai F_a within %.1e; "
                 "momentum gained (%.6g, %.6g, %.6g), dt sum_a (S_a - 1) F_a (%.6g, %.6g, %.6g)",
                 raw ? "raw" : "Shepard", smin, smax, e_u, e_fa, dp[0], dp[1], dp[2], pred[0], pred[1], pred[2]);
            CHECK(e_u < tol && e_fa < tol, "%s weights: drift velocity %g, force on the fluid %g", raw ? "raw" : "Shepard",
                  e_u, e_fa);
            for (c = 0; c < 3; ++c)
                CHECK(fabs(dp[c] - pred[c]) < (ABS_FLOAT ? 1e-4 : 1e-12) * Fabs,
                      "%s weights: momentum gained %.12g, dt sum_a (S_a - 1) F_a %.12g (scale %g)",
                      raw ? "raw" : "Shepard", dp[c], pred[c], Fabs);
            if (raw) /* the identity is not trivially zero here */
                CHECK(fabs(pred[0]) + fabs(pred[1]) + fabs(pred[2]) > 1e-3 * Fabs && smax - smin > 0.01,
                      "the scene's weights sum to one too closely (S_a %g .. %g)", smin, smax);
        }
        hcbd_hc_world_destroy(&w);
        free(n); free(fa); free(v0); free(x0); free(v1); free(buf);
    }
}

/* ---- the method of planes ---------------------------------------------
   One step of the world done again here, pair by pair, as the momentum
   each pair hands over (MODEL 6-8): fluid pairs (pressure, and the Morris
   friction and noise: Euler from the velocities of t, or the exact sweep
   in the world's order, hcbd_hc_params_sweep_grid and the order the header
   describes), polymer pairs, and each polymer's force handed to its
   fluid blobs with the Shepard weights.  A record: momentum F dt to the
   receiver, at y, from a giver at y - dy (its image). */
typedef struct s_rec {
    double y, dy, F;
} s_rec;

typedef struct s_mop {
    int nf, np, nrec, cap;
    double *x, *v, *n, *P, *y, *pn, *mu, *F, *vn, *ab; /* ab: sum |term| per blob and axis */
    s_rec *rec;
    a_owner *o;
} s_mop;

static void s_rec_add(s_mop *m, double y, double dy, double F)
{
    if (m->nrec < m->cap) {
        m->rec[m->nrec].y = y;
        m->rec[m->nrec].dy = dy;
        m->rec[m->nrec].F = F;
    }
    m->nrec++;
}

/* The records of the step the world takes next and the fluid velocities
   it ends with (m->vn, before the drift); 0 when the records overflow. */
static int s_exchange(const hcbd_hc_world *w, s_mop *M)
{
    const hcbd_hc_params *p = &w->p;
    const int nf = w->nf, np = w->np, exact = p->pair_integrator == HCBD_PAIR_SHARDLOW;
    const int noise = p->fluctuations && p->kT > 0;
    const double m = A_MASS(p), dt = p->dt, h = p->h, s = w->core.le_offset, vj = p->gdot * p->L[1];
    const double sg = p->sigma, rc = p->rc, cfh = p->p_kuhn * p->kT / p->n_max;
    double *x = M->x, *v = M->v, *n = M->n, *P = M->P, *y = M->y, *F = M->F;
    hcbd_hc_noise_stream ns;
    int i, j, a, b, c, q;
    hcbd_hc_noise_stream_init(&ns, p->seed);
    M->nrec = 0;
    s_get(w, x, v, y);
    for (i = 0; i < nf; ++i) {
        double d[3];
        n[i] = 0;
        for (j = 0; j < nf; ++j) {
            s_sep(p, s, x + 3 * i, x + 3 * j, d);
            n[i] += a_m4(s_norm(d), h);
        }
        P[i] = a_tait(p, n[i]);
    }
    for (i = 0; i < 3 * nf; ++i) M->vn[i] = M->ab[i] = 0; /* the forces of x(t) first */
    /* the owners' order: the sweep's (Euler: any order gives the same) */
    if (!a_sweep_order(p, s, x, nf, M->o)) return 0;
    for (q = 0; q < nf; ++q) {
        i = M->o[q].id;
        for (j = i + 1; j < nf; ++j) {
            double d[3], z[3] = {0, 0, 0}, r, wd, f, Fp, G[3];
            const int k = s_sep(p, s, x + 3 * i, x + 3 * j, d);
            r = s_norm(d);
            if (r >= 2 * h) continue;
            wd = a_m4d(r, h);
            f = -2.0 * p->eta * wd / (n[i] * n[j] * r);
            if (noise) hcbd_hc_noise_fluid_pair(&ns, w->step, i, j, z);
            for (c = 0; c < 3; ++c) {
                const double u = v[3 * i + c] - v[3 * j + c] - (c == 0 ? k * vj : 0.0);
                Fp = -(P[i] / (n[i] * n[i]) + P[j] / (n[j] * n[j])) * wd * d[c] / r;
                M->vn[3 * i + c] += Fp;
                M->vn[3 * j + c] -= Fp;
                M->ab[3 * i + c] += fabs(Fp);
                M->ab[3 * j + c] += fabs(Fp);
                if (exact) {
                    const double e = exp(-2.0 * f * dt / m);
                    const double u1 = u * e + (noise ? sqrt(2.0 * p->kT / m * (1.0 - e * e)) * z[c] : 0.0);
                    G[c] = 0.5 * m * (u1 - u) / dt;
                    v[3 * i + c] += G[c] * dt / m; /* the sweep moves on with these */
                    v[3 * j + c] -= G[c] * dt / m;
                } else {
                    G[c] = -f * u + sqrt(2.0 * p->kT * f / dt) * z[c];
                    M->vn[3 * i + c] += G[c];
                    M->vn[3 * j + c] -= G[c];
                    M->ab[3 * i + c] += fabs(G[c]);
                    M->ab[3 * j + c] += fabs(G[c]);
                }
                if (c == 0) s_rec_add(M, x[3 * i + 1], d[1], Fp + G[0]);
            }
        }
    }
    /* polymers: densities, pair forces, and the forces handed on */
    for (a = 0; a < np; ++a) {
        double d[3];
        M->pn[a] = 0;
        for (b = 0; b < np; ++b) {
            s_sep(p, s, y + 3 * a, y + 3 * b, d);
            M->pn[a] += a_rapid(s_norm(d), sg, rc);
        }
        M->mu[a] = p->p_kuhn > 0 ? a_mu(M->pn[a] / p->n_max, p->chi) : 0.0;
        F[3 * a] = F[3 * a + 1] = F[3 * a + 2] = 0;
    }
    for (a = 0; a < np; ++a)
        for (b = a + 1; b < np; ++b) {
            double d[3], r, fr, lam;
            s_sep(p, s, y + 3 * a, y + 3 * b, d);
            r = s_norm(d);
            if (r >= rc || r < 1e-12 * sg) continue;
            fr = -cfh * (M->mu[a] + M->mu[b]) * a_rapidd(r, sg, rc);
            if (p->alpha > 0) {
                if (hcbd_hc_world_get_lambda(w, a, b, &lam) != HCBD_OK) return 0;
                fr += p->alpha * (lam - (1 - r / rc) * (1 - r / rc)) * (-2.0 * (1 - r / rc) / rc);
            }
            for (c = 0; c < 3; ++c) {
                F[3 * a + c] += fr * d[c] / r;
                F[3 * b + c] -= fr * d[c] / r;
            }
            s_rec_add(M, y[3 * a + 1], d[1], fr * d[0] / r);
        }
    for (a = 0; a < np; ++a) {
        double d[3], S = 0;
        for (i = 0; i < nf; ++i) {
            s_sep(p, s, x + 3 * i, y + 3 * a, d);
            S += a_rapid(s_norm(d), sg, rc) / n[i];
        }
        for (i = 0; i < nf; ++i) {
            double psi;
            s_sep(p, s, x + 3 * i, y + 3 * a, d);
            psi = a_rapid(s_norm(d), sg, rc) / n[i] / S;
            if (psi == 0) continue;
            for (c = 0; c < 3; ++c) {
                M->vn[3 * i + c] += psi * F[3 * a + c];
                M->ab[3 * i + c] += fabs(psi * F[3 * a + c]);
            }
            s_rec_add(M, x[3 * i + 1], d[1], psi * F[3 * a]);
        }
    }
    for (i = 0; i < 3 * nf; ++i) M->vn[i] = v[i] + dt / m * (M->vn[i] + m * p->g[i % 3]);
    return M->nrec <= M->cap;
}

/* adds momentum q to plane k's sum for each plane y_k that the open
   interval (lo, hi) holds, as it stands or one box height away */
static void s_planes(const double *yk, int K, double Ly, double lo, double hi, double q, double *sum)
{
    int k, sh;
    for (k = 0; k < K; ++k)
        for (sh = -1; sh <= 1; ++sh) {
            const double yp = yk[k] + sh * Ly;
            if (yp > lo && yp < hi) sum[k] += q;
        }
}

/* A sheared run at Table I (hcbd_hc_params_default: time in us; 8^3
   sigma^3, 122 fluid blobs and 306 polymers, C = 2.5 c*), one sub-step of
   12.5 us, Wi = gdot tau_lambda = 10, Shepard weights: the momentum
   carried up across K planes of constant y, away from the sheared
   boundary (y_k = (k + 1/2) L_y / K), per area and time: by the blobs
   that cross them in the drift (m v_x of the velocity they drift with)
   and by the pair impulses of the step across them.  Its mean over the
   planes is minus the stress.  Every step the velocities this replay
   predicts must be the world's (so the impulses are the step's); over the
   run the mean difference between the planes' stress and the split's
   total must vanish within its block error. */
static void s_plane_run(hcbd_pair_integrator pi, int fluct, int nsteps, double *rel, int *ok_out)
{
    enum { K = 16, NB = 10 };
    hcbd_hc_world_def d = hcbd_hc_world_def_default();
    hcbd_hc_params *p = &d.params;
    hcbd_hc_world w;
    s_mop M;
    double yk[K], *diff = (double *)malloc(sizeof(double) * (size_t)nsteps), mean_mop = 0, mean_vir = 0, e_v = 0;
    double plane[K], mean_k[K], *x1 = NULL, *v1 = NULL, *py = NULL, A, col[HCBD_HC_NSTRESS] = {0}, dm, de;
    const int nf = 122, np = 306;
    int st, k, i, ok = 1;
    *ok_out = 0;
    p->L[0] = p->L[1] = p->L[2] = 8.0;
    p->dt = 12.5;
    p->gdot = 10.0 / p->tau_lambda;
    p->pair_integrator = pi;
    p->fluctuations = fluct;
    A = p->L[0] * p->L[2];
    d.fluid_capacity = nf;
    d.polymer_capacity = np;
    memset(&M, 0, sizeof M);
    M.cap = 200000;
    M.x = (double *)malloc(sizeof(double) * 3 * nf); M.v = (double *)malloc(sizeof(double) * 3 * nf);
    M.vn = (double *)malloc(sizeof(double) * 3 * nf); M.ab = (double *)malloc(sizeof(double) * 3 * nf);
    M.n = (double *)malloc(sizeof(double) * nf); M.P = (double *)malloc(sizeof(double) * nf);
    M.y = (double *)malloc(sizeof(double) * 3 * np); M.F = (double *)malloc(sizeof(double) * 3 * np);
    M.pn = (double *)malloc(sizeof(double) * np); M.mu = (double *)malloc(sizeof(double) * np);
    M.rec = (s_rec *)malloc(sizeof(s_rec) * (size_t)M.cap);
    M.o = (a_owner *)malloc(sizeof(a_owner) * nf);
    x1 = (double *)malloc(sizeof(double) * 3 * nf); v1 = (double *)malloc(sizeof(double) * 3 * nf);
    py = (double *)malloc(sizeof(double) * 3 * np);
    for (k = 0; k < K; ++k) {
        yk[k] = (k + 0.5) * p->L[1] / K;
        mean_k[k] = 0;
    }
    if (!hc_create(&w, &d)) goto out;
    if (!a_ok(&w, hcbd_hc_world_place_fluid_lattice(&w, nf), "lattice") ||
        !a_ok(&w, hcbd_hc_world_place_polymers_random(&w, np), "polymers"))
        goto done;
    for (st = 0; st < nsteps && ok; ++st) {
        double got[HCBD_HC_NSTRESS], dvmax = 0, mop = 0;
        hcbd_hc_world_stress_enable(&w, 1);
        if (!s_exchange(&w, &M)) {
            CHECK(0, "replay: more than %d pair records or no pair variable", M.cap);
            break;
        }
        if (!hc_run(&w, 1)) break;
        hcbd_hc_world_stress_read(&w, got, NULL);
        s_get(&w, x1, v1, py);
        for (k = 0; k < K; ++k) plane[k] = 0;
        for (i = 0; i < M.nrec; ++i) { /* sign(dy) F: the upper one's gain */
            const s_rec *r = M.rec + i;
            if (r->dy > 0) s_planes(yk, K, p->L[1], r->y - r->dy, r->y, r->F * p->dt, plane);
            else s_planes(yk, K, p->L[1], r->y, r->y - r->dy, -r->F * p->dt, plane);
        }
        for (i = 0; i < nf; ++i) {
            const double y0 = M.x[3 * i + 1], dy = M.vn[3 * i + 1] * p->dt;
            /* the drift across the sheared boundary shifts v_x by -k gdot L_y */
            const int kk = y0 + dy >= p->L[1] ? 1 : y0 + dy < 0 ? -1 : 0;
            const double vx = v1[3 * i] + kk * p->gdot * p->L[1];
            /* round-off, and the world's fixed-point grid of the fluid's
               pair sums: 1/(2 q) for each of at most nf terms */
            const double g = nf / w.core.qF, sx = p->dt / A_MASS(p) * (1e-9 * M.ab[3 * i] + g);
            const double sy = p->dt / A_MASS(p) * (1e-9 * M.ab[3 * i + 1] + g);
            dvmax = fmax(dvmax, fabs(vx - M.vn[3 * i]) / sx);
            dvmax = fmax(dvmax, fabs(v1[3 * i + 1] - M.vn[3 * i + 1]) / sy);
            if (dy > 0) s_planes(yk, K, p->L[1], y0, y0 + dy, A_MASS(p) * M.vn[3 * i], plane);
            else s_planes(yk, K, p->L[1], y0 + dy, y0, -A_MASS(p) * M.vn[3 * i], plane);
        }
        e_v = fmax(e_v, dvmax);
        for (k = 0; k < K; ++k) {
            plane[k] = -plane[k] / (A * p->dt);
            mean_k[k] += plane[k] / nsteps;
            mop += plane[k] / K;
        }
        diff[st] = mop - got[HCBD_HC_S_TOTAL];
        mean_mop += mop / nsteps;
        mean_vir += got[HCBD_HC_S_TOTAL] / nsteps;
        for (k = 0; k < HCBD_HC_NSTRESS; ++k) col[k] += got[k] / nsteps;
    }
    if (st < nsteps) goto done;
    block_stats(diff, nsteps, NB, &dm, &de);
    NOTE("%s pairs, fluctuations %s, %d steps: replayed velocities within %.2f of round-off; stress: "
         "planes %.6g, split %.6g (fluid %.4g = kinetic %.3g + pressure %.3g + viscous %.4g + noise %.3g, polymer "
         "%.4g, interaction %.4g); planes - split %.3g +- %.2g", pi == HCBD_PAIR_SHARDLOW ? "exact" : "Euler",
         fluct ? "on" : "off", nsteps, e_v, mean_mop, mean_vir, col[4], col[0], col[1], col[2], col[3], col[7],
         col[8], dm, de);
    NOTE("  the planes one by one (steady flux: alike): %.5g %.5g %.5g %.5g ... %.5g %.5g", mean_k[0], mean_k[1],
         mean_k[2], mean_k[3], mean_k[K - 2], mean_k[K - 1]);
    CHECK(e_v < (ABS_FLOAT ? 1e5 : 1), "the replayed step's velocities are off the world's by %g of round-off (1e-9 "
          "of dt/m sum |pair terms| and the fixed-point grid)", e_v);
    *rel = fabs(dm) / fabs(mean_vir);
    if (!t_quick)
        CHECK(fabs(dm) < 4.0 * de, "%s pairs: the planes' stress %.8g is not the split's %.8g (difference %.3g +- %.2g)",
              pi == HCBD_PAIR_SHARDLOW ? "exact" : "Euler", mean_mop, mean_vir, dm, de);
    *ok_out = 1;
done:
    hcbd_hc_world_destroy(&w);
out:
    free(diff); free(M.x); free(M.v); free(M.vn); free(M.ab); free(M.n); free(M.P); free(M.y); free(M.F); free(M.pn);
    free(M.mu); free(M.rec); free(M.o); free(x1); free(v1); free(py);
}

void test_hc_stress_planes(void)
{
    double rel = 0;
    int ok;
    s_plane_run(HCBD_PAIR_EULER, 0, t_quick ? 20 : 400, &rel, &ok);
    s_plane_run(HCBD_PAIR_SHARDLOW, 1, t_quick ? 20 : 400, &rel, &ok);
}
#endif
