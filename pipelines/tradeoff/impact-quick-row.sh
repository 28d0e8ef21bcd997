# Sourced by the QUICK impact studies (impact-levers.sh, impact-mass-scaling.sh): the QUICK
# impact row of pipelines/impact/cases-quick.txt (T2P30-E10, 2x2x2 cells, a 0.64 kg flyer at
# 2 m/s, 20 ms, uGIMP, one solver thread) as latmpm-solve options in `row`, after checking
# that its point file exists; `script` names the caller in the message.
points=results/impact/quick/points-T2P30.h5
[ -f "$points" ] || { echo "$script: $points: missing (make results/impact/quick/points-T2P30.h5 QUICK=1)" >&2; exit 2; }
row=(--set "points.0.file=$points" --set grid.cell=1mm --set grid.shape=ugimp --set run.end.time=20ms
     --set rigid_bodies.flyer.mass=0.64kg --set output.series_every=20
     --set 'rigid_bodies.flyer.min=["-100mm","-100mm","22.666700mm"]' --set 'rigid_bodies.flyer.max=["100mm","100mm","42.666700mm"]'
     --set output.snapshot_every=100000 --threads 1 --quiet)
