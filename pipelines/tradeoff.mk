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
# Run with `make -j2 tradeoff` (about 15 min of CPU on the Zen 4 of docs/benchmarks.md, 2026-11-29;
#   25 on the machine of 2026-11-21; see docs/tradeoff.md).
include pipelines/common.mk

TO_SRC := pipelines/tradeoff
TO_OUT := results/tradeoff

# The runs: the rows of pipelines/tradeoff/column.txt and lattice.txt (the DDMP rows whenever
# the solver has the shape); a numerical failure is an outcome here, not an error.
TO_COLUMN_ROWS  := $(call pipeline_rows,$(TO_SRC)/column.txt,1)
TO_LATTICE_ROWS := $(call pipeline_rows,$(TO_SRC)/lattice.txt,1)
$(call pipeline_table,$(TO_OUT)/column,$(TO_SRC)/column.txt,$(TO_COLUMN_ROWS),1)
$(call pipeline_table,$(TO_OUT)/lattice,$(TO_SRC)/lattice.txt,$(TO_LATTICE_ROWS),1)

.PHONY: tradeoff tradeoff-results
tradeoff:
	$(MAKE) build
	$(MAKE) tradeoff-results

tradeoff-results: $(TO_OUT)/summary.md
	@echo "tradeoff: results in $<"

# Points (points-h<cell>-p<points per cell per direction>.h5): the column with end plates of
# two cells and u0 = 0.32 mm sin(pi z / L); the lattice.
$(TO_OUT)/column/points-h%.h5: | $(BIN)/latmpm-lattice $(BIN)/latmpm-voxelize $(BIN)/latmpm-imperfect
	@mkdir -p $(@D)
	h=$$(echo $* | sed 's/-p.*//'); p=$$(echo $* | sed 's/.*-p//'); \
	$(BIN)/latmpm-lattice --column --diameter 1.6mm --length 16mm \
	  --end-plates $$(awk -v h=$$h 'BEGIN { print 2 * h }')mm --quiet -o - \
	| $(BIN)/latmpm-voxelize - --cell $${h}mm --ppc $$p --quiet -o - \
	| $(BIN)/latmpm-imperfect - --type sine --amount 0.32mm --length 16mm --quiet -o $@
$(TO_OUT)/lattice/points-h%.h5: | $(BIN)/latmpm-lattice $(BIN)/latmpm-voxelize
	@mkdir -p $(@D)
	h=$$(echo $* | sed 's/-p.*//'); p=$$(echo $* | sed 's/.*-p//'); \
	$(BIN)/latmpm-lattice --preset T2P30 --cells 2x2x1 --plates 1.28mm --quiet -o - \
	| $(BIN)/latmpm-voxelize - --cell $${h}mm --ppc $$p --quiet -o $@

$(eval $(call pipeline_post,$(TO_OUT)/column,$(call pipeline_label_runs,$(TO_OUT)/column,$(TO_COLUMN_ROWS)),--kind column --reference ref --reference base,Trade-off: column t = 1.6 mm,$(TO_SRC)/column-notes.md))
$(eval $(call pipeline_post,$(TO_OUT)/lattice,$(call pipeline_label_runs,$(TO_OUT)/lattice,$(TO_LATTICE_ROWS)),--kind compression --fit-range 0.3mm:1mm --reference ref --reference base,Trade-off: T2P30 2x2x1,$(TO_SRC)/lattice-notes.md))

# The table and the Pareto plot: each run's cost (status.toml) and its errors against the
# reference run, the base case and the Euler load (latmpm-post --reference: comparison.csv).
$(eval $(call pipeline_args,$(TO_OUT)/knobs.txt,$(foreach r,$(TO_COLUMN_ROWS),column:$(call pipeline_field,$r,1)) \
  $(foreach r,$(TO_LATTICE_ROWS),lattice:$(call pipeline_field,$r,1))))
$(TO_OUT)/summary.md: $(TO_OUT)/knobs.txt $(TO_OUT)/column/summary.md $(TO_OUT)/lattice/summary.md \
                      $(TO_SRC)/report.sh $(TO_SRC)/column.txt $(TO_SRC)/lattice.txt
	bash $(TO_SRC)/report.sh $(TO_OUT)

.PRECIOUS: $(TO_OUT)/column/points-h%.h5 $(TO_OUT)/lattice/points-h%.h5
