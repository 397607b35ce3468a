/* Walls (MODEL 4): the repulsion against its gradient, the artificial
   particles (count, uniformity, their share of the densities), the Morris
   friction against an independent sum, the temperature profile and its
   fluctuation-dissipation balance, momentum absorbed by the walls, the two
   ways of applying the body force, slip and depletion, determinism and bad
   inputs.  The wall tests need the walled build; the model-switch test
   runs in both. */
#include "test.h"

/* Only the walled build has wall parameters (params.wall): it accepts
   walls; in the other builds the channel is the whole box. */
void test_model_switch(void)
{
    hcbd_world_def d = hcbd_world_def_default();
    hcbd_theory t;
    char msg[256];
    hcbd_result r;
    d.params.L[1] = 13.0;
#if HCBD_MODEL == HCBD_MODEL_WALLED
    d.params.wall.thickness = 1.5;
#endif
    r = hcbd_params_check(&d.params, msg, sizeof msg);
    CHECK(r == HCBD_OK, "walls rejected: %s", msg);
    CHECK(hcbd_params_theory(&d.params, &t) == HCBD_OK &&
              t.width == (HCBD_MODEL == HCBD_MODEL_WALLED ? 10.0 : 13.0),
          "channel width %g", t.width);
}

#if HCBD_MODEL == HCBD_MODEL_WALLED
/* The paper's channel: 13^3 box, walls 1.5 thick, n# = 0.24, 406 real
   particles; ideal particles unless a test says otherwise. */
static hcbd_world_def channel(void)
{
    hcbd_world_def d = hcbd_world_def_default();
    d.params.L[0] = d.params.L[1] = d.params.L[2] = 13.0;
    d.params.wall.thickness = 1.5;
    d.params.tau = 3e-3;
    d.params.potential = HCBD_POT_IDEAL;
    d.capacity = 406;
    return d;
}

void test_wall_bad_inputs(void)
{
    hcbd_world_def d = channel();
    hcbd_world w;
    double xyz[6] = {1, 5, 1, 2, 0.7, 2};
    hcbd_result r;
    d.params.wall.thickness = 6.5; /* 2 t = L[1]: no channel */
    r = hcbd_world_create(&w, &d);
    CHECK(r == HCBD_ERR_BOX && strstr(w.err.msg, "wall.thickness = 6.5"), "thick: %s", w.err.msg);
    d.params.wall.thickness = 1.2; /* 2 t < Rc with periodic y */
    r = hcbd_world_create(&w, &d);
    CHECK(r == HCBD_ERR_BOX && strstr(w.err.msg, "wall.thickness = 1.2") &&
          strstr(w.err.msg, "periodic"), "thin: %s", w.err.msg);
    d = channel();
    d.params.wall.beta_max = 0.9;
    r = hcbd_world_create(&w, &d);
    CHECK(r == HCBD_ERR_PARAM && strstr(w.err.msg, "wall.beta_max = 0.9"), "beta: %s", w.err.msg);
    d = channel();
    d.params.gdot = 1.0;
    r = hcbd_world_create(&w, &d);
    CHECK(r == HCBD_ERR_PARAM && strstr(w.err.msg, "gdot"), "walls + shear: %s", w.err.msg);
    d = channel();
    d.params.wall.mode = (hcbd_wall_mode)7;
    r = hcbd_world_create(&w, &d);
    CHECK(r == HCBD_ERR_PARAM && strstr(w.err.msg, "wall.mode = 7"), "mode: %s", w.err.msg);
    /* a sheared bulk whose offset would move by more than a box per step,
       in either direction */
    d = hcbd_world_def_default();
    d.params.potential = HCBD_POT_IDEAL;
    d.params.gdot = -2.0 * d.params.L[0] / (d.params.L[1] * d.params.dt);
    r = hcbd_world_create(&w, &d);
    CHECK(r == HCBD_ERR_PARAM && strstr(w.err.msg, "gdot = -"), "negative gdot: %s", w.err.msg);
    /* a particle handed in inside a wall is refused, by id */
    d = channel();
    d.capacity = 2;
    if (!make_world(&w, &d)) return;
    r = hcbd_world_set_positions(&w, 2, xyz);
    CHECK(r == HCBD_ERR_WALL && w.err.id == 1 && strstr(w.err.msg, "inside a wall"),
          "inside: %s", w.err.msg);
    hcbd_world_destroy(&w);
}

/* Force = -dE/dy by central differences; the far plane's share at the
   interface (MODEL 4: 0.46 kT); the excluded width against a trapezoid
   integral of an independently written potential. */
void test_wall_potential(void)
{
    hcbd_world_def d = channel();
    hcbd_theory th;
    const hcbd_params *p = &d.params;
    double y, worst = 0, far, dep = 0, h = 1e-4;
    int k;
    for (y = 1.3; y < 11.8; y += 0.173) {
        double f, ep, em;
        hcbd_params_wall_potential(p, y, &f);
        ep = hcbd_params_wall_potential(p, y + 1e-5, NULL);
        em = hcbd_params_wall_potential(p, y - 1e-5, NULL);
        worst = fmax(worst, fabs(f + (ep - em) / 2e-5) / (1.0 + fabs(f)));
    }
    CHECK(worst < 1e-6, "force vs -dE/dy: worst relative error %g", worst);
    far = hcbd_params_wall_potential(p, 1.5, NULL) - 300.0 * exp(-2.0 * 1.2 * 1.2);
    CHECK(fabs(far - 300.0 * exp(-2.0 * 1.8 * 1.8)) < 1e-12 && fabs(far - 0.46) < 0.005,
          "far plane at the interface: %g kT", far);
    for (k = 0; k < 50000; ++k) { /* from the interface to the centre */
        double y0 = 1.5 + k * h, y1 = y0 + h, e0 = 0, e1 = 0, pl[2] = {0.3, 12.7};
        int q;
        for (q = 0; q < 2; ++q) {
            double s0 = y0 - pl[q], s1 = y1 - pl[q];
            s0 -= 13.0 * round(s0 / 13.0);
            s1 -= 13.0 * round(s1 / 13.0);
            e0 += 300.0 * exp(-2.0 * s0 * s0);
            e1 += 300.0 * exp(-2.0 * s1 * s1);
        }
        dep += 0.5 * h * ((1 - exp(-e0)) + (1 - exp(-e1)));
    }
    hcbd_params_theory(p, &th);
    CHECK(fabs(th.depletion_width - dep) < 1e-6, "depletion width %.8f vs %.8f",
          th.depletion_width, dep);
    NOTE("excluded width per wall (Boltzmann, ideal): %.4f sigma", dep);
}

