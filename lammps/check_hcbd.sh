# shellcheck shell=bash disable=SC2154
# fix hcbd's part of make test-lammps, sourced by lammps/check.sh (its
# lmp, MPI, RANKS, t, ok, bad, same_bits and within): hcbd_quick (bad
# inputs, atom by atom against hcbd's own 2018 world, lammps/hc_ref.c),
# hcbd_bits (the same bits on RANKS) and hcbd_stats (the fluid's
# temperature against hcbd's world's, a solution's viscosity against
# hcbd_polymer's).  The scene is lammps/in.hcbd_compare:
# 512 fluid blobs at nbar = 0.5 in a 10.08^3 box, every coefficient away
# from 1 (rho 0.65, eta 0.2, P0 1.5, h 1.1, kT 1.7, dt 0.02, so dt/dt_visc
# = 0.041 and dt c_s / h = 0.073), and with npoly=60, 60 polymers (xi 30,
# sigma 0.6, rc 2, alpha 200, tau_lambda 0.5, p 30, n_max 5, chi 0.3).
hplug=$B/plugin/hcbdplugin.so
hin=$root/lammps/in.hcbd_compare
# hc_ref's parameters, as hin's defaults
hcoef="dt=0.02 rho=0.65 nbar=0.5 eta=0.2 P0=1.5 h=1.1 kT=1.7 nf=512 xi=30 sigma=0.6 rc=2 alpha=200 tau_lambda=0.5 p=30 n_max=5 chi=0.3"
cc -O2 -std=c99 -DHCBD_MODEL=HCBD_MODEL_HCBD -I"$root" -o "$t/hc_ref" "$root/lammps/hc_ref.c" -lm

