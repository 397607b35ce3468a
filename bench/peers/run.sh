#!/usr/bin/env bash
# bench/peers/run.sh: hcbd against LAMMPS, side by side, in one run, single
# thread, medians of REPS runs of each code (the runs of the two codes are
# interleaved so that both see the same machine load).
#
#   bench/peers/run.sh            (from anywhere; about 8 minutes on 2 cores)
#
# lmp is the first of $LMP, /tmp/peer/build/lmp (../shared/PEERS.md: -O3
# -march=native, no MPI), lmp on the PATH and build/lammps/lmp (make lammps:
# the plugin's engine, -O2 with MPI, the slowest) that has the styles the
# inputs use: Debian's own lmp lacks fix brownian and the SPH pair styles.  Environment knobs (defaults in brackets):
#   REPS [3]  STAR_N [32768]  FLUID_N [64000]  SOLUTION_N [8000]
#   STAR_STEPS [1500]  GAUSS_STEPS [800]  DPD_STEPS [800]
#   SPH_STEPS [250]  SDPD_STEPS [40]  PEERS_OUT [out/peers]
# Writes $PEERS_OUT/peers.csv (relative to the repository root) and prints a
# table: hcbd and LAMMPS ns per particle-step, their ratio, the target and
# neighbour counts (hcbd: pairs per particle in its half Verlet list;
# LAMMPS: "Ave neighs/atom" of its half list, skin included); then hcbd on
# 2 threads: its ns, the speed-up over 1 thread and whether the two runs
# ended with the same checksum.  The "table1" row is hcbd's Table I polymer
# solution (SOLUTION_N fluid + SOLUTION_N polymer blobs, the defaults) per
# blob-step against LAMMPS's pure Tait fluid per particle-step.
set -u

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)

# has_styles BIN: lmp -h lists every style the inputs need
has_styles() {
    local h s
    h=$("$1" -h 2>/dev/null) || return 1
    for s in brownian table sph/taitwater/morris sdpd/taitwater/isothermal dpd/tstat; do
        printf '%s\n' "$h" | grep -qw -- "$s" || return 1
    done
}
LMP_BIN=""
for cand in "${LMP:-}" /tmp/peer/build/lmp "$(command -v lmp 2>/dev/null)" "$root/build/lammps/lmp"; do
    [ -n "$cand" ] && command -v "$cand" >/dev/null 2>&1 || continue
    if has_styles "$cand"; then LMP_BIN=$(command -v "$cand"); break; fi
    echo "bench/peers: $cand lacks fix brownian or an SPH/DPD style; not used"
done
if [ -z "$LMP_BIN" ]; then
    echo "bench/peers: no lmp with the styles needed (make lammps, or ../shared/PEERS.md); skipped"
    exit 0
fi

REPS=${REPS:-3}
STAR_N=${STAR_N:-32768}
FLUID_N=${FLUID_N:-64000}
SOLUTION_N=${SOLUTION_N:-8000}
STAR_STEPS=${STAR_STEPS:-1500}
GAUSS_STEPS=${GAUSS_STEPS:-800}
DPD_STEPS=${DPD_STEPS:-800}
SPH_STEPS=${SPH_STEPS:-250}
SDPD_STEPS=${SDPD_STEPS:-40}
OUTDIR=${PEERS_OUT:-out/peers}
export OMP_NUM_THREADS=1

t_start=$(date +%s)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/hcbd_peers.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# LAMMPS version (the first line of any run: "LAMMPS (7 Jan 2022)")
lmp_version=$("$LMP_BIN" -nocite -log none -in /dev/null 2>/dev/null | head -n 1 | tr -d '\r')
[ -n "$lmp_version" ] || lmp_version="unknown"
echo "bench/peers: $LMP_BIN, $lmp_version, OMP_NUM_THREADS=1, $REPS runs each (median)"

