#!/bin/sh
# The checker of docs/exercises.md: make exercise N=k [ANSWER=x].
# Runs exercise k, prints the measured value with its error and the
# expected one with its tolerance, and says whether the run (and, with
# ANSWER, the student's answer) is within it.  Exit 0 when everything
# asked for is within tolerance, 1 when the run is not, 2 for a bad call,
# 3 when the example itself failed, 4 when only the answer is off; the
# last line says which.
B=${1:-build}
k=$2
answer=$3
# HCBD_EXERCISE_ARGS: extra first_step arguments (make test uses N=500)
xargs_fs=${HCBD_EXERCISE_ARGS:-}
say() { printf '%s\n' "$*"; }
mkdir -p out

# run OUT CMD...: CMD's output into OUT, its messages into OUT.err; when
# CMD fails, says so with its last messages and exits 3 (not the
# student's answer: the example did not run)
run() {
    o=$1
    shift
    "$@" > "$o" 2> "$o.err"
    rc=$?
    if [ $rc -ne 0 ]; then
        say "exercise $k: the example failed (exit $rc): $*"
        [ $rc -eq 127 ] && say "  (not built? run make first, or make exercise N=$k, which builds it)"
        tail -n 15 "$o.err" | sed 's/^/  | /'
        exit 3
    fi
}

# finish CODE: the last line, then exit CODE
finish() {
    [ -n "$in_sub" ] && exit "$1" # a part of exercise 9: its caller says it
    case $1 in
    0) say "exercise $k: OK" ;;
    1) say "exercise $k: the run is outside its tolerance (not your answer: see above)" ;;
    4) say "exercise $k: your answer is off; the run itself is fine" ;;
    esac
    exit "$1"
}

# verdict NAME VALUE ERR EXPECTED TOL: |VALUE - EXPECTED| <= TOL, TOL
# already including the statistical error
verdict() {
    say "measured $1 = $2 +- $3; expected $4 within +- $5"
    if awk -v v="$2" -v e="$4" -v t="$5" 'BEGIN { d = v - e; if (d < 0) d = -d; exit !(d <= t) }'; then
        say "the run is within the tolerance"
        run_ok=0
    else
        say "the run is OUTSIDE the tolerance"
        run_ok=1
    fi
    if [ -n "$answer" ]; then
        if awk -v a="$answer" -v v="$2" -v t="$5" 'BEGIN { d = a - v; if (d < 0) d = -d; exit !(a + 0 == a && d <= t) }'; then
            say "your answer $answer is right (within $5 of the run's $2)"
        else
            say "your answer $answer is not within $5 of the run's $2 (the run itself is fine)"
            [ $run_ok -eq 0 ] && run_ok=4
        fi
    fi
    finish $run_ok
}

# below NAME VALUE ERR BOUND: VALUE at least four errors below BOUND; an
# answer must be within four errors of the run's value
below() {
    say "measured $1 = $2 +- $3; expected below $4 by more than 4 errors"
    if awk -v v="$2" -v e="$3" -v b="$4" 'BEGIN { exit !(v + 4 * e < b) }'; then
        say "the run is within the expectation"; run_ok=0
    else
        say "the run is OUTSIDE the expectation"; run_ok=1
    fi
    if [ -n "$answer" ]; then
        if awk -v a="$answer" -v v="$2" -v e="$3" 'BEGIN { d = a - v; if (d < 0) d = -d; exit !(a + 0 == a && d <= 4 * e) }'; then
            say "your answer $answer is right (within 4 errors of the run's $2)"
        else
            say "your answer $answer is not within 4 errors of the run's $2 (the run itself is fine)"
            [ $run_ok -eq 0 ] && run_ok=4
        fi
    fi
    finish $run_ok
}

# get FILE KEY: the value of KEY=value in FILE (the first one)
get() { awk -F= -v k="$2" '$1 == k { print $2; exit }' "$1"; }

# field LABEL COLUMN: a number of first_step's output
field() { printf '%s\n' "$out" | awk -v l="$1" -v c="$2" '$1 == l { x = $c; gsub(/[(),]/, "", x); print x }'; }

