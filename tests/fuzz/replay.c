/* Runs a libFuzzer harness on the files named on the command line, once
   each, without libFuzzer: make test replays the regression inputs and
   the seed corpora under ASan + UBSan with it. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int main(int argc, char **argv)
{
    int k;
    for (k = 1; k < argc; ++k) {
        FILE *f = fopen(argv[k], "rb");
        long n;
        uint8_t *b;
        if (!f || fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
            fprintf(stderr, "replay: cannot read %s\n", argv[k]);
            return 1;
        }
        b = (uint8_t *)malloc((size_t)n + 1);
        if (!b || fread(b, 1, (size_t)n, f) != (size_t)n) {
            fprintf(stderr, "replay: cannot read %s\n", argv[k]);
            return 1;
        }
        fclose(f);
        LLVMFuzzerTestOneInput(b, (size_t)n);
        free(b);
    }
    printf("replay: %d inputs, no crash\n1 passed, 0 failed\n", argc - 1);
    return 0;
}
