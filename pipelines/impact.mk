# make impact [QUICK=1]: paper A Sec. 6, a rigid flyer strikes a tetrahedral lattice.
#   T2P30, E = 10 MPa, nu = 0.4, real density rho0 = 1050 kg/m^3, shape in {uGIMP, DDMP}
#   (DDMP with its default MUSL; DDMP=0 leaves it out),
#   flyer 10 kg at 2 m/s, gravity 9.81 m/s^2 on flyer and lattice, bottom plate held,
#   5x5x5 cells, 3 mm plates, cell 0.64 mm, 2 points per cell per direction, 25 ms.
#   QUICK=1: 2x2x2 cells, 2 mm plates, cell 1 mm, 20 ms, and the flyer's mass scaled with the
#   lattice's volume, 10 kg x (2x2x2)/(5x5x5) = 0.64 kg, so that the energy per cell is the
#   paper's (a 10 kg flyer would crush the small lattice flat in a few ms).
# Results in results/impact/{paper,quick}/: impact-<case>.csv (time[ms], load_flyer[N],
# load_fixed[N], flyer_speed[m/s], flyer_energy[J], energy_error[J]), summary.md (latmpm-post's
# impact metrics and plots, notes, and the wall time of each run), run-<case>/ (the solver's
# run directories, with checkpoints: an interrupted run continues with
# `latmpm-solve --resume results/impact/.../run-<case>`).
# Chain: latmpm-lattice --preset T2P30 -> latmpm-voxelize -> latmpm-solve
# pipelines/impact/impact.toml (flyer placed by pipelines/impact/run-case.sh) -> latmpm-post.
include pipelines/common.mk

IM_SRC    := pipelines/impact
IM_OUT    := results/impact/$(if $(QUICK),quick,paper)
IM_CELL   := $(if $(QUICK),1mm,0.64mm)
IM_CELLS  := $(if $(QUICK),2x2x2,5x5x5)
IM_PLATES := $(if $(QUICK),2mm,3mm)
IM_END    := $(if $(QUICK),20ms,25ms)
IM_MASS   := $(if $(QUICK),0.64kg,10kg)
IM_SERIES := $(if $(QUICK),20,50)

im_case = T2P30-E10$(if $(filter ddmp,$(1)),-ddmp)
# Both shapes at either resolution (the issue asks for uGIMP and DDMP), unless DDMP=0 is
# given on the command line (pipelines/common.mk leaves DDMP out of QUICK by default).
IM_SHAPES := ugimp $(if $(LATMPM_HAVE_DDMP),$(if $(filter command line,$(origin DDMP)),$(if $(filter 1,$(DDMP)),ddmp),ddmp))
IM_CASES := $(foreach s,$(IM_SHAPES),$(call im_case,$s))
IM_RUNS  := $(foreach c,$(IM_CASES),$(IM_OUT)/run-$c)

.PHONY: impact impact-results
impact:
	$(MAKE) build
	$(MAKE) impact-results

impact-results: $(IM_OUT)/summary.md $(foreach c,$(IM_CASES),$(IM_OUT)/impact-$c.csv)
	@echo "impact: results in $(IM_OUT)/summary.md and $(IM_OUT)/impact-*.csv"

$(IM_OUT)/geometry.h5: | $(BIN)/latmpm-lattice
	@mkdir -p $(@D)
	$(BIN)/latmpm-lattice --preset T2P30 --cells $(IM_CELLS) --plates $(IM_PLATES) --quiet -o $@

$(IM_OUT)/points.h5: $(IM_OUT)/geometry.h5 | $(BIN)/latmpm-voxelize
	$(BIN)/latmpm-voxelize $< --cell $(IM_CELL) --ppc 2 --quiet -o $@

# One run per shape function; run-case.sh puts the flyer on the top plate of geometry.h5.
# The scene and overrides of a run go to run-<case>.set, rewritten only when they change
# (pipelines/common.mk): editing a case's settings here reruns exactly that case. As in
# pipelines/common.mk, the tools and scripts are order-only: editing them does not throw away
# finished runs (each takes tens of minutes at paper resolution).
im_words = $(IM_SRC)/impact.toml --set points.0.file=$(IM_OUT)/points.h5 --set grid.cell=$(IM_CELL) \
  --set grid.shape=$(1) --set run.end.time=$(IM_END) --set rigid_bodies.flyer.mass=$(IM_MASS) \
  --set output.series_every=$(IM_SERIES)
define im_run
$(call pipeline_args,$(IM_OUT)/run-$(call im_case,$(1)).set,$(call im_words,$(1)))
$(IM_OUT)/run-$(call im_case,$(1))/wall_time.txt: $(IM_OUT)/run-$(call im_case,$(1)).set $(IM_OUT)/points.h5 \
    $(IM_OUT)/geometry.h5 $(IM_SRC)/impact.toml | $(BIN)/latmpm-solve $(IM_SRC)/run-case.sh $(PIPELINE_COMMON)/solve-case.sh
	bash $(IM_SRC)/run-case.sh $(BIN) $(IM_OUT)/run-$(call im_case,$(1)) $$(SOLVE_THREADS) $(IM_OUT)/geometry.h5 -- \
	  $$$$(cat $(IM_OUT)/run-$(call im_case,$(1)).set)
endef
$(foreach s,$(IM_SHAPES),$(eval $(call im_run,$s)))

$(IM_OUT)/impact-%.csv: $(IM_OUT)/run-%/wall_time.txt $(IM_SRC)/extract.sh
	bash $(IM_SRC)/extract.sh $(<D) $@

$(eval $(call pipeline_post,$(IM_OUT),$(IM_RUNS),--kind impact,Impact of a rigid flyer on T2P30 (paper A Sec. 6),$(IM_SRC)/notes.md))

$(IM_OUT)/summary.md: pipelines/impact.mk

.PRECIOUS: $(IM_OUT)/geometry.h5 $(IM_OUT)/points.h5
