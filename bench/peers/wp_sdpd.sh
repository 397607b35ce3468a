#!/usr/bin/env bash
# bench/peers/wp_sdpd.sh (make bench-wp-sdpd-peers): run time against the
# error of the fluctuating Tait fluid (SDPD), hcbd and LAMMPS side by
# side, single thread, from the same start.
#
#   LAMMPS pair sdpd/taitwater/isothermal + fix sph (Lucy kernel,
#          continuity density, Espanol's viscous force and pair noise)
#   hcbd   the HCBD fluid with fluctuations (M4 kernel, summation
#          density), the exact pair sweep (the default) and the papers'
#          Euler pairs
#
# The scene: build/wp_sph's melted fluid (2000 blobs of mass 100, c_s =
# 2.5, support 4) at nu = 16.6 (nu / (c_s h) = 3.3 as in Table I; dt_visc
# = 0.125 h^2 / nu = 0.030), kT = 1, Maxwell velocities at the start.
# Two runs per code and step:
#   temperature  no wave; <T_kin>/kT over the last 80 % of `time`, error
#                from 10 block means (wp_sph temp=); the error axis is
#                |T/kT - 1| against the exact kT
#   viscosity    a transverse wave v_y = 1.0 sin(2 pi x / Lx) (Mach 0.4)
#                on top of the thermal velocities (300x the mode's thermal
#                amplitude at the start, 70x at the end); wp_sph's fit
#                reads its decay rate; the error axis is |nu_fit(dt) /
#                nu_fit(finest dt) - 1|, each code against its own finest
#                step; the fluctuations leave a scatter of their own
#                between steps (each step draws other numbers)
# Cost: seconds per unit of simulated time of the temperature run, the
# median over ROUNDS interleaved rounds (LAMMPS: loop time less
# "Output"; hcbd: the hcbd_hc_world_step calls alone).  The headline:
# per code and axis the cheapest run within TOL, and LAMMPS's cost over it.
#
# Knobs: ROUNDS [3] TOL [0.01] WP_OUT [out/wp_sdpd] LMP (as wp.sh)
#        DTS ["0.0009375 0.001875 0.00375 0.0075 0.015 0.03 0.06"].
# Writes $WP_OUT/wp_sdpd.csv and wp_sdpd_headline.txt (about 17 minutes);
# `wp_sdpd.sh --headline CSV` prints the headline of a stored csv again.
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
ROUNDS=${ROUNDS:-3}
TOL=${TOL:-0.01}
DTS=${DTS:-"0.0009375 0.001875 0.00375 0.0075 0.015 0.03 0.06"}
OUT=${WP_OUT:-out/wp_sdpd}
case "$OUT" in /*) ;; *) OUT="$root/$OUT" ;; esac
export OMP_NUM_THREADS=1
NU=16.6 TIME=6 SAMPLES=201 WTIME=2.4 WSAMPLES=41 AMP=1.0

# headline CSV: per axis, code and integrator the cheapest run within TOL,
# and LAMMPS's cost over it at equal error
headline() {
    awk -F, -v tol="$TOL" 'NR > 1 {
        k = $1 "/" $2 "/" $3; if (!(k in seen)) { seen[k] = 1; ord[++n] = k; fin[k] = $4 }
        e = $8 < 0 ? -$8 : $8
        # the viscosity is measured against the finest step: that one is no point
        use = $5 != "nan" && $8 != "nan" && ($1 == "temperature" || $4 != fin[k])
        if (use && e <= tol && (!(k in best) || $5 + 0 < best[k])) { best[k] = $5; bdt[k] = $4; berr[k] = $8 }
        if (use) { last[k] = $4; lerr[k] = $8 }
    }
    END {
        for (q = 1; q <= n; ++q) {
            k = ord[q]; split(k, p, "/"); l = p[1] "/lammps/lmp"; tail = ""
            if (p[2] != "lammps") tail = (l in best) ? sprintf("; LAMMPS / this at equal error: %.1f", best[l] / best[k]) : "; LAMMPS has no step within it"
            if (k in best) printf "%-28s cheapest within %g: dt = %g, %.4g s per time unit (error %+.4f)%s\n", k, tol, bdt[k], best[k], berr[k], tail
            else printf "%-28s no step within %g (largest dt run %s: error %s)\n", k, tol, last[k], lerr[k]
        }
    }' "$1"
}

if [ "${1:-}" = --headline ]; then # again from a stored csv
    headline "$2"
    exit 0
fi
. "$here/lib.sh"
find_lmp sdpd/taitwater/isothermal
if [ -z "$LMP_BIN" ]; then
    echo "bench/peers/wp_sdpd.sh: no lmp with pair sdpd/taitwater/isothermal (../shared/PEERS.md); skipped"
    exit 0
fi
(cd "$root" && make -s build/wp_sph) || { echo "wp_sdpd.sh: build failed"; exit 1; }
mkdir -p "$OUT"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/hcbd_wp_sdpd.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
W="$root/build/wp_sph"
machine_names
echo "wp_sdpd.sh: $LMP_BIN ($lmp_version), $cpu ($avx), $ROUNDS rounds, dt $DTS"
t_start=$(date +%s)
raw="$tmp/raw"
: >"$raw"

# one run: kind(temp|wave) dt code integ -> "kind code integ dt cost value err" in $raw
one() {
    local kind=$1 dt=$2 code=$3 integ=$4 T S amp every steps r L k cost val err line
    if [ "$kind" = temp ]; then T=$TIME S=$SAMPLES amp=0; else T=$WTIME S=$WSAMPLES amp=$AMP; fi
    every=$(awk -v dt="$dt" -v T="$T" -v n="$S" 'BEGIN {e = int(T / (n - 1) / dt + 0.5); print e < 1 ? 1 : e}')
    steps=$((every * (S - 1)))
    r=$("$W" dt="$dt" nu="$NU" kT=1 amp="$amp" time="$T" samples="$S" pair="${integ/lmp/exact}" \
        series="$tmp/h.txt" data="$tmp/d.data") || { echo "wp_sdpd.sh: wp_sph failed"; return; }
    L=$(echo "$r" | sed -n 's/.* L=\([^ ]*\).*/\1/p')
    if [ "$code" = hcbd ]; then
        cost=$(echo "$r" | sed 's/.*seconds_per_time_unit=\([^ ]*\).*/\1/')
        cp "$tmp/h.txt" "$tmp/s.txt"
        case "$r" in *stopped=*) cost=nan ;; esac
    else
        k=$(awk -v L="$L" 'BEGIN {printf "%.15g", 2 * 3.14159265358979324 / L}')
        (cd "$tmp" && "$LMP_BIN" -nocite -screen none -log "$tmp/log" -in "$here/in.sdpd_wave" -var data "$tmp/d.data" \
            -var dt "$dt" -var steps "$steps" -var every "$every" -var nu "$NU" -var k "$k" -var kT 1 \
            -var seed 7) >/dev/null 2>&1
        awk '/^ *Step/ {p = 1; next} /^Loop time/ {p = 0} p && NF == 5 {print $2, $3, $4, $5}' "$tmp/log" >"$tmp/s.txt"
        cost=$(lmp_cost "$tmp/log" "$dt" "$steps")
    fi
    if [ "$kind" = temp ]; then
        line=$("$W" temp="$tmp/s.txt")
        val=$(echo "$line" | sed 's/.*T=\([^ ]*\).*/\1/'); err=$(echo "$line" | sed 's/.*T_err=\([^ ]*\).*/\1/')
    else
        line=$("$W" fit="$tmp/s.txt" L="$L" nu="$NU" kernel=$([ "$code" = hcbd ] && echo m4 || echo lucy))
        val=$(echo "$line" | sed 's/.*nu_fit=\([^ ]*\).*/\1/'); err=$(echo "$line" | sed 's/.*nu_fit_err=\([^ ]*\).*/\1/')
    fi
    [ "$(wc -l <"$tmp/s.txt")" -lt 3 ] && { val=nan; err=nan; }
    [ "$cost" = nan ] && { val=nan; err=nan; }
    echo "$kind $code $integ $dt $cost $val $err" >>"$raw"
}

