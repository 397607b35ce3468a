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
set yrange [0.00154749:643939]
set logscale x2
set x2label 'Wi = γ̇τ_λ'
set xtics nomirror
set xrange [0.0666667:45]
set x2range [0.0666667:45]
set xtics (0.1, 0.3, 1, 3, 10, 30)
set x2tics (0.1, 0.3, 1, 3, 10, 30)
set title "C = 5 C*\n{/*0.8 Carreau fit: η_0 = 6.59 ± 0.037 mPa s, λ = 2.4 ± 0.051 s, n = 0 ± 0.0053}" font ',12'
plot 'flowcurve.csv' u ($1==5&&$13>0?$2:1/0):13:14 w yerrorbars pt 7 ps 1.3 lc 1 t 'total', 'flowcurve.csv' u ($1==5&&$15>0?$2:1/0):15:16 w yerrorbars pt 5 ps 1.3 lc 2 t 'fluid', 'flowcurve.csv' u ($1==5&&$17>0?$2:1/0):17:18 w yerrorbars pt 9 ps 1.3 lc 3 t 'polymer', 'flowcurve.csv' u ($1==5&&$19>0?$2:1/0):19:20 w yerrorbars pt 11 ps 1.3 lc 4 t 'interaction', \
     0.90000000000000013 + (6.5856078114663221 - 0.90000000000000013) * (1 + (2.4010635008786707 * x)**2)**((0 - 1.0) / 2) w l lw 2 lc 1 t 'Carreau fit of the total', \
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
0.416667,-0.012375
0.833333,-0.0242933
1.25,-0.035755
1.66667,-0.0467601
2.08333,-0.0573085
2.5,-0.0674003
2.91667,-0.0770354
3.33333,-0.0862139
3.75,-0.0949358
4.16667,-0.103201
4.58333,-0.11101
5,-0.118362
5.41667,-0.125257
5.83333,-0.131696
6.25,-0.137678
6.66667,-0.143204
7.08333,-0.148273
7.5,-0.152886
7.91667,-0.157042
8.33333,-0.160742
8.75,-0.163985
9.16667,-0.166772
9.58333,-0.169104
10,-0.170981
10.4167,-0.172404
10.8333,-0.173381
11.25,-0.173938
11.6667,-0.174191
12.0833,-0.174301
12.5,-0.174333
12.9167,-0.174301
13.3333,-0.174191
13.75,-0.173938
14.1667,-0.173381
14.5833,-0.172404
15,-0.170981
15.4167,-0.169104
15.8333,-0.166772
16.25,-0.163985
16.6667,-0.160742
17.0833,-0.157042
17.5,-0.152886
17.9167,-0.148273
18.3333,-0.143204
18.75,-0.137678
19.1667,-0.131696
19.5833,-0.125257
20,-0.118362
20.4167,-0.11101
20.8333,-0.103201
21.25,-0.0949358
21.6667,-0.0862139
22.0833,-0.0770354
22.5,-0.0674003
22.9167,-0.0573085
23.3333,-0.0467601
23.75,-0.035755
24.1667,-0.0242933
24.5833,-0.012375
25,0
25.4167,0.012375
25.8333,0.0242933
26.25,0.035755
26.6667,0.0467601
27.0833,0.0573085
27.5,0.0674003
27.9167,0.0770354
28.3333,0.0862139
28.75,0.0949358
29.1667,0.103201
29.5833,0.11101
30,0.118362
30.4167,0.125257
30.8333,0.131696
31.25,0.137678
31.6667,0.143204
32.0833,0.148273
32.5,0.152886
32.9167,0.157042
33.3333,0.160742
33.75,0.163985
34.1667,0.166772
34.5833,0.169104
35,0.170981
35.4167,0.172404
35.8333,0.173381
36.25,0.173938
36.6667,0.174191
37.0833,0.174301
37.5,0.174333
37.9167,0.174301
38.3333,0.174191
38.75,0.173938
39.1667,0.173381
39.5833,0.172404
40,0.170981
40.4167,0.169104
40.8333,0.166772
41.25,0.163985
41.6667,0.160742
42.0833,0.157042
42.5,0.152886
42.9167,0.148273
43.3333,0.143204
43.75,0.137678
44.1667,0.131696
44.5833,0.125257
45,0.118362
45.4167,0.11101
45.8333,0.103201
46.25,0.0949358
46.6667,0.0862139
47.0833,0.0770354
47.5,0.0674003
47.9167,0.0573085
48.3333,0.0467601
48.75,0.035755
49.1667,0.0242933
49.5833,0.012375
50,0
EOD
$table2carreau0 << EOD
0,-0
0.416667,-0.0122196
0.833333,-0.0239826
1.25,-0.0352891
1.66667,-0.0461389
2.08333,-0.0565322
2.5,-0.0664688
2.91667,-0.0759489
3.33333,-0.0849724
3.75,-0.0935394
4.16667,-0.10165
4.58333,-0.109304
5,-0.116501
5.41667,-0.123242
5.83333,-0.129526
6.25,-0.135354
6.66667,-0.140725
7.08333,-0.14564
7.5,-0.150099
7.91667,-0.154101
8.33333,-0.157647
8.75,-0.160738
9.16667,-0.163373
9.58333,-0.165552
10,-0.167279
10.4167,-0.168556
10.8333,-0.169396
11.25,-0.169854
11.6667,-0.170075
12.0833,-0.170179
12.5,-0.170211
12.9167,-0.170179
13.3333,-0.170075
13.75,-0.169854
14.1667,-0.169396
14.5833,-0.168556
15,-0.167279
15.4167,-0.165552
15.8333,-0.163373
16.25,-0.160738
16.6667,-0.157647
17.0833,-0.154101
17.5,-0.150099
17.9167,-0.14564
18.3333,-0.140725
18.75,-0.135354
19.1667,-0.129526
19.5833,-0.123242
20,-0.116501
20.4167,-0.109304
20.8333,-0.10165
21.25,-0.0935394
21.6667,-0.0849724
22.0833,-0.0759489
22.5,-0.0664688
22.9167,-0.0565322
23.3333,-0.0461389
23.75,-0.0352891
24.1667,-0.0239826
24.5833,-0.0122196
25,0
25.4167,0.0122196
25.8333,0.0239826
26.25,0.0352891
26.6667,0.0461389
27.0833,0.0565322
27.5,0.0664688
27.9167,0.0759489
28.3333,0.0849724
28.75,0.0935394
29.1667,0.10165
29.5833,0.109304
30,0.116501
30.4167,0.123242
30.8333,0.129526
31.25,0.135354
31.6667,0.140725
32.0833,0.14564
32.5,0.150099
32.9167,0.154101
33.3333,0.157647
33.75,0.160738
34.1667,0.163373
34.5833,0.165552
35,0.167279
35.4167,0.168556
35.8333,0.169396
36.25,0.169854
36.6667,0.170075
37.0833,0.170179
37.5,0.170211
37.9167,0.170179
38.3333,0.170075
38.75,0.169854
39.1667,0.169396
39.5833,0.168556
40,0.167279
40.4167,0.165552
40.8333,0.163373
41.25,0.160738
41.6667,0.157647
42.0833,0.154101
42.5,0.150099
42.9167,0.14564
43.3333,0.140725
43.75,0.135354
44.1667,0.129526
44.5833,0.123242
45,0.116501
45.4167,0.109304
45.8333,0.10165
46.25,0.0935394
46.6667,0.0849724
47.0833,0.0759489
47.5,0.0664688
47.9167,0.0565322
48.3333,0.0461389
48.75,0.0352891
49.1667,0.0239826
49.5833,0.0122196
50,0
EOD
set output 'velocity.png'
set multiplot layout 1,1 title "Reverse Poiseuille flow (+g above L_y/2, -g below), last third of the run, block errors\n{/*0.85 ".scene."}"
set xlabel 'y (μm)'
set ylabel 'v_x (mm/s)'
set key top left
set xrange [0:50]
set offsets 0, 0, graph 0.1, graph 0.1
set title 'C = 5 C*, g = 2.367 m/s^2, box 10 × 10 × 10 σ' font ',12'
plot 'profile_C5.csv' u ($20>0?$1*5:1/0):($12*5000.0000000000009):($13*5000.0000000000009) w yerrorbars pt 7 ps 1.2 lc 1 t 'fluid v_x (slabs holding blob rows)', \
     '' u ($1*5):($14*5000.0000000000009):($15*5000.0000000000009) w yerrorbars pt 6 ps 1.8 lc 2 t 'polymer drift u_x', \
     (x < 25 ? -1 : 1) * 0.00017973041580698581 * (x < 25 ? x : x - 25) * (25 - (x < 25 ? x : x - 25)) w l dt 2 lw 2 lc 'black' t "Newtonian, η_0 = 6.59 mPa s: (g/2ν_0) y′(L_y/2 - y′)", \
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
     0.028082877469841529 w l dt 2 lw 2 lc 'black' t 'Newtonian, η_0 (steady)', 0.17433332333718507 w l lw 2 lc 3 t 'Carreau fluid of the fit (steady)'
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
