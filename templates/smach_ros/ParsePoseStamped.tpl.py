{% block meta %}
name: ParsePoseStamped
description: >
  Helper function parse_posestamped: a geometry_msgs/PoseStamped of a
  PoseStamped (returned as it is), a Pose, or a list [[x, y, z], [qx, qy, qz,
  qw]], stamped now; anything else raises ValueError. Included by the message
  states.
language: Python
framework: SMACH
type: None
tags: [core, ros]
includes:
- ParsePose
extends: []
variables: []
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% from "Utils.tpl.py" import import_module, from_import %}
{% include "ParsePose.tpl.py" %}
{% block imports %}
{{ import_module(defined_headers, 'rospy') }}
{{ from_import(defined_headers, 'geometry_msgs.msg', 'PoseStamped') }}
{% endblock imports %}

{% block defs %}
{% if 'def_parse_posestamped' not in defined_headers %}
def parse_posestamped(pose_input):
    """A PoseStamped from a PoseStamped (as it is), a Pose or [position, quaternion]."""
    if isinstance(pose_input, PoseStamped):
        return pose_input
    stamped = PoseStamped(pose=parse_pose(pose_input))
    if rospy.rostime.is_rostime_initialized():
        stamped.header.stamp = rospy.Time.now()
    return stamped
{% do defined_headers.append('def_parse_posestamped') %}
{% endif %}
{% endblock defs %}
