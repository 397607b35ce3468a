#!/bin/sh
# The examples as a user drives them: every example refuses an unknown key
# and a bad value with exit code 2 and a message naming the key, and
# first_step's quick run agrees with its theory within the errors it
# prints.  Usage: tests/examples.sh BUILD_DIR.  Ends with "N passed, N failed".
B=${1:-build}
export HCBD_EXERCISE_ARGS=N=500
pass=0
fail=0
ok() { pass=$((pass + 1)); echo "  ok   $1"; }
bad() { fail=$((fail + 1)); echo "  FAIL $1"; }

# expect NAME CMD... : exit code 2 and NAME in the message
expect() {
    name=$1
    shift
    msg=$("$@" 2>&1 >/dev/null)
    rc=$?
    if [ $rc -eq 2 ] && printf '%s' "$msg" | grep -q -- "$name"; then ok "$* -> rc 2, names $name"
    else bad "$* -> rc $rc, message: $(printf '%s' "$msg" | head -n 1)"; fi
}

for e in first_step gibd_bulk shear_flow channel_flow hcbd_fluid hcbd_polymer; do
    expect bogus "$B/$e" bogus=1
    expect seed "$B/$e" seed=-3
done
expect N "$B/first_step" N=abc
expect tau "$B/first_step" tau=0
for e in gibd_bulk shear_flow channel_flow; do
    expect dt "$B/$e" dt=abc
    expect threads "$B/$e" threads=x
done
expect steps "$B/gibd_bulk" steps=12.5
for key in rho eta nbar P0 T dt sigma h; do expect $key "$B/hcbd_fluid" $key=-1; done

# first_step: T within 4 errors of kT; nu within 4 errors plus 0.5 % (the
# deficit docs/MODEL.md 12 records at this tau) of the mean field at k.
out=$("$B/first_step" N=500 2>&1)
echo "$out" | sed 's/^/    /'
if echo "$out" | awk '
    /^temperature/ { T = $2; eT = $4; kT = $7; sub(/\)/, "", kT) }
    /^viscosity/ { nu = $2; en = $4; nk = $NF; sub(/\)/, "", nk) }
    END { d = T - kT; if (d < 0) d = -d; g = nu - nk; if (g < 0) g = -g;
          exit !(T != "" && nu != "" && d < 4 * eT && g < 4 * en + 0.005 * nk) }'
then ok "first_step N=500 agrees with kT and the mean field at k"
else bad "first_step N=500: temperature or viscosity off its theory"; fi

# the exercise checker (on first_step N=500): exercises 1 and 2 within tolerance, a right and a
# wrong answer told apart, an unknown exercise refused
for n in 1 2; do
    if examples/exercise.sh "$B" $n >/dev/null; then ok "exercise $n: the run is within its tolerance"
    else bad "exercise $n: the checker says the run is outside its tolerance"; fi
done
right=$(examples/exercise.sh "$B" 1 | sed -n 's/^measured .* = \([^ ]*\) +-.*/\1/p')
if examples/exercise.sh "$B" 1 "$right" >/dev/null && ! examples/exercise.sh "$B" 1 1.5 >/dev/null
then ok "exercise 1: answer $right accepted, 1.5 refused"
else bad "exercise 1: the checker does not tell answer $right from 1.5"; fi
examples/exercise.sh "$B" 99 >/dev/null 2>&1
if [ $? -eq 2 ]; then ok "exercise 99 refused"; else bad "exercise 99 not refused"; fi

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
