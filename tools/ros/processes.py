"""Processes that a ROS test starts, and the guarantee that none outlives the test.

Every process is started in a session of its own and is told by the kernel to die with its
parent (PR_SET_PDEATHSIG), so even a test runner that kills the test with SIGKILL leaves
nothing behind. A normal exit, an exception, SIGINT or SIGTERM stop them all by PID: SIGINT
first (ROS nodes shut down cleanly on it), SIGKILL to the whole group after a grace period.
"""
import ctypes
import os
import signal
import subprocess
import threading
import time

PR_SET_PDEATHSIG = 1
_libc = ctypes.CDLL(None, use_errno=True)


def _die_with_parent():
    _libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL)


def _raise_exit(signum, _frame):
    raise SystemExit(128 + signum)


class Finished:
    """What a process run to its end (or to its timeout) left: exit code, output, timing."""

    def __init__(self, returncode, stdout, stderr, timed_out, seconds):
        self.returncode = returncode
        self.stdout = stdout
        self.stderr = stderr
        self.timed_out = timed_out
        self.seconds = seconds


class Processes:
    """A context manager that owns the processes it starts and stops all of them on exit."""

    def __init__(self, grace_seconds=3.0):
        self.grace_seconds = grace_seconds
        self.running = []

    def __enter__(self):
        # Signal handlers belong to the main thread; a session opened in a worker thread is
        # stopped when its `with` ends (the main thread's session turns the signal into
        # SystemExit) or, at the latest, with the test process (PR_SET_PDEATHSIG).
        self._previous = {}
        if threading.current_thread() is threading.main_thread():
            self._previous = {s: signal.signal(s, _raise_exit)
                              for s in (signal.SIGTERM, signal.SIGINT)}
        return self

    def __exit__(self, *_exc):
        self.stop_all()
        for s, handler in self._previous.items():
            signal.signal(s, handler)
        return False

    def start(self, argv, env, log_path, cwd=None):
        """Starts a long-running process (a master, a fixture) whose output goes to log_path."""
        log = open(log_path, "wb")
        process = subprocess.Popen(argv, env=env, cwd=cwd, stdin=subprocess.DEVNULL, stdout=log,
                                   stderr=subprocess.STDOUT, start_new_session=True,
                                   preexec_fn=_die_with_parent)
        log.close()
        self.running.append(process)
        return process

    def run(self, argv, env, timeout, cwd=None, interrupt_after=None):
        """Runs a process to its end; on timeout it is stopped and reported, never raised.
        With interrupt_after, the process gets one SIGINT that many seconds after its start."""
        began = time.monotonic()
        process = subprocess.Popen(argv, env=env, cwd=cwd, stdin=subprocess.DEVNULL,
                                   stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                   errors="replace", start_new_session=True,
                                   preexec_fn=_die_with_parent)
        self.running.append(process)
        interrupt = None
        if interrupt_after is not None:
            interrupt = threading.Timer(interrupt_after, _interrupt, (process,))
            interrupt.start()
        timed_out = False
        try:
            stdout, stderr = process.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            timed_out = True
            self.stop(process)
            stdout, stderr = process.communicate()
        finally:
            if interrupt is not None:
                interrupt.cancel()
        if process in self.running:  # stop() has removed a process that timed out
            self.running.remove(process)
        return Finished(process.returncode, stdout, stderr, timed_out, time.monotonic() - began)

    def stop(self, process):
        """SIGINT, then SIGKILL to the process group after the grace period; waits for it."""
        if process.poll() is None:
            _signal_group(process, signal.SIGINT)
            try:
                process.wait(timeout=self.grace_seconds)
            except subprocess.TimeoutExpired:
                pass
        _signal_group(process, signal.SIGKILL)  # also children the process left behind
        process.wait()
        if process in self.running:
            self.running.remove(process)

    def stop_all(self):
        for process in reversed(list(self.running)):
            self.stop(process)


def _interrupt(process):
    if process.poll() is None:
        process.send_signal(signal.SIGINT)


def _signal_group(process, signum):
    try:
        os.killpg(process.pid, signum)
    except (ProcessLookupError, PermissionError):
        pass
