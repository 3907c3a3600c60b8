{% block meta %}
name: ParsePointStamped
description: >
  Helper function parse_pointstamped: a geometry_msgs/PointStamped of a
  PointStamped (returned as it is), a Point or Point32, or a list of three
  numbers [x, y, z], stamped now; anything else raises ValueError. Included by
  the message states.
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
{{ from_import(defined_headers, 'geometry_msgs.msg', 'Point') }}
{{ from_import(defined_headers, 'geometry_msgs.msg', 'Point32') }}
{{ from_import(defined_headers, 'geometry_msgs.msg', 'PointStamped') }}
{% endblock imports %}

{% block defs %}
{% if 'def_parse_pointstamped' not in defined_headers %}
def parse_pointstamped(point_input):
    """A PointStamped from a PointStamped (as it is), a Point, a Point32 or [x, y, z]."""
    if isinstance(point_input, PointStamped):
        return point_input
    if isinstance(point_input, (Point, Point32)):
        coordinates = [point_input.x, point_input.y, point_input.z]
    else:
        coordinates = []
        if isinstance(point_input, (list, tuple)):
            try:
                coordinates = [float(value) for value in point_input]
            except (TypeError, ValueError):
                coordinates = []
        if len(coordinates) != 3:
            raise ValueError('not a point (PointStamped, Point, Point32 or [x, y, z]): '
                             '{!r}'.format(point_input))
    stamped = PointStamped()
    stamped.point.x, stamped.point.y, stamped.point.z = coordinates
    if rospy.rostime.is_rostime_initialized():
        stamped.header.stamp = rospy.Time.now()
    return stamped
{% do defined_headers.append('def_parse_pointstamped') %}
{% endif %}
{% endblock defs %}
