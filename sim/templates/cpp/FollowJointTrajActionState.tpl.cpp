{% block meta %}
name: FollowJointTrajActionState
description: >
  Moves a limb through a list of joint waypoints in order, as the
  follow-joint-trajectory action server does:
  robot::FollowJointTrajActionState. A variable left out is read from the
  input key of the same name (limb, points).
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
- - points:
      description: A list of joint positions (default input key points).
      type: list
- - speed:
      description: Fraction of the joint velocity limits, per waypoint (default 0.3).
      type: float
- - timeout:
      description: Simulated seconds per waypoint (default 15).
      type: float
input_keys: []
output_keys: []
outcomes: [succeeded, aborted, preempted]
{% endblock meta %}
{% extends "State.tpl.cpp" %}

{% block body %}
{%- set fields = [] %}
{%- if limb is defined %}{% do fields.append('.limb = ' + (limb | string | cppstr)) %}{% endif %}
{%- if points is defined %}{% do fields.append('.points = ' + (points | cppvalue)) %}{% endif %}
{%- if speed is defined %}{% do fields.append('.speed = ' + (speed | float | cppvalue)) %}{% endif %}
{%- if timeout is defined %}{% do fields.append('.timeout = ' + (timeout | float | cppvalue)) %}{% endif %}
{%- if include_comments %}
// {{ name }} ({{ class_name }})
{%- endif %}
{{ render_add_state(parent_sm_name, parent_type, name, 'smachac::robot::FollowJointTrajActionState', '*baxter_robot, smachac::robot::FollowJointTrajActionArgs{' + fields | join(', ') + '}', transitions, remapping) }}
{% endblock body %}
