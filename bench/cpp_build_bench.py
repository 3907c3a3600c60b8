#!/usr/bin/python3
"""Compile and build time of a generated 1,000-state machine on the C++ target.

usage: cpp_build_bench.py [RESULTS_DIR [BUILD_DIR]]
The build tree (with smachac and the runtime library) is BUILD_DIR, else $SMACHAC_BENCH_BUILD
(bench/run.sh sets it), else build-bench. The script has the shape of bench_smach's
smach/generate: StateMachine containers of 49 leaves (every tenth container a Concurrence),
leaves printing userdata with userdata of their own, every fifth a CallbacksState with a C++
lambda (in a Concurrence each writes a key of its own); 20 containers, 1,000 states. Measured (wall time, best of 3 for smachac):
  smachac -target=cpp (program) and -emit=library;
  the generated translation unit's size in lines and bytes;
  `c++ -std=c++20 -c` of it at -O0 and -O2 ($CXX, default c++), and the link;
and the program must run to `outcome: done`.
"""
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CONTAINERS = 20
LEAVES = 49


def leaf(name, j, succ, concurrent):
    s = f"        - {name}:\n"
    if j % 5 == 4:
        key = f"speed_{j}" if concurrent else "speed"  # parallel children write their own key
        s += ("            template: CallbacksState\n            input_keys: [speed]\n"
              f"            output_keys: [{key}]\n"
              f"            callbacks: {{{key}: '`[](rt::UserData& ud) "
              "{ return ud.get<double>(\"speed\") * 1.01; }`'}\n")
    else:
        s += ("            template: PrintUserdataState\n            input_keys: [speed]\n"
              f"            userdata: {{note_{j}: step {j}}}\n")
    if not concurrent:
        s += f"            transitions: {{succeeded: {succ}}}\n"
    return s


def container(c, succ):
    concurrent = c % 10 == 9
    name = f"C{c}"
    s = (f"  - {name}:\n      template: {'Concurrence' if concurrent else 'StateMachine'}\n"
         "      outcomes: [ok]\n      input_keys: [speed]\n")
    if concurrent:
        s += f"      default_outcome: ok\n      outcome_map: {{ok: {{{name}_0: succeeded}}}}\n"
    else:
        s += "      output_keys: [speed]\n"
    s += f"      transitions: {{ok: {succ}}}\n      states:\n"
    for j in range(LEAVES):
        s += leaf(f"{name}_{j}", j, f"{name}_{j + 1}" if j + 1 < LEAVES else "ok", concurrent)
    return s


def script():
    s = "name: big\ntemplate: Base\noutcomes: [done]\nuserdata: {speed: 1.0}\nstates:\n"
    for c in range(CONTAINERS):
        s += container(c, f"C{c + 1}" if c + 1 < CONTAINERS else "done")
    return s


def children_cpu():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def timed(cmd, repeat=1):
    """(wall, cpu) seconds of the fastest of `repeat` runs; cpu is the child's user + system
    time, which a loaded machine inflates less than the wall time."""
    best = None
    for _ in range(repeat):
        start, cpu_start = time.perf_counter(), children_cpu()
        result = subprocess.run(cmd, capture_output=True, text=True)
        times = (time.perf_counter() - start, children_cpu() - cpu_start)
        if result.returncode != 0:
            sys.exit(f"cpp_build_bench: {' '.join(map(str, cmd))} failed:\n{result.stderr[:4000]}")
        best = times if best is None or times[0] < best[0] else best
    return best


def main():
    build = Path(sys.argv[2] if len(sys.argv) > 2 else
                 os.environ.get("SMACHAC_BENCH_BUILD", ROOT / "build-bench")).resolve()
    smachac = build / "tools" / "smachac" / "smachac"
    runtime = build / "stdlib" / "runtime" / "libsmachac_runtime.a"
    include = ROOT / "stdlib" / "runtime" / "include"
    cxx = os.environ.get("CXX", "c++")
    if not smachac.exists() or not runtime.exists():
        sys.exit(f"cpp_build_bench: build smachac and smachac_runtime in {build} first")
    with tempfile.TemporaryDirectory() as work:
        work = Path(work)
        (work / "big.yml").write_text(script())
        states = CONTAINERS * (LEAVES + 1)
        source = work / "big.cpp"
        t_smachac = timed([smachac, "-target=cpp", work / "big.yml", "-o", source], repeat=3)
        t_library = timed([smachac, "-target=cpp", "-emit=library", work / "big.yml",
                           "-o", work / "big_lib.cpp"], repeat=3)
        text = source.read_text()
        lines, size = text.count("\n"), len(text.encode())
        flags = [cxx, "-std=c++20", "-Wall", "-Wextra", "-Werror", "-I", include, "-c"]
        t_o0 = timed(flags + ["-O0", source, "-o", work / "big_o0.o"])
        t_o2 = timed(flags + ["-O2", source, "-o", work / "big_o2.o"])
        t_link = timed([cxx, work / "big_o2.o", runtime, "-pthread", "-o", work / "big"])
        run = subprocess.run([work / "big"], capture_output=True, text=True, timeout=120)
        if run.returncode != 0 or not run.stdout.endswith("outcome: done\n"):
            sys.exit(f"cpp_build_bench: the program failed:\n{run.stderr[:4000]}")
    prefix = f"cpp_build/{states}_states"
    print(f"{prefix}/smachac            {t_smachac[0] * 1000:10.1f} ms (wall, best of 3)")
    print(f"{prefix}/smachac_library    {t_library[0] * 1000:10.1f} ms (wall, best of 3)")
    print(f"{prefix}/source             {lines:10d} lines, {size} bytes")
    for name, (wall, cpu) in (("cxx_O0", t_o0), ("cxx_O2", t_o2), ("link", t_link)):
        print(f"{prefix}/{name:<18} {cpu:10.2f} s cpu, {wall:.2f} s wall ({cxx})")


if __name__ == "__main__":
    main()
