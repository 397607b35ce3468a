/* The coefficients of GI-BD and of the wall model in absolute terms
   (MODEL 1-5): every prediction below is written here from the equations,
   in long double, from the positions and velocities the world holds; none
   comes from the library's own constants.  The identities are one-step and
   deterministic where the library exposes its random numbers (pair normals
   by hcbd_world_pair_normals, Brownian normals from the per-particle generator
   states), so an error of a single coefficient by 10 % fails by orders of
   magnitude more than round-off; the noise amplitudes are also measured
   statistically (one-step variances from v = 0), against errors from block
   averages, so they do not rest on the library's normals alone. */
#include "test.h"

typedef long double ld;
#define ABS_PI 3.141592653589793238462643383279502884L
/* the float build stores positions and velocities in float */
#define ABS_FLOAT (sizeof(hcbd_real) < sizeof(double))

/* W-Wendland (MODEL 1), range Rc. */
static ld abs_W(ld r, ld Rc)
{
    ld q = r / Rc, a = 1 - q;
    if (r >= Rc) return 0;
    return 21 / (2 * ABS_PI * Rc * Rc * Rc) * a * a * a * a * (4 * q + 1);
}

/* f_ij = 15/(2 pi Rc^3) m_j (1/rho_i + 1/rho_j)(1 - r/Rc)^3 (MODEL 2). */
static ld abs_f(ld r, ld Rc, ld mj, ld rhoi, ld rhoj)
{
    ld a = 1 - r / Rc;
    if (r >= Rc) return 0;
    return 15 / (2 * ABS_PI * Rc * Rc * Rc) * mj * (1 / rhoi + 1 / rhoj) * a * a * a;
}

/* Density normalisation: 1/(1 + w(0)/n#) (2016 eq. 7) or 1 (2014). */
static ld abs_norm(const hcbd_params *p)
{
    return p->density_norm == 2016 ? 1 / (1 + abs_W(0, p->Rc) / p->density) : 1;
}

/* Minimum image; the image count is found in double (fast; it is an
   integer, so nothing is lost). */
static ld abs_mi(ld d, ld L) { return d - L * (ld)round((double)d / (double)L); }

/* Minimum-image separation x_i - x_j of an interleaved array. */
static ld abs_sep(const double *x, int i, int j, const double L[3], ld d[3])
{
    int c;
    ld r2 = 0;
    for (c = 0; c < 3; ++c) {
        d[c] = abs_mi((ld)x[3 * i + c] - x[3 * j + c], L[c]);
        r2 += d[c] * d[c];
    }
    return sqrtl(r2);
}

/* 2014 eq. 28 with r -> r/sigma, energy unit eps: beta V and -dV/dr. */
static ld abs_star_V(ld r, ld f, ld sigma, ld eps)
{
    ld A = eps * 5 / 18 * powl(f, 1.5L), B = 1 / (1 + sqrtl(f) / 2), q = r / sigma;
    if (q <= 1) return A * (-logl(q) + B);
    return A * B / q * expl(-(sqrtl(f) / 2) * (q - 1));
}

static ld abs_star_F(ld r, ld f, ld sigma, ld eps)
{
    ld A = eps * 5 / 18 * powl(f, 1.5L), B = 1 / (1 + sqrtl(f) / 2), k = sqrtl(f) / 2;
    ld q = r / sigma;
    if (q <= 1) return A / r; /* -d/dr of -A ln(r/sigma) */
    /* -d/dr [A B e^{-k(q-1)} / q] = A B e^{-k(q-1)} (1/q^2 + k/q) / sigma */
    return A * B * expl(-k * (q - 1)) * (1 / (q * q) + k / q) / sigma;
}

/* lap of the pair energy, U'' + 2 U'/r = -dF/dr - 2 F/r, with dF/dr by a
   central difference of the force above (long double: error < 1e-8). */
static ld abs_star_lap(ld r, ld f, ld sigma, ld eps)
{
    ld h = 1e-5L * r;
    ld dF = (abs_star_F(r + h, f, sigma, eps) - abs_star_F(r - h, f, sigma, eps)) / (2 * h);
    return -dF - 2 * abs_star_F(r, f, sigma, eps) / r;
}

/* The Brownian normals of particle `id` in its next step (counter based:
   keyed by seed, step and id): R_n with Euler-Maruyama, (R_n + R_(n+1)) / 2
   with Leimkuhler-Matthews. */
static void abs_bd_normals(const hcbd_world *w, int id, ld out[3])
{
    double z[3], z1[3];
    int c;
    hcbd_world_particle_normals(w, w->step, id, z);
    hcbd_world_particle_normals(w, w->step + 1, id, z1);
    for (c = 0; c < 3; ++c) out[c] = w->p.brownian == HCBD_BROWNIAN_LM ? ((ld)z[c] + z1[c]) / 2 : z[c];
}

/* ------------------------------------------------------------------------
   One GI-BD step of a bulk world (no walls, no shear) from MODEL 2:
     rho_i = m N (w(0) + sum_j w(R_ij)),  N the density normalisation
     F_i   = sum_j F(R_ij) e_ij (+ fext)
     Euler:    dv_i = (F_i + G)/m dt + sum_j (f_ij/tau)(v_j - v_i) dt
                      + sum_j +-sqrt(2 kT S_ij dt/tau) zeta_ij / m
               dR_i = v_i dt + F_i/xi dt + sqrt(2 kT dt/xi) n_i
     Shardlow: pairs (a < b) in turn, u = v_a - v_b,
               u' = u e + sqrt(2 kT/m (1 - e^2)) zeta, e = exp(-2 S dt/(m tau)),
               after the kick u_i = v_i + (F_i + G)/m dt (v starts from u),
               v_a += (u' - u)/2, v_b -= (u' - u)/2, and
               dR_i = (u_i + v_i(t + dt)) dt/2 + F_i/xi dt + sqrt(2 kT dt/xi) n_i
   S_ij = m f_ij, m = xi' tau, zeta_ij the pair's normals (+ for the lower
   id), n_i the particle's normals (abs_bd_normals).  G = fext when it drives only the
   background.  x, v in id order; x1, v1, rho out. */
enum { ABS_NMAX = 64 };

