/* Shared by the examples: key=value arguments named as in docs/MODEL.md and
   DESIGN.md, output files, block statistics.  Each example handles its own
   keys in a callback and leaves the physical ones to parse_args. */
#ifndef HCBD_EXAMPLE_COMMON_H
#define HCBD_EXAMPLE_COMMON_H
#define _POSIX_C_SOURCE 200809L /* mkdir, isatty, clock_gettime under -std=c99 */
#include "../hcbd.h"
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

typedef struct {
    const char *name;          /* program name for messages */
    hcbd_world_def def;
    int N, steps;
    double density;
    double L[3];
    int box_given;
    char out[512];
    /* run output (all off by default): extended XYZ frames every xyz_every
       steps, a thermo line every thermo_every steps, a checkpoint at the
       end, a start from a checkpoint */
    char xyz[512], checkpoint[512], restart[512];
    int xyz_every, thermo_every;
    int help;                  /* help was asked for: exit 0, not 2 */
    /* the key=value arguments taken, in order (the parameter file's
       first): run.conf repeats them, and restart= refuses the ones a
       checkpoint overrides */
    const char *given[256];
    int ngiven;
} config;

/* An example's own key: 1 taken, 0 error (already reported), -1 unknown. */
typedef int (*own_key_fn)(config *c, const char *key, const char *v);

static inline int parse_double(const config *c, const char *key, const char *v, double *x)
{
    char *end;
    errno = 0;
    *x = strtod(v, &end);
    if (errno || end == v || *end || !isfinite(*x)) {
        fprintf(stderr, "%s: %s=%s is not a number\n", c->name, key, v);
        return 0;
    }
    return 1;
}

static inline int parse_int(const config *c, const char *key, const char *v, int *x)
{
    double d;
    if (!parse_double(c, key, v, &d)) return 0;
    if (d != floor(d) || d < -2e9 || d > 2e9) {
        fprintf(stderr, "%s: %s=%s is not an integer\n", c->name, key, v);
        return 0;
    }
    *x = (int)d;
    return 1;
}

static inline int parse_choice(const config *c, const char *key, const char *v, const char *a,
                        const char *b, int *x, int va, int vb)
{
    if (!strcmp(v, a)) *x = va;
    else if (!strcmp(v, b)) *x = vb;
    else {
        fprintf(stderr, "%s: %s=%s is not %s or %s\n", c->name, key, v, a, b);
        return 0;
    }
    return 1;
}

/* A comma-separated list of positive numbers into x[0..max); returns how
   many, or 0 after printing what was wrong. */
static inline int parse_list(const config *c, const char *key, const char *v, double *x, int max)
{
    char buf[512], *tok, *save = NULL;
    int n = 0;
    if (snprintf(buf, sizeof buf, "%s", v) >= (int)sizeof buf) {
        fprintf(stderr, "%s: %s is longer than %d characters\n", c->name, key, (int)sizeof buf - 1);
        return 0;
    }
    for (tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        if (n == max) {
            fprintf(stderr, "%s: more than %d values of %s\n", c->name, max, key);
            return 0;
        }
        if (!parse_double(c, key, tok, &x[n])) return 0;
        if (!(x[n] > 0)) {
            fprintf(stderr, "%s: %s=%s must be positive\n", c->name, key, tok);
            return 0;
        }
        ++n;
    }
    return n;
}

/* preset=quick|paper: read by each example before parse_args (so that
   explicit keys override it); here only checked. */
static inline int check_preset(const config *c, const char *v)
{
    if (!strcmp(v, "quick") || !strcmp(v, "paper")) return 1;
    fprintf(stderr, "%s: unknown preset '%s' (quick or paper)\n", c->name, v);
    return 0;
}

/* in=FILE or @FILE: the file's key=value lines (blank lines and text after
   # skipped, spaces around = allowed) go before the command line's other
   keys, which override them.  *argc and *argv become the expanded list
   (static storage: one call per program).  0 after a message. */
