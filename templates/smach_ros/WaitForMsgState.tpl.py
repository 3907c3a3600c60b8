{% block meta %}
name: WaitForMsgState
description: >
  A SMACH state that waits for a message on a ROS topic. With a message
  callback (msg_cb, called as msg_cb(msg, userdata)) the callback may decide
  the outcome by returning True (succeeded) or False (aborted). Also the helper
  class of ReadTopicState.
language: Python
framework: SMACH
type: State
tags: [core, ros]
includes: []
extends:
- State
variables:
- topic:
    description: The topic to listen to.
    type: str
- msg_type:
    description: The message class (a Python expression, e.g. std_msgs.msg.String).
    type: str
- - msg_cb:
      description: A function name or a backtick-wrapped lambda called with the message.
      type: str
- - latch:
      description: Keep the last message, so that later waits return it at once.
      type: bool
- - timeout:
      description: How long to wait, in seconds (default forever).
      type: float
      units: s
- - output_keys:
      description: The userdata keys the message callback writes.
      type: list of str
- - import_modules:
      description: Modules that this state's code uses, each written `import <module>`.
      type: list of str
- - from_imports:
      description: >
        Names that this state's code uses (service, action or message types,
        goal classes, callbacks), by module, each written `from <module> import
        <name>` (e.g. {std_srvs.srv: [Trigger]}).
      type: dict of list of str
input_keys: []
output_keys: []
outcomes:
- succeeded
- aborted
- preempted
{% endblock meta %}
{% from "Utils.tpl.py" import import_module, render_value %}
{% from "ScriptImports.tpl.py" import render_script_imports %}
{% extends "State.tpl.py" %}

{% block imports %}
{{ super() }}
{{ import_module(defined_headers, 'rospy') }}
{{ import_module(defined_headers, 'threading') }}
{{ render_script_imports(defined_headers, import_modules if import_modules is defined else [], from_imports if from_imports is defined else {}) }}
{% endblock imports %}

{% block class_defs %}
{{ super() }}
{% if 'class_WaitForMsgState' not in defined_headers %}
class WaitForMsgState(smach.State):
    """Waits for a message on a topic; an optional callback may decide the outcome."""

    def __init__(self, topic, msg_type, msg_cb=None, output_keys=[], latch=False, timeout=None):
        smach.State.__init__(self, outcomes=['succeeded', 'aborted', 'preempted'],
                             output_keys=output_keys)
        self._msg_cb = msg_cb
        self._latch = latch
        self._timeout = timeout
        self._lock = threading.Lock()
        self._msg = None
        self._subscriber = rospy.Subscriber(topic, msg_type, self._receive, queue_size=1)

    def __enter__(self):
        return self

    def __exit__(self, *error):
        self._subscriber.unregister()

    def _receive(self, msg):
        with self._lock:
            self._msg = msg

    def waitForMsg(self):
        """The next message; None on timeout or when ROS shuts down; 'preempted'."""
        deadline = None
        if self._timeout is not None:
            deadline = rospy.Time.now() + rospy.Duration.from_sec(self._timeout)
        while not rospy.is_shutdown() and (deadline is None or rospy.Time.now() < deadline):
            with self._lock:
                msg = self._msg
                if msg is not None and not self._latch:
                    self._msg = None
            if msg is not None:
                return msg
            if self.preempt_requested():
                self.service_preempt()
                return 'preempted'
            try:
                rospy.sleep(0.05)
            except rospy.ROSInterruptException:
                break
        return None

    def execute(self, userdata):
        msg = self.waitForMsg()
        if msg is None:
            return 'aborted'
        if isinstance(msg, str) and msg == 'preempted':
            return 'preempted'
        if self._msg_cb is not None:
            decision = self._msg_cb(msg, userdata)
            if decision is not None:
                return 'succeeded' if decision else 'aborted'
        return 'succeeded'
{% do defined_headers.append('class_WaitForMsgState') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
{% set arguments = [topic | pyrepr, msg_type] %}
{% if msg_cb is defined %}{% do arguments.append('msg_cb = ' + (msg_cb | exptostr if msg_cb is string and msg_cb is expression else msg_cb | string)) %}{% endif %}
{% if output_keys is defined %}{% do arguments.append(render_output_keys(output_keys, indent=0)) %}{% endif %}
{% if latch is defined %}{% do arguments.append('latch = ' + render_value(latch) | string) %}{% endif %}
{% if timeout is defined %}{% do arguments.append('timeout = ' + render_value(timeout) | string) %}{% endif %}
smach.{{ parent_type }}.add({{ name | pyrepr }},
                       WaitForMsgState({{ arguments | join(', ') }})
{%- if transitions is defined and parent_type != 'Concurrence' %},
{{ render_transitions(transitions) }}
{%- endif %}
{%- if remapping is defined %},
{{ render_remapping(remapping) }}
{%- endif %})
{% endblock body %}
