# make extremes: stability at the extremes (issue 7 item 5). Each case states its expected
# outcome, and pipelines/extremes/check.sh checks it: the target fails when an outcome
# differs. Results in results/extremes/: summary.md (expected and observed per case), the
# run directories, latmpm-post's plots in post-<case>/. About 5 min on 2 cores.
#   slender        column t = 0.8 mm, L = 16 mm (L/t = 20), a = 0.02 L, cell 0.2 mm: finishes,
#                  post-buckling load within 15 % of the Euler load (K = 0.5); the load ripple
#                  and the start-up peak reported against it
#   stiff-fast     T2P30 2x2x1, E = 100 MPa, real density, plate at 4 m/s (twice the paper's
#                  impact speed) for 4 mm: finishes, energy balance within 10 %
#   densify        T2P30 2x2x1 to 90 % strain, neo-Hookean: finishes, densification onset
#                  found below 90 %, final load > 10x plateau load, energy balance within 5 %
#   densify-linear the same with linear elasticity: finishes, but the energy balance is off by
#                  more than 20 %: reported, with the strain where it first passes 5 %
#   one-point      T1P30 2x2x1 with one point across a strut (cell 1.6 mm, 1 point per cell):
#                  the voxelizer warns; the run finishes; initial stiffness below half the
#                  resolved run's (cell 0.8 mm, 2 points per cell) - reported as unresolved.
#                  Below one point across (cell 2 mm) the voxelizer refuses: exit 2, one line.
#   mass-scaling   T2P30 2x2x1, mass scaling 6, 100, 1000, 10000: the kinetic / strain energy
#                  ratio over the second half of the travel is below 0.05 at 6 (quasi-static)
#                  and above 0.1 at 10000 (reported as not quasi-static), with the first
#                  mass scaling that crosses 0.1.
include pipelines/common.mk

EX_SRC := pipelines/extremes
EX_OUT := results/extremes
EX_CASES := slender stiff-fast densify densify-linear one-point mass-scaling
EX_MS := 6 100 1000 10000


.PHONY: extremes extremes-results
extremes:
	$(MAKE) build
	$(MAKE) extremes-results

extremes-results: $(EX_OUT)/summary.md
	@echo "extremes: results in $<"

# Points.
$(EX_OUT)/slender-points.h5: | $(BIN)/latmpm-lattice $(BIN)/latmpm-voxelize $(BIN)/latmpm-imperfect
	@mkdir -p $(@D)
	$(BIN)/latmpm-lattice --column --diameter 0.8mm --length 16mm --end-plates 0.4mm --quiet -o - \
	| $(BIN)/latmpm-voxelize - --cell 0.2mm --ppc 2 --quiet -o - \
	| $(BIN)/latmpm-imperfect - --type sine --amount 0.32mm --length 16mm --quiet -o $@
$(EX_OUT)/t2p30.h5: | $(BIN)/latmpm-lattice
	@mkdir -p $(@D)
	$(BIN)/latmpm-lattice --preset T2P30 --cells 2x2x1 --plates 1.28mm --quiet -o $@
$(EX_OUT)/t2p30-h%.h5: $(EX_OUT)/t2p30.h5 | $(BIN)/latmpm-voxelize
	$(BIN)/latmpm-voxelize $< --cell $*mm --ppc 2 --quiet -o $@
$(EX_OUT)/t1p30.h5: | $(BIN)/latmpm-lattice
	@mkdir -p $(@D)
	$(BIN)/latmpm-lattice --preset T1P30 --cells 2x2x1 --plates 1.6mm --quiet -o $@
$(EX_OUT)/t1p30-resolved.h5: $(EX_OUT)/t1p30.h5 | $(BIN)/latmpm-voxelize
	$(BIN)/latmpm-voxelize $< --cell 0.8mm --ppc 2 --quiet -o $@
# One point across: the voxelizer's warning is kept for the check.
$(EX_OUT)/t1p30-one-point.h5: $(EX_OUT)/t1p30.h5 | $(BIN)/latmpm-voxelize
	$(BIN)/latmpm-voxelize $< --cell 1.6mm --ppc 1 -o $@ 2> $(EX_OUT)/one-point-voxelize.txt
# Below one point across: the refusal (exit status and message) is the outcome to check.
$(EX_OUT)/below-one-point.txt: $(EX_OUT)/t1p30.h5 | $(BIN)/latmpm-voxelize
	$(BIN)/latmpm-voxelize $< --cell 2mm --ppc 1 --quiet -o $(EX_OUT)/below-one-point.h5 2> $@.tmp; \
	  echo "exit=$$?" >> $@.tmp; mv $@.tmp $@

# Runs: the rows of pipelines/extremes/cases.txt.
EX_ROWS := $(call pipeline_rows,$(EX_SRC)/cases.txt,1)
$(call pipeline_table,$(EX_OUT),$(EX_SRC)/cases.txt,$(EX_ROWS))

# Post-processing per case (plots, metrics) and the checks.
$(EX_OUT)/post-slender/metrics.csv: $(EX_OUT)/run-slender/done | $(BIN)/latmpm-post
	$(BIN)/latmpm-post $(EX_OUT)/run-slender -o $(@D) --kind column --label slender=$(EX_OUT)/run-slender > /dev/null
$(EX_OUT)/post-%/metrics.csv: $(EX_OUT)/run-%/done | $(BIN)/latmpm-post
	$(BIN)/latmpm-post $(<D) -o $(@D) --kind compression --fit-range 0.2mm:0.8mm --label $*=$(<D) > /dev/null
$(EX_OUT)/post-one-point/metrics.csv: $(EX_OUT)/run-one-point/done $(EX_OUT)/run-one-point-resolved/done | $(BIN)/latmpm-post
	$(BIN)/latmpm-post $(EX_OUT)/run-one-point $(EX_OUT)/run-one-point-resolved -o $(@D) --kind compression \
	  --fit-range 0.2mm:0.8mm --label one-point=$(EX_OUT)/run-one-point \
	  --label resolved=$(EX_OUT)/run-one-point-resolved > /dev/null
$(EX_OUT)/post-mass-scaling/metrics.csv: $(foreach m,$(EX_MS),$(EX_OUT)/run-ms$m/done) | $(BIN)/latmpm-post
	$(BIN)/latmpm-post $(foreach m,$(EX_MS),$(EX_OUT)/run-ms$m) -o $(@D) --kind compression \
	  --fit-range 0.2mm:0.8mm $(foreach m,$(EX_MS),--label ms$m=$(EX_OUT)/run-ms$m) > /dev/null

$(EX_OUT)/verdict-%.md: $(EX_OUT)/post-%/metrics.csv $(EX_SRC)/check.sh
	bash $(EX_SRC)/check.sh $* $(EX_OUT) > $@.tmp && mv $@.tmp $@ || { cat $@.tmp; rm -f $@.tmp; exit 1; }
$(EX_OUT)/verdict-one-point.md: $(EX_OUT)/below-one-point.txt

$(EX_OUT)/summary.md: $(foreach c,$(EX_CASES),$(EX_OUT)/verdict-$c.md)
	{ echo "# Stability at the extremes (make extremes)"; echo; \
	  echo "Each case: what is expected, what was observed, PASS when they agree (pipelines/extremes.mk, check.sh)."; \
	  echo; cat $^; } > $@.tmp && mv $@.tmp $@

.PRECIOUS: $(EX_OUT)/t2p30-h%.h5 $(EX_OUT)/post-%/metrics.csv
