{% block meta %}
name: LoadGazeboModelState
description: >
  The paper's name of LoadModelState (robot::LoadGazeboModelState is an alias
  of robot::LoadModelState): puts a model of the scene at a pose.
language: C++
framework: smachac runtime
type: State
tags: [baxter, sim]
includes: []
extends:
- LoadModelState
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
{% extends "LoadModelState.tpl.cpp" %}
