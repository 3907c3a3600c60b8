{% block meta %}
name: ParsePoseArray
description: >
  Helper function parse_posearray: a geometry_msgs/PoseArray of a PoseArray
  (returned as it is) or a list of poses (each a Pose, a PoseStamped or [[x,
  y, z], [qx, qy, qz, qw]]), stamped now; anything else raises ValueError.
  Included by the message states.
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
{{ from_import(defined_headers, 'geometry_msgs.msg', 'PoseArray') }}
{% endblock imports %}

{% block defs %}
{% if 'def_parse_posearray' not in defined_headers %}
def parse_posearray(posearray_input):
    """A PoseArray from a PoseArray (as it is) or a list of poses (see parse_pose)."""
    if isinstance(posearray_input, PoseArray):
        return posearray_input
    if not isinstance(posearray_input, (list, tuple)):
        raise ValueError('not a pose array (PoseArray or a list of poses): '
                         '{!r}'.format(posearray_input))
    posearray = PoseArray(poses=[parse_pose(pose) for pose in posearray_input])
    if rospy.rostime.is_rostime_initialized():
        posearray.header.stamp = rospy.Time.now()
    return posearray
{% do defined_headers.append('def_parse_posearray') %}
{% endif %}
{% endblock defs %}
