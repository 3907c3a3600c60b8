#!/usr/bin/env python

import rospy
import smach

import baxter_interface
import os
import rospkg
from geometry_msgs.msg import Point
from geometry_msgs.msg import Pose
from geometry_msgs.msg import Quaternion
from gazebo_msgs.srv import DeleteModel
from gazebo_msgs.srv import SpawnModel

from geometry_msgs.msg import PoseStamped
from std_msgs.msg import Header
from baxter_core_msgs.srv import SolvePositionIK
from baxter_core_msgs.srv import SolvePositionIKRequest


class BaxterState(smach.State):
    """A Baxter state: outcomes succeeded, aborted, preempted. Each argument named in
    input_keys is read from the userdata key of that name instead."""

    def __init__(self, arguments, input_keys=(), output_keys=()):
        smach.State.__init__(self, outcomes=['succeeded', 'aborted', 'preempted'],
                             input_keys=list(input_keys), output_keys=list(output_keys))
        self._arguments = dict(arguments)

    def arguments(self, userdata):
        values = dict(self._arguments)
        for key in self.get_registered_input_keys():
            values[key] = getattr(userdata, key)
        return values

    def execute(self, userdata):
        if self.preempt_requested():
            self.service_preempt()
            return 'preempted'
        try:
            return self.run(userdata, **self.arguments(userdata))
        except Exception as error:  # ROS, a missing key, malformed data: an outcome
            rospy.logerr('%s: %s', type(self).__name__, error)
            return 'aborted'

    def run(self, userdata, **arguments):
        raise NotImplementedError


def baxter_pose_parts(pose):
    """([x, y, z], [qx, qy, qz, qw]) of a pose given nested, flat or as a position."""
    flat = [float(v) for v in (list(pose[0]) + list(pose[1]) if len(pose) == 2 else pose)]
    if len(flat) == 3:
        flat += [0.0, 0.0, 0.0, 0.0]
    if len(flat) != 7:
        raise ValueError('a pose is [[x, y, z], [qx, qy, qz, qw]], not %r' % (pose,))
    return flat[:3], flat[3:]


def baxter_quaternion_product(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz]


def baxter_offset_pose(pose, offset):
    """The pose moved by the offset's position, then turned by its rotation (if any)."""
    position, rotation = baxter_pose_parts(pose)
    shift, turn = baxter_pose_parts(offset)
    position = [p + s for p, s in zip(position, shift)]
    if any(turn):
        rotation = baxter_quaternion_product(rotation, turn)
    return [position, rotation]


def baxter_pose_msg(pose):
    position, rotation = baxter_pose_parts(pose)
    if not any(rotation):
        rotation = [0.0, 0.0, 0.0, 1.0]
    return Pose(position=Point(*position), orientation=Quaternion(*rotation))


class LoadGazeboModelState(BaxterState):
    """Spawns a Gazebo model at a pose, replacing any model of the same name."""

    MODEL_FILES = {'table': 'cafe_table/model.sdf', 'block': 'block/model.urdf'}
    FRAMES = {'base': 'baxter::base'}
    SERVICE_TIMEOUT = 5.0  # seconds to wait for Gazebo's services

    def __init__(self, model_name, model_path=None, pose=None, reference_frame='world',
                 input_keys=()):
        BaxterState.__init__(self, dict(model_name=model_name, model_path=model_path, pose=pose,
                                        reference_frame=reference_frame), input_keys)

    def model_file(self, model_name):
        kind = model_name.rstrip('0123456789_')
        try:
            models = os.path.join(rospkg.RosPack().get_path('baxter_sim_examples'), 'models')
        except rospkg.ResourceNotFound as error:
            raise ValueError('no model_path and no baxter_sim_examples: %s' % error)
        return os.path.join(models, self.MODEL_FILES.get(kind, kind + '/model.urdf'))

    def call(self, service_name, service_type, *arguments, **fields):
        rospy.wait_for_service(service_name, self.SERVICE_TIMEOUT)
        return rospy.ServiceProxy(service_name, service_type)(*arguments, **fields)

    def run(self, userdata, model_name, model_path, pose, reference_frame):
        path = model_path or self.model_file(model_name)
        with open(path) as model_file:
            model_xml = model_file.read()
        self.call('/gazebo/delete_model', DeleteModel, model_name)
        kind = 'sdf' if path.endswith('.sdf') else 'urdf'
        response = self.call('/gazebo/spawn_%s_model' % kind, SpawnModel,
                             model_name=model_name, model_xml=model_xml, robot_namespace='/',
                             initial_pose=baxter_pose_msg(pose),
                             reference_frame=self.FRAMES.get(reference_frame, reference_frame))
        if not response.success:
            rospy.logerr('%s: %s', type(self).__name__, response.status_message)
        return 'succeeded' if response.success else 'aborted'

