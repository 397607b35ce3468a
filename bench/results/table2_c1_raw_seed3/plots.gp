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
set yrange [5.34834e-05:230013]
set logscale x2
set x2label 'Wi = γ̇τ_λ'
set xtics nomirror
set xrange [0.0666667:45]
set x2range [0.0666667:45]
set xtics (0.1, 0.3, 1, 3, 10, 30)
set x2tics (0.1, 0.3, 1, 3, 10, 30)
set title "C = 2.5 C*\n{/*0.8 Carreau fit: η_0 = 2.34 ± 0.018 mPa s, λ = 2.7 ± 0.09 s, n = 0.343 ± 0.0043}" font ',12'
plot 'flowcurve.csv' u ($1==2.5&&$13>0?$2:1/0):13:14 w yerrorbars pt 7 ps 1.3 lc 1 t 'total', 'flowcurve.csv' u ($1==2.5&&$15>0?$2:1/0):15:16 w yerrorbars pt 5 ps 1.3 lc 2 t 'fluid', 'flowcurve.csv' u ($1==2.5&&$17>0?$2:1/0):17:18 w yerrorbars pt 9 ps 1.3 lc 3 t 'polymer', 'flowcurve.csv' u ($1==2.5&&$19>0?$2:1/0):19:20 w yerrorbars pt 11 ps 1.3 lc 4 t 'interaction', \
     0.90000000000000013 + (2.3445280505102248 - 0.90000000000000013) * (1 + (2.698019621907024 * x)**2)**((0.34288936988114083 - 1) / 2) w l lw 2 lc 1 t 'Carreau fit of the total', \
     0.8999999999999998 + (2.5259999999999994 - 0.8999999999999998) * (1 + (3.0503999999999998 * x)**2)**((0.34410000000000002 - 1) / 2) w l dt 4 lw 2 lc 'gray30' t '2018 Table II Carreau, λ scaled to this τ_λ', \
     0.90000000000000013 w l dt 2 lc 1 t 'η_∞ = 0.9 mPa s (held fixed)', 0.99999999999999978 w l dt 3 lc 2 t 'solvent η = 1 mPa s'
