#!/usr/bin/python3
"""RosSession.start_master when another process holds the port it chose (the port is free
when chosen, not reserved, and tests run side by side): rosmaster then keeps running without
its XML-RPC server, so the session must notice, stop it and start again on another port,
and never take the port's holder for its master.

  master_start.py        (the overlay: $SMACHAC_ROS_OVERLAY)

Prints one line per case and exits 0 when all pass, 1 otherwise, 77 without the overlay.
"""
import os
import socket
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [os.path.join(os.path.dirname(os.path.dirname(HERE)), "tools", "ros")]

import ros_session  # noqa: E402
from ros_session import PORT_IN_USE, run_test  # noqa: E402


def listening_socket():
    """A port held by a socket that accepts connections and never answers."""
    holder = socket.socket()
    holder.bind(("127.0.0.1", 0))
    holder.listen()
    return holder


def ports(*chosen):
    """A stand-in for free_port that gives `chosen` in turn, then real free ports."""
    queue = list(chosen)
    real = ros_session.free_port
    return lambda: queue.pop(0) if queue else real()


def retried_on_another_port(session, work_dir):
    with listening_socket() as holder:
        busy = holder.getsockname()[1]
        ros_session.free_port = ports(busy)
        master = session.start_master()
    port = int(session.master_uri.rsplit(":", 1)[1])
    first_log = open(os.path.join(work_dir, "rosmaster-1.log"), encoding="utf-8").read()
    problems = []
    if port == busy:
        problems.append("the master URI still names the held port %d" % busy)
    if PORT_IN_USE not in first_log:
        problems.append("the first rosmaster did not report the held port:\n" + first_log)
    if len(session.processes.running) != 1:
        problems.append("%d processes left running, not 1 (the first rosmaster must be "
                        "stopped)" % len(session.processes.running))
    code, _, run_id = master.getParam("/smachac_test", "/run_id")
    if code != 1 or not run_id:
        problems.append("the second master has no /run_id: %r" % ((code, run_id),))
    return problems


def gives_up_after_three_starts(session, work_dir):
    with listening_socket() as holder:
        busy = holder.getsockname()[1]
        ros_session.free_port = lambda: busy
        try:
            session.start_master()
        except RuntimeError as error:
            message = str(error)
        else:
            return ["start_master took the held port %d for its master" % busy]
    problems = []
    if not message.startswith("rosmaster lost its port at each of 3 starts"):
        problems.append("unexpected error: " + message.splitlines()[0])
    if PORT_IN_USE not in message:
        problems.append("the error does not quote rosmaster's complaint: " + message)
    if session.processes.running:
        problems.append("%d rosmaster processes left running" % len(session.processes.running))
    for attempt in (1, 2, 3):
        if not os.path.exists(os.path.join(work_dir, "rosmaster-%d.log" % attempt)):
            problems.append("no log of start %d" % attempt)
    return problems


def run_case(case):
    real_free_port = ros_session.free_port

    def body(session, work_dir):
        try:
            problems = case(session, work_dir)
        finally:
            ros_session.free_port = real_free_port
        print("%s %s" % ("ok  " if not problems else "FAIL", case.__name__))
        for problem in problems:
            print("     " + problem)
        return 1 if problems else 0

    return run_test("master-start", [], body, master=False)


def main():
    results = [run_case(case) for case in (retried_on_another_port,
                                           gives_up_after_three_starts)]
    if ros_session.SKIPPED in results:
        return ros_session.SKIPPED
    return 1 if any(results) else 0


if __name__ == "__main__":
    sys.exit(main())
