# M04P1 and M04P3: a uniform rod pinned at O swinging freely under gravity, and one explicit Euler
# step that opens the pin; M04P2: a slider on a spring and a damper.
# Run in this folder: gnuplot pendulum.gp (writes pendulum.png).
set terminal pngcairo size 1200,440 font "sans,11" noenhanced
set output "pendulum.png"
unset border; unset tics; unset key
set size ratio -1
set multiplot layout 1,3

# Left: the released rod, its centroid G, phi, phi_dot and the weight.
set title "M04P1: free rod, q = (x, y, phi) of G"
L = 1.0; phi = -35*pi/180
Gx = L/2*cos(phi); Gy = L/2*sin(phi)
set xrange [-0.45:1.2]; set yrange [-0.95:0.5]
set arrow 1 from 0,0 to L*cos(phi),L*sin(phi) nohead lw 6 lc rgb "#1f4e79"
set arrow 2 from 0,0 to 0.6,0 nohead dt 2 lc rgb "gray"
set arrow 3 from Gx,Gy to Gx,Gy-0.35 lw 2 lc rgb "black"
set object 1 polygon from -0.07,0.08 to 0.07,0.08 to 0,0 to -0.07,0.08 fs pattern 2 border lc rgb "black"
set object 2 circle at 0,0 size 0.3 arc [325:360] nowedge fs empty border lc rgb "gray40"
set object 3 circle at 0,0 size 0.8 arc [300:335] nowedge fs empty border lc rgb "#c00000" lw 2
set label 1 "O (pin)" at -0.3,0.12
set label 2 "G" at Gx+0.04,Gy+0.04
set label 3 "m g" at Gx+0.04,Gy-0.3
set label 4 "phi" at 0.32,-0.08
set label 5 "phi_dot" at 0.72,-0.62 tc rgb "#c00000"
set label 6 "g" at 1.05,0.2
set arrow 4 from 1.0,0.35 to 1.0,0.05 lw 1 lc rgb "gray"
plot "-" with points pt 7 ps 1.4 lc rgb "black"
0 0
e
unset arrow; unset object; unset label

# Middle: one Euler step, exaggerated. G moves along the tangent of its circle, the rod turns by
# h phi_dot, and its end P leaves O: C(q_1) = r_O - r_P.
set title "M04P3: one Euler step opens the pin"
p0 = 10*pi/180; hw = 1.0
R0x = L/2*cos(p0); R0y = L/2*sin(p0)
R1x = R0x - L/2*hw*sin(p0); R1y = R0y + L/2*hw*cos(p0)
p1 = p0 + hw
Px = R1x - L/2*cos(p1); Py = R1y - L/2*sin(p1)
set xrange [-0.35:1.05]; set yrange [-0.3:1.0]
set arrow 1 from 0,0 to L*cos(p0),L*sin(p0) nohead lw 5 lc rgb "gray"
set arrow 2 from Px,Py to R1x + L/2*cos(p1),R1y + L/2*sin(p1) nohead lw 5 lc rgb "#1f4e79"
set arrow 3 from R0x,R0y to R1x,R1y lw 2 lc rgb "black"
set arrow 4 from Px,Py to 0,0 lw 2 lc rgb "#c00000"
set object 1 circle at 0,0 size L/2 arc [0:90] nowedge fs empty border lc rgb "gray" dt 2
set label 1 "q_0" at L*cos(p0)+0.02,L*sin(p0)
set label 2 "q_1 = q_0 + h q_dot_0" at -0.3,0.88 tc rgb "#1f4e79"
set label 3 "h R_dot_0" at (R0x+R1x)/2+0.04,(R0y+R1y)/2 
set label 4 "C(q_1) = r_O - r_P" at Px+0.05,Py/2-0.08 tc rgb "#c00000"
set label 5 "O" at -0.1,-0.06
set label 6 "P" at Px-0.08,Py+0.02
plot "-" with points pt 7 ps 1.2 lc rgb "black"
0 0
e
unset arrow; unset object; unset label

# Right: the slider on its guide, a spring and a damper in parallel to the ground.
set title "M04P2: slider, spring k and damper c"
set xrange [-0.1:1.3]; set yrange [-0.5:0.6]
set arrow 1 from 0,-0.3 to 0,0.4 nohead lw 3 lc rgb "black"
set arrow 2 from 0,-0.12 to 1.25,-0.12 nohead lw 1 lc rgb "black"
set object 1 rect from 0.75,-0.1 to 1.0,0.3 fs empty border lc rgb "#7f6000" lw 2
set arrow 3 from 0,0.2 to 0.1,0.2 nohead lw 2 lc rgb "#1f4e79"
set arrow 4 from 0.65,0.2 to 0.75,0.2 nohead lw 2 lc rgb "#1f4e79"
set arrow 5 from 0,0.02 to 0.3,0.02 nohead lw 2 lc rgb "#1f4e79"
set arrow 6 from 0.3,-0.03 to 0.3,0.07 nohead lw 2 lc rgb "#1f4e79"
set arrow 7 from 0.26,-0.05 to 0.44,-0.05 nohead lw 2 lc rgb "#1f4e79"
set arrow 8 from 0.26,0.09 to 0.44,0.09 nohead lw 2 lc rgb "#1f4e79"
set arrow 9 from 0.44,-0.05 to 0.44,0.09 nohead lw 2 lc rgb "#1f4e79"
set arrow 10 from 0.44,0.02 to 0.75,0.02 nohead lw 2 lc rgb "#1f4e79"
set arrow 11 from 0.6,-0.3 to 0.875,-0.3 lw 2 lc rgb "#c00000"
set arrow 12 from 0.6,-0.25 to 0.6,-0.35 nohead lw 1 lc rgb "gray40"
set label 1 "k" at 0.37,0.28
set label 2 "c" at 0.33,-0.14
set label 3 "m" at 0.86,0.1
set label 4 "x (0: spring unstretched)" at 0.45,-0.42 tc rgb "#c00000"
plot "-" using 1:2 with lines lw 2 lc rgb "#1f4e79"
0.1 0.2
0.15 0.27
0.2 0.13
0.25 0.27
0.3 0.13
0.35 0.27
0.4 0.13
0.45 0.27
0.5 0.13
0.55 0.27
0.6 0.13
0.65 0.2
e
unset multiplot
