/* Neighbour search against brute-force pair enumeration. */
#include "test.h"

/* Every pair within the cut-off appears exactly once in the half list (the
   owner has the lower id), and no pair beyond the list range does. */
static void compare(hcbd_world *w, const char *what)
{
    int n = w->n, i, j, missing = 0, dup = 0, wrong_owner = 0, found = 0, too_far = 0;
    unsigned char *seen = (unsigned char *)calloc((size_t)n * n, 1);
    for (i = 0; i < n; ++i) {
        int32_t p;
        for (p = w->nl.nb_start[i]; p < w->nl.nb_start[i + 1]; ++p) {
            int a = w->id[i], b = w->id[w->nl.nb_j[p]], c;
            double d2 = 0;
            if (a >= b) ++wrong_owner;
            for (c = 0; c < 3; ++c) {
                double r0 = c == 0 ? w->x[i] : c == 1 ? w->y[i] : w->z[i];
                double r1 = c == 0 ? w->x[w->nl.nb_j[p]] : c == 1 ? w->y[w->nl.nb_j[p]] : w->z[w->nl.nb_j[p]];
                double dx = r0 - r1;
                dx -= w->p.L[c] * round(dx / w->p.L[c]);
                d2 += dx * dx;
            }
            if (d2 >= w->nl.rlist * w->nl.rlist) ++too_far;
            if (seen[(size_t)a * n + b]++) ++dup;
        }
    }
    for (i = 0; i < n; ++i)
        for (j = i + 1; j < n; ++j) {
            double d2 = 0, r[2][3];
            int c;
            int si = w->slot[i], sj = w->slot[j];
            r[0][0] = w->x[si]; r[0][1] = w->y[si]; r[0][2] = w->z[si];
            r[1][0] = w->x[sj]; r[1][1] = w->y[sj]; r[1][2] = w->z[sj];
            for (c = 0; c < 3; ++c) {
                double dx = r[0][c] - r[1][c], L = w->p.L[c];
                dx -= L * round(dx / L);
                d2 += dx * dx;
            }
            if (d2 < w->cutmax * w->cutmax) {
                ++found;
                if (!seen[(size_t)i * n + j]) ++missing;
            }
        }
    CHECK(missing == 0 && dup == 0 && wrong_owner == 0 && too_far == 0,
          "%s: %d of %d pairs missing, %d duplicated, %d wrong owner, %d beyond the list range",
          what, missing, found, dup, wrong_owner, too_far);
    /* partners in increasing id (the exact pair sweep's order) */
    {
        int bad = 0;
        for (i = 0; i < n; ++i) {
            int32_t p;
            for (p = w->nl.nb_start[i] + 1; p < w->nl.nb_start[i + 1]; ++p)
                if (w->id[w->nl.nb_j[p]] <= w->id[w->nl.nb_j[p - 1]]) ++bad;
        }
        CHECK(bad == 0, "%s: %d partners out of id order", what, bad);
    }
    free(seen);
}

/* Observables that need the list build it when it is stale. */
static void build(hcbd_world *w)
{
    double out[9];
    hcbd_result r = w->gibd ? hcbd_world_friction_average(w, 1, out) : hcbd_world_virial_stress(w, out);
    CHECK(r == HCBD_OK, "%s", w->err.msg);
}

