# hcbd: make (library object + examples), make run, make test, make bench.
# Settable: CC, CFLAGS, OMP=1|0 (OpenMP on/off), SAN_CC (sanitizer compiler),
# MODEL=walled|gibd (walled, the default, is GI-BD plus walls); the HCBD
# examples, tests and bench are always built with -DHCBD_MODEL=HCBD_MODEL_HCBD.
CC      ?= cc
OMP     ?= 1
CFLAGS  ?= -O2 -march=native
WARN    := -std=c99 -Wall -Wextra -Wpedantic -Werror
# Contraction into FMA would let the compiler change rounding: keep results
# identical across builds that differ only in optimisation.  sqrt without
# errno is the same correctly rounded sqrt, minus a check and a branch.
FP      := -ffp-contract=off -fno-math-errno
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

EXAMPLES := $(B)/first_step $(B)/gibd_bulk $(B)/shear_flow $(B)/channel_flow
HC_EXAMPLES := $(B)/hcbd_fluid $(B)/hcbd_polymer $(B)/hcbd_sound
HEADERS  := hcbd.h
TEST_SRC := $(wildcard tests/test_*.c) tests/main.c

.PHONY: all run python test-python test validate mutants exercise lammps test-lammps mutants-lammps test-main test-walls test-float test-hcbd-float test-hcbd-float-clang test-examples test-gibd test-hcbd test-sanitize test-sanitize-hcbd test-tsan test-tsan-hcbd test-fuzz-args test-fuzz-ckpt test-install test-build build-check install fuzz bench bench-wp bench-wp-peers bench-wp-sph-peers bench-wp-sdpd-peers bench-wp-table1 bench-table2-departures bench-stability bench-peers bench-parts bench-soak clean

all: $(B)/hcbd_impl.o $(EXAMPLES) $(HC_EXAMPLES)

$(B):
	mkdir -p $(B)

$(B)/hcbd_impl.o: hcbd_impl.c $(HEADERS) Makefile | $(B)
	$(CC) $(ALL_CFLAGS) -c $< -o $@

$(B)/%: examples/%.c $(B)/hcbd_impl.o $(HEADERS) examples/example_common.h
	$(CC) $(ALL_CFLAGS) $< $(B)/hcbd_impl.o -o $@ $(LDLIBS)

# The 2018 model: fluid and polymer blobs (its own build of the library).
$(B)/hcbd_impl_hc.o: hcbd_impl.c $(HEADERS) Makefile | $(B)
	$(CC) $(HC_CFLAGS) -c $< -o $@

$(B)/hcbd_%: examples/hcbd_%.c $(B)/hcbd_impl_hc.o $(HEADERS) examples/example_common.h
	$(CC) $(HC_CFLAGS) $< $(B)/hcbd_impl_hc.o -o $@ $(LDLIBS)

# The main job: the flagship example on its built-in default scene.
run: $(B)/gibd_bulk
	./$(B)/gibd_bulk out=out/gibd_bulk

$(B)/run_tests: $(TEST_SRC) tests/test.h tests/scenes.h tests/list.h tests/hc_ref.h $(B)/hcbd_impl.o
	$(CC) $(ALL_CFLAGS) $(TEST_SRC) $(B)/hcbd_impl.o -o $@ $(LDLIBS)

$(B)/run_tests_float: $(TEST_SRC) tests/test.h tests/scenes.h tests/list.h tests/hc_ref.h hcbd_impl.c $(HEADERS) | $(B)
	$(CC) $(ALL_CFLAGS) -DHCBD_REAL=float $(TEST_SRC) hcbd_impl.c -o $@ $(LDLIBS)

SAN_CC ?= clang
SAN := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer

# The HCBD build runs its own tests (test_hc_*) and the shared determinism tests.
$(B)/run_tests_hcbd: $(TEST_SRC) tests/test.h tests/scenes.h tests/list.h tests/hc_ref.h $(B)/hcbd_impl_hc.o
	$(CC) $(HC_CFLAGS) $(TEST_SRC) $(B)/hcbd_impl_hc.o -o $@ $(LDLIBS)

$(B)/run_tests_hcbd_float: $(TEST_SRC) tests/test.h tests/scenes.h tests/list.h tests/hc_ref.h hcbd_impl.c $(HEADERS) | $(B)
	$(CC) $(HC_CFLAGS) -DHCBD_REAL=float $(TEST_SRC) hcbd_impl.c -o $@ $(LDLIBS)

