#!/usr/bin/env bash
# make mutants-lammps: each injected error of the plugin (a single
# coefficient 10 % off in fix_gibd.cpp, fix_hcbd.cpp, le_wrap.h, pair_star.cpp, or the functions of
# hcbd.h that only the plugin calls (hcbd_gibd_pair_exact, hcbd_walls_morris)) must make the
# quick part of make test-lammps fail (lammps/check.sh with
# HCBD_LAMMPS_QUICK=1: the atom-by-atom comparison with hcbd's world).
# Builds the plugin once per mutant against build/lammps (make lammps).
# Prints one line per mutant: caught (by the first failing check) or MISSED.
# NAMES="a b": only those.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
B=$root/build/lammps
[ -x "$B/lmp" ] || { echo "mutants-lammps: skipped: no LAMMPS (make lammps builds it)"; exit 0; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
missed=0
# NAME|FILE|OLD|NEW, OLD once in FILE
while IFS='|' read -r -u 3 name file old new; do
    [ -n "$name" ] || continue
    case " ${NAMES:-$name} " in *" $name "*) ;; *) continue ;; esac
    rm -rf "$work/src" "$work/plugin" "$work/hdr"
    cp -r "$root/lammps" "$work/src"
    mkdir -p "$work/hdr"
    cp "$root/hcbd.h" "$work/hdr/"
    target=$work/src/$file
    [ "$file" = hcbd.h ] && target=$work/hdr/hcbd.h
    if ! python3 - "$target" "$old" "$new" <<'PY'
import sys
path, old, new = sys.argv[1:4]
s = open(path).read()
if s.count(old) != 1:
    sys.exit("pattern found %d times" % s.count(old))
open(path, 'w').write(s.replace(old, new))
PY
    then echo "$name: BAD PATTERN"; missed=$((missed + 1)); continue; fi
    if ! { cmake -S "$work/src" -B "$work/plugin" -D CMAKE_BUILD_TYPE=Release -D LAMMPS_HEADER_DIR="$B/src/src" \
        -D HCBD_DIR="$work/hdr" && cmake --build "$work/plugin" -j2; } > "$work/build.log" 2>&1; then
        echo "$name: does not build"; missed=$((missed + 1)); continue
    fi
    ln -sf "$B/lmp" "$work/lmp"
    part=
    [ "$file" = fix_hcbd.cpp ] && part=hcbd
    first=$(HCBD_LAMMPS_DIR=$work HCBD_LAMMPS_QUICK=1 HCBD_LAMMPS_FIRST_FAIL=1 HCBD_LAMMPS_PART=$part "$root/lammps/check.sh" 2>&1 | grep -m 1 '^  FAIL' | sed 's/^  FAIL //')
    if [ -n "$first" ]; then echo "$name: caught by: ${first%%:*}"
    else echo "$name: MISSED"; missed=$((missed + 1)); fi
