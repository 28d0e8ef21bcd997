# make imperfections [QUICK=1]: paper A Sec. 5.3, printing imperfections of T1P40.
#   T1P40 x {none, A, B, C, D} (latmpm-imperfect, 1.28 mm each) x shape in {uGIMP, DDMP};
#   E = 10 MPa, otherwise as lattice-compression (5x5x5 cells, 3 mm plates, cell 0.64 mm,
#   2 points per cell per direction, 20 mm travel at 100 mm/s).
#   QUICK=1: 2x2x2 cells, 2 mm plates, cell 1 mm, 4 mm travel.
# Results in results/imperfections/{paper,quick}/: summary.md, metrics.csv, runs.csv, plots/,
# curves/, run-<type>[-ddmp]/.
# Chain: latmpm-lattice --preset T1P40 -> latmpm-voxelize -> latmpm-imperfect --type <X>
# -> latmpm-solve pipelines/lattice-compression/lattice.toml -> latmpm-post.
include pipelines/common.mk

IM_SRC    := pipelines/imperfections
IM_OUT    := results/imperfections/$(if $(QUICK),quick,paper)
IM_TYPES  := none A B C D
IM_AMOUNT := 1.28mm
IM_CELL   := $(if $(QUICK),1mm,0.64mm)
IM_CELLS  := $(if $(QUICK),2x2x2,5x5x5)
IM_PLATES := $(if $(QUICK),2mm,3mm)
IM_TRAVEL := $(if $(QUICK),4mm,20mm)
IM_SERIES := $(if $(QUICK),20,50)
IM_FIT    := $(if $(QUICK),0.3mm:1mm,0.5mm:3mm)

im_case = $(1)$(if $(filter ddmp,$(2)),-ddmp)
IM_RUNS :=
$(foreach x,$(IM_TYPES),$(foreach s,$(PIPELINE_SHAPES),\
  $(eval IM_RUNS += $(IM_OUT)/run-$(call im_case,$x,$s))\
  $(eval $(call pipeline_run,$(IM_OUT)/run-$(call im_case,$x,$s),$(IM_OUT)/points-$x.h5,pipelines/lattice-compression/lattice.toml,\
    --set grid.cell=$(IM_CELL) --set grid.shape=$s --set bodies.lattice.material.E=10MPa \
    --set run.end.plate_displacement=$(IM_TRAVEL) --set output.series_every=$(IM_SERIES)))))

.PHONY: imperfections imperfections-results
imperfections:
	$(MAKE) build
	$(MAKE) imperfections-results

imperfections-results: $(IM_OUT)/summary.md
	@echo "imperfections: results in $<"

$(IM_OUT)/geometry.h5: | $(BIN)/latmpm-lattice
	@mkdir -p $(@D)
	$(BIN)/latmpm-lattice --preset T1P40 --cells $(IM_CELLS) --plates $(IM_PLATES) --quiet -o $@

$(IM_OUT)/points-none.h5: $(IM_OUT)/geometry.h5 | $(BIN)/latmpm-voxelize
	$(BIN)/latmpm-voxelize $< --cell $(IM_CELL) --ppc 2 --quiet -o $@

# Types A-D with the imperfect tool's default bodies (A, C: lattice and top plate; B: all;
# D: lattice), 1.28 mm the largest displacement of any point (paper A Sec. 5.3).
$(IM_OUT)/points-%.h5: $(IM_OUT)/points-none.h5 | $(BIN)/latmpm-imperfect
	$(BIN)/latmpm-imperfect $< --type $* --amount $(IM_AMOUNT) --quiet -o $@

$(eval $(call pipeline_post,$(IM_OUT),$(IM_RUNS),--kind compression --fit-range $(IM_FIT),Imperfections of T1P40 (paper A Sec. 5.3),$(IM_SRC)/notes.md))

$(IM_OUT)/summary.md: pipelines/imperfections.mk

.PRECIOUS: $(IM_OUT)/geometry.h5 $(IM_OUT)/points-%.h5
