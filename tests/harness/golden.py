#!/usr/bin/env python3
"""Runs one golden case of smachac and compares its output with the expected files.

A case is tests/golden/<area>/<name>.yml. Its leading comment lines may hold
`# ARGS: <arguments>` (default `-target=ir`). smachac runs with the case's directory as the
working directory and the file name as given, so paths in diagnostics are stable.
  * stdout is compared with <name>.<ext>, ext from the target (ir, json, dot, smach.py, ...);
    no stdout expected when the file is absent;
  * stderr is compared with <name>.stderr (absent: stderr must be empty);
  * the exit code must be 1 if and only if the name starts with `fail_`, else 0; usage errors
    are tested with `# EXIT: 2` (and no `fail_` prefix).
The case file is appended to the arguments, unless ARGS places it with `%s` or leaves it out
with `%none`.
An `%outdir` argument becomes a fresh temporary directory; the files written there are then
appended to stdout, sorted by name, each after a `#==> <name> <==` line (multi-file targets).
With SMACHAC_UPDATE_GOLDEN=1 the expected files are rewritten instead (then review them).
"""
import os
import shlex
import subprocess
import sys
import tempfile

EXTENSIONS = {"ir": "ir", "json": "json", "dot": "dot", "smach": "smach.py", "cpp": "cpp",
              "flexbe": "flexbe.py", "yaml": "out.yml"}


def case_header(case_path):
    """The `# ARGS:` arguments and the `# EXIT:` code (None: from the name) of a case."""
    args, exit_code = [], None
    with open(case_path, encoding="utf-8", errors="replace") as f:
        for line in f:
            if not line.startswith("#"):
                break
            if line.startswith("# ARGS:"):
                args += shlex.split(line[len("# ARGS:"):])
            if line.startswith("# EXIT:"):
                exit_code = int(line[len("# EXIT:"):])
    if not any(a.lstrip("-").startswith("target") or a.startswith("-fsyntax-only") or
               a in ("lint", "help", "contain", "extract", "render") for a in args):
        args = ["-target=ir"] + args
    return args, exit_code


def target_of(args):
    for a in args:
        if a.lstrip("-").startswith("target="):
            return a.split("=", 1)[1]
    return None


def compare(path, actual, update):
    if update:
        if actual:
            with open(path, "w", encoding="utf-8", newline="") as f:
                f.write(actual)
        elif os.path.exists(path):
            os.remove(path)
        return True
    expected = ""
    if os.path.exists(path):
        with open(path, encoding="utf-8", newline="") as f:
            expected = f.read()
    if expected == actual:
        return True
    import difflib
    sys.stdout.write("".join(difflib.unified_diff(
        expected.splitlines(True), actual.splitlines(True),
        "expected " + os.path.basename(path), "actual")))
    return False


def main():
    smachac, case_path = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    case_dir, case_file = os.path.split(case_path)
    name = case_file[:-len(".yml")]
    args, exit_code = case_header(case_path)
    if "%none" in args:
        args.remove("%none")
    elif "%s" in args:
        args = [case_file if a == "%s" else a for a in args]
    else:
        args.append(case_file)
    env = dict(os.environ, LC_ALL="C")
    with tempfile.TemporaryDirectory() as outdir:
        args = [outdir if a == "%outdir" else a for a in args]
        result = subprocess.run([smachac] + args, cwd=case_dir, capture_output=True, env=env,
                                timeout=60)
        stdout = result.stdout.decode("utf-8", "replace")
        for file in sorted(os.listdir(outdir)):
            with open(os.path.join(outdir, file), encoding="utf-8", newline="") as f:
                stdout += f"#==> {file} <==\n" + f.read()
    stderr = result.stderr.decode("utf-8", "replace")
    update = os.environ.get("SMACHAC_UPDATE_GOLDEN") == "1"
    ok = True
    expected_code = 1 if name.startswith("fail_") else 0
    if exit_code is not None:
        expected_code = exit_code
    if result.returncode != expected_code:
        print(f"exit code {result.returncode}, expected {expected_code}")
        ok = False
    ext = EXTENSIONS.get(target_of(args) or "", "out")
    ok = compare(os.path.join(case_dir, f"{name}.{ext}"), stdout, update) and ok
    ok = compare(os.path.join(case_dir, f"{name}.stderr"), stderr, update) and ok
    if not ok:
        print("stderr was:\n" + stderr)
    return 0 if ok or update else 1


if __name__ == "__main__":
    sys.exit(main())
