#!/usr/bin/env python3
"""Builds every generated FlexBE behavior of the golden tests against the strict flexbe_core
stand-in (flexbe_standin.py), so that structural mistakes in generated behaviors fail a test.

  flexbe_build.py [--roots-only] <golden dir> [<golden dir> ...]
  flexbe_build.py --self-test

For every expected `*.flexbe.py` (files separated by `#==> <name> <==` lines, read with
flexbe_check.split_expected) the files are written into a package directory named after the
manifest's package_path (every other `<x>_flexbe_behaviors` package the files import points
at the same directory). A subprocess then imports every `*_sm.py` module through that
package, instantiates each Behavior class defined there (`cls(node)` with a dummy node when
its __init__ takes a node, ROS 2; `cls()` for ROS 1) and calls create(); the stand-in checks
the structure as create() returns. By default every behavior is built, the ones embedded by
another (add_behavior) too; --roots-only builds only those no other behavior of the case
embeds. The SDK, ROS 1 and message stand-ins of baxter_python_run.py serve the Baxter states.

Exit 0 when every behavior builds, 1 with "<dir>/<case>/<file>: <error>" lines otherwise.
--self-test writes deliberately broken behaviors (and correct ones with embedded behaviors,
ROS 1 and ROS 2) and checks that exactly the broken ones are reported, with the right error.
"""
import importlib
import inspect
import json
import os
import re
import subprocess
import sys
import tempfile
import traceback

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import baxter_python_run  # noqa: E402  (stand-ins for the Baxter SDK, ROS 1 and messages)
import flexbe_check  # noqa: E402
import flexbe_standin  # noqa: E402

PACKAGE = re.compile(r"\b(\w+_flexbe_behaviors)\b")
PACKAGE_PATH = re.compile(r"""package_path['"]?\s*[:=]\s*['"](\w+)\.(\w+)['"]""")
CLASS = re.compile(r"""['"]?class['"]?\s*[:=]\s*['"](\w+)['"]""")
TIMEOUT = 120


# ---------------------------------------------------------------- stand-in environment

def write_stand_ins(directory):
    """The Baxter/ROS 1/message stand-ins of baxter_python_run, and the strict flexbe_core."""
    baxter_python_run.write_stubs(directory)
    os.remove(os.path.join(directory, "flexbe_core.py"))  # its lax flexbe_core is replaced
    flexbe_standin.install(directory)


# ---------------------------------------------------------------- one case, parent side

def manifest_entries(files):
    """[(file, package, module, class)] of the manifests (Python dict or XML) among the files."""
    entries = []
    for name, text in files.items():
        if name.endswith("_manifest.py") or name.endswith(".xml"):
            path, cls = PACKAGE_PATH.search(text), CLASS.search(text)
            if path:
                entries.append((name, path.group(1), path.group(2), cls.group(1) if cls else None))
    return entries


def write_case(files, directory, case):
    """Write the files as a package; return (package, manifest entries)."""
    manifests = manifest_entries(files)
    packages = sorted({m.group(1) for text in files.values() for m in PACKAGE.finditer(text)})
    main = manifests[0][1] if manifests else (packages[0] if packages
                                              else case + "_flexbe_behaviors")
    package_dir = os.path.join(directory, main)
    os.makedirs(package_dir)
    open(os.path.join(package_dir, "__init__.py"), "w").close()
    for name, text in files.items():
        with open(os.path.join(package_dir, name), "w", encoding="utf-8") as f:
            f.write(text)
    for other in set(packages) - {main}:
        os.makedirs(os.path.join(directory, other))
        with open(os.path.join(directory, other, "__init__.py"), "w") as f:
            f.write(f"__path__[:] = [{package_dir!r}]\n")
    return main, manifests