case "$k" in
1)  say "exercise 1: the background temperature of ideal carriers (build/first_step)"
    run out/exercise1.txt "$B/first_step" $xargs_fs; out=$(cat out/exercise1.txt)
    T=$(field temperature 2); eT=$(field temperature 4)
    verdict "T / kT" "$T" "$eT" 1 "$(awk -v e="$eT" 'BEGIN { print 4 * e }')" ;;
2)  say "exercise 2: the friction network's viscosity against its mean field at k (build/first_step)"
    run out/exercise2.txt "$B/first_step" $xargs_fs; out=$(cat out/exercise2.txt)
    nu=$(field viscosity 2); en=$(field viscosity 4)
    nk=$(printf '%s\n' "$out" | awk '$1 == "viscosity" { x = $NF; gsub(/[()]/, "", x); print x }')
    verdict "nu" "$nu" "$en" "$nk" "$(awk -v e="$en" -v n="$nk" 'BEGIN { print 4 * e + 0.005 * n }')" ;;
3)  say "exercise 3: the Euler temperature bias halves with dt (build/gibd_bulk, two runs, ~1 min)"
    for dt in 1e-4 5e-5; do
        steps=$(awk -v d="$dt" 'BEGIN { printf "%d", 2 / d }')
        run out/exercise3.$dt "$B/gibd_bulk" potential=ideal pair=euler N=500 tau=1e-3 dt=$dt steps=$steps \
            out=out/exercise3/dt$dt
    done
    r1=$(get out/exercise3.1e-4 T_ratio); e1=$(get out/exercise3.1e-4 T_ratio_err)
    r2=$(get out/exercise3.5e-5 T_ratio); e2=$(get out/exercise3.5e-5 T_ratio_err)
    say "T/kT = $r1 +- $e1 at dt = 1e-4, $r2 +- $e2 at dt = 5e-5"
    q=$(awk -v a="$r1" -v b="$r2" 'BEGIN { print (a - 1) / (b - 1) }')
    eq=$(awk -v a="$r1" -v b="$r2" -v ea="$e1" -v eb="$e2" \
        'BEGIN { x = a - 1; y = b - 1; print (x / y) * sqrt((ea / x) ^ 2 + (eb / y) ^ 2) }')
    # first order: the ratio is 2; the second-order terms seen in the
    # library's runs move it by a few per cent
    verdict "bias ratio" "$q" "$eq" 2 "$(awk -v e="$eq" 'BEGIN { print 4 * e + 0.1 }')" ;;
4)  say "exercise 4: the initial-decay identity in the star liquid (build/gibd_bulk, ~30 s)"
    run out/exercise4.txt "$B/gibd_bulk" N=500 steps=40000 out=out/exercise4
    grep -E '^(nu_meanfield|nu_initial|initial_decay_identity)' out/exercise4.txt
    v=$(get out/exercise4.txt initial_decay_identity); e=$(get out/exercise4.txt initial_decay_identity_err)
    verdict "initial decay rate / friction average" "$v" "$e" 1 "$(awk -v e="$e" 'BEGIN { print 4 * e }')" ;;
5)  say "exercise 5: short- and long-time diffusion of ideal carriers (build/gibd_bulk, ~20 s)"
    o=out/exercise5.txt
    run $o "$B/gibd_bulk" potential=ideal N=500 tau=0.1 dt=1e-3 skin=1.2 steps=20000 out=out/exercise5
    say "long time: D_measured = $(get $o D_measured) +- $(get $o D_measured_err), eq. 33: $(get $o D_theory)"
    verdict "MSD(tau) / eq. 32" "$(get $o msd_ratio_at_tau)" "-" 1 0.03 ;;
6)  say "exercise 6: the viscosity of ideal carriers three ways (build/gibd_bulk, two runs, ~40 s)"
    a=out/exercise6a.txt; s=out/exercise6b.txt
    run $a "$B/gibd_bulk" potential=ideal tau=2e-3 xip=1.5 dt=2e-4 N=500 steps=20000 out=out/exercise6a
    run $s "$B/gibd_bulk" potential=ideal tau=2e-3 xip=1.5 dt=2e-4 N=500 steps=20000 gdot=4 out=out/exercise6b
    say "eq. 35: nu = $(get $a nu_theory); friction average at k: $(get $a nu_meanfield) +- $(get $a nu_meanfield_err);"
    say "transverse current, late decay: $(get $a nu_hydro) +- $(get $a nu_hydro_err)"
    r=$(awk -v m="$(get $s eta_background_measured)" -v t="$(get $s eta_background_theory)" 'BEGIN { print m / t }')
    # MODEL 12: the library's Lees-Edwards, channel and transverse-current
    # runs read 0.634-0.688 of eq. 35
    verdict "Lees-Edwards background viscosity / eq. 35" "$r" "-" 0.66 0.05 ;;
