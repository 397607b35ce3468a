#!/usr/bin/env bash
# bench/peers/wp.sh (make bench-wp-peers): run time against error, hcbd
# and LAMMPS side by side on the 2014 star fluid (f = 128, n# = 0.24, N =
# 1000, kT = xi = 1; GI-BD tau = 3.6e-3, xi' = 1), single thread.
#
#   LAMMPS fix brownian rng gaussian + pair table (Euler-Maruyama)
#   hcbd   BD, Leimkuhler-Matthews (the default) and Euler-Maruyama
#   hcbd   GI-BD, the exact sweep with Leimkuhler-Matthews (the default)
#          and the papers' Euler pairs with Euler-Maruyama
#
# at dt = 0.25 (Euler-Maruyama only), 0.5, 1, 2, 4, 8, 12, 16, 24, 32 x
# 1e-4 (DTS), interleaved dt by dt, to where each code stops.  Each run equilibrates EQ time units from the lattice, then
# runs TIME time units with a frame every 0.01; bench/wp_estimate computes
# T_conf and g(r) from the frames of both codes alike.  The reference is
# hcbd's BD with Leimkuhler-Matthews (flat in dt, issue 29) at dt = 0.25e-4
# over REF_TIME time units.  Cost: seconds per unit of simulated time, the
# loop time less LAMMPS's own "Output" (the dump) and hcbd_world_step's time
# alone.  Error: T_conf - T_conf(ref) and the rms distance of g(r) from the
# reference over r in [0.5, 3) (with g_floor, its statistical part).
#
# The headline: for each integrator the cheapest run whose |T_conf error|
# plus its error stays within 0.5 %, and LAMMPS's cost at the step where its
# first-order error (a line through 0 fitted to its points with dt <= 2e-4)
# reaches 0.5 %; their ratio is the speed-up at equal error.
#
# Knobs: N [1000] TIME [4] EQ [1] REF_TIME [12] SEED [1] DTS WP_OUT [out/wp_peers]
# LMP (else /tmp/peer/build/lmp, lmp on the PATH, build/lammps/lmp).
# Writes $WP_OUT/wp_peers.csv and, with gnuplot, wp_peers.png; ~12 minutes.
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
N=${N:-1000}
TIME=${TIME:-4}
EQ=${EQ:-1}
REF_TIME=${REF_TIME:-12}
SEED=${SEED:-1}
# to the stability limits: a run that stops (a guard, lost atoms) marks the end
DTS=${DTS:-"2.5e-5 5e-5 1e-4 2e-4 4e-4 8e-4 1.2e-3 1.6e-3 2.4e-3 3.2e-3"}
OUT=${WP_OUT:-out/wp_peers}
case "$OUT" in /*) ;; *) OUT="$root/$OUT" ;; esac
export OMP_NUM_THREADS=1
. "$here/lib.sh"
find_lmp brownian
if [ -z "$LMP_BIN" ]; then
    echo "bench/peers/wp.sh: no lmp with fix brownian (make lammps, or ../shared/PEERS.md); skipped"
    exit 0
fi
(cd "$root" && make -s build/wp_star build/wp_estimate) || { echo "wp.sh: build failed"; exit 1; }
mkdir -p "$OUT"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/hcbd_wp.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
awk -v f=128 -v sigma=1 -v eps=1 -v n=5000 -v rlo=0.01 -v rhi=2.5 -f "$here/star_table.awk" >"$tmp/star.table"
machine_names
echo "wp.sh: $LMP_BIN ($lmp_version), $cpu ($avx), N = $N, $TIME time units per point"
t_start=$(date +%s)

est() { "$root/build/wp_estimate" "$1" "${@:2}"; }

# reference: hcbd BD, LM, dt = 0.25e-4
echo "wp.sh: reference (hcbd BD LM, dt = 2.5e-5, $REF_TIME time units)"
"$root/build/wp_star" dt=2.5e-5 N="$N" time="$REF_TIME" eq="$EQ" dyn=bd seed=$((SEED + 100)) \
    out="$tmp/ref.xyz" >/dev/null || exit 1
ref=$(est "$tmp/ref.xyz" g="$tmp/ref.g") || exit 1
rm -f "$tmp/ref.xyz"
Tref=$(echo "$ref" | sed 's/.*T_conf=\([^ ]*\).*/\1/')
Tref_err=$(echo "$ref" | sed 's/.*T_conf_err=\([^ ]*\).*/\1/')
echo "wp.sh: reference T_conf = $Tref +- $Tref_err"

csv="$OUT/wp_peers.csv"
echo "code,integrator,dt,seconds_per_time_unit,T_conf,T_conf_err,T_err,T_err_err,g_err,g_floor,cpu" >"$csv"
add() { # code integrator dt cost estimate-line
    local T Te ge gf
    T=$(echo "$5" | sed 's/.*T_conf=\([^ ]*\).*/\1/')
    Te=$(echo "$5" | sed 's/.*T_conf_err=\([^ ]*\).*/\1/')
    ge=$(echo "$5" | sed 's/.*g_err=\([^ ]*\).*/\1/')
    gf=$(echo "$5" | sed 's/.*g_floor=\([^ ]*\).*/\1/')
    awk -v c="$1" -v i="$2" -v dt="$3" -v s="$4" -v T="$T" -v Te="$Te" -v R="$Tref" -v Re="$Tref_err" \
        -v ge="$ge" -v gf="$gf" -v cpu="$cpu ($avx)" \
        'BEGIN {printf "%s,%s,%g,%.6g,%.6f,%.6f,%.6f,%.6f,%s,%s,\"%s\"\n", c, i, dt, s, T, Te, T - R,
                sqrt(Te * Te + Re * Re), ge, gf, cpu}' >>"$csv"
    printf '%-6s %-14s dt %-8s %9.4g s/time  T_conf - ref %+.4f +- %.4f  g_err %s (floor %s)\n' "$1" "$2" "$3" "$4" \
        "$(awk -v a="$T" -v b="$Tref" 'BEGIN {print a - b}')" "$Te" "$ge" "$gf"
}