def baxter_joint_positions(limb_interface, positions):
    if isinstance(positions, dict):
        return dict(positions)
    names = limb_interface.joint_names()
    if len(positions) != len(names):
        raise ValueError('joint positions are %d angles, not %r' % (len(names), positions))
    return dict(zip(names, [float(q) for q in positions]))


class MoveToJointPositionsState(BaxterState):
    """Moves a limb to joint positions; aborted when it does not reach them in time."""

    TOLERANCE = 0.008726646  # rad per joint, the Baxter SDK's default threshold

    def __init__(self, limb=None, positions=None, speed=0.3, timeout=15.0, input_keys=()):
        BaxterState.__init__(self, dict(limb=limb, positions=positions, speed=speed,
                                        timeout=timeout), input_keys)

    def run(self, userdata, limb, positions, speed, timeout):
        limb_interface = baxter_interface.Limb(limb)
        goal = baxter_joint_positions(limb_interface, positions)
        limb_interface.set_joint_position_speed(speed)
        limb_interface.move_to_joint_positions(goal, timeout=timeout,
                                               threshold=self.TOLERANCE,
                                               test=self.preempt_requested)
        if self.preempt_requested():
            self.service_preempt()
            return 'preempted'
        angles = limb_interface.joint_angles()
        reached = all(abs(angles[joint] - angle) <= self.TOLERANCE
                      for joint, angle in goal.items())
        return 'succeeded' if reached else 'aborted'

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

class GripperInterfaceState(BaxterState):
    """Opens or closes a limb's gripper; aborted when an expected grasp closed on nothing."""

    def __init__(self, limb=None, command=None, expect_grasp=True, timeout=2.0, input_keys=()):
        BaxterState.__init__(self, dict(limb=limb, command=command, expect_grasp=expect_grasp,
                                        timeout=timeout), input_keys)

    def run(self, userdata, limb, command, expect_grasp, timeout):
        gripper = baxter_interface.Gripper(limb, baxter_interface.CHECK_VERSION)
        if not gripper.calibrated():
            gripper.calibrate()
        if command == 'open':
            gripper.open(block=True, timeout=timeout)
            return 'succeeded'
        if command == 'close':
            gripper.close(block=True, timeout=timeout)
            return 'aborted' if expect_grasp and not gripper.gripping() else 'succeeded'
        raise ValueError('a gripper command is open or close, not %r' % (command,))


class ReadEndpointPoseState(BaxterState):
    """Writes a limb's endpoint pose, [[x, y, z], [qx, qy, qz, qw]], to pose."""

    def __init__(self, limb=None, input_keys=()):
        BaxterState.__init__(self, dict(limb=limb), input_keys, output_keys=['pose'])

    def run(self, userdata, limb):
        endpoint = baxter_interface.Limb(limb).endpoint_pose()
        position, orientation = endpoint['position'], endpoint['orientation']
        userdata.pose = [[position.x, position.y, position.z],
                         [orientation.x, orientation.y, orientation.z, orientation.w]]
        return 'succeeded'


