# SPH work-precision against LAMMPS (bench/peers/wp_sph.sh): run in the
# folder of the wp_sph_<fluid>_<code>_<integrator>.dat series it writes
# (dt, s per time unit, |error against the code's finest step|, nu_fit /
# nu K); draws wp_sph.png.  One panel per fluid; points along a line are
# time steps, the largest at the left (the finest, the reference, is left
# out); LAMMPS's line ends where its step
# goes unstable.  The 1 % line dashed.
set terminal pngcairo size 1300,520 font ",10" enhanced
set output "wp_sph.png"
set multiplot layout 1,2 title "Tait SPH fluid, transverse-wave viscosity, 1 thread: run time against error (bench/peers/wp\\_sph.sh)"
set logscale xy
set xlabel "seconds per unit of simulated time"
set ylabel "|{/Symbol n}_{fit}(dt) / {/Symbol n}_{fit}(finest dt) - 1|"
set key top right
set grid
set yrange [1e-5:0.3]
set arrow 1 from graph 0, first 0.01 to graph 1, first 0.01 nohead dt 2 lc rgb "gray"
do for [fl in "viscous acoustic"] {
    set title (fl eq "viscous" ? "viscous: {/Symbol n} / (c_s h) = 3.3 (Table I), dt_{visc} = 0.030" : \
               "acoustic: {/Symbol n} / (c_s h) = 0.2, dt_{visc} = 0.5, 0.25 h / c_s = 0.2")
    plot "wp_sph_".fl."_lammps_fixsph.dat" using 2:3 with linespoints lw 2 title "LAMMPS sph/taitwater/morris + fix sph", \
         "wp_sph_".fl."_hcbd_exact.dat" using 2:3 with linespoints lw 2 title "hcbd, exact pair sweep (default)", \
         "wp_sph_".fl."_hcbd_euler.dat" using 2:3 with linespoints title "hcbd, the papers' Euler pairs"
}
unset multiplot
