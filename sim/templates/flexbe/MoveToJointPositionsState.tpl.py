{% block meta %}
name: MoveToJointPositionsState
description: >
  Moves a limb to joint positions at a fraction of the joint velocity limits:
  an EventState (behavior's states module) that commands
  baxter_interface.Limb's set_joint_positions on every execute() until the
  limb is within tolerance of the goal (aborted at the timeout). A variable
  left out is read from the input key of the same name (limb, positions).
language: Python
framework: FlexBE
type: State
tags: [baxter]
includes: []
extends:
- State
variables:
- - limb:
      description: left or right (default input key limb).
      type: str
- - positions:
      description: >
        Joint positions [s0, s1, e0, e1, w0, w1, w2] in radians (default
        input key positions).
      type: list of float
- - speed:
      description: Fraction of the joint velocity limits (default 0.3).
      type: float
- - timeout:
      description: Seconds for the move (default 15).
      type: float
input_keys: []
output_keys: []
outcomes: [succeeded, aborted, preempted]
{% endblock meta %}
{% extends "State.tpl.py" %}
{% from "BaxterUtils.tpl.py" import define_baxter_module, text_argument, data_argument, render_baxter_add %}
{% set state_module = '' %}
{% set state_class = 'MoveToJointPositionsState' %}

{% block class_defs %}
{{ define_baxter_module(defined_headers) }}


{% if 'class_MoveToJointPositionsState' not in defined_headers %}
class MoveToJointPositionsState(BaxterEventState):
    """
    Moves a limb to joint positions at a fraction of the joint velocity limits.

    -- limb         string  left or right (None: the input key limb).
    -- positions    list    [s0, s1, e0, e1, w0, w1, w2] in radians (None: the input key).
    -- speed        float   Fraction of the joint velocity limits.
    -- timeout      float   Seconds for the move.
    -- input_keys   list    The arguments read from the userdata.

    ># limb         string  The limb, when limb is an input key.
    ># positions    list    The joint positions, when positions is an input key.

    <= succeeded            The limb is within tolerance of the positions.
    <= aborted              It is not by the timeout.
    <= preempted            The behavior was preempted.
    """

    TOLERANCE = 0.008726646  # rad per joint, the Baxter SDK's default threshold

    def __init__(self, limb=None, positions=None, speed=0.3, timeout=15.0, input_keys=[]):
        BaxterEventState.__init__(self, dict(limb=limb, positions=positions, speed=speed,
                                             timeout=timeout), input_keys)

    def start(self, userdata, limb, positions, speed, timeout):
        self._limb = baxter_interface.Limb(limb)
        self._goal = baxter_joint_positions(self._limb, positions)
        self._limb.set_joint_position_speed(speed)
        self._deadline = rospy.get_time() + timeout
        return self.poll(userdata)

    def poll(self, userdata):
        angles = self._limb.joint_angles()
        if all(abs(angles[joint] - angle) <= self.TOLERANCE
               for joint, angle in self._goal.items()):
            return 'succeeded'
        if rospy.get_time() > self._deadline:
            return 'aborted'
        self._limb.set_joint_positions(self._goal)
        return None
{% do defined_headers.append('class_MoveToJointPositionsState') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
{%- set arguments = [] %}
{%- set keys = [] %}
{%- if limb is defined %}{% do arguments.append(text_argument('limb', limb)) %}{% else %}{% do keys.append('limb') %}{% endif %}
{%- if positions is defined %}{% do arguments.append(data_argument('positions', positions)) %}{% else %}{% do keys.append('positions') %}{% endif %}
{%- if speed is defined %}{% do arguments.append(data_argument('speed', speed | float)) %}{% endif %}
{%- if timeout is defined %}{% do arguments.append(data_argument('timeout', timeout | float)) %}{% endif %}
{{ render_baxter_add(defined_headers, default_module, state_class, name, arguments, keys, [], transitions, autonomy, remapping) }}
{% endblock body %}
