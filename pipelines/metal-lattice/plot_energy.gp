# The energy budget of a metal-lattice run against the platen's travel: the work put in
# (external_work: the platen's f.V), the plastic work (plastic_dissipation), the elastic
# energy (strain_energy: the most a release could give back), the contact springs and
# friction. gnuplot -e "csv='RUN/series.csv'; png='OUT.png'; label='...'" plot_energy.gp
set datafile separator ","
set terminal pngcairo size 900,600
set output png
if (exists("label")) set title label noenhanced
set xlabel "platen travel (mm)"
set ylabel "energy (J)"
set key top left
set grid
u = '(column("displacement[m]")*1e3)'
plot csv using @u:(column("external_work[J]")) with lines lw 2 title "work in (platen f V)", \
     csv using @u:(column("plastic_dissipation[J]")) with lines lw 2 title "plastic work", \
     csv using @u:(column("strain_energy[J]")) with lines lw 2 title "elastic energy (recoverable at most)", \
     csv using @u:(column("friction_dissipation[J]")) with lines lw 2 dt 2 title "friction", \
     csv using @u:(column("kinetic_energy[J]")) with lines lw 1 dt 3 title "kinetic"
