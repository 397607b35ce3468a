/* Bad inputs are rejected with a result code and a message naming the
   value; nothing is changed. */
#include "test.h"

/* The message must name the field followed by its value ("xi =" is not
   satisfied by "xip = ..."), or, for a NULL pointer, the field itself. */
static void expect(hcbd_world_def d, hcbd_result code, const char *name)
{
    hcbd_world w;
    char key[64];
    hcbd_result r = hcbd_world_create(&w, &d);
    snprintf(key, sizeof key, code == HCBD_ERR_NULL ? "%s " : "%s = ", name);
    CHECK(r == code, "%s: got %s (%s)", name, hcbd_result_name(r), w.err.msg);
    CHECK(strstr(w.err.msg, key) != NULL, "message does not name %s: %s", name, w.err.msg);
    if (r == HCBD_OK) hcbd_world_destroy(&w);
}

void test_bad_parameters(void)
{
    hcbd_world_def d = scene(64, 0.24), e;
    d.params.L[0] = d.params.L[1] = d.params.L[2] = 12.9;
    e = d; e.params.dt = 0; expect(e, HCBD_ERR_PARAM, "dt");
    e = d; e.params.dt = -1e-4; expect(e, HCBD_ERR_PARAM, "dt");
    e = d; e.params.dt = NAN; expect(e, HCBD_ERR_PARAM, "dt");
    /* the explicit pair friction overshoots for tau < dt */
    e = d; e.params.pair_integrator = HCBD_PAIR_EULER; e.params.tau = 0.5e-4; expect(e, HCBD_ERR_PARAM, "tau");
    e = d; e.params.Rc = 0; expect(e, HCBD_ERR_PARAM, "Rc");
    e = d; e.params.Rc = -1; expect(e, HCBD_ERR_PARAM, "Rc");
    e = d; e.params.kT = -1; expect(e, HCBD_ERR_PARAM, "kT");
    e = d; e.params.xi = INFINITY; expect(e, HCBD_ERR_PARAM, "xi");
    e = d; e.params.xip = 0; expect(e, HCBD_ERR_PARAM, "xip");
    e = d; e.params.density_norm = 2015; expect(e, HCBD_ERR_PARAM, "density_norm");
    e = d; e.params.threads = 0; expect(e, HCBD_ERR_PARAM, "threads");
    e = d; e.params.fext[2] = NAN; expect(e, HCBD_ERR_PARAM, "fext[2]");
    /* classical BD has no background for the force to drive: once the
       force was silently dropped */
    e = d; e.params.dynamics = HCBD_DYN_BD; e.params.fext[0] = 1.0; e.params.fext_background_only = 1;
    expect(e, HCBD_ERR_PARAM, "fext_background_only");
    e = d; e.params.L[2] = 4.9; expect(e, HCBD_ERR_BOX, "L[2]");
    e = d; e.capacity = 0; expect(e, HCBD_ERR_PARAM, "capacity");
    e = d; e.params.potential = HCBD_POT_TABLE; expect(e, HCBD_ERR_NULL, "table_F");
}

void test_bad_particles(void)
{
    hcbd_world_def d = scene(64, 0.24);
    hcbd_world w;
    double xyz[3 * 65];
    int k;
    hcbd_result r;
    uint64_t before;
    if (!make_world(&w, &d)) return;
    hcbd_world_place_lattice(&w, 64);
    before = hcbd_state_checksum(&w);
    for (k = 0; k < 3 * 65; ++k) xyz[k] = 0.1 * k;
    r = hcbd_world_set_positions(&w, 65, xyz);
    CHECK(r == HCBD_ERR_CAPACITY && strstr(w.err.msg, "65"), "N above capacity: %s", w.err.msg);
    xyz[3 * 5 + 1] = NAN;
    r = hcbd_world_set_positions(&w, 64, xyz);
    CHECK(r == HCBD_ERR_NONFINITE && strstr(w.err.msg, "particle 5") && w.err.id == 5,
          "non-finite position: %s", w.err.msg);
    CHECK(hcbd_state_checksum(&w) == before, "state changed by rejected input");
    r = hcbd_step(&w, -1);
    CHECK(r == HCBD_ERR_PARAM && strstr(w.err.msg, "nsteps"), "negative nsteps: %s", w.err.msg);
    {
        size_t need = hcbd_world_bytes(&d);
        char *mem = (char *)malloc(need);
        hcbd_world v;
        r = hcbd_world_init(&v, &d, mem, need - 100);
        CHECK(r == HCBD_ERR_MEMORY, "short block: %s", hcbd_result_name(r));
        r = hcbd_world_init(&v, &d, mem, need);
        CHECK(r == HCBD_OK, "caller's block: %s", v.err.msg);
        free(mem);
    }
    hcbd_world_destroy(&w);
}

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
    hcbd_get_positions(&w, xyz, 0);
    xyz[3 * 7] = xyz[3 * 3] + 0.01; /* particle 7 almost on top of 3 */
    xyz[3 * 7 + 1] = xyz[3 * 3 + 1];
    xyz[3 * 7 + 2] = xyz[3 * 3 + 2];
    hcbd_world_set_positions(&w, 64, xyz);
    r = hcbd_step(&w, 10);
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
    r = hcbd_step(&w, 1);
    CHECK(r == HCBD_ERR_CAPACITY && strstr(w.err.msg, "max_pairs"), "%s", w.err.msg);
    hcbd_world_destroy(&w);
}

/* hcbd_stability's force limit (2 xi / k at the star core) against real
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
    CHECK(hcbd_stability(&d.params, l, &n) == HCBD_OK && n >= 5, "%d limits", n);
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
        r = hcbd_step(&w, t_quick ? 500 : 2000);
        NOTE("dt = %.2f x force limit: %s at step %lld", f, hcbd_result_name(r), (long long)w.err.step);
        if (f < 1) CHECK(r == HCBD_OK, "half the force limit: %s", w.err.msg);
        else CHECK(r == HCBD_ERR_UNSTABLE || r == HCBD_ERR_NONFINITE, "4x the limit: %s", hcbd_result_name(r));
        hcbd_world_destroy(&w);
    }
    d = hcbd_world_def_default();
    d.params.pair_integrator = HCBD_PAIR_EULER;
    d.params.tau = 5 * d.params.dt;
    hcbd_stability(&d.params, l, &n);
    hcbd_limits_format(l, n, buf, sizeof buf);
    CHECK(strstr(buf, "tau >= 10 dt") && strstr(buf, "CROSSED"), "tau = 5 dt not flagged:\n%s", buf);
    CHECK(hcbd_limits_format(l, n, buf, 10) > 10 && strlen(buf) == 9, "truncation");
    CHECK(hcbd_stability(NULL, l, &n) == HCBD_ERR_NULL, "NULL params");
    d.params.dt = -1;
    CHECK(hcbd_stability(&d.params, l, &n) == HCBD_ERR_PARAM, "bad params");
}
