{% block meta %}
name: SleepState
description: >
  Waits `time` seconds (ROS time), then returns `succeeded`: the sleep state of
  the other targets under the same name, outcome and variable. FlexBE's own
  library state for this is WaitState (outcome `done`). FlexBE preempts it as
  any state, whatever its outcomes.
language: Python
framework: FlexBE
type: SleepState
tags: [core]
includes: []
extends: []
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
{% extends "State.tpl.py" %}
{% from "Utils.tpl.py" import render_value %}
{% set state_module = '' %}
{% set state_class = '' %}

{% set state_args = 'time=' ~ render_value(time) %}

{% block class_defs %}
{% if 'class_SleepState' not in defined_headers %}
import rospy


class SleepState(EventState):
    """
    Waits for a number of seconds (ROS time).

    -- time     float   The time to wait, in seconds.

    <= succeeded        The time has passed.
    """

    def __init__(self, time):
        super(SleepState, self).__init__(outcomes=['succeeded'])
        self._time = rospy.Duration(time)
        self._end = None

    def on_enter(self, userdata):
        self._end = rospy.get_rostime() + self._time

    def execute(self, userdata):
        if rospy.get_rostime() >= self._end:
            return 'succeeded'
{% do defined_headers.append('class_SleepState') %}
{% endif %}
{% endblock class_defs %}
