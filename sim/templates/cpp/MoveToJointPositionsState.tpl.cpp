{% block meta %}
name: MoveToJointPositionsState
description: >
  Moves a limb to joint positions (a smooth joint-space move, then within
  tolerance of the goal): robot::MoveToJointPositionsState. A variable left
  out is read from the input key of the same name (limb, positions).
language: C++
framework: smachac runtime
type: State
tags: [baxter, sim]
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
      description: Simulated seconds for the move (default 15).
      type: float
input_keys: []
output_keys: []
outcomes: [succeeded, aborted, preempted]
{% endblock meta %}
{% extends "State.tpl.cpp" %}

{% block body %}
{%- set fields = [] %}
{%- if limb is defined %}{% do fields.append('.limb = ' + (limb | string | cppstr)) %}{% endif %}
{%- if positions is defined %}{% do fields.append('.positions = ' + (positions | cppvalue)) %}{% endif %}
{%- if speed is defined %}{% do fields.append('.speed = ' + (speed | float | cppvalue)) %}{% endif %}
{%- if timeout is defined %}{% do fields.append('.timeout = ' + (timeout | float | cppvalue)) %}{% endif %}
{%- if include_comments %}
// {{ name }} ({{ class_name }})
{%- endif %}
{{ render_add_state(parent_sm_name, parent_type, name, 'smachac::robot::MoveToJointPositionsState', '*baxter_robot, smachac::robot::MoveToJointPositionsArgs{' + fields | join(', ') + '}', transitions, remapping) }}
{% endblock body %}
