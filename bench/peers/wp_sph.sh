#!/usr/bin/env bash
# bench/peers/wp_sph.sh (make bench-wp-sph-peers): run time against the
# viscosity error of the Tait SPH fluid, hcbd and LAMMPS side by side,
# single thread, from the same start.
#
#   LAMMPS pair sph/taitwater/morris + fix sph (Lucy kernel, continuity
#          density, explicit Morris viscosity)
#   hcbd   the HCBD fluid (M4 kernel, summation density), the exact pair
#          sweep (the default) and the papers' Euler pairs
#
# The scene (build/wp_sph): 2000 blobs melted from a lattice, then a
# transverse wave v_y = 0.3 sin(2 pi x / Lx) that decays at nu k^2 K(k);
# wp_sph's fit reads the decay rate from both codes' series alike.  Two
# fluids, c_s = 2.5, support 4:
#   viscous   nu = 16.6: nu / (c_s h) = 3.3 as in Table I (the 2018
#             solution's fluid); dt_visc = 0.125 h^2 / nu = 0.030
#   acoustic  nu = 1: nu / (c_s h) = 0.2; dt_visc = 0.5, 0.25 h / c_s = 0.2
# Error: |nu_fit(dt) / nu_fit(finest dt) - 1|, each code against its own
# finest step (the time step's error); the csv also holds nu_fit over the
# continuum nu K(k) of each code's kernel (the disorder's offset, which no
# step removes).  Cost: seconds per unit of simulated time, the median over
# ROUNDS interleaved rounds (LAMMPS: loop time less "Output"; hcbd: the
# hcbd_hc_world_step calls alone).  The headline: per fluid and integrator the
# cheapest run within TOL of its own reference, and LAMMPS's cost over it.
#
# Knobs: ROUNDS [3] TOL [0.01] WP_OUT [out/wp_sph] LMP (as wp.sh).
# Writes $WP_OUT/wp_sph.csv, wp_sph_headline.txt and, with gnuplot,
# wp_sph.png; about 5 minutes.
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
ROUNDS=${ROUNDS:-3}
TOL=${TOL:-0.01}
OUT=${WP_OUT:-out/wp_sph}
case "$OUT" in /*) ;; *) OUT="$root/$OUT" ;; esac
export OMP_NUM_THREADS=1
. "$here/lib.sh"
find_lmp sph/taitwater/morris
if [ -z "$LMP_BIN" ]; then
    echo "bench/peers/wp_sph.sh: no lmp with pair sph/taitwater/morris (../shared/PEERS.md); skipped"
    exit 0
fi
(cd "$root" && make -s build/wp_sph) || { echo "wp_sph.sh: build failed"; exit 1; }
mkdir -p "$OUT"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/hcbd_wp_sph.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
W="$root/build/wp_sph"
machine_names
echo "wp_sph.sh: $LMP_BIN ($lmp_version), $cpu ($avx), $ROUNDS rounds"
t_start=$(date +%s)
raw="$tmp/raw"
: >"$raw"

# one run: fluid nu time dt code integ -> "fluid code integ dt cost nu_fit ratio" in $raw
one() {
    local fluid=$1 nu=$2 T=$3 dt=$4 code=$5 integ=$6 every steps r L k fitline cost
    every=$(awk -v dt="$dt" -v T="$T" -v n="$SAMPLES" 'BEGIN {e = int(T / (n - 1) / dt + 0.5); print e < 1 ? 1 : e}')
    steps=$((every * (SAMPLES - 1)))
    r=$("$W" dt="$dt" nu="$nu" time="$T" samples="$SAMPLES" pair="${integ/fixsph/exact}" series="$tmp/h.txt" \
        data="$tmp/d.data") ||
        { echo "wp_sph.sh: wp_sph failed"; return; }
    L=$(echo "$r" | sed -n 's/.* L=\([^ ]*\).*/\1/p')
    [ -n "$L" ] || L=$(awk 'BEGIN {printf "%.17g", 20 * (4 * 3.14159265358979324 / 3) ^ (1 / 3)}')
    if [ "$code" = hcbd ]; then
        cost=$(echo "$r" | sed 's/.*seconds_per_time_unit=\([^ ]*\).*/\1/')
        fitline=$("$W" fit="$tmp/h.txt" L="$L" nu="$nu" kernel=m4)
    else
        k=$(awk -v L="$L" 'BEGIN {printf "%.15g", 2 * 3.14159265358979324 / L}')
        (cd "$tmp" && "$LMP_BIN" -nocite -screen none -log "$tmp/log" -in "$here/in.sph_wave" -var data "$tmp/d.data" \
            -var dt "$dt" -var steps "$steps" -var every "$every" -var nu "$nu" -var k "$k") >/dev/null 2>&1
        awk '/^ *Step/ {p = 1; next} /^Loop time/ {p = 0} p && NF == 4 {print $2, $3, $4}' "$tmp/log" >"$tmp/l.txt"
        cost=$(lmp_cost "$tmp/log" "$dt" "$steps")
        fitline=$("$W" fit="$tmp/l.txt" L="$L" nu="$nu" kernel=lucy)
        [ "$(wc -l <"$tmp/l.txt")" -lt "$SAMPLES" ] && fitline="nu_fit=nan ratio=nan"
    fi
    case "$r" in *stopped=*) cost=nan; fitline="nu_fit=nan ratio=nan" ;; esac
    echo "$fluid $code $integ $dt $cost $(echo "$fitline" | sed 's/.*nu_fit=\([^ ]*\).*/\1/') \
$(echo "$fitline" | sed 's/.*ratio=\([^ ]*\).*/\1/')" >>"$raw"
}

