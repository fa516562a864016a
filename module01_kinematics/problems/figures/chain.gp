# M01P1 and M01P2: a chain of links pinned from the ground pivot O, a slider on a guide at its tip;
# a body's point P at r_P = R + A(phi) s. Run in this folder: gnuplot chain.gp (writes chain.png).
set terminal pngcairo size 900,420 font "sans,11" noenhanced
set output "chain.png"
unset border; unset tics; unset key
set size ratio -1
set xrange [-0.1:2.3]; set yrange [-0.35:0.75]
set multiplot layout 1,2

# Left: the chain (three links here), a slider at its tip, motors on the first links.
set title "M01P1: a chain with a slider"
O = 0.0; a1 = 50*pi/180; a2 = -40*pi/180; a3 = 20*pi/180; L1 = 0.4; L2 = 0.45; L3 = 0.35
x1 = L1*cos(a1); y1 = L1*sin(a1); x2 = x1 + L2*cos(a2); y2 = y1 + L2*sin(a2)
x3 = x2 + L3*cos(a3); y3 = y2 + L3*sin(a3)
set arrow 1 from 0,0 to x1,y1 nohead lw 4 lc rgb "#1f4e79"
set arrow 2 from x1,y1 to x2,y2 nohead lw 4 lc rgb "#1f4e79"
set arrow 3 from x2,y2 to x3,y3 nohead lw 4 lc rgb "#1f4e79"
set arrow 4 from -0.05,y3-0.06 to 1.3,y3-0.06 nohead lw 1 dt 2 lc rgb "black"
set object 1 rect center x3,y3 size 0.16,0.1 fs empty border lc rgb "#7f6000" lw 2
set object 2 polygon from -0.06,-0.07 to 0.06,-0.07 to 0,0 to -0.06,-0.07 fs pattern 2 border lc rgb "black"
set label 1 "O (ground)" at -0.08,-0.13
set label 2 "link 1 (motor)" at x1/2-0.27,y1/2+0.04
set label 3 "link 2" at (x1+x2)/2+0.03,(y1+y2)/2+0.05
set label 4 "link 3" at (x2+x3)/2-0.05,(y2+y3)/2+0.08
set label 5 "slider on a guide" at x3-0.2,y3-0.14
set xrange [-0.2:1.3]
plot "-" with points pt 7 ps 1.4 lc rgb "black"
0 0
e
unset arrow; unset object; unset label

# Right: a body with its frame, the centroid R and a point P.
set title "M01P2: r_P = R + A(phi) s"
phi = 35*pi/180; Rx = 0.35; Ry = 0.1; sx = 0.45; sy = 0.15
Px = Rx + cos(phi)*sx - sin(phi)*sy; Py = Ry + sin(phi)*sx + cos(phi)*sy
X(u,v) = Rx + cos(phi)*u - sin(phi)*v
Y(u,v) = Ry + sin(phi)*u + cos(phi)*v
set object 3 polygon from X(-0.2,-0.1),Y(-0.2,-0.1) to X(0.55,-0.1),Y(0.55,-0.1) to X(0.55,0.22),Y(0.55,0.22) \
    to X(-0.2,0.22),Y(-0.2,0.22) to X(-0.2,-0.1),Y(-0.2,-0.1) fs empty border lc rgb "#1f4e79" lw 2
set arrow 5 from 0,0 to Rx,Ry lw 2 lc rgb "black"
set arrow 6 from Rx,Ry to Px,Py lw 2 lc rgb "#c00000"
set arrow 7 from Rx,Ry to Rx+0.3*cos(phi),Ry+0.3*sin(phi) lw 1 lc rgb "#1f4e79"
set arrow 8 from Rx,Ry to Rx+0.3,Ry nohead dt 2 lc rgb "gray"
set label 6 "R" at Rx/2-0.02,Ry/2+0.05
set label 7 "A s" at (Rx+Px)/2-0.08,(Ry+Py)/2+0.06 tc rgb "#c00000"
set label 8 "P" at Px+0.02,Py+0.02
set label 9 "phi" at Rx+0.3,Ry+0.06
set label 10 "x" at 0.95,-0.05
set arrow 9 from 0,0 to 1.0,0 lw 1 lc rgb "gray"
set arrow 10 from 0,0 to 0,0.6 lw 1 lc rgb "gray"
set xrange [-0.1:1.1]
plot "-" with points pt 7 ps 1.2 lc rgb "black"
0 0
0.35 0.1
e
unset multiplot
