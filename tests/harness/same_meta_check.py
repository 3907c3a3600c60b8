#!/usr/bin/env python3
"""Checks that templates of the same name declare the same interface on every target, so that
one script compiles to all of them and means the same there.

  same_meta_check.py baxter <sim/templates>   the Baxter sets (golden/baxter-templates-same-meta)
  same_meta_check.py core <templates>         the core states (golden/core-templates-same-meta)

Two templates have the same interface when their meta blocks agree on the name, the variables
(name; required, optional or one of alternatives; type), input_keys, output_keys and
outcomes (as written, descriptions of keys and outcomes included: they describe the
userdata and outcomes of the one concept). The descriptions of the template and of its
variables may differ: they say what each target's code does.

baxter: every template of sim/templates/cpp must exist in sim/templates/smach and
sim/templates/flexbe with the same interface. Helper templates of one set only (type None,
e.g. BaxterUtils) are not part of the interface.

core: each concept of CORE_CONCEPTS must exist on every target, looked up as the compiler
looks a template up (TARGET_SETS), with the same interface as on the first target, and its
`callbacks`, where it has them, must say that `!expr` expressions are callbacks there too.
Any other state template found on more than one target is reported, so that a new shared
state gets checked: add it to CORE_CONCEPTS. A template of one target only (the ROS states
of smach_ros, FlexBE's WaitState) is that target's own, not a concept (see ONE_TARGET).
"""
import glob
import os
import re
import sys

import yaml

META = re.compile(r"{%\s*block meta\s*%}(.*?){%\s*endblock meta\s*%}", re.S)
FIELDS = ("name", "variables", "input_keys", "output_keys", "outcomes")

# The states every target has, under these names.
CORE_CONCEPTS = ["PrintUserdataState", "RandomOutcomeState", "CallbacksState",
                 "ConditionalOutcomeState", "DeleteFileState", "WriteCSVFileState",
                 "SleepState", "LogState"]
# Where each target's compiler looks a template up, in order (backends/meta/template_check.cpp).
TARGET_SETS = {"smach": ["smach", "smach_ros"], "flexbe": ["flexbe"], "cpp": ["cpp"]}
SUFFIXES = (".tpl.py", ".tpl.cpp")
# Templates that are one target's own on purpose, and why none is an alias of a concept.
ONE_TARGET = {
    "WaitState": ("flexbe",
                  "FlexBE's library state flexbe_states.wait_state.WaitState, written as FlexBE "
                  "declares it (variable wait_time, outcome done) for scripts written for "
                  "FlexBE; the concept of a timed pause is SleepState, which FlexBE has too. "
                  "Checking WaitState against SleepState would rename FlexBE's own variable "
                  "and outcome."),
}
# Template types that are not states: helpers, bases and containers.
NOT_STATES = (None, "None", "Base", "Container")


def variables(entries):
    """{name: (status, type)} from a meta `variables` list, read as the compiler reads it
    (backends/meta/template_meta.cpp): a mapping entry is required, a list of one entry optional,
    a list of several entries alternatives (one of them required); `{heading: [...]}` is a
    group of entries."""
    out = {}

    def mapping(item, status):
        for name, spec in item.items():
            if isinstance(spec, list):
                read(spec)
            else:
                out[name] = (status, (spec or {}).get("type"))

    def read(items):
        for entry in items or []:
            if isinstance(entry, dict):
                mapping(entry, "required")
            elif isinstance(entry, list) and len(entry) == 1:
                mapping(entry[0], "optional")
            elif isinstance(entry, list):
                names = sorted(name for option in entry for name in option)
                for option in entry:
                    mapping(option, "one of " + ", ".join(names))

    read(entries)
    return out


def meta_of(path):
    with open(path, encoding="utf-8") as f:
        found = META.search(f.read())
    return yaml.safe_load(found.group(1)) if found else None


def interface(path):
    meta = meta_of(path) or {}
    return {"name": meta.get("name"), "type": meta.get("type"),
            "variables": variables(meta.get("variables")),
            "input_keys": meta.get("input_keys") or [],
            "output_keys": meta.get("output_keys") or [],
            "outcomes": meta.get("outcomes") or []}


