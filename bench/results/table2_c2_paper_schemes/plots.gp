set encoding utf8
set datafile separator ','
set terminal pngcairo enhanced size 1250,1100 font 'Sans,13' linewidth 1.5
set key box opaque samplen 4 spacing 1.2 font ',11'
set grid lc rgb '#e0e0e0'
set bars small
set pointsize 1.1
set title font ',13'
scene = "RaPiD polymer blobs in the SPH fluid: τ_λ = 1 s, α = 500 kT, P_0 = 0.13 Pa, solvent η = 1 mPa s, σ = 5 μm, no fluid fluctuations"
tau = 1
set output 'flowcurve.png'
set multiplot layout 2,1 title "Lees-Edwards flow curves, stress split (block errors)\n{/*0.85 ".scene."}"
set logscale xy
set format y '%g'
set xlabel 'shear rate γ̇ (1/s)'
set ylabel 'viscosity η (mPa s)'
set key top right
set yrange [0.000606973:650565]
set logscale x2
set x2label 'Wi = γ̇τ_λ'
set xtics nomirror
set xrange [0.0666667:45]
set x2range [0.0666667:45]
set xtics (0.1, 0.3, 1, 3, 10, 30)
set x2tics (0.1, 0.3, 1, 3, 10, 30)
set title "C = 5 C*\n{/*0.8 Carreau fit: η_0 = 6.51 ± 0.03 mPa s, λ = 2.05 ± 0.03 s, n = 0 ± 0.004}" font ',12'
plot 'flowcurve.csv' u ($1==5&&$13>0?$2:1/0):13:14 w yerrorbars pt 7 ps 1.3 lc 1 t 'total', 'flowcurve.csv' u ($1==5&&$15>0?$2:1/0):15:16 w yerrorbars pt 5 ps 1.3 lc 2 t 'fluid', 'flowcurve.csv' u ($1==5&&$17>0?$2:1/0):17:18 w yerrorbars pt 9 ps 1.3 lc 3 t 'polymer', 'flowcurve.csv' u ($1==5&&$19>0?$2:1/0):19:20 w yerrorbars pt 11 ps 1.3 lc 4 t 'interaction', \
     0.90000000000000013 + (6.509049965465854 - 0.90000000000000013) * (1 + (2.0474328886229562 * x)**2)**((0 - 1.0) / 2) w l lw 2 lc 1 t 'Carreau fit of the total', \
     0.8999999999999998 + (6.6687999999999983 - 0.8999999999999998) * (1 + (2.1408 * x)**2)**((0.00080000000000000004 - 1.0) / 2) w l dt 4 lw 2 lc 'gray30' t '2018 Table II Carreau, λ scaled to this τ_λ', \
     0.90000000000000013 w l dt 2 lc 1 t 'η_∞ = 0.9 mPa s (held fixed)', 0.99999999999999978 w l dt 3 lc 2 t 'solvent η = 1 mPa s'
