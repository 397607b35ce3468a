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
   is in that world's tables.  A row of a table of calls is the whole
   case: an adapter for the function called, its numbers and which of its
   pointers are NULL, and what it must give (bi_call). */
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
   altered, or NULL; err_unset: the world's error does not hold the code */
static void bi_judge(const char *name, hcbd_result want, const char *want_msg,
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
   macro writes each kind's functions (BI_KIND_FNS) and one runner takes any
   world's table of calls; the cases both worlds have are one table, run
   against each (bi_both_params, bi_both_calls, bi_both_io). */
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

typedef struct bi_kind {
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
} bi_kind;

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
        bi_judge(n2, want, want_msg, r, msg, NULL, 0);
        snprintf(n2, sizeof n2, "%s_params_stability %s", K->api, name);
        bi_judge(n2, want, NULL, K->stability(par, lim, &nl), NULL, NULL, 0);
        if (K->theory) {
            snprintf(n2, sizeof n2, "%s_params_theory %s", K->api, name);
            bi_judge(n2, want, NULL, K->theory(par), NULL, NULL, 0);
        }
    }
    snprintf(n2, sizeof n2, "%s_world_create %s", K->api, name);
    r = K->create(w, def);
    bi_judge(n2, want, want_msg, r, K->err(w)->msg, r != HCBD_OK && K->mem_kept(w) ? "memory kept" : NULL, 0);
    if (r == HCBD_OK) K->destroy(w);
    snprintf(n2, sizeof n2, "%s_world_bytes %s", K->api, name);
    bi_judge(n2, HCBD_OK, NULL, K->bytes(def) == 0 ? HCBD_OK : HCBD_ERR_STATE, NULL, NULL, 0);
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

/* ---- a call on an existing world, as one row --------------------------- */
/* A row names its adapter, a function that makes one kind of call from
   the row's numbers and flags, so that one adapter serves every bad value
   of that call.  The adapter's comment gives the call and the order of
   a[]; where a row needs a spoilt input, the adapter starts from a valid
   one (the test world's positions, a good flow curve) and a[] says what
   to change. */
typedef struct bi_call bi_call;
typedef struct {
    const bi_kind *K;
    void *w;            /* the row's world, made by K->make */
    const bi_call *row;
    const char *msg;    /* where the call's message is: w's unless the
                           adapter moves it; NULL: the call has none */
} bi_ctx;
struct bi_call {
    const char *name;
    int kind;           /* the world the call acts on (0: the kind's default) */
    hcbd_result (*fn)(bi_ctx *c);
    double a[5];        /* the call's numbers, ints and offsets too: a double holds them exactly */
    unsigned flags;     /* NUL(k), SHORT */
    hcbd_result want;
    const char *msg;    /* NULL: code only */
};
#define NUL(k) (1u << (k)) /* the call's k-th argument (1: the first) is NULL */
#define SHORT (1u << 15)   /* the memory block is one byte short of what it needs */

/* in an adapter: the row's numbers, its pointers, a call without a message */
#define A(k) (c->row->a[k])
#define I(k) ((int)A(k))
#define ARG(k, p) (c->row->flags & NUL(k) ? NULL : (p))
#define WARG(k) bi_warg(c, k)
#define NOMSG(call) (c->msg = NULL, (call))
/* argument k, the row's world or NULL; a call on a NULL world has nowhere
   to write a message */
static void *bi_warg(bi_ctx *c, int k)
{
    if (!(c->row->flags & NUL(k))) return c->w;
    c->msg = NULL;
    return NULL;
}
/* a double field of a struct as a row's number: 1 + its offset, so that a
   row that leaves the number at 0 spoils nothing */
#define FIELD(T, f) (offsetof(T, f) + 1)
static void bi_poke(void *s, double field, double v)
{
    if (field > 0) memcpy((char *)s + (size_t)field - 1, &v, sizeof v);
}

/* Each call of t on its own fresh world: the code and message it must
   give, and a refused call must leave the world as it was. */
static void bi_run(const bi_kind *K, const bi_call *t, size_t n)
{
    void *w = malloc(K->world_size);
    size_t e;
    for (e = 0; w && e < n; ++e) {
        bi_snap a, b;
        bi_ctx c;
        char buf[128], name[200];
        const char *ch;
        hcbd_result r;
        if (!K->make(w, t[e].kind)) { t_fail = 1; continue; }
        c.K = K;
        c.w = w;
        c.row = &t[e];
        c.msg = K->err(w)->msg;
        K->snap(w, &a);
        r = t[e].fn(&c);
        K->snap(w, &b);
        ch = bi_diff(&a, &b, buf, sizeof buf);
        snprintf(name, sizeof name, "%s_%s", K->api, t[e].name);
        /* a message in w->err comes with its code */
        bi_judge(name, t[e].want, t[e].msg, r, c.msg, ch,
                 r != HCBD_OK && c.msg == K->err(w)->msg && K->err(w)->code != r);
        K->destroy(w);
    }
    if (!w) t_fail = 1;
    free(w);
}
#define BI_N(t) (sizeof t / sizeof t[0])

#define NOSET {NULL, 0, 0, 0, NULL}
/* the common entry: one field of a base bad (BAD: the kind's default
   base), HCBD_ERR_PARAM with "field = value" in the message; the others
   are written out */
#define BAD_IN(base, set) {base, NOSET, set, HCBD_ERR_PARAM, NULL}
#define BAD(set) {0, NOSET, set, HCBD_ERR_PARAM, NULL}
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
    BAD(GD(L[1], 1e13)),
    /* < 2 Rc: too small even for the automatic skin, which shrinks to fit */
    {B_DEF, NOSET, GD(L[0], 4.9), HCBD_ERR_BOX, NULL},
    {B_DEF, NOSET, GD(L[2], 4.5), HCBD_ERR_BOX, NULL},
    {B_DEF, NOSET, GD(skin, 5), HCBD_ERR_BOX, "box too small|skin 5"},
    /* dynamics */
    BAD(GD(xip, 0)), BAD(GD(xip, -1)), BAD(GD(xip, NAN)), BAD(GD(xip, INFINITY)),
    BAD(GD(tau, 0)), BAD(GD(tau, -1)), BAD(GD(tau, NAN)), BAD(GD(tau, INFINITY)),
    {B_DEF, GE(pair_integrator, HCBD_PAIR_EULER), GD(tau, 6.103515625e-05), HCBD_ERR_PARAM, NULL}, /* < dt (Euler) */
    BAD(GD(Rc, 0)), BAD(GD(Rc, -1)), BAD(GD(Rc, NAN)), BAD(GD(Rc, INFINITY)),
    BAD(GD(density, 0)), BAD(GD(density, -1)), BAD(GD(density, NAN)), BAD(GD(density, INFINITY)),
    BAD(GI(density_norm, 2015)), BAD(GI(density_norm, 0)),
    BAD(GI(lagged_density, 2)), BAD(GI(lagged_density, -1)),
    BAD(GE(dynamics, 2)), BAD(GE(dynamics, -1)),
    BAD(GE(potential, 3)), BAD(GE(potential, -1)),
    BAD(GE(noise, 2)), BAD(GE(noise, -1)),
    BAD(GE(brownian, 2)), BAD(GE(brownian, -1)),
    /* star potential */
    BAD(GD(f, 0)), BAD(GD(f, -1)), BAD(GD(f, NAN)), BAD(GD(f, INFINITY)),
    BAD(GD(star_eps, -1)), BAD(GD(star_eps, NAN)), BAD(GD(star_eps, INFINITY)),
    BAD(GD(rcut, 0)), BAD(GD(rcut, -1)), BAD(GD(rcut, NAN)), BAD(GD(rcut, INFINITY)),
    /* table potential */
    {B_TABLE, NOSET, GP(table_F, NULL), HCBD_ERR_NULL, "table_F"},
    {B_TABLE, NOSET, GP(table_V, NULL), HCBD_ERR_NULL, "table_V"},
    BAD_IN(B_TABLE, GI(table_n, 1)), BAD_IN(B_TABLE, GI(table_n, 0)), BAD_IN(B_TABLE, GI(table_n, -3)),
    BAD_IN(B_TABLE, GD(table_r0, -1)), BAD_IN(B_TABLE, GD(table_r0, NAN)),
    BAD_IN(B_TABLE, GD(table_r0, 2.5)), /* = rcut */
    {B_TABLE, NOSET, GP(table_F, bi_tab_nan), HCBD_ERR_PARAM, "table_F[3] = nan"},
    {B_TABLE, NOSET, GP(table_V, bi_tab_inf), HCBD_ERR_PARAM, "table_V[5] = inf"},
    /* forces, shear */
    BAD(GD(fext[0], NAN)), BAD(GD(fext[1], INFINITY)), BAD(GD(fext[2], -INFINITY)),
    BAD(GI(fext_background_only, 2)),
    /* BD has no background for the force to drive (once silently dropped) */
    {B_BD, GD(fext[0], 1.0), GI(fext_background_only, 1), HCBD_ERR_PARAM, NULL},
    BAD(GD(fext[2], NAN)),
    BAD_IN(B_BD, GD(gdot, 1)),
    BAD(GD(gdot, 100000)), BAD(GD(gdot, -100000)), /* offset > L per step */
    {B_SHEAR, NOSET, GD(L[0], 7.4), HCBD_ERR_BOX, "L[0] = 7.4|Lees-Edwards"},
    BAD(GD(skin, -0.5)), BAD(GD(skin, NAN)), BAD(GD(skin, INFINITY)),
    BAD(GI(sort, 2)),
    BAD(GI(force_table, 2)), BAD(GI(force_table, -1)),
    /* checks of the input and of the run */
    BAD(GD(min_distance, -1)), BAD(GD(min_distance, NAN)), BAD(GD(min_distance, INFINITY)),
    BAD(GD(guard_step, 0)), BAD(GD(guard_step, -2)), BAD(GD(guard_step, NAN)), BAD(GD(guard_step, INFINITY)),
    /* walls */