static inline int expand_args(const config *c, int *argc, char ***argv)
{
    static char text[1 << 16], *av[256];
    size_t used = 0;
    int n = 1, k, files = 0;
    av[0] = (*argv)[0];
    for (k = 1; k < *argc; ++k) {
        const char *a = (*argv)[k], *path = !strncmp(a, "in=", 3) ? a + 3 : a[0] == '@' ? a + 1 : NULL;
        char line[1024];
        FILE *f;
        int ln = 0;
        if (!path) continue;
        if (++files > 1) { fprintf(stderr, "%s: more than one parameter file (%s)\n", c->name, a); return 0; }
        if (!(f = fopen(path, "r"))) { fprintf(stderr, "%s: cannot read the parameter file %s\n", c->name, path); return 0; }
        while (fgets(line, sizeof line, f)) {
            char *b = line, *e, *hash = strchr(line, '#'), *eq;
            size_t len;
            ++ln;
            if (hash) *hash = 0;
            while (*b == ' ' || *b == '\t') ++b;
            for (e = b + strlen(b); e > b && (e[-1] == ' ' || e[-1] == '\t' || e[-1] == '\n' || e[-1] == '\r');) *--e = 0;
            if (!*b) continue;
            if (!(eq = strchr(b, '=')) || eq == b) {
                fprintf(stderr, "%s: %s line %d: '%s' is not key=value\n", c->name, path, ln, b);
                fclose(f);
                return 0;
            }
            for (e = eq; e > b && (e[-1] == ' ' || e[-1] == '\t');) --e; /* "key = value" */
            len = (size_t)(e - b);
            for (++eq; *eq == ' ' || *eq == '\t';) ++eq;
            if (n == 200 || used + len + strlen(eq) + 2 > sizeof text) {
                fprintf(stderr, "%s: %s is too long (at most 200 keys)\n", c->name, path);
                fclose(f);
                return 0;
            }
            av[n++] = text + used;
            memcpy(text + used, b, len);
            used += len;
            text[used++] = '=';
            memcpy(text + used, eq, strlen(eq) + 1);
            used += strlen(eq) + 1;
        }
        fclose(f);
    }
    if (!files) return 1;
    for (k = 1; k < *argc; ++k) {
        const char *a = (*argv)[k];
        if (!strncmp(a, "in=", 3) || a[0] == '@') continue;
        if (n == 255) { fprintf(stderr, "%s: too many arguments\n", c->name); return 0; }
        av[n++] = (*argv)[k];
    }
    av[n] = NULL;
    *argc = n;
    *argv = av;
    return 1;
}

/* What every example takes besides its own keys, for help. */
static inline void common_help(FILE *f)
{
    fprintf(f, "common keys:\n"
               "  in=FILE or @FILE    key=value lines (# comments); the command line overrides them\n"
               "  threads=k           OpenMP threads (default: OMP_NUM_THREADS if set, else 1;\n"
               "                      the results are the same bits for any count)\n"
               "  seed=u              the random stream (unsigned integer)\n"
               "  out=DIR             where the CSV files, plots.gp and run.conf go\n"
               "  xyz=FILE xyz_every=k  extended XYZ frames every k steps (OVITO, ASE: docs/GUIDE.md)\n"
               "  thermo_every=k      a thermo line every k steps\n"
               "  checkpoint=FILE     save the world at the end\n"
               "  restart=FILE        start from a checkpoint\n"
               "  help (or --help, -h) this text\n"
               "limits: steps >= 1000 where an example takes steps; N >= 2; positive densities,\n"
               "times and lengths; an unknown key or a bad value ends the run with exit code 2\n");
}

/* Physical keys of docs/MODEL.md, seed, steps, threads, out; the example's
   own keys first through own().  threads defaults to OMP_NUM_THREADS when
   it is set, else to 1: threads that spin on cores other jobs hold can make
   a run many times slower than one thread (the results are the same bits
   for any count).  help, --help, -h print the usage on stdout and return 0
   with c->help set.  Returns 0 after printing what was wrong. */
