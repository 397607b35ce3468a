#!/bin/sh
# Mutation check: each injected error of mutants.txt (a single coefficient
# 10 % off) must make the suite fail.  Not part of make test (it builds
# the suite once per mutant): make mutants, optionally NAMES="a b".
# Prints one line per mutant: caught by the first failing test, or MISSED.
# The golden hashes are left out (they catch any change of bits, and the
# question here is whether a physics test does), and so is the test that
# runs the built example, which a mutant's copy does not have.
set -u
top=$(cd "$(dirname "$0")/../.." && pwd)
work=${MUT_DIR:-/tmp/hcbd_mutants}
cc=${CC:-cc}
flags="-std=c99 -ffp-contract=off -O2 -march=native -fopenmp"
missed=0
mkdir -p "$work"
grep -v '^#' "$top/tests/mutants/mutants.txt" | while IFS='	' read -r name build old new; do
    [ -n "$name" ] || continue
    if [ -n "${NAMES:-}" ] && ! echo " $NAMES " | grep -q " $name "; then continue; fi
    d="$work/$name"
    rm -rf "$d"; mkdir -p "$d"
    cp -r "$top/tests" "$top/hcbd_impl.c" "$d/"
    if ! python3 - "$top/hcbd.h" "$d/hcbd.h" "$old" "$new" <<'PY'
import sys
src, dst, old, new = sys.argv[1:5]
old = old.replace('\\n', '\n'); new = new.replace('\\n', '\n')
s = open(src).read()
if s.count(old) != 1:
    sys.exit("pattern found %d times" % s.count(old))
open(dst, 'w').write(s.replace(old, new))
PY
    then echo "$name: BAD PATTERN"; continue; fi
    model=WALLED; filter=""
    [ "$build" = hcbd ] && { model=HCBD; filter=test_hc_; }
    if ! (cd "$d" && $cc $flags -DHCBD_MODEL=HCBD_MODEL_$model tests/test_*.c tests/main.c hcbd_impl.c -o run -lm) 2>"$d/build.log"; then
        echo "$name: does not build"; continue
    fi
    (cd "$d" && HCBD_TEST_STOP=1 HCBD_TEST_SKIP=golden,from_example ./run $filter > out.log 2>&1)
    first=$(awk '/^test_/{n=$1} /^  FAILED/{print n; exit}' "$d/out.log")
    if [ -n "$first" ]; then echo "$name: caught by $first"; else echo "$name: MISSED"; fi
done
