#!/usr/bin/env bash
# bench/peers/plugin.sh: the cost of fix gibd (GI-BD on LAMMPS's engine, the
# plugin of lammps/) per particle-step, with its exact pair sweep (the
# default) and with the papers' Euler pair step, beside LAMMPS's own fix
# brownian (classical BD) in the same LAMMPS and hcbd's GI-BD with the same
# pair steps, on the 2014 star scene (N = 32768, lattice start, dt = 1e-4),
# all with uniform noise (fix brownian's default) and Euler-Maruyama
# Brownian steps (fix brownian's), 1 and 2 ranks / threads.
# Interleaved rounds (ROUNDS, default 3), medians; LAMMPS's figure is its
# "Loop time" over steps and atoms.  Needs make lammps and build/bench_speed.
# Prints a markdown table and the ratios.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
B=${HCBD_LAMMPS_DIR:-$root/build/lammps}
ROUNDS=${ROUNDS:-3}
N=32768
[ -x "$B/lmp" ] && [ -f "$B/plugin/gibdplugin.so" ] || { echo "plugin.sh: make lammps first"; exit 1; }
[ -x "$root/build/bench_speed" ] || { echo "plugin.sh: make build/bench_speed first"; exit 1; }
MPI="mpirun --allow-run-as-root --oversubscribe"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT

loop_ns() { # LAMMPS output on stdin -> ns per particle-step of its last run
    awk '/^Loop time of/ { s = $4; st = $9; n = $12 } END { printf "%.1f\n", s / (st * n) * 1e9 }'
}
median() { sort -g | awk 'NF { a[++n] = $1 } END { print a[int((n + 1) / 2)] }'; }

for r in $(seq 1 "$ROUNDS"); do
    echo "round $r/$ROUNDS" >&2
    for np in 1 2; do
        for sw in exact euler; do
            $MPI -np $np "$B/lmp" -in "$root/lammps/in.gibd_star" -var plugin "$B/plugin/gibdplugin.so" \
                -var N $N -var steps 300 -var noise uniform -var sweep $sw -var brownian euler -var rmin 0 \
                -log none | loop_ns >> "$t/gibd_$sw$np"
        done
        $MPI -np $np "$B/lmp" -in "$root/bench/peers/in.star_bd" -var N $N -var steps 1000 -var eqsteps 100 \
            -var table "$B/star.table" -log none | loop_ns >> "$t/bd$np"
    done
    for pr in shardlow euler; do
        (cd "$t" && "$root/build/bench_speed" Nmax=$N threads=2 scenes=gibd pair=$pr brownian=euler noise=uniform \
            out="$t" > /dev/null)
        for th in 1 2; do
            awk -F, -v th=$th 'NR == 1 { for (i = 1; i <= NF; ++i) h[$i] = i; next }
                $(h["scene"]) == "gibd" && $(h["N"]) == 32768 && $(h["threads"]) == th { print $(h["ns_per_particle_step"]) }' \
                "$t/speed_uniform.csv" >> "$t/hcbd_$pr$th"
        done
    done
done
for k in gibd_exact1 gibd_exact2 gibd_euler1 gibd_euler2 bd1 bd2 hcbd_shardlow1 hcbd_shardlow2 hcbd_euler1 hcbd_euler2; do
    eval "$k=$(median < "$t/$k")"
done
echo "| ns per particle-step, medians of $ROUNDS rounds | 1 rank / thread | 2 ranks / threads |"
echo "|---|---:|---:|"
echo "| fix gibd + pair_style star (GI-BD, exact pair sweep, the default) | $gibd_exact1 | $gibd_exact2 |"
echo "| fix gibd pair euler (the papers' Euler pair step) | $gibd_euler1 | $gibd_euler2 |"
echo "| LAMMPS fix brownian + pair_style table (classical BD) | $bd1 | $bd2 |"
echo "| hcbd GI-BD, exact sweep (bench_speed) | $hcbd_shardlow1 | $hcbd_shardlow2 |"
echo "| hcbd GI-BD, Euler pairs (bench_speed pair=euler) | $hcbd_euler1 | $hcbd_euler2 |"
awk -v x1="$gibd_exact1" -v x2="$gibd_exact2" -v e1="$gibd_euler1" -v b1="$bd1" -v h1="$hcbd_shardlow1" 'BEGIN {
    printf "fix gibd exact / Euler %.2f, / fix brownian %.2f, / hcbd %.2f (1 rank); 1 -> 2 ranks %.2fx\n",
        x1 / e1, x1 / b1, x1 / h1, x1 / x2 }'