/* round(n# x wall volume) artificial particles, all inside the walls,
   uniform there, new every step; a real particle at the interface sees
   half a bulk of them in its density. */
void test_wall_artificial_particles(void)
{
    hcbd_world_def d = channel();
    hcbd_world w;
    double xyz[6] = {3.0, 1.5, 3.0, 9.0, 6.5, 9.0}, rho[400], mean, err, want;
    double cy[6] = {0}, cx[5] = {0}, chi2 = 0, first_x = 0;
    int s, k, same = 0, outside = 0, nsteps = t_quick ? 100 : 400;
    d.capacity = 2;
    if (!make_world(&w, &d)) return;
    CHECK(w.ws.n_art == 122, "artificial particles: %d, want round(0.24 x 13 x 3 x 13) = 122", w.ws.n_art);
    d.params.kT = 0; /* no noise and no forces: the two real particles stay put */
    d.params.wall.mode = HCBD_WALL_REFLECT;
    hcbd_world_destroy(&w);
    if (!make_world(&w, &d)) return;
    hcbd_world_set_positions(&w, 2, xyz);
    for (s = 0; s < nsteps; ++s) {
        if (!run(&w, 1)) return;
        /* the density of this step: the particle at the interface is id 0 */
        rho[s] = w.rho[w.slot[0]];
        if (s > 0 && w.ws.ax[0] == first_x) ++same;
        first_x = w.ws.ax[0];
        for (k = 0; k < w.ws.n_art; ++k) {
            double y = w.ws.ay[k] < 6.5 ? w.ws.ay[k] + 13.0 : w.ws.ay[k]; /* slab [11.5, 14.5) */
            if (y < 11.5 || y >= 14.5) ++outside;
            cy[(int)((y - 11.5) / 0.5) % 6] += 1;
            cx[(int)(w.ws.ax[k] / 2.6) % 5] += 1;
        }
    }
    CHECK(outside == 0, "%d artificial particles outside the walls", outside);
    CHECK(same == 0, "artificial particles not redrawn in %d steps", same);
    for (k = 0; k < 6; ++k) chi2 += pow(cy[k] - nsteps * 122 / 6.0, 2) / (nsteps * 122 / 6.0);
    for (k = 0; k < 5; ++k) chi2 += pow(cx[k] - nsteps * 122 / 5.0, 2) / (nsteps * 122 / 5.0);
    /* 9 degrees of freedom: P(chi2 > 27.9) = 0.001 */
    CHECK(chi2 < 27.9, "uniformity chi2 = %.1f (9 dof)", chi2);
    block_stats(rho, nsteps, 20, &mean, &err);
    /* m rho_norm (w0 + n#/2): half the kernel lies in the wall */
    want = w.m * w.rho_norm * (w.w0 + 0.5 * 0.24);
    CHECK(fabs(mean - want) < 4 * err, "rho at the interface %.5f +- %.5f, want %.5f", mean,
          err, want);
    hcbd_world_destroy(&w);
}

/* One step with kT = 0: the velocity change of a particle near a wall is
   the Morris friction summed independently over this step's artificial
   particles, plus the wall force.  Checked for both walls, a moving wall,
   the beta cap, and the no-slip mode's shifted Morris plane. */
void test_wall_morris_friction(void)
{
    int mode, side, capped = 0, free_ = 0;
    for (mode = 0; mode < 2; ++mode)
        for (side = 0; side < 2; ++side) {
            hcbd_world_def d = channel();
            hcbd_world w;
            hcbd_theory th;
            double xyz[6] = {4.0, 2.1, 5.0, 9.0, 6.5, 9.0}, v[6] = {1.0, 0.5, -0.3, 0, 0, 0};
            double vnew[6], rhoA, P[3] = {0, 0, 0}, fy, plane, Rc = 2.5, m, err = 0;
            int k;
            d.capacity = 2;
            d.params.kT = 0;
            d.params.pair_integrator = HCBD_PAIR_EULER; /* the explicit Morris sum below */
            d.params.wall.vx[0] = 0.2;
            d.params.wall.vx[1] = -0.7;
            d.params.wall.mode = mode ? HCBD_WALL_NOSLIP : HCBD_WALL_GAUSS;
            /* a distance from the Morris plane where some pairs hit the cap */
            if (mode) xyz[1] = 2.6;
            if (side) xyz[1] = 13.0 - xyz[1];
            if (!make_world(&w, &d)) return;
            hcbd_world_set_positions(&w, 2, xyz);
            hcbd_world_set_velocities(&w, v);
            if (!run(&w, 1)) return;
            hcbd_world_get_velocities(&w, vnew);
            hcbd_params_theory(&d.params, &th);
            m = w.m;
            plane = 1.5 + (mode ? th.depletion_width : 0.0);
            rhoA = 0;
            for (k = 0; k < w.ws.n_art; ++k) { /* density of particle 0 */
                double dx = xyz[0] - w.ws.ax[k], dy = xyz[1] - w.ws.ay[k], dz = xyz[2] - w.ws.az[k], r;
                dx -= 13 * round(dx / 13); dy -= 13 * round(dy / 13); dz -= 13 * round(dz / 13);
                r = sqrt(dx * dx + dy * dy + dz * dz);
                rhoA += hcbd_wendland(r, Rc);
            }
            rhoA = m * w.rho_norm * (hcbd_wendland(0, Rc) + rhoA);
            for (k = 0; k < w.ws.n_art; ++k) {
                double dx = xyz[0] - w.ws.ax[k], dy = xyz[1] - w.ws.ay[k], dz = xyz[2] - w.ws.az[k], r;
                double dA, dB, beta, f, vw;
                dx -= 13 * round(dx / 13); dy -= 13 * round(dy / 13); dz -= 13 * round(dz / 13);
                r = sqrt(dx * dx + dy * dy + dz * dz);
                if (r >= Rc) continue;
                if (!side) { dA = xyz[1] - plane; dB = plane - (xyz[1] - dy); vw = 0.2; }
                else { dA = (13.0 - plane) - xyz[1]; dB = (xyz[1] - dy) - (13.0 - plane); vw = -0.7; }
                beta = 1 + dB / dA;
                if (beta > 1.5) { beta = 1.5; ++capped; } else ++free_;
                /* f_AB = 15/(2 pi Rc^3) m (1/rho_A + 1/rho_B)(1 - r/Rc)^3, rho_B = m n# */
                f = 15.0 / (2 * 3.14159265358979323846 * Rc * Rc * Rc) * m *
                    (1 / rhoA + 1 / (m * 0.24)) * pow(1 - r / Rc, 3);
                P[0] -= beta * f / d.params.tau * (v[0] - vw) * d.params.dt;
                P[1] -= beta * f / d.params.tau * v[1] * d.params.dt;
                P[2] -= beta * f / d.params.tau * v[2] * d.params.dt;
            }
            hcbd_params_wall_potential(&d.params, xyz[1], &fy);
            err = fmax(err, fabs(vnew[0] - (v[0] + P[0])));
            err = fmax(err, fabs(vnew[1] - (v[1] + P[1] + fy * d.params.dt / m)));
            err = fmax(err, fabs(vnew[2] - (v[2] + P[2])));
            CHECK(err < 1e-12 && P[0] != 0, "mode %d side %d: |dv - independent| = %g (dv_x %g)",
                  mode, side, err, P[0]);
            hcbd_world_destroy(&w);
        }
    CHECK(capped > 0 && free_ > 0, "the cases cover %d capped and %d free pairs", capped, free_);
}

