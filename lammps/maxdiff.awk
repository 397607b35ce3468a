# awk -v L=edge -f maxdiff.awk A B: the largest difference of the positions
# (minimum image in a cube of edge L) and of the velocities between two
# "id x y z vx vy vz" listings (LAMMPS dumps or gibd_ref output), and the
# number of B's atoms found in A
NR == FNR { if (NF == 7 && $1 ~ /^[0-9]+$/) for (c = 2; c <= 7; ++c) a[$1, c] = $c; next }
NF == 7 && $1 ~ /^[0-9]+$/ && ($1, 2) in a {
    ++n
    for (c = 2; c <= 7; ++c) {
        d = $c - a[$1, c]
        if (c <= 4) d -= L * int(d / L + (d > 0 ? 0.5 : -0.5))
        if (d < 0) d = -d
        if (c <= 4 && d > dx) dx = d
        if (c > 4 && d > dv) dv = d
    }
}
END { printf "%.3g %.3g %d\n", dx, dv, n }
