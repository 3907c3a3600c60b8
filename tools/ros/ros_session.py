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

    def start_master(self):
        port = free_port()
        self.master_uri = "http://127.0.0.1:%d" % port
        self.env["ROS_MASTER_URI"] = self.master_uri
        log = os.path.join(self.work_dir, "rosmaster.log")
        process = self.processes.start(["rosmaster", "--core", "-p", str(port)], self.env, log)
        master = xmlrpc.client.ServerProxy(self.master_uri)

        def set_run_id():
            try:
                return master.setParam("/smachac_test", "/run_id", str(uuid.uuid4()))[0] == 1
            except OSError:
                return process.poll() is not None  # died: stop waiting, reported below

        if not wait_for(set_run_id, 15) or process.poll() is not None:
            raise RuntimeError("rosmaster did not start:\n" + read(log))
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
