# The capstone's drawing: Andrews' squeezer at t = 0 in its published configuration (the data of
# include/fmbd/squeezer.hpp), lengths in mm, O at the origin.
# Run in this folder: gnuplot squeezer.gp (writes squeezer.png).
set terminal pngcairo size 1100,900 font "sans,12" noenhanced
set output "squeezer.png"
set size ratio -1
unset key
set grid lc rgb "#e8e8e8"
set xlabel "x [mm]"; set ylabel "y [mm]"
set xrange [-82:28]; set yrange [-28:80]
set title "Andrews' squeezer at t = 0 (published configuration): 7 bodies, 10 revolute joints, torque on body 1, spring C-D"

# Published data [mm] and angles [rad].
xa = -69.34; ya = -2.27; xb = -36.35; yb = 32.73; xc = 14.0; yc = 72.0
rr = 7.0; ra = 0.92; d = 28.0; da = 11.5; ss = 35.0; sa = 18.74; sb = 10.43; sc = 18.0; sd = 20.0
e = 20.0; ea = 14.21; zt = 40.0; ta = 23.08; tb = 9.16; zf = 20.0; fa = 14.21; u = 40.0; ua = 12.28; ub = 4.49
be = -0.0617138900142764; th = 0.0; ga = 0.455279819163070; ph = 0.222668390165886
de = 0.487364979543843; om = -0.222668390165886; ep = 1.23054744454982

Fx = rr*cos(be); Fy = rr*sin(be)
Ex = Fx - d*cos(be+th); Ey = Fy - d*sin(be+th)
Dx = xb + sc*sin(ga) + sd*cos(ga); Dy = yb - sc*cos(ga) + sd*sin(ga)
Gx = xa + zt*cos(de); Gy = ya + zt*sin(de)
Hx = xa + u*sin(ep); Hy = ya - u*cos(ep)
# centroids
S1x = ra*cos(be); S1y = ra*sin(be)
S2x = Fx - da*cos(be+th); S2y = Fy - da*sin(be+th)
S3x = xb + sa*sin(ga) + sb*cos(ga); S3y = yb - sa*cos(ga) + sb*sin(ga)
S4x = Ex - ea*sin(ph+de); S4y = Ey + ea*cos(ph+de)
S5x = xa + ta*cos(de) - tb*sin(de); S5y = ya + ta*sin(de) + tb*cos(de)
S6x = Ex - fa*cos(om+ep); S6y = Ey - fa*sin(om+ep)
S7x = xa + ua*sin(ep) + ub*cos(ep); S7y = ya - ua*cos(ep) + ub*sin(ep)

# Bodies: the triangle filled, the links as thick lines.
set object 1 polygon from xb,yb to Ex,Ey to Dx,Dy to xb,yb fc rgb "#1f4e79" fs transparent solid 0.25 border lc rgb "#1f4e79" lw 3
set arrow 1 from 0,0 to Fx,Fy nohead lw 7 lc rgb "#c00000"
set arrow 2 from Fx,Fy to Ex,Ey nohead lw 5 lc rgb "#e08000"
set arrow 3 from Gx,Gy to Ex,Ey nohead lw 5 lc rgb "#2e7d32"
set arrow 4 from xa,ya to Gx,Gy nohead lw 5 lc rgb "#6a1b9a"
set arrow 5 from Hx,Hy to Ex,Ey nohead lw 5 lc rgb "#00838f"
set arrow 6 from xa,ya to Hx,Hy nohead lw 5 lc rgb "#795548"
# The spring from C to D.
set arrow 7 from xc,yc to Dx,Dy nohead lw 2 dt 2 lc rgb "black"
# The motor torque about O.
set object 2 circle at 0,0 size 10 arc [200:330] fs empty border lc rgb "#c00000" lw 2
set arrow 8 from 10*cos(320*pi/180),10*sin(320*pi/180) to 10*cos(330*pi/180)+0.8,10*sin(330*pi/180)+0.9 lw 2 lc rgb "#c00000"

# Ground pivots and joints.
set object 3 polygon from 0,0 to -3,-5 to 3,-5 to 0,0 fs pattern 4 border lc rgb "black"
set object 4 polygon from xa,ya to xa-3,ya-5 to xa+3,ya-5 to xa,ya fs pattern 4 border lc rgb "black"
set object 5 polygon from xb,yb to xb-3,yb+5 to xb+3,yb+5 to xb,yb fs pattern 4 border lc rgb "black"
set object 6 polygon from xc,yc to xc-3,yc+5 to xc+3,yc+5 to xc,yc fs pattern 4 border lc rgb "black"
set print $joints
print sprintf("%g %g", 0, 0)
print sprintf("%g %g", Fx, Fy)
print sprintf("%g %g", Ex, Ey)
print sprintf("%g %g", Gx, Gy)
print sprintf("%g %g", Hx, Hy)
print sprintf("%g %g", xa, ya)
print sprintf("%g %g", xb, yb)
print sprintf("%g %g", Dx, Dy)
print sprintf("%g %g", xc, yc)
set print
set print $centroids
print sprintf("%g %g", S1x, S1y)
print sprintf("%g %g", S2x, S2y)
print sprintf("%g %g", S3x, S3y)
print sprintf("%g %g", S4x, S4y)
print sprintf("%g %g", S5x, S5y)
print sprintf("%g %g", S6x, S6y)
print sprintf("%g %g", S7x, S7y)
set print

# Labels: points, bodies, centroids.
set label 1 "O (0, 0)" at -3,-13
set label 2 "F" at Fx+1.2,Fy+2.5 font "sans,14"
set label 3 "E" at Ex-4.5,Ey+3 font "sans,14"
set label 4 "D" at Dx+1.5,Dy-1 font "sans,14"
set label 5 "G" at Gx+1.5,Gy+1.5 font "sans,14"
set label 6 "H" at Hx+1.5,Hy-2.5 font "sans,14"
set label 7 sprintf("A (%.2f, %.2f)", xa, ya) at xa-9,ya-8
set label 8 sprintf("B (%.2f, %.2f)", xb, yb) at xb-10,yb+8.5
set label 9 sprintf("C (%.2f, %.2f)", xc, yc) at xc-4.5,yc+3 right
set label 10 "1" at 3,3 tc rgb "#c00000" font "sans,15"
set label 11 "2" at S2x-1,S2y+3.5 tc rgb "#e08000" font "sans,15"
set label 12 "3" at S3x+2,S3y+1 tc rgb "#1f4e79" font "sans,15"
set label 13 "4" at S4x-1,S4y-4 tc rgb "#2e7d32" font "sans,15"
set label 14 "5" at S5x+1,S5y+2 tc rgb "#6a1b9a" font "sans,15"
set label 15 "6" at S6x+1.5,S6y+1 tc rgb "#00838f" font "sans,15"
set label 16 "7" at S7x+1.5,S7y tc rgb "#795548" font "sans,15"
set label 17 "spring c0, l0" at 0.5*(xc+Dx)+2,0.5*(yc+Dy)
set label 18 "motor torque 0.033 N m" at 26,-18 right tc rgb "#c00000"
set label 19 "x  centroid (body frame origin)" at -80,-20
set label 20 "o  revolute joint" at -80,-24

plot $joints using 1:2 with points pt 6 ps 2.2 lw 2 lc rgb "black", \
     $centroids using 1:2 with points pt 2 ps 1.8 lw 2 lc rgb "black"