static inline int parse_args(int argc, char **argv, config *c, own_key_fn own, void (*usage)(FILE *))
{
    hcbd_params *p = &c->def.params;
    const char *omp = getenv("OMP_NUM_THREADS");
    int k, e;
    p->threads = omp && atoi(omp) > 0 ? (atoi(omp) > 1024 ? 1024 : atoi(omp)) : 1;
    c->ngiven = 0;
    for (k = 1; k < argc; ++k) {
        char key[64], *eq = strchr(argv[k], '=');
        const char *v;
        double d;
        if (!strcmp(argv[k], "help") || !strncmp(argv[k], "help=", 5) || !strcmp(argv[k], "--help") ||
            !strcmp(argv[k], "-h")) {
            usage(stdout);
            common_help(stdout);
            c->help = 1;
            return 0;
        }
        if (!eq || eq == argv[k] || eq - argv[k] >= (long)sizeof key) {
            fprintf(stderr, "%s: argument '%s' is not key=value\n", c->name, argv[k]);
            usage(stderr);
            return 0;
        }
        if (c->ngiven < (int)(sizeof c->given / sizeof c->given[0])) c->given[c->ngiven++] = argv[k];
        memcpy(key, argv[k], (size_t)(eq - argv[k]));
        key[eq - argv[k]] = 0;
        v = eq + 1;
        e = own ? own(c, key, v) : -1;
        if (e == 0) return 0;
        if (e == 1) continue;
#define DBL(name, field) else if (!strcmp(key, name)) { if (!parse_double(c, key, v, &d)) return 0; field = d; }
        if (0) {}
        DBL("density", c->density)
        DBL("dt", p->dt) DBL("kT", p->kT) DBL("xi", p->xi) DBL("xip", p->xip)
        DBL("tau", p->tau) DBL("Rc", p->Rc) DBL("f", p->f) DBL("sigma", p->sigma)
        DBL("rcut", p->rcut) DBL("skin", p->skin)
        else if (!strcmp(key, "Lx") || !strcmp(key, "Ly") || !strcmp(key, "Lz")) {
            if (!parse_double(c, key, v, &d)) return 0;
            c->L[key[1] - 'x'] = d;
            c->box_given |= 1 << (key[1] - 'x');
        }
        else if (!strcmp(key, "N")) { if (!parse_int(c, key, v, &c->N)) return 0; }
        else if (!strcmp(key, "steps")) { if (!parse_int(c, key, v, &c->steps)) return 0; }
        else if (!strcmp(key, "threads")) { if (!parse_int(c, key, v, &p->threads)) return 0; }
        else if (!strcmp(key, "density_norm")) { if (!parse_int(c, key, v, &p->density_norm)) return 0; }
        else if (!strcmp(key, "lagged")) { if (!parse_int(c, key, v, &p->lagged_density)) return 0; }
        else if (!strcmp(key, "seed")) {
            char *end;
            errno = 0;
            p->seed = strtoull(v, &end, 10);
            if (errno || end == v || *end || *v < '0' || *v > '9') {
                fprintf(stderr, "%s: seed=%s is not an unsigned integer\n", c->name, v);
                return 0;
            }
        }
        else if (!strcmp(key, "potential")) {
            int x;
            if (!parse_choice(c, key, v, "star", "ideal", &x, HCBD_POT_STAR, HCBD_POT_IDEAL)) return 0;
            p->potential = (hcbd_potential)x;
        }
        else if (!strcmp(key, "dynamics")) {
            int x;
            if (!parse_choice(c, key, v, "gibd", "bd", &x, HCBD_DYN_GIBD, HCBD_DYN_BD)) return 0;
            p->dynamics = (hcbd_dynamics)x;
        }
        else if (!strcmp(key, "pair")) {
            int x;
            if (!parse_choice(c, key, v, "shardlow", "euler", &x, HCBD_PAIR_SHARDLOW, HCBD_PAIR_EULER)) return 0;
            p->pair_integrator = (hcbd_pair_integrator)x;
        }
        else if (!strcmp(key, "brownian")) {
            int x;
            if (!parse_choice(c, key, v, "lm", "euler", &x, HCBD_BROWNIAN_LM, HCBD_BROWNIAN_EULER)) return 0;
            p->brownian = (hcbd_brownian_integrator)x;
        }
        else if (!strcmp(key, "noise")) {
            int x;
            if (!parse_choice(c, key, v, "gauss", "uniform", &x, HCBD_NOISE_GAUSS, HCBD_NOISE_UNIFORM)) return 0;
            p->noise = (hcbd_noise)x;
        }
        else if (!strcmp(key, "out") || !strcmp(key, "xyz") || !strcmp(key, "checkpoint") ||
                 !strcmp(key, "restart")) {
            char *dst = key[0] == 'o' ? c->out : key[0] == 'x' ? c->xyz : key[0] == 'c' ? c->checkpoint : c->restart;
            if (!*v || strlen(v) >= sizeof c->out) {
                fprintf(stderr, "%s: %s= must be a path of 1 to %d characters\n", c->name, key, (int)sizeof c->out - 1);
                return 0;
            }
            memcpy(dst, v, strlen(v) + 1);
        }
        else if (!strcmp(key, "xyz_every") || !strcmp(key, "thermo_every")) {
            int *x = key[0] == 'x' ? &c->xyz_every : &c->thermo_every;
            if (!parse_int(c, key, v, x)) return 0;
            if (*x < 0) { fprintf(stderr, "%s: %s=%s must not be negative\n", c->name, key, v); return 0; }
        }
        else {
            fprintf(stderr, "%s: unknown key '%s' (help lists the keys)\n", c->name, key);
            usage(stderr);
            return 0;
        }
#undef DBL
    }
    if (c->N < 2) { fprintf(stderr, "%s: N=%d must be at least 2\n", c->name, c->N); return 0; }
    if (!(c->density > 0)) { fprintf(stderr, "%s: density=%g must be positive\n", c->name, c->density); return 0; }
    if (c->steps < 1000) { fprintf(stderr, "%s: steps=%d must be at least 1000\n", c->name, c->steps); return 0; }
    for (k = 0; k < 3; ++k)
        if (!(c->box_given >> k & 1)) c->L[k] = cbrt(c->N / c->density);
    memcpy(p->L, c->L, sizeof c->L);
    p->density = c->density;
    c->def.capacity = c->N;
    return 1;
}

