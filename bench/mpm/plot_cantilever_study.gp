# gnuplot -e "csv='cantilever-study.csv'; png='docs/cantilever-study.png'" bench/mpm/plot_cantilever_study.gp
# (bench/mpm/cantilever_study.sh): tip deflection against beam theory, by cells across.
set terminal pngcairo size 1000,420 font ",10" noenhanced
set output png
set datafile separator ","
set multiplot layout 1,2
set grid
set key top right
set logscale x 2
set xrange [1.5:11]
set xtics (2, 4, 8)
set xlabel "cells across the thickness"
set title "Cantilever under its own weight (L = 8 t, nu = 0)"
set ylabel "tip deflection / beam theory"
plot sprintf("< grep '^ugimp,' %s", csv) using 2:5 with linespoints lw 2 pt 7 title "uGIMP", \
     sprintf("< grep '^ddmp,' %s", csv) using 2:5 with linespoints lw 2 pt 5 title "DDMP", \
     sprintf("< grep '^linear,' %s", csv) using 2:5 with linespoints lw 2 pt 9 dt 2 title "linear MPM", \
     1 with lines lc rgb "black" dt 4 title "beam theory"
set logscale y 10
set ylabel "|tip deflection / beam theory - 1|"
set title "Error against cell size"
plot sprintf("< grep '^ugimp,' %s", csv) using 2:(abs($5 - 1)) with linespoints lw 2 pt 7 title "uGIMP", \
     sprintf("< grep '^ddmp,' %s", csv) using 2:(abs($5 - 1)) with linespoints lw 2 pt 5 title "DDMP", \
     sprintf("< grep '^linear,' %s", csv) using 2:(abs($5 - 1)) with linespoints lw 2 pt 9 dt 2 title "linear MPM"
unset multiplot
