# make lattice-stiffness [QUICK=1]: the six paper lattices' initial stiffness, effective
# modulus and first instability load from the static solver (docs/statics.md).
#   T1P20 T1P30 T1P40 T2P20 T2P30 T2P40; 5x5x5 cells, 3 mm printed plates, cell 0.64 mm,
#   2 points per cell per direction, uGIMP, E = 10 MPa, nu = 0.4, the lattice-compression
#   scene (printed base held, rigid half-space platen on the printed top plate).
#   Per lattice two static runs: "initial" (linear elastic, one increment of 0.1 mm: the
#   initial stiffness k; E* = k H / A with H the height between the plates and A the
#   footprint, from latmpm-lattice's report) and "path" (neo-Hookean, the platen moved in
#   increments until the load falls or Newton fails: the first instability load).
#   QUICK=1: 2x2x2 cells, 2 mm plates, cell 1 mm, path to 4 mm in 8 increments.
# Results in results/lattice-stiffness/{paper,quick}/: stiffness.md (table), stiffness.csv,
# stiffness.png (plot), run-<lattice>-{initial,path}/ (run directories).
include pipelines/common.mk

LS_SRC        := pipelines/lattice-stiffness
LS_OUT        := results/lattice-stiffness/$(if $(QUICK),quick,paper)
LS_LATTICES   := T1P20 T1P30 T1P40 T2P20 T2P30 T2P40
LS_CELL       := $(if $(QUICK),1mm,0.64mm)
LS_CELLS      := $(if $(QUICK),2x2x2,5x5x5)
LS_PLATES     := $(if $(QUICK),2mm,3mm)
LS_TRAVEL     := $(if $(QUICK),4mm,20mm)
LS_INCREMENTS := $(if $(QUICK),8,40)
LS_SCENE      := pipelines/lattice-compression/lattice-platen.toml

ls_common = --set grid.cell=$(LS_CELL) --set grid.shape=ugimp --set solver.kind=static \
  --set solver.check_stability=false \
  --set $(call pipeline_platen_at,$(call pipeline_lattice_top,$(1),$(lastword $(subst x, ,$(LS_CELLS))),$(LS_PLATES:mm=)))
ls_neo_hookean = --set bodies.lattice.material.model=neo_hookean --set bodies.top_plate.material.model=neo_hookean

LS_RUNS :=
$(foreach l,$(LS_LATTICES),\
  $(eval LS_RUNS += $(LS_OUT)/run-$l-initial $(LS_OUT)/run-$l-path)\
  $(eval $(call pipeline_run,$(LS_OUT)/run-$l-initial,$(LS_OUT)/points-$l.h5,$(LS_SCENE),\
    $(call ls_common,$l) --set run.end.plate_displacement=0.1mm --set solver.increments=1))\
  $(eval $(call pipeline_run,$(LS_OUT)/run-$l-path,$(LS_OUT)/points-$l.h5,$(LS_SCENE),\
    $(call ls_common,$l) $(ls_neo_hookean) --set run.end.plate_displacement=$(LS_TRAVEL) \
    --set solver.increments=$(LS_INCREMENTS))))

.PHONY: lattice-stiffness lattice-stiffness-results
lattice-stiffness:
	$(MAKE) build
	$(MAKE) lattice-stiffness-results

lattice-stiffness-results: $(LS_OUT)/stiffness.md
	@echo "lattice-stiffness: results in $<"

# Only the initial stiffness (seconds per lattice; the paths take minutes each).
.PHONY: lattice-stiffness-initial
lattice-stiffness-initial: $(foreach l,$(LS_LATTICES),$(LS_OUT)/run-$l-initial/wall_time.txt $(LS_OUT)/geometry-$l.txt)
	bash $(LS_SRC)/table.sh $(LS_OUT) $(LS_PLATES:mm=) $(LS_LATTICES)

$(LS_OUT)/geometry-%.h5: | $(BIN)/latmpm-lattice
	@mkdir -p $(@D)
	$(BIN)/latmpm-lattice --preset $* --cells $(LS_CELLS) --plates $(LS_PLATES) --quiet -o $@

# latmpm-lattice's report (bounding box, footprint volume, on stderr) for the modulus.
$(LS_OUT)/geometry-%.txt: | $(BIN)/latmpm-lattice
	@mkdir -p $(@D)
	$(BIN)/latmpm-lattice --preset $* --cells $(LS_CELLS) --plates $(LS_PLATES) -o $(@:.txt=-report.h5) 2> $@ \
	  && rm -f $(@:.txt=-report.h5)

$(LS_OUT)/points-%.h5: $(LS_OUT)/geometry-%.h5 | $(BIN)/latmpm-voxelize
	$(BIN)/latmpm-voxelize $< --cell $(LS_CELL) --ppc 2 --quiet -o $@

$(LS_OUT)/stiffness.md: $(foreach r,$(LS_RUNS),$r/wall_time.txt) $(foreach l,$(LS_LATTICES),$(LS_OUT)/geometry-$l.txt) \
  $(LS_SRC)/table.sh pipelines/lattice-stiffness.mk
	bash $(LS_SRC)/table.sh $(LS_OUT) $(LS_PLATES:mm=) $(LS_LATTICES)

.PRECIOUS: $(LS_OUT)/geometry-%.h5 $(LS_OUT)/points-%.h5
