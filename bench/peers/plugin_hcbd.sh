#!/usr/bin/env bash
# bench/peers/plugin_hcbd.sh: the cost of fix hcbd (the 2018 model on
# LAMMPS's engine, lammps/fix_hcbd.cpp) per blob-step, against hcbd's own
# world (lammps/hc_ref.c, built here as make builds the library: -O2
# -march=native -fopenmp) at the same parameters from the same atoms:
# Table I in reduced units (sigma, kT, 1 us; the fluid's step 12.5 us in 8
# sub-steps of a 100 us polymer step, preset=paper's), without fluid
# fluctuations, the fluid pairs of PAIRS (default "euler exact": the paper's
# Euler pairs, hcbd's exact sweep; fix hcbd's exact sweep on processors
# 1 * *), N fluid blobs and N polymers in a cube (lammps/in.hcbd_compare's
# lattice and random start), on the ranks / threads of RANKS (default "1 2").
# Interleaved rounds (ROUNDS, default 3), medians; LAMMPS's figure is its
# "Loop time", hcbd's the wall-clock time of its steps, both over the
# fluid steps and all blobs.  SIZES: the fluid lattice's edges (default
# "20": 8000 + 8000; "20 40" adds 64000 + 64000).  Prints a markdown table.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
B=${HCBD_LAMMPS_DIR:-$root/build/lammps}
ROUNDS=${ROUNDS:-3}
RANKS=${RANKS:-1 2}
SIZES=${SIZES:-20}
PAIRS=${PAIRS:-euler exact}
STEPS=${STEPS:-80}
[ -x "$B/lmp" ] && [ -f "$B/plugin/hcbdplugin.so" ] || { echo "plugin_hcbd.sh: make lammps first"; exit 1; }
MPI=${HCBD_MPIRUN:-mpirun --allow-run-as-root --oversubscribe}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
cc -std=c99 -O2 -march=native -fopenmp -ffp-contract=off -fno-math-errno -DHCBD_MODEL=HCBD_MODEL_HCBD -I"$root" \
    -o "$t/hc_ref" "$root/lammps/hc_ref.c" -lm
# Table I, reduced (hcbd_polymer preset=paper prints the same)
P="rho 7.54476e+08 nbar 0.238738 eta 3.0179e+07 P0 3923.28 h 2 kT 1 xi 6.03581e+08 sigma 1 rc 2.5 alpha 500"
P="$P tau_lambda 1e+06 p 300000 n_max 2387.32 chi 0.5 dt 12.5 substeps 8 fluct no jitter 0.3 warm 8 stress no pairs 64"
lvars() { local out=""; set -- $P; while [ $# -gt 1 ]; do out="$out -var $1 $2"; shift 2; done; echo "$out"; }
hvars() { local out=""; set -- $P; while [ $# -gt 1 ]; do case $1 in jitter|warm|stress|pairs) ;; *) out="$out $1=$2" ;; esac; shift 2; done; echo "$out"; }
loop_ns() { awk '/^Loop time of/ { s = $4; st = $9; n = $12 } END { printf "%.1f\n", s / (st * n) * 1e9 }'; }
median() { sort -g | awk 'NF { a[++n] = $1 } END { print a[int((n + 1) / 2)] }'; }
for ns in $SIZES; do
    N=$((ns * ns * ns))
    # the start: LAMMPS's atoms after one polymer step off the lattice
    # shellcheck disable=SC2046
    "$B/lmp" -in "$root/lammps/in.hcbd_compare" -var plugin "$B/plugin/hcbdplugin.so" $(lvars) -var ns "$ns" \
        -var npoly "$N" -var steps 0 -var start "$t/start$ns.txt" -log none -screen none
    for r in $(seq 1 "$ROUNDS"); do
        echo "N = $N + $N, round $r/$ROUNDS" >&2
        for pair in $PAIRS; do
            for np in $RANKS; do
                # shellcheck disable=SC2046
                $MPI -np "$np" "$B/lmp" -in "$root/lammps/in.hcbd_compare" -var plugin "$B/plugin/hcbdplugin.so" \
                    $(lvars) -var ns "$ns" -var npoly "$N" -var steps "$STEPS" -var pair "$pair" -var procs "1 * *" \
                    -log none | loop_ns >> "$t/lmp$ns-$pair-$np"
                # shellcheck disable=SC2046
                "$t/hc_ref" "$t/start$ns.txt" /dev/null $((STEPS / 8)) nf=$N $(hvars) pair="$pair" threads="$np" \
                    timing=1 2>&1 >/dev/null | awk -v n=$((2 * N)) -v s="$STEPS" '/^seconds/ { printf "%.1f\n", $2 / (s * n) * 1e9 }' \
                    >> "$t/hcbd$ns-$pair-$np"
            done
        done
    done
done
lscpu | awk -F: '/^Model name/ { gsub(/^ +/, "", $2); print "CPU: " $2 }'
printf '| ns per blob-step (fluid steps, fluid + polymer blobs) |'
for np in $RANKS; do printf ' %s rank(s) / thread(s) |' "$np"; done
printf '\n|---|'; for _ in $RANKS; do printf -- '---:|'; done; printf '\n'
for ns in $SIZES; do
    N=$((ns * ns * ns))
    for pair in $PAIRS; do
        printf '| fix hcbd, %d + %d, pair %s |' "$N" "$N" "$pair"
        for np in $RANKS; do printf ' %s |' "$(median < "$t/lmp$ns-$pair-$np")"; done; printf '\n'
        printf '| hcbd world, %d + %d, pair %s |' "$N" "$N" "$pair"
        for np in $RANKS; do printf ' %s |' "$(median < "$t/hcbd$ns-$pair-$np")"; done; printf '\n'
    done
done
