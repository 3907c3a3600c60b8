#!/usr/bin/python3
"""Differential test of smachac's template engine against Jinja2 3.x configured like SMACHA.

usage: run_diff.py RUNNER CASES_DIR [--list]

Every case of CASES_DIR/*.cases is rendered here with Jinja2 (lstrip_blocks=True,
trim_blocks=False, jinja2.ext.do, SMACHA's tests/filter and SkipBlockExtension) and by the
C++ runner (one process for all cases); the results must be byte-identical. The case format is
described in README.md. Exit status 1 on any difference.
"""
import json
import subprocess
import sys
from pathlib import Path

import jinja2
import yaml

import smacha_jinja

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "harness"))
from yaml12 import Yaml12Loader  # noqa: E402

# --- the case files -------------------------------------------------------------------------


def parse_cases(directory):
    cases = []
    for path in sorted(Path(directory).glob("*.cases")):
        case = None
        section = None
        for line in path.read_text(encoding="utf-8").split("\n"):
            if line.startswith("#### "):
                case = {"name": f"{path.stem}/{line[5:].strip()}", "templates": [],
                        "context": [], "ops": []}
                cases.append(case)
                section = None
            elif case is None:
                continue
            elif line.startswith("--- "):
                words = line[4:].split()
                if words[0] in ("context", "ops"):
                    section = case[words[0]]
                else:
                    section = []
                    case["templates"].append((words[0], set(words[1:]), section))
            elif section is not None:
                section.append(line)
    return cases


def strip_tail(lines):
    lines = list(lines)
    while lines and lines[-1] == "":
        lines.pop()
    return lines


def template_text(flags, lines):
    text = "\n".join(strip_tail(lines))
    if "noeol" not in flags:
        text += "\n"
    if "crlf" in flags:
        text = text.replace("\n", "\r\n")
    return text


def case_ops(case):
    ops = [op.strip() for op in strip_tail(case["ops"]) if op.strip()]
    return ops or ["render"]


# --- the reference environment: smacha_jinja.py ---------------------------------------------


def make_env(templates, skip=()):
    return smacha_jinja.make_env(jinja2.DictLoader(templates), skip)


# --- YAML 1.2 core schema contexts ---------------------------------------------------------


def load_context(lines):
    data = yaml.load("\n".join(lines), Loader=Yaml12Loader)
    return data if data is not None else {}


# --- running one case with Jinja2 ------------------------------------------------------------


def parse_op(op):
    words = op.split()
    kind, args, skip, error = words[0], [], [], False
    for w in words[1:]:
        if w.startswith("skip="):
            skip = [s for s in w[5:].split(",") if s]
        elif w == "error":
            error = True
        else:
            args.append(w)
    return kind, args, skip, error


def run_op(templates, main, context, op):
    kind, args, skip, _ = parse_op(op)
    if kind == "render":
        return make_env(templates, skip).get_template(main).render(context)
    if kind == "block":
        blocks = smacha_jinja.all_blocks(make_env(templates), main)
        skipped = smacha_jinja.block_skip_list(blocks, args[0], skip)
        return smacha_jinja.strip_block(make_env(templates, skipped).get_template(main).render(context))
    if kind == "blocks":
        return "\n".join(sorted(smacha_jinja.all_blocks(make_env(templates), main)))
    if kind == "vars":
        module = make_env(templates, skip).get_template(main).make_module(vars=context)
        names = sorted(n for n in dir(module) if not n.startswith("_"))
        return "\n".join(f"{n} = {getattr(module, n)!r}" for n in names)
    if kind == "meta":
        template = make_env(templates).get_template(main)
        if "meta" not in template.blocks:
            return "<none>"
        return "".join(template.blocks["meta"](template.new_context(vars={})))
    raise ValueError(f"unknown op {op!r}")


def reference(case):
    templates = {name: template_text(flags, lines) for name, flags, lines in case["templates"]}
    main = case["templates"][0][0]
    results = []
    for op in case_ops(case):
        context = load_context(case["context"])  # fresh per operation, like the runner
        try:
            results.append({"op": op, "ok": True, "out": run_op(templates, main, context, op)})
        except Exception as e:  # every Jinja2 error counts as "fails"
            results.append({"op": op, "ok": False, "out": f"{type(e).__name__}: {e}"})
    return results


# --- comparing ------------------------------------------------------------------------------


def main(argv):
    runner, directory = argv[1], argv[2]
    cases = parse_cases(directory)
    names = [c["name"] for c in cases]
    duplicates = {n for n in names if names.count(n) > 1}
    if duplicates:
        print(f"tmpl_diff: duplicate case names: {sorted(duplicates)}")
        return 1
    proc = subprocess.run([runner, directory], capture_output=True, text=True)
    if proc.returncode != 0:
        print(f"tmpl_diff: runner failed ({proc.returncode}):\n{proc.stderr}")
        return 1
    ours = {}
    for line in filter(None, proc.stdout.split("\n")):
        record = json.loads(line)
        ours.setdefault(record["case"], []).append(record)
    failures = 0
    renders = 0
    for case in cases:
        theirs = reference(case)
        mine = ours.get(case["name"], [])
        if len(mine) != len(theirs):
            print(f"FAIL {case['name']}: runner produced {len(mine)} results, expected {len(theirs)}")
            failures += 1
            continue
        for ref, got in zip(theirs, mine):
            renders += 1
            wants_error = parse_op(ref["op"])[3]
            problem = None
            if ref["ok"] == wants_error:
                problem = f"Jinja2 {'succeeded' if ref['ok'] else 'failed'} against expectation: {ref['out']!r}"
            elif got["ok"] != ref["ok"]:
                problem = f"smachac {'succeeded' if got['ok'] else 'failed'}: {got['out']!r}"
            elif ref["ok"] and got["out"] != ref["out"]:
                problem = f"output differs\n  jinja2:  {ref['out']!r}\n  smachac: {got['out']!r}"
            if problem:
                failures += 1
                print(f"FAIL {case['name']} [{ref['op']}]: {problem}")
    print(f"tmpl_diff: {len(cases)} cases, {renders} renders, {failures} differences")
    if len(cases) < 200:
        print("tmpl_diff: fewer than 200 cases")
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