# hcbd bench binaries
hcbd_ok=1
if ! (cd "$root" && make -s build/bench_speed build/bench_hcbd >"$tmp/make.log" 2>&1); then
    echo "bench/peers: building build/bench_speed build/bench_hcbd failed; hcbd columns n/a:"
    tail -n 20 "$tmp/make.log"
    hcbd_ok=0
fi

# star-potential table (hcbd_star_potential, f = 128, sigma = eps = 1)
awk -v f=128 -v sigma=1 -v eps=1 -v n=5000 -v rlo=0.01 -v rhi=2.5 \
    -f "$here/star_table.awk" >"$tmp/star.table"

# one LAMMPS run: name input N steps seed [extra -var pairs...]
# appends "ns_per_particle_step neighs" to $tmp/lmp_<name>.txt
lmp_run() {
    local name=$1 input=$2 n=$3 steps=$4 seed=$5
    shift 5
    local log="$tmp/log.$name.$seed"
    if ! (cd "$tmp" && "$LMP_BIN" -nocite -screen none -log "$log" -in "$here/$input" \
            -var N "$n" -var steps "$steps" -var seed "$seed" -var table "$tmp/star.table" "$@"); then
        echo "bench/peers: lmp failed on $input (log below)"
        tail -n 15 "$log"
        return 1
    fi
    # "Loop time of T on P procs for S steps with N atoms" of the timed (last) run
    awk '/^Loop time of/ {t = $4; s = $9; n = $12}
         /^Ave neighs\/atom/ {nb = $4}
         END {if (s > 0 && n > 0) printf "%.3f %s\n", 1e9 * t / (s * n), nb}' "$log" \
        >>"$tmp/lmp_$name.txt"
}

# hcbd CSV lookup by column name: file scene keycol keyval field [threads, 1]
csv_get() {
    awk -F, -v sc="$2" -v kc="$3" -v kv="$4" -v fld="$5" -v th="${6:-1}" '
        NR == 1 {for (i = 1; i <= NF; ++i) h[$i] = i; next}
        $(h["scene"]) == sc && $(h[kc]) + 0 == kv + 0 && $(h["threads"]) + 0 == th {print $(h[fld]); exit}' "$1"
}

# one run's row of an hcbd CSV: file scene keycol keyval ->
# ns (1 thread), pairs, ns (2 threads), checksums (1 thread, 2 threads)
hcbd_row() {
    echo "$(csv_get "$1" "$2" "$3" "$4" ns_per_particle_step)" \
         "$(csv_get "$1" "$2" "$3" "$4" pairs_per_particle)" \
         "$(csv_get "$1" "$2" "$3" "$4" ns_per_particle_step 2)" \
         "$(csv_get "$1" "$2" "$3" "$4" checksum)" \
         "$(csv_get "$1" "$2" "$3" "$4" checksum 2)"
}

median() { # median of the numbers on stdin (lower middle for an even count)
    sort -g | awk 'NF {a[++n] = $1} END {if (n) print a[int((n + 1) / 2)]; else print "n/a"}'
}

