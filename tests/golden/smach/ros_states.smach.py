#!/usr/bin/env python

import roslib
import rospy
import smach
import smach_ros
import std_msgs.msg
from smachac_test_msgs.msg import MoveAction
from smachac_test_msgs.msg import MoveGoal
from smachac_test_msgs.srv import SetWidth

from actionlib import *

import tf2_ros

import genpy
import roslib.message






from geometry_msgs.msg import Point
from geometry_msgs.msg import Point32
from geometry_msgs.msg import PointStamped







from geometry_msgs.msg import Pose
from geometry_msgs.msg import PoseStamped




















from geometry_msgs.msg import PoseArray






from sensor_msgs.msg import PointCloud
from sensor_msgs.msg import PointCloud2
from sensor_msgs import point_cloud2 as pc2







from sensor_msgs.point_cloud2 import create_cloud_xyz32






import threading


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
















class TF2ListenerState(smach.State):
    """Stores the transform from the `source` to the `target` frame in `output`."""

    def __init__(self, input_keys=['target', 'source'], output_keys=['output'], callbacks=[],
                 outcomes=['succeeded', 'aborted'], timeout=1.0):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded', 'aborted'])
        self._buffer, _ = TF2ListenerSingleton.get()
        self._timeout = rospy.Duration(timeout)

    def execute(self, userdata):
        try:
            userdata.output = self._buffer.lookup_transform(
                userdata.target, userdata.source, rospy.Time(0), self._timeout)
        except Exception as e:
            rospy.logerr('No transform from {} to {}: {}'.format(
                userdata.source, userdata.target, e))
            return 'aborted'
        return 'succeeded'

class MsgPublisher(object):
    """Publishes messages on topics at fixed rates until told to stop."""

    def __init__(self):
        self._lock = threading.Lock()
        self._stops = {}

    def start(self, msg, topic, rate, frame_id=''):
        if frame_id and hasattr(msg, 'header'):
            msg.header.frame_id = frame_id
        self.stop(topic)
        stop = threading.Event()
        with self._lock:
            self._stops[topic] = stop
        publisher = rospy.Publisher(topic, type(msg), queue_size=1, latch=True)

        def run():
            period = rospy.Rate(rate)
            while not stop.is_set() and not rospy.is_shutdown():
                if hasattr(msg, 'header'):
                    msg.header.stamp = rospy.Time.now()
                publisher.publish(msg)
                period.sleep()

        thread = threading.Thread(target=run)
        thread.daemon = True
        thread.start()
        return 'succeeded'

    def stop(self, topic):
        with self._lock:
            stop = self._stops.pop(topic, None)
        if stop is not None:
            stop.set()
        return 'succeeded'

    def stop_all(self):
        with self._lock:
            topics = list(self._stops)
        for topic in topics:
            self.stop(topic)
        return 'succeeded'
















class PublishMsgState(smach.State):
    """Starts or stops publishing a message through the script's MsgPublisher."""

    def __init__(self, name, msg_publisher, action, input_keys=['msg', 'topic', 'rate'],
                 output_keys=['msg', 'topic'], callbacks=[]):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded', 'aborted'])
        self._name = name
        self._publisher = msg_publisher
        self._action = action
        # The parse function of each message class (parse_msg): points and poses are stamped.
        self._parsers = [(PointStamped, parse_pointstamped), (Point, parse_pointstamped),
                         (PoseStamped, parse_posestamped), (Pose, parse_posestamped),
                         (PoseArray, parse_posearray), (PointCloud, parse_pointcloud),
                         (PointCloud2, parse_pointcloud2)]
        
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

        topic = userdata.topic if 'topic' in self._input_keys else 'smacha/' + self._name.lower()
        if self._action == 'stop':
            return self._publisher.stop(topic)
        if self._action == 'stop_all':
            return self._publisher.stop_all()
        try:
            msg_type = userdata.msg_type if 'msg_type' in self._input_keys else None
            msg = parse_msg(userdata.msg, self._parsers, msg_type)
            rate = userdata.rate if 'rate' in self._input_keys else 100.0
            frame_id = userdata.frame_id if 'frame_id' in self._input_keys else ''
            outcome = self._publisher.start(msg, topic, rate, frame_id=frame_id)
        except Exception as e:
            rospy.logerr('Cannot publish on {}: {}'.format(topic, e))
            return 'aborted'
        for key in ['msg', 'output_msg', 'msg_output']:
            if key in self._output_keys:
                setattr(userdata, key, msg)
        for key in ['topic', 'output_topic', 'topic_output']:
            if key in self._output_keys:
                setattr(userdata, key, topic)
        return outcome

class WaitForMsgState(smach.State):
    """Waits for a message on a topic; an optional callback may decide the outcome."""

    def __init__(self, topic, msg_type, msg_cb=None, output_keys=[], latch=False, timeout=None):
        smach.State.__init__(self, outcomes=['succeeded', 'aborted', 'preempted'],
                             output_keys=output_keys)
        self._msg_cb = msg_cb
        self._latch = latch
        self._timeout = timeout
        self._lock = threading.Lock()
        self._msg = None
        self._subscriber = rospy.Subscriber(topic, msg_type, self._receive, queue_size=1)

    def __enter__(self):
        return self

    def __exit__(self, *error):
        self._subscriber.unregister()

    def _receive(self, msg):
        with self._lock:
            self._msg = msg

    def waitForMsg(self):
        """The next message; None on timeout or when ROS shuts down; 'preempted'."""
        deadline = None
        if self._timeout is not None:
            deadline = rospy.Time.now() + rospy.Duration.from_sec(self._timeout)
        while not rospy.is_shutdown() and (deadline is None or rospy.Time.now() < deadline):
            with self._lock:
                msg = self._msg
                if msg is not None and not self._latch:
                    self._msg = None
            if msg is not None:
                return msg
            if self.preempt_requested():
                self.service_preempt()
                return 'preempted'
            try:
                rospy.sleep(0.05)
            except rospy.ROSInterruptException:
                break
        return None

    def execute(self, userdata):
        msg = self.waitForMsg()
        if msg is None:
            return 'aborted'
        if isinstance(msg, str) and msg == 'preempted':
            return 'preempted'
        if self._msg_cb is not None:
            decision = self._msg_cb(msg, userdata)
            if decision is not None:
                return 'succeeded' if decision else 'aborted'
        return 'succeeded'




