/* Checkpoint/restart, extended XYZ frames, thermo lines and run-time
   guards of the GI-BD world (the HCBD world's are in test_hcbd.c). */
#define _POSIX_C_SOURCE 200809L /* getpid, mkdir under -std=c99 */
#include "test.h"
#include <sys/stat.h>
#include <unistd.h>

#define WALLS_BUILD (HCBD_MODEL == HCBD_MODEL_WALLED)

/* out/test_io/<pid>/name: make test runs several builds at once */
static const char *io_path(const char *name)
{
    static char p[4][256];
    static int k;
    char dir[128];
    snprintf(dir, sizeof dir, "out/test_io/%ld", (long)getpid());
    mkdir("out", 0755);
    mkdir("out/test_io", 0755);
    mkdir(dir, 0755);
    k = (k + 1) % 4;
    snprintf(p[k], sizeof p[k], "%s/%s", dir, name);
    return p[k];
}

/* FNV-1a 64 and little-endian words, written here independently of the
   library, to forge checkpoints whose checksum is right but whose
   content is not. */
static uint64_t fnv(const unsigned char *b, size_t n)
{
    uint64_t h = 0xCBF29CE484222325ULL;
    size_t k;
    for (k = 0; k < n; ++k) h = (h ^ b[k]) * 0x100000001B3ULL;
    return h;
}

static uint64_t get64(const unsigned char *b)
{
    uint64_t v = 0;
    int k;
    for (k = 0; k < 8; ++k) v |= (uint64_t)b[k] << (8 * k);
    return v;
}

static void put64(unsigned char *b, uint64_t v)
{
    int k;
    for (k = 0; k < 8; ++k) b[k] = (unsigned char)(v >> (8 * k));
}

static void reseal(unsigned char *b, size_t n) { put64(b + 48, fnv(b + 56, n - 56)); }

/* Scenes that exercise every piece of saved state: Lees-Edwards with the
   flux sums, lagged densities, the exact pair sweep, classical BD, a table
   potential and, in the walled build, a channel. */
enum { SC_SHEAR, SC_LAGGED, SC_SHARDLOW, SC_BD, SC_TABLE, SC_WALLS, SC_N };
static const char *sc_name[SC_N] = {"shear+flux", "lagged", "Shardlow", "BD", "table", "walls"};
static double tab_F[64], tab_V[64];

static int sc_make(hcbd_world *w, int sc, int threads)
{
    hcbd_world_def d = scene(512, 0.24);
    hcbd_params *p = &d.params;
    int k;
    p->threads = threads;
    p->seed = 11 + (uint64_t)sc;
    if (sc == SC_SHEAR) p->gdot = 2.0;
    if (sc == SC_LAGGED) p->lagged_density = 1;
    if (sc == SC_SHARDLOW) { p->pair_integrator = HCBD_PAIR_SHARDLOW; p->dt = 4e-4; }
    if (sc == SC_BD) p->dynamics = HCBD_DYN_BD;
    if (sc == SC_TABLE) {
        for (k = 0; k < 64; ++k) {
            double r = 0.5 + 2.0 * k / 63.0;
            tab_V[k] = 20.0 * exp(-r * r);
            tab_F[k] = 40.0 * r * exp(-r * r);
        }
        p->potential = HCBD_POT_TABLE;
        p->table_F = tab_F;
        p->table_V = tab_V;
        p->table_n = 64;
        p->table_r0 = 0.5;
    }
    if (sc == SC_WALLS) {
#if !WALLS_BUILD
        return 0;
#else
        p->wall.thickness = 2.0;
#endif
        p->fext[0] = 5.0;
        p->L[1] = 16.0;
    }
    if (!make_world(w, &d)) return 0;
    if (hcbd_world_place_lattice(w, 512) != HCBD_OK) {
        printf("    place: %s\n", w->err.msg);
        t_fail = 1;
        return 0;
    }
    if (sc == SC_SHEAR) hcbd_world_stress_enable(w, 1);
    return 1;
}