unset logscale y
set format y '%.2f'
set ylabel 'run / Table II Carreau'
set yrange [0.85:1.15]
set key top right
t2c0(x) = 0.8999999999999998 + (6.6687999999999983 - 0.8999999999999998) * (1 + (2.1408 * x)**2)**((0.00080000000000000004 - 1.0) / 2)
set title "C = 5 C*: total viscosity over 2018 Table II's Carreau curve" font ',12'
plot 'flowcurve.csv' u ($1==5&&$13>0?$2:1/0):($13/t2c0($2)):($14/t2c0($2)) w yerrorbars pt 7 ps 1.3 lc 1 t 'this run (error from the correlation time)', 1 w l lc 'gray30' notitle, 1.03 w l dt 2 lc 'gray50' t '± 3 %', 0.97 w l dt 2 lc 'gray50' notitle
unset multiplot
unset logscale
unset x2tics
unset x2label
set xtics mirror autofreq
set offsets 0, 0, 0, 0
set xrange [*:*]
set yrange [*:*]
$carreau0 << EOD
0,-0
0.416667,-0.0123053
0.833333,-0.0241504
1.25,-0.0355355
1.66667,-0.0464604
2.08333,-0.0569253
2.5,-0.0669301
2.91667,-0.0764747
3.33333,-0.0855593
3.75,-0.0941838
4.16667,-0.102348
4.58333,-0.110053
5,-0.117297
5.41667,-0.124081
5.83333,-0.130405
6.25,-0.13627
6.66667,-0.141674
7.08333,-0.146618
7.5,-0.151103
7.91667,-0.155127
8.33333,-0.158692
8.75,-0.161798
9.16667,-0.164444
9.58333,-0.166632
10,-0.168364
10.4167,-0.169642
10.8333,-0.170482
11.25,-0.170942
11.6667,-0.171167
12.0833,-0.171274
12.5,-0.171307
12.9167,-0.171274
13.3333,-0.171167
13.75,-0.170942
14.1667,-0.170482
14.5833,-0.169642
15,-0.168364
15.4167,-0.166632
15.8333,-0.164444
16.25,-0.161798
16.6667,-0.158692
17.0833,-0.155127
17.5,-0.151103
17.9167,-0.146618
18.3333,-0.141674
18.75,-0.13627
19.1667,-0.130405
19.5833,-0.124081
20,-0.117297
20.4167,-0.110053
20.8333,-0.102348
21.25,-0.0941838
21.6667,-0.0855593
22.0833,-0.0764747
22.5,-0.0669301
22.9167,-0.0569253
23.3333,-0.0464604
23.75,-0.0355355
24.1667,-0.0241504
24.5833,-0.0123053
25,0
25.4167,0.0123053
25.8333,0.0241504
26.25,0.0355355
26.6667,0.0464604
27.0833,0.0569253
27.5,0.0669301
27.9167,0.0764747
28.3333,0.0855593
28.75,0.0941838
29.1667,0.102348
29.5833,0.110053
30,0.117297
30.4167,0.124081
30.8333,0.130405
31.25,0.13627
31.6667,0.141674
32.0833,0.146618
32.5,0.151103
32.9167,0.155127
33.3333,0.158692
33.75,0.161798
34.1667,0.164444
34.5833,0.166632
35,0.168364
35.4167,0.169642
35.8333,0.170482
36.25,0.170942
36.6667,0.171167
37.0833,0.171274
37.5,0.171307
37.9167,0.171274
38.3333,0.171167
38.75,0.170942
39.1667,0.170482
39.5833,0.169642
40,0.168364
40.4167,0.166632
40.8333,0.164444
41.25,0.161798
41.6667,0.158692
42.0833,0.155127
42.5,0.151103
42.9167,0.146618
43.3333,0.141674
43.75,0.13627
44.1667,0.130405
44.5833,0.124081
45,0.117297
45.4167,0.110053
45.8333,0.102348
46.25,0.0941838
46.6667,0.0855593
47.0833,0.0764747
47.5,0.0669301
47.9167,0.0569253
48.3333,0.0464604
48.75,0.0355355
49.1667,0.0241504
49.5833,0.0123053
50,0
EOD
$table2carreau0 << EOD
0,-0
0.416667,-0.0123219
0.833333,-0.0241837
1.25,-0.0355854
1.66667,-0.0465271
2.08333,-0.0570087
2.5,-0.0670303
2.91667,-0.0765918
3.33333,-0.0856933
3.75,-0.0943347
4.16667,-0.102516
4.58333,-0.110238
5,-0.117499
5.41667,-0.1243
5.83333,-0.130642
6.25,-0.136523
6.66667,-0.141945
7.08333,-0.146907
7.5,-0.151409
7.91667,-0.155451
8.33333,-0.159033
8.75,-0.162157
9.16667,-0.164821
9.58333,-0.167027
10,-0.168775
10.4167,-0.170071
10.8333,-0.170925
11.25,-0.171393
11.6667,-0.171616
12.0833,-0.171722
12.5,-0.171753
12.9167,-0.171722
13.3333,-0.171616
13.75,-0.171393
14.1667,-0.170925
14.5833,-0.170071
15,-0.168775
15.4167,-0.167027
15.8333,-0.164821
16.25,-0.162157
16.6667,-0.159033
17.0833,-0.155451
17.5,-0.151409
17.9167,-0.146907
18.3333,-0.141945
18.75,-0.136523
19.1667,-0.130642
19.5833,-0.1243
20,-0.117499
20.4167,-0.110238
20.8333,-0.102516
21.25,-0.0943347
21.6667,-0.0856933
22.0833,-0.0765918
22.5,-0.0670303
22.9167,-0.0570087
23.3333,-0.0465271
23.75,-0.0355854
24.1667,-0.0241837
24.5833,-0.0123219
25,0
25.4167,0.0123219
25.8333,0.0241837
26.25,0.0355854
26.6667,0.0465271
27.0833,0.0570087
27.5,0.0670303
27.9167,0.0765918
28.3333,0.0856933
28.75,0.0943347
29.1667,0.102516
29.5833,0.110238
30,0.117499
30.4167,0.1243
30.8333,0.130642
31.25,0.136523
31.6667,0.141945
32.0833,0.146907
32.5,0.151409
32.9167,0.155451
33.3333,0.159033
33.75,0.162157
34.1667,0.164821
34.5833,0.167027
35,0.168775
35.4167,0.170071
35.8333,0.170925
36.25,0.171393
36.6667,0.171616
37.0833,0.171722
37.5,0.171753
37.9167,0.171722
38.3333,0.171616
38.75,0.171393
39.1667,0.170925
39.5833,0.170071
40,0.168775
40.4167,0.167027
40.8333,0.164821
41.25,0.162157
41.6667,0.159033
42.0833,0.155451
42.5,0.151409
42.9167,0.146907
43.3333,0.141945
43.75,0.136523
44.1667,0.130642
44.5833,0.1243
45,0.117499
45.4167,0.110238
45.8333,0.102516
46.25,0.0943347
46.6667,0.0856933
47.0833,0.0765918
47.5,0.0670303
47.9167,0.0570087
48.3333,0.0465271
48.75,0.0355854
49.1667,0.0241837
49.5833,0.0123219
50,0
EOD
set output 'velocity.png'
set multiplot layout 1,1 title "Reverse Poiseuille flow (+g above L_y/2, -g below), last third of the run, block errors\n{/*0.85 ".scene."}"
set xlabel 'y (μm)'
set ylabel 'v_x (mm/s)'
set key top left
set xrange [0:50]
set offsets 0, 0, graph 0.1, graph 0.1
set title 'C = 5 C*, g = 2.385 m/s^2, box 10 × 10 × 10 σ' font ',12'
plot 'profile_C5.csv' u ($20>0?$1*5:1/0):($12*5000.0000000000009):($13*5000.0000000000009) w yerrorbars pt 7 ps 1.2 lc 1 t 'fluid v_x (slabs holding blob rows)', \
     '' u ($1*5):($14*5000.0000000000009):($15*5000.0000000000009) w yerrorbars pt 6 ps 1.8 lc 2 t 'polymer drift u_x', \
     (x < 25 ? -1 : 1) * 0.00018322461075370887 * (x < 25 ? x : x - 25) * (25 - (x < 25 ? x : x - 25)) w l dt 2 lw 2 lc 'black' t "Newtonian, η_0 = 6.51 mPa s: (g/2ν_0) y′(L_y/2 - y′)", \
     '' u ($1*5):(($14-$16)*5000.0000000000009):(sqrt($15**2+$17**2)*5000.0000000000009) w yerrorbars pt 4 ps 1.0 lc 1 t 'fluid v(r_a) at the polymers (their slabs, as u_x)', \
     $carreau0 u 1:2 w l lw 2 lc 3 t 'Carreau fluid of the fit', \
     $table2carreau0 u 1:2 w l dt 4 lw 2 lc 'gray30' t 'Carreau fluid of Table II', 0 w l lc 'gray40' notitle
