"""Baxter's joint trajectory action, robot/limb/<side>/follow_joint_trajectory
(control_msgs/FollowJointTrajectory), over the simulation: the arm is commanded along the
trajectory, interpolating linearly between its points by their time_from_start, then must
settle within the goal tolerance (Baxter's default 0.0087 rad per joint) in the goal time
tolerance (default 5 s). A cancel holds the arm where it is."""
import actionlib
import rospy
from control_msgs.msg import FollowJointTrajectoryAction, FollowJointTrajectoryResult

SIDES = ("left", "right")
PERIOD = 0.01  # s of simulated time between two commands
TOLERANCE = 0.008726646
GOAL_TIME = 5.0


class TrajectoryAction:
    def __init__(self, robot, topics):
        self.robot = robot
        self.topics = topics
        self.servers = {}
        for side in SIDES:
            self.servers[side] = actionlib.SimpleActionServer(
                "robot/limb/%s/follow_joint_trajectory" % side, FollowJointTrajectoryAction,
                execute_cb=lambda goal, side=side: self.execute(goal, side), auto_start=False)
            self.servers[side].start()

    def execute(self, goal, side):
        server = self.servers[side]
        names = self.robot.joint_names(side)
        trajectory = goal.trajectory
        if sorted(trajectory.joint_names) != sorted(names) or not trajectory.points:
            return server.set_aborted(FollowJointTrajectoryResult(
                error_code=FollowJointTrajectoryResult.INVALID_JOINTS,
                error_string="the trajectory must name the 7 joints of the %s arm" % side))
        order = [trajectory.joint_names.index(name) for name in names]
        points = [([point.positions[i] for i in order], point.time_from_start.to_sec())
                  for point in trajectory.points]
        outcome = self.follow(server, side, points)
        result = FollowJointTrajectoryResult(error_code=outcome)
        if outcome == FollowJointTrajectoryResult.SUCCESSFUL:
            server.set_succeeded(result)
        elif server.is_preempt_requested():
            server.set_preempted(result)
        else:
            server.set_aborted(result)

    def follow(self, server, side, points):
        start = self.robot.time()
        deadline = points[-1][1] + goal_time(server)
        points = [(self.robot.joint_state(side)[0], 0.0)] + points
        while not rospy.is_shutdown():
            if server.is_preempt_requested():
                self.topics.command(side, self.robot.joint_state(side)[0], 1.0)
                return FollowJointTrajectoryResult.GOAL_TOLERANCE_VIOLATED
            elapsed = self.robot.time() - start
            self.topics.command(side, interpolate(points, elapsed), 1.0)
            if elapsed >= points[-1][1] and self.settled(side, points[-1][0]):
                return FollowJointTrajectoryResult.SUCCESSFUL
            if elapsed > deadline:
                return FollowJointTrajectoryResult.GOAL_TOLERANCE_VIOLATED
            rospy.sleep(PERIOD)
        return FollowJointTrajectoryResult.GOAL_TOLERANCE_VIOLATED

    def settled(self, side, goal):
        position = self.robot.joint_state(side)[0]
        return all(abs(a - b) <= TOLERANCE for a, b in zip(position, goal))


def goal_time(server):
    tolerance = server.current_goal.get_goal().goal_time_tolerance.to_sec()
    return tolerance if tolerance > 0.0 else GOAL_TIME


def interpolate(points, elapsed):
    """The commanded positions `elapsed` seconds into the trajectory (points start at 0)."""
    for (before, since), (after, at) in zip(points, points[1:]):
        if elapsed < at:
            return blend(before, after, (elapsed - since) / (at - since))
    return points[-1][0]


def blend(a, b, fraction):
    return [x + (y - x) * fraction for x, y in zip(a, b)]
