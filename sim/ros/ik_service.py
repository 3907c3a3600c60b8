"""Baxter's IK service, ExternalTools/<side>/PositionKinematicsNode/IKService
(baxter_core_msgs/SolvePositionIK), answered by the simulation's solver: for each requested
pose (Baxter's base frame), joint positions seeded from the arm's current ones, or isValid
false when the pose is out of reach."""
import rospy
from baxter_core_msgs.srv import SolvePositionIK, SolvePositionIKRequest, SolvePositionIKResponse
from sensor_msgs.msg import JointState

SIDES = ("left", "right")
BASE_FRAMES = ("", "base", "/base")


class IkService:
    def __init__(self, robot):
        self.robot = robot
        for side in SIDES:
            rospy.Service("ExternalTools/%s/PositionKinematicsNode/IKService" % side,
                          SolvePositionIK, lambda request, side=side: self.solve(request, side))

    def solve(self, request, side):
        response = SolvePositionIKResponse()
        names = self.robot.joint_names(side)
        for stamped in request.pose_stamp:
            solved, joints = False, [0.0] * len(names)
            if stamped.header.frame_id in BASE_FRAMES:
                p, o = stamped.pose.position, stamped.pose.orientation
                solved, joints = self.robot.solve_ik(side, [p.x, p.y, p.z, o.x, o.y, o.z, o.w])
            else:
                rospy.logwarn("IK: poses are solved in the base frame, not %r",
                              stamped.header.frame_id)
            response.joints.append(JointState(name=names, position=joints))
            response.isValid.append(solved)
            # the seed that found the solution: always the current positions
            response.result_type += bytes([SolvePositionIKRequest.SEED_CURRENT if solved
                                           else SolvePositionIKResponse.RESULT_INVALID])
        return response
