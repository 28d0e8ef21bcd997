# The energy budget of a metal-lattice load-unload run against time: the work put in
# (external_work: the platen's f.V, falling as the unloading lattice pushes the platen back),
# the plastic work (plastic_dissipation), the elastic energy (strain_energy), friction,
# kinetic energy, and the platen's travel (right axis). gnuplot -e "csv='RUN/series.csv'; png='OUT.png'; label='...'" plot_energy.gp
set datafile separator ","
set terminal pngcairo size 900,600
set output png
if (exists("label")) set title label noenhanced
set xlabel "time (us)"
set ylabel "energy (J)"
set y2label "platen travel, down (mm)"
set ytics nomirror
set y2tics
set key top left
set grid
u = '(column("time[s]")*1e6)'
plot csv using @u:(column("external_work[J]")) with lines lw 2 title "work in (platen f V)", \
     csv using @u:(column("plastic_dissipation[J]")) with lines lw 2 title "plastic work", \
     csv using @u:(column("strain_energy[J]")) with lines lw 2 title "elastic energy", \
     csv using @u:(column("friction_dissipation[J]")) with lines lw 2 dt 2 title "friction", \
     csv using @u:(column("kinetic_energy[J]")) with lines lw 1 dt 3 title "kinetic", \
     csv using @u:(column("displacement[m]")*1e3) axes x1y2 with lines lw 1 lc rgb "black" dt 4 title "platen travel"
