#!/usr/bin/env python3
"""Structural checks of generated FlexBE behaviors (ROS 1 and ROS 2), read from their source.

  flexbe_structure.py <golden dir> [<golden dir> ...]
  flexbe_structure.py --self-test

The real flexbe_core builds and runs every ROS 1 behavior (tests/ros/flexbe_goldens.py) and
rejects what FlexBE rejects there: a state added outside a `with` block, twice or under a
container outcome's name, a transition to an unknown target (when its container starts), an
outcome without a transition or an autonomy level (FlexBE's structure message for the
operator's mirror), an embedded behavior used before it is added or twice, a node passed to a
ROS 1 add_behavior, an undefined `self.<parameter>`, a container without states (when it
starts), a manifest naming no behavior. FlexBE does not check the rest, and ROS 2 behaviors
cannot run here (Debian 12 has no rclpy), so every expected behavior (`*.flexbe.py`, files
separated by `#==> <name> <==` lines) is checked here from its Python source (ast), per
container of each create():

  states       added inside `with <container>:`, each label once and not a container outcome;
               a container has states
  transitions  the same outcomes as the autonomy levels, and as the state's outcomes where
               the source knows them (containers, embedded behaviors, the behavior's own
               states module); a target is a sibling or a container outcome (in a
               ConcurrencyContainer, a container outcome only)
  autonomy     `Autonomy.<Inherit|Off|Low|High|Full>`, the shape the FlexBE editor reads
  remapping    omitted when empty (FlexBE's editor cannot parse `remapping={}`); string key
               names; keys of the state where the source knows them
  conditions   of a ConcurrencyContainer: its outcomes, its states and their outcomes
  behaviors    add_behavior once per id, with a node for ROS 2 and without for ROS 1; every
               added id used once, with the class it was added as; parameters the embedded
               behavior declares with add_parameter; `self.<name>` in create() is defined
  LogState     severity `Logger.REPORT_*`
  manifests    package_path and class name a behavior class of the case

Exit 0 when every behavior passes, 1 with "<dir>/<case>/<file>: <error>" lines otherwise.
"""
import ast
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import flexbe_check  # noqa: E402  (split_expected)

LEVELS = {"Inherit", "Off", "Low", "High", "Full"}
SEVERITIES = {"REPORT_INFO", "REPORT_WARN", "REPORT_HINT", "REPORT_ERROR", "REPORT_DEBUG"}
CONTAINERS = {"OperatableStateMachine", "ConcurrencyContainer", "PriorityContainer"}
BEHAVIOR_ATTRIBUTES = {"name", "node", "contains", "id"}
PACKAGE_PATH = re.compile(r"""package_path['"]?\s*[:=]\s*['"](\w+)\.(\w+)['"]""")
CLASS = re.compile(r"""['"]?class['"]?\s*[:=]\s*['"](\w+)['"]""")


def literal(node, default=None):
    try:
        return ast.literal_eval(node)
    except (ValueError, TypeError, SyntaxError):
        return default


def keywords(call):
    return {k.arg: k.value for k in call.keywords if k.arg}


def call_name(call):
    """`f`, `obj.f` or `self.f` of a call, as text."""
    return ast.unparse(call.func) if isinstance(call, ast.Call) else ""


# ---------------------------------------------------------------- what the source declares

class StateKinds:
    """Outcomes and keys of the states a case defines: {class: (outcomes, keys or None)}."""

    def __init__(self, files):
        self.known = {}
        for name, text in files.items():
            if name.endswith("_states.py"):
                self.read(ast.parse(text))

    def read(self, tree):
        for cls in [n for n in tree.body if isinstance(n, ast.ClassDef)]:
            for call in ast.walk(cls):
                if isinstance(call, ast.Call) and call_name(call).endswith("__init__"):
                    args = keywords(call)
                    outcomes = literal(args.get("outcomes"))
                    keys = [literal(args.get(k), None if k in args else []) for k in
                            ("input_keys", "output_keys", "io_keys")]
                    if isinstance(outcomes, list):
                        self.known[cls.name] = (outcomes, None if None in keys else sum(keys, []))


class Container:
    def __init__(self, kind, call):
        args = keywords(call)
        self.kind = kind
        self.outcomes = literal(args.get("outcomes"), [])
        self.keys = literal(args.get("input_keys"), []) + literal(args.get("output_keys"), [])
        self.conditions = literal(args.get("conditions"), [])
        self.states = []  # (label, state node, transitions, autonomy, remapping)
        self.added = False


