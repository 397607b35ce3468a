# lammps/rp_amplitude.awk, for lammps/in.hcbd_channel's fluid trajectory (tevery):
# awk -v g=GDOT -f lammps/rp_amplitude.awk dump: per snapshot, the fluid's x velocities fitted
# to the Newtonian reverse-Poiseuille shape (a parabola in each half, +1 at the
# upper half's centre), over the amplitude gdot Ly / 8 that a fluid of the
# nominal viscosity would reach: "step ratio"
function out() { if (Q > 0) printf "%d %.5f\n", ts, S / Q / (g * Ly / 8); S = 0; Q = 0 }
/^ITEM: TIMESTEP/ { out(); getline; ts = $1; f = 0; next }
/^ITEM: BOX/ { getline; getline; ylo = $1; Ly = $2 - $1; getline; next }
/^ITEM: ATOMS/ { f = 1; next }
/^ITEM/ { f = 0; next }
f { y = $2 - ylo; y -= Ly * int(y / Ly); if (y < 0) y += Ly; h = Ly / 2
    if (y >= h) { u = y - h; sg = 1 } else { u = y; sg = -1 }
    s = sg * u * (h - u) / (h * h / 4); S += $3 * s; Q += s * s }
END { out() }
