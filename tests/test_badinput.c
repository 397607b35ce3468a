/* Bad inputs, table-driven: every public function and parameter is fed
   bad values (non-finite, negative, zero where it matters, out of range,
   capacity exceeded, box too small, overlapping cores, polymers without
   fluid, phi >= 1, walls thicker than the box, ...).  Each entry names
   the result code it must give and the text the message must contain
   (the field and its value; "a|b" means both a and b); a call on an
   existing world must leave it unchanged (checksum, particle count, step
   and parameters).  One line per failing entry.  What both worlds have
   (parameters, lifecycle, step, stress, transverse current, checkpoints)
   is one table each (bi_both_params, bi_both_calls, bi_both_io), run
   against each world through its kind (bi_kind); what only one world has
   is in that world's tables. */
#include "test.h"
#include <limits.h>
#include <stddef.h>

static int bi_entries, bi_bad;

/* every '|'-separated part of want occurs in msg */
static int bi_has(const char *msg, const char *want)
{
    char part[128];
    while (*want) {
        size_t k = strcspn(want, "|");
        if (k >= sizeof part) k = sizeof part - 1;
        memcpy(part, want, k);
        part[k] = 0;
        if (!strstr(msg, part)) return 0;
        want += k;
        if (*want == '|') ++want;
    }
    return 1;
}

/* msg: the message the call wrote (NULL: the function has no message
   channel, only the code is checked); changed: what a rejected call
   altered, or NULL */
static void bi_judge2(const char *name, hcbd_result want, const char *want_msg,
                      hcbd_result got, const char *msg, const char *changed, int err_unset)
{
    char why[256] = "";
    ++bi_entries;
    if (got != want)
        snprintf(why + strlen(why), sizeof why - strlen(why), " code: want %s;",
                 hcbd_result_name(want));
    if (want_msg && (!msg || !bi_has(msg, want_msg)))
        snprintf(why + strlen(why), sizeof why - strlen(why), " message lacks \"%s\";", want_msg);
    if (changed)
        snprintf(why + strlen(why), sizeof why - strlen(why), " world changed (%s);", changed);
    if (err_unset)
        snprintf(why + strlen(why), sizeof why - strlen(why), " w->err.code is not the result;");
    if (why[0]) {
        printf("    BAD %s: got %s \"%s\" --%s\n", name, hcbd_result_name(got),
               msg ? msg : "(no message)", why);
        ++bi_bad;
        t_fail = 1;
    }
}

static void bi_judge(const char *name, hcbd_result want, const char *want_msg,
                     hcbd_result got, const char *msg, const char *changed)
{
    bi_judge2(name, want, want_msg, got, msg, changed, 0);
}

static void bi_summary(const char *what)
{
    NOTE("%s: %d entries checked, %d bad", what, bi_entries, bi_bad);
    bi_entries = bi_bad = 0;
}

static void bi_valstr(char *b, size_t n, char k, double v, const void *ptr)
{
    if (k == 'p') snprintf(b, n, "%s", ptr ? "(array)" : "NULL");
    else if (k != 'd') snprintf(b, n, "%lld", (long long)v);
    else if (isnan(v)) snprintf(b, n, "nan");
    else if (isinf(v)) snprintf(b, n, v > 0 ? "inf" : "-inf");
    else snprintf(b, n, "%.17g", v);
}

/* ---- one field of a definition set to one value ------------------------ */
typedef struct {
    const char *f; /* field, as the message must name it */
    size_t off;    /* offset in the definition */
    char k;        /* d double, i int, e enum, l int64, p pointer */
    double v;
    const void *ptr;
} bi_set;

static void bi_apply(void *def, const bi_set *s)
{
    char *b = (char *)def + s->off;
    if (!s->f) return;
    if (s->k == 'd') { double x = s->v; memcpy(b, &x, sizeof x); }
    else if (s->k == 'i' || s->k == 'e') { int x = (int)s->v; memcpy(b, &x, sizeof x); }
    else if (s->k == 'l') { int64_t x = (int64_t)s->v; memcpy(b, &x, sizeof x); }
    else { const void *x = s->ptr; memcpy(b, &x, sizeof x); }
}

/* ---- a world kind, as the tables see it -------------------------------- */
/* Both worlds follow one naming rule (hcbd_world_*, hcbd_hc_world_*), so one
   macro writes each kind's adapters (BI_KIND_FNS) and one runner takes any
   world's table of calls; the cases both worlds have are one table, run
   against each (bi_both_params, bi_both_calls). */
#define BI_PMAX 4096 /* bytes of a world's parameters, at most */
/* compile-time guards: a snapshot's memcpy of the parameters stays in p */
typedef char bi_params_fit[sizeof(hcbd_params) <= BI_PMAX ? 1 : -1];
#if HCBD_MODEL == HCBD_MODEL_HCBD
typedef char bi_hc_params_fit[sizeof(hcbd_hc_params) <= BI_PMAX ? 1 : -1];
#endif
typedef struct {
    int base;        /* the valid definition it spoils (the kind's base) */
    bi_set pre, bad; /* pre: a valid setting the bad one needs */
    hcbd_result want;
    const char *msg; /* NULL: "field = value" of bad */
} bi_pentry;

typedef struct {
    uint64_t sum;
    int n[2]; /* particles (GI-BD); fluid and polymer blobs (HCBD) */
    int64_t step;
    unsigned char p[BI_PMAX];
} bi_snap;

typedef struct bi_kind bi_kind;
typedef hcbd_result (*bi_fn)(const bi_kind *K, void *w, const char **msg);
typedef struct {
    const char *name;
    int kind; /* the world the call acts on, made by the kind's make (0: its default) */
    bi_fn fn;
    hcbd_result want;
    const char *msg; /* NULL: code only (the function has no message channel) */
} bi_call;

struct bi_kind {
    const char *api;               /* prefix of the entry names */
    size_t world_size, def_size, params_off, params_size;
    const char *const *base_name;  /* of each base definition, for the entry names */
    void (*base)(void *def, int base); /* a valid definition for the cases to spoil */
    hcbd_result (*stability)(const void *params, hcbd_limit *out, int *n);
    hcbd_result (*theory)(const void *params); /* NULL: not judged for every parameter */
    int (*mem_kept)(const void *w);            /* a refused create kept its memory */
    int (*make)(void *w, int kind);
    void (*snap)(const void *w, bi_snap *s);
    const hcbd_error *(*err)(const void *w);
    void (*destroy)(void *w);
    hcbd_result (*init)(void *w, const void *def, void *mem, size_t bytes);
    hcbd_result (*create)(void *w, const void *def);
    size_t (*bytes)(const void *def);
    hcbd_result (*check)(const void *params, char *msg, size_t msg_size);
    hcbd_result (*step)(void *w, int nsteps);
    hcbd_result (*stress_enable)(void *w, int on);
    hcbd_result (*stress_read)(const void *w, double *out, int64_t *nsteps);
    hcbd_result (*tc)(const void *w, int nk, double *out);
    size_t (*ck_size)(const void *w);
    hcbd_result (*ck_save)(void *w, void *buf, size_t size);
    hcbd_result (*ck_load)(void *w, const void *buf, size_t size);
    hcbd_result (*save)(void *w, const char *path);
    hcbd_result (*load)(void *w, const char *path);
};

#define BI_KIND_FNS(P, W, D, PAR)                                                                     \
    static void P##_destroy(void *w) { W##_destroy((W *)w); }                                         \
    static const hcbd_error *P##_err(const void *w) { return &((const W *)w)->err; }                  \
    static hcbd_result P##_init(void *w, const void *d, void *m, size_t n)                             \
    {                                                                                                 \
        return W##_init((W *)w, (const D *)d, m, n);                                                  \
    }                                                                                                 \
    static hcbd_result P##_create(void *w, const void *d) { return W##_create((W *)w, (const D *)d); } \
    static size_t P##_bytes(const void *d) { return W##_bytes((const D *)d); }                        \
    static hcbd_result P##_check(const void *p, char *m, size_t n) { return PAR##_check((const PAR *)p, m, n); } \
    static hcbd_result P##_stability(const void *p, hcbd_limit *l, int *n)                            \
    {                                                                                                 \
        return PAR##_stability((const PAR *)p, l, n);                                                 \
    }                                                                                                 \
    static int P##_mem_kept(const void *w) { return ((const W *)w)->core.mem != NULL; }               \
    static hcbd_result P##_step(void *w, int n) { return W##_step((W *)w, n); }                       \
    static hcbd_result P##_stress_enable(void *w, int on) { return W##_stress_enable((W *)w, on); }   \
    static hcbd_result P##_stress_read(const void *w, double *o, int64_t *n)                          \
    {                                                                                                 \
        return W##_stress_read((const W *)w, o, n);                                                   \
    }                                                                                                 \
    static hcbd_result P##_tc(const void *w, int nk, double *o)                                       \
    {                                                                                                 \
        return W##_transverse_current((const W *)w, nk, o);                                           \
    }                                                                                                 \
    static size_t P##_ck_size(const void *w) { return W##_checkpoint_size((const W *)w); }            \
    static hcbd_result P##_ck_save(void *w, void *b, size_t n) { return W##_checkpoint_save((W *)w, b, n); } \
    static hcbd_result P##_ck_load(void *w, const void *b, size_t n)                                  \
    {                                                                                                 \
        return W##_checkpoint_load((W *)w, b, n);                                                     \
    }                                                                                                 \
    static hcbd_result P##_save(void *w, const char *path) { return W##_save((W *)w, path); }         \
    static hcbd_result P##_load(void *w, const char *path) { return W##_load((W *)w, path); }