#if HCBD_MODEL == HCBD_MODEL_WALLED
    BAD(GI(wall.guard, 2)), BAD(GI(wall.guard, -1)),
    BAD(GD(wall.thickness, NAN)), BAD(GD(wall.thickness, -1)), BAD(GD(wall.thickness, INFINITY)),
    {B_WALL, NOSET, GD(wall.thickness, 7), HCBD_ERR_BOX, NULL},   /* 2 t > L[1] */
    {B_WALL, NOSET, GD(wall.thickness, 6.5), HCBD_ERR_BOX, NULL}, /* 2 t > L[1] */
    {B_WALL, NOSET, GD(wall.thickness, 1), HCBD_ERR_BOX, NULL},   /* 2 t < Rc */
    {B_WALL, NOSET, GD(gdot, 1), HCBD_ERR_PARAM, "gdot|= 1"},
    {B_WALL, NOSET, GI(lagged_density, 1), HCBD_ERR_PARAM, "lagged_density|= 1"},
    BAD_IN(B_WALL, GD(wall.vx[0], NAN)), BAD_IN(B_WALL, GD(wall.vx[1], INFINITY)),
    BAD_IN(B_WALL, GD(wall.beta_max, 0.5)), BAD_IN(B_WALL, GD(wall.beta_max, NAN)),
    BAD_IN(B_WALL, GD(wall.beta_max, INFINITY)),
    BAD_IN(B_WALL, GE(wall.mode, 3)), BAD_IN(B_WALL, GE(wall.mode, -1)),
    BAD_IN(B_WALL, GI(wall.noise_beta, 2)),
    BAD_IN(B_WALL, GD(wall.a, -1)), BAD_IN(B_WALL, GD(wall.a, NAN)),
    BAD_IN(B_WALL, GD(wall.b, 0)), BAD_IN(B_WALL, GD(wall.b, NAN)),
    BAD_IN(B_WALL, GD(wall.plane, -1)), BAD_IN(B_WALL, GD(wall.plane, 3)), /* 3: deeper than the wall */
    BAD_IN(B_WALL, GD(wall.plane, NAN)),
    BAD_IN(B_NOSLIP, GD(wall.shift, -2)), BAD_IN(B_NOSLIP, GD(wall.shift, 3)), /* 3: > channel / 4 */
    BAD_IN(B_NOSLIP, GD(wall.shift, NAN)),
    {B_WALL, GI(density_norm, 2014), GD(density, 0), HCBD_ERR_PARAM, "density|= 0"},
    BAD_IN(B_WALL, GI(wall.guard, 2)),
    {B_WALL, NOSET, GD(L[1], 4), HCBD_ERR_BOX, NULL},
#endif
    /* the definition */
    BAD(WI(capacity, 0)), BAD(WI(capacity, -1)), BAD(WI(capacity, 536870912)),
    {B_DEF, NOSET, WI(capacity, 500000000), HCBD_ERR_CAPACITY, NULL}, /* > 2^31 pairs */
    BAD(WL(max_pairs, -2)), BAD(WL(max_pairs, 2147483648.0)),
};

/* ---- calls on an existing GI-BD world ---------------------------------- */
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

/* set_positions(w, n, xyz): n of the world's positions (then zeros) */
static hcbd_result a_setpos(bi_ctx *c)
{
    static double xyz[3 * 65];
    memcpy(xyz, bi_xyz, sizeof bi_xyz);
    return hcbd_world_set_positions(WARG(1), I(0), ARG(3, xyz));
}
/* set_positions(w, 64, xyz): the world's positions with xyz[i] = v; a = {i, v} */
static hcbd_result a_setpos_at(bi_ctx *c)
{
    double xyz[3 * 64];
    memcpy(xyz, bi_xyz, sizeof xyz);
    xyz[I(0)] = A(1);
    return hcbd_world_set_positions(c->w, 64, xyz);
}
/* set_positions(w, 64, xyz): particle i at (1, 1, 1), j at (1 + d, 1, 1); a = {i, j, d} */
static hcbd_result a_setpos_pair(bi_ctx *c)
{
    double xyz[3 * 64];
    memcpy(xyz, bi_xyz, sizeof xyz);
    xyz[3 * I(0)] = xyz[3 * I(0) + 1] = xyz[3 * I(0) + 2] = 1.0;
    xyz[3 * I(1)] = 1.0 + A(2);
    xyz[3 * I(1) + 1] = xyz[3 * I(1) + 2] = 1.0;
    return hcbd_world_set_positions(c->w, 64, xyz);
}
static hcbd_result a_lattice(bi_ctx *c) { return hcbd_world_place_lattice(WARG(1), I(0)); }
static hcbd_result a_random(bi_ctx *c) { return hcbd_world_place_random(WARG(1), I(0)); }
/* set_velocities(w, v): zeros but v[i] = v; a = {i, v} */
static hcbd_result a_setvel(bi_ctx *c)
{
    double v[3 * 64] = {0};
    v[I(0)] = A(1);
    return hcbd_world_set_velocities(WARG(1), ARG(2, v));
}
/* get_positions(w, xyz, unwrapped) */
static hcbd_result a_getpos(bi_ctx *c)
{
    double xyz[3 * 64];
    return NOMSG(hcbd_world_get_positions(ARG(1, c->w), ARG(2, xyz), I(0)));
}
static hcbd_result a_getvel(bi_ctx *c)
{
    double v[3 * 64];
    return NOMSG(hcbd_world_get_velocities(c->w, ARG(2, v)));
}
static hcbd_result a_virial(bi_ctx *c)
{
    double s[9];
    return hcbd_world_virial_stress(WARG(1), ARG(2, s));
}
/* friction_average(w, nk, out) */
static hcbd_result a_friction(bi_ctx *c)
{
    double out[3];
    return hcbd_world_friction_average(c->w, I(0), ARG(3, out));
}
/* rdf_init(g, rmax, nbins, block, hist, bytes) */
static hcbd_result a_rdf_init(bi_ctx *c)
{
    static double hist[64];
    hcbd_rdf g;
    size_t bytes = c->row->flags & SHORT ? hcbd_rdf_bytes(I(1), I(2)) - 1 : sizeof hist;
    return NOMSG(hcbd_rdf_init(ARG(1, &g), A(0), I(1), I(2), ARG(5, hist), bytes));
}
/* rdf_sample(g, w) of a g(r) to rmax in 10 bins */
static hcbd_result a_rdf_sample(bi_ctx *c)
{
    static double hist[64];
    hcbd_rdf g;
    hcbd_result r = hcbd_rdf_init(&g, A(0), 10, 0, hist, sizeof hist);
    return r != HCBD_OK ? r : hcbd_rdf_sample(ARG(1, &g), c->w);
}
/* rdf_coordination(g, rc, nc, NULL) of a g(r) to 2 after samples (0 or 1)
   of the world; a = {rc, samples} */
static hcbd_result a_coord(bi_ctx *c)
{
    static double mem[60];
    hcbd_rdf g;
    double nc;
    hcbd_result r = hcbd_rdf_init(&g, 2, 10, 5, mem, sizeof mem);
    if (r == HCBD_OK && I(1)) r = hcbd_rdf_sample(&g, c->w);
    return NOMSG(r != HCBD_OK ? r : hcbd_rdf_coordination(&g, A(0), ARG(3, &nc), NULL));
}
/* mtcorr_init(c, nch, p, m, levels, mem, bytes) */
static hcbd_result a_mtcorr(bi_ctx *c)
{
    static double mem[4096];
    hcbd_mtcorr mc;
    size_t bytes = c->row->flags & SHORT ? hcbd_mtcorr_bytes(I(0), I(1), I(2), I(3)) - 1 : sizeof mem;
    return NOMSG(hcbd_mtcorr_init(ARG(1, &mc), I(0), I(1), I(2), I(3), ARG(6, mem), bytes));
}
/* msd_init(d, n, B, levels, dense, block, mem, bytes) */
static hcbd_result a_msd_init(bi_ctx *c)
{
    static double mem[8192];
    hcbd_msd d;
    size_t bytes = c->row->flags & SHORT ? hcbd_msd_bytes(I(0), I(1), I(2), I(3)) - 1 : sizeof mem;
    return NOMSG(hcbd_msd_init(ARG(1, &d), I(0), I(1), I(2), I(3), (int64_t)A(4), ARG(7, mem), bytes));
}
/* msd_diffusion(d, lag_min, lag_max, &D, NULL) of 8 particles, B = 4,
   3 levels, after samples (particle 0 at x = sample number); a = {lag_min,
   lag_max, samples, dense, block} */
