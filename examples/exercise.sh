#!/bin/sh
# The checker of docs/exercises.md: make exercise N=k [ANSWER=x].
# Runs exercise k, prints the measured value with its error and the
# expected one with its tolerance, and says whether the run (and, with
# ANSWER, the student's answer) is within it.  Exit 0 when everything
# asked for is within tolerance, 1 when not, 2 for a bad call.
B=${1:-build}
k=$2
answer=$3
# HCBD_EXERCISE_ARGS: extra first_step arguments (make test uses N=500)
xargs_fs=${HCBD_EXERCISE_ARGS:-}
say() { printf '%s\n' "$*"; }

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
            say "your answer $answer is not within $5 of the run's $2"
            run_ok=1
        fi
    fi
    exit $run_ok
}

# field LABEL COLUMN: a number of first_step's output
field() { printf '%s\n' "$out" | awk -v l="$1" -v c="$2" '$1 == l { x = $c; gsub(/[(),]/, "", x); print x }'; }

case "$k" in
1)  say "exercise 1: the background temperature of ideal carriers (build/first_step)"
    out=$("$B/first_step" $xargs_fs) || exit 1
    T=$(field temperature 2); eT=$(field temperature 4)
    verdict "T / kT" "$T" "$eT" 1 "$(awk -v e="$eT" 'BEGIN { print 4 * e }')" ;;
2)  say "exercise 2: the friction network's viscosity against its mean field at k (build/first_step)"
    out=$("$B/first_step" $xargs_fs) || exit 1
    nu=$(field viscosity 2); en=$(field viscosity 4)
    nk=$(printf '%s\n' "$out" | awk '$1 == "viscosity" { x = $NF; gsub(/[()]/, "", x); print x }')
    verdict "nu" "$nu" "$en" "$nk" "$(awk -v e="$en" -v n="$nk" 'BEGIN { print 4 * e + 0.005 * n }')" ;;
3)  say "exercise 3: the Euler temperature bias halves with dt (build/gibd_bulk, two runs, ~1 min)"
    for dt in 1e-4 5e-5; do
        steps=$(awk -v d="$dt" 'BEGIN { printf "%d", 2 / d }')
        "$B/gibd_bulk" potential=ideal pair=euler N=500 tau=1e-3 dt=$dt steps=$steps \
            threads=2 out=out/exercise3/dt$dt 2>/dev/null | grep '^T_ratio' > out/exercise3.$dt || exit 1
    done
    r1=$(awk -F= '$1 == "T_ratio" { print $2 }' out/exercise3.1e-4)
    e1=$(awk -F= '$1 == "T_ratio_err" { print $2 }' out/exercise3.1e-4)
    r2=$(awk -F= '$1 == "T_ratio" { print $2 }' out/exercise3.5e-5)
    e2=$(awk -F= '$1 == "T_ratio_err" { print $2 }' out/exercise3.5e-5)
    say "T/kT = $r1 +- $e1 at dt = 1e-4, $r2 +- $e2 at dt = 5e-5"
    q=$(awk -v a="$r1" -v b="$r2" 'BEGIN { print (a - 1) / (b - 1) }')
    eq=$(awk -v a="$r1" -v b="$r2" -v ea="$e1" -v eb="$e2" \
        'BEGIN { x = a - 1; y = b - 1; print (x / y) * sqrt((ea / x) ^ 2 + (eb / y) ^ 2) }')
    # first order: the ratio is 2; the second-order terms seen in the
    # library's runs move it by a few per cent
    verdict "bias ratio" "$q" "$eq" 2 "$(awk -v e="$eq" 'BEGIN { print 4 * e + 0.1 }')" ;;
4)  say "exercise 4: the initial-decay identity in the star liquid (build/gibd_bulk, ~30 s)"
    "$B/gibd_bulk" N=500 steps=40000 out=out/exercise4 2>/dev/null > out/exercise4.txt || exit 1
    grep -E '^(nu_meanfield|nu_initial|initial_decay_identity)' out/exercise4.txt
    v=$(awk -F= '$1 == "initial_decay_identity" { print $2 }' out/exercise4.txt)
    e=$(awk -F= '$1 == "initial_decay_identity_err" { print $2 }' out/exercise4.txt)
    verdict "initial decay rate / friction average" "$v" "$e" 1 "$(awk -v e="$e" 'BEGIN { print 4 * e }')" ;;
*)  say "usage: make exercise N=k [ANSWER=x], k = 1..4 (docs/exercises.md)"; exit 2 ;;
esac
