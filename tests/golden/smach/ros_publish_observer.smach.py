#!/usr/bin/env python

import roslib
import rospy
import smach
import smach_ros
import std_msgs.msg
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


class MsgPublisherObserver(object):
    """Publishes messages on their topics whenever a message arrives on sub_topic."""

    def __init__(self, sub_topic='tf'):
        self._sub_topic = sub_topic
        self._subscriber = None
        self._lock = threading.Lock()
        self._msgs = {}
        self._publishers = {}

    def _observed(self, _msg):
        with self._lock:
            outgoing = [(self._publishers[topic], msg) for topic, msg in self._msgs.items()]
        for publisher, msg in outgoing:
            if hasattr(msg, 'header'):
                msg.header.stamp = rospy.Time.now()
            try:
                publisher.publish(msg)
            except rospy.ROSException as e:
                rospy.logwarn('Cannot publish on {}: {}'.format(publisher.resolved_name, e))

    def add(self, msg, topic, frame_id=None):
        if frame_id and hasattr(msg, 'header'):
            msg.header.frame_id = frame_id
        try:
            publisher = rospy.Publisher(topic, type(msg), queue_size=10)
        except Exception as e:
            rospy.logerr('Cannot publish on {}: {}'.format(topic, e))
            return 'aborted'
        with self._lock:
            previous = self._publishers.pop(topic, None)
            self._msgs[topic] = msg
            self._publishers[topic] = publisher
            if self._subscriber is None:
                # Any message type: only the arrival times matter.
                self._subscriber = rospy.Subscriber(self._sub_topic, rospy.AnyMsg,
                                                    self._observed, queue_size=1)
        if previous is not None and previous is not publisher:
            previous.unregister()
        return 'succeeded'

    def remove(self, topic):
        with self._lock:
            self._msgs.pop(topic, None)
            publisher = self._publishers.pop(topic, None)
        if publisher is not None:
            publisher.unregister()
        return 'succeeded'

    def remove_all(self):
        with self._lock:
            topics = list(self._publishers)
        for topic in topics:
            self.remove(topic)
        return 'succeeded'
















class PublishObserverMsgState(smach.State):
    """Adds a message to, or removes it from, a MsgPublisherObserver's publications."""

    def __init__(self, name, msg_pub_observer, action, input_keys=['msg', 'topic'],
                 output_keys=['msg', 'topic'], callbacks=[]):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded', 'aborted'])
        self._name = name
        self._observer = msg_pub_observer
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

        if self._action == 'remove_all':
            return self._observer.remove_all()
        topic = userdata.topic if 'topic' in self._input_keys else 'smacha/' + self._name.lower()
        if self._action == 'remove':
            return self._observer.remove(topic)
        if self._action != 'add':
            rospy.logerr('Unknown action {} (add, remove or remove_all)'.format(self._action))
            return 'aborted'
        try:
            msg_type = userdata.msg_type if 'msg_type' in self._input_keys else None
            msg = parse_msg(userdata.msg, self._parsers, msg_type)
            frame_id = userdata.frame_id if 'frame_id' in self._input_keys else None
        except Exception as e:
            rospy.logerr('Cannot publish on {}: {}'.format(topic, e))
            return 'aborted'
        outcome = self._observer.add(msg, topic, frame_id=frame_id)
        if outcome == 'succeeded':
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


def main():
    rospy.init_node('ros_publish_observer')

    _x2fsmachac_x2ftick_msg_pub_observer = MsgPublisherObserver(sub_topic='/smachac/tick')

    tf_msg_pub_observer = MsgPublisherObserver(sub_topic='tf')
    ros_publish_observer = smach.StateMachine(outcomes=['done', 'failed'])
    ros_publish_observer.userdata.topic = ''
    ros_publish_observer.userdata.point = [1.0, 2.0, 3.0]
    ros_publish_observer.userdata.point_frame = 'base'
    ros_publish_observer.userdata.point_topic = '/smachac/observed'
    ros_publish_observer.userdata.pose = [[4.0, 5.0, 6.0], [0.0, 0.0, 0.0, 1.0]]
    ros_publish_observer.userdata.pose_topic = '/smachac/observed_pose'


    with ros_publish_observer:
        smach.StateMachine.add('ADD_POINT',
                               PublishObserverMsgState('ADD_POINT', _x2fsmachac_x2ftick_msg_pub_observer, 'add', input_keys = ['msg', 'topic', 'frame_id'], output_keys = ['output_msg']),
                               transitions={'aborted':'failed',
                                            'succeeded':'ECHO_POINT'},
                               remapping={'frame_id':'point_frame',
                                          'msg':'point',
                                          'output_msg':'published',
                                          'topic':'point_topic'})

        smach.StateMachine.add('ECHO_POINT',
                               WaitForMsgState('/smachac/observed_point_echo', std_msgs.msg.String, msg_cb = lambda msg, ud: msg.data == "point 1 2 3 base", timeout = 10),
                               transitions={'aborted':'failed',
                                            'preempted':'failed',
                                            'succeeded':'ADD_POSE'})

        smach.StateMachine.add('ADD_POSE',
                               PublishObserverMsgState('ADD_POSE', tf_msg_pub_observer, 'add', input_keys = ['msg', 'topic']),
                               transitions={'aborted':'failed',
                                            'succeeded':'ECHO_POSE'},
                               remapping={'msg':'pose',
                                          'topic':'pose_topic'})

        smach.StateMachine.add('ECHO_POSE',
                               WaitForMsgState('/smachac/observed_pose_echo', std_msgs.msg.String, msg_cb = lambda msg, ud: msg.data == "pose 4 5 6", timeout = 10),
                               transitions={'aborted':'failed',
                                            'preempted':'failed',
                                            'succeeded':'REMOVE_POINT'})

        smach.StateMachine.add('REMOVE_POINT',
                               PublishObserverMsgState('REMOVE_POINT', _x2fsmachac_x2ftick_msg_pub_observer, 'remove', input_keys = ['topic']),
                               transitions={'aborted':'failed',
                                            'succeeded':'REMOVE_ALL'},
                               remapping={'topic':'point_topic'})

        smach.StateMachine.add('REMOVE_ALL',
                               PublishObserverMsgState('REMOVE_ALL', tf_msg_pub_observer, 'remove_all'),
                               transitions={'aborted':'failed',
                                            'succeeded':'done'})

    outcome = ros_publish_observer.execute()


if __name__ == '__main__':
    main()