void test_checkpoint_restart_bits(void)
{
    const int n = t_quick ? 10 : 40;
    int sc;
    for (sc = 0; sc < SC_N; ++sc) {
        int t;
        for (t = 1; t <= 2; ++t) {
            hcbd_world a, b;
            unsigned char *buf;
            size_t size;
            uint64_t ca, cb;
            double fa[4], fb[4];
            if (!sc_make(&a, sc, 1)) continue;
            run(&a, n);
            size = hcbd_world_checkpoint_size(&a);
            buf = (unsigned char *)malloc(size);
            CHECK(hcbd_world_checkpoint_save(&a, buf, size) == HCBD_OK, "%s: %s", sc_name[sc], a.err.msg);
            run(&a, n);
            ca = hcbd_world_checksum(&a);
            /* the loaded world continues on t threads */
            if (hcbd_world_checkpoint_load(&b, buf, size) != HCBD_OK) {
                CHECK(0, "%s: load: %s", sc_name[sc], b.err.msg);
            } else {
                CHECK(b.step == n && b.n == 512, "%s: step %lld n %d", sc_name[sc], (long long)b.step, b.n);
                CHECK(!memcmp(&b.p.L, &a.p.L, sizeof a.p.L) && b.p.seed == a.p.seed &&
                          b.p.dt == a.p.dt && b.p.potential == a.p.potential,
                      "%s: parameters differ after load", sc_name[sc]);
                hcbd_world_set_threads(&b, t);
                run(&b, n);
                cb = hcbd_world_checksum(&b);
                CHECK(ca == cb, "%s, %d threads: 2n steps %llx, n + save + load + n %llx",
                      sc_name[sc], t, (unsigned long long)ca, (unsigned long long)cb);
                hcbd_world_stress_read(&a, fa, NULL);
                hcbd_world_stress_read(&b, fb, NULL);
                CHECK(!memcmp(fa, fb, sizeof fa), "%s: flux sums differ", sc_name[sc]);
                CHECK(a.wall_pen == b.wall_pen, "%s: wall penetrations %lld vs %lld", sc_name[sc],
                      (long long)a.wall_pen, (long long)b.wall_pen);
                hcbd_world_destroy(&b);
            }
            free(buf);
            hcbd_world_destroy(&a);
        }
    }
}

static void expect_load(const unsigned char *buf, size_t size, hcbd_result code,
                        const char *word, const char *what)
{
    hcbd_world w;
    hcbd_result r = hcbd_world_checkpoint_load(&w, buf, size);
    CHECK(r == code, "%s: %s (%s), expected %s", what, hcbd_result_name(r), w.err.msg,
          hcbd_result_name(code));
    CHECK(r != HCBD_OK || code == HCBD_OK, "%s loaded", what);
    CHECK(strstr(w.err.msg, word) != NULL, "%s: message '%s' lacks '%s'", what, w.err.msg, word);
    if (r == HCBD_OK) hcbd_world_destroy(&w);
}

