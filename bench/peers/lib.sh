# Shared by the work-precision scripts of bench/peers (sourced, bash):
# which lmp to run and how to name the machine in their outputs.

# find_lmp STYLE: sets LMP_BIN to the first of $LMP, /tmp/peer/build/lmp
# (../shared/PEERS.md: -O3 -march=native, no MPI), lmp on the PATH and
# build/lammps/lmp (make lammps) whose `lmp -h` lists STYLE; "" if none
find_lmp() {
    local cand
    LMP_BIN=""
    for cand in "${LMP:-}" /tmp/peer/build/lmp "$(command -v lmp 2>/dev/null)" "$root/build/lammps/lmp"; do
        [ -n "$cand" ] && command -v "$cand" >/dev/null 2>&1 || continue
        if "$cand" -h 2>/dev/null | grep -qw "$1"; then LMP_BIN=$(command -v "$cand"); return; fi
    done
}

# machine_names: sets lmp_version, cpu (the model name) and avx
machine_names() {
    lmp_version=$("$LMP_BIN" -nocite -log none -in /dev/null 2>/dev/null | head -n 1 | tr -d '\r')
    cpu=$(lscpu 2>/dev/null | awk -F: '/Model name/ {gsub(/^ +/, "", $2); print $2; exit}')
    avx=$(grep -qw avx512f /proc/cpuinfo 2>/dev/null && echo "AVX-512" || echo "AVX2 or less")
}

# lmp_cost LOG DT STEPS: seconds per unit of simulated time of a LAMMPS run
# (loop time less its "Output"), nan when the run did not finish
lmp_cost() {
    if grep -q "^Loop time" "$1"; then
        awk -v dt="$2" -v s="$3" '/^Loop time of/ {t = $4} /^Output/ {o = $3}
            END {printf "%.6g", (t - o) / (s * dt)}' "$1"
    else
        echo nan # LAMMPS stopped (lost atoms): unstable at this step
    fi
}

# median_rounds RAW: the lines "k1 k2 k3 dt cost a b" of all rounds, one
# per key and step, sorted by key and then dt: the median cost over the
# rounds (nan if any round's is), a and b from the first (they do not
# change between rounds: every run is deterministic)
median_rounds() {
    sort -k1,1 -k2,2 -k3,3 -k4,4g "$1" | awk '
    function flush(   i, j, v, med) {
        if (key == "") return
        for (i = 2; i <= nk; ++i) { v = c[i]; for (j = i - 1; j >= 1 && c[j] > v; --j) c[j + 1] = c[j]; c[j + 1] = v }
        med = (nk % 2) ? c[(nk + 1) / 2] : 0.5 * (c[nk / 2] + c[nk / 2 + 1])
        print f1, f2, f3, dt, (bad ? "nan" : med), a, b
        delete c; nk = 0; bad = 0
    }
    { k = $1 " " $2 " " $3 " " $4
      if (k != key) { flush(); key = k; f1 = $1; f2 = $2; f3 = $3; dt = $4; a = $6; b = $7 }
      if ($5 == "nan") bad = 1; else c[++nk] = $5 + 0 }
    END { flush() }'
}
