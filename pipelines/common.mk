# Shared rules of the experiment pipelines (pipelines/*.mk); included by each of them and by
# the top-level Makefile's wildcard, so it is guarded against a second reading.
#
# A case is a run directory RUN (results/<experiment>/<mode>/run-<case>) made by latmpm-solve
# from a scene and --set overrides. The scene path and the overrides are written to RUN.args,
# which is replaced only when its content changes: a second `make` redoes a run only when its
# point file, its scene or its overrides changed. RUN/wall_time.txt is the stamp, written by
# pipelines/common/solve-case.sh only when the solver finished (with the wall and CPU time).
# The tools and solve-case.sh are order-only prerequisites: a rebuilt solver does not rerun
# finished cases (delete run-<case>/ to rerun one).
ifndef LATMPM_PIPELINES_COMMON
LATMPM_PIPELINES_COMMON := 1

PIPELINE_COMMON := pipelines/common
# DDMP (paper A Eq. 4-7) is in the solver once docs/scene.md lists the shape `ddmp`. Its runs
# were measured 15-30x slower than uGIMP (docs/experiments.md), so QUICK=1 leaves them out
# unless DDMP=1; the paper-resolution default includes them (DDMP=0 leaves them out).
LATMPM_HAVE_DDMP := $(shell grep -q '`ddmp`' docs/scene.md 2>/dev/null && echo 1)
DDMP ?= $(if $(QUICK),0,1)
PIPELINE_SHAPES  := ugimp $(if $(LATMPM_HAVE_DDMP),$(if $(filter 1,$(DDMP)),ddmp))

# Per-shape overrides: DDMP with MUSL (docs/scene.md: MUSL is DDMP's default, the scenes here
# name USL for paper A's GIMP runs).
pipeline_shape_sets = --set grid.shape=$(1)$(if $(filter ddmp linear,$(1)), --set grid.scheme=musl)

# The height of the top face of a tetrahedral lattice with plates (docs/geometry.md):
# 2 T + NZ (L sin(phi) + 2 L / 3), L = 8 mm. $(call pipeline_lattice_top,PRESET,NZ,T_MM) in mm.
pipeline_lattice_top = $(shell awk 'BEGIN { pi = atan2(0, -1); printf "%.6g", 2 * $(3) + $(2) * (8 * sin($(lastword $(subst P, ,$(1))) * pi / 180) + 16 / 3) }')
# The --set word that puts the rigid plate's face at Z (mm).
pipeline_platen_at = 'rigid_bodies.platen.point=["0mm","0mm","$(1)mm"]'

# Solver threads per run: 1 when make runs cases side by side (-jN), else all cores (0).
SOLVE_THREADS = $(if $(filter -j%,$(MAKEFLAGS)),1,0)

.PHONY: pipeline-args-force
pipeline-args-force:

# $(call pipeline_args,FILE,WORDS): FILE holds WORDS one per line, rewritten only on a change.
define pipeline_args
$(1): pipeline-args-force
	@mkdir -p $$(@D) && printf '%s\n' $(2) > $$@.new && \
	  if cmp -s $$@.new $$@; then rm -f $$@.new; else mv $$@.new $$@; fi
endef

# $(call pipeline_run,RUN_DIR,POINTS,SCENE,SET_WORDS[,ALLOW_FAILURE]): the run RUN_DIR of
# SCENE with the point file POINTS (points.0.file) and further overrides (words such as
# --set grid.cell=0.4mm). ALLOW_FAILURE = 1: a numerical failure is recorded, not an error.
define pipeline_run
$(call pipeline_args,$(1).args,$(3) --set points.0.file=$(2) $(4))
$(1)/wall_time.txt: $(1).args $(2) $(3) | $(BIN)/latmpm-solve $(PIPELINE_COMMON)/solve-case.sh
	bash $(PIPELINE_COMMON)/solve-case.sh $(BIN) $(1) $$(SOLVE_THREADS) $(5)
endef

# $(call pipeline_post,OUT_DIR,RUNS,POST_ARGS,TITLE,NOTES): latmpm-post over the runs into
# OUT_DIR (summary.md, metrics.csv, plots/, curves/), then the runs' cost and the set-up NOTES
# (a Markdown file) appended to summary.md by pipelines/common/append-runs.sh. A run is a run
# directory (labelled by its name without "run-") or LABEL=RUN_DIR. TITLE must not hold commas.
pipeline_run_dir   = $(lastword $(subst =, ,$(1)))
pipeline_run_label = $(if $(findstring =,$(1)),$(firstword $(subst =, ,$(1))),$(patsubst run-%,%,$(notdir $(1))))
define pipeline_post
$(1)/summary.md: $(foreach r,$(2),$(call pipeline_run_dir,$r)/wall_time.txt) $(5) $(PIPELINE_COMMON)/append-runs.sh | $(BIN)/latmpm-post
	$(BIN)/latmpm-post $(foreach r,$(2),$(call pipeline_run_dir,$r)) -o $(1) --title "$(4)" $(3) \
	  $(foreach r,$(2),--label $(call pipeline_run_label,$r)=$(call pipeline_run_dir,$r)) && \
	bash $(PIPELINE_COMMON)/append-runs.sh $(1) $(5) \
	  $(foreach r,$(2),$(call pipeline_run_label,$r)=$(call pipeline_run_dir,$r)) || { rm -f $(1)/summary.md; exit 1; }
endef

endif
