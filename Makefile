# latmpm front door.
#   make        configure and build (Release) -> build/bin/
#   make test   install missing packages, build, run every test (ctest)
#   make demo   install, build, run the default experiment
#   make bench  build and run the benchmarks (figures go to docs/benchmarks.md by hand)
#   make fuzz   build and run the hostile-input suite, every case (docs/robustness.md)
BUILD      ?= build
BUILD_TYPE ?= Release
JOBS       ?= $(shell nproc)
BIN        := $(abspath $(BUILD))/bin
CMAKE_ARGS ?=

.PHONY: all build configure deps test demo bench fuzz clean help
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

clean:
	rm -rf $(BUILD)

# One make target per experiment lives in pipelines/*.mk.
-include $(wildcard pipelines/*.mk)