for rep in $(seq 1 "$REPS"); do
    seed=$((1000 + rep))
    echo "bench/peers: run $rep/$REPS ($(($(date +%s) - t_start)) s)"
    lmp_run star_bd in.star_bd "$STAR_N" "$STAR_STEPS" "$seed" -var rng uniform
    lmp_run star_bd_gauss in.star_bd "$STAR_N" "$GAUSS_STEPS" "$seed" -var rng gaussian
    lmp_run star_dpd in.star_dpd "$STAR_N" "$DPD_STEPS" "$seed"
    lmp_run sph_tait in.sph_tait "$FLUID_N" "$SPH_STEPS" "$seed"
    lmp_run sdpd in.sdpd "$FLUID_N" "$SDPD_STEPS" "$seed"
    if [ "$hcbd_ok" = 1 ]; then
        d="$tmp/hcbd$rep"
        mkdir -p "$d"
        # like for like: Euler-Maruyama displacement, as fix brownian (hcbd's
        # default Leimkuhler-Matthews draws one more Gaussian triple per step)
        for nz in uniform gauss; do
            (cd "$root" && OMP_NUM_THREADS=2 ./build/bench_speed Nmax="$STAR_N" threads=2 noise=$nz \
                brownian=euler scenes=bd,gibd out="$d" >"$d/speed_$nz.log" 2>&1) ||
                { echo "bench/peers: bench_speed failed"; tail -n 5 "$d/speed_$nz.log"; }
        done
        (cd "$root" && OMP_NUM_THREADS=2 ./build/bench_hcbd Nmax="$FLUID_N" threads=2 scenes=sph,sdpd \
            out="$d" >"$d/hcbd.log" 2>&1) ||
            { echo "bench/peers: bench_hcbd failed"; tail -n 5 "$d/hcbd.log"; }
        mkdir -p "$d/sol"
        (cd "$root" && OMP_NUM_THREADS=2 ./build/bench_hcbd Nmax="$SOLUTION_N" threads=2 scenes=table1 \
            out="$d/sol" >"$d/sol.log" 2>&1) ||
            { echo "bench/peers: bench_hcbd table1 failed"; tail -n 5 "$d/sol.log"; }
        for s in bd gibd; do
            for f in "$d/speed_uniform.csv:_u" "$d/speed.csv:"; do
                [ -f "${f%%:*}" ] && hcbd_row "${f%%:*}" "$s" N "$STAR_N" >>"$tmp/hcbd_$s${f##*:}.txt"
            done
        done
        for s in sph sdpd; do
            [ -f "$d/speed_hcbd.csv" ] && hcbd_row "$d/speed_hcbd.csv" "$s" N_fluid "$FLUID_N" >>"$tmp/hcbd_$s.txt"
        done
        [ -f "$d/sol/speed_hcbd.csv" ] &&
            hcbd_row "$d/sol/speed_hcbd.csv" table1 N_fluid "$SOLUTION_N" >>"$tmp/hcbd_table1.txt"
    fi
done

med_col() { # file column
    [ -s "$1" ] || { echo n/a; return; }
    awk -v c="$2" '{print $c}' "$1" | grep -v '^$' | median
}

mkdir -p "$root/$OUTDIR"
csv="$root/$OUTDIR/peers.csv"
echo "hcbd_scene,lammps_scene,N,hcbd_ns_per_particle_step,lammps_ns_per_particle_step,lammps_particle_steps_per_s,ratio_lammps_over_hcbd,target,met,hcbd_pairs_per_particle,lammps_neighs_per_atom,noise,lammps_version,reps,hcbd_ns_2_threads,speedup_2_threads,same_checksum" >"$csv"

printf '\n%-12s %-14s %6s %10s %10s %7s %6s %4s %9s %9s %9s %7s %5s\n' \
    "hcbd" "LAMMPS" "N" "hcbd ns" "LAMMPS ns" "ratio" "target" "met" "hcbd nb" "LAMMPS nb" "2 thr ns" "x 2 thr" "bits"
