/* The C layer of the Python package (python/hcbd): the world behind an
   opaque handle, its parameters set by name with the library's own checks
   and messages, and what ctypes cannot reach easily (a FILE for the XYZ
   frames, the arrays of the world's storage).  It is compiled with
   hcbd_impl.c into each of the package's two shared libraries (make
   python): the walled build (GI-BD, classical BD and walls) and the 2018
   build (HCBD).  Everything else the package calls is the public C API. */
#include "../hcbd.h"
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#if HCBD_MODEL == HCBD_MODEL_HCBD
typedef hcbd_hc_world_def hpy_def;
typedef hcbd_hc_world hpy_world;
#define HPY_DEF_DEFAULT hcbd_hc_world_def_default
#else
typedef hcbd_world_def hpy_def;
typedef hcbd_world hpy_world;
#define HPY_DEF_DEFAULT hcbd_world_def_default
#endif

/* A parameter: its name (the C field's), where it lies in the world's
   definition, its kind ('d' doubles, 'i' int, 'u' uint64, 'I' int64, 'c'
   one of the choices, the int value its position in the list), and how
   many values */
typedef struct {
    const char *name;
    size_t off;
    char kind;
    int n;
    const char *choices[4];
} hpy_key;

/* a choice is written as an int into its enum */
typedef char hpy_enum_is_int[sizeof(hcbd_pair_integrator) == sizeof(int) ? 1 : -1];

#define P(f) offsetof(hpy_def, params.f)
#define D(f) offsetof(hpy_def, f)
/* the keys both builds share, each at its own build's offset */
#define HPY_COMMON_KEYS                                                                                      \
    {"max_pairs", D(max_pairs), 'I', 1, {0}}, {"L", P(L), 'd', 3, {0}}, {"dt", P(dt), 'd', 1, {0}},             \
        {"kT", P(kT), 'd', 1, {0}}, {"xi", P(xi), 'd', 1, {0}}, {"sigma", P(sigma), 'd', 1, {0}},               \
        {"gdot", P(gdot), 'd', 1, {0}}, {"pair_integrator", P(pair_integrator), 'c', 1, {"euler", "shardlow", 0}}, \
        {"seed", P(seed), 'u', 1, {0}}, {"threads", P(threads), 'i', 1, {0}},                                 \
        {"guard_every", P(guard_every), 'i', 1, {0}},
