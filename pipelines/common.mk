# Shared rules of the experiment pipelines (pipelines/*.mk); included by each of them and by
# the top-level Makefile's wildcard, so it is guarded against a second reading.
#
# An experiment's runs are rows of a case table (pipelines/<experiment>/cases-{quick,paper}.txt,
# read by pipelines/common/case-table.sh: case, points, scene, --set overrides). A case is a
# run directory RUN = OUT/run-<case> made by latmpm-solve. Its arguments are written to
# RUN.args, replaced only when their content changes: a second `make` redoes a run only when
# its row, its point file or its scene changed. RUN/done is the stamp, touched by
# pipelines/common/solve-case.sh when the solver's RUN/status.toml says the run ended (the
# status file is written by latmpm-solve at the end of every run, failed ones included).
# RUN.args ends in a comment line naming the solver's version (latmpm-solve --version, the
# version status.toml records): a run made by another build of the solver is redone, so a
# stale run never comes back without the new build's series columns. Within one build (a
# "-dirty" version) a rebuilt solver does not rerun finished cases (delete run-<case>/ to rerun
# one); the other tools and solve-case.sh are order-only prerequisites.
#
# CASES="name ..." (make <experiment> CASES=T2P30-E10) makes only the named cases and the
# summaries over them.
ifndef LATMPM_PIPELINES_COMMON
LATMPM_PIPELINES_COMMON := 1

PIPELINE_COMMON := pipelines/common
pipeline_comma := ,
pipeline_space := $(subst ,, )

