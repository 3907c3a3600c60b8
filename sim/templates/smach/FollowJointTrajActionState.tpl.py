{% block meta %}
name: FollowJointTrajActionState
description: >
  Moves a limb through a list of joint waypoints in order with the Baxter
  SDK's follow-joint-trajectory action server
  (robot/limb/<limb>/follow_joint_trajectory), timed at a fraction of the
  joint velocity limits; cancelled and aborted after timeout seconds per
  waypoint. A variable left out is read from the input key of the same name
  (limb, points).
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
- - points:
      description: A list of joint positions (default input key points).
      type: list
- - speed:
      description: Fraction of the joint velocity limits, per waypoint (default 0.3).
      type: float
- - timeout:
      description: Seconds per waypoint (default 15).
      type: float
input_keys: []
output_keys: []
outcomes: [succeeded, aborted, preempted]
{% endblock meta %}
{% from "Utils.tpl.py" import import_module, from_import %}
{% from "BaxterUtils.tpl.py" import join_definitions, join_imports, import_baxter_state, define_baxter_state, define_joint_function, text_argument, data_argument, render_baxter_state %}
{% extends "State.tpl.py" %}

{% block imports %}
{{- join_imports([import_baxter_state(defined_headers),
                 import_module(defined_headers, 'actionlib'),
                 import_module(defined_headers, 'baxter_interface'),
                 from_import(defined_headers, 'control_msgs.msg', 'FollowJointTrajectoryAction'),
                 from_import(defined_headers, 'control_msgs.msg', 'FollowJointTrajectoryGoal'),
                 from_import(defined_headers, 'control_msgs.msg', 'FollowJointTrajectoryResult'),
                 from_import(defined_headers, 'trajectory_msgs.msg', 'JointTrajectoryPoint')]) }}
{%- endblock imports %}

{% block class_defs %}
{%- set definitions = [define_baxter_state(defined_headers), define_joint_function(defined_headers)] %}
{%- if 'class_FollowJointTrajActionState' not in defined_headers %}
{%- set definition %}
class FollowJointTrajActionState(BaxterState):
    """Sends joint waypoints to a limb's follow-joint-trajectory action server."""

    JOINT_VELOCITY_LIMIT = 2.0  # rad/s, Baxter's shoulder and elbow joints
    POLL_PERIOD = 0.05  # seconds between checks for preemption

    def __init__(self, limb=None, points=None, speed=0.3, timeout=15.0, input_keys=()):
        BaxterState.__init__(self, dict(limb=limb, points=points, speed=speed, timeout=timeout),
                             input_keys)

    def goal(self, limb_interface, points, speed):
        names = limb_interface.joint_names()
        angles = limb_interface.joint_angles()
        previous, elapsed = [angles[name] for name in names], 0.0
        goal = FollowJointTrajectoryGoal()
        goal.trajectory.joint_names = names
        for point in points:
            positions = baxter_joint_positions(limb_interface, point)
            target = [positions[name] for name in names]
            largest_step = max(abs(a - b) for a, b in zip(target, previous))
            elapsed += max(largest_step / (self.JOINT_VELOCITY_LIMIT * speed), self.POLL_PERIOD)
            goal.trajectory.points.append(JointTrajectoryPoint(
                positions=target, time_from_start=rospy.Duration(elapsed)))
            previous = target
        goal.trajectory.header.stamp = rospy.Time.now()
        return goal

    def run(self, userdata, limb, points, speed, timeout):
        limb_interface = baxter_interface.Limb(limb)
        client = actionlib.SimpleActionClient('robot/limb/' + limb + '/follow_joint_trajectory',
                                              FollowJointTrajectoryAction)
        if not client.wait_for_server(rospy.Duration(timeout)):
            return 'aborted'
        client.send_goal(self.goal(limb_interface, points, speed))
        deadline = rospy.get_time() + timeout * len(points)
        while not client.wait_for_result(rospy.Duration(self.POLL_PERIOD)):
            if self.preempt_requested():
                client.cancel_goal()
                self.service_preempt()
                return 'preempted'
            if rospy.get_time() > deadline:
                client.cancel_goal()
                return 'aborted'
        result = client.get_result()
        done = result is not None and result.error_code == FollowJointTrajectoryResult.SUCCESSFUL
        return 'succeeded' if done else 'aborted'
{%- endset %}
{%- do definitions.append(definition) %}
{%- do defined_headers.append('class_FollowJointTrajActionState') %}
{%- endif %}
{{ join_definitions(definitions) }}
{%- endblock class_defs %}

{% block body %}
{%- set arguments = [] %}
{%- set keys = [] %}
{%- if limb is defined %}{% do arguments.append(text_argument('limb', limb)) %}{% else %}{% do keys.append('limb') %}{% endif %}
{%- if points is defined %}{% do arguments.append(data_argument('points', points)) %}{% else %}{% do keys.append('points') %}{% endif %}
{%- if speed is defined %}{% do arguments.append(data_argument('speed', speed | float)) %}{% endif %}
{%- if timeout is defined %}{% do arguments.append(data_argument('timeout', timeout | float)) %}{% endif %}
{%- if include_comments %}
# {{ name | pycomment }} ({{ class_name }})
{%- endif %}
{{ render_baxter_state(parent_type, name, 'FollowJointTrajActionState', arguments, keys, transitions, remapping) }}
{% endblock body %}
