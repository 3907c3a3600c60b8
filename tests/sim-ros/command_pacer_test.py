#!/usr/bin/python3
"""CommandPacer (sim/ros/command_pacer.py) without ROS: simulated time waits for a stream's
due command, gives up after its patience and runs free, and keeps the stream's period for
the next stream of the same name.

  command_pacer_test.py
"""
import os
import sys
import threading
import time
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))), "sim", "ros"))
from command_pacer import CommandPacer  # noqa: E402

PATIENCE = 0.2


class CommandPacerTest(unittest.TestCase):
    def setUp(self):
        self.pacer = CommandPacer(["left", "right_gripper"], patience=PATIENCE)

    def timed_wait(self, sim_time):
        began = time.monotonic()
        running = self.pacer.wait_for_due_commands(sim_time)
        return running, time.monotonic() - began

    def test_no_stream_no_wait(self):
        self.assertEqual(self.timed_wait(1.0)[0], False)
        self.pacer.received("left", 1.0)  # one command: no period yet
        running, waited = self.timed_wait(1.5)
        self.assertFalse(running)
        self.assertLess(waited, 0.05)

    def test_waits_for_the_due_command(self):
        self.pacer.received("left", 1.00)
        self.pacer.received("left", 1.01)  # period 0.01
        running, waited = self.timed_wait(1.015)  # not due yet
        self.assertTrue(running)
        self.assertLess(waited, 0.05)
        threading.Timer(0.05, self.pacer.received, ("left", 1.02)).start()
        running, waited = self.timed_wait(1.02)  # due: waits for it
        self.assertTrue(running)
        self.assertGreater(waited, 0.04)
        self.assertLess(waited, PATIENCE)

    def test_patience_ends_the_stream_and_the_period_is_kept(self):
        self.pacer.received("right_gripper", 2.0)
        self.pacer.received("right_gripper", 2.1)
        running, waited = self.timed_wait(2.2)
        self.assertGreaterEqual(waited, PATIENCE * 0.9)
        self.assertFalse(running)
        self.assertLess(self.timed_wait(2.3)[1], 0.05)  # ended: runs free
        self.pacer.received("right_gripper", 5.0)  # a new stream, paced from its first command
        running, waited = self.timed_wait(5.05)
        self.assertTrue(running)
        self.assertLess(waited, 0.05)
        running, waited = self.timed_wait(5.1)
        self.assertGreaterEqual(waited, PATIENCE * 0.9)


if __name__ == "__main__":
    unittest.main()
