"""Rows: the build time of generated C++ (no anchor: SMACHA has no C++ target).

The 1,000-state script of bench/cpp_build_bench.py (imported here: its script() generator)
is compiled by `smachac -target=cpp`, then the translation unit by `c++ -std=c++20 -c` at -O0
and at -O2 (the same flags as cpp_build_bench.py), config.CPP_BUILD_REPEATS times each (CPU
time of the compiler, wall for reference); the -O2 object is linked with the runtime and must
run to `outcome: done`.
"""
import os
import sys

import config
import measure
import table
from context import ROOT

GROUP = "C++ build"
NO_ANCHOR = "no anchor (SMACHA has no C++ target)"


def rows(ctx):
    sys.path.insert(0, str(ROOT / "bench"))
    import cpp_build_bench  # the 1,000-state script of bench/README.md's C++ build bench
    states = cpp_build_bench.CONTAINERS * (cpp_build_bench.LEAVES + 1)
    script = ctx.write("big.yml", cpp_build_bench.script())
    source = ctx.path("big.cpp")
    ctx.say("C++ build: smachac -target=cpp, %d states" % states)
    generate = measure.repeat(config.REPEATS, lambda: measure.run(
        [ctx.smachac, "-target=cpp", script, "-o", source]))
    text = source.read_text(encoding="utf-8")
    size = "%s lines, %s bytes" % ("{:,}".format(text.count("\n")),
                                   "{:,}".format(len(text.encode())))
    cxx = os.environ.get("CXX", "c++")
    flags = [cxx, "-std=c++20", "-Wall", "-Wextra", "-Werror", "-I", ctx.runtime_include, "-c"]
    out = [table.Row(GROUP, "`smachac -target=cpp`, %s states (wall)" % "{:,}".format(states),
                     table.seconds(measure.median([s.wall for s in generate])), "", NO_ANCHOR,
                     "—", "median of %d runs; %s generated" % (config.REPEATS, size))]
    for level in ("-O0", "-O2"):
        ctx.say("C++ build: %s %s (%d runs)" % (cxx, level, config.CPP_BUILD_REPEATS))
        obj = ctx.path("big%s.o" % level)
        samples = measure.repeat(config.CPP_BUILD_REPEATS,
                                 lambda: measure.run(flags + [level, source, "-o", obj]))
        out.append(table.Row(
            GROUP, "`%s %s -c` of that translation unit (CPU)" % (cxx, level),
            table.seconds(measure.median([s.cpu for s in samples])), "", NO_ANCHOR, "—",
            "median of %d runs; wall %s" % (config.CPP_BUILD_REPEATS,
                                            table.seconds(measure.median([s.wall
                                                                          for s in samples])))))
    program = ctx.path("big")
    measure.run([cxx, ctx.path("big-O2.o"), ctx.runtime, "-pthread", "-o", program])
    run = measure.run([program], keep_stdout=True)
    if not run.stdout.endswith("outcome: done\n"):
        raise measure.Failed("the generated 1,000-state program did not end `outcome: done`")
    return out
