# The long start-ups of issue 41 (hcbd_polymer preset=paper, the keys in
# run_*.conf): the total viscosity per half tau_lambda (points) and its mean
# over 4 tau_lambda (line) against the strain gdot t, with the 2018 Table II
# Carreau curve's viscosity at the same Wi (dashed).  gnuplot plot.gp in
# this folder writes long_startup.png.
set terminal pngcairo size 1500,520 font ",10" enhanced
set output "long_startup.png"
set datafile separator ","
set multiplot layout 1,3 title "Lees-Edwards start-up at Table I, 64 and 48 {/Symbol t}_{/Symbol l}: where the stress levels off"
set xlabel "strain {/Symbol g} = gdot t"
set ylabel "{/Symbol h} (mPa s)"
set key bottom right
set grid
c(e0, l, n, wi) = 0.9 + (e0 - 0.9) * (1 + (l * wi)**2)**((n - 1) / 2)
do for [r in "2.5:0.1 2.5:0.3 5:0.1"] {
    C = word(system("echo ".r." | tr ':' ' '"), 1)
    W = word(system("echo ".r." | tr ':' ' '"), 2)
    f = "startup_C".C."_Wi".W.".csv"
    e0 = (C eq "2.5") ? 2.526 : 6.6688
    l = (C eq "2.5") ? 3.0504 : 2.1408
    n = (C eq "2.5") ? 0.3441 : 0.0008
    set title sprintf("C = %s C*, Wi = %s", C, W)
    plot f u ($2 * W):3 every ::1 w p pt 7 ps 0.4 lc rgb "#9ab" t "half {/Symbol t}_{/Symbol l}", \
         "< awk -F, 'NR > 1 {k = int($2 / 4); s[k] += $3; m[k]++} END {for (k = 0; k in m; ++k) print (4 * k + 2) \",\" s[k] / m[k]}' ".f \
         u ($1 * W):2 w lp pt 5 lw 2 lc 1 t "4 {/Symbol t}_{/Symbol l} means", \
         c(e0, l, n, W + 0) w l dt 2 lw 2 lc rgb "black" t "Table II Carreau at this Wi"
}
unset multiplot