hcbd_quick() {
    local name edit out dx dv n
    if [ ! -f "$hplug" ]; then bad "fix hcbd: no $hplug (make lammps builds it)"; return; fi
    # atom by atom: from the same atoms (LAMMPS's after 50 steps off the
    # jittered lattice, every pair variable at lambda_eq), 20 steps of fix
    # hcbd and of hcbd's world end in the same atoms to round-off (the
    # fixed-point sums resolve 3e-11 of a pair force); the atoms move by
    # 0.6-5 and the fluid's velocities change by 1.7-10, sqrt(kT/m) = 1.14,
    # so an error of 1e-3 in any term would show by orders of magnitude
    # hmatch START END REF GDOT: LAMMPS's END in hcbd's frame (END.c) against
    # hc_ref's REF and START; sets the caller's L, dx dv n (END - REF) and
    # mx mv (END - START)
    hmatch() {
        L=$(awk 'NR == 6 { printf "%.17g", $2 - $1 }' "$1")
        awk -v vle="$(awk -v g="$4" -v L="$L" 'BEGIN { printf "%.17g", g * L }')" -f "$root/lammps/le_canon.awk" \
            "$2" > "$2.c"
        read -r dx dv n < <(awk -v L="$L" -f "$root/lammps/maxdiff.awk" "$2.c" "$3")
        read -r mx mv _ < <(awk -v L="$L" -f "$root/lammps/maxdiff.awk" "$1" "$2.c")
    }
    hcompare() { # name ranks fluct gdot gx [npoly substeps coupling steps every pair lattice rp]
        local name=$1 np=$2 fluct=$3 gdot=$4 gx=$5 npoly=${6:-0} sub=${7:-1} cpl=${8:-shepard} ns=${9:-20}
        local every=${10:-1} pair=${11:-euler} lat=${12:-8} rp=${13:-0} skin=0.5 L dx dv n mx mv procs="* * *"
        # hxv, hxc: another scene's LAMMPS variables and hc_ref's parameters;
        # hxs, hxu: its length and velocity scales (this scene's: 1)
        local co=${hxc:-$hcoef} sx=${hxs:-1} su=${hxu:-1}
        local nfl=$((lat * lat * lat))
        [ "$every" -gt 1 ] && skin=2
        [ "$pair" = exact ] && procs="1 * *"
        if ! $MPI -np "$np" "$lmp" -in "$hin" -var plugin "$hplug" -var fluct "$fluct" -var gdot "$gdot" -var gx "$gx" \
            -var npoly "$npoly" -var substeps "$sub" -var coupling "$cpl" -var steps $((ns * sub)) \
            -var every "$every" -var skin "$skin" -var pair "$pair" -var ns "$lat" -var procs "$procs" \
            -var rp "$rp" -var dir "$root/lammps" ${hxv:-} \
            -var start "$t/h0.txt" -var end "$t/h1.txt" -var stressf "$t/hs.txt" -log none -screen none \
            > /dev/null 2>&1; then
            bad "fix hcbd, $name: LAMMPS failed"; return
        fi
        # shellcheck disable=SC2086
        if ! "$t/hc_ref" "$t/h0.txt" "$t/hr.txt" "$ns" $co nf="$nfl" seed=1 fluct="$fluct" gdot="$gdot" gx="$gx" \
            substeps="$sub" coupling="$cpl" pair="$pair" $([ "$rp" != 0 ] && echo "rp=1 gx=$rp") > "$t/hrs.txt"; then
            bad "fix hcbd, $name: hc_ref failed"; return
        fi
        # sheared: LAMMPS's atoms in hcbd's frame (a polymer's velocity is its
        # drift velocity of the last polymer step, in hc_ref too)
        hmatch "$t/h0.txt" "$t/h1.txt" "$t/hr.txt" "$gdot"
        if [ "$npoly" -gt 0 ]; then # the polymers' own largest move
            awk -v nf="$nfl" '$1 > nf' "$t/h0.txt" > "$t/hp0.txt"; awk -v nf="$nfl" '$1 > nf' "$t/h1.txt.c" > "$t/hp1.txt"
            read -r mp _ < <(awk -v L="$L" -f "$root/lammps/maxdiff.awk" "$t/hp0.txt" "$t/hp1.txt")
        else mp=$sx; fi
        echo "    fix hcbd, $name: largest |x - x_hcbd| $dx, |v - v_hcbd| $dv (moved by $mx, $mv; polymers by $mp)"
        if awk -v dx="$dx" -v dv="$dv" -v mx="$mx" -v mv="$mv" -v mp="$mp" -v n="$n" -v N=$((nfl + npoly)) -v sx="$sx" -v su="$su" \
            'BEGIN { exit !(n == N && dx < 1e-9 * sx && dv < 1e-8 * su && mx > 0.3 * sx && mv > su && mp > 0.3 * sx) }'; then
            ok "fix hcbd, $name: $ns steps = hcbd's world, atom by atom"
        else bad "fix hcbd, $name: fix hcbd and hcbd's world part: |dx| $dx, |dv| $dv"; fi
        # the stress vector (stress yes), the run's mean over its polymer
        # steps, = hcbd_hc_world_stress_read's ten columns to 1e-9 of the largest
        if awk -v a="$(cat "$t/hs.txt")" -v b="$(cat "$t/hrs.txt")" 'BEGIN {
            n = split(a, x); if (n != 10 || split(b, y) != 10) exit 1
            for (k = 1; k <= n; ++k) { m = y[k] < 0 ? -y[k] : y[k]; if (m > big) big = m }
            for (k = 1; k <= n; ++k) { d = x[k] - y[k]; if (d < 0) d = -d; if (!(d <= 1e-9 * big)) exit 1 }
            exit !(big > 0) }'; then
            ok "fix hcbd, $name: the stress split (f_ID) = hcbd_hc_world_stress_read's"
        else bad "fix hcbd, $name: stress $(cat "$t/hs.txt"), hcbd's $(cat "$t/hrs.txt")"; fi
    }
    hcompare "fluid, Euler pairs with fluctuations, 1 rank" 1 yes 0 0
    hcompare "fluid, Euler pairs without fluctuations, 2 ranks" 2 no 0 0
    hcompare "fluid, Euler pairs with fluctuations, 4 ranks" 4 yes 0 0
    hcompare "fluid, sheared (gdot = 0.8), 2 ranks" 2 yes 0.8 0
    hcompare "fluid without fluctuations, sheared (gdot = 0.5), 4 ranks" 4 no 0.5 0
    hcompare "fluid, body force (gx = 3), 2 ranks" 2 yes 0 3
    hcompare "60 polymers, fluctuations, 1 rank" 1 yes 0 0 60
    hcompare "60 polymers, no fluctuations, raw coupling, 2 ranks" 2 no 0 0 60 1 raw
    hcompare "60 polymers, sheared (gdot = 0.8), 4 ranks" 4 yes 0.8 0 60
    hcompare "60 polymers, 3 sub-steps, 2 ranks" 2 yes 0 0 60 3
    hcompare "60 polymers, 2 sub-steps, raw coupling, body force (gx = 0.5), 4 ranks" 4 yes 0 0.5 60 2 raw
    # the box's tilt passes half its edge at the 31st fluid step: fix
    # deform flips it (the atoms past y's edge wrapped by fix hcbd first)
    hcompare "60 polymers, sheared through a box flip, 3 sub-steps, 2 ranks" 2 yes 0.8 0 60 3 shepard 20
    # lists checked every 4th step (skin 2): polymers stay past y's edge for
    # steps before LAMMPS wraps them, and move in their image's frame
    hcompare "60 polymers, sheared, lists every 4 steps, 2 ranks" 2 yes 0.8 0 60 1 shepard 20 4
    # pair exact, hcbd's exact fluid sweep in its order: the 8^3 lattice
    # has one block (owners by fine cell and tag); the 11^3 lattice (13.86^3)
    # 6^3 blocks in 27 colours, split between ranks along y and z
    # (processors 1 * *), and sheared past a tilt of 0.32 the x blocks give
    # way to 10 in 5 colours (gdot 0.8 would move its polymers too far)
    hcompare "fluid, exact sweep with fluctuations, one block, 1 rank" 1 yes 0 0 0 1 shepard 20 1 exact
    hcompare "60 polymers, exact sweep, 6^3 blocks, 2 ranks" 2 yes 0 0 60 1 shepard 20 1 exact 11
    hcompare "60 polymers, exact sweep without fluctuations, raw coupling, 4 ranks" 4 no 0 0 60 1 raw 20 1 exact 11
    hcompare "60 polymers, exact sweep, sheared (gdot = 0.5) through a box flip and new blocks, 3 sub-steps, 2 ranks" \
        2 yes 0.5 0 60 3 shepard 20 1 exact 11
    hcompare "60 polymers, exact sweep, 2 sub-steps, body force (gx = 0.5), lists every 4 steps, 4 ranks" \
        4 yes 0 0.5 60 2 shepard 20 4 exact 11
    # the reverse-Poiseuille force of lammps/in.hcbd_channel (lammps/in.hcbd_rp_force) = hcbd's world's
    hcompare "60 polymers, exact sweep, reverse Poiseuille (g = 3), 2 ranks" 2 yes 0 0 60 1 shepard 20 1 exact 11 3
    # through a restart file: 10 steps, the restart, 10 more (the pair
    # variables, 0.4 tau_lambda away from lambda_eq by then, come from the
    # file) = hcbd's world's 20 steps from the same atoms, atom by atom
    hrestart() { # name ranks gdot pair lattice
        local name=$1 np=$2 gdot=$3 pair=$4 lat=$5 procs="* * *" L dx dv n mx mv
        local nfl=$((lat * lat * lat)) a="-var plugin $hplug -var npoly 60 -var gdot $gdot -var pair $pair -var ns $lat"
        [ "$pair" = exact ] && procs="1 * *"
        # shellcheck disable=SC2086
        if ! { $MPI -np "$np" "$lmp" -in "$hin" $a -var procs "$procs" -var steps 10 -var start "$t/hz0.txt" \
                -var save "$t/hz.rst" -log none -screen none && $MPI -np "$np" "$lmp" -in "$hin" $a -var procs "$procs" \
                -var from restart -var restart "$t/hz.rst" -var steps 10 -var end "$t/hz2.txt" -log none -screen none
            } > /dev/null 2>&1; then bad "fix hcbd, $name: LAMMPS failed"; return; fi
        # shellcheck disable=SC2086
        "$t/hc_ref" "$t/hz0.txt" "$t/hzr.txt" 20 $hcoef nf="$nfl" seed=1 fluct=yes gdot="$gdot" pair="$pair" > /dev/null
        hmatch "$t/hz0.txt" "$t/hz2.txt" "$t/hzr.txt" "$gdot"
        echo "    fix hcbd, $name: largest |x - x_hcbd| $dx, |v - v_hcbd| $dv (moved by $mx, $mv)"
        if awk -v dx="$dx" -v dv="$dv" -v mx="$mx" -v mv="$mv" -v n="$n" -v N=$((nfl + 60)) \
            'BEGIN { exit !(n == N && dx < 1e-9 && dv < 1e-8 && mx > 0.3 && mv > 1) }'; then
            ok "fix hcbd, $name: 10 + 10 steps through a restart file = hcbd's world's 20, atom by atom"
        else bad "fix hcbd, $name: through a restart file: |dx| $dx, |dv| $dv ($n atoms)"; fi
    }
    hrestart "60 polymers, Euler pairs, sheared (gdot = 0.8), 2 ranks" 2 0.8 euler 8
    hrestart "60 polymers, exact sweep, 6^3 blocks, 4 ranks" 4 0 exact 11
    # Table I's own numbers (lammps/in.hcbd_table1's reduced units: sigma,
    # kT, 1 us; xi 6e8, tau_lambda 1e6, a fluid blob's mass 3.2e9, so
    # sqrt(kT/m) = 1.8e-5): 20 polymer steps of 8 fluid steps move the atoms
    # by 0.05-0.2 and the fluid's velocities by 6e-5-2e-4, hence the
    # scales hxs = 0.1, hxu = 3e-5.  The sheared cases (Wi = 10 and 3) have
    # polymers crossing y's edge inside a polymer step
    local t1="rho=7.54476e+08 nbar=0.238738 eta=3.0179e+07 P0=3923.28 h=2 kT=1 xi=6.03581e+08 sigma=1 rc=2.5 alpha=500"
    t1="$t1 tau_lambda=1e6 p=300000 n_max=2387.32 chi=0.5 dt=12.5"
    local t1v="-var ${t1// / -var }" t1c="$t1"
    t1v=${t1v//=/ }
    hxv="$t1v -var pairs 96" hxc=$t1c hxs=0.1 hxu=3e-5 hcompare \
        "Table I, C = 2.5 C*, exact sweep without fluctuations, 8 sub-steps, sheared (Wi = 10), 1 rank" \
        1 no 1e-5 0 540 8 shepard 20 1 exact 6
    hxv="$t1v -var pairs 96" hxc=$t1c hxs=0.1 hxu=3e-5 hcompare \
        "Table I, C = 2.5 C*, Euler pairs with fluctuations, 8 sub-steps, 2 ranks" 2 yes 0 0 540 8 shepard 20 1 euler 6
    hxv="$t1v -var pairs 192" hxc=$t1c hxs=0.1 hxu=3e-5 hcompare \
        "Table I, C = 5 C*, Euler pairs with fluctuations, raw coupling, 8 sub-steps, sheared (Wi = 3), 4 ranks" \
        4 yes 3e-6 0 1080 8 raw 20 1 euler 6
    hxv="$t1v -var pairs 96" hxc=$t1c hxs=0.1 hxu=3e-5 hcompare \
        "Table I, C = 2.5 C*, 6048 blobs, exact sweep with fluctuations, 8 sub-steps, sheared (Wi = 10), 2 ranks" \
        2 yes 1e-5 0 4320 8 shepard 20 1 exact 12
    # the channel input itself runs (tau_lambda scaled to 1e4, Wi = 0.1, one
    # tau_lambda of start-up and one of profile): the fluid and the polymers
    # move along +x in the upper half and along -x in the lower
    if "$lmp" -in "$root/lammps/in.hcbd_channel" -var plugin "$hplug" -var dir "$root/lammps" -var tau 1e4 \
        -var alpha 5e4 -var Wi 0.1 -var startup 1 -var blocks 1 -var out "$t/hch" -log "$t/hch.log" -screen none \
        > /dev/null 2>&1 && awk 'FNR == 1 { f++ } NF == 4 && $1 ~ /^[0-9]+$/ { s = $2 < 0.5 ? -1 : 1; if ($4 * s > 0) ok[f]++; n[f]++ }
        END { exit !(n[1] == 12 && ok[1] == 12 && n[2] == 12 && ok[2] >= 11) }' "$t/hch.f" "$t/hch.p"; then
        ok "lammps/in.hcbd_channel: fluid and polymers flow along +-g in the two halves"
    else bad "lammps/in.hcbd_channel: $(grep ERROR "$t/hch.log" | head -n 1) (profiles $t/hch.f, $t/hch.p)"; fi
    # its force's set point: the fluid alone (C = 0) in a channel 38.7 sigma
    # wide at gdot = 5e-6 / us flows with the amplitude gdot Ly / 8 of the
    # Newtonian profile of its viscosity, within the kernel's smoothing of the
    # force's sign change at the planes (+2.0-2.4 % at this width, +4.5 % at
    # half of it: bench/results/table2_rp_fluid); 10 % off in g would read
    # 0.93 or 1.13.  (create_atoms numbers the lattice by rank, so 1 and 2
    # ranks run other tags, another sweep order: 1.0244 and 1.0257)
    local amp
    if $MPI -np 2 "$lmp" -in "$root/lammps/in.hcbd_channel" -var plugin "$hplug" -var dir "$root/lammps" -var C 0 \
        -var eta0 1 -var ny 24 -var tau 1000 -var Wi 0.005 -var startup 10 -var blocks 20 -var tevery 80 -var out "$t/hcf" \
        -log "$t/hcf.log" -screen none > /dev/null 2>&1; then
        amp=$(awk -v g=5e-6 -f "$root/lammps/rp_amplitude.awk" "$t/hcf.traj" | awk '$1 > 1600 { s += $2; n++ }
            END { if (n) printf "%.4f", s / n }')
    fi
    echo "    lammps/in.hcbd_channel, the fluid alone: amplitude ${amp:-none} of the Newtonian profile's"
    if awk -v a="${amp:-0}" 'BEGIN { exit !(a > 1 && a < 1.05) }'; then
        ok "lammps/in.hcbd_channel: the fluid alone flows with its Newtonian amplitude within the kernel's smoothing ($amp)"
    else bad "lammps/in.hcbd_channel: the fluid alone: amplitude ${amp:-none} of gdot Ly / 8 ($(grep ERROR "$t/hcf.log" | head -n 1))"; fi
    # bad arguments and settings: LAMMPS stops with an error naming them
    hexpect() {
        name=$1 edit=$2
        sed "$edit" "$hin" > "$t/hbad.in"
        out=$("$lmp" -in "$t/hbad.in" -var plugin "$hplug" -var warm 2 -var steps 2 -log none 2>&1)
        if printf '%s' "$out" | grep -q "ERROR.*$name"; then ok "fix hcbd: bad input -> error names $name"
        else bad "fix hcbd: bad input ($edit): $(printf '%s' "$out" | grep ERROR | head -n 1)"; fi
    }
    local fl='s/^fix  *g all hcbd .*/fix g all hcbd'
    local tail_='rho ${rho} nbar ${nbar} eta ${eta} P0 ${P0} h ${h} kT ${kT}/'
    hexpect "eta = -1" "$fl eta -1 rho \${rho} nbar \${nbar} P0 \${P0} h \${h} kT \${kT}/"
    hexpect "rho = x is not a number" "$fl rho x/"
    hexpect "unknown keyword bogus" "$fl bogus 1 $tail_"
    hexpect "keyword seed has no value" "$fl $tail_; s/kT \${kT}\$/kT \${kT} seed/"
    hexpect "fluct = maybe is not yes or no" "$fl fluct maybe $tail_"
    hexpect "pair = bogus is not exact or euler" "$fl pair bogus $tail_"
    hexpect "pair exact needs an atom map" "s/^atom_modify .*//; s/^variable  *pair index euler/variable pair index exact/"
    hexpect "seed = -3 is not an unsigned integer" "$fl seed -3 $tail_"
    hexpect "comm_modify vel yes" "/^comm_modify/d"
    hexpect "needs newton on" "s/^units .*/&\nnewton off/"
    hexpect "group must be all" "s/^fix  *g all hcbd/group half id 1:10\nfix g half hcbd/"
    hexpect "has mass .* rho / nbar" "s/^pair_style .*/mass 1 2.0\n&/"
    hexpect "must reach 2 h" 's/^pair_style .*/pair_style zero 2.0/'
    hexpect "units real" "s/^units .*/units real/"
    hexpect "2 atom types" "s/^create_box .*/create_box 2 box/; s/^mass .*/mass * \$(v_rho\/v_nbar)/"
    hexpect "box edge L\\[0\\] = .* is shorter" "s/^variable  *ns index 8/variable ns index 4/"
    # a lattice whose spacing exceeds 2 h: every blob alone, n = w(0) = 4 nbar
    hexpect "density n/nbar outside" "s/^variable  *ns index 8/variable ns index 4/; s/^variable  *nbar index 0.5/variable nbar index 0.06/"
    hexpect "moved more than h/2 in one step" "s/^variable  *dt index 0.02/variable dt index 0.2/"
    hexpect "may only shear" "s/^fix  *g all hcbd .*/&\nfix grow all deform 1 x scale 1.01/"
    hexpect "define it before fix deform" "s/^fix  *g all hcbd/fix early all deform 1 xy erate 0.1 remap v\n&/; s/^if \"\\\${gdot} == 0\" then \"region/if \"1 == 0\" then \"region/"
    # pair exact on two ranks: x must not be split, nor an axis without blocks
    hranks() {
        out=$($MPI -np 2 "$lmp" -in "$hin" -var plugin "$hplug" -var pair exact -var warm 2 -var steps 2 -log none \
            -var ns "$2" -var procs "$3" 2>&1)
        if printf '%s' "$out" | grep -q "ERROR.*$1"; then ok "fix hcbd: pair exact on processors $3 -> error names $1"
        else bad "fix hcbd: pair exact on processors $3: $(printf '%s' "$out" | grep ERROR | head -n 1)"; fi
    }
    hranks "needs processors 1 \* \*" 11 "2 1 1"
    hranks "2 ranks along y needs the sweep's blocks" 8 "1 2 1"
    # with polymers (npoly 60)
    hpoly() { sed "s/^variable  *npoly index 0/variable npoly index 60/; $2" "$hin" > "$t/hbad0.in"; hin0=$hin; hin=$t/hbad0.in; hexpect "$1" "$3"; hin=$hin0; }
    hpoly "polymer = 1 is the fluid's type" "" "s/polymer 2 xi/polymer 1 xi/"
    hpoly "coupling = both is not shepard or raw" "s/^variable  *coupling index shepard/variable coupling index both/" ""
    hpoly "substeps = 0 is not an integer" "s/^variable  *substeps index 1/variable substeps index 0/" ""
    hpoly "more pair variables than pairs" "" "s/^fix  *g all hcbd .*/& pairs 1/"
    hpoly "phi = n / n_max >= 1" "s/^variable  *n_max index 5/variable n_max index 0.05/" ""
    hpoly "fluid blobs need the tags 1..512" "s/^create_atoms    1 box/create_atoms 2 single 1 1 1\n&/; s/random \${npoly}/random \$(v_npoly-1)/" ""
    hpoly "3 atom types" "s/^create_box .*/create_box 3 box/; s/^mass  *1 .*/mass * \$(v_rho\/v_nbar)/" ""
    # pairs auto (the default): twice the polymers' mean number within rc, and 16
    local want
    want=$(awk 'BEGIN { m = 60 / 1024 * 4 / 3 * atan2(0, -1) * 8; c = int(2 * m); if (c < 2 * m) ++c; print c + 16 }')
    out=$("$lmp" -in "$hin" -var plugin "$hplug" -var npoly 60 -var pairs auto -var warm 2 -var steps 2 -log none 2>&1)
    if printf '%s' "$out" | grep -q "pairs auto = $want " && ! printf '%s' "$out" | grep -q ERROR; then
        ok "fix hcbd: pairs auto holds $want pair variables for 60 polymers in 1024 sigma^3 (rc = 2)"
    else bad "fix hcbd: pairs auto: $(printf '%s' "$out" | grep 'pairs auto\|ERROR' | head -n 1), not $want"; fi
    # 100 + 100 steps through a restart file (with the pair variables)
    # equal 200 steps within round-off (reading a restart wraps the atoms
    # into the box at another step than the run does)
    "$lmp" -in "$hin" -var plugin "$hplug" -var npoly 60 -var steps 100 -var save "$t/hq0" -log none -screen none \
        > /dev/null 2>&1
    "$lmp" -in "$hin" -var plugin "$hplug" -var npoly 60 -var from restart -var restart "$t/hq0" -var steps 100 \
        -var end "$t/hc1.txt" -log none -screen none > /dev/null 2>&1
    "$lmp" -in "$hin" -var plugin "$hplug" -var npoly 60 -var steps 200 -var end "$t/hc2.txt" -log none -screen none \
        > /dev/null 2>&1
    read -r dx dv n < <(awk -v L="$(awk 'NR == 6 { printf "%.17g", $2 - $1 }' "$t/hc2.txt")" \
        -f "$root/lammps/maxdiff.awk" "$t/hc2.txt" "$t/hc1.txt" 2>/dev/null)
    if [ "$n" = 572 ] && awk -v a="$dx" -v b="$dv" 'BEGIN { exit !(a < 1e-6 && b < 1e-6) }'; then
        ok "fix hcbd, 60 polymers: 100 + 100 steps through a restart file = 200 steps within $dx, $dv"
    else bad "fix hcbd: a restart does not continue the run: largest differences $dx, $dv ($n atoms)"; fi
    # a restart file read with another pairs: refused, naming the file's
    out=$("$lmp" -in "$hin" -var plugin "$hplug" -var npoly 60 -var from restart -var restart "$t/hq0" -var pairs 20 \
        -var steps 2 -log none 2>&1)
    if printf '%s' "$out" | grep -q "ERROR.*written with pairs = 32, this fix has pairs = 20"; then
        ok "fix hcbd: a restart file of pairs 32 read with pairs 20 -> error names both"
    else bad "fix hcbd: restart with another pairs: $(printf '%s' "$out" | grep ERROR | head -n 1)"; fi
}

# from one restart file (with polymers, after 100 steps: the pair variables
# in it), 300 steps on RANKS end in the same atoms bit for bit (positions
# wrapped by their owners, each pair with the lower tag first, fixed-point
# sums, a polymer's neighbours by tag, noise keyed by step and ids); at
# rest and sheared
hcbd_bits() {
    local np g
    [ -f "$hplug" ] || return
    # pair exact: 1331 fluid blobs in 6^3 blocks, on processors 1 * *, 100
    # steps (sheared: the box flips and the blocks along x change)
    for g in 0 0.8; do
        "$lmp" -in "$hin" -var plugin "$hplug" -var npoly 60 -var ns 11 -var pair exact -var gdot "$g" -var steps 20 \
            -var save "$t/hx$g" -log none -screen none > /dev/null 2>&1
        for np in $RANKS; do
            $MPI -np "$np" "$lmp" -in "$hin" -var plugin "$hplug" -var npoly 60 -var ns 11 -var pair exact -var procs "1 * *" \
                -var from restart -var restart "$t/hx$g" -var gdot "$g" -var steps 100 -var end "$t/hy$g-$np.txt" \
                -log none -screen none > /dev/null 2>&1
        done
        if same_bits "$t/hy$g-"; then ok "fix hcbd, pair exact, 60 polymers, gdot = $g, ranks $RANKS: the same atoms bit for bit after 100 steps"
        else bad "fix hcbd, pair exact, 60 polymers, gdot = $g, ranks $RANKS: the atoms differ after 100 steps"; fi
    done
    for g in 0 0.8; do
        "$lmp" -in "$hin" -var plugin "$hplug" -var npoly 60 -var gdot "$g" -var steps 100 -var save "$t/hr$g" \
            -log none -screen none > /dev/null 2>&1
        for np in $RANKS; do
            $MPI -np "$np" "$lmp" -in "$hin" -var plugin "$hplug" -var npoly 60 -var from restart -var restart "$t/hr$g" \
                -var gdot "$g" -var steps 300 -var end "$t/hb$g-$np.txt" -log none -screen none > /dev/null 2>&1
        done
        if same_bits "$t/hb$g-"; then ok "fix hcbd, 60 polymers, gdot = $g, ranks $RANKS: the same atoms bit for bit after 300 steps"
        else bad "fix hcbd, 60 polymers, gdot = $g, ranks $RANKS: the atoms differ after 300 steps"; fi
    done
}

# the fluid's temperature with 60 polymers (Euler pairs with
# fluctuations: hot by about 0.33 dt/dt_visc = 1.3 % here) on 2 ranks
# equals hcbd's world's at the same parameters within four combined errors
# (20000 steps after the 50, T every 10 steps, 10 blocks), and is kT within
# 3 %
hcbd_stats() {
    [ -f "$hplug" ] || return
    local T eT hT heT
    blocks() { # T samples (step T per line) after the first 2000 steps: mean and error of 10 blocks
        awk 'NF == 2 && $1 > 2000 { x[++n] = $2 } END { b = int(n / 10); for (k = 0; k < 10; ++k) { s = 0
             for (j = 1; j <= b; ++j) s += x[k * b + j]; m[k] = s / b; a += m[k] / 10 }
             for (k = 0; k < 10; ++k) v += (m[k] - a) ^ 2; printf "%.6g %.3g\n", a, sqrt(v / 90) }'
    }
    if ! $MPI -np 2 "$lmp" -in "$hin" -var plugin "$hplug" -var npoly 60 -var seed 21 -var steps 22000 -var thermo 10 \
        -var start "$t/hs0.txt" -log "$t/hs.log" -screen none > /dev/null 2>&1; then
        bad "fix hcbd, 2 ranks: temperature run failed: $(grep ERROR "$t/hs.log" | head -n 1)"; return
    fi
    read -r T eT < <(awk '/^ *Step/ { f = 1; next } /^Loop/ { f = 0 } f && NF == 2' "$t/hs.log" | blocks)
    # shellcheck disable=SC2086
    read -r hT heT < <("$t/hc_ref" "$t/hs0.txt" /dev/null 22000 $hcoef seed=22 fluct=yes every=10 | blocks)
    echo "    fix hcbd: fluid temperature $T +- $eT, hcbd's world $hT +- $heT (kT = 1.7)"
    if [[ "$T $eT $hT $heT" =~ ^[0-9.e-]+\ [0-9.e-]+\ [0-9.e-]+\ [0-9.e-]+$ ]] && within "$T" "$eT" "$hT" "$heT"; then ok "fix hcbd, 2 ranks: the fluid's temperature is hcbd's world's"
    else bad "fix hcbd, 2 ranks: temperature $T +- $eT, hcbd's world $hT +- $heT"; fi
    if awk -v T="$T" 'BEGIN { d = T / 1.7 - 1; exit !(d > -0.03 && d < 0.03) }'; then
        ok "fix hcbd, 2 ranks: the fluid's temperature is kT within 3 % ($T)"
    else bad "fix hcbd, 2 ranks: temperature $T is not kT = 1.7"; fi
    # pair exact (the default) has no such bias: kT within four errors (1 rank,
    # the 8^3 lattice is one block)
    if ! "$lmp" -in "$hin" -var plugin "$hplug" -var npoly 60 -var pair exact -var seed 23 -var steps 22000 -var thermo 10 \
        -log "$t/hx.log" -screen none > /dev/null 2>&1; then
        bad "fix hcbd, pair exact: temperature run failed: $(grep ERROR "$t/hx.log" | head -n 1)"; return
    fi
    read -r T eT < <(awk '/^ *Step/ { f = 1; next } /^Loop/ { f = 0 } f && NF == 2' "$t/hx.log" | blocks)
    echo "    fix hcbd, pair exact: fluid temperature $T +- $eT (kT = 1.7)"
    if [[ "$T $eT" =~ ^[0-9.e-]+\ [0-9.e-]+$ ]] && within "$T" "$eT" 1.7 0; then
        ok "fix hcbd, pair exact: the fluid's temperature is kT within four errors"
    else bad "fix hcbd, pair exact: temperature $T +- $eT is not kT = 1.7"; fi
    # the polymers' temperature: on 2 ranks, each polymer step's displacement
    # less its drift u dt (LAMMPS's velocity of a polymer) has per component
    # the variance 2 kT dt / xi (400 steps of 60 polymers, independent
    # noise, so the error of the mean from the samples' own spread)
    local R eR
    if ! $MPI -np 2 "$lmp" -in "$hin" -var plugin "$hplug" -var npoly 60 -var seed 31 -var steps 400 -var tevery 1 \
        -var traj "$t/htraj" -log "$t/htraj.log" -screen none > /dev/null 2>&1; then
        bad "fix hcbd, 2 ranks: polymer trajectory run failed: $(grep ERROR "$t/htraj.log" | head -n 1)"; return
    fi
    read -r R eR < <(awk -v dt=0.02 -v s2="$(awk 'BEGIN { print 2 * 1.7 * 0.02 / 30 }')" '
        /^ITEM: ATOMS/ { f = 1; next } /^ITEM/ { f = 0; next }
        f && $2 == 2 { if (seen[$1]) for (e = 0; e < 3; ++e) { d = $(3 + e) - x[$1, e] - $(6 + e) * dt; r = d * d / s2; S += r; Q += r * r; ++N }
            seen[$1] = 1; for (e = 0; e < 3; ++e) x[$1, e] = $(3 + e) }
        END { m = S / N; printf "%.6g %.3g\n", m, sqrt((Q / N - m * m) / N) }' "$t/htraj")
    echo "    fix hcbd: the polymers' displacements less u dt over 2 kT dt / xi: $R +- $eR"
    if [[ "$R $eR" =~ ^[0-9.e-]+\ [0-9.e-]+$ ]] && within "$R" "$eR" 1 0; then
        ok "fix hcbd, 2 ranks: the polymers' Brownian displacements have the variance 2 kT dt / xi within four errors"
    else bad "fix hcbd, 2 ranks: the polymers' displacement variance is $R +- $eR of 2 kT dt / xi"; fi
    # the viscosity of a polymer solution at Wi = 1 on 2 ranks, from the
    # Table I input (lammps/in.hcbd_table1), equals hcbd_polymer's at the
    # same parameters within four combined errors: preset=quick's Table I
    # (tau_lambda = 200 us, alpha and P0 scaled, dt = 1 us, no sub-steps), C
    # = 2.5 C* in a 9.67^3 box (216 fluid blobs on the lattice and 540
    # polymers), gdot = 5000 / s, the paper's Euler fluid pairs, 20
    # tau_lambda (4000 steps) of start-up, then 10 blocks of one
    local E eE hE heE
    local Q="-var P0 1.72452e+07 -var alpha 2.5e+06 -var tau 200 -var dt 1 -var sub 1 -var pair euler -var Wi 1"
    # shellcheck disable=SC2086
    if ! $MPI -np 2 "$lmp" -in "$root/lammps/in.hcbd_table1" -var plugin "$hplug" $Q -var seed 5 -var startup 20 \
        -var blocks 10 -var out "$t/heta.txt" -log "$t/heta.log" -screen none > /dev/null 2>&1; then
        bad "fix hcbd, 2 ranks: viscosity run failed: $(grep ERROR "$t/heta.log" | head -n 1)"; return
    fi
    read -r E eE < <(awk '!/^#/ { x[++m] = $11 / 0.005 } END { for (k = 1; k <= m; ++k) s += x[k]
        s /= m; for (k = 1; k <= m; ++k) v += (x[k] - s) ^ 2; printf "%.6g %.3g\n", s, sqrt(v / (m * (m - 1))) }' "$t/heta.txt")
    "$root/build/hcbd_polymer" C=2.5 gdot=5000 Lx=9.6739 Ly=9.6739 Lz=9.6739 le_steps=6000 rp_steps=30 eq_steps=2 \
        blocks=10 pair=euler threads=1 seed=3 out="$t/hq" > "$t/hq.txt" 2>/dev/null
    hE=$(awk -F= '$1 == "eta_total_lowest_rate" { print $2 }' "$t/hq.txt")
    heE=$(awk -F= '$1 == "eta_total_lowest_rate_err" { print $2 }' "$t/hq.txt")
    echo "    fix hcbd: viscosity at Wi = 1 (C = 2.5 C*, preset=quick's parameters) $E +- $eE, hcbd_polymer's $hE +- $heE"
    if [[ "$E $eE $hE $heE" =~ ^[0-9.e+-]+\ [0-9.e+-]+\ [0-9.e+-]+\ [0-9.e+-]+$ ]] && within "$E" "$eE" "$hE" "$heE"; then
        ok "fix hcbd, 2 ranks: the polymer solution's viscosity at Wi = 1 is hcbd_polymer's"
    else bad "fix hcbd, 2 ranks: viscosity $E +- $eE, hcbd_polymer's $hE +- $heE"; fi
    # and the input's own figure in mPa s (its unit conversion) is hcbd_polymer's
    local M eM hM heM
    read -r M eM < <(awk '/^C = .*eta = / { for (k = 1; k <= NF; ++k) if ($k == "eta") { print $(k + 2), $(k + 4); exit } }' \
        "$t/heta.log")
    read -r hM heM < <(awk -F, 'NR == 2 { print $13, $14 }' "$t/hq/flowcurve.csv")
    echo "    lammps/in.hcbd_table1: $M +- $eM mPa s, hcbd_polymer's $hM +- $heM"
    if [[ "$M $eM $hM $heM" =~ ^[0-9.e+-]+\ [0-9.e+-]+\ [0-9.e+-]+\ [0-9.e+-]+$ ]] && within "$M" "$eM" "$hM" "$heM"; then
        ok "lammps/in.hcbd_table1: its viscosity in mPa s is hcbd_polymer's"
    else bad "lammps/in.hcbd_table1: viscosity $M +- $eM mPa s, hcbd_polymer's $hM +- $heM"; fi
}
