#!/bin/sh
# make test, part "docs": the header's banners against its CONTENTS block
# (tests/banners.sh), the HCBD step's walk through the header (tests/walk.sh,
# at most 600 lines per jump), every program the docs quote (build/NAME in
# README.md and docs/*.md) is one make knows how to build, so that a quoted
# command cannot outlive its program (build/logs, build/prefix and
# build/lammps are folders that make test and make lammps create), and
# every mutant's pattern (tests/mutants/mutants.txt) is found, and no
# function in hcbd.h is longer than 80 lines.
# Ends with "N passed, N failed".
cd "$(dirname "$0")/.." || exit 1
out=$(tests/banners.sh hcbd.h)
echo "$out"
last=$(echo "$out" | tail -n 1)
passed=${last%% passed*}
failed=${last#*passed, }
failed=${failed%% failed*}
# the HCBD step reads forward through the header (tests/walk.sh)
if tests/walk.sh hcbd.h | head -n 1; then passed=$((passed + 1)); else failed=$((failed + 1)); fi
progs=$(grep -ohE '(^|[ `(])(\./)?build/[A-Za-z0-9_]+([^A-Za-z0-9_/.]|$)' README.md docs/*.md |
    sed -E 's#^[ `(]?(\./)?##; s#^(build/[A-Za-z0-9_]+).*#\1#' | sort -u)
for p in $progs; do
    case "$p" in build/logs | build/prefix | build/lammps) continue ;; esac
    if make -n "$p" >/dev/null 2>&1; then
        passed=$((passed + 1))
    else
        echo "docs: the docs quote $p, which make cannot build"
        failed=$((failed + 1))
    fi
done
echo "docs: $(echo "$progs" | wc -w) programs quoted in README.md and docs/"
# no function in the header is longer than 80 lines (issue 64): from the
# line that names it to its closing brace in column 0
long=$(awk '
    /^[A-Za-z_].*\(/ && !/;[ \t]*$/ && !/^(typedef|struct|enum|union|#)/ { sig = $0; at = NR; next }
    /^\{/ && sig != "" { name = sig; start = at; infn = 1; sig = ""; next }
    infn && /^\}/ { if (NR - start + 1 > 80) { sub(/\(.*/, "", name); print "docs: " name " is " NR - start + 1 " lines (limit 80)" }
                    infn = 0; next }
    !infn && /;[ \t]*$/ { sig = "" }' hcbd.h)
if [ -z "$long" ]; then
    passed=$((passed + 1))
else
    echo "$long"
    failed=$((failed + 1))
fi
# every injected error of make mutants still finds its text exactly once:
# code rewritten around a pattern would otherwise drop that mutant from
# the check unseen until make mutants runs (it is not part of make test)
bad=$(awk -F'\t' '
    FNR == NR { src = src $0 "\n"; next }
    /^#/ || NF < 4 { next }
    { old = $3; gsub(/\\n/, "\n", old); n = 0; s = src
      while ((i = index(s, old)) > 0) { n++; s = substr(s, i + 1) }
      if (n != 1) print "docs: mutant " $1 "'"'"'s pattern occurs " n " times in hcbd.h" }' \
    hcbd.h tests/mutants/mutants.txt)
if [ -z "$bad" ]; then
    passed=$((passed + 1))
else
    echo "$bad"
    failed=$((failed + 1))
fi
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
