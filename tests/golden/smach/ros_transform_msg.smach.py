#!/usr/bin/env python

import roslib
import rospy
import smach
import smach_ros
import sensor_msgs.point_cloud2
from geometry_msgs.msg import Point32
from sensor_msgs.msg import PointCloud
from std_msgs.msg import Header
import genpy
import roslib.message






from geometry_msgs.msg import Transform
from geometry_msgs.msg import TransformStamped






from geometry_msgs.msg import Point

from geometry_msgs.msg import PointStamped







from geometry_msgs.msg import Pose
from geometry_msgs.msg import PoseStamped




















from geometry_msgs.msg import PoseArray






from sensor_msgs.msg import PointCloud2
from sensor_msgs.point_cloud2 import create_cloud_xyz32






import tf2_ros











import copy
import tf2_geometry_msgs
import tf2_sensor_msgs


def parse_msg(msg, parsers, msg_type=None):
    """msg as a message, through parsers, a list of (message class, parse function) pairs.
    With msg_type (a type name such as geometry_msgs/PoseStamped) the parser of that type
    converts msg (ValueError when it cannot); a message of a class in parsers goes through
    its parser, any other message is returned as it is; anything else (a list) goes through
    the first parser that accepts it, else ValueError."""
    if msg_type:
        msg_class = roslib.message.get_message_class(msg_type)
        if msg_class is None:
            raise ValueError('unknown message type {}'.format(msg_type))
        for parsed_class, parser in parsers:
            if parsed_class is msg_class:
                return parser(msg)
        if isinstance(msg, msg_class):
            return msg
        raise ValueError('{!r} is not a {}'.format(msg, msg_type))
    for parsed_class, parser in parsers:
        if isinstance(msg, parsed_class):
            return parser(msg)
    if isinstance(msg, genpy.Message):
        return msg
    for _, parser in parsers:
        try:
            return parser(msg)
        except ValueError:
            pass
    raise ValueError('cannot make a message of {!r}'.format(msg))








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







def parse_posestamped(pose_input):
    """A PoseStamped from a PoseStamped (as it is), a Pose or [position, quaternion]."""
    if isinstance(pose_input, PoseStamped):
        return pose_input
    stamped = PoseStamped(pose=parse_pose(pose_input))
    if rospy.rostime.is_rostime_initialized():
        stamped.header.stamp = rospy.Time.now()
    return stamped















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








def parse_pointcloud2(pointcloud_input):
    """A PointCloud2 from a PointCloud2 (as it is) or a PointCloud (its points)."""
    if isinstance(pointcloud_input, PointCloud2):
        return pointcloud_input
    if not isinstance(pointcloud_input, PointCloud):
        raise ValueError('not a point cloud (PointCloud2 or PointCloud): '
                         '{!r}'.format(pointcloud_input))
    return create_cloud_xyz32(pointcloud_input.header,
                              [[p.x, p.y, p.z] for p in pointcloud_input.points])


class TF2ListenerSingleton(object):
    """The script's one tf2_ros buffer and listener, created on first use."""
    _buffer = None
    _listener = None

    @classmethod
    def get(cls):
        if cls._buffer is None:
            cls._buffer = tf2_ros.Buffer()
            cls._listener = tf2_ros.TransformListener(cls._buffer)
        return cls._buffer, cls._listener
















