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
set yrange [0.000261651:1834.87]
set logscale x2
set x2label 'Wi = γ̇τ_λ'
set xtics nomirror
set xrange [0.0666667:45]
set x2range [0.0666667:45]
set xtics (0.1, 0.3, 1, 3, 10, 30)
set x2tics (0.1, 0.3, 1, 3, 10, 30)
set title "C = 2.5 C*\n{/*0.8 Carreau fit: η_0 = 2.36 ± 0.017 mPa s, λ = 2.82 ± 0.092 s, n = 0.352 ± 0.0054}" font ',12'
plot 'flowcurve.csv' u ($1==2.5&&$13>0?$2:1/0):13:14 w yerrorbars pt 7 ps 1.3 lc 1 t 'total', 'flowcurve.csv' u ($1==2.5&&$15>0?$2:1/0):15:16 w yerrorbars pt 5 ps 1.3 lc 2 t 'fluid', 'flowcurve.csv' u ($1==2.5&&$17>0?$2:1/0):17:18 w yerrorbars pt 9 ps 1.3 lc 3 t 'polymer', 'flowcurve.csv' u ($1==2.5&&$19>0?$2:1/0):19:20 w yerrorbars pt 11 ps 1.3 lc 4 t 'interaction', \
     0.90000000000000013 + (2.3630210350085918 - 0.90000000000000013) * (1 + (2.8203123515078588 * x)**2)**((0.35161107681962994 - 1) / 2) w l lw 2 lc 1 t 'Carreau fit of the total', \
     0.8999999999999998 + (2.5259999999999994 - 0.8999999999999998) * (1 + (3.0503999999999998 * x)**2)**((0.34410000000000002 - 1) / 2) w l dt 4 lw 2 lc 'gray30' t '2018 Table II Carreau, λ scaled to this τ_λ', \
     0.90000000000000013 w l dt 2 lc 1 t 'η_∞ = 0.9 mPa s (held fixed)', 0.99999999999999978 w l dt 3 lc 2 t 'solvent η = 1 mPa s'
