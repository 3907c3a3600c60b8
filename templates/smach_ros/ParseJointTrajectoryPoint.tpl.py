{% block meta %}
name: ParseJointTrajectoryPoint
description: >
  Helper function parse_jointtrajectorypoint: a
  trajectory_msgs/JointTrajectoryPoint of a JointTrajectoryPoint (returned as
  it is), a sensor_msgs/JointState (its positions, velocities and efforts) or
  a list of joint positions [p1, ..., pn]; anything else raises ValueError.
  For templates of states that command joints.
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
{{ from_import(defined_headers, 'sensor_msgs.msg', 'JointState') }}
{{ from_import(defined_headers, 'trajectory_msgs.msg', 'JointTrajectoryPoint') }}
{% endblock imports %}

{% block defs %}
{% if 'def_parse_jointtrajectorypoint' not in defined_headers %}
def parse_jointtrajectorypoint(jointtrajectorypoint_input):
    """A JointTrajectoryPoint from a JointTrajectoryPoint (as it is), a JointState or a
    list of joint positions."""
    if isinstance(jointtrajectorypoint_input, JointTrajectoryPoint):
        return jointtrajectorypoint_input
    if isinstance(jointtrajectorypoint_input, JointState):
        return JointTrajectoryPoint(positions=list(jointtrajectorypoint_input.position),
                                    velocities=list(jointtrajectorypoint_input.velocity),
                                    effort=list(jointtrajectorypoint_input.effort))
    if isinstance(jointtrajectorypoint_input, (list, tuple)):
        try:
            return JointTrajectoryPoint(
                positions=[float(value) for value in jointtrajectorypoint_input])
        except (TypeError, ValueError):
            pass
    raise ValueError('not a joint trajectory point (JointTrajectoryPoint, JointState or a '
                     'list of positions): {!r}'.format(jointtrajectorypoint_input))
{% do defined_headers.append('def_parse_jointtrajectorypoint') %}
{% endif %}
{% endblock defs %}