static void abs_ref_step(const hcbd_world *w, const double *x, const double *v, ld *x1, ld *v1,
                         ld *rho)
{
    const hcbd_params *p = &w->p;
    const int n = w->n, noise = p->kT > 0, star = p->potential == HCBD_POT_STAR;
    const ld m = (ld)p->xip * p->tau, dt = p->dt, tau = p->tau, kT = p->kT, Rc = p->Rc;
    const ld nrm = abs_norm(p);
    static ld F[ABS_NMAX][3], G[3], vs[ABS_NMAX][3], nb[ABS_NMAX][3], nb_u[ABS_NMAX][3];
    int i, j, c;
    for (i = 0; i < n; ++i) {
        ld s = abs_W(0, Rc), d[3];
        for (j = 0; j < n; ++j)
            if (j != i) s += abs_W(abs_sep(x, i, j, p->L, d), Rc);
        rho[i] = m * nrm * s;
    }
    for (c = 0; c < 3; ++c) G[c] = p->fext_background_only ? p->fext[c] : 0;
    for (i = 0; i < n; ++i) {
        for (c = 0; c < 3; ++c) F[i][c] = p->fext_background_only ? 0 : p->fext[c];
        for (j = 0; j < n && star; ++j) {
            ld d[3], r;
            if (j == i) continue;
            r = abs_sep(x, i, j, p->L, d);
            if (r < p->rcut)
                for (c = 0; c < 3; ++c) F[i][c] += abs_star_F(r, p->f, p->sigma, p->star_eps) * d[c] / r;
        }
        for (c = 0; c < 3; ++c) nb[i][c] = 0;
        if (noise) abs_bd_normals(w, i, nb[i]);
    }
    if (p->pair_integrator == HCBD_PAIR_EULER) {
        for (i = 0; i < n; ++i)
            for (c = 0; c < 3; ++c) v1[3 * i + c] = v[3 * i + c] + (F[i][c] + G[c]) * dt / m;
        for (i = 0; i < n; ++i)
            for (j = 0; j < n; ++j) {
                ld d[3], r, fij;
                double z[3];
                if (j == i) continue;
                r = abs_sep(x, i, j, p->L, d);
                if (r >= Rc) continue;
                fij = abs_f(r, Rc, m, rho[i], rho[j]);
                if (noise) hcbd_world_pair_normals(w, w->step, i < j ? i : j, i < j ? j : i, z);
                for (c = 0; c < 3; ++c) {
                    v1[3 * i + c] += fij / tau * ((ld)v[3 * j + c] - v[3 * i + c]) * dt;
                    if (noise) /* S_ij = m_i f_ij */
                        v1[3 * i + c] += (i < j ? 1 : -1) * sqrtl(2 * kT * m * fij * dt / tau) * z[c] / m;
                }
            }
        for (i = 0; i < n; ++i)
            for (c = 0; c < 3; ++c)
                x1[3 * i + c] = x[3 * i + c] + v[3 * i + c] * dt + F[i][c] * dt / p->xi +
                                sqrtl(2 * kT * dt / p->xi) * nb[i][c];
    } else {
        /* the library's sweep order: rows of y-z cells at least Rc wide (a
           multiple of 3 along each axis, or one) placed relative to
           particle 0, their nine colours (y row mod 3, z row mod 3) in
           turn, and in each row owners then partners by increasing id (rows
           of one colour touch disjoint particles, so their order is free) */
        int ns[2], colour[ABS_NMAX], col;
        for (c = 0; c < 2; ++c) {
            int k = (int)floor(p->L[c + 1] / p->Rc);
            ns[c] = k >= 3 ? 3 * (k / 3) : 1;
        }
        for (i = 0; i < n; ++i) {
            int rw[2];
            for (c = 0; c < 2; ++c) {
                double s = x[3 * i + 1 + c] - x[1 + c];
                if (s < 0) s += p->L[1 + c];
                rw[c] = (int)(s * (ns[c] / p->L[1 + c]));
                if (rw[c] > ns[c] - 1) rw[c] = ns[c] - 1;
            }
            colour[i] = rw[0] % 3 + 3 * (rw[1] % 3);
        }
        /* the kick first, with the forces of t (kept for the drift) */
        for (i = 0; i < n; ++i)
            for (c = 0; c < 3; ++c) vs[i][c] = nb_u[i][c] = v[3 * i + c] + (F[i][c] + G[c]) * dt / m;
        for (col = 0; col < 9; ++col)
        for (i = 0; i < n; ++i)
            for (j = i + 1; j < n; ++j) {
                ld d[3], r, e;
                double z[3] = {0, 0, 0};
                if (colour[i] != col) break;
                r = abs_sep(x, i, j, p->L, d);
                if (r >= Rc) continue;
                e = expl(-2 * m * abs_f(r, Rc, m, rho[i], rho[j]) * dt / (m * tau));
                if (noise) hcbd_world_pair_normals(w, w->step, i, j, z);
                for (c = 0; c < 3; ++c) {
                    ld u = vs[i][c] - vs[j][c], up = u * e + sqrtl(2 * kT / m * (1 - e * e)) * z[c];
                    vs[i][c] += (up - u) / 2;
                    vs[j][c] -= (up - u) / 2;
                }
            }
        for (i = 0; i < n; ++i)
            for (c = 0; c < 3; ++c) {
                v1[3 * i + c] = vs[i][c];
                x1[3 * i + c] = x[3 * i + c] + (nb_u[i][c] + vs[i][c]) * dt / 2 + F[i][c] * dt / p->xi +
                                sqrtl(2 * kT * dt / p->xi) * nb[i][c];
            }
    }
}

/* Largest deviations of one library step from abs_ref_step, in units of
   the tolerance: positions against tol_x, velocities against tol_v times
   (1 + |v|); densities relative. */
typedef struct { double ex, ev, erho, dv_max; } abs_dev;

static abs_dev abs_compare_step(hcbd_world *w, double tol_x, double tol_v)
{
    static double x[3 * ABS_NMAX], v[3 * ABS_NMAX], xa[3 * ABS_NMAX], va[3 * ABS_NMAX];
    static ld x1[3 * ABS_NMAX], v1[3 * ABS_NMAX], rho[ABS_NMAX];
    abs_dev e = {0, 0, 0, 0};
    int i, c, n = w->n;
    /* the step sums pair terms on a fixed-point grid of 1/q (hcbd.h, pair
       sums): each of a particle's n - 1 terms is off by at most 1/(2q) */
    const double m = w->gibd ? w->m : 1, gF = 0.5 * (n - 1) / w->core.qF;
    const double gP = w->gibd && w->qP > 0 ? 0.5 * (n - 1) / w->qP : 0;
    const double gv = (gF * w->p.dt + gP) / m, gx = gF * w->p.dt / w->p.xi + gv * w->p.dt;
    hcbd_world_get_positions(w, x, 0);
    hcbd_world_get_velocities(w, v);
    abs_ref_step(w, x, v, x1, v1, rho);
    if (!run(w, 1)) return e;
    hcbd_world_get_positions(w, xa, 0);
    hcbd_world_get_velocities(w, va);
    for (i = 0; i < n; ++i) {
        for (c = 0; c < 3; ++c) {
            ld dx = abs_mi((ld)xa[3 * i + c] - x[3 * i + c], w->p.L[c]) - (x1[3 * i + c] - x[3 * i + c]);
            ld dv = va[3 * i + c] - v1[3 * i + c];
            e.ex = fmax(e.ex, (double)fabsl(dx) / (tol_x + gx));
            e.ev = fmax(e.ev, (double)(fabsl(dv) / (tol_v * (1 + fabsl(v1[3 * i + c])) + gv)));
            e.dv_max = fmax(e.dv_max, fabs(va[3 * i + c] - v[3 * i + c]));
        }
        /* the densities of time t, which the step used */
        e.erho = fmax(e.erho, (double)fabsl(w->rho[w->slot[i]] / rho[i] - 1));
    }
    return e;
}

/* ------------------------------------------------------------------------
   Two particles, ideal, kT = 0: the relative background velocity u decays
   in one step by exactly 1 - 2 f dt/tau (Euler) or exp(-2 f dt/tau)
   (Shardlow), f = f_01 = f_10 from the densities summed here; the centre of
   mass velocity stays; the displacement is v(t) dt (Euler) or the mean of
   v(t) and v(t + dt) times dt (Shardlow: half a drift on each side of the
   sweep).  Three distances, both densities, xi' != xi. */
