# Work-precision figure: log-log error (y) against wall seconds of stepping
# per unit of simulated time (x, one thread), one panel per (model, metric),
# one point series per integrator / precision / noise / substeps, joined in
# the order of the time step; error bars are the statistical error of each
# point (clipped at the bottom of the log axis); the dashed line is 1 %.
# Called by bench/wp.sh:
#   gnuplot -e "datafile='out/bench/wp_all.csv'; outfile='out/bench/wp.png'; panels='gibd:temperature ...'" bench/wp.gp
set datafile separator ','
np = words(panels)
ncol = (np <= 1) ? 1 : ((np <= 4) ? 2 : 3)
nrow = int(ceil(np * 1.0 / ncol))
set terminal pngcairo size 620 * ncol, 470 * nrow font ',9'
set output outfile
set multiplot layout nrow, ncol title 'work-precision: error against theory vs cost; points along a line: time steps'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'wall seconds of hcbd\_step per unit simulated time (1 thread)'
set ylabel 'error'
set key top right font ',8' samplen 2 spacing 0.9 noenhanced opaque
set grid
# one series: the rows of a panel with the given integrator/precision/noise/substeps, by dt
# (sorted by h, then dt; a blank line between values of h breaks the line)
sel(m, k, s) = sprintf("< awk -F, -v m='%s' -v k='%s' -v s='%s' 'NR > 1 && $1 == m && $2 == k && $3\"/\"$4\"/\"$5\"/\"($8 == \"\" ? 1 : $8) == s && $10 > 0' '%s' | sort -t, -k7,7g -k6,6g | awk -F, 'NR > 1 && $7 != h {print \"\"} {h = $7; print}'", m, k, s, datafile)
lo(e, d) = (e - d > e / 20) ? e - d : e / 20
do for [p = 1:np] {
    pan = word(panels, p)
    m = pan[1:strstrt(pan, ':') - 1]
    k = pan[strstrt(pan, ':') + 1:]
    series = system(sprintf("awk -F, -v m='%s' -v k='%s' 'NR > 1 && $1 == m && $2 == k && $10 > 0 {print $3\"/\"$4\"/\"$5\"/\"($8 == \"\" ? 1 : $8)}' '%s' | sort -u | tr '\\n' ' '", m, k, datafile))
    set title sprintf('%s: %s', m, k) noenhanced
    if (words(series) > 0) {
        plot for [i = 1:words(series)] sel(m, k, word(series, i)) using 9:10:(lo($10, $11)):($10 + $11) \
                 with yerrorlines lw 1.2 pt (i % 7) + 4 ps 0.9 lc i title word(series, i), \
             0.01 with lines dt 2 lc rgb 'gray40' title '1 %'
    } else {
        plot 0.01 with lines dt 2 lc rgb 'gray40' title '1 % (no points)'
    }
}
unset multiplot
