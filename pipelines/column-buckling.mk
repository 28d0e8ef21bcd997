# make column-buckling [QUICK=1]: paper A Sec. 4, the buckling column.
#   t in {2.4, 1.6} mm x a in {0, 0.02 L} x v0 in {100, 50} mm/s x shape in {uGIMP, DDMP},
#   L = 16 mm, E = 10 MPa, nu = 0.4, rho = 6 rho0, plate travel 3 mm; cell 0.2 mm with 2 points
#   per cell per direction (spacing 0.1 mm); and the cell-size study of t = 2.4 mm,
#   a = 0.02 L, v0 = 100 mm/s over cells 0.1, 0.2, 0.4, 0.64 mm.
#   QUICK=1: cell 0.4 mm (spacing 0.2 mm), cell study over 0.3, 0.4, 0.64 mm.
#   DDMP cases appear once the solver has grid.shape = "ddmp" (pipelines/common.mk).
# Results in results/column-buckling/{paper,quick}/: summary.md (latmpm-post's column metrics:
# peak and post-buckling load against the Euler load, K = 0.5; plots; then the Euler table of
# summary.sh and the cost of each run), metrics.csv, plots/, curves/, load-displacement-<case>.csv,
# run-<case>/ (the solver's run directory); cell-study/ the same for the cell-size study.
# Case names: t<t>-a<a>[-v50][-ddmp] (v0 = 100 mm/s and uGIMP unless named).
# Each file depends on the files it is made from: `make -j2 column-buckling` runs cases in
# parallel and a second call redoes only what changed (pipelines/common.mk).
# Chain per case: latmpm-lattice --column -> latmpm-voxelize -> latmpm-imperfect --type sine
# (a > 0) -> latmpm-solve pipelines/column-buckling/column.toml -> latmpm-post.
include pipelines/common.mk

CB_SRC     := pipelines/column-buckling
CB_OUT     := results/column-buckling/$(if $(QUICK),quick,paper)
CB_CELL    := $(if $(QUICK),0.4mm,0.2mm)
CB_PLATE   := $(if $(QUICK),0.8mm,0.4mm)
CB_LENGTH  := 16mm
CB_STUDY_CELLS := $(if $(QUICK),0.3 0.4 0.64,0.1 0.2 0.4 0.64)

# The case name of t, a, v0, shape.
cb_case = t$(1)-a$(2)$(if $(filter 50,$(3)),-v50)$(if $(filter ddmp,$(4)),-ddmp)
cb_velocity = 'bodies.top_plate.velocity=["0mm/s","0mm/s","-$(1)mm/s"]'
CB_CASES :=
$(foreach t,2.4 1.6,$(foreach a,0 0.02L,$(foreach v,100 50,$(foreach s,$(PIPELINE_SHAPES),\
  $(eval CB_CASES += $(call cb_case,$t,$a,$v,$s))\
  $(eval $(call pipeline_run,$(CB_OUT)/run-$(call cb_case,$t,$a,$v,$s),$(CB_OUT)/points-t$t-a$a.h5,$(CB_SRC)/column.toml,\
    --set grid.cell=$(CB_CELL) $(call pipeline_shape_sets,$s) --set $(call cb_velocity,$v)))))))
CB_RUNS := $(foreach c,$(CB_CASES),$(CB_OUT)/run-$c)

.PHONY: column-buckling column-buckling-results
column-buckling:
	$(MAKE) build
	$(MAKE) column-buckling-results

column-buckling-results: $(CB_OUT)/summary.md $(CB_OUT)/cell-study/summary.md
	@echo "column-buckling: results in $(CB_OUT)/summary.md and $(CB_OUT)/cell-study/summary.md"

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

$(CB_OUT)/load-displacement-%.csv: $(CB_OUT)/run-%/wall_time.txt $(CB_SRC)/extract.sh
	bash $(CB_SRC)/extract.sh $(<D) $@

# The Euler table (E = 10 MPa, L = 16 mm, K = 0.5, clamped-clamped; summary.sh says why),
# appended to latmpm-post's summary.
$(CB_OUT)/euler.md: $(foreach c,$(CB_CASES),$(CB_OUT)/load-displacement-$(c).csv) $(CB_SRC)/summary.sh $(CB_SRC)/notes.md
	{ cat $(CB_SRC)/notes.md; echo; echo "## Against the Euler load (summary.sh)"; echo; \
	  bash $(CB_SRC)/summary.sh $(CB_OUT) 10e6 0.016 0.5 $(CB_CASES); } > $@.tmp && mv $@.tmp $@
$(eval $(call pipeline_post,$(CB_OUT),$(CB_RUNS),--kind column,Buckling column (paper A Sec. 4),$(CB_OUT)/euler.md))

# Cell-size study: t = 2.4 mm, a = 0.02 L, v0 = 100 mm/s, uGIMP (and DDMP), end plates of two
# cells, 2 points per cell per direction at every cell size.
CB_STUDY := $(CB_OUT)/cell-study
define cb_study_points
$(CB_STUDY)/geometry-h$(1).h5: | $(BIN)/latmpm-lattice
	@mkdir -p $$(@D)
	$(BIN)/latmpm-lattice --column --diameter 2.4mm --length $(CB_LENGTH) \
	  --end-plates $$$$(awk 'BEGIN { print 2 * $(1) }')mm --quiet -o $$@
$(CB_STUDY)/points-h$(1).h5: $(CB_STUDY)/geometry-h$(1).h5 | $(BIN)/latmpm-voxelize $(BIN)/latmpm-imperfect
	$(BIN)/latmpm-voxelize $$< --cell $(1)mm --ppc 2 --quiet -o - \
	  | $(BIN)/latmpm-imperfect - --type sine --amount 0.32mm --length $(CB_LENGTH) --quiet -o $$@
endef
# At the main cell size the study's case is the main case t2.4-a0.02L: its run is reused.
cb_study_label = h$(1)$(if $(filter ddmp,$(2)),-ddmp)
cb_study_main  = $(filter $(1)mm,$(CB_CELL))
cb_study_run   = $(if $(cb_study_main),$(CB_OUT)/run-$(call cb_case,2.4,0.02L,100,$(2)),$(CB_STUDY)/run-$(cb_study_label))
CB_STUDY_RUNS := $(foreach h,$(CB_STUDY_CELLS),$(foreach s,$(PIPELINE_SHAPES),$(call cb_study_label,$h,$s)=$(call cb_study_run,$h,$s)))
$(foreach h,$(CB_STUDY_CELLS),$(if $(call cb_study_main,$h),,$(eval $(call cb_study_points,$h))$(foreach s,$(PIPELINE_SHAPES),\
  $(eval $(call pipeline_run,$(call cb_study_run,$h,$s),$(CB_STUDY)/points-h$h.h5,$(CB_SRC)/column.toml,\
    --set grid.cell=$(h)mm $(call pipeline_shape_sets,$s))))))
$(eval $(call pipeline_post,$(CB_STUDY),$(CB_STUDY_RUNS),--kind column,Buckling column: cell-size study (t = 2.4 mm a = 0.02 L),$(CB_SRC)/cell-study-notes.md))

$(CB_OUT)/summary.md $(CB_STUDY)/summary.md: pipelines/column-buckling.mk

.PRECIOUS: $(CB_OUT)/geometry-t%.h5 $(CB_OUT)/voxel-t%.h5 $(CB_OUT)/points-t%-a0.h5 \
           $(CB_OUT)/points-t%-a0.02L.h5
