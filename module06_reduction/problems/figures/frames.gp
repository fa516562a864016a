# M06P1 and M06P3: the free L-shaped frame, its mass centre c and the rotation mode at node 2;
# M06P2: a beam of two unequal elements, nodes 0 and 2 the Craig-Bampton interface, and the
# constraint mode of v_2.
# Run in this folder: gnuplot frames.gp (writes frames.png).
set terminal pngcairo size 1000,440 font "sans,11" noenhanced
set output "frames.png"
unset border; unset tics; unset key
set size ratio -1
set multiplot layout 1,2

# Left: the L-shaped frame.
set title "M06P1, M06P3: free L-shaped frame, rotation about c"
L1 = 1.0; L2 = 0.7
cx = (L1*L1/2 + L1*L2)/(L1 + L2); cy = (L2*L2/2)/(L1 + L2)
set xrange [-0.3:1.75]; set yrange [-0.3:1.05]
set arrow 1 from 0,0 to L1,0 nohead lw 8 lc rgb "#1f4e79"
set arrow 2 from L1,0 to L1,L2 nohead lw 8 lc rgb "#1f4e79"
set arrow 3 from cx,cy to L1,L2 nohead dt 2 lc rgb "gray40"
# the rotation mode at node 2: (-(y2 - c_y), x2 - c_x), scaled
s = 0.45
set arrow 4 from L1,L2 to L1 - s*(L2 - cy),L2 + s*(L1 - cx) lw 2.5 lc rgb "#c00000"
set object 1 circle at cx,cy size 0.09 arc [30:300] nowedge fs empty border lc rgb "#c00000" lw 1.5
set label 1 "0" at -0.09,-0.09
set label 2 "1" at L1+0.05,-0.09
set label 3 "2" at L1+0.06,L2+0.02
set label 4 "c" at cx-0.15,cy-0.03
set label 5 "r_c at node 2" at L1-0.42,L2+0.3 tc rgb "#c00000"
set label 6 "L1" at L1/2-0.05,-0.12
set label 7 "L2" at L1+0.06,L2/2
set label 8 "x_2 - c" at (cx+L1)/2-0.25,(cy+L2)/2+0.05 tc rgb "gray40"
plot "-" with points pt 7 ps 1.4 lc rgb "black", "-" with points pt 6 ps 2 lc rgb "#c00000"
0 0
1 0
1 0.7
e
0.7059 0.1441
e
unset arrow; unset object; unset label

# Right: the beam with its interface nodes 0 and 2 and the constraint mode of v_2.
set title "M06P2: interface nodes 0 and 2, constraint mode of v_2"
set xrange [-0.2:1.3]; set yrange [-0.45:0.85]
set arrow 1 from 0,0 to 1,0 nohead lw 6 lc rgb "#1f4e79"
set object 1 rect from -0.06,-0.12 to 0.06,0.12 fs empty border lc rgb "black" lw 1.5
set object 2 rect from 0.94,-0.12 to 1.06,0.12 fs empty border lc rgb "black" lw 1.5
set arrow 2 from 1,0 to 1,0.5 lw 2 lc rgb "#c00000"
set label 1 "0" at -0.02,-0.2
set label 2 "1" at 0.38,-0.12
set label 3 "2" at 0.98,-0.2
set label 4 "v_2 = 1" at 1.03,0.45 tc rgb "#c00000"
set label 5 "(v_1, psi_1)?" at 0.18,0.33 tc rgb "#c00000"
set label 6 "L1" at 0.17,-0.3
set label 7 "L2" at 0.67,-0.3
set label 8 "interface (boxes): all DOFs of nodes 0, 2" at 0.0,-0.42
set arrow 3 from 0,-0.24 to 0.4,-0.24 heads lw 1 lc rgb "gray40"
set arrow 4 from 0.4,-0.24 to 1,-0.24 heads lw 1 lc rgb "gray40"
f(x) = 0.5*(3*x**2 - 2*x**3)
plot [0:1] f(x) with lines lw 2 dt 2 lc rgb "#c00000", "-" with points pt 7 ps 1.4 lc rgb "black"
0 0
0.4 0
1 0
e
unset multiplot