# The library under ASan + UBSan, one object per model, shared by the
# sanitized suite and the fuzz-input replays.  The HCBD one has the
# fuzzers' 64 MiB cap on the worlds a checkpoint may ask for.
FUZZ_CAP := "-DHCBD_LOAD_MAX_BYTES=((size_t)64 << 20)"
$(B)/san_impl.o: hcbd_impl.c $(HEADERS) | $(B)
	$(SAN_CC) $(WARN) $(FP) $(MODELFLAG) -O1 -g $(SAN) -c $< -o $@

$(B)/san_impl_hc.o: hcbd_impl.c $(HEADERS) | $(B)
	$(SAN_CC) $(WARN) $(FP) $(HCBDFLAG) $(FUZZ_CAP) -O1 -g $(SAN) -c $< -o $@

$(B)/run_tests_hcbd_san: $(TEST_SRC) tests/test.h tests/scenes.h tests/list.h tests/hc_ref.h $(B)/san_impl_hc.o
	$(SAN_CC) $(WARN) $(FP) $(HCBDFLAG) -O1 -g $(SAN) $(TEST_SRC) $(B)/san_impl_hc.o -o $@ $(LDLIBS)

# The lean GI-BD build: no wall code compiled, wall parameters rejected.
$(B)/run_tests_gibd: $(TEST_SRC) tests/test.h tests/scenes.h tests/list.h tests/hc_ref.h hcbd_impl.c $(HEADERS) | $(B)
	$(CC) $(WARN) $(FP) $(CFLAGS) $(OMPFLAG) -DHCBD_MODEL=HCBD_MODEL_GIBD $(TEST_SRC) hcbd_impl.c -o $@ $(LDLIBS)

$(B)/run_tests_san: $(TEST_SRC) tests/test.h tests/scenes.h tests/list.h tests/hc_ref.h $(B)/san_impl.o
	$(SAN_CC) $(WARN) $(FP) $(MODELFLAG) -O1 -g $(SAN) $(TEST_SRC) $(B)/san_impl.o -o $@ $(LDLIBS)

# make test: every part below, JOBS at a time, each into its own log in
# build/logs (a failing part's lines are shown); the last line sums all
# parts as "N passed, N failed".  Parts: strict builds of the header (gcc
# and clang, C99/C11/C++11, three models, -Wshadow -Wconversion); the full
# suite; the float, GI-BD and HCBD builds (the float HCBD goldens with clang
# too); the suite under ASan + UBSan
# (quick mode) and the threaded determinism and restart tests under TSan;
# the fuzz inputs replayed under ASan + UBSan; an install and a program
# built against the installed header only.
JOBS ?= 2
TEST_PARTS := main sanitize walls hcbd sanitize-hcbd hcbd-float hcbd-float-clang examples float gibd tsan tsan-hcbd fuzz-args fuzz-ckpt install build docs python
LOG = > $(CURDIR)/$(B)/logs/$(1).log 2>&1 || { tail -n 30 $(CURDIR)/$(B)/logs/$(1).log; exit 1; }
# The parts share the cores: an OpenMP thread that waits sleeps instead of
# spinning on a core another part needs (a threaded run took 7 s instead
# of 4 beside a busy core).
test: export OMP_WAIT_POLICY := PASSIVE
test:
	@rm -rf $(B)/logs && mkdir -p $(B)/logs
	@date +%s > $(B)/logs/start
	@# the main suite is the longest part: its binary first, so that it
	@# runs while the other parts build
	-@$(MAKE) --no-print-directory -j$(JOBS) $(B)/run_tests $(B)/gibd_bulk
	-@$(MAKE) --no-print-directory -k -j$(JOBS) $(addprefix test-,$(TEST_PARTS))
	@tests/summary.sh $(B)/logs $(TEST_PARTS)

# make python: the Python package (python/hcbd, ctypes and numpy; no
# compiled extension module): its two shared libraries, the walled build
# and the 2018 one, each hcbd_impl.c with the package's C layer
# (python/hcbd_py.c), and a .pth file in PYTHON's user site-packages that
# points at python/.  PYTHON: the first python3 that imports numpy
# (Debian's /usr/bin/python3 after apt-get install python3-numpy), or
# PYTHON=... to choose.
PYTHON ?= $(shell for p in python3 /usr/bin/python3; do $$p -c 'import numpy' >/dev/null 2>&1 && { command -v $$p; break; }; done)
PY_LIBS := python/hcbd/_hcbd_walled.so python/hcbd/_hcbd_hc.so
python/hcbd/_hcbd_walled.so: hcbd_impl.c python/hcbd_py.c $(HEADERS) Makefile
	$(CC) $(WARN) $(FP) -DHCBD_MODEL=HCBD_MODEL_WALLED $(CFLAGS) $(OMPFLAG) -fPIC -shared hcbd_impl.c python/hcbd_py.c -o $@ $(LDLIBS)