/* hcbd_walls, the walls without a world (lammps/): its artificial
   particles are the world's of the same step, bit for bit; its weight sum
   is an independent sum over all of them; one particle near each wall,
   stepped by the world, ends with the velocity the public pieces give
   (density, Morris pairs, wall force: the sweep's in place, Euler's as
   exchanges), for a moving wall, noise and both integrators; bad inputs
   are refused by name and leave nothing drawn. */
void test_walls_exported(void)
{
    int integ, side;
    for (integ = 0; integ < 2; ++integ)
        for (side = 0; side < 2; ++side) {
            hcbd_world_def d = channel();
            hcbd_world w;
            hcbd_walls wl;
            hcbd_gibd_coef c;
            double xyz[6] = {4.0, 2.2, 5.0, 9.0, 6.5, 9.0}, v[6] = {1.0, 0.5, -0.3, 0, 0, 0};
            double vw[6], u[3], P[3] = {0, 0, 0}, r[3], ws = 0, fy, rho, err = 0;
            char msg[256];
            void *mem;
            size_t nb;
            int k, same = 1;
            d.capacity = 2;
            d.params.kT = 1.3;
            d.params.pair_integrator = integ ? HCBD_PAIR_EULER : HCBD_PAIR_SHARDLOW;
            d.params.wall.vx[0] = 0.2;
            d.params.wall.vx[1] = -0.7;
            d.params.wall.mode = HCBD_WALL_NOSLIP;
            if (side) xyz[1] = 13.0 - xyz[1];
            if (!make_world(&w, &d)) return;
            CHECK(hcbd_world_set_positions(&w, 2, xyz) == HCBD_OK && hcbd_world_set_velocities(&w, v) == HCBD_OK,
                  "set-up: %s", w.err.msg);
            if (!run(&w, 3)) return;
            hcbd_world_get_positions(&w, xyz, 0);
            hcbd_world_get_velocities(&w, v);
            nb = hcbd_walls_bytes(&d.params);
            mem = malloc(nb);
            CHECK(nb > 0 && mem && hcbd_walls_init(&wl, &d.params, mem, nb, msg, sizeof msg) == HCBD_OK,
                  "hcbd_walls_init: %s", msg);
            CHECK(hcbd_walls_draw(&wl, w.step) == HCBD_OK && hcbd_params_gibd_coef(&d.params, &c, NULL, 0) == HCBD_OK,
                  "draw");
            if (!run(&w, 1)) return;
            CHECK(wl.ws.n_art == w.ws.n_art, "%d artificial particles, the world's %d", wl.ws.n_art, w.ws.n_art);
            for (k = 0; k < w.ws.n_art && k < wl.ws.n_art; ++k)
                same &= wl.ws.ax[k] == w.ws.ax[k] && wl.ws.ay[k] == w.ws.ay[k] && wl.ws.az[k] == w.ws.az[k];
            CHECK(same, "the artificial particles differ from the world's of the same step");
            for (k = 0; k < wl.ws.n_art; ++k) {
                double dx = xyz[0] - wl.ws.ax[k], dy = xyz[1] - wl.ws.ay[k], dz = xyz[2] - wl.ws.az[k];
                dx -= 13 * round(dx / 13); dy -= 13 * round(dy / 13); dz -= 13 * round(dz / 13);
                ws += hcbd_wendland(sqrt(dx * dx + dy * dy + dz * dz), 2.5);
            }
            for (k = 0; k < 3; ++k) r[k] = xyz[k];
            CHECK(ws > 0 && fabs(hcbd_walls_weights(&wl, r) - ws) < 1e-12 * ws, "weights %.15g, direct sum %.15g",
                  hcbd_walls_weights(&wl, r), ws);
            /* the particles are far apart: particle 0 has only wall pairs */
            rho = hcbd_gibd_density(&c, hcbd_walls_weights(&wl, r));
            hcbd_params_wall_potential(&d.params, r[1], &fy);
            /* the sweep kicks before its pairs; Euler adds the kick and the exchanges after */
            for (k = 0; k < 3; ++k) u[k] = v[k] + (integ ? 0.0 : (k == 1 ? fy : 0.0) * d.params.dt / c.m);
            hcbd_walls_morris(&wl, !integ, 0, r, 1.0 / rho, u, P);
            hcbd_world_get_velocities(&w, vw);
            for (k = 0; k < 3; ++k) {
                const double want = u[k] + (integ ? ((k == 1 ? fy : 0.0) * d.params.dt + P[k]) / c.m : 0.0);
                err = fmax(err, fabs(vw[k] - want));
            }
            CHECK(err < 1e-12 && (integ ? P[0] != 0 : u[0] != v[0]), "%s side %d: |v - hcbd_walls'| = %g",
                  integ ? "Euler" : "sweep", side, err);
            /* far from the walls: nothing */
            r[1] = 6.5;
            u[0] = 1.0;
            hcbd_walls_morris(&wl, 1, 0, r, 1.0 / rho, u, NULL);
            CHECK(u[0] == 1.0 && hcbd_walls_weights(&wl, r) == 0.0, "the channel's middle feels the walls");
            free(mem);
            hcbd_world_destroy(&w);
        }
    {
        hcbd_world_def d = channel();
        hcbd_walls wl;
        char msg[256];
        static char mem[1 << 16];
        d.params.tau = 0;
        CHECK(hcbd_walls_bytes(&d.params) == 0 &&
                  hcbd_walls_init(&wl, &d.params, mem, sizeof mem, msg, sizeof msg) == HCBD_ERR_PARAM &&
                  strstr(msg, "tau = 0"), "tau = 0: %s", msg);
        d = channel();
        d.params.dynamics = HCBD_DYN_BD;
        CHECK(hcbd_walls_init(&wl, &d.params, mem, sizeof mem, msg, sizeof msg) == HCBD_ERR_PARAM &&
                  strstr(msg, "dynamics"), "BD: %s", msg);
        d = channel();
        CHECK(hcbd_walls_init(&wl, &d.params, mem, 64, msg, sizeof msg) == HCBD_ERR_MEMORY &&
                  strstr(msg, "hcbd_walls_bytes"), "small block: %s", msg);
        CHECK(hcbd_walls_init(&wl, &d.params, mem, sizeof mem, msg, sizeof msg) == HCBD_OK &&
                  hcbd_walls_draw(&wl, -1) == HCBD_ERR_PARAM && wl.step == -1 && hcbd_walls_draw(NULL, 0) == HCBD_ERR_NULL,
              "draw at step -1 accepted");
    }
}

