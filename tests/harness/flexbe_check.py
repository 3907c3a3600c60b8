#!/usr/bin/env python3
"""Checks of the FlexBE target's output.

  flexbe_check.py compile <golden dir>    every .py file of every expected *.flexbe.py
                                          compiles (py_compile, this interpreter), and every
                                          behavior module matches the FlexBE editor's parse
                                          patterns
  flexbe_check.py manual <smachac> <case> regenerating over an existing behavior keeps the
                                          [MANUAL_*] sections byte for byte
"""
import os
import py_compile
import re
import shutil
import subprocess
import sys
import tempfile

# The regexes with which the FlexBE editor (flexbe_webui, io_codeparser.js) parses a behavior.
PATTERNS = {
    "class line": r"^class \w+SM\(Behavior\):$",
    "__init__": r"^    def __init__\(self(, node)?\):$",
    "create": r"^    def create\(self\):$",
    "layout comment": r"^\s*# x:-?\d+ y:-?\d+",
    "root state machine": r"^\s*_state_machine = OperatableStateMachine\(.*\)$",
    "with block": r"^\s*with \w+:$",
    "add": r"^\s*OperatableStateMachine\.add\(",
    "return": r"^\s*return _state_machine$",
}
# FlexBE's code generator leaves out an empty remapping, and its editor fails to parse
# `remapping={}`: a remapping is either absent or has entries.
ADD_LINE = re.compile(r"^\s*OperatableStateMachine\.add\('[^']+', [\w.]+(\(.*\))?, "
                      r"transitions=\{[^{}]*\}, autonomy=\{[^{}]*\}(, remapping=\{[^{}]+\})?\)$")
USERDATA_LINE = re.compile(r"^\s*\w+\.userdata\.\w+ = .+$")
MANUAL = ("IMPORT", "INIT", "CREATE", "FUNC")


def split_expected(path):
    """The files of one expected output: {name: text}."""
    files, name = {}, None
    with open(path, encoding="utf-8") as f:
        for line in f:
            m = re.match(r"^#==> (.+) <==$", line)
            if m:
                name = m.group(1)
                files[name] = ""
            elif name:
                files[name] += line
    return files


def check_behavior(name, text):
    errors = [f"{name}: no {what}" for what, pattern in PATTERNS.items()
              if not re.search(pattern, text, re.M)]
    for section in MANUAL:
        if text.count(f"# [MANUAL_{section}]") != 1 or text.count(f"# [/MANUAL_{section}]") != 1:
            errors.append(f"{name}: manual section {section} missing or repeated")
    for line in text.splitlines():
        if "OperatableStateMachine.add(" in line and not ADD_LINE.match(line):
            errors.append(f"{name}: add line not in the editor's shape: {line.strip()}")
        if ".userdata." in line and not USERDATA_LINE.match(line):
            errors.append(f"{name}: userdata line not in the editor's shape: {line.strip()}")
    return errors


def each_expected(golden_dir):
    for case in sorted(os.listdir(golden_dir)):
        if case.endswith(".flexbe.py"):
            yield case, split_expected(os.path.join(golden_dir, case))


def compile_all(golden_dir):
    errors, count = [], 0
    with tempfile.TemporaryDirectory() as tmp:
        for case, files in each_expected(golden_dir):
            for name, text in files.items():
                if not name.endswith(".py"):
                    continue
                path = os.path.join(tmp, case + "." + name)
                with open(path, "w", encoding="utf-8") as f:
                    f.write(text)
                try:
                    py_compile.compile(path, doraise=True)
                except py_compile.PyCompileError as e:
                    errors.append(f"{case}/{name}: {e.msg}")
                if name.endswith("_sm.py"):
                    errors += [f"{case}/{e}" for e in check_behavior(name, text)]
                count += 1
    print("\n".join(errors) or f"{count} files compile; behaviors match the editor's patterns")
    return 1 if errors or count == 0 else 0


def manual(smachac, case):
    with tempfile.TemporaryDirectory() as out:
        args = [smachac, "-target=flexbe", case, "-o", out]
        subprocess.run(args, check=True)
        behavior = next(n for n in os.listdir(out) if n.endswith("_sm.py"))
        path = os.path.join(out, behavior)
        with open(path, encoding="utf-8", newline="") as f:
            text = f.read()
        kept = {}
        for section in MANUAL:
            content = f"\t# kept {section}  \r\n\n  x = 1  # trailing spaces   \n"
            text = text.replace(f"# [MANUAL_{section}]\n\n", f"# [MANUAL_{section}]\n{content}", 1)
            kept[section] = content
        text = text.replace("self.name =", "self.name_changed_outside_manual =")
        with open(path, "w", encoding="utf-8", newline="") as f:
            f.write(text)
        subprocess.run(args, check=True)
        with open(path, encoding="utf-8", newline="") as f:
            regenerated = f.read()
    errors = [s for s in MANUAL if f"# [MANUAL_{s}]\n{kept[s]}" not in regenerated]
    if "name_changed_outside_manual" in regenerated:
        errors.append("code outside the manual sections was kept")
    print("manual sections not kept: " + ", ".join(errors) if errors else
          "all four manual sections kept byte for byte; the rest regenerated")
    return 1 if errors else 0


def main():
    mode = sys.argv[1]
    if mode == "compile":
        return compile_all(sys.argv[2])
    return manual(sys.argv[2], sys.argv[3])


if __name__ == "__main__":
    sys.exit(main())
