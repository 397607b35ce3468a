# Work-precision against LAMMPS (bench/peers/wp.sh): run in the folder of
# wp_peers.csv and the wp_*.dat series it writes (dt, s per time unit,
# |T_conf error|, its error, g_err, g_floor); draws wp_peers.png.  Left:
# |T_conf error| against seconds per unit of simulated time (points along a
# line are time steps, the largest at the left), the 0.5 % line dashed;
# right: the rms distance of g(r) from the reference, its statistical floor
# dashed.
set terminal pngcairo size 1300,520 font ",10" enhanced
set output "wp_peers.png"
set multiplot layout 1,2 title "Star fluid (f = 128, n# = 0.24), 1 thread: run time against error, hcbd and LAMMPS (bench/peers/wp.sh)"
set logscale xy
set xlabel "seconds per unit of simulated time"
set key top right
set grid
set ylabel "|T_{conf} - T_{conf}(reference)|"
set arrow 1 from graph 0, first 0.005 to graph 1, first 0.005 nohead dt 2 lc rgb "gray"
plot "wp_lammps_brownian_em.dat" using 2:($3 + 1e-5):4 with yerrorlines lw 2 title "LAMMPS fix brownian (Euler-Maruyama)", \
     "wp_hcbd_bd_em.dat" using 2:($3 + 1e-5):4 with yerrorlines title "hcbd BD, Euler-Maruyama", \
     "wp_hcbd_bd_lm.dat" using 2:($3 + 1e-5):4 with yerrorlines title "hcbd BD, Leimkuhler-Matthews", \
     "wp_hcbd_gibd_euler_em.dat" using 2:($3 + 1e-5):4 with yerrorlines title "hcbd GI-BD, the papers' Euler", \
     "wp_hcbd_gibd_exact_lm.dat" using 2:($3 + 1e-5):4 with yerrorlines title "hcbd GI-BD, exact sweep + LM"
unset arrow 1
set ylabel "rms |g(r) - g_{ref}(r)|, r in [0.5, 3)"
plot "wp_lammps_brownian_em.dat" using 2:5 with linespoints lw 2 title "LAMMPS fix brownian", \
     "wp_hcbd_bd_em.dat" using 2:5 with linespoints title "hcbd BD, EM", \
     "wp_hcbd_bd_lm.dat" using 2:5 with linespoints title "hcbd BD, LM", \
     "wp_hcbd_gibd_euler_em.dat" using 2:5 with linespoints title "hcbd GI-BD, Euler", \
     "wp_hcbd_gibd_exact_lm.dat" using 2:5 with linespoints title "hcbd GI-BD, exact + LM", \
     "wp_hcbd_bd_lm.dat" using 2:6 with lines dt 2 lc rgb "gray" title "statistical floor (BD LM)"
unset multiplot
