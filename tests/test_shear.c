/* Lees-Edwards shear (MODEL 5): the sheared minimum image and neighbour
   list, the jump of a crossing particle, the linear velocity profile, the
   background momentum flux against an independent sum, determinism. */
#include "test.h"

/* Sheared minimum image, written independently of the library: j's image
   above is shifted by +s in x. */
static double le_r2(const double *xyz, int i, int j, const double L[3], double s, double d[3])
{
    double dx = xyz[3 * i] - xyz[3 * j], dy = xyz[3 * i + 1] - xyz[3 * j + 1];
    double dz = xyz[3 * i + 2] - xyz[3 * j + 2];
    if (dy > 0.5 * L[1]) { dy -= L[1]; dx -= s; }
    else if (dy < -0.5 * L[1]) { dy += L[1]; dx += s; }
    dx -= L[0] * round(dx / L[0]);
    dz -= L[2] * round(dz / L[2]);
    if (d) { d[0] = dx; d[1] = dy; d[2] = dz; }
    return dx * dx + dy * dy + dz * dz;
}

static hcbd_world_def shear_scene(int N, double gdot)
{
    hcbd_world_def d = scene(N, 0.24);
    if (N < 512) d.params.L[0] = d.params.L[1] = d.params.L[2] = 12.9; /* room for 3 cells */
    d.params.potential = HCBD_POT_IDEAL;
    d.params.gdot = gdot;
    return d;
}

/* An equilibrated sheared liquid of ideal particles, tau = 1e-2, dt = 1e-3
   (a 1.0 skin: streaming particles move fast). */
static int sheared_liquid(hcbd_world *w, int N, double gdot, int equil)
{
    hcbd_world_def d = shear_scene(N, gdot);
    d.params.tau = 1e-2;
    d.params.dt = 1e-3;
    d.params.skin = 1.0;
    if (!make_world(w, &d)) return 0;
    hcbd_world_place_random(w, N);
    return run(w, equil);
}

/* Pairs listed = pairs within the cut-off by the sheared minimum image, at
   several offsets; and for particles away from the y boundary the pair
   count does not depend on the offset. */
void test_le_neighbour_list(void)
{
    double offsets[4] = {0.0, 1.234, 5.5, 11.9};
    int o, away;
    for (away = 0; away < 2; ++away)
        for (o = 0; o < 4; ++o) {
            hcbd_world_def d = shear_scene(500, 1.0);
            hcbd_world w;
            double xyz[3 * 500], out[3];
            int i, j, missing = 0, extra = 0, found = 0;
            int64_t listed = 0;
            if (!make_world(&w, &d)) return;
            hcbd_world_place_random(&w, 500);
            hcbd_world_get_positions(&w, xyz, 0);
            if (away) /* squeeze y into [rlist, Ly - rlist]: nothing crosses */
                for (i = 0; i < 500; ++i)
                    xyz[3 * i + 1] = w.nl.rlist + xyz[3 * i + 1] / w.p.L[1] * (w.p.L[1] - 2 * w.nl.rlist);
            hcbd_world_set_positions(&w, 500, xyz);
            w.core.le_offset = offsets[o];
            hcbd_world_friction_average(&w, 1, out); /* builds the list */
            for (i = 0; i < 500; ++i) {
                int32_t p;
                for (p = w.nl.nb_start[w.slot[i]]; p < w.nl.nb_start[w.slot[i] + 1]; ++p) {
                    int jd = w.id[w.nl.nb_j[p]];
                    if (le_r2(xyz, i, jd, w.p.L, offsets[o], NULL) >= w.nl.rlist * w.nl.rlist) ++extra;
                    ++listed;
                }
            }
            for (i = 0; i < 500; ++i)
                for (j = i + 1; j < 500; ++j)
                    if (le_r2(xyz, i, j, w.p.L, offsets[o], NULL) < w.nl.rlist * w.nl.rlist) {
                        int32_t p, si = w.slot[i], ok = 0;
                        ++found;
                        for (p = w.nl.nb_start[si]; p < w.nl.nb_start[si + 1]; ++p)
                            if (w.id[w.nl.nb_j[p]] == j) ok = 1;
                        if (!ok) ++missing;
                    }
            if (o == 3) NOTE("offset %g, %s: %d pairs in range, all listed once", offsets[o],
                             away ? "nothing near the boundary" : "random", found);
            CHECK(missing == 0 && extra == 0 && listed == found,
                  "offset %g away %d: %d of %d pairs missing, %d too far, %lld listed", offsets[o],
                  away, missing, found, extra, (long long)listed);
            if (away) {
                static int64_t first;
                if (o == 0) first = listed;
                CHECK(listed == first, "offset %g changed the pair count %lld -> %lld", offsets[o],
                      (long long)first, (long long)listed);
            }
            hcbd_world_destroy(&w);
        }
}