class TransformMsgState(smach.State):
    """Transforms the `msg` input into the `frame_id` (or `target`) frame, by TF2 or by the
    `transform` input; aborts when the message or the transform cannot be had."""

    def __init__(self, transform_type='transform', input_keys=['msg', 'frame_id'],
                 output_keys=['output_msg'], callbacks=[], timeout=None):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded', 'aborted'])
        self._transform_type = transform_type
        self._timeout = timeout
        self._buffer, _ = TF2ListenerSingleton.get()
        # Points, poses and clouds are transformed stamped (tf2_geometry_msgs, tf2_sensor_msgs).
        self._parsers = [(PointStamped, parse_pointstamped), (Point, parse_pointstamped),
                         (PoseStamped, parse_posestamped), (Pose, parse_posestamped),
                         (PoseArray, parse_posearray), (PointCloud2, parse_pointcloud2),
                         (PointCloud, parse_pointcloud2)]
        
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


    def _lookup(self, target, source):
        """The transform from source to target on TF2, waiting for it up to the timeout."""
        deadline = None if self._timeout is None else rospy.get_time() + self._timeout
        while not rospy.is_shutdown() and not self.preempt_requested():
            if self._buffer.can_transform(target, source, rospy.Time(0), rospy.Duration(0.05)):
                return self._buffer.lookup_transform(target, source, rospy.Time(0))
            if deadline is not None and rospy.get_time() >= deadline:
                break
        raise RuntimeError('no transform from {} to {}'.format(source, target))

    def _transform(self, userdata, msg):
        if 'transform' in self._input_keys:
            transform = copy.deepcopy(parse_transformstamped(userdata.transform))
        else:
            if 'frame_id' in self._input_keys:
                target = userdata.frame_id
            elif 'target' in self._input_keys:
                target = userdata.target
            else:
                raise ValueError('no target frame: give the input key frame_id or target')
            source = userdata.source if 'source' in self._input_keys else ''
            source = source or getattr(getattr(msg, 'header', None), 'frame_id', '')
            if not source:
                raise ValueError('no source frame: give the input key source or a header frame')
            transform = self._lookup(target, source)
        if self._transform_type == 'translation':
            r = transform.transform.rotation
            r.x, r.y, r.z, r.w = 0.0, 0.0, 0.0, 1.0
        elif self._transform_type == 'rotation':
            t = transform.transform.translation
            t.x, t.y, t.z = 0.0, 0.0, 0.0
        elif self._transform_type != 'transform':
            raise ValueError('unknown transform_type {}'.format(self._transform_type))
        return transform

    @staticmethod
    def _apply(msg, transform):
        if isinstance(msg, PointStamped):
            return tf2_geometry_msgs.do_transform_point(msg, transform)
        if isinstance(msg, PoseStamped):
            return tf2_geometry_msgs.do_transform_pose(msg, transform)
        if isinstance(msg, PointCloud2):
            return tf2_sensor_msgs.do_transform_cloud(msg, transform)
        if isinstance(msg, PoseArray):
            poses = [tf2_geometry_msgs.do_transform_pose(PoseStamped(msg.header, pose),
                                                         transform).pose for pose in msg.poses]
            return PoseArray(header=copy.deepcopy(transform.header), poses=poses)
        raise ValueError('cannot transform a {}'.format(type(msg).__name__))

    def execute(self, userdata):
        
        # Call the callbacks
        for (cb, input_keys, output_keys) in zip(self._cbs,
                                                 self._cb_input_keys,
                                                 self._cb_output_keys):
            cb(smach.Remapper(userdata, input_keys, output_keys, {}))

        try:
            msg_type = userdata.msg_type if 'msg_type' in self._input_keys else None
            msg = parse_msg(userdata.msg, self._parsers, msg_type)
            transform = self._transform(userdata, msg)
            transformed = self._apply(msg, transform)
        except Exception as e:
            rospy.logerr('Cannot transform the message: {}'.format(e))
            if self.preempt_requested():
                self.service_preempt()
            return 'aborted'
        for key in ['msg', 'output_msg', 'msg_output']:
            if key in self._output_keys:
                setattr(userdata, key, transformed)
        for key in ['transform', 'output_transform', 'transform_output']:
            if key in self._output_keys:
                setattr(userdata, key, transform)
        return 'succeeded'

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


@smach.cb_interface(input_keys=['point_in_base', 'pose_in_base', 'rotation_only', 'cloud_in_base', 'lifted'],
                    output_keys=['problems'],
                    outcomes=[])
def problems_check_bc1a3b30e41440af87efba87a7bd013a_lambda_cb(userdata):
    lambda_cb = lambda ud: [name for name, actual, expected in [("point", [round(v, 6) for v in (ud.point_in_base.point.x, ud.point_in_base.point.y, ud.point_in_base.point.z)] + [ud.point_in_base.header.frame_id], [-1.9, 1.2, 3.3, "base"]), ("pose", [round(v, 6) for v in (ud.pose_in_base.pose.position.x, ud.pose_in_base.pose.position.y, ud.pose_in_base.pose.position.z, ud.pose_in_base.pose.orientation.z, ud.pose_in_base.pose.orientation.w)], [-2.0, 1.0, 3.0, 0.707107, 0.707107]), ("transform", [round(v, 6) for v in (ud.rotation_only.transform.translation.x, ud.rotation_only.transform.translation.z, ud.rotation_only.transform.rotation.z)], [0.0, 0.0, 0.707107]), ("cloud", [[round(v, 6) for v in p] for p in sensor_msgs.point_cloud2.read_points(ud.cloud_in_base, field_names=("x", "y", "z"))] + [ud.cloud_in_base.header.frame_id], [[1.1, 0.2, 0.3], "base"]), ("poses", [[round(v, 6) for v in (p.position.x, p.position.y, p.position.z)] for p in ud.lifted.poses], [[1.0, 0.0, 1.0], [0.0, 1.0, 1.0]])] if actual != expected]
    userdata.problems = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['problems'],
                    output_keys=['ok'],
                    outcomes=['ok', 'default'])