for dt in $DTS; do
    every=$(awk -v dt="$dt" 'BEGIN {printf "%d", 0.01 / dt + 0.5}')
    steps=$(awk -v dt="$dt" -v t="$TIME" -v e="$every" 'BEGIN {printf "%d", e * int(t / (e * dt) + 0.5)}')
    eqs=$(awk -v dt="$dt" -v t="$EQ" 'BEGIN {printf "%d", t / dt + 0.5}')
    # LAMMPS
    if (cd "$tmp" && "$LMP_BIN" -nocite -screen none -log "$tmp/log" -in "$here/in.star_wp" -var N "$N" \
            -var dt "$dt" -var eqsteps "$eqs" -var steps "$steps" -var every "$every" -var seed "$SEED" \
            -var rng gaussian -var table "$tmp/star.table" -var dump "$tmp/l.dump"); then
        cost=$(lmp_cost "$tmp/log" "$dt" "$steps")
        add lammps brownian_em "$dt" "$cost" "$(est "$tmp/l.dump" ref="$tmp/ref.g")"
    else
        echo "wp.sh: lmp failed at dt = $dt"; tail -n 5 "$tmp/log"
    fi
    rm -f "$tmp/l.dump"
    # hcbd
    for cfg in "bd_lm:dyn=bd brownian=lm" "bd_em:dyn=bd brownian=euler" \
               "gibd_exact_lm:dyn=gibd pair=exact brownian=lm" "gibd_euler_em:dyn=gibd pair=euler brownian=euler"; do
        name=${cfg%%:*}
        case "$name:$dt" in *_lm:2.5e-5) continue ;; esac
        # shellcheck disable=SC2086
        r=$("$root/build/wp_star" dt="$dt" N="$N" time="$TIME" eq="$EQ" every=0.01 seed="$SEED" ${cfg#*:} \
            out="$tmp/h.xyz") || { echo "wp.sh: wp_star failed ($name, dt = $dt)"; continue; }
        cost=$(echo "$r" | sed 's/.*seconds_per_time_unit=\([^ ]*\).*/\1/')
        e=$(est "$tmp/h.xyz" ref="$tmp/ref.g")
        # the estimator against hcbd's own T_conf of the same frames
        api=$(echo "$r" | sed 's/.*T_conf_api=\([^ ]*\).*/\1/')
        all=$(echo "$e" | sed 's/.*T_conf_all=\([^ ]*\).*/\1/')
        awk -v a="$api" -v b="$all" 'BEGIN {exit !(a - b < 1e-6 * a && b - a < 1e-6 * a)}' ||
            echo "wp.sh: WARNING: wp_estimate reads T_conf $all where hcbd_world_config_temperature gives $api ($name, dt = $dt)"
        add hcbd "$name" "$dt" "$cost" "$e"
        rm -f "$tmp/h.xyz"
    done
done

# the headline: cost at equal error (T_conf within 0.5 %)
echo
awk -F, 'NR > 1 {
    k = $1 "/" $2; if (!(k in seen)) { seen[k] = 1; ord[++n] = k }
    if ($1 == "lammps" && $3 + 0 <= 2e-4) { sxy += $3 * $7; sxx += $3 * $3; c1 = $4 * $3 }
    if ($1 == "lammps" && $3 + 0 <= 2e-4 && ($3 + 0 < dtl || dtl == 0)) { dtl = $3; cl = $4 }
    e = ($7 < 0 ? -$7 : $7) + $8
    if (e <= 0.005 && (!(k in best) || $4 + 0 < best[k])) { best[k] = $4; bdt[k] = $3; berr[k] = $7 }
}
END {
    slope = sxx > 0 ? sxy / sxx : 0
    if (slope > 0) { dts = 0.005 / slope; lcost = cl * dtl / dts }
    printf "LAMMPS fix brownian: T_conf error %.3g per unit dt (fit, dt <= 2e-4): 0.5 %% at dt = %.3g, %.4g s per time unit\n", slope, dts, lcost
    for (q = 1; q <= n; ++q) {
        k = ord[q]
        if (k in best) printf "%-22s cheapest within 0.5 %%: dt = %g, %.4g s per time unit (error %+.4f)%s\n", k, bdt[k], best[k], berr[k],
            (slope > 0 && k !~ /^lammps/) ? sprintf("; LAMMPS / this at equal error: %.1f", lcost / best[k]) : ""
        else printf "%-22s no point within 0.5 %%\n", k
    }
}' "$csv" | tee "$OUT/wp_peers_headline.txt"
# one file per series for the figure (points in order of dt)
for k in lammps,brownian_em hcbd,bd_em hcbd,bd_lm hcbd,gibd_euler_em hcbd,gibd_exact_lm; do
    awk -F, -v c="${k%%,*}" -v i="${k#*,}" 'NR > 1 && $1 == c && $2 == i {print $3, $4, ($7 < 0 ? -$7 : $7), $8, $9, $10}' \
        "$csv" | sort -g >"$OUT/wp_${k%%,*}_${k#*,}.dat"
done
if command -v gnuplot >/dev/null 2>&1; then
    (cd "$OUT" && gnuplot "$here/wp.gp") && echo "wp.sh: $OUT/wp_peers.png"
else
    echo "wp.sh: gnuplot not found: no figure ($here/wp.gp draws it from wp_peers.csv)"
fi
echo "wp.sh: wrote $OUT/wp_peers.csv; $(( $(date +%s) - t_start )) s"