class BehaviorClass:
    """One Behavior subclass: __init__'s declarations and create()'s containers."""

    def __init__(self, node):
        self.name = node.name
        methods = {f.name: f for f in node.body if isinstance(f, ast.FunctionDef)}
        self.init = methods.get("__init__")
        self.create = methods.get("create")
        self.ros2 = self.init is not None and len(self.init.args.args) > 1
        self.parameters, self.attributes, self.adds = [], set(BEHAVIOR_ATTRIBUTES), []
        self.containers = {}  # create()'s containers by variable, once CreateReader read it
        for call in ast.walk(self.init) if self.init else []:
            self.read_init(call)

    def read_init(self, node):
        if isinstance(node, ast.Attribute) and isinstance(node.ctx, ast.Store):
            self.attributes.add(node.attr)
        if call_name(node) == "self.add_parameter":
            self.parameters.append(literal(node.args[0]))
            self.attributes.add(self.parameters[-1])
        elif call_name(node) == "self.add_behavior":
            self.adds.append((ast.unparse(node.args[0]), literal(node.args[1]),
                              len(node.args) > 2))

    def root(self):
        """The container create() returns, once create() was read."""
        returned = [n.value for n in ast.walk(self.create or ast.Pass())
                    if isinstance(n, ast.Return)]
        if not returned or not isinstance(returned[-1], ast.Name):
            return None
        return self.containers.get(returned[-1].id)


# ---------------------------------------------------------------- reading create()

class CreateReader:
    """Reads create() statement by statement into containers; collects errors and uses."""

    def __init__(self, behavior):
        self.behavior = behavior
        self.containers = {}
        self.uses = []  # (class, id, parameters, default keys)
        self.errors = []
        self.opened = []

    def read(self):
        if self.behavior.create is None:
            self.errors.append("no create()")
            return
        self.statements(self.behavior.create.body)
        self.self_references()
        self.behavior.containers = self.containers

    def statements(self, body):
        for statement in body:
            if isinstance(statement, ast.With):
                self.opened.append(ast.unparse(statement.items[0].context_expr))
                self.statements(statement.body)
                self.opened.pop()
            elif isinstance(statement, ast.Assign) and isinstance(statement.value, ast.Call) \
                    and call_name(statement.value) in CONTAINERS:
                self.containers[statement.targets[0].id] = Container(
                    call_name(statement.value), statement.value)
            elif isinstance(statement, ast.Expr) and \
                    call_name(statement.value) == "OperatableStateMachine.add":
                self.add(statement.value)

    def add(self, call):
        args, label = keywords(call), literal(call.args[0])
        if not self.opened or self.opened[-1] not in self.containers:
            self.errors.append("OperatableStateMachine.add(%r) outside a `with <container>:` "
                               "block" % label)
            return
        state = call.args[1]
        if isinstance(state, ast.Name) and state.id in self.containers:
            self.containers[state.id].added = True
        if call_name(state) == "self.use_behavior":
            self.use(state)
        self.severity(label, state)
        self.containers[self.opened[-1]].states.append(
            (label, state, args.get("transitions"), args.get("autonomy"), args.get("remapping")))

    def use(self, call):
        args = keywords(call)
        parameters = args.get("parameters")
        names = [literal(k) for k in parameters.keys] if isinstance(parameters, ast.Dict) else []
        self.uses.append((ast.unparse(call.args[0]), literal(call.args[1]), names,
                          literal(args.get("default_keys"), [])))

    def severity(self, label, state):
        if call_name(state) != "LogState":
            return
        value = keywords(state).get("severity")
        written = ast.unparse(value) if value is not None else None
        if written is not None and not written.startswith("self.") and \
                written not in {"Logger." + s for s in SEVERITIES}:
            self.errors.append("state %r: LogState severity %s is not a Logger.REPORT_* level"
                               % (label, ast.unparse(value)))

    def self_references(self):
        read = {node.attr for node in ast.walk(self.behavior.create)
                if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name)
                and node.value.id == "self"}
        for name in sorted(read - self.behavior.attributes):
            if not callable_member(name):
                self.errors.append("create() reads self.%s, which __init__ does not define "
                                   "(add_parameter)" % name)


def callable_member(name):
    return name in {"use_behavior", "add_behavior", "add_parameter"} or name.startswith("_")


# ---------------------------------------------------------------- checks of one container

def dict_keys(node):
    return [literal(k) for k in node.keys] if isinstance(node, ast.Dict) else None


