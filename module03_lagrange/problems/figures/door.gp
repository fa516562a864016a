# M03P4: a door at rest on two hinges on its vertical edge x = 0, a bag at its handle, under gravity.
# Run in this folder: gnuplot door.gp (writes door.png).
set terminal pngcairo size 520,560 font "sans,11" noenhanced
set output "door.png"
unset border; unset tics; unset key
set size ratio -1
set title "M03P4: door on two hinges, forces F_1, F_2 on the door"
w = 0.85; H = 2.05; y1 = 0.3; y2 = 1.75; d = 0.77; yh = 0.75
set xrange [-0.75:1.35]; set yrange [-0.2:2.3]
# the door, its hinge axis and the wall
set object 1 rect from 0,0 to w,H fc rgb "#dbe7f3" fs solid border lc rgb "#1f4e79" lw 3
set arrow 1 from -0.06,-0.1 to -0.06,H+0.1 nohead lw 4 lc rgb "gray"
set arrow 2 from 0,-0.15 to 0,H+0.15 nohead dt 2 lc rgb "gray"
set object 2 rect from -0.06,y1-0.06 to 0.04,y1+0.06 fc rgb "#7f6000" fs solid noborder
set object 3 rect from -0.06,y2-0.06 to 0.04,y2+0.06 fc rgb "#7f6000" fs solid noborder
# loads: the weight at the centroid, the bag at the handle
set arrow 3 from w/2,H/2 to w/2,H/2-0.45 lw 2 lc rgb "black"
set arrow 4 from d,yh to d,yh-0.35 lw 2 lc rgb "black"
set label 1 "m g" at w/2+0.04,H/2-0.35
set label 2 "m_b g" at d+0.04,yh-0.3
set label 3 "G" at w/2+0.04,H/2+0.06
set label 4 "handle" at d-0.12,yh+0.1
# the hinge forces on the door (the upper pulls, the lower pushes; each half the weight)
set arrow 5 from 0,y2 to -0.35,y2 lw 2 lc rgb "#c00000"
set arrow 6 from 0,y2 to 0,y2+0.3 lw 2 lc rgb "#c00000"
set arrow 7 from 0,y1 to 0.35,y1 lw 2 lc rgb "#c00000"
set arrow 8 from 0,y1 to 0,y1+0.3 lw 2 lc rgb "#c00000"
set label 5 "F_2 (upper)" at -0.72,y2+0.12 tc rgb "#c00000"
set label 6 "F_1 (lower)" at 0.1,y1+0.22 tc rgb "#c00000"
set label 7 "y_2" at -0.3,y2-0.12
set label 8 "y_1" at -0.3,y1-0.12
set label 9 "w" at w/2-0.03,-0.12
set label 10 "d" at d/2-0.1,yh+0.12
set arrow 9 from 0,yh+0.05 to d,yh+0.05 heads size 0.03,20 lw 1 lc rgb "gray"
set label 11 "x" at 1.22,0.02
set label 12 "y" at -0.7,2.2
set arrow 10 from 0.95,0 to 1.2,0 lw 1 lc rgb "black"
set arrow 11 from -0.65,2.0 to -0.65,2.25 lw 1 lc rgb "black"
set label 13 "g" at 1.2,1.85
set arrow 12 from 1.17,2.15 to 1.17,1.85 lw 1 lc rgb "gray"
plot "-" with points pt 7 ps 1.2 lc rgb "black"
0.425 1.025
e
