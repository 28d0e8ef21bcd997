# make tradeoff: what each knob costs and what it changes (issue 7 item 4; docs/tradeoff.md).
#   The column (t = 1.6 mm, L = 16 mm, a = 0.02 L, 3 mm travel) and one lattice (T2P30,
#   2x2x1 cells, 1.28 mm plates, 2 mm travel), each varied one knob at a time around a base
#   case (column: cell 0.4 mm; lattice: cell 0.64 mm; both 2 points per cell per direction,
#   uGIMP, mass scaling 6, 100 mm/s): cell size, points per cell, shape function, mass
#   scaling, loading rate. Every run's cost (CPU and wall time, with -jN one thread per run)
#   and its error against the finest run (column: cell 0.2 mm; lattice: cell 0.4 mm), and for
#   the column against the Euler load. Results in results/tradeoff/: summary.md (table,
#   Pareto plot pareto.png/svg, recommendations live in docs/tradeoff.md), errors.csv, and
#   latmpm-post's plots of each family in column/ and lattice/.
# Run with `make -j2 tradeoff` (about 25 min of CPU; see docs/tradeoff.md).
include pipelines/common.mk

TO_SRC := pipelines/tradeoff
TO_OUT := results/tradeoff

# name:cell(mm):ppc:shape:mass scaling:speed(mm/s):scheme. The first entry of each family is
# the reference (the finest run), the second the base case. Linear and DDMP run with MUSL
# (their default in docs/scene.md); linear-usl shows why.
TO_KNOBS = ref:$(1):2:ugimp:6:100:usl base:$(2):2:ugimp:6:100:usl \
  $(foreach h,$(3),h$h:$h:2:ugimp:6:100:usl) \
  ppc1:$(2):1:ugimp:6:100:usl ppc3:$(2):3:ugimp:6:100:usl \
  linear-usl:$(2):2:linear:6:100:usl linear:$(2):2:linear:6:100:musl \
  $(foreach s,cpgimp bspline2 bspline3,$s:$(2):2:$s:6:100:usl) \
  $(if $(LATMPM_HAVE_DDMP),ddmp:$(2):2:ddmp:6:100:musl) \
  ms1:$(2):2:ugimp:1:100:usl ms36:$(2):2:ugimp:36:100:usl \
  v50:$(2):2:ugimp:6:50:usl v200:$(2):2:ugimp:6:200:usl v400:$(2):2:ugimp:6:400:usl
TO_COLUMN  := $(call TO_KNOBS,0.2,0.4,0.64 0.3)
TO_LATTICE := $(call TO_KNOBS,0.4,0.64,1 0.8 0.5)

to_field = $(word $(2),$(subst :, ,$(1)))
to_points = $(TO_OUT)/$(1)points-h$(call to_field,$(2),2)-p$(call to_field,$(2),3).h5
to_sets = --set grid.cell=$(call to_field,$(1),2)mm --set grid.shape=$(call to_field,$(1),4) \
  $(if $(filter musl,$(call to_field,$(1),7)),--set grid.scheme=musl) \
  --set time.mass_scaling=$(call to_field,$(1),5) \
  --set 'bodies.top_plate.velocity=["0mm/s","0mm/s","-$(call to_field,$(1),6)mm/s"]'

$(foreach k,$(TO_COLUMN),$(eval $(call pipeline_run,$(TO_OUT)/column/run-$(call to_field,$k,1),$(call to_points,c,$k),\
  pipelines/column-buckling/column.toml,$(call to_sets,$k) --set output.series_every=25,1)))
$(foreach k,$(TO_LATTICE),$(eval $(call pipeline_run,$(TO_OUT)/lattice/run-$(call to_field,$k,1),$(call to_points,l,$k),\
  pipelines/lattice-compression/lattice.toml,$(call to_sets,$k) --set run.end.plate_displacement=2mm \
  --set output.series_every=20 --set bodies.lattice.material.E=10MPa,1)))
TO_COLUMN_RUNS  := $(foreach k,$(TO_COLUMN),$(TO_OUT)/column/run-$(call to_field,$k,1))
TO_LATTICE_RUNS := $(foreach k,$(TO_LATTICE),$(TO_OUT)/lattice/run-$(call to_field,$k,1))

.PHONY: tradeoff tradeoff-results
tradeoff:
	$(MAKE) build
	$(MAKE) tradeoff-results

tradeoff-results: $(TO_OUT)/summary.md
	@echo "tradeoff: results in $<"

# Points: the column with end plates of two cells and u0 = 0.32 mm sin(pi z / L); the lattice.
$(TO_OUT)/cpoints-h%.h5: | $(BIN)/latmpm-lattice $(BIN)/latmpm-voxelize $(BIN)/latmpm-imperfect
	@mkdir -p $(@D)
	h=$$(echo $* | sed 's/-p.*//'); p=$$(echo $* | sed 's/.*-p//'); \
	$(BIN)/latmpm-lattice --column --diameter 1.6mm --length 16mm \
	  --end-plates $$(awk -v h=$$h 'BEGIN { print 2 * h }')mm --quiet -o - \
	| $(BIN)/latmpm-voxelize - --cell $${h}mm --ppc $$p --quiet -o - \
	| $(BIN)/latmpm-imperfect - --type sine --amount 0.32mm --length 16mm --quiet -o $@
$(TO_OUT)/lpoints-h%.h5: | $(BIN)/latmpm-lattice $(BIN)/latmpm-voxelize
	@mkdir -p $(@D)
	h=$$(echo $* | sed 's/-p.*//'); p=$$(echo $* | sed 's/.*-p//'); \
	$(BIN)/latmpm-lattice --preset T2P30 --cells 2x2x1 --plates 1.28mm --quiet -o - \
	| $(BIN)/latmpm-voxelize - --cell $${h}mm --ppc $$p --quiet -o $@

$(eval $(call pipeline_post,$(TO_OUT)/column,$(TO_COLUMN_RUNS),--kind column,Trade-off: column t = 1.6 mm,$(TO_SRC)/column-notes.md))
$(eval $(call pipeline_post,$(TO_OUT)/lattice,$(TO_LATTICE_RUNS),--kind compression --fit-range 0.3mm:1mm,Trade-off: T2P30 2x2x1,$(TO_SRC)/lattice-notes.md))

# Errors against the reference runs and the Euler load (0.4961 N, K = 0.5), the table and
# the Pareto plot.
$(eval $(call pipeline_args,$(TO_OUT)/knobs.txt,$(addprefix column:,$(TO_COLUMN)) $(addprefix lattice:,$(TO_LATTICE))))
$(TO_OUT)/summary.md: $(TO_OUT)/knobs.txt $(TO_OUT)/column/summary.md $(TO_OUT)/lattice/summary.md \
                      $(TO_SRC)/errors.sh $(TO_SRC)/report.sh
	bash $(TO_SRC)/report.sh $(TO_OUT)

.PRECIOUS: $(TO_OUT)/cpoints-h%.h5 $(TO_OUT)/lpoints-h%.h5
