{% block meta %}
name: ReadEndpointPoseState
description: >
  Reads a limb's endpoint pose in Baxter's base frame with
  baxter_interface.Limb's endpoint_pose into the output key pose,
  [[x, y, z], [qx, qy, qz, qw]]. The limb is read from the input key limb
  when the variable is left out.
language: Python
framework: SMACH
type: State
tags: [baxter]
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
{% from "Utils.tpl.py" import import_module %}
{% from "BaxterUtils.tpl.py" import join_definitions, join_imports, import_baxter_state, define_baxter_state, text_argument, render_baxter_state %}
{% extends "State.tpl.py" %}

{% block imports %}
{{- join_imports([import_baxter_state(defined_headers),
                 import_module(defined_headers, 'baxter_interface')]) }}
{%- endblock imports %}

{% block class_defs %}
{%- set definitions = [define_baxter_state(defined_headers)] %}
{%- if 'class_ReadEndpointPoseState' not in defined_headers %}
{%- set definition %}
class ReadEndpointPoseState(BaxterState):
    """Writes a limb's endpoint pose, [[x, y, z], [qx, qy, qz, qw]], to pose."""

    def __init__(self, limb=None, input_keys=()):
        BaxterState.__init__(self, dict(limb=limb), input_keys, output_keys=['pose'])

    def run(self, userdata, limb):
        endpoint = baxter_interface.Limb(limb).endpoint_pose()
        position, orientation = endpoint['position'], endpoint['orientation']
        userdata.pose = [[position.x, position.y, position.z],
                         [orientation.x, orientation.y, orientation.z, orientation.w]]
        return 'succeeded'
{%- endset %}
{%- do definitions.append(definition) %}
{%- do defined_headers.append('class_ReadEndpointPoseState') %}
{%- endif %}
{{ join_definitions(definitions) }}
{%- endblock class_defs %}

{% block body %}
{%- set arguments = [] %}
{%- set keys = [] %}
{%- if limb is defined %}{% do arguments.append(text_argument('limb', limb)) %}{% else %}{% do keys.append('limb') %}{% endif %}
{%- if include_comments %}
# {{ name | pycomment }} ({{ class_name }})
{%- endif %}
{{ render_baxter_state(parent_type, name, 'ReadEndpointPoseState', arguments, keys, transitions, remapping) }}
{% endblock body %}