# Capabilities are asked of the solver, once per make and only when a table is read: the
# shape functions it has (`latmpm-solve --list shapes`; an older solver without --list: ugimp).
LATMPM_SHAPES = $(eval LATMPM_SHAPES := $$(or $$(shell $(BIN)/latmpm-solve --list shapes 2>/dev/null),ugimp))$(LATMPM_SHAPES)
# The solver's version as one word, the last line of every RUN.args (asked once per make).
LATMPM_SOLVER_STAMP = $(eval LATMPM_SOLVER_STAMP := \#solver=$$(subst $$(pipeline_space),_,$$(shell $(BIN)/latmpm-solve --version 2>/dev/null)))$(LATMPM_SOLVER_STAMP)
# DDMP (paper A Eq. 4-7) rows run in every experiment, QUICK=1 included (docs/solver.md, "DDMP";
# DDMP=0 leaves them out).
DDMP ?= 1

# $(call pipeline_rows,TABLE,DDMP_FLAG): the rows of TABLE as words case|points|scene (scene
# "-": a run reused from another table), without the rows whose shape the solver lacks, nor
# DDMP's unless DDMP_FLAG is 1.
pipeline_rows = $(shell bash $(PIPELINE_COMMON)/case-table.sh list $(1) \
  $(subst $(pipeline_space),$(pipeline_comma),$(filter-out $(if $(filter 1,$(2)),,ddmp),$(LATMPM_SHAPES))))
pipeline_field = $(word $(2),$(subst |, ,$(1)))
# The rows that CASES names (all without CASES).
pipeline_selected = $(strip $(if $(CASES),$(foreach r,$(1),$(if $(filter $(call pipeline_field,$r,1),$(CASES)),$r)),$(1)))
# The run directory of a row of the table whose output directory is OUT.
pipeline_row_run = $(if $(filter run:%,$(call pipeline_field,$(2),2)),$(shell realpath -m --relative-to=. \
  $(1)/$(patsubst run:%,%,$(call pipeline_field,$(2),2))),$(1)/run-$(call pipeline_field,$(2),1))
# label=RUN_DIR of each row, for pipeline_post.
pipeline_label_runs = $(foreach r,$(2),$(call pipeline_field,$r,1)=$(call pipeline_row_run,$(1),$r))
# $(call pipeline_check_cases,EXPERIMENT,ROWS): when make is asked for EXPERIMENT (or
# EXPERIMENT-results), stops it if CASES names a case that none of ROWS has, listing those
# there are.
pipeline_case_names = $(foreach r,$(1),$(call pipeline_field,$r,1))
pipeline_check_cases = $(if $(and $(CASES),$(filter $(1) $(1)-results,$(MAKECMDGOALS)),$(filter-out $(call pipeline_case_names,$(2)),$(CASES))),\
  $(error CASES: $(1) has no case $(filter-out $(call pipeline_case_names,$(2)),$(CASES)); its cases are: $(call pipeline_case_names,$(2))))

# KEEP_RUNS=1: a finished run stands when only the solver's version changed (its RUN.args
# differ from the case table's in the "#solver=" line alone), even when its point file is
# newer, e.g. runs put back from records/ by `make restore-runs` (pipelines/common/
# restore-runs.sh). Without it (the default) every run of another build is redone.
KEEP_RUNS ?= 0

# Solver threads per run: 1 when make runs cases side by side (-jN), else all cores (0).
SOLVE_THREADS = $(if $(filter -j%,$(MAKEFLAGS)),1,0)

.PHONY: pipeline-args-force
pipeline-args-force:

# $(call pipeline_args,FILE,WORDS): FILE holds WORDS one per line, rewritten only on a change
# (update-args.sh).
define pipeline_args
$(1): pipeline-args-force
	@mkdir -p $$(@D) && printf '%s\n' $(2) > $$@.new && bash $(PIPELINE_COMMON)/update-args.sh $$@ 0
endef

# The run of one row of TABLE into OUT (ALLOW_FAILURE = 1: a numerical failure is an outcome).
define pipeline_case_rules
$(1)/run-$(call pipeline_field,$(3),1).args: pipeline-args-force
	@mkdir -p $$(@D) && { bash $(PIPELINE_COMMON)/case-table.sh args $(2) $(call pipeline_field,$(3),1) $(1) && \
	  echo '$$(LATMPM_SOLVER_STAMP)'; } > $$@.new && \
	  bash $(PIPELINE_COMMON)/update-args.sh $$@ $(KEEP_RUNS)
$(1)/run-$(call pipeline_field,$(3),1)/done: $(1)/run-$(call pipeline_field,$(3),1).args \
    $(if $(filter 1,$(KEEP_RUNS)),,$(1)/$(call pipeline_field,$(3),2)) $(call pipeline_field,$(3),3) \
    | $(if $(filter 1,$(KEEP_RUNS)),$(1)/$(call pipeline_field,$(3),2)) $(BIN)/latmpm-solve $(PIPELINE_COMMON)/solve-case.sh
	bash $(PIPELINE_COMMON)/solve-case.sh $(BIN) $(1)/run-$(call pipeline_field,$(3),1) $$(SOLVE_THREADS) $(4)
endef
# $(call pipeline_table,OUT,TABLE,ROWS[,ALLOW_FAILURE]): the rules of every run of ROWS (from
# pipeline_rows of TABLE), selected or not (a summary may reuse an unselected run).
pipeline_table = $(foreach r,$(3),$(if $(filter -,$(call pipeline_field,$r,3)),,$(eval $(call pipeline_case_rules,$(1),$(2),$r,$(4)))))

# $(call pipeline_run,RUN_DIR,POINTS,SCENE,SET_WORDS[,ALLOW_FAILURE]): one run outside a case
# table (RUN_DIR of SCENE with the point file POINTS and further words such as
# --set grid.cell=0.4mm).
# (pipelines/stl-part.mk adds its further point files to the stamp's old name, wall_time.txt:
# they are made first, order-only, until it names RUN_DIR/done.)
define pipeline_run
$(call pipeline_args,$(1).args,$(3) --set points.0.file=$(2) $(4) '$$(LATMPM_SOLVER_STAMP)')
$(1)/done: $(1).args $(2) $(3) | $(BIN)/latmpm-solve $(PIPELINE_COMMON)/solve-case.sh $(1)/wall_time.txt
	bash $(PIPELINE_COMMON)/solve-case.sh $(BIN) $(1) $$(SOLVE_THREADS) $(5)
$(1)/wall_time.txt: ;
endef

# Paper-resolution runs are recorded in records/ as they finish (pipelines/common/
# record-run.sh, called by solve-case.sh); this puts every record back under results/.
.PHONY: restore-runs
restore-runs:
	bash $(PIPELINE_COMMON)/restore-runs.sh

# $(call pipeline_post,OUT_DIR,RUNS,POST_ARGS,TITLE,NOTES): latmpm-post over the runs into
# OUT_DIR (summary.md, metrics.csv, plots/, curves/), then the set-up NOTES (a Markdown file)
# and the runs' cost (from their status.toml) appended to summary.md by
# pipelines/common/append-runs.sh. A run is a run directory (labelled by its name without
# "run-") or LABEL=RUN_DIR. TITLE must not hold commas. OUT_DIR/post.args lists the runs: a
# summary over another selection (CASES=) is remade.
pipeline_run_dir   = $(lastword $(subst =, ,$(1)))
pipeline_run_label = $(if $(findstring =,$(1)),$(firstword $(subst =, ,$(1))),$(patsubst run-%,%,$(notdir $(1))))
define pipeline_post
$(call pipeline_args,$(1)/post.args,$(2))
$(1)/summary.md: $(1)/post.args $(foreach r,$(2),$(call pipeline_run_dir,$r)/done) $(5) $(PIPELINE_COMMON)/append-runs.sh | $(BIN)/latmpm-post
	$(BIN)/latmpm-post $(foreach r,$(2),$(call pipeline_run_dir,$r)) -o $(1) --title "$(4)" $(3) \
	  $(foreach r,$(2),--label $(call pipeline_run_label,$r)=$(call pipeline_run_dir,$r)) && \
	bash $(PIPELINE_COMMON)/append-runs.sh $(1) $(5) \
	  $(foreach r,$(2),$(call pipeline_run_label,$r)=$(call pipeline_run_dir,$r)) || { rm -f $(1)/summary.md; exit 1; }
endef

endif