static hcbd_result a_msd_diffusion(bi_ctx *c)
{
    static double mem[16384];
    double xyz[24] = {0}, D;
    hcbd_msd d;
    int s;
    hcbd_result r = hcbd_msd_init(&d, 8, 4, 3, I(3), (int64_t)A(4), mem, sizeof mem);
    if (r != HCBD_OK) return NOMSG(r);
    for (s = 0; s < I(2); ++s) {
        xyz[0] = s;
        hcbd_msd_add(&d, xyz);
    }
    return NOMSG(hcbd_msd_diffusion(&d, A(0), A(1), &D, NULL));
}
/* profile_init(pr, w, nslab, block, mem, bytes) */
static hcbd_result a_profile(bi_ctx *c)
{
    static double mem[4096];
    hcbd_profile pr;
    size_t bytes = c->row->flags & SHORT ? hcbd_profile_bytes(I(0)) - 1 : sizeof mem;
    return NOMSG(hcbd_profile_init(ARG(1, &pr), ARG(2, c->w), I(0), I(1), ARG(5, mem), bytes));
}
/* slabs_init(s, L = {10, Ly, 10}, nslab, nval, block, mem, bytes); a = {Ly,
   nslab, nval, block} */
static hcbd_result a_slabs(bi_ctx *c)
{
    static double mem[4096];
    double L[3] = {10, 10, 10};
    hcbd_slabs s;
    size_t bytes = c->row->flags & SHORT ? hcbd_slabs_bytes(I(1), I(2)) - 1 : sizeof mem;
    L[1] = A(0);
    return NOMSG(hcbd_slabs_init(&s, ARG(2, L), I(1), I(2), I(3), mem, bytes));
}
/* carreau_fit(gdot, eta, err, n, eta_inf, start, p, pe, chi2) on a good
   flow curve with one number of it spoilt; a = {n, CURVE(field), value};
   a spoilt p is a start */
typedef struct {
    double gdot[6], eta[6], err[6], eta_inf, p[3];
} bi_curve;
#define CURVE(f) FIELD(bi_curve, f)
static hcbd_result a_carreau(bi_ctx *c)
{
    bi_curve k = {{0.01, 0.1, 1, 10, 100, 1000}, {10, 9.5, 6, 2, 1.2, 1.02},
                  {0.1, 0.1, 0.1, 0.05, 0.02, 0.01}, 1.0, {10, 1, 0.5}};
    double pe[3], chi2;
    int start = A(1) >= CURVE(p);
    bi_poke(&k, A(1), A(2));
    return NOMSG(hcbd_carreau_fit(ARG(1, k.gdot), k.eta, k.err, I(0), k.eta_inf, start, ARG(7, k.p), pe, &chi2));
}
/* params_stability(&w->p, out, n), params_theory(&w->p, t) */
static hcbd_result a_stability(bi_ctx *c)
{
    hcbd_limit out[HCBD_MAX_LIMITS];
    int n;
    return NOMSG(hcbd_params_stability(ARG(1, &((hcbd_world *)c->w)->p), ARG(2, out), ARG(3, &n)));
}
static hcbd_result a_theory(bi_ctx *c)
{
    hcbd_theory t;
    return NOMSG(hcbd_params_theory(ARG(1, &((hcbd_world *)c->w)->p), ARG(2, &t)));
}
static hcbd_result a_step(bi_ctx *c); /* with the calls both worlds have */

