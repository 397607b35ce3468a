#!/usr/bin/env bash
# bench/peers/plugin.sh: the cost of fix gibd (GI-BD on LAMMPS's engine, the
# plugin of lammps/) per particle-step, with its exact pair sweep (the
# default) and with the papers' Euler pair step, beside LAMMPS's own fix
# brownian (classical BD) in the same LAMMPS and hcbd's GI-BD with the same
# pair steps, on the 2014 star scene (N = 32768, lattice start, dt = 1e-4),
# all with uniform noise (fix brownian's default) and Euler-Maruyama
# Brownian steps (fix brownian's), on the ranks / threads of RANKS (default
# "1 2"; "1 2 4 8 16" for strong scaling on a bigger machine).
# Interleaved rounds (ROUNDS, default 3), medians; LAMMPS's figure is its
# "Loop time" over steps and atoms.  Needs make lammps and build/bench_speed
# (BENCH_SPEED: another build of it); HCBD_MPIRUN replaces
# "mpirun --allow-run-as-root --oversubscribe".  Prints a markdown table
# (then the speed-up of each row against its first column) and the ratios.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
B=${HCBD_LAMMPS_DIR:-$root/build/lammps}
ROUNDS=${ROUNDS:-3}
RANKS=${RANKS:-1 2}
BS=${BENCH_SPEED:-$root/build/bench_speed}
N=32768
[ -x "$B/lmp" ] && [ -f "$B/plugin/gibdplugin.so" ] || { echo "plugin.sh: make lammps first"; exit 1; }
[ -x "$BS" ] || { echo "plugin.sh: make build/bench_speed first"; exit 1; }
MPI=${HCBD_MPIRUN:-mpirun --allow-run-as-root --oversubscribe}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT

loop_ns() { # LAMMPS output on stdin -> ns per particle-step of its last run
    awk '/^Loop time of/ { s = $4; st = $9; n = $12 } END { printf "%.1f\n", s / (st * n) * 1e9 }'
}
median() { sort -g | awk 'NF { a[++n] = $1 } END { print a[int((n + 1) / 2)] }'; }

for r in $(seq 1 "$ROUNDS"); do
    echo "round $r/$ROUNDS" >&2
    for np in $RANKS; do
        for sw in exact euler; do
            $MPI -np $np "$B/lmp" -in "$root/lammps/in.gibd_star" -var plugin "$B/plugin/gibdplugin.so" \
                -var N $N -var steps 300 -var noise uniform -var sweep $sw -var brownian euler -var rmin 0 \
                -log none | loop_ns >> "$t/gibd_$sw$np"
        done
        $MPI -np $np "$B/lmp" -in "$root/bench/peers/in.star_bd" -var N $N -var steps 1000 -var eqsteps 100 \
            -var table "$B/star.table" -log none | loop_ns >> "$t/bd$np"
    done
    for pr in shardlow euler; do
        (cd "$t" && "$BS" Nmin=$N Nmax=$N threads="${RANKS// /,}" scenes=gibd pair=$pr brownian=euler \
            noise=uniform out="$t" > "$t/speed_$pr.txt")
        [ "$(awk '/^gibd/ { print $NF }' "$t/speed_$pr.txt" | sort -u | wc -l)" = 1 ] ||
            echo "plugin.sh: bench_speed: the thread counts differ in their bits" >&2
        for th in $RANKS; do
            awk -F, -v th=$th 'NR == 1 { for (i = 1; i <= NF; ++i) h[$i] = i; next }
                $(h["scene"]) == "gibd" && $(h["N"]) == 32768 && $(h["threads"]) == th { print $(h["ns_per_particle_step"]) }' \
                "$t/speed_uniform.csv" >> "$t/hcbd_$pr$th"
        done
    done
done
first=${RANKS%% *}
row() { # LABEL KEY: the medians over RANKS
    local line="| $1 |" np
    for np in $RANKS; do line="$line $(median < "$t/$2$np") |"; done
    echo "$line"
}
head="| ns per particle-step, medians of $ROUNDS rounds; ranks / threads: |"
sep="|---|"
for np in $RANKS; do head="$head $np |"; sep="$sep---:|"; done
echo "$head"
echo "$sep"
row "fix gibd + pair_style star (GI-BD, exact pair sweep, the default)" gibd_exact
row "fix gibd pair euler (the papers' Euler pair step)" gibd_euler
row "LAMMPS fix brownian + pair_style table (classical BD)" bd
row "hcbd GI-BD, exact sweep (bench_speed)" hcbd_shardlow
row "hcbd GI-BD, Euler pairs (bench_speed pair=euler)" hcbd_euler
echo "speed-up against $first rank / thread:"
for k in gibd_exact gibd_euler bd hcbd_shardlow hcbd_euler; do
    b=$(median < "$t/$k$first")
    line="  $k:"
    for np in $RANKS; do
        line="$line $(awk -v a="$b" -v x="$(median < "$t/$k$np")" 'BEGIN { printf "%.2f", a / x }')"
    done
    echo "$line"
done
x1=$(median < "$t/gibd_exact$first")
awk -v x1="$x1" -v e1="$(median < "$t/gibd_euler$first")" -v b1="$(median < "$t/bd$first")" \
    -v h1="$(median < "$t/hcbd_shardlow$first")" -v np="$first" 'BEGIN {
    printf "fix gibd exact / Euler %.2f, / fix brownian %.2f, / hcbd %.2f (%s rank)\n",
        x1 / e1, x1 / b1, x1 / h1, np }'
