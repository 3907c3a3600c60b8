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
framework: FlexBE
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
{% extends "State.tpl.py" %}
{% from "BaxterUtils.tpl.py" import define_baxter_module, text_argument, data_argument, render_baxter_add %}
{% set state_module = '' %}
{% set state_class = 'PoseToJointTrajServiceState' %}

{% block class_defs %}
{{ define_baxter_module(defined_headers) }}


{% if 'class_PoseToJointTrajServiceState' not in defined_headers %}
class PoseToJointTrajServiceState(BaxterEventState):
    """
    Inverse kinematics with the Baxter SDK's IK service: the joint positions that put a
    limb's endpoint at a pose in the base frame, plus an offset.

    -- limb         string  left or right (None: the input key limb).
    -- poses        list    The pose, [[x, y, z], [qx, qy, qz, qw]] (None: the input key).
    -- offsets      list    An offset added to the pose (None: none, or the input key).
    -- input_keys   list    The arguments read from the userdata.

    ># limb         string  The limb, when limb is an input key.
    ># poses        list    The pose, when poses is an input key.
    ># offsets      list    The offset, when offsets is an input key.
    #> joints       dict    The joint positions, {joint: angle}.

    <= succeeded            The service found joint positions.
    <= aborted              It found none.
    <= preempted            The behavior was preempted.
    """

    SERVICE_TIMEOUT = 5.0  # seconds to wait for the IK service

    def __init__(self, limb=None, poses=None, offsets=None, input_keys=[]):
        BaxterEventState.__init__(self, dict(limb=limb, poses=poses, offsets=offsets),
                                  input_keys, output_keys=['joints'])

    def start(self, userdata, limb, poses, offsets):
        pose = poses if offsets is None else baxter_offset_pose(poses, offsets)
        service_name = 'ExternalTools/' + limb + '/PositionKinematicsNode/IKService'
        rospy.wait_for_service(service_name, self.SERVICE_TIMEOUT)
        request = SolvePositionIKRequest()
        request.pose_stamp.append(PoseStamped(header=Header(stamp=rospy.Time.now(),
                                                            frame_id='base'),
                                              pose=baxter_pose_msg(pose)))
        response = rospy.ServiceProxy(service_name, SolvePositionIK)(request)
        if not response.isValid[0]:
            Logger.logwarn('%s: no joint solution for the %s limb at %s'
                           % (type(self).__name__, limb, pose))
            return 'aborted'
        solution = response.joints[0]
        userdata.joints = dict(zip(solution.name, solution.position))
        return 'succeeded'
{% do defined_headers.append('class_PoseToJointTrajServiceState') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
{%- set arguments = [] %}
{%- set keys = [] %}
{%- if limb is defined %}{% do arguments.append(text_argument('limb', limb)) %}{% else %}{% do keys.append('limb') %}{% endif %}
{%- if poses is defined %}{% do arguments.append(data_argument('poses', poses)) %}{% else %}{% do keys.append('poses') %}{% endif %}
{%- if offsets is defined %}{% do arguments.append(data_argument('offsets', offsets)) %}
{%- elif remapping is defined and 'offsets' in remapping %}{% do keys.append('offsets') %}{% endif %}
{{ render_baxter_add(defined_headers, default_module, state_class, name, arguments, keys, ['joints'], transitions, autonomy, remapping) }}
{% endblock body %}
