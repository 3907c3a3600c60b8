{% block meta %}
name: PublishObserverMsgState
description: >
  A SMACH state that adds a ROS message to, or removes it from, the
  publications of the script's MsgPublisherObserver for `sub_topic`: with
  action `add` the `msg` input key is published on the `topic` input key
  (default smacha/<state name>) every time a message arrives on `sub_topic`
  (default tf), until a later state removes it (`remove`) or every topic
  (`remove_all`). Lists are parsed into points, poses and pose arrays as by
  PublishMsgState.
language: Python
framework: SMACH
type: State
tags: [core, ros]
includes:
- ParseMsg
- ParsePointStamped
- ParsePoseStamped
- ParsePoseArray
- ParsePointCloud
- ParsePointCloud2
- MsgPublisherObserver
extends:
- State
variables:
- action:
    description: add, remove or remove_all.
    type: str
- - sub_topic:
      description: >
        The topic whose messages set the pace of publication (default tf);
        each sub_topic has its own observer.
      type: str
- - input_keys:
      description: The userdata keys the state reads (msg, topic, msg_type, frame_id).
      type: list of str
- - output_keys:
      description: >
        The userdata keys the state writes (msg, output_msg or msg_output;
        topic, output_topic or topic_output).
      type: list of str
- - callbacks:
      description: Callbacks by output key, e.g. to build the message.
      type: dict of str
input_keys:
- msg:
    description: The message, or a list for a point, a pose or poses.
    type: [genpy.Message, list]
- topic:
    description: The topic to publish on.
    type: str
- - msg_type:
      description: The type to publish msg as, e.g. geometry_msgs/PoseArray.
      type: str
- - frame_id:
      description: The frame of the message header.
      type: str
output_keys:
- - msg:
      description: The message as published.
      type: genpy.Message
  - output_msg:
      description: The message as published.
      type: genpy.Message
  - msg_output:
      description: The message as published.
      type: genpy.Message
- - topic:
      description: The topic published on.
      type: str
  - output_topic:
      description: The topic published on.
      type: str
  - topic_output:
      description: The topic published on.
      type: str
outcomes:
- succeeded
- aborted
{% endblock meta %}
{% from "Utils.tpl.py" import render_init_callbacks, render_execute_callbacks %}
{% extends "State.tpl.py" %}
{% include "ParseMsg.tpl.py" %}
{% include "ParsePointStamped.tpl.py" %}
{% include "ParsePoseStamped.tpl.py" %}
{% include "ParsePoseArray.tpl.py" %}
{% include "ParsePointCloud.tpl.py" %}
{% include "ParsePointCloud2.tpl.py" %}
{% include "MsgPublisherObserver.tpl.py" %}

{% block class_defs %}
{{ super() }}
{% if 'class_PublishObserverMsgState' not in defined_headers %}
class PublishObserverMsgState(smach.State):
    """Adds a message to, or removes it from, a MsgPublisherObserver's publications."""

    def __init__(self, name, msg_pub_observer, action, input_keys=['msg', 'topic'],
                 output_keys=['msg', 'topic'], callbacks=[]):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded', 'aborted'])
        self._name = name
        self._observer = msg_pub_observer
        self._action = action
        # The parse function of each message class (parse_msg): points and poses are stamped.
        self._parsers = [(PointStamped, parse_pointstamped), (Point, parse_pointstamped),
                         (PoseStamped, parse_posestamped), (Pose, parse_posestamped),
                         (PoseArray, parse_posearray), (PointCloud, parse_pointcloud),
                         (PointCloud2, parse_pointcloud2)]
        {{ render_init_callbacks() }}

    def execute(self, userdata):
        {{ render_execute_callbacks() }}
        if self._action == 'remove_all':
            return self._observer.remove_all()
        topic = userdata.topic if 'topic' in self._input_keys else 'smacha/' + self._name.lower()
        if self._action == 'remove':
            return self._observer.remove(topic)
        if self._action != 'add':
            rospy.logerr('Unknown action {} (add, remove or remove_all)'.format(self._action))
            return 'aborted'
        try:
            msg_type = userdata.msg_type if 'msg_type' in self._input_keys else None
            msg = parse_msg(userdata.msg, self._parsers, msg_type)
            frame_id = userdata.frame_id if 'frame_id' in self._input_keys else None
        except Exception as e:
            rospy.logerr('Cannot publish on {}: {}'.format(topic, e))
            return 'aborted'
        outcome = self._observer.add(msg, topic, frame_id=frame_id)
        if outcome == 'succeeded':
            for key in ['msg', 'output_msg', 'msg_output']:
                if key in self._output_keys:
                    setattr(userdata, key, msg)
            for key in ['topic', 'output_topic', 'topic_output']:
                if key in self._output_keys:
                    setattr(userdata, key, topic)
        return outcome
{% do defined_headers.append('class_PublishObserverMsgState') %}
{% endif %}
{% endblock class_defs %}

{#- The observer of a sub_topic is a variable of main(), named after it as in SMACHA
    (`tf_msg_pub_observer`); bytes that cannot be in an identifier are written `_xHH`, and
    a leading digit gets a `_`. #}
{% block main_def %}
{{ super() }}
{% set observed = sub_topic if sub_topic is defined else 'tf' %}
{% set observer = ('_' if (observed | string)[:1].isdigit() else '') ~ (observed | string | pyident) ~ '_msg_pub_observer' %}
{% if observer not in defined_headers %}
{{ observer }} = MsgPublisherObserver(sub_topic={{ observed | pyrepr }})
{% do defined_headers.append(observer) %}
{% endif %}
{% endblock main_def %}

{% block header %}
{{ super() }}
{# The container gets a default `topic` for remove_all before the states' own userdata, so
   that scripts may leave it out. #}
{% if action == 'remove_all' %}
{{ render_userdata(parent_sm_name, {'topic': ''}) }}
{% endif %}
{% endblock header %}

{% block body %}
{% set observed = sub_topic if sub_topic is defined else 'tf' %}
{% set observer = ('_' if (observed | string)[:1].isdigit() else '') ~ (observed | string | pyident) ~ '_msg_pub_observer' %}
{% set arguments = [name | pyrepr, observer, action | pyrepr] %}
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
