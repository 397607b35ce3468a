/* Weight functions and pair potentials against integrals and finite
   differences (MODEL 1, 9). */
#include "test.h"

/* 4 pi int_0^R r^2 w(r) dr by composite Simpson with n intervals. */
static double radial_integral(double (*w)(double, double), double Rc, int n)
{
    double h = Rc / n, s = 0;
    int k;
    for (k = 0; k <= n; ++k) {
        double r = k * h, c = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
        s += c * r * r * w(r, Rc);
    }
    return 4 * 3.14159265358979323846 * s * h / 3;
}

void test_wendland_normalisation(void)
{
    double Rc[3] = {1.0, 2.5, 4.0};
    int k;
    for (k = 0; k < 3; ++k) {
        double I = radial_integral(hcbd_wendland, Rc[k], 20000);
        CHECK(fabs(I - 1) < 1e-12, "Rc = %g: integral %.15f", Rc[k], I);
    }
    CHECK(fabs(hcbd_wendland(0, 2.5) - 21 / (2 * 3.14159265358979323846 * 15.625)) < 1e-15,
          "w(0) = %g", hcbd_wendland(0, 2.5));
    CHECK(hcbd_wendland(2.5, 2.5) == 0 && hcbd_wendland(3, 2.5) == 0, "w beyond Rc");
}

void test_wendland_derivative(void)
{
    double r;
    for (r = 0.05; r < 2.5; r += 0.1) {
        double h = 1e-6;
        double fd = (hcbd_wendland(r + h, 2.5) - hcbd_wendland(r - h, 2.5)) / (2 * h);
        CHECK(fabs(fd - hcbd_wendland_dr(r, 2.5)) < 1e-8, "r = %g: %g vs %g", r, fd,
              hcbd_wendland_dr(r, 2.5));
    }
}

void test_star_force_is_minus_gradient(void)
{
    double f[2] = {128, 32}, r;
    int k;
    for (k = 0; k < 2; ++k)
        for (r = 0.05; r < 2.5; r += 0.0731) {
            double h = 1e-6 * r;
            double fd = -(hcbd_star_potential(r + h, f[k], 1, 1) -
                          hcbd_star_potential(r - h, f[k], 1, 1)) / (2 * h);
            double F = hcbd_star_force(r, f[k], 1, 1);
            CHECK(fabs(fd - F) < 1e-6 * (1 + fabs(F)), "f = %g r = %g: %g vs %g", f[k], r,
                  fd, F);
        }
    /* continuity of V and F at r = sigma (2014 eq. 28) */
    {
        double e = 1e-12;
        double v0 = hcbd_star_potential(1 - e, 128, 1, 1), v1 = hcbd_star_potential(1 + e, 128, 1, 1);
        double f0 = hcbd_star_force(1 - e, 128, 1, 1), f1 = hcbd_star_force(1 + e, 128, 1, 1);
        CHECK(fabs(v0 - v1) < 1e-9 * v0, "V jumps at sigma: %.15g %.15g", v0, v1);
        CHECK(fabs(f0 - f1) < 1e-9 * f0, "F jumps at sigma: %.15g %.15g", f0, f1);
    }
    /* scaling with sigma and eps */
    CHECK(fabs(hcbd_star_potential(2.0, 128, 2.0, 3.0) - 3 * hcbd_star_potential(1.0, 128, 1, 1)) < 1e-12,
          "V(r; sigma, eps) = eps V(r/sigma; 1, 1)");
}

/* hcbd_star_force_over_r (the world's evaluation, exported for pair styles)
   against hcbd_star_force(r)/r on both branches, at several f, sigma and
   eps; bad constants are refused. */
