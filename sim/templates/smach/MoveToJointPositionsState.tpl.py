{% block meta %}
name: MoveToJointPositionsState
description: >
  Moves a limb to joint positions with baxter_interface.Limb's
  move_to_joint_positions, at a fraction of the joint velocity limits;
  aborted when the limb is not within tolerance of the goal by the timeout. A
  variable left out is read from the input key of the same name (limb,
  positions).
language: Python
framework: SMACH
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
{% from "Utils.tpl.py" import import_module %}
{% from "BaxterUtils.tpl.py" import join_definitions, join_imports, import_baxter_state, define_baxter_state, define_joint_function, text_argument, data_argument, render_baxter_state %}
{% extends "State.tpl.py" %}

{% block imports %}
{{- join_imports([import_baxter_state(defined_headers),
                 import_module(defined_headers, 'baxter_interface')]) }}
{%- endblock imports %}

{% block class_defs %}
{%- set definitions = [define_baxter_state(defined_headers), define_joint_function(defined_headers)] %}
{%- if 'class_MoveToJointPositionsState' not in defined_headers %}
{%- set definition %}
class MoveToJointPositionsState(BaxterState):
    """Moves a limb to joint positions; aborted when it does not reach them in time."""

    TOLERANCE = 0.008726646  # rad per joint, the Baxter SDK's default threshold

    def __init__(self, limb=None, positions=None, speed=0.3, timeout=15.0, input_keys=()):
        BaxterState.__init__(self, dict(limb=limb, positions=positions, speed=speed,
                                        timeout=timeout), input_keys)

    def run(self, userdata, limb, positions, speed, timeout):
        limb_interface = baxter_interface.Limb(limb)
        goal = baxter_joint_positions(limb_interface, positions)
        limb_interface.set_joint_position_speed(speed)
        limb_interface.move_to_joint_positions(goal, timeout=timeout,
                                               threshold=self.TOLERANCE,
                                               test=self.preempt_requested)
        if self.preempt_requested():
            self.service_preempt()
            return 'preempted'
        angles = limb_interface.joint_angles()
        reached = all(abs(angles[joint] - angle) <= self.TOLERANCE
                      for joint, angle in goal.items())
        return 'succeeded' if reached else 'aborted'
{%- endset %}
{%- do definitions.append(definition) %}
{%- do defined_headers.append('class_MoveToJointPositionsState') %}
{%- endif %}
{{ join_definitions(definitions) }}
{%- endblock class_defs %}

{% block body %}
{%- set arguments = [] %}
{%- set keys = [] %}
{%- if limb is defined %}{% do arguments.append(text_argument('limb', limb)) %}{% else %}{% do keys.append('limb') %}{% endif %}
{%- if positions is defined %}{% do arguments.append(data_argument('positions', positions)) %}{% else %}{% do keys.append('positions') %}{% endif %}
{%- if speed is defined %}{% do arguments.append(data_argument('speed', speed | float)) %}{% endif %}
{%- if timeout is defined %}{% do arguments.append(data_argument('timeout', timeout | float)) %}{% endif %}
{%- if include_comments %}
# {{ name | pycomment }} ({{ class_name }})
{%- endif %}
{{ render_baxter_state(parent_type, name, 'MoveToJointPositionsState', arguments, keys, transitions, remapping) }}
{% endblock body %}
