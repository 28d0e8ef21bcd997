# make lattice-compression [QUICK=1]: paper A Sec. 5.2, six tetrahedral lattices compressed.
#   T1P20 T1P30 T1P40 T2P20 T2P30 T2P40 x E in {8, 10} MPa x shape in {uGIMP, DDMP};
#   5x5x5 cells, 3 mm printed plates, cell 0.64 mm, 2 points per cell per direction, nu = 0.4,
#   rho = 6 rho0, a rigid plate driven down 25 mm at 100 mm/s (past the experiments' densification
#   onsets, 17 / 20 / 23 mm for phi = 20 / 30 / 40 deg). Plates (PLATES=rigid, the
#   default; pipelines/lattice-compression/lattice-rigid.toml): the printed base omitted and a
#   fixed half-space in its place, the printed top plate kept deformable in a one-cell slice
#   under the rigid plate (docs/tradeoff.md, "Rigid plates": 2.3x fewer points, load within
#   1 % of the printed plates'). PLATES=printed: both printed plates as in paper A, the top one
#   deformable under the rigid plate, the base held as a fixed body (lattice-platen.toml),
#   results in {paper,quick}-printed/.
#   QUICK=1: 2x2x2 cells, 2 mm plates, cell 1 mm, 4 mm travel.
#   The runs are the rows of pipelines/lattice-compression/cases-{paper,quick}[-printed].txt; DDMP rows
#   run when the solver lists the shape `ddmp` (latmpm-solve --list shapes) and DDMP=1 (the
#   default without QUICK). CASES="T2P30-E10 T1P40-E8" makes only the named cases (and the
#   summary over them).
# Results in results/lattice-compression/{paper,quick}/: summary.md (latmpm-post's metrics,
# plots, the set-up and the cost of each run), metrics.csv, runs.csv, plots/, curves/,
# run-<lattice>-E<MPa>[-ddmp]/ (the solver's run directories).
# Chain per lattice: latmpm-lattice --preset -> latmpm-voxelize -> latmpm-solve
# pipelines/lattice-compression/lattice-platen.toml (one run a row) -> latmpm-post.
include pipelines/common.mk

LC_SRC      := pipelines/lattice-compression
PLATES      ?= rigid
$(if $(filter-out rigid printed,$(PLATES)),$(error PLATES: '$(PLATES)' is not one of rigid, printed))
LC_MODE     := $(if $(QUICK),quick,paper)$(if $(filter printed,$(PLATES)),-printed)
LC_OUT      := results/lattice-compression/$(LC_MODE)
LC_CELL     := $(if $(QUICK),1mm,0.64mm)
LC_CELLS    := $(if $(QUICK),2x2x2,5x5x5)
LC_PLATES   := $(if $(QUICK),2mm,3mm)
# Initial stiffness over this travel (the automatic range would sit in the start-up transient).
LC_FIT      := $(if $(QUICK),0.3mm:1mm,0.5mm:3mm)

LC_ROWS     := $(call pipeline_rows,$(LC_SRC)/cases-$(LC_MODE).txt,$(DDMP))
$(call pipeline_table,$(LC_OUT),$(LC_SRC)/cases-$(LC_MODE).txt,$(LC_ROWS))
LC_SELECTED := $(call pipeline_selected,$(LC_ROWS))
$(call pipeline_check_cases,lattice-compression,$(LC_ROWS))

.PHONY: lattice-compression lattice-compression-results
lattice-compression:
	$(MAKE) build
	$(MAKE) lattice-compression-results

lattice-compression-results: $(LC_OUT)/summary.md
	@echo "lattice-compression: results in $<"

$(LC_OUT)/geometry-%.h5: | $(BIN)/latmpm-lattice
	@mkdir -p $(@D)
	$(BIN)/latmpm-lattice --preset $* --cells $(LC_CELLS) --plates $(LC_PLATES) --quiet -o $@

$(LC_OUT)/points-%.h5: $(LC_OUT)/geometry-%.h5 | $(BIN)/latmpm-voxelize
	$(BIN)/latmpm-voxelize $< --cell $(LC_CELL) --ppc 2 --quiet -o $@

$(eval $(call pipeline_post,$(LC_OUT),$(call pipeline_label_runs,$(LC_OUT),$(LC_SELECTED)),--kind compression --load load_fixed --fit-range $(LC_FIT),Lattice compression (paper A Sec. 5.2),$(LC_SRC)/notes.md))

$(LC_OUT)/summary.md: pipelines/lattice-compression.mk

.PRECIOUS: $(LC_OUT)/geometry-%.h5 $(LC_OUT)/points-%.h5
