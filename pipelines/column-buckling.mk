# make column-buckling [QUICK=1]: paper A Sec. 4, the buckling column.
#   t in {2.4, 1.6} mm x a in {0, 0.02 L} x v0 in {100, 50} mm/s x shape in {uGIMP, DDMP},
#   L = 16 mm, E = 10 MPa, nu = 0.4, rho = 6 rho0, plate travel 3 mm; cell 0.2 mm with 2 points
#   per cell per direction (spacing 0.1 mm); and the cell-size study of t = 2.4 mm,
#   a = 0.02 L, v0 = 100 mm/s over cells 0.1, 0.2, 0.4, 0.64 mm.
#   QUICK=1: cell 0.4 mm (spacing 0.2 mm), cell study over 0.3, 0.4, 0.64 mm.
#   The runs are the rows of pipelines/column-buckling/cases-{paper,quick}.txt and
#   cell-study-{paper,quick}.txt; DDMP rows run when the solver lists the shape `ddmp`
#   (latmpm-solve --list shapes) unless DDMP=0 (they run by default, QUICK=1 included). CASES="t2.4-a0 h0.3"
#   makes only the named cases (and the summaries over them).
# Results in results/column-buckling/{paper,quick}/: ddmp-vs-ugimp/ (one plot of DDMP against
# uGIMP against the Euler load, t = 1.6 mm, a = 0.02 L: plots/load_displacement.png, and
# comparison.csv: DDMP's errors against uGIMP); summary.md (latmpm-post's column metrics:
# peak and post-buckling load against the Euler load, K = 0.5; plots; the notes and the cost
# of each run from its status.toml), metrics.csv, runs.csv, plots/, curves/,
# load-displacement-<case>.csv, run-<case>/ (the solver's run directory); cell-study/ the
# same for the cell-size study.
# Case names: t<t>-a<a>[-v50][-ddmp] (v0 = 100 mm/s and uGIMP unless named).
# Each file depends on the files it is made from: `make -j2 column-buckling` runs cases in
# parallel and a second call redoes only what changed (pipelines/common.mk).
# Chain per case: latmpm-lattice --column -> latmpm-voxelize -> latmpm-imperfect --type sine
# (a > 0) -> latmpm-solve pipelines/column-buckling/column.toml -> latmpm-post.
include pipelines/common.mk

CB_SRC     := pipelines/column-buckling
CB_MODE    := $(if $(QUICK),quick,paper)
CB_OUT     := results/column-buckling/$(CB_MODE)
CB_STUDY   := $(CB_OUT)/cell-study
CB_CELL    := $(if $(QUICK),0.4mm,0.2mm)
CB_PLATE   := $(if $(QUICK),0.8mm,0.4mm)
CB_LENGTH  := 16mm

CB_ROWS       := $(call pipeline_rows,$(CB_SRC)/cases-$(CB_MODE).txt,$(DDMP))
CB_STUDY_ROWS := $(call pipeline_rows,$(CB_SRC)/cell-study-$(CB_MODE).txt,$(DDMP))
$(call pipeline_table,$(CB_OUT),$(CB_SRC)/cases-$(CB_MODE).txt,$(CB_ROWS))
$(call pipeline_table,$(CB_STUDY),$(CB_SRC)/cell-study-$(CB_MODE).txt,$(CB_STUDY_ROWS))
CB_SELECTED       := $(call pipeline_selected,$(CB_ROWS))
CB_STUDY_SELECTED := $(call pipeline_selected,$(CB_STUDY_ROWS))
$(call pipeline_check_cases,column-buckling,$(CB_ROWS) $(CB_STUDY_ROWS))
# Both cases of the DDMP-against-uGIMP plot selected (below).
CB_HEADLINE := $(and $(filter t1.6-a0.02L,$(call pipeline_case_names,$(CB_SELECTED))),$(filter t1.6-a0.02L-ddmp,$(call pipeline_case_names,$(CB_SELECTED))))

.PHONY: column-buckling column-buckling-results
column-buckling:
	$(MAKE) build
	$(MAKE) column-buckling-results

column-buckling-results: $(if $(CB_SELECTED),$(CB_OUT)/summary.md) $(if $(CB_STUDY_SELECTED),$(CB_STUDY)/summary.md) \
    $(foreach r,$(CB_SELECTED),$(CB_OUT)/load-displacement-$(call pipeline_field,$r,1).csv) \
    $(if $(CB_HEADLINE),$(CB_OUT)/ddmp-vs-ugimp/summary.md)
	@echo "column-buckling: results in $(CB_OUT)/summary.md and $(CB_STUDY)/summary.md"

