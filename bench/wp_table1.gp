# bench/results/wp_table1.csv (make bench-wp-table1): the viscosity's
# deviation from the resolved reference (the first row of each Wi) against
# the wall time per tau_lambda, one point per (dt, fluid sub-steps).
set datafile separator ','
set terminal pngcairo size 1300,480 font 'Sans,11'
set output 'wp_table1.png'
set multiplot layout 1,3 title "Table I, C = 5 C*: viscosity error against cost (labels: dt in us / fluid sub-steps)"
set xlabel 'wall seconds per {/Symbol t}_{/Symbol l} (2 threads)'
set ylabel '({/Symbol h} - {/Symbol h}_{ref}) / {/Symbol h}_{ref}  (%)'
set grid
set key off
do for [wi in "0.3 1 3"] {
    set title sprintf('Wi = %s', wi)
    stats 'wp_table1.csv' u ($3 == wi + 0 && $6 == 0 && $7 == 0 ? $4 : 1/0) nooutput
    ref = STATS_max
    plot 'wp_table1.csv' u ($3 == wi + 0 ? $13 : 1/0):(100 * $6 / ref):(100 * $7 / ref) w yerrorbars pt 7, \
         '' u ($3 == wi + 0 ? $13 : 1/0):(100 * $6 / ref):(sprintf('%g/%g', $1, $2)) w labels offset 0,1 font ',9', \
         1 dt 2 lc 'gray', -1 dt 2 lc 'gray'
}
unset multiplot
