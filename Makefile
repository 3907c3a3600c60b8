# smachac: the two commands users run are `make demo` and `make test`.
# Each installs missing Debian packages (tools/install-deps), configures and builds a Release
# tree with warnings as errors, then acts.

BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release -DSMACHAC_WERROR=ON
SMACHAC := $(BUILD)/tools/smachac/smachac

.PHONY: all deps configure build test lint demo demo-ros bench bench-compare fuzz test-sanitize clean

all: build

deps:
	@bash tools/install-deps

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)

configure: deps $(BUILD)/CMakeCache.txt

build: configure
	cmake --build $(BUILD) -j $(JOBS)

# ctest, then why each skipped test (or left-out case) did not run (tools/run-tests.sh).
test: build
	@bash tools/run-tests.sh $(BUILD) $(JOBS)

# The house style, checked: every C++ file formatted as .clang-format says, and the lint
# tests (the component graph, typed diagnostics). .ci/run runs it after the tests.
lint: build
	@bash tools/lint.sh $(BUILD)

# Builds only what the demo runs (the compiler and the dual-arm program with the runtime and
# the simulation it links), not the tests.
DEMO_TARGETS := smachac baxter_dual_arm_stacking
demo: configure
	cmake --build $(BUILD) -j $(JOBS) --target $(DEMO_TARGETS)
	@bash tools/demo.sh $(SMACHAC)
	@bash sim/experiments/run_demo.sh $(BUILD)

# The stacking experiment as the paper ran it: SMACH Python on a (simulated) Baxter over ROS.
# Builds only the compiler and the simulation's ROS bridge.
# The ROS overlay (SMACH, FlexBE, the Baxter SDK, from an installed ROS or the frameworks
# folder: tools/frameworks) is built by its ctest.
demo-ros: configure
	cmake --build $(BUILD) -j $(JOBS) --target smachac smachac_sim_bridge
	ctest --test-dir $(BUILD) -R '^ros/overlay$$' --output-on-failure
	@bash sim/ros/run_demo_ros.sh $(BUILD)

bench: deps
	cmake -S . -B $(BUILD)-bench $(CMAKE_FLAGS) -DSMACHAC_BUILD_BENCH=ON -DSMACHAC_BUILD_TESTS=OFF
	cmake --build $(BUILD)-bench -j $(JOBS)
	@bash bench/run.sh $(BUILD)-bench

# smachac beside SMACHA, the real SMACH and python3-jinja2 on the same inputs: one table of
# figures and paired ratios (bench/compare/README.md). Builds only what it runs.
bench-compare: configure
	cmake -S . -B $(BUILD)-bench $(CMAKE_FLAGS) -DSMACHAC_BUILD_BENCH=ON -DSMACHAC_BUILD_TESTS=OFF
	cmake --build $(BUILD)-bench -j $(JOBS) --target smachac smachac_runtime bench_tmpl
	@SMACHAC_TEST_BUILD=$(BUILD) /usr/bin/python3 bench/compare/run.py $(BUILD)-bench

# Each libFuzzer harness for FUZZ_SECONDS with ASan + UBSan (clang); crashes land in
# build-fuzz/artifacts/ and make the target fail.
FUZZ_SECONDS ?= 60
fuzz: deps
	cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
	  -DSMACHAC_FUZZ=ON -DSMACHAC_SANITIZE=address,undefined
	cmake --build build-fuzz -j $(JOBS) --target smachac_fuzzers
	@bash tools/fuzz.sh build-fuzz $(FUZZ_SECONDS)

# The whole suite under AddressSanitizer + UndefinedBehaviorSanitizer (warnings are not errors
# here: GCC reports false maybe-uninitialized positives in instrumented code), then the
# runtime's concurrency tests under ThreadSanitizer (label tsan; TSan cannot share a tree with
# ASan, so build-tsan builds only that test). tests/sanitizers/lsan.supp suppresses the leaks
# of the system's OpenGL (Mesa), and nothing of ours.
LSAN_SUPPRESSIONS := $(CURDIR)/tests/sanitizers/lsan.supp
test-sanitize: deps
	cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSMACHAC_WERROR=OFF \
	  -DSMACHAC_SANITIZE=address,undefined
	cmake --build build-asan -j $(JOBS)
	ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  LSAN_OPTIONS=suppressions=$(LSAN_SUPPRESSIONS):print_suppressions=0 \
	  ctest --test-dir build-asan --output-on-failure -j $(JOBS) -LE tsan
	cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSMACHAC_WERROR=OFF
	cmake --build build-tsan -j $(JOBS) --target smachac_runtime_tsan_test
	ctest --test-dir build-tsan --output-on-failure -L tsan

clean:
	rm -rf $(BUILD) $(BUILD)-bench build-fuzz build-asan build-tsan
