#!/usr/bin/python3
"""The simulated Baxter as a ROS 1 node: the MuJoCo world of sim/ serving the ROS interface of
a Baxter in Gazebo, so that programs written for the Baxter SDK (baxter_interface) run on it
unchanged. Run it with Debian's /usr/bin/python3 and a ROS master:

  baxter_node.py [--library PATH] [--scene MJCF] [--snapshots DIR] [--max-rtf X]
                 [--idle-rtf X] [--settle SECONDS] [--report-json FILE]

It sets /use_sim_time and publishes /clock. While a program streams commands, simulated time
advances in step with them (command_pacer.py), as fast as the program keeps up (at most
--max-rtf times real time); otherwise at --idle-rtf times real time, so that the SDK's waits,
whose timeouts are in simulated time, leave a program time to connect to new topics; and while
a subscriber the master lists has not connected, time stands still (connection_gate.py). It
prints "FIXTURE READY" once it serves everything. On SIGINT or SIGTERM it steps --settle
simulated seconds, takes a last snapshot and prints the scene report of the C++ Baxter
programs and the real-time factor (with --report-json, also as JSON: the report, the time
simulated until the stop and the wall time it took, the block poses, the arms' joint positions
and endpoint poses, and the fastest joint speed after settling).
"""
import argparse
import json
import os
import signal
import sys
import threading
import time

import rosgraph
import rospy
from rosgraph_msgs.msg import Clock

from connection_gate import ConnectionGate
from gazebo_services import GazeboServices
from gripper_topics import GripperTopics
from ik_service import IkService
from robot_topics import RobotTopics
from sim_bridge import BridgeError, SimulatedBaxter
from snapshots import Snapshots
from trajectory_action import TrajectoryAction

TICK = 0.01  # s of simulated time between two publications (Baxter's 100 Hz)
STATE_EVERY = 10  # ticks between two /robot/state messages
BLOCKS = ("block1", "block2")


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--library", default=os.environ.get(
        "SMACHAC_SIM_BRIDGE", os.path.join(here, "libsmachac_sim_bridge.so")))
    parser.add_argument("--scene", default="")
    parser.add_argument("--snapshots", default="")
    parser.add_argument("--max-rtf", type=float, default=20.0)
    parser.add_argument("--idle-rtf", type=float, default=4.0)
    parser.add_argument("--settle", type=float, default=1.0)
    parser.add_argument("--report-json", default="")
    return parser.parse_args(rospy.myargv()[1:])


class BaxterNode:
    def __init__(self, args, robot):
        self.args = args
        self.robot = robot
        self.snapshots = Snapshots(robot, args.snapshots)
        self.clock = rospy.Publisher("/clock", Clock, queue_size=1)
        self.topics = RobotTopics(robot)
        self.grippers = GripperTopics(robot, self.snapshots, self.topics.pacer)
        self.services = (GazeboServices(robot), IkService(robot),
                         TrajectoryAction(robot, self.topics))
        self.steps_per_tick = max(1, int(round(TICK / robot.timestep)))
        self.stop = threading.Event()
        self.gate = ConnectionGate(rospy.get_name(), {
            publisher.resolved_name: publisher
            for publisher in [self.clock, self.topics.state, self.topics.joints,
                              *self.topics.endpoints.values(), *self.grippers.state.values(),
                              *self.grippers.property_topics.values()]})

    def run(self):
        """Steps and publishes until shutdown; returns the wall seconds spent from the first
        program's connection on."""
        tick = 0
        self.publish(tick)  # /clock starts: nodes with use_sim_time wait for it
        print("FIXTURE READY", flush=True)
        while not (self.stop.is_set() or rospy.is_shutdown() or self.gate.subscribed("/clock")):
            time.sleep(0.01)  # time starts when the first program has connected
            self.publish(tick)
        began = time.monotonic()
        while not self.stop.is_set() and not rospy.is_shutdown():
            tick_began = time.monotonic()
            self.gate.wait()
            streaming = self.topics.pacer.wait_for_due_commands(self.robot.time())
            self.robot.step(self.steps_per_tick)
            tick += 1
            self.publish(tick)
            rtf = self.args.max_rtf if streaming else self.args.idle_rtf
            rest = TICK / rtf - (time.monotonic() - tick_began)
            if rest > 0.0:
                time.sleep(rest)
        return time.monotonic() - began

    def publish(self, tick):
        """The robot's state first, then the clock: a program woken by the clock then reads
        the state of that instant."""
        stamp = rospy.Time.from_sec(self.robot.time())
        self.topics.publish_sensors(stamp)
        self.grippers.publish(stamp, TICK)
        if tick % STATE_EVERY == 0:
            self.topics.publish_state()
        self.clock.publish(Clock(clock=stamp))

    def finish(self, wall_seconds):
        simulated = self.robot.time()
        self.robot.step(int(round(self.args.settle / self.robot.timestep)))
        self.snapshots.take("final")
        report = self.robot.report()
        rtf = simulated / wall_seconds if wall_seconds > 0 else 0.0
        sys.stdout.write(report)
        sys.stdout.write("real-time factor %.1f (%.2f s simulated in %.2f s)\n"
                         % (rtf, simulated, wall_seconds))
        sys.stdout.flush()
        if self.args.report_json:
            self.write_json(report, simulated, wall_seconds)

    def write_json(self, report, simulated, wall_seconds):
        joint_speed = max(abs(v) for side in ("left", "right")
                          for v in self.robot.joint_state(side)[1])
        description = {"report": report, "time": self.robot.time(), "simulated": simulated,
                       "wall_seconds": wall_seconds, "max_joint_speed": joint_speed,
                       "blocks": {name: self.robot.body_pose(name) for name in BLOCKS},
                       "endpoints": {side: self.robot.endpoint(side)[0]
                                     for side in ("left", "right")},
                       "joints": {side: self.robot.joint_state(side)[0]
                                  for side in ("left", "right")}}
        with open(self.args.report_json, "w", encoding="utf-8") as f:
            json.dump(description, f, indent=1)


def main():
    args = parse_arguments()
    # Simulated time for every node, this one too: set before init_node reads it.
    rosgraph.Master("/baxter_sim").setParam("/use_sim_time", True)
    try:
        robot = SimulatedBaxter(args.library, args.scene)
    except BridgeError as error:
        print("baxter_node: %s" % error, file=sys.stderr)
        return 1
    # SIGINT and SIGTERM end the loop; the report comes before rospy's own shutdown, which
    # waits up to seconds for each of its threads.
    rospy.init_node("baxter_sim", disable_signals=True)
    node = BaxterNode(args, robot)
    for signum in (signal.SIGINT, signal.SIGTERM):
        signal.signal(signum, lambda _signum, _frame: node.stop.set())
    wall_seconds = node.run()
    node.finish(wall_seconds)
    robot.close()
    return 0


if __name__ == "__main__":
    code = main()
    sys.stdout.flush()
    os._exit(code)  # rospy has shut down; its remaining threads would only delay the exit