class ContainerCheck:
    """The errors of one container, given what is known of its states' outcomes and keys."""

    def __init__(self, container, interface_of):
        self.container = container
        self.interface_of = interface_of  # state node -> (outcomes, keys) or (None, None)
        self.labels = [label for label, *_ in container.states]
        self.outcomes_of = {}

    def errors(self):
        if not self.container.states:
            return ["the container has no states"]
        errors = []
        for label in sorted({l for l in self.labels if self.labels.count(l) > 1}):
            errors.append("state %r is added twice" % label)
        for label, state, transitions, autonomy, remapping in self.container.states:
            errors += ["state %r: %s" % (label, e) for e in
                       self.state_errors(label, state, transitions, autonomy, remapping)]
        return errors + self.condition_errors()

    def state_errors(self, label, state, transitions, autonomy, remapping):
        errors = ["the label is an outcome of the container"] \
            if label in self.container.outcomes else []
        outcomes, keys = self.interface_of(state)
        given, levels = dict_keys(transitions), dict_keys(autonomy)
        if given is None or levels is None:
            return errors + ["transitions and autonomy must be dict literals"]
        self.outcomes_of[label] = outcomes if outcomes is not None else given
        errors += [f"outcome {o!r} has no transition" for o in (outcomes or levels)
                   if o not in given]
        errors += [f"outcome {o!r} has no autonomy level" for o in (outcomes or given)
                   if o not in levels]
        if outcomes is not None:
            errors += [f"transition of {o!r}, which is not one of its outcomes {outcomes}"
                       for o in given if o not in outcomes]
        errors += self.target_errors(transitions)
        errors += self.level_errors(autonomy)
        return errors + self.remapping_errors(remapping, keys)

    def target_errors(self, transitions):
        concurrent = self.container.kind == "ConcurrencyContainer"
        valid = self.container.outcomes + ([] if concurrent else self.labels)
        kinds = ("one of the concurrency container's outcomes %s" if concurrent else
                 "a state of the container nor one of its outcomes %s") % self.container.outcomes
        return [f"outcome {o!r} goes to {literal(t)!r}, which is neither {kinds}"
                if not concurrent else f"outcome {o!r} goes to {literal(t)!r}, not {kinds}"
                for o, t in zip(dict_keys(transitions), transitions.values)
                if literal(t) not in valid]

    @staticmethod
    def level_errors(autonomy):
        return [f"autonomy of {literal(k)!r} is {ast.unparse(v)}, not an Autonomy level"
                for k, v in zip(autonomy.keys, autonomy.values)
                if not (isinstance(v, ast.Attribute) and ast.unparse(v.value) == "Autonomy"
                        and v.attr in LEVELS)]

    @staticmethod
    def remapping_errors(remapping, keys):
        if remapping is None:
            return []
        if not isinstance(remapping, ast.Dict):
            return ["remapping must be a dict literal"]
        if not remapping.keys:
            return ["remapping={} is written out; FlexBE's editor cannot parse it (its code "
                    "generator omits an empty remapping)"]
        errors = [f"remapping {literal(k)!r} -> {ast.unparse(v)} is not a key name"
                  for k, v in zip(remapping.keys, remapping.values)
                  if not isinstance(literal(v), str)]
        if keys is not None:
            errors += [f"remapping of {k!r}, which is none of its keys {keys}"
                       for k in dict_keys(remapping) if k not in keys]
        return errors

    def condition_errors(self):
        errors = []
        for outcome, children in self.container.conditions:
            if outcome not in self.container.outcomes:
                errors.append(f"condition of {outcome!r}, which is not one of the outcomes "
                              f"{self.container.outcomes}")
            for child, child_outcome in children:
                if child not in self.labels:
                    errors.append(f"condition {outcome!r} names {child!r}, which is not one "
                                  f"of its states {self.labels}")
                elif child_outcome not in self.outcomes_of.get(child, [child_outcome]):
                    errors.append(f"condition {outcome!r}: {child_outcome!r} is not an "
                                  f"outcome of state {child!r}")
        return errors


# ---------------------------------------------------------------- checks of one case

