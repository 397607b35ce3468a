/* GI-BD and classical BD: conservation, invariance, determinism. */
#include "test.h"

/* <sum_j f_ij> for uncorrelated positions (MODEL 3), and the library's
   value against an independent O(N^2) computation on the same points. */
void test_density_normalisation(void)
{
    int norm;
    for (norm = 2014; norm <= 2016; norm += 2) {
        hcbd_world_def d = scene(1000, 0.24);
        hcbd_world w;
        double sumf = 0, sumf2 = 0;
        int s, nconf = 8;
        d.params.potential = HCBD_POT_IDEAL;
        d.params.density_norm = norm;
        if (!make_world(&w, &d)) return;
        for (s = 0; s < nconf; ++s) {
            double out[3], *xyz = (double *)malloc(3000 * sizeof(double));
            double *rho = (double *)malloc(1000 * sizeof(double)), direct = 0;
            double Rc = 2.5, m = w.m, w0 = hcbd_wendland(0, Rc);
            double nrm = norm == 2016 ? 1 / (1 + w0 / 0.24) : 1;
            int i, j;
            w.p.seed = 1000 + s;
            hcbd_world_place_random(&w, 1000);
            hcbd_world_friction_average(&w, 1, out);
            hcbd_world_get_positions(&w, xyz, 0);
            for (i = 0; i < 1000; ++i) {
                double sw = w0;
                for (j = 0; j < 1000; ++j)
                    if (j != i) sw += hcbd_wendland(sqrt(pair_r2(xyz, i, j, w.p.L)), Rc);
                rho[i] = m * nrm * sw;
            }
            for (i = 0; i < 1000; ++i)
                for (j = 0; j < 1000; ++j) {
                    double r = sqrt(pair_r2(xyz, i, j, w.p.L));
                    if (j != i && r < Rc)
                        direct += 15 / (2 * 3.14159265358979323846 * Rc * Rc * Rc) * m *
                                  (1 / rho[i] + 1 / rho[j]) * pow(1 - r / Rc, 3);
                }
            direct /= 1000;
            CHECK(fabs(direct - out[0]) < 1e-10, "norm %d: library %.12f, direct %.12f", norm,
                  out[0], direct);
            sumf += out[0];
            sumf2 += out[0] * out[0];
            free(xyz);
            free(rho);
        }
        {
            double mean = sumf / nconf, err = sqrt((sumf2 / nconf - mean * mean) / (nconf - 1));
            NOTE("density_norm %d: <sum_j f_ij> = %.4f +- %.4f", norm, mean, err);
            if (norm == 2016)
                CHECK(mean > 0.9 && mean < 1.02, "2016: %g (MODEL 3: 0.92-1)", mean);
            else
                CHECK(mean > 0.45 && mean < 0.56, "2014: %g (MODEL 3: 0.49-0.53)", mean);
        }
        hcbd_world_destroy(&w);
    }
}

static hcbd_world_def star_scene(void)
{
    hcbd_world_def d = scene(512, 0.24);
    d.params.L[0] = d.params.L[1] = d.params.L[2] = 12.9;
    return d;
}

/* sum m v is conserved to round-off over 10^4 steps with forces and noise. */
void test_momentum_conservation(void)
{
    int integ;
    for (integ = 0; integ < 2; ++integ) {
    hcbd_world_def d = star_scene();
    hcbd_world w;
    double p0[3], p1[3], scale = 0, v[3 * 512];
    int i, steps = t_quick ? 1000 : 10000;
    d.params.pair_integrator = integ ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
    if (!make_world(&w, &d)) return;
    hcbd_world_place_lattice(&w, 512);
    hcbd_world_momentum(&w, p0);
    if (!run(&w, steps)) return;
    hcbd_world_momentum(&w, p1);
    hcbd_world_get_velocities(&w, v);
    for (i = 0; i < 3 * 512; ++i) scale += w.m * fabs(v[i]);
    for (i = 0; i < 3; ++i)
        CHECK(fabs(p1[i] - p0[i]) < 1e-12 * scale, "component %d: %g -> %g (scale %g)", i, p0[i],
              p1[i], scale);
    NOTE("%s: |dP| / sum m|v| = %.2e after %d steps", integ ? "Shardlow" : "Euler",
         fabs(p1[0] - p0[0]) / scale, steps);
    hcbd_world_destroy(&w);
    }
}

