# make paper-a [QUICK=1]: every experiment of paper A (column-buckling, lattice-compression,
#   imperfections, impact; their own targets, pipelines/*.mk) and the comparison document
#   built from their latmpm-post tables and plots by pipelines/paper-a/write-doc.sh against
#   pipelines/paper-a/paper-values.csv (no number in the document is typed by hand).
#   Paper resolution: writes docs/paper-a.md and its figures docs/paper-a-*.png.
#   QUICK=1: the experiments' QUICK sizes, uGIMP only unless DDMP=1 is given (DDMP runs
#   15-30x slower, docs/experiments.md), the document in results/paper-a/quick/paper-a.md.
#   make -j2 paper-a QUICK=1 runs the cases side by side.
include pipelines/common.mk

PA_MODE := $(if $(QUICK),quick,paper)
PA_DDMP := $(if $(filter command line,$(origin DDMP)),$(DDMP),$(if $(QUICK),0,1))
PA_DOC  := $(if $(QUICK),results/paper-a/quick/paper-a.md,docs/paper-a.md)

.PHONY: paper-a paper-a-results paper-a-document
paper-a:
	$(MAKE) build
	$(MAKE) paper-a-results

paper-a-results:
	$(MAKE) column-buckling-results lattice-compression-results imperfections-results impact-results DDMP=$(PA_DDMP)
	$(MAKE) paper-a-document

# The document alone, from the results there are (an experiment without results is named as missing).
paper-a-document:
	bash pipelines/paper-a/write-doc.sh $(PA_MODE) $(PA_DOC)
	@echo "paper-a: $(PA_DOC)"
