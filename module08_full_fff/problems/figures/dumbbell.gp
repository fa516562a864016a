# M08P1-P3: the body of two point masses m at x_bar_1 = (-d, 0) and x_bar_2 = (d, 0) in its
# floating frame, its elastic shape Phi_t,1 = (-a, b1), Phi_t,2 = (a, b2), and the spin theta_dot.
# Run in this folder: gnuplot dumbbell.gp (writes dumbbell.png).
set terminal pngcairo size 820,460 font "sans,11" noenhanced
set output "dumbbell.png"
unset border; unset tics; unset key
set size ratio -1
set title "M08P1-P3: two point masses, one elastic shape (frame axes)"
d = 1.0; a = 0.15; b1 = 0.2; b2 = 0.6
set xrange [-1.7:1.7]; set yrange [-0.62:0.95]
set arrow 1 from -d,0 to d,0 nohead lw 3 dt 2 lc rgb "#9fb7cf"
set arrow 2 from 0,0 to 0.45,0 lw 1.5 lc rgb "#1f4e79"
set arrow 3 from 0,0 to 0,0.45 lw 1.5 lc rgb "#1f4e79"
set label 1 "x (frame)" at 0.3,-0.1 tc rgb "#1f4e79"
set label 2 "y (frame)" at 0.05,0.5 tc rgb "#1f4e79"
set arrow 4 from -d,0 to -d-a,b1 lw 2.5 lc rgb "#c00000"
set arrow 5 from d,0 to d+a,b2 lw 2.5 lc rgb "#c00000"
set label 3 "Phi_t,1 = (-a, b1)" at -d-0.65,b1+0.12 tc rgb "#c00000"
set label 4 "Phi_t,2 = (a, b2)" at d-0.2,b2+0.12 tc rgb "#c00000"
set label 5 "m" at -d-0.05,-0.15
set label 6 "m" at d-0.05,-0.15
set label 7 "-d" at -d-0.08,-0.32
set label 8 "d" at d-0.04,-0.32
set object 1 circle at 0,0 size 0.25 arc [-120:180] nowedge fs empty border lc rgb "black" lw 1.5
set arrow 6 from -0.25,0.06 to -0.25,-0.04 size 0.07,25 filled lw 1.5 lc rgb "black"
set label 9 "theta_dot" at -0.55,-0.32
set label 10 "O" at -0.12,0.1
set label 11 "O: the frame origin, the undeformed mass centre" at -0.95,-0.5
plot "-" with points pt 7 ps 2.5 lc rgb "black"
-1 0
1 0
e