static const hpy_key hpy_keys[] = {
    HPY_COMMON_KEYS
#if HCBD_MODEL == HCBD_MODEL_HCBD
    {"fluid_capacity", D(fluid_capacity), 'i', 1, {0}},
    {"polymer_capacity", D(polymer_capacity), 'i', 1, {0}},
    {"pair_capacity", D(pair_capacity), 'i', 1, {0}},
    {"rho", P(rho), 'd', 1, {0}},
    {"nbar", P(nbar), 'd', 1, {0}},
    {"eta", P(eta), 'd', 1, {0}},
    {"P0", P(P0), 'd', 1, {0}},
    {"h", P(h), 'd', 1, {0}},
    {"fluctuations", P(fluctuations), 'i', 1, {0}},
    {"g", P(g), 'd', 3, {0}},
    {"reverse_poiseuille", P(reverse_poiseuille), 'i', 1, {0}},
    {"rc", P(rc), 'd', 1, {0}},
    {"alpha", P(alpha), 'd', 1, {0}},
    {"tau_lambda", P(tau_lambda), 'd', 1, {0}},
    {"p_kuhn", P(p_kuhn), 'd', 1, {0}},
    {"n_max", P(n_max), 'd', 1, {0}},
    {"chi", P(chi), 'd', 1, {0}},
    {"coupling", P(coupling), 'c', 1, {"shepard", "raw", 0}},
    {"substeps", P(substeps), 'i', 1, {0}},
#else
    {"capacity", D(capacity), 'i', 1, {0}},
    {"xip", P(xip), 'd', 1, {0}},
    {"tau", P(tau), 'd', 1, {0}},
    {"Rc", P(Rc), 'd', 1, {0}},
    {"density", P(density), 'd', 1, {0}},
    {"density_norm", P(density_norm), 'i', 1, {0}},
    {"lagged_density", P(lagged_density), 'i', 1, {0}},
    {"dynamics", P(dynamics), 'c', 1, {"gibd", "bd", 0}},
    {"potential", P(potential), 'c', 1, {"ideal", "star", 0}},
    {"noise", P(noise), 'c', 1, {"gauss", "uniform", 0}},
    {"brownian", P(brownian), 'c', 1, {"euler", "lm", 0}},
    {"f", P(f), 'd', 1, {0}},
    {"star_eps", P(star_eps), 'd', 1, {0}},
    {"rcut", P(rcut), 'd', 1, {0}},
    {"force_table", P(force_table), 'i', 1, {0}},
    {"fext", P(fext), 'd', 3, {0}},
    {"fext_background_only", P(fext_background_only), 'i', 1, {0}},
#if HCBD_MODEL == HCBD_MODEL_WALLED
    {"wall_thickness", P(wall.thickness), 'd', 1, {0}},
    {"wall_vx", P(wall.vx), 'd', 2, {0}},
    {"wall_beta_max", P(wall.beta_max), 'd', 1, {0}},
    {"wall_mode", P(wall.mode), 'c', 1, {"gauss", "reflect", "noslip", 0}},
    {"wall_a", P(wall.a), 'd', 1, {0}},
    {"wall_b", P(wall.b), 'd', 1, {0}},
    {"wall_plane", P(wall.plane), 'd', 1, {0}},
    {"wall_shift", P(wall.shift), 'd', 1, {0}},
    {"wall_noise_beta", P(wall.noise_beta), 'i', 1, {0}},
    {"wall_guard", P(wall.guard), 'i', 1, {0}},
#endif
    {"skin", P(skin), 'd', 1, {0}},
    {"sort", P(sort), 'i', 1, {0}},
    {"min_distance", P(min_distance), 'd', 1, {0}},
    {"guard_step", P(guard_step), 'd', 1, {0}},
#endif
};
#undef HPY_COMMON_KEYS
#undef P
#undef D

static int hpy_fail(char *msg, int size, hcbd_result r, const char *text)
{
    if (msg && size > 0) {
        strncpy(msg, text, (size_t)size - 1);
        msg[size - 1] = 0;
    }
    return (int)r;
}

int hpy_model(void) { return HCBD_MODEL; }
int hpy_real_size(void) { return (int)sizeof(hcbd_real); }

/* the definition with the library's defaults */
void *hpy_def_new(void)
{
    hpy_def *d = (hpy_def *)malloc(sizeof *d);
    if (d) *d = HPY_DEF_DEFAULT();
    return d;
}

void hpy_def_free(void *d) { free(d); }

/* the names of the parameters, one by one (NULL past the last) */
const char *hpy_key_name(int k)
{
    return k >= 0 && k < (int)(sizeof hpy_keys / sizeof hpy_keys[0]) ? hpy_keys[k].name : NULL;
}

/* Sets parameter `key` to the n values v (a choice by its name in s).
   Returns 0, or HCBD_ERR_PARAM with a message naming the key: the
   parameters' own checks run when the world is made, with the library's
   messages. */