set title "C = 5 C*\n{/*0.8 Carreau fit: η_0 = 6.17 ± 0.013 mPa s, λ = 1.85 ± 0.011 s, n = 0.00946 ± 0.0024}" font ',12'
plot 'flowcurve.csv' u ($1==5&&$13>0?$2:1/0):13:14 w yerrorbars pt 7 ps 1.3 lc 1 t 'total', 'flowcurve.csv' u ($1==5&&$15>0?$2:1/0):15:16 w yerrorbars pt 5 ps 1.3 lc 2 t 'fluid', 'flowcurve.csv' u ($1==5&&$17>0?$2:1/0):17:18 w yerrorbars pt 9 ps 1.3 lc 3 t 'polymer', 'flowcurve.csv' u ($1==5&&$19>0?$2:1/0):19:20 w yerrorbars pt 11 ps 1.3 lc 4 t 'interaction', \
     0.90000000000000013 + (6.1726231735751984 - 0.90000000000000013) * (1 + (1.84668719897756 * x)**2)**((0.0094564479233901037 - 1) / 2) w l lw 2 lc 1 t 'Carreau fit of the total', \
     0.8999999999999998 + (6.6687999999999983 - 0.8999999999999998) * (1 + (2.1408 * x)**2)**((0.00080000000000000004 - 1) / 2) w l dt 4 lw 2 lc 'gray30' t '2018 Table II Carreau, λ scaled to this τ_λ', \
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
0.416667,-0.0123471
0.833333,-0.0242517
1.25,-0.0357139
1.66667,-0.0467342
2.08333,-0.0573131
2.5,-0.0674508
2.91667,-0.0771479
3.33333,-0.0864047
3.75,-0.0952219
4.16667,-0.1036
4.58333,-0.11154
5,-0.119041
5.41667,-0.126106
5.83333,-0.132734
6.25,-0.138927
6.66667,-0.144685
7.08333,-0.150009
7.5,-0.154902
7.91667,-0.159363
8.33333,-0.163395
8.75,-0.167
9.16667,-0.17018
9.58333,-0.172937
10,-0.175275
10.4167,-0.177199
10.8333,-0.178714
11.25,-0.179828
11.6667,-0.180557
12.0833,-0.18093
12.5,-0.181028
12.9167,-0.18093
13.3333,-0.180557
13.75,-0.179828
14.1667,-0.178714
14.5833,-0.177199
15,-0.175275
15.4167,-0.172937
15.8333,-0.17018
16.25,-0.167
16.6667,-0.163395
17.0833,-0.159363
17.5,-0.154902
17.9167,-0.150009
18.3333,-0.144685
18.75,-0.138927
19.1667,-0.132734
19.5833,-0.126106
20,-0.119041
20.4167,-0.11154
20.8333,-0.1036
21.25,-0.0952219
21.6667,-0.0864047
22.0833,-0.0771479
22.5,-0.0674508
22.9167,-0.0573131
23.3333,-0.0467342
23.75,-0.0357139
24.1667,-0.0242517
24.5833,-0.0123471
25,0
25.4167,0.0123471
25.8333,0.0242517
26.25,0.0357139
26.6667,0.0467342
27.0833,0.0573131
27.5,0.0674508
27.9167,0.0771479
28.3333,0.0864047
28.75,0.0952219
29.1667,0.1036
29.5833,0.11154
30,0.119041
30.4167,0.126106
30.8333,0.132734
31.25,0.138927
31.6667,0.144685
32.0833,0.150009
32.5,0.154902
32.9167,0.159363
33.3333,0.163395
33.75,0.167
34.1667,0.17018
34.5833,0.172937
35,0.175275
35.4167,0.177199
35.8333,0.178714
36.25,0.179828
36.6667,0.180557
37.0833,0.18093
37.5,0.181028
37.9167,0.18093
38.3333,0.180557
38.75,0.179828
39.1667,0.178714
39.5833,0.177199
40,0.175275
40.4167,0.172937
40.8333,0.17018
41.25,0.167
41.6667,0.163395
42.0833,0.159363
42.5,0.154902
42.9167,0.150009
43.3333,0.144685
43.75,0.138927
44.1667,0.132734
44.5833,0.126106
45,0.119041
45.4167,0.11154
45.8333,0.1036
46.25,0.0952219
46.6667,0.0864047
47.0833,0.0771479
47.5,0.0674508
47.9167,0.0573131
48.3333,0.0467342
48.75,0.0357139
49.1667,0.0242517
49.5833,0.0123471
50,0
EOD
$carreau1 << EOD
0,-0
0.416667,-0.0123961
0.833333,-0.024326
1.25,-0.0357897
1.66667,-0.0467872
2.08333,-0.0573186
2.5,-0.0673838
2.91667,-0.0769829
3.33333,-0.086116
3.75,-0.0947831
4.16667,-0.102984
4.58333,-0.110719
5,-0.117989
5.41667,-0.124792
5.83333,-0.13113
6.25,-0.137002
6.66667,-0.142409
7.08333,-0.14735
7.5,-0.151827
7.91667,-0.155838
8.33333,-0.159385
8.75,-0.162467
9.16667,-0.165087
9.58333,-0.167244
10,-0.168943
10.4167,-0.170188
10.8333,-0.171002
11.25,-0.171454
11.6667,-0.171685
12.0833,-0.171799
12.5,-0.171833
12.9167,-0.171799
13.3333,-0.171685
13.75,-0.171454
14.1667,-0.171002
14.5833,-0.170188
15,-0.168943
15.4167,-0.167244
15.8333,-0.165087
16.25,-0.162467
16.6667,-0.159385
17.0833,-0.155838
17.5,-0.151827
17.9167,-0.14735
18.3333,-0.142409
18.75,-0.137002
19.1667,-0.13113
19.5833,-0.124792
20,-0.117989
20.4167,-0.110719
20.8333,-0.102984
21.25,-0.0947831
21.6667,-0.086116
22.0833,-0.0769829
22.5,-0.0673838
22.9167,-0.0573186
23.3333,-0.0467872
23.75,-0.0357897
24.1667,-0.024326
24.5833,-0.0123961
25,0
25.4167,0.0123961
25.8333,0.024326
26.25,0.0357897
26.6667,0.0467872
27.0833,0.0573186
27.5,0.0673838
27.9167,0.0769829
28.3333,0.086116
28.75,0.0947831
29.1667,0.102984
29.5833,0.110719
30,0.117989
30.4167,0.124792
30.8333,0.13113
31.25,0.137002
31.6667,0.142409
32.0833,0.14735
32.5,0.151827
32.9167,0.155838
33.3333,0.159385
33.75,0.162467
34.1667,0.165087
34.5833,0.167244
35,0.168943
35.4167,0.170188
35.8333,0.171002
36.25,0.171454
36.6667,0.171685
37.0833,0.171799
37.5,0.171833
37.9167,0.171799
38.3333,0.171685
38.75,0.171454
39.1667,0.171002
39.5833,0.170188
40,0.168943
40.4167,0.167244
40.8333,0.165087
41.25,0.162467
41.6667,0.159385
42.0833,0.155838
42.5,0.151827
42.9167,0.14735
43.3333,0.142409
43.75,0.137002
44.1667,0.13113
44.5833,0.124792
45,0.117989
45.4167,0.110719
45.8333,0.102984
46.25,0.0947831
46.6667,0.086116
47.0833,0.0769829
47.5,0.0673838
47.9167,0.0573186
48.3333,0.0467872
48.75,0.0357897
49.1667,0.024326
49.5833,0.0123961
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
     (x < 25 ? -1 : 1) * 0.00050143384730919017 * (x < 25 ? x : x - 25) * (25 - (x < 25 ? x : x - 25)) w l dt 2 lw 2 lc 'black' t "Newtonian, η_0 = 2.36 mPa s: (g/2ν_0) y′(L_y/2 - y′)", \
     $carreau0 u 1:2 w l lw 2 lc 3 t 'Carreau fluid of the fit', 0 w l lc 'gray40' notitle
