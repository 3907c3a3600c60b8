#!/usr/bin/env python3
"""Writes hot_symbols.txt: the functions a cold compile runs, for lld's
--symbol-ordering-file (top-level CMakeLists.txt), which places the code sections holding
them first and in this order, so that a compile faults in fewer pages of code.

    tools/smachac/static/hot_symbols.py BUILD_DIR [SMACHA_ROOT]

Runs BUILD_DIR's smachac under callgrind (symbols not demangled) on `--version` and on every
script of bench/compare's corpus (SMACHA's public test scripts; SMACHA_ROOT defaults to the
one bench/compare finds, anchors.smacha_root()), and lists the functions that ran: first
those that ran in the most of these processes, among equals the most used (own instructions
over all runs) first. What a page fault maps is a window of code, so the functions nearly
every compile runs are packed together, however few instructions some of them take, and
those of rarer scripts follow. The binary is compiled with a section per function
(top-level CMakeLists.txt), so a name it defines more than once (a local clone like
`...constprop.0` in many files) moves only those functions. The list goes stale as the code
changes; a name it lacks is only placed where the linker would put it anyway.
"""
import collections
import pathlib
import re
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[2] / "bench" / "compare"))
import anchors  # noqa: E402  (bench/compare/anchors.py)
import corpus  # noqa: E402  (bench/compare/corpus.py)


def command_lines(smachac, root, out):
    yield [smachac, "--version"]
    for script in corpus.scripts(root):
        argv = [str(a) for a in script.smachac_argv(smachac, out)]
        errors = subprocess.run(argv, capture_output=True, text=True).stderr
        kinds = sorted(set(re.findall(r"error: .*\[([a-z0-9-]+)\]$", errors, re.M)))
        yield argv[:3] + ["-Wno-error=" + k for k in kinds] + argv[3:]


def own_costs(profile, total, runs):
    """Adds each function's own instructions in a callgrind profile to `total`, and one to
    `runs` for each function that ran in it."""
    ran = set()
    names, current, after_call = {}, None, False
    for line in open(profile, errors="replace"):
        if line.startswith(("fn=", "cfn=")):
            match = re.match(r"c?fn=\((\d+)\)(?: (.*))?", line.strip())
            if match and match.group(2):
                names[match.group(1)] = match.group(2)
            if line.startswith("fn="):
                current = names.get(match.group(1)) if match else None
        elif line.startswith("calls="):
            after_call = True  # the next cost line is the call's, not the function's own
        elif line[:1].isdigit() or line[:1] in "+-*":
            fields = line.split()
            if not after_call and current and len(fields) >= 2 and fields[1].isdigit():
                total[current.split("'")[0]] += int(fields[1])
                ran.add(current.split("'")[0])
            after_call = False
    runs.update(ran)


def main():
    build = pathlib.Path(sys.argv[1]).resolve()
    root = sys.argv[2] if len(sys.argv) > 2 else anchors.smacha_root()
    if root is None:
        sys.exit("hot_symbols: SMACHA is missing: " + anchors.checkout_path("smacha")[1])
    root = str(root)
    smachac = str(build / "tools/smachac/smachac")
    total, runs = collections.Counter(), collections.Counter()
    with tempfile.TemporaryDirectory() as tmp:
        for i, argv in enumerate(command_lines(smachac, root, tmp + "/out.py")):
            profile = "%s/%d.cg" % (tmp, i)
            subprocess.run(["valgrind", "--tool=callgrind", "--demangle=no",
                            "--callgrind-out-file=" + profile] + argv,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            own_costs(profile, total, runs)
    named = [name for name, cost in total.items() if cost > 0 and not name.startswith(("(", "0x"))]
    hot = sorted(named, key=lambda name: (-runs[name], -total[name], name))
    (HERE / "hot_symbols.txt").write_text("\n".join(hot) + "\n")
    print("%d functions written to %s" % (len(hot), HERE / "hot_symbols.txt"))


if __name__ == "__main__":
    main()
