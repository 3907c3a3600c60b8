"""Baxter's robot-level ROS interface over the simulation: enabling (/robot/state following
/robot/set_super_enable, reset and stop), joint states, each limb's endpoint state, and joint
position commands with their speed ratio."""
import threading

import rospy
from baxter_core_msgs.msg import AssemblyState, EndpointState, JointCommand
from sensor_msgs.msg import JointState
from std_msgs.msg import Bool, Empty, Float64

from command_pacer import CommandPacer

LIMBS = ("left", "right")
POSITION_MODES = (JointCommand.POSITION_MODE, JointCommand.RAW_POSITION_MODE)
SOFTWARE_VERSION = "1.2.0"  # the Baxter SDK release whose robot interface this serves
DEFAULT_SPEED_RATIO = 0.3  # Baxter's default joint position speed


class RobotTopics:
    def __init__(self, robot):
        self.robot = robot
        self.enabled = False
        self.stopped = False
        self.speed = {limb: DEFAULT_SPEED_RATIO for limb in LIMBS}
        self.names = {limb: robot.joint_names(limb) for limb in LIMBS}
        self.pacer = CommandPacer(LIMBS + tuple(limb + "_gripper" for limb in LIMBS))
        self._goals = {}  # limb -> the last commanded {joint: angle}
        self._lock = threading.Lock()
        rospy.set_param("/rethink/software_version", SOFTWARE_VERSION)
        self.state = rospy.Publisher("/robot/state", AssemblyState, queue_size=1, latch=True)
        self.joints = rospy.Publisher("/robot/joint_states", JointState, queue_size=1)
        self.endpoints = {limb: rospy.Publisher("/robot/limb/%s/endpoint_state" % limb,
                                                EndpointState, queue_size=1) for limb in LIMBS}
        rospy.Subscriber("/robot/set_super_enable", Bool, self.on_enable)
        rospy.Subscriber("/robot/set_super_reset", Empty, self.on_reset)
        rospy.Subscriber("/robot/set_super_stop", Empty, self.on_stop)
        for limb in LIMBS:
            rospy.Subscriber("/robot/limb/%s/joint_command" % limb, JointCommand,
                             self.on_command, limb, tcp_nodelay=True)
            rospy.Subscriber("/robot/limb/%s/set_speed_ratio" % limb, Float64,
                             self.on_speed, limb)
        self.publish_state()

    # ------------------------------------------------------------ commands

    def on_enable(self, message):
        self.enabled = bool(message.data)
        self.stopped = self.stopped and not self.enabled
        self.publish_state()

    def on_reset(self, _message):
        self.enabled, self.stopped = False, False
        self.publish_state()

    def on_stop(self, _message):
        self.enabled, self.stopped = False, True
        self.hold_all()
        self.publish_state()

    def on_speed(self, message, limb):
        self.speed[limb] = min(max(float(message.data), 0.0), 1.0)

    def on_command(self, message, limb):
        if not self.enabled or message.mode not in POSITION_MODES:
            return
        with self._lock:
            goal = self._goals.get(limb) or dict(zip(self.names[limb],
                                                     self.robot.joint_state(limb)[0]))
            goal.update((n, p) for n, p in zip(message.names, message.command)
                        if n in goal)
            self._goals[limb] = goal
        positions = [goal[name] for name in self.names[limb]]
        if not self.robot.command_positions(limb, positions, self.speed[limb]):
            rospy.logwarn_throttle(1.0, "%s joint command outside the joint limits: %s"
                                   % (limb, positions))
        self.pacer.received(limb, self.robot.time())

    def command(self, limb, positions, speed):
        """A command from inside the robot (the trajectory action): not paced."""
        with self._lock:
            self._goals[limb] = dict(zip(self.names[limb], positions))
        return self.robot.command_positions(limb, positions, speed)

    def hold_all(self):
        with self._lock:
            self._goals.clear()
        for limb in LIMBS:
            self.robot.command_positions(limb, self.robot.joint_state(limb)[0], 1.0)

    # ------------------------------------------------------------ state

    def publish_state(self):
        self.state.publish(AssemblyState(ready=True, enabled=self.enabled, stopped=self.stopped,
                                         error=False, estop_button=AssemblyState.ESTOP_BUTTON_UNPRESSED,
                                         estop_source=AssemblyState.ESTOP_SOURCE_NONE))

    def publish_sensors(self, stamp):
        message = JointState()
        message.header.stamp = stamp
        for limb in LIMBS:
            position, velocity, effort = self.robot.joint_state(limb)
            message.name += self.names[limb]
            message.position += position
            message.velocity += velocity
            message.effort += effort
        self.joints.publish(message)
        for limb in LIMBS:
            pose, twist = self.robot.endpoint(limb)
            endpoint = EndpointState()
            endpoint.header.stamp = stamp
            endpoint.header.frame_id = "base"
            p, o = endpoint.pose.position, endpoint.pose.orientation
            p.x, p.y, p.z, o.x, o.y, o.z, o.w = pose
            v, w = endpoint.twist.linear, endpoint.twist.angular
            v.x, v.y, v.z, w.x, w.y, w.z = twist
            self.endpoints[limb].publish(endpoint)
