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
set yrange [0.000272116:242839]
set logscale x2
set x2label 'Wi = γ̇τ_λ'
set xtics nomirror
set xrange [0.0666667:45]
set x2range [0.0666667:45]
set xtics (0.1, 0.3, 1, 3, 10, 30)
set x2tics (0.1, 0.3, 1, 3, 10, 30)
set title "C = 2.5 C*\n{/*0.8 Carreau fit: η_0 = 2.57 ± 0.045 mPa s, λ = 3.76 ± 0.22 s, n = 0.361 ± 0.0063}" font ',12'
plot 'flowcurve.csv' u ($1==2.5&&$13>0?$2:1/0):13:14 w yerrorbars pt 7 ps 1.3 lc 1 t 'total', 'flowcurve.csv' u ($1==2.5&&$15>0?$2:1/0):15:16 w yerrorbars pt 5 ps 1.3 lc 2 t 'fluid', 'flowcurve.csv' u ($1==2.5&&$17>0?$2:1/0):17:18 w yerrorbars pt 9 ps 1.3 lc 3 t 'polymer', 'flowcurve.csv' u ($1==2.5&&$19>0?$2:1/0):19:20 w yerrorbars pt 11 ps 1.3 lc 4 t 'interaction', \
     0.90000000000000013 + (2.5681487121323276 - 0.90000000000000013) * (1 + (3.7627978743655377 * x)**2)**((0.36072593812044085 - 1.0) / 2) w l lw 2 lc 1 t 'Carreau fit of the total', \
     0.8999999999999998 + (2.5259999999999994 - 0.8999999999999998) * (1 + (3.0503999999999998 * x)**2)**((0.34410000000000002 - 1.0) / 2) w l dt 4 lw 2 lc 'gray30' t '2018 Table II Carreau, λ scaled to this τ_λ', \
     0.90000000000000013 w l dt 2 lc 1 t 'η_∞ = 0.9 mPa s (held fixed)', 0.99999999999999978 w l dt 3 lc 2 t 'solvent η = 1 mPa s'
