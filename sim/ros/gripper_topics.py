"""Baxter's electric grippers over the simulation: /robot/end_effector/<side>_gripper/state
(echoing the last command, its sender and sequence, as baxter_interface.Gripper waits for),
latched properties, and the commands calibrate, clear_calibration, go (a position in percent,
0 closed, 100 open) and stop; other commands (configure, reset, ...) are acknowledged. The
fingers close along a ramp (FINGER_RATE), as Baxter's gripper moves at a set velocity:
fingers slammed shut would bounce off a block and report a false closed position. They open
at once, as the C++ robot states open them: pads that let go slowly drag the block along.
It reports `moving` from the command on until the ramp has ended and the fingers have stopped,
and `gripping` once they have stopped on a body between both pads."""
import json
import threading

import rospy
from baxter_core_msgs.msg import EndEffectorCommand, EndEffectorProperties, EndEffectorState

SIDES = ("left", "right")
HARDWARE_ID = 65664  # an electric gripper's id
FIRMWARE_DATE = "2015/01/01 00:00:00"  # newer than the SDK 1.2.0 gripper warning date
TRUE, FALSE = EndEffectorState.STATE_TRUE, EndEffectorState.STATE_FALSE
FINGER_RATE = 150.0  # percent of the fingers' travel per second
SETTLE_TIME = 0.1  # s after the ramp's end before a still gripper has finished its action


class GripperTopics:
    def __init__(self, robot, snapshots, pacer):
        self.robot = robot
        self.pacer = pacer
        self.snapshots = snapshots
        self.status = {side: dict(calibrated=False, command="", sender="", sequence=0,
                                  action=None, missed=False, goal=100.0, commanded=100.0,
                                  reached=0.0) for side in SIDES}
        self.lock = threading.Lock()  # commands (ROS threads) against the ramps (the loop)
        self.state = {}
        self.property_topics = {}
        for side in SIDES:
            namespace = "/robot/end_effector/%s_gripper/" % side
            self.state[side] = rospy.Publisher(namespace + "state", EndEffectorState,
                                               queue_size=1)
            self.property_topics[side] = rospy.Publisher(
                namespace + "properties", EndEffectorProperties, queue_size=1, latch=True)
            self.property_topics[side].publish(self.properties())
            rospy.Subscriber(namespace + "command", EndEffectorCommand, self.on_command, side)

    @staticmethod
    def properties():
        return EndEffectorProperties(
            id=HARDWARE_ID, ui_type=EndEffectorProperties.ELECTRIC_GRIPPER,
            manufacturer="Rethink Research Robot", product="Electric Gripper",
            firmware_date=FIRMWARE_DATE, has_calibration=True, controls_grip=True,
            senses_grip=True, reverses_grip=False, controls_force=True, senses_force=True,
            controls_position=True, senses_position=True)

    def on_command(self, message, side):
        with self.lock:
            self.take_command(message, side)

    def take_command(self, message, side):
        status = self.status[side]
        repeated = (message.sender, message.sequence) == (status["sender"], status["sequence"])
        status.update(command=message.command, sender=message.sender,
                      sequence=message.sequence)
        self.pacer.received(side + "_gripper", self.robot.time())
        if repeated:  # baxter_interface re-sends a command while it waits for it
            return
        if message.command == EndEffectorCommand.CMD_CALIBRATE:
            status["calibrated"] = True
            self.go(side, 100.0)
        elif message.command == EndEffectorCommand.CMD_CLEAR_CALIBRATION:
            status["calibrated"] = False
        elif message.command == EndEffectorCommand.CMD_GO and status["calibrated"]:
            position = self.position_argument(message.args)
            if position is None:
                rospy.logwarn("%s gripper: `go` without a numeric position: %r", side,
                              message.args)
            else:
                self.go(side, position)
        elif message.command == EndEffectorCommand.CMD_STOP:
            self.go(side, self.robot.gripper_state(side)[0])

    @staticmethod
    def position_argument(args):
        """The position (percent, clamped) of a `go` command's JSON arguments, or None."""
        try:
            return min(max(float(json.loads(args or "{}")["position"]), 0.0), 100.0)
        except (ValueError, KeyError, TypeError):
            return None

    def go(self, side, percent):
        status = self.status[side]
        status.update(goal=percent, missed=False,
                      action="close" if percent < status["commanded"] else "open")

    def ramp(self, side, seconds):
        """Moves the fingers' command toward the goal: closing by at most FINGER_RATE *
        seconds, opening at once (as the C++ robot states open)."""
        status = self.status[side]
        closing = status["goal"] < status["commanded"]
        step = FINGER_RATE * seconds if closing else 100.0
        gap = status["goal"] - status["commanded"]
        if gap == 0.0:
            return
        status["commanded"] += max(-step, min(step, gap))
        if status["commanded"] == status["goal"]:
            status["reached"] = self.robot.time()
        self.robot.command_gripper(side, status["commanded"])

    def publish(self, stamp, seconds):
        """Advances the fingers' ramps by `seconds` and publishes both grippers' states."""
        for side in SIDES:
            with self.lock:
                self.ramp(side, seconds)
                position, moving, gripping, force = self.robot.gripper_state(side)
                status = self.status[side]
                moving = moving or status["commanded"] != status["goal"]
                gripping = gripping and not moving
                self.finish_action(side, status, moving, gripping)
                status = dict(status)  # what is published, as it is now
            self.state[side].publish(EndEffectorState(
                timestamp=stamp, id=HARDWARE_ID, enabled=TRUE,
                calibrated=TRUE if status["calibrated"] else FALSE, ready=TRUE,
                moving=TRUE if moving else FALSE, gripping=TRUE if gripping else FALSE,
                missed=TRUE if status["missed"] else FALSE, error=FALSE, reverse=FALSE,
                position=position, force=force, state="{}", command=status["command"],
                command_sender=status["sender"], command_sequence=status["sequence"]))

    def finish_action(self, side, status, moving, gripping):
        """When the fingers of a commanded action have settled: a snapshot, and `missed`
        for a close that holds nothing."""
        action = status["action"]
        if (action is None or moving or status["commanded"] != status["goal"]
                or self.robot.time() - status["reached"] < SETTLE_TIME):
            return
        status["action"] = None
        status["missed"] = action == "close" and not gripping
        self.snapshots.take("%s_gripper_%s" % (side, action))
