"""Strict stand-in for flexbe_core (tests/harness/flexbe_standin.py): builds behaviors only."""
import inspect


class StandInError(Exception):
    """A behavior that real FlexBE or its editor would reject."""


# ---------------------------------------------------------------- autonomy, logging, setup

class AutonomyLevel(int):
    """An autonomy level: an int that remembers its name, so Inherit and Off differ."""

    def __new__(cls, value, name):
        level = int.__new__(cls, value)
        level.level_name = name
        return level

    def __repr__(self):
        return "Autonomy." + self.level_name


class Autonomy:
    Inherit = AutonomyLevel(0, "Inherit")
    Off = AutonomyLevel(0, "Off")
    Low = AutonomyLevel(1, "Low")
    High = AutonomyLevel(2, "High")
    Full = AutonomyLevel(3, "Full")


AUTONOMY_LEVELS = (Autonomy.Inherit, Autonomy.Off, Autonomy.Low, Autonomy.High, Autonomy.Full)


def is_autonomy_level(value):
    return any(value is level for level in AUTONOMY_LEVELS)


class Logger:
    REPORT_INFO = 0
    REPORT_WARN = 1
    REPORT_HINT = 2
    REPORT_ERROR = 3
    REPORT_DEBUG = 4
    SEVERITIES = (0, 1, 2, 3, 4)
    messages = []
    _node = None

    @staticmethod
    def initialize(node):
        Logger._node = node

    @staticmethod
    def log(text, severity):
        if severity not in Logger.SEVERITIES:
            raise StandInError("unknown log severity %r" % (severity,))
        Logger.messages.append((severity, str(text)))

    @staticmethod
    def logdebug(text, *args):
        Logger.log(text % args if args else text, Logger.REPORT_DEBUG)

    @staticmethod
    def loginfo(text, *args):
        Logger.log(text % args if args else text, Logger.REPORT_INFO)

    @staticmethod
    def logwarn(text, *args):
        Logger.log(text % args if args else text, Logger.REPORT_WARN)

    @staticmethod
    def loghint(text, *args):
        Logger.log(text % args if args else text, Logger.REPORT_HINT)

    @staticmethod
    def logerr(text, *args):
        Logger.log(text % args if args else text, Logger.REPORT_ERROR)

    localdebug = logdebug
    localinfo = loginfo
    localwarn = logwarn
    localerr = logerr


class _RosInitialized:
    node = None


def initialize_flexbe_core(node):
    """ROS 2 (>= 3.0.7): one call in the behavior's __init__."""
    if node is None:
        raise StandInError("initialize_flexbe_core(None): the behavior was given no node")
    _RosInitialized.node = node
    Logger.initialize(node)
    EventState._node = node


# ---------------------------------------------------------------- states

def _string_list(what, value):
    if not isinstance(value, (list, tuple)) or not all(isinstance(v, str) for v in value):
        raise StandInError("%s must be a list of strings, not %r" % (what, value))
    return list(dict.fromkeys(value))


class State:
    """What every state and container has: outcomes, keys, a name and a parent once added."""

    _node = None

    def __init__(self, *args, **kwargs):
        if args:
            raise StandInError("%s: state arguments are keywords (outcomes=, input_keys=, "
                               "output_keys=), got positional %r" % (type(self).__name__, args))
        unknown = set(kwargs) - {"outcomes", "input_keys", "output_keys", "io_keys"}
        if unknown:
            raise StandInError("%s: unknown state arguments %s"
                               % (type(self).__name__, sorted(unknown)))
        io_keys = _string_list("io_keys", kwargs.get("io_keys", []))
        self._outcomes = _string_list("outcomes", kwargs.get("outcomes", []))
        self._input_keys = _string_list("input_keys", kwargs.get("input_keys", []) + io_keys)
        self._output_keys = _string_list("output_keys", kwargs.get("output_keys", []) + io_keys)
        if not self._outcomes:
            raise StandInError("%s: a state needs at least one outcome" % type(self).__name__)
        self._name = None
        self._parent = None

    @classmethod
    def initialize_ros(cls, node):
        """ROS 2 (2.x style): one call per state class in the behavior's __init__."""
        State._node = node

    @property
    def outcomes(self):
        return self._outcomes

    @property
    def input_keys(self):
        return self._input_keys

    @property
    def output_keys(self):
        return self._output_keys

    @property
    def name(self):
        return self._name

    @property
    def parent(self):
        return self._parent

    @property
    def path(self):
        if self._parent is None:
            return self._name or ""
        return self._parent.path + "/" + self._name

    def describe(self):
        return self.path or "the root state machine"

    def set_name(self, value):
        if self._name is not None:
            raise StandInError("state %r is added again as %r (a state instance is added once)"
                               % (self._name, value))
        self._name = value

    def set_parent(self, value):
        self._parent = value


