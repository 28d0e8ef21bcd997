# make lattice-stiffness [QUICK=1] [CASES=...]: the six paper lattices' initial stiffness,
# effective modulus and first instability load from the static solver (docs/statics.md).
#   T1P20 T1P30 T1P40 T2P20 T2P30 T2P40 at the lattice-compression sizes (5x5x5 cells, 3 mm
#   printed plates, cell 0.64 mm, 2 points per cell per direction; QUICK=1: 2x2x2 cells, 2 mm
#   plates, cell 1 mm), uGIMP, E = 10 MPa, nu = 0.4, the lattice-compression scene. The runs
#   are the rows of pipelines/lattice-stiffness/cases-{quick,paper}.txt: per lattice
#   "initial" (linear elastic, one increment of 0.1 mm: k, and E* = k H / A with H the height
#   between the plates and A the footprint, both computed by latmpm-post from the parameters
#   latmpm-lattice records) and "path"
#   (neo-Hookean, increments to 20 mm / 4 mm: where the load falls or Newton fails).
# make lattice-stiffness-initial [QUICK=1]: only the initial stiffness (seconds per lattice).
# Results in results/lattice-stiffness/{paper,quick}/: stiffness.md (table), stiffness.csv,
# stiffness.png, initial/ (latmpm-post over the initial runs), run-<lattice>-{initial,path}/
# (run directories).
include pipelines/common.mk

LS_SRC      := pipelines/lattice-stiffness
LS_MODE     := $(if $(QUICK),quick,paper)
LS_OUT      := results/lattice-stiffness/$(LS_MODE)
LS_LATTICES := T1P20 T1P30 T1P40 T2P20 T2P30 T2P40
LS_CELL     := $(if $(QUICK),1mm,0.64mm)
LS_CELLS    := $(if $(QUICK),2x2x2,5x5x5)
LS_PLATES   := $(if $(QUICK),2mm,3mm)

LS_ROWS     := $(call pipeline_rows,$(LS_SRC)/cases-$(LS_MODE).txt,1)
$(call pipeline_table,$(LS_OUT),$(LS_SRC)/cases-$(LS_MODE).txt,$(LS_ROWS))
LS_SELECTED := $(call pipeline_selected,$(LS_ROWS))
$(call pipeline_check_cases,lattice-stiffness,$(LS_ROWS))
ls_runs_done = $(foreach r,$(1),$(call pipeline_row_run,$(LS_OUT),$r)/done)
ls_lattices  = $(sort $(foreach r,$(1),$(firstword $(subst -, ,$(call pipeline_field,$r,1)))))

.PHONY: lattice-stiffness lattice-stiffness-results lattice-stiffness-initial
lattice-stiffness:
	$(MAKE) build
	$(MAKE) lattice-stiffness-results

lattice-stiffness-results: $(LS_OUT)/stiffness.md
	@echo "lattice-stiffness: results in $<"

LS_INITIAL := $(foreach r,$(LS_SELECTED),$(if $(filter %-initial,$(call pipeline_field,$r,1)),$r))
lattice-stiffness-initial: $(call ls_runs_done,$(LS_INITIAL)) | $(BIN)/latmpm-post
	bash $(LS_SRC)/table.sh $(BIN) $(LS_OUT) $(call ls_lattices,$(LS_INITIAL))

$(LS_OUT)/stiffness.md: $(call ls_runs_done,$(LS_SELECTED)) $(LS_SRC)/table.sh pipelines/lattice-stiffness.mk \
    | $(BIN)/latmpm-post
	bash $(LS_SRC)/table.sh $(BIN) $(LS_OUT) $(call ls_lattices,$(LS_SELECTED))

$(LS_OUT)/geometry-%.h5: | $(BIN)/latmpm-lattice
	@mkdir -p $(@D)
	$(BIN)/latmpm-lattice --preset $* --cells $(LS_CELLS) --plates $(LS_PLATES) --quiet -o $@

$(LS_OUT)/points-%.h5: $(LS_OUT)/geometry-%.h5 | $(BIN)/latmpm-voxelize
	$(BIN)/latmpm-voxelize $< --cell $(LS_CELL) --ppc 2 --quiet -o $@

.PRECIOUS: $(LS_OUT)/geometry-%.h5 $(LS_OUT)/points-%.h5
