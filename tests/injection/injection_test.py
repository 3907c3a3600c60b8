#!/usr/bin/env python3
"""The injection corpus: hostile names and strings reach every target intact.

Usage: injection_test.py SMACHAC CXX RUNTIME_LIB RUNTIME_INCLUDE WORK_DIR

Every tests/injection/<name>.yml is compiled for each target its `# TARGETS:` line lists (with
the arguments of its `# ARGS:` line) and checked against the script's own values, read with
PyYAML (`!str` as a plain string):
  smach, flexbe  every generated module compiles (py_compile); the userdata assignments
                 (`<container>.userdata.<key> = <expr>`) evaluate to exactly the script's
                 values; the names passed to `.add(...)` are exactly the script's state names;
                 every outcome, transition, template argument and callback named by a string
                 is a string constant of the module, and its transitions are
                 `transitions=` entries
  cpp            the program builds with -Wall -Wextra -Werror (tests/e2e/cpp_e2e.py), runs,
                 enters only the script's states, takes only the script's transitions, prints
                 (PrintUserdataState) exactly the script's values, and ends with a root outcome
  dot            Graphviz renders it (`dot -Tsvg`)
  json           it parses; names, outcomes, transitions and userdata equal the script's
Userdata keys are unique in a script, so a key names one value wherever it is set.
"""
import ast
import json
import math
import os
import py_compile
import shlex
import subprocess
import sys

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "e2e"))
import cpp_e2e  # noqa: E402  (the C++ build of the e2e tests)

STATE_KEYS = {"template", "outcomes", "transitions", "remapping", "userdata", "input_keys",
              "output_keys", "callbacks", "states", "outcome_map", "default_outcome", "params"}


class Loader(yaml.SafeLoader):
    """PyYAML's safe loader with smachac's `!str` tag (a plain string)."""


Loader.add_constructor("!str", lambda loader, node: loader.construct_scalar(node))


# ---------------------------------------------------------------------------------------------
# The script's side


class Script:
    """What the checks compare with: states by path, userdata by key, outcomes, transitions."""

    def __init__(self, path):
        self.path = path
        with open(path, encoding="utf-8") as f:
            text = f.read()
        self.root = yaml.load(text, Loader=Loader)
        self.targets, self.args = header(text)
        self.states = {}  # "A/B" -> body
        self.userdata = {}
        self.collect_userdata(self.root)
        self.walk(self.root, "")

    def walk(self, body, prefix):
        for entry in body.get("states", []):
            (name, child), = entry.items()
            path = prefix + name
            self.states[path] = child
            self.collect_userdata(child)
            self.walk(child, path + "/")

    def collect_userdata(self, body):
        for key, value in (body.get("userdata") or {}).items():
            if key in self.userdata:
                raise ValueError(f"{self.path}: userdata key {key!r} set twice")
            self.userdata[key] = value

    def state_names(self):
        names = []
        for entry_list in [self.root] + list(self.states.values()):
            for entry in entry_list.get("states", []):
                names.extend(entry.keys())
        return names

    def bodies(self):
        return [self.root] + list(self.states.values())

    def outcomes(self):
        return {o for body in self.bodies() for o in body.get("outcomes", [])}

    def transitions(self):
        return {(o, t) for body in self.bodies() for o, t in body.get("transitions", {}).items()}

    def arguments(self):
        """Template arguments and callbacks named by a string (not backtick code)."""
        pairs = {(k, v) for body in self.states.values() for k, v in body.items()
                 if k not in STATE_KEYS and isinstance(v, str)}
        for body in self.states.values():
            pairs |= {(k, v) for k, v in (body.get("callbacks") or {}).items()
                      if isinstance(v, str) and not v.startswith("`")}
        return pairs


def header(text):
    targets, args = [], []
    for line in text.splitlines():
        if not line.startswith("#"):
            break
        if line.startswith("# TARGETS:"):
            targets += line[len("# TARGETS:"):].split()
        if line.startswith("# ARGS:"):
            args += shlex.split(line[len("# ARGS:"):])
    return targets, args


