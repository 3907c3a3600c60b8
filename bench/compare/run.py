#!/usr/bin/python3
"""smachac side by side with its anchors (SMACHA, the real SMACH, python3-jinja2) on the same
inputs in one run, printed as one table of figures and ratios (bench/compare/README.md).

usage: bench/compare/run.py BUILD_DIR [GROUP...]
BUILD_DIR is a Release tree with smachac, libsmachac_runtime.a and bench/bench_tmpl
(`make bench-compare` builds build-bench). GROUPs (default all): cold scale runtime tmpl cpp.
Progress goes to standard error, the table to standard output. The knobs are in config.py.
"""
import os
import platform
import subprocess
import sys
import tempfile
import traceback
from pathlib import Path

sys.dont_write_bytecode = True  # no __pycache__ in the checkout
sys.path.insert(0, str(Path(__file__).resolve().parent))

import anchors  # noqa: E402
import config  # noqa: E402
import measure  # noqa: E402
import rows_cold  # noqa: E402
import rows_cppbuild  # noqa: E402
import rows_runtime  # noqa: E402
import rows_scale  # noqa: E402
import rows_tmpl  # noqa: E402
import table  # noqa: E402
from context import Context  # noqa: E402

GROUPS = {"cold": rows_cold, "scale": rows_scale, "runtime": rows_runtime, "tmpl": rows_tmpl,
          "cpp": rows_cppbuild}


def machine():
    cpus = subprocess.run(["nproc"], capture_output=True, text=True).stdout.strip()
    cxx = subprocess.run(["c++", "--version"], capture_output=True,
                         text=True).stdout.splitlines()[:1]
    return "%s, %s CPUs, %s, Python %s" % (platform.machine(), cpus, (cxx or ["c++ ?"])[0],
                                           platform.python_version())


def main():
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    build = Path(sys.argv[1])
    wanted = sys.argv[2:] or list(GROUPS)
    unknown = [g for g in wanted if g not in GROUPS]
    if unknown:
        print("run.py: unknown group %s (known: %s)" % (", ".join(unknown), " ".join(GROUPS)),
              file=sys.stderr)
        return 2
    rows, failures = [], []
    load_before = os.getloadavg()[0]
    with tempfile.TemporaryDirectory(prefix="smachac-compare-") as work:
        with anchors.Smacha(work) as smacha:
            ctx = Context(build, work, smacha)
            for tool in (ctx.smachac, ctx.runtime):
                if not tool.exists():
                    print("run.py: %s is missing: build %s first (make bench-compare does)"
                          % (tool, build), file=sys.stderr)
                    return 2
            for name in wanted:
                try:
                    rows += GROUPS[name].rows(ctx)
                except Exception as error:  # one broken group must not lose the others' rows
                    if not isinstance(error, measure.Failed):
                        traceback.print_exc()
                    failures.append("%s: %s" % (name, error))
                    rows.append(table.Row(GROUPS[name].GROUP, "(group failed)", "error",
                                          note=(str(error).splitlines() or [repr(error)])[0][:200]))
            ctx.say("done")
            seconds = ctx.elapsed()
    print()
    print("smachac vs its anchors; %s; repeats %d (config.py); ratio = anchor / smachac, "
          "paired run by run (above 1: smachac is faster or smaller)" % (machine(),
                                                                          config.REPEATS))
    print()
    print(table.markdown(rows))
    print()
    print("(measured in %.0f s; 1-minute load average %.1f before, %.1f after)"
          % (seconds, load_before, os.getloadavg()[0]))
    for failure in failures:
        print("\nFAILED %s" % failure, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
