/* The 2018 world's fast paths against its general passes (the GI-BD
   world's: test_fast_paths_stress_bits).  The Euler fluid kick takes a
   loop compiled without noise, or without stress, where the scene has
   none; the other passes test their switches inside one loop, and the
   options still change which passes run (the sweep or the kick, the
   coupling's weights, the sub-steps).  The world's core.general sends
   every pass through its general form,
   which the absolute tests hold to the equations.  For every combination
   of the options that switch a path (shear, stress, fluctuations,
   coupling weights, pair scheme, sub-steps) a world with its fast paths
   and one with the general passes must end in the same bits, and so must
   a general world with the stress switched the other way (the stress
   never moves a particle).  A path served to the wrong combination
   changes the bits. */
#include "test.h"

#if HCBD_MODEL == HCBD_MODEL_HCBD
enum { FH_SHEAR = 1, FH_STRESS = 2, FH_FLUCT = 4, FH_RAW = 8, FH_EULER = 16, FH_SUB = 32 };

static int fp_hc_run(int c, int general, int stress, uint64_t *sum, double st[HCBD_HC_NSTRESS])
{
    hcbd_hc_world_def d = hc_scene(10, 6, 5, 40);
    hcbd_hc_params *p = &d.params;
    hcbd_hc_world w;
    int ok;
    p->seed = 9 + (uint64_t)c;
    p->h = 1.3; /* blocks enough for the sweep's colours */
    if (c & FH_SHEAR) p->gdot = 0.05;
    p->fluctuations = (c & FH_FLUCT) != 0;
    p->coupling = c & FH_RAW ? HCBD_COUPLE_RAW : HCBD_COUPLE_SHEPARD;
    p->pair_integrator = c & FH_EULER ? HCBD_PAIR_EULER : HCBD_PAIR_SHARDLOW;
    if (c & FH_SUB) {
        p->substeps = 2;
        p->dt = 0.04;
    }
    if (hcbd_hc_world_create(&w, &d) != HCBD_OK) {
        CHECK(0, "combination %d: %s", c, w.err.msg);
        return 0;
    }
    w.core.general = general;
    ok = hcbd_hc_world_place_fluid_lattice(&w, d.fluid_capacity) == HCBD_OK &&
         hcbd_hc_world_place_polymers_random(&w, 40) == HCBD_OK &&
         (!stress || hcbd_hc_world_stress_enable(&w, 1) == HCBD_OK) && hcbd_hc_world_step(&w, 30) == HCBD_OK;
    CHECK(ok, "combination %d%s: %s", c, general ? " (general)" : "", w.err.msg);
    *sum = hcbd_hc_world_checksum(&w);
    if (stress) hcbd_hc_world_stress_read(&w, st, NULL);
    hcbd_hc_world_destroy(&w);
    return ok;
}

void test_hc_fast_paths(void)
{
    int c, ran = 0;
    for (c = 0; c < 64; ++c) {
        const int stress = (c & FH_STRESS) != 0;
        uint64_t fast = 0, gen = 0, other = 0;
        double s_fast[HCBD_HC_NSTRESS] = {0}, s_gen[HCBD_HC_NSTRESS] = {0}, s_other[HCBD_HC_NSTRESS];
        if (!fp_hc_run(c, 0, stress, &fast, s_fast) || !fp_hc_run(c, 1, stress, &gen, s_gen) ||
            !fp_hc_run(c, 1, !stress, &other, s_other))
            continue;
        ++ran;
        CHECK(fast == gen, "combination %d (gdot %s, stress %d, fluctuations %d, %s weights, %s pairs, %d sub-steps): "
              "the fast paths end in other bits than the general passes", c, c & FH_SHEAR ? "0.05" : "0", stress,
              (c & FH_FLUCT) != 0, c & FH_RAW ? "raw" : "Shepard", c & FH_EULER ? "Euler" : "exact",
              c & FH_SUB ? 2 : 1);
        CHECK(gen == other, "combination %d: the stress switched %s moves the particles", c, stress ? "off" : "on");
        if (stress)
            CHECK(!memcmp(s_fast, s_gen, sizeof s_fast), "combination %d: the stress split differs", c);
    }
    NOTE("%d combinations the same bits with their fast paths and the general passes", ran);
    CHECK(ran == 64, "only %d of 64 combinations ran", ran);
}
#endif