void test_star_force_over_r(void)
{
    const double f[3] = {128, 32, 7}, sg[3] = {1, 0.7, 2.2}, eps[3] = {1, 2.5, 0.4};
    double worst = 0, r;
    hcbd_star_coef c;
    int k;
    for (k = 0; k < 3; ++k) {
        CHECK(hcbd_star_coef_init(&c, f[k], sg[k], eps[k], NULL, 0) == HCBD_OK, "coef_of(%g, %g, %g)", f[k], sg[k],
              eps[k]);
        for (r = 0.05 * sg[k]; r < 3 * sg[k]; r += 0.0173 * sg[k]) {
            double ref = hcbd_star_force(r, f[k], sg[k], eps[k]) / r;
            worst = fmax(worst, fabs(hcbd_star_force_over_r(&c, r * r) / ref - 1));
        }
    }
    NOTE("largest relative difference %.2g", worst);
    CHECK(worst < 1e-13, "hcbd_star_force_over_r off hcbd_star_force / r by %g", worst);
    {
        char msg[128];
        CHECK(hcbd_star_coef_init(&c, 0, 1, 1, msg, sizeof msg) == HCBD_ERR_PARAM && strstr(msg, "f = 0"),
              "f = 0: %s", msg);
        CHECK(hcbd_star_coef_init(&c, 128, -1, 1, msg, sizeof msg) == HCBD_ERR_PARAM && strstr(msg, "sigma = -1"),
              "sigma = -1: %s", msg);
        CHECK(hcbd_star_coef_init(&c, 128, 1, NAN, msg, sizeof msg) == HCBD_ERR_PARAM && strstr(msg, "eps = nan"),
              "eps = nan: %s", msg);
        CHECK(hcbd_star_coef_init(NULL, 128, 1, 1, msg, sizeof msg) == HCBD_ERR_NULL && strstr(msg, "NULL"),
              "c = NULL: %s", msg);
    }
}

/* Total force on each particle, from one BD step with kT = 0 (dR = F dt /
   xi exactly, so dt need only keep the round-off of x + dR and the
   fixed-point grid of the force sums, 8 cutmax xi/dt 2^-50, small), on a
   jittered lattice of 64 particles. */
static void step_forces(hcbd_world_def d, double *xyz, double *F)
{
    enum { N = 64 };
    hcbd_world w;
    double x1[3 * N];
    int i;
    d.params.dynamics = HCBD_DYN_BD;
    d.params.kT = 0;
    d.params.dt = 1e-6;
    d.params.L[0] = d.params.L[1] = d.params.L[2] = 6.5;
    if (!make_world(&w, &d)) return;
    for (i = 0; i < N; ++i) {
        xyz[3 * i] = (i % 4 + 0.5) * 6.5 / 4 + 0.2 * sin(i);
        xyz[3 * i + 1] = ((i / 4) % 4 + 0.5) * 6.5 / 4 + 0.2 * cos(3 * i);
        xyz[3 * i + 2] = (i / 16 + 0.5) * 6.5 / 4 + 0.2 * sin(7 * i);
    }
    hcbd_world_set_positions(&w, N, xyz);
    run(&w, 1);
    hcbd_world_get_positions(&w, x1, 1);
    for (i = 0; i < 3 * N; ++i) F[i] = (x1[i] - xyz[i]) / 1e-6;
    hcbd_world_destroy(&w);
}

/* The forces the step applies are minus the gradient of the total
   potential energy (finite differences of hcbd_world_potential_energy). */
void test_pair_forces_vs_energy(void)
{
    enum { N = 64 };
    hcbd_world_def d = scene(N, 0.24);
    hcbd_world w;
    double xyz[3 * N], F[3 * N];
    int i, c;
    step_forces(d, xyz, F);
    d.params.L[0] = d.params.L[1] = d.params.L[2] = 6.5;
    if (!make_world(&w, &d)) return;
    for (i = 0; i < 6; ++i)
        for (c = 0; c < 3; ++c) {
            double h = 1e-6, e1, e0, fd;
            xyz[3 * i + c] += h;
            hcbd_world_set_positions(&w, N, xyz);
            e1 = hcbd_world_potential_energy(&w);
            xyz[3 * i + c] -= 2 * h;
            hcbd_world_set_positions(&w, N, xyz);
            e0 = hcbd_world_potential_energy(&w);
            xyz[3 * i + c] += h;
            fd = -(e1 - e0) / (2 * h);
            CHECK(fabs(fd - F[3 * i + c]) < 1e-5 * (1 + fabs(fd)), "particle %d comp %d: -dU/dx %g, F %g",
                  i, c, fd, F[3 * i + c]);
        }
    hcbd_world_destroy(&w);
}

/* hcbd_world_forces gives the forces the step applies (body force included),
   they sum to N fext (the pair forces cancel in pairs), and they do not
   depend on the storage order. */