/* Adding U to every background velocity shifts the trajectory by U t and
   the velocities by U, with the same seed, to round-off. */
void test_galilean_invariance(void)
{
    int integ;
    for (integ = 0; integ < 2; ++integ) {
    hcbd_world_def d = star_scene();
    hcbd_world a, b;
    double U[3] = {0.7, -0.4, 0.25}, va[3 * 512], vb[3 * 512], ra[3 * 512];
    double t, dev_r = 0, dev_v = 0;
    int i, steps = 300;
    d.params.tau = 3.6e-2;
    d.params.pair_integrator = integ ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
    if (!make_world(&a, &d) || !make_world(&b, &d)) return;
    hcbd_world_place_lattice(&a, 512);
    hcbd_world_place_lattice(&b, 512);
    run(&a, 500);
    hcbd_world_get_positions(&a, ra, 1);
    hcbd_world_get_velocities(&a, va);
    hcbd_world_set_positions(&b, 512, ra);
    for (i = 0; i < 3 * 512; ++i) vb[i] = va[i] + U[i % 3];
    hcbd_world_set_velocities(&b, vb);
    /* the noise is keyed by (seed, step, ids): the same step counter gives
       the same draws */
    b.step = a.step;
    hcbd_world_get_positions(&a, ra, 1);
    run(&a, steps);
    run(&b, steps);
    t = steps * d.params.dt;
    {
        double ra1[3 * 512], rb1[3 * 512];
        hcbd_world_get_positions(&a, ra1, 1);
        hcbd_world_get_positions(&b, rb1, 1);
        hcbd_world_get_velocities(&a, va);
        hcbd_world_get_velocities(&b, vb);
        for (i = 0; i < 3 * 512; ++i) {
            double e = fabs(rb1[i] - ra1[i] - U[i % 3] * t);
            double f = fabs(vb[i] - va[i] - U[i % 3]);
            if (e > dev_r) dev_r = e;
            if (f > dev_v) dev_v = f;
        }
    }
    NOTE("%s: max |dR - U t| = %.2e, max |dv - U| = %.2e", integ ? "Shardlow" : "Euler", dev_r,
         dev_v);
    CHECK(dev_r < 1e-9, "positions deviate by %g", dev_r);
    CHECK(dev_v < 1e-8, "velocities deviate by %g", dev_v);
    hcbd_world_destroy(&a);
    hcbd_world_destroy(&b);
    }
}

/* Checksum of the state and of the observables' bits. */
static uint64_t run_hash(hcbd_world_def d, int steps)
{
    hcbd_world w;
    uint64_t h;
    double obs[9 + 12 + 3 + 3 + 1];
    int k;
    if (!make_world(&w, &d)) return 0;
    hcbd_world_place_lattice(&w, d.capacity);
    run(&w, steps);
    h = hcbd_world_checksum(&w);
    hcbd_world_virial_stress(&w, obs);
    hcbd_world_transverse_current(&w, 1, obs + 9);
    hcbd_world_momentum(&w, obs + 21);
    if (w.gibd) hcbd_world_friction_average(&w, 1, obs + 24);
    else obs[24] = obs[25] = obs[26] = 0;
    obs[27] = hcbd_world_temperature(&w);
    for (k = 0; k < 28; ++k) {
        uint64_t u;
        memcpy(&u, &obs[k], 8);
        h = (h ^ u) * 0x100000001B3ULL;
    }
    hcbd_world_destroy(&w);
    return h;
}

