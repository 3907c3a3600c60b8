{% block meta %}
name: BaxterUtils
description: >
  Macro library of the Baxter FlexBE templates: the head of the Baxter part of
  the behavior's states module (the Baxter SDK imports, the BaxterEventState
  base class, the pose and joint functions; written once, tracked in
  defined_headers) and the `OperatableStateMachine.add(...)` line of a Baxter
  state, whose arguments and input keys come from the script's variables.
language: Python
framework: FlexBE
type: None
tags: [baxter]
includes: []
extends: []
variables: []
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% from "Utils.tpl.py" import render_list, layout, class_ref, render_transitions, render_autonomy, remapping_argument %}

{# What every Baxter EventState needs, written once into the states module (ROS 1: the
   Baxter SDK is ROS 1 only). BaxterEventState runs start() on the first execute() and
   poll() on the next ones until one returns an outcome; any error (ROS, a missing key,
   malformed data) is logged and gives `aborted`. #}
{% macro define_baxter_module(defined_headers) -%}
{% if 'baxter_flexbe_module' not in defined_headers -%}
import os

import actionlib
import baxter_interface
import rospkg
import rospy
from baxter_core_msgs.srv import SolvePositionIK, SolvePositionIKRequest
from control_msgs.msg import (FollowJointTrajectoryAction, FollowJointTrajectoryGoal,
                              FollowJointTrajectoryResult)
from gazebo_msgs.srv import DeleteModel, SpawnModel
from geometry_msgs.msg import Point, Pose, PoseStamped, Quaternion
from std_msgs.msg import Header
from trajectory_msgs.msg import JointTrajectoryPoint


class BaxterEventState(EventState):
    """
    A Baxter state: outcomes succeeded, aborted, preempted. Each argument named in
    input_keys is read from the userdata key of that name instead. The first Baxter state
    to run enables the robot (as baxter_tools' enable_robot.py -e).
    """

    robot_enabled = False

    def __init__(self, arguments, input_keys=[], output_keys=[]):
        super(BaxterEventState, self).__init__(outcomes=['succeeded', 'aborted', 'preempted'],
                                               input_keys=list(input_keys),
                                               output_keys=list(output_keys))
        self._arguments = dict(arguments)
        self._argument_keys = list(input_keys)
        self._started = False
        self._outcome = None

    def arguments(self, userdata):
        values = dict(self._arguments)
        for key in self._argument_keys:
            values[key] = getattr(userdata, key)
        return values

    def guarded(self, step):
        try:
            return step()
        except Exception as error:  # ROS, a missing key, malformed data: an outcome
            Logger.logerr('%s: %s' % (type(self).__name__, error))
            return 'aborted'

    def on_enter(self, userdata):
        self._started = False
        self._outcome = None

    def execute(self, userdata):
        if not self._started:
            self._started = True
            self._outcome = self.guarded(lambda: self.begin(userdata))
        elif self._outcome is None:
            self._outcome = self.guarded(lambda: self.poll(userdata))
        return self._outcome

    def begin(self, userdata):
        if not BaxterEventState.robot_enabled:
            baxter_interface.RobotEnable(baxter_interface.CHECK_VERSION).enable()
            BaxterEventState.robot_enabled = True
        return self.start(userdata, **self.arguments(userdata))

    def start(self, userdata, **arguments):
        raise NotImplementedError

    def poll(self, userdata):
        return None


def baxter_pose_parts(pose):
    """([x, y, z], [qx, qy, qz, qw]) of a pose given nested, flat or as a position."""
    flat = [float(v) for v in (list(pose[0]) + list(pose[1]) if len(pose) == 2 else pose)]
    if len(flat) == 3:
        flat += [0.0, 0.0, 0.0, 0.0]
    if len(flat) != 7:
        raise ValueError('a pose is [[x, y, z], [qx, qy, qz, qw]], not %r' % (pose,))
    return flat[:3], flat[3:]


def baxter_quaternion_product(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz]


def baxter_offset_pose(pose, offset):
    """The pose moved by the offset's position, then turned by its rotation (if any)."""
    position, rotation = baxter_pose_parts(pose)
    shift, turn = baxter_pose_parts(offset)
    position = [p + s for p, s in zip(position, shift)]
    if any(turn):
        rotation = baxter_quaternion_product(rotation, turn)
    return [position, rotation]


def baxter_pose_msg(pose):
    position, rotation = baxter_pose_parts(pose)
    if not any(rotation):
        rotation = [0.0, 0.0, 0.0, 1.0]
    return Pose(position=Point(*position), orientation=Quaternion(*rotation))


def baxter_joint_positions(limb_interface, positions):
    """{joint: angle} from [s0, s1, e0, e1, w0, w1, w2] or a {joint: angle} dict."""
    if isinstance(positions, dict):
        return dict(positions)
    names = limb_interface.joint_names()
    if len(positions) != len(names):
        raise ValueError('joint positions are %d angles, not %r' % (len(names), positions))
    return dict(zip(names, [float(q) for q in positions]))
{% do defined_headers.append('baxter_flexbe_module') %}
{%- endif %}
{%- endmacro %}

{# `name=value` for a variable the script gives: text quoted, data as Python literals
   (`pyliteral`: nan and inf as float('nan'), float('inf')). #}
{% macro text_argument(name, value) -%}
{{ name }}={{ value | string | pyrepr }}
{%- endmacro %}

{% macro data_argument(name, value) -%}
{{ name }}={{ value | pyliteral }}
{%- endmacro %}

{# The state's line in its container, as State.tpl.py writes it, with the arguments the
   template computed and `input_keys=[...]` (the variables the script left out). #}
{% macro render_baxter_add(defined_headers, module, cls, name, arguments, input_keys, output_keys, transitions, autonomy, remapping) -%}
{% set all_arguments = arguments + ['input_keys=' ~ render_list(input_keys)] -%}
{{ layout(defined_headers) }}
OperatableStateMachine.add({{ name | pyrepr }}, {{ class_ref(defined_headers, module, cls) }}({{ all_arguments | join(', ') }}), {{ render_transitions(transitions if transitions is defined else {}) }}, {{ render_autonomy(transitions if transitions is defined else {}, autonomy) }}{{ remapping_argument(input_keys, output_keys, remapping) }})
{%- endmacro %}