int hpy_def_set(void *dv, const char *key, const double *v, int n, const char *s, char *msg, int size)
{
    hpy_def *d = (hpy_def *)dv;
    char buf[256];
    int k, c;
    if (!d || !key) return hpy_fail(msg, size, HCBD_ERR_NULL, "no definition or key");
    for (k = 0; k < (int)(sizeof hpy_keys / sizeof hpy_keys[0]); ++k) {
        const hpy_key *e = hpy_keys + k;
        char *f = (char *)d + e->off;
        if (strcmp(e->name, key)) continue;
        if (e->kind == 'c') {
            for (c = 0; s && e->choices[c]; ++c)
                if (!strcmp(e->choices[c], s)) {
                    const int x = c; /* each enum counts from 0 in the order listed */
                    memcpy(f, &x, sizeof x);
                    return 0;
                }
            snprintf(buf, sizeof buf, "%s = %s is not one of %s%s%s%s%s", key, s ? s : "(a number)",
                     e->choices[0], e->choices[1] ? ", " : "", e->choices[1] ? e->choices[1] : "",
                     e->choices[2] ? ", " : "", e->choices[2] ? e->choices[2] : "");
            return hpy_fail(msg, size, HCBD_ERR_PARAM, buf);
        }
        if (s || !v || n != e->n) {
            snprintf(buf, sizeof buf, "%s takes %d number%s", key, e->n, e->n > 1 ? "s" : "");
            return hpy_fail(msg, size, HCBD_ERR_PARAM, buf);
        }
        for (c = 0; c < n; ++c) {
            const double x = v[c];
            if (e->kind == 'd') {
                memcpy(f + c * sizeof(double), &x, sizeof x);
                continue;
            }
            if (!(x == floor(x)) || (e->kind == 'u' && !(x >= 0 && x < 18446744073709551616.0)) ||
                (e->kind == 'i' && !(x >= INT_MIN && x <= INT_MAX)) ||
                (e->kind == 'I' && !(x >= -9223372036854775808.0 && x < 9223372036854775808.0))) {
                snprintf(buf, sizeof buf, "%s = %.17g is not %s", key, x,
                         e->kind == 'u' ? "an unsigned 64-bit integer" : "an integer in range");
                return hpy_fail(msg, size, HCBD_ERR_PARAM, buf);
            }
            if (e->kind == 'i') {
                int y = (int)x;
                memcpy(f, &y, sizeof y);
            } else if (e->kind == 'u') {
                uint64_t y = (uint64_t)x;
                memcpy(f, &y, sizeof y);
            } else {
                int64_t y = (int64_t)x;
                memcpy(f, &y, sizeof y);
            }
        }
        return 0;
    }
    snprintf(buf, sizeof buf, "unknown parameter '%s'", key);
    return hpy_fail(msg, size, HCBD_ERR_PARAM, buf);
}

/* A 64-bit seed does not fit a double's 53 bits: set it whole */
int hpy_def_set_seed(void *dv, uint64_t seed)
{
    if (!dv) return HCBD_ERR_NULL;
    ((hpy_def *)dv)->params.seed = seed;
    return 0;
}

/* w if r is HCBD_OK, else NULL with the world's message, w freed: the
   end of making a world (hpy_world_new, hpy_world_load) */
static void *hpy_made(hpy_world *w, hcbd_result r, char *msg, int size)
{
    if (r == HCBD_OK) return w;
    hpy_fail(msg, size, r, w->err.msg);
    free(w);
    return NULL;
}

/* The world of definition d (malloc'd; free it with hpy_world_free), or
   NULL with the library's message. */
void *hpy_world_new(const void *d, char *msg, int size)
{
    hpy_world *w = (hpy_world *)calloc(1, sizeof *w);
    if (!w || !d) {
        free(w);
        hpy_fail(msg, size, HCBD_ERR_NULL, "out of memory");
        return NULL;
    }
#if HCBD_MODEL == HCBD_MODEL_HCBD
    return hpy_made(w, hcbd_hc_world_create(w, (const hpy_def *)d), msg, size);
#else
    return hpy_made(w, hcbd_world_create(w, (const hpy_def *)d), msg, size);
#endif
}

/* A world read from a checkpoint file, or NULL with the message */
void *hpy_world_load(const char *path, char *msg, int size)
{
    hpy_world *w = (hpy_world *)calloc(1, sizeof *w);
    if (!w) {
        hpy_fail(msg, size, HCBD_ERR_NULL, "out of memory");
        return NULL;
    }
#if HCBD_MODEL == HCBD_MODEL_HCBD
    return hpy_made(w, hcbd_hc_world_load(w, path), msg, size);
#else
    return hpy_made(w, hcbd_world_load(w, path), msg, size);
#endif
}

