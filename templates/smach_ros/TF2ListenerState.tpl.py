{% block meta %}
name: TF2ListenerState
description: >
  A SMACH state that looks up the latest transform from the `source` frame to
  the `target` frame on TF2 and stores it in the `output` key.
language: Python
framework: SMACH
type: State
tags: [core, ros]
includes:
- TF2ListenerSingleton
extends:
- State
variables:
- - timeout:
      description: How long to wait for the transform, in seconds (default 1).
      type: float
      units: s
input_keys:
- target:
    description: The target frame.
    type: str
- source:
    description: The source frame.
    type: str
output_keys:
- output:
    description: The transform.
    type: geometry_msgs/TransformStamped
outcomes:
- succeeded
- aborted
{% endblock meta %}
{% from "Utils.tpl.py" import render_value %}
{% extends "State.tpl.py" %}
{% include "TF2ListenerSingleton.tpl.py" %}

{% block class_defs %}
{{ super() }}
{% if 'class_TF2ListenerState' not in defined_headers %}
class TF2ListenerState(smach.State):
    """Stores the transform from the `source` to the `target` frame in `output`."""

    def __init__(self, input_keys=['target', 'source'], output_keys=['output'], callbacks=[],
                 outcomes=['succeeded', 'aborted'], timeout=1.0):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded', 'aborted'])
        self._buffer, _ = TF2ListenerSingleton.get()
        self._timeout = rospy.Duration(timeout)

    def execute(self, userdata):
        try:
            userdata.output = self._buffer.lookup_transform(
                userdata.target, userdata.source, rospy.Time(0), self._timeout)
        except Exception as e:
            rospy.logerr('No transform from {} to {}: {}'.format(
                userdata.source, userdata.target, e))
            return 'aborted'
        return 'succeeded'
{% do defined_headers.append('class_TF2ListenerState') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
smach.{{ parent_type }}.add({{ name | pyrepr }},
                       TF2ListenerState({{ render_state_arguments(name, uuid, input_keys, output_keys, callbacks, outcomes) }}
{%- if timeout is defined %}{% if input_keys is defined or output_keys is defined or callbacks is defined or outcomes is defined %}, {% endif %}timeout={{ render_value(timeout) }}{% endif %})
{%- if transitions is defined and parent_type != 'Concurrence' %},
{{ render_transitions(transitions) }}
{%- endif %}
{%- if remapping is defined %},
{{ render_remapping(remapping) }}
{%- endif %})
{% endblock body %}