/* Equilibrium channel of ideal particles (Gaussian walls, no body force):
   slab temperature profile.  Returns the largest relative deviation of a
   slab holding 20 % of the mean count from the central slabs, the error of
   that deviation, and the central temperature with its error.  The full
   run is 20 profile blocks of time / 20; a shorter one (len < 1) keeps
   the blocks and runs round(20 len) of them: the slab temperature is taken
   about each block's slab mean, so the block length sets that estimator's
   small bias (below), which must not change with the run length. */
static int temperature_profile(double dt, int noise_beta, hcbd_pair_integrator integ, double time,
                               double len, double *dev, double *dev_err, double *Tc,
                               double *Tc_err, double *dep)
{
    hcbd_world_def d = channel();
    hcbd_world w;
    hcbd_profile pr;
    double mem[26 * 15], out[26 * 8], tc = 0, tce = 0, mc = 0;
    int k, s, nc = 0, ncen = 0, block = (int)(time / dt) / 200, nblk = (int)(20 * len + 0.5);
    d.params.dt = dt;
    d.params.pair_integrator = integ;
    /* the slab temperature is the background's: its bias is the pair
       step's, measured here with the displacement the papers use */
    d.params.brownian = HCBD_BROWNIAN_EULER;
    d.params.wall.noise_beta = noise_beta;
    if (!make_world(&w, &d)) return 0;
    hcbd_world_place_lattice(&w, 406);
    if (!run(&w, (int)(0.5 / dt))) return 0;
    hcbd_profile_init(&pr, &w, 26, block, mem, sizeof mem);
    for (k = 0; k < block * nblk; ++k) {
        if (!run(&w, 10)) return 0;
        hcbd_profile_sample(&pr, &w);
    }
    hcbd_profile_result(&pr, out);
    for (s = 0; s < 26; ++s) {
        if (fabs(out[8 * s] - 6.5) < 1.5) { /* the central fifth of the channel */
            tc += out[8 * s + 5] / 6.0;
            tce += pow(out[8 * s + 6] / 6.0, 2);
            ++ncen;
        }
        if (out[8 * s + 7] > 0) { mc += out[8 * s + 7]; ++nc; }
    }
    mc /= nc;
    if (ncen != 6) { printf("    %d central slabs, want 6\n", ncen); t_fail = 1; }
    *dev = 0;
    *dev_err = 0;
    for (s = 0; s < 26; ++s)
        if (out[8 * s + 7] >= 0.2 * mc && fabs(out[8 * s + 5] / tc - 1) > fabs(*dev)) {
            *dev = out[8 * s + 5] / tc - 1;
            *dev_err = sqrt(pow(out[8 * s + 6], 2) + tce) / tc;
        }
    *dep = 0; /* excluded width per wall; slab edges fall on the interfaces */
    for (s = 0; s < 26; ++s) {
        double nb = 0;
        for (k = 10; k < 16; ++k) nb += out[8 * k + 1] / 6.0;
        if (out[8 * s] > 1.5 && out[8 * s] < 11.5) *dep += 0.25 * (1 - out[8 * s + 1] / nb);
    }
    *Tc = tc / d.params.kT;
    *Tc_err = sqrt(tce) / d.params.kT;
    hcbd_world_destroy(&w);
    return 1;
}

/* Flat temperature with the sqrt(beta) noise, cooling at the walls without
   it; the central temperature's Euler bias, about (dt/2 tau) <sum_j f_ij>
   (MODEL 10), halves with dt.  In the same equilibrium runs, the Gaussian
   walls deplete ideal particles by the Boltzmann factor. */
