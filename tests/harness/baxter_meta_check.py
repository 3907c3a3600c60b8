#!/usr/bin/env python3
"""Checks that the Baxter template sets of every target declare the same interface, so that
the same scripts (examples/baxter) compile to all of them.

  baxter_meta_check.py <sim/templates>

For every template of sim/templates/cpp, the template of the same name in each other set
(smach, flexbe) must exist, and their meta blocks must agree on the name, the variables
(name, required or optional, type), input_keys, output_keys and outcomes. Descriptions may
differ: they say what each target's code does. Helper templates of one set only (type None,
e.g. BaxterUtils) are not part of the interface.
"""
import glob
import os
import re
import sys

import yaml

META = re.compile(r"{%\s*block meta\s*%}(.*?){%\s*endblock meta\s*%}", re.S)
OTHER_SETS = {"smach": ".tpl.py", "flexbe": ".tpl.py"}


def variables(entries):
    """{name: (required, type)} from a meta `variables` list (a list entry is optional)."""
    out = {}
    for entry in entries or []:
        required = isinstance(entry, dict)
        for item in ([entry] if required else entry):
            for name, spec in item.items():
                out[name] = (required, (spec or {}).get("type"))
    return out


def interface(path):
    with open(path, encoding="utf-8") as f:
        meta = yaml.safe_load(META.search(f.read()).group(1))
    return {"name": meta.get("name"), "type": meta.get("type"),
            "variables": variables(meta.get("variables")),
            "input_keys": meta.get("input_keys") or [],
            "output_keys": meta.get("output_keys") or [],
            "outcomes": meta.get("outcomes") or []}


def main():
    root = sys.argv[1]
    errors, checked = [], 0
    for reference in sorted(glob.glob(os.path.join(root, "cpp", "*.tpl.cpp"))):
        name = os.path.basename(reference)[:-len(".tpl.cpp")]
        expected = interface(reference)
        for target, suffix in OTHER_SETS.items():
            path = os.path.join(root, target, name + suffix)
            if not os.path.exists(path):
                errors.append(f"{target}: no template {name}")
                continue
            actual = interface(path)
            for field in ("name", "variables", "input_keys", "output_keys", "outcomes"):
                if actual[field] != expected[field]:
                    errors.append(f"{target}/{name}: {field} {actual[field]!r}, cpp has "
                                  f"{expected[field]!r}")
            checked += 1
    for e in errors:
        print("FAIL " + e)
    print(f"{checked} templates checked against sim/templates/cpp")
    return 1 if errors or not checked else 0


if __name__ == "__main__":
    sys.exit(main())