void test_abs_pair_friction(void)
{
    const double rs[3] = {0.4, 1.3, 2.3};
    const double tol = ABS_FLOAT ? 2e-6 : 1e-13;
    double worst = 0, worst_x = 0, worst_cm = 0;
    int integ, norm, k;
    for (integ = 0; integ < 2; ++integ)
        for (norm = 2014; norm <= 2016; norm += 2)
            for (k = 0; k < 3; ++k) {
                hcbd_world_def d = scene(2, 0.24);
                hcbd_world w;
                double xyz[6], v0[6] = {1.5, -0.8, 0.6, -0.7, 0.9, 0.2}, v1[6], x1[6];
                const double e[3] = {0.6, 0.48, 0.64};
                ld r = rs[k], rho, f, fac, m, u, up;
                int c;
                d.params.L[0] = d.params.L[1] = d.params.L[2] = 9.0;
                d.params.potential = HCBD_POT_IDEAL;
                d.params.kT = 0;
                d.params.xi = 3.0;
                d.params.xip = 0.7;
                d.params.tau = 1e-2;
                d.params.dt = 1e-3;
                d.params.density_norm = norm;
                d.params.pair_integrator = integ ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
                if (!make_world(&w, &d)) return;
                for (c = 0; c < 3; ++c) {
                    xyz[c] = 4.0;
                    xyz[3 + c] = 4.0 + rs[k] * e[c];
                }
                hcbd_world_set_positions(&w, 2, xyz);
                hcbd_world_set_velocities(&w, v0);
                hcbd_world_get_positions(&w, xyz, 0); /* as stored */
                if (!run(&w, 1)) return;
                hcbd_world_get_velocities(&w, v1);
                hcbd_world_get_positions(&w, x1, 0);
                {
                    ld dd[3];
                    r = abs_sep(xyz, 0, 1, d.params.L, dd);
                }
                m = (ld)d.params.xip * d.params.tau;
                rho = m * abs_norm(&d.params) * (abs_W(0, d.params.Rc) + abs_W(r, d.params.Rc));
                f = abs_f(r, d.params.Rc, m, rho, rho);
                fac = integ ? expl(-2 * f * d.params.dt / d.params.tau) : 1 - 2 * f * d.params.dt / d.params.tau;
                for (c = 0; c < 3; ++c) {
                    /* Shardlow: the mean of the velocities before and after the sweep (no force) */
                    ld vb = integ ? ((ld)v0[c] + v1[c]) / 2 : v0[c];
                    ld vc = integ ? ((ld)v0[3 + c] + v1[3 + c]) / 2 : v0[3 + c];
                    u = (ld)v0[c] - v0[3 + c];
                    up = (ld)v1[c] - v1[3 + c];
                    /* plus the fixed-point grid of the exchange, 1/(2 qP) a side */
                    worst = fmax(worst, (double)(fabsl(up - u * fac) /
                                                 (10 * tol * fabsl(u) + 1 / (w.qP * m))));
                    worst_cm = fmax(worst_cm, (double)fabsl(((ld)v1[c] + v1[3 + c]) - ((ld)v0[c] + v0[3 + c])));
                    worst_x = fmax(worst_x, (double)fabsl((ld)x1[c] - xyz[c] - vb * d.params.dt));
                    worst_x = fmax(worst_x, (double)fabsl((ld)x1[3 + c] - xyz[3 + c] - vc * d.params.dt));
                }
                if (k == 1 && norm == 2016)
                    NOTE("%s, r = %.1f: u'/u = %.10f, predicted %.10f (f = %.6f)",
                         integ ? "Shardlow" : "Euler", rs[k], (double)(up / u), (double)fac, (double)f);
                CHECK(fabsl(w.rho[w.slot[0]] / rho - 1) < tol * 10, "rho %.15g, want %.15Lg", (double)w.rho[w.slot[0]], rho);
                hcbd_world_destroy(&w);
            }
    CHECK(worst < 1, "decay factor of v_0 - v_1 off by %g of its tolerance", worst);
    CHECK(worst_cm < 10 * tol, "centre-of-mass velocity changed by %g", worst_cm);
    CHECK(worst_x < (ABS_FLOAT ? 1e-6 : 1e-14), "displacement off v dt by %g", worst_x);
}

/* ------------------------------------------------------------------------
   A full step of an 18-particle cluster (star forces on both branches of
   eq. 28, friction, pair noise, Brownian noise, a body force) against the
   reference step above: both pair integrators, both densities, three
   parameter sets with xi' != xi, sigma, eps, f, Rc, n#, kT != 1. */
static void abs_cluster(const hcbd_params *p, double *xyz, double *v)
{
    const double a = 1.05 * p->sigma, c0 = 0.5 * p->L[0] - a;
    const ld vth = sqrtl((ld)(p->kT > 0 ? p->kT : 1) / (p->xip * p->tau));
    int k;
    for (k = 0; k < 18; ++k) {
        xyz[3 * k] = c0 + a * (k % 3) + 0.25 * p->sigma * sin(1.3 * k + 0.2);
        xyz[3 * k + 1] = c0 + a * ((k / 3) % 3) + 0.25 * p->sigma * sin(2.1 * k + 1.0);
        xyz[3 * k + 2] = c0 + a * (k / 9) + 0.25 * p->sigma * sin(3.7 * k + 2.0);
        v[3 * k] = (double)(vth * sin(0.7 * k + 0.1));
        v[3 * k + 1] = (double)(vth * cos(1.9 * k + 0.4));
        v[3 * k + 2] = (double)(vth * sin(2.9 * k + 0.3));
    }
}

void test_abs_one_step_replica(void)
{
    double ex = 0, ev = 0, er = 0, dvm = 0;
    int integ, norm, set, steps, table, npair[4] = {0, 0, 0, 0};
    /* table = 1: the star force from its table (error < 1e-9 of the
       formula's, so looser positions and velocities), with the exact
       sweep the step's densities fused into the force pass: sets 1 and 2
       have Rc < rcut and Rc > rcut, so the weights' own cut-off shows */
    for (table = 0; table < 2; ++table)
    for (set = table; set < 3; ++set)
        for (integ = table; integ < 2; ++integ)
            for (norm = 2014; norm <= 2016; norm += 2) {
                const double tol_x = table ? 1e-7 : ABS_FLOAT ? 4e-6 : 1e-12;
                const double tol_v = table ? 1e-7 : ABS_FLOAT ? 1e-5 : 1e-12;
                hcbd_world_def d = scene(18, 0.24);
                hcbd_world w;
                double xyz[54], v[54];
                hcbd_params *p = &d.params;
                p->L[0] = p->L[1] = p->L[2] = 12.0;
                p->density_norm = norm;
                p->pair_integrator = integ ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
                p->force_table = table;
                if (set > 0) {
                    p->f = set == 1 ? 32 : 64;
                    p->sigma = set == 1 ? 1.25 : 0.9;
                    p->star_eps = set == 1 ? 0.7 : 1.8;
                    p->rcut = 2.5 * p->sigma;
                    p->kT = set == 1 ? 1.6 : 0.8;
                    p->xi = set == 1 ? 2.5 : 1.5;
                    p->xip = set == 1 ? 0.4 : 7.0;
                    p->tau = set == 1 ? 5e-3 : 2e-3;
                    p->dt = 2e-4;
                    p->Rc = set == 1 ? 2.2 : 2.8;
                    p->density = set == 1 ? 0.3 : 0.2;
                    p->fext[0] = 4.0; p->fext[1] = -2.0; p->fext[2] = 1.0;
                    p->fext_background_only = set == 2;
                }
                if (!make_world(&w, &d)) return;
                abs_cluster(p, xyz, v);
                if (!table && integ == 0 && norm == 2014) { /* what the cluster covers */
                    int i, j;
                    for (i = 0; i < 18; ++i)
                        for (j = i + 1; j < 18; ++j) {
                            ld dd[3], r = abs_sep(xyz, i, j, p->L, dd);
                            npair[0] += r <= p->sigma;
                            npair[1] += r > p->sigma && r < p->rcut;
                            npair[2] += r < p->Rc;
                            npair[3] += r >= p->Rc && r >= p->rcut;
                        }
                }
                hcbd_world_set_positions(&w, 18, xyz);
                hcbd_world_set_velocities(&w, v);
                /* two steps: the second after a step has mixed the state */
                for (steps = 0; steps < 2; ++steps) {
                    abs_dev e = abs_compare_step(&w, tol_x, tol_v);
                    ex = fmax(ex, e.ex);
                    ev = fmax(ev, e.ev);
                    er = fmax(er, e.erho);
                    dvm = fmax(dvm, e.dv_max);
                    if (e.ex > 1 || e.ev > 1 || e.erho > (ABS_FLOAT ? 1e-5 : 1e-13))
                        CHECK(0, "set %d %s %d%s step %d: position %.3g, velocity %.3g tolerances off, "
                              "density %.3g relative", set, integ ? "Shardlow" : "Euler", norm,
                              table ? " (force table)" : "", steps, e.ex, e.ev, e.erho);
                }
                hcbd_world_destroy(&w);
            }
    NOTE("largest deviation from the reference step: positions %.3g, velocities %.3g of the "
         "tolerances (formula %.0e, %.0e; table 1e-7); densities %.2g relative; largest one-step |dv| %.3g",
         ex, ev, ABS_FLOAT ? 4e-6 : 1e-12, ABS_FLOAT ? 1e-5 : 1e-12, er, dvm);
    NOTE("initial pairs over the three sets: %d on the inner branch (r <= sigma), %d on the "
         "outer, %d within Rc, %d beyond both cut-offs", npair[0], npair[1], npair[2], npair[3]);
    CHECK(npair[0] > 20 && npair[1] > 20 && npair[3] > 20, "the cluster does not cover both "
          "branches and the cut-offs: %d %d %d", npair[0], npair[1], npair[3]);
}

