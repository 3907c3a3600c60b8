{% block meta %}
name: EditGripperState
description: >
  Opens or closes the gripper (a template of the editor's tests). It takes a width, e.g. 0.1.
language: Python
framework: SMACH
type: State
variables:
- width:
    description: How wide to open, in metres.
    type: float
- - speed:
      description: How fast to move.
      type: float
- - force:
      description: The grip force.
      type: float
  - force_cb:
      description: A callback that computes the grip force.
      type: [function, str]
outcomes:
- opened
- failed
{% endblock meta %}
{% extends "State.tpl.py" %}