/* A particle leaving through the top (bottom) re-enters at the bottom
   (top) with x moved back (forward) by the offset and its velocity variable
   lowered (raised) by gdot Ly, exactly; its unwrapped position continues
   smoothly; the one-step carrier stress is -(m v_x)/(Lx Lz dt) upward and
   +m (v_x + gdot Ly)/(Lx Lz dt) downward (MODEL 5). */
void test_le_crossing_jump(void)
{
    int dir;
    for (dir = 0; dir < 2; ++dir) {
        hcbd_world_def d = shear_scene(2, 0.7);
        hcbd_world w;
        double xyz[6], v[6], x1[6], v1[6], u0[6], u1[6], fl[4], s, vy = dir ? -5.0 : 5.0;
        double vle = 0.7 * 12.9, area_dt = 12.9 * 12.9 * 1e-3;
        d.params.kT = 0;
        d.params.dt = 1e-3;
        if (!make_world(&w, &d)) return;
        xyz[0] = 3.0; xyz[1] = dir ? 1e-3 : w.p.L[1] - 1e-3; xyz[2] = 4.0; /* about to cross */
        xyz[3] = 9.0; xyz[4] = 6.0; xyz[5] = 9.0;                           /* far away */
        hcbd_world_set_positions(&w, 2, xyz);
        v[0] = 0.3; v[1] = vy; v[2] = 0.0; v[3] = v[4] = v[5] = 0.0;
        hcbd_world_set_velocities(&w, v);
        run(&w, 10); /* the offset moves away from 0 (particle 0 crosses once) */
        s = w.core.le_offset;
        {
            double keep = w.core.le_offset;
            hcbd_world_set_positions(&w, 2, xyz);
            w.core.le_offset = keep;
        }
        hcbd_world_set_velocities(&w, v);
        hcbd_world_get_positions(&w, u0, 1);
        hcbd_world_stress_enable(&w, 1);
        run(&w, 1);
        hcbd_world_stress_read(&w, fl, NULL);
        hcbd_world_get_positions(&w, x1, 0);
        hcbd_world_get_positions(&w, u1, 1);
        hcbd_world_get_velocities(&w, v1);
        {
            double s_new = s + 0.7 * w.p.L[1] * 1e-3, sg = dir ? -1.0 : 1.0;
            double xe = 3.0 + 0.3e-3 - sg * s_new, ye = dir ? w.p.L[1] - 4e-3 : 4e-3;
            double ce = dir ? w.m * (0.3 + vle) / area_dt : -w.m * 0.3 / area_dt;
            xe -= w.p.L[0] * floor(xe / w.p.L[0]);
            CHECK(fabs(v1[0] - (0.3 - sg * vle)) < 1e-12, "dir %d: velocity jump: %.15g", dir, v1[0]);
            CHECK(fabs(x1[1] - ye) < 1e-12, "dir %d: re-entry y %.15g", dir, x1[1]);
            CHECK(fabs(x1[0] - xe) < 1e-12, "dir %d: re-entry x %.15g, expected %.15g", dir, x1[0], xe);
            CHECK(fabs(u1[0] - (u0[0] + 0.3e-3)) < 1e-12 && fabs(u1[1] - (u0[1] + vy * 1e-3)) < 1e-12,
                  "dir %d: unwrapped position jumped: %g %g -> %g %g", dir, u0[0], u0[1], u1[0], u1[1]);
            CHECK(fabs(fl[2] / ce - 1) < 1e-12, "dir %d: carrier stress %.15g, expected %.15g", dir,
                  fl[2], ce);
        }
        hcbd_world_destroy(&w);
    }
}

/* Under shear with no noise, starting from rest, the offset drift decides
   when the list is rebuilt: at every step of a run every pair within the
   cut-off (sheared minimum image, independent code) must be in the list,
   in a box of exactly 3 cells per edge.  At gdot = 3 the list lives a few
   steps; at gdot = 20 a criterion without the drift misses pairs. */
