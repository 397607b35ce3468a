# hcbd: make (library object + examples), make run, make test, make bench.
# Settable: CC, CFLAGS, OMP=1|0 (OpenMP on/off), SAN_CC (sanitizer compiler),
# MODEL=walled|gibd (walled, the default, is GI-BD plus walls); the HCBD
# examples, tests and bench are always built with -DHCBD_MODEL=HCBD_MODEL_HCBD.
CC      ?= cc
OMP     ?= 1
CFLAGS  ?= -O2 -march=native
WARN    := -std=c99 -Wall -Wextra -Wpedantic -Werror
# Contraction into FMA would let the compiler change rounding: keep results
# identical across builds that differ only in optimisation.
FP      := -ffp-contract=off
ifeq ($(OMP),1)
OMPFLAG := -fopenmp
endif
MODEL   ?= walled
ifeq ($(MODEL),gibd)
MODELFLAG := -DHCBD_MODEL=HCBD_MODEL_GIBD
else ifeq ($(MODEL),walled)
MODELFLAG := -DHCBD_MODEL=HCBD_MODEL_WALLED
else
$(error MODEL=$(MODEL) is not walled or gibd)
endif
HCBDFLAG := -DHCBD_MODEL=HCBD_MODEL_HCBD
HC_CFLAGS = $(WARN) $(FP) $(HCBDFLAG) $(CFLAGS) $(OMPFLAG)
ALL_CFLAGS = $(WARN) $(FP) $(MODELFLAG) $(CFLAGS) $(OMPFLAG)
LDLIBS  := -lm
B       := build

EXAMPLES := $(B)/gibd_bulk $(B)/shear_flow $(B)/channel_flow
HC_EXAMPLES := $(B)/hcbd_fluid $(B)/hcbd_polymer
HEADERS  := hcbd.h
TEST_SRC := $(wildcard tests/test_*.c) tests/main.c

.PHONY: all run test test-main test-float test-gibd test-hcbd test-sanitize test-build bench bench-wp bench-stability bench-peers bench-parts clean

all: $(B)/hcbd_impl.o $(EXAMPLES) $(HC_EXAMPLES)

$(B):
	mkdir -p $(B)

$(B)/hcbd_impl.o: hcbd_impl.c $(HEADERS) Makefile | $(B)
	$(CC) $(ALL_CFLAGS) -c $< -o $@

$(B)/%: examples/%.c $(B)/hcbd_impl.o $(HEADERS)
	$(CC) $(ALL_CFLAGS) $< $(B)/hcbd_impl.o -o $@ $(LDLIBS)

# The 2018 model: fluid and polymer blobs (its own build of the library).
$(B)/hcbd_impl_hc.o: hcbd_impl.c $(HEADERS) Makefile | $(B)
	$(CC) $(HC_CFLAGS) -c $< -o $@

$(B)/hcbd_%: examples/hcbd_%.c $(B)/hcbd_impl_hc.o $(HEADERS) examples/example_common.h
	$(CC) $(HC_CFLAGS) $< $(B)/hcbd_impl_hc.o -o $@ $(LDLIBS)

# The main job: the flagship example on its built-in default scene.
run: $(B)/gibd_bulk
	./$(B)/gibd_bulk out=out/gibd_bulk

$(B)/run_tests: $(TEST_SRC) tests/test.h tests/list.h $(B)/hcbd_impl.o
	$(CC) $(ALL_CFLAGS) $(TEST_SRC) $(B)/hcbd_impl.o -o $@ $(LDLIBS)

$(B)/run_tests_float: $(TEST_SRC) tests/test.h tests/list.h hcbd_impl.c $(HEADERS) | $(B)
	$(CC) $(ALL_CFLAGS) -DHCBD_REAL=float $(TEST_SRC) hcbd_impl.c -o $@ $(LDLIBS)

SAN_CC ?= clang
SAN := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer

# The HCBD build runs its own tests (test_hc_*) and the shared determinism tests.
$(B)/run_tests_hcbd: $(TEST_SRC) tests/test.h tests/list.h $(B)/hcbd_impl_hc.o
	$(CC) $(HC_CFLAGS) $(TEST_SRC) $(B)/hcbd_impl_hc.o -o $@ $(LDLIBS)