def build_case(label, files, stand_ins, roots_only):
    """(error lines, number of behaviors built) of one expected output."""
    behaviors = sorted(n for n in files if n.endswith("_sm.py"))
    if not behaviors:
        return [f"{label}: no *_sm.py behavior module"], 0
    with tempfile.TemporaryDirectory() as directory:
        package, manifests = write_case(files, directory, os.path.basename(label))
        request = {"paths": [stand_ins, directory], "package": package,
                   "modules": [n[:-3] for n in behaviors], "manifests": manifests,
                   "roots_only": roots_only}
        try:
            result = subprocess.run([sys.executable, os.path.abspath(__file__), "--run-case",
                                     json.dumps(request)], capture_output=True, text=True,
                                    timeout=TIMEOUT, cwd=directory)
        except subprocess.TimeoutExpired:
            return [f"{label}: building took more than {TIMEOUT} s"], 0
    if result.returncode != 0:
        return [f"{label}: the build process failed: {result.stderr.strip()}"], 0
    report = json.loads(result.stdout.strip().splitlines()[-1])
    errors = [f"{label}/{error}" for error in report["errors"]]
    if not errors and not report["built"]:
        errors = [f"{label}: no behavior class built"]
    return errors, report["built"]


def build_dirs(golden_dirs, roots_only=False):
    """(errors, {case label: number of behaviors built}) over every *.flexbe.py of the dirs."""
    errors, built = [], {}
    with tempfile.TemporaryDirectory() as stand_ins:
        write_stand_ins(stand_ins)
        for golden_dir in golden_dirs:
            for case in sorted(os.listdir(golden_dir)):
                if case.endswith(".flexbe.py"):
                    files = flexbe_check.split_expected(os.path.join(golden_dir, case))
                    label = os.path.basename(os.path.normpath(golden_dir)) + "/" + \
                        case[:-len(".flexbe.py")]
                    case_errors, built[label] = build_case(label, files, stand_ins, roots_only)
                    errors += case_errors
    return errors, built


# ---------------------------------------------------------------- one case, subprocess side

def describe(error):
    """The error, with where it was raised in a generated file when it is not the stand-in's."""
    text = f"{type(error).__name__}: {error}"
    if type(error).__name__ == "StandInError":
        return text
    frames = [f for f in traceback.extract_tb(error.__traceback__)
              if "_flexbe_behaviors" in f.filename or f.filename.endswith("_sm.py")
              or f.filename.endswith("_states.py")]
    if frames:
        text += f" (at {os.path.basename(frames[-1].filename)}:{frames[-1].lineno})"
    return text


def behavior_classes(module, behavior_base):
    return [cls for _, cls in inspect.getmembers(module, inspect.isclass)
            if issubclass(cls, behavior_base) and cls is not behavior_base
            and cls.__module__ == module.__name__]


def embedded_classes(classes, node, instantiate):
    """The classes another behavior adds with add_behavior (instantiation errors ignored here)."""
    embedded = set()
    for cls in classes:
        try:
            embedded |= {type(b) for b in instantiate(cls, node).contains.values()}
        except Exception:  # reported when the class itself is built
            pass
    return embedded


def build_one(cls, node, flexbe_core):
    flexbe_core.OperatableStateMachine._opened.clear()
    behavior = flexbe_core.instantiate(cls, node)
    behavior.create()


def check_manifests(request, modules):
    errors = []
    for manifest, package, module, cls in request["manifests"]:
        if package != request["package"] or module not in modules:
            errors.append(f"{manifest}: package_path {package}.{module} is not a behavior "
                          "module of the case")
        elif cls and not hasattr(modules[module], cls):
            errors.append(f"{manifest}: {module}.py defines no class {cls}")
    return errors


def run_case(request):
    """In the subprocess: import, instantiate and build; print a JSON report."""
    sys.path[:0] = request["paths"]
    import flexbe_core
    errors, built, modules, classes = [], 0, {}, []
    for name in request["modules"]:
        try:
            modules[name] = importlib.import_module(request["package"] + "." + name)
        except Exception as error:
            errors.append(f"{name}.py: import: {describe(error)}")
            continue
        found = behavior_classes(modules[name], flexbe_core.Behavior)
        if not found:
            errors.append(f"{name}.py: no Behavior class")
        classes += [(name, cls) for cls in found]
    errors += check_manifests(request, modules)
    node = flexbe_standin.DummyNode()
    skip = embedded_classes([c for _, c in classes], node, flexbe_core.instantiate) \
        if request["roots_only"] else set()
    for name, cls in classes:
        if cls in skip:
            continue
        try:
            build_one(cls, node, flexbe_core)
            built += 1
        except Exception as error:
            errors.append(f"{name}.py: {cls.__name__}: {describe(error)}")
    print(json.dumps({"errors": errors, "built": built}))
    return 0