def ok_verdict_2812674ed5cc4af29e49fedc69cf0119_lambda_cb(userdata):
    lambda_cb = lambda ud: ud.problems == []
    userdata.ok = lambda_cb(userdata)
    return 'succeeded'


def main():
    rospy.init_node('ros_transform_msg')
    ros_transform_msg = smach.StateMachine(outcomes=['done', 'wrong'])
    ros_transform_msg.userdata.base = 'base'
    ros_transform_msg.userdata.cloud = PointCloud(header=Header(frame_id="tool"), points=[Point32(x=1.0, y=0.0, z=0.0)])
    ros_transform_msg.userdata.lift = [[0.0, 0.0, 1.0], [0.0, 0.0, 0.0, 1.0]]
    ros_transform_msg.userdata.nowhere = 'nowhere'
    ros_transform_msg.userdata.point = [1.0, 2.0, 3.0]
    ros_transform_msg.userdata.pose = [[1.0, 2.0, 3.0], [0.0, 0.0, 0.0, 1.0]]
    ros_transform_msg.userdata.poses = [[[1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]], [[0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]]]
    ros_transform_msg.userdata.tool = 'tool'

    ros_transform_msg.userdata.pose_array_type = 'geometry_msgs/PoseArray'

    with ros_transform_msg:
        smach.StateMachine.add('POINT',
                               TransformMsgState(input_keys = ['msg', 'source', 'frame_id'], output_keys = ['output_msg']),
                               transitions={'aborted':'wrong',
                                            'succeeded':'POSE'},
                               remapping={'frame_id':'base',
                                          'msg':'point',
                                          'output_msg':'point_in_base',
                                          'source':'tool'})

        smach.StateMachine.add('POSE',
                               TransformMsgState(transform_type='rotation', input_keys = ['msg', 'source', 'target'], output_keys = ['msg_output', 'transform']),
                               transitions={'aborted':'wrong',
                                            'succeeded':'CLOUD'},
                               remapping={'msg':'pose',
                                          'msg_output':'pose_in_base',
                                          'source':'tool',
                                          'target':'base',
                                          'transform':'rotation_only'})

        smach.StateMachine.add('CLOUD',
                               TransformMsgState(transform_type='translation', input_keys = ['msg', 'frame_id'], output_keys = ['output_msg']),
                               transitions={'aborted':'wrong',
                                            'succeeded':'POSES'},
                               remapping={'frame_id':'base',
                                          'msg':'cloud',
                                          'output_msg':'cloud_in_base'})

        smach.StateMachine.add('POSES',
                               TransformMsgState(input_keys = ['msg', 'msg_type', 'transform'], output_keys = ['output_msg']),
                               transitions={'aborted':'wrong',
                                            'succeeded':'UNKNOWN_FRAME'},
                               remapping={'msg':'poses',
                                          'msg_type':'pose_array_type',
                                          'output_msg':'lifted',
                                          'transform':'lift'})

        smach.StateMachine.add('UNKNOWN_FRAME',
                               TransformMsgState(input_keys = ['msg', 'source', 'frame_id'], output_keys = ['output_msg'], timeout=0.3),
                               transitions={'aborted':'CHECK',
                                            'succeeded':'wrong'},
                               remapping={'frame_id':'base',
                                          'msg':'point',
                                          'output_msg':'lost',
                                          'source':'nowhere'})

        smach.StateMachine.add('CHECK',
                               CallbacksState(input_keys = ['point_in_base', 'pose_in_base', 'rotation_only', 'cloud_in_base', 'lifted'], output_keys = ['problems'], callbacks = ['problems_check_bc1a3b30e41440af87efba87a7bd013a_lambda_cb']),
                               transitions={'succeeded':'VERDICT'})

        smach.StateMachine.add('VERDICT',
                               ConditionalOutcomeState(input_keys = ['problems'], callbacks = ['ok_verdict_2812674ed5cc4af29e49fedc69cf0119_lambda_cb'], outcomes=['ok', 'default']),
                               transitions={'default':'wrong',
                                            'ok':'done'})

    outcome = ros_transform_msg.execute()


if __name__ == '__main__':
    main()
