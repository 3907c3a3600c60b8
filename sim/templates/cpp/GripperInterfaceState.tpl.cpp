{% block meta %}
name: GripperInterfaceState
description: >
  Opens or closes a limb's electric gripper and waits until the fingers
  settle: robot::GripperInterfaceState. A variable left out is read from the
  input key of the same name (limb, command). Aborted when the fingers do not
  settle, or when a close expected to grasp closed on nothing.
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
- - command:
      description: open or close (default input key command).
      type: str
- - expect_grasp:
      description: Closing must grasp an object (default true).
      type: bool
- - timeout:
      description: Simulated seconds for the fingers to settle (default 2).
      type: float
input_keys: []
output_keys: []
outcomes: [succeeded, aborted, preempted]
{% endblock meta %}
{% extends "State.tpl.cpp" %}

{% block body %}
{%- set fields = [] %}
{%- if limb is defined %}{% do fields.append('.limb = ' + (limb | string | cppstr)) %}{% endif %}
{%- if command is defined %}{% do fields.append('.command = ' + (command | string | cppstr)) %}{% endif %}
{%- if expect_grasp is defined %}{% do fields.append('.expect_grasp = ' + ('true' if expect_grasp else 'false')) %}{% endif %}
{%- if timeout is defined %}{% do fields.append('.timeout = ' + (timeout | float | cppvalue)) %}{% endif %}
{%- if include_comments %}
// {{ name }} ({{ class_name }})
{%- endif %}
{{ render_add_state(parent_sm_name, parent_type, name, 'smachac::robot::GripperInterfaceState', '*baxter_robot, smachac::robot::GripperInterfaceArgs{' + fields | join(', ') + '}', transitions, remapping) }}
{% endblock body %}
