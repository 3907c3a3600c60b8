#!/usr/bin/python3
"""The simulation's C interface (sim/ros/bridge) through sim_bridge.py, without ROS: failures
are values, never crashes, and the report is the C++ programs'.

  sim_bridge_test.py LIBRARY
"""
import os
import re
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))), "sim", "ros"))
from sim_bridge import BridgeError, SimulatedBaxter, load_library  # noqa: E402

LIBRARY = sys.argv.pop(1) if len(sys.argv) > 1 else "libsmachac_sim_bridge.so"
DOWN = [-0.02496, 0.99965, 0.00738, 0.00486]  # the scripts' gripper orientation (x, y, z, w)
UNTUCK = [-0.08, -1.0, -1.19, 1.94, 0.67, 1.03, -0.5]


class SimBridgeTest(unittest.TestCase):
    def setUp(self):
        self.robot = SimulatedBaxter(LIBRARY)

    def tearDown(self):
        self.robot.close()

    def test_a_missing_library_or_scene_is_an_error_with_the_reason(self):
        with self.assertRaisesRegex(BridgeError, "cannot load the simulation library"):
            load_library("/nonexistent/libsmachac_sim_bridge.so")
        with self.assertRaisesRegex(BridgeError, "cannot load the simulated world: .*nope.xml"):
            SimulatedBaxter(LIBRARY, "/nonexistent/nope.xml")

    def test_bodies_are_placed_or_refused_with_why(self):
        self.assertIsNone(self.robot.place_body("block1", [0.7, 0.15, -0.13, 0, 0, 0, 1], "base"))
        self.assertEqual(self.robot.place_body("crate", [0.7, 0, -0.13, 0, 0, 0, 1], "base"),
                         "the simulated world has no model 'crate'")
        self.assertEqual(self.robot.place_body("block2", [0.7, 0, -0.13, 0, 0, 0, 0], "base"),
                         "invalid pose for model 'block2'")
        self.assertIsNone(self.robot.body_pose("crate"))
        self.assertAlmostEqual(self.robot.body_pose("block1")[0], 0.7, places=6)

    def test_commands_outside_the_limits_are_refused(self):
        self.assertFalse(self.robot.command_positions("left", [0.0, 1.5, 0, 0, 0, 0, 0], 0.3))
        self.assertTrue(self.robot.command_positions("left", UNTUCK, 0.3))
        self.robot.step(3000)
        position, _velocity, effort = self.robot.joint_state("left")
        self.assertLess(max(abs(a - b) for a, b in zip(position, UNTUCK)), 1e-3)
        self.assertLess(effort[1], -20.0)  # s1 holds the arm up against gravity
        self.assertLess(abs(effort[6]), 0.1)  # w2 turns about a vertical axis

    def test_ik_solves_within_reach_only(self):
        solved, joints = self.robot.solve_ik("left", [0.7, 0.15, 0.02] + DOWN)
        self.assertTrue(solved)
        self.robot.command_positions("left", joints, 1.0)
        self.robot.step(3000)
        self.assertLess(max(abs(a - b) for a, b in zip(self.robot.endpoint("left")[0][:3],
                                                          [0.7, 0.15, 0.02])), 1e-3)
        self.assertFalse(self.robot.solve_ik("left", [1.4, 0.15, 0.0] + DOWN)[0])

    def test_gripper_position_and_grasp(self):
        self.robot.step(250)
        self.assertAlmostEqual(self.robot.gripper_state("right")[0], 100.0, delta=1.0)
        self.robot.command_gripper("right", 0.0)
        self.robot.step(500)
        percent, moving, gripping, _force = self.robot.gripper_state("right")
        self.assertLess(percent, 1.0)
        self.assertFalse(moving)
        self.assertFalse(gripping)  # closed on nothing

    def test_report_is_the_cpp_programs(self):
        self.robot.place_body("block1", [0.7, 0.0, -0.13, 0, 0, 0, 1], "base")
        self.robot.place_body("block2", [0.7, 0.0, -0.08, 0, 0, 0, 1], "base")
        self.robot.step(500)
        lines = self.robot.report().splitlines()
        self.assertEqual(lines[0], "scene after 1.00 s simulated")
        self.assertRegex(lines[1], r"^  block1 at \(0\.7000, -?0\.0000, -0\.13\d\d\) \(base frame\)$")
        self.assertTrue(re.match(r"^  stacked: block2 on block1 \(\|dxy\| \d\.\d mm, "
                                 r"\|dz - size\| \d\.\d mm\)$", lines[3]), lines[3])

    def test_a_snapshot_that_cannot_be_written_says_why(self):
        error = self.robot.snapshot("/nonexistent/folder/x.png")
        self.assertIsNotNone(error)
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "x.png")
            self.assertIsNone(self.robot.snapshot(path))
            with open(path, "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")


if __name__ == "__main__":
    unittest.main()
