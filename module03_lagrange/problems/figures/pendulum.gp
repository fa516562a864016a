# M03P1 and M03P3: a uniform rod pinned at O, its angle phi driven by a motor, under gravity.
# Run in this folder: gnuplot pendulum.gp (writes pendulum.png).
set terminal pngcairo size 520,460 font "sans,11" noenhanced
set output "pendulum.png"
unset border; unset tics; unset key
set size ratio -1
set title "M03P1, M03P3: driven rod, pivot force F, motor torque T"
L = 1.0; phi = -35*pi/180
Gx = L/2*cos(phi); Gy = L/2*sin(phi)
set xrange [-0.45:1.2]; set yrange [-0.95:0.5]
set arrow 1 from 0,0 to L*cos(phi),L*sin(phi) nohead lw 6 lc rgb "#1f4e79"
set arrow 2 from 0,0 to 0.6,0 nohead dt 2 lc rgb "gray"
set arrow 3 from Gx,Gy to Gx,Gy-0.35 lw 2 lc rgb "black"
set arrow 4 from 0,0 to -0.25,0.3 lw 2 lc rgb "#c00000"
set object 1 circle at 0,0 size 0.12 arc [200:340] fc rgb "#7f6000" lw 2
set label 1 "O" at -0.12,-0.05
set label 2 "G" at Gx+0.04,Gy+0.04
set label 3 "m g" at Gx+0.04,Gy-0.3
set label 4 "F (pivot on rod)" at -0.42,0.37 tc rgb "#c00000"
set label 5 "phi" at 0.3,-0.08
set label 6 "T" at -0.05,-0.2 tc rgb "#7f6000"
set label 7 "g" at 1.05,0.2
set arrow 5 from 1.0,0.35 to 1.0,0.05 lw 1 lc rgb "gray"
plot "-" with points pt 7 ps 1.4 lc rgb "black"
0 0
e