void test_le_list_every_step(void)
{
    enum { N = 300 };
    double rates[2] = {3.0, 20.0};
    int g;
    for (g = 0; g < 2; ++g) {
        hcbd_world_def d = shear_scene(N, rates[g]);
        hcbd_world w;
        static double xyz[3 * N];
        int step, i, j, missing = 0, checked = 0;
        d.params.kT = 0;
        d.params.dt = 1e-3;
        d.params.L[0] = d.params.L[1] = d.params.L[2] = 8.75; /* 3 cells of 2.9 */
        if (!make_world(&w, &d)) return;
        CHECK(w.nl.nc[0] == 3 && w.nl.nc[1] == 3, "cells %d %d", w.nl.nc[0], w.nl.nc[1]);
        hcbd_world_place_random(&w, N);
        /* from rest, not on the shear profile: then only the offset drift
           moves pairs across the boundary relative to each other */
        memset(xyz, 0, sizeof xyz);
        hcbd_world_set_velocities(&w, xyz);
        for (step = 0; step < 600; ++step) {
            double out[3];
            run(&w, 1);
            hcbd_world_friction_average(&w, 1, out); /* the list the next step will use */
            hcbd_world_get_positions(&w, xyz, 0);
            for (i = 0; i < N; ++i)
                for (j = i + 1; j < N; ++j)
                    if (le_r2(xyz, i, j, w.p.L, w.core.le_offset, NULL) < 2.5 * 2.5) {
                        int32_t p, si = w.slot[i], ok = 0;
                        for (p = w.nl.nb_start[si]; p < w.nl.nb_start[si + 1]; ++p)
                            if (w.id[w.nl.nb_j[p]] == j) ok = 1;
                        missing += !ok;
                        ++checked;
                    }
        }
        NOTE("gdot %g: %d pair-steps checked over 600 steps, %lld rebuilds", rates[g], checked,
             (long long)w.nl.n_rebuilds);
        CHECK(missing == 0, "gdot %g: %d of %d in-range pairs missing from the list", rates[g], missing,
              checked);
        if (g == 0)
            CHECK(w.nl.n_rebuilds < 300, "the list is rebuilt every step (%lld): reuse not exercised",
                  (long long)w.nl.n_rebuilds);
        hcbd_world_destroy(&w);
    }
}

/* The carrier stress measured at the sheared boundary equals an
   independent count at three interior planes y = Ly/4, Ly/2, 3Ly/4: each
   particle crossing upward (downward) in a step carries +(-) m v_x of the
   new step across it.  Errors from blocks of 1000 steps, at least 700 in
   make test: particles near a plane cross back and forth, so a crossing
   count's error falls faster than the square root of the block length;
   at 0.4 the errors grew 1-5 times (2.5 on average, not 1.6) and mp > 4 ep
   held by only 4.2 errors in one of three seeds (6.7 or more at 0.7). */
void test_le_carrier_flux_planes(void)
{
    enum { N = 600, NB = 8 };
    hcbd_world w;
    static double y0[N], xyz[3 * N], v[3 * N];
    double lib[NB], pl[NB], A, ml, el, mp, ep;
    int b, s, i, q, steps = t_quick ? 100 : (int)(1000 * fmax(t_len, 0.7) + 0.5);
    if (!sheared_liquid(&w, N, 10.0, 500)) return;
    A = w.p.L[0] * w.p.L[2];
    for (b = 0; b < NB; ++b) {
        double c = 0, fl[4];
        hcbd_world_stress_enable(&w, 1);
        hcbd_world_get_positions(&w, xyz, 1);
        for (i = 0; i < N; ++i) y0[i] = xyz[3 * i + 1];
        for (s = 0; s < steps; ++s) {
            run(&w, 1);
            hcbd_world_get_positions(&w, xyz, 1); /* unwrapped: interior planes of every image */
            hcbd_world_get_velocities(&w, v);
            for (i = 0; i < N; ++i) {
                double ya = y0[i], yb = xyz[3 * i + 1];
                for (q = 1; q <= 3; ++q) {
                    double ka = floor(ya / w.p.L[1] - 0.25 * q), kb = floor(yb / w.p.L[1] - 0.25 * q);
                    /* velocities of other images differ by gdot Ly: use this
                       image's frame, where the step ends */
                    if (kb > ka) c += w.m * v[3 * i];
                    if (kb < ka) c -= w.m * v[3 * i];
                }
                y0[i] = yb;
            }
        }
        hcbd_world_stress_read(&w, fl, NULL);
        lib[b] = fl[2];
        pl[b] = -c / 3 / (A * w.p.dt * steps);
    }
    block_stats(lib, NB, NB, &ml, &el);
    block_stats(pl, NB, NB, &mp, &ep);
    NOTE("carrier stress: boundary %.5f +- %.5f, interior planes %.5f +- %.5f", ml, el, mp, ep);
    if (!t_quick) {
        CHECK(fabs(ml - mp) < 4 * sqrt(el * el + ep * ep), "boundary %g vs planes %g", ml, mp);
        CHECK(mp > 4 * ep, "carrier stress not resolved: %g +- %g", mp, ep);
    }
    hcbd_world_destroy(&w);
}