# ---------------------------------------------------------------- self-test

HEADER = {
    1: "from flexbe_core import Behavior, Autonomy, OperatableStateMachine, "
       "ConcurrencyContainer, PriorityContainer, Logger\n",
    2: "from flexbe_core import Autonomy\nfrom flexbe_core import Behavior\n"
       "from flexbe_core import ConcurrencyContainer\nfrom flexbe_core import Logger\n"
       "from flexbe_core import OperatableStateMachine\nfrom flexbe_core import PriorityContainer\n"
       "from flexbe_core import initialize_flexbe_core\n",
}
STATES = '''from flexbe_core import EventState


class KeyState(EventState):
    def __init__(self):
        super(KeyState, self).__init__(outcomes=['ok', 'bad'], input_keys=['x'], output_keys=['y'])
'''


def behavior_module(cls, init, create, imports="", ros=2):
    """A behavior module in the generated shape; init and create are indented statements."""
    node = ", node" if ros == 2 else ""
    ros_init = ("        self.node = node\n        initialize_flexbe_core(node)\n"
                if ros == 2 else "")
    return (HEADER[ros] + "from flexbe_states.wait_state import WaitState\n"
            "from flexbe_states.log_state import LogState\n"
            "from sm_flexbe_behaviors.sm_states import KeyState\n" + imports +
            f"\n\nclass {cls}(Behavior):\n    def __init__(self{node}):\n"
            f"        super({cls}, self).__init__()\n        self.name = '{cls}'\n" + ros_init +
            "".join("        " + line + "\n" for line in init) +
            "\n    def create(self):\n" +
            "".join("        " + line + "\n" for line in create) +
            "        return _state_machine\n")


def wait(label, target="finished", extra=""):
    return (f"OperatableStateMachine.add('{label}', WaitState(wait_time=1), "
            f"transitions={{'done': '{target}'}}, autonomy={{'done': Autonomy.Off}}, "
            f"remapping={{{extra}}})")


ROOT = "_state_machine = OperatableStateMachine(outcomes=['finished', 'failed'])"
PICK = "from sm_flexbe_behaviors.pick_block_sm import PickBlockSM\n"


def pick_block(ros):
    return behavior_module("PickBlockSM", ["self.add_parameter('speed', 0.5)"], [
        "_state_machine = OperatableStateMachine(outcomes=['finished', 'failed'], "
        "input_keys=['x'], output_keys=['y'])",
        "with _state_machine:",
        "    OperatableStateMachine.add('KEY', KeyState(), transitions={'ok': 'WAIT', "
        "'bad': 'failed'}, autonomy={'ok': Autonomy.Off, 'bad': Autonomy.High}, "
        "remapping={'x': 'x', 'y': 'y'})",
        "    OperatableStateMachine.add('WAIT', WaitState(wait_time=self.speed), "
        "transitions={'done': 'finished'}, autonomy={'done': Autonomy.Off}, remapping={})"],
        ros=ros)


def main_with_pick(ros, init=None, use=None, extra_create=()):
    node = ", node" if ros == 2 else ""
    init = init if init is not None else [f"self.add_behavior(PickBlockSM, 'PICK_BLOCK'{node})"]
    use = use or "self.use_behavior(PickBlockSM, 'PICK_BLOCK', parameters={'speed': 0.1})"
    return behavior_module("MainSM", init, [
        ROOT, "with _state_machine:",
        f"    OperatableStateMachine.add('PICK_BLOCK', {use}, transitions={{'finished': "
        "'finished', 'failed': 'failed'}, autonomy={'finished': Autonomy.Off, 'failed': "
        "Autonomy.Off}, remapping={'x': 'a', 'y': 'b'})", *extra_create], imports=PICK, ros=ros)


def case_files(sm_files, manifest_class="MainSM", manifest_module="sm_sm"):
    files = {"sm_manifest.py": f"manifest = {{'executable': {{'package_path': "
                               f"'sm_flexbe_behaviors.{manifest_module}', "
                               f"'class': '{manifest_class}'}}}}\n",
             "sm_states.py": STATES}
    files.update(sm_files)
    return files


def simple(create, init=(), ros=2):
    """A one-module case whose create() is ROOT + the given lines."""
    return case_files({"sm_sm.py": behavior_module("MainSM", list(init), [ROOT] + create, ros=ros)})


