{% block meta %}
name: ParsePointCloud2
description: >
  Helper function parse_pointcloud2: a sensor_msgs/PointCloud2 of a
  PointCloud2 (returned as it is) or a sensor_msgs/PointCloud (its points, as
  x, y, z float32 fields, and its header); anything else raises ValueError.
  Included by the message states.
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
{{ from_import(defined_headers, 'sensor_msgs.msg', 'PointCloud') }}
{{ from_import(defined_headers, 'sensor_msgs.msg', 'PointCloud2') }}
{{ from_import(defined_headers, 'sensor_msgs.point_cloud2', 'create_cloud_xyz32') }}
{% endblock imports %}

{% block defs %}
{% if 'def_parse_pointcloud2' not in defined_headers %}
def parse_pointcloud2(pointcloud_input):
    """A PointCloud2 from a PointCloud2 (as it is) or a PointCloud (its points)."""
    if isinstance(pointcloud_input, PointCloud2):
        return pointcloud_input
    if not isinstance(pointcloud_input, PointCloud):
        raise ValueError('not a point cloud (PointCloud2 or PointCloud): '
                         '{!r}'.format(pointcloud_input))
    return create_cloud_xyz32(pointcloud_input.header,
                              [[p.x, p.y, p.z] for p in pointcloud_input.points])
{% do defined_headers.append('def_parse_pointcloud2') %}
{% endif %}
{% endblock defs %}