/* The background flux of the friction exchanges, for velocities exactly on
   the linear profile v_x = gdot y (kT = 0), equals the independent sum
   (1/V) sum_{i<j} (S_ij/tau) gdot y_ij^2 over sheared minimum images, with
   densities summed here; across the boundary this needs the image's
   velocity shift.  Its ratio to eq. 35 (eta_inf = Rc^2 n# xi'/28) is the
   mean-field one, within the few % that <1/rho> != 1/<rho> gives. */
void test_le_background_flux(void)
{
    enum { N = 800 };
    hcbd_world_def d = shear_scene(N, 1.5);
    hcbd_world w;
    static double xyz[3 * N], v[3 * N], rho[N];
    double flux[4], direct = 0, V, Rc = 2.5, w0 = hcbd_wendland(0, 2.5), nrm, eta35, ratio_sum = 0;
    int i, j, c, s, nconf = 4;
    d.params.kT = 0;
    d.params.pair_integrator = HCBD_PAIR_EULER; /* S/tau dt: the explicit exchange */
    for (s = 0; s < nconf; ++s) {
        d.params.seed = 40 + s;
        if (!make_world(&w, &d)) return;
        hcbd_world_place_random(&w, N);
        w.core.le_offset = 2.0 + s;
        hcbd_world_get_positions(&w, xyz, 0);
        for (i = 0; i < N; ++i) {
            for (c = 0; c < 3; ++c) v[3 * i + c] = 0;
            v[3 * i] = 1.5 * xyz[3 * i + 1];
        }
        hcbd_world_set_velocities(&w, v);
        V = w.p.L[0] * w.p.L[1] * w.p.L[2];
        nrm = 1 / (1 + w0 / 0.24);
        for (i = 0; i < N; ++i) {
            double sw = w0;
            for (j = 0; j < N; ++j)
                if (j != i) sw += hcbd_wendland(sqrt(le_r2(xyz, i, j, w.p.L, w.core.le_offset, NULL)), Rc);
            rho[i] = w.m * nrm * sw;
        }
        direct = 0;
        for (i = 0; i < N; ++i)
            for (j = i + 1; j < N; ++j) {
                double dd[3], r = sqrt(le_r2(xyz, i, j, w.p.L, w.core.le_offset, dd)), S;
                if (r >= Rc) continue;
                S = 15 / (2 * 3.14159265358979323846 * Rc * Rc * Rc) * w.m * w.m * (1 / rho[i] + 1 / rho[j]) *
                    pow(1 - r / Rc, 3);
                direct += S / w.p.tau * 1.5 * dd[1] * dd[1];
            }
        direct /= V;
        hcbd_world_stress_enable(&w, 1);
        run(&w, 1);
        hcbd_world_stress_read(&w, flux, NULL);
        CHECK(fabs(flux[1] / direct - 1) < 1e-9, "background flux %.12g vs direct %.12g", flux[1], direct);
        eta35 = Rc * Rc * 0.24 * w.p.xip / 28;
        ratio_sum += flux[1] / 1.5 / eta35;
        hcbd_world_destroy(&w);
    }
    NOTE("affine background flux / (gdot eta_inf of eq. 35) = %.4f", ratio_sum / nconf);
    CHECK(fabs(ratio_sum / nconf - 1) < 0.05, "mean-field background viscosity %g of eq. 35",
          ratio_sum / nconf);
}

/* In steady shear the mean background velocity is linear in y with slope
   gdot; the viscosity contributions are measured and reported. */