unset multiplot
set output 'density.png'
set multiplot layout 1,1 title "Densities across y over their mean, reverse Poiseuille (last third of the run)\n{/*0.85 ".scene."}"
set ylabel 'density / mean'
set key top center maxrows 3 font ',10'
set offsets 0, 0, graph 0.45, graph 0.05
set object 1 rect from first 0, graph 0 to first 6.25, graph 1 fc rgb '#fbe5cf' fs solid noborder behind
set object 2 rect from first 18.75, graph 0 to first 31.25, graph 1 fc rgb '#fbe5cf' fs solid noborder behind
set object 3 rect from first 43.75, graph 0 to first 50, graph 1 fc rgb '#fbe5cf' fs solid noborder behind
set title 'C = 5 C*' font ',12'
plot 'profile_C5.csv' u ($20>0?$1*5:1/0):2:3 w yerrorbars pt 7 lc 1 t 'fluid n_i (kernel)', \
     '' u ($1*5):4:5 w yerrorlines pt 6 lc 2 t 'polymer n_a (kernel)', '' u ($1*5):6 w l dt 3 lw 2 lc 2 t 'polymer n_a, t = 0', \
     '' u ($1*5):9:10 w yerrorlines pt 1 lc 4 t 'polymer counts', '' u ($1*5):11 w l dt 3 lw 2 lc 4 t 'polymer counts, t = 0', \
     NaN w filledcurves fc rgb '#fbe5cf' t 'high shear (< L_y/8 from a plane)', 1 w l dt 2 lc 'black' notitle
