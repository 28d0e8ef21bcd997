# make lattice-compression [QUICK=1]: paper A Sec. 5.2, six tetrahedral lattices compressed.
#   T1P20 T1P30 T1P40 T2P20 T2P30 T2P40 x E in {8, 10} MPa x shape in {uGIMP, DDMP};
#   5x5x5 cells, 3 mm printed plates, cell 0.64 mm, 2 points per cell per direction, a rigid
#   plate driven down 20 mm at 100 mm/s onto the deformable printed top plate, the printed
#   base held (pipelines/lattice-compression/lattice-platen.toml), nu = 0.4, rho = 6 rho0.
#   QUICK=1: 2x2x2 cells, 2 mm plates, cell 1 mm, 4 mm travel.
#   DDMP cases appear once the solver has grid.shape = "ddmp" (pipelines/common.mk).
# Results in results/lattice-compression/{paper,quick}/: summary.md (latmpm-post's metrics,
# plots, the set-up and the cost of each run), metrics.csv, runs.csv, plots/, curves/,
# run-<lattice>-E<MPa>[-ddmp]/ (the solver's run directories).
# Chain per lattice: latmpm-lattice --preset -> latmpm-voxelize -> latmpm-solve
# pipelines/lattice-compression/lattice-platen.toml (per E and shape) -> latmpm-post.
include pipelines/common.mk

LC_SRC      := pipelines/lattice-compression
LC_OUT      := results/lattice-compression/$(if $(QUICK),quick,paper)
LC_LATTICES := T1P20 T1P30 T1P40 T2P20 T2P30 T2P40
LC_MODULI   := 8 10
LC_CELL     := $(if $(QUICK),1mm,0.64mm)
LC_CELLS    := $(if $(QUICK),2x2x2,5x5x5)
LC_PLATES   := $(if $(QUICK),2mm,3mm)
LC_TRAVEL   := $(if $(QUICK),4mm,20mm)
LC_SERIES   := $(if $(QUICK),20,50)
# Initial stiffness over this travel (the automatic range would sit in the start-up transient).
LC_FIT      := $(if $(QUICK),0.3mm:1mm,0.5mm:3mm)

lc_case = $(1)-E$(2)$(if $(filter ddmp,$(3)),-ddmp)
LC_RUNS :=
$(foreach l,$(LC_LATTICES),$(foreach e,$(LC_MODULI),$(foreach s,$(PIPELINE_SHAPES),\
  $(eval LC_RUNS += $(LC_OUT)/run-$(call lc_case,$l,$e,$s))\
  $(eval $(call pipeline_run,$(LC_OUT)/run-$(call lc_case,$l,$e,$s),$(LC_OUT)/points-$l.h5,$(LC_SRC)/lattice-platen.toml,\
    --set grid.cell=$(LC_CELL) $(call pipeline_shape_sets,$s) --set bodies.lattice.material.E=$(e)MPa \
    --set bodies.top_plate.material.E=$(e)MPa \
    --set $(call pipeline_platen_at,$(call pipeline_lattice_top,$l,$(lastword $(subst x, ,$(LC_CELLS))),$(LC_PLATES:mm=))) \
    --set run.end.plate_displacement=$(LC_TRAVEL) --set output.series_every=$(LC_SERIES))))))

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

$(eval $(call pipeline_post,$(LC_OUT),$(LC_RUNS),--kind compression --load load_fixed --fit-range $(LC_FIT),Lattice compression (paper A Sec. 5.2),$(LC_SRC)/notes.md))

$(LC_OUT)/summary.md: pipelines/lattice-compression.mk

.PRECIOUS: $(LC_OUT)/geometry-%.h5 $(LC_OUT)/points-%.h5