void hpy_world_free(void *w)
{
    if (!w) return;
#if HCBD_MODEL == HCBD_MODEL_HCBD
    hcbd_hc_world_destroy((hpy_world *)w);
#else
    hcbd_world_destroy((hpy_world *)w);
#endif
    free(w);
}

/* The world's value of parameter `key` (its params, as set and checked
   at creation): the number of values written to out (at most 3), a
   choice as its position in the list with its name in *choice, *integer
   1 for an integer; -1 for an unknown key or one of the definition's
   sizes (not a parameter). */
int hpy_param_get(const void *wv, const char *key, double *out, const char **choice, int *integer)
{
    const hpy_world *w = (const hpy_world *)wv;
    const size_t base = offsetof(hpy_def, params);
    int k, c;
    if (!w || !key || !out) return -1;
    for (k = 0; k < (int)(sizeof hpy_keys / sizeof hpy_keys[0]); ++k) {
        const hpy_key *e = hpy_keys + k;
        const char *f = (const char *)&w->p + (e->off - base);
        if (strcmp(e->name, key)) continue;
        if (e->off < base || e->off >= base + sizeof w->p) return -1;
        if (integer) *integer = e->kind != 'd' && e->kind != 'c';
        for (c = 0; c < e->n; ++c) {
            if (e->kind == 'd') {
                memcpy(out + c, f + c * sizeof(double), sizeof(double));
            } else if (e->kind == 'u') {
                uint64_t y;
                memcpy(&y, f, sizeof y);
                out[c] = (double)y;
            } else if (e->kind == 'I') {
                int64_t y;
                memcpy(&y, f, sizeof y);
                out[c] = (double)y;
            } else {
                int y;
                memcpy(&y, f, sizeof y);
                out[c] = y;
                if (e->kind == 'c' && choice) *choice = y >= 0 && y < 3 ? e->choices[y] : NULL;
            }
        }
        return e->n;
    }
    return -1;
}

uint64_t hpy_seed(const void *w) { return w ? ((const hpy_world *)w)->p.seed : 0; }

/* the message of the world's last error */
const char *hpy_error(const void *w) { return w ? ((const hpy_world *)w)->err.msg : "no world"; }

/* The world's own array `name` in its storage (no copy): *n its length.
   Walled build: x y z vx vy vz (storage order, which list rebuilds
   re-sort) and id (the id at each slot).  HCBD: fx fy fz fvx fvy fvz
   (fluid blobs in id order) and px py pz (polymers, id order). */
void *hpy_array(void *wv, const char *name, int *n)
{
    hpy_world *w = (hpy_world *)wv;
    if (!w || !name || !n) return NULL;
#if HCBD_MODEL == HCBD_MODEL_HCBD
    *n = name[0] == 'p' ? w->np : w->nf;
    if (!strcmp(name, "fx")) return w->fx;
    if (!strcmp(name, "fy")) return w->fy;
    if (!strcmp(name, "fz")) return w->fz;
    if (!strcmp(name, "fvx")) return w->fvx;
    if (!strcmp(name, "fvy")) return w->fvy;
    if (!strcmp(name, "fvz")) return w->fvz;
    if (!strcmp(name, "px")) return w->px;
    if (!strcmp(name, "py")) return w->py;
    if (!strcmp(name, "pz")) return w->pz;
#else
    *n = w->n;
    if (!strcmp(name, "x")) return w->x;
    if (!strcmp(name, "y")) return w->y;
    if (!strcmp(name, "z")) return w->z;
    if (!strcmp(name, "vx")) return w->vx;
    if (!strcmp(name, "vy")) return w->vy;
    if (!strcmp(name, "vz")) return w->vz;
    if (!strcmp(name, "id")) return w->id;
#endif
    *n = 0;
    return NULL;
}

/* the step counter, the Lees-Edwards offset and the parameters' L */
long long hpy_step_count(const void *w) { return w ? (long long)((const hpy_world *)w)->step : -1; }
double hpy_le_offset(const void *w) { return w ? ((const hpy_world *)w)->core.le_offset : 0.0; }
void hpy_box(const void *w, double L[3])
{
    if (w) memcpy(L, ((const hpy_world *)w)->p.L, 3 * sizeof(double));
}

