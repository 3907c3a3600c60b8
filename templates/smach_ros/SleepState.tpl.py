{% block meta %}
name: SleepState
description: A SMACH state that pauses the state machine for a number of seconds (rospy time).
language: Python
framework: SMACH
type: State
tags: [core, ros]
includes: []
extends:
- State
variables:
- time:
    description: How long to sleep, in seconds.
    type: float
    units: s
input_keys: []
output_keys: []
outcomes:
- succeeded
{% endblock meta %}
{% from "Utils.tpl.py" import import_module %}
{% extends "State.tpl.py" %}

{% block imports %}
{{ super() }}
{{ import_module(defined_headers, 'rospy') }}
{% endblock imports %}

{% block class_defs %}
{{ super() }}
{% if 'class_SleepState' not in defined_headers %}
class SleepState(smach.State):
    """Sleeps for a fixed time, then succeeds."""

    def __init__(self, time, input_keys=[], output_keys=[], callbacks=[], outcomes=['succeeded']):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=outcomes)
        self._time = time

    def execute(self, userdata):
        rospy.sleep(self._time)
        return 'succeeded'
{% do defined_headers.append('class_SleepState') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
smach.{{ parent_type }}.add({{ name | pyrepr }},
                       SleepState({{ time }})
{%- if transitions is defined and parent_type != 'Concurrence' %},
{{ render_transitions(transitions) }}
{%- endif %}
{%- if remapping is defined %},
{{ render_remapping(remapping) }}
{%- endif %})
{% endblock body %}
