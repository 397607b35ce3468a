#!/bin/sh
# The HCBD step read as a walk through hcbd.h: starting at
# hcbd_hc_world_step, each function defined in the header is read once, at
# its first call (depth first, in the order the calls stand in the code;
# a function handed on as a callback counts as called there; one that a
# macro writes, HCBD__PASS(X) and its kin, stands where the macro is used
# and calls what the macro's body calls).  Prints the
# walk and the mean distance in lines between the definitions of
# consecutive functions along it; fails above the limit (issue 64: a step
# reads forward through the file).  make test runs it (tests/docs.sh).
# usage: tests/walk.sh [FILE [START [LIMIT]]]   (hcbd.h hcbd_hc_world_step 600)
file=${1:-hcbd.h}
start=${2:-hcbd_hc_world_step}
limit=${3:-600}
awk -v start="$start" -v limit="$limit" '
function strip(s,    out, i, c, n) {
    # comments (they may span lines: state in incom), strings, characters
    out = ""
    n = length(s)
    for (i = 1; i <= n; i++) {
        c = substr(s, i, 1)
        if (incom) {
            if (c == "*" && substr(s, i + 1, 1) == "/") { incom = 0; i++ }
            continue
        }
        if (c == "/" && substr(s, i + 1, 1) == "*") { incom = 1; i++; continue }
        if (c == "/" && substr(s, i + 1, 1) == "/") break
        if (c == "\"" || c == "\047") {
            q = c
            for (i++; i <= n; i++) {
                c = substr(s, i, 1)
                if (c == "\\") { i++; continue }
                if (c == q) break
            }
            out = out " "
            continue
        }
        out = out c
    }
    return out
}
# a macro that writes functions (HCBD__PASS(X) and its kin): its body and
# the names of the functions it defines, for its uses below
function subst(s, p, a,    out, k) {
    gsub(p "##", a, s)
    out = ""
    while (match(s, "(^|[^A-Za-z0-9_])" p "([^A-Za-z0-9_]|$)")) {
        k = substr(s, RSTART, RLENGTH)
        sub(p, a, k)
        out = out substr(s, 1, RSTART - 1) k
        s = substr(s, RSTART + RLENGTH)
    }
    return out s
}
function expand(name, argstr, s,    na, a, np, pp, k) {
    np = split(mparams[name], pp, /[ \t]*,[ \t]*/)
    na = split(argstr, a, /[ \t]*,[ \t]*/)
    for (k = 1; k <= np && k <= na; k++) s = subst(s, pp[k], a[k])
    return s
}
{
    line = strip($0)
    if (inmac) {
        mbody[inmac] = mbody[inmac] " " line
        if (line ~ /^[ \t]*(HCBD__INLINE|HCBD__NO_SLP|static)[ \t]/ && line ~ /\(/) {
            s = line
            sub(/\(.*/, "", s)
            n = split(s, w, /[^A-Za-z0-9_#]+/)
            mdefs[inmac] = mdefs[inmac] " " w[n]
        }
        if (line !~ /\\[ \t]*$/) inmac = ""
        next
    }
    if (line ~ /^#define HCBD__[A-Z_]+\([A-Za-z_, ]+\)[ \t]*\\[ \t]*$/) {
        s = line
        sub(/^#define /, "", s)
        inmac = s
        sub(/\(.*/, "", inmac)
        sub(/^[^(]*\(/, "", s)
        sub(/\).*/, "", s)
        mparams[inmac] = s
        mbody[inmac] = ""
        mdefs[inmac] = ""
        next
    }
    if (!infn && line ~ /^HCBD__[A-Z_]+\([^()]*\)[ \t]*$/) {
        s = line
        sub(/\(.*/, "", s)
        if (s in mbody) {
            a = line
            sub(/^[^(]*\(/, "", a)
            sub(/\).*/, "", a)
            n = split(expand(s, a, mdefs[s]), w, /[ \t]+/)
            for (k = 1; k <= n; k++)
                if (w[k] != "" && !(w[k] in defline)) { defline[w[k]] = NR; body[w[k]] = expand(s, a, mbody[s]) }
            next
        }
    }
    if (infn) {
        if (line ~ /^}/) { infn = 0; next }
        body[cur] = body[cur] " " line
        next
    }
    if (line ~ /^[A-Za-z_]/ && line ~ /\(/ && line !~ /^#/ && line !~ /;[ \t]*$/ && line !~ /^(typedef|struct|enum|union)[ \t]/) {
        s = line
        sub(/\(.*/, "", s)
        n = split(s, w, /[^A-Za-z0-9_]+/)
        sig = w[n] != "" ? w[n] : w[n - 1]
        sigline = NR
        next
    }
    if (line ~ /^{/ && sig != "") {
        if (!(sig in defline)) { defline[sig] = sigline; cur = sig } else cur = "\001" sig
        infn = 1
        sig = ""
        next
    }
    if (line ~ /;[ \t]*$/ || line ~ /^}/ || line ~ /^#/) sig = ""
}
function visit(f,    n, t, k, g) {
    seen[f] = 1
    order[++norder] = f
    n = split(body[f], t, /[^A-Za-z0-9_]+/)
    for (k = 1; k <= n; k++) {
        g = t[k]
        if (g in defline && !(g in seen)) visit(g)
    }
}
END {
    if (!(start in defline)) { print "walk: " start " is not defined in the file"; print "0 passed, 1 failed"; exit 1 }
    visit(start)
    sum = 0
    for (k = 1; k <= norder; k++) {
        d = k > 1 ? defline[order[k]] - defline[order[k - 1]] : 0
        if (d < 0) d = -d
        sum += d
        if (verbose) printf "%4d %6d %+7d %s\n", k, defline[order[k]], d, order[k]
    }
    mean = norder > 1 ? sum / (norder - 1) : 0
    printf "walk: %s visits %d functions, %.0f lines per jump (limit %d)\n", start, norder, mean, limit
    if (mean <= limit) print "1 passed, 0 failed"; else print "0 passed, 1 failed"
    exit mean <= limit ? 0 : 1
}' verbose="${WALK_VERBOSE:-0}" "$file"