static inline void mkdirs(const char *path)
{
    char tmp[512];
    size_t k;
    snprintf(tmp, sizeof tmp, "%s", path);
    if (!tmp[0]) return; /* "": the loop below would start past the terminator */
    for (k = 1; tmp[k]; ++k)
        if (tmp[k] == '/') { tmp[k] = 0; mkdir(tmp, 0755); tmp[k] = '/'; }
    mkdir(tmp, 0755);
}

static inline FILE *open_out(const config *c, const char *name)
{
    char path[700];
    FILE *f;
    snprintf(path, sizeof path, "%s/%s", c->out, name);
    f = fopen(path, "w");
    if (!f) fprintf(stderr, "%s: cannot write %s\n", c->name, path);
    return f;
}

/* What became of the figures, for the last lines of the output. */
static char figures_note[800];

/* Runs gnuplot on plots.gp in the output folder, or notes why not. */
static inline void make_figures(const config *c)
{
    if (strchr(c->out, '\'')) {
        snprintf(figures_note, sizeof figures_note, "out=%s contains a quote: run gnuplot plots.gp there yourself",
                 c->out);
    } else if (system("command -v gnuplot >/dev/null 2>&1") == 0) {
        char cmd[800];
        snprintf(cmd, sizeof cmd, "cd '%s' && gnuplot plots.gp", c->out);
        snprintf(figures_note, sizeof figures_note, "%s", system(cmd) != 0 ? "gnuplot failed on plots.gp: no PNG figures"
                                                                            : "PNG figures made by gnuplot");
    } else {
        snprintf(figures_note, sizeof figures_note,
                 "gnuplot not found: no PNG figures (install gnuplot, then run gnuplot plots.gp there)");
    }
}

/* The parameters of the run beside its output (out/run.conf): the keys it
   was given, then the seed and threads it used, so that
   "example in=out/.../run.conf" repeats it bit for bit. */
static inline void write_run_conf(const config *c)
{
    FILE *f = open_out(c, "run.conf");
    int k, seed = 0;
    if (!f) return;
    fprintf(f, "# %s, hcbd %d.%d: the keys of this run; repeat it with %s in=%s/run.conf\n", c->name,
            HCBD_VERSION_MAJOR, HCBD_VERSION_MINOR, c->name, c->out);
    for (k = 0; k < c->ngiven; ++k) {
        seed |= !strncmp(c->given[k], "seed=", 5);
        fprintf(f, "%s\n", c->given[k]);
    }
    if (!seed) fprintf(f, "seed=%llu\n", (unsigned long long)c->def.params.seed);
    fprintf(f, "# threads=%d (the bits do not depend on it)\n", c->def.params.threads);
    fclose(f);
}

/* The verdict table of a summary.  judge() files one measured value with
   its block error, unit and expectation: "ok" when |value - expected| <=
   3 err + tol (tol: an allowance the expectation itself carries, 0 for an
   exact one), else "known" with the named effect that explains the
   difference, else "UNEXPLAINED"; expected NaN files a reference value
   that no theory predicts.  summary_end() prints the table, a
   key_verdict=... line for scripts, and where the output went. */
