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
set yrange [0.00131897:639739]
set logscale x2
set x2label 'Wi = γ̇τ_λ'
set xtics nomirror
set xrange [0.0666667:45]
set x2range [0.0666667:45]
set xtics (0.1, 0.3, 1, 3, 10, 30)
set x2tics (0.1, 0.3, 1, 3, 10, 30)
set title "C = 5 C*\n{/*0.8 Carreau fit: η_0 = 6.29 ± 0.032 mPa s, λ = 2.06 ± 0.035 s, n = 0 ± 0.0047}" font ',12'
plot 'flowcurve.csv' u ($1==5&&$13>0?$2:1/0):13:14 w yerrorbars pt 7 ps 1.3 lc 1 t 'total', 'flowcurve.csv' u ($1==5&&$15>0?$2:1/0):15:16 w yerrorbars pt 5 ps 1.3 lc 2 t 'fluid', 'flowcurve.csv' u ($1==5&&$17>0?$2:1/0):17:18 w yerrorbars pt 9 ps 1.3 lc 3 t 'polymer', 'flowcurve.csv' u ($1==5&&$19>0?$2:1/0):19:20 w yerrorbars pt 11 ps 1.3 lc 4 t 'interaction', \
     0.90000000000000013 + (6.2946956865901393 - 0.90000000000000013) * (1 + (2.0615684208027552 * x)**2)**((0 - 1.0) / 2) w l lw 2 lc 1 t 'Carreau fit of the total', \
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
0.416667,-0.012244
0.833333,-0.0240319
1.25,-0.0353636
1.66667,-0.0462393
2.08333,-0.0566589
2.5,-0.0666224
2.91667,-0.0761298
3.33333,-0.0851812
3.75,-0.0937764
4.16667,-0.101916
4.58333,-0.109599
5,-0.116826
5.41667,-0.123597
5.83333,-0.129912
6.25,-0.135771
6.66667,-0.141174
7.08333,-0.146121
7.5,-0.150612
7.91667,-0.154647
8.33333,-0.158227
8.75,-0.161351
9.16667,-0.16402
9.58333,-0.166234
10,-0.167996
10.4167,-0.169307
10.8333,-0.170181
11.25,-0.170668
11.6667,-0.170903
12.0833,-0.171014
12.5,-0.171047
12.9167,-0.171014
13.3333,-0.170903
13.75,-0.170668
14.1667,-0.170181
14.5833,-0.169307
15,-0.167996
15.4167,-0.166234
15.8333,-0.16402
16.25,-0.161351
16.6667,-0.158227
17.0833,-0.154647
17.5,-0.150612
17.9167,-0.146121
18.3333,-0.141174
18.75,-0.135771
19.1667,-0.129912
19.5833,-0.123597
20,-0.116826
20.4167,-0.109599
20.8333,-0.101916
21.25,-0.0937764
21.6667,-0.0851812
22.0833,-0.0761298
22.5,-0.0666224
22.9167,-0.0566589
23.3333,-0.0462393
23.75,-0.0353636
24.1667,-0.0240319
24.5833,-0.012244
25,0
25.4167,0.012244
25.8333,0.0240319
26.25,0.0353636
26.6667,0.0462393
27.0833,0.0566589
27.5,0.0666224
27.9167,0.0761298
28.3333,0.0851812
28.75,0.0937764
29.1667,0.101916
29.5833,0.109599
30,0.116826
30.4167,0.123597
30.8333,0.129912
31.25,0.135771
31.6667,0.141174
32.0833,0.146121
32.5,0.150612
32.9167,0.154647
33.3333,0.158227
33.75,0.161351
34.1667,0.16402
34.5833,0.166234
35,0.167996
35.4167,0.169307
35.8333,0.170181
36.25,0.170668
36.6667,0.170903
37.0833,0.171014
37.5,0.171047
37.9167,0.171014
38.3333,0.170903
38.75,0.170668
39.1667,0.170181
39.5833,0.169307
40,0.167996
40.4167,0.166234
40.8333,0.16402
41.25,0.161351
41.6667,0.158227
42.0833,0.154647
42.5,0.150612
42.9167,0.146121
43.3333,0.141174
43.75,0.135771
44.1667,0.129912
44.5833,0.123597
45,0.116826
45.4167,0.109599
45.8333,0.101916
46.25,0.0937764
46.6667,0.0851812
47.0833,0.0761298
47.5,0.0666224
47.9167,0.0566589
48.3333,0.0462393
48.75,0.0353636
49.1667,0.0240319
49.5833,0.012244
50,0
EOD
$table2carreau0 << EOD
0,-0
0.416667,-0.0122038
0.833333,-0.0239515
1.25,-0.0352431
1.66667,-0.0460787
2.08333,-0.0564583
2.5,-0.0663818
2.91667,-0.0758492
3.33333,-0.0848607
3.75,-0.0934161
4.16667,-0.101515
4.58333,-0.109159
5,-0.116346
5.41667,-0.123078
5.83333,-0.129353
6.25,-0.135172
6.66667,-0.140536
7.08333,-0.145444
7.5,-0.149896
7.91667,-0.153892
8.33333,-0.157433
8.75,-0.160518
9.16667,-0.163148
9.58333,-0.165324
10,-0.167047
10.4167,-0.168321
10.8333,-0.169159
11.25,-0.169616
11.6667,-0.169836
12.0833,-0.16994
12.5,-0.169972
12.9167,-0.16994
13.3333,-0.169836
13.75,-0.169616
14.1667,-0.169159
14.5833,-0.168321
15,-0.167047
15.4167,-0.165324
15.8333,-0.163148
16.25,-0.160518
16.6667,-0.157433
17.0833,-0.153892
17.5,-0.149896
17.9167,-0.145444
18.3333,-0.140536
18.75,-0.135172
19.1667,-0.129353
19.5833,-0.123078
20,-0.116346
20.4167,-0.109159
20.8333,-0.101515
21.25,-0.0934161
21.6667,-0.0848607
22.0833,-0.0758492
22.5,-0.0663818
22.9167,-0.0564583
23.3333,-0.0460787
23.75,-0.0352431
24.1667,-0.0239515
24.5833,-0.0122038
25,0
25.4167,0.0122038
25.8333,0.0239515
26.25,0.0352431
26.6667,0.0460787
27.0833,0.0564583
27.5,0.0663818
27.9167,0.0758492
28.3333,0.0848607
28.75,0.0934161
29.1667,0.101515
29.5833,0.109159
30,0.116346
30.4167,0.123078
30.8333,0.129353
31.25,0.135172
31.6667,0.140536
32.0833,0.145444
32.5,0.149896
32.9167,0.153892
33.3333,0.157433
33.75,0.160518
34.1667,0.163148
34.5833,0.165324
35,0.167047
35.4167,0.168321
35.8333,0.169159
36.25,0.169616
36.6667,0.169836
37.0833,0.16994
37.5,0.169972
37.9167,0.16994
38.3333,0.169836
38.75,0.169616
39.1667,0.169159
39.5833,0.168321
40,0.167047
40.4167,0.165324
40.8333,0.163148
41.25,0.160518
41.6667,0.157433
42.0833,0.153892
42.5,0.149896
42.9167,0.145444
43.3333,0.140536
43.75,0.135172
44.1667,0.129353
44.5833,0.123078
45,0.116346
45.4167,0.109159
45.8333,0.101515
46.25,0.0934161
46.6667,0.0848607
47.0833,0.0758492
47.5,0.0663818
47.9167,0.0564583
48.3333,0.0460787
48.75,0.0352431
49.1667,0.0239515
49.5833,0.0122038
50,0
EOD
set output 'velocity.png'
set multiplot layout 1,1 title "Reverse Poiseuille flow (+g above L_y/2, -g below), last third of the run, block errors\n{/*0.85 ".scene."}"
set xlabel 'y (μm)'
set ylabel 'v_x (mm/s)'
set key top left
set xrange [0:50]
set offsets 0, 0, graph 0.1, graph 0.1
set title 'C = 5 C*, g = 2.364 m/s^2, box 10 × 10 × 10 σ' font ',12'
plot 'profile_C5.csv' u ($20>0?$1*5:1/0):($12*5000.0000000000009):($13*5000.0000000000009) w yerrorbars pt 7 ps 1.2 lc 1 t 'fluid v_x (slabs holding blob rows)', \
     '' u ($1*5):($14*5000.0000000000009):($15*5000.0000000000009) w yerrorbars pt 6 ps 1.8 lc 2 t 'polymer drift u_x', \
     (x < 25 ? -1 : 1) * 0.00018781545537945073 * (x < 25 ? x : x - 25) * (25 - (x < 25 ? x : x - 25)) w l dt 2 lw 2 lc 'black' t "Newtonian, η_0 = 6.29 mPa s: (g/2ν_0) y′(L_y/2 - y′)", \
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
     0.029346164903039179 w l dt 2 lw 2 lc 'black' t 'Newtonian, η_0 (steady)', 0.17104715456833819 w l lw 2 lc 3 t 'Carreau fluid of the fit (steady)'
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