/* Same seed: same bits, in the state and in the observables; any thread
   count, with or without storage sorting: same bits; another seed: other
   bits. */
void test_determinism(void)
{
    const int steps = t_quick ? 50 : 400; /* the other builds need the paths */
    int lag, dyn;
    /* dyn 2: GI-BD with the Shardlow pair sweep */
    for (dyn = 0; dyn < 3; ++dyn)
        for (lag = 0; lag < 2; ++lag) {
            hcbd_world_def d = star_scene(), e;
            uint64_t h1, h2, h3, h4, h5;
            d.params.dynamics = dyn == 1 ? HCBD_DYN_BD : HCBD_DYN_GIBD;
            d.params.pair_integrator = dyn == 2 ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
            d.params.lagged_density = lag;
            if (dyn == 1 && lag) continue;
            h1 = run_hash(d, steps);
            h2 = run_hash(d, steps);
            e = d; e.params.threads = 2; h3 = run_hash(e, steps);
            e = d; e.params.sort = 0; e.params.threads = 3; h4 = run_hash(e, steps);
            e = d; e.params.seed = 2; h5 = run_hash(e, steps);
            CHECK(h1 == h2, "dyn %d lag %d: same seed differs", dyn, lag);
            CHECK(h1 == h3, "dyn %d lag %d: 2 threads differ from 1", dyn, lag);
            CHECK(h1 == h4, "dyn %d lag %d: unsorted storage, 3 threads differ", dyn, lag);
            CHECK(h1 != h5, "dyn %d lag %d: different seeds give the same state", dyn, lag);
        }
#ifndef _OPENMP
    NOTE("built without OpenMP: thread counts are ignored, the check is trivial");
#endif
}

/* Every fast path of a GI-BD step gives the bits of the general path.
   The stress accumulation is an observable, but it switches the step's
   passes: without it the forces and this step's densities share one pass,
   which with the star table streams many owners' pairs through SIMD loops,
   and the exact sweep takes each pair's r^2 from that pass (unsheared);
   with it the densities have a pass of their own, the general force pass
   runs and the sweep measures every pair again.  So a run with the stress
   on, one with it off and one with every pass in its general form
   (core.general) must end in the same state, over the options
   that switch the paths: BD, GI-BD with the sweep and with Euler pairs;
   Lees-Edwards shear on and off; lagged densities; the star, ideal and
   table potentials (and, in the walled build, walls). */