$(B)/run_tests_hcbd_san: $(TEST_SRC) tests/test.h tests/list.h hcbd_impl.c $(HEADERS) | $(B)
	$(SAN_CC) $(WARN) $(FP) $(HCBDFLAG) -O1 -g $(SAN) $(TEST_SRC) hcbd_impl.c -o $@ $(LDLIBS)

# The lean GI-BD build: no wall code compiled, wall parameters rejected.
$(B)/run_tests_gibd: $(TEST_SRC) tests/test.h tests/list.h hcbd_impl.c $(HEADERS) | $(B)
	$(CC) $(WARN) $(FP) $(CFLAGS) $(OMPFLAG) -DHCBD_MODEL=HCBD_MODEL_GIBD $(TEST_SRC) hcbd_impl.c -o $@ $(LDLIBS)

$(B)/run_tests_san: $(TEST_SRC) tests/test.h tests/list.h hcbd_impl.c $(HEADERS) | $(B)
	$(SAN_CC) $(WARN) $(FP) $(MODELFLAG) -O1 -g $(SAN) $(TEST_SRC) hcbd_impl.c -o $@ $(LDLIBS)

# make test: strict builds, the full suite, the float build's bit-level
# tests, the GI-BD build's, and the whole suite in quick mode under ASan +
# UBSan.
test: test-build test-main test-float test-gibd test-hcbd test-sanitize

test-main: $(B)/run_tests
	./$(B)/run_tests

test-float: $(B)/run_tests_float
	./$(B)/run_tests_float test_determinism

test-gibd: $(B)/run_tests_gibd
	./$(B)/run_tests_gibd test_determinism test_bad_parameters test_model_switch test_momentum

test-hcbd: $(B)/run_tests_hcbd
	./$(B)/run_tests_hcbd test_hc_

test-sanitize: $(B)/run_tests_san $(B)/run_tests_hcbd_san
	ASAN_OPTIONS=detect_leaks=1 ./$(B)/run_tests_hcbd_san --quick test_hc_
	ASAN_OPTIONS=detect_leaks=1 ./$(B)/run_tests_san --quick

