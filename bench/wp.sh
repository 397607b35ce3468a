#!/usr/bin/env bash
# Work-precision benchmark (make bench-wp): runs the GI-BD / walled-channel
# binaries (bench/bench_wp.c, double and float) and the HCBD ones
# (bench/bench_wp_hcbd.c) that exist, merges their CSVs into
# <out>/wp_all.csv, prints the cheapest configuration reaching 1 % error per
# (model, metric), draws <out>/wp.png with bench/wp.gp when gnuplot exists,
# and copies wp.png and wp_all.csv into bench/results/.
#   usage: bench/wp.sh [outdir=out/bench]    (WP_QUICK=1: smoke run)
set -u
out=${1:-out/bench}
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
cd "$root" || exit 1
mkdir -p "$out"
extra=()
[ "${WP_QUICK:-0}" = 1 ] && extra+=(quick=1)
header='model,metric,integrator,precision,noise,dt,h,substeps,seconds_per_time_unit,error,error_err,config'
stamp="$out/.wp_stamp"
touch "$stamp"
sleep 1 # CSVs written from here on are newer than the stamp
start=$(date +%s)
status=0
for b in bench_wp bench_wp_float bench_wp_hcbd bench_wp_hcbd_float; do
    if [ ! -x "build/$b" ]; then
        echo "wp.sh: build/$b not found: skipped"
        continue
    fi
    echo "=== build/$b"
    t0=$(date +%s)
    if ! "build/$b" out="$out" "${extra[@]}"; then
        echo "wp.sh: build/$b failed"
        status=1
    fi
    echo "=== build/$b: $(( $(date +%s) - t0 )) s"
done
# merge every wp*.csv written by this run (whatever its name) with the header
all="$out/wp_all.csv"
echo "$header" > "$all.tmp"
n=0
for f in $(find "$out" -maxdepth 1 -name 'wp*.csv' ! -name 'wp_all.csv' -newer "$stamp" | sort); do
    if [ "$(head -n 1 "$f")" != "$header" ]; then
        echo "wp.sh: $f: unexpected header, skipped"
        continue
    fi
    tail -n +2 "$f" | grep -v "^$header\$" >> "$all.tmp"
    n=$((n + 1))
done
mv "$all.tmp" "$all"
rm -f "$stamp"
echo "wp.sh: merged $n CSV file(s), $(( $(wc -l < "$all") - 1 )) points into $all"
# cheapest configuration whose error is below 1 % by more than its statistical error
awk -F, 'NR > 1 {
    key = $1 "," $2
    if (!(key in seen)) { seen[key] = 1; order[++nk] = key }
    if ($10 + $11 < 0.01 && (!(key in best) || $9 + 0 < cost[key])) {
        c = $12; for (j = 13; j <= NF; ++j) c = c "," $j # a label may hold commas
        best[key] = c; cost[key] = $9 + 0; err[key] = $10; ee[key] = $11
    }
}
END {
    for (i = 1; i <= nk; ++i) {
        split(order[i], mk, ",")
        if (order[i] in best)
            printf "cheapest <1%%: model=%s, metric=%s, config=%s, cost=%.4g s/time (error %.4f +- %.4f)\n",
                   mk[1], mk[2], best[order[i]], cost[order[i]], err[order[i]], ee[order[i]]
        else
            printf "cheapest <1%%: model=%s, metric=%s, none reaches 1 %%\n", mk[1], mk[2]
    }
}' "$all"
mkdir -p bench/results
if command -v gnuplot > /dev/null 2>&1; then
    panels=$(awk -F, 'NR > 1 && !seen[$1 ":" $2]++ {printf "%s%s", sep, $1 ":" $2; sep = " "}' "$all")
    if [ -n "$panels" ] && gnuplot -e "datafile='$all'; outfile='$out/wp.png'; panels='$panels'" bench/wp.gp; then
        echo "wp.sh: wrote $out/wp.png"
        cp "$out/wp.png" bench/results/
    else
        echo "wp.sh: figure failed"
        status=1
    fi
else
    echo "gnuplot not found: figure skipped"
fi
cp "$all" bench/results/
echo "wp.sh: copied to bench/results/; total $(( $(date +%s) - start )) s"
exit $status