/* ------------------------------------------------------------------------
   Pair noise, measured: isolated dimers (216, every member more than Rc
   from every other dimer), ideal, v = 0 before each step.  The relative
   velocity u of a dimer then has per component the variance
     Euler:    (2/m)^2 2 kT S dt/tau = 8 kT f dt/(tau m)
     Shardlow: 2 kT/m (1 - e^2),  e = exp(-2 f dt/tau),
   with f = f_01 from the densities summed here.  dt/tau = 0.2 makes the
   two differ by ~10 % at short distances.  <u^2/var> = 1 within 4 block
   errors; its error (~0.4 %) resolves a 10 % amplitude error 50 times. */
enum { ABS_ND = 216 };
static int abs_dimers(const hcbd_params *p, double *xyz)
{
    int k, c;
    for (k = 0; k < ABS_ND; ++k) {
        double r = 0.4 + 1.8 * (k % 7) / 6.0, e[3], en;
        e[0] = sin(1.1 * k + 0.3); e[1] = cos(2.3 * k + 0.1); e[2] = sin(0.7 * k + 1.7);
        en = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
        for (c = 0; c < 3; ++c) {
            int g = c == 0 ? k % 6 : c == 1 ? (k / 6) % 6 : k / 36;
            double ctr = (g + 0.5) * p->L[c] / 6;
            xyz[6 * k + c] = ctr - 0.5 * r * e[c] / en;
            xyz[6 * k + 3 + c] = ctr + 0.5 * r * e[c] / en;
        }
    }
    return 2 * ABS_ND;
}

/* Smallest distance between members of different dimers. */
static double abs_dimer_gap(const double *xyz, const double L[3])
{
    double g = HUGE_VAL;
    int i, j;
    for (i = 0; i < 2 * ABS_ND; ++i)
        for (j = i + 1; j < 2 * ABS_ND; ++j) {
            ld d[3];
            if (i / 2 == j / 2) continue;
            g = fmin(g, (double)abs_sep(xyz, i, j, L, d));
        }
    return g;
}

void test_abs_pair_noise_variance(void)
{
    enum { NBLK = 8, NST = 25 };
    int integ, norm;
    for (integ = 0; integ < 2; ++integ)
        for (norm = 2014; norm <= 2016; norm += 2) {
            static double xyz[6 * ABS_ND], zero[6 * ABS_ND], v[6 * ABS_ND], vals[NBLK * NST];
            double mean, err, gap = HUGE_VAL, alt = 0, pm = 0;
            int b, s, k, c;
            for (b = 0; b < NBLK; ++b) {
                hcbd_world_def d = scene(2 * ABS_ND, 0.24);
                hcbd_world w;
                hcbd_params *p = &d.params;
                ld m = 0;
                p->L[0] = p->L[1] = p->L[2] = 33.0;
                p->potential = HCBD_POT_IDEAL;
                p->kT = 1.3;
                p->xi = 40.0; /* slow drift of the dimers */
                p->xip = 5.0;
                p->tau = 1e-2;
                p->dt = 2e-3;
                p->density_norm = norm;
                p->pair_integrator = integ ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
                p->seed = 100 + b;
                m = (ld)p->xip * p->tau;
                if (!make_world(&w, &d)) return;
                abs_dimers(p, xyz);
                hcbd_world_set_positions(&w, 2 * ABS_ND, xyz);
                for (s = 0; s < NST; ++s) {
                    ld sum = 0, salt = 0;
                    hcbd_world_set_velocities(&w, zero);
                    hcbd_world_get_positions(&w, xyz, 0);
                    /* first and last step of a block: the dimers drift by
                       ~0.015 per step against a margin of 1.3 */
                    if (s == 0 || s == NST - 1) gap = fmin(gap, abs_dimer_gap(xyz, p->L));
                    if (!run(&w, 1)) return;
                    hcbd_world_get_velocities(&w, v);
                    for (k = 0; k < ABS_ND; ++k) {
                        ld dd[3], r = abs_sep(xyz, 2 * k, 2 * k + 1, p->L, dd);
                        ld rho = m * abs_norm(p) * (abs_W(0, p->Rc) + abs_W(r, p->Rc));
                        ld f = abs_f(r, p->Rc, m, rho, rho), x = 2 * f * p->dt / p->tau;
                        ld ve = 8 * p->kT * f * p->dt / (p->tau * m);
                        ld vsh = 2 * p->kT / m * (1 - expl(-2 * x));
                        ld var = integ ? vsh : ve, other = integ ? ve : vsh;
                        for (c = 0; c < 3; ++c) {
                            ld u = (ld)v[6 * k + c] - v[6 * k + 3 + c];
                            sum += u * u / var;
                            salt += u * u / other;
                            pm = fmax(pm, fabs(v[6 * k + c] + v[6 * k + 3 + c]) /
                                              (fabs(v[6 * k + c]) + 1e-300));
                        }
                    }
                    vals[b * NST + s] = (double)(sum / (3 * ABS_ND));
                    alt += (double)(salt / (3 * ABS_ND)) / (NBLK * NST);
                }
                hcbd_world_destroy(&w);
            }
            block_stats(vals, NBLK * NST, 20, &mean, &err);
            NOTE("%s %d: <u^2>/var_predicted = %.4f +- %.4f (with the other integrator's formula "
                 "%.4f); closest other dimer %.2f", integ ? "Shardlow" : "Euler", norm, mean, err,
                 alt, gap);
            CHECK(gap > 2.5, "dimers not isolated: gap %g", gap);
            CHECK(fabs(mean - 1) < 4 * err && err < 0.01, "%s %d: one-step variance ratio %g +- %g",
                  integ ? "Shardlow" : "Euler", norm, mean, err);
            CHECK(pm < (ABS_FLOAT ? 1e-5 : 1e-12), "dimer momentum not conserved: %g", pm);
        }
}

/* ------------------------------------------------------------------------
   Brownian displacement, measured: ideal particles; the displacement less
   the drift the step applies (v(t) dt for Euler, (v(t) + v(t + dt)) dt/2 for Shardlow,
   none in classical BD) has per component the variance 2 kT dt/xi with
   Euler-Maruyama, kT dt/xi with Leimkuhler-Matthews (sqrt(kT dt/(2 xi))
   (R_n + R_(n+1))), and mean 0 (kT = 1.7, xi = 2.5, xi' = 0.3).  150000 samples per case: error of
   the variance 0.4 %. */
