/* The 2018 model's equations written again for the tests (MODEL.md 1,
   6-8): own kernels and brute-force pair sums that read nothing of the
   library's but its state, and the disordered one-step scene that the
   absolute and the stress tests share. */
#ifndef HCBD_HC_REF_H
#define HCBD_HC_REF_H
#include "test.h"
#if HCBD_MODEL == HCBD_MODEL_HCBD

static const double PI_A = 3.14159265358979323846;
/* exact identities hold to round-off of the stored state: hcbd_real */
#define ABS_FLOAT (sizeof(hcbd_real) == sizeof(float))
/* the blob mass m = rho / nbar from the parameters (not the world's copy) */
#define A_MASS(p) ((p)->rho / (p)->nbar)

/* >>the model's kernels, written again (MODEL.md 1) */
static inline double a_m4(double r, double h)
{
    const double q = r / h, c = 1.0 / (4.0 * PI_A * h * h * h), a = 2.0 - q, b = 1.0 - q;
    if (q >= 2.0) return 0.0;
    return q >= 1.0 ? c * a * a * a : c * (a * a * a - 4.0 * b * b * b);
}

static inline double a_m4d(double r, double h)
{
    const double q = r / h, c = 1.0 / (4.0 * PI_A * h * h * h * h), a = 2.0 - q, b = 1.0 - q;
    if (q >= 2.0) return 0.0;
    return q >= 1.0 ? -3.0 * c * a * a : c * (-3.0 * a * a + 12.0 * b * b);
}

static inline double a_rapid(double r, double sg, double rc)
{
    double A;
    if (r >= rc) return 0.0;
    A = 15.0 / (2.0 * PI_A * (pow(rc, 5) - pow(sg, 5)));
    return r <= sg ? A * (rc - sg) * (rc + sg - 2.0 * r) : A * (r - rc) * (r - rc);
}

static inline double a_rapidd(double r, double sg, double rc)
{
    double A;
    if (r >= rc) return 0.0;
    A = 15.0 / (2.0 * PI_A * (pow(rc, 5) - pow(sg, 5)));
    return r <= sg ? -2.0 * A * (rc - sg) : 2.0 * A * (r - rc);
}

/* Flory-Huggins mu(phi) = g'(phi) = 1/2 - chi + sum_k phi^k / (k + 2) */
static inline double a_mu(double phi, double chi)
{
    double s = 0.5 - chi, t = 1.0;
    int k;
    if (phi > 0.5) return -log(1.0 - phi) / (phi * phi) - 1.0 / phi - chi;
    for (k = 1; k < 400 && t > 1e-20; ++k) {
        t *= phi;
        s += t / (k + 2);
    }
    return s;
}

/* x_a - x_b to the nearest image (no Lees-Edwards in these tests); every
   box here is wider than twice the longest range, so one image counts */
