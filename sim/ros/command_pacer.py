"""Keeps simulated time in step with a program that streams commands.

baxter_interface's moves publish a joint command once per period of a rospy.Rate (100 Hz of
simulated time), FlexBE's states once per behavior tick (10 Hz); the SDK's blocking gripper
commands re-send the command at 100 Hz while they wait. Each such stream has a name (a limb,
a gripper). A simulation free to run ahead of such a program would see fewer commands per
simulated second the busier the machine is, and a move would take longer in simulated time.

So, while a stream's commands come at a steady period, the node waits before stepping past
the time its next command is due, until that command arrives or `patience` seconds of wall
time have passed; then the stream is taken to have ended and the simulation runs free until
the next one. A stream's period is kept when it ends, so that the next stream of the same
name is paced from its first command on (a program's moves all stream at one rate): runs
then repeat, whatever the load.
"""
import threading
import time

LONGEST_PERIOD = 0.5  # s of simulated time between two commands of one stream


class CommandPacer:
    def __init__(self, streams, patience=0.1):
        self.patience = patience
        self._changed = threading.Condition()
        self._last = {name: None for name in streams}  # simulated time of the last command
        self._period = {name: None for name in streams}  # between its commands, once known
        self._active = {name: False for name in streams}

    def received(self, stream, sim_time):
        with self._changed:
            last = self._last[stream]
            if self._active[stream] and 0.0 < sim_time - last <= LONGEST_PERIOD:
                self._period[stream] = sim_time - last
            self._last[stream] = sim_time
            self._active[stream] = True
            self._changed.notify_all()

    def wait_for_due_commands(self, sim_time):
        """Returns when no stream's next command is due at sim_time (or patience ran out), and
        whether any stream is running."""
        with self._changed:
            for stream in self._last:
                self._wait_for(stream, sim_time)
            return any(self._active[stream] and self._period[stream] is not None
                       for stream in self._period)

    def _wait_for(self, stream, sim_time):
        period, last = self._period[stream], self._last[stream]
        if not self._active[stream] or period is None or last + period > sim_time + 1e-9:
            return
        deadline = time.monotonic() + self.patience
        while self._last[stream] == last:
            remaining = deadline - time.monotonic()
            if remaining <= 0.0:
                self._active[stream] = False  # the stream has ended
                return
            self._changed.wait(remaining)