python/hcbd/_hcbd_hc.so: hcbd_impl.c python/hcbd_py.c $(HEADERS) Makefile
	$(CC) $(HC_CFLAGS) -fPIC -shared hcbd_impl.c python/hcbd_py.c -o $@ $(LDLIBS)

python: $(PY_LIBS)
	@test -n "$(PYTHON)" || { echo "make python: no python3 here imports numpy (apt-get install python3-numpy, or PYTHON=...)"; exit 1; }
	@site=$$($(PYTHON) -c 'import site; print(site.getusersitepackages())') && mkdir -p "$$site" && \
	  echo "$(CURDIR)/python" > "$$site/hcbd.pth" && \
	  echo "make python: $(PYTHON) imports hcbd from $(CURDIR)/python ($$site/hcbd.pth)"

# make lammps: LAMMPS with the PLUGIN package and MPI, from Debian's source
# package, into build/lammps (cached), and the GI-BD plugin against it;
# skipped with a message where the tools are missing (lammps/build.sh).
# make test-lammps (CI runs it after make test): the plugin on 1, 2 and 4
# ranks against hcbd's own run (lammps/check.sh).
lammps:
	lammps/build.sh

test-lammps: lammps $(B)/gibd_bulk $(B)/shear_flow $(B)/channel_flow $(B)/hcbd_polymer
	lammps/check.sh

# make mutants-lammps: every injected error of the plugins is caught by the
# atom-by-atom part of test-lammps (lammps/mutants.sh, ~35 min)
mutants-lammps: lammps
	lammps/mutants.sh

# make mutants (not in CI): every injected single-coefficient error of
# tests/mutants/mutants.txt must make the suite fail; NAMES="a b" picks.
mutants:
	tests/mutants/run.sh

# make validate (not in CI, about 20 minutes): the statistical tests at
# full, paper-like length (--long), GI-BD/walled and HCBD builds.
validate: $(B)/run_tests $(B)/run_tests_hcbd $(B)/gibd_bulk
	./$(B)/run_tests --long
	./$(B)/run_tests_hcbd --long test_hc_

$(B)/logs:
	mkdir -p $@

# The suite in two parts that run side by side: the wall tests, then the rest.
test-main: $(B)/run_tests $(B)/gibd_bulk | $(B)/logs
	HCBD_TEST_SKIP=test_wall_ ./$(B)/run_tests $(call LOG,main)

test-walls: $(B)/run_tests | $(B)/logs
	./$(B)/run_tests test_wall_ $(call LOG,walls)

# The float and GI-BD builds in quick mode: their full-length runs of
# the same code are in the main suite.
test-float: $(B)/run_tests_float | $(B)/logs
	HCBD_TEST_SKIP=determinism_parallel ./$(B)/run_tests_float --quick test_determinism test_golden test_checkpoint $(call LOG,float)

test-gibd: $(B)/run_tests_gibd | $(B)/logs
	HCBD_TEST_SKIP=determinism_parallel ./$(B)/run_tests_gibd --quick test_determinism test_golden test_bad_param test_bad_input test_model_switch test_momentum test_checkpoint test_runtime $(call LOG,gibd)

test-hcbd: $(B)/run_tests_hcbd | $(B)/logs
	./$(B)/run_tests_hcbd test_hc_ test_golden $(call LOG,hcbd)

# Every example's argument handling, first_step against its theory, the
# exercise checker on exercises 1 and 2, and carreau_refit's pooled fit.
test-examples: $(EXAMPLES) $(HC_EXAMPLES) $(B)/carreau_refit | $(B)/logs
	tests/examples.sh $(B) $(call LOG,examples)

# make exercise N=k [ANSWER=x]: runs exercise k of docs/exercises.md and
# says whether the run, and the answer, are within its tolerance.
exercise: $(EXAMPLES) $(HC_EXAMPLES)
	@examples/exercise.sh $(B) "$(N)" "$(ANSWER)"

# The float HCBD build with clang too (-O1: the golden hashes hold for -O1
# and -O2 alike): the same hashes for both compilers (gcc's straight-line
# vectoriser once made them differ).  KMP_BLOCKTIME=0: clang's OpenMP
# threads sleep instead of spinning between the golden runs' steps.
$(B)/run_tests_hcbd_float_clang: $(TEST_SRC) tests/test.h tests/scenes.h tests/list.h tests/hc_ref.h hcbd_impl.c $(HEADERS) | $(B)
	$(SAN_CC) $(WARN) $(FP) $(HCBDFLAG) -O1 $(OMPFLAG) -DHCBD_REAL=float $(TEST_SRC) hcbd_impl.c -o $@ $(LDLIBS)

