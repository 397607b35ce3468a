set encoding utf8
set datafile separator ','
set terminal pngcairo enhanced size 1640,680 font 'Sans,13' linewidth 1.5
set key box opaque samplen 4 spacing 1.2 font ',11'
set grid lc rgb '#e0e0e0'
set bars small
set pointsize 1.1
set title font ',13'
scene = "RaPiD polymer blobs in the SPH fluid: τ_λ = 1 s, α = 500 kT, P_0 = 0.13 Pa, solvent η = 1 mPa s, σ = 5 μm, no fluid fluctuations"
tau = 1
set output 'flowcurve.png'
set multiplot layout 1,2 title "Lees-Edwards flow curves, stress split (block errors)\n{/*0.85 ".scene."}"
set logscale xy
set format y '%g'
set xlabel 'shear rate γ̇ (1/s)'
set ylabel 'viscosity η (mPa s)'
set key top right
set yrange [0.000253223:1781.1]
set logscale x2
set x2label 'Wi = γ̇τ_λ'
set xtics nomirror
set xrange [0.0666667:45]
set x2range [0.0666667:45]
set xtics (0.1, 0.3, 1, 3, 10, 30)
set x2tics (0.1, 0.3, 1, 3, 10, 30)
set title "C = 2.5 C*\n{/*0.8 Carreau fit: η_0 = 2.32 ± 0.02 mPa s, λ = 3.17 ± 0.13 s, n = 0.374 ± 0.0043}" font ',12'
plot 'flowcurve.csv' u ($1==2.5&&$13>0?$2:1/0):13:14 w yerrorbars pt 7 ps 1.3 lc 1 t 'total', 'flowcurve.csv' u ($1==2.5&&$15>0?$2:1/0):15:16 w yerrorbars pt 5 ps 1.3 lc 2 t 'fluid', 'flowcurve.csv' u ($1==2.5&&$17>0?$2:1/0):17:18 w yerrorbars pt 9 ps 1.3 lc 3 t 'polymer', 'flowcurve.csv' u ($1==2.5&&$19>0?$2:1/0):19:20 w yerrorbars pt 11 ps 1.3 lc 4 t 'interaction', \
     0.90000000000000013 + (2.3166648012363811 - 0.90000000000000013) * (1 + (3.1654978888370109 * x)**2)**((0.37360119743635112 - 1) / 2) w l lw 2 lc 1 t 'Carreau fit of the total', \
     0.8999999999999998 + (2.5259999999999994 - 0.8999999999999998) * (1 + (3.0503999999999998 * x)**2)**((0.34410000000000002 - 1) / 2) w l dt 4 lw 2 lc 'gray30' t '2018 Table II Carreau, λ scaled to this τ_λ', \
     0.90000000000000013 w l dt 2 lc 1 t 'η_∞ = 0.9 mPa s (held fixed)', 0.99999999999999978 w l dt 3 lc 2 t 'solvent η = 1 mPa s'