class ReadTopicState(smach.State):
    """Reads one message from the topic named by the `topic` input key; aborts after
    `timeout` seconds (None: no limit), when preempted or when ROS shuts down."""

    def __init__(self, input_keys=['topic'], output_keys=['output'], callbacks=[],
                 outcomes=['succeeded', 'aborted'], timeout=None):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded', 'aborted'])
        self._timeout = timeout
        self._reader = None
        self._reader_lock = threading.Lock()
        
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


    def request_preempt(self):
        smach.State.request_preempt(self)
        with self._reader_lock:
            if self._reader is not None:
                self._reader.request_preempt()

    def _wait(self, topic, msg_class, deadline):
        """The first message of msg_class on topic, or None (time out, preempted, shutdown)."""
        timeout = None
        if deadline is not None:
            timeout = max(0.0, (deadline - rospy.Time.now()).to_sec())
        with WaitForMsgState(topic, msg_class, latch=True, timeout=timeout) as reader:
            with self._reader_lock:
                self._reader = reader
            try:
                msg = None if self.preempt_requested() else reader.waitForMsg()
            finally:
                with self._reader_lock:
                    self._reader = None
        return msg if msg is not None and not isinstance(msg, str) else None

    def _message_class(self, userdata, topic, deadline):
        if 'msg_type' in self._input_keys:
            return roslib.message.get_message_class(userdata.msg_type)
        any_msg = self._wait(topic, rospy.AnyMsg, deadline)
        if any_msg is None:
            return None
        return roslib.message.get_message_class(any_msg._connection_header['type'])

    def execute(self, userdata):
        
        # Call the callbacks
        for (cb, input_keys, output_keys) in zip(self._cbs,
                                                 self._cb_input_keys,
                                                 self._cb_output_keys):
            cb(smach.Remapper(userdata, input_keys, output_keys, {}))

        deadline = None
        if self._timeout is not None:
            deadline = rospy.Time.now() + rospy.Duration.from_sec(self._timeout)
        try:
            topic = userdata.topic
            msg_class = self._message_class(userdata, topic, deadline)
            msg = self._wait(topic, msg_class, deadline) if msg_class is not None else None
        except Exception as e:
            rospy.logerr('Cannot read topic: {}'.format(e))
            return 'aborted'
        if self.preempt_requested():
            self.service_preempt()
        if msg is None:
            return 'aborted'
        for key in ['output', 'msg', 'output_msg', 'msg_output']:
            if key in self._output_keys:
                setattr(userdata, key, msg)
        return 'succeeded'


def main():
    rospy.init_node('ros_states')

    msg_publisher = MsgPublisher()
    ros_states = smach.StateMachine(outcomes=['done', 'failed'])
    ros_states.userdata.rate = 100.0

    ros_states.userdata.rate = 100.0
    ros_states.userdata.topic = ''
    ros_states.userdata.msg = [1.0, 2.0, 3.0]
    ros_states.userdata.source = 'tool'
    ros_states.userdata.target = 'base'
    ros_states.userdata.topic = '/chatter'
    ros_states.userdata.width = 0.04


    with ros_states:
        smach.StateMachine.add('SERVICE',
                               smach_ros.ServiceState('/gripper/set_width', SetWidth,
                                                           request_slots = ['width'],
                                                           response_cb = lambda ud, response: setattr(ud, "reply", response.width),
                                             output_keys = ['reply']),
                               transitions={'aborted':'failed',
                                            'preempted':'failed',
                                            'succeeded':'ACTION'})

        smach.StateMachine.add('ACTION',
                               smach_ros.SimpleActionState('/arm/move', MoveAction,
                                                           goal = MoveGoal(speed=0.5),
                                                           result_slots = ['final_pose']),
                               transitions={'aborted':'failed',
                                            'preempted':'failed',
                                            'succeeded':'LOOKUP'})

        smach.StateMachine.add('LOOKUP',
                               TF2ListenerState(input_keys = ['target', 'source'], output_keys = ['output'], timeout=2.0),
                               transitions={'aborted':'failed',
                                            'succeeded':'PUBLISH'})

        smach.StateMachine.add('PUBLISH',
                               PublishMsgState('PUBLISH', msg_publisher, 'start', input_keys = ['msg', 'topic']),
                               transitions={'aborted':'failed',
                                            'succeeded':'READ'})

        smach.StateMachine.add('READ',
                               ReadTopicState(input_keys = ['topic'], output_keys = ['output']),
                               transitions={'aborted':'failed',
                                            'succeeded':'LISTEN'})

        smach.StateMachine.add('LISTEN',
                               WaitForMsgState('/chatter', std_msgs.msg.String, msg_cb = lambda msg, ud: len(msg.data) > 0, latch = True, timeout = 5),
                               transitions={'aborted':'failed',
                                            'preempted':'failed',
                                            'succeeded':'STOP'})

        smach.StateMachine.add('STOP',
                               PublishMsgState('STOP', msg_publisher, 'stop_all'),
                               transitions={'aborted':'failed',
                                            'succeeded':'done'})

    outcome = ros_states.execute()


if __name__ == '__main__':
    main()
