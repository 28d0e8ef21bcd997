# gnuplot -e "prefix='/tmp/mesh'; png='docs/paper-b-meshes.png'" bench/paper_b/plot_meshes.gp
set terminal pngcairo size 1200,420 font ",10" noenhanced
set output png
set multiplot layout 1,3
unset key
set view 60,30
set view equal xyz
unset tics
unset border
set title "B2 (384 elements), 3D"
splot prefix."-B2.dat" with lines lc rgb "#1f4e79"
set view map
set title "B2, top face"
splot prefix."-B2.dat" using 1:2:($3 > 3.999 ? $3 : 1/0) with lines lc rgb "#1f4e79"
set title "B5 (6000 elements), top face"
splot prefix."-B5.dat" using 1:2:($3 > 3.999 ? $3 : 1/0) with lines lc rgb "#1f4e79"
unset multiplot
