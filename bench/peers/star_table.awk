# Likos star potential (hcbd_star_potential / hcbd_star_force in hcbd.h,
# 2014 eq. 28) as a LAMMPS pair table, keyword STAR:
#   V = a (-ln q + b)                 q = r/sigma <= 1
#   V = a b exp(-s (q - 1)) / q       q > 1
#   a = eps (5/18) f^1.5, b = 1/(1 + sqrt(f)/2), s = sqrt(f)/2
#   F = -dV/dr = a/r (q <= 1),  a b exp(-s(q-1)) (1/q^2 + s/q) / sigma (q > 1)
# usage: awk -v f=128 -v sigma=1 -v eps=1 -v n=5000 -v rlo=0.01 -v rhi=2.5 -f star_table.awk
BEGIN {
    if (f == "") f = 128; if (sigma == "") sigma = 1; if (eps == "") eps = 1
    if (n == "") n = 5000; if (rlo == "") rlo = 0.01; if (rhi == "") rhi = 2.5
    a = eps * (5.0 / 18.0) * f ^ 1.5; b = 1.0 / (1.0 + 0.5 * sqrt(f)); s = 0.5 * sqrt(f)
    printf "# Likos star potential f = %g sigma = %g eps = %g (hcbd_star_potential)\n\n", f, sigma, eps
    printf "STAR\nN %d R %.10g %.10g\n\n", n, rlo, rhi
    for (i = 1; i <= n; ++i) {
        r = rlo + (rhi - rlo) * (i - 1) / (n - 1); q = r / sigma
        if (q <= 1) { e = a * (-log(q) + b); F = a / r }
        else { x = exp(-s * (q - 1)); e = a * b * x / q; F = a * b * x * (1 / (q * q) + s / q) / sigma }
        printf "%d %.10g %.12g %.12g\n", i, r, e, F
    }
}
