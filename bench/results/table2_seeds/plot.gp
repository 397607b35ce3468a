# Table II at Table I, seed by seed (issue 41): each Lees-Edwards rate's total
# viscosity over the 2018 Table II Carreau curve at its Wi, with its error
# from the correlation time, for preset=paper (the paper's weights and pair
# step; seeds 1-3: ../table2_c<k>_paper_schemes*, C1's seed 3 in
# ../table2_paper_schemes_seed3, the whole preset in one run) and, hollow, the earlier
# preset with the library's Shepard weights and exact sweep (../paper,
# ../paper_seed2, ../paper_seed3).  Seeds are offset along Wi to be seen.
# gnuplot plot.gp in this folder writes seeds.png.
set terminal pngcairo enhanced size 1300,560 font 'Sans,12' linewidth 1.5
set output 'seeds.png'
set datafile separator ','
set encoding utf8
set multiplot layout 1,2 title "Each rate over 2018 Table II's Carreau curve: seeds at Table I (10^3 σ^3 box)"
set logscale x
set xrange [0.07:45]
set xtics (0.1, 0.3, 1, 3, 10, 30)
set xlabel 'Wi = γ̇τ_λ'
set ylabel 'run / Table II Carreau'
set yrange [0.90:1.08]
set grid lc rgb '#e0e0e0'
set key bottom left font ',10' box opaque
set bars small
t2(C, g) = (C == 2.5) ? 0.9 + (2.526 - 0.9) * (1 + (3.0504 * g)**2)**((0.3441 - 1.0) / 2) \
                      : 0.9 + (6.6688 - 0.9) * (1 + (2.1408 * g)**2)**((0.0008 - 1.0) / 2)
do for [k = 1:2] {
    C = (k == 1) ? 2.5 : 5
    d = (k == 1) ? '../table2_c1_paper_schemes' : '../table2_c2_paper_schemes'
    set title sprintf("C = %g C*", C)
    plot for [s = 1:3] (k == 1 && s == 3 ? '../table2_paper_schemes_seed3' : s == 1 ? d : d.'_seed'.s).'/flowcurve.csv' \
             u ($1 == C && $13 > 0 ? $4 * (0.93 + 0.035 * s) : 1/0):($13 / t2(C, $2)):($14 / t2(C, $2)) \
             w yerrorbars pt 7 ps 1.2 lc s t sprintf('preset=paper, seed %d', s), \
         for [s = 1:3] (s == 1 ? '../paper' : '../paper_seed'.s).'/flowcurve.csv' \
             u ($1 == C && $13 > 0 ? $4 * (1.045 + 0.035 * s) : 1/0):($13 / t2(C, $2)) \
             w p pt 6 ps 1.1 lc rgb 'gray50' t (s == 1 ? 'Shepard weights, exact sweep (seeds 1-3)' : ''), \
         1 w l lc 'gray30' notitle, 1.03 w l dt 2 lc 'gray50' t '± 3 %', 0.97 w l dt 2 lc 'gray50' notitle
}
unset multiplot