static const bi_call bi_calls[] = {
    {"set_positions w NULL", WK_GIBD, a_setpos, {64}, NUL(1), HCBD_ERR_NULL, NULL},
    {"set_positions xyz NULL", WK_GIBD, a_setpos, {64}, NUL(3), HCBD_ERR_NULL, "positions"},
    {"set_positions n = 65 > capacity", WK_GIBD, a_setpos, {65}, 0, HCBD_ERR_CAPACITY, "N = 65"},
    {"set_positions n = 0", WK_GIBD, a_setpos, {0}, 0, HCBD_ERR_PARAM, "N = 0"},
    {"set_positions n = -1", WK_GIBD, a_setpos, {-1}, 0, HCBD_ERR_PARAM, "N = -1"},
    {"set_positions n = 1 (GI-BD)", WK_GIBD, a_setpos, {1}, 0, HCBD_ERR_PARAM, "N = 1"},
    {"set_positions y NaN", WK_GIBD, a_setpos_at, {3 * 5 + 1, NAN}, 0, HCBD_ERR_NONFINITE, "particle 5|nan"},
    {"set_positions x inf", WK_GIBD, a_setpos_at, {0, INFINITY}, 0, HCBD_ERR_NONFINITE, "particle 0|inf"},
    {"set_positions z -inf", WK_GIBD, a_setpos_at, {3 * 63 + 2, -INFINITY}, 0, HCBD_ERR_NONFINITE,
     "particle 63|-inf"},
    {"set_positions x 1e20", WK_GIBD, a_setpos_at, {3 * 2, 1e20}, 0, HCBD_ERR_PARAM, "particle 2|1e+20"},
    {"set_positions closer than min_distance", WK_MIND, a_setpos_pair, {3, 7, 0.25}, 0, HCBD_ERR_OVERLAP,
     "3 and 7|0.25|min_distance = 0.5"},
    {"place_lattice n = 65 > capacity", WK_GIBD, a_lattice, {65}, 0, HCBD_ERR_CAPACITY, "N = 65"},
    {"place_lattice n = 0", WK_GIBD, a_lattice, {0}, 0, HCBD_ERR_PARAM, "N = 0"},
    {"place_lattice w NULL", WK_GIBD, a_lattice, {8}, NUL(1), HCBD_ERR_NULL, NULL},
    {"place_random n = -5", WK_GIBD, a_random, {-5}, 0, HCBD_ERR_PARAM, "N = -5"},
    {"place_random n = 65 > capacity", WK_GIBD, a_random, {65}, 0, HCBD_ERR_CAPACITY, "N = 65"},
    {"place_random w NULL", WK_GIBD, a_random, {8}, NUL(1), HCBD_ERR_NULL, NULL},
    {"set_velocities v NULL", WK_GIBD, a_setvel, {0}, NUL(2), HCBD_ERR_NULL, "velocities"},
    {"set_velocities w NULL", WK_GIBD, a_setvel, {0}, NUL(1), HCBD_ERR_NULL, NULL},
    {"set_velocities x NaN", WK_GIBD, a_setvel, {3 * 2, NAN}, 0, HCBD_ERR_NONFINITE, "particle 2|nan"},
    {"set_velocities z -inf", WK_GIBD, a_setvel, {3 * 63 + 2, -INFINITY}, 0, HCBD_ERR_NONFINITE,
     "particle 63|-inf"},
    {"set_velocities in BD", WK_BD, a_setvel, {0}, 0, HCBD_ERR_STATE, "BD"},
    {"step without particles", WK_EMPTY, a_step, {1}, 0, HCBD_ERR_STATE, "no particles"},
    {"world_get_positions xyz NULL", WK_GIBD, a_getpos, {0}, NUL(2), HCBD_ERR_NULL, NULL},
    {"world_get_positions w NULL", WK_GIBD, a_getpos, {1}, NUL(1), HCBD_ERR_NULL, NULL},
    {"get_velocities v NULL", WK_GIBD, a_getvel, {0}, NUL(2), HCBD_ERR_NULL, NULL},
    {"virial_stress s NULL", WK_GIBD, a_virial, {0}, NUL(2), HCBD_ERR_NULL, "s is NULL"},
    {"virial_stress w NULL", WK_GIBD, a_virial, {0}, NUL(1), HCBD_ERR_NULL, NULL},
    {"friction_average nk = 0", WK_GIBD, a_friction, {0}, 0, HCBD_ERR_PARAM, "nk = 0"},
    {"friction_average nk = -1", WK_GIBD, a_friction, {-1}, 0, HCBD_ERR_PARAM, "nk = -1"},
    {"friction_average out NULL", WK_GIBD, a_friction, {1}, NUL(3), HCBD_ERR_NULL, "out is NULL"},
    {"friction_average in BD", WK_BD, a_friction, {1}, 0, HCBD_ERR_STATE, "GI-BD"},
    {"rdf_init rmax = 0", WK_GIBD, a_rdf_init, {0, 10}, 0, HCBD_ERR_PARAM, NULL},
    {"rdf_init rmax = -1", WK_GIBD, a_rdf_init, {-1, 10}, 0, HCBD_ERR_PARAM, NULL},
    {"rdf_init rmax = nan", WK_GIBD, a_rdf_init, {NAN, 10}, 0, HCBD_ERR_PARAM, NULL},
    {"rdf_init rmax = inf", WK_GIBD, a_rdf_init, {INFINITY, 10}, 0, HCBD_ERR_PARAM, NULL},
    {"rdf_init nbins = 0", WK_GIBD, a_rdf_init, {2, 0}, 0, HCBD_ERR_PARAM, NULL},
    {"rdf_init nbins = -1", WK_GIBD, a_rdf_init, {2, -1}, 0, HCBD_ERR_PARAM, NULL},
    {"rdf_init g NULL", WK_GIBD, a_rdf_init, {2, 10}, NUL(1), HCBD_ERR_NULL, NULL},
    {"rdf_init hist NULL", WK_GIBD, a_rdf_init, {2, 10}, NUL(5), HCBD_ERR_NULL, NULL},
    {"rdf_sample rmax = 7 > L/2", WK_GIBD, a_rdf_sample, {7}, 0, HCBD_ERR_PARAM, "rmax = 7"}, /* L/2 = 6.45 */
    {"rdf_sample g NULL", WK_GIBD, a_rdf_sample, {2}, NUL(1), HCBD_ERR_NULL, "g is NULL"},
    {"rdf_sample without particles", WK_EMPTY, a_rdf_sample, {2}, 0, HCBD_ERR_STATE, "particles"},
    {"rdf_init block = -1", WK_GIBD, a_rdf_init, {2, 10, -1}, 0, HCBD_ERR_PARAM, NULL},
    {"rdf_init with blocks, bytes too few", WK_GIBD, a_rdf_init, {2, 10, 5}, SHORT, HCBD_ERR_MEMORY, NULL},
    {"rdf_coordination rc > rmax", WK_GIBD, a_coord, {2.5, 1}, 0, HCBD_ERR_PARAM, NULL},
    {"rdf_coordination rc < 0", WK_GIBD, a_coord, {-1, 1}, 0, HCBD_ERR_PARAM, NULL},
    {"rdf_coordination rc = nan", WK_GIBD, a_coord, {NAN, 1}, 0, HCBD_ERR_PARAM, NULL},
    {"rdf_coordination before a sample", WK_GIBD, a_coord, {1, 0}, 0, HCBD_ERR_STATE, NULL},
    {"rdf_coordination nc NULL", WK_GIBD, a_coord, {1, 1}, NUL(3), HCBD_ERR_NULL, NULL},
    {"mtcorr_init nch = 0", WK_GIBD, a_mtcorr, {0, 16, 2, 3}, 0, HCBD_ERR_PARAM, NULL},
    {"mtcorr_init p = 1", WK_GIBD, a_mtcorr, {1, 1, 2, 3}, 0, HCBD_ERR_PARAM, NULL},
    {"mtcorr_init m = 1", WK_GIBD, a_mtcorr, {1, 16, 1, 3}, 0, HCBD_ERR_PARAM, NULL},
    {"mtcorr_init p % m != 0", WK_GIBD, a_mtcorr, {1, 16, 3, 3}, 0, HCBD_ERR_PARAM, NULL},
    {"mtcorr_init levels = 0", WK_GIBD, a_mtcorr, {1, 16, 2, 0}, 0, HCBD_ERR_PARAM, NULL},
    {"mtcorr_init c NULL", WK_GIBD, a_mtcorr, {1, 16, 2, 3}, NUL(1), HCBD_ERR_NULL, NULL},
    {"mtcorr_init mem NULL", WK_GIBD, a_mtcorr, {1, 16, 2, 3}, NUL(6), HCBD_ERR_NULL, NULL},
    {"mtcorr_init bytes too few", WK_GIBD, a_mtcorr, {1, 16, 2, 3}, SHORT, HCBD_ERR_MEMORY, NULL},
    {"msd_init n = 0", WK_GIBD, a_msd_init, {0, 4, 3}, 0, HCBD_ERR_PARAM, NULL},
    {"msd_init B = 1", WK_GIBD, a_msd_init, {8, 1, 3}, 0, HCBD_ERR_PARAM, NULL},
    {"msd_init levels = 0", WK_GIBD, a_msd_init, {8, 4, 0}, 0, HCBD_ERR_PARAM, NULL},
    {"msd_init B^levels > int64", WK_GIBD, a_msd_init, {1, 2, 70}, 0, HCBD_ERR_PARAM, NULL}, /* 2^69 samples */
    {"msd_init d NULL", WK_GIBD, a_msd_init, {8, 4, 3}, NUL(1), HCBD_ERR_NULL, NULL},
    {"msd_init mem NULL", WK_GIBD, a_msd_init, {8, 4, 3}, NUL(7), HCBD_ERR_NULL, NULL},
    {"msd_init bytes too few", WK_GIBD, a_msd_init, {8, 4, 3}, SHORT, HCBD_ERR_MEMORY, NULL},
    {"msd_init dense = -1", WK_GIBD, a_msd_init, {8, 4, 3, -1}, 0, HCBD_ERR_PARAM, NULL},
    {"msd_init block = -1", WK_GIBD, a_msd_init, {8, 4, 3, 0, -1}, 0, HCBD_ERR_PARAM, NULL},
    {"msd_init B = 1000, dense = 3 (slots overflow)", WK_GIBD, a_msd_init, {8, 1000, 4, 3}, 0, HCBD_ERR_PARAM,
     NULL}, /* 999 10^9 slots */
    {"msd_diffusion lag_min > lag_max", WK_GIBD, a_msd_diffusion, {3, 1, 100}, 0, HCBD_ERR_PARAM, NULL},
    {"msd_diffusion lag_min = nan", WK_GIBD, a_msd_diffusion, {NAN, 3, 100}, 0, HCBD_ERR_PARAM, NULL},
    {"msd_diffusion one lag in the window", WK_GIBD, a_msd_diffusion, {2, 2.5, 100}, 0, HCBD_ERR_STATE, NULL},
    {"msd_diffusion before a block closes", WK_GIBD, a_msd_diffusion, {1, 3, 49, 1, 50}, 0, HCBD_ERR_STATE,
     NULL},
    {"profile_init nslab = 0", WK_GIBD, a_profile, {0, 10}, 0, HCBD_ERR_PARAM, NULL},
    {"profile_init nslab = 2^20 + 1", WK_GIBD, a_profile, {(1 << 20) + 1, 10}, 0, HCBD_ERR_PARAM, NULL},
    {"profile_init block = 0", WK_GIBD, a_profile, {10, 0}, 0, HCBD_ERR_PARAM, NULL},
    {"profile_init pr NULL", WK_GIBD, a_profile, {10, 10}, NUL(1), HCBD_ERR_NULL, NULL},
    {"profile_init w NULL", WK_GIBD, a_profile, {10, 10}, NUL(2), HCBD_ERR_NULL, NULL},
    {"profile_init mem NULL", WK_GIBD, a_profile, {10, 10}, NUL(5), HCBD_ERR_NULL, NULL},
    {"profile_init bytes too few", WK_GIBD, a_profile, {10, 10}, SHORT, HCBD_ERR_MEMORY, NULL},
    {"slabs_init nslab = 0", WK_GIBD, a_slabs, {10, 0, 1, 10}, 0, HCBD_ERR_PARAM, NULL},
    {"slabs_init nval = -1", WK_GIBD, a_slabs, {10, 10, -1, 10}, 0, HCBD_ERR_PARAM, NULL},
    {"slabs_init nval = 65", WK_GIBD, a_slabs, {10, 10, 65, 10}, 0, HCBD_ERR_PARAM, NULL},
    {"slabs_init block = 0", WK_GIBD, a_slabs, {10, 10, 1, 0}, 0, HCBD_ERR_PARAM, NULL},
    {"slabs_init L[1] = nan", WK_GIBD, a_slabs, {NAN, 10, 1, 10}, 0, HCBD_ERR_PARAM, NULL},
    {"slabs_init L[1] = -1", WK_GIBD, a_slabs, {-1, 10, 1, 10}, 0, HCBD_ERR_PARAM, NULL},
    {"slabs_init L[1] = inf", WK_GIBD, a_slabs, {INFINITY, 10, 1, 10}, 0, HCBD_ERR_PARAM, NULL},
    {"slabs_init L NULL", WK_GIBD, a_slabs, {10, 10, 1, 10}, NUL(2), HCBD_ERR_NULL, NULL},
    {"slabs_init bytes too few", WK_GIBD, a_slabs, {10, 10, 1, 10}, SHORT, HCBD_ERR_MEMORY, NULL},
    {"carreau_fit good curve", WK_GIBD, a_carreau, {6}, 0, HCBD_OK, NULL},
    {"carreau_fit n_points = 3", WK_GIBD, a_carreau, {3}, 0, HCBD_ERR_PARAM, NULL},
    {"carreau_fit n_points = 0", WK_GIBD, a_carreau, {0}, 0, HCBD_ERR_PARAM, NULL},
    {"carreau_fit gdot[2] = -1", WK_GIBD, a_carreau, {6, CURVE(gdot[2]), -1}, 0, HCBD_ERR_PARAM, NULL},
    {"carreau_fit gdot[2] = 0", WK_GIBD, a_carreau, {6, CURVE(gdot[2]), 0}, 0, HCBD_ERR_PARAM, NULL},
    {"carreau_fit gdot[2] = inf", WK_GIBD, a_carreau, {6, CURVE(gdot[2]), INFINITY}, 0, HCBD_ERR_PARAM, NULL},
    {"carreau_fit gdot[2] = nan", WK_GIBD, a_carreau, {6, CURVE(gdot[2]), NAN}, 0, HCBD_ERR_PARAM, NULL},
    {"carreau_fit eta[3] = nan", WK_GIBD, a_carreau, {6, CURVE(eta[3]), NAN}, 0, HCBD_ERR_PARAM, NULL},
    {"carreau_fit err[1] = 0", WK_GIBD, a_carreau, {6, CURVE(err[1]), 0}, 0, HCBD_ERR_PARAM, NULL},
    {"carreau_fit err[1] = -0.1", WK_GIBD, a_carreau, {6, CURVE(err[1]), -0.1}, 0, HCBD_ERR_PARAM, NULL},
    {"carreau_fit eta_inf = nan", WK_GIBD, a_carreau, {6, CURVE(eta_inf), NAN}, 0, HCBD_ERR_PARAM, NULL},
    {"carreau_fit eta_inf = inf", WK_GIBD, a_carreau, {6, CURVE(eta_inf), INFINITY}, 0, HCBD_ERR_PARAM, NULL},
    {"carreau_fit start p[0] = nan", WK_GIBD, a_carreau, {6, CURVE(p[0]), NAN}, 0, HCBD_ERR_PARAM, NULL},
    {"carreau_fit start p[1] = -1", WK_GIBD, a_carreau, {6, CURVE(p[1]), -1}, 0, HCBD_ERR_PARAM, NULL},
    {"carreau_fit start p[1] = 0", WK_GIBD, a_carreau, {6, CURVE(p[1]), 0}, 0, HCBD_ERR_PARAM, NULL},
    {"carreau_fit start p[2] = inf", WK_GIBD, a_carreau, {6, CURVE(p[2]), INFINITY}, 0, HCBD_ERR_PARAM, NULL},
    {"carreau_fit gdot NULL", WK_GIBD, a_carreau, {6}, NUL(1), HCBD_ERR_NULL, NULL},
    {"carreau_fit p NULL", WK_GIBD, a_carreau, {6}, NUL(7), HCBD_ERR_NULL, NULL},
    {"stability p NULL", WK_GIBD, a_stability, {0}, NUL(1), HCBD_ERR_NULL, NULL},
    {"stability out NULL", WK_GIBD, a_stability, {0}, NUL(2), HCBD_ERR_NULL, NULL},
    {"stability n NULL", WK_GIBD, a_stability, {0}, NUL(3), HCBD_ERR_NULL, NULL},
    {"stability of a valid BD scene", WK_BD, a_stability, {0}, 0, HCBD_OK, NULL},
    {"theory_of p NULL", WK_GIBD, a_theory, {0}, NUL(1), HCBD_ERR_NULL, NULL},
    {"theory_of t NULL", WK_GIBD, a_theory, {0}, NUL(2), HCBD_ERR_NULL, NULL},
#if HCBD_MODEL == HCBD_MODEL_WALLED
    /* walls 2 thick in a box 12.9 high */
    {"set_positions particle 5 inside the bottom wall", WK_WALL, a_setpos_at, {3 * 5 + 1, 0.5}, 0,
     HCBD_ERR_WALL, "particle 5|y = 0.5|inside a wall"},
    {"set_positions particle 0 inside the top wall", WK_WALL, a_setpos_at, {3 * 0 + 1, 12.0}, 0,
     HCBD_ERR_WALL, "particle 0|y = 12|inside a wall"},
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
    BAD(HD(rho, 0)), BAD(HD(rho, -1)), BAD(HD(rho, NAN)), BAD(HD(rho, INFINITY)),
    BAD(HD(nbar, 0)), BAD(HD(nbar, NAN)), BAD(HD(nbar, INFINITY)),
    BAD(HD(eta, -1)), BAD(HD(eta, NAN)), BAD(HD(eta, INFINITY)),
    BAD(HD(P0, -1)), BAD(HD(P0, NAN)),
    BAD(HD(h, 0)), BAD(HD(h, -1)), BAD(HD(h, NAN)), BAD(HD(h, INFINITY)),
    {HB_DEF, NOSET, HD(h, 2.5), HCBD_ERR_BOX, "2h = 5"},
    BAD(HI(fluctuations, 2)), BAD(HI(fluctuations, -1)),
    BAD(HD(g[0], NAN)), BAD(HD(g[2], INFINITY)),
    BAD(HI(reverse_poiseuille, 2)),
    BAD_IN(HB_RP, HD(gdot, 1)),
    BAD(HD(gdot, 1000000)), /* offset > L per step */
    BAD(HD(rc, 0)), BAD(HD(rc, -1)), BAD(HD(rc, NAN)), BAD(HD(rc, INFINITY)),
    {HB_DEF, NOSET, HD(rc, 4.5), HCBD_ERR_BOX, "rc = 4.5"},
    BAD(HD(sigma, 2.5)), /* = rc */
    BAD(HD(alpha, -1)), BAD(HD(alpha, NAN)), BAD(HD(alpha, INFINITY)),
    BAD(HD(tau_lambda, 0)), BAD(HD(tau_lambda, -1)), BAD(HD(tau_lambda, NAN)), BAD(HD(tau_lambda, INFINITY)),
    BAD(HD(p_kuhn, -1)), BAD(HD(p_kuhn, NAN)), BAD(HD(p_kuhn, INFINITY)),
    BAD(HD(n_max, 0)), BAD(HD(n_max, -1)), BAD(HD(n_max, NAN)), BAD(HD(n_max, INFINITY)),
    BAD(HD(chi, NAN)), BAD(HD(chi, INFINITY)),
    BAD(HE(coupling, 2)), BAD(HE(coupling, -1)),
    BAD(HI(substeps, 0)), BAD(HI(substeps, 1001)),
    BAD(HW(fluid_capacity, 1)), BAD(HW(fluid_capacity, -1)), BAD(HW(fluid_capacity, 268435457)),
    BAD(HW(polymer_capacity, -1)), BAD(HW(polymer_capacity, 268435457)),
    BAD(HW(pair_capacity, -2)), BAD(HW(pair_capacity, 1048577)),
};