# The header alone, both halves, with gcc and clang as C99 and C11 and as C++.
test-build: | $(B)
	printf '#define HCBD_IMPLEMENTATION\n#include "../hcbd.h"\nint main(void){return 0;}\n' > $(B)/compile_test.c
	for m in GIBD WALLED HCBD; do for cc in gcc clang; do for std in c99 c11; do \
	  $$cc -std=$$std -Wall -Wextra -Wpedantic -Werror -Wshadow -O2 -DHCBD_MODEL=HCBD_MODEL_$$m -c $(B)/compile_test.c -o $(B)/ct.o || exit 1; \
	  $$cc -std=$$std -Wall -Wextra -Wpedantic -Werror -O2 -fopenmp -DHCBD_REAL=float -DHCBD_MODEL=HCBD_MODEL_$$m -c $(B)/compile_test.c -o $(B)/ct.o || exit 1; \
	done; done; \
	for cxx in g++ clang++; do \
	  $$cxx -x c++ -std=c++11 -Wall -Wextra -Werror -O2 -DHCBD_MODEL=HCBD_MODEL_$$m -c $(B)/compile_test.c -o $(B)/ct.o || exit 1; done; done
	for cc in gcc clang; do $$cc $(WARN) $(MODELFLAG) -fsyntax-only $(filter-out examples/hcbd_%,$(wildcard examples/*.c)) $(filter-out bench/bench_hcbd.c bench/bench_wp_hcbd.c,$(wildcard bench/*.c)) || exit 1; \
	  $$cc $(WARN) $(HCBDFLAG) -fsyntax-only $(wildcard examples/hcbd_*.c bench/bench_hcbd.c bench/bench_wp_hcbd.c bench/stability.c bench/bench_parts.c) || exit 1; done
	@echo "test-build: header compiles as C99, C11 and C++11 with gcc and clang, GI-BD, walled and HCBD; examples and bench too"

bench: $(B)/bench_speed $(B)/bench_hcbd
	./$(B)/bench_speed out=out/bench
	./$(B)/bench_hcbd out=out/bench

$(B)/bench_hcbd: bench/bench_hcbd.c $(B)/hcbd_impl_hc.o $(HEADERS)
	$(CC) $(HC_CFLAGS) $< $(B)/hcbd_impl_hc.o -o $@ $(LDLIBS)

$(B)/bench_speed: bench/bench_speed.c $(B)/hcbd_impl.o $(HEADERS)
	$(CC) $(ALL_CFLAGS) $< $(B)/hcbd_impl.o -o $@ $(LDLIBS)

# Work-precision: run time per unit of simulated time against the error
# from theory, over dt (and h), integrators, precision and noise; CSV and
# figure in out/bench (bench/wp.sh).
WP_BINS := $(B)/bench_wp $(B)/bench_wp_float $(B)/bench_wp_hcbd $(B)/bench_wp_hcbd_float
bench-wp: $(WP_BINS)
	bench/wp.sh out/bench

$(B)/bench_wp: bench/bench_wp.c $(B)/hcbd_impl.o $(HEADERS)
	$(CC) $(ALL_CFLAGS) $< $(B)/hcbd_impl.o -o $@ $(LDLIBS)

$(B)/bench_wp_float: bench/bench_wp.c hcbd_impl.c $(HEADERS) | $(B)
	$(CC) $(ALL_CFLAGS) -DHCBD_REAL=float $< hcbd_impl.c -o $@ $(LDLIBS)

$(B)/bench_wp_hcbd: bench/bench_wp_hcbd.c $(B)/hcbd_impl_hc.o $(HEADERS)
	$(CC) $(HC_CFLAGS) $< $(B)/hcbd_impl_hc.o -o $@ $(LDLIBS)

$(B)/bench_wp_hcbd_float: bench/bench_wp_hcbd.c hcbd_impl.c $(HEADERS) | $(B)
	$(CC) $(HC_CFLAGS) -DHCBD_REAL=float $< hcbd_impl.c -o $@ $(LDLIBS)

# Stability map: the largest dt before a guard or a 10 % temperature error,
# against hcbd_stability's limits (bench/stability.sh).
bench-stability: $(B)/bench_stability $(B)/bench_stability_hcbd
	bench/stability.sh out/bench

$(B)/bench_stability: bench/stability.c $(B)/hcbd_impl.o $(HEADERS)
	$(CC) $(ALL_CFLAGS) $< $(B)/hcbd_impl.o -o $@ $(LDLIBS)

$(B)/bench_stability_hcbd: bench/stability.c $(B)/hcbd_impl_hc.o $(HEADERS)
	$(CC) $(HC_CFLAGS) $< $(B)/hcbd_impl_hc.o -o $@ $(LDLIBS)

# Cost of each optional part of a scene, on and off, in all three builds.
bench-parts: $(B)/bench_parts $(B)/bench_parts_gibd $(B)/bench_parts_hcbd
	./$(B)/bench_parts_gibd out=out/bench
	./$(B)/bench_parts out=out/bench
	./$(B)/bench_parts_hcbd out=out/bench

$(B)/bench_parts: bench/bench_parts.c $(B)/hcbd_impl.o $(HEADERS)
	$(CC) $(ALL_CFLAGS) $< $(B)/hcbd_impl.o -o $@ $(LDLIBS)

$(B)/bench_parts_gibd: bench/bench_parts.c hcbd_impl.c $(HEADERS) | $(B)
	$(CC) $(WARN) $(FP) $(CFLAGS) $(OMPFLAG) -DHCBD_MODEL=HCBD_MODEL_GIBD $< hcbd_impl.c -o $@ $(LDLIBS)

$(B)/bench_parts_hcbd: bench/bench_parts.c $(B)/hcbd_impl_hc.o $(HEADERS)
	$(CC) $(HC_CFLAGS) $< $(B)/hcbd_impl_hc.o -o $@ $(LDLIBS)

# Side by side with LAMMPS (skipped with a message when lmp is missing).
bench-peers: $(B)/bench_speed $(B)/bench_hcbd
	bench/peers/run.sh

clean:
	rm -rf $(B) out
