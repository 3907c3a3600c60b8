#!/usr/bin/env python3
"""The component graph: every #include and every link between the project's libraries goes
down the graph below, never up or sideways (label lint).

  layering_test.py REPO_ROOT LINKS_JSON INCLUDE_DIRS_JSON

ALLOWED is the one written form of the graph (the README's architecture picture draws it).
An #include "x/y.h" belongs to the component whose folder holds x/y.h (the longest match);
<smachac/runtime/...>, <smachac/sim/...> and <smachac/robot/...> to the runtime, the
simulation and the robot states. LINKS_JSON ({target: [linked targets]}) is written by CMake
at configure time (tests/layering/CMakeLists.txt) from each library's LINK_LIBRARIES.
A component may use itself and what ALLOWED lists for it; tests and benchmarks may use
everything. Prints every edge that is not allowed and exits 1 if there is one.

The build holds each library to the headers of what it links (tools/cmake/include_root.cmake),
so an include sideways fails to compile unless the link is there too; this test keeps the
links themselves on the graph, and names the two components of an edge that is not allowed.
"""
import json
import os
import re
import sys

# component folder -> the components it may include and link (its own folder excluded)
ALLOWED = {
    "ir/support": [],
    "ir": ["ir/support"],
    "frontend": ["ir", "ir/support"],
    "passes": ["ir", "ir/support"],
    "templates": ["ir/support"],
    "backends/tmpl": ["ir/support"],
    "backends/generator": ["backends/tmpl", "ir", "ir/support"],
    "backends": ["backends/generator", "backends/tmpl", "templates", "ir", "ir/support"],
    "refactor": ["frontend", "passes", "ir", "ir/support"],
    "checker": ["backends", "frontend", "passes", "ir", "ir/support"],
    "lsp": ["checker", "refactor", "backends", "backends/generator", "backends/tmpl",
            "templates", "frontend", "passes", "ir", "ir/support"],
    "tools/smachac": ["lsp", "checker", "refactor", "backends", "backends/generator",
                      "backends/tmpl", "templates", "frontend", "passes", "ir", "ir/support"],
    "stdlib/runtime": [],
    "sim": [],
    "sim/robot": ["sim", "stdlib/runtime"],
    "sim/ros": ["sim/robot", "sim"],
}
# Public include prefixes of the components whose headers are installed under smachac/.
INSTALLED_PREFIXES = {"smachac/runtime/": "stdlib/runtime", "smachac/sim/": "sim",
                      "smachac/robot/": "sim/robot"}
# CMake library -> component.
TARGETS = {
    "smachac_support": "ir/support", "smachac_ir": "ir", "smachac_frontend": "frontend",
    "smachac_passes": "passes", "smachac_templates": "templates", "smachac_tmpl": "backends/tmpl",
    "smachac_generator": "backends/generator", "smachac_backends": "backends",
    "smachac_refactor": "refactor", "smachac_checker": "checker", "smachac_lsp": "lsp",
    "smachac": "tools/smachac",
    "smachac_runtime": "stdlib/runtime", "smachac::runtime": "stdlib/runtime",
    "smachac_sim": "sim", "smachac::sim": "sim", "smachac_sim_robot": "sim/robot",
    "smachac::sim_robot": "sim/robot", "smachac_sim_bridge": "sim/ros",
}
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]')
SOURCE_SUFFIXES = (".cpp", ".h")


def component_of(path):
    """The component whose folder holds `path` (relative to the root), or None."""
    best = None
    for component in ALLOWED:
        if path == component or path.startswith(component + "/"):
            if best is None or len(component) > len(best):
                best = component
    return best


def included_component(root, header):
    for prefix, component in INSTALLED_PREFIXES.items():
        if header.startswith(prefix):
            return component
    if os.path.exists(os.path.join(root, header)):
        return component_of(header)
    return None  # a system or third-party header


def include_violations(root):
    found = []
    for folder, dirs, files in os.walk(root):
        dirs[:] = [d for d in dirs if not d.startswith(("build", "."))]
        for name in files:
            if not name.endswith(SOURCE_SUFFIXES) or ".tpl." in name:
                continue
            path = os.path.relpath(os.path.join(folder, name), root)
            source = component_of(path)
            if source is None:
                continue  # tests, bench, examples: may use everything
            with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
                for number, line in enumerate(f, 1):
                    match = INCLUDE.match(line)
                    target = match and included_component(root, match.group(1))
                    if target and target != source and target not in ALLOWED[source]:
                        found.append("%s:%d: %s includes %s (%s -> %s)" %
                                     (path, number, source, match.group(1), source, target))
    return found


def link_violations(links):
    found = []
    for target, linked in sorted(links.items()):
        source = TARGETS.get(target)
        for item in linked:
            other = TARGETS.get(item)
            if source and other and other != source and other not in ALLOWED[source]:
                found.append("%s links %s (%s -> %s)" % (target, item, source, other))
    return found


def include_dir_violations(root, include_dirs):
    """A library may compile with its own include root (include_roots/<library>), folders
    inside its own component folder, and folders outside the sources; never with a folder of
    the sources that reaches other components' headers (the repository root, say)."""
    found = []
    root = os.path.realpath(root)
    for target, folders in sorted(include_dirs.items()):
        component = TARGETS.get(target)
        for folder in filter(None, folders):  # "": an install-only generator expression
            path = os.path.realpath(folder)
            if "/include_roots/" in folder:
                if not folder.rstrip("/").endswith("/include_roots/" + target):
                    found.append("%s compiles with another library's include root %s" %
                                 (target, folder))
                continue
            inside = os.path.relpath(path, root)
            if inside.startswith("..") or component is None:
                continue
            if inside != component and not inside.startswith(component + "/"):
                found.append("%s compiles with %s, outside its folder %s (each library "
                             "exports only its own include root)" % (target, folder, component))
    return found


def main():
    root, links_json, include_dirs_json = sys.argv[1], sys.argv[2], sys.argv[3]
    with open(links_json, encoding="utf-8") as f:
        links = json.load(f)
    with open(include_dirs_json, encoding="utf-8") as f:
        include_dirs = json.load(f)
    missing = sorted(t for t in links if t not in TARGETS)
    problems = include_violations(root) + link_violations(links)
    problems += include_dir_violations(root, include_dirs)
    problems += ["%s: a library the graph does not know" % t for t in missing]
    for problem in problems:
        print("FAIL " + problem)
    print("%d libraries, %d components checked; %d problems" %
          (len(links), len(ALLOWED), len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
