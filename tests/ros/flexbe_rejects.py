#!/usr/bin/python3
"""Broken ROS 1 behaviors that the real flexbe_core rejects, each of which run_flexbe.py must
report as an error (exit 1, naming FlexBE's complaint) instead of running it or waiting for
ever; and a correct one, which must run. They show which structural checks real FlexBE makes
(the others are harness/flexbe_structure.py's, from the source).

  flexbe_rejects.py        (the overlay: $SMACHAC_ROS_OVERLAY)

The behaviors are the self-test behaviors of harness/flexbe_structure_self_test.py, for
ROS 1. Prints one line per behavior and `N passed, N failed, N skipped`; exit 77 when the
overlay has no FlexBE.
"""
import concurrent.futures
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [os.path.join(os.path.dirname(os.path.dirname(HERE)), "tools", "ros"),
                os.path.join(os.path.dirname(HERE), "harness")]

import flexbe_package  # noqa: E402
from flexbe_goldens import PARALLEL_RUNS, Report, Run  # noqa: E402
from ros_session import run_test  # noqa: E402
from flexbe_structure_self_test import (  # noqa: E402
    STATES, main_with_pick, pick_block, simple, wait)

MANIFEST = ('<?xml version="1.0" encoding="UTF-8"?>\n<behavior name="sm">\n'
            '  <executable package_path="sm_flexbe_behaviors.sm_sm" class="{cls}" />\n'
            '</behavior>\n')
KEY_NOT_CONNECTED = ("OperatableStateMachine.add('K', KeyState(), transitions={'ok': "
                     "'finished'}, autonomy={'ok': Autonomy.Off, 'bad': Autonomy.Off})")
NO_AUTONOMY = ("OperatableStateMachine.add('A', WaitState(wait_time=1), transitions={'done': "
               "'finished'}, autonomy={})")
USE_AGAIN = ("    OperatableStateMachine.add('AGAIN', self.use_behavior(PickBlockSM, "
             "'PICK_BLOCK'), transitions={'finished': 'finished', 'failed': 'failed'}, "
             "autonomy={'finished': Autonomy.Off, 'failed': Autonomy.Off})")


def embedded(**options):
    return {"sm_sm.py": main_with_pick(1, **options), "pick_block_sm.py": pick_block(1),
            "sm_states.py": STATES}


def one_module(create, init=()):
    return {name: text for name, text in simple(create, init, ros=1).items()
            if not name.endswith("_manifest.py")}


# case: (files, manifest class, what FlexBE says; None: the behavior must run to `finished`)
CASES = {
    "correct": (one_module(["with _state_machine:", "    " + wait("A")]), "MainSM", None),
    "add_outside_with": (one_module([wait("A")]), "MainSM", "No container openend"),
    "duplicate_label": (one_module(["with _state_machine:", "    " + wait("A"),
                                    "    " + wait("A")]), "MainSM", "has already been added"),
    "missing_target": (one_module(["with _state_machine:", "    " + wait("A", "NOWHERE")]),
                       "MainSM", "Transition target 'NOWHERE' missing"),
    "outcome_without_transition": (one_module(["with _state_machine:", "    " +
                                               KEY_NOT_CONNECTED]), "MainSM",
                                   "operator's mirror"),
    "outcome_without_autonomy": (one_module(["with _state_machine:", "    " + NO_AUTONOMY]),
                                 "MainSM", "operator's mirror"),
    "empty_container": (one_module(["_sm_x = OperatableStateMachine(outcomes=['done'])",
                                    "with _sm_x:", "    pass", "with _state_machine:",
                                    "    OperatableStateMachine.add('X', _sm_x, transitions="
                                    "{'done': 'finished'}, autonomy={'done': Autonomy.Off})"]),
                        "MainSM", "No states added yet"),
    "use_without_add": (embedded(init=[]), "MainSM", "'NoneType' object has no attribute"),
    "used_twice": (embedded(extra_create=[USE_AGAIN]), "MainSM", "Cannot change the name"),
    "add_with_node": (embedded(init=["self.add_behavior(PickBlockSM, 'PICK_BLOCK', 7)"]),
                      "MainSM", "positional arguments"),
    "missing_self_parameter": (one_module(["with _state_machine:", "    OperatableStateMachine."
                                           "add('A', WaitState(wait_time=self.speed), transitions"
                                           "={'done': 'finished'}, autonomy={'done': "
                                           "Autonomy.Off})"]),
                               "MainSM", "has no attribute 'speed'"),
    "manifest_wrong_class": (one_module(["with _state_machine:", "    " + wait("A")]),
                             "OtherSM", "does not define"),
}


def write_package(workspace, files, cls):
    folder = os.path.join(workspace, "sm_flexbe_behaviors")
    os.makedirs(folder)
    files = dict(files, **{"sm.xml": MANIFEST.format(cls=cls), "__init__.py": "",
                           "package.xml": flexbe_package.PACKAGE_XML.format(
                               name="sm_flexbe_behaviors")})
    for name, text in files.items():
        with open(os.path.join(folder, name), "w", encoding="utf-8") as f:
            f.write(text)
    package = flexbe_package.Package(folder, {"sm": ("sm_flexbe_behaviors.sm_sm", cls, [])})
    package.inputs = workspace
    return package


def verdict(finished, complaint):
    """Why a run does not show what the case expects, or None."""
    stderr = finished.stderr.strip().splitlines()
    last = stderr[-1] if stderr else "no output"
    if finished.timed_out:
        return "no verdict within the timeout (stopped)"
    if complaint is None:
        return None if finished.returncode == 0 else "exit %d: %s" % (finished.returncode, last)
    if finished.returncode != 1 or complaint not in last:
        return "expected exit 1 with %r, got exit %d: %s" % (complaint, finished.returncode, last)
    return None


def run_all(ros, work, report):
    runs = []
    for case, (files, cls, complaint) in CASES.items():
        package = write_package(os.path.join(work, case), files, cls)
        runs.append((case, complaint, Run("flexbe-rejects/" + case, package, [], "finished")))
    with concurrent.futures.ThreadPoolExecutor(PARALLEL_RUNS) as pool:
        results = pool.map(lambda item: item[2].start(ros), runs)
        for (case, complaint, run), finished in zip(runs, results):
            why = verdict(finished, complaint)
            if why:
                report.fail(run.label, why)
            else:
                report.ok(run.label, ("runs (%.1f s)" if complaint is None else
                                      "rejected: %s (%%.1f s)" % complaint) % finished.seconds)


def main():
    report = Report()

    def body(ros, work):
        run_all(ros, work, report)
        return report.close()

    return run_test("flexbe-rejects", ["flexbe"], body)


if __name__ == "__main__":
    sys.exit(main())
