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
{% extends "State.tpl.py" %}
{% from "BaxterUtils.tpl.py" import define_baxter_module, text_argument, data_argument, render_baxter_add %}
{% set state_module = '' %}
{% set state_class = 'FollowJointTrajActionState' %}

{% block class_defs %}
{{ define_baxter_module(defined_headers) }}


{% if 'class_FollowJointTrajActionState' not in defined_headers %}
class FollowJointTrajActionState(BaxterEventState):
    """
    Moves a limb through joint waypoints with the follow-joint-trajectory action server.

    -- limb         string  left or right (None: the input key limb).
    -- points       list    A list of joint positions (None: the input key points).
    -- speed        float   Fraction of the joint velocity limits, per waypoint.
    -- timeout      float   Seconds per waypoint.
    -- input_keys   list    The arguments read from the userdata.

    ># limb         string  The limb, when limb is an input key.
    ># points       list    The waypoints, when points is an input key.

    <= succeeded            The action server reached the last waypoint.
    <= aborted              It failed, or took longer than the timeouts.
    <= preempted            The behavior was preempted.
    """

    JOINT_VELOCITY_LIMIT = 2.0  # rad/s, Baxter's shoulder and elbow joints
    MIN_STEP = 0.05  # seconds between two waypoints at least

    def __init__(self, limb=None, points=None, speed=0.3, timeout=15.0, input_keys=[]):
        BaxterEventState.__init__(self, dict(limb=limb, points=points, speed=speed,
                                             timeout=timeout), input_keys)

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
            elapsed += max(largest_step / (self.JOINT_VELOCITY_LIMIT * speed), self.MIN_STEP)
            goal.trajectory.points.append(JointTrajectoryPoint(
                positions=target, time_from_start=rospy.Duration(elapsed)))
            previous = target
        goal.trajectory.header.stamp = rospy.Time.now()
        return goal

    def start(self, userdata, limb, points, speed, timeout):
        limb_interface = baxter_interface.Limb(limb)
        self._client = actionlib.SimpleActionClient(
            'robot/limb/' + limb + '/follow_joint_trajectory', FollowJointTrajectoryAction)
        if not self._client.wait_for_server(rospy.Duration(timeout)):
            return 'aborted'
        self._client.send_goal(self.goal(limb_interface, points, speed))
        self._deadline = rospy.get_time() + timeout * len(points)
        return None

    def poll(self, userdata):
        if self._client.wait_for_result(rospy.Duration(0.0)):
            result = self._client.get_result()
            done = (result is not None
                    and result.error_code == FollowJointTrajectoryResult.SUCCESSFUL)
            return 'succeeded' if done else 'aborted'
        if rospy.get_time() > self._deadline:
            self._client.cancel_goal()
            return 'aborted'
        return None

    def on_exit(self, userdata):
        if self._outcome is None and getattr(self, '_client', None) is not None:
            self._client.cancel_goal()
{% do defined_headers.append('class_FollowJointTrajActionState') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
{%- set arguments = [] %}
{%- set keys = [] %}
{%- if limb is defined %}{% do arguments.append(text_argument('limb', limb)) %}{% else %}{% do keys.append('limb') %}{% endif %}
{%- if points is defined %}{% do arguments.append(data_argument('points', points)) %}{% else %}{% do keys.append('points') %}{% endif %}
{%- if speed is defined %}{% do arguments.append(data_argument('speed', speed | float)) %}{% endif %}
{%- if timeout is defined %}{% do arguments.append(data_argument('timeout', timeout | float)) %}{% endif %}
{{ render_baxter_add(defined_headers, default_module, state_class, name, arguments, keys, [], transitions, autonomy, remapping) }}
{% endblock body %}
