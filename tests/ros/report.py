"""The lines a ROS test prints: one per case, then the plain closing line.

    ok smach/sequence outcome failed (0.4 s)
    FAIL smach/ros_states outcome aborted, expected done (3.1 s)
    skip smach/userdata_values (Point() is written bare ...)
    21 passed, 1 failed, 1 skipped
"""
import sys


class Report:
    def __init__(self):
        self.passed = self.failed = self.skipped = 0

    def ok(self, case, what, seconds=None):
        self.passed += 1
        timing = "" if seconds is None else " (%.1f s)" % seconds
        self._print("ok %s %s%s" % (case, what, timing))

    def fail(self, case, why, seconds=None, details=""):
        self.failed += 1
        timing = "" if seconds is None else " (%.1f s)" % seconds
        self._print("FAIL %s %s%s" % (case, why, timing))
        if details.strip():
            self._print("\n".join("    " + line for line in details.strip().splitlines()[-25:]))

    def skip(self, case, why):
        self.skipped += 1
        self._print("skip %s (%s)" % (case, why))

    def close(self):
        """Prints the closing line; the exit code of the test (0 only when nothing failed)."""
        self._print("%d passed, %d failed, %d skipped" % (self.passed, self.failed, self.skipped))
        return 1 if self.failed else 0

    @staticmethod
    def _print(text):
        sys.stdout.write(text + "\n")
        sys.stdout.flush()


class Deferred:
    """Records ok / fail / skip calls (e.g. of a scenario run in a worker thread) to replay
    them on a Report later, so that lines come out in a fixed order."""

    def __init__(self):
        self.calls = []

    def __getattr__(self, name):
        if name not in ("ok", "fail", "skip"):
            raise AttributeError(name)
        return lambda *args, **kwargs: self.calls.append((name, args, kwargs))

    def replay(self, report):
        for name, args, kwargs in self.calls:
            getattr(report, name)(*args, **kwargs)
