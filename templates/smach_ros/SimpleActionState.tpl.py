{% block meta %}
name: SimpleActionState
description: >
  Sends a goal to a ROS action server through smach_ros.SimpleActionState. The
  goal is a fixed expression (goal), built from userdata slots (goal_slots) or
  by a callback (goal_cb); the result goes to userdata slots (result_slots) or
  to a callback (result_cb).
language: Python
framework: SMACH
type: State
tags: [core, ros]
includes: []
extends:
- State
variables:
- action_server_namespace:
    description: The action server's name, e.g. /robot/joint_motion.
    type: str
- action:
    description: The action type (a Python expression, e.g. TestAction).
    type: str
- - goal:
      description: The goal, a Python expression.
      type: str
  - goal_slots:
      description: Goal fields filled from the userdata keys of the same names.
      type: list of str
  - goal_cb:
      description: A function that builds the goal from the userdata.
      type: str
- - result_slots:
      description: Result fields stored in the userdata keys of the same names.
      type: list of str
  - result_cb:
      description: A function that handles the result.
      type: str
- - input_keys:
      description: The userdata keys the goal callback reads.
      type: list of str
- - output_keys:
      description: The userdata keys the result callback writes.
      type: list of str
input_keys: []
output_keys: []
outcomes:
- succeeded
- aborted
- preempted
{% endblock meta %}
{% from "Utils.tpl.py" import from_import, render_goal_slots, render_result_slots %}
{% extends "State.tpl.py" %}

{% block imports %}
{{ super() }}
{{ from_import(defined_headers, 'actionlib', '*') }}
{% endblock imports %}

{% block body %}
smach.{{ parent_type }}.add({{ name | pyrepr }},
                       smach_ros.SimpleActionState({{ action_server_namespace | pyrepr }}, {{ action }}
{%- if goal is defined %},
{{ ' ' * 51 }}goal = {{ goal }}
{%- elif goal_slots is defined %},
{{ render_goal_slots(goal_slots) }}
{%- elif goal_cb is defined %},
{{ ' ' * 51 }}goal_cb = {{ goal_cb }}
{%- if input_keys is defined %},
{{ render_input_keys(input_keys) }}
{%- endif %}
{%- endif %}
{%- if result_slots is defined %},
{{ render_result_slots(result_slots) }}
{%- elif result_cb is defined %},
{{ ' ' * 51 }}result_cb = {{ result_cb }}
{%- if output_keys is defined %},
{{ render_output_keys(output_keys) }}
{%- endif %}
{%- endif %})
{%- if transitions is defined and parent_type != 'Concurrence' %},
{{ render_transitions(transitions) }}
{%- endif %}
{%- if remapping is defined %},
{{ render_remapping(remapping) }}
{%- endif %})
{% endblock body %}
