{% block meta %}
name: ReadTopicState
description: >
  A SMACH state that reads one message from the topic named by the `topic`
  input key and stores it in the `output` key (or in msg, output_msg or
  msg_output when those are the output keys). The message type comes from the
  `msg_type` input key when given, otherwise from the topic itself.
language: Python
framework: SMACH
type: State
tags: [core, ros]
includes: []
extends:
- WaitForMsgState
variables:
- input_keys:
    description: The userdata keys the state reads (topic, optionally msg_type).
    type: list of str
- - output_keys:
      description: The userdata keys the state writes (output by default).
      type: list of str
- - callbacks:
      description: Callbacks by output key, run before the topic is read.
      type: dict of str
input_keys:
- topic:
    description: The topic to read.
    type: str
- - msg_type:
      description: The message type, e.g. std_msgs/String.
      type: str
output_keys:
- - output:
      description: The message read.
      type: genpy.Message
outcomes:
- succeeded
- aborted
{% endblock meta %}
{% from "Utils.tpl.py" import import_module, render_init_callbacks, render_execute_callbacks %}
{% extends "WaitForMsgState.tpl.py" %}

{% block imports %}
{{ super() }}
{{ import_module(defined_headers, 'roslib.message') }}
{% endblock imports %}

{% block class_defs %}
{{ super() }}
{% if 'class_ReadTopicState' not in defined_headers %}
class ReadTopicState(smach.State):
    """Reads one message from the topic named by the `topic` input key."""

    def __init__(self, input_keys=['topic'], output_keys=['output'], callbacks=[],
                 outcomes=['succeeded', 'aborted']):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded', 'aborted'])
        {{ render_init_callbacks() }}

    def _message_class(self, userdata, topic):
        if 'msg_type' in self._input_keys:
            return roslib.message.get_message_class(userdata.msg_type)
        with WaitForMsgState(topic, rospy.AnyMsg, latch=True) as probe:
            any_msg = probe.waitForMsg()
        return roslib.message.get_message_class(any_msg._connection_header['type'])

    def execute(self, userdata):
        {{ render_execute_callbacks() }}
        try:
            topic = userdata.topic
            msg_class = self._message_class(userdata, topic)
            with WaitForMsgState(topic, msg_class, latch=True) as reader:
                msg = reader.waitForMsg()
        except Exception as e:
            rospy.logerr('Cannot read topic: {}'.format(e))
            return 'aborted'
        if msg is None:
            return 'aborted'
        for key in ['output', 'msg', 'output_msg', 'msg_output']:
            if key in self._output_keys:
                setattr(userdata, key, msg)
        return 'succeeded'
{% do defined_headers.append('class_ReadTopicState') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
smach.{{ parent_type }}.add({{ name | pyrepr }},
                       ReadTopicState({{ render_state_arguments(name, uuid, input_keys, output_keys, callbacks, outcomes) }})
{%- if transitions is defined and parent_type != 'Concurrence' %},
{{ render_transitions(transitions) }}
{%- endif %}
{%- if remapping is defined %},
{{ render_remapping(remapping) }}
{%- endif %})
{% endblock body %}
