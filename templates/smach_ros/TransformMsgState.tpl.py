{% block meta %}
name: TransformMsgState
description: >
  A SMACH state that transforms a message into another TF frame: the `msg`
  input key, from its `source` frame (or its header's frame) to the
  `frame_id` or `target` frame, looked up on TF2, or by the given `transform`
  input key. Points, poses, pose arrays and point clouds are transformed (a
  list is parsed first, as PublishMsgState does); the result goes to the
  `output_msg` key (or msg, msg_output), the transform used to `transform`
  (or output_transform, transform_output) when those are output keys.
language: Python
framework: SMACH
type: State
tags: [core, ros]
includes:
- ParseMsg
- ParseTransformStamped
- ParsePointStamped
- ParsePoseStamped
- ParsePoseArray
- ParsePointCloud2
- TF2ListenerSingleton
extends:
- State
variables:
- - transform_type:
      description: >
        transform (the whole transform, the default), translation (its
        translation only) or rotation (its rotation only).
      type: str
- - timeout:
      description: >
        How long to wait for the transform on TF2, in seconds (default: until
        it is there, the state is preempted or ROS shuts down).
      type: float
      units: s
- - input_keys:
      description: >
        The userdata keys the state reads (msg, msg_type, source, frame_id or
        target, transform); other keys are for its callbacks.
      type: list of str
- - output_keys:
      description: >
        The userdata keys the state writes (output_msg, msg or msg_output;
        transform, output_transform or transform_output); other keys are for
        its callbacks.
      type: list of str
- - callbacks:
      description: Callbacks by output key, run before the message is transformed.
      type: dict of str
input_keys:
- msg:
    description: >
      The message: a PointStamped, PoseStamped, PoseArray, PointCloud2 or
      PointCloud, a Point or Pose, or a list [x, y, z] (a point), [[x, y, z],
      [qx, qy, qz, qw]] (a pose) or a list of poses.
    type: [genpy.Message, list]
- - msg_type:
      description: The type to read msg as, e.g. geometry_msgs/PoseStamped.
      type: str
- - source:
      description: The frame the message is in (default its header's frame_id).
      type: str
- - frame_id:
      description: The frame to transform the message into.
      type: str
  - target:
      description: The frame to transform the message into.
      type: str
  - transform:
      description: >
        The transform to apply instead of a TF2 lookup: a TransformStamped,
        a Transform or [[x, y, z], [qx, qy, qz, qw]].
      type: [geometry_msgs/TransformStamped, list]
output_keys:
- - output_msg:
      description: The transformed message.
      type: genpy.Message
  - msg:
      description: The transformed message.
      type: genpy.Message
  - msg_output:
      description: The transformed message.
      type: genpy.Message
- - transform:
      description: The transform applied.
      type: geometry_msgs/TransformStamped
  - output_transform:
      description: The transform applied.
      type: geometry_msgs/TransformStamped
  - transform_output:
      description: The transform applied.
      type: geometry_msgs/TransformStamped
outcomes:
- succeeded
- aborted
{% endblock meta %}
{% from "Utils.tpl.py" import import_module, from_import, render_init_callbacks, render_execute_callbacks, render_value %}
{% extends "State.tpl.py" %}
{% include "ParseMsg.tpl.py" %}
{% include "ParseTransformStamped.tpl.py" %}
{% include "ParsePointStamped.tpl.py" %}
{% include "ParsePoseStamped.tpl.py" %}
{% include "ParsePoseArray.tpl.py" %}
{% include "ParsePointCloud2.tpl.py" %}
{% include "TF2ListenerSingleton.tpl.py" %}

{% block imports %}
{{ super() }}
{{ import_module(defined_headers, 'copy') }}
{{ import_module(defined_headers, 'tf2_geometry_msgs') }}
{{ import_module(defined_headers, 'tf2_sensor_msgs') }}
{% endblock imports %}

{% block class_defs %}
{{ super() }}
{% if 'class_TransformMsgState' not in defined_headers %}
class TransformMsgState(smach.State):
    """Transforms the `msg` input into the `frame_id` (or `target`) frame, by TF2 or by the
    `transform` input; aborts when the message or the transform cannot be had."""

    def __init__(self, transform_type='transform', input_keys=['msg', 'frame_id'],
                 output_keys=['output_msg'], callbacks=[], timeout=None):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded', 'aborted'])
        self._transform_type = transform_type
        self._timeout = timeout
        self._buffer, _ = TF2ListenerSingleton.get()
        # Points, poses and clouds are transformed stamped (tf2_geometry_msgs, tf2_sensor_msgs).
        self._parsers = [(PointStamped, parse_pointstamped), (Point, parse_pointstamped),
                         (PoseStamped, parse_posestamped), (Pose, parse_posestamped),
                         (PoseArray, parse_posearray), (PointCloud2, parse_pointcloud2),
                         (PointCloud, parse_pointcloud2)]
        {{ render_init_callbacks() }}

    def _lookup(self, target, source):
        """The transform from source to target on TF2, waiting for it up to the timeout."""
        deadline = None if self._timeout is None else rospy.get_time() + self._timeout
        while not rospy.is_shutdown() and not self.preempt_requested():
            if self._buffer.can_transform(target, source, rospy.Time(0), rospy.Duration(0.05)):
                return self._buffer.lookup_transform(target, source, rospy.Time(0))
            if deadline is not None and rospy.get_time() >= deadline:
                break
        raise RuntimeError('no transform from {} to {}'.format(source, target))

    def _transform(self, userdata, msg):
        if 'transform' in self._input_keys:
            transform = copy.deepcopy(parse_transformstamped(userdata.transform))
        else:
            if 'frame_id' in self._input_keys:
                target = userdata.frame_id
            elif 'target' in self._input_keys:
                target = userdata.target
            else:
                raise ValueError('no target frame: give the input key frame_id or target')
            source = userdata.source if 'source' in self._input_keys else ''
            source = source or getattr(getattr(msg, 'header', None), 'frame_id', '')
            if not source:
                raise ValueError('no source frame: give the input key source or a header frame')
            transform = self._lookup(target, source)
        if self._transform_type == 'translation':
            r = transform.transform.rotation
            r.x, r.y, r.z, r.w = 0.0, 0.0, 0.0, 1.0
        elif self._transform_type == 'rotation':
            t = transform.transform.translation
            t.x, t.y, t.z = 0.0, 0.0, 0.0
        elif self._transform_type != 'transform':
            raise ValueError('unknown transform_type {}'.format(self._transform_type))
        return transform

    @staticmethod
    def _apply(msg, transform):
        if isinstance(msg, PointStamped):
            return tf2_geometry_msgs.do_transform_point(msg, transform)
        if isinstance(msg, PoseStamped):
            return tf2_geometry_msgs.do_transform_pose(msg, transform)
        if isinstance(msg, PointCloud2):
            return tf2_sensor_msgs.do_transform_cloud(msg, transform)
        if isinstance(msg, PoseArray):
            poses = [tf2_geometry_msgs.do_transform_pose(PoseStamped(msg.header, pose),
                                                         transform).pose for pose in msg.poses]
            return PoseArray(header=copy.deepcopy(transform.header), poses=poses)
        raise ValueError('cannot transform a {}'.format(type(msg).__name__))

    def execute(self, userdata):
        {{ render_execute_callbacks() }}
        try:
            msg_type = userdata.msg_type if 'msg_type' in self._input_keys else None
            msg = parse_msg(userdata.msg, self._parsers, msg_type)
            transform = self._transform(userdata, msg)
            transformed = self._apply(msg, transform)
        except Exception as e:
            rospy.logerr('Cannot transform the message: {}'.format(e))
            if self.preempt_requested():
                self.service_preempt()
            return 'aborted'
        for key in ['msg', 'output_msg', 'msg_output']:
            if key in self._output_keys:
                setattr(userdata, key, transformed)
        for key in ['transform', 'output_transform', 'transform_output']:
            if key in self._output_keys:
                setattr(userdata, key, transform)
        return 'succeeded'
{% do defined_headers.append('class_TransformMsgState') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
{% set arguments = [] %}
{% if transform_type is defined %}{% do arguments.append('transform_type=' + transform_type | pyrepr) %}{% endif %}
{% if input_keys is defined %}{% do arguments.append(render_input_keys(input_keys, indent=0)) %}{% endif %}
{% if output_keys is defined %}{% do arguments.append(render_output_keys(output_keys, indent=0)) %}{% endif %}
{% if callbacks is defined %}{% do arguments.append(render_callbacks(name, uuid, callbacks, indent=0)) %}{% endif %}
{% if timeout is defined %}{% do arguments.append('timeout=' + render_value(timeout) | string) %}{% endif %}
smach.{{ parent_type }}.add({{ name | pyrepr }},
                       TransformMsgState({{ arguments | join(', ') }})
{%- if transitions is defined and parent_type != 'Concurrence' %},
{{ render_transitions(transitions) }}
{%- endif %}
{%- if remapping is defined %},
{{ render_remapping(remapping) }}
{%- endif %})
{% endblock body %}
