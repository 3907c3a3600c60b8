#!/usr/bin/env python3
"""Checks editors/schema/smacha-script.schema.json (the JSON Schema for yaml-language-server).

  schema_test.py SOURCE_DIR

* The schema is a valid draft-07 schema.
* It cannot drift from the compiler: its shorthand properties are exactly the table of
  frontend/shorthand.cpp (every shorthand in a state; at the root those whose longhand is a
  root key), its root keys those of frontend/root_keys.cpp and its state keys the core keys of
  frontend/state_builder.cpp, all parsed from the C++ source.
* Every script the compiler accepts validates: every examples/**/*.yml, every golden case that
  exits 0 (no `fail_` prefix, no `# EXIT:`) and holds a script, and every sub-script one of
  them includes (found as the compiler finds it: the including file's directory, then the
  case's `-S` directories; NAME, then NAME.yml). A golden case with an `unknown-root-key`
  warning (in its expected stderr, or turned off in its ARGS) must be rejected for that key
  alone instead.
* Broken scripts are rejected, each with exactly one error at the expected schema path.

Needs Debian's python3-jsonschema and python3-yaml. YAML is read with the YAML 1.2 core
schema, as smachac and yaml-language-server read it (`yes` stays a string), and the tags
`!expr` and `!str` as strings.
"""
import glob
import json
import os
import re
import shlex
import sys

import jsonschema
import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "harness"))
from yaml12 import Yaml12Loader  # noqa: E402

SCHEMA = "editors/schema/smacha-script.schema.json"
STATE_PATH = "else/properties/states/allOf/0/items/additionalProperties"


def load_yaml(path):
    with open(path, encoding="utf-8") as f:
        return yaml.load(f, Loader=Yaml12Loader)


class Failures:
    def __init__(self):
        self.messages = []
        self.checks = 0

    def check(self, ok, message):
        self.checks += 1
        if not ok:
            self.messages.append(message)
            print("FAIL: " + message)


def slash(path):
    return "/".join(str(p) for p in path)


# --- the compiler's key tables, read from its source --------------------------------------

def cpp_shorthands(source_dir):
    text = open(os.path.join(source_dir, "frontend/shorthand.cpp"), encoding="utf-8").read()
    m = re.search(r"std::array<std::pair<std::string_view, std::string_view>,\s*(\d+)>\s*"
                  r"kShorthands\s*=\s*\{\{(.*?)\}\};", text, re.S)
    if not m:
        raise SystemExit("schema_test: kShorthands not found in frontend/shorthand.cpp")
    pairs = re.findall(r'\{\s*"([^"]+)"\s*,\s*"([^"]+)"\s*\}', m.group(2))
    if len(pairs) != int(m.group(1)):
        raise SystemExit("schema_test: read %d shorthands, the array holds %s"
                         % (len(pairs), m.group(1)))
    return dict(pairs)


def keys_in_source(source_dir, path, function, pattern, key):
    """The quoted keys (`key`, a regex with one group) inside what `pattern` matches in `path`:
    the frontend's own table of the keys a function accepts."""
    text = open(os.path.join(source_dir, path), encoding="utf-8").read()
    m = re.search(pattern, text, re.S)
    if not m:
        raise SystemExit("schema_test: %s not found in %s" % (function, path))
    return set(re.findall(key, m.group(0)))


def cpp_root_keys(source_dir):
    return keys_in_source(source_dir, "frontend/root_keys.cpp", "knownRootKeys",
                          r"knownRootKeys\(\)\s*\{.*?kKeys\s*=\s*\{.*?\};", r'"([^"]+)"')


def cpp_state_keys(source_dir):
    return keys_in_source(source_dir, "frontend/state_builder.cpp", "readCoreKey",
                          r"bool readCoreKey\(.*?\n\}\n", r'key == "([^"]+)"')