enum { HK_FP, HK_EMPTY, HK_HOLE, HK_NMAX };
enum { BI_HNF = 125, BI_HNP = 20 }; /* fluid and polymer blobs of the test world (HK_FP) */
#define BI_HL (5 * HC_LATTICE_A)     /* its box edge, L[0] = L[1] = L[2] */

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
        r = hcbd_hc_world_place_fluid_lattice(w, BI_HNF);
        if (r == HCBD_OK) r = hcbd_hc_world_place_polymers_random(w, BI_HNP);
        if (r == HCBD_OK) r = hcbd_hc_world_step(w, 2);
    }
    if (r != HCBD_OK) {
        printf("    hc set-up: %s\n", w->err.msg);
        hcbd_hc_world_destroy(w);
        return 0;
    }
    return 1;
}

static void bi_fluid_xyz(const hcbd_hc_world *w, double *x, int n)
{
    int i;
    for (i = 0; i < n; ++i) {
        x[3 * i] = w->fx[i % w->nf];
        x[3 * i + 1] = w->fy[i % w->nf];
        x[3 * i + 2] = w->fz[i % w->nf];
    }
}
/* set_fluid(w, n, xyz, NULL) of the world's fluid positions, repeated past
   its own blobs */
static hcbd_result a_fluid(bi_ctx *c)
{
    static double xyz[3 * 130];
    int n = I(0);
    bi_fluid_xyz(c->w, xyz, n < 130 ? (n > 0 ? n : 0) : 130);
    return hcbd_hc_world_set_fluid(WARG(1), n, ARG(3, xyz), NULL);
}
/* set_fluid(w, all, xyz, NULL) with xyz[i] = v, or set_fluid(w, all, xyz, u)
   with u zero but u[i] = v (a_fluid_vel); a = {i, v} */
static hcbd_result bi_fluid_at(bi_ctx *c, int vel)
{
    static double xyz[3 * BI_HNF], u[3 * BI_HNF];
    bi_fluid_xyz(c->w, xyz, BI_HNF);
    memset(u, 0, sizeof u);
    (vel ? u : xyz)[I(0)] = A(1);
    return hcbd_hc_world_set_fluid(c->w, BI_HNF, xyz, vel ? u : NULL);
}
static hcbd_result a_fluid_at(bi_ctx *c) { return bi_fluid_at(c, 0); }
static hcbd_result a_fluid_vel(bi_ctx *c) { return bi_fluid_at(c, 1); }
static hcbd_result a_fluid_lattice(bi_ctx *c) { return hcbd_hc_world_place_fluid_lattice(WARG(1), I(0)); }
/* polymer positions: the world's first n, the rest crowded within 0.06 of
   (0.5, 0.5, 0.5), enough to overfill phi or the pair list */
