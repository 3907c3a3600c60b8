{% block meta %}
name: ParseTransformStamped
description: >
  Helper function parse_transformstamped: a geometry_msgs/TransformStamped of
  a TransformStamped (returned as it is), a Transform, or a list [[x, y, z],
  [qx, qy, qz, qw]] (translation, rotation quaternion), stamped now; anything
  else raises ValueError. Included by TransformMsgState.
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
{% from "Utils.tpl.py" import import_module, from_import %}
{% block imports %}
{{ import_module(defined_headers, 'rospy') }}
{{ from_import(defined_headers, 'geometry_msgs.msg', 'Transform') }}
{{ from_import(defined_headers, 'geometry_msgs.msg', 'TransformStamped') }}
{% endblock imports %}

{% block defs %}
{% if 'def_parse_transformstamped' not in defined_headers %}
def parse_transformstamped(transform_input):
    """A TransformStamped from a TransformStamped (as it is), a Transform or
    [[x, y, z], [qx, qy, qz, qw]]."""
    if isinstance(transform_input, TransformStamped):
        return transform_input
    if isinstance(transform_input, Transform):
        stamped = TransformStamped(transform=transform_input)
    else:
        translation = rotation = []
        if isinstance(transform_input, (list, tuple)) and len(transform_input) == 2:
            try:
                translation = [float(value) for value in transform_input[0]]
                rotation = [float(value) for value in transform_input[1]]
            except (TypeError, ValueError):
                translation = rotation = []
        if len(translation) != 3 or len(rotation) != 4:
            raise ValueError('not a transform (TransformStamped, Transform or '
                             '[[x, y, z], [qx, qy, qz, qw]]): {!r}'.format(transform_input))
        stamped = TransformStamped()
        t, r = stamped.transform.translation, stamped.transform.rotation
        t.x, t.y, t.z = translation
        r.x, r.y, r.z, r.w = rotation
    if rospy.rostime.is_rostime_initialized():
        stamped.header.stamp = rospy.Time.now()
    return stamped
{% do defined_headers.append('def_parse_transformstamped') %}
{% endif %}
{% endblock defs %}