SELF_TESTS = {  # case: (files, expected error text or None when it must build)
    "good_ros2_embedded": (case_files({"sm_sm.py": main_with_pick(2),
                                       "pick_block_sm.py": pick_block(2)}), None),
    "good_ros1_embedded": (case_files({"sm_sm.py": main_with_pick(1),
                                       "pick_block_sm.py": pick_block(1)}), None),
    "good_concurrency": (simple([
        "_sm_con = ConcurrencyContainer(outcomes=['done', 'failed'], conditions=[('done', "
        "[('A', 'done'), ('B', 'done')]), ('failed', [('K', 'bad')])])",
        "with _sm_con:", "    " + wait("A", "done"), "    " + wait("B", "done"),
        "    OperatableStateMachine.add('K', KeyState(), transitions={'ok': 'done', 'bad': "
        "'failed'}, autonomy={'ok': Autonomy.Off, 'bad': Autonomy.Off}, remapping={'x': 'x'})",
        "with _state_machine:",
        "    OperatableStateMachine.add('CON', _sm_con, transitions={'done': 'finished', "
        "'failed': 'failed'}, autonomy={'done': Autonomy.Off, 'failed': Autonomy.Off}, "
        "remapping={})"]), None),
    "unconnected_outcome": (simple([
        "with _state_machine:",
        "    OperatableStateMachine.add('K', KeyState(), transitions={'ok': 'finished'}, "
        "autonomy={'ok': Autonomy.Off, 'bad': Autonomy.Off}, remapping={})"]),
        "outcome 'bad' has no transition"),
    "missing_target": (simple(["with _state_machine:", "    " + wait("A", "NOWHERE")]),
                       "goes to 'NOWHERE'"),
    "use_without_add": (case_files({"sm_sm.py": main_with_pick(2, init=[]),
                                    "pick_block_sm.py": pick_block(2)}),
                        "was not added with add_behavior"),
    "undeclared_parameter": (case_files({
        "sm_sm.py": main_with_pick(2, use="self.use_behavior(PickBlockSM, 'PICK_BLOCK', "
                                          "parameters={'velocity': 0.1})"),
        "pick_block_sm.py": pick_block(2)}), "'velocity' is not a parameter of PickBlockSM"),
    "bad_remapping_key": (simple(["with _state_machine:", "    " + wait("A", extra="'x': 'x'")]),
                          "remapping of 'x', which is none of its keys"),
    "added_not_used": (case_files({
        "sm_sm.py": main_with_pick(2, init=["self.add_behavior(PickBlockSM, 'PICK_BLOCK', node)",
                                            "self.add_behavior(PickBlockSM, 'OTHER', node)"]),
        "pick_block_sm.py": pick_block(2)}), "added behaviors never used: OTHER"),
    "added_twice": (case_files({
        "sm_sm.py": main_with_pick(2, init=["self.add_behavior(PickBlockSM, 'PICK_BLOCK', "
                                            "node)"] * 2),
        "pick_block_sm.py": pick_block(2)}), "the id is already added"),
    "ros1_add_with_node": (case_files({
        "sm_sm.py": main_with_pick(1, init=["self.add_behavior(PickBlockSM, 'PICK_BLOCK', 7)"]),
        "pick_block_sm.py": pick_block(1)}), "the class takes none"),
    "duplicate_label": (simple(["with _state_machine:", "    " + wait("A"), "    " + wait("A")]),
                        "state 'A' is added twice"),
    "add_outside_with": (simple([wait("A")]), "outside a `with <container>:` block"),
    "empty_container": (simple(["_sm_x = OperatableStateMachine(outcomes=['done'])",
                                "with _sm_x:", "    pass", "with _state_machine:",
                                "    " + wait("A")]), "has no states"),
    "autonomy_not_a_level": (simple([
        "with _state_machine:",
        "    OperatableStateMachine.add('A', WaitState(wait_time=1), transitions={'done': "
        "'finished'}, autonomy={'done': 0}, remapping={})"]), "not an Autonomy level"),
    "autonomy_unknown_outcome": (simple([
        "with _state_machine:",
        "    OperatableStateMachine.add('A', WaitState(wait_time=1), transitions={'done': "
        "'finished'}, autonomy={'done': Autonomy.Off, 'fail': Autonomy.Off}, remapping={})"]),
        "autonomy of 'fail', which is not one of its outcomes"),
    "concurrency_bad_condition": (simple([
        "_sm_con = ConcurrencyContainer(outcomes=['done'], conditions=[('done', [('A', 'done'), "
        "('Z', 'done')]), ('other', [('A', 'nope')])])",
        "with _sm_con:", "    " + wait("A", "done"),
        "with _state_machine:",
        "    OperatableStateMachine.add('CON', _sm_con, transitions={'done': 'finished'}, "
        "autonomy={'done': Autonomy.Off}, remapping={})"]),
        "names 'Z', which is not one of its states"),
    "concurrency_sibling_target": (simple([
        "_sm_con = ConcurrencyContainer(outcomes=['done'], conditions=[('done', [('B', 'done')])])",
        "with _sm_con:", "    " + wait("A", "B"), "    " + wait("B", "done"),
        "with _state_machine:",
        "    OperatableStateMachine.add('CON', _sm_con, transitions={'done': 'finished'}, "
        "autonomy={'done': Autonomy.Off}, remapping={})"]),
        "one of the concurrency container's outcomes"),
    "missing_self_parameter": (simple([
        "with _state_machine:",
        "    OperatableStateMachine.add('A', WaitState(wait_time=self.speed), transitions="
        "{'done': 'finished'}, autonomy={'done': Autonomy.Off}, remapping={})"]),
        "AttributeError: 'MainSM' object has no attribute 'speed'"),
    "bad_log_severity": (simple([
        "with _state_machine:",
        "    OperatableStateMachine.add('L', LogState(text='x', severity='loud'), transitions="
        "{'done': 'finished'}, autonomy={'done': Autonomy.Off}, remapping={})"]),
        "is not a Logger.REPORT_* level"),
    "manifest_wrong_class": (dict(simple(["with _state_machine:", "    " + wait("A")]),
                                  **{"sm_manifest.py": "manifest = {'executable': {'package_path':"
                                     " 'sm_flexbe_behaviors.sm_sm', 'class': 'OtherSM'}}\n"}),
                             "defines no class OtherSM"),
}