static double *bi_poly_xyz(const hcbd_hc_world *w, int n)
{
    static double x[3 * 210];
    int k;
    for (k = 0; k < 3 * 210; ++k) x[k] = 0.5 + 0.01 * (k % 7);
    for (k = 0; k < BI_HNP && k < n; ++k) {
        x[3 * k] = w->px[k];
        x[3 * k + 1] = w->py[k];
        x[3 * k + 2] = w->pz[k];
    }
    return x;
}
/* set_polymers(w, n, xyz) */
static hcbd_result a_poly(bi_ctx *c)
{
    return hcbd_hc_world_set_polymers(WARG(1), I(0), ARG(3, bi_poly_xyz(c->w, I(0))));
}
/* set_polymers(w, all, xyz) with xyz[i] = v; a = {i, v} */
static hcbd_result a_poly_at(bi_ctx *c)
{
    double *x = bi_poly_xyz(c->w, BI_HNP);
    x[I(0)] = A(1);
    return hcbd_hc_world_set_polymers(c->w, BI_HNP, x);
}
/* set_polymers(w, np + 1, xyz): the world's polymers and one more at a */
static hcbd_result a_poly_add(bi_ctx *c)
{
    const hcbd_hc_world *w = c->w;
    double x[3 * (BI_HNP + 1)];
    int k;
    for (k = 0; k < w->np && k < BI_HNP; ++k) {
        x[3 * k] = w->px[k];
        x[3 * k + 1] = w->py[k];
        x[3 * k + 2] = w->pz[k];
    }
    x[3 * k] = A(0);
    x[3 * k + 1] = A(1);
    x[3 * k + 2] = A(2);
    return hcbd_hc_world_set_polymers(c->w, k + 1, x);
}
static hcbd_result a_poly_random(bi_ctx *c) { return hcbd_hc_world_place_polymers_random(WARG(1), I(0)); }
static hcbd_result a_refresh(bi_ctx *c) { return hcbd_hc_world_refresh(WARG(1)); }
/* pair variables: b = PAIR_SOME (PAIR_NONE), the first partner of a = 0
   that has (has not) one; HCBD_ERR_MODEL when the test world has none */
enum { PAIR_SOME = -100, PAIR_NONE = -101 };
static int bi_partner(const hcbd_hc_world *w, double b, int *out)
{
    int k;
    if (b != PAIR_SOME && b != PAIR_NONE) {
        *out = (int)b;
        return 1;
    }
    for (k = 1; k < w->np; ++k) {
        double l;
        if ((hcbd_hc_world_get_lambda(w, 0, k, &l) == HCBD_OK) == (b == PAIR_SOME)) {
            *out = k;
            return 1;
        }
    }
    return 0;
}
/* get_lambda(w, a, b, lambda) */
static hcbd_result a_lambda(bi_ctx *c)
{
    double l;
    int b;
    if (!bi_partner(c->w, A(1), &b)) return NOMSG(HCBD_ERR_MODEL);
    return NOMSG(hcbd_hc_world_get_lambda(ARG(1, c->w), I(0), b, ARG(4, &l)));
}
/* set_lambda(w, a, b, lambda) */
static hcbd_result a_set_lambda(bi_ctx *c)
{
    int b;
    if (!bi_partner(c->w, A(1), &b)) return HCBD_ERR_MODEL;
    return hcbd_hc_world_set_lambda(WARG(1), I(0), b, A(2));
}
static hcbd_result a_density_range(bi_ctx *c)
{
    double out[3];
    return NOMSG(hcbd_hc_world_density_range(c->w, ARG(2, out)));
}
/* hc_params_theory(p, t) of the base with one parameter spoilt; a =
   {HCPAR(field), value} */
#define HCPAR(f) FIELD(hcbd_hc_params, f)
static hcbd_result a_hc_theory(bi_ctx *c)
{
    hcbd_hc_world_def d = bi_hc_base(HB_DEF);
    hcbd_hc_theory t;
    bi_poke(&d.params, A(0), A(1));
    return NOMSG(hcbd_hc_params_theory(ARG(1, &d.params), ARG(2, &t)));
}
static hcbd_result a_hc_stability(bi_ctx *c)
{
    hcbd_limit out[HCBD_MAX_LIMITS];
    int n;
    return NOMSG(hcbd_hc_params_stability(ARG(1, &((hcbd_hc_world *)c->w)->p), ARG(2, out), ARG(3, &n)));
}
/* hc_si_params(si, time_unit, p, msg) of the default units with one
   spoilt; a = {time_unit, SI(field), value} */
#define SI(f) FIELD(hcbd_hc_si, f)
static hcbd_result a_si(bi_ctx *c)
{
    hcbd_hc_si si = hcbd_hc_si_default();
    hcbd_hc_params p;
    bi_poke(&si, A(1), A(2));
    strcpy(bi_msg, "(untouched)");
    c->msg = bi_msg;
    return hcbd_hc_si_params(ARG(1, &si), A(0), &p, bi_msg, sizeof bi_msg);
}

