/* The run-time guards: a step too long for the forces, a neighbour list
   beyond its capacity and hcbd_params_stability's limits against real runs each
   end in a result code naming what was crossed, never a crash.  (Bad
   inputs: test_badinput.c.) */
#include "test.h"

/* A step too large for the forces is caught and names the particle. */
void test_unstable_step_detected(void)
{
    hcbd_world_def d = scene(64, 0.24);
    hcbd_world w;
    double xyz[3 * 64];
    hcbd_result r;
    d.params.dynamics = HCBD_DYN_BD;
    d.params.kT = 0; /* only the overlapping pair moves */
    d.params.dt = 1e-2;
    if (!make_world(&w, &d)) return;
    hcbd_world_place_lattice(&w, 64);
    hcbd_world_get_positions(&w, xyz, 0);
    xyz[3 * 7] = xyz[3 * 3] + 0.01; /* particle 7 almost on top of 3 */
    xyz[3 * 7 + 1] = xyz[3 * 3 + 1];
    xyz[3 * 7 + 2] = xyz[3 * 3 + 2];
    hcbd_world_set_positions(&w, 64, xyz);
    r = hcbd_world_step(&w, 10);
    CHECK(r == HCBD_ERR_UNSTABLE && (w.err.id == 3 || w.err.id == 7) && w.err.step == 0,
          "got %s id %lld: %s", hcbd_result_name(r), (long long)w.err.id, w.err.msg);
    hcbd_world_destroy(&w);
}

void test_neighbour_capacity_overflow(void)
{
    hcbd_world_def d = scene(512, 0.24);
    hcbd_world w;
    hcbd_result r;
    d.max_pairs = 1000;
    if (!make_world(&w, &d)) return;
    hcbd_world_place_lattice(&w, 512);
    r = hcbd_world_step(&w, 1);
    CHECK(r == HCBD_ERR_CAPACITY && strstr(w.err.msg, "max_pairs"), "%s", w.err.msg);
    hcbd_world_destroy(&w);
}

/* hcbd_params_stability's force limit (2 xi / k at the star core) against real
   runs of the star liquid: half of it runs, four times it is stopped by a
   guard with a result code, not a crash.  Its text marks a crossed limit. */
void test_stability_limits(void)
{
    hcbd_limit l[HCBD_MAX_LIMITS];
    int n = 0, k, force = -1;
    double f;
    char buf[2048];
    hcbd_world_def d = hcbd_world_def_default();
    d.params.pair_integrator = HCBD_PAIR_EULER; /* the papers' scheme has the most limits */
    CHECK(hcbd_params_stability(&d.params, l, &n) == HCBD_OK && n >= 5, "%d limits", n);
    for (k = 0; k < n; ++k) {
        CHECK(l[k].margin > 1, "default scene crosses '%s' (margin %g)", l[k].name, l[k].margin);
        if (strstr(l[k].name, "2 xi / k")) force = k;
    }
    if (force < 0) { CHECK(0, "no force limit"); return; }
    for (f = 0.5; f < 5; f *= 8) {
        hcbd_world w;
        hcbd_result r;
        d = hcbd_world_def_default();
        d.params.dt = f * l[force].bound;
        d.params.tau = 36 * d.params.dt;
        if (!make_world(&w, &d)) return;
        hcbd_world_place_lattice(&w, 512);
        r = hcbd_world_step(&w, t_quick ? 500 : 2000);
        NOTE("dt = %.2f x force limit: %s at step %lld", f, hcbd_result_name(r), (long long)w.err.step);
        if (f < 1) CHECK(r == HCBD_OK, "half the force limit: %s", w.err.msg);
        else CHECK(r == HCBD_ERR_UNSTABLE || r == HCBD_ERR_NONFINITE, "4x the limit: %s", hcbd_result_name(r));
        hcbd_world_destroy(&w);
    }
    d = hcbd_world_def_default();
    d.params.pair_integrator = HCBD_PAIR_EULER;
    d.params.tau = 5 * d.params.dt;
    hcbd_params_stability(&d.params, l, &n);
    hcbd_limits_format(l, n, buf, sizeof buf);
    CHECK(strstr(buf, "tau >= 10 dt") && strstr(buf, "CROSSED"), "tau = 5 dt not flagged:\n%s", buf);
    CHECK(hcbd_limits_format(l, n, buf, 10) > 10 && strlen(buf) == 9, "truncation");
    CHECK(hcbd_params_stability(NULL, l, &n) == HCBD_ERR_NULL, "NULL params");
    d.params.dt = -1;
    CHECK(hcbd_params_stability(&d.params, l, &n) == HCBD_ERR_PARAM, "bad params");
}