void test_fast_paths_stress_bits(void)
{
    enum { NT = 2001 };
    static double tF[NT], tV[NT];
    const int steps = t_quick ? 20 : 120;
    int dyn, shear, lag, pot, walls, k, cases = 0;
    for (k = 0; k < NT; ++k) {
        const double r = 0.3 + k * (2.5 - 0.3) / (NT - 1);
        tF[k] = hcbd_star_force(r, 32, 1, 1);
        tV[k] = hcbd_star_potential(r, 32, 1, 1);
    }
    for (dyn = 0; dyn < 3; ++dyn)
        for (shear = 0; shear < 2; ++shear)
            for (lag = 0; lag < 2; ++lag)
                for (pot = 0; pot < 3; ++pot)
                    for (walls = 0; walls < (HCBD_MODEL == HCBD_MODEL_WALLED ? 2 : 1); ++walls) {
                        hcbd_world_def d = star_scene();
                        hcbd_world a, b, c;
                        if (dyn == 0 && (lag || shear)) continue; /* GI-BD only */
                        d.params.dynamics = dyn ? HCBD_DYN_GIBD : HCBD_DYN_BD;
                        d.params.pair_integrator = dyn == 2 ? HCBD_PAIR_EULER : HCBD_PAIR_SHARDLOW;
                        d.params.lagged_density = lag;
                        d.params.gdot = shear ? 3.0 : 0.0;
                        d.params.potential = pot == 0 ? HCBD_POT_STAR : pot == 1 ? HCBD_POT_IDEAL : HCBD_POT_TABLE;
                        if (pot == 2) {
                            d.params.table_F = tF; d.params.table_V = tV;
                            d.params.table_n = NT; d.params.table_r0 = 0.3;
                        }
#if HCBD_MODEL == HCBD_MODEL_WALLED
                        if (walls) {
                            if (shear || lag) continue; /* neither goes with walls */
                            d.params.wall.thickness = 1.5;
                            d.params.L[1] += 3.0;
                            d.params.fext[0] = 20.0;
                        }
#endif
                        if (!make_world(&a, &d)) return;
                        if (!make_world(&b, &d)) { hcbd_world_destroy(&a); return; }
                        if (!make_world(&c, &d)) { hcbd_world_destroy(&a); hcbd_world_destroy(&b); return; }
                        c.core.general = 1;
                        hcbd_world_place_lattice(&a, d.capacity);
                        hcbd_world_place_lattice(&b, d.capacity);
                        hcbd_world_place_lattice(&c, d.capacity);
                        hcbd_world_stress_enable(&b, 1);
                        run(&a, steps);
                        run(&b, steps);
                        run(&c, steps);
                        CHECK(hcbd_world_checksum(&a) == hcbd_world_checksum(&b),
                              "%s%s%s, potential %d%s: stress accumulation changes the state",
                              dyn == 0 ? "BD" : dyn == 1 ? "GI-BD sweep" : "GI-BD Euler", shear ? ", sheared" : "",
                              lag ? ", lagged densities" : "", pot, walls ? ", walls" : "");
                        CHECK(hcbd_world_checksum(&a) == hcbd_world_checksum(&c),
                              "%s%s%s, potential %d%s: the fast paths end in other bits than the general passes",
                              dyn == 0 ? "BD" : dyn == 1 ? "GI-BD sweep" : "GI-BD Euler", shear ? ", sheared" : "",
                              lag ? ", lagged densities" : "", pot, walls ? ", walls" : "");
                        ++cases;
                        hcbd_world_destroy(&a);
                        hcbd_world_destroy(&b);
                        hcbd_world_destroy(&c);
                    }
    NOTE("%d combinations, the same bits with the stress on and off", cases);
}

/* The same bits for any thread count, storage order and list rebuild
   times, in a box wide enough for the parallel paths (the pair passes cut
   it into slabs of z-layers, the exact sweep runs rows of one colour side
   by side): 4096 stars, 8 layers of cells; threads 1, 2 and 4, unsorted
   storage, a skin of 0.15 (a list build every few steps) instead of the
   automatic 0.6. */
void test_determinism_parallel(void)
{
    /* the sanitizer builds need the paths, not the length */
    const int steps = t_quick ? 12 : 60;
    int dyn;
    for (dyn = 0; dyn < 3; ++dyn) {
        hcbd_world_def d = scene(4096, 0.24), e;
        uint64_t h1, h2, h4, hs, hk;
        d.params.L[0] = d.params.L[1] = d.params.L[2] = 25.8;
        d.params.dynamics = dyn == 0 ? HCBD_DYN_BD : HCBD_DYN_GIBD;
        d.params.pair_integrator = dyn == 2 ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
        h1 = run_hash(d, steps);
        e = d; e.params.threads = 2; h2 = run_hash(e, steps);
        e = d; e.params.threads = 4; h4 = run_hash(e, steps);
        e = d; e.params.threads = 2; e.params.sort = 0; hs = run_hash(e, steps);
        e = d; e.params.skin = 0.15; hk = run_hash(e, steps);
        CHECK(h1 == h2 && h1 == h4, "%s: threads 1, 2, 4 differ", dyn == 0 ? "BD" : dyn == 1 ? "Euler" : "Shardlow");
        CHECK(h1 == hs, "%s: unsorted storage differs", dyn == 0 ? "BD" : dyn == 1 ? "Euler" : "Shardlow");
        CHECK(h1 == hk, "%s: another skin (other rebuild times) differs",
              dyn == 0 ? "BD" : dyn == 1 ? "Euler" : "Shardlow");
    }
}

