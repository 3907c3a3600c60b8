{% block meta %}
name: GripperInterfaceState
description: >
  Opens or closes a limb's electric gripper with baxter_interface.Gripper
  (calibrating it first when needed) and waits for the fingers. A variable
  left out is read from the input key of the same name (limb, command).
  Aborted when a close expected to grasp closed on nothing.
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
- - command:
      description: open or close (default input key command).
      type: str
- - expect_grasp:
      description: Closing must grasp an object (default true).
      type: bool
- - timeout:
      description: Seconds for the fingers to settle (default 2).
      type: float
input_keys: []
output_keys: []
outcomes: [succeeded, aborted, preempted]
{% endblock meta %}
{% from "Utils.tpl.py" import import_module %}
{% from "BaxterUtils.tpl.py" import join_definitions, join_imports, import_baxter_state, define_baxter_state, text_argument, data_argument, render_baxter_state %}
{% extends "State.tpl.py" %}

{% block imports %}
{{- join_imports([import_baxter_state(defined_headers),
                 import_module(defined_headers, 'baxter_interface')]) }}
{%- endblock imports %}

{% block class_defs %}
{%- set definitions = [define_baxter_state(defined_headers)] %}
{%- if 'class_GripperInterfaceState' not in defined_headers %}
{%- set definition %}
class GripperInterfaceState(BaxterState):
    """Opens or closes a limb's gripper; aborted when an expected grasp closed on nothing."""

    def __init__(self, limb=None, command=None, expect_grasp=True, timeout=2.0, input_keys=()):
        BaxterState.__init__(self, dict(limb=limb, command=command, expect_grasp=expect_grasp,
                                        timeout=timeout), input_keys)

    def run(self, userdata, limb, command, expect_grasp, timeout):
        gripper = baxter_interface.Gripper(limb, baxter_interface.CHECK_VERSION)
        if not gripper.calibrated():
            gripper.calibrate()
        if command == 'open':
            gripper.open(block=True, timeout=timeout)
            return 'succeeded'
        if command == 'close':
            gripper.close(block=True, timeout=timeout)
            return 'aborted' if expect_grasp and not gripper.gripping() else 'succeeded'
        raise ValueError('a gripper command is open or close, not %r' % (command,))
{%- endset %}
{%- do definitions.append(definition) %}
{%- do defined_headers.append('class_GripperInterfaceState') %}
{%- endif %}
{{ join_definitions(definitions) }}
{%- endblock class_defs %}

{% block body %}
{%- set arguments = [] %}
{%- set keys = [] %}
{%- if limb is defined %}{% do arguments.append(text_argument('limb', limb)) %}{% else %}{% do keys.append('limb') %}{% endif %}
{%- if command is defined %}{% do arguments.append(text_argument('command', command)) %}{% else %}{% do keys.append('command') %}{% endif %}
{%- if expect_grasp is defined %}{% do arguments.append('expect_grasp=' ~ ('True' if expect_grasp else 'False')) %}{% endif %}
{%- if timeout is defined %}{% do arguments.append(data_argument('timeout', timeout | float)) %}{% endif %}
{%- if include_comments %}
# {{ name | pycomment }} ({{ class_name }})
{%- endif %}
{{ render_baxter_state(parent_type, name, 'GripperInterfaceState', arguments, keys, transitions, remapping) }}
{% endblock body %}