set title "C = 5 C*\n{/*0.8 Carreau fit: η_0 = 6.07 ± 0.041 mPa s, λ = 1.93 ± 0.029 s, n = 0.0376 ± 0.0037}" font ',12'
plot 'flowcurve.csv' u ($1==5&&$13>0?$2:1/0):13:14 w yerrorbars pt 7 ps 1.3 lc 1 t 'total', 'flowcurve.csv' u ($1==5&&$15>0?$2:1/0):15:16 w yerrorbars pt 5 ps 1.3 lc 2 t 'fluid', 'flowcurve.csv' u ($1==5&&$17>0?$2:1/0):17:18 w yerrorbars pt 9 ps 1.3 lc 3 t 'polymer', 'flowcurve.csv' u ($1==5&&$19>0?$2:1/0):19:20 w yerrorbars pt 11 ps 1.3 lc 4 t 'interaction', \
     0.90000000000000013 + (6.0722983467671163 - 0.90000000000000013) * (1 + (1.9334993982883049 * x)**2)**((0.037628761398731295 - 1) / 2) w l lw 2 lc 1 t 'Carreau fit of the total', \
     0.8999999999999998 + (6.6689999999999978 - 0.8999999999999998) * (1 + (2.1408 * x)**2)**((0.00080000000000000004 - 1) / 2) w l dt 4 lw 2 lc 'gray30' t '2018 Table II Carreau, λ scaled to this τ_λ', \
     0.90000000000000013 w l dt 2 lc 1 t 'η_∞ = 0.9 mPa s (held fixed)', 0.99999999999999978 w l dt 3 lc 2 t 'solvent η = 1 mPa s'
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
0.416667,-0.0123542
0.833333,-0.0242666
1.25,-0.0357375
1.66667,-0.0467673
2.08333,-0.0573563
2.5,-0.0675051
2.91667,-0.077214
3.33333,-0.0864835
3.75,-0.0953142
4.16667,-0.103707
4.58333,-0.111661
5,-0.119179
5.41667,-0.12626
5.83333,-0.132906
6.25,-0.139117
6.66667,-0.144894
7.08333,-0.150238
7.5,-0.155151
7.91667,-0.159634
8.33333,-0.163689
8.75,-0.167316
9.16667,-0.170519
9.58333,-0.173301
10,-0.175663
10.4167,-0.177611
10.8333,-0.179151
11.25,-0.180289
11.6667,-0.18104
12.0833,-0.181429
12.5,-0.181531
12.9167,-0.181429
13.3333,-0.18104
13.75,-0.180289
14.1667,-0.179151
14.5833,-0.177611
15,-0.175663
15.4167,-0.173301
15.8333,-0.170519
16.25,-0.167316
16.6667,-0.163689
17.0833,-0.159634
17.5,-0.155151
17.9167,-0.150238
18.3333,-0.144894
18.75,-0.139117
19.1667,-0.132906
19.5833,-0.12626
20,-0.119179
20.4167,-0.111661
20.8333,-0.103707
21.25,-0.0953142
21.6667,-0.0864835
22.0833,-0.077214
22.5,-0.0675051
22.9167,-0.0573563
23.3333,-0.0467673
23.75,-0.0357375
24.1667,-0.0242666
24.5833,-0.0123542
25,0
25.4167,0.0123542
25.8333,0.0242666
26.25,0.0357375
26.6667,0.0467673
27.0833,0.0573563
27.5,0.0675051
27.9167,0.077214
28.3333,0.0864835
28.75,0.0953142
29.1667,0.103707
29.5833,0.111661
30,0.119179
30.4167,0.12626
30.8333,0.132906
31.25,0.139117
31.6667,0.144894
32.0833,0.150238
32.5,0.155151
32.9167,0.159634
33.3333,0.163689
33.75,0.167316
34.1667,0.170519
34.5833,0.173301
35,0.175663
35.4167,0.177611
35.8333,0.179151
36.25,0.180289
36.6667,0.18104
37.0833,0.181429
37.5,0.181531
37.9167,0.181429
38.3333,0.18104
38.75,0.180289
39.1667,0.179151
39.5833,0.177611
40,0.175663
40.4167,0.173301
40.8333,0.170519
41.25,0.167316
41.6667,0.163689
42.0833,0.159634
42.5,0.155151
42.9167,0.150238
43.3333,0.144894
43.75,0.139117
44.1667,0.132906
44.5833,0.12626
45,0.119179
45.4167,0.111661
45.8333,0.103707
46.25,0.0953142
46.6667,0.0864835
47.0833,0.077214
47.5,0.0675051
47.9167,0.0573563
48.3333,0.0467673
48.75,0.0357375
49.1667,0.0242666
49.5833,0.0123542
50,0
EOD
$carreau1 << EOD
0,-0
0.416667,-0.0123289
0.833333,-0.0241932
1.25,-0.0355927
1.66667,-0.0465278
2.08333,-0.0569984
2.5,-0.0670047
2.91667,-0.0765467
3.33333,-0.0856247
3.75,-0.0942387
4.16667,-0.102389
4.58333,-0.110075
5,-0.117299
5.41667,-0.124059
5.83333,-0.130356
6.25,-0.13619
6.66667,-0.141562
7.08333,-0.146472
7.5,-0.150921
7.91667,-0.154909
8.33333,-0.158437
8.75,-0.161507
9.16667,-0.164119
9.58333,-0.166276
10,-0.167982
10.4167,-0.169244
10.8333,-0.170083
11.25,-0.17056
11.6667,-0.170801
12.0833,-0.170918
12.5,-0.170953
12.9167,-0.170918
13.3333,-0.170801
13.75,-0.17056
14.1667,-0.170083
14.5833,-0.169244
15,-0.167982
15.4167,-0.166276
15.8333,-0.164119
16.25,-0.161507
16.6667,-0.158437
17.0833,-0.154909
17.5,-0.150921
17.9167,-0.146472
18.3333,-0.141562
18.75,-0.13619
19.1667,-0.130356
19.5833,-0.124059
20,-0.117299
20.4167,-0.110075
20.8333,-0.102389
21.25,-0.0942387
21.6667,-0.0856247
22.0833,-0.0765467
22.5,-0.0670047
22.9167,-0.0569984
23.3333,-0.0465278
23.75,-0.0355927
24.1667,-0.0241932
24.5833,-0.0123289
25,0
25.4167,0.0123289
25.8333,0.0241932
26.25,0.0355927
26.6667,0.0465278
27.0833,0.0569984
27.5,0.0670047
27.9167,0.0765467
28.3333,0.0856247
28.75,0.0942387
29.1667,0.102389
29.5833,0.110075
30,0.117299
30.4167,0.124059
30.8333,0.130356
31.25,0.13619
31.6667,0.141562
32.0833,0.146472
32.5,0.150921
32.9167,0.154909
33.3333,0.158437
33.75,0.161507
34.1667,0.164119
34.5833,0.166276
35,0.167982
35.4167,0.169244
35.8333,0.170083
36.25,0.17056
36.6667,0.170801
37.0833,0.170918
37.5,0.170953
37.9167,0.170918
38.3333,0.170801
38.75,0.17056
39.1667,0.170083
39.5833,0.169244
40,0.167982
40.4167,0.166276
40.8333,0.164119
41.25,0.161507
41.6667,0.158437
42.0833,0.154909
42.5,0.150921
42.9167,0.146472
43.3333,0.141562
43.75,0.13619
44.1667,0.130356
44.5833,0.124059
45,0.117299
45.4167,0.110075
45.8333,0.102389
46.25,0.0942387
46.6667,0.0856247
47.0833,0.0765467
47.5,0.0670047
47.9167,0.0569984
48.3333,0.0465278
48.75,0.0355927
49.1667,0.0241932
49.5833,0.0123289
50,0
EOD
set output 'velocity.png'
set multiplot layout 1,2 title "Reverse Poiseuille flow (+g above L_y/2, -g below), last third of the run, block errors\n{/*0.85 ".scene."}"
set xlabel 'y (μm)'
set ylabel 'v_x (mm/s)'
set key top left
set xrange [0:50]
set offsets 0, 0, graph 0.1, graph 0.1
set title 'C = 2.5 C*, g = 2.37 m/s^2, box 10 × 10 × 10 σ' font ',12'
plot 'profile_C2.5.csv' u ($20>0?$1*5:1/0):($12*5000.0000000000009):($13*5000.0000000000009) w yerrorbars pt 7 ps 1.2 lc 1 t 'fluid v_x (slabs holding blob rows)', \
     '' u ($1*5):($14*5000.0000000000009):($15*5000.0000000000009) w yerrorbars pt 6 ps 1.2 lc 2 t 'polymer drift u_x', \
     (x < 25 ? -1 : 1) * 0.00051143557130008403 * (x < 25 ? x : x - 25) * (25 - (x < 25 ? x : x - 25)) w l dt 2 lw 2 lc 'black' t "Newtonian, η_0 = 2.32 mPa s: (g/2ν_0) y′(L_y/2 - y′)", \
     $carreau0 u 1:2 w l lw 2 lc 3 t 'Carreau fluid of the fit', 0 w l lc 'gray40' notitle