void test_forces_observable(void)
{
    enum { N = 64 };
    hcbd_world_def d = scene(N, 0.24);
    hcbd_world w;
    double xyz[3 * N], F[3 * N], G[3 * N], H[3 * N], sum[3] = {0, 0, 0}, xr[3 * N];
    int i, c;
    d.params.fext[0] = 0.3;
    d.params.fext[2] = -0.1;
    step_forces(d, xyz, F);
    d.params.L[0] = d.params.L[1] = d.params.L[2] = 6.5;
    if (!make_world(&w, &d)) return;
    CHECK(hcbd_world_forces(&w, NULL) == HCBD_ERR_NULL && strstr(w.err.msg, "f is NULL"), "%s", w.err.msg);
    hcbd_world_set_positions(&w, N, xyz);
    CHECK(hcbd_world_forces(&w, G) == HCBD_OK, "%s", w.err.msg);
    for (i = 0; i < N; ++i)
        for (c = 0; c < 3; ++c) {
            CHECK(fabs(G[3 * i + c] - F[3 * i + c]) < 1e-6 * (1 + fabs(F[3 * i + c])),
                  "particle %d comp %d: hcbd_world_forces %g, the step's %g", i, c, G[3 * i + c],
                  F[3 * i + c]);
            sum[c] += G[3 * i + c];
        }
    CHECK(fabs(sum[0] - N * 0.3) < 1e-9 && fabs(sum[1]) < 1e-9 && fabs(sum[2] + N * 0.1) < 1e-9,
          "sum of forces (%g, %g, %g), want N fext = (%g, 0, %g)", sum[0], sum[1], sum[2], N * 0.3,
          -N * 0.1);
    /* the same particles given in reverse: each id keeps its force, bit for bit */
    for (i = 0; i < N; ++i)
        for (c = 0; c < 3; ++c) xr[3 * i + c] = xyz[3 * (N - 1 - i) + c];
    hcbd_world_set_positions(&w, N, xr);
    hcbd_world_forces(&w, H);
    for (i = 0; i < N; ++i)
        for (c = 0; c < 3; ++c)
            CHECK(fabs(H[3 * i + c] - G[3 * (N - 1 - i) + c]) < 1e-12 * (1 + fabs(G[3 * (N - 1 - i) + c])),
                  "particle %d comp %d after relabelling: %g vs %g", i, c, H[3 * i + c],
                  G[3 * (N - 1 - i) + c]);
    hcbd_world_destroy(&w);
}

/* hcbd_world_def_set_density: n over the open volume is the density, the
   edge ratios stay, and bad values are named by the create. */
void test_set_density(void)
{
    hcbd_world_def d = hcbd_world_def_default();
    hcbd_world w;
    double t = 0, open;
    d.params.L[0] = 10;
    d.params.L[1] = 20;
    d.params.L[2] = 5;
#if HCBD_MODEL == HCBD_MODEL_WALLED
    d.params.wall.thickness = 1.5;
    t = 3.0;
#endif
    CHECK(hcbd_world_def_set_density(&d, 1000, 0.24) == HCBD_OK, "set_density refused a good scene");
    open = d.params.L[0] * (d.params.L[1] - t) * d.params.L[2];
    CHECK(d.capacity == 1000 && d.params.density == 0.24 && fabs(1000 / open - 0.24) < 1e-12,
          "capacity %d, density %g, n / open volume %.15g", d.capacity, d.params.density, 1000 / open);
    CHECK(fabs(d.params.L[0] / d.params.L[2] - 2) < 1e-12 &&
              fabs((d.params.L[1] - t) / d.params.L[2] - (20 - t) / 5) < 1e-12,
          "edge ratios not kept: %g %g %g", d.params.L[0], d.params.L[1], d.params.L[2]);
    CHECK(hcbd_world_def_set_density(NULL, 10, 1) == HCBD_ERR_NULL, "NULL def accepted");
    CHECK(hcbd_world_def_set_density(&d, 1000, -1) == HCBD_ERR_PARAM &&
              hcbd_world_create(&w, &d) == HCBD_ERR_PARAM && strstr(w.err.msg, "density"),
          "negative density: %s", w.err.msg);
    d = hcbd_world_def_default();
    CHECK(hcbd_world_def_set_density(&d, 0, 0.24) == HCBD_ERR_PARAM &&
              hcbd_world_create(&w, &d) == HCBD_ERR_PARAM && strstr(w.err.msg, "capacity = 0"),
          "n = 0: %s", w.err.msg);
}