static const bi_call bi_hcalls[] = {
    {"set_fluid w NULL", HK_FP, a_fluid, {2}, NUL(1), HCBD_ERR_NULL, NULL},
    {"set_fluid xyz NULL", HK_FP, a_fluid, {BI_HNF}, NUL(3), HCBD_ERR_NULL, "xyz is NULL"},
    {"set_fluid n = 1", HK_FP, a_fluid, {1}, 0, HCBD_ERR_PARAM, "N = 1"},
    {"set_fluid n = -1", HK_FP, a_fluid, {-1}, 0, HCBD_ERR_PARAM, "N = -1"},
    {"set_fluid n = 126 > capacity", HK_FP, a_fluid, {126}, 0, HCBD_ERR_CAPACITY, "N = 126"},
    {"set_fluid y NaN", HK_FP, a_fluid_at, {3 * 4 + 1, NAN}, 0, HCBD_ERR_NONFINITE, "fluid blob 4|nan"},
    {"set_fluid x = L", HK_FP, a_fluid_at, {3 * 4, BI_HL}, 0, HCBD_ERR_PARAM, "fluid blob 4|outside the box"},
    {"set_fluid z = -0.5", HK_FP, a_fluid_at, {3 * 4 + 2, -0.5}, 0, HCBD_ERR_PARAM, "fluid blob 4|-0.5"},
    {"set_fluid v NaN", HK_FP, a_fluid_vel, {3 * 3, NAN}, 0, HCBD_ERR_NONFINITE, "fluid blob 3|nan"},
    {"place_fluid_lattice n = 126 > capacity", HK_FP, a_fluid_lattice, {126}, 0, HCBD_ERR_CAPACITY, "N = 126"},
    {"place_fluid_lattice n = 0", HK_FP, a_fluid_lattice, {0}, 0, HCBD_ERR_PARAM, "N = 0"},
    {"place_fluid_lattice w NULL", HK_FP, a_fluid_lattice, {8}, NUL(1), HCBD_ERR_NULL, NULL},
    {"set_polymers n = 201 > capacity", HK_FP, a_poly, {201}, 0, HCBD_ERR_CAPACITY, "N = 201"},
    {"set_polymers n = -1", HK_FP, a_poly, {-1}, 0, HCBD_ERR_PARAM, "N = -1"},
    {"set_polymers xyz NULL", HK_FP, a_poly, {5}, NUL(3), HCBD_ERR_NULL, "xyz is NULL"},
    {"set_polymers w NULL", HK_FP, a_poly, {0}, NUL(1) | NUL(3), HCBD_ERR_NULL, NULL},
    {"set_polymers y NaN", HK_FP, a_poly_at, {3 * 2 + 1, NAN}, 0, HCBD_ERR_NONFINITE, "polymer blob 2|nan"},
    {"set_polymers x = -0.25", HK_FP, a_poly_at, {3 * 2, -0.25}, 0, HCBD_ERR_PARAM, "polymer blob 2|-0.25"},
    /* phi = n / n_max >= 1 in the corner */
    {"set_polymers phi >= 1", HK_FP, a_poly, {200}, 0, HCBD_ERR_PARAM, "phi|>= 1"},
    /* n_max huge: the corner's 100 have more partners than pair_capacity */
    {"set_polymers more partners than pair_capacity", HK_NMAX, a_poly, {100}, 0, HCBD_ERR_CAPACITY,
     "pair_capacity"},
    /* the fluid fills 0.05 L <= x <= 0.45 L and z <= 0.5 L */
    {"set_polymers polymer without fluid within rc", HK_HOLE, a_poly_add, {0.75 * BI_HL, 0.5 * BI_HL, 0.8 * BI_HL},
     0, HCBD_ERR_PARAM, "polymer 5|no fluid blob within rc = 2.5"},
    {"place_polymers_random n = 201 > capacity", HK_FP, a_poly_random, {201}, 0, HCBD_ERR_CAPACITY, "N = 201"},
    {"place_polymers_random n = -1", HK_FP, a_poly_random, {-1}, 0, HCBD_ERR_PARAM, "N = -1"},
    {"place_polymers_random w NULL", HK_FP, a_poly_random, {1}, NUL(1), HCBD_ERR_NULL, NULL},
    {"set_polymers before the fluid", HK_EMPTY, a_poly_add, {1, 1, 1}, 0, HCBD_ERR_STATE, "fluid"},
    {"place_polymers_random before the fluid", HK_EMPTY, a_poly_random, {1}, 0, HCBD_ERR_STATE, "fluid"},
    {"refresh before the fluid", HK_EMPTY, a_refresh, {0}, 0, HCBD_ERR_STATE, "fluid"},
    {"refresh w NULL", HK_FP, a_refresh, {0}, NUL(1), HCBD_ERR_NULL, NULL},
    {"step before the fluid", HK_EMPTY, a_step, {1}, 0, HCBD_ERR_STATE, "fluid"},
    {"lambda out NULL", HK_FP, a_lambda, {0, PAIR_SOME}, NUL(4), HCBD_ERR_NULL, NULL},
    {"lambda w NULL", HK_FP, a_lambda, {0, 1}, NUL(1), HCBD_ERR_NULL, NULL},
    {"lambda a = -1", HK_FP, a_lambda, {-1, 1}, 0, HCBD_ERR_PARAM, NULL},
    {"lambda b = np", HK_FP, a_lambda, {0, BI_HNP}, 0, HCBD_ERR_PARAM, NULL},
    {"lambda a = b", HK_FP, a_lambda, {3, 3}, 0, HCBD_ERR_PARAM, NULL},
    {"lambda of a pair that does not exist", HK_FP, a_lambda, {0, PAIR_NONE}, 0, HCBD_ERR_STATE, NULL},
    {"set_lambda lambda = nan", HK_FP, a_set_lambda, {0, PAIR_SOME, NAN}, 0, HCBD_ERR_NONFINITE, "lambda = nan"},
    {"set_lambda lambda = -inf", HK_FP, a_set_lambda, {0, PAIR_SOME, -INFINITY}, 0, HCBD_ERR_NONFINITE,
     "lambda = -inf"},
    {"set_lambda a = -1", HK_FP, a_set_lambda, {-1, 1, 0.5}, 0, HCBD_ERR_PARAM, "a = -1"},
    {"set_lambda b = 20 = np", HK_FP, a_set_lambda, {0, 20, 0.5}, 0, HCBD_ERR_PARAM, "b = 20"},
    {"set_lambda a = b", HK_FP, a_set_lambda, {3, 3, 0.5}, 0, HCBD_ERR_PARAM, "a = 3|b = 3"},
    {"set_lambda of a pair that does not exist", HK_FP, a_set_lambda, {0, PAIR_NONE, 0.5}, 0, HCBD_ERR_STATE,
     "no pair variable"},
    {"set_lambda w NULL", HK_FP, a_set_lambda, {0, 1, 0.5}, NUL(1), HCBD_ERR_NULL, NULL},
    {"density_range out NULL", HK_FP, a_density_range, {0}, NUL(2), HCBD_ERR_NULL, NULL},
    {"density_range before the fluid", HK_EMPTY, a_density_range, {0}, 0, HCBD_ERR_STATE, NULL},
    {"theory_of eta = nan", HK_FP, a_hc_theory, {HCPAR(eta), NAN}, 0, HCBD_ERR_PARAM, NULL},
    {"theory_of eta = -1", HK_FP, a_hc_theory, {HCPAR(eta), -1}, 0, HCBD_ERR_PARAM, NULL},
    {"theory_of rho = inf", HK_FP, a_hc_theory, {HCPAR(rho), INFINITY}, 0, HCBD_ERR_PARAM, NULL},
    {"theory_of P0 = -1", HK_FP, a_hc_theory, {HCPAR(P0), -1}, 0, HCBD_ERR_PARAM, NULL},
    {"theory_of g[0] = nan", HK_FP, a_hc_theory, {HCPAR(g[0]), NAN}, 0, HCBD_ERR_PARAM, NULL},
    {"theory_of p NULL", HK_FP, a_hc_theory, {0}, NUL(1), HCBD_ERR_NULL, NULL},
    {"theory_of t NULL", HK_FP, a_hc_theory, {0}, NUL(2), HCBD_ERR_NULL, NULL},
    {"stability out NULL", HK_FP, a_hc_stability, {0}, NUL(2), HCBD_ERR_NULL, NULL},
    {"params_si time_unit = 0", HK_FP, a_si, {0}, 0, HCBD_ERR_PARAM, "time_unit = 0"},
    {"params_si time_unit = nan", HK_FP, a_si, {NAN}, 0, HCBD_ERR_PARAM, "time_unit = nan"},
    {"params_si si.sigma = nan", HK_FP, a_si, {1e-6, SI(sigma), NAN}, 0, HCBD_ERR_PARAM, "sigma = nan"},
    {"params_si si.T = -1", HK_FP, a_si, {1e-6, SI(T), -1}, 0, HCBD_ERR_PARAM, "T = -1"},
    {"params_si si.rho = inf", HK_FP, a_si, {1e-6, SI(rho), INFINITY}, 0, HCBD_ERR_PARAM, "rho = inf"},
    {"params_si si.dt = 0", HK_FP, a_si, {1e-6, SI(dt), 0}, 0, HCBD_ERR_PARAM, "dt = 0"},
    {"params_si si NULL", HK_FP, a_si, {1e-6}, NUL(1), HCBD_ERR_NULL, "si"},
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
#define BI_NOFILE "/nonexistent-hcbd-dir/missing.chk"
#define BI_NODIR "/nonexistent-hcbd-dir/x.chk"

/* load into a fresh world of K, from the buffer (size bytes) or, with
   path, the file; its message into bi_msg */
static hcbd_result bi_load(bi_ctx *c, const void *buf, size_t size, int path)
{
    const bi_kind *K = c->K;
    void *v = calloc(1, K->world_size);
    hcbd_result r = HCBD_ERR_MEMORY;
    c->msg = bi_msg;
    if (!v) return r;
    r = path ? K->load(v, ARG(2, BI_NOFILE)) : K->ck_load(v, buf, size);
    snprintf(bi_msg, sizeof bi_msg, "%s", K->err(v)->msg);
    if (r == HCBD_OK) K->destroy(v);
    free(v);
    return r;
}
/* checkpoint_save(w, buf, size) */
static hcbd_result a_ck_save(bi_ctx *c) { return c->K->ck_save(c->w, ARG(2, bi_ck), (size_t)A(0)); }
/* checkpoint_load(fresh, buf, size): size bytes of fill; a = {size, fill} */
static hcbd_result a_ck_load(bi_ctx *c)
{
    if (!(c->row->flags & NUL(2))) memset(bi_ck, I(1), (size_t)A(0));
    return bi_load(c, ARG(2, bi_ck), (size_t)A(0), 0);
}
/* checkpoint_load(fresh, buf, keep n) of the world's own checkpoint of n
   bytes with byte at n + off ^= bit; a = {keep, at, off, bit} */
static hcbd_result a_ck_spoilt(bi_ctx *c)
{
    size_t n = c->K->ck_size(c->w);
    if (n == 0 || n > sizeof bi_ck || c->K->ck_save(c->w, bi_ck, n) != HCBD_OK) {
        c->msg = bi_msg;
        return HCBD_ERR_MODEL;
    }
    bi_ck[(size_t)(A(1) * (double)n + A(2))] ^= (unsigned char)I(3);
    return bi_load(c, bi_ck, (size_t)(A(0) * (double)n), 0);
}
static hcbd_result a_load(bi_ctx *c) { return bi_load(c, NULL, 0, 1); }
static hcbd_result a_save(bi_ctx *c) { return c->K->save(c->w, ARG(2, BI_NODIR)); }

/* the checkpoint calls of both worlds */
static const bi_call bi_both_io[] = {
    {"checkpoint_save 16-byte buffer", 0, a_ck_save, {16}, 0, HCBD_ERR_MEMORY, "16"},
    {"checkpoint_save size 0", 0, a_ck_save, {0}, 0, HCBD_ERR_MEMORY, "0"},
    {"checkpoint_save buf NULL", 0, a_ck_save, {1 << 16}, NUL(2), HCBD_ERR_NULL, "buf"},
    {"checkpoint_load buf NULL", 0, a_ck_load, {1 << 16}, NUL(2), HCBD_ERR_NULL, "buffer is NULL"},
    {"checkpoint_load size 0", 0, a_ck_load, {0}, 0, HCBD_ERR_FORMAT, NULL},
    {"checkpoint_load garbage", 0, a_ck_load, {4096, 0xAB}, 0, HCBD_ERR_FORMAT, NULL},
    {"checkpoint_load truncated", 0, a_ck_spoilt, {0.5}, 0, HCBD_ERR_FORMAT, NULL},
    /* one bit in the middle, one near the end (the trailer) */
    {"checkpoint_load one bit flipped", 0, a_ck_spoilt, {1, 0.5, 0, 0x04}, 0, HCBD_ERR_FORMAT, NULL},
    {"checkpoint_load one bit flipped near the end", 0, a_ck_spoilt, {1, 1, -9, 0x10}, 0, HCBD_ERR_FORMAT, NULL},
    {"load missing file", 0, a_load, {0}, 0, HCBD_ERR_IO, BI_NOFILE},
    {"load path NULL", 0, a_load, {0}, NUL(2), HCBD_ERR_NULL, "path"},
    {"save into a missing directory", 0, a_save, {0}, 0, HCBD_ERR_IO, BI_NODIR},
    {"save path NULL", 0, a_save, {0}, NUL(2), HCBD_ERR_NULL, "path"},
};

/* argument k, a temporary file or NULL; 0: no file to be had */
static int bi_file(bi_ctx *c, int k, FILE **f)
{
    *f = ARG(k, tmpfile());
    return *f || c->row->flags & NUL(k);
}
/* write_xyz(w, f, ids = {0, id}, nids); a = {id, nids} */
static hcbd_result a_xyz(bi_ctx *c)
{
    int ids[2] = {0, 0};
    FILE *f;
    hcbd_result r = HCBD_ERR_MODEL;
    ids[1] = I(0);
    if (bi_file(c, 2, &f)) r = hcbd_world_write_xyz(c->w, f, ARG(3, ids), I(1));
    if (f) fclose(f);
    return NOMSG(r);
}
static hcbd_result a_offenders(bi_ctx *c)
{
    FILE *f;
    hcbd_result r = bi_file(c, 2, &f) ? hcbd_world_write_offenders(c->w, f) : HCBD_ERR_MODEL;
    if (f) fclose(f);
    return NOMSG(r);
}

static const bi_call bi_iocalls[] = {
    {"xyz_write f NULL", WK_GIBD, a_xyz, {0, 0}, NUL(2) | NUL(3), HCBD_ERR_NULL, NULL},
    {"xyz_write ids[1] = 64 = n", WK_GIBD, a_xyz, {64, 2}, 0, HCBD_ERR_PARAM, NULL},
    {"xyz_write ids[1] = -1", WK_GIBD, a_xyz, {-1, 2}, 0, HCBD_ERR_PARAM, NULL},
    {"xyz_write nids = -1", WK_GIBD, a_xyz, {1, -1}, 0, HCBD_ERR_PARAM, NULL},
    {"xyz_offenders f NULL", WK_GIBD, a_offenders, {0}, NUL(2), HCBD_ERR_NULL, NULL},
};

#if HCBD_MODEL == HCBD_MODEL_HCBD
/* set-up no row can hold: a GI-BD world's checkpoint, loaded into a fresh
   2018 world */
static hcbd_result a_gibd_checkpoint(bi_ctx *c)
{
    hcbd_world g;
    hcbd_result r;
    size_t n;
    c->msg = bi_msg;
    if (!bi_make(&g, WK_GIBD)) return HCBD_ERR_STATE;
    n = hcbd_world_checkpoint_size(&g);
    r = n > 0 && n <= sizeof bi_ck ? hcbd_world_checkpoint_save(&g, bi_ck, n) : HCBD_ERR_MEMORY;
    hcbd_world_destroy(&g);
    if (r != HCBD_OK) return HCBD_ERR_STATE;
    return bi_load(c, bi_ck, n, 0);
}
static hcbd_result a_hc_xyz(bi_ctx *c)
{
    FILE *f;
    hcbd_result r = bi_file(c, 2, &f) ? hcbd_hc_world_write_xyz(c->w, f) : HCBD_ERR_MODEL;
    if (f) fclose(f);
    return NOMSG(r);
}

static const bi_call bi_hiocalls[] = {
    {"checkpoint_load of a GI-BD checkpoint", HK_FP, a_gibd_checkpoint, {0}, 0, HCBD_ERR_MODEL, NULL},
    {"xyz_write f NULL", HK_FP, a_hc_xyz, {0}, NUL(2), HCBD_ERR_NULL, NULL},
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

/* the calls both worlds have, through the kind's functions */
static hcbd_result a_step(bi_ctx *c) { return c->K->step(WARG(1), I(0)); }
/* world_init(w, def, mem, bytes) of the kind's base into a fresh world (the
   row's is made already), bytes: what it needs less a[0] */
static hcbd_result a_init(bi_ctx *c)
{
    const bi_kind *K = c->K;
    void *v = calloc(1, K->world_size), *d = malloc(K->def_size), *mem = NULL;
    hcbd_result r = HCBD_ERR_MODEL;
    if (v && d) {
        size_t need;
        K->base(d, 0);
        need = K->bytes(d);
        mem = malloc(need);
        if (mem) r = K->init(ARG(1, v), d, ARG(3, mem), need - (size_t)A(0));
        snprintf(bi_msg, sizeof bi_msg, "%s", K->err(v)->msg);
    }
    c->msg = c->row->flags & NUL(1) ? NULL : bi_msg;
    free(mem);
    free(d);
    free(v);
    return r;
}
/* world_create(w, def) of the kind's base into a fresh world */
static hcbd_result a_create(bi_ctx *c)
{
    const bi_kind *K = c->K;
    void *v = calloc(1, K->world_size), *d = malloc(K->def_size);
    hcbd_result r = HCBD_ERR_MODEL;
    if (v && d) {
        K->base(d, 0);
        r = K->create(ARG(1, v), ARG(2, d));
        snprintf(bi_msg, sizeof bi_msg, "%s", K->err(v)->msg);
        if (r == HCBD_OK) K->destroy(v);
    }
    c->msg = c->row->flags & NUL(1) ? NULL : bi_msg;
    free(d);
    free(v);
    return r;
}
/* params_check(p, msg) of the kind's base parameters */
static hcbd_result a_check(bi_ctx *c)
{
    const bi_kind *K = c->K;
    char *d = malloc(K->def_size);
    hcbd_result r = HCBD_ERR_MODEL;
    strcpy(bi_msg, "(untouched)");
    c->msg = bi_msg;
    if (d) {
        K->base(d, 0);
        r = K->check(ARG(1, d + K->params_off), bi_msg, sizeof bi_msg);
    }
    free(d);
    return r;
}
static hcbd_result a_stress_enable(bi_ctx *c) { return c->K->stress_enable(WARG(1), I(0)); }
/* stress_read(w, out, nsteps) */
static hcbd_result a_stress_read(bi_ctx *c)
{
    double out[16];
    int64_t n;
    return NOMSG(c->K->stress_read(c->w, ARG(2, out), ARG(3, &n)));
}
/* transverse_current(w, nk, out) */
static hcbd_result a_tc(bi_ctx *c)
{
    double out[12];
    return NOMSG(c->K->tc(c->w, I(0), ARG(3, out)));
}

static const bi_call bi_both_calls[] = {
    {"step nsteps = -1", 0, a_step, {-1}, 0, HCBD_ERR_PARAM, "nsteps = -1"},
    {"step nsteps = INT_MIN", 0, a_step, {INT_MIN}, 0, HCBD_ERR_PARAM, "nsteps = -2147483648"},
    {"step w NULL", 0, a_step, {1}, NUL(1), HCBD_ERR_NULL, NULL},
    {"world_init mem NULL", 0, a_init, {0}, NUL(3), HCBD_ERR_NULL, "memory block"},
    {"world_init bytes too few", 0, a_init, {64}, 0, HCBD_ERR_MEMORY, "bytes"},
    {"world_init w NULL", 0, a_init, {0}, NUL(1), HCBD_ERR_NULL, NULL},
    {"world_create w NULL", 0, a_create, {0}, NUL(1), HCBD_ERR_NULL, NULL},
    {"world_create def NULL", 0, a_create, {0}, NUL(2), HCBD_ERR_NULL, "definition"},
    {"params_check p NULL", 0, a_check, {0}, NUL(1), HCBD_ERR_NULL, "params"},
    {"stress_enable on = 2", 0, a_stress_enable, {2}, 0, HCBD_ERR_PARAM, "on = 2"},
    {"stress_enable on = -1", 0, a_stress_enable, {-1}, 0, HCBD_ERR_PARAM, "on = -1"},
    {"stress_enable w NULL", 0, a_stress_enable, {1}, NUL(1), HCBD_ERR_NULL, NULL},
    {"stress_read out NULL", 0, a_stress_read, {0}, NUL(2) | NUL(3), HCBD_ERR_NULL, NULL},
    {"transverse_current nk = 0", 0, a_tc, {0}, 0, HCBD_ERR_PARAM, NULL},
    {"transverse_current nk = -1", 0, a_tc, {-1}, 0, HCBD_ERR_PARAM, NULL},
    {"transverse_current out NULL", 0, a_tc, {1}, NUL(3), HCBD_ERR_NULL, NULL},
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
    bi_defs(&bi_gibd, bi_params, BI_N(bi_params));
    bi_defs(&bi_gibd, bi_gboth, BI_N(bi_gboth));
    bi_summary("parameters and definitions");
    bi_run(&bi_gibd, bi_calls, BI_N(bi_calls));
    bi_run(&bi_gibd, bi_both_calls, BI_N(bi_both_calls));
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
    bi_defs(&bi_hc, bi_hparams, BI_N(bi_hparams));
    bi_defs(&bi_hc, bi_hboth, BI_N(bi_hboth));
    bi_summary("HCBD parameters and definitions");
    bi_run(&bi_hc, bi_hcalls, BI_N(bi_hcalls));
    bi_run(&bi_hc, bi_both_calls, BI_N(bi_both_calls));
    bi_summary("HCBD calls");
}
#endif

void test_bad_input_io(void)
{
    bi_run(&bi_gibd, bi_both_io, BI_N(bi_both_io));
    bi_run(&bi_gibd, bi_iocalls, BI_N(bi_iocalls));
    bi_summary("checkpoint and trajectory calls");
#if HCBD_MODEL == HCBD_MODEL_HCBD
    bi_run(&bi_hc, bi_both_io, BI_N(bi_both_io));
    bi_run(&bi_hc, bi_hiocalls, BI_N(bi_hiocalls));
    bi_summary("HCBD checkpoint and trajectory calls");
#endif
}