void test_neighbour_list_vs_brute_force(void)
{
    /* box edges giving 4, 3, 2 cells per axis, and non-cubic boxes */
    double boxes[4][3] = {{12.9, 12.9, 12.9}, {9.0, 9.5, 10.0}, {6.0, 8.8, 14.0}, {5.8, 5.8, 5.8}};
    int b, dyn;
    for (b = 0; b < 4; ++b)
        for (dyn = 0; dyn < 2; ++dyn) {
            hcbd_world_def d = scene(400, 0.24);
            hcbd_world w;
            char what[64];
            memcpy(d.params.L, boxes[b], sizeof boxes[b]);
            int n = (int)(0.3 * boxes[b][0] * boxes[b][1] * boxes[b][2]);
            /* GI-BD of ideal particles (list range Rc) can run from random
               positions; BD of stars (range rcut) is only listed */
            d.params.dynamics = dyn ? HCBD_DYN_BD : HCBD_DYN_GIBD;
            d.params.potential = dyn ? HCBD_POT_STAR : HCBD_POT_IDEAL;
            d.params.seed = 11 + b;
            if (!make_world(&w, &d)) return;
            hcbd_world_place_random(&w, n < 400 ? n : 400);
            snprintf(what, sizeof what, "box %d dyn %d", b, dyn);
            build(&w);
            compare(&w, what);
            /* after particles moved and the list was rebuilt */
            if (!dyn) {
                run(&w, 50);
                w.nl.disp_max = 1e9; /* force a rebuild at the present positions */
                build(&w);
                compare(&w, what);
            }
            hcbd_world_destroy(&w);
        }
}

/* With two threads each lists its share of particles into half of the
   spare space; when one half overflows although the total fits, the
   second-scan fallback must give the same list and the same bits. */
void test_neighbour_slice_overflow(void)
{
    hcbd_world_def d = scene(400, 0.24);
    hcbd_world w, v;
    uint64_t h1, h2;
    int needed;
    d.params.potential = HCBD_POT_IDEAL;
    d.params.threads = 2;
    if (!make_world(&w, &d)) return;
    hcbd_world_place_random(&w, 400);
    build(&w);
    needed = (int)w.nl.npairs;
    run(&w, 1);
    h1 = hcbd_world_checksum(&w);
    /* exactly enough in total: unless the two shares are equal, one
       thread's half is too small */
    d.max_pairs = needed;
    if (!make_world(&v, &d)) return;
    hcbd_world_place_random(&v, 400);
    build(&v);
    compare(&v, "slice overflow");
    run(&v, 1);
    h2 = hcbd_world_checksum(&v);
#ifdef _OPENMP
    CHECK(v.nl.n_rescans == 1, "the fallback did not run (%lld rescans)", (long long)v.nl.n_rescans);
#endif
    CHECK(h1 == h2, "fallback changed the trajectory");
    hcbd_world_destroy(&w);
    hcbd_world_destroy(&v);
}

void test_box_too_small(void)
{
    hcbd_world_def d = scene(100, 0.24);
    hcbd_world w;
    hcbd_result r;
    d.params.L[1] = 5.7; /* 2 (2.5 + 0.4) = 5.8 */
    d.params.skin = 0.4;
    r = hcbd_world_create(&w, &d);
    CHECK(r == HCBD_ERR_BOX, "got %s", hcbd_result_name(r));
    CHECK(strstr(w.err.msg, "L[1]") != NULL, "message: %s", w.err.msg);
    /* the automatic skin shrinks to what the box holds, down to 0 */
    d.params.skin = HCBD_AUTO;
    r = hcbd_world_create(&w, &d);
    CHECK(r == HCBD_OK && w.core.skin > 0.34 && w.core.skin < 0.35, "auto skin in L = 5.7: %s, skin %g",
          hcbd_result_name(r), r == HCBD_OK ? w.core.skin : -1.0);
    if (r == HCBD_OK) hcbd_world_destroy(&w);
    d.params.L[1] = 4.99;
    r = hcbd_world_create(&w, &d);
    CHECK(r == HCBD_ERR_BOX, "L = 4.99 < 2 Rc with the automatic skin: %s", hcbd_result_name(r));
    /* ideal BD needs no pairs, so any box is fine */
    d.params.dynamics = HCBD_DYN_BD;
    d.params.potential = HCBD_POT_IDEAL;
    r = hcbd_world_create(&w, &d);
    CHECK(r == HCBD_OK, "ideal BD in a small box: %s", w.err.msg);
    hcbd_world_destroy(&w);
}