void test_abs_bd_noise_variance(void)
{
    enum { N = 1000, NS = 50 };
    int k;
    for (k = 0; k < 3; ++k) {
        hcbd_world_def d = scene(N, 0.24);
        hcbd_world w;
        static double x0[3 * N], x1[3 * N], v0[3 * N], v1[3 * N], vals[NS], mvals[NS];
        double mean, err, mm, me, want;
        int s, i;
        d.params.potential = HCBD_POT_IDEAL;
        d.params.kT = 1.7;
        d.params.xi = 2.5;
        d.params.xip = 0.3;
        d.params.tau = 1e-2;
        d.params.dt = 1e-3;
        d.params.skin = 1.0;
        d.params.dynamics = k == 2 ? HCBD_DYN_BD : HCBD_DYN_GIBD;
        d.params.pair_integrator = k == 1 ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
        /* Leimkuhler-Matthews (the default) halves a single step's variance */
        d.params.brownian = k == 0 ? HCBD_BROWNIAN_EULER : HCBD_BROWNIAN_LM;
        want = (k == 0 ? 2 : 1) * d.params.kT * d.params.dt / d.params.xi;
        if (!make_world(&w, &d)) return;
        hcbd_world_place_random(&w, N);
        for (s = 0; s < NS; ++s) {
            ld sum = 0, sm = 0;
            hcbd_world_get_positions(&w, x0, 1);
            if (w.gibd) hcbd_world_get_velocities(&w, v0);
            if (!run(&w, 1)) return;
            hcbd_world_get_positions(&w, x1, 1);
            if (w.gibd) hcbd_world_get_velocities(&w, v1);
            for (i = 0; i < 3 * N; ++i) {
                ld drift = k == 2 ? 0 : (k == 1 ? ((ld)v0[i] + v1[i]) / 2 : v0[i]) * d.params.dt;
                ld dw = (ld)x1[i] - x0[i] - drift;
                sum += dw * dw;
                sm += dw;
            }
            vals[s] = (double)(sum / (3 * N)) / want;
            mvals[s] = (double)(sm / (3 * N)) / sqrt(want);
        }
        block_stats(vals, NS, 10, &mean, &err);
        block_stats(mvals, NS, 10, &mm, &me);
        NOTE("%s: <dW^2>/(%s kT dt/xi) = %.4f +- %.4f, <dW>/sqrt(that) = %.4f +- %.4f",
             k == 2 ? "classical BD, LM" : k ? "GI-BD Shardlow, LM" : "GI-BD Euler pairs, Euler-Maruyama",
             k ? "1" : "2", mean, err, mm, me);
        CHECK(fabs(mean - 1) < 4 * err && err < 0.01, "variance ratio %g +- %g", mean, err);
        CHECK(fabs(mm) < 4 * me + 1e-3, "mean displacement %g +- %g", mm, me);
        hcbd_world_destroy(&w);
    }
}

/* ------------------------------------------------------------------------
   Star potential (2014 eq. 28) written here in long double: the library's
   hcbd_star_potential and hcbd_star_force on both branches and at sigma,
   for three (f, sigma, eps); then the force a BD step applies (one step,
   kT = 0: dR = F dt/xi along the pair), hcbd_world_potential_energy,
   hcbd_world_virial_stress and hcbd_world_config_temperature of a pair at the same
   distances, and nothing beyond rcut. */
void test_abs_star_potential(void)
{
    static const double set[3][3] = {{128, 1, 1}, {32, 1.3, 0.7}, {64, 0.8, 2.5}};
    static const double q[11] = {0.3, 0.55, 0.8, 0.999, 1.0, 1.001, 1.2, 1.6, 2.0, 2.45, 2.6};
    const double e[3] = {0.6, 0.48, 0.64};
    double worst_api = 0, worst_step[2] = {0, 0}, worst_e = 0, worst_s = 0, worst_t = 0, worst_l = 0;
    double self = 0;
    int k, l, c, tab, beyond_moved = 0;
    for (k = 0; k < 3; ++k) {
        const double f = set[k][0], sg = set[k][1], eps = set[k][2];
        for (l = 0; l < 11; ++l) {
            const ld r = q[l] * sg;
            ld V = abs_star_V(r, f, sg, eps), F = abs_star_F(r, f, sg, eps);
            ld h = 1e-6L * r;
            /* the force formula is minus the derivative of the potential's */
            if (q[l] != 1.0)
                self = fmax(self, (double)fabsl((-(abs_star_V(r + h, f, sg, eps) - abs_star_V(r - h, f, sg, eps)) /
                                                 (2 * h)) / F - 1));
            worst_api = fmax(worst_api, (double)fabsl(hcbd_star_potential((double)r, f, sg, eps) / V - 1));
            worst_api = fmax(worst_api, (double)fabsl(hcbd_star_force((double)r, f, sg, eps) / F - 1));
            for (tab = 0; tab < 2; ++tab) {
                hcbd_world_def d = scene(2, 0.24);
                hcbd_world w;
                double xyz[6], x1[6], s9[9], tc[2], Vb;
                ld dd[3], rr, Fr, dt;
                d.params.L[0] = d.params.L[1] = d.params.L[2] = 12.0;
                d.params.force_table = tab;
                d.params.dynamics = HCBD_DYN_BD;
                d.params.kT = 0;
                d.params.xi = 2.5;
                d.params.f = f;
                d.params.sigma = sg;
                d.params.star_eps = eps;
                d.params.rcut = 2.5 * sg;
                /* displacements of ~0.03 (resolved in float storage) */
                dt = 0.03L * d.params.xi / (F > 3e-3L ? F : 3e-3L);
                d.params.dt = (double)dt;
                if (!make_world(&w, &d)) return;
                for (c = 0; c < 3; ++c) {
                    xyz[c] = 5.0;
                    xyz[3 + c] = 5.0 + (double)r * e[c];
                }
                hcbd_world_set_positions(&w, 2, xyz);
                hcbd_world_get_positions(&w, xyz, 0);
                rr = abs_sep(xyz, 0, 1, d.params.L, dd);
                Fr = rr < d.params.rcut ? abs_star_F(rr, f, sg, eps) : 0;
                Vb = hcbd_world_potential_energy(&w);
                if (rr < d.params.rcut)
                    worst_e = fmax(worst_e, (double)fabsl(Vb / abs_star_V(rr, f, sg, eps) - 1));
                else if (Vb != 0)
                    worst_e = HUGE_VAL;
                hcbd_world_virial_stress(&w, s9);
                for (c = 0; c < 9; ++c) {
                    ld want = -(dd[c / 3] * Fr * dd[c % 3] / rr) / (12.0L * 12 * 12);
                    worst_s = fmax(worst_s, (double)(fabsl(s9[c] - want) /
                                                     (1e-300 + fabsl(Fr * rr) / (12.0L * 12 * 12))));
                }
                if (rr < d.params.rcut && hcbd_world_config_temperature(&w, tc) == HCBD_OK) {
                    ld lap = abs_star_lap(rr, f, sg, eps);
                    worst_t = fmax(worst_t, (double)fabsl(tc[0] / (2 * Fr * Fr) - 1));
                    /* (the difference quotient would straddle the kink of F' at sigma) */
                    if (q[l] != 1.0) worst_l = fmax(worst_l, (double)fabsl(tc[1] / (2 * lap) - 1));
                }
                if (!run(&w, 1)) return;
                hcbd_world_get_positions(&w, x1, 0);
                for (c = 0; c < 3; ++c) {
                    ld want = Fr * dd[c] / rr * dt / d.params.xi; /* particle 0 */
                    ld got0 = abs_mi((ld)x1[c] - xyz[c], 12), got1 = abs_mi((ld)x1[3 + c] - xyz[3 + c], 12);
                    if (Fr == 0) beyond_moved += got0 != 0 || got1 != 0;
                    else {
                        worst_step[tab] = fmax(worst_step[tab], (double)(fabsl(got0 - want) / fabsl(Fr * dt / d.params.xi)));
                        worst_step[tab] = fmax(worst_step[tab], (double)(fabsl(got1 + want) / fabsl(Fr * dt / d.params.xi)));
                    }
                }
                hcbd_world_destroy(&w);
            }
        }
    }
    NOTE("relative deviations: API %.2g, step force %.2g (formula) and %.2g (table), energy %.2g, "
         "stress %.2g, config. temperature sum |F|^2 %.2g, sum lap U %.2g; own F vs -dV/dr %.2g",
         worst_api, worst_step[0], worst_step[1], worst_e, worst_s, worst_t, worst_l, self);
    CHECK(self < 1e-8, "test's own force is not -dV/dr: %g", self);
    CHECK(worst_api < 1e-13, "hcbd_star_potential/force off by %g", worst_api);
    CHECK(worst_step[0] < (ABS_FLOAT ? 1e-4 : 1e-10), "step force (formula) off by %g", worst_step[0]);
    /* the cubic table in r^2 (hcbd.h, kernels) promises 1e-9 */
    CHECK(worst_step[1] < (ABS_FLOAT ? 1e-4 : 1e-9), "step force (table) off by %g", worst_step[1]);
    CHECK(worst_e < (ABS_FLOAT ? 1e-5 : 1e-12), "hcbd_world_potential_energy off by %g", worst_e);
    CHECK(worst_s < (ABS_FLOAT ? 1e-5 : 1e-12), "hcbd_world_virial_stress off by %g", worst_s);
    CHECK(worst_t < (ABS_FLOAT ? 1e-5 : 1e-12), "hcbd_world_config_temperature sum |F|^2 off by %g", worst_t);
    /* the lap reference is a difference quotient, good to ~1e-8 */
    CHECK(worst_l < 1e-6, "hcbd_world_config_temperature sum lap U off by %g", worst_l);
    CHECK(beyond_moved == 0, "%d components moved beyond rcut", beyond_moved);
}