typedef struct {
    char key[40], unit[32], expect[120], verdict[200];
    const char *kind; /* ok, known, reference, UNEXPLAINED */
    double v, e;
} judged;
static judged judged_rows[48];
static int judged_n;

static inline void judge(const char *key, double v, double e, const char *unit, double expected, double tol,
                         const char *expect_what, const char *known)
{
    judged *j;
    double d = fabs(v - expected), lim = 3 * (isfinite(e) ? e : 0) + tol;
    if (judged_n == (int)(sizeof judged_rows / sizeof judged_rows[0])) return;
    j = &judged_rows[judged_n++];
    snprintf(j->key, sizeof j->key, "%s", key);
    snprintf(j->unit, sizeof j->unit, "%s", unit);
    j->v = v;
    j->e = e;
    if (!isfinite(expected)) {
        snprintf(j->expect, sizeof j->expect, "none, %s", expect_what);
        snprintf(j->verdict, sizeof j->verdict, "reference");
        j->kind = "reference";
    } else {
        snprintf(j->expect, sizeof j->expect, "%.4g (%s)", expected, expect_what);
        j->kind = isfinite(v) && d <= lim ? "ok" : isfinite(v) && known ? "known" : "UNEXPLAINED";
        if (!isfinite(v))
            snprintf(j->verdict, sizeof j->verdict, "UNEXPLAINED: not measured (run longer)");
        else if (d <= lim)
            snprintf(j->verdict, sizeof j->verdict, "ok: within %s", tol > 0 ? "3 errors + the stated allowance" : "3 errors");
        else if (known)
            snprintf(j->verdict, sizeof j->verdict, "known: %s", known);
        else
            snprintf(j->verdict, sizeof j->verdict, "UNEXPLAINED: %.2g errors off", isfinite(e) && e > 0 ? d / e : INFINITY);
    }
}

/* The table of the values judged since the last call (one per summary
   section of an example that runs several scenes). */
static inline void verdicts_flush(void)
{
    int k;
    if (judged_n) {
        printf("# verdicts: measured +- block error [unit]; expected; verdict (ok, known effect, reference, "
               "UNEXPLAINED)\n");
        for (k = 0; k < judged_n; ++k) {
            const judged *j = &judged_rows[k];
            char val[64], unit[40];
            if (isfinite(j->e)) snprintf(val, sizeof val, "%.5g +- %.2g", j->v, j->e);
            else snprintf(val, sizeof val, "%.5g", j->v);
            snprintf(unit, sizeof unit, "[%s]", j->unit);
            printf("#   %-24s %-20s %-14s expected %s: %s\n", j->key, val, unit, j->expect, j->verdict);
        }
        for (k = 0; k < judged_n; ++k) printf("%s_verdict=%s\n", judged_rows[k].key, judged_rows[k].kind);
    }
    judged_n = 0;
}

static inline void summary_end(const config *c, int has_files)
{
    verdicts_flush();
    if (figures_note[0]) printf("# figures: %s\n", figures_note);
    if (has_files)
        printf("# output: %s/ (CSV files, plots.gp, run.conf)%s%s%s%s\n", c->out, c->xyz[0] ? ", " : "", c->xyz,
               c->checkpoint[0] ? ", " : "", c->checkpoint);
    else
        printf("# output: this summary%s%s%s%s\n", c->xyz[0] ? ", " : "", c->xyz, c->checkpoint[0] ? ", " : "",
               c->checkpoint);
}

/* Mean and standard error of the finite values of x[0..n) (a block whose
   estimate could not be made is NaN and left out); returns how many were
   used.  NaN mean without any, NaN error with fewer than two. */
static inline int mean_err(const double *x, int n, double *m, double *e)
{
    double s = 0, s2 = 0;
    int k, used = 0;
    for (k = 0; k < n; ++k)
        if (isfinite(x[k])) { s += x[k]; s2 += x[k] * x[k]; ++used; }
    *m = used ? s / used : NAN;
    *e = used > 1 ? sqrt(fmax(s2 / used - *m * *m, 0) / (used - 1)) : NAN;
    return used;
}