void test_wall_temperature_profile(void)
{
    double dev, de, T1, T1e, T2, T2e, devn, den, Tn, Tne, time = t_quick ? 1.0 : 4.0, dep, dep2;
    /* runs of len x time, blocks of time / 20.  The two runs whose largest
       slab deviation must stay under a fixed 3 % (the maximum over ~20
       slabs, each with an error of 0.6-0.8 % at full length) run at least
       0.7 of it: at 0.4 that error reaches 0.7-1.4 % and 3 % is only ~3
       of them for the largest of 20 (one run came within 0.64 of them). */
    double len = t_quick ? 1.0 : t_len, flat = t_quick ? 1.0 : fmax(t_len, 0.7);
    hcbd_theory th;
    hcbd_params p = channel().params;
    hcbd_params_theory(&p, &th);
    if (!temperature_profile(2e-4, 1, HCBD_PAIR_EULER, time, flat, &dev, &de, &T1, &T1e, &dep))
        return;
    NOTE("dt = 2e-4: largest slab deviation %.4f +- %.4f, T_centre = %.4f +- %.4f, excluded "
         "width %.4f (Boltzmann %.4f)", dev, de, T1, T1e, dep, th.depletion_width);
    CHECK(fabs(dev) < 0.03, "a slab's temperature deviates by %.4f +- %.4f", dev, de);
    if (!temperature_profile(2e-4, 0, HCBD_PAIR_EULER, time, len, &devn, &den, &Tn, &Tne, &dep2))
        return;
    NOTE("without sqrt(beta): largest deviation %.4f +- %.4f", devn, den);
    CHECK(devn < -0.03 && devn + 3 * den < -0.03,
          "without sqrt(beta) the wall slabs should cool by more than 3 %%: %.4f +- %.4f", devn, den);
    if (t_quick) return;
    if (!temperature_profile(1e-4, 1, HCBD_PAIR_EULER, time, flat, &dev, &de, &T2, &T2e, &dep2))
        return;
    NOTE("dt = 1e-4: largest slab deviation %.4f +- %.4f, T_centre = %.4f +- %.4f, excluded "
         "width %.4f", dev, de, T2, T2e, dep2);
    CHECK(fabs(0.5 * (dep + dep2) / th.depletion_width - 1) < 0.1,
          "Gaussian walls: excluded width %.4f, %.4f vs Boltzmann %.4f", dep, dep2, th.depletion_width);
    CHECK(fabs(dev) < 0.03, "a slab's temperature deviates by %.4f +- %.4f", dev, de);
    /* bias(dt) = b dt: T1 - 1 = 2 (T2 - 1) */
    CHECK(fabs((T1 - 1) - 2 * (T2 - 1)) < 3 * sqrt(T1e * T1e + 4 * T2e * T2e),
          "Euler bias %.4f at dt and %.4f at dt/2 are not in ratio 2", T1 - 1, T2 - 1);
    CHECK(T1 - 1 > 3 * T1e, "no resolved bias at dt = 2e-4 (%.4f +- %.4f)", T1 - 1, T1e);
    /* The exact pair and wall sweep at dt = 2e-4 gives Euler's dt -> 0
       limit 2 T(dt/2) - T(dt) (the slab estimator, about each block's slab
       mean, reads about 1 % low in both), and a flat profile. */
    {
        double Ts, Tse, T0 = 2 * T2 - T1, T0e = sqrt(4 * T2e * T2e + T1e * T1e);
        if (!temperature_profile(2e-4, 1, HCBD_PAIR_SHARDLOW, time, len, &dev, &de, &Ts, &Tse, &dep2))
            return;
        NOTE("Shardlow, dt = 2e-4: largest slab deviation %.4f +- %.4f, T_centre = %.4f +- %.4f "
             "(Euler extrapolated to dt = 0: %.4f +- %.4f)", dev, de, Ts, Tse, T0, T0e);
        CHECK(fabs(Ts - T0) < 4 * sqrt(Tse * Tse + T0e * T0e), "Shardlow: central temperature %.4f +- "
              "%.4f, Euler's limit %.4f +- %.4f", Ts, Tse, T0, T0e);
        CHECK(fabs(dev) < 4 * de, "Shardlow: a slab's temperature deviates by %.4f +- %.4f", dev, de);
    }
}

/* Walls at rest, no body force: with kT = 0 the background momentum of a
   uniform flow never grows and falls to zero; with noise it decays to the
   level of equilibrium fluctuations. */
void test_wall_momentum_decay(void)
{
    hcbd_world_def d = channel();
    hcbd_world w;
    double v[3 * 406], p[3], prev = HUGE_VAL, p0;
    int i, b, grew = 0;
    d.params.kT = 0;
    if (!make_world(&w, &d)) return;
    hcbd_world_place_lattice(&w, 406);
    for (i = 0; i < 406; ++i) { v[3 * i] = 1.0; v[3 * i + 1] = 0.3; v[3 * i + 2] = -0.2; }
    hcbd_world_set_velocities(&w, v);
    hcbd_world_momentum(&w, p);
    p0 = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (b = 0; b < 200; ++b) {
        double a;
        if (!run(&w, 50)) return;
        hcbd_world_momentum(&w, p);
        a = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        if (a > prev * (1 + 1e-12)) ++grew;
        prev = a;
    }
    CHECK(grew == 0, "|P| grew in %d of 200 blocks without noise", grew);
    CHECK(prev < 0.05 * p0, "|P| fell only from %g to %g in 1 time unit", p0, prev);
    hcbd_world_destroy(&w);
}

/* The body force on particles and background, or on the background only,
   give the same mean flow velocity within the block errors of its time
   series (2016).  Profiles are not compared slab by slab: the velocity
   profile fluctuates as a whole, and density differences across the
   channel relax diffusively in W^2/(pi^2 D) ~ 6 time units, the length of
   the full run, so slab-wise block errors would be far too small.  The
   full run is 20 blocks of 0.3 time units (twice the slowest decay of the
   flow, W^2/(pi^2 nu) ~ 0.13); a shorter one keeps the blocks and runs
   round(20 t_len) of them. */
void test_wall_body_force_variants(void)
{
    double vm[2], ve[2];
    static double vs[3000];
    int v, k, nb = t_quick ? 20 : (int)(20 * t_len + 0.5), steps = t_quick ? 4000 : 1500 * nb;
    int ns = steps / 10;
    for (v = 0; v < 2; ++v) {
        hcbd_world_def d = channel();
        hcbd_world w;
        double p[3];
        d.params.tau = 2e-3;
        d.params.xip = 1.5;
        d.params.dt = 2e-4;
        d.params.fext[0] = 50.0 * d.params.xip * d.params.tau; /* g = 50 */
        d.params.fext_background_only = v;
        d.params.seed = 7 + v;
        if (!make_world(&w, &d)) return;
        hcbd_world_place_lattice(&w, 406);
        if (!run(&w, 5000)) return; /* 1 time unit ~ W^2/nu */
        for (k = 0; k < ns; ++k) {
            if (!run(&w, 10)) return;
            hcbd_world_momentum(&w, p);
            vs[k] = p[0] / (w.n * w.m);
        }
        block_stats(vs, ns, nb, &vm[v], &ve[v]);
        hcbd_world_destroy(&w);
    }
    NOTE("mean flow velocity %.3f +- %.3f (both) vs %.3f +- %.3f (background only)", vm[0], ve[0],
         vm[1], ve[1]);
    if (t_quick) return; /* blocks shorter than the flow's correlation time */
    CHECK(fabs(vm[0] - vm[1]) < 3.5 * sqrt(ve[0] * ve[0] + ve[1] * ve[1]) && vm[0] > 10 * ve[0],
          "mean flow velocities differ: %.3f +- %.3f vs %.3f +- %.3f", vm[0], ve[0], vm[1], ve[1]);
}

