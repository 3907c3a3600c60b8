#!/usr/bin/env python

import roslib
import rospy
import smach
import smach_ros
import sensor_msgs.point_cloud2
from geometry_msgs.msg import Point32
from geometry_msgs.msg import Pose
from sensor_msgs.msg import JointState
from sensor_msgs.msg import PointCloud
from trajectory_msgs.msg import JointTrajectoryPoint







from sensor_msgs.msg import PointCloud2
from sensor_msgs import point_cloud2 as pc2







from sensor_msgs.point_cloud2 import create_cloud_xyz32






from geometry_msgs.msg import Point

from geometry_msgs.msg import PointStamped






from geometry_msgs.msg import PoseStamped














from geometry_msgs.msg import PoseArray





















from geometry_msgs.msg import Transform
from geometry_msgs.msg import TransformStamped


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








def parse_pointcloud2(pointcloud_input):
    """A PointCloud2 from a PointCloud2 (as it is) or a PointCloud (its points)."""
    if isinstance(pointcloud_input, PointCloud2):
        return pointcloud_input
    if not isinstance(pointcloud_input, PointCloud):
        raise ValueError('not a point cloud (PointCloud2 or PointCloud): '
                         '{!r}'.format(pointcloud_input))
    return create_cloud_xyz32(pointcloud_input.header,
                              [[p.x, p.y, p.z] for p in pointcloud_input.points])








def parse_pointstamped(point_input):
    """A PointStamped from a PointStamped (as it is), a Point, a Point32 or [x, y, z]."""
    if isinstance(point_input, PointStamped):
        return point_input
    if isinstance(point_input, (Point, Point32)):
        coordinates = [point_input.x, point_input.y, point_input.z]
    else:
        coordinates = []
        if isinstance(point_input, (list, tuple)):
            try:
                coordinates = [float(value) for value in point_input]
            except (TypeError, ValueError):
                coordinates = []
        if len(coordinates) != 3:
            raise ValueError('not a point (PointStamped, Point, Point32 or [x, y, z]): '
                             '{!r}'.format(point_input))
    stamped = PointStamped()
    stamped.point.x, stamped.point.y, stamped.point.z = coordinates
    if rospy.rostime.is_rostime_initialized():
        stamped.header.stamp = rospy.Time.now()
    return stamped








def parse_pose(pose_input):
    """A Pose from a Pose (as it is), a PoseStamped (its pose) or [position, quaternion]."""
    if isinstance(pose_input, Pose):
        return pose_input
    if isinstance(pose_input, PoseStamped):
        return pose_input.pose
    position = orientation = []
    if isinstance(pose_input, (list, tuple)) and len(pose_input) == 2:
        try:
            position = [float(value) for value in pose_input[0]]
            orientation = [float(value) for value in pose_input[1]]
        except (TypeError, ValueError):
            position = orientation = []
    if len(position) != 3 or len(orientation) != 4:
        raise ValueError('not a pose (Pose, PoseStamped or [[x, y, z], [qx, qy, qz, qw]]): '
                         '{!r}'.format(pose_input))
    pose = Pose()
    pose.position.x, pose.position.y, pose.position.z = position
    pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w = orientation
    return pose















def parse_posearray(posearray_input):
    """A PoseArray from a PoseArray (as it is) or a list of poses (see parse_pose)."""
    if isinstance(posearray_input, PoseArray):
        return posearray_input
    if not isinstance(posearray_input, (list, tuple)):
        raise ValueError('not a pose array (PoseArray or a list of poses): '
                         '{!r}'.format(posearray_input))
    posearray = PoseArray(poses=[parse_pose(pose) for pose in posearray_input])
    if rospy.rostime.is_rostime_initialized():
        posearray.header.stamp = rospy.Time.now()
    return posearray















def parse_posestamped(pose_input):
    """A PoseStamped from a PoseStamped (as it is), a Pose or [position, quaternion]."""
    if isinstance(pose_input, PoseStamped):
        return pose_input
    stamped = PoseStamped(pose=parse_pose(pose_input))
    if rospy.rostime.is_rostime_initialized():
        stamped.header.stamp = rospy.Time.now()
    return stamped








