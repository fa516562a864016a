# M08P5: a tip mass m on a massless arm (length L, bending stiffness EI) clamped to a hub of radius
# r_h that turns at Omega; the bent arm keeps its length, so its tip comes in by the foreshortening.
# Run in this folder: gnuplot arm.gp (writes arm.png).
set terminal pngcairo size 820,440 font "sans,11" noenhanced
set output "arm.png"
unset border; unset tics; unset key
set size ratio -1
set title "M08P5: a spinning arm; bending it by v_tip pulls the tip in by 1/2 (integral of v'^2),\nagainst the centrifugal force that the tension holds"
rh = 0.5; L = 2.0; v = 0.55
# the bent arm: the cubic tip-load shape; x along the arm from the hub's rim, shortened so the length stays L
shape(x) = v*(3*L*x**2 - x**3)/(2*L**3)
delta = 0.25  # drawn larger than 0.6 v^2/L, to be seen
set xrange [-0.8:3.4]; set yrange [-0.95:1.05]
set object 1 circle at 0,0 size rh fs empty border lc rgb "black" lw 2
set arrow 1 from 0,0 to rh*cos(pi/4),-rh*sin(pi/4) lw 1 lc rgb "gray30"
set label 1 "r_h" at 0.05,-0.35
set object 2 circle at 0,0 size 0.75 arc [100:170] nowedge fs empty border lc rgb "black" lw 1.5
set arrow 2 from -0.72,0.2 to -0.74,0.1 size 0.07,25 filled lw 1.5 lc rgb "black"
set label 2 "Omega" at -0.78,0.85
set arrow 3 from rh,0 to rh+L,0 nohead dt 2 lw 1.5 lc rgb "#9fb7cf"
set label 3 "straight arm, length L" at rh+0.55,-0.12 tc rgb "#1f4e79"
set arrow 4 from rh+L-delta,v to rh+L-delta+0.55,v lw 2 lc rgb "#2e7d32"
set label 4 "m Omega^2 (r_h + L)" at rh+L-delta-0.3,v+0.2 tc rgb "#2e7d32"
set arrow 5 from rh+L-delta+0.03,-0.3 to rh+L,-0.3 heads lw 1 lc rgb "#c00000"
set label 5 "foreshortening" at rh+L-0.6,-0.45 tc rgb "#c00000"
set arrow 6 from rh+L+0.35,0 to rh+L+0.35,v heads lw 1 lc rgb "#c00000"
set label 6 "v_tip = q_f" at rh+L+0.42,v/2
set label 7 "m" at rh+L-delta+0.02,v-0.17
set label 8 "EI" at rh+0.9,0.2
set parametric
set trange [0:L]
plot rh + t*(1 - delta/L), shape(t) with lines lw 4 lc rgb "#1f4e79", \
     "-" using 1:2 with points pt 7 ps 3 lc rgb "black", \
     "-" using 1:2 with points pt 6 ps 3 lc rgb "gray40"
2.25 0.55
e
2.5 0
e