/* A table of the star force reproduces the analytic forces within the
   linear-interpolation error dr^2 max|F''| / 8 per pair (~1e-6 relative
   here; an index off by one would give ~1e-3). */
void test_table_potential(void)
{
    enum { N = 64, NT = 4001 };
    static double tF[NT], tV[NT];
    hcbd_world_def d = scene(N, 0.24), t;
    double xyz[3 * N], Fa[3 * N], Ft[3 * N];
    int i;
    for (i = 0; i < NT; ++i) {
        double r = 0.3 + i * (2.5 - 0.3) / (NT - 1);
        tF[i] = hcbd_star_force(r, 128, 1, 1);
        tV[i] = hcbd_star_potential(r, 128, 1, 1);
    }
    t = d;
    t.params.potential = HCBD_POT_TABLE;
    t.params.table_F = tF;
    t.params.table_V = tV;
    t.params.table_n = NT;
    t.params.table_r0 = 0.3;
    step_forces(d, xyz, Fa);
    step_forces(t, xyz, Ft);
    for (i = 0; i < 3 * N; ++i)
        CHECK(fabs(Fa[i] - Ft[i]) < 1e-4 * (1 + fabs(Fa[i])), "particle %d comp %d: %g vs %g", i / 3,
              i % 3, Ft[i], Fa[i]);
}

/* The exported GI-BD pair equations (what lammps/ calls) against the
   world's own friction average <sum_j f_ij> = <sum_j sdt tau / (m dt)>, and
   against the written-out formulas: a 10 % error in the weight, the
   normalisation or S_ij changes the average by more than the 1e-9 allowed.
   Both normalisations. */
void test_gibd_coef_exported(void)
{
    enum { N = 300 };
    int norm;
    for (norm = 0; norm < 2; ++norm) {
        hcbd_world_def d = scene(N, 0.24);
        hcbd_world w;
        hcbd_gibd_coef c;
        double xyz[3 * N], rho[N], out[3], sum = 0, pi = 3.14159265358979323846, Rc;
        int i, j;
        d.params.potential = HCBD_POT_IDEAL;
        d.params.density_norm = norm ? 2016 : 2014;
        d.params.xip = 1.7;
        if (!make_world(&w, &d)) return;
        hcbd_world_place_random(&w, N);
        hcbd_world_get_positions(&w, xyz, 0);
        CHECK(hcbd_params_gibd_coef(&d.params, &c, NULL, 0) == HCBD_OK, "coefficients");
        Rc = d.params.Rc;
        for (i = 0; i < N; ++i) {
            double s = 0, s_ref = 0;
            for (j = 0; j < N; ++j) {
                double r = sqrt(pair_r2(xyz, i, j, w.p.L)), q = r / Rc;
                if (j == i || q >= 1) continue;
                s += hcbd_gibd_weight(&c, r);
                s_ref += 21 / (2 * pi * Rc * Rc * Rc) * pow(1 - q, 4) * (4 * q + 1);
            }
            rho[i] = hcbd_gibd_density(&c, s);
            {
                double w0 = 21 / (2 * pi * Rc * Rc * Rc), m = 1.7 * d.params.tau;
                double ref = m * (w0 + s_ref) / (norm ? 1 + w0 / 0.24 : 1);
                CHECK(fabs(rho[i] / ref - 1) < 1e-12, "rho %g vs %g", rho[i], ref);
            }
        }
        for (i = 0; i < N; ++i)
            for (j = 0; j < N; ++j) {
                double r = sqrt(pair_r2(xyz, i, j, w.p.L)), q = r / Rc, m = 1.7 * d.params.tau;
                double sdt = j == i ? 0 : hcbd_gibd_sdt(&c, r, 1 / rho[i], 1 / rho[j]);
                double f = q < 1 && j != i ? 15 / (2 * pi * Rc * Rc * Rc) * m * (1 / rho[i] + 1 / rho[j]) * pow(1 - q, 3) : 0;
                CHECK(fabs(sdt - m * f * d.params.dt / d.params.tau) <= 1e-12 * (sdt + 1e-300), "S_ij dt/tau");
                sum += sdt * d.params.tau / (m * d.params.dt) / N;
            }
        hcbd_world_friction_average(&w, 1, out);
        CHECK(fabs(sum / out[0] - 1) < 1e-9, "norm %d: <sum_j f_ij> %.12g, the world's %.12g", norm ? 2016 : 2014, sum,
              out[0]);
        hcbd_world_destroy(&w);
    }
}