void test_checkpoint_rejects_bad_files(void)
{
    hcbd_world w;
    unsigned char *buf, *bad;
    size_t size, k;
    uint64_t seed = 5;
    hcbd_rng g;
    char path[256];
    if (!sc_make(&w, SC_SHEAR, 1)) return;
    run(&w, 5);
    size = hcbd_world_checkpoint_size(&w);
    buf = (unsigned char *)malloc(size);
    bad = (unsigned char *)malloc(size + 8);
    CHECK(hcbd_world_checkpoint_save(&w, buf, size - 1) == HCBD_ERR_MEMORY, "short buffer accepted");
    CHECK(hcbd_world_checkpoint_save(&w, buf, size) == HCBD_OK, "%s", w.err.msg);
    expect_load(buf, size, HCBD_OK, "", "intact");
    /* truncated anywhere, including inside the header */
    hcbd_rng_seed(&g, seed);
    for (k = 0; k < 40; ++k) {
        size_t cut = k < 8 ? (size_t[]){0, 1, 8, 55, 56, 57, 64, size - 1}[k]
                           : (size_t)(hcbd_rng_uniform(&g) * (double)size);
        memcpy(bad, buf, cut);
        expect_load(bad, cut, HCBD_ERR_FORMAT, "checkpoint", "truncated");
    }
    /* one flipped bit anywhere in the payload or the stored checksum */
    for (k = 0; k < 40; ++k) {
        size_t at = 48 + (size_t)(hcbd_rng_uniform(&g) * (double)(size - 48));
        memcpy(bad, buf, size);
        bad[at] ^= (unsigned char)(1u << (k % 8));
        expect_load(bad, size, HCBD_ERR_FORMAT, "checksum", "flipped bit");
    }
    memcpy(bad, buf, size);
    bad[0] = 'X';
    expect_load(bad, size, HCBD_ERR_FORMAT, "HCBDCKPT", "magic");
    memcpy(bad, buf, size);
    put64(bad + 8, HCBD_CHECKPOINT_VERSION + 1);
    expect_load(bad, size, HCBD_ERR_VERSION, "version", "newer version");
    memcpy(bad, buf, size);
    put64(bad + 16, HCBD_MODEL == HCBD_MODEL_GIBD ? HCBD_MODEL_WALLED : HCBD_MODEL_GIBD);
    expect_load(bad, size, HCBD_ERR_MODEL, "model", "other model");
    memcpy(bad, buf, size);
    put64(bad + 24, sizeof(hcbd_real) == 8 ? 4 : 8);
    expect_load(bad, size, HCBD_ERR_MODEL, "precision", "other precision");
    memcpy(bad, buf, size);
    put64(bad + 32, 2);
    expect_load(bad, size, HCBD_ERR_MODEL, "kind", "HCBD world");
    memcpy(bad, buf, size);
    memset(bad + size, 0, 8);
    put64(bad + 40, size - 56 + 8);
    reseal(bad, size + 8);
    expect_load(bad, size + 8, HCBD_ERR_FORMAT, "trailing", "padded");
    /* a resealed file with impossible content: n above capacity, a
       parameter out of range (dt < 0, the 4th word of the parameters),
       a position outside the box */
    memcpy(bad, buf, size);
    put64(bad + 56 + 16, 100000);
    reseal(bad, size);
    expect_load(bad, size, HCBD_ERR_FORMAT, "capacity", "n > capacity");
    memcpy(bad, buf, size);
    {
        double v = -1.0;
        uint64_t u;
        memcpy(&u, &v, 8);
        put64(bad + 56 + 24 + 24, u);
    }
    reseal(bad, size);
    expect_load(bad, size, HCBD_ERR_PARAM, "dt", "dt < 0");
    {
        /* the first x: after the fixed-size part, found by loading the
           intact file's layout: x[0] is the word whose value is x of id 0 */
        double x0 = w.x[w.slot[0]], v;
        size_t at;
        for (at = 56; at + 8 <= size; at += 8) {
            uint64_t u = get64(buf + at);
            memcpy(&v, &u, 8);
            if (v == x0) break;
        }
        memcpy(bad, buf, size);
        v = 2.0 * w.p.L[0];
        {
            uint64_t u;
            memcpy(&u, &v, 8);
            put64(bad + at, u);
        }
        reseal(bad, size);
        expect_load(bad, size, HCBD_ERR_OUTSIDE, "outside", "x outside the box");
    }
    /* a forged capacity of 5e8 particles (a small file asking for
       hundreds of GB) is refused before anything is allocated */
    memcpy(bad, buf, size);
    put64(bad + 56, 500000000);
    reseal(bad, size);
    expect_load(bad, size, HCBD_ERR_MEMORY, "HCBD_LOAD_MAX_BYTES", "huge capacity");
    { /* into a live world: a failed load leaves it as it was, a good one
         replaces it (the old memory is freed: the ASan build checks leaks) */
        hcbd_world b;
        uint64_t cb;
        int64_t sb;
        if (sc_make(&b, SC_BD, 1)) {
            run(&b, 3);
            cb = hcbd_world_checksum(&b);
            sb = b.step;
            memcpy(bad, buf, size);
            bad[size / 2] ^= 1;
            CHECK(hcbd_world_checkpoint_load(&b, bad, size) == HCBD_ERR_FORMAT, "bad file loaded");
            CHECK(hcbd_world_load(&b, io_path("missing.hcbd")) == HCBD_ERR_IO, "missing file loaded");
            CHECK(b.step == sb && hcbd_world_checksum(&b) == cb && b.n == 512,
                  "a failed load changed the live world");
            CHECK(run(&b, 1), "the live world no longer steps after a failed load");
            CHECK(hcbd_world_checkpoint_load(&b, buf, size) == HCBD_OK, "%s", b.err.msg);
            CHECK(hcbd_world_checksum(&b) == hcbd_world_checksum(&w) && b.step == w.step,
                  "load into a live world did not give the saved state");
            hcbd_world_destroy(&b);
        }
    }
    /* files: a round trip, a missing file, an unwritable path */
    snprintf(path, sizeof path, "%s", io_path("ck.hcbd"));
    CHECK(hcbd_world_save(&w, path) == HCBD_OK, "%s", w.err.msg);
    {
        hcbd_world b;
        CHECK(hcbd_world_load(&b, path) == HCBD_OK, "%s", b.err.msg);
        CHECK(hcbd_world_checksum(&b) == hcbd_world_checksum(&w), "file round trip changed the state");
        hcbd_world_destroy(&b);
        CHECK(hcbd_world_load(&b, io_path("missing.hcbd")) == HCBD_ERR_IO &&
                  strstr(b.err.msg, "missing.hcbd"), "missing file: %s", b.err.msg);
    }
    CHECK(hcbd_world_save(&w, io_path("no/such/dir/ck.hcbd")) == HCBD_ERR_IO, "unwritable: %s", w.err.msg);
    free(buf);
    free(bad);
    hcbd_world_destroy(&w);
}

