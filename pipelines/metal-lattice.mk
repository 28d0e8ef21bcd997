# make metal-lattice [QUICK=1]: a metal lattice crushed by rigid platens (issue 17, "Beyond
#   the paper"; docs/paper-b.md, "make metal-lattice"). Paper A's T2P30 tetrahedral lattice
#   (L = 8 mm, t = 2.4 mm, phi = 30 deg) without printed plates, in Ti-6Al-4V as finite-strain
#   J2 plasticity (paper B Eq. 9-13), between a fixed base and a platen that follows a
#   load-unload schedule (down at 16 m/s, back up past its start: motion = "scheduled"), both
#   rigid half-spaces in penalty contact with Coulomb friction mu = 0.3 (QUICK also mu = 0),
#   and the same lattice elastic (neo-Hookean) without friction, which must recover (QUICK
#   also with mu = 0.3); uGIMP on a 1 mm grid, 2 points per cell per direction.
#   QUICK=1: 2x2x2 cells, 5 mm of travel (24 %) and back. Paper size: 5x5x5 cells, 12 mm (24 %)
#   and back (cost measured in docs/paper-b.md).
# Results in results/metal-lattice/{paper,quick}/: residual.md (residual.py: the residual
# deformation, the lattice's own height change at the end (its top layer against its bottom
# layer, from the first and last snapshots), against the elastic run, which must come back
# within 2 % of the travel; the platen's travel where its force returns to zero on unloading;
# energies; cost), summary.md (latmpm-post: load against travel, the unloading
# branch included; the runs' cost), energy.png (work in, plastic work, elastic energy against
# time), run-<case>/ (the solver's runs).
# Chain: latmpm-lattice --preset T2P30 --no-plates -> latmpm-voxelize -> latmpm-solve
# pipelines/metal-lattice/ti-lattice.toml (one run a row) -> latmpm-post.
include pipelines/common.mk

ML_SRC   := pipelines/metal-lattice
ML_MODE  := $(if $(QUICK),quick,paper)
ML_OUT   := results/metal-lattice/$(ML_MODE)
ML_CELLS := $(if $(QUICK),2x2x2,5x5x5)
# The lattice's height NZ (L sin(phi) + 2 L / 3) + t (mm): where the platen starts.
ML_HEIGHT := $(if $(QUICK),21.0667,49.0667)

ML_ROWS := $(call pipeline_rows,$(ML_SRC)/cases-$(ML_MODE).txt,0)
$(call pipeline_table,$(ML_OUT),$(ML_SRC)/cases-$(ML_MODE).txt,$(ML_ROWS))
ML_SELECTED := $(call pipeline_selected,$(ML_ROWS))
$(call pipeline_check_cases,metal-lattice,$(ML_ROWS))
ML_FIRST := $(call pipeline_field,$(firstword $(ML_SELECTED)),1)

.PHONY: metal-lattice metal-lattice-results
metal-lattice:
	$(MAKE) build
	$(MAKE) metal-lattice-results

metal-lattice-results: $(ML_OUT)/summary.md $(ML_OUT)/energy.png $(ML_OUT)/residual.md
	@echo "metal-lattice: results in $(ML_OUT)/summary.md"

$(ML_OUT)/geometry-T2P30.h5: | $(BIN)/latmpm-lattice
	@mkdir -p $(@D)
	$(BIN)/latmpm-lattice --preset T2P30 --cells $(ML_CELLS) --no-plates --quiet -o $@

$(ML_OUT)/points-T2P30.h5: $(ML_OUT)/geometry-T2P30.h5 | $(BIN)/latmpm-voxelize
	$(BIN)/latmpm-voxelize $< --cell 1mm --ppc 2 --quiet -o $@

$(eval $(call pipeline_post,$(ML_OUT),$(call pipeline_label_runs,$(ML_OUT),$(ML_SELECTED)),--kind compression --load load_fixed,Ti-6Al-4V T2P30 lattice under rigid platens,$(ML_SRC)/notes.md))

# The first case's energies against the platen's travel.
$(ML_OUT)/energy.png: $(ML_OUT)/run-$(ML_FIRST)/done $(ML_SRC)/plot_energy.gp
	gnuplot -e "csv='$(ML_OUT)/run-$(ML_FIRST)/series.csv'; png='$@'; label='$(ML_FIRST)'" $(ML_SRC)/plot_energy.gp

# The residual deformation of every run, against the elastic run's recovery.
ML_LABEL_RUNS := $(call pipeline_label_runs,$(ML_OUT),$(ML_SELECTED))
$(ML_OUT)/residual.md: $(foreach r,$(ML_LABEL_RUNS),$(lastword $(subst =, ,$r))/done) $(ML_SRC)/residual.py $(ML_SRC)/lattice_height.py
	python3 $(ML_SRC)/residual.py --height $(ML_HEIGHT) --out $(ML_OUT) \
	  $(if $(filter T2P30-elastic-mu0=%,$(ML_LABEL_RUNS)),--must-recover T2P30-elastic-mu0 --) $(ML_LABEL_RUNS)

$(ML_OUT)/summary.md $(ML_OUT)/residual.md: pipelines/metal-lattice.mk

.PRECIOUS: $(ML_OUT)/geometry-T2P30.h5 $(ML_OUT)/points-T2P30.h5
