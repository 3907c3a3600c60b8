"""A program run in a RosSession whose output is watched while it runs: each line gets the
time it appeared, so a test can measure how long a state took, or act (signal the program)
when a line appears.

    run = LiveRun(ros, "prog", [PYTHON, "run_smach.py", "prog.py"])
    entered = run.wait_for('"event": "enter", "state": "READ"', 10)   # seconds since start
    run.signal(signal.SIGTERM)
    run.finish(timeout=10)      # stops it (by PID) if it is still running; never raises
    run.timed_out, run.returncode, run.lines   # [(seconds, text), ...]
"""
import os
import time

from ros_session import read


class LiveRun:
    def __init__(self, ros, name, argv, cwd=None):
        self.ros = ros
        self.log = os.path.join(ros.work_dir, name + ".out")
        self.began = time.monotonic()
        self.process = ros.processes.start(argv, ros.env, self.log, cwd=cwd or ros.work_dir)
        self.lines = []
        self._seen = 0
        self.timed_out = False
        self.returncode = None

    def poll(self):
        """Reads the lines the program has written since the last poll."""
        text = read(self.log)
        complete = text[:text.rfind("\n") + 1]
        now = time.monotonic() - self.began
        for line in complete[self._seen:].splitlines():
            self.lines.append((now, line))
        self._seen = len(complete)

    def wait_for(self, marker, seconds):
        """Seconds since the start when a line holding marker appeared, None if it did not."""
        deadline = time.monotonic() + seconds
        while True:
            self.poll()
            for at, line in self.lines:
                if marker in line:
                    return at
            if self.process.poll() is not None or time.monotonic() > deadline:
                self.poll()
                return next((at for at, line in self.lines if marker in line), None)
            time.sleep(0.02)

    def signal(self, signum):
        if self.process.poll() is None:
            self.process.send_signal(signum)

    def finish(self, timeout):
        """Waits for the program's end, polling its output; stops it after timeout."""
        deadline = time.monotonic() + timeout
        while self.process.poll() is None and time.monotonic() < deadline:
            self.poll()
            time.sleep(0.02)
        self.timed_out = self.process.poll() is None
        self.ros.stop(self.process)
        self.poll()
        self.returncode = self.process.returncode
        return self

    def ended_at(self):
        return self.lines[-1][0] if self.lines else None

    def text(self):
        return "\n".join(line for _, line in self.lines)