# Geometry: the column with end plates as thick as two cells (the base and the driven plate).
$(CB_OUT)/geometry-t%.h5: | $(BIN)/latmpm-lattice
	@mkdir -p $(@D)
	$(BIN)/latmpm-lattice --column --diameter $*mm --length $(CB_LENGTH) --end-plates $(CB_PLATE) --quiet -o $@

$(CB_OUT)/voxel-t%.h5: $(CB_OUT)/geometry-t%.h5 | $(BIN)/latmpm-voxelize
	$(BIN)/latmpm-voxelize $< --cell $(CB_CELL) --ppc 2 --quiet -o $@

# a = 0: the straight column as voxelized.
$(CB_OUT)/points-t%-a0.h5: $(CB_OUT)/voxel-t%.h5
	cp $< $@

# a = 0.02 L = 0.32 mm: u0(z) = a sin(pi z / L) over the column (paper A Sec. 4).
$(CB_OUT)/points-t%-a0.02L.h5: $(CB_OUT)/voxel-t%.h5 | $(BIN)/latmpm-imperfect
	$(BIN)/latmpm-imperfect $< --type sine --amount 0.32mm --length $(CB_LENGTH) --quiet -o $@

$(CB_OUT)/load-displacement-%.csv: $(CB_OUT)/run-%/done $(CB_SRC)/extract.sh
	bash $(CB_SRC)/extract.sh $(<D) $@

# latmpm-post's column metrics: peak and post-buckling load against the Euler load
# pi^2 E I / (K L)^2, K = 0.5 (clamped-clamped: notes.md says why).
$(eval $(call pipeline_post,$(CB_OUT),$(call pipeline_label_runs,$(CB_OUT),$(CB_SELECTED)),--kind column,Buckling column (paper A Sec. 4),$(CB_SRC)/notes.md))

# One plot of DDMP against uGIMP against Euler (issue 15): t = 1.6 mm, a = 0.02 L, 100 mm/s,
# both shapes in one latmpm-post call (plots/load_displacement.png, the Euler load dash-dotted),
# when both cases are selected.
$(eval $(call pipeline_post,$(CB_OUT)/ddmp-vs-ugimp,uGIMP=$(CB_OUT)/run-t1.6-a0.02L DDMP=$(CB_OUT)/run-t1.6-a0.02L-ddmp,--kind column --reference uGIMP,Column t = 1.6 mm a = 0.02 L: DDMP against uGIMP against Euler,$(CB_SRC)/notes.md))

# Cell-size study: t = 2.4 mm, a = 0.02 L, end plates of two cells, 2 points per cell per
# direction at every cell size h (the point file points-h<h>.h5).
$(CB_STUDY)/geometry-h%.h5: | $(BIN)/latmpm-lattice
	@mkdir -p $(@D)
	$(BIN)/latmpm-lattice --column --diameter 2.4mm --length $(CB_LENGTH) \
	  --end-plates $$(awk 'BEGIN { print 2 * $* }')mm --quiet -o $@
$(CB_STUDY)/points-h%.h5: $(CB_STUDY)/geometry-h%.h5 | $(BIN)/latmpm-voxelize $(BIN)/latmpm-imperfect
	$(BIN)/latmpm-voxelize $< --cell $*mm --ppc 2 --quiet -o - \
	  | $(BIN)/latmpm-imperfect - --type sine --amount 0.32mm --length $(CB_LENGTH) --quiet -o $@
$(eval $(call pipeline_post,$(CB_STUDY),$(call pipeline_label_runs,$(CB_STUDY),$(CB_STUDY_SELECTED)),--kind column,Buckling column: cell-size study (t = 2.4 mm a = 0.02 L),$(CB_SRC)/cell-study-notes.md))

$(CB_OUT)/summary.md $(CB_STUDY)/summary.md: pipelines/column-buckling.mk

.PRECIOUS: $(CB_OUT)/geometry-t%.h5 $(CB_OUT)/voxel-t%.h5 $(CB_OUT)/points-t%-a0.h5 \
           $(CB_OUT)/points-t%-a0.02L.h5 $(CB_STUDY)/geometry-h%.h5 $(CB_STUDY)/points-h%.h5
