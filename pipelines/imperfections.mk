# make imperfections [QUICK=1]: paper A Sec. 5.3, printing imperfections of T1P40.
#   T1P40 x {none, A, B, C, D} (latmpm-imperfect, 1.28 mm each) x shape in {uGIMP, DDMP};
#   E = 10 MPa, otherwise as lattice-compression (5x5x5 cells, 3 mm plates, cell 0.64 mm,
#   2 points per cell per direction; 20 mm travel at 100 mm/s, where lattice-compression has 25).
#   QUICK=1: 2x2x2 cells, 2 mm plates, cell 1 mm, 4 mm travel.
#   The runs are the rows of pipelines/imperfections/cases-{paper,quick}.txt (DDMP rows as in
#   lattice-compression.mk); CASES="none A" makes only the named cases.
# Results in results/imperfections/{paper,quick}/: summary.md, metrics.csv, runs.csv, plots/,
# curves/, run-<type>[-ddmp]/.
# Chain: latmpm-lattice --preset T1P40 -> latmpm-voxelize -> latmpm-imperfect --type <X>
# -> latmpm-solve pipelines/lattice-compression/lattice-rigid.toml (a rigid plate driven onto
# the whole deformable printed top plate; the printed base omitted, a fixed half-space on its
# upper face) -> latmpm-post.
include pipelines/common.mk

IP_SRC    := pipelines/imperfections
IP_MODE   := $(if $(QUICK),quick,paper)
IP_OUT    := results/imperfections/$(IP_MODE)
IP_AMOUNT := 1.28mm
IP_CELL   := $(if $(QUICK),1mm,0.64mm)
IP_CELLS  := $(if $(QUICK),2x2x2,5x5x5)
IP_PLATES := $(if $(QUICK),2mm,3mm)
IP_FIT    := $(if $(QUICK),0.3mm:1mm,0.5mm:3mm)

IP_ROWS     := $(call pipeline_rows,$(IP_SRC)/cases-$(IP_MODE).txt,$(DDMP))
$(call pipeline_table,$(IP_OUT),$(IP_SRC)/cases-$(IP_MODE).txt,$(IP_ROWS))
IP_SELECTED := $(call pipeline_selected,$(IP_ROWS))
$(call pipeline_check_cases,imperfections,$(IP_ROWS))

.PHONY: imperfections imperfections-results
imperfections:
	$(MAKE) build
	$(MAKE) imperfections-results

imperfections-results: $(IP_OUT)/summary.md
	@echo "imperfections: results in $<"

$(IP_OUT)/geometry.h5: | $(BIN)/latmpm-lattice
	@mkdir -p $(@D)
	$(BIN)/latmpm-lattice --preset T1P40 --cells $(IP_CELLS) --plates $(IP_PLATES) --quiet -o $@

$(IP_OUT)/points-none.h5: $(IP_OUT)/geometry.h5 | $(BIN)/latmpm-voxelize
	$(BIN)/latmpm-voxelize $< --cell $(IP_CELL) --ppc 2 --quiet -o $@

# Types A-D with the imperfect tool's default bodies (A, C: lattice and top plate; B: all;
# D: lattice), 1.28 mm the largest displacement of any point (paper A Sec. 5.3).
$(IP_OUT)/points-%.h5: $(IP_OUT)/points-none.h5 | $(BIN)/latmpm-imperfect
	$(BIN)/latmpm-imperfect $< --type $* --amount $(IP_AMOUNT) --quiet -o $@

$(eval $(call pipeline_post,$(IP_OUT),$(call pipeline_label_runs,$(IP_OUT),$(IP_SELECTED)),--kind compression --load load_fixed --fit-range $(IP_FIT),Imperfections of T1P40 (paper A Sec. 5.3),$(IP_SRC)/notes.md))

$(IP_OUT)/summary.md: pipelines/imperfections.mk

.PRECIOUS: $(IP_OUT)/geometry.h5 $(IP_OUT)/points-%.h5