static inline double a_sep(const double L[3], double xa, double ya, double za, double xb, double yb,
                    double zb, double d[3])
{
    int c;
    d[0] = xa - xb; d[1] = ya - yb; d[2] = za - zb;
    for (c = 0; c < 3; ++c) d[c] -= L[c] * round(d[c] / L[c]);
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

static inline double a_ff(const hcbd_hc_world *w, int i, int j, double d[3])
{
    return a_sep(w->p.L, w->fx[i], w->fy[i], w->fz[i], w->fx[j], w->fy[j], w->fz[j], d);
}

/* >>the model's equations, brute force (MODEL.md 6, 7, 8) */
/* fluid densities n_i = sum_j w(r_ij), j = i included */
static inline void a_fluid_density(const hcbd_hc_world *w, double *n)
{
    int i, j;
    for (i = 0; i < w->nf; ++i) {
        double s = 0, d[3];
        for (j = 0; j < w->nf; ++j) s += a_m4(a_ff(w, i, j, d), w->p.h);
        n[i] = s;
    }
}

static inline double a_tait(const hcbd_hc_params *p, double n)
{
    return p->P0 * (pow(n / p->nbar, 7.0) - 1.0);
}

/* Per fluid blob: pressure force Fp, Morris viscous force Fv (3 x nf) */
static inline void a_fluid_forces(const hcbd_hc_world *w, const double *n, double *Fp, double *Fv)
{
    const double h = w->p.h, eta = w->p.eta;
    int i, j, c;
    for (i = 0; i < 3 * w->nf; ++i) Fp[i] = Fv[i] = 0;
    for (i = 0; i < w->nf; ++i)
        for (j = 0; j < w->nf; ++j) {
            double d[3], r = a_ff(w, i, j, d), wd, f, pp;
            if (j == i || r >= 2.0 * h) continue;
            wd = a_m4d(r, h);
            pp = a_tait(&w->p, n[i]) / (n[i] * n[i]) + a_tait(&w->p, n[j]) / (n[j] * n[j]);
            f = -2.0 * eta * wd / (n[i] * n[j] * r);
            for (c = 0; c < 3; ++c) Fp[3 * i + c] -= pp * wd * d[c] / r;
            Fv[3 * i + 0] -= f * (w->fvx[i] - w->fvx[j]);
            Fv[3 * i + 1] -= f * (w->fvy[i] - w->fvy[j]);
            Fv[3 * i + 2] -= f * (w->fvz[i] - w->fvz[j]);
        }
}

/* Polymer side: RaPiD densities pn, forces F (Flory-Huggins + transient),
   drift velocities u = v(r_a) + F_a/xi, the forces given to the fluid fa
   (3 x nf) and each polymer's weight sum S_a = sum_i w(r_ai)/n_i (Sout,
   may be NULL); nfl the fluid densities.  The weights psi_ai are
   w(r_ai)/n_i / S_a (Shepard) or, with coupling = raw, w(r_ai)/n_i. */
static inline void a_polymer(const hcbd_hc_world *w, const double *nfl, double *pn, double *F, double *u,
                             double *fa, double *Sout)
{
    const hcbd_hc_params *p = &w->p;
    const double sg = p->sigma, rc = p->rc, cfh = p->p_kuhn * p->kT / p->n_max;
    const int raw = p->coupling == HCBD_COUPLE_RAW;
    double *mu = (double *)malloc(sizeof(double) * (w->np + 1)), *S = (double *)malloc(sizeof(double) * (w->np + 1));
    int a, b, i, c;
    for (a = 0; a < w->np; ++a) {
        double s = 0, d[3];
        for (b = 0; b < w->np; ++b)
            s += a_rapid(a_sep(p->L, w->px[a], w->py[a], w->pz[a], w->px[b], w->py[b], w->pz[b], d), sg, rc);
        pn[a] = s;
        mu[a] = p->p_kuhn > 0 ? a_mu(s / p->n_max, p->chi) : 0.0;
    }
    for (a = 0; a < w->np; ++a) {
        double V[3] = {0, 0, 0}, s = 0;
        for (c = 0; c < 3; ++c) F[3 * a + c] = 0;
        for (b = 0; b < w->np; ++b) {
            double d[3], r = a_sep(p->L, w->px[a], w->py[a], w->pz[a], w->px[b], w->py[b], w->pz[b], d);
            double fr = 0, lam;
            if (b == a || r >= rc) continue;
            fr = -cfh * (mu[a] + mu[b]) * a_rapidd(r, sg, rc);
            if (p->alpha > 0 && hcbd_hc_world_get_lambda(w, a, b, &lam) == HCBD_OK) {
                const double leq = (1 - r / rc) * (1 - r / rc), dleq = -2.0 * (1 - r / rc) / rc;
                fr += p->alpha * (lam - leq) * dleq;
            }
            for (c = 0; c < 3; ++c) F[3 * a + c] += fr * d[c] / r;
        }
        for (i = 0; i < w->nf; ++i) {
            double d[3], r = a_sep(p->L, w->px[a], w->py[a], w->pz[a], w->fx[i], w->fy[i], w->fz[i], d);
            double wt = a_rapid(r, sg, rc) / nfl[i];
            s += wt;
            V[0] += wt * w->fvx[i];
            V[1] += wt * w->fvy[i];
            V[2] += wt * w->fvz[i];
        }
        S[a] = s;
        if (Sout) Sout[a] = s;
        for (c = 0; c < 3; ++c) u[3 * a + c] = V[c] / (raw ? 1.0 : s) + F[3 * a + c] / p->xi;
    }
    for (i = 0; i < 3 * w->nf; ++i) fa[i] = 0;
    for (i = 0; i < w->nf; ++i)
        for (a = 0; a < w->np; ++a) {
            double d[3], r = a_sep(p->L, w->px[a], w->py[a], w->pz[a], w->fx[i], w->fy[i], w->fz[i], d);
            double psi = a_rapid(r, sg, rc) / nfl[i] / (raw ? 1.0 : S[a]);
            for (c = 0; c < 3; ++c) fa[3 * i + c] += psi * F[3 * a + c];
        }
    free(mu);
    free(S);
}

/* largest |x - y| over n values, and the largest |y| (the scale) */
static inline double a_maxdiff(const double *x, const double *y, int n, double *scale)
{
    double m = 0, s = 0;
    int k;
    for (k = 0; k < n; ++k) {
        if (fabs(x[k] - y[k]) > m) m = fabs(x[k] - y[k]);
        if (fabs(y[k]) > s) s = fabs(y[k]);
    }
    if (scale) *scale = s;
    return m;
}

static inline int a_ok(hcbd_hc_world *w, hcbd_result r, const char *what)
{
    if (r != HCBD_OK) {
        printf("    %s: %s\n", what, w->err.msg);
        t_fail = 1;
        return 0;
    }
    return 1;
}

/* The scene of the one-step tests: the fluid's lattice jittered by up to
   0.3 with velocities in (-0.5, 0.5) from the generator of seed, six
   polymers clustered at the centre, and each pair within rc given a pair
   variable off its equilibrium (lam0[6 a + b], NAN beyond rc; *npair of
   them).  Returns 0 when a call failed (the world then created or not). */
static inline int a_step_scene(hcbd_hc_world *w, const hcbd_hc_world_def *d, uint64_t seed, double lam0[36],
                        int *npair)
{
    const hcbd_hc_params *p = &d->params;
    const int nf = d->fluid_capacity, np = 6;
    const double cl[6][3] = {{0, 0, 0}, {1.3, 0.2, -0.4}, {0.3, 1.5, 0.5}, {-0.9, 0.8, 1.1},
                             {0.7, -1.2, 0.9}, {-0.2, -0.6, -1.4}};
    double *xyz = (double *)malloc(sizeof(double) * 3 * nf), *v = (double *)malloc(sizeof(double) * 3 * nf);
    double pxyz[18];
    hcbd_rng g;
    int i, a, b, c, ok;
    *npair = 0;
    hcbd_rng_seed(&g, seed);
    if (!hc_create(w, d)) {
        free(xyz); free(v);
        return 0;
    }
    ok = a_ok(w, hcbd_hc_world_place_fluid_lattice(w, nf), "lattice");
    for (i = 0; i < nf && ok; ++i)
        for (c = 0; c < 3; ++c) {
            double x = (c == 0 ? w->fx[i] : (c == 1 ? w->fy[i] : w->fz[i])) + 0.6 * (hcbd_rng_uniform(&g) - 0.5);
            xyz[3 * i + c] = x - p->L[c] * floor(x / p->L[c]);
            if (xyz[3 * i + c] >= p->L[c]) xyz[3 * i + c] = 0;
            v[3 * i + c] = hcbd_rng_uniform(&g) - 0.5;
        }
    ok = ok && a_ok(w, hcbd_hc_world_set_fluid(w, nf, xyz, v), "fluid");
    for (a = 0; a < np; ++a)
        for (c = 0; c < 3; ++c) pxyz[3 * a + c] = 0.5 * p->L[c] + cl[a][c];
    ok = ok && a_ok(w, hcbd_hc_world_set_polymers(w, np, pxyz), "polymers");
    for (a = 0; a < np && ok; ++a)
        for (b = a + 1; b < np; ++b) {
            double dd[3], r = a_sep(p->L, pxyz[3 * a], pxyz[3 * a + 1], pxyz[3 * a + 2], pxyz[3 * b],
                                    pxyz[3 * b + 1], pxyz[3 * b + 2], dd);
            lam0[6 * a + b] = NAN;
            if (r >= p->rc) continue;
            lam0[6 * a + b] = (1 - r / p->rc) * (1 - r / p->rc) + 0.3 - 0.1 * ((a + b) % 4);
            ok = a_ok(w, hcbd_hc_world_set_lambda(w, a, b, lam0[6 * a + b]), "set_lambda");
            ++*npair;
        }
    free(xyz); free(v);
    return ok;
}
/* The exact fluid sweep's order, as the header describes it next to
   hcbd_hc_params_sweep_grid: each blob's place relative to blob 0 (x tilted by
   t = s'/L_y under the Lees-Edwards offset s), its block, colour and fine
   cell; owners go by colour, block, fine cell and id.  x: nf interleaved
   positions; o: the owners in sweep order.  Returns 0 if the grid is
   refused. */
typedef struct a_owner {
    int colour, block, fine, id;
} a_owner;

static inline int a_owner_cmp(const void *a, const void *b)
{
    const a_owner *x = (const a_owner *)a, *y = (const a_owner *)b;
    if (x->colour != y->colour) return x->colour < y->colour ? -1 : 1;
    if (x->block != y->block) return x->block < y->block ? -1 : 1;
    if (x->fine != y->fine) return x->fine < y->fine ? -1 : 1;
    return x->id < y->id ? -1 : (x->id > y->id);
}

static inline int a_sweep_order(const hcbd_hc_params *p, double s, const double *x, int nf, a_owner *o)
{
    const double *L = p->L, t = (s - L[0] * floor(s / L[0] + 0.5)) / L[1];
    int nb[3], nc[3], nfc[3], i, c;
    char msg[160];
    if (hcbd_hc_params_sweep_grid(p, s, nb, nc, nfc, msg, sizeof msg) != HCBD_OK) return 0;
    for (i = 0; i < nf; ++i) {
        double r[3];
        int cb[3], cf[3];
        r[1] = x[3 * i + 1] - x[1];
        r[0] = x[3 * i] - x[0] - t * r[1];
        r[2] = x[3 * i + 2] - x[2];
        for (c = 0; c < 3; ++c) {
            r[c] -= L[c] * floor(r[c] / L[c]);
            cb[c] = (int)(r[c] * (nb[c] / L[c]));
            cf[c] = (int)(r[c] * (nfc[c] / L[c]));
            if (cb[c] > nb[c] - 1) cb[c] = nb[c] - 1;
            if (cf[c] > nfc[c] - 1) cf[c] = nfc[c] - 1;
        }
        o[i].colour = cb[0] % nc[0] + nc[0] * (cb[1] % nc[1] + nc[1] * (cb[2] % nc[2]));
        o[i].block = (cb[2] * nb[1] + cb[1]) * nb[0] + cb[0];
        o[i].fine = (cf[2] * nfc[1] + cf[1]) * nfc[0] + cf[0];
        o[i].id = i;
    }
    qsort(o, (size_t)nf, sizeof *o, a_owner_cmp);
    return 1;
}

#endif
#endif