/* The step's star force from the cubic table in r^2 (the default) against
   2014 eq. 28 at 1500 distances across both branches and three stars: one
   BD step of a pair at kT = 0 moves each by F dt/xi. */
void test_abs_star_table(void)
{
    static const double set[3][3] = {{128, 1, 1}, {32, 1.3, 0.7}, {256, 0.8, 2.5}};
    double worst = 0, worst_inner = 0;
    int k, l, c;
    for (k = 0; k < 3; ++k)
        for (l = 0; l < 500; ++l) {
            const double f = set[k][0], sg = set[k][1], eps = set[k][2];
            const double q = 0.4 + 2.09 * (l + 0.5) / 500; /* 0.4 .. 2.49 sigma */
            const ld F0 = abs_star_F(q * sg, f, sg, eps);
            hcbd_world_def d = scene(2, 0.24);
            hcbd_world w;
            double xyz[6], x1[6];
            ld dd[3], rr, Fr;
            d.params.L[0] = d.params.L[1] = d.params.L[2] = 12.0;
            d.params.dynamics = HCBD_DYN_BD;
            d.params.kT = 0;
            d.params.f = f;
            d.params.sigma = sg;
            d.params.star_eps = eps;
            d.params.rcut = 2.5 * sg;
            /* a move of 0.03: the fixed-point grid of the displacement (8
               cutmax 2^-50) and the round-off of x + dx are 1e-12 of it */
            d.params.dt = (double)(0.03L * d.params.xi / (F0 > 1e-6L ? F0 : 1e-6L));
            if (!make_world(&w, &d)) return;
            for (c = 0; c < 3; ++c) {
                xyz[c] = 5.0;
                xyz[3 + c] = 5.0 + q * sg * (c == 0 ? 0.6 : c == 1 ? 0.48 : 0.64);
            }
            hcbd_world_set_positions(&w, 2, xyz);
            hcbd_world_get_positions(&w, xyz, 0);
            rr = abs_sep(xyz, 0, 1, d.params.L, dd);
            Fr = abs_star_F(rr, f, sg, eps);
            if (!run(&w, 1)) return;
            hcbd_world_get_positions(&w, x1, 0);
            for (c = 0; c < 3; ++c) {
                ld want = Fr * dd[c] / rr * d.params.dt / d.params.xi;
                ld got = abs_mi((ld)x1[c] - xyz[c], 12);
                double e = (double)(fabsl(got - want) / fabsl(Fr * d.params.dt / d.params.xi));
                if (q <= 1) worst_inner = fmax(worst_inner, e);
                else worst = fmax(worst, e);
            }
            hcbd_world_destroy(&w);
        }
    NOTE("table against 2014 eq. 28: outer branch %.2g, inner branch %.2g (relative to |F|)", worst,
         worst_inner);
    CHECK(worst < (ABS_FLOAT ? 1e-4 : 1e-9), "star force table off by %g", worst);
    CHECK(worst_inner < (ABS_FLOAT ? 1e-4 : 1e-11), "inner branch a/r^2 off by %g", worst_inner);
}

/* ------------------------------------------------------------------------
   Lees-Edwards: a pair straddling the sheared boundary (a at y = 0.3, b at
   Ly - 0.4, b's image below at x_b - s with velocity v_b - gdot Ly), ideal,
   kT = 0, the offset s set.  With u = v_a - (v_b - gdot Ly e_x) the step
   gives u' = u (1 - 2 f dt/tau) (Euler) or u e (Shardlow), f from the
   distance through the sheared image; and when both velocities lie on one
   linear profile seen through the boundary (u = 0) nothing changes at all:
   a jump off by 10 % leaves u_x = 0.1 gdot Ly. */
void test_abs_le_velocity_jump(void)
{
    const double tol = ABS_FLOAT ? 2e-5 : 1e-12;
    double worst = 0, worst0 = 0;
    int integ, zero;
    for (integ = 0; integ < 2; ++integ)
        for (zero = 0; zero < 2; ++zero) {
            hcbd_world_def d = scene(2, 0.24);
            hcbd_world w;
            const double gdot = 1.7, s = 3.1;
            double xyz[6], v0[6], v1[6], L;
            ld m, dd[3], r, rho, f, fac, jump;
            int c;
            d.params.L[0] = d.params.L[1] = d.params.L[2] = 12.9;
            L = 12.9;
            d.params.potential = HCBD_POT_IDEAL;
            d.params.kT = 0;
            d.params.gdot = gdot;
            d.params.tau = 1e-2;
            d.params.dt = 1e-3;
            d.params.xip = 0.6;
            d.params.pair_integrator = integ ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
            if (!make_world(&w, &d)) return;
            xyz[0] = 4.0; xyz[1] = 0.3; xyz[2] = 5.0;
            xyz[3] = 4.5 + s; xyz[4] = L - 0.4; xyz[5] = 5.5;
            hcbd_world_set_positions(&w, 2, xyz);
            w.core.le_offset = s;
            jump = (ld)gdot * L;
            v0[0] = 0.8; v0[1] = 0.05; v0[2] = -0.3;
            if (zero) { v0[3] = v0[0] + (double)jump; v0[4] = v0[1]; v0[5] = v0[2]; }
            else { v0[3] = 5.0; v0[4] = -0.02; v0[5] = 0.4; }
            hcbd_world_set_velocities(&w, v0);
            hcbd_world_get_velocities(&w, v0); /* as stored */
            hcbd_world_get_positions(&w, xyz, 0);
            if (!run(&w, 1)) return;
            hcbd_world_get_velocities(&w, v1);
            /* the image of b below: x_b - s, y_b - Ly */
            dd[0] = (ld)xyz[0] - (xyz[3] - s);
            dd[1] = (ld)xyz[1] - (xyz[4] - L);
            dd[2] = (ld)xyz[2] - xyz[5];
            r = sqrtl(dd[0] * dd[0] + dd[1] * dd[1] + dd[2] * dd[2]);
            m = (ld)d.params.xip * d.params.tau;
            rho = m * abs_norm(&d.params) * (abs_W(0, 2.5L) + abs_W(r, 2.5L));
            f = abs_f(r, 2.5L, m, rho, rho);
            fac = integ ? expl(-2 * f * d.params.dt / d.params.tau) : 1 - 2 * f * d.params.dt / d.params.tau;
            for (c = 0; c < 3; ++c) {
                ld u = (ld)v0[c] - (v0[3 + c] - (c == 0 ? jump : 0));
                ld up = (ld)v1[c] - (v1[3 + c] - (c == 0 ? jump : 0));
                if (zero) worst0 = fmax(worst0, fmax(fabs(v1[c] - v0[c]), fabs(v1[3 + c] - v0[3 + c])));
                /* 10 tol relative, plus the fixed-point grid of the
                   momentum exchange (1/(2 qP) per side) */
                else worst = fmax(worst, (double)(fabsl(up - u * fac) /
                                                  (10 * tol * fabsl(u) + 1 / (w.qP * m))));
            }
            if (!zero)
                NOTE("%s: r through the sheared image %.4f, u'_x/u_x = %.8f, predicted %.8f",
                     integ ? "Shardlow" : "Euler", (double)r,
                     (double)(((ld)v1[0] - v1[3] + jump) / ((ld)v0[0] - v0[3] + jump)), (double)fac);
            hcbd_world_destroy(&w);
        }
    CHECK(worst < 1, "velocity through the sheared boundary off by %g of its tolerance", worst);
    CHECK(worst0 < (ABS_FLOAT ? 1e-5 : 1e-13) * 12.9 * 1.7,
          "velocities on one profile through the boundary changed by %g", worst0);
}