def check_tables(schema, source_dir, failures):
    failed_before = len(failures.messages)
    shorthands = cpp_shorthands(source_dir)
    levels = {"root": (schema["definitions"]["script"]["properties"], cpp_root_keys(source_dir)),
              "state": (schema["definitions"]["state"]["properties"], cpp_state_keys(source_dir))}
    for level, (props, keys) in levels.items():
        longhands = {k for k, v in props.items() if "x-smachac-shorthand-for" not in v}
        failures.check(longhands == keys,
                       "%s keys: schema %s, compiler %s" % (level, sorted(longhands), sorted(keys)))
        schema_short = {k: v["x-smachac-shorthand-for"] for k, v in props.items()
                        if "x-smachac-shorthand-for" in v}
        # Shorthands are expanded at the root and in states alike; at the root only those
        # whose longhand is a root key are allowed (the others are unknown root keys).
        expected = {s: l for s, l in shorthands.items() if level == "state" or l in keys}
        failures.check(schema_short == expected,
                       "%s shorthands: schema %s, frontend/shorthand.cpp %s"
                       % (level, sorted(schema_short.items()), sorted(expected.items())))
        for short, long in schema_short.items():
            constraint = props[short].get("allOf")
            wanted = props[long].get("allOf") if long in props else None
            failures.check(constraint == wanted,
                           "%s shorthand `%s` is not checked as `%s` is" % (level, short, long))
    if len(failures.messages) == failed_before:
        print("ok: the schema's root keys, state keys and %d shorthands match the compiler's"
              % len(shorthands))


# --- scripts the compiler accepts --------------------------------------------------------

def case_header(path):
    """(args, exit code or None) from a golden case's leading comment lines."""
    args, exit_code = [], None
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            if not line.startswith("#"):
                break
            if line.startswith("# ARGS:"):
                args += shlex.split(line[len("# ARGS:"):])
            elif line.startswith("# EXIT:"):
                exit_code = int(line[len("# EXIT:"):])
    return args, exit_code


def script_dirs(args, case_dir):
    dirs = []
    for i, a in enumerate(args):
        if a == "-S" and i + 1 < len(args):
            dirs.append(os.path.join(case_dir, args[i + 1]))
        elif a.startswith("-S") and len(a) > 2:
            dirs.append(os.path.join(case_dir, a[2:]))
    return dirs


def included_names(node):
    """The `script:` (or `S:`) names of the states anywhere in a parsed script."""
    if isinstance(node, list):
        for item in node:
            yield from included_names(item)
    elif isinstance(node, dict):
        for key, value in node.items():
            if key in ("script", "S") and isinstance(value, str):
                yield value
            elif isinstance(value, (dict, list)):
                yield from included_names(value)


def find_sub_script(name, including_dir, dirs):
    for d in [including_dir] + dirs:
        for candidate in (name, name + ".yml"):
            path = os.path.normpath(os.path.join(d, candidate))
            if os.path.isfile(path):
                return path
    return None


def accepted_scripts(source_dir):
    """[(path, `-S` dirs, expect unknown-root-key rejection)] of scripts smachac accepts."""
    scripts = [(p, [], False) for p in
               sorted(glob.glob(os.path.join(source_dir, "examples/**/*.yml"), recursive=True))]
    golden = os.path.join(source_dir, "tests/golden")
    for path in sorted(glob.glob(os.path.join(golden, "*/*.yml"))):
        name = os.path.basename(path)
        if os.path.basename(os.path.dirname(path)) == "inputs":
            continue  # helpers, not cases (tests/golden/CMakeLists.txt)
        args, exit_code = case_header(path)
        if name.startswith("fail_") or exit_code not in (None, 0):
            continue
        stderr_path = path[:-len(".yml")] + ".stderr"
        stderr = open(stderr_path, encoding="utf-8").read() if os.path.exists(stderr_path) else ""
        # The warning as text or JSON, or turned off by -Wno-unknown-root-key.
        unknown_root_key = "unknown-root-key" in stderr or any(
            "unknown-root-key" in a for a in args)
        scripts.append((path, script_dirs(args, os.path.dirname(path)), unknown_root_key))
    return scripts