def parse_transformstamped(transform_input):
    """A TransformStamped from a TransformStamped (as it is), a Transform or
    [[x, y, z], [qx, qy, qz, qw]]."""
    if isinstance(transform_input, TransformStamped):
        return transform_input
    if isinstance(transform_input, Transform):
        stamped = TransformStamped(transform=transform_input)
    else:
        translation = rotation = []
        if isinstance(transform_input, (list, tuple)) and len(transform_input) == 2:
            try:
                translation = [float(value) for value in transform_input[0]]
                rotation = [float(value) for value in transform_input[1]]
            except (TypeError, ValueError):
                translation = rotation = []
        if len(translation) != 3 or len(rotation) != 4:
            raise ValueError('not a transform (TransformStamped, Transform or '
                             '[[x, y, z], [qx, qy, qz, qw]]): {!r}'.format(transform_input))
        stamped = TransformStamped()
        t, r = stamped.transform.translation, stamped.transform.rotation
        t.x, t.y, t.z = translation
        r.x, r.y, r.z, r.w = rotation
    if rospy.rostime.is_rostime_initialized():
        stamped.header.stamp = rospy.Time.now()
    return stamped
















def parse_fails(parser, value):
    """Whether parser rejects value with a ValueError."""
    try:
        parser(value)
    except ValueError:
        return True
    return False


class CallbacksState(smach.State):
    """Runs its callbacks on the userdata, then succeeds."""

    def __init__(self, input_keys=[], output_keys=[], callbacks=[], outcomes=['succeeded']):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=outcomes)
        
        self._cbs = []
        for cb_name in (callbacks or []):
            if cb_name in globals():
                self._cbs.append(globals()[cb_name])

        self._cb_input_keys = []
        self._cb_output_keys = []
        self._cb_outcomes = []
        for cb in self._cbs:
            if cb and smach.has_smach_interface(cb):
                self._cb_input_keys.append(cb.get_registered_input_keys())
                self._cb_output_keys.append(cb.get_registered_output_keys())
                self._cb_outcomes.append(cb.get_registered_outcomes())
                self.register_input_keys(self._cb_input_keys[-1])
                self.register_output_keys(self._cb_output_keys[-1])
                self.register_outcomes(self._cb_outcomes[-1])


    def execute(self, userdata):
        
        # Call the callbacks
        for (cb, input_keys, output_keys) in zip(self._cbs,
                                                 self._cb_input_keys,
                                                 self._cb_output_keys):
            cb(smach.Remapper(userdata, input_keys, output_keys, {}))

        return 'succeeded'




class ParsingState(CallbacksState):
    """A CallbacksState (its callbacks call the parse_* functions)."""

class ConditionalOutcomeState(smach.State):
    """Ends with the first outcome whose callback output is true, else `default`."""

    def __init__(self, input_keys=[], output_keys=[], callbacks=[], outcomes=[]):
        # Each condition's callback writes the key named like the outcome, which execute()
        # then reads: it is both an output and an input key.
        self._conditions = [o for o in outcomes if o != 'default']
        input_keys = list(input_keys) + [o for o in self._conditions if o not in input_keys]
        output_keys = list(output_keys) + [o for o in self._conditions if o not in output_keys]
        if 'outcome' not in output_keys:
            output_keys.append('outcome')
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=self._conditions + ['default'])
        
        self._cbs = []
        for cb_name in (callbacks or []):
            if cb_name in globals():
                self._cbs.append(globals()[cb_name])

        self._cb_input_keys = []
        self._cb_output_keys = []
        self._cb_outcomes = []
        for cb in self._cbs:
            if cb and smach.has_smach_interface(cb):
                self._cb_input_keys.append(cb.get_registered_input_keys())
                self._cb_output_keys.append(cb.get_registered_output_keys())
                self._cb_outcomes.append(cb.get_registered_outcomes())
                self.register_input_keys(self._cb_input_keys[-1])
                self.register_output_keys(self._cb_output_keys[-1])
                self.register_outcomes(self._cb_outcomes[-1])


    def execute(self, userdata):
        
        # Call the callbacks
        for (cb, input_keys, output_keys) in zip(self._cbs,
                                                 self._cb_input_keys,
                                                 self._cb_output_keys):
            cb(smach.Remapper(userdata, input_keys, output_keys, {}))

        for outcome in self._conditions:
            if outcome in userdata and userdata[outcome]:
                userdata.outcome = outcome
                return outcome
        userdata.outcome = 'default'
        return 'default'


