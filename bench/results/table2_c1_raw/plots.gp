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
set yrange [0.000113607:239911]
set logscale x2
set x2label 'Wi = γ̇τ_λ'
set xtics nomirror
set xrange [0.0666667:45]
set x2range [0.0666667:45]
set xtics (0.1, 0.3, 1, 3, 10, 30)
set x2tics (0.1, 0.3, 1, 3, 10, 30)
set title "C = 2.5 C*\n{/*0.8 Carreau fit: η_0 = 2.48 ± 0.021 mPa s, λ = 3.27 ± 0.11 s, n = 0.353 ± 0.0033}" font ',12'
plot 'flowcurve.csv' u ($1==2.5&&$13>0?$2:1/0):13:14 w yerrorbars pt 7 ps 1.3 lc 1 t 'total', 'flowcurve.csv' u ($1==2.5&&$15>0?$2:1/0):15:16 w yerrorbars pt 5 ps 1.3 lc 2 t 'fluid', 'flowcurve.csv' u ($1==2.5&&$17>0?$2:1/0):17:18 w yerrorbars pt 9 ps 1.3 lc 3 t 'polymer', 'flowcurve.csv' u ($1==2.5&&$19>0?$2:1/0):19:20 w yerrorbars pt 11 ps 1.3 lc 4 t 'interaction', \
     0.90000000000000013 + (2.4845862815921111 - 0.90000000000000013) * (1 + (3.2701485858736339 * x)**2)**((0.35348585112655317 - 1) / 2) w l lw 2 lc 1 t 'Carreau fit of the total', \
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
0.416667,-0.01229
0.833333,-0.0241396
1.25,-0.0355492
1.66667,-0.046519
2.08333,-0.0570496
2.5,-0.0671413
2.91667,-0.0767945
3.33333,-0.0860098
3.75,-0.0947876
4.16667,-0.103128
4.58333,-0.111033
5,-0.118502
5.41667,-0.125536
5.83333,-0.132135
6.25,-0.138302
6.66667,-0.144036
7.08333,-0.149338
7.5,-0.154211
7.91667,-0.158654
8.33333,-0.162671
8.75,-0.166262
9.16667,-0.16943
9.58333,-0.172178
10,-0.174508
10.4167,-0.176426
10.8333,-0.177937
11.25,-0.179049
11.6667,-0.179776
12.0833,-0.180147
12.5,-0.180242
12.9167,-0.180147
13.3333,-0.179776
13.75,-0.179049
14.1667,-0.177937
14.5833,-0.176426
15,-0.174508
15.4167,-0.172178
15.8333,-0.16943
16.25,-0.166262
16.6667,-0.162671
17.0833,-0.158654
17.5,-0.154211
17.9167,-0.149338
18.3333,-0.144036
18.75,-0.138302
19.1667,-0.132135
19.5833,-0.125536
20,-0.118502
20.4167,-0.111033
20.8333,-0.103128
21.25,-0.0947876
21.6667,-0.0860098
22.0833,-0.0767945
22.5,-0.0671413
22.9167,-0.0570496
23.3333,-0.046519
23.75,-0.0355492
24.1667,-0.0241396
24.5833,-0.01229
25,0
25.4167,0.01229
25.8333,0.0241396
26.25,0.0355492
26.6667,0.046519
27.0833,0.0570496
27.5,0.0671413
27.9167,0.0767945
28.3333,0.0860098
28.75,0.0947876
29.1667,0.103128
29.5833,0.111033
30,0.118502
30.4167,0.125536
30.8333,0.132135
31.25,0.138302
31.6667,0.144036
32.0833,0.149338
32.5,0.154211
32.9167,0.158654
33.3333,0.162671
33.75,0.166262
34.1667,0.16943
34.5833,0.172178
35,0.174508
35.4167,0.176426
35.8333,0.177937
36.25,0.179049
36.6667,0.179776
37.0833,0.180147
37.5,0.180242
37.9167,0.180147
38.3333,0.179776
38.75,0.179049
39.1667,0.177937
39.5833,0.176426
40,0.174508
40.4167,0.172178
40.8333,0.16943
41.25,0.166262
41.6667,0.162671
42.0833,0.158654
42.5,0.154211
42.9167,0.149338
43.3333,0.144036
43.75,0.138302
44.1667,0.132135
44.5833,0.125536
45,0.118502
45.4167,0.111033
45.8333,0.103128
46.25,0.0947876
46.6667,0.0860098
47.0833,0.0767945
47.5,0.0671413
47.9167,0.0570496
48.3333,0.046519
48.75,0.0355492
49.1667,0.0241396
49.5833,0.01229
50,0
EOD
$table2carreau0 << EOD
0,-0
0.416667,-0.0122584
0.833333,-0.0240764
1.25,-0.0354545
1.66667,-0.0463929
2.08333,-0.0568921
2.5,-0.0669525
2.91667,-0.0765745
3.33333,-0.0857587
3.75,-0.0945055
4.16667,-0.102815
4.58333,-0.110689
5,-0.118128
5.41667,-0.125131
5.83333,-0.131701
6.25,-0.137837
6.66667,-0.143541
7.08333,-0.148814
7.5,-0.153658
7.91667,-0.158073
8.33333,-0.162061
8.75,-0.165624
9.16667,-0.168765
9.58333,-0.171486
10,-0.173791
10.4167,-0.175685
10.8333,-0.177172
11.25,-0.178263
11.6667,-0.178972
12.0833,-0.17933
12.5,-0.179422
12.9167,-0.17933
13.3333,-0.178972
13.75,-0.178263
14.1667,-0.177172
14.5833,-0.175685
15,-0.173791
15.4167,-0.171486
15.8333,-0.168765
16.25,-0.165624
16.6667,-0.162061
17.0833,-0.158073
17.5,-0.153658
17.9167,-0.148814
18.3333,-0.143541
18.75,-0.137837
19.1667,-0.131701
19.5833,-0.125131
20,-0.118128
20.4167,-0.110689
20.8333,-0.102815
21.25,-0.0945055
21.6667,-0.0857587
22.0833,-0.0765745
22.5,-0.0669525
22.9167,-0.0568921
23.3333,-0.0463929
23.75,-0.0354545
24.1667,-0.0240764
24.5833,-0.0122584
25,0
25.4167,0.0122584
25.8333,0.0240764
26.25,0.0354545
26.6667,0.0463929
27.0833,0.0568921
27.5,0.0669525
27.9167,0.0765745
28.3333,0.0857587
28.75,0.0945055
29.1667,0.102815
29.5833,0.110689
30,0.118128
30.4167,0.125131
30.8333,0.131701
31.25,0.137837
31.6667,0.143541
32.0833,0.148814
32.5,0.153658
32.9167,0.158073
33.3333,0.162061
33.75,0.165624
34.1667,0.168765
34.5833,0.171486
35,0.173791
35.4167,0.175685
35.8333,0.177172
36.25,0.178263
36.6667,0.178972
37.0833,0.17933
37.5,0.179422
37.9167,0.17933
38.3333,0.178972
38.75,0.178263
39.1667,0.177172
39.5833,0.175685
40,0.173791
40.4167,0.171486
40.8333,0.168765
41.25,0.165624
41.6667,0.162061
42.0833,0.158073
42.5,0.153658
42.9167,0.148814
43.3333,0.143541
43.75,0.137837
44.1667,0.131701
44.5833,0.125131
45,0.118128
45.4167,0.110689
45.8333,0.102815
46.25,0.0945055
46.6667,0.0857587
47.0833,0.0765745
47.5,0.0669525
47.9167,0.0568921
48.3333,0.0463929
48.75,0.0354545
49.1667,0.0240764
49.5833,0.0122584
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
     (x < 25 ? -1 : 1) * 0.00047451108019064254 * (x < 25 ? x : x - 25) * (25 - (x < 25 ? x : x - 25)) w l dt 2 lw 2 lc 'black' t "Newtonian, η_0 = 2.48 mPa s: (g/2ν_0) y′(L_y/2 - y′)", \
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
     0.074142356279787894 w l dt 2 lw 2 lc 'black' t 'Newtonian, η_0 (steady)', 0.18024190133428786 w l lw 2 lc 3 t 'Carreau fluid of the fit (steady)'
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