/* An extended XYZ frame read back field by field by a parser written here
   (not the library's), against the world the frame came from. */
typedef struct {
    int n;
    double L[9], time, le_offset;
    long long step;
    char props[128], pbc[16], error[32];
    char (*sp)[8];
    double *pos, *vel;
    int *id;
} frame;

static const char *kv(const char *line, const char *key)
{
    const char *p = strstr(line, key);
    return p ? p + strlen(key) : NULL;
}

static int read_frame(FILE *f, frame *fr, int cap)
{
    char line[1024];
    const char *p;
    int k;
    memset(fr->L, 0, sizeof fr->L);
    fr->error[0] = 0;
    if (!fgets(line, sizeof line, f) || sscanf(line, "%d", &fr->n) != 1 || fr->n > cap) return 0;
    if (!fgets(line, sizeof line, f)) return 0;
    if (!(p = kv(line, "Lattice=\"")) ||
        sscanf(p, "%lf %lf %lf %lf %lf %lf %lf %lf %lf", &fr->L[0], &fr->L[1], &fr->L[2], &fr->L[3],
               &fr->L[4], &fr->L[5], &fr->L[6], &fr->L[7], &fr->L[8]) != 9)
        return 0;
    if (!(p = kv(line, "Properties=")) || sscanf(p, "%127s", fr->props) != 1) return 0;
    if (!(p = kv(line, "pbc=\"")) || sscanf(p, "%15[^\"]", fr->pbc) != 1) return 0;
    if (!(p = kv(line, "Time=")) || sscanf(p, "%lf", &fr->time) != 1) return 0;
    if (!(p = kv(line, "Step=")) || sscanf(p, "%lld", &fr->step) != 1) return 0;
    if (!(p = kv(line, "le_offset=")) || sscanf(p, "%lf", &fr->le_offset) != 1) return 0;
    if ((p = kv(line, "error="))) sscanf(p, "%31s", fr->error);
    for (k = 0; k < fr->n; ++k) {
        if (!fgets(line, sizeof line, f)) return 0;
        if (sscanf(line, "%7s %lf %lf %lf %lf %lf %lf %d", fr->sp[k], &fr->pos[3 * k],
                   &fr->pos[3 * k + 1], &fr->pos[3 * k + 2], &fr->vel[3 * k], &fr->vel[3 * k + 1],
                   &fr->vel[3 * k + 2], &fr->id[k]) != 8)
            return 0;
    }
    return 1;
}

static void frame_alloc(frame *fr, int cap)
{
    fr->sp = (char(*)[8])malloc((size_t)cap * 8);
    fr->pos = (double *)malloc((size_t)cap * 3 * sizeof(double));
    fr->vel = (double *)malloc((size_t)cap * 3 * sizeof(double));
    fr->id = (int *)malloc((size_t)cap * sizeof(int));
}

static void frame_free(frame *fr)
{
    free(fr->sp); free(fr->pos); free(fr->vel); free(fr->id);
}

