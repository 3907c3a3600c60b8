{% block meta %}
name: LoadModelState
description: >
  Puts a model of the scene (table, block1, block2) at a pose, as Gazebo's
  spawn service does for the paper's scripts: smachac::robot::LoadModelState. A
  variable left out is read from the input key of the same name (pose;
  reference_frame, default world).
language: C++
framework: smachac runtime
type: State
tags: [baxter, sim]
includes: []
extends:
- State
variables:
- model_name:
    description: The scene body to load (table, block1 or block2).
    type: str
- - model_path:
      description: The model file (accepted for Gazebo scripts, unused).
      type: str
- - pose:
      description: >
        The body's pose in reference_frame, [[x, y, z], [qx, qy, qz, qw]]
        (default: input key pose).
      type: list
- - reference_frame:
      description: world or base (default input key reference_frame, else world).
      type: str
input_keys: []
output_keys: []
outcomes: [succeeded, aborted, preempted]
{% endblock meta %}
{% extends "State.tpl.cpp" %}

{% block body %}
{%- set fields = [] %}
{%- if model_name is defined %}{% do fields.append('.model_name = ' + (model_name | string | cppstr)) %}{% endif %}
{%- if model_path is defined %}{% do fields.append('.model_path = ' + (model_path | string | cppstr)) %}{% endif %}
{%- if pose is defined %}{% do fields.append('.pose = ' + (pose | cppvalue)) %}{% endif %}
{%- if reference_frame is defined %}{% do fields.append('.reference_frame = ' + (reference_frame | string | cppstr)) %}{% endif %}
{%- if include_comments %}
// {{ name }} ({{ class_name }})
{%- endif %}
{{ render_add_state(parent_sm_name, parent_type, name, 'smachac::robot::LoadModelState', '*baxter_robot, smachac::robot::LoadModelArgs{' + fields | join(', ') + '}', transitions, remapping) }}
{% endblock body %}
