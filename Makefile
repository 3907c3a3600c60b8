# smachac: the two commands users run are `make demo` and `make test`.
# Each installs missing Debian packages (tools/install-deps), configures and builds a Release
# tree with warnings as errors, then acts.

BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release -DSMACHAC_WERROR=ON
SMACHAC := $(BUILD)/tools/smachac/smachac

.PHONY: all deps configure build test demo bench clean

all: build

deps:
	@bash tools/install-deps

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)

configure: deps $(BUILD)/CMakeCache.txt

build: configure
	cmake --build $(BUILD) -j $(JOBS)

test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

demo: build
	@bash tools/demo.sh $(SMACHAC)

bench: deps
	cmake -S . -B $(BUILD)-bench $(CMAKE_FLAGS) -DSMACHAC_BUILD_BENCH=ON -DSMACHAC_BUILD_TESTS=OFF
	cmake --build $(BUILD)-bench -j $(JOBS)
	@bash bench/run.sh $(BUILD)-bench

clean:
	rm -rf $(BUILD) $(BUILD)-bench