unset logscale y
set format y '%.2f'
set ylabel 'run / Table II Carreau'
set yrange [0.85:1.15]
set key top right
t2c0(x) = 0.8999999999999998 + (2.5259999999999994 - 0.8999999999999998) * (1 + (3.0503999999999998 * x)**2)**((0.34410000000000002 - 1) / 2)
set title "C = 2.5 C*: total viscosity over 2018 Table II's Carreau curve" font ',12'
plot 'flowcurve.csv' u ($1==2.5&&$13>0?$2:1/0):($13/t2c0($2)):($14/t2c0($2)) w yerrorbars pt 7 ps 1.3 lc 1 t 'this run (error from the correlation time)', 1 w l lc 'gray30' notitle, 1.03 w l dt 2 lc 'gray50' t '± 3 %', 0.97 w l dt 2 lc 'gray50' notitle
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
0.416667,-0.0123078
0.833333,-0.0241746
1.25,-0.0356006
1.66667,-0.0465862
2.08333,-0.0571318
2.5,-0.0672377
2.91667,-0.0769045
3.33333,-0.0861326
3.75,-0.0949224
4.16667,-0.103274
4.58333,-0.111189
5,-0.118668
5.41667,-0.125711
5.83333,-0.132318
6.25,-0.138492
6.66667,-0.144232
7.08333,-0.14954
7.5,-0.154417
7.91667,-0.158865
8.33333,-0.162884
8.75,-0.166477
9.16667,-0.169646
9.58333,-0.172393
10,-0.174723
10.4167,-0.176639
10.8333,-0.178147
11.25,-0.179255
11.6667,-0.179979
12.0833,-0.180349
12.5,-0.180446
12.9167,-0.180349
13.3333,-0.179979
13.75,-0.179255
14.1667,-0.178147
14.5833,-0.176639
15,-0.174723
15.4167,-0.172393
15.8333,-0.169646
16.25,-0.166477
16.6667,-0.162884
17.0833,-0.158865
17.5,-0.154417
17.9167,-0.14954
18.3333,-0.144232
18.75,-0.138492
19.1667,-0.132318
19.5833,-0.125711
20,-0.118668
20.4167,-0.111189
20.8333,-0.103274
21.25,-0.0949224
21.6667,-0.0861326
22.0833,-0.0769045
22.5,-0.0672377
22.9167,-0.0571318
23.3333,-0.0465862
23.75,-0.0356006
24.1667,-0.0241746
24.5833,-0.0123078
25,0
25.4167,0.0123078
25.8333,0.0241746
26.25,0.0356006
26.6667,0.0465862
27.0833,0.0571318
27.5,0.0672377
27.9167,0.0769045
28.3333,0.0861326
28.75,0.0949224
29.1667,0.103274
29.5833,0.111189
30,0.118668
30.4167,0.125711
30.8333,0.132318
31.25,0.138492
31.6667,0.144232
32.0833,0.14954
32.5,0.154417
32.9167,0.158865
33.3333,0.162884
33.75,0.166477
34.1667,0.169646
34.5833,0.172393
35,0.174723
35.4167,0.176639
35.8333,0.178147
36.25,0.179255
36.6667,0.179979
37.0833,0.180349
37.5,0.180446
37.9167,0.180349
38.3333,0.179979
38.75,0.179255
39.1667,0.178147
39.5833,0.176639
40,0.174723
40.4167,0.172393
40.8333,0.169646
41.25,0.166477
41.6667,0.162884
42.0833,0.158865
42.5,0.154417
42.9167,0.14954
43.3333,0.144232
43.75,0.138492
44.1667,0.132318
44.5833,0.125711
45,0.118668
45.4167,0.111189
45.8333,0.103274
46.25,0.0949224
46.6667,0.0861326
47.0833,0.0769045
47.5,0.0672377
47.9167,0.0571318
48.3333,0.0465862
48.75,0.0356006
49.1667,0.0241746
49.5833,0.0123078
50,0
EOD
$table2carreau0 << EOD
0,-0
0.416667,-0.0122603
0.833333,-0.0240803
1.25,-0.0354602
1.66667,-0.0464004
2.08333,-0.0569013
2.5,-0.0669633
2.91667,-0.0765869
3.33333,-0.0857726
3.75,-0.0945208
4.16667,-0.102832
4.58333,-0.110707
5,-0.118147
5.41667,-0.125151
5.83333,-0.131722
6.25,-0.137859
6.66667,-0.143565
7.08333,-0.148839
7.5,-0.153683
7.91667,-0.158099
8.33333,-0.162087
8.75,-0.165652
9.16667,-0.168793
9.58333,-0.171515
10,-0.17382
10.4167,-0.175714
10.8333,-0.177201
11.25,-0.178292
11.6667,-0.179001
12.0833,-0.179359
12.5,-0.179451
12.9167,-0.179359
13.3333,-0.179001
13.75,-0.178292
14.1667,-0.177201
14.5833,-0.175714
15,-0.17382
15.4167,-0.171515
15.8333,-0.168793
16.25,-0.165652
16.6667,-0.162087
17.0833,-0.158099
17.5,-0.153683
17.9167,-0.148839
18.3333,-0.143565
18.75,-0.137859
19.1667,-0.131722
19.5833,-0.125151
20,-0.118147
20.4167,-0.110707
20.8333,-0.102832
21.25,-0.0945208
21.6667,-0.0857726
22.0833,-0.0765869
22.5,-0.0669633
22.9167,-0.0569013
23.3333,-0.0464004
23.75,-0.0354602
24.1667,-0.0240803
24.5833,-0.0122603
25,0
25.4167,0.0122603
25.8333,0.0240803
26.25,0.0354602
26.6667,0.0464004
27.0833,0.0569013
27.5,0.0669633
27.9167,0.0765869
28.3333,0.0857726
28.75,0.0945208
29.1667,0.102832
29.5833,0.110707
30,0.118147
30.4167,0.125151
30.8333,0.131722
31.25,0.137859
31.6667,0.143565
32.0833,0.148839
32.5,0.153683
32.9167,0.158099
33.3333,0.162087
33.75,0.165652
34.1667,0.168793
34.5833,0.171515
35,0.17382
35.4167,0.175714
35.8333,0.177201
36.25,0.178292
36.6667,0.179001
37.0833,0.179359
37.5,0.179451
37.9167,0.179359
38.3333,0.179001
38.75,0.178292
39.1667,0.177201
39.5833,0.175714
40,0.17382
40.4167,0.171515
40.8333,0.168793
41.25,0.165652
41.6667,0.162087
42.0833,0.158099
42.5,0.153683
42.9167,0.148839
43.3333,0.143565
43.75,0.137859
44.1667,0.131722
44.5833,0.125151
45,0.118147
45.4167,0.110707
45.8333,0.102832
46.25,0.0945208
46.6667,0.0857726
47.0833,0.0765869
47.5,0.0669633
47.9167,0.0569013
48.3333,0.0464004
48.75,0.0354602
49.1667,0.0240803
49.5833,0.0122603
50,0
EOD
set output 'velocity.png'
set multiplot layout 1,1 title "Reverse Poiseuille flow (+g above L_y/2, -g below), last third of the run, block errors\n{/*0.85 ".scene."}"
set xlabel 'y (μm)'
set ylabel 'v_x (mm/s)'
set key top left
set xrange [0:50]
set offsets 0, 0, graph 0.1, graph 0.1
set title 'C = 2.5 C*, g = 2.358 m/s^2, box 10 × 10 × 10 σ' font ',12'
plot 'profile_C2.5.csv' u ($20>0?$1*5:1/0):($12*5000.0000000000009):($13*5000.0000000000009) w yerrorbars pt 7 ps 1.2 lc 1 t 'fluid v_x (slabs holding blob rows)', \
     '' u ($1*5):($14*5000.0000000000009):($15*5000.0000000000009) w yerrorbars pt 6 ps 1.8 lc 2 t 'polymer drift u_x', \
     (x < 25 ? -1 : 1) * 0.00050293402855480871 * (x < 25 ? x : x - 25) * (25 - (x < 25 ? x : x - 25)) w l dt 2 lw 2 lc 'black' t "Newtonian, η_0 = 2.34 mPa s: (g/2ν_0) y′(L_y/2 - y′)", \
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
set title 'C = 2.5 C*' font ',12'
plot 'profile_C2.5.csv' u ($20>0?$1*5:1/0):2:3 w yerrorbars pt 7 lc 1 t 'fluid n_i (kernel)', \
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
set title 'C = 2.5 C*' font ',12'
set object 1 rect from first 3.34e+06, graph 0 to graph 1, graph 1 fc rgb '#e4ecf7' fs solid noborder behind
plot NaN w filledcurves fc rgb '#e4ecf7' t 'measured window (profiles)', 'rp_start_C2.5.csv' u ($1*1):($3*5000.0000000000009) w l lw 2 lc 1 t 'fluid', '' u ($1*1):($4*5000.0000000000009) w l lw 2 lc 2 t 'polymer', \
     0.078583441961688871 w l dt 2 lw 2 lc 'black' t 'Newtonian, η_0 (steady)', 0.18044630016162622 w l lw 2 lc 3 t 'Carreau fluid of the fit (steady)'