printf '%s\n' "--------------------------------------------------------------------------------------------------------------"
row() { # hcbd_scene lammps_scene N target noise
    local hs=$1 ls=$2 n=$3 target=$4 noise=$5
    local hns lns lnb hnb ratio met pss h2 sp same
    hns=$(med_col "$tmp/hcbd_$hs.txt" 1)
    hnb=$(med_col "$tmp/hcbd_$hs.txt" 2)
    h2=$(med_col "$tmp/hcbd_$hs.txt" 3)
    sp=$(awk -v a="$hns" -v b="$h2" 'BEGIN {if (a + 0 > 0 && b + 0 > 0) printf "%.2f", a / b; else print "n/a"}')
    same=$(awk 'NF >= 5 {n++; if ($4 != $5) d++} END {print n ? (d ? "no" : "yes") : "n/a"}' "$tmp/hcbd_$hs.txt" 2>/dev/null)
    lns=$(med_col "$tmp/lmp_$ls.txt" 1)
    lnb=$(med_col "$tmp/lmp_$ls.txt" 2)
    case "$hs" in fluid*) hnb="n/a" ;; esac   # the fluid bench reports no pair count
    ratio=$(awk -v a="$lns" -v b="$hns" 'BEGIN {if (a + 0 > 0 && b + 0 > 0) printf "%.2f", a / b; else print "n/a"}')
    pss=$(awk -v a="$lns" 'BEGIN {if (a + 0 > 0) printf "%.3g", 1e9 / a; else print "n/a"}')
    if [ "$target" = "-" ] || [ "$ratio" = "n/a" ]; then met="-"
    else met=$(awk -v r="$ratio" -v t="$target" 'BEGIN {print (r + 0 >= t + 0) ? "yes" : "no"}'); fi
    printf '%-12s %-14s %6s %10s %10s %7s %6s %4s %9s %9s %9s %7s %5s\n' \
        "$hs" "$ls" "$n" "$hns" "$lns" "$ratio" "$target" "$met" "$hnb" "$lnb" "$h2" "$sp" "$same"
    echo "$hs,$ls,$n,$hns,$lns,$pss,$ratio,$target,$met,$hnb,$lnb,$noise,\"$lmp_version\",$REPS,$h2,$sp,$same" >>"$csv"
}
row bd_u        star_bd       "$STAR_N"  3  "uniform noise on both sides (LAMMPS fix brownian default)"
row bd          star_bd_gauss "$STAR_N"  3  "Gaussian noise on both sides (LAMMPS rng gaussian)"
row gibd_u      star_bd       "$STAR_N"  1.5  "uniform: hcbd GI-BD pair and Brownian noise; LAMMPS fix brownian"
row gibd        star_bd_gauss "$STAR_N"  -  "Gaussian: hcbd GI-BD; LAMMPS fix brownian rng gaussian"
row gibd        star_dpd      "$STAR_N"  2  "LAMMPS dpd/tstat (1 Gaussian per pair) + fix nve"
row sph         sph_tait      "$FLUID_N" 1.5 "no noise; both from random positions"
row sdpd        sdpd          "$FLUID_N" 6  "LAMMPS 6 Gaussians per pair; hcbd pairwise"
row table1      sph_tait      "$SOLUTION_N" 1 "hcbd Table I solution (N fluid + N polymer blobs, defaults) per blob-step; LAMMPS pure fluid"
own=$(awk -v a="$(med_col "$tmp/hcbd_gibd_u.txt" 1)" -v b="$(med_col "$tmp/hcbd_bd_u.txt" 1)" \
    'BEGIN {if (a + 0 > 0 && b + 0 > 0) printf "%.2f", a / b; else print "n/a"}')
echo "hcbd GI-BD / hcbd BD (uniform noise): $own (target <= 1.5)"
echo "hcbd_gibd_over_bd,,$STAR_N,,,,$own,1.5,,,,uniform,\"$lmp_version\",$REPS" >>"$csv"
echo
echo "ns = nanoseconds per particle-step, single thread, median of $REPS runs; 2 thr: hcbd on"
echo "2 threads, x 2 thr its speed-up (target 1.85), bits: the same checksum on 1 and 2 threads"
echo "(hcbd: each run's value is bench_speed/bench_hcbd's own minimum over repeats);"
echo "ratio = LAMMPS / hcbd; nb = neighbours per particle in the half list (skin included)."
echo "LAMMPS particle-steps/s: $(awk -F, 'NR > 1 && !s[$2]++ {printf "%s %s  ", $2, $6}' "$csv")"
echo "$lmp_version; wrote $OUTDIR/peers.csv; $(($(date +%s) - t_start)) s"
