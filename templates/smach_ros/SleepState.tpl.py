{% block meta %}
name: SleepState
description: >
  A SMACH state that pauses the state machine for a number of seconds (rospy time).
  Declared with `outcomes: [succeeded, preempted]`, it wakes on a preempt request and
  returns `preempted` (SMACH lets a state return only the outcomes it declares).
  In a program without a ROS node (template Base) it sleeps in wall time.
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
{% from "Utils.tpl.py" import import_module, render_outcomes %}
{% extends "State.tpl.py" %}

{% block imports %}
{{ super() }}
{{ import_module(defined_headers, 'rospy') }}
{% endblock imports %}

{% block class_defs %}
{{ super() }}
{% if 'class_SleepState' not in defined_headers %}
class SleepState(smach.State):
    """Sleeps for a fixed time, then succeeds; with `preempted` among its outcomes it wakes
    on a preempt request and returns `preempted`."""

    def __init__(self, time, input_keys=[], output_keys=[], callbacks=[], outcomes=['succeeded']):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=outcomes)
        self._time = time

    def execute(self, userdata):
        if not rospy.rostime.is_rostime_initialized():
            rospy.rostime.set_rostime_initialized(True)  # no ROS node: rospy's time is wall time
        if 'preempted' not in self.get_registered_outcomes():
            rospy.sleep(self._time)
            return 'succeeded'
        end = rospy.get_rostime() + rospy.Duration(self._time)
        while rospy.get_rostime() < end:
            if self.preempt_requested():
                self.service_preempt()
                return 'preempted'
            rospy.sleep(min(0.01, (end - rospy.get_rostime()).to_sec()))
        return 'succeeded'
{% do defined_headers.append('class_SleepState') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
smach.{{ parent_type }}.add({{ name | pyrepr }},
                       SleepState({{ time }}
{%- if 'preempted' in outcomes %}, {{ render_outcomes(outcomes) }}{% endif %})
{%- if transitions is defined and parent_type != 'Concurrence' %},
{{ render_transitions(transitions) }}
{%- endif %}
{%- if remapping is defined %},
{{ render_remapping(remapping) }}
{%- endif %})
{% endblock body %}
