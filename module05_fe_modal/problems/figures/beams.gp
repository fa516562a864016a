# M05P1 and M05P3: an element a-b at the angle alpha, its global DOFs (u_x, u_y, psi) at node a
# and its local axes; M05P2: a beam clamped at both ends, two elements, the middle node free.
# Run in this folder: gnuplot beams.gp (writes beams.png).
set terminal pngcairo size 1000,420 font "sans,11" noenhanced
set output "beams.png"
unset border; unset tics; unset key
set size ratio -1
set multiplot layout 1,2

# Left: the inclined element.
set title "M05P1, M05P3: element a-b at alpha"
al = 35*pi/180; L = 1.0; c = cos(al); s = sin(al)
Bx = L*c; By = L*s
set xrange [-0.45:1.3]; set yrange [-0.4:1.05]
set arrow 1 from 0,0 to Bx,By nohead lw 8 lc rgb "#1f4e79"
set arrow 2 from 0,0 to 0.35,0 lw 2 lc rgb "#c00000"
set arrow 3 from 0,0 to 0,0.35 lw 2 lc rgb "#c00000"
set object 1 circle at 0,0 size 0.12 arc [200:340] nowedge fs empty border lc rgb "#c00000" lw 2
set arrow 4 from Bx,By to Bx+0.25*c,By+0.25*s lw 1 lc rgb "gray40"
set arrow 5 from Bx,By to Bx-0.25*s,By+0.25*c lw 1 lc rgb "gray40"
set arrow 6 from 0,0 to 0.7,0 nohead dt 2 lc rgb "gray"
set object 2 circle at 0,0 size 0.55 arc [0:35] nowedge fs empty border lc rgb "black"
set label 1 "a" at -0.1,0.08
set label 2 "b" at Bx+0.02,By-0.1
set label 3 "u_x" at 0.36,-0.06 tc rgb "#c00000"
set label 4 "u_y" at -0.13,0.38 tc rgb "#c00000"
set label 5 "psi" at -0.2,-0.2 tc rgb "#c00000"
set label 6 "alpha" at 0.58,0.14
set label 7 "x (local)" at Bx+0.1,By+0.05
set label 8 "y (local)" at Bx-0.25*s-0.2,By+0.25*c+0.05
set label 9 "L, E, rho, a x a" at 0.62,0.25
plot "-" with points pt 7 ps 1.4 lc rgb "black"
0 0
0.8192 0.5736
e
unset arrow; unset object; unset label

# Right: the clamped-clamped beam of two elements.
set title "M05P2: clamped at both ends, two elements"
set xrange [-0.25:1.25]; set yrange [-0.5:0.6]
set arrow 1 from 0,0 to 1,0 nohead lw 8 lc rgb "#1f4e79"
set object 1 rect from -0.08,-0.25 to 0,0.25 fc rgb "gray75" fs solid 1.0 border lc rgb "black"
set object 2 rect from 1,-0.25 to 1.08,0.25 fc rgb "gray75" fs solid 1.0 border lc rgb "black"
set arrow 2 from 0.5,0 to 0.5,0.3 lw 2 lc rgb "#c00000"
set arrow 3 from 0.5,0 to 0.75,0 lw 2 lc rgb "#c00000"
set object 3 circle at 0.5,0 size 0.1 arc [200:340] nowedge fs empty border lc rgb "#c00000" lw 2
set label 1 "0" at -0.02,-0.32
set label 2 "1" at 0.48,-0.32
set label 3 "2" at 0.98,-0.32
set label 4 "v_1 (u_y)" at 0.52,0.34 tc rgb "#c00000"
set label 5 "u_x" at 0.7,0.07 tc rgb "#c00000"
set label 6 "psi_1" at 0.37,-0.17 tc rgb "#c00000"
set label 7 "L/2" at 0.22,0.08
set label 8 "L/2" at 0.78,-0.12
set arrow 4 from 0,-0.45 to 1,-0.45 heads lw 1 lc rgb "gray40"
set label 9 "L" at 0.49,-0.41
plot "-" with points pt 7 ps 1.4 lc rgb "black"
0 0
0.5 0
1 0
e
unset multiplot
