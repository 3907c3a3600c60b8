{% block meta %}
name: PoseToJointTrajServiceState
description: >
  Inverse kinematics with the Baxter SDK's IK service
  (ExternalTools/<limb>/PositionKinematicsNode/IKService, SolvePositionIK):
  writes to the output key joints the joint positions ({joint: angle}) that
  put a limb's endpoint at a pose in the base frame plus an optional offset.
  A variable left out is read from the input key of the same name (limb,
  poses; offsets when the script remaps it). Aborted when the service finds
  no solution.
language: Python
framework: SMACH
type: State
tags: [baxter]
includes: []
extends:
- State
variables:
- - limb:
      description: left or right (default input key limb).
      type: str
- - poses:
      description: The endpoint pose, [[x, y, z], [qx, qy, qz, qw]] (default input key poses).
      type: list
- - offsets:
      description: An offset added to the pose (default input key offsets, when set).
      type: list
input_keys: []
output_keys: [joints]
outcomes: [succeeded, aborted, preempted]
{% endblock meta %}
{% from "Utils.tpl.py" import from_import %}
{% from "BaxterUtils.tpl.py" import join_definitions, join_imports, import_baxter_state, import_pose_functions, define_baxter_state, define_pose_functions, text_argument, data_argument, render_baxter_state %}
{% extends "State.tpl.py" %}

{% block imports %}
{{- join_imports([import_baxter_state(defined_headers),
                 import_pose_functions(defined_headers),
                 from_import(defined_headers, 'geometry_msgs.msg', 'PoseStamped'),
                 from_import(defined_headers, 'std_msgs.msg', 'Header'),
                 from_import(defined_headers, 'baxter_core_msgs.srv', 'SolvePositionIK'),
                 from_import(defined_headers, 'baxter_core_msgs.srv', 'SolvePositionIKRequest')]) }}
{%- endblock imports %}

{% block class_defs %}
{%- set definitions = [define_baxter_state(defined_headers), define_pose_functions(defined_headers)] %}
{%- if 'class_PoseToJointTrajServiceState' not in defined_headers %}
{%- set definition %}
class PoseToJointTrajServiceState(BaxterState):
    """Writes to joints the joint positions that put a limb's endpoint at a pose (in the
    base frame) plus an offset; aborted when the IK service finds no solution."""

    SERVICE_TIMEOUT = 5.0  # seconds to wait for the IK service

    def __init__(self, limb=None, poses=None, offsets=None, input_keys=()):
        BaxterState.__init__(self, dict(limb=limb, poses=poses, offsets=offsets), input_keys,
                             output_keys=['joints'])

    def run(self, userdata, limb, poses, offsets):
        pose = poses if offsets is None else baxter_offset_pose(poses, offsets)
        service_name = 'ExternalTools/' + limb + '/PositionKinematicsNode/IKService'
        rospy.wait_for_service(service_name, self.SERVICE_TIMEOUT)
        request = SolvePositionIKRequest()
        request.pose_stamp.append(PoseStamped(header=Header(stamp=rospy.Time.now(),
                                                            frame_id='base'),
                                              pose=baxter_pose_msg(pose)))
        response = rospy.ServiceProxy(service_name, SolvePositionIK)(request)
        if not response.isValid[0]:
            rospy.logwarn('%s: no joint solution for the %s limb at %s',
                          type(self).__name__, limb, pose)
            return 'aborted'
        solution = response.joints[0]
        userdata.joints = dict(zip(solution.name, solution.position))
        return 'succeeded'
{%- endset %}
{%- do definitions.append(definition) %}
{%- do defined_headers.append('class_PoseToJointTrajServiceState') %}
{%- endif %}
{{ join_definitions(definitions) }}
{%- endblock class_defs %}

{% block body %}
{%- set arguments = [] %}
{%- set keys = [] %}
{%- if limb is defined %}{% do arguments.append(text_argument('limb', limb)) %}{% else %}{% do keys.append('limb') %}{% endif %}
{%- if poses is defined %}{% do arguments.append(data_argument('poses', poses)) %}{% else %}{% do keys.append('poses') %}{% endif %}
{%- if offsets is defined %}{% do arguments.append(data_argument('offsets', offsets)) %}
{%- elif remapping is defined and 'offsets' in remapping %}{% do keys.append('offsets') %}{% endif %}
{%- if include_comments %}
# {{ name | pycomment }} ({{ class_name }})
{%- endif %}
{{ render_baxter_state(parent_type, name, 'PoseToJointTrajServiceState', arguments, keys, transitions, remapping) }}
{% endblock body %}
