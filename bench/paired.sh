#!/bin/sh
# Paired timing of two builds of one bench program: the working tree (A)
# against a git revision (B, built in a worktree under build/paired/).
# They run in turn, A B A B ..., ROUNDS times each, so that a machine whose
# speed drifts during the call slows both alike; for every row of the
# program's table (scene, size, threads) it prints the median over rounds
# of the ratio A/B of ns/particle-step, taken round by round, with its
# range, and whether the two builds end in the same state checksum (the
# same bits).  Quote the median with the command and the CPU.
#
# usage: bench/paired.sh [-n ROUNDS] REV PROGRAM [ARGS...]
#   PROGRAM  bench_speed or bench_hcbd (any bench printing their table:
#            ns/particle-step in column 5, the checksum last)
#   e.g.     bench/paired.sh -n 7 251f3af bench_hcbd scenes=fluid,table1 Nmax=8000 threads=1
set -eu
rounds=5
if [ "${1:-}" = "-n" ]; then rounds=$2; shift 2; fi
[ $# -ge 2 ] || { sed -n '2,17p' "$0"; exit 2; }
rev=$1; prog=$2; shift 2
top=$(git rev-parse --show-toplevel)
cd "$top"
sha=$(git rev-parse --short "$rev")
wt=build/paired/$sha
if [ ! -d "$wt" ]; then
    mkdir -p build/paired
    git worktree add -f --detach "$wt" "$sha" >/dev/null 2>&1 || { echo "paired: no worktree of $rev"; exit 1; }
fi
make -s "build/$prog" >/dev/null
(cd "$wt" && make -s "build/$prog" >/dev/null) || { echo "paired: $rev does not build $prog"; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
i=1
while [ "$i" -le "$rounds" ]; do
    "./build/$prog" "$@" out="$tmp/a" > "$tmp/a.$i" 2>&1
    "./$wt/build/$prog" "$@" out="$tmp/b" > "$tmp/b.$i" 2>&1
    i=$((i + 1))
done
echo "paired: $prog $*, $rounds rounds, A = working tree ($(git rev-parse --short HEAD)$(git diff --quiet HEAD || echo '+changes')), B = $sha"
echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'), $(grep -q avx512f /proc/cpuinfo && echo AVX-512 || echo 'AVX2 only')"
# rows: lines whose 5th field is a number; key = fields 1-4
printf "%-28s %9s %9s %9s %9s  %s\n" "scene/N/-/threads" "A/B" "min" "max" "B ns" "bits"
for f in "$tmp"/a.* "$tmp"/b.*; do
    awk -v f="$(basename "$f")" '$5 ~ /^[0-9.]+$/ { print f, $1 "/" $2 "/" $3 "/" $4, $5, $NF }' "$f"
done | awk '
{ split($1, s, "."); side = s[1]; r = s[2]; t[side, r, $2] = $3; sum[side, $2] = $4; keys[$2] = 1 }
END {
    for (k in keys) {
        n = 0
        for (r = 1; (("a", r, k) in t); ++r)
            if ((("b", r, k) in t) && t["b", r, k] > 0) { q[++n] = t["a", r, k] / t["b", r, k]; b[n] = t["b", r, k] }
        if (n == 0) continue
        for (x = 1; x <= n; ++x) for (y = x + 1; y <= n; ++y) {
            if (q[y] < q[x]) { z = q[x]; q[x] = q[y]; q[y] = z }
            if (b[y] < b[x]) { z = b[x]; b[x] = b[y]; b[y] = z }
        }
        med = n % 2 ? q[(n + 1) / 2] : (q[n / 2] + q[n / 2 + 1]) / 2
        mb = n % 2 ? b[(n + 1) / 2] : (b[n / 2] + b[n / 2 + 1]) / 2
        printf "%-28s %9.3f %9.3f %9.3f %9.1f  %s\n", k, med, q[1], q[n], mb,
               sum["a", k] == sum["b", k] ? "same" : "DIFFER"
    }
}' | sort