test-hcbd-float: $(B)/run_tests_hcbd_float | $(B)/logs
	./$(B)/run_tests_hcbd_float --quick test_golden test_hc_determinism test_hc_checkpoint $(call LOG,hcbd-float)

test-hcbd-float-clang: $(B)/run_tests_hcbd_float_clang | $(B)/logs
	KMP_BLOCKTIME=0 ./$(B)/run_tests_hcbd_float_clang --quick test_golden $(call LOG,hcbd-float-clang)

# Under the sanitizers the longest statistical runs are left out: they
# repeat code paths that shorter tests (the absolute one-step tests, the
# wall and shear tests) already take, and their asserts are off in quick
# mode anyway.
SAN_SKIP := test_wall_channel_flow,test_wall_body_force_variants,test_le_linear_profile,test_statics_default_tau,test_wall_temperature_profile,test_msd_tau_trend,test_msd_ideal_gibd,test_transverse_current_initial_decay,test_wall_momentum_decay,test_le_carrier_flux_planes,test_equipartition_euler_bias,test_equipartition_shardlow,test_le_list_every_step
SAN_SKIP_HC := test_hc_fluid_viscosity,test_hc_poiseuille_no_lag,test_hc_fluid_equipartition,test_hc_fluid_equipartition_shardlow
test-sanitize: $(B)/run_tests_san $(B)/gibd_bulk | $(B)/logs
	ASAN_OPTIONS=detect_leaks=1 HCBD_TEST_SKIP=$(SAN_SKIP) ./$(B)/run_tests_san --quick $(call LOG,sanitize)

test-sanitize-hcbd: $(B)/run_tests_hcbd_san | $(B)/logs
	ASAN_OPTIONS=detect_leaks=1 HCBD_TEST_SKIP=$(SAN_SKIP_HC) ./$(B)/run_tests_hcbd_san --quick test_hc_ $(call LOG,sanitize-hcbd)

# ThreadSanitizer needs an OpenMP runtime it can see through: clang's
# libomp loads its archer tool, which tells TSan where the barriers are;
# gcc's libgomp is not instrumented (hundreds of false reports).
TSAN := -fsanitize=thread -fopenmp -O1 -g
TSAN_ENV := TSAN_OPTIONS='ignore_noninstrumented_modules=1 halt_on_error=1'
$(B)/run_tests_tsan: $(TEST_SRC) tests/test.h tests/scenes.h tests/list.h tests/hc_ref.h hcbd_impl.c $(HEADERS) | $(B)
	$(SAN_CC) $(WARN) $(FP) $(MODELFLAG) $(TSAN) $(TEST_SRC) hcbd_impl.c -o $@ $(LDLIBS)

$(B)/run_tests_hcbd_tsan: $(TEST_SRC) tests/test.h tests/scenes.h tests/list.h tests/hc_ref.h hcbd_impl.c $(HEADERS) | $(B)
	$(SAN_CC) $(WARN) $(FP) $(HCBDFLAG) $(TSAN) $(TEST_SRC) hcbd_impl.c -o $@ $(LDLIBS)

test-tsan: $(B)/run_tests_tsan | $(B)/logs
	$(TSAN_ENV) ./$(B)/run_tests_tsan --quick test_determinism test_checkpoint_restart $(call LOG,tsan)

test-tsan-hcbd: $(B)/run_tests_hcbd_tsan | $(B)/logs
	$(TSAN_ENV) ./$(B)/run_tests_hcbd_tsan --quick test_hc_determinism test_hc_sweep_blocks test_hc_checkpoint $(call LOG,tsan-hcbd)