/* Progress on stderr: a rewritten line on a terminal, else one per call. */
static inline void progress(const config *c, int done, int total, const struct timespec *t0)
{
    struct timespec t1;
    double el;
    int tty = isatty(fileno(stderr));
    clock_gettime(CLOCK_MONOTONIC, &t1);
    el = (t1.tv_sec - t0->tv_sec) + 1e-9 * (t1.tv_nsec - t0->tv_nsec);
    fprintf(stderr, "%s%s: step %d / %d (%3.0f %%), %.0f s elapsed, %.0f s left   %s", tty ? "\r" : "",
            c->name, done, total, 100.0 * done / total, el, done ? el / done * (total - done) : 0.0,
            tty ? (done == total ? "\n" : "") : "\n");
}

/* Run output of every example (all off by default): extended XYZ frames
   every xyz_every steps, a thermo line every thermo_every steps, a
   checkpoint when the run ends.  An example that runs several worlds gives
   each a label, and its files become stem.label.ext (traj.xyz ->
   traj.gdot2.xyz); label NULL keeps the names.  Step through run_steps. */
#if HCBD_MODEL == HCBD_MODEL_HCBD
typedef hcbd_hc_world ex_world;
#define EX_STEP hcbd_hc_world_step
#define EX_XYZ(w, f) hcbd_hc_world_write_xyz(w, f)
#define EX_THERMO_HEADER hcbd_hc_thermo_header
#define EX_THERMO_LINE hcbd_hc_world_thermo_line
#define EX_SAVE hcbd_hc_world_save
#define EX_NPART(w) ((w)->nf + (w)->np)
#else
typedef hcbd_world ex_world;
#define EX_STEP hcbd_world_step
#define EX_XYZ(w, f) hcbd_world_write_xyz(w, f, NULL, 0)
#define EX_THERMO_HEADER hcbd_thermo_header
#define EX_THERMO_LINE hcbd_world_thermo_line
#define EX_SAVE hcbd_world_save
#define EX_NPART(w) ((w)->n)
#endif

typedef struct {
    FILE *xyz;
    char label[128];
    struct timespec t0;
    int64_t step0;
} run_out;

/* path with ".label" before its extension (or at its end) */
static inline void labelled(char *dst, size_t size, const char *path, const char *label)
{
    const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
    if (!label || !*label) { snprintf(dst, size, "%s", path); return; }
    if (!dot || (slash && dot < slash)) dot = path + strlen(path);
    snprintf(dst, size, "%.*s.%s%s", (int)(dot - path), path, label, dot);
}

static inline int run_out_open(const config *c, run_out *o, const ex_world *w, const char *label)
{
    char path[700];
    memset(o, 0, sizeof *o);
    if (label) snprintf(o->label, sizeof o->label, "%s", label);
    if (c->xyz[0] && c->xyz_every == 0) {
        fprintf(stderr, "%s: xyz=%s needs xyz_every=k > 0\n", c->name, c->xyz);
        return 0;
    }
    labelled(path, sizeof path, c->xyz, o->label);
    if (c->xyz[0] && !(o->xyz = fopen(path, "w"))) {
        fprintf(stderr, "%s: cannot write %s\n", c->name, path);
        return 0;
    }
    if (c->thermo_every > 0) {
        char head[256];
        EX_THERMO_HEADER(head, sizeof head);
        printf("%s%s%s\n", head, o->label[0] ? "  # run " : "", o->label);
    }
    clock_gettime(CLOCK_MONOTONIC, &o->t0);
    o->step0 = w->step;
    if (o->xyz) EX_XYZ(w, o->xyz);
    return 1;
}

/* n steps of w, stopping where a frame or a thermo line is due */
static inline hcbd_result run_steps(const config *c, run_out *o, ex_world *w, int n)
{
    while (n > 0) {
        int k = n;
        hcbd_result r;
        if (o->xyz && k > c->xyz_every - (int)(w->step % c->xyz_every))
            k = c->xyz_every - (int)(w->step % c->xyz_every);
        if (c->thermo_every > 0 && k > c->thermo_every - (int)(w->step % c->thermo_every))
            k = c->thermo_every - (int)(w->step % c->thermo_every);
        if ((r = EX_STEP(w, k)) != HCBD_OK) return r;
        n -= k;
        if (o->xyz && w->step % c->xyz_every == 0) EX_XYZ(w, o->xyz);
        if (c->thermo_every > 0 && w->step % c->thermo_every == 0) {
            struct timespec t1;
            char line[512];
            clock_gettime(CLOCK_MONOTONIC, &t1);
            EX_THERMO_LINE(w, ((t1.tv_sec - o->t0.tv_sec) * 1e9 + (t1.tv_nsec - o->t0.tv_nsec)) /
                                  ((double)(w->step - o->step0) * EX_NPART(w)), line, sizeof line);
            printf("%s\n", line);
            o->t0 = t1;
            o->step0 = w->step;
        }
    }
    return HCBD_OK;
}