/* Same bits for 1 and 2 threads, with sorting on and off, with walls and
   a moving wall; each wall mode. */
void test_wall_determinism(void)
{
    int mode;
    for (mode = 0; mode < 3; ++mode) {
        uint64_t c[3];
        int k;
        for (k = 0; k < 3; ++k) {
            hcbd_world_def d = channel();
            hcbd_world w;
            d.params.potential = HCBD_POT_STAR;
            d.params.wall.mode = (hcbd_wall_mode)mode;
            d.params.wall.vx[1] = 3.0;
            d.params.fext[0] = 0.4;
            d.params.threads = k == 1 ? 2 : 1;
            d.params.sort = k != 2;
            if (!make_world(&w, &d)) return;
            hcbd_world_place_lattice(&w, 406);
            if (!run(&w, t_quick ? 100 : 1000)) return;
            c[k] = hcbd_world_checksum(&w);
            hcbd_world_destroy(&w);
        }
        CHECK(c[0] == c[1] && c[0] == c[2], "mode %d: checksums %016llx %016llx %016llx", mode,
              (unsigned long long)c[0], (unsigned long long)c[1], (unsigned long long)c[2]);
    }
}
#endif

#if HCBD_MODEL == HCBD_MODEL_WALLED
/* Channel flow of ideal particles (tau = 2e-3, xi' = 1.5, dt = 2e-4, g =
   200: v_max ~ 30 against thermal velocities ~ 16, Re_max ~ 0.3).  Fits a
   parabola to the slabs at least 1 sigma from the interfaces and returns
   its maximum, the slip ratio (the parabola at the interfaces over the
   maximum) with its error from the fit covariance, and the excluded width
   per wall, integral of 1 - n(y)/n_bulk over the channel. */
typedef struct { double vmax, vmax_err, slip, slip_err, dep, pen, nu, nu_err, n_centre; } chan_result;

#define NSUB 5
/* Weighted least-squares parabola through the slabs between ylo and yhi:
   q = (a, b, c) of v = a + b y + c y^2 and its covariance C. */
static void fit_slabs(const double *out, double ylo, double yhi, double q[3], double C[9])
{
    double A[9] = {0}, r[3] = {0}, det;
    int s, i, j;
    for (s = 0; s < 26; ++s) {
        double y = out[8 * s], b[3] = {1, y, y * y}, wt;
        if (y < ylo || y > yhi) continue;
        wt = 1.0 / (out[8 * s + 4] * out[8 * s + 4]);
        for (i = 0; i < 3; ++i) {
            r[i] += wt * b[i] * out[8 * s + 3];
            for (j = 0; j < 3; ++j) A[3 * i + j] += wt * b[i] * b[j];
        }
    }
    det = A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
          A[2] * (A[3] * A[7] - A[4] * A[6]);
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {
            int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
            C[3 * i + j] = (A[3 * r0 + c0] * A[3 * r1 + c1] - A[3 * r0 + c1] * A[3 * r1 + c0]) / det;
        }
    for (i = 0; i < 3; ++i) q[i] = C[3 * i] * r[0] + C[3 * i + 1] * r[1] + C[3 * i + 2] * r[2];
}

/* A run of len x time after the equilibration; the profile's blocks are
   those of the full run (time / 20), so a shorter run has fewer of them. */
static int channel_run(hcbd_wall_mode mode, double beta_max, double time, double len,
                       chan_result *cr)
{
    hcbd_world_def d = channel();
    hcbd_world w;
    hcbd_profile pr, sub[NSUB];
    static double mem[NSUB + 1][26 * 15];
    double out[26 * 8], C[9], q[3], nb = 0, g[3], nus[NSUB];
    const double grav = 200.0;
    int k, s, i, j, ncen = 0, steps, block;
    d.params.tau = 2e-3;
    d.params.xip = 1.5;
    d.params.dt = 2e-4;
    d.params.fext[0] = grav * d.params.xip * d.params.tau;
    d.params.wall.mode = mode;
    d.params.wall.beta_max = beta_max;
    block = (int)(time / d.params.dt) / (10 * NSUB) * (10 * NSUB) / 200;
    steps = (int)(time * len / d.params.dt) / (10 * NSUB) * (10 * NSUB);
    if (!make_world(&w, &d)) return 0;
    hcbd_world_place_lattice(&w, 406);
    if (!run(&w, (int)(1.0 / d.params.dt))) return 0; /* ~10 W^2/nu */
    hcbd_profile_init(&pr, &w, 26, block, mem[NSUB], sizeof mem[NSUB]);
    for (k = 0; k < NSUB; ++k) hcbd_profile_init(&sub[k], &w, 26, steps / (10 * NSUB) / 8, mem[k], sizeof mem[k]);
    for (k = 0; k < steps / 10; ++k) {
        if (!run(&w, 10)) return 0;
        hcbd_profile_sample(&pr, &w);
        hcbd_profile_sample(&sub[k / (steps / (10 * NSUB))], &w);
    }
    cr->pen = (double)hcbd_world_wall_penetrations(&w, NULL, NULL);
    hcbd_world_destroy(&w);
    /* the curvature gives the kinematic viscosity, v'' = -g/nu, whatever
       the walls do; its error from NSUB independent stretches of the run */
    for (k = 0; k < NSUB; ++k) {
        hcbd_profile_result(&sub[k], out);
        fit_slabs(out, 2.5, 10.5, q, C);
        nus[k] = -grav / (2 * q[2]);
    }
    block_stats(nus, NSUB, NSUB, &cr->nu, &cr->nu_err);
    hcbd_profile_result(&pr, out);
    for (s = 0; s < 26; ++s)
        if (fabs(out[8 * s] - 6.5) < 1.5) { nb += out[8 * s + 1]; ++ncen; }
    nb /= ncen;
    cr->n_centre = nb;
    fit_slabs(out, 2.5, 10.5, q, C);
    cr->vmax = q[0] - q[1] * q[1] / (4 * q[2]);
    g[0] = 1; g[1] = -q[1] / (2 * q[2]); g[2] = q[1] * q[1] / (4 * q[2] * q[2]);
    cr->vmax_err = 0;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) cr->vmax_err += g[i] * C[3 * i + j] * g[j];
    cr->vmax_err = sqrt(cr->vmax_err);
    /* mean of the parabola at y = 1.5 and 11.5 */
    g[0] = 1; g[1] = 6.5; g[2] = 0.5 * (1.5 * 1.5 + 11.5 * 11.5);
    cr->slip = (g[0] * q[0] + g[1] * q[1] + g[2] * q[2]) / cr->vmax;
    cr->slip_err = 0;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) cr->slip_err += g[i] * C[3 * i + j] * g[j];
    cr->slip_err = sqrt(cr->slip_err) / cr->vmax;
    cr->dep = 0;
    for (s = 0; s < 26; ++s) /* slab edges fall on the interfaces */
        if (out[8 * s] > 1.5 && out[8 * s] < 11.5) cr->dep += 0.5 * (1 - out[8 * s + 1] / nb);
    cr->dep *= 0.5;
    return 1;
}

