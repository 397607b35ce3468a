/* libFuzzer harness for the examples' key=value parser (example_common.h):
   parse_args with an own-key callback that uses parse_list, parse_int,
   parse_choice and check_preset, then hcbd_params_check and
   hcbd_params_stability/hcbd_limits_format on what it accepted.

   The input is split at NUL and newline bytes into at most MAXARGS
   arguments after argv[0]; each argument gets its own malloc'd,
   NUL-terminated buffer of exactly its length + 1, so that ASan sees any
   read past its end.

   Build (walled or gibd model):
     clang -g -O1 -fsanitize=fuzzer,address,undefined \
       -DHCBD_MODEL=HCBD_MODEL_WALLED -I. tests/fuzz/fuzz_args.c hcbd_impl.c \
       -lm -o build/fuzz_args
   Run (-close_fd_mask=2 silences the parser's messages, not the reports;
   halt_on_error=1 turns a UBSan report into a saved crash; new inputs go
   to the first folder, so give it a scratch one):
     mkdir -p /tmp/fz && UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
       build/fuzz_args -close_fd_mask=2 -max_total_time=180 \
       -dict=tests/fuzz/args.dict /tmp/fz tests/fuzz/corpus_args
   Regression (each file once; regress_args/ holds inputs of bugs found,
   crashes or silent misparses, named after what they show):
     build/fuzz_args tests/fuzz/regress_args/FILE...  */
#if defined(__GNUC__) /* the helpers this harness does not use */
#pragma GCC diagnostic ignored "-Wunused-function"
#endif
#include "examples/example_common.h" /* first: it sets _POSIX_C_SOURCE */
#include <stddef.h>
#include <stdint.h>

#define MAXARGS 16

static int fz_list_n, fz_blocks;
static double fz_list[4];

static void fz_usage(FILE *f) { (void)f; } /* the examples' usage() exits nowhere either */

static int fz_own(config *c, const char *key, const char *v)
{
    double d;
    int x;
    if (!strcmp(key, "preset")) return check_preset(c, v);
    if (!strcmp(key, "gdot")) return (fz_list_n = parse_list(c, key, v, fz_list, 4)) > 0;
    if (!strcmp(key, "xip")) return (fz_list_n = parse_list(c, key, v, fz_list, 1)) > 0;
    if (!strcmp(key, "blocks")) {
        if (!parse_int(c, key, v, &fz_blocks)) return 0;
        return fz_blocks > 0;
    }
    if (!strcmp(key, "sort")) {
        if (!parse_choice(c, key, v, "on", "off", &x, 1, 0)) return 0;
        c->def.params.sort = x;
        return 1;
    }
    if (!strcmp(key, "gamma")) {
        if (!parse_double(c, key, v, &d)) return 0;
        c->def.params.gdot = d;
        return 1;
    }
    return -1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *argv[MAXARGS + 2];
    int argc = 0, k;
    size_t a = 0, b;
    config c;

    argv[argc++] = (char *)"fuzz_args";
    while (a <= size && argc < MAXARGS + 1) {
        for (b = a; b < size && data[b] != 0 && data[b] != '\n'; ++b) {}
        argv[argc] = (char *)malloc(b - a + 1);
        if (!argv[argc]) break;
        if (b > a) memcpy(argv[argc], data + a, b - a);
        argv[argc][b - a] = 0;
        ++argc;
        a = b + 1;
    }
    argv[argc] = NULL;

    /* as gibd_bulk's main() */
    memset(&c, 0, sizeof c);
    c.name = "fuzz_args";
    c.def = hcbd_world_def_default();
    c.N = 512;
    c.density = 0.24;
    c.steps = 40000;
    snprintf(c.out, sizeof c.out, "out/fuzz");
    fz_list_n = 0;
    fz_blocks = 0;

    if (parse_args(argc, argv, &c, fz_own, fz_usage)) {
        char msg[256], buf[4096];
        hcbd_limit l[HCBD_MAX_LIMITS];
        int n = 0;
        msg[0] = 0;
        (void)hcbd_params_check(&c.def.params, msg, sizeof msg);
        if (hcbd_params_stability(&c.def.params, l, &n) == HCBD_OK)
            (void)hcbd_limits_format(l, n, buf, sizeof buf);
    }

    for (k = 1; k < argc; ++k) free(argv[k]);
    return 0;
}