/* Figures: every plots.gp starts with gp_preamble, so that all PNGs share
   one readable look.  Greek letters and signs are UTF-8 written as octal
   escapes, which keeps the sources ASCII; the terminal is enhanced, so _
   and ^ in a label make sub- and superscripts (a literal one needs \\_). */
#define GP_PRIME "\342\200\262"
#define GP_XI "\316\276"
#define GP_XIP GP_XI GP_PRIME
#define GP_ALPHA "\316\261"
#define GP_SIGMA "\317\203"
#define GP_TAU "\317\204"
#define GP_NU "\316\275"
#define GP_ETA "\316\267"
#define GP_GDOT "\316\263\314\207"    /* gamma with a dot above */
#define GP_LAMBDA "\316\273"
#define GP_RHO "\317\201"
#define GP_MU "\316\274"
#define GP_PI "\317\200"
#define GP_SUM "\316\243"
/* the Carreau curve eta_inf + (eta0 - eta_inf) (1 + (lambda x)^2)^((n - 1) / 2)
   in gnuplot, from eta_inf, eta0, eta_inf, lambda, n: 1.0, since gnuplot
   divides integers and n printed as 0 would make the exponent 0 */
#define GP_CARREAU "%.17g + (%.17g - %.17g) * (1 + (%.17g * x)**2)**((%.17g - 1.0) / 2)"
#define GP_PM "\302\261"
#define GP_GEQ "\342\211\245"
#define GP_INF "\342\210\236"
#define GP_TIMES "\303\227"
#define GP_CDOT "\302\267"
#define GP_LANGLE "\342\237\250"
#define GP_RANGLE "\342\237\251"

/* The terminal again for a figure of another size (a bare "set terminal
   pngcairo size" would drop the font and the enhanced mode). */
static inline void gp_terminal(FILE *f, int width, int height)
{
    fprintf(f, "set terminal pngcairo enhanced size %d,%d font 'Sans,13' linewidth 1.5\n", width, height);
}

static inline void gp_preamble(FILE *f, int width, int height)
{
    fprintf(f, "set encoding utf8\nset datafile separator ','\n");
    gp_terminal(f, width, height);
    fprintf(f, "set key box opaque samplen 4 spacing 1.2 font ',11'\n"
               "set grid lc rgb '#e0e0e0'\nset bars small\nset pointsize 1.1\n"
               "set title font ',13'\n");
}

#if HCBD_MODEL != HCBD_MODEL_HCBD
/* The world of a run: loaded from restart= (the checkpoint's parameters
   and particles replace the command line's; returns 2) or created from
   c->def (returns 1); 0 after a message.  Beside restart= only the keys of
   the run itself (steps, threads, output) may be given. */
static inline int world_start(config *c, hcbd_world *w)
{
    const int threads = c->def.params.threads;
    int k;
    if (!c->restart[0]) {
        if (hcbd_world_create(w, &c->def) == HCBD_OK) return 1;
        fprintf(stderr, "%s: %s\n", c->name, w->err.msg);
        return 0;
    }
    for (k = 0; k < c->ngiven; ++k) { /* keys a checkpoint would silently override */
        static const char *run_keys[] = {"steps=", "threads=", "out=", "xyz=", "xyz_every=", "thermo_every=",
                                         "checkpoint=", "restart=", "preset=", "slabs="};
        size_t r;
        int ok = 0;
        for (r = 0; r < sizeof run_keys / sizeof run_keys[0]; ++r)
            ok |= !strncmp(c->given[k], run_keys[r], strlen(run_keys[r]));
        if (!ok) {
            fprintf(stderr, "%s: %s cannot apply with restart=%s: a run from a checkpoint keeps the "
                    "checkpoint's particles and parameters (drop the key, or start afresh without "
                    "restart=)\n", c->name, c->given[k], c->restart);
            return 0;
        }
    }
    if (hcbd_world_load(w, c->restart) != HCBD_OK) {
        fprintf(stderr, "%s: restart=%s: %s\n", c->name, c->restart, w->err.msg);
        return 0;
    }
    if (hcbd_world_set_threads(w, threads) != HCBD_OK) {
        fprintf(stderr, "%s: %s\n", c->name, w->err.msg);
        hcbd_world_destroy(w);
        return 0;
    }
    c->def.params = w->p;
    c->N = w->n;
    c->density = w->n / (w->p.L[0] * w->p.L[1] * w->p.L[2]);
    printf("restart=%s: step %lld, N = %d\n", c->restart, (long long)w->step, w->n);
    return 2;
}
#endif