/* The bulk at the channel's parameters (ideal, n# = 0.24, tau = 2e-3,
   xi' = 1.5, dt = 2e-4), 512 particles in a 12.9^3 box. */
static hcbd_world_def bulk_twin(void)
{
    hcbd_world_def d = hcbd_world_def_default();
    d.params.potential = HCBD_POT_IDEAL;
    d.params.tau = 2e-3;
    d.params.xip = 1.5;
    d.params.dt = 2e-4;
    d.capacity = 512;
    d.params.L[0] = d.params.L[1] = d.params.L[2] = cbrt(512 / 0.24);
    return d;
}

/* Kinematic viscosity from Lees-Edwards: total shear stress (pair,
   background and carriers) / (gdot n m), 10 blocks. */
static int le_nu(double gdot, double time, double *nu, double *err)
{
    hcbd_world_def d = bulk_twin();
    hcbd_world w;
    double eta[10], fl[4];
    int b;
    d.params.gdot = gdot;
    d.params.skin = 1.0; /* streaming particles move fast */
    if (!make_world(&w, &d)) return 0;
    hcbd_world_place_random(&w, 512);
    if (!run(&w, 5000)) return 0;
    for (b = 0; b < 10; ++b) {
        hcbd_world_stress_enable(&w, 1);
        if (!run(&w, (int)(time / 10 / d.params.dt))) return 0;
        hcbd_world_stress_read(&w, fl, NULL);
        eta[b] = fl[3] / gdot / (0.24 * w.m);
    }
    block_stats(eta, 10, 10, nu, err);
    hcbd_world_destroy(&w);
    return 1;
}

/* Kinematic viscosity from the hydrodynamic (late) decay of the transverse
   current at k = 2 pi / L: the slope of ln C_t over the first stretch where
   C_t(t)/C_t(0) falls from 0.6 to 0.1, minus the Brownian kT/xi (MODEL 10);
   all 12 channels (3 axes, 2 polarisations, cos and sin), nb blocks. */
static int transverse_nu(int nb, double block_time, double *nu, double *err)
{
    hcbd_world_def d = bulk_twin();
    hcbd_world w;
    hcbd_mtcorr c;
    static char mem[1 << 20];
    double vals[16], k = 2 * 3.14159265358979323846 / d.params.L[0];
    int b, s, steps = (int)(block_time / d.params.dt);
    if (nb > 16 || hcbd_mtcorr_bytes(12, 32, 2, 12) > sizeof mem) return 0;
    if (!make_world(&w, &d)) return 0;
    hcbd_world_place_random(&w, 512);
    if (!run(&w, 2000)) return 0;
    for (b = 0; b < nb; ++b) {
        double lag[512], cc[512], sx = 0, sy = 0, sxx = 0, sxy = 0;
        int n, q, m = 0;
        hcbd_mtcorr_init(&c, 12, 32, 2, 12, mem, sizeof mem);
        for (s = 0; s < steps; ++s) {
            double o[12];
            hcbd_world_transverse_current(&w, 1, o);
            hcbd_mtcorr_add(&c, o);
            if (!run(&w, 1)) return 0;
        }
        hcbd_mtcorr_finalize(&c);
        n = hcbd_mtcorr_result(&c, 1, lag, cc, NULL, 512);
        for (q = 1; q < n; ++q) {
            double r = cc[q] / cc[0], t = lag[q] * d.params.dt;
            if (r < 0.1) break;
            if (r > 0.6) continue;
            sx += t; sy += log(r); sxx += t * t; sxy += t * log(r); ++m;
        }
        vals[b] = -(m * sxy - sx * sy) / (m * sxx - sx * sx) / (k * k) - d.params.kT / d.params.xi;
    }
    block_stats(vals, nb, nb, nu, err);
    hcbd_world_destroy(&w);
    return 1;
}

/* The paper's Gaussian walls slip (their depletion is tested in
   equilibrium, with the temperature profile: strong flow widens it); the
   no-slip mode (Morris plane at the edge of the depleted layer, beta_max =
   5) does not.  Reflecting walls are reported: the velocity part of the
   carriers' motion is damped next to the wall, so ideal carriers pile up
   there (an Ito drift: density ~ 1 / local diffusivity) and the flow
   sticks slightly (docs/GUIDE.md).
   One transport coefficient, three measurements: the curvature of the
   reflecting channel's profile, the Lees-Edwards stress and the late decay
   of the transverse current give the same kinematic viscosity within
   their errors plus 10 %; each is reported against Rc^2/(28 tau). */
