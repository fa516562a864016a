# The capstone's drawing: Simeon's flexible slider-crank (the data of
# include/fmbd/slider_crank_capstone.hpp) at a crank angle of 50 degrees, lengths in mm, O at the
# origin. The rod's deflection is drawn about 100 times larger than its size in the published run.
# Run in this folder: gnuplot slider_crank.gp (writes slider_crank.png).
set terminal pngcairo size 1200,620 font "sans,12" noenhanced
set output "slider_crank.png"
set size ratio -1
unset key
unset border; unset xtics; unset ytics
set xrange [-60:470]; set yrange [-70:212]
set title "Simeon's flexible slider-crank: rigid crank driven at omega, elastic rod pinned at both ends, point-mass slider on the x axis"

L1 = 150.0; L2 = 300.0
p1 = 50.0*pi/180
Ax = L1*cos(p1); Ay = L1*sin(p1)
p2 = -asin(L1*sin(p1)/L2)
Bx = Ax + L2*cos(p2); By = 0.0
# The drawn deflection from the chord, w(x) = q1 sin(pi x/L2) + q2 sin(2 pi x/L2), exaggerated.
q1 = 22.0; q2 = 5.0
w(x) = q1*sin(pi*x/L2) + q2*sin(2*pi*x/L2)
X(x) = Ax + x*cos(p2) - w(x)*sin(p2)
Y(x) = Ay + x*sin(p2) + w(x)*cos(p2)

# Ground: the guide on the x axis and the bearing at O.
set arrow 1 from -50,-9 to 460,-9 nohead lw 1 lc rgb "#555555"
do for [k=0:50] { set arrow 100+k from -50+10*k,-9 to -56+10*k,-17 nohead lw 1 lc rgb "#999999" }
set object 1 polygon from 0,0 to -12,-9 to 12,-9 to 0,0 fc rgb "#777777" fs solid border lc rgb "#555555"
# Crank, slider block, pins.
set arrow 2 from 0,0 to Ax,Ay nohead lw 8 lc rgb "#c00000"
set object 2 rect center Bx,0 size 46,18 fc rgb "#1f4e79" fs transparent solid 0.3 border lc rgb "#1f4e79" lw 2
set object 3 circle at 0,0 size 4 fc rgb "white" fs solid border lc rgb "black" front
set object 4 circle at Ax,Ay size 4 fc rgb "white" fs solid border lc rgb "black" front
set object 5 circle at Bx,0 size 4 fc rgb "white" fs solid border lc rgb "black" front
# The chord and the rod's frame at the crank pin.
set arrow 3 from Ax,Ay to Bx,By nohead dt 2 lw 1.5 lc rgb "#444444"
set arrow 4 from Ax,Ay to Ax+70*cos(p2),Ay+70*sin(p2) head filled size 6,20 lw 2 lc rgb "#2e7d32" front
set arrow 5 from Ax,Ay to Ax-45*sin(p2),Ay+45*cos(p2) head filled size 6,20 lw 2 lc rgb "#2e7d32" front
set label 1 "x (chord)" at Ax+50*cos(p2)+8,Ay+50*sin(p2)-22 tc rgb "#2e7d32"
set label 2 "y" at Ax-47*sin(p2)+3,Ay+47*cos(p2)+6 tc rgb "#2e7d32"
# Angles: phi1 at O from the x axis, phi2 of the chord at the crank pin (negative here).
set arrow 6 from 0,0 to 70,0 nohead dt 3 lc rgb "#888888"
set object 6 circle at 0,0 size 40 arc [0:50] fs empty border lc rgb "#c00000" lw 1.5
set label 3 "phi1 = omega t" at 44,18 tc rgb "#c00000"
set arrow 7 from Ax,Ay to Ax+90,Ay nohead dt 3 lc rgb "#888888"
set object 7 circle at Ax,Ay size 55 arc [360+p2*180/pi:360] fs empty border lc rgb "#444444" lw 1.5
set label 4 "phi2" at Ax+60,Ay-12 tc rgb "#444444"
# Lengths, names and the slider's coordinate.
set label 5 "crank: L1 = 150 mm, m1 = 0.36 kg, J1 = 0.002727 kg m^2 about O" at -55,198 tc rgb "#c00000"
set label 6 "O" at -6,12
set label 7 "crank pin" at Ax-70,Ay+4
set label 8 "wrist pin" at Bx-20,26
set label 9 "slider: m3 = 0.075552 kg (point mass)" at Bx-120,-32 tc rgb "#1f4e79"
set label 10 "rod: L2 = 300 mm, 8 x 8 mm, E = 200 GPa, rho = 7870 kg/m^3" at 200,168 tc rgb "#e08000"
set label 11 "w(x): its deflection from the chord (exaggerated)" at 200,152 tc rgb "#e08000"
set arrow 8 from 0,-48 to Bx,-48 heads size 5,20 lw 1 lc rgb "#333333"
set label 12 "x3" at Bx/2,-58
set arrow 9 from Bx,-40 to Bx,-56 nohead lc rgb "#333333"

plot sample [x=0:L2] '+' using (X($1)):(Y($1)) with lines lw 6 lc rgb "#e08000"