#if HCBD_MODEL == HCBD_MODEL_HCBD
/* The configuration of the checkpoint restart= names, for the runs of an
   HCBD example to start from (their parameters stay the command line's):
   fluid positions and velocities (6 nf: xyz, then v) and polymer
   positions (3 np), interleaved, malloc'd; 0 after a message. */
typedef struct { int nf, np; double *fluid, *poly; } hc_config;

static inline int hc_restart(const config *c, hc_config *r)
{
    hcbd_hc_world w;
    memset(r, 0, sizeof *r);
    if (hcbd_hc_world_load(&w, c->restart) != HCBD_OK) {
        fprintf(stderr, "%s: restart=%s: %s\n", c->name, c->restart, w.err.msg);
        return 0;
    }
    r->nf = w.nf;
    r->np = w.np;
    r->fluid = (double *)malloc((6 * (size_t)w.nf + 1) * sizeof(double));
    r->poly = (double *)malloc((3 * (size_t)w.np + 1) * sizeof(double));
    if (!r->fluid || !r->poly) {
        fprintf(stderr, "%s: out of memory\n", c->name);
        hcbd_hc_world_destroy(&w);
        return 0;
    }
    hcbd_hc_world_get_fluid(&w, r->fluid, r->fluid + 3 * (size_t)w.nf);
    hcbd_hc_world_get_polymers(&w, r->poly);
    printf("restart=%s: step %lld, %d fluid blobs, %d polymers\n", c->restart, (long long)w.step, w.nf, w.np);
    hcbd_hc_world_destroy(&w);
    return 1;
}

/* w takes the configuration r if its counts are nf and np; 0 after a message. */
static inline int hc_place(const config *c, const hc_config *r, hcbd_hc_world *w, int nf, int np)
{
    if (r->nf != nf || r->np != np) {
        fprintf(stderr, "%s: restart=%s holds %d fluid blobs and %d polymers, the run %d and %d\n",
                c->name, c->restart, r->nf, r->np, nf, np);
        return 0;
    }
    if (hcbd_hc_world_set_fluid(w, nf, r->fluid, r->fluid + 3 * (size_t)nf) != HCBD_OK ||
        (np && hcbd_hc_world_set_polymers(w, np, r->poly) != HCBD_OK)) {
        fprintf(stderr, "%s: restart=%s: %s\n", c->name, c->restart, w->err.msg);
        return 0;
    }
    return 1;
}
#endif

/* Closes the trajectory and writes the checkpoint; 0 after a message. */
static inline int run_out_close(const config *c, run_out *o, ex_world *w)
{
    char path[700];
    if (o->xyz) fclose(o->xyz);
    o->xyz = NULL;
    if (!c->checkpoint[0]) return 1;
    labelled(path, sizeof path, c->checkpoint, o->label);
    if (EX_SAVE(w, path) != HCBD_OK) {
        fprintf(stderr, "%s: %s\n", c->name, w->err.msg);
        return 0;
    }
    printf("checkpoint=%s (step %lld)\n", path, (long long)w->step);
    return 1;
}

/* The scene's stability limits with their margins (hcbd_params_stability),
   printed at start. */
#if HCBD_MODEL == HCBD_MODEL_HCBD
static inline void print_limits(const hcbd_hc_params *p)
#else
static inline void print_limits(const hcbd_params *p)
#endif
{
    hcbd_limit l[HCBD_MAX_LIMITS];
    char buf[4096];
    int n = 0;
#if HCBD_MODEL == HCBD_MODEL_HCBD
    if (hcbd_hc_params_stability(p, l, &n) != HCBD_OK) return;
#else
    if (hcbd_params_stability(p, l, &n) != HCBD_OK) return;
#endif
    static char last[4096];
    hcbd_limits_format(l, n, buf, sizeof buf);
    if (!strcmp(buf, last)) return; /* the runs of one scene repeat them */
    memcpy(last, buf, sizeof last);
    printf("# stability limits (value / bound; margin = bound / value, ok above 1; what crossing does):\n%s", buf);
}
#endif
