# make column-buckling [QUICK=1]: paper A Sec. 4, the buckling column.
#   t in {2.4, 1.6} mm x a in {0, 0.02 L}, L = 16 mm, v0 = 100 mm/s, E = 10 MPa, nu = 0.4,
#   rho = 6 rho0, uGIMP, cell 0.2 mm with 2 points per cell per direction (spacing 0.1 mm);
#   QUICK=1: cell 0.4 mm (spacing 0.2 mm). Results in results/column-buckling/{paper,quick}/:
#   load-displacement-<case>.csv, run-<case>/ (the solver's run directory, wall_time.txt),
#   summary.md (peak and plateau load against the Euler load, K = 0.5) and summary.csv.
# Each file depends on the files it is made from: `make -j4 column-buckling` runs the four
# cases in parallel and a second call redoes only what changed. The tools are order-only
# prerequisites (a rebuilt solver does not rerun finished cases; delete a run-<case>/ to).
# Chain per case: latmpm-lattice --column -> latmpm-voxelize -> latmpm-imperfect --type sine
# (a > 0) -> latmpm-solve pipelines/column-buckling/column.toml -> extract.sh.

CB_SRC     := pipelines/column-buckling
CB_OUT     := results/column-buckling/$(if $(QUICK),quick,paper)
CB_CELL    := $(if $(QUICK),0.4mm,0.2mm)
CB_PPC     := 2
CB_PLATE   := $(if $(QUICK),0.8mm,0.4mm)
CB_LENGTH  := 16mm
CB_CASES   := t2.4-a0 t2.4-a0.02L t1.6-a0 t1.6-a0.02L

.PHONY: column-buckling column-buckling-results
column-buckling:
	$(MAKE) build
	$(MAKE) column-buckling-results

column-buckling-results: $(CB_OUT)/summary.md
	@cat $<

# Geometry: the column with end plates as thick as two cells (the base and the driven plate).
$(CB_OUT)/geometry-t%.h5: | $(BIN)/latmpm-lattice
	@mkdir -p $(@D)
	$(BIN)/latmpm-lattice --column --diameter $*mm --length $(CB_LENGTH) --end-plates $(CB_PLATE) --quiet -o $@

$(CB_OUT)/voxel-t%.h5: $(CB_OUT)/geometry-t%.h5 | $(BIN)/latmpm-voxelize
	$(BIN)/latmpm-voxelize $< --cell $(CB_CELL) --ppc $(CB_PPC) --quiet -o $@

# a = 0: the straight column as voxelized.
$(CB_OUT)/points-t%-a0.h5: $(CB_OUT)/voxel-t%.h5
	cp $< $@

# a = 0.02 L = 0.32 mm: u0(z) = a sin(pi z / L) over the column (paper A Sec. 4).
$(CB_OUT)/points-t%-a0.02L.h5: $(CB_OUT)/voxel-t%.h5 | $(BIN)/latmpm-imperfect
	$(BIN)/latmpm-imperfect $< --type sine --amount 0.32mm --length $(CB_LENGTH) --quiet -o $@

# The run; wall_time.txt is written only when the solver finished.
$(CB_OUT)/run-%/wall_time.txt: $(CB_OUT)/points-%.h5 $(CB_SRC)/column.toml | $(BIN)/latmpm-solve
	@rm -f $@ && mkdir -p $(@D)
	start=$$(date +%s.%N) && \
	$(BIN)/latmpm-solve $(CB_SRC)/column.toml --set points.0.file=$< --set grid.cell=$(CB_CELL) \
	  -o $(@D) --quiet > $(@D)/summary.txt && \
	awk -v a=$$start -v b=$$(date +%s.%N) 'BEGIN { printf "wall_s=%.1f\n", b - a }' > $@.tmp && mv $@.tmp $@

$(CB_OUT)/load-displacement-%.csv: $(CB_OUT)/run-%/wall_time.txt $(CB_SRC)/extract.sh
	bash $(CB_SRC)/extract.sh $(<D) $@

# Euler load with E = 10 MPa, L = 16 mm, K = 0.5 (clamped-clamped; summary.sh says why).
$(CB_OUT)/summary.md: $(foreach c,$(CB_CASES),$(CB_OUT)/load-displacement-$(c).csv) $(CB_SRC)/summary.sh
	bash $(CB_SRC)/summary.sh $(CB_OUT) 10e6 0.016 0.5 $(CB_CASES) > $@.tmp && mv $@.tmp $@

.PRECIOUS: $(CB_OUT)/geometry-t%.h5 $(CB_OUT)/voxel-t%.h5 $(CB_OUT)/points-t%-a0.h5 \
           $(CB_OUT)/points-t%-a0.02L.h5 $(CB_OUT)/run-%/wall_time.txt
