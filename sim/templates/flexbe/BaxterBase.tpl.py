{% block meta %}
name: BaxterBase
description: >
  The base template of a Baxter FlexBE behavior: the core Base (behavior
  module, states module, manifest). The Baxter states are ROS 1 code (the
  Baxter SDK is ROS 1 only): compile with -flexbe-ros=1; with ROS 2 the
  render fails with an error that says so. A FlexBE behavior is
  started by the onboard engine, which owns the ROS node, so the robot is
  enabled by the first Baxter state that runs (BaxterEventState), not here.
  function_name is accepted for SMACH scripts and unused.
language: Python
framework: FlexBE
type: Base
tags: [baxter]
includes: []
extends:
- Base
variables:
- outcomes:
    description: The outcomes of the behavior.
    type: list of str
- - userdata:
      description: Userdata defaults of the behavior's state machine, by key.
      type: dict
- - function_name:
      description: Accepted for SMACH scripts, unused.
      type: str
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% extends "Base.tpl.py" %}
{#- The Baxter states are ROS 1 code: a ROS 2 behavior fails to render, naming the flag. #}
{%- block base_header %}
{%- if flexbe_ros != 1 %}{{ {}['the Baxter SDK is ROS 1 only: use -flexbe-ros=1'].stop }}{% endif %}
{{- super() }}
{%- endblock base_header %}
