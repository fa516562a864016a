# M02P1 and M02P2: a link pinned at O with its tip's x driven; the slider-crank O-B-C.
# Run in this folder: gnuplot slider_crank.gp (writes slider_crank.png).
set terminal pngcairo size 900,400 font "sans,11" noenhanced
set output "slider_crank.png"
unset border; unset tics; unset key
set size ratio -1
set multiplot layout 1,2

# Left: one Newton step. The guess phi_0 and the solution where x_B = x_d.
set title "M02P1: link O-B, x of B driven to x_B"
L = 1.0; p0 = 40*pi/180; p1 = 58*pi/180
set xrange [-0.2:1.2]; set yrange [-0.25:1.0]
set arrow 1 from 0,0 to L*cos(p0),L*sin(p0) nohead lw 4 lc rgb "gray"
set arrow 2 from 0,0 to L*cos(p1),L*sin(p1) nohead lw 4 lc rgb "#1f4e79"
set arrow 3 from L*cos(p1),-0.15 to L*cos(p1),0.95 nohead dt 2 lc rgb "#c00000"
set arrow 4 from 0,0 to 1.1,0 lc rgb "gray"
set label 1 "guess phi_0" at L*cos(p0)+0.03,L*sin(p0) tc rgb "gray40"
set label 2 "B" at L*cos(p1)+0.03,L*sin(p1)+0.03
set label 3 "x = x_B" at L*cos(p1)+0.03,-0.12 tc rgb "#c00000"
set label 4 "O = A" at -0.15,-0.1
set label 5 "phi" at 0.22,0.1
plot "-" with points pt 7 ps 1.4 lc rgb "black"
0 0
e
unset arrow; unset label

# Right: the slider-crank, crank r at angle A, rod l, slider C on the x axis.
set title "M02P2: slider-crank, crank at omega (rpm)"
r = 0.35; l = 0.9; A = 50*pi/180
Bx = r*cos(A); By = r*sin(A); Cx = r*cos(A) + sqrt(l*l - r*r*sin(A)**2)
set xrange [-0.2:1.4]; set yrange [-0.3:0.6]
set arrow 1 from 0,0 to Bx,By nohead lw 4 lc rgb "#1f4e79"
set arrow 2 from Bx,By to Cx,0 nohead lw 4 lc rgb "#1f4e79"
set arrow 3 from -0.1,-0.06 to 1.35,-0.06 nohead lw 1 lc rgb "black"
set arrow 4 from Cx+0.12,0 to Cx+0.3,0 lw 2 lc rgb "#c00000"
set object 1 rect center Cx,0 size 0.2,0.1 fs empty border lc rgb "#7f6000" lw 2
set label 1 "O" at -0.08,-0.13
set label 2 "B" at Bx-0.02,By+0.06
set label 3 "C" at Cx-0.02,0.1
set label 4 "r" at Bx/2-0.08,By/2+0.02
set label 5 "l" at (Bx+Cx)/2+0.02,By/2+0.04
set label 6 "A" at 0.1,0.03
set label 7 "dx_C/dt" at Cx+0.14,0.06 tc rgb "#c00000"
plot "-" with points pt 7 ps 1.4 lc rgb "black"
0 0
e
unset multiplot
