#!/usr/bin/env python3
"""End to end through C++: script -> `smachac -target=cpp` -> c++ -> run -> trace.

Usage: cpp_e2e.py SMACHAC CXX RUNTIME_LIB RUNTIME_INCLUDE WORK_DIR

Every case below is compiled to C++, built with `CXX -std=c++20 -Wall -Wextra -Werror` (plus
$SMACHAC_E2E_CXXFLAGS: the sanitizer flags of a sanitized tree) against the runtime's static
library (two builds at a time), run with `--seed=1 --trace=json`, and its
outcome and entered states compared with tests/golden/cpp/<name>.trace. Entered states are
printed as a tree (two spaces per level), each state's children in the order entered, except
those of a Concurrence (a container whose children never transition): those are sorted by
label, and so are the lines the program prints when it has one, so that the trace does not
depend on thread scheduling.
With SMACHAC_UPDATE_GOLDEN=1 the .trace files are rewritten instead (then review them).
"""
import concurrent.futures
import difflib
import json
import os
import shlex
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SMACH = os.path.join(ROOT, "tests", "golden", "smach")
CPP = os.path.join(ROOT, "tests", "golden", "cpp")

# Golden SMACH scripts that use only core templates and no Python code.
SMACH_CASES = ["comments", "concurrence_userdata", "files", "introspection_plain_base",
               "log_and_sleep", "random_outcomes", "state_keys_override", "userdata_levels"]
# Why the other SMACH golden scripts are not built as C++.
SKIPPED = {
    "callbacks": "custom template CallbacksFoo (Python) and Python lambdas",
    "concurrence": "custom template ParamState (Python)",
    "concurrence_whole": "custom template ParamState (Python)",
    "conditional_outcome": "Python lambda callbacks (C++ version: cpp/conditional.yml)",
    "custom_base": "custom Python base template",
    "custom_templates": "custom template Greeter (Python)",
    "expr_callbacks": "built as cpp/expr_callbacks.yml, the same script",
    "nesting_end": "custom template ParamState (Python)",
    "nesting_start": "custom template ParamState (Python)",
    "nesting_whole": "custom template ParamState (Python)",
    "params_lookups": "custom template ParamState (Python)",
    "python_text_unicode": "a Python lambda callback checks Python's str()",
    "ros_base": "ROS templates (ROSBase)",
    "ros_introspection": "ROS templates (ROSBase)",
    "ros_states": "ROS templates",
    "ros_parsers": "ROS templates (message parsers)",
    "ros_publish_observer": "ROS templates (MsgPublisherObserver)",
    "ros_rosbag_api": "ROS templates (RecordROSBagState)",
    "ros_rosbag_cli": "ROS templates (RecordROSBagState)",
    "ros_transform_msg": "ROS templates (TransformMsgState)",
    "ros_code_like_values": "ROS templates",
    "sequence": "a Python lambda callback (C++ version: cpp/sequence.yml)",
    "shorthand": "custom Python templates",
    "sub_script_params_leak": "custom template ParamState (Python)",
    "sub_script_twice": "custom template ParamState (Python) in the sub-script",
    "template_globals": "custom templates Painter and ShowColour (Python)",
    "templates_2017": "SMACHA 2017 custom templates (Python)",
    "userdata_values": "Python expressions and names as userdata values",
}


def cpp_cases():
    """The runnable C++ golden cases: tests/golden/cpp/*.yml whose ARGS target cpp, not fail_."""
    cases = []
    for name in sorted(os.listdir(CPP)):
        if not name.endswith(".yml") or name.startswith("fail_"):
            continue
        with open(os.path.join(CPP, name), encoding="utf-8") as f:
            if "# E2E: no" in f.read():
                continue
        cases.append(("cpp", name[:-4]))
    return cases


def case_args(path):
    """The smachac arguments of a golden case (its `# ARGS:` minus the target)."""
    args = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            if not line.startswith("#"):
                break
            if line.startswith("# ARGS:"):
                args += [a for a in shlex.split(line[len("# ARGS:"):])
                         if not a.lstrip("-").startswith("target") and a not in ("-c", "-i")]
    return args


def generate(smachac, area, name, work):
    case_dir = SMACH if area == "smach" else CPP
    out = os.path.join(work, f"{area}_{name}.cpp")
    cmd = [smachac, "-target=cpp", *case_args(os.path.join(case_dir, name + ".yml")),
           name + ".yml", "-o", out]
    result = subprocess.run(cmd, cwd=case_dir, capture_output=True, text=True)
    if result.returncode != 0:
        return None, f"smachac failed:\n{result.stderr}"
    return out, ""


