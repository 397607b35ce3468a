#!/bin/sh
# make test's Python part: builds the package's libraries and runs the
# pytest suite (tests/python) with PYTHON, the interpreter the Makefile
# chose (one that imports numpy); ends in "N passed, N failed" as every
# part does.  Without such an interpreter or pytest it says so and counts
# nothing, so that the C suite runs on its own.
cd "$(dirname "$0")/.."
if [ -z "${PYTHON:-}" ]; then
    echo "python: skipped, no python3 here imports numpy (apt-get install python3-numpy python3-pytest, or PYTHON=...)"
    echo "0 passed, 0 failed"
    exit 0
fi
if ! "$PYTHON" -c 'import pytest' >/dev/null 2>&1; then
    echo "python: skipped, $PYTHON has no pytest (apt-get install python3-pytest)"
    echo "0 passed, 0 failed"
    exit 0
fi
echo "python: $PYTHON ($("$PYTHON" -c 'import sys, numpy; print(sys.version.split()[0], "numpy", numpy.__version__)'))"
${MAKE:-make} --no-print-directory python/hcbd/_hcbd_walled.so python/hcbd/_hcbd_hc.so || { echo "0 passed, 1 failed"; exit 1; }
out=$(mktemp)
"$PYTHON" -m pytest -q -p no:cacheprovider tests/python 2>&1 | tee "$out"
rc=$?
summary=$(tail -n 1 "$out")
rm -f "$out"
p=$(echo "$summary" | sed -n 's/.* \([0-9][0-9]*\) passed.*/\1/p; s/^\([0-9][0-9]*\) passed.*/\1/p' | head -1)
f=$(echo "$summary" | sed -n 's/.* \([0-9][0-9]*\) failed.*/\1/p; s/^\([0-9][0-9]*\) failed.*/\1/p' | head -1)
e=$(echo "$summary" | sed -n 's/.* \([0-9][0-9]*\) error.*/\1/p' | head -1)
sk=$(echo "$summary" | sed -n 's/.* \([0-9][0-9]*\) skipped.*/\1/p' | head -1)
[ -n "$sk" ] && echo "python: $sk skipped (the notebooks need python3-nbclient, python3-ipykernel, python3-nbformat, python3-matplotlib)"
p=${p:-0}; f=$(( ${f:-0} + ${e:-0} ))
[ "$f" = 0 ] && [ "$p" = 0 ] && f=1  # nothing ran: count it as a failure
echo "$p passed, $f failed"
[ "$f" = 0 ]