#if HCBD_MODEL == HCBD_MODEL_WALLED
/* ------------------------------------------------------------------------
   Walls (MODEL 4).  Real particles near both walls, every pair of them
   more than Rc apart (4 x 4 columns in x-z, one near each wall), so each
   feels only this step's artificial particles B: with d_A, d_B from the
   interface, beta = min(beta_max, 1 + d_B/d_A), rho_B = m n# (2016) or
   m (n# + w(0)) (2014), rate k_B = beta f_AB dt/tau,
     Euler:    v' = v - sum_B k_B (v - v_wall) + sum_B sqrt(2 kT S dt beta/tau) z / m
     Shardlow: v' - v_wall = (v - v_wall) prod_B e_B + noise, e_B = exp(-k_B),
               variance from v = v_wall: kT/m (1 - prod_B e_B^2)
   (each B in turn solved exactly, noise variance kT/m (1 - e_B^2)). */
static int abs_wall_particles(double *xyz)
{
    static const double h[4] = {0.05, 0.15, 0.3, 0.55}; /* d_A from the interface */
    int k, n = 0;
    for (k = 0; k < 16; ++k) {
        double x = (k % 4 + 0.5) * 13.0 / 4, z = (k / 4 + 0.5) * 13.0 / 4;
        xyz[3 * n] = x; xyz[3 * n + 1] = 1.5 + h[k % 4]; xyz[3 * n + 2] = z; ++n;
        xyz[3 * n] = x + 0.4; xyz[3 * n + 1] = 11.5 - h[(k + 2) % 4]; xyz[3 * n + 2] = z + 0.3; ++n;
    }
    return n;
}

static hcbd_world_def abs_channel(int n)
{
    hcbd_world_def d = hcbd_world_def_default();
    d.params.L[0] = d.params.L[1] = d.params.L[2] = 13.0;
    d.params.wall.thickness = 1.5;
    d.params.potential = HCBD_POT_IDEAL;
    d.params.tau = 1e-2;
    d.params.dt = 1e-3;
    d.capacity = n;
    return d;
}

/* Wall force of the Gaussian planes at t - plane and L - t + plane, each
   at its minimum-image distance (MODEL 4). */
static ld abs_wall_F(const hcbd_params *p, ld y)
{
    ld pl[2], F = 0;
    int k;
    if (p->wall.mode == HCBD_WALL_REFLECT) return 0;
    pl[0] = p->wall.thickness - p->wall.plane;
    pl[1] = p->L[1] - p->wall.thickness + p->wall.plane;
    for (k = 0; k < 2; ++k) {
        ld s = abs_mi(y - pl[k], p->L[1]);
        F += 2 * p->wall.a * p->wall.b * s * expl(-p->wall.b * s * s);
    }
    return F;
}

/* For real particle i at x (this step's artificial particles in w): the
   Euler friction rate sum k_B, the Shardlow log-decay sum ln e_B (= -sum
   k_B), the Euler noise variance factor sum k_B (2 kT/m per component),
   its value without sqrt(beta) (sum k_B / beta), the wall velocity, and
   counts of capped and free pairs.  Returns 0 if a real neighbour lies
   within Rc. */
typedef struct { ld ksum, knb, vw; int capped, free_; } abs_morris;

static int abs_morris_of(const hcbd_world *w, const double *x, int i, abs_morris *o)
{
    const hcbd_params *p = &w->p;
    const ld m = (ld)p->xip * p->tau, Rc = p->Rc, t = p->wall.thickness, L = p->L[1];
    const ld rhoB = p->density_norm == 2016 ? m * p->density : m * (p->density + abs_W(0, Rc));
    ld rho = abs_W(0, Rc);
    int k, j, q, nn, near[256];
    memset(o, 0, sizeof *o);
    for (j = 0; j < w->n; ++j) {
        ld d[3];
        if (j != i && abs_sep(x, i, j, p->L, d) < Rc) return 0;
    }
    /* the artificial particles within Rc (a coarse test in double first) */
    for (k = 0, nn = 0; k < w->ws.n_art && nn < 256; ++k) {
        double ex = x[3 * i] - w->ws.ax[k], ey = x[3 * i + 1] - w->ws.ay[k], ez = x[3 * i + 2] - w->ws.az[k];
        ex -= p->L[0] * round(ex / p->L[0]);
        ey -= p->L[1] * round(ey / p->L[1]);
        ez -= p->L[2] * round(ez / p->L[2]);
        if (ex * ex + ey * ey + ez * ez < 1.01 * p->Rc * p->Rc) near[nn++] = k;
    }
    for (q = 0; q < nn; ++q) {
        k = near[q];
        {
            ld dx = abs_mi((ld)x[3 * i] - w->ws.ax[k], p->L[0]), dy = abs_mi((ld)x[3 * i + 1] - w->ws.ay[k], L);
            ld dz = abs_mi((ld)x[3 * i + 2] - w->ws.az[k], p->L[2]);
            rho += abs_W(sqrtl(dx * dx + dy * dy + dz * dz), Rc);
        }
    }
    rho *= m * abs_norm(p);
    for (q = 0; q < nn; ++q) {
        ld dx, dy, dz, r, yA, yB, dA, dB, beta, kB;
        k = near[q];
        dx = abs_mi((ld)x[3 * i] - w->ws.ax[k], p->L[0]);
        dy = abs_mi((ld)x[3 * i + 1] - w->ws.ay[k], L);
        dz = abs_mi((ld)x[3 * i + 2] - w->ws.az[k], p->L[2]);
        r = sqrtl(dx * dx + dy * dy + dz * dz);
        yA = x[3 * i + 1];
        yB = yA - dy;
        if (r >= Rc) continue;
        if (dy > 0) { dA = yA - t; dB = t - yB; o->vw = p->wall.vx[0]; }
        else { dA = (L - t) - yA; dB = yB - (L - t); o->vw = p->wall.vx[1]; }
        beta = 1 + dB / dA;
        if (beta > p->wall.beta_max) { beta = p->wall.beta_max; ++o->capped; }
        else ++o->free_;
        kB = beta * abs_f(r, Rc, m, rho, rhoB) * p->dt / p->tau;
        o->ksum += kB;
        o->knb += kB / beta;
    }
    return 1;
}

