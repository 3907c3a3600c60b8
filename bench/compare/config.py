"""Every knob of bench-compare in one place: repetitions and sizes. The defaults keep
`make bench-compare` at about 4 minutes on an idle 2-core machine, 7 under load from other
builds (an up-to-date build tree). SMACHAC_COMPARE_REPEATS overrides REPEATS,
SMACHAC_COMPARE_QUICK=1 shrinks everything for a smoke run (about a minute).
"""
import os

# Runs per measurement (each figure is the median of these; ratios are paired run by run).
REPEATS = int(os.environ.get("SMACHAC_COMPARE_REPEATS", "5"))

# Process start-up: `smachac --version` vs /bin/true (tiny, so more runs).
STARTUP_REPEATS = 4 * REPEATS

# Cold compile of SMACHA's test scripts: runs per script (SMACHA takes 0.2-1 s a script, and
# there are 49 of them).
CORPUS_REPEATS = 5

# In-process compile of the generated flat script (bench/passes_bench.cpp's `flat` shape).
SCALE_SIZES = (1000, 10000, 100000)
SMACHA_MAX_STATES = 10000      # SMACHA is slow: it is run up to this size only
SMACHA_SCALE_REPEATS = {1000: REPEATS, 10000: 3}  # SMACHA runs per size (10k: 15-25 s a run)

# Runtime: the counter loop (2 transitions per iteration) and the Concurrence fan-out.
LOOP_ITERATIONS = 100000
FAN_OUT_CHILDREN = 8
FAN_OUT_ROUNDS = 1000

# Generated C++ build time (bench/cpp_build_bench.py's 1,000-state script): c++ runs per level.
CPP_BUILD_REPEATS = 3

if os.environ.get("SMACHAC_COMPARE_QUICK") == "1":
    REPEATS = STARTUP_REPEATS = CORPUS_REPEATS = CPP_BUILD_REPEATS = 1
    SCALE_SIZES = (1000, 10000)
    SMACHA_MAX_STATES = 1000
    SMACHA_SCALE_REPEATS = {1000: 1}
    LOOP_ITERATIONS = 10000
    FAN_OUT_ROUNDS = 100