done 3<<'LIST'
brownian_amplitude|fix_gibd.cpp|std::sqrt(2.0 * p.kT * dt / p.xi)|std::sqrt(2.2 * p.kT * dt / p.xi)
mobility|fix_gibd.cpp|F[d] * dt / p.xi|1.1 * F[d] * dt / p.xi
force_on_background|fix_gibd.cpp|v[i][d] += F[d] * dt / m|v[i][d] += 1.1 * F[d] * dt / m
advection|fix_gibd.cpp|x[i][d] += v[i][d] * dt|x[i][d] += 1.1 * v[i][d] * dt
pair_friction|fix_gibd.cpp|(sdt * (v[j][d] - v[i][d])|(1.1 * sdt * (v[j][d] - v[i][d])
pair_noise|fix_gibd.cpp|std::sqrt(two_kT * sdt)|std::sqrt(2.2 * p.kT * sdt)
pair_mass|fix_gibd.cpp|+ amp * z[d]) / m * vscale|+ amp * z[d]) / (1.1 * m) * vscale
weight_of_partner|fix_gibd.cpp|acc[j] += w;|acc[j] += w + w / 10;
reaction_on_partner|fix_gibd.cpp|acc[3 * j + d] -= q;|acc[3 * j + d] -= q + q / 10;
fric_scale|fix_gibd.cpp|fscale = p.tau / (p.dt * c.m);|fscale = 1.1 * p.tau / (p.dt * c.m);
fric_wave|fix_gibd.cpp|fs[2] += 2.0 * fij|fs[2] += 2.2 * fij
density|fix_gibd.cpp|inv_rho[i] = 1.0 / hcbd_gibd_density|inv_rho[i] = 1.1 / hcbd_gibd_density
noise_step|fix_gibd.cpp|update->ntimestep - 1;|update->ntimestep;
exact_kick|fix_gibd.cpp|vc[3 * i + d] += F[d] * dt_m;|vc[3 * i + d] += 1.1 * F[d] * dt_m;
exact_drift_mean|fix_gibd.cpp|(u + v[i][d]) * (0.5 * dt)|(u + v[i][d]) * (0.55 * dt)
exact_mobility|fix_gibd.cpp|x[i][d] += F[d] * dt_xi|x[i][d] += 1.1 * F[d] * dt_xi
exact_advection|fix_gibd.cpp|(u + v[i][d]) * (0.5 * dt)|(u + 1.1 * v[i][d]) * (0.5 * dt)
lm_amplitude|fix_gibd.cpp|sdz = lmw ? 0.5 * bd : bd|sdz = lmw ? 0.55 * bd : bd
lm_next_step|fix_gibd.cpp|hcbd_noise_particle(&ns, step + 1, id, z1);|hcbd_noise_particle(&ns, step + 2, id, z1);
sweep_anchor|fix_gibd.cpp|r[1] - o[0], r[2] - o[1]|r[1] - 1.1 * o[0], r[2] - o[1]
pair_exact_rate|hcbd.h|x = 2.0 * sdt * inv_m;|x = 2.2 * sdt * inv_m;
pair_exact_noise|hcbd.h|sqrt(0.5 * kT * m * om|sqrt(0.55 * kT * m * om
pair_exact_share|hcbd.h|h = 0.5 * m * om;|h = 0.55 * m * om;
le_pair_shift|fix_gibd.cpp|part_k[t] * le_v, vc|1.1 * part_k[t] * le_v, vc
le_image_offset|fix_gibd.cpp|min_image(ri[0] - rj[0] - k * le_s|min_image(ri[0] - rj[0] - 1.1 * k * le_s
le_frame|fix_gibd.cpp|if (k) vc[3 * i] -= k * le_v;|if (k) vc[3 * i] -= 1.1 * k * le_v;
le_frame_back|fix_gibd.cpp|if (kw[i]) v[i][0] += kw[i] * le_v;|if (kw[i]) v[i][0] += 1.1 * kw[i] * le_v;
le_flip_jump|le_wrap.h|v[i][0] -= k * vj;|v[i][0] -= 1.1 * k * vj;
le_flip_offset|le_wrap.h|x[i][0] -= k * xy;|x[i][0] -= 1.1 * k * xy;
stress_exchange|fix_gibd.cpp|sfl[0] = -tot[0] / (p.L[0]|sfl[0] = -1.1 * tot[0] / (p.L[0]
stress_exchange_euler|fix_gibd.cpp|if (stress) sbg += dy * (sdt|if (stress) sbg += 1.1 * dy * (sdt
stress_carrier_up|fix_gibd.cpp|if (k1 > k0) scr += m * vx;|if (k1 > k0) scr += 1.1 * m * vx;
stress_carrier_down|fix_gibd.cpp|else if (k1 < k0) scr -= m * (vx + le_v);|else if (k1 < k0) scr -= m * (vx + 1.1 * le_v);
stress_carrier_area|fix_gibd.cpp|sfl[1] = -tot[1] / (p.L[0] * p.L[2] * dt);|sfl[1] = -1.1 * tot[1] / (p.L[0] * p.L[2] * dt);
wall_weights|fix_gibd.cpp|s += hcbd_walls_weights(&wl, xw + 3 * i);|s += 1.1 * hcbd_walls_weights(&wl, xw + 3 * i);
wall_step|fix_gibd.cpp|if (walls) hcbd_walls_draw(&wl, step);|if (walls) hcbd_walls_draw(&wl, step + 1);
wall_morris_sweep|fix_gibd.cpp|xw + 3 * i, inv_rho[i], vc + 3 * i, nullptr)|xw + 3 * i, 1.1 * inv_rho[i], vc + 3 * i, nullptr)
wall_morris_euler|fix_gibd.cpp|+ P[d] / m;|+ 1.1 * P[d] / m;
wall_force|fix_gibd.cpp|F[1] += fy;|F[1] += 1.1 * fy;
wall_reflect_lo|fix_gibd.cpp|if (u < lo) u = 2.0 * lo - u;|if (u < lo) u = 2.2 * lo - u;
wall_reflect_hi|fix_gibd.cpp|else if (u > hi) u = 2.0 * hi - u;|else if (u > hi) u = 2.2 * hi - u;
wall_pair_key|hcbd.h|hcbd__ws_pair_step_key(&wl->ws, wl->step, exact)|hcbd__ws_pair_step_key(&wl->ws, wl->step + 1, exact)
star_force|pair_star.cpp|const double fpair = hcbd_star_force_over_r(|const double fpair = 1.1 * hcbd_star_force_over_r(
star_sigma|pair_star.cpp|sigma[i][j] = s1;|sigma[i][j] = 1.1 * s1;
star_eps|pair_star.cpp|eps[i][j] = e1;|eps[i][j] = 1.1 * e1;
star_energy|pair_star.cpp|const double e = eflag ? hcbd_star_potential(|const double e = eflag ? 1.1 * hcbd_star_potential(
hc_weight_of_partner|fix_hcbd.cpp|acc[j] += w;|acc[j] += w + w / 10;
hc_reaction_on_partner|fix_hcbd.cpp|acc[3 * j + e] -= q;|acc[3 * j + e] -= q + q / 10;
hc_density|fix_hcbd.cpp|hcbd_hc_fluid_density(&c, (double) acc[i] / wscale)|hcbd_hc_fluid_density(&c, 1.1 * (double) acc[i] / wscale)
hc_pressure|fix_hcbd.cpp|np_[2 * i + 1] = hcbd_hc_fluid_pressure(&c, n);|np_[2 * i + 1] = 1.1 * hcbd_hc_fluid_pressure(&c, n);
hc_kick|fix_hcbd.cpp|v[i][d] += dt_m * (|v[i][d] += 1.1 * dt_m * (
hc_lammps_force|fix_hcbd.cpp|: 0.0) + f[i][d])|: 0.0) + 1.1 * f[i][d])
hc_advection|fix_hcbd.cpp|x[i][d] += v[i][d] * dt;|x[i][d] += 1.1 * v[i][d] * dt;
hc_noise_step|fix_hcbd.cpp|fluid_pairs(k, stress && last);|fluid_pairs(k + 1, stress && last);
hc_exact_noise_step|fix_hcbd.cpp|if (exact) sweep(k, stress && last);|if (exact) sweep(k + 1, stress && last);
hc_exact_owner_density|fix_hcbd.cpp|const double ini = 1.0 / np_[2 * i];|const double ini = 1.1 / np_[2 * i];
hc_exact_partner_density|fix_hcbd.cpp|ini, 1.0 / np_[2 * j],|ini, 1.1 / np_[2 * j],
hc_exact_le_velocity|fix_hcbd.cpp|pt.k * le_v,|1.1 * pt.k * le_v,
hc_exact_frame|fix_hcbd.cpp|v[i][d] = vc[3 * i + d] + (d == 0 ? kw[i] * le_v : 0.0);|v[i][d] = vc[3 * i + d] + (d == 0 ? 1.1 * kw[i] * le_v : 0.0);
hc_exact_stress_pressure|fix_hcbd.cpp|if (sum) ss[0] += d[1] * F[0];|if (sum) ss[0] += 1.1 * d[1] * F[0];
hc_exact_stress_viscous|fix_hcbd.cpp|ss[1] += pt.y * P[0] / c.dt;|ss[1] += 1.1 * pt.y * P[0] / c.dt;
hc_exact_fine_order|fix_hcbd.cpp|if (a.fine != b.fine) return a.fine < b.fine;|if (a.fine != b.fine) return a.fine > b.fine;
hc_exact_origin|fix_hcbd.cpp|for (int d = 0; d < 3; ++d) a0[d] = xw[3 * i1 + d];|for (int d = 0; d < 3; ++d) a0[d] = 1.1 * xw[3 * i1 + d];
hc_exact_shear_cut|fix_hcbd.cpp|const double t = le_s / L[1];|const double t = 1.1 * le_s / L[1];
hc_exact_ghost_relay|fix_hcbd.cpp|touched[slist[k]] = 1;|touched[slist[k]] = 0;
hc_exact_stale_partners|fix_hcbd.cpp|neighbor->ago == 0|neighbor->ago == -1
hc_poly_velocity|fix_hcbd.cpp|v[i][d] = tp ? st[i][1 + d] + (d == 0 ? kw[i] * le_v : 0.0) : 0.0;|v[i][d] = tp ? 1.1 * st[i][1 + d] + (d == 0 ? kw[i] * le_v : 0.0) : 0.0;
hc_noise_lower_tag|fix_hcbd.cpp|const int i = tag[i0] < tag[j0] ? i0 : j0|const int i = tag[i0] > tag[j0] ? i0 : j0
hc_le_velocity|fix_hcbd.cpp|(vj[0] + kj * le_v)|(vj[0] + 1.1 * kj * le_v)
hc_le_offset|fix_hcbd.cpp|min_image(ri[0] - rj[0] - k * le_s|min_image(ri[0] - rj[0] - 1.1 * k * le_s
hc_le_frame|fix_hcbd.cpp|if (k) vc[3 * i] -= k * le_v;|if (k) vc[3 * i] -= 1.1 * k * le_v;
hc_poly_weight|fix_hcbd.cpp|return hcbd_hc_polymer_weight(&c, r); });|return 1.1 * hcbd_hc_polymer_weight(&c, r); });
hc_poly_mu|fix_hcbd.cpp|np_[2 * i + 1] = hcbd_hc_polymer_mu(&c, n);|np_[2 * i + 1] = 1.1 * hcbd_hc_polymer_mu(&c, n);
hc_poly_reaction|fix_hcbd.cpp|acc[3 * j + e] -= qp;|acc[3 * j + e] -= qp + qp / 10;
hc_lambda_kept|fix_hcbd.cpp|lam = e >= 0 ? st[o][4 + 3 * e + 1]|lam = e >= 0 ? 1.1 * st[o][4 + 3 * e + 1]
hc_lambda_new|fix_hcbd.cpp|e >= 0 ? st[a][4 + 3 * e + 1] : leq, leq}|e >= 0 ? st[a][4 + 3 * e + 1] : 1.1 * leq, leq}
hc_lambda_eq_held|fix_hcbd.cpp|row[4 + 3 * e + 2], z);|1.1 * row[4 + 3 * e + 2], z);
hc_lambda_noise_step|fix_hcbd.cpp|hcbd_hc_noise_lambda(&ns, step,|hcbd_hc_noise_lambda(&ns, step + 1,
hc_interp_weight|fix_hcbd.cpp|const Near nb = {tag[i], hcbd_hc_polymer_weight(&c, r) / np_[2 * i],|const Near nb = {tag[i], 1.1 * hcbd_hc_polymer_weight(&c, r) / np_[2 * i],
hc_interp_image|fix_hcbd.cpp|{vc[3 * i] - k * le_v,|{vc[3 * i] - 1.1 * k * le_v,
hc_poly_image_once|fix_hcbd.cpp|x[i][0] += kw[i] * le_v * dt;|x[i][0] += (sub == nsub - 1) * kw[i] * le_v * p.dt;
hc_pairs_auto|fix_hcbd.cpp|std::ceil(2.0 * mean) + 16.0|std::ceil(2.2 * mean) + 16.0
hc_interp_shepard|fix_hcbd.cpp|v[e] = shep ? ref + dv[e] / S|v[e] = shep ? ref + 1.1 * dv[e] / S
hc_mobility|fix_hcbd.cpp|st[a][1 + e] = v[e] + fs[4 * a + e] / p.xi;|st[a][1 + e] = v[e] + 1.1 * fs[4 * a + e] / p.xi;
hc_redistribution|fix_hcbd.cpp|const double psi = hcbd_hc_polymer_weight(&c, r)|const double psi = 1.1 * hcbd_hc_polymer_weight(&c, r)
hc_coupling_kick|fix_hcbd.cpp|(tp ? st[i][1 + d] : 0.0)|(tp ? 1.1 * st[i][1 + d] : 0.0)
hc_poly_noise|fix_hcbd.cpp|sdr = std::sqrt(2.0 * p.kT * dt / p.xi)|sdr = std::sqrt(2.2 * p.kT * dt / p.xi)
hc_poly_noise_step|fix_hcbd.cpp|hcbd_hc_noise_polymer(&ns, step,|hcbd_hc_noise_polymer(&ns, step + 1,
hc_poly_id|fix_hcbd.cpp|(int32_t) (atom->tag[a] - 1 - nfluid)|(int32_t) (atom->tag[a] - nfluid)
hc_poly_drift|fix_hcbd.cpp|dr[e] = st[a][1 + e] * dt + sdr * z[e];|dr[e] = 1.1 * st[a][1 + e] * dt + sdr * z[e];
hc_polymer_step|fix_hcbd.cpp|p.dt = update->dt * p.substeps;|p.dt = 1.1 * update->dt * p.substeps;
hc_restart_pairs|fix_hcbd.cpp|std::memcpy(st[n], &extra[n][m + 1], sizeof(double) * width);|std::memset(st[n], 0, sizeof(double) * width);
hc_polymer_frame|fix_hcbd.cpp|x[i][0] += kw[i] * le_v * dt;|x[i][0] += 1.1 * kw[i] * le_v * dt;
hc_stress_pressure|fix_hcbd.cpp|ss[0] += d[1] * Fp[0];|ss[0] += 1.1 * d[1] * Fp[0];
hc_stress_viscous|fix_hcbd.cpp|ss[1] += d[1] * (Fv[0] - Fp[0]);|ss[1] += 1.1 * d[1] * (Fv[0] - Fp[0]);
hc_stress_noise|fix_hcbd.cpp|ss[2] += d[1] * (F[0] - Fv[0]);|ss[2] += 1.1 * d[1] * (F[0] - Fv[0]);
hc_stress_kinetic|fix_hcbd.cpp|ss[6] += c.m * (vc[3 * i]|ss[6] += 1.1 * c.m * (vc[3 * i]
hc_stress_profile|fix_hcbd.cpp|const double gdot = le_v / p.L[1];|const double gdot = 1.1 * le_v / p.L[1];
hc_stress_conservative|fix_hcbd.cpp|ss[3] += d[1] * fc * d[0];|ss[3] += 1.1 * d[1] * fc * d[0];
hc_stress_transient|fix_hcbd.cpp|ss[4] += d[1] * (fr - fc) * d[0];|ss[4] += 1.1 * d[1] * (fr - fc) * d[0];
hc_stress_interaction|fix_hcbd.cpp|ss[5] += lever / fs[4 * a + 3] * fs[4 * a];|ss[5] += 1.1 * lever / fs[4 * a + 3] * fs[4 * a];
hc_stress_volume|fix_hcbd.cpp|const double f = -1.0 / (p.L[0] * p.L[1] * p.L[2]);|const double f = -1.1 / (p.L[0] * p.L[1] * p.L[2]);
LIST
echo "mutants-lammps: $missed missed"
[ $missed -eq 0 ]
