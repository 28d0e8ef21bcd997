# f_i (the incident plane's contact force, load_driven) of several SHPB runs against time:
# paper B Fig. 11 (friction) and Fig. 12 (meshes on G4, grids on B4) at our sizes.
# gnuplot -e "files='A/series.csv B/series.csv'; labels='B2 B3'; png='OUT.png'; label='...'" plot_study.gp
set datafile separator ","
set terminal pngcairo size 900,600
set output png
set xlabel "time (us)"
set ylabel "f_i (kN)"
set key top left
set grid
if (exists("label")) set title label noenhanced
plot for [i=1:words(files)] word(files, i) using (column("time[s]")*1e6):(column("load_driven[N]")/1e3) \
     with lines lw 2 title word(labels, i) noenhanced