#define BI_KIND(P, api, W, D, PAR, base_name, base, theory, make, snap)                              \
    {api, sizeof(W), sizeof(D), offsetof(D, params), sizeof(PAR), base_name, base, P##_stability,   \
     theory, P##_mem_kept, make, snap,                                                              \
     P##_err, P##_destroy, P##_init, P##_create, P##_bytes, P##_check, P##_step, P##_stress_enable,  \
     P##_stress_read, P##_tc, P##_ck_size, P##_ck_save, P##_ck_load, P##_save, P##_load}

static const char *bi_diff(const bi_snap *a, const bi_snap *b, char *buf, size_t n)
{
    int k;
    buf[0] = 0;
    for (k = 0; k < 2; ++k)
        if (a->n[k] != b->n[k])
            snprintf(buf + strlen(buf), n - strlen(buf), "n[%d] %d -> %d ", k, a->n[k], b->n[k]);
    if (a->step != b->step)
        snprintf(buf + strlen(buf), n - strlen(buf), "step %lld -> %lld ", (long long)a->step,
                 (long long)b->step);
    if (a->sum != b->sum) snprintf(buf + strlen(buf), n - strlen(buf), "checksum ");
    if (memcmp(a->p, b->p, sizeof a->p)) snprintf(buf + strlen(buf), n - strlen(buf), "params ");
    return buf[0] ? buf : NULL;
}

/* The checks of one definition: params_check (when the bad value is in the
   parameters), stability and theory give want; world_create gives it,
   with want_msg, and keeps no memory when it fails; world_bytes stays
   defined. */
static void bi_judge_def(const bi_kind *K, const char *name, void *def, int in_params, hcbd_result want,
                         const char *want_msg)
{
    const void *par = (const char *)def + K->params_off;
    void *w = calloc(1, K->world_size);
    hcbd_limit lim[HCBD_MAX_LIMITS];
    char msg[256], n2[200];
    int nl;
    hcbd_result r;
    if (!w) {
        t_fail = 1;
        return;
    }
    if (in_params) {
        strcpy(msg, "(untouched)");
        r = K->check(par, msg, sizeof msg);
        snprintf(n2, sizeof n2, "%s_params_check %s", K->api, name);
        bi_judge(n2, want, want_msg, r, msg, NULL);
        snprintf(n2, sizeof n2, "%s_params_stability %s", K->api, name);
        bi_judge(n2, want, NULL, K->stability(par, lim, &nl), NULL, NULL);
        if (K->theory) {
            snprintf(n2, sizeof n2, "%s_params_theory %s", K->api, name);
            bi_judge(n2, want, NULL, K->theory(par), NULL, NULL);
        }
    }
    snprintf(n2, sizeof n2, "%s_world_create %s", K->api, name);
    r = K->create(w, def);
    bi_judge(n2, want, want_msg, r, K->err(w)->msg, r != HCBD_OK && K->mem_kept(w) ? "memory kept" : NULL);
    if (r == HCBD_OK) K->destroy(w);
    snprintf(n2, sizeof n2, "%s_world_bytes %s", K->api, name);
    bi_judge(n2, HCBD_OK, NULL, K->bytes(def) == 0 ? HCBD_OK : HCBD_ERR_STATE, NULL, NULL);
    free(w);
}

/* Each definition of t: the base spoilt by pre and bad, judged by the kind. */
static void bi_defs(const bi_kind *K, const bi_pentry *t, size_t n)
{
    void *d = malloc(K->def_size);
    size_t e;
    for (e = 0; d && e < n; ++e) {
        char name[160], val[64], want[128];
        K->base(d, t[e].base);
        bi_apply(d, &t[e].pre);
        bi_apply(d, &t[e].bad);
        bi_valstr(val, sizeof val, t[e].bad.k, t[e].bad.v, t[e].bad.ptr);
        snprintf(name, sizeof name, "%s%s = %s", K->base_name[t[e].base], t[e].bad.f, val);
        snprintf(want, sizeof want, "%s = %s", t[e].bad.f, val);
        if (t[e].msg) snprintf(want, sizeof want, "%s", t[e].msg);
        bi_judge_def(K, name, d, t[e].bad.off >= K->params_off && t[e].bad.off < K->params_off + K->params_size,
                     t[e].want, want);
    }
    if (!d) t_fail = 1;
    free(d);
}

/* Each call of t on its own fresh world: the code and message it must
   give, and a refused call must leave the world as it was. */
static void bi_run(const bi_kind *K, const bi_call *t, size_t n)
{
    void *w = malloc(K->world_size);
    size_t e;
    for (e = 0; w && e < n; ++e) {
        bi_snap a, b;
        char buf[128], name[200];
        const char *msg, *ch;
        hcbd_result r;
        if (!K->make(w, t[e].kind)) { t_fail = 1; continue; }
        K->snap(w, &a);
        msg = K->err(w)->msg;
        r = t[e].fn(K, w, &msg);
        K->snap(w, &b);
        ch = bi_diff(&a, &b, buf, sizeof buf);
        snprintf(name, sizeof name, "%s_%s", K->api, t[e].name);
        /* a message in w->err comes with its code */
        bi_judge2(name, t[e].want, t[e].msg, r, msg, ch,
                  r != HCBD_OK && msg == K->err(w)->msg && K->err(w)->code != r);
        K->destroy(w);
    }
    if (!w) t_fail = 1;
    free(w);
}

#define NOSET {NULL, 0, 0, 0, NULL}
/* GI-BD: fields of hcbd_params (in hcbd_world_def) and of hcbd_world_def */
#define GD(f, v) {#f, offsetof(hcbd_world_def, params.f), 'd', (v), NULL}
#define GI(f, v) {#f, offsetof(hcbd_world_def, params.f), 'i', (v), NULL}
#define GE(f, v) {#f, offsetof(hcbd_world_def, params.f), 'e', (v), NULL}
#define GP(f, p) {#f, offsetof(hcbd_world_def, params.f), 'p', 0, (p)}
#define WI(f, v) {#f, offsetof(hcbd_world_def, f), 'i', (v), NULL}
#define WL(f, v) {#f, offsetof(hcbd_world_def, f), 'l', (v), NULL}

enum { B_DEF, B_BD, B_TABLE, B_SHEAR, B_WALL, B_NOSLIP, B_NBASE };
static const char *bi_base_name[B_NBASE] = {"", "BD ", "table ", "sheared ", "walled ",
                                            "no-slip walls "};


static double bi_tab[16], bi_tab_nan[16], bi_tab_inf[16];

static hcbd_world_def bi_base(int base)
{
    hcbd_world_def d = hcbd_world_def_default();
    int k;
    for (k = 0; k < 16; ++k) {
        bi_tab[k] = bi_tab_nan[k] = bi_tab_inf[k] = 16.0 - k;
    }
    bi_tab_nan[3] = NAN;
    bi_tab_inf[5] = INFINITY;
    d.capacity = 64;
    if (base == B_BD) d.params.dynamics = HCBD_DYN_BD;
    if (base == B_TABLE) {
        d.params.potential = HCBD_POT_TABLE;
        d.params.table_F = bi_tab;
        d.params.table_V = bi_tab;
        d.params.table_n = 16;
        d.params.table_r0 = 0.5;
    }
    if (base == B_SHEAR) d.params.gdot = 1.0;
#if HCBD_MODEL == HCBD_MODEL_WALLED
    if (base == B_WALL || base == B_NOSLIP) d.params.wall.thickness = 2.0;
    if (base == B_NOSLIP) d.params.wall.mode = HCBD_WALL_NOSLIP;
#endif
    return d;
}

static const bi_pentry bi_params[] = {
    /* box */
    {B_DEF, NOSET, GD(L[1], 1e13), HCBD_ERR_PARAM, NULL},
    /* < 2 Rc: too small even for the automatic skin, which shrinks to fit */
    {B_DEF, NOSET, GD(L[0], 4.9), HCBD_ERR_BOX, NULL},
    {B_DEF, NOSET, GD(L[2], 4.5), HCBD_ERR_BOX, NULL},
    {B_DEF, NOSET, GD(skin, 5), HCBD_ERR_BOX, "box too small|skin 5"},
    /* dynamics */
    {B_DEF, NOSET, GD(xip, 0), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(xip, -1), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(xip, NAN), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(xip, INFINITY), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(tau, 0), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(tau, -1), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(tau, NAN), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(tau, INFINITY), HCBD_ERR_PARAM, NULL},
    {B_DEF, GE(pair_integrator, HCBD_PAIR_EULER), GD(tau, 6.103515625e-05), HCBD_ERR_PARAM, NULL}, /* < dt (Euler) */
    {B_DEF, NOSET, GD(Rc, 0), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(Rc, -1), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(Rc, NAN), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(Rc, INFINITY), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(density, 0), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(density, -1), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(density, NAN), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(density, INFINITY), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GI(density_norm, 2015), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GI(density_norm, 0), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GI(lagged_density, 2), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GI(lagged_density, -1), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GE(dynamics, 2), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GE(dynamics, -1), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GE(potential, 3), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GE(potential, -1), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GE(noise, 2), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GE(noise, -1), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GE(brownian, 2), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GE(brownian, -1), HCBD_ERR_PARAM, NULL},
    /* star potential */
    {B_DEF, NOSET, GD(f, 0), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(f, -1), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(f, NAN), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(f, INFINITY), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(star_eps, -1), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(star_eps, NAN), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(star_eps, INFINITY), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(rcut, 0), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(rcut, -1), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(rcut, NAN), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(rcut, INFINITY), HCBD_ERR_PARAM, NULL},
    /* table potential */
    {B_TABLE, NOSET, GP(table_F, NULL), HCBD_ERR_NULL, "table_F"},
    {B_TABLE, NOSET, GP(table_V, NULL), HCBD_ERR_NULL, "table_V"},
    {B_TABLE, NOSET, GI(table_n, 1), HCBD_ERR_PARAM, NULL},
    {B_TABLE, NOSET, GI(table_n, 0), HCBD_ERR_PARAM, NULL},
    {B_TABLE, NOSET, GI(table_n, -3), HCBD_ERR_PARAM, NULL},
    {B_TABLE, NOSET, GD(table_r0, -1), HCBD_ERR_PARAM, NULL},
    {B_TABLE, NOSET, GD(table_r0, NAN), HCBD_ERR_PARAM, NULL},
    {B_TABLE, NOSET, GD(table_r0, 2.5), HCBD_ERR_PARAM, NULL}, /* = rcut */
    {B_TABLE, NOSET, GP(table_F, bi_tab_nan), HCBD_ERR_PARAM, "table_F[3] = nan"},
    {B_TABLE, NOSET, GP(table_V, bi_tab_inf), HCBD_ERR_PARAM, "table_V[5] = inf"},
    /* forces, shear */
    {B_DEF, NOSET, GD(fext[0], NAN), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(fext[1], INFINITY), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(fext[2], -INFINITY), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GI(fext_background_only, 2), HCBD_ERR_PARAM, NULL},
    /* BD has no background for the force to drive (once silently dropped) */
    {B_BD, GD(fext[0], 1.0), GI(fext_background_only, 1), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(fext[2], NAN), HCBD_ERR_PARAM, NULL},
    {B_BD, NOSET, GD(gdot, 1), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(gdot, 100000), HCBD_ERR_PARAM, NULL}, /* offset > L per step */
    {B_DEF, NOSET, GD(gdot, -100000), HCBD_ERR_PARAM, NULL},
    {B_SHEAR, NOSET, GD(L[0], 7.4), HCBD_ERR_BOX, "L[0] = 7.4|Lees-Edwards"},
    {B_DEF, NOSET, GD(skin, -0.5), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(skin, NAN), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(skin, INFINITY), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GI(sort, 2), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GI(force_table, 2), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GI(force_table, -1), HCBD_ERR_PARAM, NULL},
    /* checks of the input and of the run */
    {B_DEF, NOSET, GD(min_distance, -1), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(min_distance, NAN), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(min_distance, INFINITY), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(guard_step, 0), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(guard_step, -2), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(guard_step, NAN), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(guard_step, INFINITY), HCBD_ERR_PARAM, NULL},
    /* walls */
#if HCBD_MODEL == HCBD_MODEL_WALLED
    {B_DEF, NOSET, GI(wall.guard, 2), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GI(wall.guard, -1), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(wall.thickness, NAN), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(wall.thickness, -1), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, GD(wall.thickness, INFINITY), HCBD_ERR_PARAM, NULL},
    {B_WALL, NOSET, GD(wall.thickness, 7), HCBD_ERR_BOX, NULL},   /* 2 t > L[1] */
    {B_WALL, NOSET, GD(wall.thickness, 6.5), HCBD_ERR_BOX, NULL}, /* 2 t > L[1] */
    {B_WALL, NOSET, GD(wall.thickness, 1), HCBD_ERR_BOX, NULL},   /* 2 t < Rc */
    {B_WALL, NOSET, GD(gdot, 1), HCBD_ERR_PARAM, "gdot|= 1"},
    {B_WALL, NOSET, GI(lagged_density, 1), HCBD_ERR_PARAM, "lagged_density|= 1"},
    {B_WALL, NOSET, GD(wall.vx[0], NAN), HCBD_ERR_PARAM, NULL},
    {B_WALL, NOSET, GD(wall.vx[1], INFINITY), HCBD_ERR_PARAM, NULL},
    {B_WALL, NOSET, GD(wall.beta_max, 0.5), HCBD_ERR_PARAM, NULL},
    {B_WALL, NOSET, GD(wall.beta_max, NAN), HCBD_ERR_PARAM, NULL},
    {B_WALL, NOSET, GD(wall.beta_max, INFINITY), HCBD_ERR_PARAM, NULL},
    {B_WALL, NOSET, GE(wall.mode, 3), HCBD_ERR_PARAM, NULL},
    {B_WALL, NOSET, GE(wall.mode, -1), HCBD_ERR_PARAM, NULL},
    {B_WALL, NOSET, GI(wall.noise_beta, 2), HCBD_ERR_PARAM, NULL},
    {B_WALL, NOSET, GD(wall.a, -1), HCBD_ERR_PARAM, NULL},
    {B_WALL, NOSET, GD(wall.a, NAN), HCBD_ERR_PARAM, NULL},
    {B_WALL, NOSET, GD(wall.b, 0), HCBD_ERR_PARAM, NULL},
    {B_WALL, NOSET, GD(wall.b, NAN), HCBD_ERR_PARAM, NULL},
    {B_WALL, NOSET, GD(wall.plane, -1), HCBD_ERR_PARAM, NULL},
    {B_WALL, NOSET, GD(wall.plane, 3), HCBD_ERR_PARAM, NULL}, /* deeper than the wall */
    {B_WALL, NOSET, GD(wall.plane, NAN), HCBD_ERR_PARAM, NULL},
    {B_NOSLIP, NOSET, GD(wall.shift, -2), HCBD_ERR_PARAM, NULL},
    {B_NOSLIP, NOSET, GD(wall.shift, 3), HCBD_ERR_PARAM, NULL}, /* > channel / 4 */
    {B_NOSLIP, NOSET, GD(wall.shift, NAN), HCBD_ERR_PARAM, NULL},
    {B_WALL, GI(density_norm, 2014), GD(density, 0), HCBD_ERR_PARAM, "density|= 0"},
    {B_WALL, NOSET, GI(wall.guard, 2), HCBD_ERR_PARAM, NULL},
    {B_WALL, NOSET, GD(L[1], 4), HCBD_ERR_BOX, NULL},
#endif
    /* the definition */
    {B_DEF, NOSET, WI(capacity, 0), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, WI(capacity, -1), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, WI(capacity, 536870912), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, WI(capacity, 500000000), HCBD_ERR_CAPACITY, NULL}, /* > 2^31 pairs */
    {B_DEF, NOSET, WL(max_pairs, -2), HCBD_ERR_PARAM, NULL},
    {B_DEF, NOSET, WL(max_pairs, 2147483648.0), HCBD_ERR_PARAM, NULL},
};

/* ---- calls on an existing world --------------------------------------- */
enum { WK_GIBD, WK_BD, WK_EMPTY, WK_MIND, WK_WALL };
static double bi_xyz[3 * 64]; /* the test world's positions, id order */
static char bi_msg[256];      /* messages of worlds made inside a call */

static int bi_make(hcbd_world *w, int kind)
{
    hcbd_world_def d = bi_base(kind == WK_WALL ? B_WALL : B_DEF);
    if (kind == WK_BD) d.params.dynamics = HCBD_DYN_BD;
    if (kind == WK_MIND) d.params.min_distance = 0.5;
    if (hcbd_world_create(w, &d) != HCBD_OK) {
        printf("    world: %s\n", w->err.msg);
        return 0;
    }
    if (kind == WK_EMPTY) return 1;
    if (hcbd_world_place_lattice(w, 64) != HCBD_OK || hcbd_world_step(w, 3) != HCBD_OK) {
        printf("    set-up: %s\n", w->err.msg);
        hcbd_world_destroy(w);
        return 0;
    }
    hcbd_world_get_positions(w, bi_xyz, 0);
    return 1;
}

/* a call on a GI-BD world (bi_call's fn, the world typed) */
#define WF(f)                                                                  \
    static hcbd_result f##_(hcbd_world *w, const char **msg);                  \
    static hcbd_result f(const bi_kind *K, void *w, const char **msg)          \
    {                                                                          \
        (void)K;                                                               \
        return f##_((hcbd_world *)w, msg);                                     \
    }                                                                          \
    static hcbd_result f##_(hcbd_world *w, const char **msg)
#define NOMSG (*msg = NULL, (void)w)

/* set-up */
WF(c_setpos_nullw) { NOMSG; return hcbd_world_set_positions(NULL, 64, bi_xyz); }
WF(c_setpos_null) { (void)msg; return hcbd_world_set_positions(w, 64, NULL); }
WF(c_setpos_65) { static double x[3 * 65]; (void)msg; memcpy(x, bi_xyz, sizeof bi_xyz); return hcbd_world_set_positions(w, 65, x); }
WF(c_setpos_0) { (void)msg; return hcbd_world_set_positions(w, 0, bi_xyz); }
WF(c_setpos_m1) { (void)msg; return hcbd_world_set_positions(w, -1, bi_xyz); }
WF(c_setpos_1) { (void)msg; return hcbd_world_set_positions(w, 1, bi_xyz); }
static hcbd_result bi_setpos_mod(hcbd_world *w, int i, double v)
{
    double x[3 * 64];
    memcpy(x, bi_xyz, sizeof x);
    x[i] = v;
    return hcbd_world_set_positions(w, 64, x);
}
WF(c_setpos_nan) { (void)msg; return bi_setpos_mod(w, 3 * 5 + 1, NAN); }
WF(c_setpos_inf) { (void)msg; return bi_setpos_mod(w, 0, INFINITY); }
WF(c_setpos_minf) { (void)msg; return bi_setpos_mod(w, 3 * 63 + 2, -INFINITY); }
WF(c_setpos_far) { (void)msg; return bi_setpos_mod(w, 3 * 2, 1e20); }
WF(c_setpos_overlap)
{
    double x[3 * 64];
    (void)msg;
    memcpy(x, bi_xyz, sizeof x);
    x[9] = 1.0; x[10] = 1.0; x[11] = 1.0;  /* particle 3 */
    x[21] = 1.25; x[22] = 1.0; x[23] = 1.0; /* particle 7, 0.25 away */
    return hcbd_world_set_positions(w, 64, x);
}
#if HCBD_MODEL == HCBD_MODEL_WALLED
WF(c_setpos_wall)
{
    double x[3 * 64];
    (void)msg;
    memcpy(x, bi_xyz, sizeof x);
    x[3 * 5 + 1] = 0.5; /* particle 5 inside the bottom wall (t = 2) */
    return hcbd_world_set_positions(w, 64, x);
}
WF(c_setpos_wall_top) { (void)msg; return bi_setpos_mod(w, 3 * 0 + 1, 12.0); }
#endif
WF(c_lattice_65) { (void)msg; return hcbd_world_place_lattice(w, 65); }
WF(c_lattice_0) { (void)msg; return hcbd_world_place_lattice(w, 0); }
WF(c_lattice_nullw) { NOMSG; return hcbd_world_place_lattice(NULL, 8); }
WF(c_random_m5) { (void)msg; return hcbd_world_place_random(w, -5); }
WF(c_random_65) { (void)msg; return hcbd_world_place_random(w, 65); }
WF(c_random_nullw) { NOMSG; return hcbd_world_place_random(NULL, 8); }
WF(c_setvel_null) { (void)msg; return hcbd_world_set_velocities(w, NULL); }
WF(c_setvel_nullw) { NOMSG; return hcbd_world_set_velocities(NULL, bi_xyz); }
WF(c_setvel_nan)
{
    double v[3 * 64] = {0};
    (void)msg;
    v[3 * 2] = NAN;
    return hcbd_world_set_velocities(w, v);
}
WF(c_setvel_inf)
{
    double v[3 * 64] = {0};
    (void)msg;
    v[3 * 63 + 2] = -INFINITY;
    return hcbd_world_set_velocities(w, v);
}
WF(c_setvel_zero) { double v[3 * 64] = {0}; (void)msg; return hcbd_world_set_velocities(w, v); }
/* step (the cases both worlds have: bi_both_calls) */
WF(c_step_1) { (void)msg; return hcbd_world_step(w, 1); }
/* observables */
WF(c_getpos_null) { NOMSG; return hcbd_world_get_positions(w, NULL, 0); }
WF(c_getpos_nullw) { double x[3]; NOMSG; return hcbd_world_get_positions(NULL, x, 1); }
WF(c_getvel_null) { NOMSG; return hcbd_world_get_velocities(w, NULL); }
WF(c_stress_null) { (void)msg; return hcbd_world_virial_stress(w, NULL); }
WF(c_stress_nullw) { double s[9]; NOMSG; return hcbd_world_virial_stress(NULL, s); }
WF(c_fric_nk0) { double o[3]; (void)msg; return hcbd_world_friction_average(w, 0, o); }
WF(c_fric_nkm1) { double o[3]; (void)msg; return hcbd_world_friction_average(w, -1, o); }
WF(c_fric_null) { (void)msg; return hcbd_world_friction_average(w, 1, NULL); }
WF(c_fric_ok) { double o[3]; (void)msg; return hcbd_world_friction_average(w, 1, o); }
static hcbd_result bi_rdf(hcbd_world *w, double rmax, int nbins, int null_g, int null_h)
{
    static double hist[64];
    hcbd_rdf g;
    hcbd_result r = hcbd_rdf_init(null_g ? NULL : &g, rmax, nbins, 0, null_h ? NULL : hist, sizeof hist);
    if (r != HCBD_OK || !w) return r;
    return hcbd_rdf_sample(&g, w);
}
WF(c_rdf_r0) { NOMSG; return bi_rdf(NULL, 0, 10, 0, 0); }
WF(c_rdf_rm1) { NOMSG; return bi_rdf(NULL, -1, 10, 0, 0); }
WF(c_rdf_rnan) { NOMSG; return bi_rdf(NULL, NAN, 10, 0, 0); }
WF(c_rdf_rinf) { NOMSG; return bi_rdf(NULL, INFINITY, 10, 0, 0); }
WF(c_rdf_nb0) { NOMSG; return bi_rdf(NULL, 2, 0, 0, 0); }
WF(c_rdf_nbm1) { NOMSG; return bi_rdf(NULL, 2, -1, 0, 0); }
WF(c_rdf_nullg) { NOMSG; return bi_rdf(NULL, 2, 10, 1, 0); }
WF(c_rdf_nullh) { NOMSG; return bi_rdf(NULL, 2, 10, 0, 1); }
WF(c_rdf_big) { (void)msg; return bi_rdf(w, 7, 10, 0, 0); } /* > L/2 = 6.45 */
WF(c_rdf_sample_nullg) { (void)msg; return hcbd_rdf_sample(NULL, w); }
WF(c_rdf_empty) { (void)msg; return bi_rdf(w, 2, 10, 0, 0); }
static hcbd_result bi_rdf_blocks(int block, size_t shortby)
{
    static double mem[60];
    hcbd_rdf g;
    return hcbd_rdf_init(&g, 2, 10, block, mem, hcbd_rdf_bytes(10, 1) - shortby);
}
WF(c_rdf_blockm1) { NOMSG; return bi_rdf_blocks(-1, 0); }
WF(c_rdf_blockshort) { NOMSG; return bi_rdf_blocks(5, 1); }
/* coordination within rc of a g(r) to rmax = 2, one ideal-gas sample unless empty */
static hcbd_result bi_coord(hcbd_world *w, double rc, int empty, int nullnc)
{
    static double mem[60];
    hcbd_rdf g;
    double nc;
    hcbd_result r = hcbd_rdf_init(&g, 2, 10, 5, mem, sizeof mem);
    if (r == HCBD_OK && !empty) r = hcbd_rdf_sample(&g, w);
    return r != HCBD_OK ? r : hcbd_rdf_coordination(&g, rc, nullnc ? NULL : &nc, NULL);
}
WF(c_coord_big) { NOMSG; return bi_coord(w, 2.5, 0, 0); }
WF(c_coord_neg) { NOMSG; return bi_coord(w, -1, 0, 0); }
WF(c_coord_nan) { NOMSG; return bi_coord(w, NAN, 0, 0); }
WF(c_coord_empty) { NOMSG; return bi_coord(w, 1, 1, 0); }
WF(c_coord_null) { NOMSG; return bi_coord(w, 1, 0, 1); }
static hcbd_result bi_mt(int nch, int p, int m, int levels, int nullc, int nullmem, int shortmem)
{
    static double mem[4096];
    hcbd_mtcorr c;
    size_t b = sizeof mem;
    if (shortmem) b = hcbd_mtcorr_bytes(nch, p, m, levels) - 1;
    return hcbd_mtcorr_init(nullc ? NULL : &c, nch, p, m, levels, nullmem ? NULL : mem, b);
}
WF(c_mt_nch0) { NOMSG; return bi_mt(0, 16, 2, 3, 0, 0, 0); }
WF(c_mt_p1) { NOMSG; return bi_mt(1, 1, 2, 3, 0, 0, 0); }
WF(c_mt_m1) { NOMSG; return bi_mt(1, 16, 1, 3, 0, 0, 0); }
WF(c_mt_pmod) { NOMSG; return bi_mt(1, 16, 3, 3, 0, 0, 0); }
WF(c_mt_lev0) { NOMSG; return bi_mt(1, 16, 2, 0, 0, 0, 0); }
WF(c_mt_nullc) { NOMSG; return bi_mt(1, 16, 2, 3, 1, 0, 0); }
WF(c_mt_nullmem) { NOMSG; return bi_mt(1, 16, 2, 3, 0, 1, 0); }
WF(c_mt_short) { NOMSG; return bi_mt(1, 16, 2, 3, 0, 0, 1); }
static hcbd_result bi_msd(int n, int B, int levels, int nulld, int nullmem, int shortmem)
{
    static double mem[8192];
    hcbd_msd d;
    size_t b = sizeof mem;
    if (shortmem) b = hcbd_msd_bytes(n, B, levels, 0) - 1;
    return hcbd_msd_init(nulld ? NULL : &d, n, B, levels, 0, 0, nullmem ? NULL : mem, b);
}
WF(c_msd_n0) { NOMSG; return bi_msd(0, 4, 3, 0, 0, 0); }
WF(c_msd_B1) { NOMSG; return bi_msd(8, 1, 3, 0, 0, 0); }
WF(c_msd_lev0) { NOMSG; return bi_msd(8, 4, 0, 0, 0, 0); }
WF(c_msd_span) { NOMSG; return bi_msd(1, 2, 70, 0, 0, 0); } /* 2^69 samples */
WF(c_msd_nulld) { NOMSG; return bi_msd(8, 4, 3, 1, 0, 0); }
WF(c_msd_nullmem) { NOMSG; return bi_msd(8, 4, 3, 0, 1, 0); }
WF(c_msd_short) { NOMSG; return bi_msd(8, 4, 3, 0, 0, 1); }
static hcbd_result bi_msd2(int dense, int64_t block, double lag_min, double lag_max, int samples)
{
    static double mem[16384], xyz[24];
    hcbd_msd d;
    double D;
    int s;
    hcbd_result r = hcbd_msd_init(&d, 8, 4, 3, dense, block, mem, sizeof mem);
    if (r != HCBD_OK) return r;
    for (s = 0; s < samples; ++s) {
        xyz[0] = s;
        hcbd_msd_add(&d, xyz);
    }
    return hcbd_msd_diffusion(&d, lag_min, lag_max, &D, NULL);
}
WF(c_msd_densem1) { NOMSG; return bi_msd2(-1, 0, 1, 3, 0); }
WF(c_msd_blockm1) { NOMSG; return bi_msd2(0, -1, 1, 3, 0); }
WF(c_msd_dense_big)
{
    static double mem[64];
    hcbd_msd d;
    NOMSG;
    return hcbd_msd_init(&d, 8, 1000, 4, 3, 0, mem, sizeof mem); /* 999 10^9 slots */
}
WF(c_msd_window) { NOMSG; return bi_msd2(0, 0, 3, 1, 100); }
WF(c_msd_window_nan) { NOMSG; return bi_msd2(0, 0, NAN, 3, 100); }
WF(c_msd_one_lag) { NOMSG; return bi_msd2(0, 0, 2, 2.5, 100); }
WF(c_msd_no_block) { NOMSG; return bi_msd2(1, 50, 1, 3, 49); } /* no block closed yet */
static hcbd_result bi_prof(hcbd_world *w, int nslab, int block, int nullpr, int nullmem, int shortmem)
{
    static double mem[4096];
    hcbd_profile pr;
    size_t b = sizeof mem;
    if (shortmem) b = hcbd_profile_bytes(nslab) - 1;
    return hcbd_profile_init(nullpr ? NULL : &pr, w, nslab, block, nullmem ? NULL : mem, b);
}
WF(c_prof_ns0) { NOMSG; return bi_prof(w, 0, 10, 0, 0, 0); }
WF(c_prof_nsbig) { NOMSG; return bi_prof(w, (1 << 20) + 1, 10, 0, 0, 0); }
WF(c_prof_bl0) { NOMSG; return bi_prof(w, 10, 0, 0, 0, 0); }
WF(c_prof_nullpr) { NOMSG; return bi_prof(w, 10, 10, 1, 0, 0); }
WF(c_prof_nullw) { NOMSG; return bi_prof(NULL, 10, 10, 0, 0, 0); }
WF(c_prof_nullmem) { NOMSG; return bi_prof(w, 10, 10, 0, 1, 0); }
WF(c_prof_short) { NOMSG; return bi_prof(w, 10, 10, 0, 0, 1); }
static hcbd_result bi_slabs(double Ly, int nslab, int nval, int block, int nullL, int shortmem)
{
    static double mem[4096];
    double L[3] = {10, 10, 10};
    hcbd_slabs s;
    size_t b = sizeof mem;
    L[1] = Ly;
    if (shortmem) b = hcbd_slabs_bytes(nslab, nval) - 1;
    return hcbd_slabs_init(&s, nullL ? NULL : L, nslab, nval, block, mem, b);
}
WF(c_slabs_ns0) { NOMSG; return bi_slabs(10, 0, 1, 10, 0, 0); }
WF(c_slabs_nvm1) { NOMSG; return bi_slabs(10, 10, -1, 10, 0, 0); }
WF(c_slabs_nv65) { NOMSG; return bi_slabs(10, 10, 65, 10, 0, 0); }
WF(c_slabs_bl0) { NOMSG; return bi_slabs(10, 10, 1, 0, 0, 0); }
WF(c_slabs_Lnan) { NOMSG; return bi_slabs(NAN, 10, 1, 10, 0, 0); }
WF(c_slabs_Lneg) { NOMSG; return bi_slabs(-1, 10, 1, 10, 0, 0); }
WF(c_slabs_Linf) { NOMSG; return bi_slabs(INFINITY, 10, 1, 10, 0, 0); }
WF(c_slabs_nullL) { NOMSG; return bi_slabs(10, 10, 1, 10, 1, 0); }
WF(c_slabs_short) { NOMSG; return bi_slabs(10, 10, 1, 10, 0, 1); }
/* Carreau: a good flow curve with one thing spoilt */
static hcbd_result bi_carreau(int n, int what, double v)
{
    double g[6] = {0.01, 0.1, 1, 10, 100, 1000}, eta[6] = {10, 9.5, 6, 2, 1.2, 1.02};
    double err[6] = {0.1, 0.1, 0.1, 0.05, 0.02, 0.01}, p[3] = {10, 1, 0.5}, pe[3], c2;
    double eta_inf = 1.0;
    int start = 0;
    if (what == 1) g[2] = v;
    if (what == 2) eta[3] = v;
    if (what == 3) err[1] = v;
    if (what == 4) eta_inf = v;
    if (what == 5) { start = 1; p[0] = v; }
    if (what == 6) { start = 1; p[1] = v; }
    if (what == 7) { start = 1; p[2] = v; }
    if (what == 8) return hcbd_carreau_fit(NULL, eta, err, n, eta_inf, start, p, pe, &c2);
    if (what == 9) return hcbd_carreau_fit(g, eta, err, n, eta_inf, start, NULL, pe, &c2);
    return hcbd_carreau_fit(g, eta, err, n, eta_inf, start, p, pe, &c2);
}
WF(c_car_ok) { NOMSG; return bi_carreau(6, 0, 0); }
WF(c_car_n3) { NOMSG; return bi_carreau(3, 0, 0); }
WF(c_car_n0) { NOMSG; return bi_carreau(0, 0, 0); }
WF(c_car_gneg) { NOMSG; return bi_carreau(6, 1, -1); }
WF(c_car_g0) { NOMSG; return bi_carreau(6, 1, 0); }
WF(c_car_ginf) { NOMSG; return bi_carreau(6, 1, INFINITY); }
WF(c_car_gnan) { NOMSG; return bi_carreau(6, 1, NAN); }
WF(c_car_etanan) { NOMSG; return bi_carreau(6, 2, NAN); }
WF(c_car_err0) { NOMSG; return bi_carreau(6, 3, 0); }
WF(c_car_errneg) { NOMSG; return bi_carreau(6, 3, -0.1); }
WF(c_car_einfnan) { NOMSG; return bi_carreau(6, 4, NAN); }
WF(c_car_einfinf) { NOMSG; return bi_carreau(6, 4, INFINITY); }
WF(c_car_p0nan) { NOMSG; return bi_carreau(6, 5, NAN); }
WF(c_car_p1neg) { NOMSG; return bi_carreau(6, 6, -1); }
WF(c_car_p1zero) { NOMSG; return bi_carreau(6, 6, 0); }
WF(c_car_p2inf) { NOMSG; return bi_carreau(6, 7, INFINITY); }
WF(c_car_nullg) { NOMSG; return bi_carreau(6, 8, 0); }
WF(c_car_nullp) { NOMSG; return bi_carreau(6, 9, 0); }
/* limits and theory */
WF(c_stab_nullp) { hcbd_limit l[HCBD_MAX_LIMITS]; int n; NOMSG; return hcbd_params_stability(NULL, l, &n); }
WF(c_stab_nullout) { int n; NOMSG; return hcbd_params_stability(&w->p, NULL, &n); }
WF(c_stab_nulln) { hcbd_limit l[HCBD_MAX_LIMITS]; NOMSG; return hcbd_params_stability(&w->p, l, NULL); }
WF(c_stab_ok) { hcbd_limit l[HCBD_MAX_LIMITS]; int n; NOMSG; return hcbd_params_stability(&w->p, l, &n); }
WF(c_theory_nullp) { hcbd_theory t; NOMSG; return hcbd_params_theory(NULL, &t); }
WF(c_theory_nullt) { NOMSG; return hcbd_params_theory(&w->p, NULL); }

static const bi_call bi_calls[] = {
    {"set_positions w NULL", WK_GIBD, c_setpos_nullw, HCBD_ERR_NULL, NULL},
    {"set_positions xyz NULL", WK_GIBD, c_setpos_null, HCBD_ERR_NULL, "positions"},
    {"set_positions n = 65 > capacity", WK_GIBD, c_setpos_65, HCBD_ERR_CAPACITY, "N = 65"},
    {"set_positions n = 0", WK_GIBD, c_setpos_0, HCBD_ERR_PARAM, "N = 0"},
    {"set_positions n = -1", WK_GIBD, c_setpos_m1, HCBD_ERR_PARAM, "N = -1"},
    {"set_positions n = 1 (GI-BD)", WK_GIBD, c_setpos_1, HCBD_ERR_PARAM, "N = 1"},
    {"set_positions y NaN", WK_GIBD, c_setpos_nan, HCBD_ERR_NONFINITE, "particle 5|nan"},
    {"set_positions x inf", WK_GIBD, c_setpos_inf, HCBD_ERR_NONFINITE, "particle 0|inf"},
    {"set_positions z -inf", WK_GIBD, c_setpos_minf, HCBD_ERR_NONFINITE, "particle 63|-inf"},
    {"set_positions x 1e20", WK_GIBD, c_setpos_far, HCBD_ERR_PARAM, "particle 2|1e+20"},
    {"set_positions closer than min_distance", WK_MIND, c_setpos_overlap, HCBD_ERR_OVERLAP,
     "3 and 7|0.25|min_distance = 0.5"},
    {"place_lattice n = 65 > capacity", WK_GIBD, c_lattice_65, HCBD_ERR_CAPACITY, "N = 65"},
    {"place_lattice n = 0", WK_GIBD, c_lattice_0, HCBD_ERR_PARAM, "N = 0"},
    {"place_lattice w NULL", WK_GIBD, c_lattice_nullw, HCBD_ERR_NULL, NULL},
    {"place_random n = -5", WK_GIBD, c_random_m5, HCBD_ERR_PARAM, "N = -5"},
    {"place_random n = 65 > capacity", WK_GIBD, c_random_65, HCBD_ERR_CAPACITY, "N = 65"},
    {"place_random w NULL", WK_GIBD, c_random_nullw, HCBD_ERR_NULL, NULL},
    {"set_velocities v NULL", WK_GIBD, c_setvel_null, HCBD_ERR_NULL, "velocities"},
    {"set_velocities w NULL", WK_GIBD, c_setvel_nullw, HCBD_ERR_NULL, NULL},
    {"set_velocities x NaN", WK_GIBD, c_setvel_nan, HCBD_ERR_NONFINITE, "particle 2|nan"},
    {"set_velocities z -inf", WK_GIBD, c_setvel_inf, HCBD_ERR_NONFINITE, "particle 63|-inf"},
    {"set_velocities in BD", WK_BD, c_setvel_zero, HCBD_ERR_STATE, "BD"},
    {"step without particles", WK_EMPTY, c_step_1, HCBD_ERR_STATE, "no particles"},
    {"world_get_positions xyz NULL", WK_GIBD, c_getpos_null, HCBD_ERR_NULL, NULL},
    {"world_get_positions w NULL", WK_GIBD, c_getpos_nullw, HCBD_ERR_NULL, NULL},
    {"get_velocities v NULL", WK_GIBD, c_getvel_null, HCBD_ERR_NULL, NULL},
    {"virial_stress s NULL", WK_GIBD, c_stress_null, HCBD_ERR_NULL, "s is NULL"},
    {"virial_stress w NULL", WK_GIBD, c_stress_nullw, HCBD_ERR_NULL, NULL},
    {"friction_average nk = 0", WK_GIBD, c_fric_nk0, HCBD_ERR_PARAM, "nk = 0"},
    {"friction_average nk = -1", WK_GIBD, c_fric_nkm1, HCBD_ERR_PARAM, "nk = -1"},
    {"friction_average out NULL", WK_GIBD, c_fric_null, HCBD_ERR_NULL, "out is NULL"},
    {"friction_average in BD", WK_BD, c_fric_ok, HCBD_ERR_STATE, "GI-BD"},
    {"rdf_init rmax = 0", WK_GIBD, c_rdf_r0, HCBD_ERR_PARAM, NULL},
    {"rdf_init rmax = -1", WK_GIBD, c_rdf_rm1, HCBD_ERR_PARAM, NULL},
    {"rdf_init rmax = nan", WK_GIBD, c_rdf_rnan, HCBD_ERR_PARAM, NULL},
    {"rdf_init rmax = inf", WK_GIBD, c_rdf_rinf, HCBD_ERR_PARAM, NULL},
    {"rdf_init nbins = 0", WK_GIBD, c_rdf_nb0, HCBD_ERR_PARAM, NULL},
    {"rdf_init nbins = -1", WK_GIBD, c_rdf_nbm1, HCBD_ERR_PARAM, NULL},
    {"rdf_init g NULL", WK_GIBD, c_rdf_nullg, HCBD_ERR_NULL, NULL},
    {"rdf_init hist NULL", WK_GIBD, c_rdf_nullh, HCBD_ERR_NULL, NULL},
    {"rdf_sample rmax = 7 > L/2", WK_GIBD, c_rdf_big, HCBD_ERR_PARAM, "rmax = 7"},
    {"rdf_sample g NULL", WK_GIBD, c_rdf_sample_nullg, HCBD_ERR_NULL, "g is NULL"},
    {"rdf_sample without particles", WK_EMPTY, c_rdf_empty, HCBD_ERR_STATE, "particles"},
    {"rdf_init block = -1", WK_GIBD, c_rdf_blockm1, HCBD_ERR_PARAM, NULL},
    {"rdf_init with blocks, bytes too few", WK_GIBD, c_rdf_blockshort, HCBD_ERR_MEMORY, NULL},
    {"rdf_coordination rc > rmax", WK_GIBD, c_coord_big, HCBD_ERR_PARAM, NULL},
    {"rdf_coordination rc < 0", WK_GIBD, c_coord_neg, HCBD_ERR_PARAM, NULL},
    {"rdf_coordination rc = nan", WK_GIBD, c_coord_nan, HCBD_ERR_PARAM, NULL},
    {"rdf_coordination before a sample", WK_GIBD, c_coord_empty, HCBD_ERR_STATE, NULL},
    {"rdf_coordination nc NULL", WK_GIBD, c_coord_null, HCBD_ERR_NULL, NULL},
    {"mtcorr_init nch = 0", WK_GIBD, c_mt_nch0, HCBD_ERR_PARAM, NULL},
    {"mtcorr_init p = 1", WK_GIBD, c_mt_p1, HCBD_ERR_PARAM, NULL},
    {"mtcorr_init m = 1", WK_GIBD, c_mt_m1, HCBD_ERR_PARAM, NULL},
    {"mtcorr_init p % m != 0", WK_GIBD, c_mt_pmod, HCBD_ERR_PARAM, NULL},
    {"mtcorr_init levels = 0", WK_GIBD, c_mt_lev0, HCBD_ERR_PARAM, NULL},
    {"mtcorr_init c NULL", WK_GIBD, c_mt_nullc, HCBD_ERR_NULL, NULL},
    {"mtcorr_init mem NULL", WK_GIBD, c_mt_nullmem, HCBD_ERR_NULL, NULL},
    {"mtcorr_init bytes too few", WK_GIBD, c_mt_short, HCBD_ERR_MEMORY, NULL},
    {"msd_init n = 0", WK_GIBD, c_msd_n0, HCBD_ERR_PARAM, NULL},
    {"msd_init B = 1", WK_GIBD, c_msd_B1, HCBD_ERR_PARAM, NULL},
    {"msd_init levels = 0", WK_GIBD, c_msd_lev0, HCBD_ERR_PARAM, NULL},
    {"msd_init B^levels > int64", WK_GIBD, c_msd_span, HCBD_ERR_PARAM, NULL},
    {"msd_init d NULL", WK_GIBD, c_msd_nulld, HCBD_ERR_NULL, NULL},
    {"msd_init mem NULL", WK_GIBD, c_msd_nullmem, HCBD_ERR_NULL, NULL},
    {"msd_init bytes too few", WK_GIBD, c_msd_short, HCBD_ERR_MEMORY, NULL},
    {"msd_init dense = -1", WK_GIBD, c_msd_densem1, HCBD_ERR_PARAM, NULL},
    {"msd_init block = -1", WK_GIBD, c_msd_blockm1, HCBD_ERR_PARAM, NULL},
    {"msd_init B = 1000, dense = 3 (slots overflow)", WK_GIBD, c_msd_dense_big, HCBD_ERR_PARAM, NULL},
    {"msd_diffusion lag_min > lag_max", WK_GIBD, c_msd_window, HCBD_ERR_PARAM, NULL},
    {"msd_diffusion lag_min = nan", WK_GIBD, c_msd_window_nan, HCBD_ERR_PARAM, NULL},
    {"msd_diffusion one lag in the window", WK_GIBD, c_msd_one_lag, HCBD_ERR_STATE, NULL},
    {"msd_diffusion before a block closes", WK_GIBD, c_msd_no_block, HCBD_ERR_STATE, NULL},
    {"profile_init nslab = 0", WK_GIBD, c_prof_ns0, HCBD_ERR_PARAM, NULL},
    {"profile_init nslab = 2^20 + 1", WK_GIBD, c_prof_nsbig, HCBD_ERR_PARAM, NULL},
    {"profile_init block = 0", WK_GIBD, c_prof_bl0, HCBD_ERR_PARAM, NULL},
    {"profile_init pr NULL", WK_GIBD, c_prof_nullpr, HCBD_ERR_NULL, NULL},
    {"profile_init w NULL", WK_GIBD, c_prof_nullw, HCBD_ERR_NULL, NULL},
    {"profile_init mem NULL", WK_GIBD, c_prof_nullmem, HCBD_ERR_NULL, NULL},
    {"profile_init bytes too few", WK_GIBD, c_prof_short, HCBD_ERR_MEMORY, NULL},
    {"slabs_init nslab = 0", WK_GIBD, c_slabs_ns0, HCBD_ERR_PARAM, NULL},
    {"slabs_init nval = -1", WK_GIBD, c_slabs_nvm1, HCBD_ERR_PARAM, NULL},
    {"slabs_init nval = 65", WK_GIBD, c_slabs_nv65, HCBD_ERR_PARAM, NULL},
    {"slabs_init block = 0", WK_GIBD, c_slabs_bl0, HCBD_ERR_PARAM, NULL},
    {"slabs_init L[1] = nan", WK_GIBD, c_slabs_Lnan, HCBD_ERR_PARAM, NULL},
    {"slabs_init L[1] = -1", WK_GIBD, c_slabs_Lneg, HCBD_ERR_PARAM, NULL},
    {"slabs_init L[1] = inf", WK_GIBD, c_slabs_Linf, HCBD_ERR_PARAM, NULL},
    {"slabs_init L NULL", WK_GIBD, c_slabs_nullL, HCBD_ERR_NULL, NULL},
    {"slabs_init bytes too few", WK_GIBD, c_slabs_short, HCBD_ERR_MEMORY, NULL},
    {"carreau_fit good curve", WK_GIBD, c_car_ok, HCBD_OK, NULL},
    {"carreau_fit n_points = 3", WK_GIBD, c_car_n3, HCBD_ERR_PARAM, NULL},
    {"carreau_fit n_points = 0", WK_GIBD, c_car_n0, HCBD_ERR_PARAM, NULL},
    {"carreau_fit gdot[2] = -1", WK_GIBD, c_car_gneg, HCBD_ERR_PARAM, NULL},
    {"carreau_fit gdot[2] = 0", WK_GIBD, c_car_g0, HCBD_ERR_PARAM, NULL},
    {"carreau_fit gdot[2] = inf", WK_GIBD, c_car_ginf, HCBD_ERR_PARAM, NULL},
    {"carreau_fit gdot[2] = nan", WK_GIBD, c_car_gnan, HCBD_ERR_PARAM, NULL},
    {"carreau_fit eta[3] = nan", WK_GIBD, c_car_etanan, HCBD_ERR_PARAM, NULL},
    {"carreau_fit err[1] = 0", WK_GIBD, c_car_err0, HCBD_ERR_PARAM, NULL},
    {"carreau_fit err[1] = -0.1", WK_GIBD, c_car_errneg, HCBD_ERR_PARAM, NULL},
    {"carreau_fit eta_inf = nan", WK_GIBD, c_car_einfnan, HCBD_ERR_PARAM, NULL},
    {"carreau_fit eta_inf = inf", WK_GIBD, c_car_einfinf, HCBD_ERR_PARAM, NULL},
    {"carreau_fit start p[0] = nan", WK_GIBD, c_car_p0nan, HCBD_ERR_PARAM, NULL},
    {"carreau_fit start p[1] = -1", WK_GIBD, c_car_p1neg, HCBD_ERR_PARAM, NULL},
    {"carreau_fit start p[1] = 0", WK_GIBD, c_car_p1zero, HCBD_ERR_PARAM, NULL},
    {"carreau_fit start p[2] = inf", WK_GIBD, c_car_p2inf, HCBD_ERR_PARAM, NULL},
    {"carreau_fit gdot NULL", WK_GIBD, c_car_nullg, HCBD_ERR_NULL, NULL},
    {"carreau_fit p NULL", WK_GIBD, c_car_nullp, HCBD_ERR_NULL, NULL},
    {"stability p NULL", WK_GIBD, c_stab_nullp, HCBD_ERR_NULL, NULL},
    {"stability out NULL", WK_GIBD, c_stab_nullout, HCBD_ERR_NULL, NULL},
    {"stability n NULL", WK_GIBD, c_stab_nulln, HCBD_ERR_NULL, NULL},
    {"stability of a valid BD scene", WK_BD, c_stab_ok, HCBD_OK, NULL},
    {"theory_of p NULL", WK_GIBD, c_theory_nullp, HCBD_ERR_NULL, NULL},
    {"theory_of t NULL", WK_GIBD, c_theory_nullt, HCBD_ERR_NULL, NULL},
#if HCBD_MODEL == HCBD_MODEL_WALLED
    {"set_positions particle 5 inside the bottom wall", WK_WALL, c_setpos_wall, HCBD_ERR_WALL,
     "particle 5|y = 0.5|inside a wall"},
    {"set_positions particle 0 inside the top wall", WK_WALL, c_setpos_wall_top, HCBD_ERR_WALL,
     "particle 0|y = 12|inside a wall"},
#endif
};

static void bi_gsnap(const void *v, bi_snap *s)
{
    const hcbd_world *w = (const hcbd_world *)v;
    memset(s, 0, sizeof *s);
    s->sum = hcbd_world_checksum(w);
    s->n[0] = w->n;
    s->step = w->step;
    memcpy(s->p, &w->p, sizeof w->p);
}

#if HCBD_MODEL == HCBD_MODEL_HCBD
/* ---- the 2018 world ---------------------------------------------------- */
#define HD(f, v) {#f, offsetof(hcbd_hc_world_def, params.f), 'd', (v), NULL}
#define HI(f, v) {#f, offsetof(hcbd_hc_world_def, params.f), 'i', (v), NULL}
#define HE(f, v) {#f, offsetof(hcbd_hc_world_def, params.f), 'e', (v), NULL}
#define HW(f, v) {#f, offsetof(hcbd_hc_world_def, f), 'i', (v), NULL}

enum { HB_DEF, HB_RP, HB_NBASE };
static const char *bi_hbase_name[HB_NBASE] = {"", "reverse-Poiseuille "};

/* the reduced scene of test.h on a 5 x 5 x 5 lattice */
static hcbd_hc_world_def bi_hc_base(int base)
{
    hcbd_hc_world_def d = hc_scene(5, 5, 5, 200);
    if (base == HB_RP) d.params.reverse_poiseuille = 1;
    return d;
}

static const bi_pentry bi_hparams[] = {
    {HB_DEF, NOSET, HD(L[0], 4), HCBD_ERR_BOX, NULL}, /* < 2 max(2h, rc) */
    {HB_DEF, NOSET, HD(L[2], 7.5), HCBD_ERR_BOX, NULL},
    {HB_DEF, NOSET, HD(rho, 0), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(rho, -1), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(rho, NAN), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(rho, INFINITY), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(nbar, 0), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(nbar, NAN), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(nbar, INFINITY), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(eta, -1), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(eta, NAN), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(eta, INFINITY), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(P0, -1), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(P0, NAN), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(h, 0), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(h, -1), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(h, NAN), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(h, INFINITY), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(h, 2.5), HCBD_ERR_BOX, "2h = 5"},
    {HB_DEF, NOSET, HI(fluctuations, 2), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HI(fluctuations, -1), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(g[0], NAN), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(g[2], INFINITY), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HI(reverse_poiseuille, 2), HCBD_ERR_PARAM, NULL},
    {HB_RP, NOSET, HD(gdot, 1), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(gdot, 1000000), HCBD_ERR_PARAM, NULL}, /* offset > L per step */
    {HB_DEF, NOSET, HD(rc, 0), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(rc, -1), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(rc, NAN), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(rc, INFINITY), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(rc, 4.5), HCBD_ERR_BOX, "rc = 4.5"},
    {HB_DEF, NOSET, HD(sigma, 2.5), HCBD_ERR_PARAM, NULL}, /* = rc */
    {HB_DEF, NOSET, HD(alpha, -1), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(alpha, NAN), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(alpha, INFINITY), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(tau_lambda, 0), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(tau_lambda, -1), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(tau_lambda, NAN), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(tau_lambda, INFINITY), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(p_kuhn, -1), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(p_kuhn, NAN), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(p_kuhn, INFINITY), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(n_max, 0), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(n_max, -1), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(n_max, NAN), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(n_max, INFINITY), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(chi, NAN), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HD(chi, INFINITY), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HE(coupling, 2), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HE(coupling, -1), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HI(substeps, 0), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HI(substeps, 1001), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HW(fluid_capacity, 1), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HW(fluid_capacity, -1), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HW(fluid_capacity, 268435457), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HW(polymer_capacity, -1), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HW(polymer_capacity, 268435457), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HW(pair_capacity, -2), HCBD_ERR_PARAM, NULL},
    {HB_DEF, NOSET, HW(pair_capacity, 1048577), HCBD_ERR_PARAM, NULL},
};

enum { HK_FP, HK_EMPTY, HK_HOLE, HK_NMAX };

static int bi_hmake(hcbd_hc_world *w, int kind)
{
    hcbd_hc_world_def d = bi_hc_base(HB_DEF);
    hcbd_result r = HCBD_OK;
    if (kind == HK_NMAX) d.params.n_max = 1e6;
    if (hcbd_hc_world_create(w, &d) != HCBD_OK) {
        printf("    hc world: %s\n", w->err.msg);
        return 0;
    }
    if (kind == HK_EMPTY) return 1;
    if (kind == HK_HOLE) {
        /* fluid only where x < L/2; polymers among it */
        double f[3 * 125], p[3 * 5];
        int i, k = 0;
        const double L = d.params.L[0];
        for (i = 0; i < 125 && k < 60; ++i) {
            f[3 * k] = 0.5 * L * ((i % 5) + 0.5) / 5;
            f[3 * k + 1] = L * ((i / 5 % 5) + 0.5) / 5;
            f[3 * k + 2] = L * ((i / 25) + 0.5) / 5;
            ++k;
        }
        for (i = 0; i < 5; ++i) {
            p[3 * i] = 0.1 * L + 0.05 * L * i;
            p[3 * i + 1] = 0.2 * L * i + 0.1;
            p[3 * i + 2] = 0.5 * L;
        }
        r = hcbd_hc_world_set_fluid(w, k, f, NULL);
        if (r == HCBD_OK) r = hcbd_hc_world_set_polymers(w, 5, p);
    } else {
        r = hcbd_hc_world_place_fluid_lattice(w, 125);
        if (r == HCBD_OK) r = hcbd_hc_world_place_polymers_random(w, 20);
        if (r == HCBD_OK) r = hcbd_hc_world_step(w, 2);
    }
    if (r != HCBD_OK) {
        printf("    hc set-up: %s\n", w->err.msg);
        hcbd_hc_world_destroy(w);
        return 0;
    }
    return 1;
}

/* a call on an HCBD world */
#define HF(f)                                                                  \
    static hcbd_result f##_(hcbd_hc_world *w, const char **msg);               \
    static hcbd_result f(const bi_kind *K, void *w, const char **msg)          \
    {                                                                          \
        (void)K;                                                               \
        return f##_((hcbd_hc_world *)w, msg);                                  \
    }                                                                          \
    static hcbd_result f##_(hcbd_hc_world *w, const char **msg)

static void bi_fluid_xyz(const hcbd_hc_world *w, double *x, int n)
{
    int i;
    for (i = 0; i < n; ++i) {
        x[3 * i] = w->fx[i % w->nf];
        x[3 * i + 1] = w->fy[i % w->nf];
        x[3 * i + 2] = w->fz[i % w->nf];
    }
}
static hcbd_result bi_setfluid(hcbd_hc_world *w, int n, int i, double v, int vel)
{
    static double x[3 * 130], u[3 * 130];
    bi_fluid_xyz(w, x, n < 130 ? (n > 0 ? n : 0) : 130);
    memset(u, 0, sizeof u);
    if (i >= 0 && !vel) x[i] = v;
    if (i >= 0 && vel) u[i] = v;
    return hcbd_hc_world_set_fluid(w, n, x, vel ? u : NULL);
}
HF(h_fl_nullw) { (void)w; *msg = NULL; return hcbd_hc_world_set_fluid(NULL, 2, bi_xyz, NULL); }
HF(h_fl_null) { (void)msg; return hcbd_hc_world_set_fluid(w, 125, NULL, NULL); }
HF(h_fl_1) { (void)msg; return bi_setfluid(w, 1, -1, 0, 0); }
HF(h_fl_m1) { (void)msg; return bi_setfluid(w, -1, -1, 0, 0); }
HF(h_fl_126) { (void)msg; return bi_setfluid(w, 126, -1, 0, 0); }
HF(h_fl_nan) { (void)msg; return bi_setfluid(w, 125, 3 * 4 + 1, NAN, 0); }
HF(h_fl_out) { (void)msg; return bi_setfluid(w, 125, 3 * 4, w->p.L[0], 0); }
HF(h_fl_neg) { (void)msg; return bi_setfluid(w, 125, 3 * 4 + 2, -0.5, 0); }
HF(h_fl_vnan) { (void)msg; return bi_setfluid(w, 125, 3 * 3, NAN, 1); }
HF(h_lat_126) { (void)msg; return hcbd_hc_world_place_fluid_lattice(w, 126); }
HF(h_lat_0) { (void)msg; return hcbd_hc_world_place_fluid_lattice(w, 0); }
HF(h_lat_nullw) { (void)w; *msg = NULL; return hcbd_hc_world_place_fluid_lattice(NULL, 8); }
static hcbd_result bi_setpoly(hcbd_hc_world *w, int n, int i, double v)
{
    static double x[3 * 210];
    int k;
    for (k = 0; k < 3 * 210; ++k) x[k] = 0.5 + 0.01 * (k % 7); /* a fluid region */
    for (k = 0; k < 20 && k < n; ++k) {
        x[3 * k] = w->px[k];
        x[3 * k + 1] = w->py[k];
        x[3 * k + 2] = w->pz[k];
    }
    if (i >= 0) x[i] = v;
    return hcbd_hc_world_set_polymers(w, n, x);
}
HF(h_po_201) { (void)msg; return bi_setpoly(w, 201, -1, 0); }
HF(h_po_m1) { (void)msg; return bi_setpoly(w, -1, -1, 0); }
HF(h_po_null) { (void)msg; return hcbd_hc_world_set_polymers(w, 5, NULL); }
HF(h_po_nullw) { (void)w; *msg = NULL; return hcbd_hc_world_set_polymers(NULL, 0, NULL); }
HF(h_po_nan) { (void)msg; return bi_setpoly(w, 20, 3 * 2 + 1, NAN); }
HF(h_po_out) { (void)msg; return bi_setpoly(w, 20, 3 * 2, -0.25); }
HF(h_po_dense)
{
    /* 200 polymers in one spot: phi = n/n_max >= 1 */
    (void)msg;
    return bi_setpoly(w, 200, -1, 0);
}
HF(h_po_pairs)
{
    /* 100 polymers in one spot with n_max huge: more partners than
       pair_capacity */
    (void)msg;
    return bi_setpoly(w, 100, -1, 0);
}
HF(h_po_nofluid)
{
    /* the five polymers of the world plus one where there is no fluid */
    double x[3 * 6];
    int k;
    (void)msg;
    for (k = 0; k < 5; ++k) {
        x[3 * k] = w->px[k];
        x[3 * k + 1] = w->py[k];
        x[3 * k + 2] = w->pz[k];
    }
    /* the fluid fills 0.05 L <= x <= 0.45 L and z <= 0.5 L */
    x[15] = 0.75 * w->p.L[0];
    x[16] = 0.5 * w->p.L[1];
    x[17] = 0.8 * w->p.L[2];
    return hcbd_hc_world_set_polymers(w, 6, x);
}
HF(h_prand_201) { (void)msg; return hcbd_hc_world_place_polymers_random(w, 201); }
HF(h_prand_m1) { (void)msg; return hcbd_hc_world_place_polymers_random(w, -1); }
HF(h_prand_nullw) { (void)w; *msg = NULL; return hcbd_hc_world_place_polymers_random(NULL, 1); }
HF(h_po_empty) { double x[3] = {1, 1, 1}; (void)msg; return hcbd_hc_world_set_polymers(w, 1, x); }
HF(h_prand_empty) { (void)msg; return hcbd_hc_world_place_polymers_random(w, 1); }
HF(h_refresh_empty) { (void)msg; return hcbd_hc_world_refresh(w); }
HF(h_refresh_nullw) { (void)w; *msg = NULL; return hcbd_hc_world_refresh(NULL); }
HF(h_step_empty) { (void)msg; return hcbd_hc_world_step(w, 1); }
/* pair variables: a pair that exists and one that does not */
static int bi_pair(const hcbd_hc_world *w, int exists, int *b)
{
    int k;
    for (k = 1; k < w->np; ++k) {
        double l;
        if ((hcbd_hc_world_get_lambda(w, 0, k, &l) == HCBD_OK) == exists) {
            *b = k;
            return 1;
        }
    }
    return 0;
}
HF(h_lam_nullout) { int b = 1; *msg = NULL; bi_pair(w, 1, &b); return hcbd_hc_world_get_lambda(w, 0, b, NULL); }
HF(h_lam_nullw) { double l; (void)w; *msg = NULL; return hcbd_hc_world_get_lambda(NULL, 0, 1, &l); }
HF(h_lam_am1) { double l; *msg = NULL; return hcbd_hc_world_get_lambda(w, -1, 1, &l); }
HF(h_lam_bnp) { double l; *msg = NULL; return hcbd_hc_world_get_lambda(w, 0, w->np, &l); }
HF(h_lam_aa) { double l; *msg = NULL; return hcbd_hc_world_get_lambda(w, 3, 3, &l); }
HF(h_lam_none)
{
    double l;
    int b = -1;
    *msg = NULL;
    if (!bi_pair(w, 0, &b)) return HCBD_ERR_MODEL; /* the test world has no such pair */
    return hcbd_hc_world_get_lambda(w, 0, b, &l);
}
HF(h_slam_nan)
{
    int b = -1;
    (void)msg;
    if (!bi_pair(w, 1, &b)) return HCBD_ERR_MODEL;
    return hcbd_hc_world_set_lambda(w, 0, b, NAN);
}
HF(h_slam_inf)
{
    int b = -1;
    (void)msg;
    if (!bi_pair(w, 1, &b)) return HCBD_ERR_MODEL;
    return hcbd_hc_world_set_lambda(w, 0, b, -INFINITY);
}
HF(h_slam_am1) { (void)msg; return hcbd_hc_world_set_lambda(w, -1, 1, 0.5); }
HF(h_slam_b20) { (void)msg; return hcbd_hc_world_set_lambda(w, 0, 20, 0.5); }
HF(h_slam_aa) { (void)msg; return hcbd_hc_world_set_lambda(w, 3, 3, 0.5); }
HF(h_slam_none)
{
    int b = -1;
    (void)msg;
    if (!bi_pair(w, 0, &b)) return HCBD_ERR_MODEL;
    return hcbd_hc_world_set_lambda(w, 0, b, 0.5);
}
HF(h_slam_nullw) { (void)w; *msg = NULL; return hcbd_hc_world_set_lambda(NULL, 0, 1, 0.5); }
HF(h_dr_null) { *msg = NULL; return hcbd_hc_world_density_range(w, NULL); }
HF(h_dr_empty) { double o[3]; *msg = NULL; return hcbd_hc_world_density_range(w, o); }
static hcbd_result bi_htheory(int what, double v)
{
    hcbd_hc_world_def d = bi_hc_base(HB_DEF);
    hcbd_hc_theory t;
    if (what == 1) d.params.eta = v;
    if (what == 2) d.params.rho = v;
    if (what == 3) d.params.P0 = v;
    if (what == 4) d.params.g[0] = v;
    if (what == 5) return hcbd_hc_params_theory(NULL, &t);
    if (what == 6) return hcbd_hc_params_theory(&d.params, NULL);
    return hcbd_hc_params_theory(&d.params, &t);
}
HF(h_th_eta) { (void)w; *msg = NULL; return bi_htheory(1, NAN); }
HF(h_th_etaneg) { (void)w; *msg = NULL; return bi_htheory(1, -1); }
HF(h_th_rho) { (void)w; *msg = NULL; return bi_htheory(2, INFINITY); }
HF(h_th_P0) { (void)w; *msg = NULL; return bi_htheory(3, -1); }
HF(h_th_g) { (void)w; *msg = NULL; return bi_htheory(4, NAN); }
HF(h_th_nullp) { (void)w; *msg = NULL; return bi_htheory(5, 0); }
HF(h_th_nullt) { (void)w; *msg = NULL; return bi_htheory(6, 0); }
HF(h_stab_null) { int n; (void)w; *msg = NULL; return hcbd_hc_params_stability(&w->p, NULL, &n); }
static hcbd_result bi_si(int what, double v)
{
    hcbd_hc_si si = hcbd_hc_si_default();
    hcbd_hc_params p;
    double tu = 1e-6;
    strcpy(bi_msg, "(untouched)");
    if (what == 1) tu = v;
    if (what == 2) si.sigma = v;
    if (what == 3) si.T = v;
    if (what == 4) si.rho = v;
    if (what == 5) si.dt = v;
    if (what == 6) return hcbd_hc_si_params(NULL, tu, &p, bi_msg, sizeof bi_msg);
    return hcbd_hc_si_params(&si, tu, &p, bi_msg, sizeof bi_msg);
}
HF(h_si_tu0) { (void)w; *msg = bi_msg; return bi_si(1, 0); }
HF(h_si_tunan) { (void)w; *msg = bi_msg; return bi_si(1, NAN); }
HF(h_si_sigma) { (void)w; *msg = bi_msg; return bi_si(2, NAN); }
HF(h_si_T) { (void)w; *msg = bi_msg; return bi_si(3, -1); }
HF(h_si_rho) { (void)w; *msg = bi_msg; return bi_si(4, INFINITY); }
HF(h_si_dt) { (void)w; *msg = bi_msg; return bi_si(5, 0); }
HF(h_si_null) { (void)w; *msg = bi_msg; return bi_si(6, 0); }

static const bi_call bi_hcalls[] = {
    {"set_fluid w NULL", HK_FP, h_fl_nullw, HCBD_ERR_NULL, NULL},
    {"set_fluid xyz NULL", HK_FP, h_fl_null, HCBD_ERR_NULL, "xyz is NULL"},
    {"set_fluid n = 1", HK_FP, h_fl_1, HCBD_ERR_PARAM, "N = 1"},
    {"set_fluid n = -1", HK_FP, h_fl_m1, HCBD_ERR_PARAM, "N = -1"},
    {"set_fluid n = 126 > capacity", HK_FP, h_fl_126, HCBD_ERR_CAPACITY, "N = 126"},
    {"set_fluid y NaN", HK_FP, h_fl_nan, HCBD_ERR_NONFINITE, "fluid blob 4|nan"},
    {"set_fluid x = L", HK_FP, h_fl_out, HCBD_ERR_PARAM, "fluid blob 4|outside the box"},
    {"set_fluid z = -0.5", HK_FP, h_fl_neg, HCBD_ERR_PARAM, "fluid blob 4|-0.5"},
    {"set_fluid v NaN", HK_FP, h_fl_vnan, HCBD_ERR_NONFINITE, "fluid blob 3|nan"},
    {"place_fluid_lattice n = 126 > capacity", HK_FP, h_lat_126, HCBD_ERR_CAPACITY, "N = 126"},
    {"place_fluid_lattice n = 0", HK_FP, h_lat_0, HCBD_ERR_PARAM, "N = 0"},
    {"place_fluid_lattice w NULL", HK_FP, h_lat_nullw, HCBD_ERR_NULL, NULL},
    {"set_polymers n = 201 > capacity", HK_FP, h_po_201, HCBD_ERR_CAPACITY, "N = 201"},
    {"set_polymers n = -1", HK_FP, h_po_m1, HCBD_ERR_PARAM, "N = -1"},
    {"set_polymers xyz NULL", HK_FP, h_po_null, HCBD_ERR_NULL, "xyz is NULL"},
    {"set_polymers w NULL", HK_FP, h_po_nullw, HCBD_ERR_NULL, NULL},
    {"set_polymers y NaN", HK_FP, h_po_nan, HCBD_ERR_NONFINITE, "polymer blob 2|nan"},
    {"set_polymers x = -0.25", HK_FP, h_po_out, HCBD_ERR_PARAM, "polymer blob 2|-0.25"},
    {"set_polymers phi >= 1", HK_FP, h_po_dense, HCBD_ERR_PARAM, "phi|>= 1"},
    {"set_polymers more partners than pair_capacity", HK_NMAX, h_po_pairs, HCBD_ERR_CAPACITY,
     "pair_capacity"},
    {"set_polymers polymer without fluid within rc", HK_HOLE, h_po_nofluid, HCBD_ERR_PARAM,
     "polymer 5|no fluid blob within rc = 2.5"},
    {"place_polymers_random n = 201 > capacity", HK_FP, h_prand_201, HCBD_ERR_CAPACITY, "N = 201"},
    {"place_polymers_random n = -1", HK_FP, h_prand_m1, HCBD_ERR_PARAM, "N = -1"},
    {"place_polymers_random w NULL", HK_FP, h_prand_nullw, HCBD_ERR_NULL, NULL},
    {"set_polymers before the fluid", HK_EMPTY, h_po_empty, HCBD_ERR_STATE, "fluid"},
    {"place_polymers_random before the fluid", HK_EMPTY, h_prand_empty, HCBD_ERR_STATE, "fluid"},
    {"refresh before the fluid", HK_EMPTY, h_refresh_empty, HCBD_ERR_STATE, "fluid"},
    {"refresh w NULL", HK_FP, h_refresh_nullw, HCBD_ERR_NULL, NULL},
    {"step before the fluid", HK_EMPTY, h_step_empty, HCBD_ERR_STATE, "fluid"},
    {"lambda out NULL", HK_FP, h_lam_nullout, HCBD_ERR_NULL, NULL},
    {"lambda w NULL", HK_FP, h_lam_nullw, HCBD_ERR_NULL, NULL},
    {"lambda a = -1", HK_FP, h_lam_am1, HCBD_ERR_PARAM, NULL},
    {"lambda b = np", HK_FP, h_lam_bnp, HCBD_ERR_PARAM, NULL},
    {"lambda a = b", HK_FP, h_lam_aa, HCBD_ERR_PARAM, NULL},
    {"lambda of a pair that does not exist", HK_FP, h_lam_none, HCBD_ERR_STATE, NULL},
    {"set_lambda lambda = nan", HK_FP, h_slam_nan, HCBD_ERR_NONFINITE, "lambda = nan"},
    {"set_lambda lambda = -inf", HK_FP, h_slam_inf, HCBD_ERR_NONFINITE, "lambda = -inf"},
    {"set_lambda a = -1", HK_FP, h_slam_am1, HCBD_ERR_PARAM, "a = -1"},
    {"set_lambda b = 20 = np", HK_FP, h_slam_b20, HCBD_ERR_PARAM, "b = 20"},
    {"set_lambda a = b", HK_FP, h_slam_aa, HCBD_ERR_PARAM, "a = 3|b = 3"},
    {"set_lambda of a pair that does not exist", HK_FP, h_slam_none, HCBD_ERR_STATE,
     "no pair variable"},
    {"set_lambda w NULL", HK_FP, h_slam_nullw, HCBD_ERR_NULL, NULL},
    {"density_range out NULL", HK_FP, h_dr_null, HCBD_ERR_NULL, NULL},
    {"density_range before the fluid", HK_EMPTY, h_dr_empty, HCBD_ERR_STATE, NULL},
    {"theory_of eta = nan", HK_FP, h_th_eta, HCBD_ERR_PARAM, NULL},
    {"theory_of eta = -1", HK_FP, h_th_etaneg, HCBD_ERR_PARAM, NULL},
    {"theory_of rho = inf", HK_FP, h_th_rho, HCBD_ERR_PARAM, NULL},
    {"theory_of P0 = -1", HK_FP, h_th_P0, HCBD_ERR_PARAM, NULL},
    {"theory_of g[0] = nan", HK_FP, h_th_g, HCBD_ERR_PARAM, NULL},
    {"theory_of p NULL", HK_FP, h_th_nullp, HCBD_ERR_NULL, NULL},
    {"theory_of t NULL", HK_FP, h_th_nullt, HCBD_ERR_NULL, NULL},
    {"stability out NULL", HK_FP, h_stab_null, HCBD_ERR_NULL, NULL},
    {"params_si time_unit = 0", HK_FP, h_si_tu0, HCBD_ERR_PARAM, "time_unit = 0"},
    {"params_si time_unit = nan", HK_FP, h_si_tunan, HCBD_ERR_PARAM, "time_unit = nan"},
    {"params_si si.sigma = nan", HK_FP, h_si_sigma, HCBD_ERR_PARAM, "sigma = nan"},
    {"params_si si.T = -1", HK_FP, h_si_T, HCBD_ERR_PARAM, "T = -1"},
    {"params_si si.rho = inf", HK_FP, h_si_rho, HCBD_ERR_PARAM, "rho = inf"},
    {"params_si si.dt = 0", HK_FP, h_si_dt, HCBD_ERR_PARAM, "dt = 0"},
    {"params_si si NULL", HK_FP, h_si_null, HCBD_ERR_NULL, "si"},
};

static void bi_hsnap(const void *v, bi_snap *s)
{
    const hcbd_hc_world *w = (const hcbd_hc_world *)v;
    memset(s, 0, sizeof *s);
    s->sum = hcbd_hc_world_checksum(w);
    s->n[0] = w->nf;
    s->n[1] = w->np;
    s->step = w->step;
    memcpy(s->p, &w->p, sizeof w->p);
}
#endif /* HCBD_MODEL_HCBD */

/* ---- checkpoints, trajectories ---------------------------------------- */
static unsigned char bi_ck[1 << 20];
static size_t bi_ck_n;

#define BF(f) static hcbd_result f(const bi_kind *K, void *w, const char **msg)
/* a checkpoint of size bytes at buf loaded into a fresh world of K */
static hcbd_result bi_load_buf(const bi_kind *K, const void *buf, size_t size)
{
    void *v = calloc(1, K->world_size);
    hcbd_result r = HCBD_ERR_MEMORY;
    if (!v) return r;
    r = K->ck_load(v, buf, size);
    snprintf(bi_msg, sizeof bi_msg, "%s", K->err(v)->msg);
    if (r == HCBD_OK) K->destroy(v);
    free(v);
    return r;
}
/* a real checkpoint of the test world, spoilt as asked */
static hcbd_result bi_ck_take(const bi_kind *K, void *w)
{
    bi_ck_n = K->ck_size(w);
    if (bi_ck_n == 0 || bi_ck_n > sizeof bi_ck) return HCBD_ERR_MEMORY;
    return K->ck_save(w, bi_ck, bi_ck_n);
}
static hcbd_result bi_load_path(const bi_kind *K, const char *path)
{
    void *v = calloc(1, K->world_size);
    hcbd_result r = HCBD_ERR_MEMORY;
    if (!v) return r;
    r = K->load(v, path);
    snprintf(bi_msg, sizeof bi_msg, "%s", K->err(v)->msg);
    if (r == HCBD_OK) K->destroy(v);
    free(v);
    return r;
}
BF(io_save_short) { unsigned char b[16]; (void)msg; return K->ck_save(w, b, sizeof b); }
BF(io_save_null) { (void)msg; return K->ck_save(w, NULL, 1 << 16); }
BF(io_save_size0) { unsigned char b[16]; (void)msg; return K->ck_save(w, b, 0); }
BF(io_load_null) { (void)w; *msg = bi_msg; return bi_load_buf(K, NULL, 1 << 16); }
BF(io_load_0) { (void)w; *msg = bi_msg; return bi_load_buf(K, bi_ck, 0); }
BF(io_load_garbage)
{
    static unsigned char g[4096];
    (void)w;
    memset(g, 0xAB, sizeof g);
    *msg = bi_msg;
    return bi_load_buf(K, g, sizeof g);
}
BF(io_load_trunc)
{
    hcbd_result r = bi_ck_take(K, w);
    *msg = bi_msg;
    if (r != HCBD_OK) return HCBD_ERR_MODEL;
    return bi_load_buf(K, bi_ck, bi_ck_n / 2);
}
/* one bit flipped in the middle and one near the end (the trailer) */
BF(io_load_flip)
{
    hcbd_result r = bi_ck_take(K, w);
    *msg = bi_msg;
    if (r != HCBD_OK) return HCBD_ERR_MODEL;
    bi_ck[bi_ck_n / 2] ^= 0x04;
    return bi_load_buf(K, bi_ck, bi_ck_n);
}
BF(io_load_flip_end)
{
    hcbd_result r = bi_ck_take(K, w);
    *msg = bi_msg;
    if (r != HCBD_OK) return HCBD_ERR_MODEL;
    bi_ck[bi_ck_n - 9] ^= 0x10;
    return bi_load_buf(K, bi_ck, bi_ck_n);
}
BF(io_load_missing) { (void)w; *msg = bi_msg; return bi_load_path(K, "/nonexistent-hcbd-dir/missing.chk"); }
BF(io_load_nullpath) { (void)w; *msg = bi_msg; return bi_load_path(K, NULL); }
BF(io_save_baddir) { (void)msg; return K->save(w, "/nonexistent-hcbd-dir/x.chk"); }
BF(io_save_nullpath) { (void)msg; return K->save(w, NULL); }

/* the checkpoint calls of both worlds */
static const bi_call bi_both_io[] = {
    {"checkpoint_save 16-byte buffer", 0, io_save_short, HCBD_ERR_MEMORY, "16"},
    {"checkpoint_save size 0", 0, io_save_size0, HCBD_ERR_MEMORY, "0"},
    {"checkpoint_save buf NULL", 0, io_save_null, HCBD_ERR_NULL, "buf"},
    {"checkpoint_load buf NULL", 0, io_load_null, HCBD_ERR_NULL, "buffer is NULL"},
    {"checkpoint_load size 0", 0, io_load_0, HCBD_ERR_FORMAT, NULL},
    {"checkpoint_load garbage", 0, io_load_garbage, HCBD_ERR_FORMAT, NULL},
    {"checkpoint_load truncated", 0, io_load_trunc, HCBD_ERR_FORMAT, NULL},
    {"checkpoint_load one bit flipped", 0, io_load_flip, HCBD_ERR_FORMAT, NULL},
    {"checkpoint_load one bit flipped near the end", 0, io_load_flip_end, HCBD_ERR_FORMAT, NULL},
    {"load missing file", 0, io_load_missing, HCBD_ERR_IO, "/nonexistent-hcbd-dir/missing.chk"},
    {"load path NULL", 0, io_load_nullpath, HCBD_ERR_NULL, "path"},
    {"save into a missing directory", 0, io_save_baddir, HCBD_ERR_IO, "/nonexistent-hcbd-dir/x.chk"},
    {"save path NULL", 0, io_save_nullpath, HCBD_ERR_NULL, "path"},
};

WF(io_xyz_nullf) { *msg = NULL; return hcbd_world_write_xyz(w, NULL, NULL, 0); }
static hcbd_result bi_xyz_ids(const hcbd_world *w, int id, int nids)
{
    int ids[2] = {0, 0};
    FILE *f = tmpfile();
    hcbd_result r;
    if (!f) return HCBD_ERR_MODEL;
    ids[1] = id;
    r = hcbd_world_write_xyz(w, f, ids, nids);
    fclose(f);
    return r;
}
WF(io_xyz_id64) { *msg = NULL; return bi_xyz_ids(w, 64, 2); }
WF(io_xyz_idm1) { *msg = NULL; return bi_xyz_ids(w, -1, 2); }
WF(io_xyz_nidsm1) { *msg = NULL; return bi_xyz_ids(w, 1, -1); }
WF(io_off_nullf) { *msg = NULL; return hcbd_world_write_offenders(w, NULL); }

static const bi_call bi_iocalls[] = {
    {"xyz_write f NULL", WK_GIBD, io_xyz_nullf, HCBD_ERR_NULL, NULL},
    {"xyz_write ids[1] = 64 = n", WK_GIBD, io_xyz_id64, HCBD_ERR_PARAM, NULL},
    {"xyz_write ids[1] = -1", WK_GIBD, io_xyz_idm1, HCBD_ERR_PARAM, NULL},
    {"xyz_write nids = -1", WK_GIBD, io_xyz_nidsm1, HCBD_ERR_PARAM, NULL},
    {"xyz_offenders f NULL", WK_GIBD, io_off_nullf, HCBD_ERR_NULL, NULL},
};

#if HCBD_MODEL == HCBD_MODEL_HCBD
/* a GI-BD checkpoint handed to the 2018 world */
BF(hio_load_gibd)
{
    hcbd_world g;
    hcbd_result r;
    size_t n;
    (void)w;
    *msg = bi_msg;
    if (!bi_make(&g, WK_GIBD)) return HCBD_ERR_STATE;
    n = hcbd_world_checkpoint_size(&g);
    r = n > 0 && n <= sizeof bi_ck ? hcbd_world_checkpoint_save(&g, bi_ck, n) : HCBD_ERR_MEMORY;
    hcbd_world_destroy(&g);
    if (r != HCBD_OK) return HCBD_ERR_STATE;
    return bi_load_buf(K, bi_ck, n);
}
HF(hio_xyz_nullf) { *msg = NULL; return hcbd_hc_world_write_xyz(w, NULL); }

static const bi_call bi_hiocalls[] = {
    {"checkpoint_load of a GI-BD checkpoint", HK_FP, hio_load_gibd, HCBD_ERR_MODEL, NULL},
    {"xyz_write f NULL", HK_FP, hio_xyz_nullf, HCBD_ERR_NULL, NULL},
};
#endif

/* ---- both worlds: one table of parameters and one of calls -------------- */
/* The parameters both worlds have, spoilt the same way; BI_BOTH_PARAMS(D)
   writes the one table for the definition D of each world. */
#define BD_(D, f, v) {0, NOSET, {#f, offsetof(D, params.f), 'd', (v), NULL}, HCBD_ERR_PARAM, NULL}
#define BI_(D, f, v) {0, NOSET, {#f, offsetof(D, params.f), 'i', (v), NULL}, HCBD_ERR_PARAM, NULL}
#define BE_(D, f, v) {0, NOSET, {#f, offsetof(D, params.f), 'e', (v), NULL}, HCBD_ERR_PARAM, NULL}
#define BI_BOTH_PARAMS(D)                                                                          \
    BD_(D, L[0], NAN), BD_(D, L[1], INFINITY), BD_(D, L[2], -1), BD_(D, L[0], 0), BD_(D, dt, 0),   \
    BD_(D, dt, -1), BD_(D, dt, NAN), BD_(D, dt, INFINITY), BD_(D, kT, -1), BD_(D, kT, NAN),         \
    BD_(D, kT, INFINITY), BD_(D, xi, 0), BD_(D, xi, -1), BD_(D, xi, NAN), BD_(D, xi, INFINITY),     \
    BD_(D, sigma, 0), BD_(D, sigma, -1), BD_(D, sigma, NAN), BD_(D, sigma, INFINITY),               \
    BD_(D, gdot, NAN), BD_(D, gdot, INFINITY), BI_(D, threads, 0), BI_(D, threads, -1),             \
    BI_(D, threads, 1025), BI_(D, guard_every, -1), BE_(D, pair_integrator, 2),                     \
    BE_(D, pair_integrator, -1)

BF(b_step_m1) { (void)msg; return K->step(w, -1); }
BF(b_step_min) { (void)msg; return K->step(w, INT_MIN); }
BF(b_step_nullw) { NOMSG; return K->step(NULL, 1); }
/* K's base definition into a world of its own, in memory of bytes (mem NULL: none) */
static hcbd_result bi_init(const bi_kind *K, int null_mem, size_t less, const char **msg)
{
    void *v = calloc(1, K->world_size), *d = malloc(K->def_size), *mem = NULL;
    size_t need;
    hcbd_result r = HCBD_ERR_MODEL;
    if (v && d) {
        K->base(d, 0);
        need = K->bytes(d);
        mem = null_mem ? NULL : malloc(need);
        if (null_mem || mem) r = K->init(v, d, mem, need - less);
        snprintf(bi_msg, sizeof bi_msg, "%s", K->err(v)->msg);
    }
    *msg = bi_msg;
    free(mem);
    free(d);
    free(v);
    return r;
}
BF(b_init_nullmem) { (void)w; return bi_init(K, 1, 0, msg); }
BF(b_init_short) { (void)w; return bi_init(K, 0, 64, msg); }
BF(b_init_nullw)
{
    void *d = malloc(K->def_size);
    char mem[64];
    hcbd_result r = HCBD_ERR_MODEL;
    NOMSG;
    if (d) {
        K->base(d, 0);
        r = K->init(NULL, d, mem, sizeof mem);
    }
    free(d);
    return r;
}
BF(b_create_nullw)
{
    void *d = malloc(K->def_size);
    hcbd_result r = HCBD_ERR_MODEL;
    NOMSG;
    if (d) {
        K->base(d, 0);
        r = K->create(NULL, d);
    }
    free(d);
    return r;
}
BF(b_create_nulldef)
{
    void *v = calloc(1, K->world_size);
    hcbd_result r = HCBD_ERR_MODEL;
    (void)w;
    if (v) {
        r = K->create(v, NULL);
        snprintf(bi_msg, sizeof bi_msg, "%s", K->err(v)->msg);
        if (r == HCBD_OK) K->destroy(v);
    }
    *msg = bi_msg;
    free(v);
    return r;
}
BF(b_check_null)
{
    (void)w;
    strcpy(bi_msg, "(untouched)");
    *msg = bi_msg;
    return K->check(NULL, bi_msg, sizeof bi_msg);
}
BF(b_stress_2) { (void)msg; return K->stress_enable(w, 2); }
BF(b_stress_m1) { (void)msg; return K->stress_enable(w, -1); }
BF(b_stress_nullw) { NOMSG; return K->stress_enable(NULL, 1); }
BF(b_sread_null) { NOMSG; return K->stress_read(w, NULL, NULL); }
BF(b_tc_nk0) { double o[12]; NOMSG; return K->tc(w, 0, o); }
BF(b_tc_nkm1) { double o[12]; NOMSG; return K->tc(w, -1, o); }
BF(b_tc_null) { NOMSG; return K->tc(w, 1, NULL); }

/* the calls both worlds have */
static const bi_call bi_both_calls[] = {
    {"step nsteps = -1", 0, b_step_m1, HCBD_ERR_PARAM, "nsteps = -1"},
    {"step nsteps = INT_MIN", 0, b_step_min, HCBD_ERR_PARAM, "nsteps = -2147483648"},
    {"step w NULL", 0, b_step_nullw, HCBD_ERR_NULL, NULL},
    {"world_init mem NULL", 0, b_init_nullmem, HCBD_ERR_NULL, "memory block"},
    {"world_init bytes too few", 0, b_init_short, HCBD_ERR_MEMORY, "bytes"},
    {"world_init w NULL", 0, b_init_nullw, HCBD_ERR_NULL, NULL},
    {"world_create w NULL", 0, b_create_nullw, HCBD_ERR_NULL, NULL},
    {"world_create def NULL", 0, b_create_nulldef, HCBD_ERR_NULL, "definition"},
    {"params_check p NULL", 0, b_check_null, HCBD_ERR_NULL, "params"},
    {"stress_enable on = 2", 0, b_stress_2, HCBD_ERR_PARAM, "on = 2"},
    {"stress_enable on = -1", 0, b_stress_m1, HCBD_ERR_PARAM, "on = -1"},
    {"stress_enable w NULL", 0, b_stress_nullw, HCBD_ERR_NULL, NULL},
    {"stress_read out NULL", 0, b_sread_null, HCBD_ERR_NULL, NULL},
    {"transverse_current nk = 0", 0, b_tc_nk0, HCBD_ERR_PARAM, NULL},
    {"transverse_current nk = -1", 0, b_tc_nkm1, HCBD_ERR_PARAM, NULL},
    {"transverse_current out NULL", 0, b_tc_null, HCBD_ERR_NULL, NULL},
};

/* ---- the world kinds and the tests -------------------------------------- */
static void bi_gbase(void *d, int base) { *(hcbd_world_def *)d = bi_base(base); }
static int bi_gmake(void *w, int kind) { return bi_make((hcbd_world *)w, kind); }
static hcbd_result bi_gtheory(const void *p)
{
    hcbd_theory th;
    return hcbd_params_theory((const hcbd_params *)p, &th);
}
BI_KIND_FNS(bi_g, hcbd_world, hcbd_world_def, hcbd_params)
static const bi_kind bi_gibd = BI_KIND(bi_g, "hcbd", hcbd_world, hcbd_world_def, hcbd_params, bi_base_name,
                                      bi_gbase, bi_gtheory, bi_gmake, bi_gsnap);
static const bi_pentry bi_gboth[] = {BI_BOTH_PARAMS(hcbd_world_def)};

void test_bad_input(void)
{
    bi_defs(&bi_gibd, bi_params, sizeof bi_params / sizeof bi_params[0]);
    bi_defs(&bi_gibd, bi_gboth, sizeof bi_gboth / sizeof bi_gboth[0]);
    bi_summary("parameters and definitions");
    bi_run(&bi_gibd, bi_calls, sizeof bi_calls / sizeof bi_calls[0]);
    bi_run(&bi_gibd, bi_both_calls, sizeof bi_both_calls / sizeof bi_both_calls[0]);
    bi_summary("calls");
}

#if HCBD_MODEL == HCBD_MODEL_HCBD
static void bi_hbase(void *d, int base) { *(hcbd_hc_world_def *)d = bi_hc_base(base); }
static int bi_hmake_(void *w, int kind) { return bi_hmake((hcbd_hc_world *)w, kind); }
BI_KIND_FNS(bi_h, hcbd_hc_world, hcbd_hc_world_def, hcbd_hc_params)
static const bi_kind bi_hc = BI_KIND(bi_h, "hcbd_hc", hcbd_hc_world, hcbd_hc_world_def, hcbd_hc_params,
                                    bi_hbase_name, bi_hbase, NULL, bi_hmake_, bi_hsnap);
static const bi_pentry bi_hboth[] = {BI_BOTH_PARAMS(hcbd_hc_world_def)};

void test_hc_bad_input(void)
{
    bi_defs(&bi_hc, bi_hparams, sizeof bi_hparams / sizeof bi_hparams[0]);
    bi_defs(&bi_hc, bi_hboth, sizeof bi_hboth / sizeof bi_hboth[0]);
    bi_summary("HCBD parameters and definitions");
    bi_run(&bi_hc, bi_hcalls, sizeof bi_hcalls / sizeof bi_hcalls[0]);
    bi_run(&bi_hc, bi_both_calls, sizeof bi_both_calls / sizeof bi_both_calls[0]);
    bi_summary("HCBD calls");
}
#endif

void test_bad_input_io(void)
{
    bi_run(&bi_gibd, bi_both_io, sizeof bi_both_io / sizeof bi_both_io[0]);
    bi_run(&bi_gibd, bi_iocalls, sizeof bi_iocalls / sizeof bi_iocalls[0]);
    bi_summary("checkpoint and trajectory calls");
#if HCBD_MODEL == HCBD_MODEL_HCBD
    bi_run(&bi_hc, bi_both_io, sizeof bi_both_io / sizeof bi_both_io[0]);
    bi_run(&bi_hc, bi_hiocalls, sizeof bi_hiocalls / sizeof bi_hiocalls[0]);
    bi_summary("HCBD checkpoint and trajectory calls");
#endif
}
