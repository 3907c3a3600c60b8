"""A ROS 1 session for one test: the overlay's environment, a private master on loopback, and
the processes started in it, all stopped on exit.

    with RosSession(overlay_dir, work_dir) as ros:   # raises Unavailable with the reason
        ros.require("smach")
        ros.start_master()
        ros.start_fixture("servers", [PYTHON, "servers.py"])   # waits for "FIXTURE READY"
        finished = ros.run([PYTHON, "script.py"], timeout=60)

The master is `rosmaster --core` on 127.0.0.1 and a free port (roscore would also start a
rosout that listens on every interface); every node binds 127.0.0.1 through ROS_IP, and
ROS_HOME / ROS_LOG_DIR are in the work folder. /run_id is set as roscore would.
"""
import itertools
import json
import os
import socket
import tempfile
import time
import uuid
import xmlrpc.client

from processes import Processes

PYTHON = "/usr/bin/python3"
SKIPPED = 77  # a test's exit code when what it needs is absent (ctest SKIP_RETURN_CODE)


class Unavailable(Exception):
    """The ROS set-up a test needs is absent here; the message says why (the test skips)."""


# What rosmaster writes when another process holds its port (it keeps running regardless):
# the traceback of its XML-RPC thread on standard error ("Address already in use"), then, on
# its buffered standard output, "port N is already in use".
PORT_IN_USE = "already in use"


class _TimeoutTransport(xmlrpc.client.Transport):
    """XML-RPC over HTTP with a socket timeout: a port's holder that accepts and never
    answers must not stall the check."""

    def __init__(self, seconds):
        super().__init__()
        self.seconds = seconds

    def make_connection(self, host):
        connection = super().make_connection(host)
        connection.timeout = self.seconds
        return connection


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_for(condition, seconds, step=0.1):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if condition():
            return True
        time.sleep(step)
    return condition()