def main():
    rospy.init_node('sm')
    robot = baxter_interface.RobotEnable(baxter_interface.CHECK_VERSION)
    robot.enable()
    sm = smach.StateMachine(outcomes=['succeeded', 'aborted', 'preempted'])
    sm.userdata.hover_offset = [[0.0, 0.0, 0.15], [0.0, 0.0, 0.0, 0.0]]
    sm.userdata.limb = 'left'

    sm.userdata.table_model_pose_world = [[1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]]
    sm.userdata.table_model_ref_frame = 'world'

    sm.userdata.block_model_pick_pose = [[0.7, 0.15, -0.129], [-0.02496, 0.99965, 0.00738, 0.00486]]
    sm.userdata.block_model_place_pose = [[0.75, 0.0, -0.129], [-0.02496, 0.99965, 0.00738, 0.00486]]
    sm.userdata.block_model_pose_base = [[0.7, 0.15, -0.13], [0.0, 0.0, 0.0, 1.0]]
    sm.userdata.block_model_ref_frame = 'base'

    sm.userdata.joint_start_positions = [-0.08, -1.0, -1.19, 1.94, 0.67, 1.03, -0.5]

    with sm:
        smach.StateMachine.add('LOAD_TABLE_MODEL',
                               LoadGazeboModelState(model_name='table', input_keys=['pose', 'reference_frame']),
                               transitions={'succeeded':'LOAD_BLOCK_MODEL'},
                               remapping={'pose':'table_model_pose_world',
                                          'reference_frame':'table_model_ref_frame'})

        smach.StateMachine.add('LOAD_BLOCK_MODEL',
                               LoadGazeboModelState(model_name='block1', input_keys=['pose', 'reference_frame']),
                               transitions={'succeeded':'MOVE_TO_START_POSITION'},
                               remapping={'pose':'block_model_pose_base',
                                          'reference_frame':'block_model_ref_frame'})

        smach.StateMachine.add('MOVE_TO_START_POSITION',
                               MoveToJointPositionsState(input_keys=['limb', 'positions']),
                               transitions={'succeeded':'PICK_BLOCK'},
                               remapping={'positions':'joint_start_positions'})

        sm_pick_block = smach.StateMachine(outcomes=['succeeded', 'aborted', 'preempted'],
                                             input_keys = ['limb', 'pick_pose', 'hover_offset'])

        with sm_pick_block:
            smach.StateMachine.add('IK_PICK_BLOCK_HOVER_POSE',
                                   PoseToJointTrajServiceState(input_keys=['limb', 'poses', 'offsets']),
                                   transitions={'succeeded':'MOVE_TO_PICK_BLOCK_HOVER_POSE'},
                                   remapping={'joints':'ik_joint_response_block_pick_hover_pose',
                                              'offsets':'hover_offset',
                                              'poses':'pick_pose'})

            smach.StateMachine.add('MOVE_TO_PICK_BLOCK_HOVER_POSE',
                                   MoveToJointPositionsState(input_keys=['limb', 'positions']),
                                   transitions={'succeeded':'OPEN_GRIPPER'},
                                   remapping={'positions':'ik_joint_response_block_pick_hover_pose'})

            smach.StateMachine.add('OPEN_GRIPPER',
                                   GripperInterfaceState(command='open', input_keys=['limb']),
                                   transitions={'succeeded':'IK_PICK_BLOCK_GRIP_POSE'})

            smach.StateMachine.add('IK_PICK_BLOCK_GRIP_POSE',
                                   PoseToJointTrajServiceState(input_keys=['limb', 'poses']),
                                   transitions={'succeeded':'MOVE_TO_PICK_BLOCK_GRIP_POSE'},
                                   remapping={'joints':'ik_joint_response_block_pick_pose',
                                              'poses':'pick_pose'})

            smach.StateMachine.add('MOVE_TO_PICK_BLOCK_GRIP_POSE',
                                   MoveToJointPositionsState(input_keys=['limb', 'positions']),
                                   transitions={'succeeded':'CLOSE_GRIPPER'},
                                   remapping={'positions':'ik_joint_response_block_pick_pose'})

            smach.StateMachine.add('CLOSE_GRIPPER',
                                   GripperInterfaceState(command='close', input_keys=['limb']),
                                   transitions={'succeeded':'MOVE_TO_GRIPPED_BLOCK_HOVER_POSE'})

            smach.StateMachine.add('MOVE_TO_GRIPPED_BLOCK_HOVER_POSE',
                                   MoveToJointPositionsState(input_keys=['limb', 'positions']),
                                   transitions={'succeeded':'succeeded'},
                                   remapping={'positions':'ik_joint_response_block_pick_hover_pose'})



        smach.StateMachine.add('PICK_BLOCK', sm_pick_block,
                               transitions={'succeeded':'PLACE_BLOCK'},
                               remapping={'pick_pose':'block_model_pick_pose'})

        sm_place_block = smach.StateMachine(outcomes=['succeeded', 'aborted', 'preempted'],
                                             input_keys = ['limb', 'place_pose', 'hover_offset'])

        with sm_place_block:
            smach.StateMachine.add('IK_PLACE_BLOCK_HOVER_POSE',
                                   PoseToJointTrajServiceState(input_keys=['limb', 'poses', 'offsets']),
                                   transitions={'succeeded':'MOVE_TO_PLACE_BLOCK_HOVER_POSE'},
                                   remapping={'joints':'ik_joint_response_block_place_hover_pose',
                                              'offsets':'hover_offset',
                                              'poses':'place_pose'})

            smach.StateMachine.add('MOVE_TO_PLACE_BLOCK_HOVER_POSE',
                                   MoveToJointPositionsState(input_keys=['limb', 'positions']),
                                   transitions={'succeeded':'IK_PLACE_BLOCK_RELEASE_POSE'},
                                   remapping={'positions':'ik_joint_response_block_place_hover_pose'})

            smach.StateMachine.add('IK_PLACE_BLOCK_RELEASE_POSE',
                                   PoseToJointTrajServiceState(input_keys=['limb', 'poses']),
                                   transitions={'succeeded':'MOVE_TO_PLACE_BLOCK_RELEASE_POSE'},
                                   remapping={'joints':'ik_joint_response_block_place_pose',
                                              'poses':'place_pose'})

            smach.StateMachine.add('MOVE_TO_PLACE_BLOCK_RELEASE_POSE',
                                   MoveToJointPositionsState(input_keys=['limb', 'positions']),
                                   transitions={'succeeded':'OPEN_GRIPPER'},
                                   remapping={'positions':'ik_joint_response_block_place_pose'})

            smach.StateMachine.add('OPEN_GRIPPER',
                                   GripperInterfaceState(command='open', input_keys=['limb']),
                                   transitions={'succeeded':'READ_RELEASED_BLOCK_ENDPOINT_POSE'})

            smach.StateMachine.add('READ_RELEASED_BLOCK_ENDPOINT_POSE',
                                   ReadEndpointPoseState(input_keys=['limb']),
                                   transitions={'succeeded':'IK_RELEASED_BLOCK_HOVER_POSE'},
                                   remapping={'pose':'released_block_endpoint_pose'})

            smach.StateMachine.add('IK_RELEASED_BLOCK_HOVER_POSE',
                                   PoseToJointTrajServiceState(input_keys=['limb', 'poses', 'offsets']),
                                   transitions={'succeeded':'MOVE_TO_RELEASED_BLOCK_HOVER_POSE'},
                                   remapping={'joints':'ik_joint_response_released_block_hover_pose',
                                              'offsets':'hover_offset',
                                              'poses':'released_block_endpoint_pose'})

            smach.StateMachine.add('MOVE_TO_RELEASED_BLOCK_HOVER_POSE',
                                   MoveToJointPositionsState(input_keys=['limb', 'positions']),
                                   transitions={'succeeded':'succeeded'},
                                   remapping={'positions':'ik_joint_response_released_block_hover_pose'})



        smach.StateMachine.add('PLACE_BLOCK', sm_place_block,
                               transitions={'succeeded':'succeeded'},
                               remapping={'place_pose':'block_model_place_pose'})


    outcome = sm.execute()
    rospy.loginfo('outcome: %s', outcome)


if __name__ == '__main__':
    main()