def same(a, b):
    """Exact equality of values: types too (1 is not 1.0 nor True), NaN equals NaN."""
    if type(a) is not type(b):
        return False
    if isinstance(a, float):
        return (math.isnan(a) and math.isnan(b)) or a == b
    if isinstance(a, list):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    return a == b


def evaluate(node, runtime=False):
    """A literal expression's value, float('nan') and float('inf') included; with `runtime`,
    also the bare nan and inf of the C++ runtime's repr (no Python expressions)."""
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "float" \
            and len(node.args) == 1 and isinstance(node.args[0], ast.Constant):
        return float(node.args[0].value)
    if runtime and isinstance(node, ast.Name) and node.id in ("nan", "inf"):
        return float(node.id)
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
        value = evaluate(node.operand, runtime)
        return -value if isinstance(node.op, ast.USub) else value
    if isinstance(node, ast.List):
        return [evaluate(e, runtime) for e in node.elts]
    if isinstance(node, ast.Dict):
        return {evaluate(k, runtime): evaluate(v, runtime) for k, v in zip(node.keys, node.values)}
    return ast.literal_eval(node)


def compare_userdata(expected, actual, errors):
    for key in sorted(set(expected) | set(actual)):
        if key not in actual:
            errors.append(f"userdata {key!r} is missing")
        elif key not in expected:
            errors.append(f"userdata {key!r} is not in the script")
        elif not same(expected[key], actual[key]):
            errors.append(f"userdata {key!r}: expected {expected[key]!r}, got {actual[key]!r}")


# ---------------------------------------------------------------------------------------------
# Python targets


class PythonModule:
    """What a generated module holds: userdata assignments, added states, string constants."""

    def __init__(self, source, errors):
        self.userdata, self.added, self.strings, self.transitions = {}, [], set(), set()
        tree = ast.parse(source)
        for node in ast.walk(tree):
            if isinstance(node, ast.Constant) and isinstance(node.value, str):
                self.strings.add(node.value)
            elif isinstance(node, ast.Assign):
                self.assignment(node, errors)
            elif isinstance(node, ast.Call):
                self.call(node)

    def assignment(self, node, errors):
        target = node.targets[0]
        if not (isinstance(target, ast.Attribute) and isinstance(target.value, ast.Attribute)
                and target.value.attr == "userdata"):
            return
        try:
            self.userdata[target.attr] = evaluate(node.value)
        except ValueError:
            errors.append(f"userdata {target.attr!r} is code: {ast.unparse(node.value)}")

    def call(self, node):
        if isinstance(node.func, ast.Attribute) and node.func.attr == "add" and node.args and \
                isinstance(node.args[0], ast.Constant):
            self.added.append(node.args[0].value)
        for keyword in node.keywords:
            if keyword.arg == "transitions" and isinstance(keyword.value, ast.Dict):
                for k, v in zip(keyword.value.keys, keyword.value.values):
                    if isinstance(k, ast.Constant) and isinstance(v, ast.Constant):
                        self.transitions.add((k.value, v.value))


def check_python_modules(script, files, errors):
    modules = []
    for path in files:
        try:
            py_compile.compile(path, cfile=path + "c", doraise=True)
        except py_compile.PyCompileError as e:
            errors.append(f"{os.path.basename(path)} does not compile: {e.msg.strip()}")
            return
        with open(path, encoding="utf-8") as f:
            modules.append(PythonModule(f.read(), errors))
    userdata = {k: v for m in modules for k, v in m.userdata.items()}
    compare_userdata(script.userdata, userdata, errors)
    added = sorted(name for m in modules for name in m.added)
    if added != sorted(script.state_names()):
        errors.append(f"added states {added!r} are not the script's {script.state_names()!r}")
    strings = set().union(*(m.strings for m in modules))
    wanted = script.outcomes() | {t for pair in script.transitions() for t in pair}
    wanted |= {v for _, v in script.arguments()}
    for text in sorted(wanted - strings):
        errors.append(f"{text!r} is no string constant of the generated code")
    transitions = set().union(*(m.transitions for m in modules))
    for pair in sorted(script.transitions() - transitions):
        errors.append(f"transition {pair!r} is not written")