# Fuzzing (not part of make test): libFuzzer on the examples' argument
# parser and on the checkpoint loaders, FUZZ_TIME seconds each; new
# inputs go to build/fuzz, crashes to build/fuzz/crash-*.  Inputs that
# found bugs are kept in tests/fuzz/regress_*; make test replays them and
# the seed corpora under ASan + UBSan without libFuzzer.
FUZZ_TIME ?= 120
FUZZ_SAN := -g -O1 -fsanitize=address,undefined -fno-sanitize-recover=all
fuzz: | $(B)
	mkdir -p $(B)/fuzz/args $(B)/fuzz/ckpt
	$(SAN_CC) $(FUZZ_SAN) -fsanitize=fuzzer $(MODELFLAG) -I. tests/fuzz/fuzz_args.c hcbd_impl.c -o $(B)/fuzz_args $(LDLIBS)
	$(SAN_CC) $(FUZZ_SAN) -fsanitize=fuzzer $(HCBDFLAG) $(FUZZ_CAP) -I. tests/fuzz/fuzz_checkpoint.c hcbd_impl.c -o $(B)/fuzz_ckpt $(LDLIBS)
	./$(B)/fuzz_args -close_fd_mask=2 -max_total_time=$(FUZZ_TIME) -artifact_prefix=$(B)/fuzz/ -dict=tests/fuzz/args.dict $(B)/fuzz/args tests/fuzz/corpus_args
	./$(B)/fuzz_ckpt -max_total_time=$(FUZZ_TIME) -artifact_prefix=$(B)/fuzz/ $(B)/fuzz/ckpt tests/fuzz/corpus_ckpt

$(B)/replay_args: tests/fuzz/fuzz_args.c tests/fuzz/replay.c examples/example_common.h $(B)/san_impl.o
	$(SAN_CC) $(SAN) -g -O1 $(MODELFLAG) -I. tests/fuzz/fuzz_args.c tests/fuzz/replay.c $(B)/san_impl.o -o $@ $(LDLIBS)

$(B)/replay_ckpt: tests/fuzz/fuzz_checkpoint.c tests/fuzz/replay.c $(B)/san_impl_hc.o
	$(SAN_CC) $(SAN) -g -O1 $(HCBDFLAG) $(FUZZ_CAP) -I. tests/fuzz/fuzz_checkpoint.c tests/fuzz/replay.c $(B)/san_impl_hc.o -o $@ $(LDLIBS)

