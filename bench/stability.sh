#!/usr/bin/env bash
# bench/stability.sh: the stability map of both models (bench/stability.c),
# then, with gnuplot, the figure of the measured failing dt against the
# limit hcbd_params_stability predicts; CSVs and figure copied to bench/results/.
#
#   make bench-stability          (builds both binaries, then runs this)
#   bench/stability.sh [outdir]   (default out/bench; about 3 minutes)
#
# Extra arguments for both binaries can be passed in $STABILITY_ARGS
# (e.g. STABILITY_ARGS="quick=1").
set -eu

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
cd "$root"
out=${1:-out/bench}
mkdir -p "$out"

for b in build/bench_stability build/bench_stability_hcbd; do
    if [ ! -x "$b" ]; then
        echo "stability.sh: $b missing (make build/bench_stability build/bench_stability_hcbd)" >&2
        exit 1
    fi
done

start=$(date +%s)
# shellcheck disable=SC2086
./build/bench_stability out="$out" ${STABILITY_ARGS:-}
# shellcheck disable=SC2086
./build/bench_stability_hcbd out="$out" ${STABILITY_ARGS:-}
echo "stability map: $(($(date +%s) - start)) s"

results=bench/results
mkdir -p "$results"
cp "$out/stability.csv" "$out/stability_hcbd.csv" "$results/"

if ! command -v gnuplot >/dev/null 2>&1; then
    echo "gnuplot not found: figure skipped"
    exit 0
fi

# predicted_dt (7) and dt_fail (9) per model/integrator; quoted fields
# (limit names hold commas) are blanked first; points without a failure
# or without a guarded limit are left out.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for f in "$out/stability.csv" "$out/stability_hcbd.csv"; do
    awk -v dir="$tmp" 'NR > 1 {
        gsub(/"[^"]*"/, "Q")
        n = split($0, c, ",")
        if (n < 11 || c[7] ~ /inf|nan/ || c[9] ~ /inf|nan/) next
        g = c[1] "-" c[4] (c[5] > 1 ? "-sub" c[5] : "")
        print c[7], c[9] > (dir "/" g ".dat")
    }' "$f"
done

plots=""
for g in walled-euler walled-shardlow hcbd-euler hcbd-shardlow hcbd-euler-sub2 hcbd-shardlow-sub2; do
    [ -s "$tmp/$g.dat" ] || continue
    case $g in
        walled-euler) pt=7 ;; walled-shardlow) pt=5 ;; hcbd-euler) pt=9 ;;
        hcbd-shardlow) pt=13 ;; *) pt=11 ;;
    esac
    plots="$plots, '$tmp/$g.dat' using 1:2 with points pt $pt ps 1.6 title '$g'"
done

gnuplot <<EOF
set terminal pngcairo size 900,700 enhanced font ",11"
set output '$out/stability.png'
set logscale xy
set xrange [1e-4:1e3]
set yrange [1e-4:1e3]
set format x "10^{%L}"
set format y "10^{%L}"
set xlabel 'predicted bound of the binding limit (hcbd\\_stability), dt'
set ylabel 'measured smallest failing dt'
set title 'Stability: measured failing dt against prediction (GI-BD left, HCBD fluid right; reduced units)'
set key top left
set grid
plot x/3 with lines dt 2 lc rgb 'gray50' title 'y = x/3', \
     x with lines lc rgb 'black' title 'y = x', \
     3*x with lines dt 2 lc rgb 'gray50' title 'y = 3x'$plots
EOF
cp "$out/stability.png" "$results/"
echo "wrote $out/stability.png and $results/"