def run_smachac(smachac, target, script, output):
    cmd = [smachac, f"-target={target}", *script.args, os.path.basename(script.path), "-o", output]
    result = subprocess.run(cmd, cwd=os.path.dirname(script.path), capture_output=True)
    if result.returncode != 0:
        return result.stderr.decode("utf-8", "replace")
    return None


def check_smach(ctx, script, work, errors):
    out = os.path.join(work, "smach.py")
    failure = run_smachac(ctx["smachac"], "smach", script, out)
    if failure:
        errors.append(f"smachac failed:\n{failure}")
        return
    check_python_modules(script, [out], errors)


def check_flexbe(ctx, script, work, errors):
    out = os.path.join(work, "flexbe")
    os.makedirs(out, exist_ok=True)
    for name in os.listdir(out):
        os.remove(os.path.join(out, name))
    failure = run_smachac(ctx["smachac"], "flexbe", script, out)
    if failure:
        errors.append(f"smachac failed:\n{failure}")
        return
    files = sorted(os.path.join(out, n) for n in os.listdir(out) if n.endswith(".py"))
    check_python_modules(script, files, errors)


# ---------------------------------------------------------------------------------------------
# C++


def read_printed(stdout, script, entered, errors):
    """Checks the PrintUserdataState lines of the entered states, in order; returns the rest."""
    at = 0
    for path in entered:
        body = script.states.get(path, {})
        if body.get("template") != "PrintUserdataState":
            continue
        for key in body.get("input_keys", []):
            prefix = f"userdata.{key}: "
            if not stdout.startswith(prefix, at):
                errors.append(f"expected {prefix!r} at {stdout[at:at + 60]!r}")
                return None
            at += len(prefix)
            expected = script.userdata[key]
            if isinstance(expected, str):
                printed = stdout[at:at + len(expected)]
                at += len(expected)
            else:
                end = stdout.find("\n", at)
                text = stdout[at:end]
                at = end
                printed = evaluate(ast.parse(text, mode="eval").body, runtime=True)
            if not same(expected, printed) or not stdout.startswith("\n", at):
                errors.append(f"{path}: {key!r} printed {printed!r}, expected {expected!r}")
                return None
            at += 1
    return stdout[at:]


def check_trace(script, events, errors):
    entered = [e["state"] for e in events if e["event"] == "enter" and e["state"]]
    for path in entered:
        if path not in script.states:
            errors.append(f"entered state {path!r} is not in the script")
    for e in events:
        if e["event"] != "transition":
            continue
        declared = script.states.get(e["state"], {}).get("transitions", {})
        if declared.get(e["outcome"]) != e["target"]:
            errors.append(f"transition {e['state']!r}: {e['outcome']!r} -> {e['target']!r} "
                          "is not in the script")
    return entered


def check_cpp(ctx, script, work, errors):
    source = os.path.join(work, "machine.cpp")
    failure = run_smachac(ctx["smachac"], "cpp", script, source)
    if failure:
        errors.append(f"smachac failed:\n{failure}")
        return
    exe, failure = cpp_e2e.build(ctx["cxx"], ctx["lib"], ctx["include"], source)
    if not exe:
        errors.append(f"the C++ program does not build:\n{failure}")
        return
    result = subprocess.run([exe, "--seed=1", "--trace=json"], capture_output=True, timeout=60)
    stdout = result.stdout.decode("utf-8")
    events = [json.loads(line) for line in result.stderr.decode("utf-8").splitlines()
              if line.startswith("{")]
    if result.returncode != 0:
        errors.append(f"the program exits {result.returncode}")
    entered = check_trace(script, events, errors)
    rest = read_printed(stdout, script, entered, errors)
    ends = [e.get("outcome") for e in events if e["event"] == "exit" and e["state"] == ""]
    if rest is not None and (len(ends) != 1 or rest != f"outcome: {ends[0]}\n"
                             or ends[0] not in script.root["outcomes"]):
        errors.append(f"the program ends with {rest!r}, its root with {ends!r}")