/* one extended XYZ frame appended to path (or a new file) */
int hpy_write_xyz(const void *wv, const char *path, int append, char *msg, int size)
{
    const hpy_world *w = (const hpy_world *)wv;
    FILE *f;
    hcbd_result r;
    if (!w || !path) return hpy_fail(msg, size, HCBD_ERR_NULL, "no world or path");
    f = fopen(path, append ? "a" : "w");
    if (!f) return hpy_fail(msg, size, HCBD_ERR_IO, "cannot open the XYZ file for writing");
#if HCBD_MODEL == HCBD_MODEL_HCBD
    r = hcbd_hc_world_write_xyz(w, f);
#else
    r = hcbd_world_write_xyz(w, f, NULL, 0);
#endif
    if (fclose(f) != 0 && r == HCBD_OK) r = HCBD_ERR_IO;
    return r == HCBD_OK ? 0 : hpy_fail(msg, size, r, r == HCBD_ERR_IO ? "write failed" : w->err.msg);
}

/* The accumulators with their memory in one block (free with hpy_free):
   g(r) and the MSD (either build; g(r) samples a GI-BD world), the slab
   profiles of a GI-BD world. */
void hpy_free(void *p) { free(p); }

void *hpy_rdf_new(double rmax, int nbins, int block, char *msg, int size)
{
    const size_t b = nbins > 0 && block >= 0 ? hcbd_rdf_bytes(nbins, block) : 0;
    hcbd_rdf *g = (hcbd_rdf *)malloc(sizeof *g + b);
    if (!g) {
        hpy_fail(msg, size, HCBD_ERR_MEMORY, "out of memory");
        return NULL;
    }
    if (hcbd_rdf_init(g, rmax, nbins, block, g + 1, b) != HCBD_OK) {
        char buf[160];
        snprintf(buf, sizeof buf, "g(r): rmax = %g, nbins = %d, block = %d refused (rmax > 0, nbins >= 1, block >= 0)",
                 rmax, nbins, block);
        hpy_fail(msg, size, HCBD_ERR_PARAM, buf);
        free(g);
        return NULL;
    }
    return g;
}

void *hpy_msd_new(int n, int B, int levels, int dense, long long block, char *msg, int size)
{
    const size_t b = n > 0 && B >= 2 && levels >= 1 && dense >= 0 ? hcbd_msd_bytes(n, B, levels, dense) : 0;
    hcbd_msd *d = b ? (hcbd_msd *)malloc(sizeof *d + b) : NULL;
    if (!d || hcbd_msd_init(d, n, B, levels, dense, (int64_t)block, d + 1, b) != HCBD_OK) {
        char buf[200];
        snprintf(buf, sizeof buf, "MSD: n = %d, B = %d, levels = %d, dense = %d, block = %lld refused (n >= 1, "
                 "B >= 2, levels >= 1, dense >= 0, block >= 0)", n, B, levels, dense, block);
        hpy_fail(msg, size, HCBD_ERR_PARAM, buf);
        free(d);
        return NULL;
    }
    return d;
}

#if HCBD_MODEL != HCBD_MODEL_HCBD
void *hpy_profile_new(const void *w, int nslab, int block, char *msg, int size)
{
    const size_t b = nslab > 0 ? hcbd_profile_bytes(nslab) : 0;
    hcbd_profile *pr = (hcbd_profile *)malloc(sizeof *pr + b);
    if (!pr) {
        hpy_fail(msg, size, HCBD_ERR_MEMORY, "out of memory");
        return NULL;
    }
    if (hcbd_profile_init(pr, (const hcbd_world *)w, nslab, block, pr + 1, b) != HCBD_OK) {
        char buf[160];
        snprintf(buf, sizeof buf, "profile: nslab = %d, block = %d refused (nslab >= 1, block >= 1)", nslab, block);
        hpy_fail(msg, size, HCBD_ERR_PARAM, buf);
        free(pr);
        return NULL;
    }
    return pr;
}
#endif