7)  say "exercise 7: walls: slip and no slip (build/channel_flow, two runs, ~40 s)"
    a=out/exercise7a.txt; s=out/exercise7b.txt
    run $a "$B/channel_flow" xip=1 out=out/exercise7a
    run $s "$B/channel_flow" xip=1 wall=noslip out=out/exercise7b
    say "Gaussian walls: slip velocity / v_max = $(get $a slip_velocity_ratio) +- $(get $a slip_velocity_ratio_err)," \
        "depletion width $(get $a depletion_width) (Boltzmann $(get $a depletion_width_boltzmann))"
    e=$(get $s slip_velocity_ratio_err)
    verdict "no-slip walls: slip velocity / v_max" "$(get $s slip_velocity_ratio)" "$e" 0 \
        "$(awk -v e="$e" 'BEGIN { print 4 * e }')" ;;
8)  say "exercise 8: the flow curve of the star liquid and its Carreau fit (build/shear_flow, ~40 s)"
    o=out/exercise8.txt
    run $o "$B/shear_flow" xip=1 out=out/exercise8
    grep -E '^(eta_total_measured|eta_total_err|eta_background_theory|eta0|lambda|n|n_err)=' $o
    below "Carreau exponent n" "$(get $o n)" "$(get $o n_err)" 1 ;;
9)  say "exercise 9: the viscosity and the sound speed of the SPH fluid (build/hcbd_fluid, build/hcbd_sound, ~35 s)"
    o=out/exercise9.txt; s=out/exercise9s.txt
    run $o "$B/hcbd_fluid" out=out/exercise9
    run $s "$B/hcbd_sound"
    say "with fluctuations: nu_le = $(get $o nu_le) +- $(get $o nu_le_err); reverse Poiseuille:" \
        "$(get $o nu_poiseuille) +- $(get $o nu_poiseuille_err), the kernel-smoothed prediction $(get $o nu_kernel_poiseuille)"
    t=$(get $o nu_theory)
    # laminar Lees-Edwards: the block error (1e-6) is far below what the
    # discretisation at h = 2 sigma leaves; 1 % is the tolerance
    verdict_ok=0
    ( in_sub=1; verdict "laminar Lees-Edwards nu" "$(get $o nu_le_nofluct)" "$(get $o nu_le_nofluct_err)" "$t" \
        "$(awk -v t="$t" 'BEGIN { print 0.01 * t }')" ) || verdict_ok=$?
    say "sound: c_s = $(get $s c_s), c_s W~(k) = $(get $s c_expected), measured $(get $s c_measured);" \
        "damping $(get $s damping_measured) against nu k^2 / 2 = $(get $s damping_expected)"
    # the kernel factor is 2 %: 2 % tells it from the bare c_s
    ( in_sub=1; answer=; verdict "sound speed / (c_s W~(k)) (ANSWER is the viscosity)" "$(get $s c_ratio)" "-" 1 0.02 ) || verdict_ok=1 # the run, never the answer
    finish $verdict_ok ;;
10) say "exercise 10: shear thinning with RaPiD transient pairs (build/hcbd_polymer, ~15 s)"
    o=out/exercise10.txt
    run $o "$B/hcbd_polymer" out=out/exercise10
    s1=$(awk -F= '$1 == "shear_thinning" { print $2; exit }' $o)
    s2=$(awk -F= '$1 == "shear_thinning" { n++; if (n == 2) print $2 }' $o)
    e2=$(awk -F= '$1 == "shear_thinning_err" { n++; if (n == 2) print $2 }' $o)
    say "eta(fastest) / eta(slowest): $s1 at C = 2.5 C*, $s2 +- $e2 at C = 5 C*"
    below "eta ratio at 5 C*, against the one at 2.5 C*" "$s2" "$e2" "$s1" ;;
*)  say "usage: make exercise N=k [ANSWER=x], k = 1..10 (docs/exercises.md)"; exit 2 ;;
esac
