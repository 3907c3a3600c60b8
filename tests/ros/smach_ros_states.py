#!/usr/bin/python3
"""The built-in smach_ros templates against real counterparts (label ros).

  smach_ros_states.py SMACHAC            the overlay is $SMACHAC_ROS_OVERLAY

Compiles the scripts of cases/ and runs them on the real SMACH and smach_ros, each with a
private master and the fixtures of fixtures/, then checks what happened on the ROS side:
  counterparts   ServiceState (request received, response stored), SimpleActionState (goal
                 received, result stored), TF2ListenerState (the broadcast transform),
                 PublishMsgState (the fixture received the point and echoed it), ReadTopicState
                 (latched topic, with and without msg_type; another type ends at its timeout),
                 WaitForMsgState (live topic and callback; a silent topic ends at its
                 timeout), SleepState (how long it slept);
  introspection  -i: container_structure and container_status read back from the master;
  read_forever   a ReadTopicState on a topic of another type, without timeout, ends when
                 preempted and when the program gets SIGTERM.
Prints one line per check and the closing `N passed, N failed, N skipped`; exits 77 (skip)
when the overlay has no SMACH.
"""
import concurrent.futures
import json
import os
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROS_TOOLS = os.path.join(os.path.dirname(os.path.dirname(HERE)), "tools", "ros")
sys.path[:0] = [HERE, ROS_TOOLS]

import trace_protocol  # noqa: E402
from live_run import LiveRun  # noqa: E402
from report import Deferred, Report  # noqa: E402
from ros_session import PYTHON, RosSession, Unavailable  # noqa: E402

SKIPPED = 77
RUN_SMACH = os.path.join(ROS_TOOLS, "run_smach.py")
CASES = os.path.join(HERE, "cases")
FIXTURES = os.path.join(HERE, "fixtures")


class Check:
    """One named check of a scenario: its conditions, reported as one line."""

    def __init__(self, report, name, began):
        self.report, self.name, self.began = report, "smach_ros/" + name, began

    def expect(self, what, conditions):
        """conditions: [(holds, why it does not)]; reports ok with `what` or the first why."""
        seconds = time.monotonic() - self.began
        for holds, why in conditions:
            if not holds:
                return self.report.fail(self.name, why, seconds)
        self.report.ok(self.name, what, seconds)


def compile_script(smachac, name, out_dir, flags=()):
    program = os.path.join(out_dir, name + ".py")
    argv = [smachac, "-target=smach"] + list(flags) + [name + ".yml", "-o", program]
    result = subprocess.run(argv, cwd=CASES, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, errors="replace", timeout=60)
    if result.returncode != 0:
        raise RuntimeError("smachac %s failed:\n%s" % (name, result.stdout))
    return program


def state_times(run, state):
    """(seconds at enter, seconds at exit, outcome) of a state's first run in a LiveRun."""
    entered = exited = outcome = None
    for at, line in run.lines:
        events, _ = trace_protocol.parse(line)
        for event in events:
            if event["state"] != state:
                continue
            if event["event"] == "enter" and entered is None:
                entered = at
            elif event["event"] == "exit" and exited is None:
                exited, outcome = at, event["outcome"]
    return entered, exited, outcome


def took(run, state):
    entered, exited, _ = state_times(run, state)
    return None if entered is None or exited is None else exited - entered


def outcome_of(run, state):
    return state_times(run, state)[2]