class EventState(State):
    """Base of user states: super().__init__(outcomes=[...], input_keys=[...], output_keys=...)."""

    def on_enter(self, userdata):
        pass

    def on_exit(self, userdata):
        pass

    def on_start(self):
        pass

    def on_stop(self):
        pass

    def execute(self, userdata):
        return None


# ---------------------------------------------------------------- containers

class UserData:
    """Default userdata of a container: attributes set in create()."""


class OperatableStateMachine(State):
    """A container, opened with `with`; OperatableStateMachine.add adds to the opened one."""

    _opened = []

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self._labels = {}
        self._transitions = {}
        self._autonomy = {}
        self._remappings = {}
        self.userdata = UserData()

    def __enter__(self):
        OperatableStateMachine._opened.append(self)
        return self

    def __exit__(self, exc_type, exc, tb):
        OperatableStateMachine._opened.pop()
        if exc_type is None:
            self.check()
        return False

    def __contains__(self, label):
        return label in self._labels

    def __getitem__(self, label):
        return self._labels[label]

    @property
    def initial_state(self):
        return next(iter(self._labels.values()), None)

    @staticmethod
    def add(label, state, transitions=None, autonomy=None, remapping=None):
        if not OperatableStateMachine._opened:
            raise StandInError("OperatableStateMachine.add(%r) outside a `with <container>:` block"
                               % (label,))
        OperatableStateMachine._opened[-1]._add(label, state, transitions, autonomy, remapping)

    def _add(self, label, state, transitions, autonomy, remapping):
        where = "%s: state %r" % (self.describe_open(), label)
        if not isinstance(label, str) or not label:
            raise StandInError("%s: the label must be a non-empty string" % where)
        if label in self._labels:
            raise StandInError("%s is added twice" % where)
        if label in self._outcomes:
            raise StandInError("%s: the label is an outcome of the container" % where)
        if not isinstance(state, State):
            raise StandInError("%s: %r is not a state (None: a use_behavior that failed?)"
                               % (where, state))
        if not hasattr(state, "_outcomes"):
            raise StandInError("%s: %s.__init__ did not call EventState.__init__"
                               % (where, type(state).__name__))
        for what, value in (("transitions", transitions), ("autonomy", autonomy),
                            ("remapping", remapping)):
            if value is not None and not isinstance(value, dict):
                raise StandInError("%s: %s must be a dict, not %r" % (where, what, value))
        state.set_name(label)
        state.set_parent(self)
        self._labels[label] = state
        self._transitions[label] = dict(transitions or {})
        self._autonomy[label] = dict(autonomy or {})
        self._remappings[label] = dict(remapping or {})

    def describe_open(self):
        if self._name is not None or self._parent is not None:
            return self.describe()
        if not self._labels:
            return "the %s with outcomes %s" % (type(self).__name__, self._outcomes)
        return "the %s whose initial state is %r" % (type(self).__name__, next(iter(self._labels)))

    # ------------------------------------------------------------ checks

    def valid_targets(self, label):
        return list(self._labels) + self._outcomes

    def check(self):
        """Raise StandInError listing every structural error of this container."""
        errors = self.errors()
        if errors:
            raise StandInError("%s: %s" % (self.describe_open(), "; ".join(errors)))

    def errors(self):
        if not self._labels:
            return ["the container has no states"]
        errors = []
        for label, state in self._labels.items():
            errors += self._transition_errors(label, state)
            errors += self._autonomy_errors(label, state)
            errors += self._remapping_errors(label, state)
        return errors

    def _transition_errors(self, label, state):
        transitions = self._transitions[label]
        errors = _missing(label, state, transitions, "transition")
        for outcome, target in transitions.items():
            if outcome not in state.outcomes:
                errors.append("state %r: transition of %r, which is not one of its outcomes %s"
                              % (label, outcome, state.outcomes))
            elif target not in self.valid_targets(label):
                errors.append("state %r: outcome %r goes to %r, which is neither %s"
                              % (label, outcome, target, self.target_kinds()))
        return errors

    def target_kinds(self):
        return "a state of the container nor one of its outcomes %s" % self._outcomes

    def _autonomy_errors(self, label, state):
        autonomy = self._autonomy[label]
        errors = _missing(label, state, autonomy, "autonomy level")
        for outcome, level in autonomy.items():
            if outcome not in state.outcomes:
                errors.append("state %r: autonomy of %r, which is not one of its outcomes %s"
                              % (label, outcome, state.outcomes))
            if not is_autonomy_level(level):
                errors.append("state %r: autonomy of %r is %r, not an Autonomy level"
                              % (label, outcome, level))
        return errors

    def _remapping_errors(self, label, state):
        keys = state.input_keys + state.output_keys
        errors = []
        for key, value in self._remappings[label].items():
            if key not in keys:
                errors.append("state %r: remapping of %r, which is none of its keys %s"
                              % (label, key, keys))
            if not isinstance(value, str):
                errors.append("state %r: remapping %r -> %r is not a key name"
                              % (label, key, value))
        return errors

    def check_tree(self):
        """Every container of the tree, deepest first."""
        errors = []
        for state in self._labels.values():
            if isinstance(state, OperatableStateMachine):
                errors += state.check_tree()
        own = self.errors()
        if own:
            errors.append("%s: %s" % (self.describe_open(), "; ".join(own)))
        return errors