/* hcbd_gibd_pair_exact (what lammps/ calls for the exact sweep) against the
   written-out Ornstein-Uhlenbeck step of u = v_i - v_j and against the
   world's own sweep: two particles within Rc, one step, no force, so the
   world's velocities after the step are its one pair's update; the third
   case pairs them across the sheared boundary (Lees-Edwards, the partner's
   image one box down: dvx = -gdot L).  A 10 % error in the rate, the noise,
   the share or the shift moves them by far more than the 1e-12 allowed. */
void test_gibd_pair_exact_exported(void)
{
    int cs;
    /* rates 2 sdt/m of 0.09 and 0.35: the series of 1 - e and expm1 */
    for (cs = 0; cs < 3; ++cs) {
        hcbd_world_def d = hcbd_world_def_default();
        hcbd_world w;
        hcbd_gibd_coef c;
        const double L = cs == 2 ? 10.0 : 8.0, gdot = cs == 2 ? 5.0 : 0.0;
        const double xyz[6] = {1.0, cs == 2 ? 0.4 : 1.0, 1.0, 2.3, cs == 2 ? 9.2 : 1.9, 0.4};
        double v[6] = {0.3, -1.2, 0.5, -0.7, 0.1, 2.0}, out[6], z[3], vi[3], vj[3], r, rho, sdt;
        int k;
        d.capacity = 2;
        d.params.L[0] = d.params.L[1] = d.params.L[2] = L;
        d.params.gdot = gdot;
        d.params.potential = HCBD_POT_IDEAL;
        d.params.kT = 1.3;
        d.params.xip = 1.7;
        d.params.tau = cs == 1 ? 5e-5 : 2e-4;
        if (!make_world(&w, &d)) return;
        CHECK(hcbd_world_set_positions(&w, 2, xyz) == HCBD_OK && hcbd_world_set_velocities(&w, v) == HCBD_OK,
              "set-up: %s", w.err.msg);
        CHECK(hcbd_params_gibd_coef(&d.params, &c, NULL, 0) == HCBD_OK, "coefficients");
        r = sqrt(1.3 * 1.3 + (cs == 2 ? 1.2 * 1.2 : 0.9 * 0.9) + 0.6 * 0.6);
        rho = hcbd_gibd_density(&c, hcbd_gibd_weight(&c, r));
        sdt = hcbd_gibd_sdt(&c, r, 1 / rho, 1 / rho);
        CHECK(cs == 1 ? 2 * sdt / c.m > 0.125 : 2 * sdt / c.m < 0.125, "rate %g", 2 * sdt / c.m);
        hcbd_world_pair_normals(&w, 0, 0, 1, z);
        for (k = 0; k < 3; ++k) {
            vi[k] = v[k];
            vj[k] = v[3 + k];
        }
        hcbd_gibd_pair_exact(&c, 1.3, sdt, z, -gdot * L, vi, vj);
        for (k = 0; k < 3; ++k) {
            const double m = c.m, e = exp(-2 * sdt / m), u = v[k] - v[3 + k] + (k ? 0 : gdot * L);
            const double u1 = u * e + sqrt(2 * 1.3 / m * (1 - e * e)) * z[k], P = 0.5 * m * (u1 - u);
            CHECK(fabs(vi[k] - (v[k] + P / m)) < 1e-12 && fabs(vj[k] - (v[3 + k] - P / m)) < 1e-12,
                  "component %d: %.15g %.15g, the formula's %.15g %.15g", k, vi[k], vj[k], v[k] + P / m,
                  v[3 + k] - P / m);
        }
        CHECK(hcbd_world_step(&w, 1) == HCBD_OK, "step: %s", w.err.msg);
        hcbd_world_get_velocities(&w, out);
        for (k = 0; k < 3; ++k)
            CHECK(fabs(out[k] - vi[k]) < 1e-12 && fabs(out[3 + k] - vj[k]) < 1e-12,
                  "component %d: the world's %.15g %.15g, hcbd_gibd_pair_exact's %.15g %.15g", k, out[k],
                  out[3 + k], vi[k], vj[k]);
        hcbd_world_destroy(&w);
    }
}