unset multiplot
unset object 1
unset object 2
unset object 3
set offsets 0, 0, 0, 0
set output 'rp_start.png'
set xrange [*:*]
set multiplot layout 1,1 title "Start-up of the reverse Poiseuille flow: centre velocity (mean within L_y/8 of y = L_y/4, 3L_y/4)\n{/*0.85 ".scene."}"
set xlabel 't (μs)'
set ylabel 'centre velocity (mm/s)'
set key bottom right maxrows auto font ',11'
set offsets 0, 0, graph 0.1, 0
set yrange [0:*]
set title 'C = 5 C*' font ',12'
set object 1 rect from first 3.34e+06, graph 0 to graph 1, graph 1 fc rgb '#e4ecf7' fs solid noborder behind
plot NaN w filledcurves fc rgb '#e4ecf7' t 'measured window (profiles)', 'rp_start_C5.csv' u ($1*1):($3*5000.0000000000009) w l lw 2 lc 1 t 'fluid', '' u ($1*1):($4*5000.0000000000009) w l lw 2 lc 2 t 'polymer', \
     0.028628845430267013 w l dt 2 lw 2 lc 'black' t 'Newtonian, η_0 (steady)', 0.17130679912096178 w l lw 2 lc 3 t 'Carreau fluid of the fit (steady)'
unset multiplot
unset object 1
set output 'startup.png'
set xrange [0:*]
set yrange [*:*]
set multiplot layout 1,1 title "Lees-Edwards start-up: the total viscosity of each half block over the measured mean (start-up: points; measured: line)\n{/*0.85 ".scene."}"
set xlabel 't / τ_λ'
set ylabel 'η / η (measured)'
set key bottom right font ',11'
set title 'C = 5 C*' font ',12'
plot 1 w l dt 2 lc 'black' notitle, 'startup_C5.csv' u ($1 == 0.1 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 1 t 'Wi = 0.1', '' u ($1 == 0.1 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 1 notitle, 'startup_C5.csv' u ($1 == 0.3 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 2 t 'Wi = 0.3', '' u ($1 == 0.3 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 2 notitle, 'startup_C5.csv' u ($1 == 1 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 3 t 'Wi = 1', '' u ($1 == 1 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 3 notitle, 'startup_C5.csv' u ($1 == 3 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 4 t 'Wi = 3', '' u ($1 == 3 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 4 notitle, 'startup_C5.csv' u ($1 == 10 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 5 t 'Wi = 10', '' u ($1 == 10 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 5 notitle, 'startup_C5.csv' u ($1 == 30 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 6 t 'Wi = 30', '' u ($1 == 30 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 6 notitle
unset multiplot