/* Every field of fr against world w (all particles, in id order). */
static void frame_check(const frame *fr, const hcbd_world *w, const char *what)
{
    double *x = (double *)malloc((size_t)w->n * 3 * sizeof(double));
    double *v = (double *)malloc((size_t)w->n * 3 * sizeof(double));
    int k, bad = 0;
    hcbd_world_get_positions(w, x, 0);
    hcbd_world_get_velocities(w, v);
    CHECK(fr->n == w->n, "%s: %d particles, world %d", what, fr->n, w->n);
    CHECK(fr->L[0] == w->p.L[0] && fr->L[4] == w->p.L[1] && fr->L[8] == w->p.L[2] &&
              fr->L[1] == 0 && fr->L[3] == 0 && fr->L[5] == 0,
          "%s: lattice %g %g %g", what, fr->L[0], fr->L[4], fr->L[8]);
    CHECK(!strcmp(fr->props, "species:S:1:pos:R:3:velo:R:3:id:I:1"), "%s: %s", what, fr->props);
    CHECK(!strcmp(fr->pbc, "T T T"), "%s: pbc %s", what, fr->pbc);
    CHECK(fr->step == w->step && fr->time == w->step * w->p.dt, "%s: step %lld time %g", what,
          fr->step, fr->time);
    CHECK(fr->le_offset == w->core.le_offset, "%s: le_offset %.17g vs %.17g", what, fr->le_offset,
          w->core.le_offset);
    for (k = 0; k < fr->n && k < w->n && bad < 5; ++k) {
        int d, ok = fr->id[k] == k && !strcmp(fr->sp[k], "S");
        for (d = 0; d < 3; ++d)
            ok &= fr->pos[3 * k + d] == x[3 * k + d] && fr->vel[3 * k + d] == v[3 * k + d];
        if (!ok) {
            CHECK(0, "%s: atom line %d differs (id %d, x %.17g vs %.17g)", what, k, fr->id[k],
                  fr->pos[3 * k], x[3 * k]);
            ++bad;
        }
    }
    free(x);
    free(v);
}

void test_xyz_frame_fields(void)
{
    hcbd_world w;
    frame fr;
    FILE *f;
    char line[256];
    if (!sc_make(&w, SC_SHEAR, 1)) return;
    run(&w, 20);
    f = tmpfile();
    CHECK(hcbd_world_write_xyz(&w, f, NULL, 0) == HCBD_OK, "xyz_write");
    rewind(f);
    frame_alloc(&fr, 512);
    CHECK(read_frame(f, &fr, 512), "frame does not parse");
    frame_check(&fr, &w, "library frame");
    fclose(f);
    CHECK(w.core.le_offset != 0.0, "the sheared scene should have a nonzero offset");
    /* the thermo line has as many fields as its header, and they are the
       world's numbers */
    {
        char head[256], *tok;
        int nh = 0, nl = 0;
        long long step;
        double t, T;
        hcbd_thermo_header(head, sizeof head);
        hcbd_world_thermo_line(&w, 123.0, line, sizeof line);
        for (tok = strtok(head, " "); tok; tok = strtok(NULL, " ")) nh++;
        CHECK(sscanf(line, "%lld %lf %lf", &step, &t, &T) == 3, "thermo: %s", line);
        CHECK(step == w.step && fabs(T - hcbd_world_temperature(&w)) < 1e-8 * T, "thermo: %s", line);
        for (tok = strtok(line, " "); tok; tok = strtok(NULL, " ")) nl++;
        CHECK(nh - 1 == nl, "thermo: %d header names (with '#'), %d fields", nh, nl);
        CHECK(hcbd_world_thermo_line(&w, NAN, line, 8) > 8, "thermo reports the length it needs");
    }
    frame_free(&fr);
    hcbd_world_destroy(&w);
}

/* The example writes a frame and a checkpoint at its last step; the frame
   must hold exactly the checkpointed world. */
