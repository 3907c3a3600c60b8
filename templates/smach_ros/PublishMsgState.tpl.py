{% block meta %}
name: PublishMsgState
description: >
  A SMACH state that starts or stops publishing a ROS message. With action
  `start` it publishes the `msg` input key on the `topic` input key (default
  smacha/<state name>) at the `rate` input key (default 100 Hz) until a later
  state stops it (`stop`) or stops every topic (`stop_all`). A list message
  [x, y, z] becomes a geometry_msgs/PointStamped, [[x, y, z], [x, y, z, w]] a
  geometry_msgs/PoseStamped.
language: Python
framework: SMACH
type: State
tags: [core, ros]
includes:
- MsgPublisher
extends:
- State
variables:
- action:
    description: start, stop or stop_all.
    type: str
- - input_keys:
      description: The userdata keys the state reads (msg, topic, rate, frame_id).
      type: list of str
- - output_keys:
      description: The userdata keys the state writes (msg, topic).
      type: list of str
- - callbacks:
      description: Callbacks by output key, e.g. to build the message.
      type: dict of str
- - import_modules:
      description: Modules that this state's code uses, each written `import <module>`.
      type: list of str
- - from_imports:
      description: >
        Names that this state's code uses (service, action or message types,
        goal classes, callbacks), by module, each written `from <module> import
        <name>` (e.g. {std_srvs.srv: [Trigger]}).
      type: dict of list of str
input_keys:
- msg:
    description: The message, or a list for a point or a pose.
    type: [genpy.Message, list]
- topic:
    description: The topic to publish on.
    type: str
- - rate:
      description: The publishing rate.
      type: float
      units: Hz
- - frame_id:
      description: The frame of the message header.
      type: str
output_keys:
- - msg:
      description: The message as published.
      type: genpy.Message
- - topic:
      description: The topic published on.
      type: str
outcomes:
- succeeded
- aborted
{% endblock meta %}
{% from "Utils.tpl.py" import import_module, render_init_callbacks, render_execute_callbacks %}
{% from "ScriptImports.tpl.py" import render_script_imports %}
{% extends "State.tpl.py" %}
{% include "MsgPublisher.tpl.py" %}

{% block imports %}
{{ super() }}
{{ import_module(defined_headers, 'geometry_msgs.msg') }}
{{ render_script_imports(defined_headers, import_modules if import_modules is defined else [], from_imports if from_imports is defined else {}) }}
{% endblock imports %}

{% block class_defs %}
{{ super() }}
{% if 'class_PublishMsgState' not in defined_headers %}
class PublishMsgState(smach.State):
    """Starts or stops publishing a message through the script's MsgPublisher."""

    def __init__(self, name, msg_publisher, action, input_keys=['msg', 'topic', 'rate'],
                 output_keys=['msg', 'topic'], callbacks=[]):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded', 'aborted'])
        self._name = name
        self._publisher = msg_publisher
        self._action = action
        {{ render_init_callbacks() }}

    @staticmethod
    def _message(msg):
        if isinstance(msg, (list, tuple)) and len(msg) == 3:
            point = geometry_msgs.msg.PointStamped()
            point.point.x, point.point.y, point.point.z = msg
            return point
        if isinstance(msg, (list, tuple)) and len(msg) == 2:
            pose = geometry_msgs.msg.PoseStamped()
            p, q = pose.pose.position, pose.pose.orientation
            p.x, p.y, p.z = msg[0]
            q.x, q.y, q.z, q.w = msg[1]
            return pose
        return msg

    def execute(self, userdata):
        {{ render_execute_callbacks() }}
        topic = userdata.topic if 'topic' in self._input_keys else 'smacha/' + self._name.lower()
        if self._action == 'stop':
            return self._publisher.stop(topic)
        if self._action == 'stop_all':
            return self._publisher.stop_all()
        try:
            msg = self._message(userdata.msg)
            rate = userdata.rate if 'rate' in self._input_keys else 100.0
            frame_id = userdata.frame_id if 'frame_id' in self._input_keys else ''
            outcome = self._publisher.start(msg, topic, rate, frame_id=frame_id)
        except Exception as e:
            rospy.logerr('Cannot publish on {}: {}'.format(topic, e))
            return 'aborted'
        if 'msg' in self._output_keys:
            userdata.msg = msg
        if 'topic' in self._output_keys:
            userdata.topic = topic
        return outcome
{% do defined_headers.append('class_PublishMsgState') %}
{% endif %}
{% endblock class_defs %}

{% block main_def %}
{{ super() }}
{% if 'msg_publisher' not in defined_headers %}
msg_publisher = MsgPublisher()
{% do defined_headers.append('msg_publisher') %}
{% endif %}
{% endblock main_def %}

{% block header %}
{{ super() }}
{# The container gets default `rate` (and `topic` for stop_all) userdata before the states'
   own userdata, so that scripts may leave them out. #}
{% set defaults = {'rate': 100.0} %}
{% if action == 'stop_all' %}{% do defaults.update({'topic': ''}) %}{% endif %}
{{ render_userdata(parent_sm_name, defaults) }}
{% endblock header %}

{% block body %}
{% set arguments = [name | pyrepr, 'msg_publisher', action | pyrepr] %}
{% if input_keys is defined %}{% do arguments.append(render_input_keys(input_keys, indent=0)) %}{% endif %}
{% if output_keys is defined %}{% do arguments.append(render_output_keys(output_keys, indent=0)) %}{% endif %}
{% if callbacks is defined %}{% do arguments.append(render_callbacks(name, uuid, callbacks, indent=0)) %}{% endif %}
smach.{{ parent_type }}.add({{ name | pyrepr }},
                       {{ class_name }}({{ arguments | join(', ') }})
{%- if transitions is defined and parent_type != 'Concurrence' %},
{{ render_transitions(transitions) }}
{%- endif %}
{%- if remapping is defined %},
{{ render_remapping(remapping) }}
{%- endif %})
{% endblock body %}