def self_test():
    failures = []
    with tempfile.TemporaryDirectory() as golden:
        for case, (files, _) in SELF_TESTS.items():
            with open(os.path.join(golden, case + ".flexbe.py"), "w", encoding="utf-8") as f:
                f.write("".join(f"#==> {name} <==\n{text}" for name, text in files.items()))
        for roots_only in (False, True):
            errors, built = build_dirs([golden], roots_only)
            failures += self_test_failures(errors, built, os.path.basename(golden), roots_only)
    for failure in failures:
        print("FAIL " + failure)
    print(f"self-test: {len(SELF_TESTS)} cases, each built with all behaviors and roots only: "
          f"{len(failures)} failures")
    return 1 if failures else 0


def self_test_failures(errors, built, prefix, roots_only):
    mode = "roots only" if roots_only else "all behaviors"
    failures = []
    for case, (files, expected) in SELF_TESTS.items():
        reported = [e for e in errors if e.startswith(f"{prefix}/{case}/")
                    or e.startswith(f"{prefix}/{case}:")]
        modules = len([n for n in files if n.endswith("_sm.py")])
        if expected is None and reported:
            failures.append(f"{case} ({mode}) must build: {reported}")
        elif expected is None and built[f"{prefix}/{case}"] != (1 if roots_only else modules):
            failures.append(f"{case} ({mode}): {built[prefix + '/' + case]} behaviors built")
        elif expected is not None and not any(expected in e for e in reported):
            failures.append(f"{case} ({mode}): expected an error with {expected!r}, got {reported}")
    return failures


def main(argv):
    if argv[:1] == ["--run-case"]:
        return run_case(json.loads(argv[1]))
    if argv[:1] == ["--self-test"]:
        return self_test()
    roots_only = "--roots-only" in argv
    dirs = [a for a in argv if a != "--roots-only"]
    if not dirs:
        print(__doc__)
        return 2
    errors, built = build_dirs(dirs, roots_only)
    for error in errors:
        print(error)
    if not errors:
        print(f"{len(built)} cases, {sum(built.values())} behaviors: every behavior builds "
              "against the strict flexbe_core stand-in")
    return 1 if errors or not built else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