void test_xyz_from_example(void)
{
    frame fr;
    FILE *f;
    hcbd_world w;
    int rc;
    struct stat st;
    if (stat("build/gibd_bulk", &st) != 0) {
        CHECK(0, "build/gibd_bulk is missing: make test builds it first");
        return;
    }
    {
        char cmd[2048], dir[256];
        snprintf(dir, sizeof dir, "%s", io_path("ex"));
        snprintf(cmd, sizeof cmd, "./build/gibd_bulk N=216 steps=1000 out=%s xyz=%s/traj.xyz "
                 "xyz_every=1000 thermo_every=500 checkpoint=%s/end.hcbd > %s.log 2>&1",
                 dir, dir, dir, dir);
        rc = system(cmd);
        CHECK(rc == 0, "example exited with %d (see %s.log)", rc, dir);
    }
    if (rc != 0) return;
    f = fopen(io_path("ex/traj.xyz"), "r");
    CHECK(f != NULL, "no trajectory");
    if (!f) return;
    frame_alloc(&fr, 1024);
    /* frames at the start (after equilibration) and 1000 steps later: the last one is compared */
    CHECK(read_frame(f, &fr, 1024) && fr.step == 5000, "first frame, step %lld", fr.step);
    CHECK(read_frame(f, &fr, 1024), "second frame");
    fclose(f);
    if (hcbd_world_load(&w, io_path("ex/end.hcbd")) != HCBD_OK) {
        CHECK(0, "checkpoint: %s", w.err.msg);
    } else {
        frame_check(&fr, &w, "example frame");
        hcbd_world_destroy(&w);
    }
    frame_free(&fr);
}

/* Each guard stops the run at the step it fires, names the particle and
   the cause, and the offenders' frame holds that particle. */
void test_runtime_guards(void)
{
    hcbd_world w;
    hcbd_result r;
    frame fr;
    FILE *f;
    int k, found = 0;
    /* image counter about to overflow: caught by the scan at the next
       multiple of guard_every */
    if (!sc_make(&w, SC_LAGGED, 1)) return;
    w.p.guard_every = 4;
    run(&w, 1);
    w.ix[w.slot[7]] = 0x40000000;
    r = hcbd_world_step(&w, 10);
    CHECK(r == HCBD_ERR_OUTSIDE && w.err.id == 7 && w.err.step == 4 && w.step == 4,
          "image overflow: %s at step %lld id %lld: %s", hcbd_result_name(r),
          (long long)w.err.step, (long long)w.err.id, w.err.msg);
    CHECK(strstr(w.err.msg, "particle 7") != NULL, "%s", w.err.msg);
    f = tmpfile();
    CHECK(hcbd_world_write_offenders(&w, f) == HCBD_OK, "offenders");
    rewind(f);
    frame_alloc(&fr, 512);
    CHECK(read_frame(f, &fr, 512), "offenders' frame does not parse");
    for (k = 0; k < fr.n; ++k) found |= fr.id[k] == 7;
    CHECK(found && fr.n > 1 && fr.n < 512, "offenders: %d particles, id 7 %s", fr.n,
          found ? "in" : "missing");
    CHECK(!strcmp(fr.error, "HCBD_ERR_OUTSIDE"), "offenders' error field: %s", fr.error);
    fclose(f);
    frame_free(&fr);
    hcbd_world_destroy(&w);
    /* guard_every = 0 switches the scan off: the same poke goes unseen */
    if (!sc_make(&w, SC_LAGGED, 1)) return;
    w.p.guard_every = 0;
    run(&w, 1);
    w.ix[w.slot[7]] = 0x40000000;
    r = hcbd_world_step(&w, 10);
    CHECK(r == HCBD_OK, "guard_every = 0 still scanned: %s", w.err.msg);
    hcbd_world_destroy(&w);
    /* guard_step: the smallest displacement limit stops the first step */
    if (!sc_make(&w, SC_SHARDLOW, 1)) return;
    w.p.guard_step = 1e-6; /* read at every step, not only at creation */
    r = hcbd_world_step(&w, 1);
    CHECK(r == HCBD_ERR_UNSTABLE && strstr(w.err.msg, "guard_step"), "guard_step: %s: %s",
          hcbd_result_name(r), w.err.msg);
    hcbd_world_destroy(&w);
#if WALLS_BUILD
    {
        /* a particle pushed into the wall, with wall.guard on */
        if (!sc_make(&w, SC_WALLS, 1)) return;
        w.p.wall.guard = 1;
        run(&w, 1);
        w.y[w.slot[9]] = (hcbd_real)(0.5 * w.p.wall.thickness);
        r = hcbd_world_step(&w, 1);
        CHECK(r == HCBD_ERR_WALL && w.err.id == 9, "wall: %s id %lld: %s", hcbd_result_name(r),
              (long long)w.err.id, w.err.msg);
        hcbd_world_destroy(&w);
    }
#endif
}
