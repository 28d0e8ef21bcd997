# make shpb [QUICK=1]: paper B's split-Hopkinson-bar specimen (docs/paper-b.md).
#   42CrMo4 cylinder d0 = l0 = 4 mm, one CPDI1 domain per hexahedron of latmpm-hexmesh's
#   O-grid cylinder (levels B1-B6), finite-strain J2 plasticity, the incident plane driven
#   at 10.6476 m/s and the transmitter plane fixed, penalty contact with Coulomb friction.
#   Paper: 150 us at dt = 5 ns; friction mu in {0.05, 0.1, 0.2, 0.35} on B5/G4, meshes B1-B6
#   on G4, grids G1-G4 on B4. QUICK=1: 10 us (dt = 5 ns); friction on B2/G4, meshes B2-B4 on
#   G4, grids G2-G4 on B3.
# Results in results/shpb/{paper,quick}/: friction/, meshes/, grids/ (latmpm-post: summary.md,
# metrics.csv, comparison.csv against mu = 0.1, the finest mesh and the finest grid, plots of
# f_i against time), forces.png (f_i, f_t and f_a of the mu = 0.1 run, paper B Fig. 8), run-<case>/
# (series.csv: load_driven = f_i, load_fixed = f_t, load_average = f_a, Eq. 14).
# Chain: latmpm-hexmesh --cylinder -> latmpm-solve pipelines/shpb/shpb.toml -> latmpm-post.
# Cost (measured, docs/paper-b.md "The paper-size table"): the paper table is 34 min of CPU
# (B6 for 150 us: 6.7 min, B5: ~4 min each), ~25 min of wall with -j2 on an idle 2-core
# machine; QUICK=1 ~30 s of CPU.
include pipelines/common.mk

SH_SRC  := pipelines/shpb
SH_MODE := $(if $(QUICK),quick,paper)
SH_OUT  := results/shpb/$(SH_MODE)

SH_ROWS := $(call pipeline_rows,$(SH_SRC)/cases-$(SH_MODE).txt,0)
$(call pipeline_table,$(SH_OUT),$(SH_SRC)/cases-$(SH_MODE).txt,$(SH_ROWS),1)
SH_SELECTED := $(call pipeline_selected,$(SH_ROWS))
$(call pipeline_check_cases,shpb,$(SH_ROWS))

# The three studies by case name: mu<..>-..., B<k>G4, and B<mesh>G<k> on the grid study's mesh.
SH_GRID_MESH := $(if $(QUICK),B3,B4)
sh_rows_named = $(foreach r,$(SH_SELECTED),$(if $(filter $(1),$(call pipeline_field,$r,1)),$r))
SH_FRICTION  := $(call sh_rows_named,mu%)
SH_MESHES    := $(call sh_rows_named,B1G4 B2G4 B3G4 B4G4 B5G4 B6G4)
SH_GRIDS     := $(call sh_rows_named,$(addprefix $(SH_GRID_MESH)G,1 2 3 4))
SH_MESH_REF  := $(if $(QUICK),B4G4,B6G4)
SH_GRID_REF  := $(SH_GRID_MESH)G4

.PHONY: shpb shpb-results
shpb:
	$(MAKE) build
	$(MAKE) shpb-results

SH_FORCES_RUN := $(firstword $(filter mu0.1-%,$(foreach r,$(SH_FRICTION),$(call pipeline_field,$r,1))))

shpb-results: $(if $(SH_FRICTION),$(SH_OUT)/friction/summary.md) $(if $(SH_MESHES),$(SH_OUT)/meshes/summary.md) \
    $(if $(SH_GRIDS),$(SH_OUT)/grids/summary.md) $(if $(SH_FORCES_RUN),$(SH_OUT)/forces.png) \
    $(SH_OUT)/comparison.md $(if $(SH_FRICTION),$(SH_OUT)/friction.png) $(if $(SH_MESHES),$(SH_OUT)/meshes.png) \
    $(if $(SH_GRIDS),$(SH_OUT)/grids.png)
	@echo "shpb: results in $(SH_OUT)/comparison.md and $(SH_OUT)/{friction,meshes,grids}/summary.md"

# Every selected row against paper B in numbers (paper_table.py): the table of f_i, f_t, f_a,
# energy and CPU per run, then the friction spread per mesh, mesh and grid convergence, B6.
SH_LABEL_RUNS := $(call pipeline_label_runs,$(SH_OUT),$(SH_SELECTED))
sh_done = $(foreach r,$(1),$(lastword $(subst =, ,$r))/done)
$(SH_OUT)/comparison.md: $(call sh_done,$(SH_LABEL_RUNS)) $(SH_SRC)/paper_table.py
	python3 $(SH_SRC)/paper_table.py --out $@ $(SH_LABEL_RUNS)