def read_json(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def result_of(run):
    return trace_protocol.parse(run.text())[1] or {"outcome": None, "userdata": {}}


def run_counterparts(ctx):
    """The counterparts program's LiveRun and what the fixture recorded."""
    program = compile_script(ctx.smachac, "counterparts", ctx.work_dir)
    with ctx.session("counterparts") as ros:
        record_path = os.path.join(ros.work_dir, "record.json")
        ros.start_master()
        ros.start_fixture("counterparts", [PYTHON, os.path.join(FIXTURES, "counterparts.py"),
                                           record_path])
        run = LiveRun(ros, "counterparts", [PYTHON, RUN_SMACH, program]).finish(timeout=60)
        return run, read_json(record_path)


def calls_checks(run, record, ud):
    """ServiceState and SimpleActionState: what the servers got, what the states stored."""
    final_pose = str(ud.get("final_pose"))
    return [
        ("ServiceState", "requests 0.25 and 0.125 received, responses stored", [
            (record["set_width"] == [0.25, 0.125], "service received %s" % record["set_width"]),
            (ud.get("width") == 0.5, "response slot width = %r, expected 0.5" % ud.get("width")),
            (ud.get("reply") == 0.25, "response_cb reply = %r, expected 0.25" % ud.get("reply"))]),
        ("SimpleActionState", "goals 0.75 and 0.5 received, result stored", [
            (record["move"] == [0.75, 0.5], "action server received %s" % record["move"]),
            ("x: 1.5" in final_pose, "result slot final_pose = %s" % final_pose)])]


def topic_checks(run, record, ud):
    """TF2ListenerState, PublishMsgState, ReadTopicState: what went over TF and the topics."""
    transform = str(ud.get("transform"))
    return [
        ("TF2ListenerState", "transform base -> tool read", [
            (outcome_of(run, "LOOKUP") == "succeeded", "LOOKUP: %s" % outcome_of(run, "LOOKUP")),
            (all(t in transform for t in ("tool", "x: 0.1", "y: 0.2", "z: 0.3")),
             "transform = %s" % transform)]),
        ("PublishMsgState", "point [1, 2, 3] received and echoed, then stopped", [
            (record["published"] == [[1.0, 2.0, 3.0]], "fixture received %s" % record["published"]),
            (outcome_of(run, "WAIT_ECHO") == "succeeded", "WAIT_ECHO: %s" % outcome_of(run, "WAIT_ECHO")),
            (outcome_of(run, "STOP") == "succeeded", "STOP: %s" % outcome_of(run, "STOP"))]),
        ("ReadTopicState", "latched message read, by the topic's type and by msg_type", [
            ("latched hello" in str(ud.get("latched")), "latched = %s" % ud.get("latched")),
            ("latched hello" in str(ud.get("typed")), "typed = %s" % ud.get("typed"))])]


def timing_checks(run, record, ud):
    """WaitForMsgState, ReadTopicState with another type, SleepState: outcomes and durations."""
    wrong, silent, nap = took(run, "READ_WRONG_TYPE"), took(run, "WAIT_SILENT"), took(run, "NAP")
    return [
        ("ReadTopicState-wrong-type", "aborted after %.2f s (timeout 1 s)" % (wrong or 0), [
            (outcome_of(run, "READ_WRONG_TYPE") == "aborted",
             "READ_WRONG_TYPE: %s" % outcome_of(run, "READ_WRONG_TYPE")),
            (wrong is not None and 0.9 <= wrong <= 3.0, "took %s s, timeout 1 s" % wrong),
            ("wrong" not in ud, "wrong was written: %s" % ud.get("wrong"))]),
        ("WaitForMsgState", "live message accepted; silent topic aborted after %.2f s"
         % (silent or 0), [
            (outcome_of(run, "WAIT_LIVE") == "succeeded", "WAIT_LIVE: %s" % outcome_of(run, "WAIT_LIVE")),
            (outcome_of(run, "WAIT_SILENT") == "aborted",
             "WAIT_SILENT: %s" % outcome_of(run, "WAIT_SILENT")),
            (silent is not None and 0.4 <= silent <= 2.5, "WAIT_SILENT took %s s, timeout 0.5 s"
             % silent)]),
        ("SleepState", "slept %.2f s (0.5 s asked)" % (nap or 0), [
            (nap is not None and 0.45 <= nap <= 2.0, "NAP took %s s" % nap)])]


def check_counterparts(ctx):
    began = time.monotonic()
    run, record = run_counterparts(ctx)
    result = result_of(run)
    Check(ctx.report, "counterparts", began).expect("outcome done", [
        (not run.timed_out, "timed out:\n" + run.text()[-2000:]),
        (result["outcome"] == "done", "outcome %s, expected done:\n%s"
         % (result["outcome"], run.text()[-2000:]))])
    for checks in (calls_checks, topic_checks, timing_checks):
        for name, what, conditions in checks(run, record, result["userdata"]):
            Check(ctx.report, name, began).expect(what, conditions)


def check_introspection(ctx):
    began = time.monotonic()
    program = compile_script(ctx.smachac, "introspection", ctx.work_dir, ["-i"])
    with ctx.session("introspection") as ros:
        record_path = os.path.join(ros.work_dir, "introspection.json")
        ros.start_master()
        ros.start_fixture("listener", [PYTHON, os.path.join(FIXTURES, "introspection_listener.py"),
                                       "/inspected", record_path])
        ros.env["SMACHAC_SPIN_SECONDS"] = "4.5"  # structures every 2 s: two or three more
        run = LiveRun(ros, "introspection", [PYTHON, RUN_SMACH, program]).finish(timeout=60)
        record = read_json(record_path)
    structure, active = record["structure"], record["active"]
    top, work = structure.get("/inspected", {}), structure.get("/inspected/WORK", {})
    top_transitions = list(zip(top.get("outcomes_from", []), top.get("outcomes_to", [])))
    Check(ctx.report, "IntrospectionServer", began).expect(
        "structure and status of /inspected and /inspected/WORK read back", [
            (result_of(run)["outcome"] == "done", "outcome %s:\n%s"
             % (result_of(run)["outcome"], run.text()[-2000:])),
            (top.get("children") == ["NAP", "PAUSE", "WORK"],
             "/inspected children %s" % top.get("children")),
            (top.get("container_outcomes") == ["done"], "/inspected outcomes %s"
             % top.get("container_outcomes")),
            (("NAP", "PAUSE") in top_transitions, "/inspected transitions %s" % top_transitions),
            (work.get("children") == ["STEP", "STEP_2"],
             "/inspected/WORK children %s" % work.get("children")),
            (["PAUSE"] in active.get("/inspected", []), "/inspected active %s"
             % active.get("/inspected")),
            (["WORK"] in active.get("/inspected", []), "/inspected active %s"
             % active.get("/inspected")),
            (["STEP_2"] in active.get("/inspected/WORK", []), "/inspected/WORK active %s"
             % active.get("/inspected/WORK"))])


def check_read_forever(ctx):
    began = time.monotonic()
    program = compile_script(ctx.smachac, "read_forever", ctx.work_dir)
    with ctx.session("read_forever") as ros:
        ros.start_master()
        ros.start_fixture("counterparts", [PYTHON, os.path.join(FIXTURES, "counterparts.py"),
                                           os.path.join(ros.work_dir, "record.json")])
        preempted = LiveRun(ros, "preempted", [PYTHON, RUN_SMACH, program, "--preempt-after", "1.5"])
        preempted.finish(timeout=20)
        terminated = LiveRun(ros, "terminated", [PYTHON, RUN_SMACH, program])
        entered = terminated.wait_for('"state": "READ"', 20)
        time.sleep(1.0)
        sent = time.monotonic() - terminated.began
        terminated.signal(signal.SIGTERM)
        terminated.finish(timeout=15)
    entered_p, exited_p, outcome_p = state_times(preempted, "READ")
    Check(ctx.report, "ReadTopicState-preempted", began).expect(
        "aborted %.2f s after entering (preempted at 1.5 s)" % ((exited_p or 0) - (entered_p or 0)), [
            (outcome_p == "aborted", "READ: %s\n%s" % (outcome_p, preempted.text()[-2000:])),
            (not preempted.timed_out and exited_p is not None and exited_p <= 1.5 + 3.0,
             "READ ended at %s s, preempted at 1.5 s" % exited_p)])
    ended = terminated.ended_at() if not terminated.timed_out else None
    Check(ctx.report, "ReadTopicState-SIGTERM", began).expect(
        "the program ended %.2f s after SIGTERM" % ((ended or sent) - sent), [
            (entered is not None, "READ never started:\n" + terminated.text()[-2000:]),
            (not terminated.timed_out, "still running 15 s after SIGTERM:\n"
             + terminated.text()[-2000:])])


class Context:
    def __init__(self, smachac, overlay, work_dir, report):
        self.smachac, self.overlay, self.work_dir, self.report = smachac, overlay, work_dir, report

    def session(self, name):
        return RosSession(self.overlay, os.path.join(self.work_dir, name))

    def with_report(self, report):
        return Context(self.smachac, self.overlay, self.work_dir, report)


def run_scenario(ctx, scenario):
    try:
        scenario(ctx)
    except Exception as error:  # a broken scenario is a failure, the others still run
        ctx.report.fail("smach_ros/" + scenario.__name__[len("check_"):], repr(error))


def run_scenarios(ctx, scenarios):
    """Runs the scenarios at once, each with its own master, and reports them in order."""
    deferred = [Deferred() for _ in scenarios]
    with concurrent.futures.ThreadPoolExecutor(max_workers=len(scenarios)) as pool:
        for future in [pool.submit(run_scenario, ctx.with_report(d), s)
                       for d, s in zip(deferred, scenarios)]:
            future.result()
    for d in deferred:
        d.replay(ctx.report)


def main():
    if len(sys.argv) != 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    report = Report()
    with tempfile.TemporaryDirectory(prefix="smachac-smach-ros-") as work_dir:
        ctx = Context(os.path.abspath(sys.argv[1]), os.environ.get("SMACHAC_ROS_OVERLAY", ""),
                      work_dir, report)
        try:
            ctx.session("probe").require("smach")
        except Unavailable as why:
            print("skip smach_ros templates (%s)" % why)
            return SKIPPED
        run_scenarios(ctx, (check_counterparts, check_introspection, check_read_forever))
    return report.close()


if __name__ == "__main__":
    sys.exit(main())
