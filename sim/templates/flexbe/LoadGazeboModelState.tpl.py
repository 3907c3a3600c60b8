{% block meta %}
name: LoadGazeboModelState
description: >
  The paper's name of LoadModelState: loads a Gazebo model at a pose.
language: Python
framework: FlexBE
type: State
tags: [baxter]
includes: []
extends:
- LoadModelState
variables:
- model_name:
    description: The name of the model in Gazebo (table, block1, block2, ...).
    type: str
- - model_path:
      description: The model's SDF or URDF file (default from baxter_sim_examples).
      type: str
- - pose:
      description: >
        The model's pose in reference_frame, [[x, y, z], [qx, qy, qz, qw]]
        (default: input key pose).
      type: list
- - reference_frame:
      description: world or base (default input key reference_frame, else world).
      type: str
input_keys: []
output_keys: []
outcomes: [succeeded, aborted, preempted]
{% endblock meta %}
{% extends "LoadModelState.tpl.py" %}
