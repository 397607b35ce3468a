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
set yrange [0.000342675:245771]
set logscale x2
set x2label 'Wi = γ̇τ_λ'
set xtics nomirror
set xrange [0.0666667:45]
set x2range [0.0666667:45]
set xtics (0.1, 0.3, 1, 3, 10, 30)
set x2tics (0.1, 0.3, 1, 3, 10, 30)
set title "C = 2.5 C*\n{/*0.8 Carreau fit: η_0 = 2.55 ± 0.035 mPa s, λ = 3.62 ± 0.17 s, n = 0.354 ± 0.0039}" font ',12'
plot 'flowcurve.csv' u ($1==2.5&&$13>0?$2:1/0):13:14 w yerrorbars pt 7 ps 1.3 lc 1 t 'total', 'flowcurve.csv' u ($1==2.5&&$15>0?$2:1/0):15:16 w yerrorbars pt 5 ps 1.3 lc 2 t 'fluid', 'flowcurve.csv' u ($1==2.5&&$17>0?$2:1/0):17:18 w yerrorbars pt 9 ps 1.3 lc 3 t 'polymer', 'flowcurve.csv' u ($1==2.5&&$19>0?$2:1/0):19:20 w yerrorbars pt 11 ps 1.3 lc 4 t 'interaction', \
     0.90000000000000013 + (2.5540896341088488 - 0.90000000000000013) * (1 + (3.6245760432553094 * x)**2)**((0.35422273829406525 - 1) / 2) w l lw 2 lc 1 t 'Carreau fit of the total', \
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
0.416667,-0.012315
0.833333,-0.0241892
1.25,-0.035623
1.66667,-0.0466167
2.08333,-0.0571707
2.5,-0.0672854
2.91667,-0.0769613
3.33333,-0.0861987
3.75,-0.0949983
4.16667,-0.10336
4.58333,-0.111286
5,-0.118775
5.41667,-0.125829
5.83333,-0.132448
6.25,-0.138633
6.66667,-0.144385
7.08333,-0.149705
7.5,-0.154595
7.91667,-0.159055
8.33333,-0.163088
8.75,-0.166694
9.16667,-0.169876
9.58333,-0.172638
10,-0.174981
10.4167,-0.17691
10.8333,-0.178432
11.25,-0.179553
11.6667,-0.180287
12.0833,-0.180661
12.5,-0.180756
12.9167,-0.180661
13.3333,-0.180287
13.75,-0.179553
14.1667,-0.178432
14.5833,-0.17691
15,-0.174981
15.4167,-0.172638
15.8333,-0.169876
16.25,-0.166694
16.6667,-0.163088
17.0833,-0.159055
17.5,-0.154595
17.9167,-0.149705
18.3333,-0.144385
18.75,-0.138633
19.1667,-0.132448
19.5833,-0.125829
20,-0.118775
20.4167,-0.111286
20.8333,-0.10336
21.25,-0.0949983
21.6667,-0.0861987
22.0833,-0.0769613
22.5,-0.0672854
22.9167,-0.0571707
23.3333,-0.0466167
23.75,-0.035623
24.1667,-0.0241892
24.5833,-0.012315
25,0
25.4167,0.012315
25.8333,0.0241892
26.25,0.035623
26.6667,0.0466167
27.0833,0.0571707
27.5,0.0672854
27.9167,0.0769613
28.3333,0.0861987
28.75,0.0949983
29.1667,0.10336
29.5833,0.111286
30,0.118775
30.4167,0.125829
30.8333,0.132448
31.25,0.138633
31.6667,0.144385
32.0833,0.149705
32.5,0.154595
32.9167,0.159055
33.3333,0.163088
33.75,0.166694
34.1667,0.169876
34.5833,0.172638
35,0.174981
35.4167,0.17691
35.8333,0.178432
36.25,0.179553
36.6667,0.180287
37.0833,0.180661
37.5,0.180756
37.9167,0.180661
38.3333,0.180287
38.75,0.179553
39.1667,0.178432
39.5833,0.17691
40,0.174981
40.4167,0.172638
40.8333,0.169876
41.25,0.166694
41.6667,0.163088
42.0833,0.159055
42.5,0.154595
42.9167,0.149705
43.3333,0.144385
43.75,0.138633
44.1667,0.132448
44.5833,0.125829
45,0.118775
45.4167,0.111286
45.8333,0.10336
46.25,0.0949983
46.6667,0.0861987
47.0833,0.0769613
47.5,0.0672854
47.9167,0.0571707
48.3333,0.0466167
48.75,0.035623
49.1667,0.0241892
49.5833,0.012315
50,0
EOD
$table2carreau0 << EOD
0,-0
0.416667,-0.0122616
0.833333,-0.0240827
1.25,-0.0354637
1.66667,-0.0464049
2.08333,-0.0569069
2.5,-0.0669699
2.91667,-0.0765945
3.33333,-0.085781
3.75,-0.0945301
4.16667,-0.102842
4.58333,-0.110718
5,-0.118158
5.41667,-0.125164
5.83333,-0.131735
6.25,-0.137873
6.66667,-0.143579
7.08333,-0.148853
7.5,-0.153698
7.91667,-0.158114
8.33333,-0.162104
8.75,-0.165668
9.16667,-0.16881
9.58333,-0.171532
10,-0.173837
10.4167,-0.175731
10.8333,-0.177219
11.25,-0.17831
11.6667,-0.179019
12.0833,-0.179377
12.5,-0.17947
12.9167,-0.179377
13.3333,-0.179019
13.75,-0.17831
14.1667,-0.177219
14.5833,-0.175731
15,-0.173837
15.4167,-0.171532
15.8333,-0.16881
16.25,-0.165668
16.6667,-0.162104
17.0833,-0.158114
17.5,-0.153698
17.9167,-0.148853
18.3333,-0.143579
18.75,-0.137873
19.1667,-0.131735
19.5833,-0.125164
20,-0.118158
20.4167,-0.110718
20.8333,-0.102842
21.25,-0.0945301
21.6667,-0.085781
22.0833,-0.0765945
22.5,-0.0669699
22.9167,-0.0569069
23.3333,-0.0464049
23.75,-0.0354637
24.1667,-0.0240827
24.5833,-0.0122616
25,0
25.4167,0.0122616
25.8333,0.0240827
26.25,0.0354637
26.6667,0.0464049
27.0833,0.0569069
27.5,0.0669699
27.9167,0.0765945
28.3333,0.085781
28.75,0.0945301
29.1667,0.102842
29.5833,0.110718
30,0.118158
30.4167,0.125164
30.8333,0.131735
31.25,0.137873
31.6667,0.143579
32.0833,0.148853
32.5,0.153698
32.9167,0.158114
33.3333,0.162104
33.75,0.165668
34.1667,0.16881
34.5833,0.171532
35,0.173837
35.4167,0.175731
35.8333,0.177219
36.25,0.17831
36.6667,0.179019
37.0833,0.179377
37.5,0.17947
37.9167,0.179377
38.3333,0.179019
38.75,0.17831
39.1667,0.177219
39.5833,0.175731
40,0.173837
40.4167,0.171532
40.8333,0.16881
41.25,0.165668
41.6667,0.162104
42.0833,0.158114
42.5,0.153698
42.9167,0.148853
43.3333,0.143579
43.75,0.137873
44.1667,0.131735
44.5833,0.125164
45,0.118158
45.4167,0.110718
45.8333,0.102842
46.25,0.0945301
46.6667,0.085781
47.0833,0.0765945
47.5,0.0669699
47.9167,0.0569069
48.3333,0.0464049
48.75,0.0354637
49.1667,0.0240827
49.5833,0.0122616
50,0
EOD
set output 'velocity.png'
set multiplot layout 1,1 title "Reverse Poiseuille flow (+g above L_y/2, -g below), last third of the run, block errors\n{/*0.85 ".scene."}"
set xlabel 'y (μm)'
set ylabel 'v_x (mm/s)'
set key top left
set xrange [0:50]
set offsets 0, 0, graph 0.1, graph 0.1
set title 'C = 2.5 C*, g = 2.359 m/s^2, box 10 × 10 × 10 σ' font ',12'
plot 'profile_C2.5.csv' u ($20>0?$1*5:1/0):($12*5000.0000000000009):($13*5000.0000000000009) w yerrorbars pt 7 ps 1.2 lc 1 t 'fluid v_x (slabs holding blob rows)', \
     '' u ($1*5):($14*5000.0000000000009):($15*5000.0000000000009) w yerrorbars pt 6 ps 1.8 lc 2 t 'polymer drift u_x', \
     (x < 25 ? -1 : 1) * 0.00046171141318464065 * (x < 25 ? x : x - 25) * (25 - (x < 25 ? x : x - 25)) w l dt 2 lw 2 lc 'black' t "Newtonian, η_0 = 2.55 mPa s: (g/2ν_0) y′(L_y/2 - y′)", \
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
     0.072142408310100103 w l dt 2 lw 2 lc 'black' t 'Newtonian, η_0 (steady)', 0.18075590743841993 w l lw 2 lc 3 t 'Carreau fluid of the fit (steady)'
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
