{% block meta %}
name: ReadEndpointPoseState
description: >
  Reads a limb's endpoint pose in Baxter's base frame with
  baxter_interface.Limb's endpoint_pose into the output key pose,
  [[x, y, z], [qx, qy, qz, qw]]. The limb is read from the input key limb
  when the variable is left out.
language: Python
framework: FlexBE
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
{% extends "State.tpl.py" %}
{% from "BaxterUtils.tpl.py" import define_baxter_module, text_argument, render_baxter_add %}
{% set state_module = '' %}
{% set state_class = 'ReadEndpointPoseState' %}

{% block class_defs %}
{{ define_baxter_module(defined_headers) }}


{% if 'class_ReadEndpointPoseState' not in defined_headers %}
class ReadEndpointPoseState(BaxterEventState):
    """
    Reads a limb's endpoint pose in the base frame.

    -- limb         string  left or right (None: the input key limb).
    -- input_keys   list    The arguments read from the userdata.

    ># limb         string  The limb, when limb is an input key.
    #> pose         list    The endpoint pose, [[x, y, z], [qx, qy, qz, qw]].

    <= succeeded            The pose was read.
    <= aborted              The limb could not be read.
    <= preempted            The behavior was preempted.
    """

    def __init__(self, limb=None, input_keys=[]):
        BaxterEventState.__init__(self, dict(limb=limb), input_keys, output_keys=['pose'])

    def start(self, userdata, limb):
        endpoint = baxter_interface.Limb(limb).endpoint_pose()
        position, orientation = endpoint['position'], endpoint['orientation']
        userdata.pose = [[position.x, position.y, position.z],
                         [orientation.x, orientation.y, orientation.z, orientation.w]]
        return 'succeeded'
{% do defined_headers.append('class_ReadEndpointPoseState') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
{%- set arguments = [] %}
{%- set keys = [] %}
{%- if limb is defined %}{% do arguments.append(text_argument('limb', limb)) %}{% else %}{% do keys.append('limb') %}{% endif %}
{{ render_baxter_add(defined_headers, default_module, state_class, name, arguments, keys, ['pose'], transitions, autonomy, remapping) }}
{% endblock body %}
