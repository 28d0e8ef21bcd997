# Paper B Fig. 8 at our sizes: the contact forces f_i (incident plane, load_driven) and
# f_t (transmitter, load_fixed) and the volume-averaged f_a (Eq. 14, load_average) of one
# SHPB run against time. gnuplot -e "csv='RUN/series.csv'; png='OUT.png'; label='...'" plot_forces.gp
set datafile separator ","
set terminal pngcairo size 900,600
set output png
set xlabel "time (us)"
set ylabel "force (kN)"
set key bottom right
set grid
if (exists("label")) set title label noenhanced
plot csv using (column("time[s]")*1e6):(column("load_driven[N]")/1e3) with lines lw 2 title "f_i (incident plane)", \
     csv using (column("time[s]")*1e6):(column("load_fixed[N]")/1e3) with lines lw 2 dt 2 title "f_t (transmitter plane)", \
     csv using (column("time[s]")*1e6):(column("load_average[N]")/1e3) with lines lw 2 title "f_a = A_0/V {/Symbol S} {/Symbol s}_{zz} v_p (Eq. 14)"