def _missing(label, state, given, what):
    """An error naming the outcomes of the state without an entry in given, or none."""
    missing = [o for o in state.outcomes if o not in given]
    if not missing:
        return []
    return ["state %r: outcome%s %s ha%s no %s" % (label, "s" if len(missing) > 1 else "",
                                                  ", ".join(repr(o) for o in missing),
                                                  "ve" if len(missing) > 1 else "s", what)]


class PriorityContainer(OperatableStateMachine):
    """A container whose active state pauses the others; same structure as a state machine."""


def _is_child_outcome(pair):
    return isinstance(pair, tuple) and len(pair) == 2 and all(isinstance(s, str) for s in pair)


class ConcurrencyContainer(OperatableStateMachine):
    """Runs its states in parallel; conditions=[(outcome, [(child, child_outcome), ...]), ...]."""

    def __init__(self, conditions=None, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self._conditions = self._checked_shape(conditions)

    def _checked_shape(self, conditions):
        shape = "conditions must be [(outcome, [(child, child_outcome), ...]), ...], not %r"
        if not isinstance(conditions, (list, tuple)):
            raise StandInError(shape % (conditions,))
        for item in conditions:
            ok = (isinstance(item, tuple) and len(item) == 2 and isinstance(item[0], str)
                  and isinstance(item[1], (list, tuple))
                  and all(_is_child_outcome(c) for c in item[1]))
            if not ok:
                raise StandInError(shape % (conditions,))
        return list(conditions)

    def valid_targets(self, label):
        return list(self._outcomes)

    def target_kinds(self):
        return "one of the concurrency container's outcomes %s" % self._outcomes

    def errors(self):
        errors = super().errors()
        for outcome, children in self._conditions:
            if outcome not in self._outcomes:
                errors.append("condition of %r, which is not one of the outcomes %s"
                              % (outcome, self._outcomes))
            for child, child_outcome in children:
                if child not in self._labels:
                    errors.append("condition %r names %r, which is not one of its states %s"
                                  % (outcome, child, list(self._labels)))
                elif child_outcome not in self._labels[child].outcomes:
                    errors.append("condition %r: %r is not an outcome of state %r %s"
                                  % (outcome, child_outcome, child, self._labels[child].outcomes))
        return errors


# ---------------------------------------------------------------- behaviors

def _class_name(cls):
    return getattr(cls, "__name__", repr(cls))


def takes_node(behavior_class):
    """Whether the class's __init__ takes a node (ROS 2) besides self."""
    parameters = list(inspect.signature(behavior_class.__init__).parameters.values())[1:]
    return any(p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD, p.VAR_POSITIONAL)
               for p in parameters)