def check_accepted(validator, source_dir, failures):
    failed_before = len(failures.messages)
    queue = accepted_scripts(source_dir)
    seen, validated, included, rejected_keys = set(), 0, 0, 0
    while queue:
        path, dirs, unknown_root_key = queue.pop(0)
        if path in seen:
            continue
        seen.add(path)
        rel = os.path.relpath(path, source_dir)
        doc = load_yaml(path)
        if doc is None:
            continue  # a golden case that only names its script in `# ARGS:` (examples/ has it)
        errors = list(validator.iter_errors(doc))
        if unknown_root_key:
            failures.check(errors and all(slash(e.relative_schema_path) == "else/additionalProperties"
                                          for e in errors),
                           "%s: its unknown root key is not rejected alone: %s"
                           % (rel, [(slash(e.absolute_path), e.message) for e in errors]))
            rejected_keys += 1
        else:
            for e in errors:
                failures.check(False, "%s: %s: %s (schema %s)"
                               % (rel, slash(e.absolute_path) or "(root)", e.message,
                                  slash(e.relative_schema_path)))
            failures.check(True, "")
            validated += 1
        for name in included_names(doc):
            sub = find_sub_script(name, os.path.dirname(path), dirs)
            failures.check(sub is not None, "%s: sub-script `%s` not found" % (rel, name))
            if sub and sub not in seen:
                included += 1
                queue.append((sub, dirs, False))
    failures.check(validated >= 100 and included >= 10 and rejected_keys >= 1,
                   "too few scripts found under %s: %d scripts, %d included sub-scripts, %d "
                   "with an unknown root key" % (source_dir, validated, included, rejected_keys))
    if len(failures.messages) == failed_before:
        print("ok: %d scripts that smachac accepts validate (%d of them sub-scripts included by "
              "the others); %d with an unknown root key are rejected for that key alone"
              % (validated, included, rejected_keys))


# --- scripts the schema must reject -----------------------------------------------------

BASE = "name: t\ntemplate: Base\noutcomes: [done]\n"
REJECTED = [
    ("states not a list",
     BASE + "states:\n  A: {template: S}\n",
     "states", "else/properties/states/allOf/0/type"),
    ("a state with two keys",
     BASE + "states:\n  - A: {template: S}\n    B: {template: S}\n",
     "states/0", "else/properties/states/allOf/0/items/maxProperties"),
    ("a state that is a scalar",
     BASE + "states:\n  - A\n",
     "states/0", "else/properties/states/allOf/0/items/type"),
    ("a state body that is not a mapping",
     BASE + "states:\n  - A: PrintUserdataState\n",
     "states/0/A", STATE_PATH + "/type"),
    ("a state without template or script",
     BASE + "states:\n  - A: {outcomes: [done]}\n",
     "states/0/A", STATE_PATH + "/anyOf"),
    ("transitions not a mapping",
     BASE + "states:\n  - A: {template: S, transitions: done}\n",
     "states/0/A/transitions", STATE_PATH + "/properties/transitions/allOf/0/type"),
    ("transitions not a mapping, shorthand",
     BASE + "states:\n  - A: {T: S, t: done}\n",
     "states/0/A/t", STATE_PATH + "/properties/t/allOf/0/type"),
    ("a transition target that is a mapping",
     BASE + "states:\n  - A: {template: S, transitions: {succeeded: {x: 1}}}\n",
     "states/0/A/transitions/succeeded",
     STATE_PATH + "/properties/transitions/allOf/0/additionalProperties/type"),
    ("outcomes not a list",
     BASE + "states:\n  - A: {template: S, outcomes: done}\n",
     "states/0/A/outcomes", STATE_PATH + "/properties/outcomes/allOf/0/type"),
    ("outcomes not a list of names",
     BASE + "states:\n  - A: {template: S, outcomes: [done, {x: 1}]}\n",
     "states/0/A/outcomes/1", STATE_PATH + "/properties/outcomes/allOf/0/items/type"),
    ("an empty outcome",
     BASE + "states:\n  - A: {template: S, outcomes: ['']}\n",
     "states/0/A/outcomes/0", STATE_PATH + "/properties/outcomes/allOf/0/items/minLength"),
    ("the script's outcomes not a list",
     "name: t\ntemplate: Base\noutcomes: done\nstates:\n  - A: {template: S}\n",
     "outcomes", "else/properties/outcomes/allOf/0/type"),
    ("a float as a name",
     BASE + "states:\n  - A: {template: S, default_outcome: 1.5}\n",
     "states/0/A/default_outcome", STATE_PATH + "/properties/default_outcome/allOf/0/type"),
    ("an outcome_map entry that is not a mapping",
     BASE + "states:\n  - C: {template: Concurrence, outcome_map: {ok: A}, states: []}\n",
     "states/0/C/outcome_map/ok",
     STATE_PATH + "/properties/outcome_map/allOf/0/additionalProperties/type"),
    ("params not a mapping",
     BASE + "states:\n  - A: {template: S, params: fast}\n",
     "states/0/A/params", STATE_PATH + "/properties/params/allOf/0/type"),
    ("an unknown root key",
     BASE + "colour: red\nstates:\n  - A: {template: S}\n",
     "", "else/additionalProperties"),
    ("a shorthand that is no root key (`ik`)",
     BASE + "ik: [x]\nstates:\n  - A: {template: S}\n",
     "", "else/additionalProperties"),
    ("a script without states",
     BASE,
     "", "else/allOf/2/anyOf"),
    ("a script without name (nor n)",
     "template: Base\nstates:\n  - A: {template: S}\n",
     "", "else/allOf/0/anyOf"),
    ("a sub-script of two states",
     "- A: {template: S}\n- B: {template: S}\n",
     "", "then/maxItems"),
    ("a scalar document",
     "just a sentence\n",
     "", "else/type"),
]