test-fuzz-args: $(B)/replay_args | $(B)/logs
	./$(B)/replay_args $(wildcard tests/fuzz/corpus_args/* tests/fuzz/regress_args/*) $(call LOG,fuzz-args)

test-fuzz-ckpt: $(B)/replay_ckpt | $(B)/logs
	./$(B)/replay_ckpt $(wildcard tests/fuzz/corpus_ckpt/* tests/fuzz/regress_ckpt/*) $(call LOG,fuzz-ckpt)

# make install PREFIX=...: the header, the implementation compiled for
# this machine (CFLAGS, so -march=native unless set) as libhcbd.a (the
# Makefile's MODEL) and libhcbd_hc.a (HCBD), and a pkg-config file for each
# (hcbd, hcbd-hcbd) that carries the model define and the OpenMP flag: a
# program built with those flags reads the examples' checkpoints.  A
# program may instead define HCBD_IMPLEMENTATION in one file and skip the
# library (the same Cflags still apply).
PREFIX ?= /usr/local
VERSION := $(shell sed -n 's/^\#define HCBD_VERSION_MAJOR //p' hcbd.h).$(shell sed -n 's/^\#define HCBD_VERSION_MINOR //p' hcbd.h)
MODELNAME := $(patsubst -DHCBD_MODEL=%,%,$(MODELFLAG))
PCSUB = -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(VERSION)|' -e 's|@OMPFLAG@|$(OMPFLAG)|g'
install: $(B)/hcbd_impl.o $(B)/hcbd_impl_hc.o
	mkdir -p $(DESTDIR)$(PREFIX)/include $(DESTDIR)$(PREFIX)/lib/pkgconfig
	cp hcbd.h $(DESTDIR)$(PREFIX)/include/hcbd.h
	rm -f $(DESTDIR)$(PREFIX)/lib/libhcbd.a $(DESTDIR)$(PREFIX)/lib/libhcbd_hc.a
	ar rcs $(DESTDIR)$(PREFIX)/lib/libhcbd.a $(B)/hcbd_impl.o
	ar rcs $(DESTDIR)$(PREFIX)/lib/libhcbd_hc.a $(B)/hcbd_impl_hc.o
	sed $(PCSUB) -e 's|@NAME@|hcbd|' -e 's|@MODEL@|$(MODELNAME)|g' -e 's|@LIB@|hcbd|' hcbd.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/hcbd.pc
	sed $(PCSUB) -e 's|@NAME@|hcbd-hcbd|' -e 's|@MODEL@|HCBD_MODEL_HCBD|g' -e 's|@LIB@|hcbd_hc|' hcbd.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/hcbd-hcbd.pc

# Programs built against the installed copy alone (a fresh prefix; the
# flags from pkg-config when it is there): one that defines
# HCBD_IMPLEMENTATION itself, one that links the installed library (the
# objects are prerequisites here, so that the install's own make finds
# them built and never races the other parts for them).
test-install: $(B)/hcbd_impl.o $(B)/hcbd_impl_hc.o | $(B)/logs
	rm -rf $(B)/prefix
	$(MAKE) --no-print-directory install PREFIX=$(CURDIR)/$(B)/prefix $(call LOG,install-copy)
	cd $(B) && flags=$$(PKG_CONFIG_PATH=$(CURDIR)/$(B)/prefix/lib/pkgconfig pkg-config --cflags --libs hcbd 2>/dev/null || \
	    echo "-I$(CURDIR)/$(B)/prefix/include $(MODELFLAG) $(OMPFLAG) -L$(CURDIR)/$(B)/prefix/lib -lhcbd -lm"); \
	  $(CC) $(WARN) -x c ../tests/install_check.c $$flags -o install_check && \
	  $(CC) $(WARN) -DHCBD_CHECK_LIBRARY -x c ../tests/install_check.c $$flags -o install_check_lib && \
	  { ./install_check && ./install_check_lib && echo "2 passed, 0 failed"; } $(call LOG,install)

# The header alone, both halves, with gcc and clang as C99 (and C11 in the
# HCBD build, which holds all of the code) and as
# C++, with -Wshadow and -Wconversion (sign conversions excepted: every
# one is a non-negative int widened to size_t for index arithmetic, on
# purpose); then the examples and bench programs.  Code is generated for
# double C99 with each compiler: at -O2 (whose analyses give the deepest
# warnings) for the HCBD model, which holds all of the code, and at -O0 for
# the two others (gcc reports unused functions only when it generates
# code); the float, C11 and C++ variants are checked without code
# generation (their front-end warnings are the same; the float build is
# compiled in full for its own test part).
CONV := -Wshadow -Wconversion -Wno-sign-conversion
# the header's banners against its CONTENTS, and the programs the docs quote
test-docs: | $(B)/logs
	tests/docs.sh $(call LOG,docs)

# the Python package's pytest suite (tests/python), or a line saying why
# it was skipped; its counts join the total
test-python: | $(B)/logs
	PYTHON="$(PYTHON)" MAKE="$(MAKE)" tests/python.sh $(call LOG,python)

test-build: | $(B)/logs
	$(MAKE) --no-print-directory build-check $(call LOG,build)

build-check: | $(B)
	printf '#define HCBD_IMPLEMENTATION\n#include "../hcbd.h"\nint main(void){return 0;}\n' > $(B)/compile_test.c
	for m in GIBD WALLED HCBD; do for cc in gcc clang; do for std in c99 $$([ $$m = HCBD ] && echo c11); do \
	  gen=$$([ $$std = c99 ] && echo "-c -o $(B)/ct.o" || echo -fsyntax-only); \
	  opt=$$([ $$m = HCBD ] && echo -O2 || echo -O0); \
	  $$cc -std=$$std -Wall -Wextra -Wpedantic -Werror $(CONV) $$opt -DHCBD_MODEL=HCBD_MODEL_$$m $$gen $(B)/compile_test.c || exit 1; \
	  $$cc -std=$$std -Wall -Wextra -Wpedantic -Werror $(CONV) -O2 -fopenmp -DHCBD_REAL=float -DHCBD_MODEL=HCBD_MODEL_$$m -fsyntax-only $(B)/compile_test.c || exit 1; \
	done; done; \
	for cxx in g++ clang++; do \
	  $$cxx -x c++ -std=c++11 -Wall -Wextra -Werror -O2 -DHCBD_MODEL=HCBD_MODEL_$$m -fsyntax-only $(B)/compile_test.c || exit 1; done; done
	for cc in gcc clang; do $$cc $(WARN) $(MODELFLAG) -fsyntax-only $(filter-out examples/hcbd_%,$(wildcard examples/*.c)) $(filter-out bench/bench_hcbd.c bench/bench_wp_hcbd.c bench/wp_table1.c bench/wp_sph.c bench/carreau_refit.c bench/paired_series.c bench/roofline.c,$(wildcard bench/*.c)) || exit 1; \
	  $$cc $(WARN) $(HCBDFLAG) -fsyntax-only $(wildcard examples/hcbd_*.c bench/bench_hcbd.c bench/bench_wp_hcbd.c bench/wp_table1.c bench/wp_sph.c bench/carreau_refit.c bench/paired_series.c bench/stability.c bench/bench_parts.c bench/soak.c bench/roofline.c) || exit 1; done
	@echo "build: the header compiles as C99, C11 and C++11 with gcc and clang, GI-BD, walled and HCBD, double and float, $(CONV); examples and bench too"
	@echo "1 passed, 0 failed"

bench: $(B)/bench_speed $(B)/bench_hcbd
	./$(B)/bench_speed out=out/bench
	./$(B)/bench_hcbd out=out/bench

$(B)/bench_hcbd: bench/bench_hcbd.c $(B)/hcbd_impl_hc.o $(HEADERS) bench/bench_common.h
	$(CC) $(HC_CFLAGS) $< $(B)/hcbd_impl_hc.o -o $@ $(LDLIBS)

$(B)/bench_speed: bench/bench_speed.c $(B)/hcbd_impl.o $(HEADERS) bench/bench_common.h
	$(CC) $(ALL_CFLAGS) $< $(B)/hcbd_impl.o -o $@ $(LDLIBS)

# Work-precision: run time per unit of simulated time against the error
# from theory, over dt (and h), integrators, precision and noise; CSV and
# figure in out/bench (bench/wp.sh).
WP_BINS := $(B)/bench_wp $(B)/bench_wp_float $(B)/bench_wp_hcbd $(B)/bench_wp_hcbd_float
bench-wp: $(WP_BINS)
	bench/wp.sh out/bench

# Work-precision against LAMMPS fix brownian, the star fluid's T_conf and
# g(r) from dumped configurations by one estimator (bench/peers/wp.sh,
# ~40 min; skipped with a message without lmp).
bench-wp-peers: $(B)/wp_star $(B)/wp_estimate
	bench/peers/wp.sh

# The SPH fluid's viscosity against LAMMPS sph/taitwater/morris at equal
# error (bench/peers/wp_sph.sh, ~4 min; skipped with a message without lmp).
bench-wp-sph-peers: $(B)/wp_sph
	bench/peers/wp_sph.sh

# The fluctuating fluid's temperature and viscosity against LAMMPS
# sdpd/taitwater/isothermal at equal error (bench/peers/wp_sdpd.sh, ~17 min).
bench-wp-sdpd-peers: $(B)/wp_sph
	bench/peers/wp_sdpd.sh

$(B)/wp_star: bench/wp_star.c $(B)/hcbd_impl.o $(HEADERS) bench/bench_common.h
	$(CC) $(ALL_CFLAGS) $< $(B)/hcbd_impl.o -o $@ $(LDLIBS)

$(B)/wp_sph: bench/wp_sph.c $(B)/hcbd_impl_hc.o $(HEADERS) bench/bench_common.h tests/scenes.h
	$(CC) $(HC_CFLAGS) $< $(B)/hcbd_impl_hc.o -o $@ $(LDLIBS)

$(B)/wp_estimate: bench/wp_estimate.c | $(B)
	$(CC) $(WARN) $(CFLAGS) $< -o $@ $(LDLIBS)

# The time step of the 2018 polymer solution at Table I (~35 min, two
# threads): bench/results/wp_table1.csv and, with gnuplot, wp_table1.png.
bench-wp-table1: $(B)/wp_table1
	./$(B)/wp_table1 out=bench/results
	@if command -v gnuplot >/dev/null 2>&1; then cd bench/results && gnuplot ../wp_table1.gp; \
	 else echo "gnuplot not found: skipped bench/results/wp_table1.png (bench/wp_table1.gp draws it)"; fi

$(B)/wp_table1: bench/wp_table1.c $(B)/hcbd_impl_hc.o $(HEADERS) bench/bench_common.h
	$(CC) $(HC_CFLAGS) $< $(B)/hcbd_impl_hc.o -o $@ $(LDLIBS)

# What each departure from the 2018 paper does to eta at Table I, from
# paired runs (bench/table2_departures.sh, ~30 min on 2 cores).
bench-table2-departures: $(B)/hcbd_polymer $(B)/paired_series
	bench/table2_departures.sh

$(B)/paired_series: bench/paired_series.c $(B)/hcbd_impl_hc.o $(HEADERS)
	$(CC) $(HC_CFLAGS) $< $(B)/hcbd_impl_hc.o -o $@ $(LDLIBS)

# Refits of hcbd_polymer's flow curves: build/carreau_refit out/hcbd_polymer/flowcurve.csv
# the pass-by-pass roofline at Table II's composition (it includes the
# implementation to call the passes one at a time)
$(B)/roofline: bench/roofline.c $(HEADERS) bench/bench_common.h | $(B)
	$(CC) $(HC_CFLAGS) $< -o $@ $(LDLIBS)

$(B)/carreau_refit: bench/carreau_refit.c $(B)/hcbd_impl_hc.o $(HEADERS)
	$(CC) $(HC_CFLAGS) $< $(B)/hcbd_impl_hc.o -o $@ $(LDLIBS)

$(B)/bench_wp: bench/bench_wp.c $(B)/hcbd_impl.o $(HEADERS) bench/bench_common.h tests/scenes.h
	$(CC) $(ALL_CFLAGS) $< $(B)/hcbd_impl.o -o $@ $(LDLIBS)

$(B)/bench_wp_float: bench/bench_wp.c hcbd_impl.c $(HEADERS) bench/bench_common.h tests/scenes.h | $(B)
	$(CC) $(ALL_CFLAGS) -DHCBD_REAL=float $< hcbd_impl.c -o $@ $(LDLIBS)

$(B)/bench_wp_hcbd: bench/bench_wp_hcbd.c $(B)/hcbd_impl_hc.o $(HEADERS) bench/bench_common.h tests/scenes.h
	$(CC) $(HC_CFLAGS) $< $(B)/hcbd_impl_hc.o -o $@ $(LDLIBS)

$(B)/bench_wp_hcbd_float: bench/bench_wp_hcbd.c hcbd_impl.c $(HEADERS) bench/bench_common.h tests/scenes.h | $(B)
	$(CC) $(HC_CFLAGS) -DHCBD_REAL=float $< hcbd_impl.c -o $@ $(LDLIBS)

# Stability map: the largest dt before a guard or a 10 % temperature error,
# against hcbd_params_stability's limits (bench/stability.sh).
bench-stability: $(B)/bench_stability $(B)/bench_stability_hcbd
	bench/stability.sh out/bench

$(B)/bench_stability: bench/stability.c $(B)/hcbd_impl.o $(HEADERS) bench/bench_common.h
	$(CC) $(ALL_CFLAGS) $< $(B)/hcbd_impl.o -o $@ $(LDLIBS)

$(B)/bench_stability_hcbd: bench/stability.c $(B)/hcbd_impl_hc.o $(HEADERS) bench/bench_common.h
	$(CC) $(HC_CFLAGS) $< $(B)/hcbd_impl_hc.o -o $@ $(LDLIBS)

# Cost of each optional part of a scene, on and off, in all three builds.
bench-parts: $(B)/bench_parts $(B)/bench_parts_gibd $(B)/bench_parts_hcbd
	./$(B)/bench_parts_gibd out=out/bench
	./$(B)/bench_parts out=out/bench
	./$(B)/bench_parts_hcbd out=out/bench

$(B)/bench_parts: bench/bench_parts.c $(B)/hcbd_impl.o $(HEADERS) bench/bench_common.h
	$(CC) $(ALL_CFLAGS) $< $(B)/hcbd_impl.o -o $@ $(LDLIBS)

$(B)/bench_parts_gibd: bench/bench_parts.c hcbd_impl.c $(HEADERS) bench/bench_common.h | $(B)
	$(CC) $(WARN) $(FP) $(CFLAGS) $(OMPFLAG) -DHCBD_MODEL=HCBD_MODEL_GIBD $< hcbd_impl.c -o $@ $(LDLIBS)

$(B)/bench_parts_hcbd: bench/bench_parts.c $(B)/hcbd_impl_hc.o $(HEADERS) bench/bench_common.h
	$(CC) $(HC_CFLAGS) $< $(B)/hcbd_impl_hc.o -o $@ $(LDLIBS)

# Soak: each model for PSTEPS particle-steps (bench/soak.c); drift of the
# temperature, momentum and density against their block errors.
PSTEPS ?= 1e7
bench-soak: $(B)/bench_soak $(B)/bench_soak_hcbd
	./$(B)/bench_soak psteps=$(PSTEPS) out=out/bench; s=$$?; ./$(B)/bench_soak_hcbd psteps=$(PSTEPS) out=out/bench && exit $$s

$(B)/bench_soak: bench/soak.c $(B)/hcbd_impl.o $(HEADERS) bench/bench_common.h tests/scenes.h
	$(CC) $(ALL_CFLAGS) $< $(B)/hcbd_impl.o -o $@ $(LDLIBS)

$(B)/bench_soak_hcbd: bench/soak.c $(B)/hcbd_impl_hc.o $(HEADERS) bench/bench_common.h tests/scenes.h
	$(CC) $(HC_CFLAGS) $< $(B)/hcbd_impl_hc.o -o $@ $(LDLIBS)

# Side by side with LAMMPS (skipped with a message when lmp is missing).
bench-peers: $(B)/bench_speed $(B)/bench_hcbd
	bench/peers/run.sh

clean:
	rm -rf $(B) out
