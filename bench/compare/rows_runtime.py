"""Rows: the generated programs at run time, the C++ runtime vs the real SMACH.

One script (scripts.py, built-in templates and `!expr` callbacks only) is compiled twice:
`-target=cpp`, built with `c++ -std=c++20 -O2` ($CXX, default c++) against the build tree's
libsmachac_runtime.a, and `-target=smach`, run by Debian's python3 on the real SMACH. The two
programs run alternately (config.REPEATS times), each a whole process; the figures are its
CPU time (user + system: SMACH's threads and polling included) and wall time.
  counter loop   COUNT / CHECK for config.LOOP_ITERATIONS iterations (2 transitions each)
  fan-out        a Concurrence of config.FAN_OUT_CHILDREN CallbacksStates, run
                 config.FAN_OUT_ROUNDS times in a loop
The SMACH program is run as generated: SMACH logs every transition (smach.loginfo prints it);
its standard output goes to a file, whose last line must say the machine ended in `done`. The
C++ program prints only its outcome (no trace), which must be `done`.
"""
import os

import config
import measure
import scripts
import table

GROUP = "runtime"


def rows(ctx):
    loop = "counter loop, %s iterations (%s transitions)" % (
        "{:,}".format(config.LOOP_ITERATIONS), "{:,}".format(2 * config.LOOP_ITERATIONS))
    fan = "Concurrence fan-out, %d children × %s rounds" % (
        config.FAN_OUT_CHILDREN, "{:,}".format(config.FAN_OUT_ROUNDS))
    out = []
    for name, what, text in (
            ("loop", loop, scripts.counter_loop(config.LOOP_ITERATIONS)),
            ("fan_out", fan, scripts.fan_out(config.FAN_OUT_CHILDREN, config.FAN_OUT_ROUNDS))):
        out += program_rows(ctx, name, what, text)
    return out


def program_rows(ctx, name, what, text):
    ctx.say("runtime: %s (build)" % what)
    script = ctx.write(name + ".yml", text)
    flags = ["-Wno-unused-userdata-key"]  # the fan-out's children write keys nobody reads
    cpp, program = ctx.path(name + ".cpp"), ctx.path(name + "_cpp")
    python = ctx.path(name + ".py")
    measure.run([ctx.smachac, "-target=cpp"] + flags + [script, "-o", cpp])
    measure.run([os.environ.get("CXX", "c++"), "-std=c++20", "-O2", "-I", ctx.runtime_include,
                 cpp, ctx.runtime, "-pthread", "-o", program])
    measure.run([ctx.smachac, "-target=smach"] + flags + [script, "-o", python])

    def ours():
        sample = measure.run([program], keep_stdout=True)
        if sample.stdout.strip().splitlines()[-1:] != ["outcome: done"]:
            raise measure.Failed("%s did not end with `outcome: done`" % program)
        return sample

    log = ctx.path(name + ".smach.log")

    def anchor():
        sample = measure.run(["/usr/bin/python3", python], env=ctx.smach.env(), stdout=log)
        last = log.read_bytes()[-200:].decode(errors="replace").strip().splitlines()[-1:]
        if not last or "'done'" not in last[0]:
            raise measure.Failed("%s did not end in `done`: %s" % (python, last))
        return sample

    if ctx.smach.why_not:
        ctx.say("runtime: %s (C++ only)" % what)
        result = measure.pair(config.REPEATS, ours, None, anchor_repeats=0)
        return [table.skipped(GROUP, "%s (%s)" % (what, kind),
                              table.seconds(result.median("ours", key)), "SMACH 2.5",
                              ctx.smach.why_not) for kind, key in (("CPU", "cpu"),
                                                                   ("wall", "wall"))]
    ctx.say("runtime: %s (%d runs each)" % (what, config.REPEATS))
    result = measure.pair(config.REPEATS, ours, anchor)
    note = "C++ -O2 vs SMACH Python; median of %d runs" % config.REPEATS
    return [table.Row(GROUP, "%s (%s)" % (what, kind), table.seconds(result.median("ours", key)),
                      "SMACH 2.5 (Python)", table.seconds(result.median("anchor", key)),
                      result.ratio(key), note if kind == "CPU" else "the same runs")
            for kind, key in (("CPU", "cpu"), ("wall", "wall"))]