@smach.cb_interface(input_keys=['xyz', 'pose_list', 'joint_state', 'cloud'],
                    output_keys=['point'],
                    outcomes=[])
def point_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb(userdata):
    lambda_cb = lambda ud: parse_pointstamped(ud.xyz)
    userdata.point = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['xyz', 'pose_list', 'joint_state', 'cloud'],
                    output_keys=['pose'],
                    outcomes=[])
def pose_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb(userdata):
    lambda_cb = lambda ud: parse_pose(ud.pose_list)
    userdata.pose = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['xyz', 'pose_list', 'joint_state', 'cloud'],
                    output_keys=['pose_stamped'],
                    outcomes=[])
def pose_stamped_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb(userdata):
    lambda_cb = lambda ud: parse_posestamped(parse_pose(ud.pose_list))
    userdata.pose_stamped = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['xyz', 'pose_list', 'joint_state', 'cloud'],
                    output_keys=['pose_array'],
                    outcomes=[])
def pose_array_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb(userdata):
    lambda_cb = lambda ud: parse_posearray([ud.pose_list, Pose(), parse_posestamped(ud.pose_list)])
    userdata.pose_array = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['xyz', 'pose_list', 'joint_state', 'cloud'],
                    output_keys=['transform'],
                    outcomes=[])
def transform_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb(userdata):
    lambda_cb = lambda ud: parse_transformstamped(ud.pose_list)
    userdata.transform = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['xyz', 'pose_list', 'joint_state', 'cloud'],
                    output_keys=['joints'],
                    outcomes=[])
def joints_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb(userdata):
    lambda_cb = lambda ud: parse_jointtrajectorypoint(ud.joint_state)
    userdata.joints = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['xyz', 'pose_list', 'joint_state', 'cloud'],
                    output_keys=['positions'],
                    outcomes=[])
def positions_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb(userdata):
    lambda_cb = lambda ud: parse_jointtrajectorypoint([0.5, 1.5])
    userdata.positions = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['xyz', 'pose_list', 'joint_state', 'cloud'],
                    output_keys=['cloud2'],
                    outcomes=[])
def cloud2_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb(userdata):
    lambda_cb = lambda ud: parse_pointcloud2(ud.cloud)
    userdata.cloud2 = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['xyz', 'pose_list', 'joint_state', 'cloud'],
                    output_keys=['cloud_back'],
                    outcomes=[])
def cloud_back_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb(userdata):
    lambda_cb = lambda ud: parse_pointcloud(parse_pointcloud2(ud.cloud))
    userdata.cloud_back = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['xyz', 'pose_list', 'joint_state', 'cloud'],
                    output_keys=['rejected'],
                    outcomes=[])
def rejected_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb(userdata):
    lambda_cb = lambda ud: [parse_fails(parser, value) for parser, value in [(parse_pointstamped, [1.0, 2.0]), (parse_pointstamped, "123"), (parse_pose, [[1.0, 2.0, 3.0], [0.0, 0.0, 1.0]]), (parse_posestamped, "pose"), (parse_posearray, Pose()), (parse_posearray, [[1.0, 2.0]]), (parse_transformstamped, [1.0, 2.0, 3.0]), (parse_transformstamped, Pose()), (parse_jointtrajectorypoint, ["a"]), (parse_pointcloud, [1.0, 2.0, 3.0]), (parse_pointcloud2, Pose())]]
    userdata.rejected = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['point', 'pose', 'pose_stamped', 'pose_array', 'transform', 'joints', 'positions', 'cloud2', 'cloud_back', 'rejected'],
                    output_keys=['problems'],
                    outcomes=[])
