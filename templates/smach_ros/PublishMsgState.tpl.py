{% block meta %}
name: PublishMsgState
description: >
  A SMACH state that starts or stops publishing a ROS message. With action
  `start` it publishes the `msg` input key on the `topic` input key (default
  smacha/<state name>) at the `rate` input key (default 100 Hz) until a later
  state stops it (`stop`) or stops every topic (`stop_all`). Points and poses
  are published stamped: a Point or a list [x, y, z] as a
  geometry_msgs/PointStamped, a Pose or [[x, y, z], [qx, qy, qz, qw]] as a
  geometry_msgs/PoseStamped, a list of poses as a PoseArray (the Parse*
  helpers; the `msg_type` input key names the type when a list is ambiguous).
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
- MsgPublisher
extends:
- State
variables:
- action:
    description: start, stop or stop_all.
    type: str
- - input_keys:
      description: The userdata keys the state reads (msg, topic, rate, msg_type, frame_id).
      type: list of str
- - output_keys:
      description: >
        The userdata keys the state writes (msg, output_msg or msg_output;
        topic, output_topic or topic_output).
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
    description: The message, or a list for a point, a pose or poses.
    type: [genpy.Message, list]
- topic:
    description: The topic to publish on.
    type: str
- - rate:
      description: The publishing rate.
      type: float
      units: Hz
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
{% from "Utils.tpl.py" import import_module, render_init_callbacks, render_execute_callbacks %}
{% from "ScriptImports.tpl.py" import render_script_imports %}
{% extends "State.tpl.py" %}
{% include "ParseMsg.tpl.py" %}
{% include "ParsePointStamped.tpl.py" %}
{% include "ParsePoseStamped.tpl.py" %}
{% include "ParsePoseArray.tpl.py" %}
{% include "ParsePointCloud.tpl.py" %}
{% include "ParsePointCloud2.tpl.py" %}
{% include "MsgPublisher.tpl.py" %}

{% block imports %}
{{ super() }}
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
        # The parse function of each message class (parse_msg): points and poses are stamped.
        self._parsers = [(PointStamped, parse_pointstamped), (Point, parse_pointstamped),
                         (PoseStamped, parse_posestamped), (Pose, parse_posestamped),
                         (PoseArray, parse_posearray), (PointCloud, parse_pointcloud),
                         (PointCloud2, parse_pointcloud2)]
        {{ render_init_callbacks() }}

    def execute(self, userdata):
        {{ render_execute_callbacks() }}
        topic = userdata.topic if 'topic' in self._input_keys else 'smacha/' + self._name.lower()
        if self._action == 'stop':
            return self._publisher.stop(topic)
        if self._action == 'stop_all':
            return self._publisher.stop_all()
        try:
            msg_type = userdata.msg_type if 'msg_type' in self._input_keys else None
            msg = parse_msg(userdata.msg, self._parsers, msg_type)
            rate = userdata.rate if 'rate' in self._input_keys else 100.0
            frame_id = userdata.frame_id if 'frame_id' in self._input_keys else ''
            outcome = self._publisher.start(msg, topic, rate, frame_id=frame_id)
        except Exception as e:
            rospy.logerr('Cannot publish on {}: {}'.format(topic, e))
            return 'aborted'
        for key in ['msg', 'output_msg', 'msg_output']:
            if key in self._output_keys:
                setattr(userdata, key, msg)
        for key in ['topic', 'output_topic', 'topic_output']:
            if key in self._output_keys:
                setattr(userdata, key, topic)
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
