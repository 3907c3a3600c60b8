#!/usr/bin/python3
"""Runs a generated FlexBE (ROS 1) behavior headless on the real flexbe_core, the way
flexbe_testing runs behaviors, and reports what happened in the trace protocol of
trace_protocol.py.

  run_flexbe.py BEHAVIOR [--param NAME=VALUE ...] [--seed N] [--autonomy LEVEL]
                [--preempt-after SECONDS]

BEHAVIOR is the behavior's name in its manifest. As flexbe_onboard does, flexbe_core's
BehaviorLibrary finds it among the packages on ROS_PACKAGE_PATH that export
`<flexbe_behaviors/>`; its package must also be on PYTHONPATH (the imports of embedded
behaviors and of the states module go through it). flexbe_testing's TestInterface then
instantiates the behavior, sets the parameters (Behavior.set_parameter, which casts each value
to the parameter's type; a name that is no parameter is an error), and spins the state machine
until it returns an outcome, after prepare_for_execution() and confirm().

Every state and container reports one enter (when it starts, before on_enter) and one exit
(when it returns an outcome: EventStates execute repeatedly), under its path: the labels from
the top state machine down, joined by `/`, the top one excluded. A state that its
ConcurrencyContainer leaves before it returned an outcome exits with the outcome null. The
result is the top state machine's outcome and its final userdata.

The autonomy level is flexbe_testing's 255 (every transition allowed) unless --autonomy gives
one (0 Off ... 3 Full): then a transition that requires at least that level is requested from
the operator, as FlexBE does; this runner plays the operator over the real topics, printing
    SMACHAC-FLEXBE-REQUEST {"state": PATH, "outcome": O, "required": LEVEL}
and confirming the requested outcome. Before running, the structure message that FlexBE sends
the operator's mirror is built once (it needs a transition and an autonomy level for every
outcome of every state). A state that raises makes FlexBE keep it active for the operator;
headless, that is reported as an error (exit 1) instead of waiting for ever.

With --preempt-after, FlexBE's preempt command (an Empty message on flexbe/command/preempt,
which every FlexBE state machine listens to) is published that many seconds after the
behavior starts; SIGUSR1 publishes it at any time.

FlexBE names its topics (commands, the operator's mirror, the log) relative to the node's
namespace. Runs that share a master at the same time must each get a namespace of their own
(ROS_NAMESPACE; RosSession.namespaced_env gives one), or each hears the others' commands: a
preempt, published latched, would end every run that starts while its publisher lives.
"""
import argparse
import json
import random
import os
import signal
import sys
import threading
import time
import traceback

import rospy

import trace_protocol

REQUEST = "SMACHAC-FLEXBE-REQUEST "
TESTING_AUTONOMY = 255  # flexbe_testing's level: no transition needs the operator
CONNECT_SECONDS = 5.0


class BehaviorError(Exception):
    """The behavior cannot run; the message says why (exit 1)."""


# ---------------------------------------------------------------- tracing the state tree

def label_path(state):
    return state.path.lstrip("/")


def children(container):
    return list(getattr(container, "_states", []))


def close_active(container):
    """Exit (outcome null) every state below container still active, deepest first."""
    for child in children(container):
        close_active(child)
        if getattr(child, "_smachac_active", False):
            child._smachac_active = False
            trace_protocol.emit("exit", label_path(child), None)


def traced(state):
    execute = state.execute  # EventStates already hold their wrapped execute per instance

    def traced_execute(userdata):
        if not state._smachac_active:
            state._smachac_active = True
            trace_protocol.emit("enter", label_path(state))
        outcome = execute(userdata)
        if outcome is not None:
            close_active(state)
            state._smachac_active = False
            trace_protocol.emit("exit", label_path(state), outcome)
        return outcome

    return traced_execute


def trace_tree(container):
    for child in children(container):
        child._smachac_active = False
        child.execute = traced(child)
        trace_tree(child)


def raised(container):
    """An exception that a container of the tree caught from its state (FlexBE logs it and
    keeps the state active for the operator), or None."""
    found = getattr(container, "_last_exception", None)
    for child in children(container):
        found = found or raised(child)
    return found


# ---------------------------------------------------------------- the operator

class Operator:
    """Confirms every outcome a state requests because the autonomy level is too low."""

    def __init__(self):
        from flexbe_msgs.msg import OutcomeRequest
        self.message = OutcomeRequest
        self.commands = rospy.Publisher("flexbe/command/transition", OutcomeRequest,
                                        queue_size=10)
        self.state_machine = None
        rospy.Subscriber("flexbe/outcome_request", OutcomeRequest, self.requested)

    def requested(self, request):
        if request.outcome == 255:  # the state withdrew its request
            return
        state = self.find(request.target)
        outcome = state.outcomes[request.outcome]
        required = state.parent.get_required_autonomy(outcome)
        sys.stdout.write(REQUEST + json.dumps({"state": label_path(state), "outcome": outcome,
                                               "required": required}, sort_keys=True) + "\n")
        sys.stdout.flush()
        deadline = time.monotonic() + CONNECT_SECONDS
        while self.commands.get_num_connections() == 0 and time.monotonic() < deadline:
            time.sleep(0.05)  # a command sent before FlexBE's subscriber connects is lost
        self.commands.publish(self.message(outcome=request.outcome, target=state.name))

    def find(self, path):
        state = self.state_machine
        for label in path.strip("/").split("/"):
            state = state[label]
        return state