# f_i against time per study (paper B Figs. 11, 12a, 12b): plot_study.gp over the study's rows
# (friction: also the rows <mesh>G4-mu<mu> of another mesh).
SH_FRICTION_PLOT := $(SH_FRICTION) $(call sh_rows_named,$(SH_GRID_MESH:B4=B3)G4-mu%)
sh_plot = gnuplot -e "files='$(foreach r,$(2),$(lastword $(subst =, ,$r))/series.csv)'; \
  labels='$(foreach r,$(2),$(firstword $(subst =, ,$r)))'; png='$(1)'; label='$(3)'" $(SH_SRC)/plot_study.gp
$(SH_OUT)/friction.png: $(call sh_done,$(call pipeline_label_runs,$(SH_OUT),$(SH_FRICTION_PLOT))) $(SH_SRC)/plot_study.gp
	$(call sh_plot,$@,$(call pipeline_label_runs,$(SH_OUT),$(SH_FRICTION_PLOT)),SHPB: f_i against friction (paper B Fig. 11))
$(SH_OUT)/meshes.png: $(call sh_done,$(call pipeline_label_runs,$(SH_OUT),$(SH_MESHES))) $(SH_SRC)/plot_study.gp
	$(call sh_plot,$@,$(call pipeline_label_runs,$(SH_OUT),$(SH_MESHES)),SHPB: f_i of the meshes on G4 (paper B Fig. 12a))
$(SH_OUT)/grids.png: $(call sh_done,$(call pipeline_label_runs,$(SH_OUT),$(SH_GRIDS))) $(SH_SRC)/plot_study.gp
	$(call sh_plot,$@,$(call pipeline_label_runs,$(SH_OUT),$(SH_GRIDS)),SHPB: f_i of the grids on $(SH_GRID_MESH) (paper B Fig. 12b))

# The paper-size figures and table of docs/paper-b.md ("The paper-size study, run").
.PHONY: shpb-docs
shpb-docs: shpb-results
	cp $(SH_OUT)/friction.png docs/paper-b-shpb-friction.png
	cp $(SH_OUT)/meshes.png docs/paper-b-shpb-meshes.png
	cp $(SH_OUT)/grids.png docs/paper-b-shpb-grids.png
	cp $(SH_OUT)/forces.png docs/paper-b-shpb-forces.png
	@echo "shpb-docs: figures copied; the table and comparisons of docs/paper-b.md are $(SH_OUT)/comparison.md"

# Mesh level k (B<k>): core 2k, ring k, axial 4k divisions (docs/paper-b.md).
$(SH_OUT)/b%.h5: | $(BIN)/latmpm-hexmesh
	@mkdir -p $(@D)
	$(BIN)/latmpm-hexmesh --cylinder --diameter 4mm --height 4mm --level $* --cell 0.4mm -o $@

$(eval $(call pipeline_post,$(SH_OUT)/friction,$(call pipeline_label_runs,$(SH_OUT),$(SH_FRICTION)),--kind compression --load load_driven --reference $(SH_FORCES_RUN),SHPB specimen: friction study (paper B Sec. 3.4),$(SH_SRC)/notes.md))
$(eval $(call pipeline_post,$(SH_OUT)/meshes,$(call pipeline_label_runs,$(SH_OUT),$(SH_MESHES)),--kind compression --load load_driven --reference $(SH_MESH_REF),SHPB specimen: CPDI meshes on G4 (paper B Sec. 3.4),$(SH_SRC)/notes.md))
$(eval $(call pipeline_post,$(SH_OUT)/grids,$(call pipeline_label_runs,$(SH_OUT),$(SH_GRIDS)),--kind compression --load load_driven --reference $(SH_GRID_REF),SHPB specimen: grids on $(SH_GRID_MESH) (paper B Sec. 3.4),$(SH_SRC)/notes.md))

# Paper B Fig. 8: f_i, f_t and f_a of the mu = 0.1 run against time.
$(SH_OUT)/forces.png: $(SH_OUT)/run-$(SH_FORCES_RUN)/done $(SH_SRC)/plot_forces.gp
	gnuplot -e "csv='$(SH_OUT)/run-$(SH_FORCES_RUN)/series.csv'; png='$@'; label='SHPB $(SH_FORCES_RUN): contact forces and f_a'" $(SH_SRC)/plot_forces.gp

$(SH_OUT)/friction/summary.md $(SH_OUT)/meshes/summary.md $(SH_OUT)/grids/summary.md: pipelines/shpb.mk

.PRECIOUS: $(SH_OUT)/b%.h5
