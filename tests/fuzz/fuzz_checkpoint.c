/* libFuzzer harness for the checkpoint loaders.  The first input byte picks
   what the rest is:
     0  a whole file, loaded as it is (header checks, truncation);
     1  a GI-BD/walled world's payload, 2 an HCBD world's: the harness puts a
        valid header with the right checksum in front, so the fuzzer gets
        past the checksum into the parser.
   A world that loads is stepped once, saved and loaded again (it must give
   the same bits).  HCBD_LOAD_MAX_BYTES keeps the worlds a file may ask for
   small enough to fuzz.

   Build and run: make fuzz (see the Makefile); replay a folder of inputs
   without libFuzzer: tests/fuzz/replay.c. */
#include "hcbd.h"
#include <stdlib.h>
#include <string.h>

static void put64(unsigned char *b, uint64_t v)
{
    int k;
    for (k = 0; k < 8; ++k) b[k] = (unsigned char)(v >> (8 * k));
}

static uint64_t fnv(const unsigned char *b, size_t n)
{
    uint64_t h = 0xCBF29CE484222325ULL;
    size_t k;
    for (k = 0; k < n; ++k) h = (h ^ b[k]) * 0x100000001B3ULL;
    return h;
}

static void round_trip(hcbd_world *w)
{
    size_t n = hcbd_world_checkpoint_size(w);
    unsigned char *b = (unsigned char *)malloc(n);
    hcbd_world v;
    if (b && hcbd_world_checkpoint_save(w, b, n) == HCBD_OK && hcbd_world_checkpoint_load(&v, b, n) == HCBD_OK) {
        if (hcbd_world_checksum(&v) != hcbd_world_checksum(w)) abort();
        hcbd_world_destroy(&v);
    }
    free(b);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    unsigned char *b;
    size_t n;
    int kind;
    if (size < 1) return 0;
    kind = data[0];
    if (kind == 0) {
        b = (unsigned char *)malloc(size - 1 + 1);
        memcpy(b, data + 1, size - 1);
        n = size - 1;
    } else {
        n = 56 + size - 1;
        b = (unsigned char *)malloc(n);
        memcpy(b, "HCBDCKPT", 8);
        put64(b + 8, HCBD_CHECKPOINT_VERSION);
        put64(b + 16, HCBD_MODEL);
        put64(b + 24, sizeof(hcbd_real));
        put64(b + 32, (uint64_t)kind);
        put64(b + 40, size - 1);
        memcpy(b + 56, data + 1, size - 1);
        put64(b + 48, fnv(b + 56, size - 1));
    }
    {
        hcbd_world w;
        if (hcbd_world_checkpoint_load(&w, b, n) == HCBD_OK) {
            hcbd_world_step(&w, 1);
            round_trip(&w);
            hcbd_world_destroy(&w);
        }
    }
#if HCBD_MODEL == HCBD_MODEL_HCBD
    {
        hcbd_hc_world w;
        if (hcbd_hc_world_checkpoint_load(&w, b, n) == HCBD_OK) {
            hcbd_hc_world_step(&w, 1);
            hcbd_hc_world_destroy(&w);
        }
    }
#endif
    free(b);
    return 0;
}
