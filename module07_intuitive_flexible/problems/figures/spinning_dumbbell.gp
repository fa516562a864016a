# M07P1-P2 (and module 8's M08P4): two point masses m on a spring k, spun at a steady Omega about
# their mass centre; the stretch mode moves each mass outwards by q_f.
# Run in this folder: gnuplot spinning_dumbbell.gp (writes spinning_dumbbell.png).
set terminal pngcairo size 820,420 font "sans,11" noenhanced
set output "spinning_dumbbell.png"
unset border; unset tics; unset key
set size ratio -1
set title "M07P1-P2, M08P4: a spring dumbbell spun at Omega; each mass moves outwards by q_f\nopen circles: the masses undeformed at -d and d (the spring unstretched); filled: stretched"
d = 1.0; u = 0.22
set xrange [-1.9:1.9]; set yrange [-0.75:0.8]
# the spring, a zigzag between the masses
set samples 400
spring(x) = 0.07*sin(2*pi*6*(x + d + u)/(2*(d + u)))
set arrow 1 from -d,0 to d,0 nohead lw 1 dt 2 lc rgb "#9fb7cf"
set arrow 2 from -d,-0.3 to -d-u,-0.3 lw 2 lc rgb "#c00000"
set arrow 3 from d,-0.3 to d+u,-0.3 lw 2 lc rgb "#c00000"
set label 1 "q_f" at -d-u/2-0.08,-0.42 tc rgb "#c00000"
set label 2 "q_f" at d+u/2-0.08,-0.42 tc rgb "#c00000"
set arrow 4 from 0,-0.55 to d,-0.55 heads lw 1 lc rgb "#1f4e79"
set label 3 "d" at d/2-0.03,-0.65 tc rgb "#1f4e79"
set label 4 "m" at -d-u-0.05,0.2
set label 5 "m" at d+u-0.05,0.2
set label 6 "k" at -0.55,0.17
set object 1 circle at 0,0 size 0.22 arc [200:520] nowedge fs empty border lc rgb "black" lw 1.5
set arrow 5 from -0.205,-0.08 to -0.19,-0.11 size 0.06,25 filled lw 1.5 lc rgb "black"
set label 7 "Omega" at 0.25,0.3
set label 9 "O" at 0.03,-0.1
plot [-d-u:d+u] spring(x) with lines lw 1.5 lc rgb "gray30", \
     "-" with points pt 7 ps 3 lc rgb "black", \
     "-" with points pt 6 ps 3 lc rgb "gray40"
-1.22 0
1.22 0
e
-1 0
1 0
e