# ---------------------------------------------------------------------------------------------
# dot, json


def check_dot(ctx, script, work, errors):
    out = os.path.join(work, "graph.dot")
    failure = run_smachac(ctx["smachac"], "dot", script, out)
    if failure:
        errors.append(f"smachac failed:\n{failure}")
        return
    result = subprocess.run(["dot", "-Tsvg", "-o", os.devnull, out], capture_output=True, text=True)
    if result.returncode != 0 or result.stderr:
        errors.append(f"dot -Tsvg rejects it: {result.stderr.strip()}")


def json_value(value):
    if isinstance(value, dict) and set(value) == {"float"}:
        return float(value["float"])
    if isinstance(value, list):
        return [json_value(v) for v in value]
    if isinstance(value, dict):
        return {k: json_value(v) for k, v in value.items()}
    return value


def json_states(state, prefix, found):
    for child in state.get("states", []):
        path = prefix + child["name"]
        found[path] = child
        json_states(child, path + "/", found)


def check_json_state(body, state, where, errors):
    outcomes = [o["text"] for o in state.get("outcomes", [])]
    if "outcomes" in body and outcomes != body["outcomes"]:
        errors.append(f"{where}: outcomes {outcomes!r}, expected {body['outcomes']!r}")
    transitions = {t["outcome"]["text"]: t["target"]["text"] for t in state.get("transitions", [])}
    if transitions != body.get("transitions", {}):
        errors.append(f"{where}: transitions {transitions!r}, expected {body.get('transitions')!r}")


def check_json(ctx, script, work, errors):
    out = os.path.join(work, "ir.json")
    failure = run_smachac(ctx["smachac"], "json", script, out)
    if failure:
        errors.append(f"smachac failed:\n{failure}")
        return
    with open(out, encoding="utf-8") as f:
        root = json.load(f)["root"]
    found = {}
    json_states(root, "", found)
    if sorted(found) != sorted(script.states):
        errors.append(f"states {sorted(found)!r}, expected {sorted(script.states)!r}")
        return
    check_json_state(script.root, root, "root", errors)
    userdata = {}
    for state in [root] + list(found.values()):
        for entry in state.get("userdata", []):
            userdata[entry["key"]["text"]] = json_value(entry["value"]["value"])
    for path, state in found.items():
        check_json_state(script.states[path], state, path, errors)
    compare_userdata(script.userdata, userdata, errors)


CHECKS = {"smach": check_smach, "flexbe": check_flexbe, "cpp": check_cpp, "dot": check_dot,
          "json": check_json}


def main():
    smachac, cxx, lib, include, work = sys.argv[1:6]
    ctx = {"smachac": os.path.abspath(smachac), "cxx": cxx, "lib": os.path.abspath(lib),
           "include": os.path.abspath(include)}
    scripts = sorted(n for n in os.listdir(HERE) if n.endswith(".yml"))
    ok, runs = True, 0
    for name in scripts:
        script = Script(os.path.join(HERE, name))
        if not script.targets:
            print(f"FAIL {name}: no `# TARGETS:` line")
            ok = False
        for target in script.targets:
            case_work = os.path.abspath(os.path.join(work, name[:-4], target))
            os.makedirs(case_work, exist_ok=True)
            errors = []
            CHECKS[target](ctx, script, case_work, errors)
            runs += 1
            print(f"{'ok  ' if not errors else 'FAIL'} {name} -> {target}")
            for error in errors:
                print(f"     {error}")
            ok = ok and not errors
    print(f"{runs} compilations of {len(scripts)} scripts")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
