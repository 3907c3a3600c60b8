{% block meta %}
name: ParsePointCloud
description: >
  Helper function parse_pointcloud: a sensor_msgs/PointCloud of a PointCloud
  (returned as it is) or a sensor_msgs/PointCloud2 (its x, y, z points, NaNs
  skipped, and its header); anything else raises ValueError. Included by the
  message states.
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
{% from "Utils.tpl.py" import from_import, from_import_as %}
{% block imports %}
{{ from_import(defined_headers, 'geometry_msgs.msg', 'Point32') }}
{{ from_import(defined_headers, 'sensor_msgs.msg', 'PointCloud') }}
{{ from_import(defined_headers, 'sensor_msgs.msg', 'PointCloud2') }}
{{ from_import_as(defined_headers, 'sensor_msgs', 'point_cloud2', 'pc2') }}
{% endblock imports %}

{% block defs %}
{% if 'def_parse_pointcloud' not in defined_headers %}
def parse_pointcloud(pointcloud_input):
    """A PointCloud from a PointCloud (as it is) or a PointCloud2 (x, y, z of each point)."""
    if isinstance(pointcloud_input, PointCloud):
        return pointcloud_input
    if not isinstance(pointcloud_input, PointCloud2):
        raise ValueError('not a point cloud (PointCloud or PointCloud2): '
                         '{!r}'.format(pointcloud_input))
    points = pc2.read_points(pointcloud_input, field_names=('x', 'y', 'z'), skip_nans=True)
    return PointCloud(header=pointcloud_input.header,
                      points=[Point32(x=x, y=y, z=z) for x, y, z in points])
{% do defined_headers.append('def_parse_pointcloud') %}
{% endif %}
{% endblock defs %}