def instantiate(behavior_class, node):
    return behavior_class(node) if takes_node(behavior_class) else behavior_class()


class Behavior:
    """Base of generated behaviors; a subclass's create() is checked when it returns."""

    def __init__(self):
        self.name = "unnamed behavior"
        self.contains = {}
        self._parameters = {}
        self._used = set()
        self._state_machine = None

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        create = cls.__dict__.get("create")
        if create is not None and not getattr(create, "_checked", False):
            cls.create = _checked_create(create)

    def create(self):
        raise StandInError("%s does not define create()" % type(self).__name__)

    def add_parameter(self, name, default):
        if name in self._parameters:
            raise StandInError("%s: parameter %r is added twice" % (self._label(), name))
        self._parameters[name] = default
        setattr(self, name, default)

    def add_behavior(self, behavior_class, behavior_id, node=None):
        where = "%s: add_behavior(%s, %r)" % (self._label(), _class_name(behavior_class),
                                              behavior_id)
        if not hasattr(self, "contains"):
            raise StandInError("%s before Behavior.__init__ (call the superclass constructor)"
                               % where)
        if not (isinstance(behavior_class, type) and issubclass(behavior_class, Behavior)):
            raise StandInError("%s: not a Behavior class" % where)
        if behavior_id in self.contains:
            raise StandInError("%s: the id is already added" % where)
        if takes_node(behavior_class) and node is None:
            raise StandInError("%s: the class takes a node (ROS 2) but none is passed" % where)
        if not takes_node(behavior_class) and node is not None:
            raise StandInError("%s: a node is passed but the class takes none (ROS 1)" % where)
        self.contains[behavior_id] = instantiate(behavior_class, node)

    def use_behavior(self, behavior_class, behavior_id, default_keys=None, parameters=None):
        where = "%s: use_behavior(%s, %r)" % (self._label(), _class_name(behavior_class),
                                              behavior_id)
        if behavior_id not in self.contains:
            raise StandInError("%s: the id was not added with add_behavior" % where)
        contained = self.contains[behavior_id]
        if type(contained) is not behavior_class:
            raise StandInError("%s: the id was added as %s" % (where, type(contained).__name__))
        if behavior_id in self._used:
            raise StandInError("%s: the id is used twice" % where)
        self._used.add(behavior_id)
        for name, value in (parameters or {}).items():
            if name not in contained._parameters:
                raise StandInError("%s: %r is not a parameter of %s (declared: %s)"
                                   % (where, name, behavior_class.__name__,
                                      sorted(contained._parameters)))
            setattr(contained, name, value)
        state_machine = contained.create()
        for key in default_keys or []:
            if key not in state_machine._input_keys:
                raise StandInError("%s: default key %r is not an input key of the behavior %s"
                                   % (where, key, state_machine._input_keys))
            state_machine._input_keys.remove(key)
        return state_machine

    def _label(self):
        return type(self).__name__


def _checked_create(create):
    def checked(self):
        self._used = set()
        opened = len(OperatableStateMachine._opened)
        state_machine = create(self)
        _check_built(self, state_machine, opened)
        self._state_machine = state_machine
        return state_machine
    checked._checked = True
    checked.__wrapped__ = create
    return checked


def _check_built(behavior, state_machine, opened):
    label = "%s.create()" % type(behavior).__name__
    if len(OperatableStateMachine._opened) != opened:
        raise StandInError("%s left a container open" % label)
    if not isinstance(state_machine, OperatableStateMachine):
        raise StandInError("%s returned %r, not a state machine" % (label, state_machine))
    if state_machine.parent is not None:
        raise StandInError("%s returned a state machine that is a state of another one" % label)
    errors = state_machine.check_tree()
    unused = sorted(set(behavior.contains) - behavior._used)
    if unused:
        errors.append("added behaviors never used: %s" % ", ".join(unused))
    if errors:
        raise StandInError("%s: %s" % (label, "; ".join(errors)))