unset multiplot
unset object 1
set output 'startup.png'
set xrange [0:*]
set yrange [*:*]
set multiplot layout 1,1 title "Lees-Edwards start-up: the total viscosity of each half block over the measured mean (start-up: points; measured: line)\n{/*0.85 ".scene."}"
set xlabel 't / τ_λ'
set ylabel 'η / η (measured)'
set key bottom right font ',11'
set title 'C = 2.5 C*' font ',12'
plot 1 w l dt 2 lc 'black' notitle, 'startup_C2.5.csv' u ($1 == 0.1 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 1 t 'Wi = 0.1', '' u ($1 == 0.1 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 1 notitle, 'startup_C2.5.csv' u ($1 == 0.3 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 2 t 'Wi = 0.3', '' u ($1 == 0.3 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 2 notitle, 'startup_C2.5.csv' u ($1 == 1 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 3 t 'Wi = 1', '' u ($1 == 1 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 3 notitle, 'startup_C2.5.csv' u ($1 == 3 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 4 t 'Wi = 3', '' u ($1 == 3 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 4 notitle, 'startup_C2.5.csv' u ($1 == 10 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 5 t 'Wi = 10', '' u ($1 == 10 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 5 notitle, 'startup_C2.5.csv' u ($1 == 30 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 6 t 'Wi = 30', '' u ($1 == 30 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 6 notitle
unset multiplot
