{% block meta %}
name: ReadTopicState
description: >
  A SMACH state that reads one message from the topic named by the `topic`
  input key and stores it in the `output` key (or in msg, output_msg or
  msg_output when those are the output keys). The message type comes from the
  `msg_type` input key when given, otherwise from the topic itself. It gives
  up (aborted) after `timeout` seconds, when preempted or when ROS shuts down,
  also while the topic has another type than msg_type.
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
- - timeout:
      description: How long to wait for a message, in seconds (default forever).
      type: float
      units: s
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
{% from "Utils.tpl.py" import import_module, render_init_callbacks, render_execute_callbacks, render_value %}
{% extends "WaitForMsgState.tpl.py" %}

{% block imports %}
{{ super() }}
{{ import_module(defined_headers, 'roslib.message') }}
{% endblock imports %}

{% block class_defs %}
{{ super() }}
{% if 'class_ReadTopicState' not in defined_headers %}
class ReadTopicState(smach.State):
    """Reads one message from the topic named by the `topic` input key; aborts after
    `timeout` seconds (None: no limit), when preempted or when ROS shuts down."""

    def __init__(self, input_keys=['topic'], output_keys=['output'], callbacks=[],
                 outcomes=['succeeded', 'aborted'], timeout=None):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded', 'aborted'])
        self._timeout = timeout
        self._reader = None
        self._reader_lock = threading.Lock()
        {{ render_init_callbacks() }}

    def request_preempt(self):
        smach.State.request_preempt(self)
        with self._reader_lock:
            if self._reader is not None:
                self._reader.request_preempt()

    def _wait(self, topic, msg_class, deadline):
        """The first message of msg_class on topic, or None (time out, preempted, shutdown)."""
        timeout = None
        if deadline is not None:
            timeout = max(0.0, (deadline - rospy.Time.now()).to_sec())
        with WaitForMsgState(topic, msg_class, latch=True, timeout=timeout) as reader:
            with self._reader_lock:
                self._reader = reader
            try:
                msg = None if self.preempt_requested() else reader.waitForMsg()
            finally:
                with self._reader_lock:
                    self._reader = None
        return msg if msg is not None and not isinstance(msg, str) else None

    def _message_class(self, userdata, topic, deadline):
        if 'msg_type' in self._input_keys:
            return roslib.message.get_message_class(userdata.msg_type)
        any_msg = self._wait(topic, rospy.AnyMsg, deadline)
        if any_msg is None:
            return None
        return roslib.message.get_message_class(any_msg._connection_header['type'])

    def execute(self, userdata):
        {{ render_execute_callbacks() }}
        deadline = None
        if self._timeout is not None:
            deadline = rospy.Time.now() + rospy.Duration.from_sec(self._timeout)
        try:
            topic = userdata.topic
            msg_class = self._message_class(userdata, topic, deadline)
            msg = self._wait(topic, msg_class, deadline) if msg_class is not None else None
        except Exception as e:
            rospy.logerr('Cannot read topic: {}'.format(e))
            return 'aborted'
        if self.preempt_requested():
            self.service_preempt()
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
                       ReadTopicState({{ render_state_arguments(name, uuid, input_keys, output_keys, callbacks, outcomes) }}
{%- if timeout is defined %}{% if input_keys is defined or output_keys is defined or callbacks is defined or outcomes is defined %}, {% endif %}timeout={{ render_value(timeout) }}{% endif %})
{%- if transitions is defined and parent_type != 'Concurrence' %},
{{ render_transitions(transitions) }}
{%- endif %}
{%- if remapping is defined %},
{{ render_remapping(remapping) }}
{%- endif %})
{% endblock body %}
