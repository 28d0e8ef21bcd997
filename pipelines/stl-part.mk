# make stl-part [QUICK=1] [STL=part.stl UNITS=mm SCALE=1 ROTATE="x:90deg" REPAIR=1]: an STL
#   of a printed part through the same chain. Default part, "the scanned part": a BCC block
#   (3x3x3 cells, struts 5 mm long and 1.2 mm thick, 1.5 mm printed plates) written as STL by
#   latmpm-lattice --stl. STL=path.stl takes any other part: UNITS its length unit (default
#   mm), SCALE a factor, ROTATE rotations in order (z is the compression axis), REPAIR=1
#   passes --repair. latmpm-voxelize --place centres the part on x = y = 0 and stands it on
#   z = 0 (CGAL checks, level set, points); two rigid disc platens (latmpm-lattice --column
#   --stl, voxelized as bottom_plate below z = 0 and top_plate standing on the part's points
#   with --stand-on: the height is the part's, computed), the top one driven down 5 mm at
#   100 mm/s, E = 10 MPa, nu = 0.4, rho = 6 rho0, uGIMP, cell 0.3 mm with 2 points per cell
#   per direction. QUICK=1: cell 0.6 mm, 2 mm travel.
# Results in results/stl-part/{paper,quick}/: summary.md, metrics.csv, runs.csv, plots/,
# curves/, run-part/, part.stl.
include pipelines/common.mk

SP_SRC    := pipelines/stl-part
SP_OUT    := results/stl-part/$(if $(QUICK),quick,paper)
SP_CELL   := $(if $(QUICK),0.6mm,0.3mm)
SP_TRAVEL := $(if $(QUICK),2mm,5mm)
SP_PLATEN := 2mm
# The part's placement options (a change re-voxelizes it: they are in part.args).
SP_PART_OPTIONS := --units $(or $(UNITS),mm) --scale $(or $(SCALE),1) $(if $(filter 1,$(REPAIR)),--repair) \
  $(foreach r,$(ROTATE),--rotate $(r)) --place
comma := ,
# The title names the part by its file (no commas: see pipeline_post).
SP_NAME   := $(if $(STL),$(subst $(comma), ,$(basename $(notdir $(STL)))),a BCC block (3x3x3 cells))

.PHONY: stl-part stl-part-results
stl-part:
	$(MAKE) build
	$(MAKE) stl-part-results

stl-part-results: $(SP_OUT)/summary.md
	@echo "stl-part: results in $<"

ifdef STL
$(SP_OUT)/part.stl: $(STL)
	@mkdir -p $(@D)
	cp $< $@
else
$(SP_OUT)/part.stl: | $(BIN)/latmpm-lattice
	@mkdir -p $(@D)
	$(BIN)/latmpm-lattice --cell bcc --cells 3x3x3 --strut-length 5mm --strut-diameter 1.2mm \
	  --plates 1.5mm --stl $@.tmp.stl --voxel 0.2mm --quiet -o $(SP_OUT)/part-geometry.h5 && mv $@.tmp.stl $@
endif

$(eval $(call pipeline_args,$(SP_OUT)/part.args,$(SP_PART_OPTIONS)))
$(SP_OUT)/part.h5: $(SP_OUT)/part.stl $(SP_OUT)/part.args | $(BIN)/latmpm-voxelize
	$(BIN)/latmpm-voxelize $< $(SP_PART_OPTIONS) --cell $(SP_CELL) --ppc 2 --quiet -o $@

# The platens: a disc 24 mm across and 2 mm thick, below z = 0 and standing on the part.
$(SP_OUT)/platen.stl: | $(BIN)/latmpm-lattice
	@mkdir -p $(@D)
	$(BIN)/latmpm-lattice --column --diameter 24mm --length $(SP_PLATEN) --stl $@ --voxel 0.25mm \
	  --quiet -o $(SP_OUT)/platen-geometry.h5
$(SP_OUT)/bottom.h5: $(SP_OUT)/platen.stl | $(BIN)/latmpm-voxelize
	$(BIN)/latmpm-voxelize $< --units mm --cell $(SP_CELL) --ppc 2 --body bottom_plate \
	  --place --translate 0mm,0mm,-$(SP_PLATEN) --quiet -o $@
$(SP_OUT)/top.h5: $(SP_OUT)/platen.stl $(SP_OUT)/part.h5 | $(BIN)/latmpm-voxelize
	$(BIN)/latmpm-voxelize $< --units mm --cell $(SP_CELL) --ppc 2 --body top_plate \
	  --place --stand-on $(SP_OUT)/part.h5 --quiet -o $@

$(eval $(call pipeline_run,$(SP_OUT)/run-part,$(SP_OUT)/part.h5,$(SP_SRC)/part.toml,\
  --set points.1.file=$(SP_OUT)/bottom.h5 --set points.2.file=$(SP_OUT)/top.h5 \
  --set grid.cell=$(SP_CELL) --set run.end.plate_displacement=$(SP_TRAVEL)))
$(SP_OUT)/run-part/wall_time.txt: $(SP_OUT)/bottom.h5 $(SP_OUT)/top.h5

$(eval $(call pipeline_post,$(SP_OUT),$(SP_OUT)/run-part,--kind compression --fit-range $(if $(QUICK),0.3mm:1mm,0.5mm:2mm),STL part: $(SP_NAME) between rigid platens,$(SP_SRC)/notes.md))
$(SP_OUT)/summary.md: pipelines/stl-part.mk
