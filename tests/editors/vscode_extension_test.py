#!/usr/bin/env python3
"""Builds, tests and packages the VS Code extension (editors/vscode) as a user would.

  vscode_extension_test.py SOURCE_DIR WORK_DIR

Copies editors/vscode to WORK_DIR (emptied first; node_modules/, out/ and *.vsix of the source
tree are left behind), so that nothing is written into the source tree, and runs there:
  npm ci --ignore-scripts   the locked dependencies (npm's cache serves what it holds; no
                            install script is needed to build or package)
  npm run compile           tsc
  npm test                  the node:test unit tests of src/config.ts and package.json
  npm run package           vsce package -> smachac-<version>.vsix
then checks the .vsix (a zip): extension/package.json, the compiled file its `main` names,
the runtime dependency vscode-languageclient, and none of the sources, tests or build tools.

Exit 77 (skip, with the reason) when node or npm is missing, or when the node version is not
one that the locked packages accept (their engines.node in package-lock.json: @vscode/vsce 3
and its dependencies need node 20, Debian 12's nodejs is 18).
"""
import json
import os
import posixpath
import re
import shutil
import subprocess
import sys
import zipfile

SKIP = 77


def skip(reason):
    print("skip: " + reason)
    sys.exit(SKIP)


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def node_version():
    try:
        out = subprocess.run(["node", "--version"], capture_output=True, text=True, check=True,
                             timeout=60).stdout.strip()
    except (OSError, subprocess.SubprocessError) as error:
        skip("node does not run: %s" % error)
    m = re.match(r"v?(\d+)\.(\d+)\.(\d+)", out)
    if not m:
        skip("cannot read node's version from %r" % out)
    return tuple(int(x) for x in m.groups())


def version_of(text):
    parts = [int(x) for x in re.findall(r"\d+", text)[:3]]
    return tuple(parts + [0] * (3 - len(parts)))


def satisfies(version, comparator):
    """One `||` alternative of an engines range, in the forms npm packages use; None when it
    is none of them."""
    c = comparator.strip()
    if c in ("", "*", "x"):
        return True
    m = re.fullmatch(r"(>=|>|\^|~)?\s*v?(\d+(?:\.\d+){0,2})(?:\.x)?", c)
    if not m:
        return None
    op, bound = m.group(1), version_of(m.group(2))
    depth = m.group(2).count(".") + 1
    if op == ">=":
        return version >= bound
    if op == ">":
        return version > bound
    if op == "^":
        return version[0] == bound[0] and version >= bound
    if op == "~":  # ~20.1.2: 20.1.x from 20.1.2 on
        return version[:2] == bound[:2] and version >= bound
    return version[:depth] == bound[:depth]  # 20 is 20.x.x, 20.1 is 20.1.x


def unaccepted_by(version, lock):
    """[(package, version, engines)] of the locked packages whose engines.node the given node
    version does not satisfy (ranges this cannot read count as satisfied)."""
    needs = []
    for key, package in lock.get("packages", {}).items():
        engines = package.get("engines", {})
        wanted = engines.get("node") if isinstance(engines, dict) else None
        if not key or not isinstance(wanted, str):
            continue
        verdicts = [satisfies(version, alt) for alt in wanted.split("||")]
        if all(v is False for v in verdicts):
            needs.append((key[key.rfind("node_modules/") + len("node_modules/"):],
                          package.get("version", "?"), wanted))
    return needs


def run(args, cwd):
    print("$ " + " ".join(args), flush=True)
    env = dict(os.environ, npm_config_fund="false", npm_config_audit="false",
               npm_config_update_notifier="false")
    result = subprocess.run(args, cwd=cwd, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, timeout=600)
    print(result.stdout.rstrip(), flush=True)
    if result.returncode != 0:
        fail("`%s` exited %d" % (" ".join(args), result.returncode))
    return result.stdout


def copy_sources(source, work):
    if os.path.exists(work):
        shutil.rmtree(work)
    ignore = shutil.ignore_patterns("node_modules", "out", "*.vsix")
    shutil.copytree(source, work, ignore=ignore)


def check_vsix(path, manifest):
    with zipfile.ZipFile(path) as z:
        names = set(z.namelist())
        bad = z.testzip()
        if bad is not None:
            fail("%s: corrupt member %s" % (path, bad))
        for needed in ("extension/package.json", "extension/out/extension.js",
                       "extension/out/config.js", "extension.vsixmanifest",
                       "extension/node_modules/vscode-languageclient/package.json"):
            if needed not in names:
                fail("%s lacks %s" % (path, needed))
        packed = json.loads(z.read("extension/package.json"))
        main = posixpath.normpath(packed.get("main", ""))
        if main != "out/extension.js":
            fail("package.json's main is %r, not the compiled out/extension.js" % packed.get("main"))
        main_file = main if main.endswith(".js") else main + ".js"
        if "extension/" + main_file not in names:
            fail("package.json's main %r is not in the package" % packed["main"])
        if packed.get("version") != manifest["version"] or packed.get("name") != manifest["name"]:
            fail("the packaged package.json is not the source's")
        for name in sorted(names):
            if not name.startswith("extension/"):
                continue
            rel = name[len("extension/"):]
            if rel.startswith("node_modules/"):
                for dev in ("typescript", "@vscode/vsce", "@types/vscode", ".bin"):
                    if rel.startswith("node_modules/%s/" % dev):
                        fail("%s holds the development dependency %s" % (path, dev))
            elif rel.startswith(("src/", "out/test/")) or rel.endswith((".ts", ".map")) \
                    or rel in ("tsconfig.json", "package-lock.json"):
                fail("%s holds %s, which .vscodeignore leaves out" % (path, rel))
        print("ok: %s: %d files; main %s; vscode-languageclient %s" % (
            os.path.basename(path), len(names), packed["main"],
            json.loads(z.read("extension/node_modules/vscode-languageclient/package.json"))
            ["version"]))


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    source = os.path.join(os.path.abspath(sys.argv[1]), "editors", "vscode")
    work = os.path.abspath(sys.argv[2])
    if os.path.commonpath([source, work]) == source:
        fail("the work directory %s is inside the sources" % work)

    for tool in ("node", "npm"):
        if shutil.which(tool) is None:
            skip("`%s` is not installed (Node.js with npm is needed to build the VS Code "
                 "extension)" % tool)
    with open(os.path.join(source, "package-lock.json"), encoding="utf-8") as f:
        lock = json.load(f)
    with open(os.path.join(source, "package.json"), encoding="utf-8") as f:
        manifest = json.load(f)
    version = node_version()
    needs = unaccepted_by(version, lock)
    if needs:
        shown = ", ".join("%s %s (node %s)" % need for need in sorted(needs)[:4])
        skip("node %s is not a version that %d of the build's packages accept: %s%s"
             % (".".join(map(str, version)), len(needs), shown,
                ", ..." if len(needs) > 4 else ""))

    copy_sources(source, work)
    run(["npm", "ci", "--ignore-scripts", "--prefer-offline"], work)
    run(["npm", "run", "compile"], work)
    run(["npm", "test"], work)
    run(["npm", "run", "package"], work)
    vsix = os.path.join(work, "%s-%s.vsix" % (manifest["name"], manifest["version"]))
    if not os.path.isfile(vsix):
        fail("npm run package did not write %s" % vsix)
    check_vsix(vsix, manifest)
    return 0


if __name__ == "__main__":
    sys.exit(main())
