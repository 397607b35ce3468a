# awk -v vle=V -f le_canon.awk DUMP: the atoms of a LAMMPS dump (id x y z vx
# vy vz, a box tilted in xy only) in hcbd's Lees-Edwards frame: an atom past
# y's edge becomes its image inside, moved along x by the tilt and with the
# velocity jump vle = gdot Ly taken off (what LAMMPS's remap v does at its
# next neighbour-list build), x wrapped into [xlo, xhi).  Prints "id x y z vx
# vy vz" lines, as gibd_ref writes them.
NR == 5 { tri = ($4 == "xy") }
NR == 6 { xlo = $1; xhi = $2; xy = tri ? $3 : 0 }
NR == 7 { ylo = $1; yhi = $2 }
NR == 9 {
    if (xy < 0) xlo -= xy; else xhi -= xy # the bounds hold the tilt
    Lx = xhi - xlo; Ly = yhi - ylo
}
NR > 9 && NF == 7 {
    uy = $3 - ylo; k = uy < 0 ? -1 : (uy >= Ly ? 1 : 0)
    uy -= k * Ly; ux = $2 - xlo - k * xy
    while (ux < 0) ux += Lx
    while (ux >= Lx) ux -= Lx
    printf "%d %.17g %.17g %.17g %.17g %.17g %.17g\n", $1, ux + xlo, uy + ylo, $4, $5 - k * vle, $6, $7
}
