{% block meta %}
name: PoseToJointTrajServiceState
description: >
  Inverse kinematics, as Baxter's IK service: writes to the output key joints
  the joint positions that put a limb's endpoint at a pose (in the base frame)
  plus an optional offset: robot::PoseToJointTrajServiceState. A variable left
  out is read from the input key of the same name (limb, poses, offsets when
  set). Aborted when the pose is out of reach.
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
- - poses:
      description: The endpoint pose, [[x, y, z], [qx, qy, qz, qw]] (default input key poses).
      type: list
- - offsets:
      description: An offset added to the pose (default input key offsets, when set).
      type: list
input_keys: []
output_keys: [joints]
outcomes: [succeeded, aborted, preempted]
{% endblock meta %}
{% extends "State.tpl.cpp" %}

{% block body %}
{%- set fields = [] %}
{%- if limb is defined %}{% do fields.append('.limb = ' + (limb | string | cppstr)) %}{% endif %}
{%- if poses is defined %}{% do fields.append('.poses = ' + (poses | cppvalue)) %}{% endif %}
{%- if offsets is defined %}{% do fields.append('.offsets = ' + (offsets | cppvalue)) %}{% endif %}
{%- if include_comments %}
// {{ name }} ({{ class_name }})
{%- endif %}
{{ render_add_state(parent_sm_name, parent_type, name, 'smachac::robot::PoseToJointTrajServiceState', '*baxter_robot, smachac::robot::PoseToJointTrajServiceArgs{' + fields | join(', ') + '}', transitions, remapping) }}
{% endblock body %}
