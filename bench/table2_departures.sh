#!/usr/bin/env bash
# bench/table2_departures.sh (make bench-table2-departures): what each of
# hcbd_polymer's departures from the 2018 paper does to the Lees-Edwards
# viscosity at Table I (issue 41), from paired runs: preset=paper with the
# library's own schemes (coupling=shepard pair=shardlow, the base the stored
# rows in bench/results/table2_departures were measured from; the preset
# itself now takes the paper's) and one with a single change, same seed,
# same start-up (STARTUP tau_lambda) and window (BLOCKS of one tau_lambda),
# compared half block by half block (build/paired_series: the runs share
# their polymer and pair noise, so the difference is far less noisy than
# either viscosity).
#   coupling=raw   the paper's w(r_ai)/n_i weights instead of Shepard's
#   pair=euler     the paper's explicit fluid pairs instead of the sweep
#   substeps=16    the fluid step halved (6.25 us; the polymer step stays)
# Knobs: C [2.5,5] WI [1] STARTUP [10] BLOCKS [12] SEED [1] JOBS [2]
# OUT [out/table2_departures]; writes $OUT/departures.csv.
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
C=${C:-2.5,5}
WI=${WI:-1}
STARTUP=${STARTUP:-10}
BLOCKS=${BLOCKS:-12}
SEED=${SEED:-1}
JOBS=${JOBS:-2}
OUT=${OUT:-out/table2_departures}
case "$OUT" in /*) ;; *) OUT="$root/$OUT" ;; esac
export OMP_NUM_THREADS=1
(cd "$root" && make -s build/hcbd_polymer build/paired_series) || { echo "table2_departures.sh: build failed"; exit 1; }
mkdir -p "$OUT"
P="$root/build/hcbd_polymer"
variants="base coupling=raw pair=euler substeps=16"
t_start=$(date +%s)
run() { # C Wi variant
    local dir="$OUT/C$1_Wi$2_${3/=/_}" extra=""
    [ "$3" = base ] || extra=$3
    # shellcheck disable=SC2086
    "$P" preset=paper coupling=shepard pair=shardlow C="$1" gdot="$2" startup_min="$STARTUP" startup_max="$STARTUP" blocks="$BLOCKS" \
        measure_strain=0.001 rp_steps=30 eq_steps=1 threads=1 seed="$SEED" $extra out="$dir" >"$dir.log" 2>&1 ||
        echo "table2_departures.sh: run failed: C=$1 Wi=$2 $3 (see $dir.log)"
}
n=0
for c in ${C//,/ }; do
    for w in ${WI//,/ }; do
        for v in $variants; do
            run "$c" "$w" "$v" &
            n=$((n + 1))
            [ $((n % JOBS)) -eq 0 ] && wait
        done
    done
done
wait
csv="$OUT/departures.csv"
echo "C,Wi,change,eta_base_mPas,eta_base_err,eta_changed_mPas,eta_changed_err,rel_diff,rel_diff_err" >"$csv"
for c in ${C//,/ }; do
    for w in ${WI//,/ }; do
        a="$OUT/C${c}_Wi${w}_base/startup_C$c.csv"
        for v in $variants; do
            [ "$v" = base ] && continue
            b="$OUT/C${c}_Wi${w}_${v/=/_}/startup_C$c.csv"
            r=$("$root/build/paired_series" "$a" "$b" "$w") || continue
            echo "C = $c, Wi = $w, $v: $r"
            echo "$r" | awk -v c="$c" -v w="$w" -v v="$v" '{
                for (k = 1; k <= NF; ++k) { split($k, p, "="); x[p[1]] = p[2] }
                printf "%s,%s,%s,%s,%s,%s,%s,%s,%s\n", c, w, v, x["a"], x["a_err"], x["b"], x["b_err"],
                       x["rel_diff"], x["rel_diff_err"] }' >>"$csv"
        done
    done
done
echo "table2_departures.sh: wrote $csv; $(( $(date +%s) - t_start )) s"