def build(cxx, lib, include, source):
    exe = source[:-4]
    # A sanitized build's runtime needs the same instrumentation in the program (see CMake).
    sanitize = shlex.split(os.environ.get("SMACHAC_E2E_CXXFLAGS", ""))
    cmd = [cxx, "-std=c++20", "-Wall", "-Wextra", "-Werror", "-O0", *sanitize, "-I", include,
           source, lib, "-pthread", "-o", exe]
    result = subprocess.run(cmd, capture_output=True, text=True)
    if result.returncode != 0:
        return None, f"{' '.join(cmd)}\n{result.stderr}"
    return exe, ""


def parent_of(path):
    return path.rsplit("/", 1)[0] if "/" in path else ""


def tree(events):
    """The entered states as indented lines, and whether a Concurrence ran."""
    nodes = {"": {"label": "", "children": []}}
    transitioned = {e["state"] for e in events if e["event"] == "transition"}
    for e in events:
        path = e.get("state", "")
        if e["event"] == "enter" and path:
            node = {"label": path.rsplit("/", 1)[-1], "children": [], "path": path}
            nodes.setdefault(parent_of(path), nodes[""])["children"].append(node)
            nodes[path] = node
    lines, concurrent = [], False

    def walk(node, depth):
        nonlocal concurrent
        children = node["children"]
        if children and not any(c["path"] in transitioned for c in children):
            concurrent = True
            children = sorted(children, key=lambda n: n["label"])
        for child in children:
            lines.append("  " * depth + child["label"])
            walk(child, depth + 1)

    walk(nodes[""], 0)
    return lines, concurrent


def run(exe):
    result = subprocess.run([exe, "--seed=1", "--trace=json"], capture_output=True, text=True,
                            timeout=60)
    events = []
    for line in result.stderr.splitlines():
        if line.startswith("{"):
            events.append(json.loads(line))
    lines, concurrent = tree(events)
    printed = result.stdout.splitlines(True)
    if concurrent:
        printed.sort()
    text = f"exit: {result.returncode}\n" + "".join(printed)
    return text + "entered:\n" + "".join(f"  {line}\n" for line in lines)


def check(area, name, actual, update):
    path = os.path.join(CPP, f"{name}.trace" if area == "cpp" else f"smach_{name}.trace")
    if update:
        with open(path, "w", encoding="utf-8") as f:
            f.write(actual)
        return True
    expected = open(path, encoding="utf-8").read() if os.path.exists(path) else ""
    if expected == actual:
        return True
    sys.stdout.write("".join(difflib.unified_diff(expected.splitlines(True),
                                                  actual.splitlines(True),
                                                  "expected " + os.path.basename(path), "actual")))
    return False


def one_case(args, area, name):
    smachac, cxx, lib, include, work = args
    source, error = generate(smachac, area, name, work)
    if not source:
        return area, name, None, error
    exe, error = build(cxx, lib, include, source)
    if not exe:
        return area, name, None, error
    return area, name, run(exe), ""


def main():
    args = [os.path.abspath(a) if i != 1 else a for i, a in enumerate(sys.argv[1:6])]
    os.makedirs(args[4], exist_ok=True)
    update = os.environ.get("SMACHAC_UPDATE_GOLDEN") == "1"
    cases = [("smach", n) for n in SMACH_CASES] + cpp_cases()
    listed = set(SMACH_CASES) | set(SKIPPED)
    unlisted = [n[:-4] for n in os.listdir(SMACH) if n.endswith(".yml")
                and not n.startswith("fail_") and n[:-4] not in listed]
    ok = not unlisted
    if unlisted:
        print("SMACH golden scripts neither built nor skipped:", ", ".join(sorted(unlisted)))
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        for area, name, actual, error in pool.map(lambda c: one_case(args, *c), cases):
            if actual is None:
                print(f"FAIL {area}/{name}: {error}")
                ok = False
            elif check(area, name, actual, update):
                print(f"ok   {area}/{name}")
            else:
                print(f"FAIL {area}/{name}: trace differs")
                ok = False
    for name, why in sorted(SKIPPED.items()):
        print(f"skip smach/{name}: {why}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