for round in $(seq 1 "$ROUNDS"); do
    for dt in $DTS; do
        for kind in temp wave; do
            one "$kind" "$dt" lammps lmp
            one "$kind" "$dt" hcbd exact
            one "$kind" "$dt" hcbd euler
        done
    done
    echo "wp_sdpd.sh: round $round done ($(( $(date +%s) - t_start )) s)"
done

csv="$OUT/wp_sdpd.csv"
echo "axis,code,integrator,dt,seconds_per_time_unit,value,value_err,error,cpu" >"$csv"
# the median cost over the rounds; the values are the same every round
# (deterministic), the temperature's error is |T/kT - 1|, the
# viscosity's against the code's finest step
median_rounds "$raw" | awk -v cpu="$cpu ($avx)" '{
    if ($1 " " $2 " " $3 != last) { ref = $6; last = $1 " " $2 " " $3 }  # the finest step
    if ($6 == "nan") err = "nan"
    else if ($1 == "temp") err = sprintf("%.6f", $6 - 1)
    else err = (ref == "nan") ? "nan" : sprintf("%.6f", $6 / ref - 1)
    printf "%s,%s,%s,%s,%s,%s,%s,%s,\"%s\"\n", ($1 == "temp" ? "temperature" : "viscosity"), $2, $3, $4, $5, $6, $7, err, cpu
}' >>"$csv"

headline "$csv" | tee "$OUT/wp_sdpd_headline.txt"
echo "wp_sdpd.sh: wrote $csv; $(( $(date +%s) - t_start )) s"