set title 'C = 5 C*, g = 2.42 m/s^2, box 10 × 10 × 10 σ' font ',12'
plot 'profile_C5.csv' u ($20>0?$1*5:1/0):($12*5000.0000000000009):($13*5000.0000000000009) w yerrorbars pt 7 ps 1.2 lc 1 t 'fluid v_x (slabs holding blob rows)', \
     '' u ($1*5):($14*5000.0000000000009):($15*5000.0000000000009) w yerrorbars pt 6 ps 1.2 lc 2 t 'polymer drift u_x', \
     (x < 25 ? -1 : 1) * 0.00019599193286837718 * (x < 25 ? x : x - 25) * (25 - (x < 25 ? x : x - 25)) w l dt 2 lw 2 lc 'black' t "Newtonian, η_0 = 6.17 mPa s: (g/2ν_0) y′(L_y/2 - y′)", \
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
     0.078349038642060956 w l dt 2 lw 2 lc 'black' t 'Newtonian, η_0 (steady)', 0.18102779277970099 w l lw 2 lc 3 t 'Carreau fluid of the fit (steady)'
set title 'C = 5 C*' font ',12'
set object 1 rect from first 3.34e+06, graph 0 to graph 1, graph 1 fc rgb '#e4ecf7' fs solid noborder behind
plot NaN w filledcurves fc rgb '#e4ecf7' t 'measured window (profiles)', 'rp_start_C5.csv' u ($1*1):($3*5000.0000000000009) w l lw 2 lc 1 t 'fluid', '' u ($1*1):($4*5000.0000000000009) w l lw 2 lc 2 t 'polymer', \
     0.03062373951068393 w l dt 2 lw 2 lc 'black' t 'Newtonian, η_0 (steady)', 0.17183321146100614 w l lw 2 lc 3 t 'Carreau fluid of the fit (steady)'
unset multiplot
unset object 1
set output 'startup.png'
set xrange [0:*]
set yrange [*:*]
set multiplot layout 1,2 title "Lees-Edwards start-up: the total viscosity of each half block over the measured mean (start-up: points; measured: line)\n{/*0.85 ".scene."}"
set xlabel 't / τ_λ'
set ylabel 'η / η (measured)'
set key bottom right font ',11'
set title 'C = 2.5 C*' font ',12'
plot 1 w l dt 2 lc 'black' notitle, 'startup_C2.5.csv' u ($1 == 0.1 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 1 t 'Wi = 0.1', '' u ($1 == 0.1 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 1 notitle, 'startup_C2.5.csv' u ($1 == 0.3 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 2 t 'Wi = 0.3', '' u ($1 == 0.3 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 2 notitle, 'startup_C2.5.csv' u ($1 == 1 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 3 t 'Wi = 1', '' u ($1 == 1 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 3 notitle, 'startup_C2.5.csv' u ($1 == 3 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 4 t 'Wi = 3', '' u ($1 == 3 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 4 notitle, 'startup_C2.5.csv' u ($1 == 10 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 5 t 'Wi = 10', '' u ($1 == 10 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 5 notitle, 'startup_C2.5.csv' u ($1 == 30 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 6 t 'Wi = 30', '' u ($1 == 30 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 6 notitle
set title 'C = 5 C*' font ',12'
plot 1 w l dt 2 lc 'black' notitle, 'startup_C5.csv' u ($1 == 0.1 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 1 t 'Wi = 0.1', '' u ($1 == 0.1 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 1 notitle, 'startup_C5.csv' u ($1 == 0.3 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 2 t 'Wi = 0.3', '' u ($1 == 0.3 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 2 notitle, 'startup_C5.csv' u ($1 == 1 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 3 t 'Wi = 1', '' u ($1 == 1 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 3 notitle, 'startup_C5.csv' u ($1 == 3 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 4 t 'Wi = 3', '' u ($1 == 3 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 4 notitle, 'startup_C5.csv' u ($1 == 10 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 5 t 'Wi = 10', '' u ($1 == 10 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 5 notitle, 'startup_C5.csv' u ($1 == 30 && $5 == 0 ? $2 : NaN):4 w p pt 7 ps 0.6 lc 6 t 'Wi = 30', '' u ($1 == 30 && $5 == 1 ? $2 : NaN):4 w l lw 2 lc 6 notitle
unset multiplot