# ---------------------------------------------------------------- running

def parse_params(pairs):
    params = {}
    for pair in pairs:
        name, equals, value = pair.partition("=")
        if not equals:
            raise BehaviorError("--param %r is not NAME=VALUE" % pair)
        params[name] = value
    return params


def find_behavior(name):
    from flexbe_core.behavior_library import BehaviorLibrary
    _, entry = BehaviorLibrary().find_behavior(name)
    if entry is None:
        raise BehaviorError("no behavior %r in the packages on ROS_PACKAGE_PATH that export "
                            "flexbe_behaviors" % name)
    return entry["package"] + "." + entry["file"], entry["class"]


def instrument(behavior, operator):
    """Wrap create() so that the state machine it builds is checked and traced."""
    create = behavior.create

    def instrumented_create():
        try:
            state_machine = create()
        except Exception as error:
            raise BehaviorError("create() raised %s: %s" % (type(error).__name__, error))
        if state_machine is None or not hasattr(state_machine, "_build_structure_msg"):
            raise BehaviorError("create() returned %r, not a state machine" % (state_machine,))
        try:
            state_machine._build_structure_msg()
        except Exception as error:
            raise BehaviorError("FlexBE cannot describe the behavior to the operator's mirror "
                                "(a state outcome without a transition or autonomy level): "
                                "%s: %s" % (type(error).__name__, error))
        trace_tree(state_machine)
        if operator is not None:
            operator.state_machine = state_machine
        return state_machine

    behavior.create = instrumented_create


def prepared(args, operator):
    from flexbe_testing.test_interface import TestInterface
    module, cls = find_behavior(args.behavior)
    try:
        interface = TestInterface(module, cls)
    except StopIteration:
        raise BehaviorError("the manifest names class %s, which %s does not define"
                            % (cls, module))
    try:
        interface.instantiate()
    except Exception as error:
        raise BehaviorError("instantiating %s raised %s: %s" % (cls, type(error).__name__, error))
    behavior = interface._instance
    for name, value in parse_params(args.param).items():
        if not behavior.set_parameter(name, value):
            raise BehaviorError("%s has no parameter %r" % (cls, name))
    behavior.set_up(id=0, autonomy_level=args.autonomy, debug=False)
    instrument(behavior, operator)
    return interface, behavior


def preempt_command():
    """Publishes FlexBE's preempt command after --preempt-after seconds and on SIGUSR1."""
    from std_msgs.msg import Empty
    command = rospy.Publisher("flexbe/command/preempt", Empty, queue_size=1, latch=True)

    def preempt():
        command.publish(Empty())

    # From a thread of its own: the handler runs in the main thread, which may hold the
    # publisher's lock.
    signal.signal(signal.SIGUSR1,
                  lambda _signum, _frame: threading.Thread(target=preempt, daemon=True).start())
    return preempt


def preempt_later(preempt, seconds):
    timer = threading.Timer(seconds, preempt)
    timer.daemon = True
    timer.start()


def run(args):
    from flexbe_core.core.user_data import UserData
    operator = Operator() if args.autonomy != TESTING_AUTONOMY else None
    interface, behavior = prepared(args, operator)
    userdata = UserData()
    random.seed(args.seed)  # here: rospy and FlexBE draw no random numbers from now on

    def check_tick():
        error = raised(behavior._state_machine)
        if error is not None:
            raise BehaviorError("a state raised %s: %s" % (type(error).__name__, error))

    preempt = preempt_command()
    if args.preempt_after is not None:
        preempt_later(preempt, args.preempt_after)
    outcome = interface.execute(userdata, spin_cb=check_tick)
    if outcome is None:
        raise BehaviorError("stopped before the behavior returned an outcome")
    trace_protocol.result(outcome, dict(userdata._data))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("behavior")
    parser.add_argument("--param", action="append", default=[], metavar="NAME=VALUE")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--autonomy", type=int, default=TESTING_AUTONOMY)
    parser.add_argument("--preempt-after", type=float, default=None)
    args = parser.parse_args()
    rospy.init_node("smachac_flexbe_run_%d" % os.getpid())
    from flexbe_core import Logger
    Logger.initialize()
    try:
        run(args)
    except Exception as error:  # reported on the last line of stderr, where the tests read it
        if not isinstance(error, BehaviorError):
            traceback.print_exc()
            error = "%s: %s" % (type(error).__name__, error)
        print("run_flexbe: %s" % error, file=sys.stderr, flush=True)
        return 1
    finally:
        rospy.signal_shutdown("smachac test: the behavior has finished")
    return 0


if __name__ == "__main__":
    code = main()
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)  # rospy has shut down; its remaining threads would only delay the exit
