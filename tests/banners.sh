#!/bin/sh
# The header's ">>" banners against its CONTENTS block (make test, part
# "docs"): the same banners in the same order (each CONTENTS title opens its
# banner's first line), and every public function (a hcbd_ name declared or
# defined at the start of a line) under a banner one of the prefixes its
# CONTENTS line names in [ ], each prefix used at least once.  So a banner
# cannot be moved, renamed or filled with another concern's API unnoticed.
# And each public function stands with its object (the NAMING paragraph's:
# hcbd_<object>_..., the longest object that fits): under a banner whose
# CONTENTS line claims the object whole (the prefix hcbd_<object>_), or a
# group for that object alone (every prefix of the line that belongs to an
# object not claimed whole belongs to this one).  Functions of numbers
# alone belong to no object.
# Prints one line per disagreement and ends with "N passed, N failed" (one
# check per banner, plus one for the banner count).
h=${1:-hcbd.h}
awk '
function trim(t) { sub(/^[ \t]+/, "", t); sub(/[ \t]+$/, "", t); return t }
# the object of a name: the longest of the objects NAMING lists
function obj(f,   k, best) {
    best = ""
    for (k in OBJ) if (index(f, "hcbd_" k "_") == 1 && length(k) > length(best)) best = k
    return best
}
BEGIN {
    n = split("world world_def hc_world hc_world_def params hc_params hc_si rdf mtcorr msd profile slabs " \
              "rng noise walls gibd_coef hc_coef star_coef limits", L, " ")
    for (i = 1; i <= n; ++i) OBJ[L[i]] = 1
}
# every object above is named in the NAMING paragraph
/^   NAMING/ { innm = 1; next }
innm && /^   [A-Z][A-Z ]+$/ { innm = 0 }
innm { naming = naming " " $0 }
# the CONTENTS block: from its heading to the next heading of the header comment
/^   CONTENTS/ { inc = 1; next }
inc && /^   [A-Z][A-Z ]+$/ { inc = 0 }
inc && /^     >>/ {
    line = $0; sub(/^     >>/, "", line)
    nc++; pre[nc] = ""
    if (index(line, "[")) {
        title[nc] = trim(substr(line, 1, index(line, "[") - 1))
        rest = substr(line, index(line, "[") + 1)
        if (index(rest, "]")) { pre[nc] = substr(rest, 1, index(rest, "]") - 1); open = 0 }
        else { pre[nc] = rest; open = 1 }
    } else { title[nc] = trim(line); open = 0 }
    next
}
inc && open {
    rest = $0
    if (index(rest, "]")) { pre[nc] = pre[nc] " " substr(rest, 1, index(rest, "]") - 1); open = 0 }
    else pre[nc] = pre[nc] " " rest
    next
}
/^\/\* >>/ {
    t = $0; sub(/^\/\* >>/, "", t); sub(/\*\/.*$/, "", t); sub(/[- ]+$/, "", t)
    nb++; btext[nb] = t; bline[nb] = NR; nf[nb] = 0
    next
}
nb && /^[A-Za-z]/ && !/^(typedef|static|return|HCBD)/ {
    if (match($0, /hcbd_[a-z0-9][a-z0-9_]*[ ]*\(/)) {
        f = substr($0, RSTART, RLENGTH); sub(/[ ]*\($/, "", f)
        nf[nb]++; fn[nb, nf[nb]] = f; fl[nb, nf[nb]] = NR
    }
}
END {
    pass = 0; fail = 0
    if (nc == nb && nb > 0) pass++
    else { fail++; printf "banners: %d banners in %s, %d lines in CONTENTS\n", nb, FILENAME, nc }
    n = nb > nc ? nb : nc
    for (i = 1; i <= n; ++i) {
        bad = 0
        if (i > nb || i > nc) {
            if (i > nb) printf "banners: CONTENTS line \"%s\" has no banner\n", title[i]
            else printf "banners: banner \"%s\" (line %d) is not in CONTENTS\n", btext[i], bline[i]
            fail++; continue
        }
        if (index(btext[i], title[i]) != 1) {
            printf "banners: banner %d (line %d) reads \"%s\", CONTENTS says \"%s\"\n", i, bline[i], btext[i], title[i]
            bad = 1
        }
        np = split(pre[i], P, /[ \t]+/)
        delete used
        for (k = 1; k <= nf[i]; ++k) {
            ok = 0
            for (q = 1; q <= np; ++q)
                if (P[q] != "" && index(fn[i, k], P[q]) == 1) { ok = 1; used[q] = 1 }
            if (!ok) {
                printf "banners: %s (line %d) sits under \">>%s\", whose CONTENTS line does not name it\n", fn[i, k], fl[i, k], title[i]
                bad = 1
            }
        }
        for (q = 1; q <= np; ++q)
            if (P[q] != "" && !used[q]) {
                printf "banners: \">>%s\" names %s, but holds no such function\n", title[i], P[q]
                bad = 1
            }
        if (bad) fail++; else pass++
    }
    # each function with its object
    for (k in OBJ) {
        if (!match(naming, "[^a-z_]" k "[^a-z_]")) { printf "banners: object %s is not in the NAMING paragraph\n", k; fail++ }
    }
    for (i = 1; i <= nb && i <= nc; ++i) {
        np = split(pre[i], P, /[ \t]+/); claim = " "; part = " "; npart = 0
        for (q = 1; q <= np; ++q) if (P[q] != "" && (o = obj(P[q])) != "" && P[q] == "hcbd_" o "_") claim = claim o " "
        for (q = 1; q <= np; ++q) {
            if (P[q] == "" || (o = obj(P[q])) == "" || index(claim, " " o " ")) continue
            if (!index(part, " " o " ")) { part = part o " "; npart++ }
        }
        bad = 0
        for (k = 1; k <= nf[i]; ++k) {
            o = obj(fn[i, k])
            if (o == "" || index(claim, " " o " ") || (npart == 1 && index(part, " " o " "))) continue
            printf "banners: %s (line %d, object %s) sits under \">>%s\", which neither claims %s (hcbd_%s_) nor is a group of it alone%s\n", fn[i, k], fl[i, k], o, title[i], o, o, (npart > 1 ? " (its CONTENTS line mixes objects)" : "")
            bad = 1
        }
        if (bad) { fail++; pass-- }
    }
    printf "banners: %d banners, %d CONTENTS lines\n", nb, nc
    printf "%d passed, %d failed\n", pass, fail
    exit fail != 0
}' "$h"