void test_wall_channel_flow(void)
{
    hcbd_params p = channel().params;
    hcbd_theory th;
    chan_result g, ns, rf;
    double time = t_quick ? 1.0 : 6.0, nu_le, nu_le_err, nu_tc, nu_tc_err, nu_mf, a, b, c;
    double len = t_quick ? 1.0 : t_len;
    hcbd_params_theory(&p, &th);
    if (!channel_run(HCBD_WALL_GAUSS, 1.5, 0.5 * time, len, &g)) return; /* a large slip */
    NOTE("gauss:   v_max %.3f +- %.3f, slip %.4f +- %.4f, excluded width %.4f (Boltzmann %.4f)",
         g.vmax, g.vmax_err, g.slip, g.slip_err, g.dep, th.depletion_width);
    /* the no-slip bound |slip| + 2 err < 0.05 needs the full run: its
       error is 0.014-0.016 there and 0.02-0.033 at 0.4, where 2 errors
       alone reach 0.05 */
    if (!channel_run(HCBD_WALL_NOSLIP, 5.0, time, 1.0, &ns)) return;
    NOTE("noslip:  v_max %.3f +- %.3f, slip %.4f +- %.4f, excluded width %.4f, centre density %.4f",
         ns.vmax, ns.vmax_err, ns.slip, ns.slip_err, ns.dep, ns.n_centre);
    if (!channel_run(HCBD_WALL_REFLECT, 1.5, time, len, &rf)) return;
    NOTE("reflect: v_max %.3f +- %.3f, slip %.4f +- %.4f, excluded width %.4f, centre "
         "density %.4f", rf.vmax, rf.vmax_err, rf.slip, rf.slip_err, rf.dep, rf.n_centre);
    CHECK(g.pen == 0 && ns.pen == 0 && rf.pen == 0, "ideal particles entered a wall: %g %g %g",
          g.pen, ns.pen, rf.pen);
    if (t_quick) return;
    CHECK(g.slip > 0.1 && g.slip - 3 * g.slip_err > 0.05, "Gaussian walls should slip: %.4f +- %.4f",
          g.slip, g.slip_err);
    CHECK(fabs(ns.slip) + 2 * ns.slip_err < 0.05, "no-slip mode slips: %.4f +- %.4f", ns.slip,
          ns.slip_err);
    /* The papers' Euler pairs drift with v(t) and pile the carriers up
       where the Morris friction slows them (excluded width -0.48 here);
       the exact sweep kicks before the drift, and the density of ideal
       carriers is flat: a tenth of that pile-up, or of the Gaussian wall's
       depletion (0.56), would show. */
    CHECK(fabs(rf.dep) < 0.05, "reflecting walls change the density of ideal carriers (excluded "
          "width %.4f)", rf.dep);

    if (!le_nu(4.0, 8.0 * len, &nu_le, &nu_le_err)) return;
    /* blocks of 1.5 len: still 4.5 times the decay to C_t(t)/C_t(0) = 0.1 at
       0.4 (t ~ ln 10 / ((nu + kT/xi) k^2) = 0.13) */
    if (!transverse_nu(8, 1.5 * len, &nu_tc, &nu_tc_err)) return;
    nu_mf = 2.5 * 2.5 / (28 * 2e-3);
    NOTE("kinematic viscosity / (Rc^2/28 tau = %.1f): channel curvature %.3f +- %.3f (no-slip "
         "mode %.3f +- %.3f), Lees-Edwards %.3f +- %.3f, transverse current %.3f +- %.3f", nu_mf,
         rf.nu / nu_mf, rf.nu_err / nu_mf, ns.nu / nu_mf, ns.nu_err / nu_mf, nu_le / nu_mf,
         nu_le_err / nu_mf, nu_tc / nu_mf, nu_tc_err / nu_mf);
    a = fabs(rf.nu - nu_le) - 2 * sqrt(rf.nu_err * rf.nu_err + nu_le_err * nu_le_err);
    b = fabs(rf.nu - nu_tc) - 2 * sqrt(rf.nu_err * rf.nu_err + nu_tc_err * nu_tc_err);
    c = fabs(nu_le - nu_tc) - 2 * sqrt(nu_le_err * nu_le_err + nu_tc_err * nu_tc_err);
    CHECK(a < 0.1 * nu_le && b < 0.1 * nu_le && c < 0.1 * nu_le,
          "channel %.2f +- %.2f, Lees-Edwards %.2f +- %.2f, transverse %.2f +- %.2f disagree", rf.nu,
          rf.nu_err, nu_le, nu_le_err, nu_tc, nu_tc_err);
    /* all three sit well below mean field: the sparse friction network */
    CHECK(nu_le < 0.85 * nu_mf && nu_le > 0.5 * nu_mf, "Lees-Edwards nu %.2f vs mean field %.2f",
          nu_le, nu_mf);
}
#endif

#if HCBD_MODEL == HCBD_MODEL_WALLED
/* Real particles found inside a wall are counted exactly (an independent
   scan after every step, with a wall weak enough to be crossed); in the
   paper's star-polymer channel under flow none gets deeper than 0.1 sigma
   past the interface, where the repulsion exceeds 20 kT. */
void test_wall_penetration(void)
{
    int pass;
    for (pass = 0; pass < 2; ++pass) {
        hcbd_world_def d = channel();
        hcbd_world w;
        int64_t count = 0, last_step = -1, got_step;
        int s, i, got_id, last_id = -1;
        int steps = pass ? (t_quick ? 2000 : (int)(30000 * t_len)) : 500;
        double deepest = 0;
        if (pass == 0) d.params.wall.a = 3.0; /* 3 kT plane, ideal particles */
        else {
            d.params.potential = HCBD_POT_STAR;
            d.params.fext[0] = 133.4 * d.params.xip * d.params.tau;
        }
        if (!make_world(&w, &d)) return;
        hcbd_world_place_lattice(&w, 406);
        for (s = 0; s < steps; ++s) {
            int first = INT32_MAX;
            if (!run(&w, 1)) return;
            for (i = 0; i < w.n; ++i) {
                double y = w.y[i], depth = fmax(1.5 - y, y - 11.5);
                if (depth > 0) {
                    ++count;
                    if (w.id[i] < first) first = w.id[i];
                }
                deepest = fmax(deepest, depth);
            }
            if (first != INT32_MAX) { last_step = w.step - 1; last_id = first; }
        }
        CHECK(hcbd_world_wall_penetrations(&w, &got_step, &got_id) == count && got_step == last_step &&
              got_id == last_id, "pass %d: counter %lld (last step %lld id %d), scan %lld (%lld, %d)",
              pass, (long long)hcbd_world_wall_penetrations(&w, NULL, NULL), (long long)got_step, got_id,
              (long long)count, (long long)last_step, last_id);
        if (pass == 0) CHECK(count > 100, "the weak wall was crossed only %lld times", (long long)count);
        else {
            NOTE("stars under flow: %lld particle-steps past an interface in %d steps, deepest %.4f sigma",
                 (long long)count, steps, deepest);
            CHECK(deepest < 0.1, "a star got %.4f sigma into a wall", deepest);
        }
        hcbd_world_destroy(&w);
    }
}
#endif