ACCEPTED = [
    ("shorthands at the root and in states",
     "{n: t, T: Base, o: [done], p: {x: 1}, ud: {a: 1}, s: [A: {T: S, ik: [a], ok: [b],"
     " r: {a: a}, t: {succeeded: done}, cb: {b: '`lambda ud: 1`'}, o: [succeeded]}]}\n"),
    ("lookups and string constructs",
     "name: t\ntemplate: Base\noutcomes: [done]\nstates:\n"
     "  - A:\n      template: [[tmpl]]\n      params: {tmpl: S, next: done, outs: [succeeded]}\n"
     "      outcomes: [[outs]]\n      transitions: {succeeded: [[next]]}\n"
     "      userdata: {text: [[[tmpl]], ', ', [params, next]]}\n"),
    ("nested state lists and a Concurrence",
     "name: t\ntemplate: Base\noutcomes: [done]\nstates:\n"
     "  - - A: {template: S, transitions: {succeeded: C}}\n"
     "  - C:\n      template: Concurrence\n      outcomes: [ok, bad]\n"
     "      default_outcome: bad\n      outcome_map: {ok: {X: succeeded, Y: succeeded}}\n"
     "      transitions: {ok: done, bad: done}\n"
     "      states: [X: {template: S}, Y: {template: S}]\n"),
    ("a sub-script", "- SUB:\n    template: StateMachine\n    outcomes: [done]\n"
     "    states: [A: {template: S, transitions: {succeeded: done}}]\n"),
    ("!expr callbacks and !str values",
     "name: t\ntemplate: Base\noutcomes: [done]\nuserdata: {n: !str 007}\nstates:\n"
     "  - A: {template: CallbacksState, input_keys: [n], output_keys: [n],\n"
     "        callbacks: {n: !expr 'n + 1'}, transitions: {succeeded: done}}\n"),
]


def check_rejected(validator, failures):
    failed_before = len(failures.messages)
    for what, text, instance_path, schema_path in REJECTED:
        errors = list(validator.iter_errors(yaml.load(text, Loader=Yaml12Loader)))
        found = [(slash(e.absolute_path), slash(e.relative_schema_path)) for e in errors]
        failures.check(found == [(instance_path, schema_path)],
                       "%s: expected one error at %r (schema %s), got %r"
                       % (what, instance_path, schema_path, found))
    for what, text in ACCEPTED:
        errors = list(validator.iter_errors(yaml.load(text, Loader=Yaml12Loader)))
        failures.check(not errors, "%s: rejected: %s"
                       % (what, [(slash(e.absolute_path), e.message) for e in errors]))
    if len(failures.messages) == failed_before:
        print("ok: %d broken scripts rejected where expected, %d written-out forms accepted"
              % (len(REJECTED), len(ACCEPTED)))


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    source_dir = os.path.abspath(sys.argv[1])
    with open(os.path.join(source_dir, SCHEMA), encoding="utf-8") as f:
        schema = json.load(f)
    jsonschema.Draft7Validator.check_schema(schema)
    validator = jsonschema.Draft7Validator(schema)
    failures = Failures()
    check_tables(schema, source_dir, failures)
    check_accepted(validator, source_dir, failures)
    check_rejected(validator, failures)
    if failures.messages:
        print("schema_test: %d of %d checks failed" % (len(failures.messages), failures.checks))
        return 1
    print("schema_test: all %d checks passed" % failures.checks)
    return 0


if __name__ == "__main__":
    sys.exit(main())
