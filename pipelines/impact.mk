# make impact [QUICK=1]: paper A Sec. 6, a rigid flyer strikes a tetrahedral lattice.
#   T1P20 ... T2P40 x E in {10, 100} MPa, nu = 0.4, real density rho0 = 1050 kg/m^3, shape in
#   {uGIMP, DDMP} (DDMP with USL, its default; DDMP=0 leaves it out; QUICK: T2P30-E10 only),
#   flyer 10 kg at 2 m/s, gravity 9.81 m/s^2 on flyer and lattice, bottom plate held,
#   5x5x5 cells, 3 mm plates, cell 0.64 mm, 2 points per cell per direction, 25 ms (the
#   40-degree lattices 30 ms: their flyers reverse after 25 ms).
#   QUICK=1: 2x2x2 cells, 2 mm plates, cell 1 mm, 20 ms, and the flyer's mass scaled with the
#   lattice's volume, 10 kg x (2x2x2)/(5x5x5) = 0.64 kg, so that the energy per cell is the
#   paper's (a 10 kg flyer would crush the small lattice flat in a few ms).
# Results in results/impact/{paper,quick}/: impact-<case>.csv (time[ms], load_flyer[N],
# load_fixed[N], flyer_speed[m/s], flyer_energy[J], energy_error[J]), summary.md (latmpm-post's
# impact metrics and plots, notes, and the wall time of each run), run-<case>/ (the solver's
# run directories, with checkpoints: an interrupted run continues with
# `latmpm-solve --resume results/impact/.../run-<case>`).
# The runs are the rows of pipelines/impact/cases-{paper,quick}.txt (the flyer's position is
# in the rows); CASES=T2P30-E10 makes only the named cases.
# Chain: latmpm-lattice --preset <lattice> -> latmpm-voxelize -> latmpm-solve
# pipelines/impact/impact.toml -> latmpm-post.
include pipelines/common.mk

IM_SRC    := pipelines/impact
IM_MODE   := $(if $(QUICK),quick,paper)
IM_OUT    := results/impact/$(IM_MODE)
IM_CELL   := $(if $(QUICK),1mm,0.64mm)
IM_CELLS  := $(if $(QUICK),2x2x2,5x5x5)
IM_PLATES := $(if $(QUICK),2mm,3mm)

# Both shapes at either resolution (the issue asks for uGIMP and DDMP), unless DDMP=0 is
# given on the command line.
IM_DDMP     := $(if $(filter command line,$(origin DDMP)),$(DDMP),1)
IM_ROWS     := $(call pipeline_rows,$(IM_SRC)/cases-$(IM_MODE).txt,$(IM_DDMP))
$(call pipeline_table,$(IM_OUT),$(IM_SRC)/cases-$(IM_MODE).txt,$(IM_ROWS))
IM_SELECTED := $(call pipeline_selected,$(IM_ROWS))
$(call pipeline_check_cases,impact,$(IM_ROWS))

.PHONY: impact impact-results
impact:
	$(MAKE) build
	$(MAKE) impact-results

impact-results: $(IM_OUT)/summary.md $(foreach r,$(IM_SELECTED),$(IM_OUT)/impact-$(call pipeline_field,$r,1).csv)
	@echo "impact: results in $(IM_OUT)/summary.md and $(IM_OUT)/impact-*.csv"

$(IM_OUT)/geometry-%.h5: | $(BIN)/latmpm-lattice
	@mkdir -p $(@D)
	$(BIN)/latmpm-lattice --preset $* --cells $(IM_CELLS) --plates $(IM_PLATES) --quiet -o $@

$(IM_OUT)/points-%.h5: $(IM_OUT)/geometry-%.h5 | $(BIN)/latmpm-voxelize
	$(BIN)/latmpm-voxelize $< --cell $(IM_CELL) --ppc 2 --quiet -o $@

$(IM_OUT)/impact-%.csv: $(IM_OUT)/run-%/done $(IM_OUT)/summary.md $(IM_SRC)/extract.sh
	bash $(IM_SRC)/extract.sh $(<D) $(IM_OUT)/curves/$*.load_time.csv $@

$(eval $(call pipeline_post,$(IM_OUT),$(call pipeline_label_runs,$(IM_OUT),$(IM_SELECTED)),--kind impact,Impact of a rigid flyer on the six lattices (paper A Sec. 6),$(IM_SRC)/notes.md))

$(IM_OUT)/summary.md: pipelines/impact.mk

.PRECIOUS: $(IM_OUT)/geometry-%.h5 $(IM_OUT)/points-%.h5
