# gnuplot -e "csv='curves.csv'; png='docs/paper-b-j2.png'" bench/paper_b/plot_curves.gp
set terminal pngcairo size 1100,420 font ",10" noenhanced
set yrange [0:*]
set output png
set datafile separator ","
set multiplot layout 1,2
set key bottom right
set grid
set title "Uniaxial stress (one material point)"
set xlabel "true axial strain ln(l/l0)"
set ylabel "Cauchy stress sigma_xx (MPa)"
plot csv every ::1 using ((strcol(1) eq "42CrMo4 400C" && strcol(2) eq "uniaxial") ? $3 : 1/0):4 with lines lw 2 title "42CrMo4 at 400 C, 2662 1/s", \
     csv every ::1 using ((strcol(1) eq "Ti-6Al-4V" && strcol(2) eq "uniaxial") ? $3 : 1/0):4 with lines lw 2 title "Ti-6Al-4V"
set title "Simple shear F = I + gamma e_x e_y"
set xlabel "gamma"
set ylabel "stress (MPa)"
plot csv every ::1 using ((strcol(1) eq "42CrMo4 400C" && strcol(2) eq "shear") ? $3 : 1/0):4 with lines lw 2 title "42CrMo4 sigma_xy", \
     csv every ::1 using ((strcol(1) eq "42CrMo4 400C" && strcol(2) eq "shear") ? $3 : 1/0):5 with lines dt 2 lw 2 title "42CrMo4 von Mises", \
     csv every ::1 using ((strcol(1) eq "Ti-6Al-4V" && strcol(2) eq "shear") ? $3 : 1/0):4 with lines lw 2 title "Ti-6Al-4V sigma_xy", \
     csv every ::1 using ((strcol(1) eq "Ti-6Al-4V" && strcol(2) eq "shear") ? $3 : 1/0):5 with lines dt 2 lw 2 title "Ti-6Al-4V von Mises"
unset multiplot
