{% block meta %}
name: ReadEndpointPoseState
description: >
  Reads a limb's endpoint pose in Baxter's base frame into the output key
  pose, [[x, y, z], [qx, qy, qz, qw]]: robot::ReadEndpointPoseState. The limb
  is read from the input key limb when the variable is left out.
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
input_keys: []
output_keys: [pose]
outcomes: [succeeded, aborted, preempted]
{% endblock meta %}
{% extends "State.tpl.cpp" %}

{% block body %}
{%- set fields = [] %}
{%- if limb is defined %}{% do fields.append('.limb = ' + (limb | string | cppstr)) %}{% endif %}
{%- if include_comments %}
// {{ name }} ({{ class_name }})
{%- endif %}
{{ render_add_state(parent_sm_name, parent_type, name, 'smachac::robot::ReadEndpointPoseState', '*baxter_robot, smachac::robot::ReadEndpointPoseArgs{' + fields | join(', ') + '}', transitions, remapping) }}
{% endblock body %}