unset logscale y
set format y '%.2f'
set ylabel 'run / Table II Carreau'
set yrange [0.85:1.15]
set key top right
t2c0(x) = 0.8999999999999998 + (2.5259999999999994 - 0.8999999999999998) * (1 + (3.0503999999999998 * x)**2)**((0.34410000000000002 - 1.0) / 2)
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
0.416667,-0.0124026
0.833333,-0.0243612
1.25,-0.0358764
1.66667,-0.0469483
2.08333,-0.0575775
2.5,-0.0677643
2.91667,-0.0775092
3.33333,-0.0868125
3.75,-0.095675
4.16667,-0.104097
4.58333,-0.112079
5,-0.119622
5.41667,-0.126727
5.83333,-0.133394
6.25,-0.139624
6.66667,-0.145418
7.08333,-0.150777
7.5,-0.155703
7.91667,-0.160196
8.33333,-0.164259
8.75,-0.167893
9.16667,-0.1711
9.58333,-0.173883
10,-0.176245
10.4167,-0.178191
10.8333,-0.179726
11.25,-0.180859
11.6667,-0.181601
12.0833,-0.181981
12.5,-0.182077
12.9167,-0.181981
13.3333,-0.181601
13.75,-0.180859
14.1667,-0.179726
14.5833,-0.178191
15,-0.176245
15.4167,-0.173883
15.8333,-0.1711
16.25,-0.167893
16.6667,-0.164259
17.0833,-0.160196
17.5,-0.155703
17.9167,-0.150777
18.3333,-0.145418
18.75,-0.139624
19.1667,-0.133394
19.5833,-0.126727
20,-0.119622
20.4167,-0.112079
20.8333,-0.104097
21.25,-0.095675
21.6667,-0.0868125
22.0833,-0.0775092
22.5,-0.0677643
22.9167,-0.0575775
23.3333,-0.0469483
23.75,-0.0358764
24.1667,-0.0243612
24.5833,-0.0124026
25,0
25.4167,0.0124026
25.8333,0.0243612
26.25,0.0358764
26.6667,0.0469483
27.0833,0.0575775
27.5,0.0677643
27.9167,0.0775092
28.3333,0.0868125
28.75,0.095675
29.1667,0.104097
29.5833,0.112079
30,0.119622
30.4167,0.126727
30.8333,0.133394
31.25,0.139624
31.6667,0.145418
32.0833,0.150777
32.5,0.155703
32.9167,0.160196
33.3333,0.164259
33.75,0.167893
34.1667,0.1711
34.5833,0.173883
35,0.176245
35.4167,0.178191
35.8333,0.179726
36.25,0.180859
36.6667,0.181601
37.0833,0.181981
37.5,0.182077
37.9167,0.181981
38.3333,0.181601
38.75,0.180859
39.1667,0.179726
39.5833,0.178191
40,0.176245
40.4167,0.173883
40.8333,0.1711
41.25,0.167893
41.6667,0.164259
42.0833,0.160196
42.5,0.155703
42.9167,0.150777
43.3333,0.145418
43.75,0.139624
44.1667,0.133394
44.5833,0.126727
45,0.119622
45.4167,0.112079
45.8333,0.104097
46.25,0.095675
46.6667,0.0868125
47.0833,0.0775092
47.5,0.0677643
47.9167,0.0575775
48.3333,0.0469483
48.75,0.0358764
49.1667,0.0243612
49.5833,0.0124026
50,0
EOD
$table2carreau0 << EOD
0,-0
0.416667,-0.0123653
0.833333,-0.0242865
1.25,-0.0357641
1.66667,-0.0467983
2.08333,-0.0573896
2.5,-0.0675384
2.91667,-0.0772452
3.33333,-0.0865103
3.75,-0.0953344
4.16667,-0.103718
4.58333,-0.111662
5,-0.119166
5.41667,-0.126232
5.83333,-0.132861
6.25,-0.139052
6.66667,-0.144808
7.08333,-0.150129
7.5,-0.155016
7.91667,-0.159472
8.33333,-0.163497
8.75,-0.167094
9.16667,-0.170264
9.58333,-0.173011
10,-0.175338
10.4167,-0.17725
10.8333,-0.178752
11.25,-0.179854
11.6667,-0.180571
12.0833,-0.180933
12.5,-0.181026
12.9167,-0.180933
13.3333,-0.180571
13.75,-0.179854
14.1667,-0.178752
14.5833,-0.17725
15,-0.175338
15.4167,-0.173011
15.8333,-0.170264
16.25,-0.167094
16.6667,-0.163497
17.0833,-0.159472
17.5,-0.155016
17.9167,-0.150129
18.3333,-0.144808
18.75,-0.139052
19.1667,-0.132861
19.5833,-0.126232
20,-0.119166
20.4167,-0.111662
20.8333,-0.103718
21.25,-0.0953344
21.6667,-0.0865103
22.0833,-0.0772452
22.5,-0.0675384
22.9167,-0.0573896
23.3333,-0.0467983
23.75,-0.0357641
24.1667,-0.0242865
24.5833,-0.0123653
25,0
25.4167,0.0123653
25.8333,0.0242865
26.25,0.0357641
26.6667,0.0467983
27.0833,0.0573896
27.5,0.0675384
27.9167,0.0772452
28.3333,0.0865103
28.75,0.0953344
29.1667,0.103718
29.5833,0.111662
30,0.119166
30.4167,0.126232
30.8333,0.132861
31.25,0.139052
31.6667,0.144808
32.0833,0.150129
32.5,0.155016
32.9167,0.159472
33.3333,0.163497
33.75,0.167094
34.1667,0.170264
34.5833,0.173011
35,0.175338
35.4167,0.17725
35.8333,0.178752
36.25,0.179854
36.6667,0.180571
37.0833,0.180933
37.5,0.181026
37.9167,0.180933
38.3333,0.180571
38.75,0.179854
39.1667,0.178752
39.5833,0.17725
40,0.175338
40.4167,0.173011
40.8333,0.170264
41.25,0.167094
41.6667,0.163497
42.0833,0.159472
42.5,0.155016
42.9167,0.150129
43.3333,0.144808
43.75,0.139052
44.1667,0.132861
44.5833,0.126232
45,0.119166
45.4167,0.111662
45.8333,0.103718
46.25,0.0953344
46.6667,0.0865103
47.0833,0.0772452
47.5,0.0675384
47.9167,0.0573896
48.3333,0.0467983
48.75,0.0357641
49.1667,0.0242865
49.5833,0.0123653
50,0
EOD
set output 'velocity.png'
set multiplot layout 1,1 title "Reverse Poiseuille flow (+g above L_y/2, -g below), last third of the run, block errors\n{/*0.85 ".scene."}"
set xlabel 'y (μm)'
set ylabel 'v_x (mm/s)'
set key top left
set xrange [0:50]
set offsets 0, 0, graph 0.1, graph 0.1
set title 'C = 2.5 C*, g = 2.377 m/s^2, box 10 × 10 × 10 σ' font ',12'
plot 'profile_C2.5.csv' u ($20>0?$1*5:1/0):($12*5000.0000000000009):($13*5000.0000000000009) w yerrorbars pt 7 ps 1.2 lc 1 t 'fluid v_x (slabs holding blob rows)', \
     '' u ($1*5):($14*5000.0000000000009):($15*5000.0000000000009) w yerrorbars pt 6 ps 1.8 lc 2 t 'polymer drift u_x', \
     (x < 25 ? -1 : 1) * 0.00046284793347768009 * (x < 25 ? x : x - 25) * (25 - (x < 25 ? x : x - 25)) w l dt 2 lw 2 lc 'black' t "Newtonian, η_0 = 2.57 mPa s: (g/2ν_0) y′(L_y/2 - y′)", \
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
     0.072319989605887508 w l dt 2 lw 2 lc 'black' t 'Newtonian, η_0 (steady)', 0.18207665061609413 w l lw 2 lc 3 t 'Carreau fluid of the fit (steady)'
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
