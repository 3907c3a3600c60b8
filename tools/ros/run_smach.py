#!/usr/bin/python3
"""Runs a generated SMACH program as a user would (`python3 prog.py`), on the real SMACH, and
reports what happened in the trace protocol of trace_protocol.py.

  run_smach.py PROGRAM.py [--seed N] [--preempt-after SECONDS]

The program runs as __main__, unchanged. Around it: `random` is seeded (RandomOutcomeState
repeats), every state that a container adds reports its entry and its outcome under its path
(labels joined by `/`, the top state machine itself being ``), `rospy.spin()` at the end of an
introspection program returns (the machine has finished) after the introspection server has
published, and the top state machine's outcome and final userdata are reported. With
--preempt-after, the top state machine is asked to preempt (request_preempt) that many seconds
after it starts, as a parent or a user would; SIGUSR1 asks it the same at any time.
"""
import argparse
import random
import runpy
import signal
import sys
import threading

import smach

import trace_protocol

_lock = threading.Lock()
_depth = threading.local()
_running = []  # the top state machine while it executes


def path_of(state):
    labels = []
    while getattr(state, "_smachac_label", None) is not None:
        labels.append(state._smachac_label)
        state = state._smachac_parent
    return "/".join(reversed(labels))


def traced_add(original):
    def add(label, state, *args, **kwargs):
        state._smachac_label = label
        state._smachac_parent = smach.container.Container._currently_opened_container()
        execute = state.execute

        def traced_execute(*a, **kw):
            path = path_of(state)
            trace_protocol.emit("enter", path)
            outcome = execute(*a, **kw)
            trace_protocol.emit("exit", path, outcome)
            return outcome

        state.execute = traced_execute
        return original(label, state, *args, **kwargs)

    return staticmethod(add)


def preempt_later(machine, seconds):
    timer = threading.Timer(seconds, machine.request_preempt)
    timer.daemon = True
    timer.start()


def report_top_machine(preempt_after):
    original = smach.StateMachine.execute

    def execute(self, *args, **kwargs):
        top = getattr(self, "_smachac_label", None) is None and not getattr(_depth, "n", 0)
        if top and preempt_after is not None:
            preempt_later(self, preempt_after)
        if top:
            _running.append(self)
        _depth.n = getattr(_depth, "n", 0) + 1
        try:
            outcome = original(self, *args, **kwargs)
        finally:
            _depth.n -= 1
            if top:
                _running.remove(self)
        if top:
            trace_protocol.result(outcome, dict(self.userdata._data))
        return outcome

    smach.StateMachine.execute = execute


def preempt_on_signal():
    """SIGUSR1 preempts the running top machine, from a thread of its own: the handler runs in
    the main thread, which may hold the locks that request_preempt() takes."""
    def preempt():
        for machine in list(_running):
            machine.request_preempt()

    signal.signal(signal.SIGUSR1,
                  lambda _signum, _frame: threading.Thread(target=preempt, daemon=True).start())


def return_from_spin():
    try:
        import rospy
    except ImportError:
        return
    # An introspection program spins until shut down; the machine has finished by then, and
    # the introspection server has published its structure and status. Give subscribers a
    # moment to read them, then return as on shutdown.
    def spin():
        rospy.sleep(float(__import__("os").environ.get("SMACHAC_SPIN_SECONDS", "0")))
        rospy.signal_shutdown("smachac test: the state machine has finished")

    rospy.spin = spin


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("program")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--preempt-after", type=float, default=None)
    args = parser.parse_args()
    random.seed(args.seed)
    for container in (smach.StateMachine, smach.Concurrence):
        container.add = traced_add(container.add)
    report_top_machine(args.preempt_after)
    preempt_on_signal()
    return_from_spin()
    sys.argv = [args.program]
    runpy.run_path(args.program, run_name="__main__")


if __name__ == "__main__":
    main()
