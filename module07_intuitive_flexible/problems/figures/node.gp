# M07P3: a flexible body's floating frame at R turned by theta, node k at x_bar_k in the frame,
# its displacement Phi_t,k q_f, its global position r_k, the force F at the node and gravity.
# Run in this folder: gnuplot node.gp (writes node.png).
set terminal pngcairo size 760,520 font "sans,11" noenhanced
set output "node.png"
unset border; unset tics; unset key
set size ratio -1
set title "M07P3: a force F at node k of a free-free body, r_k = R + A(theta) (x_bar_k + Phi_t,k q_f)"
th = 30*pi/180; c = cos(th); s = sin(th)
Rx = 1.0; Ry = 0.15
xb = 1.3; yb = 0.0; ux = -0.05; uy = 0.3
# global point of a frame point (x, y)
gx(x, y) = Rx + c*x - s*y
gy(x, y) = Ry + s*x + c*y
set xrange [-0.3:2.8]; set yrange [-0.45:1.75]
set arrow 1 from 0,0 to 0.5,0 lw 1.5 lc rgb "black"
set arrow 2 from 0,0 to 0,0.5 lw 1.5 lc rgb "black"
set label 1 "x" at 0.45,-0.1
set label 2 "y" at -0.08,0.52
set label 3 "O" at -0.12,-0.08
set arrow 3 from 0,0 to Rx,Ry lw 2 lc rgb "gray30"
set label 4 "R" at 0.4,0.13
# the frame's axes
set arrow 14 from Rx,Ry to gx(0.5,0),gy(0.5,0) lw 2 lc rgb "#1f4e79"
set arrow 15 from Rx,Ry to gx(0,0.5),gy(0,0.5) lw 1.5 lc rgb "#1f4e79"
set label 5 "frame x" at gx(0.35,-0.2),gy(0.35,-0.2) tc rgb "#1f4e79"
set label 6 "frame y" at gx(-0.3,0.55),gy(-0.3,0.55) tc rgb "#1f4e79"
set arrow 16 from Rx,Ry to Rx+0.55,Ry nohead dt 2 lc rgb "gray"
set object 1 circle at Rx,Ry size 0.35 arc [0:30] nowedge fs empty border lc rgb "black"
set label 7 "theta" at Rx+0.36,Ry+0.07
# undeformed body (dashed) and deformed body
set arrow 6 from gx(-0.7,0),gy(-0.7,0) to gx(xb,yb),gy(xb,yb) nohead lw 6 lc rgb "#9fb7cf"
set arrow 7 from gx(xb,yb),gy(xb,yb) to gx(xb+ux,yb+uy),gy(xb+ux,yb+uy) lw 2 lc rgb "#c00000"
set label 8 "A Phi_t,k q_f" at gx(xb+0.08,0.1),gy(xb+0.08,0.1) tc rgb "#c00000"
set arrow 10 from gx(0,-0.2),gy(0,-0.2) to gx(xb,-0.2),gy(xb,-0.2) heads lw 1 lc rgb "#1f4e79"
set label 9 "x_bar_k" at gx(0.85,-0.32),gy(0.85,-0.32) tc rgb "#1f4e79"
set arrow 8 from 0,0 to gx(xb+ux,yb+uy),gy(xb+ux,yb+uy) dt 2 lw 1.5 lc rgb "#c00000"
set label 10 "r_k" at gx(xb+ux,yb+uy)/2-0.12,gy(xb+ux,yb+uy)/2+0.06 tc rgb "#c00000"
set label 11 "k" at gx(xb+ux,yb+uy)+0.04,gy(xb+ux,yb+uy)+0.06
set arrow 9 from 2.35,1.6 to 2.35,1.2 lw 2 lc rgb "gray30"
set label 12 "g" at 2.4,1.4
# the force at the node (global axes)
set arrow 17 from gx(xb+ux,yb+uy),gy(xb+ux,yb+uy) to gx(xb+ux,yb+uy)+0.45,gy(xb+ux,yb+uy)-0.35 lw 2.5 lc rgb "#2e7d32"
set label 13 "F" at gx(xb+ux,yb+uy)+0.48,gy(xb+ux,yb+uy)-0.38 tc rgb "#2e7d32"
plot "-" using 1:2 with points pt 7 ps 1.2 lc rgb "black"
1.0 0.15
e
