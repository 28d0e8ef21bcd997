# make optimize [QUICK=1]: paper C (LETO topology optimisation) against the SIMP baseline,
# with latmpm-optimize (docs/paper-c.md).
#   QUICK=1: the 2D concentrated-load beam (60x20 cells) and the 3D beam (24x8x6 cells, half
#            model), 200 iterations at most: about 4 minutes on 2 cores.
#   full:    the 2D concentrated-load beam (60x20 cells), the Michell truss (40x20), the 2D
#            distributed-load beam (40x20) with and without LETO's narrow band (without:
#            Eq. 38's sharpening) and without the connectivity correction, the 3D beam
#            (24x8x6 cells, half model), the 3D bridge (24x12x6 cells, quarter model), the
#            2D beam with a neo-Hookean solid under a 150 times larger load (LETO only).
# Both end with the optimised 3D beam in latmpm-solve: each method's STL (the whole part,
# mirrored) through latmpm-voxelize, and its point file, loaded quasi-statically in the
# explicit solver as it was optimised (pipelines/optimize/beam-3d-explicit.toml); the
# stiffness against the optimiser's compliance is the last table of summary.md (about 40 s
# per run, four runs).
# Results in results/optimize/{paper,quick}/: summary.md (per example and method: volume
# fraction, compliance at the optimisation resolution and on the grid refined twice,
# iterations, seconds per iteration), <example>/ (latmpm-optimize's output directory:
# summary.toml, histories, designs, PNG pictures, <method>-part.stl, <method>-points.h5).
.PHONY: optimize
optimize:
	$(MAKE) build
	bash pipelines/optimize/run.sh $(BIN) results/optimize/$(if $(QUICK),quick,paper) $(if $(QUICK),quick,paper)
