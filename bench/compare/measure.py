"""Running a command and measuring it: wall time, CPU time (user + system) and peak RSS of the
child, from os.wait4; medians; paired runs of smachac and an anchor.

A Sample is one run. pair() runs two commands alternately (smachac first on even runs, the
anchor first on odd ones, so neither always runs on a warmer cache) and keeps each run's
ratio anchor / smachac: the ratio of a row is the median of those per-run ratios, not the
ratio of the two medians.
"""
import os
import statistics
import signal
import subprocess
import tempfile
import threading
import time


class Failed(Exception):
    """A measured command exited with an error, or its output was not what it should be;
    argv is the command (a list of str), when there was one."""

    def __init__(self, message, argv=()):
        super().__init__(message)
        self.argv = list(argv)


class Sample:
    """One run: wall and CPU seconds, peak RSS in MB, and the output when it was kept."""

    def __init__(self, wall, cpu, rss_mb, stdout=""):
        self.wall, self.cpu, self.rss_mb, self.stdout = wall, cpu, rss_mb, stdout

    def get(self, what):
        return getattr(self, what)


def run(argv, env=None, stdout=None, keep_stdout=False, timeout=600):
    """Runs argv to its end and returns its Sample; raises Failed on a non-zero exit or when
    it runs longer than timeout seconds (it is killed). stdout: a path to write the standard
    output to (else it is discarded, or kept in the Sample with keep_stdout). The wall time
    includes starting the process from Python (about 0.5 ms: see /bin/true's row), but not
    the start of the thread that watches for the timeout, which waits before the clock starts."""
    argv = [str(a) for a in argv]
    with tempfile.TemporaryFile() as err, tempfile.TemporaryFile() as kept:
        out = open(stdout, "wb") if stdout else (kept if keep_stdout else subprocess.DEVNULL)
        watchdog = _Watchdog(timeout)
        try:
            start = time.perf_counter()
            proc = subprocess.Popen(argv, stdout=out, stderr=err, env=env)
            watchdog.watch(proc.pid)
            try:
                _, status, usage = os.wait4(proc.pid, 0)  # blocks; keeps the child's rusage
            finally:
                watchdog.stop()
            wall = time.perf_counter() - start
            proc.returncode = os.waitstatus_to_exitcode(status)
        finally:
            watchdog.stop()
            if stdout:
                out.close()
        kept.seek(0)
        text = kept.read().decode(errors="replace")
        if proc.returncode != 0:
            err.seek(0)
            raise Failed("%s exited %d:\n%s" % (" ".join(argv), proc.returncode,
                                                 err.read().decode(errors="replace")[-3000:]),
                         argv)
    return Sample(wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024.0, text)


class _Watchdog:
    """A thread, started before the measured run, that kills the watched process if it has
    not ended `timeout` seconds after watch() (or after the watchdog started, if earlier)."""

    def __init__(self, timeout):
        self._pid = None
        self._done = threading.Event()
        self._thread = threading.Thread(target=self._wait, args=(timeout,), daemon=True)
        self._thread.start()

    def watch(self, pid):
        self._pid = pid

    def stop(self):
        self._done.set()

    def _wait(self, timeout):
        if not self._done.wait(timeout) and self._pid is not None:
            try:
                os.kill(self._pid, signal.SIGKILL)
            except ProcessLookupError:
                pass


def median(values):
    return statistics.median(values) if values else None


class Pair:
    """Paired runs of smachac and an anchor: their samples and the per-run ratios."""

    def __init__(self):
        self.ours, self.anchor = [], []

    def add(self, ours, anchor):
        self.ours.append(ours)
        self.anchor.append(anchor)

    def median(self, side, what):
        return median([s.get(what) for s in (self.ours if side == "ours" else self.anchor)])

    def ratio(self, what):
        """Median of anchor / smachac over the runs."""
        ratios = [a.get(what) / o.get(what) for o, a in zip(self.ours, self.anchor)
                  if o.get(what) > 0]
        return median(ratios)


def pair(repeats, ours, anchor, anchor_repeats=None):
    """Runs the callables ours() and anchor() (each returns a Sample) `repeats` times
    alternately, the anchor only in the first `anchor_repeats` runs when that is given (a slow
    anchor); returns the Pair (ratios over the runs that have both)."""
    result = Pair()
    anchor_repeats = repeats if anchor_repeats is None else anchor_repeats
    for i in range(repeats):
        if i >= anchor_repeats:
            result.ours.append(ours())
        elif i % 2 == 0:
            o = ours()
            result.add(o, anchor())
        else:
            a = anchor()
            result.add(ours(), a)
    return result


def repeat(repeats, fn):
    """fn() `repeats` times: the list of Samples."""
    return [fn() for _ in range(repeats)]