void test_le_linear_profile(void)
{
    enum { N = 600, NS = 8, NB = 10 };
    hcbd_world w;
    double slopes[NB], xyz[3 * N], v[3 * N], flux[4];
    int b, s, i, steps = t_quick ? 200 : 10 * (int)(100 * t_len + 0.5); /* per block */
    if (!sheared_liquid(&w, N, 2.0, 1000)) return;
    hcbd_world_stress_enable(&w, 1);
    for (b = 0; b < NB; ++b) {
        double sum[NS] = {0}, cnt[NS] = {0}, sy = 0, sv = 0, syy = 0, syv = 0, n = 0;
        for (s = 0; s < steps; s += 10) {
            run(&w, 10);
            hcbd_world_get_positions(&w, xyz, 0);
            hcbd_world_get_velocities(&w, v);
            for (i = 0; i < N; ++i) {
                int k = (int)(xyz[3 * i + 1] / w.p.L[1] * NS);
                if (k >= NS) k = NS - 1;
                sum[k] += v[3 * i];
                cnt[k] += 1;
            }
        }
        for (i = 0; i < NS; ++i) {
            double y = (i + 0.5) * w.p.L[1] / NS, u = sum[i] / cnt[i];
            sy += y; sv += u; syy += y * y; syv += y * u; n += 1;
        }
        slopes[b] = (n * syv - sy * sv) / (n * syy - sy * sy);
    }
    {
        double m, e;
        block_stats(slopes, NB, NB, &m, &e);
        hcbd_world_stress_read(&w, flux, NULL);
        NOTE("velocity slope %.4f +- %.4f (gdot 2)", m, e);
        NOTE("viscosity: pair 0, background %.4f, carriers %.4f, total %.4f; eq. 35 %.4f",
             flux[1] / 2, flux[2] / 2, flux[3] / 2, 2.5 * 2.5 * 0.24 / 28);
        if (!t_quick) CHECK(fabs(m - 2.0) < 4 * e && e < 0.1, "slope %g +- %g", m, e);
        CHECK(flux[0] == 0.0, "ideal particles have no pair stress");
    }
    hcbd_world_destroy(&w);
}

/* Same bits for 1, 2 and 3 threads and unsorted storage under shear, stars
   included. */
void test_le_determinism(void)
{
    uint64_t h[4];
    int k;
    for (k = 0; k < 4; ++k) {
        hcbd_world_def d = shear_scene(512, 3.0);
        hcbd_world w;
        double f[4];
        d.params.potential = HCBD_POT_STAR;
        d.params.L[0] = d.params.L[1] = d.params.L[2] = 12.9;
        d.params.threads = k == 3 ? 2 : k + 1;
        d.params.sort = k == 3 ? 0 : 1;
        if (!make_world(&w, &d)) return;
        hcbd_world_place_lattice(&w, 512);
        hcbd_world_stress_enable(&w, 1);
        run(&w, 400);
        hcbd_world_stress_read(&w, f, NULL);
        h[k] = hcbd_world_checksum(&w);
        {
            uint64_t u;
            int c;
            for (c = 0; c < 4; ++c) {
                memcpy(&u, &f[c], 8);
                h[k] = (h[k] ^ u) * 0x100000001B3ULL;
            }
        }
        hcbd_world_destroy(&w);
    }
    CHECK(h[0] == h[1] && h[0] == h[2] && h[0] == h[3], "sheared runs differ: %llx %llx %llx %llx",
          (unsigned long long)h[0], (unsigned long long)h[1], (unsigned long long)h[2],
          (unsigned long long)h[3]);
}

void test_le_bad_inputs(void)
{
    hcbd_world_def d = shear_scene(100, 1.0);
    hcbd_world w;
    hcbd_result r;
    d.params.L[1] = 8.0; /* < 3 (2.5 + 0.4) */
    d.params.skin = 0.4;
    r = hcbd_world_create(&w, &d);
    CHECK(r == HCBD_ERR_BOX && strstr(w.err.msg, "L[1] = 8"), "short box: %s", w.err.msg);
    d = shear_scene(100, 1.0);
    d.params.skin = 0.178;
    d.params.L[1] = 3 * (2.5 + 0.178); /* L / rl = 2.9999999999999996: 2 cells */
    r = hcbd_world_create(&w, &d);
    CHECK(r == HCBD_ERR_BOX, "box of 3 (cut + skin) that rounds to 2 cells: %s", w.err.msg);
    d = shear_scene(100, 1e6); /* offset moves more than a box per step */
    r = hcbd_world_create(&w, &d);
    CHECK(r == HCBD_ERR_PARAM && strstr(w.err.msg, "gdot = "), "huge gdot: %s", w.err.msg);
    d = shear_scene(100, 1.0);
    d.params.dynamics = HCBD_DYN_BD;
    r = hcbd_world_create(&w, &d);
    CHECK(r == HCBD_ERR_PARAM && strstr(w.err.msg, "gdot = "), "shear with BD: %s", w.err.msg);
    d = shear_scene(100, NAN);
    r = hcbd_world_create(&w, &d);
    CHECK(r == HCBD_ERR_PARAM && strstr(w.err.msg, "gdot = "), "NaN gdot: %s", w.err.msg);
}