class CaseCheck:
    """Every behavior module and manifest of one expected output."""

    def __init__(self, files):
        self.files = files
        self.kinds = StateKinds(files)
        self.behaviors = {}  # class name -> (module, BehaviorClass, CreateReader)
        self.errors = []
        for name in sorted(n for n in files if n.endswith("_sm.py")):
            self.read_module(name)

    def read_module(self, name):
        try:
            tree = ast.parse(self.files[name])
        except SyntaxError as error:
            self.errors.append(f"{name}: {error}")
            return
        classes = [n for n in tree.body if isinstance(n, ast.ClassDef)
                   and any(ast.unparse(b) == "Behavior" for b in n.bases)]
        if not classes:
            self.errors.append(f"{name}: no Behavior class")
        for node in classes:
            behavior = BehaviorClass(node)
            reader = CreateReader(behavior)
            reader.read()
            self.behaviors[behavior.name] = (name[:-3], behavior, reader)

    def interface_of(self, containers):
        def interface(state):
            if isinstance(state, ast.Name) and state.id in containers:
                return containers[state.id].outcomes, containers[state.id].keys
            if call_name(state) == "self.use_behavior":
                embedded = self.behaviors.get(ast.unparse(state.args[0]))
                root = embedded[1].root() if embedded else None
                return (root.outcomes, root.keys) if root else (None, None)
            return self.kinds.known.get(call_name(state), (None, None))
        return interface

    def check(self):
        errors = list(self.errors)
        for cls, (module, behavior, reader) in self.behaviors.items():
            where = f"{module}.py: {cls}"
            errors += [f"{where}: {e}" for e in reader.errors + self.behavior_errors(
                behavior, reader)]
            for var, container in reader.containers.items():
                check = ContainerCheck(container, self.interface_of(reader.containers))
                errors += [f"{where}: container {var}: {e}" for e in check.errors()]
        return errors + self.manifest_errors()

    def behavior_errors(self, behavior, reader):
        errors, added = [], {}
        for cls, bid, with_node in behavior.adds:
            if bid in added:
                errors.append(f"add_behavior({cls}, {bid!r}): the id is already added")
            added[bid] = cls
            if with_node != behavior.ros2:
                errors.append(f"add_behavior({cls}, {bid!r}): " + (
                    "a node is passed but the class takes none (ROS 1)" if with_node else
                    "the class takes a node (ROS 2) but none is passed"))
        used = [bid for _, bid, _, _ in reader.uses]
        for cls, bid, parameters, default_keys in reader.uses:
            errors += self.use_errors(cls, bid, parameters, default_keys, added, used)
        unused = sorted(set(added) - set(used))
        if unused:
            errors.append("added behaviors never used: " + ", ".join(unused))
        root = behavior.root()
        if root is None or root.added:
            errors.append("create() does not return its root state machine")
        return errors

    def use_errors(self, cls, bid, parameters, default_keys, added, used):
        where = f"use_behavior({cls}, {bid!r})"
        if bid not in added:
            return [f"{where}: the id was not added with add_behavior"]
        errors = [f"{where}: the id was added as {added[bid]}"] if added[bid] != cls else []
        if used.count(bid) > 1:
            errors.append(f"{where}: the id is used twice")
        embedded = self.behaviors.get(cls)
        if embedded is None:
            return errors + [f"{where}: no behavior class {cls} in the case"]
        declared = embedded[1].parameters
        errors += [f"{where}: {p!r} is not a parameter of {cls} (declared: {sorted(declared)})"
                   for p in parameters if p not in declared]
        root = embedded[1].root()
        return errors + [f"{where}: default key {k!r} is not an input key of the behavior"
                         for k in default_keys if root is not None and k not in root.keys]

    def manifest_errors(self):
        errors = []
        modules = {module: cls for cls, (module, _, _) in self.behaviors.items()}
        for name, text in self.files.items():
            if not (name.endswith("_manifest.py") or name.endswith(".xml")):
                continue
            path, cls = PACKAGE_PATH.search(text), CLASS.search(text)
            if path and path.group(2) not in modules:
                errors.append(f"{name}: package_path {path.group(1)}.{path.group(2)} is not "
                              "a behavior module of the case")
            elif path and cls and cls.group(1) not in self.behaviors:
                errors.append(f"{name}: {path.group(2)}.py defines no class {cls.group(1)}")
        return errors


def check_dirs(golden_dirs):
    """(errors, {case label: number of behaviors checked})."""
    errors, checked = [], {}
    for golden_dir in golden_dirs:
        area = os.path.basename(os.path.normpath(golden_dir))
        for case, files in flexbe_check.each_expected(golden_dir):
            label = area + "/" + case[:-len(".flexbe.py")]
            check = CaseCheck(files)
            errors += [f"{label}/{e}" for e in check.check()]
            checked[label] = len(check.behaviors)
    return errors, checked


def main(argv):
    if argv[:1] == ["--self-test"]:
        import flexbe_structure_self_test
        return flexbe_structure_self_test.run()
    if not argv:
        print(__doc__)
        return 2
    errors, checked = check_dirs(argv)
    for error in errors:
        print(error)
    if not errors:
        print(f"{len(checked)} cases, {sum(checked.values())} behaviors: every behavior has "
              "the structure FlexBE and its editor expect")
    return 1 if errors or not checked else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