/* The exact sweep's order as exported for engines that match the world bit
   for bit (hcbd_params_sweep_rows, hcbd_sweep_row_place: lammps/fix_gibd
   places its atoms by them), against the order written out from the
   header's description: y-z rows at least Rc wide, a multiple of 3 along
   each axis or a single one, each particle's row from its place relative
   to particle 0, colour (y row mod 3) + 3 (z row mod 3).  The world's own
   sweep is held to the same description by test_abs_one_step_replica.  Bad input
   is refused. */
void test_sweep_rows_exported(void)
{
    const double Ls[3][3] = {{12.9, 12.9, 12.9}, {10.0, 7.4, 30.2}, {8.0, 6.3, 16.0}};
    const int want_ns[3][2] = {{3, 3}, {1, 12}, {1, 6}};
    hcbd_rng g;
    int t, k, bad = 0;
    hcbd_rng_seed(&g, 41);
    for (t = 0; t < 3; ++t) {
        hcbd_params p = hcbd_params_default();
        int ns[2] = {0, 0}, d;
        for (d = 0; d < 3; ++d) p.L[d] = Ls[t][d];
        CHECK(hcbd_params_sweep_rows(&p, ns) == want_ns[t][0] * want_ns[t][1] && ns[0] == want_ns[t][0] &&
                  ns[1] == want_ns[t][1],
              "box %g x %g x %g, Rc %g: %d x %d rows, %d x %d meant", p.L[0], p.L[1], p.L[2], p.Rc, ns[0], ns[1],
              want_ns[t][0], want_ns[t][1]);
        for (k = 0; k < 400; ++k) {
            /* the last cases: a place just below particle 0's, whose
               wrap rounds to the edge */
            const double dy = k == 398 ? -1e-17 : (2.0 * hcbd_rng_uniform(&g) - 1.0) * p.L[1];
            const double dz = k == 399 ? -1e-17 : (2.0 * hcbd_rng_uniform(&g) - 1.0) * p.L[2];
            const double s[2] = {dy < 0 ? dy + p.L[1] : dy, dz < 0 ? dz + p.L[2] : dz};
            int a[2], c[2] = {-1, -1}, row = -1, col;
            for (d = 0; d < 2; ++d) {
                a[d] = (int)(s[d] * (ns[d] / p.L[d + 1]));
                if (a[d] > ns[d] - 1) a[d] = ns[d] - 1;
            }
            col = hcbd_sweep_row_place(ns, p.L, dy, dz, c, &row);
            if (col != a[0] % 3 + 3 * (a[1] % 3) || c[0] != a[0] || c[1] != a[1] || row != a[1] * ns[0] + a[0]) {
                if (!bad++)
                    NOTE("box %d, (%.17g, %.17g): row %d colour %d, written out %d %d", t, dy, dz, row, col,
                         a[1] * ns[0] + a[0], a[0] % 3 + 3 * (a[1] % 3));
            }
        }
    }
    CHECK(!bad, "%d places differ from the written-out order", bad);
    {
        hcbd_params p = hcbd_params_default();
        const int ns[2] = {3, 3}, ns0[2] = {0, 3};
        int c[2], row, n2[2];
        CHECK(hcbd_sweep_row_place(NULL, p.L, 0, 0, c, &row) == -1 && hcbd_sweep_row_place(ns, NULL, 0, 0, c, &row) == -1 &&
                  hcbd_sweep_row_place(ns, p.L, 0, 0, NULL, &row) == -1 &&
                  hcbd_sweep_row_place(ns, p.L, 0, 0, c, NULL) == -1 &&
                  hcbd_sweep_row_place(ns0, p.L, 0, 0, c, &row) == -1 &&
                  hcbd_sweep_row_place(ns, p.L, p.L[1], 0, c, &row) == -1 &&
                  hcbd_sweep_row_place(ns, p.L, 0, NAN, c, &row) == -1,
              "bad input to hcbd_sweep_row_place refused");
        CHECK(hcbd_params_sweep_rows(NULL, n2) == 0 && hcbd_params_sweep_rows(&p, NULL) == 0, "NULL refused");
        p.dynamics = HCBD_DYN_BD;
        CHECK(hcbd_params_sweep_rows(&p, n2) == 0, "BD has no sweep");
        p = hcbd_params_default();
        p.Rc = -1;
        CHECK(hcbd_params_sweep_rows(&p, n2) == 0, "Rc = -1 refused");
    }
}