class RosSession:
    def __init__(self, overlay_dir, work_dir):
        self.work_dir = work_dir
        self.overlay = self._read_overlay(overlay_dir)
        self.env = self._environment()
        self.processes = Processes()
        self.master_uri = None
        self._namespaces = itertools.count(1)

    @staticmethod
    def _read_overlay(overlay_dir):
        path = os.path.join(overlay_dir, "overlay.json")
        if not os.path.exists(path):
            raise Unavailable("no ROS overlay at %s (the ctest ros/overlay builds it)" % overlay_dir)
        with open(path, encoding="utf-8") as f:
            overlay = json.load(f)
        if overlay["problem"]:
            raise Unavailable(overlay["problem"])
        return overlay

    def _environment(self):
        env = {k: v for k, v in os.environ.items() if not k.startswith(("ROS_", "PYTHON"))}
        for name in ("ros_home", "ros_log"):
            os.makedirs(os.path.join(self.work_dir, name), exist_ok=True)
        env.update({
            "PATH": "/usr/bin:/bin:" + env.get("PATH", ""),  # rostopic & co. use env python3
            "PYTHONPATH": os.pathsep.join(self.overlay["python_path"]),
            "PYTHONDONTWRITEBYTECODE": "1",
            "ROS_PACKAGE_PATH": os.pathsep.join(self.overlay["package_path"]),
            "ROS_IP": "127.0.0.1",
            "ROS_HOSTNAME": "127.0.0.1",
            "ROS_HOME": os.path.join(self.work_dir, "ros_home"),
            "ROS_LOG_DIR": os.path.join(self.work_dir, "ros_log"),
            "ROS_PYTHON_VERSION": "3",
            "ROS_MASTER_URI": "http://127.0.0.1:1",  # no master until start_master()
        })
        return env

    def __enter__(self):
        self.processes.__enter__()
        return self

    def __exit__(self, *exc):
        return self.processes.__exit__(*exc)

    def require(self, framework):
        why = self.overlay["frameworks"].get(framework, "unknown framework " + framework)
        if why is not None:
            raise Unavailable(why)

    def namespaced_env(self):
        """A copy of the environment whose nodes live in a namespace no other run of this
        session has: for programs that share the master at the same time and must not hear
        each other on their relative topics."""
        return dict(self.env, ROS_NAMESPACE="/smachac_run_%d" % next(self._namespaces))

    def add_python_path(self, folder):
        self.env["PYTHONPATH"] = folder + os.pathsep + self.env["PYTHONPATH"]

    def add_package_path(self, folder):
        self.env["ROS_PACKAGE_PATH"] = folder + os.pathsep + self.env["ROS_PACKAGE_PATH"]

    def start_master(self, attempts=3):
        """Starts the master on a free port. The port is free when chosen but not reserved:
        another process may bind it before rosmaster does. rosmaster then keeps running
        without its XML-RPC server, and whatever holds the port would answer in its place;
        such a start is stopped and retried on another port."""
        for attempt in range(1, attempts + 1):
            log = os.path.join(self.work_dir, "rosmaster-%d.log" % attempt)
            master = self._try_master(free_port(), log)
            if master is not None:
                return master
        raise RuntimeError("rosmaster lost its port at each of %d starts; the last said:\n%s"
                           % (attempts, read(log)))

    def _try_master(self, port, log):
        """The master's proxy once it answers as our rosmaster (by its pid), or None when it
        could not bind the port (it said so, or exited)."""
        self.master_uri = "http://127.0.0.1:%d" % port
        self.env["ROS_MASTER_URI"] = self.master_uri
        process = self.processes.start(["rosmaster", "--core", "-p", str(port)], self.env, log)
        probe = xmlrpc.client.ServerProxy(self.master_uri, transport=_TimeoutTransport(2.0))

        def state():
            if process.poll() is not None or PORT_IN_USE in read(log):
                return "lost"
            try:
                return "ours" if probe.getPid("/smachac_test")[2] == process.pid else "waiting"
            except (OSError, xmlrpc.client.Error):
                return "waiting"

        wait_for(lambda: state() != "waiting", 15)
        outcome = state()
        if outcome == "lost":
            self.processes.stop(process)
            return None
        if outcome != "ours":
            raise RuntimeError("rosmaster did not answer in 15 s:\n" + read(log))
        master = xmlrpc.client.ServerProxy(self.master_uri)
        master.setParam("/smachac_test", "/run_id", str(uuid.uuid4()))
        return master

    def start_fixture(self, name, argv, timeout=20):
        """Starts a helper process (servers, publishers) and waits until it prints READY."""
        log = os.path.join(self.work_dir, name + ".log")
        process = self.processes.start(argv, self.env, log, cwd=self.work_dir)
        ready = wait_for(lambda: "FIXTURE READY" in read(log) or process.poll() is not None,
                         timeout)
        if not ready or process.poll() is not None:
            raise RuntimeError("fixture %s did not get ready:\n%s" % (name, read(log)))
        return process

    def stop(self, process):
        self.processes.stop(process)

    def run(self, argv, timeout, cwd=None, interrupt_after=None):
        return self.processes.run(argv, self.env, timeout, cwd=cwd or self.work_dir,
                                  interrupt_after=interrupt_after)


def read(path):
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            return f.read()
    except FileNotFoundError:
        return ""


def run_test(name, frameworks, body, master=True):
    """The frame of a ROS test: a fresh work folder, a RosSession with `frameworks` (and a
    master unless told otherwise), body(session, work_dir). Returns body's exit code, or
    SKIPPED after printing why when a framework is absent."""
    overlay = os.environ.get("SMACHAC_ROS_OVERLAY", "")
    with tempfile.TemporaryDirectory(prefix="smachac-%s-" % name) as work_dir:
        try:
            with RosSession(overlay, work_dir) as session:
                for framework in frameworks:
                    session.require(framework)
                if master:
                    session.start_master()
                return body(session, work_dir)
        except Unavailable as why:
            print("skip %s (%s)" % (name, why))
            return SKIPPED
