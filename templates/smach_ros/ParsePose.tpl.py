{% block meta %}
name: ParsePose
description: >
  Helper function parse_pose: a geometry_msgs/Pose of a Pose (returned as it
  is), the pose of a PoseStamped, or a list [[x, y, z], [qx, qy, qz, qw]]
  (position, orientation quaternion); anything else raises ValueError.
language: Python
framework: SMACH
type: None
tags: [core, ros]
includes: []
extends: []
variables: []
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% from "Utils.tpl.py" import from_import %}
{% block imports %}
{{ from_import(defined_headers, 'geometry_msgs.msg', 'Pose') }}
{{ from_import(defined_headers, 'geometry_msgs.msg', 'PoseStamped') }}
{% endblock imports %}

{% block defs %}
{% if 'def_parse_pose' not in defined_headers %}
def parse_pose(pose_input):
    """A Pose from a Pose (as it is), a PoseStamped (its pose) or [position, quaternion]."""
    if isinstance(pose_input, Pose):
        return pose_input
    if isinstance(pose_input, PoseStamped):
        return pose_input.pose
    position = orientation = []
    if isinstance(pose_input, (list, tuple)) and len(pose_input) == 2:
        try:
            position = [float(value) for value in pose_input[0]]
            orientation = [float(value) for value in pose_input[1]]
        except (TypeError, ValueError):
            position = orientation = []
    if len(position) != 3 or len(orientation) != 4:
        raise ValueError('not a pose (Pose, PoseStamped or [[x, y, z], [qx, qy, qz, qw]]): '
                         '{!r}'.format(pose_input))
    pose = Pose()
    pose.position.x, pose.position.y, pose.position.z = position
    pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w = orientation
    return pose
{% do defined_headers.append('def_parse_pose') %}
{% endif %}
{% endblock defs %}