def differences(label, actual, reference_label, expected):
    """One line per field where interface `actual` differs from `expected`."""
    return [f"{label}: {field} {actual[field]!r}, {reference_label} has {expected[field]!r}"
            for field in FIELDS if actual[field] != expected[field]]


def check_baxter(root):
    """Every template of <root>/cpp against the template of the same name in smach and
    flexbe."""
    errors, checked = [], 0
    for reference in sorted(glob.glob(os.path.join(root, "cpp", "*.tpl.cpp"))):
        name = os.path.basename(reference)[:-len(".tpl.cpp")]
        expected = interface(reference)
        for target in ("smach", "flexbe"):
            path = os.path.join(root, target, name + ".tpl.py")
            if not os.path.exists(path):
                errors.append(f"{target}: no template {name}")
                continue
            errors += differences(f"{target}/{name}", interface(path), "cpp", expected)
            checked += 1
    return errors, f"{checked} templates checked against sim/templates/cpp", checked


def resolve(root, target, name):
    """The file the compiler uses for template `name` on `target`, or None."""
    for folder in TARGET_SETS[target]:
        for suffix in SUFFIXES:
            path = os.path.join(root, folder, name + suffix)
            if os.path.exists(path):
                return path
    return None


def state_templates(root, target):
    """{name: path} of the state templates of a target (the first of a name wins)."""
    found = {}
    for folder in TARGET_SETS[target]:
        for suffix in SUFFIXES:
            for path in sorted(glob.glob(os.path.join(root, folder, "*" + suffix))):
                name = os.path.basename(path)[:-len(suffix)]
                meta = meta_of(path)
                if name not in found and meta and meta.get("type") not in NOT_STATES:
                    found[name] = path
    return found


def check_core(root):
    errors, checked = [], 0
    targets = list(TARGET_SETS)
    for name in CORE_CONCEPTS:
        paths = {target: resolve(root, target, name) for target in targets}
        for target, path in paths.items():
            if path is None:
                errors.append(f"{target}: no template {name}")
        present = [target for target in targets if paths[target]]
        if not present:
            continue
        reference = present[0]
        expected = interface(paths[reference])
        for target in present:
            actual = interface(paths[target])
            label = os.path.relpath(paths[target], root)
            if target != reference:
                errors += differences(label, actual, reference, expected)
            callbacks = (meta_of(paths[target]) or {}).get("variables") or []
            for entry in callbacks:
                for item in (entry if isinstance(entry, list) else [entry]):
                    spec = item.get("callbacks") if isinstance(item, dict) else None
                    if isinstance(spec, dict) and "!expr" not in (spec.get("description") or ""):
                        errors.append(f"{label}: the description of `callbacks` does not "
                                      "mention `!expr` expressions")
            checked += 1
    by_target = {target: state_templates(root, target) for target in targets}
    for name in sorted(set().union(*by_target.values())):
        having = [target for target in targets if name in by_target[target]]
        if name in ONE_TARGET:
            if having != [ONE_TARGET[name][0]]:
                errors.append(f"{name}: declared {ONE_TARGET[name][0]}'s own template "
                              f"(ONE_TARGET), found on {', '.join(having)}")
        elif len(having) > 1 and name not in CORE_CONCEPTS:
            errors.append(f"{name}: a state template of {', '.join(having)} that is not in "
                          "CORE_CONCEPTS, so nothing checks that it means the same there")
    return errors, (f"{checked} templates of {len(CORE_CONCEPTS)} core states checked on "
                    f"{', '.join(targets)}"), checked


CHECKS = {"baxter": check_baxter, "core": check_core}


def main(argv):
    if len(argv) != 2 or argv[0] not in CHECKS:
        print(__doc__, file=sys.stderr)
        return 2
    errors, summary, checked = CHECKS[argv[0]](argv[1])
    for e in errors:
        print("FAIL " + e)
    print(summary)
    return 1 if errors or not checked else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
