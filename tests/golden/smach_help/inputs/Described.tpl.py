{% block meta %}
name: Described
description: A test template whose meta block uses every form help knows.
language: Python
framework: SMACH
type: State
tags: [test]
includes: [Helper]
extends: State
variables:
- speed:
    description: How fast to move.
    type: float
    units: m/s
- mode:
    description: How to move.
    type: str
    values: [linear, joint]
- - tolerance:
      description: The accepted error.
      type: [float, list of float]
- Gripper settings:
  - width: {description: The opening., type: float, units: m}
  - - force: {description: The grip force., type: float, units: N}
- - goal: {description: A fixed goal., type: str}
  - goal_cb: {description: A goal callback., type: str}
input_keys:
- pose: {description: Where to go., type: geometry_msgs/Pose}
output_keys: []
outcomes:
- succeeded
- aborted: {description: The motion failed.}
{% endblock meta %}
{% extends "State.tpl.py" %}
