# make optimize [QUICK=1]: paper C (LETO topology optimisation) against the SIMP baseline,
# with latmpm-optimize (docs/paper-c.md).
#   QUICK=1: the 2D concentrated-load beam (60x20 cells) and the 3D beam (24x8x6 cells, half
#            model), 100 iterations at most: a few minutes on 2 cores.
#   full:    the 2D concentrated-load beam (60x20 cells), the Michell truss (40x20), the 2D
#            distributed-load beam (40x20) with and without LETO's narrow band, the 3D beam
#            (24x8x6 cells, half model).
# Results in results/optimize/{paper,quick}/: summary.md (per example and method: volume
# fraction, compliance at the optimisation resolution and on the grid refined twice,
# iterations, seconds per iteration), <example>/ (latmpm-optimize's output directory:
# summary.toml, histories, designs, PNG pictures, <method>-part.stl, <method>-points.h5).
.PHONY: optimize
optimize:
	$(MAKE) build
	bash pipelines/optimize/run.sh $(BIN) results/optimize/$(if $(QUICK),quick,paper) $(if $(QUICK),quick,paper)