/* kT = 0: the one-step velocity and position of every real particle, with
   a moving wall on each side, the Gaussian wall force, beta_max 1.5 (2016
   density) and 3 (2014 density), both integrators. */
void test_abs_wall_morris_friction(void)
{
    const double tol = ABS_FLOAT ? 2e-5 : 1e-12;
    double worst_v = 0, worst_x = 0, dv_min = HUGE_VAL;
    int integ, c2, capped = 0, free_ = 0, used = 0;
    for (integ = 0; integ < 2; ++integ)
        for (c2 = 0; c2 < 2; ++c2) {
            static double xyz[96], v0[96], v1[96], x1[96];
            int n = abs_wall_particles(xyz), i, c;
            hcbd_world_def d = abs_channel(n);
            hcbd_world w;
            hcbd_params *p = &d.params;
            ld m;
            p->kT = 0;
            p->xi = 4.0;
            p->xip = 0.8;
            p->wall.vx[0] = 0.3;
            p->wall.vx[1] = -0.8;
            p->wall.beta_max = c2 ? 3.0 : 1.5;
            p->density_norm = c2 ? 2014 : 2016;
            p->pair_integrator = integ ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
            m = (ld)p->xip * p->tau;
            if (!make_world(&w, &d)) return;
            hcbd_world_set_positions(&w, n, xyz);
            for (i = 0; i < n; ++i) {
                v0[3 * i] = 1.2 * sin(0.9 * i + 0.3);
                v0[3 * i + 1] = 0.7 * cos(1.3 * i);
                v0[3 * i + 2] = -0.55 + 0.1 * i;
            }
            hcbd_world_set_velocities(&w, v0);
            hcbd_world_get_velocities(&w, v0);
            hcbd_world_get_positions(&w, xyz, 0);
            if (!run(&w, 1)) return;
            hcbd_world_get_velocities(&w, v1);
            hcbd_world_get_positions(&w, x1, 0);
            for (i = 0; i < n; ++i) {
                abs_morris o;
                ld F[3];
                if (!abs_morris_of(&w, xyz, i, &o)) continue;
                ++used;
                capped += o.capped;
                free_ += o.free_;
                F[0] = F[2] = 0;
                F[1] = abs_wall_F(p, xyz[3 * i + 1]);
                for (c = 0; c < 3; ++c) {
                    /* Shardlow: the kick, the Morris pairs, then the drift with the mean velocity */
                    ld vw = c == 0 ? o.vw : 0, u = v0[3 * i + c] + F[c] * p->dt / m, vn, xn;
                    vn = integ ? vw + (u - vw) * expl(-o.ksum) : u + (v0[3 * i + c] - vw) * -o.ksum;
                    xn = xyz[3 * i + c] + (integ ? (u + vn) / 2 : (ld)v0[3 * i + c]) * p->dt + F[c] * p->dt / p->xi;
                    worst_v = fmax(worst_v, (double)(fabsl(v1[3 * i + c] - vn) / (1 + fabsl(vn))));
                    worst_x = fmax(worst_x, (double)fabsl(abs_mi((ld)x1[3 * i + c] - xn, 13)));
                    if (c != 1) dv_min = fmin(dv_min, fabs(v1[3 * i + c] - v0[3 * i + c]));
                }
            }
            hcbd_world_destroy(&w);
        }
    NOTE("%d particle-steps, %d capped and %d free Morris pairs; deviation v %.2g, x %.2g; smallest "
         "friction |dv| %.3g", used, capped, free_, worst_v, worst_x, dv_min);
    CHECK(used >= 120 && capped > 100 && free_ > 100, "cases: %d particles, %d capped, %d free", used,
          capped, free_);
    CHECK(worst_v < 10 * tol, "Morris velocity update off by %g", worst_v);
    CHECK(worst_x < (ABS_FLOAT ? 2e-6 : 1e-13), "position update near the wall off by %g", worst_x);
}

/* Noise on, v = v_wall = 0 before each step, reflecting walls (no wall
   force): the one-step variance of each velocity component against
   (2 kT/m) sum_B k_B (Euler) or kT/m (1 - exp(-2 sum_B k_B)) (Shardlow),
   beta_max = 3 with the particles 0.05-0.55 from the interface, so most
   pairs are capped and sqrt(beta) changes the noise by up to 1.7.  With
   wall.noise_beta = 0 (Euler) the variance follows sum_B k_B / beta
   instead, and differs from the sqrt(beta) one by many errors. */
void test_abs_wall_morris_noise(void)
{
    enum { NBLK = 10, NST = 60 };
    int cs;
    for (cs = 0; cs < 3; ++cs) {
        static double xyz[96], zero[96], v[96], vals[NBLK * NST], alts[NBLK * NST];
        double mean, err, am, ae;
        int b, s, i, c, nval = 0;
        for (b = 0; b < NBLK; ++b) {
            int n = abs_wall_particles(xyz);
            hcbd_world_def d = abs_channel(n);
            hcbd_world w;
            hcbd_params *p = &d.params;
            ld m;
            p->kT = 1.0;
            p->xi = 50.0;
            p->xip = 1.0;
            p->wall.mode = HCBD_WALL_REFLECT;
            p->wall.beta_max = 3.0;
            p->wall.noise_beta = cs == 2 ? 0 : 1;
            p->pair_integrator = cs == 1 ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
            p->seed = 300 + b;
            m = (ld)p->xip * p->tau;
            memset(zero, 0, sizeof zero);
            if (!make_world(&w, &d)) return;
            hcbd_world_set_positions(&w, n, xyz);
            for (s = 0; s < NST; ++s) {
                ld sum = 0, alt = 0;
                int cnt = 0;
                hcbd_world_set_velocities(&w, zero);
                hcbd_world_get_positions(&w, xyz, 0);
                if (!run(&w, 1)) return;
                hcbd_world_get_velocities(&w, v);
                for (i = 0; i < n; ++i) {
                    abs_morris o;
                    ld var, var_alt;
                    if (!abs_morris_of(&w, xyz, i, &o) || o.ksum == 0) continue;
                    if (cs == 1) var = var_alt = p->kT / m * (1 - expl(-2 * o.ksum));
                    else {
                        var = 2 * p->kT / m * (cs == 2 ? o.knb : o.ksum);
                        var_alt = 2 * p->kT / m * (cs == 2 ? o.ksum : o.knb);
                    }
                    for (c = 0; c < 3; ++c) {
                        sum += v[3 * i + c] * v[3 * i + c] / var;
                        alt += v[3 * i + c] * v[3 * i + c] / var_alt;
                    }
                    cnt += 3;
                }
                vals[nval] = (double)(sum / cnt);
                alts[nval++] = (double)(alt / cnt);
            }
            hcbd_world_destroy(&w);
        }
        block_stats(vals, nval, 20, &mean, &err);
        block_stats(alts, nval, 20, &am, &ae);
        if (cs == 1) {
            NOTE("Shardlow: <v^2>/(kT/m (1 - exp(-2 sum k_B))) = %.4f +- %.4f", mean, err);
        } else {
            NOTE("Euler, wall.noise_beta %d: <v^2>/predicted = %.4f +- %.4f; against the %s "
                 "prediction %.4f", cs == 2 ? 0 : 1, mean, err, cs == 2 ? "sqrt(beta)" : "unscaled", am);
            CHECK(fabs(am - 1) > 10 * err, "sqrt(beta) not resolved: %g vs %g +- %g", am, mean, err);
        }
        CHECK(fabs(mean - 1) < 4 * err && err < 0.012, "case %d: variance ratio %g +- %g", cs, mean, err);
    }
}
#endif
