# latmpm front door.
#   make        configure and build (Release) -> build/bin/
#   make test   install missing packages, build, run every test (ctest; the mpi.* tests on
#               2-4 processes use the MPI solver built beside it in build/mpi/)
#   make demo   install, build, run the default experiment
#   make bench  build and run the benchmarks (figures go to docs/benchmarks.md by hand)
#   make fuzz   build and run the hostile-input suite, every case (docs/robustness.md)
#   make mpi    install OpenMPI, build the solver on MPI in build-mpi/ (docs/cluster.md):
#               mpirun -np 2 build-mpi/bin/latmpm-solve SCENE -o RUN
BUILD      ?= build
BUILD_TYPE ?= Release
JOBS       ?= $(shell nproc)
BIN        := $(abspath $(BUILD))/bin
CMAKE_ARGS ?=
MPI_BUILD  ?= build-mpi

.PHONY: all build configure deps test demo bench fuzz mpi clean help
all: build

help:
	@sed -n 's/^#   //p' Makefile

deps:
	@bash scripts/install-deps.sh

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) $(CMAKE_ARGS)

configure: $(BUILD)/CMakeCache.txt

build: configure
	cmake --build $(BUILD) -j$(JOBS)

test: deps
	$(MAKE) build
	cd $(BUILD) && ctest --output-on-failure -j$(JOBS) --timeout 900

demo: deps
	$(MAKE) build
	bash scripts/demo.sh $(BIN) results/demo

bench: deps
	$(MAKE) build
	bash bench/run.sh $(BIN)

fuzz: deps
	$(MAKE) build
	python3 tests/fuzz/run_fuzz.py --bin $(BIN) --source $(CURDIR) --jobs $(JOBS)

# The MPI solver beside the one-process build; `make test BUILD=build-mpi` runs the suite
# there, with the mpi.* tests on 2 and 4 processes.
mpi:
	@bash scripts/install-deps.sh
	$(MAKE) build BUILD=$(MPI_BUILD) CMAKE_ARGS="-DLATMPM_MPI=ON $(CMAKE_ARGS)"

clean:
	rm -rf $(BUILD)

# One make target per experiment lives in pipelines/*.mk.
-include $(wildcard pipelines/*.mk)
