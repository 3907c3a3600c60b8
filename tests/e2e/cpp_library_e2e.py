#!/usr/bin/env python3
"""End to end through `smachac -target=cpp -emit=library`: two libraries in one program.

Usage: cpp_library_e2e.py SMACHAC CXX RUNTIME_LIB RUNTIME_INCLUDE WORK_DIR

cpp_library/counter.yml is generated with `-o DIR` (files named after the script) and
cpp_library/light.yml with `-o DIR/smachac-e2e-light.cpp` (namespace smachac_e2e_light); both
use the custom template cpp_library/templates/Step.tpl.cpp, whose class and helper function
have the same names and different bodies in the two libraries. Each source is compiled on its
own, then cpp_library/two_machines.cpp, all with `-std=c++20 -Wall -Wextra -Werror`; the
program is linked with the runtime and its output compared with EXPECTED. Also checked:
-emit=program writes what no -emit writes, and a failed -emit=library run writes nothing and
leaves existing files as they were, and -o file names become the header's name and the
namespace (NAMES) and the depfile's target. $SMACHAC_E2E_CXXFLAGS is added to the compiler flags.
"""
import filecmp
import os
import shlex
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CASES = os.path.join(HERE, "cpp_library")
EXPECTED = ("counter: done, n = 3 (outcomes: done; userdata: limit n)\n"
            "light: go, n = 10, colour = green (outcomes: go)\n"
            "a new counter: n = 0\n")
# Extra flags for compiling and linking (a sanitizer tree's runtime needs its sanitizers).
EXTRA_FLAGS = shlex.split(os.environ.get("SMACHAC_E2E_CXXFLAGS", ""))
CXXFLAGS = ["-std=c++20", "-Wall", "-Wextra", "-Werror", "-O0", *EXTRA_FLAGS]


def run(cmd, **kwargs):
    result = subprocess.run(cmd, capture_output=True, text=True, **kwargs)
    if result.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} exited {result.returncode}:\n{result.stderr}")
    return result


def smachac(tool, *args):
    return run([tool, "-target=cpp", "-I", os.path.join(CASES, "templates"), *args], cwd=CASES)


def generate(tool, work):
    smachac(tool, "-emit=library", "counter.yml", "-o", work)
    smachac(tool, "-emit=library", "light.yml", "-o", os.path.join(work, "smachac-e2e-light.cpp"))
    names = sorted(os.listdir(work))
    expected = ["smachac-e2e-light.cpp", "smachac-e2e-light.h", "smachac_e2e_counter.cpp",
                "smachac_e2e_counter.h"]
    if names != expected:
        raise RuntimeError(f"generated {names}, expected {expected}")


def build_and_run(cxx, lib, include, work):
    objects = []
    sources = [os.path.join(work, "smachac_e2e_counter.cpp"),
               os.path.join(work, "smachac-e2e-light.cpp"), os.path.join(CASES, "two_machines.cpp")]
    for source in sources:
        obj = os.path.join(work, os.path.basename(source) + ".o")
        run([cxx, *CXXFLAGS, "-I", include, "-I", work, "-c", source, "-o", obj])
        objects.append(obj)
    exe = os.path.join(work, "two_machines")
    run([cxx, *EXTRA_FLAGS, *objects, lib, "-pthread", "-o", exe])
    output = run([exe], timeout=60).stdout
    if output != EXPECTED:
        raise RuntimeError(f"the program printed:\n{output}expected:\n{EXPECTED}")


def program_unchanged(tool, work):
    default = os.path.join(work, "default.cpp")
    program = os.path.join(work, "program.cpp")
    smachac(tool, "counter.yml", "-o", default)
    smachac(tool, "-emit=program", "counter.yml", "-o", program)
    if not filecmp.cmp(default, program, shallow=False):
        raise RuntimeError("-emit=program differs from the default output")


def failure_writes_nothing(tool, work):
    os.makedirs(work)
    kept = {"kept.h": "// the old header\n", "kept.cpp": "// the old source\n"}
    for name, text in kept.items():
        with open(os.path.join(work, name), "w", encoding="utf-8") as f:
            f.write(text)
    bad = os.path.join(work, "bad.yml")
    with open(bad, "w", encoding="utf-8") as f:
        f.write("name: bad\ntemplate: Base\noutcomes: [done]\nstates:\n"
                "  - S:\n      template: CallbacksState\n      output_keys: [n]\n"
                "      callbacks: {n: '`lambda ud: 1`'}\n      transitions: {succeeded: done}\n")
    result = subprocess.run([tool, "-target=cpp", "-emit=library", bad, "-o",
                             os.path.join(work, "kept.cpp")], capture_output=True, text=True)
    if result.returncode != 1 or "python-code-in-cpp" not in result.stderr:
        raise RuntimeError(f"expected exit 1 and python-code-in-cpp, got {result.returncode}:\n"
                           f"{result.stderr}")
    left = {}
    for name in sorted(os.listdir(work)):
        if name != "bad.yml":
            with open(os.path.join(work, name), encoding="utf-8") as f:
                left[name] = f.read()
    if left != kept:
        raise RuntimeError(f"a failed run changed the output directory: {left}")


# -o file name -> (header file name, namespace).
NAMES = {"9-lives.cpp": ("9-lives.h", "sm_9_lives"), "int.cc": ("int.h", "int_"),
         "rt.cxx": ("rt.h", "rt_"), "__a..b.cpp": ("__a..b.h", "sm_a_b"),
         "Traffic Light.cpp": ("Traffic Light.h", "Traffic_Light")}


def names_become_namespaces(tool, work):
    os.makedirs(work)
    for output, (header, namespace) in NAMES.items():
        depfile = os.path.join(work, "out.d")
        smachac(tool, "-emit=library", "counter.yml", "-o", os.path.join(work, output),
                f"--depfile={depfile}")
        with open(os.path.join(work, header), encoding="utf-8") as f:
            if f"\nnamespace {namespace} {{\n" not in f.read():
                raise RuntimeError(f"{header}: no `namespace {namespace} {{`")
        with open(os.path.join(work, output), encoding="utf-8") as f:
            if f'#include "{header}"' not in f.read():
                raise RuntimeError(f"{output} does not include {header}")
        with open(depfile, encoding="utf-8") as f:
            target = f.read().split(":", 1)[0]
        if target != os.path.join(work, output).replace(" ", "\\ "):
            raise RuntimeError(f"the depfile's target is `{target}`")


def main():
    tool, cxx, lib, include, work = sys.argv[1:6]
    tool, lib, include, work = (os.path.abspath(p) for p in (tool, lib, include, work))
    subprocess.run(["rm", "-rf", work], check=True)
    os.makedirs(os.path.join(work, "libraries"))
    checks = [
        ("two libraries in one program",
         lambda: (generate(tool, os.path.join(work, "libraries")),
                  build_and_run(cxx, lib, include, os.path.join(work, "libraries")))),
        ("-emit=program is the default", lambda: program_unchanged(tool, work)),
        ("file names become namespaces",
         lambda: names_become_namespaces(tool, os.path.join(work, "names"))),
        ("a failed run writes nothing", lambda: failure_writes_nothing(tool,
                                                                       os.path.join(work, "fail"))),
    ]
    ok = True
    for name, check in checks:
        try:
            check()
            print(f"ok   {name}")
        except (RuntimeError, subprocess.TimeoutExpired) as e:
            print(f"FAIL {name}: {e}")
            ok = False
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