set title 'C = 5 C*, g = 2.42 m/s^2, box 10 × 10 × 10 σ' font ',12'
plot 'profile_C5.csv' u ($20>0?$1*5:1/0):($12*5000.0000000000009):($13*5000.0000000000009) w yerrorbars pt 7 ps 1.2 lc 1 t 'fluid v_x (slabs holding blob rows)', \
     '' u ($1*5):($14*5000.0000000000009):($15*5000.0000000000009) w yerrorbars pt 6 ps 1.2 lc 2 t 'polymer drift u_x', \
     (x < 25 ? -1 : 1) * 0.00019926080028917121 * (x < 25 ? x : x - 25) * (25 - (x < 25 ? x : x - 25)) w l dt 2 lw 2 lc 'black' t "Newtonian, η_0 = 6.07 mPa s: (g/2ν_0) y′(L_y/2 - y′)", \
     $carreau1 u 1:2 w l lw 2 lc 3 t 'Carreau fluid of the fit', 0 w l lc 'gray40' notitle
unset multiplot
set output 'density.png'
set multiplot layout 1,2 title "Densities across y over their mean, reverse Poiseuille (last third of the run)\n{/*0.85 ".scene."}"
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
set multiplot layout 1,2 title "Start-up of the reverse Poiseuille flow: centre velocity (mean within L_y/8 of y = L_y/4, 3L_y/4)\n{/*0.85 ".scene."}"
set xlabel 't (μs)'
set ylabel 'centre velocity (mm/s)'
set key bottom right maxrows auto font ',11'
set offsets 0, 0, graph 0.1, 0
set yrange [0:*]
set title 'C = 2.5 C*' font ',12'
set object 1 rect from first 3.34e+06, graph 0 to graph 1, graph 1 fc rgb '#e4ecf7' fs solid noborder behind
plot NaN w filledcurves fc rgb '#e4ecf7' t 'measured window (profiles)', 'rp_start_C2.5.csv' u ($1*1):($3*5000.0000000000009) w l lw 2 lc 1 t 'fluid', '' u ($1*1):($4*5000.0000000000009) w l lw 2 lc 2 t 'polymer', \
     0.079911808015638131 w l dt 2 lw 2 lc 'black' t 'Newtonian, η_0 (steady)', 0.18153081749745775 w l lw 2 lc 3 t 'Carreau fluid of the fit (steady)'
set title 'C = 5 C*' font ',12'
set object 1 rect from first 3.34e+06, graph 0 to graph 1, graph 1 fc rgb '#e4ecf7' fs solid noborder behind
plot NaN w filledcurves fc rgb '#e4ecf7' t 'measured window (profiles)', 'rp_start_C5.csv' u ($1*1):($3*5000.0000000000009) w l lw 2 lc 1 t 'fluid', '' u ($1*1):($4*5000.0000000000009) w l lw 2 lc 2 t 'polymer', \
     0.031134500045182999 w l dt 2 lw 2 lc 'black' t 'Newtonian, η_0 (steady)', 0.17095315743690614 w l lw 2 lc 3 t 'Carreau fluid of the fit (steady)'
unset multiplot
unset object 1