def problems_check_8df28351c3554c2c9e6f0da1c44b266a_lambda_cb(userdata):
    lambda_cb = lambda ud: [name for name, holds in [("point", [ud.point.point.x, ud.point.point.y, ud.point.point.z] == [1.0, 2.0, 3.0] and ud.point.header.stamp.to_sec() > 0), ("pose", [ud.pose.position.z, ud.pose.orientation.z, ud.pose.orientation.w] == [3.0, 0.6, 0.8]), ("pose_stamped", ud.pose_stamped.pose.position.y == 2.0 and ud.pose_stamped.header.stamp.to_sec() > 0), ("pose_array", [p.position.x for p in ud.pose_array.poses] == [1.0, 0.0, 1.0]), ("transform", [ud.transform.transform.translation.x, ud.transform.transform.rotation.w] == [1.0, 0.8]), ("joints", [list(ud.joints.positions), list(ud.joints.velocities), list(ud.joints.effort)] == [[0.1, 0.2], [1.0, 2.0], [5.0, 6.0]]), ("positions", list(ud.positions.positions) == [0.5, 1.5]), ("cloud2", list(sensor_msgs.point_cloud2.read_points(ud.cloud2)) == [(1.0, 2.0, 3.0), (4.0, 5.0, 6.0)]), ("cloud_back", [(p.x, p.y, p.z) for p in ud.cloud_back.points] == [(1.0, 2.0, 3.0), (4.0, 5.0, 6.0)]), ("rejected", ud.rejected == [True] * 11)] if not holds]
    userdata.problems = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['problems'],
                    output_keys=['ok'],
                    outcomes=['ok', 'default'])
def ok_verdict_e5d0eb5d5a3945238cd495f673b87df0_lambda_cb(userdata):
    lambda_cb = lambda ud: ud.problems == []
    userdata.ok = lambda_cb(userdata)
    return 'succeeded'


def main():
    rospy.init_node('ros_parsers')
    ros_parsers = smach.StateMachine(outcomes=['done', 'wrong'])
    ros_parsers.userdata.cloud = PointCloud(points=[Point32(x=1.0, y=2.0, z=3.0), Point32(x=4.0, y=5.0, z=6.0)])
    ros_parsers.userdata.joint_state = JointState(position=[0.1, 0.2], velocity=[1.0, 2.0], effort=[5.0, 6.0])
    ros_parsers.userdata.pose_list = [[1.0, 2.0, 3.0], [0.0, 0.0, 0.6, 0.8]]
    ros_parsers.userdata.xyz = [1.0, 2.0, 3.0]


    with ros_parsers:
        smach.StateMachine.add('PARSE',
                               ParsingState(input_keys = ['xyz', 'pose_list', 'joint_state', 'cloud'], output_keys = ['point', 'pose', 'pose_stamped', 'pose_array', 'transform', 'joints', 'positions', 'cloud2', 'cloud_back', 'rejected'], callbacks = ['point_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb', 'pose_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb', 'pose_stamped_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb', 'pose_array_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb', 'transform_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb', 'joints_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb', 'positions_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb', 'cloud2_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb', 'cloud_back_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb', 'rejected_parse_35ce55b136154a89bd5e60e4a7fe177c_lambda_cb']),
                               transitions={'succeeded':'CHECK'})

        smach.StateMachine.add('CHECK',
                               CallbacksState(input_keys = ['point', 'pose', 'pose_stamped', 'pose_array', 'transform', 'joints', 'positions', 'cloud2', 'cloud_back', 'rejected'], output_keys = ['problems'], callbacks = ['problems_check_8df28351c3554c2c9e6f0da1c44b266a_lambda_cb']),
                               transitions={'succeeded':'VERDICT'})

        smach.StateMachine.add('VERDICT',
                               ConditionalOutcomeState(input_keys = ['problems'], callbacks = ['ok_verdict_e5d0eb5d5a3945238cd495f673b87df0_lambda_cb'], outcomes=['ok', 'default']),
                               transitions={'default':'wrong',
                                            'ok':'done'})

    outcome = ros_parsers.execute()


if __name__ == '__main__':
    main()