for round in $(seq 1 "$ROUNDS"); do
    # every step divides the sample interval (0.36, 1.2): every run fits the same window
    for spec in "viscous 16.6 4.32 13 0.0075 0.015 0.03 0.045 0.06 0.09 0.12 0.18 0.36" \
                "acoustic 1 20.4 18 0.025 0.05 0.1 0.15 0.2 0.3 0.4 0.6"; do
        set -- $spec
        fluid=$1 nu=$2 T=$3 SAMPLES=$4
        shift 4
        for dt in "$@"; do
            one "$fluid" "$nu" "$T" "$dt" lammps fixsph
            one "$fluid" "$nu" "$T" "$dt" hcbd exact
            one "$fluid" "$nu" "$T" "$dt" hcbd euler
        done
    done
    echo "wp_sph.sh: round $round done ($(( $(date +%s) - t_start )) s)"
done

csv="$OUT/wp_sph.csv"
echo "fluid,code,integrator,dt,seconds_per_time_unit,nu_fit,nu_fit_over_nuK,error_vs_finest,cpu" >"$csv"
# the median cost over the rounds; the error against the finest step
median_rounds "$raw" | awk -v cpu="$cpu ($avx)" '{
    if ($1 " " $2 " " $3 != last) { ref = $6; last = $1 " " $2 " " $3 }  # the finest step
    err = ($6 == "nan" || ref == "nan") ? "nan" : sprintf("%.6f", $6 / ref - 1)
    printf "%s,%s,%s,%s,%s,%s,%s,%s,\"%s\"\n", $1, $2, $3, $4, $5, $6, $7, err, cpu
}' >>"$csv"

awk -F, -v tol="$TOL" 'NR > 1 {
    k = $1 "/" $2 "/" $3; if (!(k in seen)) { seen[k] = 1; ord[++n] = k }
    e = $8 < 0 ? -$8 : $8
    if ($5 != "nan" && $8 != "nan" && e <= tol && (!(k in best) || $5 + 0 < best[k])) { best[k] = $5; bdt[k] = $4; berr[k] = $8 }
    if ($2 == "lammps" && $5 != "nan" && $8 != "nan" && $4 + 0 > maxdt[$1]) maxdt[$1] = $4 + 0
}
END {
    for (q = 1; q <= n; ++q) {
        k = ord[q]; split(k, p, "/"); l = p[1] "/lammps/fixsph"
        if (k in best) printf "%-24s cheapest within %g: dt = %g, %.4g s per time unit (error %+.4f)%s\n", k, tol, bdt[k], best[k], berr[k],
            (p[2] != "lammps" && (l in best)) ? sprintf("; LAMMPS / this at equal error: %.2f", best[l] / best[k]) : ""
        else printf "%-24s no point within %g\n", k, tol
    }
    for (f in maxdt) printf "LAMMPS %s: largest stable dt tried %g\n", f, maxdt[f]
}' "$csv" | tee "$OUT/wp_sph_headline.txt"
for fl in viscous acoustic; do
    for k in lammps,fixsph hcbd,exact hcbd,euler; do
        awk -F, -v f="$fl" -v c="${k%%,*}" -v i="${k#*,}" \
            'NR > 1 && $1 == f && $2 == c && $3 == i && $5 != "nan" && $8 != "nan" && $8 + 0 != 0 {print $4, $5, ($8 < 0 ? -$8 : $8), $7}' \
            "$csv" >"$tmp/wp_sph_${fl}_${k%%,*}_${k#*,}.dat"
    done
done
if command -v gnuplot >/dev/null 2>&1; then
    (cd "$tmp" && gnuplot "$here/wp_sph.gp") && cp "$tmp/wp_sph.png" "$OUT/" && echo "wp_sph.sh: $OUT/wp_sph.png"
else
    echo "wp_sph.sh: gnuplot not found: no figure ($here/wp_sph.gp draws it from the .dat files)"
fi
echo "wp_sph.sh: wrote $csv; $(( $(date +%s) - t_start )) s"