/* kT = 0 draws no random numbers (another seed gives the same bits), and
   ideal BD builds no neighbour list. */
void test_skipped_work(void)
{
    hcbd_world_def d = star_scene();
    hcbd_world w, w2;
    d.params.kT = 0;
    if (!make_world(&w, &d)) return;
    d.params.seed ^= 0x5151;
    if (!make_world(&w2, &d)) { hcbd_world_destroy(&w); return; }
    hcbd_world_place_lattice(&w, 512);
    hcbd_world_place_lattice(&w2, 512);
    run(&w, 50);
    run(&w2, 50);
    CHECK(hcbd_world_checksum(&w) == hcbd_world_checksum(&w2), "kT = 0 depends on the seed");
    hcbd_world_destroy(&w2);
    CHECK(hcbd_world_temperature(&w) < 1e-20, "kT = 0 lattice start has T = %g", hcbd_world_temperature(&w));
    hcbd_world_destroy(&w);
    d = star_scene();
    d.params.dynamics = HCBD_DYN_BD;
    d.params.potential = HCBD_POT_IDEAL;
    if (!make_world(&w, &d)) return;
    hcbd_world_place_lattice(&w, 512);
    run(&w, 50);
    CHECK(w.nl.n_rebuilds == 0, "ideal BD built %lld neighbour lists", (long long)w.nl.n_rebuilds);
    hcbd_world_destroy(&w);
}

/* The lagged densities (2014's speed-up) are the densities of the
   previous step: a run with them stays close to the exact run and keeps
   momentum. */
void test_lagged_density(void)
{
    hcbd_world_def d = star_scene();
    hcbd_world a, b;
    double pa[3], pb[3], ta, tb;
    d.params.kT = 1;
    if (!make_world(&a, &d)) return;
    d.params.lagged_density = 1;
    if (!make_world(&b, &d)) return;
    hcbd_world_place_lattice(&a, 512);
    hcbd_world_place_lattice(&b, 512);
    run(&a, 1);
    run(&b, 1);
    /* first step: no lag yet, identical */
    CHECK(hcbd_world_checksum(&a) == hcbd_world_checksum(&b), "first step differs");
    run(&a, 200);
    run(&b, 200);
    hcbd_world_momentum(&b, pb);
    hcbd_world_momentum(&a, pa);
    ta = hcbd_world_temperature(&a);
    tb = hcbd_world_temperature(&b);
    CHECK(fabs(pb[0]) < 1e-12 && fabs(pb[1]) < 1e-12, "lagged momentum %g %g", pb[0], pb[1]);
    CHECK(hcbd_world_checksum(&a) != hcbd_world_checksum(&b), "lag has no effect");
    /* the densities held for the next step are those of the positions
       before the last step (2014's lag), by an independent O(N^2) sum */
    {
        static double xyz[3 * 512];
        double w0 = hcbd_wendland(0, 2.5), nrm = 1 / (1 + w0 / 0.24), maxdev = 0;
        int i, j;
        hcbd_world_get_positions(&b, xyz, 0);
        run(&b, 1);
        for (i = 0; i < 512; ++i) {
            double sw = w0;
            for (j = 0; j < 512; ++j)
                if (j != i) sw += hcbd_wendland(sqrt(pair_r2(xyz, i, j, b.p.L)), 2.5);
            sw *= b.m * nrm;
            if (fabs(b.rho[b.slot[i]] / sw - 1) > maxdev) maxdev = fabs(b.rho[b.slot[i]] / sw - 1);
        }
        CHECK(maxdev < 1e-12, "lagged densities differ from those of the previous step by %g", maxdev);
    }
    NOTE("T exact %.4f, lagged %.4f", ta, tb);
    hcbd_world_destroy(&a);
    hcbd_world_destroy(&b);
}
