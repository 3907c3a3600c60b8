#!/usr/bin/env python3
"""A strict stand-in for flexbe_core and two flexbe_states library states, for building the
generated FlexBE behaviors where the real FlexBE is not installed (it is not packaged for
Debian).

MODULES maps module names to their Python source; install(directory) writes them there as
packages, so a subprocess with `directory` on sys.path imports them as flexbe_core,
flexbe_states.wait_state, ... The stand-in only builds behaviors (Behavior.create()); it
does not execute them. It is STRICT where real FlexBE is strict and where the FlexBE editor
rejects a behavior (facts: /work/shared/reference/peers.md §2 and FlexBE/flexbe_behavior_engine
flexbe_core), and raises StandInError then:

  OperatableStateMachine.add   outside a `with` block, a duplicate label, a label that is an
                               outcome of the container, a state added twice, a state whose
                               EventState.__init__ did not run
  a container, when closed     no states; an outcome without a transition, a transition of
  and at the end of create()   an unknown outcome or to a target that is neither a sibling
                               nor an outcome (a concurrency child: only container outcomes);
                               an outcome without an autonomy level (real FlexBE fails to
                               build the structure message then), an autonomy key that is not
                               an outcome, a level that is not an Autonomy constant; a
                               remapping key that is not an input or output key of the child;
                               a concurrency condition on an unknown outcome, child or child
                               outcome
  Behavior                     add_behavior of an id already added, or with/without a node
                               when the class's __init__ does not take/takes one;
                               use_behavior of an id not added, of another class, twice in
                               one create(), with a parameter the behavior did not declare
                               with add_parameter, with a default key that is not an input
                               key; an added behavior not used by create(); create()
                               returning something else than a state machine
  EventState.__init__          positional or unknown arguments, outcomes/keys not lists of
                               strings, no outcomes

Autonomy levels are int subclasses (Inherit and Off are both 0 but distinct objects), and
only those objects are accepted as levels.

Besides flexbe_states, `my_flexbe_states.wait_state.WaitState` (no parameter, outcome done)
stands for the second state package of the import_clash golden case
(tests/golden/flexbe/inputs/templates/OtherWaitState.tpl.py).
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))
# The flexbe_core stand-in is a real module (so that it can be read and linted as such).
with open(os.path.join(HERE, "standins", "flexbe_core.py"), encoding="utf-8") as _core:
    FLEXBE_CORE = _core.read()

WAIT_STATE = r'''
"""Stand-in for flexbe_states.wait_state (tests/harness/flexbe_standin.py)."""
from flexbe_core import EventState
from flexbe_core import StandInError


class WaitState(EventState):
    """Waits wait_time seconds. <= done"""

    def __init__(self, wait_time):
        super().__init__(outcomes=["done"])
        if isinstance(wait_time, bool) or not isinstance(wait_time, (int, float)):
            raise StandInError("WaitState: wait_time must be a number, not %r" % (wait_time,))
        self._wait_time = wait_time
'''

LOG_STATE = r'''
"""Stand-in for flexbe_states.log_state (tests/harness/flexbe_standin.py)."""
from flexbe_core import EventState
from flexbe_core import Logger
from flexbe_core import StandInError


class LogState(EventState):
    """Logs text at severity. <= done"""

    def __init__(self, text, severity=Logger.REPORT_HINT):
        super().__init__(outcomes=["done"])
        if isinstance(severity, bool) or severity not in Logger.SEVERITIES:
            raise StandInError("LogState: severity %r is not a Logger.REPORT_* level" % (severity,))
        self._text, self._severity = text, severity
'''

OTHER_WAIT_STATE = r'''
"""Stand-in for the second WaitState package of the import_clash golden case."""
from flexbe_core import EventState


class WaitState(EventState):
    """<= done"""

    def __init__(self):
        super().__init__(outcomes=["done"])
'''

PACKAGE_DOC = '"""Stand-in package (tests/harness/flexbe_standin.py)."""\n'

MODULES = {
    "flexbe_core": FLEXBE_CORE,
    "flexbe_states": PACKAGE_DOC,
    "flexbe_states.wait_state": WAIT_STATE,
    "flexbe_states.log_state": LOG_STATE,
    "my_flexbe_states": PACKAGE_DOC,
    "my_flexbe_states.wait_state": OTHER_WAIT_STATE,
}


class DummyNode:
    """What a ROS 2 behavior is given as its node: any attribute is a no-op callable."""

    def __getattr__(self, name):
        if name.startswith("__"):
            raise AttributeError(name)
        return lambda *args, **kwargs: DummyNode()


def install(directory):
    """Write MODULES under directory as packages (flexbe_core/__init__.py, ...)."""
    for name, source in MODULES.items():
        parts = name.split(".")
        package = os.path.join(directory, *parts[:1])
        os.makedirs(package, exist_ok=True)
        path = os.path.join(package, "__init__.py") if len(parts) == 1 else \
            os.path.join(directory, *parts[:-1], parts[-1] + ".py")
        with open(path, "w", encoding="utf-8") as f:
            f.write(source)
