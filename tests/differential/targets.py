"""Compiling one script for a target and running it on that target's real runtime.

Each target gives back a Run: the trace events and the result (top outcome, final userdata)
in the protocol of tools/ros/trace_protocol.py, or the reason it did not run. Given
preempt_after (seconds), each target's own preempt request reaches the running machine then.
  smach   smachac -target=smach, then tools/ros/run_smach.py on the real SMACH
          (preempt: request_preempt() on the top machine)
  flexbe  smachac -target=flexbe -flexbe-ros=1 into its behaviors package
          (tools/ros/flexbe_package.py), then tools/ros/run_flexbe.py on the real flexbe_core
          (with the session's master; preempt: FlexBE's preempt command topic)
  cpp     smachac -target=cpp, c++ against the runtime library, then the program with
          --seed=1 --trace=json --print-userdata (its JSON-lines trace read back;
          preempt: SIGINT, which the generated program turns into a preempt request)
"""
import ast
import json
import os
import shlex
import subprocess
import threading

from ros_session import PYTHON

HERE = os.path.dirname(os.path.abspath(__file__))
ROS_DIR = os.path.join(os.path.dirname(os.path.dirname(HERE)), "tools", "ros")
TIMEOUT = 60


class Run:
    def __init__(self, events=None, result=None, problem=None):
        self.events = events or []
        self.result = result
        self.problem = problem


class Toolchain:
    """Where smachac and the C++ runtime are, and the session that runs Python targets."""

    def __init__(self, smachac, cxx, runtime_lib, runtime_include, session, work_dir):
        self.smachac = smachac
        self.cxx = cxx
        self.runtime_lib = runtime_lib
        self.runtime_include = runtime_include
        self.session = session
        self.work_dir = work_dir
        self._header_lock = threading.Lock()
        self._header = None

    def cxx_flags(self):
        sanitizers = shlex.split(os.environ.get("SMACHAC_E2E_CXXFLAGS", ""))
        return [self.cxx, "-std=c++20", "-O0", "-pthread", *sanitizers, "-I",
                self.runtime_include]

    def precompiled_runtime_header(self):
        """A header that includes the runtime, precompiled once per run (each program's build
        then skips parsing the runtime and the standard library): about half of its time."""
        with self._header_lock:
            if self._header is None:
                self._header = os.path.join(self.work_dir, "runtime_pch", "runtime_all.h")
                os.makedirs(os.path.dirname(self._header), exist_ok=True)
                with open(self._header, "w", encoding="utf-8") as f:
                    f.write("#include <smachac/runtime/runtime.h>\n")
                subprocess.run(self.cxx_flags() + ["-x", "c++-header", self._header, "-o",
                                                   self._header + ".gch"], check=True)
            return self._header

    def compile(self, script, target, output, extra=()):
        argv = [self.smachac, "-target=" + target, *extra, os.path.basename(script), "-o", output]
        result = subprocess.run(argv, cwd=os.path.dirname(script), capture_output=True, text=True)
        if result.returncode != 0:
            return first_error(result.stderr)
        return None

    def ir_json(self, script):
        result = subprocess.run([self.smachac, "-target=json", os.path.basename(script)],
                                cwd=os.path.dirname(script), capture_output=True, text=True)
        return json.loads(result.stdout) if result.returncode == 0 else None


def first_error(stderr):
    errors = [l for l in stderr.splitlines() if ": error: " in l]
    return (errors or stderr.strip().splitlines() or ["failed without a message"])[0]


def from_protocol(finished):
    """A Run from a Python runner's output (trace_protocol lines)."""
    import trace_protocol
    events, result = trace_protocol.parse(finished.stdout)
    if finished.timed_out:
        return Run(events, None, "timed out after %.0f s" % finished.seconds)
    if result is None:
        tail = (finished.stderr.strip().splitlines() or ["no output"])[-1]
        return Run(events, None, "exit %s: %s" % (finished.returncode, tail))
    return Run(events, result)


def preempt_flag(preempt_after):
    return [] if preempt_after is None else ["--preempt-after", str(preempt_after)]


def run_smach(tools, name, script, preempt_after=None):
    program = os.path.join(tools.work_dir, "smach", name + ".py")
    os.makedirs(os.path.dirname(program), exist_ok=True)
    problem = tools.compile(script, "smach", program)
    if problem:
        return Run(problem="smachac: " + problem)
    argv = [PYTHON, os.path.join(ROS_DIR, "run_smach.py"), program, *preempt_flag(preempt_after)]
    return from_protocol(tools.session.run(argv, TIMEOUT))


def run_flexbe(tools, name, script, preempt_after=None):
    import flexbe_package
    try:
        package = flexbe_package.generate(tools.smachac, os.path.basename(script),
                                          ["-target=flexbe"], os.path.dirname(script),
                                          os.path.join(tools.work_dir, "flexbe", name))
    except flexbe_package.GenerateError as error:
        return Run(problem="smachac: " + first_error(str(error)))
    env = tools.session.namespaced_env()  # the cases run two at a time
    for variable in ("PYTHONPATH", "ROS_PACKAGE_PATH"):
        env[variable] = package.workspace + os.pathsep + env[variable]
    argv = [PYTHON, os.path.join(ROS_DIR, "run_flexbe.py"), package.top[0],
            *preempt_flag(preempt_after)]
    return from_protocol(tools.session.processes.run(argv, env, TIMEOUT, cwd=package.workspace))


def run_cpp(tools, name, script, preempt_after=None):
    source = os.path.join(tools.work_dir, "cpp", name + ".cpp")
    os.makedirs(os.path.dirname(source), exist_ok=True)
    problem = tools.compile(script, "cpp", source)
    if problem:
        return Run(problem="smachac: " + problem)
    program = source[:-4]
    header = tools.precompiled_runtime_header()
    build = subprocess.run(tools.cxx_flags() + ["-include", header, source, tools.runtime_lib,
                                                "-o", program], capture_output=True, text=True)
    if build.returncode != 0:
        return Run(problem="c++: " + first_error(build.stderr))
    finished = tools.session.run([program, "--seed=1", "--trace=json", "--print-userdata"],
                                 TIMEOUT, interrupt_after=preempt_after)
    return cpp_run(finished)


def cpp_run(finished):
    """A Run from a C++ program's JSON-lines trace (stderr) and its outcome lines (stdout)."""
    events = []
    for line in finished.stderr.splitlines():
        if not line.startswith("{"):
            continue
        event = json.loads(line)
        if event["event"] in ("enter", "exit") and event["state"] not in ("", "<root>"):
            events.append({k: event[k] for k in ("event", "state", "outcome") if k in event})
    fields = {}  # the program's own output comes first; runMain's lines come last
    for line in finished.stdout.splitlines():
        for field in ("outcome", "userdata"):
            if line.startswith(field + ": "):
                fields[field] = line[len(field) + 2:]
    if finished.timed_out or "outcome" not in fields:
        why = "timed out" if finished.timed_out else "exit %s" % finished.returncode
        return Run(events, None, "%s: %s" % (why, finished.stderr.strip()[-300:]))
    userdata = ast.literal_eval(fields.get("userdata", "{}"))
    return Run(events, {"outcome": fields["outcome"], "userdata": userdata})


RUNNERS = {"smach": run_smach, "cpp": run_cpp, "flexbe": run_flexbe}
